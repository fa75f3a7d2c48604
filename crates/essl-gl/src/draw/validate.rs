//! WebGL's checks of a draw, in the order browsers make them, and the [`DrawCall`] that a
//! draw which passes them becomes. What the program reads is collected (and checked) by
//! [`super::gather`].

use super::topology::Emulated;
use super::{DrawArgs, DrawCall, Indices, Source};
use crate::buffer::index_size;
use crate::context::Context;
use crate::gl;
use crate::program::ShaderInput;

impl Context {
    /// Records a GL error and answers `None`, for checks that end a draw.
    pub(super) fn fail<T>(
        &mut self,
        code: u32,
        function: &str,
        what: impl std::fmt::Display,
    ) -> Option<T> {
        self.error(code, function, what);
        None
    }

    /// Checks a draw and gathers what it reads; `None` when it draws nothing (with the error
    /// recorded when WebGL's rules are broken).
    pub(super) fn prepare_draw(&mut self, args: DrawArgs) -> Option<DrawCall> {
        let f = args.function;
        let (topology, mut emulated) = self.draw_topology(args.mode, f)?;
        if args.first < 0 || args.count < 0 || args.instances < 0 {
            return self.fail(
                gl::INVALID_VALUE,
                f,
                "negative first, count or instance count",
            );
        }
        let index_info = match args.elements {
            Some((ty, offset)) => Some(self.check_index_args(ty, offset, f)?),
            None => None,
        };
        if !self.require_complete(true, f) {
            return None;
        }
        let Some(pid) = self.bindings.program() else {
            return self.fail(gl::INVALID_OPERATION, f, "no program in use");
        };
        if self.objects.linked(pid).is_none() {
            return self.fail(
                gl::INVALID_OPERATION,
                f,
                "the program in use was relinked and its link failed",
            );
        }
        let session = self.capturing();
        if let Some(session) = session {
            self.check_capture_mode(&args, session.mode)?;
        }
        let indices = match index_info {
            None => Indices::None {
                first: args.first as u32,
            },
            Some((ty, offset)) => match self.vao().element_buffer {
                Some(buffer) => Indices::Elements { buffer, ty, offset },
                None => {
                    return self.fail(gl::INVALID_OPERATION, f, "no ELEMENT_ARRAY_BUFFER bound")
                }
            },
        };
        if let Some(i) = self
            .vao()
            .attribs
            .iter()
            .position(|a| a.enabled && a.buffer.is_none())
        {
            return self.fail(
                gl::INVALID_OPERATION,
                f,
                format_args!("attribute {i} is enabled but has no buffer"),
            );
        }
        let blocks = self.gather_blocks(pid, f)?;
        let sources = self.gather_sources(pid, f)?;
        // WebGL 2 §5.1: a buffer at an indexed binding of the bound transform feedback object
        // cannot be read by a draw, capturing or not (while capturing, `plan_capture` also
        // refuses one bound anywhere else).
        let read_for_feedback = sources.iter().any(
            |(_, s)| matches!(s, Source::Array { buffer, .. } if self.in_feedback_object(*buffer)),
        ) || blocks.iter().any(|&(b, _, _)| self.in_feedback_object(b));
        if read_for_feedback {
            return self.fail(
                gl::INVALID_OPERATION,
                f,
                "a buffer the draw reads is bound for transform feedback",
            );
        }
        let slot_plans = self.gather_samplers(pid, f)?;
        let formats = self.draw_formats();
        self.check_outputs(pid, &formats, f)?;
        // WebGL 1 §6.11, as Chromium applies it: only while the stencil test runs on a
        // framebuffer with stencil bits.
        if formats.stencil && self.state.stencil_test && !self.state.stencil.faces_agree() {
            return self.fail(
                gl::INVALID_OPERATION,
                f,
                "front and back stencil references or masks differ (WebGL)",
            );
        }
        // ANGLE_instanced_arrays (WebGL 1): an instanced draw needs an attribute the program
        // uses whose divisor is 0.
        if self.webgl1.on && f.ends_with("Instanced") && !self.has_divisor_zero(pid) {
            let msg = "no attribute of the program has a divisor of 0 (ANGLE_instanced_arrays)";
            return self.fail(gl::INVALID_OPERATION, f, msg);
        }
        if args.count == 0 || args.instances == 0 {
            return None;
        }
        let (mut count, instances) = (args.count as u32, args.instances as u32);
        let capture = match session {
            Some(session) => {
                // Only whole primitives are captured (and drawn).
                count -= count % super::feedback::per_primitive(session.mode);
                Some(self.plan_capture(session, args.first as u32, count, instances, f)?)
            }
            None => None,
        };
        let (max_vertex, restarts) = self.index_range(&indices, count, f)?;
        if restarts && emulated == Emulated::None {
            match args.mode {
                gl::POINTS => emulated = Emulated::List(1),
                gl::LINES => emulated = Emulated::List(2),
                gl::TRIANGLES => emulated = Emulated::List(3),
                _ => {}
            }
        }
        self.check_attribute_ranges(&sources, max_vertex, instances, f)?;

        // Draws that GL would rasterize to nothing: still made when they capture vertices.
        let s = &self.state;
        let triangles = matches!(
            args.mode,
            gl::TRIANGLES | gl::TRIANGLE_STRIP | gl::TRIANGLE_FAN
        );
        let scissor = self.scissor_rect_for(formats.size);
        let rasterize = !(s.rasterizer_discard
            || (s.cull_face && s.cull_face_mode == gl::FRONT_AND_BACK && triangles)
            || s.viewport[2] == 0
            || s.viewport[3] == 0
            || scissor.is_none());
        if !rasterize && capture.is_none() || count == 0 {
            return None;
        }
        Some(DrawCall {
            program: pid,
            topology,
            emulated,
            triangles,
            indices,
            count,
            instances,
            sources,
            slot_plans,
            blocks,
            scissor: scissor.unwrap_or([0, 0, 1, 1]),
            capture,
            rasterize,
        })
    }

