//! The default framebuffer ("drawing buffer") and the context attributes that shape it:
//! alpha, depth, stencil, antialias (a multisampled image resolved at the end of every
//! render pass), premultiplied alpha and whether the image is preserved across
//! [`Context::present`](crate::Context::present).

use crate::gl;
use crate::gpu::Gpu;

/// WebGL's `WebGLContextAttributes`: what the default framebuffer has, as given to
/// [`Context::with_attributes`](crate::Context::with_attributes) and returned by
/// [`Context::get_context_attributes`](crate::Context::get_context_attributes).
///
/// `Default` is WebGL's defaults except `antialias`, which is false so that images are
/// deterministic; ask for it to draw with 4× multisampling.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ContextAttributes {
    /// An alpha channel (`alpha`; true). Without one, alpha reads back as 1 and blending
    /// sees a destination alpha of 1.
    pub alpha: bool,
    /// A depth buffer of at least 16 bits (`depth`; true): essl-gl's has 24.
    pub depth: bool,
    /// An 8-bit stencil buffer (`stencil`; false).
    pub stencil: bool,
    /// Multisampling (`antialias`; false here, true in WebGL): 4 samples per pixel.
    pub antialias: bool,
    /// Whether colours are premultiplied by alpha when composited (`premultipliedAlpha`;
    /// true). essl-gl composites nothing; the value is kept and reported.
    pub premultiplied_alpha: bool,
    /// Whether the image survives [`Context::present`](crate::Context::present)
    /// (`preserveDrawingBuffer`; false): otherwise it is cleared there, as a browser clears
    /// the drawing buffer after compositing.
    pub preserve_drawing_buffer: bool,
    /// `failIfMajorPerformanceCaveat` (false): kept and reported; a software adapter is
    /// accepted either way.
    pub fail_if_major_performance_caveat: bool,
}

impl Default for ContextAttributes {
    fn default() -> Self {
        ContextAttributes {
            alpha: true,
            depth: true,
            stencil: false,
            antialias: false,
            premultiplied_alpha: true,
            preserve_drawing_buffer: false,
            fail_if_major_performance_caveat: false,
        }
    }
}

/// The colour format of the default framebuffer unless `drawing_buffer_storage` changes it:
/// 8-bit RGBA, linear, as WebGL's drawing buffer.
pub const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// The offscreen default framebuffer.
pub(crate) struct DefaultFramebuffer {
    pub(crate) width: u32,
    pub(crate) height: u32,
    /// The colour format (`RGBA8`, or what `drawing_buffer_storage` chose).
    pub(crate) format: crate::texture::InternalFormat,
    pub(crate) attributes: ContextAttributes,
    /// The single-sample colour image: what reads see (the resolve target with antialias).
    pub(crate) color: wgpu::Texture,
    pub(crate) color_view: wgpu::TextureView,
    /// The multisampled colour image that draws go to with antialias.
    pub(crate) msaa: Option<(wgpu::Texture, wgpu::TextureView)>,
    /// Depth and/or stencil, multisampled like the colour.
    pub(crate) depth_stencil: Option<(wgpu::Texture, wgpu::TextureView)>,
    /// `drawBuffers` of the default framebuffer: `BACK` or `NONE`.
    pub(crate) draw_buffer: u32,
    /// `readBuffer` of the default framebuffer: `BACK` or `NONE`.
    pub(crate) read_buffer: u32,
}

impl DefaultFramebuffer {
    /// The depth/stencil format the attributes ask for.
    pub(crate) fn depth_format(attributes: &ContextAttributes) -> Option<wgpu::TextureFormat> {
        match (attributes.depth, attributes.stencil) {
            (true, true) => Some(wgpu::TextureFormat::Depth24PlusStencil8),
            (true, false) => Some(wgpu::TextureFormat::Depth24Plus),
            (false, true) => Some(wgpu::TextureFormat::Stencil8),
            (false, false) => None,
        }
    }

    /// Samples per pixel: 4 with antialias, else 1.
    pub(crate) fn samples(&self) -> u32 {
        if self.attributes.antialias {
            4
        } else {
            1
        }
    }

    pub(crate) fn new(gpu: &Gpu, width: u32, height: u32, attributes: ContextAttributes) -> Self {
        let rgba8 = crate::texture::internal_format(gl::RGBA8).expect("a supported format");
        Self::with_format(gpu, [width, height], attributes, rgba8)
    }

    /// A default framebuffer of `size` whose colour has `format`.
    pub(crate) fn with_format(
        gpu: &Gpu,
        [width, height]: [u32; 2],
        attributes: ContextAttributes,
        format: crate::texture::InternalFormat,
    ) -> Self {
        let color_format = format.gpu_format();
        let samples = if attributes.antialias { 4 } else { 1 };
        let size = wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        };
        let texture = |label, format, sample_count, usage| {
            let t = gpu.device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size,
                mip_level_count: 1,
                sample_count,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            });
            let v = t.create_view(&Default::default());
            (t, v)
        };
        let (color, color_view) = texture(
            "essl-gl default colour",
            color_format,
            1,
            wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::COPY_SRC
                | wgpu::TextureUsages::COPY_DST
                | wgpu::TextureUsages::TEXTURE_BINDING,
        );
        let msaa = attributes.antialias.then(|| {
            texture(
                "essl-gl default colour (multisampled)",
                color_format,
                samples,
                wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
            )
        });
        let depth_stencil = Self::depth_format(&attributes).map(|format| {
            let mut usage =
                wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
            if samples == 1 && format != wgpu::TextureFormat::Depth24Plus {
                usage |= wgpu::TextureUsages::COPY_SRC | wgpu::TextureUsages::COPY_DST;
            }
            texture("essl-gl default depth/stencil", format, samples, usage)
        });
        DefaultFramebuffer {
            width,
            height,
            format,
            attributes,
            color,
            color_view,
            msaa,
            depth_stencil,
            draw_buffer: gl::BACK,
            read_buffer: gl::BACK,
        }
    }
}
