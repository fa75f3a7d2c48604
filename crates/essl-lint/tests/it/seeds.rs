//! Snapshots of the lint findings for every shader of `shaders-glsl/` (the seeds' shaders, their
//! corrected twins and variants), and for `tests/articles/`: the article code of the twins and
//! variants before their numerical fixes, where the hazards the articles mention are reported.

use std::path::{Path, PathBuf};

use essl::diagnostic::{apply_fixes, Applicability};
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Shader, Stage};
use essl_lint::{lint, LintOptions};
use serde_json::{json, Value};

fn shaders(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| Stage::from_path(p).is_some())
        .collect();
    v.sort();
    v
}

fn compiled(path: &Path) -> Shader {
    let text = std::fs::read_to_string(path).expect("a readable shader");
    let name = path
        .file_name()
        .expect("a file name")
        .to_string_lossy()
        .to_string();
    compile(
        SourceFile::new(name, text),
        Stage::from_path(path).expect("a stage"),
        &CompileOptions::default(),
    )
}

/// The findings as the snapshots hold them.
fn findings(shader: &Shader) -> Value {
    let file = &shader.file;
    Value::Array(
        lint(shader, &LintOptions::default().notes(true))
            .iter()
            .map(|d| {
                let (s, e) = (file.line_col(d.span.start), file.line_col(d.span.end));
                json!({
                    "code": d.code,
                    "severity": d.severity.as_str(),
                    "message": d.message,
                    "line": s.line,
                    "column": s.column,
                    "end_line": e.line,
                    "end_column": e.column,
                    "label": d.label,
                    "help": d.help_text(file),
                })
            })
            .collect(),
    )
}

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

#[test]
fn shaders_glsl() {
    let files = shaders(&repo().join("shaders-glsl"));
    assert!(files.len() >= 36, "the seeds' shaders are there");
    for path in files {
        let shader = compiled(&path);
        let name = path
            .file_name()
            .expect("a file name")
            .to_string_lossy()
            .to_string();
        insta::assert_json_snapshot!(format!("shaders-glsl__{name}"), findings(&shader));
    }
}

#[test]
fn article_code_before_the_numerical_fixes() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/articles");
    for path in shaders(&dir) {
        let shader = compiled(&path);
        assert!(shader.ok(), "{} compiles", path.display());
        let name = path
            .file_name()
            .expect("a file name")
            .to_string_lossy()
            .to_string();
        insta::assert_json_snapshot!(format!("articles__{name}"), findings(&shader));
    }
}

/// The corrected twins and variants are clean; so is the article code once the suggested fixes
/// are applied, except for what has no mechanical fix.
#[test]
fn twins_are_clean_and_fixes_clean_the_article_code() {
    for path in shaders(&repo().join("shaders-glsl")) {
        let name = path
            .file_name()
            .expect("a file name")
            .to_string_lossy()
            .to_string();
        let twin = name.contains(".fixed.")
            || ["spot-step.frag", "spot-linear.frag", "spot-smoothstep.frag"]
                .contains(&name.as_str());
        if twin {
            let shader = compiled(&path);
            assert!(shader.ok(), "{name} compiles");
            assert_eq!(findings(&shader), json!([]), "{name} is clean");
        }
    }
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/articles");
    for path in shaders(&dir) {
        let shader = compiled(&path);
        let found = lint(&shader, &LintOptions::default().notes(true));
        assert!(!found.is_empty(), "{} has hazards", path.display());
        let (fixed, n) = apply_fixes(shader.file.text(), &found, Applicability::Suggested);
        assert_eq!(n, found.len());
        let again = compile(
            SourceFile::new("fixed", fixed.clone()),
            Stage::from_path(&path).expect("a stage"),
            &CompileOptions::default(),
        );
        assert!(
            again.ok(),
            "the fixed {} compiles:\n{fixed}",
            path.display()
        );
        assert_eq!(
            findings(&again),
            json!([]),
            "the fixed {} is clean:\n{fixed}",
            path.display()
        );
    }
}
