//! `smoothstep-edges`: `smoothstep(e0, e1, x)` whose edges can be equal or swapped.

use essl::diagnostic::{Diagnostic, Fix};
use naga::{Expression as E, MathFunction as Mf};

use super::rule::declare_rule;
use super::{fmt_num, Cx};
use crate::value::Facts;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `smoothstep(edge0, edge1, x)` where the edges depend on uniforms and nothing in the
    /// shader keeps `edge0 < edge1` — `smoothstep(u_outerLimit, u_innerLimit, d)` — and calls whose
    /// constant edges are equal or in the wrong order. Edges the shader orders itself
    /// (`smoothstep(u_r, u_r + 0.1, d)`, `max(e1, e0 + 1e-3)`) are not reported.
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

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for (id, f) in cx.functions() {
        let sym = cx.sym(id, f);
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
            if span.is_empty() {
                continue;
            }
            let (e0, e1, x) = (
                cx.operand(f, h, arg),
                cx.operand(f, h, a1),
                cx.operand(f, h, a2),
            );
            let (Some(v0), Some(v1)) = (cx.sound.num(id, e0), cx.sound.num(id, e1)) else {
                continue;
            };
            let (s0, s1, sx) = (cx.span(f, e0), cx.span(f, e1), cx.span(f, x));
            let constant = |v: &crate::value::Num| v.comps().iter().all(|c| c.as_point().is_some());
            if constant(v0) && constant(v1) {
                let pairs: Vec<(f64, f64)> = (0..v0.n.max(v1.n) as usize)
                    .map(|i| {
                        (
                            v0.c[i.min(v0.n as usize - 1)].lo,
                            v1.c[i.min(v1.n as usize - 1)].lo,
                        )
                    })
                    .collect();
                if pairs.iter().all(|(a, b)| a < b) {
                    continue;
                }
                let equal = pairs.iter().any(|(a, b)| a == b);
                let msg = if equal {
                    "`smoothstep` edges are equal, where `smoothstep` is undefined"
                } else {
                    "`smoothstep` edges are swapped (edge0 > edge1), where `smoothstep` is undefined"
                };
                let mut d = Diagnostic::rule_warning(SmoothstepEdges::RULE.id, msg, span)
                    .with_label(if pairs.len() == 1 {
                        format!(
                            "edge0 = {}, edge1 = {}",
                            fmt_num(pairs[0].0),
                            fmt_num(pairs[0].1)
                        )
                    } else {
                        "edge0 >= edge1 in some component".to_string()
                    })
                    .with_note("GLSL ES 3.00 §8.3: smoothstep is undefined if edge0 >= edge1");
                if equal {
                    d = d.with_help(
                        "use `step(edge, x)` for a hard edge, or give the edges a width",
                    );
                } else {
                    d = d.with_help("mirror the call: `1.0 - smoothstep(edge1, edge0, x)`");
                    if pairs.iter().all(|(a, b)| a > b)
                        && !s0.is_empty()
                        && !s1.is_empty()
                        && !sx.is_empty()
                    {
                        let fixed = format!(
                            "(1.0 - smoothstep({}, {}, {}))",
                            cx.text(s1),
                            cx.text(s0),
                            cx.text(sx)
                        );
                        d = d.with_fix(Fix::suggested(
                            "mirror the call with the edges in order",
                            span,
                            fixed,
                        ));
                    }
                }
                out.push(d);
                continue;
            }
            let uniform = v0.facts.any(Facts::UNIFORM) || v1.facts.any(Facts::UNIFORM);
            if !uniform
                || sym.diff_lower(Some(e1), Some(e0)) > 0.0
                || cx.ordered(f, id, e0, e1, &cx.guards(f, id, h))
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
            if !s0.is_empty() && !s1.is_empty() && cx.pure(f, e0) {
                let fixed = format!("max({}, {} + {eps})", cx.text(s1), cx.text(s0));
                d = d.with_fix(Fix::suggested(
                    format!("keep edge1 at least {eps} above edge0"),
                    s1,
                    fixed,
                ));
            }
            out.push(d);
        }
    }
}
