//! Snapshots of `essl lint`'s human (`--color never`) and JSON output for every shader in
//! `shaders-glsl/`, one snapshot per file and format. Review changes with `cargo insta review`.

use std::path::Path;
use std::process::Command;

fn lint(file: &Path, format: &str) -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let relative = format!(
        "shaders-glsl/{}",
        file.file_name().unwrap().to_str().unwrap()
    );
    let out = Command::new(env!("CARGO_BIN_EXE_essl"))
        .args(["lint", "--color", "never", "--format", format, &relative])
        .current_dir(root)
        .output()
        .expect("the essl binary runs");
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let status = out.status.code().unwrap();
    format!(
        "exit status {status}\n{}",
        String::from_utf8(out.stdout).unwrap()
    )
}

#[test]
fn human() {
    insta::glob!("../../../../shaders-glsl", "*.{vert,frag}", |path| {
        insta::assert_snapshot!(lint(path, "human"));
    });
}

#[test]
fn json() {
    insta::glob!("../../../../shaders-glsl", "*.{vert,frag}", |path| {
        let text = lint(path, "json");
        let (status, lines) = text.split_once('\n').unwrap();
        let values: Vec<serde_json::Value> = lines
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        insta::assert_json_snapshot!(serde_json::json!({"status": status, "lines": values}));
    });
}
