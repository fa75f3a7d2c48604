//! Malformed scenes give clear errors (never panics), and defaults and path resolution behave as
//! FORMAT.md says. Each test writes a small scene and its shaders into a fresh temporary folder.

use std::path::{Path, PathBuf};

use essl_scene::{Draw, Mat4, Resolved, Scene, SceneError, Stream};
use serde_json::{json, Value};

/// A temporary folder holding `shaders/s.vert` and `shaders/s.frag`, removed on drop.
struct TempScene {
    dir: PathBuf,
}

impl TempScene {
    fn new(tag: &str) -> TempScene {
        let dir =
            std::env::temp_dir().join(format!("essl-scene-errors-{}-{tag}", std::process::id()));
        std::fs::create_dir_all(dir.join("shaders")).unwrap();
        std::fs::write(
            dir.join("shaders/s.vert"),
            "#version 300 es\nin vec4 p;\nvoid main() { gl_Position = p; }\n",
        )
        .unwrap();
        std::fs::write(
            dir.join("shaders/s.frag"),
            "#version 300 es\nprecision mediump float;\nout vec4 c;\nvoid main() { c = vec4(1); }\n",
        )
        .unwrap();
        TempScene { dir }
    }

    /// Writes `scene` as `scene.json` and loads it.
    fn load(&self, scene: &Value) -> Result<Scene, SceneError> {
        let path = self.dir.join("scene.json");
        std::fs::write(&path, serde_json::to_string_pretty(scene).unwrap()).unwrap();
        Scene::load(&path)
    }
}

impl Drop for TempScene {
    fn drop(&mut self) {
        std::fs::remove_dir_all(&self.dir).ok();
    }
}

/// A minimal valid scene.
fn base() -> Value {
    json!({
        "width": 8,
        "height": 4,
        "vertex_shader": "shaders/s.vert",
        "fragment_shader": "shaders/s.frag",
        "mesh": {"kind": "grid", "size": 2, "cells": 2},
        "attributes": {"p": "position"},
        "camera": {"eye": [0, 5, 5], "target": [0, 0, 0], "up": [0, 1, 0],
                   "fov_y_deg": 60, "near": 0.5, "far": 100}
    })
}

/// `base()` with `edit` applied.
fn with(edit: impl FnOnce(&mut Value)) -> Value {
    let mut v = base();
    edit(&mut v);
    v
}

/// Loads the scene and returns the error's message, failing if it loads.
fn error_of(t: &TempScene, scene: &Value) -> (SceneError, String) {
    match t.load(scene) {
        Ok(_) => panic!("loaded, but should not have: {scene}"),
        Err(e) => {
            let msg = e.to_string();
            (e, msg)
        }
    }
}

#[test]
fn minimal_scene_loads_with_defaults() {
    let t = TempScene::new("defaults");
    let s = t.load(&base()).unwrap();
    assert_eq!(s.clear_color(), [0.0, 0.0, 0.0, 1.0]);
    assert!(s.depth_test());
    assert!(!s.cull_face());
    assert_eq!(s.matrices.model, Mat4::IDENTITY);
    assert!(s.uniforms.is_empty() && s.textures.is_empty());
    assert_eq!(s.mesh.vertex_count(), 9);
    assert!(s.vertex_shader.source.starts_with("#version 300 es"));
    assert_eq!(s.vertex_shader.name, "shaders/s.vert");
    assert_eq!(s.vertex_shader.path, t.dir.join("shaders/s.vert"));
    assert_eq!(s.matrices.viewport, [8.0, 4.0]);
    assert_eq!(s.matrices.projection.0[0], s.matrices.projection.0[5] / 2.0);
}

#[test]
fn unknown_keys_are_errors_everywhere() {
    let t = TempScene::new("unknown");
    let cases: Vec<(Value, &str)> = vec![
        (with(|v| v["colour"] = json!([0, 0, 0, 1])), "colour"),
        (with(|v| v["mesh"]["radius"] = json!(1)), "radius"),
        (with(|v| v["camera"]["fov"] = json!(60)), "fov"),
        (
            with(|v| v["model"] = json!({"rotate": [0, 0, 0]})),
            "rotate",
        ),
        (
            with(|v| {
                v["textures"] = json!({"t": {"kind": "checker", "size": 4, "cells": 2,
                    "colors": [[0, 0, 0, 255], [255, 255, 255, 255]], "filter": "nearest",
                    "wrap": "repeat", "mipmaps": true}})
            }),
            "mipmaps",
        ),
        (
            with(
                |v| v["mesh"] = json!({"kind": "arrays", "attributes": {"position": [0, 0, 0, 1, 0, 0, 0, 1, 0], "color": [1]}}),
            ),
            "color",
        ),
        (
            with(|v| v["uniforms"] = json!({"u": {"cos_deg": 1, "extra": 2}})),
            "extra",
        ),
        (
            with(|v| v["uniforms"] = json!({"u": {"cosine": 1}})),
            "cosine",
        ),
    ];
    for (scene, key) in cases {
        let (e, msg) = error_of(&t, &scene);
        assert!(matches!(e, SceneError::Json(_)), "{msg}");
        assert!(msg.contains(key), "{key}: {msg}");
    }
}

