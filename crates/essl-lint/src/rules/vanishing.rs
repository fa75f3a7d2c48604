//! Whether a vertex shader's value is degenerate — the zero vector, or NaN — wherever its
//! attributes are the zero vector: what a mesh without a normal or tangent buffer (read as 0)
//! makes of it.
//!
//! A normal through the normal matrix (`normalMatrix * normal`), a direction with `w = 0`
//! through an affine one (`(M * vec4(tangent, 0.0)).xyz`), a cross product with one, a
//! Gram–Schmidt step (`T - dot(T, N) * N`) all vanish with the attribute; a vector decoded from
//! an octahedral encoding (`vec3(e.x, e.y, 1.0 - abs(e.x) - abs(e.y))`) does not, and neither
//! does a position (`vec4(p, 1.0)`). The test substitutes 0 for every attribute and follows
//! the operations that keep a zero: products with anything, sums and differences of zeros,
//! swizzles, constructors of zeros, either value of a `?:` or `mix`, `cross`, `dot`,
//! `normalize` (NaN), locals and the arguments of every call. The attributes taken as 0 are
//! the caller's choice: those that hold a direction, for a vector that also reads a position
//! (Babylon's fur offsets its tangent by random factors of the position) — and then only the
//! zero vector counts, not the NaN of a `normalize` of it, which is reported where it is made.

use naga::{BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf};
use rustc_hash::FxHashMap as HashMap;

use super::Cx;

/// How deep the test follows operands, locals and calls.
const MAX_DEPTH: u32 = 24;

/// Whether value `h` of function `id` is the zero vector (or NaN) wherever the attributes
/// `zero` picks are the zero vector, whatever the others hold; with `nan`, a `normalize` of
/// such a vector counts (NaN), else only the zero vector does.
pub(super) fn with_attributes(
    cx: &Cx,
    f: &Function,
    id: usize,
    h: Handle<E>,
    zero: &dyn Fn(Handle<naga::GlobalVariable>) -> bool,
    nan: bool,
) -> bool {
    let mut seen = Walk {
        locals: Vec::new(),
        known: HashMap::default(),
        zero,
        nan,
    };
    walk(cx, f, id, h, 0, &mut seen)
}

/// What the test has met: the locals it follows (a store that reads the local itself adds
/// nothing), and the answer for each expression already asked (a shared operand, `t + t`,
/// is asked once, so the work is linear in the expressions); which attributes are 0, and
/// whether NaN counts.
struct Walk<'z> {
    locals: Vec<(usize, Handle<E>)>,
    known: HashMap<(usize, Handle<E>), bool>,
    zero: &'z dyn Fn(Handle<naga::GlobalVariable>) -> bool,
    nan: bool,
}

fn walk(cx: &Cx, f: &Function, id: usize, h: Handle<E>, depth: u32, seen: &mut Walk<'_>) -> bool {
    if depth > MAX_DEPTH {
        return false;
    }
    if let Some(&known) = seen.known.get(&(id, h)) {
        return known;
    }
    let answer = vanishes(cx, f, id, h, depth, seen);
    seen.known.insert((id, h), answer);
    answer
}

/// [`walk`]'s answer for `h`, not yet known.
fn vanishes(
    cx: &Cx,
    f: &Function,
    id: usize,
    h: Handle<E>,
    depth: u32,
    seen: &mut Walk<'_>,
) -> bool {
    macro_rules! go {
        ($x:expr) => {
            walk(cx, f, id, $x, depth + 1, seen)
        };
    }
    match f.expressions[h] {
        E::Literal(_) | E::Constant(_) | E::ZeroValue(_) => cx
            .sound()
            .num(id, h)
            .is_some_and(|n| n.comps().iter().all(|c| c.as_point() == Some(0.0))),
        E::Load { pointer } => {
            if let Some(g) = super::parameters::vertex_private(cx, f, pointer) {
                return (seen.zero)(g);
            }
            // A local that reads itself (`t = t - dot(t, n) * n`): its other stores decide.
            if seen.locals.contains(&(id, pointer)) {
                return true;
            }
            seen.locals.push((id, pointer));
            let stored = cx.stored(f, id, pointer);
            !stored.is_empty() && stored.into_iter().all(|x| go!(x))
        }
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } => go!(left) || go!(right),
        E::Binary {
            op: Bo::Add | Bo::Subtract,
            left,
            right,
        } => go!(left) && go!(right),
        E::Binary {
            op: Bo::Divide,
            left,
            ..
        } => go!(left),
        E::Unary { expr, .. } => go!(expr),
        E::AccessIndex { base: x, .. }
        | E::Swizzle { vector: x, .. }
        | E::Splat { value: x, .. }
        | E::As { expr: x, .. } => go!(x),
        E::Compose { ref components, .. } => components.iter().all(|&c| go!(c)),
        E::Select { accept, reject, .. } => go!(accept) && go!(reject),
        E::Math {
            fun: Mf::Mix,
            arg,
            arg1: Some(b),
            ..
        } => go!(arg) && go!(b),
        E::Math {
            fun: Mf::Normalize,
            arg,
            ..
        } => {
            // Without NaN, only a local normalised in place (`t = normalize(t)`), which its
            // other stores decide.
            let in_place = matches!(f.expressions[arg], E::Load { pointer }
                if seen.locals.contains(&(id, pointer)));
            (seen.nan || in_place) && go!(arg)
        }
        E::Math {
            fun: Mf::Cross | Mf::Dot,
            arg,
            arg1: Some(b),
            ..
        } => go!(arg) || go!(b),
        E::FunctionArgument(i) if id < cx.module.functions.len() => {
            let calls = cx.flows().callers(id);
            !calls.is_empty()
                && calls.iter().all(|(caller, args)| {
                    let g = crate::analysis::function(cx.module, *caller);
                    args.get(i as usize)
                        .is_some_and(|&a| walk(cx, g, *caller, a, depth + 1, seen))
                })
        }
        _ => false,
    }
}
