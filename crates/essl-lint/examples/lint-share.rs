//! Compiles every `300 es` shader of the dEQP corpus, and lints it with `--lint` (its `#ifdef`
//! configurations too, as a check does by default: `essl_lint::variants`): what
//! `scripts/bench-lint-share.sh` runs twice to measure the lints' share of the work.
//! `cargo run --release -p essl-lint --example lint-share -- [--lint] [--pipeline] [CORPORA_DIR]`.
//!
//! By default every shader is compiled with `essl::compile` (front end, lowering, naga's
//! validation) either way. With `--pipeline`, as `essl lint` does it: the front end alone, and
//! with `--lint` the shader lowered (typed, not validated) where a rule on the IR has something
//! to look at, then linted; the lowering is then the lints' cost.
//!
//! The corpus is read and parsed first; the work on the shaders is the function
//! [`compile_all`], which `scripts/bench-lint-share.sh` counts alone (callgrind's
//! `--toggle-collect`), so that reading the corpus's JSON is in neither figure.

use essl::source::SourceFile;
use essl::{compile, compile_front_end, CompileOptions, Stage};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let lint = args.iter().any(|a| a == "--lint");
    let pipeline = args.iter().any(|a| a == "--pipeline");
    let dir = args
        .iter()
        .find(|a| !a.starts_with("--"))
        .cloned()
        .unwrap_or_else(|| "../shared/corpora".to_string());
    let text = std::fs::read_to_string(format!("{dir}/deqp_gles3.jsonl"))
        .unwrap_or_else(|e| panic!("{dir}/deqp_gles3.jsonl: {e}"));
    let mut shaders = Vec::new();
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
            if let Some(src) = case[key].as_str() {
                shaders.push((src.to_string(), stage));
            }
        }
    }
    let (compiled, findings) = compile_all(&shaders, lint, pipeline);
    let what = if pipeline { "compiled" } else { "lowered" };
    println!(
        "{} shaders, {compiled} {what}, {findings} findings",
        shaders.len()
    );
}

/// Compiles (and with `lint`, lints) every shader: the work the bench counts. Returns how many
/// compiled and how many findings there were.
#[inline(never)]
fn compile_all(shaders: &[(String, Stage)], lint: bool, pipeline: bool) -> (usize, usize) {
    let options = essl_lint::LintOptions::new();
    let (mut compiled, mut findings) = (0, 0);
    for (src, stage) in shaders {
        let file = SourceFile::new("deqp", src);
        let mut shader = if pipeline {
            compile_front_end(file, *stage, &CompileOptions::default())
        } else {
            compile(file, *stage, &CompileOptions::default())
        };
        if pipeline && lint && essl_lint::needs_ir(&shader) {
            shader.lower_typed();
        }
        let ok = if pipeline {
            shader.ok()
        } else {
            shader.naga.is_some()
        };
        compiled += usize::from(ok);
        if lint && ok {
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
    (compiled, findings)
}
