//! Expressions to values: the dispatch over expression kinds, accesses to values that are not
//! variables, constants (with the non-finite ones built at run time), calls of user functions
//! and the texture and sampler a sampler expression denotes.

use naga::{Expression, Handle, Literal, Span as NSpan, Statement};

use super::operators::Operand;
use super::{all_finite, global_constant, has_effects, int_zero_divisor, literal};
use super::{FnCx, ParamLower};
use crate::ast::BinaryOp;
use crate::builtins::BuiltinVar;
use crate::hir::{self, ConstValue, Expr, ExprKind, FuncId, ParamMode, Scalar};
use crate::lower::{nspan, unsupported, GlobalLower, LowerError};
use crate::source::Span;
use crate::types::{ScalarKind, Type};

impl<'c, 'a> FnCx<'c, 'a> {
    /// Lowers an expression to a value.
    pub(crate) fn expr(&mut self, e: &Expr) -> Result<Handle<Expression>, LowerError> {
        let span = e.span;
        Ok(match &e.kind {
            ExprKind::Error => {
                return Err(LowerError::Internal {
                    message: "an expression that failed to check reached the lowering".into(),
                    span,
                })
            }
            ExprKind::Const(c) => self.constant(c, &e.ty, span),
            ExprKind::Local(_)
            | ExprKind::Param(_)
            | ExprKind::Global(_)
            | ExprKind::BuiltinVar(_)
            | ExprKind::BlockMember(..)
            | ExprKind::Member(..)
            | ExprKind::Index(..) => match self.place(e)? {
                Some(p) => self.load(&p, span),
                None => self.value_access(e)?,
            },
            ExprKind::Swizzle(b, comps) => {
                let v = self.expr(b)?;
                self.swizzle(v, comps, span)
            }
            ExprKind::Unary(op, a) => {
                let v = self.expr(a)?;
                match op {
                    hir::UnaryOp::Not => self.add(
                        Expression::Unary {
                            op: naga::UnaryOperator::LogicalNot,
                            expr: v,
                        },
                        span,
                    ),
                    hir::UnaryOp::BitNot => self.add(
                        Expression::Unary {
                            op: naga::UnaryOperator::BitwiseNot,
                            expr: v,
                        },
                        span,
                    ),
                    hir::UnaryOp::Neg => self.negate(v, &a.ty, span),
                }
            }
            ExprKind::Binary(op, a, b) => self.binary(*op, a, b, &e.ty, span)?,
            ExprKind::Assign(op, l, r) => {
                let lv = self.lvalue(l)?;
                let value = match op {
                    None => self.expr(r)?,
                    Some(o) if int_zero_divisor(*o, r) => self.zero(&e.ty),
                    Some(o) => {
                        let old = self.load_lvalue(&lv, &l.ty, span);
                        let rv = self.expr(r)?;
                        self.arith(
                            *o,
                            Operand::new(old, &l.ty),
                            Operand::new(rv, &r.ty),
                            &e.ty,
                            span,
                        )?
                    }
                };
                self.store(&lv, value, span);
                value
            }
            ExprKind::IncDec(inc, pre, t) => {
                let lv = self.lvalue(t)?;
                let old = self.load_lvalue(&lv, &t.ty, span);
                let one = self.one_like(&t.ty, span);
                let op = if *inc { BinaryOp::Add } else { BinaryOp::Sub };
                let new = self.arith(
                    op,
                    Operand::new(old, &t.ty),
                    Operand::new(one, &t.ty),
                    &t.ty,
                    span,
                )?;
                self.store(&lv, new, span);
                if *pre {
                    new
                } else {
                    old
                }
            }
            ExprKind::Select(c, a, b) => {
                let simple = (a.ty.is_scalar_or_vector()) && !has_effects(a) && !has_effects(b);
                if simple {
                    let cv = self.expr(c)?;
                    let av = self.expr(a)?;
                    let bv = self.expr(b)?;
                    self.add(
                        Expression::Select {
                            condition: cv,
                            accept: av,
                            reject: bv,
                        },
                        span,
                    )
                } else {
                    let tmp = self.new_local("_essl_select", &e.ty);
                    let cv = self.expr(c)?;
                    let accept = self.capture(|fx| {
                        let v = fx.expr(a)?;
                        fx.store_local(tmp, v, span);
                        Ok(())
                    })?;
                    let reject = self.capture(|fx| {
                        let v = fx.expr(b)?;
                        fx.store_local(tmp, v, span);
                        Ok(())
                    })?;
                    self.push(
                        Statement::If {
                            condition: cv,
                            accept,
                            reject,
                        },
                        span,
                    );
                    let p = self.add(Expression::LocalVariable(tmp), span);
                    self.add(Expression::Load { pointer: p }, span)
                }
            }
            ExprKind::Comma(a, b) => {
                self.effect(a)?;
                self.expr(b)?
            }
            ExprKind::Call(f, args) => self.call(*f, args, &e.ty, span)?,
            ExprKind::Builtin(op, args) => self.builtin(*op, args, &e.ty, span)?,
            ExprKind::Construct(args) => self.construct(&e.ty, args, span)?,
        })
    }

