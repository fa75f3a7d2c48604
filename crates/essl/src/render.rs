//! Output formats for diagnostics: rustc-style text through codespan-reporting for people,
//! JSON for tools, and WebGL's `ERROR: 0:LINE: 'token' : message` info log.
//!
//! Every format reads the same [`Diagnostic`]; lines and columns are 1-based and columns count
//! characters, never bytes, so a no-break space or a `°` in a comment does not shift them.

use std::ops::Range;

use codespan_reporting::diagnostic as cs;
use codespan_reporting::files::{self, Files};
use codespan_reporting::term::{self, termcolor::WriteColor};

use crate::diagnostic::{Applicability, Diagnostic, Severity};
use crate::source::{SourceFile, Span};

/// The configuration [`emit_human`] uses by default: rustc's ASCII look (`-->`, `|`, `=`).
pub fn default_config() -> term::Config {
    term::Config {
        chars: term::Chars::ascii(),
        ..term::Config::default()
    }
}

/// A [`SourceFile`] seen through codespan-reporting's [`Files`] trait, with the same line
/// breaks (`\n`, `\r\n` and a lone `\r`) as the front end counts them.
#[derive(Clone, Copy, Debug)]
pub struct CodespanFile<'a>(pub &'a SourceFile);

impl<'a> Files<'a> for CodespanFile<'a> {
    type FileId = ();
    type Name = &'a str;
    type Source = &'a str;

    fn name(&'a self, (): ()) -> Result<&'a str, files::Error> {
        Ok(self.0.name())
    }

    fn source(&'a self, (): ()) -> Result<&'a str, files::Error> {
        Ok(self.0.text())
    }

    fn line_index(&'a self, (): (), byte_index: usize) -> Result<usize, files::Error> {
        Ok(self
            .0
            .line_index(byte_index.min(self.0.text().len()) as u32))
    }

    fn line_range(&'a self, (): (), line_index: usize) -> Result<Range<usize>, files::Error> {
        let count = self.0.line_count();
        if line_index >= count {
            return Err(files::Error::LineTooLarge {
                given: line_index,
                max: count - 1,
            });
        }
        // Like codespan's own `SimpleFile`, the range includes the line break.
        let start = self.0.line_start(line_index) as usize;
        let end = self.0.line_start(line_index + 1) as usize;
        Ok(start..end.max(start))
    }
}

/// A span as a byte range that is safe to slice: clamped to the text and to character
/// boundaries (an out-of-range span becomes an empty range at the end of the text).
pub fn clamp_span(file: &SourceFile, span: Span) -> Range<usize> {
    let text = file.text();
    let floor = |mut i: usize| {
        i = i.min(text.len());
        while !text.is_char_boundary(i) {
            i -= 1;
        }
        i
    };
    let start = floor(span.start as usize);
    let end = floor(span.end as usize).max(start);
    start..end
}

/// Converts a diagnostic to codespan-reporting's form: the primary label at the span,
/// secondary labels, `note:` lines, and `help:` from [`Diagnostic::help_text`] (with the fixed
/// line when the fix touches one line). With no file (a link error that points nowhere), the
/// labels are left out.
pub fn to_codespan(file: Option<&SourceFile>, d: &Diagnostic) -> cs::Diagnostic<()> {
    let severity = match d.severity {
        Severity::Error => cs::Severity::Error,
        Severity::Warning => cs::Severity::Warning,
        Severity::Note => cs::Severity::Note,
    };
    let mut out = cs::Diagnostic::new(severity)
        .with_code(d.code)
        .with_message(&d.message);
    let mut notes: Vec<String> = d.notes.iter().map(|n| format!("note: {n}")).collect();
    if let Some(file) = file {
        let mut labels =
            vec![cs::Label::primary((), clamp_span(file, d.span)).with_message(&d.label)];
        labels.extend(
            d.secondary.iter().map(|l| {
                cs::Label::secondary((), clamp_span(file, l.span)).with_message(&l.message)
            }),
        );
        out = out.with_labels(labels);
        if let Some(help) = d.help_text(file) {
            notes.push(format!("help: {help}"));
        }
    } else if let Some(help) = &d.help {
        notes.push(format!("help: {help}"));
    }
    out.with_notes(notes)
}

/// Writes diagnostics rustc-style (`error[code]: message`, `--> file:line:col`, the source line
/// with a caret under the span, `= note:` and `= help:` lines), one after the other, through
/// codespan-reporting; colours follow what `writer` supports.
pub fn emit_human(
    writer: &mut dyn WriteColor,
    file: &SourceFile,
    diagnostics: &[Diagnostic],
    config: &term::Config,
) -> std::io::Result<()> {
    let files = CodespanFile(file);
    for d in diagnostics {
        emit_one(writer, &files, &to_codespan(Some(file), d), config)?;
    }
    Ok(())
}

/// Writes diagnostics that point into no file (only the header, notes and help).
pub fn emit_human_unlocated(
    writer: &mut dyn WriteColor,
    diagnostics: &[Diagnostic],
    config: &term::Config,
) -> std::io::Result<()> {
    let empty = SourceFile::new("", "");
    let files = CodespanFile(&empty);
    for d in diagnostics {
        emit_one(writer, &files, &to_codespan(None, d), config)?;
    }
    Ok(())
}

fn emit_one(
    mut writer: &mut dyn WriteColor,
    files: &CodespanFile<'_>,
    d: &cs::Diagnostic<()>,
    config: &term::Config,
) -> std::io::Result<()> {
    term::emit_to_write_style(&mut writer, config, files, d).map_err(|e| match e {
        files::Error::Io(e) => e,
        e => std::io::Error::other(e.to_string()),
    })
}

/// Renders diagnostics to a string without colour (what `--color never` prints).
pub fn human_string(file: &SourceFile, diagnostics: &[Diagnostic]) -> String {
    let mut buf = term::termcolor::NoColor::new(Vec::new());
    emit_human(&mut buf, file, diagnostics, &default_config())
        .expect("writing to memory cannot fail");
    String::from_utf8(buf.into_inner()).expect("codespan writes UTF-8")
}

/// 1-based `(line, column)` of a byte offset, the column in characters.
fn position(file: &SourceFile, offset: u32) -> (u32, u32) {
    let lc = file.line_col(offset);
    (lc.line, lc.column)
}

/// A diagnostic as JSON, for `serde_json` to write:
/// `{"severity","code","message","line","column","end_line","end_column","help"}` (1-based,
/// columns in characters, `help` null when there is none) plus
/// `"fix": {"message","applicability":"certain"|"suggested","edits":[{"line","column",
/// "end_line","end_column","replacement"}]}` when there is a fix, and `"file"` when
/// [`JsonDiagnostic::in_file`] names one. Keys are written in alphabetical order.
///
/// It borrows the diagnostic and is written straight into the output: no `serde_json::Value`
/// tree is built on the way (a tree per diagnostic took as long as linking the pair did).
#[derive(Debug, serde::Serialize)]
pub struct JsonDiagnostic<'a> {
    code: &'a str,
    column: Option<u32>,
    end_column: Option<u32>,
    end_line: Option<u32>,
    /// Absent unless named; `Some(None)` is written as `null`.
    #[serde(skip_serializing_if = "Option::is_none")]
    file: Option<Option<&'a str>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    fix: Option<JsonFix<'a>>,
    help: Option<String>,
    line: Option<u32>,
    message: &'a str,
    severity: &'static str,
}

