//! Texels of a framebuffer image, converted to what `read_pixels` was asked for: decoded from
//! the GPU format into floats or integers, then encoded in the client `(format, type)`.

use crate::gl;
use crate::texture::{f16_to_f32, f32_to_f16, Comp, Expand, InternalFormat, Packing, SampleKind};

/// One texel, decoded.
#[derive(Clone, Copy, Debug)]
pub(super) enum Texel {
    /// Normalized, float and packed-float formats.
    Float([f32; 4]),
    /// Signed integer formats.
    Int([i64; 4]),
    /// Unsigned integer formats.
    Uint([u64; 4]),
}

/// The unsigned float of an 11- or 10-bit channel with a 5-bit exponent.
fn small_float(bits: u32, mantissa: u32) -> f32 {
    let exp = (bits >> mantissa) & 0x1F;
    let m = (bits & ((1 << mantissa) - 1)) as f32 / (1u32 << mantissa) as f32;
    match exp {
        0 => m * 2f32.powi(-14),
        0x1F => f32::INFINITY,
        e => (1.0 + m) * 2f32.powi(e as i32 - 15),
    }
}

/// Decodes one texel of `f` stored in the GPU format (`bytes` holds at least one texel).
pub(super) fn decode(f: &InternalFormat, bytes: &[u8]) -> Texel {
    let word = |i: usize| u32::from_ne_bytes([bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]]);
    match f.packing {
        Packing::Rgb10A2 => {
            let w = word(0);
            let c = |s: u32, bits: u32| {
                ((w >> s) & ((1 << bits) - 1)) as f32 / ((1 << bits) - 1) as f32
            };
            return Texel::Float([c(0, 10), c(10, 10), c(20, 10), c(30, 2)]);
        }
        Packing::Rgb10A2Ui => {
            let w = word(0) as u64;
            return Texel::Uint([w & 0x3FF, (w >> 10) & 0x3FF, (w >> 20) & 0x3FF, w >> 30]);
        }
        Packing::Rg11B10F => {
            let w = word(0);
            return Texel::Float([
                small_float(w & 0x7FF, 6),
                small_float((w >> 11) & 0x7FF, 6),
                small_float(w >> 22, 5),
                1.0,
            ]);
        }
        Packing::None => {}
        _ => return Texel::Float([0.0, 0.0, 0.0, 1.0]),
    }
    let n = f.gpu_channels() as usize;
    let size = f.comp.size();
    let at = |c: usize| &bytes[c * size..(c + 1) * size];
    let mut floats = [0.0f32, 0.0, 0.0, 1.0];
    let mut ints = [0i64, 0, 0, 1];
    for c in 0..n.min(4) {
        let b = at(c);
        match f.comp {
            Comp::Unorm8 => floats[c] = b[0] as f32 / 255.0,
            Comp::Snorm8 => floats[c] = ((b[0] as i8) as f32 / 127.0).max(-1.0),
            Comp::F16 => floats[c] = f16_to_f32(u16::from_ne_bytes([b[0], b[1]])),
            Comp::F32 => floats[c] = f32::from_ne_bytes([b[0], b[1], b[2], b[3]]),
            Comp::U8 => ints[c] = b[0] as i64,
            Comp::I8 => ints[c] = b[0] as i8 as i64,
            Comp::U16 => ints[c] = u16::from_ne_bytes([b[0], b[1]]) as i64,
            Comp::I16 => ints[c] = i16::from_ne_bytes([b[0], b[1]]) as i64,
            Comp::U32 => ints[c] = u32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as i64,
            Comp::I32 => ints[c] = i32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as i64,
        }
    }
    // Formats with fewer bits than the GPU stores them in (RGB565, RGBA4, RGB5_A1) read as
    // their own bits hold the value: rounded to the nearest of their steps.
    if f.comp == Comp::Unorm8 {
        let b = crate::texture::bit_sizes(f);
        for (c, bits) in [b.red, b.green, b.blue, b.alpha].into_iter().enumerate() {
            if (1..8).contains(&bits) {
                let steps = ((1u32 << bits) - 1) as f32;
                floats[c] = (floats[c] * steps).round() / steps;
            }
        }
    }
    // RGB formats are stored with a fourth channel, which draws may have written: GL's
    // alpha of an RGB image is 1.
    if f.rgb_in_four_channels() {
        floats[3] = 1.0;
        ints[3] = 1;
    }
    // Legacy formats read as their GL components (luminance in R, G, B).
    if f.expand == Expand::Alpha {
        floats = [0.0, 0.0, 0.0, floats[3]];
    }
    match f.kind() {
        SampleKind::Sint => Texel::Int(ints),
        SampleKind::Uint => Texel::Uint(ints.map(|v| v as u64)),
        _ => Texel::Float(floats),
    }
}

