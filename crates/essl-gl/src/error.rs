//! Errors: why a [`Context`](crate::Context) could not be created, and GL's error flag.

use std::cell::{Cell, RefCell};

use crate::gl;

/// Why [`Context::new`](crate::Context::new) failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ContextError {
    /// No Vulkan adapter was found, not even a software one.
    #[error(
        "no Vulkan adapter found ({0}); install a Vulkan driver, e.g. Mesa's software \
         rasterizer lavapipe: `apt-get install mesa-vulkan-drivers libvulkan1` on Debian/Ubuntu"
    )]
    NoAdapter(String),
    /// The adapter refused to create a device.
    #[error("the Vulkan adapter `{adapter}` could not create a device: {source}")]
    RequestDevice {
        /// The adapter's name.
        adapter: String,
        /// wgpu's error.
        #[source]
        source: wgpu::RequestDeviceError,
    },
    /// The requested framebuffer size is zero or larger than the device allows.
    #[error("framebuffer size {width}x{height} is not between 1 and {max} in each dimension")]
    InvalidSize {
        /// The requested width.
        width: u32,
        /// The requested height.
        height: u32,
        /// The largest dimension the device allows.
        max: u32,
    },
}

/// GL's error flag: the first error recorded sticks until [`ErrorState::take`] reads it.
/// Interior-mutable, so that queries which change nothing else take `&Context`.
#[derive(Debug, Default)]
pub(crate) struct ErrorState {
    code: Cell<u32>,
    message: RefCell<Option<String>>,
}

impl ErrorState {
    /// Records `code` unless an earlier error has not been read yet.
    pub(crate) fn record(&self, code: u32, message: impl FnOnce() -> String) {
        if self.code.get() == gl::NO_ERROR {
            self.code.set(code);
            *self.message.borrow_mut() = Some(message());
        }
    }

    /// Returns the recorded error (or `NO_ERROR`) and clears it.
    pub(crate) fn take(&self) -> u32 {
        *self.message.borrow_mut() = None;
        self.code.replace(gl::NO_ERROR)
    }

    /// Describes the recorded error, if any.
    pub(crate) fn message(&self) -> Option<String> {
        self.message.borrow().clone()
    }
}

/// The name of a GL error code (`"INVALID_OPERATION"`), for messages.
pub fn error_name(code: u32) -> &'static str {
    match code {
        gl::NO_ERROR => "NO_ERROR",
        gl::INVALID_ENUM => "INVALID_ENUM",
        gl::INVALID_VALUE => "INVALID_VALUE",
        gl::INVALID_OPERATION => "INVALID_OPERATION",
        gl::OUT_OF_MEMORY => "OUT_OF_MEMORY",
        gl::INVALID_FRAMEBUFFER_OPERATION => "INVALID_FRAMEBUFFER_OPERATION",
        gl::CONTEXT_LOST_WEBGL => "CONTEXT_LOST_WEBGL",
        _ => "unknown error",
    }
}
