//! The report's variants: each a lit scene on a geometry, drawn by one program.

use std::path::Path;

use glam::{DVec2, DVec3, DVec4};

use essl_scene::{Camera, Filter, MeshSpec, Model, OrderedMap, Scene, SceneFile, Stream, Wrap};

use crate::bridge;
use crate::error::LightsError;
use crate::formulas::{library_fragment, FragmentInputs, Seed};
use crate::gpu_stiff::gpu_setup;
use crate::program::ShaderPair;
use crate::real::{Real, F16, V3};
use crate::reference::{sample_texture, FragmentIn, RefShader, VertexIn};
use crate::scene::*;
use crate::seed_glsl::{seed_program, seed_uniforms};
use crate::stiff::{Case, Model as StiffModel};
use crate::uniforms::{uber_uniform_values, uniform_values, Uniforms, View};

/// What a variant is about (one colour in the chart).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Group {
    /// Gouraud against Phong shading at several tessellations of the plane.
    Shading,
    /// A small spot between the vertices of a coarse grid.
    SmallSpot,
    /// Step, linear and smooth spot edges.
    Edge,
    /// `highp` against (emulated) `mediump`.
    Precision,
    /// Article 003's `acos` projector coordinates against the library's `atan` ones.
    Projector,
    /// The specialised program against the uber-shader, on the shared seed scenes.
    Program,
}

impl Group {
    /// Every group, in report order.
    pub const ALL: [Group; 6] = [
        Group::Shading,
        Group::SmallSpot,
        Group::Edge,
        Group::Precision,
        Group::Projector,
        Group::Program,
    ];

    /// The group's title.
    pub fn title(self) -> &'static str {
        match self {
            Group::Shading => "Gouraud vs Phong × tessellation",
            Group::SmallSpot => "small spot between vertices",
            Group::Edge => "spot edge profile",
            Group::Precision => "highp vs mediump",
            Group::Projector => "projector coordinates",
            Group::Program => "specialised vs uber (seed scenes)",
        }
    }
}

/// The program a variant is drawn with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProgramKind {
    /// The specialised program ([`crate::generate`]).
    Specialised,
    /// The specialised program with `precision mediump float`: lavapipe draws it in 32 bits
    /// (its time is measured), its error is the CPU's binary16 emulation
    /// ([`MediumpShader`]).
    Mediump,
    /// The uber-shader ([`crate::generate_uber`]).
    Uber,
    /// A seed's formulas ([`crate::seed_glsl`]).
    Seed(Seed),
}

/// One variant of the report.
#[derive(Clone, Debug)]
pub struct Variant {
    /// Its group.
    pub group: Group,
    /// The row name.
    pub name: String,
    /// The chart label (short).
    pub label: String,
    /// The scene (lights and material).
    pub lit: LitScene,
    /// Geometry, camera and canvas; the canvas size is set per drawing.
    pub base: SceneFile,
    /// The program.
    pub program: ProgramKind,
}

impl Variant {
    /// The program's shaders.
    pub fn shaders(&self) -> Result<ShaderPair, LightsError> {
        Ok(match self.program {
            ProgramKind::Specialised => crate::generate(&self.lit)?,
            ProgramKind::Mediump => {
                let mut p = crate::generate(&self.lit)?;
                p.fragment =
                    p.fragment
                        .replacen("precision highp float;", "precision mediump float;", 1);
                p
            }
            ProgramKind::Uber => crate::generate_uber(),
            ProgramKind::Seed(s) => seed_program(s),
        })
    }

    /// The uniform values for `view`.
    pub fn uniforms(&self, view: &View) -> Result<Uniforms, LightsError> {
        match self.program {
            ProgramKind::Specialised | ProgramKind::Mediump => uniform_values(&self.lit, view),
            ProgramKind::Uber => uber_uniform_values(&self.lit, view),
            ProgramKind::Seed(s) => seed_uniforms(
                s,
                &self.lit,
                view,
                [f64::from(view.width), f64::from(view.height)],
            ),
        }
    }

    /// The scene file at `size`×`size`.
    pub fn file(&self, size: u32) -> SceneFile {
        let mut f = self.base.clone();
        f.width = size;
        f.height = size;
        f
    }

    /// The drawable scene at `size`×`size` with `program` (the variant's, or its probe) and
    /// its view.
    pub fn scene_with(
        &self,
        size: u32,
        program: &ShaderPair,
    ) -> Result<(Scene, View), LightsError> {
        let f = self.file(size);
        let view = View {
            matrices: essl_scene::Matrices::new(&f.camera, &f.model, size, size)?,
            width: size,
            height: size,
        };
        let u = self.uniforms(&view)?;
        Ok((bridge::to_scene(&f, program, &u)?, view))
    }

