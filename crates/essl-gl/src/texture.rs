//! Textures: `create_texture`, `bind_texture`, `active_texture`, `tex_image_2d`,
//! `tex_sub_image_2d`, `tex_image_3d`, `tex_storage_2d`, `tex_parameteri`, `generate_mipmap`,
//! GL's texture completeness, and the samplers and placeholder textures draws bind.
//!
//! Each level image is kept on the CPU in the GPU format's layout; a texture is (re)made on
//! the GPU when a draw samples it, from level `TEXTURE_BASE_LEVEL` to the last level that
//! completeness uses. Data row 0 is texture row 0 (`t = 0`), as in GL, with no flip.

use std::collections::HashMap;

use crate::context::{Context, Gpu, MAX_TEXTURE_UNITS};
use crate::gl;
use crate::objects::{Id, Texture};
use crate::state::{is_compare_func, PixelStore};

/// The component type of an internal format's storage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Comp {
    Unorm8,
    Snorm8,
    U8,
    I8,
    U16,
    I16,
    U32,
    I32,
    F16,
    F32,
}

impl Comp {
    fn size(self) -> usize {
        match self {
            Comp::Unorm8 | Comp::Snorm8 | Comp::U8 | Comp::I8 => 1,
            Comp::U16 | Comp::I16 | Comp::F16 => 2,
            Comp::U32 | Comp::I32 | Comp::F32 => 4,
        }
    }

    /// The GL type whose components are stored as they are.
    fn native_type(self) -> u32 {
        match self {
            Comp::Unorm8 | Comp::U8 => gl::UNSIGNED_BYTE,
            Comp::Snorm8 | Comp::I8 => gl::BYTE,
            Comp::U16 => gl::UNSIGNED_SHORT,
            Comp::I16 => gl::SHORT,
            Comp::U32 => gl::UNSIGNED_INT,
            Comp::I32 => gl::INT,
            Comp::F16 => gl::HALF_FLOAT,
            Comp::F32 => gl::FLOAT,
        }
    }

    /// The bytes of 1 (the alpha GL supplies for RGB data).
    fn one(self) -> [u8; 4] {
        let mut b = [0u8; 4];
        match self {
            Comp::Unorm8 => b[0] = 0xFF,
            Comp::Snorm8 => b[0] = 0x7F,
            Comp::U8 | Comp::I8 => b[0] = 1,
            Comp::U16 | Comp::I16 => b[..2].copy_from_slice(&1u16.to_ne_bytes()),
            Comp::U32 | Comp::I32 => b.copy_from_slice(&1u32.to_ne_bytes()),
            Comp::F16 => b[..2].copy_from_slice(&0x3C00u16.to_ne_bytes()),
            Comp::F32 => b.copy_from_slice(&1.0f32.to_ne_bytes()),
        }
        b
    }

    fn kind(self) -> SampleKind {
        match self {
            Comp::Unorm8 | Comp::Snorm8 | Comp::F16 | Comp::F32 => SampleKind::Float,
            Comp::I8 | Comp::I16 | Comp::I32 => SampleKind::Sint,
            Comp::U8 | Comp::U16 | Comp::U32 => SampleKind::Uint,
        }
    }
}

/// What sampling a texture returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum SampleKind {
    /// Floats (normalized, half or float formats).
    Float,
    /// Signed integers.
    Sint,
    /// Unsigned integers.
    Uint,
    /// Depth comparisons (shadow samplers).
    Depth,
}

/// How a legacy unsized format spreads its channels over RGBA.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Expand {
    None,
    Luminance,
    Alpha,
    LuminanceAlpha,
}

/// An internal format that essl-gl supports, and how it is stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct InternalFormat {
    /// GL's enum, as given (`RGBA` and `RGBA8` are different internal formats).
    pub(crate) gl: u32,
    /// The `format` argument that goes with it (`RGBA`, `RED_INTEGER`, `LUMINANCE`, …).
    pub(crate) base: u32,
    /// Channels of the data.
    pub(crate) channels: u8,
    pub(crate) comp: Comp,
    pub(crate) srgb: bool,
    pub(crate) expand: Expand,
}

impl InternalFormat {
    /// Channels of the GPU texture (RGB and the legacy formats are stored as RGBA).
    fn gpu_channels(&self) -> u8 {
        match (self.expand, self.channels) {
            (Expand::None, 3) => 4,
            (Expand::None, n) => n,
            _ => 4,
        }
    }

    /// Bytes per texel on the GPU (and in the CPU copy).
    pub(crate) fn texel_size(&self) -> usize {
        self.gpu_channels() as usize * self.comp.size()
    }

    /// The wgpu format of the GPU texture.
    pub(crate) fn gpu_format(&self) -> wgpu::TextureFormat {
        use wgpu::TextureFormat as F;
        match (self.comp, self.gpu_channels(), self.srgb) {
            (Comp::Unorm8, 4, true) => F::Rgba8UnormSrgb,
            (Comp::Unorm8, 1, _) => F::R8Unorm,
            (Comp::Unorm8, 2, _) => F::Rg8Unorm,
            (Comp::Unorm8, _, _) => F::Rgba8Unorm,
            (Comp::Snorm8, 1, _) => F::R8Snorm,
            (Comp::Snorm8, 2, _) => F::Rg8Snorm,
            (Comp::Snorm8, _, _) => F::Rgba8Snorm,
            (Comp::U8, 1, _) => F::R8Uint,
            (Comp::U8, 2, _) => F::Rg8Uint,
            (Comp::U8, _, _) => F::Rgba8Uint,
            (Comp::I8, 1, _) => F::R8Sint,
            (Comp::I8, 2, _) => F::Rg8Sint,
            (Comp::I8, _, _) => F::Rgba8Sint,
            (Comp::U16, 1, _) => F::R16Uint,
            (Comp::U16, 2, _) => F::Rg16Uint,
            (Comp::U16, _, _) => F::Rgba16Uint,
            (Comp::I16, 1, _) => F::R16Sint,
            (Comp::I16, 2, _) => F::Rg16Sint,
            (Comp::I16, _, _) => F::Rgba16Sint,
            (Comp::U32, 1, _) => F::R32Uint,
            (Comp::U32, 2, _) => F::Rg32Uint,
            (Comp::U32, _, _) => F::Rgba32Uint,
            (Comp::I32, 1, _) => F::R32Sint,
            (Comp::I32, 2, _) => F::Rg32Sint,
            (Comp::I32, _, _) => F::Rgba32Sint,
            (Comp::F16, 1, _) => F::R16Float,
            (Comp::F16, 2, _) => F::Rg16Float,
            (Comp::F16, _, _) => F::Rgba16Float,
            (Comp::F32, 1, _) => F::R32Float,
            (Comp::F32, 2, _) => F::Rg32Float,
            (Comp::F32, _, _) => F::Rgba32Float,
        }
    }

    /// Whether GL ES 3.0 lets the format be filtered linearly (32-bit floats and integers not).
    pub(crate) fn filterable(&self) -> bool {
        matches!(self.comp, Comp::Unorm8 | Comp::Snorm8 | Comp::F16)
    }

    pub(crate) fn kind(&self) -> SampleKind {
        self.comp.kind()
    }

