//! Renderer-level tests: what WebGL2 programs draw, read back from the framebuffer.

use crate::common;

use common::*;
use essl::program::InternalUniform;
use essl::types::GlType;
use essl_gl::gl;

const W: u32 = 64;
const H: u32 = 64;

#[test]
fn clear_color_reads_back() {
    let Some(mut ctx) = context(W, H) else { return };
    ctx.clear_color(0.25, 0.5, 0.75, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    assert_eq!(pixel(&mut ctx, 0, 0), [64, 128, 191, 255]);
    assert!(all_are(&mut ctx, [64, 128, 191, 255]));
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_clean(&ctx);
}

/// GL converts the clear colour to 8 bits rounding to nearest: 0.3 is 76.500003 → 77 (lavapipe's
/// own conversion gives 76), 0.5 → 128, 0.2 → 51; a scissored (drawn) clear agrees.
#[test]
fn clear_colour_rounds_to_nearest() {
    let Some(mut ctx) = context(4, 4) else { return };
    ctx.clear_color(0.3, 0.5, 0.2, 0.1);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    assert_eq!(pixel(&mut ctx, 0, 0), [77, 128, 51, 26]);
    ctx.clear_color(0.0, 0.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.enable(gl::SCISSOR_TEST);
    ctx.scissor(0, 0, 2, 2);
    ctx.clear_color(0.3, 0.5, 0.2, 0.1);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    assert_eq!(pixel(&mut ctx, 1, 1), [77, 128, 51, 26]);
    assert_eq!(pixel(&mut ctx, 3, 3), [0, 0, 0, 255]);
    assert_clean(&ctx);
}

#[test]
fn triangle_covers_the_lower_left_half() {
    let Some(mut ctx) = context(W, H) else { return };
    let program = ctx.program_from_layout(solid(1.0, 0.0, 0.0));
    assert!(
        ctx.get_program_link_status(program),
        "{:?}",
        ctx.get_program_info_log(program)
    );
    clear_black(&mut ctx);
    ctx.use_program(Some(program));
    // A vec4 input fed 2 floats: z = 0, w = 1.
    float_attribute(&mut ctx, 0, 2, &[-1.0, -1.0, 1.0, -1.0, -1.0, 1.0]);
    ctx.draw_arrays(gl::TRIANGLES, 0, 3);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    let px = all_pixels(&mut ctx);
    for y in 0..H {
        for x in 0..W {
            let p = &px[((y * W + x) * 4) as usize..][..4];
            // Pixel centres strictly below the diagonal x + y = W are inside (row 0 = bottom).
            if x + y + 1 < W {
                assert_eq!(p, [255, 0, 0, 255], "({x}, {y}) should be covered");
            } else if x + y > W {
                assert_eq!(p, [0, 0, 0, 255], "({x}, {y}) should be clear");
            }
        }
    }
    assert_clean(&ctx);
}

/// Two triangles covering the screen at depths `z` (already in 0..1, as the lowering emits).
fn flat_at(ctx: &mut essl_gl::Context, z: f32) -> essl_gl::Buffer {
    let mut data = Vec::new();
    for xy in QUAD.chunks(2) {
        data.extend_from_slice(&[xy[0], xy[1], z]);
    }
    float_attribute(ctx, 0, 3, &data)
}

#[test]
fn depth_test_hides_a_far_triangle_behind_a_near_one() {
    let Some(mut ctx) = context(W, H) else { return };
    let red = ctx.program_from_layout(solid(1.0, 0.0, 0.0));
    let green = ctx.program_from_layout(solid(0.0, 1.0, 0.0));
    ctx.enable(gl::DEPTH_TEST);
    for near_first in [true, false] {
        clear_black(&mut ctx);
        let order = if near_first {
            [(red, 0.25), (green, 0.75)]
        } else {
            [(green, 0.75), (red, 0.25)]
        };
        for (program, z) in order {
            ctx.use_program(Some(program));
            flat_at(&mut ctx, z);
            ctx.draw_arrays(gl::TRIANGLES, 0, 6);
        }
        assert!(
            all_are(&mut ctx, [255, 0, 0, 255]),
            "near (red) wins, near first: {near_first}"
        );
    }
    // Without the test, the last draw wins.
    ctx.disable(gl::DEPTH_TEST);
    ctx.use_program(Some(green));
    flat_at(&mut ctx, 0.75);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert!(all_are(&mut ctx, [0, 255, 0, 255]));
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_clean(&ctx);
}

#[test]
fn counter_clockwise_triangles_are_front_faces() {
    let Some(mut ctx) = context(W, H) else { return };
    let program = ctx.program_from_layout(solid(1.0, 1.0, 1.0));
    ctx.use_program(Some(program));
    let ccw = [-1.0f32, -1.0, 1.0, -1.0, -1.0, 1.0];
    let cw = [-1.0f32, -1.0, -1.0, 1.0, 1.0, -1.0];
    ctx.enable(gl::CULL_FACE);
    let cases = [
        (gl::BACK, gl::CCW, ccw, true),
        (gl::BACK, gl::CCW, cw, false),
        (gl::FRONT, gl::CCW, ccw, false),
        (gl::FRONT, gl::CCW, cw, true),
        (gl::BACK, gl::CW, cw, true),
        (gl::BACK, gl::CW, ccw, false),
        (gl::FRONT_AND_BACK, gl::CCW, ccw, false),
    ];
    for (cull, front, tri, drawn) in cases {
        clear_black(&mut ctx);
        ctx.cull_face(cull);
        ctx.front_face(front);
        float_attribute(&mut ctx, 0, 2, &tri);
        ctx.draw_arrays(gl::TRIANGLES, 0, 3);
        let expect = if drawn { [255; 4] } else { [0, 0, 0, 255] };
        assert_eq!(
            pixel(&mut ctx, 4, 4),
            expect,
            "cull {cull:#x} front {front:#x}"
        );
    }
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_clean(&ctx);
}

/// A program that samples `u_tex` at `a_uv` over a full-screen quad.
fn textured() -> essl::program::ProgramLayout {
    Layout::new(
        "struct Out { @builtin(position) pos: vec4<f32>, @location(0) uv: vec2<f32> }
         @vertex fn main(@location(0) a_position: vec2<f32>, @location(1) a_uv: vec2<f32>) -> Out {
             return Out(gl_clip(vec4(a_position, 0.0, 1.0)), a_uv);
         }",
        "@group(1) @binding(0) var u_tex: texture_2d<f32>;
         @group(1) @binding(1) var u_tex_sampler: sampler;
         @fragment fn main(@location(0) uv: vec2<f32>) -> @location(0) vec4<f32> {
             return textureSample(u_tex, u_tex_sampler, uv);
         }",
    )
    .attribute("a_position", GlType::FLOAT_VEC2, 0)
    .attribute("a_uv", GlType::FLOAT_VEC2, 1)
    .sampler("u_tex", GlType::SAMPLER_2D)
    .build()
}

/// Sets up `textured()` over a full-screen quad with texture coordinates `0..uv_max`.
fn textured_quad(ctx: &mut essl_gl::Context, uv_max: f32) {
    let program = ctx.program_from_layout(textured());
    assert!(
        ctx.get_program_link_status(program),
        "{:?}",
        ctx.get_program_info_log(program)
    );
    ctx.use_program(Some(program));
    float_attribute(ctx, 0, 2, &QUAD);
    let uv: Vec<f32> = QUAD.iter().map(|&c| (c + 1.0) / 2.0 * uv_max).collect();
    float_attribute(ctx, 1, 2, &uv);
}

const CHECKER: [u8; 16] = [
    255, 0, 0, 255, /* */ 0, 255, 0, 255, // row 0 (t = 0): red, green
    0, 0, 255, 255, /* */ 255, 255, 255, 255, // row 1: blue, white
];

#[test]
fn texture_sampled_with_nearest_and_repeat() {
    let Some(mut ctx) = context(W, H) else { return };
    textured_quad(&mut ctx, 2.0);
    let tex = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(tex));
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&CHECKER),
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    // uv 0..2 repeats the 2×2 texture twice: each texel covers 16×16 pixels.
    let q = W / 4;
    for (ty, row) in [
        [255, 0, 0, 255],
        [0, 255, 0, 255],
        [0, 0, 255, 255],
        [255, 255, 255, 255],
    ]
    .chunks(2)
    .enumerate()
    {
        for rep in 0..2 {
            for (tx, &expect) in row.iter().enumerate() {
                let x = (rep * 2 + tx as u32) * q + q / 2;
                let y = (rep * 2 + ty as u32) * q + q / 2;
                assert_eq!(
                    pixel(&mut ctx, x, y),
                    expect,
                    "texel ({tx}, {ty}) at ({x}, {y})"
                );
            }
        }
    }
    assert_clean(&ctx);
}

