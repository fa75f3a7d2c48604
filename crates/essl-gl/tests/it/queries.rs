//! WebGL2's queries: `getShaderParameter`, `getProgramParameter`, `validateProgram` and
//! `getParameter`, with their values and their errors (`INVALID_ENUM` for an unknown pname,
//! `INVALID_VALUE` for a deleted shader or program, `INVALID_OPERATION` for another context's).

use crate::common;

use common::*;
use essl_gl::{gl, Context, Parameter, Program, Shader};

const VS: &str = "#version 300 es
in vec4 a_position;
in vec3 a_normal;
uniform mat4 u_matrix;
out vec3 v_normal;
void main() { v_normal = a_normal; gl_Position = u_matrix * a_position; }";

const FS: &str = "#version 300 es
precision mediump float;
uniform vec4 u_color;
uniform sampler2D u_image;
uniform samplerCube u_sky;
uniform Light { vec3 u_direction; float u_power; };
in vec3 v_normal;
out vec4 color;
void main() {
    color = u_color * texture(u_image, v_normal.xy) * texture(u_sky, v_normal)
        * dot(v_normal, u_direction) * u_power;
}";

fn shader(ctx: &mut Context, ty: u32, src: &str) -> Shader {
    let s = ctx.create_shader(ty).expect("a shader type");
    ctx.shader_source(s, src);
    ctx.compile_shader(s);
    s
}

fn linked(ctx: &mut Context) -> (Program, Shader, Shader) {
    let p = ctx.create_program();
    let vs = shader(ctx, gl::VERTEX_SHADER, VS);
    let fs = shader(ctx, gl::FRAGMENT_SHADER, FS);
    ctx.attach_shader(p, vs);
    ctx.attach_shader(p, fs);
    ctx.link_program(p);
    assert!(
        ctx.get_program_link_status(p),
        "{:?}",
        ctx.get_program_info_log(p)
    );
    (p, vs, fs)
}

/// Asserts the error flag holds `code` (and clears it).
fn expect_error(ctx: &mut Context, code: u32) {
    assert_eq!(
        essl_gl::error_name(ctx.get_error()),
        essl_gl::error_name(code),
        "expected {}",
        essl_gl::error_name(code)
    );
}

#[test]
fn shader_parameters() {
    let Some(mut ctx) = context(8, 8) else { return };
    let vs = shader(&mut ctx, gl::VERTEX_SHADER, VS);
    let q = |ctx: &mut Context, pname| ctx.get_shader_parameter(vs, pname);
    assert_eq!(
        q(&mut ctx, gl::SHADER_TYPE),
        Some(Parameter::Enum(gl::VERTEX_SHADER))
    );
    assert_eq!(q(&mut ctx, gl::COMPILE_STATUS), Some(Parameter::Bool(true)));
    assert_eq!(q(&mut ctx, gl::DELETE_STATUS), Some(Parameter::Bool(false)));
    expect_error(&mut ctx, gl::NO_ERROR);

    let bad = shader(
        &mut ctx,
        gl::FRAGMENT_SHADER,
        "#version 300 es\nvoid main() { x; }",
    );
    assert_eq!(
        ctx.get_shader_parameter(bad, gl::COMPILE_STATUS),
        Some(Parameter::Bool(false))
    );
    assert_eq!(
        ctx.get_shader_parameter(bad, gl::SHADER_TYPE),
        Some(Parameter::Enum(gl::FRAGMENT_SHADER))
    );
    let never = ctx.create_shader(gl::FRAGMENT_SHADER).unwrap();
    assert_eq!(
        ctx.get_shader_parameter(never, gl::COMPILE_STATUS),
        Some(Parameter::Bool(false)),
        "not compiled yet"
    );

    // GL's INFO_LOG_LENGTH and SHADER_SOURCE_LENGTH are not WebGL's; LINK_STATUS is a program's.
    for pname in [0x8B84, 0x8B88, gl::LINK_STATUS, 0] {
        assert_eq!(ctx.get_shader_parameter(vs, pname), None);
        expect_error(&mut ctx, gl::INVALID_ENUM);
    }
    assert_clean(&ctx);
}

