//! essl: a front end for GLSL ES 3.00 as WebGL2 accepts it.
//!
//! A shader travels one way, and the modules are named for where it is:
//! `source` → `lex` → `preprocess` → `parse` → `check` → `lower` (naga IR) → `reflect` → `link`.

pub mod diagnostic;
pub mod lex;
pub mod preprocess;
pub mod program;
pub mod source;
pub mod types;
