//! `division-by-difference`: `x / (a - b)` where `a` and `b` are uniforms that may be equal, or
//! texels whose difference is 0 at an end of their range; and `x / t` of a texel `t` whose range
//! ends at 0.

use essl::diagnostic::{Diagnostic, Fix};
use naga::{BinaryOperator as Bo, Expression as E, ScalarKind};

use super::clip_space::{self, Clip};
use super::derivatives;
use super::normalize_zero;
use super::parameters::caller_value;
use super::rule::declare_rule;
use super::settings::{grid_step, settings_of};
use super::Cx;
use crate::symbolic::resolve;
use crate::value::{Facts, Num};
use crate::Level;

declare_rule! {
    /// ## What it does
    /// Reports a division whose divisor is a difference of per-draw values (uniforms and constants)
    /// that nothing in the shader keeps away from zero: `(d - u_outerLimit) / (u_innerLimit - u_outerLimit)`, or the
    /// same through a local (`float limitRange = u_innerLimit - u_outerLimit; … / limitRange`). A
    /// divisor the shader guards (`max(limitRange, 1e-4)`) or can order itself (`u_r + 0.1 - u_r`) is
    /// not reported. A difference of texel values is reported where it is 0 at an end of the texels'
    /// range: `1.0 - k` for `k = min(1.0 - c.r, min(1.0 - c.g, 1.0 - c.b))` of a texel's colour `c`
    /// is 0 for every black texel, `1.0 - c.a` for every opaque one, and so is a sum with a
    /// negative constant (FSR's `4.0 * mn + peakC.y`, `peakC.y == -4.0`, wherever it is
    /// white), and one whose end is 0 to within a `float`'s rounding: `1.0 - Y` of a luminance
    /// `Y = dot(c, vec3(0.299, 0.587, 0.114))`, whose weights sum to 1 − 1.3e-8 as `float`s, is 0
    /// or 6e-8 for a white texel, and an epsilon added before the subtraction
    /// (`1e-10 + 1.0 - Y`) folds into the 1.0. An input whose name says it holds a colour (`v_color`, a function's `vec3 rgb` its callers pass an input to) counts as
    /// a texel: black and white are ordinary colours. A divisor that is a texel (or such a colour)
    /// itself is reported too: `c.rgb / c.a` un-premultiplies by an alpha that is 0 wherever the
    /// texture is transparent, `x / t.r` divides by 0 wherever it is black; and so is a sum,
    /// product, `dot`, matrix product, `max` or `min` of texels (through locals and calls;
    /// FSR's `1.0 / (4.0 * mx)` of the largest of a pixel's neighbours): a luminance
    /// `dot(c.rgb, w)` a tone mapping divides by, the `X + Y + Z` of a colour's chromaticity, 0
    /// over every black region of the picture. So is a shading term
    /// that is 0 wherever the surface faces away from the light or the viewer: a product with a
    /// clamped cosine (`max(dot(n, l), 0.0)`, `saturate(dot(n, v))`), or a sum, difference or
    /// `mix` of such products — Cook–Torrance's `4.0 * NdotL * NdotV`, Neubelt's sheen
    /// `4.0 * (dotNL + dotNV - dotNL * dotNV)`, Smith–GGX's `lambdaV + lambdaL`. A parameter named
    /// for such a cosine (`NoL`, `NdotV`, `dotNL`) counts as one where a call passes it an input
    /// as such, as a library function's harness does. And, as a note naming it, a uniform as such
    /// whose name says it holds a setting a user may set to 0 — a count, a length, a radius, a
    /// gamma, a fade, a near or far distance, a soft edge's width, a tone mapping's white point,
    /// a fraction, a stroke's or a filter's size (`1.0 / uGamma`,
    /// `1.0 / float(directionCount)`, `d / uRadius`, `d / Proximity_Far_Distance`,
    /// `match / feather`, `x / uWavelength`, `color / white`, `x / Glow_Fraction`,
    /// `d / strokeSize`, a Gaussian's `2.0 * sigma * sigma` for `sigma = float(filterSize)`),
    /// or whatever its name the step of a grid the quotient snaps to (a pixelation's
    /// `floor(coord / uSize) * uSize`; not `mod`), a multiple of
    /// one (`lengthCap * sqrt(-z)`, through locals and calls), or a blend of several, 0 for
    /// the whole draw once each is whatever the weights (`mix(fadeA, fadeB, c.g)`,
    /// `(w.y - w.x) * k + w.x`, through `out` parameters too) — but not a size,
    /// resolution, ratio or distance the host computes from the canvas or the camera, nor a count
    /// of the vertices drawn. Also as a note, naming them, a function's division by its own
    /// parameters where its callers pass inputs as such — a library function whose guard is
    /// left to the caller: lygia's `gaussian(d, s)` dividing by `2.0 * s * s` (a blur of sigma
    /// 0), an attenuation by `pow(dist, 2.0)` and an ellipsoid's distance by
    /// `length(p / (r * r))` (0 where the power's base or the quotient's dividend is),
    /// `map(v, iMin, iMax)` by `iMax - iMin` (a collapsed range), `perspective` by
    /// `near - far`, `0.5 / (res - 1.0)` (a texture one texel wide). The same, as a note, for a
    /// vertex shader's division by its attributes as such: a particle's `age / a_life`, a
    /// skinning weight's `1.0 / (w.x + w.y + w.z + w.w)`, a point's `0.5 / a_size` (an
    /// attribute's size or ratio is the vertex data's, not the canvas's), the last of four
    /// values packed in an attribute that is no position (MapLibre's `dasharray_from.w`, a
    /// dash pattern's length, 0 for a dash array `[0, 0]`), through a function
    /// that unpacks them, the outputs the shader keeps them in, a product with a uniform and a
    /// function's parameter every call passes such a value (MapLibre's
    /// `floorwidth = unpack_mix_vec2(a_floorwidth, t)`, `/ pixel_ratio_from` of a pattern
    /// missing from the atlas, regl-scatter2d's `1.0 / gl_PointSize` of a point of size 0) —
    /// values of the host's vertex data, 0 for a vertex that holds 0. And the length of a normal or tangent attribute through a
    /// transform (`r / length((world * vec4(cross(normal, tangent), 0.0)).xyz)`), 0 for a
    /// vertex of a mesh without the buffer (read as the zero vector); more generally, the length
    /// (or its square, `dot(x, x)`; a multiple of either, or what a function returns that is
    /// one: lygia's `area(tri)`) of any vector `normalize-zero` reports `normalize` of
    /// (`d / length(d)`, a normalisation
    /// by hand; `t / length(b - a)` of an edge of a triangle a caller passes, 0 for a degenerate
    /// one; `delta / length(delta)` of `delta = xy - clamp(xy, 0.0, 1.0)`, 0 for every `xy`
    /// inside the bounds; `uRadius / length(coord)` of a pixel's offset from a centre uniform,
    /// 0 at the pixel on the centre), at that rule's severity. And, as a note, a vertex
    /// shader's perspective divide by the `w` of `gl_Position` or of a product with a projection
    /// matrix (`p.xy / p.w`, through locals, calls and parameters): the vertex shader runs before
    /// clipping, so a vertex on the camera's plane (a line or triangle crossing it) has `w = 0`
    /// and one behind the camera a negative `w`; likewise, in a fragment shader, a position
    /// projected by another frame's camera (`prevViewProjection`, a reprojection). And a divisor
    /// that is 0 whatever the inputs: `i / (m - 1.0)` for `m = float(LAYERS)` in the
    /// configuration where the flag `LAYERS` is 1, or, as a note, a constant division by zero in
    /// the configuration where a count the text defines under `#ifndef` is 1
    /// (`1.0 / float(RAYMARCH_AO_SAMPLES - 1)`: one sample, the fewest its loop can take).
    /// And a division by a derivative's width (`d / fwidth(d)`, a grid line's distance over
    /// `length(vec2(dFdx(x), dFdy(x)))`, through locals and parameters): 0 wherever the value
    /// differentiated is the same across the 2×2 pixel quad — the coordinate along a face's
    /// normal, a flat stretch of a distance field —, where the quotient is ±∞ on IEEE hardware
    /// (GLSL ES 3.00 does not require it) and NaN where the dividend is 0 too: a warning where the
    /// dividend is computed from inputs and can be 0 (Babylon's grid on a ground plane at
    /// `y = 0`), a note otherwise (a distance texture's `d / fwidth(d)`, ±∞ over its saturated
    /// stretches, which a clamp turns into the right coverage).
    ///
    /// ## Why is this bad?
    /// Two parameters a user sets independently are equal sooner or later — a spot light with the
    /// same inner and outer limit, a LearnOpenGL flashlight with `cutOff == outerCutOff`. Then the
    /// divisor is 0 and the quotient is ±∞, or NaN where the numerator is 0 too: the clamp after it
    /// turns ±∞ into a hard edge but lets NaN through as black or garbage pixels on the cone's
    /// boundary. Article 001 says it itself: "dividing by zero is bad/undefined … we just need to make
    /// sure in our JavaScript that `u_innerLimit` is never equal to `u_outerLimit` (note: the example
    /// code does not do this)". A BRDF's visibility term divided by the clamped cosines is ±∞ on
    /// the whole unlit side of every object, and NaN where the numerator carries the same cosine:
    /// `saturate` turns +∞ into 1 but NaN into whatever the GPU makes of it.
    ///
    /// ## Example
    /// ```glsl
    /// float limitRange = u_innerLimit - u_outerLimit;
    /// float inLight = clamp((dotFromDirection - u_outerLimit) / limitRange, 0.0, 1.0);
    /// ```
    ///
    /// ## Use instead
    /// ```glsl
    /// float limitRange = u_innerLimit - u_outerLimit;
    /// float inLight = clamp((dotFromDirection - u_outerLimit) / max(limitRange, 1e-4), 0.0, 1.0);
    /// ```
    /// The suggested fix guards the divisor with `max(…, 1e-4)` (a floor above `mediump`'s smallest
    /// normal number, 6.1e-5), which also makes a swapped pair behave like a hard edge. Where the
    /// difference may legitimately be negative, guard its magnitude instead.
    ///
    /// ## What it does not flag
    /// - A divisor the shader keeps away from 0: `max(d, 1e-4)`, `d + 0.1` of a non-negative `d`, a
    ///   difference it orders itself (`u_r + 0.1 - u_r`), or one an enclosing condition says is not 0
    ///   (`if (u_a != u_b)`, `abs(d) > 1e-6 ? x / d : 0.0`), also an integer's conversion after
    ///   `if (n == 0) return;` (`x / float(n)`).
    /// - A shading term the shader keeps from 0 (`4.0 * NdotL * NdotV + 0.0001`, `max(NdotL, 1e-4)`,
    ///   under `if (NdotL > 0.0 && NdotV > 0.0)`), and a raw `dot(n, l)`, 0 on a line of pixels only.
    /// - A sum of texels with a constant added (`t.r + t.g + 1e-3`), or a clamp or `max` of one;
    ///   a difference of texels is 0 at an end of their range or not at all (above).
    /// - Any other uniform as such (`gl_FragCoord.xy / u_resolution`, `/ u_pixelRatio`): essl-gl's
    ///   validation mode checks divisors at draw time.
    /// - A parameter's division where a call passes a uniform or a computed value (the value
    ///   decides, as for any other divisor), or where ordinary non-negative values keep it from 0
    ///   (`x / (x + 0.155)`); the `w` of a `vec4` that no projection made (`world.xyz / world.w`
    ///   of an affine transform, 1), of the camera's own clip position in a fragment shader
    ///   (positive wherever a pixel is drawn), in a vertex shader that sets `gl_PointSize` (a
    ///   point on the camera's plane is clipped whole), or whose quotient is only compared,
    ///   `step`ped or clamped to constant bounds (±∞ gives a defined answer there); a
    ///   varying as such in a fragment shader (0 on a line of pixels at most); a
    ///   parameter named for a size the host computes, or a multiple of one (`1.0 / texResolution`,
    ///   `floor(v * res) / res`; not a size a setting's word qualifies, `cellSize`); one named for what is never 0 (an index of refraction `ior`, a
    ///   `shutterSpeed`, a number `base`).
    /// - The length of a vector's derivative (`1.0 / length(dFdx(p))` of a position): 0 only where
    ///   all of `p` is the same across the quad, which a surface's position never is.
    /// - A divisor with a per-pixel part, zero at isolated pixels at most (but for the length
    ///   of a pixel's offset from a centre, above): the depth linearisation
    ///   `far + near - z * (far - near)` (positive for `z` in [-1, 1]), a Fresnel term
    ///   `1.0 - Ems * Favg`, a difference of texels that is 0 only inside their range
    ///   (`c.r - c.g`, `c.r * 2.0 - 1.0`: an exact mid value, where black, white and transparent
    ///   texels fill whole regions); and integer divisions.
    ///
    /// Severity: a warning when values the shader itself produces reach the hazard, a texel at an
    /// end of its range among them; a note, naming
    /// the uniform, when one uniform alone (with constants) does — the hazard then needs that value out
    /// of the range the shader was written for, and essl-gl's validation mode checks it at draw time. (`x / (u_resolution - 1.0)` needs `u_resolution == 1`). A difference of two uniforms
    /// a user sets independently (`cutOff - outerCutOff`, `far - near`) gives a warning. A
    /// division by parameters whose callers pass inputs as such, or by attributes, is a note:
    /// the values are the callers' or the host's, which the shader does not show.
    ///
    /// ## References
    /// - Article 001 (webgl2fundamentals, spot lights), the note after the `limitRange` diff.
    /// - Article 004 (LearnOpenGL spot light): `epsilon = light.cutOff - light.outerCutOff` and
    ///   `/ epsilon`.
    pub(crate) struct DivisionByDifference {
        id: "division-by-difference",
        summary: "division by a difference of uniforms, a texel (or a sum, product or luminance of texels) or a difference of texels at an end of their range, a shading term of clamped cosines, what callers or vertex data pass, or a perspective divide before clipping, that can be zero",
        default_level: Level::Warn,
        check: check,
    }
}

fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    for (id, f) in cx.functions() {
        // Set up at the first division: a function without one never asks for the analysis.
        let mut sym = None;
        for (h, e) in f.expressions.iter() {
            let E::Binary {
                op: Bo::Divide,
                right,
                ..
            } = *e
            else {
                continue;
            };
            if cx.span(f, h).is_empty() {
                continue;
            }
            let d = cx.operand(f, h, right);
            let Some(v) = cx.sound().num(id, d) else {
                continue;
            };
            // A difference of per-draw values: one with a per-pixel part (a depth, a ray) is
            // zero at isolated pixels at most, not for the whole draw — unless the part is a
            // texel and the difference is 0 at an end of its range.
            if cx.kind(id, d) != Some(ScalarKind::Float) {
                continue;
            }
            let div = Division { f, id, h, d };
            if let Some(diag) = derivative_divisor(cx, &div, v) {
                out.push(diag);
                continue;
            }
            if let Some(diag) = zero_divisor(cx, &div, v) {
                out.push(diag);
                continue;
            }
            if let Some(diag) = unlit_divisor(cx, &div, v) {
                out.push(diag);
                continue;
            }
            if let Some(diag) = clip_divisor(cx, &div) {
                out.push(diag);
                continue;
            }
            if !v.facts.has(Facts::DIFF) && !offset_texel(cx, f, id, d, v.facts) {
                if let Some(diag) = texel_divisor(cx, &div) {
                    out.push(diag);
                } else if let Some(diag) = black_divisor(cx, &div, v) {
                    out.push(diag);
                } else if let Some(diag) = setting_divisor(cx, &div) {
                    out.push(diag);
                } else if let Some(diag) = parameter_divisor(cx, &div) {
                    out.push(diag);
                } else if let Some(diag) = direction_divisor(cx, &div) {
                    out.push(diag);
                } else {
                    out.extend(length_divisor(cx, &div));
                }
                continue;
            }
            let per_pixel = v.facts.any(Facts::INPUT.with(Facts::TEXTURE));
            if (!per_pixel && !v.facts.any(Facts::UNIFORM))
                || !v.comps().iter().any(|c| c.contains(0.0))
            {
                continue;
            }
            // Only a per-pixel difference asks about texels, with the analysis of ordinary
            // values (a second run over the module): after the cheaper tests.
            let texel = per_pixel && zero_at_texel_end(cx, id, d, v.facts);
            if per_pixel && !texel {
                out.extend(
                    parameter_divisor(cx, &div)
                        .or_else(|| length_divisor(cx, &div))
                        .or_else(|| setting_divisor(cx, &div)),
                );
                continue;
            }
            if sym.get_or_insert_with(|| cx.sym(id, f)).nonzero(d) {
                continue;
            }
            let Some(span) = unguarded(cx, &div) else {
                continue;
            };
            let what = cx.what(f, id, d);
            let mut diag = if texel {
                Diagnostic::rule_warning(
                    DivisionByDifference::RULE.id,
                    "division by a difference that is zero for ordinary texels or colours",
                    span,
                )
                .with_label(format!(
                    "{what} is 0 where a texel or colour it reads is at an end of its range (black, white, transparent)"
                ))
            } else {
                Diagnostic::rule_warning(
                    DivisionByDifference::RULE.id,
                    "division by a difference of uniforms that can be zero",
                    span,
                )
                .with_label(format!("{what} is 0 when the uniforms are equal"))
            }
            .with_help("guard the divisor");
            let def = resolve(f, cx.sound(), id, d);
            let def_span = cx.span(f, def);
            if def != d
                && !def_span.is_empty()
                && matches!(
                    f.expressions[def],
                    E::Binary {
                        op: Bo::Subtract,
                        ..
                    }
                )
            {
                diag = diag.with_secondary(def_span, "the difference");
            }
            out.push(cx.grade(diag.with_fix(floor_fix(cx, span)), &[(id, d)]));
        }
    }
}

