//! Printing `essl lint`'s results: human (codespan, optionally coloured), JSON Lines, or one
//! line per diagnostic (concise, GitHub annotations: [`super::lines`]).
//!
//! Each format is a pair of functions, one for a shader and one for a program, so that a new
//! format is one more pair and one more [`Format`] variant. SARIF needs every file at once, so
//! it is written by [`write`] from the kept diagnostics.

use std::io::Write;

use codespan_reporting::term::termcolor::{Buffer, Color, ColorSpec, WriteColor};
use essl::diagnostic::Diagnostic;
use essl::link::LinkDiagnostic;
use essl::render;
use essl::source::SourceFile;
use essl::{Shader, Stage};
use serde_json::json;

use super::options::{Format, Look};
use super::results::{Checked, Linked, LintResults, Totals};
use super::{json, lines};
use crate::discover::{Input, Source};

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
    for f in &results.files {
        let Some((old, new)) = &f.fixed else { continue };
        let stdin = match &f.input.source {
            Source::Text(_) => true,
            Source::Embedded(host, _) => host.stdin,
            Source::File => false,
        };
        if diff {
            let name = f.input.path.display().to_string();
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
        eprintln!("skipped {}: {}", s.at, s.reason);
    }
    for f in &results.files {
        if let Some(e) = &f.read_error {
            eprintln!("error: cannot read `{}`: {e}", f.input.path.display());
        }
        if let Some(e) = &f.write_error {
            eprintln!(
                "error: cannot write the fixed `{}`: {e}",
                f.input.path.display()
            );
        }
    }
    for f in &results.files {
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
            if look.deny_warnings && t.warnings > 0 {
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

/// A file's output in `look.format`.
pub(crate) fn render_file(input: &Input, checked: &Result<Checked, String>, look: Look) -> Vec<u8> {
    match look.format {
        Format::Human => human_file(input, checked, look),
        Format::Json => json::shader_line(input, checked, look),
        Format::Sarif => Vec::new(),
        Format::Concise | Format::Github => match checked {
            Ok(c) => std::iter::once((&c.shader.file, &c.shader.diagnostics))
                .chain(c.included.iter().map(|(f, ds)| (f, ds)))
                .flat_map(|(f, ds)| {
                    ds.iter()
                        .map(move |d| lines::line(look.format, Some(f), "", d))
                })
                .collect::<String>()
                .into_bytes(),
            Err(_) => Vec::new(),
        },
    }
}

/// A program's output in `look.format`.
pub(crate) fn render_program(linked: &Linked, look: Look) -> Vec<u8> {
    match look.format {
        Format::Human => human_program(linked, look),
        Format::Json => json::program_line(linked, look),
        Format::Sarif => Vec::new(),
        Format::Concise | Format::Github => {
            let fallback = linked.vertex.path.display().to_string();
            linked
                .program
                .diagnostics
                .iter()
                .map(|d| {
                    let file = file_of(linked.vs, linked.fs, d);
                    lines::line(look.format, file, &fallback, &d.diagnostic)
                })
                .collect::<String>()
                .into_bytes()
        }
    }
}

/// The SARIF log of every file's diagnostics, link diagnostics included (added to the file
/// they point into; one that points into no file goes to the vertex shader's).
fn sarif(results: &LintResults) -> String {
    let mut files: Vec<(SourceFile, Vec<Diagnostic>)> = results
        .files
        .iter()
        .flat_map(|f| f.diagnostics.clone().into_iter().chain(f.included.clone()))
        .collect();
    for p in &results.programs {
        for (path, d) in &p.diagnostics {
            let path = path.clone().unwrap_or_else(|| p.vertex.path.clone());
            let name = path.display().to_string();
            if let Some((_, ds)) = files.iter_mut().find(|(f, _)| f.name() == name) {
                ds.push(d.clone());
            }
        }
    }
    let list: Vec<essl_lint::sarif::FileDiagnostics> = files
        .iter()
        .map(|(file, diagnostics)| essl_lint::sarif::FileDiagnostics { file, diagnostics })
        .collect();
    essl_lint::sarif::to_string(&list)
}

/// A file's human output: how many fixes were applied, then its diagnostics.
fn human_file(input: &Input, checked: &Result<Checked, String>, look: Look) -> Vec<u8> {
    let mut buf = buffer(look.color);
    if let Ok(c) = checked {
        let _ = write_human_file(&mut buf, input, c, look.fix);
    }
    buf.into_inner()
}

fn write_human_file(
    buf: &mut Buffer,
    input: &Input,
    c: &Checked,
    fix: bool,
) -> std::io::Result<()> {
    if fix && c.fixes_applied > 0 {
        buf.set_color(ColorSpec::new().set_fg(Some(Color::Green)).set_bold(true))?;
        write!(buf, "fixed")?;
        buf.reset()?;
        writeln!(
            buf,
            " `{}`: {} applied",
            input.label(),
            plural(c.fixes_applied, "fix")
        )?;
    }
    let config = render::default_config();
    render::emit_human(buf, &c.shader.file, &c.shader.diagnostics, &config)?;
    for (file, diagnostics) in &c.included {
        render::emit_human(buf, file, diagnostics, &config)?;
    }
    Ok(())
}

fn program_name(vertex: &Input, fragment: &Input) -> String {
    format!("`{}` + `{}`", vertex.label(), fragment.label())
}

/// A program's human output: one line when it links cleanly or was not linked; otherwise its
/// diagnostics, each shown in the shader it points into, and the info log when linking failed.
fn human_program(linked: &Linked, look: Look) -> Vec<u8> {
    let mut buf = buffer(look.color);
    let _ = write_human_program(&mut buf, linked, look.quiet);
    buf.into_inner()
}

fn write_human_program(buf: &mut Buffer, linked: &Linked, quiet: bool) -> std::io::Result<()> {
    let Linked {
        vertex,
        fragment,
        vs,
        fs,
        program,
    } = *linked;
    let name = program_name(vertex, fragment);
    if quiet && (program.ok || !vs.ok() || !fs.ok()) && program.diagnostics.is_empty() {
        return Ok(());
    }
    if !vs.ok() || !fs.ok() {
        let broken = match (vs.ok(), fs.ok()) {
            (false, false) => "the vertex and fragment shaders have errors",
            (false, true) => "the vertex shader has errors",
            _ => "the fragment shader has errors",
        };
        writeln!(buf, "program {name}: not linked ({broken})")?;
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
    for d in &program.diagnostics {
        let one = std::slice::from_ref(&d.diagnostic);
        match file_of(vs, fs, d) {
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

/// The file a link diagnostic points into, if any.
pub(super) fn file_of<'a>(
    vs: &'a Shader,
    fs: &'a Shader,
    d: &LinkDiagnostic,
) -> Option<&'a SourceFile> {
    match d.stage? {
        Stage::Vertex => Some(&vs.file),
        Stage::Fragment => Some(&fs.file),
    }
}
