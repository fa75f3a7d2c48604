//! One diagnostic type for every output: codespan for people, JSON and SARIF for tools, and
//! WebGL's `ERROR: 0:LINE: 'token' : message` info log for the program API.

use crate::diagnostic_code::Code;
use crate::source::{SourceFile, Span};

/// How serious a diagnostic is.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Severity {
    /// A note: a hazard that only a value out of its plausible range reaches (a lint rule's
    /// quieter level); hidden unless asked for.
    Note,
    /// A warning: the shader still compiles.
    Warning,
    /// An error: WebGL2 rejects the shader.
    Error,
}

impl Severity {
    /// `"error"`, `"warning"` or `"note"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Note => "note",
        }
    }
}

/// Whether a fix may be applied without a person looking at it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Applicability {
    /// Certain: `essl lint --fix` applies it (a missing `;`, a no-break space).
    Certain,
    /// A suggestion: shown, never applied automatically.
    Suggested,
}

/// One replacement of a span of the original text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Edit {
    /// What to replace (empty for an insertion).
    pub span: Span,
    /// The new text.
    pub replacement: String,
}

/// A fix: edits that belong together, and what they do.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fix {
    /// What the fix does, in the imperative ("insert `;`").
    pub message: String,
    /// The edits, in any order, not overlapping.
    pub edits: Vec<Edit>,
    /// Whether `--fix` applies it.
    pub applicability: Applicability,
}

/// A secondary label: another span that explains the primary one.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Label {
    /// Where.
    pub span: Span,
    /// What to say there (may be empty).
    pub message: String,
}

/// A diagnostic about a shader, pointing into its original text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// A stable kebab-case id (`missing-semicolon`, `implicit-conversion`, `pow-negative-base`).
    pub code: &'static str,
    /// One line, lower case, no final period, GLSL terms only.
    pub message: String,
    /// The primary span.
    pub span: Span,
    /// What to say at the primary span.
    pub label: String,
    /// Other spans that explain the primary one.
    pub secondary: Vec<Label>,
    /// Notes: background facts (`note: ES 3.00 has no implicit conversions`).
    pub notes: Vec<String>,
    /// How to fix it, in words.
    pub help: Option<String>,
    /// How to fix it, as edits.
    pub fix: Option<Fix>,
    /// The token WebGL's info log quotes (`'u_innerLimit'`); empty when there is none.
    pub token: String,
}

impl Diagnostic {
    /// Every span the diagnostic holds: the primary one, the secondary labels', and its fix's
    /// edits (for moving it onto another text).
    pub fn spans_mut(&mut self) -> impl Iterator<Item = &mut Span> {
        let edits = self
            .fix
            .iter_mut()
            .flat_map(|f| f.edits.iter_mut().map(|e| &mut e.span));
        std::iter::once(&mut self.span)
            .chain(self.secondary.iter_mut().map(|l| &mut l.span))
            .chain(edits)
    }

    /// A new error of the front end.
    pub fn error(code: Code, message: impl Into<String>, span: Span) -> Diagnostic {
        Diagnostic::new(Severity::Error, code.as_str(), message, span)
    }

    /// A new warning of the front end.
    pub fn warning(code: Code, message: impl Into<String>, span: Span) -> Diagnostic {
        Diagnostic::new(Severity::Warning, code.as_str(), message, span)
    }

    /// A new warning of a rule another crate defines (essl-lint's numerical-hazard rules),
    /// under the rule's id.
    pub fn rule_warning(id: &'static str, message: impl Into<String>, span: Span) -> Diagnostic {
        Diagnostic::new(Severity::Warning, id, message, span)
    }

    /// A new note of a rule another crate defines: a hazard only a value out of its plausible
    /// range reaches.
    pub fn rule_note(id: &'static str, message: impl Into<String>, span: Span) -> Diagnostic {
        Diagnostic::new(Severity::Note, id, message, span)
    }

    /// A new diagnostic with any code: a front-end [`Code`]'s name, or the id of a rule that
    /// another crate defines (essl-lint's numerical-hazard rules).
    pub fn new(
        severity: Severity,
        code: &'static str,
        message: impl Into<String>,
        span: Span,
    ) -> Diagnostic {
        Diagnostic {
            severity,
            code,
            message: message.into(),
            span,
            label: String::new(),
            secondary: Vec::new(),
            notes: Vec::new(),
            help: None,
            fix: None,
            token: String::new(),
        }
    }

