//! `essl.toml`: a project's settings for checking its shaders, found upward from each shader as
//! ruff finds `ruff.toml`. Every key is optional; an unknown key is an error (a typo must not
//! silently turn a setting off).
//!
//! ```toml
//! # The WebGL version the shaders are for (only "webgl2" today).
//! target = "webgl2"
//! # Files and folders to leave out, as globs relative to this file's folder.
//! exclude = ["vendor/**", "*.verbatim.frag"]
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
    #[error("{}: {}", .path.display(), crate::files::io_message(.source))]
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
    #[error("{}: target `{target}` is not supported (supported: webgl2)", .path.display())]
    Target {
        /// The file.
        path: PathBuf,
        /// The value given.
        target: String,
    },
    /// A `[rules]` key that is no rule, or a level that is not allow/warn/deny.
    #[error("{}: [rules] {message}", .path.display())]
    Rule {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// An `exclude` pattern that is not a glob.
    #[error("{}: exclude pattern `{pattern}`: {message}", .path.display())]
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
    exclude: Option<GlobSet>,
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
        if let Some(target) = file.target.filter(|t| t != "webgl2") {
            return Err(ConfigError::Target {
                path: path.to_path_buf(),
                target,
            });
        }
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
        let exclude = if file.exclude.is_empty() {
            None
        } else {
            let mut set = GlobSetBuilder::new();
            for pattern in &file.exclude {
                let glob = Glob::new(pattern).map_err(|e| ConfigError::Glob {
                    path: path.to_path_buf(),
                    pattern: pattern.clone(),
                    message: e.kind().to_string(),
                })?;
                set.add(glob);
            }
            Some(set.build().map_err(|e| ConfigError::Glob {
                path: path.to_path_buf(),
                pattern: file.exclude.join(", "),
                message: e.to_string(),
            })?)
        };
        Ok(Config {
            path: Some(path.to_path_buf()),
            defines: file.defines.into_iter().collect(),
            rules,
            deny_warnings,
            exclude,
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
        let (Some(set), Some(file)) = (&self.exclude, &self.path) else {
            return false;
        };
        let base = file.parent().unwrap_or(Path::new(""));
        let abs = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
        let relative = abs.strip_prefix(base).unwrap_or(&abs);
        set.is_match(relative) || path.file_name().is_some_and(|name| set.is_match(name))
    }

    /// The compile options these settings give.
    pub fn compile_options(&self) -> essl::CompileOptions {
        essl::CompileOptions {
            defines: self.defines.clone(),
            ..essl::CompileOptions::default()
        }
    }
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
            e("target = \"webgl1\"\n"),
            "/p/essl.toml: target `webgl1` is not supported (supported: webgl2)"
        );
        assert!(
            e("[rules]\nno-such-rule = \"deny\"\n").contains("unknown lint rule `no-such-rule`")
        );
        assert_eq!(
            e("[rules]\nall = \"error\"\n"),
            "/p/essl.toml: [rules] all = \"error\": the level is allow, warn or deny"
        );
        assert!(e("exclude = [\"a[\"]\n").contains("exclude pattern `a[`"));
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
}
