//! Values computed from screen-space derivatives (`dFdx`, `dFdy`, `fwidth`): 0 wherever the
//! value differentiated is the same across the 2×2 pixel quad — a coordinate along a flat face's
//! normal (the `y` of a ground plane), a shading term constant over a face under a directional
//! light, a saturated stretch of a distance field. `smoothstep-edges` reports the antialiasing
//! idiom's edges `e ∓ w` of such a width, equal there; `division-by-difference` a division by one
//! (`d / fwidth(d)`, a grid line's `fract(x) / length(vec2(dFdx(x), dFdy(x)))`).

use essl::diagnostic::{Diagnostic, Fix, Severity};
use essl::source::Span;
use naga::{Expression as E, Function, Handle};

use super::Cx;
use crate::value::{Facts, Num};

/// Whether `h` is computed from a `dFdx`, `dFdy` or `fwidth` (through locals whose every value,
/// initializer and stores, is: [`Cx::stored`]; and parameters every call passes one: Cesium's
/// `getSDFColor(…, smoothing)` of `smoothing = fwidth(distance)`). A local that a store
/// computes from itself (`w = max(w, cap)`) is derived where its other values are; one that
/// only its own stores compute (a loop counter's `i + 1`) is not.
pub(super) fn from_derivative(cx: &Cx, id: usize, f: &Function, h: Handle<E>) -> bool {
    derived(cx, id, f, h, &mut Walk::new(false)) == Derived::Yes
}

/// Whether `h` is 0 wherever a derivative it is made of is: `fwidth(x)`, `dFdx(x)`, a component
/// of one, `length(vec2(dFdx(x), dFdy(x)))`, `abs(dFdx(x)) + abs(dFdy(x))`, the larger or
/// smaller of one and another value, any of them times or over another value (through locals
/// and parameters, as [`from_derivative`]). Not the length of a vector's derivative
/// (`length(dFdx(p))`, 0 only where all of `p` is the same across the quad: a position on a
/// surface never is), nor a value only computed from a derivative (`fract(log2(w))`).
pub(super) fn derivative_width(cx: &Cx, id: usize, f: &Function, h: Handle<E>) -> bool {
    derived(cx, id, f, h, &mut Walk::new(true)) == Derived::Yes
}

/// What [`derived`] finds: computed from a derivative, or only from the variables whose values
/// are being looked at (which decide), or not.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Derived {
    Yes,
    Cycle,
    No,
}

/// Every one of `all` derived (a cycle among them decided by the others): `Yes` where one is and
/// none is not.
fn every(all: impl Iterator<Item = Derived>) -> Derived {
    let mut out = Derived::Cycle;
    for d in all {
        match d {
            Derived::No => return Derived::No,
            Derived::Yes => out = Derived::Yes,
            Derived::Cycle => {}
        }
    }
    out
}

/// Some one of `any` derived; else a cycle where one is.
fn some(any: impl Iterator<Item = Derived>) -> Derived {
    let mut out = Derived::No;
    for d in any {
        match d {
            Derived::Yes => return Derived::Yes,
            Derived::Cycle => out = Derived::Cycle,
            Derived::No => {}
        }
    }
    out
}

/// A walk of [`derived`]: the variables whose values are being looked at, (function, local); and
/// whether it asks for a width ([`derivative_width`]) rather than any use of a derivative.
struct Walk {
    path: Vec<(usize, usize)>,
    width: bool,
}

impl Walk {
    fn new(width: bool) -> Walk {
        Walk {
            path: Vec::new(),
            width,
        }
    }
}

fn derived(cx: &Cx, id: usize, f: &Function, h: Handle<E>, path: &mut Walk) -> Derived {
    if path.path.len() > 8 {
        return Derived::No;
    }
    match &f.expressions[h] {
        E::Derivative { .. } => Derived::Yes,
        E::FunctionArgument(i) if id < cx.module.functions.len() => {
            let callers = cx.flows().callers(id);
            if callers.is_empty() {
                return Derived::No;
            }
            every(callers.iter().map(|(caller, args)| {
                let g = crate::analysis::function(cx.module, *caller);
                args.get(*i as usize)
                    .map_or(Derived::No, |&a| derived(cx, *caller, g, a, path))
            }))
        }
        E::Load { pointer } => {
            // Each use of a local names it with an expression of its own: the variable is the
            // key.
            let E::LocalVariable(l) = f.expressions[*pointer] else {
                return Derived::No;
            };
            let key = (id, l.index());
            if path.path.contains(&key) {
                return Derived::Cycle;
            }
            let values = cx.stored(f, id, *pointer);
            if values.is_empty() {
                return Derived::No;
            }
            path.path.push(key);
            let d = every(values.iter().map(|v| derived(cx, id, f, *v, path)));
            path.path.pop();
            d
        }
        e if path.width => width(cx, id, f, e, path),
        e => some(
            super::operands(e)
                .into_iter()
                .map(|o| derived(cx, id, f, o, path)),
        ),
    }
}

