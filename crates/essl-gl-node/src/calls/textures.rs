//! Textures and samplers: objects, parameters, storage, uploads from typed arrays and from a
//! bound `PIXEL_UNPACK_BUFFER`, and copies from the framebuffer.

use essl_gl::{Sampler, Texture};
use napi_derive::napi;

use crate::answer::Answer;
use crate::context::NativeContext;
use crate::registry::Handle;
use crate::view::View;

/// The numbers of a `texImage`/`texSubImage` call before its data: target, level, then
/// (internalformat, width, height, [depth], border) or (x, y, [z], width, height, [depth]),
/// then format and type.
#[napi(object)]
#[derive(Clone, Copy, Debug)]
pub struct Region {
    /// `target`.
    pub target: u32,
    /// `level`.
    pub level: i32,
    /// `internalformat` (texImage) or 0.
    pub internalformat: i32,
    /// `xoffset` (texSubImage) or 0.
    pub x: i32,
    /// `yoffset` (texSubImage) or 0.
    pub y: i32,
    /// `zoffset` (texSubImage3D) or 0.
    pub z: i32,
    /// `width`.
    pub width: i32,
    /// `height`.
    pub height: i32,
    /// `depth` (1 in 2D).
    pub depth: i32,
    /// `border` (texImage) or 0.
    pub border: i32,
    /// `format`.
    pub format: u32,
    /// `type`.
    pub ty: u32,
}

/// Which of the four upload calls.
#[derive(Clone, Copy)]
enum Upload {
    Image2D,
    Image3D,
    SubImage2D,
    SubImage3D,
}

impl Upload {
    fn of(sub: bool, three_d: bool) -> Upload {
        match (sub, three_d) {
            (false, false) => Upload::Image2D,
            (false, true) => Upload::Image3D,
            (true, false) => Upload::SubImage2D,
            (true, true) => Upload::SubImage3D,
        }
    }

    fn name(self) -> &'static str {
        match self {
            Upload::Image2D => "texImage2D",
            Upload::Image3D => "texImage3D",
            Upload::SubImage2D => "texSubImage2D",
            Upload::SubImage3D => "texSubImage3D",
        }
    }
}

#[napi]
impl NativeContext {
    /// `createTexture`.
    #[napi(catch_unwind)]
    pub fn create_texture(&mut self) -> napi::Result<u32> {
        let t = self.gl()?.create_texture();
        Ok(self.register(Handle::Texture(t)))
    }

    /// `isTexture`.
    #[napi(catch_unwind)]
    pub fn is_texture(&mut self, texture: u32) -> napi::Result<bool> {
        let t = self.arg::<Texture>(texture, "isTexture").flatten();
        Ok(t.is_some_and(|t| self.ctx.as_ref().is_some_and(|c| c.is_texture(t))))
    }

    /// `deleteTexture`.
    #[napi(catch_unwind)]
    pub fn delete_texture(&mut self, texture: u32) -> napi::Result<()> {
        if let Some(t) = self.arg::<Texture>(texture, "deleteTexture").flatten() {
            self.gl()?.delete_texture(t);
        }
        Ok(())
    }

    /// `activeTexture`.
    #[napi(catch_unwind)]
    pub fn active_texture(&mut self, unit: u32) -> napi::Result<()> {
        self.gl()?.active_texture(unit);
        Ok(())
    }

    /// `bindTexture`.
    #[napi(catch_unwind)]
    pub fn bind_texture(&mut self, target: u32, texture: u32) -> napi::Result<()> {
        if let Some(t) = self.arg(texture, "bindTexture") {
            self.gl()?.bind_texture(target, t);
        }
        Ok(())
    }

    /// `texParameteri`.
    #[napi(catch_unwind)]
    pub fn tex_parameteri(&mut self, target: u32, pname: u32, param: i32) -> napi::Result<()> {
        self.gl()?.tex_parameteri(target, pname, param);
        Ok(())
    }

