//! The check `acos-domain` and `asin-domain` share: an argument of `acos` or `asin` that can
//! leave `[-1, 1]`.

use essl::diagnostic::{Diagnostic, Fix};
use naga::{Expression as E, MathFunction as Mf};

use super::{describe, Cx, Rule};
use crate::interval::Interval;
use crate::symbolic::resolve;
use crate::value::Facts;

/// Reports `which` (`acos` or `asin`) of an argument that can leave `[-1, 1]`, as `rule`.
pub(super) fn check(cx: &Cx, out: &mut Vec<Diagnostic>, which: Mf, rule: &Rule) {
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
            let Some(v) = cx.sound().num(id, x) else {
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
                f.expressions[resolve(f, cx.sound(), id, x)],
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
            let message = if rounding || dot {
                format!("`{name}` argument is in [-1, 1] only in exact arithmetic: rounding can push it past ±1, where `{name}` is undefined (NaN)")
            } else {
                format!(
                    "`{name}` argument can be outside [-1, 1], where `{name}` is undefined (NaN)"
                )
            };
            let mut d = Diagnostic::rule_warning(rule.id, message, span)
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
            out.push(cx.grade(d, &[(id, x)]));
        }
    }
}
