//! A WebGL 1 context: WebGL 2's calls with WebGL 1's rules.
//!
//! [`Context::set_webgl1`] makes a context answer as a `WebGLRenderingContext` does: shaders
//! are GLSL ES 1.00 only, `VERSION` and `SHADING_LANGUAGE_VERSION` say WebGL 1.0, and every
//! enum WebGL 2 added ([`enums::WEBGL2_ONLY`]: `TEXTURE_3D`, `RGBA8`, `READ_FRAMEBUFFER`,
//! `UNPACK_ROW_LENGTH`, `RASTERIZER_DISCARD`, …) is `INVALID_ENUM` wherever a call takes an
//! enum, unless a WebGL 1 extension the application turned on brings it back
//! (`OES_vertex_array_object`'s `VERTEX_ARRAY_BINDING_OES`, `WEBGL_draw_buffers`'
//! `COLOR_ATTACHMENT1_WEBGL`, `EXT_blend_minmax`'s `MIN_EXT`, …). Rules of WebGL 1 that are
//! not about enums are checked where they apply: `vertexAttribPointer` takes the five
//! WebGL 1 types, `drawElements` takes `UNSIGNED_INT` only with `OES_element_index_uint`,
//! `texImage2D`'s internal format must be its format, texture images of a
//! non-power-of-two size take no mipmaps or repeat wrapping, and `WEBGL_depth_texture`'s depth
//! images are level-0 `TEXTURE_2D`s without data, a depth-and-stencil one attached at
//! `DEPTH_STENCIL_ATTACHMENT` only.

mod enums;
mod float;

pub(crate) use float::HALF_FLOAT_OES;

use crate::context::Context;
use crate::extensions::Extension;
use crate::gl;

/// Whether a context is WebGL 1, and the WebGL 1 extensions turned on.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Webgl1 {
    /// A WebGL 1 context.
    pub(crate) on: bool,
    pub(crate) vertex_array_object: bool,
    pub(crate) instanced_arrays: bool,
    pub(crate) element_index_uint: bool,
    pub(crate) standard_derivatives: bool,
    pub(crate) draw_buffers: bool,
    pub(crate) blend_minmax: bool,
    pub(crate) frag_depth: bool,
    pub(crate) shader_texture_lod: bool,
    pub(crate) texture_float: bool,
    pub(crate) texture_half_float: bool,
    pub(crate) texture_half_float_linear: bool,
    pub(crate) color_buffer_float: bool,
    pub(crate) color_buffer_half_float: bool,
    pub(crate) depth_texture: bool,
    pub(crate) srgb: bool,
    /// `OES_fbo_render_mipmap`: a framebuffer may attach a texture level other than 0.
    pub(crate) fbo_render_mipmap: bool,
}

/// The extensions a WebGL 1 context offers (`EXT_float_blend` and `OES_texture_float_linear`
/// too, where the adapter blends and filters 32-bit floats).
pub(crate) const WEBGL1_EXTENSIONS: [Extension; 16] = [
    Extension::AngleInstancedArrays,
    Extension::ColorBufferHalfFloat,
    Extension::ExtBlendMinmax,
    Extension::ExtFragDepth,
    Extension::ExtShaderTextureLod,
    Extension::OesElementIndexUint,
    Extension::OesStandardDerivatives,
    Extension::OesTextureFloat,
    Extension::OesTextureHalfFloat,
    Extension::OesTextureHalfFloatLinear,
    Extension::OesVertexArrayObject,
    Extension::WebglColorBufferFloat,
    Extension::WebglDrawBuffers,
    Extension::WebglDepthTexture,
    Extension::ExtSrgb,
    Extension::OesFboRenderMipmap,
];

impl Context {
    /// Makes this a WebGL 1 context (`canvas.getContext("webgl")`): GLSL ES 1.00 shaders and
    /// WebGL 1's enums and rules (see the [module](self)); extensions from
    /// [`Context::get_extension`] are WebGL 1's.
    pub fn set_webgl1(&mut self) {
        self.webgl1.on = true;
        self.set_shader_target(essl::Target::WebGl1, &[]);
    }

    /// Whether this is a WebGL 1 context ([`Context::set_webgl1`]).
    pub fn is_webgl1(&self) -> bool {
        self.webgl1.on
    }