    /// `texParameterf`.
    #[napi(catch_unwind)]
    pub fn tex_parameterf(&mut self, target: u32, pname: u32, param: f64) -> napi::Result<()> {
        self.gl()?.tex_parameterf(target, pname, param as f32);
        Ok(())
    }

    /// `getTexParameter`.
    #[napi(catch_unwind)]
    pub fn get_tex_parameter(&mut self, target: u32, pname: u32) -> napi::Result<Answer> {
        Ok(self.gl()?.get_tex_parameter(target, pname).into())
    }

    /// `generateMipmap`.
    #[napi(catch_unwind)]
    pub fn generate_mipmap(&mut self, target: u32) -> napi::Result<()> {
        self.gl()?.generate_mipmap(target);
        Ok(())
    }

    /// `texStorage2D`.
    #[napi(js_name = "texStorage2D", catch_unwind)]
    pub fn tex_storage_2d(
        &mut self,
        target: u32,
        levels: i32,
        format: u32,
        width: i32,
        height: i32,
    ) -> napi::Result<()> {
        self.gl()?
            .tex_storage_2d(target, levels, format, width, height);
        Ok(())
    }

    /// `texStorage3D`.
    #[napi(js_name = "texStorage3D", catch_unwind)]
    pub fn tex_storage_3d(
        &mut self,
        target: u32,
        levels: i32,
        format: u32,
        width: i32,
        height: i32,
        depth: i32,
    ) -> napi::Result<()> {
        self.gl()?
            .tex_storage_3d(target, levels, format, width, height, depth);
        Ok(())
    }

    /// `texImage2D`/`texImage3D`/`texSubImage2D`/`texSubImage3D` with an
    /// `ArrayBufferView` (or `null`, `texImage` only) and its `srcOffset` in elements.
    #[napi(catch_unwind)]
    pub fn tex_image_view(
        &mut self,
        sub: bool,
        three_d: bool,
        r: Region,
        pixels: Option<View>,
        offset: u32,
    ) -> napi::Result<()> {
        let upload = Upload::of(sub, three_d);
        let pixels = match &pixels {
            Some(v) => match v.window(offset, 0) {
                Some(w) => Some(w),
                None => {
                    // As Chromium: an srcOffset past the view's end leaves too little data,
                    // INVALID_OPERATION.
                    if let Some(c) = &self.ctx {
                        c.synthesize_error(
                            essl_gl::gl::INVALID_OPERATION,
                            upload.name(),
                            "srcOffset past the end of the ArrayBufferView",
                        );
                    }
                    return Ok(());
                }
            },
            None => None,
        };
        let c = self.gl()?;
        let (t, l) = (r.target, r.level);
        match (upload, pixels) {
            (Upload::Image2D, p) => c.tex_image_2d_view(
                t,
                l,
                r.internalformat,
                r.width,
                r.height,
                r.border,
                r.format,
                r.ty,
                p,
            ),
            (Upload::Image3D, p) => c.tex_image_3d_view(
                t,
                l,
                r.internalformat,
                r.width,
                r.height,
                r.depth,
                r.border,
                r.format,
                r.ty,
                p,
            ),
            (Upload::SubImage2D, Some(p)) => {
                c.tex_sub_image_2d_view(t, l, r.x, r.y, r.width, r.height, r.format, r.ty, p)
            }
            (Upload::SubImage3D, Some(p)) => c.tex_sub_image_3d_view(
                t, l, r.x, r.y, r.z, r.width, r.height, r.depth, r.format, r.ty, p,
            ),
            // The JavaScript side refuses a null source of texSubImage with a TypeError.
            (_, None) => {}
        }
        Ok(())
    }

