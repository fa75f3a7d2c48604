//! Queries of objects as Chromium answers them: a shader deleted while attached and a program
//! deleted while in use are still shaders and programs; an attachment point with nothing
//! attached answers `OBJECT_TYPE` (and in WebGL 2 `OBJECT_NAME`), and errors otherwise —
//! `INVALID_ENUM` in WebGL 1, `INVALID_OPERATION` in WebGL 2 — and WebGL 1 has no default
//! framebuffer to query.

use essl_gl::{gl, Parameter};

use crate::common;

const VS: &str = "#version 300 es\nin vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }";
const FS: &str =
    "#version 300 es\nprecision mediump float; out vec4 o; void main() { o = vec4(1.0); }";

#[test]
fn deleted_objects_still_in_use_are_still_objects() {
    let Some(mut ctx) = common::context(1, 1) else {
        return;
    };
    let p = common::program(&mut ctx, VS, FS);
    ctx.use_program(Some(p));
    let shaders = ctx.get_attached_shaders(p);
    ctx.delete_shader(shaders[0]);
    assert!(ctx.is_shader(shaders[0]), "attached");
    ctx.detach_shader(p, shaders[0]);
    assert!(!ctx.is_shader(shaders[0]), "detached, so freed");
    ctx.delete_program(p);
    assert!(ctx.is_program(p), "in use");
    ctx.use_program(None);
    assert!(!ctx.is_program(p));
}

#[test]
fn empty_attachment_points_answer_as_chromium_does() {
    for webgl1 in [false, true] {
        let Some(mut ctx) = common::context(1, 1) else {
            return;
        };
        if webgl1 {
            ctx.set_webgl1();
        }
        let q = |ctx: &mut essl_gl::Context, pname| {
            let v = ctx.get_framebuffer_attachment_parameter(
                gl::FRAMEBUFFER,
                gl::COLOR_ATTACHMENT0,
                pname,
            );
            (v, ctx.get_error())
        };
        // The default framebuffer: WebGL 1 has none to query.
        let v = ctx.get_framebuffer_attachment_parameter(
            gl::FRAMEBUFFER,
            gl::BACK,
            gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
        );
        let e = ctx.get_error();
        if webgl1 {
            assert_eq!((v, e), (None, gl::INVALID_OPERATION));
        } else {
            assert_eq!(v, Some(Parameter::Enum(gl::FRAMEBUFFER_DEFAULT)));
        }
        let fb = ctx.create_framebuffer();
        ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
        assert_eq!(
            q(&mut ctx, gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE),
            (Some(Parameter::Enum(gl::NONE)), gl::NO_ERROR)
        );
        let name = q(&mut ctx, gl::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME);
        let size = q(&mut ctx, gl::FRAMEBUFFER_ATTACHMENT_RED_SIZE);
        if webgl1 {
            assert_eq!(name, (None, gl::INVALID_ENUM));
            assert_eq!(size, (None, gl::INVALID_ENUM));
        } else {
            assert_eq!(name, (Some(Parameter::Null), gl::NO_ERROR));
            assert_eq!(size, (None, gl::INVALID_OPERATION));
            assert_eq!(
                q(&mut ctx, 0),
                (None, gl::INVALID_OPERATION),
                "whatever the name"
            );
        }
    }
}
