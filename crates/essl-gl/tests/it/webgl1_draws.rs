//! WebGL 1's draw rules from its extensions: with `GL_EXT_draw_buffers` enabled, what a shader
//! writes to `gl_FragColor` reaches every draw buffer; `ANGLE_instanced_arrays` needs an
//! attribute the program uses whose divisor is 0; the compositor clears the drawing buffer
//! whatever `drawBuffers` says.

use essl_gl::{gl, Context};

use crate::common;

const VS: &str = "attribute vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }";

fn webgl1(w: u32, h: u32) -> Option<Context> {
    let mut ctx = common::context(w, h)?;
    ctx.set_webgl1();
    Some(ctx)
}

/// A framebuffer with `n` 1×1 RGBA textures drawn to, all cleared to black.
fn targets(ctx: &mut Context, n: u32) {
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    let mut buffers = Vec::new();
    for i in 0..n {
        let t = ctx.create_texture();
        ctx.bind_texture(gl::TEXTURE_2D, Some(t));
        ctx.tex_image_2d::<u8>(
            gl::TEXTURE_2D,
            0,
            gl::RGBA as i32,
            1,
            1,
            0,
            gl::RGBA,
            gl::UNSIGNED_BYTE,
            None,
        );
        ctx.framebuffer_texture_2d(
            gl::FRAMEBUFFER,
            gl::COLOR_ATTACHMENT0 + i,
            gl::TEXTURE_2D,
            Some(t),
            0,
        );
        buffers.push(gl::COLOR_ATTACHMENT0 + i);
    }
    ctx.draw_buffers(&buffers);
    common::clear_black(ctx);
}

#[test]
fn frag_color_reaches_every_draw_buffer_once_the_shader_enables_draw_buffers() {
    let Some(mut ctx) = webgl1(1, 1) else { return };
    ctx.get_extension("WEBGL_draw_buffers").expect("offered");
    targets(&mut ctx, 3);
    let fs = "#extension GL_EXT_draw_buffers : require
precision mediump float;
void main() { gl_FragColor = vec4(1.0, 0.0, 0.0, 1.0); }";
    let p = common::program(&mut ctx, VS, fs);
    ctx.use_program(Some(p));
    common::float_attribute(&mut ctx, 0, 2, &common::QUAD);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    for i in 0..3 {
        ctx.read_buffer(gl::COLOR_ATTACHMENT0 + i);
        assert_eq!(
            common::pixel(&mut ctx, 0, 0),
            [255, 0, 0, 255],
            "draw buffer {i}"
        );
    }
    // Without the directive gl_FragColor is draw buffer 0's alone: the others have no output.
    let fs = "precision mediump float; void main() { gl_FragColor = vec4(1.0); }";
    let p = common::program(&mut ctx, VS, fs);
    ctx.use_program(Some(p));
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    common::assert_clean(&ctx);
}

#[test]
fn instanced_draws_need_an_attribute_with_divisor_zero() {
    let Some(mut ctx) = webgl1(1, 1) else { return };
    ctx.get_extension("ANGLE_instanced_arrays")
        .expect("offered");
    let fs = "precision mediump float; void main() { gl_FragColor = vec4(1.0); }";
    let p = common::program(&mut ctx, VS, fs);
    ctx.use_program(Some(p));
    common::float_attribute(&mut ctx, 0, 2, &common::QUAD);
    ctx.vertex_attrib_divisor(0, 1);
    ctx.draw_arrays_instanced(gl::TRIANGLES, 0, 3, 1);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.vertex_attrib_divisor(0, 0);
    ctx.draw_arrays_instanced(gl::TRIANGLES, 0, 3, 1);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
}

#[test]
fn the_compositor_clears_the_drawing_buffer_whatever_draw_buffers_says() {
    let Some(mut ctx) = webgl1(1, 1) else { return };
    ctx.get_extension("WEBGL_draw_buffers").expect("offered");
    ctx.clear_color(1.0, 1.0, 0.0, 1.0);
    ctx.clear(gl::COLOR_BUFFER_BIT);
    ctx.draw_buffers(&[gl::NONE]);
    ctx.present();
    assert_eq!(common::pixel(&mut ctx, 0, 0), [0, 0, 0, 0]);
}
