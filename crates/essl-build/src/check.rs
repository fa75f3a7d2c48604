//! Checking a folder of shaders from a build script: the one checking pipeline
//! ([`essl_check`], the one `essl lint` and the editor server use) finds, compiles, lints and
//! links every shader — shader files, `.glsl` files essl.toml places, shaders inside HTML and
//! JS/TS files, `#include`s where essl.toml names include folders — and this module tells
//! Cargo what to watch and what went wrong, and fails on errors.
//!
//! Cargo reads a build script's standard output: each diagnostic becomes a
//! `cargo:warning=FILE:LINE:COL: error[CODE]: MESSAGE` line (Cargo shows those on every build),
//! and `cargo:rerun-if-changed` names the folder (Cargo scans it recursively) and each
//! `essl.toml` used, so the script runs again exactly when a shader or a setting changes. The
//! rustc-style text of each diagnostic goes to standard error, which Cargo shows when the
//! script fails.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use essl::diagnostic::{Diagnostic, Severity};
use essl::link::Program;
use essl::source::SourceFile;
use essl::Shader;
use essl_check::{
    CheckOptions, CheckedUnit, ConfigError, Configs, Files, FindOptions, Found, Overrides,
};

/// Why a check failed. Its `Debug` is its `Display`, so that `fn main() -> Result<(), Box<dyn
/// Error>>` in a build script prints the message, not a struct.
#[derive(thiserror::Error)]
#[non_exhaustive]
pub enum CheckError {
    /// The folder to check does not exist or cannot be listed.
    #[error("essl: cannot check `{}`: {message}", .path.display())]
    Folder {
        /// The folder.
        path: PathBuf,
        /// Why.
        message: String,
    },
    /// An `essl.toml` on the way could not be used.
    #[error("essl: {0}")]
    Config(Arc<ConfigError>),
    /// Some shader has errors (or warnings, when warnings are denied).
    #[error(
        "essl: {errors} error{} in the shaders under `{}` ({} file{} checked, {} program{} linked); \
         each is a `warning:` line above",
        s(*errors), .path.display(), .files, s(*files), .programs, s(*programs)
    )]
    Failed {
        /// The folder checked.
        path: PathBuf,
        /// Errors, counting denied warnings.
        errors: usize,
        /// Files checked.
        files: usize,
        /// Programs linked.
        programs: usize,
    },
    /// Writing to Cargo failed.
    #[error("essl: cannot write to Cargo: {0}")]
    Output(#[from] std::io::Error),
}

impl std::fmt::Debug for CheckError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(self, f)
    }
}

fn s(n: usize) -> &'static str {
    if n == 1 {
        ""
    } else {
        "s"
    }
}

/// A linked `NAME.vert` + `NAME.frag` program found by a check.
#[derive(Debug)]
pub struct LinkedProgram {
    /// A Rust module name for it: its path under the checked folder, without extensions, in
    /// snake case (`lights/spot.vert` → `lights_spot`, `3d.vert` → `program_3d`, `match.vert` →
    /// `match_`).
    pub name: String,
    /// The vertex shader's path.
    pub vertex_path: PathBuf,
    /// The fragment shader's path.
    pub fragment_path: PathBuf,
    /// The vertex shader, compiled.
    pub vertex: Shader,
    /// The fragment shader, compiled.
    pub fragment: Shader,
    /// The link result.
    pub program: Program,
}

/// What a check found when it passed.
#[derive(Debug, Default)]
pub struct Report {
    /// Shader files checked.
    pub files: usize,
    /// Warnings reported.
    pub warnings: usize,
    /// The programs that linked, in the order of their vertex shaders' paths.
    pub programs: Vec<LinkedProgram>,
}

impl Report {
    /// Rust bindings for every linked program ([`crate::bindings`]), one module each.
    pub fn bindings(&self) -> String {
        crate::bindings::generate(&self.programs)
    }

