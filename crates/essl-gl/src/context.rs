//! The [`Context`]: a wgpu device and queue, an offscreen default framebuffer, and all of
//! WebGL2's state.

use std::sync::{Arc, Mutex};

use crate::bindings::Bindings;
use crate::caches::Caches;
use crate::error::{error_name, ContextError, ErrorState};
use crate::extensions::{Extension, Extensions};
use crate::frame::Frame;
use crate::framebuffer::{ContextAttributes, DefaultFramebuffer};
use crate::gl;
use crate::gpu::Gpu;
use crate::objects::{next_context_id, Objects};
use crate::program::Linker;
use crate::state::{PixelStore, RenderState};
use crate::vertex_array::VertexArrayObject;

/// The most vertex attributes a program may use (`MAX_VERTEX_ATTRIBS`).
pub const MAX_VERTEX_ATTRIBS: u32 = 16;

/// The number of texture units (`MAX_COMBINED_TEXTURE_IMAGE_UNITS`), WebGL2's minimum.
pub const MAX_TEXTURE_UNITS: u32 = 32;

/// The number of indexed `UNIFORM_BUFFER` binding points (`MAX_UNIFORM_BUFFER_BINDINGS`):
/// Chromium's on ANGLE/SwiftShader (WebGL 2's minimum is 24). They are the context's state
/// alone; what one program may use at once is `MAX_COMBINED_UNIFORM_BLOCKS`.
pub const MAX_UNIFORM_BUFFER_BINDINGS: u32 = 72;

/// Limits of the context that depend on the device.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Limits {
    /// `MAX_VERTEX_ATTRIBS`: 16, or fewer where the device has fewer vertex buffers.
    pub(crate) max_vertex_attribs: u32,
    /// `MAX_COLOR_ATTACHMENTS` and `MAX_DRAW_BUFFERS`: 8, or fewer where the device cannot
    /// write 8 targets of 16 bytes a sample (WebGL2's minimum is 4).
    pub(crate) max_color_attachments: u32,
}

/// A WebGL2 rendering context drawing into an offscreen framebuffer, on wgpu's Vulkan backend.
///
/// Method names are WebGL2's in snake_case and enums are GL's `u32` constants from
/// [`gl`](crate::gl). Misuse never panics: it records WebGL's error (read it with
/// [`Context::get_error`]) and does nothing, as a browser would.
///
/// Commands are recorded into one command encoder and submitted when the context needs the
/// GPU to have executed them ([`Context::read_pixels`], [`Context::finish`], [`Context::flush`]).
///
/// The context is a few owned parts, each in its module and each keeping its own invariants:
/// the objects and the references between them ([`Objects`]), what is bound ([`Bindings`]),
/// the fixed-function state ([`RenderState`], [`PixelStore`]), the batch being recorded
/// ([`Frame`]), derived GPU objects ([`Caches`]), the linker's settings ([`Linker`]) and the
/// uniform-value checks ([`Validation`](crate::validation::Validation)).
pub struct Context {
    pub(crate) id: u32,
    pub(crate) gpu: Gpu,
    pub(crate) limits: Limits,
    pub(crate) errors: ErrorState,
    pub(crate) backend_errors: Arc<Mutex<Vec<String>>>,
    pub(crate) fb: DefaultFramebuffer,
    /// The extensions `get_extension` has turned on.
    pub(crate) extensions: Extensions,
    /// The largest point the device draws, measured the first time it is asked for.
    pub(crate) largest_point: std::cell::OnceCell<f32>,
    pub(crate) frame: Frame,
    pub(crate) objects: Objects,
    pub(crate) bindings: Bindings,
    pub(crate) state: RenderState,
    pub(crate) pixel_store: PixelStore,
    pub(crate) caches: Caches,
    pub(crate) linker: Linker,
    /// The uniform-value checks ([`Context::set_validation`]) and their warnings.
    pub(crate) validation: crate::validation::Validation,
    /// Whether this is a WebGL 1 context, and its WebGL 1 extensions.
    pub(crate) webgl1: crate::webgl1::Webgl1,
    /// How many times [`Context::present`] ran: queries and fences ended before one are
    /// answered after it.
    pub(crate) presents: u64,
    /// `gl_DrawID`: the index of the draw a multi-draw call is encoding, 0 for other draws
    /// (`WEBGL_multi_draw`, `draw/multi.rs`).
    pub(crate) draw_id: i32,
}