/// A division by a derivative's width that the shader does not keep from 0
/// ([`derivatives::divisor_finding`]); a warning where the dividend is computed from inputs
/// and can be 0 too.
fn derivative_divisor(cx: &Cx, div: &Division, v: &Num) -> Option<Diagnostic> {
    let Division { f, id, h, d } = *div;
    if !v.comps().iter().any(|c| c.contains(0.0)) || !derivatives::derivative_width(cx, id, f, d) {
        return None;
    }
    let span = unguarded(cx, div)?;
    let E::Binary { left, .. } = f.expressions[h] else {
        return None;
    };
    let nan = cx.sound().num(id, left).is_some_and(|n| {
        n.facts.has(Facts::INPUT)
            && !n.facts.any(Facts::TEXTURE)
            && n.comps().iter().any(|c| c.contains(0.0))
    });
    let what = cx.what(f, id, d);
    Some(derivatives::divisor_finding(
        DivisionByDifference::RULE.id,
        cx,
        &what,
        v,
        nan,
        span,
    ))
}

/// A division: its function, the function's id, the division and its divisor.
struct Division<'a> {
    f: &'a naga::Function,
    id: usize,
    h: naga::Handle<E>,
    d: naga::Handle<E>,
}

/// Whether divisor `d` is texels plus a constant that is 0 at an end of their range, a
/// difference written as a sum: FSR's `4.0 * mn + peakC.y` with `peakC.y == -4.0`, 0 wherever
/// the four neighbours are white.
fn offset_texel(cx: &Cx, f: &naga::Function, id: usize, d: naga::Handle<E>, facts: Facts) -> bool {
    let E::Binary {
        op: Bo::Add,
        left,
        right,
    } = f.expressions[resolve(f, cx.sound(), id, d)]
    else {
        return false;
    };
    let constant = |x| {
        cx.sound()
            .num(id, x)
            .and_then(|n| n.hull().as_point())
            .is_some_and(|c| c < 0.0)
    };
    (constant(left) || constant(right)) && zero_at_texel_end(cx, id, d, facts)
}

