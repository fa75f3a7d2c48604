//! Times a 256×256 frame with readback: `cargo run --release -p essl-gl --example frame_time`.
//!
//! Draws `N` small triangles that each set a uniform (a program made from hand-written WGSL
//! in the front end's conventions) and reads the frame back. With `SAME_UNIFORMS=1` the
//! uniform is left alone, which shows what a changed uniform costs per draw.

use essl::program::{ActiveAttribute, ActiveUniform, ProgramLayout, UniformBlock, UniformStorage};
use essl::types::GlType;
use essl_gl::{gl, Context};
use std::time::Instant;

fn layout() -> ProgramLayout {
    let vs = "struct U { u_offset: vec2<f32> }
        @group(0) @binding(0) var<uniform> u: U;
        @vertex fn main(@location(0) a_position: vec2<f32>) -> @builtin(position) vec4<f32> {
            let p = a_position * 0.05 + u.u_offset;
            return vec4(p.x, -p.y, 0.0, 1.0);
        }";
    let fs = "@fragment fn main() -> @location(0) vec4<f32> { return vec4(1.0, 0.5, 0.0, 1.0); }";
    let vertex = naga::front::wgsl::parse_str(vs).expect("valid WGSL");
    let fragment = naga::front::wgsl::parse_str(fs).expect("valid WGSL");
    let mut validator = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    );
    ProgramLayout {
        vertex_info: validator.validate(&vertex).expect("valid module"),
        vertex,
        fragment_info: validator.validate(&fragment).expect("valid module"),
        fragment,
        uniform_block: Some(UniformBlock {
            size: 16,
            internal: Vec::new(),
        }),
        uniforms: vec![ActiveUniform {
            name: "u_offset".into(),
            ty: GlType::FLOAT_VEC2,
            size: 1,
            storage: UniformStorage::Buffer {
                offset: 0,
                array_stride: 16,
                matrix_stride: 0,
            },
        }],
        attributes: vec![ActiveAttribute {
            name: "a_position".into(),
            ty: GlType::FLOAT_VEC2,
            size: 1,
            location: 0,
        }],
        samplers: Vec::new(),
        blocks: Vec::new(),
        fragment_outputs: vec![(0, GlType::FLOAT_VEC4)],
        captured: Vec::new(),
    }
}

fn main() -> Result<(), essl_gl::ContextError> {
    let mut ctx = Context::new(256, 256)?;
    println!("adapter: {}", ctx.adapter_info().name);
    let program = ctx.program_from_layout(layout());
    ctx.use_program(Some(program));
    let offset = ctx.get_uniform_location(program, "u_offset");
    let b = ctx.create_buffer();
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(b));
    ctx.buffer_data(
        gl::ARRAY_BUFFER,
        &[-1.0f32, -1.0, 1.0, -1.0, -1.0, 1.0],
        gl::STATIC_DRAW,
    );
    ctx.enable_vertex_attrib_array(0);
    ctx.vertex_attrib_pointer(0, 2, gl::FLOAT, false, 0, 0);
    for draws in [0u32, 1, 100, 1000] {
        let frames = 50;
        let (mut record, mut total) = (0.0, 0.0);
        for f in 0..frames + 5 {
            let t = Instant::now();
            ctx.clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT);
            for i in 0..draws {
                if std::env::var_os("SAME_UNIFORMS").is_none() {
                    ctx.uniform2f(
                        offset,
                        (i % 10) as f32 * 0.2 - 0.9,
                        (i / 10 % 10) as f32 * 0.2 - 0.9,
                    );
                }
                ctx.draw_arrays(gl::TRIANGLES, 0, 3);
            }
            let r = t.elapsed().as_secs_f64();
            let pixels = ctx.read_pixels_rgba8(0, 0, 256, 256);
            std::hint::black_box(pixels);
            if f >= 5 {
                record += r;
                total += t.elapsed().as_secs_f64();
            }
        }
        let ms = |s: f64| s * 1000.0 / frames as f64;
        println!(
            "{draws:5} draws: {:.3} ms per frame ({:.3} ms recording, {:.3} ms submit + GPU + readback)",
            ms(total),
            ms(record),
            ms(total - record)
        );
    }
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    Ok(())
}
