//! Buffers, vertex arrays, vertex attributes and draws.

use essl_gl::{Buffer, VertexArray};
use napi_derive::napi;

use crate::answer::Answer;
use crate::context::NativeContext;
use crate::registry::Handle;
use crate::view::View;

#[napi]
impl NativeContext {
    /// `createBuffer`: the new buffer's id.
    #[napi(catch_unwind)]
    pub fn create_buffer(&mut self) -> napi::Result<u32> {
        let b = self.gl()?.create_buffer();
        Ok(self.register(Handle::Buffer(b)))
    }

    /// `isBuffer`.
    #[napi(catch_unwind)]
    pub fn is_buffer(&mut self, buffer: u32) -> napi::Result<bool> {
        let b = self.arg::<Buffer>(buffer, "isBuffer").flatten();
        Ok(b.is_some_and(|b| self.ctx.as_ref().is_some_and(|c| c.is_buffer(b))))
    }

    /// `deleteBuffer`.
    #[napi(catch_unwind)]
    pub fn delete_buffer(&mut self, buffer: u32) -> napi::Result<()> {
        if let Some(b) = self.arg::<Buffer>(buffer, "deleteBuffer").flatten() {
            self.gl()?.delete_buffer(b);
        }
        Ok(())
    }

    /// `bindBuffer`.
    #[napi(catch_unwind)]
    pub fn bind_buffer(&mut self, target: u32, buffer: u32) -> napi::Result<()> {
        if let Some(b) = self.arg(buffer, "bindBuffer") {
            self.gl()?.bind_buffer(target, b);
        }
        Ok(())
    }

    /// `bindBufferBase`.
    #[napi(catch_unwind)]
    pub fn bind_buffer_base(&mut self, target: u32, index: u32, buffer: u32) -> napi::Result<()> {
        if let Some(b) = self.arg(buffer, "bindBufferBase") {
            self.gl()?.bind_buffer_base(target, index, b);
        }
        Ok(())
    }

    /// `bindBufferRange`.
    #[napi(catch_unwind)]
    pub fn bind_buffer_range(
        &mut self,
        target: u32,
        index: u32,
        buffer: u32,
        offset: i64,
        size: i64,
    ) -> napi::Result<()> {
        if let Some(b) = self.arg(buffer, "bindBufferRange") {
            self.gl()?.bind_buffer_range(target, index, b, offset, size);
        }
        Ok(())
    }

    /// `bufferData(target, size, usage)`.
    #[napi(catch_unwind)]
    pub fn buffer_data_size(&mut self, target: u32, size: i64, usage: u32) -> napi::Result<()> {
        self.gl()?.buffer_data_size(target, size, usage);
        Ok(())
    }

    /// `bufferData(target, srcData, usage, srcOffset, length)`.
    #[napi(catch_unwind)]
    pub fn buffer_data(
        &mut self,
        target: u32,
        data: View,
        usage: u32,
        offset: u32,
        length: u32,
    ) -> napi::Result<()> {
        let Some(w) = data.window(offset, length) else {
            self.past_end("bufferData");
            return Ok(());
        };
        self.gl()?.buffer_data(target, w.bytes, usage);
        Ok(())
    }

    /// `bufferSubData(target, dstByteOffset, srcData, srcOffset, length)`.
    #[napi(catch_unwind)]
    pub fn buffer_sub_data(
        &mut self,
        target: u32,
        dst_offset: i64,
        data: View,
        offset: u32,
        length: u32,
    ) -> napi::Result<()> {
        let Some(w) = data.window(offset, length) else {
            self.past_end("bufferSubData");
            return Ok(());
        };
        self.gl()?.buffer_sub_data(target, dst_offset, w.bytes);
        Ok(())
    }

    /// `getBufferSubData(target, srcByteOffset, dstBuffer, dstOffset, length)`.
    #[napi(catch_unwind)]
    pub fn get_buffer_sub_data(
        &mut self,
        target: u32,
        src_offset: i64,
        mut dst: View,
        offset: u32,
        length: u32,
    ) -> napi::Result<()> {
        let Some(w) = dst.window_mut(offset, length) else {
            self.past_end("getBufferSubData");
            return Ok(());
        };
        if let Some(c) = self.ctx.as_mut() {
            c.get_buffer_sub_data(target, src_offset, w.bytes);
        }
        Ok(())
    }

