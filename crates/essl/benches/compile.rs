//! Compile + check time per shader, for every file in `shaders-glsl/`.
//!
//! Run with `cargo bench -p essl --bench compile`.

use std::path::Path;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use essl::source::SourceFile;
use essl::{compile, CompileOptions, Stage};

fn shaders() -> Vec<(String, Stage, String)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shaders-glsl");
    let mut out: Vec<_> = std::fs::read_dir(&dir)
        .expect("shaders-glsl/ is in the repository")
        .filter_map(|e| {
            let path = e.ok()?.path();
            let stage = Stage::from_path(&path)?;
            let text = std::fs::read_to_string(&path).ok()?;
            Some((
                path.file_name()?.to_string_lossy().into_owned(),
                stage,
                text,
            ))
        })
        .collect();
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

fn bench_compile(c: &mut Criterion) {
    let options = CompileOptions::default();
    let mut group = c.benchmark_group("compile");
    for (name, stage, text) in shaders() {
        group.throughput(Throughput::Bytes(text.len() as u64));
        group.bench_function(&name, |b| {
            b.iter(|| {
                let shader = compile(
                    SourceFile::new(name.as_str(), text.as_str()),
                    stage,
                    &options,
                );
                std::hint::black_box(shader.diagnostics.len())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_compile);
criterion_main!(benches);
