//! Annotated shader cases, as rust-analyzer writes its tests: the expected diagnostics sit
//! under the line they point at (`//^^^ error code: message`). Shared by `rules.rs` and
//! `rules_es100.rs`; see `rules.rs` for the format.

use essl::diagnostic::Diagnostic;
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Stage};

/// Whether a line of a case is an annotation.
fn is_annotation(line: &str) -> bool {
    let t = line.trim_start();
    t.starts_with("//^") || t.starts_with("//|")
}

/// The annotation of `d`, whose span starts on `line` (without its line break), which starts
/// at byte `line_start` of the case.
fn annotation(line: &str, line_start: usize, d: &Diagnostic) -> String {
    let start = (d.span.start as usize - line_start).min(line.len());
    let end = (d.span.end as usize)
        .saturating_sub(line_start)
        .clamp(start, line.len());
    let col = line[..start].chars().count();
    let marks = if d.span.is_empty() {
        "|".to_string()
    } else {
        "^".repeat(line[start..end].chars().count().max(1))
    };
    let what = format!("{} {}: {}", d.severity.as_str(), d.code, d.message);
    match col.checked_sub(2) {
        Some(indent) => format!("{}//{marks} {what}", " ".repeat(indent)),
        None => format!("//{marks} {what} (at column {}: indent the line)", col + 1),
    }
}

/// The case's text with its annotations replaced by those of `diagnostics`.
pub fn annotate(src: &str, diagnostics: &[Diagnostic]) -> String {
    let mut out = String::new();
    let mut placed = vec![false; diagnostics.len()];
    let mut line_start = 0;
    for line in src.split_inclusive('\n') {
        let here = line_start;
        line_start += line.len();
        if is_annotation(line) {
            continue;
        }
        out.push_str(line);
        let last = line_start == src.len();
        for (d, placed) in diagnostics.iter().zip(&mut placed) {
            let at = d.span.start as usize;
            if (here..line_start).contains(&at) || (last && at == src.len()) {
                if !out.ends_with('\n') {
                    out.push('\n');
                }
                out.push_str(&annotation(line.trim_end_matches('\n'), here, d));
                out.push('\n');
                *placed = true;
            }
        }
    }
    for (d, placed) in diagnostics.iter().zip(placed) {
        if !placed {
            out.push_str(&format!("(outside the text) {} {}\n", d.code, d.message));
        }
    }
    out
}

/// Compiles a case for WebGL 2 and compares its diagnostics with its annotations.
#[track_caller]
pub fn check(stage: Stage, src: &str) {
    check_with(stage, src, &CompileOptions::default());
}

/// Compiles a case with `options` and compares its diagnostics with its annotations.
#[track_caller]
pub fn check_with(stage: Stage, src: &str, options: &CompileOptions) {
    let sh = compile(SourceFile::new("case", src), stage, options);
    let actual = annotate(src, &sh.diagnostics);
    assert!(
        actual == src,
        "the diagnostics differ from the annotations\n--- the case:\n{src}\n--- the case as it \
         would pass:\n{actual}--- end"
    );
}
