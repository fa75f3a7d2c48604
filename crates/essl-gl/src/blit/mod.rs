//! Copies between framebuffer images: `blit_framebuffer` (colour, depth and stencil; scaled,
//! flipped by swapped coordinates, `NEAREST` or `LINEAR`, resolving multisampled images) and
//! the texture copies `copy_tex_image_2d`, `copy_tex_sub_image_2d` and
//! `copy_tex_sub_image_3d` ([`copy`]).
//!
//! Everything is drawn ([`crate::pipeline::BlitKey`]): a multisampled colour source is first
//! resolved into a single-sampled copy, a slice of a 3D texture is first copied into a 2D
//! one, and stencil is copied one bit per draw (wgpu cannot write stencil from a shader).

mod check;
mod copy;

use crate::context::Context;
use crate::frame::{ColorTarget, DepthTarget, PassTarget};
use crate::framebuffer::SurfaceImage;
use crate::gl;
use crate::pipeline::{BlitKey, BlitSource, Channels, ClearKind};
use crate::texture::SampleKind;

/// A rectangle given by two corners, GL's way (`x0, y0, x1, y1`; x1 < x0 flips).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Corners(pub(crate) [i32; 4]);

impl Corners {
    fn as_f32(self) -> [f32; 4] {
        self.0.map(|v| v as f32)
    }

    /// The rectangle's pixels as (x, y, width, height) with positive sizes.
    fn bounds(self) -> [i64; 4] {
        let [x0, y0, x1, y1] = self.0.map(|v| v as i64);
        [x0.min(x1), y0.min(y1), (x1 - x0).abs(), (y1 - y0).abs()]
    }
}

/// One blit draw: what is read, where it goes.
pub(crate) struct BlitDraw<'a> {
    pub(crate) source: &'a SurfaceImage,
    pub(crate) read: BlitSource,
    pub(crate) src: Corners,
    pub(crate) dst: Corners,
    pub(crate) linear: bool,
    pub(crate) channels: Channels,
    /// The colour images written (by draw buffer).
    pub(crate) colors: Vec<Option<SurfaceImage>>,
    /// The depth/stencil image written.
    pub(crate) depth: Option<SurfaceImage>,
    /// For a stencil bit: the bit.
    pub(crate) bit: u32,
    /// Whether the scissor test limits the destination (blits: yes; copies: no).
    pub(crate) scissor: bool,
}

/// The kind a colour format reads and writes as.
pub(crate) fn kind_of(image: &SurfaceImage) -> ClearKind {
    match image.format.kind() {
        SampleKind::Sint => ClearKind::Int,
        SampleKind::Uint => ClearKind::Uint,
        _ => ClearKind::Float,
    }
}

/// How the blit shader reads colour image `source`: its kind, and its samples where it is still
/// multisampled ([`Context::single_sampled`] keeps formats the GPU cannot resolve so).
pub(crate) fn color_source(source: &SurfaceImage) -> BlitSource {
    BlitSource::Color {
        kind: kind_of(source),
        samples: source.samples.max(1),
    }
}

