//! `get_parameter`: the context's state by `pname`, one function per family (fixed-function
//! state, bindings, pixel storage, the framebuffer, limits and strings).

use super::{Parameter, SHADING_LANGUAGE_VERSION, SUBPIXEL_BITS, VENDOR, VERSION};
use crate::context::{Context, MAX_TEXTURE_UNITS, MAX_UNIFORM_BUFFER_BINDINGS};
use crate::gl;
use crate::objects::{Buffer, Id, Texture, VertexArray};
use crate::state::draw_buffer_parameter;

impl Context {
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
    pub fn get_parameter(&self, pname: u32) -> Option<Parameter> {
        if self.webgl1_refuses("getParameter", &[pname]) {
            return None;
        }
        if self.webgl1.on {
            match pname {
                gl::VERSION => return Some(Parameter::String(super::VERSION_1.into())),
                gl::SHADING_LANGUAGE_VERSION => {
                    return Some(Parameter::String(super::SHADING_LANGUAGE_VERSION_1.into()))
                }
                _ => {}
            }
        }
        if matches!(
            pname,
            gl::IMPLEMENTATION_COLOR_READ_FORMAT | gl::IMPLEMENTATION_COLOR_READ_TYPE
        ) && self.read_framebuffer_incomplete()
        {
            self.error(
                gl::INVALID_OPERATION,
                "getParameter",
                "the read framebuffer is incomplete",
            );
            return None;
        }
        if pname == gl::COMPRESSED_TEXTURE_FORMATS {
            return Some(Parameter::Uints(self.compressed_formats()));
        }
        if pname == crate::extensions::MAX_TEXTURE_MAX_ANISOTROPY_EXT && self.extensions.anisotropic
        {
            return Some(Parameter::Float(crate::extensions::MAX_ANISOTROPY));
        }
        let value = self
            .state_parameter(pname)
            .or_else(|| self.clip_distance_parameter(pname))
            .or_else(|| self.clip_control_parameter(pname))
            .or_else(|| self.raster_parameter(pname))
            .or_else(|| self.binding_parameter(pname))
            .or_else(|| self.pixel_store_parameter(pname))
            .or_else(|| self.framebuffer_parameter(pname))
            .or_else(|| self.limit_parameter(pname));
        // WebGL 1 names half floats by OES_texture_half_float's HALF_FLOAT_OES.
        if self.webgl1.on && matches!(value, Some(Parameter::Enum(gl::HALF_FLOAT))) {
            return Some(Parameter::Enum(crate::webgl1::HALF_FLOAT_OES));
        }
        if value.is_none() {
            self.error(
                gl::INVALID_ENUM,
                "getParameter",
                format_args!("pname 0x{pname:04X}"),
            );
        }
        value
    }

    /// Fixed-function state and capabilities.
    fn state_parameter(&self, pname: u32) -> Option<Parameter> {
        use Parameter::{Bool, Enum, Float, Floats, Int, Ints};
        let s = &self.state;
        Some(match pname {
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
            // Blending and the colour mask: draw buffer 0's.
            gl::BLEND_SRC_RGB
            | gl::BLEND_DST_RGB
            | gl::BLEND_SRC_ALPHA
            | gl::BLEND_DST_ALPHA
            | gl::BLEND_EQUATION_RGB
            | gl::BLEND_EQUATION_ALPHA
            | gl::COLOR_WRITEMASK => return draw_buffer_parameter(&s.draw_buffers[0], pname),
            gl::BLEND_COLOR => Floats(s.blend_color.to_vec()),
            gl::POLYGON_OFFSET_FACTOR => Float(s.polygon_offset_factor),
            gl::POLYGON_OFFSET_UNITS => Float(s.polygon_offset_units),
            gl::LINE_WIDTH => Float(s.line_width),
            gl::BLEND => Bool(s.draw_buffers[0].blend),
            gl::CULL_FACE => Bool(s.cull_face),
            gl::DEPTH_TEST => Bool(s.depth_test),
            gl::DITHER => Bool(s.dither),
            gl::POLYGON_OFFSET_FILL => Bool(s.polygon_offset_fill),
            gl::RASTERIZER_DISCARD => Bool(s.rasterizer_discard),
            gl::SAMPLE_ALPHA_TO_COVERAGE => Bool(s.sample_alpha_to_coverage),
            gl::SAMPLE_COVERAGE => Bool(s.sample_coverage),
            gl::SCISSOR_TEST => Bool(s.scissor_test),
            gl::STENCIL_TEST => Bool(s.stencil_test),
            gl::SAMPLE_COVERAGE_VALUE => Float(s.sample_coverage_value.0),
            gl::SAMPLE_COVERAGE_INVERT => Bool(s.sample_coverage_value.1),
            gl::GENERATE_MIPMAP_HINT => Enum(s.hints[0]),
            gl::FRAGMENT_SHADER_DERIVATIVE_HINT => Enum(s.hints[1]),
            gl::STENCIL_FUNC => Enum(s.stencil.func[0]),
            gl::STENCIL_BACK_FUNC => Enum(s.stencil.func[1]),
            gl::STENCIL_FAIL => Enum(s.stencil.fail[0]),
            gl::STENCIL_BACK_FAIL => Enum(s.stencil.fail[1]),
            gl::STENCIL_PASS_DEPTH_FAIL => Enum(s.stencil.depth_fail[0]),
            gl::STENCIL_BACK_PASS_DEPTH_FAIL => Enum(s.stencil.depth_fail[1]),
            gl::STENCIL_PASS_DEPTH_PASS => Enum(s.stencil.pass[0]),
            gl::STENCIL_BACK_PASS_DEPTH_PASS => Enum(s.stencil.pass[1]),
            gl::STENCIL_REF => Int(s.stencil.reference[0] as i64),
            gl::STENCIL_BACK_REF => Int(s.stencil.reference[1] as i64),
            gl::STENCIL_VALUE_MASK => Int(s.stencil.value_mask[0] as i64),
            gl::STENCIL_BACK_VALUE_MASK => Int(s.stencil.value_mask[1] as i64),
            gl::STENCIL_WRITEMASK => Int(s.stencil.writemask[0] as i64),
            gl::STENCIL_BACK_WRITEMASK => Int(s.stencil.writemask[1] as i64),
            _ => return None,
        })
    }