    /// Whether `(format, ty)` data may be uploaded to this internal format (ES 3.0 table 3.2).
    fn accepts(&self, format: u32, ty: u32) -> bool {
        if format != self.base {
            return false;
        }
        if ty == self.comp.native_type() {
            return true;
        }
        match ty {
            gl::FLOAT => self.comp == Comp::F16,
            gl::UNSIGNED_SHORT_5_6_5 => matches!(self.gl, gl::RGB | gl::RGB565),
            gl::UNSIGNED_SHORT_4_4_4_4 => matches!(self.gl, gl::RGBA | gl::RGBA4),
            gl::UNSIGNED_SHORT_5_5_5_1 => matches!(self.gl, gl::RGBA | gl::RGB5_A1),
            _ => false,
        }
    }
}

/// The internal formats essl-gl supports; `Err(true)` for a GL format it does not support,
/// `Err(false)` for a value that is no internal format.
pub(crate) fn internal_format(internal: u32) -> Result<InternalFormat, bool> {
    use Comp::*;
    let f = |base, channels, comp, srgb, expand| InternalFormat {
        gl: internal,
        base,
        channels,
        comp,
        srgb,
        expand,
    };
    let plain = |base, channels, comp| f(base, channels, comp, false, Expand::None);
    Ok(match internal {
        gl::RGBA | gl::RGBA8 | gl::RGBA4 | gl::RGB5_A1 => plain(gl::RGBA, 4, Unorm8),
        gl::RGB | gl::RGB8 | gl::RGB565 => plain(gl::RGB, 3, Unorm8),
        gl::LUMINANCE => f(gl::LUMINANCE, 1, Unorm8, false, Expand::Luminance),
        gl::ALPHA => f(gl::ALPHA, 1, Unorm8, false, Expand::Alpha),
        gl::LUMINANCE_ALPHA => f(
            gl::LUMINANCE_ALPHA,
            2,
            Unorm8,
            false,
            Expand::LuminanceAlpha,
        ),
        gl::SRGB8_ALPHA8 => f(gl::RGBA, 4, Unorm8, true, Expand::None),
        gl::SRGB8 => f(gl::RGB, 3, Unorm8, true, Expand::None),
        gl::R8 => plain(gl::RED, 1, Unorm8),
        gl::RG8 => plain(gl::RG, 2, Unorm8),
        gl::R8_SNORM => plain(gl::RED, 1, Snorm8),
        gl::RG8_SNORM => plain(gl::RG, 2, Snorm8),
        gl::RGB8_SNORM => plain(gl::RGB, 3, Snorm8),
        gl::RGBA8_SNORM => plain(gl::RGBA, 4, Snorm8),
        gl::R16F => plain(gl::RED, 1, F16),
        gl::RG16F => plain(gl::RG, 2, F16),
        gl::RGB16F => plain(gl::RGB, 3, F16),
        gl::RGBA16F => plain(gl::RGBA, 4, F16),
        gl::R32F => plain(gl::RED, 1, F32),
        gl::RG32F => plain(gl::RG, 2, F32),
        gl::RGB32F => plain(gl::RGB, 3, F32),
        gl::RGBA32F => plain(gl::RGBA, 4, F32),
        gl::R8UI => plain(gl::RED_INTEGER, 1, U8),
        gl::RG8UI => plain(gl::RG_INTEGER, 2, U8),
        gl::RGB8UI => plain(gl::RGB_INTEGER, 3, U8),
        gl::RGBA8UI => plain(gl::RGBA_INTEGER, 4, U8),
        gl::R8I => plain(gl::RED_INTEGER, 1, I8),
        gl::RG8I => plain(gl::RG_INTEGER, 2, I8),
        gl::RGB8I => plain(gl::RGB_INTEGER, 3, I8),
        gl::RGBA8I => plain(gl::RGBA_INTEGER, 4, I8),
        gl::R16UI => plain(gl::RED_INTEGER, 1, U16),
        gl::RG16UI => plain(gl::RG_INTEGER, 2, U16),
        gl::RGB16UI => plain(gl::RGB_INTEGER, 3, U16),
        gl::RGBA16UI => plain(gl::RGBA_INTEGER, 4, U16),
        gl::R16I => plain(gl::RED_INTEGER, 1, I16),
        gl::RG16I => plain(gl::RG_INTEGER, 2, I16),
        gl::RGB16I => plain(gl::RGB_INTEGER, 3, I16),
        gl::RGBA16I => plain(gl::RGBA_INTEGER, 4, I16),
        gl::R32UI => plain(gl::RED_INTEGER, 1, U32),
        gl::RG32UI => plain(gl::RG_INTEGER, 2, U32),
        gl::RGB32UI => plain(gl::RGB_INTEGER, 3, U32),
        gl::RGBA32UI => plain(gl::RGBA_INTEGER, 4, U32),
        gl::R32I => plain(gl::RED_INTEGER, 1, I32),
        gl::RG32I => plain(gl::RG_INTEGER, 2, I32),
        gl::RGB32I => plain(gl::RGB_INTEGER, 3, I32),
        gl::RGBA32I => plain(gl::RGBA_INTEGER, 4, I32),
        gl::R11F_G11F_B10F
        | gl::RGB9_E5
        | gl::RGB10_A2
        | gl::RGB10_A2UI
        | gl::DEPTH_COMPONENT16
        | gl::DEPTH_COMPONENT24
        | gl::DEPTH_COMPONENT32F
        | gl::DEPTH24_STENCIL8
        | gl::DEPTH32F_STENCIL8
        | gl::DEPTH_COMPONENT
        | gl::DEPTH_STENCIL => return Err(true),
        _ => return Err(false),
    })
}

fn format_channels(format: u32) -> Option<usize> {
    match format {
        gl::RED | gl::RED_INTEGER | gl::LUMINANCE | gl::ALPHA => Some(1),
        gl::RG | gl::RG_INTEGER | gl::LUMINANCE_ALPHA => Some(2),
        gl::RGB | gl::RGB_INTEGER => Some(3),
        gl::RGBA | gl::RGBA_INTEGER => Some(4),
        _ => None,
    }
}

fn is_pixel_type(ty: u32) -> bool {
    matches!(
        ty,
        gl::UNSIGNED_BYTE
            | gl::BYTE
            | gl::UNSIGNED_SHORT
            | gl::SHORT
            | gl::UNSIGNED_INT
            | gl::INT
            | gl::HALF_FLOAT
            | gl::FLOAT
            | gl::UNSIGNED_SHORT_5_6_5
            | gl::UNSIGNED_SHORT_4_4_4_4
            | gl::UNSIGNED_SHORT_5_5_5_1
    )
}

/// Bytes per pixel of client data in `(format, ty)`.
fn pixel_size(format: u32, ty: u32) -> usize {
    match ty {
        gl::UNSIGNED_SHORT_5_6_5 | gl::UNSIGNED_SHORT_4_4_4_4 | gl::UNSIGNED_SHORT_5_5_5_1 => 2,
        _ => {
            let comp = match ty {
                gl::UNSIGNED_BYTE | gl::BYTE => 1,
                gl::UNSIGNED_SHORT | gl::SHORT | gl::HALF_FLOAT => 2,
                _ => 4,
            };
            format_channels(format).unwrap_or(4) * comp
        }
    }
}

