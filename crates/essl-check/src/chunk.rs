//! Chunks — code to put into shaders, checked as a library: the prelude a shader that
//! includes one has before it, and the codes a chunk does not report.

use essl::Stage;

use crate::assembly::Assembly;
use crate::settings::Settings;

/// The codes a chunk does not report: what the shader that includes it supplies (the names it
/// uses and declares elsewhere, `main`).
pub(crate) const FREE_IN_A_CHUNK: [&str; 4] = [
    "missing-main",
    "undeclared-identifier",
    "undeclared-function",
    "unknown-type",
];

/// A chunk with what a shader that includes it has before it, where it does not say: the
/// `#version` of the target (unless the chunk is written in GLSL ES 1.00), a float precision
/// in a fragment shader, and the macros its module defines for it.
pub(crate) fn chunk_prelude(
    source: Assembly,
    stage: Stage,
    settings: &Settings,
    defines: &[(String, String)],
) -> Assembly {
    if source.text().trim_start().starts_with("#version") {
        return source;
    }
    let mut prelude = String::new();
    if settings.compile.target == essl::Target::WebGl2 && !es100_idioms(source.text()) {
        prelude.push_str("#version 300 es\n");
    }
    if stage == Stage::Fragment {
        prelude.push_str("precision highp float;\n");
    }
    for (name, value) in defines {
        prelude.push_str(&format!("#define {name} {value}\n"));
    }
    let Some((f, at)) = source.map_span(essl::source::Span::empty(0)) else {
        return source;
    };
    let mut a = Assembly::default();
    let own = a.file_index(&source.files()[f as usize]);
    a.generated(&prelude, own, at.start as usize);
    a.extend_from(&source, 0..source.text().len());
    a
}

/// Whether a chunk is written in GLSL ES 1.00: it uses `attribute`, `varying`, `texture2D`
/// or `gl_FragColor`, and nothing only GLSL ES 3.00 has (`in`/`out` declarations, `layout`,
/// `texture(`).
fn es100_idioms(text: &str) -> bool {
    let word = |w: &str| {
        text.match_indices(w).any(|(i, _)| {
            let before = text[..i].chars().next_back();
            let after = text[i + w.len()..].chars().next();
            !before.is_some_and(|c| c.is_alphanumeric() || c == '_')
                && !after.is_some_and(|c| c.is_alphanumeric() || c == '_')
        })
    };
    let es100 = [
        "attribute",
        "varying",
        "texture2D",
        "textureCube",
        "gl_FragColor",
    ];
    let declares_300 = text.lines().any(|l| {
        let l = l.trim_start();
        ["in ", "out ", "flat ", "layout", "centroid "]
            .iter()
            .any(|p| l.starts_with(p))
    });
    es100.iter().any(|w| word(w))
        && !declares_300
        && !text.contains("texture(")
        && !text.contains("texelFetch")
}
