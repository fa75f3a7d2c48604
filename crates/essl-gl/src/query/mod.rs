//! State queries with WebGL's names: `get_parameter`, `get_shader_parameter`,
//! `get_program_parameter` and `validate_program`, returning a [`Parameter`].
//!
//! WebGL's queries return "any" (a boolean, a number, a typed array, an object or `null`);
//! [`Parameter`] is that value in Rust. An unknown `pname` records `INVALID_ENUM` and returns
//! `None`, as WebGL returns `null`.

mod objects;
mod parameter;

pub use objects::ShaderPrecisionFormat;

use crate::context::Context;
use crate::gl;
use crate::objects::{Buffer, Program, Shader, Texture, VertexArray};

/// A value returned by [`Context::get_parameter`], [`Context::get_shader_parameter`] and
/// [`Context::get_program_parameter`]: what WebGL's `any` holds for that `pname`.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Parameter {
    /// `GLboolean`.
    Bool(bool),
    /// `GLint`, `GLuint` or `GLint64` (`MAX_TEXTURE_SIZE`, `ACTIVE_UNIFORMS`, …).
    Int(i64),
    /// `GLenum` (`SHADER_TYPE`, `DEPTH_FUNC`, `ACTIVE_TEXTURE`, …).
    Enum(u32),
    /// `GLfloat` (`DEPTH_CLEAR_VALUE`, `LINE_WIDTH`, …).
    Float(f32),
    /// `Int32Array` (`VIEWPORT`, `SCISSOR_BOX`, `MAX_VIEWPORT_DIMS`).
    Ints(Vec<i32>),
    /// `Float32Array` (`COLOR_CLEAR_VALUE`, `DEPTH_RANGE`, `BLEND_COLOR`, …).
    Floats(Vec<f32>),
    /// `sequence<GLboolean>` (`COLOR_WRITEMASK`).
    Bools(Vec<bool>),
    /// `DOMString` (`VERSION`, `SHADING_LANGUAGE_VERSION`, `VENDOR`, `RENDERER`).
    String(String),
    /// `WebGLProgram` or `null` (`CURRENT_PROGRAM`).
    Program(Option<Program>),
    /// `WebGLBuffer` or `null` (`ARRAY_BUFFER_BINDING`, …).
    Buffer(Option<Buffer>),
    /// `WebGLTexture` or `null` (`TEXTURE_BINDING_2D`, …).
    Texture(Option<Texture>),
    /// `WebGLVertexArrayObject` or `null` for the default one (`VERTEX_ARRAY_BINDING`).
    VertexArray(Option<VertexArray>),
    /// `WebGLFramebuffer` or `null` for the default one (`DRAW_FRAMEBUFFER_BINDING`, …).
    Framebuffer(Option<crate::Framebuffer>),
    /// `WebGLRenderbuffer` or `null` (`RENDERBUFFER_BINDING`, an attachment's object).
    Renderbuffer(Option<crate::Renderbuffer>),
    /// `WebGLSampler` or `null` (`SAMPLER_BINDING`).
    Sampler(Option<crate::Sampler>),
    /// `WebGLTransformFeedback` or `null` (`TRANSFORM_FEEDBACK_BINDING`).
    TransformFeedback(Option<crate::TransformFeedback>),
    /// `WebGLQuery` or `null` (`getQuery(target, CURRENT_QUERY)`).
    Query(Option<crate::Query>),
    /// `Uint32Array` (`getActiveUniforms` of several uniforms, `getUniformIndices`).
    Uints(Vec<u32>),
    /// `null`: a query with no object to return (an attachment point with nothing
    /// attached, a default framebuffer's object name).
    Null,
}

impl Parameter {
    /// The value if it is a [`Parameter::Bool`].
    pub fn as_bool(&self) -> Option<bool> {
        match self {
            Parameter::Bool(b) => Some(*b),
            _ => None,
        }
    }

    /// The value if it is a [`Parameter::Int`].
    pub fn as_int(&self) -> Option<i64> {
        match self {
            Parameter::Int(i) => Some(*i),
            _ => None,
        }
    }

    /// The value if it is a [`Parameter::Enum`].
    pub fn as_enum(&self) -> Option<u32> {
        match self {
            Parameter::Enum(e) => Some(*e),
            _ => None,
        }
    }

    /// The value if it is a [`Parameter::Float`].
    pub fn as_float(&self) -> Option<f32> {
        match self {
            Parameter::Float(f) => Some(*f),
            _ => None,
        }
    }

    /// The value if it is a [`Parameter::Ints`].
    pub fn as_ints(&self) -> Option<&[i32]> {
        match self {
            Parameter::Ints(v) => Some(v),
            _ => None,
        }
    }

    /// The value if it is a [`Parameter::Floats`].
    pub fn as_floats(&self) -> Option<&[f32]> {
        match self {
            Parameter::Floats(v) => Some(v),
            _ => None,
        }
    }

    /// The value if it is a [`Parameter::String`].
    pub fn as_str(&self) -> Option<&str> {
        match self {
            Parameter::String(s) => Some(s),
            _ => None,
        }
    }
}

/// `VERSION` (WebGL requires the `"WebGL 2.0"` prefix).
pub const VERSION: &str = "WebGL 2.0 (essl-gl)";
/// `SHADING_LANGUAGE_VERSION` (WebGL requires the `"WebGL GLSL ES 3.00"` prefix).
pub const SHADING_LANGUAGE_VERSION: &str = "WebGL GLSL ES 3.00 (essl)";
/// `VENDOR`.
pub const VENDOR: &str = "essl";
/// Bits of sub-pixel precision reported as `SUBPIXEL_BITS` (Vulkan's minimum is 4; lavapipe
/// has 8).
pub const SUBPIXEL_BITS: i64 = 8;

