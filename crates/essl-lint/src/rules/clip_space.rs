//! Clip-space positions: whether a `vec4` is `gl_Position` or a product with a projection
//! matrix, what `division-by-difference` asks of a divisor `p.w`.
//!
//! The `w` of a clip-space position is the point's depth in front of the camera for a
//! perspective projection: 0 on the plane through the camera, negative behind it. The fixed
//! function clips primitives after the vertex shader, so every vertex of a triangle or a line
//! that crosses that plane reaches a vertex shader's own perspective divide (`p.xy / p.w` of a
//! line renderer projecting its neighbours to the screen, Cesium's depth clamp): ±∞ or NaN at
//! the plane, and positions mirrored through the camera behind it. A fragment shader sees only
//! what clipping kept, where the camera's `w` is positive, and a vertex shader that sets
//! `gl_PointSize` draws points, which are clipped whole; another frame's projection
//! (a reprojection into the previous frame's camera for motion blur) has no such guarantee.

use naga::{BinaryOperator as Bo, Expression as E, Function, Handle, ShaderStage};

use super::Cx;

/// The deepest walk through locals, calls and arguments.
const MAX_DEPTH: u32 = 8;

/// What makes a `vec4` a clip-space position: `gl_Position`, or the projection matrix (its
/// WebGL name) it is a product with.
pub(super) enum Clip {
    /// The vertex shader's `gl_Position`.
    Position,
    /// A product with the named projection matrix.
    Projection(String),
}

/// The clip-space position `d` (a divisor) is the `w` of, where a perspective divide by it
/// can meet 0: in a vertex shader, `gl_Position.w` or the `w` of a product with a projection
/// matrix; in a fragment shader, the `w` of a product with another frame's projection
/// (`prevViewProjection`). `None` for anything else (a homogeneous coordinate of an affine
/// transform, whose `w` is 1; the camera's own clip `w` in a fragment shader).
pub(super) fn perspective_w(cx: &Cx, f: &Function, id: usize, d: Handle<E>) -> Option<Clip> {
    let stage = cx.module.entry_points.first()?.stage;
    let vector = w_of(f, d)?;
    if draws_points(cx) {
        return None;
    }
    let clip = clip_space(cx, f, id, vector, 0)?;
    match (&clip, stage) {
        (_, ShaderStage::Vertex) => Some(clip),
        (Clip::Projection(name), ShaderStage::Fragment) if another_frame(name) => Some(clip),
        _ => None,
    }
}

/// Whether every use of the quotient `h` gives a finite, defined answer for ±∞ (what a divide
/// by a `w` of 0 gives where `z` or `xy` is not 0): a comparison, `step`, a `clamp` to constant
/// bounds (Cesium's depth clamp `clamp(z / w, -1.0, 1.0) * w`).
pub(super) fn tolerates_infinity(f: &Function, h: Handle<E>) -> bool {
    use naga::MathFunction as Mf;
    let constant = |x: Option<Handle<E>>| {
        x.is_some_and(|x| {
            matches!(
                f.expressions[x],
                E::Literal(_) | E::Constant(_) | E::ZeroValue(_)
            )
        })
    };
    let users = super::users(f);
    let Some(list) = users.get(&h) else {
        return false;
    };
    list.iter().all(|u| {
        let super::User::Expr(user) = *u else {
            return false;
        };
        match f.expressions[user] {
            E::Binary { op, .. } => matches!(
                op,
                Bo::Less
                    | Bo::LessEqual
                    | Bo::Greater
                    | Bo::GreaterEqual
                    | Bo::Equal
                    | Bo::NotEqual
            ),
            E::Math {
                fun: Mf::Step,
                arg1,
                ..
            } => arg1 == Some(h),
            E::Math {
                fun: Mf::Clamp,
                arg,
                arg1,
                arg2,
                ..
            } => arg == h && constant(arg1) && constant(arg2),
            _ => false,
        }
    })
}

/// Whether the shader sets `gl_PointSize`: it draws points, and a point on or behind the
/// camera's plane is clipped whole, whatever its vertex shader computed.
fn draws_points(cx: &Cx) -> bool {
    cx.module
        .global_variables
        .iter()
        .any(|(_, g)| g.name.as_deref() == Some("gl_PointSize"))
}

/// The `vec4` whose `w` expression `d` reads (`p.w`, through a load of `p.w`), as a value or
/// as a pointer.
fn w_of(f: &Function, d: Handle<E>) -> Option<Handle<E>> {
    match f.expressions[d] {
        E::AccessIndex { base, index: 3 } => Some(base),
        E::Load { pointer } => match f.expressions[pointer] {
            E::AccessIndex { base, index: 3 } => Some(base),
            _ => None,
        },
        _ => None,
    }
}