#[test]
fn wrong_vector_lengths_are_errors() {
    let t = TempScene::new("lengths");
    for (scene, what) in [
        (with(|v| v["camera"]["eye"] = json!([0, 5])), "eye"),
        (with(|v| v["clear_color"] = json!([0, 0, 0])), "clear_color"),
        (
            with(|v| v["model"] = json!({"scale": [1, 1, 1, 1]})),
            "scale",
        ),
        (
            with(|v| {
                v["textures"] = json!({"t": {"kind": "checker", "size": 4, "cells": 2,
                "colors": [[0, 0, 0], [255, 255, 255, 255]], "filter": "nearest", "wrap": "clamp"}})
            }),
            "colors",
        ),
    ] {
        let (e, msg) = error_of(&t, &scene);
        assert!(matches!(e, SceneError::Json(_)), "{what}: {msg}");
        assert!(msg.contains("invalid length"), "{what}: {msg}");
    }
    // A stream whose length is not a whole number of vertices.
    let scene = with(|v| {
        v["mesh"] = json!({"kind": "arrays", "attributes": {"position": [0, 0, 0, 1, 0, 0, 0, 1]}})
    });
    let (_, msg) = error_of(&t, &scene);
    assert!(
        msg.starts_with("mesh.attributes.position: length 8"),
        "{msg}"
    );
    // Streams with different vertex counts.
    let scene = with(|v| {
        v["mesh"] = json!({"kind": "arrays", "attributes":
            {"position": [0, 0, 0, 1, 0, 0, 0, 1, 0], "uv": [0, 0, 1, 0]}})
    });
    let (_, msg) = error_of(&t, &scene);
    assert!(msg.starts_with("mesh.attributes.uv"), "{msg}");
}

#[test]
fn missing_files_are_errors() {
    let t = TempScene::new("missing");
    let (e, msg) = error_of(&t, &with(|v| v["fragment_shader"] = json!("nope.frag")));
    assert!(matches!(e, SceneError::Io { .. }), "{msg}");
    assert!(msg.contains("nope.frag"), "{msg}");
    match Scene::load(t.dir.join("no-such-scene.json")) {
        Err(SceneError::Io { path, .. }) => assert!(path.ends_with("no-such-scene.json")),
        other => panic!("{other:?}"),
    }
    // A shader that is not UTF-8.
    std::fs::write(
        t.dir.join("shaders/bad.frag"),
        b"#version 300 es\n\xff\xfe\n",
    )
    .unwrap();
    let (e, msg) = error_of(
        &t,
        &with(|v| v["fragment_shader"] = json!("shaders/bad.frag")),
    );
    assert!(
        matches!(
            e,
            SceneError::NotUtf8 {
                what: "fragment_shader",
                ..
            }
        ),
        "{msg}"
    );
    // Malformed JSON.
    std::fs::write(t.dir.join("broken.json"), "{\"width\": 8,").unwrap();
    assert!(matches!(
        Scene::load(t.dir.join("broken.json")),
        Err(SceneError::Json(_))
    ));
    // A missing required key.
    let (_, msg) = error_of(
        &t,
        &with(|v| {
            v.as_object_mut().unwrap().remove("camera");
        }),
    );
    assert!(msg.contains("missing field `camera`"), "{msg}");
}

