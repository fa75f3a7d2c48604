//! The build-script check on copies of the seeds' spot light: it passes on the corrected
//! shaders, and an error planted in a copy fails it with the right `file:line:col` on Cargo's
//! warning line; `essl.toml` settings apply; the bindings text is snapshotted.

use std::path::{Path, PathBuf};

use essl_build::{Check, CheckError, Report};

fn seeds() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shaders-glsl")
}

/// A folder holding the corrected spot light as `spot.vert` + `spot.frag`, with `edit` applied
/// to the fragment shader's text.
fn project(edit: impl Fn(String) -> String) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let shaders = dir.path().join("shaders");
    std::fs::create_dir(&shaders).unwrap();
    std::fs::copy(
        seeds().join("spot-smooth-nbsp.fixed.vert"),
        shaders.join("spot.vert"),
    )
    .unwrap();
    let frag = std::fs::read_to_string(seeds().join("spot-smooth-nbsp.fixed.frag")).unwrap();
    std::fs::write(shaders.join("spot.frag"), edit(frag)).unwrap();
    dir
}

/// Runs a check of `dir/shaders`, returning the result and Cargo's lines.
fn run(check: Check) -> (Result<Report, CheckError>, Vec<String>, String) {
    let (mut cargo, mut human) = (Vec::new(), Vec::new());
    let result = check.run_with(&mut cargo, &mut human);
    let lines = String::from_utf8(cargo)
        .unwrap()
        .lines()
        .map(str::to_owned)
        .collect();
    (result, lines, String::from_utf8(human).unwrap())
}

/// 1-based line and column of the first occurrence of `needle`.
fn position(text: &str, needle: &str) -> (usize, usize) {
    let at = text.find(needle).expect("the planted text");
    let line = text[..at].matches('\n').count() + 1;
    let column = at - text[..at].rfind('\n').map_or(0, |i| i + 1) + 1;
    (line, column)
}

#[test]
fn the_corrected_shaders_pass_and_cargo_watches_the_folder() {
    let dir = project(|t| t);
    let shaders = dir.path().join("shaders");
    let (result, lines, human) = run(Check::new(&shaders));
    let report = result.unwrap();
    assert_eq!((report.files, report.warnings), (2, 0));
    assert_eq!(report.programs.len(), 1);
    assert_eq!(report.programs[0].name, "spot");
    assert_eq!(
        lines,
        [format!("cargo:rerun-if-changed={}", shaders.display())]
    );
    assert_eq!(human, "");
}

#[test]
fn a_planted_error_fails_with_its_position() {
    let planted = "vec3 broken = normalise(v_normal);";
    let dir = project(|t| t.replacen("void main() {", &format!("void main() {{\n  {planted}"), 1));
    let shaders = dir.path().join("shaders");
    let text = std::fs::read_to_string(shaders.join("spot.frag")).unwrap();
    let (line, column) = position(&text, "normalise");
    let (result, lines, human) = run(Check::new(&shaders));
    let e = result.unwrap_err();
    assert!(
        matches!(
            e,
            CheckError::Failed {
                errors: 1,
                files: 2,
                programs: 0,
                ..
            }
        ),
        "{e}"
    );
    assert!(
        e.to_string()
            .starts_with("essl: 1 error in the shaders under"),
        "{e}"
    );
    let expected = format!(
        "cargo:warning={}:{line}:{column}: error[undeclared-function]: ",
        shaders.join("spot.frag").display()
    );
    assert!(
        lines.iter().any(|l| l.starts_with(&expected)),
        "no `{expected}` in {lines:#?}"
    );
    assert!(
        human.contains(&format!("spot.frag:{line}:{column}")),
        "{human}"
    );
    // `fn main() -> Result<(), Box<dyn Error>>` prints the Debug form: the same sentence.
    assert_eq!(format!("{e:?}"), e.to_string());
}

