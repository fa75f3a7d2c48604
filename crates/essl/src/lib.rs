//! essl: a front end for GLSL ES 3.00 as WebGL2 accepts it.
//!
//! A shader travels one way, and the modules are named for where it is:
//! `source` → `lex` → `preprocess` → `token` → `parse` → `check` → `lower` (naga IR) →
//! `reflect` → `link`.

#![warn(missing_docs)]

pub mod ast;
pub mod builtins;
pub mod check;
pub mod diagnostic;
pub mod diagnostic_code;
pub mod hir;
pub mod lex;
pub mod link;
pub mod lower;
pub mod parse;
pub mod preprocess;
pub mod program;
pub mod reflect;
pub mod render;
pub mod shader;
pub mod snapshot;
pub mod source;
mod stack;
pub mod token;
pub mod types;
pub mod usage;

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

pub use shader::{compile, CompileOptions, Shader};
