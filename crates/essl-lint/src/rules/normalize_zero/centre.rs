//! The warning for `normalize` of a pixel's offset from a centre the host sets: a bulge, a
//! zoom blur or a chromatic aberration around `uCenter` computes `vUv - uCenter` (or
//! `vTextureCoord * size - uCenter * size`) and normalises it, or divides by its length.
//!
//! A per-pixel difference is 0 at isolated pixels at most, which `normalize-zero` otherwise
//! leaves alone: a varying crosses a value between pixel centres. A centre is different: the
//! effect is placed on the picture, and its usual value is the middle of the target, (0.5, 0.5)
//! in texture coordinates, which lies exactly on the centre of the middle pixel of a target of
//! odd size (`(i + 0.5) / w == 0.5` for `i = (w - 1) / 2`). That pixel gets NaN (or ±∞ from a
//! division) every frame, and so does every pixel a click puts the centre on. The pixel
//! coordinate must be a fragment shader's varying named for a texture or screen coordinate
//! (`uv`, `st`, `coord`, `texcoord`) or `gl_FragCoord`, possibly scaled by uniforms; the centre
//! a uniform named `center` or `centre`, possibly scaled by uniforms; nothing else reaches
//! either. The offset may be scaled by values the same for every pixel and widened with zeros
//! (`vec3(offset * k, 0.0)`): still the zero vector on the centre. A warning: the centre's
//! ordinary value reaches the hazard.

use essl::diagnostic::{Diagnostic, Severity};
use naga::{BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf};

use super::super::Cx;
use super::{kept_from_zero, zero_vector_note, Normalize};
use crate::analysis::names;
use crate::symbolic::resolve;

/// Words naming a texture or screen coordinate.
const PIXEL_WORDS: &[&str] = &[
    "uv",
    "uvs",
    "st",
    "coord",
    "coords",
    "coordinate",
    "coordinates",
    "texcoord",
    "texcoords",
];
/// Words naming a centre.
const CENTRE_WORDS: &[&str] = &["center", "centre"];

/// The warning for `normalize(x)` of a fragment's coordinate minus a centre uniform (see the
/// module's documentation).
pub(super) fn centre_pixel(cx: &Cx, n: Normalize) -> Option<Diagnostic> {
    let Normalize { f, id, x, .. } = n;
    if cx.module.entry_points.first()?.stage != naga::ShaderStage::Fragment {
        return None;
    }
    let centre = centre_offset(cx, f, id, x, names_centre(cx.module))?;
    if kept_from_zero(cx, n, x) {
        return None;
    }
    let mut d = zero_vector_note(
        cx.span(f, x),
        format!("`normalize` of a pixel's offset from the centre `{centre}`, the zero vector at the pixel on the centre"),
        format!(
            "{} is the zero vector at the pixel whose coordinate is `{centre}`",
            cx.what(f, id, x)
        ),
        "a centre in the middle of the target, (0.5, 0.5), is exactly the middle pixel's coordinate on a target of odd size: that pixel gets NaN every frame",
    );
    d.severity = Severity::Warning;
    Some(d)
}

/// The centre uniform's name where `x` is a pixel's coordinate minus it (either order), such
/// a difference scaled by per-draw values (`(vec2(0.5) - uv) * ghostDispersal`), or a vector
/// made of such differences component by component, constant zeros aside
/// (`vec2(vUV.x - center.x, vUV.y - center.y)`, `vec3(offset, 0.0)`).
/// `named`: whether the module has a uniform named as a centre (otherwise only `0.5` can be
/// one, and the walks to the uniforms are skipped).
fn centre_offset(cx: &Cx, f: &Function, id: usize, x: Handle<E>, named: bool) -> Option<String> {
    match f.expressions[resolve(f, cx.sound(), id, x)] {
        E::Binary {
            op: Bo::Subtract,
            left,
            right,
        } => {
            centre_of(cx, id, left, right, named).or_else(|| centre_of(cx, id, right, left, named))
        }
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } => {
            // Uniforms and constants: the same for every pixel.
            let per_draw = |h: Handle<E>| {
                cx.sound().num(id, h).is_some_and(|n| {
                    !n.facts
                        .any(crate::value::Facts::INPUT.with(crate::value::Facts::TEXTURE))
                })
            };
            if per_draw(right) {
                centre_offset(cx, f, id, left, named)
            } else if per_draw(left) {
                centre_offset(cx, f, id, right, named)
            } else {
                None
            }
        }
        E::Compose { ref components, .. } if components.len() >= 2 => {
            let zero = |h: Handle<E>| {
                cx.sound()
                    .num(id, h)
                    .is_some_and(|n| n.comps().iter().all(|c| c.as_point() == Some(0.0)))
            };
            let parts: Vec<Handle<E>> = components.iter().copied().filter(|&c| !zero(c)).collect();
            // Every component of one vector, in order: `vec3(offset, 0.0)` holds
            // `offset.x, offset.y, 0.0`.
            let whole = parts.first().and_then(|&c| match f.expressions[c] {
                E::AccessIndex { base, index: 0 } => Some(base),
                _ => None,
            });
            if let Some(base) = whole {
                let size = cx.sound().num(id, base).map_or(0, |n| n.n as usize);
                let every = size == parts.len()
                    && parts.iter().enumerate().all(|(k, &c)| {
                        matches!(f.expressions[c], E::AccessIndex { base: b, index }
                            if b == base && index as usize == k)
                    });
                if every {
                    return centre_offset(cx, f, id, base, named);
                }
            }
            let names: Option<Vec<String>> = parts
                .iter()
                .map(|&c| centre_offset(cx, f, id, c, named))
                .collect();
            names?.into_iter().next()
        }
        _ => None,
    }
}

