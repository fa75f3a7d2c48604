//! End to end: GLSL ES 3.00 compiled, linked and lowered by the essl front end, drawn by
//! essl-gl — the `ProgramLayout` contract exercised by real lowered modules.

use crate::common;

use common::*;
use essl_gl::{gl, Context, Program};

const W: u32 = 32;
const H: u32 = 32;

const PASS_VS: &str = "#version 300 es
in vec4 a_position;
void main() { gl_Position = a_position; }";

#[test]
fn a_glsl_triangle_with_a_uniform_colour() {
    let Some(mut ctx) = context(W, H) else { return };
    let p = program(
        &mut ctx,
        PASS_VS,
        "#version 300 es
        precision mediump float;
        uniform vec4 u_color;
        out vec4 color;
        void main() { color = u_color; }",
    );
    ctx.use_program(Some(p));
    let loc = ctx.get_attrib_location(p, "a_position");
    assert!(loc >= 0);
    float_attribute(&mut ctx, loc as u32, 2, &[-1.0, -1.0, 1.0, -1.0, -1.0, 1.0]);
    let color = ctx.get_uniform_location(p, "u_color");
    ctx.uniform4f(color, 0.0, 1.0, 0.0, 1.0);
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 3);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_eq!(pixel(&mut ctx, 2, 2), [0, 255, 0, 255]);
    assert_eq!(pixel(&mut ctx, W - 2, H - 2), [0, 0, 0, 255]);
    assert_clean(&ctx);
}

#[test]
fn gl_depth_range_and_frag_coord_follow_gl() {
    let Some(mut ctx) = context(W, H) else { return };
    let p = program(
        &mut ctx,
        PASS_VS,
        "#version 300 es
        precision highp float;
        uniform vec4 u_color;
        out vec4 color;
        void main() { color = vec4(u_color.rgb, gl_FragCoord.y < 8.0 ? 1.0 : 0.0); }",
    );
    ctx.use_program(Some(p));
    let color = ctx.get_uniform_location(p, "u_color");
    ctx.enable(gl::DEPTH_TEST);
    clear_black(&mut ctx);
    // GL clip z: -0.5 is nearer than +0.5 with LESS, whatever the draw order.
    for (z, rgb) in [(-0.5f32, [1.0, 0.0, 0.0]), (0.5, [0.0, 0.0, 1.0])] {
        let data: Vec<f32> = QUAD.chunks(2).flat_map(|c| [c[0], c[1], z]).collect();
        float_attribute(&mut ctx, 0, 3, &data);
        ctx.uniform4f(color, rgb[0], rgb[1], rgb[2], 1.0);
        ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    }
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    // gl_FragCoord.y counts from the bottom: rows 0..8 are opaque.
    assert_eq!(pixel(&mut ctx, 4, 2), [255, 0, 0, 255]);
    assert_eq!(pixel(&mut ctx, 4, 20), [255, 0, 0, 0]);
    assert_clean(&ctx);
}

#[test]
fn a_glsl_texture_on_unit_one() {
    let Some(mut ctx) = context(W, H) else { return };
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
    let pos = ctx_attrib(&mut ctx, p, "a_position");
    float_attribute(&mut ctx, pos, 2, &QUAD);
    let tex = ctx.create_texture();
    ctx.active_texture(gl::TEXTURE1);
    ctx.bind_texture(gl::TEXTURE_2D, Some(tex));
    // Row 0 (t = 0, the bottom) red, row 1 blue.
    let texels = [
        255u8, 0, 0, 255, 255, 0, 0, 255, 0, 0, 255, 255, 0, 0, 255, 255,
    ];
    ctx.tex_image_2d(
        gl::TEXTURE_2D,
        0,
        gl::RGBA8 as i32,
        2,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&texels),
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    let sampler = ctx.get_uniform_location(p, "u_tex");
    ctx.uniform1i(sampler, 1);
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_eq!(pixel(&mut ctx, 4, 4), [255, 0, 0, 255]);
    assert_eq!(pixel(&mut ctx, 4, H - 4), [0, 0, 255, 255]);
    assert_clean(&ctx);
}

