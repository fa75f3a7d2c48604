//! The stiff-case matrix: every light model × every stiff case × both formulations (the
//! seed's, [`crate::formulas::seed_fragment`], and the library's,
//! [`crate::formulas::library_fragment`]), evaluated on the CPU in float64, `highp` (float32)
//! and `mediump` (binary16 emulation), each measured against the model in exact float64
//! ([`crate::ideal`]).
//!
//! **Error.** The output colour is clamped to [0, 1] as the framebuffer does; the error is the
//! largest channel's distance, in 1/255 units, from the *reference band*: the model evaluated
//! with both cone cosines moved by `−δ`, `0` and `+δ` (`δ = 2^-22`, a few float32 ulps of a
//! cosine near 1). A cone's edge is only defined to the precision of its uploaded cosine, so a
//! hard edge (the step profile, inner == outer, a 0° cone) falling on a sample counts as right
//! on either side; everywhere else the band is a point. An output that is NaN or infinite
//! before the clamp is *not finite*, whatever a GPU's clamp would make of it.
//!
//! **Rejected.** Where the library refuses the parameters ([`crate::LightsError`]) instead of
//! rendering, the library's cell says so; the seed formula is still evaluated (its reference is
//! the corrected scene where one exists — the swapped cone sorted — and none otherwise).

use std::f64::consts::PI;
use std::fmt::Write as _;

use glam::{DVec2, DVec3};

use crate::formulas::{library_fragment, seed_fragment, FragmentInputs, Seed};
use crate::ideal;
use crate::real::{Real, F16, F32, V3};
use crate::scene::*;
use crate::uniforms::inv_viewport;

/// Half-width of the reference band in cosine units (`2^-22`).
pub const BAND: f64 = 2.384185791015625e-7;

/// A light model of the matrix: one light, the reflection model and the seed it comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Model {
    /// Directional light, Phong reflection (article 002).
    Directional,
    /// Directional light, Lambert reflection (article 002's Gouraud vertex shader).
    DirectionalLambert,
    /// Point light, Phong reflection (article 002's positional light).
    Point,
    /// Spot light, step edge, Blinn–Phong (article 001).
    SpotStep,
    /// Spot light, linear edge, Blinn–Phong (article 001).
    SpotLinear,
    /// Spot light, smooth edge, Blinn–Phong (article 000).
    SpotSmooth,
    /// Spot light with a projected cookie and an up vector, smooth edge (article 003).
    SpotProjected,
    /// Flashlight: spot light with a screen-space cookie, linear edge, Phong (article 004).
    Flashlight,
}

impl Model {
    /// Every model, in table order.
    pub const ALL: [Model; 8] = [
        Model::Directional,
        Model::DirectionalLambert,
        Model::Point,
        Model::SpotStep,
        Model::SpotLinear,
        Model::SpotSmooth,
        Model::SpotProjected,
        Model::Flashlight,
    ];

    /// The seed formulation.
    pub fn seed(self) -> Seed {
        match self {
            Model::Directional => Seed::A002Directional,
            Model::DirectionalLambert => Seed::A002Lambert,
            Model::Point => Seed::A002Positional,
            Model::SpotStep => Seed::A001Step,
            Model::SpotLinear => Seed::A001Linear,
            Model::SpotSmooth => Seed::A000Smooth,
            Model::SpotProjected => Seed::A003Projected,
            Model::Flashlight => Seed::A004Flashlight,
        }
    }

