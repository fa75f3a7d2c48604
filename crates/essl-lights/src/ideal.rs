//! The light model in exact float64 — the reference every shader is measured against.
//!
//! This is the *model*, not a formulation: where a formula is undefined (a zero vector's
//! direction, `0^0`, a zero-width ramp) the model takes the limit the library documents:
//!
//! - a zero vector has no direction: its unit vector is zero, so a light on the surface or a
//!   zero normal contributes nothing (the limit along the surface, where `N·L → 0`);
//! - `max(x, 0)^0 = 1`, and for `n ≥ 1`, `max(x, 0)^n` with `x ≤ 0` is 0;
//! - a linear or smooth edge with `cos inner == cos outer` is the limit of the ramp: 1 for
//!   `d > cos outer`, 0 otherwise; the step edge is `d ≥ cos outer`;
//! - Blinn's `H = normalize(L + V)` is zero when `L = −V`.
//!
//! Colour at a surface point: `ambient + Σ a · k · max(N·L, 0) · (diffuse + s · specular)`,
//! with `a` the spot edge, `k` the cookie's RGB, `s` the specular power (0 for Lambert), the
//! products of light and material colours formed as in [`crate::uniforms`].

use glam::{DVec2, DVec3};

use crate::scene::{CookieKind, EdgeProfile, LightShape, LitScene, PreparedScene, Reflection};

/// A point being shaded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Surface {
    /// World position.
    pub position: DVec3,
    /// The (interpolated, not necessarily unit) normal, world space.
    pub normal: DVec3,
    /// The eye, world space.
    pub eye: DVec3,
    /// `gl_FragCoord.xy`: window coordinates, pixel centres at `+0.5`, y up.
    pub frag_coord: DVec2,
}

/// A cookie lookup: light index and texture coordinates to RGB.
pub type CookieFn<'a> = &'a dyn Fn(usize, DVec2) -> DVec3;

/// The unit vector of `v`, or zero when `v` is zero (or not finite): scaled by its largest
/// component first so nothing under- or overflows.
pub fn unit_or_zero(v: DVec3) -> DVec3 {
    let m = v.abs().max_element();
    if m == 0.0 || !m.is_finite() {
        return DVec3::ZERO;
    }
    let s = v / m;
    s / s.length()
}

/// The spot edge at cosine `d` (model semantics, see the module docs).
pub fn edge(profile: EdgeProfile, d: f64, cos_outer: f64, cos_inner: f64) -> f64 {
    match profile {
        EdgeProfile::Step => {
            if d >= cos_outer {
                1.0
            } else {
                0.0
            }
        }
        EdgeProfile::Linear | EdgeProfile::Smooth => {
            let t = if cos_inner > cos_outer {
                ((d - cos_outer) / (cos_inner - cos_outer)).clamp(0.0, 1.0)
            } else if d > cos_outer {
                1.0
            } else {
                0.0
            };
            if profile == EdgeProfile::Smooth {
                t * t * (3.0 - 2.0 * t)
            } else {
                t
            }
        }
    }
}

/// `max(x, 0)^n` with `0^0 = 1` and the base at most 1.
pub fn power(x: f64, n: f64) -> f64 {
    if x <= 0.0 {
        if n == 0.0 {
            1.0
        } else {
            0.0
        }
    } else {
        x.min(1.0).powf(n)
    }
}

/// The projector's texture coordinates of the unit light-to-surface direction `q` in the
/// projector frame (left, up, forward): `0.5 + asin(q.xy) / (2 · outer)`, exactly.
pub fn projector_uv(q: DVec3, scale: f64) -> DVec2 {
    let x = q.x.atan2(q.y.hypot(q.z));
    let y = q.y.atan2(q.x.hypot(q.z));
    DVec2::new(0.5 + scale * x, 0.5 + scale * y)
}

