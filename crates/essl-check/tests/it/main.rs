//! The checking pipeline end to end, on folders written in a temporary directory: what it
//! finds, where its diagnostics land, what `--fix` changes, and what a host file costs.

mod find;
mod fix;
mod hosts;
mod includes;
mod presets;
mod three;

use std::path::Path;

use essl_check::{CheckOptions, CheckedUnit, Configs, Files, FindOptions, Overrides, Run};

/// Writes `files` (path, text) under `dir`.
pub fn write(dir: &Path, files: &[(&str, &str)]) {
    for (path, text) in files {
        let path = dir.join(path);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }
}

/// Checks `dir` as `essl lint DIR` would, keeping every unit.
pub fn check(dir: &Path, overrides: Overrides, options: CheckOptions) -> Run<CheckedUnit> {
    let configs = Configs::new(overrides);
    let found = essl_check::find(&[dir.to_path_buf()], &FindOptions::new(), &configs).unwrap();
    assert!(found.errors.is_empty(), "{:?}", found.errors);
    let keep = |_, unit: CheckedUnit| unit;
    essl_check::run(&found, &configs, &mut Files::disk(), options, &keep)
}

/// Every diagnostic of a run as `FILE:LINE:COL code`, file names relative to `dir`, sorted.
pub fn lines(dir: &Path, run: &Run<CheckedUnit>) -> Vec<String> {
    let name = |f: &str| {
        Path::new(f)
            .strip_prefix(dir)
            .map_or(f.to_string(), |p| p.display().to_string())
    };
    let mut out = Vec::new();
    for unit in &run.results {
        for s in &unit.shaders {
            for (file, d) in s.all() {
                let lc = file.line_col(d.span.start);
                out.push(format!(
                    "{}:{}:{} {}",
                    name(file.name()),
                    lc.line,
                    lc.column,
                    d.code
                ));
            }
        }
        for p in &unit.programs {
            for d in &p.diagnostics {
                let at = match &d.file {
                    Some(f) => {
                        let lc = f.line_col(d.diagnostic.span.start);
                        format!("{}:{}:{}", name(f.name()), lc.line, lc.column)
                    }
                    None => "-".to_string(),
                };
                out.push(format!("{at} {}", d.diagnostic.code));
            }
        }
    }
    out.sort();
    out
}
