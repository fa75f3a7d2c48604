//! Any bytes through the front end alone (preprocess, classify, parse, check), as written and
//! after an ES 3.00 version line, for the stage the first byte picks: no panic, and every
//! diagnostic points inside the text. Lowering, naga's validation and the lints are left to
//! `compile`, which costs many times more per input; this target explores the front end's
//! branches at a much higher rate.
#![no_main]

use essl::passes::{check_as, classify_as, lex, parse_as, preprocess, Language, PreprocessOptions};
use essl::source::SourceFile;
use essl::{Stage, Target};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let stage = if data.first().is_some_and(|b| b & 1 == 1) { Stage::Vertex } else { Stage::Fragment };
    for src in [text.to_string(), format!("#version 300 es\nprecision mediump float;\n{text}")] {
        let len = src.len();
        let file = SourceFile::new("fuzz", src);
        let options = PreprocessOptions {
            extensions: PreprocessOptions::extension_macros(Target::WebGl2, &[]),
            stage: Some(stage),
            ..PreprocessOptions::default()
        };
        let mut pp = preprocess(&file, lex(&file), &options);
        let lang = Language::of(&pp, Target::WebGl2, &[]);
        let mut diagnostics = std::mem::take(&mut pp.diagnostics);
        let tokens = classify_as(pp.tokens, &lang, &mut diagnostics);
        let (unit, found) = parse_as(&file, tokens, stage, &lang);
        diagnostics.extend(found);
        let (_, found) = check_as(&file, &unit, stage, pp.invariant_all, &lang);
        diagnostics.extend(found);
        for d in &diagnostics {
            assert!(d.span.end as usize <= len && d.span.start <= d.span.end);
        }
    }
});
