//! Compiling one shader: the whole front-end pipeline from text to a checked module.

use crate::diagnostic::{self, Diagnostic, MAX_DIAGNOSTICS};
use crate::diagnostic_code::Code;
use crate::hir;
use crate::preprocess::{self, PreprocessOptions, Version};
use crate::source::SourceFile;
use crate::target::{Extension, Language, Target};
use crate::Stage;

/// Options for compiling a shader.
#[derive(Clone, Debug)]
pub struct CompileOptions {
    /// Macros defined before the first line, as `(name, value)`.
    pub defines: Vec<(String, String)>,
    /// The WebGL version of the context (WebGL 2 by default).
    pub target: Target,
    /// The WebGL 1 extensions the context has enabled (`getExtension`), which a GLSL ES 1.00
    /// shader may then enable with `#extension`; WebGL 2 ignores them. By default all of
    /// [`Extension::ALL`], as for an application that enables what its shaders ask for.
    pub extensions: Vec<Extension>,
}

impl Default for CompileOptions {
    fn default() -> CompileOptions {
        CompileOptions {
            defines: Vec::new(),
            target: Target::WebGl2,
            extensions: Extension::ALL.to_vec(),
        }
    }
}

impl CompileOptions {
    /// The default options for `target`.
    pub fn for_target(target: Target) -> CompileOptions {
        CompileOptions {
            target,
            ..CompileOptions::default()
        }
    }
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
    /// The WebGL version it was compiled for.
    pub target: Target,
    /// All diagnostics, in source order.
    pub diagnostics: Vec<Diagnostic>,
    /// The checked module (present even when there are errors, for reflection of what parsed).
    pub module: hir::Module,
    /// The shader lowered on its own to naga IR (when it compiled): validated by [`compile`]
    /// and [`Shader::lower`], typed alone by [`Shader::lower_typed`].
    pub naga: Option<crate::lower::Lowered>,
    /// The invocations in the text of the shader's own macros: a diagnostic that underlines
    /// one whole is labelled with the macro's `#define` ([`Shader::label_expansions`]).
    pub expansions: Vec<preprocess::Expansion>,
}

impl Shader {
    /// Labels the `#define` of a macro whose invocation a diagnostic of this shader underlines
    /// whole (a lint's finding, as the front end's own are): the code at fault is in the
    /// macro's replacement list.
    pub fn label_expansions(&self, diagnostics: &mut [Diagnostic]) {
        expanded_from(diagnostics, &self.expansions);
    }

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
        self.diagnostics
            .iter()
            .filter(|d| d.severity == crate::diagnostic::Severity::Warning)
            .count()
    }

    /// Number of notes (lint findings that only a value out of its plausible range reaches).
    pub fn note_count(&self) -> usize {
        self.diagnostics
            .iter()
            .filter(|d| d.severity == crate::diagnostic::Severity::Note)
            .count()
    }
}

/// The checked module, which is what lowering reads ([`crate::lower::lower_shader`]).
impl AsRef<hir::Module> for Shader {
    fn as_ref(&self) -> &hir::Module {
        &self.module
    }
}

pub(crate) use crate::stack::with_stack;
pub use crate::stack::COMPILE_STACK;

/// Compiles a shader's text: the front end, then lowering to naga IR and naga's validation
/// ([`compile_front_end`] and [`Shader::lower`]).
pub fn compile(file: SourceFile, stage: Stage, options: &CompileOptions) -> Shader {
    with_stack(move || {
        let mut shader = front_end_here(file, stage, options);
        shader.lower_here();
        shader
    })
}

/// The front end alone (preprocess, parse, check): every diagnostic but those of lowering.
/// An editor publishes these first and calls [`Shader::lower`] after; lowering finds an error
/// only where naga rejects what the front end accepted (WebGL's size limits, say).
pub fn compile_front_end(file: SourceFile, stage: Stage, options: &CompileOptions) -> Shader {
    with_stack(move || front_end_here(file, stage, options))
}

impl Shader {
    /// Lowers a shader from [`compile_front_end`] to a validated naga module, adding the
    /// diagnostic of a failure; nothing when it has errors or is lowered already.
    pub fn lower(&mut self) {
        with_stack(|| self.lower_here())
    }

    /// [`Shader::lower`] without validation, for tools that read the IR without translating
    /// it (the lints): the module and the type of each expression ([`crate::lower::Lowered`]).
    /// Validation checks essl's lowering, which the front end's verdict does not depend on.
    pub fn lower_typed(&mut self) {
        with_stack(|| self.lower_with(true))
    }

    fn lower_here(&mut self) {
        self.lower_with(false)
    }

    fn lower_with(&mut self, typed: bool) {
        if !self.ok() || self.naga.is_some() {
            return;
        }
        let options = crate::program::LowerOptions::default();
        let lowered = if typed {
            crate::lower::lower_shader_typed(self, &options)
        } else {
            crate::lower::lower_shader(self, &options)
                .map(|(m, info)| crate::lower::Lowered::validated(m, info))
        };
        match lowered {
            Ok(m) => self.naga = Some(m),
            Err(e) => {
                self.diagnostics.push(lowering_diagnostic(&e));
                diagnostic::sort(&mut self.diagnostics);
                cap_diagnostics(&mut self.diagnostics);
            }
        }
    }
}

