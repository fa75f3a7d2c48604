//! Expressions: names, operators, l-values, swizzles, calls, overloads and constructors.

use super::fold;
use super::{Checker, Sym, Var};
use crate::ast::{self, BinaryOp, Callee, UnaryOp};
use crate::builtins::{self, BuiltinFn, BuiltinVar};
use crate::diagnostic::{Applicability, Fix, Label};
use crate::hir::{self, ConstValue, Expr, ExprKind, GlobalKind, ParamMode, Scalar};
use crate::source::{SourceFile, Span};
use crate::types::{ScalarKind, Type};
use crate::Stage;

/// An expression that failed to check: type `void`, already reported.
pub(crate) fn error_expr(span: Span) -> Expr {
    Expr {
        kind: ExprKind::Const(ConstValue::Composite(Vec::new())),
        ty: Type::Void,
        span,
    }
}

/// Whether an expression failed to check (errors are silent from then on).
pub(crate) fn is_error(e: &Expr) -> bool {
    e.ty == Type::Void && matches!(e.kind, ExprKind::Const(_))
}

fn constant(value: ConstValue, ty: Type, span: Span) -> Expr {
    Expr {
        kind: ExprKind::Const(value),
        ty,
        span,
    }
}

/// A fix that converts an expression to the wanted type: `1` → `1.0` for an integer literal
/// (certain), `float(x)` otherwise (suggested).
pub(crate) fn conversion_fix(file: &SourceFile, e: &Expr, want: &Type) -> Option<Fix> {
    let got = &e.ty;
    let text = file.slice(e.span);
    if got.vector_size() != want.vector_size()
        || got.scalar_kind().is_none()
        || want.scalar_kind().is_none()
    {
        return None;
    }
    let want_kind = want.scalar_kind()?;
    if got.is_scalar() && text.bytes().all(|b| b.is_ascii_digit()) && !text.is_empty() {
        let value: u64 = text.parse().ok()?;
        return match want_kind {
            ScalarKind::Float if value < (1 << 24) => Some(Fix {
                message: format!("write a float literal: `{text}.0`"),
                edits: vec![crate::diagnostic::Edit {
                    span: e.span,
                    replacement: format!("{text}.0"),
                }],
                applicability: Applicability::Certain,
            }),
            ScalarKind::Uint => Some(Fix {
                message: format!("write an unsigned literal: `{text}u`"),
                edits: vec![crate::diagnostic::Edit {
                    span: e.span,
                    replacement: format!("{text}u"),
                }],
                applicability: Applicability::Certain,
            }),
            _ => None,
        };
    }
    let ctor = want.display(&[]).to_string();
    Some(Fix::suggested(
        format!("convert explicitly: `{ctor}({text})`"),
        e.span,
        format!("{ctor}({text})"),
    ))
}

/// The component set of a swizzle letter, and its index.
fn swizzle_component(c: u8) -> Option<(u8, u8)> {
    Some(match c {
        b'x' => (0, 0),
        b'y' => (0, 1),
        b'z' => (0, 2),
        b'w' => (0, 3),
        b'r' => (1, 0),
        b'g' => (1, 1),
        b'b' => (1, 2),
        b'a' => (1, 3),
        b's' => (2, 0),
        b't' => (2, 1),
        b'p' => (2, 2),
        b'q' => (2, 3),
        _ => return None,
    })
}