impl Context {
    /// Copies a rectangle of the read framebuffer into one of the draw framebuffer
    /// (`blitFramebuffer`): `COLOR_BUFFER_BIT` (the read buffer into every draw buffer),
    /// `DEPTH_BUFFER_BIT`, `STENCIL_BUFFER_BIT`; scaled with `NEAREST` or `LINEAR` filtering,
    /// flipped where a rectangle's corners are swapped, resolved when the read framebuffer
    /// is multisampled. The scissor test limits the destination.
    ///
    /// Errors as WebGL2 has them: other mask bits → `INVALID_VALUE`; another filter →
    /// `INVALID_ENUM`; `LINEAR` with depth or stencil, or with an integer read buffer,
    /// a multisampled draw framebuffer, a multisampled read framebuffer with rectangles of
    /// other sizes or formats that differ, colour formats of other kinds, depth or stencil
    /// formats that differ, or the same image read and drawn → `INVALID_OPERATION`; an
    /// incomplete framebuffer → `INVALID_FRAMEBUFFER_OPERATION`.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn blit_framebuffer(
        &mut self,
        src_x0: i32,
        src_y0: i32,
        src_x1: i32,
        src_y1: i32,
        dst_x0: i32,
        dst_y0: i32,
        dst_x1: i32,
        dst_y1: i32,
        mask: u32,
        filter: u32,
    ) {
        const F: &str = "blitFramebuffer";
        if mask & !(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT) != 0 {
            return self.error(gl::INVALID_VALUE, F, format_args!("mask 0x{mask:X}"));
        }
        if !matches!(filter, gl::NEAREST | gl::LINEAR) {
            return self.error(gl::INVALID_ENUM, F, format_args!("filter 0x{filter:04X}"));
        }
        // A rectangle whose width or height, either way round, does not fit an i32 (ANGLE's
        // "blit dimensions are out of range").
        let fits = |a: i32, b: i32| (i64::from(b) - i64::from(a)).abs() <= i64::from(i32::MAX);
        let spans = [
            (src_x0, src_x1),
            (src_y0, src_y1),
            (dst_x0, dst_x1),
            (dst_y0, dst_y1),
        ];
        if !spans.iter().all(|&(a, b)| fits(a, b)) {
            return self.error(gl::INVALID_VALUE, F, "blit dimensions are out of range");
        }
        let linear = filter == gl::LINEAR;
        if linear && mask & (gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT) != 0 {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "depth and stencil can only be blitted with NEAREST",
            );
        }
        if !self.require_complete(false, F) || !self.require_complete(true, F) {
            return;
        }
        let src = Corners([src_x0, src_y0, src_x1, src_y1]);
        let dst = Corners([dst_x0, dst_y0, dst_x1, dst_y1]);
        let read = self.read_surface();
        let draw = self.draw_images();
        let Some(plan) = self.check_blit(&read, &draw, src, dst, mask, linear, F) else {
            return;
        };
        if self.state.rasterizer_discard {
            return;
        }
        self.run_blit(plan, src, dst, linear);
    }

    /// Runs a checked blit.
    fn run_blit(&mut self, plan: BlitPlan, src: Corners, dst: Corners, linear: bool) {
        if let Some(color) = plan.color {
            let source = self.single_sampled(&color);
            let draw = BlitDraw {
                read: color_source(&source),
                source: &source,
                src,
                dst,
                linear,
                channels: Channels::Rgba,
                colors: plan.draw_colors.clone(),
                depth: None,
                bit: 0,
                scissor: true,
            };
            self.blit_draw(&draw);
        }
        if let Some((from, to)) = plan.depth {
            let draw = BlitDraw {
                read: BlitSource::Depth {
                    samples: from.samples,
                },
                source: &from,
                src,
                dst,
                linear: false,
                channels: Channels::Rgba,
                colors: Vec::new(),
                depth: Some(to),
                bit: 0,
                scissor: true,
            };
            self.blit_draw(&draw);
        }
        if let Some((from, to)) = plan.stencil {
            self.blit_stencil(&from, &to, src, dst);
        }
    }

    /// Copies stencil: the destination rectangle's stencil is cleared, then each bit set in
    /// the source is set by one draw that keeps only the fragments where the source has it.
    fn blit_stencil(&mut self, from: &SurfaceImage, to: &SurfaceImage, src: Corners, dst: Corners) {
        for bit in [8, 0, 1, 2, 3, 4, 5, 6, 7] {
            // Bit "8", which no 8-bit buffer has, stands for the draw that writes zeros to
            // every bit where the source covers the destination.
            let draw = BlitDraw {
                read: BlitSource::StencilBit {
                    samples: from.samples,
                },
                source: from,
                src,
                dst,
                linear: false,
                channels: Channels::Rgba,
                colors: Vec::new(),
                depth: Some(to.clone()),
                bit,
                scissor: true,
            };
            self.blit_draw(&draw);
        }
    }

    /// A single-sampled copy of `image` (itself when it is one): multisampled images are
    /// resolved, slices of 3D textures copied into a 2D texture. A multisampled image of a
    /// format the GPU cannot resolve (32-bit floats) is returned as it is: the blit shader
    /// averages its samples.
    fn single_sampled(&mut self, image: &SurfaceImage) -> SurfaceImage {
        if image.samples <= 1 && !image.slice_3d {
            return image.clone();
        }
        let format = image.format.gpu_format();
        let resolvable = format
            .guaranteed_format_features(self.gpu.device.features())
            .flags
            .contains(wgpu::TextureFormatFeatureFlags::MULTISAMPLE_RESOLVE);
        if !image.slice_3d && !resolvable {
            return image.clone();
        }
        let temp = self.gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("essl-gl blit source"),
            size: wgpu::Extent3d {
                width: image.width,
                height: image.height,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        });
        let view = temp.create_view(&Default::default());
        if image.slice_3d {
            self.frame.commands(&self.gpu).copy_texture_to_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &image.texture,
                    mip_level: image.mip,
                    origin: wgpu::Origin3d {
                        x: 0,
                        y: 0,
                        z: image.layer,
                    },
                    aspect: wgpu::TextureAspect::All,
                },
                temp.as_image_copy(),
                wgpu::Extent3d {
                    width: image.width,
                    height: image.height,
                    depth_or_array_layers: 1,
                },
            );
        } else {
            // A pass that only resolves: the multisampled image is loaded and kept.
            let target = PassTarget {
                colors: vec![Some(ColorTarget {
                    view: image.view.clone(),
                    depth_slice: None,
                    resolve: Some(view.clone()),
                    format,
                })],
                depth: None,
                samples: image.samples,
                size: [image.width, image.height],
            };
            self.frame.pass(&self.gpu, &target);
            self.frame.end_pass();
        }
        SurfaceImage {
            texture: temp,
            mip: 0,
            layer: 0,
            samples: 1,
            slice_3d: false,
            view,
            depth_slice: None,
            ..image.clone()
        }
    }

    /// Records one blit draw into a pass on its destination images.
    pub(crate) fn blit_draw(&mut self, d: &BlitDraw) {
        let size = d
            .colors
            .iter()
            .flatten()
            .chain(&d.depth)
            .map(|i| [i.width, i.height])
            .next();
        let Some(size) = size else { return };
        let [dx, dy, dw, dh] = d.dst.bounds();
        let clip = if d.scissor {
            self.scissor_rect_for(size)
        } else {
            Some([0, 0, size[0], size[1]])
        };
        let Some([sx, sy, sw, sh]) = clip else { return };
        let x0 = dx.max(sx as i64);
        let y0 = dy.max(sy as i64);
        let x1 = (dx + dw).min((sx + sw) as i64);
        let y1 = (dy + dh).min((sy + sh) as i64);
        if x1 <= x0 || y1 <= y0 {
            return;
        }
        let target = PassTarget {
            colors: d
                .colors
                .iter()
                .map(|c| {
                    c.as_ref().map(|i| ColorTarget {
                        view: i.view.clone(),
                        depth_slice: i.depth_slice,
                        resolve: None,
                        format: i.format.gpu_format(),
                    })
                })
                .collect(),
            depth: d.depth.as_ref().map(|i| DepthTarget {
                view: i.view.clone(),
                format: i.format.gpu_format(),
            }),
            samples: 1,
            size,
        };
        let stencil_mask = match d.read {
            BlitSource::StencilBit { .. } if d.bit < 8 => 1 << d.bit,
            BlitSource::StencilBit { .. } => 0xFF,
            _ => 0,
        };
        let key = BlitKey {
            source: d.read,
            linear: d.linear,
            channels: d.channels,
            colors: d
                .colors
                .iter()
                .map(|c| c.as_ref().map(|i| (i.format.gpu_format(), kind_of(i))))
                .collect(),
            depth: d.depth.as_ref().map(|i| i.format.gpu_format()),
            stencil_mask,
        };
        let (pipeline, layout) = self.caches.pipelines.blit_pipeline(&self.gpu, &key);
        let source_view = source_view(d.source, d.read);
        let sampler = self
            .caches
            .samplers
            .get(&self.gpu.device, crate::texture::SamplerKey::blit(d.linear));
        let group1 = self
            .gpu
            .device
            .create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("essl-gl blit source"),
                layout: &layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: wgpu::BindingResource::TextureView(&source_view),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: wgpu::BindingResource::Sampler(&sampler),
                    },
                ],
            });
        // Stencil bit draws set their bit (reference 0xFF); the first one (bit "8") keeps
        // every fragment and writes 0 to all bits.
        let (bit, reference) = match d.read {
            BlitSource::StencilBit { .. } if d.bit < 8 => (1u32 << d.bit, 0xFF),
            _ => (0, 0),
        };
        let mut uniforms = [0u8; 64];
        let words: [f32; 12] = {
            let s = d.src.as_f32();
            let t = d.dst.as_f32();
            [
                s[0],
                s[1],
                s[2],
                s[3],
                t[0],
                t[1],
                t[2],
                t[3],
                d.source.width as f32,
                d.source.height as f32,
                0.0,
                0.0,
            ]
        };
        uniforms[..48].copy_from_slice(bytemuck::cast_slice(&words));
        uniforms[48..52].copy_from_slice(&bit.to_ne_bytes());
        let align = self.gpu.limits.min_uniform_buffer_offset_alignment as u64;
        let alloc = self.frame.arena.push(&self.gpu, &uniforms, align);
        let group0 =
            self.caches
                .pipelines
                .group0(&self.gpu, Some((alloc.chunk, &alloc.buffer, 64)), &[]);
        let pass = self.frame.internal_pass(&self.gpu, &target);
        pass.set_pipeline(&pipeline);
        pass.set_viewport(0.0, 0.0, size[0] as f32, size[1] as f32, 0.0, 1.0);
        pass.set_scissor_rect(x0 as u32, y0 as u32, (x1 - x0) as u32, (y1 - y0) as u32);
        pass.set_bind_group(0, &group0, &[alloc.offset as u32]);
        pass.set_bind_group(1, &group1, &[]);
        pass.set_stencil_reference(reference);
        pass.draw(0..3, 0..1);
    }
}

/// A view of one layer of `image` for reading in the blit shader.
fn source_view(image: &SurfaceImage, read: BlitSource) -> wgpu::TextureView {
    image.texture.create_view(&wgpu::TextureViewDescriptor {
        label: Some("essl-gl blit source"),
        dimension: Some(wgpu::TextureViewDimension::D2),
        aspect: match read {
            BlitSource::Depth { .. } => wgpu::TextureAspect::DepthOnly,
            BlitSource::StencilBit { .. } => wgpu::TextureAspect::StencilOnly,
            BlitSource::Color { .. } => wgpu::TextureAspect::All,
        },
        base_mip_level: image.mip,
        mip_level_count: Some(1),
        base_array_layer: image.layer,
        array_layer_count: Some(1),
        ..Default::default()
    })
}

/// What a checked blit copies.
pub(crate) struct BlitPlan {
    /// The colour read buffer, when colour is copied.
    pub(crate) color: Option<SurfaceImage>,
    pub(crate) draw_colors: Vec<Option<SurfaceImage>>,
    pub(crate) depth: Option<(SurfaceImage, SurfaceImage)>,
    pub(crate) stencil: Option<(SurfaceImage, SurfaceImage)>,
}
