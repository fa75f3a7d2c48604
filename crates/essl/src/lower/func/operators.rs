//! Operators: negation, the binary operators (with short-circuit `&&`/`||`), equality of
//! composites component by component, and arithmetic with GLSL's mixing of scalars, vectors
//! and matrices.

use naga::{Expression, Handle, Literal, Statement};

use super::FnCx;
use super::{has_effects, int_zero_divisor};
use crate::ast::BinaryOp;
use crate::hir::Expr;
use crate::lower::{unsupported, LowerError};
use crate::source::Span;
use crate::types::{ScalarKind, Type};

/// An operand of an operator: its lowered value and its GLSL type.
#[derive(Clone, Copy)]
pub(crate) struct Operand<'t> {
    /// The value.
    pub value: Handle<Expression>,
    /// Its type.
    pub ty: &'t Type,
}

impl<'t> Operand<'t> {
    pub(crate) fn new(value: Handle<Expression>, ty: &'t Type) -> Self {
        Operand { value, ty }
    }
}

impl<'c, 'a> FnCx<'c, 'a> {
    pub(super) fn negate(
        &mut self,
        v: Handle<Expression>,
        ty: &Type,
        span: Span,
    ) -> Handle<Expression> {
        match ty {
            Type::Matrix { cols, rows } => {
                let col_ty = Type::Vector(ScalarKind::Float, *rows);
                let parts: Vec<_> = (0..*cols as u32)
                    .map(|i| {
                        let c = self.access_index(v, i, span);
                        self.negate(c, &col_ty, span)
                    })
                    .collect();
                self.compose(ty, parts, span)
            }
            t if t.scalar_kind() == Some(ScalarKind::Uint) => {
                let zero = self.zero(t);
                self.binop(naga::BinaryOperator::Subtract, zero, v, span)
            }
            _ => self.add(
                Expression::Unary {
                    op: naga::UnaryOperator::Negate,
                    expr: v,
                },
                span,
            ),
        }
    }

    pub(super) fn binary(
        &mut self,
        op: BinaryOp,
        a: &Expr,
        b: &Expr,
        rt: &Type,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        use naga::BinaryOperator as Bo;
        match op {
            BinaryOp::And | BinaryOp::Or if has_effects(b) => {
                // Short-circuit: evaluate `b` only when needed.
                let tmp = self.new_local("_essl_logic", &Type::BOOL);
                let av = self.expr(a)?;
                self.store_local(tmp, av, span);
                let eval_b = self.capture(|fx| {
                    let bv = fx.expr(b)?;
                    fx.store_local(tmp, bv, span);
                    Ok(())
                })?;
                let (accept, reject) = if op == BinaryOp::And {
                    (eval_b, naga::Block::new())
                } else {
                    (naga::Block::new(), eval_b)
                };
                self.push(
                    Statement::If {
                        condition: av,
                        accept,
                        reject,
                    },
                    span,
                );
                let p = self.add(Expression::LocalVariable(tmp), span);
                Ok(self.add(Expression::Load { pointer: p }, span))
            }
            BinaryOp::And | BinaryOp::Or | BinaryOp::Xor => {
                let av = self.expr(a)?;
                let bv = self.expr(b)?;
                let o = match op {
                    BinaryOp::And => Bo::LogicalAnd,
                    BinaryOp::Or => Bo::LogicalOr,
                    _ => Bo::NotEqual,
                };
                Ok(self.binop(o, av, bv, span))
            }
            BinaryOp::Eq | BinaryOp::NotEq => {
                let av = self.expr(a)?;
                let bv = self.expr(b)?;
                let eq = self.equal(av, bv, &a.ty, span);
                Ok(if op == BinaryOp::Eq {
                    eq
                } else {
                    self.add(
                        Expression::Unary {
                            op: naga::UnaryOperator::LogicalNot,
                            expr: eq,
                        },
                        span,
                    )
                })
            }
            BinaryOp::Less | BinaryOp::Greater | BinaryOp::LessEq | BinaryOp::GreaterEq => {
                let av = self.expr(a)?;
                let bv = self.expr(b)?;
                let o = match op {
                    BinaryOp::Less => Bo::Less,
                    BinaryOp::Greater => Bo::Greater,
                    BinaryOp::LessEq => Bo::LessEqual,
                    _ => Bo::GreaterEqual,
                };
                Ok(self.binop(o, av, bv, span))
            }
            _ => {
                let av = self.expr(a)?;
                if int_zero_divisor(op, b) {
                    // Undefined in GLSL (the checker warned); naga rejects it outright.
                    return Ok(self.zero(rt));
                }
                let bv = self.expr(b)?;
                self.arith(
                    op,
                    Operand::new(av, &a.ty),
                    Operand::new(bv, &b.ty),
                    rt,
                    span,
                )
            }
        }
    }

