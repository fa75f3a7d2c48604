//! `clear` and `clear_buffer{fv,iv,uiv,fi}`, and the scissor rectangle that they and draws
//! share.
//!
//! A clear of whole attachments with nothing masked becomes the load operation of a new
//! render pass; a clear that the scissor box, the colour mask or the stencil write mask
//! restricts draws a rectangle with a pipeline that writes only what is cleared.

use crate::context::Context;
use crate::frame::{PassClears, PassTarget};
use crate::gl;
use crate::pipeline::{ClearKey, ClearKind};

/// A value `clearBuffer*` writes into a colour buffer, in the buffer's kind.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum ClearValue {
    Float([f32; 4]),
    Int([i32; 4]),
    Uint([u32; 4]),
}

impl ClearValue {
    fn kind(&self) -> ClearKind {
        match self {
            ClearValue::Float(_) => ClearKind::Float,
            ClearValue::Int(_) => ClearKind::Int,
            ClearValue::Uint(_) => ClearKind::Uint,
        }
    }

    /// The value as wgpu's load operation colour.
    fn color(&self) -> wgpu::Color {
        let [r, g, b, a] = match *self {
            ClearValue::Float(v) => v.map(|c| c as f64),
            ClearValue::Int(v) => v.map(|c| c as f64),
            ClearValue::Uint(v) => v.map(|c| c as f64),
        };
        wgpu::Color { r, g, b, a }
    }

    /// The 16 bytes of the value in the clear pipeline's uniform block.
    fn bytes(&self) -> [u8; 16] {
        let words: [u32; 4] = match *self {
            ClearValue::Float(v) => v.map(f32::to_bits),
            ClearValue::Int(v) => v.map(|c| c as u32),
            ClearValue::Uint(v) => v,
        };
        bytemuck::cast(words)
    }
}

/// What one clear writes: a value per draw buffer, depth, stencil.
#[derive(Clone, Debug, Default)]
pub(crate) struct ClearRequest {
    pub(crate) colors: Vec<Option<ClearValue>>,
    pub(crate) depth: Option<f32>,
    pub(crate) stencil: Option<u32>,
}

/// What sampling or rendering an attachment's format takes: float, signed or unsigned.
fn format_kind(format: wgpu::TextureFormat) -> ClearKind {
    match format.sample_type(None, None) {
        Some(wgpu::TextureSampleType::Sint) => ClearKind::Int,
        Some(wgpu::TextureSampleType::Uint) => ClearKind::Uint,
        _ => ClearKind::Float,
    }
}

impl Context {
    /// Clears buffers of the draw framebuffer (`clear`): `COLOR_BUFFER_BIT` (every draw
    /// buffer, with `clearColor`), `DEPTH_BUFFER_BIT`, `STENCIL_BUFFER_BIT`. The clear
    /// respects the colour mask, the depth mask, the stencil write mask and the scissor test,
    /// as in GL. Other bits → `INVALID_VALUE`; colour with an integer draw buffer →
    /// `INVALID_OPERATION` (WebGL2); an incomplete framebuffer →
    /// `INVALID_FRAMEBUFFER_OPERATION`.
    pub fn clear(&mut self, mask: u32) {
        const F: &str = "clear";
        if mask & !(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT) != 0 {
            return self.error(gl::INVALID_VALUE, F, format_args!("mask 0x{mask:X}"));
        }
        if !self.require_complete(true, F) {
            return;
        }
        let target = self.draw_target();
        let mut request = ClearRequest::default();
        if mask & gl::COLOR_BUFFER_BIT != 0 {
            let integer = target
                .colors
                .iter()
                .flatten()
                .any(|c| format_kind(c.format) != ClearKind::Float);
            if integer {
                return self.error(
                    gl::INVALID_OPERATION,
                    F,
                    "an integer draw buffer cannot be cleared with clear; use clearBuffer",
                );
            }
            let color = ClearValue::Float(self.state.clear_color);
            request.colors = target
                .colors
                .iter()
                .map(|c| c.as_ref().map(|_| color))
                .collect();
        }
        if mask & gl::DEPTH_BUFFER_BIT != 0 {
            request.depth = Some(self.state.clear_depth);
        }
        if mask & gl::STENCIL_BUFFER_BIT != 0 {
            request.stencil = Some(self.state.clear_stencil as u32);
        }
        self.clear_target(&target, request);
    }

