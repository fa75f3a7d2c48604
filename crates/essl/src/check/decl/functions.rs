//! Functions: prototypes and definitions, parameters, overload and redeclaration rules, and
//! the check that a non-void function returns.

use crate::diagnostic_code::Code;
use crate::Name;
use std::fmt::Write as _;

use crate::ast::{self, Qualifier, Storage};
use crate::check::{Checker, FnCtx, Sym, Var};
use crate::hir::{self, ParamMode};
use crate::types::{Precision, Type};

impl Checker<'_> {
    /// Declares a function (prototype or the signature of a definition). Returns its id.
    pub(in crate::check) fn function_decl(
        &mut self,
        proto: &ast::FunctionProto,
        defining: bool,
    ) -> Option<usize> {
        let name = &proto.name;
        if !self.lang.es100 && crate::builtins::is_builtin_function(&name.name) {
            let d = self.error(
                Code::BuiltinRedeclared,
                name.span,
                format!(
                    "`{}` is a built-in function and cannot be declared or overloaded",
                    name.name
                ),
            );
            d.label = "a built-in function's name".into();
            d.help = Some("choose another name".into());
            return None;
        }
        self.check_name(name);
        let (ret, ret_precision) = self.return_type(&proto.ret)?;
        // A struct defined in a parameter's type is scoped to the function.
        self.push_scope();
        let mut params = Vec::new();
        for p in &proto.params {
            if let Some(hp) = self.param(p) {
                params.push(hp);
            }
        }
        self.pop_scope();
        if params.len() != proto.params.len() {
            return None;
        }
        if self.lang.es100 && self.redefines_builtin(name, &params) {
            return None;
        }
        // `name(type,type)`, written into one string.
        let mut signature = String::with_capacity(name.name.len() + 8 * params.len() + 2);
        signature.push_str(&name.name);
        signature.push('(');
        for (i, p) in params.iter().enumerate() {
            if i > 0 {
                signature.push(',');
            }
            let _ = write!(signature, "{}", p.ty.display(&self.structs));
        }
        signature.push(')');
        self.check_main_signature(proto, &params, &ret);
        // Find an earlier declaration with the same parameter types.
        let existing = match self.lookup(&name.name).cloned() {
            Some(Sym::Funcs(ids)) => ids
                .iter()
                .copied()
                .find(|&f| self.functions[f].signature == signature),
            Some(_) if self.scopes[0].names.contains_key(&name.name) => {
                let d = self.error(
                    Code::Redefinition,
                    name.span,
                    format!(
                        "`{}` is already declared as something other than a function",
                        name.name
                    ),
                );
                d.label = "name already in use".into();
                return None;
            }
            _ => None,
        };
        if &*name.name == "main" {
            if let Some(Sym::Funcs(ids)) = self.lookup("main") {
                if ids
                    .iter()
                    .any(|&f| self.functions[f].signature != signature)
                {
                    let d = self.error(Code::InvalidMain, name.span, "`main` cannot be overloaded");
                    d.label = "a second `main`".into();
                    return None;
                }
            }
        }
        let f = match existing {
            Some(f) => self.redeclare_function(f, name, params, &ret, defining)?,
            None => self.add_function(name, signature, params, ret, ret_precision),
        };
        if !defining {
            if self.lang.es100 && self.fn_prototyped[f] {
                let d = self.error(
                    Code::FunctionRedeclared,
                    name.span,
                    format!("`{}` is declared twice", name.name),
                );
                d.label = "a second prototype".into();
                d.notes
                    .push("GLSL ES 1.00 allows one prototype per function".into());
                d.fix = Some(crate::diagnostic::Fix::suggested(
                    "remove this prototype",
                    proto.span,
                    "",
                ));
                return None;
            }
            self.fn_prototyped[f] = true;
        }
        Some(f)
    }

    /// GLSL ES 1.00 lets a shader overload a built-in function but not redefine one (the same
    /// parameter types): whether `params` redefine one (reported).
    fn redefines_builtin(&mut self, name: &ast::Ident, params: &[hir::Param]) -> bool {
        let Some(sigs) = crate::builtins::overloads_in(&name.name, true) else {
            return false;
        };
        let same = sigs.iter().any(|s| {
            s.params.len() == params.len() && s.params.iter().zip(params).all(|(a, b)| a.0 == b.ty)
        });
        if same {
            let d = self.error(
                Code::BuiltinRedeclared,
                name.span,
                format!("`{}` redefines a built-in function", name.name),
            );
            d.label = "a built-in function with these parameter types".into();
            d.notes.push(
                "GLSL ES 1.00 allows overloading a built-in function with other parameter types,                  not redefining it"
                    .into(),
            );
            d.help = Some("choose another name".into());
        }
        same
    }

    /// The return type and its precision: only a precision qualifier, a sized array, no
    /// sampler.
    fn return_type(&mut self, ret: &ast::FullType) -> Option<(Type, Option<Precision>)> {
        for (q, s) in &ret.qualifiers {
            if !matches!(q, Qualifier::Precision(_)) {
                let d = self.error(
                    Code::InvalidQualifier,
                    *s,
                    "a return type can only have a precision qualifier",
                );
                d.label = "not allowed on a return type".into();
            }
        }
        let ty = self.resolve_type(&ret.spec)?;
        if let Type::Array(_, 0) = ty {
            let d = self.error(
                Code::UnsizedArray,
                ret.spec.span,
                "a returned array needs a size",
            );
            d.label = "unsized".into();
        }
        if self.lang.es100 && matches!(ty, Type::Struct(_)) && ty.contains_array(&self.structs) {
            let d = self.error(
                Code::NotInEs100,
                ret.spec.span,
                "a function cannot return a struct containing an array in GLSL ES 1.00",
            );
            d.label = "a struct with an array member".into();
            d.help = Some("return the struct through an `out` parameter".into());
        }
        if ty.contains_sampler(&self.structs) {
            let d = self.error(
                Code::SamplerReturn,
                ret.spec.span,
                "functions cannot return a sampler",
            );
            d.label = "a sampler".into();
        }
        let precision = if ty == Type::Void {
            None
        } else {
            self.precision_for(&ty, ret.precision().map(|p| p.0), ret.spec.span)
        };
        Some((ty, precision))
    }

    /// `main` takes no parameters and returns `void`.
    fn check_main_signature(
        &mut self,
        proto: &ast::FunctionProto,
        params: &[hir::Param],
        ret: &Type,
    ) {
        let name = &proto.name;
        if &*name.name == "main" {
            if !params.is_empty() {
                let d = self.error(
                    Code::InvalidMain,
                    name.span,
                    "`main` cannot take parameters",
                );
                d.label = "`void main()` expected".into();
            }
            if *ret != Type::Void {
                let d = self.error(
                    Code::InvalidMain,
                    proto.ret.spec.span,
                    "`main` must return `void`",
                );
                d.label = "`void main()` expected".into();
            }
        }
    }

    /// A function declared again (a prototype, then its definition): the same return type and
    /// parameter qualifiers, one definition only. The function's id, `None` when invalid.
    fn redeclare_function(
        &mut self,
        f: usize,
        name: &ast::Ident,
        params: Vec<hir::Param>,
        ret: &Type,
        defining: bool,
    ) -> Option<usize> {
        if self.functions[f].ret != *ret {
            let prev = self.functions[f].span;
            let d = self.error(
                Code::FunctionRedeclared,
                name.span,
                format!(
                    "`{}` is declared again with a different return type",
                    name.name
                ),
            );
            d.label = "return type differs from the earlier declaration".into();
            d.secondary.push(crate::diagnostic::Label {
                span: prev,
                message: "first declared here".into(),
            });
            return None;
        }
        let modes_differ = self.functions[f]
            .params
            .iter()
            .zip(&params)
            .any(|(a, b)| a.mode != b.mode || a.is_const != b.is_const);
        if modes_differ {
            let d = self.error(
                Code::FunctionRedeclared,
                name.span,
                format!(
                    "`{}` is declared again with different parameter qualifiers",
                    name.name
                ),
            );
            d.label = "qualifiers differ from the earlier declaration".into();
            return None;
        }
        if defining {
            if self.fn_defined[f] {
                let prev = self.functions[f].span;
                let d = self.error(
                    Code::FunctionRedefined,
                    name.span,
                    format!("function `{}` is defined twice", name.name),
                );
                d.label = "second definition".into();
                d.secondary.push(crate::diagnostic::Label {
                    span: prev,
                    message: "first defined here".into(),
                });
                return None;
            }
            // The definition's parameter names win.
            self.functions[f].params = params;
            self.functions[f].span = name.span;
        }
        Some(f)
    }

    /// Adds a new function (or overload) to the module and the global scope; its id.
    fn add_function(
        &mut self,
        name: &ast::Ident,
        signature: String,
        params: Vec<hir::Param>,
        ret: Type,
        ret_precision: Option<Precision>,
    ) -> usize {
        let id = self.functions.len();
        self.functions.push(hir::Function {
            name: name.name.clone(),
            signature,
            params,
            ret,
            ret_precision,
            locals: Vec::new(),
            body: Vec::new(),
            calls: Vec::new(),
            span: name.span,
            used: false,
        });
        self.fn_defined.push(false);
        self.fn_prototyped.push(false);
        match self.scopes[0].names.get_mut(&name.name) {
            Some(Sym::Funcs(ids)) => ids.push(id),
            _ => {
                self.scopes[0]
                    .names
                    .insert(name.name.clone(), Sym::Funcs(vec![id]));
            }
        }
        if &*name.name == "main" {
            self.entry = Some(id);
        }
        id
    }

    fn param(&mut self, p: &ast::Param) -> Option<hir::Param> {
        let mut mode = ParamMode::In;
        let mut is_const = false;
        self.check_qualifier_list(&p.ty.qualifiers);
        for (q, s) in &p.ty.qualifiers {
            match q {
                Qualifier::Storage(Storage::Const) => is_const = true,
                Qualifier::Storage(Storage::In) => mode = ParamMode::In,
                Qualifier::Storage(Storage::Out) => mode = ParamMode::Out,
                Qualifier::Storage(Storage::Inout) => mode = ParamMode::InOut,
                Qualifier::Precision(_) => {}
                _ => {
                    let d = self.error(
                        Code::InvalidQualifier,
                        *s,
                        "this qualifier cannot apply to a parameter",
                    );
                    d.label = "not allowed on a parameter".into();
                }
            }
        }
        if is_const && mode != ParamMode::In {
            let span = p.ty.span;
            let d = self.error(
                Code::InvalidQualifier,
                span,
                "`const` parameters can only be `in`",
            );
            d.label = "`const` with `out` or `inout`".into();
        }
        let base = self.resolve_type(&p.ty.spec)?;
        let ty = match &p.array {
            Some(a) => self.array_of(base, a, p.span)?,
            None => base,
        };
        if ty == Type::Void {
            let d = self.error(
                Code::VoidParameter,
                p.ty.spec.span,
                "a parameter cannot be `void`",
            );
            d.label = "`void`".into();
            return None;
        }
        if let Type::Array(_, 0) = ty {
            let d = self.error(Code::UnsizedArray, p.span, "array parameters need a size");
            d.label = "unsized".into();
            return None;
        }
        if ty.contains_sampler(&self.structs) && mode != ParamMode::In {
            let d = self.error(
                Code::SamplerOutParameter,
                p.span,
                "samplers can only be `in` parameters",
            );
            d.label = "an `out` or `inout` sampler".into();
        }
        let precision = self.precision_for(&ty, p.ty.precision().map(|q| q.0), p.span);
        let name = match &p.name {
            Some(n) => {
                self.check_name(n);
                n.name.clone()
            }
            None => self.unnamed_param(),
        };
        let name_span = p.name.as_ref().map_or(p.span, |n| n.span);
        self.check_variable_size(&name, name_span, &ty, true);
        Some(hir::Param {
            name,
            ty,
            mode,
            is_const,
            precision,
            span: p.name.as_ref().map_or(p.span, |n| n.span),
        })
    }

    pub(in crate::check) fn function_def(&mut self, f: &ast::FunctionDef) {
        let Some(id) = self.function_decl(&f.proto, true) else {
            // Still check the body for errors, in a throwaway context.
            self.check_body_detached(f);
            return;
        };
        self.fn_defined[id] = true;
        self.ended.clear();
        let ret = self.functions[id].ret.clone();
        self.fctx = Some(FnCtx {
            func: id,
            locals: Vec::new(),
            loop_indices: Vec::new(),
            loops: 0,
            switches: 0,
            calls: Vec::new(),
            ret,
        });
        self.push_scope();
        let params: Vec<(usize, Option<ast::Ident>)> = f
            .proto
            .params
            .iter()
            .enumerate()
            .map(|(i, p)| (i, p.name.clone()))
            .collect();
        for (i, name) in params {
            if let Some(n) = name {
                self.declare(&n, Sym::Var(Var::Param(i)));
            }
        }
        let body = self.block_stmts_same_scope(&f.body.stmts);
        self.pop_scope();
        let ctx = self.fctx.take().expect("function context");
        if ctx.ret != Type::Void && !has_return(&f.body.stmts) {
            let name = f.proto.name.clone();
            let ret = ctx.ret.display(&self.structs).to_string();
            let d = self.error(
                Code::MissingReturn,
                name.span,
                format!("function `{}` never returns a value", name.name),
            );
            d.label = format!("declared to return `{ret}`");
            d.notes
                .push("WebGL rejects a non-void function without any `return` statement".into());
            d.help = Some("return a value at the end of the function".into());
        }
        let func = &mut self.functions[id];
        func.body = body;
        func.locals = ctx.locals;
        let mut calls = ctx.calls;
        calls.sort_unstable();
        calls.dedup();
        func.calls = calls;
    }

    /// Checks a function body whose signature failed, so its own errors are still reported:
    /// with the parameters and return type it declares (resolved again, quietly: their errors
    /// are already reported), so that their uses do not cascade.
    fn check_body_detached(&mut self, f: &ast::FunctionDef) {
        let before = self.diags.len();
        self.push_scope();
        let ret = self.resolve_type(&f.proto.ret.spec).unwrap_or(Type::Void);
        let params: Vec<(Option<ast::Ident>, hir::Param)> = f
            .proto
            .params
            .iter()
            .filter_map(|p| self.param(p).map(|hp| (p.name.clone(), hp)))
            .collect();
        self.diags.truncate(before);
        let id = self.functions.len();
        self.functions.push(hir::Function {
            name: Name::new_static("_essl_invalid"),
            signature: String::new(),
            params: params.iter().map(|(_, p)| p.clone()).collect(),
            ret: ret.clone(),
            ret_precision: None,
            locals: Vec::new(),
            body: Vec::new(),
            calls: Vec::new(),
            span: f.proto.name.span,
            used: false,
        });
        self.fn_defined.push(true);
        self.fn_prototyped.push(false);
        self.fctx = Some(FnCtx {
            func: id,
            locals: Vec::new(),
            loop_indices: Vec::new(),
            loops: 0,
            switches: 0,
            calls: Vec::new(),
            ret,
        });
        for (i, (name, _)) in params.iter().enumerate() {
            if let Some(n) = name {
                self.declare(n, Sym::Var(Var::Param(i)));
            }
        }
        let _ = self.block_stmts_same_scope(&f.body.stmts);
        self.pop_scope();
        self.fctx = None;
    }
}

/// Whether a statement list holds a `return` anywhere (nested blocks, branches and loops
/// included): ANGLE rejects a non-void function with none.
fn has_return(stmts: &[ast::Stmt]) -> bool {
    stmts.iter().any(stmt_has_return)
}

fn stmt_has_return(s: &ast::Stmt) -> bool {
    use ast::StmtKind as K;
    match &s.kind {
        K::Return(_) => true,
        K::Block(b) => has_return(&b.stmts),
        K::If(_, then, otherwise) => {
            stmt_has_return(then) || otherwise.as_deref().is_some_and(stmt_has_return)
        }
        K::While(_, body) | K::DoWhile(body, _) => stmt_has_return(body),
        K::For { body, .. } => stmt_has_return(body),
        K::Switch(_, body) => has_return(&body.stmts),
        _ => false,
    }
}
