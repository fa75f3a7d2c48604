//! Any bytes, as a vertex and as a fragment shader: the front end, the lowering (typed, as the
//! lints read it, and validated by naga, as a translation takes it) and the lints (with two of
//! the configurations its `#ifdef`s select) must not panic, and every diagnostic must point
//! inside the text.
#![no_main]

use essl::source::SourceFile;
use essl::{compile_front_end, Stage};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    for stage in [Stage::Vertex, Stage::Fragment] {
        // With and without a version line, so that most inputs get past the preprocessor.
        for src in [
            text.to_string(),
            format!("#version 300 es\nprecision mediump float;\n{text}"),
        ] {
            let len = src.len();
            let mut shader =
                compile_front_end(SourceFile::new("fuzz", src), stage, &Default::default());
            if shader.ok() {
                let _ = essl::lower::lower_shader(&shader, &Default::default());
            }
            shader.lower_typed();
            for d in &shader.diagnostics {
                assert!(d.span.end as usize <= len && d.span.start <= d.span.end);
            }
            let options = essl_lint::LintOptions::new();
            let found = essl_lint::lint(&shader, &options);
            let compile_options = essl::CompileOptions::default();
            for f in essl_lint::variants::lint_text(&shader, &compile_options, &options, &found, 2)
            {
                let d = f.diagnostic;
                assert!(d.span.end as usize <= len && d.span.start <= d.span.end);
            }
        }
    }
});
