//! Renderbuffer objects: `create_renderbuffer`, `bind_renderbuffer`, `renderbuffer_storage`,
//! `renderbuffer_storage_multisample`, `get_renderbuffer_parameter`, `delete_renderbuffer`.
//!
//! A renderbuffer's storage is a wgpu texture that can only be drawn into and copied (a
//! multisampled one is resolved by `blit_framebuffer`). wgpu zero-fills new textures, which
//! is WebGL's rule for new storage. The object's state is [`object`]'s; this file adds the
//! calls.

mod object;

pub(crate) use object::{RenderbufferObject, RenderbufferStorage};

use crate::context::Context;
use crate::gl;
use crate::gpu::Gpu;
use crate::objects::{Id, Renderbuffer};
use crate::query::Parameter;
use crate::texture::{internal_format, InternalFormat};

/// The internal formats a renderbuffer may have (ES 3.0 table 3.13 and WebGL's
/// `DEPTH_STENCIL`), with the float formats when `EXT_color_buffer_float` is on.
fn renderbuffer_format(internal: u32, float_ok: bool) -> Option<InternalFormat> {
    let internal = match internal {
        gl::DEPTH_STENCIL => gl::DEPTH24_STENCIL8,
        gl::RGBA | gl::RGB | gl::LUMINANCE | gl::ALPHA | gl::LUMINANCE_ALPHA => return None,
        other => other,
    };
    let f = internal_format(internal).ok()?;
    (f.color_renderable(float_ok) || f.depth_stencil_renderable()).then_some(f)
}

/// Samples a device offers for attachments of `format`: 4 where wgpu guarantees 4×, else 1.
pub(crate) fn max_samples(gpu: &Gpu, format: wgpu::TextureFormat) -> u32 {
    let flags = format
        .guaranteed_format_features(gpu.device.features())
        .flags;
    if flags.contains(wgpu::TextureFormatFeatureFlags::MULTISAMPLE_X4) {
        4
    } else {
        1
    }
}

impl Context {
    /// Creates a renderbuffer (`createRenderbuffer`).
    pub fn create_renderbuffer(&mut self) -> Renderbuffer {
        Renderbuffer {
            ctx: self.id,
            id: self
                .objects
                .renderbuffers
                .insert(RenderbufferObject::default()),
        }
    }

    /// Whether `renderbuffer` names a live renderbuffer that was bound once (`isRenderbuffer`).
    pub fn is_renderbuffer(&self, renderbuffer: Renderbuffer) -> bool {
        renderbuffer.ctx == self.id
            && self
                .objects
                .renderbuffers
                .get(renderbuffer.id)
                .is_some_and(|r| r.bound_once)
    }