/// Screen-space cookie coordinates: `s` left to right, `t` top (0) to bottom (1).
pub fn screen_uv(frag_coord: DVec2, inv_viewport: DVec2) -> DVec2 {
    let c = frag_coord * inv_viewport;
    DVec2::new(c.x, 1.0 - c.y)
}

/// The colour of one surface point, split for Gouraud shading.
#[derive(Clone, Debug, PartialEq)]
pub struct Terms {
    /// Ambient plus every light whose cookie (if any) is not in screen space — or every light,
    /// when screen cookies were applied.
    pub base: DVec3,
    /// `(light index, colour before its screen cookie)` for screen-cookie lights left to the
    /// fragment stage.
    pub deferred: Vec<(usize, DVec3)>,
}

/// How [`terms`] evaluates the model.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TermOptions {
    /// Moves both cone cosines of every spot light (the reference band of the stiff matrix;
    /// 0 for the model itself).
    pub shift: f64,
    /// Returns screen-cookie lights in [`Terms::deferred`] instead of sampling them (Gouraud:
    /// the vertex stage cannot know `gl_FragCoord`).
    pub defer_screen: bool,
}

/// Evaluates the model at `s` as `options` say.
pub fn terms(
    scene: &LitScene,
    prepared: &PreparedScene,
    s: &Surface,
    cookie: CookieFn<'_>,
    inv_viewport: DVec2,
    options: TermOptions,
) -> Terms {
    let TermOptions {
        shift,
        defer_screen,
    } = options;
    let m = &scene.material;
    let mut base = scene
        .ambient_light
        .map(|a| a * m.ambient)
        .unwrap_or(DVec3::ZERO);
    let mut deferred = Vec::new();
    if prepared.lights.is_empty() {
        return Terms { base, deferred };
    }
    let n = unit_or_zero(s.normal);
    let v = unit_or_zero(s.eye - s.position);
    for (i, l) in prepared.lights.iter().enumerate() {
        let diffuse = l.color * m.diffuse;
        let specular = l.specular * m.specular;
        let to_light = match l.shape {
            LightShape::Directional => -l.direction,
            _ => unit_or_zero(l.position - s.position),
        };
        let mut k = DVec3::ONE;
        let mut a = 1.0;
        let mut screen = false;
        if let LightShape::Spot { edge: e, cookie: c } = l.shape {
            let d = to_light.dot(-l.direction);
            a = edge(e, d, l.cos_outer + shift, l.cos_inner + shift);
            match c {
                Some(CookieKind::Projected) => {
                    let w = -to_light;
                    let q = DVec3::new(w.dot(l.basis[0]), w.dot(l.basis[1]), w.dot(l.basis[2]));
                    k = cookie(i, projector_uv(q, l.cookie_scale));
                }
                Some(CookieKind::Screen) => {
                    if defer_screen {
                        screen = true;
                    } else {
                        k = cookie(i, screen_uv(s.frag_coord, inv_viewport));
                    }
                }
                None => {}
            }
        }
        let nl = n.dot(to_light).max(0.0);
        let spec = match scene.reflection {
            Reflection::Lambert => 0.0,
            Reflection::Phong => {
                let r = (-to_light) - 2.0 * n.dot(-to_light) * n;
                power(r.dot(v), m.shininess)
            }
            Reflection::BlinnPhong => power(n.dot(unit_or_zero(to_light + v)), m.shininess),
        };
        let c = a * k * nl * (diffuse + spec * specular);
        if screen {
            deferred.push((i, c));
        } else {
            base += c;
        }
    }
    Terms { base, deferred }
}

/// The model's colour at `s` (every cookie applied).
pub fn color(
    scene: &LitScene,
    prepared: &PreparedScene,
    s: &Surface,
    cookie: CookieFn<'_>,
    inv_viewport: DVec2,
) -> DVec3 {
    terms(
        scene,
        prepared,
        s,
        cookie,
        inv_viewport,
        TermOptions::default(),
    )
    .base
}
