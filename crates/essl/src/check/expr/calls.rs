//! Function calls: user functions, built-in functions and overload resolution.

use super::{constant, error_expr, is_error};
use crate::ast::{self, Callee};
use crate::builtins::{self, BuiltinFn};
use crate::check::fold;
use crate::check::{Checker, Sym};
use crate::diagnostic::{Applicability, Fix};
use crate::diagnostic_code::Code;
use crate::hir::{ConstValue, Expr, ExprKind, ParamMode, Scalar};
use crate::source::Span;
use crate::types::{ScalarKind, Type};
use crate::Stage;

impl Checker<'_> {
    pub(super) fn call(&mut self, callee: &Callee, args: &[ast::Expr], span: Span) -> Expr {
        match callee {
            Callee::Length(base) => {
                let b = self.expr(base);
                if is_error(&b) {
                    return error_expr(span);
                }
                if self.lang.es100 {
                    let d = self.not_in_es100(span, "the `.length()` method");
                    d.token = "length".into();
                    d.help = Some("write the array's size".into());
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
                            Code::InvalidLength,
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
                if self.lang.es100 && spec.array.is_some() {
                    let d = self.not_in_es100(spec.span, "an array constructor");
                    d.token = "[]".into();
                    d.help = Some("declare the array, then assign its elements".into());
                    return error_expr(span);
                }
                let Some(ty) = self.resolve_type(spec) else {
                    return error_expr(span);
                };
                self.construct(ty, args, span, spec.span)
            }
            Callee::Name(id) => {
                let args: Vec<Expr> = args.iter().map(|a| self.expr(a)).collect();
                let builtins = builtins::overloads_in(&id.name, self.lang.es100);
                match self.lookup(&id.name).cloned() {
                    Some(Sym::Struct(s)) => self.construct(Type::Struct(s), args, span, id.span),
                    // GLSL ES 1.00 lets a shader overload a built-in function: both sets count.
                    Some(Sym::Funcs(ids)) if self.lang.es100 && builtins.is_some() => {
                        let sigs = builtins.expect("checked");
                        if self.user_overload_matches(&ids, &args) {
                            self.user_call(id, &ids, args, span)
                        } else {
                            self.builtin_call(id, sigs, args, span)
                        }
                    }
                    Some(Sym::Funcs(ids)) => self.user_call(id, &ids, args, span),
                    Some(Sym::Var(_)) | Some(Sym::Block(_)) => {
                        let hides = self.scopes[0]
                            .names
                            .get(&id.name)
                            .is_some_and(|s| matches!(s, Sym::Funcs(_)));
                        let d = self.error(
                            Code::NotAFunction,
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
                    None => match builtins {
                        Some(sigs) => self.builtin_call(id, sigs, args, span),
                        None => {
                            let es100 = self.lang.es100;
                            let es300_builtin =
                                es100 && builtins::overloads_in(&id.name, false).is_some();
                            let d = self.error(
                                Code::UndeclaredFunction,
                                id.span,
                                format!("no function named `{}` is declared", id.name),
                            );
                            d.label = "not declared before this call".into();
                            let help = match &*id.name {
                                "texture" | "textureLod" | "textureProj" if es100 => Some("GLSL ES 1.00 samples with `texture2D` (a `sampler2D`) or `textureCube` (a `samplerCube`), `texture2DProj`, and `texture2DLod`/`textureCubeLod` in vertex shaders".to_string()),
                                _ if es300_builtin => Some(format!("`{}` is a GLSL ES 3.00 built-in function: start the shader with `#version 300 es` (WebGL 2), or write it out", id.name)),
                                "texture2D" | "textureCube" | "texture3D" => Some("`texture2D`/`textureCube` are GLSL ES 1.00; in GLSL ES 3.00 use `texture`".to_string()),
                                "texture2DLod" | "textureCubeLod" => Some("in GLSL ES 3.00 use `textureLod`".to_string()),
                                "texture2DProj" => Some("in GLSL ES 3.00 use `textureProj`".to_string()),
                                "saturate" => Some("GLSL has no `saturate`: use `clamp(x, 0.0, 1.0)`".to_string()),
                                "lerp" => Some("GLSL calls it `mix`".to_string()),
                                "frac" => Some("GLSL calls it `fract`".to_string()),
                                "atan2" => Some("GLSL's two-argument arctangent is `atan(y, x)`".to_string()),
                                "mul" => Some("GLSL multiplies matrices with `*`".to_string()),
                                _ => match crate::near::builtin_function(&id.name, es100) {
                                    Some(near) => {
                                        d.fix = Some(Fix::suggested(
                                            format!("call `{near}`"),
                                            id.span,
                                            near,
                                        ));
                                        Some(format!("a built-in function with a similar name exists, `{near}`"))
                                    }
                                    None => Some("functions must be declared (or prototyped) before they are called".to_string()),
                                },
                            };
                            if let Some(h) = help {
                                if !es100 && h.starts_with('`') && h.contains("texture") {
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

    /// Whether one of the user functions `ids` takes exactly these arguments.
    fn user_overload_matches(&self, ids: &[usize], args: &[Expr]) -> bool {
        ids.iter().any(|&f| {
            let ps = &self.functions[f].params;
            ps.len() == args.len() && ps.iter().zip(args).all(|(p, a)| p.ty == a.ty)
        })
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
                Code::NoMatchingOverload,
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
                Code::NoMatchingOverload,
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
        if self.builtin_unavailable(&id.name, sig, id.span) {
            return error_expr(span);
        }
        if sig.fragment_only && self.stage != Stage::Fragment {
            let d = self.error(
                Code::FragmentOnlyBuiltin,
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
                                Code::TexelOffsetRange,
                                off.span,
                                format!("texel offsets must be between {lo} and {hi}"),
                            );
                            d.label = "out of range".into();
                            return error_expr(span);
                        }
                    }
                    None => {
                        let d = self.error(
                            Code::NonConstantOffset,
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
                let mut warnings = Vec::new();
                if let Some(v) = fold::builtin(sig.op, &cs, &tys, &ty, &mut warnings) {
                    for w in warnings {
                        self.fold_warning(w, sig.op.name(), span);
                    }
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
}