/// The `(format, type)` pairs `read_pixels` accepts from an image of `f` (ES 3.0 §4.3.2):
/// the pair every image of its kind accepts, and the implementation's own pair
/// (`IMPLEMENTATION_COLOR_READ_FORMAT`/`_TYPE`), which is [`native_pair`].
pub(super) fn accepts(f: &InternalFormat, format: u32, ty: u32) -> bool {
    let always = match f.kind() {
        SampleKind::Sint => (gl::RGBA_INTEGER, gl::INT),
        SampleKind::Uint => (gl::RGBA_INTEGER, gl::UNSIGNED_INT),
        _ if matches!(f.comp, Comp::F16 | Comp::F32) || f.packing == Packing::Rg11B10F => {
            (gl::RGBA, gl::FLOAT)
        }
        _ => (gl::RGBA, gl::UNSIGNED_BYTE),
    };
    let rgb10 = f.packing == Packing::Rgb10A2
        && (format, ty) == (gl::RGBA, gl::UNSIGNED_INT_2_10_10_10_REV);
    (format, ty) == always || (format, ty) == native_pair(f) || rgb10
}

/// `IMPLEMENTATION_COLOR_READ_FORMAT` and `_TYPE` for an image of `f`: its own channels in
/// its own component type.
pub(crate) fn native_pair(f: &InternalFormat) -> (u32, u32) {
    let integer = matches!(f.kind(), SampleKind::Sint | SampleKind::Uint);
    let base = match (f.channels, integer, f.expand) {
        (_, _, Expand::Luminance | Expand::Alpha | Expand::LuminanceAlpha) => gl::RGBA,
        (1, false, _) => gl::RED,
        (2, false, _) => gl::RG,
        // 8-bit RGB reads as RGBA (Chromium's answer; ES 3.0 leaves the choice open).
        (3, false, _) if f.comp == Comp::Unorm8 && f.gl != gl::RGB565 => gl::RGBA,
        (3, false, _) => gl::RGB,
        (1, true, _) => gl::RED_INTEGER,
        (2, true, _) => gl::RG_INTEGER,
        (3, true, _) => gl::RGB_INTEGER,
        (_, true, _) => gl::RGBA_INTEGER,
        _ => gl::RGBA,
    };
    let ty = match f.packing {
        Packing::Rgb10A2 | Packing::Rgb10A2Ui => gl::UNSIGNED_INT_2_10_10_10_REV,
        Packing::Rg11B10F => gl::UNSIGNED_INT_10F_11F_11F_REV,
        _ => match f.gl {
            gl::RGB565 => gl::UNSIGNED_SHORT_5_6_5,
            gl::RGBA4 => gl::UNSIGNED_SHORT_4_4_4_4,
            gl::RGB5_A1 => gl::UNSIGNED_SHORT_5_5_5_1,
            _ => f.comp.native_type(),
        },
    };
    (base, ty)
}

/// Bytes per pixel of client data in `(format, ty)` for reads.
pub(super) fn pixel_bytes(format: u32, ty: u32) -> usize {
    let channels = match format {
        gl::RED | gl::RED_INTEGER | gl::ALPHA | gl::LUMINANCE => 1,
        gl::RG | gl::RG_INTEGER | gl::LUMINANCE_ALPHA => 2,
        gl::RGB | gl::RGB_INTEGER => 3,
        _ => 4,
    };
    match ty {
        gl::UNSIGNED_SHORT_5_6_5 | gl::UNSIGNED_SHORT_4_4_4_4 | gl::UNSIGNED_SHORT_5_5_5_1 => 2,
        gl::UNSIGNED_INT_2_10_10_10_REV | gl::UNSIGNED_INT_10F_11F_11F_REV => 4,
        gl::UNSIGNED_BYTE | gl::BYTE => channels,
        gl::UNSIGNED_SHORT | gl::SHORT | gl::HALF_FLOAT => 2 * channels,
        _ => 4 * channels,
    }
}