    /// The drawable scene at `size`×`size` and its view.
    pub fn scene(&self, size: u32) -> Result<(Scene, View), LightsError> {
        self.scene_with(size, &self.shaders()?)
    }
}

/// The library's Phong-shading fragment shader evaluated in binary16 (`mediump` on a mobile
/// GPU: every value and operation rounded to 11 significant bits, ±65504): the vertex stage
/// in float64 (a `highp` vertex shader is float32, far finer than binary16), the varyings,
/// uniforms and texels rounded to binary16 on input, as [`library_fragment`] does.
pub struct MediumpShader {
    lit: LitScene,
    prepared: PreparedScene,
    model: glam::DMat4,
    normal: glam::DMat3,
    eye: DVec3,
    inv_viewport: [f64; 2],
}

impl MediumpShader {
    /// The emulation for `lit` (Phong shading only) seen from `view`.
    pub fn new(lit: &LitScene, view: &View) -> Result<MediumpShader, LightsError> {
        if lit.shading != Shading::Phong {
            return Err(LightsError::Reference(
                "the mediump emulation mirrors the Phong-shading fragment shader".into(),
            ));
        }
        Ok(MediumpShader {
            lit: lit.clone(),
            prepared: lit.prepare()?,
            model: glam::DMat4::from_cols_array(&view.matrices.model.0),
            normal: glam::DMat3::from_cols_array(&view.normal_matrix()?),
            eye: DVec3::from_array(view.matrices.eye),
            inv_viewport: view.inv_viewport().unwrap_or([0.0, 0.0]),
        })
    }
}

impl RefShader for MediumpShader {
    fn vertex(&self, v: &VertexIn) -> Vec<f64> {
        let p = (self.model * v.position.extend(1.0)).truncate();
        let n = self.normal * v.normal;
        vec![p.x, p.y, p.z, n.x, n.y, n.z]
    }

    fn fragment(&self, f: &FragmentIn<'_>) -> DVec4 {
        let v = f.varyings;
        let s = FragmentInputs {
            position: DVec3::new(v[0], v[1], v[2]),
            normal: DVec3::new(v[3], v[4], v[5]),
            eye: self.eye,
            frag_coord: f.frag_coord,
        };
        let cookie = |i: usize, u: F16, t: F16| -> V3<F16> {
            match &self.lit.lights[i] {
                Light::Spot(SpotLight {
                    cookie: Some(c), ..
                }) => {
                    let img = c.image();
                    let rgb = sample_texture(
                        img.width,
                        img.height,
                        &img.texels,
                        img.filter,
                        img.wrap,
                        DVec2::new(u.to_f64(), t.to_f64()),
                    )
                    .truncate();
                    V3::of(rgb)
                }
                _ => V3::splat(F16::of(1.0)),
            }
        };
        library_fragment::<F16>(&self.lit, &self.prepared, self.inv_viewport, &s, &cookie)
            .to_f64()
            .extend(1.0)
    }
}

fn plane_file(cells: u32, cull: bool) -> SceneFile {
    SceneFile {
        description: None,
        width: 256,
        height: 256,
        clear_color: [0.0, 0.0, 0.0, 1.0],
        depth_test: true,
        cull_face: cull,
        vertex_shader: bridge::VERTEX_FILE.into(),
        fragment_shader: bridge::FRAGMENT_FILE.into(),
        mesh: MeshSpec::Grid { size: 200.0, cells },
        attributes: OrderedMap(vec![
            ("a_position".into(), Stream::Position),
            ("a_normal".into(), Stream::Normal),
        ]),
        camera: Camera {
            eye: [0.0, 140.0, 70.0],
            target: [0.0, 0.0, 0.0],
            up: [0.0, 1.0, 0.0],
            fov_y_deg: 60.0,
            near: 1.0,
            far: 2000.0,
        },
        model: Model::default(),
        uniforms: OrderedMap(Vec::new()),
        textures: OrderedMap(Vec::new()),
    }
}

fn sphere_file() -> SceneFile {
    let mut f = plane_file(1, true);
    f.clear_color = [0.5, 0.5, 0.5, 1.0];
    f.mesh = MeshSpec::Sphere {
        radius: 50.0,
        segments: 48,
        rings: 32,
    };
    f.camera.eye = [0.0, 80.0, 127.0];
    f.camera.far = 1000.0;
    f
}

