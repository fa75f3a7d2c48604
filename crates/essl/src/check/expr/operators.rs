//! Operators: the result types of binary operators, unary and binary expressions, assignments,
//! l-values and the conditional operator.

use super::{constant, conversion_fix, error_expr, is_error};
use crate::ast::{self, BinaryOp, UnaryOp};
use crate::check::fold;
use crate::check::Checker;
use crate::diagnostic::Label;
use crate::diagnostic_code::Code;
use crate::hir::{self, Expr, ExprKind, GlobalKind, Scalar};
use crate::source::Span;
use crate::types::{ScalarKind, Type};

/// Why a binary operator cannot be applied to its operands. The text (`Display`) is the label of
/// the `invalid-operands` diagnostic.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub(crate) enum BinaryError {
    /// Arithmetic on an operand that is not a number, vector or matrix.
    #[error("arithmetic needs numbers, vectors or matrices")]
    NotArithmetic,
    /// Arithmetic on `bool` operands.
    #[error("arithmetic is not defined on `bool`")]
    ArithmeticOnBool,
    /// Arithmetic between different base types (`int + float`): there are no implicit conversions.
    #[error("the operands have different base types and GLSL ES 3.00 has no implicit conversions")]
    MixedBaseTypes,
    /// `m * m` for a non-square matrix `m`.
    #[error("a non-square matrix times itself has mismatched dimensions")]
    NonSquareSquared,
    /// `m * v` where the matrix's column count is not the vector's size.
    #[error("a matrix with {cols} columns cannot multiply a {n}-component vector")]
    MatrixTimesVector {
        /// The matrix's column count.
        cols: u8,
        /// The vector's size.
        n: u8,
    },
    /// `v * m` where the vector's size is not the matrix's row count.
    #[error("a {n}-component vector cannot multiply a matrix with {rows} rows")]
    VectorTimesMatrix {
        /// The vector's size.
        n: u8,
        /// The matrix's row count.
        rows: u8,
    },
    /// `a * b` for matrices where `a`'s column count is not `b`'s row count.
    #[error("a {cols}-column matrix cannot multiply a {rows}-row matrix")]
    MatrixTimesMatrix {
        /// The left matrix's column count.
        cols: u8,
        /// The right matrix's row count.
        rows: u8,
    },
    /// Operands of the same base type whose sizes do not combine.
    #[error("the operands' sizes do not match")]
    SizeMismatch,
    /// `%` or a bitwise operator on an operand that is not a number, vector or matrix.
    #[error("needs integers")]
    NotInteger,
    /// `%` or a bitwise operator (the one given) on operands that are not integer scalars or
    /// vectors.
    #[error("`{}` needs `int` or `uint` operands (scalars or vectors)", .0.as_str())]
    IntegerOperands(BinaryOp),
    /// `%` or a bitwise operator between `int` and `uint`.
    #[error("the operands must both be signed or both unsigned")]
    MixedSignedness,
    /// A shift of, or by, something that is not an integer scalar or vector.
    #[error("shifts need `int` or `uint` operands (scalars or vectors)")]
    ShiftOperands,
    /// A scalar shifted by a vector.
    #[error("a scalar cannot be shifted by a vector")]
    ScalarShiftedByVector,
    /// A comparison between different types.
    #[error("the operands have different types")]
    DifferentTypes,
    /// `<`, `>`, `<=` or `>=` on something other than scalar numbers.
    #[error("relational operators compare scalar numbers only (use `lessThan` etc. for vectors)")]
    RelationalNotScalar,
    /// `==` or `!=` on samplers (or values holding them) or `void`.
    #[error("samplers cannot be compared")]
    SamplerComparison,
    /// `&&`, `||` or `^^` (the one given) on operands that are not `bool`.
    #[error("`{}` needs `bool` operands", .0.as_str())]
    LogicalNotBool(BinaryOp),
}

