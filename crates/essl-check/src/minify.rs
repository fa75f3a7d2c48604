//! Minifying a checked shader: [`essl::minify`] on the text WebGL is given (its `#include`s in
//! place) with the settings it was checked with (target, `defines`). A shader assembled by a
//! preset is not minified: three.js and luma.gl put their own prefix and chunks around the
//! text at run time, and the names of that prefix are not the text's to rename.

use essl::minify::{Minified, MinifyOptions};

use crate::CheckedShader;

/// Why a checked shader is not minified.
#[derive(Debug, thiserror::Error)]
pub enum MinifyError {
    /// The shader follows a library's preset.
    #[error(
        "a shader checked with preset '{0}' is not minified (the library assembles it at run time)"
    )]
    Preset(&'static str),
    /// An `#include` could not be followed: there is no complete text.
    #[error("the shader's text is not complete (an #include could not be followed)")]
    Incomplete,
    /// The minifier's own refusal: errors in the shader, or an output that failed its check.
    #[error(transparent)]
    Minify(#[from] essl::minify::MinifyError),
}

/// Minifies a checked shader's assembled text; `rename`: shorten local names too.
pub fn minify(shader: &CheckedShader, rename: bool) -> Result<Minified, MinifyError> {
    if let Some(preset) = shader.settings.preset {
        return Err(MinifyError::Preset(preset.as_str()));
    }
    if shader.shader.is_none() {
        return Err(MinifyError::Incomplete);
    }
    let options = MinifyOptions {
        compile: shader.settings.compile.clone(),
        rename,
    };
    Ok(essl::minify::minify(
        shader.assembly.text(),
        shader.stage,
        &options,
    )?)
}
