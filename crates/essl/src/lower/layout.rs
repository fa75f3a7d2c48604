//! GLSL types as naga types, and std140 storage for uniforms.
//!
//! A value in a uniform buffer is stored with std140 rules, which naga's uniform layout does
//! not always match: `bool` becomes `u32`, a matrix with 2 rows becomes an array of `vec2`
//! columns with a 16-byte stride, arrays get a 16-byte-aligned stride. [`Repr`] records how
//! the stored form differs from the GLSL type, so that a load can convert it back.

use naga::{Handle, Scalar as NScalar, StructMember, TypeInner, VectorSize};

use crate::reflect::PathStep;
use crate::types::{ScalarKind, StructDef, Type};

/// naga's scalar for a GLSL scalar kind (in a logical value).
pub fn scalar(kind: ScalarKind) -> NScalar {
    match kind {
        ScalarKind::Float => NScalar::F32,
        ScalarKind::Int => NScalar::I32,
        ScalarKind::Uint => NScalar::U32,
        ScalarKind::Bool => NScalar::BOOL,
    }
}

/// naga's vector size for 2..=4.
pub fn vsize(n: u8) -> VectorSize {
    match n {
        2 => VectorSize::Bi,
        3 => VectorSize::Tri,
        _ => VectorSize::Quad,
    }
}

fn round_up(x: u32, to: u32) -> u32 {
    x.div_ceil(to) * to
}

/// Size and alignment of a type in std140 (samplers take no space).
pub fn std140(ty: &Type, structs: &[StructDef]) -> (u32, u32) {
    match ty {
        Type::Scalar(_) => (4, 4),
        Type::Vector(_, 2) => (8, 8),
        Type::Vector(_, 3) => (12, 16),
        Type::Vector(_, _) => (16, 16),
        Type::Matrix { cols, .. } => (16 * *cols as u32, 16),
        Type::Array(el, n) => {
            let (s, _) = std140(el, structs);
            (round_up(s, 16) * n, 16)
        }
        Type::Struct(id) => {
            let mut offset = 0;
            let mut align = 16;
            for m in &structs[id.0 as usize].members {
                if m.ty.contains_sampler(structs) && !has_data(&m.ty, structs) {
                    continue;
                }
                let (s, a) = std140(&m.ty, structs);
                offset = round_up(offset, a) + s;
                align = align.max(a);
            }
            (round_up(offset.max(1), 16), align)
        }
        Type::Sampler(_) | Type::Void => (0, 1),
    }
}

/// Whether a type holds any non-sampler data.
pub fn has_data(ty: &Type, structs: &[StructDef]) -> bool {
    match ty {
        Type::Sampler(_) | Type::Void => false,
        Type::Array(el, _) => has_data(el, structs),
        Type::Struct(id) => structs[id.0 as usize]
            .members
            .iter()
            .any(|m| has_data(&m.ty, structs)),
        _ => true,
    }
}

/// How a stored value differs from its GLSL type.
#[derive(Clone, Debug, PartialEq)]
pub enum Repr {
    /// Stored as the GLSL type itself.
    Same,
    /// A `bool`/`bvecN` stored as `u32`/`uvecN`.
    Bool(Option<VectorSize>),
    /// A `matCx2` stored as `array<vec2<f32>, C>` with stride 16.
    Columns {
        /// Columns.
        cols: u8,
        /// Rows (2).
        rows: u8,
    },
    /// An array whose elements are stored differently.
    Array(Box<Repr>),
    /// An array element stored as the only member (`value`, offset 0) of a 16-byte struct:
    /// std140 puts array elements 16 bytes apart, and a scalar or two-component vector has a
    /// smaller natural stride in WGSL, which has no stride attribute to say otherwise. naga's
    /// IR could say it with the array's stride, but its WGSL writer cannot write that.
    Padded(Box<Repr>),
    /// A struct: for each GLSL member, its index in the stored struct and its repr (`None`
    /// for a sampler member, which is not stored).
    Struct(Vec<Option<(u32, Repr)>>),
}

impl Repr {
    /// Whether loading needs no conversion.
    pub fn is_same(&self) -> bool {
        matches!(self, Repr::Same)
    }

    /// The repr of an element, column or component.
    pub fn index(&self) -> Repr {
        match self {
            Repr::Array(el) => (**el).clone(),
            Repr::Bool(Some(_)) => Repr::Bool(None),
            Repr::Columns { .. } => Repr::Padded(Box::new(Repr::Same)),
            _ => Repr::Same,
        }
    }
}

