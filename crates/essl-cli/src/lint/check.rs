//! Checking: read, (fix,) compile and lint each shader, link the pairs, on a thread pool; each
//! result is rendered on the thread that compiled it, so that only its bytes cross threads.
//! The shaders of one host file (an HTML page, a script) are one unit of work: their fixes go
//! back into the one file, and their diagnostics are moved onto its lines ([`super::relocate`]).

use std::sync::Arc;

use essl::link::{link, Program};
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Shader, Stage};
use rayon::prelude::*;

use super::fix;
use super::include;
use super::options::{Format, LintOptions, Look};
use super::output;
use super::relocate::relocate;
use super::results::{program_counts, Checked, FileResult, Linked, LintResults, ProgramResult};
use crate::discover::{Host, Input, Source};
use crate::files;

/// Adds the numerical-hazard lints to a compiled shader's diagnostics (notes only under
/// `--show-notes`); returns how many notes were left out.
fn add_lints(shader: &mut Shader, options: &LintOptions) -> usize {
    let rules = options.rules.clone().notes(true);
    let (notes, rest): (Vec<_>, Vec<_>) = essl_lint::lint(shader, &rules)
        .into_iter()
        .partition(|d| d.severity == essl::diagnostic::Severity::Note);
    let hidden = if options.show_notes { 0 } else { notes.len() };
    let mut found = rest;
    if options.show_notes {
        found.extend(notes);
    }
    if !found.is_empty() {
        shader.diagnostics.extend(found);
        essl::diagnostic::sort(&mut shader.diagnostics);
    }
    hidden
}

/// (Fixes, when `fix`,) compiles and lints one shader's text; nothing is written.
fn check_text(name: &str, text: String, stage: Stage, options: &LintOptions, fix: bool) -> Checked {
    let compile_options = CompileOptions {
        defines: options.defines.clone(),
        ..CompileOptions::for_target(options.target)
    };
    let mut checked = if fix {
        let original = text.clone();
        let fixed = fix::fix_text(name, text, stage, &compile_options, options.unsafe_fixes);
        let changed = fixed.applied > 0 && fixed.text != original;
        Checked {
            shader: fixed.shader,
            fixes_applied: fixed.applied,
            fixed: changed.then_some((original, fixed.text)),
            write_error: None,
            notes_hidden: 0,
            included: Vec::new(),
        }
    } else {
        Checked {
            shader: compile(SourceFile::new(name, text), stage, &compile_options),
            fixes_applied: 0,
            fixed: None,
            write_error: None,
            notes_hidden: 0,
            included: Vec::new(),
        }
    };
    checked.notes_hidden = add_lints(&mut checked.shader, options);
    checked
}

/// Compiles and lints a shader with its `#include`s put in place (`-I`), each diagnostic moved
/// onto the file it points into. `--fix` leaves such a shader alone.
fn check_expanded(input: &Input, text: String, options: &LintOptions) -> Result<Checked, String> {
    let name = input.path.display().to_string();
    let expanded = include::expand(
        SourceFile::new(name.as_str(), text),
        &input.path,
        &options.include_dirs,
    )?;
    let mut checked = check_text(&name, expanded.text.clone(), input.stage, options, false);
    let (mine, theirs) = expanded.split(std::mem::take(&mut checked.shader.diagnostics));
    checked.shader.diagnostics = mine;
    checked.shader.file = expanded.files[0].clone();
    checked.included = theirs;
    Ok(checked)
}

/// Reads, (fixes,) compiles and lints a shader file or standard input, and writes a fix back
/// to the file (not under `--diff`; standard input's fixed text is printed instead).
fn check_file(input: &Input, options: &LintOptions) -> Result<Checked, String> {
    let text = match &input.source {
        Source::Text(t) => t.to_string(),
        _ => files::read_source(&input.path).map_err(|e| e.to_string())?,
    };
    if !options.include_dirs.is_empty() && include::has_include(&text) {
        return check_expanded(input, text, options);
    }
    let name = input.path.display().to_string();
    let mut checked = check_text(&name, text, input.stage, options, options.fix);
    if let (Some((_, new)), Source::File, false) = (&checked.fixed, &input.source, options.diff) {
        checked.write_error = fix::write_atomically(&input.path, new)
            .err()
            .map(|e| files::io_message(&e));
    }
    Ok(checked)
}

