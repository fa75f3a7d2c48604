//! `EXT_clip_control`: the state and its errors, the origin (the image and facing), the depth
//! mode, and transform feedback capturing `gl_Position` as the shader wrote it.

use essl_gl::{gl, Context, Parameter};

use crate::common;

const LOWER_LEFT_EXT: u32 = 0x8CA1;
const UPPER_LEFT_EXT: u32 = 0x8CA2;
const NEGATIVE_ONE_TO_ONE_EXT: u32 = 0x935E;
const ZERO_TO_ONE_EXT: u32 = 0x935F;
const CLIP_ORIGIN_EXT: u32 = 0x935C;
const CLIP_DEPTH_MODE_EXT: u32 = 0x935D;

/// A shader of a triangle in the upper-left half of the canvas (counter-clockwise in clip
/// space), at depth `z`, red.
const VS: &str = "#version 300 es
in vec2 p;
uniform float z;
void main() { gl_Position = vec4(p, z, 1.0); }";
const FS: &str = "#version 300 es
precision mediump float;
uniform vec4 c;
out vec4 o;
void main() { o = c; }";
const TRIANGLE: [f32; 6] = [-1.0, -1.0, 1.0, 1.0, -1.0, 1.0];

fn setup(ctx: &mut Context) -> essl_gl::Program {
    assert!(ctx.get_extension("EXT_clip_control").is_some());
    let p = common::program(ctx, VS, FS);
    ctx.use_program(Some(p));
    common::float_attribute(ctx, 0, 2, &TRIANGLE);
    p
}

fn draw(ctx: &mut Context, p: essl_gl::Program, z: f32, rgba: [f32; 4]) {
    let zl = ctx.get_uniform_location(p, "z");
    ctx.uniform1f(zl, z);
    let cl = ctx.get_uniform_location(p, "c");
    ctx.uniform4f(cl, rgba[0], rgba[1], rgba[2], rgba[3]);
    ctx.draw_arrays(gl::TRIANGLES, 0, 3);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
}

#[test]
fn state_and_errors() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    ctx.clip_control_ext(UPPER_LEFT_EXT, ZERO_TO_ONE_EXT);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "before the extension"
    );
    assert!(ctx.get_parameter(CLIP_ORIGIN_EXT).is_none());
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    setup(&mut ctx);
    assert_eq!(
        ctx.get_parameter(CLIP_ORIGIN_EXT),
        Some(Parameter::Enum(LOWER_LEFT_EXT))
    );
    ctx.clip_control_ext(UPPER_LEFT_EXT, ZERO_TO_ONE_EXT);
    assert_eq!(
        ctx.get_parameter(CLIP_DEPTH_MODE_EXT),
        Some(Parameter::Enum(ZERO_TO_ONE_EXT))
    );
    ctx.clip_control_ext(gl::CW, NEGATIVE_ONE_TO_ONE_EXT);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    assert_eq!(
        ctx.get_parameter(CLIP_ORIGIN_EXT),
        Some(Parameter::Enum(UPPER_LEFT_EXT)),
        "a refused call changes nothing"
    );
}

#[test]
fn the_upper_left_origin_flips_the_image_and_keeps_the_facing() {
    let Some(mut ctx) = common::context(8, 8) else {
        return;
    };
    let p = setup(&mut ctx);
    // Back faces culled: the triangle is counter-clockwise, front-facing under both origins
    // (GL negates the area under UPPER_LEFT_EXT as it flips y).
    ctx.enable(gl::CULL_FACE);
    let red = [255, 0, 0, 255];
    let black = [0, 0, 0, 255];
    for (origin, top_left, bottom_left) in
        [(LOWER_LEFT_EXT, red, black), (UPPER_LEFT_EXT, black, red)]
    {
        ctx.clip_control_ext(origin, NEGATIVE_ONE_TO_ONE_EXT);
        common::clear_black(&mut ctx);
        draw(&mut ctx, p, 0.0, [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(
            common::pixel(&mut ctx, 0, 7),
            top_left,
            "origin 0x{origin:X}"
        );
        assert_eq!(
            common::pixel(&mut ctx, 0, 0),
            bottom_left,
            "origin 0x{origin:X}"
        );
        assert_eq!(common::pixel(&mut ctx, 7, 0), black);
    }
    common::assert_clean(&ctx);
}

#[test]
fn zero_to_one_keeps_z_as_depth() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    let p = setup(&mut ctx);
    ctx.enable(gl::DEPTH_TEST);
    common::clear_black(&mut ctx);
    // z = 0 is depth 0.5 under NEGATIVE_ONE_TO_ONE_EXT and 0 under ZERO_TO_ONE_EXT.
    draw(&mut ctx, p, 0.0, [1.0, 0.0, 0.0, 1.0]);
    draw(&mut ctx, p, 0.0, [0.0, 1.0, 0.0, 1.0]);
    assert_eq!(
        common::pixel(&mut ctx, 0, 3),
        [255, 0, 0, 255],
        "LESS fails at equal depth"
    );
    ctx.clip_control_ext(LOWER_LEFT_EXT, ZERO_TO_ONE_EXT);
    draw(&mut ctx, p, 0.0, [0.0, 1.0, 0.0, 1.0]);
    assert_eq!(common::pixel(&mut ctx, 0, 3), [0, 255, 0, 255]);
    // z = −0.5 is outside ZERO_TO_ONE_EXT's volume: clipped.
    draw(&mut ctx, p, -0.5, [0.0, 0.0, 1.0, 1.0]);
    assert_eq!(common::pixel(&mut ctx, 0, 3), [0, 255, 0, 255]);
    common::assert_clean(&ctx);
}

#[test]
fn transform_feedback_captures_the_position_the_shader_wrote() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    assert!(ctx.get_extension("EXT_clip_control").is_some());
    let p = ctx.create_program();
    for (ty, src) in [(gl::VERTEX_SHADER, VS), (gl::FRAGMENT_SHADER, FS)] {
        let s = ctx.create_shader(ty).expect("a shader type");
        ctx.shader_source(s, src);
        ctx.compile_shader(s);
        ctx.attach_shader(p, s);
    }
    ctx.transform_feedback_varyings(p, &["gl_Position"], gl::INTERLEAVED_ATTRIBS);
    ctx.link_program(p);
    assert!(ctx.get_program_link_status(p));
    ctx.use_program(Some(p));
    common::float_attribute(&mut ctx, 0, 2, &TRIANGLE);
    let zl = ctx.get_uniform_location(p, "z");
    ctx.uniform1f(zl, 0.25);
    ctx.clip_control_ext(UPPER_LEFT_EXT, ZERO_TO_ONE_EXT);
    let out = ctx.create_buffer();
    ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, Some(out));
    ctx.buffer_data_size(gl::TRANSFORM_FEEDBACK_BUFFER, 48, gl::STATIC_READ);
    ctx.bind_buffer_base(gl::TRANSFORM_FEEDBACK_BUFFER, 0, Some(out));
    ctx.enable(gl::RASTERIZER_DISCARD);
    ctx.begin_transform_feedback(gl::TRIANGLES);
    ctx.draw_arrays(gl::TRIANGLES, 0, 3);
    ctx.end_transform_feedback();
    let mut got = [0f32; 12];
    ctx.get_buffer_sub_data(gl::TRANSFORM_FEEDBACK_BUFFER, 0, &mut got);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_eq!(
        got,
        [-1.0, -1.0, 0.25, 1.0, 1.0, 1.0, 0.25, 1.0, -1.0, 1.0, 0.25, 1.0]
    );
}