    /// Writes [`Report::bindings`] to `path` (in a build script: a file in `OUT_DIR`, brought
    /// in with `include!`), only when its text changed.
    pub fn write_bindings(&self, path: impl AsRef<Path>) -> std::io::Result<()> {
        let text = self.bindings();
        if std::fs::read_to_string(path.as_ref()).ok().as_deref() != Some(text.as_str()) {
            std::fs::write(path, text)?;
        }
        Ok(())
    }
}

/// Checks every shader under `dir` with the settings of the nearest `essl.toml`: what a build
/// script calls.
///
/// ```no_run
/// // build.rs
/// fn main() -> Result<(), Box<dyn std::error::Error>> {
///     essl_build::check("shaders")?;
///     Ok(())
/// }
/// ```
pub fn check(dir: impl Into<PathBuf>) -> Result<Report, CheckError> {
    Check::new(dir).run()
}

type Filter = Box<dyn FnMut(&Path) -> bool>;

/// A check with settings beyond those of `essl.toml`: a filter, denied warnings, no lints.
pub struct Check {
    dir: PathBuf,
    filter: Option<Filter>,
    deny_warnings: bool,
    lints: bool,
    link: bool,
}

impl Check {
    /// A check of the shaders under `dir` (a path relative to the crate's folder in a build
    /// script).
    pub fn new(dir: impl Into<PathBuf>) -> Check {
        Check {
            dir: dir.into(),
            filter: None,
            deny_warnings: false,
            lints: true,
            link: true,
        }
    }

    /// Checks only the files (and enters only the folders) for which `keep` is true.
    pub fn filter(mut self, keep: impl FnMut(&Path) -> bool + 'static) -> Check {
        self.filter = Some(Box::new(keep));
        self
    }

    /// Fails on warnings too (as `warnings = "deny"` in `essl.toml` does).
    pub fn deny_warnings(mut self, deny: bool) -> Check {
        self.deny_warnings = deny;
        self
    }

    /// Runs the numerical-hazard lints (on by default).
    pub fn lints(mut self, on: bool) -> Check {
        self.lints = on;
        self
    }

    /// Links `NAME.vert` + `NAME.frag` pairs (on by default; bindings need it).
    pub fn link(mut self, on: bool) -> Check {
        self.link = on;
        self
    }

    /// Runs the check, writing Cargo's lines to standard output and the rendered diagnostics
    /// to standard error.
    pub fn run(self) -> Result<Report, CheckError> {
        let stdout = std::io::stdout();
        let stderr = std::io::stderr();
        self.run_with(&mut stdout.lock(), &mut stderr.lock())
    }

