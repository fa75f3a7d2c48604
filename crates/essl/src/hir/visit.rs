//! Walking a checked module's statements and expressions in source order, so that a pass that
//! looks at some kinds of node overrides only those ([`Visitor`]) and every other kind is
//! walked the same way everywhere (the editor's index, the lints' precision pass).
//!
//! As in `syn` and rust-analyzer: a visitor's `visit_*` methods default to the `walk_*`
//! functions, which visit the node's children; an override that still wants the children
//! calls the `walk_*` function itself.
//!
//! ```
//! use essl::hir::visit::{self, Visitor};
//! use essl::hir::{Expr, ExprKind};
//! use essl::source::SourceFile;
//!
//! /// Counts the calls of built-in functions.
//! struct Builtins(usize);
//! impl Visitor for Builtins {
//!     fn visit_expr(&mut self, e: &Expr) {
//!         if matches!(e.kind, ExprKind::Builtin(..)) {
//!             self.0 += 1;
//!         }
//!         visit::walk_expr(self, e);
//!     }
//! }
//!
//! let text = "#version 300 es\nprecision mediump float;\nuniform float t;\nout vec4 c;\n\
//!             void main() { c = vec4(sin(t) + cos(t)); }\n";
//! let shader = essl::compile(SourceFile::new("a.frag", text), essl::Stage::Fragment, &Default::default());
//! let mut count = Builtins(0);
//! for f in &shader.module.functions {
//!     count.visit_stmts(&f.body);
//! }
//! assert_eq!(count.0, 2);
//! ```

use super::{Cond, Expr, ExprKind, Stmt, StmtKind};

/// A pass over statements and expressions; each method defaults to walking the children.
pub trait Visitor {
    /// A list of statements (a function body, a block, a branch).
    fn visit_stmts(&mut self, stmts: &[Stmt]) {
        walk_stmts(self, stmts);
    }

    /// One statement.
    fn visit_stmt(&mut self, s: &Stmt) {
        walk_stmt(self, s);
    }

    /// One expression.
    fn visit_expr(&mut self, e: &Expr) {
        walk_expr(self, e);
    }
}

/// Visits each statement of `stmts` in order.
pub fn walk_stmts<V: Visitor + ?Sized>(v: &mut V, stmts: &[Stmt]) {
    for s in stmts {
        v.visit_stmt(s);
    }
}

/// Visits the expressions and statement lists directly inside `s`, in source order (a loop's
/// initialiser, condition, step, then body).
pub fn walk_stmt<V: Visitor + ?Sized>(v: &mut V, s: &Stmt) {
    match &s.kind {
        StmtKind::Expr(e) | StmtKind::Local(_, Some(e)) | StmtKind::Return(Some(e)) => {
            v.visit_expr(e)
        }
        StmtKind::Block(b) => v.visit_stmts(b),
        StmtKind::If(c, a, b) => {
            v.visit_expr(c);
            v.visit_stmts(a);
            v.visit_stmts(b);
        }
        StmtKind::Loop {
            init,
            cond,
            step,
            body,
            ..
        } => {
            v.visit_stmts(init);
            if let Some(Cond::Expr(e) | Cond::Decl(_, e)) = cond.as_deref() {
                v.visit_expr(e);
            }
            if let Some(e) = step {
                v.visit_expr(e);
            }
            v.visit_stmts(body);
        }
        StmtKind::Switch(e, cases) => {
            v.visit_expr(e);
            for c in cases {
                v.visit_stmts(&c.body);
            }
        }
        StmtKind::Local(_, None)
        | StmtKind::Return(None)
        | StmtKind::Break
        | StmtKind::Continue
        | StmtKind::Discard => {}
    }
}

/// Visits the operands of `e`, left to right.
pub fn walk_expr<V: Visitor + ?Sized>(v: &mut V, e: &Expr) {
    match &e.kind {
        ExprKind::Call(_, args) | ExprKind::Builtin(_, args) | ExprKind::Construct(args) => {
            args.iter().for_each(|a| v.visit_expr(a))
        }
        ExprKind::Unary(_, a)
        | ExprKind::Member(a, _)
        | ExprKind::Swizzle(a, _)
        | ExprKind::IncDec(_, _, a) => v.visit_expr(a),
        ExprKind::Binary(_, a, b)
        | ExprKind::Assign(_, a, b)
        | ExprKind::Comma(a, b)
        | ExprKind::Index(a, b) => {
            v.visit_expr(a);
            v.visit_expr(b);
        }
        ExprKind::Select(c, a, b) => {
            v.visit_expr(c);
            v.visit_expr(a);
            v.visit_expr(b);
        }
        ExprKind::BlockMember(_, Some(i), _) => v.visit_expr(i),
        ExprKind::BlockMember(_, None, _)
        | ExprKind::Error
        | ExprKind::Const(_)
        | ExprKind::Local(_)
        | ExprKind::Param(_)
        | ExprKind::Global(_)
        | ExprKind::BuiltinVar(_) => {}
    }
}
