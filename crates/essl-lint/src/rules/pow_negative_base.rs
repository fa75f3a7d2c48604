//! `pow-negative-base`: `pow(x, y)` whose base the shader's own arithmetic can make negative.

use essl::diagnostic::{Diagnostic, Edit, Fix};
use naga::Expression as E;

use super::context::PowCall;
use super::rule::declare_rule;
use super::Cx;
use crate::analysis::Refinement;
use crate::value::Facts;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `pow(x, y)` where the shader's own arithmetic can make the base `x` negative: a dot
    /// product, a difference, a sine. A base that is only negative when a uniform or an input is
    /// (`pow(u_base, 2.0)`) is not reported: checking uniform values is the runtime check's job.
    /// As a note, a library function's `pow` of its own scalar parameter where its callers pass
    /// inputs as such (lygia's easing `quarticIn(t)` returning `pow(t, 4.0)`): a negative
    /// argument (`sin(time)`, an overshooting `t`) is left to the caller, as the function's
    /// divisions by its parameters are; a test that keeps the parameter from below 0 (`t > 0.0 ?
    /// pow(t, k) : 0.0`, but not an easing's `t < 0.5 ? 8.0 * pow(t, 4.0) : …`, which takes
    /// every negative `t`), or a name that says it is a distance, length, radius, size or depth,
    /// keeps it quiet.
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves `pow(x, y)` undefined for `x < 0` (§8.2), whatever `y` is. Many GPUs
    /// compute it as `exp2(y * log2(x))`, which is NaN for a negative base; optimisers may rewrite
    /// `pow(a, 2.0)` as `a * a`, so a constant exponent can give the square on one device and NaN on
    /// another. A NaN in a colour shows as black (or garbage after blending) exactly where the dot
    /// product turns negative: the back of a specular highlight, the edge of a spot light. The
    /// article's spot light computes `pow(dot(normal, halfVector), u_shininess)` after a test on a
    /// *different* dot product (`dot(normal, surfaceToLight) > 0.0`), which does not keep
    /// `dot(normal, halfVector)` positive.
    ///
    /// ## Example
    /// ```glsl
    /// float specular = pow(dot(normal, halfVector), u_shininess);
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float specular = pow(max(dot(normal, halfVector), 0.0), u_shininess);
    /// ```
    /// The fix (`max(…, 0.0)`) is suggested, not applied by `--fix`: it changes the value where the
    /// base was negative (from undefined, NaN on many GPUs, to 0, which is what the lighting model
    /// means). For a constant integer exponent the suggestion keeps the power's meaning instead:
    /// `pow(abs(x), 2.0)` for an even power, `sign(x) * pow(abs(x), 3.0)` for an odd one (or write the
    /// product, `x * x`).
    ///
    /// ## What it does not flag
    /// - A base the shader clamps, in the same expression or on an earlier line: `max(x, 0.0)`,
    ///   `clamp(x, 0.0, 1.0)`, `saturate(x)`, `abs(x)`, `x * x`, `length(v)`, `exp(x)`
    ///   (`x = max(x, 0.0); … pow(x, k)`: the analysis follows what a variable holds from statement
    ///   to statement, through `inout` parameters and the cases of a `switch`).
    /// - A base under a guard: `if (d > 0.0) … pow(d, k)`, `d > 0.0 ? pow(d, k) : 0.0`,
    ///   `if (d <= 0.0) return;`, and the sign-split idiom `x < 0.0 ? -pow(-x, p) : pow(x, p)` (a
    ///   guard on `x` bounds `-x` and other arithmetic on `x`).
    /// - A uniform, input or texel as such, and `1.0 - x` of one in [0, 1] (`1.0 - metalness`,
    ///   `1.0 - gl_FragCoord.z * 0.9`): valid values are the runtime check's business.
    /// - Sums and products of such values, and what keeps them non-negative by construction: a weighted
    ///   sum (`dot(u_attenuation, vec3(1.0, d, d * d))`), `mix(a, b, t)` with `t` in [0, 1] (a uniform
    ///   weight, or `0.5 * dot(n, l) + 0.5`), Schlick's `F0 + (1.0 - F0) * pow(1.0 - c, 5.0)`,
    ///   `1.0 - exp(-k * x)` with `k * x ≥ 0`, a colour matrix with non-negative entries times a colour,
    ///   `dot(n, u_dir)` of a unit vector and a uniform direction taken in [-1, 1].
    /// - What a user function returns for the arguments of each call: `float lum(vec3 c)` returning
    ///   `dot(c, W)` is non-negative where it is called with a colour, even if another call passes a
    ///   signed vector.
    /// - Code essl does not lower (reads of inactive inputs in dead code).
    ///
    /// A base negative only through rounding (`1.0 - dot(v, h)` of unit vectors) is reported with a
    /// message that says so, and `max(…, 0.0)` as the fix.
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard; a note, naming
    /// the uniform, when one uniform alone (with constants) does — the hazard then needs that value out
    /// of the range the shader was written for, and essl-gl's validation mode checks it at draw time.
    /// A parameter its callers pass as such is a note: the values are the callers'.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.2 Exponential Functions: "Results are undefined if x < 0."
    /// - Article 001 (webgl2fundamentals, spot lights): `pow(dot(normal, halfVector), u_shininess)`.
    pub(crate) struct PowNegativeBase {
        id: "pow-negative-base",
        summary: "`pow(x, y)` whose base the shader's own arithmetic can make negative",
        default_level: Level::Warn,
        check: check_negative,
    }
}

