//! Texture uploads from the bound `PIXEL_UNPACK_BUFFER` (WebGL2's overloads of `texImage*`
//! and `texSubImage*` that take a byte offset), and the compressed-texture entry points,
//! which take no format here: essl-gl offers no compressed-texture extension, so every
//! compressed internal format is `INVALID_ENUM`, as in a WebGL2 context without one.

use super::upload::{TexImage, TexSubImage};
use crate::context::Context;
use crate::gl;

impl Context {
    /// The bound unpack buffer's bytes from `offset`, or the error: none bound →
    /// `INVALID_OPERATION`, a negative offset → `INVALID_VALUE`, `UNPACK_FLIP_Y_WEBGL` or
    /// `UNPACK_PREMULTIPLY_ALPHA_WEBGL` set → `INVALID_OPERATION` (as WebGL 2 has it).
    fn unpack_source(&mut self, offset: i64, function: &str) -> Option<Vec<u8>> {
        let Some(id) = self.bindings.buffer(gl::PIXEL_UNPACK_BUFFER) else {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "no PIXEL_UNPACK_BUFFER bound",
            );
            return None;
        };
        if offset < 0 {
            self.error(gl::INVALID_VALUE, function, "negative offset");
            return None;
        }
        if self.pixel_store.unpack_flip_y || self.pixel_store.unpack_premultiply_alpha {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "UNPACK_FLIP_Y_WEBGL or UNPACK_PREMULTIPLY_ALPHA_WEBGL with a PIXEL_UNPACK_BUFFER",
            );
            return None;
        }
        let b = self.objects.buffers.get_any_mut(id)?;
        let data = b.cpu_bytes(&self.gpu, &mut self.frame);
        Some(data.get(offset as usize..).unwrap_or_default().to_vec())
    }

    /// `texImage2D` from the bound `PIXEL_UNPACK_BUFFER` at byte `offset`; see
    /// [`Context::tex_image_2d`]. Data past the buffer's end → `INVALID_OPERATION`.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_image_2d_from_buffer(
        &mut self,
        target: u32,
        level: i32,
        internalformat: i32,
        width: i32,
        height: i32,
        border: i32,
        format: u32,
        ty: u32,
        offset: i64,
    ) {
        const F: &str = "texImage2D";
        if !matches!(
            super::image_target(target),
            Some((gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP, _))
        ) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        let Some(src) = self.unpack_source(offset, F) else {
            return;
        };
        self.tex_image(TexImage {
            target,
            level,
            internalformat,
            size: [width, height, 1],
            border,
            format,
            ty,
            pixels: Some(&src),
            array: None,
            function: F,
        });
    }

    /// `texImage3D` from the bound `PIXEL_UNPACK_BUFFER` at byte `offset`.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_image_3d_from_buffer(
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
        offset: i64,
    ) {
        const F: &str = "texImage3D";
        if !matches!(target, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        let Some(src) = self.unpack_source(offset, F) else {
            return;
        };
        self.tex_image(TexImage {
            target,
            level,
            internalformat,
            size: [width, height, depth],
            border,
            format,
            ty,
            pixels: Some(&src),
            array: None,
            function: F,
        });
    }

    /// `texSubImage2D` from the bound `PIXEL_UNPACK_BUFFER` at byte `offset`.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_sub_image_2d_from_buffer(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        offset: i64,
    ) {
        const F: &str = "texSubImage2D";
        if !matches!(
            super::image_target(target),
            Some((gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP, _))
        ) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        let Some(src) = self.unpack_source(offset, F) else {
            return;
        };
        self.tex_sub_image(TexSubImage {
            target,
            level,
            offset: [xoffset, yoffset, 0],
            size: [width, height, 1],
            format,
            ty,
            pixels: &src,
            array: None,
            function: F,
        });
    }

    /// `texSubImage3D` from the bound `PIXEL_UNPACK_BUFFER` at byte `offset`.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_sub_image_3d_from_buffer(
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
        offset: i64,
    ) {
        const F: &str = "texSubImage3D";
        if !matches!(target, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        let Some(src) = self.unpack_source(offset, F) else {
            return;
        };
        self.tex_sub_image(TexSubImage {
            target,
            level,
            offset: [xoffset, yoffset, zoffset],
            size: [width, height, depth],
            format,
            ty,
            pixels: &src,
            array: None,
            function: F,
        });
    }

    /// `compressedTexImage2D`: no compressed format is offered → `INVALID_ENUM`.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn compressed_tex_image_2d(
        &mut self,
        _target: u32,
        _level: i32,
        internalformat: u32,
        _width: i32,
        _height: i32,
        _border: i32,
        _data: &[u8],
    ) {
        self.no_compressed_format(internalformat, "compressedTexImage2D");
    }

    /// `compressedTexImage3D`: no compressed format is offered → `INVALID_ENUM`.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn compressed_tex_image_3d(
        &mut self,
        _target: u32,
        _level: i32,
        internalformat: u32,
        _width: i32,
        _height: i32,
        _depth: i32,
        _border: i32,
        _data: &[u8],
    ) {
        self.no_compressed_format(internalformat, "compressedTexImage3D");
    }

    /// `compressedTexSubImage2D`: no compressed format is offered → `INVALID_ENUM`.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn compressed_tex_sub_image_2d(
        &mut self,
        _target: u32,
        _level: i32,
        _xoffset: i32,
        _yoffset: i32,
        _width: i32,
        _height: i32,
        format: u32,
        _data: &[u8],
    ) {
        self.no_compressed_format(format, "compressedTexSubImage2D");
    }

    /// `compressedTexSubImage3D`: no compressed format is offered → `INVALID_ENUM`.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn compressed_tex_sub_image_3d(
        &mut self,
        _target: u32,
        _level: i32,
        _xoffset: i32,
        _yoffset: i32,
        _zoffset: i32,
        _width: i32,
        _height: i32,
        _depth: i32,
        format: u32,
        _data: &[u8],
    ) {
        self.no_compressed_format(format, "compressedTexSubImage3D");
    }

    fn no_compressed_format(&mut self, format: u32, function: &str) {
        self.error(
            gl::INVALID_ENUM,
            function,
            format_args!("0x{format:04X}: no compressed texture format is enabled"),
        );
    }
}
