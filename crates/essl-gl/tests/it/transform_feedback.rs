//! Transform feedback: varyings captured into buffers by draws, interleaved and separate,
//! with rasterizer discard, pauses, the primitives-written query and WebGL's errors.

use crate::common;

use common::*;
use essl_gl::{gl, Context, Parameter};

const STEP_VS: &str = "#version 300 es
in vec2 a_pos;
in vec2 a_vel;
out vec2 v_pos;
out vec2 v_vel;
void main() {
    v_pos = a_pos + a_vel;
    v_vel = a_vel * 0.5;
    gl_Position = vec4(v_pos, 0.0, 1.0);
    gl_PointSize = 1.0;
}";

const EMPTY_FS: &str = "#version 300 es
precision mediump float;
out vec4 color;
void main() { color = vec4(1.0); }";

fn linked(ctx: &mut Context, varyings: &[&str], mode: u32) -> essl_gl::Program {
    let p = ctx.create_program();
    for (ty, src) in [
        (gl::VERTEX_SHADER, STEP_VS),
        (gl::FRAGMENT_SHADER, EMPTY_FS),
    ] {
        let s = ctx.create_shader(ty).unwrap();
        ctx.shader_source(s, src);
        ctx.compile_shader(s);
        ctx.attach_shader(p, s);
    }
    ctx.bind_attrib_location(p, 0, "a_pos");
    ctx.bind_attrib_location(p, 1, "a_vel");
    ctx.transform_feedback_varyings(p, varyings, mode);
    ctx.link_program(p);
    assert!(
        ctx.get_program_link_status(p),
        "{:?}",
        ctx.get_program_info_log(p)
    );
    p
}

/// The first `n` floats of `buffer`, read through the generic `TRANSFORM_FEEDBACK_BUFFER`
/// binding: a buffer still at an indexed binding of the bound transform feedback object cannot
/// be read through another target (WebGL 2 §5.1).
fn floats(ctx: &mut Context, buffer: essl_gl::Buffer, n: usize) -> Vec<f32> {
    ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, Some(buffer));
    let mut out = vec![0f32; n];
    ctx.get_buffer_sub_data(gl::TRANSFORM_FEEDBACK_BUFFER, 0, &mut out);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    out
}

#[test]
fn interleaved_varyings_are_captured_vertex_by_vertex() {
    let Some(mut ctx) = context(4, 4) else { return };
    let p = linked(&mut ctx, &["v_pos", "v_vel"], gl::INTERLEAVED_ATTRIBS);
    assert_eq!(
        ctx.get_program_parameter(p, gl::TRANSFORM_FEEDBACK_VARYINGS),
        Some(Parameter::Int(2))
    );
    let info = ctx.get_transform_feedback_varying(p, 1).unwrap();
    assert_eq!(
        (info.name.as_str(), info.ty, info.size),
        ("v_vel", gl::FLOAT_VEC2, 1)
    );
    ctx.use_program(Some(p));
    float_attribute(&mut ctx, 0, 2, &[0.0, 0.0, 1.0, 1.0, -1.0, 0.5]);
    float_attribute(&mut ctx, 1, 2, &[0.1, 0.2, 0.3, 0.4, 0.5, 0.6]);
    let out = ctx.create_buffer();
    ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, Some(out));
    ctx.buffer_data_size(gl::TRANSFORM_FEEDBACK_BUFFER, 3 * 4 * 4, gl::STREAM_COPY);
    ctx.bind_buffer_base(gl::TRANSFORM_FEEDBACK_BUFFER, 0, Some(out));
    let q = ctx.create_query();
    ctx.enable(gl::RASTERIZER_DISCARD);
    ctx.begin_query(gl::TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, q);
    ctx.begin_transform_feedback(gl::POINTS);
    ctx.draw_arrays(gl::POINTS, 0, 3);
    ctx.end_transform_feedback();
    ctx.end_query(gl::TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    ctx.disable(gl::RASTERIZER_DISCARD);
    let message = ctx.error_message();
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{message:?}");
    ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, None);
    let got = floats(&mut ctx, out, 12);
    let want = [
        0.1, 0.2, 0.05, 0.1, //
        1.3, 1.4, 0.15, 0.2, //
        -0.5, 1.1, 0.25, 0.3,
    ];
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < 1e-6, "{got:?}");
    }
    ctx.present();
    assert_eq!(
        ctx.get_query_parameter(q, gl::QUERY_RESULT),
        Some(Parameter::Int(3))
    );
    assert_clean(&ctx);
}