    /// Turns a WebGL 1 extension on (from `get_extension`); the shader extensions change
    /// what later compiles accept.
    pub(crate) fn enable_webgl1_extension(&mut self, e: Extension) {
        let w = &mut self.webgl1;
        match e {
            Extension::OesVertexArrayObject => w.vertex_array_object = true,
            Extension::AngleInstancedArrays => w.instanced_arrays = true,
            Extension::OesElementIndexUint => w.element_index_uint = true,
            Extension::OesStandardDerivatives => w.standard_derivatives = true,
            Extension::WebglDrawBuffers => w.draw_buffers = true,
            Extension::ExtBlendMinmax => w.blend_minmax = true,
            Extension::ExtFragDepth => w.frag_depth = true,
            Extension::ExtShaderTextureLod => w.shader_texture_lod = true,
            Extension::OesTextureFloat | Extension::WebglColorBufferFloat => {
                w.texture_float |= e == Extension::OesTextureFloat;
                w.color_buffer_float = true;
            }
            Extension::OesTextureHalfFloat | Extension::ColorBufferHalfFloat => {
                w.texture_half_float |= e == Extension::OesTextureHalfFloat;
                w.color_buffer_half_float = true;
            }
            Extension::OesTextureHalfFloatLinear => w.texture_half_float_linear = true,
            Extension::WebglDepthTexture => w.depth_texture = true,
            Extension::ExtSrgb => w.srgb = true,
            Extension::OesFboRenderMipmap => w.fbo_render_mipmap = true,
            Extension::TextureFloatLinear => self.extensions.texture_float_linear = true,
            _ => {}
        }
        // The float attachments of WebGL 2's EXT_color_buffer_float are these extensions'.
        self.extensions.color_buffer_float |= w.color_buffer_float || w.color_buffer_half_float;
        let w = self.webgl1;
        let shader: Vec<essl::Extension> = [
            (
                w.standard_derivatives,
                essl::Extension::OesStandardDerivatives,
            ),
            (w.frag_depth, essl::Extension::ExtFragDepth),
            (w.shader_texture_lod, essl::Extension::ExtShaderTextureLod),
            (w.draw_buffers, essl::Extension::WebglDrawBuffers),
            (self.extensions.multi_draw, essl::Extension::WebglMultiDraw),
        ]
        .into_iter()
        .filter_map(|(on, e)| on.then_some(e))
        .collect();
        self.set_shader_target(essl::Target::WebGl1, &shader);
    }

    /// Whether enum `value` exists for this context: always in WebGL 2; in WebGL 1 unless
    /// WebGL 2 added it and no extension that is on brings it back.
    pub(crate) fn webgl1_has_enum(&self, value: u32) -> bool {
        if !self.webgl1.on || enums::WEBGL2_ONLY.binary_search(&value).is_err() {
            return true;
        }
        let w = &self.webgl1;
        match value {
            gl::VERTEX_ARRAY_BINDING => w.vertex_array_object,
            gl::VERTEX_ATTRIB_ARRAY_DIVISOR => w.instanced_arrays,
            gl::FRAGMENT_SHADER_DERIVATIVE_HINT => w.standard_derivatives,
            gl::MIN | gl::MAX => w.blend_minmax,
            gl::FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE => {
                w.color_buffer_float || w.color_buffer_half_float
            }
            gl::RGBA32F => w.color_buffer_float,
            gl::RGBA16F | gl::RGB16F => w.color_buffer_half_float,
            gl::UNSIGNED_INT_24_8 => w.depth_texture,
            gl::SRGB8_ALPHA8 | gl::FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING => w.srgb,
            gl::MAX_COLOR_ATTACHMENTS | gl::MAX_DRAW_BUFFERS => w.draw_buffers,
            v if (gl::COLOR_ATTACHMENT1..=gl::COLOR_ATTACHMENT15).contains(&v) => w.draw_buffers,
            v if (gl::DRAW_BUFFER0..=gl::DRAW_BUFFER15).contains(&v) => w.draw_buffers,
            _ => false,
        }
    }

    /// Records `INVALID_ENUM` for the first of `values` a WebGL 1 context does not have;
    /// whether one was refused.
    pub(crate) fn webgl1_refuses(&self, function: &str, values: &[u32]) -> bool {
        if !self.webgl1.on {
            return false;
        }
        match values.iter().find(|&&v| !self.webgl1_has_enum(v)) {
            Some(v) => {
                self.error(
                    gl::INVALID_ENUM,
                    function,
                    format_args!("0x{v:04X} is not an enum of WebGL 1"),
                );
                true
            }
            None => false,
        }
    }