    /// `x[i]`, `s.m` on values that are not variables (function results, constructors), and
    /// reads of variables that are not lowered (dead code: a zero value).
    fn value_access(&mut self, e: &Expr) -> Result<Handle<Expression>, LowerError> {
        let span = e.span;
        match &e.kind {
            ExprKind::Index(b, i) => {
                let base_is_var = self.is_unlowered_variable(b);
                if base_is_var {
                    return Ok(self.dead_value(&e.ty, span));
                }
                let bv = self.expr(b)?;
                if let Some(k) = i.as_const().and_then(|c| c.as_int()) {
                    return Ok(self.access_index(bv, k as u32, span));
                }
                let iv = self.expr(i)?;
                if matches!(b.ty, Type::Matrix { .. } | Type::Array(..)) {
                    // A dynamic index into a matrix (or array) value goes through a variable.
                    let tmp = self.new_local("_essl_index", &b.ty);
                    let p = self.store_local(tmp, bv, span);
                    let ep = self.add(Expression::Access { base: p, index: iv }, span);
                    return Ok(self.add(Expression::Load { pointer: ep }, span));
                }
                Ok(self.add(
                    Expression::Access {
                        base: bv,
                        index: iv,
                    },
                    span,
                ))
            }
            ExprKind::Member(b, m) => {
                if self.is_unlowered_variable(b) {
                    return Ok(self.dead_value(&e.ty, span));
                }
                let bv = self.expr(b)?;
                if let ExprKind::BuiltinVar(BuiltinVar::DepthRange) = b.kind {
                    return Ok(bv);
                }
                Ok(self.access_index(bv, *m as u32, span))
            }
            ExprKind::Param(i) => match self.params[*i] {
                ParamLower::Value(a) => Ok(self.add(Expression::FunctionArgument(a), span)),
                _ => Ok(self.zero(&e.ty)),
            },
            ExprKind::BuiltinVar(BuiltinVar::DepthRange) => {
                // WebGL's default depth range: near 0, far 1, diff 1.
                let c = ConstValue::Composite(vec![
                    ConstValue::Basic(vec![Scalar::F(0.0)]),
                    ConstValue::Basic(vec![Scalar::F(1.0)]),
                    ConstValue::Basic(vec![Scalar::F(1.0)]),
                ]);
                Ok(self.constant(&c, &e.ty, span))
            }
            ExprKind::Global(_) if self.is_unlowered_variable(e) => {
                Ok(self.dead_value(&e.ty, span))
            }
            _ => Ok(self.zero(&e.ty)),
        }
    }

    /// The value of a variable the lowering left out (an inactive uniform, read only by code
    /// whose value nothing uses): 0, loaded from a local, so that naga does not evaluate an
    /// expression of it as a constant (`7u % inactive` would be a division by zero there).
    fn dead_value(&mut self, ty: &Type, span: Span) -> Handle<Expression> {
        let tmp = self.new_local("_essl_inactive", ty);
        let pointer = self.add(Expression::LocalVariable(tmp), span);
        self.add(Expression::Load { pointer }, span)
    }