fn check_negative(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for PowCall {
        id,
        f,
        call: h,
        span,
        base,
        exp,
    } in cx.pow_calls()
    {
        let Some(b) = cx.sound().num(id, base) else {
            continue;
        };
        if let Some(d) = caller_base(cx, f, id, h, base, exp) {
            out.push(d);
            continue;
        }
        if b.hull().lo >= 0.0 || b.facts.has(Facts::NN) {
            continue;
        }
        // Under the conditions the call runs in (`if (d > 0.0)`, `d > 0.0 ? pow(d, k) : 0.0`).
        let Some(b) = cx.refined(f, id, base, &cx.guards(f, id, h)) else {
            continue;
        };
        let bi = b.hull();
        if bi.lo >= 0.0 || b.facts.has(Facts::NN) {
            continue;
        }
        let bspan = cx.span(f, base);
        let what = cx.what(f, id, base);
        // Negative only by the slack of a dot product or a square root of unit vectors:
        // `1.0 - dot(v, h)` with `v == h`.
        let rounding = bi.lo >= -ROUNDING;
        let (message, label) = if rounding {
            (
                "`pow` base can be slightly negative through rounding, where `pow` is undefined (NaN on many GPUs)",
                format!(
                    "{what} is not negative in exact arithmetic, but rounding can take it to {}",
                    super::fmt_num(bi.lo)
                ),
            )
        } else if bi.lo.is_finite() {
            (
                "`pow` base can be negative, where `pow` is undefined (NaN on many GPUs)",
                format!("{what} can be as low as {}", super::fmt_num(bi.lo)),
            )
        } else {
            (
                "`pow` base can be negative, where `pow` is undefined (NaN on many GPUs)",
                format!("{what} can be negative"),
            )
        };
        let d = Diagnostic::rule_warning(PowNegativeBase::RULE.id, message, bspan)
            .with_label(label)
            .with_note("GLSL ES 3.00 §8.2: pow(x, y) is undefined if x < 0");
        let d = if rounding {
            clamp_fix(cx, bspan, floor_exponent(cx, f, id, exp), d)
        } else {
            fix_negative(cx, f, id, span, base, exp, d)
        };
        out.push(cx.grade(d, &[(id, base)]));
    }
}

/// The note for `pow(p, y)` of a function's scalar parameter as such where its callers pass
/// inputs as such: lygia's easing `quarticIn(t)` returning `pow(t, 4.0)` — a library function
/// that leaves a negative argument (`sin(time)`, a `t` past its range) to the caller, as its
/// divisions by its parameters do. The analysis takes inputs for positive, so this is decided
/// before that: a guard on the parameter silences it.
fn caller_base(
    cx: &Cx,
    f: &naga::Function,
    id: usize,
    call: naga::Handle<E>,
    base: naga::Handle<E>,
    exp: naga::Handle<E>,
) -> Option<Diagnostic> {
    let param = super::parameters::parameter_itself(cx, f, id, call, base)?;
    let found = super::parameters::caller_value(cx, f, id, param)?;
    let [name] = &found.names[..] else {
        return None;
    };
    // A distance, length or radius is not negative by what it is.
    if found.attribute || crate::analysis::names::says_any(name, NOT_NEGATIVE) {
        return None;
    }
    // Under a test of the parameter that keeps it from below 0 (`t > 0.0 ? pow(t, k) : 0.0`,
    // `if (t < 0.0) return 0.0;`): the analysis takes the parameter for positive already, so
    // the test's own bound says whether it guards; `t < 0.5 ? 8.0 * pow(t, 4.0) : …` (an
    // easing's first half) does not.
    let g = cx.guards(f, id, call);
    if g.facts.iter().any(|(s, r)| {
        matches!(r, Refinement::Value(iv) if iv.lo >= 0.0) && cx.sound().same(f, id, *s, base)
    }) {
        return None;
    }
    let span = cx.span(f, base);
    if span.is_empty() {
        return None;
    }
    let d = Diagnostic::rule_note(
        PowNegativeBase::RULE.id,
        format!("`pow` of the parameter `{name}`, which a caller may pass negative"),
        span,
    )
    .with_label(format!(
        "undefined wherever a caller passes `{name}` below 0"
    ))
    .with_note("GLSL ES 3.00 §8.2: pow(x, y) is undefined if x < 0")
    .with_note(found.why());
    Some(fix_negative(cx, f, id, cx.span(f, call), base, exp, d))
}

