//! One fixture per diagnostic code: `tests/codes/CODE.frag` or `CODE.vert` is a small shader
//! that produces the code `CODE`, and `CODE.vert` + `CODE.frag` together a program whose link
//! produces it. Each fixture's diagnostics of that code are snapshot as essl renders them
//! (rustc-style, without colour), under a header that lists every diagnostic the fixture
//! produced, so that a change of message, span, label, note or help shows in review.
//!
//! Every fixture is compiled with one macro defined through the API, [`OPTION_DEFINE`], as a
//! program that passes `CompileOptions::defines` does: the fixture of
//! `option-macro-redefined` redefines it. Fixtures are compiled for WebGL 2, or for a WebGL 1
//! context (which enabled every WebGL 1 extension) when their text says `essl-target: webgl1`
//! (in a comment).
//!
//! The tests check that every [`Code`] has a fixture (but those in [`UNREACHABLE`]), that each
//! fixture produces its code, and that every code named in `src` is a [`Code`].

use std::fmt::Write as _;
use std::panic::{self, AssertUnwindSafe};
use std::path::{Path, PathBuf};

use essl::diagnostic::Diagnostic;
use essl::diagnostic_code::Code;
use essl::source::SourceFile;
use essl::{compile, render, CompileOptions, Shader, Stage};

/// Codes that no shader text produces, each with the reason.
const UNREACHABLE: &[(Code, &str)] = &[
    (
        Code::InternalError,
        "reports a naga module that naga rejects, which is a bug in essl: a shader that \
         produces it is fixed, not kept as a fixture",
    ),
    (
        Code::Unsupported,
        "reports valid GLSL the lowering cannot express; every construct WebGL accepts is \
         lowered, so a shader that produces it is a gap to close, not a fixture",
    ),
];

/// The macro every fixture is compiled with, as a program defines it through
/// `CompileOptions::defines`.
const OPTION_DEFINE: (&str, &str) = ("FROM_OPTIONS", "1.0");

/// The folder of the fixtures.
fn fixture_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/codes")
}

/// What one fixture produced.
struct Outcome {
    /// Every diagnostic, in order: vertex shader, fragment shader, link.
    diagnostics: Vec<(Option<Stage>, Diagnostic)>,
    /// The snapshot text.
    text: String,
}

/// Compiles the fixture of `code` (and links it when it is a program); `None` when it has no
/// fixture.
fn run(code: Code) -> Option<Outcome> {
    let name = code.as_str();
    let load = |stage: Stage, ext: &str| {
        let path = fixture_dir().join(format!("{name}.{ext}"));
        let text = std::fs::read_to_string(&path).ok()?;
        let target = if text.contains("essl-target: webgl1") {
            essl::Target::WebGl1
        } else {
            essl::Target::WebGl2
        };
        let options = CompileOptions {
            defines: vec![(OPTION_DEFINE.0.into(), OPTION_DEFINE.1.into())],
            target,
            ..CompileOptions::default()
        };
        let file = SourceFile::new(format!("codes/{name}.{ext}"), text);
        Some(compile(file, stage, &options))
    };
    let vs = load(Stage::Vertex, "vert");
    let fs = load(Stage::Fragment, "frag");
    if vs.is_none() && fs.is_none() {
        return None;
    }
    let mut diagnostics = Vec::new();
    for s in [&vs, &fs].into_iter().flatten() {
        diagnostics.extend(s.diagnostics.iter().map(|d| (Some(s.stage), d.clone())));
    }
    if let (Some(vs), Some(fs)) = (&vs, &fs) {
        if vs.ok() && fs.ok() {
            let program = essl::link::link(vs, fs);
            diagnostics.extend(
                program
                    .diagnostics
                    .into_iter()
                    .map(|d| (d.stage, d.diagnostic)),
            );
        }
    }
    let text = render_outcome(code, &diagnostics, vs.as_ref(), fs.as_ref());
    Some(Outcome { diagnostics, text })
}

