//! The size limits WebGL implementations put on variables, which the GLSL ES specification
//! leaves to the implementation. Chromium's ANGLE (`ValidateTypeSizeLimitations`) refuses, as
//! measured on Chromium 156 (`tests/oracle/PROBES.md`, "Variable size limits"):
//! - a variable of 2 GiB or more laid out as a std140 block member, where every array element
//!   takes at least 16 bytes ("Size of declared variable exceeds implementation-defined limit");
//! - a *private* variable — a local, global, constant, parameter or varying — of 64 KiB or more,
//!   counting 4 bytes per scalar component, tightly packed ("Size of declared private variable
//!   exceeds implementation-defined limit"): `float[16383]` compiles, `float[16384]` does not;
//! - private variables that add up to more than 16 MiB ("Total size of declared private
//!   variables exceeds implementation-defined limit").
//!
//! Vertex inputs, fragment outputs and uniforms are not private.

use crate::diagnostic_code::Code;
use crate::source::Span;
use crate::types::{StructDef, Type};

use super::Checker;

/// Variables must stay below this many std140 bytes.
pub(super) const MAX_VARIABLE_BYTES: u64 = 2 << 30;
/// Private variables (local, global, constant, parameter, varying) must stay below this many
/// packed bytes.
pub(super) const MAX_PRIVATE_BYTES: u64 = 64 << 10;
/// All private variables of a shader together may take at most this many packed bytes.
pub(super) const MAX_TOTAL_PRIVATE_BYTES: u64 = 16 << 20;

/// A type's size as a member of a std140 block, in bytes (saturating: sizes past `u64` are
/// over every limit anyway). Samplers count as one scalar.
pub(super) fn std140_bytes(ty: &Type, structs: &[StructDef]) -> u64 {
    std140(ty, structs).0
}

/// A type's size with 4 bytes per scalar component and no padding (saturating).
pub(super) fn packed_bytes(ty: &Type, structs: &[StructDef]) -> u64 {
    match ty {
        Type::Void => 0,
        Type::Scalar(_) | Type::Sampler(_) => 4,
        Type::Vector(_, n) => 4 * u64::from(*n),
        Type::Matrix { cols, rows } => 4 * u64::from(*cols) * u64::from(*rows),
        Type::Array(el, n) => packed_bytes(el, structs).saturating_mul(u64::from(*n)),
        Type::Struct(id) => structs
            .get(id.0 as usize)
            .map_or(&[][..], |s| &s.members)
            .iter()
            .fold(0u64, |sum, m| {
                sum.saturating_add(packed_bytes(&m.ty, structs))
            }),
    }
}

fn round_up(x: u64, to: u64) -> u64 {
    x.div_ceil(to).saturating_mul(to)
}

/// (size, alignment)
fn std140(ty: &Type, structs: &[StructDef]) -> (u64, u64) {
    match ty {
        Type::Void => (0, 1),
        Type::Scalar(_) | Type::Sampler(_) => (4, 4),
        Type::Vector(_, 2) => (8, 8),
        Type::Vector(_, 3) => (12, 16),
        Type::Vector(_, _) => (16, 16),
        Type::Matrix { cols, .. } => (16 * u64::from(*cols), 16),
        Type::Array(el, n) => {
            let stride = round_up(std140(el, structs).0, 16);
            (stride.saturating_mul(u64::from(*n)), 16)
        }
        Type::Struct(id) => {
            let mut offset = 0u64;
            for m in structs.get(id.0 as usize).map_or(&[][..], |s| &s.members) {
                let (size, align) = std140(&m.ty, structs);
                offset = round_up(offset, align).saturating_add(size);
            }
            (round_up(offset, 16), 16)
        }
    }
}

/// A size for messages: bytes, KiB, MiB or GiB.
fn human(bytes: u64) -> String {
    const UNITS: [(&str, u64); 3] = [("GiB", 1 << 30), ("MiB", 1 << 20), ("KiB", 1 << 10)];
    for (unit, size) in UNITS {
        if bytes >= size {
            let whole = bytes / size;
            return if bytes.is_multiple_of(size) {
                format!("{whole} {unit}")
            } else {
                format!("{:.1} {unit}", bytes as f64 / size as f64)
            };
        }
    }
    format!("{bytes} bytes")
}

impl Checker<'_> {
    /// Checks a declared variable or parameter `name` of type `ty` against the limits; `private`
    /// says whether it is a local, global, constant, parameter or varying.
    pub(super) fn check_variable_size(&mut self, name: &str, span: Span, ty: &Type, private: bool) {
        let bytes = std140_bytes(ty, &self.structs);
        if bytes >= MAX_VARIABLE_BYTES {
            let d = self.error(
                Code::VariableTooLarge,
                span,
                format!(
                    "`{name}` takes {} laid out as a std140 block member, and WebGL \
                     implementations allow less than {} for one variable",
                    human(bytes),
                    human(MAX_VARIABLE_BYTES)
                ),
            );
            d.label = "too large".into();
            d.notes.push(
                "WebGL measures a variable as in a std140 block here: every array element takes \
                 at least 16 bytes"
                    .into(),
            );
            return;
        }
        if !private {
            return;
        }
        let bytes = packed_bytes(ty, &self.structs);
        if bytes >= MAX_PRIVATE_BYTES {
            let d = self.error(
                Code::PrivateVariableTooLarge,
                span,
                format!(
                    "`{name}` takes {}, and WebGL implementations allow less than {} for a \
                     local, global, constant, parameter or varying",
                    human(bytes),
                    human(MAX_PRIVATE_BYTES)
                ),
            );
            d.label = "too large for a private variable".into();
            d.notes
                .push("counting 4 bytes per component: `float[16384]` is 64 KiB".into());
            d.help = Some("keep large tables in a uniform block or a texture".into());
            return;
        }
        let before = self.private_bytes;
        self.private_bytes = before.saturating_add(bytes);
        if before <= MAX_TOTAL_PRIVATE_BYTES && self.private_bytes > MAX_TOTAL_PRIVATE_BYTES {
            let d = self.error(
                Code::PrivateVariablesTooLarge,
                span,
                format!(
                    "with `{name}`, the shader's locals, globals, constants, parameters and \
                     varyings take more than the {} a WebGL implementation allows in all",
                    human(MAX_TOTAL_PRIVATE_BYTES)
                ),
            );
            d.label = "the total passes the limit here".into();
            d.help = Some("keep large tables in a uniform block or a texture".into());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::types::ScalarKind;

    #[test]
    fn sizes_are_std140_and_saturate() {
        let float = Type::Scalar(ScalarKind::Float);
        assert_eq!(std140_bytes(&float, &[]), 4);
        assert_eq!(
            std140_bytes(&Type::Array(Box::new(float.clone()), 4096), &[]),
            64 << 10
        );
        assert_eq!(
            packed_bytes(&Type::Array(Box::new(float.clone()), 4096), &[]),
            16 << 10
        );
        let vec3 = Type::Vector(ScalarKind::Float, 3);
        assert_eq!(
            std140_bytes(&Type::Array(Box::new(vec3.clone()), 2), &[]),
            32
        );
        assert_eq!(packed_bytes(&Type::Array(Box::new(vec3), 2), &[]), 24);
        let huge = Type::Array(Box::new(Type::Array(Box::new(float), u32::MAX)), u32::MAX);
        assert!(std140_bytes(&huge, &[]) > MAX_VARIABLE_BYTES);
        assert_eq!(human(64 << 10), "64 KiB");
        assert_eq!(human(3 << 29), "1.5 GiB");
    }
}
