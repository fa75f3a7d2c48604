//! Typed handles (`Buffer`, `Texture`, …): the id of the context that created the object and
//! where it lives in its [`Table`](super::Table). A handle from another context, or one whose
//! object was deleted, is detected (WebGL's `INVALID_OPERATION`) rather than aliasing a newer
//! object.

use std::sync::atomic::{AtomicU32, Ordering};

/// Where an object lives in its table: an index and the generation of that slot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub(crate) struct Id {
    pub(crate) index: u32,
    pub(crate) generation: u32,
}

static NEXT_CONTEXT_ID: AtomicU32 = AtomicU32::new(1);

/// A fresh context id, never reused within the process.
pub(crate) fn next_context_id() -> u32 {
    NEXT_CONTEXT_ID.fetch_add(1, Ordering::Relaxed)
}

macro_rules! handle {
    ($(#[$doc:meta])* $name:ident) => {
        $(#[$doc])*
        ///
        /// A small `Copy` value; it is only meaningful to the context that created it.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub struct $name {
            pub(crate) ctx: u32,
            pub(crate) id: Id,
        }
    };
}

handle! {
    /// A buffer object (`WebGLBuffer`).
    Buffer
}
handle! {
    /// A texture object (`WebGLTexture`).
    Texture
}
handle! {
    /// A vertex array object (`WebGLVertexArrayObject`).
    VertexArray
}
handle! {
    /// A program object (`WebGLProgram`).
    Program
}
handle! {
    /// A shader object (`WebGLShader`).
    Shader
}
handle! {
    /// A framebuffer object (`WebGLFramebuffer`).
    Framebuffer
}
handle! {
    /// A renderbuffer object (`WebGLRenderbuffer`).
    Renderbuffer
}
handle! {
    /// A sampler object (`WebGLSampler`).
    Sampler
}
handle! {
    /// A query object (`WebGLQuery`).
    Query
}
handle! {
    /// A sync object (`WebGLSync`), made by [`Context::fence_sync`](crate::Context::fence_sync).
    Sync
}
handle! {
    /// A transform feedback object (`WebGLTransformFeedback`).
    TransformFeedback
}

/// The location of a uniform (or of one element of a uniform array) in a linked program
/// (`WebGLUniformLocation`). It is invalidated when the program is linked again.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct UniformLocation {
    pub(crate) ctx: u32,
    pub(crate) program: Id,
    /// Which link of the program the location belongs to.
    pub(crate) link: u64,
    /// Index into the program's active uniforms.
    pub(crate) uniform: u32,
    /// The array element the location starts at.
    pub(crate) element: u32,
}