#[test]
fn incomplete_textures_read_black() {
    let Some(mut ctx) = context(W, H) else { return };
    textured_quad(&mut ctx, 1.0);
    let tex = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(tex));
    let white = [255u8; 16];
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&white),
    );
    ctx.clear_color(0.5, 0.5, 0.5, 0.5);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    // The default MIN_FILTER (NEAREST_MIPMAP_LINEAR) needs levels 1.. too: incomplete.
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert!(all_are(&mut ctx, [0, 0, 0, 255]));
    // generateMipmap completes it.
    ctx.generate_mipmap(gl::TEXTURE_2D);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert!(all_are(&mut ctx, [255; 4]));
    // An unbound unit reads (0, 0, 0, 1) too.
    ctx.bind_texture(gl::TEXTURE_2D, None);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert!(all_are(&mut ctx, [0, 0, 0, 255]));
    // A texture with only level 0 and a non-mipmap filter is complete.
    let tex2 = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(tex2));
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&white),
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::LINEAR as i32);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert!(all_are(&mut ctx, [255; 4]));
    // A level 1 of the wrong size breaks mipmap completeness again.
    ctx.tex_parameteri(
        gl::TEXTURE_2D,
        gl::TEXTURE_MIN_FILTER,
        gl::LINEAR_MIPMAP_LINEAR as i32,
    );
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        1,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&white),
    );
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert!(all_are(&mut ctx, [0, 0, 0, 255]));
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_clean(&ctx);
}