/// The spot-smooth seed scene in the library's model: a spot at (0, 100, 0) pointing down,
/// 10°/20°, Blinn–Phong, green plane with a red highlight.
pub fn spot_scene(shading: Shading, edge: EdgeProfile) -> LitScene {
    LitScene::new(
        shading,
        Reflection::BlinnPhong,
        Material {
            ambient: DVec3::ZERO,
            diffuse: DVec3::new(0.2, 1.0, 0.2),
            specular: DVec3::ONE,
            shininess: 150.0,
        },
    )
    .with_light(Light::Spot(SpotLight {
        position: DVec3::new(0.0, 100.0, 0.0),
        direction: DVec3::NEG_Y,
        inner_deg: 10.0,
        outer_deg: 20.0,
        edge,
        cookie: None,
        color: DVec3::new(1.0, 0.6, 0.6),
        specular: DVec3::new(1.0, 0.2, 0.2),
    }))
}

/// A small spot (3°/5°, 8.7 units wide on the plane) aimed at the centre of a cell of the
/// 4×4 grid, (25, 0, 25): no vertex of that grid is lit; ambient light shows the plane.
pub fn small_spot_scene(shading: Shading) -> LitScene {
    LitScene::new(
        shading,
        Reflection::BlinnPhong,
        Material {
            ambient: DVec3::new(1.0, 0.9, 0.7),
            diffuse: DVec3::new(1.0, 0.9, 0.7),
            specular: DVec3::splat(0.5),
            shininess: 30.0,
        },
    )
    .with_ambient(DVec3::splat(0.15))
    .with_light(Light::Spot(SpotLight {
        position: DVec3::new(25.0, 100.0, 25.0),
        direction: DVec3::NEG_Y,
        inner_deg: 3.0,
        outer_deg: 5.0,
        edge: EdgeProfile::Smooth,
        cookie: None,
        color: DVec3::ONE,
        specular: DVec3::ONE,
    }))
}

/// The phong-positional seed scene in the library's model: a point light at (100, 100, 100)
/// on a blue sphere, Phong reflection, ambient.
pub fn point_scene() -> LitScene {
    LitScene::new(
        Shading::Phong,
        Reflection::Phong,
        Material {
            ambient: DVec3::new(0.2, 0.5, 1.0),
            diffuse: DVec3::new(0.2, 0.5, 1.0),
            specular: DVec3::ONE,
            shininess: 30.0,
        },
    )
    .with_ambient(DVec3::splat(0.1))
    .with_light(Light::Point(PointLight {
        position: DVec3::new(100.0, 100.0, 100.0),
        color: DVec3::ONE,
        specular: DVec3::ONE,
    }))
}

/// The projector cookie of the report: 8×8 cells of 8 texels, repeat, with `filter`.
pub fn projector_cookie(filter: Filter) -> CookieImage {
    CookieImage::checker(64, 8, filter, Wrap::Repeat)
}

/// The stiff matrix's projector (a 100°/120° smooth spot at (0, 100, 0) along (1, −2, 0.5),
/// up vector orthogonal to it) with [`projector_cookie`], and the zoomed view of its "acos
/// past ±1" case (`zoom`) or the plane from above.
fn projector(zoom: bool, filter: Filter) -> Result<(LitScene, SceneFile), LightsError> {
    let setup = gpu_setup(StiffModel::SpotProjected, Case::AcosPastOne, 256)?;
    let mut lit = setup.cpu.scene.clone();
    lit.material.diffuse = DVec3::new(1.0, 0.9, 0.8);
    if let Some(Light::Spot(s)) = lit.lights.first_mut() {
        if let Some(Cookie::Projected { image, .. }) = &mut s.cookie {
            *image = projector_cookie(filter);
        }
    }
    let file = if zoom {
        setup.base
    } else {
        plane_file(8, false)
    };
    Ok((lit, file))
}

/// How much of the report to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Extent {
    /// Every variant.
    Full,
    /// Fewer tessellations (for the quick run).
    Quick,
}

