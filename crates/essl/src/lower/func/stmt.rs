//! Statements: blocks, `if`, loops (with their conditions and steps), `switch` without
//! fall-through, jumps, and expressions evaluated only for their effects.

use naga::{Expression, Handle, Statement};

use super::const_bool;
use super::FnCx;
use crate::hir::{self, Expr, ExprKind, Stmt, StmtKind};
use crate::lower::LowerError;
use crate::source::Span;
use crate::types::Type;

impl<'c, 'a> FnCx<'c, 'a> {
    pub(super) fn stmts(&mut self, stmts: &[Stmt]) -> Result<(), LowerError> {
        for s in stmts {
            if self.stmt(s)? {
                // Code after a return, discard, break or continue in the same block is dead.
                break;
            }
        }
        Ok(())
    }

    /// Lowers a statement; returns whether it ends the block's control flow.
    fn stmt(&mut self, s: &Stmt) -> Result<bool, LowerError> {
        match &s.kind {
            StmtKind::Expr(e) => {
                self.effect(e)?;
            }
            StmtKind::Local(l, init) => {
                if let Some(e) = init {
                    self.local_init(*l, e, s.span)?;
                } else {
                    self.local_handle(*l);
                }
            }
            StmtKind::Block(b) => {
                let block = self.block_of(b)?;
                self.push(Statement::Block(block), s.span);
            }
            StmtKind::If(c, t, e) => self.if_stmt(c, t, e, s.span)?,
            StmtKind::Loop {
                init,
                cond,
                step,
                body,
                do_while,
            } => {
                for st in init {
                    if self.stmt(st)? {
                        return Ok(true);
                    }
                }
                let cond = cond.as_deref();
                let body = self.loop_body(cond.filter(|_| !do_while), body, s.span)?;
                let (continuing, break_if) =
                    self.loop_continuing(step.as_ref(), cond.filter(|_| *do_while), s.span)?;
                self.push(
                    Statement::Loop {
                        body,
                        continuing,
                        break_if,
                    },
                    s.span,
                );
            }
            StmtKind::Switch(sel, cases) => self.switch_stmt(sel, cases, s.span)?,
            StmtKind::Break => {
                self.push(Statement::Break, s.span);
                return Ok(true);
            }
            StmtKind::Continue => {
                self.push(Statement::Continue, s.span);
                return Ok(true);
            }
            StmtKind::Return(v) => {
                let value = match v {
                    Some(e) => Some(self.expr(e)?),
                    None => None,
                };
                self.push(Statement::Return { value }, s.span);
                return Ok(true);
            }
            StmtKind::Discard => {
                self.push(Statement::Kill, s.span);
                return Ok(true);
            }
        }
        Ok(false)
    }

    /// A local's declaration with an initializer: the value stored into the local.
    fn local_init(&mut self, l: usize, init: &Expr, span: Span) -> Result<(), LowerError> {
        let local = self.local_handle(l);
        let v = self.expr(init)?;
        self.store_local(local, v, span);
        Ok(())
    }

    /// `if`: a constant condition keeps only the branch taken (as a block).
    fn if_stmt(
        &mut self,
        c: &Expr,
        then: &[Stmt],
        els: &[Stmt],
        span: Span,
    ) -> Result<(), LowerError> {
        if let Some(b) = const_bool(c) {
            let chosen = if b { then } else { els };
            let block = self.block_of(chosen)?;
            self.push(Statement::Block(block), span);
            return Ok(());
        }
        let cond = self.expr(c)?;
        let accept = self.block_of(then)?;
        let reject = self.block_of(els)?;
        self.push(
            Statement::If {
                condition: cond,
                accept,
                reject,
            },
            span,
        );
        Ok(())
    }

    /// The body of a loop, led by `if (!cond) { break; }` when the condition is tested first.
    fn loop_body(
        &mut self,
        test_first: Option<&hir::Cond>,
        body: &[Stmt],
        span: Span,
    ) -> Result<naga::Block, LowerError> {
        self.capture(|fx| {
            if let Some(c) = test_first {
                let not = fx.loop_exit(c, span)?;
                fx.push(
                    Statement::If {
                        condition: not,
                        accept: naga::Block::from_vec(vec![Statement::Break]),
                        reject: naga::Block::new(),
                    },
                    span,
                );
            }
            fx.stmts(body)
        })
    }