/// A program whose colour is its `vec4` attribute at location 1.
fn attribute_colour() -> essl::program::ProgramLayout {
    Layout::new(
        "struct Out { @builtin(position) pos: vec4<f32>, @location(0) c: vec4<f32> }
         @vertex fn main(@location(0) a_position: vec2<f32>, @location(1) a_color: vec4<f32>) -> Out {
             return Out(gl_clip(vec4(a_position, 0.0, 1.0)), a_color);
         }",
        "@fragment fn main(@location(0) c: vec4<f32>) -> @location(0) vec4<f32> { return c; }",
    )
    .attribute("a_position", GlType::FLOAT_VEC2, 0)
    .attribute("a_color", GlType::FLOAT_VEC4, 1)
    .build()
}

#[test]
fn narrow_attributes_get_gl_defaults() {
    let Some(mut ctx) = context(W, H) else { return };
    let program = ctx.program_from_layout(attribute_colour());
    ctx.use_program(Some(program));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    let colour = ctx.create_buffer();
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(colour));
    ctx.enable_vertex_attrib_array(1);
    let check = |ctx: &mut essl_gl::Context, expect: [u8; 4], what: &str| {
        ctx.clear_color(0.5, 0.5, 0.5, 0.5);
        ctx.clear(gl::COLOR_BUFFER_BIT);
        ctx.draw_arrays(gl::TRIANGLES, 0, 6);
        assert_eq!(
            ctx.get_error(),
            gl::NO_ERROR,
            "{what}: {:?}",
            ctx.error_message()
        );
        assert_eq!(pixel(ctx, W / 2, H / 2), expect, "{what}");
    };
    // 3 floats: w = 1.
    let three: Vec<f32> = (0..6).flat_map(|_| [0.2, 0.4, 0.6]).collect();
    ctx.buffer_data(gl::ARRAY_BUFFER, &three, gl::STATIC_DRAW);
    ctx.vertex_attrib_pointer(1, 3, gl::FLOAT, false, 0, 0);
    check(&mut ctx, [51, 102, 153, 255], "3 floats");
    // 2 floats: z = 0, w = 1.
    ctx.vertex_attrib_pointer(1, 2, gl::FLOAT, false, 12, 0);
    check(&mut ctx, [51, 102, 0, 255], "2 floats");
    // 1 float: y = z = 0, w = 1.
    ctx.vertex_attrib_pointer(1, 1, gl::FLOAT, false, 12, 4);
    check(&mut ctx, [102, 0, 0, 255], "1 float");
    // 3 normalized unsigned bytes (no such wgpu format: read as 4 and patched).
    let bytes: Vec<u8> = (0..6).flat_map(|_| [255u8, 128, 0]).collect();
    ctx.buffer_data(gl::ARRAY_BUFFER, &bytes, gl::STATIC_DRAW);
    ctx.vertex_attrib_pointer(1, 3, gl::UNSIGNED_BYTE, true, 0, 0);
    check(
        &mut ctx,
        [255, 128, 0, 255],
        "3 normalized bytes, stride 3 (re-packed)",
    );
    let padded: Vec<u8> = (0..6).flat_map(|_| [255u8, 128, 0, 7]).collect();
    ctx.buffer_data(gl::ARRAY_BUFFER, &padded, gl::STATIC_DRAW);
    ctx.vertex_attrib_pointer(1, 3, gl::UNSIGNED_BYTE, true, 4, 0);
    check(
        &mut ctx,
        [255, 128, 0, 255],
        "3 normalized bytes, stride 4 (patched)",
    );
    // Unnormalized shorts become floats.
    let shorts: Vec<i16> = (0..6).flat_map(|_| [1i16, 0, 1, 0]).collect();
    ctx.buffer_data(gl::ARRAY_BUFFER, &shorts, gl::STATIC_DRAW);
    ctx.vertex_attrib_pointer(1, 4, gl::SHORT, false, 0, 0);
    check(&mut ctx, [255, 0, 255, 0], "4 shorts");
    // A disabled array reads the generic value.
    ctx.disable_vertex_attrib_array(1);
    ctx.vertex_attrib3f(1, 0.0, 1.0, 0.0);
    check(&mut ctx, [0, 255, 0, 255], "generic vertexAttrib3f");
    assert_clean(&ctx);
}

