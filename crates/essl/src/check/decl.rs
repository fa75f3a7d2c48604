//! Declarations: variables, qualifiers, precision statements, uniform blocks and functions.

use std::sync::Arc;

use super::{Checker, FnCtx, PrecKey, Sym, Var};
use crate::ast::{self, Interpolation, Qualifier, Storage};
use crate::builtins::BuiltinVar;
use crate::diagnostic::Fix;
use crate::hir::{self, GlobalKind, ParamMode};
use crate::source::Span;
use crate::types::{Precision, ScalarKind, Type};
use crate::Stage;

/// Qualifier order rank required by GLSL ES 3.00: invariant, interpolation/layout, centroid,
/// storage, precision.
fn rank(q: &Qualifier) -> u8 {
    match q {
        Qualifier::Invariant => 0,
        Qualifier::Interpolation(_) | Qualifier::Layout(_) => 1,
        Qualifier::Centroid => 2,
        Qualifier::Storage(_) => 3,
        Qualifier::Precision(_) => 4,
    }
}

fn qualifier_text(q: &Qualifier) -> &'static str {
    match q {
        Qualifier::Invariant => "invariant",
        Qualifier::Interpolation(Interpolation::Flat) => "flat",
        Qualifier::Interpolation(Interpolation::Smooth) => "smooth",
        Qualifier::Layout(_) => "layout",
        Qualifier::Centroid => "centroid",
        Qualifier::Storage(s) => s.as_str(),
        Qualifier::Precision(p) => p.name(),
    }
}

/// What a variable declaration declares, from its storage qualifier and place.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum DeclKind {
    GlobalPrivate,
    Const,
    Uniform,
    Input,
    Output,
    Local,
}

