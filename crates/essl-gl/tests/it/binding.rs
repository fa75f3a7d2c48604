//! What a JavaScript binding relies on: typed arrays of any kind (`*_view`), uploads from DOM
//! image sources, the drawing buffer read as an image, a canvas's resize, errors a binding
//! records, and a WebGL 1 context's enums, rules and extensions.

use crate::common;

use essl_gl::{gl, ArrayType, ArrayView, ArrayViewMut, ImageSource, SourceUpload};

const RED: [u8; 4] = [255, 0, 0, 255];
const GREEN: [u8; 4] = [0, 255, 0, 255];
const BLUE: [u8; 4] = [0, 0, 255, 255];
const WHITE: [u8; 4] = [255; 4];

/// A 2×2 image, top row red then green, bottom row blue then white.
fn image() -> Vec<u8> {
    [RED, GREEN, BLUE, WHITE].concat()
}

/// Reads the 2×2 RGBA8 level 0 of `texture` through a framebuffer.
fn texels(ctx: &mut essl_gl::Context, texture: essl_gl::Texture) -> Vec<u8> {
    common::colour_framebuffer(ctx, texture);
    let mut px = vec![0u8; 16];
    ctx.read_pixels(0, 0, 2, 2, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    ctx.bind_framebuffer(gl::FRAMEBUFFER, None);
    px
}

fn upload(flip: bool, premultiply: bool, rgba: &[u8]) -> Option<Vec<u8>> {
    upload_source(flip, premultiply, rgba, false)
}

/// [`upload`] of an image or (`bitmap`) an ImageBitmap.
fn upload_source(flip: bool, premultiply: bool, rgba: &[u8], bitmap: bool) -> Option<Vec<u8>> {
    let mut ctx = common::context(4, 4)?;
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.pixel_storei(gl::UNPACK_FLIP_Y_WEBGL, i32::from(flip));
    ctx.pixel_storei(gl::UNPACK_PREMULTIPLY_ALPHA_WEBGL, i32::from(premultiply));
    let u = SourceUpload {
        sub: false,
        three_d: false,
        target: gl::TEXTURE_2D,
        level: 0,
        internalformat: gl::RGBA as i32,
        offset: [0; 3],
        size: [2, 2, 1],
        border: 0,
        format: gl::RGBA,
        ty: gl::UNSIGNED_BYTE,
    };
    ctx.tex_image_source(
        u,
        ImageSource {
            width: 2,
            height: 2,
            rgba,
            bitmap,
        },
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    Some(texels(&mut ctx, t))
}

#[test]
fn an_image_source_goes_to_row_0_first_and_flips_and_premultiplies_as_asked() {
    let Some(plain) = upload(false, false, &image()) else {
        return;
    };
    assert_eq!(
        plain,
        image(),
        "the source's first row is the texture's row 0"
    );
    let flipped = upload(true, false, &image()).unwrap();
    assert_eq!(flipped, [BLUE, WHITE, RED, GREEN].concat());
    let half = [[200, 100, 50, 128]; 4].concat();
    let pre = upload(false, true, &half).unwrap();
    assert_eq!(&pre[..4], &[100, 50, 25, 128]);
}

#[test]
fn an_image_bitmap_is_uploaded_as_it_is_whatever_the_pixel_store_says() {
    let half = [[200, 100, 50, 128]; 4].concat();
    let Some(bitmap) = upload_source(true, true, &half, true) else {
        return;
    };
    assert_eq!(bitmap, half);
    assert_eq!(upload_source(true, false, &image(), true).unwrap(), image());
}

#[test]
fn a_flipped_image_source_gives_the_rectangle_of_the_flipped_source() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    // 1×1 rectangles at (1, 0) and (0, 1) of the 2×2 image, flipped: taken from the image
    // turned upside down, as Chromium takes them.
    let mut got = Vec::new();
    for (skip_x, skip_y) in [(1, 0), (0, 1)] {
        let t = ctx.create_texture();
        ctx.bind_texture(gl::TEXTURE_2D, Some(t));
        ctx.pixel_storei(gl::UNPACK_FLIP_Y_WEBGL, 1);
        ctx.pixel_storei(gl::UNPACK_SKIP_PIXELS, skip_x);
        ctx.pixel_storei(gl::UNPACK_SKIP_ROWS, skip_y);
        let u = SourceUpload {
            sub: false,
            three_d: false,
            target: gl::TEXTURE_2D,
            level: 0,
            internalformat: gl::RGBA as i32,
            offset: [0; 3],
            size: [1, 1, 1],
            border: 0,
            format: gl::RGBA,
            ty: gl::UNSIGNED_BYTE,
        };
        let rgba = image();
        ctx.tex_image_source(
            u,
            ImageSource {
                width: 2,
                height: 2,
                rgba: &rgba,
                bitmap: false,
            },
        );
        assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
        got.push(texels(&mut ctx, t)[..4].to_vec());
    }
    assert_eq!(got, [WHITE.to_vec(), RED.to_vec()]);
}

#[test]
fn an_image_source_converts_to_float_and_packed_types() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    let mut u = SourceUpload {
        sub: false,
        three_d: false,
        target: gl::TEXTURE_2D,
        level: 0,
        internalformat: gl::RGBA32F as i32,
        offset: [0; 3],
        size: [2, 2, 1],
        border: 0,
        format: gl::RGBA,
        ty: gl::FLOAT,
    };
    let rgba = image();
    ctx.tex_image_source(
        u,
        ImageSource {
            width: 2,
            height: 2,
            rgba: &rgba,
            bitmap: false,
        },
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    u.internalformat = gl::RGB565 as i32;
    u.format = gl::RGB;
    u.ty = gl::UNSIGNED_SHORT_5_6_5;
    ctx.tex_image_source(
        u,
        ImageSource {
            width: 2,
            height: 2,
            rgba: &rgba,
            bitmap: false,
        },
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    // A source too short for its size reaches the usual checks with no data.
    ctx.tex_image_source(
        u,
        ImageSource {
            width: 2,
            height: 2,
            rgba: &rgba[..8],
            bitmap: false,
        },
    );
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
}

#[test]
fn views_are_checked_against_the_pixel_type() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    let clamped = ArrayView {
        array: ArrayType::Uint8Clamped,
        bytes: &image(),
    };
    ctx.tex_image_2d_view(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(clamped),
    );
    assert_eq!(
        ctx.get_error(),
        gl::NO_ERROR,
        "a Uint8ClampedArray goes where a Uint8Array does"
    );
    let f64s = ArrayView {
        array: ArrayType::Other,
        bytes: &[0; 32],
    };
    ctx.tex_image_2d_view(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(f64s),
    );
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    let mut out = [0u8; 16];
    let dst = ArrayViewMut {
        array: ArrayType::Other,
        bytes: &mut out,
    };
    ctx.read_pixels_view(0, 0, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, dst);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
}

#[test]
fn the_drawing_buffer_reads_top_row_first_whatever_is_bound_and_resizes() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    ctx.enable(gl::SCISSOR_TEST);
    ctx.scissor(0, 1, 2, 1);
    ctx.clear_color(1.0, 0.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.disable(gl::SCISSOR_TEST);
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    let px = ctx.read_drawing_buffer();
    assert_eq!(&px[..4], &RED, "GL's top row is the image's first");
    assert_eq!(&px[8..12], &[0, 0, 0, 0]);
    ctx.resize_drawing_buffer(5, 3);
    assert_eq!(
        (ctx.drawing_buffer_width(), ctx.drawing_buffer_height()),
        (5, 3)
    );
    assert_eq!(ctx.read_drawing_buffer().len(), 5 * 3 * 4);
    ctx.resize_drawing_buffer(0, 3);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    ctx.synthesize_error(gl::INVALID_VALUE, "bufferData", "no data");
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    assert!(
        ctx.backend_errors().is_empty(),
        "{:?}",
        ctx.backend_errors()
    );
}

#[test]
fn names_outside_glsl_characters_or_too_long_are_invalid_value() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    let p = ctx.create_program();
    ctx.bind_attrib_location(p, 0, "a$b");
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    assert_eq!(ctx.get_attrib_location(p, &"a".repeat(1025)), -1);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    assert!(ctx.get_uniform_location(p, "u\\v").is_none());
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
}

