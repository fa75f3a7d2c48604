//! essl-build: a Rust project's GLSL ES shaders checked where its code is checked.
//!
//! - [`check`] (from `build.rs`): compiles, lints and links every shader under a folder with
//!   the settings of the nearest `essl.toml` ([`config`]), prints each diagnostic as a
//!   `cargo:warning=FILE:LINE:COL: …` line, tells Cargo to run again when a shader or a setting
//!   changes, and fails the build on errors.
//! - [`bindings`]: from the programs a check linked, a Rust module per program with its active
//!   uniforms as a typed struct and the `uniform*` calls that upload it through `essl-gl`, so
//!   that a renamed or retyped uniform breaks the build instead of the picture.
//!
//! ```no_run
//! // build.rs
//! fn main() -> Result<(), Box<dyn std::error::Error>> {
//!     let report = essl_build::check("shaders")?;
//!     let out = std::path::PathBuf::from(std::env::var("OUT_DIR")?);
//!     report.write_bindings(out.join("shaders.rs"))?;
//!     Ok(())
//! }
//! ```
//!
//! `docs/testing.md` shows the whole set-up, with `essl::snapshot` for snapshot tests. This
//! crate depends on the front end and the lints only: a build script that uses it builds no
//! GPU stack.

#![warn(missing_docs)]

pub mod bindings;
mod check;

pub use check::{check, module_name, Check, CheckError, LinkedProgram, Report};
pub use essl_check::{Config, ConfigError};