    /// A short name.
    pub fn name(self) -> &'static str {
        match self {
            Model::Directional => "directional (002)",
            Model::DirectionalLambert => "directional Lambert (002 Gouraud)",
            Model::Point => "point (002)",
            Model::SpotStep => "spot step (001)",
            Model::SpotLinear => "spot linear (001)",
            Model::SpotSmooth => "spot smooth (000)",
            Model::SpotProjected => "spot projected cookie (003)",
            Model::Flashlight => "flashlight cookie (004)",
        }
    }

    fn is_spot(self) -> bool {
        matches!(
            self,
            Model::SpotStep
                | Model::SpotLinear
                | Model::SpotSmooth
                | Model::SpotProjected
                | Model::Flashlight
        )
    }

    fn positional(self) -> bool {
        !matches!(self, Model::Directional | Model::DirectionalLambert)
    }

    fn reflection(self) -> Reflection {
        match self {
            Model::DirectionalLambert => Reflection::Lambert,
            Model::Directional | Model::Point | Model::Flashlight => Reflection::Phong,
            _ => Reflection::BlinnPhong,
        }
    }

    /// The default cone (inner, outer) of a spot model.
    fn cone(self) -> (f64, f64) {
        if self == Model::Flashlight {
            (12.5, 17.5)
        } else {
            (10.0, 20.0)
        }
    }
}

/// A stiff case.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Case {
    /// Ordinary parameters (the control: nothing should fail here).
    Baseline,
    /// `inner == outer`.
    InnerEqualsOuter,
    /// Inner cone wider than the outer (cosines swapped).
    Swapped,
    /// A 0° cone.
    Cone0,
    /// A 90° outer cone (`cos = 0`).
    Cone90,
    /// A 120° outer cone (`cos < 0`).
    Cone120,
    /// A 180° outer cone (`cos = −1`).
    Cone180,
    /// Samples exactly on the inner and outer limits.
    LimitOnSample,
    /// The projector's up vector parallel to the spot direction.
    UpParallel,
    /// Projector samples along ±up and ±left of a 120° cone, where `dot` rounds past ±1.
    AcosPastOne,
    /// The light exactly on the surface point.
    LightOnSurface,
    /// A zero-length normal.
    ZeroNormal,
    /// The normal perpendicular to the light (`N·L` = 0, ±1e-6, 1e-3).
    Grazing,
    /// The surface seen from behind, light in front; includes `L = −V` exactly.
    BackFace,
    /// The light behind the surface (`N·L < 0`, `N·H < 0`).
    LightBehind,
    /// Shininess 0.
    Shininess0,
    /// Shininess 1e4, samples at the highlight.
    Shininess1e4,
    /// The whole scene scaled by 1e-6.
    ScaleMicro,
    /// The whole scene scaled by 1e6.
    ScaleMega,
    /// The scene scaled by 4: vector lengths around 400, `dot(v, v)` past mediump's 65504.
    MediumpRange,
    /// A 0×0 viewport.
    ZeroViewport,
}

impl Case {
    /// Every case, in table order.
    pub const ALL: [Case; 21] = [
        Case::Baseline,
        Case::InnerEqualsOuter,
        Case::Swapped,
        Case::Cone0,
        Case::Cone90,
        Case::Cone120,
        Case::Cone180,
        Case::LimitOnSample,
        Case::UpParallel,
        Case::AcosPastOne,
        Case::LightOnSurface,
        Case::ZeroNormal,
        Case::Grazing,
        Case::BackFace,
        Case::LightBehind,
        Case::Shininess0,
        Case::Shininess1e4,
        Case::ScaleMicro,
        Case::ScaleMega,
        Case::MediumpRange,
        Case::ZeroViewport,
    ];