/// A checked shader's result, rendered with `look`.
fn file_result(input: &Input, checked: &Result<Checked, String>, look: Look) -> FileResult {
    let rendered = output::render_file(input, checked, look);
    let mut result = FileResult::new(input.clone(), rendered);
    match checked {
        Err(e) => result.read_error = Some(e.clone()),
        Ok(c) => {
            let included = c.included.iter().flat_map(|(_, ds)| ds);
            let count = |s: essl::diagnostic::Severity| {
                included.clone().filter(|d| d.severity == s).count()
            };
            result.write_error = c.write_error.clone();
            result.errors = c.shader.error_count() + count(essl::diagnostic::Severity::Error);
            result.warnings = c.shader.warning_count() + count(essl::diagnostic::Severity::Warning);
            result.notes = c.shader.note_count() + count(essl::diagnostic::Severity::Note);
            result.notes_hidden = c.notes_hidden;
            result.fixes_applied = c.fixes_applied;
            result.codes = c
                .shader
                .diagnostics
                .iter()
                .map(|d| (d.code, d.severity))
                .collect();
            result.fixed = c.fixed.clone();
            result
                .codes
                .extend(included.clone().map(|d| (d.code, d.severity)));
            if look.format == Format::Sarif {
                result.diagnostics = Some((c.shader.file.clone(), c.shader.diagnostics.clone()));
                result.included = c.included.clone();
            }
        }
    }
    result
}

/// A linked pair's result, rendered with `look`.
fn program_result(linked: &Linked, look: Look) -> ProgramResult {
    let (errors, warnings) = program_counts(linked.vs, linked.fs, linked.program);
    let diagnostics = if look.format == Format::Sarif {
        linked
            .program
            .diagnostics
            .iter()
            .map(|d| {
                let path = match d.stage {
                    Some(Stage::Vertex) => Some(linked.vertex.path.clone()),
                    Some(Stage::Fragment) => Some(linked.fragment.path.clone()),
                    None => None,
                };
                (path, d.diagnostic.clone())
            })
            .collect()
    } else {
        Vec::new()
    };
    ProgramResult {
        vertex: linked.vertex.clone(),
        linked: linked.vs.ok() && linked.fs.ok(),
        errors,
        warnings,
        codes: linked
            .program
            .diagnostics
            .iter()
            .map(|d| (d.diagnostic.code, d.diagnostic.severity))
            .collect(),
        rendered: output::render_program(linked, look),
        diagnostics,
    }
}

/// What a unit of work gives: its files' results and its programs' (each with the index that
/// sorts it).
type UnitResult = (Vec<(usize, FileResult)>, Vec<(usize, ProgramResult)>);

/// A unit of work.
enum Unit {
    /// One shader file (or standard input).
    Single(usize),
    /// A `NAME.vert` + `NAME.frag` pair, compiled and linked on one thread.
    Pair(usize, usize),
    /// The shaders of one host file (input indices) and the pairs it makes plain.
    Host(Vec<usize>, Vec<(usize, usize)>),
}

