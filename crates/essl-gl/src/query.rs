//! State queries with WebGL's names: `get_parameter`, `get_shader_parameter`,
//! `get_program_parameter` and `validate_program`, returning a [`Parameter`].
//!
//! WebGL's queries return "any" (a boolean, a number, a typed array, an object or `null`);
//! [`Parameter`] is that value in Rust. An unknown `pname` records `INVALID_ENUM` and returns
//! `None`, as WebGL returns `null`.

use crate::context::{Context, MAX_TEXTURE_UNITS, MAX_UNIFORM_BUFFER_BINDINGS};
use crate::gl;
use crate::objects::{Buffer, Id, Program, Shader, Texture, VertexArray};

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
    /// `null` for a binding of an object kind essl-gl does not have (`FRAMEBUFFER_BINDING`,
    /// `RENDERBUFFER_BINDING`: always the default framebuffer, no renderbuffer).
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
    pub fn get_shader_parameter(&mut self, shader: Shader, pname: u32) -> Option<Parameter> {
        const F: &str = "getShaderParameter";
        let id = self.shader_id(shader, F)?;
        let s = self.shaders.get_any(id)?;
        match pname {
            gl::SHADER_TYPE => Some(Parameter::Enum(s.ty)),
            gl::COMPILE_STATUS => Some(Parameter::Bool(
                s.compiled.as_ref().is_some_and(|(_, ok)| *ok),
            )),
            gl::DELETE_STATUS => Some(Parameter::Bool(self.shaders.is_marked_deleted(id))),
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
    /// `TRANSFORM_FEEDBACK_BUFFER_MODE` ([`Parameter::Enum`], always `SEPARATE_ATTRIBS`).
    ///
    /// Another `pname` → `INVALID_ENUM`; a program that no longer exists → `INVALID_VALUE`;
    /// one of another context → `INVALID_OPERATION`; all return `None`. A deleted program
    /// that is still current can be queried (`DELETE_STATUS` is then true).
    pub fn get_program_parameter(&mut self, program: Program, pname: u32) -> Option<Parameter> {
        const F: &str = "getProgramParameter";
        let id = self.program_id(program, F)?;
        let p = self.programs.get_any(id)?;
        let active = |n: fn(&essl::program::ProgramLayout) -> usize| {
            Parameter::Int(p.linked.as_ref().map_or(0, |l| n(&l.layout)) as i64)
        };
        match pname {
            gl::LINK_STATUS => Some(Parameter::Bool(p.link_status)),
            gl::DELETE_STATUS => Some(Parameter::Bool(self.programs.is_marked_deleted(id))),
            gl::VALIDATE_STATUS => Some(Parameter::Bool(p.validate_status)),
            gl::ATTACHED_SHADERS => Some(Parameter::Int(p.attached.len() as i64)),
            gl::ACTIVE_UNIFORMS => Some(active(|l| l.uniforms.len())),
            gl::ACTIVE_ATTRIBUTES => Some(active(|l| l.attributes.len())),
            gl::ACTIVE_UNIFORM_BLOCKS => Some(active(|l| l.blocks.len())),
            gl::TRANSFORM_FEEDBACK_VARYINGS => Some(Parameter::Int(0)),
            gl::TRANSFORM_FEEDBACK_BUFFER_MODE => Some(Parameter::Enum(gl::SEPARATE_ATTRIBS)),
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
        let p = self.programs.get_any_mut(id).expect("checked");
        let problem = match &p.linked {
            Some(linked) if p.link_status => sampler_conflict(linked),
            _ => Some("Program has not been successfully linked.".to_owned()),
        };
        p.validate_status = problem.is_none();
        p.info_log = problem.unwrap_or_default();
    }

    fn handle_buffer(&self, id: Option<Id>) -> Parameter {
        Parameter::Buffer(id.map(|id| Buffer { ctx: self.id, id }))
    }

    fn handle_texture(&self, target: u32) -> Parameter {
        let id = self.texture_units[self.active_texture as usize].get(target);
        Parameter::Texture(id.map(|id| Texture { ctx: self.id, id }))
    }

    /// A value of the context's state (`getParameter`).
    ///
    /// Supported: the viewport, scissor, clear, depth, culling, blending, colour-mask,
    /// polygon-offset and line-width state and the capabilities (`BLEND`, `DEPTH_TEST`, …);
    /// the bindings (`CURRENT_PROGRAM`, `ARRAY_BUFFER_BINDING`, `ELEMENT_ARRAY_BUFFER_BINDING`,
    /// `COPY_*_BUFFER_BINDING`, `UNIFORM_BUFFER_BINDING`, `VERTEX_ARRAY_BINDING`,
    /// `ACTIVE_TEXTURE`, `TEXTURE_BINDING_*`; `FRAMEBUFFER_BINDING` and friends are
    /// [`Parameter::Null`]); pixel storage (`UNPACK_ALIGNMENT`, `PACK_ALIGNMENT`, …); the
    /// default framebuffer's bit depths (8-bit RGBA, 24-bit depth, no stencil, no
    /// multisampling); stencil state (its defaults: essl-gl has no stencil buffer); the
    /// limits (`MAX_TEXTURE_SIZE`, `MAX_VERTEX_ATTRIBS`, `MAX_COMBINED_TEXTURE_IMAGE_UNITS`,
    /// `MAX_VIEWPORT_DIMS`, `MAX_UNIFORM_BUFFER_BINDINGS`, `UNIFORM_BUFFER_OFFSET_ALIGNMENT`,
    /// …, from the device's limits); and the strings `VERSION`, `SHADING_LANGUAGE_VERSION`,
    /// `VENDOR`, `RENDERER`.
    ///
    /// Another `pname` → `INVALID_ENUM` and `None`.
    pub fn get_parameter(&mut self, pname: u32) -> Option<Parameter> {
        use Parameter::{Bool, Enum, Float, Floats, Int, Ints};
        let s = &self.state;
        let l = &self.gpu.limits;
        let uniform_vectors = (l.max_uniform_buffer_binding_size / 16).min(4096) as i64;
        let blocks = l.max_uniform_buffers_per_shader_stage.saturating_sub(1) as i64;
        let image_units = l
            .max_sampled_textures_per_shader_stage
            .min(MAX_TEXTURE_UNITS) as i64;
        let varyings = l.max_inter_stage_shader_variables as i64;
        let p = &self.pixel_store;
        let value = match pname {
            // Viewport, scissor and clearing.
            gl::VIEWPORT => Ints(s.viewport.to_vec()),
            gl::SCISSOR_BOX => Ints(s.scissor.to_vec()),
            gl::COLOR_CLEAR_VALUE => Floats(s.clear_color.to_vec()),
            gl::DEPTH_CLEAR_VALUE => Float(s.clear_depth),
            gl::STENCIL_CLEAR_VALUE => Int(s.clear_stencil as i64),
            // Depth, culling, blending, masks.
            gl::DEPTH_FUNC => Enum(s.depth_func),
            gl::DEPTH_WRITEMASK => Bool(s.depth_mask),
            gl::DEPTH_RANGE => Floats(s.depth_range.to_vec()),
            gl::CULL_FACE_MODE => Enum(s.cull_face_mode),
            gl::FRONT_FACE => Enum(s.front_face),
            gl::BLEND_SRC_RGB => Enum(s.blend_src_rgb),
            gl::BLEND_DST_RGB => Enum(s.blend_dst_rgb),
            gl::BLEND_SRC_ALPHA => Enum(s.blend_src_alpha),
            gl::BLEND_DST_ALPHA => Enum(s.blend_dst_alpha),
            gl::BLEND_EQUATION_RGB => Enum(s.blend_equation_rgb),
            gl::BLEND_EQUATION_ALPHA => Enum(s.blend_equation_alpha),
            gl::BLEND_COLOR => Floats(s.blend_color.to_vec()),
            gl::COLOR_WRITEMASK => Parameter::Bools(s.color_mask.to_vec()),
            gl::POLYGON_OFFSET_FACTOR => Float(s.polygon_offset_factor),
            gl::POLYGON_OFFSET_UNITS => Float(s.polygon_offset_units),
            gl::LINE_WIDTH => Float(s.line_width),
            gl::BLEND => Bool(s.blend),
            gl::CULL_FACE => Bool(s.cull_face),
            gl::DEPTH_TEST => Bool(s.depth_test),
            gl::DITHER => Bool(s.dither),
            gl::POLYGON_OFFSET_FILL => Bool(s.polygon_offset_fill),
            gl::RASTERIZER_DISCARD => Bool(s.rasterizer_discard),
            gl::SAMPLE_ALPHA_TO_COVERAGE => Bool(s.sample_alpha_to_coverage),
            gl::SAMPLE_COVERAGE => Bool(s.sample_coverage),
            gl::SCISSOR_TEST => Bool(s.scissor_test),
            gl::STENCIL_TEST => Bool(s.stencil_test),
            gl::SAMPLE_COVERAGE_VALUE => Float(1.0),
            gl::SAMPLE_COVERAGE_INVERT => Bool(false),
            // Stencil state keeps GL's initial values: there is no stencil buffer to use it.
            gl::STENCIL_FUNC | gl::STENCIL_BACK_FUNC => Enum(gl::ALWAYS),
            gl::STENCIL_FAIL
            | gl::STENCIL_PASS_DEPTH_FAIL
            | gl::STENCIL_PASS_DEPTH_PASS
            | gl::STENCIL_BACK_FAIL
            | gl::STENCIL_BACK_PASS_DEPTH_FAIL
            | gl::STENCIL_BACK_PASS_DEPTH_PASS => Enum(gl::KEEP),
            gl::STENCIL_REF | gl::STENCIL_BACK_REF => Int(0),
            gl::STENCIL_VALUE_MASK
            | gl::STENCIL_WRITEMASK
            | gl::STENCIL_BACK_VALUE_MASK
            | gl::STENCIL_BACK_WRITEMASK => Int(u32::MAX as i64),
            // Bindings.
            gl::CURRENT_PROGRAM => Parameter::Program(self.get_current_program()),
            gl::ARRAY_BUFFER_BINDING => self.handle_buffer(self.array_buffer),
            gl::ELEMENT_ARRAY_BUFFER_BINDING => self.handle_buffer(self.vao().element_buffer),
            gl::COPY_READ_BUFFER_BINDING => self.handle_buffer(self.copy_read_buffer),
            gl::COPY_WRITE_BUFFER_BINDING => self.handle_buffer(self.copy_write_buffer),
            gl::UNIFORM_BUFFER_BINDING => self.handle_buffer(self.uniform_buffer),
            gl::PIXEL_PACK_BUFFER_BINDING
            | gl::PIXEL_UNPACK_BUFFER_BINDING
            | gl::TRANSFORM_FEEDBACK_BUFFER_BINDING => Parameter::Buffer(None),
            gl::VERTEX_ARRAY_BINDING => {
                Parameter::VertexArray(self.bound_vao.map(|id| VertexArray { ctx: self.id, id }))
            }
            gl::ACTIVE_TEXTURE => Enum(gl::TEXTURE0 + self.active_texture),
            gl::TEXTURE_BINDING_2D => self.handle_texture(gl::TEXTURE_2D),
            gl::TEXTURE_BINDING_CUBE_MAP => self.handle_texture(gl::TEXTURE_CUBE_MAP),
            gl::TEXTURE_BINDING_3D => self.handle_texture(gl::TEXTURE_3D),
            gl::TEXTURE_BINDING_2D_ARRAY => self.handle_texture(gl::TEXTURE_2D_ARRAY),
            gl::FRAMEBUFFER_BINDING | gl::READ_FRAMEBUFFER_BINDING | gl::RENDERBUFFER_BINDING => {
                Parameter::Null
            }
            // Pixel storage.
            gl::UNPACK_ALIGNMENT => Int(p.unpack_alignment as i64),
            gl::PACK_ALIGNMENT => Int(p.pack_alignment as i64),
            gl::UNPACK_ROW_LENGTH => Int(p.unpack_row_length as i64),
            gl::UNPACK_SKIP_ROWS => Int(p.unpack_skip_rows as i64),
            gl::UNPACK_SKIP_PIXELS => Int(p.unpack_skip_pixels as i64),
            gl::UNPACK_IMAGE_HEIGHT => Int(p.unpack_image_height as i64),
            gl::UNPACK_SKIP_IMAGES => Int(p.unpack_skip_images as i64),
            gl::PACK_ROW_LENGTH => Int(p.pack_row_length as i64),
            gl::PACK_SKIP_ROWS => Int(p.pack_skip_rows as i64),
            gl::PACK_SKIP_PIXELS => Int(p.pack_skip_pixels as i64),
            gl::UNPACK_FLIP_Y_WEBGL => Bool(p.unpack_flip_y),
            gl::UNPACK_PREMULTIPLY_ALPHA_WEBGL => Bool(p.unpack_premultiply_alpha),
            gl::UNPACK_COLORSPACE_CONVERSION_WEBGL => Enum(p.unpack_colorspace_conversion),
            // The default framebuffer.
            gl::RED_BITS | gl::GREEN_BITS | gl::BLUE_BITS | gl::ALPHA_BITS => Int(8),
            gl::DEPTH_BITS => Int(24),
            gl::STENCIL_BITS | gl::SAMPLES | gl::SAMPLE_BUFFERS => Int(0),
            gl::SUBPIXEL_BITS => Int(SUBPIXEL_BITS),
            gl::IMPLEMENTATION_COLOR_READ_FORMAT => Enum(gl::RGBA),
            gl::IMPLEMENTATION_COLOR_READ_TYPE => Enum(gl::UNSIGNED_BYTE),
            // Limits.
            gl::MAX_TEXTURE_SIZE | gl::MAX_CUBE_MAP_TEXTURE_SIZE | gl::MAX_RENDERBUFFER_SIZE => {
                Int(l.max_texture_dimension_2d as i64)
            }
            gl::MAX_3D_TEXTURE_SIZE => Int(l.max_texture_dimension_3d as i64),
            gl::MAX_ARRAY_TEXTURE_LAYERS => Int(l.max_texture_array_layers as i64),
            gl::MAX_VIEWPORT_DIMS => Ints(vec![l.max_texture_dimension_2d as i32; 2]),
            gl::MAX_VERTEX_ATTRIBS => Int(self.max_vertex_attribs as i64),
            gl::MAX_COMBINED_TEXTURE_IMAGE_UNITS => Int(MAX_TEXTURE_UNITS as i64),
            gl::MAX_TEXTURE_IMAGE_UNITS | gl::MAX_VERTEX_TEXTURE_IMAGE_UNITS => Int(image_units),
            gl::MAX_VERTEX_UNIFORM_VECTORS | gl::MAX_FRAGMENT_UNIFORM_VECTORS => {
                Int(uniform_vectors)
            }
            gl::MAX_VERTEX_UNIFORM_COMPONENTS | gl::MAX_FRAGMENT_UNIFORM_COMPONENTS => {
                Int(uniform_vectors * 4)
            }
            gl::MAX_VARYING_VECTORS => Int(varyings),
            gl::MAX_VARYING_COMPONENTS
            | gl::MAX_VERTEX_OUTPUT_COMPONENTS
            | gl::MAX_FRAGMENT_INPUT_COMPONENTS => Int(varyings * 4),
            gl::MAX_UNIFORM_BUFFER_BINDINGS => Int(MAX_UNIFORM_BUFFER_BINDINGS as i64),
            gl::MAX_UNIFORM_BLOCK_SIZE => Int(l.max_uniform_buffer_binding_size as i64),
            gl::MAX_VERTEX_UNIFORM_BLOCKS | gl::MAX_FRAGMENT_UNIFORM_BLOCKS => Int(blocks),
            gl::MAX_COMBINED_UNIFORM_BLOCKS => Int(blocks * 2),
            gl::UNIFORM_BUFFER_OFFSET_ALIGNMENT => {
                Int(self.uniform_buffer_offset_alignment() as i64)
            }
            gl::MAX_ELEMENT_INDEX => Int(u32::MAX as i64),
            gl::MAX_DRAW_BUFFERS | gl::MAX_COLOR_ATTACHMENTS => Int(1),
            gl::ALIASED_LINE_WIDTH_RANGE | gl::ALIASED_POINT_SIZE_RANGE => Floats(vec![1.0, 1.0]),
            // Strings.
            gl::VERSION => Parameter::String(VERSION.to_owned()),
            gl::SHADING_LANGUAGE_VERSION => Parameter::String(SHADING_LANGUAGE_VERSION.to_owned()),
            gl::VENDOR => Parameter::String(VENDOR.to_owned()),
            gl::RENDERER => Parameter::String(format!("essl-gl on {}", self.gpu.info.name)),
            _ => {
                self.error(
                    gl::INVALID_ENUM,
                    "getParameter",
                    format_args!("pname 0x{pname:04X}"),
                );
                return None;
            }
        };
        Some(value)
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
