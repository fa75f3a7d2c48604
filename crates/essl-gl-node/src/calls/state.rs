//! Fixed-function state, clears, errors, parameters and extensions of the context.

use napi_derive::napi;

use crate::answer::Answer;
use crate::context::NativeContext;

#[napi]
impl NativeContext {
    /// `enable`.
    #[napi(catch_unwind)]
    pub fn enable(&mut self, cap: u32) -> napi::Result<()> {
        self.gl()?.enable(cap);
        Ok(())
    }

    /// `EXT_clip_control.clipControlEXT`.
    #[napi(catch_unwind)]
    pub fn clip_control_ext(&mut self, origin: u32, depth: u32) -> napi::Result<()> {
        self.gl()?.clip_control_ext(origin, depth);
        Ok(())
    }

    /// `disable`.
    #[napi(catch_unwind)]
    pub fn disable(&mut self, cap: u32) -> napi::Result<()> {
        self.gl()?.disable(cap);
        Ok(())
    }

    /// `isEnabled`.
    #[napi(catch_unwind)]
    pub fn is_enabled(&mut self, cap: u32) -> napi::Result<bool> {
        Ok(self.gl()?.is_enabled(cap))
    }

    /// `viewport`.
    #[napi(catch_unwind)]
    pub fn viewport(&mut self, x: i32, y: i32, width: i32, height: i32) -> napi::Result<()> {
        self.gl()?.viewport(x, y, width, height);
        Ok(())
    }

    /// `scissor`.
    #[napi(catch_unwind)]
    pub fn scissor(&mut self, x: i32, y: i32, width: i32, height: i32) -> napi::Result<()> {
        self.gl()?.scissor(x, y, width, height);
        Ok(())
    }

    /// `clearColor`.
    #[napi(catch_unwind)]
    pub fn clear_color(&mut self, r: f64, g: f64, b: f64, a: f64) -> napi::Result<()> {
        self.gl()?
            .clear_color(r as f32, g as f32, b as f32, a as f32);
        Ok(())
    }

    /// `clearDepth`.
    #[napi(catch_unwind)]
    pub fn clear_depth(&mut self, depth: f64) -> napi::Result<()> {
        self.gl()?.clear_depth(depth as f32);
        Ok(())
    }

    /// `clearStencil`.
    #[napi(catch_unwind)]
    pub fn clear_stencil(&mut self, s: i32) -> napi::Result<()> {
        self.gl()?.clear_stencil(s);
        Ok(())
    }

    /// `depthFunc`.
    #[napi(catch_unwind)]
    pub fn depth_func(&mut self, func: u32) -> napi::Result<()> {
        self.gl()?.depth_func(func);
        Ok(())
    }

    /// `depthMask`.
    #[napi(catch_unwind)]
    pub fn depth_mask(&mut self, flag: bool) -> napi::Result<()> {
        self.gl()?.depth_mask(flag);
        Ok(())
    }

    /// `depthRange`.
    #[napi(catch_unwind)]
    pub fn depth_range(&mut self, near: f64, far: f64) -> napi::Result<()> {
        self.gl()?.depth_range(near as f32, far as f32);
        Ok(())
    }

    /// `cullFace`.
    #[napi(catch_unwind)]
    pub fn cull_face(&mut self, mode: u32) -> napi::Result<()> {
        self.gl()?.cull_face(mode);
        Ok(())
    }

    /// `frontFace`.
    #[napi(catch_unwind)]
    pub fn front_face(&mut self, mode: u32) -> napi::Result<()> {
        self.gl()?.front_face(mode);
        Ok(())
    }

    /// `blendFunc`.
    #[napi(catch_unwind)]
    pub fn blend_func(&mut self, sfactor: u32, dfactor: u32) -> napi::Result<()> {
        self.gl()?.blend_func(sfactor, dfactor);
        Ok(())
    }

    /// `blendFuncSeparate`.
    #[napi(catch_unwind)]
    pub fn blend_func_separate(
        &mut self,
        src_rgb: u32,
        dst_rgb: u32,
        src_alpha: u32,
        dst_alpha: u32,
    ) -> napi::Result<()> {
        self.gl()?
            .blend_func_separate(src_rgb, dst_rgb, src_alpha, dst_alpha);
        Ok(())
    }

    /// `blendEquation`.
    #[napi(catch_unwind)]
    pub fn blend_equation(&mut self, mode: u32) -> napi::Result<()> {
        self.gl()?.blend_equation(mode);
        Ok(())
    }

    /// `blendEquationSeparate`.
    #[napi(catch_unwind)]
    pub fn blend_equation_separate(&mut self, rgb: u32, alpha: u32) -> napi::Result<()> {
        self.gl()?.blend_equation_separate(rgb, alpha);
        Ok(())
    }

