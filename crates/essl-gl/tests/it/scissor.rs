//! The scissor box bounds multisampled draws exactly: no sample of a pixel outside it is
//! written, in a multisampled framebuffer object and in an antialiased drawing buffer (a
//! rasterizer that covers samples left of and below the box — Mesa 22's lavapipe — would
//! leave half-covered pixels there), and a draw without the scissor test still covers all.

use essl_gl::{gl, Context, ContextAttributes};

use crate::common::{self, pixel};

const VS: &str = "#version 300 es\nin vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }";
const FS: &str = "#version 300 es\nprecision mediump float; out vec4 o;\
    void main() { o = vec4(0.0, 1.0, 0.0, 1.0); }";
/// A fragment shader that reads `gl_FragCoord` (the position argument the test shares).
const FS_FRAG_COORD: &str = "#version 300 es\nprecision mediump float; out vec4 o;\
    void main() { o = vec4(0.0, gl_FragCoord.x > 0.0 ? 1.0 : 0.5, 0.0, 1.0); }";

/// Clears to transparent black and draws a green full-screen quad, with the scissor box at
/// (1, 1) of size 2 × 2 when `scissor`.
fn scissored_quad(ctx: &mut Context, fs: &str, scissor: bool) {
    let p = common::program(ctx, VS, fs);
    ctx.use_program(Some(p));
    common::float_attribute(ctx, 0, 2, &common::QUAD);
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    if scissor {
        ctx.enable(gl::SCISSOR_TEST);
    }
    ctx.scissor(1, 1, 2, 2);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    ctx.disable(gl::SCISSOR_TEST);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
}

/// The green channel of each pixel of the 4 × 4 default framebuffer, bottom row first.
fn green(ctx: &mut Context) -> Vec<Vec<u8>> {
    (0..4)
        .map(|y| (0..4).map(|x| pixel(ctx, x, y)[1]).collect())
        .collect()
}

const BOX: [[u8; 4]; 4] = [
    [0, 0, 0, 0],
    [0, 255, 255, 0],
    [0, 255, 255, 0],
    [0, 0, 0, 0],
];

#[test]
fn a_multisampled_framebuffer_object_keeps_draws_inside_the_box() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    for fs in [FS, FS_FRAG_COORD] {
        common::renderbuffer_framebuffer(&mut ctx, gl::RGBA8, 4, 4, 4);
        scissored_quad(&mut ctx, fs, true);
        ctx.bind_framebuffer(gl::DRAW_FRAMEBUFFER, None);
        ctx.blit_framebuffer(0, 0, 4, 4, 0, 0, 4, 4, gl::COLOR_BUFFER_BIT, gl::NEAREST);
        ctx.bind_framebuffer(gl::FRAMEBUFFER, None);
        assert_eq!(green(&mut ctx), BOX.map(|r| r.to_vec()).to_vec(), "{fs}");
    }
    common::assert_clean(&ctx);
}

#[test]
fn an_antialiased_drawing_buffer_keeps_draws_inside_the_box() {
    let attributes = ContextAttributes {
        antialias: true,
        ..ContextAttributes::default()
    };
    let Some(mut ctx) = common::context_with(4, 4, attributes) else {
        return;
    };
    scissored_quad(&mut ctx, FS, true);
    assert_eq!(green(&mut ctx), BOX.map(|r| r.to_vec()).to_vec());
    // Without the scissor test the same program covers every pixel.
    scissored_quad(&mut ctx, FS, false);
    assert!(green(&mut ctx).iter().flatten().all(|&g| g == 255));
    common::assert_clean(&ctx);
}