/// Whether a difference that reads a texel is 0 where texels sit at an end of their range:
/// with texels in `[0, 1]` (and other external values ordinary), 0 is an end of the
/// difference's range (`1.0 - k` for `k = min(1.0 - rgb)` of a texel's colour, `1.0 - t.a`).
/// Black, white and transparent texels cover whole regions of a picture, where a varying
/// crosses a value at isolated pixels only. An end within rounding of 0 counts: `1.0 - Y` for
/// a luminance `Y = dot(rgb, vec3(0.299, 0.587, 0.114))`, whose weights sum to 1 − 1.3e-8 as
/// `float`s, is 0 or 6e-8 for a white texel, as the GPU rounds the dot product.
fn zero_at_texel_end(cx: &Cx, id: usize, d: naga::Handle<E>, facts: Facts) -> bool {
    if !facts.any(Facts::TEXTURE) {
        return false;
    }
    let near = |x: f64| x.abs() <= ROUNDING;
    cx.typical()
        .num(id, d)
        .is_some_and(|t| t.comps().iter().any(|c| near(c.lo) || near(c.hi)))
}

/// How far from 0 an end of a texel difference's range may be and still be 0 after the GPU's
/// rounding: a few units in the last place of a `float` near 1 (1.2e-7 each).
const ROUNDING: f64 = 1e-6;

