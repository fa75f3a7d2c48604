//! Checking, through the one pipeline ([`essl_check::run`]): each unit's result is turned into
//! rendered results on the thread that checked it, so that only their bytes cross threads, and
//! a unit's own fixed file is written back there (the output then says whether that worked).

use essl::diagnostic::Severity;
use essl_check::{CheckedProgram, CheckedShader, CheckedUnit, FileDiagnostics, FixedFile};

use super::options::{Format, LintOptions, Look};
use super::output;
use super::results::{FileResult, Named, ProgramResult};

/// What a unit gives the output.
pub(crate) type UnitResult = (Vec<FileResult>, Vec<ProgramResult>);

/// How a shader is named, from its check.
pub(crate) fn named(s: &CheckedShader, stdin: bool) -> Named {
    Named {
        path: s.path.clone(),
        stage: s.stage,
        label: s.label(),
        embedded: s.embedded_at.is_some(),
        stdin,
    }
}

/// Leaves the lints' notes out of `groups` unless `--show-notes` asks for them; how many were
/// left out.
fn hide_notes(groups: &mut [FileDiagnostics], show: bool) -> usize {
    if show {
        return 0;
    }
    let mut hidden = 0;
    for g in groups {
        let before = g.diagnostics.len();
        g.diagnostics.retain(|d| d.severity != Severity::Note);
        hidden += before - g.diagnostics.len();
    }
    hidden
}

/// Writes a unit's own fixed file back (not under `--diff`; standard input's fixed text is
/// printed instead); why it could not be, if it could not.
fn write_back(fixed: &FixedFile, options: &LintOptions) -> Option<String> {
    if fixed.stdin || options.diff {
        return None;
    }
    essl_check::write_atomically(&fixed.path, &fixed.after)
        .err()
        .map(|e| essl_check::io_message(&e))
}

/// One checked unit, rendered with `look`.
pub(crate) fn unit_result(mut unit: CheckedUnit, options: &LintOptions, look: Look) -> UnitResult {
    let write_errors: Vec<Option<String>> =
        unit.fixed.iter().map(|f| write_back(f, options)).collect();
    let mut files = Vec::new();
    for u in &unit.unread {
        let named = Named {
            path: u.path.clone(),
            stage: u.stage,
            label: u.path.display().to_string(),
            embedded: false,
            stdin: false,
        };
        let mut r = FileResult::new(u.order, named);
        r.read_error = Some(u.message.clone());
        r.rendered = output::render_unread(&r, look);
        files.push(r);
    }
    let mut fixes_told = vec![false; unit.fixed.len()];
    for s in &mut unit.shaders {
        let deny = s.settings.deny_warnings;
        let hidden = hide_notes(&mut s.diagnostics, options.show_notes);
        let mut r = FileResult::new(s.order, named(s, s.given));
        r.deny_warnings = deny;
        r.notes_hidden = hidden;
        r.errors = s.count(Severity::Error);
        r.warnings = s.count(Severity::Warning);
        r.notes = s.count(Severity::Note);
        r.codes = s.all().map(|(_, d)| (d.code, d.severity)).collect();
        if let Some(k) = unit.fixed.iter().position(|f| f.path == s.path) {
            if !fixes_told[k] {
                fixes_told[k] = true;
                let f = &unit.fixed[k];
                r.fixes_applied = f.applied;
                r.fixed = Some((f.before.text().to_string(), f.after.clone()));
                r.write_error = write_errors[k].clone();
            }
        }
        r.rendered = output::render_shader(&r, s, look);
        if look.format == Format::Sarif {
            r.diagnostics = s.diagnostics.clone();
        }
        files.push(r);
    }
    let programs = unit
        .programs
        .iter()
        .map(|p| program_result(p, &unit.shaders, look))
        .collect();
    (files, programs)
}

/// A linked pair's result, rendered with `look`.
fn program_result(p: &CheckedProgram, shaders: &[CheckedShader], look: Look) -> ProgramResult {
    let (vs, fs) = (&shaders[p.vertex], &shaders[p.fragment]);
    let (errors, warnings) = p.counts();
    ProgramResult {
        order: vs.order,
        vertex: vs.path.clone(),
        linked: p.linked,
        errors,
        warnings,
        deny_warnings: vs.settings.deny_warnings,
        codes: p
            .diagnostics
            .iter()
            .map(|d| (d.diagnostic.code, d.diagnostic.severity))
            .collect(),
        rendered: output::render_program(p, vs, fs, look),
        diagnostics: if look.format == Format::Sarif {
            p.diagnostics.clone()
        } else {
            Vec::new()
        },
    }
}

/// An included file `--fix` changed, as a result of its own (no diagnostics: those are shown
/// with the shaders that include it).
pub(crate) fn fixed_include(
    f: &FixedFile,
    order: usize,
    options: &LintOptions,
    look: Look,
) -> FileResult {
    let named = Named {
        path: f.path.clone(),
        stage: essl::Stage::Fragment,
        label: f.path.display().to_string(),
        embedded: false,
        stdin: false,
    };
    let mut r = FileResult::new(order, named);
    r.fixes_applied = f.applied;
    r.fixed = Some((f.before.text().to_string(), f.after.clone()));
    r.write_error = write_back(f, options);
    r.rendered = output::render_fixed_include(&r, look);
    r
}
