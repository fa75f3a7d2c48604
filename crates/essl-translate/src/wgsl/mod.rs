//! essl's own WGSL writer: naga IR as a person would write the shader in WGSL.
//!
//! naga's WGSL writer is made to be correct for any module: it gives every load and every
//! value used twice a `let _eN`, puts every binary operation in parentheses, writes `0.5f`,
//! `vec3<f32>`, and declares every local at the top of its function. For the seeds' corrected
//! shaders that is 2.1 lines of WGSL per line of GLSL, a quarter of them `let _eN`. Patching
//! that text afterwards cannot put a value back where it is used: which values can move is a
//! question about the IR (what each statement stores to, where each load happens). So this
//! writer works on the IR, with naga's writer as its model for everything it spells
//! (attributes, texture calls, pointers and references), and its own choices where a person's
//! differ:
//! - [`bake`]: a value is written where it is used unless that could change it;
//! - [`decls`]: locals declared where GLSL declared them, `let` when never assigned again;
//! - [`loops`]: `for` and `while` where the GLSL had them; `x += y`, `i++` ([`stmt`]);
//! - [`expr`]: parentheses only where WGSL's grammar needs them; literals as written;
//! - [`names`]: the GLSL names wherever WGSL takes them;
//! - [`module`]: declarations grouped as WGSL code keeps them (structs, bindings, functions,
//!   entry points), each group in the source's order, each line remembering the GLSL it came
//!   from so that the author's comments can follow it ([`crate::source`]).
//!
//! Every module it writes is read back by naga's WGSL front end and validated (the corpus
//! tests and [`crate::write`]); a module it cannot write (a construct a WebGL shader never
//! lowers to) goes through naga's writer instead.

mod analysis;
mod bake;
mod decls;
mod doc;
mod expr;
mod func;
mod image;
mod loops;
mod module;
mod names;
mod stmt;
mod types;

use naga::{Handle, Module};

pub(crate) use module::write;

/// One line of output.
#[derive(Clone, Debug)]
pub(crate) struct Line {
    /// Indentation in levels of four spaces (0 for a continuation line, which holds its own).
    pub indent: usize,
    pub text: String,
    pub origin: Origin,
    /// essl's comments, above the line.
    pub notes: Vec<String>,
}

impl Line {
    pub(crate) fn new(indent: usize, text: String, origin: Origin) -> Line {
        Line {
            indent,
            text,
            origin,
            notes: Vec::new(),
        }
    }

    /// A blank line.
    pub(crate) fn blank() -> Line {
        Line::new(0, String::new(), Origin::Continued)
    }
}

/// Where a line came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Origin {
    /// Nothing in the GLSL: the author's comments do not go above it.
    None,
    /// A declaration or statement of GLSL source `file`, at these bytes.
    Source { file: usize, start: u32, end: u32 },
    /// The rest of the line or block above.
    Continued,
}

/// The module-level facts every function's writer shares.
pub(crate) struct Env<'a> {
    pub module: &'a Module,
    pub names: names::ModuleNames,
    pub writes: bake::Writes,
    /// The buffer of loose uniforms.
    pub uniforms: Option<Handle<naga::GlobalVariable>>,
    /// Whether functions read loose uniforms through `let` aliases of their own names.
    pub module_scope_uniforms: bool,
    /// essl's comment for a value it named (`clip_position_depth_0_to_w`…).
    pub note_for: &'a dyn Fn(&str) -> Option<String>,
    /// The GLSL sources' texts, by file.
    pub texts: &'a [&'a str],
}

impl Env<'_> {
    pub(crate) fn types(&self) -> types::TypeNames<'_> {
        types::TypeNames {
            module: self.module,
            names: &self.names,
        }
    }
}

/// What the writer needs besides the module.
pub(crate) struct Input<'a> {
    pub module: &'a Module,
    pub info: &'a naga::valid::ModuleInfo,
    /// The GLSL source each function's (and entry point's) spans point into.
    pub function_files: Vec<Option<usize>>,
    pub entry_files: Vec<Option<usize>>,
    /// Where the module-level items were declared in the GLSL.
    pub anchors: &'a crate::source::Anchors,
    pub module_scope_uniforms: bool,
    pub notes: &'a crate::comments::Notes,
    /// Whether the author wrote a comment right above the declaration at this origin.
    pub commented: &'a dyn Fn(Origin) -> bool,
    /// The GLSL sources' texts, by file.
    pub texts: &'a [&'a str],
}
