//! Framebuffer objects: rendering into textures and renderbuffers, reading them back,
//! sampling what was drawn, completeness, and WebGL's errors for their misuse.

use crate::common;

use common::*;
use essl_gl::{gl, Context, Parameter, Texture};

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
        None::<&[u8]>,
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
    colour_framebuffer(&mut ctx, t);
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
    colour_framebuffer(&mut ctx, t);
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

#[test]
fn a_multisampled_renderbuffer_resolves_through_blit() {
    let Some(mut ctx) = context(16, 16) else {
        return;
    };
    let fb = renderbuffer_framebuffer(&mut ctx, gl::RGBA8, 4, 16, 16);
    assert_eq!(
        ctx.get_renderbuffer_parameter(gl::RENDERBUFFER, gl::RENDERBUFFER_SAMPLES)
            .and_then(|p| p.as_int()),
        Some(4)
    );
    ctx.clear_color(0.0, 0.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    lower_left_triangle(&mut ctx, [1.0, 1.0, 1.0, 1.0]);
    // Reading a multisampled framebuffer object is an error; blitting it resolves it.
    let mut px = [0u8; 4];
    ctx.read_pixels(0, 0, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, Some(fb));
    ctx.bind_framebuffer(gl::DRAW_FRAMEBUFFER, None);
    ctx.blit_framebuffer(
        0,
        0,
        16,
        16,
        0,
        0,
        16,
        16,
        gl::COLOR_BUFFER_BIT,
        gl::NEAREST,
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    ctx.bind_framebuffer(gl::FRAMEBUFFER, None);
    assert_eq!(pixel(&mut ctx, 2, 2), [255, 255, 255, 255]);
    assert_eq!(pixel(&mut ctx, 13, 13), [0, 0, 0, 255]);
    // On the diagonal edge some pixels are partly covered: a resolve averages samples.
    let edge: Vec<u8> = (0..16).map(|i| pixel(&mut ctx, i, 15 - i)[0]).collect();
    assert!(
        edge.iter().any(|&v| v > 0 && v < 255),
        "no partly covered pixel: {edge:?}"
    );
    // A blit that scales a multisampled image is an error.
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, Some(fb));
    ctx.blit_framebuffer(0, 0, 16, 16, 0, 0, 8, 8, gl::COLOR_BUFFER_BIT, gl::NEAREST);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    assert_clean(&ctx);
}

#[test]
fn blits_scale_and_flip_with_nearest_filtering() {
    let Some(mut ctx) = context(8, 8) else { return };
    // A 2×2 texture: red, green (bottom row), blue, white (top row).
    let t = rgba8_texture(&mut ctx, 2, 2);
    let texels: [u8; 16] = [
        255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255,
    ];
    ctx.tex_sub_image_2d(
        gl::TEXTURE_2D,
        0,
        0,
        0,
        2,
        2,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        &texels,
    );
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, Some(fb));
    ctx.framebuffer_texture_2d(
        gl::READ_FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::TEXTURE_2D,
        Some(t),
        0,
    );
    ctx.blit_framebuffer(0, 0, 2, 2, 0, 0, 8, 8, gl::COLOR_BUFFER_BIT, gl::NEAREST);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, None);
    assert_eq!(pixel(&mut ctx, 1, 1), [255, 0, 0, 255]);
    assert_eq!(pixel(&mut ctx, 6, 1), [0, 255, 0, 255]);
    assert_eq!(pixel(&mut ctx, 1, 6), [0, 0, 255, 255]);
    assert_eq!(pixel(&mut ctx, 6, 6), [255, 255, 255, 255]);
    // Swapped destination corners flip both ways.
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, Some(fb));
    ctx.blit_framebuffer(0, 0, 2, 2, 8, 8, 0, 0, gl::COLOR_BUFFER_BIT, gl::NEAREST);
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, None);
    assert_eq!(pixel(&mut ctx, 1, 1), [255, 255, 255, 255]);
    assert_eq!(pixel(&mut ctx, 6, 6), [255, 0, 0, 255]);
    // The scissor box limits the destination.
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, Some(fb));
    ctx.enable(gl::SCISSOR_TEST);
    ctx.scissor(0, 0, 4, 8);
    ctx.blit_framebuffer(0, 0, 2, 2, 0, 0, 8, 8, gl::COLOR_BUFFER_BIT, gl::NEAREST);
    ctx.disable(gl::SCISSOR_TEST);
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, None);
    assert_eq!(pixel(&mut ctx, 1, 1), [255, 0, 0, 255]);
    assert_eq!(
        pixel(&mut ctx, 6, 6),
        [255, 0, 0, 255],
        "outside the scissor: kept"
    );
    assert_clean(&ctx);
}

