//! `normalize-zero`: `normalize(v)` of a vector that can be zero for ordinary parameters.

use essl::diagnostic::Diagnostic;
use essl::source::Span;
use naga::{BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf};

use super::rule::declare_rule;
use super::Cx;
use crate::interval::Interval;
use crate::symbolic::resolve;
use crate::value::Facts;
use crate::Level;

mod callers;
mod centre;
use callers::{caller_cross, caller_difference, caller_vector};
pub(super) use centre::centre_length;

declare_rule! {
    /// ## What it does
    /// Reports `normalize(v)` where `v` can be the zero vector even though every uniform and input is
    /// a valid (non-zero) vector and every matrix invertible:
    ///
    /// - a cross product, which vanishes when its two vectors are parallel
    ///   (`normalize(cross(spotLightEx.up, spotLight.direction))` for a spot light pointing straight
    ///   up or down; `cross(normal, vec3(0.0, 1.0, 0.0))` on a floor);
    /// - a sum or difference computed from uniforms and constants only — the same for every pixel of
    ///   a draw, such as `normalize(u_target - u_eye)` or `normalize(u_a + u_b)`;
    /// - an image's gradient: a vector each of whose components is a weighted sum of reads of one
    ///   channel of one texture with weights that sum to 0 (a Sobel or central difference,
    ///   `vec2(r - l, t - b)`), the zero vector wherever the image is flat.
    ///
    /// And, as a note, `normalize` in a vertex shader of an attribute that holds a direction — a
    /// normal, a tangent, a particle's direction — as such or through a transform
    /// (`normalize(normalMatrix * normal)`, three.js's `normalize(transformedNormal)`): the host's
    /// vertex data holds the zero vector for a degenerate triangle's computed normal, or where the
    /// mesh lacks the buffer (read as 0). A row vector through the inverse model matrix
    /// (`(vec4(normal, 0.0) * inverseModel).xyz`, the inverse transpose) counts as such a
    /// transform, and so does whatever is the zero vector wherever the attribute is — a
    /// Gram–Schmidt step `T - dot(T, N) * N`, a cross product with another direction, offsets
    /// from the normal by factors of the position (Babylon's fur, `(n.y, -n.x, 0) * J + (-n.z, 0,
    /// n.x) * K`), whatever the other attributes hold — but not a vector decoded from the
    /// attribute's components (an octahedral encoding's `vec3(e, 1.0 - abs(e.x) - abs(e.y))`,
    /// never zero), and, where other attributes take part, not the NaN of a normalised
    /// direction carried on (reported where it is normalised).
    ///
    /// And, as a note, `normalize` of a difference of two vertex attributes, or of a function's
    /// parameters where its callers pass inputs as such, or of a product with one: a line
    /// renderer's segment direction `normalize((b - a) * scale)`, lygia's `lookAt(eye, target)`
    /// normalizing `target - eye` — the zero vector where the data repeats a point or a caller
    /// passes the same point twice. The same for a vector parameter as such where the callers
    /// pass inputs as such: lygia's `rotate3d(a, r)` normalizing its axis `a`, `lookAt(forward)`
    /// — a library function that leaves the zero vector (a cross product of parallel vectors,
    /// an eye at its target) to its caller; and for a cross product of two such parameters,
    /// lygia's Ward specular `normalize(cross(N, fiber))` and `tbn(n, up)`'s
    /// `normalize(cross(up, n))`, the zero vector where a caller passes them parallel (but not
    /// two that name a mesh's frame, a normal and a tangent).
    ///
    /// And `normalize` of a texel as such (`normalize(texture(gNormal, uv).rgb)`), or of one
    /// through a matrix (`czm_normal * texel`): the zero vector for every black texel, the
    /// background a G-buffer is cleared to, or a per-instance vector a data texture holds as 0.
    /// A difference of a point and the point it was offset from (`(n * e + sw) - sw`) is the
    /// offset: Cesium's `length(southEastCorner - southWestCorner)` of a batch table's east
    /// vector.
    ///
    /// And `normalize` of what is left of a value outside a box, `p - clamp(p, lo, hi)` (times
    /// constants), where `p`'s ordinary values reach inside the bounds: the zero vector for every
    /// pixel or vertex whose `p` is inside — a whole region, such as the middle of a plane whose
    /// corners a vertex shader rounds (Babylon's `delta = 2.0 * (xy - clamp(xy, 0.0, 1.0))`
    /// divided by its length). Bounds from uniforms (`clamp(p, -u_size, u_size)`) are left out:
    /// the box is empty for a size of 0.
    ///
    /// And `normalize` in a fragment shader of a pixel's offset from a centre the
    /// host sets — a texture or screen coordinate (`v_uv`, `vTextureCoord * size`,
    /// `gl_FragCoord.xy`) minus a uniform named `center` or `centre` (scaled by uniforms), or a
    /// texture coordinate minus the middle `0.5` (a flipped one too), the offset scaled by
    /// uniforms or constants or widened with zeros (Cesium's lens flare normalises
    /// `vec3((vec2(0.5) - texcoord) * ghostDispersal, 0.0)`) — and a division by its length: a bulge's
    /// `uRadius / length(coord)`, a chromatic aberration's direction. A per-pixel difference is 0
    /// between pixel centres at most, but the usual centre, (0.5, 0.5), is exactly the middle
    /// pixel's coordinate on a target of odd size, which gets NaN every frame.
    ///
    /// Not reported: `normalize` of a uniform or a varying itself (`normalize(v_normal)`; the
    /// runtime check validates uniform values), of a decoded texel (`t.rgb * 2.0 - 1.0`, the
    /// zero vector only for the middle grey a normal map does not hold), and of per-pixel sums
    /// and differences such as `normalize(u_lightPos - v_position)` or a half vector
    /// `normalize(l + v)`: those vanish only at isolated points (the pixel that is at the
    /// light's position), not for a whole draw. A gradient with a constant component
    /// (`normalize(vec3(r - l, t - b, 1.0))`, a normal from a height map) is not zero.
    ///
    /// ## Why is this bad?
    /// `normalize(v)` is `v / length(v)`: for the zero vector it is `0 / 0`, NaN in every component.
    /// When the zero comes from the parameters — a spot light whose direction is parallel to its `up`
    /// vector — *every* pixel of the light is NaN: the projected texture's coordinates become NaN and
    /// the lookup returns garbage for the whole cone.
    ///
    /// ## Example
    /// ```glsl
    /// vec3 left = normalize(cross(spotLightEx.up, spotLight.direction));
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// vec3 d = spotLight.direction;
    /// vec3 c = cross(spotLightEx.up, d);
    /// // Parallel vectors: fall back to an axis the direction is far from.
    /// vec3 axis = abs(d.x) < 0.5 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    /// vec3 left = dot(c, c) > 1e-12 ? normalize(c) : normalize(cross(axis, d));
    /// ```
    /// There is no mechanical fix: the degenerate case needs a choice (a fallback axis, or no light).
    ///
    /// ## What it does not flag
    /// - `normalize` of a uniform or varying as such, of a transformed uniform, of an
    ///   attribute whose name does not say it holds a direction (`normalize(position)` of a globe's
    ///   vertex), of a constant non-zero vector, and of per-pixel sums and differences other
    ///   than a pixel's offset from a centre.
    /// - A cross product of vectors built perpendicular to each other (a camera frame), and of a vector
    ///   with an up axis chosen away from it: `up = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) :
    ///   vec3(1.0, 0.0, 0.0)` (each axis is used only where `n` is not along it).
    /// - A cross product of a per-pixel normal with a constant tilted off the coordinate axes
    ///   (`normalize(vec3(0.001, 1.0, 0.001))`): the tilt keeps it away from axis-aligned normals.
    /// - A vector with a sine and a cosine of one angle among its components (`vec3(sin(a), y,
    ///   cos(a))`): they are not both 0.
    /// - A vector a guard says is not zero (`dot(c, c) > 1e-12 ? normalize(c) : …`, `if (length(c) >
    ///   0.0)`).
    /// - Code essl does not lower: an inactive input read by dead code is no zero vector.
    ///
    /// Severity: a cross product with a vector fixed for the draw is a warning (a light pointing
    /// straight down is ordinary), as is a gradient (flat regions are in every picture) and a
    /// texel (black ones are), a value outside a box and a pixel's offset from a centre (the
    /// middle of the target is an ordinary centre); `normalize` of a per-draw difference is a note when one uniform
    /// alone reaches it, and of a direction attribute, a difference of attributes or parameters,
    /// or a parameter as such always.
    ///
    /// ## References
    /// - GLSL ES 3.00 specification, §8.4 Geometric Functions (normalize: "a vector in the same
    ///   direction as x but with a length of 1", undefined for a zero vector).
    /// - Article 003 (A-Frame projected-texture spot lights): `left = normalize(cross(up, direction))`.
    pub(crate) struct NormalizeZero {
        id: "normalize-zero",
        summary: "`normalize(v)` of a cross product, per-draw difference, image gradient, texel, direction attribute or pixel offset from a centre that can be the zero vector",
        default_level: Level::Warn,
        check: check,
    }
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for (id, f) in cx.functions() {
        for (h, e) in f.expressions.iter() {
            let E::Math {
                fun: Mf::Normalize,
                arg,
                ..
            } = *e
            else {
                continue;
            };
            if cx.span(f, h).is_empty() {
                continue;
            }
            let x = cx.operand(f, h, arg);
            out.extend(zero_vector(cx, f, id, h, x));
        }
    }
}

