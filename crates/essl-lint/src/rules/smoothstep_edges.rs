//! `smoothstep-edges`: `smoothstep(e0, e1, x)` whose edges can be equal or swapped.

use essl::diagnostic::{Diagnostic, Fix};
use essl::source::Span;
use naga::{Expression as E, Function, Handle, MathFunction as Mf};

use super::rule::declare_rule;
use super::{fmt_num, Cx};
use crate::value::{Facts, Num};
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `smoothstep(edge0, edge1, x)` where the edges are per-draw values computed from
    /// uniforms and nothing in the shader keeps `edge0 < edge1` —
    /// `smoothstep(u_outerLimit, u_innerLimit, d)` — and calls whose constant edges are equal.
    /// Edges the shader orders itself (`smoothstep(u_r, u_r + 0.1, d)`, `max(e1, e0 + 1e-3)`) are
    /// not reported; constant edges in reversed order are `smoothstep-reversed-constant`'s.
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves `smoothstep` undefined if `edge0 ≥ edge1` (§8.3). GPUs evaluate
    /// `t = clamp((x - edge0) / (edge1 - edge0), 0, 1)`: equal edges divide by zero, and where
    /// `x == edge0` the result is NaN; the spot light of article 001 gets a hard, speckled edge the
    /// moment a user sets the inner limit equal to the outer one. The article notes it — "the
    /// `smoothstep` function has undefined results if the `lowerBound` is greater than or equal to
    /// `upperBound`" — and leaves it to JavaScript to avoid.
    ///
    /// ## Example
    /// ```glsl
    /// float inLight = smoothstep(u_outerLimit, u_innerLimit, dotFromDirection);
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float inLight = smoothstep(u_outerLimit, max(u_innerLimit, u_outerLimit + 1e-3), dotFromDirection);
    /// ```
    /// The suggested fix keeps `edge1` above `edge0` by 1e-3 in `mediump`/`lowp` (more than a
    /// `mediump` ulp for edges in `[-2, 2]`) and 1e-4 in `highp`. Constant edges in the wrong order
    /// are fixed by mirroring: `smoothstep(1.0, 0.0, x)` is `1.0 - smoothstep(0.0, 1.0, x)`.
    ///
    /// ## What it does not flag
    /// - Edges the shader orders itself: `smoothstep(u_r, u_r + 0.1, d)`, `max(e1, e0 + 1e-3)`, a
    ///   clamp of one edge above the other, or an enclosing `if (u_a < u_b)`.
    /// - Edges with a per-pixel part (`0.7 - fwidth(c), 0.7 + fwidth(c)`): equal at isolated
    ///   pixels at most, where `x` is exactly the edge.
    /// - Constant edges in reversed order: a deliberate mirror, `smoothstep-reversed-constant`'s (a
    ///   note). Equal constant edges are reported here: they divide by zero.
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard; a note, naming
    /// the uniform, when one uniform alone (with constants) does — the hazard then needs that value out
    /// of the range the shader was written for, and essl-gl's validation mode checks it at draw time. (`smoothstep(cos(u_angle), 1.0, d)` needs `u_angle == 0`). Two uniforms a user sets
    /// independently (`u_outerLimit`, `u_innerLimit`; three.js's `coneCos` and `penumbraCos`, equal when
    /// the penumbra is 0, its default) give a warning.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.3 Common Functions: smoothstep "Results are undefined if
    ///   edge0 >= edge1."
    /// - Article 001 (webgl2fundamentals, spot lights), its closing note on `smoothstep`.
    pub(crate) struct SmoothstepEdges {
        id: "smoothstep-edges",
        summary: "`smoothstep(e0, e1, x)` whose edges come from uniforms and can be equal or swapped",
        default_level: Level::Warn,
        check: check,
    }
}

/// A `smoothstep(edge0, edge1, x)` call with a span in the source.
pub(super) struct Call<'a> {
    pub id: usize,
    pub f: &'a Function,
    pub call: Handle<E>,
    pub span: Span,
    pub e0: Handle<E>,
    pub e1: Handle<E>,
    pub x: Handle<E>,
}

/// Every `smoothstep` call of the user's functions.
pub(super) fn calls<'a>(cx: &Cx<'a>) -> Vec<Call<'a>> {
    let mut out = Vec::new();
    for (id, f) in cx.functions() {
        for (h, e) in f.expressions.iter() {
            let E::Math {
                fun: Mf::SmoothStep,
                arg,
                arg1: Some(a1),
                arg2: Some(a2),
                ..
            } = *e
            else {
                continue;
            };
            let span = cx.span(f, h);
            if !span.is_empty() {
                out.push(Call {
                    id,
                    f,
                    call: h,
                    span,
                    e0: cx.operand(f, h, arg),
                    e1: cx.operand(f, h, a1),
                    x: cx.operand(f, h, a2),
                });
            }
        }
    }
    out
}