/// Builds naga types for GLSL types of one module.
pub struct Types<'a> {
    /// The module's struct table.
    pub structs: &'a [StructDef],
    /// Logical naga struct types, by struct id.
    logical_structs: Vec<Option<Handle<naga::Type>>>,
    /// Logical naga scalar, vector and matrix types, by [`simple_slot`]: most lookups, and
    /// each would otherwise hash a naga type into the module's type table.
    logical_simple: [Option<Handle<naga::Type>>; SIMPLE_SLOTS],
}

/// Scalars (4 kinds), vectors (4 kinds × 3 sizes), matrices (3 × 3 sizes), and the one type
/// that samplers and `void` stand for.
const SIMPLE_SLOTS: usize = 4 + 12 + 9 + 1;

/// The slot of a scalar, vector or matrix type (or a sampler or `void`) in
/// [`Types::logical_simple`].
fn simple_slot(ty: &Type) -> Option<usize> {
    let kind = |k: ScalarKind| match k {
        ScalarKind::Float => 0,
        ScalarKind::Int => 1,
        ScalarKind::Uint => 2,
        ScalarKind::Bool => 3,
    };
    let size = |n: u8| (2..=4).contains(&n).then(|| usize::from(n) - 2);
    match *ty {
        Type::Scalar(k) => Some(kind(k)),
        Type::Vector(k, n) => Some(4 + 3 * kind(k) + size(n)?),
        Type::Matrix { cols, rows } => Some(16 + 3 * size(cols)? + size(rows)?),
        Type::Sampler(_) | Type::Void => Some(25),
        Type::Struct(_) | Type::Array(..) => None,
    }
}

