//! The preconditions of each kind of expression at risk (`smoothstep`, a division,
//! `normalize`, `pow`, `acos` / `asin`) and of every uniform read (finite values).

use essl::source::Span;
use naga::{
    BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf, ScalarKind,
};

use super::extract::{as_num, Context, Extractor};
use super::{Condition, Precision, Precondition, UniformRef, DIVISION_BY_ZERO, NON_FINITE_UNIFORM};
use crate::interval::Interval;
use crate::symbolic::{resolve, Sym};

/// An expression whose preconditions are extracted: where it is, its span and precision.
#[derive(Clone, Copy)]
struct At<'a> {
    /// The function's index.
    id: usize,
    /// The function.
    f: &'a Function,
    /// The expression.
    h: Handle<E>,
    /// Its span (not empty).
    span: Span,
    /// Whether it is computed in low precision.
    low: bool,
    /// The symbolic view of the function.
    sym: &'a Sym<'a>,
}

impl Extractor<'_> {
    fn precondition(
        &self,
        rule: &'static str,
        condition: Condition,
        span: Span,
        ctx: &Context,
        low: bool,
        message: String,
    ) -> Precondition {
        Precondition {
            rule,
            condition,
            span,
            stage: self.stage,
            call_sites: ctx.sites.clone(),
            precision: if low { Precision::Low } else { Precision::High },
            message,
            reported: false,
        }
    }

    fn quote(&self, span: Span) -> String {
        let t: String = self
            .cx
            .text(span)
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        if t.chars().count() > 60 {
            format!("{}…", t.chars().take(59).collect::<String>())
        } else {
            t
        }
    }

    /// The preconditions of the expressions of one function.
    pub(super) fn function(&self, id: usize, f: &Function, out: &mut Vec<Precondition>) {
        let cx = self.cx;
        let sym = cx.sym(id, f);
        for (h, e) in f.expressions.iter() {
            let span = cx.span(f, h);
            if span.is_empty() {
                continue;
            }
            let at = At {
                id,
                f,
                h,
                span,
                low: cx.prec.is_low(span),
                sym: &sym,
            };
            match *e {
                E::Math {
                    fun: Mf::SmoothStep,
                    arg,
                    arg1: Some(a1),
                    ..
                } => self.smoothstep(&at, arg, a1, out),
                E::Binary {
                    op: Bo::Divide,
                    right,
                    ..
                } => self.division(&at, right, out),
                E::Math {
                    fun: Mf::Normalize,
                    arg,
                    ..
                } => self.normalize(&at, arg, out),
                E::Math {
                    fun: Mf::Pow,
                    arg,
                    arg1: Some(y),
                    ..
                } => self.pow(&at, arg, y, out),
                E::Math {
                    fun: fun @ (Mf::Acos | Mf::Asin),
                    arg,
                    ..
                } => self.inverse_trig(&at, fun, arg, out),
                _ => {}
            }
        }
    }

    /// `smoothstep(edge0, edge1, x)`: [`Condition::Less`] on edges the shader does not order.
    fn smoothstep(&self, at: &At, arg: Handle<E>, a1: Handle<E>, out: &mut Vec<Precondition>) {
        let At {
            id,
            f,
            h,
            span,
            low,
            ..
        } = *at;
        let cx = self.cx;
        let (e0, e1) = (cx.operand(f, h, arg), cx.operand(f, h, a1));
        let constant = |x: Handle<E>| {
            cx.sound()
                .num(id, x)
                .is_some_and(|v| v.comps().iter().all(|c| c.as_point().is_some()))
        };
        if (constant(e0) && constant(e1))
            || at.sym.diff_lower(Some(e1), Some(e0)) > 0.0
            || cx.ordered(f, id, e0, e1, &cx.guards(f, id, h))
        {
            return;
        }
        for ctx in self.contexts(id, 0) {
            let (Some(t0), Some(t1)) = (
                self.value(id, &ctx, e0, 0).and_then(as_num),
                self.value(id, &ctx, e1, 0).and_then(as_num),
            ) else {
                continue;
            };
            if t0.uniforms().is_empty() && t1.uniforms().is_empty() {
                continue;
            }
            out.push(
                self.precondition(
                    "smoothstep-edges",
                    Condition::Less(t0, t1),
                    span,
                    &ctx,
                    low,
                    "`smoothstep(edge0, edge1, x)` is undefined unless edge0 < edge1 \
                     (GLSL ES 3.00 §8.3): NaN where x equals the edges, or a hard or \
                     inverted edge"
                        .into(),
                ),
            );
        }
    }

    /// `x / d`: [`Condition::NotEqual`] for `d = a - b`, else [`Condition::NonZero`].
    fn division(&self, at: &At, right: Handle<E>, out: &mut Vec<Precondition>) {
        let At { id, f, h, low, .. } = *at;
        let cx = self.cx;
        let d = cx.operand(f, h, right);
        if !matches!(
            cx.kind(id, d),
            Some(ScalarKind::Float | ScalarKind::Sint | ScalarKind::Uint)
        ) || at.sym.nonzero(d)
        {
            return;
        }
        let g = cx.guards(f, id, h);
        let may_be_zero = || {
            cx.refined(f, id, d, &g)
                .is_some_and(|v| v.comps().iter().any(|c| c.contains(0.0)))
        };
        if cx.nonzero(f, id, d, &g) || !may_be_zero() {
            return;
        }
        let dspan = cx.span(f, d);
        if dspan.is_empty() {
            return;
        }
        let def = resolve(f, cx.sound(), id, d);
        for ctx in self.contexts(id, 0) {
            let Some(t) = self.term(id, &ctx, d) else {
                continue;
            };
            let diff = match f.expressions[def] {
                E::Binary {
                    op: Bo::Subtract,
                    left,
                    right,
                } => self
                    .value(id, &ctx, left, 0)
                    .and_then(as_num)
                    .zip(self.value(id, &ctx, right, 0).and_then(as_num)),
                _ => None,
            };
            let p = match diff {
                Some((a, b)) => {
                    let msg = format!(
                        "division by `{}` = `{a} - {b}`: ±∞ when they are equal, \
                             NaN where the numerator is 0 too",
                        self.quote(dspan)
                    );
                    self.precondition(
                        "division-by-difference",
                        Condition::NotEqual(a, b),
                        dspan,
                        &ctx,
                        low,
                        msg,
                    )
                }
                None => {
                    let msg = format!(
                        "division by `{}`, computed from uniforms: ±∞, or NaN, \
                             when it is 0",
                        self.quote(dspan)
                    );
                    self.precondition(
                        DIVISION_BY_ZERO,
                        Condition::NonZero(t),
                        dspan,
                        &ctx,
                        low,
                        msg,
                    )
                }
            };
            out.push(p);
        }
    }

    /// `normalize(v)`: [`Condition::NotParallel`] for `v = cross(a, b)`, else [`Condition::NonZeroVector`].
    fn normalize(&self, at: &At, arg: Handle<E>, out: &mut Vec<Precondition>) {
        let At { id, f, h, low, .. } = *at;
        let cx = self.cx;
        let x = cx.operand(f, h, arg);
        let g = cx.guards(f, id, h);
        if !cx.refined(f, id, x, &g).is_some_and(|v| v.may_be_zero()) {
            return;
        }
        let xspan = cx.span(f, x);
        if xspan.is_empty() {
            return;
        }
        let def = resolve(f, cx.sound(), id, x);
        let cross = match f.expressions[def] {
            E::Math {
                fun: Mf::Cross,
                arg: a,
                arg1: Some(b),
                ..
            } if !crate::rules::orthogonal_cross(cx, f, id, x) => Some((a, b)),
            _ => None,
        };
        for ctx in self.contexts(id, 0) {
            let Some(t) = self.term(id, &ctx, x) else {
                continue;
            };
            let pair = cross.and_then(|(a, b)| {
                self.value(id, &ctx, a, 0)
                    .and_then(as_num)
                    .zip(self.value(id, &ctx, b, 0).and_then(as_num))
            });
            let p = match pair {
                Some((a, b)) => self.precondition(
                    "normalize-zero",
                    Condition::NotParallel(a, b),
                    xspan,
                    &ctx,
                    low,
                    "`normalize(cross(a, b))` of parallel (or zero) vectors is \
                         `normalize` of the zero vector: NaN for the whole draw"
                        .into(),
                ),
                None => self.precondition(
                    "normalize-zero",
                    Condition::NonZeroVector(t),
                    xspan,
                    &ctx,
                    low,
                    format!(
                        "`normalize({})` of the zero vector is 0 / 0: NaN in every \
                             component, for the whole draw",
                        self.quote(xspan)
                    ),
                ),
            };
            out.push(p);
        }
    }

    /// `pow(x, y)`: [`Condition::NonNegative`] on the base, and [`Condition::PowBaseZero`] (or [`Condition::Positive`]) where the base can be 0.
    fn pow(&self, at: &At, arg: Handle<E>, y: Handle<E>, out: &mut Vec<Precondition>) {
        let At {
            id,
            f,
            h,
            span,
            low,
            ..
        } = *at;
        let cx = self.cx;
        let (base, exp) = (cx.operand(f, h, arg), cx.operand(f, h, y));
        let g = cx.guards(f, id, h);
        let (Some(rb), Some(re)) = (cx.refined(f, id, base, &g), cx.refined(f, id, exp, &g)) else {
            return;
        };
        let negative = rb.hull().lo < 0.0;
        let zero = rb.hull().contains(0.0) && !cx.nonzero(f, id, base, &g);
        let nonpositive = re.hull().lo <= 0.0;
        let bspan = cx.span(f, base);
        for ctx in self.contexts(id, 0) {
            let tb = self.term(id, &ctx, base);
            let te = self.term(id, &ctx, exp);
            if let (Some(tb), true, false) = (&tb, negative, bspan.is_empty()) {
                out.push(self.precondition(
                    "pow-negative-base",
                    Condition::NonNegative(tb.clone()),
                    bspan,
                    &ctx,
                    low,
                    "`pow(x, y)` is undefined for x < 0 (GLSL ES 3.00 §8.2): NaN".into(),
                ));
            }
            if !(zero && nonpositive) {
                continue;
            }
            let condition = match (tb, te) {
                (Some(b), Some(e)) => Condition::PowBaseZero {
                    base: b,
                    exponent: e,
                },
                (None, Some(e)) => Condition::Positive(e),
                _ => continue,
            };
            out.push(self.precondition(
                "pow-zero-base",
                condition,
                span,
                &ctx,
                low,
                format!(
                    "`pow(x, y)` is undefined for x = 0 and y ≤ 0 (GLSL ES 3.00 §8.2), \
                         and the base `{}` can be 0: NaN for y = 0, +∞ for y < 0",
                    self.quote(bspan)
                ),
            ));
        }
    }

    /// `acos(x)`, `asin(x)`: [`Condition::WithinUnit`].
    fn inverse_trig(&self, at: &At, fun: Mf, arg: Handle<E>, out: &mut Vec<Precondition>) {
        let At { id, f, h, low, .. } = *at;
        let cx = self.cx;
        let x = cx.operand(f, h, arg);
        let g = cx.guards(f, id, h);
        let Some(v) = cx.refined(f, id, x, &g) else {
            return;
        };
        let xspan = cx.span(f, x);
        if v.hull().within(Interval::SIGNED_UNIT) || xspan.is_empty() {
            return;
        }
        let (rule, name) = if fun == Mf::Acos {
            ("acos-domain", "acos")
        } else {
            ("asin-domain", "asin")
        };
        for ctx in self.contexts(id, 0) {
            let Some(t) = self.term(id, &ctx, x) else {
                continue;
            };
            out.push(self.precondition(
                rule,
                Condition::WithinUnit(t),
                xspan,
                &ctx,
                low,
                format!("`{name}(x)` is undefined for |x| > 1 (GLSL ES 3.00 §8.1): NaN"),
            ));
        }
    }

    /// [`Condition::Finite`] for every uniform (or part) the shader reads, at its first read.
    pub(super) fn finite(&self, out: &mut Vec<Precondition>) {
        let mut first: Vec<(UniformRef, Span, bool)> = Vec::new();
        for (id, f) in self.cx.functions() {
            for (h, e) in f.expressions.iter() {
                let E::Load { pointer } = *e else { continue };
                let Some(r) = self.uniform_of_pointer(id, pointer) else {
                    continue;
                };
                let span = self.cx.span(f, h);
                if span.is_empty() {
                    continue;
                }
                let low = self.cx.prec.is_low(span);
                match first.iter_mut().find(|(u, _, _)| *u == r) {
                    Some(slot) if span.start < slot.1.start => *slot = (r, span, low),
                    Some(_) => {}
                    None => first.push((r, span, low)),
                }
            }
        }
        for (r, span, low) in first {
            out.push(
                self.precondition(
                    NON_FINITE_UNIFORM,
                    Condition::Finite(r),
                    span,
                    &Context::default(),
                    low,
                    "a NaN or infinite uniform value spreads through everything computed from it"
                        .into(),
                ),
            );
        }
    }
}
