//! The settings a shader is checked with: the nearest `essl.toml` above it (as ruff finds
//! `ruff.toml`: each folder's own, so that a project's `vendor/` can have other rules), with
//! what the caller asks on top ([`Overrides`]: the command line's flags, a plugin's options).

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use essl::{CompileOptions, Stage, Target};
use essl_lint::{Level, LintOptions, UnknownRule};

use crate::config::{Config, ConfigError};

/// What a caller asks beyond `essl.toml`.
#[derive(Clone, Debug, Default)]
pub struct Overrides {
    /// One `essl.toml` for every shader instead of each folder's nearest (`--config FILE`).
    pub config: Option<PathBuf>,
    /// The WebGL version, instead of essl.toml's `target`.
    pub target: Option<Target>,
    /// Macros defined after essl.toml's (`-D NAME=VALUE`).
    pub defines: Vec<(String, String)>,
    /// Include folders searched before essl.toml's (`-I DIR`); giving one turns `#include` on.
    pub include_dirs: Vec<PathBuf>,
    /// Follow `#include` even with no include folder (each file's own folder is searched), as
    /// a bundler plugin does.
    pub includes: bool,
    /// Rule levels set after essl.toml's, in order (`--allow`, `--deny`…); [`Overrides::rule`]
    /// adds one after checking its name (a rule no rule has matches nothing).
    pub rules: Vec<(String, Level)>,
    /// `--deny warnings`: every warning counts as an error.
    pub deny_warnings: bool,
    /// The stage of a file named explicitly (or standard input) that nothing else places.
    pub stage: Option<Stage>,
    /// The preset, instead of essl.toml's.
    pub preset: Option<crate::preset::Preset>,
    /// How many `#ifdef` configurations the lints check, instead of essl.toml's `variants`.
    pub variants: Option<usize>,
}

impl Overrides {
    /// Sets a rule's level after essl.toml's (`all`: every rule's); an unknown rule is an error.
    pub fn rule(&mut self, rule: &str, level: Level) -> Result<(), UnknownRule> {
        LintOptions::new().set(rule, level)?;
        self.rules.push((rule.to_string(), level));
        Ok(())
    }
}

/// The settings one shader is checked with.
#[derive(Clone, Debug)]
pub struct Settings {
    /// The `essl.toml` they come from (the defaults where there is none).
    pub config: Arc<Config>,
    /// The front end's options: target, macros.
    pub compile: CompileOptions,
    /// The lint rules' levels (notes on: callers decide whether to show them).
    pub rules: LintOptions,
    /// Whether warnings count as errors.
    pub deny_warnings: bool,
    /// The folders `#include` searches after the including file's own, where `#include` is
    /// followed at all (`None`: it is an error, as in GLSL ES).
    pub include: Option<Vec<PathBuf>>,
    /// The library whose way of assembling shaders a check follows.
    pub preset: Option<crate::preset::Preset>,
    /// How many `#ifdef` configurations besides the one the defines select the lints check
    /// ([`essl_lint::variants`]; 0: none).
    pub variants: usize,
}

impl Settings {
    /// `config` with `overrides` on top.
    pub fn new(config: Arc<Config>, overrides: &Overrides) -> Settings {
        let mut compile = config.compile_options();
        if let Some(target) = overrides.target {
            compile.target = target;
        }
        compile.defines.extend(overrides.defines.iter().cloned());
        let mut rules = config.rules.clone().notes(true);
        for (rule, level) in &overrides.rules {
            // Checked by `Overrides::rule`.
            let _ = rules.set(rule, *level);
        }
        let mut dirs = overrides.include_dirs.clone();
        // essl.toml's folders are absolute (the file is found from a canonical path); written
        // relative to the working folder where they are below it, included files are named
        // as the walk names the files beside them.
        let cwd = std::env::current_dir().ok();
        dirs.extend(config.include_dirs().into_iter().map(|d| {
            match cwd.as_deref().and_then(|c| d.strip_prefix(c).ok()) {
                Some(rel) if !rel.as_os_str().is_empty() => rel.to_path_buf(),
                _ => d,
            }
        }));
        let include = (overrides.includes || !dirs.is_empty()).then_some(dirs);
        Settings {
            preset: overrides.preset.or(config.preset),
            variants: overrides
                .variants
                .or(config.variants)
                .unwrap_or(essl_lint::variants::DEFAULT),
            deny_warnings: overrides.deny_warnings || config.deny_warnings,
            config,
            compile,
            rules,
            include,
        }
    }

    /// The defaults with `overrides` on top, for a text that lives in no folder.
    pub fn defaults(overrides: &Overrides) -> Settings {
        Settings::new(Arc::new(Config::default()), overrides)
    }
}

