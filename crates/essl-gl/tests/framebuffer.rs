//! Framebuffer objects: rendering into textures and renderbuffers, reading them back,
//! sampling what was drawn, completeness, and WebGL's errors for their misuse.

mod common;

use common::*;
use essl_gl::{gl, Context, Texture};

const PASS_VS: &str = "#version 300 es
in vec4 a_position;
void main() { gl_Position = a_position; }";

const SOLID_FS: &str = "#version 300 es
precision mediump float;
uniform vec4 u_color;
out vec4 color;
void main() { color = u_color; }";

/// A texture of `w` × `h` RGBA8 texels, unfiltered, no data.
fn rgba8_texture(ctx: &mut Context, w: i32, h: i32) -> Texture {
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA8 as i32,
        w,
        h,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        None,
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    t
}

/// Draws a triangle over the lower-left half of the draw framebuffer in `rgba`.
fn lower_left_triangle(ctx: &mut Context, rgba: [f32; 4]) {
    let p = program(ctx, PASS_VS, SOLID_FS);
    ctx.use_program(Some(p));
    let color = ctx.get_uniform_location(p, "u_color");
    ctx.uniform4f(color, rgba[0], rgba[1], rgba[2], rgba[3]);
    float_attribute(ctx, 0, 2, &[-1.0, -1.0, 1.0, -1.0, -1.0, 1.0]);
    ctx.draw_arrays(gl::TRIANGLES, 0, 3);
}

#[test]
fn a_texture_drawn_into_is_read_and_sampled_the_way_gl_has_it() {
    let Some(mut ctx) = context(16, 16) else {
        return;
    };
    let t = rgba8_texture(&mut ctx, 8, 8);
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::TEXTURE_2D,
        Some(t),
        0,
    );
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE
    );
    ctx.viewport(0, 0, 8, 8);
    ctx.clear_color(0.0, 0.0, 1.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    lower_left_triangle(&mut ctx, [0.0, 1.0, 0.0, 1.0]);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    // Read from the framebuffer object: GL's row 0 is the bottom.
    assert_eq!(pixel(&mut ctx, 1, 1), [0, 255, 0, 255]);
    assert_eq!(pixel(&mut ctx, 6, 6), [0, 0, 255, 255]);

    // Sample it in the default framebuffer: texture coordinate t = 0 is the bottom row.
    ctx.bind_framebuffer(gl::FRAMEBUFFER, None);
    ctx.viewport(0, 0, 16, 16);
    let p = program(
        &mut ctx,
        "#version 300 es
        in vec2 a_position;
        out vec2 v_uv;
        void main() { v_uv = a_position * 0.5 + 0.5; gl_Position = vec4(a_position, 0.0, 1.0); }",
        "#version 300 es
        precision mediump float;
        uniform sampler2D u_tex;
        in vec2 v_uv;
        out vec4 color;
        void main() { color = texture(u_tex, v_uv); }",
    );
    ctx.use_program(Some(p));
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_eq!(
        pixel(&mut ctx, 2, 2),
        [0, 255, 0, 255],
        "lower left drawn green"
    );
    assert_eq!(
        pixel(&mut ctx, 13, 13),
        [0, 0, 255, 255],
        "upper right cleared blue"
    );
    assert_clean(&ctx);
}

#[test]
fn status_follows_webgl2s_completeness_rules() {
    let Some(mut ctx) = context(4, 4) else { return };
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT
    );
    let a = rgba8_texture(&mut ctx, 4, 4);
    let b = rgba8_texture(&mut ctx, 8, 8);
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::TEXTURE_2D,
        Some(a),
        0,
    );
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT1,
        gl::TEXTURE_2D,
        Some(b),
        0,
    );
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_INCOMPLETE_DIMENSIONS
    );
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT1,
        gl::TEXTURE_2D,
        Some(a),
        0,
    );
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_UNSUPPORTED,
        "one image at two attachment points"
    );
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT1,
        gl::TEXTURE_2D,
        None,
        0,
    );
    // A depth format at a colour attachment point.
    let d = ctx.create_renderbuffer();
    ctx.bind_renderbuffer(gl::RENDERBUFFER, Some(d));
    ctx.renderbuffer_storage(gl::RENDERBUFFER, gl::DEPTH_COMPONENT16, 4, 4);
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT2,
        gl::RENDERBUFFER,
        Some(d),
    );
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_INCOMPLETE_ATTACHMENT
    );
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT2,
        gl::RENDERBUFFER,
        None,
    );
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::DEPTH_ATTACHMENT,
        gl::RENDERBUFFER,
        Some(d),
    );
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE
    );
    // Drawing with an incomplete framebuffer is INVALID_FRAMEBUFFER_OPERATION.
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT1,
        gl::TEXTURE_2D,
        Some(b),
        0,
    );
    ctx.clear(gl::COLOR_BUFFER_BIT);
    assert_eq!(ctx.get_error(), gl::INVALID_FRAMEBUFFER_OPERATION);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_clean(&ctx);
}

#[test]
fn sampling_a_texture_that_is_drawn_into_is_a_feedback_loop() {
    let Some(mut ctx) = context(4, 4) else { return };
    let t = rgba8_texture(&mut ctx, 4, 4);
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::TEXTURE_2D,
        Some(t),
        0,
    );
    ctx.clear_color(1.0, 0.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    let p = program(
        &mut ctx,
        PASS_VS,
        "#version 300 es
        precision mediump float;
        uniform sampler2D u_tex;
        out vec4 color;
        void main() { color = texture(u_tex, vec2(0.5)) + vec4(0.0, 1.0, 0.0, 0.0); }",
    );
    ctx.use_program(Some(p));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    assert_eq!(pixel(&mut ctx, 1, 1), [255, 0, 0, 255], "nothing was drawn");
    assert_clean(&ctx);
}