/// Converts an `f32` to IEEE half-precision bits, rounding to nearest even.
pub(crate) fn f32_to_f16(x: f32) -> u16 {
    let b = x.to_bits();
    let sign = ((b >> 16) & 0x8000) as u16;
    let exp = ((b >> 23) & 0xFF) as i32;
    let mant = b & 0x7F_FFFF;
    if exp == 0xFF {
        return sign | 0x7C00 | if mant != 0 { 0x200 } else { 0 };
    }
    let e = exp - 127 + 15;
    if e >= 0x1F {
        return sign | 0x7C00;
    }
    if e <= 0 {
        if e < -10 {
            return sign;
        }
        let m = mant | 0x80_0000;
        let shift = (14 - e) as u32;
        let half = 1u32 << (shift - 1);
        let mut r = m >> shift;
        let rem = m & ((1 << shift) - 1);
        if rem > half || (rem == half && r & 1 == 1) {
            r += 1;
        }
        return sign | r as u16;
    }
    let mut r = ((e as u32) << 10) | (mant >> 13);
    let rem = mant & 0x1FFF;
    if rem > 0x1000 || (rem == 0x1000 && r & 1 == 1) {
        r += 1;
    }
    sign | r as u16
}

fn unpack_16(v: u16, ty: u32) -> [u8; 4] {
    let scale = |x: u16, bits: u32| -> u8 {
        let max = (1u32 << bits) - 1;
        ((x as u32 * 255 + max / 2) / max) as u8
    };
    match ty {
        gl::UNSIGNED_SHORT_5_6_5 => [
            scale(v >> 11, 5),
            scale((v >> 5) & 0x3F, 6),
            scale(v & 0x1F, 5),
            255,
        ],
        gl::UNSIGNED_SHORT_4_4_4_4 => [
            scale(v >> 12, 4),
            scale((v >> 8) & 0xF, 4),
            scale((v >> 4) & 0xF, 4),
            scale(v & 0xF, 4),
        ],
        _ => [
            scale(v >> 11, 5),
            scale((v >> 6) & 0x1F, 5),
            scale((v >> 1) & 0x1F, 5),
            if v & 1 != 0 { 255 } else { 0 },
        ],
    }
}

/// Converts `count` pixels of `(format, ty)` client data to the storage of `f`.
fn convert_pixels(src: &[u8], count: usize, f: &InternalFormat, ty: u32, out: &mut Vec<u8>) {
    if matches!(
        ty,
        gl::UNSIGNED_SHORT_5_6_5 | gl::UNSIGNED_SHORT_4_4_4_4 | gl::UNSIGNED_SHORT_5_5_5_1
    ) {
        for px in src.chunks_exact(2).take(count) {
            out.extend_from_slice(&unpack_16(u16::from_ne_bytes([px[0], px[1]]), ty));
        }
        return;
    }
    let cs = f.comp.size();
    let src_cs = if ty == gl::FLOAT { 4 } else { cs };
    let n = f.channels as usize;
    let one = f.comp.one();
    let zero = [0u8; 4];
    let comp = |px: &[u8], c: usize| -> [u8; 4] {
        let s = &px[c * src_cs..(c + 1) * src_cs];
        let mut b = [0u8; 4];
        if src_cs == cs {
            b[..cs].copy_from_slice(s);
        } else {
            let v = f32::from_ne_bytes([s[0], s[1], s[2], s[3]]);
            b[..2].copy_from_slice(&f32_to_f16(v).to_ne_bytes());
        }
        b
    };
    for px in src.chunks_exact(n * src_cs).take(count) {
        let mut push = |b: [u8; 4]| out.extend_from_slice(&b[..cs]);
        match f.expand {
            Expand::None => {
                for c in 0..n {
                    push(comp(px, c));
                }
                if n == 3 {
                    push(one);
                }
            }
            Expand::Luminance => {
                let l = comp(px, 0);
                [l, l, l, one].into_iter().for_each(push);
            }
            Expand::Alpha => [zero, zero, zero, comp(px, 0)].into_iter().for_each(push),
            Expand::LuminanceAlpha => {
                let l = comp(px, 0);
                [l, l, l, comp(px, 1)].into_iter().for_each(push);
            }
        }
    }
}

/// One level image (of one cube face).
#[derive(Clone, Debug)]
pub(crate) struct Level {
    pub(crate) width: u32,
    pub(crate) height: u32,
    /// Depth of a 3D texture, layers of a 2D array, 1 otherwise.
    pub(crate) depth: u32,
    pub(crate) format: InternalFormat,
    /// Texels in the GPU format, tightly packed, row 0 first.
    pub(crate) data: Vec<u8>,
}

/// Sampling parameters (`tex_parameteri`/`tex_parameterf`).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct TexParams {
    pub(crate) min_filter: u32,
    pub(crate) mag_filter: u32,
    pub(crate) wrap_s: u32,
    pub(crate) wrap_t: u32,
    pub(crate) wrap_r: u32,
    pub(crate) min_lod: f32,
    pub(crate) max_lod: f32,
    pub(crate) base_level: u32,
    pub(crate) max_level: u32,
    pub(crate) compare_mode: u32,
    pub(crate) compare_func: u32,
}

impl Default for TexParams {
    fn default() -> Self {
        TexParams {
            min_filter: gl::NEAREST_MIPMAP_LINEAR,
            mag_filter: gl::LINEAR,
            wrap_s: gl::REPEAT,
            wrap_t: gl::REPEAT,
            wrap_r: gl::REPEAT,
            min_lod: -1000.0,
            max_lod: 1000.0,
            base_level: 0,
            max_level: 1000,
            compare_mode: gl::NONE,
            compare_func: gl::LEQUAL,
        }
    }
}

impl TexParams {
    fn mipmapped(&self) -> bool {
        !matches!(self.min_filter, gl::NEAREST | gl::LINEAR)
    }
}

/// The GPU copy of a texture: levels `base..base + levels` of the GL texture.
pub(crate) struct GpuTexture {
    pub(crate) view: wgpu::TextureView,
    texture: wgpu::Texture,
    base: u32,
    levels: u32,
    version: u64,
    pub(crate) last_batch: u64,
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
    /// Bumped on every change of an image.
    pub(crate) version: u64,
    pub(crate) gpu: Option<GpuTexture>,
}

/// What a complete texture uses: levels `base..base + levels`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Complete {
    pub(crate) base: u32,
    pub(crate) levels: u32,
    pub(crate) format: InternalFormat,
}

fn mip_size(size: u32, level: u32) -> u32 {
    (size >> level.min(31)).max(1)
}

impl TextureObject {
    fn new() -> Self {
        TextureObject {
            target: None,
            faces: Vec::new(),
            params: TexParams::default(),
            immutable_levels: None,
            version: 0,
            gpu: None,
        }
    }

    fn level(&self, face: usize, level: u32) -> Option<&Level> {
        self.faces.get(face)?.get(level as usize)?.as_ref()
    }

