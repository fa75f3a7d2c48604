//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::collections::BTreeMap;

use glam::DVec3;

use essl_lights::*;
use essl_scene::{Filter, Wrap};

/// Every light shape with ordinary values.
pub fn light_of(shape: LightShape, k: usize) -> Light {
    let kf = k as f64;
    let color = DVec3::new(1.0, 0.9 - 0.05 * kf, 0.8);
    let specular = DVec3::new(0.5, 0.5, 0.6);
    match shape {
        LightShape::Directional => Light::Directional(DirectionalLight {
            direction: DVec3::new(-0.3 + 0.1 * kf, -1.0, -0.2),
            color,
            specular,
        }),
        LightShape::Point => Light::Point(PointLight {
            position: DVec3::new(30.0 - 5.0 * kf, 100.0, 20.0),
            color,
            specular,
        }),
        LightShape::Spot { edge, cookie } => Light::Spot(SpotLight {
            position: DVec3::new(5.0 * kf, 100.0, 0.0),
            direction: DVec3::new(0.05 * kf, -1.0, 0.0),
            inner_deg: 10.0,
            outer_deg: 20.0,
            edge,
            cookie: cookie.map(|c| {
                let image = CookieImage::checker(16, 4, Filter::Linear, Wrap::Repeat);
                match c {
                    CookieKind::Projected => Cookie::Projected {
                        up: DVec3::new(0.0, 0.0, -1.0),
                        image,
                    },
                    CookieKind::Screen => Cookie::Screen { image },
                }
            }),
            color,
            specular,
        }),
    }
}

/// Directional, point, and spot with every edge × cookie.
pub fn all_light_shapes() -> Vec<LightShape> {
    let mut v = vec![LightShape::Directional, LightShape::Point];
    for edge in [EdgeProfile::Step, EdgeProfile::Linear, EdgeProfile::Smooth] {
        for cookie in [None, Some(CookieKind::Projected), Some(CookieKind::Screen)] {
            v.push(LightShape::Spot { edge, cookie });
        }
    }
    v
}

pub const SHADINGS: [Shading; 2] = [Shading::Gouraud, Shading::Phong];
pub const REFLECTIONS: [Reflection; 3] = [
    Reflection::Lambert,
    Reflection::Phong,
    Reflection::BlinnPhong,
];

/// A scene of these light shapes.
pub fn scene_of(
    shading: Shading,
    reflection: Reflection,
    ambient: bool,
    shapes: &[LightShape],
) -> LitScene {
    let mut s = LitScene::new(shading, reflection, Material::default());
    if ambient {
        s = s.with_ambient(DVec3::splat(0.1));
    }
    for (k, &sh) in shapes.iter().enumerate() {
        s = s.with_light(light_of(sh, k));
    }
    s
}

/// The spot-smooth scene file's view (a 256×256 camera over a grid).
pub fn test_view() -> (essl_scene::SceneFile, View) {
    let json = r#"{
      "width": 64, "height": 48,
      "vertex_shader": "x.vert", "fragment_shader": "x.frag",
      "mesh": {"kind": "grid", "size": 200, "cells": 8},
      "attributes": {"a_position": "position"},
      "camera": {"eye": [0, 140, 70], "target": [0, 0, 0], "up": [0, 1, 0],
                 "fov_y_deg": 60, "near": 1, "far": 2000},
      "model": {"translate": [1, 2, 3], "rotate_deg": [10, 20, 30], "scale": [1, 2, 1]}
    }"#;
    let file = essl_scene::SceneFile::parse(json).unwrap();
    let m = essl_scene::Matrices::new(&file.camera, &file.model, file.width, file.height).unwrap();
    (
        file.clone(),
        View {
            matrices: m,
            width: file.width,
            height: file.height,
        },
    )
}

/// Checks a generated program: clean, minimal, and its uniform values match its declarations.
pub fn check_program(scene: &LitScene) -> Result<ShaderPair, String> {
    let p = generate(scene).map_err(|e| e.to_string())?;
    let v = verify(&p);
    if !v.is_minimal() {
        return Err(format!(
            "not clean/minimal: {v:#?}\n--- vertex\n{}\n--- fragment\n{}",
            p.vertex, p.fragment
        ));
    }
    // WebGL's active list covers every declared uniform.
    let declared: Vec<String> = p.uniforms.iter().map(|u| u.active_name()).collect();
    let mut active = v.active_uniforms.clone();
    active.sort();
    let mut d = declared.clone();
    d.sort();
    if active != d {
        return Err(format!("active {active:?} != declared {d:?}"));
    }
    let (_, view) = test_view();
    let u = uniform_values(scene, &view).map_err(|e| e.to_string())?;
    check_values(&p, &u)?;
    Ok(p)
}

/// The values cover exactly the declared uniforms, with matching types and lengths.
pub fn check_values(p: &ShaderPair, u: &Uniforms) -> Result<(), String> {
    let declared: BTreeMap<&str, &UniformDecl> =
        p.uniforms.iter().map(|d| (d.name.as_str(), d)).collect();
    let mut set: Vec<&str> = u.values.iter().map(|s| s.name.as_str()).collect();
    set.sort();
    let mut want: Vec<&str> = declared.keys().copied().collect();
    // Uber samplers without a cookie are left unset (they read unit 0 and are never sampled).
    if p.uniforms.iter().any(|d| d.array.is_some()) {
        want.retain(|n| !n.starts_with("u_cookie") || set.contains(n));
    }
    if set != want {
        return Err(format!("values for {set:?}, declared {want:?}"));
    }
    for s in &u.values {
        let d = declared[s.name.as_str()];
        if d.ty != s.ty {
            return Err(format!("{}: declared {:?}, value {:?}", s.name, d.ty, s.ty));
        }
        let n = match &s.data {
            UniformData::Floats(v) => v.len(),
            UniformData::Ints(v) => v.len(),
            UniformData::Sampler(_) => 0,
        };
        if n != d.ty.components() * d.len() {
            return Err(format!(
                "{}: {n} values for {:?}[{}]",
                s.name,
                d.ty,
                d.len()
            ));
        }
        if let UniformData::Floats(v) = &s.data {
            if v.iter().any(|x| !x.is_finite() || !(*x as f32).is_finite()) {
                return Err(format!("{}: non-finite value {v:?}", s.name));
            }
        }
    }
    Ok(())
}
