//! What validation reports: a [`ValidationWarning`] with the [`SourceLocation`]s of the
//! expression at risk, and the context's queue of them ([`Validation`], with its settings).

use std::fmt;

use essl::source::{SourceFile, Span};
use essl::Stage;

use crate::objects::Program;

/// The most warnings the queue holds; later ones are counted
/// ([`Context::validation_warnings_dropped`](crate::Context::validation_warnings_dropped))
/// until it is read.
pub const MAX_VALIDATION_WARNINGS: usize = 4096;

/// A place in a shader's source: the span of an expression, with its file name, 1-based line
/// and column (in characters) and the text of that line. `Display` writes `file:line:col`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SourceLocation {
    /// The shader's name: [`Context::set_shader_name`](crate::Context::set_shader_name)'s,
    /// or `vertex` / `fragment`.
    pub file: String,
    /// The expression's byte range in the shader's text.
    pub span: Span,
    /// 1-based line of the span's start.
    pub line: u32,
    /// 1-based column of the span's start, in characters.
    pub column: u32,
    /// The text of that line (without its line break).
    pub source_line: String,
}

impl SourceLocation {
    /// The location of `span` in `file`.
    pub(crate) fn new(file: &SourceFile, span: Span) -> SourceLocation {
        let lc = file.line_col(span.start);
        SourceLocation {
            file: file.name().to_string(),
            span,
            line: lc.line,
            column: lc.column,
            source_line: file
                .line_text(file.line_index(span.start))
                .trim_end_matches(['\r', '\n'])
                .to_string(),
        }
    }
}

impl fmt::Display for SourceLocation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file, self.line, self.column)
    }
}

/// A uniform value that makes an expression of the program NaN, infinite or undefined, found
/// by a draw with validation on.
///
/// `Display` writes it as a compiler would:
///
/// ```text
/// warning[smoothstep-edges]: `u_outerLimit` = 0.9 is not below `u_innerLimit` = 0.9 (equal): `smoothstep(edge0, edge1, x)` is undefined unless edge0 < edge1 …
///   --> spot-smooth.frag:43:19
///    |   float inLight = smoothstep(u_outerLimit, u_innerLimit, dotFromDirection);
///    = uniforms: u_outerLimit, u_innerLimit (drawElements)
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ValidationWarning {
    /// The program drawn with.
    pub program: Program,
    /// The draw call that found it (`drawArrays`, `drawElements`, …).
    pub function: &'static str,
    /// The rule: an `essl-lint` rule id (`smoothstep-edges`, `division-by-difference`,
    /// `normalize-zero`, `pow-zero-base`, `pow-negative-base`, `acos-domain`, `asin-domain`,
    /// `mediump-overflow`) or a runtime-only one (`division-by-zero`, `non-finite-uniform`).
    pub rule: &'static str,
    /// The uniforms involved, as WebGL names them (`u_innerLimit`, `light.cutOff`,
    /// `spotLights[0].coneCos`).
    pub uniforms: Vec<String>,
    /// What is wrong, with the values, and what it does to the result.
    pub message: String,
    /// The stage of the expression at risk (`None` for a program linked from a layout, whose
    /// source essl-gl does not have).
    pub stage: Option<Stage>,
    /// The expression at risk.
    pub location: Option<SourceLocation>,
    /// The calls through which the values reach it, outermost first (a helper function's
    /// parameters).
    pub call_sites: Vec<SourceLocation>,
}

impl ValidationWarning {
    /// `file:line:col` of the expression at risk.
    pub fn position(&self) -> Option<String> {
        self.location.as_ref().map(|l| l.to_string())
    }
}

impl fmt::Display for ValidationWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "warning[{}]: {}", self.rule, self.message)?;
        if let Some(l) = &self.location {
            write!(f, "\n  --> {l}\n   | {}", l.source_line)?;
        }
        for c in &self.call_sites {
            write!(f, "\n   = via {c}: {}", c.source_line.trim())?;
        }
        write!(
            f,
            "\n   = uniforms: {} ({})",
            self.uniforms.join(", "),
            self.function
        )
    }
}

/// The context's validation settings and queue.
#[derive(Default)]
pub(crate) struct Validation {
    /// Whether draws check uniform values.
    pub(crate) enabled: bool,
    /// Whether warnings are also written to stderr.
    pub(crate) stderr: bool,
    warnings: Vec<ValidationWarning>,
    dropped: u64,
}

impl Validation {
    /// Queues a warning (and writes it to stderr if asked), or counts it when the queue
    /// holds [`MAX_VALIDATION_WARNINGS`].
    pub(crate) fn push(&mut self, warning: ValidationWarning) {
        if self.stderr {
            eprintln!("{warning}");
        }
        if self.warnings.len() < MAX_VALIDATION_WARNINGS {
            self.warnings.push(warning);
        } else {
            self.dropped += 1;
        }
    }

    /// The queued warnings, oldest first; the queue and the dropped count start over.
    pub(crate) fn take(&mut self) -> Vec<ValidationWarning> {
        self.dropped = 0;
        std::mem::take(&mut self.warnings)
    }

    /// How many warnings did not fit in the queue since it was last read.
    pub(crate) fn dropped(&self) -> u64 {
        self.dropped
    }
}
