//! The seeds' program flow, in Rust, on essl-gl:
//!
//! ```text
//! cargo run -p essl-gl --example spot_light [-- OUT.png]
//! ```
//!
//! Article 002 builds its program with `createProgram` and `compileShader` (checking
//! `getShaderParameter(COMPILE_STATUS)`, printing `getShaderInfoLog`, checking
//! `getProgramParameter(LINK_STATUS)`); article 001 looks its spot-light uniforms up and sets
//! the limits with `gl.uniform1f(limitLocation, Math.cos(limit))`. Both are ported here line
//! for line, with the WebGL calls in snake_case. They draw article 000's smooth spot light
//! (`shaders-glsl/spot-smooth-nbsp.fixed.*`: the article's shader with its two missing `;`
//! and its no-break spaces fixed) on a grid plane, as the `spot-smooth` scene does, and write
//! the frame as a PNG (default `spot_light.png`).
//!
//! Then the same flow is given the shader **verbatim** from article 000
//! (`shaders-glsl/spot-smooth-nbsp.frag`): `compileShader` prints the info log (the no-break
//! space on the `#version` line is an unexpected token, as in Chromium) and `createProgram`
//! fails.

use essl_gl::{gl, Context, Parameter, Program, Shader};
use essl_scene::{Mat4, Mesh, RgbaImage, Stream};

/// The vertex shader of the webgl2fundamentals spot-light lesson.
const VERTEX_SHADER_SOURCE: &str =
    include_str!("../../../shaders-glsl/spot-smooth-nbsp.fixed.vert");
/// Article 000's fragment shader, corrected.
const FRAGMENT_SHADER_SOURCE: &str =
    include_str!("../../../shaders-glsl/spot-smooth-nbsp.fixed.frag");
/// Article 000's fragment shader as printed (U+00A0 spaces, two `;` missing).
const SEED_FRAGMENT_SHADER_SOURCE: &str =
    include_str!("../../../shaders-glsl/spot-smooth-nbsp.frag");

const WIDTH: u32 = 256;
const HEIGHT: u32 = 256;

/// Article 002's `PROGRAM_TYPE`.
enum ProgramType {
    Vertex,
    Fragment,
}

/// Article 002's `compileShader`: compiles the vertex or fragment shader; on failure prints
/// the info log (`console.error`) and returns `None` (`null`).
fn compile_shader(gl: &mut Context, ty: ProgramType, source: &str) -> Option<Shader> {
    let shader = match ty {
        ProgramType::Vertex => gl.create_shader(gl::VERTEX_SHADER),
        ProgramType::Fragment => gl.create_shader(gl::FRAGMENT_SHADER),
    };

    let shader = shader?; // if (!shader) return;

    gl.shader_source(shader, source);
    gl.compile_shader(shader);

    if gl.get_shader_parameter(shader, gl::COMPILE_STATUS) != Some(Parameter::Bool(true)) {
        eprint!("{}", gl.get_shader_info_log(shader).unwrap_or_default());
        return None;
    }

    Some(shader)
}

/// Article 002's `createProgram`: a program made up of a vertex shader and a fragment shader,
/// linked and in use. Its `throw`s are `Err`s, with the article's messages.
fn create_program(
    gl: &mut Context,
    vertex_shader_source: &str,
    fragment_shader_source: &str,
) -> Result<Program, &'static str> {
    // Obtain the shaders
    let vertex_shader = compile_shader(gl, ProgramType::Vertex, vertex_shader_source);
    let fragment_shader = compile_shader(gl, ProgramType::Fragment, fragment_shader_source);

    // Create a program
    let program = gl.create_program();
    let (Some(vertex_shader), Some(fragment_shader)) = (vertex_shader, fragment_shader) else {
        return Err("Could no create program"); // sic
    };

    // Attach the shaders to this program
    gl.attach_shader(program, vertex_shader);
    gl.attach_shader(program, fragment_shader);
    gl.link_program(program);

    if gl.get_program_parameter(program, gl::LINK_STATUS) != Some(Parameter::Bool(true)) {
        return Err("Could not initialize shaders");
    }

    // Use this program instance
    gl.use_program(Some(program));

    Ok(program)
}

