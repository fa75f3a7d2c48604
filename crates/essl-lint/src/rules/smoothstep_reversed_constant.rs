//! `smoothstep-reversed-constant`: `smoothstep(e0, e1, x)` with edges in a fixed reversed order.

use essl::diagnostic::{Diagnostic, Fix};

use super::rule::declare_rule;
use super::smoothstep_edges::{calls, constant_edges, reversed};
use super::{fmt_num, Cx};
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `smoothstep(edge0, edge1, x)` whose edges are in a fixed reversed order: constants
    /// with `edge0 > edge1` (`smoothstep(0.1, 0.0, d)`; in some components of a vector and equal
    /// in none: a per-channel mirror), or edges the shader itself puts in that
    /// order (`smoothstep(r + w, r - w, d)` with a constant `w > 0`). It is a note by default:
    /// `essl lint --show-notes` prints it, an editor shows it.
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves `smoothstep` undefined if `edge0 ≥ edge1` (§8.3). In practice every
    /// driver evaluates `t = clamp((x - edge0) / (edge1 - edge0), 0, 1)` for reversed edges too,
    /// which gives the mirrored curve, falling from 1 to 0 — and shaders use it on purpose for a
    /// fade-out or an anti-aliased disc. It is a portability note, not a hazard: unlike edges that
    /// can become equal (`smoothstep-edges`), the divisor is never 0.
    ///
    /// ## Example
    /// ```glsl
    /// float a = smoothstep(0.25, 0.24, dot(d, d));   // 1 inside the disc, 0 outside
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float a = 1.0 - smoothstep(0.24, 0.25, dot(d, d));
    /// ```
    /// The suggested fix mirrors the call (the same values on every driver that computes the
    /// reversed curve, and defined by the specification).
    ///
    /// ## What it does not flag
    /// - Edges in order, and edges that can become equal or swap depending on uniforms: those are
    ///   `smoothstep-edges`' findings (equal constant edges too: they divide by zero).
    /// - Edges whose order the shader does not fix (`smoothstep(a, b, x)` of two computed values).
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.3 Common Functions: smoothstep "Results are undefined if
    ///   edge0 >= edge1."
    pub(crate) struct SmoothstepReversedConstant {
        id: "smoothstep-reversed-constant",
        summary: "`smoothstep(e0, e1, x)` with edges in a fixed reversed order: a deliberate mirror the specification leaves undefined",
        default_level: Level::Note,
        check: check,
    }
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for c in calls(cx) {
        if !reversed(cx, &c) {
            continue;
        }
        let (s0, s1, sx) = (cx.span(c.f, c.e0), cx.span(c.f, c.e1), cx.span(c.f, c.x));
        let pairs = constant_edges(cx, &c);
        let label = match pairs.as_deref() {
            Some([(a, b)]) => format!("edge0 = {}, edge1 = {}", fmt_num(*a), fmt_num(*b)),
            _ => "edge0 > edge1".to_string(),
        };
        // Some components reversed, others in order: mirroring the call would reverse those.
        let mixed: Vec<&str> = pairs
            .iter()
            .flatten()
            .enumerate()
            .filter(|(_, (a, b))| a > b)
            .map(|(i, _)| ["x", "y", "z", "w"][i.min(3)])
            .collect();
        if pairs.as_ref().is_some_and(|p| mixed.len() < p.len()) {
            out.push(
                Diagnostic::rule_warning(
                    SmoothstepReversedConstant::RULE.id,
                    "`smoothstep` edges are in reversed order in some components: undefined by the specification, though drivers compute the mirrored curve there",
                    c.span,
                )
                .with_label(format!("edge0 > edge1 in `{}`", mixed.join("`, `")))
                .with_note("GLSL ES 3.00 §8.3: smoothstep is undefined if edge0 >= edge1")
                .with_help("put each component's edges in order and mirror those components with `1.0 - smoothstep(…)`"),
            );
            continue;
        }
        let mut d = Diagnostic::rule_warning(
            SmoothstepReversedConstant::RULE.id,
            "`smoothstep` edges are in reversed order (edge0 > edge1): undefined by the specification, though drivers compute the mirrored curve",
            c.span,
        )
        .with_label(label)
        .with_note("GLSL ES 3.00 §8.3: smoothstep is undefined if edge0 >= edge1")
        .with_help("mirror the call: `1.0 - smoothstep(edge1, edge0, x)`");
        if !s0.is_empty() && !s1.is_empty() && !sx.is_empty() {
            let fixed = format!(
                "(1.0 - smoothstep({}, {}, {}))",
                cx.text(s1),
                cx.text(s0),
                cx.text(sx)
            );
            d = d.with_fix(Fix::suggested(
                "mirror the call with the edges in order",
                c.span,
                fixed,
            ));
        }
        out.push(d);
    }
}