#[test]
fn indexed_fans_loops_and_byte_indices() {
    let Some(mut ctx) = context(W, H) else { return };
    let program = ctx.program_from_layout(solid(0.0, 0.0, 1.0));
    ctx.use_program(Some(program));
    float_attribute(
        &mut ctx,
        0,
        2,
        &[-1.0, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, 1.0],
    );
    let ib = ctx.create_buffer();
    ctx.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, Some(ib));
    for (ty, data) in [
        (gl::UNSIGNED_BYTE, vec![0u8, 1, 2, 3]),
        (gl::UNSIGNED_SHORT, bytemuck_u16(&[0, 1, 2, 3])),
        (gl::UNSIGNED_INT, bytemuck_u32(&[0, 1, 2, 3])),
    ] {
        ctx.buffer_data(gl::ELEMENT_ARRAY_BUFFER, &data, gl::STATIC_DRAW);
        clear_black(&mut ctx);
        ctx.draw_elements(gl::TRIANGLE_FAN, 4, ty, 0);
        assert!(all_are(&mut ctx, [0, 0, 255, 255]), "fan with type {ty:#x}");
    }
    // Arrays: a fan of 4 covers the screen; a strip too.
    for mode in [gl::TRIANGLE_FAN, gl::TRIANGLE_STRIP] {
        clear_black(&mut ctx);
        if mode == gl::TRIANGLE_STRIP {
            float_attribute(
                &mut ctx,
                0,
                2,
                &[-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0],
            );
        }
        ctx.draw_arrays(mode, 0, 4);
        assert!(all_are(&mut ctx, [0, 0, 255, 255]), "mode {mode:#x}");
    }
    // A line loop around the edges touches the corner pixels.
    float_attribute(
        &mut ctx,
        0,
        2,
        &[-0.9, -0.9, 0.9, -0.9, 0.9, 0.9, -0.9, 0.9],
    );
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::LINE_LOOP, 0, 4);
    let px = all_pixels(&mut ctx);
    let lit = px.chunks_exact(4).filter(|p| p[2] == 255).count();
    assert!(lit > 4 * 50, "line loop drew {lit} pixels");
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_clean(&ctx);
}

fn bytemuck_u16(v: &[u16]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_ne_bytes()).collect()
}

fn bytemuck_u32(v: &[u32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_ne_bytes()).collect()
}

#[test]
fn uniforms_and_framebuffer_height() {
    let Some(mut ctx) = context(W, H) else { return };
    // u_color at 0, u_offset (vec2) at 16, FramebufferHeight at 24.
    let layout = Layout::new(
        "struct U { u_color: vec4<f32>, u_offset: vec2<f32>, height: f32 }
         @group(0) @binding(0) var<uniform> u: U;
         @vertex fn main(@location(0) a_position: vec2<f32>) -> @builtin(position) vec4<f32> {
             return gl_clip(vec4(a_position + u.u_offset, 0.0, 1.0));
         }",
        "struct U { u_color: vec4<f32>, u_offset: vec2<f32>, height: f32 }
         @group(0) @binding(0) var<uniform> u: U;
         @fragment fn main(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
             // Framebuffers store GL's row 0 first, so the API's y is gl_FragCoord.y; the
             // framebuffer height a layout asks for still arrives.
             let gl_y = p.y;
             return vec4(u.u_color.rgb, select(0.0, 1.0, gl_y < 16.0 && u.height == 64.0));
         }",
    )
    .attribute("a_position", GlType::FLOAT_VEC2, 0)
    .uniform("u_color", GlType::FLOAT_VEC4, 1, 0, 16, 0)
    .uniform("u_offset", GlType::FLOAT_VEC2, 1, 16, 16, 0)
    .internal(InternalUniform::FramebufferHeight, 24)
    .block_size(32)
    .build();
    let program = ctx.program_from_layout(layout);
    ctx.use_program(Some(program));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    let color = ctx.get_uniform_location(program, "u_color");
    let offset = ctx.get_uniform_location(program, "u_offset");
    assert!(color.is_some() && offset.is_some());
    assert_eq!(ctx.get_uniform_location(program, "nope"), None);
    clear_black(&mut ctx);
    ctx.uniform4f(color, 1.0, 0.0, 1.0, 1.0);
    ctx.uniform2f(offset, 0.0, 0.0);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    // Uniforms change between draws of one batch: each draw sees its own values.
    ctx.uniform4f(color, 0.0, 1.0, 0.0, 1.0);
    ctx.uniform2f(offset, 1.0, 0.0);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_eq!(pixel(&mut ctx, 8, 8), [255, 0, 255, 255]);
    assert_eq!(
        pixel(&mut ctx, 8, 40),
        [255, 0, 255, 0],
        "alpha 0 above GL row 16"
    );
    assert_eq!(pixel(&mut ctx, 56, 8), [0, 255, 0, 255]);
    // Type mismatch: INVALID_OPERATION, value unchanged.
    ctx.uniform3f(color, 0.0, 0.0, 0.0);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    assert_clean(&ctx);
}

