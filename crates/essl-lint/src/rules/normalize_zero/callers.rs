//! The notes for `normalize` of what a function's callers pass as such: a difference of two
//! points, a vector parameter itself, a cross product of two — the zero vector for some
//! arguments, which a library function leaves to its callers.

use essl::diagnostic::Diagnostic;
use naga::{Expression as E, Function, Handle};

use super::super::{parameters, Cx};
use super::{cross_operands, length_guarded, zero_vector_note, Normalize};
use crate::symbolic::resolve;

/// The note for `normalize(x)` of a difference of values callers pass as such, or of a vertex
/// shader's attributes, or a product with one (a product is zero wherever a factor is):
/// lygia's `lookAt(eye, target)` normalizing `target - eye`, a line renderer's segment direction
/// `normalize((b - a) * scale)` of two positions a vertex holds — the zero vector where a caller
/// passes the same point twice, or the data repeats a point.
pub(super) fn caller_difference(cx: &Cx, n: Normalize) -> Option<Diagnostic> {
    let Normalize { f, id, call, x } = n;
    let d = difference_factor(cx, f, id, x, 0)?;
    let found = parameters::caller_value(cx, f, id, d)?;
    if found.names.len() < 2 {
        return None;
    }
    let g = cx.guards(f, id, call);
    if cx.refined(f, id, x, &g).is_none_or(|v| !v.may_be_zero())
        || cx.nonzero(f, id, x, &g)
        || length_guarded(cx, f, id, x, &g)
    {
        return None;
    }
    let list = found.list();
    let (whose, equal) = if found.attribute {
        ("attributes", "a vertex may hold equal")
    } else {
        ("parameters", "callers may pass equal")
    };
    Some(zero_vector_note(
        cx.span(f, x),
        format!("`normalize` of a difference of the {whose} {list}, which {equal}"),
        format!(
            "{} is the zero vector wherever they are equal",
            cx.what(f, id, x)
        ),
        if found.attribute {
            "attributes are the host's vertex data: a repeated point, a segment of length 0, makes them equal"
        } else {
            found.why()
        },
    ))
}

/// The note for `normalize(p)` of a function's vector parameter as such (or a multiple of
/// it) where its callers pass inputs as such: lygia's `rotate3d(axis, angle)` normalizing its
/// axis, `lookAt(forward)` its forward direction — a library function that leaves the zero
/// vector (a cross product of parallel vectors, an eye at its target) to the caller.
pub(super) fn caller_vector(cx: &Cx, n: Normalize) -> Option<Diagnostic> {
    let Normalize { f, id, call, x } = n;
    let param = parameters::parameter_itself(cx, f, id, call, x)?;
    let found = parameters::caller_value(cx, f, id, param)?;
    let [name] = &found.names[..] else {
        return None;
    };
    if found.attribute {
        return None;
    }
    // The analysis takes inputs for non-zero vectors: only a test of the length says more.
    if length_guarded(cx, f, id, x, &cx.guards(f, id, call)) {
        return None;
    }
    Some(zero_vector_note(
        cx.span(f, x),
        format!(
            "`normalize` of the parameter `{name}`, which a caller may pass as the zero vector"
        ),
        format!("NaN wherever a caller passes `{name}` as the zero vector"),
        found.why(),
    ))
}

/// `h` itself where it is a difference, or a factor of a product that is (`diff * scale`);
/// through locals.
fn difference_factor(
    cx: &Cx,
    f: &Function,
    id: usize,
    h: Handle<E>,
    depth: u32,
) -> Option<Handle<E>> {
    if depth > 8 {
        return None;
    }
    match f.expressions[resolve(f, cx.sound(), id, h)] {
        E::Binary {
            op: naga::BinaryOperator::Subtract,
            ..
        } => Some(h),
        E::Binary {
            op: naga::BinaryOperator::Multiply,
            left,
            right,
        } => difference_factor(cx, f, id, left, depth + 1)
            .or_else(|| difference_factor(cx, f, id, right, depth + 1)),
        _ => None,
    }
}

/// Words of a parameter's name that say it holds a vector of a mesh's frame: two such
/// parameters (a normal and a tangent) are taken to be a valid frame, as two per-pixel
/// vectors are.
const FRAME: &[&str] = &[
    "n",
    "normal",
    "nor",
    "nrm",
    "t",
    "tangent",
    "b",
    "bitangent",
    "binormal",
];

/// The note for `normalize(cross(a, b))` of two vector parameters as such where the callers
/// pass inputs as such: lygia's Ward specular `normalize(cross(N, fiber))`, the zero vector
/// wherever a caller passes a fibre direction along the normal (an upward fibre on a floor) —
/// a library function that leaves parallel vectors to its callers. Two parameters that name a
/// mesh's frame (a normal and a tangent) are left alone, as per-pixel vectors are.
pub(super) fn caller_cross(cx: &Cx, n: Normalize) -> Option<Diagnostic> {
    let Normalize { f, id, call, x } = n;
    let (a, b) = cross_operands(cx, f, id, x)?;
    let mut names = Vec::new();
    let mut why = "";
    for v in [a, b] {
        let param = parameters::parameter_itself(cx, f, id, call, v)?;
        let found = parameters::caller_value(cx, f, id, param)?;
        let [name] = &found.names[..] else {
            return None;
        };
        if found.attribute || names.contains(name) {
            return None;
        }
        names.push(name.clone());
        why = found.why();
    }
    let frame = |n: &String| crate::analysis::names::says_any(n, FRAME);
    if names.iter().all(frame) || length_guarded(cx, f, id, x, &cx.guards(f, id, call)) {
        return None;
    }
    let [p, q] = &names[..] else {
        return None;
    };
    Some(zero_vector_note(
        cx.span(f, x),
        format!(
            "`normalize` of a cross product of the parameters `{p}` and `{q}`, which callers may pass parallel"
        ),
        format!(
            "{} is the zero vector wherever they are parallel",
            cx.what(f, id, x)
        ),
        why,
    ))
}
