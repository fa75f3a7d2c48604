//! Depth: `gl_FragDepth` written into framebuffers without a depth attachment, which GL
//! ignores (wgpu refuses a pipeline whose fragment stage writes depth without a depth target,
//! so essl-gl draws with the output taken out); with a depth attachment the value is tested;
//! new depth renderbuffers hold 1.0.

use essl_gl::{gl, Context};

use crate::common::{self, pixel};

const VS: &str = "#version 300 es\nin vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }";
const FS: &str = "#version 300 es\nprecision mediump float; out vec4 o;\
    void main() { o = vec4(0.0, 1.0, 0.0, 1.0); gl_FragDepth = 0.5; }";
/// Writes depth and, only when `u_on`, colour: a `return` before the end of `main`.
const FS_EARLY_RETURN: &str = "#version 300 es\nprecision mediump float; out vec4 o;\
    uniform bool u_on;\
    void main() { gl_FragDepth = 0.25; o = vec4(0.0, 0.0, 1.0, 1.0); if (!u_on) return;\
    o = vec4(0.0, 1.0, 0.0, 1.0); }";

/// A 2 × 2 RGBA8 texture at COLOR_ATTACHMENT0 of a new framebuffer, cleared to red.
fn colour_target(ctx: &mut Context) {
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.tex_storage_2d(gl::TEXTURE_2D, 1, gl::RGBA8, 2, 2);
    common::colour_framebuffer(ctx, t);
    ctx.clear_color(1.0, 0.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
}

fn draw(ctx: &mut Context, fs: &str) {
    let p = common::program(ctx, VS, fs);
    ctx.use_program(Some(p));
    let on = ctx.get_uniform_location(p, "u_on");
    ctx.uniform1i(on, 1);
    common::float_attribute(ctx, 0, 2, &common::QUAD);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
}

#[test]
fn a_depth_write_without_a_depth_attachment_is_ignored() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    for fs in [FS, FS_EARLY_RETURN] {
        colour_target(&mut ctx);
        ctx.enable(gl::DEPTH_TEST);
        draw(&mut ctx, fs);
        assert_eq!(pixel(&mut ctx, 1, 1), [0, 255, 0, 255], "{fs}");
        ctx.disable(gl::DEPTH_TEST);
    }
    common::assert_clean(&ctx);
}

#[test]
fn a_depth_write_with_a_depth_attachment_is_tested() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    colour_target(&mut ctx);
    let rb = ctx.create_renderbuffer();
    ctx.bind_renderbuffer(gl::RENDERBUFFER, Some(rb));
    ctx.renderbuffer_storage(gl::RENDERBUFFER, gl::DEPTH_COMPONENT16, 2, 2);
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::DEPTH_ATTACHMENT,
        gl::RENDERBUFFER,
        Some(rb),
    );
    ctx.enable(gl::DEPTH_TEST);
    // The quad is at depth 0.5 (z = 0) as rasterized, but writes 0.5 itself: a clear depth of
    // 0.4 keeps it out, 0.6 lets it in.
    for (clear, expected) in [(0.4, [255, 0, 0, 255]), (0.6, [0, 255, 0, 255])] {
        ctx.clear_color(1.0, 0.0, 0.0, 1.0);
        ctx.clear_depth(clear);
        ctx.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
        draw(&mut ctx, FS);
        assert_eq!(pixel(&mut ctx, 1, 1), expected, "clear depth {clear}");
    }
    common::assert_clean(&ctx);
}

#[test]
fn new_depth_renderbuffers_hold_one() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    for (format, samples) in [
        (gl::DEPTH_COMPONENT16, 0),
        (gl::DEPTH24_STENCIL8, 0),
        (gl::DEPTH_COMPONENT24, 4),
    ] {
        common::renderbuffer_framebuffer(&mut ctx, gl::RGBA8, samples, 2, 2);
        let depth = ctx.create_renderbuffer();
        ctx.bind_renderbuffer(gl::RENDERBUFFER, Some(depth));
        ctx.renderbuffer_storage_multisample(gl::RENDERBUFFER, samples, format, 2, 2);
        let point = if format == gl::DEPTH24_STENCIL8 {
            gl::DEPTH_STENCIL_ATTACHMENT
        } else {
            gl::DEPTH_ATTACHMENT
        };
        ctx.framebuffer_renderbuffer(gl::FRAMEBUFFER, point, gl::RENDERBUFFER, Some(depth));
        ctx.enable(gl::DEPTH_TEST);
        ctx.depth_func(gl::LESS);
        // No clear: the quad at depth 0.5 passes against 1.0.
        draw(&mut ctx, FS_GREEN);
        ctx.disable(gl::DEPTH_TEST);
        ctx.bind_framebuffer(gl::DRAW_FRAMEBUFFER, None);
        ctx.blit_framebuffer(0, 0, 2, 2, 0, 0, 2, 2, gl::COLOR_BUFFER_BIT, gl::NEAREST);
        ctx.bind_framebuffer(gl::FRAMEBUFFER, None);
        assert_eq!(
            pixel(&mut ctx, 1, 1),
            [0, 255, 0, 255],
            "0x{format:04X}, {samples} samples"
        );
    }
    // WebGL 1's unsized DEPTH_STENCIL takes no samples.
    ctx.renderbuffer_storage_multisample(gl::RENDERBUFFER, 0, gl::DEPTH_STENCIL, 1, 1);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.renderbuffer_storage_multisample(gl::RENDERBUFFER, 2, gl::DEPTH_STENCIL, 1, 1);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    common::assert_clean(&ctx);
}

const FS_GREEN: &str = "#version 300 es\nprecision mediump float; out vec4 o;\
    void main() { o = vec4(0.0, 1.0, 0.0, 1.0); }";
