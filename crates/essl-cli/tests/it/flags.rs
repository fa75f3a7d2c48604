//! `essl lint`'s flags for editors and CI: standard input, `--diff`, `--unsafe-fixes`,
//! `--statistics`, `--quiet`, `--exit-zero`, essl.toml (and `essl config`), and
//! `essl explain`.

use std::io::Write;
use std::path::Path;
use std::process::{Command, Output, Stdio};

fn essl_with_stdin(args: &[&str], dir: &Path, input: Option<&str>) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_essl"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the essl binary runs");
    let mut stdin = child.stdin.take().unwrap();
    stdin.write_all(input.unwrap_or("").as_bytes()).unwrap();
    drop(stdin);
    child.wait_with_output().unwrap()
}

fn essl(args: &[&str], dir: &Path) -> Output {
    essl_with_stdin(args, dir, None)
}

fn out(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

fn err(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).unwrap()
}

const BROKEN: &str = "#version 300 es\nprecision highp float;\nuniform float a\nout vec4 c;\nvoid main() {\n    c = vec4(a);\n}\n";

#[test]
fn standard_input_under_a_file_name() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "lint",
        "--format",
        "concise",
        "--stdin-filename",
        "src/a.frag",
        "-",
    ];
    let o = essl_with_stdin(&args, dir.path(), Some(BROKEN));
    assert_eq!(o.status.code(), Some(1), "{}", err(&o));
    assert!(
        out(&o).starts_with("src/a.frag:3:16: error[missing-semicolon]"),
        "{}",
        out(&o)
    );
    // `--fix` on standard input prints the fixed text; the report goes to stderr.
    let args = [
        "lint",
        "--fix",
        "--color",
        "never",
        "--stdin-filename",
        "a.frag",
        "-",
    ];
    let o = essl_with_stdin(&args, dir.path(), Some(BROKEN));
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert_eq!(
        out(&o),
        BROKEN.replace("uniform float a\n", "uniform float a;\n")
    );
    assert!(err(&o).contains("1 fix applied"), "{}", err(&o));
    // HTML on standard input: positions on the page's lines.
    let page = format!("<p>\n<script>\nconst fs = `{BROKEN}`;\n</script>\n");
    let args = [
        "lint",
        "--format",
        "concise",
        "--stdin-filename",
        "p.html",
        "-",
    ];
    let o = essl_with_stdin(&args, dir.path(), Some(&page));
    assert!(
        out(&o).starts_with("p.html:5:16: error[missing-semicolon]"),
        "{}",
        out(&o)
    );
    // Without a name or `--stage`, the stage cannot be told.
    let o = essl_with_stdin(&["lint", "-"], dir.path(), Some(BROKEN));
    assert_eq!(o.status.code(), Some(2));
    assert!(err(&o).contains("--stdin-filename"), "{}", err(&o));
}

#[test]
fn diff_shows_the_fix_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("a.frag"), BROKEN).unwrap();
    let o = essl(&["lint", "--fix", "--diff", "a.frag"], dir.path());
    assert_eq!(o.status.code(), Some(1), "{}", err(&o));
    assert_eq!(
        out(&o),
        "--- a/a.frag\n+++ b/a.frag\n@@ -1,6 +1,6 @@\n #version 300 es\n precision highp float;\n\
         -uniform float a\n+uniform float a;\n out vec4 c;\n void main() {\n     c = vec4(a);\n"
    );
    assert_eq!(
        std::fs::read_to_string(dir.path().join("a.frag")).unwrap(),
        BROKEN
    );
    let o = essl(&["lint", "--diff", "a.frag"], dir.path());
    assert_eq!(o.status.code(), Some(2), "--diff needs --fix");
}

#[test]
fn statistics_quiet_and_exit_zero() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("a.frag"), BROKEN).unwrap();
    std::fs::write(dir.path().join("b.frag"), BROKEN).unwrap();
    let o = essl(&["lint", "--statistics", "."], dir.path());
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(out(&o), "    2  missing-semicolon                error\n");
    let o = essl(&["lint", "--quiet", "--format", "concise", "."], dir.path());
    assert_eq!(out(&o).lines().count(), 2, "no summary: {}", out(&o));
    let o = essl(&["lint", "--exit-zero", "."], dir.path());
    assert_eq!(o.status.code(), Some(0));
    let o = essl(&["lint", "--exit-zero", "missing.frag"], dir.path());
    assert_eq!(o.status.code(), Some(2), "I/O errors still exit 2");
}

#[test]
fn unsafe_fixes_apply_suggestions_too() {
    let dir = tempfile::tempdir().unwrap();
    // `#pragma STDGL invariant(all)` in a fragment shader: removing it is only suggested.
    let text = "#version 300 es\n#pragma STDGL invariant(all)\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
    std::fs::write(dir.path().join("a.frag"), text).unwrap();
    let o = essl(&["lint", "--fix", "a.frag"], dir.path());
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(
        std::fs::read_to_string(dir.path().join("a.frag")).unwrap(),
        text
    );
    let o = essl(&["lint", "--fix", "--unsafe-fixes", "a.frag"], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}", out(&o));
    let fixed = std::fs::read_to_string(dir.path().join("a.frag")).unwrap();
    assert!(!fixed.contains("invariant"), "{fixed}");
}