    /// WebGL 1's `vertexAttribPointer` types: the five 8-, 16- and 32-bit ones.
    pub(crate) fn webgl1_refuses_vertex_type(&self, ty: u32) -> bool {
        let ok = matches!(
            ty,
            gl::BYTE | gl::UNSIGNED_BYTE | gl::SHORT | gl::UNSIGNED_SHORT | gl::FLOAT
        );
        if self.webgl1.on && !ok {
            self.error(
                gl::INVALID_ENUM,
                "vertexAttribPointer",
                format_args!("type 0x{ty:04X} is not a vertex type of WebGL 1"),
            );
            return true;
        }
        false
    }

    /// WebGL 1's index types: `UNSIGNED_INT` only with `OES_element_index_uint`.
    pub(crate) fn webgl1_refuses_index_type(&self, ty: u32, function: &str) -> bool {
        if self.webgl1.on && ty == gl::UNSIGNED_INT && !self.webgl1.element_index_uint {
            self.error(
                gl::INVALID_ENUM,
                function,
                "UNSIGNED_INT indices need OES_element_index_uint",
            );
            return true;
        }
        false
    }

    /// WebGL 1's renderbuffer formats.
    pub(crate) fn webgl1_refuses_renderbuffer_format(&self, format: u32) -> bool {
        let ok = matches!(
            format,
            gl::RGBA4
                | gl::RGB565
                | gl::RGB5_A1
                | gl::DEPTH_COMPONENT16
                | gl::STENCIL_INDEX8
                | gl::DEPTH_STENCIL
        ) || self.webgl1_float_renderbuffer(format)
            || (format == gl::SRGB8_ALPHA8 && self.webgl1.srgb);
        if self.webgl1.on && !ok {
            self.error(
                gl::INVALID_ENUM,
                "renderbufferStorage",
                format_args!("0x{format:04X} is not a renderbuffer format of WebGL 1"),
            );
            return true;
        }
        false
    }

    /// `WEBGL_depth_texture`: the sized format a WebGL 1 `texImage2D` of `DEPTH_COMPONENT`
    /// (`UNSIGNED_SHORT` → 16 bits, `UNSIGNED_INT` → 24) or `DEPTH_STENCIL`
    /// (`UNSIGNED_INT_24_8_WEBGL`) allocates once the extension is on; `internal` otherwise.
    pub(crate) fn webgl1_depth_internal(&self, internal: u32, ty: u32) -> u32 {
        if !(self.webgl1.on && self.webgl1.depth_texture) {
            return internal;
        }
        match (internal, ty) {
            (gl::DEPTH_COMPONENT, gl::UNSIGNED_SHORT) => gl::DEPTH_COMPONENT16,
            (gl::DEPTH_COMPONENT, gl::UNSIGNED_INT) => gl::DEPTH_COMPONENT24,
            (gl::DEPTH_STENCIL, gl::UNSIGNED_INT_24_8) => gl::DEPTH24_STENCIL8,
            _ => internal,
        }
    }

    /// `WEBGL_depth_texture`'s rules for a WebGL 1 depth texture image: a `TEXTURE_2D`, level
    /// 0, no data (`INVALID_OPERATION`); whether the call may go on.
    pub(crate) fn webgl1_depth_image_ok(
        &mut self,
        target: u32,
        level: i32,
        has_data: bool,
        function: &str,
    ) -> bool {
        let why = if target != gl::TEXTURE_2D {
            "a WebGL 1 depth texture is a TEXTURE_2D"
        } else if level != 0 {
            "a WebGL 1 depth texture has level 0 only"
        } else if has_data {
            "a WebGL 1 depth texture takes no data (null)"
        } else {
            return true;
        };
        self.error(gl::INVALID_OPERATION, function, why);
        false
    }

    /// `EXT_sRGB`: a WebGL 1 upload's `(internalformat, format)` with `SRGB_EXT` and
    /// `SRGB_ALPHA_EXT` as the sized sRGB formats and the formats their texels come in.
    pub(crate) fn webgl1_srgb(&self, internal: i32, format: u32) -> (i32, u32) {
        if !(self.webgl1.on && self.webgl1.srgb) {
            return (internal, format);
        }
        let internal = match internal as u32 {
            SRGB_EXT => gl::SRGB8 as i32,
            SRGB_ALPHA_EXT => gl::SRGB8_ALPHA8 as i32,
            _ => internal,
        };
        let format = match format {
            SRGB_EXT => gl::RGB,
            SRGB_ALPHA_EXT => gl::RGBA,
            _ => format,
        };
        (internal, format)
    }
}

/// `EXT_sRGB`'s `SRGB_EXT` (WebGL 2's `SRGB`).
pub(crate) const SRGB_EXT: u32 = 0x8C40;
/// `EXT_sRGB`'s `SRGB_ALPHA_EXT`.
pub(crate) const SRGB_ALPHA_EXT: u32 = 0x8C42;
