//! The generated bindings set every kind of uniform right: `shaders/every-uniform.frag` draws
//! green only when each one (structs, arrays of structs, a struct holding an array of structs,
//! `bool`/`bvec`, `uint`, `int` arrays, square and non-square matrices and their arrays, a
//! field named with a Rust keyword, a sampler array) holds the value uploaded here through
//! `Program::upload`, and red when any one differs.

use essl_gl::{gl, Context};
use shader_tests::shaders::every_uniform::{self, blocks, types};

fn context() -> Option<Context> {
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        // Silences a harmless complaint of the Vulkan loader.
        std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
    }
    match Context::new(4, 4) {
        Ok(ctx) => Some(ctx),
        Err(e) => {
            essl_testdata::adapter_missing(&e);
            None
        }
    }
}

fn light(position: [f32; 3], cutoff: f32, on: bool) -> types::Light {
    types::Light {
        position,
        cutoff,
        on,
    }
}

/// The values the fragment shader expects.
fn expected() -> every_uniform::Uniforms {
    every_uniform::Uniforms {
        u_offset: [0.0, 0.0],
        u_flags: [true, false, true],
        u_light: light([1.0, 2.0, 3.0], 0.5, true),
        u_lights: [0.0f32, 1.0, 2.0].map(|f| light([f, f + 0.25, -f], f * 0.125, f != 1.0)),
        u_rig: types::Rig {
            lights: [
                light([0.0; 3], 0.0, false),
                light([7.0, 8.0, 9.0], 0.0, true),
            ],
            warp: [1.0, 2.0, 3.0, 4.0, 5.0, 6.0],
            cells: [-3, 4],
        },
        u_switches: [false, true],
        u_mask: [1, u32::MAX, 3, 4],
        u_counts: [-1, 0, i32::MAX],
        u_turns: [[2.0, 0.0, 0.0, 2.0], [0.0, 1.0, -1.0, 0.0]],
        u_frame: [
            1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0,
        ],
        u_colors: [[0.0; 4], [0.25, 0.5, 0.75, 1.0]],
        r#type: -2.5,
        u_textures: [1, 2],
    }
}

/// The blocks' values the shaders expect.
fn camera() -> blocks::Camera {
    let mut view = [0.0; 16];
    view[0] = 1.0;
    view[5] = 1.0;
    view[10] = 1.0;
    view[15] = 1.0;
    blocks::Camera {
        u_view: view,
        u_eye: [0.0, 0.0, 1.0],
        u_scale: 1.0,
    }
}

fn material() -> blocks::Material {
    blocks::Material {
        key: light([-1.0, -2.0, -3.0], 0.75, true),
        uvs: [[0.5, 1.5], [2.5, 3.5], [4.5, 5.5]],
        basis: [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0],
        bits: [false, true],
        tag: 77,
    }
}

/// Uploads the blocks' bytes to buffers bound at binding points 3 (Camera) and 5 (Material).
fn bind_blocks(
    gl: &mut Context,
    program: &every_uniform::Program,
    c: &blocks::Camera,
    m: &blocks::Material,
) {
    for (name, binding, bytes) in [
        (blocks::Camera::NAME, 3, c.to_std140()),
        (blocks::Material::NAME, 5, m.to_std140()),
    ] {
        let buffer = gl.create_buffer();
        gl.bind_buffer(gl::UNIFORM_BUFFER, Some(buffer));
        gl.buffer_data(gl::UNIFORM_BUFFER, &bytes, gl::STATIC_DRAW);
        gl.bind_buffer_base(gl::UNIFORM_BUFFER, binding, Some(buffer));
        let index = gl.get_uniform_block_index(program.program, name);
        gl.uniform_block_binding(program.program, index, binding);
    }
}

/// Draws with `uniforms` and returns the centre pixel.
fn draw(
    gl: &mut Context,
    program: &every_uniform::Program,
    u: &every_uniform::Uniforms,
) -> [u8; 4] {
    program.upload(gl, u);
    gl.clear(gl::COLOR_BUFFER_BIT);
    gl.draw_arrays(gl::TRIANGLES, 0, 3);
    let mut px = [0u8; 4];
    gl.read_pixels(2, 2, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, &mut px);
    assert_eq!(gl.get_error(), gl::NO_ERROR, "{:?}", gl.error_message());
    px
}

