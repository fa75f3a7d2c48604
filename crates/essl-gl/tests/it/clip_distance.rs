//! `WEBGL_clip_cull_distance`: the switches and limits appear with the extension, a vertex
//! shader's `gl_ClipDistance` clips where its switch is on, and a fragment shader reads the
//! interpolated distances.

use essl_gl::{gl, Context, Parameter};

use crate::common;

const MAX_CLIP_DISTANCES_WEBGL: u32 = 0x0D32;
const MAX_CULL_DISTANCES_WEBGL: u32 = 0x82F9;
const CLIP_DISTANCE0_WEBGL: u32 = 0x3000;

/// A vertex shader that clips at the plane `u_plane` with distance 0 and writes its
/// distances to the seven others as `k`·x.
const VS: &str = "#version 300 es
#extension GL_ANGLE_clip_cull_distance : require
uniform vec4 u_plane;
in vec2 p;
void main() {
    gl_Position = vec4(p, 0.0, 1.0);
    gl_ClipDistance[0] = dot(gl_Position, u_plane);
    for (int i = 1; i < gl_MaxClipDistances; i++) gl_ClipDistance[i] = float(i) * 0.1;
}";

const FS: &str = "#version 300 es
precision mediump float;
out vec4 o;
void main() { o = vec4(1.0, 0.0, 0.0, 1.0); }";

/// A 32 × 32 WebGL 2 context with the extension on; `None` (with a message) where the
/// adapter has no clip distances.
fn context() -> Option<Context> {
    let mut ctx = common::context(32, 32)?;
    if ctx.get_extension("WEBGL_clip_cull_distance").is_none() {
        eprintln!("skipped: the adapter has no clip distances (wgpu's CLIP_DISTANCES)");
        return None;
    }
    Some(ctx)
}

/// Draws the full-canvas quad over blue.
fn draw(ctx: &mut Context) {
    ctx.clear_color(0.0, 0.0, 1.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
}

#[test]
fn switches_and_limits_wait_for_the_extension() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    ctx.enable(CLIP_DISTANCE0_WEBGL);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    assert!(ctx.get_parameter(MAX_CLIP_DISTANCES_WEBGL).is_none());
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    let s = ctx.create_shader(gl::VERTEX_SHADER).expect("a shader");
    ctx.shader_source(s, VS);
    ctx.compile_shader(s);
    assert!(
        !ctx.get_shader_compile_status(s),
        "the directive needs the extension"
    );
    let log = ctx.get_shader_info_log(s).unwrap_or_default();
    assert!(log.contains("GL_ANGLE_clip_cull_distance"), "{log}");
    if ctx.get_extension("WEBGL_clip_cull_distance").is_none() {
        return;
    }
    assert_eq!(
        ctx.get_parameter(MAX_CLIP_DISTANCES_WEBGL),
        Some(Parameter::Int(8))
    );
    assert_eq!(
        ctx.get_parameter(MAX_CULL_DISTANCES_WEBGL),
        Some(Parameter::Int(0))
    );
    for i in 0..8 {
        let cap = CLIP_DISTANCE0_WEBGL + i;
        assert!(!ctx.is_enabled(cap));
        ctx.enable(cap);
        assert!(ctx.is_enabled(cap));
        assert_eq!(ctx.get_parameter(cap), Some(Parameter::Bool(true)));
        ctx.disable(cap);
        assert!(!ctx.is_enabled(cap));
    }
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.enable(CLIP_DISTANCE0_WEBGL + 8);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
}

#[test]
fn an_enabled_distance_clips_and_a_disabled_one_does_not() {
    let Some(mut ctx) = context() else { return };
    let p = common::program(&mut ctx, VS, FS);
    ctx.use_program(Some(p));
    common::float_attribute(&mut ctx, 0, 2, &common::QUAD);
    let plane = ctx.get_uniform_location(p, "u_plane");
    // Keep x > −0.5: the left quarter (columns 0..8) stays blue.
    ctx.uniform4f(plane, 1.0, 0.0, 0.0, 0.5);
    ctx.enable(CLIP_DISTANCE0_WEBGL);
    draw(&mut ctx);
    let red = [255, 0, 0, 255];
    let blue = [0, 0, 255, 255];
    for x in [0, 3, 6] {
        assert_eq!(common::pixel(&mut ctx, x, 16), blue, "column {x}");
    }
    for x in [10, 20, 31] {
        assert_eq!(common::pixel(&mut ctx, x, 16), red, "column {x}");
    }
    // The other distances are positive and enabled or not, clip nothing.
    for i in 1..8 {
        ctx.enable(CLIP_DISTANCE0_WEBGL + i);
    }
    ctx.disable(CLIP_DISTANCE0_WEBGL);
    draw(&mut ctx);
    assert!(common::all_are(&mut ctx, red), "distance 0 switched off");
    common::assert_clean(&ctx);
}

#[test]
fn a_fragment_shader_reads_the_interpolated_distances() {
    let Some(mut ctx) = context() else { return };
    let vs = "#version 300 es
#extension GL_ANGLE_clip_cull_distance : require
in vec2 p;
out float v;
void main() {
    gl_Position = vec4(p, 0.0, 1.0);
    v = 0.25;
    gl_ClipDistance[0] = dot(gl_Position, vec4(1, 0, 0, 0.5));
    gl_ClipDistance[1] = dot(gl_Position, vec4(-1, 0, 0, 0.5));
    gl_ClipDistance[6] = 0.5 + 0.5 * p.y;
}";
    let fs = "#version 300 es
#extension GL_ANGLE_clip_cull_distance : require
precision highp float;
in float v;
out vec4 o;
void main() {
    o = vec4(gl_ClipDistance[0] + gl_ClipDistance[1], gl_ClipDistance[6], v, 1.0);
}";
    let p = common::program(&mut ctx, vs, fs);
    ctx.use_program(Some(p));
    common::float_attribute(&mut ctx, 0, 2, &common::QUAD);
    ctx.enable(CLIP_DISTANCE0_WEBGL);
    ctx.enable(CLIP_DISTANCE0_WEBGL + 1);
    draw(&mut ctx);
    // Columns 8..24 survive both planes: red is d0 + d1 = 1, green the row's height.
    let [r, g, b, _] = common::pixel(&mut ctx, 16, 8);
    assert_eq!(
        (r, b),
        (255, 64),
        "the sum of the two distances and the user varying"
    );
    assert!(
        (g as i32 - 70).abs() <= 2,
        "row 8 of 32: 0.5 + 0.5·y ≈ 0.27, got {g}"
    );
    assert_eq!(common::pixel(&mut ctx, 2, 8), [0, 0, 255, 255]);
    assert_eq!(common::pixel(&mut ctx, 29, 8), [0, 0, 255, 255]);
    common::assert_clean(&ctx);
}
