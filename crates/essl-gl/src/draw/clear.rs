//! `clear`, and the scissor rectangle that it and draws share.

use crate::context::Context;
use crate::gl;

impl Context {
    /// Clears buffers of the framebuffer (`clear`): `COLOR_BUFFER_BIT`, `DEPTH_BUFFER_BIT`,
    /// `STENCIL_BUFFER_BIT` (no stencil buffer: nothing to clear). The clear respects the
    /// colour mask, the depth mask and the scissor test, as in GL. Other bits →
    /// `INVALID_VALUE`.
    pub fn clear(&mut self, mask: u32) {
        if mask & !(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT) != 0 {
            return self.error(gl::INVALID_VALUE, "clear", format_args!("mask 0x{mask:X}"));
        }
        let s = &self.state;
        if s.rasterizer_discard {
            return;
        }
        let color = mask & gl::COLOR_BUFFER_BIT != 0 && s.color_mask.iter().any(|&m| m);
        let depth = mask & gl::DEPTH_BUFFER_BIT != 0 && s.depth_mask;
        if !color && !depth {
            return;
        }
        let Some(rect) = self.scissor_rect() else {
            return;
        };
        let full = rect == [0, 0, self.fb.width, self.fb.height];
        // The default framebuffer is 8-bit UNORM: give the GPU the centre of the byte GL's
        // round-to-nearest picks, so that the driver's own conversion cannot land elsewhere
        // (lavapipe's float-to-byte trick turns 0.3, i.e. 76.500003, into 76; GL and
        // Chromium give 77).
        let [r, g, b, a] = s
            .clear_color
            .map(|c| ((c.clamp(0.0, 1.0) as f64 * 255.0 + 0.5).floor() / 255.0) as f32);
        let clear_color = wgpu::Color {
            r: r as f64,
            g: g as f64,
            b: b as f64,
            a: a as f64,
        };
        if full && (!color || s.color_mask == [true; 4]) {
            self.frame
                .clear(color.then_some(clear_color), depth.then_some(s.clear_depth));
            return;
        }
        // Masked or scissored: draw a full-screen triangle with the clear pipeline.
        let mut write_mask = wgpu::ColorWrites::empty();
        if color {
            for (m, bit) in s.color_mask.iter().zip([
                wgpu::ColorWrites::RED,
                wgpu::ColorWrites::GREEN,
                wgpu::ColorWrites::BLUE,
                wgpu::ColorWrites::ALPHA,
            ]) {
                if *m {
                    write_mask |= bit;
                }
            }
        }
        let values = [r, g, b, a, s.clear_depth, 0.0, 0.0, 0.0];
        let pipeline = self
            .caches
            .pipelines
            .clear_pipeline(&self.gpu, write_mask, depth);
        let align = self.gpu.limits.min_uniform_buffer_offset_alignment as u64;
        let alloc = self
            .frame
            .arena
            .push(&self.gpu, bytemuck::cast_slice(&values), align);
        let group =
            self.caches
                .pipelines
                .group0(&self.gpu, Some((alloc.chunk, &alloc.buffer, 32)), &[]);
        let (w, h) = (self.fb.width as f32, self.fb.height as f32);
        self.frame.pass(&self.gpu, &self.fb);
        let frame = &mut self.frame;
        let pass = frame.pass.as_mut().expect("opened above");
        pass.set_pipeline(&pipeline);
        pass.set_viewport(0.0, 0.0, w, h, 0.0, 1.0);
        pass.set_scissor_rect(rect[0], rect[1], rect[2], rect[3]);
        pass.set_bind_group(0, &group, &[alloc.offset as u32]);
        pass.draw(0..3, 0..1);
        frame.pass_state.pipeline = None;
        frame.pass_state.viewport = None;
        frame.pass_state.scissor = None;
        frame.pass_state.group0 = None;
    }

    /// The scissor rectangle in wgpu's coordinates (GL's: rows are stored bottom first),
    /// clipped to the framebuffer; the whole framebuffer without `SCISSOR_TEST`; `None` when
    /// empty.
    pub(super) fn scissor_rect(&self) -> Option<[u32; 4]> {
        let (fw, fh) = (self.fb.width as i64, self.fb.height as i64);
        if !self.state.scissor_test {
            return Some([0, 0, fw as u32, fh as u32]);
        }
        let [x, y, w, h] = self.state.scissor.map(|v| v as i64);
        let x0 = x.clamp(0, fw);
        let x1 = (x + w).clamp(0, fw);
        let y0 = y.clamp(0, fh);
        let y1 = (y + h).clamp(0, fh);
        (x1 > x0 && y1 > y0).then(|| [x0 as u32, y0 as u32, (x1 - x0) as u32, (y1 - y0) as u32])
    }
}
