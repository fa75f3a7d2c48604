//! A texture object: its level images, its parameters, and GL ES 3.0 completeness. The GPU
//! copy of the images is [`super::gpu`]'s business.

use super::format::{Expand, InternalFormat, Packing};
use super::sampling::SamplerKey;
use crate::gl;
use crate::sampler::SamplerParams;
use crate::state::compare_function;

/// One level image (of one cube face).
#[derive(Clone, Debug)]
pub(crate) struct Level {
    pub(crate) width: u32,
    pub(crate) height: u32,
    /// Depth of a 3D texture, layers of a 2D array, 1 otherwise.
    pub(crate) depth: u32,
    pub(crate) format: InternalFormat,
    /// Texels in the GPU format, tightly packed, row 0 first; `None` when the GPU copy holds
    /// newer texels (the level was drawn into or copied into on the GPU).
    pub(crate) data: Option<Vec<u8>>,
    /// Whether `data` is what the GPU copy holds (set when it is uploaded).
    pub(crate) uploaded: bool,
}

impl Level {
    /// Copies a `size` box of tightly packed texels into the CPU copy at `offset` (nothing
    /// where the GPU holds the newer texels); the GPU copy is then stale.
    pub(crate) fn write_box(&mut self, offset: [u32; 3], size: [u32; 3], src: &[u8]) {
        let texel = self.format.texel_size();
        let (width, height) = (self.width as usize, self.height as usize);
        let Some(data) = self.data.as_mut() else {
            return;
        };
        let row = size[0] as usize * texel;
        for z in 0..size[2] as usize {
            for y in 0..size[1] as usize {
                let s = (z * size[1] as usize + y) * row;
                let dz = offset[2] as usize + z;
                let dy = offset[1] as usize + y;
                let at = ((dz * height + dy) * width + offset[0] as usize) * texel;
                data[at..at + row].copy_from_slice(&src[s..s + row]);
            }
        }
        self.uploaded = false;
    }

    /// A level image from texels in the GPU format (not yet on the GPU).
    pub(crate) fn new(size: [u32; 3], format: InternalFormat, data: Vec<u8>) -> Self {
        Level {
            width: size[0],
            height: size[1],
            depth: size[2],
            format,
            data: Some(data),
            uploaded: false,
        }
    }

    /// A level image with no data given (`null` pixels, `texStorage*`): zeros, but depth 1.0
    /// in depth formats, as Chromium initializes them (a shadow lookup of a depth texture
    /// nothing was drawn into passes), and alpha 1 in formats without alpha that are stored
    /// with it (`RGB8` as RGBA, `LUMINANCE`), which GL samples as 1.
    pub(crate) fn blank(size: [u32; 3], format: InternalFormat) -> Self {
        let texels = size[0] as usize * size[1] as usize * size[2] as usize;
        let stored_alpha = format.packing == Packing::None
            && (format.channels == 3 && format.expand == Expand::None
                || format.expand == Expand::Luminance);
        if stored_alpha {
            let cs = format.comp.size();
            let mut texel = vec![0; 3 * cs];
            texel.extend_from_slice(&format.comp.one()[..cs]);
            debug_assert_eq!(texel.len(), format.texel_size());
            return Level::new(size, format, texel.repeat(texels));
        }
        let one: &[u8] = match format.packing {
            Packing::Depth16 => &[0xFF; 2],
            Packing::Depth24 => &[0xFF; 4],
            Packing::Depth32F => &const { 1.0f32.to_ne_bytes() },
            Packing::Depth24Stencil8 => &const { 0xFFFF_FF00u32.to_ne_bytes() },
            Packing::Depth32FStencil8 => {
                &const {
                    let d = 1.0f32.to_ne_bytes();
                    [d[0], d[1], d[2], d[3], 0, 0, 0, 0]
                }
            }
            _ => return Level::new(size, format, vec![0; texels * format.texel_size()]),
        };
        debug_assert_eq!(one.len(), format.texel_size());
        Level::new(size, format, one.repeat(texels))
    }
}

/// A texture's parameters (`tex_parameteri`/`tex_parameterf`): how it is sampled, and the
/// range of levels used.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct TexParams {
    pub(crate) sampling: SamplerParams,
    pub(crate) base_level: u32,
    pub(crate) max_level: u32,
    /// `DEPTH_STENCIL_TEXTURE_MODE_WEBGL` (`WEBGL_stencil_texturing`): a depth-stencil
    /// texture is sampled for its stencil values (an unsigned integer texture).
    pub(crate) stencil_mode: bool,
}

impl Default for TexParams {
    fn default() -> Self {
        TexParams {
            sampling: SamplerParams::default(),
            base_level: 0,
            max_level: 1000,
            stencil_mode: false,
        }
    }
}

/// A texture object.
pub(crate) struct TextureObject {
    /// The target it was first bound to; fixed from then on.
    pub(crate) target: Option<u32>,
    /// `faces[face][level]`: 6 faces for a cube map, 1 otherwise.
    pub(crate) faces: Vec<Vec<Option<Level>>>,
    pub(crate) params: TexParams,
    /// Levels of an immutable texture (`tex_storage_*`).
    pub(crate) immutable_levels: Option<u32>,
    /// Bumped on every change of an image or of the GPU copy's shape.
    pub(crate) version: u64,
    pub(crate) gpu: Option<super::gpu::GpuTexture>,
}