    /// The `continuing` block of a loop (its step) and its `break_if` (the negated condition of
    /// a `do`-`while`, tested last).
    fn loop_continuing(
        &mut self,
        step: Option<&Expr>,
        test_last: Option<&hir::Cond>,
        span: Span,
    ) -> Result<(naga::Block, Option<Handle<Expression>>), LowerError> {
        let mut break_if = None;
        let continuing = self.capture(|fx| {
            if let Some(st) = step {
                fx.effect(st)?;
            }
            if let Some(c) = test_last {
                break_if = Some(fx.loop_exit(c, span)?);
            }
            Ok(())
        })?;
        Ok((continuing, break_if))
    }

    /// `!cond`: whether the loop ends.
    fn loop_exit(&mut self, c: &hir::Cond, span: Span) -> Result<Handle<Expression>, LowerError> {
        let v = self.loop_cond(c)?;
        Ok(self.add(
            Expression::Unary {
                op: naga::UnaryOperator::LogicalNot,
                expr: v,
            },
            span,
        ))
    }

    /// `switch`: every case gets a body of its own, and a `default` is added when missing
    /// (naga wants one).
    fn switch_stmt(
        &mut self,
        sel: &Expr,
        cases: &[hir::SwitchCase],
        span: Span,
    ) -> Result<(), LowerError> {
        let selector = self.expr(sel)?;
        let unsigned = sel.ty == Type::UINT;
        let mut ncases = Vec::new();
        let mut has_default = false;
        for (i, c) in cases.iter().enumerate() {
            let (body, copies) = self.case_body(cases, i)?;
            let value = match c.value {
                None => {
                    has_default = true;
                    naga::SwitchValue::Default
                }
                Some(v) if unsigned => naga::SwitchValue::U32(v as u32),
                Some(v) => naga::SwitchValue::I32(v as i32),
            };
            ncases.push(naga::SwitchCase {
                value,
                body,
                fall_through: c.fall_through && !copies,
            });
        }
        if let Some(last) = ncases.last_mut() {
            last.fall_through = false;
        }
        if !has_default {
            ncases.push(naga::SwitchCase {
                value: naga::SwitchValue::Default,
                body: naga::Block::new(),
                fall_through: false,
            });
        }
        self.push(
            Statement::Switch {
                selector,
                cases: ncases,
            },
            span,
        );
        Ok(())
    }

    /// The body of case `i`, and whether it holds copies of the cases it falls into.
    ///
    /// A case with statements that falls through gets the statements of the cases it falls
    /// into, up to one that does not fall through: WGSL has no fall-through (an empty case
    /// that falls through shares the next one's body in every target). Each copy is lowered
    /// anew, with its own expressions.
    fn case_body(
        &mut self,
        cases: &[hir::SwitchCase],
        i: usize,
    ) -> Result<(naga::Block, bool), LowerError> {
        let c = &cases[i];
        let copies = c.fall_through && !c.body.is_empty();
        let body = if copies {
            let mut stmts = c.body.clone();
            for next in &cases[i + 1..] {
                stmts.extend(next.body.iter().cloned());
                if !next.fall_through {
                    break;
                }
            }
            self.block_of(&stmts)?
        } else {
            self.block_of(&c.body)?
        };
        Ok((body, copies))
    }

    fn loop_cond(&mut self, c: &hir::Cond) -> Result<Handle<Expression>, LowerError> {
        match c {
            hir::Cond::Expr(e) => self.expr(e),
            hir::Cond::Decl(l, init) => {
                let v = self.expr(init)?;
                let local = self.local_handle(*l);
                let p = self.add(Expression::LocalVariable(local), init.span);
                self.push(
                    Statement::Store {
                        pointer: p,
                        value: v,
                    },
                    init.span,
                );
                Ok(v)
            }
        }
    }

    pub(super) fn local_handle(&mut self, l: usize) -> Handle<naga::LocalVariable> {
        if let Some(h) = self.locals[l] {
            return h;
        }
        // The function outlives `self`'s borrow: its name and type need no copies.
        let local = &self.hir_fn.expect("in a function").locals[l];
        // Where the GLSL declared it, for a translation to put its comments back.
        let h = self.new_local_at(&local.name, &local.ty, local.span);
        self.locals[l] = Some(h);
        h
    }

    pub(super) fn effect(&mut self, e: &Expr) -> Result<(), LowerError> {
        match &e.kind {
            ExprKind::Comma(a, b) => {
                self.effect(a)?;
                self.effect(b)
            }
            ExprKind::Const(_)
            | ExprKind::Local(_)
            | ExprKind::Global(_)
            | ExprKind::Param(_)
            | ExprKind::BuiltinVar(_) => Ok(()),
            _ => self.expr(e).map(|_| ()),
        }
    }
}