fn ctx_attrib(ctx: &mut Context, p: Program, name: &str) -> u32 {
    let loc = ctx.get_attrib_location(p, name);
    assert!(loc >= 0, "{name} is not active");
    loc as u32
}

#[test]
fn a_vec4_attribute_fed_three_floats_gets_w_one() {
    let Some(mut ctx) = context(W, H) else { return };
    let p = program(
        &mut ctx,
        "#version 300 es
        in vec2 a_position;
        in vec4 a_color;
        out vec4 v_color;
        void main() { v_color = a_color; gl_Position = vec4(a_position, 0.0, 1.0); }",
        "#version 300 es
        precision mediump float;
        in vec4 v_color;
        out vec4 color;
        void main() { color = v_color; }",
    );
    ctx.use_program(Some(p));
    let pos = ctx_attrib(&mut ctx, p, "a_position");
    let col = ctx_attrib(&mut ctx, p, "a_color");
    float_attribute(&mut ctx, pos, 2, &QUAD);
    let colours: Vec<f32> = (0..6).flat_map(|_| [1.0, 0.0, 1.0]).collect();
    float_attribute(&mut ctx, col, 3, &colours);
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_eq!(pixel(&mut ctx, W / 2, H / 2), [255, 0, 255, 255]);
    assert_clean(&ctx);
}