#[test]
fn zero_length_normalize_is_an_error() {
    let t = TempScene::new("normalize");
    for zero in [json!([0, 0, 0]), json!([]), json!([0.0, -0.0])] {
        let (e, msg) = error_of(
            &t,
            &with(|v| v["uniforms"] = json!({"u_dir": {"normalize": zero}})),
        );
        assert!(matches!(e, SceneError::ZeroVector { .. }), "{msg}");
        assert!(msg.contains("uniforms.u_dir"), "{msg}");
    }
    // The camera's normalizations too.
    let (e, _) = error_of(&t, &with(|v| v["camera"]["target"] = json!([0, 5, 5])));
    assert!(matches!(e, SceneError::ZeroVector { .. }));
    let (e, msg) = error_of(&t, &with(|v| v["camera"]["up"] = json!([0, 1, 1])));
    assert!(matches!(e, SceneError::ZeroVector { .. }), "{msg}");
    // Any length works.
    let s = t
        .load(&with(|v| {
            v["uniforms"] = json!({"u": {"normalize": [3, 0, 0, 4]}})
        }))
        .unwrap();
    assert_eq!(
        s.uniform("u").unwrap().resolved,
        Resolved::Values(vec![0.6, 0.0, 0.0, 0.8])
    );
}

#[test]
fn ranges_are_checked() {
    let t = TempScene::new("ranges");
    let cases: Vec<(Value, &str)> = vec![
        (with(|v| v["width"] = json!(0)), "width:"),
        (with(|v| v["height"] = json!(4097)), "height:"),
        (with(|v| v["mesh"]["cells"] = json!(0)), "mesh.cells:"),
        (with(|v| v["mesh"]["cells"] = json!(1025)), "mesh.cells:"),
        (with(|v| v["mesh"]["size"] = json!(0)), "mesh.size:"),
        (
            with(|v| v["mesh"] = json!({"kind": "sphere", "radius": 1, "segments": 2, "rings": 4})),
            "mesh.segments:",
        ),
        (
            with(|v| v["mesh"] = json!({"kind": "sphere", "radius": 1, "segments": 3, "rings": 1})),
            "mesh.rings:",
        ),
        (
            with(|v| v["mesh"] = json!({"kind": "cube", "size": -1})),
            "mesh.size:",
        ),
        (with(|v| v["camera"]["near"] = json!(0)), "camera.near:"),
        (with(|v| v["camera"]["far"] = json!(0.25)), "camera:"),
        (with(|v| v["camera"]["fov_y_deg"] = json!(180)), "camera:"),
        (
            with(|v| {
                v["mesh"] =
                    json!({"kind": "arrays", "attributes": {"position": [0, 0, 0, 1, 0, 0]}})
            }),
            "mesh.attributes: vertex count 2",
        ),
        (
            with(|v| v["mesh"] = json!({"kind": "arrays", "attributes": {}})),
            "mesh.attributes: no vertices",
        ),
        (
            with(|v| {
                v["mesh"] = json!({"kind": "arrays",
                "attributes": {"position": [0, 0, 0, 1, 0, 0, 0, 1, 0]}, "indices": [0, 1, 3]})
            }),
            "mesh.indices: expected integers in 0..2",
        ),
        (
            with(|v| {
                v["mesh"] = json!({"kind": "arrays",
                "attributes": {"position": [0, 0, 0, 1, 0, 0, 0, 1, 0]}, "indices": [0, 1]})
            }),
            "mesh.indices: length 2",
        ),
        (
            with(|v| {
                v["mesh"] = json!({"kind": "arrays", "attributes": {"position": [0, 0, 0, 1, 0, 0, 0, 1, 0]}});
                v["attributes"] = json!({"p": "position", "n": "normal"});
            }),
            "attributes.n:",
        ),
        (with(|v| v["attributes"] = json!({})), "attributes:"),
        (
            with(|v| {
                v["textures"] = json!({"u": {"kind": "pixels", "width": 2, "height": 1,
                    "data": [1, 2, 3, 4], "filter": "linear", "wrap": "mirror"}})
            }),
            "textures.u.data: expected width*height*4 = 8 bytes",
        ),
        (
            with(|v| {
                v["textures"] = json!({"u": {"kind": "checker", "size": 0, "cells": 1,
                    "colors": [[0, 0, 0, 0], [0, 0, 0, 0]], "filter": "linear", "wrap": "mirror"}})
            }),
            "textures.u.size:",
        ),
        (
            with(|v| {
                v["textures"] = json!({"u": {"kind": "checker", "size": 2, "cells": 1,
                    "colors": [[0, 0, 0, 0], [0, 0, 0, 0]], "filter": "linear", "wrap": "mirror"}});
                v["uniforms"] = json!({"u": 0});
            }),
            "uniforms.u: also named in textures",
        ),
    ];
    for (scene, want) in cases {
        let (e, msg) = error_of(&t, &scene);
        assert!(
            matches!(e, SceneError::Invalid { .. }),
            "{want}: {msg} ({e:?})"
        );
        assert!(msg.starts_with(want), "want {want:?}, got {msg:?}");
    }
}

