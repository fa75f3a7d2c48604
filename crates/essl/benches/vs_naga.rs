//! essl's compile (preprocess through naga validation) against naga's own GLSL front end
//! (parse + validate), on the shaders both accept: the WebGL ES 3.00 conformance must-pass
//! cases whose two shaders naga parses once `#version 300 es` is rewritten to
//! `#version 450 core` (naga reads no GLSL ES; `docs/frontend.md`). essl compiles the original
//! text. One iteration runs all of them.
//!
//! Needs the corpus (`$ESSL_CORPORA` or `../shared/corpora/webgl_conformance_es300.jsonl`).
//! Run with `cargo bench -p essl --bench vs_naga`.
//! Both sides run on the system allocator; `vs_naga_mimalloc` runs the same with mimalloc.

use criterion::{criterion_group, criterion_main};

#[path = "common/vs_naga.rs"]
mod common;

criterion_group!(benches, common::bench);
criterion_main!(benches);
