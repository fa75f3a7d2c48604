//! `domain-atan2`: `atan(y, x)` whose arguments can both be 0 for ordinary inputs.

use essl::diagnostic::Diagnostic;
use naga::{Expression as E, Function, Handle, MathFunction as Mf};

use super::guards::Guards;
use super::parameters::caller_value;
use super::rule::declare_rule;
use super::Cx;
use crate::analysis::Refinement;
use crate::value::Facts;
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports `atan(y, x)` where `y` and `x` can both be 0 for ordinary inputs:
    ///
    /// - two components of one texel or of a vector computed from texels, uniforms and constants
    ///   only (`atan(n.y, n.x)` of a normal-map texel, unpacked, normalised or turned by a
    ///   uniform matrix, wherever the texture is read): both are 0 wherever the texel lies along
    ///   the third axis — every flat part of a normal map; the same for a vector computed from a
    ///   colour (`atan(lab.z, lab.y)` of a texel's Lab form: both 0 for every black texel);
    /// - two components of a normal: an input whose name says it holds one (`v_normal`, a
    ///   function's `vec3 normal` its callers pass an input to), alone, normalised or turned by a
    ///   uniform matrix, is the same over every flat face, and lies along the third axis on every
    ///   face that faces that way;
    /// - values that are 0 over a region (a clamp saturating at 0, a texel) or for a whole draw
    ///   (uniforms and constants).
    ///
    /// ## Why is this bad?
    /// GLSL ES 3.00 leaves `atan(y, x)` undefined when `x` and `y` are both 0 (§8.1). Drivers return
    /// 0, π, or NaN; the azimuth of a normal-map texel is then arbitrary or NaN on every flat part
    /// of the map (a texel pointing straight along z), and what the angle drives — an anisotropy
    /// direction, a rotated or equirectangular lookup — goes wrong over whole regions.
    ///
    /// ## Example
    /// ```glsl
    /// vec3 n = texture(u_normalMap, v_uv).xyz * 2.0 - 1.0;
    /// float phi = atan(n.y, n.x);
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float phi = (abs(n.x) + abs(n.y) > 1e-6) ? atan(n.y, n.x) : 0.0;
    /// ```
    /// There is no mechanical fix: the angle of the zero vector needs a choice.
    ///
    /// ## What it does not flag
    /// - A point in the plane crossing the origin only at isolated pixels:
    ///   `atan(uv.y - 0.5, uv.x - 0.5)` is undefined at one pixel centre at most; and a direction
    ///   that varies per pixel (`atan(dir.z, dir.x)` of a view ray, a normalised position in an
    ///   equirectangular lookup, a normal-map texel turned by an interpolated tangent frame),
    ///   which passes the axis at isolated pixels (the pole, where every column is the same
    ///   point anyway).
    /// - Two components of a direction in the plane (`atan(d.y, d.x)` of a normalised `vec2`), which
    ///   cannot both be 0; arguments a guard keeps apart from 0 (`if (abs(x) > 0.0)`), or from
    ///   being both 0 (`abs(y) + abs(x) > 1e-6`, the fix above).
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard; a note, naming
    /// the uniform, when one uniform alone (with constants) does. A note, naming them, where `y`
    /// and `x` are built from a function's parameters alone and its callers pass inputs as such
    /// (or from a vertex shader's attributes): both 0 wherever a caller passes a point at the
    /// centre it measures the angle around (`atan(uv.y, uv.x)` of `uv = coord - center`).
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.1 Angle and Trigonometry Functions: atan(y, x) "Results
    ///   are undefined if x and y are both 0."
    pub(crate) struct DomainAtan2 {
        id: "domain-atan2",
        summary: "`atan(y, x)` whose arguments can both be 0 for ordinary inputs",
        default_level: Level::Warn,
        check: check,
    }
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for c in cx.math_calls(Mf::Atan2) {
        let (id, f, h, span) = (c.id, c.f, c.call, c.span);
        let [y, x] = c.args[..] else {
            continue;
        };
        let g = cx.guards(f, id, h);
        let zero = |v: Handle<E>| {
            cx.refined(f, id, v, &g).is_some_and(|n| {
                n.comps().iter().any(|c| c.contains(0.0))
                    && !n.facts.has(Facts::NZ)
                    && !cx.nonzero(f, id, v, &g)
            })
        };
        if apart(cx, f, id, y, x, &g) {
            continue;
        }
        if !zero(y) || !zero(x) {
            // The analysis takes an input as such to be non-zero: what callers pass is asked
            // about without that.
            if !cx.kept_from_zero(f, id, y, &g) && !cx.kept_from_zero(f, id, x, &g) {
                out.extend(from_callers(cx, f, id, span, y, x));
            }
            continue;
        }
        let axis = components_of_direction(cx, f, id, y, x);
        if !(axis || cx.flat_at(f, id, y, 0.0) && cx.flat_at(f, id, x, 0.0)) {
            out.extend(from_callers(cx, f, id, span, y, x));
            continue;
        }
        let label = if axis {
            "both are components of one vector: 0 wherever it lies along the third axis"
        } else {
            "both can be 0 over a whole region, or for the whole draw"
        };
        let d = Diagnostic::rule_warning(
            DomainAtan2::RULE.id,
            "`atan(y, x)` with `y` and `x` both 0 for ordinary inputs, where `atan` is undefined",
            span,
        )
        .with_label(label)
        .with_secondary(cx.span(f, y), "y")
        .with_secondary(cx.span(f, x), "x")
        .with_note("GLSL ES 3.00 §8.1: atan(y, x) is undefined if x and y are both 0")
        .with_help("choose the angle of the zero vector: test `abs(x) + abs(y) > 1e-6` first");
        out.push(cx.grade(d, &[(id, y), (id, x)]));
    }
}

