//! Checking: read, (fix,) compile and lint each file, link the pairs, on a thread pool; each
//! result is rendered on the thread that compiled it, so that only its bytes cross threads.

use essl::link::link;
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Shader, Stage};
use rayon::prelude::*;

use super::fix;
use super::options::{Format, LintOptions, Look};
use super::output;
use super::results::{program_counts, Checked, FileResult, Linked, LintResults, ProgramResult};
use crate::files::{self, Input, ReadError};

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

/// Reads, (fixes,) compiles and lints one file.
fn check_file(input: &Input, options: &LintOptions) -> Result<Checked, ReadError> {
    let compile_options = CompileOptions {
        defines: options.defines.clone(),
        ..CompileOptions::for_target(options.target)
    };
    let name = input.path.display().to_string();
    let mut checked = files::read_source(&input.path).map(|text| {
        if options.fix {
            let fixed = fix::fix_text(&name, text, input.stage, &compile_options);
            let write_error = if fixed.applied > 0 {
                fix::write_atomically(&input.path, &fixed.text)
                    .err()
                    .map(|e| files::io_message(&e))
            } else {
                None
            };
            Checked {
                shader: fixed.shader,
                fixes_applied: fixed.applied,
                write_error,
                notes_hidden: 0,
            }
        } else {
            let shader = compile(SourceFile::new(name, text), input.stage, &compile_options);
            Checked {
                shader,
                fixes_applied: 0,
                write_error: None,
                notes_hidden: 0,
            }
        }
    })?;
    checked.notes_hidden = add_lints(&mut checked.shader, options);
    Ok(checked)
}

/// A checked file's result, rendered with `look`.
fn file_result(input: &Input, checked: &Result<Checked, ReadError>, look: Look) -> FileResult {
    let rendered = output::render_file(input, checked, look);
    match checked {
        Err(e) => FileResult {
            input: input.clone(),
            read_error: Some(e.to_string()),
            write_error: None,
            errors: 0,
            warnings: 0,
            notes: 0,
            notes_hidden: 0,
            fixes_applied: 0,
            rendered,
            diagnostics: None,
        },
        Ok(c) => FileResult {
            input: input.clone(),
            read_error: None,
            write_error: c.write_error.clone(),
            errors: c.shader.error_count(),
            warnings: c.shader.warning_count(),
            notes: c.shader.note_count(),
            notes_hidden: c.notes_hidden,
            fixes_applied: c.fixes_applied,
            rendered,
            diagnostics: (look.format == Format::Sarif)
                .then(|| (c.shader.file.clone(), c.shader.diagnostics.clone())),
        },
    }
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
        rendered: output::render_program(linked, look),
        diagnostics,
    }
}

/// What a unit of work gives: its files' results and, for a pair, the program's (each with
/// the index that sorts it).
type UnitResult = (Vec<(usize, FileResult)>, Option<(usize, ProgramResult)>);

/// A unit of work: one file, or a pair to compile and link on one thread.
enum Unit {
    Single(usize),
    Pair(usize, usize),
}

/// The units of work: the pairs to link (unless `link` is off), then every unpaired file.
fn units(inputs: &[Input], link: bool) -> Vec<Unit> {
    let pairs = if link {
        files::pairs(inputs)
    } else {
        Vec::new()
    };
    let mut paired = vec![false; inputs.len()];
    let mut units: Vec<Unit> = Vec::with_capacity(inputs.len());
    for &(v, f) in &pairs {
        paired[v] = true;
        paired[f] = true;
        units.push(Unit::Pair(v, f));
    }
    units.extend((0..inputs.len()).filter(|&i| !paired[i]).map(Unit::Single));
    units
}

/// Checks one unit of work and renders its results.
fn check_unit(
    unit: &Unit,
    inputs: &[Input],
    options: &LintOptions,
    look: Look,
    progress: &(dyn Fn() + Sync),
) -> UnitResult {
    match *unit {
        Unit::Single(i) => {
            let checked = check_file(&inputs[i], options);
            progress();
            (vec![(i, file_result(&inputs[i], &checked, look))], None)
        }
        Unit::Pair(v, f) => {
            let vs = check_file(&inputs[v], options);
            progress();
            let fs = check_file(&inputs[f], options);
            progress();
            let program = match (&vs, &fs) {
                (Ok(a), Ok(b)) => {
                    let program = link(&a.shader, &b.shader);
                    let linked = Linked {
                        vertex: &inputs[v],
                        fragment: &inputs[f],
                        vs: &a.shader,
                        fs: &b.shader,
                        program: &program,
                    };
                    Some((v, program_result(&linked, look)))
                }
                _ => None,
            };
            (
                vec![
                    (v, file_result(&inputs[v], &vs, look)),
                    (f, file_result(&inputs[f], &fs, look)),
                ],
                program,
            )
        }
    }
}

/// Checks the shaders in parallel, links the pairs (unless `options.link` is off) and renders
/// every result with `look`; `progress` is called once per file checked (from any thread).
/// Results come back sorted by path.
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
    let mut files: Vec<(usize, FileResult)> = Vec::with_capacity(inputs.len());
    let mut programs: Vec<(usize, ProgramResult)> = Vec::new();
    for (f, p) in done {
        files.extend(f);
        programs.extend(p);
    }
    files.sort_by_key(|(i, _)| *i);
    programs.sort_by_key(|(i, _)| *i);
    LintResults {
        collect_errors: Vec::new(),
        files: files.into_iter().map(|(_, f)| f).collect(),
        programs: programs.into_iter().map(|(_, p)| p).collect(),
    }
}
