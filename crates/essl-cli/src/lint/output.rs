//! Printing `essl lint`'s results: human (codespan, optionally coloured), JSON Lines, or one
//! line per diagnostic (concise, GitHub annotations: [`super::lines`]).
//!
//! Each format is a pair of functions, one for a shader and one for a program, so that a new
//! format is one more pair and one more [`Format`] variant. SARIF needs every file at once, so
//! it is written by [`write`] from the kept diagnostics.

use std::io::Write;
use std::sync::Arc;

use codespan_reporting::term::termcolor::{Buffer, Color, ColorSpec, WriteColor};
use essl::diagnostic::Diagnostic;
use essl::render;
use essl::source::SourceFile;
use essl_check::{CheckedProgram, CheckedShader};
use serde_json::json;

use super::options::{Format, Look};
use super::results::{FileResult, LintResults, Totals};
use super::{json, lines};

fn plural(n: usize, word: &str) -> String {
    match (n, word) {
        (1, _) => format!("{n} {word}"),
        (_, "fix") => format!("{n} fixes"),
        _ => format!("{n} {word}s"),
    }
}

/// `N files, E errors, W warnings`, plus `, P programs linked` when any were,
/// `, U pairs not linked` when a pair was not linked because a shader has errors,
/// `, F fixes applied` when any were, `, K notes` when notes were shown and
/// `, H notes hidden (--show-notes)` when some were left out.
fn summary_line(t: &Totals) -> String {
    let mut s = format!(
        "{}, {}, {}",
        plural(t.files, "file"),
        plural(t.errors, "error"),
        plural(t.warnings, "warning")
    );
    if t.programs > 0 {
        s.push_str(&format!(", {} linked", plural(t.programs, "program")));
    }
    if t.unlinked > 0 {
        s.push_str(&format!(", {} not linked", plural(t.unlinked, "pair")));
    }
    if t.fixes > 0 {
        s.push_str(&format!(", {} applied", plural(t.fixes, "fix")));
    }
    if t.notes > 0 {
        s.push_str(&format!(", {}", plural(t.notes, "note")));
    }
    if t.notes_hidden > 0 {
        s.push_str(&format!(
            ", {} hidden (--show-notes)",
            plural(t.notes_hidden, "note")
        ));
    }
    if t.skipped > 0 {
        s.push_str(&format!(", {} skipped", plural(t.skipped, "shader")));
    }
    s
}

/// Writes what `--fix` changed as unified diffs (`--diff`), or, for standard input, the fixed
/// text itself.
pub(crate) fn write_fixed(
    out: &mut dyn Write,
    results: &LintResults,
    diff: bool,
) -> std::io::Result<()> {
    for f in results.files.iter().chain(&results.fixed_includes) {
        let Some((old, new)) = &f.fixed else { continue };
        let stdin = f.named.stdin;
        if diff {
            let name = f.named.path.display().to_string();
            let text = similar::TextDiff::from_lines(old.as_str(), new.as_str());
            write!(
                out,
                "{}",
                text.unified_diff()
                    .header(&format!("a/{name}"), &format!("b/{name}"))
            )?;
        } else if stdin {
            out.write_all(new.as_bytes())?;
        }
    }
    Ok(())
}