/// The note for `y` and `x` built from a function's parameters alone, where its callers pass
/// inputs as such, or from a vertex shader's attributes ([`caller_value`]): `atan(y, x)` of a
/// vector a caller may pass as the zero vector.
fn from_callers(
    cx: &Cx,
    f: &Function,
    id: usize,
    span: essl::source::Span,
    y: Handle<E>,
    x: Handle<E>,
) -> Option<Diagnostic> {
    let both = caller_value(cx, f, id, y)?.and(caller_value(cx, f, id, x)?)?;
    Some(
        Diagnostic::rule_note(
            DomainAtan2::RULE.id,
            format!(
                "`atan(y, x)` of {}, both 0 for some of their values, where `atan` is undefined",
                both.list()
            ),
            span,
        )
        .with_label(format!(
            "`y` and `x` are both 0 for some values of {}",
            both.list()
        ))
        .with_secondary(cx.span(f, y), "y")
        .with_secondary(cx.span(f, x), "x")
        .with_note("GLSL ES 3.00 §8.1: atan(y, x) is undefined if x and y are both 0")
        .with_note(both.why())
        .with_help("choose the angle of the zero vector: test `abs(x) + abs(y) > 1e-6` first"),
    )
}

/// Whether a guard keeps `y` and `x` from being both 0: `abs(y) + abs(x)` (either order)
/// compared so that it is positive where the `atan` runs.
fn apart(cx: &Cx, f: &Function, id: usize, y: Handle<E>, x: Handle<E>, g: &Guards) -> bool {
    let an = cx.sound();
    let abs_of = |h: Handle<E>| match f.expressions[h] {
        E::Math {
            fun: Mf::Abs, arg, ..
        } => Some(arg),
        _ => None,
    };
    g.facts.iter().any(|(h, r)| {
        let positive = match r {
            Refinement::Value(i) | Refinement::Norm(i) => i.lo > 0.0,
        };
        if !positive {
            return false;
        }
        let E::Binary {
            op: naga::BinaryOperator::Add,
            left,
            right,
        } = f.expressions[*h]
        else {
            return false;
        };
        let (Some(a), Some(b)) = (abs_of(left), abs_of(right)) else {
            return false;
        };
        (an.same(f, id, a, y) && an.same(f, id, b, x))
            || (an.same(f, id, a, x) && an.same(f, id, b, y))
    })
}

/// Whether `y` and `x` are two components of one texel of three or more components (a
/// normal-map texel): both 0 wherever it lies along the third axis, a flat region.
fn components_of_direction(cx: &Cx, f: &Function, id: usize, y: Handle<E>, x: Handle<E>) -> bool {
    // `t.y` of a vector value, or of a local written once (`vec3 nm = …; nm.y`): the vector's
    // value and the component.
    let an = cx.sound();
    let part = |h: Handle<E>| match f.expressions[h] {
        E::AccessIndex { base, index } => Some((crate::symbolic::resolve(f, an, id, base), index)),
        E::Load { pointer } => match f.expressions[pointer] {
            E::AccessIndex { base, index } => match f.expressions[base] {
                E::LocalVariable(l) => an.functions[id]
                    .single_store
                    .get(&l.index())
                    .map(|v| (crate::symbolic::resolve(f, an, id, *v), index)),
                _ => None,
            },
            _ => None,
        },
        _ => None,
    };
    let (Some((by, iy)), Some((bx, ix))) = (part(y), part(x)) else {
        return false;
    };
    if iy == ix || !cx.sound().same(f, id, by, bx) {
        return false;
    }
    let Some(v) = cx.sound().num(id, by) else {
        return false;
    };
    // A texel (a normal map, read at coordinates from an input or not) or a normal is the same
    // direction over a whole flat region; a direction that also varies per pixel through
    // something else (a view ray, a normal map turned by an interpolated tangent frame, a
    // position) passes the axis at isolated points.
    v.n >= 3 && v.facts.any(Facts::TEXTURE) && !v.facts.any(Facts::INPUT)
}
