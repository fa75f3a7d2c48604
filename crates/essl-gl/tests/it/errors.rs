//! Misuse: each WebGL error essl-gl records, asserting the error code and that nothing was
//! drawn (or that the failed call changed nothing a draw could see).

use crate::common;

use common::*;
use essl::types::GlType;
use essl_gl::{gl, Context, Program};

/// A misuse and the error it records.
type Case<'a> = (&'a dyn Fn(&mut Context), u32);
/// A misuse (owning its data) and the error it records.
type BoxedCase = (Box<dyn Fn(&mut Context)>, u32);

const W: u32 = 32;
const H: u32 = 32;
const BLACK: [u8; 4] = [0, 0, 0, 255];
const WHITE: [u8; 4] = [255; 4];

/// A context with a white full-screen quad program in use, attribute 0 fed, cleared black.
fn ready() -> Option<(Context, Program)> {
    let mut ctx = context(W, H)?;
    let program = ctx.program_from_layout(solid(1.0, 1.0, 1.0));
    ctx.use_program(Some(program));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    clear_black(&mut ctx);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    Some((ctx, program))
}

/// Asserts the recorded error, then that the framebuffer is still black.
fn assert_error_and_nothing_drawn(ctx: &mut Context, code: u32) {
    assert_eq!(ctx.get_error(), code, "{:?}", ctx.error_message());
    assert_eq!(
        ctx.get_error(),
        gl::NO_ERROR,
        "the error is cleared once read"
    );
    assert!(all_are(ctx, BLACK), "nothing may be drawn");
    assert_clean(ctx);
}

/// Asserts the recorded error, then that a draw still draws the white quad.
fn assert_error_and_no_effect(ctx: &mut Context, code: u32) {
    assert_eq!(ctx.get_error(), code, "{:?}", ctx.error_message());
    clear_black(ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert!(
        all_are(ctx, WHITE),
        "the failed call must not have changed what is drawn"
    );
    assert_clean(ctx);
}

#[test]
fn draw_without_a_program_is_invalid_operation() {
    let Some((mut ctx, _)) = ready() else { return };
    ctx.use_program(None);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
}

#[test]
fn an_enabled_attribute_without_a_buffer_is_invalid_operation() {
    let Some((mut ctx, _)) = ready() else { return };
    ctx.enable_vertex_attrib_array(3);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
}

#[test]
fn vertices_past_the_end_of_a_buffer_are_invalid_operation() {
    let Some((mut ctx, _)) = ready() else { return };
    ctx.draw_arrays(gl::TRIANGLES, 0, 9);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
    ctx.draw_arrays(gl::TRIANGLES, 4, 3);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
    // An attribute offset that pushes the last vertex past the end.
    ctx.vertex_attrib_pointer(0, 2, gl::FLOAT, false, 0, 8);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
}

#[test]
fn indices_past_the_end_are_invalid_operation() {
    let Some((mut ctx, _)) = ready() else { return };
    let ib = ctx.create_buffer();
    ctx.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, Some(ib));
    ctx.buffer_data(
        gl::ELEMENT_ARRAY_BUFFER,
        &[0u16, 1, 2, 3, 4, 5],
        gl::STATIC_DRAW,
    );
    // More indices than the buffer holds.
    ctx.draw_elements(gl::TRIANGLES, 7, gl::UNSIGNED_SHORT, 0);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
    ctx.draw_elements(gl::TRIANGLES, 6, gl::UNSIGNED_SHORT, 2);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
    // An index naming a vertex past the end of the vertex buffer.
    ctx.buffer_data(gl::ELEMENT_ARRAY_BUFFER, &[0u16, 1, 6], gl::STATIC_DRAW);
    ctx.draw_elements(gl::TRIANGLES, 3, gl::UNSIGNED_SHORT, 0);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
    // The restart index does not count as a vertex.
    ctx.buffer_data(
        gl::ELEMENT_ARRAY_BUFFER,
        &[0u16, 1, 2, 0xFFFF, 3, 4, 5],
        gl::STATIC_DRAW,
    );
    ctx.draw_elements(gl::TRIANGLE_STRIP, 7, gl::UNSIGNED_SHORT, 0);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
}