/// A header line per kind of diagnostic produced (severity, code, count), then the
/// diagnostics of `code` rendered.
fn render_outcome(
    code: Code,
    diagnostics: &[(Option<Stage>, Diagnostic)],
    vs: Option<&Shader>,
    fs: Option<&Shader>,
) -> String {
    let mut out = String::from("produces:\n");
    let mut counted: Vec<(String, usize)> = Vec::new();
    for (_, d) in diagnostics {
        let key = format!("{} {}", d.severity.as_str(), d.code);
        match counted.iter_mut().find(|(k, _)| *k == key) {
            Some((_, n)) => *n += 1,
            None => counted.push((key, 1)),
        }
    }
    for (key, n) in counted {
        let times = if n > 1 {
            format!(" ×{n}")
        } else {
            String::new()
        };
        let _ = writeln!(out, "  {key}{times}");
    }
    out.push('\n');
    for (stage, d) in diagnostics.iter().filter(|(_, d)| d.code == code.as_str()) {
        let shader = match stage {
            Some(Stage::Vertex) => vs,
            Some(Stage::Fragment) => fs,
            None => None,
        };
        match shader {
            Some(s) => out.push_str(&render::human_string(&s.file, std::slice::from_ref(d))),
            None => {
                let mut buf = codespan_reporting::term::termcolor::NoColor::new(Vec::new());
                render::emit_human_unlocated(
                    &mut buf,
                    std::slice::from_ref(d),
                    &render::default_config(),
                )
                .expect("writing to memory cannot fail");
                out.push_str(&String::from_utf8_lossy(&buf.into_inner()));
            }
        }
    }
    out
}

/// The codes that should have a fixture.
fn reachable() -> impl Iterator<Item = Code> {
    Code::ALL
        .iter()
        .copied()
        .filter(|c| !UNREACHABLE.iter().any(|(u, _)| u == c))
}

#[test]
fn every_code_has_a_fixture_that_produces_it() {
    let mut failures = Vec::new();
    for code in reachable() {
        let Some(outcome) = run(code) else {
            failures.push(format!(
                "{code}: no fixture tests/codes/{code}.frag or .vert"
            ));
            continue;
        };
        if !outcome
            .diagnostics
            .iter()
            .any(|(_, d)| d.code == code.as_str())
        {
            let got: Vec<&str> = outcome.diagnostics.iter().map(|(_, d)| d.code).collect();
            failures.push(format!("{code}: its fixture produces {got:?} instead"));
        }
        for (_, d) in &outcome.diagnostics {
            if Code::from_name(d.code).is_none() {
                failures.push(format!(
                    "{code}: its fixture produces `{}`, not a Code",
                    d.code
                ));
            }
        }
    }
    for (code, _) in UNREACHABLE {
        if run(*code).is_some() {
            failures.push(format!("{code}: listed as unreachable but has a fixture"));
        }
    }
    for entry in std::fs::read_dir(fixture_dir()).expect("tests/codes exists") {
        let path = entry.expect("a directory entry").path();
        let stem = path
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or_default();
        if Code::from_name(stem).is_none() {
            failures.push(format!("{}: not named for a code", path.display()));
        }
    }
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}

#[test]
fn rendered_diagnostics_of_each_code() {
    let mut failures = Vec::new();
    for code in reachable() {
        let Some(outcome) = run(code) else { continue };
        let result = panic::catch_unwind(AssertUnwindSafe(|| {
            insta::assert_snapshot!(code.as_str(), outcome.text);
        }));
        if result.is_err() {
            failures.push(code.as_str());
        }
    }
    assert!(
        failures.is_empty(),
        "snapshots differ for: {}",
        failures.join(", ")
    );
}

// ----- every code in the source is a `Code` -----

/// Literals in `src` that the scan takes for codes but that are not.
const NOT_CODES: &[&str] = &[
    // `check`'s stand-in for a diagnostic past `MAX_DIAGNOSTICS`, completed and dropped,
    // never shown.
    "dropped",
];

