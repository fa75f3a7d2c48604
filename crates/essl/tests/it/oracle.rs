//! The front end against what WebGL2 (Chromium's ANGLE) answered, committed in `tests/oracle/`:
//! compile status of every shader, and link status and active uniforms/attributes (names,
//! types, sizes, locations, order) of every program.

use std::path::{Path, PathBuf};

use essl::link::{link, Program};
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Extension, Shader, Stage, Target};
use serde_json::Value;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn corpora() -> Option<PathBuf> {
    essl_testdata::corpora()
}

fn compile_str(name: &str, src: &str, stage: Stage) -> Shader {
    compile_with(name, src, stage, &Default::default())
}

fn compile_with(name: &str, src: &str, stage: Stage, options: &CompileOptions) -> Shader {
    compile(SourceFile::new(name, src), stage, options)
}

fn stage_of(name: &str) -> Stage {
    if name.ends_with(".vert") {
        Stage::Vertex
    } else {
        Stage::Fragment
    }
}

/// Compares one program's active lists with the oracle's; returns a description of differences.
fn compare_program(p: &Program, expected: &Value) -> Vec<String> {
    let mut diffs = Vec::new();
    let ok = expected["ok"].as_bool().unwrap_or(false);
    if p.ok != ok {
        diffs.push(format!(
            "link ok: essl {} vs WebGL {ok}; essl log: {}",
            p.ok,
            p.log.trim()
        ));
        return diffs;
    }
    if !ok {
        return diffs;
    }
    let gl_name = |v: &Value| -> String {
        match v {
            Value::String(s) => s.clone(),
            Value::Number(n) => essl::types::GlType::from_u32(n.as_u64().unwrap_or(0) as u32)
                .map(|t| t.name().to_string())
                .unwrap_or_default(),
            _ => String::new(),
        }
    };
    let want_u: Vec<String> = expected["uniforms"]
        .as_array()
        .unwrap()
        .iter()
        .map(|u| {
            format!(
                "{} {} {}",
                u["name"].as_str().unwrap(),
                gl_name(&u["type"]),
                u["size"]
            )
        })
        .collect();
    let got_u: Vec<String> = p
        .uniforms
        .iter()
        .map(|u| format!("{} {} {}", u.name, u.ty.name(), u.size))
        .collect();
    if want_u != got_u {
        diffs.push(format!("uniforms:\n  WebGL {want_u:?}\n  essl  {got_u:?}"));
    }
    let want_a: Vec<String> = expected["attributes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| {
            format!(
                "{} {} {} @{}",
                a["name"].as_str().unwrap(),
                gl_name(&a["type"]),
                a["size"],
                a["location"]
            )
        })
        .collect();
    let got_a: Vec<String> = p
        .attributes
        .iter()
        .map(|a| format!("{} {} {} @{}", a.name, a.ty.name(), a.size, a.location))
        .collect();
    if want_a != got_a {
        diffs.push(format!(
            "attributes:\n  WebGL {want_a:?}\n  essl  {got_a:?}"
        ));
    }
    diffs
}

/// Checks an oracle file produced by `webgl2-oracle.py` over a folder of NAME.vert/NAME.frag.
fn check_oracle_folder(json: &str) -> Vec<String> {
    check_oracle_folder_with(json, &CompileOptions::default())
}

/// Checks an oracle file, compiling with `options` (the context the oracle asked).
fn check_oracle_folder_with(json: &str, options: &CompileOptions) -> Vec<String> {
    let data: Value =
        serde_json::from_str(&std::fs::read_to_string(repo().join(json)).unwrap()).unwrap();
    let mut failures = Vec::new();
    let mut shaders = std::collections::HashMap::new();
    for (file, expect) in data["compile"].as_object().unwrap() {
        let src = std::fs::read_to_string(repo().join(file)).unwrap();
        let sh = compile_with(file, &src, stage_of(file), options);
        let ok = expect["ok"].as_bool().unwrap();
        if sh.ok() != ok {
            let first = sh
                .diagnostics
                .iter()
                .find(|d| d.is_error())
                .map(|d| d.message.clone())
                .unwrap_or_default();
            failures.push(format!(
                "{file}: compile ok essl {} vs WebGL {ok} ({}) {first}",
                sh.ok(),
                expect["log"].as_str().unwrap_or("").trim()
            ));
        }
        shaders.insert(file.clone(), sh);
    }
    for (base, expect) in data["link"].as_object().unwrap() {
        let (Some(vs), Some(fs)) = (
            shaders.get(&format!("{base}.vert")),
            shaders.get(&format!("{base}.frag")),
        ) else {
            continue;
        };
        let p = link(vs, fs);
        for d in compare_program(&p, expect) {
            failures.push(format!("{base}: {d}"));
        }
    }
    failures
}

