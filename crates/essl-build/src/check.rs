//! Checking a folder of shaders from a build script: compile, lint and link every shader the way
//! `essl lint` does, tell Cargo what to watch and what went wrong, and fail on errors.
//!
//! Cargo reads a build script's standard output: each diagnostic becomes a
//! `cargo:warning=FILE:LINE:COL: error[CODE]: MESSAGE` line (Cargo shows those on every build),
//! and `cargo:rerun-if-changed` names the folder (Cargo scans it recursively) and each
//! `essl.toml` used, so the script runs again exactly when a shader or a setting changes. The
//! rustc-style text of each diagnostic goes to standard error, which Cargo shows when the
//! script fails.

use std::collections::HashMap;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use essl::diagnostic::{Diagnostic, Severity};
use essl::link::Program;
use essl::source::SourceFile;
use essl::{Shader, Stage};

use crate::config::{Config, ConfigError};
use crate::files::{self, ShaderFile};

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
    Config(#[from] ConfigError),
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
                message: files::io_message(&e),
            });
        }
        writeln!(cargo, "cargo:rerun-if-changed={}", dir.display())?;
        let mut configs = Configs::default();
        let mut config_error = None;
        let mut filter = self.filter.take();
        let (found, walk_errors) = files::walk(&dir, &mut |path| {
            if filter.as_mut().is_some_and(|keep| !keep(path)) {
                return false;
            }
            match configs.for_file(path) {
                Ok(config) => !config.excludes(path),
                Err(e) => {
                    config_error.get_or_insert(e);
                    false
                }
            }
        });
        if let Some(e) = config_error {
            return Err(e.into());
        }
        if let Some((path, e)) = walk_errors.into_iter().next() {
            return Err(CheckError::Folder {
                path,
                message: files::io_message(&e),
            });
        }
        for path in configs.used() {
            writeln!(cargo, "cargo:rerun-if-changed={}", path.display())?;
        }
        if found.is_empty() {
            writeln!(
                cargo,
                "cargo:warning=essl: no shader under `{}` (files named .vert/.vs/.vsh or \
                 .frag/.fs/.fsh are checked)",
                dir.display()
            )?;
        }

        let mut tally = Tally::default();
        let mut shaders: Vec<Option<Shader>> = Vec::with_capacity(found.len());
        for file in &found {
            let config = configs.for_file(&file.path)?;
            let deny = self.deny_warnings || config.deny_warnings;
            let shader = match files::read_source(&file.path) {
                Ok(text) => {
                    let shader = self.compile(file, text, &config);
                    for d in &shader.diagnostics {
                        tally.report(cargo, &file.path, Some(&shader.file), d, deny)?;
                    }
                    if !shader.diagnostics.is_empty() {
                        human.write_all(
                            essl::render::human_string(&shader.file, &shader.diagnostics)
                                .as_bytes(),
                        )?;
                    }
                    Some(shader)
                }
                Err(e) => {
                    tally.errors += 1;
                    writeln!(cargo, "cargo:warning={}: error: {e}", file.path.display())?;
                    None
                }
            };
            shaders.push(shader);
        }

        let mut programs = Vec::new();
        let pairs = if self.link {
            files::pairs(&found)
        } else {
            Vec::new()
        };
        for (v, f) in pairs {
            let deny = self.deny_warnings || configs.for_file(&found[v].path)?.deny_warnings;
            let (Some(vs), Some(fs)) = (&shaders[v], &shaders[f]) else {
                continue;
            };
            if !(vs.ok() && fs.ok()) {
                continue;
            }
            let program = essl::link::link(vs, fs);
            for d in &program.diagnostics {
                let (path, file) = match d.stage {
                    Some(Stage::Vertex) => (found[v].path.clone(), Some(&vs.file)),
                    Some(Stage::Fragment) => (found[f].path.clone(), Some(&fs.file)),
                    None => (program_path(&found[v].path, &found[f].path), None),
                };
                tally.report(cargo, &path, file, &d.diagnostic, deny)?;
                if let Some(file) = file {
                    let text =
                        essl::render::human_string(file, std::slice::from_ref(&d.diagnostic));
                    human.write_all(text.as_bytes())?;
                }
            }
            if program.ok {
                let vertex = shaders[v].take().expect("present");
                let fragment = shaders[f].take().expect("present");
                programs.push(LinkedProgram {
                    name: module_name(&dir, &found[v].path),
                    vertex_path: found[v].path.clone(),
                    fragment_path: found[f].path.clone(),
                    vertex,
                    fragment,
                    program,
                });
            } else {
                // A link can fail with only `None`-stage diagnostics' text in its log.
                tally.errors += program.diagnostics.is_empty() as usize;
            }
        }
        if tally.errors > 0 {
            return Err(CheckError::Failed {
                path: dir,
                errors: tally.errors,
                files: found.len(),
                programs: programs.len(),
            });
        }
        Ok(Report {
            files: found.len(),
            warnings: tally.warnings,
            programs,
        })
    }

    fn compile(&self, file: &ShaderFile, text: String, config: &Config) -> Shader {
        let name = file.path.display().to_string();
        let mut shader = essl::compile(
            SourceFile::new(name, text),
            file.stage,
            &config.compile_options(),
        );
        if self.lints {
            let found = essl_lint::lint(&shader, &config.rules);
            if !found.is_empty() {
                shader.diagnostics.extend(found);
                essl::diagnostic::sort(&mut shader.diagnostics);
            }
        }
        shader
    }
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
    fn report(
        &mut self,
        cargo: &mut dyn Write,
        path: &Path,
        file: Option<&SourceFile>,
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
                format!("{}:{}:{}", path.display(), lc.line, lc.column)
            }
            None => path.display().to_string(),
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

/// The settings of each folder, read once.
#[derive(Default)]
struct Configs {
    by_folder: HashMap<PathBuf, Arc<Config>>,
}

impl Configs {
    fn for_file(&mut self, path: &Path) -> Result<Arc<Config>, ConfigError> {
        let folder = path.parent().unwrap_or(Path::new(".")).to_path_buf();
        if let Some(c) = self.by_folder.get(&folder) {
            return Ok(c.clone());
        }
        let config = Arc::new(Config::discover(&folder)?.unwrap_or_default());
        self.by_folder.insert(folder, config.clone());
        Ok(config)
    }

    fn used(&self) -> Vec<PathBuf> {
        let mut paths: Vec<PathBuf> = self
            .by_folder
            .values()
            .filter_map(|c| c.path.clone())
            .collect();
        paths.sort();
        paths.dedup();
        paths
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