/// Whether a uniform of `module` (a block's member too) is named as a centre.
fn names_centre(module: &naga::Module) -> bool {
    module.global_variables.iter().any(|(_, g)| {
        if !matches!(
            g.space,
            naga::AddressSpace::Uniform | naga::AddressSpace::Handle
        ) {
            return false;
        }
        let member = match &module.types[g.ty].inner {
            naga::TypeInner::Struct { members, .. } => members.iter().any(|m| {
                m.name
                    .as_deref()
                    .is_some_and(|n| names::says_any(n, CENTRE_WORDS))
            }),
            _ => false,
        };
        member
            || g.name
                .as_deref()
                .is_some_and(|n| names::says_any(n, CENTRE_WORDS))
    })
}

/// The centre uniform's name where `pixel` is a fragment's coordinate (scaled by uniforms at
/// most) and `centre` a centre uniform (scaled by uniforms at most).
fn centre_of(
    cx: &Cx,
    id: usize,
    pixel: Handle<E>,
    centre: Handle<E>,
    named: bool,
) -> Option<String> {
    let middle = cx
        .sound()
        .num(id, centre)
        .is_some_and(|n| n.comps().iter().all(|i| i.as_point() == Some(0.5)));
    if !named && !middle {
        return None;
    }
    let p = cx.origin(&[(id, pixel)]);
    let c = cx.origin(&[(id, centre)]);
    if p.unknown || c.unknown || p.texels || c.texels || !c.inputs.is_empty() {
        return None;
    }
    let coordinate = |name: &String| name == "gl_FragCoord" || names::says_any(name, PIXEL_WORDS);
    if p.inputs.is_empty() || !p.inputs.iter().all(coordinate) {
        return None;
    }
    if middle && c.uniforms.is_empty() && !p.inputs.iter().any(|n| n == "gl_FragCoord") {
        return Some("0.5".to_string());
    }
    c.uniforms
        .iter()
        .find(|u| names::says_any(u, CENTRE_WORDS))
        .map(|u| match u.rsplit_once('.') {
            Some((base, part)) if part.chars().all(|c| "xyzwrgba".contains(c)) => base.to_string(),
            _ => u.clone(),
        })
}

/// The centre uniform's name where `h` is the length of a pixel's offset from it: `length(c)`,
/// `distance(p, centre)`, `sqrt(dot(c, c))` or `sqrt(c.x * c.x + c.y * c.y)` — 0 at the pixel
/// on the centre (`pow(radius, u_k)` there is `pow(0.0, u_k)`).
pub(crate) fn centre_length(cx: &Cx, f: &Function, id: usize, h: Handle<E>) -> Option<String> {
    // A vertex's coordinate on the centre is one vertex, not a pixel every frame.
    if cx.module.entry_points.first()?.stage != naga::ShaderStage::Fragment {
        return None;
    }
    let named = names_centre(cx.module);
    let an = cx.sound();
    match f.expressions[resolve(f, an, id, h)] {
        E::Math {
            fun: Mf::Length,
            arg,
            ..
        } => centre_offset(cx, f, id, arg, named),
        E::Math {
            fun: Mf::Distance,
            arg,
            arg1: Some(b),
            ..
        } => centre_of(cx, id, arg, b, named).or_else(|| centre_of(cx, id, b, arg, named)),
        E::Math {
            fun: Mf::Sqrt, arg, ..
        } => match f.expressions[resolve(f, an, id, arg)] {
            E::Math {
                fun: Mf::Dot,
                arg: a,
                arg1: Some(b),
                ..
            } if an.same(f, id, a, b) => centre_offset(cx, f, id, a, named),
            E::Binary {
                op: Bo::Add,
                left,
                right,
            } => {
                let v = square_of_component(cx, f, id, left, 0)?;
                let w = square_of_component(cx, f, id, right, 1)?;
                an.same(f, id, v, w)
                    .then(|| centre_offset(cx, f, id, v, named))
                    .flatten()
            }
            _ => None,
        },
        _ => None,
    }
}

/// The vector `v` where `h` is `v[k] * v[k]`.
fn square_of_component(
    cx: &Cx,
    f: &Function,
    id: usize,
    h: Handle<E>,
    k: u32,
) -> Option<Handle<E>> {
    let an = cx.sound();
    let E::Binary {
        op: Bo::Multiply,
        left,
        right,
    } = f.expressions[resolve(f, an, id, h)]
    else {
        return None;
    };
    let component = |x: Handle<E>| match f.expressions[x] {
        E::AccessIndex { base, index } if index == k => Some(base),
        _ => None,
    };
    let (a, b) = (component(left)?, component(right)?);
    an.same(f, id, a, b).then_some(a)
}
