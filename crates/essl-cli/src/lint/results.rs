//! What checking gives: one result per file and per linked pair, already rendered on the
//! thread that compiled it, and the totals and exit status computed from them.

use std::path::PathBuf;

use essl::link::Program;
use essl::source::SourceFile;
use essl::Shader;

use essl::diagnostic::Severity;

use super::options::{EXIT_ERRORS, EXIT_OK, EXIT_USAGE};
use crate::discover::{FindError, Input, Skipped};

/// A shader that was read and compiled.
#[derive(Debug)]
pub(crate) struct Checked {
    /// The compiled shader (after `--fix`, of the fixed text).
    pub shader: Shader,
    /// How many fixes `--fix` applied.
    pub fixes_applied: usize,
    /// The text before and after `--fix`, when the fixes changed it.
    pub fixed: Option<(String, String)>,
    /// Why the fixed text could not be written back, if it could not.
    pub write_error: Option<String>,
    /// Lint notes left out (no `--show-notes`).
    pub notes_hidden: usize,
    /// Diagnostics inside `#include`d files (`-I`), with each file.
    pub included: Vec<(SourceFile, Vec<essl::diagnostic::Diagnostic>)>,
}

impl Checked {
    /// Whether its included files have no errors.
    pub fn included_ok(&self) -> bool {
        self.included
            .iter()
            .all(|(_, ds)| !ds.iter().any(|d| d.is_error()))
    }
}

/// The two shaders of a linked pair and their program.
pub(crate) struct Linked<'a> {
    /// The vertex shader's file.
    pub vertex: &'a Input,
    /// The fragment shader's file.
    pub fragment: &'a Input,
    /// The compiled vertex shader.
    pub vs: &'a Shader,
    /// The compiled fragment shader.
    pub fs: &'a Shader,
    /// The program linked from them.
    pub program: &'a Program,
}