#[derive(Debug, serde::Serialize)]
struct JsonFix<'a> {
    applicability: &'static str,
    edits: Vec<JsonEdit<'a>>,
    message: &'a str,
}

#[derive(Debug, serde::Serialize)]
struct JsonEdit<'a> {
    column: u32,
    end_column: u32,
    end_line: u32,
    line: u32,
    replacement: &'a str,
}

impl<'a> JsonDiagnostic<'a> {
    /// `d`, which points into `file`.
    pub fn new(file: &SourceFile, d: &'a Diagnostic) -> Self {
        let (line, column) = position(file, d.span.start);
        let (end_line, end_column) = position(file, d.span.end);
        let fix = d.fix.as_ref().map(|fix| JsonFix {
            applicability: match fix.applicability {
                Applicability::Certain => "certain",
                Applicability::Suggested => "suggested",
            },
            edits: fix
                .edits
                .iter()
                .map(|e| {
                    let (line, column) = position(file, e.span.start);
                    let (end_line, end_column) = position(file, e.span.end);
                    JsonEdit {
                        column,
                        end_column,
                        end_line,
                        line,
                        replacement: &e.replacement,
                    }
                })
                .collect(),
            message: &fix.message,
        });
        JsonDiagnostic {
            code: d.code,
            column: Some(column),
            end_column: Some(end_column),
            end_line: Some(end_line),
            file: None,
            fix,
            help: d.help_text(file),
            line: Some(line),
            message: &d.message,
            severity: d.severity.as_str(),
        }
    }