    /// Runs the check, writing Cargo's lines to `cargo` and the rendered diagnostics to
    /// `human`.
    pub fn run_with(
        mut self,
        cargo: &mut dyn Write,
        human: &mut dyn Write,
    ) -> Result<Report, CheckError> {
        let dir = self.dir.clone();
        if let Err(e) = std::fs::read_dir(&dir) {
            return Err(CheckError::Folder {
                path: dir,
                message: essl_check::io_message(&e),
            });
        }
        writeln!(cargo, "cargo:rerun-if-changed={}", dir.display())?;
        let configs = Configs::new(Overrides {
            deny_warnings: self.deny_warnings,
            ..Overrides::default()
        });
        let mut found = essl_check::find(std::slice::from_ref(&dir), &FindOptions::new(), &configs)
            .map_err(|e| CheckError::Folder {
                path: dir.clone(),
                message: e.to_string(),
            })?;
        if let Some(keep) = self.filter.as_mut() {
            filter(&mut found, &dir, keep);
        }
        if let Some(e) = std::mem::take(&mut found.errors).into_iter().next() {
            return Err(match e {
                essl_check::FindError::Config(c) => CheckError::Config(c),
                other => CheckError::Folder {
                    path: dir,
                    message: other.to_string(),
                },
            });
        }
        for path in configs.used() {
            writeln!(cargo, "cargo:rerun-if-changed={}", path.display())?;
        }
        let shaders = found.shader_count();
        if shaders == 0 {
            writeln!(
                cargo,
                "cargo:warning=essl: no shader under `{}` (files named .vert/.vs/.vsh or \
                 .frag/.fs/.fsh, .glsl files essl.toml places, and shaders inside .html and \
                 .js/.ts files are checked)",
                dir.display()
            )?;
        }
        for s in &found.skipped {
            writeln!(
                cargo,
                "cargo:warning={}: shader not checked: {}",
                s.at,
                s.reason()
            )?;
        }
        let options = CheckOptions {
            link: self.link,
            lints: self.lints,
            ..CheckOptions::default()
        };
        let keep = |_, unit: CheckedUnit| unit;
        let run = essl_check::run(&found, &configs, &mut Files::disk(), options, &keep);
        let mut tally = Tally::default();
        let mut watched = std::collections::BTreeSet::new();
        let mut programs = Vec::new();
        for unit in run.results {
            tally.unit(cargo, human, &unit, &dir, &mut watched)?;
            programs.extend(linked_programs(unit, &dir));
        }
        for path in watched {
            writeln!(cargo, "cargo:rerun-if-changed={}", path.display())?;
        }
        if tally.errors > 0 {
            return Err(CheckError::Failed {
                path: dir,
                errors: tally.errors,
                files: shaders,
                programs: programs.len(),
            });
        }
        Ok(Report {
            files: shaders,
            warnings: tally.warnings,
            programs,
        })
    }
}

/// Keeps the shaders whose file, and every folder between `dir` and it, `keep` accepts.
fn filter(found: &mut Found, dir: &Path, keep: &mut dyn FnMut(&Path) -> bool) {
    let mut kept = |path: &Path| {
        let mut ok = true;
        for a in path.ancestors().skip(1) {
            if a == dir || !a.starts_with(dir) {
                break;
            }
            ok &= keep(a);
        }
        ok && keep(path)
    };
    found.inputs.retain(|i| kept(&i.path));
    found.hosts.retain(|h| kept(&h.path));
}

/// The programs of a unit that linked, with their shaders.
fn linked_programs(mut unit: CheckedUnit, dir: &Path) -> Vec<LinkedProgram> {
    let mut out = Vec::new();
    for p in unit.programs {
        let Some(program) = p.program.filter(|x| x.ok && p.linked) else {
            continue;
        };
        let (v, f) = (p.vertex, p.fragment);
        let (Some(vertex), Some(fragment)) =
            (unit.shaders[v].shader.take(), unit.shaders[f].shader.take())
        else {
            continue;
        };
        out.push(LinkedProgram {
            name: module_name(dir, &unit.shaders[v].path),
            vertex_path: unit.shaders[v].path.clone(),
            fragment_path: unit.shaders[f].path.clone(),
            vertex,
            fragment,
            program,
        });
    }
    out
}

/// `a.vert + a.frag`, for link diagnostics that belong to neither file.
fn program_path(vertex: &Path, fragment: &Path) -> PathBuf {
    let name = fragment.file_name().unwrap_or_default().to_string_lossy();
    PathBuf::from(format!("{} + {name}", vertex.display()))
}

/// A snake-case Rust module name for the program whose vertex shader is at `path` under
/// `root`: the folders and the file name without its last extension, joined by `_`.
pub fn module_name(root: &Path, path: &Path) -> String {
    let relative = path.strip_prefix(root).unwrap_or(path).with_extension("");
    let mut name = String::new();
    for c in relative.to_string_lossy().chars() {
        if c.is_ascii_alphanumeric() {
            name.push(c.to_ascii_lowercase());
        } else if !name.ends_with('_') && !name.is_empty() {
            name.push('_');
        }
    }
    let name = name.trim_end_matches('_').to_string();
    if name.is_empty() || name.starts_with(|c: char| c.is_ascii_digit()) {
        format!("program_{name}")
    } else if crate::bindings::is_keyword(&name) {
        format!("{name}_")
    } else {
        name
    }
}