/// The wgpu features essl-gl asks for when the adapter has them: vertex shaders that write
/// storage buffers (transform feedback), `DEPTH32F_STENCIL8`, filterable and blendable 32-bit
/// floats, and `R11F_G11F_B10F` as a render target (`EXT_color_buffer_float`).
const WANTED_FEATURES: wgpu::Features = wgpu::Features::VERTEX_WRITABLE_STORAGE
    .union(wgpu::Features::DEPTH32FLOAT_STENCIL8)
    .union(wgpu::Features::FLOAT32_FILTERABLE)
    .union(wgpu::Features::FLOAT32_BLENDABLE)
    .union(wgpu::Features::RG11B10UFLOAT_RENDERABLE)
    .union(wgpu::Features::CLIP_DISTANCES)
    .union(wgpu::Features::DEPTH_CLIP_CONTROL)
    .union(wgpu::Features::POLYGON_MODE_LINE);

/// The Vulkan adapter every context of the process takes its device from, found once: creating
/// a wgpu instance loads the Vulkan loader and its drivers (lavapipe: LLVM) and enumerates the
/// adapters, most of the time a context took to create.
fn adapter() -> Result<wgpu::Adapter, ContextError> {
    static ADAPTER: std::sync::OnceLock<Result<wgpu::Adapter, String>> = std::sync::OnceLock::new();
    ADAPTER
        .get_or_init(|| {
            quiet_vulkan_loader();
            let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
            desc.backends = wgpu::Backends::VULKAN;
            desc.flags = wgpu::InstanceFlags::empty();
            let instance = wgpu::Instance::new(desc);
            pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::HighPerformance,
                force_fallback_adapter: false,
                compatible_surface: None,
                apply_limit_buckets: false,
            }))
            .map_err(|e| e.to_string())
        })
        .clone()
        .map_err(ContextError::NoAdapter)
}

impl Context {
    /// Creates a context with an offscreen default framebuffer of `width` × `height` pixels
    /// and the default [`ContextAttributes`] (8-bit RGBA, 24-bit depth, no stencil, no
    /// multisampling).
    ///
    /// It uses wgpu's Vulkan backend and takes the adapter Vulkan offers, a software one
    /// (Mesa's lavapipe) included. With none, the error says what to install.
    pub fn new(width: u32, height: u32) -> Result<Context, ContextError> {
        Context::with_attributes(width, height, ContextAttributes::default())
    }

