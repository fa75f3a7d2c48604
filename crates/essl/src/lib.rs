//! essl: a front end for GLSL ES 3.00 and 1.00 as WebGL 2 and WebGL 1 accept them.
//!
//! A shader travels one way, and the modules are named for where it is:
//! `source` → `lex` → `preprocess` → `token` → `parse` → `check` → `lower` (naga IR) →
//! `reflect` → `link`.
//!
//! The public surface is what a user of the front end needs: [`compile`] a shader into a
//! [`Shader`] (its [`diagnostic`]s, its checked tree [`hir`], its naga module), [`link::link`]
//! two of them into a [`link::Program`], [`lower::lower_program`] a program into a
//! [`program::ProgramLayout`], and the data those carry ([`source`], [`types`], [`reflect`]).
//! The passes themselves are private; [`passes`] runs them one at a time for tools that time or
//! fuzz them separately.

#![warn(missing_docs)]

pub mod diagnostic;
pub mod diagnostic_code;
pub mod hir;
pub mod link;
pub mod lower;
pub mod minify;
pub mod passes;
pub mod program;
pub mod reflect;
pub mod render;
pub mod snapshot;
pub mod source;
pub mod suggest;
pub mod target;
pub mod types;

mod ast;
mod builtins;
mod check;
mod lex;
mod near;
mod parse;
mod preprocess;
mod shader;
mod stack;
mod token;
mod usage;

pub use builtins::MAX_CLIP_DISTANCES;
pub use preprocess::Version;
pub use shader::{compile, compile_front_end, CompileOptions, Shader, COMPILE_STACK};
pub use target::{Extension, Target};

/// A name or token text: up to 23 bytes kept inline (no allocation, and a clone is a copy
/// rather than an atomic count), longer texts shared behind an `Arc`. Nearly every GLSL name
/// and token fits inline.
pub type Name = smol_str::SmolStr;

/// A shader stage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    /// A vertex shader.
    Vertex,
    /// A fragment shader.
    Fragment,
}

impl Stage {
    /// `"vertex"` or `"fragment"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Stage::Vertex => "vertex",
            Stage::Fragment => "fragment",
        }
    }

    /// The stage a file name's extension implies (`.vert`, `.vs`, `.frag`, `.fs`).
    pub fn from_path(path: &std::path::Path) -> Option<Stage> {
        match path.extension()?.to_str()? {
            "vert" | "vs" | "vsh" => Some(Stage::Vertex),
            "frag" | "fs" | "fsh" => Some(Stage::Fragment),
            _ => None,
        }
    }
}
