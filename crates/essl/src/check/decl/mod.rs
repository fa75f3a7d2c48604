//! Declarations: the dispatch of a declaration statement, qualifier order, precision and
//! `invariant` statements.
//!
//! The checker's `impl` is spread over the files of this module, one concern each: variables,
//! uniform blocks and functions.

mod blocks;
mod es100;
mod functions;
mod variables;

use super::{Checker, PrecKey, Sym, Var};
use crate::ast::{self, Interpolation, Qualifier, Storage};
use crate::builtins::BuiltinVar;
use crate::diagnostic::Fix;
use crate::diagnostic_code::Code;
use crate::hir::{self, GlobalKind};
use crate::source::Span;
use crate::types::{Precision, ScalarKind};
use crate::Stage;

/// Qualifier order rank required by GLSL ES 3.00: invariant, interpolation/layout, centroid,
/// storage, precision.
pub(super) fn rank(q: &Qualifier) -> u8 {
    match q {
        Qualifier::Invariant => 0,
        Qualifier::Interpolation(_) | Qualifier::Layout(_) => 1,
        Qualifier::Centroid => 2,
        Qualifier::Storage(_) => 3,
        Qualifier::Precision(_) => 4,
    }
}

pub(super) fn qualifier_text(q: &Qualifier) -> &'static str {
    match q {
        Qualifier::Invariant => "invariant",
        Qualifier::Interpolation(Interpolation::Flat) => "flat",
        Qualifier::Interpolation(Interpolation::Smooth) => "smooth",
        Qualifier::Interpolation(Interpolation::NoPerspective) => "noperspective",
        Qualifier::Layout(_) => "layout",
        Qualifier::Centroid => "centroid",
        Qualifier::Storage(s) => s.as_str(),
        Qualifier::Precision(p) => p.name(),
    }
}

/// What a variable declaration declares, from its storage qualifier and place.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum DeclKind {
    GlobalPrivate,
    Const,
    Uniform,
    Input,
    Output,
    Local,
}

impl Checker<'_> {
    /// Checks qualifier order and duplicates.
    pub(super) fn check_qualifier_list(&mut self, qualifiers: &[(Qualifier, Span)]) {
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
                    Code::DuplicateQualifier,
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
                    let d = self.error(Code::QualifierOrder, *s, msg);
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
                if self.lang.es100 {
                    let d = self.not_in_es100(name.span, "a uniform block");
                    d.token = name.name.to_string();
                    d.help = Some("declare the members as separate uniforms".into());
                } else if !global {
                    let d = self.error(
                        Code::BlockNotGlobal,
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
                                        Code::InvalidLayout,
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
                        Code::InvalidDeclaration,
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
                    Code::InvalidPrecisionStatement,
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
                Code::InvariantNotGlobal,
                span,
                "`invariant` declarations must be at global scope",
            );
            d.label = "inside a function".into();
            return;
        }
        for n in names {
            if let Some(bv) = BuiltinVar::lookup_in(&n.name, self.stage, &self.lang, n.span.start) {
                // GLSL ES 1.00 also lets a fragment shader make its built-in inputs and outputs
                // invariant, except `gl_FrontFacing`.
                let allowed = matches!(bv, BuiltinVar::Position | BuiltinVar::PointSize)
                    || (self.lang.es100
                        && matches!(
                            bv,
                            BuiltinVar::FragCoord
                                | BuiltinVar::PointCoord
                                | BuiltinVar::FragColor
                                | BuiltinVar::FragData
                        ));
                if allowed {
                    if !self.invariant_builtins.contains(&bv) {
                        self.invariant_builtins.push(bv);
                    }
                    continue;
                }
                let es100 = self.lang.es100;
                let d = self.error(
                    Code::InvalidInvariant,
                    n.span,
                    format!("`{}` cannot be declared invariant", n.name),
                );
                d.label = if es100 {
                    "not a varying or a built-in output"
                } else {
                    "not an output of the vertex shader"
                }
                .into();
                continue;
            }
            match self.lookup(&n.name).cloned() {
                Some(Sym::Var(Var::Global(g)))
                    if (self.globals[g].kind == GlobalKind::Output
                        && self.stage == Stage::Vertex)
                        || (self.lang.es100
                            && self.globals[g].kind == GlobalKind::Input
                            && self.stage == Stage::Fragment) =>
                {
                    self.globals[g].invariant = true;
                }
                Some(Sym::Var(_)) => {
                    let d = self.error(
                        Code::InvalidInvariant,
                        n.span,
                        format!("`{}` cannot be declared invariant", n.name),
                    );
                    d.label = "only vertex shader outputs can be invariant".into();
                }
                _ => {
                    let d = self.error(
                        Code::UndeclaredIdentifier,
                        n.span,
                        format!("`{}` is not declared", n.name),
                    );
                    d.label = "declare the output before making it invariant".into();
                }
            }
        }
    }
}
