//! Bit-for-bit checks of everything this crate derives against what `webgl2-render.py` uploads,
//! for every scene in `shared/scenes/` (the folder beside the repository, `../shared` from its
//! root) and for this crate's own awkward scenes in `tests/data/local-scenes/`.
//!
//! The expectations in `tests/data/{shared,local}/*.json` were made by
//! `tests/data/make_expectations.py` from the tool's `--dump` (uniform values as read back from
//! the page, mesh streams and indices, texture units, attribute bindings) and from the tool's own
//! functions (every derived value and the meshes as float32 and float64 bit patterns, the texels'
//! hash). Without the shared scenes (`ESSL_SCENES` or `../shared/scenes`) the shared-scene tests
//! print why and pass, unless `ESSL_REQUIRE_CORPORA=1`, in which case they fail; the local
//! scenes need nothing outside the crate.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use essl_scene::{Derived, DerivedValue, Draw, Scene, Stream, UniformType, UploadValues};
use serde_json::Value;

/// The shared scenes, or `None` (after saying so) when they are absent and not required.
fn shared_scenes() -> Option<PathBuf> {
    essl_testdata::scenes()
}

fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data")
}

/// Every expectation file of a set (`shared` or `local`): (scene file name, parsed JSON).
fn expectations(set: &str) -> Vec<(String, Value)> {
    let dir = data_dir().join(set);
    let mut out = Vec::new();
    for entry in std::fs::read_dir(&dir).expect("tests/data") {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "json") {
            let v: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap())
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            out.push((v["scene"].as_str().unwrap().to_string(), v));
        }
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    assert!(
        out.len() >= 5,
        "expected at least 5 scenes' expectations in {set}"
    );
    out
}

fn fnv1a64(bytes: impl IntoIterator<Item = u8>) -> String {
    let mut h: u64 = 0xcbf29ce484222325;
    for b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x100000001b3);
    }
    format!("{h:016x}")
}

fn hex_bits(v: &Value) -> u32 {
    let s = v.as_str().unwrap();
    u32::from_str_radix(s.trim_start_matches("0x"), 16).unwrap()
}

fn hex_bits64(v: &Value) -> u64 {
    let s = v.as_str().unwrap();
    u64::from_str_radix(s.trim_start_matches("0x"), 16).unwrap()
}

fn bits(values: &[f32]) -> Vec<u32> {
    values.iter().map(|x| x.to_bits()).collect()
}

fn f32s(v: &Value) -> Vec<f32> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap() as f32)
        .collect()
}

fn load(scenes: &Path, scene: &str) -> Scene {
    Scene::load(scenes.join(scene)).unwrap_or_else(|e| panic!("{scene}: {e}"))
}

/// Every derived value (FORMAT.md's table), the inverse transposes included, as float32 bits
/// and as float64 bits before rounding, against the tool's functions.
fn check_derived(scene: &Scene, exp: &Value, label: &str) {
    for d in Derived::ALL {
        let want32: Vec<u32> = exp["derived"][d.name()]
            .as_array()
            .unwrap_or_else(|| panic!("{label}: no derived {d}"))
            .iter()
            .map(hex_bits)
            .collect();
        let want64: Vec<u64> = exp["derived_f64"][d.name()]
            .as_array()
            .unwrap()
            .iter()
            .map(hex_bits64)
            .collect();
        let got: Vec<f64> = match scene.derived(d).unwrap() {
            DerivedValue::Matrix(m) => {
                assert_eq!(bits(&m.as_f32()), want32, "{label}: derived {d} (as_f32)");
                m.0.to_vec()
            }
            DerivedValue::Vector(v) => v,
        };
        let got32: Vec<f32> = got.iter().map(|&x| x as f32).collect();
        assert_eq!(bits(&got32), want32, "{label}: derived {d}");
        let got64: Vec<u64> = got.iter().map(|x| x.to_bits()).collect();
        assert_eq!(got64, want64, "{label}: derived {d} (f64)");
    }
}

