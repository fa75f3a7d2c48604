//! The validation mode (`Context::set_validation`): the seed spot-light programs, the articles'
//! versions before their numerical fixes and the shared scenes, rendered with equal and swapped
//! limits, a NaN uniform, a zero light direction and a shininess of 0, report the hazard with
//! its rule, uniforms and shader line; valid values report nothing; with validation off nothing
//! is reported.
//!
//! Without a Vulkan adapter the tests print why and pass, unless `ESSL_REQUIRE_ADAPTER=1`;
//! without the shared scenes the shared-scene test likewise, unless `ESSL_REQUIRE_CORPORA=1`.

use crate::common;

use std::path::{Path, PathBuf};

use essl::Stage;
use essl_gl::scene::SceneRenderer;
use essl_gl::{gl, Context, Program, ValidationWarning};
use essl_scene::Scene;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn shared_dir() -> Option<PathBuf> {
    essl_testdata::scenes()
}

/// A context with validation on, or `None` (with a message) without an adapter.
fn validating(w: u32, h: u32) -> Option<Context> {
    let mut ctx = common::context(w, h)?;
    ctx.set_validation(true);
    assert!(ctx.validation_enabled());
    Some(ctx)
}

/// The spot-light scene of articles 000/001 (`spot-smooth.json`'s set-up on a small grid),
/// drawn with the given shaders (paths relative to the repository).
fn spot_scene(vert: &str, frag: &str) -> Scene {
    let json = format!(
        r#"{{
  "width": 64, "height": 64, "clear_color": [0, 0, 0, 1], "depth_test": true, "cull_face": true,
  "vertex_shader": "{vert}", "fragment_shader": "{frag}",
  "mesh": {{"kind": "grid", "size": 200, "cells": 8}},
  "attributes": {{"a_position": "position", "a_normal": "normal"}},
  "camera": {{"eye": [0, 140, 70], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 60, "near": 1, "far": 2000}},
  "model": {{"translate": [0, 0, 0], "rotate_deg": [0, 0, 0], "scale": [1, 1, 1]}},
  "uniforms": {{
    "u_worldViewProjection": "model_view_projection", "u_world": "model",
    "u_worldInverseTranspose": "model_inverse_transpose", "u_lightWorldPosition": [0, 100, 0],
    "u_viewWorldPosition": "eye", "u_color": [0.2, 1, 0.2, 1], "u_shininess": 150,
    "u_lightColor": [1, 0.6, 0.6], "u_specularColor": [1, 0.2, 0.2],
    "u_lightDirection": {{"normalize": [0, -1, 0]}},
    "u_innerLimit": {{"cos_deg": 10}}, "u_outerLimit": {{"cos_deg": 20}}, "u_limit": {{"cos_deg": 15}}
  }}
}}"#
    );
    Scene::from_json(&json, &repo()).unwrap_or_else(|e| panic!("{vert} + {frag}: {e}"))
}

/// Sets a float uniform (scalar, vector, mat3 or mat4) of the current program by name.
fn set(ctx: &mut Context, program: Program, name: &str, v: &[f32]) {
    let loc = ctx.get_uniform_location(program, name);
    assert!(loc.is_some(), "{name} is not active");
    match v.len() {
        1 => ctx.uniform1f(loc, v[0]),
        2 => ctx.uniform2fv(loc, v),
        3 => ctx.uniform3fv(loc, v),
        4 => ctx.uniform4fv(loc, v),
        9 => ctx.uniform_matrix3fv(loc, false, v),
        16 => ctx.uniform_matrix4fv(loc, false, v),
        n => panic!("{n} values"),
    }
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "setting {name}");
}

/// Draws a frame and returns the warnings it produced.
fn frame(r: &mut SceneRenderer) -> Vec<ValidationWarning> {
    r.frame();
    r.read_image().expect("the frame renders");
    r.context().take_validation_warnings()
}

fn show(ws: &[ValidationWarning]) -> String {
    ws.iter()
        .map(|w| format!("{w}\n"))
        .collect::<Vec<_>>()
        .join("")
}

