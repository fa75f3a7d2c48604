//! The `vs_naga` bench with mimalloc as the allocator of both sides: the allocator the CLI
//! and the editor server run essl with. Run with `cargo bench -p essl --bench vs_naga_mimalloc`.

use criterion::{criterion_group, criterion_main};

#[global_allocator]
static GLOBAL: essl_alloc::Allocator = essl_alloc::Allocator;

#[path = "common/vs_naga.rs"]
mod common;

criterion_group!(benches, common::bench);
criterion_main!(benches);