#[test]
fn negative_counts_are_invalid_value() {
    let Some((mut ctx, _)) = ready() else { return };
    ctx.draw_arrays(gl::TRIANGLES, 0, -1);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_VALUE);
    ctx.draw_arrays(gl::TRIANGLES, -1, 3);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_VALUE);
    ctx.draw_arrays_instanced(gl::TRIANGLES, 0, 6, -1);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_VALUE);
    ctx.draw_elements(gl::TRIANGLES, 3, gl::UNSIGNED_SHORT, -2);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_VALUE);
}

#[test]
fn an_unknown_mode_is_invalid_enum() {
    let Some((mut ctx, _)) = ready() else { return };
    ctx.draw_arrays(0x0007, 0, 6); // GL_QUADS is not in WebGL
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_ENUM);
}

#[test]
fn element_draw_errors() {
    let Some((mut ctx, _)) = ready() else { return };
    // No element buffer.
    ctx.draw_elements(gl::TRIANGLES, 3, gl::UNSIGNED_SHORT, 0);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
    let ib = ctx.create_buffer();
    ctx.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, Some(ib));
    ctx.buffer_data(
        gl::ELEMENT_ARRAY_BUFFER,
        &[0u16, 1, 2, 3, 4, 5],
        gl::STATIC_DRAW,
    );
    // Not an index type.
    ctx.draw_elements(gl::TRIANGLES, 3, gl::FLOAT, 0);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_ENUM);
    // An offset that is not a multiple of the index size.
    ctx.draw_elements(gl::TRIANGLES, 3, gl::UNSIGNED_SHORT, 1);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
}

#[test]
fn attribute_types_must_match_the_shader() {
    let Some((mut ctx, _)) = ready() else { return };
    // An integer array for a float input.
    ctx.vertex_attrib_i_pointer(0, 2, gl::INT, 0, 0);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
    // An integer generic value for a float input whose array is disabled.
    ctx.disable_vertex_attrib_array(0);
    ctx.vertex_attrib_i4i(0, 1, 1, 0, 1);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
}

fn two_samplers() -> essl::program::ProgramLayout {
    Layout::new(
        "@vertex fn main(@location(0) a_position: vec2<f32>) -> @builtin(position) vec4<f32> { return gl_clip(vec4(a_position, 0.0, 1.0)); }",
        "@group(1) @binding(0) var t0: texture_2d<f32>;
         @group(1) @binding(1) var s0: sampler;
         @group(1) @binding(2) var t1: texture_cube<f32>;
         @group(1) @binding(3) var s1: sampler;
         @fragment fn main() -> @location(0) vec4<f32> {
             return textureSample(t0, s0, vec2(0.5)) + textureSample(t1, s1, vec3(1.0, 0.0, 0.0)) + vec4(1.0);
         }",
    )
    .attribute("a_position", GlType::FLOAT_VEC2, 0)
    .sampler("u_2d", GlType::SAMPLER_2D)
    .sampler("u_cube", GlType::SAMPLER_CUBE)
    .build()
}

#[test]
fn samplers_of_two_types_on_one_unit_are_invalid_operation() {
    let Some((mut ctx, _)) = ready() else { return };
    let program = ctx.program_from_layout(two_samplers());
    assert!(
        ctx.get_program_link_status(program),
        "{:?}",
        ctx.get_program_info_log(program)
    );
    ctx.use_program(Some(program));
    // Both samplers default to unit 0.
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
    let cube = ctx.get_uniform_location(program, "u_cube");
    ctx.uniform1i(cube, 1);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_error_and_no_effect(&mut ctx, gl::NO_ERROR);
}

#[test]
fn an_integer_texture_on_a_float_sampler_is_invalid_operation() {
    let Some((mut ctx, _)) = ready() else { return };
    let program = ctx.program_from_layout(two_samplers());
    ctx.use_program(Some(program));
    let cube = ctx.get_uniform_location(program, "u_cube");
    ctx.uniform1i(cube, 1);
    let tex = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(tex));
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA8UI as i32,
        1,
        1,
        0,
        gl::RGBA_INTEGER,
        gl::UNSIGNED_BYTE,
        Some(&[1u8, 2, 3, 4]),
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_OPERATION);
}

