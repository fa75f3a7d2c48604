//! A draw while transform feedback is active: WebGL2's checks (only `draw_arrays*`, the
//! session's primitive mode, room in every buffer, no buffer both captured into and read),
//! what the vertex stage writes where, and the bookkeeping after the draw.

use super::DrawArgs;
use crate::buffer::BufferRange;
use crate::context::Context;
use crate::gl;
use crate::objects::Id;
use crate::shader_patch::CaptureSpec;
use crate::transform_feedback::{vertices_per_primitive, Session};

/// What one draw captures.
pub(super) struct CaptureDraw {
    pub(super) spec: CaptureSpec,
    /// The buffers written (binding `b` of group 2 is `buffers[b]`).
    pub(super) buffers: Vec<Id>,
    /// The first record's word in each buffer.
    pub(super) base: [u32; 4],
    /// The draw's first vertex and vertices per instance.
    pub(super) first: u32,
    pub(super) count: u32,
    /// Vertices written in all.
    pub(super) vertices: u64,
}

/// Vertices per primitive of a session's mode.
pub(super) fn per_primitive(mode: u32) -> u32 {
    vertices_per_primitive(mode) as u32
}

impl Context {
    /// The draw must be a `draw_arrays*` of the session's primitive mode.
    pub(super) fn check_capture_mode(&mut self, args: &DrawArgs, mode: u32) -> Option<()> {
        if args.elements.is_some() {
            return self.fail(
                gl::INVALID_OPERATION,
                args.function,
                "transform feedback captures draw_arrays only",
            );
        }
        if args.mode != mode {
            return self.fail(
                gl::INVALID_OPERATION,
                args.function,
                "the mode is not the transform feedback primitive mode",
            );
        }
        Some(())
    }

    /// Where the draw's captured vertices go, checking that each buffer has room and is not
    /// also bound elsewhere.
    pub(super) fn plan_capture(
        &mut self,
        session: Session,
        first: u32,
        count: u32,
        instances: u32,
        f: &str,
    ) -> Option<CaptureDraw> {
        let feedback = self
            .objects
            .linked(session.program)
            .and_then(|l| l.feedback.clone())
            .expect("a session's program captures");
        let bindings: Vec<BufferRange> = self.feedback_object().buffers
            [..feedback.spec.buffers as usize]
            .iter()
            .map(|b| b.expect("checked at begin"))
            .collect();
        let vertices = count as u64 * instances as u64;
        let mut base = [0u32; 4];
        for (b, range) in bindings.iter().enumerate() {
            // WebGL 2 §5.1: a buffer bound for transform feedback and at any other point
            // (generic ARRAY_BUFFER included, as Chromium checks it) cannot be written; one the
            // draw reads was refused before (`validate`).
            if self.bound_elsewhere(range.buffer) {
                return self.fail(
                    gl::INVALID_OPERATION,
                    f,
                    "a transform feedback buffer is also bound elsewhere",
                );
            }
            let len = self
                .objects
                .buffers
                .get_any(range.buffer)
                .map_or(0, |b| b.len() as u64);
            let end = range.size.map_or(len, |s| (range.offset + s).min(len));
            let stride = 4 * feedback.stride(b as u32) as u64;
            let start = range.offset + session.written * stride;
            if start + vertices * stride > end {
                return self.fail(
                    gl::INVALID_OPERATION,
                    f,
                    "not enough room in a transform feedback buffer",
                );
            }
            base[b] = (start / 4) as u32;
        }
        Some(CaptureDraw {
            spec: feedback.spec.clone(),
            buffers: bindings.iter().map(|r| r.buffer).collect(),
            base,
            first,
            count,
            vertices,
        })
    }

    /// After a capturing draw: the session has written `vertices` more, and the
    /// primitives-written query counts them.
    pub(super) fn count_captured(&mut self, vertices: u64) {
        let tf = self.bindings.transform_feedback();
        let Some(session) = self.objects.feedback_mut(tf).session.as_mut() else {
            return;
        };
        session.written += vertices;
        let primitives = vertices / vertices_per_primitive(session.mode);
        if let Some(q) = self
            .bindings
            .query(1)
            .and_then(|id| self.objects.queries.get_any_mut(id))
        {
            q.primitives += primitives;
        }
    }
}