#[test]
fn a_link_error_points_into_the_fragment_shader() {
    let dir = project(|t| t.replacen("in vec3 v_normal;", "flat in vec3 v_normal;", 1));
    let shaders = dir.path().join("shaders");
    let text = std::fs::read_to_string(shaders.join("spot.frag")).unwrap();
    let (line, _) = position(&text, "flat in vec3 v_normal;");
    let (result, lines, _) = run(Check::new(&shaders).lints(false));
    assert!(
        matches!(result, Err(CheckError::Failed { errors: 1, .. })),
        "{lines:?}"
    );
    let prefix = format!(
        "cargo:warning={}:{line}:",
        shaders.join("spot.frag").display()
    );
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with(&prefix) && l.contains("error[varying-interpolation-mismatch]")),
        "{lines:#?}"
    );
}

#[test]
fn essl_toml_denies_warnings_and_excludes() {
    // The verbatim smoothstep has a lint warning (smoothstep-edges): fine by default.
    let dir = project(|t| {
        t.replacen(
            "smoothstep(u_outerLimit, max(u_innerLimit, u_outerLimit + 1e-4), dotFromDirection)",
            "smoothstep(u_outerLimit, u_innerLimit, dotFromDirection)",
            1,
        )
    });
    let shaders = dir.path().join("shaders");
    let (result, lines, _) = run(Check::new(&shaders));
    assert_eq!(result.unwrap().warnings, 1, "{lines:#?}");
    assert!(lines
        .iter()
        .any(|l| l.contains(": warning[smoothstep-edges]: ")));

    let config = dir.path().join("essl.toml");
    std::fs::write(&config, "[rules]\nwarnings = \"deny\"\n").unwrap();
    let (result, lines, _) = run(Check::new(&shaders));
    assert!(matches!(result, Err(CheckError::Failed { errors: 1, .. })));
    assert!(lines
        .iter()
        .any(|l| l.contains(": error (denied warning)[smoothstep-edges]: ")));
    let watched = format!(
        "cargo:rerun-if-changed={}",
        std::fs::canonicalize(&config).unwrap().display()
    );
    assert!(lines.contains(&watched), "{lines:#?}");

    std::fs::write(
        &config,
        "[rules]\nsmoothstep-edges = \"allow\"\nwarnings = \"deny\"\n",
    )
    .unwrap();
    assert_eq!(run(Check::new(&shaders)).0.unwrap().warnings, 0);

    std::fs::write(&config, "exclude = [\"spot.frag\"]\n").unwrap();
    let report = run(Check::new(&shaders)).0.unwrap();
    assert_eq!((report.files, report.programs.len()), (1, 0));

    std::fs::write(&config, "[rules]\nsmoothstep = \"deny\"\n").unwrap();
    let e = run(Check::new(&shaders)).0.unwrap_err();
    assert!(matches!(e, CheckError::Config(_)));
    assert!(
        e.to_string().contains("unknown lint rule `smoothstep`"),
        "{e}"
    );
}

#[test]
fn a_missing_folder_or_an_empty_one() {
    let dir = tempfile::tempdir().unwrap();
    let e = run(Check::new(dir.path().join("nope"))).0.unwrap_err();
    assert!(e.to_string().ends_with("no such file or directory"), "{e}");
    let (result, lines, _) = run(Check::new(dir.path()));
    assert_eq!(result.unwrap().files, 0);
    assert!(
        lines[1].starts_with("cargo:warning=essl: no shader under"),
        "{lines:?}"
    );
}

/// The generated text, reviewed for readability: every kind of uniform.
#[test]
fn bindings_text() {
    let shaders = Path::new("../../examples/shader-tests/shaders");
    let (result, _, _) = run(Check::new(shaders));
    let report = result.unwrap();
    let text = essl_build::bindings::generate_with(
        &report.programs,
        essl_build::bindings::Sources::Inline,
    );
    insta::assert_snapshot!(text);
}
