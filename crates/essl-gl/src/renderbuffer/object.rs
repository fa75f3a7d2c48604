//! A renderbuffer object's state: its storage, once `renderbuffer_storage` has made it.

use crate::texture::InternalFormat;

/// A renderbuffer's storage.
pub(crate) struct RenderbufferStorage {
    pub(crate) format: InternalFormat,
    /// The internal format as asked (`RENDERBUFFER_INTERNAL_FORMAT`: WebGL's
    /// `DEPTH_STENCIL` stays `DEPTH_STENCIL`, as Chromium answers).
    pub(crate) asked: u32,
    pub(crate) width: u32,
    pub(crate) height: u32,
    /// `RENDERBUFFER_SAMPLES`: 0 for single-sampled storage.
    pub(crate) samples: u32,
    /// The GPU texture and a view of it; `None` for a zero-sized renderbuffer.
    pub(crate) gpu: Option<(wgpu::Texture, wgpu::TextureView)>,
}

/// A renderbuffer object.
#[derive(Default)]
pub(crate) struct RenderbufferObject {
    pub(crate) bound_once: bool,
    pub(crate) storage: Option<RenderbufferStorage>,
}