fn front_end_here(file: SourceFile, stage: Stage, options: &CompileOptions) -> Shader {
    let lexed = crate::lex::lex(&file);
    let target = options.target;
    let mut pp = preprocess::preprocess(
        &file,
        lexed,
        &PreprocessOptions {
            defines: options.defines.clone(),
            extensions: PreprocessOptions::extension_macros(target, &options.extensions),
            stage: Some(stage),
            target,
        },
    );
    let lang = Language::of(&pp, target, &options.extensions);
    let mut diagnostics = std::mem::take(&mut pp.diagnostics);
    // The preprocessor's own diagnostics of a macro say where in it they are.
    let after_preprocessing = diagnostics.len();
    let tokens = crate::token::classify_as(pp.tokens, &lang, &mut diagnostics);
    let (unit, parse_diags) = crate::parse::parse_as(&file, tokens, stage, &lang);
    diagnostics.extend(parse_diags);
    let (module, check_diags) =
        crate::check::check_as(&file, &unit, stage, pp.invariant_all, &lang);
    // The syntax tree is not needed past this point: free it before lowering.
    drop(unit);
    diagnostics.extend(check_diags);
    expanded_from(&mut diagnostics[after_preprocessing..], &pp.expansions);
    diagnostic::sort(&mut diagnostics);
    cap_diagnostics(&mut diagnostics);
    Shader {
        file,
        stage,
        version: pp.version,
        target,
        diagnostics,
        module,
        naga: None,
        expansions: pp.expansions,
    }
}

/// Labels the `#define` of a macro whose invocation a diagnostic underlines whole: the code at
/// fault is in its replacement list, whose tokens carry the invocation's span (an argument's
/// keep their own, and a diagnostic of one underlines it).
fn expanded_from(diagnostics: &mut [Diagnostic], expansions: &[preprocess::Expansion]) {
    if expansions.is_empty() || diagnostics.is_empty() {
        return;
    }
    let by_span: std::collections::HashMap<(u32, u32), &preprocess::Expansion> = expansions
        .iter()
        .rev()
        .map(|e| ((e.invocation.start, e.invocation.end), e))
        .collect();
    for d in diagnostics {
        let Some(e) = by_span.get(&(d.span.start, d.span.end)) else {
            continue;
        };
        if e.defined.is_empty() || d.secondary.iter().any(|l| l.span == e.defined) {
            continue;
        }
        let label = format!("in this expansion of `{}`, defined here", e.name);
        d.secondary.push(diagnostic::Label {
            span: e.defined,
            message: label,
        });
    }
}

/// Keeps the first [`MAX_DIAGNOSTICS`] diagnostics (in source order) and says that more were
/// found; the note is an error when an error was dropped, so that the shader still fails.
fn cap_diagnostics(diagnostics: &mut Vec<Diagnostic>) {
    if diagnostics.len() <= MAX_DIAGNOSTICS {
        return;
    }
    let dropped = diagnostics.split_off(MAX_DIAGNOSTICS);
    let errors = dropped.iter().filter(|d| d.is_error()).count();
    let at = dropped
        .first()
        .map_or(crate::source::Span::default(), |d| d.span);
    // Each pass stops collecting past the limit too, so the count is a lower bound.
    let message = format!(
        "at least {} more diagnostics ({errors} of them errors) after the first \
         {MAX_DIAGNOSTICS} are not shown",
        dropped.len()
    );
    let d = if errors > 0 {
        Diagnostic::error(Code::TooManyDiagnostics, message, at)
    } else {
        Diagnostic::warning(Code::TooManyDiagnostics, message, at)
    };
    diagnostics.push(
        d.with_label("the rest start here")
            .with_help("fix the first ones and run again"),
    );
}

/// A diagnostic for a shader essl could not lower: valid GLSL that essl does not support yet,
/// or a bug in essl; either way, say so plainly.
pub(crate) fn lowering_diagnostic(e: &crate::lower::LowerError) -> Diagnostic {
    let (code, help) = match e {
        crate::lower::LowerError::Unsupported { .. } => (
            Code::Unsupported,
            "this is valid GLSL ES that essl cannot translate yet",
        ),
        crate::lower::LowerError::Invalid { .. } | crate::lower::LowerError::Internal { .. } => (
            Code::InternalError,
            "this is a bug in essl: please report it with the shader",
        ),
    };
    Diagnostic::error(code, e.to_string(), e.span())
        .with_label("essl stops here")
        .with_help(help)
}

#[cfg(test)]
mod tests {
    /// Compiled shaders cross threads (the CLI checks files in parallel; a GL context keeps
    /// them).
    #[test]
    fn shader_is_send_and_sync() {
        fn assert_send_sync<T: Send + Sync>() {}
        assert_send_sync::<super::Shader>();
    }
}