/// The finding for `normalize(x)` at `site` (the call, or for [`zero_length`] the division
/// by `length(x)`), where `x` can be the zero vector; `None` where it cannot, or is kept from
/// it.
fn zero_vector(
    cx: &Cx,
    f: &Function,
    id: usize,
    site: Handle<E>,
    x: Handle<E>,
) -> Option<Diagnostic> {
    let x = cancelled(cx, f, id, x);
    let at = Normalize {
        f,
        id,
        call: site,
        x,
    };
    let v = cx.sound().num(id, x)?;
    if v.n >= 2 && v.facts.has(Facts::NZ) {
        return attribute_direction(cx, at)
            .or_else(|| black_texel(cx, at))
            .or_else(|| caller_vector(cx, at));
    }
    if v.n < 2 || !v.may_be_zero() || v.facts.has(Facts::NZ) {
        return None;
    }
    // A per-pixel vector that is not a cross product or an image's gradient is left alone
    // (below): the guards refine intervals and keep where a value comes from, so they need
    // not be looked up.
    let gradient = !v.facts.any(Facts::CROSS)
        && v.facts.any(Facts::TEXTURE)
        && super::gradient::texel_gradient(cx, f, id, x);
    if !v.facts.any(Facts::CROSS) && v.facts.any(Facts::INPUT.with(Facts::TEXTURE)) && !gradient {
        return attribute_direction(cx, at)
            .or_else(|| caller_difference(cx, at))
            .or_else(|| caller_cross(cx, at))
            .or_else(|| black_texel(cx, at))
            .or_else(|| inside_box(cx, at))
            .or_else(|| centre::centre_pixel(cx, at));
    }
    // `dot(v, v) > 1e-12 ? normalize(v) : fallback`, `if (length(v) > 0.0)`.
    let v = cx.refined(f, id, x, &cx.guards(f, id, site))?;
    if !v.may_be_zero() || v.facts.has(Facts::NZ) {
        return None;
    }
    let cross = v.facts.any(Facts::CROSS);
    if cross
        && (orthogonal_cross(cx, f, id, x)
            || axis_chosen_away(cx, f, id, x)
            || tilted_axis(cx, f, id, x))
    {
        return None;
    }
    let per_draw = !v.facts.any(Facts::INPUT.with(Facts::TEXTURE));
    if !cross && !per_draw && !gradient {
        return None;
    }
    let what = cx.what(f, id, x);
    let label = if cross {
        format!("{what} is the zero vector when its two vectors are parallel")
    } else if gradient {
        format!("{what}, a difference of texels, is the zero vector wherever the image is flat")
    } else if v.facts.any(Facts::UNIFORM) {
        format!(
            "{what} is the zero vector for some values of the uniforms, for every pixel of the draw"
        )
    } else {
        format!("{what} is the zero vector")
    };
    let d = Diagnostic::rule_warning(
        NormalizeZero::RULE.id,
        "`normalize` of a vector that can be zero, which gives NaN",
        cx.span(f, x),
    )
    .with_label(label)
    .with_note(NORMALIZE_DIVIDES)
    .with_help("test the length first (`dot(v, v) > 1e-12`) and choose a fallback direction");
    Some(if cross || gradient {
        d
    } else {
        cx.grade(d, &[(id, x)])
    })
}

