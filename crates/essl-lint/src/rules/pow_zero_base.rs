//! `pow-zero-base`: `pow(x, y)` whose base can be 0 while its exponent can be ≤ 0.

use essl::diagnostic::{Diagnostic, Fix};
use essl::source::Span;

use super::context::PowCall;
use super::parameters::caller_value;
use super::rule::declare_rule;
use super::{describe, Cx};
use crate::value::Facts;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `pow(x, y)` where the base can be 0 (a `max(…, 0.0)`, a product that vanishes) while the
    /// exponent can be 0 or negative, and where both come from the shader's arithmetic or constants.
    /// An exponent that is one uniform as such (`pow(max(dot(n, h), 0.0), u_shininess)`) is 0 when
    /// the user sets it to 0, the value a shininess slider starts at; with a base that is 0 over a
    /// whole region (the side facing away from the highlight, a texel wherever the texture is
    /// black: `pow(texture(uAmbient, uv).r, uOcclusionStrength)`) that is a note naming the
    /// uniform; so is a base that is the length of a pixel's offset from a centre the host sets
    /// (`pow(length(vUV - centerPosition), radialIntensity)`), 0 at the middle pixel of a target
    /// of odd size for the usual centre (0.5, 0.5) — see `normalize-zero`.
    /// three.js keeps this from happening in JavaScript: its Phong material passes
    /// `Math.max(shininess, 1e-4)`, "to prevent pow( 0.0, 0.0 )".
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves `pow(x, y)` undefined for `x = 0` and `y ≤ 0` (§8.2). `exp2(y * log2(0))`
    /// is `exp2(-∞ * y)`: `+∞` for a negative `y` and NaN for `y = 0`.
    ///
    /// ## Example
    /// ```glsl
    /// float f = pow(max(dot(n, l), 0.0), k - 1.0);   // k - 1.0 can be 0 or negative
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float f = pow(max(dot(n, l), 1e-4), k - 1.0);  // a base that is never 0
    /// ```
    /// (or make the exponent positive, `max(k - 1.0, 1e-4)`). 1e-4 is above `mediump`'s smallest
    /// normal number (6.1e-5), so the guard survives in `mediump` too. For a uniform exponent the
    /// suggested fix is on the exponent, `pow(max(dot(n, h), 0.0), max(u_shininess, 1e-4))`,
    /// which changes no result for a shininess of 1e-4 or more.
    ///
    /// ## What it does not flag
    /// - An exponent positive by construction (`max(u_shininess, 1e-4)`, `u_k + 1.0`), or a uniform
    ///   exponent whose base is 0 at isolated pixels only (`pow(abs(v_x - 0.5), u_k)`) other than
    ///   the pixel on a centre.
    /// - A base the shader keeps above 0 (`max(x, 1e-4)`, `exp(x)`, `x * x + 1.0`) or a guard says is
    ///   not 0 (`if (x > 0.0)`, `x != 0.0 ? pow(x, y) : 0.0`).
    /// - A base that can be negative: `pow-negative-base` reports it.
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard; a note, naming
    /// the uniform, when one uniform alone (with constants) does — the hazard then needs that value out
    /// of the range the shader was written for, and essl-gl's validation mode checks it at draw time. (`pow(r, u_power - 1.0)` needs `u_power ≤ 1`).
    /// An exponent that is a uniform as such is a note too. So is an exponent never above 0
    /// (`pow(t, -1.5)`) of a base built from a function's parameters alone, where its callers
    /// pass inputs as such, or from a vertex shader's attributes, that ordinary values make 0:
    /// lygia's `k2rgb(t)` for a temperature of 0 K.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.2 Exponential Functions: "Results are undefined if x = 0 and
    ///   y ≤ 0."
    pub(crate) struct PowZeroBase {
        id: "pow-zero-base",
        summary: "`pow(x, y)` whose base can be 0 while its exponent can be ≤ 0",
        default_level: Level::Warn,
        check: check_zero,
    }
}

