//! Drawing: `clear`, `draw_arrays`, `draw_elements` and their instanced forms.
//!
//! A draw first checks WebGL's rules (and records the error without drawing when one is
//! broken), then brings the buffers and textures it uses up to date on the GPU, fetches or
//! builds the pipeline for the program, vertex layout and state, fills the uniform block and
//! records the draw into the open render pass.

use essl::program::InternalUniform;
use essl::types::{SamplerDim, ScalarKind, Type};

use crate::buffer::DerivedKey;
use crate::context::Context;
use crate::gl;
use crate::objects::Id;
use crate::pipeline::{PipelineKey, SlotBinding, VertexSlot};
use crate::program::ValueKind;
use crate::shader_patch::{InputPatch, Norm32};
use crate::texture::{compare_function, view_dimension, Complete, SampleKind, SamplerKey};
use crate::vertex_array::{GenericAttrib, VertexAttrib};

/// A topology wgpu lacks, drawn as another one with generated indices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Emulated {
    None,
    /// `LINE_LOOP` as a line strip that returns to its first vertex.
    LineLoop,
    /// `TRIANGLE_FAN` as a triangle list.
    TriangleFan,
    /// A list (of primitives of this many vertices) whose indices hold the restart index:
    /// Vulkan restarts only strips, so the restarts are applied to the indices, dropping
    /// incomplete primitives as GL does.
    List(usize),
}

/// How a vertex format feeds an attribute.
#[derive(Clone, Copy, Debug)]
struct Feed {
    format: wgpu::VertexFormat,
    kind: ValueKind,
    count: u8,
    used: u8,
    norm: Option<Norm32>,
}

/// The wgpu vertex format for an attribute array, and what the shader must still do.
fn feed_for(a: &VertexAttrib) -> Feed {
    use wgpu::VertexFormat as V;
    let n = a.size;
    // wgpu has no 3-component 8/16-bit formats: those are read as 4 components.
    let pick = |one: V, two: V, four: V| match n {
        1 => (one, 1),
        2 => (two, 2),
        _ => (four, 4),
    };
    let (format, count, kind, norm) = match (a.ty, a.normalized && !a.integer) {
        (gl::FLOAT, _) => {
            let f = [V::Float32, V::Float32x2, V::Float32x3, V::Float32x4][n as usize - 1];
            (f, n, ValueKind::Float, None)
        }
        (gl::HALF_FLOAT, _) => {
            let (f, c) = pick(V::Float16, V::Float16x2, V::Float16x4);
            (f, c, ValueKind::Float, None)
        }
        (gl::BYTE, true) => {
            let (f, c) = pick(V::Snorm8, V::Snorm8x2, V::Snorm8x4);
            (f, c, ValueKind::Float, None)
        }
        (gl::UNSIGNED_BYTE, true) => {
            let (f, c) = pick(V::Unorm8, V::Unorm8x2, V::Unorm8x4);
            (f, c, ValueKind::Float, None)
        }
        (gl::SHORT, true) => {
            let (f, c) = pick(V::Snorm16, V::Snorm16x2, V::Snorm16x4);
            (f, c, ValueKind::Float, None)
        }
        (gl::UNSIGNED_SHORT, true) => {
            let (f, c) = pick(V::Unorm16, V::Unorm16x2, V::Unorm16x4);
            (f, c, ValueKind::Float, None)
        }
        (gl::BYTE, false) => {
            let (f, c) = pick(V::Sint8, V::Sint8x2, V::Sint8x4);
            (f, c, ValueKind::Sint, None)
        }
        (gl::UNSIGNED_BYTE, false) => {
            let (f, c) = pick(V::Uint8, V::Uint8x2, V::Uint8x4);
            (f, c, ValueKind::Uint, None)
        }
        (gl::SHORT, false) => {
            let (f, c) = pick(V::Sint16, V::Sint16x2, V::Sint16x4);
            (f, c, ValueKind::Sint, None)
        }
        (gl::UNSIGNED_SHORT, false) => {
            let (f, c) = pick(V::Uint16, V::Uint16x2, V::Uint16x4);
            (f, c, ValueKind::Uint, None)
        }
        (gl::INT, norm) => {
            let f = [V::Sint32, V::Sint32x2, V::Sint32x3, V::Sint32x4][n as usize - 1];
            (f, n, ValueKind::Sint, norm.then_some(Norm32::Signed))
        }
        (_, norm) => {
            let f = [V::Uint32, V::Uint32x2, V::Uint32x3, V::Uint32x4][n as usize - 1];
            (f, n, ValueKind::Uint, norm.then_some(Norm32::Unsigned))
        }
    };
    Feed {
        format,
        kind,
        count,
        used: n.min(count),
        norm,
    }
}

/// Where one shader input's values come from.
enum Source {
    /// An enabled array.
    Array {
        buffer: Id,
        attrib: VertexAttrib,
        feed: Feed,
    },
    /// The generic value of a disabled array.
    Constant(GenericAttrib),
}

/// What a sampler slot reads.
struct SlotPlan {
    texture: Option<(Id, Complete)>,
    dim: wgpu::TextureViewDimension,
    kind: SampleKind,
}

