//! WebGL 1's float texture extensions: `OES_texture_float`, `OES_texture_half_float`
//! (`HALF_FLOAT_OES`), their `_linear` forms, `WEBGL_color_buffer_float` and
//! `EXT_color_buffer_half_float`: refused until `getExtension`, then uploaded, sampled,
//! rendered to and read back.

use crate::common;

use essl_gl::{gl, Context};

/// `OES_texture_half_float`'s `HALF_FLOAT_OES`.
const HALF_FLOAT_OES: u32 = 0x8D61;

const VS: &str = "attribute vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }";
const FS: &str = "precision mediump float; uniform sampler2D t;\
    void main() { gl_FragColor = texture2D(t, vec2(0.5)); }";

fn webgl1(w: u32, h: u32) -> Option<Context> {
    let mut ctx = common::context(w, h)?;
    ctx.set_webgl1();
    Some(ctx)
}

/// A bound 1×1 texture of `(format, ty)` from `data`, with `filter`; the error it recorded.
fn texture<T: essl_gl::ArrayElement>(
    ctx: &mut Context,
    format: u32,
    ty: u32,
    data: Option<&[T]>,
    filter: u32,
) -> u32 {
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, filter as i32);
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, filter as i32);
    ctx.tex_image_2d(gl::TEXTURE_2D, 0, format as i32, 1, 1, 0, format, ty, data);
    ctx.get_error()
}

/// Draws the bound texture's texel over the canvas; the centre pixel.
fn sample(ctx: &mut Context) -> [u8; 4] {
    common::draw_quad_pixel(ctx, VS, FS)
}

#[test]
fn float_types_need_their_extensions() {
    let Some(mut ctx) = webgl1(2, 2) else {
        return;
    };
    let ones = [1.0f32; 4];
    let halves = [0x3C00u16; 4];
    let e = texture(&mut ctx, gl::RGBA, gl::FLOAT, Some(&ones), gl::NEAREST);
    assert_eq!(e, gl::INVALID_ENUM, "FLOAT before OES_texture_float");
    let e = texture(
        &mut ctx,
        gl::RGBA,
        HALF_FLOAT_OES,
        Some(&halves),
        gl::NEAREST,
    );
    assert_eq!(
        e,
        gl::INVALID_ENUM,
        "HALF_FLOAT_OES before OES_texture_half_float"
    );
    assert!(ctx.get_extension("OES_texture_float").is_some());
    assert!(ctx.get_extension("OES_texture_half_float").is_some());
    let e = texture(&mut ctx, gl::RGBA, gl::FLOAT, Some(&ones), gl::NEAREST);
    assert_eq!(e, gl::NO_ERROR, "FLOAT with OES_texture_float");
    let e = texture(
        &mut ctx,
        gl::RGBA,
        HALF_FLOAT_OES,
        Some(&halves),
        gl::NEAREST,
    );
    assert_eq!(
        e,
        gl::NO_ERROR,
        "HALF_FLOAT_OES with OES_texture_half_float"
    );
    let e = texture(&mut ctx, gl::RGBA, HALF_FLOAT_OES, Some(&ones), gl::NEAREST);
    assert_eq!(
        e,
        gl::INVALID_OPERATION,
        "HALF_FLOAT_OES from a Float32Array"
    );
    let e = texture(
        &mut ctx,
        gl::RGBA,
        gl::HALF_FLOAT,
        Some(&halves),
        gl::NEAREST,
    );
    assert_eq!(e, gl::INVALID_ENUM, "WebGL 2's HALF_FLOAT");
    let none: Option<&[u16]> = None;
    let e = texture(&mut ctx, gl::LUMINANCE, HALF_FLOAT_OES, none, gl::NEAREST);
    assert_eq!(e, gl::NO_ERROR, "LUMINANCE HALF_FLOAT_OES from null");
}

#[test]
fn luminance_in_floats_samples_spread_over_rgb() {
    let Some(mut ctx) = webgl1(2, 2) else {
        return;
    };
    ctx.get_extension("OES_texture_float");
    let e = texture(
        &mut ctx,
        gl::LUMINANCE,
        gl::FLOAT,
        Some(&[0.5f32]),
        gl::NEAREST,
    );
    assert_eq!(e, gl::NO_ERROR);
    let p = sample(&mut ctx);
    assert!(
        p[..3].iter().all(|&c| c.abs_diff(128) <= 1) && p[3] == 255,
        "{p:?}"
    );
}

