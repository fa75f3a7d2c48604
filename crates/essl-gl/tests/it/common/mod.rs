//! Helpers for renderer tests: a context (or a skip when no Vulkan adapter exists), program
//! layouts made by hand from WGSL that follows the front end's conventions, and pixel reads.

#![allow(dead_code)]

use essl::program::{
    ActiveAttribute, ActiveUniform, InternalUniform, ProgramLayout, SamplerSlot, UniformBlock,
    UniformStorage,
};
use essl::types::GlType;
use essl_gl::{gl, Context};

/// A context of `w`×`h`, or `None` (with a message) when this machine has no Vulkan adapter.
/// With `ESSL_REQUIRE_ADAPTER=1`, a missing adapter fails the test instead.
pub fn context(w: u32, h: u32) -> Option<Context> {
    context_with(w, h, essl_gl::ContextAttributes::default())
}

/// A context with the given attributes, or `None` (with the skip message) without an adapter.
pub fn context_with(w: u32, h: u32, attributes: essl_gl::ContextAttributes) -> Option<Context> {
    essl_testdata::with_adapter(|| Context::with_attributes(w, h, attributes))
}

fn validate(module: &naga::Module) -> naga::valid::ModuleInfo {
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    )
    .validate(module)
    .unwrap_or_else(|e| panic!("invalid test shader: {e:?}"))
}

/// A layout builder: WGSL for both stages plus the reflection the front end would provide.
pub struct Layout {
    vs: String,
    fs: String,
    block_size: u32,
    internal: Vec<(InternalUniform, u32)>,
    uniforms: Vec<ActiveUniform>,
    attributes: Vec<ActiveAttribute>,
    samplers: Vec<SamplerSlot>,
}

/// A WGSL function every test vertex shader can call on its clip position: essl-gl draws with
/// y negated (`essl_gl::LOWER_OPTIONS`), so that framebuffers store GL's row 0 first.
const GL_CLIP: &str =
    "\nfn gl_clip(p: vec4<f32>) -> vec4<f32> { return vec4(p.x, -p.y, p.z, p.w); }\n";

impl Layout {
    /// A layout from WGSL; the vertex shader may call `gl_clip` on its position.
    pub fn new(vs: &str, fs: &str) -> Self {
        Layout {
            vs: format!("{vs}{GL_CLIP}"),
            fs: fs.into(),
            block_size: 0,
            internal: Vec::new(),
            uniforms: Vec::new(),
            attributes: Vec::new(),
            samplers: Vec::new(),
        }
    }

    pub fn attribute(mut self, name: &str, ty: GlType, location: u32) -> Self {
        self.attributes.push(ActiveAttribute {
            name: name.into(),
            ty,
            size: 1,
            location,
        });
        self
    }

    /// A uniform in the default block (std140 offsets given by the test).
    pub fn uniform(
        mut self,
        name: &str,
        ty: GlType,
        size: u32,
        offset: u32,
        array_stride: u32,
        matrix_stride: u32,
    ) -> Self {
        self.uniforms.push(ActiveUniform {
            name: name.into(),
            ty,
            size,
            storage: UniformStorage::Buffer {
                offset,
                array_stride,
                matrix_stride,
            },
        });
        self
    }

    pub fn block_size(mut self, size: u32) -> Self {
        self.block_size = size;
        self
    }

    pub fn internal(mut self, what: InternalUniform, offset: u32) -> Self {
        self.internal.push((what, offset));
        self
    }

    pub fn sampler(mut self, name: &str, ty: GlType) -> Self {
        let first_slot = self.samplers.len() as u32;
        self.samplers.push(SamplerSlot {
            name: name.into(),
            ty,
            comparison: false,
        });
        self.uniforms.push(ActiveUniform {
            name: name.into(),
            ty,
            size: 1,
            storage: UniformStorage::Sampler { first_slot },
        });
        self
    }

    pub fn build(self) -> ProgramLayout {
        let vertex = naga::front::wgsl::parse_str(&self.vs)
            .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&self.vs)));
        let fragment = naga::front::wgsl::parse_str(&self.fs)
            .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&self.fs)));
        ProgramLayout {
            vertex_info: validate(&vertex),
            vertex,
            fragment_info: validate(&fragment),
            fragment,
            uniform_block: (self.block_size > 0).then_some(UniformBlock {
                size: self.block_size,
                internal: self.internal,
            }),
            uniforms: self.uniforms,
            attributes: self.attributes,
            samplers: self.samplers,
            blocks: Vec::new(),
            fragment_outputs: vec![(0, GlType::FLOAT_VEC4)],
            captured: Vec::new(),
            fragment_output_names: Vec::new(),
        }
    }
}