/// Words of a parameter's name that say its value is not negative by what it is.
const NOT_NEGATIVE: &[&str] = &[
    "dist", "distance", "length", "len", "radius", "size", "depth",
];

/// How far below 0 rounding alone takes a base that is not negative in exact arithmetic (the
/// analysis's slack on dot products and lengths of unit vectors is a few ulps).
const ROUNDING: f64 = 1e-4;

/// The fix for a base negative only through rounding: `max(x, 0.0)`, whatever the exponent
/// (with `exponent`, the edit that keeps a uniform exponent above 0).
fn clamp_fix(
    cx: &Cx,
    bspan: essl::source::Span,
    exponent: Option<Edit>,
    d: Diagnostic,
) -> Diagnostic {
    if bspan.is_empty() {
        return d.with_help("clamp the base to 0");
    }
    let help = match exponent {
        Some(_) => "clamp the base to 0 (rounding is all that takes it below) and keep the uniform exponent above 0 (`pow(0.0, 0.0)` is NaN)",
        None => "clamp the base to 0: rounding is all that takes it below",
    };
    d.with_help(help).with_fix(base_floor(cx, bspan, exponent))
}

/// `max(x, 0.0)` of the base at `bspan`, and the edit of a uniform exponent where there is
/// one: the clamped base is 0 where the base was negative, and `pow(0.0, 0.0)` is undefined
/// when the uniform is 0 (what `pow-zero-base` notes).
fn base_floor(cx: &Cx, bspan: essl::source::Span, exponent: Option<Edit>) -> Fix {
    let mut fix = Fix::suggested(
        "wrap the base in `max(…, 0.0)`",
        bspan,
        format!("max({}, 0.0)", cx.text(bspan)),
    );
    if let Some(e) = exponent {
        fix.message = "wrap the base in `max(…, 0.0)` and the exponent in `max(…, 1e-4)`".into();
        fix.edits.push(e);
    }
    fix
}

/// The edit `max(u, 1e-4)` of an exponent that is a uniform as such.
fn floor_exponent(cx: &Cx, f: &naga::Function, id: usize, exp: naga::Handle<E>) -> Option<Edit> {
    let espan = cx.span(f, exp);
    let x = cx.sound().num(id, exp)?;
    (super::pow_zero_base::as_uniform(x.facts) && !espan.is_empty()).then(|| Edit {
        span: espan,
        replacement: format!("max({}, 1e-4)", cx.text(espan)),
    })
}

/// The fix for a base that can be negative, by exponent: an even integer power is the power of
/// `abs(x)`; an odd one keeps the sign, `sign(x) * pow(abs(x), n)`; any other exponent means a
/// base that should not go below 0, `max(x, 0.0)`.
fn fix_negative(
    cx: &Cx,
    f: &naga::Function,
    id: usize,
    span: essl::source::Span,
    base: naga::Handle<E>,
    exp: naga::Handle<E>,
    d: Diagnostic,
) -> Diagnostic {
    let bspan = cx.span(f, base);
    if bspan.is_empty() {
        return d.with_help("clamp the base to 0");
    }
    let b = cx.text(bspan);
    let n = cx
        .sound()
        .num(id, exp)
        .and_then(|v| v.hull().as_point())
        .filter(|n| n.fract() == 0.0 && n.abs() < 1e6);
    match n {
        Some(n) if n % 2.0 == 0.0 => d
            .with_help(format!("an even power of a negative number is the power of its magnitude: `pow(abs(x), {})`", super::fmt_num(n)))
            .with_fix(Fix::suggested("take the magnitude of the base", bspan, format!("abs({b})"))),
        Some(n) => {
            let espan = cx.span(f, exp);
            let help = format!("an odd power keeps the sign: `sign(x) * pow(abs(x), {})`", super::fmt_num(n));
            let d = d.with_help(help);
            if cx.pure(f, base) && !espan.is_empty() {
                let fixed = format!("(sign({b}) * pow(abs({b}), {}))", cx.text(espan));
                d.with_fix(Fix::suggested("keep the sign outside the power", span, fixed))
            } else {
                d
            }
        }
        None => {
            let exponent = floor_exponent(cx, f, id, exp);
            let help = match exponent {
                Some(_) => "clamp the base to 0 and keep the uniform exponent above 0 (`pow(0.0, 0.0)` is NaN)",
                None => "clamp the base to 0",
            };
            d.with_help(help).with_fix(base_floor(cx, bspan, exponent))
        }
    }
}
