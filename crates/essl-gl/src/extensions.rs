//! WebGL extensions: `get_extension` turns one on, `get_supported_extensions` lists them.
//!
//! essl-gl implements the WebGL2 extensions that change what the core API accepts and that
//! wgpu can do on every adapter it runs on: `EXT_color_buffer_float` (render to 16- and
//! 32-bit float formats and `R11F_G11F_B10F`), `EXT_color_buffer_half_float`,
//! `EXT_float_blend` (blend into 32-bit float attachments), `OES_texture_float_linear`
//! (filter 32-bit float textures, where the adapter can) and `KHR_parallel_shader_compile`
//! (`COMPLETION_STATUS_KHR`, always true: compiling is synchronous).

use crate::context::Context;

/// The WebGL extensions a context has turned on.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Extensions {
    /// `EXT_color_buffer_float`.
    pub(crate) color_buffer_float: bool,
    /// `EXT_float_blend`.
    pub(crate) float_blend: bool,
    /// `OES_texture_float_linear`.
    pub(crate) texture_float_linear: bool,
    /// `KHR_parallel_shader_compile`.
    pub(crate) parallel_shader_compile: bool,
}

/// An extension [`Context::get_extension`] turned on. WebGL returns an object holding the
/// extension's constants; essl-gl's constants are in [`gl`](crate::gl), so the value only
/// names the extension.
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
    /// `KHR_parallel_shader_compile`.
    ParallelShaderCompile,
}

impl Extension {
    /// The extension's WebGL name.
    pub fn name(self) -> &'static str {
        match self {
            Extension::ColorBufferFloat => "EXT_color_buffer_float",
            Extension::ColorBufferHalfFloat => "EXT_color_buffer_half_float",
            Extension::FloatBlend => "EXT_float_blend",
            Extension::TextureFloatLinear => "OES_texture_float_linear",
            Extension::ParallelShaderCompile => "KHR_parallel_shader_compile",
        }
    }
}

impl Context {
    /// The extensions this context offers (`getSupportedExtensions`).
    pub fn get_supported_extensions(&self) -> Vec<&'static str> {
        self.supported().iter().map(|e| e.name()).collect()
    }

    fn supported(&self) -> Vec<Extension> {
        let mut v = vec![
            Extension::ColorBufferFloat,
            Extension::ColorBufferHalfFloat,
            Extension::FloatBlend,
        ];
        if self
            .gpu
            .device
            .features()
            .contains(wgpu::Features::FLOAT32_FILTERABLE)
        {
            v.push(Extension::TextureFloatLinear);
        }
        v.push(Extension::ParallelShaderCompile);
        v
    }

    /// Turns an extension on and returns it (`getExtension`); `None` for a name this context
    /// does not offer (names compare case-insensitively, as in WebGL).
    pub fn get_extension(&mut self, name: &str) -> Option<Extension> {
        let e = self
            .supported()
            .into_iter()
            .find(|e| e.name().eq_ignore_ascii_case(name))?;
        let x = &mut self.extensions;
        match e {
            // EXT_color_buffer_half_float makes the 16-bit formats renderable, which
            // EXT_color_buffer_float also does; essl-gl tracks the two together.
            Extension::ColorBufferFloat | Extension::ColorBufferHalfFloat => {
                x.color_buffer_float = true
            }
            Extension::FloatBlend => x.float_blend = true,
            Extension::TextureFloatLinear => x.texture_float_linear = true,
            Extension::ParallelShaderCompile => x.parallel_shader_compile = true,
        }
        Some(e)
    }
}