/// What a complete texture uses: levels `base..base + levels`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Complete {
    pub(crate) base: u32,
    pub(crate) levels: u32,
    pub(crate) format: InternalFormat,
    /// Sampled for its stencil values (`WEBGL_stencil_texturing`): an unsigned integer
    /// texture of the stencil aspect.
    pub(crate) stencil: bool,
}

pub(super) fn mip_size(size: u32, level: u32) -> u32 {
    (size >> level.min(31)).max(1)
}

impl TextureObject {
    pub(super) fn new() -> Self {
        TextureObject {
            target: None,
            faces: Vec::new(),
            params: TexParams::default(),
            immutable_levels: None,
            version: 0,
            gpu: None,
        }
    }

    pub(crate) fn level(&self, face: usize, level: u32) -> Option<&Level> {
        self.faces.get(face)?.get(level as usize)?.as_ref()
    }

    /// What sampling reads whether or not the texture is complete: the base level's format,
    /// and whether the stencil is sampled (`WEBGL_stencil_texturing`); `None` without a base
    /// level.
    pub(crate) fn sampled_format(&self) -> Option<(InternalFormat, bool)> {
        let (base, _) = self.level_range();
        let format = self.level(0, base)?.format;
        Some((format, self.params.stencil_mode && format.has_stencil()))
    }

    /// Mutable [`TextureObject::level`].
    pub(crate) fn level_mut(&mut self, face: usize, level: u32) -> Option<&mut Level> {
        self.faces.get_mut(face)?.get_mut(level as usize)?.as_mut()
    }

    /// The number of faces: 6 for a cube map, else 1.
    pub(crate) fn face_count(&self) -> usize {
        if self.target == Some(gl::TEXTURE_CUBE_MAP) {
            6
        } else {
            1
        }
    }

    pub(crate) fn set_level(&mut self, face: usize, level: u32, image: Level) {
        let faces = self.face_count();
        if self.faces.len() < faces {
            self.faces.resize_with(faces, Vec::new);
        }
        let levels = &mut self.faces[face];
        if levels.len() <= level as usize {
            levels.resize_with(level as usize + 1, || None);
        }
        levels[level as usize] = Some(image);
        self.version += 1;
    }

    /// The effective base and max levels (clamped for immutable textures, ES 3.0 §3.8.10).
    pub(crate) fn level_range(&self) -> (u32, u32) {
        let p = &self.params;
        match self.immutable_levels {
            Some(n) => {
                let base = p.base_level.min(n - 1);
                (base, p.max_level.clamp(base, n - 1))
            }
            None => (p.base_level, p.max_level),
        }
    }

    /// Whether `level` of this texture may be a framebuffer attachment by ES 3.0 §4.4.4: an
    /// immutable texture's any level; a mutable one's a level in `[base, q]` (q the last level
    /// a complete mipmap chain from the base level reaches, at most the max level), and one
    /// other than the base only while the texture is mipmap complete.
    pub(crate) fn attachable_level(&self, level: u32) -> bool {
        if self.immutable_levels.is_some() {
            return true;
        }
        let (base, max) = self.level_range();
        if base > max {
            return false;
        }
        if level == base {
            return true;
        }
        let mipmapped = SamplerParams {
            min_filter: gl::NEAREST_MIPMAP_NEAREST,
            mag_filter: gl::NEAREST,
            ..SamplerParams::default()
        };
        self.completeness(true, true, false, &mipmapped)
            .is_some_and(|c| level > base && level < base + c.levels)
    }