    /// Whether an expression is (part of) a variable the lowering left out.
    fn is_unlowered_variable(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Global(g) => matches!(self.cx.globals[*g], GlobalLower::None),
            ExprKind::Index(b, _) | ExprKind::Member(b, _) => self.is_unlowered_variable(b),
            _ => false,
        }
    }

    pub(crate) fn constant(&mut self, c: &ConstValue, ty: &Type, span: Span) -> Handle<Expression> {
        if !all_finite(c) {
            return self.runtime_constant(c, ty, span);
        }
        match (c, ty) {
            (ConstValue::Basic(v), Type::Scalar(_)) => {
                self.add(Expression::Literal(literal(v[0])), span)
            }
            _ => {
                let init = global_constant(self.cx, c, ty);
                let nty = self.ty(ty);
                let h = self.cx.module.constants.append(
                    naga::Constant {
                        name: None,
                        ty: nty,
                        init,
                    },
                    NSpan::UNDEFINED,
                );
                self.add(Expression::Constant(h), span)
            }
        }
    }

    /// The float whose bits are `bits`, at run time (an infinity or NaN, which no naga
    /// literal holds).
    pub(crate) fn f32_from_bits(&mut self, bits: u32, span: Span) -> Handle<Expression> {
        let bits = self.lit(Literal::U32(bits));
        self.add(
            Expression::As {
                expr: bits,
                kind: naga::ScalarKind::Float,
                convert: None,
            },
            span,
        )
    }

    /// A constant holding an infinity or NaN, which naga literals cannot: built at run time
    /// from the float's bits.
    fn runtime_constant(&mut self, c: &ConstValue, ty: &Type, span: Span) -> Handle<Expression> {
        match (c, ty) {
            (ConstValue::Basic(v), Type::Scalar(_)) => match v[0] {
                Scalar::F(f) if !f.is_finite() => self.f32_from_bits(f.to_bits(), span),
                s => self.add(Expression::Literal(literal(s)), span),
            },
            (ConstValue::Basic(v), Type::Vector(k, _)) => {
                let parts: Vec<_> = v
                    .iter()
                    .map(|s| {
                        self.runtime_constant(&ConstValue::Basic(vec![*s]), &Type::Scalar(*k), span)
                    })
                    .collect();
                self.compose(ty, parts, span)
            }
            (ConstValue::Basic(v), Type::Matrix { cols, rows }) => {
                let col_ty = Type::Vector(ScalarKind::Float, *rows);
                let parts: Vec<_> = (0..*cols as usize)
                    .map(|c| {
                        self.runtime_constant(
                            &ConstValue::Basic(
                                v[c * *rows as usize..(c + 1) * *rows as usize].to_vec(),
                            ),
                            &col_ty,
                            span,
                        )
                    })
                    .collect();
                self.compose(ty, parts, span)
            }
            (ConstValue::Composite(elems), Type::Array(el, _)) => {
                let el = (**el).clone();
                let parts: Vec<_> = elems
                    .iter()
                    .map(|e| self.runtime_constant(e, &el, span))
                    .collect();
                self.compose(ty, parts, span)
            }
            (ConstValue::Composite(members), Type::Struct(id)) => {
                let mtys: Vec<Type> = self.cx.hir.structs[id.0 as usize]
                    .members
                    .iter()
                    .map(|m| m.ty.clone())
                    .collect();
                let parts: Vec<_> = members
                    .iter()
                    .zip(&mtys)
                    .map(|(e, t)| self.runtime_constant(e, t, span))
                    .collect();
                self.compose(ty, parts, span)
            }
            _ => self.zero(ty),
        }
    }

    fn one_like(&mut self, ty: &Type, span: Span) -> Handle<Expression> {
        let one = match ty.scalar_kind() {
            Some(ScalarKind::Int) => Literal::I32(1),
            Some(ScalarKind::Uint) => Literal::U32(1),
            _ => Literal::F32(1.0),
        };
        let o = self.lit(one);
        match ty {
            Type::Vector(_, n) => self.splat(o, *n, span),
            Type::Matrix { cols, rows } => {
                let col = self.splat(o, *rows, span);
                let cols = vec![col; *cols as usize];
                self.compose(ty, cols, span)
            }
            _ => o,
        }
    }

    fn call(
        &mut self,
        f: FuncId,
        args: &[Expr],
        ret: &Type,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        if let Some(r) =
            self.per_sampler_element(args, ret, span, &|fx, a| fx.call(f, a, ret, span))
        {
            return r;
        }
        let callee = &self.cx.hir.functions[f];
        let Some(function) = self.cx.functions[f] else {
            return Err(unsupported(
                "a call to a function that was not lowered",
                span,
            ));
        };
        let mut arguments = Vec::new();
        let mut writebacks = Vec::new();
        let mut sampler_arguments = Vec::new();
        for (arg, p) in args.iter().zip(callee.params.clone()) {
            if let Type::Sampler(_) = p.ty {
                let (img, smp) = self.sampler(arg)?;
                arguments.push(img);
                arguments.push(smp);
                continue;
            }
            for path in crate::lower::plan::sampler_paths(&p.ty, &self.cx.hir.structs) {
                let (img, smp) = self.sampler_at(arg, &path)?;
                sampler_arguments.push(img);
                sampler_arguments.push(smp);
            }
            match p.mode {
                ParamMode::In => arguments.push(self.expr(arg)?),
                mode => {
                    let tmp = self.new_local(&format!("_essl_{}", p.name), &p.ty);
                    let lv = self.lvalue(arg)?;
                    if mode == ParamMode::InOut {
                        let v = self.load_lvalue(&lv, &arg.ty, span);
                        self.store_local(tmp, v, span);
                    }
                    let tp = self.add(Expression::LocalVariable(tmp), span);
                    arguments.push(tp);
                    writebacks.push((lv, tmp));
                }
            }
        }
        arguments.extend(sampler_arguments);
        self.flush_only();
        let result = if *ret != Type::Void {
            Some(
                self.f
                    .expressions
                    .append(Expression::CallResult(function), nspan(span)),
            )
        } else {
            None
        };
        self.blocks.last_mut().expect("block").push(
            Statement::Call {
                function,
                arguments,
                result,
            },
            nspan(span),
        );
        self.emitter.start(&self.f.expressions);
        for (lv, tmp) in writebacks {
            let tp = self.add(Expression::LocalVariable(tmp), span);
            let v = self.add(Expression::Load { pointer: tp }, span);
            self.store(&lv, v, span);
        }
        Ok(match result {
            Some(r) => r,
            None => self.lit(Literal::Bool(false)),
        })
    }
}