    /// `copyBufferSubData`.
    #[napi(catch_unwind)]
    pub fn copy_buffer_sub_data(
        &mut self,
        read_target: u32,
        write_target: u32,
        read_offset: i64,
        write_offset: i64,
        size: i64,
    ) -> napi::Result<()> {
        self.gl()?
            .copy_buffer_sub_data(read_target, write_target, read_offset, write_offset, size);
        Ok(())
    }

    /// `getBufferParameter`.
    #[napi(catch_unwind)]
    pub fn get_buffer_parameter(&mut self, target: u32, pname: u32) -> napi::Result<Answer> {
        Ok(self.gl()?.get_buffer_parameter(target, pname).into())
    }

    /// `createVertexArray`.
    #[napi(catch_unwind)]
    pub fn create_vertex_array(&mut self) -> napi::Result<u32> {
        let v = self.gl()?.create_vertex_array();
        Ok(self.register(Handle::VertexArray(v)))
    }

    /// `isVertexArray`.
    #[napi(catch_unwind)]
    pub fn is_vertex_array(&mut self, vertex_array: u32) -> napi::Result<bool> {
        let v = self
            .arg::<VertexArray>(vertex_array, "isVertexArray")
            .flatten();
        Ok(v.is_some_and(|v| self.ctx.as_ref().is_some_and(|c| c.is_vertex_array(v))))
    }

    /// `deleteVertexArray`.
    #[napi(catch_unwind)]
    pub fn delete_vertex_array(&mut self, vertex_array: u32) -> napi::Result<()> {
        if let Some(v) = self
            .arg::<VertexArray>(vertex_array, "deleteVertexArray")
            .flatten()
        {
            self.gl()?.delete_vertex_array(v);
        }
        Ok(())
    }

    /// `bindVertexArray`.
    #[napi(catch_unwind)]
    pub fn bind_vertex_array(&mut self, vertex_array: u32) -> napi::Result<()> {
        if let Some(v) = self.arg(vertex_array, "bindVertexArray") {
            self.gl()?.bind_vertex_array(v);
        }
        Ok(())
    }

    /// `enableVertexAttribArray`.
    #[napi(catch_unwind)]
    pub fn enable_vertex_attrib_array(&mut self, index: u32) -> napi::Result<()> {
        self.gl()?.enable_vertex_attrib_array(index);
        Ok(())
    }

    /// `disableVertexAttribArray`.
    #[napi(catch_unwind)]
    pub fn disable_vertex_attrib_array(&mut self, index: u32) -> napi::Result<()> {
        self.gl()?.disable_vertex_attrib_array(index);
        Ok(())
    }

    /// `vertexAttribPointer`.
    #[napi(catch_unwind)]
    pub fn vertex_attrib_pointer(
        &mut self,
        index: u32,
        size: i32,
        ty: u32,
        normalized: bool,
        stride: i32,
        offset: i64,
    ) -> napi::Result<()> {
        self.gl()?
            .vertex_attrib_pointer(index, size, ty, normalized, stride, offset);
        Ok(())
    }

    /// `vertexAttribIPointer`.
    #[napi(js_name = "vertexAttribIPointer", catch_unwind)]
    pub fn vertex_attrib_i_pointer(
        &mut self,
        index: u32,
        size: i32,
        ty: u32,
        stride: i32,
        offset: i64,
    ) -> napi::Result<()> {
        self.gl()?
            .vertex_attrib_i_pointer(index, size, ty, stride, offset);
        Ok(())
    }

    /// `vertexAttribDivisor`.
    #[napi(catch_unwind)]
    pub fn vertex_attrib_divisor(&mut self, index: u32, divisor: u32) -> napi::Result<()> {
        self.gl()?.vertex_attrib_divisor(index, divisor);
        Ok(())
    }

    /// `vertexAttrib4f` (the 1f/2f/3f forms pass GL's defaults for the rest).
    #[napi(js_name = "vertexAttrib4f", catch_unwind)]
    pub fn vertex_attrib4f(
        &mut self,
        index: u32,
        x: f64,
        y: f64,
        z: f64,
        w: f64,
    ) -> napi::Result<()> {
        self.gl()?
            .vertex_attrib4f(index, x as f32, y as f32, z as f32, w as f32);
        Ok(())
    }