    /// Clears draw buffer `drawbuffer` to a float value (`clearBufferfv(COLOR, …)`), or the
    /// depth buffer (`clearBufferfv(DEPTH, 0, [d])`).
    pub fn clear_bufferfv(&mut self, buffer: u32, drawbuffer: i32, values: &[f32]) {
        const F: &str = "clearBufferfv";
        match buffer {
            gl::COLOR => {
                let Some(v) = values.get(..4) else {
                    return self.error(gl::INVALID_VALUE, F, "4 values needed");
                };
                let v = [v[0], v[1], v[2], v[3]];
                self.clear_color_buffer(drawbuffer, ClearValue::Float(v), F);
            }
            gl::DEPTH => {
                let Some(&d) = values.first() else {
                    return self.error(gl::INVALID_VALUE, F, "1 value needed");
                };
                self.clear_depth_stencil(drawbuffer, Some(d), None, F);
            }
            _ => self.error(gl::INVALID_ENUM, F, format_args!("buffer 0x{buffer:04X}")),
        }
    }

    /// Clears draw buffer `drawbuffer` to a signed integer value (`clearBufferiv(COLOR, …)`),
    /// or the stencil buffer (`clearBufferiv(STENCIL, 0, [s])`).
    pub fn clear_bufferiv(&mut self, buffer: u32, drawbuffer: i32, values: &[i32]) {
        const F: &str = "clearBufferiv";
        match buffer {
            gl::COLOR => {
                let Some(v) = values.get(..4) else {
                    return self.error(gl::INVALID_VALUE, F, "4 values needed");
                };
                let v = [v[0], v[1], v[2], v[3]];
                self.clear_color_buffer(drawbuffer, ClearValue::Int(v), F);
            }
            gl::STENCIL => {
                let Some(&s) = values.first() else {
                    return self.error(gl::INVALID_VALUE, F, "1 value needed");
                };
                self.clear_depth_stencil(drawbuffer, None, Some(s as u32), F);
            }
            _ => self.error(gl::INVALID_ENUM, F, format_args!("buffer 0x{buffer:04X}")),
        }
    }

    /// Clears draw buffer `drawbuffer` to an unsigned integer value
    /// (`clearBufferuiv(COLOR, …)`).
    pub fn clear_bufferuiv(&mut self, buffer: u32, drawbuffer: i32, values: &[u32]) {
        const F: &str = "clearBufferuiv";
        if buffer != gl::COLOR {
            return self.error(gl::INVALID_ENUM, F, format_args!("buffer 0x{buffer:04X}"));
        }
        let Some(v) = values.get(..4) else {
            return self.error(gl::INVALID_VALUE, F, "4 values needed");
        };
        let v = [v[0], v[1], v[2], v[3]];
        self.clear_color_buffer(drawbuffer, ClearValue::Uint(v), F);
    }

    /// Clears depth and stencil together (`clearBufferfi(DEPTH_STENCIL, 0, depth, stencil)`).
    pub fn clear_bufferfi(&mut self, buffer: u32, drawbuffer: i32, depth: f32, stencil: i32) {
        const F: &str = "clearBufferfi";
        if buffer != gl::DEPTH_STENCIL {
            return self.error(gl::INVALID_ENUM, F, format_args!("buffer 0x{buffer:04X}"));
        }
        self.clear_depth_stencil(drawbuffer, Some(depth), Some(stencil as u32), F);
    }