    /// What is bound.
    fn binding_parameter(&self, pname: u32) -> Option<Parameter> {
        use Parameter::Enum;
        Some(match pname {
            // Bindings.
            gl::CURRENT_PROGRAM => Parameter::Program(self.get_current_program()),
            gl::ARRAY_BUFFER_BINDING => self.handle_buffer(self.bindings.buffer(gl::ARRAY_BUFFER)),
            gl::ELEMENT_ARRAY_BUFFER_BINDING => self.handle_buffer(self.vao().element_buffer),
            gl::COPY_READ_BUFFER_BINDING => {
                self.handle_buffer(self.bindings.buffer(gl::COPY_READ_BUFFER))
            }
            gl::COPY_WRITE_BUFFER_BINDING => {
                self.handle_buffer(self.bindings.buffer(gl::COPY_WRITE_BUFFER))
            }
            gl::UNIFORM_BUFFER_BINDING => {
                self.handle_buffer(self.bindings.buffer(gl::UNIFORM_BUFFER))
            }
            gl::PIXEL_PACK_BUFFER_BINDING => {
                self.handle_buffer(self.bindings.buffer(gl::PIXEL_PACK_BUFFER))
            }
            gl::PIXEL_UNPACK_BUFFER_BINDING => {
                self.handle_buffer(self.bindings.buffer(gl::PIXEL_UNPACK_BUFFER))
            }
            gl::TRANSFORM_FEEDBACK_BUFFER_BINDING => {
                self.handle_buffer(self.bindings.buffer(gl::TRANSFORM_FEEDBACK_BUFFER))
            }
            gl::VERTEX_ARRAY_BINDING => Parameter::VertexArray(
                self.bindings
                    .vertex_array()
                    .map(|id| VertexArray { ctx: self.id, id }),
            ),
            gl::ACTIVE_TEXTURE => Enum(gl::TEXTURE0 + self.bindings.active_unit()),
            gl::TEXTURE_BINDING_2D => self.handle_texture(gl::TEXTURE_2D),
            gl::TEXTURE_BINDING_CUBE_MAP => self.handle_texture(gl::TEXTURE_CUBE_MAP),
            gl::TEXTURE_BINDING_3D => self.handle_texture(gl::TEXTURE_3D),
            gl::TEXTURE_BINDING_2D_ARRAY => self.handle_texture(gl::TEXTURE_2D_ARRAY),
            gl::FRAMEBUFFER_BINDING => Parameter::Framebuffer(
                self.bindings.framebuffers()[0].map(|id| crate::Framebuffer { ctx: self.id, id }),
            ),
            gl::READ_FRAMEBUFFER_BINDING => Parameter::Framebuffer(
                self.bindings.framebuffers()[1].map(|id| crate::Framebuffer { ctx: self.id, id }),
            ),
            gl::SAMPLER_BINDING => Parameter::Sampler(
                self.bindings
                    .sampler(self.bindings.active_unit())
                    .map(|id| crate::Sampler { ctx: self.id, id }),
            ),
            gl::TRANSFORM_FEEDBACK_BINDING => Parameter::TransformFeedback(
                self.bindings
                    .transform_feedback()
                    .map(|id| crate::TransformFeedback { ctx: self.id, id }),
            ),
            gl::TRANSFORM_FEEDBACK_ACTIVE => {
                Parameter::Bool(self.feedback_object().session.is_some())
            }
            gl::TRANSFORM_FEEDBACK_PAUSED => {
                Parameter::Bool(self.feedback_object().session.is_some_and(|s| s.paused))
            }
            gl::RENDERBUFFER_BINDING => Parameter::Renderbuffer(
                self.bindings
                    .renderbuffer()
                    .map(|id| crate::Renderbuffer { ctx: self.id, id }),
            ),
            _ => return None,
        })
    }