/// The finding for a divisor `d` of `h` that is a texel (or a colour input) as such, whose
/// range ends at 0: `c.rgb / c.a` un-premultiplies by an alpha that is 0 wherever the texture
/// is transparent, `x / t.r` divides by 0 wherever it is black.
fn texel_divisor(cx: &Cx, div: &Division) -> Option<Diagnostic> {
    let Division { f, id, d, .. } = *div;
    if !cx.black_texel(id, d) {
        return None;
    }
    let span = unguarded(cx, div)?;
    let what = cx.what(f, id, d);
    Some(
        Diagnostic::rule_warning(
            DivisionByDifference::RULE.id,
            "division by a texel or colour that is 0 wherever the texture is black or transparent",
            span,
        )
        .with_label(format!(
            "{what} is 0 where the texel is at the bottom of its range"
        ))
        .with_help("guard the divisor: `max(x, 1e-4)`, or test it first")
        .with_fix(floor_fix(cx, span)),
    )
}

/// The finding for a divisor `d` of `h` that is a uniform as such whose name says it holds a
/// setting a user may set to 0 (a count, a length, a radius, a gamma: `1.0 / uGamma`,
/// `1.0 / float(directionCount)`), or a multiple or blend of such ([`settings_of`]:
/// `lengthCap * sqrt(-z)`, `mix(fadeA, fadeB, t)`), or the step of a grid ([`grid_step`]:
/// `floor(x / uSize) * uSize`): a note naming them.
fn setting_divisor(cx: &Cx, div: &Division) -> Option<Diagnostic> {
    let Division { f, id, h, d } = *div;
    let (found, kind) = match settings_of(cx, f, id, d) {
        Some(found) => (found, "setting"),
        None => (grid_step(cx, f, id, h, d)?, "grid step"),
    };
    let span = unguarded(cx, div)?;
    let what = cx.what(f, id, d);
    let (message, label) = match &found.names[..] {
        [name] if found.itself => (
            format!("division by the {kind} `{name}`, which a user may set to 0"),
            format!("0 when `{name}` is"),
        ),
        [name] => (
            format!("division by a multiple of the setting `{name}`, which a user may set to 0"),
            format!("{what} is 0 wherever `{name}` is"),
        ),
        names => {
            let list = names
                .iter()
                .map(|n| format!("`{n}`"))
                .collect::<Vec<_>>()
                .join(" and ");
            (
                format!("division by a blend of the settings {list}, which a user may set to 0"),
                format!("{what} is 0 wherever {list} are"),
            )
        }
    };
    let mut diag = Diagnostic::rule_warning(DivisionByDifference::RULE.id, message, span)
        .with_label(label)
        .with_help("guard the divisor: `max(x, 1e-4)`, or keep the setting above 0 where it is set")
        .with_fix(floor_fix(cx, span));
    if found.itself {
        return Some(cx.grade(diag, &[(id, d)]));
    }
    diag.severity = essl::diagnostic::Severity::Note;
    let settings = match &found.names[..] {
        [name] => format!("`{name}` at 0 makes"),
        _ => "the settings at 0 make".to_string(),
    };
    Some(diag.with_note(format!(
        "{settings} the divisor 0 for the whole draw: essl-gl's validation mode checks the value at each draw"
    )))
}

