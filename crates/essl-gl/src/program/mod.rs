//! Shader and program objects, linking a [`ProgramLayout`] from the front end, and the
//! program's uniform storage (`get_uniform_location`, `uniform*`).
//!
//! A linked program keeps a CPU image of its default uniform block, laid out as the layout's
//! [`UniformStorage::Buffer`] offsets say, and the texture unit of each sampler slot. Draws
//! copy the image into a per-batch buffer.
//!
//! Split by concern: [`shader`] (shader objects, compiling), [`lifecycle`] (program objects,
//! attaching, deleting), [`link`] (linking and `use_program`), [`interface`] (a module's
//! inputs and outputs), [`uniform`] (the `uniform*` calls and low-level setters) and
//! [`introspect`] (locations, blocks, active attributes and uniforms). All but `interface`
//! add methods to [`Context`]: its `impl` is spread over these files on purpose, one file per
//! group of GL calls.

mod blocks;
mod feedback;
mod interface;
mod introspect;
mod lifecycle;
mod link;
mod shader;
mod uniform;

pub(crate) use feedback::MAX_SEPARATE_ATTRIBS;
pub(crate) use interface::{main_entry, type_shape};

/// `MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS`: the indexed transform feedback bindings.
pub(crate) fn feedback_max_buffers() -> u32 {
    MAX_SEPARATE_ATTRIBS
}
pub(crate) use link::{LinkError, Linker};
pub(crate) use uniform::{find_uniform, uniform_shape};

use essl::program::ProgramLayout;

use crate::context::Context;
use crate::gl;
use crate::objects::{Id, Program};

/// The scalar kind of a shader input or output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum ValueKind {
    Float,
    Sint,
    Uint,
}

/// A vertex shader input, read from the naga module's entry point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct ShaderInput {
    pub(crate) location: u32,
    pub(crate) kind: ValueKind,
    pub(crate) components: u8,
}

/// What `get_active_attrib`, `get_active_uniform` and `get_transform_feedback_varying`
/// return (`WebGLActiveInfo`): the name as WebGL enumerates it, the array size (1 for a
/// non-array) and the type enum (`FLOAT_VEC3`, `SAMPLER_2D`, …).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ActiveInfo {
    /// The name (`u_lights[0].color`, `u_weights[0]`).
    pub name: String,
    /// Elements of an array, else 1.
    pub size: u32,
    /// The type, as a GL enum.
    pub ty: u32,
}

/// A shader object (`WebGLShader`).
pub(crate) struct ShaderObject {
    pub(crate) ty: u32,
    pub(crate) source: String,
    /// The source of the last `compile_shader` and whether it compiled. `link_program`
    /// compiles it again (the front end's `Shader` is not `Send`; a `Context` is).
    pub(crate) compiled: Option<(String, bool)>,
    pub(crate) info_log: String,
    /// The file name validation warnings give the shader ([`Context::set_shader_name`]).
    pub(crate) name: Option<String>,
}

/// A program object (`WebGLProgram`).
pub(crate) struct ProgramObject {
    pub(crate) attached: Vec<Id>,
    /// `bind_attrib_location` requests, applied at the next link.
    pub(crate) attrib_bindings: Vec<(String, u32)>,
    pub(crate) linked: Option<LinkedProgram>,
    pub(crate) link_status: bool,
    /// The result of the last `validate_program`.
    pub(crate) validate_status: bool,
    pub(crate) info_log: String,
    /// `transformFeedbackVaryings`: the names and the buffer mode the next link uses.
    pub(crate) feedback_varyings: (Vec<String>, u32),
}

impl Default for ProgramObject {
    fn default() -> Self {
        ProgramObject {
            attached: Vec::new(),
            attrib_bindings: Vec::new(),
            linked: None,
            link_status: false,
            validate_status: false,
            info_log: String::new(),
            feedback_varyings: (Vec::new(), gl::INTERLEAVED_ATTRIBS),
        }
    }
}

/// The result of a successful link.
pub(crate) struct LinkedProgram {
    /// Unique per link within the context: keys pipelines and uniform locations.
    pub(crate) serial: u64,
    pub(crate) layout: ProgramLayout,
    pub(crate) vertex_module: wgpu::ShaderModule,
    pub(crate) fragment_module: wgpu::ShaderModule,
    pub(crate) inputs: Vec<ShaderInput>,
    /// The fragment outputs: location and kind.
    pub(crate) outputs: Vec<(u32, ValueKind)>,
    pub(crate) uniform_data: Vec<u8>,
    /// Bumped when `uniform_data` changes.
    pub(crate) uniform_version: u64,
    pub(crate) sampler_units: Vec<u32>,
    /// The `UNIFORM_BUFFER` binding point of each uniform block (`uniformBlockBinding`).
    pub(crate) block_bindings: Vec<u32>,
    /// Where the current uniform image was last put: (batch, version, chunk, offset).
    pub(crate) uploaded: Option<(u64, u64, u64, u32)>,
    /// The shaders' names and texts as linked (`link_program`; `None` for a layout linked
    /// directly), from which validation extracts the uniform preconditions when it is on.
    pub(crate) sources: Option<Box<crate::validation::LinkedSources>>,
    /// The runtime checks of uniform values, built at the first draw with validation on.
    pub(crate) checks: Option<Box<crate::validation::ProgramChecks>>,
    /// What transform feedback captures, when the link asked for varyings.
    pub(crate) feedback: Option<feedback::Feedback>,
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