/// The units of work: the pairs to link (unless `link` is off), every unpaired file, and one
/// unit per host file.
fn units(inputs: &[Input], link: bool) -> Vec<Unit> {
    let plain: Vec<usize> = (0..inputs.len())
        .filter(|&i| matches!(inputs[i].source, Source::File))
        .collect();
    let shader_files: Vec<essl_build::files::ShaderFile> = plain
        .iter()
        .map(|&i| essl_build::files::ShaderFile {
            path: inputs[i].path.clone(),
            stage: inputs[i].stage,
        })
        .collect();
    let pairs = if link {
        files::pairs(&shader_files)
    } else {
        Vec::new()
    };
    let mut paired = vec![false; inputs.len()];
    let mut units: Vec<Unit> = Vec::with_capacity(inputs.len());
    for &(v, f) in &pairs {
        let (v, f) = (plain[v], plain[f]);
        paired[v] = true;
        paired[f] = true;
        units.push(Unit::Pair(v, f));
    }
    let mut hosts: Vec<(*const Host, Vec<usize>)> = Vec::new();
    for (i, input) in inputs.iter().enumerate() {
        match &input.source {
            Source::Embedded(host, _) => {
                match hosts.iter_mut().find(|(h, _)| *h == Arc::as_ptr(host)) {
                    Some((_, members)) => members.push(i),
                    None => hosts.push((Arc::as_ptr(host), vec![i])),
                }
            }
            _ if !paired[i] => units.push(Unit::Single(i)),
            _ => {}
        }
    }
    for (_, members) in hosts {
        let Source::Embedded(host, _) = &inputs[members[0]].source else {
            continue;
        };
        let index_of = |e: usize| {
            members
                .iter()
                .copied()
                .find(|&m| matches!(&inputs[m].source, Source::Embedded(_, k) if *k == e))
        };
        let pairs = if link {
            host.pairs
                .iter()
                .filter_map(|&(v, f)| Some((index_of(v)?, index_of(f)?)))
                .collect()
        } else {
            Vec::new()
        };
        units.push(Unit::Host(members, pairs));
    }
    units
}

/// Links a pair and renders the program's result.
fn link_pair(
    inputs: &[Input],
    v: usize,
    f: usize,
    vs: &Shader,
    fs: &Shader,
    look: Look,
) -> ProgramResult {
    let program = link(vs, fs);
    link_result(inputs, v, f, vs, fs, &program, look)
}

fn link_result(
    inputs: &[Input],
    v: usize,
    f: usize,
    vs: &Shader,
    fs: &Shader,
    program: &Program,
    look: Look,
) -> ProgramResult {
    let linked = Linked {
        vertex: &inputs[v],
        fragment: &inputs[f],
        vs,
        fs,
        program,
    };
    program_result(&linked, look)
}

/// Checks one unit of work and renders its results.
fn check_unit(
    unit: &Unit,
    inputs: &[Input],
    options: &LintOptions,
    look: Look,
    progress: &(dyn Fn() + Sync),
) -> UnitResult {
    match unit {
        &Unit::Single(i) => {
            let checked = check_file(&inputs[i], options);
            progress();
            (
                vec![(i, file_result(&inputs[i], &checked, look))],
                Vec::new(),
            )
        }
        &Unit::Pair(v, f) => {
            let vs = check_file(&inputs[v], options);
            progress();
            let fs = check_file(&inputs[f], options);
            progress();
            // A pair whose includes have errors is not linked: its shaders are incomplete.
            let program = match (&vs, &fs) {
                (Ok(a), Ok(b)) if a.included_ok() && b.included_ok() => {
                    vec![(v, link_pair(inputs, v, f, &a.shader, &b.shader, look))]
                }
                _ => Vec::new(),
            };
            let files = vec![
                (v, file_result(&inputs[v], &vs, look)),
                (f, file_result(&inputs[f], &fs, look)),
            ];
            (files, program)
        }
        Unit::Host(members, pairs) => check_host(members, pairs, inputs, options, look, progress),
    }
}

