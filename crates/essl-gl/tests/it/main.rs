//! The integration tests of this crate, one binary (each test file was a binary of its own,
//! and linking them was most of the test suite's time). Each module is one former file.

mod active_lists;
mod binding;
mod clip_control;
mod clip_distance;
mod common;
mod compressed;
mod draw_buffers_indexed;
mod errors;
mod es100_render;
mod frag_depth;
mod framebuffer;
mod glsl;
mod multi_draw;
mod object_queries;
mod queries;
mod queries_sync;
mod raster;
mod render;
mod scenes;
mod scissor;
mod small_extensions;
mod stencil_texturing;
mod transform_feedback;
mod validation;
mod webgl1_draws;
mod webgl1_float;
