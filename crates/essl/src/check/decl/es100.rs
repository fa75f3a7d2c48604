//! Declarations in GLSL ES 1.00: `attribute` and `varying` instead of `in` and `out`, with
//! their type rules; arrays without GLSL ES 3.00's first-class features (no `float[2]` type, no
//! initializer, no unsized or `const` array); and WebGL's global initializers, which may read
//! uniforms and other globals (with a warning) but not call functions.
//!
//! The checker's `impl` is spread over the files of the `check` module.

use super::DeclKind;
use crate::ast::{self, Storage};
use crate::check::Checker;
use crate::diagnostic_code::Code;
use crate::hir::{self, ExprKind, GlobalKind};
use crate::source::Span;
use crate::types::{ScalarKind, Type};
use crate::Stage;

impl Checker<'_> {
    /// The kind a GLSL ES 1.00 global storage qualifier declares; `None` after an error that
    /// leaves the variable undeclared.
    pub(super) fn es100_storage(&mut self, storage: Storage, span: Span) -> Option<DeclKind> {
        match storage {
            Storage::Attribute if self.stage == Stage::Vertex => Some(DeclKind::Input),
            Storage::Attribute => {
                let d = self.error(
                    Code::InvalidStorage,
                    span,
                    "`attribute` is only for vertex shader inputs",
                );
                d.label = "in a fragment shader".into();
                d.help = Some("a fragment shader receives values through `varying`".into());
                None
            }
            Storage::Varying if self.stage == Stage::Vertex => Some(DeclKind::Output),
            Storage::Varying => Some(DeclKind::Input),
            Storage::In | Storage::Out => {
                let stage = self.stage;
                let d = self.not_in_es100(span, &format!("an `{}` variable", storage.as_str()));
                d.token = storage.as_str().into();
                let replacement = match (storage, stage) {
                    (Storage::In, Stage::Vertex) => Some("attribute"),
                    (Storage::Out, Stage::Fragment) => None,
                    _ => Some("varying"),
                };
                match replacement {
                    Some(r) => {
                        d.help = Some(format!("GLSL ES 1.00 declares it `{r}`"));
                        d.fix = Some(crate::diagnostic::Fix::suggested(
                            format!("write `{r}`"),
                            span,
                            r,
                        ));
                    }
                    None => {
                        d.help = Some(
                            "a GLSL ES 1.00 fragment shader writes its color to `gl_FragColor` \
                             (or `gl_FragData[n]`), or add `#version 300 es` as the first line"
                                .into(),
                        );
                    }
                }
                // Declared all the same, so that its uses do not cascade.
                Some(if storage == Storage::In {
                    DeclKind::Input
                } else {
                    DeclKind::Output
                })
            }
            _ => Some(DeclKind::GlobalPrivate),
        }
    }

    /// GLSL ES 1.00's rules on a declaration's type: no `float[2]` array type; `attribute`s of
    /// float types only, not arrays or structs; `varying`s of float types (arrays included), not
    /// structs.
    pub(super) fn es100_declaration_type(
        &mut self,
        fty: &ast::FullType,
        kind: DeclKind,
        base: &Type,
    ) {
        if let Some(a) = &fty.spec.array {
            let d = self.not_in_es100(a.span, "an array type (`float[2]`)");
            d.token = "first-class array".into();
            d.help = Some("put the size after the name: `float a[2]`".into());
        }
        let role = match (kind, self.stage) {
            (DeclKind::Input, Stage::Vertex) => "attribute",
            (DeclKind::Input | DeclKind::Output, _) => "varying",
            _ => return,
        };
        let problem = if base.contains_sampler(&self.structs) {
            None // reported as `sampler-not-uniform`
        } else if base.contains_struct() {
            Some("a struct")
        } else if matches!(
            base.scalar_kind(),
            Some(ScalarKind::Bool | ScalarKind::Int | ScalarKind::Uint)
        ) {
            Some("a `bool` or an integer")
        } else {
            None
        };
        if let Some(p) = problem {
            let d = self.error(
                Code::InvalidInterfaceType,
                fty.spec.span,
                format!(
                    "{} `{role}` cannot be {p}",
                    if role == "attribute" { "an" } else { "a" }
                ),
            );
            d.label = format!("`{role}` of this type is not allowed");
            d.token = role.into();
            d.notes.push(format!(
                "GLSL ES 1.00 `{role}`s are `float`, `vec2`–`vec4` or `mat2`–`mat4`{}",
                if role == "varying" {
                    ", or arrays of them"
                } else {
                    ""
                }
            ));
        }
    }

    /// GLSL ES 1.00's rules on one declarator: no unsized array, no array initializer, no
    /// `const` array (it could not be initialized), no `attribute` array. Whether to go on.
    pub(super) fn es100_declarator(
        &mut self,
        kind: DeclKind,
        decl: &ast::Declarator,
        ty: &Type,
    ) -> bool {
        if let Some(a) = &decl.array {
            if a.size.is_none() {
                let d = self.not_in_es100(a.span, "an array without a size");
                d.token = "[]".into();
                d.help = Some("give the array its size: `a[4]`".into());
                return false;
            }
            if kind == DeclKind::Const || (kind == DeclKind::Input && self.stage == Stage::Vertex) {
                let what = if kind == DeclKind::Const {
                    "const"
                } else {
                    "attribute"
                };
                let d = self.error(
                    Code::NotInEs100,
                    decl.name.span,
                    format!("GLSL ES 1.00 cannot declare `{what}` arrays"),
                );
                d.label = format!("a `{what}` array");
                d.token = what.into();
                if kind == DeclKind::Const {
                    d.notes.push(
                        "GLSL ES 1.00 has no array constructors to initialize one with".into(),
                    );
                    d.help = Some("declare a `uniform` array, or write the values out".into());
                } else {
                    d.help = Some("declare one `attribute` per element".into());
                }
                return false;
            }
            if let Some(init) = &decl.init {
                let d = self.not_in_es100(init.span, "an array initializer");
                d.token = "=".into();
                d.help = Some("declare the array, then assign its elements".into());
                return false;
            }
        }
        if kind == DeclKind::Const
            && matches!(ty, Type::Struct(_))
            && ty.contains_array(&self.structs)
        {
            let d = self.error(
                Code::NotInEs100,
                decl.name.span,
                "a struct containing an array cannot be `const` in GLSL ES 1.00",
            );
            d.label = "cannot be initialized".into();
            d.notes.push(
                "GLSL ES 1.00 has no array constructors, so no constant such struct exists".into(),
            );
            return false;
        }
        true
    }

    /// A global's initializer that is not a constant expression, in GLSL ES 1.00 for WebGL:
    /// a warning when it reads only uniforms and other globals through operators, constructors
    /// and math built-ins (WebGL 1.0 "GLSL ES Global Variable Initialization"), an error when
    /// it calls a function, samples a texture, assigns, or reads an input or a built-in.
    pub(super) fn es100_global_initializer(&mut self, init: &hir::Expr) {
        let problem = self.global_init_problem(init);
        let d = match problem {
            None => {
                let d = self.warning(
                    Code::NonConstantInitializer,
                    init.span,
                    "a global variable's initializer should be a constant expression",
                );
                d.label = "reads uniforms or other globals".into();
                d.notes.push(
                    "WebGL allows uniforms and globals here in GLSL ES 1.00 for compatibility; \
                     GLSL ES 3.00 does not"
                        .into(),
                );
                d
            }
            Some(why) => {
                let d = self.error(
                    Code::NonConstantInitializer,
                    init.span,
                    "global variable initializers must be constant expressions",
                );
                d.label = why;
                d
            }
        };
        d.token = "=".into();
        d.help = Some("assign it at the start of `main` instead".into());
    }

    /// What makes an expression more than a WebGL global initializer expression, if anything.
    fn global_init_problem(&self, e: &hir::Expr) -> Option<String> {
        let sub = |es: &[&hir::Expr]| es.iter().find_map(|x| self.global_init_problem(x));
        match &e.kind {
            ExprKind::Global(g) => match self.globals[*g].kind {
                GlobalKind::Private | GlobalKind::Const | GlobalKind::Uniform => None,
                _ => Some(format!(
                    "reads the shader input `{}`",
                    self.globals[*g].name
                )),
            },
            ExprKind::BuiltinVar(v) => Some(format!("reads `{}`", v.name())),
            ExprKind::Call(..) => Some("calls a function".into()),
            ExprKind::Builtin(op, _) if op.is_texture() => Some("samples a texture".into()),
            ExprKind::Builtin(_, args) | ExprKind::Construct(args) => {
                sub(&args.iter().collect::<Vec<_>>())
            }
            ExprKind::Assign(..) | ExprKind::IncDec(..) => Some("assigns a variable".into()),
            ExprKind::Unary(_, a) | ExprKind::Member(a, _) | ExprKind::Swizzle(a, _) => sub(&[a]),
            ExprKind::Binary(_, a, b) | ExprKind::Comma(a, b) | ExprKind::Index(a, b) => {
                sub(&[a, b])
            }
            ExprKind::Select(c, a, b) => sub(&[c, a, b]),
            _ => None,
        }
    }
}
