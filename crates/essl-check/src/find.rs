//! Finding the shaders to check: files named, folders walked as git would see them
//! (`.gitignore`, `.ignore`, hidden entries skipped; `exclude` patterns), standard input (`-`),
//! and the shaders inside HTML, JS and TS files ([`crate::extract`]).
//!
//! A shader's stage comes from its extension (`.vert`/`.vs`/`.vsh`, `.frag`/`.fs`/`.fsh`, also
//! before `.glsl`: `light.vert.glsl`), then from the `[stages]` globs of its `essl.toml`, then
//! from a `#pragma essl stage(vertex)` line, then from the forced stage (`--stage`) for a file
//! named explicitly. A `.glsl` file found in a folder that none of these places is an error
//! naming the file, never silently skipped.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use essl::source::SourceFile;
use essl::Stage;
use globset::GlobSet;

use crate::extract::{self, Embedded, HostKind, Skip};
use crate::read::{io_message, read_source, MAX_FILE_SIZE};
use crate::settings::Configs;

/// A shader file, or standard input, to check.
#[derive(Clone, Debug)]
pub struct Input {
    /// The file shown in diagnostics (standard input's `--stdin-filename`, or `<stdin>`).
    pub path: PathBuf,
    /// Its stage.
    pub stage: Stage,
    /// Its text, where it is not read from `path` (standard input, an editor's buffer).
    pub text: Option<Arc<str>>,
    /// Whether it is a chunk: code to put into shaders (`#pragma essl chunk`, essl.toml's
    /// `chunks`, a `.glsl` file in an include folder), checked as a library.
    pub chunk: bool,
}

/// A file that holds shaders inside it (an HTML page, a script), read and searched.
#[derive(Debug)]
pub struct Host {
    /// Its path (the `--stdin-filename` for standard input).
    pub path: PathBuf,
    /// What kind of file it is.
    pub kind: HostKind,
    /// Its text.
    pub file: Arc<SourceFile>,
    /// Whether it came from standard input (fixes are then written to standard output).
    pub stdin: bool,
    /// The shaders in it.
    pub embedded: Vec<Embedded>,
}

impl Host {
    /// Reads the shaders of `text`, a file of kind `kind` at `path` (what its literals import
    /// is read beside it).
    pub fn new(path: PathBuf, kind: HostKind, text: String, stdin: bool) -> Host {
        let embedded = Host::extract(&path, kind, &text);
        let file = Arc::new(SourceFile::new(path.display().to_string(), text));
        Host {
            path,
            kind,
            file,
            stdin,
            embedded,
        }
    }

    /// The shaders in `text`, the text of a host file at `path`.
    pub fn extract(path: &Path, kind: HostKind, text: &str) -> Vec<Embedded> {
        let dir = path.parent().unwrap_or(Path::new(""));
        extract::extract(kind, text, &crate::imports::DiskImports::new(dir))
    }

    /// How many of its shaders are checked.
    pub fn checked(&self) -> usize {
        self.embedded.iter().filter(|e| e.skip.is_none()).count()
    }
}

/// A shader found but not checked, and why.
#[derive(Clone, Debug)]
pub struct Skipped {
    /// `FILE:LINE:COLUMN` where its text starts.
    pub at: String,
    /// Its byte range in its host file.
    pub range: std::ops::Range<usize>,
    /// Why it is not checked.
    pub skip: Skip,
}

impl Skipped {
    /// Why it is not checked, in words.
    pub fn reason(&self) -> &'static str {
        self.skip.reason()
    }
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
    /// An `essl.toml` could not be used; the files it governs are not checked.
    #[error("{0}")]
    Config(Arc<crate::ConfigError>),
}

/// A usage error: what was named cannot be checked at all.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum UsageError {
    /// A file named explicitly whose stage nothing tells.
    #[error(
        "cannot tell the stage of `{}`: name it `.vert` or `.frag` (also `.vs`, `.fs`, `.vsh`, \
         `.fsh`, `NAME.vert.glsl`), add `#pragma essl stage(vertex)`, or pass `--stage vertex` \
         or `--stage fragment`",
        .0.display()
    )]
    NoStage(PathBuf),
    /// Standard input's stage is not told.
    #[error(
        "cannot tell the stage of standard input: pass `--stdin-filename NAME.frag` (or \
         `.vert`, `.html`, `.js`…), `--stage`, or add `#pragma essl stage(vertex)`"
    )]
    StdinStage,
    /// Standard input could not be read.
    #[error("cannot read standard input: {0}")]
    Stdin(String),
    /// The `essl.toml` that applies to the text cannot be read (a `--config` that names no
    /// file, a malformed one found upward).
    #[error("{0}")]
    Config(Arc<crate::ConfigError>),
}

