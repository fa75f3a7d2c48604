//! What a lowered module reads and writes: its vertex inputs, its first fragment output,
//! and the kinds and shapes of their types.

use super::{ShaderInput, ValueKind};

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
