//! Transform feedback objects: `create_transform_feedback`, `bind_transform_feedback`, the
//! indexed `TRANSFORM_FEEDBACK_BUFFER` bindings, `begin_transform_feedback`,
//! `end_transform_feedback`, `pause_transform_feedback`, `resume_transform_feedback`.
//!
//! An object ([`object`]) holds its buffer bindings and the session begun on it: the
//! primitive mode, the
//! program, whether it is paused, and how many vertices it has written. The draws of an
//! active session write their vertices' captured varyings after those already written
//! ([`crate::shader_patch::capture_outputs`]).

mod object;

pub(crate) use object::{vertices_per_primitive, Session, TransformFeedbackObject};

use crate::buffer::BufferRange;
use crate::context::Context;
use crate::gl;
use crate::objects::TransformFeedback;
use crate::program::feedback_max_buffers;

impl Context {
    /// The bound transform feedback object (the default one for `None`).
    pub(crate) fn feedback_object(&self) -> &TransformFeedbackObject {
        self.objects.feedback(self.bindings.transform_feedback())
    }

    /// The active, unpaused session, if any.
    pub(crate) fn capturing(&self) -> Option<Session> {
        self.feedback_object().session.filter(|s| !s.paused)
    }

    /// Whether `buffer` is bound at a point other than the transform feedback ones: a generic
    /// binding, an indexed uniform buffer binding, or the vertex array's element buffer.
    pub(crate) fn bound_elsewhere(&self, buffer: crate::objects::Id) -> bool {
        const GENERIC: [u32; 6] = [
            gl::ARRAY_BUFFER,
            gl::COPY_READ_BUFFER,
            gl::COPY_WRITE_BUFFER,
            gl::PIXEL_PACK_BUFFER,
            gl::PIXEL_UNPACK_BUFFER,
            gl::UNIFORM_BUFFER,
        ];
        GENERIC
            .iter()
            .any(|&t| self.bindings.buffer(t) == Some(buffer))
            || (0..crate::context::MAX_UNIFORM_BUFFER_BINDINGS as usize).any(|i| {
                self.bindings
                    .uniform_range(i)
                    .is_some_and(|r| r.buffer == buffer)
            })
            || self.vao().element_buffer == Some(buffer)
    }

    /// Whether `buffer` is at an indexed binding of the bound transform feedback object, in
    /// use or not: WebGL 2 §5.1 forbids reading or writing it through any other binding.
    pub(crate) fn in_feedback_object(&self, buffer: crate::objects::Id) -> bool {
        self.feedback_object()
            .buffers
            .iter()
            .flatten()
            .any(|r| r.buffer == buffer)
    }

    /// `INVALID_OPERATION` for an operation on `buffer`'s data (`bufferData`, a copy, a pixel
    /// transfer through it) while it is bound for transform feedback and at another binding
    /// point, or while a transform feedback session writes it, as Chromium checks (WebGL 2
    /// §5.1); true when that is recorded.
    pub(crate) fn refuse_double_bound(&mut self, buffer: crate::objects::Id, f: &str) -> bool {
        let why = if self.objects.captures_into(buffer) {
            "a transform feedback session writes the buffer"
        } else if self.in_feedback_object(buffer) && self.bound_elsewhere(buffer) {
            "the buffer is bound for transform feedback and at another binding point"
        } else {
            return false;
        };
        self.error(gl::INVALID_OPERATION, f, why);
        true
    }

    /// Creates a transform feedback object (`createTransformFeedback`).
    pub fn create_transform_feedback(&mut self) -> TransformFeedback {
        TransformFeedback {
            ctx: self.id,
            id: self
                .objects
                .transform_feedbacks
                .insert(TransformFeedbackObject::default()),
        }
    }

    /// Whether `tf` names a live transform feedback object that was bound once
    /// (`isTransformFeedback`).
    pub fn is_transform_feedback(&self, tf: TransformFeedback) -> bool {
        tf.ctx == self.id
            && self
                .objects
                .transform_feedbacks
                .get(tf.id)
                .is_some_and(|t| t.bound_once)
    }

    /// Deletes a transform feedback object (`deleteTransformFeedback`); an active one →
    /// `INVALID_OPERATION`.
    pub fn delete_transform_feedback(&mut self, tf: TransformFeedback) {
        const F: &str = "deleteTransformFeedback";
        if !self.owns(tf.ctx, F) {
            return;
        }
        let Some(t) = self.objects.transform_feedbacks.get(tf.id) else {
            return;
        };
        if t.session.is_some() {
            return self.error(gl::INVALID_OPERATION, F, "the object is active");
        }
        self.bindings.forget_transform_feedback(tf.id);
        self.objects.delete_transform_feedback(tf.id);
    }

