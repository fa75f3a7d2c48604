//! Shader formulas written once, generic over [`Real`], so the CPU can run them in float64,
//! `highp` and `mediump`:
//!
//! - the library's formulations, line for line the GLSL of [`crate::glsl`] and of the
//!   generator's `main` ([`library_fragment`] mirrors a Phong-shading fragment shader);
//! - the seeds' formulas ([`Seed`], [`seed_fragment`]), each as its article writes it.
//!
//! A seed formula is *transplanted* into the library's shading skeleton
//! `ambient + a · k · lambert · (diffuse + s · specular)`: only the parts the articles write
//! differently (normalisation, the Lambert term, the specular power, the cone edge, the cookie
//! coordinates) are the article's. Both sides then compute the same function wherever the
//! article's formula is defined, and what the stiff-case matrix measures is the formulation.

use glam::{DVec2, DVec3};

use crate::real::{Real, V3};
use crate::scene::{
    CookieKind, EdgeProfile, Light, LightShape, LitScene, PreparedScene, Reflection,
};

/// A cookie lookup in precision `R`: light index, `(s, t)` to RGB.
pub type CookieFnR<'a, R> = &'a dyn Fn(usize, R, R) -> V3<R>;

/// [`crate::glsl::NORMALIZE`].
pub fn el_normalize<R: Real>(v: V3<R>) -> V3<R> {
    let m = v.x.abs().max(v.y.abs()).max(v.z.abs());
    let s = v.div_scalar(m.max(R::of(1.0e-30)));
    if m > R::of(0.0) {
        s.scale(s.dot(s).inversesqrt())
    } else {
        V3::zero()
    }
}

/// [`crate::glsl::POWER`].
pub fn el_power<R: Real>(x: R, n: R) -> R {
    x.clamp(R::of(5.9604645e-8), R::of(1.0)).pow(n)
}

/// `el_direct` of [`crate::glsl::DIRECT_LAMBERT`], [`crate::glsl::DIRECT_PHONG`],
/// [`crate::glsl::DIRECT_BLINN`].
pub fn el_direct<R: Real>(
    reflection: Reflection,
    n: V3<R>,
    l: V3<R>,
    v: V3<R>,
    diffuse: V3<R>,
    specular: V3<R>,
    shininess: R,
) -> V3<R> {
    let nl = n.dot(l).max(R::of(0.0));
    match reflection {
        Reflection::Lambert => diffuse.scale(nl),
        Reflection::Phong => {
            let s = el_power((-l).reflect(n).dot(v), shininess);
            (diffuse + specular.scale(s)).scale(nl)
        }
        Reflection::BlinnPhong => {
            let s = el_power(n.dot(el_normalize(l + v)), shininess);
            (diffuse + specular.scale(s)).scale(nl)
        }
    }
}

/// [`crate::glsl::EDGE_LINEAR`].
pub fn el_edge_linear<R: Real>(d: R, cos_outer: R, inv_range: R) -> R {
    ((d - cos_outer) * inv_range).clamp(R::of(0.0), R::of(1.0))
}

/// [`crate::glsl::EDGE_SMOOTH`].
pub fn el_edge_smooth<R: Real>(d: R, cos_outer: R, inv_range: R) -> R {
    let t = el_edge_linear(d, cos_outer, inv_range);
    t * t * (R::of(3.0) - R::of(2.0) * t)
}

/// [`crate::glsl::PROJECTOR_UV`].
pub fn el_projector_uv<R: Real>(q: V3<R>, scale: R) -> (R, R) {
    let tiny = R::of(1.0e-30);
    let x = q.x.atan2((q.y * q.y + q.z * q.z).sqrt().max(tiny));
    let y = q.y.atan2((q.x * q.x + q.z * q.z).sqrt().max(tiny));
    (R::of(0.5) + scale * x, R::of(0.5) + scale * y)
}

/// [`crate::glsl::SCREEN_UV`].
pub fn el_screen_uv<R: Real>(frag: (R, R), inv_viewport: (R, R)) -> (R, R) {
    (
        frag.0 * inv_viewport.0,
        R::of(1.0) - frag.1 * inv_viewport.1,
    )
}

/// The varyings and built-ins a fragment formula reads.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FragmentInputs {
    /// World position (`v_position`).
    pub position: DVec3,
    /// Interpolated normal (`v_normal`).
    pub normal: DVec3,
    /// `u_eye`.
    pub eye: DVec3,
    /// `gl_FragCoord.xy`.
    pub frag_coord: DVec2,
}

