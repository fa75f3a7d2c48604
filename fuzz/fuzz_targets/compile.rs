//! Any bytes, as a vertex and as a fragment shader: the front end, the lowering (typed, as the
//! lints read it, and validated by naga, as a translation takes it) and the lints (with two of
//! the configurations its `#ifdef`s select) must not panic, and every diagnostic must point
//! inside the text; a shader the lint screen leaves unlowered must get the same findings
//! lowered.
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
            let options = essl_lint::LintOptions::new().notes(true);
            // As the pipeline lints: lowered where the screen says a rule on the IR may look.
            // Where it says none may, lowering must change no finding.
            let screened = essl_lint::needs_ir(&shader);
            let unlowered = (!screened).then(|| essl_lint::lint(&shader, &options));
            shader.lower_typed();
            for d in &shader.diagnostics {
                assert!(d.span.end as usize <= len && d.span.start <= d.span.end);
            }
            let found = essl_lint::lint(&shader, &options);
            if let Some(before) = unlowered {
                let key = |d: &essl::diagnostic::Diagnostic| (d.code, d.span);
                assert_eq!(
                    before.iter().map(key).collect::<Vec<_>>(),
                    found.iter().map(key).collect::<Vec<_>>(),
                    "the lint screen missed what a rule on the IR found"
                );
            }
            let compile_options = essl::CompileOptions::default();
            for f in essl_lint::variants::lint_text(&shader, &compile_options, &options, &found, 2)
            {
                let d = f.diagnostic;
                assert!(d.span.end as usize <= len && d.span.start <= d.span.end);
            }
        }
    }
});