    /// `d`, which points into no file: `"file"` and the positions are null, and there is no
    /// `"fix"`.
    pub fn unlocated(d: &'a Diagnostic) -> Self {
        JsonDiagnostic {
            code: d.code,
            column: None,
            end_column: None,
            end_line: None,
            file: Some(None),
            fix: None,
            help: d.help.clone(),
            line: None,
            message: &d.message,
            severity: d.severity.as_str(),
        }
    }

    /// Adds `"file": name`.
    pub fn in_file(mut self, name: &'a str) -> Self {
        self.file = Some(Some(name));
        self
    }
}

/// WebGL's info log: one line per diagnostic, `ERROR: 0:LINE: 'token' : message` or
/// `WARNING: 0:LINE: 'token' : message`, each followed by `\n`, in source order.
pub fn webgl_info_log(file: &SourceFile, diagnostics: &[Diagnostic]) -> String {
    let mut ordered: Vec<&Diagnostic> = diagnostics.iter().collect();
    ordered.sort_by_key(|d| d.span.start);
    let mut log = String::new();
    for d in ordered {
        let kind = match d.severity {
            Severity::Error => "ERROR",
            Severity::Warning | Severity::Note => "WARNING",
        };
        let line = file.line_of(clamp_span(file, d.span).start as u32);
        log.push_str(&format!(
            "{kind}: 0:{line}: '{}' : {}\n",
            d.token, d.message
        ));
    }
    log
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::Fix;
    use crate::diagnostic::Severity;
    use crate::diagnostic_code::Code;

    fn file() -> SourceFile {
        SourceFile::new(
            "spot.frag",
            "#version 300 es\nprecision highp float;\nuniform float u_innerLimit\n\u{a0}\u{a0}float x = y;\n",
        )
    }

    fn diagnostics(file: &SourceFile) -> Vec<Diagnostic> {
        let semi = file.text().find("u_innerLimit").unwrap() as u32 + 12;
        let y = file.text().find("y;").unwrap() as u32;
        vec![
            Diagnostic::error(
                Code::MissingSemicolon,
                "expected `;` after the declaration",
                Span::empty(semi),
            )
            .with_label("`;` goes here")
            .with_fix(Fix::certain("insert `;`", Span::empty(semi), ";"))
            .with_token("uniform"),
            Diagnostic::new(
                Severity::Error,
                "undeclared-identifier",
                "undeclared identifier `y`",
                Span::new(y, y + 1),
            )
            .with_label("not declared")
            .with_secondary(Span::new(semi - 12, semi), "a uniform declared here")
            .with_note("ES 3.00 declares every name before its use")
            .with_help("declare `y` before `main`")
            .with_token("y"),
        ]
    }

    #[test]
    fn human_output() {
        let file = file();
        insta::assert_snapshot!(human_string(&file, &diagnostics(&file)), @r"
        error[missing-semicolon]: expected `;` after the declaration
          --> spot.frag:3:27
          |
        3 | uniform float u_innerLimit
          |                           ^ `;` goes here
          |
          = help: insert `;`: `uniform float u_innerLimit;`

        error[undeclared-identifier]: undeclared identifier `y`
          --> spot.frag:4:13
          |
        3 | uniform float u_innerLimit
          |               ------------ a uniform declared here
        4 |   float x = y;
          |             ^ not declared
          |
          = note: ES 3.00 declares every name before its use
          = help: declare `y` before `main`

        ");
    }

    #[test]
    fn empty_span_at_end_of_text_shows_a_caret() {
        let file = SourceFile::new("a.frag", "void main() {");
        let d = Diagnostic::new(
            Severity::Error,
            "unexpected-eof",
            "unexpected end of file",
            Span::empty(13),
        )
        .with_label("expected `}`");
        let out = human_string(&file, &[d]);
        assert!(out.contains("a.frag:1:14"), "{out}");
        assert!(out.contains('^'), "{out}");
    }

    #[test]
    fn out_of_range_spans_do_not_panic() {
        let file = SourceFile::new("a.frag", "é");
        let d = Diagnostic::new(Severity::Error, "x", "m", Span::new(1, 99));
        let _ = human_string(&file, std::slice::from_ref(&d));
        let _ = serde_json::to_string(&JsonDiagnostic::new(&file, &d));
        assert_eq!(webgl_info_log(&file, &[d]), "ERROR: 0:1: '' : m\n");
    }

    #[test]
    fn json_output() {
        let file = file();
        let ds = diagnostics(&file);
        insta::assert_json_snapshot!(ds.iter().map(|d| JsonDiagnostic::new(&file, d)).collect::<Vec<_>>(), @r#"
        [
          {
            "code": "missing-semicolon",
            "column": 27,
            "end_column": 27,
            "end_line": 3,
            "fix": {
              "applicability": "certain",
              "edits": [
                {
                  "column": 27,
                  "end_column": 27,
                  "end_line": 3,
                  "line": 3,
                  "replacement": ";"
                }
              ],
              "message": "insert `;`"
            },
            "help": "insert `;`: `uniform float u_innerLimit;`",
            "line": 3,
            "message": "expected `;` after the declaration",
            "severity": "error"
          },
          {
            "code": "undeclared-identifier",
            "column": 13,
            "end_column": 14,
            "end_line": 4,
            "help": "declare `y` before `main`",
            "line": 4,
            "message": "undeclared identifier `y`",
            "severity": "error"
          }
        ]
        "#);
    }

    #[test]
    fn json_help_is_null_without_help() {
        let file = file();
        let d = Diagnostic::new(Severity::Warning, "w", "m", Span::new(0, 1));
        let v = serde_json::to_value(JsonDiagnostic::new(&file, &d)).expect("serialises");
        assert_eq!(v["help"], serde_json::Value::Null);
        assert_eq!(v["severity"], "warning");
        assert!(v.get("fix").is_none());
    }

    #[test]
    fn info_log_is_webgl_shaped_and_in_source_order() {
        let file = file();
        let mut ds = diagnostics(&file);
        ds.reverse();
        ds.push(
            Diagnostic::new(Severity::Warning, "w", "a warning", Span::new(0, 1)).with_token("#"),
        );
        assert_eq!(
            webgl_info_log(&file, &ds),
            "WARNING: 0:1: '#' : a warning\n\
             ERROR: 0:3: 'uniform' : expected `;` after the declaration\n\
             ERROR: 0:4: 'y' : undeclared identifier `y`\n"
        );
    }
}