    fn set_level(&mut self, face: usize, level: u32, image: Level) {
        let faces = if self.target == Some(gl::TEXTURE_CUBE_MAP) {
            6
        } else {
            1
        };
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
    fn level_range(&self) -> (u32, u32) {
        let p = &self.params;
        match self.immutable_levels {
            Some(n) => {
                let base = p.base_level.min(n - 1);
                (base, p.max_level.clamp(base, n - 1))
            }
            None => (p.base_level, p.max_level),
        }
    }

    /// GL ES 3.0's texture completeness (§3.8.13): `None` when incomplete, in which case
    /// sampling returns (0, 0, 0, 1).
    pub(crate) fn completeness(&self) -> Option<Complete> {
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
        let p = &self.params;
        if !format.filterable()
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
        })
    }

    /// The GPU texture view for a complete texture, made or updated as needed.
    pub(crate) fn gpu_view(&mut self, gpu: &Gpu, serial: u64, c: &Complete) -> wgpu::TextureView {
        if let Some(g) = &mut self.gpu {
            if g.version == self.version && g.base == c.base && g.levels == c.levels {
                g.last_batch = serial;
                return g.view.clone();
            }
        }
        let target = self.target.expect("complete textures have a target");
        let first = self.level(0, c.base).expect("complete");
        let (width, height, depth) = (first.width, first.height, first.depth);
        let layers = if target == gl::TEXTURE_CUBE_MAP {
            6
        } else {
            depth
        };
        let same_shape = self.gpu.as_ref().is_some_and(|g| {
            g.base == c.base
                && g.levels == c.levels
                && g.last_batch != serial
                && g.texture.format() == c.format.gpu_format()
                && g.texture.width() == width
                && g.texture.height() == height
                && g.texture.depth_or_array_layers() == layers
        });
        if !same_shape {
            let dimension = if target == gl::TEXTURE_3D {
                wgpu::TextureDimension::D3
            } else {
                wgpu::TextureDimension::D2
            };
            let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
                label: Some("essl-gl texture"),
                size: wgpu::Extent3d {
                    width,
                    height,
                    depth_or_array_layers: layers,
                },
                mip_level_count: c.levels,
                sample_count: 1,
                dimension,
                format: c.format.gpu_format(),
                usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            });
            let view = texture.create_view(&wgpu::TextureViewDescriptor {
                dimension: Some(view_dimension(target)),
                ..Default::default()
            });
            self.gpu = Some(GpuTexture {
                view,
                texture,
                base: c.base,
                levels: c.levels,
                version: 0,
                last_batch: 0,
            });
        }
        let faces = if target == gl::TEXTURE_CUBE_MAP { 6 } else { 1 };
        let g = self.gpu.as_ref().expect("made above");
        for i in 0..c.levels {
            for face in 0..faces {
                let l = self.faces[face][(c.base + i) as usize]
                    .as_ref()
                    .expect("complete");
                let texel = l.format.texel_size() as u32;
                gpu.queue.write_texture(
                    wgpu::TexelCopyTextureInfo {
                        texture: &g.texture,
                        mip_level: i,
                        origin: wgpu::Origin3d {
                            x: 0,
                            y: 0,
                            z: face as u32,
                        },
                        aspect: wgpu::TextureAspect::All,
                    },
                    &l.data,
                    wgpu::TexelCopyBufferLayout {
                        offset: 0,
                        bytes_per_row: Some(l.width * texel),
                        rows_per_image: Some(l.height),
                    },
                    wgpu::Extent3d {
                        width: l.width,
                        height: l.height,
                        depth_or_array_layers: l.depth,
                    },
                );
            }
        }
        let version = self.version;
        let g = self.gpu.as_mut().expect("made above");
        g.version = version;
        g.last_batch = serial;
        g.view.clone()
    }

    /// The sampler a complete texture is sampled with.
    pub(crate) fn sampler_key(&self, comparison: bool) -> SamplerKey {
        let p = &self.params;
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
        SamplerKey {
            min: filter(p.min_filter),
            mag: filter(p.mag_filter),
            mip,
            wrap: [wrap(p.wrap_s), wrap(p.wrap_t), wrap(p.wrap_r)],
            lod_min: lod_min.to_bits(),
            lod_max: lod_max.to_bits(),
            compare: comparison.then(|| compare_function(p.compare_func)),
        }
    }
}

/// wgpu's comparison function for a GL one.
pub(crate) fn compare_function(func: u32) -> wgpu::CompareFunction {
    match func {
        gl::NEVER => wgpu::CompareFunction::Never,
        gl::LESS => wgpu::CompareFunction::Less,
        gl::EQUAL => wgpu::CompareFunction::Equal,
        gl::LEQUAL => wgpu::CompareFunction::LessEqual,
        gl::GREATER => wgpu::CompareFunction::Greater,
        gl::NOTEQUAL => wgpu::CompareFunction::NotEqual,
        gl::GEQUAL => wgpu::CompareFunction::GreaterEqual,
        _ => wgpu::CompareFunction::Always,
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

/// The textures bound to one texture unit, one per target.
#[derive(Clone, Debug, Default)]
pub(crate) struct TextureUnit {
    pub(crate) d2: Option<Id>,
    pub(crate) cube: Option<Id>,
    pub(crate) d3: Option<Id>,
    pub(crate) d2_array: Option<Id>,
}

impl TextureUnit {
    pub(crate) fn get(&self, target: u32) -> Option<Id> {
        match target {
            gl::TEXTURE_2D => self.d2,
            gl::TEXTURE_CUBE_MAP => self.cube,
            gl::TEXTURE_3D => self.d3,
            _ => self.d2_array,
        }
    }

    fn slot(&mut self, target: u32) -> &mut Option<Id> {
        match target {
            gl::TEXTURE_2D => &mut self.d2,
            gl::TEXTURE_CUBE_MAP => &mut self.cube,
            gl::TEXTURE_3D => &mut self.d3,
            _ => &mut self.d2_array,
        }
    }
}

/// A sampler's parameters, as a hashable key.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct SamplerKey {
    min: wgpu::FilterMode,
    mag: wgpu::FilterMode,
    mip: wgpu::MipmapFilterMode,
    wrap: [wgpu::AddressMode; 3],
    lod_min: u32,
    lod_max: u32,
    compare: Option<wgpu::CompareFunction>,
}

impl SamplerKey {
    /// A nearest, clamping sampler (for placeholder textures).
    pub(crate) fn placeholder(comparison: bool) -> Self {
        SamplerKey {
            min: wgpu::FilterMode::Nearest,
            mag: wgpu::FilterMode::Nearest,
            mip: wgpu::MipmapFilterMode::Nearest,
            wrap: [wgpu::AddressMode::ClampToEdge; 3],
            lod_min: 0.0f32.to_bits(),
            lod_max: 0.25f32.to_bits(),
            compare: comparison.then_some(wgpu::CompareFunction::LessEqual),
        }
    }
}

/// wgpu samplers by parameters.
#[derive(Default)]
pub(crate) struct SamplerCache {
    samplers: HashMap<SamplerKey, wgpu::Sampler>,
}

impl SamplerCache {
    pub(crate) fn get(&mut self, device: &wgpu::Device, key: SamplerKey) -> wgpu::Sampler {
        self.samplers
            .entry(key)
            .or_insert_with(|| {
                device.create_sampler(&wgpu::SamplerDescriptor {
                    label: Some("essl-gl sampler"),
                    address_mode_u: key.wrap[0],
                    address_mode_v: key.wrap[1],
                    address_mode_w: key.wrap[2],
                    mag_filter: key.mag,
                    min_filter: key.min,
                    mipmap_filter: key.mip,
                    lod_min_clamp: f32::from_bits(key.lod_min),
                    lod_max_clamp: f32::from_bits(key.lod_max),
                    compare: key.compare,
                    anisotropy_clamp: 1,
                    border_color: None,
                })
            })
            .clone()
    }
}

/// 1×1 textures reading (0, 0, 0, 1), bound where a sampler's unit has no complete texture.
#[derive(Default)]
pub(crate) struct Dummies {
    views: HashMap<(wgpu::TextureViewDimension, SampleKind), wgpu::TextureView>,
}

impl Dummies {
    pub(crate) fn get(
        &mut self,
        gpu: &Gpu,
        dim: wgpu::TextureViewDimension,
        kind: SampleKind,
    ) -> wgpu::TextureView {
        self.views
            .entry((dim, kind))
            .or_insert_with(|| {
                let (format, texel): (_, Vec<u8>) = match kind {
                    SampleKind::Float => (wgpu::TextureFormat::Rgba8Unorm, vec![0, 0, 0, 255]),
                    SampleKind::Sint => (
                        wgpu::TextureFormat::Rgba32Sint,
                        bytemuck::cast_slice(&[0i32, 0, 0, 1]).to_vec(),
                    ),
                    SampleKind::Uint => (
                        wgpu::TextureFormat::Rgba32Uint,
                        bytemuck::cast_slice(&[0u32, 0, 0, 1]).to_vec(),
                    ),
                    SampleKind::Depth => (wgpu::TextureFormat::Depth16Unorm, vec![0xFF, 0xFF]),
                };
                let layers = if dim == wgpu::TextureViewDimension::Cube {
                    6
                } else {
                    1
                };
                let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
                    label: Some("essl-gl placeholder texture"),
                    size: wgpu::Extent3d {
                        width: 1,
                        height: 1,
                        depth_or_array_layers: layers,
                    },
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: if dim == wgpu::TextureViewDimension::D3 {
                        wgpu::TextureDimension::D3
                    } else {
                        wgpu::TextureDimension::D2
                    },
                    format,
                    usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                    view_formats: &[],
                });
                for layer in 0..layers {
                    gpu.queue.write_texture(
                        wgpu::TexelCopyTextureInfo {
                            texture: &texture,
                            mip_level: 0,
                            origin: wgpu::Origin3d {
                                x: 0,
                                y: 0,
                                z: layer,
                            },
                            aspect: wgpu::TextureAspect::All,
                        },
                        &texel,
                        wgpu::TexelCopyBufferLayout {
                            offset: 0,
                            bytes_per_row: None,
                            rows_per_image: None,
                        },
                        wgpu::Extent3d {
                            width: 1,
                            height: 1,
                            depth_or_array_layers: 1,
                        },
                    );
                }
                texture.create_view(&wgpu::TextureViewDescriptor {
                    dimension: Some(dim),
                    ..Default::default()
                })
            })
            .clone()
    }
}

