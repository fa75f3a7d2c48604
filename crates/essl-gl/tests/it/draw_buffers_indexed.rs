//! `OES_draw_buffers_indexed`: each draw buffer blends and masks on its own; the core calls
//! set every draw buffer's state and the core queries read draw buffer 0's; indexed queries
//! wait for the extension and check their index; clears follow each buffer's mask.

use essl_gl::{gl, Context, Parameter};

use crate::common;

const VS: &str = "#version 300 es\nin vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }";
const FS: &str = "#version 300 es
precision mediump float;
layout(location = 0) out vec4 o0;
layout(location = 1) out vec4 o1;
void main() { o0 = vec4(1.0, 0.0, 0.0, 0.5); o1 = vec4(1.0, 0.0, 0.0, 0.5); }";

/// A 1×1 framebuffer with two RGBA8 colour attachments, both drawn to, and the program.
fn setup() -> Option<Context> {
    let mut ctx = common::context(1, 1)?;
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    for i in 0..2 {
        let t = ctx.create_texture();
        ctx.bind_texture(gl::TEXTURE_2D, Some(t));
        ctx.tex_storage_2d(gl::TEXTURE_2D, 1, gl::RGBA8, 1, 1);
        ctx.framebuffer_texture_2d(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0 + i,
            gl::TEXTURE_2D,
            Some(t),
            0,
        );
    }
    ctx.draw_buffers(&[gl::COLOR_ATTACHMENT0, gl::COLOR_ATTACHMENT1]);
    let p = common::program(&mut ctx, VS, FS);
    ctx.use_program(Some(p));
    common::float_attribute(&mut ctx, 0, 2, &common::QUAD);
    Some(ctx)
}

/// Attachment `i`'s pixel.
fn read(ctx: &mut Context, i: u32) -> [u8; 4] {
    ctx.read_buffer(gl::COLOR_ATTACHMENT0 + i);
    common::pixel(ctx, 0, 0)
}

#[test]
fn indexed_state_waits_for_the_extension_and_checks_its_index() {
    let Some(mut ctx) = setup() else { return };
    assert_eq!(ctx.get_indexed_parameter(gl::BLEND_EQUATION_RGB, 0), None);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    assert!(ctx.get_extension("OES_draw_buffers_indexed").is_some());
    assert_eq!(
        ctx.get_indexed_parameter(gl::COLOR_WRITEMASK, 1),
        Some(Parameter::Bools(vec![true; 4]))
    );
    assert_eq!(ctx.get_indexed_parameter(gl::BLEND_SRC_RGB, 8), None);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    ctx.color_mask_indexed(8, [true; 4]);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    ctx.set_enabled_indexed(gl::DEPTH_TEST, 0, true);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    ctx.blend_func_separate_indexed(
        0,
        [gl::CONSTANT_COLOR, gl::CONSTANT_ALPHA, gl::ONE, gl::ONE],
    );
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    // Core calls set every draw buffer; core queries read draw buffer 0.
    ctx.blend_equation_separate_indexed(1, gl::FUNC_SUBTRACT, gl::MAX);
    assert_eq!(
        ctx.get_parameter(gl::BLEND_EQUATION_RGB),
        Some(Parameter::Enum(gl::FUNC_ADD))
    );
    ctx.blend_func(gl::SRC_ALPHA, gl::ONE);
    for i in 0..8 {
        assert_eq!(
            ctx.get_indexed_parameter(gl::BLEND_DST_ALPHA, i),
            Some(Parameter::Enum(gl::ONE))
        );
    }
    assert_eq!(
        ctx.get_indexed_parameter(gl::BLEND_EQUATION_ALPHA, 1),
        Some(Parameter::Enum(gl::MAX))
    );
    ctx.set_enabled_indexed(gl::BLEND, 1, true);
    assert!(!ctx.is_enabled(gl::BLEND), "isEnabled reads draw buffer 0");
    assert!(ctx.is_enabled_indexed(gl::BLEND, 1));
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
}

#[test]
fn each_draw_buffer_blends_and_masks_on_its_own() {
    let Some(mut ctx) = setup() else { return };
    ctx.get_extension("OES_draw_buffers_indexed")
        .expect("offered");
    ctx.clear_color(0.0, 0.0, 1.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    // Buffer 0 adds, buffer 1 mixes by source alpha; buffer 1 does not write blue.
    ctx.set_enabled_indexed(gl::BLEND, 0, true);
    ctx.set_enabled_indexed(gl::BLEND, 1, true);
    ctx.blend_func_separate_indexed(0, [gl::ONE, gl::ONE, gl::ONE, gl::ONE]);
    ctx.blend_func_separate_indexed(
        1,
        [gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA, gl::ONE, gl::ZERO],
    );
    ctx.color_mask_indexed(1, [true, true, false, true]);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_eq!(read(&mut ctx, 0), [255, 0, 255, 255]);
    // Red 0.5·1 + 0.5·0, blue kept at 1 by the mask, alpha 0.5.
    let b1 = read(&mut ctx, 1);
    assert!(
        (127..=128).contains(&b1[0]) && b1[1] == 0 && b1[2] == 255,
        "{b1:?}"
    );
    assert!((127..=128).contains(&b1[3]), "{b1:?}");
    // A clear follows each buffer's mask: buffer 0 all off keeps its colour.
    ctx.color_mask_indexed(0, [false; 4]);
    ctx.color_mask_indexed(1, [true; 4]);
    ctx.clear_color(0.0, 1.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    assert_eq!(read(&mut ctx, 0), [255, 0, 255, 255]);
    assert_eq!(read(&mut ctx, 1), [0, 255, 0, 255]);
    common::assert_clean(&ctx);
}