#[test]
fn shader_delete_status_and_deleted_shaders() {
    let Some(mut ctx) = context(8, 8) else { return };
    let (p, vs, fs) = linked(&mut ctx);
    // Attached: only marked for deletion, still queryable.
    ctx.delete_shader(vs);
    assert_eq!(
        ctx.get_shader_parameter(vs, gl::DELETE_STATUS),
        Some(Parameter::Bool(true))
    );
    assert_eq!(
        ctx.get_shader_parameter(vs, gl::COMPILE_STATUS),
        Some(Parameter::Bool(true))
    );
    expect_error(&mut ctx, gl::NO_ERROR);
    assert_eq!(
        ctx.get_program_parameter(p, gl::ATTACHED_SHADERS),
        Some(Parameter::Int(2))
    );
    // Detached: gone, INVALID_VALUE (WebGL's rule for shaders and programs).
    ctx.detach_shader(p, vs);
    assert_eq!(
        ctx.get_program_parameter(p, gl::ATTACHED_SHADERS),
        Some(Parameter::Int(1))
    );
    assert_eq!(ctx.get_shader_parameter(vs, gl::DELETE_STATUS), None);
    expect_error(&mut ctx, gl::INVALID_VALUE);
    assert_eq!(ctx.get_shader_info_log(vs), None);
    expect_error(&mut ctx, gl::INVALID_VALUE);
    // A shader that is not attached is freed at once.
    let lone = shader(&mut ctx, gl::VERTEX_SHADER, VS);
    ctx.delete_shader(lone);
    assert_eq!(ctx.get_shader_parameter(lone, gl::SHADER_TYPE), None);
    expect_error(&mut ctx, gl::INVALID_VALUE);
    assert_eq!(
        ctx.get_shader_parameter(fs, gl::DELETE_STATUS),
        Some(Parameter::Bool(false))
    );
}

#[test]
fn program_parameters() {
    let Some(mut ctx) = context(8, 8) else { return };
    let (p, ..) = linked(&mut ctx);
    let q = |ctx: &mut Context, pname| ctx.get_program_parameter(p, pname);
    assert_eq!(q(&mut ctx, gl::LINK_STATUS), Some(Parameter::Bool(true)));
    assert_eq!(q(&mut ctx, gl::DELETE_STATUS), Some(Parameter::Bool(false)));
    assert_eq!(
        q(&mut ctx, gl::VALIDATE_STATUS),
        Some(Parameter::Bool(false))
    );
    assert_eq!(q(&mut ctx, gl::ATTACHED_SHADERS), Some(Parameter::Int(2)));
    // u_matrix, u_color, u_image, u_sky and the block's two members.
    assert_eq!(q(&mut ctx, gl::ACTIVE_UNIFORMS), Some(Parameter::Int(6)));
    assert_eq!(q(&mut ctx, gl::ACTIVE_ATTRIBUTES), Some(Parameter::Int(2)));
    assert_eq!(
        q(&mut ctx, gl::ACTIVE_UNIFORM_BLOCKS),
        Some(Parameter::Int(1))
    );
    assert_eq!(
        q(&mut ctx, gl::TRANSFORM_FEEDBACK_BUFFER_MODE),
        Some(Parameter::Enum(gl::INTERLEAVED_ATTRIBS)),
        "ES 3.0's initial value"
    );
    assert_eq!(
        q(&mut ctx, gl::TRANSFORM_FEEDBACK_VARYINGS),
        Some(Parameter::Int(0))
    );
    expect_error(&mut ctx, gl::NO_ERROR);
    // The counts agree with the enumeration.
    let n = q(&mut ctx, gl::ACTIVE_UNIFORMS).unwrap().as_int().unwrap() as u32;
    assert!(ctx.get_active_uniform(p, n - 1).is_some());
    assert_eq!(ctx.get_active_uniform(p, n), None);
    expect_error(&mut ctx, gl::INVALID_VALUE);

    // COMPILE_STATUS is a shader's; INFO_LOG_LENGTH and ACTIVE_UNIFORM_MAX_LENGTH are not WebGL's.
    for pname in [gl::COMPILE_STATUS, 0x8B84, 0x8B87, 0x1234] {
        assert_eq!(ctx.get_program_parameter(p, pname), None);
        expect_error(&mut ctx, gl::INVALID_ENUM);
    }

    // A program that failed to link has no active lists.
    let broken = ctx.create_program();
    let vs = shader(&mut ctx, gl::VERTEX_SHADER, VS);
    ctx.attach_shader(broken, vs);
    ctx.link_program(broken);
    let q = |ctx: &mut Context, pname| ctx.get_program_parameter(broken, pname);
    assert_eq!(q(&mut ctx, gl::LINK_STATUS), Some(Parameter::Bool(false)));
    assert_eq!(q(&mut ctx, gl::ACTIVE_UNIFORMS), Some(Parameter::Int(0)));
    assert_eq!(q(&mut ctx, gl::ACTIVE_ATTRIBUTES), Some(Parameter::Int(0)));
    assert_eq!(q(&mut ctx, gl::ATTACHED_SHADERS), Some(Parameter::Int(1)));
    expect_error(&mut ctx, gl::NO_ERROR);
    assert_clean(&ctx);
}

