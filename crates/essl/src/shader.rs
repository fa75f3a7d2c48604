//! Compiling one shader: the whole front-end pipeline from text to a checked module.

use crate::diagnostic::{self, Diagnostic};
use crate::hir;
use crate::preprocess::{self, PreprocessOptions, Version};
use crate::source::SourceFile;
use crate::Stage;

/// Options for compiling a shader.
#[derive(Clone, Debug, Default)]
pub struct CompileOptions {
    /// Macros defined before the first line, as `(name, value)`.
    pub defines: Vec<(String, String)>,
}

/// A compiled shader: its source, diagnostics and (when parsing succeeded) checked module.
#[derive(Debug)]
pub struct Shader {
    /// The original text.
    pub file: SourceFile,
    /// The stage.
    pub stage: Stage,
    /// The declared version.
    pub version: Version,
    /// All diagnostics, in source order.
    pub diagnostics: Vec<Diagnostic>,
    /// The checked module (present even when there are errors, for reflection of what parsed).
    pub module: hir::Module,
}

impl Shader {
    /// Whether WebGL2 would compile it: no errors.
    pub fn ok(&self) -> bool {
        !self.diagnostics.iter().any(|d| d.is_error())
    }

    /// Number of errors.
    pub fn error_count(&self) -> usize {
        self.diagnostics.iter().filter(|d| d.is_error()).count()
    }

    /// Number of warnings.
    pub fn warning_count(&self) -> usize {
        self.diagnostics.len() - self.error_count()
    }
}

/// Compiles a shader's text.
pub fn compile(file: SourceFile, stage: Stage, options: &CompileOptions) -> Shader {
    let lexed = crate::lex::lex(&file);
    let pp = preprocess::preprocess(&file, lexed, &PreprocessOptions { defines: options.defines.clone(), extensions: Vec::new(), stage: Some(stage) });
    let mut diagnostics = pp.diagnostics;
    let tokens = crate::token::classify(pp.tokens, &mut diagnostics);
    let (unit, parse_diags) = crate::parse::parse(&file, tokens, stage);
    diagnostics.extend(parse_diags);
    let (module, check_diags) = crate::check::check(&file, &unit, stage, pp.invariant_all);
    diagnostics.extend(check_diags);
    diagnostic::sort(&mut diagnostics);
    Shader { file, stage, version: pp.version, diagnostics, module }
}