impl<'a> Types<'a> {
    /// A builder for a module's struct table.
    pub fn new(structs: &'a [StructDef]) -> Types<'a> {
        Types {
            structs,
            logical_structs: vec![None; structs.len()],
            logical_simple: [None; SIMPLE_SLOTS],
        }
    }

    /// The naga type of a GLSL value (function and private variables, expressions).
    pub fn logical(&mut self, m: &mut naga::Module, ty: &Type) -> Handle<naga::Type> {
        let slot = simple_slot(ty);
        if let Some(h) = slot.and_then(|i| self.logical_simple[i]) {
            return h;
        }
        let inner = match ty {
            Type::Scalar(k) => TypeInner::Scalar(scalar(*k)),
            Type::Vector(k, n) => TypeInner::Vector {
                size: vsize(*n),
                scalar: scalar(*k),
            },
            Type::Matrix { cols, rows } => TypeInner::Matrix {
                columns: vsize(*cols),
                rows: vsize(*rows),
                scalar: NScalar::F32,
            },
            Type::Array(el, n) => {
                let base = self.logical(m, el);
                let stride = m.types[base].inner.size(m.to_ctx()).max(1);
                let align = naga_align(m, base);
                TypeInner::Array {
                    base,
                    size: naga::ArraySize::Constant(
                        std::num::NonZeroU32::new((*n).max(1)).expect("non-zero"),
                    ),
                    stride: round_up(stride, align),
                }
            }
            Type::Struct(id) => {
                if let Some(h) = self.logical_structs[id.0 as usize] {
                    return h;
                }
                let def = &self.structs[id.0 as usize];
                let mut members = Vec::new();
                let mut offset = 0u32;
                let mut max_align = 1u32;
                for mem in &def.members {
                    if matches!(mem.ty, Type::Sampler(_)) || !has_data(&mem.ty, self.structs) {
                        // Samplers in structs live in their own bindings; keep a placeholder
                        // so member indices stay the same.
                        let h = m.types.insert(
                            naga::Type {
                                name: None,
                                inner: TypeInner::Scalar(NScalar::U32),
                            },
                            Default::default(),
                        );
                        offset = round_up(offset, 4);
                        members.push(StructMember {
                            name: Some(mem.name.clone()),
                            ty: h,
                            binding: None,
                            offset,
                        });
                        offset += 4;
                        max_align = max_align.max(4);
                        continue;
                    }
                    let h = self.logical(m, &mem.ty);
                    let a = naga_align(m, h);
                    let s = m.types[h].inner.size(m.to_ctx());
                    offset = round_up(offset, a);
                    members.push(StructMember {
                        name: Some(mem.name.clone()),
                        ty: h,
                        binding: None,
                        offset,
                    });
                    offset += s;
                    max_align = max_align.max(a);
                }
                let span = round_up(offset.max(1), max_align);
                let h = m.types.insert(
                    naga::Type {
                        name: def.name.clone(),
                        inner: TypeInner::Struct { members, span },
                    },
                    Default::default(),
                );
                self.logical_structs[id.0 as usize] = Some(h);
                return h;
            }
            Type::Sampler(_) | Type::Void => TypeInner::Scalar(NScalar::U32),
        };
        let h = m
            .types
            .insert(naga::Type { name: None, inner }, Default::default());
        if let Some(i) = slot {
            self.logical_simple[i] = Some(h);
        }
        h
    }

    /// The naga type a uniform of this GLSL type is stored as (std140), and its repr.
    pub fn storage(&mut self, m: &mut naga::Module, ty: &Type) -> (Handle<naga::Type>, Repr) {
        match ty {
            Type::Scalar(ScalarKind::Bool) => (self.scalar_ty(m, NScalar::U32), Repr::Bool(None)),
            Type::Vector(ScalarKind::Bool, n) => {
                let h = m.types.insert(
                    naga::Type {
                        name: None,
                        inner: TypeInner::Vector {
                            size: vsize(*n),
                            scalar: NScalar::U32,
                        },
                    },
                    Default::default(),
                );
                (h, Repr::Bool(Some(vsize(*n))))
            }
            Type::Matrix { cols, rows: 2 } => {
                let col = m.types.insert(
                    naga::Type {
                        name: None,
                        inner: TypeInner::Vector {
                            size: VectorSize::Bi,
                            scalar: NScalar::F32,
                        },
                    },
                    Default::default(),
                );
                let col = self.padded(m, col);
                let h = m.types.insert(
                    naga::Type {
                        name: None,
                        inner: TypeInner::Array {
                            base: col,
                            size: naga::ArraySize::Constant(
                                std::num::NonZeroU32::new(*cols as u32).expect("cols"),
                            ),
                            stride: 16,
                        },
                    },
                    Default::default(),
                );
                (
                    h,
                    Repr::Columns {
                        cols: *cols,
                        rows: 2,
                    },
                )
            }
            Type::Array(el, n) => {
                let (mut base, mut repr) = self.storage(m, el);
                let (size, _) = std140(el, self.structs);
                let natural = m.types[base].inner.size(m.to_ctx());
                if round_up(natural, naga_align(m, base)) < round_up(size, 16) {
                    base = self.padded(m, base);
                    repr = Repr::Padded(Box::new(repr));
                }
                let h = m.types.insert(
                    naga::Type {
                        name: None,
                        inner: TypeInner::Array {
                            base,
                            size: naga::ArraySize::Constant(
                                std::num::NonZeroU32::new((*n).max(1)).expect("n"),
                            ),
                            stride: round_up(size, 16),
                        },
                    },
                    Default::default(),
                );
                (
                    h,
                    if repr.is_same() {
                        Repr::Same
                    } else {
                        Repr::Array(Box::new(repr))
                    },
                )
            }
            Type::Struct(id) => {
                let def = &self.structs[id.0 as usize];
                let mut members = Vec::new();
                let mut reprs = Vec::new();
                let mut offset = 0u32;
                let mut same = true;
                for mem in &def.members {
                    if !has_data(&mem.ty, self.structs) {
                        reprs.push(None);
                        same = false;
                        continue;
                    }
                    let (h, r) = self.storage(m, &mem.ty);
                    let (s, a) = std140(&mem.ty, self.structs);
                    offset = round_up(offset, a);
                    reprs.push(Some((members.len() as u32, r.clone())));
                    same &= r.is_same();
                    members.push(StructMember {
                        name: Some(mem.name.clone()),
                        ty: h,
                        binding: None,
                        offset,
                    });
                    offset += s;
                }
                let (size, _) = std140(ty, self.structs);
                let h = m.types.insert(
                    naga::Type {
                        name: def.name.as_ref().map(|n| format!("{n}_std140")),
                        inner: TypeInner::Struct {
                            members,
                            span: size,
                        },
                    },
                    Default::default(),
                );
                // A struct whose stored form equals the logical one still loads through a
                // conversion, because the logical struct type is a different naga type.
                let _ = same;
                (h, Repr::Struct(reprs))
            }
            _ => (self.logical(m, ty), Repr::Same),
        }
    }

    /// The 16-byte struct that holds one array element of type `base` ([`Repr::Padded`]).
    fn padded(&mut self, m: &mut naga::Module, base: Handle<naga::Type>) -> Handle<naga::Type> {
        let name = match &m.types[base].inner {
            TypeInner::Scalar(s) => format!("std140_{}", scalar_name(*s)),
            TypeInner::Vector { size, scalar } => {
                format!("std140_vec{}{}", *size as u8, scalar_name(*scalar))
            }
            _ => "std140_element".to_owned(),
        };
        m.types.insert(
            naga::Type {
                name: Some(name),
                inner: TypeInner::Struct {
                    members: vec![StructMember {
                        name: Some("value".into()),
                        ty: base,
                        binding: None,
                        offset: 0,
                    }],
                    span: 16,
                },
            },
            Default::default(),
        )
    }

    fn scalar_ty(&mut self, m: &mut naga::Module, s: NScalar) -> Handle<naga::Type> {
        m.types.insert(
            naga::Type {
                name: None,
                inner: TypeInner::Scalar(s),
            },
            Default::default(),
        )
    }
}

/// Offset of a leaf inside a uniform (a uniform leaf's path from its variable, as
/// [`crate::reflect`] gives it), its array stride and matrix stride (std140).
pub fn leaf_layout(ty: &Type, path: &[PathStep], structs: &[StructDef]) -> (u32, u32, u32) {
    let mut t = ty.clone();
    let mut offset = 0;
    for step in path {
        match (step, &t) {
            (PathStep::Index(i), Type::Array(el, _)) => {
                let (s, _) = std140(el, structs);
                offset += s.div_ceil(16) * 16 * i;
                t = (**el).clone();
            }
            (PathStep::Member(i), Type::Struct(id)) => {
                let mut off: u32 = 0;
                let members = &structs[id.0 as usize].members;
                for (j, m) in members.iter().enumerate() {
                    if !has_data(&m.ty, structs) {
                        continue;
                    }
                    let (s, a) = std140(&m.ty, structs);
                    off = off.div_ceil(a) * a;
                    if j == *i as usize {
                        break;
                    }
                    off += s;
                }
                offset += off;
                t = members[*i as usize].ty.clone();
            }
            _ => break,
        }
    }
    let (array_stride, el) = match &t {
        Type::Array(el, _) => (std140(el, structs).0.div_ceil(16) * 16, (**el).clone()),
        other => (0, other.clone()),
    };
    let matrix_stride = if matches!(el, Type::Matrix { .. }) {
        16
    } else {
        0
    };
    (offset, array_stride, matrix_stride)
}

/// Whether `ty` is the 16-byte struct of a padded array element ([`Repr::Padded`]): its one
/// member, `value`, is the element (passes that name uniforms leave the member out).
pub fn is_padded(m: &naga::Module, ty: Handle<naga::Type>) -> bool {
    let t = &m.types[ty];
    t.name.as_deref().is_some_and(|n| n.starts_with("std140_"))
        && matches!(&t.inner, TypeInner::Struct { members, span: 16 }
            if members.len() == 1 && members[0].name.as_deref() == Some("value"))
}

/// `f32`, `i32`, `u32`: a scalar's name in a padded element's struct name.
fn scalar_name(s: NScalar) -> &'static str {
    match s.kind {
        naga::ScalarKind::Sint => "i32",
        naga::ScalarKind::Uint => "u32",
        naga::ScalarKind::Bool => "bool",
        _ => "f32",
    }
}

