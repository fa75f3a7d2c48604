//! Variable declarations: layout locations, declaration qualifiers, declarators with their
//! initialisers, and the rules on shader interface (`in`/`out`/`uniform`) types.

use super::DeclKind;
use crate::ast::{self, Interpolation, Storage};
use crate::check::{Checker, Sym, Var};
use crate::diagnostic::Fix;
use crate::diagnostic_code::Code;
use crate::hir::{self, GlobalKind};
use crate::source::Span;
use crate::types::{Precision, ScalarKind, Type};
use crate::Stage;

impl Checker<'_> {
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
                            Code::InvalidLayout,
                            item.name.span,
                            "`location` can only be given to vertex shader inputs and fragment shader outputs in GLSL ES 3.00",
                        );
                        d.label = "not allowed here".into();
                        continue;
                    }
                    let Some(v) = &item.value else {
                        let d = self.error(
                            Code::InvalidLayout,
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
                                Code::InvalidLayout,
                                v.span,
                                "a location must be a non-negative integer literal",
                            );
                            d.label = "not an integer literal".into();
                        }
                    }
                }
                "std140" | "shared" | "packed" | "row_major" | "column_major" => {
                    let d = self.error(
                        Code::InvalidLayout,
                        item.name.span,
                        format!("`{}` can only qualify a uniform block", item.name.name),
                    );
                    d.label = "not allowed on a variable".into();
                }
                other => {
                    let d = self.error(
                        Code::InvalidLayout,
                        item.name.span,
                        format!("unknown layout qualifier `{other}`"),
                    );
                    d.label = "not a GLSL ES 3.00 layout qualifier".into();
                }
            }
        }
        location
    }

    pub(super) fn variables(
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
            (
                Some(s @ (Storage::In | Storage::Out | Storage::Attribute | Storage::Varying)),
                true,
            ) if self.lang.es100 => match self.es100_storage(s, storage.expect("storage").1) {
                Some(k) => k,
                None => return Vec::new(),
            },
            (Some(Storage::In), true) => DeclKind::Input,
            (Some(Storage::Out), true) => DeclKind::Output,
            (Some(s), _) => {
                let (st, sspan) = storage.expect("storage");
                let d = self.error(
                    Code::InvalidStorage,
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
        if self.conservative_depth(ty, kind, &base, declarators, span) {
            return Vec::new();
        }
        if !declarators.is_empty() {
            self.check_declaration_qualifiers(ty, kind, &base);
        }
        if self.lang.es100 {
            self.es100_declaration_type(ty, kind, &base);
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
                    Code::UnsizedArray,
                    ty.spec.span,
                    "an unsized array type needs a variable and an initializer",
                );
                d.label = "declares nothing".into();
                return Vec::new();
            }
            if !matches!(ty.spec.name, ast::TypeName::Struct(_)) && ty.qualifiers.is_empty() {
                // `float;` declares nothing: harmless, as C compilers warn.
                let d = self.warning(
                    Code::EmptyDeclaration,
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

    /// `layout(depth_any | depth_greater | depth_less) out float gl_FragDepth;` in a fragment
    /// shader that enabled `GL_EXT_conservative_depth`: a redeclaration that only promises how
    /// the shader moves depth, which essl checks and then has no use for (true: handled).
    /// Without the extension the declaration is checked as any other, and fails.
    fn conservative_depth(
        &mut self,
        ty: &ast::FullType,
        kind: DeclKind,
        base: &Type,
        declarators: &[ast::Declarator],
        span: Span,
    ) -> bool {
        use crate::target::Extension;
        let [d] = declarators else { return false };
        if self.stage != Stage::Fragment
            || kind != DeclKind::Output
            || &*d.name.name != "gl_FragDepth"
            || !self
                .lang
                .has_at(Extension::ExtConservativeDepth, span.start)
        {
            return false;
        }
        let layout = ty.layout();
        let ok = matches!(
            layout.as_slice(),
            [item] if matches!(&*item.name.name, "depth_any" | "depth_greater" | "depth_less")
        );
        if !ok {
            let at = layout.first().map_or(ty.spec.span, |i| i.name.span);
            let d = self.error(
                Code::InvalidLayout,
                at,
                "`gl_FragDepth` takes one of `depth_any`, `depth_greater` or `depth_less`",
            );
            d.label = "not a depth layout WebGL's EXT_conservative_depth offers".into();
        } else if *base != Type::FLOAT || d.array.is_some() || d.init.is_some() {
            let d = self.error(
                Code::InvalidLayout,
                d.span,
                "`gl_FragDepth` is redeclared as `out float gl_FragDepth;`",
            );
            d.label = "another type, an array or an initializer".into();
        }
        true
    }

    fn check_declaration_qualifiers(&mut self, ty: &ast::FullType, kind: DeclKind, base: &Type) {
        let varying = (kind == DeclKind::Output && self.stage == Stage::Vertex)
            || (kind == DeclKind::Input && self.stage == Stage::Fragment);
        if let Some((_, s)) = ty.interpolation() {
            if !varying {
                let d = self.error(
                    Code::InvalidInterpolation,
                    s,
                    "interpolation qualifiers only apply to vertex outputs and fragment inputs",
                );
                d.label = "not a varying".into();
            }
        }
        if let Some(s) = ty.centroid() {
            if !varying {
                let d = self.error(
                    Code::InvalidCentroid,
                    s,
                    "`centroid` only applies to vertex outputs and fragment inputs",
                );
                d.label = "not a varying".into();
            }
        }
        if let Some(s) = ty.invariant() {
            // GLSL ES 1.00 also lets a fragment shader declare its varyings invariant.
            let allowed = (kind == DeclKind::Output && self.stage == Stage::Vertex)
                || (self.lang.es100 && varying);
            if !allowed {
                let d = self.error(
                    Code::InvalidInvariant,
                    s,
                    "only vertex shader outputs can be declared `invariant`",
                );
                d.label = "not allowed here".into();
            }
        }
        if *base == Type::Void {
            let d = self.error(
                Code::VoidVariable,
                ty.spec.span,
                "variables cannot have type `void`",
            );
            d.label = "`void`".into();
        }
        if base.contains_sampler(&self.structs) && !matches!(kind, DeclKind::Uniform) {
            let d = self.error(
                Code::SamplerNotUniform,
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
        if self.lang.es100 && !self.es100_declarator(kind, decl, base) {
            return None;
        }
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
                Code::UnsizedArray,
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
        if !self.lang.es100 {
            self.check_interface_type(fty, &ty, kind, decl.name.span);
        }
        self.check_initializer(kind, decl, &ty, init.as_ref());
        let init_ok = init.filter(|i| i.ty == ty);
        match kind {
            DeclKind::Local => {
                let id = self.declare_local(decl, &ty, precision, None);
                Some(hir::Stmt {
                    kind: hir::StmtKind::Local(id, init_ok),
                    span: decl.span,
                })
            }
            DeclKind::Const if self.fctx.is_some() => {
                let constant = init_ok.and_then(|i| i.as_const().cloned());
                self.declare_local(decl, &ty, precision, constant);
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
                    None => hir::Init::Expr(i),
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

    /// A declarator's initialiser: none on shader interface variables, of the variable's type,
    /// constant for `const` and global variables; `const` needs one.
    fn check_initializer(
        &mut self,
        kind: DeclKind,
        decl: &ast::Declarator,
        ty: &Type,
        init: Option<&hir::Expr>,
    ) {
        if let Some(i) = init {
            let eq_span = Span::new(decl.name.span.end, i.span.start);
            if matches!(kind, DeclKind::Uniform | DeclKind::Input | DeclKind::Output) {
                let what = match kind {
                    DeclKind::Uniform => "uniforms",
                    DeclKind::Input => "inputs",
                    _ => "outputs",
                };
                let d = self.error(
                    Code::InvalidInitializer,
                    i.span,
                    format!("{what} cannot have an initializer"),
                );
                d.label = "initializer not allowed".into();
            } else if i.ty != Type::Void && i.ty != *ty {
                self.type_mismatch_in_init(ty, i, eq_span);
            } else if i.ty != Type::Void {
                let constant = i.as_const().is_some();
                if kind == DeclKind::Const && !constant {
                    let d = self.error(
                        Code::NonConstantInitializer,
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
                } else if kind == DeclKind::GlobalPrivate && !constant && self.lang.es100 {
                    self.es100_global_initializer(i);
                } else if kind == DeclKind::GlobalPrivate && !constant {
                    let d = self.error(
                        Code::NonConstantInitializer,
                        i.span,
                        "global variable initializers must be constant expressions",
                    );
                    d.label = "not a constant expression".into();
                    d.help = Some("assign it at the start of `main` instead".into());
                }
            }
        } else if kind == DeclKind::Const {
            let d = self.error(
                Code::MissingInitializer,
                decl.name.span,
                format!("`const` variable `{}` needs an initializer", decl.name.name),
            );
            d.label = "no initializer".into();
        }
    }

    /// Declares a local variable (a `const` one with its folded value) in the current scope.
    fn declare_local(
        &mut self,
        decl: &ast::Declarator,
        ty: &Type,
        precision: Option<Precision>,
        constant: Option<hir::ConstValue>,
    ) -> hir::LocalId {
        let local = hir::Local {
            name: decl.name.name.clone(),
            ty: ty.clone(),
            constant,
            precision,
            span: decl.name.span,
        };
        let id = self.new_local(local);
        self.declare(&decl.name, Sym::Var(Var::Local(id)));
        id
    }

    fn type_mismatch_in_init(&mut self, ty: &Type, init: &hir::Expr, eq_span: Span) {
        let want = self.type_name(ty);
        let got = self.type_name(&init.ty);
        let span = init.span;
        let fix = crate::check::expr::conversion_fix(self.file, init, ty);
        let d = self.error(
            Code::TypeMismatch,
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
                Code::InvalidInterfaceType,
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
                Code::IntegerVaryingNotFlat,
                span,
                format!("an integer {role} must be `flat`"),
            );
            d.label = "integers cannot be interpolated".into();
            d.token = qualifier.into();
            let at = fty.span.start;
            d.fix = Some(Fix::certain("add `flat`", Span::empty(at), "flat "));
        }
    }
}