    /// Binds a renderbuffer to `RENDERBUFFER` (`bindRenderbuffer`); another target →
    /// `INVALID_ENUM`, a deleted renderbuffer → `INVALID_OPERATION`.
    pub fn bind_renderbuffer(&mut self, target: u32, renderbuffer: Option<Renderbuffer>) {
        const F: &str = "bindRenderbuffer";
        if self.webgl1_refuses("bindRenderbuffer", &[target]) {
            return;
        }
        if target != gl::RENDERBUFFER {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        let id = match renderbuffer {
            None => None,
            Some(r) => {
                if !self.owns(r.ctx, F) {
                    return;
                }
                let Some(obj) = self.objects.renderbuffers.get_mut(r.id) else {
                    return self.error(gl::INVALID_OPERATION, F, "deleted renderbuffer");
                };
                obj.bound_once = true;
                Some(r.id)
            }
        };
        self.bindings.bind_renderbuffer(id);
    }

    /// Deletes a renderbuffer (`deleteRenderbuffer`): unbound, detached from the bound
    /// framebuffers, and freed once no other framebuffer uses it.
    pub fn delete_renderbuffer(&mut self, renderbuffer: Renderbuffer) {
        if !self.owns(renderbuffer.ctx, "deleteRenderbuffer")
            || !self.objects.renderbuffers.is_live(renderbuffer.id)
        {
            return;
        }
        self.bindings.forget_renderbuffer(renderbuffer.id);
        let bound = self.bindings.framebuffers();
        self.objects.delete_renderbuffer(renderbuffer.id, bound);
    }

    /// Gives the bound renderbuffer storage of `internalformat` and `width` × `height`
    /// (`renderbufferStorage`).
    pub fn renderbuffer_storage(
        &mut self,
        target: u32,
        internalformat: u32,
        width: i32,
        height: i32,
    ) {
        if self.webgl1_refuses("renderbufferStorage", &[target])
            || self.webgl1_refuses_renderbuffer_format(internalformat)
        {
            return;
        }
        self.storage(
            target,
            0,
            internalformat,
            [width, height],
            "renderbufferStorage",
        );
    }

    /// [`Context::renderbuffer_storage`] with `samples` samples per pixel
    /// (`renderbufferStorageMultisample`): more than the format allows →
    /// `INVALID_OPERATION` (integer formats allow none).
    pub fn renderbuffer_storage_multisample(
        &mut self,
        target: u32,
        samples: i32,
        internalformat: u32,
        width: i32,
        height: i32,
    ) {
        const F: &str = "renderbufferStorageMultisample";
        if samples < 0 {
            return self.error(gl::INVALID_VALUE, F, "negative samples");
        }
        if samples > 0 && internalformat == gl::DEPTH_STENCIL {
            // WebGL 1's unsized DEPTH_STENCIL is single-sampled only, as Chromium has it.
            return self.error(gl::INVALID_OPERATION, F, "DEPTH_STENCIL with samples");
        }
        self.storage(target, samples as u32, internalformat, [width, height], F);
    }

    fn storage(&mut self, target: u32, samples: u32, internal: u32, size: [i32; 2], f: &str) {
        if target != gl::RENDERBUFFER {
            return self.error(gl::INVALID_ENUM, f, format_args!("target 0x{target:04X}"));
        }
        let Some(format) = renderbuffer_format(internal, self.extensions.color_buffer_float) else {
            return self.error(
                gl::INVALID_ENUM,
                f,
                format_args!("internal format 0x{internal:04X} is not renderable"),
            );
        };
        let [w, h] = size;
        let max = self.gpu.limits.max_texture_dimension_2d as i32;
        if w < 0 || h < 0 || w > max || h > max {
            return self.error(
                gl::INVALID_VALUE,
                f,
                "size outside 0..MAX_RENDERBUFFER_SIZE",
            );
        }
        let allowed = self.format_samples(&format).first().copied().unwrap_or(0);
        if samples > allowed {
            return self.error(
                gl::INVALID_OPERATION,
                f,
                format_args!("{samples} samples: the format allows {allowed}"),
            );
        }
        let Some(id) = self.bindings.renderbuffer() else {
            return self.error(gl::INVALID_OPERATION, f, "no renderbuffer bound");
        };
        // Multisampled storage is 4× (the one count wgpu guarantees) whatever was asked.
        let samples = if samples > 0 { 4 } else { 0 };
        let gpu = (w > 0 && h > 0).then(|| {
            let t = self.gpu.device.create_texture(&wgpu::TextureDescriptor {
                label: Some("essl-gl renderbuffer"),
                size: wgpu::Extent3d {
                    width: w as u32,
                    height: h as u32,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: samples.max(1),
                dimension: wgpu::TextureDimension::D2,
                format: format.gpu_format(),
                usage: renderbuffer_usages(samples, format.gpu_format()),
                view_formats: &[],
            });
            let v = t.create_view(&Default::default());
            (t, v)
        });
        // Depth 1.0 in new depth storage, as Chromium initializes it: wgpu's own is zeros,
        // which a `LESS` depth test passes nothing against.
        if let Some((_, view)) = &gpu {
            if format.gpu_format().has_depth_aspect() {
                self.clear_depth_view(view, format.gpu_format(), 1.0);
            }
        }
        let r = self
            .objects
            .renderbuffers
            .get_mut(id)
            .expect("bound renderbuffers are live");
        r.storage = Some(RenderbufferStorage {
            format,
            asked: internal,
            width: w as u32,
            height: h as u32,
            samples,
            gpu,
        });
    }

    /// The sample counts a format allows, largest first (`getInternalformatParameter(SAMPLES)`):
    /// none for integer formats, as in ES 3.0.
    pub(crate) fn format_samples(&self, format: &InternalFormat) -> Vec<u32> {
        let integer = matches!(
            format.kind(),
            crate::texture::SampleKind::Sint | crate::texture::SampleKind::Uint
        );
        if integer || max_samples(&self.gpu, format.gpu_format()) < 4 {
            Vec::new()
        } else {
            vec![4]
        }
    }

    /// A parameter of the bound renderbuffer (`getRenderbufferParameter`): `RENDERBUFFER_WIDTH`,
    /// `_HEIGHT`, `_INTERNAL_FORMAT`, `_SAMPLES`, and the bit sizes `_RED_SIZE` …
    /// `_STENCIL_SIZE`.
    pub fn get_renderbuffer_parameter(&self, target: u32, pname: u32) -> Option<Parameter> {
        const F: &str = "getRenderbufferParameter";
        if self.webgl1_refuses("getRenderbufferParameter", &[target, pname]) {
            return None;
        }
        if target != gl::RENDERBUFFER {
            self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
            return None;
        }
        let Some(id) = self.bindings.renderbuffer() else {
            self.error(gl::INVALID_OPERATION, F, "no renderbuffer bound");
            return None;
        };
        let r = self.objects.renderbuffers.get(id)?;
        let s = r.storage.as_ref();
        let bits = s
            .map(|s| crate::texture::bit_sizes(&s.format))
            .unwrap_or_default();
        let int = |v: u32| Some(Parameter::Int(v as i64));
        match pname {
            gl::RENDERBUFFER_WIDTH => int(s.map_or(0, |s| s.width)),
            gl::RENDERBUFFER_HEIGHT => int(s.map_or(0, |s| s.height)),
            gl::RENDERBUFFER_INTERNAL_FORMAT => {
                Some(Parameter::Enum(s.map_or(gl::RGBA4, |s| s.asked)))
            }
            gl::RENDERBUFFER_SAMPLES => int(s.map_or(0, |s| s.samples)),
            gl::RENDERBUFFER_RED_SIZE => int(bits.red),
            gl::RENDERBUFFER_GREEN_SIZE => int(bits.green),
            gl::RENDERBUFFER_BLUE_SIZE => int(bits.blue),
            gl::RENDERBUFFER_ALPHA_SIZE => int(bits.alpha),
            gl::RENDERBUFFER_DEPTH_SIZE => int(bits.depth),
            gl::RENDERBUFFER_STENCIL_SIZE => int(bits.stencil),
            _ => {
                self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
                None
            }
        }
    }

    /// The id behind a renderbuffer handle, or `INVALID_OPERATION`.
    pub(crate) fn renderbuffer_id(&mut self, r: Renderbuffer, function: &str) -> Option<Id> {
        if !self.owns(r.ctx, function) {
            return None;
        }
        if !self.objects.renderbuffers.is_live(r.id) {
            self.error(gl::INVALID_OPERATION, function, "deleted renderbuffer");
            return None;
        }
        Some(r.id)
    }
}

/// What a renderbuffer's texture is used for: drawn into and copied (blits); a
/// single-sampled one may also be read by the blitter.
fn renderbuffer_usages(samples: u32, format: wgpu::TextureFormat) -> wgpu::TextureUsages {
    let mut usage = wgpu::TextureUsages::RENDER_ATTACHMENT;
    if samples == 0 {
        usage |= wgpu::TextureUsages::COPY_SRC
            | wgpu::TextureUsages::COPY_DST
            | wgpu::TextureUsages::TEXTURE_BINDING;
    } else {
        usage |= wgpu::TextureUsages::TEXTURE_BINDING;
    }
    let _ = format;
    usage
}
