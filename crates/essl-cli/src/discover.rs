//! Finding the shaders `essl lint` checks: files named on the command line, folders walked as
//! git would see them (`.gitignore`, `.ignore`, hidden entries skipped; `exclude` patterns),
//! standard input (`-`), and the shaders inside HTML, JS and TS files ([`essl_build::extract`]).
//!
//! A shader's stage comes from its extension (`.vert`/`.vs`/`.vsh`, `.frag`/`.fs`/`.fsh`, also
//! before `.glsl`: `light.vert.glsl`), then from the `[stages]` globs of `essl.toml`, then from
//! a `#pragma essl stage(vertex)` line, then from `--stage` for a file named explicitly. A
//! `.glsl` file found in a folder that none of these places is an error naming the file, never
//! silently skipped.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use essl::Stage;
use essl_build::Config;
use globset::GlobSet;

use crate::files::{io_message, read_source};
use essl_build::extract::{self, Embedded, HostKind};

/// Where a shader's text comes from.
#[derive(Clone, Debug)]
pub enum Source {
    /// The file at the input's path, read when it is checked.
    File,
    /// Text already read (standard input).
    Text(Arc<str>),
    /// A shader inside a host file: the host and the index of the shader in its list.
    Embedded(Arc<Host>, usize),
}

/// A file that holds shaders inside it (an HTML page, a script), read and searched.
#[derive(Debug)]
pub struct Host {
    /// Its path (the `--stdin-filename` for standard input).
    pub path: PathBuf,
    /// Its text.
    pub text: String,
    /// Whether it came from standard input (fixes are then written to standard output).
    pub stdin: bool,
    /// The shaders in it.
    pub embedded: Vec<Embedded>,
    /// The programs the file makes plain (indices into `embedded`).
    pub pairs: Vec<(usize, usize)>,
}

/// A shader to check.
#[derive(Clone, Debug)]
pub struct Input {
    /// The file shown in diagnostics: the shader's, or its host's.
    pub path: PathBuf,
    /// Its stage.
    pub stage: Stage,
    /// Where its text comes from.
    pub source: Source,
}

impl Input {
    /// How the input is named in messages: its path, or for an embedded shader
    /// `page.html:LINE` (the line its text starts on).
    pub fn label(&self) -> String {
        match &self.source {
            Source::Embedded(host, i) => {
                let start = host.embedded[*i].range.start;
                let line = host.text[..start].matches('\n').count() + 1;
                format!("{}:{line}", self.path.display())
            }
            _ => self.path.display().to_string(),
        }
    }
}

/// A shader found but not checked, and why.
#[derive(Clone, Debug)]
pub struct Skipped {
    /// `FILE:LINE:COLUMN` where its text starts.
    pub at: String,
    /// Why it is not checked.
    pub reason: &'static str,
}

/// What could not be searched or placed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum FindError {
    /// A path that does not exist, or a folder or host file that cannot be read.
    #[error("cannot read `{}`: {message}", .path.display())]
    Io {
        /// The path.
        path: PathBuf,
        /// What went wrong.
        message: String,
    },
    /// A `.glsl` file whose stage nothing tells.
    #[error(
        "cannot tell the stage of `{}`: name it `.vert` or `.frag` (or `NAME.vert.glsl`), add \
         `#pragma essl stage(vertex)` or `stage(fragment)`, or list it under `[stages]` in \
         essl.toml",
        .path.display()
    )]
    NoStage {
        /// The file.
        path: PathBuf,
    },
    /// `essl.toml` could not be used.
    #[error("{0}")]
    Config(#[from] essl_build::ConfigError),
}

/// How to find shaders.
#[derive(Clone, Debug, Default)]
pub struct Finder {
    /// `--stage`: the stage of named files (and standard input) that nothing else places.
    pub forced: Option<Stage>,
    /// The settings of `essl.toml` (its `exclude` and `[stages]`).
    pub config: Config,
    /// `--exclude`/`--extend-exclude` patterns, matched against paths as walked and file
    /// names.
    pub exclude: Option<GlobSet>,
    /// Whether `essl.toml`'s `exclude` applies (not when `--exclude` replaced it).
    pub config_exclude: bool,
    /// `--stdin-filename`: the name standard input is checked under.
    pub stdin_name: Option<PathBuf>,
}

/// What a search found.
#[derive(Debug, Default)]
pub struct Found {
    /// Shader files and standard input, sorted by path.
    pub inputs: Vec<Input>,
    /// Host files with at least one shader, sorted by path.
    pub hosts: Vec<Arc<Host>>,
    /// Shaders found but not checked.
    pub skipped: Vec<Skipped>,
    /// What could not be searched.
    pub errors: Vec<FindError>,
}

impl Found {
    /// How many shaders will be checked.
    pub fn shader_count(&self) -> usize {
        self.inputs.len()
            + self
                .hosts
                .iter()
                .map(|h| h.embedded.iter().filter(|e| e.skip.is_none()).count())
                .sum::<usize>()
    }
}