    /// `clearBuffer*(COLOR, i, value)`: the value's kind must be the draw buffer's
    /// (`INVALID_OPERATION`); a draw buffer that is `NONE` is left alone.
    fn clear_color_buffer(&mut self, drawbuffer: i32, value: ClearValue, f: &str) {
        if drawbuffer < 0 || drawbuffer >= self.limits.max_color_attachments as i32 {
            return self.error(
                gl::INVALID_VALUE,
                f,
                format_args!("draw buffer {drawbuffer}"),
            );
        }
        if !self.require_complete(true, f) {
            return;
        }
        let target = self.draw_target();
        let i = drawbuffer as usize;
        let Some(Some(color)) = target.colors.get(i) else {
            return;
        };
        if format_kind(color.format) != value.kind() {
            return self.error(
                gl::INVALID_OPERATION,
                f,
                "the value's type does not match the draw buffer's format",
            );
        }
        let mut colors = vec![None; target.colors.len()];
        colors[i] = Some(value);
        let request = ClearRequest {
            colors,
            ..Default::default()
        };
        self.clear_target(&target, request);
    }

    /// `clearBuffer*(DEPTH | STENCIL | DEPTH_STENCIL, 0, …)`.
    fn clear_depth_stencil(
        &mut self,
        drawbuffer: i32,
        depth: Option<f32>,
        stencil: Option<u32>,
        f: &str,
    ) {
        if drawbuffer != 0 {
            return self.error(gl::INVALID_VALUE, f, "draw buffer must be 0");
        }
        if !self.require_complete(true, f) {
            return;
        }
        let target = self.draw_target();
        let request = ClearRequest {
            colors: Vec::new(),
            depth,
            stencil,
        };
        self.clear_target(&target, request);
    }

    /// Clears what `request` names in `target`, as masks and the scissor box allow.
    fn clear_target(&mut self, target: &PassTarget, mut request: ClearRequest) {
        let s = &self.state;
        if s.rasterizer_discard {
            return;
        }
        let masks: Vec<[bool; 4]> = (0..request.colors.len())
            .map(|i| s.draw_buffer(i).color_mask)
            .collect();
        let has_depth = target.depth.as_ref().is_some_and(|d| d.has_depth());
        let has_stencil = target.depth.as_ref().is_some_and(|d| d.has_stencil());
        if !s.depth_mask || !has_depth {
            request.depth = None;
        }
        let stencil_mask = s.stencil.writemask[0] & 0xFF;
        if stencil_mask == 0 || !has_stencil {
            request.stencil = None;
        }
        for (c, mask) in request.colors.iter_mut().zip(&masks) {
            if !mask.iter().any(|&m| m) {
                *c = None;
            }
        }
        let default_fb = self.bindings.framebuffers()[0].is_none();
        let no_alpha = default_fb && !self.fb.attributes.alpha;
        let rgb = self.rgb_draw_buffers();
        for (i, c) in request.colors.iter_mut().enumerate() {
            if let (Some(ClearValue::Float(v)), Some(Some(t))) = (c.as_mut(), target.colors.get(i))
            {
                if no_alpha || (i < 32 && rgb & (1 << i) != 0) {
                    v[3] = 1.0;
                }
                if t.format == wgpu::TextureFormat::Rgba8Unorm
                    || t.format == wgpu::TextureFormat::R8Unorm
                    || t.format == wgpu::TextureFormat::Rg8Unorm
                {
                    // Give the GPU the centre of the byte GL's round-to-nearest picks, so
                    // that the driver's own conversion cannot land elsewhere (lavapipe turns
                    // 0.3, i.e. 76.500003, into 76; GL and Chromium give 77).
                    *v = v
                        .map(|c| ((c.clamp(0.0, 1.0) as f64 * 255.0 + 0.5).floor() / 255.0) as f32);
                }
            }
        }
        let nothing = request.colors.iter().all(|c| c.is_none())
            && request.depth.is_none()
            && request.stencil.is_none();
        let Some(rect) = self.scissor_rect_for(target.size) else {
            return;
        };
        if nothing {
            return;
        }
        let full = rect == [0, 0, target.size[0], target.size[1]];
        let unmasked_color = request
            .colors
            .iter()
            .zip(&masks)
            .all(|(c, mask)| c.is_none() || (*mask == [true; 4] && !no_alpha));
        let unmasked_stencil = request.stencil.is_none() || stencil_mask == 0xFF;
        if full && unmasked_color && unmasked_stencil {
            let clears = PassClears {
                colors: request
                    .colors
                    .iter()
                    .map(|c| c.map(|v| v.color()))
                    .collect(),
                depth: request.depth,
                stencil: request.stencil,
            };
            self.frame.clear_pass(&self.gpu, target, &clears);
            return;
        }
        self.clear_with_quad(target, &request, rect, stencil_mask);
    }