    /// `vertexAttrib[1234]fv`: `n` components from `values`.
    #[napi(js_name = "vertexAttribFv", catch_unwind)]
    pub fn vertex_attrib_fv(&mut self, n: u32, index: u32, values: &[f32]) -> napi::Result<()> {
        let c = self.gl()?;
        match n {
            1 => c.vertex_attrib1fv(index, values),
            2 => c.vertex_attrib2fv(index, values),
            3 => c.vertex_attrib3fv(index, values),
            _ => c.vertex_attrib4fv(index, values),
        }
        Ok(())
    }

    /// `vertexAttribI4i`.
    #[napi(js_name = "vertexAttribI4i", catch_unwind)]
    pub fn vertex_attrib_i4i(
        &mut self,
        index: u32,
        x: i32,
        y: i32,
        z: i32,
        w: i32,
    ) -> napi::Result<()> {
        self.gl()?.vertex_attrib_i4i(index, x, y, z, w);
        Ok(())
    }

    /// `vertexAttribI4ui`.
    #[napi(js_name = "vertexAttribI4ui", catch_unwind)]
    pub fn vertex_attrib_i4ui(
        &mut self,
        index: u32,
        x: u32,
        y: u32,
        z: u32,
        w: u32,
    ) -> napi::Result<()> {
        self.gl()?.vertex_attrib_i4ui(index, x, y, z, w);
        Ok(())
    }

    /// `vertexAttribI4iv`.
    #[napi(js_name = "vertexAttribI4iv", catch_unwind)]
    pub fn vertex_attrib_i4iv(&mut self, index: u32, values: &[i32]) -> napi::Result<()> {
        self.gl()?.vertex_attrib_i4iv(index, values);
        Ok(())
    }

    /// `vertexAttribI4uiv`.
    #[napi(js_name = "vertexAttribI4uiv", catch_unwind)]
    pub fn vertex_attrib_i4uiv(&mut self, index: u32, values: &[u32]) -> napi::Result<()> {
        self.gl()?.vertex_attrib_i4uiv(index, values);
        Ok(())
    }

    /// `getVertexAttrib`.
    #[napi(catch_unwind)]
    pub fn get_vertex_attrib(&mut self, index: u32, pname: u32) -> napi::Result<Answer> {
        Ok(self.gl()?.get_vertex_attrib(index, pname).into())
    }

    /// `getVertexAttribOffset`.
    #[napi(catch_unwind)]
    pub fn get_vertex_attrib_offset(&mut self, index: u32, pname: u32) -> napi::Result<f64> {
        Ok(self.gl()?.get_vertex_attrib_offset(index, pname) as f64)
    }

    /// `drawArrays`.
    #[napi(catch_unwind)]
    pub fn draw_arrays(&mut self, mode: u32, first: i32, count: i32) -> napi::Result<()> {
        self.gl()?.draw_arrays(mode, first, count);
        Ok(())
    }

    /// `drawArraysInstanced`.
    #[napi(catch_unwind)]
    pub fn draw_arrays_instanced(
        &mut self,
        mode: u32,
        first: i32,
        count: i32,
        instances: i32,
    ) -> napi::Result<()> {
        self.gl()?
            .draw_arrays_instanced(mode, first, count, instances);
        Ok(())
    }

    /// `drawElements`.
    #[napi(catch_unwind)]
    pub fn draw_elements(
        &mut self,
        mode: u32,
        count: i32,
        ty: u32,
        offset: i64,
    ) -> napi::Result<()> {
        self.gl()?.draw_elements(mode, count, ty, offset);
        Ok(())
    }

    /// `drawElementsInstanced`.
    #[napi(catch_unwind)]
    pub fn draw_elements_instanced(
        &mut self,
        mode: u32,
        count: i32,
        ty: u32,
        offset: i64,
        instances: i32,
    ) -> napi::Result<()> {
        self.gl()?
            .draw_elements_instanced(mode, count, ty, offset, instances);
        Ok(())
    }

    /// `drawRangeElements`.
    #[napi(catch_unwind)]
    pub fn draw_range_elements(
        &mut self,
        mode: u32,
        start: u32,
        end: u32,
        count: i32,
        ty: u32,
        offset: i64,
    ) -> napi::Result<()> {
        self.gl()?
            .draw_range_elements(mode, start, end, count, ty, offset);
        Ok(())
    }
}
