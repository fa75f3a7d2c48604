//! Shader and program objects, linking a
//! [`ProgramLayout`](essl::program::ProgramLayout) from the front end, and the program's
//! uniform storage (`get_uniform_location`, `uniform*`).
//!
//! A linked program keeps a CPU image of its default uniform block, laid out as the layout's
//! [`UniformStorage::Buffer`](essl::program::UniformStorage::Buffer) offsets say, and the
//! texture unit of each sampler slot. Draws copy the image into a per-batch buffer.
//!
//! Split by concern. The state, which adds nothing to [`Context`]: [`object`] (shader and
//! program objects, a successful link), [`interface`] (what a module reads and writes, and
//! uniforms by WebGL's names), [`feedback_layout`] (what transform feedback captures) and
//! [`linker`] (the linker's settings, why a link fails). The calls: [`shader`] (compiling),
//! [`lifecycle`] (program objects, attaching, deleting), [`link`] (linking and
//! `use_program`), [`uniform`] (the `uniform*` calls and low-level setters), [`introspect`]
//! (locations, uniform blocks, active attributes and uniforms), [`blocks`] (the rest of
//! introspection: uniform indices, block parameters, `get_uniform`) and [`feedback`]
//! (transform feedback varyings): they add methods to [`Context`], whose `impl` is spread
//! over these files on purpose, one file per group of GL calls.

mod blocks;
mod feedback;
mod feedback_layout;
mod interface;
mod introspect;
mod lifecycle;
mod link;
mod linker;
mod object;
mod shader;
mod uniform;

pub(crate) use feedback_layout::MAX_SEPARATE_ATTRIBS;
pub use interface::ActiveInfo;
pub(crate) use interface::{
    find_uniform, main_entry, type_shape, uniform_shape, ShaderInput, ValueKind,
};
pub(crate) use linker::Linker;
pub use linker::ProgramFilter;
pub(crate) use object::{LinkedProgram, ProgramObject, ShaderObject};

use crate::context::Context;
use crate::gl;
use crate::objects::Program;

/// `MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS`: the indexed transform feedback bindings.
pub(crate) fn feedback_max_buffers() -> u32 {
    MAX_SEPARATE_ATTRIBS
}

impl Context {
    /// The last successful link of `program`; `None` with WebGL's error otherwise (a foreign
    /// or deleted program, or `INVALID_OPERATION` for one that is not linked).
    pub(crate) fn linked_program(
        &self,
        program: Program,
        function: &str,
    ) -> Option<&LinkedProgram> {
        let id = self.program_id(program, function)?;
        let linked = self.objects.linked(id);
        if linked.is_none() {
            self.error(gl::INVALID_OPERATION, function, "program is not linked");
        }
        linked
    }

    /// [`Context::linked_program`], to change its uniform values.
    pub(crate) fn linked_program_mut(
        &mut self,
        program: Program,
        function: &str,
    ) -> Option<&mut LinkedProgram> {
        self.linked_program(program, function)?;
        let id = self.program_id(program, function)?;
        self.objects.linked_mut(id)
    }
}