/// The texture binding target and cube face of an image target.
fn image_target(target: u32) -> Option<(u32, usize)> {
    match target {
        gl::TEXTURE_2D => Some((gl::TEXTURE_2D, 0)),
        gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z => Some((
            gl::TEXTURE_CUBE_MAP,
            (target - gl::TEXTURE_CUBE_MAP_POSITIVE_X) as usize,
        )),
        gl::TEXTURE_3D => Some((gl::TEXTURE_3D, 0)),
        gl::TEXTURE_2D_ARRAY => Some((gl::TEXTURE_2D_ARRAY, 0)),
        _ => None,
    }
}

fn is_texture_target(target: u32) -> bool {
    matches!(
        target,
        gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP | gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY
    )
}

/// Where a region of client pixel data lies, by GL's unpack rules.
struct Unpack {
    start: usize,
    row_stride: usize,
    image_stride: usize,
    pixel: usize,
    needed: usize,
}

fn unpack_layout(
    store: &PixelStore,
    w: u32,
    h: u32,
    d: u32,
    pixel: usize,
    three_d: bool,
) -> Unpack {
    let row_len = if store.unpack_row_length > 0 {
        store.unpack_row_length
    } else {
        w
    } as usize;
    let a = store.unpack_alignment as usize;
    let row_stride = (row_len * pixel).div_ceil(a) * a;
    let image_height = if three_d && store.unpack_image_height > 0 {
        store.unpack_image_height
    } else {
        h
    };
    let image_stride = row_stride * image_height as usize;
    let skip_images = if three_d {
        store.unpack_skip_images as usize
    } else {
        0
    };
    let start = skip_images * image_stride
        + store.unpack_skip_rows as usize * row_stride
        + store.unpack_skip_pixels as usize * pixel;
    let needed = if w == 0 || h == 0 || d == 0 {
        0
    } else {
        start + (d as usize - 1) * image_stride + (h as usize - 1) * row_stride + w as usize * pixel
    };
    Unpack {
        start,
        row_stride,
        image_stride,
        pixel,
        needed,
    }
}

impl Context {
    /// Creates a texture object (`createTexture`).
    pub fn create_texture(&mut self) -> Texture {
        Texture {
            ctx: self.id,
            id: self.textures.insert(TextureObject::new()),
        }
    }

    /// Whether `texture` names a live texture that was bound once (`isTexture`).
    pub fn is_texture(&self, texture: Texture) -> bool {
        texture.ctx == self.id
            && self
                .textures
                .get(texture.id)
                .is_some_and(|t| t.target.is_some())
    }

    /// Selects the texture unit that `bind_texture` and the `tex*` calls address
    /// (`activeTexture`): `TEXTURE0 + i` for `i` below 32, else `INVALID_ENUM`.
    pub fn active_texture(&mut self, texture: u32) {
        match texture.checked_sub(gl::TEXTURE0) {
            Some(i) if i < MAX_TEXTURE_UNITS => self.active_texture = i,
            _ => self.error(
                gl::INVALID_ENUM,
                "activeTexture",
                format_args!("0x{texture:04X}"),
            ),
        }
    }

    /// Binds a texture to a target of the active unit (`bindTexture`): `TEXTURE_2D`,
    /// `TEXTURE_CUBE_MAP`, `TEXTURE_3D`, `TEXTURE_2D_ARRAY`. A texture keeps the target it
    /// was first bound to (`INVALID_OPERATION` for another).
    pub fn bind_texture(&mut self, target: u32, texture: Option<Texture>) {
        const F: &str = "bindTexture";
        if !is_texture_target(target) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        let id = match texture {
            None => None,
            Some(t) => {
                if !self.owns(t.ctx, F) {
                    return;
                }
                let Some(obj) = self.textures.get_mut(t.id) else {
                    return self.error(gl::INVALID_OPERATION, F, "deleted texture");
                };
                match obj.target {
                    None => obj.target = Some(target),
                    Some(have) if have != target => {
                        return self.error(
                            gl::INVALID_OPERATION,
                            F,
                            "texture bound to another target before",
                        );
                    }
                    _ => {}
                }
                Some(t.id)
            }
        };
        *self.texture_units[self.active_texture as usize].slot(target) = id;
    }

    /// Deletes a texture (`deleteTexture`), unbinding it from every unit.
    pub fn delete_texture(&mut self, texture: Texture) {
        if !self.owns(texture.ctx, "deleteTexture") || !self.textures.is_live(texture.id) {
            return;
        }
        for unit in &mut self.texture_units {
            for slot in [
                &mut unit.d2,
                &mut unit.cube,
                &mut unit.d3,
                &mut unit.d2_array,
            ] {
                if *slot == Some(texture.id) {
                    *slot = None;
                }
            }
        }
        self.textures.delete(texture.id);
    }