    /// A short name.
    pub fn name(self) -> &'static str {
        match self {
            Case::Baseline => "baseline",
            Case::InnerEqualsOuter => "inner == outer",
            Case::Swapped => "inner > outer (swapped)",
            Case::Cone0 => "cone 0°",
            Case::Cone90 => "cone 90°",
            Case::Cone120 => "cone 120°",
            Case::Cone180 => "cone 180°",
            Case::LimitOnSample => "limit on the sample",
            Case::UpParallel => "up ∥ direction",
            Case::AcosPastOne => "acos past ±1",
            Case::LightOnSurface => "light on the surface",
            Case::ZeroNormal => "zero normal",
            Case::Grazing => "grazing",
            Case::BackFace => "back face",
            Case::LightBehind => "light behind (pow of negative)",
            Case::Shininess0 => "shininess 0",
            Case::Shininess1e4 => "shininess 1e4",
            Case::ScaleMicro => "scale 1e-6",
            Case::ScaleMega => "scale 1e6",
            Case::MediumpRange => "mediump range (lengths ≈ 400)",
            Case::ZeroViewport => "viewport 0×0",
        }
    }

    /// Whether the case means something for the model.
    pub fn applies(self, m: Model) -> bool {
        match self {
            Case::InnerEqualsOuter | Case::Swapped => m.is_spot() && m != Model::SpotStep,
            Case::Cone0 | Case::Cone90 | Case::Cone120 | Case::Cone180 | Case::LimitOnSample => {
                m.is_spot()
            }
            Case::UpParallel | Case::AcosPastOne => m == Model::SpotProjected,
            Case::LightOnSurface => m.positional(),
            Case::Shininess0 | Case::Shininess1e4 => m.reflection() != Reflection::Lambert,
            Case::ZeroViewport => m == Model::Flashlight,
            _ => true,
        }
    }
}

/// One evaluation's result.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// The library refused the parameters (the error's message).
    Rejected(String),
    /// Evaluated against the reference band.
    Measured {
        /// Samples whose output was NaN or infinite.
        non_finite: usize,
        /// Samples evaluated.
        samples: usize,
        /// The largest error of the finite samples, 1/255 units.
        max_error: f64,
    },
    /// Evaluated where no reference exists (the parameters have no meaning).
    Unmeasured {
        /// Samples whose output was NaN or infinite.
        non_finite: usize,
        /// Samples evaluated.
        samples: usize,
    },
}

impl Outcome {
    /// Every output finite.
    pub fn finite(&self) -> bool {
        match self {
            Outcome::Rejected(_) => true,
            Outcome::Measured { non_finite, .. } | Outcome::Unmeasured { non_finite, .. } => {
                *non_finite == 0
            }
        }
    }

    /// Finite and within 1/255 everywhere (or rejected).
    pub fn ok(&self) -> bool {
        match self {
            Outcome::Rejected(_) => true,
            Outcome::Measured {
                non_finite,
                max_error,
                ..
            } => *non_finite == 0 && *max_error <= 1.0,
            Outcome::Unmeasured { .. } => false,
        }
    }

    /// A table cell: the error (bold beyond 1/255), `NaN k/n`, `rejected`, or for no
    /// reference `finite` / `NaN k/n`.
    pub fn cell(&self) -> String {
        match self {
            Outcome::Rejected(_) => "rejected".into(),
            Outcome::Measured {
                non_finite,
                samples,
                max_error,
            } => {
                if *non_finite > 0 {
                    format!("**NaN {non_finite}/{samples}**")
                } else if *max_error > 1.0 {
                    format!("**{}**", fmt_err(*max_error))
                } else {
                    fmt_err(*max_error)
                }
            }
            Outcome::Unmeasured {
                non_finite,
                samples,
            } => {
                if *non_finite > 0 {
                    format!("**NaN {non_finite}/{samples}**")
                } else {
                    "finite (no ref.)".into()
                }
            }
        }
    }
}

fn fmt_err(e: f64) -> String {
    if e == 0.0 {
        "0".into()
    } else if e < 0.01 {
        format!("{e:.0e}")
    } else if e < 10.0 {
        format!("{e:.2}")
    } else {
        format!("{e:.0}")
    }
}

/// One row of the matrix.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The light model.
    pub model: Model,
    /// The case.
    pub case: Case,
    /// The seed's formula in float64.
    pub seed_f64: Outcome,
    /// The seed's formula in float32.
    pub seed_highp: Outcome,
    /// The seed's formula in binary16.
    pub seed_mediump: Outcome,
    /// The library's formula in float32 (what it emits: `precision highp float`).
    pub library_highp: Outcome,
    /// The library's formula in binary16 (for information: the library never emits mediump).
    pub library_mediump: Outcome,
}

