//! Derivatives after a `discard` that some pixels of a quad take: the rest of the function runs
//! for the others only, so the specification leaves its derivatives undefined (SPIR-V's
//! `OpKill` ends the discarded invocations; `OpDemoteToHelperInvocation` exists because of it).
//! Most GPUs keep discarded pixels running as helpers, which is why alpha-tested shaders work:
//! these are [`Finding::after_discard`] findings, a note rather than a warning, and a variable
//! written after the `discard` is not taken to vary (the pixels still running agree on it).
//!
//! The walk follows each function's statements in order; a `discard` under a condition that
//! varies (or in a loop or `switch` that does) marks what follows it in its block and in the
//! blocks around it, and the functions called there (and those they call): Cesium's billboard
//! shader reads its SDF atlas in `getDistance`, called after `doDepthTest`'s `discard`. A
//! `discard` in a called function marks the rest of that function only.

use essl::hir::visit::{self, Visitor};
use essl::hir::{Cond, Expr, ExprKind, Stmt, StmtKind};

use super::{takes_derivatives, Finding, Reason, Uniformity};

impl Uniformity<'_> {
    /// Adds the derivatives and implicit-LOD lookups that follow a `discard` some pixels take,
    /// and that no varying condition already explains.
    pub(super) fn after_discards(&mut self) {
        let m = self.m;
        for (fid, f) in m.functions.iter().enumerate() {
            if !f.used {
                continue;
            }
            self.fid = fid;
            let mut after = None;
            self.seq(&f.body, &mut after, false);
        }
    }

    /// Walks `ss` in order: where `after` holds a `discard`, records the derivatives of each
    /// statement; sets it at a statement that discards some pixels only (`under`: inside
    /// control flow that varies).
    fn seq(&mut self, ss: &[Stmt], after: &mut Option<Reason>, under: bool) {
        for s in ss {
            if let Some(why) = *after {
                self.record_derivatives(s, why);
                continue;
            }
            match &s.kind {
                StmtKind::Block(b) => self.seq(b, after, under),
                StmtKind::If(c, a, b) => {
                    let under = under || self.varies(c);
                    // The branches exclude each other: a `discard` in one does not precede the
                    // other.
                    let (mut xa, mut xb) = (None, None);
                    self.seq(a, &mut xa, under);
                    self.seq(b, &mut xb, under);
                    *after = xa.or(xb);
                }
                StmtKind::Loop { cond, body, .. } => {
                    let varies = match cond.as_deref() {
                        Some(Cond::Expr(e) | Cond::Decl(_, e)) => self.varies(e),
                        None => false,
                    };
                    let mut x = None;
                    self.seq(body, &mut x, under || varies);
                    *after = x;
                }
                StmtKind::Switch(sel, cases) => {
                    let under = under || self.varies(sel);
                    for c in cases {
                        let mut x = None;
                        self.seq(&c.body, &mut x, under);
                        *after = after.or(x);
                    }
                }
                StmtKind::Discard if under => {
                    *after = Some(Reason {
                        span: s.span,
                        what: "this `discard` is taken by some pixels only",
                    });
                }
                _ => {}
            }
        }
    }

    /// Records every derivative and implicit-LOD lookup in `s`, and in the functions it calls
    /// (each function once in the whole walk, `why` then its first call), not already found.
    fn record_derivatives(&mut self, s: &Stmt, why: Reason) {
        let mut calls = Calls::default();
        calls.visit_stmt(s);
        let mut pending: Vec<(usize, Reason)> = calls
            .functions
            .iter()
            .map(|&(f, span)| (f, Self::called_after(span)))
            .collect();
        self.record(&calls.builtins, why);
        while let Some((f, why)) = pending.pop() {
            if f >= self.m.functions.len() || !self.walked_after.insert(f) {
                continue;
            }
            let mut inner = Calls::default();
            for s in &self.m.functions[f].body {
                inner.visit_stmt(s);
            }
            self.record(&inner.builtins, why);
            pending.extend(inner.functions.iter().map(|&(g, _)| (g, why)));
        }
    }

    /// The reason for what a function called after a `discard` runs: the call.
    fn called_after(span: essl::source::Span) -> Reason {
        Reason {
            span,
            what: "called here after a `discard` some pixels take",
        }
    }

    fn record(&mut self, builtins: &[(essl::source::Span, essl::hir::BuiltinFn)], why: Reason) {
        for &(span, op) in builtins {
            if self.found.iter().any(|f| f.span == span) {
                continue;
            }
            self.found.push(Finding {
                span,
                op,
                why,
                after_discard: true,
            });
        }
    }
}

/// The built-ins that take derivatives, with their spans, and the user functions called, with
/// the calls' spans, in source order.
#[derive(Default)]
struct Calls {
    builtins: Vec<(essl::source::Span, essl::hir::BuiltinFn)>,
    functions: Vec<(usize, essl::source::Span)>,
}

impl Visitor for Calls {
    fn visit_expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Builtin(op, _) if takes_derivatives(*op) => {
                self.builtins.push((e.span, *op));
            }
            ExprKind::Call(f, _) => self.functions.push((*f, e.span)),
            _ => {}
        }
        visit::walk_expr(self, e);
    }
}