    /// Whether a framebuffer object is bound for reading and is not complete.
    fn read_framebuffer_incomplete(&self) -> bool {
        let [_, read] = self.bindings.framebuffers();
        read.is_some_and(|id| self.framebuffer_status(id) != gl::FRAMEBUFFER_COMPLETE)
    }

    /// What the bound framebuffers have: bit depths and samples of the draw framebuffer,
    /// the read format of the read buffer, the draw and read buffers.
    fn framebuffer_parameter(&self, pname: u32) -> Option<Parameter> {
        use Parameter::{Enum, Int};
        let [draw, read] = self.bindings.framebuffers();
        let formats = self.draw_formats();
        let color = formats.colors.first().copied().flatten();
        let bits = color
            .map(|f| crate::texture::bit_sizes(&f))
            .unwrap_or_default();
        // Depth bits from the depth attachment, stencil bits from the stencil one: a
        // depth-and-stencil image at only one of them gives that one's bits alone.
        let fbo = draw.and_then(|id| self.objects.framebuffers.get_any(id));
        let bits_at = |a: Option<_>| {
            a.and_then(|a| self.image_info(a))
                .map(|i| crate::texture::bit_sizes(&i.format))
                .unwrap_or_default()
        };
        let ds = crate::texture::BitSizes {
            depth: bits_at(fbo.and_then(|f| f.depth)).depth,
            stencil: bits_at(fbo.and_then(|f| f.stencil)).stencil,
            ..Default::default()
        };
        let (depth_bits, stencil_bits, samples) = match draw {
            Some(id) => {
                let f = self.objects.framebuffers.get_any(id)?;
                let samples = f
                    .attachments()
                    .find_map(|(_, a)| self.image_info(a))
                    .map_or(0, |i| i.samples);
                (ds.depth, ds.stencil, samples)
            }
            None => {
                let a = &self.fb.attributes;
                (
                    if a.depth { 24 } else { 0 },
                    if a.stencil { 8 } else { 0 },
                    if a.antialias { 4 } else { 0 },
                )
            }
        };
        let alpha_bits = if draw.is_none() && !self.fb.attributes.alpha {
            0
        } else {
            bits.alpha
        };
        Some(match pname {
            gl::RED_BITS => Int(bits.red as i64),
            gl::GREEN_BITS => Int(bits.green as i64),
            gl::BLUE_BITS => Int(bits.blue as i64),
            gl::ALPHA_BITS => Int(alpha_bits as i64),
            gl::DEPTH_BITS => Int(depth_bits as i64),
            gl::STENCIL_BITS => Int(stencil_bits as i64),
            gl::SAMPLES => Int(samples as i64),
            gl::SAMPLE_BUFFERS => Int((samples > 0) as i64),
            gl::IMPLEMENTATION_COLOR_READ_FORMAT | gl::IMPLEMENTATION_COLOR_READ_TYPE => {
                let read_format = match read.and_then(|id| self.objects.framebuffers.get_any(id)) {
                    None => Some(self.fb.format),
                    Some(f) => f
                        .attachment(f.read_buffer)
                        .and_then(|a| self.image_info(a))
                        .map(|i| i.format),
                }?;
                let (format, ty) = crate::readback::native_pair(&read_format);
                Enum(if pname == gl::IMPLEMENTATION_COLOR_READ_FORMAT {
                    format
                } else {
                    ty
                })
            }
            gl::READ_BUFFER => Enum(
                match read.and_then(|id| self.objects.framebuffers.get_any(id)) {
                    None => self.fb.read_buffer,
                    Some(f) => f.read_buffer,
                },
            ),
            p if (gl::DRAW_BUFFER0..gl::DRAW_BUFFER0 + self.limits.max_color_attachments)
                .contains(&p) =>
            {
                let i = (p - gl::DRAW_BUFFER0) as usize;
                Enum(
                    match draw.and_then(|id| self.objects.framebuffers.get_any(id)) {
                        None if i == 0 => self.fb.draw_buffer,
                        None => gl::NONE,
                        Some(f) => f.draw_buffers[i],
                    },
                )
            }
            _ => return None,
        })
    }