/// `p` for `(p + q) - q` or `(q + p) - q`, else `x`: the difference of a point and the point
/// it was offset from is the offset (Cesium's `eastWard = southEastCorner - southWestCorner`
/// of `southEastCorner = czm_normal * eastward + southWestCorner`), which the interval
/// arithmetic of the two points cannot tell.
fn cancelled(cx: &Cx, f: &Function, id: usize, x: Handle<E>) -> Handle<E> {
    let an = cx.sound();
    let resolve = |h| crate::symbolic::resolve(f, an, id, h);
    let E::Binary {
        op: Bo::Subtract,
        left,
        right,
    } = f.expressions[resolve(x)]
    else {
        return x;
    };
    let E::Binary {
        op: Bo::Add,
        left: p,
        right: q,
    } = f.expressions[resolve(left)]
    else {
        return x;
    };
    let same = |a: Handle<E>, b: Handle<E>| an.same(f, id, resolve(a), resolve(b));
    if same(q, right) {
        p
    } else if same(p, right) {
        q
    } else {
        x
    }
}

/// `v` for `M * v` of a matrix `M`, else `x`: a linear map of the zero vector is the zero
/// vector.
fn linear_operand(cx: &Cx, f: &Function, id: usize, x: Handle<E>) -> Handle<E> {
    let an = cx.sound();
    let E::Binary {
        op: Bo::Multiply,
        left,
        right,
    } = f.expressions[crate::symbolic::resolve(f, an, id, x)]
    else {
        return x;
    };
    if cx.is_matrix(id, left) {
        right
    } else {
        x
    }
}