/// Every uniform the page set, fitted to the active type the page reported, against the values
/// read back from its typed array (JSON numbers: exact, but the sign of a zero is lost).
fn check_uniforms(scene: &Scene, exp: &Value, label: &str) {
    let dumped = exp["dump"]["uniforms"].as_object().unwrap();
    let ours: BTreeSet<&str> = scene.uniforms.iter().map(|u| u.name.as_str()).collect();
    let theirs: BTreeSet<&str> = dumped.keys().map(String::as_str).collect();
    assert_eq!(ours, theirs, "{label}: uniforms set");
    for (name, d) in dumped {
        let ty = UniformType::from_gl_name(d["type"].as_str().unwrap()).unwrap();
        let size = d["size"].as_u64().unwrap() as usize;
        let up = scene
            .uniform(name)
            .unwrap()
            .resolved
            .upload(name, ty, size)
            .unwrap_or_else(|e| panic!("{label}: {e}"));
        let want: Vec<f64> = d["values"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        let got = up.to_f64();
        assert_eq!(got.len(), want.len(), "{label}: {name}");
        for (i, (g, w)) in got.iter().zip(&want).enumerate() {
            let same = g.to_bits() == w.to_bits() || (*g == 0.0 && *w == 0.0);
            assert!(same, "{label}: {name}[{i}]: ours {g:e}, dump {w:e}");
        }
        let kind_ok = matches!(
            (&up, ty),
            (
                UploadValues::I32(_),
                UniformType::Int(_) | UniformType::Bool(_)
            ) | (UploadValues::U32(_), UniformType::Uint(_))
                | (
                    UploadValues::F32(_),
                    UniformType::Float(_)
                        | UniformType::Mat2
                        | UniformType::Mat3
                        | UniformType::Mat4
                )
        );
        assert!(kind_ok, "{label}: {name}: {up:?} for {ty:?}");
    }
}

/// Streams (hash of the float32 bytes, first and last values; hash of the float64 values),
/// indices, index type and vertex count against the dump's mesh; every value for the small
/// meshes dumped whole. Returns whether the mesh was dumped whole.
fn check_mesh(scene: &Scene, exp: &Value, label: &str) -> bool {
    let mesh = &scene.mesh;
    let m = &exp["mesh"];
    assert_eq!(
        mesh.vertex_count() as u64,
        m["vertex_count"].as_u64().unwrap(),
        "{label}"
    );
    let streams = m["streams"].as_object().unwrap();
    let names: Vec<&str> = mesh.streams().iter().map(|s| s.name()).collect();
    let mut theirs: Vec<&str> = streams.keys().map(String::as_str).collect();
    theirs.sort_by_key(|n| Stream::ALL.iter().position(|s| s.name() == *n));
    assert_eq!(names, theirs, "{label}: streams");
    for s in mesh.streams() {
        let e = &streams[s.name()];
        let got = mesh.stream_f32(s).unwrap();
        assert_eq!(got.len() as u64, e["len"].as_u64().unwrap());
        let bytes = got.iter().flat_map(|x| x.to_le_bytes());
        assert_eq!(
            fnv1a64(bytes),
            e["fnv1a64"].as_str().unwrap(),
            "{label}: {s} hash"
        );
        let head: Vec<u32> = e["head"].as_array().unwrap().iter().map(hex_bits).collect();
        let tail: Vec<u32> = e["tail"].as_array().unwrap().iter().map(hex_bits).collect();
        assert_eq!(bits(&got[..head.len()]), head, "{label}: {s} head");
        assert_eq!(
            bits(&got[got.len() - tail.len()..]),
            tail,
            "{label}: {s} tail"
        );
        let e64 = &exp["mesh_f64"][s.name()];
        let got64 = mesh.stream(s).unwrap();
        assert_eq!(
            fnv1a64(got64.iter().flat_map(|x| x.to_le_bytes())),
            e64["fnv1a64"].as_str().unwrap(),
            "{label}: {s} (f64) hash"
        );
        let head: Vec<u64> = e64["head"]
            .as_array()
            .unwrap()
            .iter()
            .map(hex_bits64)
            .collect();
        let got_head: Vec<u64> = got64[..head.len()].iter().map(|x| x.to_bits()).collect();
        assert_eq!(got_head, head, "{label}: {s} (f64) head");
    }
    match (&mesh.indices, &m["indices"]) {
        (None, Value::Null) => {
            assert!(exp["dump"]["index_type"].is_null(), "{label}: index type");
            assert_eq!(
                mesh.draw(),
                Draw::Arrays {
                    count: mesh.vertex_count()
                }
            );
        }
        (Some(idx), e) => {
            assert_eq!(idx.len() as u64, e["count"].as_u64().unwrap());
            assert_eq!(
                fnv1a64(idx.iter().flat_map(|i| i.to_le_bytes())),
                e["fnv1a64_u32le"].as_str().unwrap(),
                "{label}: indices hash"
            );
            let head: Vec<u32> = e["head"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_u64().unwrap() as u32)
                .collect();
            assert_eq!(&idx[..head.len()], &head[..], "{label}: indices head");
            assert_eq!(
                mesh.index_type().gl_name(),
                exp["dump"]["index_type"].as_str().unwrap(),
                "{label}: index type"
            );
        }
        (None, _) => panic!("{label}: the tool drew with indices, we without"),
    }
    let Some(whole) = exp.get("mesh_full") else {
        return false;
    };
    for s in mesh.streams() {
        let want = f32s(&whole[s.name()]);
        let got = mesh.stream_f32(s).unwrap();
        // JSON keeps the sign of zero here (Python wrote these numbers).
        assert_eq!(bits(&got), bits(&want), "{label}: whole {s}");
    }
    if let Some(idx) = &mesh.indices {
        let want: Vec<u32> = whole["indices"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap() as u32)
            .collect();
        assert_eq!(idx, &want, "{label}: whole indices");
    }
    true
}

/// Attribute bindings, texture units, sizes, sampling state and texels.
fn check_attributes_and_textures(scene: &Scene, exp: &Value, label: &str) {
    let ours: BTreeMap<&str, &str> = scene.attributes().map(|(a, s)| (a, s.name())).collect();
    let theirs: BTreeMap<&str, &str> = exp["dump"]["attributes"]
        .as_object()
        .unwrap()
        .iter()
        .map(|(a, v)| (a.as_str(), v["stream"].as_str().unwrap()))
        .collect();
    assert_eq!(ours, theirs, "{label}: attributes");
    let dumped = exp["dump"]["textures"].as_object().unwrap();
    assert_eq!(scene.textures.len(), dumped.len(), "{label}: textures");
    for (name, d) in dumped {
        let t = scene.texture(name).unwrap();
        assert_eq!(
            u64::from(t.unit),
            d["unit"].as_u64().unwrap(),
            "{label}: {name} unit"
        );
        assert_eq!(u64::from(t.width), d["width"].as_u64().unwrap());
        assert_eq!(u64::from(t.height), d["height"].as_u64().unwrap());
        let e = &exp["texels"][name];
        assert_eq!(t.filter.gl_name(), e["filter"].as_str().unwrap());
        assert_eq!(t.wrap.gl_name(), e["wrap"].as_str().unwrap());
        assert_eq!(
            fnv1a64(t.texels.iter().copied()),
            e["fnv1a64"].as_str().unwrap(),
            "{label}: {name} texels"
        );
    }
}

/// Runs every check on every scene of a set; returns how many meshes were compared whole.
fn check_set(scenes: &Path, set: &str) -> usize {
    let mut whole = 0;
    for (scene_name, exp) in expectations(set) {
        let label = format!("{set}/{scene_name}");
        let scene = load(scenes, &scene_name);
        check_derived(&scene, &exp, &label);
        check_uniforms(&scene, &exp, &label);
        whole += usize::from(check_mesh(&scene, &exp, &label));
        check_attributes_and_textures(&scene, &exp, &label);
    }
    whole
}

/// The shared scenes: derived values, uniforms, meshes, attributes and textures, bit for bit.
#[test]
fn shared_scenes_match_the_tool() {
    let Some(scenes) = shared_scenes() else {
        return;
    };
    assert!(check_set(&scenes, "shared") >= 1, "no mesh compared whole");
}

/// This crate's own scenes (odd sizes, rotated and scaled models, a cube, given arrays with a
/// `-0.0`, `drawArrays`, every uniform form and integer type, two textures out of order).
#[test]
fn local_scenes_match_the_tool() {
    assert!(check_set(&data_dir().join("local-scenes"), "local") >= 5);
}

/// Every scene in shared/scenes has expectations here, and loads.
#[test]
fn every_shared_scene_has_expectations() {
    let Some(scenes) = shared_scenes() else {
        return;
    };
    let have: Vec<String> = expectations("shared").into_iter().map(|(s, _)| s).collect();
    for entry in std::fs::read_dir(&scenes).unwrap() {
        let name = entry.unwrap().file_name().to_string_lossy().into_owned();
        if name.ends_with(".json") {
            load(&scenes, &name);
            assert!(
                have.contains(&name),
                "{name} has no expectations: run tests/data/make_expectations.py"
            );
        }
    }
}

/// The golden PNGs decode to RGBA8 of the scene's size and survive our GL-rows writer unchanged.
#[test]
fn reference_pngs_round_trip() {
    let Some(scenes) = shared_scenes() else {
        return;
    };
    let tmp = std::env::temp_dir().join(format!("essl-scene-png-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    for (scene_name, _) in expectations("shared") {
        let scene = load(&scenes, &scene_name);
        let png = scenes
            .join("reference")
            .join(scene_name.replace(".json", ".png"));
        let img = essl_scene::read_png(&png).unwrap();
        assert_eq!((img.width, img.height), (scene.width(), scene.height()));
        let out = tmp.join(format!("{scene_name}.png"));
        essl_scene::write_png_gl_rows(&out, img.width, img.height, &img.to_gl_rows()).unwrap();
        let back = essl_scene::read_png(&out).unwrap();
        let diff = essl_scene::compare(&img, &back, 0).unwrap();
        assert!(diff.all_within() && diff.max_abs == 0, "{scene_name}");
    }
    // spot-smooth and spot-hard differ only at the edge of the disc.
    let read = |n: &str| essl_scene::read_png(&scenes.join("reference").join(n)).unwrap();
    let (smooth, hard) = (read("spot-smooth.png"), read("spot-hard.png"));
    let diff = essl_scene::compare(&smooth, &hard, 0).unwrap();
    assert!(diff.identical > 0 && diff.identical < diff.pixels);
    assert!(diff.max_abs > 0 && diff.mean_abs > 0.0);
    essl_scene::write_diff_png(&tmp.join("diff.png"), &smooth, &hard, 2).unwrap();
    std::fs::remove_dir_all(&tmp).ok();
}
