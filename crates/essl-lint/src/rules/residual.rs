//! What is left of a value outside a box: `p - clamp(p, lo, hi)` (or `clamp(p, lo, hi) - p`),
//! times constants. It is the zero vector for every `p` inside `[lo, hi]` — a whole region
//! of pixels or vertices, not isolated points — so `normalize` of it, or a division by its
//! length, is undefined there: a rounded rectangle's `delta / length(delta)` for every vertex
//! in the middle of the plane (Babylon's `Move_Verts` of `xy - clamp(xy, 0.0, 1.0)`), a box's
//! outward direction for every pixel inside the box.
//!
//! The interval arithmetic of `p` and `clamp(p, …)` cannot see it (it does not know they are
//! the same `p`), so the shape is matched on the IR, through locals and constant factors.

use naga::{BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf};

use super::Cx;
use crate::symbolic::resolve;

/// The `clamp` of `x = k * (p - clamp(p, lo, hi))` in function `id`, where every component of
/// `p`'s ordinary values overlaps `[lo, hi]` over a range (not at a point): `x` is then the
/// zero vector over a region of the inputs.
pub(super) fn clamp_residual(cx: &Cx, f: &Function, id: usize, x: Handle<E>) -> Option<Handle<E>> {
    let an = cx.sound();
    let mut h = resolve(f, an, id, x);
    // Constant factors: `2.0 * (xy - center)`.
    for _ in 0..4 {
        let E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } = f.expressions[h]
        else {
            break;
        };
        let constant = |y: Handle<E>| {
            an.num(id, y)
                .and_then(|n| n.hull().as_point())
                .is_some_and(|c| c != 0.0)
        };
        h = match (constant(left), constant(right)) {
            (true, false) => resolve(f, an, id, right),
            (false, true) => resolve(f, an, id, left),
            _ => return None,
        };
    }
    let E::Binary {
        op: Bo::Subtract,
        left,
        right,
    } = f.expressions[h]
    else {
        return None;
    };
    let (left, right) = (resolve(f, an, id, left), resolve(f, an, id, right));
    let clamp_of = |c: Handle<E>, p: Handle<E>| match f.expressions[c] {
        E::Math {
            fun: Mf::Clamp,
            arg,
            arg1: Some(lo),
            arg2: Some(hi),
            ..
        } if an.same(f, id, resolve(f, an, id, arg), p) => Some((c, arg, lo, hi)),
        _ => None,
    };
    let (c, p, lo, hi) = clamp_of(right, left).or_else(|| clamp_of(left, right))?;
    let typical = cx.typical();
    let (p, lo, hi) = (
        typical.num(id, p)?,
        typical.num(id, lo)?,
        typical.num(id, hi)?,
    );
    // A scalar bound applies to every component.
    let at = |n: &crate::value::Num, i: usize| n.comps().get(i).or(n.comps().last()).copied();
    let overlaps = (0..p.comps().len()).all(|i| match (at(p, i), at(lo, i), at(hi, i)) {
        // The bounds' values that hold for every choice: the box is at least [a.hi, b.lo].
        (Some(v), Some(a), Some(b)) => v.lo.max(a.hi) < v.hi.min(b.lo),
        _ => false,
    });
    (overlaps && !p.comps().is_empty()).then_some(c)
}
