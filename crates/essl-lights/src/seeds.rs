//! The shared scenes' own shaders (`shared/scenes/*.vert`, `*.frag`, from the seed articles)
//! written as float64 [`RefShader`]s: the seeds' formulas exactly as the scene shaders compute
//! them (article 002's unclamped Lambert and `vec4(n, 1.0)` normal transform, article 000's
//! `step(0.1, light)` specular gate, article 004's `length(rgb)` cookie included), with the
//! scene's uniform values in float64. Rendered by [`crate::reference::render`] they are the
//! float64 reference for Chromium's `reference/*.png`.

use glam::{DMat3, DMat4, DVec2, DVec3, DVec4};

use essl_scene::{Resolved, Scene, Texture};

use crate::error::LightsError;
use crate::reference::{sample_texture, FnShader, FragmentIn, RefShader, VertexIn};

fn values(scene: &Scene, name: &str) -> Result<Vec<f64>, LightsError> {
    let u = scene
        .uniform(name)
        .ok_or_else(|| LightsError::Reference(format!("the scene does not set {name}")))?;
    Ok(match &u.resolved {
        Resolved::Values(v) => v.clone(),
        Resolved::Matrix(m) => m.0.to_vec(),
    })
}

fn float(scene: &Scene, name: &str) -> Result<f64, LightsError> {
    Ok(values(scene, name)?[0])
}

fn vec3(scene: &Scene, name: &str) -> Result<DVec3, LightsError> {
    let v = values(scene, name)?;
    Ok(DVec3::new(v[0], v[1], v[2]))
}

fn vec4(scene: &Scene, name: &str) -> Result<DVec4, LightsError> {
    let v = values(scene, name)?;
    Ok(DVec4::new(v[0], v[1], v[2], v[3]))
}

fn mat4(scene: &Scene, name: &str) -> Result<DMat4, LightsError> {
    let v = values(scene, name)?;
    if v.len() != 16 {
        return Err(LightsError::Reference(format!("{name} is not a mat4")));
    }
    Ok(DMat4::from_cols_slice(&v))
}

fn v3(v: &[f64]) -> DVec3 {
    DVec3::new(v[0], v[1], v[2])
}

/// GLSL's `smoothstep` by its definition (NaN when `e0 == e1` and `x == e0`).
fn smoothstep(e0: f64, e1: f64, x: f64) -> f64 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

fn step(edge: f64, x: f64) -> f64 {
    if x < edge {
        0.0
    } else {
        1.0
    }
}

/// Which `inLight` the spot scene's fragment shader computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpotEdge {
    /// `spot-smooth.frag`: `smoothstep(u_outerLimit, u_innerLimit, d)`.
    Smooth,
    /// `spot-hard.frag`: `step(u_limit, d)`.
    Hard,
    /// `spot-linear.frag`: `clamp((d - outer) / (inner - outer), 0, 1)`.
    Linear,
    /// `spot-cookie.frag`: smooth, times `length(texture(u_cookie, fc / viewport * (1, -1)).rgb)`.
    Cookie,
}

/// `spot.vert` + one of the spot fragment shaders.
pub fn spot_shader(scene: &Scene, edge: SpotEdge) -> Result<Box<dyn RefShader>, LightsError> {
    let world = mat4(scene, "u_world")?;
    let wit = DMat3::from_mat4(mat4(scene, "u_worldInverseTranspose")?);
    let light_pos = vec3(scene, "u_lightWorldPosition")?;
    let view_pos = vec3(scene, "u_viewWorldPosition")?;
    let color = vec4(scene, "u_color")?;
    let shininess = float(scene, "u_shininess")?;
    let light_color = vec3(scene, "u_lightColor")?;
    let specular_color = vec3(scene, "u_specularColor")?;
    let light_dir = vec3(scene, "u_lightDirection")?;
    let (inner, outer) = match edge {
        SpotEdge::Hard => (0.0, float(scene, "u_limit")?),
        _ => (float(scene, "u_innerLimit")?, float(scene, "u_outerLimit")?),
    };
    let cookie: Option<(Texture, DVec2)> = if edge == SpotEdge::Cookie {
        let t = scene
            .texture("u_cookie")
            .ok_or_else(|| LightsError::Reference("the scene has no u_cookie texture".into()))?
            .clone();
        let vp = values(scene, "u_viewport")?;
        Some((t, DVec2::new(vp[0], vp[1])))
    } else {
        None
    };
    Ok(Box::new(FnShader {
        vertex: move |v: &VertexIn| {
            let a_position = v.position.extend(1.0);
            let n = wit * v.normal;
            let swp = (world * a_position).truncate();
            let stl = light_pos - swp;
            let stv = view_pos - swp;
            vec![n.x, n.y, n.z, stl.x, stl.y, stl.z, stv.x, stv.y, stv.z]
        },
        fragment: move |f: &FragmentIn<'_>| {
            let v = f.varyings;
            let normal = v3(&v[0..3]).normalize();
            let ustl = v3(&v[3..6]).normalize();
            let ustv = v3(&v[6..9]).normalize();
            let half = (ustl + ustv).normalize();
            let d = ustl.dot(-light_dir);
            let mut in_light = match edge {
                SpotEdge::Smooth | SpotEdge::Cookie => smoothstep(outer, inner, d),
                SpotEdge::Hard => step(outer, d),
                SpotEdge::Linear => ((d - outer) / (inner - outer)).clamp(0.0, 1.0),
            };
            if let Some((t, vp)) = &cookie {
                let uv = f.frag_coord / *vp * DVec2::new(1.0, -1.0);
                let c = sample_texture(t.width, t.height, &t.texels, t.filter, t.wrap, uv);
                in_light *= c.truncate().length();
            }
            let light = in_light * normal.dot(ustl);
            let raw = normal.dot(half).max(0.0);
            let spec = raw.powf(shininess);
            let limited = step(0.1, light) * spec;
            let rgb = color.truncate() * (light * light_color) + limited * specular_color;
            rgb.extend(color.w)
        },
    }))
}

