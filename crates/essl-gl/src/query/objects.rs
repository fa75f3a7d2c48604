//! Queries about objects and formats: `get_buffer_parameter`, `get_indexed_parameter`,
//! `get_internalformat_parameter`, `get_shader_precision_format`, `get_vertex_attrib` and
//! `get_vertex_attrib_offset`.

use super::Parameter;
use crate::context::Context;
use crate::gl;
use crate::objects::Buffer;
use crate::vertex_array::GenericAttrib;

/// What `get_shader_precision_format` returns (`WebGLShaderPrecisionFormat`): the log2 of the
/// range's ends and the bits of precision.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShaderPrecisionFormat {
    /// log2 of the magnitude of the smallest representable value (the range's low end).
    pub range_min: i32,
    /// log2 of the magnitude of the largest representable value.
    pub range_max: i32,
    /// Bits of precision (0 for integers).
    pub precision: i32,
}

impl Context {
    /// A parameter of the buffer bound to `target` (`getBufferParameter`): `BUFFER_SIZE`
    /// ([`Parameter::Int`]) or `BUFFER_USAGE` ([`Parameter::Enum`]).
    pub fn get_buffer_parameter(&self, target: u32, pname: u32) -> Option<Parameter> {
        const F: &str = "getBufferParameter";
        if self.webgl1_refuses("getBufferParameter", &[target, pname]) {
            return None;
        }
        if !matches!(pname, gl::BUFFER_SIZE | gl::BUFFER_USAGE) {
            self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
            return None;
        }
        let id = self.bound_buffer(target, F)?;
        let b = self.objects.buffers.get_any(id)?;
        Some(match pname {
            gl::BUFFER_SIZE => Parameter::Int(b.len() as i64),
            _ => Parameter::Enum(b.usage()),
        })
    }

    /// An indexed binding (`getIndexedParameter`): `UNIFORM_BUFFER_BINDING`,
    /// `UNIFORM_BUFFER_START`, `UNIFORM_BUFFER_SIZE`, and the same of
    /// `TRANSFORM_FEEDBACK_BUFFER_…` (of the bound transform feedback object). An index out
    /// of range → `INVALID_VALUE`.
    pub fn get_indexed_parameter(&self, target: u32, index: u32) -> Option<Parameter> {
        const F: &str = "getIndexedParameter";
        if let Some(p) = self.indexed_blend_parameter(target, index) {
            return p;
        }
        let range = match target {
            gl::UNIFORM_BUFFER_BINDING | gl::UNIFORM_BUFFER_START | gl::UNIFORM_BUFFER_SIZE => {
                if index >= crate::context::MAX_UNIFORM_BUFFER_BINDINGS {
                    self.error(gl::INVALID_VALUE, F, "index out of range");
                    return None;
                }
                self.bindings.uniform_range(index as usize)
            }
            gl::TRANSFORM_FEEDBACK_BUFFER_BINDING
            | gl::TRANSFORM_FEEDBACK_BUFFER_START
            | gl::TRANSFORM_FEEDBACK_BUFFER_SIZE => {
                if index >= crate::program::feedback_max_buffers() {
                    self.error(gl::INVALID_VALUE, F, "index out of range");
                    return None;
                }
                self.feedback_object().buffers[index as usize]
            }
            _ => {
                self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
                return None;
            }
        };
        Some(match target {
            gl::UNIFORM_BUFFER_BINDING | gl::TRANSFORM_FEEDBACK_BUFFER_BINDING => {
                Parameter::Buffer(range.map(|r| Buffer {
                    ctx: self.id,
                    id: r.buffer,
                }))
            }
            gl::UNIFORM_BUFFER_START | gl::TRANSFORM_FEEDBACK_BUFFER_START => {
                Parameter::Int(range.map_or(0, |r| r.offset as i64))
            }
            _ => Parameter::Int(range.and_then(|r| r.size).unwrap_or(0) as i64),
        })
    }

    /// What an internal format allows (`getInternalformatParameter`): `SAMPLES` of a
    /// renderable format for `RENDERBUFFER`, largest first ([`Parameter::Ints`]; empty for
    /// integer formats). Another target or pname, or a format that cannot be rendered →
    /// `INVALID_ENUM`.
    pub fn get_internalformat_parameter(
        &self,
        target: u32,
        internalformat: u32,
        pname: u32,
    ) -> Option<Parameter> {
        const F: &str = "getInternalformatParameter";
        if target != gl::RENDERBUFFER {
            self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
            return None;
        }
        if pname != gl::SAMPLES {
            self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
            return None;
        }
        let float_ok = self.extensions.color_buffer_float;
        let format = crate::texture::internal_format(internalformat)
            .ok()
            .filter(|f| f.color_renderable(float_ok) || f.depth_stencil_renderable())
            .filter(|_| !matches!(internalformat, gl::RGBA | gl::RGB));
        let Some(format) = format else {
            self.error(
                gl::INVALID_ENUM,
                F,
                format_args!("internal format 0x{internalformat:04X}"),
            );
            return None;
        };
        Some(Parameter::Ints(
            self.format_samples(&format)
                .into_iter()
                .map(|s| s as i32)
                .collect(),
        ))
    }