/// How to find shaders beyond essl.toml: the caller's exclude patterns, and the name standard
/// input is checked under.
#[derive(Clone, Debug, Default)]
pub struct FindOptions {
    /// `--exclude`/`--extend-exclude` patterns, matched against paths as walked and file
    /// names.
    pub exclude: Option<GlobSet>,
    /// Whether essl.toml's `exclude` applies (not when `--exclude` replaced it).
    pub config_exclude: bool,
    /// `--stdin-filename`: the name standard input is checked under.
    pub stdin_name: Option<PathBuf>,
    /// Look for shaders inside HTML and JS/TS files.
    pub hosts: bool,
}

impl FindOptions {
    /// essl.toml's excludes, hosts searched: what `essl lint` does without flags.
    pub fn new() -> FindOptions {
        FindOptions {
            exclude: None,
            config_exclude: true,
            stdin_name: None,
            hosts: true,
        }
    }
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
        self.inputs.len() + self.hosts.iter().map(|h| h.checked()).sum::<usize>()
    }
}

/// A path's stage from its name alone: `a.vert`, `a.vert.glsl`.
pub fn stage_from_name(path: &Path) -> Option<Stage> {
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

/// A search: the options, the settings of each folder, and what it found so far.
struct Search<'a> {
    options: &'a FindOptions,
    configs: &'a Configs,
    found: Found,
}

/// Finds the shaders `paths` name (`-`: standard input).
pub fn find(
    paths: &[PathBuf],
    options: &FindOptions,
    configs: &Configs,
) -> Result<Found, UsageError> {
    let mut s = Search {
        options,
        configs,
        found: Found::default(),
    };
    for path in paths {
        if path.as_os_str() == "-" {
            s.stdin()?;
            continue;
        }
        match std::fs::metadata(path) {
            Ok(meta) if meta.is_dir() => s.walk(path),
            Ok(_) => s.file(path, true)?,
            Err(e) => s.found.errors.push(FindError::Io {
                path: path.clone(),
                message: io_message(&e),
            }),
        }
    }
    let mut found = s.found;
    dedup(&mut found, paths.len() > 1);
    Ok(found)
}

/// The shaders in `text`, a file at `path` (not read from disk: an editor's buffer, a
/// bundler's module): a host's, or the one shader a shader file is.
pub fn find_text(path: &Path, text: String, configs: &Configs) -> Result<Found, UsageError> {
    let options = FindOptions::new();
    let mut s = Search {
        options: &options,
        configs,
        found: Found::default(),
    };
    s.text(path.to_path_buf(), text, false)?;
    Ok(s.found)
}

