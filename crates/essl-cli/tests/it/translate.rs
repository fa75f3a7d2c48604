//! `essl translate` end to end: a program and a lone shader in a folder become WGSL files and
//! binding maps next to them, in the folder `-o` names, or in the one file it names; a program
//! becomes one module with `--module single`; a shader with errors is reported as `essl lint`
//! would and not translated; every target writes something its reader takes.

use std::path::Path;
use std::process::{Command, Output};

fn essl(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_essl"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("essl runs")
}

const VERT: &str = "#version 300 es
in vec4 a_position;
in vec2 a_uv0;
uniform mat4 u_matrix;
uniform float u_weights[3];
out vec2 v_uv0;
void main() {
    v_uv0 = a_uv0 * (u_weights[0] + u_weights[2]);
    gl_Position = u_matrix * a_position;
}
";

const FRAG: &str = "#version 300 es
precision highp float;
in vec2 v_uv0;
uniform sampler2D u_tex[2];
uniform vec4 u_tint;
out vec4 outColor;
void main() {
    outColor = texture(u_tex[1], v_uv0) * u_tint + vec4(gl_FragCoord.y * 0.0);
}
";

fn project() -> tempfile::TempDir {
    let dir = tempfile::tempdir().expect("a temporary folder");
    std::fs::write(dir.path().join("tinted.vert"), VERT).unwrap();
    std::fs::write(dir.path().join("tinted.frag"), FRAG).unwrap();
    std::fs::write(dir.path().join("alone.frag"), FRAG).unwrap();
    dir
}

#[test]
fn a_folder_becomes_wgsl_and_binding_maps_next_to_it() {
    let dir = project();
    let o = essl(&["translate", ".", "--bindings", "json"], dir.path());
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("5 file(s) written (wgsl)"), "{stderr}");
    let read = |name: &str| std::fs::read_to_string(dir.path().join(name)).expect(name);
    let vert = read("tinted.vert.wgsl");
    let frag = read("tinted.frag.wgsl");
    // GLSL names kept, even those ending in a digit (naga's namer would write `v_uv0_`).
    assert!(
        vert.contains("v_uv0 = ") && frag.contains("v_uv0"),
        "{vert}\n{frag}"
    );
    assert!(
        !vert.contains("v_uv0_ ") && !vert.contains("u_weights_"),
        "{vert}"
    );
    // The std140 float array: 16-byte elements, spelled out for WGSL.
    assert!(vert.contains("@size(16) value: f32"), "{vert}");
    // The comments of what the lowering added.
    assert!(vert.contains("clip-space z runs from -w to w"), "{vert}");
    assert!(frag.contains("gl_FragCoord.y counts up in WebGL"), "{frag}");
    assert!(
        frag.contains("Each GLSL sampler is a texture and a sampler"),
        "{frag}"
    );
    let map: serde_json::Value = serde_json::from_str(&read("tinted.bindings.json")).unwrap();
    let uniform = |name: &str| {
        map["uniforms"]
            .as_array()
            .unwrap()
            .iter()
            .find(|u| u["name"] == name)
            .unwrap_or_else(|| panic!("{name} in {map:#}"))
            .clone()
    };
    assert_eq!(uniform("u_weights[0]")["array_stride"], 16);
    assert_eq!(uniform("u_weights[0]")["size"], 3);
    assert_eq!(uniform("u_tex[0]")["storage"], "sampler");
    assert_eq!(uniform("u_tex[0]")["textures"], serde_json::json!([0, 2]));
    assert_eq!(uniform("u_tex[0]")["samplers"], serde_json::json!([1, 3]));
    assert_eq!(map["internal"][0]["value"], "framebuffer_height");
    assert_eq!(map["attributes"].as_array().unwrap().len(), 2);
    // The lone shader has its own map.
    let alone: serde_json::Value = serde_json::from_str(&read("alone.frag.bindings.json")).unwrap();
    assert_eq!(alone["uniforms"].as_array().unwrap().len(), 2, "{alone:#}");
}

#[test]
fn into_a_folder_without_the_webgl_conventions() {
    let dir = project();
    let o = essl(
        &[
            "translate",
            "tinted.vert",
            "tinted.frag",
            "-o",
            "out",
            "--no-depth-remap",
            "--no-flip-y",
            "--no-comments",
        ],
        dir.path(),
    );
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let vert = std::fs::read_to_string(dir.path().join("out/tinted.vert.wgsl")).unwrap();
    let frag = std::fs::read_to_string(dir.path().join("out/tinted.frag.wgsl")).unwrap();
    assert!(!vert.contains("//") && !frag.contains("//"), "{vert}{frag}");
    assert!(!vert.contains("clip_position_depth_0_to_w"), "{vert}");
    assert!(!frag.contains("frag_coord_y_up") && !frag.contains("_essl_framebuffer_height"));
}

