//! `acos-domain` and `asin-domain`: an argument that can leave `[-1, 1]`.

use essl::diagnostic::{Diagnostic, Fix};
use naga::{Expression as E, MathFunction as Mf};

use super::{describe, Cx, Rule};
use crate::interval::Interval;
use crate::symbolic::resolve;
use crate::value::Facts;
use crate::Level;

/// `acos-domain`.
pub static ACOS: Rule = Rule {
    id: "acos-domain",
    summary: "`acos(x)` of a value that rounding or arithmetic can push past ±1",
    default_level: Level::Warn,
    doc: DOC_ACOS,
    check: check_acos,
};

/// `asin-domain`.
pub static ASIN: Rule = Rule {
    id: "asin-domain",
    summary: "`asin(x)` of a value that rounding or arithmetic can push past ±1",
    default_level: Level::Warn,
    doc: DOC_ASIN,
    check: check_asin,
};

const DOC_ACOS: &str = r#"
## What it does
Reports `acos(x)` where the shader computes `x` and cannot guarantee `-1 ≤ x ≤ 1`. The classic
case is the cosine of an angle as a dot product of unit vectors: mathematically in `[-1, 1]`,
but `normalize` and `dot` round, and the result can be `1.0000001`. An argument that is a
uniform as such (`acos(u_coneCos)`) is not reported: the runtime check validates uniform values.

## Why is this bad?
GLSL ES 3.00 leaves `acos(x)` undefined for `|x| > 1` (§8.1); GPUs return NaN. The NaN appears
exactly where the two vectors are (anti)parallel — the centre of a spot light, the pixel that
faces the light — and turns the texture coordinate computed from the angle into NaN, so the
lookup returns garbage.

## Example
```glsl
float upCos = dot(light.direction, spotLightEx.up);
float upAngle = acos(upCos);
```

## Use instead
```glsl
float upAngle = acos(clamp(upCos, -1.0, 1.0));
```
The fix is suggested (`clamp(…, -1.0, 1.0)`); it changes nothing where the argument was in range.

## References
- GLSL ES 3.00 specification, §8.1 Angle and Trigonometry Functions: acos "Results are undefined
  if |x| > 1."
- Article 003 (A-Frame projected-texture spot lights): `acos(dot(light.direction, spotLightEx.up))`.
"#;

const DOC_ASIN: &str = r#"
## What it does
Reports `asin(x)` where the shader computes `x` and cannot guarantee `-1 ≤ x ≤ 1` — a dot
product or a component of unit vectors, which rounding can push to `1.0000001`. A uniform as
such is not reported.

## Why is this bad?
GLSL ES 3.00 leaves `asin(x)` undefined for `|x| > 1` (§8.1); GPUs return NaN, which then
spreads through every value computed from the angle.

## Example
```glsl
float lat = asin(normalize(p).y);
```

## Use instead
```glsl
float lat = asin(clamp(normalize(p).y, -1.0, 1.0));
```

## References
- GLSL ES 3.00 specification, §8.1 Angle and Trigonometry Functions: asin "Results are undefined
  if |x| > 1."
"#;

fn check_acos(cx: &Cx, out: &mut Vec<Diagnostic>) {
    check(cx, out, Mf::Acos, &ACOS);
}

fn check_asin(cx: &Cx, out: &mut Vec<Diagnostic>) {
    check(cx, out, Mf::Asin, &ASIN);
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>, which: Mf, rule: &Rule) {
    let name = if which == Mf::Acos { "acos" } else { "asin" };
    for (id, f) in cx.functions() {
        for (h, e) in f.expressions.iter() {
            let E::Math { fun, arg, .. } = *e else {
                continue;
            };
            if fun != which || cx.span(f, h).is_empty() {
                continue;
            }
            let x = cx.operand(f, h, arg);
            let Some(v) = cx.sound.num(id, x) else {
                continue;
            };
            let i = v.hull();
            if i.within(Interval::SIGNED_UNIT) || v.facts.has(Facts::UNIT) {
                continue;
            }
            let Some(v) = cx.refined(f, id, x, &cx.guards(f, id, h)) else {
                continue;
            };
            let i = v.hull();
            if i.within(Interval::SIGNED_UNIT) || v.facts.has(Facts::UNIT) {
                continue;
            }
            let span = cx.span(f, x);
            let what = cx.what(f, id, x);
            let rounding = i.within(Interval::new(-1.0001, 1.0001));
            let dot = matches!(
                f.expressions[resolve(f, &cx.sound, id, x)],
                E::Math { fun: Mf::Dot, .. }
            );
            let label = if rounding {
                format!(
                    "{what} is in [-1, 1] only in exact arithmetic: rounding can push it past ±1"
                )
            } else if dot {
                format!("{what} has a factor not known to be a unit vector, and rounding pushes even unit vectors past ±1")
            } else {
                format!("{what} can be outside [-1, 1]: {}", describe(i))
            };
            let mut d = Diagnostic::warning(
                rule.id,
                format!(
                    "`{name}` argument can be outside [-1, 1], where `{name}` is undefined (NaN)"
                ),
                span,
            )
            .with_label(label)
            .with_note(format!(
                "GLSL ES 3.00 §8.1: {name}(x) is undefined if |x| > 1"
            ))
            .with_help("clamp the argument to [-1, 1]");
            if !span.is_empty() {
                d = d.with_fix(Fix::suggested(
                    "wrap the argument in `clamp(…, -1.0, 1.0)`",
                    span,
                    format!("clamp({}, -1.0, 1.0)", cx.text(span)),
                ));
            }
            out.push(d);
        }
    }
}
