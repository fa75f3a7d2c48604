//! A program's interface: what a lowered module reads and writes (its vertex inputs, its
//! first fragment output, the kinds and shapes of their types), and its uniforms as WebGL
//! names them.

use essl::program::{ProgramLayout, UniformStorage};
use essl::types::GlType;

/// The scalar kind of a shader input or output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum ValueKind {
    Float,
    Sint,
    Uint,
}

/// A vertex shader input, read from the naga module's entry point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct ShaderInput {
    pub(crate) location: u32,
    pub(crate) kind: ValueKind,
    pub(crate) components: u8,
}

/// What `get_active_attrib`, `get_active_uniform` and `get_transform_feedback_varying`
/// return (`WebGLActiveInfo`): the name as WebGL enumerates it, the array size (1 for a
/// non-array) and the type enum (`FLOAT_VEC3`, `SAMPLER_2D`, …).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ActiveInfo {
    /// The name (`u_lights[0].color`, `u_weights[0]`).
    pub name: String,
    /// Elements of an array, else 1.
    pub size: u32,
    /// The type, as a GL enum.
    pub ty: u32,
}

pub(super) fn value_kind(scalar: naga::Scalar) -> Option<ValueKind> {
    match scalar.kind {
        naga::ScalarKind::Float => Some(ValueKind::Float),
        naga::ScalarKind::Sint => Some(ValueKind::Sint),
        naga::ScalarKind::Uint => Some(ValueKind::Uint),
        _ => None,
    }
}

/// The kind and width of a scalar or vector type.
pub(crate) fn type_shape(
    module: &naga::Module,
    ty: naga::Handle<naga::Type>,
) -> Option<(ValueKind, u8)> {
    match module.types[ty].inner {
        naga::TypeInner::Scalar(s) => Some((value_kind(s)?, 1)),
        naga::TypeInner::Vector { size, scalar } => Some((value_kind(scalar)?, size as u8)),
        _ => None,
    }
}

/// The entry point `main` of a module (the first one if none is so named).
pub(crate) fn main_entry(module: &naga::Module) -> Option<&naga::EntryPoint> {
    module
        .entry_points
        .iter()
        .find(|e| e.name == "main")
        .or(module.entry_points.first())
}

pub(super) fn shader_inputs(module: &naga::Module) -> Vec<ShaderInput> {
    let Some(ep) = main_entry(module) else {
        return Vec::new();
    };
    ep.function
        .arguments
        .iter()
        .filter_map(|arg| match arg.binding {
            Some(naga::Binding::Location { location, .. }) => {
                let (kind, components) = type_shape(module, arg.ty)?;
                Some(ShaderInput {
                    location,
                    kind,
                    components,
                })
            }
            _ => None,
        })
        .collect()
}

/// The fragment outputs of a module: each location and the kind of its value.
pub(super) fn outputs(module: &naga::Module) -> Vec<(u32, ValueKind)> {
    let Some(result) = main_entry(module).and_then(|e| e.function.result.as_ref()) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    if let Some(naga::Binding::Location { location, .. }) = result.binding {
        out.extend(type_shape(module, result.ty).map(|(k, _)| (location, k)));
    }
    if let naga::TypeInner::Struct { members, .. } = &module.types[result.ty].inner {
        for m in members {
            if let Some(naga::Binding::Location { location, .. }) = m.binding {
                out.extend(type_shape(module, m.ty).map(|(k, _)| (location, k)));
            }
        }
    }
    out
}

/// Components and matrix shape of a uniform type.
pub(crate) fn uniform_shape(ty: GlType) -> (u8, Option<(u8, u8)>, bool) {
    use GlType::*;
    match ty {
        FLOAT | INT | UNSIGNED_INT => (1, None, false),
        BOOL => (1, None, true),
        FLOAT_VEC2 | INT_VEC2 | UNSIGNED_INT_VEC2 => (2, None, false),
        BOOL_VEC2 => (2, None, true),
        FLOAT_VEC3 | INT_VEC3 | UNSIGNED_INT_VEC3 => (3, None, false),
        BOOL_VEC3 => (3, None, true),
        FLOAT_VEC4 | INT_VEC4 | UNSIGNED_INT_VEC4 => (4, None, false),
        BOOL_VEC4 => (4, None, true),
        FLOAT_MAT2 => (4, Some((2, 2)), false),
        FLOAT_MAT3 => (9, Some((3, 3)), false),
        FLOAT_MAT4 => (16, Some((4, 4)), false),
        FLOAT_MAT2x3 => (6, Some((2, 3)), false),
        FLOAT_MAT2x4 => (8, Some((2, 4)), false),
        FLOAT_MAT3x2 => (6, Some((3, 2)), false),
        FLOAT_MAT3x4 => (12, Some((3, 4)), false),
        FLOAT_MAT4x2 => (8, Some((4, 2)), false),
        FLOAT_MAT4x3 => (12, Some((4, 3)), false),
        _ => (1, None, false),
    }
}

/// The active uniform (its index) and the array element that WebGL's `name` designates
/// (`"u_color"`, `"u_lights[2].position"`, `"u_weights[3]"`); members of uniform blocks have
/// none.
pub(crate) fn find_uniform(layout: &ProgramLayout, name: &str) -> Option<(usize, u32)> {
    for (i, u) in layout.uniforms.iter().enumerate() {
        // Members of uniform blocks have no location in WebGL.
        if matches!(u.storage, UniformStorage::Block { .. }) {
            continue;
        }
        let element = if u.name == name {
            Some(0)
        } else if let Some(base) = u.name.strip_suffix("[0]") {
            if name == base {
                Some(0)
            } else {
                name.strip_prefix(base)
                    .and_then(|rest| rest.strip_prefix('['))
                    .and_then(|rest| rest.strip_suffix(']'))
                    .filter(|k| !k.is_empty() && k.bytes().all(|b| b.is_ascii_digit()))
                    .and_then(|k| k.parse::<u32>().ok())
                    .filter(|&k| k < u.size)
            }
        } else {
            None
        };
        if let Some(element) = element {
            return Some((i, element));
        }
    }
    None
}