/// The result type of `lhs op rhs`, or why it is invalid.
pub(crate) fn binary_result(
    op: BinaryOp,
    l: &Type,
    r: &Type,
    structs: &[crate::types::StructDef],
) -> Result<Type, String> {
    use BinaryOp::*;
    use ScalarKind::*;
    let lk = l.scalar_kind();
    let rk = r.scalar_kind();
    match op {
        Add | Sub | Mul | Div => {
            let (Some(lk), Some(rk)) = (lk, rk) else {
                return Err("arithmetic needs numbers, vectors or matrices".into());
            };
            if lk == Bool || rk == Bool {
                return Err("arithmetic is not defined on `bool`".into());
            }
            if lk != rk {
                return Err("the operands have different base types and GLSL ES 3.00 has no implicit conversions".into());
            }
            match (l, r) {
                (a, b) if a == b => {
                    if op == Mul {
                        if let Type::Matrix { cols, rows } = a {
                            if cols != rows {
                                return Err(
                                    "a non-square matrix times itself has mismatched dimensions"
                                        .into(),
                                );
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
                        Err(format!(
                            "a matrix with {cols} columns cannot multiply a {n}-component vector"
                        ))
                    }
                }
                (Type::Vector(_, n), Type::Matrix { cols, rows }) if op == Mul => {
                    if *rows == *n {
                        Ok(Type::Vector(Float, *cols))
                    } else {
                        Err(format!(
                            "a {n}-component vector cannot multiply a matrix with {rows} rows"
                        ))
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
                        Err(format!(
                            "a {c1}-column matrix cannot multiply a {r2}-row matrix"
                        ))
                    }
                }
                _ => Err("the operands' sizes do not match".into()),
            }
        }
        Mod | BitAnd | BitOr | BitXor => {
            let (Some(lk), Some(rk)) = (lk, rk) else {
                return Err("needs integers".into());
            };
            if !matches!(lk, Int | Uint)
                || !matches!(rk, Int | Uint)
                || l.vector_size().is_none()
                || r.vector_size().is_none()
            {
                return Err(format!(
                    "`{}` needs `int` or `uint` operands (scalars or vectors)",
                    op.as_str()
                ));
            }
            if lk != rk {
                return Err("the operands must both be signed or both unsigned".into());
            }
            match (l, r) {
                (a, b) if a == b => Ok(a.clone()),
                (Type::Scalar(_), t) | (t, Type::Scalar(_)) => Ok(t.clone()),
                _ => Err("the operands' sizes do not match".into()),
            }
        }
        Shl | Shr => {
            let (Some(lk), Some(rk)) = (lk, rk) else {
                return Err("needs integers".into());
            };
            if !matches!(lk, Int | Uint)
                || !matches!(rk, Int | Uint)
                || l.vector_size().is_none()
                || r.vector_size().is_none()
            {
                return Err("shifts need `int` or `uint` operands (scalars or vectors)".into());
            }
            match (l, r) {
                (Type::Scalar(_), Type::Scalar(_)) => Ok(l.clone()),
                (Type::Vector(_, n), Type::Scalar(_)) => Ok(Type::Vector(lk, *n)),
                (Type::Vector(_, n), Type::Vector(_, m)) if n == m => Ok(l.clone()),
                (Type::Scalar(_), Type::Vector(..)) => {
                    Err("a scalar cannot be shifted by a vector".into())
                }
                _ => Err("the operands' sizes do not match".into()),
            }
        }
        Less | Greater | LessEq | GreaterEq => {
            if l != r {
                return Err("the operands have different types".into());
            }
            match l {
                Type::Scalar(Float | Int | Uint) => Ok(Type::BOOL),
                _ => Err("relational operators compare scalar numbers only (use `lessThan` etc. for vectors)".into()),
            }
        }
        Eq | NotEq => {
            if l != r {
                return Err("the operands have different types".into());
            }
            if l.contains_sampler(structs) || matches!(l, Type::Void | Type::Sampler(_)) {
                return Err("samplers cannot be compared".into());
            }
            Ok(Type::BOOL)
        }
        And | Or | Xor => {
            if *l == Type::BOOL && *r == Type::BOOL {
                Ok(Type::BOOL)
            } else {
                Err(format!("`{}` needs `bool` operands", op.as_str()))
            }
        }
    }
}

impl Checker<'_> {
    /// Checks an expression.
    pub(crate) fn expr(&mut self, e: &ast::Expr) -> Expr {
        let span = e.span;
        match &e.kind {
            ast::ExprKind::Error => error_expr(span),
            ast::ExprKind::Int(v, unsigned) => {
                if *unsigned {
                    constant(
                        ConstValue::Basic(vec![Scalar::U(*v as u32)]),
                        Type::UINT,
                        span,
                    )
                } else {
                    constant(
                        ConstValue::Basic(vec![Scalar::I(*v as u32 as i32)]),
                        Type::INT,
                        span,
                    )
                }
            }
            ast::ExprKind::Float(f) => {
                constant(ConstValue::Basic(vec![Scalar::F(*f)]), Type::FLOAT, span)
            }
            ast::ExprKind::Bool(b) => {
                constant(ConstValue::Basic(vec![Scalar::B(*b)]), Type::BOOL, span)
            }
            ast::ExprKind::Ident(id) => self.ident(id),
            ast::ExprKind::Unary(op, a) => self.unary(*op, a, span),
            ast::ExprKind::Binary(op, a, b) => {
                let a = self.expr(a);
                let b = self.expr(b);
                self.binary(*op, a, b, span)
            }
            ast::ExprKind::Assign(op, l, r) => self.assign(*op, l, r, span),
            ast::ExprKind::Ternary(c, a, b) => self.ternary(c, a, b, span),
            ast::ExprKind::Comma(a, b) => {
                let a = self.expr(a);
                let b = self.expr(b);
                if is_error(&a) || is_error(&b) {
                    return error_expr(span);
                }
                if let Some(what) = [&a, &b]
                    .iter()
                    .find_map(|e| self.webgl_forbidden_operand(&e.ty))
                {
                    let d = self.error(
                        "webgl-forbidden-operand",
                        span,
                        format!("the sequence operator `,` cannot be used with {what} in WebGL"),
                    );
                    d.label = format!("an operand is {what}");
                    d.token = ",".into();
                    return error_expr(span);
                }
                let ty = b.ty.clone();
                Expr {
                    kind: ExprKind::Comma(Box::new(a), Box::new(b)),
                    ty,
                    span,
                }
            }
            ast::ExprKind::Index(base, index) => self.index(base, index, span),
            ast::ExprKind::Field(base, name) => self.field(base, name, span),
            ast::ExprKind::Call(callee, args) => self.call(callee, args, span),
        }
    }

    /// WebGL2 forbids `?:` and `,` on arrays, structs containing arrays, and `void`.
    fn webgl_forbidden_operand(&self, ty: &Type) -> Option<&'static str> {
        match ty {
            Type::Void => Some("`void` values"),
            Type::Array(..) => Some("arrays"),
            Type::Struct(_) if ty.contains_array(&self.structs) => {
                Some("structs containing arrays")
            }
            _ => None,
        }
    }

    fn ident(&mut self, id: &ast::Ident) -> Expr {
        let span = id.span;
        match self.lookup(&id.name).cloned() {
            Some(Sym::Var(Var::Local(l))) => {
                let local = &self.fctx.as_ref().expect("function").locals[l];
                let ty = local.ty.clone();
                match &local.constant {
                    Some(c) => constant(c.clone(), ty, span),
                    None if ty == Type::Void => error_expr(span),
                    None => Expr {
                        kind: ExprKind::Local(l),
                        ty,
                        span,
                    },
                }
            }
            Some(Sym::Var(Var::Param(i))) => {
                let f = self.fctx.as_ref().expect("function").func;
                let ty = self.functions[f].params[i].ty.clone();
                Expr {
                    kind: ExprKind::Param(i),
                    ty,
                    span,
                }
            }
            Some(Sym::Var(Var::Global(g))) => {
                let global = &self.globals[g];
                let ty = global.ty.clone();
                if global.kind == GlobalKind::Const {
                    match &global.init {
                        Some(hir::Init::Const(c)) => return constant(c.clone(), ty, span),
                        _ => return error_expr(span),
                    }
                }
                Expr {
                    kind: ExprKind::Global(g),
                    ty,
                    span,
                }
            }
            Some(Sym::Funcs(_)) => {
                let d = self.error(
                    "not-a-value",
                    span,
                    format!("`{}` is a function, not a value", id.name),
                );
                d.label = "a function name".into();
                d.help = Some(format!("call it: `{}(…)`", id.name));
                error_expr(span)
            }
            Some(Sym::Struct(_)) => {
                let d = self.error(
                    "not-a-value",
                    span,
                    format!("`{}` is a type, not a value", id.name),
                );
                d.label = "a struct name".into();
                error_expr(span)
            }
            Some(Sym::Block(_)) => {
                let d = self.error(
                    "not-a-value",
                    span,
                    format!("`{}` is a uniform block; use one of its members", id.name),
                );
                d.label = "a block instance".into();
                error_expr(span)
            }
            None => {
                if let Some(v) = BuiltinVar::lookup(&id.name, self.stage) {
                    let ty = self.builtin_var_type(v);
                    return Expr {
                        kind: ExprKind::BuiltinVar(v),
                        ty,
                        span,
                    };
                }
                if let Some(c) = builtins::constant(&id.name) {
                    return constant(ConstValue::Basic(vec![Scalar::I(c)]), Type::INT, span);
                }
                self.undeclared(id);
                error_expr(span)
            }
        }
    }

    fn undeclared(&mut self, id: &ast::Ident) {
        let name = &*id.name;
        let other_stage = BuiltinVar::lookup(
            name,
            if self.stage == Stage::Vertex {
                Stage::Fragment
            } else {
                Stage::Vertex
            },
        );
        let stage_name = if self.stage == Stage::Vertex {
            "fragment"
        } else {
            "vertex"
        };
        let similar = self.similar_name(name);
        let ended = self
            .ended
            .iter()
            .rev()
            .find(|(n, _)| &**n == name)
            .map(|(_, sp)| *sp);
        let ended_line = ended.map(|sp| self.file.line_of(sp.start));
        let d = self.error(
            "undeclared-identifier",
            id.span,
            format!("`{name}` is not declared"),
        );
        d.label = "not declared in this scope".into();
        match name {
            "gl_FragColor" | "gl_FragData" => {
                d.label = "a GLSL ES 1.00 built-in".into();
                d.help = Some(format!(
                    "`{name}` does not exist in GLSL ES 3.00: declare an output such as `out vec4 fragColor;` and write to it"
                ));
            }
            "gl_Vertex" | "gl_Normal" | "gl_ModelViewMatrix" | "gl_ModelViewProjectionMatrix" => {
                d.help = Some("desktop GL's fixed-function built-ins do not exist in GLSL ES; declare an `in` or a `uniform`".into());
            }
            _ if other_stage.is_some() => {
                d.help = Some(format!("`{name}` only exists in {stage_name} shaders"));
            }
            _ => {
                if let (Some(sp), Some(line)) = (ended, ended_line) {
                    d.secondary.push(Label {
                        span: sp,
                        message: format!(
                            "`{name}` is declared here, in a block that ends before this use"
                        ),
                    });
                    d.help = Some(format!("move the declaration of `{name}` (line {line}) out of its block, before it, so that it is still in scope here"));
                } else if let Some(similar) = similar {
                    d.help = Some(format!("a name in scope is similar: `{similar}`"));
                }
            }
        }
    }

    /// A declared name within edit distance 2 (case-insensitive match first).
    fn similar_name(&self, name: &str) -> Option<String> {
        let mut best: Option<(usize, String)> = None;
        for scope in &self.scopes {
            for (n, sym) in &scope.names {
                if matches!(sym, Sym::Funcs(_)) {
                    continue;
                }
                let dist = if n.eq_ignore_ascii_case(name) {
                    0
                } else {
                    edit_distance(n, name)
                };
                if dist <= 2
                    && dist < name.len().max(2)
                    && best.as_ref().is_none_or(|(b, _)| dist < *b)
                {
                    best = Some((dist, n.to_string()));
                }
            }
        }
        best.map(|(_, n)| n)
    }

    fn unary(&mut self, op: UnaryOp, a: &ast::Expr, span: Span) -> Expr {
        let a = self.expr(a);
        if is_error(&a) {
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
                "invalid-operand",
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

    pub(super) fn binary(&mut self, op: BinaryOp, a: Expr, b: Expr, span: Span) -> Expr {
        if is_error(&a) || is_error(&b) {
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
                    "invalid-operands",
                    span,
                    format!("`{}` cannot be applied to {lt} and {rt}", op.as_str()),
                );
                d.label = why;
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
            match fold::binary(op, x, &a.ty, y, &b.ty, &ty) {
                Ok(v) => return constant(v, ty, span),
                Err(fold::FoldError::DivideByZero) => {
                    let d = self.warning(
                        "division-by-zero",
                        span,
                        "division by zero in a constant expression",
                    );
                    d.label = "the divisor is zero".into();
                    d.token = "/".into();
                    d.notes.push("the result is undefined".into());
                }
                Err(fold::FoldError::Unsupported) => {}
            }
        }
        Expr {
            kind: ExprKind::Binary(op, Box::new(a), Box::new(b)),
            ty,
            span,
        }
    }

    fn assign(&mut self, op: Option<BinaryOp>, l: &ast::Expr, r: &ast::Expr, span: Span) -> Expr {
        let lhs = self.expr(l);
        let rhs = self.expr(r);
        if is_error(&lhs) || is_error(&rhs) {
            return error_expr(span);
        }
        let op_text = op.map_or("=".to_string(), |o| format!("{}=", o.as_str()));
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
                "type-mismatch",
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
            let d = self.error("sampler-assignment", span, "samplers cannot be assigned");
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
    pub(super) fn check_lvalue(&mut self, e: &Expr, at: Span, op: &str) -> bool {
        let why: Option<(String, Span)> = self.lvalue_problem(e);
        match why {
            None => true,
            Some((msg, span)) => {
                let d = self.error("not-assignable", span, msg);
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
            ExprKind::BuiltinVar(v) => (!v.writable()).then(|| {
                (
                    format!("cannot assign to read-only built-in `{}`", v.name()),
                    e.span,
                )
            }),
            ExprKind::BlockMember(..) => {
                Some(("cannot assign to a uniform block member".into(), e.span))
            }
            ExprKind::Index(b, _) | ExprKind::Member(b, _) => self.lvalue_problem(b),
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

    fn ternary(&mut self, c: &ast::Expr, a: &ast::Expr, b: &ast::Expr, span: Span) -> Expr {
        let c = self.expr(c);
        let a = self.expr(a);
        let b = self.expr(b);
        if is_error(&c) || is_error(&a) || is_error(&b) {
            return error_expr(span);
        }
        if c.ty != Type::BOOL {
            let t = self.type_name(&c.ty);
            let d = self.error(
                "type-mismatch",
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
                "type-mismatch",
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
        if let Some(what) = self.webgl_forbidden_operand(&a.ty) {
            let d = self.error(
                "webgl-forbidden-operand",
                span,
                format!("the ternary operator `?:` cannot select {what} in WebGL"),
            );
            d.label = format!("both sides are {what}");
            d.token = "?:".into();
            return error_expr(span);
        }
        if a.ty.contains_sampler(&self.structs) {
            let d = self.error("invalid-operands", span, "`?:` cannot select samplers");
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

    fn index(&mut self, base: &ast::Expr, index: &ast::Expr, span: Span) -> Expr {
        // A uniform block instance array: `blocks[i]` is only valid before `.member`.
        if let ast::ExprKind::Ident(id) = &base.kind {
            if let Some(Sym::Block(_)) = self.lookup(&id.name) {
                let d = self.error(
                    "not-a-value",
                    span,
                    "an element of a uniform block array must be followed by `.member`",
                );
                d.label = "a block, not a value".into();
                return error_expr(span);
            }
        }
        let b = self.expr(base);
        let i = self.expr(index);
        if is_error(&b) || is_error(&i) {
            return error_expr(span);
        }
        self.index_checked(b, i, span)
    }

    fn index_checked(&mut self, b: Expr, i: Expr, span: Span) -> Expr {
        let Some(elem) = b.ty.index_result() else {
            let t = self.type_name(&b.ty);
            let d = self.error("not-indexable", b.span, format!("{t} cannot be indexed"));
            d.label = "not an array, matrix or vector".into();
            d.token = "[".into();
            return error_expr(span);
        };
        if i.ty != Type::INT && i.ty != Type::UINT {
            let t = self.type_name(&i.ty);
            let d = self.error(
                "type-mismatch",
                i.span,
                format!("an index must be an `int` or `uint`, not {t}"),
            );
            d.label = format!("this is {t}");
            d.token = "[".into();
            return error_expr(span);
        }
        let bound = b.ty.index_bound().unwrap_or(0);
        if bound == 0 {
            // An array whose size is missing (a struct member `float b[]`), already reported.
            return error_expr(span);
        }
        if let Some(v) = i.as_const().and_then(|c| c.as_int()) {
            if v < 0 {
                let d = self.error(
                    "index-out-of-range",
                    i.span,
                    format!("index {v} is negative"),
                );
                d.label = "negative index".into();
                d.token = "[]".into();
                return error_expr(span);
            }
            if v >= bound as i64 {
                let what = if b.ty.is_array() {
                    "array"
                } else if matches!(b.ty, Type::Matrix { .. }) {
                    "matrix"
                } else {
                    "vector"
                };
                let d = self.error(
                    "index-out-of-range",
                    i.span,
                    format!("index {v} is out of range for a {what} of {bound}"),
                );
                d.label = format!("valid indices are 0 to {}", bound - 1);
                d.token = "[]".into();
                return error_expr(span);
            }
            if let Some(c) = b.as_const() {
                if let Some(v) = fold::index(c, &b.ty, v as usize) {
                    return constant(v, elem, span);
                }
            }
        } else if elem.contains_sampler(&self.structs) || matches!(elem, Type::Sampler(_)) {
            let d = self.error(
                "dynamic-sampler-index",
                i.span,
                "arrays of samplers can only be indexed with constant integral expressions",
            );
            d.label = "not a constant expression".into();
            d.token = "[".into();
            d.notes
                .push("GLSL ES 3.00 does not allow selecting a sampler at run time".into());
            d.help =
                Some("use a constant index, or an `if`/`switch` over the possible samplers".into());
            return error_expr(span);
        }
        Expr {
            kind: ExprKind::Index(Box::new(b), Box::new(i)),
            ty: elem,
            span,
        }
    }

    fn field(&mut self, base: &ast::Expr, name: &ast::Ident, span: Span) -> Expr {
        // Uniform block instance members.
        let block_ref = match &base.kind {
            ast::ExprKind::Ident(id) => match self.lookup(&id.name) {
                Some(Sym::Block(b)) => Some((*b, None)),
                _ => None,
            },
            ast::ExprKind::Index(inner, idx) => match &inner.kind {
                ast::ExprKind::Ident(id) => match self.lookup(&id.name) {
                    Some(Sym::Block(b)) => Some((*b, Some(idx))),
                    _ => None,
                },
                _ => None,
            },
            _ => None,
        };
        if let Some((b, idx)) = block_ref {
            return self.block_member(b, idx.map(|i| &**i), name, span);
        }
        let b = self.expr(base);
        if is_error(&b) {
            return error_expr(span);
        }
        match &b.ty {
            Type::Struct(id) => {
                let def = &self.structs[id.0 as usize];
                match def.members.iter().position(|m| *m.name == *name.name) {
                    Some(i) => {
                        let ty = def.members[i].ty.clone();
                        if let Some(ConstValue::Composite(members)) = b.as_const() {
                            return constant(members[i].clone(), ty, span);
                        }
                        Expr {
                            kind: ExprKind::Member(Box::new(b), i),
                            ty,
                            span,
                        }
                    }
                    None => {
                        let members: Vec<String> = def
                            .members
                            .iter()
                            .map(|m| format!("`{}`", m.name))
                            .collect();
                        let sname = def.name.clone().unwrap_or_else(|| "struct".into());
                        let d = self.error(
                            "no-such-field",
                            name.span,
                            format!("`{sname}` has no member `{}`", name.name),
                        );
                        d.label = "unknown member".into();
                        d.notes
                            .push(format!("its members are {}", members.join(", ")));
                        error_expr(span)
                    }
                }
            }
            Type::Vector(k, n) => {
                let (k, n) = (*k, *n);
                self.swizzle(b, k, n, name, span)
            }
            Type::Array(..) => {
                let d = self.error(
                    "invalid-field",
                    name.span,
                    format!("an array has no field `{}`", name.name),
                );
                d.label = "not a struct or vector".into();
                if &*name.name == "length" {
                    d.help = Some("the length of an array is `a.length()`".into());
                }
                error_expr(span)
            }
            t => {
                let t = self.type_name(t);
                let d = self.error(
                    "invalid-field",
                    name.span,
                    format!(
                        "{t} has no fields: `.{}` needs a struct or a vector",
                        name.name
                    ),
                );
                d.label = "field selection on a non-vector".into();
                if b.ty.is_scalar() {
                    d.notes
                        .push("GLSL ES 3.00 does not allow swizzling a scalar".into());
                }
                error_expr(span)
            }
        }
    }

    fn swizzle(&mut self, b: Expr, kind: ScalarKind, n: u8, name: &ast::Ident, span: Span) -> Expr {
        let text = name.name.as_bytes();
        let mut comps = Vec::new();
        let mut set: Option<u8> = None;
        for &c in text {
            let Some((s, i)) = swizzle_component(c) else {
                let d = self.error(
                    "invalid-swizzle",
                    name.span,
                    format!(
                        "`{}` is not a swizzle: `{}` is not a component name",
                        name.name, c as char
                    ),
                );
                d.label = "use x, y, z, w or r, g, b, a or s, t, p, q".into();
                return error_expr(span);
            };
            if set.is_some_and(|p| p != s) {
                let d = self.error(
                    "invalid-swizzle",
                    name.span,
                    format!("swizzle `{}` mixes component sets", name.name),
                );
                d.label = "use only one of xyzw, rgba or stpq".into();
                return error_expr(span);
            }
            set = Some(s);
            if i >= n {
                let d = self.error(
                    "invalid-swizzle",
                    name.span,
                    format!(
                        "swizzle `{}` reads past the end of a {n}-component vector",
                        name.name
                    ),
                );
                d.label = "component out of range".into();
                return error_expr(span);
            }
            comps.push(i);
        }
        if comps.len() > 4 {
            let d = self.error(
                "invalid-swizzle",
                name.span,
                "a swizzle selects at most 4 components",
            );
            d.label = "too many components".into();
            return error_expr(span);
        }
        let ty = Type::vec(kind, comps.len() as u8);
        if let Some(c) = b.as_const() {
            if let Some(v) = fold::swizzle(c, &comps) {
                return constant(v, ty, span);
            }
        }
        Expr {
            kind: ExprKind::Swizzle(Box::new(b), comps),
            ty,
            span,
        }
    }

    fn block_member(
        &mut self,
        block: usize,
        idx: Option<&ast::Expr>,
        name: &ast::Ident,
        span: Span,
    ) -> Expr {
        let idx = match idx {
            Some(i) => {
                let i = self.expr(i);
                if is_error(&i) {
                    return error_expr(span);
                }
                let Some(n) = self.blocks[block].array else {
                    let d = self.error(
                        "not-indexable",
                        i.span,
                        "this uniform block is not an array",
                    );
                    d.label = "index on a non-array block".into();
                    return error_expr(span);
                };
                match i.as_const().and_then(|c| c.as_int()) {
                    Some(v) if v >= 0 && v < n as i64 => Some(Box::new(i)),
                    Some(v) => {
                        let d = self.error(
                            "index-out-of-range",
                            i.span,
                            format!("index {v} is out of range for a block array of {n}"),
                        );
                        d.label = "out of range".into();
                        return error_expr(span);
                    }
                    None => {
                        let d = self.error(
                            "dynamic-block-index",
                            i.span,
                            "uniform block arrays can only be indexed with constant expressions",
                        );
                        d.label = "not a constant expression".into();
                        return error_expr(span);
                    }
                }
            }
            None => {
                if self.blocks[block].array.is_some() {
                    let d = self.error(
                        "not-a-value",
                        span,
                        "a uniform block array needs an index before `.member`",
                    );
                    d.label = "missing `[i]`".into();
                    return error_expr(span);
                }
                None
            }
        };
        let b = &self.blocks[block];
        match b.members.iter().position(|m| *m.0 == *name.name) {
            Some(m) => {
                let ty = b.members[m].1.clone();
                Expr {
                    kind: ExprKind::BlockMember(block, idx, m),
                    ty,
                    span,
                }
            }
            None => {
                let bname = b.name.clone();
                let d = self.error(
                    "no-such-field",
                    name.span,
                    format!("uniform block `{bname}` has no member `{}`", name.name),
                );
                d.label = "unknown member".into();
                error_expr(span)
            }
        }
    }

    // ----- calls -----

    fn call(&mut self, callee: &Callee, args: &[ast::Expr], span: Span) -> Expr {
        match callee {
            Callee::Length(base) => {
                let b = self.expr(base);
                if is_error(&b) {
                    return error_expr(span);
                }
                match b.ty {
                    Type::Array(_, n) => constant(
                        ConstValue::Basic(vec![Scalar::I(n as i32)]),
                        Type::INT,
                        span,
                    ),
                    _ => {
                        let t = self.type_name(&b.ty);
                        let d = self.error(
                            "invalid-length",
                            span,
                            format!("`.length()` needs an array, not {t}"),
                        );
                        d.label = "not an array".into();
                        d.token = "length".into();
                        error_expr(span)
                    }
                }
            }
            Callee::Type(spec) => {
                let args: Vec<Expr> = args.iter().map(|a| self.expr(a)).collect();
                let Some(ty) = self.resolve_type(spec) else {
                    return error_expr(span);
                };
                self.construct(ty, args, span, spec.span)
            }
            Callee::Name(id) => {
                let args: Vec<Expr> = args.iter().map(|a| self.expr(a)).collect();
                match self.lookup(&id.name).cloned() {
                    Some(Sym::Struct(s)) => self.construct(Type::Struct(s), args, span, id.span),
                    Some(Sym::Funcs(ids)) => self.user_call(id, &ids, args, span),
                    Some(Sym::Var(_)) | Some(Sym::Block(_)) => {
                        let hides = self.scopes[0]
                            .names
                            .get(&id.name)
                            .is_some_and(|s| matches!(s, Sym::Funcs(_)));
                        let d = self.error(
                            "not-a-function",
                            id.span,
                            format!("`{}` is a variable, not a function", id.name),
                        );
                        d.label = "not a function".into();
                        if hides {
                            d.notes.push(format!(
                                "a local declaration hides the function `{}`",
                                id.name
                            ));
                        }
                        error_expr(span)
                    }
                    None => match builtins::overloads(&id.name) {
                        Some(sigs) => self.builtin_call(id, sigs, args, span),
                        None => {
                            let d = self.error(
                                "undeclared-function",
                                id.span,
                                format!("no function named `{}` is declared", id.name),
                            );
                            d.label = "not declared before this call".into();
                            let help = match &*id.name {
                                "texture2D" | "textureCube" | "texture3D" => Some("`texture2D`/`textureCube` are GLSL ES 1.00; in GLSL ES 3.00 use `texture`".to_string()),
                                "texture2DLod" | "textureCubeLod" => Some("in GLSL ES 3.00 use `textureLod`".to_string()),
                                "texture2DProj" => Some("in GLSL ES 3.00 use `textureProj`".to_string()),
                                "saturate" => Some("GLSL has no `saturate`: use `clamp(x, 0.0, 1.0)`".to_string()),
                                "lerp" => Some("GLSL calls it `mix`".to_string()),
                                "frac" => Some("GLSL calls it `fract`".to_string()),
                                "atan2" => Some("GLSL's two-argument arctangent is `atan(y, x)`".to_string()),
                                "mul" => Some("GLSL multiplies matrices with `*`".to_string()),
                                _ => Some("functions must be declared (or prototyped) before they are called".to_string()),
                            };
                            if let Some(h) = help {
                                if h.starts_with('`') && h.contains("texture") {
                                    let replacement = match &*id.name {
                                        "texture2D" | "textureCube" | "texture3D" => "texture",
                                        "texture2DLod" | "textureCubeLod" => "textureLod",
                                        _ => "textureProj",
                                    };
                                    d.fix = Some(Fix::suggested(
                                        format!("use `{replacement}`"),
                                        id.span,
                                        replacement,
                                    ));
                                }
                                d.help = Some(h);
                            }
                            error_expr(span)
                        }
                    },
                }
            }
        }
    }

    fn arg_types(&self, args: &[Expr]) -> String {
        args.iter()
            .map(|a| format!("`{}`", a.ty.display(&self.structs)))
            .collect::<Vec<_>>()
            .join(", ")
    }

    fn user_call(&mut self, id: &ast::Ident, ids: &[usize], args: Vec<Expr>, span: Span) -> Expr {
        if args.iter().any(is_error) {
            return error_expr(span);
        }
        let found = ids.iter().copied().find(|&f| {
            let ps = &self.functions[f].params;
            ps.len() == args.len() && ps.iter().zip(&args).all(|(p, a)| p.ty == a.ty)
        });
        let Some(f) = found else {
            let cands: Vec<String> = ids
                .iter()
                .map(|&f| {
                    let func = &self.functions[f];
                    format!(
                        "`{} {}({})`",
                        func.ret.display(&self.structs),
                        func.name,
                        func.params
                            .iter()
                            .map(|p| p.ty.display(&self.structs).to_string())
                            .collect::<Vec<_>>()
                            .join(", ")
                    )
                })
                .collect();
            let at = self.arg_types(&args);
            let d = self.error(
                "no-matching-overload",
                id.span,
                format!("no declaration of `{}` takes ({at})", id.name),
            );
            d.label = "no matching declaration".into();
            d.notes.push(format!("declared: {}", cands.join(", ")));
            return error_expr(span);
        };
        let modes: Vec<ParamMode> = self.functions[f].params.iter().map(|p| p.mode).collect();
        for (a, m) in args.iter().zip(modes) {
            if m != ParamMode::In && !self.check_lvalue(a, a.span, "out") {
                return error_expr(span);
            }
        }
        if let Some(ctx) = self.fctx.as_mut() {
            ctx.calls.push(f);
        }
        let ty = self.functions[f].ret.clone();
        Expr {
            kind: ExprKind::Call(f, args),
            ty,
            span,
        }
    }

    fn builtin_call(
        &mut self,
        id: &ast::Ident,
        sigs: &'static [builtins::Signature],
        args: Vec<Expr>,
        span: Span,
    ) -> Expr {
        if args.iter().any(is_error) {
            return error_expr(span);
        }
        let sig = sigs.iter().find(|s| {
            s.params.len() == args.len() && s.params.iter().zip(&args).all(|(p, a)| p.0 == a.ty)
        });
        let Some(sig) = sig else {
            let at = self.arg_types(&args);
            let mut cands: Vec<String> = sigs
                .iter()
                .filter(|s| s.params.len() == args.len() || sigs.len() <= 8)
                .map(|s| {
                    format!(
                        "{}({})",
                        id.name,
                        s.params
                            .iter()
                            .map(|p| p.0.display(&[]).to_string())
                            .collect::<Vec<_>>()
                            .join(", ")
                    )
                })
                .collect();
            cands.dedup();
            let total = cands.len();
            cands.truncate(6);
            let fix = self.builtin_fix(id, sigs, &args);
            let d = self.error(
                "no-matching-overload",
                id.span,
                format!("no overload of `{}` takes ({at})", id.name),
            );
            d.label = "no matching overload".into();
            if total > 0 {
                d.notes.push(format!(
                    "candidates: {}{}",
                    cands.join("; "),
                    if total > 6 {
                        format!("; and {} more", total - 6)
                    } else {
                        String::new()
                    }
                ));
            }
            if let Some(f) = fix {
                d.help = Some(f.message.clone());
                d.fix = Some(f);
            }
            return error_expr(span);
        };
        if sig.fragment_only && self.stage != Stage::Fragment {
            let d = self.error(
                "fragment-only-builtin",
                id.span,
                if matches!(
                    sig.op,
                    BuiltinFn::DFdx | BuiltinFn::DFdy | BuiltinFn::Fwidth
                ) {
                    format!("`{}` is only available in fragment shaders", id.name)
                } else {
                    format!(
                        "`{}` with a bias argument is only available in fragment shaders",
                        id.name
                    )
                },
            );
            d.label = "not available in a vertex shader".into();
            return error_expr(span);
        }
        for (a, p) in args.iter().zip(&sig.params) {
            if p.1 != ParamMode::In && !self.check_lvalue(a, a.span, "out") {
                return error_expr(span);
            }
        }
        if sig.op.has_offset() {
            // The offset is the argument after the coordinates and lod/gradients: the one of
            // integer vector type after the first two.
            if let Some(off) = args
                .iter()
                .skip(2)
                .find(|a| matches!(a.ty, Type::Vector(ScalarKind::Int, _)))
            {
                match off.as_const().and_then(|c| c.scalars()) {
                    Some(vals) => {
                        let (lo, hi) = (
                            builtins::constant("gl_MinProgramTexelOffset").unwrap_or(-8),
                            builtins::constant("gl_MaxProgramTexelOffset").unwrap_or(7),
                        );
                        if vals
                            .iter()
                            .any(|v| !matches!(v, Scalar::I(x) if (lo..=hi).contains(x)))
                        {
                            let d = self.error(
                                "texel-offset-range",
                                off.span,
                                format!("texel offsets must be between {lo} and {hi}"),
                            );
                            d.label = "out of range".into();
                            return error_expr(span);
                        }
                    }
                    None => {
                        let d = self.error(
                            "non-constant-offset",
                            off.span,
                            "a texel offset must be a constant expression",
                        );
                        d.label = "not a constant expression".into();
                        return error_expr(span);
                    }
                }
            }
        }
        let ty = sig.ret.clone();
        if !sig.op.is_texture()
            && !matches!(
                sig.op,
                BuiltinFn::DFdx | BuiltinFn::DFdy | BuiltinFn::Fwidth | BuiltinFn::Modf
            )
        {
            let consts: Option<Vec<&ConstValue>> = args.iter().map(|a| a.as_const()).collect();
            if let Some(cs) = consts {
                let tys: Vec<&Type> = args.iter().map(|a| &a.ty).collect();
                if let Some(v) = fold::builtin(sig.op, &cs, &tys, &ty) {
                    return constant(v, ty, span);
                }
            }
        }
        Expr {
            kind: ExprKind::Builtin(sig.op, args),
            ty,
            span,
        }
    }

    /// For a failed built-in call: a candidate reached by widening scalar arguments to the
    /// vector type the other arguments have (`pow(v, 2.0)` → `pow(v, vec3(2.0))`).
    fn builtin_fix(
        &self,
        id: &ast::Ident,
        sigs: &[builtins::Signature],
        args: &[Expr],
    ) -> Option<Fix> {
        for s in sigs.iter().filter(|s| s.params.len() == args.len()) {
            let mut edits = Vec::new();
            let mut ok = true;
            for (p, a) in s.params.iter().zip(args) {
                if p.0 == a.ty {
                    continue;
                }
                if a.ty.is_scalar()
                    && p.0.scalar_kind() == a.ty.scalar_kind()
                    && matches!(p.0, Type::Vector(..))
                {
                    let ctor = p.0.display(&[]).to_string();
                    let text = self.file.slice(a.span);
                    edits.push(crate::diagnostic::Edit {
                        span: a.span,
                        replacement: format!("{ctor}({text})"),
                    });
                } else {
                    ok = false;
                    break;
                }
            }
            if ok && !edits.is_empty() {
                return Some(Fix {
                    message: format!(
                        "`{}` has no mixed vector/scalar form here: widen the scalar",
                        id.name
                    ),
                    edits,
                    applicability: Applicability::Suggested,
                });
            }
        }
        None
    }

    // ----- constructors -----

    fn construct(&mut self, ty: Type, args: Vec<Expr>, span: Span, type_span: Span) -> Expr {
        if args.iter().any(is_error) {
            return error_expr(span);
        }
        let tname = self.type_name(&ty);
        let fail = |c: &mut Self, msg: String, label: &str| {
            let token = c.file.slice(type_span).to_string();
            let d = c.error("invalid-constructor", span, msg);
            d.label = label.into();
            d.token = token;
            error_expr(span)
        };
        if args.is_empty() {
            return fail(
                self,
                format!("a {tname} constructor needs arguments"),
                "no arguments",
            );
        }
        for a in &args {
            if a.ty == Type::Void {
                return fail(
                    self,
                    "a `void` value cannot be a constructor argument".into(),
                    "void argument",
                );
            }
            if a.ty.contains_sampler(&self.structs) {
                return fail(
                    self,
                    "samplers cannot be constructor arguments".into(),
                    "sampler argument",
                );
            }
        }
        let mut ty = ty;
        match &ty {
            Type::Void | Type::Sampler(_) => {
                return fail(
                    self,
                    format!("{tname} has no constructor"),
                    "no constructor",
                )
            }
            Type::Array(el, n) => {
                let el = (**el).clone();
                let n = *n;
                if n != 0 && args.len() != n as usize {
                    return fail(
                        self,
                        format!("{tname} needs {n} arguments, not {}", args.len()),
                        "wrong number of elements",
                    );
                }
                if let Some(bad) = args.iter().find(|a| a.ty != el) {
                    let (e, b) = (self.type_name(&el), self.type_name(&bad.ty));
                    let bspan = bad.span;
                    let d = self.error(
                        "invalid-constructor",
                        bspan,
                        format!("array elements must be {e}, not {b}"),
                    );
                    d.label = format!("this is {b}");
                    return error_expr(span);
                }
                ty = Type::Array(Box::new(el), args.len() as u32);
            }
            Type::Struct(id) => {
                let members = self.structs[id.0 as usize].members.clone();
                if members.len() != args.len() {
                    return fail(
                        self,
                        format!(
                            "{tname} has {} members but {} arguments are given",
                            members.len(),
                            args.len()
                        ),
                        "wrong number of arguments",
                    );
                }
                for (m, a) in members.iter().zip(&args) {
                    if m.ty != a.ty {
                        let (want, got) = (self.type_name(&m.ty), self.type_name(&a.ty));
                        let aspan = a.span;
                        let d = self.error(
                            "invalid-constructor",
                            aspan,
                            format!("member `{}` is {want}, not {got}", m.name),
                        );
                        d.label = format!("this is {got}");
                        return error_expr(span);
                    }
                }
            }
            Type::Scalar(_) => {
                if args.len() != 1 {
                    return fail(
                        self,
                        format!("a {tname} constructor takes one argument"),
                        "too many arguments",
                    );
                }
                if !args[0].ty.is_numeric_basic() {
                    let t = self.type_name(&args[0].ty);
                    return fail(
                        self,
                        format!("cannot construct {tname} from {t}"),
                        "not a scalar, vector or matrix",
                    );
                }
            }
            Type::Vector(_, n) | Type::Matrix { cols: n, .. } => {
                let needed = ty.component_count().unwrap_or(0);
                let is_matrix = matches!(ty, Type::Matrix { .. });
                let _ = n;
                if args.iter().any(|a| !a.ty.is_numeric_basic()) {
                    return fail(
                        self,
                        format!("{tname} can only be built from scalars, vectors and matrices"),
                        "invalid argument type",
                    );
                }
                let single = args.len() == 1;
                if is_matrix && !single && args.iter().any(|a| matches!(a.ty, Type::Matrix { .. }))
                {
                    return fail(
                        self,
                        format!(
                            "a matrix argument must be the only argument of a {tname} constructor"
                        ),
                        "matrix among other arguments",
                    );
                }
                if !single
                    || !(args[0].ty.is_scalar()
                        || (is_matrix && matches!(args[0].ty, Type::Matrix { .. })))
                {
                    let total: u32 = args
                        .iter()
                        .map(|a| a.ty.component_count().unwrap_or(0))
                        .sum();
                    let before_last: u32 = args[..args.len() - 1]
                        .iter()
                        .map(|a| a.ty.component_count().unwrap_or(0))
                        .sum();
                    if single && !is_matrix && total >= needed {
                        // vecN(vecM) with M >= N, vecN(matrix) with enough components.
                    } else if total < needed {
                        return fail(
                            self,
                            format!(
                                "{tname} needs {needed} components, but the arguments have {total}"
                            ),
                            "not enough components",
                        );
                    } else if before_last >= needed {
                        return fail(
                            self,
                            format!(
                                "too many arguments for {tname}: the last argument is not used"
                            ),
                            "too many arguments",
                        );
                    } else if is_matrix && single {
                        // mat from a vector: needs exactly enough? handled above.
                    }
                }
            }
        }
        let consts: Option<Vec<&ConstValue>> = args.iter().map(|a| a.as_const()).collect();
        if let Some(cs) = consts {
            let tys: Vec<&Type> = args.iter().map(|a| &a.ty).collect();
            if let Some(v) = fold::construct(&ty, &cs, &tys) {
                return constant(v, ty, span);
            }
        }
        Expr {
            kind: ExprKind::Construct(args),
            ty,
            span,
        }
    }
}

/// Levenshtein distance (small strings only).
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    if a.len().abs_diff(b.len()) > 2 {
        return 3;
    }
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let v = (prev[j] + usize::from(ca != cb))
                .min(prev[j + 1] + 1)
                .min(cur[j] + 1);
            cur.push(v);
        }
        prev = cur;
    }
    prev[b.len()]
}
