//! Types: resolving a type specifier (declaring an inline struct), array sizes, struct
//! declarations with their members' rules, and the types of built-in variables.
//!
//! The checker's `impl` is spread over the files of the `check` module.

use super::{Checker, Sym};
use crate::ast;
use crate::builtins::BuiltinVar;
use crate::diagnostic_code::Code;
use crate::source::Span;
use crate::types::{Precision, StructDef, StructMember, Type};

impl Checker<'_> {
    /// Resolves a type specifier, declaring an inline struct. `None` after an error.
    pub(super) fn resolve_type(&mut self, spec: &ast::TypeSpec) -> Option<Type> {
        let base = match &spec.name {
            ast::TypeName::Void => Type::Void,
            ast::TypeName::Scalar(k) => Type::Scalar(*k),
            ast::TypeName::Vector(k, n) => Type::Vector(*k, *n),
            ast::TypeName::Matrix { cols, rows } => Type::Matrix {
                cols: *cols,
                rows: *rows,
            },
            ast::TypeName::Sampler(s) => Type::Sampler(*s),
            ast::TypeName::Struct(decl) => Type::Struct(self.declare_struct(decl)?),
            ast::TypeName::Named(id) => match self.lookup(&id.name) {
                Some(Sym::Struct(s)) => Type::Struct(*s),
                _ => {
                    let d = self.error(
                        Code::UnknownType,
                        id.span,
                        format!("`{}` is not a type", id.name),
                    );
                    d.label = "not a type".into();
                    return None;
                }
            },
        };
        match &spec.array {
            None => Some(base),
            Some(a) => self.array_of(base, a, spec.span),
        }
    }

    /// Applies an array size to a type; `[]` gives size 0, to be fixed by an initializer.
    pub(super) fn array_of(
        &mut self,
        base: Type,
        size: &ast::ArraySize,
        span: Span,
    ) -> Option<Type> {
        if base.is_array() {
            let d = self.error(
                Code::ArrayOfArrays,
                size.span,
                "arrays of arrays are not allowed in GLSL ES 3.00",
            );
            d.label = "a second array dimension".into();
            return None;
        }
        if base == Type::Void {
            let d = self.error(Code::VoidArray, span, "`void` cannot be an array element");
            d.label = "an array of `void`".into();
            return None;
        }
        let Some(e) = &size.size else {
            return Some(Type::Array(Box::new(base), 0));
        };
        let n = self.array_size(e)?;
        Some(Type::Array(Box::new(base), n))
    }

    /// Evaluates an array size: a constant integral expression greater than zero.
    pub(super) fn array_size(&mut self, e: &ast::Expr) -> Option<u32> {
        let checked = self.expr(e);
        if checked.ty == Type::Void {
            return None;
        }
        let Some(c) = checked.as_const() else {
            let d = self.error(
                Code::NonConstantArraySize,
                e.span,
                "array size must be a constant integral expression",
            );
            d.label = "not a constant expression".into();
            return None;
        };
        let value = match (&checked.ty, c.as_int()) {
            (
                Type::Scalar(crate::types::ScalarKind::Int | crate::types::ScalarKind::Uint),
                Some(v),
            ) => v,
            _ => {
                let ty = self.type_name(&checked.ty);
                let d = self.error(
                    Code::ArraySizeType,
                    e.span,
                    format!("array size must be an `int` or `uint`, not {ty}"),
                );
                d.label = "not an integer".into();
                return None;
            }
        };
        if value <= 0 {
            let d = self.error(
                Code::ArraySize,
                e.span,
                format!("array size must be greater than zero, not {value}"),
            );
            d.label = "not a positive size".into();
            return None;
        }
        Some(value as u32)
    }

    pub(super) fn declare_struct(
        &mut self,
        decl: &ast::StructDecl,
    ) -> Option<crate::types::StructId> {
        if let Some(name) = &decl.name {
            self.check_name(name);
        }
        let mut members: Vec<StructMember> = Vec::new();
        let mut ok = true;
        for m in &decl.members {
            let fty = &m.ty.0;
            for (q, s) in &fty.qualifiers {
                if !matches!(q, ast::Qualifier::Precision(_)) {
                    let d = self.error(
                        Code::StructMemberQualifier,
                        *s,
                        "struct members may only have a precision qualifier",
                    );
                    d.label = "not allowed on a struct member".into();
                }
            }
            if let ast::TypeName::Struct(inner) = &fty.spec.name {
                let d = self.error(
                    Code::EmbeddedStruct,
                    inner.span,
                    "structs cannot be defined inside a struct in GLSL ES 3.00",
                );
                d.label = "an embedded struct definition".into();
                d.help = Some("define it before the outer struct and use its name".into());
            }
            let Some(base) = self.resolve_type(&fty.spec) else {
                ok = false;
                continue;
            };
            for (name, arr) in &m.names {
                let ty = match arr {
                    Some(a) => match self.array_of(base.clone(), a, name.span) {
                        Some(t) => t,
                        None => {
                            ok = false;
                            continue;
                        }
                    },
                    None => base.clone(),
                };
                if let Type::Array(_, 0) = ty {
                    let d = self.error(
                        Code::UnsizedArray,
                        name.span,
                        "struct members must have a size",
                    );
                    d.label = "an unsized array".into();
                    ok = false;
                }
                if ty == Type::Void {
                    let d = self.error(
                        Code::VoidVariable,
                        name.span,
                        "a struct member cannot be `void`",
                    );
                    d.label = "`void` member".into();
                    ok = false;
                    continue;
                }
                self.check_name(name);
                if members.iter().any(|mm| *mm.name == *name.name) {
                    let d = self.error(
                        Code::Redefinition,
                        name.span,
                        format!("struct member `{}` is declared twice", name.name),
                    );
                    d.label = "a second member with this name".into();
                    continue;
                }
                self.check_struct_nesting(&ty, &name.name, name.span);
                let precision = self.precision_for(&ty, fty.precision().map(|p| p.0), name.span);
                members.push(StructMember {
                    name: name.name.to_string(),
                    ty,
                    precision,
                });
            }
        }
        if members.is_empty() && ok {
            let d = self.error(
                Code::EmptyStruct,
                decl.span,
                "a struct must have at least one member",
            );
            d.label = "no members".into();
        }
        let id = crate::types::StructId(self.structs.len() as u32);
        let depth = 1 + members
            .iter()
            .map(|m| self.struct_depth(&m.ty))
            .max()
            .unwrap_or(0);
        self.struct_depths.push(depth);
        self.structs.push(StructDef {
            name: decl.name.as_ref().map(|n| n.name.to_string()),
            members,
        });
        if let Some(name) = &decl.name {
            self.declare(name, Sym::Struct(id));
        }
        Some(id)
    }

    /// The struct type of `gl_DepthRange`.
    pub(super) fn depth_range_type(&mut self) -> Type {
        if let Some(id) = self.depth_range_struct {
            return Type::Struct(id);
        }
        let id = crate::types::StructId(self.structs.len() as u32);
        let member = |n: &str| StructMember {
            name: n.into(),
            ty: Type::FLOAT,
            precision: Some(Precision::High),
        };
        self.struct_depths.push(1);
        self.structs.push(StructDef {
            name: Some("gl_DepthRangeParameters".into()),
            members: vec![member("near"), member("far"), member("diff")],
        });
        self.depth_range_struct = Some(id);
        Type::Struct(id)
    }

    /// The type of a built-in variable.
    pub(super) fn builtin_var_type(&mut self, v: BuiltinVar) -> Type {
        match v {
            BuiltinVar::DepthRange => self.depth_range_type(),
            BuiltinVar::FragData => {
                let n = crate::builtins::constant_in("gl_MaxDrawBuffers", &self.lang).unwrap_or(1);
                Type::Array(
                    Box::new(Type::Vector(crate::types::ScalarKind::Float, 4)),
                    n as u32,
                )
            }
            _ => v.ty(),
        }
    }
}