/// The result type of `lhs op rhs`, or why it is invalid.
pub(crate) fn binary_result(
    op: BinaryOp,
    l: &Type,
    r: &Type,
    structs: &[crate::types::StructDef],
) -> Result<Type, BinaryError> {
    use BinaryOp::*;
    use ScalarKind::*;
    let lk = l.scalar_kind();
    let rk = r.scalar_kind();
    match op {
        Add | Sub | Mul | Div => {
            let (Some(lk), Some(rk)) = (lk, rk) else {
                return Err(BinaryError::NotArithmetic);
            };
            if lk == Bool || rk == Bool {
                return Err(BinaryError::ArithmeticOnBool);
            }
            if lk != rk {
                return Err(BinaryError::MixedBaseTypes);
            }
            match (l, r) {
                (a, b) if a == b => {
                    if op == Mul {
                        if let Type::Matrix { cols, rows } = a {
                            if cols != rows {
                                return Err(BinaryError::NonSquareSquared);
                            }
                        }
                    }
                    Ok(a.clone())
                }
                (Type::Scalar(_), t) | (t, Type::Scalar(_)) => Ok(t.clone()),
                (Type::Matrix { cols, rows }, Type::Vector(_, n)) if op == Mul => {
                    if *cols == *n {
                        Ok(Type::Vector(Float, *rows))
                    } else {
                        Err(BinaryError::MatrixTimesVector { cols: *cols, n: *n })
                    }
                }
                (Type::Vector(_, n), Type::Matrix { cols, rows }) if op == Mul => {
                    if *rows == *n {
                        Ok(Type::Vector(Float, *cols))
                    } else {
                        Err(BinaryError::VectorTimesMatrix { n: *n, rows: *rows })
                    }
                }
                (Type::Matrix { cols: c1, rows: r1 }, Type::Matrix { cols: c2, rows: r2 })
                    if op == Mul =>
                {
                    if c1 == r2 {
                        Ok(Type::Matrix {
                            cols: *c2,
                            rows: *r1,
                        })
                    } else {
                        Err(BinaryError::MatrixTimesMatrix {
                            cols: *c1,
                            rows: *r2,
                        })
                    }
                }
                _ => Err(BinaryError::SizeMismatch),
            }
        }
        Mod | BitAnd | BitOr | BitXor => {
            let (Some(lk), Some(rk)) = (lk, rk) else {
                return Err(BinaryError::NotInteger);
            };
            if !matches!(lk, Int | Uint)
                || !matches!(rk, Int | Uint)
                || l.vector_size().is_none()
                || r.vector_size().is_none()
            {
                return Err(BinaryError::IntegerOperands(op));
            }
            if lk != rk {
                return Err(BinaryError::MixedSignedness);
            }
            match (l, r) {
                (a, b) if a == b => Ok(a.clone()),
                (Type::Scalar(_), t) | (t, Type::Scalar(_)) => Ok(t.clone()),
                _ => Err(BinaryError::SizeMismatch),
            }
        }
        Shl | Shr => {
            let (Some(lk), Some(rk)) = (lk, rk) else {
                return Err(BinaryError::NotInteger);
            };
            if !matches!(lk, Int | Uint)
                || !matches!(rk, Int | Uint)
                || l.vector_size().is_none()
                || r.vector_size().is_none()
            {
                return Err(BinaryError::ShiftOperands);
            }
            match (l, r) {
                (Type::Scalar(_), Type::Scalar(_)) => Ok(l.clone()),
                (Type::Vector(_, n), Type::Scalar(_)) => Ok(Type::Vector(lk, *n)),
                (Type::Vector(_, n), Type::Vector(_, m)) if n == m => Ok(l.clone()),
                (Type::Scalar(_), Type::Vector(..)) => Err(BinaryError::ScalarShiftedByVector),
                _ => Err(BinaryError::SizeMismatch),
            }
        }
        Less | Greater | LessEq | GreaterEq => {
            if l != r {
                return Err(BinaryError::DifferentTypes);
            }
            match l {
                Type::Scalar(Float | Int | Uint) => Ok(Type::BOOL),
                _ => Err(BinaryError::RelationalNotScalar),
            }
        }
        Eq | NotEq => {
            if l != r {
                return Err(BinaryError::DifferentTypes);
            }
            if l.contains_sampler(structs) || matches!(l, Type::Void | Type::Sampler(_)) {
                return Err(BinaryError::SamplerComparison);
            }
            Ok(Type::BOOL)
        }
        And | Or | Xor => {
            if *l == Type::BOOL && *r == Type::BOOL {
                Ok(Type::BOOL)
            } else {
                Err(BinaryError::LogicalNotBool(op))
            }
        }
    }
}

