//! Internal formats: how each of GL's internal formats is stored (component type,
//! channels, the wgpu format), which client `(format, type)` pairs it accepts, and the sizes
//! of client pixels.

use crate::gl;

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
    pub(crate) fn size(self) -> usize {
        match self {
            Comp::Unorm8 | Comp::Snorm8 | Comp::U8 | Comp::I8 => 1,
            Comp::U16 | Comp::I16 | Comp::F16 => 2,
            Comp::U32 | Comp::I32 | Comp::F32 => 4,
        }
    }

    /// The GL type whose components are stored as they are.
    pub(crate) fn native_type(self) -> u32 {
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
    pub(super) fn one(self) -> [u8; 4] {
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

    pub(super) fn kind(self) -> SampleKind {
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

/// Formats whose texels are not one value per channel: packed colours and depth/stencil.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Packing {
    /// One value of [`InternalFormat::comp`] per channel.
    None,
    /// `RGB10_A2`: 10-bit normalized RGB and 2-bit alpha in one 32-bit word.
    Rgb10A2,
    /// `RGB10_A2UI`: the same bits as unsigned integers.
    Rgb10A2Ui,
    /// `R11F_G11F_B10F`: unsigned 11-, 11- and 10-bit floats.
    Rg11B10F,
    /// `RGB9_E5`: three 9-bit mantissas sharing a 5-bit exponent (not renderable).
    Rgb9E5,
    /// `DEPTH_COMPONENT16`.
    Depth16,
    /// `DEPTH_COMPONENT24` (stored as a 32-bit word on the CPU).
    Depth24,
    /// `DEPTH_COMPONENT32F`.
    Depth32F,
    /// `DEPTH24_STENCIL8`.
    Depth24Stencil8,
    /// `DEPTH32F_STENCIL8`.
    Depth32FStencil8,
    /// `STENCIL_INDEX8` (renderbuffers only).
    Stencil8,
}

impl Packing {
    /// Whether the format has a depth component.
    pub(crate) fn has_depth(self) -> bool {
        matches!(
            self,
            Packing::Depth16
                | Packing::Depth24
                | Packing::Depth32F
                | Packing::Depth24Stencil8
                | Packing::Depth32FStencil8
        )
    }

    /// Whether the format has a stencil component.
    pub(crate) fn has_stencil(self) -> bool {
        matches!(
            self,
            Packing::Depth24Stencil8 | Packing::Depth32FStencil8 | Packing::Stencil8
        )
    }
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
    pub(crate) packing: Packing,
}

impl InternalFormat {
    /// Channels of the GPU texture (RGB and the legacy formats are stored as RGBA).
    pub(crate) fn gpu_channels(&self) -> u8 {
        match (self.expand, self.channels) {
            _ if self.packing != Packing::None => self.channels,
            (Expand::None, 3) => 4,
            (Expand::None, n) => n,
            _ => 4,
        }
    }

    /// Whether the format is RGB stored with a fourth channel (whose value GL reads as 1).
    pub(crate) fn rgb_in_four_channels(&self) -> bool {
        self.channels == 3 && self.expand == Expand::None && self.packing == Packing::None
    }

    /// Bytes per texel on the GPU (and in the CPU copy).
    pub(crate) fn texel_size(&self) -> usize {
        match self.packing {
            Packing::None => self.gpu_channels() as usize * self.comp.size(),
            Packing::Depth16 => 2,
            Packing::Stencil8 => 1,
            Packing::Depth32FStencil8 => 8,
            _ => 4,
        }
    }

    /// Whether the format has a depth component.
    pub(crate) fn has_depth(&self) -> bool {
        self.packing.has_depth()
    }

    /// Whether the format has a stencil component.
    pub(crate) fn has_stencil(&self) -> bool {
        self.packing.has_stencil()
    }

    /// The wgpu format of the GPU texture.
    pub(crate) fn gpu_format(&self) -> wgpu::TextureFormat {
        use wgpu::TextureFormat as F;
        match self.packing {
            Packing::None => {}
            Packing::Rgb10A2 => return F::Rgb10a2Unorm,
            Packing::Rgb10A2Ui => return F::Rgb10a2Uint,
            Packing::Rg11B10F => return F::Rg11b10Ufloat,
            Packing::Rgb9E5 => return F::Rgb9e5Ufloat,
            Packing::Depth16 => return F::Depth16Unorm,
            Packing::Depth24 => return F::Depth24Plus,
            Packing::Depth32F => return F::Depth32Float,
            Packing::Depth24Stencil8 => return F::Depth24PlusStencil8,
            Packing::Depth32FStencil8 => return F::Depth32FloatStencil8,
            Packing::Stencil8 => return F::Stencil8,
        }
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

    /// Whether GL ES 3.0 lets the format be filtered linearly (32-bit floats, integers and
    /// depth not).
    pub(crate) fn filterable(&self) -> bool {
        match self.packing {
            Packing::None => matches!(self.comp, Comp::Unorm8 | Comp::Snorm8 | Comp::F16),
            Packing::Rgb10A2 | Packing::Rg11B10F | Packing::Rgb9E5 => true,
            _ => false,
        }
    }

    /// What sampling the format returns (a depth format sampled without comparison returns
    /// floats).
    pub(crate) fn kind(&self) -> SampleKind {
        match self.packing {
            Packing::Rgb10A2Ui => SampleKind::Uint,
            Packing::None => self.comp.kind(),
            _ => SampleKind::Float,
        }
    }

    /// Whether ES 3.0 makes the format colour-renderable (table 3.13); the float formats with
    /// `EXT_color_buffer_float` (`float_ok`). Unsized and legacy formats: only `RGBA`/`RGB`.
    pub(crate) fn color_renderable(&self, float_ok: bool) -> bool {
        if self.base == super::compressed::COMPRESSED_BASE {
            return false; // compressed formats are sampled only
        }
        match self.packing {
            Packing::Rgb10A2 | Packing::Rgb10A2Ui => true,
            Packing::Rg11B10F => float_ok,
            Packing::None => {
                if self.expand != Expand::None {
                    return false;
                }
                match self.comp {
                    Comp::Snorm8 => false,
                    // WebGL 1's unsized RGB in floats renders, as in Chromium.
                    Comp::F16 | Comp::F32 => float_ok && (self.channels != 3 || self.gl == gl::RGB),
                    Comp::Unorm8 => {
                        self.channels != 3 || matches!(self.gl, gl::RGB | gl::RGB8 | gl::RGB565)
                    }
                    _ => self.channels != 3,
                }
            }
            _ => false,
        }
    }

    /// Whether the format can be a depth or stencil attachment.
    pub(crate) fn depth_stencil_renderable(&self) -> bool {
        self.has_depth() || self.has_stencil()
    }

    /// Whether textures may have the format (`STENCIL_INDEX8` is for renderbuffers only).
    pub(crate) fn texture_format(&self) -> bool {
        self.packing != Packing::Stencil8
    }

    /// Whether the texel bytes are the GPU's own encoding of client data of the format's
    /// native type (so uploads copy bytes); false for depth formats, which wgpu cannot copy
    /// into (they are written by drawing).
    pub(crate) fn copyable(&self) -> bool {
        !self.has_depth()
    }

    /// Whether `(format, ty)` data may be uploaded to this internal format (ES 3.0 table 3.2).
    pub(super) fn accepts(&self, format: u32, ty: u32) -> bool {
        if format != self.base {
            return false;
        }
        match self.packing {
            Packing::None => {}
            Packing::Rgb10A2 | Packing::Rgb10A2Ui => return ty == gl::UNSIGNED_INT_2_10_10_10_REV,
            Packing::Rg11B10F => {
                return matches!(
                    ty,
                    gl::UNSIGNED_INT_10F_11F_11F_REV | gl::HALF_FLOAT | gl::FLOAT
                )
            }
            Packing::Rgb9E5 => {
                return matches!(
                    ty,
                    gl::UNSIGNED_INT_5_9_9_9_REV | gl::HALF_FLOAT | gl::FLOAT
                )
            }
            Packing::Depth16 => return matches!(ty, gl::UNSIGNED_SHORT | gl::UNSIGNED_INT),
            Packing::Depth24 => return ty == gl::UNSIGNED_INT,
            Packing::Depth32F => return ty == gl::FLOAT,
            Packing::Depth24Stencil8 => return ty == gl::UNSIGNED_INT_24_8,
            Packing::Depth32FStencil8 => return ty == gl::FLOAT_32_UNSIGNED_INT_24_8_REV,
            Packing::Stencil8 => return false,
        }
        if ty == self.comp.native_type() {
            return true;
        }
        match ty {
            gl::FLOAT => self.comp == Comp::F16,
            gl::UNSIGNED_SHORT_5_6_5 => matches!(self.gl, gl::RGB | gl::RGB565),
            gl::UNSIGNED_SHORT_4_4_4_4 => matches!(self.gl, gl::RGBA | gl::RGBA4),
            gl::UNSIGNED_SHORT_5_5_5_1 => matches!(self.gl, gl::RGBA | gl::RGB5_A1),
            // ES 3.0 table 3.2: RGB5_A1 also takes 10-bit colour with 2-bit alpha.
            gl::UNSIGNED_INT_2_10_10_10_REV => self.gl == gl::RGB5_A1,
            _ => false,
        }
    }
}

/// Bits per component of a format, as `getRenderbufferParameter` and
/// `getFramebufferAttachmentParameter` report them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct BitSizes {
    pub(crate) red: u32,
    pub(crate) green: u32,
    pub(crate) blue: u32,
    pub(crate) alpha: u32,
    pub(crate) depth: u32,
    pub(crate) stencil: u32,
}

/// The bit sizes of a format's components (GL's sizes, not the GPU's: `RGBA4` has 4 bits
/// per channel though it is stored in 8).
pub(crate) fn bit_sizes(f: &InternalFormat) -> BitSizes {
    let rgba = |r, g, b, a| BitSizes {
        red: r,
        green: g,
        blue: b,
        alpha: a,
        ..Default::default()
    };
    match f.packing {
        Packing::Rgb10A2 | Packing::Rgb10A2Ui => return rgba(10, 10, 10, 2),
        Packing::Rg11B10F => return rgba(11, 11, 10, 0),
        Packing::Rgb9E5 => return rgba(9, 9, 9, 0),
        Packing::Depth16 => {
            return BitSizes {
                depth: 16,
                ..Default::default()
            }
        }
        Packing::Depth24 => {
            return BitSizes {
                depth: 24,
                ..Default::default()
            }
        }
        Packing::Depth32F => {
            return BitSizes {
                depth: 32,
                ..Default::default()
            }
        }
        Packing::Depth24Stencil8 => {
            return BitSizes {
                depth: 24,
                stencil: 8,
                ..Default::default()
            }
        }
        Packing::Depth32FStencil8 => {
            return BitSizes {
                depth: 32,
                stencil: 8,
                ..Default::default()
            }
        }
        Packing::Stencil8 => {
            return BitSizes {
                stencil: 8,
                ..Default::default()
            }
        }
        Packing::None => {}
    }
    match f.gl {
        gl::RGBA4 => return rgba(4, 4, 4, 4),
        gl::RGB5_A1 => return rgba(5, 5, 5, 1),
        gl::RGB565 => return rgba(5, 6, 5, 0),
        _ => {}
    }
    let bits = 8 * f.comp.size() as u32;
    let n = f.channels;
    let on = |c: u8| if n > c { bits } else { 0 };
    match f.expand {
        Expand::Luminance => rgba(bits, bits, bits, 0),
        Expand::Alpha => rgba(0, 0, 0, bits),
        Expand::LuminanceAlpha => rgba(bits, bits, bits, bits),
        Expand::None => rgba(on(0), on(1), on(2), on(3)),
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
        packing: Packing::None,
    };
    let plain = |base, channels, comp| f(base, channels, comp, false, Expand::None);
    let packed = |base, channels, comp, packing| InternalFormat {
        packing,
        ..f(base, channels, comp, false, Expand::None)
    };
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
        gl::RGB10_A2 => packed(gl::RGBA, 4, U32, Packing::Rgb10A2),
        gl::RGB10_A2UI => packed(gl::RGBA_INTEGER, 4, U32, Packing::Rgb10A2Ui),
        gl::R11F_G11F_B10F => packed(gl::RGB, 3, F32, Packing::Rg11B10F),
        gl::RGB9_E5 => packed(gl::RGB, 3, F32, Packing::Rgb9E5),
        gl::DEPTH_COMPONENT16 => packed(gl::DEPTH_COMPONENT, 1, U16, Packing::Depth16),
        gl::DEPTH_COMPONENT24 => packed(gl::DEPTH_COMPONENT, 1, U32, Packing::Depth24),
        gl::DEPTH_COMPONENT32F => packed(gl::DEPTH_COMPONENT, 1, F32, Packing::Depth32F),
        gl::DEPTH24_STENCIL8 => packed(gl::DEPTH_STENCIL, 2, U32, Packing::Depth24Stencil8),
        gl::DEPTH32F_STENCIL8 => packed(gl::DEPTH_STENCIL, 2, F32, Packing::Depth32FStencil8),
        gl::STENCIL_INDEX8 => packed(gl::STENCIL_INDEX8, 1, U8, Packing::Stencil8),
        gl::DEPTH_COMPONENT | gl::DEPTH_STENCIL => return Err(true),
        _ => return Err(false),
    })
}

