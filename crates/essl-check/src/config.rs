//! `essl.toml`: a project's settings for checking its shaders, found upward from each shader as
//! ruff finds `ruff.toml`. Every key is optional; an unknown key is an error (a typo must not
//! silently turn a setting off).
//!
//! ```toml
//! # The WebGL version the shaders are for: "webgl2" (the default) or "webgl1".
//! target = "webgl2"
//! # Files and folders to leave out, as globs relative to this file's folder.
//! exclude = ["vendor/**", "*.verbatim.frag"]
//! # Folders `#include "FILE"` searches (relative to this file's folder), for `essl lint`.
//! include = ["shaders/common"]
//! # A library whose way of assembling shaders to follow: "luma" (luma.gl, deck.gl) or
//! # "three" (three.js materials).
//! preset = "luma"
//! # How many `#ifdef` configurations besides the one the defines select the lints also
//! # check (each flag's code, and all flags together): 64 by default, 0 for none.
//! variants = 64
//! # Files that are chunks — code to put into shaders, checked as a library (no `main`, names
//! # free for the including shader to declare) — as globs relative to this file's folder.
//! chunks = ["shaders/chunks/**"]
//!
//! # The stage of files whose extension does not tell it (`.glsl`), as globs relative to this
//! # file's folder or matching a file name.
//! [stages]
//! vertex = ["*.vs.glsl", "vertex/**"]
//! fragment = ["*.fs.glsl"]
//!
//! # Macros defined before each shader's first line, as `#define NAME VALUE`.
//! [defines]
//! USE_FOG = "1"
//!
//! # Lint levels: "allow", "warn" or "deny". `all` sets every rule first; `warnings = "deny"`
//! # makes every warning (front-end warnings too) an error.
//! [rules]
//! smoothstep-edges = "deny"
//! mediump-overflow = "allow"
//! ```

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use essl_lint::{Level, LintOptions};
use globset::{Glob, GlobSet, GlobSetBuilder};
use serde::Deserialize;

/// The file name looked for.
pub const FILE_NAME: &str = "essl.toml";

/// Why an `essl.toml` could not be used. Each names the file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ConfigError {
    /// The file could not be read.
    #[error("{}: {}", .path.display(), crate::read::io_message(.source))]
    Read {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        source: std::io::Error,
    },
    /// The file is not TOML, or has a key or a value of a type that is not listed.
    #[error("{}: {message}", .path.display())]
    Syntax {
        /// The file.
        path: PathBuf,
        /// The TOML parser's message, with the line and column.
        message: String,
    },
    /// `target` names a WebGL version essl does not check.
    #[error("{}: target `{target}` is not supported (supported: webgl2, webgl1)", .path.display())]
    Target {
        /// The file.
        path: PathBuf,
        /// The value given.
        target: String,
    },
    /// `preset` names no preset essl has.
    #[error("{}: preset `{preset}` is not one essl has (it has: luma, three)", .path.display())]
    Preset {
        /// The file.
        path: PathBuf,
        /// The value given.
        preset: String,
    },
    /// A `[rules]` key that is no rule, or a level that is not allow/warn/deny.
    #[error("{}: [rules] {message}", .path.display())]
    Rule {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// An `exclude` or `[stages]` pattern that is not a glob.
    #[error("{}: pattern `{pattern}`: {message}", .path.display())]
    Glob {
        /// The file.
        path: PathBuf,
        /// The pattern.
        pattern: String,
        /// What is wrong.
        message: String,
    },
}

/// The file as written.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct ConfigFile {
    target: Option<String>,
    #[serde(default)]
    exclude: Vec<String>,
    #[serde(default)]
    defines: BTreeMap<String, String>,
    #[serde(default)]
    rules: BTreeMap<String, String>,
    #[serde(default)]
    include: Vec<PathBuf>,
    #[serde(default)]
    chunks: Vec<String>,
    preset: Option<String>,
    variants: Option<usize>,
    #[serde(default)]
    stages: StagesFile,
}

/// The `[stages]` table as written.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct StagesFile {
    #[serde(default)]
    vertex: Vec<String>,
    #[serde(default)]
    fragment: Vec<String>,
}

/// The settings for the shaders under one folder: an `essl.toml` read and checked, or the
/// defaults.
#[derive(Clone, Debug, Default)]
pub struct Config {
    /// The file the settings come from (`None`: the defaults).
    pub path: Option<PathBuf>,
    /// Macros defined before each shader's first line, in name order.
    pub defines: Vec<(String, String)>,
    /// Lint levels.
    pub rules: LintOptions,
    /// `warnings = "deny"`: every warning counts as an error.
    pub deny_warnings: bool,
    /// The WebGL version named by `target` (`None`: not set, WebGL 2).
    pub target: Option<essl::Target>,
    /// `include`: folders `#include` searches, relative to the file's folder as written.
    pub include: Vec<PathBuf>,
    /// The `exclude` patterns as written.
    pub exclude_patterns: Vec<String>,
    /// The `[stages]` patterns as written: vertex, then fragment.
    pub stage_patterns: [Vec<String>; 2],
    /// The `chunks` patterns as written.
    pub chunk_patterns: Vec<String>,
    /// `preset`: the library whose way of assembling shaders to follow.
    pub preset: Option<crate::preset::Preset>,
    /// `variants`: how many `#ifdef` configurations the lints check besides the one the
    /// defines select (`None`: not set, [`essl_lint::variants::DEFAULT`]).
    pub variants: Option<usize>,
    exclude: Option<GlobSet>,
    stages: [Option<GlobSet>; 2],
    chunks: Option<GlobSet>,
}

