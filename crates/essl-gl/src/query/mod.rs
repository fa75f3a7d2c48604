//! State queries with WebGL's names: `get_parameter` ([`parameter`]), `get_shader_parameter`,
//! `get_program_parameter` and `validate_program` ([`program`]), and the parameters of
//! objects ([`objects`]), returning a [`Parameter`], which this file defines.
//!
//! WebGL's queries return "any" (a boolean, a number, a typed array, an object or `null`);
//! [`Parameter`] is that value in Rust. An unknown `pname` records `INVALID_ENUM` and returns
//! `None`, as WebGL returns `null`.

mod objects;
mod parameter;
mod point_size;
mod program;

pub use objects::ShaderPrecisionFormat;

use crate::objects::{Buffer, Program, Texture, VertexArray};

/// A value returned by [`Context::get_parameter`](crate::Context::get_parameter),
/// [`Context::get_shader_parameter`](crate::Context::get_shader_parameter) and
/// [`Context::get_program_parameter`](crate::Context::get_program_parameter): what WebGL's
/// `any` holds for that `pname`.
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
/// `VERSION` of a WebGL 1 context.
pub const VERSION_1: &str = "WebGL 1.0 (essl-gl)";
/// `SHADING_LANGUAGE_VERSION` of a WebGL 1 context.
pub const SHADING_LANGUAGE_VERSION_1: &str = "WebGL GLSL ES 1.0 (essl)";
/// `VENDOR`.
pub const VENDOR: &str = "essl";
/// Bits of sub-pixel precision reported as `SUBPIXEL_BITS` (Vulkan's minimum is 4; lavapipe
/// has 8).
pub const SUBPIXEL_BITS: i64 = 8;