/// `gouraud-lambert.vert` + `.frag`: article 002's Gouraud shading with Lambert reflection.
pub fn gouraud_lambert_shader(scene: &Scene) -> Result<Box<dyn RefShader>, LightsError> {
    let normal_matrix = mat4(scene, "uNormalMatrix")?;
    let light_dir = vec3(scene, "uLightDirection")?;
    let light_diffuse = vec3(scene, "uLightDiffuse")?;
    let material_diffuse = vec3(scene, "uMaterialDiffuse")?;
    Ok(Box::new(FnShader {
        vertex: move |v: &VertexIn| {
            let n = (normal_matrix * v.normal.extend(1.0))
                .truncate()
                .normalize();
            let l = light_dir.normalize();
            let lambert = n.dot(-l);
            let id = material_diffuse * light_diffuse * lambert;
            vec![id.x, id.y, id.z, 1.0]
        },
        fragment: |f: &FragmentIn<'_>| DVec4::from_slice(f.varyings),
    }))
}

/// `phong-positional.vert` + `.frag`: article 002's positional light, Phong shading and
/// reflection.
pub fn phong_positional_shader(scene: &Scene) -> Result<Box<dyn RefShader>, LightsError> {
    let mv = mat4(scene, "uModelViewMatrix")?;
    let normal_matrix = mat4(scene, "uNormalMatrix")?;
    let light_pos = vec3(scene, "uLightPosition")?;
    let md = vec4(scene, "uMaterialDiffuseColor")?;
    let ms = vec4(scene, "uMaterialSpecularColor")?;
    let ma = vec4(scene, "uMaterialAmbientColor")?;
    let ld = vec4(scene, "uLightDiffuseColor")?;
    let la = vec4(scene, "uLightAmbientColor")?;
    let ls = vec4(scene, "uLightSpecularColor")?;
    let shininess = float(scene, "uShininess")?;
    Ok(Box::new(FnShader {
        vertex: move |v: &VertexIn| {
            let vertex = mv * v.position.extend(1.0);
            let light = mv * light_pos.extend(1.0);
            let n = (normal_matrix * v.normal.extend(1.0)).truncate();
            let ray = vertex.truncate() - light.truncate();
            let eye = -vertex.truncate();
            vec![n.x, n.y, n.z, ray.x, ray.y, ray.z, eye.x, eye.y, eye.z]
        },
        fragment: move |f: &FragmentIn<'_>| {
            let v = f.varyings;
            let l = v3(&v[3..6]).normalize();
            let n = v3(&v[0..3]).normalize();
            let ia = ma * la;
            let mut id = DVec4::new(0.0, 0.0, 0.0, 1.0);
            let mut is = DVec4::new(0.0, 0.0, 0.0, 1.0);
            let lambert = n.dot(-l);
            if lambert > 0.0 {
                id = ld * md * lambert;
                let e = v3(&v[6..9]).normalize();
                let r = l - 2.0 * n.dot(l) * n;
                let specular = r.dot(e).max(0.0).powf(shininess);
                is = ls * ms * specular;
            }
            (ia + id + is).truncate().extend(1.0)
        },
    }))
}

/// The float64 shader of a shared scene, chosen by its fragment shader's file name; `None` for
/// a scene whose shaders are not modelled here.
pub fn seed_shader(scene: &Scene) -> Result<Option<Box<dyn RefShader>>, LightsError> {
    let name = scene.fragment_shader.name.as_str();
    Ok(Some(match name {
        "spot-smooth.frag" => spot_shader(scene, SpotEdge::Smooth)?,
        "spot-hard.frag" => spot_shader(scene, SpotEdge::Hard)?,
        "spot-linear.frag" => spot_shader(scene, SpotEdge::Linear)?,
        "spot-cookie.frag" => spot_shader(scene, SpotEdge::Cookie)?,
        "gouraud-lambert.frag" => gouraud_lambert_shader(scene)?,
        "phong-positional.frag" => phong_positional_shader(scene)?,
        _ => return Ok(None),
    }))
}
