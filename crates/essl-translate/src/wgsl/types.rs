//! Types and literals as a person writes them in WGSL: the predeclared short forms (`vec3f`,
//! `mat4x4f`, `vec2i`), and constants as written (`0.5`, `2`) with a suffix only where WGSL
//! needs one (`1u`, and where two bare literals would be computed in abstract precision).

use std::fmt::Write as _;

use naga::common::wgsl::TypeContext;
use naga::{Handle, Literal, Module, Scalar, ScalarKind, TypeInner, VectorSize};

/// The scalar's WGSL name (`f32`, `i32`, `u32`, `bool`).
pub(crate) fn scalar(s: Scalar) -> &'static str {
    match (s.kind, s.width) {
        (ScalarKind::Float, 2) => "f16",
        (ScalarKind::Float, 8) => "f64",
        (ScalarKind::Float, _) => "f32",
        (ScalarKind::Sint, _) => "i32",
        (ScalarKind::Uint, _) => "u32",
        (ScalarKind::Bool, _) => "bool",
        (ScalarKind::AbstractInt, _) => "i32",
        (ScalarKind::AbstractFloat, _) => "f32",
    }
}

/// `2`, `3` or `4`.
pub(crate) fn size(n: VectorSize) -> u8 {
    n as u8
}

/// `vec3f`, `vec2i`, `vec4u`, `vec3<bool>`.
pub(crate) fn vector(n: VectorSize, s: Scalar) -> String {
    match s.kind {
        ScalarKind::Float if s.width == 4 => format!("vec{}f", size(n)),
        ScalarKind::Sint => format!("vec{}i", size(n)),
        ScalarKind::Uint => format!("vec{}u", size(n)),
        _ => format!("vec{}<{}>", size(n), scalar(s)),
    }
}

/// `mat4x4f`, `mat3x2f`.
pub(crate) fn matrix(columns: VectorSize, rows: VectorSize, s: Scalar) -> String {
    match s.width {
        4 => format!("mat{}x{}f", size(columns), size(rows)),
        _ => format!("mat{}x{}<{}>", size(columns), size(rows), scalar(s)),
    }
}

/// Names of types: struct names come from the writer's names.
pub(crate) struct TypeNames<'a> {
    pub module: &'a Module,
    pub names: &'a super::names::ModuleNames,
}

impl TypeNames<'_> {
    /// The type's WGSL spelling.
    pub(crate) fn name(&self, ty: Handle<naga::Type>) -> String {
        match &self.module.types[ty].inner {
            TypeInner::Struct { .. } => self.names.get(naga::proc::NameKey::Type(ty)).to_owned(),
            inner => self.inner(inner),
        }
    }

    /// The spelling of a type that may be anonymous (a pointer, a value pointer).
    pub(crate) fn inner(&self, inner: &TypeInner) -> String {
        match *inner {
            TypeInner::Scalar(s) => scalar(s).to_owned(),
            TypeInner::Vector { size, scalar } => vector(size, scalar),
            TypeInner::Matrix {
                columns,
                rows,
                scalar,
            } => matrix(columns, rows, scalar),
            TypeInner::Array { base, size, .. } => match size {
                naga::ArraySize::Constant(n) => format!("array<{}, {n}>", self.name(base)),
                _ => format!("array<{}>", self.name(base)),
            },
            TypeInner::Pointer { base, space } => {
                format!("ptr<{}, {}>", space_name(space), self.name(base))
            }
            TypeInner::ValuePointer {
                size,
                scalar: s,
                space,
            } => {
                let base = match size {
                    Some(n) => vector(n, s),
                    None => scalar(s).to_owned(),
                };
                format!("ptr<{}, {base}>", space_name(space))
            }
            ref other => {
                let mut out = String::new();
                let names = NagaTypes(self);
                if names.write_type_inner(other, &mut out).is_err() {
                    out = "unknown".into();
                }
                out
            }
        }
    }
}

fn space_name(space: naga::AddressSpace) -> &'static str {
    match space {
        naga::AddressSpace::Function => "function",
        naga::AddressSpace::Private => "private",
        naga::AddressSpace::Uniform => "uniform",
        naga::AddressSpace::WorkGroup => "workgroup",
        _ => "storage",
    }
}

/// naga's own spelling, for the types a WebGL shader rarely has (textures, samplers).
struct NagaTypes<'a, 'b>(&'a TypeNames<'b>);

impl TypeContext for NagaTypes<'_, '_> {
    fn lookup_type(&self, handle: Handle<naga::Type>) -> &naga::Type {
        &self.0.module.types[handle]
    }

