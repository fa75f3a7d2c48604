//! `smoothstep-edges`: `smoothstep(e0, e1, x)` whose edges can be equal or swapped.

use essl::diagnostic::{Diagnostic, Fix};
use essl::source::Span;
use naga::{Expression as E, Function, Handle, MathFunction as Mf};

use super::derivatives::from_derivative;
use super::rule::declare_rule;
use super::{fmt_num, Cx};
use crate::value::{Facts, Num};
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `smoothstep(edge0, edge1, x)` where nothing in the shader keeps `edge0 < edge1` for
    /// every input it ordinarily gets:
    ///
    /// - edges from uniforms set independently (`smoothstep(u_outerLimit, u_innerLimit, d)`);
    /// - edges the shader computes per pixel — from varyings, texels, dot products, and clamps of
    ///   those: `smoothstep(clamp(d - 0.3, 0.0, 1.0), clamp(d, 0.0, 1.0), t)` keeps `edge0 ≤ edge1`,
    ///   but both are 0 wherever `d ≤ 0` (the whole unlit side) and both 1 wherever `d ≥ 1.3`:
    ///   ordered is not apart;
    /// - edges `e, e + w` whose gap `w` is below the spacing of floats at their magnitude
    ///   (`smoothstep(r, r + 1e-8, d)` in `highp`, `r + 1e-4` in `mediump` for `r` near 2): equal
    ///   after rounding;
    /// - constant edges that are equal.
    ///
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
    ///   gap a constant or a parameter's value keeps positive (`clamp(d - 0.3, 0.0, 1.0)` and
    ///   `clamp(d, 0.0, 1.0) + 1e-3`: the clamps are ordered, the constant keeps them apart), or
    ///   an enclosing `if (u_a < u_b)`. A guard proves the order only of the edges it compares.
    /// - Edges `e ∓ w` whose width only an input or a parameter as such makes 0 (`buff ∓ gamma *
    ///   v_scale`, with `gamma` a constant over a uniform): a width of 0 is a value out of the
    ///   input's range, the caller's business, as for `sqrt(v_t)`. A uniform width (`t, t +
    ///   u_smoothWidth`) is a setting a user can set to 0, and is reported.
    /// - Constant edges in reversed order, or edges `r + w, r - w` with a constant `w > 0`: a
    ///   deliberate mirror, `smoothstep-reversed-constant`'s (a note). Equal constant edges are
    ///   reported here: they divide by zero.
    ///
    /// The antialiasing idiom, edges `e ∓ w` of a width computed from a derivative (`0.7 -
    /// fwidth(c), 0.7 + fwidth(c)`, in either order, an edge also kept in range by a constant:
    /// `max(0.0, r - w), r`; the width also a parameter every call passes one, Cesium's
    /// `getSDFColor(…, fwidth(distance))`), is a note: the edges are equal wherever the value differentiated is
    /// the same across the 2×2 pixel quad — whole flat faces under a directional light in
    /// three.js's toon shading, flat stretches of a field — where the specification leaves
    /// `smoothstep` undefined. Drivers that compute the formula give the exact step there, and NaN
    /// where `x` equals the edge; `max(fwidth(c), 1e-4)` makes it defined.
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard; a note, naming
    /// the uniform, when one uniform alone (with constants) does — the hazard then needs that value out
    /// of the range the shader was written for, and essl-gl's validation mode checks it at draw time
    /// (`smoothstep(cos(u_angle), 1.0, d)` needs `u_angle == 0`). Two uniforms a user sets
    /// independently (`u_outerLimit`, `u_innerLimit`; three.js's `coneCos` and `penumbraCos`, equal when
    /// the penumbra is 0, its default) give a warning, and so do edges computed per pixel; a width
    /// that is one input as such (`smoothstep(0.0, v_radius, d)`) gives a note naming it.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.3 Common Functions: smoothstep "Results are undefined if
    ///   edge0 >= edge1."
    /// - Article 001 (webgl2fundamentals, spot lights), its closing note on `smoothstep`.
    pub(crate) struct SmoothstepEdges {
        id: "smoothstep-edges",
        summary: "`smoothstep(e0, e1, x)` whose edges can be equal or swapped for ordinary inputs, or equal after rounding",
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
    cx.math_calls(Mf::SmoothStep)
        .into_iter()
        .filter(|c| c.args.len() == 3)
        .map(|c| Call {
            id: c.id,
            f: c.f,
            call: c.call,
            span: c.span,
            e0: c.args[0],
            e1: c.args[1],
            x: c.args[2],
        })
        .collect()
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

/// Whether the edges are in a fixed reversed order: constants with edge0 > edge1 in some
/// component and equal in none (a per-channel mirror: lygia's `smoothstep(vec3(3, 0, 3),
/// vec3(2, 2, 4), f)`), or edges the shader itself puts in that order (`smoothstep(r + w,
/// r - w, d)` with a constant `w > 0`): a deliberate mirror, `smoothstep-reversed-constant`'s
/// business.
pub(super) fn reversed(cx: &Cx, c: &Call) -> bool {
    match constant_edges(cx, c) {
        Some(pairs) => pairs.iter().all(|(a, b)| a != b) && pairs.iter().any(|(a, b)| a > b),
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
        if let Some(pairs) = constant_edges(cx, &c) {
            if !pairs.iter().all(|(a, b)| a < b) {
                out.push(equal_constants(&c, &pairs));
            }
            continue;
        }
        let sym = cx.sym(id, f);
        let low = [span, cx.span(f, c.e0), cx.span(f, c.e1)]
            .iter()
            .any(|s| cx.prec.is_low(*s));
        let gap = sym.diff_lower(Some(c.e1), Some(c.e0));
        if gap > 0.0 {
            // Ordered in exact arithmetic: equal only if the gap is below the edges' ulp.
            if let Some(d) = lost_gap(cx, &c, gap, low) {
                out.push(d);
            }
            continue;
        }
        if cx.ordered(f, id, c.e0, c.e1, &cx.guards(f, id, c.call)) {
            continue;
        }
        if derivative_width(cx, &c) {
            out.push(flat_quad(cx, &c));
            continue;
        }
        let single = single_input(cx, &c);
        if single.is_none() && input_width(cx, &c) {
            continue;
        }
        let per_pixel = Facts::INPUT.with(Facts::TEXTURE);
        let computed = v0.facts.any(per_pixel) || v1.facts.any(per_pixel);
        let message = if computed {
            "`smoothstep` edges can be equal or swapped for ordinary inputs, where `smoothstep` is undefined"
        } else {
            "`smoothstep` edges come from uniforms and can be equal or swapped, where `smoothstep` is undefined"
        };
        let d = Diagnostic::rule_warning(SmoothstepEdges::RULE.id, message, span)
            .with_label(if computed {
                "nothing keeps edge0 below edge1 for every input"
            } else {
                "undefined when edge0 >= edge1"
            })
            .with_note("GLSL ES 3.00 §8.3: smoothstep is undefined if edge0 >= edge1");
        let d = with_fix(cx, &c, d, low);
        out.push(match single {
            Some(name) => input_note(d, &name),
            None => cx.grade(d, &[(id, c.e0), (id, c.e1)]),
        });
    }
}

/// The note for the antialiasing idiom `e ∓ w` with `w` a derivative's width: both edges are `e`
/// wherever the value differentiated is the same across the 2×2 pixel quad (a flat face under a
/// directional light, a saturated texel, a constant stretch of a field) — whole regions, not
/// points. Drivers that compute the formula give an exact step there, and NaN where `x == e`.
fn flat_quad(cx: &Cx, c: &Call) -> Diagnostic {
    let d = Diagnostic::rule_warning(
        SmoothstepEdges::RULE.id,
        "`smoothstep` edges `e ∓ w` of a derivative's width are equal wherever the value differentiated is constant across the pixel quad, where `smoothstep` is undefined",
        c.span,
    )
    .with_label("w = 0 over flat regions: edge0 == edge1")
    .with_note("GLSL ES 3.00 §8.3: smoothstep is undefined if edge0 >= edge1; drivers that compute the formula give a hard step there, and NaN where x equals the edge")
    .with_help("keep the width above 0: `max(fwidth(x), 1e-4)`");
    let mut d = with_secondaries(cx, c, d);
    d.severity = essl::diagnostic::Severity::Note;
    d
}

/// The finding for constant edges that are equal in some component.
fn equal_constants(c: &Call, pairs: &[(f64, f64)]) -> Diagnostic {
    Diagnostic::rule_warning(
        SmoothstepEdges::RULE.id,
        "`smoothstep` edges are equal, where `smoothstep` is undefined",
        c.span,
    )
    .with_label(if pairs.len() == 1 {
        format!(
            "edge0 = {}, edge1 = {}",
            fmt_num(pairs[0].0),
            fmt_num(pairs[0].1)
        )
    } else {
        let (i, (a, _)) = pairs
            .iter()
            .enumerate()
            .find(|(_, (a, b))| a == b)
            .unwrap_or((0, &pairs[0]));
        format!(
            "edge0 = edge1 = {} in component `{}`",
            fmt_num(*a),
            ["x", "y", "z", "w"][i.min(3)]
        )
    })
    .with_note("GLSL ES 3.00 §8.3: smoothstep is undefined if edge0 >= edge1")
    .with_help("use `step(edge, x)` for a hard edge, or give the edges a width")
}

/// The edges' secondary labels, the help and the suggested fix `max(edge1, edge0 + eps)`.
fn with_fix(cx: &Cx, c: &Call, mut d: Diagnostic, low: bool) -> Diagnostic {
    let (s0, s1) = (cx.span(c.f, c.e0), cx.span(c.f, c.e1));
    let eps = if low { "1e-3" } else { "1e-4" };
    d = with_secondaries(
        cx,
        c,
        d.with_help(format!(
            "keep edge1 above edge0, e.g. `max(edge1, edge0 + {eps})`"
        )),
    );
    if !s0.is_empty() && !s1.is_empty() && cx.pure(c.f, c.e0) {
        let fixed = format!("max({}, {} + {eps})", cx.text(s1), cx.text(s0));
        d = d.with_fix(Fix::suggested(
            format!("keep edge1 at least {eps} above edge0"),
            s1,
            fixed,
        ));
    }
    d
}

/// `d` with the edges labelled.
fn with_secondaries(cx: &Cx, c: &Call, mut d: Diagnostic) -> Diagnostic {
    let (s0, s1) = (cx.span(c.f, c.e0), cx.span(c.f, c.e1));
    if !s0.is_empty() {
        d = d.with_secondary(s0, "edge0");
    }
    if !s1.is_empty() {
        d = d.with_secondary(s1, "edge1");
    }
    d
}

/// Edges `e0 < e1` in exact arithmetic whose gap is below the spacing of floats at their
/// magnitude (`smoothstep(r, r + 1e-4, d)` in `mediump` with `r` near 2): equal after
/// rounding. The magnitude is the edges' bound, or 1 for edges a uniform leaves unbounded
/// (edges are mostly cosines and distances in texture space).
fn lost_gap(cx: &Cx, c: &Call, gap: f64, low: bool) -> Option<Diagnostic> {
    let a = cx.sound();
    let m0 = a.num(c.id, c.e0)?.hull().mag();
    let m1 = a.num(c.id, c.e1)?.hull().mag();
    let m = match m0.max(m1) {
        m if m.is_finite() => m,
        _ => 1.0,
    };
    // The spacing of floats just below `m`: 2^-10 (mediump) or 2^-23 (highp) of its binade.
    let bits = if low { 10 } else { 23 };
    let binade = 2f64.powi(m.max(f64::MIN_POSITIVE).log2().floor() as i32);
    let ulp = binade * 2f64.powi(-bits);
    if m == 0.0 || gap >= ulp {
        return None;
    }
    let d = Diagnostic::rule_warning(
        SmoothstepEdges::RULE.id,
        "`smoothstep` edges differ by less than the spacing of floats at their magnitude: equal after rounding, where `smoothstep` is undefined",
        c.span,
    )
    .with_label(format!(
        "edge1 - edge0 = {} in exact arithmetic, below the {} spacing {} near {}",
        fmt_num(gap),
        if low { "mediump" } else { "highp" },
        fmt_num(ulp),
        fmt_num(m)
    ))
    .with_note("GLSL ES 3.00 §8.3: smoothstep is undefined if edge0 >= edge1");
    Some(with_fix(cx, c, d, low))
}

/// Whether the edges are `e ± w` of a width computed from a derivative (`0.7 - fwidth(c)`,
/// `0.7 + fwidth(c)`): the antialiasing idiom, whose edges meet only where `x` does not change
/// across the pixel, and there the step is exact.
fn derivative_width(cx: &Cx, c: &Call) -> bool {
    // `max(0.0, e - w)`: the edge kept in range is the same edge.
    let inner = |h: Handle<E>| match c.f.expressions[h] {
        E::Math {
            fun: Mf::Max | Mf::Min,
            arg,
            arg1: Some(b),
            ..
        } => {
            let constant = |x: Handle<E>| {
                cx.sound()
                    .num(c.id, x)
                    .is_some_and(|n| n.hull().as_point().is_some())
            };
            if constant(arg) {
                b
            } else if constant(b) {
                arg
            } else {
                h
            }
        }
        _ => h,
    };
    let (e0, e1) = (
        inner(crate::symbolic::resolve(c.f, cx.sound(), c.id, c.e0)),
        inner(crate::symbolic::resolve(c.f, cx.sound(), c.id, c.e1)),
    );
    width(cx, c, e0, e1).is_some_and(|w| from_derivative(cx, c.id, c.f, w))
}

/// The width `w` of edges `e0, e1` that are `e - w, e + w` (or, mirrored, `e + w, e - w`) for a
/// `w` the analysis keeps non-negative.
fn width(cx: &Cx, c: &Call, e0: Handle<E>, e1: Handle<E>) -> Option<Handle<E>> {
    let (c0, k, x) = cx.sym(c.id, c.f).single_term(e1, e0)?;
    ((c0 >= 0.0 && k > 0.0 || c0 <= 0.0 && k < 0.0)
        && cx
            .sound()
            .num(c.id, x)
            .is_some_and(|v| v.facts.has(Facts::NN)))
    .then_some(x)
}

/// Whether the edges are `e ∓ w` (`buff - gamma * scale`, `buff + gamma * scale`) of a
/// non-negative width that is 0 only where an input or parameter as such is 0
/// ([`zero_only_as_input`]): a width of 0 is then a value out of the input's range, which the
/// rules leave to the caller, as `sqrt(v_t)`.
fn input_width(cx: &Cx, c: &Call) -> bool {
    width(cx, c, c.e0, c.e1).is_some_and(|w| zero_only_as_input(cx, c.id, c.f, w, 0))
}

/// Whether `h` is 0 only where an input (an attribute, a varying) or a parameter as such is: one
/// of those (through locals, swizzles and `abs`), a non-zero constant, a product of such, a
/// quotient whose dividend is one (the divisor makes it larger, never 0), or a sum of
/// non-negative values one of which is such. A uniform is not: a width a user sets
/// (`luminosityThreshold + smoothWidth`) is 0 when they set it so, and stays reported.
fn zero_only_as_input(cx: &Cx, id: usize, f: &Function, h: Handle<E>, depth: u32) -> bool {
    use naga::BinaryOperator as Bo;
    if depth > 8 {
        return false;
    }
    let num = cx.sound().num(id, h);
    let nn = |x: Handle<E>| {
        cx.sound()
            .num(id, x)
            .is_some_and(|v| v.facts.has(Facts::NN))
    };
    let go = |x: Handle<E>| zero_only_as_input(cx, id, f, x, depth + 1);
    match f.expressions[h] {
        E::Literal(_) | E::Constant(_) => num.is_some_and(|v| !v.hull().contains(0.0)),
        E::FunctionArgument(_) => true,
        E::Load { pointer } if matches!(f.expressions[pointer], E::LocalVariable(_)) => {
            let values = cx.stored(f, id, pointer);
            !values.is_empty() && values.iter().all(|v| go(*v))
        }
        E::Load { .. } | E::AccessIndex { .. } | E::Swizzle { .. } => {
            num.is_some_and(|v| {
                v.facts.has(Facts::EXT) && !v.facts.any(Facts::TEXTURE.with(Facts::UNIFORM))
            }) || match f.expressions[h] {
                E::AccessIndex { base, .. } => go(base),
                E::Swizzle { vector, .. } => go(vector),
                _ => false,
            }
        }
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } => go(left) && go(right),
        E::Binary {
            op: Bo::Divide,
            left,
            ..
        } => go(left),
        E::Binary {
            op: Bo::Add,
            left,
            right,
        } => nn(left) && nn(right) && (go(left) || go(right)),
        E::Math {
            fun: Mf::Abs, arg, ..
        } => go(arg),
        _ => false,
    }
}

/// The one input whose value alone, up to a positive factor, is `edge1 - edge0`
/// (`smoothstep(0.0, v_radius, d)`): the hazard needs that input at 0 or below.
fn single_input(cx: &Cx, c: &Call) -> Option<String> {
    let (k0, k, x) = cx.sym(c.id, c.f).single_term(c.e1, c.e0)?;
    if k0 != 0.0 || k <= 0.0 {
        return None;
    }
    let v = cx.sound().num(c.id, x)?;
    if !v.facts.has(Facts::EXT) || v.facts.any(Facts::TEXTURE.with(Facts::UNIFORM)) {
        return None;
    }
    let o = cx.origin(&[(c.id, x)]);
    match (&o.inputs[..], o.uniforms.is_empty(), o.texels, o.unknown) {
        ([i], true, false, false) => Some(i.clone()),
        _ => None,
    }
}

/// Makes `d` a note naming the input that alone reaches it.
fn input_note(mut d: Diagnostic, name: &str) -> Diagnostic {
    d.severity = essl::diagnostic::Severity::Note;
    d.message = format!("{}, only when the input `{name}` is 0 or below", d.message);
    d
}
