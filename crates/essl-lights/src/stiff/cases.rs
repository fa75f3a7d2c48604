//! The stiff cases' scenes and samples: a model's defaults, then what each case changes
//! (the cone, the surface, the range), and the fragments it is evaluated at.

use glam::{DVec2, DVec3};

use super::{Case, Model};
use crate::formulas::FragmentInputs;
use crate::ideal;
use crate::scene::*;

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

/// A case's parameters while they are being built: the model's defaults, then what the case
/// changes.
struct Build {
    model: Model,
    /// The model's own cone (inner, outer), degrees.
    cone: (f64, f64),
    /// The cone the case sets.
    inner: f64,
    outer: f64,
    shininess: f64,
    up: DVec3,
    dir: DVec3,
    viewport: [f64; 2],
    samples: Vec<FragmentInputs>,
    /// How much positions are scaled (1 for none).
    scale: f64,
}

impl Build {
    fn new(model: Model) -> Build {
        let (inner, outer) = model.cone();
        Build {
            model,
            cone: (inner, outer),
            inner,
            outer,
            shininess: 30.0,
            up: DVec3::NEG_Z,
            dir: DVec3::NEG_Y,
            viewport: [256.0, 256.0],
            samples: plane(EYE),
            scale: 1.0,
        }
    }

    /// The model's light as the case sets it, the model's own cone and up vector.
    fn model_light(&self) -> Light {
        let (inner, outer) = self.cone;
        light_of(self.model, inner, outer, DVec3::NEG_Z, self.dir)
    }

    /// Sets the cone to (`inner`, `outer`) and adds samples across both edges.
    fn cone_with_shell(&mut self, inner: f64, outer: f64) {
        self.inner = inner;
        self.outer = outer;
        self.samples.extend(cone_shell(inner, outer));
    }

