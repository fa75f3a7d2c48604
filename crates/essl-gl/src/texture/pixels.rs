//! Client pixel data: where a region lies by GL's `UNPACK_*` rules, and the conversion of
//! pixels of a `(format, type)` into an internal format's storage layout.

use super::format::{f32_to_f16, Expand, InternalFormat, Packing};
use crate::gl;
use crate::state::PixelStore;

pub(super) fn unpack_16(v: u16, ty: u32) -> [u8; 4] {
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

/// An unsigned float of `mantissa` bits and a 5-bit exponent (the channels of
/// `R11F_G11F_B10F`), from an `f32`: negative and NaN become 0, too large the largest value.
pub(super) fn unsigned_small_float(x: f32, mantissa: u32) -> u32 {
    if x.is_nan() || x <= 0.0 {
        return 0;
    }
    let bits = x.to_bits();
    let exp = ((bits >> 23) & 0xFF) as i32 - 127 + 15;
    let max = (0x1E << mantissa) | ((1 << mantissa) - 1);
    if exp >= 0x1F {
        return max;
    }
    let m = (bits & 0x7F_FFFF) | 0x80_0000;
    if exp <= 0 {
        // Denormal: shift the implicit 1 in.
        let shift = 24 - mantissa as i32 - exp;
        return if shift > 24 { 0 } else { m >> shift };
    }
    ((exp as u32) << mantissa) | ((bits & 0x7F_FFFF) >> (23 - mantissa))
}

/// `RGB9_E5`'s shared-exponent encoding of three floats (ES 3.0 §3.8.3.2).
pub(super) fn rgb9e5(rgb: [f32; 3]) -> u32 {
    const MAX: f32 = (511.0 / 512.0) * 65536.0;
    let c = rgb.map(|x| if x.is_nan() { 0.0 } else { x.clamp(0.0, MAX) });
    let max = c[0].max(c[1]).max(c[2]);
    let mut exp = (max.max(f32::MIN_POSITIVE).log2().floor() as i32).max(-16) + 1 + 15;
    let mut scale = 2f32.powi(exp - 15 - 9);
    if (max / scale + 0.5).floor() as u32 == 512 {
        exp += 1;
        scale *= 2.0;
    }
    let [r, g, b] = c.map(|x| (x / scale + 0.5).floor() as u32 & 0x1FF);
    r | (g << 9) | (b << 18) | ((exp as u32) << 27)
}

/// Converts pixels for the packed and depth formats ([`Packing`]).
fn convert_packed(src: &[u8], count: usize, f: &InternalFormat, ty: u32, out: &mut Vec<u8>) {
    let word = |px: &[u8], i: usize| u32::from_ne_bytes([px[i], px[i + 1], px[i + 2], px[i + 3]]);
    let float = |px: &[u8], i: usize, half: bool| {
        if half {
            f16_to_f32(u16::from_ne_bytes([px[2 * i], px[2 * i + 1]]))
        } else {
            f32::from_bits(word(px, 4 * i))
        }
    };
    match (f.packing, ty) {
        (Packing::Rg11B10F | Packing::Rgb9E5, gl::HALF_FLOAT | gl::FLOAT) => {
            let half = ty == gl::HALF_FLOAT;
            let size = if half { 6 } else { 12 };
            for px in src.chunks_exact(size).take(count) {
                let c = [float(px, 0, half), float(px, 1, half), float(px, 2, half)];
                let v = if f.packing == Packing::Rgb9E5 {
                    rgb9e5(c)
                } else {
                    unsigned_small_float(c[0], 6)
                        | (unsigned_small_float(c[1], 6) << 11)
                        | (unsigned_small_float(c[2], 5) << 22)
                };
                out.extend_from_slice(&v.to_ne_bytes());
            }
        }
        (Packing::Depth16, gl::UNSIGNED_INT) => {
            for px in src.chunks_exact(4).take(count) {
                out.extend_from_slice(&((word(px, 0) >> 16) as u16).to_ne_bytes());
            }
        }
        // Every other pair is stored as the client gives it.
        _ => {
            let size = f.texel_size();
            out.extend_from_slice(&src[..(count * size).min(src.len())]);
        }
    }
}

/// An IEEE half-precision value as an `f32`.
pub(crate) fn f16_to_f32(h: u16) -> f32 {
    let sign = if h & 0x8000 != 0 { -1.0 } else { 1.0 };
    let exp = ((h >> 10) & 0x1F) as i32;
    let mant = (h & 0x3FF) as f32;
    match exp {
        0 => sign * mant * 2f32.powi(-24),
        0x1F if mant == 0.0 => sign * f32::INFINITY,
        0x1F => f32::NAN,
        _ => sign * (1.0 + mant / 1024.0) * 2f32.powi(exp - 15),
    }
}

/// Converts `count` pixels of `(format, ty)` client data to the storage of `f`.
pub(super) fn convert_pixels(
    src: &[u8],
    count: usize,
    f: &InternalFormat,
    ty: u32,
    out: &mut Vec<u8>,
) {
    if f.packing != Packing::None {
        return convert_packed(src, count, f, ty, out);
    }
    if matches!(
        ty,
        gl::UNSIGNED_SHORT_5_6_5 | gl::UNSIGNED_SHORT_4_4_4_4 | gl::UNSIGNED_SHORT_5_5_5_1
    ) {
        for px in src.chunks_exact(2).take(count) {
            out.extend_from_slice(&unpack_16(u16::from_ne_bytes([px[0], px[1]]), ty));
        }
        return;
    }
    if ty == gl::UNSIGNED_INT_2_10_10_10_REV {
        // Into RGB5_A1 (stored as RGBA8): each channel rounded to the format's 5 bits, alpha
        // to its 1, as GL converts.
        let to5 = |x: u32| -> u8 {
            let q = (x * 31 + 511) / 1023;
            ((q * 255 + 15) / 31) as u8
        };
        for px in src.chunks_exact(4).take(count) {
            let v = u32::from_ne_bytes([px[0], px[1], px[2], px[3]]);
            let a = if v >> 30 >= 2 { 255 } else { 0 };
            out.extend_from_slice(&[
                to5(v & 0x3FF),
                to5((v >> 10) & 0x3FF),
                to5((v >> 20) & 0x3FF),
                a,
            ]);
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

/// Where a region of client pixel data lies, by GL's unpack rules.
pub(super) struct Unpack {
    pub(super) start: usize,
    pub(super) row_stride: usize,
    pub(super) image_stride: usize,
    pub(super) pixel: usize,
    pub(super) needed: usize,
}

pub(super) fn unpack_layout(
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::internal_format;

    #[test]
    pub(super) fn half_floats_round_to_nearest_even() {
        assert_eq!(f32_to_f16(1.0), 0x3C00);
        assert_eq!(f32_to_f16(-2.0), 0xC000);
        assert_eq!(f32_to_f16(65504.0), 0x7BFF);
        assert_eq!(f32_to_f16(1.0e6), 0x7C00);
        assert_eq!(f32_to_f16(5.960_464_5e-8), 0x0001);
        assert_eq!(f32_to_f16(0.0), 0);
    }

    #[test]
    pub(super) fn legacy_formats_expand_to_rgba() {
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
    fn packed_floats_encode_as_gl_specifies() {
        // 1.0 in an 11-bit float: exponent 15, mantissa 0; in 10 bits likewise.
        assert_eq!(unsigned_small_float(1.0, 6), 15 << 6);
        assert_eq!(unsigned_small_float(1.0, 5), 15 << 5);
        assert_eq!(unsigned_small_float(-1.0, 6), 0);
        assert_eq!(unsigned_small_float(1e9, 6), (0x1E << 6) | 0x3F);
        // RGB9_E5 of (1, 0.5, 0): exponent 16 (bias 15), mantissas 256, 128, 0.
        let v = rgb9e5([1.0, 0.5, 0.0]);
        assert_eq!((v & 0x1FF, (v >> 9) & 0x1FF, v >> 27), (256, 128, 16));
        assert_eq!(f16_to_f32(0x3C00), 1.0);
        assert_eq!(f16_to_f32(f32_to_f16(-0.333)), f16_to_f32(0xB554));
    }

    #[test]
    pub(super) fn unpack_alignment_pads_rows() {
        let store = PixelStore::default();
        let u = unpack_layout(&store, 3, 2, 1, 3, false);
        assert_eq!(u.row_stride, 12);
        assert_eq!(u.needed, 12 + 9);
    }
}