impl Config {
    /// Reads and checks an `essl.toml`.
    pub fn load(path: &Path) -> Result<Config, ConfigError> {
        let text = std::fs::read_to_string(path).map_err(|source| ConfigError::Read {
            path: path.to_path_buf(),
            source,
        })?;
        Config::parse(&text, path)
    }

    /// Checks the text of an `essl.toml` that lives at `path`.
    pub fn parse(text: &str, path: &Path) -> Result<Config, ConfigError> {
        let file: ConfigFile = toml::from_str(text).map_err(|e| ConfigError::Syntax {
            path: path.to_path_buf(),
            message: e.to_string().trim_end().to_string(),
        })?;
        let target = match file.target.as_deref() {
            None => None,
            Some("webgl2") => Some(essl::Target::WebGl2),
            Some("webgl1") => Some(essl::Target::WebGl1),
            Some(other) => {
                return Err(ConfigError::Target {
                    path: path.to_path_buf(),
                    target: other.to_string(),
                })
            }
        };
        let mut rules = LintOptions::new();
        let mut deny_warnings = false;
        // `all` first, so that a rule named beside it wins whatever the key order.
        let mut entries: Vec<(&String, &String)> = file.rules.iter().collect();
        entries.sort_by_key(|(rule, _)| *rule != "all");
        for (rule, level) in entries {
            let level = match level.as_str() {
                "allow" => Level::Allow,
                "warn" => Level::Warn,
                "deny" => Level::Deny,
                other => {
                    return Err(ConfigError::Rule {
                        path: path.to_path_buf(),
                        message: format!("{rule} = \"{other}\": the level is allow, warn or deny"),
                    })
                }
            };
            if rule == "warnings" {
                deny_warnings = level == Level::Deny;
                continue;
            }
            rules.set(rule, level).map_err(|e| ConfigError::Rule {
                path: path.to_path_buf(),
                message: e.to_string(),
            })?;
        }
        let exclude = glob_set(&file.exclude, path)?;
        let chunks = glob_set(&file.chunks, path)?;
        let preset =
            match file.preset.as_deref() {
                None => None,
                Some(name) => Some(crate::preset::Preset::from_name(name).ok_or_else(|| {
                    ConfigError::Preset {
                        path: path.to_path_buf(),
                        preset: name.to_string(),
                    }
                })?),
            };
        let stages = [
            glob_set(&file.stages.vertex, path)?,
            glob_set(&file.stages.fragment, path)?,
        ];
        Ok(Config {
            path: Some(path.to_path_buf()),
            defines: file.defines.into_iter().collect(),
            rules,
            deny_warnings,
            target,
            include: file.include,
            exclude_patterns: file.exclude,
            stage_patterns: [file.stages.vertex, file.stages.fragment],
            chunk_patterns: file.chunks,
            preset,
            variants: file.variants,
            exclude,
            stages,
            chunks,
        })
    }

    /// The nearest `essl.toml` in `dir` or a folder above it, read; `None` when there is none.
    pub fn discover(dir: &Path) -> Result<Option<Config>, ConfigError> {
        let start = std::fs::canonicalize(dir).unwrap_or_else(|_| dir.to_path_buf());
        for folder in start.ancestors() {
            let candidate = folder.join(FILE_NAME);
            if candidate.is_file() {
                return Config::load(&candidate).map(Some);
            }
        }
        Ok(None)
    }

    /// Whether `path` matches an `exclude` pattern (patterns are relative to the folder of the
    /// `essl.toml`; a pattern without `/` also matches a file name in any folder).
    pub fn excludes(&self, path: &Path) -> bool {
        self.matches(self.exclude.as_ref(), path)
    }

    /// Whether `path` matches a `chunks` pattern.
    pub fn is_chunk(&self, path: &Path) -> bool {
        self.matches(self.chunks.as_ref(), path)
    }

    /// The stage `[stages]` gives `path` (vertex patterns first), if a pattern matches.
    pub fn stage_of(&self, path: &Path) -> Option<essl::Stage> {
        if self.matches(self.stages[0].as_ref(), path) {
            Some(essl::Stage::Vertex)
        } else if self.matches(self.stages[1].as_ref(), path) {
            Some(essl::Stage::Fragment)
        } else {
            None
        }
    }

    /// Whether `path`, relative to this file's folder, or its file name matches `set`.
    fn matches(&self, set: Option<&GlobSet>, path: &Path) -> bool {
        let (Some(set), Some(file)) = (set, &self.path) else {
            return false;
        };
        let base = file.parent().unwrap_or(Path::new(""));
        let abs = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
        let relative = abs.strip_prefix(base).unwrap_or(&abs);
        set.is_match(relative) || path.file_name().is_some_and(|name| set.is_match(name))
    }

