//! Snapshots of `essl lint shaders-glsl/` (the seeds' shaders, verbatim and corrected) in the
//! machine formats: `--format github`, `concise`, `sarif` and `json`, one snapshot each.
//! Review changes with `cargo insta review`.

use std::path::Path;
use std::process::Command;

fn lint(format: &str) -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let out = Command::new(env!("CARGO_BIN_EXE_essl"))
        .args([
            "lint",
            "--color",
            "never",
            "--format",
            format,
            "shaders-glsl",
        ])
        .current_dir(root)
        .output()
        .expect("the essl binary runs");
    let status = out.status.code().unwrap();
    format!(
        "exit status {status}\n{}",
        String::from_utf8(out.stdout).unwrap()
    )
}

#[test]
fn github() {
    insta::assert_snapshot!(lint("github"));
}

#[test]
fn concise() {
    insta::assert_snapshot!(lint("concise"));
}

#[test]
fn sarif() {
    let text = lint("sarif");
    let (status, log) = text.split_once('\n').unwrap();
    let log: serde_json::Value = serde_json::from_str(log).unwrap();
    insta::assert_json_snapshot!(serde_json::json!({"status": status, "log": log}));
}

#[test]
fn json() {
    let text = lint("json");
    let (status, lines) = text.split_once('\n').unwrap();
    let lines: Vec<serde_json::Value> = lines
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    insta::assert_json_snapshot!(serde_json::json!({"status": status, "lines": lines}));
}