pub(super) fn format_channels(format: u32) -> Option<usize> {
    match format {
        gl::RED | gl::RED_INTEGER | gl::LUMINANCE | gl::ALPHA | gl::DEPTH_COMPONENT => Some(1),
        gl::RG | gl::RG_INTEGER | gl::LUMINANCE_ALPHA | gl::DEPTH_STENCIL => Some(2),
        gl::RGB | gl::RGB_INTEGER => Some(3),
        gl::RGBA | gl::RGBA_INTEGER => Some(4),
        _ => None,
    }
}

/// Whether `ty` is a pixel type of client data (ES 3.0 table 3.2, with the packed ones).
pub(crate) fn is_pixel_type(ty: u32) -> bool {
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
            | gl::UNSIGNED_INT_2_10_10_10_REV
            | gl::UNSIGNED_INT_10F_11F_11F_REV
            | gl::UNSIGNED_INT_5_9_9_9_REV
            | gl::UNSIGNED_INT_24_8
            | gl::FLOAT_32_UNSIGNED_INT_24_8_REV
    )
}

/// Bytes per pixel of client data in `(format, ty)`.
pub(super) fn pixel_size(format: u32, ty: u32) -> usize {
    match ty {
        gl::UNSIGNED_SHORT_5_6_5 | gl::UNSIGNED_SHORT_4_4_4_4 | gl::UNSIGNED_SHORT_5_5_5_1 => 2,
        gl::UNSIGNED_INT_2_10_10_10_REV
        | gl::UNSIGNED_INT_10F_11F_11F_REV
        | gl::UNSIGNED_INT_5_9_9_9_REV
        | gl::UNSIGNED_INT_24_8 => 4,
        gl::FLOAT_32_UNSIGNED_INT_24_8_REV => 8,
        _ if format == gl::DEPTH_COMPONENT => match ty {
            gl::UNSIGNED_SHORT => 2,
            _ => 4,
        },
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