/// Writes every result in order (files sorted by path, then programs) and the summary (a line
/// of text, or a `{"kind":"summary"}` object). Files that could not be listed, read or written
/// are also reported on stderr.
pub(crate) fn write(out: &mut dyn Write, results: &LintResults, look: Look) -> std::io::Result<()> {
    for e in &results.collect_errors {
        eprintln!("error: {e}");
    }
    for s in &results.skipped {
        eprintln!("skipped {}: {}", s.at, s.reason());
    }
    for f in results.files.iter().chain(&results.fixed_includes) {
        if let Some(e) = &f.read_error {
            eprintln!("error: cannot read `{}`: {e}", f.named.path.display());
        }
        if let Some(e) = &f.write_error {
            eprintln!(
                "error: cannot write the fixed `{}`: {e}",
                f.named.path.display()
            );
        }
    }
    for f in results.files.iter().chain(&results.fixed_includes) {
        out.write_all(&f.rendered)?;
    }
    for p in &results.programs {
        out.write_all(&p.rendered)?;
    }
    let t = results.totals();
    match look.format {
        Format::Human | Format::Concise | Format::Github if look.quiet => {}
        Format::Github => {}
        Format::Human | Format::Concise => {
            let mut summary = buffer(look.color);
            summary.set_color(ColorSpec::new().set_bold(true))?;
            write!(summary, "{}", summary_line(&t))?;
            summary.reset()?;
            if results.denied_warnings() {
                write!(summary, " (warnings denied)")?;
            }
            writeln!(summary)?;
            out.write_all(summary.as_slice())?;
        }
        Format::Sarif => {
            writeln!(out, "{}", sarif(results))?;
        }
        Format::Json => {
            let summary = json!({
                "kind": "summary",
                "target": look.target.as_str(),
                "files": t.files,
                "errors": t.errors,
                "warnings": t.warnings,
                "programs": t.programs,
                "unlinked": t.unlinked,
                "fixes": t.fixes,
                "notes": t.notes,
                "notes_hidden": t.notes_hidden,
            });
            writeln!(out, "{summary}")?;
        }
    }
    Ok(())
}

fn buffer(color: bool) -> Buffer {
    if color {
        Buffer::ansi()
    } else {
        Buffer::no_color()
    }
}

/// A shader's output in `look.format`.
pub(crate) fn render_shader(r: &FileResult, s: &CheckedShader, look: Look) -> Vec<u8> {
    match look.format {
        Format::Human => human_shader(r, s, look),
        Format::Json => json::shader_line(r, s, look),
        Format::Sarif => Vec::new(),
        Format::Concise | Format::Github => s
            .all()
            .map(|(f, d)| lines::line(look.format, Some(f), "", d))
            .collect::<String>()
            .into_bytes(),
    }
}

/// The output for a file that could not be read (the error itself goes to stderr).
pub(crate) fn render_unread(r: &FileResult, look: Look) -> Vec<u8> {
    match look.format {
        Format::Json => json::unread_line(r, look),
        _ => Vec::new(),
    }
}

/// The output for an included file `--fix` changed.
pub(crate) fn render_fixed_include(r: &FileResult, look: Look) -> Vec<u8> {
    match look.format {
        Format::Human => {
            let mut buf = buffer(look.color);
            let _ = write_fixed_line(&mut buf, &r.named.label, r.fixes_applied);
            buf.into_inner()
        }
        Format::Json => json::fixed_line(r),
        _ => Vec::new(),
    }
}

/// A program's output in `look.format`.
pub(crate) fn render_program(
    p: &CheckedProgram,
    vs: &CheckedShader,
    fs: &CheckedShader,
    look: Look,
) -> Vec<u8> {
    match look.format {
        Format::Human => human_program(p, vs, fs, look),
        Format::Json => json::program_line(p, vs, fs, look),
        Format::Sarif => Vec::new(),
        Format::Concise | Format::Github => {
            let fallback = vs.path.display().to_string();
            p.diagnostics
                .iter()
                .map(|d| lines::line(look.format, d.file.as_deref(), &fallback, &d.diagnostic))
                .collect::<String>()
                .into_bytes()
        }
    }
}

/// The SARIF log of every file's diagnostics, link diagnostics included (added to the file
/// they point into; one that points into no file goes to the vertex shader's).
fn sarif(results: &LintResults) -> String {
    type Files = Vec<(Arc<SourceFile>, Vec<Diagnostic>)>;
    fn add(files: &mut Files, file: &Arc<SourceFile>, ds: &[Diagnostic]) {
        match files.iter_mut().find(|(f, _)| Arc::ptr_eq(f, file)) {
            Some((_, list)) => list.extend_from_slice(ds),
            None => files.push((file.clone(), ds.to_vec())),
        }
    }
    let mut files: Files = Vec::new();
    for f in &results.files {
        for g in &f.diagnostics {
            add(&mut files, &g.file, &g.diagnostics);
        }
    }
    for p in &results.programs {
        for d in &p.diagnostics {
            let file = d.file.clone().or_else(|| {
                let name = p.vertex.display().to_string();
                let found = files.iter().find(|(f, _)| f.name() == name);
                found.map(|(f, _)| f.clone())
            });
            if let Some(file) = file {
                add(&mut files, &file, std::slice::from_ref(&d.diagnostic));
            }
        }
    }
    let list: Vec<essl_lint::sarif::FileDiagnostics> = files
        .iter()
        .map(|(file, diagnostics)| essl_lint::sarif::FileDiagnostics { file, diagnostics })
        .collect();
    essl_lint::sarif::to_string(&list)
}

