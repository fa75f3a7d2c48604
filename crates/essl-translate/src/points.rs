//! Points in WGSL: WebGPU draws every point one pixel wide, and WGSL has neither
//! `gl_PointSize` nor `gl_PointCoord`.
//!
//! For the WGSL target the vertex shader's `gl_PointSize` output is left out (the shader still
//! computes it into its private variable; nothing reads it) and the fragment shader's
//! `gl_PointCoord` is the centre of the one-pixel point, (0.5, 0.5), which is what WebGL
//! gives a point of size 1. A program that draws larger points needs quads in WebGPU; the
//! output says so in a comment ([`crate::comments`]).

use naga::{BuiltIn, Expression, Handle, Module, Span, TypeInner};

/// What [`drop_point_builtins`] changed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Dropped {
    /// The vertex output `gl_PointSize` was left out.
    pub point_size: bool,
    /// The fragment input `gl_PointCoord` became (0.5, 0.5).
    pub point_coord: bool,
}

/// Removes `gl_PointSize` from the entry points' outputs and replaces `gl_PointCoord` inputs
/// by (0.5, 0.5).
pub fn drop_point_builtins(module: &mut Module) -> Dropped {
    let mut dropped = Dropped::default();
    for i in 0..module.entry_points.len() {
        dropped.point_size |= drop_point_size(module, i);
        dropped.point_coord |= drop_point_coord(module, i);
    }
    dropped
}

fn drop_point_size(module: &mut Module, ep: usize) -> bool {
    let Some(result) = module.entry_points[ep].function.result.clone() else {
        return false;
    };
    let TypeInner::Struct { members, span } = module.types[result.ty].inner.clone() else {
        return false;
    };
    let Some(at) = members
        .iter()
        .position(|m| m.binding == Some(naga::Binding::BuiltIn(BuiltIn::PointSize)))
    else {
        return false;
    };
    let mut kept = members;
    kept.remove(at);
    // The struct is changed in place: the old one would still be written otherwise.
    let new = naga::Type {
        name: module.types[result.ty].name.clone(),
        inner: TypeInner::Struct {
            members: kept,
            span,
        },
    };
    if module.types.get(&new).is_some() {
        return false; // Not an output struct essl made: leave it to the writer to refuse.
    }
    module.types.replace(result.ty, new);
    let f = &mut module.entry_points[ep].function;
    for (_, e) in f.expressions.iter_mut() {
        if let Expression::Compose { ty, components } = e {
            if *ty == result.ty && components.len() > at {
                components.remove(at);
            }
        }
    }
    true
}

fn drop_point_coord(module: &mut Module, ep: usize) -> bool {
    let args = &module.entry_points[ep].function.arguments;
    let Some(at) = args
        .iter()
        .position(|a| a.binding == Some(naga::Binding::BuiltIn(BuiltIn::PointCoord)))
    else {
        return false;
    };
    let ty = args[at].ty;
    let centre = point_centre(module, ty);
    let f = &mut module.entry_points[ep].function;
    f.arguments.remove(at);
    let at = at as u32;
    for (_, e) in f.expressions.iter_mut() {
        if let Expression::FunctionArgument(k) = e {
            if *k == at {
                *e = Expression::Constant(centre);
            } else if *k > at {
                *k -= 1;
            }
        }
    }
    true
}

/// A module constant `gl_PointCoord_1px = vec2(0.5, 0.5)` of type `ty`.
fn point_centre(module: &mut Module, ty: Handle<naga::Type>) -> Handle<naga::Constant> {
    let half = module.global_expressions.append(
        Expression::Literal(naga::Literal::F32(0.5)),
        Span::UNDEFINED,
    );
    let init = module.global_expressions.append(
        Expression::Compose {
            ty,
            components: vec![half, half],
        },
        Span::UNDEFINED,
    );
    module.constants.append(
        naga::Constant {
            name: Some("gl_PointCoord_one_pixel".into()),
            ty,
            init,
        },
        Span::UNDEFINED,
    )
}