/// A case's scene, samples and viewport.
#[derive(Clone, Debug)]
pub struct Setup {
    /// The scene as the case gives it (may be refused by the library).
    pub scene: LitScene,
    /// The scene the reference evaluates (the corrected one), if any.
    pub reference: Option<LitScene>,
    /// The fragments evaluated.
    pub samples: Vec<FragmentInputs>,
    /// The viewport (width, height).
    pub viewport: [f64; 2],
}

/// Where the matrix's spot lights are (pointing down, −y).
pub const LIGHT_SPOT: DVec3 = DVec3::new(0.0, 100.0, 0.0);
/// Where the matrix's plane samples are seen from.
pub const EYE: DVec3 = DVec3::new(0.0, 140.0, 70.0);

fn material(shininess: f64) -> Material {
    Material {
        ambient: DVec3::ONE,
        diffuse: DVec3::new(0.5, 0.4, 0.3),
        specular: DVec3::splat(0.4),
        shininess,
    }
}

fn light_of(m: Model, inner: f64, outer: f64, up: DVec3, dir: DVec3) -> Light {
    let (color, specular) = (DVec3::ONE, DVec3::ONE);
    match m {
        Model::Directional | Model::DirectionalLambert => Light::Directional(DirectionalLight {
            direction: DVec3::new(-0.3, -1.0, -0.2),
            color,
            specular,
        }),
        Model::Point => Light::Point(PointLight {
            position: DVec3::new(30.0, 100.0, 20.0),
            color,
            specular,
        }),
        _ => Light::Spot(SpotLight {
            position: LIGHT_SPOT,
            direction: dir,
            inner_deg: inner,
            outer_deg: outer,
            edge: match m {
                Model::SpotStep => EdgeProfile::Step,
                Model::SpotLinear | Model::Flashlight => EdgeProfile::Linear,
                _ => EdgeProfile::Smooth,
            },
            cookie: match m {
                Model::SpotProjected => Some(Cookie::Projected {
                    up,
                    image: CookieImage::solid([255; 4]),
                }),
                Model::Flashlight => Some(Cookie::Screen {
                    image: CookieImage::solid([255; 4]),
                }),
                _ => None,
            },
            color,
            specular,
        }),
    }
}

fn scene_of(m: Model, shininess: f64, inner: f64, outer: f64, up: DVec3, dir: DVec3) -> LitScene {
    LitScene::new(Shading::Phong, m.reflection(), material(shininess))
        .with_ambient(DVec3::splat(0.1))
        .with_light(light_of(m, inner, outer, up, dir))
}

fn frag_of(p: DVec3) -> DVec2 {
    DVec2::new(128.0 + 1.5 * p.x, 128.0 - 1.5 * p.z)
}

fn sample(p: DVec3, n: DVec3, eye: DVec3) -> FragmentInputs {
    FragmentInputs {
        position: p,
        normal: n,
        eye,
        frag_coord: frag_of(p),
    }
}

/// The plane grid: 21 × 21 points of y = 0 over [−60, 60]², normal +y.
fn plane(eye: DVec3) -> Vec<FragmentInputs> {
    let mut out = Vec::new();
    for j in 0..=20 {
        for i in 0..=20 {
            let p = DVec3::new(-60.0 + 6.0 * f64::from(i), 0.0, -60.0 + 6.0 * f64::from(j));
            out.push(sample(p, DVec3::Y, eye));
        }
    }
    out
}

/// Two unit vectors perpendicular to `f` and to each other.
fn perp(f: DVec3) -> (DVec3, DVec3) {
    let a = if f.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let e1 = f.cross(a).normalize();
    (e1, f.cross(e1))
}

/// Points on a sphere of radius 50 around the light at the given angles off its axis, facing
/// the light (`N·L = 1`), at four azimuths.
fn shell(light: DVec3, axis: DVec3, angles_deg: &[f64]) -> Vec<FragmentInputs> {
    let (e1, e2) = perp(axis);
    let mut out = Vec::new();
    for &t in angles_deg {
        let (st, ct) = t.to_radians().sin_cos();
        for phi in [0.0f64, 37.0, 90.0, 200.0] {
            let (sp, cp) = phi.to_radians().sin_cos();
            let w = axis * ct + (e1 * cp + e2 * sp) * st;
            let p = light + w * 50.0;
            out.push(FragmentInputs {
                position: p,
                normal: -w,
                eye: light + DVec3::new(30.0, 60.0, 90.0),
                frag_coord: DVec2::new(128.0 + 100.0 * w.x, 128.0 + 100.0 * w.z),
            });
        }
    }
    out
}