/// The note every finding of `normalize` of a zero vector carries.
const NORMALIZE_DIVIDES: &str = "normalize(v) divides by length(v): 0 / 0 for the zero vector";

/// What [`zero_vector`] finds for `normalize(x)`, for a division `site` by `length(x)`: the
/// same zero vector makes the divisor 0 (`v / length(v)`, a normalisation by hand;
/// `d / length(planeNormal)`). Its label, notes (but the one on `normalize`) and severity, for
/// the division's finding to carry.
pub(super) fn zero_length(
    cx: &Cx,
    f: &Function,
    id: usize,
    site: Handle<E>,
    x: Handle<E>,
) -> Option<Diagnostic> {
    let mut d = zero_vector(cx, f, id, site, x)?;
    d.notes.retain(|n| n != NORMALIZE_DIVIDES);
    Some(d)
}

/// Whether `h` is `cross(a, b)` of non-zero vectors where every value `a` (or `b`) can hold is
/// itself a cross product with the other: perpendicular vectors, whose cross product is not
/// zero (`up = normalize(cross(right, forward)); right = normalize(cross(up, forward))`).
pub(crate) fn orthogonal_cross(cx: &Cx, f: &Function, id: usize, h: Handle<E>) -> bool {
    let Some((a, b)) = cross_operands(cx, f, id, h) else {
        return false;
    };
    let nz = |x: Handle<E>| {
        cx.sound()
            .num(id, x)
            .is_some_and(|n| n.facts.has(Facts::NZ))
    };
    if !nz(a) || !nz(b) {
        return false;
    }
    let perpendicular = |x: Handle<E>, y: Handle<E>| {
        values(cx, f, id, x).iter().all(|v| {
            let mut v = resolve(f, cx.sound(), id, *v);
            if let E::Math {
                fun: Mf::Normalize,
                arg,
                ..
            } = f.expressions[v]
            {
                v = resolve(f, cx.sound(), id, arg);
            }
            match f.expressions[v] {
                E::Math {
                    fun: Mf::Cross,
                    arg: p,
                    arg1: Some(q),
                    ..
                } => cx.sound().same(f, id, p, y) || cx.sound().same(f, id, q, y),
                _ => false,
            }
        })
    };
    perpendicular(a, b) || perpendicular(b, a)
}

/// The values `h` can be: every value the local it loads is given ([`Cx::stored`]: its
/// initializer and stores), or itself.
fn values(cx: &Cx, f: &Function, id: usize, h: Handle<E>) -> Vec<Handle<E>> {
    if let E::Load { pointer } = f.expressions[h] {
        let vs = cx.stored(f, id, pointer);
        if !vs.is_empty() {
            return vs;
        }
    }
    vec![h]
}