/// naga's alignment of a type (for building logical structs and arrays).
pub fn naga_align(m: &naga::Module, h: Handle<naga::Type>) -> u32 {
    match &m.types[h].inner {
        TypeInner::Scalar(s) => s.width as u32,
        TypeInner::Vector { size, scalar } => {
            let w = scalar.width as u32;
            match size {
                VectorSize::Bi => 2 * w,
                _ => 4 * w,
            }
        }
        TypeInner::Matrix { rows, scalar, .. } => {
            let w = scalar.width as u32;
            match rows {
                VectorSize::Bi => 2 * w,
                _ => 4 * w,
            }
        }
        TypeInner::Array { base, .. } => naga_align(m, *base),
        TypeInner::Struct { members, .. } => members
            .iter()
            .map(|mm| naga_align(m, mm.ty))
            .max()
            .unwrap_or(1),
        _ => 4,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn std140_sizes() {
        let v3 = Type::Vector(ScalarKind::Float, 3);
        assert_eq!(std140(&v3, &[]), (12, 16));
        assert_eq!(
            std140(&Type::Array(Box::new(Type::FLOAT), 4), &[]),
            (64, 16)
        );
        assert_eq!(std140(&Type::Matrix { cols: 3, rows: 3 }, &[]), (48, 16));
        assert_eq!(std140(&Type::Matrix { cols: 2, rows: 2 }, &[]), (32, 16));
    }
}
