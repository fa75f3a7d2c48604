//! `domain-integer-division`: integer `/` or `%` by a value that can be 0.

use essl::diagnostic::{Diagnostic, Fix};
use naga::{BinaryOperator as Bo, Expression as E, ScalarKind};

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
    /// - Float division (see `division-by-difference`).
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard; a note, naming
    /// the uniform, when one uniform alone (with constants) does — a column count of 0 is the host's
    /// mistake, which essl-gl's validation mode checks at each draw.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §5.9 Expressions: for `/` and `%` of integers, a zero divisor
    ///   gives an undefined result.
    pub(crate) struct DomainIntegerDivision {
        id: "domain-integer-division",
        summary: "integer `/` or `%` by a value that can be 0",
        default_level: Level::Warn,
        check: check,
    }
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for (id, f) in cx.functions() {
        for (h, e) in f.expressions.iter() {
            let E::Binary {
                op: op @ (Bo::Divide | Bo::Modulo),
                right,
                ..
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
            let zero = |n: &crate::value::Num| {
                n.comps().iter().any(|c| c.contains(0.0)) && !(n.n == 1 && n.facts.has(Facts::NZ))
            };
            if !cx.sound().num(id, d).is_some_and(zero) || cx.sym(id, f).nonzero(d) {
                continue;
            }
            let g = cx.guards(f, id, h);
            if cx.nonzero(f, id, d, &g) || cx.refined(f, id, d, &g).is_none_or(|n| !zero(&n)) {
                continue;
            }
            let span = cx.span(f, d);
            if span.is_empty() {
                continue;
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
            out.push(cx.grade(diag, &[(id, d)]));
        }
    }
}
