//! What checking gives: one result per file and per linked pair, already rendered on the
//! thread that compiled it, and the totals and exit status computed from them.

use std::path::PathBuf;

use essl::diagnostic::Severity;
use essl::Stage;
use essl_check::{FileDiagnostics, FindError, ProgramDiagnostic, Skipped};

use super::options::{EXIT_ERRORS, EXIT_OK, EXIT_USAGE};

/// How a shader is named in the output.
#[derive(Clone, Debug)]
pub(crate) struct Named {
    /// Its file (for a shader inside an HTML or JS file, the host's).
    pub path: PathBuf,
    /// Its stage.
    pub stage: Stage,
    /// `FILE`, or `FILE:LINE` for a shader inside a host file.
    pub label: String,
    /// Whether it is inside a host file.
    pub embedded: bool,
    /// Whether it came from standard input.
    pub stdin: bool,
}

/// One shader's result, rendered in the requested format (shaders stay on the thread that
/// compiled them; what crosses threads is this).
#[derive(Debug)]
pub(crate) struct FileResult {
    /// Where it sorts: shader files in path order, then each host file's shaders.
    pub order: usize,
    /// The shader.
    pub named: Named,
    /// Why it could not be read, if it could not.
    pub read_error: Option<String>,
    /// Why the fixed text could not be written back, if it could not.
    pub write_error: Option<String>,
    /// Its errors.
    pub errors: usize,
    /// Its warnings.
    pub warnings: usize,
    /// Whether its folder's settings (or `--deny warnings`) make its warnings fail the run.
    pub deny_warnings: bool,
    /// Its notes shown (`--show-notes`).
    pub notes: usize,
    /// Its notes left out.
    pub notes_hidden: usize,
    /// Fixes applied by `--fix` to its file (counted with the file's first shader).
    pub fixes_applied: usize,
    /// The text before and after `--fix`, when the fixes changed it (for `--diff`, and for
    /// standard input, whose fixed text is printed).
    pub fixed: Option<(String, String)>,
    /// The code and severity of each diagnostic (for `--statistics`).
    pub codes: Vec<(&'static str, Severity)>,
    /// Its output (human text or one JSON line).
    pub rendered: Vec<u8>,
    /// Its diagnostics on their files, kept for formats that need every file at once (SARIF).
    pub diagnostics: Vec<FileDiagnostics>,
}

impl FileResult {
    /// A result with nothing counted yet.
    pub fn new(order: usize, named: Named) -> FileResult {
        FileResult {
            order,
            named,
            read_error: None,
            write_error: None,
            errors: 0,
            warnings: 0,
            deny_warnings: false,
            notes: 0,
            notes_hidden: 0,
            fixes_applied: 0,
            fixed: None,
            codes: Vec::new(),
            rendered: Vec::new(),
            diagnostics: Vec::new(),
        }
    }
}

/// One linked pair's result, rendered.
#[derive(Debug)]
pub(crate) struct ProgramResult {
    /// Where it sorts: its vertex shader's place.
    pub order: usize,
    /// The vertex shader's file.
    pub vertex: PathBuf,
    /// Whether it was linked (both shaders compiled).
    pub linked: bool,
    /// Errors it adds to the totals (see [`essl_check::CheckedProgram::counts`]).
    pub errors: usize,
    /// Warnings it adds to the totals.
    pub warnings: usize,
    /// Whether its warnings fail the run.
    pub deny_warnings: bool,
    /// The code and severity of each link diagnostic (for `--statistics`).
    pub codes: Vec<(&'static str, Severity)>,
    /// Its output (human text or one JSON line).
    pub rendered: Vec<u8>,
    /// Its link diagnostics on their files, for formats that need every file at once (SARIF).
    pub diagnostics: Vec<ProgramDiagnostic>,
}

/// Everything `essl lint` found, rendered, before printing.
#[derive(Debug, Default)]
pub(crate) struct LintResults {
    /// Paths that could not be searched, or files whose stage nothing tells.
    pub collect_errors: Vec<FindError>,
    /// Shaders found and not checked.
    pub skipped: Vec<Skipped>,
    /// One result per shader, sorted by path.
    pub files: Vec<FileResult>,
    /// Included files `--fix` changed.
    pub fixed_includes: Vec<FileResult>,
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
        for f in &self.fixed_includes {
            t.fixes += f.fixes_applied;
        }
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
                .chain(&self.fixed_includes)
                .any(|f| f.read_error.is_some() || f.write_error.is_some())
    }

    /// Whether some warning is denied (by `--deny warnings` or its folder's essl.toml).
    pub fn denied_warnings(&self) -> bool {
        self.files.iter().any(|f| f.deny_warnings && f.warnings > 0)
            || self
                .programs
                .iter()
                .any(|p| p.deny_warnings && p.warnings > 0)
    }

    /// The exit status: 2 for I/O errors, 1 for errors (or warnings under `--deny warnings`;
    /// under `--diff`, for a fix that would change a file), 0 otherwise or under
    /// `--exit-zero`.
    pub fn exit_status(&self, exit_zero: bool, diff: bool) -> i32 {
        let t = self.totals();
        if self.has_io_errors() {
            EXIT_USAGE
        } else if exit_zero {
            EXIT_OK
        } else if diff {
            if self
                .files
                .iter()
                .chain(&self.fixed_includes)
                .any(|f| f.fixed.is_some())
            {
                EXIT_ERRORS
            } else {
                EXIT_OK
            }
        } else if t.errors > 0 || self.denied_warnings() {
            EXIT_ERRORS
        } else {
            EXIT_OK
        }
    }
}