#[test]
fn separate_varyings_go_to_their_own_buffers_and_sessions_append() {
    let Some(mut ctx) = context(4, 4) else { return };
    let p = linked(&mut ctx, &["v_vel", "gl_Position"], gl::SEPARATE_ATTRIBS);
    ctx.use_program(Some(p));
    float_attribute(&mut ctx, 0, 2, &[0.5, -0.5, 0.25, 0.25]);
    float_attribute(&mut ctx, 1, 2, &[0.0, 0.0, 0.2, 0.4]);
    let tf = ctx.create_transform_feedback();
    ctx.bind_transform_feedback(gl::TRANSFORM_FEEDBACK, Some(tf));
    let vel = ctx.create_buffer();
    let pos = ctx.create_buffer();
    for (i, b, size) in [(0, vel, 4 * 2 * 4), (1, pos, 4 * 4 * 4)] {
        ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, Some(b));
        ctx.buffer_data_size(gl::TRANSFORM_FEEDBACK_BUFFER, size, gl::STREAM_COPY);
        ctx.bind_buffer_base(gl::TRANSFORM_FEEDBACK_BUFFER, i, Some(b));
    }
    ctx.begin_transform_feedback(gl::POINTS);
    ctx.draw_arrays(gl::POINTS, 0, 2);
    // Paused: draws are not captured, and a draw of another mode is allowed.
    ctx.pause_transform_feedback();
    ctx.draw_arrays(gl::LINES, 0, 2);
    ctx.resume_transform_feedback();
    ctx.draw_arrays(gl::POINTS, 1, 1);
    // Room for one more vertex only: a draw of two is an error and writes nothing.
    ctx.draw_arrays(gl::POINTS, 0, 2);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.draw_arrays(gl::LINES, 0, 2);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "not the primitive mode"
    );
    ctx.use_program(None);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "program change while active"
    );
    ctx.end_transform_feedback();
    let message = ctx.error_message();
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{message:?}");
    ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, None);
    let v = floats(&mut ctx, vel, 6);
    assert_eq!(v, [0.0, 0.0, 0.1, 0.2, 0.1, 0.2]);
    let g = floats(&mut ctx, pos, 12);
    // gl_Position as GL's: (x, y, 0, 1), whatever the API's clip space.
    assert_eq!(&g[..4], &[0.5, -0.5, 0.0, 1.0]);
    assert_eq!(&g[8..], &[0.45, 0.65, 0.0, 1.0]);
    assert_clean(&ctx);
}

#[test]
fn misuse_is_invalid_operation() {
    let Some(mut ctx) = context(4, 4) else { return };
    ctx.begin_transform_feedback(gl::POINTS);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "no program");
    let p = linked(&mut ctx, &["v_pos"], gl::INTERLEAVED_ATTRIBS);
    ctx.use_program(Some(p));
    ctx.begin_transform_feedback(gl::POINTS);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "no buffer bound");
    ctx.begin_transform_feedback(gl::TRIANGLE_STRIP);
    assert_eq!(ctx.get_error(), gl::INVALID_ENUM);
    ctx.end_transform_feedback();
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "not active");
    // A varying the vertex shader does not write fails the link.
    let q = ctx.create_program();
    let vs = ctx.create_shader(gl::VERTEX_SHADER).unwrap();
    ctx.shader_source(vs, STEP_VS);
    ctx.compile_shader(vs);
    let fs = ctx.create_shader(gl::FRAGMENT_SHADER).unwrap();
    ctx.shader_source(fs, EMPTY_FS);
    ctx.compile_shader(fs);
    ctx.attach_shader(q, vs);
    ctx.attach_shader(q, fs);
    ctx.transform_feedback_varyings(q, &["v_missing"], gl::INTERLEAVED_ATTRIBS);
    ctx.link_program(q);
    assert!(!ctx.get_program_link_status(q));
    assert!(ctx.get_program_info_log(q).unwrap().contains("v_missing"));
    assert_clean(&ctx);
}