/// webgl2fundamentals' `degToRad`.
fn deg_to_rad(d: f64) -> f64 {
    d * std::f64::consts::PI / 180.0
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "spot_light.png".into());
    let gl = &mut Context::new(WIDTH, HEIGHT)?;
    println!("adapter: {}", gl.adapter_info().name);

    // Article 002's initProgram (with this scene's clear colour and culling).
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.enable(gl::DEPTH_TEST);
    gl.enable(gl::CULL_FACE);
    let program = create_program(gl, VERTEX_SHADER_SOURCE, FRAGMENT_SHADER_SOURCE)?;

    // The geometry: a 200×200 plane of 64×64 cells facing +y, one buffer per attribute.
    let plane = Mesh::grid(200.0, 64);
    let vao = gl.create_vertex_array();
    gl.bind_vertex_array(Some(vao));
    for (name, stream) in [
        ("a_position", Stream::Position),
        ("a_normal", Stream::Normal),
    ] {
        let location = gl.get_attrib_location(program, name);
        let buffer = gl.create_buffer();
        gl.bind_buffer(gl::ARRAY_BUFFER, Some(buffer));
        let data = plane.stream_f32(stream).expect("a grid has every stream");
        gl.buffer_data(gl::ARRAY_BUFFER, &data, gl::STATIC_DRAW);
        gl.enable_vertex_attrib_array(location as u32);
        gl.vertex_attrib_pointer(location as u32, 3, gl::FLOAT, false, 0, 0);
    }
    let indices: Vec<u16> = plane.indices.iter().flatten().map(|&i| i as u16).collect();
    let index_buffer = gl.create_buffer();
    gl.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, Some(index_buffer));
    gl.buffer_data(gl::ELEMENT_ARRAY_BUFFER, &indices, gl::STATIC_DRAW);

    // The camera and the matrices of the lesson (float64, rounded once when uploaded).
    let eye = [0.0, 140.0, 70.0];
    let world = Mat4::IDENTITY;
    let view = Mat4::look_at(eye, [0.0, 0.0, 0.0], [0.0, 1.0, 0.0])?;
    let projection = Mat4::perspective(60.0, WIDTH as f64 / HEIGHT as f64, 1.0, 2000.0);
    let world_view_projection = projection.mul(&view).mul(&world);
    let world_inverse_transpose = world.inverse("world")?.transpose();

    let world_view_projection_location = gl.get_uniform_location(program, "u_worldViewProjection");
    let world_location = gl.get_uniform_location(program, "u_world");
    let world_inverse_transpose_location =
        gl.get_uniform_location(program, "u_worldInverseTranspose");
    let light_world_position_location = gl.get_uniform_location(program, "u_lightWorldPosition");
    let view_world_position_location = gl.get_uniform_location(program, "u_viewWorldPosition");
    let color_location = gl.get_uniform_location(program, "u_color");
    let shininess_location = gl.get_uniform_location(program, "u_shininess");
    let light_color_location = gl.get_uniform_location(program, "u_lightColor");
    let specular_color_location = gl.get_uniform_location(program, "u_specularColor");
    gl.uniform_matrix4fv(
        world_view_projection_location,
        false,
        &world_view_projection.as_f32(),
    );
    gl.uniform_matrix4fv(world_location, false, &world.as_f32());
    gl.uniform_matrix4fv(
        world_inverse_transpose_location,
        false,
        &world_inverse_transpose.as_f32(),
    );
    gl.uniform3fv(light_world_position_location, &[0.0, 100.0, 0.0]);
    gl.uniform3fv(view_world_position_location, &eye.map(|v| v as f32));
    gl.uniform4fv(color_location, &[0.2, 1.0, 0.2, 1.0]);
    gl.uniform1f(shininess_location, 150.0);
    gl.uniform3fv(light_color_location, &[1.0, 0.6, 0.6]);
    gl.uniform3fv(specular_color_location, &[1.0, 0.2, 0.2]);

    // Article 001: the spot light's direction and its limits, looked up and set. The light
    // points straight down; inside 10° it is full, outside 20° off, smooth in between.
    let light_direction = [0.0f32, -1.0, 0.0];
    let inner_limit = deg_to_rad(10.0);
    let outer_limit = deg_to_rad(20.0);
    let light_direction_location = gl.get_uniform_location(program, "u_lightDirection");
    let inner_limit_location = gl.get_uniform_location(program, "u_innerLimit");
    let outer_limit_location = gl.get_uniform_location(program, "u_outerLimit");
    gl.uniform3fv(light_direction_location, &light_direction);
    gl.uniform1f(inner_limit_location, inner_limit.cos() as f32); // Math.cos(limit)
    gl.uniform1f(outer_limit_location, outer_limit.cos() as f32);

    // Draw, read back (GL's rows start at the bottom) and write the PNG (top row first).
    gl.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
    gl.draw_elements(gl::TRIANGLES, indices.len() as i32, gl::UNSIGNED_SHORT, 0);
    let mut pixels = vec![0u8; (WIDTH * HEIGHT * 4) as usize];
    gl.read_pixels(
        0,
        0,
        WIDTH as i32,
        HEIGHT as i32,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        &mut pixels,
    );
    assert_eq!(gl.get_error(), gl::NO_ERROR, "{:?}", gl.error_message());
    let image = RgbaImage::from_gl_rows(WIDTH, HEIGHT, &pixels)?;
    image.write_png(std::path::Path::new(&out))?;
    println!("wrote {out}");

    // Against Chromium's render of the same scene, when the shared folder is there.
    let reference = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/scenes/reference/spot-smooth.png"
    );
    if let Ok(reference) = RgbaImage::read_png(std::path::Path::new(reference)) {
        let d = essl_scene::compare(&image, &reference, 3)?;
        println!(
            "against Chromium's spot-smooth.png: {:.3}% of pixels within 3/255, {:.3}% identical, mean abs error {:.4}/255",
            d.fraction_within() * 100.0,
            d.identical as f64 / d.pixels as f64 * 100.0,
            d.mean_abs
        );
    }

    // The same flow with article 000's shader exactly as printed.
    println!("\narticle 000's fragment shader, verbatim (shaders-glsl/spot-smooth-nbsp.frag):");
    match create_program(gl, VERTEX_SHADER_SOURCE, SEED_FRAGMENT_SHADER_SOURCE) {
        Ok(_) => println!("it linked (unexpected: Chromium rejects it)"),
        Err(message) => println!("createProgram threw: {message}"),
    }
    Ok(())
}