#[test]
fn half_floats_filter_linearly_only_with_the_linear_extension() {
    let Some(mut ctx) = webgl1(2, 2) else {
        return;
    };
    ctx.get_extension("OES_texture_half_float");
    let half = [0x3800u16; 4]; // 0.5
    let e = texture(&mut ctx, gl::RGBA, HALF_FLOAT_OES, Some(&half), gl::LINEAR);
    assert_eq!(e, gl::NO_ERROR);
    assert_eq!(
        sample(&mut ctx),
        [0, 0, 0, 255],
        "incomplete: sampled as black"
    );
    assert!(ctx.get_extension("OES_texture_half_float_linear").is_some());
    let p = sample(&mut ctx);
    assert!(p.iter().all(|&c| c.abs_diff(128) <= 1), "{p:?}");
}

#[test]
fn float_textures_and_renderbuffers_render_with_color_buffer_float() {
    let Some(mut ctx) = webgl1(2, 2) else {
        return;
    };
    let rb = ctx.create_renderbuffer();
    ctx.bind_renderbuffer(gl::RENDERBUFFER, Some(rb));
    ctx.renderbuffer_storage(gl::RENDERBUFFER, gl::RGBA32F, 2, 2);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_ENUM,
        "RGBA32F before the extension"
    );
    assert!(ctx.get_extension("WEBGL_color_buffer_float").is_some());
    ctx.renderbuffer_storage(gl::RENDERBUFFER, gl::RGBA32F, 2, 2);
    assert_eq!(
        ctx.get_error(),
        gl::NO_ERROR,
        "RGBA32F with WEBGL_color_buffer_float"
    );
    ctx.renderbuffer_storage(gl::RENDERBUFFER, gl::RGBA16F, 2, 2);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_ENUM,
        "RGBA16F is the half-float one's"
    );
    ctx.get_extension("OES_texture_float");
    let none: Option<&[f32]> = None;
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::FLOAT,
        none,
    );
    common::colour_framebuffer(&mut ctx, t);
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE
    );
    ctx.clear_color(1000.0, -2.0, 0.25, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    let mut out = [0f32; 4];
    ctx.read_pixels(0, 0, 1, 1, gl::RGBA, gl::FLOAT, &mut out);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_eq!(out, [1000.0, -2.0, 0.25, 1.0]);
    let p = common::program(&mut ctx, VS, "void main() { gl_FragColor = vec4(1.0); }");
    ctx.use_program(Some(p));
    common::float_attribute(&mut ctx, 0, 2, &common::QUAD);
    ctx.enable(gl::BLEND);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    // EXT_float_blend is offered where the adapter blends 32-bit floats, and blending is
    // then allowed whether or not it was turned on (as in Chromium).
    let want = if ctx.get_supported_extensions().contains(&"EXT_float_blend") {
        gl::NO_ERROR
    } else {
        gl::INVALID_OPERATION
    };
    assert_eq!(ctx.get_error(), want, "blending into RGBA32F");
}

#[test]
fn an_rgb_half_float_attachment_reads_back_alpha_1() {
    let Some(mut ctx) = webgl1(2, 2) else {
        return;
    };
    ctx.get_extension("OES_texture_half_float");
    let none: Option<&[u16]> = None;
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGB as i32,
        2,
        2,
        0,
        gl::RGB,
        HALF_FLOAT_OES,
        none,
    );
    common::colour_framebuffer(&mut ctx, t);
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE,
        "RGB in half floats renders with EXT_color_buffer_half_float"
    );
    ctx.clear_color(1000.0, 2.0, 0.5, 1000.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    let mut out = [0f32; 4];
    ctx.read_pixels(0, 0, 1, 1, gl::RGBA, gl::FLOAT, &mut out);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_eq!(out, [1000.0, 2.0, 0.5, 1.0]);
    let mut halves = [0u16; 3];
    ctx.read_pixels(0, 0, 1, 1, gl::RGB, HALF_FLOAT_OES, &mut halves);
    assert_eq!(
        ctx.get_error(),
        gl::NO_ERROR,
        "RGB, HALF_FLOAT_OES: the native pair"
    );
    assert_eq!(halves, [0x63D0, 0x4000, 0x3800]);
    assert_eq!(
        ctx.get_parameter(gl::IMPLEMENTATION_COLOR_READ_TYPE),
        Some(essl_gl::Parameter::Enum(HALF_FLOAT_OES))
    );
}

