//! The ids JavaScript holds for WebGL objects.
//!
//! A `WebGLBuffer` in JavaScript keeps a number; this registry maps it to essl-gl's handle
//! and back, so that an answer naming an object (`getParameter(ARRAY_BUFFER_BINDING)`)
//! comes back as the id of the object JavaScript bound, and the JavaScript side returns
//! that very object. Ids are unique in the thread (a Node.js main thread or worker) and never
//! reused, so a handle of another context reaches essl-gl as what it is — an object of
//! another context, `INVALID_OPERATION` — rather than as some object of this one.

use std::cell::RefCell;
use std::collections::HashMap;

use essl_gl::{
    Buffer, Framebuffer, Program, Query, Renderbuffer, Sampler, Shader, Sync, Texture,
    TransformFeedback, UniformLocation, VertexArray,
};

/// Any of essl-gl's handles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Handle {
    Buffer(Buffer),
    Framebuffer(Framebuffer),
    Program(Program),
    Query(Query),
    Renderbuffer(Renderbuffer),
    Sampler(Sampler),
    Shader(Shader),
    Sync(Sync),
    Texture(Texture),
    TransformFeedback(TransformFeedback),
    UniformLocation(UniformLocation),
    VertexArray(VertexArray),
}

#[derive(Default)]
struct Registry {
    next: u32,
    by_id: HashMap<u32, Handle>,
    by_handle: HashMap<Handle, u32>,
}

thread_local! {
    static REGISTRY: RefCell<Registry> = RefCell::new(Registry::default());
}

/// The id of `handle`, registering it the first time.
pub(crate) fn id_of(handle: Handle) -> u32 {
    REGISTRY.with_borrow_mut(|r| {
        if let Some(&id) = r.by_handle.get(&handle) {
            return id;
        }
        r.next += 1;
        let id = r.next;
        r.by_id.insert(id, handle);
        r.by_handle.insert(handle, id);
        id
    })
}

/// The handle of `id`; `None` for 0 (JavaScript's `null`) and for an id that was forgotten
/// (its context destroyed).
pub(crate) fn handle(id: u32) -> Option<Handle> {
    if id == 0 {
        return None;
    }
    REGISTRY.with_borrow(|r| r.by_id.get(&id).copied())
}

/// Forgets ids (a destroyed context's objects).
pub(crate) fn forget(ids: &[u32]) {
    REGISTRY.with_borrow_mut(|r| {
        for id in ids {
            if let Some(h) = r.by_id.remove(id) {
                r.by_handle.remove(&h);
            }
        }
    });
}

/// How many ids are registered (the tests watch it stay flat over created and destroyed
/// contexts).
pub(crate) fn len() -> usize {
    REGISTRY.with_borrow(|r| r.by_id.len())
}

/// A kind of handle: how a handle is taken out of [`Handle`].
pub(crate) trait Kind: Sized + Copy {
    fn unwrap(h: Handle) -> Option<Self>;
}

macro_rules! kinds {
    ($($t:ident),*) => {
        $(impl Kind for $t {
            fn unwrap(h: Handle) -> Option<Self> {
                match h {
                    Handle::$t(x) => Some(x),
                    _ => None,
                }
            }
        })*
    };
}

kinds!(
    Buffer,
    Framebuffer,
    Program,
    Query,
    Renderbuffer,
    Sampler,
    Shader,
    Sync,
    Texture,
    TransformFeedback,
    UniformLocation,
    VertexArray
);
