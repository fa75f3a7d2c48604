//! The errors of reading, validating and resolving a scene, and of the image helpers.

use std::path::PathBuf;

/// Everything that can go wrong reading a scene or computing its derived values.
///
/// Bad input never panics: it gives one of these, whose message names the offending key
/// (`mesh.cells`, `uniforms.u_light`, …) the way `webgl2-render.py` does.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SceneError {
    /// A file (the scene or a shader) could not be read.
    #[error("cannot read {}: {source}", path.display())]
    Io {
        /// The file as it was opened (shader paths already resolved against the scene's folder).
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// A shader file (or the scene file) is not UTF-8.
    #[error("{what} {}: not valid UTF-8 ({source})", path.display())]
    NotUtf8 {
        /// Which file: `scene`, `vertex_shader` or `fragment_shader`.
        what: &'static str,
        /// The file.
        path: PathBuf,
        /// Where the first invalid byte is.
        source: std::str::Utf8Error,
    },
    /// The JSON is malformed, or its shape is wrong: an unknown key, a missing required key,
    /// a value of the wrong type, a vector of the wrong length, an unknown `kind`.
    /// The message is serde's, with the line and column.
    #[error("scene JSON: {0}")]
    Json(#[from] serde_json::Error),
    /// A value has the right type but is out of range or inconsistent with another.
    #[error("{field}: {message}")]
    Invalid {
        /// The key, dotted from the top level (`mesh.segments`, `textures.u_cookie.data`).
        field: String,
        /// What was expected.
        message: String,
    },
    /// `normalize` of a vector whose length is 0 (a `{"normalize": …}` uniform, or the camera's
    /// `eye - target` or `cross(up, eye - target)`).
    #[error("{what}: cannot normalize a zero vector")]
    ZeroVector {
        /// What was being normalized.
        what: String,
    },
    /// A matrix that had to be inverted (for `model_inverse_transpose` or `normal_matrix`)
    /// has determinant 0.
    #[error("{what}: matrix is singular")]
    Singular {
        /// Which derived value needed the inverse.
        what: String,
    },
    /// A uniform's resolved values do not fit the active type they are given to.
    #[error("uniform {name}: {message}")]
    UniformType {
        /// The uniform's name.
        name: String,
        /// Why the values do not fit.
        message: String,
    },
}

impl SceneError {
    /// Shorthand for [`SceneError::Invalid`].
    pub(crate) fn invalid(field: impl Into<String>, message: impl Into<String>) -> Self {
        SceneError::Invalid {
            field: field.into(),
            message: message.into(),
        }
    }
}

/// Errors of the PNG and image-comparison helpers.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ImageError {
    /// A PNG file could not be read or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// The PNG could not be decoded.
    #[error("cannot decode PNG: {0}")]
    Decode(#[from] png::DecodingError),
    /// The PNG could not be encoded.
    #[error("cannot encode PNG: {0}")]
    Encode(#[from] png::EncodingError),
    /// The pixel buffer does not hold `width * height * 4` bytes, or a dimension is 0.
    #[error("image buffer of {len} bytes does not match {width}x{height} RGBA8")]
    BufferSize {
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
        /// Bytes given.
        len: usize,
    },
    /// Two images compared have different sizes.
    #[error("image sizes differ: {a_width}x{a_height} vs {b_width}x{b_height}")]
    SizeMismatch {
        /// First image's width.
        a_width: u32,
        /// First image's height.
        a_height: u32,
        /// Second image's width.
        b_width: u32,
        /// Second image's height.
        b_height: u32,
    },
    /// A PNG layout this reader does not convert to RGBA8.
    #[error("unsupported PNG layout: {0}")]
    Unsupported(String),
}