    /// Sets the primary label.
    pub fn with_label(mut self, label: impl Into<String>) -> Diagnostic {
        self.label = label.into();
        self
    }

    /// Adds a secondary label.
    pub fn with_secondary(mut self, span: Span, message: impl Into<String>) -> Diagnostic {
        self.secondary.push(Label {
            span,
            message: message.into(),
        });
        self
    }

    /// Adds a note.
    pub fn with_note(mut self, note: impl Into<String>) -> Diagnostic {
        self.notes.push(note.into());
        self
    }

    /// Sets the help text.
    pub fn with_help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }

    /// Sets a fix.
    pub fn with_fix(mut self, fix: Fix) -> Diagnostic {
        self.fix = Some(fix);
        self
    }

    /// Sets the token WebGL's info log quotes.
    pub fn with_token(mut self, token: impl Into<String>) -> Diagnostic {
        self.token = token.into();
        self
    }

    /// Whether this is an error.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }

    /// The help text, or, where there is a fix on one line, the help with the fixed line:
    /// ``insert `;`: `uniform float u_innerLimit;` ``.
    pub fn help_text(&self, file: &SourceFile) -> Option<String> {
        let Some(fix) = &self.fix else {
            return self.help.clone();
        };
        let base = self.help.clone().unwrap_or_else(|| fix.message.clone());
        // A fix that only changes white space would show a line that looks unchanged.
        let only_space = fix.edits.iter().all(|e| {
            e.replacement.chars().all(char::is_whitespace)
                && file.slice(e.span).chars().all(char::is_whitespace)
        });
        // A fix that adds a line would show two lines as one.
        let adds_line = fix.edits.iter().any(|e| e.replacement.contains('\n'));
        if only_space || adds_line {
            return Some(base);
        }
        match fixed_line(file, fix) {
            Some(line) => Some(format!("{base}: `{}`", line.trim())),
            None => Some(base),
        }
    }
}

impl Fix {
    /// A certain fix of one edit.
    pub fn certain(message: impl Into<String>, span: Span, replacement: impl Into<String>) -> Fix {
        Fix {
            message: message.into(),
            edits: vec![Edit {
                span,
                replacement: replacement.into(),
            }],
            applicability: Applicability::Certain,
        }
    }

    /// A suggested fix of one edit.
    pub fn suggested(
        message: impl Into<String>,
        span: Span,
        replacement: impl Into<String>,
    ) -> Fix {
        Fix {
            message: message.into(),
            edits: vec![Edit {
                span,
                replacement: replacement.into(),
            }],
            applicability: Applicability::Suggested,
        }
    }
}

/// The longest line (in bytes) that a help shows fixed.
const MAX_PREVIEW_LINE: usize = 200;

/// The text of the one line a fix touches, with the fix applied; `None` when the fix spans
/// several lines or the line is longer than [`MAX_PREVIEW_LINE`].
fn fixed_line(file: &SourceFile, fix: &Fix) -> Option<String> {
    let first = fix.edits.first()?;
    let line = file.line_index(first.span.start);
    if fix
        .edits
        .iter()
        .any(|e| file.line_index(e.span.start) != line || file.line_index(e.span.end) != line)
    {
        return None;
    }
    let range = file.line_range(line);
    // A preview of a very long line (generated or minified code) would repeat the whole line in
    // every diagnostic on it.
    if range.len() > MAX_PREVIEW_LINE {
        return None;
    }
    let mut text = file.text()[range.clone()].to_string();
    let mut edits: Vec<&Edit> = fix.edits.iter().collect();
    edits.sort_by_key(|e| std::cmp::Reverse(e.span.start));
    for e in edits {
        let s = (e.span.start as usize).checked_sub(range.start)?;
        let t = (e.span.end as usize).checked_sub(range.start)?;
        if t > text.len() || !text.is_char_boundary(s) || !text.is_char_boundary(t) {
            return None;
        }
        text.replace_range(s..t, &e.replacement);
    }
    Some(text)
}