    /// The four upload calls from the bound `PIXEL_UNPACK_BUFFER` at byte `offset`.
    #[napi(catch_unwind)]
    pub fn tex_image_buffer(
        &mut self,
        sub: bool,
        three_d: bool,
        r: Region,
        offset: i64,
    ) -> napi::Result<()> {
        let c = self.gl()?;
        let (t, l) = (r.target, r.level);
        match Upload::of(sub, three_d) {
            Upload::Image2D => c.tex_image_2d_from_buffer(
                t,
                l,
                r.internalformat,
                r.width,
                r.height,
                r.border,
                r.format,
                r.ty,
                offset,
            ),
            Upload::Image3D => c.tex_image_3d_from_buffer(
                t,
                l,
                r.internalformat,
                r.width,
                r.height,
                r.depth,
                r.border,
                r.format,
                r.ty,
                offset,
            ),
            Upload::SubImage2D => c.tex_sub_image_2d_from_buffer(
                t, l, r.x, r.y, r.width, r.height, r.format, r.ty, offset,
            ),
            Upload::SubImage3D => c.tex_sub_image_3d_from_buffer(
                t, l, r.x, r.y, r.z, r.width, r.height, r.depth, r.format, r.ty, offset,
            ),
        }
        Ok(())
    }

    /// `copyTexImage2D`.
    #[napi(js_name = "copyTexImage2D", catch_unwind)]
    #[allow(clippy::too_many_arguments)] // WebGL's own argument list
    pub fn copy_tex_image_2d(
        &mut self,
        target: u32,
        level: i32,
        format: u32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        border: i32,
    ) -> napi::Result<()> {
        self.gl()?
            .copy_tex_image_2d(target, level, format, x, y, width, height, border);
        Ok(())
    }

    /// `copyTexSubImage2D`.
    #[napi(js_name = "copyTexSubImage2D", catch_unwind)]
    #[allow(clippy::too_many_arguments)] // WebGL's own argument list
    pub fn copy_tex_sub_image_2d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
    ) -> napi::Result<()> {
        self.gl()?
            .copy_tex_sub_image_2d(target, level, xoffset, yoffset, x, y, width, height);
        Ok(())
    }

    /// `copyTexSubImage3D`.
    #[napi(js_name = "copyTexSubImage3D", catch_unwind)]
    #[allow(clippy::too_many_arguments)] // WebGL's own argument list
    pub fn copy_tex_sub_image_3d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        zoffset: i32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
    ) -> napi::Result<()> {
        self.gl()?.copy_tex_sub_image_3d(
            target, level, xoffset, yoffset, zoffset, x, y, width, height,
        );
        Ok(())
    }

    /// The compressed-texture calls (the S3TC and ETC formats, once their extension is on);
    /// `numbers` are the arguments between `level` and the data, `data` the bytes if any.
    #[napi(catch_unwind)]
    pub fn compressed_tex_image(
        &mut self,
        name: String,
        target: u32,
        level: i32,
        numbers: Vec<f64>,
        data: Option<View>,
    ) -> napi::Result<()> {
        let n = |k: usize| numbers.get(k).copied().unwrap_or(0.0);
        let (i, u) = (|k| n(k) as i32, |k| n(k) as u32);
        let c = self.gl()?;
        let Some(data) = data else {
            // (…, imageSize, offset): the bound PIXEL_UNPACK_BUFFER's bytes.
            let ints: Vec<i64> = numbers.iter().map(|&x| x as i64).collect();
            if let [head @ .., size, offset] = &ints[..] {
                c.compressed_tex_from_buffer(&name, target, level, head, *size, *offset);
            }
            return Ok(());
        };
        let bytes = data.bytes();
        match name.as_str() {
            "compressedTexImage2D" => {
                c.compressed_tex_image_2d(target, level, u(0), i(1), i(2), i(3), bytes)
            }
            "compressedTexImage3D" => {
                c.compressed_tex_image_3d(target, level, u(0), i(1), i(2), i(3), i(4), bytes)
            }
            "compressedTexSubImage2D" => {
                c.compressed_tex_sub_image_2d(target, level, i(0), i(1), i(2), i(3), u(4), bytes)
            }
            _ => c.compressed_tex_sub_image_3d(
                target,
                level,
                i(0),
                i(1),
                i(2),
                i(3),
                i(4),
                i(5),
                u(6),
                bytes,
            ),
        }
        Ok(())
    }

    /// `createSampler`.
    #[napi(catch_unwind)]
    pub fn create_sampler(&mut self) -> napi::Result<u32> {
        let s = self.gl()?.create_sampler();
        Ok(self.register(Handle::Sampler(s)))
    }

    /// `isSampler`.
    #[napi(catch_unwind)]
    pub fn is_sampler(&mut self, sampler: u32) -> napi::Result<bool> {
        let s = self.arg::<Sampler>(sampler, "isSampler").flatten();
        Ok(s.is_some_and(|s| self.ctx.as_ref().is_some_and(|c| c.is_sampler(s))))
    }

    /// `deleteSampler`.
    #[napi(catch_unwind)]
    pub fn delete_sampler(&mut self, sampler: u32) -> napi::Result<()> {
        if let Some(s) = self.arg::<Sampler>(sampler, "deleteSampler").flatten() {
            self.gl()?.delete_sampler(s);
        }
        Ok(())
    }

    /// `bindSampler`.
    #[napi(catch_unwind)]
    pub fn bind_sampler(&mut self, unit: u32, sampler: u32) -> napi::Result<()> {
        if let Some(s) = self.arg(sampler, "bindSampler") {
            self.gl()?.bind_sampler(unit, s);
        }
        Ok(())
    }

    /// `samplerParameteri`.
    #[napi(catch_unwind)]
    pub fn sampler_parameteri(&mut self, sampler: u32, pname: u32, param: i32) -> napi::Result<()> {
        if let Some(s) = self.req::<Sampler>(sampler, "samplerParameteri") {
            self.gl()?.sampler_parameteri(s, pname, param);
        }
        Ok(())
    }

    /// `samplerParameterf`.
    #[napi(catch_unwind)]
    pub fn sampler_parameterf(&mut self, sampler: u32, pname: u32, param: f64) -> napi::Result<()> {
        if let Some(s) = self.req::<Sampler>(sampler, "samplerParameterf") {
            self.gl()?.sampler_parameterf(s, pname, param as f32);
        }
        Ok(())
    }

    /// `getSamplerParameter`.
    #[napi(catch_unwind)]
    pub fn get_sampler_parameter(&mut self, sampler: u32, pname: u32) -> napi::Result<Answer> {
        let Some(s) = self.req::<Sampler>(sampler, "getSamplerParameter") else {
            return Ok(Answer::Null);
        };
        Ok(self.gl()?.get_sampler_parameter(s, pname).into())
    }
}

