//! The check the `domain-*` rules of one-argument functions share: `sqrt`, `inversesqrt`,
//! `log` and `log2` of an argument the shader's own arithmetic can make negative (or, for those
//! undefined at 0, zero over a region), with the same value analysis and guards as
//! `pow-negative-base` and `acos-domain`.

use essl::diagnostic::{Diagnostic, Fix};
use naga::{Expression as E, Function, Handle, MathFunction as Mf};

use super::parameters::caller_value;
use super::{fmt_num, Cx, Rule};
use crate::value::Facts;

/// How far below 0 rounding alone takes a value that is not negative in exact arithmetic
/// (`1.0 - d * d` of a dot product of unit vectors).
pub(super) const ROUNDING: f64 = 1e-4;

/// A function and what its domain excludes.
pub(super) struct Domain {
    /// The built-in.
    pub fun: Mf,
    /// Its name in GLSL.
    pub name: &'static str,
    /// Whether 0 is outside the domain too (`inversesqrt`, `log`, `log2`).
    pub zero: bool,
    /// The specification's words.
    pub spec: &'static str,
}

/// A call: (function id, function, the call, the argument as written, the built-in).
type Site<'a> = (usize, &'a Function, Handle<E>, Handle<E>, Mf);

/// Every call of the built-ins `funs` in the user's functions.
fn calls<'a>(cx: &Cx<'a>, funs: &[Mf]) -> Vec<Site<'a>> {
    let mut out = Vec::new();
    for (id, f) in cx.functions() {
        for (h, e) in f.expressions.iter() {
            let E::Math { fun, arg, .. } = *e else {
                continue;
            };
            if funs.contains(&fun) && !cx.span(f, h).is_empty() {
                out.push((id, f, h, cx.operand(f, h, arg), fun));
            }
        }
    }
    out
}

/// Reports the calls of the functions of `domains` whose argument can leave the domain, as
/// `rule`.
pub(super) fn check(cx: &Cx, out: &mut Vec<Diagnostic>, domains: &[Domain], rule: &Rule) {
    let funs: Vec<Mf> = domains.iter().map(|d| d.fun).collect();
    for (id, f, call, x, fun) in calls(cx, &funs) {
        let Some(dom) = domains.iter().find(|d| d.fun == fun) else {
            continue;
        };
        let Some(v) = cx.sound().num(id, x) else {
            continue;
        };
        let negative = v.hull().lo < 0.0 && !v.facts.has(Facts::NN);
        // A per-draw value positive only because its uniforms are taken to be: 0 is an
        // ordinary value of many (a blurriness, a roughness at its default).
        let per_draw = v.facts.per_draw();
        let zero = dom.zero
            && v.comps().iter().any(|c| c.contains(0.0))
            && (!v.facts.has(Facts::POS) || v.facts.any(Facts::TEXTURE) || per_draw);
        if !negative && !zero {
            if dom.zero {
                out.extend(from_callers(cx, f, id, call, x, dom, rule));
            }
            continue;
        }
        let g = cx.guards(f, id, call);
        let Some(r) = cx.refined(f, id, x, &g) else {
            continue;
        };
        let lo = r.hull().lo;
        let negative = lo < 0.0 && !r.facts.has(Facts::NN);
        let zero = dom.zero
            && !negative
            && r.comps().iter().any(|c| c.contains(0.0))
            && !cx.nonzero(f, id, x, &g)
            && cx.flat_at(f, id, x, 0.0);
        if !negative && !zero {
            // 0 at isolated points only for inputs in general, but what the callers pass may
            // make it 0 (`log(dot(st, st))` of `st - 0.5`, at the centre).
            if dom.zero {
                out.extend(from_callers(cx, f, id, call, x, dom, rule));
            }
            continue;
        }
        let d = finding(cx, f, id, x, dom, rule, negative, lo);
        let uniform = (!negative && per_draw)
            .then(|| cx.origin(&[(id, x)]).single_uniform().map(str::to_string))
            .flatten();
        out.push(match uniform {
            Some(name) => at_zero_uniform(d, dom.name, &name),
            None => cx.grade(d, &[(id, x)]),
        });
    }
}