fn write_fixed_line(buf: &mut Buffer, label: &str, applied: usize) -> std::io::Result<()> {
    buf.set_color(ColorSpec::new().set_fg(Some(Color::Green)).set_bold(true))?;
    write!(buf, "fixed")?;
    buf.reset()?;
    writeln!(buf, " `{label}`: {} applied", plural(applied, "fix"))
}

/// A shader's human output: how many fixes were applied to its file, then its diagnostics.
fn human_shader(r: &FileResult, s: &CheckedShader, look: Look) -> Vec<u8> {
    let mut buf = buffer(look.color);
    let _ = (|| -> std::io::Result<()> {
        if look.fix && r.fixes_applied > 0 {
            let label = if r.named.embedded {
                r.named.path.display().to_string()
            } else {
                r.named.label.clone()
            };
            write_fixed_line(&mut buf, &label, r.fixes_applied)?;
        }
        let config = render::default_config();
        for g in &s.diagnostics {
            render::emit_human(&mut buf, &g.file, &g.diagnostics, &config)?;
        }
        Ok(())
    })();
    buf.into_inner()
}

fn program_name(vs: &CheckedShader, fs: &CheckedShader) -> String {
    format!("`{}` + `{}`", vs.label(), fs.label())
}

/// A program's human output: one line when it links cleanly or was not linked; otherwise its
/// diagnostics, each shown in the file it points into, and the info log when linking failed.
fn human_program(
    p: &CheckedProgram,
    vs: &CheckedShader,
    fs: &CheckedShader,
    look: Look,
) -> Vec<u8> {
    let mut buf = buffer(look.color);
    let _ = write_human_program(&mut buf, p, vs, fs, look.quiet);
    buf.into_inner()
}

fn write_human_program(
    buf: &mut Buffer,
    p: &CheckedProgram,
    vs: &CheckedShader,
    fs: &CheckedShader,
    quiet: bool,
) -> std::io::Result<()> {
    let name = program_name(vs, fs);
    let Some(program) = p.program.as_ref().filter(|_| p.linked) else {
        if quiet {
            return Ok(());
        }
        let broken = match (vs.ok(), fs.ok()) {
            (false, false) => "the vertex and fragment shaders have errors",
            (false, true) => "the vertex shader has errors",
            _ => "the fragment shader has errors",
        };
        writeln!(buf, "program {name}: not linked ({broken})")?;
        return Ok(());
    };
    if quiet && program.ok && p.diagnostics.is_empty() {
        return Ok(());
    }
    if program.ok {
        buf.set_color(ColorSpec::new().set_fg(Some(Color::Green)).set_bold(true))?;
        write!(buf, "linked")?;
        buf.reset()?;
        writeln!(
            buf,
            " {name}: {}, {}",
            plural(program.uniforms.len(), "active uniform"),
            plural(program.attributes.len(), "active attribute")
        )?;
    } else {
        buf.set_color(ColorSpec::new().set_fg(Some(Color::Red)).set_bold(true))?;
        write!(buf, "error")?;
        buf.set_color(ColorSpec::new().set_bold(true))?;
        write!(buf, ": program {name} does not link")?;
        buf.reset()?;
        writeln!(buf)?;
    }
    let config = render::default_config();
    for d in &p.diagnostics {
        let one = std::slice::from_ref(&d.diagnostic);
        match &d.file {
            Some(file) => render::emit_human(buf, file, one, &config)?,
            None => render::emit_human_unlocated(buf, one, &config)?,
        }
    }
    if !program.ok && !program.log.is_empty() {
        writeln!(buf, "info log (getProgramInfoLog):")?;
        for line in program.log.lines() {
            writeln!(buf, "    {line}")?;
        }
        writeln!(buf)?;
    }
    Ok(())
}