#[test]
fn wrong_types_are_errors() {
    let t = TempScene::new("types");
    for scene in [
        with(|v| v["width"] = json!(8.0)),
        with(|v| v["width"] = json!("8")),
        with(|v| v["depth_test"] = json!(1)),
        with(|v| v["mesh"]["kind"] = json!("torus")),
        with(|v| v["mesh"]["cells"] = json!(2.5)),
        with(|v| v["attributes"] = json!({"p": "colour"})),
        with(|v| v["model"] = Value::Null),
        with(|v| v["clear_color"] = Value::Null),
        with(|v| v["uniforms"] = json!({"u": "model_view_projektion"})),
        with(|v| v["uniforms"] = json!({"u": [1, "2"]})),
        with(|v| v["uniforms"] = json!({"u": null})),
        with(|v| v["camera"]["eye"] = json!([0, true, 5])),
        with(|v| {
            v["textures"] = json!({"u": {"kind": "pixels", "width": 1, "height": 1,
                "data": [0, 0, 0, 256], "filter": "linear", "wrap": "mirror"}})
        }),
        with(|v| {
            v["textures"] = json!({"u": {"kind": "pixels", "width": 1, "height": 1,
                "data": [0, 0, 0, 255], "filter": "trilinear", "wrap": "mirror"}})
        }),
    ] {
        let (e, msg) = error_of(&t, &scene);
        assert!(matches!(e, SceneError::Json(_)), "{msg}");
    }
    // Duplicate keys are refused, in maps as in structs.
    let path = t.dir.join("dup.json");
    let text = serde_json::to_string(&base()).unwrap();
    let dup = text.replacen('{', "{\"uniforms\": {\"u\": 1, \"u\": 2},", 1);
    std::fs::write(&path, dup).unwrap();
    let msg = Scene::load(&path).unwrap_err().to_string();
    assert!(msg.contains("duplicate key `u`"), "{msg}");
}

#[test]
fn singular_model_fails_only_where_inverted() {
    let t = TempScene::new("singular");
    let flat = with(|v| v["model"] = json!({"scale": [1, 0, 1]}));
    assert!(t.load(&flat).is_ok(), "unused inverse must not fail");
    let mut used = flat.clone();
    used["uniforms"] = json!({"u_n": "normal_matrix"});
    let (e, msg) = error_of(&t, &used);
    assert!(matches!(e, SceneError::Singular { .. }), "{msg}");
    used["uniforms"] = json!({"u_n": "model_inverse_transpose"});
    let (e, _) = error_of(&t, &used);
    assert!(matches!(e, SceneError::Singular { .. }));
}

#[test]
fn arrays_without_indices_draw_arrays_and_null_indices_mean_none() {
    let t = TempScene::new("arrays");
    let positions = json!([0, 0, 0, 1, 0, 0, 0, 1, 0, -0.0, 1, 0, 1, 1, 0, 1, 0, 0]);
    let s = t
        .load(&with(|v| {
            v["mesh"] = json!({"kind": "arrays", "attributes": {"position": positions}, "indices": null})
        }))
        .unwrap();
    assert_eq!(s.mesh.draw(), Draw::Arrays { count: 6 });
    assert_eq!(s.mesh.streams(), vec![Stream::Position]);
    assert!(s.mesh.stream(Stream::Normal).is_none());
    assert_eq!(s.mesh.triangles(), vec![[0, 1, 2], [3, 4, 5]]);
    // -0.0 is kept.
    assert_eq!(
        s.mesh.stream_f32(Stream::Position).unwrap()[9].to_bits(),
        (-0.0f32).to_bits()
    );
}

#[test]
fn shader_paths_resolve_against_the_scene_folder() {
    let t = TempScene::new("paths");
    // Load through a relative path from a different working directory would need chdir; a scene
    // in a subfolder pointing to `../shaders` checks the join instead.
    std::fs::create_dir_all(t.dir.join("sub")).unwrap();
    let mut scene = base();
    scene["vertex_shader"] = json!("../shaders/s.vert");
    scene["fragment_shader"] = json!("../shaders/s.frag");
    let path = t.dir.join("sub/scene.json");
    std::fs::write(&path, scene.to_string()).unwrap();
    let s = Scene::load(&path).unwrap();
    assert_eq!(
        s.fragment_shader.path,
        Path::new(&t.dir).join("sub/../shaders/s.frag")
    );
    assert!(s.fragment_shader.source.contains("precision mediump float"));
}