    /// A masked or scissored clear: a rectangle drawn with a pipeline that writes the clear
    /// values.
    fn clear_with_quad(
        &mut self,
        target: &PassTarget,
        request: &ClearRequest,
        rect: [u32; 4],
        stencil_mask: u32,
    ) {
        let key = ClearKey {
            colors: target
                .colors
                .iter()
                .enumerate()
                .map(|(i, c)| {
                    let cleared = request.colors.get(i).copied().flatten();
                    c.as_ref().map(|c| {
                        (
                            c.format,
                            cleared.map(|v| v.kind()),
                            if cleared.is_some() {
                                self.draw_write_mask(i)
                            } else {
                                wgpu::ColorWrites::empty()
                            },
                        )
                    })
                })
                .collect(),
            depth: target.depth.as_ref().map(|d| d.format),
            write_depth: request.depth.is_some(),
            stencil_mask: request.stencil.map_or(0, |_| stencil_mask),
            samples: target.samples,
        };
        let mut values = vec![0u8; 16 * (1 + crate::MAX_COLOR_ATTACHMENTS as usize)];
        values[..4].copy_from_slice(&request.depth.unwrap_or(0.0).to_ne_bytes());
        for (i, c) in request.colors.iter().enumerate() {
            if let Some(v) = c {
                values[16 * (i + 1)..16 * (i + 2)].copy_from_slice(&v.bytes());
            }
        }
        let pipeline = self.caches.pipelines.clear_pipeline(&self.gpu, &key);
        let align = self.gpu.limits.min_uniform_buffer_offset_alignment as u64;
        let alloc = self.frame.arena.push(&self.gpu, &values, align);
        let size = values.len() as u64;
        let group =
            self.caches
                .pipelines
                .group0(&self.gpu, Some((alloc.chunk, &alloc.buffer, size)), &[]);
        let pass = self.frame.internal_pass(&self.gpu, target);
        pass.set_pipeline(&pipeline);
        // The triangle covers the viewport: make that the rectangle, not only the scissor
        // box. lavapipe (Mesa 22.3) lets a multisampled draw cover the samples of the pixels
        // left of and below a scissor box that does not start at 0; the geometry itself ends
        // on the box's edges.
        let [x, y, w, h] = rect.map(|v| v as f32);
        pass.set_viewport(x, y, w, h, 0.0, 1.0);
        pass.set_scissor_rect(rect[0], rect[1], rect[2], rect[3]);
        pass.set_bind_group(0, &group, &[alloc.offset as u32]);
        if let Some(s) = request.stencil {
            pass.set_stencil_reference(s);
        }
        pass.draw(0..3, 0..1);
    }

    /// The scissor rectangle in wgpu's coordinates (GL's: rows are stored bottom first),
    /// clipped to a target of `size`; the whole target without `SCISSOR_TEST`; `None` when
    /// empty.
    pub(crate) fn scissor_rect_for(&self, size: [u32; 2]) -> Option<[u32; 4]> {
        let (fw, fh) = (size[0] as i64, size[1] as i64);
        if fw == 0 || fh == 0 {
            return None;
        }
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