fn check_zero(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for PowCall {
        id,
        f,
        call: h,
        span: _,
        base,
        exp,
    } in cx.pow_calls()
    {
        let (Some(b), Some(x)) = (cx.sound().num(id, base), cx.sound().num(id, exp)) else {
            continue;
        };
        let (bi, xi) = (b.hull(), x.hull());
        // An exponent that is one uniform as such is positive only because uniforms are taken
        // to be: 0 is the value a material's shininess slider starts at.
        let at_zero = as_uniform(x.facts);
        // A texel as such can be anything to the sound analysis (a float texture), but an
        // ordinary one is 0 wherever the picture is black: `pow(texture(t, uv).r, u_strength)`.
        let black = at_zero && texel_from_zero(cx, id, base, b.facts);
        if bi.lo < 0.0 && !b.facts.has(Facts::NN) && !black {
            continue; // pow-negative-base says it
        }
        // The texel, like the uniform, is positive only by assumption.
        let base_zero = bi.contains(0.0) && (!b.facts.has(Facts::POS) || black);
        let exp_nonpositive = xi.lo <= 0.0 && (!x.facts.has(Facts::POS) || at_zero);
        if !base_zero || !exp_nonpositive {
            if xi.hi <= 0.0 {
                out.extend(from_callers(cx, f, id, h, base, exp));
            }
            continue;
        }
        let g = cx.guards(f, id, h);
        let (Some(b), Some(x)) = (cx.refined(f, id, base, &g), cx.refined(f, id, exp, &g)) else {
            continue;
        };
        let (bi, xi) = (b.hull(), x.hull());
        let base_zero =
            bi.contains(0.0) && (!b.facts.has(Facts::POS) || black) && !cx.nonzero(f, id, base, &g);
        let exp_nonpositive = xi.lo <= 0.0 && (!x.facts.has(Facts::POS) || at_zero);
        if !base_zero || !exp_nonpositive {
            continue;
        }
        // With the uniform at 0, the base must be 0 over a region (the side facing away), not
        // at isolated pixels.
        let uniform = at_zero
            .then(|| cx.origin(&[(id, exp)]).single_uniform().map(str::to_string))
            .flatten();
        // Or at the pixel on a centre the host sets, which the usual centre hits exactly.
        let centre = match (at_zero, &uniform) {
            (false, _) => None,
            (true, None) => continue,
            (true, Some(_)) if cx.flat_at(f, id, base, 0.0) => None,
            (true, Some(_)) => match super::normalize_zero::centre_length(cx, f, id, base) {
                Some(c) => Some(c),
                None => continue,
            },
        };
        let bspan = cx.span(f, base);
        let xspan = cx.span(f, exp);
        let mut d = Diagnostic::rule_warning(
            PowZeroBase::RULE.id,
            "`pow` base can be 0 while the exponent can be ≤ 0, where `pow` is undefined",
            bspan,
        )
        .with_label(match uniform {
            Some(_) if black => format!(
                "{} is 0 wherever the texture is black",
                cx.what(f, id, base)
            ),
            Some(_) => match &centre {
                Some(c) => format!(
                    "{} is 0 at the pixel on the centre `{c}`",
                    cx.what(f, id, base)
                ),
                None => format!("{} is 0 over a whole region", cx.what(f, id, base)),
            },
            None => format!("{} can be 0", cx.what(f, id, base)),
        })
        .with_note("GLSL ES 3.00 §8.2: pow(x, y) is undefined if x = 0 and y <= 0")
        .with_help("keep the base above 0");
        if !xspan.is_empty() {
            d = d.with_secondary(
                xspan,
                match &uniform {
                    Some(u) => format!("the exponent: 0 when `{u}` is 0"),
                    None => format!("the exponent can be ≤ 0: {}", describe(xi)),
                },
            );
        }
        if !bspan.is_empty() {
            d = d.with_fix(Fix::suggested(
                "wrap the base in `max(…, 1e-4)`",
                bspan,
                format!("max({}, 1e-4)", cx.text(bspan)),
            ));
        }
        out.push(match uniform {
            Some(name) => at_zero_uniform(cx, d, &name, xspan, centre.is_some()),
            None => cx.grade(d, &[(id, exp)]),
        });
    }
}