#[test]
fn blit_errors_are_webgl2s_and_draw_nothing() {
    let Some(mut ctx) = context(4, 4) else { return };
    let t = rgba8_texture(&mut ctx, 4, 4);
    colour_framebuffer(&mut ctx, t);
    // Read and draw the same image.
    ctx.blit_framebuffer(0, 0, 2, 2, 2, 2, 4, 4, gl::COLOR_BUFFER_BIT, gl::NEAREST);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    // Depth with LINEAR.
    ctx.blit_framebuffer(0, 0, 4, 4, 0, 0, 4, 4, gl::DEPTH_BUFFER_BIT, gl::LINEAR);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.blit_framebuffer(0, 0, 4, 4, 0, 0, 4, 4, 0x8000, gl::NEAREST);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    ctx.blit_framebuffer(
        0,
        0,
        4,
        4,
        0,
        0,
        4,
        4,
        gl::COLOR_BUFFER_BIT,
        gl::LINEAR_MIPMAP_LINEAR,
    );
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    // A width past i32::MAX; i32::MAX itself is a size GL clips.
    let c = gl::COLOR_BUFFER_BIT;
    let max = i32::MAX;
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, None);
    ctx.blit_framebuffer(-1, 0, max, 4, 0, 0, 4, 4, c, gl::NEAREST);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    ctx.blit_framebuffer(0, 0, 4, 4, 0, max, 4, -1, c, gl::NEAREST);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    ctx.blit_framebuffer(0, 0, max, max, 0, 0, 4, 4, c, gl::NEAREST);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    // An integer image into a normalized one.
    let rb = ctx.create_renderbuffer();
    ctx.bind_renderbuffer(gl::RENDERBUFFER, Some(rb));
    ctx.renderbuffer_storage(gl::RENDERBUFFER, gl::RGBA8UI, 4, 4);
    let ifb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, Some(ifb));
    ctx.framebuffer_renderbuffer(
        gl::READ_FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::RENDERBUFFER,
        Some(rb),
    );
    ctx.bind_framebuffer(gl::DRAW_FRAMEBUFFER, None);
    ctx.clear_color(0.0, 1.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.blit_framebuffer(0, 0, 4, 4, 0, 0, 4, 4, gl::COLOR_BUFFER_BIT, gl::NEAREST);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, None);
    assert!(all_are(&mut ctx, [0, 255, 0, 255]), "nothing was drawn");
    assert_clean(&ctx);
}

#[test]
fn copy_tex_image_spreads_channels_and_zeroes_what_lies_outside() {
    let Some(mut ctx) = context(4, 4) else { return };
    ctx.clear_color(0.2, 0.4, 0.6, 0.8);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    // Half of the rectangle lies right of the framebuffer: those texels are 0.
    ctx.copy_tex_image_2d(gl::TEXTURE_2D, 0, gl::RGBA8, 2, 0, 4, 4, 0);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    colour_framebuffer(&mut ctx, t);
    assert_eq!(pixel(&mut ctx, 0, 0), [51, 102, 153, 204]);
    assert_eq!(pixel(&mut ctx, 3, 3), [0, 0, 0, 0]);
    // Into LUMINANCE: (R, R, R, 1).
    ctx.bind_framebuffer(gl::FRAMEBUFFER, None);
    let l = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(l));
    ctx.copy_tex_image_2d(gl::TEXTURE_2D, 0, gl::LUMINANCE, 0, 0, 2, 2, 0);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    // An integer format cannot take a normalized read buffer.
    ctx.copy_tex_image_2d(gl::TEXTURE_2D, 0, gl::RGBA8UI, 0, 0, 2, 2, 0);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    assert_clean(&ctx);
}

