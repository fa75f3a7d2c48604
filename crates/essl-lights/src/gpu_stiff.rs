//! The stiff-case matrix on the GPU: every (light model, case) row of [`crate::stiff`] drawn
//! through essl-gl with the library's specialised program and with the seed's program
//! ([`crate::seed_glsl`]), on a small canvas, and measured against the float64 model.
//!
//! **Geometry.** The CPU matrix evaluates chosen sample points; a GPU draws surfaces, so each
//! case gets a mesh and a camera that put the stiff configuration on pixels ([`gpu_setup`]):
//! the plane `y = 0` seen from above (most cases); the same scaled by 1e-6, 4 or 1e6; a plane
//! with zero normals, with normals turned away from the light, or half and half; a plane
//! through the light (the light on the surface); a plane containing the light's rays, with
//! normals on either side (grazing: `N·L = 0` exactly); the plane seen from below straight under
//! the light (back face, `L = −V` at the centre pixel); the inside of a sphere around a spot
//! light seen from the light (cones of 90°–180°); a zoom on the point 90° off a projector's
//! axis along its up vector, where article 003's `acos` receives dot products rounded past ±1;
//! a zoom on the shininess-1e4 highlight; the centre pixel on the cone's edge (limit on the
//! sample) or on its axis (0° cone). The canvas is odd-sized so the centre pixel's ray is the
//! camera's axis.
//!
//! **Measure.** Each program is drawn twice: as generated, and as its NaN probe
//! ([`crate::gpu::probe_program`]), whose flags count the fragments whose colour (or a texture
//! coordinate) was NaN or infinite. The picture is compared with the float64 model of the
//! case's reference scene ([`crate::gpu::reference_band`]: a band across hard edges), leaving
//! out the pixels within 1 pixel of a silhouette (a coverage change of the reference) and the
//! flagged ones; the error is the largest channel's distance in 1/255 units. Where the library
//! refuses the parameters (`LightsError`), its cell says `rejected`.

use std::fmt::Write as _;

use glam::{DVec2, DVec3};

use essl_scene::{Camera, MeshSpec, Model as ModelTransform, OrderedMap, SceneFile, Stream};

use crate::bridge;
use crate::error::LightsError;
use crate::gpu::{self, count_probe, probe_program, reference_band_jittered};
use crate::ideal;
use crate::program::ShaderPair;
use crate::reference::{compare_band_excluding, CompareOptions, Geometry};
use crate::scene::{Light, LitScene};
use crate::seed_glsl::{seed_program, seed_uniforms};
use crate::stiff::{self, Case, Model, Outcome, Setup, EYE, LIGHT_SPOT};
use crate::uniforms::{inv_viewport, uniform_values, Uniforms, View};

/// The canvas side the GPU matrix is drawn at by `essl report` (odd: the centre pixel's ray is
/// the camera axis).
pub const SIZE: u32 = 65;

/// A case's GPU scene.
#[derive(Clone, Debug)]
pub struct GpuSetup {
    /// The CPU matrix's setup: the scene (perhaps refused by the library), the reference scene
    /// and the viewport the seeds' JavaScript passes.
    pub cpu: Setup,
    /// Geometry, camera and canvas (shaders, uniforms and textures are filled in per program).
    pub base: SceneFile,
    /// What the picture shows, in a few words.
    pub geometry: &'static str,
    /// The reference band's world-space jitter ([`crate::gpu::reference_band_jittered`]): 0,
    /// or [`WORLD_JITTER`] where the picture holds a singular point.
    pub world_jitter: f64,
}

/// The world-space uncertainty of a float32 GPU's interpolated position near the light on the
/// surface (the light at 100 units: float32's spacing there is 8e-6, and perspective-correct
/// interpolation rounds a few times).
pub const WORLD_JITTER: f64 = 1e-4;

fn camera(eye: DVec3, target: DVec3, up: DVec3, fov_y_deg: f64, near: f64, far: f64) -> Camera {
    Camera {
        eye: eye.to_array(),
        target: target.to_array(),
        up: up.to_array(),
        fov_y_deg,
        near,
        far,
    }
}