#[test]
fn matrices_arrays_and_bind_attrib_location() {
    let Some(mut ctx) = context(W, H) else { return };
    let p = ctx.create_program();
    let vs = ctx.create_shader(gl::VERTEX_SHADER).expect("type");
    ctx.shader_source(
        vs,
        "#version 300 es
        uniform mat4 u_matrix;
        in vec2 a_position;
        void main() { gl_Position = u_matrix * vec4(a_position, 0.0, 1.0); }",
    );
    ctx.compile_shader(vs);
    let fs = ctx.create_shader(gl::FRAGMENT_SHADER).expect("type");
    ctx.shader_source(
        fs,
        "#version 300 es
        precision mediump float;
        uniform float u_weights[3];
        out vec4 color;
        void main() { color = vec4(u_weights[0], u_weights[1], u_weights[2], 1.0); }",
    );
    ctx.compile_shader(fs);
    ctx.attach_shader(p, vs);
    ctx.attach_shader(p, fs);
    ctx.bind_attrib_location(p, 5, "a_position");
    ctx.link_program(p);
    assert!(
        ctx.get_program_link_status(p),
        "{:?}",
        ctx.get_program_info_log(p)
    );
    assert_eq!(ctx.get_attrib_location(p, "a_position"), 5);
    ctx.use_program(Some(p));
    float_attribute(&mut ctx, 5, 2, &QUAD);
    // Scale by a half: only the middle is covered.
    let m = ctx.get_uniform_location(p, "u_matrix");
    #[rustfmt::skip]
    let half = [0.5, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
    ctx.uniform_matrix4fv(m, false, &half);
    let weights = ctx.get_uniform_location(p, "u_weights");
    ctx.uniform1fv(weights, &[1.0, 0.0, 1.0]);
    let second = ctx.get_uniform_location(p, "u_weights[1]");
    ctx.uniform1f(second, 1.0);
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_eq!(pixel(&mut ctx, W / 2, H / 2), [255; 4]);
    assert_eq!(pixel(&mut ctx, 1, 1), [0, 0, 0, 255]);
    assert_clean(&ctx);
}

#[test]
fn compile_and_link_failures_are_reported() {
    let Some(mut ctx) = context(W, H) else { return };
    let vs = ctx.create_shader(gl::VERTEX_SHADER).expect("type");
    ctx.shader_source(
        vs,
        "#version 300 es\nvoid main() { gl_Position = vec4(undeclared); }",
    );
    ctx.compile_shader(vs);
    assert!(!ctx.get_shader_compile_status(vs));
    let log = ctx.get_shader_info_log(vs).unwrap_or_default();
    assert!(log.starts_with("ERROR: 0:2:"), "{log}");
    let fs = ctx.create_shader(gl::FRAGMENT_SHADER).expect("type");
    ctx.shader_source(
        fs,
        "#version 300 es\nprecision mediump float;\nout vec4 c;\nvoid main() { c = vec4(1.0); }",
    );
    ctx.compile_shader(fs);
    let p = ctx.create_program();
    ctx.attach_shader(p, vs);
    ctx.attach_shader(p, fs);
    ctx.link_program(p);
    assert!(!ctx.get_program_link_status(p));
    ctx.use_program(Some(p));
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    // Varyings that do not match fail the link, with the front end's log.
    ctx.shader_source(
        vs,
        "#version 300 es\nin vec4 a;\nout vec3 v;\nvoid main() { v = a.xyz; gl_Position = a; }",
    );
    ctx.compile_shader(vs);
    ctx.shader_source(fs, "#version 300 es\nprecision mediump float;\nin vec4 v;\nout vec4 c;\nvoid main() { c = v; }");
    ctx.compile_shader(fs);
    ctx.link_program(p);
    assert!(!ctx.get_program_link_status(p));
    assert!(!ctx.get_program_info_log(p).unwrap_or_default().is_empty());
    assert_clean(&ctx);
}

#[test]
fn narrow_outputs_integer_and_matrix_attributes_sampler_arrays_and_structs() {
    let Some(mut ctx) = context(W, H) else { return };
    let p = program(
        &mut ctx,
        "#version 300 es
        in vec2 a_position;
        in ivec2 a_select;
        in mat2 a_scale;
        flat out ivec2 v_select;
        void main() { v_select = a_select; gl_Position = vec4(a_scale * a_position, 0.0, 1.0); }",
        "#version 300 es
        precision mediump float;
        struct Light { vec3 color; float strength; };
        uniform Light u_light;
        uniform sampler2D u_tex[2];
        flat in ivec2 v_select;
        out vec3 color;
        void main() {
            vec4 t = v_select.x == 1 ? texture(u_tex[1], vec2(0.5)) : texture(u_tex[0], vec2(0.5));
            color = u_light.color * u_light.strength + t.rgb;
        }",
    );
    ctx.use_program(Some(p));
    let pos = ctx_attrib(&mut ctx, p, "a_position");
    let sel = ctx_attrib(&mut ctx, p, "a_select");
    let scale = ctx_attrib(&mut ctx, p, "a_scale");
    float_attribute(&mut ctx, pos, 2, &QUAD);
    let b = ctx.create_buffer();
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(b));
    ctx.buffer_data(gl::ARRAY_BUFFER, &[1i32, 0].repeat(6), gl::STATIC_DRAW);
    ctx.enable_vertex_attrib_array(sel);
    ctx.vertex_attrib_i_pointer(sel, 2, gl::INT, 0, 0);
    // mat2 columns at locations scale and scale + 1, as generic values: identity.
    ctx.vertex_attrib2f(scale, 1.0, 0.0);
    ctx.vertex_attrib2f(scale + 1, 0.0, 1.0);
    let strength = ctx.get_uniform_location(p, "u_light.strength");
    let light_color = ctx.get_uniform_location(p, "u_light.color");
    ctx.uniform1f(strength, 1.0);
    ctx.uniform3f(light_color, 0.0, 0.0, 1.0);
    // u_tex[1] on unit 2 holds red.
    let units = ctx.get_uniform_location(p, "u_tex");
    ctx.uniform1iv(units, &[0, 2]);
    let tex = ctx.create_texture();
    ctx.active_texture(gl::TEXTURE2);
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
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    // A vec3 output is widened with alpha 1.
    assert_eq!(pixel(&mut ctx, W / 2, H / 2), [255, 0, 255, 255]);
    assert_clean(&ctx);
}

