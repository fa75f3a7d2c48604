//! `EXT_polygon_offset_clamp`, `EXT_depth_clamp` and `WEBGL_polygon_mode`: their state waits
//! for the extension; a triangle past the far plane is drawn with depth clamped; triangles in
//! line mode draw only their edges; `polygonOffset` resets the clamp.

use essl_gl::{gl, Context, Parameter};

use crate::common;

const POLYGON_OFFSET_CLAMP: u32 = 0x8E1B;
const DEPTH_CLAMP: u32 = 0x864F;
const POLYGON_MODE: u32 = 0x0B40;
const LINE: u32 = 0x1B01;
const FILL: u32 = 0x1B02;

const FS: &str = "#version 300 es\nprecision mediump float; out vec4 o;\
    void main() { o = vec4(1.0, 0.0, 0.0, 1.0); }";

/// A vertex shader drawing its quad at depth `z`.
fn vs(z: f32) -> String {
    format!("#version 300 es\nin vec2 p; void main() {{ gl_Position = vec4(p, {z:?}, 1.0); }}")
}

fn draw(ctx: &mut Context, z: f32) {
    let p = common::program(ctx, &vs(z), FS);
    ctx.use_program(Some(p));
    common::float_attribute(ctx, 0, 2, &common::QUAD);
    common::clear_black(ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
}

#[test]
fn the_state_waits_for_each_extension() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    for pname in [POLYGON_OFFSET_CLAMP, DEPTH_CLAMP, POLYGON_MODE] {
        assert_eq!(ctx.get_parameter(pname), None);
        assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    }
    ctx.enable(DEPTH_CLAMP);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    ctx.polygon_mode_webgl(gl::FRONT_AND_BACK, LINE);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    for name in [
        "EXT_polygon_offset_clamp",
        "EXT_depth_clamp",
        "WEBGL_polygon_mode",
    ] {
        if ctx.get_extension(name).is_none() {
            eprintln!("skipped: the adapter cannot do {name}");
            return;
        }
    }
    ctx.polygon_offset_clamp_ext(1.0, 2.0, 3.0);
    assert_eq!(
        ctx.get_parameter(POLYGON_OFFSET_CLAMP),
        Some(Parameter::Float(3.0))
    );
    ctx.polygon_offset(4.0, 5.0);
    assert_eq!(
        ctx.get_parameter(POLYGON_OFFSET_CLAMP),
        Some(Parameter::Float(0.0))
    );
    ctx.enable(DEPTH_CLAMP);
    assert!(ctx.is_enabled(DEPTH_CLAMP));
    assert_eq!(ctx.get_parameter(POLYGON_MODE), Some(Parameter::Enum(FILL)));
    ctx.polygon_mode_webgl(gl::FRONT, LINE);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    ctx.polygon_mode_webgl(gl::FRONT_AND_BACK, 0);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    ctx.polygon_mode_webgl(gl::FRONT_AND_BACK, LINE);
    assert_eq!(ctx.get_parameter(POLYGON_MODE), Some(Parameter::Enum(LINE)));
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
}

#[test]
fn depth_clamp_keeps_what_the_far_plane_clips() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    if ctx.get_extension("EXT_depth_clamp").is_none() {
        return;
    }
    draw(&mut ctx, 2.0);
    assert_eq!(common::pixel(&mut ctx, 1, 1), [0, 0, 0, 255], "clipped");
    ctx.enable(DEPTH_CLAMP);
    draw(&mut ctx, 2.0);
    assert_eq!(common::pixel(&mut ctx, 1, 1), [255, 0, 0, 255], "clamped");
    common::assert_clean(&ctx);
}

#[test]
fn line_mode_draws_the_edges_only() {
    let Some(mut ctx) = common::context(16, 16) else {
        return;
    };
    if ctx.get_extension("WEBGL_polygon_mode").is_none() {
        return;
    }
    ctx.polygon_mode_webgl(gl::FRONT_AND_BACK, LINE);
    draw(&mut ctx, 0.0);
    // The quad's diagonal is an edge of both triangles; the middle of each triangle is not.
    assert_eq!(common::pixel(&mut ctx, 8, 8), [255, 0, 0, 255]);
    assert_eq!(common::pixel(&mut ctx, 11, 4), [0, 0, 0, 255]);
    assert_eq!(common::pixel(&mut ctx, 4, 11), [0, 0, 0, 255]);
    ctx.polygon_mode_webgl(gl::FRONT_AND_BACK, FILL);
    draw(&mut ctx, 0.0);
    assert_eq!(common::pixel(&mut ctx, 11, 4), [255, 0, 0, 255]);
    common::assert_clean(&ctx);
}
