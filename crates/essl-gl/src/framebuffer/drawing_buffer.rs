//! The drawing buffer's calls: `present` (what returning to the browser does),
//! `drawing_buffer_storage`, and clearing it to its initial contents.

use super::DefaultFramebuffer;
use crate::context::Context;
use crate::frame::PassClears;
use crate::gl;

impl Context {
    /// What returning control to the browser does for a WebGL canvas: the drawing buffer is
    /// presented — here, only finished: the GPU executes everything recorded — and then
    /// cleared (colour 0, depth 1, stencil 0) unless `preserveDrawingBuffer`; the results of
    /// queries and the status of fences ended before it become available. An application
    /// calls it once a frame, where a browser would composite.
    pub fn present(&mut self) {
        self.finish();
        self.presents += 1;
        if self.fb.attributes.preserve_drawing_buffer {
            return;
        }
        self.clear_drawing_buffer();
    }

    /// Ends a frame of a canvas that is not shown (not in a document, an `OffscreenCanvas`):
    /// queries and fences ended before it become available, as with [`Context::present`],
    /// but nothing composites the drawing buffer, so it keeps its contents. Submits the
    /// recorded commands and waits for them.
    pub fn present_offscreen(&mut self) {
        self.finish();
        self.presents += 1;
    }

    /// Clears the drawing buffer to its initial contents: colour 0 (alpha 1 without an alpha
    /// channel, which then reads back as 1), depth 1, stencil 0.
    pub(crate) fn clear_drawing_buffer(&mut self) {
        let target = self.default_target_with(true);
        let alpha = if self.fb.attributes.alpha { 0.0 } else { 1.0 };
        let color = wgpu::Color {
            a: alpha,
            ..wgpu::Color::TRANSPARENT
        };
        let clears = PassClears {
            colors: vec![Some(color); target.colors.len()],
            depth: Some(1.0),
            stencil: Some(0),
        };
        self.frame.clear_pass(&self.gpu, &target, &clears);
        self.frame.end_pass();
    }
}

impl Context {
    /// Gives the drawing buffer new storage (`drawingBufferStorage`): `RGBA8`,
    /// `SRGB8_ALPHA8` or `RGBA16F` (`INVALID_ENUM` otherwise), `width` × `height` within
    /// `MAX_RENDERBUFFER_SIZE` (`INVALID_VALUE`). Its contents start cleared; the viewport is
    /// not changed.
    pub fn drawing_buffer_storage(&mut self, sized_format: u32, width: u32, height: u32) {
        self.drawing_buffer_storage_as(sized_format, width, height, "drawingBufferStorage");
    }

    /// Gives the drawing buffer new storage of `width` × `height` in its format, as setting
    /// a canvas's `width` or `height` does: its contents start cleared, the viewport is not
    /// changed. A size of 0 or past `MAX_RENDERBUFFER_SIZE` → `INVALID_VALUE`.
    pub fn resize_drawing_buffer(&mut self, width: u32, height: u32) {
        let format = self.fb.format.gl;
        self.drawing_buffer_storage_as(format, width, height, "resize");
    }

    fn drawing_buffer_storage_as(&mut self, sized_format: u32, width: u32, height: u32, f: &str) {
        if !matches!(sized_format, gl::RGBA8 | gl::SRGB8_ALPHA8 | gl::RGBA16F) {
            return self.error(
                gl::INVALID_ENUM,
                f,
                format_args!("format 0x{sized_format:04X}"),
            );
        }
        let max = self.gpu.limits.max_texture_dimension_2d;
        if width == 0 || height == 0 || width > max || height > max {
            return self.error(gl::INVALID_VALUE, f, "size out of range");
        }
        let format = crate::texture::internal_format(sized_format).expect("a supported format");
        self.frame.end_pass();
        let (attributes, draw, read) =
            (self.fb.attributes, self.fb.draw_buffer, self.fb.read_buffer);
        self.fb = DefaultFramebuffer::with_format(&self.gpu, [width, height], attributes, format);
        (self.fb.draw_buffer, self.fb.read_buffer) = (draw, read);
        if !attributes.alpha {
            self.clear_drawing_buffer();
        }
    }
}