/// Counts and writes diagnostics as Cargo warning lines.
#[derive(Default)]
struct Tally {
    errors: usize,
    warnings: usize,
}

impl Tally {
    /// Reports a unit: its unreadable files, its shaders' diagnostics (the lints' notes left
    /// out) and its programs'; records the files it includes from outside `dir`, for Cargo to
    /// watch.
    fn unit(
        &mut self,
        cargo: &mut dyn Write,
        human: &mut dyn Write,
        unit: &CheckedUnit,
        dir: &Path,
        watched: &mut std::collections::BTreeSet<PathBuf>,
    ) -> std::io::Result<()> {
        for u in &unit.unread {
            self.errors += 1;
            writeln!(
                cargo,
                "cargo:warning={}: error: {}",
                u.path.display(),
                u.message
            )?;
        }
        for s in &unit.shaders {
            let deny = s.settings.deny_warnings;
            for g in &s.diagnostics {
                let shown: Vec<Diagnostic> = g
                    .diagnostics
                    .iter()
                    .filter(|d| d.severity != Severity::Note)
                    .cloned()
                    .collect();
                for d in &shown {
                    self.report(cargo, Some(&g.file), g.file.name(), d, deny)?;
                }
                if !shown.is_empty() {
                    human.write_all(essl::render::human_string(&g.file, &shown).as_bytes())?;
                }
            }
            for f in s.assembly.files().iter().skip(1) {
                let path = PathBuf::from(f.name());
                if !path.starts_with(dir) {
                    watched.insert(path);
                }
            }
        }
        for p in &unit.programs {
            let (vs, fs) = (&unit.shaders[p.vertex], &unit.shaders[p.fragment]);
            let deny = vs.settings.deny_warnings;
            let Some(program) = p.program.as_ref().filter(|_| p.linked) else {
                continue;
            };
            for d in &p.diagnostics {
                let name = match &d.file {
                    Some(f) => f.name().to_string(),
                    None => program_path(&vs.path, &fs.path).display().to_string(),
                };
                self.report(cargo, d.file.as_deref(), &name, &d.diagnostic, deny)?;
                if let Some(file) = &d.file {
                    let one = std::slice::from_ref(&d.diagnostic);
                    human.write_all(essl::render::human_string(file, one).as_bytes())?;
                }
            }
            // A link can fail with only `None`-stage diagnostics' text in its log.
            if !program.ok && p.diagnostics.is_empty() {
                self.errors += 1;
            }
        }
        Ok(())
    }

    fn report(
        &mut self,
        cargo: &mut dyn Write,
        file: Option<&SourceFile>,
        name: &str,
        d: &Diagnostic,
        deny_warnings: bool,
    ) -> std::io::Result<()> {
        let error =
            d.severity == Severity::Error || (deny_warnings && d.severity == Severity::Warning);
        if error {
            self.errors += 1;
        } else {
            self.warnings += 1;
        }
        let at = match file {
            Some(file) => {
                let lc = file.line_col(d.span.start);
                format!("{name}:{}:{}", lc.line, lc.column)
            }
            None => name.to_string(),
        };
        let severity = match (d.severity, error) {
            (Severity::Error, _) => "error",
            (Severity::Warning, true) => "error (denied warning)",
            (other, _) => other.as_str(),
        };
        // One line each: Cargo's warning lines end at a newline.
        let message = d.message.replace(['\n', '\r'], " ");
        writeln!(
            cargo,
            "cargo:warning={at}: {severity}[{}]: {message}",
            d.code
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn module_names() {
        let root = Path::new("shaders");
        assert_eq!(module_name(root, Path::new("shaders/spot.vert")), "spot");
        assert_eq!(
            module_name(root, Path::new("shaders/lights/spot-smooth.fixed.vert")),
            "lights_spot_smooth_fixed"
        );
        assert_eq!(
            module_name(root, Path::new("shaders/3d.vert")),
            "program_3d"
        );
    }
}
