//! GPU objects derived from the context's state and kept for reuse: render pipelines, shader
//! modules and bind groups ([`PipelineCache`]), wgpu samplers by parameters, the placeholder
//! textures that stand for a missing or incomplete texture, and the readback buffer.
//!
//! Nothing here is GL state: any entry could be dropped and made again from the state, so
//! the caches keep no invariant with the rest of the context.

use crate::pipeline::PipelineCache;
use crate::texture::{Dummies, SamplerCache};

/// The context's caches.
#[derive(Default)]
pub(crate) struct Caches {
    pub(crate) pipelines: PipelineCache,
    pub(crate) samplers: SamplerCache,
    pub(crate) dummies: Dummies,
    /// The buffer `read_pixels` copies into, grown as needed.
    pub(crate) readback: Option<wgpu::Buffer>,
    /// The 1×1 depth image a draw that makes no fragments (transform feedback with
    /// `RASTERIZER_DISCARD`) renders into.
    pub(crate) discard: Option<wgpu::TextureView>,
}
