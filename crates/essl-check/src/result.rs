//! What checking gives: each unit's shaders (compiled, their diagnostics moved onto the files
//! the author wrote), its linked programs, and the text `--fix` wrote in its file.

use std::path::PathBuf;
use std::sync::Arc;

use essl::diagnostic::{Diagnostic, Severity};
use essl::link::Program;
use essl::source::SourceFile;
use essl::{Shader, Stage};

use crate::assembly::Assembly;
use crate::settings::Settings;

/// Diagnostics in one file, with spans in that file's text.
#[derive(Clone, Debug)]
pub struct FileDiagnostics {
    /// The file (a shader file, a host file, an included file).
    pub file: Arc<SourceFile>,
    /// Its diagnostics, in source order.
    pub diagnostics: Vec<Diagnostic>,
}

/// One shader checked.
#[derive(Debug)]
pub struct CheckedShader {
    /// Where it sorts among the run's shaders: shader files in path order, then the shaders
    /// of each host file in order.
    pub order: usize,
    /// Its file (for a shader inside an HTML or JS file, the host's).
    pub path: PathBuf,
    /// Its stage.
    pub stage: Stage,
    /// Where its text starts in its host file, for a shader inside one.
    pub embedded_at: Option<u32>,
    /// The name its host gives it (a tag's `id`, the variable a literal is assigned to).
    pub name: Option<String>,
    /// The compiled shader, on the assembled text (`None` where an `#include` could not be
    /// followed: there is nothing complete to compile).
    pub shader: Option<Shader>,
    /// The text compiled and where each of its bytes came from.
    pub assembly: Assembly,
    /// Every diagnostic, moved onto its file: the shader's own (or host) file first, then each
    /// included file with diagnostics.
    pub diagnostics: Vec<FileDiagnostics>,
    /// Whether the lints ran (an editor runs them after the front end's diagnostics are out).
    pub linted: bool,
    /// Whether its file's text was given rather than read from its path (standard input).
    pub given: bool,
    /// The settings it was checked with (its folder's essl.toml and the overrides).
    pub settings: Arc<Settings>,
}

impl CheckedShader {
    /// Every diagnostic with its file.
    pub fn all(&self) -> impl Iterator<Item = (&Arc<SourceFile>, &Diagnostic)> {
        self.diagnostics
            .iter()
            .flat_map(|f| f.diagnostics.iter().map(move |d| (&f.file, d)))
    }

    /// How many diagnostics of `severity` it has, in every file.
    pub fn count(&self, severity: Severity) -> usize {
        self.all().filter(|(_, d)| d.severity == severity).count()
    }

    /// Whether it compiled without errors (its includes' included).
    pub fn ok(&self) -> bool {
        self.shader.is_some() && self.count(Severity::Error) == 0
    }

    /// Its own (or host) file: where its text starts.
    pub fn file(&self) -> &Arc<SourceFile> {
        &self.diagnostics[0].file
    }

    /// How it is named in messages: its path, or for a shader inside a host file
    /// `page.html:LINE` (the line its text starts on).
    pub fn label(&self) -> String {
        match self.embedded_at {
            Some(at) => {
                let line = self.file().line_col(at).line;
                format!("{}:{line}", self.path.display())
            }
            None => self.path.display().to_string(),
        }
    }
}

/// A link diagnostic moved onto the file it points into (`None`: it points into neither
/// shader, as a missing `main` does).
#[derive(Clone, Debug)]
pub struct ProgramDiagnostic {
    /// The file, if the diagnostic has a place.
    pub file: Option<Arc<SourceFile>>,
    /// The shader it points into, if any.
    pub stage: Option<Stage>,
    /// The diagnostic, with spans in `file`.
    pub diagnostic: Diagnostic,
}

/// A vertex and a fragment shader of one unit, linked.
#[derive(Debug)]
pub struct CheckedProgram {
    /// The vertex shader: an index into the unit's shaders.
    pub vertex: usize,
    /// The fragment shader.
    pub fragment: usize,
    /// The link result, as WebGL's `linkProgram` gives it (`None` where an `#include` could
    /// not be followed: no shader was compiled). Where a shader has errors it fails with the
    /// info log a browser writes ("Fragment shader is not compiled.").
    pub program: Option<Program>,
    /// Whether both shaders compiled without errors: only then does the link say something
    /// about the program rather than about its shaders.
    pub linked: bool,
    /// Its diagnostics, moved onto their files (none where it is not `linked`).
    pub diagnostics: Vec<ProgramDiagnostic>,
}

impl CheckedProgram {
    /// Errors and warnings the program adds to a run's totals: its link diagnostics, or one
    /// error for a failed link that has none. A pair not linked because a shader has errors
    /// adds nothing (those errors are counted with the shader).
    pub fn counts(&self) -> (usize, usize) {
        let Some(program) = self.program.as_ref().filter(|_| self.linked) else {
            return (0, 0);
        };
        let errors = self
            .diagnostics
            .iter()
            .filter(|d| d.diagnostic.is_error())
            .count();
        let warnings = self.diagnostics.len() - errors;
        let errors = if !program.ok && errors == 0 {
            1
        } else {
            errors
        };
        (errors, warnings)
    }
}

/// A file `--fix` changed.
#[derive(Clone, Debug)]
pub struct FixedFile {
    /// The file.
    pub path: PathBuf,
    /// Its text before.
    pub before: Arc<SourceFile>,
    /// Its text after.
    pub after: String,
    /// How many fixes were applied.
    pub applied: usize,
    /// Whether it is standard input (the fixed text is printed, not written).
    pub stdin: bool,
}

/// A file that could not be read.
#[derive(Clone, Debug)]
pub struct Unread {
    /// Where it sorts among the run's shaders.
    pub order: usize,
    /// The file.
    pub path: PathBuf,
    /// Its stage.
    pub stage: Stage,
    /// Why.
    pub message: String,
}

/// What one unit of work gives: a shader file, a `NAME.vert` + `NAME.frag` pair, or the
/// shaders of one host file.
#[derive(Debug, Default)]
pub struct CheckedUnit {
    /// Its shaders, in order.
    pub shaders: Vec<CheckedShader>,
    /// Its linked programs.
    pub programs: Vec<CheckedProgram>,
    /// Files `--fix` changed (its own; included files are fixed by the run).
    pub fixed: Vec<FixedFile>,
    /// Files that could not be read.
    pub unread: Vec<Unread>,
}
