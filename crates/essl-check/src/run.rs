//! A whole run: every unit of what a search found, checked on a thread pool, each result handed
//! to the caller's sink on the thread that checked it (so that only what the caller keeps
//! crosses threads); then, under `--fix`, the fixes that fall in included files, applied once
//! per file and followed by a check again of the units that include them.

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};

use essl::diagnostic::{apply_fixes, Applicability, Diagnostic};
use rayon::prelude::*;

use crate::check::{self, check_unit, CheckOptions, Context, FixMode, Unit, MAX_FIX_ROUNDS};
use crate::find::{find_text, Found, Skipped, UsageError};
use crate::read::Files;
use crate::result::{CheckedProgram, CheckedShader, CheckedUnit, FixedFile};
use crate::settings::Configs;

/// What a run gives besides each unit's result.
#[derive(Debug)]
pub struct Run<R> {
    /// The units, in the order [`check::units`] lists them.
    pub units: Vec<Unit>,
    /// The sink's result for each unit.
    pub results: Vec<R>,
    /// Included files `--fix` changed (a unit's own files are in its [`CheckedUnit::fixed`]).
    pub fixed_includes: Vec<FixedFile>,
}

/// Fixes a unit proposes in files it includes: the file and the diagnostics with fixes, with
/// spans in it.
type Pending = Vec<(PathBuf, Vec<Diagnostic>)>;

/// What a unit includes and the fixes it proposes there.
fn included(unit: &CheckedUnit, fix: FixMode) -> (HashSet<PathBuf>, Pending) {
    let mut paths = HashSet::new();
    let mut pending: Pending = Vec::new();
    for s in &unit.shaders {
        for f in s.assembly.files().iter().skip(1) {
            paths.insert(PathBuf::from(f.name()));
        }
        if fix == FixMode::Off {
            continue;
        }
        for g in s.diagnostics.iter().skip(1) {
            let fixes: Vec<Diagnostic> = g
                .diagnostics
                .iter()
                .filter(|d| d.fix.is_some())
                .cloned()
                .collect();
            if !fixes.is_empty() {
                pending.push((PathBuf::from(g.file.name()), fixes));
            }
        }
    }
    (paths, pending)
}

/// Checks every unit of `found` and hands each result to `sink` (called on the thread that
/// checked the unit; under `--fix`, again for a unit checked again after its includes were
/// fixed). Included files fixed are given to `files`, so that what follows reads them fixed.
pub fn run<R: Send>(
    found: &Found,
    configs: &Configs,
    files: &mut Files,
    options: CheckOptions,
    sink: &(dyn Fn(Unit, CheckedUnit) -> R + Sync),
) -> Run<R> {
    let units = check::units(found, options.link);
    let prepared = crate::preset::prepare(found, configs);
    type Checked<R> = (R, HashSet<PathBuf>, Pending, Vec<(PathBuf, String)>);
    let checked = |files: &Files, list: &[usize]| -> Vec<Checked<R>> {
        let cx = Context {
            configs,
            files,
            options,
            prepared: &prepared,
        };
        list.par_iter()
            .map(|&i| {
                let unit = check_unit(units[i], found, &cx);
                let (paths, pending) = included(&unit, options.fix);
                let own_fixed = unit
                    .fixed
                    .iter()
                    .filter(|f| !f.stdin)
                    .map(|f| (f.path.clone(), f.after.clone()))
                    .collect();
                (sink(units[i], unit), paths, pending, own_fixed)
            })
            .collect()
    };
    let all: Vec<usize> = (0..units.len()).collect();
    let mut results = Vec::with_capacity(units.len());
    let mut includes = Vec::with_capacity(units.len());
    let mut pending = Vec::with_capacity(units.len());
    let mut own_fixed: Vec<(PathBuf, String)> = Vec::new();
    for (r, i, p, o) in checked(files, &all) {
        results.push(r);
        includes.push(i);
        pending.push(p);
        own_fixed.extend(o);
    }
    // A unit's own files are fixed by the unit: what other units propose there is left to
    // it, and the texts it wrote are what the units that include them read next.
    let real = |p: &Path| std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf());
    let own: HashSet<PathBuf> = found
        .inputs
        .iter()
        .map(|i| real(&i.path))
        .chain(found.hosts.iter().map(|h| real(&h.path)))
        .collect();
    let mut fixed: HashMap<PathBuf, FixedFile> = HashMap::new();
    for _ in 0..MAX_FIX_ROUNDS {
        let mut changed = HashSet::new();
        for (path, text) in std::mem::take(&mut own_fixed) {
            files.give(path.clone(), text);
            changed.insert(path);
        }
        for p in pending.iter_mut() {
            p.retain(|(path, _)| !own.contains(&real(path)));
        }
        changed.extend(fix_includes(files, &mut pending, options.fix, &mut fixed));
        if changed.is_empty() {
            break;
        }
        let again: Vec<usize> = (0..units.len())
            .filter(|&i| includes[i].iter().any(|p| changed.contains(p)))
            .collect();
        for (k, (r, inc, p, o)) in checked(files, &again).into_iter().enumerate() {
            results[again[k]] = r;
            includes[again[k]] = inc;
            pending[again[k]] = p;
            own_fixed.extend(o);
        }
    }
    let mut fixed_includes: Vec<FixedFile> = fixed.into_values().collect();
    fixed_includes.sort_by(|a, b| a.path.cmp(&b.path));
    Run {
        units,
        results,
        fixed_includes,
    }
}