/// Whether `h` is `cross(u, n)` (either order) where `u` is one of two constant axes chosen by
/// a test of a component of `n`, each away from `n` where it is chosen: `up = abs(N.z) <
/// 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0)`. `n` is taken to be a direction (the
/// test of one component against a bound below 1 means nothing otherwise).
fn axis_chosen_away(cx: &Cx, f: &Function, id: usize, h: Handle<E>) -> bool {
    let Some((a, b)) = cross_operands(cx, f, id, h) else {
        return false;
    };
    [(a, b), (b, a)].into_iter().any(|(u, n)| {
        let E::Select {
            condition,
            accept,
            reject,
        } = f.expressions[resolve(f, cx.sound(), id, u)]
        else {
            return false;
        };
        [(accept, true), (reject, false)]
            .into_iter()
            .all(|(axis, polarity)| away(cx, f, id, n, axis, condition, polarity))
    })
}

/// Whether constant vector `axis` is not parallel to direction `n` wherever `condition` is
/// `polarity`: a comparison it implies bounds a component of `n` (or its magnitude) away from
/// what that component would be if `n` were along `axis`.
fn away(
    cx: &Cx,
    f: &Function,
    id: usize,
    n: Handle<E>,
    axis: Handle<E>,
    condition: Handle<E>,
    polarity: bool,
) -> bool {
    let Some(av) = cx.sound().num(id, axis) else {
        return false;
    };
    let a: Vec<f64> = av.comps().iter().filter_map(|c| c.as_point()).collect();
    let len = a.iter().map(|x| x * x).sum::<f64>().sqrt();
    if a.len() != av.n as usize || len == 0.0 {
        return false;
    }
    let mut proved = false;
    crate::analysis::condition_atoms(f, condition, polarity, &mut |atom, pol| {
        let E::Binary { op, left, right } = f.expressions[atom] else {
            return;
        };
        for (x, bound, x_left) in [(left, right, true), (right, left, false)] {
            let Some(b) = cx.sound().num(id, bound).and_then(|v| v.hull().as_point()) else {
                continue;
            };
            let Some(range) = crate::analysis::relation(op, pol, x_left, Interval::point(b)) else {
                continue;
            };
            let (inner, magnitude) = match f.expressions[x] {
                E::Math {
                    fun: Mf::Abs, arg, ..
                } => (arg, true),
                _ => (x, false),
            };
            let E::AccessIndex { base, index } = f.expressions[inner] else {
                continue;
            };
            if (index as usize) >= a.len() || !cx.sound().same(f, id, base, n) {
                continue;
            }
            // Along the axis, the unit vector's component is ±a[k] / |a|.
            let along = a[index as usize] / len;
            let values = if magnitude {
                vec![along.abs()]
            } else {
                vec![along, -along]
            };
            if values.iter().all(|v| !range.contains(*v)) {
                proved = true;
            }
        }
    });
    proved
}

/// Whether `h` is `cross(n, up)` (either order) of a per-pixel vector and a constant tilted off
/// the coordinate axes (`normalize(vec3(0.001, 1.0, 0.001))`): the tilt is the guard, since
/// mesh normals lie along the axes (a floor), not along an arbitrary constant direction.
fn tilted_axis(cx: &Cx, f: &Function, id: usize, h: Handle<E>) -> bool {
    let Some((a, b)) = cross_operands(cx, f, id, h) else {
        return false;
    };
    let per_pixel = |x: Handle<E>| {
        cx.sound()
            .num(id, x)
            .is_some_and(|v| v.facts.any(Facts::INPUT.with(Facts::TEXTURE)))
    };
    let tilted = |x: Handle<E>| {
        cx.sound().num(id, x).is_some_and(|v| {
            let off_zero = v.comps().iter().filter(|c| !c.contains(0.0)).count();
            v.comps()
                .iter()
                .all(|c| c.hi - c.lo <= 1e-6 * c.mag().max(1.0))
                && off_zero >= 2
        })
    };
    (per_pixel(a) && tilted(b)) || (per_pixel(b) && tilted(a))
}

/// The two vectors of `cross(a, b)` when `h` is (or a local holds) a cross product.
fn cross_operands(
    cx: &Cx,
    f: &Function,
    id: usize,
    h: Handle<E>,
) -> Option<(Handle<E>, Handle<E>)> {
    match f.expressions[resolve(f, cx.sound(), id, h)] {
        E::Math {
            fun: Mf::Cross,
            arg,
            arg1: Some(b),
            ..
        } => Some((arg, b)),
        _ => None,
    }
}