    /// `blendColor`.
    #[napi(catch_unwind)]
    pub fn blend_color(&mut self, r: f64, g: f64, b: f64, a: f64) -> napi::Result<()> {
        self.gl()?
            .blend_color(r as f32, g as f32, b as f32, a as f32);
        Ok(())
    }

    /// `colorMask`.
    #[napi(catch_unwind)]
    pub fn color_mask(&mut self, r: bool, g: bool, b: bool, a: bool) -> napi::Result<()> {
        self.gl()?.color_mask(r, g, b, a);
        Ok(())
    }

    /// `EXT_polygon_offset_clamp.polygonOffsetClampEXT`.
    #[napi(catch_unwind)]
    pub fn polygon_offset_clamp_ext(
        &mut self,
        factor: f64,
        units: f64,
        clamp: f64,
    ) -> napi::Result<()> {
        self.gl()?
            .polygon_offset_clamp_ext(factor as f32, units as f32, clamp as f32);
        Ok(())
    }

    /// `WEBGL_polygon_mode.polygonModeWEBGL`.
    #[napi(catch_unwind)]
    pub fn polygon_mode_webgl(&mut self, face: u32, mode: u32) -> napi::Result<()> {
        self.gl()?.polygon_mode_webgl(face, mode);
        Ok(())
    }

    /// `OES_draw_buffers_indexed.enableiOES` / `disableiOES`.
    #[napi(catch_unwind)]
    pub fn enable_indexed(&mut self, target: u32, index: u32, on: bool) -> napi::Result<()> {
        self.gl()?.set_enabled_indexed(target, index, on);
        Ok(())
    }

    /// `OES_draw_buffers_indexed.blendEquationSeparateiOES` (and `blendEquationiOES`).
    #[napi(catch_unwind)]
    pub fn blend_equation_separate_indexed(
        &mut self,
        index: u32,
        rgb: u32,
        alpha: u32,
    ) -> napi::Result<()> {
        self.gl()?
            .blend_equation_separate_indexed(index, rgb, alpha);
        Ok(())
    }

    /// `OES_draw_buffers_indexed.blendFuncSeparateiOES` (and `blendFunciOES`).
    #[napi(catch_unwind)]
    pub fn blend_func_separate_indexed(
        &mut self,
        index: u32,
        src_rgb: u32,
        dst_rgb: u32,
        src_alpha: u32,
        dst_alpha: u32,
    ) -> napi::Result<()> {
        let factors = [src_rgb, dst_rgb, src_alpha, dst_alpha];
        self.gl()?.blend_func_separate_indexed(index, factors);
        Ok(())
    }

    /// `OES_draw_buffers_indexed.colorMaskiOES`.
    #[napi(catch_unwind)]
    pub fn color_mask_indexed(
        &mut self,
        index: u32,
        r: bool,
        g: bool,
        b: bool,
        a: bool,
    ) -> napi::Result<()> {
        self.gl()?.color_mask_indexed(index, [r, g, b, a]);
        Ok(())
    }

    /// `polygonOffset`.
    #[napi(catch_unwind)]
    pub fn polygon_offset(&mut self, factor: f64, units: f64) -> napi::Result<()> {
        self.gl()?.polygon_offset(factor as f32, units as f32);
        Ok(())
    }

    /// `sampleCoverage`.
    #[napi(catch_unwind)]
    pub fn sample_coverage(&mut self, value: f64, invert: bool) -> napi::Result<()> {
        self.gl()?.sample_coverage(value as f32, invert);
        Ok(())
    }

    /// `hint`.
    #[napi(catch_unwind)]
    pub fn hint(&mut self, target: u32, mode: u32) -> napi::Result<()> {
        self.gl()?.hint(target, mode);
        Ok(())
    }

    /// `lineWidth`.
    #[napi(catch_unwind)]
    pub fn line_width(&mut self, width: f64) -> napi::Result<()> {
        self.gl()?.line_width(width as f32);
        Ok(())
    }

    /// `pixelStorei`.
    #[napi(catch_unwind)]
    pub fn pixel_storei(&mut self, pname: u32, param: i32) -> napi::Result<()> {
        self.gl()?.pixel_storei(pname, param);
        Ok(())
    }

    /// `stencilFunc`.
    #[napi(catch_unwind)]
    pub fn stencil_func(&mut self, func: u32, reference: i32, mask: u32) -> napi::Result<()> {
        self.gl()?.stencil_func(func, reference, mask);
        Ok(())
    }

    /// `stencilFuncSeparate`.
    #[napi(catch_unwind)]
    pub fn stencil_func_separate(
        &mut self,
        face: u32,
        func: u32,
        reference: i32,
        mask: u32,
    ) -> napi::Result<()> {
        self.gl()?
            .stencil_func_separate(face, func, reference, mask);
        Ok(())
    }