/// The library's Phong-shading fragment shader for `scene` (what [`crate::generate`] emits),
/// its uniforms rounded to `R` as uploading does, evaluated in `R`.
pub fn library_fragment<R: Real>(
    scene: &LitScene,
    prepared: &PreparedScene,
    inv_viewport: [f64; 2],
    s: &FragmentInputs,
    cookie: CookieFnR<'_, R>,
) -> V3<R> {
    let m = &scene.material;
    let p = V3::<R>::of(s.position);
    let n = el_normalize(V3::<R>::of(s.normal));
    let v = el_normalize(V3::<R>::of(s.eye) - p);
    let shininess = R::of(m.shininess);
    let mut color = match scene.ambient_light {
        Some(a) => V3::of(a * m.ambient),
        None => V3::zero(),
    };
    for (i, l) in prepared.lights.iter().enumerate() {
        let diffuse = V3::<R>::of(l.color * m.diffuse);
        let specular = V3::<R>::of(l.specular * m.specular);
        let to_light = match l.shape {
            LightShape::Directional => -V3::<R>::of(l.direction),
            _ => el_normalize(V3::<R>::of(l.position) - p),
        };
        let direct = el_direct(
            scene.reflection,
            n,
            to_light,
            v,
            diffuse,
            specular,
            shininess,
        );
        let c = if let LightShape::Spot { edge, cookie: ck } = l.shape {
            let cos_outer = R::of(l.cos_outer);
            let inv_range = R::of(l.inv_range);
            let (d, q) = if ck == Some(CookieKind::Projected) {
                let w = -to_light;
                let b = l.basis.map(V3::<R>::of);
                let q = V3::new(w.dot(b[0]), w.dot(b[1]), w.dot(b[2]));
                (q.z, q)
            } else {
                (to_light.dot(-V3::<R>::of(l.direction)), V3::zero())
            };
            let a = match edge {
                EdgeProfile::Step => d.step_from(cos_outer),
                EdgeProfile::Linear => el_edge_linear(d, cos_outer, inv_range),
                EdgeProfile::Smooth => el_edge_smooth(d, cos_outer, inv_range),
            };
            let k = match ck {
                Some(CookieKind::Projected) => {
                    let (u, t) = el_projector_uv(q, R::of(l.cookie_scale));
                    Some(cookie(i, u, t))
                }
                Some(CookieKind::Screen) => {
                    let (u, t) = el_screen_uv(
                        (R::of(s.frag_coord.x), R::of(s.frag_coord.y)),
                        (R::of(inv_viewport[0]), R::of(inv_viewport[1])),
                    );
                    Some(cookie(i, u, t))
                }
                None => None,
            };
            match k {
                Some(k) => k.scale(a).mul_elem(direct),
                None => direct.scale(a),
            }
        } else {
            direct
        };
        color = color + c;
    }
    color
}

/// A seed's formulation of one light, as its article writes it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Seed {
    /// Article 002, directional light, Phong reflection (`precision mediump float`):
    /// `normalize`, `lambertTerm = dot(N, -L)` gating `if (lambertTerm > 0.0)`,
    /// `pow(max(dot(R, E), 0.0), uShininess)`.
    A002Directional,
    /// Article 002, Gouraud + Lambert vertex shader (`mediump`): `dot(N, -L)` unclamped.
    A002Lambert,
    /// Article 002, positional light (`highp`): `normalize(vertex - light)`, as
    /// [`Seed::A002Directional`] otherwise.
    A002Positional,
    /// Article 001, step edge (`mediump`): `step(u_limit, d)`, `dot(N, L)` unclamped,
    /// `pow(dot(N, H), n)` with no `max`.
    A001Step,
    /// Article 001, linear edge (`mediump`): `clamp((d - outer) / (inner - outer), 0, 1)`.
    A001Linear,
    /// Article 000, smooth edge (`highp`): `smoothstep(outer, inner, d)`,
    /// `pow(max(0.0, dot(N, H)), n)`.
    A000Smooth,
    /// Article 003, three.js spot with a projected texture (`highp`): `smoothstep` edge,
    /// `acos` of dot products for the coordinates, `left = normalize(cross(up, direction))`.
    A003Projected,
    /// Article 004, LearnOpenGL flashlight (`highp`): linear edge with `epsilon`, cookie at
    /// `gl_FragCoord.xy / viewPort * vec2(1.0, -1.0)`.
    A004Flashlight,
}

impl Seed {
    /// The precision the article declares.
    pub fn precision(self) -> &'static str {
        match self {
            Seed::A002Directional | Seed::A002Lambert | Seed::A001Step | Seed::A001Linear => {
                "mediump"
            }
            _ => "highp",
        }
    }
}