/// The one warning of `rule` in `ws`, checked: its uniforms, its line and the text there.
fn expect(
    ws: &[ValidationWarning],
    rule: &str,
    uniforms: &[&str],
    line: u32,
    text: &str,
) -> ValidationWarning {
    let mine: Vec<&ValidationWarning> = ws.iter().filter(|w| w.rule == rule).collect();
    assert_eq!(mine.len(), 1, "one {rule} warning expected:\n{}", show(ws));
    let w = mine[0].clone();
    assert_eq!(w.uniforms, uniforms, "{w}");
    let loc = w
        .location
        .as_ref()
        .unwrap_or_else(|| panic!("no location: {w}"));
    assert_eq!(loc.line, line, "{w}");
    assert!(
        loc.source_line.contains(text),
        "line {line} should contain {text:?}: {w}"
    );
    assert!(w
        .position()
        .is_some_and(|p| p.ends_with(&format!(":{line}:{}", loc.column))));
    w
}

/// A warning's rule, line, text on that line and uniforms.
type Hazard = (&'static str, u32, &'static str, [&'static str; 2]);

const EDGES: [&str; 2] = ["u_outerLimit", "u_innerLimit"];
const RANGE: [&str; 2] = ["u_innerLimit", "u_outerLimit"];

/// What a spot-light program must report.
struct Spot {
    vert: &'static str,
    frag: &'static str,
    /// Equal limits: rule, line and text of the expression at risk, uniforms, if any.
    equal: Option<Hazard>,
    /// Swapped limits.
    swapped: Option<Hazard>,
    /// The `pow` line (shininess 0); `None` where the shader keeps the exponent above 0.
    pow_line: Option<u32>,
    /// The first read of `u_shininess` (NaN).
    shininess_line: u32,
    /// Which limit uniforms the program has (`u_limit` for the hard edge).
    limits: [&'static str; 2],
}

fn check_spot(ctx: Context, scene: &Scene, s: &Spot) {
    let name = s.frag;
    let mut r = SceneRenderer::with_context(ctx, scene).unwrap_or_else(|e| panic!("{name}: {e}"));
    let p = r.program();
    let ws = frame(&mut r);
    assert!(ws.is_empty(), "{name}: valid values warn:\n{}", show(&ws));
    let (inner, outer) = (10f32.to_radians().cos(), 20f32.to_radians().cos());
    fn c(r: &mut SceneRenderer) -> &mut Context {
        r.context()
    }
    if s.limits[0] == "u_innerLimit" {
        // Equal limits.
        set(c(&mut r), p, "u_innerLimit", &[outer]);
        let ws = frame(&mut r);
        match s.equal {
            Some((rule, line, text, uniforms)) => {
                let w = expect(&ws, rule, &uniforms, line, text);
                assert!(w.message.contains("0.9396926"), "{w}");
                assert_eq!(w.stage, Some(Stage::Fragment));
                assert_eq!(w.program, p);
                assert_eq!(ws.len(), 1, "{name}:\n{}", show(&ws));
            }
            None => assert!(ws.is_empty(), "{name}: equal limits:\n{}", show(&ws)),
        }
        // The same values again: reported once, not at every draw.
        let ws = frame(&mut r);
        assert!(ws.is_empty(), "{name}: reported twice:\n{}", show(&ws));
        // Swapped limits.
        set(c(&mut r), p, "u_innerLimit", &[outer]);
        set(c(&mut r), p, "u_outerLimit", &[inner]);
        let ws = frame(&mut r);
        match s.swapped {
            Some((rule, line, text, uniforms)) => {
                let w = expect(&ws, rule, &uniforms, line, text);
                assert!(w.message.contains("swapped"), "{w}");
            }
            None => assert!(ws.is_empty(), "{name}: swapped limits:\n{}", show(&ws)),
        }
        set(c(&mut r), p, "u_innerLimit", &[inner]);
        set(c(&mut r), p, "u_outerLimit", &[outer]);
        let ws = frame(&mut r);
        assert!(ws.is_empty(), "{name}: valid again:\n{}", show(&ws));
    }

    // A NaN: reported as such, once, not as the comparisons it breaks.
    set(c(&mut r), p, "u_shininess", &[f32::NAN]);
    let ws = frame(&mut r);
    let w = expect(
        &ws,
        "non-finite-uniform",
        &["u_shininess"],
        s.shininess_line,
        "u_shininess",
    );
    assert!(w.message.contains("NaN"), "{w}");
    assert_eq!(ws.len(), 1, "{name}:\n{}", show(&ws));

    // Shininess 0 where the base of `pow` can be 0.
    set(c(&mut r), p, "u_shininess", &[0.0]);
    let ws = frame(&mut r);
    match s.pow_line {
        Some(line) => {
            let w = expect(&ws, "pow-zero-base", &["u_shininess"], line, "pow(");
            assert!(w.message.contains("`u_shininess` = 0 is not > 0"), "{w}");
        }
        None => assert!(ws.is_empty(), "{name}: shininess 0:\n{}", show(&ws)),
    }
    set(c(&mut r), p, "u_shininess", &[150.0]);

    // A zero light direction: not normalised by these shaders (the spot is just off).
    set(c(&mut r), p, "u_lightDirection", &[0.0, 0.0, 0.0]);
    let ws = frame(&mut r);
    assert!(ws.is_empty(), "{name}: zero direction:\n{}", show(&ws));

    // An infinity in a vertex-stage matrix.
    let mut m = [0.0f32; 16];
    m[0] = f32::INFINITY;
    set(c(&mut r), p, "u_world", &m);
    let ws = frame(&mut r);
    let w = ws
        .iter()
        .find(|w| w.rule == "non-finite-uniform")
        .unwrap_or_else(|| panic!("{name}: no warning for u_world:\n{}", show(&ws)));
    assert_eq!(w.uniforms, ["u_world"]);
    assert_eq!(w.stage, Some(Stage::Vertex));
    assert!(w.message.contains("infinity"), "{w}");
    assert!(r.context().backend_errors().is_empty());
}

const VERT_FIXED: &str = "shaders-glsl/spot-smooth-nbsp.fixed.vert";

fn seed_programs() -> Vec<Spot> {
    vec![
        // The corrected twin of article 000: the fix keeps the edges ordered.
        Spot {
            vert: VERT_FIXED,
            frag: "shaders-glsl/spot-smooth-nbsp.fixed.frag",
            equal: None,
            swapped: None,
            pow_line: None,
            shininess_line: 55,
            limits: ["u_innerLimit", "u_outerLimit"],
        },
        // Article 001's linear edge with its fix (`max(limitRange, 1e-4)`).
        Spot {
            vert: "shaders-glsl/spot-linear.vert",
            frag: "shaders-glsl/spot-linear.frag",
            equal: None,
            swapped: None,
            pow_line: None,
            shininess_line: 38,
            limits: ["u_innerLimit", "u_outerLimit"],
        },
        // The articles' code before the fixes.
        Spot {
            vert: VERT_FIXED,
            frag: "crates/essl-lint/tests/articles/spot-smooth-nbsp.fixed.frag",
            equal: Some((
                "smoothstep-edges",
                46,
                "smoothstep(u_outerLimit, u_innerLimit",
                EDGES,
            )),
            swapped: Some((
                "smoothstep-edges",
                46,
                "smoothstep(u_outerLimit, u_innerLimit",
                EDGES,
            )),
            pow_line: Some(50),
            shininess_line: 50,
            limits: ["u_innerLimit", "u_outerLimit"],
        },
        Spot {
            vert: "shaders-glsl/spot-linear.vert",
            frag: "crates/essl-lint/tests/articles/spot-linear.frag",
            equal: Some(("division-by-difference", 29, "/ limitRange", RANGE)),
            swapped: None,
            pow_line: Some(31),
            shininess_line: 31,
            limits: ["u_innerLimit", "u_outerLimit"],
        },
        Spot {
            vert: "shaders-glsl/spot-smoothstep.vert",
            frag: "crates/essl-lint/tests/articles/spot-smoothstep.frag",
            equal: Some((
                "smoothstep-edges",
                28,
                "smoothstep(u_outerLimit, u_innerLimit",
                EDGES,
            )),
            swapped: Some((
                "smoothstep-edges",
                28,
                "smoothstep(u_outerLimit, u_innerLimit",
                EDGES,
            )),
            pow_line: Some(30),
            shininess_line: 30,
            limits: ["u_innerLimit", "u_outerLimit"],
        },
        Spot {
            vert: "shaders-glsl/spot-step.vert",
            frag: "crates/essl-lint/tests/articles/spot-step.frag",
            equal: None,
            swapped: None,
            pow_line: Some(29),
            shininess_line: 29,
            limits: ["u_limit", ""],
        },
    ]
}

#[test]
fn seed_spot_lights() {
    for s in seed_programs() {
        let Some(ctx) = validating(64, 64) else {
            return;
        };
        check_spot(ctx, &spot_scene(s.vert, s.frag), &s);
    }
}

#[test]
fn shared_scenes() {
    let Some(dir) = shared_dir() else { return };
    let load = |name: &str| Scene::load(dir.join(name)).expect("a scene");
    let spots = [
        Spot {
            vert: "spot.vert",
            frag: "spot-smooth.json",
            equal: Some((
                "smoothstep-edges",
                43,
                "smoothstep(u_outerLimit, u_innerLimit",
                EDGES,
            )),
            swapped: Some((
                "smoothstep-edges",
                43,
                "smoothstep(u_outerLimit, u_innerLimit",
                EDGES,
            )),
            pow_line: Some(47),
            shininess_line: 47,
            limits: ["u_innerLimit", "u_outerLimit"],
        },
        Spot {
            vert: "spot.vert",
            frag: "spot-linear.json",
            equal: Some(("division-by-difference", 44, "/ limitRange", RANGE)),
            swapped: None,
            pow_line: Some(48),
            shininess_line: 48,
            limits: ["u_innerLimit", "u_outerLimit"],
        },
        Spot {
            vert: "spot.vert",
            frag: "spot-hard.json",
            equal: None,
            swapped: None,
            pow_line: Some(47),
            shininess_line: 47,
            limits: ["u_limit", ""],
        },
    ];
    for s in &spots {
        let Some(ctx) = validating(256, 256) else {
            return;
        };
        check_spot(ctx, &load(s.frag), s);
    }

    // The flashlight cookie: `gl_FragCoord.xy / u_viewport` with the viewport never set.
    let Some(ctx) = validating(256, 256) else {
        return;
    };
    let mut r = SceneRenderer::with_context(ctx, &load("spot-cookie.json")).expect("spot-cookie");
    let p = r.program();
    assert!(frame(&mut r).is_empty());
    set(r.context(), p, "u_viewport", &[0.0, 0.0]);
    let ws = frame(&mut r);
    let w = expect(&ws, "division-by-zero", &["u_viewport"], 49, "/ u_viewport");
    assert!(w.message.contains("was it set?"), "{w}");
    assert_eq!(w.location.as_ref().unwrap().file, "spot-cookie.frag");

    // Gouraud: `normalize(uLightDirection)` in the vertex shader.
    let Some(ctx) = validating(256, 256) else {
        return;
    };
    let mut r =
        SceneRenderer::with_context(ctx, &load("gouraud-lambert.json")).expect("gouraud-lambert");
    let p = r.program();
    assert!(frame(&mut r).is_empty());
    set(r.context(), p, "uLightDirection", &[0.0, 0.0, 0.0]);
    let ws = frame(&mut r);
    let w = expect(
        &ws,
        "normalize-zero",
        &["uLightDirection"],
        19,
        "normalize(uLightDirection)",
    );
    assert_eq!(w.stage, Some(Stage::Vertex));
    assert_eq!(w.location.as_ref().unwrap().file, "gouraud-lambert.vert");
    assert!(w.message.contains("zero vector"), "{w}");

    // Phong: `pow(max(dot(R, E), 0.0), uShininess)`.
    let Some(ctx) = validating(256, 256) else {
        return;
    };
    let mut r =
        SceneRenderer::with_context(ctx, &load("phong-positional.json")).expect("phong-positional");
    let p = r.program();
    assert!(frame(&mut r).is_empty());
    set(r.context(), p, "uShininess", &[0.0]);
    let ws = frame(&mut r);
    expect(
        &ws,
        "pow-zero-base",
        &["uShininess"],
        33,
        "pow(max(dot(R, E)",
    );
    set(r.context(), p, "uShininess", &[-2.0]);
    let ws = frame(&mut r);
    expect(
        &ws,
        "pow-zero-base",
        &["uShininess"],
        33,
        "pow(max(dot(R, E)",
    );
}

/// Compiles, links and uses a program from repository files, named as the files.
fn program(ctx: &mut Context, vert: &str, frag: &str) -> Program {
    let p = ctx.create_program();
    for (ty, path) in [(gl::VERTEX_SHADER, vert), (gl::FRAGMENT_SHADER, frag)] {
        let text = std::fs::read_to_string(repo().join(path)).expect("a shader");
        let sh = ctx.create_shader(ty).expect("a shader");
        ctx.set_shader_name(sh, Path::new(path).file_name().unwrap().to_str().unwrap());
        ctx.shader_source(sh, &text);
        ctx.compile_shader(sh);
        assert!(ctx.get_shader_compile_status(sh), "{path}");
        ctx.attach_shader(p, sh);
    }
    ctx.link_program(p);
    assert!(
        ctx.get_program_link_status(p),
        "{:?}",
        ctx.get_program_info_log(p)
    );
    ctx.use_program(Some(p));
    p
}

/// One triangle from generic attribute values (enough for the checks, which run per draw).
fn draw(ctx: &mut Context) -> Vec<ValidationWarning> {
    ctx.draw_arrays(gl::TRIANGLES, 0, 3);
    ctx.finish();
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    ctx.take_validation_warnings()
}

const IDENTITY4: [f32; 16] = [
    1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
];

#[test]
fn article_004_flashlight() {
    let Some(mut ctx) = validating(32, 32) else {
        return;
    };
    let p = program(
        &mut ctx,
        "shaders-glsl/spot-flashlight-cookie.vert",
        "shaders-glsl/spot-flashlight-cookie.frag",
    );
    let valid = |ctx: &mut Context| {
        for m in ["model", "view", "projection"] {
            set(ctx, p, m, &IDENTITY4);
        }
        set(ctx, p, "viewPos", &[0.0, 0.0, 3.0]);
        set(ctx, p, "material.shininess", &[32.0]);
        set(ctx, p, "light.position", &[0.0, 0.0, 3.0]);
        set(ctx, p, "light.direction", &[0.0, 0.0, -1.0]);
        set(ctx, p, "light.cutOff", &[12.5f32.to_radians().cos()]);
        set(ctx, p, "light.outerCutOff", &[17.5f32.to_radians().cos()]);
        set(ctx, p, "light.ambient", &[0.1, 0.1, 0.1]);
        set(ctx, p, "light.diffuse", &[0.8, 0.8, 0.8]);
        set(ctx, p, "light.specular", &[1.0, 1.0, 1.0]);
        set(ctx, p, "viewPort", &[32.0, 32.0]);
    };
    // Nothing set: every zero default that breaks something is reported.
    let ws = draw(&mut ctx);
    let rules: Vec<&str> = ws.iter().map(|w| w.rule).collect();
    for rule in [
        "pow-zero-base",
        "normalize-zero",
        "division-by-difference",
        "division-by-zero",
    ] {
        assert!(rules.contains(&rule), "{rule} missing:\n{}", show(&ws));
    }
    valid(&mut ctx);
    let ws = draw(&mut ctx);
    assert!(ws.is_empty(), "valid values warn:\n{}", show(&ws));

    // Article 004's `epsilon = light.cutOff - light.outerCutOff` with equal angles.
    set(
        &mut ctx,
        p,
        "light.outerCutOff",
        &[12.5f32.to_radians().cos()],
    );
    let ws = draw(&mut ctx);
    let w = expect(
        &ws,
        "division-by-difference",
        &["light.cutOff", "light.outerCutOff"],
        65,
        "/ epsilon",
    );
    assert_eq!(ws.len(), 1, "{}", show(&ws));
    assert_eq!(
        w.location.as_ref().unwrap().to_string(),
        "spot-flashlight-cookie.frag:65:55"
    );
    valid(&mut ctx);
    // A zero light direction: `normalize(-light.direction)`.
    set(&mut ctx, p, "light.direction", &[0.0, 0.0, 0.0]);
    let ws = draw(&mut ctx);
    expect(
        &ws,
        "normalize-zero",
        &["light.direction"],
        63,
        "normalize(-light.direction)",
    );
    valid(&mut ctx);
    set(&mut ctx, p, "material.shininess", &[0.0]);
    let ws = draw(&mut ctx);
    expect(
        &ws,
        "pow-zero-base",
        &["material.shininess"],
        59,
        "material.shininess",
    );
    valid(&mut ctx);
    set(&mut ctx, p, "light.cutOff", &[f32::NAN]);
    let ws = draw(&mut ctx);
    expect(
        &ws,
        "non-finite-uniform",
        &["light.cutOff"],
        64,
        "light.cutOff",
    );
    assert_eq!(ws.len(), 1, "{}", show(&ws));
    assert!(ctx.backend_errors().is_empty());
}

#[test]
fn article_003_projected_texture() {
    let Some(mut ctx) = validating(32, 32) else {
        return;
    };
    let p = program(
        &mut ctx,
        "shaders-glsl/spot-projected-texture.vert",
        "shaders-glsl/spot-projected-texture.frag",
    );
    let valid = |ctx: &mut Context| {
        set(ctx, p, "u_modelView", &IDENTITY4);
        set(ctx, p, "u_projection", &IDENTITY4);
        set(
            ctx,
            p,
            "u_normalMatrix",
            &[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0],
        );
        set(ctx, p, "spotLights[0].position", &[0.0, 0.0, 5.0]);
        set(ctx, p, "spotLights[0].direction", &[0.0, 0.0, -1.0]);
        set(ctx, p, "spotLights[0].color", &[1.0, 1.0, 1.0]);
        set(ctx, p, "spotLights[0].distance", &[0.0]);
        set(ctx, p, "spotLights[0].decay", &[1.0]);
        set(ctx, p, "spotLights[0].coneCos", &[30f32.to_radians().cos()]);
        set(
            ctx,
            p,
            "spotLights[0].penumbraCos",
            &[25f32.to_radians().cos()],
        );
        set(ctx, p, "spotLightExs[0].up", &[0.0, 1.0, 0.0]);
        set(ctx, p, "spotLightExs[0].intensity", &[1.0]);
    };
    valid(&mut ctx);
    let ws = draw(&mut ctx);
    assert!(ws.is_empty(), "valid values warn:\n{}", show(&ws));

    // three.js's `smoothstep(coneCosine, penumbraCosine, …)` with no penumbra, through two
    // helper calls.
    set(
        &mut ctx,
        p,
        "spotLights[0].penumbraCos",
        &[30f32.to_radians().cos()],
    );
    let ws = draw(&mut ctx);
    let w = expect(
        &ws,
        "smoothstep-edges",
        &["spotLights[0].coneCos", "spotLights[0].penumbraCos"],
        55,
        "smoothstep( coneCosine, penumbraCosine",
    );
    assert_eq!(w.call_sites.len(), 2, "{w}");
    assert_eq!(w.call_sites[0].line, 134, "{w}");
    assert_eq!(w.call_sites[1].line, 75, "{w}");
    valid(&mut ctx);
    // Article 003's `normalize(cross(spotLightEx.up, spotLight.direction))` for a light
    // pointing along its up vector.
    set(&mut ctx, p, "spotLights[0].direction", &[0.0, -2.0, 0.0]);
    let ws = draw(&mut ctx);
    let w = expect(
        &ws,
        "normalize-zero",
        &["spotLightExs[0].up", "spotLights[0].direction"],
        101,
        "normalize(cross(spotLightEx.up, spotLight.direction))",
    );
    assert!(w.message.contains("parallel"), "{w}");
    valid(&mut ctx);
    // `acos(spotLight.coneCos)` of a cosine past 1.
    set(&mut ctx, p, "spotLights[0].coneCos", &[1.5]);
    let ws = draw(&mut ctx);
    expect(
        &ws,
        "acos-domain",
        &["spotLights[0].coneCos"],
        87,
        "acos(spotLight.coneCos)",
    );
    // A cone of angle 0: `/ (2.0 * coneAngle)` twice.
    set(&mut ctx, p, "spotLights[0].coneCos", &[1.0]);
    let ws = draw(&mut ctx);
    let lines: Vec<u32> = ws
        .iter()
        .filter(|w| w.rule == "division-by-zero")
        .map(|w| w.location.as_ref().unwrap().line)
        .collect();
    assert_eq!(lines, [98, 109], "{}", show(&ws));
    assert!(ctx.backend_errors().is_empty());
}

#[test]
fn nothing_is_reported_with_validation_off() {
    let Some(ctx) = common::context(64, 64) else {
        return;
    };
    assert!(!ctx.validation_enabled());
    let scene = spot_scene(
        VERT_FIXED,
        "crates/essl-lint/tests/articles/spot-smooth-nbsp.fixed.frag",
    );
    let mut r = SceneRenderer::with_context(ctx, &scene).expect("the scene");
    let p = r.program();
    let v = 20f32.to_radians().cos();
    set(r.context(), p, "u_innerLimit", &[v]);
    set(r.context(), p, "u_shininess", &[f32::NAN]);
    set(r.context(), p, "u_lightDirection", &[0.0, 0.0, 0.0]);
    for _ in 0..3 {
        assert!(frame(&mut r).is_empty());
    }
    assert_eq!(r.context().validation_warnings_dropped(), 0);
    // Turned on later, it checks the program linked before.
    r.context().set_validation(true);
    let ws = frame(&mut r);
    let rules: Vec<&str> = ws.iter().map(|w| w.rule).collect();
    assert_eq!(
        rules,
        ["non-finite-uniform", "smoothstep-edges"],
        "{}",
        show(&ws)
    );
    expect(&ws, "smoothstep-edges", &EDGES, 46, "smoothstep");
    // Fixing the NaN reports nothing new.
    set(r.context(), p, "u_shininess", &[150.0]);
    assert!(frame(&mut r).is_empty());
    // And off again.
    r.context().set_validation(false);
    set(r.context(), p, "u_shininess", &[0.0]);
    assert!(frame(&mut r).is_empty());
}

#[test]
fn the_preconditions_of_a_program() {
    let Some(mut ctx) = common::context(8, 8) else {
        return;
    };
    let p = program(
        &mut ctx,
        "shaders-glsl/spot-linear.vert",
        "crates/essl-lint/tests/articles/spot-linear.frag",
    );
    let pre: Vec<String> = ctx
        .program_preconditions(p)
        .iter()
        .filter(|p| p.rule != "non-finite-uniform")
        .map(|p| format!("{:?} {} {}", p.stage, p.rule, p.condition))
        .collect();
    assert_eq!(
        pre,
        [
            "Fragment division-by-difference u_innerLimit != u_outerLimit",
            "Fragment pow-zero-base u_shininess > 0"
        ]
    );
    // A program linked from a layout has no source: no preconditions (finite checks only).
    let q = ctx.program_from_layout(common::solid(1.0, 0.0, 0.0));
    assert!(ctx.program_preconditions(q).is_empty());
}

#[test]
fn mediump_range() {
    let Some(mut ctx) = validating(8, 8) else {
        return;
    };
    // Article 001's shader is `precision mediump float`; its vertex shader is highp.
    let p = program(
        &mut ctx,
        "shaders-glsl/spot-linear.vert",
        "crates/essl-lint/tests/articles/spot-linear.frag",
    );
    set(&mut ctx, p, "u_innerLimit", &[0.98]);
    set(&mut ctx, p, "u_outerLimit", &[0.9]);
    set(&mut ctx, p, "u_shininess", &[150.0]);
    // 1e5 is a fine highp value.
    set(&mut ctx, p, "u_lightWorldPosition", &[1e5, 0.0, 0.0]);
    let ws = draw(&mut ctx);
    assert!(ws.is_empty(), "{}", show(&ws));
    set(&mut ctx, p, "u_shininess", &[1e5]);
    let ws = draw(&mut ctx);
    let w = expect(&ws, "mediump-overflow", &["u_shininess"], 31, "u_shininess");
    assert!(w.message.contains("65504"), "{w}");
    assert_eq!(ws.len(), 1, "{}", show(&ws));
    // Equal limits that differ in highp but not in mediump.
    set(&mut ctx, p, "u_shininess", &[150.0]);
    set(&mut ctx, p, "u_innerLimit", &[0.9001]);
    let ws = draw(&mut ctx);
    let w = expect(&ws, "division-by-difference", &RANGE, 29, "/ limitRange");
    assert!(
        w.message.contains("0.9001") && w.message.contains("in mediump"),
        "{w}"
    );
}

#[test]
fn arrays_of_structs_indexed_in_a_loop() {
    let Some(mut ctx) = validating(8, 8) else {
        return;
    };
    let vert = "#version 300 es\nin vec4 a_position;\nvoid main() { gl_Position = a_position; }\n";
    let frag = "#version 300 es\nprecision highp float;\n\
                struct Spot { vec3 direction; float inner; float outer; };\n\
                uniform Spot u_spots[3];\nin vec3 v_dummy;\nout vec4 o;\n\
                void main() {\n  float light = 0.0;\n\
                \x20 for (int i = 0; i < 3; i++) {\n\
                \x20   float d = dot(vec3(0.0, 0.0, -1.0), normalize(u_spots[i].direction));\n\
                \x20   light += smoothstep(u_spots[i].outer, u_spots[i].inner, d);\n  }\n\
                \x20 o = vec4(light);\n}\n";
    let vert = vert
        .replace(
            "in vec4 a_position;\n",
            "in vec4 a_position;\nout vec3 v_dummy;\n",
        )
        .replace(
            "gl_Position = a_position;",
            "gl_Position = a_position; v_dummy = a_position.xyz;",
        );
    let p = ctx.create_program();
    for (ty, text, name) in [
        (gl::VERTEX_SHADER, vert.as_str(), "spots.vert"),
        (gl::FRAGMENT_SHADER, frag, "spots.frag"),
    ] {
        let sh = ctx.create_shader(ty).expect("a shader");
        ctx.set_shader_name(sh, name);
        ctx.shader_source(sh, text);
        ctx.compile_shader(sh);
        assert!(
            ctx.get_shader_compile_status(sh),
            "{:?}",
            ctx.get_shader_info_log(sh)
        );
        ctx.attach_shader(p, sh);
    }
    ctx.link_program(p);
    assert!(
        ctx.get_program_link_status(p),
        "{:?}",
        ctx.get_program_info_log(p)
    );
    ctx.use_program(Some(p));
    let conds: Vec<String> = ctx
        .program_preconditions(p)
        .iter()
        .filter(|p| p.rule != "non-finite-uniform")
        .map(|p| p.condition.to_string())
        .collect();
    assert_eq!(
        conds,
        [
            "length(u_spots[*].direction) > 0",
            "u_spots[*].outer < u_spots[*].inner"
        ]
    );
    for i in 0..3 {
        set(
            &mut ctx,
            p,
            &format!("u_spots[{i}].direction"),
            &[0.0, 0.0, -1.0],
        );
        set(&mut ctx, p, &format!("u_spots[{i}].inner"), &[0.98]);
        set(&mut ctx, p, &format!("u_spots[{i}].outer"), &[0.9]);
    }
    let ws = draw(&mut ctx);
    assert!(ws.is_empty(), "{}", show(&ws));
    // Element 1's limits equal, element 2's direction zero: each named with its index.
    set(&mut ctx, p, "u_spots[1].outer", &[0.98]);
    set(&mut ctx, p, "u_spots[2].direction", &[0.0, 0.0, 0.0]);
    let ws = draw(&mut ctx);
    let w = expect(
        &ws,
        "smoothstep-edges",
        &["u_spots[1].outer", "u_spots[1].inner"],
        11,
        "smoothstep(u_spots[i].outer",
    );
    assert!(w.message.contains("`u_spots[1].outer` = 0.98"), "{w}");
    expect(
        &ws,
        "normalize-zero",
        &["u_spots[2].direction"],
        10,
        "normalize(u_spots[i].direction)",
    );
    assert_eq!(ws.len(), 2, "{}", show(&ws));
}