/// [`derived`] of an operation, for a width: see [`derivative_width`].
fn width(cx: &Cx, id: usize, f: &Function, e: &E, path: &mut Walk) -> Derived {
    use naga::{BinaryOperator as Bo, MathFunction as Mf};
    let mut go = |h: Handle<E>| derived(cx, id, f, h, path);
    match *e {
        // The length of a vector is 0 only where every component is: a vector built of
        // widths (`vec2(dFdx(x), dFdy(x))`), not a vector's derivative (`dFdy` lowers to a
        // negated one).
        E::Math {
            fun: Mf::Length,
            arg,
            ..
        } if !matches!(cx.info.ty(id, arg), naga::TypeInner::Scalar(_))
            && !matches!(f.expressions[arg], E::Compose { .. }) =>
        {
            Derived::No
        }
        E::Math {
            fun: Mf::Length | Mf::Abs | Mf::Sqrt,
            arg,
            ..
        }
        | E::Unary { expr: arg, .. }
        | E::Swizzle { vector: arg, .. }
        | E::AccessIndex { base: arg, .. } => go(arg),
        // Where the other operand's range lets it be 0: the analysis's value of the divisor
        // says (`max(w, cap)` under `if (cap > 0.0)` is not).
        E::Math {
            fun: Mf::Max | Mf::Min,
            arg,
            arg1: Some(b),
            ..
        } => some([go(arg), go(b)].into_iter()),
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } => some([go(left), go(right)].into_iter()),
        E::Binary {
            op: Bo::Divide,
            left,
            ..
        } => go(left),
        E::Binary {
            op: Bo::Add,
            left,
            right,
        } => every([go(left), go(right)].into_iter()),
        E::Select { accept, reject, .. } => every([go(accept), go(reject)].into_iter()),
        E::Compose { ref components, .. } => {
            let all: Vec<Derived> = components.iter().map(|c| go(*c)).collect();
            every(all.into_iter())
        }
        _ => Derived::No,
    }
}

/// The finding for a division at `span` by a derivative's width (value `v`) not kept from 0: the
/// quotient is ±∞ (on hardware that follows IEEE 754; GLSL ES 3.00 does not require it) over
/// whole flat regions, and NaN where the dividend is 0 there too. `nan`: the dividend is one the
/// inputs compute (not a texel) and can be 0 — Babylon's grid divides a coordinate's distance to
/// the nearest line by its derivatives' length, 0 on every face the coordinate runs across, and
/// at an integer coordinate (a ground plane at `y = 0`) the distance is 0 as well: a warning.
/// Otherwise a note: a distance field's `d / fwidth(d)` is ±∞ over its flat (saturated) stretches,
/// which the clamp after it turns into the right coverage.
pub(super) fn divisor_finding(
    rule: &'static str,
    cx: &Cx,
    what: &str,
    v: &Num,
    nan: bool,
    span: Span,
) -> Diagnostic {
    let width = v.facts.has(Facts::NN);
    let mut d = Diagnostic::rule_warning(
        rule,
        "division by a derivative, which is 0 wherever the value differentiated is constant across the pixel quad",
        span,
    )
    .with_label(if nan {
        format!("{what} is 0 over flat regions, where the dividend can be 0 too: NaN")
    } else {
        format!("{what} is 0 over flat regions")
    })
    .with_note("the quotient is then ±∞ where the hardware follows IEEE 754 (GLSL ES 3.00 does not require it), and NaN where the dividend is 0 too");
    d = if width {
        d.with_help("keep the width above 0: `max(fwidth(x), 1e-4)`")
            .with_fix(Fix::suggested(
                "wrap the divisor in `max(…, 1e-4)`",
                span,
                format!("max({}, 1e-4)", cx.text(span)),
            ))
    } else {
        d.with_help("test the derivative before dividing by it")
    };
    if !nan {
        d.severity = Severity::Note;
    }
    d
}
