//! The `essl` command's library: each subcommand is a module with a `run` function that returns
//! the exit status, so that the binary (`main.rs`, the clap definitions) stays thin and tests can
//! call the same code.
//!
//! - [`lint`]: `essl lint` — check shaders and programs: collect the inputs (`files`), check
//!   them, render the results as text, JSON Lines or SARIF (its module doc shows the pipeline).
//! - [`conformance`]: `essl conformance` — score the front end on the conformance corpora.
//! - [`deqp_exec`]: `essl deqp-exec` — execute the dEQP value cases through essl-gl.
//! - [`report`]: `essl report` — the light shaders' error against run time on essl-gl.
//! - [`translate`]: `essl translate` — shaders to WGSL, SPIR-V, MSL, HLSL or GLSL.

#![warn(missing_docs)]

pub mod conformance;
pub mod deqp_exec;
mod files;
pub mod lint;
pub mod render;
pub mod report;
pub mod rules;
pub mod translate;