#[test]
fn uniform_blocks_read_their_bound_buffer_ranges() {
    let Some(mut ctx) = context(W, H) else { return };
    let p = program(
        &mut ctx,
        PASS_VS,
        "#version 300 es
        precision mediump float;
        uniform Material { vec4 tint; vec4 unused; };
        uniform vec4 u_add;
        out vec4 color;
        void main() { color = tint + u_add; }",
    );
    ctx.use_program(Some(p));
    float_attribute(&mut ctx, 0, 2, &QUAD);
    assert_eq!(
        ctx.get_uniform_location(p, "tint"),
        None,
        "block members have no location"
    );
    let add = ctx.get_uniform_location(p, "u_add");
    ctx.uniform4f(add, 0.0, 0.0, 1.0, 0.0);
    // No buffer at the block's binding point: INVALID_OPERATION, nothing drawn.
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    assert!(all_are(&mut ctx, [0, 0, 0, 255]));
    // A range smaller than the block: INVALID_OPERATION.
    let ubo = ctx.create_buffer();
    let align = ctx.uniform_buffer_offset_alignment() as usize;
    let mut data = vec![0.0f32; align / 4 + 8];
    data[align / 4..align / 4 + 4].copy_from_slice(&[1.0, 0.0, 0.0, 1.0]);
    ctx.bind_buffer(gl::UNIFORM_BUFFER, Some(ubo));
    ctx.buffer_data(gl::UNIFORM_BUFFER, &data, gl::DYNAMIC_DRAW);
    let block = ctx.get_uniform_block_index(p, "Material");
    assert_eq!(block, 0);
    ctx.uniform_block_binding(p, block, 3);
    ctx.bind_buffer_range(gl::UNIFORM_BUFFER, 3, Some(ubo), align as i64, 16);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    assert!(all_are(&mut ctx, [0, 0, 0, 255]));
    // A misaligned range: INVALID_VALUE.
    ctx.bind_buffer_range(gl::UNIFORM_BUFFER, 3, Some(ubo), 4, 32);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    // The whole block: tint red + u_add blue.
    ctx.bind_buffer_range(gl::UNIFORM_BUFFER, 3, Some(ubo), align as i64, 32);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert!(all_are(&mut ctx, [255, 0, 255, 255]));
    // The buffer changes between draws of one batch: each draw sees its contents.
    ctx.enable(gl::SCISSOR_TEST);
    ctx.scissor(0, 0, W as i32 / 2, H as i32);
    ctx.buffer_sub_data(gl::UNIFORM_BUFFER, align as i64, &[0.0f32, 1.0, 0.0, 1.0]);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    ctx.disable(gl::SCISSOR_TEST);
    assert_eq!(pixel(&mut ctx, 2, 2), [0, 255, 255, 255]);
    assert_eq!(pixel(&mut ctx, W - 2, 2), [255, 0, 255, 255]);
    assert_clean(&ctx);
}

/// Draws a full-screen quad whose fragment shader is `fs` (which sees `v_pos` in -1..1).
fn full_screen(ctx: &mut Context, fs: &str) -> Program {
    let p = program(
        ctx,
        "#version 300 es
        in vec2 a_position;
        out vec2 v_pos;
        void main() { v_pos = a_position; gl_Position = vec4(a_position, 0.0, 1.0); }",
        fs,
    );
    ctx.use_program(Some(p));
    let pos = ctx_attrib(ctx, p, "a_position");
    float_attribute(ctx, pos, 2, &QUAD);
    p
}

#[test]
fn cube_maps_select_faces_and_rows_as_gl() {
    let Some(mut ctx) = context(W, H) else { return };
    // Left half samples (1, 0.5, 0) (t = 0.25 on +X: row 0), right half (1, -0.5, 0) (row 1),
    // top rows sample -Z's centre.
    full_screen(
        &mut ctx,
        "#version 300 es
        precision mediump float;
        uniform samplerCube u_cube;
        in vec2 v_pos;
        out vec4 color;
        void main() {
            vec3 d = v_pos.y > 0.5 ? vec3(0.0, 0.0, -1.0) : vec3(1.0, v_pos.x < 0.0 ? 0.5 : -0.5, 0.0);
            color = texture(u_cube, d);
        }",
    );
    let tex = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_CUBE_MAP, Some(tex));
    for face in 0..6u32 {
        let (a, b): ([u8; 4], [u8; 4]) = match face {
            0 => ([255, 0, 0, 255], [0, 255, 0, 255]),
            5 => ([0, 0, 255, 255], [0, 0, 255, 255]),
            _ => ([9, 9, 9, 255], [9, 9, 9, 255]),
        };
        let texels: Vec<u8> = [a, a, b, b].concat();
        ctx.tex_image_2d(
            gl::TEXTURE_CUBE_MAP_POSITIVE_X + face,
            0,
            gl::RGBA as i32,
            2,
            2,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            Some(&texels),
        );
    }
    ctx.tex_parameteri(
        gl::TEXTURE_CUBE_MAP,
        gl::TEXTURE_MIN_FILTER,
        gl::NEAREST as i32,
    );
    ctx.tex_parameteri(
        gl::TEXTURE_CUBE_MAP,
        gl::TEXTURE_MAG_FILTER,
        gl::NEAREST as i32,
    );
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_eq!(
        pixel(&mut ctx, 2, 2),
        [255, 0, 0, 255],
        "+X, t = 0.25: row 0"
    );
    assert_eq!(
        pixel(&mut ctx, W - 2, 2),
        [0, 255, 0, 255],
        "+X, t = 0.75: row 1"
    );
    assert_eq!(pixel(&mut ctx, 2, H - 2), [0, 0, 255, 255], "-Z");
    assert_clean(&ctx);
}

