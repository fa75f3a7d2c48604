//! Query objects, fences and `present`, with WebGL's rule that results become available
//! only after control returns to the event loop (`present` stands for it).

use crate::common;

use common::*;
use essl_gl::{gl, Context, ContextAttributes, Parameter};

const PASS_VS: &str = "#version 300 es
in vec4 a_position;
void main() { gl_Position = a_position; }";

fn white_program(ctx: &mut Context) {
    let p = program(
        ctx,
        PASS_VS,
        "#version 300 es
        precision mediump float;
        out vec4 color;
        void main() { color = vec4(1.0); }",
    );
    ctx.use_program(Some(p));
    float_attribute(ctx, 0, 2, &QUAD);
}

#[test]
fn any_samples_passed_answers_after_present() {
    let Some(mut ctx) = context(8, 8) else { return };
    white_program(&mut ctx);
    let q = ctx.create_query();
    assert!(!ctx.is_query(q), "not a query until begun");
    ctx.begin_query(gl::ANY_SAMPLES_PASSED, q);
    assert_eq!(
        ctx.get_query(gl::ANY_SAMPLES_PASSED, gl::CURRENT_QUERY),
        Some(q)
    );
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    ctx.get_query_parameter(q, gl::QUERY_RESULT);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "asked while active");
    ctx.end_query(gl::ANY_SAMPLES_PASSED);
    assert_eq!(
        ctx.get_query_parameter(q, gl::QUERY_RESULT_AVAILABLE),
        Some(Parameter::Bool(false))
    );
    ctx.present();
    assert_eq!(
        ctx.get_query_parameter(q, gl::QUERY_RESULT_AVAILABLE),
        Some(Parameter::Bool(true))
    );
    assert_eq!(
        ctx.get_query_parameter(q, gl::QUERY_RESULT),
        Some(Parameter::Int(1))
    );
    // Nothing passes the depth test: no sample.
    ctx.enable(gl::DEPTH_TEST);
    ctx.depth_func(gl::NEVER);
    ctx.begin_query(gl::ANY_SAMPLES_PASSED_CONSERVATIVE, q);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "begun before with another target"
    );
    let q2 = ctx.create_query();
    ctx.begin_query(gl::ANY_SAMPLES_PASSED, q2);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    ctx.end_query(gl::ANY_SAMPLES_PASSED);
    ctx.present();
    assert_eq!(
        ctx.get_query_parameter(q2, gl::QUERY_RESULT),
        Some(Parameter::Int(0))
    );
    ctx.end_query(gl::ANY_SAMPLES_PASSED);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "none active");
    assert_clean(&ctx);
}

#[test]
fn fences_signal_after_present_and_never_block() {
    let Some(mut ctx) = context(4, 4) else { return };
    let sync = ctx
        .fence_sync(gl::SYNC_GPU_COMMANDS_COMPLETE, 0)
        .expect("a fence");
    assert!(ctx.is_sync(sync));
    assert_eq!(ctx.client_wait_sync(sync, 0, 0), gl::TIMEOUT_EXPIRED);
    assert_eq!(
        ctx.get_sync_parameter(sync, gl::SYNC_STATUS),
        Some(Parameter::Enum(gl::UNSIGNALED))
    );
    ctx.client_wait_sync(sync, 0, 1_000_000);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "a timeout above the WebGL maximum"
    );
    ctx.present();
    assert_eq!(
        ctx.client_wait_sync(sync, gl::SYNC_FLUSH_COMMANDS_BIT, 0),
        gl::ALREADY_SIGNALED
    );
    assert_eq!(
        ctx.get_sync_parameter(sync, gl::SYNC_STATUS),
        Some(Parameter::Enum(gl::SIGNALED))
    );
    ctx.wait_sync(sync, 0, gl::TIMEOUT_IGNORED);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.wait_sync(sync, 0, 5);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    ctx.delete_sync(sync);
    assert!(!ctx.is_sync(sync));
    assert_clean(&ctx);
}

#[test]
fn present_clears_the_drawing_buffer_unless_it_is_preserved() {
    for preserve in [false, true] {
        let attributes = ContextAttributes {
            preserve_drawing_buffer: preserve,
            ..Default::default()
        };
        let Some(mut ctx) = context_with(4, 4, attributes) else {
            return;
        };
        ctx.clear_color(1.0, 0.0, 0.0, 1.0);
        ctx.clear(gl::COLOR_BUFFER_BIT);
        ctx.present();
        let want = if preserve {
            [255, 0, 0, 255]
        } else {
            [0, 0, 0, 0]
        };
        assert_eq!(
            pixel(&mut ctx, 1, 1),
            want,
            "preserveDrawingBuffer: {preserve}"
        );
        assert_eq!(ctx.get_context_attributes(), attributes);
        assert_clean(&ctx);
    }
}
