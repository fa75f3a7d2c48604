//! Time of the lints, all rules and each rule alone, on the shaders `vite-overhead.mjs` builds:
//! the first 200 webgl2fundamentals shaders that compile (`webgl2fundamentals_shaders.jsonl`,
//! not templated). Each shader is compiled once; then every pass lints all of them.
//!
//! `cargo run --release -p essl-lint --example rule-times -- [CORPORA_DIR] [--passes N]
//! [--rule ID]` (default `../shared/corpora`, 40 passes, every rule). Prints milliseconds a
//! pass: three passes of all rules, then each rule alone (which includes the value analysis
//! for every rule that asks for it).

use std::time::Instant;

use essl::source::SourceFile;
use essl::{compile, CompileOptions, Shader, Stage};
use essl_lint::LintOptions;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let after = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1))
    };
    let passes: usize = after("--passes").and_then(|n| n.parse().ok()).unwrap_or(40);
    let only = after("--rule");
    let dir = args
        .iter()
        .enumerate()
        .find(|(i, a)| !a.starts_with("--") && (*i == 0 || !args[i - 1].starts_with("--")))
        .map_or("../shared/corpora", |(_, a)| a.as_str());
    let path = format!("{dir}/webgl2fundamentals_shaders.jsonl");
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("rule-times: {path}: {e}");
            std::process::exit(1);
        }
    };
    let shaders = shaders(&text);
    println!("{} shaders, {passes} passes", shaders.len());
    let time = |options: &LintOptions| {
        let start = Instant::now();
        let mut findings = 0;
        for _ in 0..passes {
            for s in &shaders {
                findings += essl_lint::lint(s, options).len();
            }
        }
        let ms = start.elapsed().as_secs_f64() * 1e3 / passes as f64;
        (ms, findings / passes.max(1))
    };
    for _ in 0..3 {
        let (ms, findings) = time(&LintOptions::new());
        println!("all rules {ms:.3} ms a pass ({findings} findings)");
    }
    for r in essl_lint::RULES {
        if only.is_some_and(|o| o != r.id) {
            continue;
        }
        let (ms, _) = time(&LintOptions::new().allow("all").warn(r.id));
        println!("  {:30} {ms:.3} ms a pass", r.id);
    }
}

/// The corpus's first 200 shaders that are not templated and are expected to compile,
/// compiled.
fn shaders(jsonl: &str) -> Vec<Shader> {
    jsonl
        .lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .filter(|c| c["templated"] != true && c["expect_compile"] == true)
        .filter_map(|c| {
            let stage = match c["stage"].as_str()? {
                "vertex" => Stage::Vertex,
                "fragment" => Stage::Fragment,
                _ => return None,
            };
            let source = c["source"].as_str()?.to_string();
            Some((source, stage))
        })
        .take(200)
        .map(|(source, stage)| {
            compile(
                SourceFile::new("shader", source),
                stage,
                &CompileOptions::default(),
            )
        })
        .collect()
}