    /// Creates a context whose default framebuffer has the given attributes
    /// (`canvas.getContext("webgl2", attributes)`).
    pub fn with_attributes(
        width: u32,
        height: u32,
        attributes: ContextAttributes,
    ) -> Result<Context, ContextError> {
        let adapter = adapter()?;
        let info = adapter.get_info();
        let downlevel = adapter.get_downlevel_capabilities().flags;
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("essl-gl"),
            required_features: adapter.features() & WANTED_FEATURES,
            required_limits: adapter.limits(),
            experimental_features: wgpu::ExperimentalFeatures::disabled(),
            memory_hints: wgpu::MemoryHints::Performance,
            trace: wgpu::Trace::Off,
        }))
        .map_err(|source| ContextError::RequestDevice {
            adapter: info.name.clone(),
            source,
        })?;
        Context::on_device(device, queue, width, height, attributes, downlevel)
    }

    /// Creates a context on a caller's wgpu device and queue (an application that already
    /// renders with wgpu). essl-gl uses the device's features where they help (transform
    /// feedback needs `VERTEX_WRITABLE_STORAGE`) and records wgpu's validation errors in
    /// [`Context::backend_errors`] instead of panicking. The device says nothing of its
    /// adapter's downlevel abilities, so `EXT_polygon_offset_clamp` is not offered.
    pub fn from_device(
        device: wgpu::Device,
        queue: wgpu::Queue,
        width: u32,
        height: u32,
        attributes: ContextAttributes,
    ) -> Result<Context, ContextError> {
        let none = wgpu::DownlevelFlags::empty();
        Context::on_device(device, queue, width, height, attributes, none)
    }

    /// [`Context::from_device`] with the adapter's downlevel abilities.
    fn on_device(
        device: wgpu::Device,
        queue: wgpu::Queue,
        width: u32,
        height: u32,
        attributes: ContextAttributes,
        downlevel: wgpu::DownlevelFlags,
    ) -> Result<Context, ContextError> {
        let info = device.adapter_info();
        let limits = device.limits();
        let max = limits.max_texture_dimension_2d;
        if width == 0 || height == 0 || width > max || height > max {
            return Err(ContextError::InvalidSize { width, height, max });
        }
        // wgpu's default handler panics on a validation error; essl-gl validates everything
        // itself, so an error here is a bug in essl-gl: keep it for `backend_errors`.
        let backend_errors = Arc::new(Mutex::new(Vec::new()));
        let sink = backend_errors.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            // wgpu's own text is "Validation Error"; the causes say what was wrong.
            let mut text = e.to_string();
            let mut cause = std::error::Error::source(&e);
            while let Some(c) = cause {
                text.push_str(&format!(": {c}"));
                cause = c.source();
            }
            if let Ok(mut v) = sink.lock() {
                v.push(text);
            }
        }));
        let max_vertex_attribs = MAX_VERTEX_ATTRIBS
            .min(limits.max_vertex_attributes)
            .min(limits.max_vertex_buffers);
        let max_color_attachments = crate::MAX_COLOR_ATTACHMENTS
            .min(limits.max_color_attachments)
            .min(limits.max_color_attachment_bytes_per_sample / 16)
            .max(4);
        let gpu = Gpu {
            device,
            queue,
            info,
            limits,
            downlevel,
        };
        let fb = DefaultFramebuffer::new(&gpu, width, height, attributes);
        let mut ctx = Context {
            id: next_context_id(),
            limits: Limits {
                max_vertex_attribs,
                max_color_attachments,
            },
            errors: ErrorState::default(),
            backend_errors,
            fb,
            extensions: Extensions::default(),
            largest_point: std::cell::OnceCell::new(),
            frame: Frame::new(),
            objects: Objects::new(max_vertex_attribs),
            bindings: Bindings::new(MAX_UNIFORM_BUFFER_BINDINGS, MAX_TEXTURE_UNITS),
            state: RenderState::new(width, height, max_vertex_attribs),
            pixel_store: PixelStore::default(),
            caches: Caches::default(),
            linker: Linker::default(),
            validation: Default::default(),
            presents: 0,
            draw_id: 0,
            webgl1: Default::default(),
            gpu,
        };
        if !attributes.alpha {
            ctx.clear_drawing_buffer();
        }
        Ok(ctx)
    }

    /// The attributes the default framebuffer was made with (`getContextAttributes`).
    pub fn get_context_attributes(&self) -> ContextAttributes {
        self.fb.attributes
    }

    /// Whether the context is lost (`isContextLost`): never, as an offscreen wgpu device is
    /// not taken away; a device lost to a driver fault shows as [`Context::backend_errors`].
    pub fn is_context_lost(&self) -> bool {
        false
    }

    /// The adapter the context renders with (name, driver, device type).
    pub fn adapter_info(&self) -> &wgpu::AdapterInfo {
        &self.gpu.info
    }

    /// The wgpu device, for interoperation.
    pub fn device(&self) -> &wgpu::Device {
        &self.gpu.device
    }

    /// The wgpu queue, for interoperation.
    pub fn queue(&self) -> &wgpu::Queue {
        &self.gpu.queue
    }

    /// The width of the default framebuffer (`drawingBufferWidth`).
    pub fn drawing_buffer_width(&self) -> u32 {
        self.fb.width
    }

    /// The height of the default framebuffer (`drawingBufferHeight`).
    pub fn drawing_buffer_height(&self) -> u32 {
        self.fb.height
    }

    /// Returns the first error recorded since the last call (or `NO_ERROR`) and clears it.
    pub fn get_error(&self) -> u32 {
        self.errors.take()
    }

    /// A description of the error [`Context::get_error`] would return, as a browser's console
    /// would print it (`"drawArrays: no program in use"`).
    pub fn error_message(&self) -> Option<String> {
        self.errors.message()
    }

    /// Validation errors wgpu reported. essl-gl checks WebGL's rules before calling wgpu, so
    /// any error here is a bug in essl-gl; tests assert this stays empty.
    pub fn backend_errors(&self) -> Vec<String> {
        self.backend_errors
            .lock()
            .map(|v| v.clone())
            .unwrap_or_default()
    }

    /// Submits the recorded commands to the GPU without waiting (`flush`).
    pub fn flush(&mut self) {
        if !self.frame.is_empty() {
            self.frame.submit(&self.gpu, |_| {});
        }
    }

    /// Submits the recorded commands and waits until the GPU has executed them (`finish`).
    pub fn finish(&mut self) {
        self.flush();
        let _ = self.gpu.device.poll(wgpu::PollType::wait_indefinitely());
    }

    /// Records WebGL error `code` for `function` as a binding does for what only it can see
    /// (a `srcOffset` past the end of a JavaScript array, an object of a context that is
    /// gone): the first error sticks, as with every error essl-gl records.
    pub fn synthesize_error(&self, code: u32, function: &str, what: &str) {
        self.error(code, function, what);
    }

    /// Records a GL error (the first one sticks) with a message naming the function.
    pub(crate) fn error(&self, code: u32, function: &str, what: impl std::fmt::Display) {
        self.errors.record(code, || {
            format!("{}: {}: {}", function, error_name(code), what)
        });
    }

    /// The vertex array object that is bound (the default one for `None`).
    pub(crate) fn vao(&self) -> &VertexArrayObject {
        self.objects.vertex_array(self.bindings.vertex_array())
    }

    /// Mutable [`Context::vao`] (for the state that holds no reference).
    pub(crate) fn vao_mut(&mut self) -> &mut VertexArrayObject {
        self.objects.vertex_array_mut(self.bindings.vertex_array())
    }

    /// Checks that a handle belongs to this context, recording `INVALID_OPERATION` if not.
    pub(crate) fn owns(&self, ctx: u32, function: &str) -> bool {
        if ctx != self.id {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "object from another context",
            );
            false
        } else {
            true
        }
    }
}