#[test]
fn validate_program_checks_link_and_sampler_units() {
    let Some(mut ctx) = context(8, 8) else { return };
    let (p, ..) = linked(&mut ctx);
    ctx.use_program(Some(p));
    // Both samplers read unit 0 at first: a 2D and a cube sampler may not share a unit.
    ctx.validate_program(p);
    assert_eq!(
        ctx.get_program_parameter(p, gl::VALIDATE_STATUS),
        Some(Parameter::Bool(false))
    );
    let log = ctx.get_program_info_log(p).unwrap();
    assert!(log.contains("conflicting types"), "{log}");
    let sky = ctx.get_uniform_location(p, "u_sky");
    ctx.uniform1i(sky, 1);
    ctx.validate_program(p);
    assert_eq!(
        ctx.get_program_parameter(p, gl::VALIDATE_STATUS),
        Some(Parameter::Bool(true))
    );
    assert_eq!(ctx.get_program_info_log(p).as_deref(), Some(""));
    // A new link resets it.
    ctx.link_program(p);
    assert_eq!(
        ctx.get_program_parameter(p, gl::VALIDATE_STATUS),
        Some(Parameter::Bool(false))
    );

    let unlinked = ctx.create_program();
    ctx.validate_program(unlinked);
    assert_eq!(
        ctx.get_program_parameter(unlinked, gl::VALIDATE_STATUS),
        Some(Parameter::Bool(false))
    );
    assert!(ctx
        .get_program_info_log(unlinked)
        .unwrap()
        .contains("not been successfully linked"));
    expect_error(&mut ctx, gl::NO_ERROR);

    ctx.delete_program(unlinked);
    ctx.validate_program(unlinked);
    expect_error(&mut ctx, gl::INVALID_VALUE);
}

#[test]
fn program_delete_status_and_deleted_programs() {
    let Some(mut ctx) = context(8, 8) else { return };
    let (p, vs, fs) = linked(&mut ctx);
    ctx.delete_shader(vs);
    ctx.delete_shader(fs);
    ctx.use_program(Some(p));
    ctx.delete_program(p);
    // Current: marked for deletion, still usable and queryable, shaders still attached.
    assert_eq!(
        ctx.get_program_parameter(p, gl::DELETE_STATUS),
        Some(Parameter::Bool(true))
    );
    assert_eq!(
        ctx.get_program_parameter(p, gl::ATTACHED_SHADERS),
        Some(Parameter::Int(2))
    );
    assert_eq!(
        ctx.get_shader_parameter(vs, gl::DELETE_STATUS),
        Some(Parameter::Bool(true))
    );
    assert_eq!(
        ctx.get_parameter(gl::CURRENT_PROGRAM),
        Some(Parameter::Program(Some(p)))
    );
    expect_error(&mut ctx, gl::NO_ERROR);
    // useProgram refuses a program marked for deletion.
    ctx.use_program(Some(p));
    expect_error(&mut ctx, gl::INVALID_OPERATION);
    // No longer current: freed, with its shaders.
    ctx.use_program(None);
    assert_eq!(ctx.get_program_parameter(p, gl::LINK_STATUS), None);
    expect_error(&mut ctx, gl::INVALID_VALUE);
    assert_eq!(ctx.get_shader_parameter(vs, gl::SHADER_TYPE), None);
    expect_error(&mut ctx, gl::INVALID_VALUE);
    assert_eq!(
        ctx.get_parameter(gl::CURRENT_PROGRAM),
        Some(Parameter::Program(None))
    );
}

#[test]
fn objects_of_another_context_are_invalid_operation() {
    let Some(mut a) = context(8, 8) else { return };
    let Some(mut b) = context(8, 8) else { return };
    let (p, vs, _) = linked(&mut a);
    assert_eq!(b.get_shader_parameter(vs, gl::SHADER_TYPE), None);
    expect_error(&mut b, gl::INVALID_OPERATION);
    assert_eq!(b.get_program_parameter(p, gl::LINK_STATUS), None);
    expect_error(&mut b, gl::INVALID_OPERATION);
    b.validate_program(p);
    expect_error(&mut b, gl::INVALID_OPERATION);
    expect_error(&mut a, gl::NO_ERROR);
}

