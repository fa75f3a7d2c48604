//! WebGL extensions: the ones a context has turned on ([`Extensions`]) and their names
//! ([`Extension`]). `get_extension` and `get_supported_extensions` are in `context.rs`.
//!
//! essl-gl implements the WebGL2 extensions that change what the core API accepts and that
//! wgpu can do on every adapter it runs on: `EXT_color_buffer_float` (render to 16- and
//! 32-bit float formats and `R11F_G11F_B10F`), `EXT_color_buffer_half_float`,
//! `EXT_float_blend` (32-bit float attachments blend where the adapter can, whether or not
//! the extension was turned on, as in Chromium and as the conformance suite checks; elsewhere
//! such a draw is `INVALID_OPERATION` and the extension is not offered),
//! and `OES_texture_float_linear` (filter 32-bit float textures, where the adapter can). It
//! does not offer `KHR_parallel_shader_compile`: programs link inside `linkProgram`, so
//! `COMPLETION_STATUS_KHR` could never be false, and a page that waits for it to be (the
//! conformance suite's) grows its shaders until memory runs out. Both contexts offer the
//! compressed-texture extensions (S3TC, S3TC sRGB, ETC, ETC1, ASTC LDR, RGTC, BPTC: decoded on
//! upload, `texture/compressed/`) and
//! `EXT_texture_filter_anisotropic` (wgpu's anisotropy clamp, up to 16, where the
//! minification, magnification and mipmap filters are all linear, as wgpu requires). WebGL 2
//! contexts offer `WEBGL_clip_cull_distance` where the adapter has clip distances (eight; no
//! cull distances: `state/clip_distance.rs`), `OES_draw_buffers_indexed` (`state/blend.rs`),
//! `WEBGL_stencil_texturing` (`texture/params.rs`), and for shaders only
//! `EXT_conservative_depth` and `NV_shader_noperspective_interpolation`. Both offer
//! `WEBGL_debug_shaders` (a compiled shader's lowered module as WGSL),
//! `WEBGL_debug_renderer_info` (the adapter's vendor and name), `EXT_clip_control`
//! (`state/clip_control.rs`) and `WEBGL_multi_draw` (`draw/multi.rs`), and where the adapter
//! can, `EXT_polygon_offset_clamp`, `EXT_depth_clamp` and `WEBGL_polygon_mode`
//! (`state/raster.rs`). WebGL 1 contexts offer their own list besides, float textures among
//! them (`webgl1/float.rs`).

/// The WebGL extensions a context has turned on.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Extensions {
    /// `EXT_color_buffer_float`.
    pub(crate) color_buffer_float: bool,
    /// `OES_texture_float_linear`.
    pub(crate) texture_float_linear: bool,
    /// The compressed-texture extensions turned on.
    pub(crate) compressed: CompressedSet,
    /// `EXT_texture_filter_anisotropic`.
    pub(crate) anisotropic: bool,
    /// `WEBGL_clip_cull_distance`.
    pub(crate) clip_cull_distance: bool,
    /// `EXT_clip_control`.
    pub(crate) clip_control: bool,
    /// `WEBGL_multi_draw`.
    pub(crate) multi_draw: bool,
    /// `OES_draw_buffers_indexed`.
    pub(crate) draw_buffers_indexed: bool,
    /// `WEBGL_stencil_texturing`.
    pub(crate) stencil_texturing: bool,
    /// `EXT_polygon_offset_clamp`.
    pub(crate) polygon_offset_clamp: bool,
    /// `EXT_depth_clamp`.
    pub(crate) depth_clamp: bool,
    /// `WEBGL_polygon_mode`.
    pub(crate) polygon_mode: bool,
    /// `WEBGL_debug_renderer_info`.
    pub(crate) debug_renderer_info: bool,
}

/// `WEBGL_debug_renderer_info`'s `getParameter` name: the adapter's vendor.
pub(crate) const UNMASKED_VENDOR: u32 = 0x9245;
/// `WEBGL_debug_renderer_info`'s `getParameter` name: the adapter's name.
pub(crate) const UNMASKED_RENDERER: u32 = 0x9246;

/// The vendor `UNMASKED_VENDOR_WEBGL` names: the company of the adapter's PCI (or Vulkan)
/// vendor id, else its driver's name.
pub(crate) fn unmasked_vendor(info: &wgpu::AdapterInfo) -> String {
    let known = match info.vendor {
        0x1002 | 0x1022 => "AMD",
        0x10DE => "NVIDIA",
        0x8086 => "Intel",
        0x13B5 => "ARM",
        0x5143 => "Qualcomm",
        0x106B => "Apple",
        0x1010 => "Imagination Technologies",
        // VK_VENDOR_ID_MESA: lavapipe and Mesa's other software drivers.
        0x10005 => "Mesa",
        _ => return info.driver.clone(),
    };
    known.to_owned()
}

