//! GLSL ES 1.00 programs drawn by essl-gl: the `render: true` cases of the WebGL conformance
//! suite's ES 1.00 shaders, drawn as its harness (GLSLConformanceTester) draws them, in a
//! context compiling for WebGL 1 and in one compiling for WebGL 2. A case is expected to draw
//! its `render_color` (green by default) on every pixel wherever Chromium did
//! (`tests/oracle/es100-render.json`, written by `tests/oracle/render_es100.py`).

use crate::common;

use essl::Target;
use essl_gl::{gl, Context};
use serde_json::Value;

const SIZE: u32 = 32;

/// The harness's quad: two triangles, vec3 positions.
const POSITIONS: [f32; 18] = [
    1.0, 1.0, 0.0, -1.0, 1.0, 0.0, -1.0, -1.0, 0.0, 1.0, 1.0, 0.0, -1.0, -1.0, 0.0, 1.0, -1.0, 0.0,
];
/// The harness's texture coordinates, one vec2 per vertex.
const TEX_COORDS: [f32; 12] = [1.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0];

/// Compiles, links and draws one case; `Err` says which step failed or what was drawn.
fn draw(ctx: &mut Context, vs: &str, fs: &str, color: [u8; 4]) -> Result<(), String> {
    let p = ctx.create_program();
    let mut shaders = Vec::new();
    for (ty, src) in [(gl::VERTEX_SHADER, vs), (gl::FRAGMENT_SHADER, fs)] {
        let s = ctx.create_shader(ty).expect("a shader type");
        ctx.shader_source(s, src);
        ctx.compile_shader(s);
        if !ctx.get_shader_compile_status(s) {
            return Err(format!("compile: {:?}", ctx.get_shader_info_log(s)));
        }
        ctx.attach_shader(p, s);
        shaders.push(s);
    }
    if vs.contains("vPosition") {
        ctx.bind_attrib_location(p, 0, "vPosition");
    }
    if vs.contains("texCoord0") {
        ctx.bind_attrib_location(p, 1, "texCoord0");
    }
    ctx.link_program(p);
    if !ctx.get_program_link_status(p) {
        return Err(format!("link: {:?}", ctx.get_program_info_log(p)));
    }
    ctx.use_program(Some(p));
    let b0 = common::float_attribute(ctx, 0, 3, &POSITIONS);
    let b1 = common::float_attribute(ctx, 1, 2, &TEX_COORDS);
    ctx.clear_color(1.0, 1.0, 1.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    let error = ctx.get_error();
    let pixels = common::all_pixels(ctx);
    ctx.use_program(None);
    ctx.delete_program(p);
    for s in shaders {
        ctx.delete_shader(s);
    }
    ctx.delete_buffer(b0);
    ctx.delete_buffer(b1);
    if error != gl::NO_ERROR {
        return Err(format!("draw: 0x{error:04X} {:?}", ctx.error_message()));
    }
    let wrong = pixels.chunks_exact(4).filter(|p| *p != color).count();
    match wrong {
        0 => Ok(()),
        n => Err(format!(
            "{n} of {} pixels are not {color:?} (centre {:?})",
            SIZE * SIZE,
            &pixels[((16 * SIZE + 16) * 4) as usize..][..4]
        )),
    }
}

/// The case's colour: `render_color` as 0..255 bytes, green when absent.
fn render_color(case: &Value) -> [u8; 4] {
    match case["render_color"].as_array() {
        Some(c) if c.len() == 4 => {
            let mut rgba = [0u8; 4];
            for (out, v) in rgba.iter_mut().zip(c) {
                *out = v.as_u64().expect("a byte") as u8;
            }
            rgba
        }
        _ => [0, 255, 0, 255],
    }
}

/// Draws every render case Chromium drew in `context` (`webgl1` or `webgl2`) with a context
/// compiling for `target`.
fn draws_what_chromium_draws(target: Target, context: &str) {
    let Some(corpus) = essl_testdata::corpus_file("webgl_conformance_es100.jsonl") else {
        return;
    };
    let Some(mut ctx) = common::context(SIZE, SIZE) else {
        return;
    };
    // The harness's page turns on no extension.
    ctx.set_shader_target(target, &[]);
    let path = essl_testdata::repo_root().join("tests/oracle/es100-render.json");
    let oracle: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let (mut drawn, mut failures) = (0, Vec::new());
    for line in std::fs::read_to_string(&corpus).unwrap().lines() {
        let case: Value = serde_json::from_str(line).unwrap();
        if case["render"] != Value::Bool(true) {
            continue;
        }
        let key = format!("{}#{}", case["file"].as_str().unwrap(), case["index"]);
        if oracle[&key][context]["drawn"] != Value::Bool(true) {
            continue;
        }
        let vs = case["vertex_source"].as_str().unwrap();
        let fs = case["fragment_source"].as_str().unwrap();
        match draw(&mut ctx, vs, fs, render_color(&case)) {
            Ok(()) => drawn += 1,
            Err(e) => failures.push(format!("{key}: {e}")),
        }
    }
    println!("{context}: {drawn} cases drawn as Chromium draws them");
    assert!(drawn >= 600, "only {drawn} cases");
    assert!(
        failures.is_empty(),
        "{} cases differ from Chromium:\n{}",
        failures.len(),
        failures.join("\n")
    );
    common::assert_clean(&ctx);
}

#[test]
fn webgl1_draws_the_render_cases_as_chromium_does() {
    draws_what_chromium_draws(Target::WebGl1, "webgl1");
}

#[test]
fn webgl2_draws_the_render_cases_as_chromium_does() {
    draws_what_chromium_draws(Target::WebGl2, "webgl2");
}

#[test]
fn a_webgl1_context_refuses_glsl_es_300() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    let source = "#version 300 es\nin vec4 p;\nvoid main() { gl_Position = p; }";
    let compiles = |ctx: &mut Context| {
        let s = ctx.create_shader(gl::VERTEX_SHADER).unwrap();
        ctx.shader_source(s, source);
        ctx.compile_shader(s);
        (
            ctx.get_shader_compile_status(s),
            ctx.get_shader_info_log(s).unwrap(),
        )
    };
    assert_eq!(ctx.shader_target(), Target::WebGl2);
    assert_eq!(compiles(&mut ctx), (true, String::new()));
    ctx.set_shader_target(Target::WebGl1, &essl::Extension::ALL);
    let (ok, log) = compiles(&mut ctx);
    assert!(!ok);
    assert!(log.starts_with("ERROR: 0:1: "), "{log}");
}

#[test]
fn a_webgl1_shader_enables_only_the_extensions_the_context_turned_on() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    let source = "#extension GL_OES_standard_derivatives : enable
precision mediump float;
varying vec2 v;
void main() { gl_FragColor = vec4(dFdx(v), 0.0, 1.0); }";
    let mut compiles = |extensions: &[essl::Extension]| {
        ctx.set_shader_target(Target::WebGl1, extensions);
        let s = ctx.create_shader(gl::FRAGMENT_SHADER).unwrap();
        ctx.shader_source(s, source);
        ctx.compile_shader(s);
        ctx.get_shader_compile_status(s)
    };
    assert!(!compiles(&[]));
    assert!(compiles(&[essl::Extension::OesStandardDerivatives]));
}
