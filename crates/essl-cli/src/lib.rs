//! The `essl` command's library: each subcommand is a module with a `run` function that returns
//! the exit status, so that the binary (`main.rs`, the clap definitions) stays thin and tests can
//! call the same code.
//!
//! - [`cli`]: the command line's arguments, for the binary and for `npx essl`.
//! - [`lint`]: `essl lint` — check shaders and programs through the one checking pipeline
//!   ([`essl_check`]: finding them in files, folders, HTML and JS, essl.toml, includes, fixes,
//!   compile, lint, link), and render the results as text, JSON Lines, SARIF, GitHub
//!   annotations or one line each; [`settings`] prints the `essl.toml` settings in effect
//!   (`essl config`).
//! - [`explain`]: `essl explain CODE` — a diagnostic code's documentation.
//! - [`rules`]: `essl rules` — the lint rules, or one rule's documentation.
//! - [`conformance`]: `essl conformance` — score the front end on the conformance corpora.
//! - [`translate`]: `essl translate` — shaders to WGSL, SPIR-V, MSL, HLSL or GLSL.
//! - [`minify`]: `essl minify` — a shader file without comments, white space or long local
//!   names, checked again.
//! - `render`: `essl render` — draw a scene through essl-gl.
//! - `deqp_exec`: `essl deqp-exec` — execute the dEQP value cases through essl-gl.
//! - `report`: `essl report` — the light shaders' error against run time on essl-gl.
//!
//! `essl server` runs `essl_server::run_stdio`. `render`, `deqp_exec` (Cargo feature `render`)
//! and `report` (feature `report`) use the WebGL2 API on wgpu; without those features the
//! command builds no GPU stack.

#![warn(missing_docs)]

pub mod cli;
pub mod conformance;
#[cfg(feature = "render")]
pub mod deqp_exec;
pub mod explain;
pub mod lint;
pub mod minify;
#[cfg(feature = "render")]
pub mod render;
#[cfg(feature = "report")]
pub mod report;
pub mod rules;
pub mod settings;
pub mod translate;