fn file(mesh: MeshSpec, camera: Camera, size: u32) -> SceneFile {
    SceneFile {
        description: None,
        width: size,
        height: size,
        clear_color: [0.0, 0.0, 0.0, 1.0],
        depth_test: true,
        cull_face: false,
        vertex_shader: bridge::VERTEX_FILE.into(),
        fragment_shader: bridge::FRAGMENT_FILE.into(),
        mesh,
        attributes: OrderedMap(vec![
            ("a_position".into(), Stream::Position),
            ("a_normal".into(), Stream::Normal),
        ]),
        camera,
        model: ModelTransform::default(),
        uniforms: OrderedMap(Vec::new()),
        textures: OrderedMap(Vec::new()),
    }
}

/// Meshes as flat streams and indices.
#[derive(Default)]
struct Arrays {
    position: Vec<f64>,
    normal: Vec<f64>,
    indices: Vec<u32>,
}

impl Arrays {
    /// A square `cells`×`cells` grid centred at `centre`, spanned by unit `u` and `v`, `2·half`
    /// across, each vertex's normal `normal(position)`; triangles counter-clockwise about
    /// `u × v`.
    fn plane(
        &mut self,
        centre: DVec3,
        u: DVec3,
        v: DVec3,
        half: f64,
        cells: u32,
        normal: &dyn Fn(DVec3) -> DVec3,
    ) -> &mut Self {
        let base = (self.position.len() / 3) as u32;
        let n = cells;
        for j in 0..=n {
            for i in 0..=n {
                let s = -half + 2.0 * half * f64::from(i) / f64::from(n);
                let t = -half + 2.0 * half * f64::from(j) / f64::from(n);
                let p = centre + u * s + v * t;
                self.position.extend(p.to_array());
                self.normal.extend(normal(p).to_array());
            }
        }
        for j in 0..n {
            for i in 0..n {
                let a = base + j * (n + 1) + i;
                let (b, c) = (a + 1, a + n + 1);
                self.indices.extend([a, b, c, b, c + 1, c]);
            }
        }
        self
    }

    fn mesh(&self) -> MeshSpec {
        MeshSpec::Arrays {
            attributes: essl_scene::ArrayStreams {
                position: Some(self.position.clone()),
                normal: Some(self.normal.clone()),
                uv: None,
            },
            indices: Some(self.indices.clone()),
        }
    }
}

fn default_grid(scale: f64) -> MeshSpec {
    MeshSpec::Grid {
        size: 200.0 * scale,
        cells: 8,
    }
}

fn default_camera(scale: f64) -> Camera {
    camera(
        EYE * scale,
        DVec3::ZERO,
        DVec3::Y,
        60.0,
        scale,
        2000.0 * scale,
    )
}

fn light_position(scene: &LitScene) -> Option<DVec3> {
    match scene.lights.first()? {
        Light::Point(p) => Some(p.position),
        Light::Spot(s) => Some(s.position),
        Light::Directional(_) => None,
    }
}

fn outer_deg(scene: &LitScene) -> f64 {
    match scene.lights.first() {
        Some(Light::Spot(s)) => s.outer_deg,
        _ => 0.0,
    }
}

/// The point of the plane `y = 0` (normal +y, eye [`EYE`]) where the scene's specular term
/// peaks, on a 1-unit grid over [−100, 100]².
fn highlight_peak(scene: &LitScene) -> Result<DVec3, LightsError> {
    let prepared = scene.prepare()?;
    let mut best = (f64::NEG_INFINITY, DVec3::ZERO);
    for j in -100..=100 {
        for i in -100..=100 {
            let p = DVec3::new(f64::from(i), 0.0, f64::from(j));
            let s = ideal::Surface {
                position: p,
                normal: DVec3::Y,
                eye: EYE,
                frag_coord: DVec2::ZERO,
            };
            let v = ideal::color(scene, &prepared, &s, &|_, _| DVec3::ONE, DVec2::ZERO).x;
            if v > best.0 {
                best = (v, p);
            }
        }
    }
    Ok(best.1)
}

/// What a case's GPU picture shows: the mesh, the camera, a description, and how far the
/// reference moves the world (see [`GpuSetup::world_jitter`]).
struct Shot {
    mesh: MeshSpec,
    cam: Camera,
    geometry: &'static str,
    jitter: f64,
}

impl Shot {
    /// The default picture: the plane y = 0 from above, scaled by `scale`.
    fn plane(scale: f64, geometry: &'static str) -> Shot {
        Shot {
            mesh: default_grid(scale),
            cam: default_camera(scale),
            geometry,
            jitter: 0.0,
        }
    }

