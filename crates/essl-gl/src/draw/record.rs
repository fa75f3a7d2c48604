//! The end of a draw: the pipeline for the program, vertex layout and GL state (fetched from
//! the cache or built), and the commands recorded into the open render pass — only the pass
//! state that changed since the last draw is set again.

use super::encode::{DrawRange, Groups};
use super::DrawCall;
use crate::context::Context;
use crate::frame::PassTarget;
use crate::gl;
use crate::pipeline::{CachedPipeline, PipelineKey, VertexSlot};
use crate::shader_patch::InputPatch;
use crate::state::compare_function;

/// The wgpu blend factor for a GL one.
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

/// The wgpu blend component for GL's source and destination factors and equation.
pub(crate) fn blend_component(src: u32, dst: u32, eq: u32) -> wgpu::BlendComponent {
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

/// The colour write mask for GL's `colorMask`.
pub(crate) fn write_mask(color_mask: &[bool; 4]) -> wgpu::ColorWrites {
    let mut write_mask = wgpu::ColorWrites::empty();
    for (m, bit) in color_mask.iter().zip([
        wgpu::ColorWrites::RED,
        wgpu::ColorWrites::GREEN,
        wgpu::ColorWrites::BLUE,
        wgpu::ColorWrites::ALPHA,
    ]) {
        if *m {
            write_mask |= bit;
        }
    }
    write_mask
}

/// What the pass is set to for a draw beyond its pipeline and bindings.
struct PassValues {
    /// x, y, width, height, near, far, in wgpu's coordinates.
    viewport: [f32; 6],
    /// The blend constant, and whether the blend state reads it.
    blend_constant: [f32; 4],
    uses_constant: bool,
    stencil_reference: u32,
}

/// What a draw's pipeline key is made of besides the GL state.
struct KeyParts<'a> {
    slots: Vec<VertexSlot>,
    patches: Vec<InputPatch>,
    range: &'a DrawRange,
    groups: &'a Groups,
    target: &'a PassTarget,
}

impl Context {
    /// Encodes a checked draw and records it into the open render pass.
    pub(super) fn encode_draw(&mut self, call: DrawCall) {
        // First what may submit the batch (buffers read back, textures and attachments
        // remade): the bindings that follow all belong to the batch the draw is recorded in.
        // The pass on the target begins at the recording, after the texture uploads.
        self.settle_reads(&call);
        let target = if call.rasterize {
            self.draw_target()
        } else {
            self.discard_target()
        };
        let serial = self.frame.serial();
        let vertex = self.bind_vertex_inputs(&call);
        let Some(range) = self.bind_indices(&call) else {
            return;
        };
        let groups = self.bind_groups(&call);
        debug_assert_eq!(
            serial,
            self.frame.serial(),
            "a draw's bindings span batches"
        );
        let parts = KeyParts {
            slots: vertex.slots,
            patches: vertex.patches,
            range: &range,
            groups: &groups,
            target: &target,
        };
        let (key, values) = self.pipeline_key(&call, parts);
        let linked = self
            .objects
            .linked_mut(call.program)
            .expect("current programs are linked");
        let pipeline = match self.caches.pipelines.pipeline(&self.gpu, &key, linked) {
            Ok(p) => p,
            Err(e) => {
                self.errors.record(gl::INVALID_OPERATION, || {
                    format!("draw: INVALID_OPERATION: wgpu rejected the pipeline: {e}")
                });
                return;
            }
        };
        // A capturing draw writes its buffers as storage, which wgpu does not allow in a pass
        // that also reads them as vertices, indices or uniforms: it gets a pass of its own.
        let captures = call.capture.is_some();
        if captures {
            self.frame.end_pass();
        }
        self.record_draw(
            &call,
            &target,
            &pipeline,
            &values,
            groups,
            vertex.bindings,
            range,
        );
        if captures {
            self.frame.end_pass();
        }
    }