#[test]
fn vertex_attrib_pointer_errors_change_nothing() {
    let Some((mut ctx, _)) = ready() else { return };
    let cases: [Case; 8] = [
        (
            &|c| c.vertex_attrib_pointer(0, 2, gl::FLOAT, false, 256, 0),
            gl::INVALID_VALUE,
        ),
        (
            &|c| c.vertex_attrib_pointer(0, 2, gl::FLOAT, false, -4, 0),
            gl::INVALID_VALUE,
        ),
        (
            &|c| c.vertex_attrib_pointer(0, 5, gl::FLOAT, false, 0, 0),
            gl::INVALID_VALUE,
        ),
        (
            &|c| c.vertex_attrib_pointer(0, 2, gl::FLOAT, false, 0, -4),
            gl::INVALID_VALUE,
        ),
        (
            &|c| c.vertex_attrib_pointer(16, 2, gl::FLOAT, false, 0, 0),
            gl::INVALID_VALUE,
        ),
        (
            &|c| c.vertex_attrib_pointer(0, 2, gl::RGBA, false, 0, 0),
            gl::INVALID_ENUM,
        ),
        (
            &|c| c.vertex_attrib_pointer(0, 2, gl::FLOAT, false, 0, 2),
            gl::INVALID_OPERATION,
        ),
        (
            &|c| c.vertex_attrib_pointer(0, 2, gl::FLOAT, false, 6, 0),
            gl::INVALID_OPERATION,
        ),
    ];
    for (call, code) in cases {
        call(&mut ctx);
        assert_error_and_no_effect(&mut ctx, code);
    }
    // A nonzero offset with no ARRAY_BUFFER bound.
    ctx.bind_buffer(gl::ARRAY_BUFFER, None);
    ctx.vertex_attrib_pointer(0, 2, gl::FLOAT, false, 0, 8);
    assert_error_and_no_effect(&mut ctx, gl::INVALID_OPERATION);
}

#[test]
fn buffer_errors_change_nothing() {
    let Some((mut ctx, _)) = ready() else { return };
    let zeros = [0.0f32; 12];
    ctx.buffer_data(gl::ARRAY_BUFFER, &zeros, 0x1234);
    assert_error_and_no_effect(&mut ctx, gl::INVALID_ENUM);
    ctx.buffer_data(0x1234, &zeros, gl::STATIC_DRAW);
    assert_error_and_no_effect(&mut ctx, gl::INVALID_ENUM);
    ctx.buffer_data_size(gl::ARRAY_BUFFER, -1, gl::STATIC_DRAW);
    assert_error_and_no_effect(&mut ctx, gl::INVALID_VALUE);
    ctx.buffer_sub_data(gl::ARRAY_BUFFER, 4, &zeros);
    assert_error_and_no_effect(&mut ctx, gl::INVALID_VALUE);
    ctx.buffer_sub_data(gl::ARRAY_BUFFER, -4, &zeros[..1]);
    assert_error_and_no_effect(&mut ctx, gl::INVALID_VALUE);
    // Nothing bound to ELEMENT_ARRAY_BUFFER.
    ctx.buffer_data(gl::ELEMENT_ARRAY_BUFFER, &zeros, gl::STATIC_DRAW);
    assert_error_and_no_effect(&mut ctx, gl::INVALID_OPERATION);
    // A vertex buffer cannot become an index buffer (WebGL).
    let vertices = ctx.create_buffer();
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(vertices));
    ctx.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, Some(vertices));
    assert_error_and_no_effect(&mut ctx, gl::INVALID_OPERATION);
}

#[test]
fn foreign_and_deleted_handles_are_invalid_operation() {
    let Some((mut ctx, _)) = ready() else { return };
    let Some(mut other) = context(4, 4) else {
        return;
    };
    let foreign = other.create_buffer();
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(foreign));
    assert_error_and_no_effect(&mut ctx, gl::INVALID_OPERATION);
    let foreign_program = other.program_from_layout(solid(0.0, 0.0, 0.0));
    ctx.use_program(Some(foreign_program));
    assert_error_and_no_effect(&mut ctx, gl::INVALID_OPERATION);
    let tex = ctx.create_texture();
    ctx.delete_texture(tex);
    ctx.bind_texture(gl::TEXTURE_2D, Some(tex));
    assert_error_and_no_effect(&mut ctx, gl::INVALID_OPERATION);
    // A handle of a deleted object is not confused with a newer object in its slot.
    let newer = ctx.create_texture();
    assert_ne!(tex, newer);
    assert!(!ctx.is_texture(tex));
}