/// Checks the shaders of one host file: each is compiled from its own text, the pairs are
/// linked, and then every diagnostic is moved onto the host's lines (of the fixed host text,
/// under `--fix`, which is written back once).
fn check_host(
    members: &[usize],
    pairs: &[(usize, usize)],
    inputs: &[Input],
    options: &LintOptions,
    look: Look,
    progress: &(dyn Fn() + Sync),
) -> UnitResult {
    let Source::Embedded(host, _) = &inputs[members[0]].source else {
        return (Vec::new(), Vec::new());
    };
    let range = |m: usize| match &inputs[m].source {
        Source::Embedded(h, k) => h.embedded[*k].range.clone(),
        _ => 0..0,
    };
    let name = host.path.display().to_string();
    let mut checked: Vec<Checked> = members
        .iter()
        .map(|&m| {
            let text = host.text[range(m)].to_string();
            let c = check_text(&name, text, inputs[m].stage, options, options.fix);
            progress();
            c
        })
        .collect();
    let at = |m: usize| members.iter().position(|&x| x == m).unwrap_or(0);
    let mut programs: Vec<(usize, usize, Program)> = pairs
        .iter()
        .map(|&(v, f)| (v, f, link(&checked[at(v)].shader, &checked[at(f)].shader)))
        .collect();
    // The host's text after the fixes, and where each shader now starts in it.
    let mut text = String::with_capacity(host.text.len());
    let mut starts = Vec::with_capacity(members.len());
    let mut pos = 0;
    for (k, &m) in members.iter().enumerate() {
        let r = range(m);
        text.push_str(&host.text[pos..r.start]);
        starts.push(text.len() as u32);
        match &checked[k].fixed {
            Some((_, new)) => text.push_str(new),
            None => text.push_str(&host.text[r.clone()]),
        }
        pos = r.end;
    }
    text.push_str(&host.text[pos..]);
    let file = SourceFile::new(name, text.as_str());
    for (k, c) in checked.iter_mut().enumerate() {
        relocate(&mut c.shader.diagnostics, starts[k]);
        c.shader.file = file.clone();
    }
    for (v, f, program) in &mut programs {
        for d in &mut program.diagnostics {
            let shift = match d.stage {
                Some(Stage::Fragment) => starts[at(*f)],
                _ => starts[at(*v)],
            };
            relocate(std::slice::from_mut(&mut d.diagnostic), shift);
        }
    }
    let changed = text != host.text;
    for c in checked.iter_mut() {
        c.fixed = None;
    }
    if changed {
        checked[0].fixed = Some((host.text.clone(), text.clone()));
        if !host.stdin && !options.diff {
            checked[0].write_error = fix::write_atomically(&host.path, &text)
                .err()
                .map(|e| files::io_message(&e));
        }
    }
    let program_results = programs
        .iter()
        .map(|(v, f, p)| {
            let (vs, fs) = (&checked[at(*v)].shader, &checked[at(*f)].shader);
            (*v, link_result(inputs, *v, *f, vs, fs, p, look))
        })
        .collect();
    let files = members
        .iter()
        .zip(checked)
        .map(|(&m, c)| (m, file_result(&inputs[m], &Ok(c), look)))
        .collect();
    (files, program_results)
}

/// Checks the shaders in parallel, links the pairs (unless `options.link` is off) and renders
/// every result with `look`; `progress` is called once per shader checked (from any thread).
/// Results come back in the order of `inputs`.
pub(crate) fn check(
    inputs: &[Input],
    options: &LintOptions,
    look: Look,
    progress: &(dyn Fn() + Sync),
) -> LintResults {
    let units = units(inputs, options.link);
    let done: Vec<UnitResult> = units
        .par_iter()
        .map(|unit| check_unit(unit, inputs, options, look, progress))
        .collect();
    // Each result goes to its input's slot: no sort moving 10,000 results around.
    let mut files: Vec<Option<FileResult>> =
        std::iter::repeat_with(|| None).take(inputs.len()).collect();
    let mut programs: Vec<Option<ProgramResult>> =
        std::iter::repeat_with(|| None).take(inputs.len()).collect();
    for (f, p) in done {
        for (i, r) in f {
            files[i] = Some(r);
        }
        for (i, r) in p {
            programs[i] = Some(r);
        }
    }
    LintResults {
        files: files.into_iter().flatten().collect(),
        programs: programs.into_iter().flatten().collect(),
        ..LintResults::default()
    }
}