#[test]
fn webgl1_depth_textures_with_their_extension() {
    let Some(mut ctx) = webgl1(4, 4) else {
        return;
    };
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    let depth = |ctx: &mut Context, level: i32, data: Option<&[u16]>| {
        let (f, ty) = (gl::DEPTH_COMPONENT, gl::UNSIGNED_SHORT);
        ctx.tex_image_2d(gl::TEXTURE_2D, level, f as i32, 4, 4, 0, f, ty, data);
        ctx.get_error()
    };
    assert_eq!(
        depth(&mut ctx, 0, None),
        gl::INVALID_ENUM,
        "before WEBGL_depth_texture"
    );
    assert!(ctx.get_extension("WEBGL_depth_texture").is_some());
    assert_eq!(
        depth(&mut ctx, 0, Some(&[0; 16])),
        gl::INVALID_OPERATION,
        "data"
    );
    assert_eq!(depth(&mut ctx, 1, None), gl::INVALID_OPERATION, "level 1");
    assert_eq!(depth(&mut ctx, 0, None), gl::NO_ERROR);
    for filter in [gl::TEXTURE_MIN_FILTER, gl::TEXTURE_MAG_FILTER] {
        ctx.tex_parameteri(gl::TEXTURE_2D, filter, gl::LINEAR as i32);
    }
    // Rendered into as a depth attachment, then sampled: the cleared depth in red.
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    let colour = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(colour));
    ctx.tex_image_2d::<u8>(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        4,
        4,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        None,
    );
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::TEXTURE_2D,
        Some(colour),
        0,
    );
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::DEPTH_ATTACHMENT,
        gl::TEXTURE_2D,
        Some(t),
        0,
    );
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE
    );
    ctx.clear_depth(0.5);
    ctx.clear(gl::DEPTH_BUFFER_BIT);
    ctx.bind_framebuffer(gl::FRAMEBUFFER, None);
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    let [r, _, _, a] = sample(&mut ctx);
    assert!((126..=129).contains(&r) && a == 255, "{r} {a}");
    // A depth-and-stencil texture belongs at DEPTH_STENCIL_ATTACHMENT, not DEPTH_ATTACHMENT.
    let ds = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(ds));
    let f = gl::DEPTH_STENCIL;
    ctx.tex_image_2d::<u32>(
        gl::TEXTURE_2D,
        0,
        f as i32,
        4,
        4,
        0,
        f,
        gl::UNSIGNED_INT_24_8,
        None,
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::DEPTH_ATTACHMENT,
        gl::TEXTURE_2D,
        Some(ds),
        0,
    );
    assert_ne!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE
    );
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::DEPTH_ATTACHMENT,
        gl::TEXTURE_2D,
        None,
        0,
    );
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::DEPTH_STENCIL_ATTACHMENT,
        gl::TEXTURE_2D,
        Some(ds),
        0,
    );
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE
    );
}

#[test]
fn webgl1_srgb_textures_with_ext_srgb() {
    let Some(mut ctx) = webgl1(4, 4) else {
        return;
    };
    const SRGB_ALPHA_EXT: u32 = 0x8C42;
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    let upload = |ctx: &mut Context| {
        let f = SRGB_ALPHA_EXT;
        let texel = [188u8, 188, 188, 255];
        ctx.tex_image_2d(
            gl::TEXTURE_2D,
            0,
            f as i32,
            1,
            1,
            0,
            f,
            gl::UNSIGNED_BYTE,
            Some(&texel[..]),
        );
        ctx.get_error()
    };
    assert_eq!(upload(&mut ctx), gl::INVALID_ENUM, "before EXT_sRGB");
    assert!(ctx.get_extension("EXT_sRGB").is_some());
    assert_eq!(upload(&mut ctx), gl::NO_ERROR);
    // sRGB 188 is linear 0.50: sampled, it is written as 128.
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    let [r, g, b, a] = sample(&mut ctx);
    assert!(
        (126..=130).contains(&r) && r == g && g == b && a == 255,
        "{r} {g} {b} {a}"
    );
    ctx.generate_mipmap(gl::TEXTURE_2D);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "no sRGB mipmaps in WebGL 1"
    );
}
