//! [`NativeContext`](crate::NativeContext)'s WebGL calls, grouped as essl-gl groups them:
//! state and queries of the context ([`state`]), buffers, vertex arrays and draws
//! ([`vertex`]; `WEBGL_multi_draw`'s in [`multi_draw`]), textures and samplers ([`textures`]), renderbuffers, framebuffers and reads
//! ([`framebuffers`]), shaders and programs ([`programs`]), uniforms ([`uniforms`]), and
//! transform feedback, queries and syncs ([`queries`]).

mod framebuffers;
mod multi_draw;
mod programs;
mod queries;
mod state;
mod textures;
mod uniforms;
mod vertex;