    /// The pipeline key of the draw from the GL state, and the pass values that go with it.
    fn pipeline_key(&self, call: &DrawCall, parts: KeyParts) -> (PipelineKey, PassValues) {
        let KeyParts {
            slots,
            patches,
            range,
            groups,
            target,
        } = parts;
        let strip = matches!(
            call.topology,
            wgpu::PrimitiveTopology::LineStrip | wgpu::PrimitiveTopology::TriangleStrip
        );
        let strip_index_format = if strip {
            range.index.as_ref().map(|i| i.2)
        } else {
            None
        };
        let linked = self
            .objects
            .linked(call.program)
            .expect("current programs are linked");
        let program = linked.serial;
        let clip_control = if linked.layout.vertex.overrides.is_empty() {
            (false, false)
        } else {
            self.clip_control_flags()
        };
        let s = &self.state;
        // Lavapipe lets a multisampled draw cover samples outside the scissor box: the
        // fragment shader tests the box itself there (`shader_patch::with_scissor_discard`).
        let scissor_discard = (s.scissor_test && target.samples > 1 && call.rasterize).then(|| {
            let [x, y, w, h] = call.scissor;
            [x, y, x + w, y + h]
        });
        let buffers = &s.draw_buffers[..target.colors.len().min(s.draw_buffers.len())];
        let blends: Vec<_> = buffers
            .iter()
            .enumerate()
            .map(|(i, b)| (b.wgpu_blend(), self.draw_write_mask(i)))
            .collect();
        // wgpu has one constant colour: CONSTANT_ALPHA reads it as (a, a, a, a).
        let constant_alpha = buffers.iter().any(|b| b.uses_constant_alpha());
        let blend_constant = if constant_alpha {
            [s.blend_color[3]; 4]
        } else {
            s.blend_color
        };
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
        // Triangles drawn as lines (WEBGL_polygon_mode) take POLYGON_OFFSET_LINE's switch.
        let offset = if s.polygon_line {
            s.polygon_offset_line
        } else {
            s.polygon_offset_fill
        };
        let depth_bias = if offset && call.triangles {
            (
                s.polygon_offset_units as i32,
                s.polygon_offset_factor.to_bits(),
                s.polygon_offset_clamp.to_bits(),
            )
        } else {
            (0, 0f32.to_bits(), 0f32.to_bits())
        };
        let key = PipelineKey {
            program,
            vertex: slots,
            patches,
            topology: call.topology,
            strip_index_format,
            cull_mode,
            // Draws are flipped vertically (`LOWER_OPTIONS`), which swaps the winding; under
            // EXT_clip_control's upper-left origin they are not, and GL negates the polygon's
            // area itself, so the winding is GL's as it stands.
            front_face: if (s.front_face == gl::CW) != clip_control.0 {
                wgpu::FrontFace::Ccw
            } else {
                wgpu::FrontFace::Cw
            },
            depth_write,
            depth_compare,
            depth_bias,
            unclipped_depth: s.depth_clamp,
            polygon_line: s.polygon_line && call.triangles,
            blends,
            rgb_targets: self.rgb_draw_buffers(),
            slots: groups.slot_bindings.clone(),
            targets: target
                .colors
                .iter()
                .map(|c| c.as_ref().map(|c| c.format))
                .collect(),
            depth_format: target.depth.as_ref().map(|d| d.format),
            stencil: s.stencil.wgpu(s.stencil_test),
            samples: target.samples,
            alpha_to_coverage: s.sample_alpha_to_coverage,
            sample_mask: sample_mask(s, target.samples),
            float_blend: self.blends_float32(),
            capture: call.capture.as_ref().map(|c| c.spec.clone()),
            rasterize: call.rasterize,
            clip_control,
            scissor_discard,
        };
        let uses_constant = key.blends.iter().flat_map(|(b, _)| b).any(|b| {
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
        let values = PassValues {
            viewport: if call.rasterize {
                self.draw_viewport()
            } else {
                [0.0, 0.0, 1.0, 1.0, 0.0, 1.0]
            },
            blend_constant,
            uses_constant,
            stencil_reference: s.stencil.reference(),
        };
        (key, values)
    }

    /// The draw buffers whose image is RGB stored with a fourth channel, bit `i` for draw
    /// buffer `i`: draws and clears keep their alpha at 1.
    pub(crate) fn rgb_draw_buffers(&self) -> u32 {
        let formats = self.draw_formats().colors;
        formats
            .iter()
            .take(32)
            .enumerate()
            .fold(0, |bits, (i, f)| match f {
                Some(f) if f.rgb_in_four_channels() => bits | 1 << i,
                _ => bits,
            })
    }

    /// The channels draws write into draw buffer `i`: its colour mask, without alpha on a
    /// default framebuffer that has none (`alpha: false`), so that it stays 1.
    pub(crate) fn draw_write_mask(&self, i: usize) -> wgpu::ColorWrites {
        let mut mask = write_mask(&self.state.draw_buffer(i).color_mask);
        if self.bindings.framebuffers()[0].is_none() && !self.fb.attributes.alpha {
            mask -= wgpu::ColorWrites::ALPHA;
        }
        mask
    }

    /// The viewport in wgpu's coordinates, clamped to what wgpu accepts, with the depth
    /// range. Framebuffers store GL's row 0 first and draws are flipped
    /// ([`crate::LOWER_OPTIONS`]), so GL's window y is wgpu's y.
    fn draw_viewport(&self) -> [f32; 6] {
        let s = &self.state;
        let [vx, vy, vw, vh] = s.viewport.map(|v| v as i64);
        let max = 2 * self.gpu.limits.max_texture_dimension_2d as i64 - 1;
        let vy = vy.clamp(-max, max - vh);
        let vx = vx.clamp(-max, max - vw);
        [
            vx as f32,
            vy as f32,
            vw as f32,
            vh as f32,
            s.depth_range[0],
            s.depth_range[1],
        ]
    }

    /// Records the draw into the open render pass, setting only the pass state that changed.
    #[allow(clippy::too_many_arguments)] // the parts of one draw, made by the steps above
    fn record_draw(
        &mut self,
        call: &DrawCall,
        target: &PassTarget,
        pipeline: &CachedPipeline,
        values: &PassValues,
        groups: Groups,
        bindings: Vec<(wgpu::Buffer, u64)>,
        range: DrawRange,
    ) {
        let viewport = values.viewport;
        let viewport_bits = viewport.map(f32::to_bits);
        let blend_bits = values.blend_constant.map(f32::to_bits);
        let scissor = if call.rasterize {
            call.scissor
        } else {
            [0, 0, 1, 1]
        };
        let (pass, ps) = self.frame.pass(&self.gpu, target);
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
        if ps.stencil_reference != Some(values.stencil_reference) {
            pass.set_stencil_reference(values.stencil_reference);
            ps.stencil_reference = Some(values.stencil_reference);
        }
        if values.uses_constant && ps.blend_constant != Some(blend_bits) {
            let [r, g, b, a] = values.blend_constant.map(|c| c as f64);
            pass.set_blend_constant(wgpu::Color { r, g, b, a });
            ps.blend_constant = Some(blend_bits);
        }
        // Bindings are pass state: set only what changed since the last draw.
        if let Some((group, offset)) = &groups.group0 {
            if ps.group0.as_ref() != Some(&(group.clone(), *offset)) {
                pass.set_bind_group(0, group, offset.as_slice());
                ps.group0 = groups.group0.clone();
            }
        }
        if let Some(group) = &groups.group2 {
            pass.set_bind_group(2, group, &[]);
        }
        if let Some(group) = &groups.group1 {
            if ps.group1.as_ref() != Some(group) {
                pass.set_bind_group(1, group, &[]);
                ps.group1 = groups.group1.clone();
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
        let instances = call.instances;
        match range.index {
            Some((buffer, offset, format, range)) => {
                let binding = (buffer, offset, format);
                if ps.index_buffer.as_ref() != Some(&binding) {
                    pass.set_index_buffer(binding.0.slice(offset..), format);
                    ps.index_buffer = Some(binding);
                }
                pass.draw_indexed(range, 0, 0..instances);
            }
            None => pass.draw(range.vertices, 0..instances),
        }
    }
}

/// The samples a draw writes: all, or with `SAMPLE_COVERAGE` enabled on a multisampled target
/// the first `round(value · samples)` of them (the others with `invert`). GL leaves which
/// samples to the implementation; a fixed choice keeps the result deterministic.
fn sample_mask(s: &crate::state::RenderState, samples: u32) -> u64 {
    if !s.sample_coverage || samples <= 1 {
        return !0;
    }
    let (value, invert) = s.sample_coverage_value;
    let all = (1u64 << samples) - 1;
    let kept = (1u64 << (value * samples as f32).round() as u32) - 1;
    if invert {
        all & !kept
    } else {
        kept
    }
}