#[test]
fn the_first_error_sticks_until_read() {
    let Some((mut ctx, _)) = ready() else { return };
    ctx.enable(0x1234);
    ctx.viewport(0, 0, -1, -1);
    ctx.draw_arrays(gl::TRIANGLES, 0, 60);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert!(all_are(&mut ctx, BLACK));
}

#[test]
fn texture_errors_change_nothing() {
    let Some(mut ctx) = context(W, H) else { return };
    let program = ctx.program_from_layout(Layout::new(
        "struct Out { @builtin(position) pos: vec4<f32>, @location(0) uv: vec2<f32> }
         @vertex fn main(@location(0) p: vec2<f32>) -> Out { return Out(gl_clip(vec4(p, 0.0, 1.0)), p * 0.5 + 0.5); }",
        "@group(1) @binding(0) var t: texture_2d<f32>;
         @group(1) @binding(1) var s: sampler;
         @fragment fn main(@location(0) uv: vec2<f32>) -> @location(0) vec4<f32> { return textureSample(t, s, uv); }",
    )
    .attribute("a_position", GlType::FLOAT_VEC2, 0)
    .sampler("u_tex", GlType::SAMPLER_2D)
    .build());
    ctx.use_program(Some(program));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    let tex = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(tex));
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        1,
        1,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&[255u8, 255, 255, 255]),
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    let red = [255u8, 0, 0, 255];
    let cases: Vec<BoxedCase> = vec![
        (
            Box::new(move |c| {
                c.tex_image_2d(
                    0x1234,
                    0,
                    gl::RGBA as i32,
                    1,
                    1,
                    0,
                    gl::RGBA,
                    gl::UNSIGNED_BYTE,
                    Some(&red),
                )
            }),
            gl::INVALID_ENUM,
        ),
        (
            Box::new(move |c| {
                c.tex_image_2d(
                    gl::TEXTURE_2D,
                    -1,
                    gl::RGBA as i32,
                    1,
                    1,
                    0,
                    gl::RGBA,
                    gl::UNSIGNED_BYTE,
                    Some(&red),
                )
            }),
            gl::INVALID_VALUE,
        ),
        (
            Box::new(move |c| {
                c.tex_image_2d(
                    gl::TEXTURE_2D,
                    0,
                    gl::RGBA as i32,
                    1,
                    1,
                    1,
                    gl::RGBA,
                    gl::UNSIGNED_BYTE,
                    Some(&red),
                )
            }),
            gl::INVALID_VALUE,
        ),
        (
            Box::new(move |c| {
                c.tex_image_2d(
                    gl::TEXTURE_2D,
                    0,
                    gl::RGBA as i32,
                    -1,
                    1,
                    0,
                    gl::RGBA,
                    gl::UNSIGNED_BYTE,
                    Some(&red),
                )
            }),
            gl::INVALID_VALUE,
        ),
        (
            Box::new(move |c| {
                c.tex_image_2d(
                    gl::TEXTURE_2D,
                    0,
                    gl::RGBA8 as i32,
                    1,
                    1,
                    0,
                    gl::RGB,
                    gl::UNSIGNED_BYTE,
                    Some(&red),
                )
            }),
            gl::INVALID_OPERATION,
        ),
        (
            Box::new(move |c| {
                c.tex_image_2d(
                    gl::TEXTURE_2D,
                    0,
                    gl::RGBA as i32,
                    2,
                    2,
                    0,
                    gl::RGBA,
                    gl::UNSIGNED_BYTE,
                    Some(&red),
                )
            }),
            gl::INVALID_OPERATION,
        ),
        (
            Box::new(move |c| {
                c.tex_image_2d(
                    gl::TEXTURE_2D,
                    0,
                    0x1234,
                    1,
                    1,
                    0,
                    gl::RGBA,
                    gl::UNSIGNED_BYTE,
                    Some(&red),
                )
            }),
            gl::INVALID_VALUE,
        ),
        (
            Box::new(move |c| {
                c.tex_image_2d(
                    gl::TEXTURE_2D,
                    0,
                    gl::RGBA as i32,
                    1,
                    1,
                    0,
                    gl::RGBA,
                    0x1234,
                    Some(&red),
                )
            }),
            gl::INVALID_ENUM,
        ),
        (
            Box::new(move |c| {
                c.tex_sub_image_2d(
                    gl::TEXTURE_2D,
                    0,
                    1,
                    0,
                    1,
                    1,
                    gl::RGBA,
                    gl::UNSIGNED_BYTE,
                    &red,
                )
            }),
            gl::INVALID_VALUE,
        ),
        (
            Box::new(|c| c.tex_parameteri(gl::TEXTURE_2D, 0x1234, gl::NEAREST as i32)),
            gl::INVALID_ENUM,
        ),
        (
            Box::new(|c| {
                c.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::REPEAT as i32)
            }),
            gl::INVALID_ENUM,
        ),
        (
            Box::new(|c| {
                let t = c_texture(c);
                c.bind_texture(gl::TEXTURE_CUBE_MAP, Some(t))
            }),
            gl::INVALID_OPERATION,
        ),
        (
            Box::new(|c| c.active_texture(gl::TEXTURE0 + 32)),
            gl::INVALID_ENUM,
        ),
    ];
    for (i, (call, code)) in cases.into_iter().enumerate() {
        clear_black(&mut ctx);
        call(&mut ctx);
        assert_eq!(ctx.get_error(), code, "case {i}: {:?}", ctx.error_message());
        ctx.draw_arrays(gl::TRIANGLES, 0, 6);
        assert_eq!(ctx.get_error(), gl::NO_ERROR, "case {i}");
        assert!(
            all_are(&mut ctx, WHITE),
            "case {i}: the texture must be unchanged"
        );
    }
    // Cube faces must be square; no texture bound is INVALID_OPERATION.
    let cube = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_CUBE_MAP, Some(cube));
    ctx.tex_image_2d(
        gl::TEXTURE_CUBE_MAP_POSITIVE_X,
        0,
        gl::RGBA as i32,
        2,
        1,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        None::<&[u8]>,
    );
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    ctx.bind_texture(gl::TEXTURE_2D, None);
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        1,
        1,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        None::<&[u8]>,
    );
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.generate_mipmap(gl::TEXTURE_2D);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    assert_clean(&ctx);
}

