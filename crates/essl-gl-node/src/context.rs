//! [`NativeContext`]: one essl-gl [`Context`] as JavaScript holds it, its lifetime
//! (`destroy`, `resize`, a lost context) and the conversions every call shares.

use essl_gl::{Context, ContextAttributes};
use napi_derive::napi;

use crate::error::BindingError;
use crate::registry::{self, Handle, Kind};

/// The attributes of `getContext(type, attributes)` (WebGL's `WebGLContextAttributes`), as
/// the JavaScript side passes them: every member present.
#[napi(object)]
#[derive(Clone, Copy, Debug)]
pub struct Attributes {
    /// An alpha channel.
    pub alpha: bool,
    /// A depth buffer.
    pub depth: bool,
    /// A stencil buffer.
    pub stencil: bool,
    /// Multisampling.
    pub antialias: bool,
    /// Premultiplied alpha (kept and reported).
    pub premultiplied_alpha: bool,
    /// Whether the drawing buffer survives a frame's end.
    pub preserve_drawing_buffer: bool,
    /// Kept and reported.
    pub fail_if_major_performance_caveat: bool,
}

impl From<Attributes> for ContextAttributes {
    fn from(a: Attributes) -> ContextAttributes {
        ContextAttributes {
            alpha: a.alpha,
            depth: a.depth,
            stencil: a.stencil,
            antialias: a.antialias,
            premultiplied_alpha: a.premultiplied_alpha,
            preserve_drawing_buffer: a.preserve_drawing_buffer,
            fail_if_major_performance_caveat: a.fail_if_major_performance_caveat,
        }
    }
}

impl From<ContextAttributes> for Attributes {
    fn from(a: ContextAttributes) -> Attributes {
        Attributes {
            alpha: a.alpha,
            depth: a.depth,
            stencil: a.stencil,
            antialias: a.antialias,
            premultiplied_alpha: a.premultiplied_alpha,
            preserve_drawing_buffer: a.preserve_drawing_buffer,
            fail_if_major_performance_caveat: a.fail_if_major_performance_caveat,
        }
    }
}

/// A WebGL context of essl-gl, as the JavaScript classes `WebGL2RenderingContext` and
/// `WebGLRenderingContext` call it. Its methods take arguments already converted as WebIDL
/// converts them (numbers, booleans, strings, typed arrays, object ids; 0 for `null`).
#[napi]
pub struct NativeContext {
    /// `None` once destroyed.
    pub(crate) ctx: Option<Context>,
    /// The ids this context registered, forgotten when it is destroyed.
    pub(crate) ids: Vec<u32>,
    /// Major version: 1 or 2.
    pub(crate) version: u32,
}

#[napi]
impl NativeContext {
    /// A context of `width` × `height` (each at least 1) with `attributes`, WebGL `version`
    /// 1 or 2. Fails with an error naming what to install when there is no Vulkan adapter.
    #[napi(constructor)]
    pub fn new(
        width: u32,
        height: u32,
        attributes: Attributes,
        version: u32,
    ) -> napi::Result<Self> {
        let attributes: ContextAttributes = attributes.into();
        let (w, h) = (width.max(1), height.max(1));
        // A canvas larger than the device allows gets a smaller drawing buffer (WebGL §2.2):
        // as large as it allows in each dimension, as Chromium makes it.
        let mut ctx = match Context::with_attributes(w, h, attributes) {
            Err(essl_gl::ContextError::InvalidSize { max, .. }) => {
                Context::with_attributes(w.min(max), h.min(max), attributes)
            }
            other => other,
        }
        .map_err(BindingError::from)?;
        if version == 1 {
            ctx.set_webgl1();
        }
        Ok(NativeContext {
            ctx: Some(ctx),
            ids: Vec::new(),
            version,
        })
    }

    /// Frees the context's GPU device and memory now; later calls do nothing.
    #[napi(catch_unwind)]
    pub fn destroy(&mut self) {
        if let Some(ctx) = self.ctx.take() {
            drop(ctx);
        }
        registry::forget(&self.ids);
        self.ids.clear();
    }

    /// The WebGL version the context was made for: 1 or 2.
    #[napi(getter)]
    pub fn version(&self) -> u32 {
        self.version
    }

    /// Whether [`NativeContext::destroy`] ran.
    #[napi(getter)]
    pub fn destroyed(&self) -> bool {
        self.ctx.is_none()
    }

