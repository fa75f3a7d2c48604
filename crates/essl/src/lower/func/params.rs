//! Which `in` parameters a function writes. GLSL lets a function assign its `in` parameters,
//! so the lowering copies each into a local; a scalar or vector parameter the body never
//! writes is read straight from its argument instead, which leaves the lowered function (and
//! what naga validates and the lints walk) a local, a store and a load per use smaller.

use crate::builtins::BuiltinFn;
use crate::hir::visit::{self, Visitor};
use crate::hir::{self, Expr, ExprKind, ParamMode};
use crate::types::Type;

/// For each parameter of `f`: whether it can be read from its argument — an `in` scalar or
/// vector that nothing in the body assigns, increments, or passes as an `out` or `inout`
/// argument (or as `modf`'s second argument).
pub(super) fn read_in_place(m: &hir::Module, f: &hir::Function) -> Vec<bool> {
    let mut w = Writes {
        module: m,
        written: vec![false; f.params.len()],
    };
    w.visit_stmts(&f.body);
    f.params
        .iter()
        .zip(&w.written)
        .map(|(p, &written)| {
            !written
                && p.mode == ParamMode::In
                && matches!(p.ty, Type::Scalar(_) | Type::Vector(..))
        })
        .collect()
}

/// The parameters a body writes.
struct Writes<'m> {
    module: &'m hir::Module,
    written: Vec<bool>,
}

impl Writes<'_> {
    /// Marks the parameter that the write target `e` is (part of).
    fn target(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Param(i) => {
                if let Some(w) = self.written.get_mut(*i) {
                    *w = true;
                }
            }
            ExprKind::Index(b, _) | ExprKind::Member(b, _) | ExprKind::Swizzle(b, _) => {
                self.target(b)
            }
            _ => {}
        }
    }
}

impl Visitor for Writes<'_> {
    fn visit_expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Assign(_, l, _) | ExprKind::IncDec(_, _, l) => self.target(l),
            ExprKind::Call(id, args) => {
                if let Some(callee) = self.module.functions.get(*id) {
                    for (a, p) in args.iter().zip(&callee.params) {
                        if p.mode != ParamMode::In {
                            self.target(a);
                        }
                    }
                }
            }
            ExprKind::Builtin(BuiltinFn::Modf, args) => {
                if let Some(a) = args.get(1) {
                    self.target(a);
                }
            }
            _ => {}
        }
        visit::walk_expr(self, e);
    }
}