#[test]
fn a_webgl1_context_refuses_webgl2_enums_until_an_extension_brings_them() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    ctx.set_webgl1();
    assert!(ctx.is_webgl1());
    let version = ctx.get_parameter(gl::VERSION).unwrap();
    assert!(version.as_str().unwrap().starts_with("WebGL 1.0"));
    for (what, call) in [
        (
            "bindTexture TEXTURE_3D",
            Box::new(|c: &mut essl_gl::Context| c.bind_texture(gl::TEXTURE_3D, None))
                as Box<dyn Fn(&mut essl_gl::Context)>,
        ),
        (
            "enable RASTERIZER_DISCARD",
            Box::new(|c| c.enable(gl::RASTERIZER_DISCARD)),
        ),
        (
            "pixelStorei UNPACK_ROW_LENGTH",
            Box::new(|c| c.pixel_storei(gl::UNPACK_ROW_LENGTH, 0)),
        ),
        ("blendEquation MIN", Box::new(|c| c.blend_equation(gl::MIN))),
        (
            "getParameter VERTEX_ARRAY_BINDING",
            Box::new(|c| drop(c.get_parameter(gl::VERTEX_ARRAY_BINDING))),
        ),
        (
            "vertexAttribPointer INT",
            Box::new(|c| c.vertex_attrib_pointer(0, 1, gl::INT, false, 0, 0)),
        ),
    ] {
        call(&mut ctx);
        assert_eq!(ctx.get_error(), gl::INVALID_ENUM, "{what}");
    }
    assert!(
        ctx.get_extension("EXT_color_buffer_float").is_none(),
        "a WebGL 2 extension"
    );
    assert!(ctx.get_extension("EXT_blend_minmax").is_some());
    ctx.blend_equation(gl::MIN);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert!(ctx.get_extension("OES_vertex_array_object").is_some());
    assert!(ctx.get_parameter(gl::VERTEX_ARRAY_BINDING).is_some());
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA8 as i32,
        1,
        1,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        None::<&[u8]>,
    );
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "the internal format must be the format"
    );
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        3,
        3,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        None::<&[u8]>,
    );
    ctx.generate_mipmap(gl::TEXTURE_2D);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "no mipmaps of a non-power-of-two image"
    );
}

