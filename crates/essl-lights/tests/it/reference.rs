//! The float64 reference renderer: geometry, interpolation, facing, exact surfaces, the
//! comparison helpers, and agreement between the library's model, its CPU mirror and the
//! scene bridge.

use crate::common;

use common::*;
use essl_lights::formulas::{library_fragment, FragmentInputs};
use essl_lights::real::F32;
use essl_lights::reference::*;
use essl_lights::*;
use essl_scene::{RgbaImage, Scene, SceneFile};
use glam::{DVec2, DVec3, DVec4};

fn base(mesh: &str, cull: bool) -> SceneFile {
    SceneFile::parse(&format!(
        r#"{{
      "width": 96, "height": 80, "clear_color": [0.5, 0.5, 0.5, 1], "cull_face": {cull},
      "vertex_shader": "x.vert", "fragment_shader": "x.frag",
      "mesh": {mesh},
      "attributes": {{"a_position": "position"}},
      "camera": {{"eye": [0, 80, 127], "target": [0, 0, 0], "up": [0, 1, 0],
                 "fov_y_deg": 60, "near": 1, "far": 1000}}
    }}"#
    ))
    .unwrap()
}

fn lit_scene(file: &SceneFile, lit: &LitScene) -> (Scene, LitShader) {
    let p = generate(lit).unwrap();
    let m = essl_scene::Matrices::new(&file.camera, &file.model, file.width, file.height).unwrap();
    let view = View {
        matrices: m,
        width: file.width,
        height: file.height,
    };
    let u = uniform_values(lit, &view).unwrap();
    let scene = bridge::to_scene(file, &p, &u).unwrap();
    let shader = LitShader::new(lit, &View::of_scene(&scene)).unwrap();
    (scene, shader)
}

