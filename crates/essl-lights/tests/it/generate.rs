//! The generators' output compiles and links with `essl` with zero diagnostics; specialised
//! programs are minimal (every declared uniform active, no unused function or varying) and
//! contain nothing for absent features.

use crate::common;

use common::*;
use essl_lights::*;
use proptest::prelude::*;

#[test]
fn every_single_light_shape_in_every_model() {
    let mut n = 0;
    for shading in SHADINGS {
        for reflection in REFLECTIONS {
            for ambient in [false, true] {
                let mut sets: Vec<Vec<LightShape>> = vec![vec![]];
                sets.extend(all_light_shapes().into_iter().map(|s| vec![s]));
                for shapes in sets {
                    let scene = scene_of(shading, reflection, ambient, &shapes);
                    if let Err(e) = check_program(&scene) {
                        panic!("{shading:?} {reflection:?} ambient={ambient} {shapes:?}: {e}");
                    }
                    n += 1;
                }
            }
        }
    }
    assert_eq!(n, 2 * 3 * 2 * 12);
}

#[test]
fn many_lights_of_every_kind() {
    let all = all_light_shapes();
    for shading in SHADINGS {
        for reflection in REFLECTIONS {
            for chunk in all.chunks(MAX_LIGHTS) {
                let scene = scene_of(shading, reflection, true, chunk);
                check_program(&scene).unwrap_or_else(|e| panic!("{chunk:?}: {e}"));
            }
            // Two screen-cookie lights and nothing else (Gouraud: no v_color at all).
            let two = [
                LightShape::Spot {
                    edge: EdgeProfile::Smooth,
                    cookie: Some(CookieKind::Screen),
                },
                LightShape::Spot {
                    edge: EdgeProfile::Step,
                    cookie: Some(CookieKind::Screen),
                },
            ];
            check_program(&scene_of(shading, reflection, false, &two)).unwrap();
        }
    }
}

#[test]
fn absent_features_leave_no_trace() {
    let scene = scene_of(
        Shading::Phong,
        Reflection::Lambert,
        false,
        &[LightShape::Directional],
    );
    let p = check_program(&scene).unwrap();
    let text = format!("{}{}", p.vertex, p.fragment);
    for absent in [
        "u_eye",
        "u_shininess",
        "v_position",
        "u_model;",
        "el_power",
        "el_edge",
        "cookie",
        "sampler",
        "u_ambient",
        "specular",
        "gl_FragCoord",
        "u_invViewport",
    ] {
        assert!(!text.contains(absent), "{absent} in\n{text}");
    }
    // No light at all: just the transform and black.
    let p = check_program(&scene_of(
        Shading::Phong,
        Reflection::BlinnPhong,
        false,
        &[],
    ))
    .unwrap();
    assert_eq!(p.uniforms.len(), 1);
    assert_eq!(p.attributes.len(), 1);
    assert!(p.varyings.is_empty());
    // Gouraud keeps the fragment shader trivial unless a screen cookie needs gl_FragCoord.
    let p = check_program(&scene_of(
        Shading::Gouraud,
        Reflection::Phong,
        true,
        &[LightShape::Point],
    ))
    .unwrap();
    assert!(p.uniforms.iter().all(|u| !u.stages.fragment));
    assert_eq!(p.varyings.len(), 1);
}

#[test]
fn uber_shader_compiles_and_links_clean() {
    let p = generate_uber();
    let v = verify(&p);
    assert!(v.is_clean(), "{v:#?}");
    assert!(v.unused_functions.is_empty(), "{v:#?}");
    // Every declared uniform is active too.
    assert!(v.inactive_uniforms.is_empty(), "{v:#?}");
    let (_, view) = test_view();
    for shading in SHADINGS {
        for reflection in REFLECTIONS {
            let shapes: Vec<LightShape> = all_light_shapes().into_iter().step_by(3).collect();
            for chunk in shapes.chunks(UBER_MAX_LIGHTS) {
                let scene = scene_of(shading, reflection, true, chunk);
                let u = uber_uniform_values(&scene, &view).unwrap();
                check_values(&p, &u).unwrap_or_else(|e| panic!("{chunk:?}: {e}"));
            }
        }
    }
}

#[test]
fn specialised_is_smaller_than_uber() {
    let uber = generate_uber();
    for shape in all_light_shapes() {
        let scene = scene_of(Shading::Phong, Reflection::BlinnPhong, true, &[shape]);
        let p = generate(&scene).unwrap();
        assert!(p.uniforms.len() < uber.uniforms.len());
        assert!(p.uniform_scalars() < uber.uniform_scalars());
        assert!(p.fragment.len() < uber.fragment.len());
    }
}

fn arb_shape() -> impl Strategy<Value = LightShape> {
    (0usize..11).prop_map(|i| all_light_shapes()[i])
}

fn arb_vec(lo: f64, hi: f64) -> impl Strategy<Value = glam::DVec3> {
    (lo..hi, lo..hi, lo..hi).prop_map(|(x, y, z)| glam::DVec3::new(x, y, z))
}

fn arb_scene() -> impl Strategy<Value = LitScene> {
    (
        prop::sample::select(SHADINGS.to_vec()),
        prop::sample::select(REFLECTIONS.to_vec()),
        prop::option::of(arb_vec(0.0, 1.0)),
        prop::collection::vec(
            (
                arb_shape(),
                arb_vec(-200.0, 200.0),
                arb_vec(-1.0, 1.0),
                0.0f64..180.0,
                0.0f64..1.0,
                arb_vec(0.0, 2.0),
            ),
            0..=MAX_LIGHTS,
        ),
        prop_oneof![Just(0.0), 1.0f64..10_000.0],
        arb_vec(0.0, 1.0),
    )
        .prop_map(
            |(shading, reflection, ambient, lights, shininess, diffuse)| {
                let mut s = LitScene::new(
                    shading,
                    reflection,
                    Material {
                        ambient: glam::DVec3::splat(0.5),
                        diffuse,
                        specular: glam::DVec3::splat(0.3),
                        shininess,
                    },
                );
                s.ambient_light = ambient;
                for (k, (shape, pos, dir, outer, frac, color)) in lights.into_iter().enumerate() {
                    let mut l = light_of(shape, k);
                    match &mut l {
                        Light::Directional(d) => {
                            d.direction = dir;
                            d.color = color;
                        }
                        Light::Point(p) => {
                            p.position = pos;
                            p.color = color;
                        }
                        Light::Spot(sp) => {
                            sp.position = pos;
                            sp.direction = dir;
                            sp.outer_deg = outer;
                            sp.inner_deg = outer * frac;
                            sp.color = color;
                            if let Some(Cookie::Projected { up, .. }) = &mut sp.cookie {
                                *up = glam::DVec3::new(dir.z, dir.x, -dir.y) + glam::DVec3::X * 0.3;
                            }
                        }
                    }
                    s.lights.push(l);
                }
                s
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Any scene the API accepts gives a clean, minimal program whose uniform values match its
    /// declarations; any it refuses is refused by the generator too.
    #[test]
    fn random_scenes(scene in arb_scene()) {
        match scene.validate() {
            Ok(()) => {
                if let Err(e) = check_program(&scene) {
                    prop_assert!(false, "{e}");
                }
            }
            Err(_) => prop_assert!(generate(&scene).is_err()),
        }
    }
}