    /// GL ES 3.0's texture completeness (§3.8.13): `None` when incomplete, in which case
    /// sampling returns (0, 0, 0, 1). 32-bit float formats filter linearly with
    /// `float_linear`, 16-bit ones only with `half_linear` (always in WebGL 2; in WebGL 1
    /// with `OES_texture_half_float_linear`).
    /// With `webgl1`, WebGL 1's rule too: a base image of a non-power-of-two size is complete
    /// only without mipmaps and with `CLAMP_TO_EDGE` wrapping (ES 2.0 § 3.8.2).
    pub(crate) fn completeness(
        &self,
        float_linear: bool,
        half_linear: bool,
        webgl1: bool,
        p: &SamplerParams,
    ) -> Option<Complete> {
        if webgl1 {
            let first = self.level(0, self.level_range().0)?;
            let npot = !first.width.is_power_of_two() || !first.height.is_power_of_two();
            let clamped = p.wrap_s == gl::CLAMP_TO_EDGE && p.wrap_t == gl::CLAMP_TO_EDGE;
            if npot && (p.mipmapped() || !clamped) {
                return None;
            }
        }
        let target = self.target?;
        let (base, max) = self.level_range();
        let faces = if target == gl::TEXTURE_CUBE_MAP { 6 } else { 1 };
        let first = self.level(0, base)?;
        if first.width == 0 || first.height == 0 || first.depth == 0 {
            return None;
        }
        let format = first.format;
        for face in 1..faces {
            let l = self.level(face, base)?;
            if (l.width, l.height, l.depth, l.format)
                != (first.width, first.height, first.depth, format)
            {
                return None;
            }
        }
        if target == gl::TEXTURE_CUBE_MAP && first.width != first.height {
            return None;
        }
        // A depth-stencil texture sampled for its stencil is an integer texture.
        let stencil = self.params.stencil_mode && format.has_stencil();
        // Depth formats filter only when compared (ES 3.0 §3.8.13).
        let compared = format.has_depth() && p.compare_mode == gl::COMPARE_REF_TO_TEXTURE;
        let half = format.comp == super::format::Comp::F16 && format.packing == Packing::None;
        // WebGL 1's depth textures (WEBGL_depth_texture) take LINEAR, read as NEAREST.
        let filterable = !stencil
            && ((format.filterable() && (half_linear || !half))
                || compared
                || (webgl1 && format.has_depth())
                || (float_linear
                    && format.comp == super::format::Comp::F32
                    && format.packing == super::format::Packing::None));
        if !filterable
            && (p.mag_filter != gl::NEAREST
                || !matches!(p.min_filter, gl::NEAREST | gl::NEAREST_MIPMAP_NEAREST))
        {
            return None;
        }
        if !p.mipmapped() {
            return Some(Complete {
                base,
                levels: 1,
                format,
                stencil,
            });
        }
        if base > max {
            return None;
        }
        let largest = match target {
            gl::TEXTURE_3D => first.width.max(first.height).max(first.depth),
            _ => first.width.max(first.height),
        };
        let q = (base + (31 - largest.leading_zeros())).min(max);
        for level in base + 1..=q {
            let i = level - base;
            let depth = if target == gl::TEXTURE_3D {
                mip_size(first.depth, i)
            } else {
                first.depth
            };
            let want = (
                mip_size(first.width, i),
                mip_size(first.height, i),
                depth,
                format,
            );
            for face in 0..faces {
                let l = self.level(face, level)?;
                if (l.width, l.height, l.depth, l.format) != want {
                    return None;
                }
            }
        }
        Some(Complete {
            base,
            levels: q - base + 1,
            format,
            stencil,
        })
    }

    /// The sampler a texture is sampled with, with sampling parameters `p` (its own or a
    /// bound sampler object's).
    pub(crate) fn sampler_key(p: &SamplerParams, comparison: bool) -> SamplerKey {
        let filter = |f: u32| match f {
            gl::NEAREST | gl::NEAREST_MIPMAP_NEAREST | gl::NEAREST_MIPMAP_LINEAR => {
                wgpu::FilterMode::Nearest
            }
            _ => wgpu::FilterMode::Linear,
        };
        let (mip, lod_min, lod_max) = if p.mipmapped() {
            let mip = match p.min_filter {
                gl::NEAREST_MIPMAP_NEAREST | gl::LINEAR_MIPMAP_NEAREST => {
                    wgpu::MipmapFilterMode::Nearest
                }
                _ => wgpu::MipmapFilterMode::Linear,
            };
            let lo = p.min_lod.clamp(0.0, 1000.0);
            let hi = p.max_lod.min(1000.0).max(lo);
            (mip, lo, hi)
        } else {
            // Vulkan's way to sample only the base level while keeping the
            // minification/magnification choice: a maximum LOD of 0.25.
            (wgpu::MipmapFilterMode::Nearest, 0.0, 0.25)
        };
        let wrap = |w: u32| match w {
            gl::CLAMP_TO_EDGE => wgpu::AddressMode::ClampToEdge,
            gl::MIRRORED_REPEAT => wgpu::AddressMode::MirrorRepeat,
            _ => wgpu::AddressMode::Repeat,
        };
        let (min, mag) = (filter(p.min_filter), filter(p.mag_filter));
        // wgpu takes an anisotropy clamp only where every filter is linear.
        let linear = wgpu::FilterMode::Linear;
        let anisotropy = if min == linear && mag == linear && mip == wgpu::MipmapFilterMode::Linear
        {
            p.max_anisotropy.min(crate::extensions::MAX_ANISOTROPY) as u16
        } else {
            1
        };
        SamplerKey {
            min,
            mag,
            mip,
            anisotropy,
            wrap: [wrap(p.wrap_s), wrap(p.wrap_t), wrap(p.wrap_r)],
            lod_min: lod_min.to_bits(),
            lod_max: lod_max.to_bits(),
            compare: comparison.then(|| compare_function(p.compare_func)),
        }
    }
}

/// The view dimension for a texture target.
pub(crate) fn view_dimension(target: u32) -> wgpu::TextureViewDimension {
    match target {
        gl::TEXTURE_CUBE_MAP => wgpu::TextureViewDimension::Cube,
        gl::TEXTURE_3D => wgpu::TextureViewDimension::D3,
        gl::TEXTURE_2D_ARRAY => wgpu::TextureViewDimension::D2Array,
        _ => wgpu::TextureViewDimension::D2,
    }
}