/// A seed's fragment formula for light 0 of `scene`, transplanted into the library's skeleton
/// (see the module docs), evaluated in `R`. The light's parameters are what the article's
/// JavaScript would upload: unit directions and cone cosines computed in float64, inner and
/// outer as given (even swapped).
pub fn seed_fragment<R: Real>(
    seed: Seed,
    scene: &LitScene,
    viewport: [f64; 2],
    s: &FragmentInputs,
    cookie: CookieFnR<'_, R>,
) -> V3<R> {
    let m = &scene.material;
    let mut color = match scene.ambient_light {
        Some(a) => V3::of(a * m.ambient),
        None => V3::zero(),
    };
    let Some(light) = scene.lights.first() else {
        return color;
    };
    let zero = R::of(0.0);
    let one = R::of(1.0);
    let unit = |v: DVec3| V3::<R>::of(v.normalize());
    let diffuse = V3::<R>::of(light.color() * m.diffuse);
    let specular = V3::<R>::of(light.specular() * m.specular);
    let n_sh = R::of(m.shininess);
    let p = V3::<R>::of(s.position);
    let eye = V3::<R>::of(s.eye);
    let nrm = V3::<R>::of(s.normal).normalize();
    let (position, direction, inner, outer) = match light {
        Light::Directional(d) => (DVec3::ZERO, d.direction, 0.0, 0.0),
        Light::Point(pt) => (pt.position, DVec3::NEG_Y, 0.0, 0.0),
        Light::Spot(sp) => (sp.position, sp.direction, sp.inner_deg, sp.outer_deg),
    };
    let cos_outer = R::of(outer.to_radians().cos());
    let cos_inner = R::of(inner.to_radians().cos());
    let c = match seed {
        Seed::A002Directional | Seed::A002Positional => {
            // L is the direction the light travels.
            let l = if seed == Seed::A002Directional {
                unit(direction).normalize()
            } else {
                (p - V3::of(position)).normalize()
            };
            let lambert = nrm.dot(-l);
            if lambert > zero {
                let e = (eye - p).normalize();
                let r = l.reflect(nrm);
                let spec = r.dot(e).max(zero).pow(n_sh);
                (diffuse + specular.scale(spec)).scale(lambert)
            } else {
                V3::zero()
            }
        }
        Seed::A002Lambert => {
            let l = unit(direction).normalize();
            diffuse.scale(nrm.dot(-l))
        }
        Seed::A001Step | Seed::A001Linear | Seed::A000Smooth => {
            let stl = (V3::of(position) - p).normalize();
            let stv = (eye - p).normalize();
            let h = (stl + stv).normalize();
            let d = stl.dot(-unit(direction));
            let in_light = match seed {
                Seed::A001Step => d.step_from(cos_outer),
                Seed::A001Linear => ((d - cos_outer) / (cos_inner - cos_outer)).clamp(zero, one),
                _ => d.smoothstep(cos_outer, cos_inner),
            };
            let light = in_light * nrm.dot(stl);
            let spec = if seed == Seed::A000Smooth {
                zero.max(nrm.dot(h)).pow(n_sh)
            } else {
                nrm.dot(h).pow(n_sh)
            };
            (diffuse + specular.scale(spec)).scale(light)
        }
        Seed::A003Projected => {
            let up = match light {
                Light::Spot(sp) => match &sp.cookie {
                    Some(crate::Cookie::Projected { up, .. }) => *up,
                    _ => DVec3::Y,
                },
                _ => DVec3::Y,
            };
            let l = (V3::of(position) - p).normalize();
            let spot_dir = -unit(direction); // three.js: from the target to the light
            let d = l.dot(spot_dir);
            let att = d.smoothstep(cos_outer, cos_inner);
            let mut k = V3::splat(one);
            if att > zero {
                let pi = R::of(std::f64::consts::PI);
                let two = R::of(2.0);
                let cone = cos_outer.acos();
                let upv = unit(up);
                let y = R::of(0.5) + (l.dot(upv).acos() - pi / two) / (two * cone);
                let left = upv.cross(spot_dir).normalize();
                let x = R::of(0.5) + (l.dot(left).acos() - pi / two) / (two * cone);
                k = cookie(0, x, y);
            }
            let v = (eye - p).normalize();
            let h = (l + v).normalize();
            let nl = nrm.dot(l).clamp(zero, one);
            let nh = nrm.dot(h).clamp(zero, one);
            let spec = nh.pow(n_sh);
            k.scale(att)
                .mul_elem((diffuse + specular.scale(spec)).scale(nl))
        }
        Seed::A004Flashlight => {
            let l = (V3::of(position) - p).normalize();
            let theta = l.dot((-V3::of(direction)).normalize());
            let epsilon = cos_inner - cos_outer;
            let intensity = ((theta - cos_outer) / epsilon).clamp(zero, one);
            let u = R::of(s.frag_coord.x) / R::of(viewport[0]);
            let t = (R::of(s.frag_coord.y) / R::of(viewport[1])) * R::of(-1.0);
            let k = cookie(0, u, t);
            let diff = nrm.dot(l).max(zero);
            let view = (eye - p).normalize();
            let r = (-l).reflect(nrm);
            let spec = view.dot(r).max(zero).pow(n_sh);
            k.scale(intensity)
                .mul_elem((diffuse + specular.scale(spec)).scale(diff))
        }
    };
    color = color + c;
    color
}