#[test]
fn three_draw_buffers_take_three_outputs() {
    let Some(mut ctx) = context(4, 4) else { return };
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    let textures: Vec<Texture> = (0..3).map(|_| rgba8_texture(&mut ctx, 4, 4)).collect();
    for (i, t) in textures.iter().enumerate() {
        ctx.framebuffer_texture_2d(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0 + i as u32,
            gl::TEXTURE_2D,
            Some(*t),
            0,
        );
    }
    ctx.draw_buffers(&[
        gl::COLOR_ATTACHMENT0,
        gl::COLOR_ATTACHMENT1,
        gl::COLOR_ATTACHMENT2,
    ]);
    let p = program(
        &mut ctx,
        PASS_VS,
        "#version 300 es
        precision mediump float;
        layout(location = 0) out vec4 a;
        layout(location = 1) out vec4 b;
        layout(location = 2) out vec4 c;
        void main() { a = vec4(1, 0, 0, 1); b = vec4(0, 1, 0, 1); c = vec4(0, 0, 1, 1); }",
    );
    ctx.use_program(Some(p));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    for (i, want) in [[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255]]
        .into_iter()
        .enumerate()
    {
        ctx.read_buffer(gl::COLOR_ATTACHMENT0 + i as u32);
        assert_eq!(pixel(&mut ctx, 1, 1), want, "attachment {i}");
    }
    // A draw buffer that is not COLOR_ATTACHMENTi at position i is an error.
    ctx.draw_buffers(&[gl::COLOR_ATTACHMENT1]);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    // clearBufferfv clears one draw buffer.
    ctx.draw_buffers(&[gl::COLOR_ATTACHMENT0, gl::COLOR_ATTACHMENT1]);
    ctx.clear_bufferfv(gl::COLOR, 1, &[1.0, 1.0, 0.0, 1.0]);
    ctx.read_buffer(gl::COLOR_ATTACHMENT1);
    assert_eq!(pixel(&mut ctx, 2, 2), [255, 255, 0, 255]);
    ctx.read_buffer(gl::COLOR_ATTACHMENT0);
    assert_eq!(pixel(&mut ctx, 2, 2), [255, 0, 0, 255]);
    assert_clean(&ctx);
}

#[test]
fn an_integer_attachment_holds_ids_read_back_as_integers() {
    let Some(mut ctx) = context(4, 4) else { return };
    renderbuffer_framebuffer(&mut ctx, gl::R32UI, 0, 4, 4);
    // clear() with a float colour is an error on an integer buffer; clearBufferuiv is not.
    ctx.clear(gl::COLOR_BUFFER_BIT);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.clear_bufferuiv(gl::COLOR, 0, &[7, 0, 0, 0]);
    ctx.clear_bufferfv(gl::COLOR, 0, &[1.0, 0.0, 0.0, 0.0]);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "a float value into an integer buffer"
    );
    let p = program(
        &mut ctx,
        PASS_VS,
        "#version 300 es
        precision highp float;
        uniform uint u_id;
        out uint id;
        void main() { id = u_id; }",
    );
    ctx.use_program(Some(p));
    let id = ctx.get_uniform_location(p, "u_id");
    ctx.uniform1ui(id, 3_000_000_000);
    float_attribute(&mut ctx, 0, 2, &[-1.0, -1.0, 1.0, -1.0, -1.0, 1.0]);
    ctx.draw_arrays(gl::TRIANGLES, 0, 3);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    let mut out = [0u32; 4];
    ctx.read_pixels(0, 0, 1, 1, gl::RGBA_INTEGER, gl::UNSIGNED_INT, &mut out);
    assert_eq!(out, [3_000_000_000, 0, 0, 1]);
    ctx.read_pixels(3, 3, 1, 1, gl::RGBA_INTEGER, gl::UNSIGNED_INT, &mut out);
    assert_eq!(out, [7, 0, 0, 1]);
    // RGBA/UNSIGNED_BYTE cannot read an integer buffer.
    let mut px = [0u8; 4];
    ctx.read_pixels(0, 0, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    assert_clean(&ctx);
}

