//! `clamp-bounds`: `clamp(x, minVal, maxVal)` whose `minVal` exceeds `maxVal` — constant bounds
//! in reversed order, or the value and the bounds passed in the wrong order
//! (`clamp(0.0, 1.0, v)`).
//!
//! Both shapes are told apart from the rest without the value analysis ([`suspect`]): two
//! constants before a value that is not one, or two constant bounds in reversed order.
//! `clamp(x, 0.0, 1.0)` is in nearly every shader, and only these two shapes make the analysis
//! run for this rule.

use essl::diagnostic::{Diagnostic, Fix};
use naga::{Expression as E, Function, Handle, MathFunction as Mf};

use super::rule::declare_rule;
use super::{fmt_num, Cx};
use crate::analysis::literal;
use crate::value::Num;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `clamp(x, minVal, maxVal)` where `minVal > maxVal` is reached:
    ///
    /// - constant bounds in reversed order (`clamp(x, 1.0, 0.0)`), in any component;
    /// - two constants with the value after them (`clamp(0.0, 1.0, v)`): the arguments of
    ///   `clamp(v, 0.0, 1.0)` in the wrong order. `minVal` is then 1.0 and `maxVal` is `v`,
    ///   reversed for every `v < 1`. It is reported where `v` can be below the constant: a
    ///   varying, a texel, `float(gl_FrontFacing)`, a computed value, a uniform.
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 and 1.00 leave `clamp` undefined if `minVal > maxVal` (§8.3), and so do
    /// SPIR-V's `FClamp` and Metal's `clamp`, which ANGLE translates WebGL to. Drivers that
    /// evaluate `min(max(x, minVal), maxVal)` return `maxVal`; those that evaluate
    /// `max(min(x, maxVal), minVal)` return `minVal`; a median-of-three instruction returns
    /// the middle value. `clamp(0.0, 1.0, float(gl_FrontFacing))` is then 0 or 1 on back faces
    /// depending on the GPU, and `col *= clamp(0.3, 1.0, 1.05 - size * darken)` darkens on one
    /// driver and does nothing on another.
    ///
    /// ## Example
    /// ```glsl
    /// float isFrontFace = clamp(0.0, 1.0, float(gl_FrontFacing));
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float isFrontFace = clamp(float(gl_FrontFacing), 0.0, 1.0);
    /// ```
    /// The suggested fix puts the arguments in order — the value first, then the constants in
    /// increasing order — or swaps reversed constant bounds. It is the call the author meant; on a
    /// driver that evaluated the reversed call as `min(max(x, minVal), maxVal)` its values differ
    /// where `v` was below the smaller constant.
    ///
    /// ## What it does not flag
    /// - Bounds that are not both constants when the value is not one (`clamp(x, 0.0, u_max)`,
    ///   `clamp(x, lo, hi)` of computed bounds): their order is the shader's and the host's. So
    ///   is a constant clamped between two values (`clamp(0.5, lo, hi)`, dEQP's tests of
    ///   `clamp`).
    /// - A constant value with bounds that can never be reversed (`clamp(0.5, 0.0, 1.0 + v *
    ///   v)`: `maxVal ≥ 1 > 0`).
    /// - Equal constant bounds (`clamp(x, 0.5, 0.5)`): defined, it is the constant.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.3 Common Functions: clamp "Returns min(max(x, minVal),
    ///   maxVal). Results are undefined if minVal > maxVal."
    /// - GLSL ES 1.00 specification, §8.3 Common Functions (the same words).
    /// - SPIR-V Extended Instructions for GLSL, `FClamp`, `SClamp`, `UClamp`: "the resulting value
    ///   is undefined if minVal > maxVal."
    pub(crate) struct ClampBounds {
        id: "clamp-bounds",
        summary: "`clamp(x, minVal, maxVal)` with `minVal > maxVal`: reversed constant bounds, or the value and bounds in the wrong order",
        default_level: Level::Warn,
        check: check,
    }
}

/// The values of a constant expression of `f` in the source's own terms: a literal, a splat or a
/// composition of literals, or a named constant of such.
fn constant(module: &naga::Module, f: &Function, h: Handle<E>) -> Option<Vec<f64>> {
    fn of(
        arena: &naga::Arena<E>,
        module: &naga::Module,
        h: Handle<E>,
        depth: u8,
    ) -> Option<Vec<f64>> {
        if depth > 8 {
            return None;
        }
        match &arena[h] {
            E::Literal(l) => Some(vec![literal(l)]),
            E::Splat { value, .. } => of(arena, module, *value, depth + 1),
            E::Compose { components, .. } => {
                let mut out = Vec::new();
                for c in components {
                    out.extend(of(arena, module, *c, depth + 1)?);
                }
                Some(out)
            }
            E::Constant(c) => of(
                &module.global_expressions,
                module,
                module.constants[*c].init,
                depth + 1,
            ),
            _ => None,
        }
    }
    of(&f.expressions, module, h, 0)
}

/// Component `i` of a constant (a scalar stands for every component).
fn pick(v: &[f64], i: usize) -> f64 {
    v[i.min(v.len() - 1)]
}

/// Whether constant bounds are reversed in some component.
fn reversed(lo: &[f64], hi: &[f64]) -> bool {
    (0..lo.len().max(hi.len())).any(|i| pick(lo, i) > pick(hi, i))
}