/// The settings of each folder, each `essl.toml` read once per run. Clones share what was
/// read.
#[derive(Clone, Debug, Default)]
pub struct Configs {
    inner: Arc<Inner>,
}

#[derive(Debug, Default)]
struct Inner {
    overrides: Overrides,
    by_folder: Mutex<Folders>,
    explicit: Option<Found>,
}

/// The folders met so far, and the last one asked for: files come folder by folder, and a
/// byte comparison of the path is cheaper than hashing it component by component.
#[derive(Debug, Default)]
struct Folders {
    all: HashMap<PathBuf, Found>,
    last: Option<(PathBuf, Found)>,
}

type Found = Result<Arc<Settings>, Arc<ConfigError>>;

impl Configs {
    /// Settings found upward from each shader, with `overrides` on top.
    pub fn new(overrides: Overrides) -> Configs {
        let explicit = overrides.config.as_ref().map(|path| {
            Config::load(path)
                .map(|c| Arc::new(Settings::new(Arc::new(c), &overrides)))
                .map_err(Arc::new)
        });
        Configs {
            inner: Arc::new(Inner {
                overrides,
                by_folder: Mutex::default(),
                explicit,
            }),
        }
    }

    /// What the caller asked on top of essl.toml.
    pub fn overrides(&self) -> &Overrides {
        &self.inner.overrides
    }

    /// The settings of the file at `path`: from the nearest `essl.toml` in its folder or above
    /// (or the one `--config` names).
    pub fn for_file(&self, path: &Path) -> Result<Arc<Settings>, Arc<ConfigError>> {
        let folder = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        self.for_folder(folder)
    }

    /// The settings of the files in `folder`.
    pub fn for_folder(&self, folder: &Path) -> Result<Arc<Settings>, Arc<ConfigError>> {
        if let Some(explicit) = &self.inner.explicit {
            return explicit.clone();
        }
        let mut by_folder = self
            .inner
            .by_folder
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        if let Some((last, s)) = &by_folder.last {
            if last.as_os_str() == folder.as_os_str() {
                return s.clone();
            }
        }
        if let Some(s) = by_folder.all.get(folder).cloned() {
            by_folder.last = Some((folder.to_path_buf(), s.clone()));
            return s;
        }
        let found = Config::discover(folder)
            .map(|c| {
                let config = Arc::new(c.unwrap_or_default());
                Arc::new(Settings::new(config, &self.inner.overrides))
            })
            .map_err(Arc::new);
        by_folder.all.insert(folder.to_path_buf(), found.clone());
        by_folder.last = Some((folder.to_path_buf(), found.clone()));
        found
    }

    /// The `essl.toml` files used so far, sorted (a build script asks Cargo to watch them).
    pub fn used(&self) -> Vec<PathBuf> {
        let by_folder = self
            .inner
            .by_folder
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        let mut paths: Vec<PathBuf> = by_folder
            .all
            .values()
            .chain(self.inner.explicit.iter())
            .filter_map(|s| s.as_ref().ok()?.config.path.clone())
            .collect();
        paths.sort();
        paths.dedup();
        paths
    }

    /// Forgets every folder's settings (an `essl.toml` may have changed).
    pub fn forget(&self) {
        self.inner
            .by_folder
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .all
            .clear();
        self.inner
            .by_folder
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .last = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_config_per_folder_with_overrides_on_top() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        std::fs::create_dir_all(root.join("vendor")).unwrap();
        std::fs::write(
            root.join("essl.toml"),
            "target = \"webgl1\"\n[defines]\nA = \"1\"\n",
        )
        .unwrap();
        std::fs::write(root.join("vendor/essl.toml"), "[rules]\nall = \"allow\"\n").unwrap();
        let mut overrides = Overrides {
            defines: vec![("B".into(), "2".into())],
            ..Overrides::default()
        };
        overrides.rule("smoothstep-edges", Level::Deny).unwrap();
        assert!(overrides.rule("no-such-rule", Level::Deny).is_err());
        let configs = Configs::new(overrides);
        let top = configs.for_file(&root.join("a.frag")).unwrap();
        assert_eq!(top.compile.target, Target::WebGl1);
        assert_eq!(top.compile.defines.len(), 2);
        assert!(top.include.is_none());
        let vendor = configs.for_file(&root.join("vendor/b.frag")).unwrap();
        assert_eq!(vendor.compile.target, Target::WebGl2);
        let edges = essl_lint::rule("smoothstep-edges").unwrap();
        let pow = essl_lint::rule("pow-negative-base").unwrap();
        assert_eq!(vendor.rules.level(edges), Level::Deny);
        assert_eq!(vendor.rules.level(pow), Level::Allow);
        assert_eq!(configs.used().len(), 2);
    }
}
