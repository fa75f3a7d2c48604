//! Any bytes through the front end alone (`essl::compile_front_end`: preprocess, classify,
//! parse, check), as written and after an ES 3.00 version line, for the stage the first byte
//! picks: no panic, and every diagnostic points inside the text. Lowering, naga's validation
//! and the lints are left to `compile`, which costs more per input; this target explores the
//! front end's branches at a higher rate.
#![no_main]

use essl::source::SourceFile;
use essl::{compile_front_end, Stage};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let stage = if data.first().is_some_and(|b| b & 1 == 1) { Stage::Vertex } else { Stage::Fragment };
    for src in [text.to_string(), format!("#version 300 es\nprecision mediump float;\n{text}")] {
        let len = src.len();
        let shader = compile_front_end(SourceFile::new("fuzz", src), stage, &Default::default());
        for d in &shader.diagnostics {
            assert!(d.span.end as usize <= len && d.span.start <= d.span.end);
        }
    }
});