#[test]
fn every_kind_of_uniform_arrives() {
    let Some(mut ctx) = context() else { return };
    let gl = &mut ctx;
    let program = every_uniform::Program::new(gl).unwrap_or_else(|e| panic!("{e}"));
    // A red texel on unit 1 and a green one on unit 2, for `u_textures = [1, 2]`.
    for (unit, texel) in [(1, [255u8, 0, 0, 255]), (2, [0, 255, 0, 255])] {
        let t = gl.create_texture();
        gl.active_texture(gl::TEXTURE0 + unit);
        gl.bind_texture(gl::TEXTURE_2D, Some(t));
        gl.tex_image_2d(
            gl::TEXTURE_2D,
            0,
            gl::RGBA8 as i32,
            1,
            1,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            Some(&texel),
        );
        gl.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    }
    assert_eq!(every_uniform::UNIFORM_BLOCKS, ["Camera", "Material"]);
    bind_blocks(gl, &program, &camera(), &material());
    let green = [0, 255, 0, 255];
    let red = [255, 0, 0, 255];
    assert_eq!(draw(gl, &program, &expected()), green);

    // Each change below reaches the shader (the test can fail), and the next upload repairs it.
    type Change = (&'static str, fn(&mut every_uniform::Uniforms));
    let changes: [Change; 12] = [
        ("struct member", |u| u.u_light.cutoff = 0.25),
        ("bool in an array of structs", |u| u.u_lights[1].on = true),
        ("nested struct array", |u| {
            u.u_rig.lights[1].position[2] = 0.0
        }),
        ("non-square matrix in a struct", |u| u.u_rig.warp[5] = 0.0),
        ("ivec2 in a struct", |u| u.u_rig.cells[0] = 3),
        ("bvec3", |u| u.u_flags[1] = true),
        ("bool array", |u| u.u_switches[0] = true),
        ("uvec4", |u| u.u_mask[1] = 2),
        ("int array's last element", |u| u.u_counts[2] = 0),
        ("matrix array", |u| u.u_turns[1][2] = 1.0),
        ("keyword-named float", |u| u.r#type = 2.5),
        ("sampler units", |u| u.u_textures = [2, 1]),
    ];
    for (what, change) in changes {
        let mut u = expected();
        change(&mut u);
        assert_eq!(draw(gl, &program, &u), red, "{what}");
        assert_eq!(draw(gl, &program, &expected()), green, "after {what}");
    }
    // The blocks' bytes: each change below reaches the shader, through std140 offsets.
    type BlockChange = (&'static str, fn(&mut blocks::Material));
    let block_changes: [BlockChange; 5] = [
        ("struct member in a block", |m| m.key.cutoff = 0.5),
        ("array element in a block", |m| m.uvs[2][1] = 0.0),
        ("mat3 column in a block", |m| m.basis[4] = 0.0),
        ("bvec2 in a block", |m| m.bits = [true, true]),
        ("uint after a bvec2", |m| m.tag = 78),
    ];
    for (what, change) in block_changes {
        let mut m = material();
        change(&mut m);
        bind_blocks(gl, &program, &camera(), &m);
        assert_eq!(draw(gl, &program, &expected()), red, "{what}");
    }
    let mut c = camera();
    c.u_eye[2] = 5.0; // z = 4 > w: clipped
    bind_blocks(gl, &program, &c, &material());
    assert_eq!(
        draw(gl, &program, &expected()),
        [0, 0, 0, 0],
        "the vertex stage's block"
    );
    bind_blocks(gl, &program, &camera(), &material());
    assert_eq!(draw(gl, &program, &expected()), green);

    // The vertex-only uniform moves the triangle off the sampled pixel.
    let mut u = expected();
    u.u_offset = [-10.0, 0.0];
    assert_eq!(draw(gl, &program, &u), [0, 0, 0, 0]);
}

#[test]
fn zero_is_what_a_fresh_program_holds() {
    let u = every_uniform::Uniforms::default();
    assert_eq!(u, every_uniform::Uniforms::ZERO);
    assert_eq!(u.u_rig.lights[1], types::Light::ZERO);
    assert_eq!(every_uniform::ATTRIBUTES, &[] as &[(&str, u32)]);
    assert_eq!(every_uniform::UNIFORM_NAMES.len(), 30);
    assert_eq!(every_uniform::UNIFORM_NAMES[20], "u_rig.warp");
    assert_eq!(blocks::Camera::SIZE, 80);
    assert_eq!(blocks::Material::SIZE, 144);
    // std140: `uvs[1]` at 32 + 16, `basis` column 1 at 80 + 16, `tag` at 136.
    let bytes = material().to_std140();
    let f32_at = |o: usize| f32::from_ne_bytes(bytes[o..o + 4].try_into().unwrap());
    assert_eq!((f32_at(48), f32_at(52)), (2.5, 3.5));
    assert_eq!((f32_at(96), f32_at(104)), (4.0, 6.0));
    assert_eq!(u32::from_ne_bytes(bytes[136..140].try_into().unwrap()), 77);
}

/// `shaders/match.*` uses names that Rust reserves or that the bindings use themselves; its
/// module compiles (this file would not otherwise) and works on a context.
#[test]
fn odd_names_link_and_upload() {
    use shader_tests::shaders::match_;
    let Some(mut ctx) = context() else { return };
    let gl = &mut ctx;
    let program = match_::Program::new(gl).unwrap_or_else(|e| panic!("{e}"));
    let mut u = match_::Uniforms::ZERO;
    u.self_.r#impl = 2.0;
    u.self_.Self_ = 3;
    u.u_anonymous.r#mod = 1.0;
    u.u_anonymous.ZERO = true;
    u.u_fragmentLight.r#loop = 0.5;
    u.gl = 1.0;
    program.upload(gl, &u);
    assert_eq!(gl.get_error(), gl::NO_ERROR, "{:?}", gl.error_message());
    assert_eq!(match_::attributes::r#type, 0);
    assert_eq!(
        gl.get_attrib_location(program.program, "a_uv"),
        match_::attributes::a_uv as i32
    );
    assert_eq!(match_::UNIFORM_NAMES[0], "self.impl");
}