/// A path's stage from its name alone: `a.vert`, `a.vert.glsl`.
fn stage_from_name(path: &Path) -> Option<Stage> {
    Stage::from_path(path).or_else(|| {
        let ext = path.extension()?.to_str()?;
        if !ext.eq_ignore_ascii_case("glsl") {
            return None;
        }
        Stage::from_path(Path::new(path.file_stem()?))
    })
}

/// Whether a walk considers a file that its name does not place: `.glsl` and `.essl`.
fn is_glsl(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("glsl") || e.eq_ignore_ascii_case("essl"))
}

impl Finder {
    /// Finds the shaders `paths` name (`-`: standard input). A usage error (a named file whose
    /// stage nothing tells) is returned as `Err`.
    pub fn find(&self, paths: &[PathBuf]) -> Result<Found, String> {
        let mut found = Found::default();
        for path in paths {
            if path.as_os_str() == "-" {
                self.stdin(&mut found)?;
                continue;
            }
            match std::fs::metadata(path) {
                Ok(meta) if meta.is_dir() => self.walk(path, &mut found),
                Ok(_) => self.file(path, true, &mut found)?,
                Err(e) => found.errors.push(FindError::Io {
                    path: path.clone(),
                    message: io_message(&e),
                }),
            }
        }
        dedup(&mut found, paths.len() > 1);
        Ok(found)
    }

    /// The stage of a shader file, or `None` (`text` is read for the pragma when needed).
    fn stage_of(&self, path: &Path, named: bool) -> Result<Option<Stage>, FindError> {
        if let Some(s) = stage_from_name(path).or_else(|| self.config.stage_of(path)) {
            return Ok(Some(s));
        }
        if !named && !is_glsl(path) {
            return Ok(None);
        }
        let text = read_source(path).map_err(|e| FindError::Io {
            path: path.to_path_buf(),
            message: e.to_string(),
        })?;
        Ok(extract::stage_pragma(&text).or(if named { self.forced } else { None }))
    }

    /// One file: a shader, a host, or (in a walk) something else to pass over.
    fn file(&self, path: &Path, named: bool, found: &mut Found) -> Result<(), String> {
        if let Some(kind) = HostKind::of(path) {
            match read_source(path) {
                Ok(text) => self.host(path.to_path_buf(), text, kind, false, found),
                Err(e) => found.errors.push(FindError::Io {
                    path: path.to_path_buf(),
                    message: e.to_string(),
                }),
            }
            return Ok(());
        }
        match self.stage_of(path, named) {
            Ok(Some(stage)) => found.inputs.push(Input {
                path: path.to_path_buf(),
                stage,
                source: Source::File,
            }),
            Ok(None) if named => {
                return Err(format!(
                    "cannot tell the stage of `{}`: name it `.vert` or `.frag` (also `.vs`, \
                     `.fs`, `.vsh`, `.fsh`, `NAME.vert.glsl`), add `#pragma essl stage(vertex)`, \
                     or pass `--stage vertex` or `--stage fragment`",
                    path.display()
                ))
            }
            Ok(None) if is_glsl(path) => found.errors.push(FindError::NoStage {
                path: path.to_path_buf(),
            }),
            Ok(None) => {}
            Err(e) => found.errors.push(e),
        }
        Ok(())
    }

    /// A host file's shaders.
    fn host(&self, path: PathBuf, text: String, kind: HostKind, stdin: bool, found: &mut Found) {
        let embedded = extract::extract(kind, &text);
        if embedded.is_empty() {
            return;
        }
        let file = essl::source::SourceFile::new(path.display().to_string(), text.as_str());
        for e in embedded.iter().filter(|e| e.skip.is_some()) {
            let lc = file.line_col(e.range.start as u32);
            found.skipped.push(Skipped {
                at: format!("{}:{}:{}", path.display(), lc.line, lc.column),
                reason: e.skip.map_or("", |s| s.reason()),
            });
        }
        let pairs = extract::pairs(&embedded);
        found.hosts.push(Arc::new(Host {
            path,
            text,
            stdin,
            embedded,
            pairs,
        }));
    }

    /// Standard input, under `--stdin-filename` (or `<stdin>`).
    fn stdin(&self, found: &mut Found) -> Result<(), String> {
        use std::io::Read;
        let mut text = String::new();
        std::io::stdin()
            .take(essl_build::files::MAX_FILE_SIZE + 1)
            .read_to_string(&mut text)
            .map_err(|e| format!("cannot read standard input: {}", io_message(&e)))?;
        let path = self
            .stdin_name
            .clone()
            .unwrap_or_else(|| PathBuf::from("<stdin>"));
        if let Some(kind) = HostKind::of(&path) {
            self.host(path, text, kind, true, found);
            return Ok(());
        }
        let stage = stage_from_name(&path)
            .or_else(|| self.config.stage_of(&path))
            .or_else(|| extract::stage_pragma(&text))
            .or(self.forced)
            .ok_or_else(|| {
                "cannot tell the stage of standard input: pass `--stdin-filename NAME.frag` \
                 (or `.vert`, `.html`, `.js`…), `--stage`, or add `#pragma essl stage(vertex)`"
                    .to_string()
            })?;
        found.inputs.push(Input {
            path,
            stage,
            source: Source::Text(text.into()),
        });
        Ok(())
    }