fn angles(lo: f64, hi: f64, step: f64, extra: &[f64]) -> Vec<f64> {
    let mut v: Vec<f64> = (0..)
        .map(|k| lo + step * f64::from(k))
        .take_while(|a| *a <= hi)
        .collect();
    v.extend_from_slice(extra);
    v
}

/// The scene and samples of `case` for `model`.
pub fn setup(model: Model, case: Case) -> Setup {
    let (inner, outer) = model.cone();
    let up = DVec3::NEG_Z;
    let mut shininess = 30.0;
    let (mut inner_c, mut outer_c) = (inner, outer);
    let mut up_c = up;
    let mut dir_c = DVec3::NEG_Y;
    let mut viewport = [256.0, 256.0];
    let mut samples = plane(EYE);
    let cone_shell = |i: f64, o: f64| {
        shell(
            LIGHT_SPOT,
            DVec3::NEG_Y,
            &angles(0.0, 180.0, 0.5, &[i, o, i + 1e-9, o - 1e-9, o + 1e-9]),
        )
    };
    let mut scale = 1.0;
    match case {
        Case::Baseline => {
            if model.is_spot() {
                samples.extend(cone_shell(inner, outer));
            }
        }
        Case::InnerEqualsOuter => {
            inner_c = outer;
            samples.extend(cone_shell(outer, outer));
        }
        Case::Swapped => {
            inner_c = outer;
            outer_c = inner;
            samples.extend(cone_shell(inner, outer));
        }
        Case::Cone0 => {
            inner_c = 0.0;
            outer_c = 0.0;
            samples.extend(cone_shell(0.0, 0.0));
        }
        Case::Cone90 => {
            inner_c = 80.0;
            outer_c = 90.0;
            samples.extend(cone_shell(80.0, 90.0));
        }
        Case::Cone120 => {
            inner_c = 100.0;
            outer_c = 120.0;
            samples.extend(cone_shell(100.0, 120.0));
        }
        Case::Cone180 => {
            inner_c = 170.0;
            outer_c = 180.0;
            samples.extend(cone_shell(170.0, 180.0));
        }
        Case::LimitOnSample => {
            samples = shell(
                LIGHT_SPOT,
                DVec3::NEG_Y,
                &[
                    inner,
                    outer,
                    inner - 1e-9,
                    inner + 1e-9,
                    outer - 1e-9,
                    outer + 1e-9,
                ],
            );
        }
        Case::UpParallel => {
            up_c = DVec3::NEG_Y;
            samples.extend(cone_shell(inner, outer));
        }
        Case::AcosPastOne => {
            inner_c = 100.0;
            outer_c = 120.0;
            // A tilted projector (no component exact in binary), and points 90° off its axis
            // along ±up and ±left (left = forward × up), nudged by up to 1e-7 rad.
            let f = DVec3::new(1.0, -2.0, 0.5).normalize();
            let u = f.cross(DVec3::new(0.3, 0.1, 1.0)).normalize();
            dir_c = f;
            up_c = u;
            let left = f.cross(u);
            samples = Vec::new();
            for dir in [u, -u, left, -left] {
                for k in -20..=20 {
                    let e = f64::from(k) * 5e-9;
                    for r in [1.0, 3.0, 7.0, 50.0, 123.456] {
                        let w = (dir + f * e + dir.cross(f) * (e * 0.7)).normalize();
                        let p = LIGHT_SPOT + w * r;
                        samples.push(FragmentInputs {
                            position: p,
                            normal: -w,
                            eye: LIGHT_SPOT + DVec3::new(30.0, 60.0, 90.0),
                            frag_coord: frag_of(p),
                        });
                    }
                }
            }
        }
        Case::LightOnSurface => {
            let lp = match light_of(model, inner, outer, up, dir_c) {
                Light::Point(p) => p.position,
                Light::Spot(s) => s.position,
                Light::Directional(_) => DVec3::ZERO,
            };
            samples = vec![
                sample(lp, DVec3::Y, EYE),
                sample(lp, DVec3::new(0.3, 0.9, 0.1), EYE),
                sample(lp, DVec3::NEG_Y, EYE),
            ];
        }
        Case::ZeroNormal => {
            for s in &mut samples {
                s.normal = DVec3::ZERO;
            }
        }
        Case::Grazing => {
            let light = light_of(model, inner, outer, up, dir_c);
            let mut out = Vec::new();
            for s in &samples {
                let l = match &light {
                    Light::Directional(d) => -d.direction.normalize(),
                    Light::Point(p) => (p.position - s.position).normalize(),
                    Light::Spot(sp) => (sp.position - s.position).normalize(),
                };
                let (e1, e2) = perp(l);
                for side in [e1, -e1, e2] {
                    for eps in [0.0, 1e-6, -1e-6, 1e-3] {
                        let mut g = *s;
                        g.normal = side + l * eps;
                        out.push(g);
                    }
                }
            }
            samples = out;
        }
        Case::BackFace => {
            let eye = DVec3::new(0.0, -140.0, 70.0);
            samples = plane(eye);
            // L = −V exactly: the eye straight below the point, the light straight above.
            let lp = match light_of(model, inner, outer, up, dir_c) {
                Light::Point(p) => p.position,
                _ => LIGHT_SPOT,
            };
            let p = DVec3::new(lp.x, 0.0, lp.z);
            samples.push(sample(p, DVec3::Y, DVec3::new(lp.x, -lp.y, lp.z)));
        }
        Case::LightBehind => {
            for s in &mut samples {
                s.normal = DVec3::NEG_Y;
            }
        }
        Case::Shininess0 => {
            shininess = 0.0;
            let mut behind = samples.clone();
            for s in &mut behind {
                s.normal = DVec3::NEG_Y;
            }
            samples.extend(behind);
        }
        Case::Shininess1e4 => {
            shininess = 1e4;
            let scene = scene_of(model, shininess, inner, outer, up, dir_c);
            samples.extend(highlight(&scene));
        }
        Case::ScaleMicro => scale = 1e-6,
        Case::ScaleMega => scale = 1e6,
        Case::MediumpRange => scale = 4.0,
        Case::ZeroViewport => viewport = [0.0, 0.0],
    }
    let mut scene = scene_of(model, shininess, inner_c, outer_c, up_c, dir_c);
    if scale != 1.0 {
        for s in &mut samples {
            s.position *= scale;
            s.eye *= scale;
        }
        for l in &mut scene.lights {
            match l {
                Light::Point(p) => p.position *= scale,
                Light::Spot(s) => s.position *= scale,
                Light::Directional(_) => {}
            }
        }
    }
    let reference = match case {
        Case::Swapped => {
            let mut r = scene.clone();
            if let Some(Light::Spot(s)) = r.lights.first_mut() {
                std::mem::swap(&mut s.inner_deg, &mut s.outer_deg);
            }
            Some(r)
        }
        Case::UpParallel | Case::ZeroViewport => None,
        _ => Some(scene.clone()),
    };
    Setup {
        scene,
        reference,
        samples,
        viewport,
    }
}