#[test]
fn one_output_into_the_file_o_names() {
    let dir = project();
    let o = essl(
        &[
            "translate",
            "alone.frag",
            "-o",
            "out.wgsl",
            "--bindings",
            "json",
        ],
        dir.path(),
    );
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{stderr}");
    let out = dir.path().join("out.wgsl");
    assert!(out.is_file(), "-o out.wgsl is a file");
    assert!(std::fs::read_to_string(&out).unwrap().contains("@fragment"));
    assert!(dir.path().join("out.bindings.json").is_file());
    // Two outputs (a program's stages) do not fit one file: an error, and no folder.
    let o = essl(
        &["translate", "tinted.vert", "tinted.frag", "-o", "pair.wgsl"],
        dir.path(),
    );
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("a file takes one output, and 2 would be written"),
        "{stderr}"
    );
    assert!(!dir.path().join("pair.wgsl").exists());
}

#[test]
fn a_program_as_one_module() {
    let dir = project();
    let o = essl(
        &[
            "translate",
            "tinted.vert",
            "tinted.frag",
            "--module",
            "single",
            "-o",
            "tinted.wgsl",
            "--bindings",
            "json",
        ],
        dir.path(),
    );
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{stderr}");
    let wgsl = std::fs::read_to_string(dir.path().join("tinted.wgsl")).unwrap();
    assert!(
        wgsl.contains("fn vs_main(") && wgsl.contains("fn fs_main("),
        "{wgsl}"
    );
    // One struct of both stages' uniforms, declared once.
    assert_eq!(wgsl.matches("struct Uniforms {").count(), 1, "{wgsl}");
    assert!(wgsl.contains("u_matrix: mat4x4f") && wgsl.contains("u_tint: vec4f"));
    // The binding map is the per-stage translation's.
    let single = std::fs::read_to_string(dir.path().join("tinted.bindings.json")).unwrap();
    let o = essl(
        &[
            "translate",
            "tinted.vert",
            "tinted.frag",
            "-o",
            "stages",
            "--bindings",
            "json",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(0));
    let stages = std::fs::read_to_string(dir.path().join("stages/tinted.bindings.json")).unwrap();
    assert_eq!(single, stages);
    // Other targets write a file per stage.
    let o = essl(
        &[
            "translate",
            "tinted.vert",
            "tinted.frag",
            "--module",
            "single",
            "--to",
            "msl",
        ],
        dir.path(),
    );
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn uniforms_by_their_glsl_names() {
    let dir = project();
    let o = essl(
        &[
            "translate",
            "tinted.vert",
            "--uniforms",
            "module-scope",
            "-o",
            "-",
        ],
        dir.path(),
    );
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(
        stdout.contains("let u_matrix = uniforms.u_matrix;"),
        "{stdout}"
    );
    assert!(stdout.contains("= u_matrix * a_position;"), "{stdout}");
    // The other targets read uniforms as naga's writers do.
    let o = essl(
        &[
            "translate",
            "tinted.vert",
            "--uniforms",
            "module-scope",
            "--to",
            "hlsl",
        ],
        dir.path(),
    );
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("--uniforms module-scope writes WGSL only"),
        "{stderr}"
    );
}

#[test]
fn every_target_writes() {
    let dir = project();
    for (to, ext, marker) in [
        ("spirv", "spv", None),
        ("msl", "metal", Some("#include <metal_stdlib>")),
        ("hlsl", "hlsl", Some("SV_Position")),
        ("glsl", "glsl", Some("#version 450 core")),
    ] {
        let o = essl(
            &["translate", "tinted.vert", "tinted.frag", "--to", to],
            dir.path(),
        );
        assert_eq!(
            o.status.code(),
            Some(0),
            "{to}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let bytes = std::fs::read(dir.path().join(format!("tinted.vert.{ext}"))).unwrap();
        match marker {
            Some(m) => assert!(String::from_utf8_lossy(&bytes).contains(m), "{to}"),
            // The SPIR-V magic number, little-endian.
            None => assert_eq!(bytes[..4], [0x03, 0x02, 0x23, 0x07]),
        }
    }
}

#[test]
fn a_shader_with_errors_is_reported_not_translated() {
    let dir = project();
    std::fs::write(
        dir.path().join("broken.frag"),
        FRAG.replace("u_tint +", "u_tint +;"),
    )
    .unwrap();
    let o = essl(&["translate", "broken.frag"], dir.path());
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("broken.frag:8:"), "{stderr}");
    assert!(!dir.path().join("broken.frag.wgsl").exists());
    let o = essl(&["translate", "nothing-here"], dir.path());
    assert_eq!(o.status.code(), Some(2));
}