/// The two shapes of `clamp(x, minVal, maxVal)` this rule looks at, read from the IR alone.
enum Shape {
    /// Constant bounds, reversed in some component: (minVal, maxVal).
    Reversed(Vec<f64>, Vec<f64>),
    /// `clamp(c0, c1, v)`: a constant value and a constant lower bound before a value that is
    /// not constant, (c0, c1).
    Swapped(Vec<f64>, Vec<f64>),
}

/// The shape of `clamp(x, lo, hi)`, if it is one this rule looks at.
fn shape(
    module: &naga::Module,
    f: &Function,
    x: Handle<E>,
    lo: Handle<E>,
    hi: Handle<E>,
) -> Option<Shape> {
    match (
        constant(module, f, x),
        constant(module, f, lo),
        constant(module, f, hi),
    ) {
        (_, Some(l), Some(h)) => reversed(&l, &h).then_some(Shape::Reversed(l, h)),
        (Some(c), Some(l), None) => Some(Shape::Swapped(c, l)),
        _ => None,
    }
}

/// Whether a `clamp` is of a shape this rule looks at (a constant value and a constant lower
/// bound before a value that is not constant, or constant bounds in reversed order), read from
/// the IR alone: the rule needs the value analysis only then.
pub(super) fn suspect(module: &naga::Module, f: &Function, e: &E) -> bool {
    match *e {
        E::Math {
            fun: Mf::Clamp,
            arg,
            arg1: Some(lo),
            arg2: Some(hi),
            ..
        } => shape(module, f, arg, lo, hi).is_some(),
        _ => false,
    }
}

/// Whether `lo > hi` is reachable in some component of the two values.
fn can_reverse(lo: &Num, hi: &Num) -> bool {
    let n = lo.n.max(hi.n) as usize;
    (0..n).any(|i| {
        let (l, h) = (
            lo.c[i.min(lo.n as usize - 1)],
            hi.c[i.min(hi.n as usize - 1)],
        );
        !l.is_empty() && !h.is_empty() && l.hi > h.lo
    })
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for c in cx.math_calls(Mf::Clamp) {
        let (id, f, h, span) = (c.id, c.f, c.call, c.span);
        let [x, lo, hi] = c.args[..] else {
            continue;
        };
        let Some(shape) = shape(cx.module, f, x, lo, hi) else {
            continue;
        };
        let text = |h: Handle<E>| {
            let s = cx.span(f, h);
            (!s.is_empty() && s != span).then(|| cx.text(s))
        };
        let d = match shape {
            Shape::Reversed(l, hv) => {
                let label = if l.len() == 1 && hv.len() == 1 {
                    format!("minVal = {}, maxVal = {}", fmt_num(l[0]), fmt_num(hv[0]))
                } else {
                    "minVal > maxVal in some component".to_string()
                };
                let d = Diagnostic::rule_warning(
                        ClampBounds::RULE.id,
                        "`clamp` bounds are in reversed order (minVal > maxVal): undefined, and drivers disagree on the result",
                        span,
                    )
                    .with_label(label)
                    .with_help("swap the bounds: `clamp(x, maxVal, minVal)`");
                match (text(x), text(lo), text(hi)) {
                    (Some(tx), Some(tl), Some(th)) => d.with_fix(Fix::suggested(
                        "swap the bounds",
                        span,
                        format!("clamp({tx}, {th}, {tl})"),
                    )),
                    _ => d,
                }
            }
            Shape::Swapped(value, l) => {
                let g = cx.guards(f, id, h);
                let (Some(vl), Some(vh)) = (cx.refined(f, id, lo, &g), cx.refined(f, id, hi, &g))
                else {
                    continue;
                };
                if !can_reverse(&vl, &vh) {
                    continue;
                }
                let low = vh.hull().lo;
                let label = match l[..] {
                    [l] if low.is_finite() => format!(
                        "minVal is {}, and maxVal can be as low as {}",
                        fmt_num(l),
                        fmt_num(low)
                    ),
                    [l] => format!("minVal is {}, and maxVal can be below it", fmt_num(l)),
                    _ => "minVal can exceed maxVal".to_string(),
                };
                let d = Diagnostic::rule_warning(
                        ClampBounds::RULE.id,
                        "`clamp` of a constant with the value among the bounds: the arguments look swapped, and minVal > maxVal is undefined",
                        span,
                    )
                    .with_label(label)
                    .with_help("`clamp` takes the value first, then the bounds: `clamp(x, minVal, maxVal)`");
                // `clamp(c0, c1, v)` with `c0 <= c1`: the call meant is `clamp(v, c0, c1)`.
                match (text(x), text(lo), text(hi)) {
                    (Some(tx), Some(tl), Some(th)) if !reversed(&value, &l) => {
                        d.with_fix(Fix::suggested(
                            "put the value first",
                            span,
                            format!("clamp({th}, {tx}, {tl})"),
                        ))
                    }
                    _ => d,
                }
            }
        };
        out.push(d.with_note(
                "GLSL ES 3.00 §8.3: clamp returns min(max(x, minVal), maxVal), undefined if minVal > maxVal",
            ));
    }
}
