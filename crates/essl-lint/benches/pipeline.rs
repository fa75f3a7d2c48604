//! The whole pipeline, stage by stage, on one set of shaders, so that a regression shows where
//! it came from: lex + preprocess, classify + parse, check, lower (+ naga validation), naga
//! validation alone, and the lints. Each stage gets the previous stage's output, prepared
//! outside the timed loop; one iteration runs the stage over the whole set.
//!
//! The set: every shader of `shaders-glsl/` and every 10th shader of the dEQP corpus
//! (`$ESSL_CORPORA` or `../shared/corpora/deqp_gles3.jsonl`, `300 es` cases) that compiles
//! (about 1,000 shaders; without the corpus, `shaders-glsl/` alone). `docs/performance.md` has
//! the current figure, `docs/performance-history.md` the table per pass.
//!
//! Run with `cargo bench -p essl-lint --bench pipeline`.

use std::path::Path;

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use essl::passes::{preprocess, PreprocessOptions};
use essl::program::LowerOptions;
use essl::source::SourceFile;
use essl::{Shader, Stage};

fn shaders() -> Vec<(String, Stage, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut out = Vec::new();
    for entry in std::fs::read_dir(root.join("shaders-glsl")).expect("shaders-glsl/ is there") {
        let path = entry.expect("a folder entry").path();
        if let (Some(stage), Ok(text)) = (Stage::from_path(&path), std::fs::read_to_string(&path)) {
            out.push((path.display().to_string(), stage, text));
        }
    }
    let corpora = std::env::var_os("ESSL_CORPORA")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| root.join("../shared/corpora"));
    if let Ok(text) = std::fs::read_to_string(corpora.join("deqp_gles3.jsonl")) {
        let cases = text
            .lines()
            .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
            .filter(|c| c["version"] == "300 es");
        for (i, case) in cases.enumerate().filter(|(i, _)| i % 10 == 0) {
            for (key, stage) in [
                ("vertex_source", Stage::Vertex),
                ("fragment_source", Stage::Fragment),
            ] {
                if let Some(src) = case[key].as_str() {
                    out.push((format!("deqp-{i}"), stage, src.to_string()));
                }
            }
        }
    } else {
        eprintln!(
            "no dEQP corpus at {}: shaders-glsl/ only",
            corpora.display()
        );
    }
    // Only shaders that compile: every stage then does its whole work.
    out.retain(|(name, stage, text)| {
        essl::compile(
            SourceFile::new(name.as_str(), text.as_str()),
            *stage,
            &Default::default(),
        )
        .ok()
    });
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

struct Parsed {
    file: SourceFile,
    stage: Stage,
    unit: essl::passes::TranslationUnit,
    invariant_all: bool,
    version: essl::Version,
}

fn pp_options(stage: Stage) -> PreprocessOptions {
    PreprocessOptions {
        stage: Some(stage),
        ..Default::default()
    }
}

fn parse_all(set: &[(String, Stage, String)]) -> Vec<Parsed> {
    set.iter()
        .map(|(name, stage, text)| {
            let file = SourceFile::new(name.as_str(), text.as_str());
            let pp = preprocess(&file, essl::passes::lex(&file), &pp_options(*stage));
            let mut diags = Vec::new();
            let tokens = essl::passes::classify(pp.tokens, &mut diags);
            let (unit, _) = essl::passes::parse(&file, tokens, *stage);
            Parsed {
                file,
                stage: *stage,
                unit,
                invariant_all: pp.invariant_all,
                version: pp.version,
            }
        })
        .collect()
}

fn checked(parsed: &[Parsed]) -> Vec<Shader> {
    parsed
        .iter()
        .map(|p| {
            let (module, diagnostics) =
                essl::passes::check(&p.file, &p.unit, p.stage, p.invariant_all);
            Shader {
                file: p.file.clone(),
                stage: p.stage,
                version: p.version,
                target: essl::Target::WebGl2,
                diagnostics,
                module,
                naga: None,
                expansions: Vec::new(),
            }
        })
        .collect()
}

fn bench_stages(c: &mut Criterion) {
    let set = shaders();
    let n = set.len() as u64;
    eprintln!("{n} shaders");
    let mut group = c.benchmark_group("pipeline");
    group.sample_size(10);
    group.throughput(Throughput::Elements(n));

    let files: Vec<(SourceFile, Stage)> = set
        .iter()
        .map(|(name, stage, text)| (SourceFile::new(name.as_str(), text.as_str()), *stage))
        .collect();
    group.bench_function("1 lex + preprocess", |b| {
        b.iter(|| {
            for (file, stage) in &files {
                let pp = preprocess(file, essl::passes::lex(file), &pp_options(*stage));
                std::hint::black_box(pp.tokens.len());
            }
        })
    });

    let pps: Vec<_> = files
        .iter()
        .map(|(file, stage)| preprocess(file, essl::passes::lex(file), &pp_options(*stage)).tokens)
        .collect();
    group.bench_function("2 classify + parse", |b| {
        b.iter_batched(
            || pps.clone(),
            |pps| {
                for ((file, stage), tokens) in files.iter().zip(pps) {
                    let mut diags = Vec::new();
                    let tokens = essl::passes::classify(tokens, &mut diags);
                    std::hint::black_box(essl::passes::parse(file, tokens, *stage));
                }
            },
            BatchSize::LargeInput,
        )
    });

    let parsed = parse_all(&set);
    group.bench_function("3 check", |b| {
        b.iter(|| {
            for p in &parsed {
                std::hint::black_box(essl::passes::check(
                    &p.file,
                    &p.unit,
                    p.stage,
                    p.invariant_all,
                ));
            }
        })
    });

    let mut shaders = checked(&parsed);
    let options = LowerOptions::default();
    group.bench_function("4 lower + naga validation", |b| {
        b.iter(|| {
            for s in &shaders {
                std::hint::black_box(essl::lower::lower_shader(s, &options).is_ok());
            }
        })
    });

    for s in &mut shaders {
        s.naga = essl::lower::lower_shader(s, &options)
            .ok()
            .map(|(m, info)| essl::lower::Lowered::validated(m, info));
    }
    group.bench_function("5 naga validation alone", |b| {
        b.iter(|| {
            for s in &shaders {
                if let Some(essl::lower::Lowered { module, .. }) = &s.naga {
                    let mut v = naga::valid::Validator::new(
                        naga::valid::ValidationFlags::all(),
                        naga::valid::Capabilities::default(),
                    );
                    std::hint::black_box(v.validate(module).is_ok());
                }
            }
        })
    });

    let lint_options = essl_lint::LintOptions::new();
    group.bench_function("6 lints", |b| {
        b.iter(|| {
            for s in &shaders {
                std::hint::black_box(essl_lint::lint(s, &lint_options).len());
            }
        })
    });

    group.bench_function("all: compile + lints", |b| {
        b.iter(|| {
            for (file, stage) in &files {
                let shader = essl::compile(file.clone(), *stage, &Default::default());
                std::hint::black_box(essl_lint::lint(&shader, &lint_options).len());
            }
        })
    });
    group.finish();
}

criterion_group!(benches, bench_stages);
criterion_main!(benches);
