//! The settings a run uses: the nearest `essl.toml` (found upward from the first path, as
//! ruff finds `ruff.toml`, or named by `--config`) with the command line's flags on top; and
//! `essl config`, which prints them.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use essl_check::{Config, ConfigError};

/// Where to look for `essl.toml`: `explicit` (`--config FILE`), else upward from the folder
/// of the first path (standard input: the `--stdin-filename`'s folder, else the current one).
pub fn load(
    explicit: Option<&Path>,
    paths: &[PathBuf],
    stdin_name: Option<&Path>,
) -> Result<Config, ConfigError> {
    if let Some(file) = explicit {
        return Config::load(file);
    }
    let first = paths.first().map(PathBuf::as_path);
    let start = match first {
        Some(p) if p.as_os_str() == "-" => stdin_name
            .and_then(Path::parent)
            .map(Path::to_path_buf)
            .unwrap_or_default(),
        Some(p) if p.is_dir() => p.to_path_buf(),
        Some(p) => p.parent().map(Path::to_path_buf).unwrap_or_default(),
        None => PathBuf::new(),
    };
    let start = if start.as_os_str().is_empty() {
        PathBuf::from(".")
    } else {
        start
    };
    Ok(Config::discover(&start)?.unwrap_or_default())
}

fn list(items: &[String]) -> String {
    let quoted: Vec<String> = items.iter().map(|s| format!("{s:?}")).collect();
    format!("[{}]", quoted.join(", "))
}

/// The effective settings as `essl.toml` would spell them, every lint rule's level included.
pub fn describe(config: &Config) -> String {
    let mut out = String::new();
    match &config.path {
        Some(p) => {
            let _ = writeln!(out, "# from {}", p.display());
        }
        None => out.push_str("# no essl.toml found: the defaults\n"),
    }
    let target = config.target.unwrap_or(essl::Target::WebGl2);
    let _ = writeln!(out, "target = {:?}", target.as_str());
    let _ = writeln!(out, "exclude = {}", list(&config.exclude_patterns));
    let include: Vec<String> = config
        .include_dirs()
        .iter()
        .map(|p| p.display().to_string())
        .collect();
    let _ = writeln!(out, "include = {}", list(&include));
    let variants = config.variants.unwrap_or(essl_lint::variants::DEFAULT);
    let _ = writeln!(out, "variants = {variants}");
    out.push_str("\n[defines]\n");
    for (name, value) in &config.defines {
        let _ = writeln!(out, "{name} = {value:?}");
    }
    out.push_str("\n[stages]\n");
    let _ = writeln!(out, "vertex = {}", list(&config.stage_patterns[0]));
    let _ = writeln!(out, "fragment = {}", list(&config.stage_patterns[1]));
    out.push_str("\n[rules]\n");
    let warnings = if config.deny_warnings { "deny" } else { "warn" };
    let _ = writeln!(out, "warnings = {warnings:?}");
    for rule in essl_lint::RULES {
        let _ = writeln!(out, "{} = {:?}", rule.id, config.rules.level(rule).as_str());
    }
    out
}

/// `essl config [PATH]`: prints the settings that apply under `path`; returns the exit status.
pub fn run(explicit: Option<&Path>, path: Option<&Path>) -> i32 {
    let paths: Vec<PathBuf> = path.map(Path::to_path_buf).into_iter().collect();
    match load(explicit, &paths, None) {
        Ok(config) => {
            print!("{}", describe(&config));
            0
        }
        Err(e) => {
            eprintln!("error: {e}");
            2
        }
    }
}
