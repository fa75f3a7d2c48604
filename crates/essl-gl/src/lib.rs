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
//! Programs are GLSL ES 3.00: [`Context::compile_shader`] runs the `essl` front end, and
//! [`Context::link_program`] links and lowers the shaders to an
//! [`essl::program::ProgramLayout`] — two naga modules and a description of their bindings —
//! which [`Context::link_program_from_layout`] installs (tests and tools may hand it layouts
//! made otherwise, e.g. from WGSL that follows the same conventions).
//!
//! GL's conventions are kept: `read_pixels` returns the bottom row first, texture data row 0
//! is `t = 0`, front faces are counter-clockwise in normalized device coordinates, and a vertex
//! input wider than its array gets GL's (0, 0, 0, 1) defaults.

#![warn(missing_docs)]

pub mod gl;

mod buffer;
mod context;
mod draw;
mod error;
mod frame;
mod objects;
mod pipeline;
mod program;
mod readback;
mod shader_patch;
mod state;
mod texture;
mod vertex_array;

pub use bytemuck;
pub use context::{Context, COLOR_FORMAT, DEPTH_FORMAT, MAX_TEXTURE_UNITS, MAX_VERTEX_ATTRIBS};
pub use error::{error_name, ContextError};
pub use objects::{Buffer, Program, Shader, Texture, UniformLocation, VertexArray};
pub use wgpu;