/// The finding for `dom.name(x)` with `x` negative down to `lo` (or zero).
#[allow(clippy::too_many_arguments)]
fn finding(
    cx: &Cx,
    f: &Function,
    id: usize,
    x: Handle<E>,
    dom: &Domain,
    rule: &Rule,
    negative: bool,
    lo: f64,
) -> Diagnostic {
    let name = dom.name;
    let span = cx.span(f, x);
    let what = cx.what(f, id, x);
    let rounding = negative && lo >= -ROUNDING;
    let (message, label) = if rounding {
        (
            format!("`{name}` argument can be slightly negative through rounding, where `{name}` is undefined (NaN)"),
            format!("{what} is not negative in exact arithmetic, but rounding can take it to {}", fmt_num(lo)),
        )
    } else if negative {
        let how = if lo.is_finite() {
            format!("{what} can be as low as {}", fmt_num(lo))
        } else {
            format!("{what} can be negative")
        };
        (
            format!("`{name}` of a value that can be negative, where `{name}` is undefined (NaN)"),
            how,
        )
    } else {
        (
            format!(
                "`{name}` of a value that can be 0, where `{name}` is undefined (±∞, then NaN)"
            ),
            format!(
                "{what} is 0 over a whole region: where it saturates at 0, or for the whole draw"
            ),
        )
    };
    let floor = match (dom.zero, cx.prec.is_low(span)) {
        (false, _) => "0.0",
        // Above `mediump`'s smallest normal number, 6.1e-5.
        (true, true) => "1e-4",
        (true, false) => "1e-6",
    };
    let mut d = Diagnostic::rule_warning(rule.id, message, span)
        .with_label(label)
        .with_note(dom.spec.to_string())
        .with_help(format!(
            "keep the argument at or above {floor}: `max(x, {floor})`"
        ));
    if !span.is_empty() {
        d = d.with_fix(Fix::suggested(
            format!("wrap the argument in `max(…, {floor})`"),
            span,
            format!("max({}, {floor})", cx.text(span)),
        ));
    }
    d
}

/// The note for an argument built from a function's parameters alone, where its callers pass
/// inputs as such, or from a vertex shader's attributes ([`caller_value`]): `log(t)` of a
/// temperature `t` a caller may pass as 0.
fn from_callers(
    cx: &Cx,
    f: &Function,
    id: usize,
    call: Handle<E>,
    x: Handle<E>,
    dom: &Domain,
    rule: &Rule,
) -> Option<Diagnostic> {
    let found = caller_value(cx, f, id, x)?;
    if cx.kept_from_zero(f, id, x, &cx.guards(f, id, call)) {
        return None;
    }
    let mut d = finding(cx, f, id, x, dom, rule, false, 0.0);
    let fun = dom.name;
    let whose = if found.attribute {
        "attribute"
    } else {
        "parameter"
    };
    let names = found.list();
    d.severity = essl::diagnostic::Severity::Note;
    d.message = match &found.names[..] {
        [name] => format!(
            "`{fun}` of {}, where `{fun}` is undefined (±∞, then NaN)",
            found.lone(name)
        ),
        _ => format!(
            "`{fun}` of a value of the {whose}s {names}, 0 for some of their values, where `{fun}` is undefined (±∞, then NaN)"
        ),
    };
    d.label = format!("{} is 0 for some values of {names}", cx.what(f, id, x));
    Some(d.with_note(found.why().to_string()))
}

/// A note for an argument that is 0 when one uniform is: 0 is an ordinary value of many
/// parameters (a blurriness, a roughness at its default), not one out of their range.
fn at_zero_uniform(mut d: Diagnostic, fun: &str, uniform: &str) -> Diagnostic {
    d.severity = essl::diagnostic::Severity::Note;
    d.message = format!(
        "`{fun}` of a value that is 0 when `{uniform}` is 0, where `{fun}` is undefined (±∞, then NaN)"
    );
    d.with_note(format!(
        "0 is an ordinary value of many parameters: keep the argument above 0 whatever `{uniform}` is"
    ))
}