    /// Binds a transform feedback object to `TRANSFORM_FEEDBACK` (`bindTransformFeedback`);
    /// `None` binds the default one. While a session is active and not paused →
    /// `INVALID_OPERATION`.
    pub fn bind_transform_feedback(&mut self, target: u32, tf: Option<TransformFeedback>) {
        const F: &str = "bindTransformFeedback";
        if target != gl::TRANSFORM_FEEDBACK {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        if self.capturing().is_some() {
            return self.error(gl::INVALID_OPERATION, F, "transform feedback is active");
        }
        let id = match tf {
            None => None,
            Some(t) => {
                if !self.owns(t.ctx, F) {
                    return;
                }
                let Some(obj) = self.objects.transform_feedbacks.get_mut(t.id) else {
                    return self.error(gl::INVALID_OPERATION, F, "deleted object");
                };
                obj.bound_once = true;
                Some(t.id)
            }
        };
        self.bindings.bind_transform_feedback(id);
    }

    /// Binds a range of a buffer (or none) to indexed `TRANSFORM_FEEDBACK_BUFFER` point
    /// `index` of the bound object. An index ≥ `MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS` →
    /// `INVALID_VALUE`; an active session → `INVALID_OPERATION`; an offset or size that is
    /// not a multiple of 4 → `INVALID_VALUE`.
    pub(crate) fn bind_feedback_buffer(
        &mut self,
        index: u32,
        range: Option<BufferRange>,
        function: &str,
    ) {
        if index >= feedback_max_buffers() {
            return self.error(
                gl::INVALID_VALUE,
                function,
                "index ≥ MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS",
            );
        }
        if self.feedback_object().session.is_some() {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "transform feedback is active",
            );
        }
        if range.is_some_and(|r| r.offset % 4 != 0 || r.size.is_some_and(|s| s % 4 != 0)) {
            return self.error(
                gl::INVALID_VALUE,
                function,
                "offset and size must be multiples of 4",
            );
        }
        let tf = self.bindings.transform_feedback();
        self.objects.set_feedback_buffer(tf, index as usize, range);
        self.bindings
            .bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, range.map(|r| r.buffer));
    }

    /// Starts capturing (`beginTransformFeedback`) `POINTS`, `LINES` or `TRIANGLES`
    /// (`INVALID_ENUM`). Already active, no program in use, a program that captures
    /// nothing, or a buffer missing for one of its varyings → `INVALID_OPERATION`.
    pub fn begin_transform_feedback(&mut self, primitive_mode: u32) {
        const F: &str = "beginTransformFeedback";
        if !matches!(primitive_mode, gl::POINTS | gl::LINES | gl::TRIANGLES) {
            return self.error(
                gl::INVALID_ENUM,
                F,
                format_args!("mode 0x{primitive_mode:04X}"),
            );
        }
        if self.feedback_object().session.is_some() {
            return self.error(gl::INVALID_OPERATION, F, "transform feedback is active");
        }
        let Some(program) = self.bindings.program() else {
            return self.error(gl::INVALID_OPERATION, F, "no program in use");
        };
        let Some(buffers) = self
            .objects
            .linked(program)
            .and_then(|l| l.feedback.as_ref())
            .map(|f| f.spec.buffers)
        else {
            return self.error(gl::INVALID_OPERATION, F, "the program captures no varying");
        };
        let bound = &self.feedback_object().buffers;
        if (0..buffers as usize).any(|b| bound[b].is_none()) {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "a varying has no TRANSFORM_FEEDBACK_BUFFER bound",
            );
        }
        // Every binding counts, those past the program's outputs too, as Chromium checks.
        let used: Vec<_> = bound.iter().flatten().collect();
        if (1..used.len()).any(|i| used[..i].iter().any(|b| b.buffer == used[i].buffer)) {
            // WebGL 2 §5.21: one buffer at two bindings of a session.
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "one buffer is bound at two TRANSFORM_FEEDBACK_BUFFER indices",
            );
        }
        let tf = self.bindings.transform_feedback();
        self.objects.feedback_mut(tf).session = Some(Session {
            mode: primitive_mode,
            program,
            paused: false,
            written: 0,
        });
    }

    /// Ends capturing (`endTransformFeedback`); not active → `INVALID_OPERATION`.
    pub fn end_transform_feedback(&mut self) {
        let tf = self.bindings.transform_feedback();
        if self.objects.feedback_mut(tf).session.take().is_none() {
            self.error(
                gl::INVALID_OPERATION,
                "endTransformFeedback",
                "transform feedback is not active",
            );
        }
    }

    /// Pauses capturing (`pauseTransformFeedback`); not active or already paused →
    /// `INVALID_OPERATION`.
    pub fn pause_transform_feedback(&mut self) {
        self.set_paused(true, "pauseTransformFeedback");
    }

    /// Resumes capturing (`resumeTransformFeedback`); not active or not paused →
    /// `INVALID_OPERATION`.
    pub fn resume_transform_feedback(&mut self) {
        self.set_paused(false, "resumeTransformFeedback");
    }

    fn set_paused(&mut self, paused: bool, function: &str) {
        let tf = self.bindings.transform_feedback();
        let program = self.bindings.program();
        let session = self.objects.feedback(tf).session;
        if !paused && session.is_some_and(|s| s.paused && Some(s.program) != program) {
            // ES 3.0 §2.15.2: resuming needs the program that began the session in use.
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "the program in use is not the one that began transform feedback",
            );
        }
        match &mut self.objects.feedback_mut(tf).session {
            Some(s) if s.paused != paused => s.paused = paused,
            _ => self.error(
                gl::INVALID_OPERATION,
                function,
                if paused {
                    "transform feedback is not active, or paused"
                } else {
                    "transform feedback is not paused"
                },
            ),
        }
    }
}