    /// The texture bound to `target` of the active unit, or `INVALID_OPERATION`.
    fn bound_texture(&mut self, target: u32, function: &str) -> Option<Id> {
        let id = self.texture_units[self.active_texture as usize].get(target);
        if id.is_none() {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "no texture bound to the target",
            );
        }
        id
    }

    /// Specifies a level of a 2D texture or of a cube map face (`texImage2D`) from
    /// `width` × `height` pixels of `(format, ty)` data, laid out by the `UNPACK_*` pixel
    /// storage parameters, or zeros for `None`. Row 0 of the data is row 0 of the texture.
    ///
    /// Supported internal formats: `RGBA`, `RGB`, `LUMINANCE_ALPHA`, `LUMINANCE`, `ALPHA`
    /// (unsigned bytes and the packed 16-bit types), and the sized colour formats of
    /// ES 3.0 except `R11F_G11F_B10F`, `RGB9_E5`, `RGB10_A2`, `RGB10_A2UI` (those and depth
    /// formats record `INVALID_ENUM`).
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_2d(
        &mut self,
        target: u32,
        level: i32,
        internalformat: i32,
        width: i32,
        height: i32,
        border: i32,
        format: u32,
        ty: u32,
        pixels: Option<&[u8]>,
    ) {
        const F: &str = "texImage2D";
        match image_target(target) {
            Some((gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP, _)) => {}
            _ => return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}")),
        }
        self.tex_image(
            target,
            level,
            internalformat,
            width,
            height,
            1,
            border,
            format,
            ty,
            pixels,
            F,
        );
    }

    /// Specifies a level of a 3D texture or 2D array texture (`texImage3D`); see
    /// [`Context::tex_image_2d`].
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_3d(
        &mut self,
        target: u32,
        level: i32,
        internalformat: i32,
        width: i32,
        height: i32,
        depth: i32,
        border: i32,
        format: u32,
        ty: u32,
        pixels: Option<&[u8]>,
    ) {
        const F: &str = "texImage3D";
        if !matches!(target, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        self.tex_image(
            target,
            level,
            internalformat,
            width,
            height,
            depth,
            border,
            format,
            ty,
            pixels,
            F,
        );
    }

    /// Checks level and size against GL's limits for the target.
    fn check_level_size(
        &mut self,
        bind: u32,
        level: i32,
        w: i32,
        h: i32,
        d: i32,
        function: &str,
    ) -> bool {
        let max = match bind {
            gl::TEXTURE_3D => self.gpu.limits.max_texture_dimension_3d,
            _ => self.gpu.limits.max_texture_dimension_2d,
        };
        let max_level = 31 - max.leading_zeros();
        if level < 0 || level as u32 > max_level {
            self.error(gl::INVALID_VALUE, function, format_args!("level {level}"));
            return false;
        }
        let lmax = (max >> level) as i32;
        let max_layers = self.gpu.limits.max_texture_array_layers as i32;
        let depth_ok = match bind {
            gl::TEXTURE_3D => d <= lmax,
            gl::TEXTURE_2D_ARRAY => d <= max_layers,
            _ => true,
        };
        if w < 0 || h < 0 || d < 0 || w > lmax || h > lmax || !depth_ok {
            self.error(
                gl::INVALID_VALUE,
                function,
                format_args!("size {w}x{h}x{d} out of range"),
            );
            return false;
        }
        if bind == gl::TEXTURE_CUBE_MAP && w != h {
            self.error(gl::INVALID_VALUE, function, "cube map faces must be square");
            return false;
        }
        true
    }

    /// Checks `(format, ty)` against an internal format.
    fn check_format(&mut self, f: &InternalFormat, format: u32, ty: u32, function: &str) -> bool {
        if format_channels(format).is_none() || !is_pixel_type(ty) {
            self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("format 0x{format:04X} / type 0x{ty:04X}"),
            );
            return false;
        }
        if !f.accepts(format, ty) {
            self.error(
                gl::INVALID_OPERATION,
                function,
                format_args!(
                    "format 0x{format:04X} / type 0x{ty:04X} do not match the internal format"
                ),
            );
            return false;
        }
        true
    }

    /// Reads `w × h × d` pixels of client data into the storage layout of `f`.
    #[allow(clippy::too_many_arguments)]
    fn unpack_pixels(
        &mut self,
        src: &[u8],
        w: u32,
        h: u32,
        d: u32,
        f: &InternalFormat,
        format: u32,
        ty: u32,
        three_d: bool,
        function: &str,
    ) -> Option<Vec<u8>> {
        let store = self.pixel_store.clone();
        let u = unpack_layout(&store, w, h, d, pixel_size(format, ty), three_d);
        if src.len() < u.needed {
            self.error(
                gl::INVALID_OPERATION,
                function,
                format_args!("{} bytes of pixel data, {} needed", src.len(), u.needed),
            );
            return None;
        }
        let mut out = Vec::with_capacity(w as usize * h as usize * d as usize * f.texel_size());
        for z in 0..d as usize {
            for y in 0..h as usize {
                let row = if store.unpack_flip_y {
                    h as usize - 1 - y
                } else {
                    y
                };
                let at = u.start + z * u.image_stride + row * u.row_stride;
                convert_pixels(
                    &src[at..at + w as usize * u.pixel],
                    w as usize,
                    f,
                    ty,
                    &mut out,
                );
            }
        }
        if store.unpack_premultiply_alpha && f.comp == Comp::Unorm8 && f.gpu_channels() == 4 {
            for px in out.chunks_exact_mut(4) {
                let a = px[3] as u32;
                for c in &mut px[..3] {
                    *c = ((*c as u32 * a + 127) / 255) as u8;
                }
            }
        }
        Some(out)
    }

    #[allow(clippy::too_many_arguments)]
    fn tex_image(
        &mut self,
        target: u32,
        level: i32,
        internalformat: i32,
        width: i32,
        height: i32,
        depth: i32,
        border: i32,
        format: u32,
        ty: u32,
        pixels: Option<&[u8]>,
        function: &str,
    ) {
        let (bind, face) = image_target(target).expect("checked by the caller");
        if !self.check_level_size(bind, level, width, height, depth, function) {
            return;
        }
        if border != 0 {
            return self.error(gl::INVALID_VALUE, function, "border must be 0");
        }
        let f = match internal_format(internalformat as u32) {
            Ok(f) => f,
            Err(true) => {
                return self.error(
                    gl::INVALID_ENUM,
                    function,
                    "internal format not supported by essl-gl",
                )
            }
            Err(false) => {
                return self.error(
                    gl::INVALID_VALUE,
                    function,
                    format_args!("internal format 0x{internalformat:04X}"),
                )
            }
        };
        if !self.check_format(&f, format, ty, function) {
            return;
        }
        let Some(id) = self.bound_texture(bind, function) else {
            return;
        };
        if self
            .textures
            .get(id)
            .is_some_and(|t| t.immutable_levels.is_some())
        {
            return self.error(gl::INVALID_OPERATION, function, "immutable texture");
        }
        let (w, h, d) = (width as u32, height as u32, depth as u32);
        let data = match pixels {
            Some(src) => {
                let three_d = matches!(bind, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY);
                match self.unpack_pixels(src, w, h, d, &f, format, ty, three_d, function) {
                    Some(d) => d,
                    None => return,
                }
            }
            None => vec![0; w as usize * h as usize * d as usize * f.texel_size()],
        };
        let t = self.textures.get_mut(id).expect("bound textures are live");
        t.set_level(
            face,
            level as u32,
            Level {
                width: w,
                height: h,
                depth: d,
                format: f,
                data,
            },
        );
    }

    /// Replaces a region of a level of a 2D texture or cube map face (`texSubImage2D`).
    /// The region must lie in the level (`INVALID_VALUE`) and `(format, ty)` must suit the
    /// level's internal format (`INVALID_OPERATION`).
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_2d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        pixels: &[u8],
    ) {
        const F: &str = "texSubImage2D";
        match image_target(target) {
            Some((gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP, _)) => {}
            _ => return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}")),
        }
        self.tex_sub_image(
            target,
            level,
            [xoffset, yoffset, 0],
            [width, height, 1],
            format,
            ty,
            pixels,
            F,
        );
    }

    /// Replaces a box of a level of a 3D or 2D array texture (`texSubImage3D`).
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_3d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        zoffset: i32,
        width: i32,
        height: i32,
        depth: i32,
        format: u32,
        ty: u32,
        pixels: &[u8],
    ) {
        const F: &str = "texSubImage3D";
        if !matches!(target, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        self.tex_sub_image(
            target,
            level,
            [xoffset, yoffset, zoffset],
            [width, height, depth],
            format,
            ty,
            pixels,
            F,
        );
    }

    #[allow(clippy::too_many_arguments)]
    fn tex_sub_image(
        &mut self,
        target: u32,
        level: i32,
        offset: [i32; 3],
        size: [i32; 3],
        format: u32,
        ty: u32,
        pixels: &[u8],
        function: &str,
    ) {
        let (bind, face) = image_target(target).expect("checked by the caller");
        let Some(id) = self.bound_texture(bind, function) else {
            return;
        };
        if level < 0 {
            return self.error(gl::INVALID_VALUE, function, "negative level");
        }
        let Some(l) = self
            .textures
            .get(id)
            .and_then(|t| t.level(face, level as u32))
            .cloned()
        else {
            return self.error(gl::INVALID_OPERATION, function, "the level has no image");
        };
        if offset.iter().chain(&size).any(|&v| v < 0)
            || offset[0] as u64 + size[0] as u64 > l.width as u64
            || offset[1] as u64 + size[1] as u64 > l.height as u64
            || offset[2] as u64 + size[2] as u64 > l.depth as u64
        {
            return self.error(gl::INVALID_VALUE, function, "region outside the level");
        }
        if !self.check_format(&l.format, format, ty, function) {
            return;
        }
        let (w, h, d) = (size[0] as u32, size[1] as u32, size[2] as u32);
        let three_d = matches!(bind, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY);
        let Some(src) =
            self.unpack_pixels(pixels, w, h, d, &l.format, format, ty, three_d, function)
        else {
            return;
        };
        if w == 0 || h == 0 || d == 0 {
            return;
        }
        let t = self.textures.get_mut(id).expect("bound textures are live");
        let dst = t.faces[face][level as usize].as_mut().expect("checked");
        let texel = dst.format.texel_size();
        let row = w as usize * texel;
        for z in 0..d as usize {
            for y in 0..h as usize {
                let s = (z * h as usize + y) * row;
                let dz = offset[2] as usize + z;
                let dy = offset[1] as usize + y;
                let at = ((dz * dst.height as usize + dy) * dst.width as usize
                    + offset[0] as usize)
                    * texel;
                dst.data[at..at + row].copy_from_slice(&src[s..s + row]);
            }
        }
        t.version += 1;
    }

    /// Allocates all levels of an immutable 2D or cube map texture (`texStorage2D`).
    pub fn tex_storage_2d(
        &mut self,
        target: u32,
        levels: i32,
        internalformat: u32,
        width: i32,
        height: i32,
    ) {
        const F: &str = "texStorage2D";
        if !matches!(target, gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        self.tex_storage(target, levels, internalformat, width, height, 1, F);
    }

    /// Allocates all levels of an immutable 3D or 2D array texture (`texStorage3D`).
    #[allow(clippy::too_many_arguments)]
    pub fn tex_storage_3d(
        &mut self,
        target: u32,
        levels: i32,
        internalformat: u32,
        width: i32,
        height: i32,
        depth: i32,
    ) {
        const F: &str = "texStorage3D";
        if !matches!(target, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        self.tex_storage(target, levels, internalformat, width, height, depth, F);
    }

    #[allow(clippy::too_many_arguments)]
    fn tex_storage(
        &mut self,
        target: u32,
        levels: i32,
        internal: u32,
        w: i32,
        h: i32,
        d: i32,
        function: &str,
    ) {
        let f = match internal_format(internal) {
            Ok(f) if f.expand == Expand::None && !matches!(internal, gl::RGBA | gl::RGB) => f,
            Err(true) => {
                return self.error(
                    gl::INVALID_ENUM,
                    function,
                    "internal format not supported by essl-gl",
                )
            }
            _ => {
                return self.error(
                    gl::INVALID_ENUM,
                    function,
                    "texStorage needs a sized internal format",
                )
            }
        };
        if w < 1 || h < 1 || d < 1 || levels < 1 {
            return self.error(gl::INVALID_VALUE, function, "sizes and levels must be ≥ 1");
        }
        if !self.check_level_size(target, 0, w, h, d, function) {
            return;
        }
        let largest = if target == gl::TEXTURE_3D {
            w.max(h).max(d)
        } else {
            w.max(h)
        } as u32;
        if levels as u32 > 32 - largest.leading_zeros() {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "too many levels for the size",
            );
        }
        let Some(id) = self.bound_texture(target, function) else {
            return;
        };
        let t = self.textures.get_mut(id).expect("bound textures are live");
        if t.immutable_levels.is_some() {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "texture is already immutable",
            );
        }
        let faces = if target == gl::TEXTURE_CUBE_MAP { 6 } else { 1 };
        for level in 0..levels as u32 {
            let (lw, lh) = (mip_size(w as u32, level), mip_size(h as u32, level));
            let ld = if target == gl::TEXTURE_3D {
                mip_size(d as u32, level)
            } else {
                d as u32
            };
            for face in 0..faces {
                let data = vec![0; lw as usize * lh as usize * ld as usize * f.texel_size()];
                t.set_level(
                    face,
                    level,
                    Level {
                        width: lw,
                        height: lh,
                        depth: ld,
                        format: f,
                        data,
                    },
                );
            }
        }
        t.immutable_levels = Some(levels as u32);
    }

    /// Sets an integer texture parameter of the texture bound to `target` (`texParameteri`):
    /// `TEXTURE_MIN_FILTER`, `TEXTURE_MAG_FILTER`, `TEXTURE_WRAP_S/T/R`,
    /// `TEXTURE_BASE_LEVEL`, `TEXTURE_MAX_LEVEL`, `TEXTURE_COMPARE_MODE`,
    /// `TEXTURE_COMPARE_FUNC`, `TEXTURE_MIN_LOD`, `TEXTURE_MAX_LOD`.
    pub fn tex_parameteri(&mut self, target: u32, pname: u32, param: i32) {
        self.tex_parameter(target, pname, param as f32, "texParameteri");
    }

    /// Sets a float texture parameter (`texParameterf`); see [`Context::tex_parameteri`].
    pub fn tex_parameterf(&mut self, target: u32, pname: u32, param: f32) {
        self.tex_parameter(target, pname, param, "texParameterf");
    }

    fn tex_parameter(&mut self, target: u32, pname: u32, value: f32, function: &str) {
        if !is_texture_target(target) {
            return self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("target 0x{target:04X}"),
            );
        }
        let Some(id) = self.bound_texture(target, function) else {
            return;
        };
        let e = value as i64 as u32;
        let ok_enum = match pname {
            gl::TEXTURE_MIN_FILTER => matches!(
                e,
                gl::NEAREST
                    | gl::LINEAR
                    | gl::NEAREST_MIPMAP_NEAREST
                    | gl::LINEAR_MIPMAP_NEAREST
                    | gl::NEAREST_MIPMAP_LINEAR
                    | gl::LINEAR_MIPMAP_LINEAR
            ),
            gl::TEXTURE_MAG_FILTER => matches!(e, gl::NEAREST | gl::LINEAR),
            gl::TEXTURE_WRAP_S | gl::TEXTURE_WRAP_T | gl::TEXTURE_WRAP_R => {
                matches!(e, gl::REPEAT | gl::CLAMP_TO_EDGE | gl::MIRRORED_REPEAT)
            }
            gl::TEXTURE_COMPARE_MODE => matches!(e, gl::NONE | gl::COMPARE_REF_TO_TEXTURE),
            gl::TEXTURE_COMPARE_FUNC => is_compare_func(e),
            gl::TEXTURE_BASE_LEVEL | gl::TEXTURE_MAX_LEVEL => {
                if value < 0.0 {
                    return self.error(gl::INVALID_VALUE, function, "negative level");
                }
                true
            }
            gl::TEXTURE_MIN_LOD | gl::TEXTURE_MAX_LOD => true,
            _ => {
                return self.error(
                    gl::INVALID_ENUM,
                    function,
                    format_args!("pname 0x{pname:04X}"),
                )
            }
        };
        if !ok_enum {
            return self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("value {value} for pname 0x{pname:04X}"),
            );
        }
        let p = &mut self
            .textures
            .get_mut(id)
            .expect("bound textures are live")
            .params;
        match pname {
            gl::TEXTURE_MIN_FILTER => p.min_filter = e,
            gl::TEXTURE_MAG_FILTER => p.mag_filter = e,
            gl::TEXTURE_WRAP_S => p.wrap_s = e,
            gl::TEXTURE_WRAP_T => p.wrap_t = e,
            gl::TEXTURE_WRAP_R => p.wrap_r = e,
            gl::TEXTURE_COMPARE_MODE => p.compare_mode = e,
            gl::TEXTURE_COMPARE_FUNC => p.compare_func = e,
            gl::TEXTURE_BASE_LEVEL => p.base_level = value as u32,
            gl::TEXTURE_MAX_LEVEL => p.max_level = value as u32,
            gl::TEXTURE_MIN_LOD => p.min_lod = value,
            _ => p.max_lod = value,
        }
    }

    /// Computes levels `base + 1..` of the texture bound to `target` from its base level by
    /// averaging 2×2 (2×2×2 in 3D) blocks (`generateMipmap`). The base level must exist and
    /// be an 8-bit normalized or unsized format (`INVALID_OPERATION` otherwise, as ES 3.0's
    /// "colour-renderable and filterable"); a cube map's faces must match.
    pub fn generate_mipmap(&mut self, target: u32) {
        const F: &str = "generateMipmap";
        if !is_texture_target(target) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        let Some(id) = self.bound_texture(target, F) else {
            return;
        };
        let t = self.textures.get(id).expect("bound textures are live");
        let (base, _) = t.level_range();
        let faces = if target == gl::TEXTURE_CUBE_MAP { 6 } else { 1 };
        let Some(first) = t.level(0, base).cloned() else {
            return self.error(gl::INVALID_OPERATION, F, "the base level has no image");
        };
        if first.format.comp != Comp::Unorm8 {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "format is not colour-renderable and filterable",
            );
        }
        for face in 1..faces {
            let same = t.level(face, base).is_some_and(|l| {
                (l.width, l.height, l.format) == (first.width, first.height, first.format)
            });
            if !same {
                return self.error(gl::INVALID_OPERATION, F, "cube map is not cube complete");
            }
        }
        let three_d = target == gl::TEXTURE_3D;
        let largest = if three_d {
            first.width.max(first.height).max(first.depth)
        } else {
            first.width.max(first.height)
        };
        let mut last = base + (31 - largest.leading_zeros());
        if let Some(n) = t.immutable_levels {
            last = last.min(n - 1);
        }
        let t = self.textures.get_mut(id).expect("bound textures are live");
        for face in 0..faces {
            let mut src = t.level(face, base).cloned().expect("checked");
            for level in base + 1..=last {
                let dst = downsample(&src, three_d);
                t.set_level(face, level, dst.clone());
                src = dst;
            }
        }
    }
}

