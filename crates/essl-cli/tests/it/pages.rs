//! Shaders inside web pages: the 297 webgl2fundamentals lesson pages
//! (`../shared/corpora/webgl2fundamentals-pages`), whose shaders sit in JS template literals
//! and `<script type="x-shader/…">` tags. Every shader found must compile (Chromium compiles
//! every one of them: `webgl2fundamentals_shaders.jsonl` expects each to), and errors planted
//! in copies of three pages must be reported on the pages' own lines, link errors included,
//! and `--fix` must repair the page itself. Skips without the corpora unless
//! `ESSL_REQUIRE_CORPORA=1`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn pages() -> Option<PathBuf> {
    let dir = essl_testdata::corpora()?.join("webgl2fundamentals-pages");
    if dir.is_dir() {
        return Some(dir);
    }
    if std::env::var_os(essl_testdata::REQUIRE_CORPORA).is_some_and(|v| v == "1") {
        panic!("{} is missing", dir.display());
    }
    eprintln!("SKIPPED: {} is absent", dir.display());
    None
}

fn essl(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_essl"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the essl binary runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).unwrap()
}

#[test]
fn every_shader_in_the_pages_is_found_and_compiles() {
    let Some(dir) = pages() else { return };
    let o = essl(&["lint", "--format", "json", "."], &dir);
    let lines: Vec<serde_json::Value> = text(&o.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let shaders: Vec<&serde_json::Value> = lines.iter().filter(|l| l["kind"] == "shader").collect();
    let failed: Vec<String> = shaders
        .iter()
        .filter(|s| s["ok"] != true)
        .map(|s| format!("{} {}", s["embedded_at"], s["diagnostics"]))
        .collect();
    assert!(
        failed.is_empty(),
        "shaders that do not compile: {failed:#?}"
    );
    assert!(shaders.len() >= 476, "{} shaders found", shaders.len());
    let programs = lines.iter().filter(|l| l["kind"] == "program").count();
    let summary = lines.last().unwrap();
    assert_eq!(summary["errors"], 0);
    // Every literal is read: the two that interpolate constants
    // (`layout(location=${loc_aPosition})`) have their values put in.
    let err = text(&o.stderr);
    assert_eq!(err.matches("skipped ").count(), 0, "{err}");
    assert_eq!(o.status.code(), Some(0), "{err}");
    let interpolated = lines
        .iter()
        .find(|l| {
            l["kind"] == "program"
                && l["vertex"]
                    .as_str()
                    .is_some_and(|v| v.contains("displacement-map-and-specular-map-example-2"))
        })
        .expect("the page's program");
    assert_eq!(
        interpolated["attributes"][0]["location"], 3,
        "{interpolated}"
    );
    eprintln!("{} shaders, {programs} programs", shaders.len());
    assert!(programs >= 228, "{programs} programs linked");
}

/// The 1-based line of the first occurrence of `needle` in `page`, and the 1-based column
/// just past it.
fn position_after(page: &str, needle: &str) -> (usize, usize) {
    let at = page
        .find(needle)
        .unwrap_or_else(|| panic!("`{needle}` not found"))
        + needle.len();
    let line = page[..at].matches('\n').count() + 1;
    let col = at - page[..at].rfind('\n').map_or(0, |n| n + 1) + 1;
    (line, col)
}

fn line_of(page: &str, needle: &str) -> usize {
    let at = page
        .find(needle)
        .unwrap_or_else(|| panic!("`{needle}` not found"));
    page[..at].matches('\n').count() + 1
}

#[test]
fn planted_errors_are_reported_on_the_pages_lines() {
    let Some(dir) = pages() else { return };
    let tmp = tempfile::tempdir().unwrap();
    let copy = |name: &str, from: &str, to: &str| -> String {
        let page = std::fs::read_to_string(dir.join(name)).unwrap();
        assert!(page.contains(from), "{name} holds `{from}`");
        let planted = page.replacen(from, to, 1);
        std::fs::write(tmp.path().join(name), &planted).unwrap();
        planted
    };
    // A missing `;` in a template literal's vertex shader.
    let rect = copy(
        "webgl-2d-rectangle.html",
        "vec2 zeroToTwo = zeroToOne * 2.0;",
        "vec2 zeroToTwo = zeroToOne * 2.0",
    );
    // An undeclared name in a `<script type="x-shader/x-fragment">` tag.
    let pick = copy(
        "webgl-picking-w-gpu-1pixel-w-texture.html",
        "    gl_FragColor = u_id;",
        "    gl_FragColor = u_idd;",
    );
    // A fragment input the vertex shader does not write: a link error, on the fragment
    // shader's line.
    let light = copy(
        "webgl-3d-lighting-directional.html",
        "in vec3 v_normal;",
        "in vec3 v_normal;\nin vec2 v_planted;",
    );
    let light = light.replacen(
        "outColor = u_color;",
        "outColor = u_color + v_planted.xxxx;",
        1,
    );
    std::fs::write(
        tmp.path().join("webgl-3d-lighting-directional.html"),
        &light,
    )
    .unwrap();

    let o = essl(&["lint", "--format", "concise", "--quiet", "."], tmp.path());
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}{}", text(&o.stderr));
    let (line, col) = position_after(&rect, "zeroToOne * 2.0");
    assert!(
        out.contains(&format!(
            "webgl-2d-rectangle.html:{line}:{col}: error[missing-semicolon]"
        )),
        "{out}"
    );
    let (line, col) = position_after(&pick, "gl_FragColor = u_idd");
    let col = col - "u_idd".len();
    assert!(
        out.contains(&format!(
            "webgl-picking-w-gpu-1pixel-w-texture.html:{line}:{col}: error[undeclared-identifier]"
        )),
        "{out}"
    );
    let line = line_of(&light, "in vec2 v_planted;");
    assert!(
        out.contains(&format!("webgl-3d-lighting-directional.html:{line}:")),
        "the link error is on the fragment shader's line {line}: {out}"
    );

    // `--fix` repairs the page itself, and nothing else in it changes.
    let o = essl(&["lint", "--fix", "webgl-2d-rectangle.html"], tmp.path());
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stdout));
    let fixed = std::fs::read_to_string(tmp.path().join("webgl-2d-rectangle.html")).unwrap();
    let original = std::fs::read_to_string(dir.join("webgl-2d-rectangle.html")).unwrap();
    assert_eq!(fixed, original);
}

