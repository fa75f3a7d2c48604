//! Transform feedback varyings: `transform_feedback_varyings` (applied at the next link),
//! `get_transform_feedback_varying`, and the layout of what a draw captures: each varying's
//! words, in one interleaved buffer or one buffer each.

use super::feedback_layout::MAX_SEPARATE_ATTRIBS;
use super::ActiveInfo;
use crate::context::Context;
use crate::gl;
use crate::objects::Program;

impl Context {
    /// Names the varyings transform feedback captures and how (`transformFeedbackVaryings`):
    /// `INTERLEAVED_ATTRIBS` (one buffer) or `SEPARATE_ATTRIBS` (one buffer each, at most
    /// 4 → `INVALID_VALUE`). Takes effect at the next link.
    pub fn transform_feedback_varyings(
        &mut self,
        program: Program,
        varyings: &[&str],
        buffer_mode: u32,
    ) {
        const F: &str = "transformFeedbackVaryings";
        let Some(id) = self.program_id(program, F) else {
            return;
        };
        if !matches!(buffer_mode, gl::INTERLEAVED_ATTRIBS | gl::SEPARATE_ATTRIBS) {
            return self.error(
                gl::INVALID_ENUM,
                F,
                format_args!("buffer mode 0x{buffer_mode:04X}"),
            );
        }
        if buffer_mode == gl::SEPARATE_ATTRIBS && varyings.len() as u32 > MAX_SEPARATE_ATTRIBS {
            return self.error(
                gl::INVALID_VALUE,
                F,
                "more than MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS varyings",
            );
        }
        let p = self.objects.programs.get_any_mut(id).expect("checked");
        p.feedback_varyings = (
            varyings.iter().map(|v| v.to_string()).collect(),
            buffer_mode,
        );
    }

    /// The `index`-th varying the last link captures (`getTransformFeedbackVarying`); an
    /// index out of range → `INVALID_VALUE`.
    pub fn get_transform_feedback_varying(
        &self,
        program: Program,
        index: u32,
    ) -> Option<ActiveInfo> {
        const F: &str = "getTransformFeedbackVarying";
        let id = self.program_id(program, F)?;
        let found = self
            .objects
            .linked(id)
            .and_then(|l| l.feedback.as_ref())
            .and_then(|f| f.varyings.get(index as usize))
            .cloned();
        if found.is_none() {
            self.error(gl::INVALID_VALUE, F, "index out of range");
        }
        found
    }
}
