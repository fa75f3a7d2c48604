//! Uniform blocks: a struct per block with `to_std140()`, the bytes a `UNIFORM_BUFFER` takes.

use std::fmt::Write as _;

use essl::hir::Module;
use essl::types::{ScalarKind, StructDef, Type};

use super::names::{declaration, field_ident, type_ident, StructNames};
use super::text::string_literal;

/// The struct of a uniform block, with `NAME`, `SIZE`, `ZERO` and `to_std140`; `None` for a
/// block this generator leaves out (an instance array, a `row_major` matrix, `packed`).
pub(super) fn block_struct(
    names: &mut StructNames,
    stage: u8,
    index: usize,
    modules: [&Module; 2],
) -> Option<String> {
    use essl::lower::layout::std140;
    let module = modules[stage as usize];
    let block = &module.blocks[index];
    let structs = &module.structs;
    let plain = block.array.is_none()
        && block.layout != essl::hir::BlockLayout::Packed
        && block
            .members
            .iter()
            .all(|(_, ty, _, row_major)| !row_major || !has_matrix(ty, structs));
    if !plain {
        return None;
    }
    let name = type_ident(&block.name);
    let (mut fields, mut zero, mut writes) = (String::new(), String::new(), String::new());
    let mut offset = 0u32;
    for (member, ty, _, _) in &block.members {
        let (size, align) = std140(ty, structs);
        offset = offset.div_ceil(align) * align;
        let (rust, z) = names.rust_type(ty, stage, modules, "super::types::");
        let ident = field_ident(member);
        let _ = writeln!(
            fields,
            "    /// `{}` at byte {offset}\n    pub {ident}: {rust},",
            declaration(ty, member, structs)
        );
        let _ = write!(zero, "\n        {ident}: {z},");
        let at = Offset {
            dynamic: String::new(),
            constant: offset,
        };
        write_std140(ty, &format!("self.{ident}"), &at, structs, 2, &mut writes);
        offset += size;
    }
    let size = offset.div_ceil(16) * 16;
    Some(format!(
        "/// `uniform {}` (std140).\n#[derive(Clone, Copy, Debug, PartialEq)]\npub struct {name} {{\n{fields}}}\n\n\
         impl {name} {{\n    /// The block's name, as `getUniformBlockIndex` takes it.\n    \
         pub const NAME: &str = {};\n    /// The size of its data in bytes (std140).\n    \
         pub const SIZE: usize = {size};\n    /// Every member zero (false).\n    \
         pub const ZERO: Self = Self {{{zero}\n    }};\n\n    \
         /// The block's data in std140 layout, for `bufferData(UNIFORM_BUFFER, …)`.\n    \
         pub fn to_std140(&self) -> ::std::vec::Vec<u8> {{\n        \
         let mut out = ::std::vec![0u8; Self::SIZE];\n{writes}        out\n    }}\n}}\n\n\
         impl ::core::default::Default for {name} {{\n    fn default() -> Self {{\n        Self::ZERO\n    }}\n}}\n",
        block.name,
        string_literal(&block.name),
    ))
}

/// Whether a type holds a matrix.
pub(super) fn has_matrix(ty: &Type, structs: &[StructDef]) -> bool {
    match ty {
        Type::Matrix { .. } => true,
        Type::Array(el, _) => has_matrix(el, structs),
        Type::Struct(id) => structs[id.0 as usize]
            .members
            .iter()
            .any(|m| has_matrix(&m.ty, structs)),
        _ => false,
    }
}

/// A byte offset in a std140 buffer: a run-time part (loop indices) plus a constant.
#[derive(Clone)]
pub(super) struct Offset {
    dynamic: String,
    constant: u32,
}

impl Offset {
    fn plus(&self, n: u32) -> Offset {
        Offset {
            dynamic: self.dynamic.clone(),
            constant: self.constant + n,
        }
    }

    /// The offset as an expression, with `extra` (a run-time term) added.
    fn expr(&self, extra: &str) -> String {
        let terms: Vec<String> = [self.dynamic.as_str(), extra]
            .into_iter()
            .filter(|t| !t.is_empty())
            .map(str::to_owned)
            .chain((self.constant > 0).then(|| self.constant.to_string()))
            .collect();
        if terms.is_empty() {
            "0".into()
        } else {
            terms.join(" + ")
        }
    }
}

/// Statements that write the value at `expr` (of type `ty`) at `base` of `out`, in std140:
/// 4 bytes a component (`bool` as a `u32` 0 or 1), matrix columns and array elements 16-byte
/// aligned, struct members at their aligned offsets.
pub(super) fn write_std140(
    ty: &Type,
    expr: &str,
    base: &Offset,
    structs: &[StructDef],
    depth: usize,
    out: &mut String,
) {
    use essl::lower::layout::std140;
    let pad = "    ".repeat(depth);
    let bytes = |value: &str, kind: ScalarKind| match kind {
        ScalarKind::Bool => format!("({value} as u32).to_ne_bytes()"),
        _ => format!("{value}.to_ne_bytes()"),
    };
    let put = "super::super::put_std140(&mut out";
    match ty {
        Type::Scalar(k) => {
            let _ = writeln!(out, "{pad}{put}, {}, {});", base.expr(""), bytes(expr, *k));
        }
        Type::Vector(k, _) => {
            let _ = writeln!(
                out,
                "{pad}for (k, v) in {expr}.iter().enumerate() {{\n{pad}    {put}, {}, {});\n{pad}}}",
                base.expr("4 * k"),
                bytes(if *k == ScalarKind::Bool { "*v" } else { "v" }, *k)
            );
        }
        Type::Matrix { rows, .. } => {
            let _ = writeln!(
                out,
                "{pad}for (k, v) in {expr}.iter().enumerate() {{\n{pad}    \
                 // Element k is row k % {rows} of column k / {rows}; columns are 16 bytes apart.\n{pad}    \
                 {put}, {}, v.to_ne_bytes());\n{pad}}}",
                base.expr(&format!("16 * (k / {rows}) + 4 * (k % {rows})"))
            );
        }
        Type::Array(el, n) => {
            let stride = std140(el, structs).0.div_ceil(16) * 16;
            let i = format!("i{depth}");
            let _ = writeln!(out, "{pad}for {i} in 0..{n} {{");
            let inner = Offset {
                dynamic: base.expr(&format!("{stride} * {i}")),
                constant: 0,
            };
            write_std140(el, &format!("{expr}[{i}]"), &inner, structs, depth + 1, out);
            let _ = writeln!(out, "{pad}}}");
        }
        Type::Struct(id) => {
            let mut offset = 0u32;
            for m in &structs[id.0 as usize].members {
                let (size, align) = std140(&m.ty, structs);
                offset = offset.div_ceil(align) * align;
                let member = format!("{expr}.{}", field_ident(&m.name));
                write_std140(&m.ty, &member, &base.plus(offset), structs, depth, out);
                offset += size;
            }
        }
        Type::Sampler(_) | Type::Void => {}
    }
}
