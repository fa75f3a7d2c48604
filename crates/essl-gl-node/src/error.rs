//! Errors the binding throws to JavaScript (WebGL's own errors are GL error codes, read with
//! `getError`, never exceptions).

/// Why a context could not be made or used.
#[derive(Debug, thiserror::Error)]
pub enum BindingError {
    /// No Vulkan adapter: the message says what to install.
    #[error(
        "essl-gl: no Vulkan adapter ({0}). Install Mesa's software Vulkan driver, lavapipe \
         (Debian/Ubuntu: `apt-get install mesa-vulkan-drivers libvulkan1`; Fedora: \
         `dnf install mesa-vulkan-drivers vulkan-loader`), or a GPU's Vulkan driver"
    )]
    NoAdapter(String),
    /// Another reason the context could not be made (a size past the device's limit).
    #[error("essl-gl: {0}")]
    Context(String),
    /// A call on a destroyed context.
    #[error("essl-gl: the context was destroyed")]
    Destroyed,
    /// The PNG encoder failed.
    #[error("essl-gl: PNG: {0}")]
    Png(String),
}

impl From<essl_gl::ContextError> for BindingError {
    fn from(e: essl_gl::ContextError) -> Self {
        match e {
            essl_gl::ContextError::NoAdapter(m) => BindingError::NoAdapter(m),
            other => BindingError::Context(other.to_string()),
        }
    }
}

impl From<BindingError> for napi::Error {
    fn from(e: BindingError) -> Self {
        napi::Error::from_reason(e.to_string())
    }
}