#[test]
fn integer_cube_maps_take_the_face_and_level_a_lookup_selects() {
    let Some(mut ctx) = context(W, H) else { return };
    // Left half: +X at lod -2 (level 0); right half: +X at lod 3 (past the last level, 2);
    // top rows: -Y at level 0.
    full_screen(
        &mut ctx,
        "#version 300 es
        precision mediump float;
        uniform highp isamplerCube u_cube;
        in vec2 v_pos;
        out vec4 color;
        void main() {
            vec3 d = v_pos.y > 0.5 ? vec3(0.0, -1.0, 0.0) : vec3(1.0, 0.0, 0.0);
            float lod = v_pos.y > 0.5 || v_pos.x < 0.0 ? -2.0 : 3.0;
            ivec4 c = textureLod(u_cube, d, lod);
            color = vec4(vec2(c.rg) / 100.0, 0.0, 1.0);
        }",
    );
    let tex = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_CUBE_MAP, Some(tex));
    // Level 0 of face f holds (10 (f + 1), 100); levels 1 and 2 hold (100, 0). Levels are
    // given past level 0 first, as the conformance suite's specification-order page does.
    for level in [1, 2, 0] {
        let side = 4 >> level;
        for face in 0..6i8 {
            let rg: [i8; 2] = if level == 0 {
                [10 * (face + 1), 100]
            } else {
                [100, 0]
            };
            let texels: Vec<i8> = rg.repeat(side * side);
            ctx.tex_image_2d(
                gl::TEXTURE_CUBE_MAP_POSITIVE_X + face as u32,
                level,
                gl::RG8I as i32,
                side as i32,
                side as i32,
                0,
                gl::RG_INTEGER,
                gl::BYTE,
                Some(&texels),
            );
        }
    }
    ctx.tex_parameteri(
        gl::TEXTURE_CUBE_MAP,
        gl::TEXTURE_MIN_FILTER,
        gl::NEAREST_MIPMAP_NEAREST as i32,
    );
    ctx.tex_parameteri(
        gl::TEXTURE_CUBE_MAP,
        gl::TEXTURE_MAG_FILTER,
        gl::NEAREST as i32,
    );
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    let near = |p: [u8; 4], want: [u8; 4]| p.iter().zip(want).all(|(&a, b)| a.abs_diff(b) <= 1);
    let p = pixel(&mut ctx, 2, 2);
    assert!(near(p, [26, 255, 0, 255]), "+X, level 0: {p:?}");
    let p = pixel(&mut ctx, W - 2, 2);
    assert!(
        near(p, [255, 0, 0, 255]),
        "+X, lod 3: the last level: {p:?}"
    );
    let p = pixel(&mut ctx, 2, H - 2);
    assert!(near(p, [102, 255, 0, 255]), "-Y (face 3), level 0: {p:?}");
    assert_clean(&ctx);
}