    fn type_name(&self, _: Handle<naga::Type>) -> &str {
        // Only reached for structs, which `TypeNames::name` spells itself.
        "unnamed"
    }

    fn write_override<W: std::fmt::Write>(
        &self,
        _: Handle<naga::Override>,
        out: &mut W,
    ) -> std::fmt::Result {
        out.write_str("override")
    }

    fn write_unnamed_struct<W: std::fmt::Write>(
        &self,
        _: &TypeInner,
        out: &mut W,
    ) -> std::fmt::Result {
        out.write_str("unnamed")
    }
}

/// How a literal is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum LiteralForm {
    /// As written in GLSL: `0.5`, `2` (WGSL's abstract literals, which take the type the
    /// context gives them: the same as the IR's wherever the writer puts one bare).
    Bare,
    /// With the type spelled: `0.5f`, `2i`, where a bare literal would be evaluated in
    /// abstract precision (an operation on two literals) or take no type from its context.
    Typed,
}

/// The literal's text.
pub(crate) fn literal(l: Literal, form: LiteralForm) -> String {
    let typed = form == LiteralForm::Typed;
    match l {
        Literal::F32(v) => float(v, typed),
        Literal::F16(v) => format!("{}h", f32::from(v)),
        Literal::F64(v) => format!("{v:?}lf"),
        Literal::I32(v) if v == i32::MIN => format!("i32({v})"),
        Literal::I32(v) if typed => format!("{v}i"),
        Literal::I32(v) => v.to_string(),
        Literal::U32(v) => format!("{v}u"),
        Literal::I16(v) => format!("i16({v})"),
        Literal::U16(v) => format!("u16({v})"),
        Literal::I64(v) => format!("{v}li"),
        Literal::U64(v) => format!("{v}lu"),
        Literal::Bool(v) => v.to_string(),
        Literal::AbstractInt(v) => v.to_string(),
        Literal::AbstractFloat(v) => format!("{v:?}"),
    }
}

/// The shortest text that reads back as `v`: `0.5`, `1.0`, `1e-7`; with an `f` where the
/// abstract literal's f64 value would round to another f32, or when `typed`.
fn float(v: f32, typed: bool) -> String {
    let mut s = format!("{v:?}");
    if !s.contains(['.', 'e', 'E']) {
        s.push_str(".0");
    }
    let exact = s.parse::<f64>().is_ok_and(|d| d as f32 == v);
    if typed || !exact {
        let _ = write!(s, "f");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn literals_as_written() {
        let bare = LiteralForm::Bare;
        assert_eq!(literal(Literal::F32(0.5), bare), "0.5");
        assert_eq!(literal(Literal::F32(1.0), bare), "1.0");
        assert_eq!(literal(Literal::F32(1e-4), bare), "0.0001");
        assert_eq!(literal(Literal::F32(1e20), bare), "1e20");
        assert_eq!(literal(Literal::F32(-2.0), bare), "-2.0");
        assert_eq!(literal(Literal::F32(0.1), LiteralForm::Typed), "0.1f");
        assert_eq!(literal(Literal::I32(3), bare), "3");
        assert_eq!(literal(Literal::I32(3), LiteralForm::Typed), "3i");
        assert_eq!(literal(Literal::I32(i32::MIN), bare), "i32(-2147483648)");
        assert_eq!(literal(Literal::U32(3), bare), "3u");
        assert_eq!(literal(Literal::Bool(true), bare), "true");
    }

    #[test]
    fn every_f32_reads_back() {
        for bits in (0u32..u32::MAX)
            .step_by(1 << 20)
            .chain([1, 0x7f7f_ffff, 0x0080_0000])
        {
            let v = f32::from_bits(bits);
            if !v.is_finite() {
                continue;
            }
            let s = literal(Literal::F32(v), LiteralForm::Bare);
            let back = match s.strip_suffix('f') {
                Some(t) => t.parse::<f32>().expect("a float"),
                None => s.parse::<f64>().expect("a float") as f32,
            };
            assert_eq!(back.to_bits(), v.to_bits(), "{s}");
        }
    }

    #[test]
    fn short_type_names() {
        let f = Scalar::F32;
        assert_eq!(vector(VectorSize::Tri, f), "vec3f");
        assert_eq!(vector(VectorSize::Bi, Scalar::I32), "vec2i");
        assert_eq!(vector(VectorSize::Quad, Scalar::U32), "vec4u");
        assert_eq!(vector(VectorSize::Bi, Scalar::BOOL), "vec2<bool>");
        assert_eq!(matrix(VectorSize::Quad, VectorSize::Quad, f), "mat4x4f");
        assert_eq!(matrix(VectorSize::Tri, VectorSize::Bi, f), "mat3x2f");
    }
}