    /// The default plane seen by another camera.
    fn plane_from(cam: Camera, geometry: &'static str) -> Shot {
        Shot {
            cam,
            ..Shot::plane(1.0, geometry)
        }
    }

    /// Another mesh seen by another camera.
    fn of(mesh: MeshSpec, cam: Camera, geometry: &'static str) -> Shot {
        Shot {
            mesh,
            cam,
            geometry,
            jitter: 0.0,
        }
    }
}

/// The cases drawn on planes whose normals the case sets: zero, away from the light, or half
/// and half.
fn normals_shot(case: Case) -> Shot {
    let mut a = Arrays::default();
    let n = match case {
        Case::ZeroNormal => DVec3::ZERO,
        _ => DVec3::NEG_Y,
    };
    let geometry = if case == Case::Shininess0 {
        // Left half facing the light, right half away from it.
        // (A gap between the halves: a seam on a pixel centre would be a depth tie.)
        a.plane(
            DVec3::new(-51.0, 0.0, 0.0),
            DVec3::X,
            DVec3::Z,
            50.0,
            4,
            &|_| DVec3::Y,
        );
        a.plane(
            DVec3::new(51.0, 0.0, 0.0),
            DVec3::X,
            DVec3::Z,
            50.0,
            4,
            &|_| n,
        );
        "plane, left half normal +y, right half −y"
    } else {
        a.plane(DVec3::ZERO, DVec3::X, DVec3::Z, 100.0, 8, &|_| n);
        if case == Case::ZeroNormal {
            "plane with zero normals"
        } else {
            "plane with normals −y (away from the light)"
        }
    };
    Shot {
        mesh: a.mesh(),
        ..Shot::plane(1.0, geometry)
    }
}

/// A plane through the light, the centre pixel on it.
fn light_on_surface_shot(lp: Option<DVec3>) -> Shot {
    let p = lp.unwrap_or(LIGHT_SPOT);
    let mut a = Arrays::default();
    a.plane(p, DVec3::X, DVec3::Z, 100.0, 8, &|_| DVec3::Y);
    let cam = camera(
        p + DVec3::new(0.0, 40.0, 20.0),
        p,
        DVec3::Y,
        60.0,
        1.0,
        1000.0,
    );
    Shot {
        jitter: WORLD_JITTER,
        ..Shot::of(a.mesh(), cam, "plane through the light, centre pixel on it")
    }
}

/// A plane containing the light's rays: N·L = 0 at every point (exactly, for a positional
/// light on an axis-aligned plane). Left half normal +n, right half −n.
fn grazing_shot(scene: &LitScene, lp: Option<DVec3>) -> Shot {
    let (centre, n, u) = match (scene.lights.first(), lp) {
        (Some(Light::Directional(d)), _) => {
            let l = -d.direction.normalize();
            let n = l.cross(DVec3::Z).normalize();
            (DVec3::ZERO, n, l)
        }
        (_, Some(p)) => (p + DVec3::new(0.0, -60.0, 0.0), DVec3::X, DVec3::NEG_Y),
        _ => (DVec3::ZERO, DVec3::X, DVec3::Y),
    };
    let v = n.cross(u).normalize();
    let mut a = Arrays::default();
    a.plane(centre - v * 31.0, u, v, 30.0, 4, &|_| n);
    a.plane(centre + v * 31.0, u, v, 30.0, 4, &|_| -n);
    let cam = camera(centre + n * 120.0 + u * 10.0, centre, u, 60.0, 1.0, 1000.0);
    Shot::of(
        a.mesh(),
        cam,
        "plane containing the light's rays, halves with normals ±n",
    )
}