#[test]
fn a_webgl1_mipmap_level_past_0_needs_power_of_two_sides() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    ctx.set_webgl1();
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    let none: Option<&[u8]> = None;
    for (level, w, h, want) in [
        (0, 3, 5, gl::NO_ERROR),
        (1, 3, 4, gl::INVALID_VALUE),
        (1, 2, 4, gl::NO_ERROR),
        (2, 1, 0, gl::NO_ERROR),
    ] {
        ctx.tex_image_2d(
            gl::TEXTURE_2D,
            level,
            gl::RGBA as i32,
            w,
            h,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            none,
        );
        assert_eq!(ctx.get_error(), want, "texImage2D level {level}, {w}x{h}");
    }
    ctx.copy_tex_image_2d(gl::TEXTURE_2D, 1, gl::RGBA, 0, 0, 3, 3, 0);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_VALUE,
        "copyTexImage2D level 1, 3x3"
    );
}

#[test]
fn a_current_program_whose_relink_failed_draws_nothing_and_takes_no_uniforms() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    let p = common::program(
        &mut ctx,
        "#version 300 es\nvoid main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }",
        "#version 300 es\nprecision mediump float; uniform vec4 u; out vec4 o; void main() { o = u; }",
    );
    ctx.use_program(Some(p));
    let u = ctx.get_uniform_location(p, "u");
    ctx.uniform4fv(u, &[1.0, 0.0, 0.0, 1.0]);
    ctx.draw_arrays(gl::POINTS, 0, 1);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    // A relink without a fragment shader fails: WebGL keeps no executable from before.
    let fs = ctx.get_attached_shaders(p)[1];
    ctx.detach_shader(p, fs);
    ctx.link_program(p);
    assert!(!ctx.get_program_link_status(p));
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.uniform4fv(u, &[0.0, 1.0, 0.0, 1.0]);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "uniform4fv");
    ctx.draw_arrays(gl::POINTS, 0, 1);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "drawArrays");
}

