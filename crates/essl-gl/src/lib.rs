//! essl-gl: WebGL2's API in Rust, on wgpu.
//!
//! A [`Context`] is a WebGL2 rendering context that draws into an offscreen framebuffer with
//! wgpu's Vulkan backend (a software adapter such as Mesa's lavapipe will do). A programmer who
//! knows WebGL2 should feel at home: method names are WebGL2's in snake_case
//! (`buffer_data`, `vertex_attrib_pointer`, `draw_elements`), enums are GL's `u32` constants in
//! [`gl`], objects are small typed handles ([`Buffer`], [`Texture`], [`VertexArray`],
//! [`Program`], [`Shader`], [`UniformLocation`]), and misuse records WebGL's error
//! ([`Context::get_error`]) instead of panicking.
//!
//! Programs are GLSL ES 3.00 or 1.00, compiled as a WebGL 2 context compiles them (GLSL ES 1.00
//! alone, as WebGL 1 does, after [`Context::set_shader_target`]): [`Context::compile_shader`]
//! runs the `essl` front end, and
//! [`Context::link_program`] links and lowers the shaders to an
//! [`essl::program::ProgramLayout`] — two naga modules and a description of their bindings —
//! which [`Context::link_program_from_layout`] installs (tests and tools may hand it layouts
//! made otherwise, e.g. from WGSL that follows the same conventions).
//!
//! GL's conventions are kept: `read_pixels` returns the bottom row first, texture data row 0
//! is `t = 0`, front faces are counter-clockwise in normalized device coordinates, and a vertex
//! input wider than its array gets GL's (0, 0, 0, 1) defaults. Every framebuffer stores GL's
//! row 0 first in memory: programs are lowered with [`LOWER_OPTIONS`], which draw upside down
//! on wgpu, so that a rendered texture is sampled, read and blitted the way GL has it.
//!
//! # How WebGL maps onto wgpu
//!
//! - **Vertex formats.** wgpu accepts a format *narrower* than the shader input of the same
//!   scalar kind, and Vulkan fills the missing components with 0, 0, 1 — GL's defaults — so a
//!   `vec4` fed 3 floats gets `w = 1` with no work. wgpu rejects a wider format, another
//!   scalar kind (GL turns unnormalized integers into floats), and has no 3-component
//!   8/16-bit or normalized 32-bit formats: for those the vertex entry point is wrapped (the
//!   lowered `main` becomes a function; a new `main` takes the inputs as fed, converts and
//!   widens them). Pipelines are cached per variant, so the cost is one module per layout.
//! - **Strides and offsets.** GL's stride 0 means "tightly packed"; wgpu's means "every vertex
//!   reads the same element" (essl-gl uses that for disabled arrays' generic values). wgpu
//!   wants strides that are multiples of 4 and aligned attribute offsets; other layouts
//!   (3 unsigned bytes at stride 3) are re-packed on the CPU once per buffer version, as are
//!   instanced arrays with a divisor above 1.
//! - **Topologies and indices.** `LINE_LOOP` and `TRIANGLE_FAN` become strips and lists with
//!   generated indices; 8-bit indices are widened to 16 bits; WebGL2's always-on primitive
//!   restart is native for strips and applied on the CPU for lists.
//! - **Batching.** Draws are recorded into one render pass and submitted when results are
//!   needed (`read_pixels`, `flush`, `finish`). Per-draw data (uniforms, generic attributes,
//!   generated indices) goes to an arena written just before the submit; a buffer or texture
//!   that the open batch already uses is replaced rather than written in place, so every draw
//!   sees the data of its moment, in GL's order.
//! - **Textures.** Levels live on the CPU in the GPU format and are uploaded when a draw
//!   samples a complete texture (GL ES 3.0 completeness; an incomplete one reads (0, 0, 0, 1)
//!   from a placeholder). Non-mipmapped filters sample the base level with a maximum LOD of
//!   0.25, Vulkan's way to keep the minification/magnification choice.

//!
//! # Validation of uniform values
//!
//! A debug mode that no WebGL implementation has: with [`Context::set_validation`] (or
//! [`Context::with_validation`]) on, each draw checks the current program's uniform values
//! against the hazards `essl-lint` finds in its shaders ([`essl_lint::preconditions`]) —
//! `smoothstep(u_outerLimit, u_innerLimit, d)` with equal or swapped limits, a division by
//! `u_innerLimit - u_outerLimit` with equal limits, `normalize` of a zero vector,
//! `pow(x, u_shininess)` with `u_shininess <= 0`, a NaN anywhere — once per change of the values
//! involved, and queues a [`ValidationWarning`] with the uniforms' names and the
//! `file:line:col` of the expression at risk ([`Context::take_validation_warnings`]). Off (the
//! default) it costs a draw one test of a flag; see `docs/runtime-checks.md`.

#![warn(missing_docs)]

pub mod gl;

mod array;
mod bindings;
mod blit;
mod buffer;
mod caches;
mod context;
mod draw;
mod error;
mod extensions;
mod frame;
mod framebuffer;
mod gpu;
mod native;
mod objects;
mod pipeline;
mod program;
mod query;
mod query_object;
mod readback;
mod renderbuffer;
mod sampler;
pub mod scene;
mod shader_patch;
mod state;
mod sync;
mod texture;
mod transform_feedback;
mod validation;
mod vertex_array;
mod webgl1;

pub use array::{ArrayElement, ArrayType, ArrayView, ArrayViewMut};
pub use bytemuck;
pub use context::{Context, MAX_TEXTURE_UNITS, MAX_VERTEX_ATTRIBS};
pub use draw::DrawList;
pub use error::{error_name, ContextError};
pub use extensions::Extension;
pub use framebuffer::{ContextAttributes, COLOR_FORMAT, MAX_COLOR_ATTACHMENTS};
pub use objects::{
    Buffer, Framebuffer, Program, Query, Renderbuffer, Sampler, Shader, Sync, Texture,
    TransformFeedback, UniformLocation, VertexArray,
};
pub use program::{ActiveInfo, ProgramFilter};
pub use query::{
    Parameter, ShaderPrecisionFormat, SHADING_LANGUAGE_VERSION, SUBPIXEL_BITS, VENDOR, VERSION,
};
pub use texture::{ImageSource, SourceUpload};
pub use validation::{SourceLocation, ValidationWarning, MAX_VALIDATION_WARNINGS};
pub use wgpu;

/// How essl-gl has the front end lower programs ([`Context::link_program`]), and what a layout
/// handed to [`Context::link_program_from_layout`] must follow: clip z in 0..w, and clip y
/// negated so that every framebuffer (the default one, textures, renderbuffers) stores GL's
/// row 0 first — sampling a rendered texture, `read_pixels`, blits and copies then need no
/// flip — with `gl_FragCoord` and `dFdy` as the API gives them.
pub const LOWER_OPTIONS: essl::program::LowerOptions = essl::program::LowerOptions {
    zero_to_one_depth: true,
    flip_frag_coord_y: false,
    flip_clip_y: true,
    transform_feedback: Vec::new(),
    integer_cube_as_array: true,
    clip_distance_switches: true,
    clip_control: false,
    clamp_lod_bias: true,
};