#[test]
fn get_parameter_state_and_bindings() {
    let Some(mut ctx) = context(64, 32) else {
        return;
    };
    let q = |ctx: &mut Context, pname| ctx.get_parameter(pname).expect("a known pname");
    assert_eq!(
        q(&mut ctx, gl::VIEWPORT),
        Parameter::Ints(vec![0, 0, 64, 32])
    );
    ctx.viewport(1, 2, 30, 20);
    assert_eq!(
        q(&mut ctx, gl::VIEWPORT),
        Parameter::Ints(vec![1, 2, 30, 20])
    );
    assert_eq!(
        q(&mut ctx, gl::SCISSOR_BOX),
        Parameter::Ints(vec![0, 0, 64, 32])
    );
    assert_eq!(q(&mut ctx, gl::DEPTH_TEST), Parameter::Bool(false));
    ctx.enable(gl::DEPTH_TEST);
    assert_eq!(q(&mut ctx, gl::DEPTH_TEST), Parameter::Bool(true));
    assert_eq!(q(&mut ctx, gl::DITHER), Parameter::Bool(true));
    assert_eq!(q(&mut ctx, gl::DEPTH_FUNC), Parameter::Enum(gl::LESS));
    ctx.depth_func(gl::LEQUAL);
    assert_eq!(q(&mut ctx, gl::DEPTH_FUNC), Parameter::Enum(gl::LEQUAL));
    assert_eq!(q(&mut ctx, gl::DEPTH_WRITEMASK), Parameter::Bool(true));
    assert_eq!(q(&mut ctx, gl::DEPTH_CLEAR_VALUE), Parameter::Float(1.0));
    ctx.clear_color(0.25, 0.5, 0.75, 1.0);
    assert_eq!(
        q(&mut ctx, gl::COLOR_CLEAR_VALUE),
        Parameter::Floats(vec![0.25, 0.5, 0.75, 1.0])
    );
    assert_eq!(
        q(&mut ctx, gl::COLOR_WRITEMASK),
        Parameter::Bools(vec![true; 4])
    );
    assert_eq!(q(&mut ctx, gl::CULL_FACE_MODE), Parameter::Enum(gl::BACK));
    assert_eq!(q(&mut ctx, gl::FRONT_FACE), Parameter::Enum(gl::CCW));
    assert_eq!(q(&mut ctx, gl::BLEND_SRC_RGB), Parameter::Enum(gl::ONE));
    assert_eq!(q(&mut ctx, gl::BLEND_DST_ALPHA), Parameter::Enum(gl::ZERO));
    assert_eq!(
        q(&mut ctx, gl::DEPTH_RANGE),
        Parameter::Floats(vec![0.0, 1.0])
    );
    assert_eq!(q(&mut ctx, gl::UNPACK_ALIGNMENT), Parameter::Int(4));
    ctx.pixel_storei(gl::UNPACK_ALIGNMENT, 1);
    assert_eq!(q(&mut ctx, gl::UNPACK_ALIGNMENT), Parameter::Int(1));
    assert_eq!(q(&mut ctx, gl::UNPACK_FLIP_Y_WEBGL), Parameter::Bool(false));

    // Bindings.
    assert_eq!(q(&mut ctx, gl::CURRENT_PROGRAM), Parameter::Program(None));
    assert_eq!(
        q(&mut ctx, gl::ARRAY_BUFFER_BINDING),
        Parameter::Buffer(None)
    );
    let buf = ctx.create_buffer();
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(buf));
    assert_eq!(
        q(&mut ctx, gl::ARRAY_BUFFER_BINDING),
        Parameter::Buffer(Some(buf))
    );
    assert_eq!(
        q(&mut ctx, gl::VERTEX_ARRAY_BINDING),
        Parameter::VertexArray(None)
    );
    let vao = ctx.create_vertex_array();
    ctx.bind_vertex_array(Some(vao));
    assert_eq!(
        q(&mut ctx, gl::VERTEX_ARRAY_BINDING),
        Parameter::VertexArray(Some(vao))
    );
    let ebo = ctx.create_buffer();
    ctx.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, Some(ebo));
    assert_eq!(
        q(&mut ctx, gl::ELEMENT_ARRAY_BUFFER_BINDING),
        Parameter::Buffer(Some(ebo))
    );
    ctx.bind_vertex_array(None);
    assert_eq!(
        q(&mut ctx, gl::ELEMENT_ARRAY_BUFFER_BINDING),
        Parameter::Buffer(None),
        "the element buffer belongs to the vertex array"
    );
    assert_eq!(
        q(&mut ctx, gl::ACTIVE_TEXTURE),
        Parameter::Enum(gl::TEXTURE0)
    );
    let tex = ctx.create_texture();
    ctx.active_texture(gl::TEXTURE3);
    ctx.bind_texture(gl::TEXTURE_2D, Some(tex));
    assert_eq!(
        q(&mut ctx, gl::ACTIVE_TEXTURE),
        Parameter::Enum(gl::TEXTURE3)
    );
    assert_eq!(
        q(&mut ctx, gl::TEXTURE_BINDING_2D),
        Parameter::Texture(Some(tex))
    );
    assert_eq!(
        q(&mut ctx, gl::TEXTURE_BINDING_CUBE_MAP),
        Parameter::Texture(None)
    );
    ctx.active_texture(gl::TEXTURE0);
    assert_eq!(
        q(&mut ctx, gl::TEXTURE_BINDING_2D),
        Parameter::Texture(None)
    );
    assert_eq!(
        q(&mut ctx, gl::FRAMEBUFFER_BINDING),
        Parameter::Framebuffer(None)
    );

    let (p, ..) = linked(&mut ctx);
    ctx.use_program(Some(p));
    assert_eq!(
        q(&mut ctx, gl::CURRENT_PROGRAM),
        Parameter::Program(Some(p))
    );
    expect_error(&mut ctx, gl::NO_ERROR);
    assert_clean(&ctx);
}