#[test]
fn a_depth_texture_drawn_from_the_light_is_compared_by_a_shadow_sampler() {
    let Some(mut ctx) = context(8, 8) else { return };
    let depth = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(depth));
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::DEPTH_COMPONENT24 as i32,
        8,
        8,
        0,
        gl::DEPTH_COMPONENT,
        gl::UNSIGNED_INT,
        None::<&[u8]>,
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    ctx.tex_parameteri(
        gl::TEXTURE_2D,
        gl::TEXTURE_COMPARE_MODE,
        gl::COMPARE_REF_TO_TEXTURE as i32,
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_COMPARE_FUNC, gl::LEQUAL as i32);
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::DEPTH_ATTACHMENT,
        gl::TEXTURE_2D,
        Some(depth),
        0,
    );
    ctx.draw_buffers(&[gl::NONE]);
    ctx.read_buffer(gl::NONE);
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE
    );
    ctx.enable(gl::DEPTH_TEST);
    ctx.clear(gl::DEPTH_BUFFER_BIT);
    // An occluder at depth 0.5 (z = 0) over the lower-left half.
    let p = program(&mut ctx, PASS_VS, "#version 300 es\nvoid main() {}");
    ctx.use_program(Some(p));
    float_attribute(&mut ctx, 0, 2, &[-1.0, -1.0, 1.0, -1.0, -1.0, 1.0]);
    ctx.draw_arrays(gl::TRIANGLES, 0, 3);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    // Compare a reference depth of 0.75 against it: lit (1) where the occluder is not.
    ctx.bind_framebuffer(gl::FRAMEBUFFER, None);
    ctx.disable(gl::DEPTH_TEST);
    let q = program(
        &mut ctx,
        "#version 300 es
        in vec2 a_position;
        out vec2 v_uv;
        void main() { v_uv = a_position * 0.5 + 0.5; gl_Position = vec4(a_position, 0.0, 1.0); }",
        "#version 300 es
        precision mediump float;
        precision mediump sampler2DShadow;
        uniform sampler2DShadow u_shadow;
        in vec2 v_uv;
        out vec4 color;
        void main() { color = vec4(texture(u_shadow, vec3(v_uv, 0.75))); }",
    );
    ctx.use_program(Some(q));
    ctx.bind_texture(gl::TEXTURE_2D, Some(depth));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_eq!(pixel(&mut ctx, 1, 1), [0, 0, 0, 0], "in shadow");
    assert_eq!(pixel(&mut ctx, 6, 6), [255, 255, 255, 255], "lit");
    assert_clean(&ctx);
}