/// Whether an exponent with `facts` is one uniform as such (through copies, swizzles and
/// conversions, not negation: positive whenever the uniform is), and no per-pixel value.
/// The note for a base built from a function's parameters alone, where its callers pass inputs
/// as such, or from a vertex shader's attributes ([`caller_value`]), under an exponent that is
/// never above 0: `pow(t, -1.5)` of a temperature a caller may pass as 0.
fn from_callers(
    cx: &Cx,
    f: &naga::Function,
    id: usize,
    call: naga::Handle<naga::Expression>,
    base: naga::Handle<naga::Expression>,
    exp: naga::Handle<naga::Expression>,
) -> Option<Diagnostic> {
    let found = caller_value(cx, f, id, base)?;
    if cx.kept_from_zero(f, id, base, &cx.guards(f, id, call)) {
        return None;
    }
    let bspan = cx.span(f, base);
    let xi = cx.sound().num(id, exp)?.hull();
    let message = match &found.names[..] {
        [name] if !found.offset => format!(
            "`pow` of the base `{name}`, which {}, with an exponent ≤ 0: undefined",
            if found.attribute {
                "a vertex may hold as 0"
            } else {
                "a caller may pass as 0"
            }
        ),
        _ => format!(
            "`pow` of a base built from {}, 0 for some of their values, with an exponent ≤ 0: undefined",
            found.list()
        ),
    };
    let mut d = Diagnostic::rule_note(PowZeroBase::RULE.id, message, bspan)
        .with_label(format!(
            "{} is 0 for some values of {}",
            cx.what(f, id, base),
            found.list()
        ))
        .with_note("GLSL ES 3.00 §8.2: pow(x, y) is undefined if x = 0 and y <= 0")
        .with_note(found.why())
        .with_help("keep the base above 0");
    let xspan = cx.span(f, exp);
    if !xspan.is_empty() {
        d = d.with_secondary(xspan, format!("the exponent is {}", describe(xi)));
    }
    if !bspan.is_empty() {
        d = d.with_fix(Fix::suggested(
            "wrap the base in `max(…, 1e-4)`",
            bspan,
            format!("max({}, 1e-4)", cx.text(bspan)),
        ));
    }
    Some(d)
}

pub(super) fn as_uniform(facts: Facts) -> bool {
    facts.has(Facts::EXT) && facts.has(Facts::POS) && facts.per_draw()
}

/// Whether `base` (with `facts`) is a texel as such whose ordinary values start at 0.
fn texel_from_zero(cx: &Cx, id: usize, base: naga::Handle<naga::Expression>, facts: Facts) -> bool {
    facts.has(Facts::EXT)
        && facts.any(Facts::TEXTURE)
        && !facts.any(Facts::INPUT.with(Facts::UNIFORM))
        && cx
            .typical()
            .num(id, base)
            .is_some_and(|t| t.comps().iter().any(|c| c.lo == 0.0))
}

/// The note for a base that is 0 over a region (or, `centre`, at the pixel on a centre the
/// host sets) raised to a uniform exponent `uniform`, which is
/// 0 when the uniform is: three.js's Phong material passes `max(shininess, 1e-4)` "to prevent
/// pow(0.0, 0.0)". Its fix keeps the exponent above 0, which changes no result for the values the uniform is
/// meant to take.
fn at_zero_uniform(
    cx: &Cx,
    mut d: Diagnostic,
    uniform: &str,
    xspan: Span,
    centre: bool,
) -> Diagnostic {
    d.severity = essl::diagnostic::Severity::Note;
    let zero = if centre {
        "at the pixel on a centre"
    } else {
        "over a region"
    };
    d.message = format!(
        "`pow` of a base that is 0 {zero}, with the exponent `{uniform}`: undefined (NaN) when `{uniform}` is 0"
    );
    d.help = Some("keep the exponent above 0 (or the base)".to_string());
    if !xspan.is_empty() {
        d.fix = Some(Fix::suggested(
            "wrap the exponent in `max(…, 1e-4)`",
            xspan,
            format!("max({}, 1e-4)", cx.text(xspan)),
        ));
    }
    d.with_note(
        "0 is an ordinary value of an exponent a user sets (a shininess slider starts there): `pow(0.0, 0.0)` is NaN on GPUs that compute `exp2(y * log2(x))`",
    )
}