/// Words of an attribute's name that say it holds a direction: a normal, a tangent.
const DIRECTION: &[&str] = &[
    "normal",
    "normals",
    "nor",
    "nrm",
    "tangent",
    "tangents",
    "bitangent",
    "binormal",
    "direction",
    "dir",
];

/// Why a direction attribute may be the zero vector, the note of the findings that need it.
pub(super) const ZERO_DIRECTION: &str = "attributes are the host's vertex data: a degenerate triangle's normal, or a buffer the mesh lacks (read as 0), is the zero vector";

/// The attributes, in backticks, of a vertex shader's value `x` built from attributes that
/// hold a direction (a normal, a tangent) alone, with uniforms and constants, and that is the
/// zero vector wherever they are ([`super::vanishing`]); `None` for anything else (a
/// position, a texel, an octahedral decoding, another stage).
pub(super) fn direction_attributes(
    cx: &Cx,
    f: &Function,
    id: usize,
    x: Handle<E>,
) -> Option<String> {
    if cx.module.entry_points.first()?.stage != naga::ShaderStage::Vertex {
        return None;
    }
    let o = cx.origin(&[(id, x)]);
    let direction = |n: &str| crate::analysis::names::says_any(n, DIRECTION);
    if o.texels || o.unknown || !o.inputs.iter().any(|n| direction(n)) {
        return None;
    }
    // Zero where the direction attributes are, whatever the others (a position) hold; with
    // others, a `normalize` of them on the way is reported by itself.
    let zero = |g: Handle<naga::GlobalVariable>| {
        cx.module.global_variables[g]
            .name
            .as_deref()
            .is_some_and(direction)
    };
    let mixed = !o.inputs.iter().all(|n| direction(n));
    if !super::vanishing::with_attributes(cx, f, id, x, &zero, !mixed) {
        return None;
    }
    let list: Vec<String> = o
        .inputs
        .iter()
        .filter(|n| direction(n))
        .map(|n| format!("`{n}`"))
        .collect();
    Some(list.join(", "))
}

/// A `normalize` call: the function it is in (and that function's id), the call, and its
/// argument.
#[derive(Clone, Copy)]
struct Normalize<'a> {
    f: &'a Function,
    id: usize,
    call: Handle<E>,
    x: Handle<E>,
}

/// A note on `normalize` of a vector that the values `why` names can make the zero vector.
fn zero_vector_note(span: Span, message: String, label: String, why: &str) -> Diagnostic {
    Diagnostic::rule_note(NormalizeZero::RULE.id, message, span)
        .with_label(label)
        .with_note(NORMALIZE_DIVIDES)
        .with_note(why)
        .with_help("test the length first (`dot(v, v) > 1e-12`) and choose a fallback direction")
}

/// The note for `normalize(x)` in a vertex shader of a vector not zero unless an attribute that
/// holds a direction is (a normal through the normal matrix, `(M * vec4(tangent, 0.0)).xyz`):
/// a vertex whose normal is the zero vector — a degenerate triangle's, a buffer the mesh lacks —
/// gets NaN. `None` where the origin holds anything else (a position, a texel).
fn attribute_direction(cx: &Cx, n: Normalize) -> Option<Diagnostic> {
    let Normalize { f, id, call, x } = n;
    let list = direction_attributes(cx, f, id, x)?;
    let g = cx.guards(f, id, call);
    // The analysis takes an attribute as such to be non-zero: only a guard that rules out a
    // zero the unguarded value may be counts.
    let unguarded = cx.sound().num(id, x)?.may_be_zero();
    let guarded = cx.refined(f, id, x, &g).is_none_or(|v| !v.may_be_zero());
    if cx.nonzero(f, id, x, &g) || (unguarded && guarded) || length_guarded(cx, f, id, x, &g) {
        return None;
    }
    Some(zero_vector_note(
        cx.span(f, x),
        format!("`normalize` of the attribute {list}, which a vertex may hold as the zero vector"),
        format!(
            "{} is the zero vector for a vertex whose {list} is",
            cx.what(f, id, x)
        ),
        ZERO_DIRECTION,
    ))
}

