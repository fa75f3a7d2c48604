//! Lints the real-world corpus that `scripts/lint-corpus/fetch.sh` builds and prints one JSON
//! line per finding (`file`, `repo`, `path`, `rule`, `severity`, `line`, `text`: the source
//! line, trimmed; `defined`: the line and text of the `#define` a finding inside a macro's
//! expansion labels), then a summary line (`"kind": "summary"`: shaders, compiled, findings per rule
//! and severity). Notes are included: the corpus counts every level.
//!
//! `cargo run --release -p essl-lint --example lint-corpus -- CORPUS_DIR [VARIANTS]`
//! (`CORPUS_DIR/manifest.jsonl`, as `scripts/lint-corpus/extract.py` writes it); `VARIANTS`:
//! how many `#ifdef` configurations of each shader to lint besides the one compiled
//! (`essl_lint::variants`; 0 by default), whose findings carry `"variant"`, the macros defined.

use std::collections::BTreeMap;

use essl::source::SourceFile;
use essl::{compile_front_end, CompileOptions, Stage};
use serde_json::{json, Value};

fn main() {
    let dir = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "../lint-corpus".to_string());
    let manifest = std::fs::read_to_string(format!("{dir}/manifest.jsonl"))
        .unwrap_or_else(|e| panic!("{dir}/manifest.jsonl: {e}"));
    let variants: usize = std::env::args()
        .nth(2)
        .map_or(0, |n| n.parse().expect("VARIANTS: a number"));
    let options = essl_lint::LintOptions::new().notes(true);
    let (mut shaders, mut compiled) = (0, 0);
    let mut per_rule: BTreeMap<String, usize> = BTreeMap::new();
    let mut repos_compiled: BTreeMap<String, usize> = BTreeMap::new();
    for line in manifest.lines().filter(|l| !l.trim().is_empty()) {
        let entry: Value = serde_json::from_str(line).expect("a JSON line");
        let file = entry["file"].as_str().unwrap_or_default();
        let stage = match entry["stage"].as_str() {
            Some("vertex") => Stage::Vertex,
            _ => Stage::Fragment,
        };
        let Ok(text) = std::fs::read_to_string(format!("{dir}/{file}")) else {
            continue;
        };
        shaders += 1;
        // Lowered as `essl lint` lowers for the lints: where a rule on the IR has something to
        // look at, typed, not validated.
        let mut shader = compile_front_end(
            SourceFile::new(file, text.as_str()),
            stage,
            &CompileOptions::default(),
        );
        if essl_lint::needs_ir(&shader) {
            shader.lower_typed();
        }
        if !shader.ok() {
            continue;
        }
        compiled += 1;
        let repo = entry["repo"].as_str().unwrap_or_default().to_string();
        *repos_compiled.entry(repo.clone()).or_default() += 1;
        let compile_options = CompileOptions::default();
        let mut found: Vec<(essl::diagnostic::Diagnostic, Value)> =
            essl_lint::lint(&shader, &options)
                .into_iter()
                .map(|d| (d, Value::Null))
                .collect();
        if variants > 0 {
            let base: Vec<_> = found.iter().map(|(d, _)| d.clone()).collect();
            let more = essl_lint::variants::lint_text(
                &shader,
                &compile_options,
                &options,
                &base,
                variants,
            );
            found.extend(more.into_iter().map(|f| (f.diagnostic, json!(f.defines))));
        }
        for (d, variant) in found {
            let lc = shader.file.line_col(d.span.start);
            let source_line = text.lines().nth(lc.line as usize - 1).unwrap_or("").trim();
            // The `#define` a finding inside a macro's replacement list labels: the line a
            // reader finds the hazard on.
            let defined: Vec<Value> = d
                .secondary
                .iter()
                .filter(|l| l.message.starts_with("in this expansion of"))
                .map(|l| {
                    let at = shader.file.line_col(l.span.start).line;
                    let t = text.lines().nth(at as usize - 1).unwrap_or("").trim();
                    json!({ "line": at, "text": t })
                })
                .collect();
            *per_rule
                .entry(format!("{} {}", d.code, d.severity.as_str()))
                .or_default() += 1;
            println!(
                "{}",
                json!({
                    "file": file,
                    "repo": repo,
                    "path": entry["path"],
                    "rule": d.code,
                    "severity": d.severity.as_str(),
                    "line": lc.line,
                    "column": lc.column,
                    "span": shader.file.slice(d.span),
                    "message": d.message,
                    "label": d.label,
                    "text": source_line,
                    "variant": variant,
                    "defined": defined,
                })
            );
        }
    }
    println!(
        "{}",
        json!({
            "kind": "summary",
            "shaders": shaders,
            "compiled": compiled,
            "repositories": repos_compiled.len(),
            "per_repository": repos_compiled,
            "findings": per_rule,
        })
    );
}