/// `EXT_texture_filter_anisotropic`'s texture and sampler parameter.
pub(crate) const TEXTURE_MAX_ANISOTROPY_EXT: u32 = 0x84FE;
/// `EXT_texture_filter_anisotropic`'s `getParameter` name.
pub(crate) const MAX_TEXTURE_MAX_ANISOTROPY_EXT: u32 = 0x84FF;
/// The largest anisotropy essl-gl asks of the device (wgpu's clamp).
pub(crate) const MAX_ANISOTROPY: f32 = 16.0;

/// A set of the compressed-texture extensions.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct CompressedSet(u8);

impl CompressedSet {
    fn bit(e: &Extension) -> u8 {
        match e {
            Extension::CompressedS3tc => 1,
            Extension::CompressedS3tcSrgb => 2,
            Extension::CompressedEtc => 4,
            Extension::CompressedEtc1 => 8,
            Extension::CompressedAstc => 16,
            Extension::CompressedRgtc => 32,
            Extension::CompressedBptc => 64,
            _ => 0,
        }
    }

    /// Whether `e` is on.
    pub(crate) fn contains(&self, e: &Extension) -> bool {
        self.0 & Self::bit(e) != 0
    }

    /// Turns `e` on; false when it is no compressed-texture extension.
    pub(crate) fn insert(&mut self, e: Extension) -> bool {
        self.0 |= Self::bit(&e);
        Self::bit(&e) != 0
    }
}

/// The compressed-texture extensions, offered in both contexts.
pub(crate) const COMPRESSED_EXTENSIONS: [Extension; 7] = [
    Extension::CompressedS3tc,
    Extension::CompressedS3tcSrgb,
    Extension::CompressedEtc,
    Extension::CompressedEtc1,
    Extension::CompressedAstc,
    Extension::CompressedRgtc,
    Extension::CompressedBptc,
];

/// An extension [`Context::get_extension`](crate::Context::get_extension) turned on. WebGL
/// returns an object holding the extension's constants; essl-gl's constants are in
/// [`gl`](crate::gl), so the value only names the extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Extension {
    /// `EXT_color_buffer_float`.
    ColorBufferFloat,
    /// `EXT_color_buffer_half_float`.
    ColorBufferHalfFloat,
    /// `EXT_float_blend`.
    FloatBlend,
    /// `OES_texture_float_linear`.
    TextureFloatLinear,
    /// `ANGLE_instanced_arrays` (WebGL 1).
    AngleInstancedArrays,
    /// `EXT_blend_minmax` (WebGL 1).
    ExtBlendMinmax,
    /// `EXT_frag_depth` (WebGL 1).
    ExtFragDepth,
    /// `EXT_shader_texture_lod` (WebGL 1).
    ExtShaderTextureLod,
    /// `OES_element_index_uint` (WebGL 1).
    OesElementIndexUint,
    /// `OES_standard_derivatives` (WebGL 1).
    OesStandardDerivatives,
    /// `OES_vertex_array_object` (WebGL 1).
    OesVertexArrayObject,
    /// `WEBGL_draw_buffers` (WebGL 1).
    WebglDrawBuffers,
    /// `OES_texture_float` (WebGL 1).
    OesTextureFloat,
    /// `OES_texture_half_float` (WebGL 1).
    OesTextureHalfFloat,
    /// `OES_texture_half_float_linear` (WebGL 1).
    OesTextureHalfFloatLinear,
    /// `WEBGL_color_buffer_float` (WebGL 1).
    WebglColorBufferFloat,
    /// `WEBGL_depth_texture` (WebGL 1).
    WebglDepthTexture,
    /// `EXT_sRGB` (WebGL 1).
    ExtSrgb,
    /// `OES_fbo_render_mipmap` (WebGL 1): framebuffers attach any level of a texture.
    OesFboRenderMipmap,
    /// `WEBGL_compressed_texture_s3tc`.
    CompressedS3tc,
    /// `WEBGL_compressed_texture_s3tc_srgb`.
    CompressedS3tcSrgb,
    /// `WEBGL_compressed_texture_etc`.
    CompressedEtc,
    /// `WEBGL_compressed_texture_etc1`.
    CompressedEtc1,
    /// `WEBGL_compressed_texture_astc` (the LDR profile).
    CompressedAstc,
    /// `EXT_texture_compression_rgtc` (BC4 and BC5).
    CompressedRgtc,
    /// `EXT_texture_compression_bptc` (BC6H and BC7).
    CompressedBptc,
    /// `EXT_texture_filter_anisotropic`.
    TextureFilterAnisotropic,
    /// `WEBGL_clip_cull_distance` (WebGL 2; clip distances only, where the adapter has them).
    ClipCullDistance,
    /// `WEBGL_debug_shaders`: [`Context::get_translated_shader_source`](crate::Context::get_translated_shader_source).
    DebugShaders,
    /// `EXT_clip_control`: [`Context::clip_control_ext`](crate::Context::clip_control_ext).
    ClipControl,
    /// `WEBGL_multi_draw`: [`Context::multi_draw_arrays`](crate::Context::multi_draw_arrays)
    /// and its kin, and `gl_DrawID` in shaders.
    MultiDraw,
    /// `OES_draw_buffers_indexed` (WebGL 2): blending and colour masks per draw buffer
    /// ([`Context::color_mask_indexed`](crate::Context::color_mask_indexed) and its kin).
    DrawBuffersIndexed,
    /// `WEBGL_stencil_texturing` (WebGL 2): a depth-stencil texture sampled for its stencil
    /// (`DEPTH_STENCIL_TEXTURE_MODE_WEBGL`).
    StencilTexturing,
    /// `EXT_polygon_offset_clamp`:
    /// [`Context::polygon_offset_clamp_ext`](crate::Context::polygon_offset_clamp_ext).
    PolygonOffsetClamp,
    /// `EXT_depth_clamp`: the `DEPTH_CLAMP_EXT` capability.
    DepthClamp,
    /// `WEBGL_polygon_mode`: [`Context::polygon_mode_webgl`](crate::Context::polygon_mode_webgl).
    PolygonMode,
    /// `WEBGL_debug_renderer_info`: the adapter's vendor and name
    /// (`UNMASKED_VENDOR_WEBGL`, `UNMASKED_RENDERER_WEBGL`).
    DebugRendererInfo,
    /// `EXT_conservative_depth` (WebGL 2): `layout(depth_any | depth_greater | depth_less)` on
    /// `gl_FragDepth` in shaders.
    ConservativeDepth,
    /// `NV_shader_noperspective_interpolation` (WebGL 2): the `noperspective` qualifier in
    /// shaders.
    NoperspectiveInterpolation,
}