#[test]
fn skipped_pixels_past_the_row_are_invalid_a_row_length_of_0_being_the_width() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    let data = [0u8; 4 * 5 * 20];
    let upload = |ctx: &mut essl_gl::Context, row: i32, skip: i32| {
        ctx.pixel_storei(gl::UNPACK_ROW_LENGTH, row);
        ctx.pixel_storei(gl::UNPACK_SKIP_PIXELS, skip);
        let f = gl::RGBA;
        ctx.tex_image_2d(
            gl::TEXTURE_2D,
            0,
            gl::RGBA8 as i32,
            5,
            7,
            0,
            f,
            gl::UNSIGNED_BYTE,
            Some(&data[..]),
        );
        ctx.get_error()
    };
    assert_eq!(upload(&mut ctx, 0, 2), gl::INVALID_OPERATION, "5 + 2 > 5");
    assert_eq!(upload(&mut ctx, 6, 2), gl::INVALID_OPERATION, "5 + 2 > 6");
    assert_eq!(upload(&mut ctx, 7, 2), gl::NO_ERROR);
    assert_eq!(upload(&mut ctx, 0, 0), gl::NO_ERROR);
    // The same for reads: PACK_SKIP_PIXELS + width within PACK_ROW_LENGTH (or the width).
    let mut px = [0u8; 4 * 8 * 2];
    let mut read = |ctx: &mut essl_gl::Context, row: i32, skip: i32| {
        ctx.pixel_storei(gl::PACK_ROW_LENGTH, row);
        ctx.pixel_storei(gl::PACK_SKIP_PIXELS, skip);
        ctx.read_pixels(0, 0, 2, 2, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
        ctx.get_error()
    };
    assert_eq!(read(&mut ctx, 0, 1), gl::INVALID_OPERATION, "2 + 1 > 2");
    assert_eq!(read(&mut ctx, 1, 0), gl::INVALID_OPERATION, "2 + 0 > 1");
    assert_eq!(read(&mut ctx, 3, 1), gl::NO_ERROR);
    assert_eq!(read(&mut ctx, 0, 0), gl::NO_ERROR);
}

#[test]
fn the_drawing_buffer_reads_unpremultiplied_unless_the_context_is_not_premultiplied() {
    for premultiplied_alpha in [true, false] {
        let attributes = essl_gl::ContextAttributes {
            premultiplied_alpha,
            ..Default::default()
        };
        let Some(mut ctx) = common::context_with(1, 1, attributes) else {
            return;
        };
        // Stored as (64, 128, 128, 128) and (0, 0, 0, 0).
        ctx.clear_color(0.25, 0.5, 0.5, 0.5);
        ctx.clear(gl::COLOR_BUFFER_BIT);
        let want = if premultiplied_alpha {
            [128, 255, 255, 128]
        } else {
            [64, 128, 128, 128]
        };
        assert_eq!(ctx.read_drawing_buffer(), want, "{premultiplied_alpha}");
        ctx.clear_color(0.5, 0.5, 0.5, 0.0);
        ctx.clear(gl::COLOR_BUFFER_BIT);
        let want = if premultiplied_alpha {
            [0, 0, 0, 0]
        } else {
            [128, 128, 128, 0]
        };
        assert_eq!(ctx.read_drawing_buffer(), want, "{premultiplied_alpha}");
    }
}

#[test]
fn a_scissored_clear_of_a_multisampled_drawing_buffer_stays_in_its_box() {
    let attributes = essl_gl::ContextAttributes {
        antialias: true,
        ..Default::default()
    };
    let Some(mut ctx) = common::context_with(4, 4, attributes) else {
        return;
    };
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.enable(gl::SCISSOR_TEST);
    ctx.scissor(1, 1, 1, 1);
    ctx.clear_color(0.0, 1.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    let px = ctx.read_pixels_rgba8(0, 0, 4, 4);
    for (i, p) in px.chunks_exact(4).enumerate() {
        let want = if i == 5 { [0, 255, 0, 255] } else { [0; 4] };
        assert_eq!(p, want, "pixel ({}, {})", i % 4, i / 4);
    }
}

#[test]
fn rgb5_a1_takes_10_bit_colour_rounded_to_its_5_bits() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    // (1023, 512, 0, alpha 3) and (33, 0, 1023, alpha 1), as UNSIGNED_INT_2_10_10_10_REV.
    let texels: [u32; 2] = [
        1023 | (512 << 10) | (3 << 30),
        33 | (1023 << 20) | (1 << 30),
    ];
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGB5_A1 as i32,
        2,
        1,
        0,
        gl::RGBA,
        gl::UNSIGNED_INT_2_10_10_10_REV,
        Some(&texels[..]),
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    // The unsized RGBA format does not take the type.
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        1,
        0,
        gl::RGBA,
        gl::UNSIGNED_INT_2_10_10_10_REV,
        Some(&texels[..]),
    );
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    common::colour_framebuffer(&mut ctx, t);
    let mut px = [0u8; 8];
    ctx.read_pixels(0, 0, 2, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    // 512/1023 → 16/31 → 132; 33/1023 → 1/31 → 8; alpha 1/3 → 0.
    assert_eq!(px, [255, 132, 0, 255, 8, 0, 255, 0]);
    common::assert_clean(&ctx);
}