/// A program that draws `a_position` (vec4 at location 0) in a solid colour.
pub fn solid(r: f32, g: f32, b: f32) -> ProgramLayout {
    Layout::new(
        "@vertex fn main(@location(0) a_position: vec4<f32>) -> @builtin(position) vec4<f32> { return gl_clip(a_position); }",
        &format!("@fragment fn main() -> @location(0) vec4<f32> {{ return vec4({r:?}, {g:?}, {b:?}, 1.0); }}"),
    )
    .attribute("a_position", GlType::FLOAT_VEC4, 0)
    .build()
}

/// The RGBA of pixel (x, y), y from the bottom.
pub fn pixel(ctx: &mut Context, x: u32, y: u32) -> [u8; 4] {
    let p = ctx.read_pixels_rgba8(x, y, 1, 1);
    [p[0], p[1], p[2], p[3]]
}

/// Every pixel of the framebuffer, bottom row first.
pub fn all_pixels(ctx: &mut Context) -> Vec<u8> {
    let (w, h) = (ctx.drawing_buffer_width(), ctx.drawing_buffer_height());
    ctx.read_pixels_rgba8(0, 0, w, h)
}

/// Whether every pixel is `rgba`.
pub fn all_are(ctx: &mut Context, rgba: [u8; 4]) -> bool {
    all_pixels(ctx).chunks_exact(4).all(|p| p == rgba)
}

/// Uploads `data` to a new ARRAY_BUFFER and points attribute `index` at it (`size` floats).
pub fn float_attribute(ctx: &mut Context, index: u32, size: i32, data: &[f32]) -> essl_gl::Buffer {
    let b = ctx.create_buffer();
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(b));
    ctx.buffer_data(gl::ARRAY_BUFFER, data, gl::STATIC_DRAW);
    ctx.enable_vertex_attrib_array(index);
    ctx.vertex_attrib_pointer(index, size, gl::FLOAT, false, 0, 0);
    b
}

/// Clears to opaque black.
pub fn clear_black(ctx: &mut Context) {
    ctx.clear_color(0.0, 0.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
}

/// Asserts that wgpu reported no validation error (essl-gl checks everything first).
pub fn assert_clean(ctx: &Context) {
    assert_eq!(ctx.backend_errors(), Vec::<String>::new());
}

/// A full-screen quad as two triangles, 2D positions.
pub const QUAD: [f32; 12] = [
    -1.0, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, -1.0, 1.0, 1.0, -1.0, 1.0,
];

/// Compiles and links a GLSL ES program, panicking with the logs on failure.
#[allow(dead_code)]
pub fn program(ctx: &mut Context, vs: &str, fs: &str) -> essl_gl::Program {
    let p = ctx.create_program();
    for (ty, src) in [(gl::VERTEX_SHADER, vs), (gl::FRAGMENT_SHADER, fs)] {
        let s = ctx.create_shader(ty).expect("a shader type");
        ctx.shader_source(s, src);
        ctx.compile_shader(s);
        assert!(
            ctx.get_shader_compile_status(s),
            "{:?}",
            ctx.get_shader_info_log(s)
        );
        ctx.attach_shader(p, s);
    }
    ctx.link_program(p);
    assert!(
        ctx.get_program_link_status(p),
        "{:?}",
        ctx.get_program_info_log(p)
    );
    p
}

/// Draws a full-canvas quad (attribute 0) with the program of `vs` and `fs` over a black
/// canvas, checks the draw recorded no error, and returns the pixel at (1, 1).
pub fn draw_quad_pixel(ctx: &mut Context, vs: &str, fs: &str) -> [u8; 4] {
    let p = program(ctx, vs, fs);
    ctx.use_program(Some(p));
    float_attribute(ctx, 0, 2, &QUAD);
    clear_black(ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    pixel(ctx, 1, 1)
}

/// A new framebuffer, bound to `FRAMEBUFFER`, with level 0 of 2D texture `t` at
/// `COLOR_ATTACHMENT0`.
pub fn colour_framebuffer(ctx: &mut Context, t: essl_gl::Texture) -> essl_gl::Framebuffer {
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::TEXTURE_2D,
        Some(t),
        0,
    );
    fb
}

/// A framebuffer with one renderbuffer of `format` at COLOR_ATTACHMENT0, `samples` per pixel.
#[allow(dead_code)]
pub fn renderbuffer_framebuffer(
    ctx: &mut Context,
    format: u32,
    samples: i32,
    w: i32,
    h: i32,
) -> essl_gl::Framebuffer {
    let rb = ctx.create_renderbuffer();
    ctx.bind_renderbuffer(gl::RENDERBUFFER, Some(rb));
    ctx.renderbuffer_storage_multisample(gl::RENDERBUFFER, samples, format, w, h);
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::RENDERBUFFER,
        Some(rb),
    );
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE
    );
    fb
}