#[test]
fn array_and_3d_textures() {
    let Some(mut ctx) = context(W, H) else { return };
    full_screen(
        &mut ctx,
        "#version 300 es
        precision mediump float;
        precision mediump sampler2DArray;
        precision mediump sampler3D;
        uniform sampler2DArray u_layers;
        uniform sampler3D u_volume;
        in vec2 v_pos;
        out vec4 color;
        void main() {
            color = v_pos.x < 0.0 ? texture(u_layers, vec3(0.5, 0.5, 1.0)) : texture(u_volume, vec3(0.5, 0.5, 0.75));
        }",
    );
    let p = ctx.get_current_program().expect("in use");
    let layers = ctx.get_uniform_location(p, "u_layers");
    let volume = ctx.get_uniform_location(p, "u_volume");
    ctx.uniform1i(layers, 0);
    ctx.uniform1i(volume, 1);
    let a = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D_ARRAY, Some(a));
    ctx.tex_storage_3d(gl::TEXTURE_2D_ARRAY, 1, gl::RGBA8, 1, 1, 2);
    ctx.tex_sub_image_3d(
        gl::TEXTURE_2D_ARRAY,
        0,
        0,
        0,
        1,
        1,
        1,
        1,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        &[255u8, 0, 0, 255],
    );
    let v = ctx.create_texture();
    ctx.active_texture(gl::TEXTURE1);
    ctx.bind_texture(gl::TEXTURE_3D, Some(v));
    ctx.tex_image_3d(
        gl::TEXTURE_3D,
        0,
        gl::RGBA as i32,
        1,
        1,
        2,
        0,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        Some(&[0u8, 0, 255, 255, 0, 255, 0, 255]),
    );
    ctx.tex_parameteri(gl::TEXTURE_3D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    ctx.tex_parameteri(gl::TEXTURE_3D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    assert_eq!(
        pixel(&mut ctx, 2, 2),
        [255, 0, 0, 255],
        "layer 1 of the array"
    );
    assert_eq!(
        pixel(&mut ctx, W - 2, 2),
        [0, 255, 0, 255],
        "slice 1 of the volume"
    );
    assert_clean(&ctx);
}

#[test]
fn a_shadow_sampler_without_a_depth_texture_draws() {
    let Some(mut ctx) = context(W, H) else { return };
    full_screen(
        &mut ctx,
        "#version 300 es
        precision mediump float;
        precision mediump sampler2DShadow;
        uniform sampler2DShadow u_shadow;
        out vec4 color;
        void main() { color = vec4(texture(u_shadow, vec3(0.5, 0.5, 0.5)), 0.0, 0.0, 1.0); }",
    );
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{:?}", ctx.error_message());
    let p = pixel(&mut ctx, 2, 2);
    assert_eq!(p[3], 255);
    assert_clean(&ctx);
}

#[test]
fn non_square_outer_products_and_scalar_faceforward_and_refract_compute_as_glsl() {
    let Some(mut ctx) = context(W, H) else { return };
    // Uniform inputs keep the values out of constant folding. Each check is a pass/fail bit;
    // green means every one held on the GPU.
    let p = full_screen(
        &mut ctx,
        "#version 300 es
        precision highp float;
        uniform vec2 u_c;
        uniform vec3 u_r;
        uniform float u_one;
        out vec4 color;
        bool near(float a, float b) { return abs(a - b) < 1e-4; }
        void main() {
            mat3x2 m = outerProduct(u_c, u_r);          // column i = c * r[i]
            mat2x3 n = outerProduct(u_r, u_c);
            bool ok = near(m[0][0], 3.0) && near(m[0][1], 6.0) && near(m[2][0], 5.0)
                && near(m[2][1], 10.0) && near(n[1][2], 10.0) && near(n[0][1], 4.0);
            ok = ok && near(faceforward(2.0 * u_one, u_one, -u_one), 2.0)
                && near(faceforward(2.0 * u_one, u_one, u_one), -2.0);
            // refract(I, N, eta) = eta I - (eta N.I + sqrt(k)) N, k = 1 - eta^2 (1 - (N.I)^2)
            float r = refract(-u_one, u_one, 0.5 * u_one);
            ok = ok && near(r, -0.5 - (0.5 * -1.0 + 1.0) * 1.0);
            ok = ok && near(refract(0.5 * u_one, u_one, 4.0 * u_one), 0.0);
            color = ok ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);
        }",
    );
    let c = ctx.get_uniform_location(p, "u_c");
    ctx.uniform2f(c, 1.0, 2.0);
    let r = ctx.get_uniform_location(p, "u_r");
    ctx.uniform3f(r, 3.0, 4.0, 5.0);
    let one = ctx.get_uniform_location(p, "u_one");
    ctx.uniform1f(one, 1.0);
    clear_black(&mut ctx);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(pixel(&mut ctx, W / 2, H / 2), [0, 255, 0, 255]);
    assert_clean(&ctx);
}

