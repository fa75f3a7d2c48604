//! Extensions with one rule each: `WEBGL_debug_renderer_info` (the adapter's vendor and name)
//! and WebGL 1's `OES_fbo_render_mipmap` (a framebuffer attaches any level of a texture).

use essl_gl::{gl, Parameter};

use crate::common;

const UNMASKED_VENDOR: u32 = 0x9245;
const UNMASKED_RENDERER: u32 = 0x9246;

#[test]
fn debug_renderer_info_names_the_adapter_once_enabled() {
    let Some(mut ctx) = common::context(1, 1) else {
        return;
    };
    assert_eq!(ctx.get_parameter(UNMASKED_RENDERER), None);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    ctx.get_extension("WEBGL_debug_renderer_info")
        .expect("offered");
    let Some(Parameter::String(renderer)) = ctx.get_parameter(UNMASKED_RENDERER) else {
        panic!("a string");
    };
    let Some(Parameter::String(vendor)) = ctx.get_parameter(UNMASKED_VENDOR) else {
        panic!("a string");
    };
    assert!(!renderer.is_empty() && !vendor.is_empty());
    // RENDERER names essl-gl and the adapter; the unmasked name is the adapter's alone.
    let Some(Parameter::String(masked)) = ctx.get_parameter(gl::RENDERER) else {
        panic!("a string");
    };
    assert_eq!(masked, format!("essl-gl on {renderer}"));
}

#[test]
fn webgl1_attaches_level_0_only_until_fbo_render_mipmap() {
    let Some(mut ctx) = common::context(1, 1) else {
        return;
    };
    ctx.set_webgl1();
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    for level in 0..2 {
        let size = 2 >> level;
        ctx.tex_image_2d::<u8>(
            gl::TEXTURE_2D,
            level,
            gl::RGBA as i32,
            size,
            size,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            None,
        );
    }
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    let attach = |ctx: &mut essl_gl::Context| {
        ctx.framebuffer_texture_2d(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0,
            gl::TEXTURE_2D,
            Some(t),
            1,
        );
        ctx.get_error()
    };
    assert_eq!(attach(&mut ctx), gl::INVALID_VALUE);
    ctx.get_extension("OES_fbo_render_mipmap").expect("offered");
    assert_eq!(attach(&mut ctx), gl::NO_ERROR);
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE
    );
}