fn srgb_to_linear(c: u8) -> f32 {
    let c = c as f32 / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

fn linear_to_srgb(l: f32) -> u8 {
    let c = if l <= 0.003_130_8 {
        l * 12.92
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    };
    (c * 255.0 + 0.5).clamp(0.0, 255.0) as u8
}

/// The next level of an 8-bit normalized image: each texel the mean of its 2×2(×2) block.
fn downsample(src: &Level, three_d: bool) -> Level {
    let (w, h) = (mip_size(src.width, 1), mip_size(src.height, 1));
    let d = if three_d {
        mip_size(src.depth, 1)
    } else {
        src.depth
    };
    let n = src.format.texel_size();
    let srgb = src.format.srgb;
    let mut data = vec![0u8; w as usize * h as usize * d as usize * n];
    let at = |x: u32, y: u32, z: u32| ((z * src.height + y) * src.width + x) as usize * n;
    for z in 0..d {
        let zs: Vec<u32> = if three_d {
            vec![(2 * z).min(src.depth - 1), (2 * z + 1).min(src.depth - 1)]
        } else {
            vec![z]
        };
        for y in 0..h {
            let ys = [(2 * y).min(src.height - 1), (2 * y + 1).min(src.height - 1)];
            for x in 0..w {
                let xs = [(2 * x).min(src.width - 1), (2 * x + 1).min(src.width - 1)];
                for c in 0..n {
                    let mut sum = 0.0f32;
                    let mut count = 0.0f32;
                    for &sz in &zs {
                        for sy in ys {
                            for sx in xs {
                                let v = src.data[at(sx, sy, sz) + c];
                                sum += if srgb && c % 4 != 3 {
                                    srgb_to_linear(v)
                                } else {
                                    v as f32 / 255.0
                                };
                                count += 1.0;
                            }
                        }
                    }
                    let mean = sum / count;
                    data[((z * h + y) * w + x) as usize * n + c] = if srgb && c % 4 != 3 {
                        linear_to_srgb(mean)
                    } else {
                        (mean * 255.0 + 0.5) as u8
                    };
                }
            }
        }
    }
    Level {
        width: w,
        height: h,
        depth: d,
        format: src.format,
        data,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_floats_round_to_nearest_even() {
        assert_eq!(f32_to_f16(1.0), 0x3C00);
        assert_eq!(f32_to_f16(-2.0), 0xC000);
        assert_eq!(f32_to_f16(65504.0), 0x7BFF);
        assert_eq!(f32_to_f16(1.0e6), 0x7C00);
        assert_eq!(f32_to_f16(5.960_464_5e-8), 0x0001);
        assert_eq!(f32_to_f16(0.0), 0);
    }

    #[test]
    fn legacy_formats_expand_to_rgba() {
        let f = internal_format(gl::LUMINANCE_ALPHA).unwrap();
        let mut out = Vec::new();
        convert_pixels(&[10, 20], 1, &f, gl::UNSIGNED_BYTE, &mut out);
        assert_eq!(out, [10, 10, 10, 20]);
        let f = internal_format(gl::RGB).unwrap();
        out.clear();
        convert_pixels(&[0xFF, 0xFF], 1, &f, gl::UNSIGNED_SHORT_5_6_5, &mut out);
        assert_eq!(out, [255, 255, 255, 255]);
    }

    #[test]
    fn unpack_alignment_pads_rows() {
        let store = PixelStore::default();
        let u = unpack_layout(&store, 3, 2, 1, 3, false);
        assert_eq!(u.row_stride, 12);
        assert_eq!(u.needed, 12 + 9);
    }
}