impl Checker<'_> {
    /// Checks qualifier order and duplicates.
    fn check_qualifier_list(&mut self, qualifiers: &[(Qualifier, Span)]) {
        let mut last: Option<(u8, &Qualifier)> = None;
        for (i, (q, s)) in qualifiers.iter().enumerate() {
            let dup = qualifiers[..i].iter().any(|(p, _)| {
                std::mem::discriminant(p) == std::mem::discriminant(q)
                    && !matches!(q, Qualifier::Layout(_))
                    && !matches!(
                        (p, q),
                        (
                            Qualifier::Storage(Storage::Const),
                            Qualifier::Storage(Storage::In)
                        )
                    )
            });
            if dup {
                let d = self.error(
                    "duplicate-qualifier",
                    *s,
                    format!("`{}` qualifier given twice", qualifier_text(q)),
                );
                d.label = "a second qualifier of this kind".into();
                d.fix = Some(Fix::suggested("remove it", *s, ""));
                continue;
            }
            let r = rank(q);
            if let Some((pr, pq)) = last {
                if r < pr {
                    let msg = format!(
                        "`{}` must come before `{}`",
                        qualifier_text(q),
                        qualifier_text(pq)
                    );
                    let d = self.error("qualifier-order", *s, msg);
                    d.label = "out of order".into();
                    d.notes.push(
                        "GLSL ES 3.00 orders qualifiers: invariant, interpolation (or layout), centroid, storage, precision".into(),
                    );
                }
            }
            last = Some((r, q));
        }
    }

    pub(super) fn declaration(&mut self, d: &ast::Declaration, global: bool) -> Vec<hir::Stmt> {
        match d {
            ast::Declaration::Precision {
                precision,
                ty,
                span,
            } => {
                self.precision_statement(*precision, ty, *span);
                Vec::new()
            }
            ast::Declaration::Invariant { names, span } => {
                self.invariant_statement(names, *span);
                Vec::new()
            }
            ast::Declaration::Block {
                qualifiers,
                name,
                members,
                instance,
                span,
            } => {
                if !global {
                    let d = self.error(
                        "block-not-global",
                        *span,
                        "uniform blocks can only be declared at global scope",
                    );
                    d.label = "inside a function".into();
                } else {
                    self.uniform_block(qualifiers, name, members, instance.as_ref(), *span);
                }
                Vec::new()
            }
            ast::Declaration::Qualifiers { qualifiers, span } => {
                self.check_qualifier_list(qualifiers);
                let ok = global
                    && qualifiers.iter().all(|(q, _)| {
                        matches!(
                            q,
                            Qualifier::Layout(_) | Qualifier::Storage(Storage::Uniform)
                        )
                    })
                    && qualifiers
                        .iter()
                        .any(|(q, _)| matches!(q, Qualifier::Layout(_)));
                if ok {
                    for (q, _) in qualifiers {
                        if let Qualifier::Layout(items) = q {
                            for item in items {
                                if !matches!(
                                    &*item.name.name,
                                    "std140" | "shared" | "packed" | "row_major" | "column_major"
                                ) {
                                    let d = self.error(
                                        "invalid-layout",
                                        item.name.span,
                                        format!("`{}` is not a layout for a default uniform block declaration", item.name.name),
                                    );
                                    d.label = "unexpected layout qualifier".into();
                                }
                            }
                        }
                    }
                } else {
                    let d = self.error(
                        "invalid-declaration",
                        *span,
                        "a declaration with qualifiers but no type",
                    );
                    d.label = "only `layout(...) uniform;` is allowed without a type".into();
                }
                Vec::new()
            }
            ast::Declaration::Variables {
                ty,
                declarators,
                span,
            } => self.variables(ty, declarators, *span, global),
        }
    }

    fn precision_statement(&mut self, precision: Precision, ty: &ast::TypeSpec, span: Span) {
        let key = match (&ty.name, &ty.array) {
            (ast::TypeName::Scalar(ScalarKind::Float), None) => Some(PrecKey::Float),
            (ast::TypeName::Scalar(ScalarKind::Int), None) => Some(PrecKey::Int),
            (ast::TypeName::Sampler(s), None) => Some(PrecKey::Sampler(*s)),
            _ => None,
        };
        match key {
            Some(k) => self
                .scopes
                .last_mut()
                .expect("scope")
                .precisions
                .push((k, precision)),
            None => {
                let d = self.error(
                    "invalid-precision-statement",
                    ty.span,
                    "a default precision can only be declared for `float`, `int` or a sampler type",
                );
                d.label = "not `float`, `int` or a sampler".into();
                let _ = span;
            }
        }
    }

    fn invariant_statement(&mut self, names: &[ast::Ident], span: Span) {
        if !self.at_global_scope() {
            let d = self.error(
                "invariant-not-global",
                span,
                "`invariant` declarations must be at global scope",
            );
            d.label = "inside a function".into();
            return;
        }
        for n in names {
            if let Some(bv) = BuiltinVar::lookup(&n.name, self.stage) {
                if bv == BuiltinVar::Position || bv == BuiltinVar::PointSize {
                    continue;
                }
                let d = self.error(
                    "invalid-invariant",
                    n.span,
                    format!("`{}` cannot be declared invariant", n.name),
                );
                d.label = "not an output of the vertex shader".into();
                continue;
            }
            match self.lookup(&n.name).cloned() {
                Some(Sym::Var(Var::Global(g)))
                    if self.globals[g].kind == GlobalKind::Output
                        && self.stage == Stage::Vertex =>
                {
                    self.globals[g].invariant = true;
                }
                Some(Sym::Var(_)) => {
                    let d = self.error(
                        "invalid-invariant",
                        n.span,
                        format!("`{}` cannot be declared invariant", n.name),
                    );
                    d.label = "only vertex shader outputs can be invariant".into();
                }
                _ => {
                    let d = self.error(
                        "undeclared-identifier",
                        n.span,
                        format!("`{}` is not declared", n.name),
                    );
                    d.label = "declare the output before making it invariant".into();
                }
            }
        }
    }

    /// Reads `layout(...)` items of a variable declaration: `location = N`.
    fn layout_location(&mut self, ty: &ast::FullType, kind: DeclKind) -> Option<u32> {
        let mut location = None;
        for item in ty.layout() {
            match &*item.name.name {
                "location" => {
                    let allowed = (kind == DeclKind::Input && self.stage == Stage::Vertex)
                        || (kind == DeclKind::Output && self.stage == Stage::Fragment);
                    if !allowed {
                        let d = self.error(
                            "invalid-layout",
                            item.name.span,
                            "`location` can only be given to vertex shader inputs and fragment shader outputs in GLSL ES 3.00",
                        );
                        d.label = "not allowed here".into();
                        continue;
                    }
                    let Some(v) = &item.value else {
                        let d = self.error(
                            "invalid-layout",
                            item.name.span,
                            "`location` needs a value: `location = N`",
                        );
                        d.label = "no value".into();
                        continue;
                    };
                    let value = match &v.kind {
                        ast::ExprKind::Int(n, _) => Some(*n as i64),
                        _ => None,
                    };
                    match value {
                        Some(n) if (0..=i32::MAX as i64).contains(&n) => location = Some(n as u32),
                        _ => {
                            let d = self.error(
                                "invalid-layout",
                                v.span,
                                "a location must be a non-negative integer literal",
                            );
                            d.label = "not an integer literal".into();
                        }
                    }
                }
                "std140" | "shared" | "packed" | "row_major" | "column_major" => {
                    let d = self.error(
                        "invalid-layout",
                        item.name.span,
                        format!("`{}` can only qualify a uniform block", item.name.name),
                    );
                    d.label = "not allowed on a variable".into();
                }
                other => {
                    let d = self.error(
                        "invalid-layout",
                        item.name.span,
                        format!("unknown layout qualifier `{other}`"),
                    );
                    d.label = "not a GLSL ES 3.00 layout qualifier".into();
                }
            }
        }
        location
    }

    fn variables(
        &mut self,
        ty: &ast::FullType,
        declarators: &[ast::Declarator],
        span: Span,
        global: bool,
    ) -> Vec<hir::Stmt> {
        self.check_qualifier_list(&ty.qualifiers);
        let storage = ty.storage();
        let kind = match (storage.map(|s| s.0), global) {
            (None, true) => DeclKind::GlobalPrivate,
            (None, false) => DeclKind::Local,
            (Some(Storage::Const), _) => DeclKind::Const,
            (Some(Storage::Uniform), true) => DeclKind::Uniform,
            (Some(Storage::In), true) => DeclKind::Input,
            (Some(Storage::Out), true) => DeclKind::Output,
            (Some(s), _) => {
                let (st, sspan) = storage.expect("storage");
                let d = self.error(
                    "invalid-storage",
                    sspan,
                    if global {
                        format!("`{}` is only for function parameters", s.as_str())
                    } else {
                        format!(
                            "`{}` variables can only be declared at global scope",
                            st.as_str()
                        )
                    },
                );
                d.label = "not allowed here".into();
                if global {
                    DeclKind::GlobalPrivate
                } else {
                    DeclKind::Local
                }
            }
        };
        let Some(base) = self.resolve_type(&ty.spec) else {
            return Vec::new();
        };
        if !declarators.is_empty() {
            self.check_declaration_qualifiers(ty, kind, &base);
        }
        let location = if matches!(kind, DeclKind::Input | DeclKind::Output) {
            self.layout_location(ty, kind)
        } else {
            if !ty.layout().is_empty() {
                self.layout_location(ty, kind);
            }
            None
        };
        if declarators.is_empty() {
            if let Type::Array(_, 0) = base {
                let d = self.error(
                    "unsized-array",
                    ty.spec.span,
                    "an unsized array type needs a variable and an initializer",
                );
                d.label = "declares nothing".into();
                return Vec::new();
            }
            if !matches!(ty.spec.name, ast::TypeName::Struct(_)) && ty.qualifiers.is_empty() {
                // `float;` declares nothing: harmless, as C compilers warn.
                let d = self.warning(
                    "empty-declaration",
                    span,
                    "this declaration declares nothing",
                );
                d.label = "no variable name".into();
            }
            return Vec::new();
        }
        let mut out = Vec::new();
        for decl in declarators {
            if let Some(s) = self.declarator(ty, &base, kind, location, decl) {
                out.push(s);
            }
        }
        out
    }

    fn check_declaration_qualifiers(&mut self, ty: &ast::FullType, kind: DeclKind, base: &Type) {
        let varying = (kind == DeclKind::Output && self.stage == Stage::Vertex)
            || (kind == DeclKind::Input && self.stage == Stage::Fragment);
        if let Some((_, s)) = ty.interpolation() {
            if !varying {
                let d = self.error(
                    "invalid-interpolation",
                    s,
                    "interpolation qualifiers only apply to vertex outputs and fragment inputs",
                );
                d.label = "not a varying".into();
            }
        }
        if let Some(s) = ty.centroid() {
            if !varying {
                let d = self.error(
                    "invalid-centroid",
                    s,
                    "`centroid` only applies to vertex outputs and fragment inputs",
                );
                d.label = "not a varying".into();
            }
        }
        if let Some(s) = ty.invariant() {
            if !(kind == DeclKind::Output && self.stage == Stage::Vertex) {
                let d = self.error(
                    "invalid-invariant",
                    s,
                    "only vertex shader outputs can be declared `invariant`",
                );
                d.label = "not allowed here".into();
            }
        }
        if *base == Type::Void {
            let d = self.error(
                "void-variable",
                ty.spec.span,
                "variables cannot have type `void`",
            );
            d.label = "`void`".into();
        }
        if base.contains_sampler(&self.structs) && !matches!(kind, DeclKind::Uniform) {
            let d = self.error(
                "sampler-not-uniform",
                ty.spec.span,
                "samplers can only be declared as uniforms or function parameters",
            );
            d.label = "a sampler here".into();
        }
    }

    fn declarator(
        &mut self,
        fty: &ast::FullType,
        base: &Type,
        kind: DeclKind,
        location: Option<u32>,
        decl: &ast::Declarator,
    ) -> Option<hir::Stmt> {
        self.check_name(&decl.name);
        let mut ty = match &decl.array {
            Some(a) => self.array_of(base.clone(), a, decl.name.span)?,
            None => base.clone(),
        };
        if *base == Type::Void {
            return None;
        }
        // Initializer.
        let init = decl.init.as_ref().map(|e| self.expr(e));
        if let Some(i) = &init {
            // Unsized array: take the initializer's size.
            if let (Type::Array(el, 0), Type::Array(iel, n)) = (&ty, &i.ty) {
                if el == iel {
                    ty = Type::Array(el.clone(), *n);
                }
            }
        }
        if let Type::Array(_, 0) = ty {
            let d = self.error(
                "unsized-array",
                decl.name.span,
                format!("array `{}` needs a size", decl.name.name),
            );
            d.label = "no size and no initializer to take it from".into();
            return None;
        }
        let private = match kind {
            DeclKind::Local | DeclKind::Const | DeclKind::GlobalPrivate => true,
            DeclKind::Input => self.stage == Stage::Fragment,
            DeclKind::Output => self.stage == Stage::Vertex,
            DeclKind::Uniform => false,
        };
        self.check_variable_size(&decl.name.name, decl.name.span, &ty, private);
        let precision = self.precision_for(&ty, fty.precision().map(|p| p.0), decl.name.span);
        self.check_interface_type(fty, &ty, kind, decl.name.span);
        if let Some(i) = &init {
            let eq_span = Span::new(decl.name.span.end, i.span.start);
            if matches!(kind, DeclKind::Uniform | DeclKind::Input | DeclKind::Output) {
                let what = match kind {
                    DeclKind::Uniform => "uniforms",
                    DeclKind::Input => "inputs",
                    _ => "outputs",
                };
                let d = self.error(
                    "invalid-initializer",
                    i.span,
                    format!("{what} cannot have an initializer"),
                );
                d.label = "initializer not allowed".into();
            } else if i.ty != Type::Void && i.ty != ty {
                self.type_mismatch_in_init(&ty, i, eq_span);
            } else if i.ty != Type::Void {
                let constant = i.as_const().is_some();
                if kind == DeclKind::Const && !constant {
                    let d = self.error(
                        "non-constant-initializer",
                        i.span,
                        format!(
                            "`const` variable `{}` needs a constant initializer",
                            decl.name.name
                        ),
                    );
                    d.label = "not a constant expression".into();
                    d.help = Some(
                        "remove `const`, or initialize it from literals and other constants".into(),
                    );
                } else if kind == DeclKind::GlobalPrivate && !constant {
                    let d = self.error(
                        "non-constant-initializer",
                        i.span,
                        "global variable initializers must be constant expressions",
                    );
                    d.label = "not a constant expression".into();
                    d.help = Some("assign it at the start of `main` instead".into());
                }
            }
        } else if kind == DeclKind::Const {
            let d = self.error(
                "missing-initializer",
                decl.name.span,
                format!("`const` variable `{}` needs an initializer", decl.name.name),
            );
            d.label = "no initializer".into();
        }
        let init_ok = init.as_ref().filter(|i| i.ty == ty);
        match kind {
            DeclKind::Local => {
                let local = hir::Local {
                    name: decl.name.name.clone(),
                    ty: ty.clone(),
                    constant: None,
                    precision,
                    span: decl.name.span,
                };
                let id = self.new_local(local);
                self.declare(&decl.name, Sym::Var(Var::Local(id)));
                Some(hir::Stmt {
                    kind: hir::StmtKind::Local(id, init_ok.cloned()),
                    span: decl.span,
                })
            }
            DeclKind::Const if self.fctx.is_some() => {
                let constant = init_ok.and_then(|i| i.as_const().cloned());
                let local = hir::Local {
                    name: decl.name.name.clone(),
                    ty: ty.clone(),
                    constant: constant.clone(),
                    precision,
                    span: decl.name.span,
                };
                let id = self.new_local(local);
                self.declare(&decl.name, Sym::Var(Var::Local(id)));
                None
            }
            _ => {
                let gkind = match kind {
                    DeclKind::Const => GlobalKind::Const,
                    DeclKind::Uniform => GlobalKind::Uniform,
                    DeclKind::Input => GlobalKind::Input,
                    DeclKind::Output => GlobalKind::Output,
                    _ => GlobalKind::Private,
                };
                let init = init_ok.map(|i| match i.as_const() {
                    Some(c) => hir::Init::Const(c.clone()),
                    None => hir::Init::Expr(i.clone()),
                });
                let invariant = fty.invariant().is_some()
                    || (self.invariant_all
                        && gkind == GlobalKind::Output
                        && self.stage == Stage::Vertex);
                let g = hir::Global {
                    name: decl.name.name.clone(),
                    ty,
                    kind: gkind,
                    precision,
                    interpolation: fty.interpolation().map(|i| i.0),
                    centroid: fty.centroid().is_some(),
                    invariant,
                    location,
                    init,
                    span: decl.name.span,
                    used: false,
                };
                let id = self.globals.len();
                self.globals.push(g);
                if gkind == GlobalKind::Output && self.stage == Stage::Fragment {
                    self.frag_outputs.push(id);
                }
                self.declare(&decl.name, Sym::Var(Var::Global(id)));
                None
            }
        }
    }

    fn type_mismatch_in_init(&mut self, ty: &Type, init: &hir::Expr, eq_span: Span) {
        let want = self.type_name(ty);
        let got = self.type_name(&init.ty);
        let span = init.span;
        let fix = super::expr::conversion_fix(self.file, init, ty);
        let d = self.error(
            "type-mismatch",
            span,
            format!("cannot initialize a {want} with a {got}"),
        );
        d.label = format!("this is {got}");
        d.token = "=".into();
        if init.ty.scalar_kind().is_some()
            && ty.scalar_kind().is_some()
            && init.ty.scalar_kind() != ty.scalar_kind()
        {
            d.notes
                .push("GLSL ES 3.00 has no implicit conversions".into());
        }
        if let Some(fix) = fix {
            d.help = Some(fix.message.clone());
            d.fix = Some(fix);
        }
        let _ = eq_span;
    }

    /// Rules for shader inputs and outputs.
    fn check_interface_type(&mut self, fty: &ast::FullType, ty: &Type, kind: DeclKind, span: Span) {
        let structs = &self.structs;
        let (vertex_in, varying_out, varying_in, frag_out) = (
            kind == DeclKind::Input && self.stage == Stage::Vertex,
            kind == DeclKind::Output && self.stage == Stage::Vertex,
            kind == DeclKind::Input && self.stage == Stage::Fragment,
            kind == DeclKind::Output && self.stage == Stage::Fragment,
        );
        if !(vertex_in || varying_out || varying_in || frag_out) {
            return;
        }
        let qualifier = if kind == DeclKind::Input { "in" } else { "out" };
        let has_bool = ty.contains_kind(ScalarKind::Bool, structs);
        let is_int = ty.contains_kind(ScalarKind::Int, structs)
            || ty.contains_kind(ScalarKind::Uint, structs);
        let mut problem: Option<String> = None;
        if ty.contains_sampler(structs) {
            problem = Some("a sampler".into());
        } else if has_bool {
            problem = Some("a `bool`".into());
        } else if vertex_in && (ty.is_array() || ty.contains_struct()) {
            problem = Some(
                if ty.is_array() {
                    "an array"
                } else {
                    "a struct"
                }
                .into(),
            );
        } else if frag_out
            && (matches!(ty, Type::Matrix { .. })
                || ty.contains_struct()
                || matches!(ty, Type::Array(t, _) if matches!(**t, Type::Matrix { .. })))
        {
            problem = Some(
                if ty.contains_struct() {
                    "a struct"
                } else {
                    "a matrix"
                }
                .into(),
            );
        } else if varying_out || varying_in {
            if let Type::Array(el, _) = ty {
                if el.contains_struct() {
                    problem = Some("an array of structs".into());
                }
            } else if let Type::Struct(id) = ty {
                let s = &structs[id.0 as usize];
                if s.members.iter().any(|m| m.ty.is_array()) {
                    problem = Some("a struct containing an array".into());
                } else if s.members.iter().any(|m| m.ty.contains_struct()) {
                    problem = Some("a struct containing a struct".into());
                }
            }
        }
        if let Some(p) = problem {
            let role = if vertex_in {
                "vertex shader input"
            } else if varying_out {
                "vertex shader output"
            } else if varying_in {
                "fragment shader input"
            } else {
                "fragment shader output"
            };
            let d = self.error(
                "invalid-interface-type",
                span,
                format!("a {role} cannot be {p}"),
            );
            d.label = format!("`{qualifier}` of this type is not allowed");
            d.token = qualifier.into();
            return;
        }
        if (varying_out || varying_in)
            && is_int
            && fty.interpolation().map(|i| i.0) != Some(Interpolation::Flat)
        {
            let role = if varying_out {
                "vertex shader output"
            } else {
                "fragment shader input"
            };
            let d = self.error(
                "integer-varying-not-flat",
                span,
                format!("an integer {role} must be `flat`"),
            );
            d.label = "integers cannot be interpolated".into();
            d.token = qualifier.into();
            let at = fty.span.start;
            d.fix = Some(Fix::certain("add `flat`", Span::empty(at), "flat "));
        }
    }

    fn uniform_block(
        &mut self,
        qualifiers: &[(Qualifier, Span)],
        name: &ast::Ident,
        members: &[ast::MemberDecl],
        instance: Option<&(ast::Ident, Option<ast::ArraySize>)>,
        span: Span,
    ) {
        self.check_qualifier_list(qualifiers);
        // WebGL2 has only std140: a block without a layout qualifier is std140.
        let mut layout = hir::BlockLayout::Std140;
        let mut block_row_major = false;
        for (q, s) in qualifiers {
            match q {
                Qualifier::Storage(Storage::Uniform) => {}
                Qualifier::Layout(items) => {
                    for item in items {
                        match &*item.name.name {
                            "std140" => layout = hir::BlockLayout::Std140,
                            "shared" | "packed" => {
                                let which = item.name.name.clone();
                                let d = self.error(
                                    "webgl-block-layout",
                                    item.name.span,
                                    format!("`{which}` uniform blocks are not allowed in WebGL2"),
                                );
                                d.label = "only `std140` is portable".into();
                                d.notes.push("WebGL2 forbids `shared` and `packed` layouts so that block layouts are the same everywhere".into());
                                d.fix =
                                    Some(Fix::certain("use `std140`", item.name.span, "std140"));
                                layout = if &*which == "shared" {
                                    hir::BlockLayout::Shared
                                } else {
                                    hir::BlockLayout::Packed
                                };
                            }
                            "row_major" => block_row_major = true,
                            "column_major" => block_row_major = false,
                            other => {
                                let d = self.error(
                                    "invalid-layout",
                                    item.name.span,
                                    format!("`{other}` is not a uniform block layout"),
                                );
                                d.label =
                                    "expected std140, shared, packed, row_major or column_major"
                                        .into();
                            }
                        }
                    }
                }
                Qualifier::Storage(st) => {
                    let d = self.error(
                        "invalid-block",
                        *s,
                        format!(
                            "`{}` blocks are not allowed in GLSL ES 3.00: only uniform blocks",
                            st.as_str()
                        ),
                    );
                    d.label = "not `uniform`".into();
                }
                _ => {
                    let d = self.error(
                        "invalid-block",
                        *s,
                        "this qualifier cannot apply to a uniform block",
                    );
                    d.label = "not allowed here".into();
                }
            }
        }
        self.check_name(name);
        let mut hmembers = Vec::new();
        for m in members {
            let fty = &m.ty.0;
            let mut row_major = block_row_major;
            for (q, s) in &fty.qualifiers {
                match q {
                    Qualifier::Precision(_) => {}
                    Qualifier::Storage(Storage::Uniform) => {}
                    Qualifier::Layout(items) => {
                        for item in items {
                            match &*item.name.name {
                                "row_major" => row_major = true,
                                "column_major" => row_major = false,
                                other => {
                                    let d = self.error(
                                        "invalid-layout",
                                        item.name.span,
                                        format!("`{other}` cannot qualify a block member"),
                                    );
                                    d.label = "only row_major or column_major here".into();
                                }
                            }
                        }
                    }
                    _ => {
                        let d = self.error(
                            "invalid-block",
                            *s,
                            "block members may only have a precision or a matrix layout",
                        );
                        d.label = "not allowed here".into();
                    }
                }
            }
            if let ast::TypeName::Struct(inner) = &fty.spec.name {
                let d = self.error(
                    "embedded-struct",
                    inner.span,
                    "structs cannot be defined inside a uniform block",
                );
                d.label = "define it before the block".into();
            }
            let Some(base) = self.resolve_type(&fty.spec) else {
                continue;
            };
            for (n, arr) in &m.names {
                let ty = match arr {
                    Some(a) => match self.array_of(base.clone(), a, n.span) {
                        Some(t) => t,
                        None => continue,
                    },
                    None => base.clone(),
                };
                if ty.contains_sampler(&self.structs) {
                    let d = self.error(
                        "sampler-in-block",
                        n.span,
                        "a uniform block cannot contain a sampler",
                    );
                    d.label = "a sampler".into();
                    continue;
                }
                if matches!(ty, Type::Array(_, 0)) {
                    let d = self.error("unsized-array", n.span, "block members must have a size");
                    d.label = "unsized".into();
                    continue;
                }
                let precision = self.precision_for(&ty, fty.precision().map(|p| p.0), n.span);
                if hmembers
                    .iter()
                    .any(|(mn, ..): &(Arc<str>, Type, Option<Precision>, bool)| **mn == *n.name)
                {
                    let d = self.error(
                        "redefinition",
                        n.span,
                        format!("block member `{}` is declared twice", n.name),
                    );
                    d.label = "a second member with this name".into();
                    continue;
                }
                hmembers.push((n.name.clone(), ty, precision, row_major));
            }
        }
        if self.blocks.iter().any(|b| *b.name == *name.name) {
            let d = self.error(
                "redefinition",
                name.span,
                format!("uniform block `{}` is declared twice", name.name),
            );
            d.label = "a second block with this name".into();
            return;
        }
        let array = match instance.and_then(|(_, a)| a.as_ref()) {
            Some(a) => match &a.size {
                Some(e) => self.array_size(e),
                None => {
                    let d = self.error(
                        "unsized-array",
                        a.span,
                        "a uniform block array needs a size",
                    );
                    d.label = "unsized".into();
                    None
                }
            },
            None => None,
        };
        let idx = self.blocks.len();
        self.blocks.push(hir::UniformBlock {
            name: name.name.clone(),
            instance: instance.map(|(i, _)| i.name.clone()),
            array,
            members: hmembers.clone(),
            layout,
            span,
            used: false,
        });
        match instance {
            Some((inst, _)) => {
                self.check_name(inst);
                if *inst.name == *name.name {
                    let d = self.error(
                        "redefinition",
                        inst.span,
                        "a block's instance name cannot be the block's name",
                    );
                    d.label = "same name as the block".into();
                }
                self.declare(inst, Sym::Block(idx));
            }
            None => {
                for (mi, (mname, ty, precision, _)) in hmembers.iter().enumerate() {
                    let g = hir::Global {
                        name: mname.clone(),
                        ty: ty.clone(),
                        kind: GlobalKind::BlockMember(idx, mi),
                        precision: *precision,
                        interpolation: None,
                        centroid: false,
                        invariant: false,
                        location: None,
                        init: None,
                        span,
                        used: false,
                    };
                    let id = self.globals.len();
                    self.globals.push(g);
                    self.declare(
                        &ast::Ident {
                            name: mname.clone(),
                            span,
                        },
                        Sym::Var(Var::Global(id)),
                    );
                }
            }
        }
    }

    // ----- functions -----

    /// Declares a function (prototype or the signature of a definition). Returns its id.
    pub(super) fn function_decl(
        &mut self,
        proto: &ast::FunctionProto,
        defining: bool,
    ) -> Option<usize> {
        let name = &proto.name;
        if crate::builtins::is_builtin_function(&name.name) {
            let d = self.error(
                "builtin-redeclared",
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
        // Return type.
        for (q, s) in &proto.ret.qualifiers {
            if !matches!(q, Qualifier::Precision(_)) {
                let d = self.error(
                    "invalid-qualifier",
                    *s,
                    "a return type can only have a precision qualifier",
                );
                d.label = "not allowed on a return type".into();
            }
        }
        let ret = self.resolve_type(&proto.ret.spec)?;
        if let Type::Array(_, 0) = ret {
            let d = self.error(
                "unsized-array",
                proto.ret.spec.span,
                "a returned array needs a size",
            );
            d.label = "unsized".into();
        }
        if ret.contains_sampler(&self.structs) {
            let d = self.error(
                "sampler-return",
                proto.ret.spec.span,
                "functions cannot return a sampler",
            );
            d.label = "a sampler".into();
        }
        let ret_precision = if ret == Type::Void {
            None
        } else {
            self.precision_for(
                &ret,
                proto.ret.precision().map(|p| p.0),
                proto.ret.spec.span,
            )
        };
        let mut params = Vec::new();
        for p in &proto.params {
            if let Some(hp) = self.param(p) {
                params.push(hp);
            }
        }
        if params.len() != proto.params.len() {
            return None;
        }
        let signature = format!(
            "{}({})",
            name.name,
            params
                .iter()
                .map(|p| p.ty.display(&self.structs).to_string())
                .collect::<Vec<_>>()
                .join(",")
        );
        if &*name.name == "main" {
            if !params.is_empty() {
                let d = self.error("invalid-main", name.span, "`main` cannot take parameters");
                d.label = "`void main()` expected".into();
            }
            if ret != Type::Void {
                let d = self.error(
                    "invalid-main",
                    proto.ret.spec.span,
                    "`main` must return `void`",
                );
                d.label = "`void main()` expected".into();
            }
        }
        // Find an earlier declaration with the same parameter types.
        let existing = match self.lookup(&name.name).cloned() {
            Some(Sym::Funcs(ids)) => ids
                .iter()
                .copied()
                .find(|&f| self.functions[f].signature == signature),
            Some(_) if self.scopes[0].names.contains_key(&name.name) => {
                let d = self.error(
                    "redefinition",
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
                    let d = self.error("invalid-main", name.span, "`main` cannot be overloaded");
                    d.label = "a second `main`".into();
                    return None;
                }
            }
        }
        if let Some(f) = existing {
            if self.functions[f].ret != ret {
                let prev = self.functions[f].span;
                let d = self.error(
                    "function-redeclared",
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
                    "function-redeclared",
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
                        "function-redefined",
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
            return Some(f);
        }
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
        Some(id)
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
                        "invalid-qualifier",
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
                "invalid-qualifier",
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
                "void-parameter",
                p.ty.spec.span,
                "a parameter cannot be `void`",
            );
            d.label = "`void`".into();
            return None;
        }
        if let Type::Array(_, 0) = ty {
            let d = self.error("unsized-array", p.span, "array parameters need a size");
            d.label = "unsized".into();
            return None;
        }
        if ty.contains_sampler(&self.structs) && mode != ParamMode::In {
            let d = self.error(
                "sampler-out-parameter",
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

    pub(super) fn function_def(&mut self, f: &ast::FunctionDef) {
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
                "missing-return",
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

    /// Checks a function body whose signature failed, so its own errors are still reported.
    fn check_body_detached(&mut self, f: &ast::FunctionDef) {
        let id = self.functions.len();
        self.functions.push(hir::Function {
            name: Arc::from("_essl_invalid"),
            signature: String::new(),
            params: Vec::new(),
            ret: Type::Void,
            ret_precision: None,
            locals: Vec::new(),
            body: Vec::new(),
            calls: Vec::new(),
            span: f.proto.name.span,
            used: false,
        });
        self.fn_defined.push(true);
        self.fctx = Some(FnCtx {
            func: id,
            locals: Vec::new(),
            loops: 0,
            switches: 0,
            calls: Vec::new(),
            ret: Type::Void,
        });
        self.push_scope();
        // Parameters are unknown: declare nothing; uses of them report undeclared names, which
        // is acceptable after a signature error.
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