#[test]
fn instancing_with_divisors() {
    let Some(mut ctx) = context(W, H) else { return };
    let layout = Layout::new(
        "@vertex fn main(@location(0) a_position: vec2<f32>, @location(1) a_offset: vec2<f32>) -> @builtin(position) vec4<f32> {
             return gl_clip(vec4(a_position + a_offset, 0.0, 1.0));
         }",
        "@fragment fn main() -> @location(0) vec4<f32> { return vec4(1.0); }",
    )
    .attribute("a_position", GlType::FLOAT_VEC2, 0)
    .attribute("a_offset", GlType::FLOAT_VEC2, 1)
    .build();
    let program = ctx.program_from_layout(layout);
    ctx.use_program(Some(program));
    // A quad covering the bottom-left quarter, moved per instance.
    let quarter: Vec<f32> = QUAD.iter().map(|&c| (c + 1.0) / 2.0 - 1.0).collect();
    float_attribute(&mut ctx, 0, 2, &quarter);
    float_attribute(&mut ctx, 1, 2, &[0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 1.0]);
    for (divisor, instances, lit) in [
        (1, 2, vec![(0, 0), (1, 1)]),
        (2, 4, vec![(0, 0), (1, 1)]),
        (1, 4, vec![(0, 0), (1, 1), (1, 0), (0, 1)]),
    ] {
        ctx.vertex_attrib_divisor(1, divisor);
        clear_black(&mut ctx);
        ctx.draw_arrays_instanced(gl::TRIANGLES, 0, 6, instances);
        assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
        for qx in 0..2 {
            for qy in 0..2 {
                let expect = if lit.contains(&(qx, qy)) {
                    [255; 4]
                } else {
                    [0, 0, 0, 255]
                };
                let p = pixel(&mut ctx, qx * W / 2 + 8, qy * H / 2 + 8);
                assert_eq!(
                    p, expect,
                    "divisor {divisor}, {instances} instances, quarter ({qx}, {qy})"
                );
            }
        }
    }
    // 3 instances with divisor 2 need 2 offsets; 5 with divisor 1 need 5: past the end.
    ctx.vertex_attrib_divisor(1, 1);
    clear_black(&mut ctx);
    ctx.draw_arrays_instanced(gl::TRIANGLES, 0, 6, 5);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    assert!(all_are(&mut ctx, [0, 0, 0, 255]));
    assert_clean(&ctx);
}