/// The string literals of Rust source outside comments, raw strings and the `#[cfg(test)]`
/// module at its end, each with the code before it (without comments, white space trimmed).
fn string_literals(src: &str) -> Vec<(String, String)> {
    let src = src.split("\n#[cfg(test)]").next().unwrap_or_default();
    let mut out = Vec::new();
    let mut code = String::new();
    let mut i = 0;
    while i < src.len() {
        let rest = &src[i..];
        if rest.starts_with("//") {
            i += rest.find('\n').unwrap_or(rest.len());
        } else if rest.starts_with("/*") {
            i += rest.find("*/").map_or(rest.len(), |e| e + 2);
        } else if rest.starts_with("r#\"") || rest.starts_with("r\"") {
            let hashes = rest[1..].find('"').unwrap_or(0);
            let close = format!("\"{}", "#".repeat(hashes));
            let body = 2 + hashes;
            i += body
                + rest[body..]
                    .find(&close)
                    .map_or(rest.len(), |e| e + close.len());
            code.push_str("\"\"");
        } else if rest.starts_with("'\"'") || rest.starts_with("'\\\"'") {
            // `'"'` and `'\"'` are characters, not the start of a string.
            i += rest[1..].find('\'').map_or(rest.len(), |e| e + 2);
        } else if let Some(body) = rest.strip_prefix('"') {
            let bytes = body.as_bytes();
            let mut j = 0;
            while j < bytes.len() && bytes[j] != b'"' {
                j += if bytes[j] == b'\\' { 2 } else { 1 };
            }
            let j = j.min(bytes.len());
            out.push((body[..j].to_string(), code.trim_end().to_string()));
            code.push_str("\"\"");
            i += j + 2;
        } else {
            let c = rest.chars().next().expect("not at the end");
            code.push(c);
            i += c.len_utf8();
        }
    }
    out
}

/// Whether `s` looks like a code: two or more lower-case words joined by `-`.
fn looks_like_a_code(s: &str) -> bool {
    s.contains('-')
        && !s.ends_with('-')
        && !s.contains("--")
        && s.starts_with(|c: char| c.is_ascii_lowercase())
        && s.chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')
}

/// Every `.rs` file under `dir`.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("readable") {
        let path = entry.expect("a directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// A code in the source is a string literal that is kebab-case (`type-mismatch`), or that is
/// the first argument of a call of `error` or `warning` (`recursion`); each must be a
/// [`Code`], so that a new code cannot be added without its variant and its documentation.
#[test]
fn every_code_in_the_source_is_a_code() {
    let mut files = Vec::new();
    rust_files(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("src"),
        &mut files,
    );
    files.sort();
    let mut unknown = Vec::new();
    let mut found = 0;
    for path in &files {
        let src = std::fs::read_to_string(path).expect("readable");
        for (lit, before) in string_literals(&src) {
            let called = (before.ends_with("error(") || before.ends_with("warning("))
                && !before.ends_with("#[error(")
                && lit.chars().all(|c| c.is_ascii_lowercase() || c == '-');
            let kebab = looks_like_a_code(&lit) && !before.ends_with("expect(");
            if !(called || kebab) || NOT_CODES.contains(&lit.as_str()) {
                continue;
            }
            found += 1;
            if Code::from_name(&lit).is_none() {
                unknown.push(format!("{}: \"{lit}\"", path.display()));
            }
        }
    }
    assert!(found > 100, "the scan found only {found} codes");
    assert!(
        unknown.is_empty(),
        "string literals that look like diagnostic codes but are not a `Code` (add a variant \
         to essl::diagnostic_code, or the literal to NOT_CODES if it is no code):\n{}",
        unknown.join("\n")
    );
}

#[test]
fn the_scan_sees_codes_and_skips_comments_raw_strings_and_tests() {
    let src = "let d = Diagnostic::error(\n    \"recursion\", m, s); // \"not-this\"\n\
               let x = r#\"raw-one\"#; let (w, c) = (\"Types\", \"block-type-mismatch\");\n\
               #[cfg(test)]\nmod tests { \"in-tests\" }";
    let lits = string_literals(src);
    let names: Vec<&str> = lits.iter().map(|l| l.0.as_str()).collect();
    assert_eq!(names, ["recursion", "Types", "block-type-mismatch"]);
    assert!(lits[0].1.ends_with("error("));
}