/// Indices to draw with.
enum Indices {
    /// `draw_arrays`: vertices `first..first + count`.
    None { first: u32 },
    /// `draw_elements`: the element buffer.
    Elements { buffer: Id, ty: u32, offset: u64 },
}

fn index_size(ty: u32) -> Option<u64> {
    match ty {
        gl::UNSIGNED_BYTE => Some(1),
        gl::UNSIGNED_SHORT => Some(2),
        gl::UNSIGNED_INT => Some(4),
        _ => None,
    }
}

/// Index `i` of `count` indices of type `ty` at `offset`, as `u32` (`u32::MAX` for the
/// primitive restart index, which WebGL2 always enables).
fn read_indices(data: &[u8], ty: u32, offset: u64, count: u64) -> impl Iterator<Item = u32> + '_ {
    let size = index_size(ty).unwrap_or(4) as usize;
    let start = offset as usize;
    data[start..start + count as usize * size]
        .chunks_exact(size)
        .map(move |c| match size {
            1 => {
                if c[0] == 0xFF {
                    u32::MAX
                } else {
                    c[0] as u32
                }
            }
            2 => {
                let v = u16::from_ne_bytes([c[0], c[1]]);
                if v == 0xFFFF {
                    u32::MAX
                } else {
                    v as u32
                }
            }
            _ => u32::from_ne_bytes([c[0], c[1], c[2], c[3]]),
        })
}

/// Generated indices for an emulated topology over `indices` (restart splits primitives).
fn emulate(indices: impl Iterator<Item = u32>, how: Emulated) -> Vec<u32> {
    let mut out = Vec::new();
    let mut segment: Vec<u32> = Vec::new();
    let flush = |segment: &mut Vec<u32>, out: &mut Vec<u32>| {
        match how {
            Emulated::LineLoop if segment.len() >= 2 => {
                if !out.is_empty() {
                    out.push(u32::MAX);
                }
                out.extend_from_slice(segment);
                out.push(segment[0]);
            }
            Emulated::List(n) => {
                let keep = segment.len() / n * n;
                out.extend_from_slice(&segment[..keep]);
            }
            Emulated::TriangleFan if segment.len() >= 3 => {
                for i in 1..segment.len() - 1 {
                    out.extend_from_slice(&[segment[0], segment[i], segment[i + 1]]);
                }
            }
            _ => {}
        }
        segment.clear();
    };
    for i in indices {
        if i == u32::MAX {
            flush(&mut segment, &mut out);
        } else {
            segment.push(i);
        }
    }
    flush(&mut segment, &mut out);
    out
}

fn sampler_type(ty: essl::types::GlType) -> Option<essl::types::SamplerType> {
    match ty.to_type() {
        Type::Sampler(s) => Some(s),
        _ => None,
    }
}

fn dim_target(dim: SamplerDim) -> u32 {
    match dim {
        SamplerDim::D2 => gl::TEXTURE_2D,
        SamplerDim::D3 => gl::TEXTURE_3D,
        SamplerDim::Cube => gl::TEXTURE_CUBE_MAP,
        SamplerDim::D2Array => gl::TEXTURE_2D_ARRAY,
    }
}

fn blend_factor(f: u32) -> wgpu::BlendFactor {
    use wgpu::BlendFactor as B;
    match f {
        gl::ZERO => B::Zero,
        gl::ONE => B::One,
        gl::SRC_COLOR => B::Src,
        gl::ONE_MINUS_SRC_COLOR => B::OneMinusSrc,
        gl::DST_COLOR => B::Dst,
        gl::ONE_MINUS_DST_COLOR => B::OneMinusDst,
        gl::SRC_ALPHA => B::SrcAlpha,
        gl::ONE_MINUS_SRC_ALPHA => B::OneMinusSrcAlpha,
        gl::DST_ALPHA => B::DstAlpha,
        gl::ONE_MINUS_DST_ALPHA => B::OneMinusDstAlpha,
        gl::CONSTANT_COLOR | gl::CONSTANT_ALPHA => B::Constant,
        gl::ONE_MINUS_CONSTANT_COLOR | gl::ONE_MINUS_CONSTANT_ALPHA => B::OneMinusConstant,
        _ => B::SrcAlphaSaturated,
    }
}

fn blend_component(src: u32, dst: u32, eq: u32) -> wgpu::BlendComponent {
    let operation = match eq {
        gl::FUNC_SUBTRACT => wgpu::BlendOperation::Subtract,
        gl::FUNC_REVERSE_SUBTRACT => wgpu::BlendOperation::ReverseSubtract,
        gl::MIN => wgpu::BlendOperation::Min,
        gl::MAX => wgpu::BlendOperation::Max,
        _ => wgpu::BlendOperation::Add,
    };
    // GL ignores the factors of MIN and MAX; wgpu requires them to be One.
    if matches!(eq, gl::MIN | gl::MAX) {
        return wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::One,
            operation,
        };
    }
    wgpu::BlendComponent {
        src_factor: blend_factor(src),
        dst_factor: blend_factor(dst),
        operation,
    }
}