/// The inside of a sphere of radius 50 around the light, normals inwards, seen from the
/// light towards the middle of the cone's ramp.
fn wide_cone_shot(scene: &LitScene, lp: Option<DVec3>) -> Shot {
    let (inner, outer) = match scene.lights.first() {
        Some(Light::Spot(s)) => (s.inner_deg, s.outer_deg),
        _ => (0.0, 90.0),
    };
    let centre = lp.unwrap_or(LIGHT_SPOT);
    let sphere = essl_scene::Mesh::sphere(1.0, 64, 32);
    let pos = sphere.position.unwrap_or_default();
    let mut a = Arrays::default();
    for k in 0..pos.len() / 3 {
        let n = DVec3::new(pos[3 * k], pos[3 * k + 1], pos[3 * k + 2]);
        a.position.extend((centre + n * 50.0).to_array());
        a.normal.extend((-n).to_array());
    }
    a.indices = sphere.indices.unwrap_or_default();
    let t = (0.5 * (inner + outer)).to_radians();
    let w = DVec3::new(t.sin(), -t.cos(), 0.0);
    let cam = camera(centre, centre + w * 50.0, DVec3::Z, 60.0, 1.0, 200.0);
    Shot::of(
        a.mesh(),
        cam,
        "inside of a sphere around the light, seen from the light",
    )
}

/// A zoom on the point 90° off the projector's axis along its up vector.
fn acos_shot(scene: &LitScene, lp: Option<DVec3>) -> Shot {
    let (f, up) = match scene.lights.first() {
        Some(Light::Spot(s)) => match &s.cookie {
            Some(crate::Cookie::Projected { up, .. }) => (s.direction.normalize(), *up),
            _ => (s.direction.normalize(), DVec3::Y),
        },
        _ => (DVec3::NEG_Y, DVec3::Z),
    };
    let u = (up - f * up.dot(f)).normalize();
    let left = f.cross(u).normalize();
    let centre = lp.unwrap_or(LIGHT_SPOT);
    let target = centre + u * 50.0;
    let mut a = Arrays::default();
    a.plane(target, left, u.cross(left), 1.0, 2, &|_| -u);
    // ±0.05 units across at distance 10.
    let fov = 2.0 * (0.05f64 / 10.0).atan().to_degrees();
    let cam = camera(centre + u * 40.0, target, left, fov, 1.0, 100.0);
    Shot::of(a.mesh(), cam, "zoom on the point 90° off the axis along up")
}

/// The default plane, the camera aimed at `target` from the usual offset.
fn aimed_at(target: DVec3, geometry: &'static str) -> Shot {
    let cam = camera(
        target + DVec3::new(0.0, 140.0, 70.0),
        target,
        DVec3::Y,
        60.0,
        1.0,
        2000.0,
    );
    Shot::plane_from(cam, geometry)
}

/// The GPU scene of `case` for `model` on a `size`×`size` canvas (see the module docs).
pub fn gpu_setup(model: Model, case: Case, size: u32) -> Result<GpuSetup, LightsError> {
    let cpu = stiff::setup(model, case);
    let scene = &cpu.scene;
    let lp = light_position(scene);
    let shot = match case {
        Case::ScaleMicro => Shot::plane(1e-6, "plane from above, scene scaled"),
        Case::ScaleMega => Shot::plane(1e6, "plane from above, scene scaled"),
        Case::MediumpRange => Shot::plane(4.0, "plane from above, scene scaled"),
        Case::ZeroNormal | Case::LightBehind | Case::Shininess0 => normals_shot(case),
        Case::LightOnSurface => light_on_surface_shot(lp),
        Case::Grazing => grazing_shot(scene, lp),
        Case::BackFace => {
            let cam = camera(
                DVec3::new(EYE.x, -EYE.y, EYE.z),
                DVec3::ZERO,
                DVec3::Y,
                60.0,
                1.0,
                2000.0,
            );
            Shot::plane_from(cam, "plane seen from below, the light above")
        }
        Case::Cone90 | Case::Cone120 | Case::Cone180 => wide_cone_shot(scene, lp),
        Case::AcosPastOne => acos_shot(scene, lp),
        Case::Shininess1e4 => {
            let peak = highlight_peak(scene)?;
            let fov = 2.0 * (6.0 / (EYE - peak).length()).atan().to_degrees();
            let cam = camera(EYE, peak, DVec3::Y, fov, 1.0, 2000.0);
            Shot::plane_from(cam, "zoom on the highlight")
        }
        Case::LimitOnSample => {
            let p = lp.unwrap_or(LIGHT_SPOT);
            let r = p.y * outer_deg(scene).to_radians().tan();
            aimed_at(
                DVec3::new(p.x + r, 0.0, p.z),
                "plane, centre pixel on the outer cone",
            )
        }
        Case::Cone0 => {
            let p = lp.unwrap_or(LIGHT_SPOT);
            aimed_at(
                DVec3::new(p.x, 0.0, p.z),
                "plane, centre pixel on the cone's axis",
            )
        }
        _ => Shot::plane(1.0, "plane y = 0 from above"),
    };
    Ok(GpuSetup {
        cpu,
        base: file(shot.mesh, shot.cam, size),
        geometry: shot.geometry,
        world_jitter: shot.jitter,
    })
}