    /// Pixel storage (`pixelStorei`).
    fn pixel_store_parameter(&self, pname: u32) -> Option<Parameter> {
        use Parameter::{Bool, Enum, Int};
        let p = &self.pixel_store;
        Some(match pname {
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
            _ => return None,
        })
    }

    /// The default framebuffer's formats, the limits and the strings.
    fn limit_parameter(&self, pname: u32) -> Option<Parameter> {
        use Parameter::{Floats, Int, Ints};
        let l = &self.gpu.limits;
        let uniform_vectors = (l.max_uniform_buffer_binding_size / 16).min(4096) as i64;
        let blocks = l.max_uniform_buffers_per_shader_stage.saturating_sub(1) as i64;
        let image_units = l
            .max_sampled_textures_per_shader_stage
            .min(MAX_TEXTURE_UNITS) as i64;
        let varyings = l.max_inter_stage_shader_variables as i64;
        Some(match pname {
            // The default framebuffer.
            gl::SUBPIXEL_BITS => Int(SUBPIXEL_BITS),
            // Limits.
            gl::MAX_TEXTURE_SIZE | gl::MAX_CUBE_MAP_TEXTURE_SIZE | gl::MAX_RENDERBUFFER_SIZE => {
                Int(l.max_texture_dimension_2d as i64)
            }
            gl::MAX_3D_TEXTURE_SIZE => Int(l.max_texture_dimension_3d as i64),
            gl::MAX_ARRAY_TEXTURE_LAYERS => Int(l.max_texture_array_layers as i64),
            gl::MAX_VIEWPORT_DIMS => Ints(vec![l.max_texture_dimension_2d as i32; 2]),
            gl::MAX_VERTEX_ATTRIBS => Int(self.limits.max_vertex_attribs as i64),
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
            gl::MAX_DRAW_BUFFERS | gl::MAX_COLOR_ATTACHMENTS => {
                Int(self.limits.max_color_attachments as i64)
            }
            gl::MAX_SAMPLES => Int(4),
            gl::MAX_ELEMENTS_VERTICES | gl::MAX_ELEMENTS_INDICES => Int(i32::MAX as i64),
            gl::MIN_PROGRAM_TEXEL_OFFSET => Int(-8),
            gl::MAX_PROGRAM_TEXEL_OFFSET => Int(7),
            gl::MAX_TEXTURE_LOD_BIAS => Parameter::Float(essl::program::MAX_TEXTURE_LOD_BIAS),
            gl::MAX_SERVER_WAIT_TIMEOUT => Int(0),
            gl::MAX_CLIENT_WAIT_TIMEOUT_WEBGL => Int(0),
            gl::MAX_COMBINED_VERTEX_UNIFORM_COMPONENTS
            | gl::MAX_COMBINED_FRAGMENT_UNIFORM_COMPONENTS => {
                Int(uniform_vectors * 4 + blocks * l.max_uniform_buffer_binding_size as i64 / 4)
            }
            gl::MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS => Int(64),
            gl::MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS => Int(4),
            gl::MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS => Int(4),
            gl::ALIASED_LINE_WIDTH_RANGE => Floats(vec![1.0, 1.0]),
            gl::ALIASED_POINT_SIZE_RANGE => {
                let max = self
                    .largest_point
                    .get_or_init(|| super::point_size::largest_point(&self.gpu));
                Floats(vec![1.0, *max])
            }
            // Strings.
            gl::VERSION => Parameter::String(VERSION.to_owned()),
            gl::SHADING_LANGUAGE_VERSION => Parameter::String(SHADING_LANGUAGE_VERSION.to_owned()),
            gl::VENDOR => Parameter::String(VENDOR.to_owned()),
            gl::RENDERER => Parameter::String(format!("essl-gl on {}", self.gpu.info.name)),
            crate::extensions::UNMASKED_VENDOR if self.extensions.debug_renderer_info => {
                Parameter::String(crate::extensions::unmasked_vendor(&self.gpu.info))
            }
            crate::extensions::UNMASKED_RENDERER if self.extensions.debug_renderer_info => {
                Parameter::String(self.gpu.info.name.clone())
            }
            _ => return None,
        })
    }

    fn handle_buffer(&self, id: Option<Id>) -> Parameter {
        Parameter::Buffer(id.map(|id| Buffer { ctx: self.id, id }))
    }

    fn handle_texture(&self, target: u32) -> Parameter {
        let id = self.bindings.texture(self.bindings.active_unit(), target);
        Parameter::Texture(id.map(|id| Texture { ctx: self.id, id }))
    }
}
