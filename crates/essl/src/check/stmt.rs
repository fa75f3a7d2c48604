//! Statements: control flow, loops, `switch`, `return`, `discard`.

use super::{Checker, Sym, Var};
use crate::ast;
use crate::diagnostic::Fix;
use crate::diagnostic_code::Code;
use crate::hir::{self, Cond, StmtKind};
use crate::types::{ScalarKind, Type};
use crate::Stage;

impl Checker<'_> {
    /// Checks statements in the current scope (a function body, a loop body).
    pub(super) fn block_stmts_same_scope(&mut self, stmts: &[ast::Stmt]) -> Vec<hir::Stmt> {
        let mut out = Vec::new();
        for s in stmts {
            self.stmt_into(s, &mut out);
        }
        out
    }

    fn scoped(&mut self, s: &ast::Stmt) -> Vec<hir::Stmt> {
        self.push_scope();
        let mut out = Vec::new();
        self.stmt_into(s, &mut out);
        self.pop_scope();
        out
    }

    /// A loop body: a compound statement shares the scope of the loop header.
    fn loop_body(&mut self, s: &ast::Stmt) -> Vec<hir::Stmt> {
        match &s.kind {
            ast::StmtKind::Block(b) => self.block_stmts_same_scope(&b.stmts),
            _ => {
                let mut out = Vec::new();
                self.stmt_into(s, &mut out);
                out
            }
        }
    }

    /// Checks a boolean condition.
    fn condition_expr(&mut self, e: &ast::Expr, what: &str) -> hir::Expr {
        let c = self.expr(e);
        if !super::expr::is_error(&c) && c.ty != Type::BOOL {
            let ty = self.type_name(&c.ty);
            let d = self.error(
                Code::TypeMismatch,
                c.span,
                format!("{what} must be a `bool`, not {ty}"),
            );
            d.label = format!("this is {ty}");
            if c.ty.is_scalar() && c.ty.scalar_kind() != Some(ScalarKind::Bool) {
                d.help = Some("compare it explicitly, e.g. `x != 0`".into());
            }
        }
        c
    }

    fn loop_condition(&mut self, c: &ast::Condition) -> Cond {
        match c {
            ast::Condition::Expr(e) => Cond::Expr(self.condition_expr(e, "a loop condition")),
            ast::Condition::Decl(fty, name, init) => {
                self.check_name(name);
                let ty = self.resolve_type(&fty.spec).unwrap_or(Type::Void);
                let init = self.expr(init);
                if ty != Type::BOOL && ty != Type::Void {
                    let t = self.type_name(&ty);
                    let d = self.error(
                        Code::TypeMismatch,
                        fty.spec.span,
                        format!("a loop condition must be a `bool`, not {t}"),
                    );
                    d.label = "not `bool`".into();
                } else if !super::expr::is_error(&init) && init.ty != ty {
                    let (want, got) = (self.type_name(&ty), self.type_name(&init.ty));
                    let d = self.error(
                        Code::TypeMismatch,
                        init.span,
                        format!("cannot initialize a {want} with a {got}"),
                    );
                    d.label = format!("this is {got}");
                }
                let precision = None;
                let id = self.new_local(hir::Local {
                    name: name.name.clone(),
                    ty: Type::BOOL,
                    constant: None,
                    precision,
                    span: name.span,
                });
                self.declare(name, Sym::Var(Var::Local(id)));
                Cond::Decl(id, init)
            }
        }
    }

    fn stmt_into(&mut self, s: &ast::Stmt, out: &mut Vec<hir::Stmt>) {
        let span = s.span;
        let kind = match &s.kind {
            ast::StmtKind::Decl(d) => {
                out.extend(self.declaration(d, false));
                return;
            }
            ast::StmtKind::Expr(e) => StmtKind::Expr(self.expr(e)),
            ast::StmtKind::Block(b) => {
                self.push_scope();
                let stmts = self.block_stmts_same_scope(&b.stmts);
                self.pop_scope();
                StmtKind::Block(stmts)
            }
            ast::StmtKind::If(c, then, els) => {
                let c = self.condition_expr(c, "an `if` condition");
                let t = self.scoped(then);
                let e = els.as_ref().map(|e| self.scoped(e)).unwrap_or_default();
                StmtKind::If(c, t, e)
            }
            ast::StmtKind::While(c, body) => {
                self.es100_unsupported_loop("while", span);
                self.push_scope();
                let cond = self.loop_condition(c);
                self.fctx_mut().loops += 1;
                let body = self.loop_body(body);
                self.fctx_mut().loops -= 1;
                self.pop_scope();
                StmtKind::Loop {
                    init: Vec::new(),
                    cond: Some(Box::new(cond)),
                    step: None,
                    body,
                    do_while: false,
                }
            }
            ast::StmtKind::DoWhile(body, c) => {
                self.es100_unsupported_loop("do", span);
                self.fctx_mut().loops += 1;
                let body = self.scoped(body);
                self.fctx_mut().loops -= 1;
                let cond = self.condition_expr(c, "a loop condition");
                StmtKind::Loop {
                    init: Vec::new(),
                    cond: Some(Box::new(Cond::Expr(cond))),
                    step: None,
                    body,
                    do_while: true,
                }
            }
            ast::StmtKind::For {
                init,
                cond,
                step,
                body,
            } => {
                self.push_scope();
                let mut init_out = Vec::new();
                self.stmt_into(init, &mut init_out);
                let cond = cond.as_ref().map(|c| Box::new(self.loop_condition(c)));
                let step = step.as_ref().map(|e| self.expr(e));
                let index = self.es100_for_header(&init_out, cond.as_deref(), step.as_ref(), span);
                self.fctx_mut().loops += 1;
                let body = self.with_loop_index(index, |c| c.loop_body(body));
                self.fctx_mut().loops -= 1;
                self.pop_scope();
                StmtKind::Loop {
                    init: init_out,
                    cond,
                    step,
                    body,
                    do_while: false,
                }
            }
            ast::StmtKind::Switch(sel, body) => self.switch(sel, body, span),
            ast::StmtKind::Case(e) => {
                let d = self.error(
                    Code::CaseOutsideSwitch,
                    span,
                    "`case` label outside a `switch`",
                );
                d.label = "not directly inside a switch body".into();
                let _ = e;
                return;
            }
            ast::StmtKind::Default => {
                let d = self.error(
                    Code::CaseOutsideSwitch,
                    span,
                    "`default` label outside a `switch`",
                );
                d.label = "not directly inside a switch body".into();
                return;
            }
            ast::StmtKind::Continue => {
                if self.fctx_mut().loops == 0 {
                    let d =
                        self.error(Code::ContinueOutsideLoop, span, "`continue` outside a loop");
                    d.label = "no loop to continue".into();
                    return;
                }
                StmtKind::Continue
            }
            ast::StmtKind::Break => {
                let f = self.fctx_mut();
                if f.loops == 0 && f.switches == 0 {
                    let d = self.error(
                        Code::BreakOutsideLoop,
                        span,
                        "`break` outside a loop or `switch`",
                    );
                    d.label = "nothing to break out of".into();
                    return;
                }
                StmtKind::Break
            }
            ast::StmtKind::Return(e) => self.return_stmt(e.as_ref(), span),
            ast::StmtKind::Discard => {
                if self.stage != Stage::Fragment {
                    let d = self.error(
                        Code::DiscardInVertex,
                        span,
                        "`discard` is only allowed in fragment shaders",
                    );
                    d.label = "in a vertex shader".into();
                    d.token = "discard".into();
                    return;
                }
                StmtKind::Discard
            }
            ast::StmtKind::Empty | ast::StmtKind::Error => return,
        };
        out.push(hir::Stmt { kind, span });
    }

    fn fctx_mut(&mut self) -> &mut super::FnCtx {
        self.fctx
            .as_mut()
            .expect("statements are checked inside a function")
    }

    fn return_stmt(&mut self, e: Option<&ast::Expr>, span: crate::source::Span) -> StmtKind {
        let ret = self.fctx_mut().ret.clone();
        match e {
            None => {
                if ret != Type::Void {
                    let t = self.type_name(&ret);
                    let d = self.error(
                        Code::MissingReturnValue,
                        span,
                        format!("this function must return a {t}"),
                    );
                    d.label = "`return` without a value".into();
                    d.token = "return".into();
                }
                StmtKind::Return(None)
            }
            Some(e) => {
                let v = self.expr(e);
                if super::expr::is_error(&v) {
                    return StmtKind::Return(None);
                }
                if ret == Type::Void {
                    let d = self.error(
                        Code::ReturnValueInVoid,
                        v.span,
                        "a `void` function cannot return a value",
                    );
                    d.label = "a value returned".into();
                    d.token = "return".into();
                    return StmtKind::Return(None);
                }
                if v.ty != ret {
                    let (want, got) = (self.type_name(&ret), self.type_name(&v.ty));
                    let fix = super::expr::conversion_fix(self.file, &v, &ret);
                    let d = self.error(
                        Code::TypeMismatch,
                        v.span,
                        format!("this function returns {want}, not {got}"),
                    );
                    d.label = format!("this is {got}");
                    d.token = "return".into();
                    if let Some(f) = fix {
                        d.help = Some(f.message.clone());
                        d.fix = Some(f);
                    }
                    return StmtKind::Return(None);
                }
                StmtKind::Return(Some(v))
            }
        }
    }

    fn switch(
        &mut self,
        sel: &ast::Expr,
        body: &ast::Block,
        span: crate::source::Span,
    ) -> StmtKind {
        let selector = self.expr(sel);
        let sel_ty = selector.ty.clone();
        if !super::expr::is_error(&selector) && sel_ty != Type::INT && sel_ty != Type::UINT {
            let t = self.type_name(&sel_ty);
            let d = self.error(
                Code::TypeMismatch,
                selector.span,
                format!("a `switch` selector must be an `int` or `uint`, not {t}"),
            );
            d.label = format!("this is {t}");
        }
        self.push_scope();
        self.fctx_mut().switches += 1;
        let mut cases: Vec<hir::SwitchCase> = Vec::new();
        let mut seen: Vec<(i64, crate::source::Span)> = Vec::new();
        let mut seen_default: Option<crate::source::Span> = None;
        // Whether a statement that ANGLE keeps follows the latest label: it removes an `if`
        // whose condition is the constant `false` and that has no `else` as it parses it,
        // before it looks for a statement after the last label.
        let mut kept_after_label = false;
        for s in &body.stmts {
            match &s.kind {
                ast::StmtKind::Case(e) => {
                    kept_after_label = false;
                    let value = self.case_label(e, s.span, &sel_ty, &mut seen);
                    open_case(&mut cases, Some(value.unwrap_or(i64::MIN)), s.span);
                }
                ast::StmtKind::Default => {
                    if let Some(prev) = seen_default {
                        let d = self.error(
                            Code::DuplicateCase,
                            s.span,
                            "more than one `default` label",
                        );
                        d.label = "second `default`".into();
                        d.secondary.push(crate::diagnostic::Label {
                            span: prev,
                            message: "first here".into(),
                        });
                    }
                    seen_default = Some(s.span);
                    kept_after_label = false;
                    open_case(&mut cases, None, s.span);
                }
                _ => {
                    let mut stmts = Vec::new();
                    self.stmt_into(s, &mut stmts);
                    kept_after_label |= !self.removed_if(s, &stmts);
                    match cases.last_mut() {
                        Some(c) => c.body.extend(stmts),
                        None => {
                            if !matches!(s.kind, ast::StmtKind::Empty | ast::StmtKind::Error) {
                                let d = self.error(
                                    Code::StatementBeforeCase,
                                    s.span,
                                    "statements in a `switch` must come after a `case` or `default` label",
                                );
                                d.label = "before the first label".into();
                            }
                        }
                    }
                }
            }
        }
        self.fctx_mut().switches -= 1;
        self.pop_scope();
        self.check_label_at_end(body, kept_after_label);
        if let Some(last) = cases.last_mut() {
            last.fall_through = false;
        }
        let _ = span;
        // Cases with a failed label are dropped.
        cases.retain(|c| c.value != Some(i64::MIN));
        StmtKind::Switch(selector, cases)
    }

    /// A `case` label's value: a constant integer of the selector's type, not seen before in
    /// this `switch` (`seen` holds the values so far and where). `None` when invalid.
    fn case_label(
        &mut self,
        e: &ast::Expr,
        span: crate::source::Span,
        sel_ty: &Type,
        seen: &mut Vec<(i64, crate::source::Span)>,
    ) -> Option<i64> {
        let v = self.expr(e);
        let value = if super::expr::is_error(&v) {
            None
        } else if let Some(c) = v.as_const().and_then(|c| c.as_int()).filter(|_| {
            v.ty.is_scalar()
                && matches!(v.ty.scalar_kind(), Some(ScalarKind::Int | ScalarKind::Uint))
        }) {
            if v.ty != *sel_ty && (*sel_ty == Type::INT || *sel_ty == Type::UINT) {
                let (a, b) = (self.type_name(&v.ty), self.type_name(sel_ty));
                let d = self.error(
                    Code::TypeMismatch,
                    v.span,
                    format!("`case` label is {a} but the selector is {b}"),
                );
                d.label = format!("this is {a}");
            }
            Some(c)
        } else {
            let d = self.error(
                Code::NonConstantCase,
                v.span,
                "a `case` label must be a constant integer expression",
            );
            d.label = "not a constant integer".into();
            None
        };
        if let Some(c) = value {
            if let Some((_, prev)) = seen.iter().find(|(x, _)| *x == c) {
                let prev = *prev;
                let d = self.error(Code::DuplicateCase, span, format!("duplicate `case {c}`"));
                d.label = "already handled".into();
                d.secondary.push(crate::diagnostic::Label {
                    span: prev,
                    message: "first here".into(),
                });
            } else {
                seen.push((c, span));
            }
        }
        value
    }

    /// Whether `s` (checked into `stmts`) is an `if` without `else` whose condition ANGLE
    /// finds is the constant `false` as it parses it, and removes.
    fn removed_if(&self, s: &ast::Stmt, stmts: &[hir::Stmt]) -> bool {
        let ast::StmtKind::If(cond, _, None) = &s.kind else {
            return false;
        };
        self.folded_at_parse(cond)
            && matches!(
                stmts,
                [hir::Stmt { kind: StmtKind::If(c, _, _), .. }]
                    if c.as_const() == Some(&hir::ConstValue::Basic(vec![hir::Scalar::B(false)]))
            )
    }

    /// Whether ANGLE folds `e` to a constant as it parses it: literals and constant variables,
    /// and operators, built-in calls, constructors, indices and fields of such (a `?:` only when
    /// its three operands are; a `,` never, in GLSL ES 3.00). Where essl's checker folds more
    /// (`false ? u > 0 : false`), ANGLE keeps the `if` it would remove.
    fn folded_at_parse(&self, e: &ast::Expr) -> bool {
        use ast::ExprKind as K;
        match &e.kind {
            K::Int(..) | K::Float(_) | K::Bool(_) => true,
            K::Ident(id) => match self.lookup(&id.name) {
                Some(super::Sym::Var(super::Var::Local(l))) => self
                    .fctx
                    .as_ref()
                    .and_then(|f| f.locals.get(*l))
                    .is_some_and(|l| l.constant.is_some()),
                Some(super::Sym::Var(super::Var::Global(g))) => {
                    self.globals[*g].kind == hir::GlobalKind::Const
                }
                _ => false,
            },
            K::Unary(_, a) | K::Field(a, _) => self.folded_at_parse(a),
            K::Binary(_, a, b) | K::Index(a, b) => {
                self.folded_at_parse(a) && self.folded_at_parse(b)
            }
            K::Ternary(c, a, b) => {
                self.folded_at_parse(c) && self.folded_at_parse(a) && self.folded_at_parse(b)
            }
            K::Call(ast::Callee::Type(_), args) => args.iter().all(|a| self.folded_at_parse(a)),
            K::Call(ast::Callee::Name(n), args) => {
                // A user function's value is not a constant; a built-in's or a struct's is.
                !matches!(self.lookup(&n.name), Some(super::Sym::Funcs(_)))
                    && args.iter().all(|a| self.folded_at_parse(a))
            }
            _ => false,
        }
    }

    /// The last label of a `switch` must be followed by a statement (`kept`: one that ANGLE
    /// does not remove as it parses it).
    fn check_label_at_end(&mut self, body: &ast::Block, kept: bool) {
        let is_label =
            |s: &ast::Stmt| matches!(s.kind, ast::StmtKind::Case(_) | ast::StmtKind::Default);
        let last_stmt_is_label = body.stmts.last().is_some_and(is_label);
        let only_removed = !kept && body.stmts.iter().any(is_label);
        if last_stmt_is_label || only_removed {
            let end = body.span.end.saturating_sub(1);
            let d = self.error(
                Code::LabelAtEndOfSwitch,
                crate::source::Span::new(end, end + 1),
                "no statement between the last `case` label and the end of the `switch`",
            );
            d.label = "a statement is needed before `}`".into();
            d.token = "switch".into();
            if !last_stmt_is_label {
                d.notes.push(
                    "an `if` whose condition is the constant `false` and that has no `else` is \
                     not a statement here: WebGL implementations built on ANGLE (Chromium) \
                     remove it before this check"
                        .into(),
                );
            }
            d.fix = Some(Fix::certain(
                "add `break;`",
                crate::source::Span::empty(end),
                "break; ",
            ));
        }
    }
}

/// Whether a statement list ends in `break`, `continue`, `return` or `discard`.
pub(crate) fn ends_in_jump(stmts: &[hir::Stmt]) -> bool {
    match stmts.last().map(|s| &s.kind) {
        Some(StmtKind::Break | StmtKind::Continue | StmtKind::Return(_) | StmtKind::Discard) => {
            true
        }
        Some(StmtKind::Block(b)) => ends_in_jump(b),
        _ => false,
    }
}

/// Starts a new case in `cases` (`value` `None` for `default`); the case before falls through
/// unless it ends in a jump.
fn open_case(cases: &mut Vec<hir::SwitchCase>, value: Option<i64>, span: crate::source::Span) {
    if let Some(last) = cases.last_mut() {
        last.fall_through = !ends_in_jump(&last.body);
    }
    cases.push(hir::SwitchCase {
        value,
        body: Vec::new(),
        fall_through: true,
        span,
    });
}