/// One file's result, rendered in the requested format (shaders stay on the thread that
/// compiled them; what crosses threads is this).
#[derive(Debug)]
pub(crate) struct FileResult {
    /// The file.
    pub input: Input,
    /// Why it could not be read, if it could not.
    pub read_error: Option<String>,
    /// Why the fixed text could not be written back, if it could not.
    pub write_error: Option<String>,
    /// Its errors.
    pub errors: usize,
    /// Its warnings.
    pub warnings: usize,
    /// Its notes shown (`--show-notes`).
    pub notes: usize,
    /// Its notes left out.
    pub notes_hidden: usize,
    /// Fixes applied by `--fix`.
    pub fixes_applied: usize,
    /// The text before and after `--fix`, when the fixes changed it (for `--diff`, and for
    /// standard input, whose fixed text is printed).
    pub fixed: Option<(String, String)>,
    /// The code and severity of each diagnostic (for `--statistics`).
    pub codes: Vec<(&'static str, Severity)>,
    /// Its output (human text or one JSON line).
    pub rendered: Vec<u8>,
    /// Its text and diagnostics, kept for formats that need every file at once (SARIF).
    pub diagnostics: Option<(SourceFile, Vec<essl::diagnostic::Diagnostic>)>,
    /// Diagnostics inside its `#include`d files, kept likewise.
    pub included: Vec<(SourceFile, Vec<essl::diagnostic::Diagnostic>)>,
}

impl FileResult {
    /// A result with nothing counted yet.
    pub fn new(input: Input, rendered: Vec<u8>) -> FileResult {
        FileResult {
            input,
            read_error: None,
            write_error: None,
            errors: 0,
            warnings: 0,
            notes: 0,
            notes_hidden: 0,
            fixes_applied: 0,
            fixed: None,
            codes: Vec::new(),
            rendered,
            diagnostics: None,
            included: Vec::new(),
        }
    }
}

/// One linked pair's result, rendered.
#[derive(Debug)]
pub(crate) struct ProgramResult {
    /// The vertex shader.
    pub vertex: Input,
    /// Whether it was linked (both shaders compiled).
    pub linked: bool,
    /// Errors it adds to the totals (see [`program_counts`]).
    pub errors: usize,
    /// Warnings it adds to the totals.
    pub warnings: usize,
    /// The code and severity of each link diagnostic (for `--statistics`).
    pub codes: Vec<(&'static str, Severity)>,
    /// Its output (human text or one JSON line).
    pub rendered: Vec<u8>,
    /// Its link diagnostics with the file each points into, for formats that need every file
    /// at once (SARIF).
    pub diagnostics: Vec<(Option<PathBuf>, essl::diagnostic::Diagnostic)>,
}

/// Everything `essl lint` found, rendered, before printing.
#[derive(Debug, Default)]
pub(crate) struct LintResults {
    /// Paths that could not be searched, or files whose stage nothing tells.
    pub collect_errors: Vec<FindError>,
    /// Shaders found and not checked.
    pub skipped: Vec<Skipped>,
    /// One result per file, sorted by path.
    pub files: Vec<FileResult>,
    /// One result per linked pair, sorted by the vertex shader's path.
    pub programs: Vec<ProgramResult>,
}

/// What the summary line counts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Totals {
    /// Files checked (read or not).
    pub files: usize,
    /// Errors in shaders and programs.
    pub errors: usize,
    /// Warnings in shaders and programs.
    pub warnings: usize,
    /// Lint notes shown.
    pub notes: usize,
    /// Lint notes left out (no `--show-notes`).
    pub notes_hidden: usize,
    /// Pairs linked (both shaders compiled).
    pub programs: usize,
    /// Pairs not linked because a shader has errors.
    pub unlinked: usize,
    /// Fixes applied by `--fix`.
    pub fixes: usize,
    /// Shaders found and not checked.
    pub skipped: usize,
}

impl LintResults {
    /// Error and warning counts, and how many programs were linked.
    pub fn totals(&self) -> Totals {
        let mut t = Totals {
            files: self.files.len(),
            skipped: self.skipped.len(),
            ..Totals::default()
        };
        for f in &self.files {
            t.errors += f.errors;
            t.warnings += f.warnings;
            t.notes += f.notes;
            t.notes_hidden += f.notes_hidden;
            t.fixes += f.fixes_applied;
        }
        for p in &self.programs {
            if p.linked {
                t.programs += 1;
            } else {
                t.unlinked += 1;
            }
            t.errors += p.errors;
            t.warnings += p.warnings;
        }
        t
    }

    /// Whether a file could not be listed, read or written back.
    pub fn has_io_errors(&self) -> bool {
        !self.collect_errors.is_empty()
            || self
                .files
                .iter()
                .any(|f| f.read_error.is_some() || f.write_error.is_some())
    }

    /// The exit status: 2 for I/O errors, 1 for errors (or warnings under `--deny warnings`;
    /// under `--diff`, for a fix that would change a file), 0 otherwise or under
    /// `--exit-zero`.
    pub fn exit_status(&self, deny_warnings: bool, exit_zero: bool, diff: bool) -> i32 {
        let t = self.totals();
        if self.has_io_errors() {
            EXIT_USAGE
        } else if exit_zero {
            EXIT_OK
        } else if diff {
            if self.files.iter().any(|f| f.fixed.is_some()) {
                EXIT_ERRORS
            } else {
                EXIT_OK
            }
        } else if t.errors > 0 || (deny_warnings && t.warnings > 0) {
            EXIT_ERRORS
        } else {
            EXIT_OK
        }
    }
}

/// Errors and warnings a program adds to the totals: its link diagnostics, or one error for a
/// failed link that has none. A pair that was not linked because a shader has errors adds
/// nothing (those errors are counted with the shader).
pub(crate) fn program_counts(vs: &Shader, fs: &Shader, program: &Program) -> (usize, usize) {
    if !vs.ok() || !fs.ok() {
        return (0, 0);
    }
    let errors = program
        .diagnostics
        .iter()
        .filter(|d| d.diagnostic.is_error())
        .count();
    let warnings = program.diagnostics.len() - errors;
    let errors = if !program.ok && errors == 0 {
        1
    } else {
        errors
    };
    (errors, warnings)
}