#[test]
fn read_pixels_into_a_captured_buffer_keeps_both_writes() {
    // Transform feedback writes the buffer's GPU copy; `readPixels` into it as a
    // PIXEL_PACK_BUFFER then changes 4 bytes in the middle. `getBufferSubData` must see the
    // captured floats around the pixel, and the pixel.
    let Some(mut ctx) = context(4, 4) else { return };
    let p = linked(&mut ctx, &["v_pos"], gl::INTERLEAVED_ATTRIBS);
    ctx.use_program(Some(p));
    float_attribute(&mut ctx, 0, 2, &[0.0, 0.0, 1.0, 1.0, -1.0, 0.5]);
    float_attribute(&mut ctx, 1, 2, &[0.1, 0.2, 0.3, 0.4, 0.5, 0.6]);
    let out = ctx.create_buffer();
    ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, Some(out));
    ctx.buffer_data_size(gl::TRANSFORM_FEEDBACK_BUFFER, 3 * 2 * 4, gl::STREAM_READ);
    ctx.bind_buffer_base(gl::TRANSFORM_FEEDBACK_BUFFER, 0, Some(out));
    ctx.enable(gl::RASTERIZER_DISCARD);
    ctx.begin_transform_feedback(gl::POINTS);
    ctx.draw_arrays(gl::POINTS, 0, 3);
    ctx.end_transform_feedback();
    ctx.disable(gl::RASTERIZER_DISCARD);
    ctx.bind_buffer_base(gl::TRANSFORM_FEEDBACK_BUFFER, 0, None);
    ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, None);

    ctx.clear_color(1.0, 0.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.bind_buffer(gl::PIXEL_PACK_BUFFER, Some(out));
    ctx.read_pixels_to_buffer(0, 0, 1, 1, gl::RGBA, gl::UNSIGNED_BYTE, 8);
    let message = ctx.error_message();
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{message:?}");

    let mut got = [0f32; 6];
    ctx.get_buffer_sub_data(gl::PIXEL_PACK_BUFFER, 0, &mut got);
    let pixel = got[2].to_ne_bytes();
    assert_eq!(pixel, [255, 0, 0, 255], "the pixel read into the buffer");
    let captured = [got[0], got[1], got[3], got[4], got[5]];
    let want = [0.1, 0.2, 1.4, -0.5, 1.1];
    for (g, w) in captured.iter().zip(want) {
        assert!((g - w).abs() < 1e-6, "the captured floats: {got:?}");
    }
    assert_clean(&ctx);
}

const OFFSET_VS: &str = "#version 300 es
layout(location = 0) in vec2 a_pos;
layout(location = 1) in vec2 a_off;
void main() {
    gl_Position = vec4(a_pos + a_off, 0.0, 1.0);
    gl_PointSize = 1.0;
}";

#[test]
fn a_draw_that_reads_a_captured_buffer_keeps_its_other_buffers_contents() {
    // The second attribute reads a buffer transform feedback wrote, through a copy made on
    // the CPU (a divisor above 1): bringing the captured bytes back submits the batch. The
    // first attribute's buffer, bound before that, then changes for the next draw: the first
    // draw must still see its old contents.
    let Some(mut ctx) = context(4, 4) else { return };
    let p = linked(&mut ctx, &["v_pos"], gl::INTERLEAVED_ATTRIBS);
    ctx.use_program(Some(p));
    float_attribute(&mut ctx, 0, 2, &[0.0, 0.0]);
    float_attribute(&mut ctx, 1, 2, &[0.0, 0.0]);
    let captured = ctx.create_buffer();
    ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, Some(captured));
    ctx.buffer_data_size(gl::TRANSFORM_FEEDBACK_BUFFER, 2 * 4, gl::STREAM_COPY);
    ctx.bind_buffer_base(gl::TRANSFORM_FEEDBACK_BUFFER, 0, Some(captured));
    ctx.enable(gl::RASTERIZER_DISCARD);
    ctx.begin_transform_feedback(gl::POINTS);
    ctx.draw_arrays(gl::POINTS, 0, 1);
    ctx.end_transform_feedback();
    ctx.disable(gl::RASTERIZER_DISCARD);
    ctx.bind_buffer_base(gl::TRANSFORM_FEEDBACK_BUFFER, 0, None);
    ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, None);

    let draw = program(&mut ctx, OFFSET_VS, EMPTY_FS);
    ctx.use_program(Some(draw));
    clear_black(&mut ctx);
    let positions = float_attribute(&mut ctx, 0, 2, &[-0.75, -0.75]);
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(captured));
    ctx.vertex_attrib_pointer(1, 2, gl::FLOAT, false, 0, 0);
    ctx.vertex_attrib_divisor(1, 2);
    ctx.draw_arrays_instanced(gl::POINTS, 0, 1, 1);
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(positions));
    ctx.buffer_sub_data(gl::ARRAY_BUFFER, 0, &[0.75f32, 0.75]);
    ctx.draw_arrays_instanced(gl::POINTS, 0, 1, 1);
    let message = ctx.error_message();
    assert_eq!(ctx.get_error(), gl::NO_ERROR, "{message:?}");
    assert_eq!(pixel(&mut ctx, 0, 0), [255; 4], "the first draw's point");
    assert_eq!(pixel(&mut ctx, 3, 3), [255; 4], "the second draw's point");
    assert_clean(&ctx);
}

