//! `WEBGL_multi_draw`: `gl_DrawID` needs the directive and the extension, is each draw's index
//! within a multi-draw and 0 for other draws; the calls check `drawcount` and the lists'
//! bounds, and draw nothing when one of their draws is invalid.

use essl_gl::{gl, Context, DrawList};

use crate::common;

/// Four vertical strips of a 16 × 4 canvas, two triangles each (6 vertices per strip).
fn strips() -> Vec<f32> {
    let mut v = Vec::new();
    for i in 0..4 {
        let (x0, x1) = (-1.0 + 0.5 * i as f32, -0.5 + 0.5 * i as f32);
        v.extend([x0, -1.0, x1, -1.0, x1, 1.0, x0, -1.0, x1, 1.0, x0, 1.0]);
    }
    v
}

/// A vertex shader of each language that colours a draw by its `gl_DrawID`: red 0.25 × id,
/// green 1 for the instance 1 (and 0 for instance 0, GLSL ES 3.00 only).
const VS_300: &str = "#version 300 es
#extension GL_ANGLE_multi_draw : require
in vec2 p;
out vec4 c;
void main() {
    c = vec4(0.25 * float(gl_DrawID), float(gl_InstanceID), 0.0, 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}";
const FS_300: &str = "#version 300 es
precision mediump float;
in vec4 c;
out vec4 o;
void main() { o = c; }";
const VS_100: &str = "#extension GL_ANGLE_multi_draw : require
attribute vec2 p;
varying vec4 c;
void main() {
    c = vec4(0.25 * float(gl_DrawID), 0.0, 0.0, 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}";
const FS_100: &str = "precision mediump float;
varying vec4 c;
void main() { gl_FragColor = c; }";

fn compiles(ctx: &mut Context, src: &str) -> (bool, String) {
    let s = ctx.create_shader(gl::VERTEX_SHADER).expect("a shader");
    ctx.shader_source(s, src);
    ctx.compile_shader(s);
    let log = ctx.get_shader_info_log(s).unwrap_or_default();
    (ctx.get_shader_compile_status(s), log)
}

/// The red channel of the middle of each strip.
fn strip_reds(ctx: &mut Context) -> Vec<u8> {
    (0..4)
        .map(|i| common::pixel(ctx, 4 * i + 2, 2)[0])
        .collect()
}

/// A context of WebGL `version` with the extension on, the program of `vs` and `fs` in use
/// and the strips at attribute 0.
fn setup(version: u32, vs: &str, fs: &str) -> Option<Context> {
    let mut ctx = common::context(16, 4)?;
    if version == 1 {
        ctx.set_webgl1();
    }
    assert!(ctx.get_extension("WEBGL_multi_draw").is_some());
    let p = common::program(&mut ctx, vs, fs);
    ctx.use_program(Some(p));
    let loc = ctx.get_attrib_location(p, "p") as u32;
    common::float_attribute(&mut ctx, loc, 2, &strips());
    common::clear_black(&mut ctx);
    Some(ctx)
}

#[test]
fn draw_id_needs_the_directive_and_the_extension() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    assert!(ctx.get_supported_extensions().contains(&"WEBGL_multi_draw"));
    let (ok, log) = compiles(&mut ctx, VS_300);
    assert!(!ok, "the directive needs the extension");
    assert!(log.contains("GL_ANGLE_multi_draw"), "{log}");
    ctx.get_extension("WEBGL_multi_draw").expect("offered");
    assert!(compiles(&mut ctx, VS_300).0);
    assert!(compiles(&mut ctx, VS_100).0, "GLSL ES 1.00 has it too");
    let undirected = VS_100.replace("#extension GL_ANGLE_multi_draw : require\n", "");
    let (ok, log) = compiles(&mut ctx, &undirected);
    assert!(!ok, "gl_DrawID without the directive");
    assert!(log.contains("gl_DrawID"), "{log}");
}

#[test]
fn each_draw_sees_its_index_in_both_languages_and_contexts() {
    for (version, vs, fs) in [
        (2, VS_300, FS_300),
        (2, VS_100, FS_100),
        (1, VS_100, FS_100),
    ] {
        let Some(mut ctx) = setup(version, vs, fs) else {
            return;
        };
        // Strips 1, 3 and 0, in that order: draw ids 0, 1, 2.
        let firsts = [99, 6, 18, 0];
        let counts = [6, 6, 6];
        ctx.multi_draw_arrays(
            gl::TRIANGLES,
            DrawList::new(&firsts, 1),
            DrawList::new(&counts, 0),
            3,
        );
        assert_eq!(ctx.get_error(), gl::NO_ERROR);
        // Red 0.25·id: 0, 64, 128 (strip 2 not drawn: black).
        assert_eq!(strip_reds(&mut ctx), [128, 0, 0, 64], "WebGL {version}");
        // A plain draw after it has gl_DrawID 0.
        ctx.draw_arrays(gl::TRIANGLES, 12, 6);
        assert_eq!(strip_reds(&mut ctx)[2], 0);
        common::assert_clean(&ctx);
    }
}

#[test]
fn indexed_and_instanced_draws_see_their_index() {
    let Some(mut ctx) = setup(2, VS_300, FS_300) else {
        return;
    };
    let indices: Vec<u16> = (0..24).collect();
    let b = ctx.create_buffer();
    ctx.bind_buffer(gl::ELEMENT_ARRAY_BUFFER, Some(b));
    ctx.buffer_data(gl::ELEMENT_ARRAY_BUFFER, &indices[..], gl::STATIC_DRAW);
    // Strips 3 and 2 (byte offsets of their first index), two instances of strip 2.
    let counts = [6, 6];
    let offsets = [36, 24];
    let instances = [1, 2];
    ctx.multi_draw_elements_instanced(
        gl::TRIANGLES,
        DrawList::new(&counts, 0),
        gl::UNSIGNED_SHORT,
        DrawList::new(&offsets, 0),
        DrawList::new(&instances, 0),
        2,
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_eq!(common::pixel(&mut ctx, 14, 2), [0, 0, 0, 255]);
    // Draw 1's second instance is drawn last: green 1, red 0.25.
    assert_eq!(common::pixel(&mut ctx, 10, 2), [64, 255, 0, 255]);
    assert_eq!(strip_reds(&mut ctx)[..2], [0, 0]);
    common::assert_clean(&ctx);
}

#[test]
fn counts_and_bounds_are_checked_and_a_bad_draw_stops_the_call() {
    let Some(mut ctx) = setup(2, VS_300, FS_300) else {
        return;
    };
    let firsts = [0, 6];
    let counts = [6, 6];
    let list = |v| DrawList::new(v, 0);
    ctx.multi_draw_arrays(gl::TRIANGLES, list(&firsts), list(&counts), -1);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    ctx.multi_draw_arrays(gl::TRIANGLES, list(&firsts), list(&counts), 3);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.multi_draw_arrays(gl::TRIANGLES, DrawList::new(&firsts, 1), list(&counts), 2);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.multi_draw_arrays(gl::TRIANGLES, list(&firsts), list(&counts), 0);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    // The second draw's count is negative: the first is not drawn either.
    ctx.multi_draw_arrays(gl::TRIANGLES, list(&firsts), list(&[6, -1]), 2);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    assert!(common::all_are(&mut ctx, [0, 0, 0, 255]));
    common::assert_clean(&ctx);
}

#[test]
fn the_calls_wait_for_the_extension() {
    let Some(mut ctx) = common::context(4, 4) else {
        return;
    };
    ctx.multi_draw_arrays(
        gl::TRIANGLES,
        DrawList::new(&[0], 0),
        DrawList::new(&[3], 0),
        1,
    );
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
}