/// The most diagnostics one shader reports: enough for any shader a person wrote, and a bound
/// on the time and memory that generated or hostile input can take. Each pass stops collecting
/// past it (keeping an error if it has none yet), and the compile keeps the first ones in source
/// order with a note that says more were found.
pub const MAX_DIAGNOSTICS: usize = 1000;

/// Whether a pass that has collected `list` still takes `d`.
pub(crate) fn accepts(list: &[Diagnostic], d: &Diagnostic) -> bool {
    // From the end: past the limit, the only error kept may be the one just added.
    list.len() <= MAX_DIAGNOSTICS || (d.is_error() && !list.iter().rev().any(Diagnostic::is_error))
}

/// Adds `d` to a pass's diagnostics unless the pass has collected enough ([`MAX_DIAGNOSTICS`]).
pub(crate) fn push_capped(list: &mut Vec<Diagnostic>, d: Diagnostic) {
    if accepts(list, &d) {
        list.push(d);
    }
}

/// Applies every fix of the given applicability to the text, skipping fixes that overlap one
/// already applied. Returns the new text and the number of fixes applied.
pub fn apply_fixes(
    text: &str,
    diagnostics: &[Diagnostic],
    which: Applicability,
) -> (String, usize) {
    let mut chosen: Vec<&Edit> = Vec::new();
    let mut applied = 0;
    for fix in diagnostics.iter().filter_map(|d| d.fix.as_ref()) {
        if fix.applicability != which {
            continue;
        }
        let overlaps = fix.edits.iter().any(|e| {
            chosen.iter().any(|c| {
                (e.span.start < c.span.end && c.span.start < e.span.end)
                    || (e.span.is_empty() && c.span.is_empty() && e.span.start == c.span.start)
            })
        });
        if overlaps {
            continue;
        }
        chosen.extend(fix.edits.iter());
        applied += 1;
    }
    chosen.sort_by_key(|e| (e.span.start, e.span.end));
    let mut out = String::with_capacity(text.len() + 16);
    let mut pos = 0usize;
    for e in chosen {
        let (s, t) = (e.span.start as usize, e.span.end as usize);
        if s < pos || t > text.len() {
            continue;
        }
        out.push_str(&text[pos..s]);
        out.push_str(&e.replacement);
        pos = t;
    }
    out.push_str(&text[pos..]);
    (out, applied)
}

/// Sorts diagnostics by position, then severity, as they are shown.
pub fn sort(diagnostics: &mut [Diagnostic]) {
    diagnostics.sort_by(order);
}

/// The order [`sort`] puts diagnostics in: by span, the more severe first at one span.
pub fn order(a: &Diagnostic, b: &Diagnostic) -> std::cmp::Ordering {
    (a.span.start, a.span.end, std::cmp::Reverse(a.severity)).cmp(&(
        b.span.start,
        b.span.end,
        std::cmp::Reverse(b.severity),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::Severity;
    use crate::diagnostic_code::Code;

    #[test]
    fn help_shows_the_fixed_line() {
        let file = SourceFile::new("a.frag", "uniform float x\nfloat y;");
        let d = Diagnostic::error(Code::MissingSemicolon, "expected `;`", Span::empty(15))
            .with_fix(Fix::certain("insert `;`", Span::empty(15), ";"));
        assert_eq!(
            d.help_text(&file).unwrap(),
            "insert `;`: `uniform float x;`"
        );
    }

    #[test]
    fn applies_non_overlapping_certain_fixes() {
        let text = "a b c";
        let ds =
            vec![
                Diagnostic::new(Severity::Error, "x", "", Span::new(0, 1)).with_fix(Fix::certain(
                    "",
                    Span::new(0, 1),
                    "A",
                )),
                Diagnostic::new(Severity::Error, "x", "", Span::new(0, 1)).with_fix(Fix::certain(
                    "",
                    Span::new(0, 1),
                    "Z",
                )),
                Diagnostic::new(Severity::Error, "x", "", Span::new(4, 5))
                    .with_fix(Fix::suggested("", Span::new(4, 5), "C")),
            ];
        assert_eq!(
            apply_fixes(text, &ds, Applicability::Certain),
            ("A b c".to_string(), 1)
        );
    }
}