#[napi]
impl NativeContext {
    /// The four upload calls from a DOM image source: `rgba` is 8-bit RGBA, unpremultiplied,
    /// top row first, `width` × `height`; `bitmap` for an ImageBitmap, uploaded as it is.
    #[allow(clippy::too_many_arguments)]
    #[napi(catch_unwind)]
    pub fn tex_image_source(
        &mut self,
        sub: bool,
        three_d: bool,
        r: Region,
        rgba: View,
        width: u32,
        height: u32,
        bitmap: bool,
    ) -> napi::Result<()> {
        let upload = essl_gl::SourceUpload {
            sub,
            three_d,
            target: r.target,
            level: r.level,
            internalformat: r.internalformat,
            offset: [r.x, r.y, r.z],
            size: [r.width, r.height, r.depth],
            border: r.border,
            format: r.format,
            ty: r.ty,
        };
        let source = essl_gl::ImageSource {
            width,
            height,
            rgba: rgba.bytes(),
            bitmap,
        };
        self.gl()?.tex_image_source(upload, source);
        Ok(())
    }

    /// Records a WebGL error as the bindings do for what only they see (`bufferData` with
    /// `null`, `readPixels` into `null`).
    #[napi(catch_unwind)]
    pub fn synthesize_error(
        &mut self,
        code: u32,
        call: String,
        message: String,
    ) -> napi::Result<()> {
        self.gl()?.synthesize_error(code, &call, &message);
        Ok(())
    }
}