/// One row: the CPU matrix's row and the two GPU cells.
#[derive(Clone, Debug, PartialEq)]
pub struct GpuRow {
    /// The light model.
    pub model: Model,
    /// The case.
    pub case: Case,
    /// What the GPU picture shows.
    pub geometry: &'static str,
    /// The CPU matrix's row (float64, float32, binary16 evaluations of sample points).
    pub cpu: stiff::Row,
    /// The seed's program on the GPU.
    pub seed: Outcome,
    /// The library's specialised program on the GPU.
    pub library: Outcome,
}

/// Draws `program` and its probe on `setup`'s geometry and measures the picture.
fn measure(
    setup: &GpuSetup,
    view: &View,
    program: &ShaderPair,
    uniforms: &Uniforms,
) -> Result<Outcome, LightsError> {
    let scene = bridge::to_scene(&setup.base, program, uniforms)?;
    let image = gpu::render(&scene)?;
    let probe_scene = bridge::to_scene(&setup.base, &probe_program(program)?, uniforms)?;
    let probe = gpu::render(&probe_scene)?;
    let counts = count_probe(&probe);
    let fragments = counts.finite + counts.non_finite;
    let Some(reference) = &setup.cpu.reference else {
        return Ok(Outcome::Unmeasured {
            non_finite: counts.non_finite,
            samples: fragments,
        });
    };
    if reference.prepare().is_err() {
        // No meaningful reference (e.g. a projected cookie with a 0° cone).
        return Ok(Outcome::Unmeasured {
            non_finite: counts.non_finite,
            samples: fragments,
        });
    }
    let band =
        reference_band_jittered(&scene, reference, view, Geometry::Mesh, setup.world_jitter)?;
    let flagged: Vec<bool> = probe
        .data
        .chunks_exact(4)
        .map(|p| p == gpu::PROBE_NON_FINITE)
        .collect();
    let d = compare_band_excluding(
        &image,
        &band,
        CompareOptions {
            ignore_silhouettes: true,
        },
        &flagged,
    )?;
    Ok(Outcome::Measured {
        non_finite: counts.non_finite,
        samples: fragments,
        max_error: d.max,
    })
}

/// Evaluates one row on a `size`×`size` canvas (the CPU row is computed too).
pub fn evaluate(model: Model, case: Case, size: u32) -> Result<GpuRow, LightsError> {
    let setup = gpu_setup(model, case, size)?;
    let view = View {
        matrices: essl_scene::Matrices::new(
            &setup.base.camera,
            &setup.base.model,
            setup.base.width,
            setup.base.height,
        )?,
        width: size,
        height: size,
    };
    let scene = &setup.cpu.scene;
    let seed_viewport = if case == Case::ZeroViewport {
        setup.cpu.viewport
    } else {
        [f64::from(size); 2]
    };
    let seed = measure(
        &setup,
        &view,
        &seed_program(model.seed()),
        &seed_uniforms(model.seed(), scene, &view, seed_viewport)?,
    )?;
    let library = match crate::generate(scene).and_then(|p| {
        if scene.shape().has_screen_cookie() {
            inv_viewport(setup.cpu.viewport[0], setup.cpu.viewport[1])?;
        }
        Ok(p)
    }) {
        Err(e) => Outcome::Rejected(e.to_string()),
        Ok(p) => measure(&setup, &view, &p, &uniform_values(scene, &view)?)?,
    };
    Ok(GpuRow {
        model,
        case,
        geometry: setup.geometry,
        cpu: stiff::evaluate(model, case),
        seed,
        library,
    })
}

/// Every row of the matrix (every model × every case that applies), at `size`, in that order.
/// The rows are drawn on rayon's threads, each on a context of its own: most of a row's time is
/// the CPU's (the float64 model of every pixel, lavapipe's shading).
pub fn run(size: u32) -> Result<Vec<GpuRow>, LightsError> {
    use rayon::prelude::*;
    let pairs: Vec<(Model, Case)> = Model::ALL
        .into_iter()
        .flat_map(|m| {
            Case::ALL
                .into_iter()
                .filter(move |c| c.applies(m))
                .map(move |c| (m, c))
        })
        .collect();
    let rows: Vec<Result<GpuRow, LightsError>> = pairs
        .par_iter()
        .map(|&(m, c)| evaluate(m, c, size))
        .collect();
    // The first error in the matrix's order, as a walk in order would meet it.
    rows.into_iter().collect()
}