/// A texture bound once to TEXTURE_2D (on unit 1, leaving unit 0 alone).
fn c_texture(ctx: &mut Context) -> essl_gl::Texture {
    let t = ctx.create_texture();
    ctx.active_texture(gl::TEXTURE1);
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.active_texture(gl::TEXTURE0);
    t
}

#[test]
fn state_errors_change_nothing() {
    let Some((mut ctx, _)) = ready() else { return };
    let cases: [Case; 9] = [
        (&|c| c.enable(0x1234), gl::INVALID_ENUM),
        (&|c| c.depth_func(0x1234), gl::INVALID_ENUM),
        (&|c| c.cull_face(gl::CCW), gl::INVALID_ENUM),
        (&|c| c.blend_func(0x1234, gl::ONE), gl::INVALID_ENUM),
        (
            &|c| c.blend_func(gl::CONSTANT_COLOR, gl::CONSTANT_ALPHA),
            gl::INVALID_OPERATION,
        ),
        (&|c| c.blend_equation(gl::ONE), gl::INVALID_ENUM),
        (&|c| c.viewport(0, 0, -1, 4), gl::INVALID_VALUE),
        (&|c| c.depth_range(1.0, 0.0), gl::INVALID_OPERATION),
        (
            &|c| c.pixel_storei(gl::UNPACK_ALIGNMENT, 3),
            gl::INVALID_VALUE,
        ),
    ];
    for (call, code) in cases {
        call(&mut ctx);
        assert_error_and_no_effect(&mut ctx, code);
    }
}

#[test]
fn a_clear_with_unknown_bits_is_invalid_value() {
    let Some((mut ctx, _)) = ready() else { return };
    ctx.clear_color(1.0, 1.0, 1.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT | 0x1);
    assert_error_and_nothing_drawn(&mut ctx, gl::INVALID_VALUE);
}

