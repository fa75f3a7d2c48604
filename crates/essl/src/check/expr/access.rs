//! Access to parts of a value: indexing, struct fields, swizzles and uniform block members.

use super::{constant, error_expr, is_error};
use crate::ast;
use crate::check::fold;
use crate::check::{Checker, Sym};
use crate::diagnostic_code::Code;
use crate::hir::{ConstValue, Expr, ExprKind};
use crate::source::Span;
use crate::types::{ScalarKind, Type};

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

impl Checker<'_> {
    pub(super) fn index(&mut self, base: &ast::Expr, index: &ast::Expr, span: Span) -> Expr {
        // A uniform block instance array: `blocks[i]` is only valid before `.member`.
        if let ast::ExprKind::Ident(id) = &base.kind {
            if let Some(Sym::Block(_)) = self.lookup(&id.name) {
                let d = self.error(
                    Code::NotAValue,
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
            let d = self.error(Code::NotIndexable, b.span, format!("{t} cannot be indexed"));
            d.label = "not an array, matrix or vector".into();
            d.token = "[".into();
            return error_expr(span);
        };
        if i.ty != Type::INT && i.ty != Type::UINT {
            let t = self.type_name(&i.ty);
            let d = self.error(
                Code::TypeMismatch,
                i.span,
                format!("an index must be an `int` or `uint`, not {t}"),
            );
            d.label = format!("this is {t}");
            d.token = "[".into();
            return error_expr(span);
        }
        if self.es100_check_index(&b, &i)
            || self.check_frag_data_index(&b, &i)
            || self.check_output_index(&b, &i)
        {
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
                    Code::IndexOutOfRange,
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
                    Code::IndexOutOfRange,
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
        } else if !self.lang.es100
            && (elem.contains_sampler(&self.structs) || matches!(elem, Type::Sampler(_)))
        {
            let d = self.error(
                Code::DynamicSamplerIndex,
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

    pub(super) fn field(&mut self, base: &ast::Expr, name: &ast::Ident, span: Span) -> Expr {
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
                            Code::NoSuchField,
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
                    Code::InvalidField,
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
                    Code::InvalidField,
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
                    Code::InvalidSwizzle,
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
                    Code::InvalidSwizzle,
                    name.span,
                    format!("swizzle `{}` mixes component sets", name.name),
                );
                d.label = "use only one of xyzw, rgba or stpq".into();
                return error_expr(span);
            }
            set = Some(s);
            if i >= n {
                let d = self.error(
                    Code::InvalidSwizzle,
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
                Code::InvalidSwizzle,
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
                        Code::NotIndexable,
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
                            Code::IndexOutOfRange,
                            i.span,
                            format!("index {v} is out of range for a block array of {n}"),
                        );
                        d.label = "out of range".into();
                        return error_expr(span);
                    }
                    None => {
                        let d = self.error(
                            Code::DynamicBlockIndex,
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
                        Code::NotAValue,
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
                    Code::NoSuchField,
                    name.span,
                    format!("uniform block `{bname}` has no member `{}`", name.name),
                );
                d.label = "unknown member".into();
                error_expr(span)
            }
        }
    }
}