/// Counts: rows, rows where the seed's program fails on the GPU (NaN or more than 1/255 off),
/// rows where the library's does.
pub fn summary(rows: &[GpuRow]) -> (usize, usize, usize) {
    let seed = rows.iter().filter(|r| !r.seed.ok()).count();
    let lib = rows.iter().filter(|r| !r.library.ok()).count();
    (rows.len(), seed, lib)
}

/// The GPU matrix as a Markdown table, the CPU's `highp` cells beside the GPU's.
pub fn markdown(rows: &[GpuRow]) -> String {
    let mut s = String::from(
        "| light model | case | GPU picture | seed CPU highp | seed GPU | library CPU highp | library GPU |\n\
         | --- | --- | --- | --- | --- | --- | --- |\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} |",
            r.model.name(),
            r.case.name(),
            r.geometry,
            r.cpu.seed_highp.cell(),
            r.seed.cell(),
            r.cpu.library_highp.cell(),
            r.library.cell(),
        );
    }
    s
}

/// The start marker of the GPU section in `docs/numerical-stability.md`.
pub const BEGIN_MARKER: &str = "<!-- gpu-stiff-table:begin -->";
/// The end marker.
pub const END_MARKER: &str = "<!-- gpu-stiff-table:end -->";

/// The generated GPU section: how it was run, a summary line, where the GPU and the CPU's
/// float32 disagree about the seed, and the table.
pub fn document_section(rows: &[GpuRow], size: u32, renderer: &str) -> String {
    let (total, seed_fail, lib_fail) = summary(rows);
    let cpu_seed_fail = rows.iter().filter(|r| !r.cpu.seed_highp.ok()).count();
    let list = |pick: &dyn Fn(&GpuRow) -> bool| {
        let v: Vec<String> = rows
            .iter()
            .filter(|r| pick(r))
            .map(|r| {
                format!(
                    "{} / {} (CPU {}, GPU {})",
                    r.model.name(),
                    r.case.name(),
                    r.cpu.seed_highp.cell(),
                    r.seed.cell()
                )
            })
            .collect();
        if v.is_empty() {
            "none".to_string()
        } else {
            v.join("; ")
        }
    };
    let cpu_only = list(&|r| !r.cpu.seed_highp.ok() && r.seed.ok());
    let gpu_only = list(&|r| r.cpu.seed_highp.ok() && !r.seed.ok());
    let nan_kind = list(&|r| {
        r.cpu.seed_highp.finite() != r.seed.finite() && !r.seed.ok() && !r.cpu.seed_highp.ok()
    });
    format!(
        "{BEGIN_MARKER}\n\
         <!-- written by `essl report` (essl_lights::gpu_stiff); do not edit by hand -->\n\n\
         Drawn at {size}×{size} by essl-gl on `{renderer}` (every precision computed in 32 \
         bits). {total} (model, case) rows. The seed's program is NaN or more than 1/255 off \
         in **{seed_fail}** of them on the GPU (its formula in CPU float32: {cpu_seed_fail}); \
         the library's program in **{lib_fail}**.\n\n\
         - The seed fails in CPU float32 but not on the GPU: {cpu_only}.\n\
         - The seed fails on the GPU but not in CPU float32: {gpu_only}.\n\
         - Both fail, one with NaN and the other without: {nan_kind}.\n\n{}\n{END_MARKER}",
        markdown(rows)
    )
}

/// `doc` with the GPU section replaced by `section`, or `section` appended (after a blank
/// line) when the markers are absent.
pub fn replace_section(doc: &str, section: &str) -> String {
    if let Some(a) = doc.find(BEGIN_MARKER) {
        if let Some(b) = doc[a..].find(END_MARKER) {
            let b = a + b + END_MARKER.len();
            return format!("{}{}{}", &doc[..a], section, &doc[b..]);
        }
    }
    format!(
        "{}\n{section}\n",
        doc.trim_end_matches('\n').to_string() + "\n"
    )
}