impl Context {
    /// The extensions this context offers (`getSupportedExtensions`).
    pub fn get_supported_extensions(&self) -> Vec<&'static str> {
        self.supported().iter().map(|e| e.name()).collect()
    }

    fn supported(&self) -> Vec<Extension> {
        let features = self.gpu.device.features();
        let mut v = if self.webgl1.on {
            crate::webgl1::WEBGL1_EXTENSIONS.to_vec()
        } else {
            let mut v = vec![
                Extension::ColorBufferFloat,
                Extension::ColorBufferHalfFloat,
                Extension::DrawBuffersIndexed,
                Extension::StencilTexturing,
                Extension::ConservativeDepth,
                Extension::NoperspectiveInterpolation,
            ];
            if features.contains(wgpu::Features::CLIP_DISTANCES) {
                v.push(Extension::ClipCullDistance);
            }
            v
        };
        // Both contexts.
        if self.blends_float32() {
            v.push(Extension::FloatBlend);
        }
        if features.contains(wgpu::Features::FLOAT32_FILTERABLE) {
            v.push(Extension::TextureFloatLinear);
        }
        v.extend(crate::extensions::COMPRESSED_EXTENSIONS);
        v.extend([
            Extension::TextureFilterAnisotropic,
            Extension::DebugShaders,
            Extension::DebugRendererInfo,
            Extension::ClipControl,
            Extension::MultiDraw,
        ]);
        v.extend(self.raster_extensions());
        v
    }

    /// Turns on `e` where it means the same in both contexts; false for an extension of one
    /// context only.
    fn turn_on_in_either_context(&mut self, e: Extension) -> bool {
        let x = &mut self.extensions;
        match e {
            // Nothing to turn on: get_translated_shader_source answers in any case.
            Extension::DebugShaders => {}
            Extension::TextureFilterAnisotropic => x.anisotropic = true,
            Extension::ClipControl => x.clip_control = true,
            Extension::PolygonOffsetClamp => x.polygon_offset_clamp = true,
            Extension::DepthClamp => x.depth_clamp = true,
            Extension::PolygonMode => x.polygon_mode = true,
            Extension::DebugRendererInfo => x.debug_renderer_info = true,
            Extension::MultiDraw => {
                x.multi_draw = true;
                // WebGL 1: its instanced calls need ANGLE_instanced_arrays, which it turns on.
                if self.webgl1.on {
                    self.enable_webgl1_extension(Extension::AngleInstancedArrays);
                }
                self.enable_shader_extension(essl::Extension::WebglMultiDraw);
            }
            _ => return x.compressed.insert(e),
        }
        true
    }

    /// Lets the shaders compiled from now on use `e`.
    fn enable_shader_extension(&mut self, e: essl::Extension) {
        let shaders = &mut self.linker.shaders.extensions;
        if !shaders.contains(&e) {
            shaders.push(e);
        }
    }

    /// The rasterization extensions the adapter can do (`state/raster.rs`).
    fn raster_extensions(&self) -> Vec<Extension> {
        let features = self.gpu.device.features();
        let downlevel = &self.gpu.downlevel;
        [
            (
                downlevel.contains(wgpu::DownlevelFlags::DEPTH_BIAS_CLAMP),
                Extension::PolygonOffsetClamp,
            ),
            (
                features.contains(wgpu::Features::DEPTH_CLIP_CONTROL),
                Extension::DepthClamp,
            ),
            (
                features.contains(wgpu::Features::POLYGON_MODE_LINE),
                Extension::PolygonMode,
            ),
        ]
        .into_iter()
        .filter_map(|(on, e)| on.then_some(e))
        .collect()
    }

    /// Whether 32-bit float attachments blend (`EXT_float_blend`): the adapter's
    /// `FLOAT32_BLENDABLE`.
    pub(crate) fn blends_float32(&self) -> bool {
        let features = self.gpu.device.features();
        features.contains(wgpu::Features::FLOAT32_BLENDABLE)
    }

    /// Turns an extension on and returns it (`getExtension`); `None` for a name this context
    /// does not offer (names compare case-insensitively, as in WebGL).
    pub fn get_extension(&mut self, name: &str) -> Option<Extension> {
        let e = self
            .supported()
            .into_iter()
            .find(|e| e.name().eq_ignore_ascii_case(name))?;
        if self.turn_on_in_either_context(e) {
            return Some(e);
        }
        if self.webgl1.on {
            self.enable_webgl1_extension(e);
            return Some(e);
        }
        let x = &mut self.extensions;
        match e {
            // EXT_color_buffer_half_float makes the 16-bit formats renderable, which
            // EXT_color_buffer_float also does; essl-gl tracks the two together.
            Extension::ColorBufferFloat | Extension::ColorBufferHalfFloat => {
                x.color_buffer_float = true
            }
            // Blending 32-bit floats depends on the adapter only (`blends_float32`).
            Extension::FloatBlend => {}
            Extension::TextureFloatLinear => x.texture_float_linear = true,
            Extension::DrawBuffersIndexed => x.draw_buffers_indexed = true,
            Extension::StencilTexturing => x.stencil_texturing = true,
            Extension::ClipCullDistance => {
                x.clip_cull_distance = true;
                self.enable_shader_extension(essl::Extension::WebglClipCullDistance);
            }
            Extension::ConservativeDepth => {
                self.enable_shader_extension(essl::Extension::ExtConservativeDepth)
            }
            Extension::NoperspectiveInterpolation => {
                self.enable_shader_extension(essl::Extension::NvShaderNoperspectiveInterpolation)
            }
            webgl1 => self.enable_webgl1_extension(webgl1),
        }
        Some(e)
    }
}

/// The Vulkan loader prints "XDG_RUNTIME_DIR is invalid or not set in the environment" on
/// stderr when that variable is unset; give it a private directory first, unless the
/// environment already has one. Called once, before the process's one wgpu instance
/// ([`adapter`]).
fn quiet_vulkan_loader() {
    if std::env::var_os("XDG_RUNTIME_DIR").is_some() {
        return;
    }
    let dir = std::env::temp_dir().join(format!("essl-gl-runtime-{}", std::process::id()));
    if std::fs::create_dir_all(&dir).is_ok() {
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let _ = std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700));
        }
        std::env::set_var("XDG_RUNTIME_DIR", &dir);
    }
}