impl Search<'_> {
    /// The stage of a shader file at `path` from its name and settings, or the pragma in
    /// `text`; `None` where nothing tells.
    fn stage_of(&mut self, path: &Path, text: Option<&str>, named: bool) -> Option<Stage> {
        let by_config = || {
            let settings = self.configs.for_file(path).ok()?;
            settings.config.stage_of(path)
        };
        let by_name = stage_from_name(path).or_else(by_config);
        by_name
            .or_else(|| text.and_then(extract::stage_pragma))
            .or(if named {
                self.configs.overrides().stage
            } else {
                None
            })
    }

    /// One file on disk: a shader, a host, or (in a walk) something else to pass over.
    fn file(&mut self, path: &Path, named: bool) -> Result<(), UsageError> {
        if let Err(e) = self.configs.for_file(path) {
            self.config_error(e);
            return Ok(());
        }
        if let Some(kind) = HostKind::of(path).filter(|_| self.options.hosts) {
            match read_source(path) {
                Ok(text) => self.host(Host::new(path.to_path_buf(), kind, text, false)),
                Err(e) => self.found.errors.push(FindError::Io {
                    path: path.to_path_buf(),
                    message: e.to_string(),
                }),
            }
            return Ok(());
        }
        let mut stage = self.stage_of(path, None, false);
        let by_config = self
            .configs
            .for_file(path)
            .is_ok_and(|s| s.config.is_chunk(path));
        let mut chunk = by_config || (is_glsl(path) && self.in_include_folder(path));
        if stage.is_none() && (named || is_glsl(path)) {
            match read_source(path) {
                Ok(text) => {
                    stage = self.stage_of(path, Some(&text), named);
                    chunk |= extract::chunk_pragma(&text);
                }
                Err(e) => {
                    self.found.errors.push(FindError::Io {
                        path: path.to_path_buf(),
                        message: e.to_string(),
                    });
                    return Ok(());
                }
            }
        }
        // A chunk compiles alike in both stages unless something says which it is for.
        let stage = stage.or(chunk.then_some(Stage::Vertex));
        match stage {
            Some(stage) => self.found.inputs.push(Input {
                path: path.to_path_buf(),
                stage,
                text: None,
                chunk,
            }),
            None if named => return Err(UsageError::NoStage(path.to_path_buf())),
            None if is_glsl(path) => self.found.errors.push(FindError::NoStage {
                path: path.to_path_buf(),
            }),
            None => {}
        }
        Ok(())
    }

    /// A text not on disk, named `path`.
    fn text(&mut self, path: PathBuf, text: String, stdin: bool) -> Result<(), UsageError> {
        if let Some(kind) = HostKind::of(&path) {
            self.host(Host::new(path, kind, text, stdin));
            return Ok(());
        }
        let chunk = extract::chunk_pragma(&text)
            || self
                .configs
                .for_file(&path)
                .is_ok_and(|s| s.config.is_chunk(&path))
            || (is_glsl(&path) && self.in_include_folder(&path));
        let stage = self
            .stage_of(&path, Some(&text), true)
            .or(chunk.then_some(Stage::Vertex));
        let stage = match stage {
            Some(s) => s,
            None if stdin => return Err(UsageError::StdinStage),
            None => return Err(UsageError::NoStage(path)),
        };
        self.found.inputs.push(Input {
            path,
            stage,
            text: Some(text.into()),
            chunk,
        });
        Ok(())
    }

    /// Whether `path` lies in an include folder of its settings: a file to include (a chunk),
    /// not a shader.
    fn in_include_folder(&self, path: &Path) -> bool {
        let Ok(settings) = self.configs.for_file(path) else {
            return false;
        };
        let Some(dirs) = &settings.include else {
            return false;
        };
        let real = |p: &Path| std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf());
        let file = real(path);
        dirs.iter().any(|d| file.starts_with(real(d)))
    }

    fn config_error(&mut self, e: Arc<crate::ConfigError>) {
        let known = self.found.errors.iter().any(|x| match x {
            FindError::Config(c) => Arc::ptr_eq(c, &e),
            _ => false,
        });
        if !known {
            self.found.errors.push(FindError::Config(e));
        }
    }

    /// A host file's shaders, with a note for each one not checked. A script with none is
    /// kept where a preset applies and it may name a program (its shaders in other files).
    fn host(&mut self, host: Host) {
        let programs = host.kind == HostKind::Script
            && ["modules", "getShaders", "vertexShader", "fragmentShader"]
                .iter()
                .any(|w| host.file.text().contains(w))
            && self
                .configs
                .for_file(&host.path)
                .is_ok_and(|s| s.preset.is_some());
        if host.embedded.is_empty() && !programs {
            return;
        }
        for e in &host.embedded {
            let Some(skip) = e.skip else { continue };
            let lc = host.file.line_col(e.range.start as u32);
            self.found.skipped.push(Skipped {
                at: format!("{}:{}:{}", host.path.display(), lc.line, lc.column),
                range: e.range.clone(),
                skip,
            });
        }
        self.found.hosts.push(Arc::new(host));
    }

    /// Standard input, under `--stdin-filename` (or `<stdin>`).
    fn stdin(&mut self) -> Result<(), UsageError> {
        use std::io::Read;
        let mut text = String::new();
        std::io::stdin()
            .take(MAX_FILE_SIZE + 1)
            .read_to_string(&mut text)
            .map_err(|e| UsageError::Stdin(io_message(&e)))?;
        let path = self
            .options
            .stdin_name
            .clone()
            .unwrap_or_else(|| PathBuf::from("<stdin>"));
        self.text(path, text, true)
    }

    /// A folder, walked as git sees it.
    fn walk(&mut self, dir: &Path) {
        let exclude = self.options.exclude.clone();
        let by_config = self.options.config_exclude;
        let configs = self.configs.clone();
        let walker = ignore::WalkBuilder::new(dir)
            .require_git(false)
            .git_global(false)
            .filter_entry(move |entry| {
                let path = entry.path();
                let by_flag = exclude.as_ref().is_some_and(|set| {
                    set.is_match(path) || path.file_name().is_some_and(|n| set.is_match(n))
                });
                // Each file (and folder) is excluded by the `essl.toml` that governs it.
                let by_file = by_config
                    && entry.depth() > 0
                    && configs
                        .for_file(path)
                        .is_ok_and(|s| s.config.excludes(path));
                !by_flag && !by_file
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
            let _ = self.file(&path, false);
        }
        errors.sort();
        self.found
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
        .retain(|i| i.text.is_some() || seen.insert(key(&i.path)));
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