#[test]
fn uniform_errors_change_nothing() {
    let Some(mut ctx) = context(W, H) else { return };
    let layout = || {
        Layout::new(
            "@vertex fn main(@location(0) p: vec2<f32>) -> @builtin(position) vec4<f32> { return gl_clip(vec4(p, 0.0, 1.0)); }",
            "struct U { u_color: vec4<f32>, u_unit: i32 }
             @group(0) @binding(0) var<uniform> u: U;
             @fragment fn main() -> @location(0) vec4<f32> { return u.u_color; }",
        )
        .attribute("a_position", GlType::FLOAT_VEC2, 0)
        .uniform("u_color", GlType::FLOAT_VEC4, 1, 0, 16, 0)
        .uniform("u_unit", GlType::INT, 1, 16, 16, 0)
        .block_size(32)
        .build()
    };
    let program = ctx.program_from_layout(layout());
    let other = ctx.program_from_layout(layout());
    ctx.use_program(Some(program));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    let color = ctx.get_uniform_location(program, "u_color");
    let unit = ctx.get_uniform_location(program, "u_unit");
    let other_color = ctx.get_uniform_location(other, "u_color");
    ctx.uniform4f(color, 1.0, 1.0, 1.0, 1.0);
    let cases: [Case; 5] = [
        (
            &|c| c.uniform3f(color, 0.0, 0.0, 0.0),
            gl::INVALID_OPERATION,
        ),
        (&|c| c.uniform4i(color, 0, 0, 0, 0), gl::INVALID_OPERATION),
        (
            &|c| c.uniform4f(other_color, 0.0, 0.0, 0.0, 1.0),
            gl::INVALID_OPERATION,
        ),
        (&|c| c.uniform4fv(color, &[0.0; 8]), gl::INVALID_OPERATION),
        (&|c| c.uniform4fv(color, &[0.0; 3]), gl::INVALID_VALUE),
    ];
    for (call, code) in cases {
        call(&mut ctx);
        assert_error_and_no_effect(&mut ctx, code);
    }
    ctx.uniform1i(unit, 3);
    ctx.uniform4f(None, 0.0, 0.0, 0.0, 0.0);
    assert_error_and_no_effect(&mut ctx, gl::NO_ERROR);
    // No current program.
    ctx.use_program(None);
    ctx.uniform4f(color, 0.0, 0.0, 0.0, 1.0);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.use_program(Some(program));
    assert_error_and_no_effect(&mut ctx, gl::NO_ERROR);
    // A program whose link failed cannot be used.
    let unlinked = ctx.create_program();
    ctx.use_program(Some(unlinked));
    assert_error_and_no_effect(&mut ctx, gl::INVALID_OPERATION);
}

#[test]
fn generate_mipmap_of_an_empty_base_level_is_an_error() {
    // A 0 × 0 base level once made the level count wrap around and the call never returned.
    let Some(mut ctx) = context(4, 4) else { return };
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    for (w, h) in [(0, 0), (4, 0), (0, 4)] {
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
        ctx.generate_mipmap(gl::TEXTURE_2D);
        assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "{w} × {h}");
    }
    assert_clean(&ctx);
}

#[test]
fn renderbuffers_attach_once_bound_and_depth_and_stencil_bits_come_from_their_own_attachment() {
    let Some(mut ctx) = context(2, 2) else { return };
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    let never_bound = ctx.create_renderbuffer();
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::DEPTH_ATTACHMENT,
        gl::RENDERBUFFER,
        Some(never_bound),
    );
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    let colour = ctx.create_renderbuffer();
    ctx.bind_renderbuffer(gl::RENDERBUFFER, Some(colour));
    ctx.renderbuffer_storage(gl::RENDERBUFFER, gl::RGBA8, 2, 2);
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::RENDERBUFFER,
        Some(colour),
    );
    let ds = ctx.create_renderbuffer();
    ctx.bind_renderbuffer(gl::RENDERBUFFER, Some(ds));
    ctx.renderbuffer_storage(gl::RENDERBUFFER, gl::DEPTH24_STENCIL8, 2, 2);
    let bits = |ctx: &mut Context| {
        [gl::DEPTH_BITS, gl::STENCIL_BITS].map(|p| ctx.get_parameter(p).and_then(|v| v.as_int()))
    };
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::DEPTH_ATTACHMENT,
        gl::RENDERBUFFER,
        Some(ds),
    );
    assert_eq!(bits(&mut ctx), [Some(24), Some(0)]);
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::DEPTH_ATTACHMENT,
        gl::RENDERBUFFER,
        None,
    );
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::STENCIL_ATTACHMENT,
        gl::RENDERBUFFER,
        Some(ds),
    );
    assert_eq!(bits(&mut ctx), [Some(0), Some(8)]);
    ctx.framebuffer_renderbuffer(
        gl::FRAMEBUFFER,
        gl::DEPTH_STENCIL_ATTACHMENT,
        gl::RENDERBUFFER,
        Some(ds),
    );
    assert_eq!(bits(&mut ctx), [Some(24), Some(8)]);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
}