/// Whether a guard bounds `length(x)` or `dot(x, x)` above 0 (`length(n) > 0.0 ? normalize(n)
/// : …`).
fn length_guarded(
    cx: &Cx,
    f: &Function,
    id: usize,
    x: Handle<E>,
    g: &super::guards::Guards,
) -> bool {
    let an = cx.sound();
    g.facts.iter().any(|&(h, ref r)| {
        let (crate::analysis::Refinement::Value(i) | crate::analysis::Refinement::Norm(i)) = r;
        if i.lo <= 0.0 {
            return false;
        }
        match f.expressions[resolve(f, an, id, h)] {
            E::Math {
                fun: Mf::Length,
                arg,
                ..
            } => an.same(f, id, arg, x),
            E::Math {
                fun: Mf::Dot,
                arg,
                arg1: Some(b),
                ..
            } => an.same(f, id, arg, x) && an.same(f, id, b, x),
            _ => an.same(f, id, h, x),
        }
    })
}

/// The finding for `normalize(x)` of a texel as such (`texture(gNormal, uv).rgb`,
/// `texelFetch(uNormalBuffer, p, 0).xyz`), whose ordinary values reach the zero vector: every
/// black texel, such as the background a G-buffer is cleared to.
fn black_texel(cx: &Cx, n: Normalize) -> Option<Diagnostic> {
    let Normalize { f, id, x: at, .. } = n;
    // A texel through a matrix (`czm_normal * texel`) is the zero vector wherever the texel
    // is.
    let x = linear_operand(cx, f, id, at);
    let v = cx.sound().num(id, x)?;
    // A texel as such: a uniform it depends on is in its coordinates (Cesium's batch table,
    // `texture(batchTexture, computeSt(batchId))`).
    if !v.facts.has(Facts::EXT) || !v.facts.any(Facts::TEXTURE) || v.facts.any(Facts::INPUT) {
        return None;
    }
    // Texels are in [0, 1] in the typical analysis: the zero vector is an end of the range.
    let t = cx.typical().num(id, x)?;
    if !t.comps().iter().all(|c| c.lo == 0.0) || !cx.origin(&[(id, x)]).texels {
        return None;
    }
    if kept_from_zero(cx, n, x) {
        return None;
    }
    Some(
        Diagnostic::rule_warning(
            NormalizeZero::RULE.id,
            "`normalize` of a texel, the zero vector wherever the texture is black",
            cx.span(f, at),
        )
        .with_label(format!(
            "{} is the zero vector for every black texel (a G-buffer's cleared background)",
            cx.what(f, id, at)
        ))
        .with_note(NORMALIZE_DIVIDES)
        .with_help("test the length first (`dot(v, v) > 1e-12`), or store normals encoded (`n * 0.5 + 0.5`)"),
    )
}

/// The finding for `normalize(x)` of what is left of a value outside a box,
/// `p - clamp(p, lo, hi)` ([`super::residual::clamp_residual`]): the zero vector for every
/// pixel or vertex whose `p` is inside.
fn inside_box(cx: &Cx, n: Normalize) -> Option<Diagnostic> {
    let Normalize { f, id, x, .. } = n;
    let clamp = super::residual::clamp_residual(cx, f, id, x)?;
    if kept_from_zero(cx, n, x) {
        return None;
    }
    let mut d = Diagnostic::rule_warning(
        NormalizeZero::RULE.id,
        "`normalize` of a value's distance outside a box, the zero vector everywhere inside it",
        cx.span(f, x),
    )
    .with_label(format!(
        "{} is the zero vector wherever the clamped value is inside the clamp's bounds",
        cx.what(f, id, x)
    ))
    .with_note(NORMALIZE_DIVIDES)
    .with_help("test the length first (`dot(v, v) > 1e-12`) and choose a fallback direction");
    let (span, whole) = (cx.span(f, clamp), cx.span(f, x));
    let inside = whole.start <= span.start && span.end <= whole.end;
    if !span.is_empty() && !inside {
        d = d.with_secondary(span, "equal to its argument inside the bounds");
    }
    Some(d)
}

/// Whether the guards at `normalize`'s call keep vector `x` from the zero vector: a test of
/// the vector or of its length (`dot(c, c) > 1e-12 ? normalize(c) : …`).
fn kept_from_zero(cx: &Cx, n: Normalize, x: Handle<E>) -> bool {
    let Normalize { f, id, call, .. } = n;
    let g = cx.guards(f, id, call);
    cx.nonzero(f, id, x, &g) || length_guarded(cx, f, id, x, &g)
}