/// Applies the fixes the units propose in included files, each file's once (the same fix
/// proposed by every shader that includes the file is one fix), and gives the new texts to
/// `files`. Returns the files changed.
fn fix_includes(
    files: &mut Files,
    pending: &mut [Pending],
    mode: FixMode,
    fixed: &mut HashMap<PathBuf, FixedFile>,
) -> HashSet<PathBuf> {
    let mut by_file: HashMap<PathBuf, Vec<Diagnostic>> = HashMap::new();
    for p in pending.iter_mut() {
        for (path, ds) in p.drain(..) {
            let list = by_file.entry(path).or_default();
            for d in ds {
                if !list.iter().any(|x| x.fix == d.fix) {
                    list.push(d);
                }
            }
        }
    }
    let mut changed = HashSet::new();
    let mut paths: Vec<PathBuf> = by_file.keys().cloned().collect();
    paths.sort();
    for path in paths {
        let Ok(file) = files.read(&path) else {
            continue;
        };
        let ds = &by_file[&path];
        let (mut text, mut n) = apply_fixes(file.text(), ds, Applicability::Certain);
        if n == 0 && mode == FixMode::Suggested {
            (text, n) = apply_fixes(file.text(), ds, Applicability::Suggested);
        }
        if n == 0 || text == file.text() {
            continue;
        }
        let entry = fixed.entry(path.clone()).or_insert_with(|| FixedFile {
            path: path.clone(),
            before: file.clone(),
            after: String::new(),
            applied: 0,
            stdin: false,
        });
        entry.applied += n;
        entry.after = text.clone();
        files.give(path.clone(), text);
        changed.insert(path);
    }
    changed
}

/// Checks one text, the file at `path`, as a run would check it among its folder's files: a
/// shader file (its stage from its name, settings or pragma) or a host file's shaders, and the
/// shaders a host holds that are not checked. What it includes is read through `files`.
pub fn check_text(
    path: &Path,
    text: String,
    configs: &Configs,
    files: &Files,
    options: CheckOptions,
) -> Result<(CheckedUnit, Vec<Skipped>), UsageError> {
    // Checked without its settings, the text would be checked as nothing.
    configs.for_file(path).map_err(UsageError::Config)?;
    let found = find_text(path, text, configs)?;
    let prepared = crate::preset::prepare_alone(&found, configs);
    let cx = Context {
        configs,
        files,
        options,
        prepared: &prepared,
    };
    let mut out = CheckedUnit::default();
    for unit in check::units(&found, options.link) {
        let u = check_unit(unit, &found, &cx);
        out.shaders.extend(u.shaders);
        out.programs.extend(u.programs);
        out.fixed.extend(u.fixed);
        out.unread.extend(u.unread);
    }
    Ok((out, found.skipped))
}

/// Lowers and lints a shader that a [`crate::Phase::FrontEnd`] check left, with the settings
/// it was checked with (without `lints`, nothing more is done: the check is complete).
pub fn finish(shader: &mut CheckedShader, lints: bool) {
    let settings = shader.settings.clone();
    check::lint(shader, &settings, lints);
}

/// Links two shaders checked apart (an editor's document and its partner file) as a run links
/// a pair: the program records them as shaders 0 and 1.
pub fn link(vertex: &CheckedShader, fragment: &CheckedShader) -> CheckedProgram {
    check::link_shaders(vertex, fragment, 0, 1)
}
