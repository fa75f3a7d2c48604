//! Shaders on which essl and glslangValidator disagreed in differential runs
//! (`scripts/differential/`, `docs/differential.md`), minimised, with Chromium's WebGL2 answer
//! on the second line (`// Chromium: compiles` or `// Chromium: rejects`). Each must agree with
//! Chromium, except the ones listed in `KNOWN_DIFFERENCES`, which must still differ (so that
//! fixing one fails this test until it is taken off the list).

use std::path::Path;

use essl::source::SourceFile;
use essl::{compile, Stage};

/// Where essl still answers differently from Chromium.
const KNOWN_DIFFERENCES: &[&str] = &[];

#[test]
fn minimised_differential_cases_agree_with_chromium() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/differential/essl-wrong");
    let mut entries: Vec<_> = std::fs::read_dir(&dir)
        .expect("tests/differential/essl-wrong is in the repository")
        .map(|e| e.expect("a folder entry").path())
        .collect();
    entries.sort();
    let (mut wrong, mut fixed, mut seen) = (Vec::new(), Vec::new(), 0);
    for path in entries {
        let Some(stage) = Stage::from_path(&path) else {
            continue;
        };
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let text = std::fs::read_to_string(&path).unwrap();
        let verdict = text.lines().nth(1).unwrap_or_default();
        let chromium_compiles = if verdict.starts_with("// Chromium: compiles") {
            true
        } else if verdict.starts_with("// Chromium: rejects") {
            false
        } else {
            panic!("{name}: line 2 must say `// Chromium: compiles` or `// Chromium: rejects`");
        };
        seen += 1;
        let shader = compile(
            SourceFile::new(name.as_str(), text.as_str()),
            stage,
            &Default::default(),
        );
        let agrees = shader.ok() == chromium_compiles;
        let known = KNOWN_DIFFERENCES.contains(&name.as_str());
        if !agrees && !known {
            let first = shader
                .diagnostics
                .first()
                .map(|d| format!("{}: {}", d.code, d.message));
            wrong.push(format!(
                "{name}: Chromium compiles = {chromium_compiles}, essl: {first:?}"
            ));
        }
        if agrees && known {
            fixed.push(name);
        }
    }
    assert!(seen >= KNOWN_DIFFERENCES.len());
    assert!(
        wrong.is_empty(),
        "essl disagrees with Chromium:\n{}",
        wrong.join("\n")
    );
    assert!(
        fixed.is_empty(),
        "now agree: take them off KNOWN_DIFFERENCES: {fixed:?}"
    );
}