/// A fine grid of plane points around the model's specular peak (found on a coarse grid).
fn highlight(scene: &LitScene) -> Vec<FragmentInputs> {
    let prepared = scene.prepare().expect("a valid scene");
    let spec_only = |p: DVec3| {
        let s = ideal::Surface {
            position: p,
            normal: DVec3::Y,
            eye: EYE,
            frag_coord: frag_of(p),
        };
        ideal::color(
            scene,
            &prepared,
            &s,
            &|_, _| DVec3::ONE,
            DVec2::splat(1.0 / 256.0),
        )
        .x
    };
    let mut best = (f64::NEG_INFINITY, DVec3::ZERO);
    for j in -100..=100 {
        for i in -100..=100 {
            let p = DVec3::new(f64::from(i), 0.0, f64::from(j));
            let v = spec_only(p);
            if v > best.0 {
                best = (v, p);
            }
        }
    }
    let mut out = Vec::new();
    for j in -15..=15 {
        for i in -15..=15 {
            let p = best.1 + DVec3::new(f64::from(i) * 0.1, 0.0, f64::from(j) * 0.1);
            out.push(sample(p, DVec3::Y, EYE));
        }
    }
    out
}

/// The analytic cookie of the matrix: smooth and periodic, so errors in the coordinates show
/// as colour errors and wrapping changes nothing.
pub fn analytic_cookie(u: f64, t: f64) -> DVec3 {
    DVec3::new(
        0.5 + 0.5 * (2.0 * PI * u).cos(),
        0.5 + 0.5 * (2.0 * PI * t).cos(),
        1.0,
    )
}

