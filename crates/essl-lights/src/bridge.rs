//! From a lit scene to the scene format of `shared/scenes/FORMAT.md`: the generated shaders,
//! their uniform values and cookie textures on a base scene's geometry, camera and canvas —
//! what a renderer of scene files (essl-gl, or Chromium through `webgl2-render.py`) draws, and
//! what [`crate::reference::render`] draws in float64.

use std::path::{Path, PathBuf};

use serde_json::{json, Value};

use essl_scene::{
    Filter, MeshSpec, OrderedMap, Scene, SceneFile, ShaderSource, Stream, TextureSpec,
    UniformValue, Wrap,
};

use crate::error::LightsError;
use crate::names;
use crate::program::ShaderPair;
use crate::uniforms::{UniformData, Uniforms};

/// The file names the generated shaders get in a scene.
pub const VERTEX_FILE: &str = "essl-lights.vert";
/// See [`VERTEX_FILE`].
pub const FRAGMENT_FILE: &str = "essl-lights.frag";

/// A scene drawing `program` with `uniforms` on `base`'s mesh, camera, model transform, canvas
/// and render state (its shaders, attributes, uniforms and textures are replaced).
pub fn to_scene(
    base: &SceneFile,
    program: &ShaderPair,
    uniforms: &Uniforms,
) -> Result<Scene, LightsError> {
    to_scene_named(base, program, uniforms, VERTEX_FILE, FRAGMENT_FILE)
}

/// [`to_scene`] with the shader file names given.
pub fn to_scene_named(
    base: &SceneFile,
    program: &ShaderPair,
    uniforms: &Uniforms,
    vertex_name: &str,
    fragment_name: &str,
) -> Result<Scene, LightsError> {
    let mut file = base.clone();
    file.vertex_shader = vertex_name.to_string();
    file.fragment_shader = fragment_name.to_string();
    let mut attributes = Vec::new();
    for (name, _) in &program.attributes {
        let stream = if name == names::NORMAL {
            Stream::Normal
        } else {
            Stream::Position
        };
        attributes.push((name.clone(), stream));
    }
    file.attributes = OrderedMap(attributes);
    let mut values = Vec::new();
    for u in &uniforms.values {
        match &u.data {
            UniformData::Floats(v) => {
                values.push((u.name.clone(), UniformValue::Numbers(v.clone())))
            }
            UniformData::Ints(v) => values.push((
                u.name.clone(),
                UniformValue::Numbers(v.iter().map(|&x| f64::from(x)).collect()),
            )),
            UniformData::Sampler(_) => {}
        }
    }
    file.uniforms = OrderedMap(values);
    file.textures = OrderedMap(
        uniforms
            .cookies
            .iter()
            .map(|c| {
                (
                    c.sampler.clone(),
                    TextureSpec::Pixels {
                        width: c.image.width,
                        height: c.image.height,
                        data: c.image.texels.clone(),
                        filter: c.image.filter,
                        wrap: c.image.wrap,
                    },
                )
            })
            .collect(),
    );
    let vs = ShaderSource {
        name: vertex_name.to_string(),
        path: PathBuf::from(vertex_name),
        source: program.vertex.clone(),
    };
    let fs = ShaderSource {
        name: fragment_name.to_string(),
        path: PathBuf::from(fragment_name),
        source: program.fragment.clone(),
    };
    Ok(Scene::build(file, vs, fs)?)
}

fn filter_name(f: Filter) -> &'static str {
    match f {
        Filter::Nearest => "nearest",
        Filter::Linear => "linear",
    }
}

fn wrap_name(w: Wrap) -> &'static str {
    match w {
        Wrap::Clamp => "clamp",
        Wrap::Repeat => "repeat",
        Wrap::Mirror => "mirror",
    }
}

