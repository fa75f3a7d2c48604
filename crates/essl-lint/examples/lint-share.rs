//! Compiles every `300 es` shader of the dEQP corpus, and lints it with `--lint` (its `#ifdef`
//! configurations too, as a check does by default: `essl_lint::variants`): what
//! `scripts/bench-lint-share.sh` runs twice to measure the lints' share of the work.
//! `cargo run --release -p essl-lint --example lint-share -- [--lint] [CORPORA_DIR]`.

use essl::source::SourceFile;
use essl::{compile, CompileOptions, Stage};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let lint = args.iter().any(|a| a == "--lint");
    let dir = args
        .iter()
        .find(|a| !a.starts_with("--"))
        .cloned()
        .unwrap_or_else(|| "../shared/corpora".to_string());
    let text = std::fs::read_to_string(format!("{dir}/deqp_gles3.jsonl"))
        .unwrap_or_else(|e| panic!("{dir}/deqp_gles3.jsonl: {e}"));
    let options = essl_lint::LintOptions::new();
    let (mut shaders, mut compiled, mut findings) = (0, 0, 0);
    for line in text.lines() {
        let Ok(case) = serde_json::from_str::<serde_json::Value>(line) else {
            continue;
        };
        if case["version"] != "300 es" {
            continue;
        }
        for (key, stage) in [
            ("vertex_source", Stage::Vertex),
            ("fragment_source", Stage::Fragment),
        ] {
            let Some(src) = case[key].as_str() else {
                continue;
            };
            shaders += 1;
            let shader = compile(
                SourceFile::new("deqp", src),
                stage,
                &CompileOptions::default(),
            );
            compiled += usize::from(shader.naga.is_some());
            if lint && shader.naga.is_some() {
                let found = essl_lint::lint(&shader, &options);
                let compile_options = CompileOptions::default();
                findings += found.len()
                    + essl_lint::variants::lint_text(
                        &shader,
                        &compile_options,
                        &options,
                        &found,
                        essl_lint::variants::DEFAULT,
                    )
                    .len();
            }
        }
    }
    println!("{shaders} shaders, {compiled} lowered, {findings} findings");
}
