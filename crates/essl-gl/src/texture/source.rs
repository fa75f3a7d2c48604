//! Uploads from a `TexImageSource` — an `ImageData`, a canvas, an image — which a binding
//! hands over as 8-bit RGBA, unpremultiplied, top row first ([`ImageSource`]).
//!
//! WebGL's rules for such sources (WebGL 2 § 5.35 and the `UNPACK_*_WEBGL` parameters):
//! `UNPACK_ALIGNMENT` and `UNPACK_ROW_LENGTH` are ignored; `UNPACK_SKIP_PIXELS` and
//! `UNPACK_SKIP_ROWS` place the selected rectangle in the source, `UNPACK_IMAGE_HEIGHT` and
//! `UNPACK_SKIP_IMAGES` (3D only) pick slices; `UNPACK_PREMULTIPLY_ALPHA_WEBGL` multiplies
//! colour by alpha and `UNPACK_FLIP_Y_WEBGL` puts the rectangle's bottom row first. The
//! source's first row otherwise goes to row 0 of the texture. The selected texels are then
//! converted to the call's `(format, type)` and uploaded as client data would be, so every
//! other check (formats, sizes, levels) is the typed-array path's.

use super::format::f32_to_f16;
use super::pixels::{rgb9e5, unsigned_small_float};
use crate::array::{pixel_array_type, ArrayType, ArrayView};
use crate::context::Context;
use crate::gl;
use crate::state::PixelStore;

/// An image from the DOM as WebGL reads it: 8-bit RGBA, not premultiplied, top row first.
#[derive(Clone, Copy, Debug)]
pub struct ImageSource<'a> {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width × height × 4` bytes.
    pub rgba: &'a [u8],
    /// An `ImageBitmap`: uploaded as it is, without `UNPACK_FLIP_Y_WEBGL` and
    /// `UNPACK_PREMULTIPLY_ALPHA_WEBGL`, which WebGL's pixel storage parameters leave to
    /// the bitmap's own options.
    pub bitmap: bool,
}

/// Which upload, and the numbers of its call.
#[derive(Clone, Copy, Debug)]
pub struct SourceUpload {
    /// `texSubImage*` rather than `texImage*`.
    pub sub: bool,
    /// `tex*3D` rather than `tex*2D`.
    pub three_d: bool,
    /// `target`.
    pub target: u32,
    /// `level`.
    pub level: i32,
    /// `internalformat` (`texImage*`).
    pub internalformat: i32,
    /// `xoffset`, `yoffset`, `zoffset` (`texSubImage*`).
    pub offset: [i32; 3],
    /// `width`, `height`, `depth` (1 in 2D).
    pub size: [i32; 3],
    /// `border` (`texImage*`).
    pub border: i32,
    /// `format`.
    pub format: u32,
    /// `type`.
    pub ty: u32,
}

/// The channels of a `format` as indices into RGBA, or `None` for another format.
fn channels(format: u32) -> Option<&'static [usize]> {
    Some(match format {
        gl::RGBA | gl::RGBA_INTEGER => &[0, 1, 2, 3],
        gl::RGB | gl::RGB_INTEGER => &[0, 1, 2],
        gl::RG | gl::RG_INTEGER => &[0, 1],
        gl::RED | gl::RED_INTEGER | gl::LUMINANCE => &[0],
        gl::ALPHA => &[3],
        gl::LUMINANCE_ALPHA => &[0, 3],
        _ => return None,
    })
}

/// Appends one texel of 8-bit RGBA as `(format, ty)` client data; `false` for a pair an
/// image cannot be converted to.
fn encode(px: [u8; 4], format: u32, ty: u32, out: &mut Vec<u8>) -> bool {
    let Some(ch) = channels(format) else {
        return false;
    };
    let unit = |c: u8| f32::from(c) / 255.0;
    let scale = |c: u8, bits: u32| ((u32::from(c) * ((1 << bits) - 1) + 127) / 255) as u16;
    match ty {
        gl::UNSIGNED_BYTE => out.extend(ch.iter().map(|&i| px[i])),
        gl::FLOAT => {
            for &i in ch {
                out.extend_from_slice(&unit(px[i]).to_ne_bytes());
            }
        }
        // 0x8D61: WebGL 1's HALF_FLOAT_OES.
        gl::HALF_FLOAT | 0x8D61 => {
            for &i in ch {
                out.extend_from_slice(&f32_to_f16(unit(px[i])).to_ne_bytes());
            }
        }
        gl::UNSIGNED_SHORT_5_6_5 if format == gl::RGB => {
            let v = (scale(px[0], 5) << 11) | (scale(px[1], 6) << 5) | scale(px[2], 5);
            out.extend_from_slice(&v.to_ne_bytes());
        }
        gl::UNSIGNED_SHORT_4_4_4_4 if format == gl::RGBA => {
            let [r, g, b, a] = px.map(|c| scale(c, 4));
            out.extend_from_slice(&((r << 12) | (g << 8) | (b << 4) | a).to_ne_bytes());
        }
        gl::UNSIGNED_SHORT_5_5_5_1 if format == gl::RGBA => {
            let [r, g, b] = [px[0], px[1], px[2]].map(|c| scale(c, 5));
            let a = u16::from(px[3] >= 128);
            out.extend_from_slice(&((r << 11) | (g << 6) | (b << 1) | a).to_ne_bytes());
        }
        gl::UNSIGNED_INT_10F_11F_11F_REV if format == gl::RGB => {
            let [r, g, b] = [px[0], px[1], px[2]].map(unit);
            let v = unsigned_small_float(r, 6)
                | (unsigned_small_float(g, 6) << 11)
                | (unsigned_small_float(b, 5) << 22);
            out.extend_from_slice(&v.to_ne_bytes());
        }
        gl::UNSIGNED_INT_5_9_9_9_REV if format == gl::RGB => {
            let v = rgb9e5([px[0], px[1], px[2]].map(unit));
            out.extend_from_slice(&v.to_ne_bytes());
        }
        gl::UNSIGNED_INT_2_10_10_10_REV if format == gl::RGBA => {
            let [r, g, b] = [px[0], px[1], px[2]].map(|c| u32::from(scale(c, 10)));
            let a = u32::from(scale(px[3], 2));
            out.extend_from_slice(&(r | (g << 10) | (b << 20) | (a << 30)).to_ne_bytes());
        }
        _ => return false,
    }
    true
}