/// Re-packs one attribute's elements at a stride wgpu accepts.
fn repack(data: &[u8], key: &DerivedKey) -> Vec<u8> {
    let DerivedKey::Repacked {
        offset,
        stride,
        element,
        packed,
        per_instance,
    } = *key
    else {
        return Vec::new();
    };
    let (offset, stride, element, packed) = (
        offset as usize,
        stride as usize,
        element as usize,
        packed as usize,
    );
    let available = if data.len() >= offset + element {
        (data.len() - offset - element) / stride + 1
    } else {
        0
    };
    let (count, source): (usize, Box<dyn Fn(usize) -> usize>) = match per_instance {
        Some((divisor, instances)) => (instances as usize, Box::new(move |i| i / divisor as usize)),
        None => (available, Box::new(|i| i)),
    };
    let mut out = vec![0u8; count * packed];
    for i in 0..count {
        let s = source(i);
        if s < available {
            let at = offset + s * stride;
            out[i * packed..i * packed + element].copy_from_slice(&data[at..at + element]);
        }
    }
    out
}

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
        let pipeline = self.pipelines.clear_pipeline(&self.gpu, write_mask, depth);
        let align = self.gpu.limits.min_uniform_buffer_offset_alignment as u64;
        let alloc = self
            .frame
            .arena
            .push(&self.gpu, bytemuck::cast_slice(&values), align);
        let group = self
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

    /// The scissor rectangle in wgpu's coordinates (origin top-left), clipped to the
    /// framebuffer; the whole framebuffer without `SCISSOR_TEST`; `None` when empty.
    fn scissor_rect(&self) -> Option<[u32; 4]> {
        let (fw, fh) = (self.fb.width as i64, self.fb.height as i64);
        if !self.state.scissor_test {
            return Some([0, 0, fw as u32, fh as u32]);
        }
        let [x, y, w, h] = self.state.scissor.map(|v| v as i64);
        let x0 = x.clamp(0, fw);
        let x1 = (x + w).clamp(0, fw);
        let top = (fh - (y + h)).clamp(0, fh);
        let bottom = (fh - y).clamp(0, fh);
        (x1 > x0 && bottom > top).then(|| {
            [
                x0 as u32,
                top as u32,
                (x1 - x0) as u32,
                (bottom - top) as u32,
            ]
        })
    }

    /// Draws `count` vertices from `first` (`drawArrays`).
    pub fn draw_arrays(&mut self, mode: u32, first: i32, count: i32) {
        self.draw(mode, first, count, None, 1, "drawArrays");
    }

    /// Draws `instance_count` instances of `count` vertices from `first`
    /// (`drawArraysInstanced`).
    pub fn draw_arrays_instanced(
        &mut self,
        mode: u32,
        first: i32,
        count: i32,
        instance_count: i32,
    ) {
        self.draw(
            mode,
            first,
            count,
            None,
            instance_count,
            "drawArraysInstanced",
        );
    }

    /// Draws `count` indices of type `ty` (`UNSIGNED_BYTE`, `UNSIGNED_SHORT`,
    /// `UNSIGNED_INT`) read from byte `offset` of the element array buffer (`drawElements`).
    /// The fixed primitive restart index (all ones) is always enabled, as in WebGL2.
    pub fn draw_elements(&mut self, mode: u32, count: i32, ty: u32, offset: i64) {
        self.draw(mode, 0, count, Some((ty, offset)), 1, "drawElements");
    }

    /// Draws `instance_count` instances of indexed geometry (`drawElementsInstanced`).
    pub fn draw_elements_instanced(
        &mut self,
        mode: u32,
        count: i32,
        ty: u32,
        offset: i64,
        instance_count: i32,
    ) {
        self.draw(
            mode,
            0,
            count,
            Some((ty, offset)),
            instance_count,
            "drawElementsInstanced",
        );
    }

    /// [`Context::draw_elements`] with a promise that the indices lie in `start..=end`
    /// (`drawRangeElements`); `end < start` → `INVALID_VALUE`.
    pub fn draw_range_elements(
        &mut self,
        mode: u32,
        start: u32,
        end: u32,
        count: i32,
        ty: u32,
        offset: i64,
    ) {
        if end < start {
            return self.error(gl::INVALID_VALUE, "drawRangeElements", "end < start");
        }
        self.draw(mode, 0, count, Some((ty, offset)), 1, "drawRangeElements");
    }

    #[allow(clippy::too_many_lines)]
    fn draw(
        &mut self,
        mode: u32,
        first: i32,
        count: i32,
        elements: Option<(u32, i64)>,
        instances: i32,
        f: &'static str,
    ) {
        use wgpu::PrimitiveTopology as T;
        // WebGL's checks, in the order browsers make them.
        let (topology, mut emulated) = match mode {
            gl::POINTS => (T::PointList, Emulated::None),
            gl::LINES => (T::LineList, Emulated::None),
            gl::LINE_STRIP => (T::LineStrip, Emulated::None),
            gl::LINE_LOOP => (T::LineStrip, Emulated::LineLoop),
            gl::TRIANGLES => (T::TriangleList, Emulated::None),
            gl::TRIANGLE_STRIP => (T::TriangleStrip, Emulated::None),
            gl::TRIANGLE_FAN => (T::TriangleList, Emulated::TriangleFan),
            _ => return self.error(gl::INVALID_ENUM, f, format_args!("mode 0x{mode:04X}")),
        };
        if first < 0 || count < 0 || instances < 0 {
            return self.error(
                gl::INVALID_VALUE,
                f,
                "negative first, count or instance count",
            );
        }
        let mut index_info = None;
        if let Some((ty, offset)) = elements {
            let Some(size) = index_size(ty) else {
                return self.error(gl::INVALID_ENUM, f, format_args!("index type 0x{ty:04X}"));
            };
            if offset < 0 {
                return self.error(gl::INVALID_VALUE, f, "negative offset");
            }
            if offset as u64 % size != 0 {
                return self.error(
                    gl::INVALID_OPERATION,
                    f,
                    "offset is not a multiple of the index size",
                );
            }
            index_info = Some((ty, offset as u64, size));
        }
        let Some(pid) = self.current_program else {
            return self.error(gl::INVALID_OPERATION, f, "no program in use");
        };
        let indices = match index_info {
            None => Indices::None {
                first: first as u32,
            },
            Some((ty, offset, _)) => match self.vao().element_buffer {
                Some(buffer) => Indices::Elements { buffer, ty, offset },
                None => {
                    return self.error(gl::INVALID_OPERATION, f, "no ELEMENT_ARRAY_BUFFER bound")
                }
            },
        };
        if let Some(i) = self
            .vao()
            .attribs
            .iter()
            .position(|a| a.enabled && a.buffer.is_none())
        {
            return self.error(
                gl::INVALID_OPERATION,
                f,
                format_args!("attribute {i} is enabled but has no buffer"),
            );
        }
        let linked = self
            .programs
            .get_any(pid)
            .and_then(|p| p.linked.as_ref())
            .expect("current programs are linked");
        // Uniform blocks read the buffer ranges bound to their binding points.
        let mut blocks = Vec::new();
        for (i, block) in linked.layout.blocks.iter().enumerate() {
            let point = linked.block_bindings[i] as usize;
            let Some((buffer, offset, size)) = self.uniform_bindings.get(point).copied().flatten()
            else {
                let msg = format!(
                    "uniform block {} has no buffer at binding point {point}",
                    block.name
                );
                return self.error(gl::INVALID_OPERATION, f, msg);
            };
            let len = self
                .buffers
                .get_any(buffer)
                .map_or(0, |b| b.data.len() as u64);
            let size = size.unwrap_or(len.saturating_sub(offset));
            if offset + size > len || size < block.size as u64 {
                let msg = format!(
                    "the buffer range of uniform block {} is too small",
                    block.name
                );
                return self.error(gl::INVALID_OPERATION, f, msg);
            }
            blocks.push((buffer, offset, size));
        }
        // Vertex inputs: types must match the arrays or generic values (WebGL2).
        let mut sources = Vec::new();
        for input in &linked.inputs {
            let a = &self.vao().attribs[input.location as usize];
            let source = if a.enabled {
                let feed = feed_for(a);
                let ok = if a.integer {
                    feed.kind == input.kind
                } else {
                    input.kind == ValueKind::Float
                };
                if !ok {
                    let msg = format!(
                        "attribute {} is fed a type that does not match the shader's",
                        input.location
                    );
                    return self.error(gl::INVALID_OPERATION, f, msg);
                }
                Source::Array {
                    buffer: a.buffer.expect("checked above"),
                    attrib: a.clone(),
                    feed,
                }
            } else {
                let g = self.generic_attribs[input.location as usize];
                let kind = match g {
                    GenericAttrib::Float(_) => ValueKind::Float,
                    GenericAttrib::Int(_) => ValueKind::Sint,
                    GenericAttrib::Uint(_) => ValueKind::Uint,
                };
                if kind != input.kind {
                    let msg = format!(
                        "generic value of attribute {} does not match the shader's type",
                        input.location
                    );
                    return self.error(gl::INVALID_OPERATION, f, msg);
                }
                Source::Constant(g)
            };
            sources.push((*input, source));
        }
        // Samplers: one unit may not serve two sampler types; textures must match the kind.
        let mut slot_plans = Vec::new();
        let mut unit_targets: Vec<(u32, u32)> = Vec::new();
        for (s, slot) in linked.layout.samplers.iter().enumerate() {
            let Some(st) = sampler_type(slot.ty) else {
                return self.error(
                    gl::INVALID_OPERATION,
                    f,
                    "sampler slot of a non-sampler type",
                );
            };
            let unit = linked.sampler_units[s];
            let target = dim_target(st.dim);
            if unit_targets.iter().any(|&(u, t)| u == unit && t != target) {
                return self.error(
                    gl::INVALID_OPERATION,
                    f,
                    format_args!("texture unit {unit} used by samplers of two types"),
                );
            }
            unit_targets.push((unit, target));
            let kind = match (st.shadow || slot.comparison, st.kind) {
                (true, _) => SampleKind::Depth,
                (false, ScalarKind::Int) => SampleKind::Sint,
                (false, ScalarKind::Uint) => SampleKind::Uint,
                _ => SampleKind::Float,
            };
            let texture = self.texture_units[unit as usize]
                .get(target)
                .and_then(|id| {
                    self.textures
                        .get_any(id)
                        .and_then(|t| t.completeness())
                        .map(|c| (id, c))
                });
            if let Some((_, c)) = &texture {
                if c.format.kind() != kind {
                    let msg = format!("texture on unit {unit} does not match its sampler's type");
                    return self.error(gl::INVALID_OPERATION, f, msg);
                }
            }
            slot_plans.push(SlotPlan {
                texture,
                dim: view_dimension(target),
                kind,
            });
        }
        if let Some((kind, _)) = linked.output0 {
            if kind != ValueKind::Float {
                return self.error(
                    gl::INVALID_OPERATION,
                    f,
                    "integer fragment output to a normalized framebuffer",
                );
            }
        }
        if count == 0 || instances == 0 {
            return;
        }

        // Index range, and the largest vertex the draw reads.
        let max_vertex: Option<u64> = match &indices {
            Indices::None { first } => Some(*first as u64 + count as u64 - 1),
            Indices::Elements { buffer, ty, offset } => {
                let size = index_size(*ty).expect("checked");
                let b = self
                    .buffers
                    .get_any_mut(*buffer)
                    .expect("bound buffers are alive");
                if offset + count as u64 * size > b.data.len() as u64 {
                    return self.error(
                        gl::INVALID_OPERATION,
                        f,
                        "indices past the end of the element buffer",
                    );
                }
                let key = (*ty, *offset, count as u64, b.version);
                let (max, restarts) = match b.max_index_cache {
                    Some((k, m, r)) if k == key => (m, r),
                    _ => {
                        let (mut max, mut restarts) = (None, false);
                        for i in read_indices(&b.data, *ty, *offset, count as u64) {
                            if i == u32::MAX {
                                restarts = true;
                            } else {
                                max = max.max(Some(i));
                            }
                        }
                        b.max_index_cache = Some((key, max, restarts));
                        (max, restarts)
                    }
                };
                if restarts && emulated == Emulated::None {
                    match mode {
                        gl::POINTS => emulated = Emulated::List(1),
                        gl::LINES => emulated = Emulated::List(2),
                        gl::TRIANGLES => emulated = Emulated::List(3),
                        _ => {}
                    }
                }
                max.map(u64::from)
            }
        };
        for (input, source) in &sources {
            let Source::Array {
                buffer, attrib: a, ..
            } = source
            else {
                continue;
            };
            let last = if a.divisor == 0 {
                max_vertex
            } else {
                Some((instances as u64 - 1) / a.divisor as u64)
            };
            let Some(last) = last else { continue };
            let len = self
                .buffers
                .get_any(*buffer)
                .expect("attached buffers are alive")
                .data
                .len() as u64;
            if a.offset + last * a.effective_stride() + a.element_size() > len {
                let msg = format!(
                    "attribute {} reads past the end of its buffer",
                    input.location
                );
                return self.error(gl::INVALID_OPERATION, f, msg);
            }
        }

        // Draws that GL would rasterize to nothing.
        let s = &self.state;
        let triangles = matches!(mode, gl::TRIANGLES | gl::TRIANGLE_STRIP | gl::TRIANGLE_FAN);
        if s.rasterizer_discard
            || (s.cull_face && s.cull_face_mode == gl::FRONT_AND_BACK && triangles)
            || s.viewport[2] == 0
            || s.viewport[3] == 0
        {
            return;
        }
        let Some(scissor) = self.scissor_rect() else {
            return;
        };
        // The debug mode: one test when it is off (the checks and their bookkeeping live
        // behind it).
        if self.validation.enabled {
            self.validate_uniforms(pid, f);
        }
        self.encode_draw(
            pid,
            topology,
            emulated,
            triangles,
            indices,
            count as u32,
            instances as u32,
            sources,
            slot_plans,
            blocks,
            scissor,
        );
    }

    #[allow(clippy::too_many_arguments)]
    fn encode_draw(
        &mut self,
        pid: Id,
        topology: wgpu::PrimitiveTopology,
        emulated: Emulated,
        triangles: bool,
        indices: Indices,
        count: u32,
        instances: u32,
        sources: Vec<(crate::program::ShaderInput, Source)>,
        slot_plans: Vec<SlotPlan>,
        blocks: Vec<(Id, u64, u64)>,
        scissor: [u32; 4],
    ) {
        let serial = self.frame.serial;
        let gpu = &self.gpu;

        // Vertex buffers.
        let mut slots = Vec::new();
        let mut patches = Vec::new();
        let mut bindings: Vec<(wgpu::Buffer, u64)> = Vec::new();
        for (input, source) in &sources {
            match source {
                Source::Array {
                    buffer,
                    attrib: a,
                    feed,
                } => {
                    let b = self
                        .buffers
                        .get_any_mut(*buffer)
                        .expect("attached buffers are alive");
                    let stride = a.effective_stride();
                    let fmt_size = feed.format.size();
                    let rel = a.offset & 3;
                    let direct = stride % 4 == 0
                        && rel % fmt_size.min(4) == 0
                        && rel + fmt_size <= stride
                        && a.divisor <= 1;
                    let step = if a.divisor == 0 {
                        wgpu::VertexStepMode::Vertex
                    } else {
                        wgpu::VertexStepMode::Instance
                    };
                    if direct {
                        bindings.push((b.gpu_buffer(gpu, serial), a.offset - rel));
                        slots.push(VertexSlot {
                            stride,
                            step,
                            format: feed.format,
                            offset: rel,
                            location: input.location,
                        });
                    } else {
                        let packed = fmt_size.div_ceil(4) * 4;
                        let key = DerivedKey::Repacked {
                            offset: a.offset,
                            stride,
                            element: a.element_size(),
                            packed,
                            per_instance: (a.divisor > 1).then_some((a.divisor, instances)),
                        };
                        let buffer = b.derived(gpu, key.clone(), |data| repack(data, &key));
                        bindings.push((buffer, 0));
                        slots.push(VertexSlot {
                            stride: packed,
                            step,
                            format: feed.format,
                            offset: 0,
                            location: input.location,
                        });
                    }
                    let needs_patch = feed.kind != input.kind
                        || feed.count > input.components
                        || feed.used < feed.count
                        || feed.norm.is_some();
                    if needs_patch {
                        patches.push(InputPatch {
                            location: input.location,
                            fed_kind: feed.kind,
                            fed_count: feed.count,
                            used: feed.used,
                            norm: feed.norm,
                        });
                    }
                }
                Source::Constant(g) => {
                    let n = input.components as usize;
                    let (bytes, formats): (Vec<u8>, [wgpu::VertexFormat; 4]) = match g {
                        GenericAttrib::Float(v) => (
                            bytemuck::cast_slice(&v[..n]).to_vec(),
                            [
                                wgpu::VertexFormat::Float32,
                                wgpu::VertexFormat::Float32x2,
                                wgpu::VertexFormat::Float32x3,
                                wgpu::VertexFormat::Float32x4,
                            ],
                        ),
                        GenericAttrib::Int(v) => (
                            bytemuck::cast_slice(&v[..n]).to_vec(),
                            [
                                wgpu::VertexFormat::Sint32,
                                wgpu::VertexFormat::Sint32x2,
                                wgpu::VertexFormat::Sint32x3,
                                wgpu::VertexFormat::Sint32x4,
                            ],
                        ),
                        GenericAttrib::Uint(v) => (
                            bytemuck::cast_slice(&v[..n]).to_vec(),
                            [
                                wgpu::VertexFormat::Uint32,
                                wgpu::VertexFormat::Uint32x2,
                                wgpu::VertexFormat::Uint32x3,
                                wgpu::VertexFormat::Uint32x4,
                            ],
                        ),
                    };
                    let alloc = self.frame.arena.push(gpu, &bytes, 4);
                    bindings.push((alloc.buffer, alloc.offset));
                    // Stride 0: every vertex reads the same value.
                    slots.push(VertexSlot {
                        stride: 0,
                        step: wgpu::VertexStepMode::Vertex,
                        format: formats[n - 1],
                        offset: 0,
                        location: input.location,
                    });
                }
            }
        }

        // Index buffer.
        let mut index: Option<(wgpu::Buffer, u64, wgpu::IndexFormat, std::ops::Range<u32>)> = None;
        let mut vertices = 0..count;
        match (&indices, emulated) {
            (Indices::None { first }, Emulated::None) => vertices = *first..*first + count,
            (Indices::None { first }, how) => {
                let generated = emulate(*first..*first + count, how);
                if generated.is_empty() {
                    return;
                }
                let alloc = self
                    .frame
                    .arena
                    .push(gpu, bytemuck::cast_slice(&generated), 4);
                index = Some((
                    alloc.buffer,
                    alloc.offset,
                    wgpu::IndexFormat::Uint32,
                    0..generated.len() as u32,
                ));
            }
            (Indices::Elements { buffer, ty, offset }, Emulated::None) => {
                let b = self
                    .buffers
                    .get_any_mut(*buffer)
                    .expect("bound buffers are alive");
                let size = index_size(*ty).expect("checked");
                let first = (offset / size) as u32;
                let (buf, format) = match *ty {
                    gl::UNSIGNED_BYTE => (
                        b.derived(gpu, DerivedKey::WideIndices, |data| {
                            let wide: Vec<u16> = data
                                .iter()
                                .map(|&i| if i == 0xFF { 0xFFFF } else { i as u16 })
                                .collect();
                            bytemuck::cast_slice(&wide).to_vec()
                        }),
                        wgpu::IndexFormat::Uint16,
                    ),
                    gl::UNSIGNED_SHORT => (b.gpu_buffer(gpu, serial), wgpu::IndexFormat::Uint16),
                    _ => (b.gpu_buffer(gpu, serial), wgpu::IndexFormat::Uint32),
                };
                index = Some((buf, 0, format, first..first + count));
            }
            (Indices::Elements { buffer, ty, offset }, how) => {
                let b = self
                    .buffers
                    .get_any(*buffer)
                    .expect("bound buffers are alive");
                let generated = emulate(read_indices(&b.data, *ty, *offset, count as u64), how);
                if generated.is_empty() {
                    return;
                }
                let alloc = self
                    .frame
                    .arena
                    .push(gpu, bytemuck::cast_slice(&generated), 4);
                index = Some((
                    alloc.buffer,
                    alloc.offset,
                    wgpu::IndexFormat::Uint32,
                    0..generated.len() as u32,
                ));
            }
        }
        let strip = matches!(
            topology,
            wgpu::PrimitiveTopology::LineStrip | wgpu::PrimitiveTopology::TriangleStrip
        );
        let strip_index_format = if strip {
            index.as_ref().map(|i| i.2)
        } else {
            None
        };

        // Textures and samplers.
        let mut slot_bindings = Vec::new();
        let mut resources = Vec::new();
        for plan in &slot_plans {
            let shadow = plan.kind == SampleKind::Depth;
            match plan.texture {
                Some((id, c)) => {
                    let t = self
                        .textures
                        .get_any_mut(id)
                        .expect("bound textures are alive");
                    let view = t.gpu_view(gpu, serial, &c);
                    let key = t.sampler_key(shadow);
                    let sampler = self.samplers.get(&gpu.device, key);
                    slot_bindings.push(SlotBinding {
                        dim: plan.dim,
                        kind: plan.kind,
                        filterable: c.format.filterable(),
                    });
                    resources.push((view, sampler));
                }
                None => {
                    let view = self.dummies.get(gpu, plan.dim, plan.kind);
                    let sampler = self
                        .samplers
                        .get(&gpu.device, SamplerKey::placeholder(shadow));
                    slot_bindings.push(SlotBinding {
                        dim: plan.dim,
                        kind: plan.kind,
                        filterable: true,
                    });
                    resources.push((view, sampler));
                }
            }
        }
        let _ = compare_function;

        // Uniforms (with the values the renderer provides).
        let height = self.fb.height as f32;
        let linked = self
            .programs
            .get_any_mut(pid)
            .and_then(|p| p.linked.as_mut())
            .expect("current programs are linked");
        let mut default = None;
        if let Some(block) = &linked.layout.uniform_block {
            for (what, offset) in &block.internal {
                match what {
                    InternalUniform::FramebufferHeight => {
                        let at = *offset as usize;
                        if let Some(dst) = linked.uniform_data.get_mut(at..at + 4) {
                            if dst != height.to_ne_bytes() {
                                dst.copy_from_slice(&height.to_ne_bytes());
                                linked.uniform_version += 1;
                            }
                        }
                    }
                }
            }
            let (chunk, buffer, offset) = match &linked.uploaded {
                Some((batch, version, chunk, offset))
                    if *batch == serial && *version == linked.uniform_version =>
                {
                    let buffer = self
                        .frame
                        .arena
                        .chunks
                        .iter()
                        .find(|c| c.id == *chunk)
                        .map(|c| c.buffer.clone());
                    (
                        *chunk,
                        buffer.expect("chunks live for the batch"),
                        *offset as u64,
                    )
                }
                _ => {
                    let align = gpu.limits.min_uniform_buffer_offset_alignment as u64;
                    let alloc = self.frame.arena.push(gpu, &linked.uniform_data, align);
                    linked.uploaded = Some((
                        serial,
                        linked.uniform_version,
                        alloc.chunk,
                        alloc.offset as u32,
                    ));
                    (alloc.chunk, alloc.buffer, alloc.offset)
                }
            };
            default = Some((chunk, buffer, offset as u32, block.size as u64));
        }
        let block_buffers: Vec<(wgpu::Buffer, u64, u64)> = blocks
            .iter()
            .map(|&(id, offset, size)| {
                let b = self
                    .buffers
                    .get_any_mut(id)
                    .expect("bound buffers are alive");
                (b.gpu_buffer(gpu, serial), offset, size)
            })
            .collect();
        let mut group0 = None;
        if default.is_some() || !block_buffers.is_empty() {
            let arena = default
                .as_ref()
                .map(|(chunk, buffer, _, size)| (*chunk, buffer, *size));
            let group = self.pipelines.group0(gpu, arena, &block_buffers);
            group0 = Some((group, default.as_ref().map(|d| d.2)));
        }
        let group1 = (!slot_bindings.is_empty())
            .then(|| self.pipelines.group1(gpu, &slot_bindings, resources));

        // The pipeline.
        let s = &self.state;
        let blend = s.blend.then(|| wgpu::BlendState {
            color: blend_component(s.blend_src_rgb, s.blend_dst_rgb, s.blend_equation_rgb),
            alpha: blend_component(s.blend_src_alpha, s.blend_dst_alpha, s.blend_equation_alpha),
        });
        let constant_alpha = [
            s.blend_src_rgb,
            s.blend_dst_rgb,
            s.blend_src_alpha,
            s.blend_dst_alpha,
        ]
        .iter()
        .any(|&f| matches!(f, gl::CONSTANT_ALPHA | gl::ONE_MINUS_CONSTANT_ALPHA));
        let blend_constant = if constant_alpha {
            [s.blend_color[3]; 4]
        } else {
            s.blend_color
        };
        let mut write_mask = wgpu::ColorWrites::empty();
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
        let cull_mode = match (s.cull_face, s.cull_face_mode) {
            (true, gl::FRONT) => Some(wgpu::Face::Front),
            (true, gl::BACK) => Some(wgpu::Face::Back),
            _ => None,
        };
        let (depth_write, depth_compare) = if s.depth_test {
            (s.depth_mask, compare_function(s.depth_func))
        } else {
            (false, wgpu::CompareFunction::Always)
        };
        let depth_bias = if s.polygon_offset_fill && triangles {
            (
                s.polygon_offset_units as i32,
                s.polygon_offset_factor.to_bits(),
            )
        } else {
            (0, 0f32.to_bits())
        };
        let key = PipelineKey {
            program: linked.serial,
            vertex: slots,
            patches,
            topology,
            strip_index_format,
            cull_mode,
            front_face: if s.front_face == gl::CW {
                wgpu::FrontFace::Cw
            } else {
                wgpu::FrontFace::Ccw
            },
            depth_write,
            depth_compare,
            depth_bias,
            blend,
            write_mask,
            slots: slot_bindings,
        };
        let pipeline = match self.pipelines.pipeline(gpu, &key, linked) {
            Ok(p) => p,
            Err(e) => {
                self.errors.record(gl::INVALID_OPERATION, || {
                    format!("draw: INVALID_OPERATION: wgpu rejected the pipeline: {e}")
                });
                return;
            }
        };

        // Record.
        let fh = self.fb.height as i64;
        let [vx, vy, vw, vh] = s.viewport.map(|v| v as i64);
        let max = 2 * gpu.limits.max_texture_dimension_2d as i64 - 1;
        let top = (fh - (vy + vh)).clamp(-max, max - vh);
        let vx = vx.clamp(-max, max - vw);
        let viewport = [
            vx as f32,
            top as f32,
            vw as f32,
            vh as f32,
            s.depth_range[0],
            s.depth_range[1],
        ];
        let viewport_bits = viewport.map(f32::to_bits);
        let blend_bits = blend_constant.map(f32::to_bits);
        let uses_constant = blend.is_some_and(|b| {
            [
                b.color.src_factor,
                b.color.dst_factor,
                b.alpha.src_factor,
                b.alpha.dst_factor,
            ]
            .iter()
            .any(|f| {
                matches!(
                    f,
                    wgpu::BlendFactor::Constant | wgpu::BlendFactor::OneMinusConstant
                )
            })
        });
        self.frame.pass(gpu, &self.fb);
        let frame = &mut self.frame;
        let pass = frame.pass.as_mut().expect("opened above");
        let ps = &mut frame.pass_state;
        if ps.pipeline != Some(pipeline.id) {
            pass.set_pipeline(&pipeline.pipeline);
            ps.pipeline = Some(pipeline.id);
        }
        if ps.viewport != Some(viewport_bits) {
            pass.set_viewport(
                viewport[0],
                viewport[1],
                viewport[2],
                viewport[3],
                viewport[4],
                viewport[5],
            );
            ps.viewport = Some(viewport_bits);
        }
        if ps.scissor != Some(scissor) {
            pass.set_scissor_rect(scissor[0], scissor[1], scissor[2], scissor[3]);
            ps.scissor = Some(scissor);
        }
        if uses_constant && ps.blend_constant != Some(blend_bits) {
            let [r, g, b, a] = blend_constant.map(|c| c as f64);
            pass.set_blend_constant(wgpu::Color { r, g, b, a });
            ps.blend_constant = Some(blend_bits);
        }
        // Bindings are pass state: set only what changed since the last draw.
        if let Some((group, offset)) = &group0 {
            if ps.group0.as_ref() != Some(&(group.clone(), *offset)) {
                pass.set_bind_group(0, group, offset.as_slice());
                ps.group0 = group0.clone();
            }
        }
        if let Some(group) = &group1 {
            if ps.group1.as_ref() != Some(group) {
                pass.set_bind_group(1, group, &[]);
                ps.group1 = group1.clone();
            }
        }
        if ps.vertex_buffers.len() < bindings.len() {
            ps.vertex_buffers.resize(bindings.len(), None);
        }
        for (slot, binding) in bindings.into_iter().enumerate() {
            if ps.vertex_buffers[slot].as_ref() != Some(&binding) {
                pass.set_vertex_buffer(slot as u32, binding.0.slice(binding.1..));
                ps.vertex_buffers[slot] = Some(binding);
            }
        }
        match index {
            Some((buffer, offset, format, range)) => {
                let binding = (buffer, offset, format);
                if ps.index_buffer.as_ref() != Some(&binding) {
                    pass.set_index_buffer(binding.0.slice(offset..), format);
                    ps.index_buffer = Some(binding);
                }
                pass.draw_indexed(range, 0, 0..instances);
            }
            None => pass.draw(vertices, 0..instances),
        }
        frame.draws += 1;
    }
}
