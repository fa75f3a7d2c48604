//! The shared seed scenes described as lit scenes: the same lights, colours and cone, in the
//! library's model and world space — what the specialised generator emits for each seed scene,
//! and what the GPU comparison renders with the library's shaders.
//!
//! The library's model differs from the seeds' formulas on purpose where those are fragile or
//! wrong (see `docs/numerical-stability.md`): the Lambert term is clamped, the specular term is
//! weighted by `max(N·L, 0)` instead of gated by `step(0.1, light)` or `if (lambert > 0)`, and a
//! cookie multiplies the light by its RGB rather than by `length(rgb)` (which makes white √3
//! bright).

use glam::{DMat4, DVec3};

use essl_scene::{Resolved, Scene};

use crate::error::LightsError;
use crate::scene::*;

fn values(scene: &Scene, name: &str) -> Result<Vec<f64>, LightsError> {
    let u = scene
        .uniform(name)
        .ok_or_else(|| LightsError::Reference(format!("the scene does not set {name}")))?;
    Ok(match &u.resolved {
        Resolved::Values(v) => v.clone(),
        Resolved::Matrix(m) => m.0.to_vec(),
    })
}

fn v3(scene: &Scene, name: &str) -> Result<DVec3, LightsError> {
    let v = values(scene, name)?;
    Ok(DVec3::new(v[0], v[1], v[2]))
}

fn cone_deg(scene: &Scene, name: &str) -> Result<f64, LightsError> {
    Ok(values(scene, name)?[0].clamp(-1.0, 1.0).acos().to_degrees())
}

/// The library's description of a shared seed scene (chosen by its fragment shader's name), or
/// `None` for a scene not modelled.
pub fn seed_equivalent(scene: &Scene) -> Result<Option<LitScene>, LightsError> {
    let name = scene.fragment_shader.name.as_str();
    Ok(Some(match name {
        "spot-smooth.frag" | "spot-hard.frag" | "spot-linear.frag" | "spot-cookie.frag" => {
            let (inner, outer) = if name == "spot-hard.frag" {
                let l = cone_deg(scene, "u_limit")?;
                (l, l)
            } else {
                (
                    cone_deg(scene, "u_innerLimit")?,
                    cone_deg(scene, "u_outerLimit")?,
                )
            };
            let edge = match name {
                "spot-hard.frag" => EdgeProfile::Step,
                "spot-linear.frag" => EdgeProfile::Linear,
                _ => EdgeProfile::Smooth,
            };
            let cookie = if name == "spot-cookie.frag" {
                let t = scene
                    .texture("u_cookie")
                    .ok_or_else(|| LightsError::Reference("no u_cookie texture".into()))?;
                Some(Cookie::Screen {
                    image: CookieImage {
                        width: t.width,
                        height: t.height,
                        texels: t.texels.clone(),
                        filter: t.filter,
                        wrap: t.wrap,
                    },
                })
            } else {
                None
            };
            let color = values(scene, "u_color")?;
            let material = Material {
                ambient: DVec3::ZERO,
                diffuse: DVec3::new(color[0], color[1], color[2]),
                specular: DVec3::ONE,
                shininess: values(scene, "u_shininess")?[0],
            };
            LitScene::new(Shading::Phong, Reflection::BlinnPhong, material).with_light(Light::Spot(
                SpotLight {
                    position: v3(scene, "u_lightWorldPosition")?,
                    direction: v3(scene, "u_lightDirection")?,
                    inner_deg: inner,
                    outer_deg: outer,
                    edge,
                    cookie,
                    color: v3(scene, "u_lightColor")?,
                    specular: v3(scene, "u_specularColor")?,
                },
            ))
        }
        "phong-positional.frag" => {
            let rgb = |n: &str| -> Result<DVec3, LightsError> {
                let v = values(scene, n)?;
                Ok(DVec3::new(v[0], v[1], v[2]))
            };
            // The shader moves the light by uModelViewMatrix: in world space that is model · p.
            let model = DMat4::from_cols_array(&scene.matrices.model.0);
            let position = (model * v3(scene, "uLightPosition")?.extend(1.0)).truncate();
            let material = Material {
                ambient: rgb("uMaterialAmbientColor")?,
                diffuse: rgb("uMaterialDiffuseColor")?,
                specular: rgb("uMaterialSpecularColor")?,
                shininess: values(scene, "uShininess")?[0],
            };
            LitScene::new(Shading::Phong, Reflection::Phong, material)
                .with_ambient(rgb("uLightAmbientColor")?)
                .with_light(Light::Point(PointLight {
                    position,
                    color: rgb("uLightDiffuseColor")?,
                    specular: rgb("uLightSpecularColor")?,
                }))
        }
        "gouraud-lambert.frag" => {
            // The shader uses uLightDirection as an eye-space direction: in world space that
            // is inverse(view) applied to it.
            let view = DMat4::from_cols_array(&scene.matrices.view.0);
            let dir = view
                .inverse()
                .transform_vector3(v3(scene, "uLightDirection")?);
            let material = Material {
                ambient: DVec3::ZERO,
                diffuse: v3(scene, "uMaterialDiffuse")?,
                specular: DVec3::ZERO,
                shininess: 0.0,
            };
            LitScene::new(Shading::Gouraud, Reflection::Lambert, material).with_light(
                Light::Directional(DirectionalLight {
                    direction: dir,
                    color: v3(scene, "uLightDiffuse")?,
                    specular: DVec3::ZERO,
                }),
            )
        }
        _ => return Ok(None),
    }))
}