/// The texels a source upload selects, converted: `None` when `(format, ty)` is not one
/// an image converts to.
fn select(source: &ImageSource, u: &SourceUpload, p: &PixelStore) -> Option<Vec<u8>> {
    let [w, h, d] = u.size.map(|n| n.max(0) as usize);
    let (sw, sh) = (source.width as usize, source.height as usize);
    let stride = if u.three_d && p.unpack_image_height > 0 {
        p.unpack_image_height as usize
    } else {
        h
    };
    let skip_images = if u.three_d {
        p.unpack_skip_images as usize
    } else {
        0
    };
    let (skip_x, skip_y) = (p.unpack_skip_pixels as usize, p.unpack_skip_rows as usize);
    let mut out = Vec::new();
    for z in 0..d {
        for row in 0..h {
            // Flipped, the rectangle is selected from the source turned upside down (the
            // whole source, as Chromium flips it before the UNPACK_SKIP_* rectangle is taken).
            let f = skip_y + (skip_images + z) * stride + row;
            let sy = if p.unpack_flip_y {
                sh.checked_sub(1 + f)
            } else {
                Some(f)
            };
            for x in 0..w {
                let sx = skip_x + x;
                let mut px = [0u8; 4];
                if let Some(sy) = sy.filter(|&sy| sx < sw && sy < sh) {
                    let i = (sy * sw + sx) * 4;
                    px.copy_from_slice(&source.rgba[i..i + 4]);
                }
                if p.unpack_premultiply_alpha {
                    let a = u32::from(px[3]);
                    for c in &mut px[..3] {
                        *c = ((u32::from(*c) * a + 127) / 255) as u8;
                    }
                }
                if !encode(px, u.format, u.ty, &mut out) {
                    return None;
                }
            }
        }
    }
    Some(out)
}

impl Context {
    /// Specifies or replaces texels from a DOM image source (`texImage2D`, `texImage3D`,
    /// `texSubImage2D`, `texSubImage3D` with a `TexImageSource`), as WebGL 2 does: the
    /// rectangle the `UNPACK_SKIP_*` parameters and the call's size select, flipped and
    /// premultiplied as `UNPACK_FLIP_Y_WEBGL` and `UNPACK_PREMULTIPLY_ALPHA_WEBGL` say,
    /// converted to `(format, type)`. Texels outside the source are transparent black. A
    /// source too short for its size, or a pair no image converts to, reaches the usual
    /// checks with no data (their error).
    pub fn tex_image_source(&mut self, u: SourceUpload, source: ImageSource) {
        let complete = source.rgba.len() >= source.width as usize * source.height as usize * 4;
        // WebGL 1's EXT_sRGB formats take the texels of RGB and RGBA.
        let mut texels = u;
        texels.format = self.webgl1_srgb(0, u.format).1;
        let mut store = self.pixel_store;
        if source.bitmap {
            (store.unpack_flip_y, store.unpack_premultiply_alpha) = (false, false);
        }
        let converted = complete
            .then(|| select(&source, &texels, &store))
            .flatten()
            .unwrap_or_default();
        let array = pixel_array_type(u.ty).unwrap_or(ArrayType::Uint8);
        let view = ArrayView {
            array,
            bytes: &converted,
        };
        // The converted texels are tightly packed, in order: unpack them as such.
        let saved = self.pixel_store;
        let p = &mut self.pixel_store;
        p.unpack_alignment = 1;
        p.unpack_row_length = 0;
        p.unpack_image_height = 0;
        (
            p.unpack_skip_pixels,
            p.unpack_skip_rows,
            p.unpack_skip_images,
        ) = (0, 0, 0);
        (p.unpack_flip_y, p.unpack_premultiply_alpha) = (false, false);
        let (t, l, [x, y, z], [w, h, d]) = (u.target, u.level, u.offset, u.size);
        let (f, ty, ifmt, b) = (u.format, u.ty, u.internalformat, u.border);
        match (u.sub, u.three_d) {
            (false, false) => self.tex_image_2d_view(t, l, ifmt, w, h, b, f, ty, Some(view)),
            (false, true) => self.tex_image_3d_view(t, l, ifmt, w, h, d, b, f, ty, Some(view)),
            (true, false) => self.tex_sub_image_2d_view(t, l, x, y, w, h, f, ty, view),
            (true, true) => self.tex_sub_image_3d_view(t, l, x, y, z, w, h, d, f, ty, view),
        }
        self.pixel_store = saved;
    }
}