/// The scene file as JSON in FORMAT.md's form (every key written, defaults included).
pub fn scene_json(file: &SceneFile) -> Value {
    let mesh = match &file.mesh {
        MeshSpec::Grid { size, cells } => json!({"kind": "grid", "size": size, "cells": cells}),
        MeshSpec::Sphere {
            radius,
            segments,
            rings,
        } => json!({"kind": "sphere", "radius": radius, "segments": segments, "rings": rings}),
        MeshSpec::Cube { size } => json!({"kind": "cube", "size": size}),
        MeshSpec::Arrays {
            attributes,
            indices,
        } => {
            let mut a = serde_json::Map::new();
            for s in attributes.present() {
                a.insert(s.name().into(), json!(attributes.get(s)));
            }
            let mut m = json!({"kind": "arrays", "attributes": a});
            if let Some(i) = indices {
                m["indices"] = json!(i);
            }
            m
        }
    };
    let uniforms: serde_json::Map<String, Value> = file
        .uniforms
        .iter()
        .map(|(k, v)| {
            let v = match v {
                UniformValue::Numbers(n) if n.len() == 1 => json!(n[0]),
                UniformValue::Numbers(n) => json!(n),
                UniformValue::Bool(b) => json!(b),
                UniformValue::Derived(d) => json!(d.name()),
                UniformValue::CosDeg(d) => json!({"cos_deg": d}),
                UniformValue::Normalize(n) => json!({"normalize": n}),
            };
            (k.to_string(), v)
        })
        .collect();
    let textures: serde_json::Map<String, Value> = file
        .textures
        .iter()
        .map(|(k, t)| {
            let v = match t {
                TextureSpec::Checker {
                    size,
                    cells,
                    colors,
                    filter,
                    wrap,
                } => json!({"kind": "checker", "size": size, "cells": cells, "colors": colors,
                            "filter": filter_name(*filter), "wrap": wrap_name(*wrap)}),
                TextureSpec::Pixels {
                    width,
                    height,
                    data,
                    filter,
                    wrap,
                } => json!({"kind": "pixels", "width": width, "height": height, "data": data,
                            "filter": filter_name(*filter), "wrap": wrap_name(*wrap)}),
            };
            (k.to_string(), v)
        })
        .collect();
    let attributes: serde_json::Map<String, Value> = file
        .attributes
        .iter()
        .map(|(k, s)| (k.to_string(), json!(s.name())))
        .collect();
    let c = &file.camera;
    let m = &file.model;
    let mut out = json!({
        "width": file.width,
        "height": file.height,
        "clear_color": file.clear_color,
        "depth_test": file.depth_test,
        "cull_face": file.cull_face,
        "vertex_shader": file.vertex_shader,
        "fragment_shader": file.fragment_shader,
        "mesh": mesh,
        "attributes": attributes,
        "camera": {"eye": c.eye, "target": c.target, "up": c.up, "fov_y_deg": c.fov_y_deg,
                   "near": c.near, "far": c.far},
        "model": {"translate": m.translate, "rotate_deg": m.rotate_deg, "scale": m.scale},
        "uniforms": uniforms,
        "textures": textures,
    });
    if let Some(d) = &file.description {
        out["description"] = json!(d);
    }
    out
}

/// Writes `scene` as `dir/name.json` with its shaders beside it (`name.vert`, `name.frag`), ready
/// for `webgl2-render.py`.
pub fn write_scene(dir: &Path, name: &str, scene: &Scene) -> std::io::Result<PathBuf> {
    std::fs::create_dir_all(dir)?;
    let mut file = scene.file.clone();
    file.vertex_shader = format!("{name}.vert");
    file.fragment_shader = format!("{name}.frag");
    std::fs::write(dir.join(&file.vertex_shader), &scene.vertex_shader.source)?;
    std::fs::write(
        dir.join(&file.fragment_shader),
        &scene.fragment_shader.source,
    )?;
    let path = dir.join(format!("{name}.json"));
    let text = serde_json::to_string_pretty(&scene_json(&file)).map_err(std::io::Error::other)?;
    std::fs::write(&path, text + "\n")?;
    Ok(path)
}
