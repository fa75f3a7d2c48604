//! The shared body of the `vs_naga` benches: the shader set both front ends accept, and the
//! two timed loops.

use criterion::{Criterion, Throughput};
use essl::source::SourceFile;
use essl::Stage;

fn naga_stage(stage: Stage) -> naga::ShaderStage {
    match stage {
        Stage::Vertex => naga::ShaderStage::Vertex,
        Stage::Fragment => naga::ShaderStage::Fragment,
    }
}

/// naga's parse + validate; a panic inside naga's front end (it has some on these corpora)
/// counts as a rejection.
fn naga_compile(src: &str, stage: Stage) -> bool {
    std::panic::catch_unwind(|| naga_compile_here(src, stage)).unwrap_or(false)
}

fn naga_compile_here(src: &str, stage: Stage) -> bool {
    let mut frontend = naga::front::glsl::Frontend::default();
    let options = naga::front::glsl::Options::from(naga_stage(stage));
    match frontend.parse(&options, src) {
        Ok(module) => naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::default(),
        )
        .validate(&module)
        .is_ok(),
        Err(_) => false,
    }
}

/// (essl text, naga text, stage) for every shader of the cases both accept.
fn shaders() -> Vec<(String, String, Stage)> {
    let Some(path) = essl_testdata::corpus_file("webgl_conformance_es300.jsonl") else {
        return Vec::new();
    };
    let text = std::fs::read_to_string(&path).expect("the corpus file reads");
    let mut out = Vec::new();
    let mut cases = 0;
    // naga's panics on some cases would print a backtrace each.
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    for case in text
        .lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .filter(|c| c["outcome"] == "must_pass")
    {
        let pair: Vec<(String, String, Stage)> = [
            ("vertex_source", Stage::Vertex),
            ("fragment_source", Stage::Fragment),
        ]
        .iter()
        .filter_map(|(key, stage)| {
            let src = case[*key].as_str()?.to_string();
            let rewritten = src.replacen("#version 300 es", "#version 450 core", 1);
            Some((src, rewritten, *stage))
        })
        .collect();
        let both = pair.iter().all(|(src, rewritten, stage)| {
            naga_compile(rewritten, *stage)
                && essl::compile(
                    SourceFile::new("s", src.as_str()),
                    *stage,
                    &Default::default(),
                )
                .ok()
        });
        if both && !pair.is_empty() {
            cases += 1;
            out.extend(pair);
        }
    }
    std::panic::set_hook(hook);
    eprintln!(
        "{cases} cases, {} shaders that both front ends accept",
        out.len()
    );
    out
}

fn essl_pass(set: &[(String, String, Stage)]) {
    for (src, _, stage) in set {
        let shader = essl::compile(
            SourceFile::new("s", src.as_str()),
            *stage,
            &Default::default(),
        );
        std::hint::black_box(shader.ok());
    }
}

fn naga_pass(set: &[(String, String, Stage)]) {
    for (_, rewritten, stage) in set {
        std::hint::black_box(naga_compile(rewritten, *stage));
    }
}

/// essl's time over naga's, from passes that alternate (essl, naga, essl, …): the median of
/// the per-round ratios, so that a change of the machine's load between criterion's two
/// measurements does not move the ratio.
fn interleaved_ratio(set: &[(String, String, Stage)], rounds: usize) -> f64 {
    use std::time::Instant;
    let mut ratios: Vec<f64> = (0..rounds)
        .map(|_| {
            let t = Instant::now();
            essl_pass(set);
            let essl = t.elapsed().as_secs_f64();
            let t = Instant::now();
            naga_pass(set);
            essl / t.elapsed().as_secs_f64()
        })
        .collect();
    ratios.sort_by(f64::total_cmp);
    ratios[rounds / 2]
}

/// Both sides over the whole set, in one criterion group, then their interleaved ratio.
pub fn bench(c: &mut Criterion) {
    let set = shaders();
    if set.is_empty() {
        return;
    }
    let mut group = c.benchmark_group("front end");
    group.throughput(Throughput::Elements(set.len() as u64));
    group.bench_function("essl compile (through naga validation)", |b| {
        b.iter(|| essl_pass(&set))
    });
    group.bench_function("naga glsl-in parse + validate", |b| {
        b.iter(|| naga_pass(&set))
    });
    group.finish();
    const ROUNDS: usize = 201;
    eprintln!(
        "essl / naga, interleaved, median of {ROUNDS} rounds: {:.3}",
        interleaved_ratio(&set, ROUNDS)
    );
}