impl Extension {
    /// The extension's WebGL name.
    pub fn name(self) -> &'static str {
        match self {
            Extension::ColorBufferFloat => "EXT_color_buffer_float",
            Extension::ColorBufferHalfFloat => "EXT_color_buffer_half_float",
            Extension::FloatBlend => "EXT_float_blend",
            Extension::TextureFloatLinear => "OES_texture_float_linear",
            Extension::AngleInstancedArrays => "ANGLE_instanced_arrays",
            Extension::ExtBlendMinmax => "EXT_blend_minmax",
            Extension::ExtFragDepth => "EXT_frag_depth",
            Extension::ExtShaderTextureLod => "EXT_shader_texture_lod",
            Extension::OesElementIndexUint => "OES_element_index_uint",
            Extension::OesStandardDerivatives => "OES_standard_derivatives",
            Extension::OesVertexArrayObject => "OES_vertex_array_object",
            Extension::WebglDrawBuffers => "WEBGL_draw_buffers",
            Extension::OesTextureFloat => "OES_texture_float",
            Extension::OesTextureHalfFloat => "OES_texture_half_float",
            Extension::OesTextureHalfFloatLinear => "OES_texture_half_float_linear",
            Extension::WebglColorBufferFloat => "WEBGL_color_buffer_float",
            Extension::WebglDepthTexture => "WEBGL_depth_texture",
            Extension::ExtSrgb => "EXT_sRGB",
            Extension::OesFboRenderMipmap => "OES_fbo_render_mipmap",
            Extension::CompressedS3tc => "WEBGL_compressed_texture_s3tc",
            Extension::CompressedS3tcSrgb => "WEBGL_compressed_texture_s3tc_srgb",
            Extension::CompressedEtc => "WEBGL_compressed_texture_etc",
            Extension::CompressedEtc1 => "WEBGL_compressed_texture_etc1",
            Extension::CompressedAstc => "WEBGL_compressed_texture_astc",
            Extension::CompressedRgtc => "EXT_texture_compression_rgtc",
            Extension::CompressedBptc => "EXT_texture_compression_bptc",
            Extension::TextureFilterAnisotropic => "EXT_texture_filter_anisotropic",
            Extension::ClipCullDistance => "WEBGL_clip_cull_distance",
            Extension::DebugShaders => "WEBGL_debug_shaders",
            Extension::ClipControl => "EXT_clip_control",
            Extension::MultiDraw => "WEBGL_multi_draw",
            Extension::DrawBuffersIndexed => "OES_draw_buffers_indexed",
            Extension::StencilTexturing => "WEBGL_stencil_texturing",
            Extension::PolygonOffsetClamp => "EXT_polygon_offset_clamp",
            Extension::DepthClamp => "EXT_depth_clamp",
            Extension::PolygonMode => "WEBGL_polygon_mode",
            Extension::DebugRendererInfo => "WEBGL_debug_renderer_info",
            Extension::ConservativeDepth => "EXT_conservative_depth",
            Extension::NoperspectiveInterpolation => "NV_shader_noperspective_interpolation",
        }
    }
}
