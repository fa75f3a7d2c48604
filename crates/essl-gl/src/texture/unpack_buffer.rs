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
        let id = self.unpack_buffer(function)?;
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
        let data = self.unpack_bytes(id)?;
        Some(data.get(offset as usize..).unwrap_or_default().to_vec())
    }

    /// The bound `PIXEL_UNPACK_BUFFER`, or `INVALID_OPERATION` when none is or it is bound
    /// for transform feedback too.
    fn unpack_buffer(&mut self, function: &str) -> Option<crate::objects::Id> {
        let Some(id) = self.bindings.buffer(gl::PIXEL_UNPACK_BUFFER) else {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "no PIXEL_UNPACK_BUFFER bound",
            );
            return None;
        };
        (!self.refuse_double_bound(id, function)).then_some(id)
    }

    /// The CPU copy of buffer `id`'s bytes, brought up to date.
    fn unpack_bytes(&mut self, id: crate::objects::Id) -> Option<&[u8]> {
        let b = self.objects.buffers.get_any_mut(id)?;
        Some(b.cpu_bytes(&self.gpu, &mut self.frame))
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

    /// `compressedTexImage2D`: a level of a 2D texture or cube face from compressed blocks
    /// (`texture/compressed/`); formats whose extension is off are `INVALID_ENUM`.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn compressed_tex_image_2d(
        &mut self,
        target: u32,
        level: i32,
        internalformat: u32,
        width: i32,
        height: i32,
        border: i32,
        data: &[u8],
    ) {
        let n = [
            internalformat as i64,
            width as i64,
            height as i64,
            border as i64,
        ];
        self.compressed_dispatch("compressedTexImage2D", target, level, &n, Src::Client(data));
    }

    /// `compressedTexImage3D`: a level of a 2D array texture from compressed blocks (3D
    /// textures take none of the formats: `INVALID_OPERATION`).
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn compressed_tex_image_3d(
        &mut self,
        target: u32,
        level: i32,
        internalformat: u32,
        width: i32,
        height: i32,
        depth: i32,
        border: i32,
        data: &[u8],
    ) {
        let n = [
            internalformat as i64,
            width as i64,
            height as i64,
            depth as i64,
            border as i64,
        ];
        self.compressed_dispatch("compressedTexImage3D", target, level, &n, Src::Client(data));
    }

    /// `compressedTexSubImage2D`: a region of a compressed level, in whole blocks.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn compressed_tex_sub_image_2d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        width: i32,
        height: i32,
        format: u32,
        data: &[u8],
    ) {
        let n = [
            xoffset as i64,
            yoffset as i64,
            width as i64,
            height as i64,
            format as i64,
        ];
        self.compressed_dispatch(
            "compressedTexSubImage2D",
            target,
            level,
            &n,
            Src::Client(data),
        );
    }

    /// `compressedTexSubImage3D`: a region of a compressed 2D array level.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn compressed_tex_sub_image_3d(
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
        data: &[u8],
    ) {
        let region = [xoffset, yoffset, zoffset, width, height, depth].map(i64::from);
        let mut n = region.to_vec();
        n.push(format as i64);
        self.compressed_dispatch(
            "compressedTexSubImage3D",
            target,
            level,
            &n,
            Src::Client(data),
        );
    }

    /// The compressed calls' forms that read the bound `PIXEL_UNPACK_BUFFER`: `image_size`
    /// bytes at `offset` (past the buffer's end → `INVALID_OPERATION`). `function` names the
    /// call (`compressedTexImage2D`, …); `numbers` are its arguments between `level` and
    /// `imageSize`, as in WebGL.
    pub fn compressed_tex_from_buffer(
        &mut self,
        function: &str,
        target: u32,
        level: i32,
        numbers: &[i64],
        image_size: i64,
        offset: i64,
    ) {
        let src = Src::Buffer { image_size, offset };
        self.compressed_dispatch(function, target, level, numbers, src);
    }

    /// A compressed call by name: the target check, then the image or region it names.
    fn compressed_dispatch(
        &mut self,
        function: &str,
        target: u32,
        level: i32,
        numbers: &[i64],
        src: Src,
    ) {
        let n = |k: usize| numbers.get(k).copied().unwrap_or(0) as i32;
        let f: &'static str = match function {
            "compressedTexImage2D" => "compressedTexImage2D",
            "compressedTexImage3D" => "compressedTexImage3D",
            "compressedTexSubImage2D" => "compressedTexSubImage2D",
            _ => "compressedTexSubImage3D",
        };
        let target_ok = if f.ends_with("3D") {
            matches!(target, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY)
        } else {
            two_d(target)
        };
        if !target_ok {
            return self.error(gl::INVALID_ENUM, f, format_args!("target 0x{target:04X}"));
        }
        let (format, size, offset, border) = match f {
            "compressedTexImage2D" => (n(0), [n(1), n(2), 1], None, n(3)),
            "compressedTexImage3D" => (n(0), [n(1), n(2), n(3)], None, n(4)),
            "compressedTexSubImage2D" => (n(4), [n(2), n(3), 1], Some([n(0), n(1), 0]), 0),
            _ => (n(6), [n(3), n(4), n(5)], Some([n(0), n(1), n(2)]), 0),
        };
        self.compressed_call(target, level, format as u32, size, offset, border, src, f);
    }

    #[allow(clippy::too_many_arguments)]
    fn compressed_call(
        &mut self,
        target: u32,
        level: i32,
        format: u32,
        size: [i32; 3],
        offset: Option<[i32; 3]>,
        border: i32,
        src: Src,
        function: &'static str,
    ) {
        let owned;
        let data = match src {
            Src::Client(data) => {
                if self.client_data_refused(function) {
                    return;
                }
                data
            }
            Src::Buffer { image_size, offset } => {
                let Some(id) = self.unpack_buffer(function) else {
                    return;
                };
                if image_size < 0 || offset < 0 {
                    return self.error(gl::INVALID_VALUE, function, "negative imageSize or offset");
                }
                let Some(bytes) = self.unpack_bytes(id) else {
                    return;
                };
                let end = offset as u64 + image_size as u64;
                if end > bytes.len() as u64 {
                    return self.error(
                        gl::INVALID_OPERATION,
                        function,
                        "imageSize bytes at offset run past the PIXEL_UNPACK_BUFFER's end",
                    );
                }
                owned = bytes[offset as usize..end as usize].to_vec();
                &owned[..]
            }
        };
        if border != 0 {
            return self.error(gl::INVALID_VALUE, function, "border must be 0");
        }
        self.compressed_image(super::compressed::CompressedImage {
            target,
            level,
            format,
            size,
            offset,
            data,
            function,
        });
    }
}

/// Where a compressed upload's bytes come from.
enum Src<'a> {
    Client(&'a [u8]),
    Buffer { image_size: i64, offset: i64 },
}

/// Whether `target` is a 2D image target (`TEXTURE_2D` or a cube face).
fn two_d(target: u32) -> bool {
    matches!(
        target,
        gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z
    )
}
