//! WebGL 1's float texture extensions: `OES_texture_float` (`FLOAT` as the type of the five
//! unsized formats), `OES_texture_half_float` (`HALF_FLOAT_OES`, 0x8D61, the same),
//! `OES_texture_float_linear` and `OES_texture_half_float_linear` (linear filtering of
//! those), `WEBGL_color_buffer_float` (`RGBA32F_EXT` renderbuffers, float textures as colour
//! attachments) and `EXT_color_buffer_half_float` (`RGBA16F_EXT`, half-float attachments).
//!
//! An unsized format uploaded with a float type is stored as WebGL 2's float formats are
//! (`RGBA` with `FLOAT` as `RGBA32F` is, `LUMINANCE` with `HALF_FLOAT_OES` as 16-bit floats
//! spread over RGBA), so sampling, rendering and reading back are WebGL 2's code. As in
//! Chromium, turning `OES_texture_float` on turns `WEBGL_color_buffer_float` on too, and
//! `OES_texture_half_float` turns `EXT_color_buffer_half_float` on.

use crate::context::Context;
use crate::gl;
use crate::texture::{Comp, InternalFormat};

/// `HALF_FLOAT_OES`: `OES_texture_half_float`'s type (WebGL 2's `HALF_FLOAT` is 0x140B).
pub(crate) const HALF_FLOAT_OES: u32 = 0x8D61;

impl Context {
    /// The type a WebGL 1 `texImage2D`/`texSubImage2D` uploads as, or `None` after recording
    /// the error: the internal format must be the format, one of the five unsized ones;
    /// the type `UNSIGNED_BYTE`, a packed 16-bit type, `FLOAT` with `OES_texture_float`, or
    /// `HALF_FLOAT_OES` with `OES_texture_half_float` (answered as `HALF_FLOAT`). Any type
    /// passes in WebGL 2.
    pub(crate) fn webgl1_image_type(
        &self,
        function: &str,
        internalformat: i32,
        format: u32,
        ty: u32,
    ) -> Option<u32> {
        if !self.webgl1.on {
            return Some(ty);
        }
        let formats = [
            gl::ALPHA,
            gl::LUMINANCE,
            gl::LUMINANCE_ALPHA,
            gl::RGB,
            gl::RGBA,
        ];
        let w = &self.webgl1;
        let depth = w.depth_texture && matches!(format, gl::DEPTH_COMPONENT | gl::DEPTH_STENCIL);
        let srgb = w.srgb && matches!(format, super::SRGB_EXT | super::SRGB_ALPHA_EXT);
        if !formats.contains(&format) && !depth && !srgb {
            self.error(gl::INVALID_ENUM, function, "not a format of WebGL 1");
            return None;
        }
        let ty = match ty {
            // WEBGL_depth_texture's types.
            gl::UNSIGNED_SHORT | gl::UNSIGNED_INT if depth && format == gl::DEPTH_COMPONENT => ty,
            gl::UNSIGNED_INT_24_8 if depth && format == gl::DEPTH_STENCIL => ty,
            gl::UNSIGNED_BYTE
            | gl::UNSIGNED_SHORT_5_6_5
            | gl::UNSIGNED_SHORT_4_4_4_4
            | gl::UNSIGNED_SHORT_5_5_5_1 => ty,
            gl::FLOAT if w.texture_float => ty,
            HALF_FLOAT_OES if w.texture_half_float => gl::HALF_FLOAT,
            _ => {
                self.error(gl::INVALID_ENUM, function, "not a type of WebGL 1");
                return None;
            }
        };
        if internalformat as u32 != format {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "WebGL 1: the internal format must be the format",
            );
            return None;
        }
        Some(ty)
    }

    /// The internal format a WebGL 1 upload of type `ty` makes of unsized `f`: its 32- or
    /// 16-bit float form for `FLOAT` and `HALF_FLOAT`, `f` itself otherwise (and in WebGL 2).
    pub(crate) fn webgl1_float_format(&self, f: InternalFormat, ty: u32) -> InternalFormat {
        let comp = match ty {
            gl::FLOAT => Comp::F32,
            gl::HALF_FLOAT => Comp::F16,
            _ => return f,
        };
        if !self.webgl1.on {
            return f;
        }
        InternalFormat { comp, ..f }
    }

    /// The type a WebGL 1 `readPixels` reads as: `HALF_FLOAT_OES` is `HALF_FLOAT` once
    /// `OES_texture_half_float` or `EXT_color_buffer_half_float` is on; any other type (and
    /// every type in WebGL 2) is itself.
    pub(crate) fn webgl1_read_type(&self, ty: u32) -> u32 {
        let w = &self.webgl1;
        if w.on && ty == HALF_FLOAT_OES && (w.texture_half_float || w.color_buffer_half_float) {
            gl::HALF_FLOAT
        } else {
            ty
        }
    }

    /// Whether the float renderbuffer formats of WebGL 1's extensions are on for
    /// `renderbufferStorage`: `RGBA32F` with `WEBGL_color_buffer_float`, `RGBA16F` with
    /// `EXT_color_buffer_half_float`.
    pub(crate) fn webgl1_float_renderbuffer(&self, format: u32) -> bool {
        match format {
            gl::RGBA32F => self.webgl1.color_buffer_float,
            gl::RGBA16F => self.webgl1.color_buffer_half_float,
            _ => false,
        }
    }
}