/// The (edge0, edge1) pairs of each component when both edges are constants.
pub(super) fn constant_edges(cx: &Cx, c: &Call) -> Option<Vec<(f64, f64)>> {
    let (v0, v1) = (cx.sound().num(c.id, c.e0)?, cx.sound().num(c.id, c.e1)?);
    let constant = |v: &Num| v.comps().iter().all(|c| c.as_point().is_some());
    if !constant(v0) || !constant(v1) {
        return None;
    }
    let pick = |v: &Num, i: usize| v.c[i.min(v.n as usize - 1)].lo;
    Some(
        (0..v0.n.max(v1.n) as usize)
            .map(|i| (pick(v0, i), pick(v1, i)))
            .collect(),
    )
}

/// Whether the edges are in a fixed reversed order: constants with edge0 > edge1 in every
/// component, or edges the shader itself puts in that order (`smoothstep(r + w, r - w, d)`
/// with a constant `w > 0`): a deliberate mirror, `smoothstep-reversed-constant`'s business.
pub(super) fn reversed(cx: &Cx, c: &Call) -> bool {
    match constant_edges(cx, c) {
        Some(pairs) => pairs.iter().all(|(a, b)| a > b),
        None => cx.sym(c.id, c.f).diff_lower(Some(c.e0), Some(c.e1)) > 0.0,
    }
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for c in calls(cx) {
        if reversed(cx, &c) {
            continue;
        }
        let (id, f, span) = (c.id, c.f, c.span);
        let (Some(v0), Some(v1)) = (cx.sound().num(id, c.e0), cx.sound().num(id, c.e1)) else {
            continue;
        };
        let (s0, s1) = (cx.span(f, c.e0), cx.span(f, c.e1));
        if let Some(pairs) = constant_edges(cx, &c) {
            if pairs.iter().all(|(a, b)| a < b) {
                continue;
            }
            out.push(
                Diagnostic::rule_warning(
                    SmoothstepEdges::RULE.id,
                    "`smoothstep` edges are equal, where `smoothstep` is undefined",
                    span,
                )
                .with_label(if pairs.len() == 1 {
                    format!(
                        "edge0 = {}, edge1 = {}",
                        fmt_num(pairs[0].0),
                        fmt_num(pairs[0].1)
                    )
                } else {
                    "edge0 >= edge1 in some component".to_string()
                })
                .with_note("GLSL ES 3.00 §8.3: smoothstep is undefined if edge0 >= edge1")
                .with_help("use `step(edge, x)` for a hard edge, or give the edges a width"),
            );
            continue;
        }
        let uniform = v0.facts.any(Facts::UNIFORM) || v1.facts.any(Facts::UNIFORM);
        let per_pixel = Facts::INPUT.with(Facts::TEXTURE);
        if !uniform
            || v0.facts.any(per_pixel)
            || v1.facts.any(per_pixel)
            || cx.sym(id, f).diff_lower(Some(c.e1), Some(c.e0)) > 0.0
            || cx.ordered(f, id, c.e0, c.e1, &cx.guards(f, id, c.call))
        {
            continue;
        }
        let low = cx.prec.is_low(span) || cx.prec.is_low(s0) || cx.prec.is_low(s1);
        let eps = if low { "1e-3" } else { "1e-4" };
        let mut d = Diagnostic::rule_warning(SmoothstepEdges::RULE.id, "`smoothstep` edges come from uniforms and can be equal or swapped, where `smoothstep` is undefined", span)
            .with_label("undefined when edge0 >= edge1")
            .with_note("GLSL ES 3.00 §8.3: smoothstep is undefined if edge0 >= edge1")
            .with_help(format!("keep edge1 above edge0, e.g. `max(edge1, edge0 + {eps})`"));
        if !s0.is_empty() {
            d = d.with_secondary(s0, "edge0");
        }
        if !s1.is_empty() {
            d = d.with_secondary(s1, "edge1");
        }
        if !s0.is_empty() && !s1.is_empty() && cx.pure(f, c.e0) {
            let fixed = format!("max({}, {} + {eps})", cx.text(s1), cx.text(s0));
            d = d.with_fix(Fix::suggested(
                format!("keep edge1 at least {eps} above edge0"),
                s1,
                fixed,
            ));
        }
        out.push(cx.grade(d, &[(id, c.e0), (id, c.e1)]));
    }
}