#[test]
fn the_stencil_buffer_masks_later_draws() {
    let attributes = essl_gl::ContextAttributes {
        stencil: true,
        ..Default::default()
    };
    let Some(mut ctx) = context_with(4, 4, attributes) else {
        return;
    };
    ctx.clear_color(0.0, 0.0, 0.0, 1.0);
    ctx.clear_stencil(0);
    ctx.clear(gl::COLOR_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
    ctx.enable(gl::STENCIL_TEST);
    ctx.stencil_func(gl::ALWAYS, 1, 0xFF);
    ctx.stencil_op(gl::KEEP, gl::KEEP, gl::REPLACE);
    ctx.color_mask(false, false, false, false);
    lower_left_triangle(&mut ctx, [1.0, 1.0, 1.0, 1.0]);
    ctx.color_mask(true, true, true, true);
    ctx.stencil_func(gl::NOTEQUAL, 1, 0xFF);
    ctx.stencil_op(gl::KEEP, gl::KEEP, gl::KEEP);
    let p = program(&mut ctx, PASS_VS, SOLID_FS);
    ctx.use_program(Some(p));
    let color = ctx.get_uniform_location(p, "u_color");
    ctx.uniform4f(color, 1.0, 0.0, 0.0, 1.0);
    float_attribute(&mut ctx, 0, 2, &QUAD);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_eq!(pixel(&mut ctx, 0, 0), [0, 0, 0, 255], "stencilled out");
    assert_eq!(pixel(&mut ctx, 3, 3), [255, 0, 0, 255]);
    // Front and back references that differ make a draw an error (WebGL).
    ctx.stencil_func_separate(gl::BACK, gl::NOTEQUAL, 2, 0xFF);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    assert_clean(&ctx);
}

/// Draws a full-screen white quad into a fresh 4-sample framebuffer with `SAMPLE_COVERAGE`
/// (`value`, `invert`) and returns the resolved pixel.
fn covered_pixel(ctx: &mut Context, value: f32, invert: bool) -> [u8; 4] {
    let fb = renderbuffer_framebuffer(ctx, gl::RGBA8, 4, 4, 4);
    ctx.clear_color(0.0, 0.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.enable(gl::SAMPLE_COVERAGE);
    ctx.sample_coverage(value, invert);
    let p = program(ctx, PASS_VS, SOLID_FS);
    ctx.use_program(Some(p));
    let color = ctx.get_uniform_location(p, "u_color");
    ctx.uniform4f(color, 1.0, 1.0, 1.0, 1.0);
    float_attribute(
        ctx,
        0,
        2,
        &[
            -1.0, -1.0, 1.0, -1.0, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, 1.0, 1.0,
        ],
    );
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    ctx.disable(gl::SAMPLE_COVERAGE);
    ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, Some(fb));
    ctx.bind_framebuffer(gl::DRAW_FRAMEBUFFER, None);
    ctx.blit_framebuffer(0, 0, 4, 4, 0, 0, 4, 4, gl::COLOR_BUFFER_BIT, gl::NEAREST);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    ctx.bind_framebuffer(gl::FRAMEBUFFER, None);
    pixel(ctx, 1, 1)
}

#[test]
fn sample_coverage_masks_the_samples_a_draw_writes() {
    let Some(mut ctx) = context(4, 4) else { return };
    let full = covered_pixel(&mut ctx, 1.0, false)[0];
    let half = covered_pixel(&mut ctx, 0.5, false)[0];
    let other_half = covered_pixel(&mut ctx, 0.5, true)[0];
    let none = covered_pixel(&mut ctx, 0.0, false)[0];
    let quarter = covered_pixel(&mut ctx, 0.25, false)[0];
    assert_eq!((full, none), (255, 0));
    // Two of four samples white: the resolve averages to half, however it rounds.
    assert!(
        (127..=128).contains(&half),
        "half coverage resolved to {half}"
    );
    assert!(
        (127..=128).contains(&other_half),
        "inverted half: {other_half}"
    );
    assert!((63..=64).contains(&quarter), "a quarter: {quarter}");
    assert_clean(&ctx);
}

#[test]
fn multisampled_32_bit_floats_resolve_through_blit() {
    // wgpu cannot resolve R32Float and RGBA32Float; the blit shader averages their samples.
    let Some(mut ctx) = context(2, 2) else { return };
    assert!(ctx.get_extension("EXT_color_buffer_float").is_some());
    for format in [gl::R32F, gl::RGBA32F, gl::R16F] {
        let samples = match ctx.get_internalformat_parameter(gl::RENDERBUFFER, format, gl::SAMPLES)
        {
            Some(Parameter::Ints(s)) if !s.is_empty() => s[0],
            _ => continue,
        };
        let resolved = renderbuffer_framebuffer(&mut ctx, format, 0, 2, 2);
        // Bound to FRAMEBUFFER: the clear and the blit's read.
        renderbuffer_framebuffer(&mut ctx, format, samples, 2, 2);
        ctx.clear_color(1000.0, 1000.0, 1000.0, 1000.0);
        ctx.clear(gl::COLOR_BUFFER_BIT);
        ctx.bind_framebuffer(gl::DRAW_FRAMEBUFFER, Some(resolved));
        ctx.blit_framebuffer(0, 0, 2, 2, 0, 0, 2, 2, gl::COLOR_BUFFER_BIT, gl::NEAREST);
        ctx.bind_framebuffer(gl::READ_FRAMEBUFFER, Some(resolved));
        let mut texel = [0f32; 4];
        ctx.read_pixels(0, 0, 1, 1, gl::RGBA, gl::FLOAT, &mut texel);
        assert_eq!(ctx.get_error(), gl::NO_ERROR);
        assert_eq!(texel[0], 1000.0, "format 0x{format:04X}");
    }
    assert_clean(&ctx);
}

#[test]
fn small_integer_images_read_back_in_their_own_pair() {
    // The implementation's pair of an 8- or 16-bit integer image names a 1- or 2-byte type.
    let Some(mut ctx) = context(2, 2) else { return };
    for (format, bytes) in [
        (gl::RGBA8I, 1),
        (gl::RGBA8UI, 1),
        (gl::RGBA16I, 2),
        (gl::RG16UI, 2),
        (gl::R32I, 4),
    ] {
        renderbuffer_framebuffer(&mut ctx, format, 0, 2, 2);
        ctx.clear_bufferiv(gl::COLOR, 0, &[3, 5, 7, 9]);
        ctx.clear_bufferuiv(gl::COLOR, 0, &[3, 5, 7, 9]);
        let Some(Parameter::Enum(f)) = ctx.get_parameter(gl::IMPLEMENTATION_COLOR_READ_FORMAT)
        else {
            panic!("no read format for 0x{format:04X}");
        };
        let Some(Parameter::Enum(ty)) = ctx.get_parameter(gl::IMPLEMENTATION_COLOR_READ_TYPE)
        else {
            panic!("no read type for 0x{format:04X}");
        };
        let _ = ctx.get_error();
        // The first channel of the first pixel, read into the array type `ty` takes.
        let first = match ty {
            gl::BYTE => read_first::<i8>(&mut ctx, f, ty, 16) as i64,
            gl::UNSIGNED_BYTE => read_first::<u8>(&mut ctx, f, ty, 16) as i64,
            gl::SHORT => read_first::<i16>(&mut ctx, f, ty, 16) as i64,
            gl::UNSIGNED_SHORT => read_first::<u16>(&mut ctx, f, ty, 16) as i64,
            gl::INT => read_first::<i32>(&mut ctx, f, ty, 16) as i64,
            _ => read_first::<u32>(&mut ctx, f, ty, 16) as i64,
        };
        assert_eq!(
            ctx.get_error(),
            gl::NO_ERROR,
            "format 0x{format:04X}: 0x{f:X} 0x{ty:X}"
        );
        assert_eq!(first, 3, "format 0x{format:04X}");
        let size = match ty {
            gl::BYTE | gl::UNSIGNED_BYTE => 1,
            gl::SHORT | gl::UNSIGNED_SHORT => 2,
            _ => 4,
        };
        assert_eq!(size, bytes, "format 0x{format:04X}: its own type");
    }
}

/// The first element `read_pixels` writes of a 2 × 2 read in `(format, ty)` into `n` `T`s.
fn read_first<T: essl_gl::ArrayElement + Copy + Default>(
    ctx: &mut Context,
    format: u32,
    ty: u32,
    n: usize,
) -> T {
    let mut out = vec![T::default(); n];
    ctx.read_pixels(0, 0, 2, 2, format, ty, &mut out[..]);
    out[0]
}

#[test]
fn a_mutable_textures_attached_level_lies_in_its_complete_mip_chain() {
    // ES 3.0 §4.4.4: level in [base, q], and other than the base only when mipmap complete.
    let Some(mut ctx) = context(4, 4) else { return };
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    let level = |ctx: &mut Context, level: i32, size: i32| {
        ctx.tex_image_2d(
            gl::TEXTURE_2D,
            level,
            gl::RGBA8 as i32,
            size,
            size,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            None::<&[u8]>,
        );
    };
    level(&mut ctx, 0, 4);
    level(&mut ctx, 1, 2);
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    let status = |ctx: &mut Context, at: i32| {
        ctx.framebuffer_texture_2d(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0,
            gl::TEXTURE_2D,
            Some(t),
            at,
        );
        ctx.check_framebuffer_status(gl::FRAMEBUFFER)
    };
    assert_eq!(
        status(&mut ctx, 0),
        gl::FRAMEBUFFER_COMPLETE,
        "the base level"
    );
    assert_eq!(
        status(&mut ctx, 1),
        gl::FRAMEBUFFER_INCOMPLETE_ATTACHMENT,
        "no 1 × 1 level yet"
    );
    level(&mut ctx, 2, 1);
    assert_eq!(
        status(&mut ctx, 1),
        gl::FRAMEBUFFER_COMPLETE,
        "mipmap complete"
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_BASE_LEVEL, 1);
    assert_eq!(
        status(&mut ctx, 0),
        gl::FRAMEBUFFER_INCOMPLETE_ATTACHMENT,
        "below the base"
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAX_LEVEL, 0);
    assert_eq!(
        status(&mut ctx, 1),
        gl::FRAMEBUFFER_INCOMPLETE_ATTACHMENT,
        "max below base"
    );
    // An immutable texture's every level may be attached.
    let s = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(s));
    ctx.tex_storage_2d(gl::TEXTURE_2D, 3, gl::RGBA8, 4, 4);
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_BASE_LEVEL, 2);
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::TEXTURE_2D,
        Some(s),
        0,
    );
    assert_eq!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE
    );
}