    /// The `include` folders, resolved against this file's folder.
    pub fn include_dirs(&self) -> Vec<PathBuf> {
        let base = self
            .path
            .as_deref()
            .and_then(Path::parent)
            .unwrap_or(Path::new(""));
        self.include.iter().map(|d| base.join(d)).collect()
    }

    /// The compile options these settings give.
    pub fn compile_options(&self) -> essl::CompileOptions {
        essl::CompileOptions {
            defines: self.defines.clone(),
            ..essl::CompileOptions::for_target(self.target.unwrap_or(essl::Target::WebGl2))
        }
    }
}

/// The glob set of `patterns` (`None` when there are none); an error names the pattern.
fn glob_set(patterns: &[String], path: &Path) -> Result<Option<GlobSet>, ConfigError> {
    if patterns.is_empty() {
        return Ok(None);
    }
    let mut set = GlobSetBuilder::new();
    for pattern in patterns {
        let glob = Glob::new(pattern).map_err(|e| ConfigError::Glob {
            path: path.to_path_buf(),
            pattern: pattern.clone(),
            message: e.kind().to_string(),
        })?;
        set.add(glob);
    }
    set.build().map(Some).map_err(|e| ConfigError::Glob {
        path: path.to_path_buf(),
        pattern: patterns.join(", "),
        message: e.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<Config, ConfigError> {
        Config::parse(text, Path::new("/p/essl.toml"))
    }

    #[test]
    fn every_key() {
        let c = parse(
            "target = \"webgl2\"\nexclude = [\"vendor/**\"]\n[defines]\nB = \"2\"\nA = \"1\"\n\
             [rules]\nsmoothstep-edges = \"deny\"\nall = \"allow\"\nwarnings = \"deny\"\n",
        )
        .unwrap();
        assert_eq!(
            c.defines,
            [("A".into(), "1".into()), ("B".into(), "2".into())]
        );
        assert!(c.deny_warnings);
        let smoothstep = essl_lint::rule("smoothstep-edges").unwrap();
        assert_eq!(c.rules.level(smoothstep), Level::Deny, "a rule beats `all`");
        let pow = essl_lint::rule("pow-negative-base").unwrap();
        assert_eq!(c.rules.level(pow), Level::Allow);
    }

    #[test]
    fn mistakes_name_the_file_and_the_key() {
        let e = |text: &str| parse(text).unwrap_err().to_string();
        assert!(e("targt = \"webgl2\"\n").starts_with("/p/essl.toml: "));
        assert!(e("targt = \"webgl2\"\n").contains("unknown field `targt`"));
        assert_eq!(
            e("target = \"webgl3\"\n"),
            "/p/essl.toml: target `webgl3` is not supported (supported: webgl2, webgl1)"
        );
        assert!(
            e("[rules]\nno-such-rule = \"deny\"\n").contains("unknown lint rule `no-such-rule`")
        );
        assert_eq!(
            e("[rules]\nall = \"error\"\n"),
            "/p/essl.toml: [rules] all = \"error\": the level is allow, warn or deny"
        );
        assert!(e("exclude = [\"a[\"]\n").contains("pattern `a[`"));
        assert!(e("[stages]\ngeometry = []\n").contains("unknown field `geometry`"));
    }

    #[test]
    fn exclude_is_relative_to_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let root = std::fs::canonicalize(dir.path()).unwrap();
        std::fs::create_dir_all(root.join("shaders/vendor")).unwrap();
        std::fs::write(
            root.join(FILE_NAME),
            "exclude = [\"shaders/vendor/**\", \"*.old.frag\"]\n",
        )
        .unwrap();
        let c = Config::discover(&root.join("shaders/vendor"))
            .unwrap()
            .unwrap();
        assert!(c.excludes(&root.join("shaders/vendor/x.frag")));
        assert!(c.excludes(&root.join("shaders/a.old.frag")));
        assert!(!c.excludes(&root.join("shaders/a.frag")));
        assert!(Config::discover(Path::new("/")).unwrap().is_none());
    }

    #[test]
    fn stages_and_target() {
        let c = parse(
            "target = \"webgl1\"\ninclude = [\"common\"]\n[stages]\nvertex = [\"*.vs.glsl\"]\n\
             fragment = [\"frag/**\"]\n",
        )
        .unwrap();
        assert_eq!(c.target, Some(essl::Target::WebGl1));
        assert_eq!(c.include_dirs(), [PathBuf::from("/p/common")]);
        assert_eq!(
            c.stage_of(Path::new("/p/a.vs.glsl")),
            Some(essl::Stage::Vertex)
        );
        assert_eq!(
            c.stage_of(Path::new("/p/frag/b.glsl")),
            Some(essl::Stage::Fragment)
        );
        assert_eq!(c.stage_of(Path::new("/p/c.glsl")), None);
    }
}
