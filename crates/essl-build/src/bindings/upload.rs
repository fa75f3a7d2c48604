//! The `uniform*` call that uploads one uniform leaf, and the Rust expression that reads the
//! leaf's value out of a `Uniforms` field.

use std::fmt::Write as _;

use essl::reflect::PathStep;
use essl::types::{ScalarKind, StructDef, Type};

use super::names::field_ident;

/// The suffix of `uniformMatrix{…}fv` for a `cols`×`rows` matrix.
pub(super) fn matrix_suffix(cols: u8, rows: u8) -> String {
    if cols == rows {
        cols.to_string()
    } else {
        format!("{cols}x{rows}")
    }
}

/// The statement that uploads the value at `expr` (of type `ty`, an array of basic values or
/// a basic value) to `loc`.
pub(super) fn upload_statement(ty: &Type, expr: &str, loc: &str) -> String {
    let (basic, array) = match ty {
        Type::Array(el, _) => (&**el, true),
        t => (t, false),
    };
    let flat = |e: &str| {
        if array {
            format!("{e}.as_flattened()")
        } else {
            format!("&{e}")
        }
    };
    match basic {
        Type::Scalar(ScalarKind::Bool) if array => {
            format!("gl.uniform1iv({loc}, &{expr}.map(i32::from));")
        }
        Type::Scalar(ScalarKind::Bool) => format!("gl.uniform1i({loc}, {expr} as i32);"),
        Type::Sampler(_) if array => format!("gl.uniform1iv({loc}, &{expr});"),
        Type::Scalar(k) if array => format!("gl.uniform1{}v({loc}, &{expr});", kind_suffix(*k)),
        Type::Scalar(k) => format!("gl.uniform1{}({loc}, {expr});", kind_suffix(*k)),
        Type::Sampler(_) => format!("gl.uniform1i({loc}, {expr});"),
        Type::Vector(ScalarKind::Bool, n) => {
            let values = if array {
                format!("&{expr}.map(|v| v.map(i32::from)).as_flattened()")
            } else {
                format!("&{expr}.map(i32::from)")
            };
            format!("gl.uniform{n}iv({loc}, {values});")
        }
        Type::Vector(k, n) => format!("gl.uniform{n}{}v({loc}, {});", kind_suffix(*k), flat(expr)),
        Type::Matrix { cols, rows } => format!(
            "gl.uniform_matrix{}fv({loc}, false, {});",
            matrix_suffix(*cols, *rows),
            flat(expr)
        ),
        Type::Struct(_) | Type::Array(..) | Type::Void => {
            unreachable!("a uniform leaf is a basic type or an array of one")
        }
    }
}

pub(super) fn kind_suffix(k: ScalarKind) -> &'static str {
    match k {
        ScalarKind::Float => "f",
        ScalarKind::Int | ScalarKind::Bool => "i",
        ScalarKind::Uint => "ui",
    }
}

/// The Rust expression of the leaf at `path` inside the uniform `ident` of type `ty`, and the
/// leaf's type.
pub(super) fn leaf_expr(
    ident: &str,
    ty: &Type,
    path: &[PathStep],
    structs: &[StructDef],
) -> (String, Type) {
    let mut expr = format!("u.{ident}");
    let mut ty = ty.clone();
    for step in path {
        ty = match (step, &ty) {
            (PathStep::Member(i), Type::Struct(id)) => {
                let m = &structs[id.0 as usize].members[*i as usize];
                let _ = write!(expr, ".{}", field_ident(&m.name));
                m.ty.clone()
            }
            (PathStep::Index(i), Type::Array(el, _)) => {
                let _ = write!(expr, "[{i}]");
                (**el).clone()
            }
            _ => unreachable!("a reflection path follows its type"),
        };
    }
    (expr, ty)
}