/// Whether `h` (a `vec4` value, or a pointer to a variable holding one) is a clip-space
/// position, through locals, calls and the arguments callers pass.
fn clip_space(cx: &Cx, f: &Function, id: usize, h: Handle<E>, depth: u32) -> Option<Clip> {
    if depth > MAX_DEPTH {
        return None;
    }
    let go = |x: Handle<E>| clip_space(cx, f, id, x, depth + 1);
    match f.expressions[h] {
        E::GlobalVariable(g) => {
            let gv = &cx.module.global_variables[g];
            (gv.space == naga::AddressSpace::Private && gv.name.as_deref() == Some("gl_Position"))
                .then_some(Clip::Position)
        }
        // Stores into other components (`coords.z = 0.0`) keep `w`.
        E::LocalVariable(l) => f.local_variables[l]
            .init
            .into_iter()
            .chain(cx.flows().whole_stores(id, l.index()))
            .find_map(go),
        E::Load { pointer } => go(pointer),
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } if cx.is_matrix(id, left) && !cx.is_matrix(id, right) => {
            projection(cx, f, id, left, depth + 1).map(Clip::Projection)
        }
        E::CallResult(callee) => returned(cx, callee.index(), depth + 1),
        E::FunctionArgument(i) if id < cx.module.functions.len() => {
            cx.flows().callers(id).iter().find_map(|(caller, args)| {
                let g = crate::analysis::function(cx.module, *caller);
                clip_space(cx, g, *caller, *args.get(i as usize)?, depth + 1)
            })
        }
        _ => None,
    }
}

/// Whether some value function `callee` returns is a clip-space position.
fn returned(cx: &Cx, callee: usize, depth: u32) -> Option<Clip> {
    if callee >= cx.module.functions.len() {
        return None;
    }
    let g = crate::analysis::function(cx.module, callee);
    cx.flows()
        .returns(callee)
        .iter()
        .find_map(|r| clip_space(cx, g, callee, *r, depth))
}

/// The WebGL name of the projection matrix `h` is or begins with (the leftmost factor of a
/// product, `projection * view * model`), through locals and arguments.
fn projection(cx: &Cx, f: &Function, id: usize, h: Handle<E>, depth: u32) -> Option<String> {
    if depth > MAX_DEPTH {
        return None;
    }
    let go = |x: Handle<E>| projection(cx, f, id, x, depth + 1);
    match f.expressions[h] {
        E::Binary {
            op: Bo::Multiply,
            left,
            ..
        } => go(left),
        E::Load { pointer } if matches!(f.expressions[pointer], E::LocalVariable(_)) => {
            cx.stored(f, id, pointer).into_iter().find_map(go)
        }
        E::FunctionArgument(i) if id < cx.module.functions.len() => {
            cx.flows().callers(id).iter().find_map(|(caller, args)| {
                let g = crate::analysis::function(cx.module, *caller);
                projection(cx, g, *caller, *args.get(i as usize)?, depth + 1)
            })
        }
        _ => {
            let origin = cx.origin(&[(id, h)]);
            let name = origin.single_uniform()?;
            is_projection(name).then(|| name.to_string())
        }
    }
}

/// Whether a matrix's name says it holds a perspective projection (`projectionMatrix`,
/// `u_mvp`, `viewProj`, `uPMatrix`), not an orthographic one.
fn is_projection(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    let last = lower.rsplit(['.', ']']).next().unwrap_or(&lower);
    !["ortho", "inv", "unproj"].iter().any(|w| last.contains(w))
        && (last.contains("proj") || last.contains("mvp") || last.ends_with("pmatrix"))
}

/// Whether a projection's name says it is another frame's (a reprojection for motion blur or
/// temporal filtering): `prevViewProjection`, `u_previousViewProj`, `lastFrameProj`.
fn another_frame(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    ["prev", "last", "old", "history"]
        .iter()
        .any(|w| lower.contains(w))
}

#[cfg(test)]
mod tests {
    use super::{another_frame, is_projection};

    #[test]
    fn projection_names() {
        for yes in [
            "projectionMatrix",
            "u_mvp",
            "viewProj",
            "uPMatrix",
            "czm_modelViewProjection",
            "global.proj_view",
            "MVP",
        ] {
            assert!(is_projection(yes), "{yes}");
        }
        for no in [
            "czm_viewportOrthographic",
            "u_matrix",
            "modelMatrix",
            "view",
            "uOrthoProjection",
            "uUnprojectMatrix",
            "inverseViewProjection",
        ] {
            assert!(!is_projection(no), "{no}");
        }
        assert!(another_frame("prevViewProjection"));
        assert!(!another_frame("viewProjection"));
    }
}
