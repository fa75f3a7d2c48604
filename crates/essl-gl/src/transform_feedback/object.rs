//! A transform feedback object's state: its indexed buffer bindings and the session begun on
//! it.

use crate::buffer::BufferRange;
use crate::gl;
use crate::objects::Id;

/// A transform feedback session (between begin and end).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Session {
    /// `POINTS`, `LINES` or `TRIANGLES`.
    pub(crate) mode: u32,
    pub(crate) program: Id,
    pub(crate) paused: bool,
    /// Vertices written since begin.
    pub(crate) written: u64,
}

/// A transform feedback object.
#[derive(Clone, Debug, Default)]
pub(crate) struct TransformFeedbackObject {
    pub(crate) bound_once: bool,
    /// The indexed `TRANSFORM_FEEDBACK_BUFFER` bindings.
    pub(crate) buffers: [Option<BufferRange>; 4],
    pub(crate) session: Option<Session>,
}

/// Vertices per primitive of a transform feedback primitive mode.
pub(crate) fn vertices_per_primitive(mode: u32) -> u64 {
    match mode {
        gl::LINES => 2,
        gl::TRIANGLES => 3,
        _ => 1,
    }
}
