//! The [`Context`]: a wgpu device and queue, an offscreen default framebuffer, and all of
//! WebGL2's state.

use std::sync::{Arc, Mutex};

use crate::bindings::Bindings;
use crate::caches::Caches;
use crate::error::{error_name, ContextError, ErrorState};
use crate::frame::Frame;
use crate::gl;
use crate::objects::{next_context_id, Objects};
use crate::program::Linker;
use crate::state::{PixelStore, RenderState};
use crate::vertex_array::VertexArrayObject;

/// The colour format of the default framebuffer: 8-bit RGBA, linear (not sRGB), as WebGL's
/// default drawing buffer.
pub const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// The depth format of the default framebuffer: wgpu's `Depth24Plus`, at least 24 bits of
/// depth (Vulkan picks `X8_D24_UNORM_PACK32` or `D32_SFLOAT`); no stencil, as WebGL's default
/// `{ stencil: false }`.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth24Plus;

/// The most vertex attributes a program may use (`MAX_VERTEX_ATTRIBS`).
pub const MAX_VERTEX_ATTRIBS: u32 = 16;

/// The number of texture units (`MAX_COMBINED_TEXTURE_IMAGE_UNITS`), WebGL2's minimum.
pub const MAX_TEXTURE_UNITS: u32 = 32;

/// The number of indexed `UNIFORM_BUFFER` binding points (`MAX_UNIFORM_BUFFER_BINDINGS`),
/// WebGL2's minimum.
pub const MAX_UNIFORM_BUFFER_BINDINGS: u32 = 24;

/// The GPU objects the context renders with.
pub(crate) struct Gpu {
    pub(crate) device: wgpu::Device,
    pub(crate) queue: wgpu::Queue,
    pub(crate) info: wgpu::AdapterInfo,
    pub(crate) limits: wgpu::Limits,
    /// Whether 32-bit float textures may be filtered (`FLOAT32_FILTERABLE`); WebGL2 without
    /// `OES_texture_float_linear` treats them as unfilterable either way.
    pub(crate) _float32_filterable: bool,
}

/// The offscreen default framebuffer.
pub(crate) struct DefaultFramebuffer {
    pub(crate) width: u32,
    pub(crate) height: u32,
    pub(crate) color: wgpu::Texture,
    pub(crate) color_view: wgpu::TextureView,
    pub(crate) _depth: wgpu::Texture,
    pub(crate) depth_view: wgpu::TextureView,
}

/// Limits of the context that depend on the device.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Limits {
    /// `MAX_VERTEX_ATTRIBS`: 16, or fewer where the device has fewer vertex buffers.
    pub(crate) max_vertex_attribs: u32,
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
    pub(crate) frame: Frame,
    pub(crate) objects: Objects,
    pub(crate) bindings: Bindings,
    pub(crate) state: RenderState,
    pub(crate) pixel_store: PixelStore,
    pub(crate) caches: Caches,
    pub(crate) linker: Linker,
    /// The uniform-value checks ([`Context::set_validation`]) and their warnings.
    pub(crate) validation: crate::validation::Validation,
}

/// A step between lowering and installing a program: see [`Context::set_program_filter`].
pub type ProgramFilter = Box<
    dyn FnMut(essl::program::ProgramLayout) -> Result<essl::program::ProgramLayout, String> + Send,
>;

impl Context {
    /// Creates a context with an offscreen default framebuffer of `width` × `height` pixels:
    /// [`COLOR_FORMAT`] colour and [`DEPTH_FORMAT`] depth.
    ///
    /// It uses wgpu's Vulkan backend and takes the adapter Vulkan offers, a software one
    /// (Mesa's lavapipe) included. With none, the error says what to install.
    pub fn new(width: u32, height: u32) -> Result<Context, ContextError> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = wgpu::Backends::VULKAN;
        desc.flags = wgpu::InstanceFlags::empty();
        let instance = wgpu::Instance::new(desc);
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            force_fallback_adapter: false,
            compatible_surface: None,
            apply_limit_buckets: false,
        }))
        .map_err(|e| ContextError::NoAdapter(e.to_string()))?;
        let info = adapter.get_info();
        let adapter_limits = adapter.limits();
        let max = adapter_limits.max_texture_dimension_2d;
        if width == 0 || height == 0 || width > max || height > max {
            return Err(ContextError::InvalidSize { width, height, max });
        }
        let float32_filterable = adapter
            .features()
            .contains(wgpu::Features::FLOAT32_FILTERABLE);
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("essl-gl"),
            required_features: wgpu::Features::empty(),
            required_limits: adapter_limits.clone(),
            experimental_features: wgpu::ExperimentalFeatures::disabled(),
            memory_hints: wgpu::MemoryHints::Performance,
            trace: wgpu::Trace::Off,
        }))
        .map_err(|source| ContextError::RequestDevice {
            adapter: info.name.clone(),
            source,
        })?;

        // wgpu's default handler panics on a validation error; essl-gl validates everything
        // itself, so an error here is a bug in essl-gl: keep it for `backend_errors`.
        let backend_errors = Arc::new(Mutex::new(Vec::new()));
        let sink = backend_errors.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            if let Ok(mut v) = sink.lock() {
                v.push(e.to_string());
            }
        }));

        let limits = device.limits();
        let fb = DefaultFramebuffer::new(&device, width, height);
        let max_vertex_attribs = MAX_VERTEX_ATTRIBS
            .min(limits.max_vertex_attributes)
            .min(limits.max_vertex_buffers);
        let gpu = Gpu {
            device,
            queue,
            info,
            limits,
            _float32_filterable: float32_filterable,
        };
        let frame = Frame::new(&gpu);
        Ok(Context {
            id: next_context_id(),
            limits: Limits { max_vertex_attribs },
            errors: ErrorState::default(),
            backend_errors,
            fb,
            frame,
            objects: Objects::new(max_vertex_attribs),
            bindings: Bindings::new(MAX_UNIFORM_BUFFER_BINDINGS, MAX_TEXTURE_UNITS),
            state: RenderState::new(width, height, max_vertex_attribs),
            pixel_store: PixelStore::default(),
            caches: Caches::default(),
            linker: Linker::default(),
            validation: Default::default(),
            gpu,
        })
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
    pub fn get_error(&mut self) -> u32 {
        self.errors.take()
    }

    /// A description of the error [`Context::get_error`] would return, as a browser's console
    /// would print it (`"drawArrays: no program in use"`).
    pub fn error_message(&self) -> Option<&str> {
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

    /// Records a GL error (the first one sticks) with a message naming the function.
    pub(crate) fn error(&mut self, code: u32, function: &str, what: impl std::fmt::Display) {
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
    pub(crate) fn owns(&mut self, ctx: u32, function: &str) -> bool {
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

impl DefaultFramebuffer {
    fn new(device: &wgpu::Device, width: u32, height: u32) -> Self {
        let size = wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        };
        let color = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("essl-gl default colour"),
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: COLOR_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::COPY_SRC
                | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        });
        let depth = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("essl-gl default depth"),
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: DEPTH_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            view_formats: &[],
        });
        DefaultFramebuffer {
            width,
            height,
            color_view: color.create_view(&Default::default()),
            color,
            depth_view: depth.create_view(&Default::default()),
            _depth: depth,
        }
    }
}
