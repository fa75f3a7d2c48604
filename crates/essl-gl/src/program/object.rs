//! The state of shader and program objects, and of a successful link: the modules, the
//! interface draws read, the default uniform block's image and what transform feedback
//! captures.

use essl::program::ProgramLayout;

use super::feedback_layout::Feedback;
use super::interface::{ShaderInput, ValueKind};
use crate::gl;
use crate::objects::Id;
use crate::validation::{LinkedSources, ProgramChecks};

/// A shader object (`WebGLShader`).
pub(crate) struct ShaderObject {
    pub(crate) ty: u32,
    pub(crate) source: String,
    /// The source of the last `compile_shader` and whether it compiled. `link_program`
    /// compiles it again (the front end's `Shader` is not `Send`; a `Context` is).
    pub(crate) compiled: Option<(String, bool)>,
    pub(crate) info_log: String,
    /// The file name validation warnings give the shader
    /// ([`Context::set_shader_name`](crate::Context::set_shader_name)).
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
    pub(crate) sources: Option<Box<LinkedSources>>,
    /// The runtime checks of uniform values, built at the first draw with validation on.
    pub(crate) checks: Option<Box<ProgramChecks>>,
    /// What transform feedback captures, when the link asked for varyings.
    pub(crate) feedback: Option<Feedback>,
}