/// Every variant of the report; the seed scenes' pairs only when `scenes` (the folder of
/// `shared/scenes`) holds them.
pub fn variants(extent: Extent, scenes: Option<&Path>) -> Result<Vec<Variant>, LightsError> {
    let mut v = Vec::new();
    let tess: &[u32] = match extent {
        Extent::Full => &[2, 8, 32, 128],
        Extent::Quick => &[2, 32],
    };
    for &cells in tess {
        for (shading, s) in [(Shading::Gouraud, "Gouraud"), (Shading::Phong, "Phong")] {
            v.push(Variant {
                group: Group::Shading,
                name: format!("{s}, grid {cells}×{cells}"),
                label: format!("{}{cells}", &s[..1]),
                lit: spot_scene(shading, EdgeProfile::Smooth),
                base: plane_file(cells, true),
                program: ProgramKind::Specialised,
            });
        }
    }
    let small: &[u32] = match extent {
        Extent::Full => &[4, 64],
        Extent::Quick => &[4],
    };
    for &cells in small {
        for (shading, s) in [(Shading::Gouraud, "Gouraud"), (Shading::Phong, "Phong")] {
            v.push(Variant {
                group: Group::SmallSpot,
                name: format!("small spot, {s}, grid {cells}×{cells}"),
                label: format!("small {}{cells}", &s[..1]),
                lit: small_spot_scene(shading),
                base: plane_file(cells, true),
                program: ProgramKind::Specialised,
            });
        }
    }
    for (edge, s) in [
        (EdgeProfile::Step, "step"),
        (EdgeProfile::Linear, "linear"),
        (EdgeProfile::Smooth, "smooth"),
    ] {
        v.push(Variant {
            group: Group::Edge,
            name: format!("{s} edge (Phong, grid 8×8)"),
            label: s.into(),
            lit: spot_scene(Shading::Phong, edge),
            base: plane_file(8, true),
            program: ProgramKind::Specialised,
        });
    }
    for (lit, base, what, short) in [
        (
            spot_scene(Shading::Phong, EdgeProfile::Smooth),
            plane_file(8, true),
            "spot plane",
            "spot",
        ),
        (point_scene(), sphere_file(), "point-lit sphere", "sphere"),
    ] {
        for (kind, p) in [
            (ProgramKind::Specialised, "highp"),
            (ProgramKind::Mediump, "mediump"),
        ] {
            v.push(Variant {
                group: Group::Precision,
                name: format!("{what}, {p}"),
                label: format!("{short} {}", &p[..1]),
                lit: lit.clone(),
                base: base.clone(),
                program: kind,
            });
        }
    }
    for (zoom, filter, view, tag) in [
        (false, Filter::Linear, "plane", ""),
        (false, Filter::Nearest, "plane, nearest", " near"),
        (true, Filter::Nearest, "zoom along up", " zoom"),
    ] {
        let (lit, base) = projector(zoom, filter)?;
        for (kind, p, short) in [
            (ProgramKind::Specialised, "library atan", "atan"),
            (
                ProgramKind::Seed(Seed::A003Projected),
                "seed 003 acos",
                "acos",
            ),
        ] {
            v.push(Variant {
                group: Group::Projector,
                name: format!("projected cookie, {p}, {view}"),
                label: format!("{short}{tag}"),
                lit: lit.clone(),
                base: base.clone(),
                program: kind,
            });
        }
    }
    if let Some(dir) = scenes {
        for name in SEED_SCENES {
            let path = dir.join(format!("{name}.json"));
            if !path.is_file() {
                continue;
            }
            let scene = Scene::load(&path)?;
            let Some(lit) = crate::presets::seed_equivalent(&scene)? else {
                continue;
            };
            for (kind, p) in [
                (ProgramKind::Specialised, "spec"),
                (ProgramKind::Uber, "uber"),
            ] {
                v.push(Variant {
                    group: Group::Program,
                    name: format!("{name}, {p}"),
                    label: format!("{} {p}", short_name(name)),
                    lit: lit.clone(),
                    base: scene.file.clone(),
                    program: kind,
                });
            }
        }
    }
    Ok(v)
}

/// The shared seed scenes the report compares the specialised program and the uber-shader on.
pub const SEED_SCENES: [&str; 7] = [
    "spot-smooth",
    "spot-hard",
    "spot-linear",
    "spot-cookie",
    "phong-positional",
    "gouraud-lambert",
    "gouraud-lambert-coarse",
];

fn short_name(scene: &str) -> &'static str {
    match scene {
        "spot-smooth" => "ss",
        "spot-hard" => "sh",
        "spot-linear" => "sl",
        "spot-cookie" => "sc",
        "phong-positional" => "pp",
        "gouraud-lambert" => "gl",
        "gouraud-lambert-coarse" => "glc",
        _ => "?",
    }
}