    /// Deep equality of two values of the same type, as one `bool`.
    fn equal(
        &mut self,
        a: Handle<Expression>,
        b: Handle<Expression>,
        ty: &Type,
        span: Span,
    ) -> Handle<Expression> {
        use naga::BinaryOperator as Bo;
        match ty {
            Type::Scalar(_) => self.binop(Bo::Equal, a, b, span),
            Type::Vector(..) => {
                let v = self.binop(Bo::Equal, a, b, span);
                self.add(
                    Expression::Relational {
                        fun: naga::RelationalFunction::All,
                        argument: v,
                    },
                    span,
                )
            }
            Type::Matrix { cols, rows } => {
                let col = Type::Vector(ScalarKind::Float, *rows);
                self.fold_and(*cols as u32, a, b, &col, span)
            }
            Type::Array(el, n) => {
                let el = (**el).clone();
                self.fold_and(*n, a, b, &el, span)
            }
            Type::Struct(id) => {
                let mtys: Vec<Type> = self.cx.hir.structs[id.0 as usize]
                    .members
                    .iter()
                    .map(|m| m.ty.clone())
                    .collect();
                let mut acc: Option<Handle<Expression>> = None;
                for (i, t) in mtys.iter().enumerate() {
                    let x = self.access_index(a, i as u32, span);
                    let y = self.access_index(b, i as u32, span);
                    let e = self.equal(x, y, t, span);
                    acc = Some(match acc {
                        Some(p) => self.binop(Bo::LogicalAnd, p, e, span),
                        None => e,
                    });
                }
                acc.unwrap_or_else(|| self.lit(Literal::Bool(true)))
            }
            _ => self.lit(Literal::Bool(false)),
        }
    }

    fn fold_and(
        &mut self,
        n: u32,
        a: Handle<Expression>,
        b: Handle<Expression>,
        el: &Type,
        span: Span,
    ) -> Handle<Expression> {
        let mut acc: Option<Handle<Expression>> = None;
        for i in 0..n {
            let x = self.access_index(a, i, span);
            let y = self.access_index(b, i, span);
            let e = self.equal(x, y, el, span);
            acc = Some(match acc {
                Some(p) => self.binop(naga::BinaryOperator::LogicalAnd, p, e, span),
                None => e,
            });
        }
        acc.unwrap_or_else(|| self.lit(Literal::Bool(true)))
    }

    /// Whether expression `h` is a constant naga evaluates with a zero integer in it: a zero
    /// literal, a zero value, or a splat or composition of one.
    fn zero_in_constant(&self, h: Handle<Expression>) -> bool {
        match &self.f.expressions[h] {
            Expression::Constant(c) => {
                let m = &self.cx.module;
                zero_in(&m.global_expressions, m.constants[*c].init)
            }
            _ => zero_in(&self.f.expressions, h),
        }
    }