#[test]
fn stages_agree_with_the_corpus_extraction() {
    let Some(dir) = pages() else { return };
    let Some(corpus) = essl_testdata::corpus_file("webgl2fundamentals_shaders.jsonl") else {
        return;
    };
    // The stage the corpus's own extractor gave each source (where it could tell).
    let mut known = std::collections::HashMap::new();
    for line in std::fs::read_to_string(corpus).unwrap().lines() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        if let Some(stage) = v["stage"].as_str() {
            known.insert(v["source"].as_str().unwrap().to_string(), stage.to_string());
        }
    }
    let (mut compared, mut differ) = (0, Vec::new());
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let Some(kind) = essl_check::extract::HostKind::of(&path) else {
            continue;
        };
        let page = std::fs::read_to_string(&path).unwrap();
        for e in essl_check::extract::extract(kind, &page, &essl_check::extract::NoImports) {
            let (Some(stage), Some(expected)) = (e.stage, known.get(&page[e.range.clone()])) else {
                continue;
            };
            compared += 1;
            if stage.as_str() != expected {
                differ.push(format!("{}: {:?}", path.display(), e.name));
            }
        }
    }
    assert!(differ.is_empty(), "stages that differ: {differ:#?}");
    eprintln!("{compared} shaders' stages agree with the corpus");
    assert!(compared >= 300, "{compared} shaders compared");
}