    /// Gives the drawing buffer a new size (a canvas's `width` or `height` set), each at most
    /// `MAX_TEXTURE_SIZE` (WebGL §2.2: a smaller drawing buffer where the size cannot be had).
    #[napi(catch_unwind)]
    pub fn resize(&mut self, width: u32, height: u32) -> napi::Result<()> {
        let gl = self.gl()?;
        let max = gl
            .get_parameter(essl_gl::gl::MAX_TEXTURE_SIZE)
            .and_then(|p| p.as_int())
            .map_or(u32::MAX, |m| m as u32);
        gl.resize_drawing_buffer(width.clamp(1, max), height.clamp(1, max));
        Ok(())
    }

    /// `drawingBufferWidth`.
    #[napi(getter)]
    pub fn drawing_buffer_width(&self) -> u32 {
        self.ctx.as_ref().map_or(0, Context::drawing_buffer_width)
    }

    /// `drawingBufferHeight`.
    #[napi(getter)]
    pub fn drawing_buffer_height(&self) -> u32 {
        self.ctx.as_ref().map_or(0, Context::drawing_buffer_height)
    }

    /// The attributes the context was made with (`getContextAttributes`).
    #[napi(catch_unwind)]
    pub fn get_context_attributes(&self) -> Option<Attributes> {
        self.ctx.as_ref().map(|c| c.get_context_attributes().into())
    }

    /// Ends a frame as a browser does when a task that drew returns: queries and fences
    /// become available; a `composited` canvas (one in a document) has its drawing buffer
    /// cleared unless `preserveDrawingBuffer`, an offscreen one keeps it.
    #[napi(catch_unwind)]
    pub fn present(&mut self, composited: bool) -> napi::Result<()> {
        let c = self.gl()?;
        if composited {
            c.present();
        } else {
            c.present_offscreen();
        }
        Ok(())
    }

    /// The adapter's name and driver (`"llvmpipe (LLVM 15.0.6, 256 bits)"`).
    #[napi(catch_unwind)]
    pub fn adapter(&self) -> String {
        self.ctx.as_ref().map_or(String::new(), |c| {
            let i = c.adapter_info();
            format!("{} ({})", i.name, i.driver_info)
        })
    }

    /// The message of the first error `getError` would return, if any.
    #[napi(catch_unwind)]
    pub fn error_message(&self) -> Option<String> {
        self.ctx.as_ref().and_then(Context::error_message)
    }

    /// Validation errors wgpu reported (a bug in essl-gl if not empty).
    #[napi(catch_unwind)]
    pub fn backend_errors(&self) -> Vec<String> {
        self.ctx
            .as_ref()
            .map_or_else(Vec::new, Context::backend_errors)
    }

    /// How many object ids are registered in this thread (all contexts).
    #[napi(catch_unwind)]
    pub fn registered_objects() -> u32 {
        registry::len() as u32
    }
}

impl NativeContext {
    /// The live context, or the error for a destroyed one.
    pub(crate) fn gl(&mut self) -> napi::Result<&mut Context> {
        self.ctx
            .as_mut()
            .ok_or_else(|| BindingError::Destroyed.into())
    }

    /// The id of a new object, remembered for `destroy`.
    pub(crate) fn register(&mut self, h: Handle) -> u32 {
        let id = registry::id_of(h);
        self.ids.push(id);
        id
    }

    /// Object argument `id` of kind `T`: `Some(None)` for `null` (0), `None` when the id
    /// names nothing any more (an object of a destroyed context) — recorded as
    /// `INVALID_OPERATION`, as WebGL answers an object that is not this context's.
    pub(crate) fn arg<T: Kind>(&self, id: u32, function: &str) -> Option<Option<T>> {
        if id == 0 {
            return Some(None);
        }
        match registry::handle(id).and_then(T::unwrap) {
            Some(o) => Some(Some(o)),
            None => {
                if let Some(c) = &self.ctx {
                    c.synthesize_error(
                        essl_gl::gl::INVALID_OPERATION,
                        function,
                        "an object of a context that is gone",
                    );
                }
                None
            }
        }
    }

    /// A non-null object argument (the JavaScript side refuses `null` with a `TypeError`).
    pub(crate) fn req<T: Kind>(&self, id: u32, function: &str) -> Option<T> {
        self.arg(id, function).flatten()
    }

    /// Records `INVALID_VALUE` for a `srcOffset`/`srcLength` past the end of an array.
    pub(crate) fn past_end(&self, function: &str) {
        if let Some(c) = &self.ctx {
            c.synthesize_error(
                essl_gl::gl::INVALID_VALUE,
                function,
                "offset or length past the end of the array",
            );
        }
    }
}