    /// Arithmetic and bitwise operators with GLSL's scalar/vector/matrix mixing; `rt` is the
    /// result's type.
    pub(crate) fn arith(
        &mut self,
        op: BinaryOp,
        a: Operand,
        b: Operand,
        rt: &Type,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        use naga::BinaryOperator as Bo;
        let (Operand { value: a, ty: at }, Operand { value: b, ty: bt }) = (a, b);
        // An integer divisor naga can evaluate to 0 (the value of `(i = 0)`, an inactive
        // uniform's): it rejects the division outright, while GLSL only leaves the result
        // undefined (Chromium compiles it). Through a local, the divisor is a run-time value.
        let b = if matches!(op, BinaryOp::Div | BinaryOp::Mod)
            && matches!(bt.scalar_kind(), Some(ScalarKind::Int | ScalarKind::Uint))
            && self.zero_in_constant(b)
        {
            let tmp = self.new_local("_essl_divisor", bt);
            let pointer = self.store_local(tmp, b, span);
            self.add(Expression::Load { pointer }, span)
        } else {
            b
        };
        let nop = match op {
            BinaryOp::Add => Bo::Add,
            BinaryOp::Sub => Bo::Subtract,
            BinaryOp::Mul => Bo::Multiply,
            BinaryOp::Div => Bo::Divide,
            BinaryOp::Mod => Bo::Modulo,
            BinaryOp::BitAnd => Bo::And,
            BinaryOp::BitOr => Bo::InclusiveOr,
            BinaryOp::BitXor => Bo::ExclusiveOr,
            BinaryOp::Shl => Bo::ShiftLeft,
            BinaryOp::Shr => Bo::ShiftRight,
            _ => {
                return Err(unsupported(
                    format!("operator `{}` here", op.as_str()),
                    span,
                ))
            }
        };
        // Shifts: the amount is unsigned, and a vector when the value is. It is taken modulo 32:
        // GLSL leaves a shift by 32 or more undefined (Chromium compiles `3 >> 40u` with a
        // warning), and naga rejects a constant one.
        if matches!(op, BinaryOp::Shl | BinaryOp::Shr) {
            let mut amount = b;
            if bt.scalar_kind() == Some(ScalarKind::Int) {
                amount = self.cast(amount, naga::ScalarKind::Uint, span);
            }
            let mut mask = self.lit(naga::Literal::U32(31));
            if let Type::Vector(_, n) = bt {
                mask = self.splat(mask, *n, span);
            }
            amount = self.binop(Bo::And, amount, mask, span);
            if let (Type::Vector(_, n), true) = (at, bt.is_scalar()) {
                amount = self.splat(amount, *n, span);
            }
            return Ok(self.binop(nop, a, amount, span));
        }
        match (at, bt) {
            (Type::Matrix { cols, rows }, _) | (_, Type::Matrix { cols, rows })
                if matches!((at, bt), (Type::Matrix { .. }, Type::Matrix { .. }))
                    && op != BinaryOp::Mul =>
            {
                if matches!(op, BinaryOp::Add | BinaryOp::Sub) {
                    return Ok(self.binop(nop, a, b, span));
                }
                // Component-wise division of matrices: column by column.
                let col = Type::Vector(ScalarKind::Float, *rows);
                let parts: Vec<_> = (0..*cols as u32)
                    .map(|i| {
                        let x = self.access_index(a, i, span);
                        let y = self.access_index(b, i, span);
                        self.binop(nop, x, y, span)
                    })
                    .collect();
                let _ = col;
                Ok(self.compose(rt, parts, span))
            }
            (Type::Matrix { cols, rows }, Type::Scalar(_))
            | (Type::Scalar(_), Type::Matrix { cols, rows })
                if op != BinaryOp::Mul =>
            {
                let scalar_left = at.is_scalar();
                let s = if scalar_left { a } else { b };
                let m = if scalar_left { b } else { a };
                let sv = self.splat(s, *rows, span);
                let parts: Vec<_> = (0..*cols as u32)
                    .map(|i| {
                        let c = self.access_index(m, i, span);
                        if scalar_left {
                            self.binop(nop, sv, c, span)
                        } else {
                            self.binop(nop, c, sv, span)
                        }
                    })
                    .collect();
                Ok(self.compose(rt, parts, span))
            }
            (Type::Vector(_, n), Type::Scalar(_)) if op != BinaryOp::Mul => {
                let bs = self.splat(b, *n, span);
                Ok(self.binop(nop, a, bs, span))
            }
            (Type::Scalar(_), Type::Vector(_, n)) if op != BinaryOp::Mul => {
                let as_ = self.splat(a, *n, span);
                Ok(self.binop(nop, as_, b, span))
            }
            _ => Ok(self.binop(nop, a, b, span)),
        }
    }
}

/// Whether expression `h` of `arena` is a zero integer, a zero value, or a splat or
/// composition with one (not a load, which naga does not evaluate).
fn zero_in(arena: &naga::Arena<Expression>, h: Handle<Expression>) -> bool {
    match &arena[h] {
        Expression::Literal(naga::Literal::I32(0) | naga::Literal::U32(0))
        | Expression::ZeroValue(_) => true,
        Expression::Splat { value, .. } => zero_in(arena, *value),
        Expression::Compose { components, .. } => components.iter().any(|c| zero_in(arena, *c)),
        _ => false,
    }
}