fn cookie_r<R: Real>(_: usize, u: R, t: R) -> V3<R> {
    V3::of(analytic_cookie(u.to_f64(), t.to_f64()))
}

/// The reference band `[lo, hi]` of every sample (clamped to [0, 1]).
fn bands(setup: &Setup) -> Option<Vec<(DVec3, DVec3)>> {
    let r = setup.reference.as_ref()?;
    let prepared = r.prepare().ok()?;
    let inv = inv_viewport(setup.viewport[0], setup.viewport[1])
        .map(DVec2::from_array)
        .unwrap_or(DVec2::ZERO);
    let cookie = |_: usize, uv: DVec2| analytic_cookie(uv.x, uv.y);
    Some(
        setup
            .samples
            .iter()
            .map(|f| {
                let s = ideal::Surface {
                    position: f.position,
                    normal: f.normal,
                    eye: f.eye,
                    frag_coord: f.frag_coord,
                };
                let vals: Vec<DVec3> = [-BAND, 0.0, BAND]
                    .iter()
                    .map(|&sh| {
                        ideal::terms(r, &prepared, &s, &cookie, inv, sh, false)
                            .base
                            .clamp(DVec3::ZERO, DVec3::ONE)
                    })
                    .collect();
                (
                    vals[0].min(vals[1]).min(vals[2]),
                    vals[0].max(vals[1]).max(vals[2]),
                )
            })
            .collect(),
    )
}

fn measure<R: Real>(
    samples: &[FragmentInputs],
    bands: Option<&[(DVec3, DVec3)]>,
    eval: impl Fn(&FragmentInputs) -> V3<R>,
) -> Outcome {
    let mut non_finite = 0;
    let mut max_error = 0.0f64;
    for (k, s) in samples.iter().enumerate() {
        let out = eval(s).to_f64();
        if !out.is_finite() {
            non_finite += 1;
            continue;
        }
        if let Some(b) = bands {
            let (lo, hi) = b[k];
            let o = out.clamp(DVec3::ZERO, DVec3::ONE);
            let e = (lo - o).max(o - hi).max(DVec3::ZERO).max_element() * 255.0;
            max_error = max_error.max(e);
        }
    }
    match bands {
        Some(_) => Outcome::Measured {
            non_finite,
            samples: samples.len(),
            max_error,
        },
        None => Outcome::Unmeasured {
            non_finite,
            samples: samples.len(),
        },
    }
}

fn seed_outcome<R: Real>(model: Model, setup: &Setup, bands: Option<&[(DVec3, DVec3)]>) -> Outcome {
    measure::<R>(&setup.samples, bands, |s| {
        seed_fragment::<R>(
            model.seed(),
            &setup.scene,
            setup.viewport,
            s,
            &cookie_r::<R>,
        )
    })
}