    /// A folder, walked as git sees it.
    fn walk(&self, dir: &Path, found: &mut Found) {
        let exclude = self.exclude.clone();
        let config = self.config_exclude.then(|| self.config.clone());
        let walker = ignore::WalkBuilder::new(dir)
            .require_git(false)
            .git_global(false)
            .filter_entry(move |entry| {
                let path = entry.path();
                let by_flag = exclude.as_ref().is_some_and(|set| {
                    set.is_match(path) || path.file_name().is_some_and(|n| set.is_match(n))
                });
                !by_flag && !config.as_ref().is_some_and(|c| c.excludes(path))
            })
            .build();
        let mut files = Vec::new();
        let mut errors = Vec::new();
        for entry in walker {
            match entry {
                Ok(entry) if entry.file_type().is_some_and(|t| t.is_file()) => {
                    files.push(match entry.path().strip_prefix(".") {
                        Ok(rest) if dir == Path::new(".") => rest.to_path_buf(),
                        _ => entry.into_path(),
                    });
                }
                Ok(_) => {}
                Err(e) => errors.push(e.to_string()),
            }
        }
        // Sorted once here rather than by the walker, whose comparison splits both paths into
        // components at every step (4.4 M instructions for a folder of 600 files).
        files.sort_unstable_by(|a, b| path_order(a, b));
        for path in files {
            // Never an `Err`: only named files are usage errors.
            let _ = self.file(&path, false, found);
        }
        errors.sort();
        found
            .errors
            .extend(errors.into_iter().map(|message| FindError::Io {
                path: dir.to_path_buf(),
                message,
            }));
    }
}

/// `Path`'s component order (`a/x` before `a.b`, as a walk meets them) for paths a walk writes
/// below its folder (no `.` or `..` component after the folder's own), by bytes: paths compare
/// as if each separator were a 0 byte, which sorts before every byte a component can hold, so
/// only the first byte where they differ needs mapping.
fn path_order(a: &Path, b: &Path) -> std::cmp::Ordering {
    let key = |byte: u8| {
        if std::path::is_separator(char::from(byte)) {
            0
        } else {
            byte
        }
    };
    let (a, b) = (
        a.as_os_str().as_encoded_bytes(),
        b.as_os_str().as_encoded_bytes(),
    );
    match a.iter().zip(b).position(|(x, y)| x != y) {
        // Two different separators (`/` and `\` on Windows) are the same step.
        Some(i) if key(a[i]) == key(b[i]) => a[i..]
            .iter()
            .map(|&x| key(x))
            .cmp(b[i..].iter().map(|&x| key(x))),
        Some(i) => key(a[i]).cmp(&key(b[i])),
        None => a.len().cmp(&b.len()),
    }
}

/// Sorts by path and drops a file named twice (`a.frag` and `./a.frag`, or a file and its
/// folder), keeping the first name in path order. One path names every file once.
fn dedup(found: &mut Found, several: bool) {
    if !several {
        return;
    }
    let key = |p: &Path| std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf());
    found.inputs.sort_by(|a, b| a.path.cmp(&b.path));
    let mut seen = std::collections::HashSet::new();
    found
        .inputs
        .retain(|i| matches!(i.source, Source::Text(_)) || seen.insert(key(&i.path)));
    found.hosts.sort_by(|a, b| a.path.cmp(&b.path));
    found.hosts.retain(|h| h.stdin || seen.insert(key(&h.path)));
}

#[cfg(test)]
mod tests {
    use super::path_order;
    use std::path::Path;

    /// Every path of up to four characters from `a`, `.`, `-` and `/`, as a walk writes them
    /// below its folder (no empty, `.` or `..` component).
    fn paths() -> Vec<String> {
        let mut all = vec![String::new()];
        let mut out = Vec::new();
        for _ in 0..4 {
            all = all
                .iter()
                .flat_map(|p| ["a", ".", "-", "/"].map(|c| format!("{p}{c}")))
                .collect();
            out.extend(
                all.iter()
                    .filter(|p| p.split('/').all(|c| !matches!(c, "" | "." | "..")))
                    .cloned(),
            );
        }
        out
    }

    #[test]
    fn byte_order_with_separators_first_is_path_order() {
        let paths = paths();
        for a in &paths {
            for b in &paths {
                assert_eq!(
                    path_order(Path::new(a), Path::new(b)),
                    Path::new(a).cmp(Path::new(b)),
                    "{a} against {b}"
                );
            }
        }
    }
}