    /// The wgpu topology for a GL mode, and how it is emulated; `INVALID_ENUM` for others.
    fn draw_topology(&mut self, mode: u32, f: &str) -> Option<(wgpu::PrimitiveTopology, Emulated)> {
        use wgpu::PrimitiveTopology as T;
        Some(match mode {
            gl::POINTS => (T::PointList, Emulated::None),
            gl::LINES => (T::LineList, Emulated::None),
            gl::LINE_STRIP => (T::LineStrip, Emulated::None),
            gl::LINE_LOOP => (T::LineStrip, Emulated::LineLoop),
            gl::TRIANGLES => (T::TriangleList, Emulated::None),
            gl::TRIANGLE_STRIP => (T::TriangleStrip, Emulated::None),
            gl::TRIANGLE_FAN => (T::TriangleList, Emulated::TriangleFan),
            _ => return self.fail(gl::INVALID_ENUM, f, format_args!("mode 0x{mode:04X}")),
        })
    }

    /// Checks the index type and offset of `draw_elements`: the type and the offset as
    /// `u64`.
    fn check_index_args(&mut self, ty: u32, offset: i64, f: &str) -> Option<(u32, u64)> {
        let Some(size) = index_size(ty) else {
            return self.fail(gl::INVALID_ENUM, f, format_args!("index type 0x{ty:04X}"));
        };
        if offset < 0 {
            return self.fail(gl::INVALID_VALUE, f, "negative offset");
        }
        if offset as u64 % size != 0 {
            return self.fail(
                gl::INVALID_OPERATION,
                f,
                "offset is not a multiple of the index size",
            );
        }
        Some((ty, offset as u64))
    }

    /// The largest vertex the draw reads (`None`: no vertex, all indices restart) and
    /// whether the indices hold the restart index; indices past the end of the element
    /// buffer → `INVALID_OPERATION`. The element buffer caches the answer per version.
    fn index_range(
        &mut self,
        indices: &Indices,
        count: u32,
        f: &str,
    ) -> Option<(Option<u64>, bool)> {
        let (buffer, ty, offset) = match indices {
            Indices::None { first } => {
                return Some((Some(*first as u64 + count as u64 - 1), false))
            }
            Indices::Elements { buffer, ty, offset } => (*buffer, *ty, *offset),
        };
        let b = self
            .objects
            .buffers
            .get_any_mut(buffer)
            .expect("bound buffers are alive");
        let Some(range) = b.index_range(&self.gpu, &mut self.frame, ty, offset, count as u64)
        else {
            return self.fail(
                gl::INVALID_OPERATION,
                f,
                "indices past the end of the element buffer",
            );
        };
        Some((range.max.map(u64::from), range.restarts))
    }

    /// Checks that no enabled array is read past the end of its buffer, up to vertex
    /// `max_vertex` (or the last instance, for instanced arrays).
    fn check_attribute_ranges(
        &mut self,
        sources: &[(ShaderInput, Source)],
        max_vertex: Option<u64>,
        instances: u32,
        f: &str,
    ) -> Option<()> {
        for (input, source) in sources {
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
                .objects
                .buffers
                .get_any(*buffer)
                .expect("attached buffers are alive")
                .len() as u64;
            if a.offset + last * a.effective_stride() + a.element_size() > len {
                let msg = format!(
                    "attribute {} reads past the end of its buffer",
                    input.location
                );
                return self.fail(gl::INVALID_OPERATION, f, msg);
            }
        }
        Some(())
    }

    /// Whether an attribute the program `pid` uses reads its array with divisor 0.
    fn has_divisor_zero(&self, pid: crate::objects::Id) -> bool {
        let Some(linked) = self.objects.linked(pid) else {
            return true;
        };
        let attribs = &self.vao().attribs;
        linked.layout.attributes.iter().any(|a| {
            attribs
                .get(a.location as usize)
                .is_some_and(|x| x.divisor == 0)
        })
    }
}
