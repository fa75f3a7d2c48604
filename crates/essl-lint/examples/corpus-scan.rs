//! Runs the lints over the must-pass shaders of the shared corpora and prints every finding with
//! its source line (the configurations its `#ifdef`s select too, as a check lints them), then
//! the counts per rule — the figures of `docs/lints/README.md`:
//! `cargo run --release -p essl-lint --example corpus-scan [-- CORPORA_DIR [--all]]`.
//! `--all` takes every case (must-fail ones too, and glslang's), to check that nothing panics.

use std::collections::{BTreeMap, HashSet};

use essl::source::SourceFile;
use essl::{compile, CompileOptions, Stage};
use serde_json::Value;

fn main() {
    let dir = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "../shared/corpora".to_string());
    let all = std::env::args().any(|a| a == "--all");
    let mut shaders: Vec<(String, String, Stage, String)> = Vec::new(); // (corpus, case, stage, source)
    let read = |name: &str| -> Vec<Value> {
        let text = std::fs::read_to_string(format!("{dir}/{name}"))
            .unwrap_or_else(|e| panic!("{dir}/{name}: {e}"));
        text.lines()
            .filter(|l| !l.trim().is_empty())
            .map(|l| serde_json::from_str(l).expect("a JSON line"))
            .collect()
    };
    for c in read("webgl_conformance_es300.jsonl") {
        if c["outcome"] != "must_pass" && !all {
            continue;
        }
        let case = format!("{}#{}", c["file"].as_str().unwrap_or(""), c["index"]);
        for (key, stage) in [
            ("vertex_source", Stage::Vertex),
            ("fragment_source", Stage::Fragment),
        ] {
            if let Some(s) = c[key].as_str() {
                shaders.push(("webgl".into(), case.clone(), stage, s.to_string()));
            }
        }
    }
    for c in read("deqp_gles3.jsonl") {
        if !matches!(c["expect"].as_str(), Some("pass" | "build_successful")) && !all {
            continue;
        }
        let case = c["name"].as_str().unwrap_or("").to_string();
        for (key, stage) in [
            ("vertex_source", Stage::Vertex),
            ("fragment_source", Stage::Fragment),
        ] {
            if let Some(s) = c[key].as_str() {
                shaders.push(("deqp".into(), case.clone(), stage, s.to_string()));
            }
        }
    }
    for c in read("webgl2fundamentals_shaders.jsonl") {
        if (c["templated"] == true || c["expect_compile"] == false) && !all {
            continue;
        }
        let stage = match c["stage"].as_str() {
            Some("vertex") => Stage::Vertex,
            Some("fragment") => Stage::Fragment,
            _ => continue,
        };
        shaders.push((
            "webgl2fundamentals".into(),
            c["file"].as_str().unwrap_or("").to_string(),
            stage,
            c["source"].as_str().unwrap_or("").to_string(),
        ));
    }
    if all {
        for c in read("glslang_es300.jsonl") {
            let stage = if c["stage"] == "vertex" {
                Stage::Vertex
            } else {
                Stage::Fragment
            };
            shaders.push((
                "glslang".into(),
                c["file"].as_str().unwrap_or("").to_string(),
                stage,
                c["source"].as_str().unwrap_or("").to_string(),
            ));
        }
    }
    let mut seen = HashSet::new();
    let mut per_rule: BTreeMap<&str, usize> = BTreeMap::new();
    let mut distinct: BTreeMap<(&str, String), usize> = BTreeMap::new();
    let (mut total, mut compiled, mut flagged_shaders) = (0usize, 0usize, 0usize);
    let mut per_corpus: BTreeMap<String, (usize, usize, usize)> = BTreeMap::new();
    for (corpus, case, stage, source) in shaders {
        if !seen.insert((stage, source.clone())) {
            continue;
        }
        total += 1;
        let e = per_corpus.entry(corpus.clone()).or_default();
        e.0 += 1;
        let shader = compile(
            SourceFile::new(case.clone(), source),
            stage,
            &CompileOptions::default(),
        );
        if shader.naga.is_none() {
            continue;
        }
        compiled += 1;
        e.1 += 1;
        let options = essl_lint::LintOptions::default();
        let mut found = essl_lint::lint(&shader, &options);
        // The configurations its `#ifdef`s select, as a check lints them by default.
        let more = essl_lint::variants::lint_text(
            &shader,
            &CompileOptions::default(),
            &options,
            &found,
            essl_lint::variants::DEFAULT,
        );
        found.extend(more.into_iter().map(|f| f.diagnostic));
        if !found.is_empty() {
            flagged_shaders += 1;
            e.2 += 1;
        }
        for d in found {
            *per_rule.entry(d.code).or_default() += 1;
            let lc = shader.file.line_col(d.span.start);
            let line = shader
                .file
                .line_text(lc.line as usize - 1)
                .trim()
                .to_string();
            *distinct.entry((d.code, line.clone())).or_default() += 1;
            println!(
                "{corpus} {case} ({}) {lc} [{}] {}\n    {line}\n    {}",
                stage.as_str(),
                d.code,
                d.message,
                d.label
            );
        }
    }
    println!("\n== {total} distinct shaders, {compiled} lowered to naga, {flagged_shaders} with findings");
    for (c, (t, k, f)) in &per_corpus {
        println!("   {c}: {t} shaders, {k} lowered, {f} with findings");
    }
    for r in essl_lint::RULES {
        println!("{:24} {}", r.id, per_rule.get(r.id).copied().unwrap_or(0));
    }
    println!("\n== distinct findings (rule, line): {}", distinct.len());
    for ((code, line), n) in &distinct {
        println!("{n:4}  [{code}] {line}");
    }
}
