//! The GLSL ES 3.00 preprocessor: directives, conditionals and macro expansion.
//!
//! Input: the lexer's tokens. Output: the tokens the parser sees (no newlines, ending with one
//! `Eof`), each with a span into the original text; a token produced by a macro expansion
//! carries the span of the macro's invocation (its name, or the whole `NAME(args)`) and
//! `from_macro = true`.

use crate::diagnostic::Diagnostic;
use crate::lex::{Lexed, PpToken};
use crate::source::{SourceFile, Span};

/// Options of the preprocessor.
#[derive(Clone, Debug, Default)]
pub struct PreprocessOptions {
    /// Macros defined before the first line, as `(name, replacement text)` (like `-DNAME=VALUE`).
    pub defines: Vec<(String, String)>,
}

/// The language version a shader declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Version {
    /// `#version 300 es` on the first line.
    Es300,
    /// No `#version` on the first line: GLSL ES 1.00.
    Es100,
    /// Another `#version` (e.g. `310 es`, `330`): the number and whether `es` followed.
    Other(u32, bool),
}

/// An `#extension` directive's behaviour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExtensionBehavior {
    /// `require`
    Require,
    /// `enable`
    Enable,
    /// `warn`
    Warn,
    /// `disable`
    Disable,
}

/// What the preprocessor produced.
#[derive(Debug)]
pub struct Preprocessed {
    /// Tokens for the parser: no `Newline`, exactly one final `Eof`.
    pub tokens: Vec<PpToken>,
    /// The declared version.
    pub version: Version,
    /// Span of the `#version` directive, if any.
    pub version_span: Option<Span>,
    /// `#extension NAME : behavior` directives in order, with their spans.
    pub extensions: Vec<(String, ExtensionBehavior, Span)>,
    /// `#pragma STDGL invariant(all)` was given.
    pub invariant_all: bool,
    /// Errors and warnings.
    pub diagnostics: Vec<Diagnostic>,
}

/// Preprocesses a lexed shader.
pub fn preprocess(_file: &SourceFile, lexed: Lexed, _options: &PreprocessOptions) -> Preprocessed {
    // Placeholder until the real preprocessor lands: drops newlines, no directives.
    let tokens = lexed
        .tokens
        .into_iter()
        .filter(|t| t.kind != crate::lex::PpKind::Newline)
        .collect();
    Preprocessed {
        tokens,
        version: Version::Es300,
        version_span: None,
        extensions: Vec::new(),
        invariant_all: false,
        diagnostics: lexed.diagnostics,
    }
}