/// Writes one texel as client data of `(format, ty)` into `out` (which has room for it).
pub(super) fn encode(t: Texel, format: u32, ty: u32, out: &mut [u8]) {
    let pick: &[usize] = match format {
        gl::RED | gl::RED_INTEGER => &[0],
        gl::RG | gl::RG_INTEGER => &[0, 1],
        gl::RGB | gl::RGB_INTEGER => &[0, 1, 2],
        gl::ALPHA => &[3],
        _ => &[0, 1, 2, 3],
    };
    let unorm = |x: f32, bits: u32| {
        let max = ((1u64 << bits) - 1) as f32;
        (x.clamp(0.0, 1.0) * max + 0.5).floor() as u32
    };
    match (t, ty) {
        (Texel::Float(c), gl::UNSIGNED_SHORT_5_6_5) => {
            let v = (unorm(c[0], 5) << 11) | (unorm(c[1], 6) << 5) | unorm(c[2], 5);
            out[..2].copy_from_slice(&(v as u16).to_ne_bytes());
        }
        (Texel::Float(c), gl::UNSIGNED_SHORT_4_4_4_4) => {
            let v = (unorm(c[0], 4) << 12)
                | (unorm(c[1], 4) << 8)
                | (unorm(c[2], 4) << 4)
                | unorm(c[3], 4);
            out[..2].copy_from_slice(&(v as u16).to_ne_bytes());
        }
        (Texel::Float(c), gl::UNSIGNED_SHORT_5_5_5_1) => {
            let v = (unorm(c[0], 5) << 11)
                | (unorm(c[1], 5) << 6)
                | (unorm(c[2], 5) << 1)
                | unorm(c[3], 1);
            out[..2].copy_from_slice(&(v as u16).to_ne_bytes());
        }
        (Texel::Float(c), gl::UNSIGNED_INT_2_10_10_10_REV) => {
            let v = unorm(c[0], 10)
                | (unorm(c[1], 10) << 10)
                | (unorm(c[2], 10) << 20)
                | (unorm(c[3], 2) << 30);
            out[..4].copy_from_slice(&v.to_ne_bytes());
        }
        (Texel::Uint(c), gl::UNSIGNED_INT_2_10_10_10_REV) => {
            let v = (c[0] & 0x3FF)
                | ((c[1] & 0x3FF) << 10)
                | ((c[2] & 0x3FF) << 20)
                | ((c[3] & 3) << 30);
            out[..4].copy_from_slice(&(v as u32).to_ne_bytes());
        }
        (Texel::Float(c), _) => {
            for (i, &ch) in pick.iter().enumerate() {
                let x = c[ch];
                match ty {
                    gl::UNSIGNED_BYTE => out[i] = unorm(x, 8) as u8,
                    gl::BYTE => out[i] = (x.clamp(-1.0, 1.0) * 127.0).round() as i8 as u8,
                    gl::HALF_FLOAT => {
                        out[2 * i..2 * i + 2].copy_from_slice(&f32_to_f16(x).to_ne_bytes())
                    }
                    gl::UNSIGNED_SHORT => {
                        out[2 * i..2 * i + 2].copy_from_slice(&(unorm(x, 16) as u16).to_ne_bytes())
                    }
                    _ => out[4 * i..4 * i + 4].copy_from_slice(&x.to_ne_bytes()),
                }
            }
        }
        (Texel::Int(c), _) => {
            for (i, &ch) in pick.iter().enumerate() {
                write_integer(out, i, ty, c[ch]);
            }
        }
        (Texel::Uint(c), _) => {
            for (i, &ch) in pick.iter().enumerate() {
                write_integer(out, i, ty, c[ch] as i64);
            }
        }
    }
}

/// Writes channel `i` of an integer texel as client data of type `ty` (the implementation's
/// pair of an 8- or 16-bit integer image is `BYTE`, `SHORT` or their unsigned types):
/// the value's low bits, as GL converts it.
fn write_integer(out: &mut [u8], i: usize, ty: u32, v: i64) {
    match ty {
        gl::BYTE | gl::UNSIGNED_BYTE => out[i] = v as u8,
        gl::SHORT | gl::UNSIGNED_SHORT => {
            out[2 * i..2 * i + 2].copy_from_slice(&(v as u16).to_ne_bytes())
        }
        _ => out[4 * i..4 * i + 4].copy_from_slice(&(v as u32).to_ne_bytes()),
    }
}
