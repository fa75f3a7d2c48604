//! `WEBGL_stencil_texturing`: `DEPTH_STENCIL_TEXTURE_MODE_WEBGL` waits for the extension; in
//! `STENCIL_INDEX_WEBGL` mode a depth-stencil texture is an unsigned integer texture of its
//! stencil values, which only an unsigned sampler reads; a sampler of the wrong type is an
//! error whether or not the texture is complete.

use essl_gl::{gl, Context, Parameter};

use crate::common;

const MODE: u32 = 0x90EA;
const STENCIL_INDEX: u32 = 0x1901;

const VS: &str = "#version 300 es\nin vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }";
const RED: &str = "#version 300 es\nprecision mediump float; out vec4 o;\
    void main() { o = vec4(1.0, 0.0, 0.0, 1.0); }";
const READ_STENCIL: &str = "#version 300 es
precision highp float;
uniform highp usampler2D t;
out vec4 o;
void main() { o = vec4(texture(t, vec2(0.5))) / 255.0; }";
const READ_DEPTH: &str = "#version 300 es
precision highp float;
uniform highp sampler2D t;
out vec4 o;
void main() { o = texture(t, vec2(0.5)); }";

/// A 1×1 DEPTH24_STENCIL8 texture (bound on unit 0) whose stencil is 170 and depth 0.5,
/// drawn through a framebuffer with an RGBA8 colour renderbuffer, which stays bound with the
/// texture detached.
fn stencil_170(ctx: &mut Context) {
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    let rb = ctx.create_renderbuffer();
    ctx.bind_renderbuffer(gl::RENDERBUFFER, Some(rb));
    ctx.renderbuffer_storage(gl::RENDERBUFFER, gl::RGBA8, 1, 1);
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::RENDERBUFFER,
        Some(rb),
    );
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.tex_storage_2d(gl::TEXTURE_2D, 1, gl::DEPTH24_STENCIL8, 1, 1);
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::DEPTH_STENCIL_ATTACHMENT,
        gl::TEXTURE_2D,
        Some(t),
        0,
    );
    ctx.enable(gl::STENCIL_TEST);
    ctx.enable(gl::DEPTH_TEST);
    ctx.stencil_func(gl::ALWAYS, 170, 0xFF);
    ctx.stencil_op(gl::REPLACE, gl::REPLACE, gl::REPLACE);
    ctx.clear(gl::STENCIL_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    let p = common::program(ctx, VS, RED);
    ctx.use_program(Some(p));
    common::float_attribute(ctx, 0, 2, &common::QUAD);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    ctx.disable(gl::STENCIL_TEST);
    ctx.disable(gl::DEPTH_TEST);
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::DEPTH_STENCIL_ATTACHMENT,
        gl::TEXTURE_2D,
        None,
        0,
    );
    for (pname, v) in [
        (gl::TEXTURE_MIN_FILTER, gl::NEAREST),
        (gl::TEXTURE_MAG_FILTER, gl::NEAREST),
    ] {
        ctx.tex_parameteri(gl::TEXTURE_2D, pname, v as i32);
    }
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
}

/// Draws with the program of `fs`; the error and the pixel.
fn draw(ctx: &mut Context, fs: &str) -> (u32, [u8; 4]) {
    let p = common::program(ctx, VS, fs);
    ctx.use_program(Some(p));
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    let e = ctx.get_error();
    (e, common::pixel(ctx, 0, 0))
}

#[test]
fn the_mode_waits_for_the_extension() {
    let Some(mut ctx) = common::context(1, 1) else {
        return;
    };
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.tex_parameteri(gl::TEXTURE_2D, MODE, STENCIL_INDEX as i32);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    assert!(ctx.get_extension("WEBGL_stencil_texturing").is_some());
    assert_eq!(
        ctx.get_tex_parameter(gl::TEXTURE_2D, MODE),
        Some(Parameter::Enum(gl::DEPTH_COMPONENT))
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, MODE, STENCIL_INDEX as i32);
    assert_eq!(
        ctx.get_tex_parameter(gl::TEXTURE_2D, MODE),
        Some(Parameter::Enum(STENCIL_INDEX))
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, MODE, 0);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    let s = ctx.create_sampler();
    ctx.sampler_parameteri(s, MODE, gl::DEPTH_COMPONENT as i32);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_ENUM,
        "a texture parameter only"
    );
}

#[test]
fn stencil_mode_samples_the_stencil_through_an_unsigned_sampler_only() {
    let Some(mut ctx) = common::context(1, 1) else {
        return;
    };
    ctx.get_extension("WEBGL_stencil_texturing")
        .expect("offered");
    stencil_170(&mut ctx);
    ctx.tex_parameteri(gl::TEXTURE_2D, MODE, STENCIL_INDEX as i32);
    let (e, px) = draw(&mut ctx, READ_STENCIL);
    assert_eq!(e, gl::NO_ERROR);
    assert_eq!(px[0], 170);
    assert_eq!(draw(&mut ctx, READ_DEPTH).0, gl::INVALID_OPERATION);
    // Depth mode: a float sampler reads the depth (0.5 at z = 0), an unsigned one is an
    // error, complete or not.
    ctx.tex_parameteri(gl::TEXTURE_2D, MODE, gl::DEPTH_COMPONENT as i32);
    let (e, px) = draw(&mut ctx, READ_DEPTH);
    assert_eq!(e, gl::NO_ERROR);
    assert!((127..=128).contains(&px[0]), "{px:?}");
    assert_eq!(draw(&mut ctx, READ_STENCIL).0, gl::INVALID_OPERATION);
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::LINEAR as i32);
    assert_eq!(
        draw(&mut ctx, READ_STENCIL).0,
        gl::INVALID_OPERATION,
        "incomplete"
    );
    // Stencil mode with LINEAR: incomplete, read as 0.
    ctx.tex_parameteri(gl::TEXTURE_2D, MODE, STENCIL_INDEX as i32);
    let (e, px) = draw(&mut ctx, READ_STENCIL);
    assert_eq!(e, gl::NO_ERROR);
    assert_eq!(px[..3], [0, 0, 0]);
    common::assert_clean(&ctx);
}
