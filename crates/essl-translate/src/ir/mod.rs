//! Changes to the lowered IR before a writer sees it, each leaving a module naga validates:
//! - [`restructure`]: the shader's `main` inlined into the entry point, and the private
//!   variables only the entry point uses made its locals (WGSL only);
//! - [`inverse`]: `inverse()` as a call of a function computing it by cofactors, for the
//!   targets that have no `inverse` (WGSL, MSL, HLSL);
//! - [`merge`]: a program's two stages as one module with both entry points.

mod entry;
pub(crate) mod inverse;
pub(crate) mod merge;
mod remap;
pub(crate) mod restructure;

use naga::{Handle, Module, Type};

pub(crate) use remap::{Maps, ModuleMaps};

/// Copies the types of `from` into `to` (equal types become one); the map of handles.
pub(crate) fn import_types(from: &Module, to: &mut Module) -> Vec<Handle<Type>> {
    let mut map: Vec<Handle<Type>> = Vec::with_capacity(from.types.len());
    for (h, t) in from.types.iter() {
        let inner = match &t.inner {
            naga::TypeInner::Struct { members, span } => naga::TypeInner::Struct {
                members: members
                    .iter()
                    .map(|m| naga::StructMember {
                        name: m.name.clone(),
                        ty: map[m.ty.index()],
                        binding: m.binding.clone(),
                        offset: m.offset,
                    })
                    .collect(),
                span: *span,
            },
            naga::TypeInner::Array { base, size, stride } => naga::TypeInner::Array {
                base: map[base.index()],
                size: *size,
                stride: *stride,
            },
            naga::TypeInner::BindingArray { base, size } => naga::TypeInner::BindingArray {
                base: map[base.index()],
                size: *size,
            },
            naga::TypeInner::Pointer { base, space } => naga::TypeInner::Pointer {
                base: map[base.index()],
                space: *space,
            },
            other => other.clone(),
        };
        let new = to.types.insert(
            Type {
                name: t.name.clone(),
                inner,
            },
            from.types.get_span(h),
        );
        map.push(new);
    }
    map
}

/// Copies the constant expressions and constants of `from` into `to`; `maps` must hold the
/// types' map, and gets the constants' (its expression map is then the global one).
pub(crate) fn import_global_expressions(
    from: &Module,
    to: &mut Module,
    maps: &mut Maps,
) -> Option<()> {
    maps.exprs.clear();
    // Constants refer to expressions and expressions to constants: each constant is copied
    // as soon as its initializer is.
    let mut constants: Vec<(Handle<naga::Constant>, &naga::Constant)> =
        from.constants.iter().collect();
    constants.sort_by_key(|(_, c)| c.init.index());
    let mut next = 0;
    for (h, e) in from.global_expressions.iter() {
        let mapped = maps.expression(e)?;
        let new = to
            .global_expressions
            .append(mapped, from.global_expressions.get_span(h));
        maps.exprs.push(new);
        while let Some(&(c, constant)) = constants.get(next) {
            if constant.init.index() > h.index() {
                break;
            }
            let copied = to.constants.append(
                naga::Constant {
                    name: constant.name.clone(),
                    ty: maps.ty(constant.ty),
                    init: maps.exprs[constant.init.index()],
                },
                from.constants.get_span(c),
            );
            let module = maps.module.as_mut()?;
            if module.constants.len() <= c.index() {
                module.constants.resize(c.index() + 1, copied);
            }
            module.constants[c.index()] = copied;
            next += 1;
        }
    }
    Some(())
}

/// Validates a module as wgpu does.
pub(crate) fn validate(module: &Module) -> Option<naga::valid::ModuleInfo> {
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        essl::lower::capabilities(),
    )
    .validate(module)
    .ok()
}