#[test]
fn a_texture_bias_is_clamped_to_max_texture_lod_bias() {
    let Some(mut ctx) = context(1, 1) else { return };
    assert_eq!(
        ctx.get_parameter(gl::MAX_TEXTURE_LOD_BIAS),
        Some(essl_gl::Parameter::Float(15.0))
    );
    // Levels of 8192 × 1 down to 1 × 1, level `l` holding the value `l + 1`.
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.tex_storage_2d(gl::TEXTURE_2D, 14, gl::RGBA8, 8192, 1);
    for level in 0..14 {
        let w = 8192 >> level;
        let texels = vec![level as u8 + 1; w * 4];
        ctx.tex_sub_image_2d(
            gl::TEXTURE_2D,
            level,
            0,
            0,
            w as i32,
            1,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            &texels[..],
        );
    }
    ctx.tex_parameteri(
        gl::TEXTURE_2D,
        gl::TEXTURE_MIN_FILTER,
        gl::NEAREST_MIPMAP_NEAREST as i32,
    );
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
    // One pixel spans 1/16 of a texel: level -4 before the bias, which is clamped to 15 (WGSL's
    // own clamp, at 15.99, would reach level 12).
    for (bias, level) in [(1.0, 0), (6.0, 2), (15.0, 11), (17.0, 11)] {
        let fs = format!(
            "#version 300 es\nprecision highp float; uniform sampler2D t; out vec4 o;\
             void main() {{ o = texture(t, vec2(gl_FragCoord.x / 131072.0, 0.5), {bias:?}); }}"
        );
        full_screen(&mut ctx, &fs);
        ctx.draw_arrays(gl::TRIANGLES, 0, 6);
        assert_eq!(pixel(&mut ctx, 0, 0)[0], level + 1, "bias {bias}");
    }
    assert_clean(&ctx);
}

#[test]
fn textures_without_alpha_given_no_data_sample_alpha_one() {
    let Some(mut ctx) = context(1, 1) else { return };
    for (internal, format, ty) in [
        (gl::RGB8, gl::RGB, gl::UNSIGNED_BYTE),
        (gl::RGB, gl::RGB, gl::UNSIGNED_BYTE),
        (gl::LUMINANCE, gl::LUMINANCE, gl::UNSIGNED_BYTE),
        (gl::RGB16F, gl::RGB, gl::HALF_FLOAT),
        (gl::RGB32F, gl::RGB, gl::FLOAT),
        (gl::RGBA8, gl::RGBA, gl::UNSIGNED_BYTE),
    ] {
        let t = ctx.create_texture();
        ctx.bind_texture(gl::TEXTURE_2D, Some(t));
        ctx.tex_image_2d(
            gl::TEXTURE_2D,
            0,
            internal as i32,
            2,
            2,
            0,
            format,
            ty,
            None::<&[u8]>,
        );
        ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
        ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
        full_screen(
            &mut ctx,
            "#version 300 es\nprecision highp float; uniform sampler2D t; out vec4 o;\
             void main() { o = texture(t, vec2(0.5)) + vec4(0.0, 0.0, 0.5, 0.0); }",
        );
        ctx.draw_arrays(gl::TRIANGLES, 0, 6);
        let alpha = if internal == gl::RGBA8 { 0 } else { 255 };
        assert_eq!(
            pixel(&mut ctx, 0, 0),
            [0, 0, 128, alpha],
            "0x{internal:04X}"
        );
    }
    assert_clean(&ctx);
}
