//! Drawing: `clear`, `draw_arrays`, `draw_elements` and their instanced forms.
//!
//! A draw goes through three steps, each in its own module:
//!
//! 1. [`validate`] checks WebGL's rules that do not depend on the program's interface (mode,
//!    counts, index type and offset, a program in use, enabled arrays with buffers) and, once
//!    the program's inputs are known, the ranges the draw reads;
//! 2. [`gather`] collects what the draw reads — uniform block ranges, where each vertex input
//!    comes from, which texture each sampler slot samples — checking WebGL2's type rules as
//!    it goes. Together they make a [`DrawCall`], or record the error and draw nothing;
//! 3. [`encode`] brings the buffers and textures the draw uses up to date on the GPU and
//!    makes the bind groups; [`record`] fetches or builds the pipeline for the program,
//!    vertex layout and state, and records the draw into the open render pass.
//!
//! [`multi`] holds `WEBGL_multi_draw`'s calls, which are draws in a row.
//! [`topology`] makes on the CPU what wgpu lacks (emulated topologies, re-packed arrays) and
//! [`clear`] holds `clear`. Each module adds methods to [`Context`]: its `impl` is spread
//! over these files on purpose, one file per step.

mod clear;
mod encode;
mod feedback;
mod gather;
mod multi;
mod record;
mod topology;
mod validate;

use crate::context::Context;
use crate::gl;
use crate::objects::Id;
use crate::program::{ShaderInput, ValueKind};
use crate::shader_patch::{Norm32, Packed};
use crate::texture::{Complete, SampleKind};
use crate::vertex_array::{GenericAttrib, VertexAttrib};

pub use multi::DrawList;
pub(crate) use record::blend_component;
use topology::Emulated;

/// How a vertex format feeds an attribute.
#[derive(Clone, Copy, Debug)]
pub(super) struct Feed {
    pub(super) format: wgpu::VertexFormat,
    pub(super) kind: ValueKind,
    pub(super) count: u8,
    pub(super) used: u8,
    pub(super) norm: Option<Norm32>,
    /// A packed `2_10_10_10` word the shader unpacks.
    pub(super) packed: Option<Packed>,
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
    /// The complete texture read, and the sampling parameters that apply (its own or the
    /// unit's sampler object's).
    texture: Option<(Id, Complete, crate::sampler::SamplerParams)>,
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

/// The arguments of a draw entry point, as WebGL gives them.
#[derive(Clone, Copy)]
struct DrawArgs {
    mode: u32,
    first: i32,
    count: i32,
    /// Index type and byte offset (`draw_elements`), or `None` (`draw_arrays`).
    elements: Option<(u32, i64)>,
    instances: i32,
    /// The WebGL function's name, for error messages.
    function: &'static str,
}

/// A draw that passed WebGL's checks: everything encoding needs.
struct DrawCall {
    /// The program in use.
    program: Id,
    topology: wgpu::PrimitiveTopology,
    emulated: Emulated,
    /// Whether the mode draws triangles (polygon offset applies).
    triangles: bool,
    indices: Indices,
    count: u32,
    instances: u32,
    /// Each vertex input of the program and where its values come from.
    sources: Vec<(ShaderInput, Source)>,
    /// What each sampler slot of the program reads.
    slot_plans: Vec<SlotPlan>,
    /// The buffer ranges (buffer, offset, size) of the program's uniform blocks.
    blocks: Vec<(Id, u64, u64)>,
    /// The scissor rectangle in wgpu's coordinates.
    scissor: [u32; 4],
    /// What transform feedback captures, when a session is active.
    capture: Option<feedback::CaptureDraw>,
    /// Whether the draw makes fragments (false while capturing with `RASTERIZER_DISCARD`).
    rasterize: bool,
}

impl Context {
    /// Draws `count` vertices from `first` (`drawArrays`).
    pub fn draw_arrays(&mut self, mode: u32, first: i32, count: i32) {
        self.draw(DrawArgs {
            mode,
            first,
            count,
            elements: None,
            instances: 1,
            function: "drawArrays",
        });
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
        self.draw(DrawArgs {
            mode,
            first,
            count,
            elements: None,
            instances: instance_count,
            function: "drawArraysInstanced",
        });
    }

    /// Draws `count` indices of type `ty` (`UNSIGNED_BYTE`, `UNSIGNED_SHORT`,
    /// `UNSIGNED_INT`) read from byte `offset` of the element array buffer (`drawElements`).
    /// The fixed primitive restart index (all ones) is always enabled, as in WebGL2.
    pub fn draw_elements(&mut self, mode: u32, count: i32, ty: u32, offset: i64) {
        if self.webgl1_refuses_index_type(ty, "drawElements") {
            return;
        }
        self.draw(DrawArgs {
            mode,
            first: 0,
            count,
            elements: Some((ty, offset)),
            instances: 1,
            function: "drawElements",
        });
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
        if self.webgl1_refuses_index_type(ty, "drawElementsInstanced") {
            return;
        }
        self.draw(DrawArgs {
            mode,
            first: 0,
            count,
            elements: Some((ty, offset)),
            instances: instance_count,
            function: "drawElementsInstanced",
        });
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
        self.draw(DrawArgs {
            mode,
            first: 0,
            count,
            elements: Some((ty, offset)),
            instances: 1,
            function: "drawRangeElements",
        });
    }

    /// A draw: checked and gathered into a [`DrawCall`] (or an error recorded), then
    /// encoded.
    fn draw(&mut self, args: DrawArgs) {
        let Some(call) = self.prepare_draw(args) else {
            return;
        };
        // The debug mode: one test when it is off (the checks and their bookkeeping live
        // behind it).
        if self.validation.enabled {
            self.validate_uniforms(call.program, args.function);
        }
        let captured = call.capture.as_ref().map(|c| c.vertices);
        self.encode_draw(call);
        if let Some(vertices) = captured {
            self.count_captured(vertices);
        }
    }
}