#[test]
fn shaders_glsl_agree_with_webgl2() {
    let failures = check_oracle_folder("tests/oracle/shaders-glsl.json");
    assert!(
        failures.is_empty(),
        "{} disagreements:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// Probes where essl knowingly differs from WebGL2 (none at present). Each entry must still
/// disagree, so fixing one fails this test until it is removed from the list.
const KNOWN_GAPS: &[&str] = &[];

#[test]
fn probes_agree_with_webgl2() {
    let failures = check_oracle_folder("tests/oracle/probes.json");
    let (known, unexpected): (Vec<_>, Vec<_>) = failures
        .iter()
        .partition(|f| KNOWN_GAPS.iter().any(|k| f.contains(k)));
    assert!(
        unexpected.is_empty(),
        "{} disagreements:\n{}",
        unexpected.len(),
        unexpected
            .iter()
            .map(|s| s.as_str())
            .collect::<Vec<_>>()
            .join("\n")
    );
    for gap in KNOWN_GAPS {
        assert!(
            known.iter().any(|f| f.contains(gap)),
            "known gap `{gap}` no longer differs: remove it from KNOWN_GAPS"
        );
    }
}

/// The constant-folding probes (`f-*`): besides compiling as Chromium does (and folding to
/// ANGLE's values, which each probe tests through an array size), essl warns where Chromium's
/// log does, on the same lines, with the same kinds (Chromium repeats a warning for each
/// component of a vector, essl says it once): Chromium's messages map to `division-by-zero`
/// ("Divide by zero", "Zero divided by zero"), `non-finite-constant` ("Infinity divided by
/// infinity", "overflowed to infinity", "undefined … generated NaN"), `negative-modulus`, `undefined-constant-call`
/// ("operation result is undefined") and `negative-to-uint`.
#[test]
fn folding_warnings_agree_with_chromium() {
    let data: Value = serde_json::from_str(
        &std::fs::read_to_string(repo().join("tests/oracle/probes.json")).unwrap(),
    )
    .unwrap();
    let code_of = |message: &str| {
        if message.contains("negative float to uint") {
            "negative-to-uint"
        } else if message.contains("operation result is undefined") {
            "undefined-constant-call"
        } else if message.contains("Negative modulus") {
            "negative-modulus"
        } else if message.contains("Infinity divided")
            || message.contains("overflowed")
            || message.contains("generated NaN") && !message.contains("Zero divided")
        {
            "non-finite-constant"
        } else if message.contains("ivide") {
            "division-by-zero"
        } else {
            "other"
        }
    };
    let mut seen = 0;
    for (file, expect) in data["compile"].as_object().unwrap() {
        if !file.contains("/f-") || !file.ends_with(".frag") {
            continue;
        }
        seen += 1;
        let mut chromium: Vec<(u32, &str)> = expect["log"]
            .as_str()
            .unwrap()
            .lines()
            .filter_map(|l| l.strip_prefix("WARNING: 0:"))
            .map(|l| {
                let (line, rest) = l.split_once(':').unwrap();
                (line.parse().unwrap(), code_of(rest))
            })
            .collect();
        let src = std::fs::read_to_string(repo().join(file)).unwrap();
        let sh = compile_str(file, &src, Stage::Fragment);
        let mut essl: Vec<(u32, &str)> = sh
            .diagnostics
            .iter()
            .filter(|d| !d.is_error())
            .map(|d| (sh.file.line_col(d.span.start).line, d.code))
            .collect();
        for w in [&mut chromium, &mut essl] {
            w.sort();
            w.dedup();
        }
        assert_eq!(essl, chromium, "{file}: essl's warnings against Chromium's");
    }
    assert!(
        seen >= 15,
        "the folding probes are in tests/oracle/probes.json"
    );
}

/// The GLSL ES 1.00 and WebGL-limit probes (`tests/oracle/ES100.md`), each answer file with the
/// options of the context that gave it: WebGL 1 with no extension, WebGL 1 with the four
/// extensions enabled, WebGL 2.
#[test]
fn es100_probes_agree_with_chromium() {
    let webgl1 = |extensions: Vec<Extension>| CompileOptions {
        target: Target::WebGl1,
        extensions,
        ..CompileOptions::default()
    };
    let mut failures = Vec::new();
    for (json, options) in [
        ("tests/oracle/es100-webgl1.json", webgl1(Vec::new())),
        (
            "tests/oracle/es100-webgl1-ext.json",
            webgl1(Extension::ALL.to_vec()),
        ),
        (
            "tests/oracle/es100-webgl2.json",
            CompileOptions::for_target(Target::WebGl2),
        ),
    ] {
        failures.extend(
            check_oracle_folder_with(json, &options)
                .into_iter()
                .map(|f| format!("{json}: {f}")),
        );
    }
    assert!(
        failures.is_empty(),
        "{} disagreements:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn webgl2fundamentals_programs_agree_with_webgl2() {
    let Some(corpora) = corpora() else { return };
    let corpus: Vec<Value> =
        std::fs::read_to_string(corpora.join("webgl2fundamentals_shaders.jsonl"))
            .unwrap()
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
    let data: Value = serde_json::from_str(
        &std::fs::read_to_string(repo().join("tests/oracle/webgl2fundamentals.json")).unwrap(),
    )
    .unwrap();
    let mut failures = Vec::new();
    let mut compiled = std::collections::HashMap::new();
    for (idx, expect) in data["shaders"].as_object().unwrap() {
        let i: usize = idx.parse().unwrap();
        let entry = &corpus[i];
        let stage = if entry["stage"] == "vertex" {
            Stage::Vertex
        } else {
            Stage::Fragment
        };
        let sh = compile_str(&format!("{i}"), entry["source"].as_str().unwrap(), stage);
        if sh.ok() != expect["ok"].as_bool().unwrap() {
            failures.push(format!(
                "shader {i} ({}): compile ok essl {}",
                entry["file"],
                sh.ok()
            ));
        }
        compiled.insert(i, sh);
    }
    for p in data["programs"].as_array().unwrap() {
        let (v, f) = (
            p["vertex"].as_u64().unwrap() as usize,
            p["fragment"].as_u64().unwrap() as usize,
        );
        let prog = link(&compiled[&v], &compiled[&f]);
        for d in compare_program(&prog, p) {
            failures.push(format!("program {v}+{f} ({}): {d}", p["file"]));
        }
    }
    assert!(
        failures.is_empty(),
        "{} disagreements:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