/// The note for a divisor `d` of `h` built from the function's parameters alone, where the
/// callers pass inputs as such ([`parameters::caller_value`]): `2.0 * s * s`, `iMax - iMin`.
fn parameter_divisor(cx: &Cx, div: &Division) -> Option<Diagnostic> {
    let Division { f, id, d, .. } = *div;
    let found = caller_value(cx, f, id, d)?;
    let span = unguarded(cx, div)?;
    let names = &found.names;
    let list = found.list();
    let what = cx.what(f, id, d);
    let (message, label) = match &names[..] {
        [name] if found.offset => (
            format!("division by {}", found.lone(name)),
            format!("{what} is 0 for some values of `{name}`"),
        ),
        [name] if found.attribute => (
            format!("division by the attribute `{name}`, which a vertex may hold as 0"),
            format!("{what} is 0 for every vertex whose `{name}` is 0"),
        ),
        _ if found.attribute => (
            format!("division by a value of the attributes {list}, which is 0 for some vertices"),
            format!("{what} is 0 for some values of {list}"),
        ),
        [name] => (
            format!("division by the parameter `{name}`, which a caller may pass as 0"),
            format!("{what} is 0 wherever a caller passes `{name}` as 0"),
        ),
        [a, b] if found.difference => (
            format!("division by a difference of the parameters `{a}` and `{b}`, which callers may pass equal"),
            format!("{what} is 0 wherever a caller passes equal `{a}` and `{b}`"),
        ),
        _ => (
            format!("division by a value of the parameters {list}, which is 0 for some arguments"),
            format!("{what} is 0 for some values of {list}"),
        ),
    };
    let mut diag = Diagnostic::rule_warning(DivisionByDifference::RULE.id, message, span)
        .with_label(label)
        .with_help("guard the divisor: `max(x, 1e-4)`, or keep it from 0 in every caller")
        .with_fix(floor_fix(cx, span))
        .with_note(found.why());
    diag.severity = essl::diagnostic::Severity::Note;
    Some(diag)
}

/// What a finding for a divisor 0 over a region of the picture says.
struct Region {
    message: &'static str,
    /// Follows the divisor's name.
    label: &'static str,
    help: &'static str,
    /// On the value that makes it 0, where that is elsewhere.
    secondary: &'static str,
}

/// The finding for a divisor `d` of `h` that is 0 over the unlit side of a surface
/// ([`Cx::unlit_zero`]): a visibility term's `4.0 * NdotL * NdotV`, `lambdaV + lambdaL`.
fn unlit_divisor(cx: &Cx, div: &Division, v: &crate::value::Num) -> Option<Diagnostic> {
    if !v.comps().iter().any(|c| c.contains(0.0)) {
        return None;
    }
    let zero = cx.unlit_zero(div.f, div.id, div.d)?;
    region_divisor(
        cx,
        div,
        zero,
        &Region {
            message: "division by a shading term that is 0 wherever the surface faces away from the light or the viewer",
            label: "is 0 wherever the clamped cosine is",
            help: "guard the divisor: `max(x, 1e-4)`, or test the cosine first",
            secondary: "0 over every pixel where this dot product is negative",
        },
    )
}

/// The message of [`zero_divisor`]'s findings.
pub(crate) const ZERO_DIVISOR: &str = "division by a value that is always zero";

/// The finding for a divisor that is 0 whatever the inputs (a component of it, for a vector):
/// `i / (m - 1.0)` for `m = float(LAYERS)` where the count `LAYERS` is 1 — most often in a
/// configuration of the text's `#define`s (`variants`).
fn zero_divisor(cx: &Cx, div: &Division, v: &crate::value::Num) -> Option<Diagnostic> {
    if !v.comps().iter().any(|c| c.as_point() == Some(0.0)) {
        return None;
    }
    let span = unguarded(cx, div)?;
    // A texture function of a sampler the entry point never reads is lowered to 0 (its code
    // never runs, or its value is never used).
    if cx.text(span).contains("texture") {
        return None;
    }
    let what = cx.what(div.f, div.id, div.d);
    Some(
        Diagnostic::rule_warning(
            DivisionByDifference::RULE.id,
            ZERO_DIVISOR,
            span,
        )
        .with_label(format!("{what} is 0 whatever the inputs"))
        .with_help("the quotient is ±∞, or NaN where the dividend is 0 too: check the constants it is computed from"),
    )
}

