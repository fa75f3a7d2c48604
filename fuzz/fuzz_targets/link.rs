//! Two shaders from one input (split at the first NUL): compile, link and lower the program.
#![no_main]

use essl::source::SourceFile;
use essl::{compile, Stage};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let (vs, fs) = text.split_once('\0').unwrap_or((&text, ""));
    let vs = compile(SourceFile::new("v", format!("#version 300 es\n{vs}")), Stage::Vertex, &Default::default());
    let fs = compile(SourceFile::new("f", format!("#version 300 es\nprecision mediump float;\n{fs}")), Stage::Fragment, &Default::default());
    let program = essl::link::link(&vs, &fs);
    if program.ok {
        let _ = essl::lower::lower_program(&vs, &fs, &program, &Default::default());
    }
});