#[test]
fn blending_scissor_and_masked_clears() {
    let Some(mut ctx) = context(W, H) else { return };
    let layout = Layout::new(
        "@vertex fn main(@location(0) a_position: vec2<f32>) -> @builtin(position) vec4<f32> { return gl_clip(vec4(a_position, 0.0, 1.0)); }",
        "@fragment fn main() -> @location(0) vec4<f32> { return vec4(1.0, 0.0, 0.0, 0.5); }",
    )
    .attribute("a_position", GlType::FLOAT_VEC2, 0)
    .build();
    let program = ctx.program_from_layout(layout);
    ctx.use_program(Some(program));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    ctx.clear_color(0.0, 0.0, 1.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.enable(gl::BLEND);
    ctx.blend_func(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    let p = pixel(&mut ctx, 1, 1);
    assert!(
        (127..=129).contains(&p[0]) && p[1] == 0 && (126..=128).contains(&p[2]),
        "{p:?}"
    );
    ctx.disable(gl::BLEND);
    // A scissored clear touches only the box (x 0..16, y 0..8 from the bottom).
    ctx.enable(gl::SCISSOR_TEST);
    ctx.scissor(0, 0, 16, 8);
    ctx.clear_color(0.0, 1.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.disable(gl::SCISSOR_TEST);
    assert_eq!(pixel(&mut ctx, 2, 2), [0, 255, 0, 255]);
    assert_eq!(pixel(&mut ctx, 2, 12), p);
    assert_eq!(pixel(&mut ctx, 20, 2), p);
    // A colour-masked clear keeps the masked channels.
    ctx.color_mask(true, false, false, true);
    ctx.clear_color(1.0, 1.0, 1.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.color_mask(true, true, true, true);
    assert_eq!(pixel(&mut ctx, 2, 2), [255, 255, 0, 255]);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_clean(&ctx);
}

#[test]
fn a_deleted_buffer_lives_on_in_a_vertex_array() {
    let Some(mut ctx) = context(W, H) else { return };
    let program = ctx.program_from_layout(solid(1.0, 1.0, 0.0));
    ctx.use_program(Some(program));
    let vao = ctx.create_vertex_array();
    ctx.bind_vertex_array(Some(vao));
    let b = float_attribute(&mut ctx, 0, 2, &QUAD);
    ctx.bind_vertex_array(None);
    ctx.delete_buffer(b);
    assert!(!ctx.is_buffer(b));
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(b));
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "a deleted handle is detected"
    );
    ctx.bind_vertex_array(Some(vao));
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert!(all_are(&mut ctx, [255, 255, 0, 255]));
    assert_clean(&ctx);
}

#[test]
fn read_pixels_follows_gl_rules() {
    let Some(mut ctx) = context(W, H) else { return };
    ctx.clear_color(1.0, 0.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    // Partly outside: the outside part of dst is left alone.
    let mut dst = vec![7u8; 4 * 4];
    ctx.read_pixels(-2, 0, 4, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut dst);
    assert_eq!(&dst[..8], &[7; 8]);
    assert_eq!(&dst[8..], &[255, 0, 0, 255, 255, 0, 0, 255]);
    let mut small = vec![0u8; 3];
    ctx.read_pixels(0, 0, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut small);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.read_pixels(0, 0, 1, 1, gl::RGB, gl::UNSIGNED_BYTE, &mut dst);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.read_pixels(0, 0, -1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut dst);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    ctx.read_pixels(0, 0, 1, 1, 0x1234, gl::UNSIGNED_BYTE, &mut dst);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    assert_clean(&ctx);
}

/// Measures a 256² frame with readback: a clear and a textured quad, then the same plus 100
/// small triangles that each set a uniform (per-draw overhead).
#[test]
fn frame_time_256() {
    let Some(mut ctx) = context(256, 256) else {
        return;
    };
    textured_quad(&mut ctx, 1.0);
    let quad_program = ctx.program_from_layout(textured());
    let tex = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(tex));
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&CHECKER),
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    let small = ctx.program_from_layout(
        Layout::new(
            "struct U { u_offset: vec2<f32> }
             @group(0) @binding(0) var<uniform> u: U;
             @vertex fn main(@location(0) a_position: vec2<f32>) -> @builtin(position) vec4<f32> {
                 return gl_clip(vec4(a_position * 0.05 + u.u_offset, 0.0, 1.0));
             }",
            "@fragment fn main() -> @location(0) vec4<f32> { return vec4(1.0, 0.5, 0.0, 1.0); }",
        )
        .attribute("a_position", GlType::FLOAT_VEC2, 0)
        .uniform("u_offset", GlType::FLOAT_VEC2, 1, 0, 16, 0)
        .block_size(16)
        .build(),
    );
    let offset = ctx.get_uniform_location(small, "u_offset");
    let frame = |ctx: &mut essl_gl::Context, small_draws: u32| {
        ctx.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
        ctx.use_program(Some(quad_program));
        ctx.draw_arrays(gl::TRIANGLES, 0, 6);
        if small_draws > 0 {
            ctx.use_program(Some(small));
            for i in 0..small_draws {
                ctx.uniform2f(
                    offset,
                    (i % 10) as f32 * 0.2 - 0.9,
                    (i / 10) as f32 * 0.2 - 0.9,
                );
                ctx.draw_arrays(gl::TRIANGLES, 0, 3);
            }
        }
        ctx.read_pixels_rgba8(0, 0, 256, 256)
    };
    for _ in 0..5 {
        frame(&mut ctx, 100);
    }
    for small_draws in [0, 100] {
        let n = 50;
        let t = std::time::Instant::now();
        for _ in 0..n {
            frame(&mut ctx, small_draws);
        }
        let ms = t.elapsed().as_secs_f64() * 1000.0 / n as f64;
        eprintln!(
            "256x256 frame, textured quad + {small_draws} small draws + readback: {ms:.3} ms ({})",
            ctx.adapter_info().name
        );
    }
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_clean(&ctx);
}

#[test]
fn updates_between_draws_keep_gl_order() {
    let Some(mut ctx) = context(W, H) else { return };
    // Buffer contents change between two draws of one batch.
    let program = ctx.program_from_layout(solid(1.0, 1.0, 1.0));
    ctx.use_program(Some(program));
    let left: Vec<f32> = QUAD
        .chunks(2)
        .flat_map(|p| [(p[0] - 1.0) / 2.0, p[1]])
        .collect();
    let right: Vec<f32> = QUAD
        .chunks(2)
        .flat_map(|p| [(p[0] + 1.0) / 2.0, p[1]])
        .collect();
    float_attribute(&mut ctx, 0, 2, &left);
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    ctx.buffer_sub_data(gl::ARRAY_BUFFER, 0, &right[..6]);
    ctx.buffer_sub_data(gl::ARRAY_BUFFER, 24, &right[6..]);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert!(all_are(&mut ctx, [255; 4]), "both halves drawn");
    // Texture contents change between two draws of one batch.
    textured_quad(&mut ctx, 1.0);
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
        Some(&[255u8, 0, 0, 255]),
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    clear_black(&mut ctx);
    ctx.enable(gl::SCISSOR_TEST);
    ctx.scissor(0, 0, W as i32 / 2, H as i32);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    ctx.tex_sub_image_2d(
        gl::TEXTURE_2D,
        0,
        0,
        0,
        1,
        1,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        &[0u8, 255, 0, 255],
    );
    ctx.scissor(W as i32 / 2, 0, W as i32 / 2, H as i32);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    ctx.disable(gl::SCISSOR_TEST);
    assert_eq!(
        pixel(&mut ctx, 4, 4),
        [255, 0, 0, 255],
        "the first draw saw the old texel"
    );
    assert_eq!(
        pixel(&mut ctx, W - 4, 4),
        [0, 255, 0, 255],
        "the second draw saw the new texel"
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_clean(&ctx);
}

#[test]
fn the_viewport_counts_from_the_bottom_left() {
    let Some(mut ctx) = context(W, H) else { return };
    let program = ctx.program_from_layout(solid(1.0, 1.0, 1.0));
    ctx.use_program(Some(program));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    clear_black(&mut ctx);
    ctx.viewport(0, 0, W as i32 / 2, H as i32 / 4);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(pixel(&mut ctx, 1, 1), [255; 4]);
    assert_eq!(pixel(&mut ctx, W / 2 - 1, H / 4 - 1), [255; 4]);
    assert_eq!(pixel(&mut ctx, W / 2 + 1, 1), [0, 0, 0, 255]);
    assert_eq!(pixel(&mut ctx, 1, H / 4 + 1), [0, 0, 0, 255]);
    // Partly off-screen viewports are allowed.
    clear_black(&mut ctx);
    ctx.viewport(-(W as i32), -(H as i32), 2 * W as i32, 2 * H as i32);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert!(all_are(&mut ctx, [255; 4]));
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_clean(&ctx);
}

#[test]
fn the_restart_index_splits_lists_too() {
    let Some(mut ctx) = context(W, H) else { return };
    let program = ctx.program_from_layout(solid(1.0, 1.0, 1.0));
    ctx.use_program(Some(program));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    let ib = ctx.create_buffer();
    ctx.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, Some(ib));
    // Triangle 0, then an incomplete one cut by the restart index, then triangle 1.
    ctx.buffer_data(
        gl::ELEMENT_ARRAY_BUFFER,
        &[0u16, 1, 2, 3, 0xFFFF, 3, 4, 5],
        gl::STATIC_DRAW,
    );
    clear_black(&mut ctx);
    ctx.draw_elements(gl::TRIANGLES, 8, gl::UNSIGNED_SHORT, 0);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert!(all_are(&mut ctx, [255; 4]));
    assert_clean(&ctx);
}

/// A context can move to another thread.
#[test]
fn contexts_are_send() {
    fn send<T: Send>() {}
    send::<essl_gl::Context>();
}

#[test]
fn points_are_as_large_as_the_reported_range_allows() {
    let Some(mut ctx) = common::context(32, 32) else {
        return;
    };
    let range = match ctx.get_parameter(gl::ALIASED_POINT_SIZE_RANGE) {
        Some(essl_gl::Parameter::Floats(v)) => v,
        other => panic!("{other:?}"),
    };
    assert_eq!(range[0], 1.0);
    assert!(range[1] >= 1.0);
    // A point of min(max, 8) pixels covers that square, gl_PointCoord running 0 → 1.
    let size = range[1].min(8.0);
    let vs = format!(
        "#version 300 es\nvoid main() {{ gl_Position = vec4(0.0, 0.0, 0.0, 1.0); gl_PointSize = {size:.1}; }}"
    );
    let fs = "#version 300 es\nprecision mediump float; out vec4 c;\
        void main() { c = vec4(gl_PointCoord, 1.0, 1.0); }";
    let p = common::program(&mut ctx, &vs, fs);
    ctx.use_program(Some(p));
    common::clear_black(&mut ctx);
    ctx.draw_arrays(gl::POINTS, 0, 1);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    let lit = (0..32)
        .flat_map(|y| (0..32).map(move |x| (x, y)))
        .filter(|&(x, y)| common::pixel(&mut ctx, x, y)[2] == 255)
        .count();
    assert_eq!(lit, (size as usize).pow(2));
}

#[test]
fn anisotropy_waits_for_its_extension_and_checks_its_range() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    const TEXTURE_MAX_ANISOTROPY_EXT: u32 = 0x84FE;
    const MAX_TEXTURE_MAX_ANISOTROPY_EXT: u32 = 0x84FF;
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.tex_parameterf(gl::TEXTURE_2D, TEXTURE_MAX_ANISOTROPY_EXT, 4.0);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM, "before the extension");
    assert!(ctx.get_parameter(MAX_TEXTURE_MAX_ANISOTROPY_EXT).is_none());
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    assert!(ctx
        .get_extension("EXT_texture_filter_anisotropic")
        .is_some());
    assert_eq!(
        ctx.get_parameter(MAX_TEXTURE_MAX_ANISOTROPY_EXT),
        Some(essl_gl::Parameter::Float(16.0))
    );
    ctx.tex_parameterf(gl::TEXTURE_2D, TEXTURE_MAX_ANISOTROPY_EXT, 0.5);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    ctx.tex_parameterf(gl::TEXTURE_2D, TEXTURE_MAX_ANISOTROPY_EXT, 8.0);
    assert_eq!(
        ctx.get_tex_parameter(gl::TEXTURE_2D, TEXTURE_MAX_ANISOTROPY_EXT),
        Some(essl_gl::Parameter::Float(8.0))
    );
    // A mipmapped, linearly filtered texture with anisotropy samples as the device filters it.
    let level = [255u8; 16];
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&level[..]),
    );
    ctx.generate_mipmap(gl::TEXTURE_2D);
    let mode = gl::LINEAR_MIPMAP_LINEAR as i32;
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, mode);
    let texel = common::draw_quad_pixel(
        &mut ctx,
        "#version 300 es\nin vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }",
        "#version 300 es\nprecision mediump float; uniform sampler2D t; out vec4 c; void main() { c = texture(t, vec2(0.3, 0.7)); }",
    );
    assert_eq!(texel, [255, 255, 255, 255]);
}