    /// `stencilOp`.
    #[napi(catch_unwind)]
    pub fn stencil_op(&mut self, fail: u32, zfail: u32, zpass: u32) -> napi::Result<()> {
        self.gl()?.stencil_op(fail, zfail, zpass);
        Ok(())
    }

    /// `stencilOpSeparate`.
    #[napi(catch_unwind)]
    pub fn stencil_op_separate(
        &mut self,
        face: u32,
        fail: u32,
        zfail: u32,
        zpass: u32,
    ) -> napi::Result<()> {
        self.gl()?.stencil_op_separate(face, fail, zfail, zpass);
        Ok(())
    }

    /// `stencilMask`.
    #[napi(catch_unwind)]
    pub fn stencil_mask(&mut self, mask: u32) -> napi::Result<()> {
        self.gl()?.stencil_mask(mask);
        Ok(())
    }

    /// `stencilMaskSeparate`.
    #[napi(catch_unwind)]
    pub fn stencil_mask_separate(&mut self, face: u32, mask: u32) -> napi::Result<()> {
        self.gl()?.stencil_mask_separate(face, mask);
        Ok(())
    }

    /// `clear`.
    #[napi(catch_unwind)]
    pub fn clear(&mut self, mask: u32) -> napi::Result<()> {
        self.gl()?.clear(mask);
        Ok(())
    }

    /// `clearBufferfv` with its `srcOffset`.
    #[napi(catch_unwind)]
    pub fn clear_bufferfv(
        &mut self,
        buffer: u32,
        drawbuffer: i32,
        values: &[f32],
        offset: u32,
    ) -> napi::Result<()> {
        let Some(v) = values.get(offset as usize..) else {
            self.past_end("clearBufferfv");
            return Ok(());
        };
        self.gl()?.clear_bufferfv(buffer, drawbuffer, v);
        Ok(())
    }

    /// `clearBufferiv` with its `srcOffset`.
    #[napi(catch_unwind)]
    pub fn clear_bufferiv(
        &mut self,
        buffer: u32,
        drawbuffer: i32,
        values: &[i32],
        offset: u32,
    ) -> napi::Result<()> {
        let Some(v) = values.get(offset as usize..) else {
            self.past_end("clearBufferiv");
            return Ok(());
        };
        self.gl()?.clear_bufferiv(buffer, drawbuffer, v);
        Ok(())
    }

    /// `clearBufferuiv` with its `srcOffset`.
    #[napi(catch_unwind)]
    pub fn clear_bufferuiv(
        &mut self,
        buffer: u32,
        drawbuffer: i32,
        values: &[u32],
        offset: u32,
    ) -> napi::Result<()> {
        let Some(v) = values.get(offset as usize..) else {
            self.past_end("clearBufferuiv");
            return Ok(());
        };
        self.gl()?.clear_bufferuiv(buffer, drawbuffer, v);
        Ok(())
    }

    /// `clearBufferfi`.
    #[napi(catch_unwind)]
    pub fn clear_bufferfi(
        &mut self,
        buffer: u32,
        drawbuffer: i32,
        depth: f64,
        stencil: i32,
    ) -> napi::Result<()> {
        self.gl()?
            .clear_bufferfi(buffer, drawbuffer, depth as f32, stencil);
        Ok(())
    }

    /// `getError`.
    #[napi(catch_unwind)]
    pub fn get_error(&mut self) -> napi::Result<u32> {
        Ok(self.gl()?.get_error())
    }

    /// `finish`.
    #[napi(catch_unwind)]
    pub fn finish(&mut self) -> napi::Result<()> {
        self.gl()?.finish();
        Ok(())
    }

    /// `flush`.
    #[napi(catch_unwind)]
    pub fn flush(&mut self) -> napi::Result<()> {
        self.gl()?.flush();
        Ok(())
    }

    /// `getParameter`.
    #[napi(catch_unwind)]
    pub fn get_parameter(&mut self, pname: u32) -> napi::Result<Answer> {
        Ok(self.gl()?.get_parameter(pname).into())
    }

    /// `getSupportedExtensions`: the extensions essl-gl implements.
    #[napi(catch_unwind)]
    pub fn get_supported_extensions(&mut self) -> napi::Result<Vec<String>> {
        Ok(self
            .gl()?
            .get_supported_extensions()
            .into_iter()
            .map(str::to_string)
            .collect())
    }

    /// `getExtension`: turns an extension of essl-gl on; its name, or `None`.
    #[napi(catch_unwind)]
    pub fn get_extension(&mut self, name: String) -> napi::Result<Option<String>> {
        Ok(self.gl()?.get_extension(&name).map(|e| e.name().into()))
    }

    /// `drawingBufferStorage`.
    #[napi(catch_unwind)]
    pub fn drawing_buffer_storage(
        &mut self,
        format: u32,
        width: u32,
        height: u32,
    ) -> napi::Result<()> {
        self.gl()?.drawing_buffer_storage(format, width, height);
        Ok(())
    }
}