    /// The cases that change the cone or the spot's frame.
    fn cone_case(&mut self, case: Case) {
        let (inner, outer) = self.cone;
        match case {
            Case::Baseline if self.model.is_spot() => {
                self.samples.extend(cone_shell(inner, outer));
            }
            Case::InnerEqualsOuter => self.cone_with_shell(outer, outer),
            Case::Swapped => {
                self.inner = outer;
                self.outer = inner;
                self.samples.extend(cone_shell(inner, outer));
            }
            Case::Cone0 => self.cone_with_shell(0.0, 0.0),
            Case::Cone90 => self.cone_with_shell(80.0, 90.0),
            Case::Cone120 => self.cone_with_shell(100.0, 120.0),
            Case::Cone180 => self.cone_with_shell(170.0, 180.0),
            Case::LimitOnSample => {
                self.samples = shell(
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
                self.up = DVec3::NEG_Y;
                self.samples.extend(cone_shell(inner, outer));
            }
            Case::AcosPastOne => self.acos_past_one(),
            _ => {}
        }
    }

    /// A tilted projector (no component exact in binary), and points 90° off its axis along
    /// ±up and ±left (left = forward × up), nudged by up to 1e-7 rad.
    fn acos_past_one(&mut self) {
        self.inner = 100.0;
        self.outer = 120.0;
        let f = DVec3::new(1.0, -2.0, 0.5).normalize();
        let u = f.cross(DVec3::new(0.3, 0.1, 1.0)).normalize();
        self.dir = f;
        self.up = u;
        let left = f.cross(u);
        self.samples = Vec::new();
        for dir in [u, -u, left, -left] {
            for k in -20..=20 {
                let e = f64::from(k) * 5e-9;
                for r in [1.0, 3.0, 7.0, 50.0, 123.456] {
                    let w = (dir + f * e + dir.cross(f) * (e * 0.7)).normalize();
                    let p = LIGHT_SPOT + w * r;
                    self.samples.push(FragmentInputs {
                        position: p,
                        normal: -w,
                        eye: LIGHT_SPOT + DVec3::new(30.0, 60.0, 90.0),
                        frag_coord: frag_of(p),
                    });
                }
            }
        }
    }

    /// The cases that change the surface: where the samples are and which way they face.
    fn surface_case(&mut self, case: Case) {
        match case {
            Case::LightOnSurface => {
                let lp = match self.model_light() {
                    Light::Point(p) => p.position,
                    Light::Spot(s) => s.position,
                    Light::Directional(_) => DVec3::ZERO,
                };
                self.samples = vec![
                    sample(lp, DVec3::Y, EYE),
                    sample(lp, DVec3::new(0.3, 0.9, 0.1), EYE),
                    sample(lp, DVec3::NEG_Y, EYE),
                ];
            }
            Case::ZeroNormal => {
                for s in &mut self.samples {
                    s.normal = DVec3::ZERO;
                }
            }
            Case::Grazing => self.grazing(),
            Case::BackFace => {
                self.samples = plane(DVec3::new(0.0, -140.0, 70.0));
                // L = −V exactly: the eye straight below the point, the light straight above.
                let lp = match self.model_light() {
                    Light::Point(p) => p.position,
                    _ => LIGHT_SPOT,
                };
                let p = DVec3::new(lp.x, 0.0, lp.z);
                self.samples
                    .push(sample(p, DVec3::Y, DVec3::new(lp.x, -lp.y, lp.z)));
            }
            Case::LightBehind => {
                for s in &mut self.samples {
                    s.normal = DVec3::NEG_Y;
                }
            }
            _ => {}
        }
    }

    /// Normals perpendicular to the light direction, and nudged either side of it.
    fn grazing(&mut self) {
        let light = self.model_light();
        let mut out = Vec::new();
        for s in &self.samples {
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
        self.samples = out;
    }

    /// The cases that change the material, the scale or the viewport.
    fn range_case(&mut self, case: Case) {
        match case {
            Case::Shininess0 => {
                self.shininess = 0.0;
                let mut behind = self.samples.clone();
                for s in &mut behind {
                    s.normal = DVec3::NEG_Y;
                }
                self.samples.extend(behind);
            }
            Case::Shininess1e4 => {
                self.shininess = 1e4;
                let (inner, outer) = self.cone;
                let scene = scene_of(
                    self.model,
                    self.shininess,
                    inner,
                    outer,
                    DVec3::NEG_Z,
                    self.dir,
                );
                self.samples.extend(highlight(&scene));
            }
            Case::ScaleMicro => self.scale = 1e-6,
            Case::ScaleMega => self.scale = 1e6,
            Case::MediumpRange => self.scale = 4.0,
            Case::ZeroViewport => self.viewport = [0.0, 0.0],
            _ => {}
        }
    }

    /// The scene the case gives, positions scaled.
    fn scene(&mut self) -> LitScene {
        let mut scene = scene_of(
            self.model,
            self.shininess,
            self.inner,
            self.outer,
            self.up,
            self.dir,
        );
        if self.scale != 1.0 {
            for s in &mut self.samples {
                s.position *= self.scale;
                s.eye *= self.scale;
            }
            for l in &mut scene.lights {
                match l {
                    Light::Point(p) => p.position *= self.scale,
                    Light::Spot(s) => s.position *= self.scale,
                    Light::Directional(_) => {}
                }
            }
        }
        scene
    }
}

/// Samples across a spot cone's edges at 0.5° steps, and on and just either side of them.
fn cone_shell(inner: f64, outer: f64) -> Vec<FragmentInputs> {
    shell(
        LIGHT_SPOT,
        DVec3::NEG_Y,
        &angles(
            0.0,
            180.0,
            0.5,
            &[inner, outer, inner + 1e-9, outer - 1e-9, outer + 1e-9],
        ),
    )
}

/// The scene and samples of `case` for `model`.
pub fn setup(model: Model, case: Case) -> Setup {
    let mut build = Build::new(model);
    build.cone_case(case);
    build.surface_case(case);
    build.range_case(case);
    let scene = build.scene();
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
        samples: build.samples,
        viewport: build.viewport,
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