#[test]
fn get_parameter_limits_and_strings() {
    let Some(mut ctx) = context(8, 8) else { return };
    let int = |ctx: &mut Context, pname| {
        ctx.get_parameter(pname)
            .and_then(|p| p.as_int())
            .expect("an integer")
    };
    // WebGL2's minimum values.
    assert!(int(&mut ctx, gl::MAX_TEXTURE_SIZE) >= 2048);
    assert!(int(&mut ctx, gl::MAX_CUBE_MAP_TEXTURE_SIZE) >= 2048);
    assert!(int(&mut ctx, gl::MAX_3D_TEXTURE_SIZE) >= 256);
    assert!(int(&mut ctx, gl::MAX_ARRAY_TEXTURE_LAYERS) >= 256);
    assert_eq!(int(&mut ctx, gl::MAX_VERTEX_ATTRIBS), 16);
    assert_eq!(int(&mut ctx, gl::MAX_COMBINED_TEXTURE_IMAGE_UNITS), 32);
    assert!(int(&mut ctx, gl::MAX_TEXTURE_IMAGE_UNITS) >= 16);
    assert!(int(&mut ctx, gl::MAX_VERTEX_UNIFORM_VECTORS) >= 256);
    assert!(int(&mut ctx, gl::MAX_FRAGMENT_UNIFORM_VECTORS) >= 224);
    assert!(int(&mut ctx, gl::MAX_VARYING_VECTORS) >= 15);
    assert_eq!(int(&mut ctx, gl::MAX_UNIFORM_BUFFER_BINDINGS), 72);
    assert!(int(&mut ctx, gl::MAX_UNIFORM_BLOCK_SIZE) >= 16384);
    assert!(int(&mut ctx, gl::UNIFORM_BUFFER_OFFSET_ALIGNMENT) >= 1);
    assert_eq!(int(&mut ctx, gl::DEPTH_BITS), 24);
    assert_eq!(int(&mut ctx, gl::STENCIL_BITS), 0);
    assert_eq!(int(&mut ctx, gl::ALPHA_BITS), 8);
    let max = ctx.get_parameter(gl::MAX_VIEWPORT_DIMS).unwrap();
    assert_eq!(max.as_ints().unwrap().len(), 2);
    let version = ctx.get_parameter(gl::VERSION).unwrap();
    assert!(version.as_str().unwrap().starts_with("WebGL 2.0"));
    let slv = ctx.get_parameter(gl::SHADING_LANGUAGE_VERSION).unwrap();
    assert!(slv.as_str().unwrap().starts_with("WebGL GLSL ES 3.00"));
    expect_error(&mut ctx, gl::NO_ERROR);

    // Unknown pnames, and GL ES enums that are not getParameter's.
    for pname in [0x1234, gl::TEXTURE_2D, gl::COMPILE_STATUS, gl::LINK_STATUS] {
        assert_eq!(ctx.get_parameter(pname), None);
        expect_error(&mut ctx, gl::INVALID_ENUM);
    }
}