#[test]
fn essl_toml_is_found_upward_and_shown_by_essl_config() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(dir.path().join("shaders/deep")).unwrap();
    std::fs::write(
        dir.path().join("essl.toml"),
        "[defines]\nBROKEN = \"1\"\n[rules]\nall = \"allow\"\n[stages]\nfragment = [\"*.fs.glsl\"]\n",
    )
    .unwrap();
    let text = "#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() {\n#ifdef BROKEN\n  c = vec4(1.0)\n#endif\n}\n";
    std::fs::write(dir.path().join("shaders/deep/a.fs.glsl"), text).unwrap();
    let o = essl(&["lint", "--format", "concise", "shaders"], dir.path());
    assert!(
        out(&o).contains("a.fs.glsl:6:16: error[missing-semicolon]"),
        "the define from essl.toml applies: {}{}",
        out(&o),
        err(&o)
    );
    let o = essl(&["config", "shaders/deep"], dir.path());
    assert_eq!(o.status.code(), Some(0));
    let shown = out(&o);
    assert!(shown.starts_with("# from "), "{shown}");
    assert!(shown.contains("\n[defines]\nBROKEN = \"1\"\n"), "{shown}");
    assert!(shown.contains("fragment = [\"*.fs.glsl\"]"), "{shown}");
    assert!(shown.contains("pow-negative-base = \"allow\""), "{shown}");
    assert!(shown.contains("\nvariants = 64\n"), "{shown}");
    std::fs::write(dir.path().join("essl.toml"), "targt = \"webgl2\"\n").unwrap();
    let o = essl(&["lint", "shaders"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(err(&o).contains("unknown field `targt`"), "{}", err(&o));
}

#[test]
fn variants_lint_the_code_a_flag_compiles_in() {
    let dir = tempfile::tempdir().unwrap();
    let text = "#version 300 es\nprecision highp float;\nuniform float u_near, u_far;\nout vec4 c;\n\
                void main() {\n  c = vec4(1.0);\n#ifdef LINEAR_DEPTH\n  c.x /= u_far - u_near;\n#endif\n}\n";
    std::fs::write(dir.path().join("a.frag"), text).unwrap();
    let o = essl(&["lint", "--format", "concise", "a.frag"], dir.path());
    assert!(
        out(&o).contains("a.frag:8:10: warning[division-by-difference]"),
        "{}",
        out(&o)
    );
    let o = essl(&["lint", "a.frag"], dir.path());
    assert!(
        out(&o).contains("note: in code compiled only with `LINEAR_DEPTH` defined"),
        "{}",
        out(&o)
    );
    let o = essl(&["lint", "--variants", "0", "a.frag"], dir.path());
    assert!(!out(&o).contains("warning["), "{}", out(&o));
    std::fs::write(dir.path().join("essl.toml"), "variants = 0\n").unwrap();
    let o = essl(&["lint", "a.frag"], dir.path());
    assert!(!out(&o).contains("warning["), "{}", out(&o));
    let o = essl(&["lint", "--variants", "1", "a.frag"], dir.path());
    assert!(out(&o).contains("warning["), "the flag wins: {}", out(&o));
}

#[test]
fn explain_prints_every_codes_page() {
    let dir = tempfile::tempdir().unwrap();
    let o = essl(&["explain", "missing-semicolon"], dir.path());
    assert_eq!(o.status.code(), Some(0));
    assert!(out(&o).starts_with("# missing-semicolon\n"), "{}", out(&o));
    let o = essl(&["explain", "pow-negative-base"], dir.path());
    assert!(out(&o).contains("Default level"), "{}", out(&o));
    let o = essl(&["explain"], dir.path());
    let listed = out(&o).lines().count();
    assert!(listed > 150, "{listed} codes listed");
    let o = essl(&["explain", "no-such-code"], dir.path());
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn includes_are_opt_in_and_report_into_the_included_file() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(dir.path().join("common")).unwrap();
    std::fs::write(
        dir.path().join("common/light.glsl"),
        "float light(float d) {\n    return d * 0.5\n}\n",
    )
    .unwrap();
    let main = "#version 300 es\nprecision highp float;\n#include \"light.glsl\"\nout vec4 c;\nvoid main() { c = vec4(light(1.0)); }\n";
    std::fs::write(dir.path().join("a.frag"), main).unwrap();
    // Without an include folder, `#include` is the error GLSL ES makes it.
    let o = essl(&["lint", "--format", "concise", "a.frag"], dir.path());
    assert!(
        out(&o).starts_with("a.frag:3:1: error[unknown-directive]"),
        "{}",
        out(&o)
    );
    // With one, the error inside the included file is reported at its own line.
    let o = essl(
        &["lint", "-I", "common", "--format", "concise", "a.frag"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(1), "{}{}", out(&o), err(&o));
    assert!(
        out(&o).starts_with("common/light.glsl:2:19: error[missing-semicolon]"),
        "{}",
        out(&o)
    );
    std::fs::write(
        dir.path().join("common/light.glsl"),
        "float light(float d) {\n    return d * 0.5;\n}\n",
    )
    .unwrap();
    let o = essl(&["lint", "-I", "common", "a.frag"], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}{}", out(&o), err(&o));
    // An include that cannot be found is an error at its directive.
    std::fs::write(
        dir.path().join("b.frag"),
        main.replace("light.glsl", "none.glsl"),
    )
    .unwrap();
    let o = essl(
        &["lint", "-I", "common", "--format", "concise", "b.frag"],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(
        out(&o).starts_with(
            "b.frag:3:1: error[include-not-found]: cannot find `none.glsl`: searched `.` (the \
             including file's folder), `common`"
        ),
        "{}",
        out(&o)
    );
}
