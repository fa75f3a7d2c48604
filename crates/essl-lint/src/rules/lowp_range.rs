//! `lowp` variables whose names say they hold lengths in pixels or world units: the range
//! `lowp` must hold is only (−2, 2) (GLSL ES 3.00 §4.5.2, 8 bits of relative precision), and
//! a line width, a blur, an offset, an atlas rectangle or a building's height leave it.
//!
//! GPUs that compute `lowp` as 16-bit floats hold such values; those that implement the
//! minimum (10-bit fixed point, as PowerVR's SGX parts did) clamp them to 2. The name is the
//! only evidence a declaration gives — an attribute's values are the host's — so the words are
//! those WebGL code gives such measures (MapLibre's `lowp float floorwidth`, `a_pattern_from`,
//! `halo_width`, and a sprite's `pixel_ratio_from`, 2 for an `@2x` image), and an
//! interpolation factor named after one (`u_width_t`, in [0, 1]) is left out.

use essl::diagnostic::Diagnostic;
use essl::source::Span;
use essl::types::{Precision, ScalarKind, Type};

use super::Cx;

/// Words a name ends with (`floorwidth`, `antialiasblur`) that say it holds a length.
const LENGTH: &[&str] = &[
    "width", "blur", "offset", "pattern", "height", "radius", "size", "gap", "distance",
];

/// Whether `name` says its value is a length: one of its words ends with a [`LENGTH`] word,
/// and its last word is not `t` (a factor that mixes two of them); or a pixel ratio (a sprite's
/// or the screen's: 2 or 3 on high-density displays, which (−2, 2) leaves out).
fn says_length(name: &str) -> bool {
    let words = crate::analysis::names::words(name);
    if words.last().is_some_and(|w| w == "t") {
        return false;
    }
    let has = |x: &str| words.iter().any(|w| w == x);
    words.iter().any(|w| LENGTH.iter().any(|l| w.ends_with(l))) || (has("pixel") && has("ratio"))
}

/// Whether the declaration of the name at `span` says `lowp` itself, on its line before the
/// name: a `precision lowp float;` default makes every variable `lowp`, a choice made once
/// for the whole shader rather than for a value that needs range.
fn declared_lowp(text: &str, span: Span) -> bool {
    declaration_before(text, span).is_some_and(|(_, d)| d.split_whitespace().any(|w| w == "lowp"))
}

/// The declaration of the name at `span`, on its line before the name (from the line's start or
/// the last `;` or `{` on it), with the offset where it starts; `None` past the text's end.
pub(super) fn declaration_before(text: &str, span: Span) -> Option<(usize, &str)> {
    let before = text.get(..span.start as usize)?;
    let start = before.rfind(['\n', ';', '{']).map_or(0, |i| i + 1);
    Some((start, &before[start..]))
}

/// The notes for every floating-point global or local declared `lowp` whose name says it
/// holds a length.
pub(super) fn check(cx: &Cx, rule: &'static str, out: &mut Vec<Diagnostic>) {
    let lowp_float = |ty: &Type, p: Option<Precision>| {
        p == Some(Precision::Low) && ty.scalar_kind() == Some(ScalarKind::Float)
    };
    let mut found: Vec<(&str, Span)> = Vec::new();
    for g in &cx.hir.globals {
        if g.used && lowp_float(&g.ty, g.precision) && says_length(&g.name) {
            found.push((&g.name, g.span));
        }
    }
    for f in &cx.hir.functions {
        for l in &f.locals {
            if lowp_float(&l.ty, l.precision) && says_length(&l.name) {
                found.push((&l.name, l.span));
            }
        }
    }
    for (name, span) in found {
        if span.is_empty() || !declared_lowp(cx.file.text(), span) {
            continue;
        }
        let d = Diagnostic::rule_note(
            rule,
            format!("`{name}` is `lowp`, which need only hold values in (-2, 2)"),
            span,
        )
        .with_label("a length in pixels or world units, declared `lowp`")
        .with_note("GLSL ES 3.00 §4.5.2: lowp's minimum range is (-2, 2) with 8 bits of relative precision; GPUs that implement the minimum clamp larger values")
        .with_help("declare it `mediump` (or `highp`)");
        out.push(d);
    }
}

#[cfg(test)]
mod tests {
    use super::says_length;

    #[test]
    fn lengths_by_name_but_not_their_mix_factors() {
        for n in [
            "floorwidth",
            "a_pattern_from",
            "halo_width",
            "antialiasblur",
            "u_lineatlas_width",
            "a_height",
            "pixel_ratio_from",
        ] {
            assert!(says_length(n), "{n}");
        }
        for n in [
            "u_width_t",
            "opacity",
            "color",
            "u_blur_t",
            "u_pixel_ratio_from_t",
            "v_gamma_scale",
        ] {
            assert!(!says_length(n), "{n}");
        }
    }
}