impl Checker<'_> {
    pub(super) fn unary(&mut self, op: UnaryOp, a: &ast::Expr, span: Span) -> Expr {
        let a = self.expr(a);
        if is_error(&a) {
            return error_expr(span);
        }
        if op == UnaryOp::BitNot && self.es100_operator("~", span) {
            return error_expr(span);
        }
        let kind = a.ty.scalar_kind();
        let numeric = a.ty.is_numeric_basic() && kind != Some(ScalarKind::Bool);
        let ok = match op {
            UnaryOp::Plus
            | UnaryOp::Neg
            | UnaryOp::PreInc
            | UnaryOp::PreDec
            | UnaryOp::PostInc
            | UnaryOp::PostDec => numeric,
            UnaryOp::Not => a.ty == Type::BOOL,
            UnaryOp::BitNot => {
                a.ty.is_scalar_or_vector()
                    && matches!(kind, Some(ScalarKind::Int | ScalarKind::Uint))
            }
        };
        if !ok {
            let t = self.type_name(&a.ty);
            let need = match op {
                UnaryOp::Not => "a `bool` (use `not()` for a `bvec`)",
                UnaryOp::BitNot => "an `int` or `uint` scalar or vector",
                _ => "a number, vector or matrix (not `bool`)",
            };
            let d = self.error(
                Code::InvalidOperand,
                span,
                format!("`{}` cannot be applied to {t}", op.as_str()),
            );
            d.label = format!("needs {need}");
            d.token = op.as_str().into();
            return error_expr(span);
        }
        let ty = a.ty.clone();
        match op {
            UnaryOp::Plus => Expr { span, ..a },
            UnaryOp::Neg | UnaryOp::Not | UnaryOp::BitNot => {
                let hop = match op {
                    UnaryOp::Neg => hir::UnaryOp::Neg,
                    UnaryOp::Not => hir::UnaryOp::Not,
                    _ => hir::UnaryOp::BitNot,
                };
                if let Some(c) = a.as_const() {
                    if let Some(v) = fold::unary(hop, c) {
                        return constant(v, ty, span);
                    }
                }
                Expr {
                    kind: ExprKind::Unary(hop, Box::new(a)),
                    ty,
                    span,
                }
            }
            _ => {
                let inc = matches!(op, UnaryOp::PreInc | UnaryOp::PostInc);
                let pre = matches!(op, UnaryOp::PreInc | UnaryOp::PreDec);
                if !self.check_lvalue(&a, span, op.as_str()) {
                    return error_expr(span);
                }
                Expr {
                    kind: ExprKind::IncDec(inc, pre, Box::new(a)),
                    ty,
                    span,
                }
            }
        }
    }

    pub(in crate::check) fn binary(&mut self, op: BinaryOp, a: Expr, b: Expr, span: Span) -> Expr {
        if is_error(&a) || is_error(&b) {
            return error_expr(span);
        }
        if matches!(op, BinaryOp::Eq | BinaryOp::NotEq)
            && self.es100_array_operand(&a, op.as_str(), span)
        {
            return error_expr(span);
        }
        let ty = match binary_result(op, &a.ty, &b.ty, &self.structs) {
            Ok(t) => t,
            Err(why) => {
                let (lt, rt) = (self.type_name(&a.ty), self.type_name(&b.ty));
                let op_span = Span::new(a.span.end, b.span.start);
                let fix = if a.ty.scalar_kind() != b.ty.scalar_kind()
                    && a.ty.vector_size() == b.ty.vector_size()
                {
                    conversion_fix(self.file, &b, &a.ty)
                        .or_else(|| conversion_fix(self.file, &a, &b.ty))
                } else {
                    None
                };
                let d = self.error(
                    Code::InvalidOperands,
                    span,
                    format!("`{}` cannot be applied to {lt} and {rt}", op.as_str()),
                );
                d.label = why.to_string();
                d.token = op.as_str().into();
                d.secondary.push(Label {
                    span: a.span,
                    message: lt.to_string(),
                });
                d.secondary.push(Label {
                    span: b.span,
                    message: rt.to_string(),
                });
                if let Some(f) = fix {
                    d.help = Some(f.message.clone());
                    d.fix = Some(f);
                }
                let _ = op_span;
                return error_expr(span);
            }
        };
        if let (Some(x), Some(y)) = (a.as_const(), b.as_const()) {
            let mut warnings = Vec::new();
            if let Ok(v) = fold::binary(op, x, &a.ty, y, &b.ty, &ty, &mut warnings) {
                for w in warnings {
                    self.fold_warning(w, op.as_str(), span);
                }
                return constant(v, ty, span);
            }
        }
        Expr {
            kind: ExprKind::Binary(op, Box::new(a), Box::new(b)),
            ty,
            span,
        }
    }

    /// The warning for a result a constant fold gave a value although it is undefined or not
    /// finite, where Chromium warns and compiles (its value, ANGLE's, in the note).
    pub(super) fn fold_warning(&mut self, w: fold::FoldWarning, token: &str, span: Span) {
        use fold::FoldWarning as W;
        const ANGLE: &str = "WebGL implementations built on ANGLE (Chromium)";
        let operation = match token {
            "+" => "addition",
            "-" => "subtraction",
            "*" => "multiplication",
            _ => "division",
        };
        let (code, message, label, note) = match w {
            W::IntegerDivideByZero | W::FloatDivideByZero => (
                Code::DivisionByZero,
                "division by zero in a constant expression".to_string(),
                "the divisor is zero",
                if w == W::IntegerDivideByZero {
                    format!("the result is undefined; {ANGLE} fold it to the largest value of the type")
                } else {
                    format!("the result is undefined; {ANGLE} fold it to infinity")
                },
            ),
            W::ZeroByZero => (
                Code::DivisionByZero,
                "zero divided by zero in a constant expression".to_string(),
                "both operands are zero",
                format!("the result is undefined; {ANGLE} fold it to NaN"),
            ),
            W::NotANumber => (
                Code::NonFiniteConstant,
                format!("a constant {operation} gives NaN"),
                "NaN",
                "the result is NaN (`∞ - ∞`, `∞ * 0` and `∞ / ∞` are undefined)".to_string(),
            ),
            W::Overflow => (
                Code::NonFiniteConstant,
                format!("a constant {operation} overflows to infinity"),
                "past the largest float",
                "the result is infinity, past the range of every precision".to_string(),
            ),
            W::NegativeModulus => (
                Code::NegativeModulus,
                "`%` of a negative operand in a constant expression".to_string(),
                "an operand is negative",
                format!("the result is undefined in GLSL ES; {ANGLE} fold it to 0"),
            ),
            W::NegativeToUint => (
                Code::NegativeToUint,
                "a negative constant converted to `uint`".to_string(),
                "a negative float",
                format!(
                    "the result is undefined; {ANGLE} convert through `int` (`uint(-1.0)` is 4294967295)"
                ),
            ),
            W::UndefinedCall => (
                Code::UndefinedConstantCall,
                format!("`{token}` is undefined for these constant arguments"),
                "undefined for these values",
                format!("{ANGLE} fold the undefined components to 0"),
            ),
        };
        let d = self.warning(code, span, message);
        d.label = label.into();
        d.token = token.into();
        d.notes.push(note);
    }

    pub(super) fn assign(
        &mut self,
        op: Option<BinaryOp>,
        l: &ast::Expr,
        r: &ast::Expr,
        span: Span,
    ) -> Expr {
        let lhs = self.expr(l);
        let rhs = self.expr(r);
        if is_error(&lhs) || is_error(&rhs) {
            return error_expr(span);
        }
        let op_text = op.map_or("=".to_string(), |o| format!("{}=", o.as_str()));
        if op.is_some_and(Self::is_es300_operator) && self.es100_operator(&op_text, span) {
            return error_expr(span);
        }
        if self.lang.es100 && op.is_none() && self.es100_array_operand(&lhs, "=", span) {
            return error_expr(span);
        }
        if !self.check_lvalue(&lhs, span, &op_text) {
            return error_expr(span);
        }
        let ok = match op {
            None => lhs.ty == rhs.ty,
            Some(o) => binary_result(o, &lhs.ty, &rhs.ty, &self.structs).is_ok_and(|t| t == lhs.ty),
        };
        if !ok {
            let (lt, rt) = (self.type_name(&lhs.ty), self.type_name(&rhs.ty));
            let fix = conversion_fix(self.file, &rhs, &lhs.ty);
            let d = self.error(
                Code::TypeMismatch,
                rhs.span,
                match op {
                    None => format!("cannot assign {rt} to {lt}"),
                    Some(_) => format!("`{op_text}` cannot combine {lt} with {rt}"),
                },
            );
            d.label = format!("this is {rt}");
            d.token = op_text;
            d.secondary.push(Label {
                span: lhs.span,
                message: format!("this is {lt}"),
            });
            if lhs.ty.scalar_kind() != rhs.ty.scalar_kind() {
                d.notes
                    .push("GLSL ES 3.00 has no implicit conversions".into());
            }
            if let Some(f) = fix {
                d.help = Some(f.message.clone());
                d.fix = Some(f);
            }
            return error_expr(span);
        }
        let ty = lhs.ty.clone();
        if ty.contains_sampler(&self.structs) {
            let d = self.error(Code::SamplerAssignment, span, "samplers cannot be assigned");
            d.label = "assigns a sampler".into();
            return error_expr(span);
        }
        Expr {
            kind: ExprKind::Assign(op, Box::new(lhs), Box::new(rhs)),
            ty,
            span,
        }
    }

    /// Whether an expression can be written; reports why not.
    pub(in crate::check) fn check_lvalue(&mut self, e: &Expr, at: Span, op: &str) -> bool {
        if self.es100_writes_loop_index(e) {
            return false;
        }
        let why: Option<(String, Span)> = self.lvalue_problem(e);
        match why {
            None => true,
            Some((msg, span)) => {
                let d = self.error(Code::NotAssignable, span, msg);
                d.label = "cannot be written".into();
                d.token = if op.contains('=') {
                    "assign".into()
                } else {
                    op.into()
                };
                let _ = at;
                false
            }
        }
    }

    fn lvalue_problem(&self, e: &Expr) -> Option<(String, Span)> {
        // `+x` is checked as `x` itself (the operator does nothing), but its value is not a
        // variable: the text tells it apart, as no variable's text starts with `+`.
        let text = self.file.slice(e.span);
        if !matches!(e.kind, ExprKind::Error)
            && text
                .trim_start_matches(|c: char| c == '(' || c.is_whitespace())
                .starts_with('+')
        {
            return Some((
                "`+x` is a value, not a variable: it cannot be assigned".into(),
                e.span,
            ));
        }
        match &e.kind {
            ExprKind::Local(_) => None,
            ExprKind::Param(i) => {
                let f = self.fctx.as_ref()?.func;
                let p = &self.functions[f].params[*i];
                p.is_const.then(|| {
                    (
                        format!("cannot assign to `const` parameter `{}`", p.name),
                        e.span,
                    )
                })
            }
            ExprKind::Global(g) => {
                let g = &self.globals[*g];
                match g.kind {
                    GlobalKind::Private | GlobalKind::Output => None,
                    GlobalKind::Uniform | GlobalKind::BlockMember(..) => {
                        Some((format!("cannot assign to uniform `{}`", g.name), e.span))
                    }
                    GlobalKind::Input => {
                        Some((format!("cannot assign to input `{}`", g.name), e.span))
                    }
                    GlobalKind::Const => {
                        Some((format!("cannot assign to constant `{}`", g.name), e.span))
                    }
                }
            }
            ExprKind::BuiltinVar(v) => (!v.writable_in(self.stage)).then(|| {
                (
                    format!("cannot assign to read-only built-in `{}`", v.name()),
                    e.span,
                )
            }),
            ExprKind::BlockMember(..) => {
                Some(("cannot assign to a uniform block member".into(), e.span))
            }
            ExprKind::Index(b, _) | ExprKind::Member(b, _) => self.lvalue_problem(b),
            // `(a, v) = x` writes `v` where `a` does nothing (ANGLE keeps only `v` of such a
            // comma expression), unless `v` is a global or a parameter as such (`(a, g)`,
            // `(a, out)`, `(a, p)`, which Chromium refuses while it takes `(a, out.x)`);
            // `(w += 1.0, v)` is a value.
            ExprKind::Comma(a, b)
                if !a.has_effects()
                    && !matches!(b.kind, ExprKind::Global(_) | ExprKind::Param(_)) =>
            {
                self.lvalue_problem(b)
            }
            ExprKind::Swizzle(b, comps) => {
                for (i, c) in comps.iter().enumerate() {
                    if comps[..i].contains(c) {
                        return Some((
                            "a swizzle with repeated components cannot be assigned".into(),
                            e.span,
                        ));
                    }
                }
                self.lvalue_problem(b)
            }
            // Already reported.
            ExprKind::Error => None,
            ExprKind::Const(_) => Some(match self.file.slice(e.span).chars().next() {
                Some(c) if c.is_ascii_alphabetic() || c == '_' => (
                    format!("cannot assign to constant `{}`", self.file.slice(e.span)),
                    e.span,
                ),
                _ => ("cannot assign to a constant value".into(), e.span),
            }),
            _ => Some((
                "this expression cannot be assigned (it is not a variable)".into(),
                e.span,
            )),
        }
    }

    pub(super) fn ternary(
        &mut self,
        c: &ast::Expr,
        a: &ast::Expr,
        b: &ast::Expr,
        span: Span,
    ) -> Expr {
        let c = self.expr(c);
        let a = self.expr(a);
        let b = self.expr(b);
        if is_error(&c) || is_error(&a) || is_error(&b) {
            return error_expr(span);
        }
        if c.ty != Type::BOOL {
            let t = self.type_name(&c.ty);
            let d = self.error(
                Code::TypeMismatch,
                c.span,
                format!("the condition of `?:` must be a `bool`, not {t}"),
            );
            d.label = format!("this is {t}");
            d.token = "?".into();
            return error_expr(span);
        }
        if a.ty != b.ty {
            let (at, bt) = (self.type_name(&a.ty), self.type_name(&b.ty));
            let d = self.error(
                Code::TypeMismatch,
                span,
                format!("the two sides of `?:` differ: {at} and {bt}"),
            );
            d.label = "both sides must have the same type".into();
            d.token = ":".into();
            d.secondary.push(Label {
                span: a.span,
                message: at,
            });
            d.secondary.push(Label {
                span: b.span,
                message: bt,
            });
            return error_expr(span);
        }
        let what = match &a.ty {
            Type::Struct(_) => Some("structs"),
            t => self.webgl_forbidden_operand(t),
        };
        if let Some(what) = what {
            let d = self.error(
                Code::WebglForbiddenOperand,
                span,
                format!("the ternary operator `?:` cannot select {what} in WebGL"),
            );
            if what == "structs" {
                d.help = Some("select the members one by one, or use `if`".into());
            }
            d.label = format!("both sides are {what}");
            d.token = "?:".into();
            return error_expr(span);
        }
        if a.ty.contains_sampler(&self.structs) {
            let d = self.error(Code::InvalidOperands, span, "`?:` cannot select samplers");
            d.label = "samplers".into();
            return error_expr(span);
        }
        let ty = a.ty.clone();
        // A constant condition selects one side (WebGL then ignores the other side's uses).
        if let Some([Scalar::B(v)]) = c.as_const().and_then(|c| c.scalars()) {
            let chosen = if *v { a } else { b };
            return Expr { span, ..chosen };
        }
        Expr {
            kind: ExprKind::Select(Box::new(c), Box::new(a), Box::new(b)),
            ty,
            span,
        }
    }
}
