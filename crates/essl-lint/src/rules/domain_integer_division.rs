//! `domain-integer-division`: integer `/` or `%` by a value that can be 0, and `%` of a value
//! that can be negative.

use essl::diagnostic::{Diagnostic, Fix};
use naga::{BinaryOperator as Bo, Expression as E, Function, Handle, ScalarKind};

use super::rule::declare_rule;
use super::Cx;
use crate::value::Facts;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports an integer division `a / b` or remainder `a % b` (of `int`, `uint` or their vectors)
    /// whose divisor can be 0: a difference (`u_columns - 1`), a conversion of a per-pixel value
    /// (`int(v_uv.x * 4.0)` is 0 on a quarter of the screen), a texel of an integer texture. A
    /// uniform as such (`index % u_columns`) is not reported: essl-gl's validation mode checks
    /// uniform values.
    ///
    /// It also reports an `int` remainder `a % b` whose operands the shader's own arithmetic can
    /// make negative: a cell index `int(floor(v_uv.x * 8.0 - 4.0))`, a neighbour `(i - 1) % n` of
    /// a loop counter from 0. GLSL ES 3.00 leaves `%` undefined when either operand is negative;
    /// a checkerboard or a tiling taken that way breaks on one side of the origin. An input as such
    /// (`v_cell % 2` of a varying) is the caller's to keep non-negative, as for `pow-negative-base`.
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves integer division by zero undefined (§5.9: "the result is undefined").
    /// Unlike a float division, which gives ±∞ that a clamp can still tame, an integer division by
    /// zero gives an arbitrary value — 0, −1, the dividend — that differs between GPUs, and a
    /// texel index or loop count computed from it reads or loops wherever that value says.
    ///
    /// ## Example
    /// ```glsl
    /// int bands = int(v_uv.x * 4.0);   // 0 on the left quarter of the screen
    /// int cell = index % bands;
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// int cell = index % max(bands, 1);
    /// ```
    /// The suggested fix keeps the divisor at least 1 (`max(…, 1)`, `max(…, 1u)`), which is right for
    /// counts and sizes; a divisor that may be negative needs its own guard.
    ///
    /// ## What it does not flag
    /// - A constant divisor other than 0, and a divisor kept away from 0: `max(n, 1)`, `n + 1` of a
    ///   non-negative `n`, or a guard (`if (n > 0)`, `n != 0 ? a / n : 0`).
    /// - Float division (see `division-by-difference`), and `uint` remainders (never negative).
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard; a note, naming
    /// the uniform, when one uniform alone (with constants) does — a column count of 0 is the host's
    /// mistake, which essl-gl's validation mode checks at each draw.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §5.9 Expressions: for `/` and `%` of integers, a zero divisor
    ///   gives an undefined result; for `%`, "Results are undefined if one or both operands are
    ///   negative."
    pub(crate) struct DomainIntegerDivision {
        id: "domain-integer-division",
        summary: "integer `/` or `%` by a value that can be 0, or `%` of a negative value",
        default_level: Level::Warn,
        check: check,
    }
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for (id, f) in cx.functions() {
        for (h, e) in f.expressions.iter() {
            let E::Binary {
                op: op @ (Bo::Divide | Bo::Modulo),
                left,
                right,
            } = *e
            else {
                continue;
            };
            if cx.span(f, h).is_empty() {
                continue;
            }
            let d = cx.operand(f, h, right);
            let kind = cx.kind(id, d);
            if !matches!(kind, Some(ScalarKind::Sint | ScalarKind::Uint)) {
                continue;
            }
            if let Some(diag) = zero_divisor(cx, f, id, h, d, op, kind) {
                out.push(diag);
            } else if op == Bo::Modulo && kind == Some(ScalarKind::Sint) {
                let x = cx.operand(f, h, left);
                if let Some(diag) = [x, d].into_iter().find_map(|o| negative(cx, f, id, h, o)) {
                    out.push(diag);
                }
            }
        }
    }
}

/// The finding for a divisor `d` of `h` that can be 0.
fn zero_divisor(
    cx: &Cx,
    f: &Function,
    id: usize,
    h: Handle<E>,
    d: Handle<E>,
    op: Bo,
    kind: Option<ScalarKind>,
) -> Option<Diagnostic> {
    let zero = |n: &crate::value::Num| {
        n.comps().iter().any(|c| c.contains(0.0)) && !(n.n == 1 && n.facts.has(Facts::NZ))
    };
    if !cx.sound().num(id, d).is_some_and(zero) || cx.sym(id, f).nonzero(d) {
        return None;
    }
    let g = cx.guards(f, id, h);
    if cx.nonzero(f, id, d, &g) || cx.refined(f, id, d, &g).is_none_or(|n| !zero(&n)) {
        return None;
    }
    let span = cx.span(f, d);
    if span.is_empty() {
        return None;
    }
    let what = cx.what(f, id, d);
    let sign = if op == Bo::Divide { "/" } else { "%" };
    let one = if kind == Some(ScalarKind::Uint) {
        "1u"
    } else {
        "1"
    };
    let diag = Diagnostic::rule_warning(
        DomainIntegerDivision::RULE.id,
        format!("integer `{sign}` by a value that can be 0, which is undefined"),
        span,
    )
    .with_label(format!("{what} can be 0"))
    .with_note("GLSL ES 3.00 §5.9: integer division by zero gives an undefined result")
    .with_help(format!("keep the divisor at least {one}, or test it first"))
    .with_fix(Fix::suggested(
        format!("wrap the divisor in `max(…, {one})`"),
        span,
        format!("max({}, {one})", cx.text(span)),
    ));
    Some(cx.grade(diag, &[(id, d)]))
}

/// The finding for an operand `o` of the `int` remainder `h` that the shader's own arithmetic
/// can make negative (an input as such is the caller's, as for `pow-negative-base`).
fn negative(cx: &Cx, f: &Function, id: usize, h: Handle<E>, o: Handle<E>) -> Option<Diagnostic> {
    let neg = |n: &crate::value::Num| n.hull().lo < 0.0 && !n.facts.has(Facts::NN);
    if !cx.sound().num(id, o).is_some_and(neg) {
        return None;
    }
    let r = cx.refined(f, id, o, &cx.guards(f, id, h))?;
    let span = cx.span(f, o);
    if !neg(&r) || span.is_empty() {
        return None;
    }
    let what = cx.what(f, id, o);
    let lo = r.hull().lo;
    let how = if lo > -1e6 {
        format!("{what} can be as low as {}", super::fmt_num(lo))
    } else {
        format!("{what} can be negative")
    };
    let diag = Diagnostic::rule_warning(
        DomainIntegerDivision::RULE.id,
        "integer `%` of a value that can be negative, which is undefined",
        span,
    )
    .with_label(how)
    .with_note(
        "GLSL ES 3.00 §5.9: the results of `%` are undefined if one or both operands are negative",
    )
    .with_help(
        "keep both operands non-negative (an offset by a multiple of the divisor), or take the \
         remainder in float: `int(mod(float(a), float(n)))`, exact below 2^24",
    );
    Some(cx.grade(diag, &[(id, o)]))
}