fn library_outcome<R: Real>(setup: &Setup, bands: Option<&[(DVec3, DVec3)]>) -> Outcome {
    let prepared = match setup.scene.prepare() {
        Ok(p) => p,
        Err(e) => return Outcome::Rejected(e.to_string()),
    };
    let inv = if prepared.shape.has_screen_cookie() {
        match inv_viewport(setup.viewport[0], setup.viewport[1]) {
            Ok(v) => v,
            Err(e) => return Outcome::Rejected(e.to_string()),
        }
    } else {
        [0.0, 0.0]
    };
    measure::<R>(&setup.samples, bands, |s| {
        library_fragment::<R>(&setup.scene, &prepared, inv, s, &cookie_r::<R>)
    })
}

/// Evaluates one cell row.
pub fn evaluate(model: Model, case: Case) -> Row {
    let setup = setup(model, case);
    let b = bands(&setup);
    let b = b.as_deref();
    Row {
        model,
        case,
        seed_f64: seed_outcome::<f64>(model, &setup, b),
        seed_highp: seed_outcome::<F32>(model, &setup, b),
        seed_mediump: seed_outcome::<F16>(model, &setup, b),
        library_highp: library_outcome::<F32>(&setup, b),
        library_mediump: library_outcome::<F16>(&setup, b),
    }
}

/// The whole matrix: every model × every case that applies to it.
pub fn run() -> Vec<Row> {
    let mut rows = Vec::new();
    for m in Model::ALL {
        for c in Case::ALL {
            if c.applies(m) {
                rows.push(evaluate(m, c));
            }
        }
    }
    rows
}

/// The matrix as a Markdown table (seed precision marked `*`).
pub fn markdown(rows: &[Row]) -> String {
    let mut s = String::from(
        "| light model | case | seed f64 | seed highp | seed mediump | library highp | library mediump |\n\
         | --- | --- | --- | --- | --- | --- | --- |\n",
    );
    for r in rows {
        let seed_prec = r.model.seed().precision();
        let mark = |o: &Outcome, p: &str| {
            let c = o.cell();
            if p == seed_prec {
                format!("{c} *")
            } else {
                c
            }
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} |",
            r.model.name(),
            r.case.name(),
            r.seed_f64.cell(),
            mark(&r.seed_highp, "highp"),
            mark(&r.seed_mediump, "mediump"),
            r.library_highp.cell(),
            r.library_mediump.cell(),
        );
    }
    s
}

/// Counts for a summary: rows, seed failures at the seed's own precision, library highp
/// failures (must be 0).
pub fn summary(rows: &[Row]) -> (usize, usize, usize) {
    let seed_fail = rows
        .iter()
        .filter(|r| {
            let o = if r.model.seed().precision() == "mediump" {
                &r.seed_mediump
            } else {
                &r.seed_highp
            };
            !o.ok()
        })
        .count();
    let lib_fail = rows.iter().filter(|r| !r.library_highp.ok()).count();
    (rows.len(), seed_fail, lib_fail)
}

/// The start marker of the generated section in `docs/numerical-stability.md`.
pub const BEGIN_MARKER: &str = "<!-- stiff-table:begin -->";
/// The end marker.
pub const END_MARKER: &str = "<!-- stiff-table:end -->";

/// The generated section: a summary line and the table.
pub fn document_section(rows: &[Row]) -> String {
    let (total, seed_fail, lib_fail) = summary(rows);
    format!(
        "{BEGIN_MARKER}\n\
         <!-- written by `cargo run -p essl-lights --bin stiff-table`; do not edit by hand -->\n\n\
         {total} (model, case) rows. The seed's formula, at the precision its article declares \
         (marked `*`), is NaN or more than 1/255 off in **{seed_fail}** of them; the library's \
         `highp` formula in **{lib_fail}**.\n\n{}\n{END_MARKER}",
        markdown(rows)
    )
}

/// `doc` with the text between the markers (inclusive) replaced by `section`; `None` without
/// markers.
pub fn replace_section(doc: &str, section: &str) -> Option<String> {
    let a = doc.find(BEGIN_MARKER)?;
    let b = doc[a..].find(END_MARKER)? + a + END_MARKER.len();
    Some(format!("{}{}{}", &doc[..a], section, &doc[b..]))
}