#[test]
fn a_buffer_bound_for_transform_feedback_is_not_read_or_written_elsewhere() {
    let Some(mut ctx) = context(4, 4) else { return };
    let p = linked(&mut ctx, &["v_pos"], gl::SEPARATE_ATTRIBS);
    ctx.use_program(Some(p));
    float_attribute(&mut ctx, 1, 2, &[0.0; 6]);
    let tf = ctx.create_buffer();
    ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, Some(tf));
    ctx.buffer_data_size(gl::TRANSFORM_FEEDBACK_BUFFER, 64, gl::STREAM_COPY);
    ctx.bind_buffer_base(gl::TRANSFORM_FEEDBACK_BUFFER, 0, Some(tf));
    // Data calls through another binding of it (or on it while it has one).
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(tf));
    ctx.buffer_data_size(gl::ARRAY_BUFFER, 64, gl::STATIC_DRAW);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "bufferData");
    ctx.buffer_data_size(gl::TRANSFORM_FEEDBACK_BUFFER, 64, gl::STATIC_DRAW);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "bufferData, double bound"
    );
    // A draw that reads it, capturing or not.
    ctx.vertex_attrib_pointer(0, 2, gl::FLOAT, false, 0, 0);
    ctx.enable_vertex_attrib_array(0);
    ctx.draw_arrays(gl::POINTS, 0, 3);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "drawArrays reading it"
    );
    float_attribute(&mut ctx, 0, 2, &[0.0; 6]);
    ctx.draw_arrays(gl::POINTS, 0, 3);
    assert_eq!(
        ctx.get_error(),
        gl::NO_ERROR,
        "drawArrays reading another buffer"
    );
    // One buffer at two indices, one past the program's outputs, cannot be captured into.
    ctx.bind_buffer(gl::ARRAY_BUFFER, None);
    ctx.bind_buffer_base(gl::TRANSFORM_FEEDBACK_BUFFER, 2, Some(tf));
    ctx.begin_transform_feedback(gl::POINTS);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "the same buffer twice"
    );
    ctx.bind_buffer_base(gl::TRANSFORM_FEEDBACK_BUFFER, 2, None);
    // (which unbinds the generic binding too)
    ctx.bind_buffer(gl::TRANSFORM_FEEDBACK_BUFFER, Some(tf));
    ctx.begin_transform_feedback(gl::POINTS);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    // While a session writes it, not even its own target reads it.
    let mut out = [0f32; 2];
    ctx.get_buffer_sub_data(gl::TRANSFORM_FEEDBACK_BUFFER, 0, &mut out);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "getBufferSubData while capturing"
    );
    ctx.end_transform_feedback();
    ctx.get_buffer_sub_data(gl::TRANSFORM_FEEDBACK_BUFFER, 0, &mut out);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.bind_buffer_base(gl::TRANSFORM_FEEDBACK_BUFFER, 0, None);
    ctx.bind_buffer(gl::ARRAY_BUFFER, Some(tf));
    ctx.buffer_data_size(gl::ARRAY_BUFFER, 64, gl::STATIC_DRAW);
    assert_eq!(
        ctx.get_error(),
        gl::NO_ERROR,
        "no longer bound for transform feedback"
    );
}