    /// The range and precision of a precision qualifier in a stage
    /// (`getShaderPrecisionFormat`). essl-gl computes every float at 32 bits and every int
    /// at 32 bits, whatever the qualifier, and says so.
    pub fn get_shader_precision_format(
        &self,
        shader_type: u32,
        precision_type: u32,
    ) -> Option<ShaderPrecisionFormat> {
        const F: &str = "getShaderPrecisionFormat";
        if !matches!(shader_type, gl::VERTEX_SHADER | gl::FRAGMENT_SHADER) {
            self.error(
                gl::INVALID_ENUM,
                F,
                format_args!("shader type 0x{shader_type:04X}"),
            );
            return None;
        }
        match precision_type {
            gl::LOW_FLOAT | gl::MEDIUM_FLOAT | gl::HIGH_FLOAT => Some(ShaderPrecisionFormat {
                range_min: 127,
                range_max: 127,
                precision: 23,
            }),
            gl::LOW_INT | gl::MEDIUM_INT | gl::HIGH_INT => Some(ShaderPrecisionFormat {
                range_min: 31,
                range_max: 30,
                precision: 0,
            }),
            _ => {
                self.error(
                    gl::INVALID_ENUM,
                    F,
                    format_args!("precision type 0x{precision_type:04X}"),
                );
                None
            }
        }
    }

    /// A property of vertex attribute `index` of the bound vertex array
    /// (`getVertexAttrib`): `VERTEX_ATTRIB_ARRAY_BUFFER_BINDING` ([`Parameter::Buffer`]),
    /// `…_ENABLED`, `…_NORMALIZED`, `…_INTEGER` ([`Parameter::Bool`]), `…_SIZE`, `…_STRIDE`,
    /// `…_DIVISOR` ([`Parameter::Int`]), `…_TYPE` ([`Parameter::Enum`]) and
    /// `CURRENT_VERTEX_ATTRIB` (the generic value: floats, ints or uints).
    pub fn get_vertex_attrib(&self, index: u32, pname: u32) -> Option<Parameter> {
        const F: &str = "getVertexAttrib";
        if self.webgl1_refuses("getVertexAttrib", &[pname]) {
            return None;
        }
        if index >= self.limits.max_vertex_attribs {
            self.error(gl::INVALID_VALUE, F, "index ≥ MAX_VERTEX_ATTRIBS");
            return None;
        }
        let a = self.vao().attribs[index as usize].clone();
        Some(match pname {
            gl::VERTEX_ATTRIB_ARRAY_BUFFER_BINDING => {
                Parameter::Buffer(a.buffer.map(|id| Buffer { ctx: self.id, id }))
            }
            gl::VERTEX_ATTRIB_ARRAY_ENABLED => Parameter::Bool(a.enabled),
            gl::VERTEX_ATTRIB_ARRAY_NORMALIZED => Parameter::Bool(a.normalized),
            gl::VERTEX_ATTRIB_ARRAY_INTEGER => Parameter::Bool(a.integer),
            gl::VERTEX_ATTRIB_ARRAY_SIZE => Parameter::Int(a.size as i64),
            gl::VERTEX_ATTRIB_ARRAY_STRIDE => Parameter::Int(a.stride as i64),
            gl::VERTEX_ATTRIB_ARRAY_DIVISOR => Parameter::Int(a.divisor as i64),
            gl::VERTEX_ATTRIB_ARRAY_TYPE => Parameter::Enum(a.ty),
            gl::CURRENT_VERTEX_ATTRIB => match self.state.generic_attribs[index as usize] {
                GenericAttrib::Float(v) => Parameter::Floats(v.to_vec()),
                GenericAttrib::Int(v) => Parameter::Ints(v.to_vec()),
                GenericAttrib::Uint(v) => Parameter::Uints(v.to_vec()),
            },
            _ => {
                self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
                return None;
            }
        })
    }

    /// The byte offset of vertex attribute `index`'s array (`getVertexAttribOffset`); `pname`
    /// must be `VERTEX_ATTRIB_ARRAY_POINTER`.
    pub fn get_vertex_attrib_offset(&self, index: u32, pname: u32) -> i64 {
        const F: &str = "getVertexAttribOffset";
        if pname != gl::VERTEX_ATTRIB_ARRAY_POINTER {
            self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
            return 0;
        }
        if index >= self.limits.max_vertex_attribs {
            self.error(gl::INVALID_VALUE, F, "index ≥ MAX_VERTEX_ATTRIBS");
            return 0;
        }
        self.vao().attribs[index as usize].offset as i64
    }
}