/// The finding for a divisor that is 0 wherever a texel it reads is black or transparent: a sum,
/// product or `dot` of texels as such ([`Cx::black_zero`]) — the `X + Y + Z` of a colour's
/// chromaticity, a luminance a tone mapping divides by.
fn black_divisor(cx: &Cx, div: &Division, v: &crate::value::Num) -> Option<Diagnostic> {
    if !v.facts.any(Facts::TEXTURE) || !v.comps().iter().any(|c| c.contains(0.0)) {
        return None;
    }
    let zero = cx.black_zero(div.f, div.id, div.d)?;
    region_divisor(
        cx,
        div,
        zero,
        &Region {
            message: "division by a sum or product of texels that is 0 wherever the texture is black or transparent",
            label: "is 0 where the texels it reads are",
            help: "guard the divisor: `max(x, 1e-4)`, or test it first",
            secondary: "the texel",
        },
    )
}

/// The finding for an unguarded divisor that `zero` (an expression of function `zero.0`) makes
/// 0 over a region of the picture.
fn region_divisor(
    cx: &Cx,
    div: &Division,
    zero: (usize, naga::Handle<E>),
    text: &Region,
) -> Option<Diagnostic> {
    let span = unguarded(cx, div)?;
    let what = cx.what(div.f, div.id, div.d);
    let mut diag = Diagnostic::rule_warning(DivisionByDifference::RULE.id, text.message, span)
        .with_label(format!("{what} {}", text.label))
        .with_help(text.help)
        .with_fix(floor_fix(cx, span));
    let zspan = cx.span(crate::analysis::function(cx.module, zero.0), zero.1);
    let inside =
        |a: essl::source::Span, b: essl::source::Span| a.start <= b.start && b.end <= a.end;
    if !zspan.is_empty() && !inside(zspan, span) && !inside(span, zspan) {
        diag = diag.with_secondary(zspan, text.secondary);
    }
    Some(diag)
}

/// The note for a vertex shader's division by the length of a direction attribute, through
/// a transform (`r / length((world * vec4(cross(normal, tangent), 0.0)).xyz)`): 0 for a vertex
/// whose normal or tangent is the zero vector, as a mesh without the buffer reads it.
fn direction_divisor(cx: &Cx, div: &Division) -> Option<Diagnostic> {
    let Division { f, id, d, .. } = *div;
    let E::Math {
        fun: naga::MathFunction::Length,
        arg,
        ..
    } = f.expressions[crate::symbolic::resolve(f, cx.sound(), id, d)]
    else {
        return None;
    };
    let list = super::normalize_zero::direction_attributes(cx, f, id, arg)?;
    let span = unguarded(cx, div)?;
    let attribute = if list.contains(", ") {
        "a vector of the attributes"
    } else {
        "the attribute"
    };
    let diag = Diagnostic::rule_note(
        DivisionByDifference::RULE.id,
        format!("division by the length of {attribute} {list}, which a vertex may hold as the zero vector"),
        span,
    )
    .with_label(format!(
        "{} is 0 for a vertex that holds {list} as the zero vector",
        cx.what(f, id, d)
    ))
    .with_help("guard the divisor: `max(x, 1e-4)`")
    .with_fix(floor_fix(cx, span))
    .with_note(super::normalize_zero::ZERO_DIRECTION);
    Some(diag)
}

/// The finding for a division by `length(x)` or `dot(x, x)` where `normalize(x)` would be one
/// ([`normalize_zero::zero_length`]): a normalisation by hand (`delta / length(delta)`), the
/// length of a parameter callers pass as such (`/ length(planeNormal)`), of a cross product of
/// vectors that can be parallel, or of a difference of points a vertex holds.
fn length_divisor(cx: &Cx, div: &Division) -> Option<Diagnostic> {
    let Division { f, id, h, d } = *div;
    let l = length_of(cx, f, id, d, 0)?;
    // Guards are looked up at the division where the length is its function's own, at the
    // `length` call in a function that returns it.
    let site = if l.id == id { h } else { l.call };
    let found = normalize_zero::zero_length(cx, l.f, l.id, site, l.arg)?;
    let span = unguarded(cx, div)?;
    let mut diag = Diagnostic::rule_warning(
        DivisionByDifference::RULE.id,
        format!(
            "division by the {} of a vector that can be the zero vector",
            l.what
        ),
        span,
    )
    .with_label(found.label)
    .with_help("guard the divisor: `max(x, 1e-4)`, or test the length first")
    .with_fix(floor_fix(cx, span));
    if found.span != span && !found.span.is_empty() {
        diag = diag.with_secondary(found.span, "the vector");
    }
    diag.notes = found.notes;
    diag.severity = found.severity;
    Some(diag)
}

