//! The values a loop counter takes: `for (int i = 0; i < 3; i++)` runs its body with `i` in
//! 0..=2, so `v[i] = …` there writes `v.x`, `v.y` and `v.z` of a `vec4`, and not `v.w`
//! (three.js's dispersion loop writes `transmittedLight[ i ]` for `i < 3` and then reads
//! `transmittedLight.a`). A counter is a local the loop's initializer sets to a constant and
//! its condition compares with a constant, which its step moves towards the bound by a
//! constant and its body never writes (nor passes to a function's `out` or `inout`
//! parameter); anything else gives no range, and a write through the index then counts for
//! every component, as before. Here too: whether a loop with constant bounds runs its body at
//! least once.

use essl::hir::visit::{self, Visitor};
use essl::hir::{self, BinaryOp, Cond, Expr, ExprKind, ParamMode, Stmt, StmtKind};

/// The counter of a loop and the values it takes in the body, inclusive.
pub(super) fn counter_range(
    m: &hir::Module,
    init: &[Stmt],
    cond: Option<&Cond>,
    step: Option<&Expr>,
    body: &[Stmt],
) -> Option<(usize, i64, i64)> {
    let (op, i, start, bound) = constant_bounds(init, cond)?;
    let (start, bound) = (whole(start)?, whole(bound)?);
    let up = step_sign(step?, i)?;
    let (lo, hi) = match (op, up) {
        (BinaryOp::Less, true) => (start, bound - 1),
        (BinaryOp::LessEq, true) => (start, bound),
        (BinaryOp::Greater, false) => (bound + 1, start),
        (BinaryOp::GreaterEq, false) => (bound, start),
        _ => return None,
    };
    if lo > hi {
        return None;
    }
    let mut w = Writes {
        m,
        local: i,
        found: false,
    };
    w.visit_stmts(body);
    (!w.found).then_some((i, lo, hi))
}

/// An integer-valued constant.
fn whole(x: f64) -> Option<i64> {
    (x.fract() == 0.0 && x.abs() < 1e9).then_some(x as i64)
}

/// Whether a loop's step moves local `i` up (`true`) or down by a constant.
fn step_sign(step: &Expr, i: usize) -> Option<bool> {
    let is_i = |e: &Expr| matches!(e.kind, ExprKind::Local(j) if j == i);
    match &step.kind {
        ExprKind::IncDec(inc, _, x) if is_i(x) => Some(*inc),
        ExprKind::Assign(Some(op), x, c) if is_i(x) => {
            let c = c.as_const().and_then(scalar)?;
            match op {
                BinaryOp::Add if c > 0.0 => Some(true),
                BinaryOp::Sub if c > 0.0 => Some(false),
                _ => None,
            }
        }
        _ => None,
    }
}

/// Finds a write to a local in a loop's body, or a call that may write it through an `out` or
/// `inout` parameter.
struct Writes<'m> {
    m: &'m hir::Module,
    local: usize,
    found: bool,
}

impl Writes<'_> {
    /// Whether a call passes the local to an `out` or `inout` parameter (or to a function the
    /// module does not describe).
    fn writes_through(&self, callee: usize, args: &[Expr]) -> bool {
        let Some(f) = self.m.functions.get(callee) else {
            return args.iter().any(|a| self.names(a));
        };
        args.iter()
            .enumerate()
            .any(|(i, a)| self.names(a) && f.params.get(i).is_none_or(|p| p.mode != ParamMode::In))
    }

    fn names(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Local(j) => *j == self.local,
            ExprKind::Swizzle(b, _) | ExprKind::Index(b, _) | ExprKind::Member(b, _) => {
                self.names(b)
            }
            _ => false,
        }
    }
}

impl Visitor for Writes<'_> {
    fn visit_expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Assign(_, lhs, _) | ExprKind::IncDec(_, _, lhs) if self.names(lhs) => {
                self.found = true;
            }
            ExprKind::Call(callee, args) if self.writes_through(*callee, args) => {
                self.found = true;
            }
            _ => visit::walk_expr(self, e),
        }
    }
}

/// A `for` loop's counter and constant bounds: the comparison, the local it tests, the constant
/// the initializer gives it and the constant it is compared with (`for (int i = 0; i < 4; …)`).
pub(super) fn constant_bounds(
    init: &[Stmt],
    cond: Option<&Cond>,
) -> Option<(BinaryOp, usize, f64, f64)> {
    let Some(Cond::Expr(Expr {
        kind: ExprKind::Binary(op, l, r),
        ..
    })) = cond
    else {
        return None;
    };
    let ExprKind::Local(i) = l.kind else {
        return None;
    };
    let bound = r.as_const().and_then(scalar)?;
    let start = init.iter().find_map(|s| match &s.kind {
        StmtKind::Local(j, Some(e)) if *j == i => e.as_const().and_then(scalar),
        _ => None,
    })?;
    Some((*op, i, start, bound))
}

/// Whether a `for` loop's constant bounds let its body run at least once:
/// `for (int i = 0; i < 4; …)` (an initializer and a comparison with constants).
pub(super) fn runs_once(init: &[Stmt], cond: Option<&Cond>) -> bool {
    let Some((op, _, c, n)) = constant_bounds(init, cond) else {
        return false;
    };
    match op {
        BinaryOp::Less => c < n,
        BinaryOp::LessEq => c <= n,
        BinaryOp::Greater => c > n,
        BinaryOp::GreaterEq => c >= n,
        BinaryOp::NotEq => c != n,
        _ => false,
    }
}

/// The value of a scalar constant.
pub(super) fn scalar(c: &hir::ConstValue) -> Option<f64> {
    match c.scalars()? {
        [s] => Some(s.as_f64()),
        _ => None,
    }
}