fn point_phong() -> LitScene {
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

fn diff(a: &RefImage, b: &RefImage) -> RefDiff {
    compare_rgba8(
        &a.to_rgba8(),
        b,
        CompareOptions {
            ignore_silhouettes: true,
        },
    )
    .unwrap()
}

#[test]
fn exact_surface_shows_the_tessellation_error() {
    let fine = base(
        r#"{"kind": "sphere", "radius": 50, "segments": 48, "rings": 32}"#,
        true,
    );
    let coarse = base(
        r#"{"kind": "sphere", "radius": 50, "segments": 8, "rings": 6}"#,
        true,
    );
    let (s, sh) = lit_scene(&fine, &point_phong());
    let d_fine = diff(
        &render(&s, &sh, Geometry::Mesh).unwrap(),
        &render(&s, &sh, Geometry::Exact).unwrap(),
    );
    let (s, sh) = lit_scene(&coarse, &point_phong());
    let d_coarse = diff(
        &render(&s, &sh, Geometry::Mesh).unwrap(),
        &render(&s, &sh, Geometry::Exact).unwrap(),
    );
    assert!(d_fine.rms < 1.0 && d_fine.max < 8.0, "{d_fine:?}");
    assert!(d_coarse.rms > 5.0 && d_coarse.max > 50.0, "{d_coarse:?}");
}

#[test]
fn a_plane_is_exact() {
    let grid = base(r#"{"kind": "grid", "size": 200, "cells": 4}"#, true);
    let mut lit = point_phong();
    lit.reflection = Reflection::BlinnPhong;
    let (s, sh) = lit_scene(&grid, &lit);
    let m = render(&s, &sh, Geometry::Mesh).unwrap();
    let e = render(&s, &sh, Geometry::Exact).unwrap();
    assert!(m.coverage.iter().filter(|c| **c).count() > 1000);
    let mask = e.silhouette_mask(1);
    for (i, edge) in mask.iter().enumerate() {
        if !edge {
            assert_eq!(m.coverage[i], e.coverage[i]);
            assert!(
                (m.pixels[i] - e.pixels[i]).abs().max_element() < 1e-9,
                "{i}"
            );
        }
    }
}

#[test]
fn gouraud_equals_phong_where_lighting_is_linear() {
    // A directional light on a plane: constant normal, so per-vertex and per-pixel Lambert
    // lighting are the same everywhere.
    let grid = base(r#"{"kind": "grid", "size": 200, "cells": 3}"#, false);
    let mk = |shading| {
        LitScene::new(shading, Reflection::Lambert, Material::default())
            .with_ambient(DVec3::splat(0.1))
            .with_light(Light::Directional(DirectionalLight {
                direction: DVec3::new(-1.0, -1.0, -0.5),
                color: DVec3::ONE,
                specular: DVec3::ZERO,
            }))
    };
    let (s, g) = lit_scene(&grid, &mk(Shading::Gouraud));
    let a = render(&s, &g, Geometry::Mesh).unwrap();
    let (s, p) = lit_scene(&grid, &mk(Shading::Phong));
    let b = render(&s, &p, Geometry::Mesh).unwrap();
    assert!(a.coverage.iter().any(|c| *c));
    for (x, y) in a.pixels.iter().zip(&b.pixels) {
        assert!((*x - *y).abs().max_element() < 1e-12);
    }
}

#[test]
fn facing_and_culling_follow_gl() {
    let shader = FnShader {
        vertex: |_: &VertexIn| vec![],
        fragment: |f: &FragmentIn<'_>| {
            if f.front_facing {
                DVec4::new(1.0, 0.0, 0.0, 1.0)
            } else {
                DVec4::new(0.0, 0.0, 1.0, 1.0)
            }
        },
    };
    // The camera above the plane sees its front (+y) face.
    let above = base(r#"{"kind": "grid", "size": 100, "cells": 2}"#, true);
    let s = Scene::build(above.clone(), src("v"), src("f")).unwrap();
    let img = render(&s, &shader, Geometry::Mesh).unwrap();
    assert!(img.covered(48, 40));
    assert_eq!(img.pixel(48, 40), DVec4::new(1.0, 0.0, 0.0, 1.0));
    // From below: culled; without culling, a back face.
    let mut below = above.clone();
    below.camera.eye = [0.0, -80.0, 127.0];
    let s = Scene::build(below.clone(), src("v"), src("f")).unwrap();
    let img = render(&s, &shader, Geometry::Mesh).unwrap();
    assert!(!img.coverage.iter().any(|c| *c));
    below.cull_face = false;
    let s = Scene::build(below, src("v"), src("f")).unwrap();
    let img = render(&s, &shader, Geometry::Mesh).unwrap();
    assert_eq!(img.pixel(48, 40), DVec4::new(0.0, 0.0, 1.0, 1.0));
    // A mirrored model flips the winding in window space, as in GL.
    let mut mirrored = above;
    mirrored.model.scale = [-1.0, 1.0, 1.0];
    let s = Scene::build(mirrored, src("v"), src("f")).unwrap();
    let img = render(&s, &shader, Geometry::Mesh).unwrap();
    assert!(!img.coverage.iter().any(|c| *c));
}

fn src(name: &str) -> essl_scene::ShaderSource {
    essl_scene::ShaderSource {
        name: name.into(),
        path: name.into(),
        source: String::new(),
    }
}

#[test]
fn comparison_numbers() {
    let reference = RefImage {
        width: 3,
        height: 1,
        pixels: vec![
            DVec4::new(0.5, 0.0, 1.2, 1.0),
            DVec4::new(0.1, 0.2, 0.3, 1.0),
            DVec4::new(0.0, 0.0, 0.0, 1.0),
        ],
        coverage: vec![true, true, false],
    };
    let gpu = RgbaImage::new(3, 1, vec![128, 0, 255, 255, 26, 51, 80, 255, 0, 0, 0, 255]).unwrap();
    let d = compare_rgba8(&gpu, &reference, CompareOptions::default()).unwrap();
    assert_eq!(d.compared, 3);
    assert!((d.max - 3.5).abs() < 1e-9, "{d:?}"); // 80 vs 76.5
    assert_eq!(d.over_one, 1);
    assert_eq!(d.worst, Some((1, 0)));
    let d = compare_rgba8(
        &gpu,
        &reference,
        CompareOptions {
            ignore_silhouettes: true,
        },
    )
    .unwrap();
    // Pixel 0 has only covered neighbours; pixels 1 and 2 border the coverage change.
    assert_eq!((d.compared, d.ignored), (1, 2));
    assert!(compare_rgba8(
        &RgbaImage::new(1, 1, vec![0; 4]).unwrap(),
        &reference,
        CompareOptions::default()
    )
    .is_err());
}

#[test]
fn texture_sampling_matches_gl() {
    // 2x1: black, white.
    let t = [0, 0, 0, 255, 255, 255, 255, 255];
    use essl_scene::{Filter, Wrap};
    let s = |f, w, u: f64| sample_texture(2, 1, &t, f, w, DVec2::new(u, 0.5)).x;
    assert_eq!(s(Filter::Nearest, Wrap::Repeat, 0.25), 0.0);
    assert_eq!(s(Filter::Nearest, Wrap::Repeat, 0.75), 1.0);
    assert_eq!(s(Filter::Nearest, Wrap::Repeat, -0.25), 1.0);
    assert_eq!(s(Filter::Nearest, Wrap::Clamp, -0.25), 0.0);
    assert_eq!(s(Filter::Nearest, Wrap::Mirror, -0.25), 0.0);
    assert_eq!(s(Filter::Linear, Wrap::Clamp, 0.5), 0.5);
    assert_eq!(s(Filter::Linear, Wrap::Repeat, 0.0), 0.5);
    assert!(sample_texture(
        2,
        1,
        &t,
        Filter::Linear,
        Wrap::Clamp,
        DVec2::new(f64::NAN, 0.0)
    )
    .x
    .is_nan());
}

/// The CPU mirror of the generated fragment shader agrees with the model: exactly (to float64
/// rounding) in float64, within 1/255 in float32, for every light shape.
#[test]
fn mirror_matches_model() {
    let (_, view) = test_view();
    for reflection in REFLECTIONS {
        for shape in all_light_shapes() {
            let lit = scene_of(Shading::Phong, reflection, true, &[shape]);
            let prepared = lit.prepare().unwrap();
            let inv = view.inv_viewport().unwrap();
            let cookie64 = |_: usize, u: f64, t: f64| {
                essl_lights::real::V3::of(essl_lights::stiff::analytic_cookie(u, t))
            };
            let cookie32 = |_: usize, u: F32, t: F32| {
                use essl_lights::real::Real;
                essl_lights::real::V3::of(essl_lights::stiff::analytic_cookie(
                    u.to_f64(),
                    t.to_f64(),
                ))
            };
            for j in 0..15 {
                for i in 0..15 {
                    let p = DVec3::new(
                        -70.0 + 10.0 * f64::from(i),
                        0.0,
                        -70.0 + 10.0 * f64::from(j),
                    );
                    let f = FragmentInputs {
                        position: p,
                        normal: DVec3::new(0.1, 1.0, -0.05),
                        eye: DVec3::new(0.0, 140.0, 70.0),
                        frag_coord: DVec2::new(3.5 + f64::from(i) * 4.0, 2.5 + f64::from(j) * 3.0),
                    };
                    let s = ideal::Surface {
                        position: f.position,
                        normal: f.normal,
                        eye: f.eye,
                        frag_coord: f.frag_coord,
                    };
                    let want = ideal::color(
                        &lit,
                        &prepared,
                        &s,
                        &|_, uv| essl_lights::stiff::analytic_cookie(uv.x, uv.y),
                        DVec2::from_array(inv),
                    );
                    let got = library_fragment::<f64>(&lit, &prepared, inv, &f, &cookie64).to_f64();
                    assert!(
                        (want - got).abs().max_element() < 1e-9,
                        "{shape:?}: {want} {got}"
                    );
                    let got32 =
                        library_fragment::<F32>(&lit, &prepared, inv, &f, &cookie32).to_f64();
                    let e = (want.clamp(DVec3::ZERO, DVec3::ONE)
                        - got32.clamp(DVec3::ZERO, DVec3::ONE))
                    .abs()
                    .max_element()
                        * 255.0;
                    assert!(e <= 1.0, "{shape:?} {reflection:?}: {e}");
                }
            }
        }
    }
}

#[test]
fn bridge_round_trips_through_json() {
    let grid = base(r#"{"kind": "grid", "size": 200, "cells": 4}"#, true);
    let lit = scene_of(
        Shading::Gouraud,
        Reflection::BlinnPhong,
        true,
        &all_light_shapes()[2..8],
    );
    let (scene, _) = lit_scene(&grid, &lit);
    let p = generate(&lit).unwrap();
    // Every value uniform is in the scene, every sampler has a texture.
    for u in &p.uniforms {
        if u.ty == GlslType::Sampler2D {
            assert!(scene.texture(&u.name).is_some(), "{}", u.name);
        } else {
            assert!(scene.uniform(&u.name).is_some(), "{}", u.name);
        }
    }
    let dir = std::env::temp_dir().join(format!("essl-lights-bridge-{}", std::process::id()));
    let path = bridge::write_scene(&dir, "lit", &scene).unwrap();
    let again = Scene::load(&path).unwrap();
    let sorted = |s: &Scene| {
        let mut u = s.uniforms.clone();
        u.sort_by(|a, b| a.name.cmp(&b.name));
        u
    };
    assert_eq!(sorted(&again), sorted(&scene));
    assert_eq!(again.textures, scene.textures);
    assert_eq!(again.vertex_shader.source, p.vertex);
    assert_eq!(again.mesh, scene.mesh);
    std::fs::remove_dir_all(&dir).unwrap();
}