/// A `length(x)` (or `dot(x, x)`) call: the function it is in (and that function's id), the
/// call, its argument and what it measures.
struct Length<'a> {
    f: &'a naga::Function,
    id: usize,
    call: naga::Handle<E>,
    arg: naga::Handle<E>,
    what: &'static str,
}

/// The [`Length`] that `h` of function `id` is: `length(x)` or its square `dot(x, x)` (a
/// projection onto a segment: `/ dot(ba, ba)`), a multiple of one by a constant, or what a
/// function returns that is one (lygia's `area(tri)`, `length(cross(b - a, c - a)) * 0.5`).
fn length_of<'a>(
    cx: &Cx<'a>,
    f: &'a naga::Function,
    id: usize,
    h: naga::Handle<E>,
    depth: u32,
) -> Option<Length<'a>> {
    if depth > 4 {
        return None;
    }
    let top = resolve(f, cx.sound(), id, h);
    let constant = |x: naga::Handle<E>| {
        cx.sound()
            .num(id, x)
            .and_then(|n| n.hull().as_point())
            .is_some_and(|c| c != 0.0)
    };
    let here = |arg, what| {
        Some(Length {
            f,
            id,
            call: top,
            arg,
            what,
        })
    };
    match f.expressions[top] {
        E::Math {
            fun: naga::MathFunction::Length,
            arg,
            ..
        } => here(arg, "length"),
        E::Math {
            fun: naga::MathFunction::Dot,
            arg,
            arg1: Some(b),
            ..
        } if cx.sound().same(f, id, arg, b) => here(arg, "squared length"),
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } if constant(right) => length_of(cx, f, id, left, depth + 1),
        E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } if constant(left) => length_of(cx, f, id, right, depth + 1),
        E::CallResult(callee) if callee.index() < cx.module.functions.len() => {
            let [r] = cx.flows().returns(callee.index())[..] else {
                return None;
            };
            let g = crate::analysis::function(cx.module, callee.index());
            length_of(cx, g, callee.index(), r, depth + 1)
        }
        _ => None,
    }
}

/// The note for a perspective divide by the `w` of a clip-space position where it can be 0
/// ([`clip_space::perspective_w`]): a vertex shader's `p.xy / p.w` of `gl_Position` or of a
/// product with the projection, which sees the vertices on and behind the camera's plane
/// that clipping removes only afterwards.
fn clip_divisor(cx: &Cx, div: &Division) -> Option<Diagnostic> {
    let Division { f, id, d, .. } = *div;
    let clip = clip_space::perspective_w(cx, f, id, d)?;
    if clip_space::tolerates_infinity(f, div.h) {
        return None;
    }
    let span = unguarded(cx, div)?;
    let fragment = cx.module.entry_points.first()?.stage == naga::ShaderStage::Fragment;
    let what = match &clip {
        Clip::Position => "`gl_Position`".to_string(),
        Clip::Projection(name) => format!("a position projected by `{name}`"),
    };
    let (note, help) = if fragment {
        (
            "another frame's camera: a pixel this frame shows may lie on that camera's plane (w = 0) or behind it",
            "test `w` first: `if (p.w > 1e-6)`",
        )
    } else {
        (
            "the vertex shader runs before clipping: a vertex on the camera's plane has w = 0, one behind the camera a negative w",
            "test `w` first (`if (p.w > 1e-6)`), or divide after clipping, in the fragment shader",
        )
    };
    let diag = Diagnostic::rule_note(
        DivisionByDifference::RULE.id,
        format!("perspective divide by the `w` of {what}, which is 0 on the camera's plane"),
        span,
    )
    .with_label("0 for a point on the plane through the camera")
    .with_help(help)
    .with_note(note);
    Some(diag)
}

/// The span of divisor `d` of the division `h` where no guard keeps it from 0 (an enclosing
/// condition, `abs(d) > 1e-6 ? x / d : 0.0`); `None` where one does, or where `d` has no span.
fn unguarded(cx: &Cx, div: &Division) -> Option<essl::source::Span> {
    let Division { f, id, h, d } = *div;
    if cx.kept_from_zero(f, id, d, &cx.guards(f, id, h)) {
        return None;
    }
    let span = cx.span(f, d);
    (!span.is_empty()).then_some(span)
}

/// The suggested fix for a divisor at `span`: `max(…, 1e-4)`.
fn floor_fix(cx: &Cx, span: essl::source::Span) -> Fix {
    Fix::suggested(
        "wrap the divisor in `max(…, 1e-4)`",
        span,
        format!("max({}, 1e-4)", cx.text(span)),
    )
}
