//! The verbatim seed spot-light shader (article 000): exactly its two missing `;` — each at the
//! end of the line that lacks it, with the fix — plus its 25 no-break spaces, one diagnostic
//! per line (errors in code, warnings in comments), and nothing else; the certain fixes make
//! it compile.

use essl::diagnostic::{apply_fixes, Applicability};
use essl::source::SourceFile;
use essl::{compile, Stage};

const SEED: &str = include_str!("../../../../shaders-glsl/spot-smooth-nbsp.frag");

#[test]
fn seed_spot_light_reports_exactly_its_problems() {
    let sh = compile(
        SourceFile::new("spot-smooth-nbsp.frag", SEED),
        Stage::Fragment,
        &Default::default(),
    );
    let semis: Vec<(u32, u32)> = sh
        .diagnostics
        .iter()
        .filter(|d| d.code == "missing-semicolon")
        .map(|d| {
            let lc = sh.file.line_col(d.span.start);
            (lc.line, lc.column)
        })
        .collect();
    // `uniform float u_innerLimit` (line 19) and `... -u_lightDirection)` (line 39): the caret
    // sits right after the last character of the line.
    let end_of = |line: u32| {
        sh.file
            .line_text(line as usize - 1)
            .trim_end()
            .chars()
            .count() as u32
            + 1
    };
    assert_eq!(semis, [(19, end_of(19)), (39, end_of(39))]);
    for d in sh
        .diagnostics
        .iter()
        .filter(|d| d.code == "missing-semicolon")
    {
        let help = d.help_text(&sh.file).unwrap();
        assert!(
            help.ends_with(";`"),
            "the help shows the fixed line: {help}"
        );
    }
    let nbsp_lines: Vec<(u32, &str)> = sh
        .diagnostics
        .iter()
        .filter(|d| d.code == "no-break-space")
        .map(|d| (sh.file.line_col(d.span.start).line, d.severity.as_str()))
        .collect();
    let total_nbsp: usize = sh
        .diagnostics
        .iter()
        .filter(|d| d.code == "no-break-space")
        .map(|d| d.fix.as_ref().unwrap().edits.len())
        .sum();
    assert_eq!(total_nbsp, 25);
    assert_eq!(nbsp_lines.len(), 25, "one diagnostic per line");
    let warnings: Vec<u32> = nbsp_lines
        .iter()
        .filter(|(_, s)| *s == "warning")
        .map(|(l, _)| *l)
        .collect();
    assert_eq!(
        warnings,
        [3, 4, 22],
        "no-break spaces inside comments are warnings"
    );
    let others: Vec<&str> = sh
        .diagnostics
        .iter()
        .filter(|d| d.code != "no-break-space" && d.code != "missing-semicolon")
        .map(|d| d.code)
        .collect();
    assert!(others.is_empty(), "no cascade: {others:?}");
}

#[test]
fn certain_fixes_make_the_seed_compile() {
    let sh = compile(
        SourceFile::new("spot-smooth-nbsp.frag", SEED),
        Stage::Fragment,
        &Default::default(),
    );
    let (fixed, applied) = apply_fixes(SEED, &sh.diagnostics, Applicability::Certain);
    assert_eq!(applied, 27);
    assert!(!fixed.contains('\u{a0}'));
    let again = compile(
        SourceFile::new("fixed.frag", fixed),
        Stage::Fragment,
        &Default::default(),
    );
    assert!(again.diagnostics.is_empty(), "{:?}", again.diagnostics);
}
