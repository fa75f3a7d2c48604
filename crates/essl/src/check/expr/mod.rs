//! Expressions: literals, names and the dispatch to operators, access, calls and constructors.
//!
//! The checker's `impl` is spread over the files of this module, one concern each: this file
//! types literals and names and dispatches on the expression's kind.

mod access;
mod calls;
mod construct;
mod operators;

use super::{Checker, Sym, Var};
use crate::ast;
use crate::builtins::{self, BuiltinVar};
use crate::diagnostic::{Applicability, Fix, Label};
use crate::diagnostic_code::Code;
use crate::hir::{self, ConstValue, Expr, ExprKind, GlobalKind, Scalar};
use crate::source::{SourceFile, Span};
use crate::types::{ScalarKind, Type};
use crate::Stage;

/// An expression that failed to check ([`ExprKind::Error`], type `void`), already reported.
pub(crate) fn error_expr(span: Span) -> Expr {
    Expr {
        kind: ExprKind::Error,
        ty: Type::Void,
        span,
    }
}

/// Whether an expression failed to check (errors are silent from then on).
pub(crate) fn is_error(e: &Expr) -> bool {
    matches!(e.kind, ExprKind::Error)
}

/// A constant expression of type `ty`.
pub(super) fn constant(value: ConstValue, ty: Type, span: Span) -> Expr {
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
                if Self::is_es300_operator(*op) && self.es100_operator(op.as_str(), span) {
                    return error_expr(span);
                }
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
                        Code::WebglForbiddenOperand,
                        span,
                        format!("the sequence operator `,` cannot be used with {what} in WebGL"),
                    );
                    d.label = format!("an operand is {what}");
                    d.token = ",".into();
                    return error_expr(span);
                }
                let ty = b.ty.clone();
                // GLSL ES 1.00 (not 3.00) counts a sequence of constants as a constant.
                if self.lang.es100 && a.as_const().is_some() {
                    if let Some(c) = b.as_const() {
                        return constant(c.clone(), ty, span);
                    }
                }
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
    pub(super) fn webgl_forbidden_operand(&self, ty: &Type) -> Option<&'static str> {
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
                    Code::NotAValue,
                    span,
                    format!("`{}` is a function, not a value", id.name),
                );
                d.label = "a function name".into();
                d.help = Some(format!("call it: `{}(…)`", id.name));
                error_expr(span)
            }
            Some(Sym::Struct(_)) => {
                let d = self.error(
                    Code::NotAValue,
                    span,
                    format!("`{}` is a type, not a value", id.name),
                );
                d.label = "a struct name".into();
                error_expr(span)
            }
            Some(Sym::Block(_)) => {
                let d = self.error(
                    Code::NotAValue,
                    span,
                    format!("`{}` is a uniform block; use one of its members", id.name),
                );
                d.label = "a block instance".into();
                error_expr(span)
            }
            None => {
                if let Some(v) =
                    BuiltinVar::lookup_in(&id.name, self.stage, &self.lang, id.span.start)
                {
                    let ty = self.builtin_var_type(v);
                    self.note_fragment_output(v, span);
                    return Expr {
                        kind: ExprKind::BuiltinVar(v),
                        ty,
                        span,
                    };
                }
                if let Some(c) = builtins::constant_in(&id.name, &self.lang) {
                    return constant(ConstValue::Basic(vec![Scalar::I(c)]), Type::INT, span);
                }
                self.undeclared(id);
                error_expr(span)
            }
        }
    }

    fn undeclared(&mut self, id: &ast::Ident) {
        let name = &*id.name;
        let other_stage = BuiltinVar::lookup_in(
            name,
            if self.stage == Stage::Vertex {
                Stage::Fragment
            } else {
                Stage::Vertex
            },
            &self.lang,
            id.span.start,
        );
        let stage_name = if self.stage == Stage::Vertex {
            "fragment"
        } else {
            "vertex"
        };
        let similar = self.similar_name(name);
        let lang_help = self.other_language_builtin(name);
        let es100 = self.lang.es100;
        let ended = self
            .ended
            .iter()
            .rev()
            .find(|(n, _)| &**n == name)
            .map(|(_, sp)| *sp);
        let ended_line = ended.map(|sp| self.file.line_of(sp.start));
        let d = self.error(
            Code::UndeclaredIdentifier,
            id.span,
            format!("`{name}` is not declared"),
        );
        d.label = "not declared in this scope".into();
        if let Some(help) = lang_help {
            d.help = Some(help);
            return;
        }
        match name {
            "gl_FragColor" | "gl_FragData" if !es100 => {
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
                } else if name.len() < 3 {
                    continue;
                } else {
                    crate::near::edit_distance(n, name)
                };
                if dist <= (name.len() / 3).clamp(1, 2)
                    && best.as_ref().is_none_or(|(b, _)| dist < *b)
                {
                    best = Some((dist, n.to_string()));
                }
            }
        }
        best.map(|(_, n)| n)
    }
}