impl Context {
    /// A shader's parameter (`getShaderParameter`): `SHADER_TYPE` ([`Parameter::Enum`]),
    /// `COMPILE_STATUS` and `DELETE_STATUS` ([`Parameter::Bool`]).
    ///
    /// Another `pname` → `INVALID_ENUM` (WebGL dropped GL's `INFO_LOG_LENGTH` and
    /// `SHADER_SOURCE_LENGTH`); a shader that no longer exists → `INVALID_VALUE`; one of another
    /// context → `INVALID_OPERATION`; all return `None`. A shader marked for deletion but
    /// still attached to a program can be queried (`DELETE_STATUS` is then true).
    pub fn get_shader_parameter(&self, shader: Shader, pname: u32) -> Option<Parameter> {
        const F: &str = "getShaderParameter";
        let id = self.shader_id(shader, F)?;
        let s = self.objects.shaders.get_any(id)?;
        match pname {
            gl::SHADER_TYPE => Some(Parameter::Enum(s.ty)),
            gl::COMPILE_STATUS => Some(Parameter::Bool(
                s.compiled.as_ref().is_some_and(|(_, ok)| *ok),
            )),
            gl::DELETE_STATUS => Some(Parameter::Bool(self.objects.shaders.is_marked_deleted(id))),
            _ => {
                self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
                None
            }
        }
    }

    /// A program's parameter (`getProgramParameter`): `LINK_STATUS`, `DELETE_STATUS`,
    /// `VALIDATE_STATUS` ([`Parameter::Bool`]); `ATTACHED_SHADERS`, `ACTIVE_UNIFORMS`,
    /// `ACTIVE_ATTRIBUTES`, `ACTIVE_UNIFORM_BLOCKS`, `TRANSFORM_FEEDBACK_VARYINGS`
    /// ([`Parameter::Int`]; the active counts are 0 unless the last link succeeded);
    /// `TRANSFORM_FEEDBACK_BUFFER_MODE` ([`Parameter::Enum`]).
    ///
    /// Another `pname` → `INVALID_ENUM`; a program that no longer exists → `INVALID_VALUE`;
    /// one of another context → `INVALID_OPERATION`; all return `None`. A deleted program
    /// that is still current can be queried (`DELETE_STATUS` is then true).
    pub fn get_program_parameter(&self, program: Program, pname: u32) -> Option<Parameter> {
        const F: &str = "getProgramParameter";
        let id = self.program_id(program, F)?;
        let p = self.objects.programs.get_any(id)?;
        let active = |n: fn(&essl::program::ProgramLayout) -> usize| {
            Parameter::Int(p.linked.as_ref().map_or(0, |l| n(&l.layout)) as i64)
        };
        match pname {
            gl::LINK_STATUS => Some(Parameter::Bool(p.link_status)),
            gl::DELETE_STATUS => Some(Parameter::Bool(self.objects.programs.is_marked_deleted(id))),
            gl::VALIDATE_STATUS => Some(Parameter::Bool(p.validate_status)),
            gl::ATTACHED_SHADERS => Some(Parameter::Int(p.attached.len() as i64)),
            gl::ACTIVE_UNIFORMS => Some(active(|l| l.uniforms.len())),
            gl::ACTIVE_ATTRIBUTES => Some(active(|l| l.attributes.len())),
            gl::ACTIVE_UNIFORM_BLOCKS => Some(active(|l| l.blocks.len())),
            gl::TRANSFORM_FEEDBACK_VARYINGS => Some(Parameter::Int(
                p.linked
                    .as_ref()
                    .and_then(|l| l.feedback.as_ref())
                    .map_or(0, |f| f.varyings.len()) as i64,
            )),
            gl::TRANSFORM_FEEDBACK_BUFFER_MODE => Some(Parameter::Enum(
                p.linked
                    .as_ref()
                    .and_then(|l| l.feedback.as_ref())
                    .map_or(p.feedback_varyings.1, |f| f.mode),
            )),
            _ => {
                self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
                None
            }
        }
    }

    /// Checks whether the program could draw with the current state (`validateProgram`) and
    /// stores the answer as `VALIDATE_STATUS`, with the reason in the info log (which it
    /// replaces, as ANGLE does). A program fails when its last link failed or when samplers
    /// of different types read the same texture unit.
    pub fn validate_program(&mut self, program: Program) {
        let Some(id) = self.program_id(program, "validateProgram") else {
            return;
        };
        let p = self.objects.programs.get_any_mut(id).expect("checked");
        let problem = match &p.linked {
            Some(linked) if p.link_status => sampler_conflict(linked),
            _ => Some("Program has not been successfully linked.".to_owned()),
        };
        p.validate_status = problem.is_none();
        p.info_log = problem.unwrap_or_default();
    }
}

/// Why a linked program cannot draw with its sampler units, if it cannot: samplers of
/// different types on one texture unit.
fn sampler_conflict(linked: &crate::program::LinkedProgram) -> Option<String> {
    let samplers = &linked.layout.samplers;
    for (i, a) in samplers.iter().enumerate() {
        for (j, b) in samplers.iter().enumerate().skip(i + 1) {
            let (ua, ub) = (linked.sampler_units[i], linked.sampler_units[j]);
            if ua == ub && a.ty != b.ty {
                return Some(format!(
                    "Samplers of conflicting types refer to the same texture image unit ({ua})."
                ));
            }
        }
    }
    None
}