#[test]
fn packed_2_10_10_10_attributes_unpack_and_normalize_as_gl() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    let vs = "#version 300 es\nin vec2 p; in vec4 c; out vec4 v;\
        void main() { v = c; gl_Position = vec4(p, 0.0, 1.0); }";
    let fs = "#version 300 es\nprecision highp float; in vec4 v; out vec4 o;\
        void main() { o = vec4(v.x, -v.y, v.z, v.w); }";
    let prog = common::program(&mut ctx, vs, fs);
    ctx.bind_attrib_location(prog, 0, "p");
    ctx.bind_attrib_location(prog, 1, "c");
    ctx.link_program(prog);
    ctx.use_program(Some(prog));
    common::float_attribute(&mut ctx, 0, 2, &common::QUAD);
    // x = 511 → 1, y = −512 → −1 (clamped), z = 0, w = 1: (1, 1, 0, 1) after the shader.
    let field = |v: i32, bits: u32| (v as u32) & ((1 << bits) - 1);
    let word = field(511, 10) | field(-512, 10) << 10 | field(0, 10) << 20 | field(1, 2) << 30;
    let b = ctx.create_buffer();
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(b));
    ctx.buffer_data(gl::ARRAY_BUFFER, &[word; 6], gl::STATIC_DRAW);
    ctx.vertex_attrib_pointer(1, 3, gl::INT_2_10_10_10_REV, true, 0, 0);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "size 3");
    ctx.vertex_attrib_pointer(1, 4, gl::INT_2_10_10_10_REV, true, 0, 0);
    ctx.enable_vertex_attrib_array(1);
    common::clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_eq!(common::pixel(&mut ctx, 1, 1), [255, 255, 0, 255]);
    // Unsigned, not normalized: 1, 0, 0, 1 read as floats (1, −0, 0, 1).
    let word = 1u32 | 1 << 30;
    ctx.buffer_data(gl::ARRAY_BUFFER, &[word; 6], gl::STATIC_DRAW);
    ctx.vertex_attrib_pointer(1, 4, gl::UNSIGNED_INT_2_10_10_10_REV, false, 0, 0);
    common::clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_eq!(common::pixel(&mut ctx, 1, 1), [255, 0, 0, 255]);
}
