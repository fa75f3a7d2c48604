//! Compressed textures: refused until their extension is on, then decoded on upload and
//! sampled; the extensions' rules on data length, block alignment and sub-images; compressed
//! levels are not renderable, not mipmapped and not written by `texSubImage2D`.

use crate::common;

use essl_gl::{gl, Context};

const DXT1_RGB: u32 = 0x83F0;
const DXT1_RGBA: u32 = 0x83F1;
const DXT5: u32 = 0x83F3;
const ETC2_RGB8: u32 = 0x9274;
const ETC1: u32 = 0x8D64;
const ASTC_4X4: u32 = 0x93B0;
const ASTC_8X8: u32 = 0x93B7;

/// A DXT1 block of red (c0 = 0xF800 > c1, every index 0).
const DXT1_RED: [u8; 8] = [0x00, 0xF8, 0x1F, 0x00, 0, 0, 0, 0];
/// A DXT1 block in three-colour mode (c0 ≤ c1) with every index 3: transparent black in
/// `RGBA_DXT1`, opaque black in `RGB_DXT1`.
const DXT1_INDEX3: [u8; 8] = [0x00, 0x00, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF];
/// An ASTC void-extent block (one LDR colour for the block): red, opaque.
const ASTC_RED: [u8; 16] = [
    0xFC, 0xFD, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x00, 0xFF, 0xFF,
];

const VS: &str = "#version 300 es\nin vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }";
const FS: &str = "#version 300 es\nprecision mediump float; uniform sampler2D t; out vec4 c;\
    void main() { c = texture(t, vec2(0.5)); }";

/// A bound texture with nearest filtering and one level.
fn texture(ctx: &mut Context) {
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MIN_FILTER, gl::NEAREST as i32);
    ctx.tex_parameteri(gl::TEXTURE_2D, gl::TEXTURE_MAG_FILTER, gl::NEAREST as i32);
}

/// Draws the bound texture's centre over the canvas; the centre pixel.
fn sample(ctx: &mut Context) -> [u8; 4] {
    common::draw_quad_pixel(ctx, VS, FS)
}

fn formats(ctx: &mut Context) -> Vec<u32> {
    match ctx.get_parameter(gl::COMPRESSED_TEXTURE_FORMATS) {
        Some(essl_gl::Parameter::Uints(v)) => v,
        other => panic!("COMPRESSED_TEXTURE_FORMATS: {other:?}"),
    }
}

#[test]
fn formats_wait_for_their_extension() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    assert!(formats(&mut ctx).is_empty());
    texture(&mut ctx);
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, DXT1_RGB, 4, 4, 0, &DXT1_RED);
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_ENUM,
        "DXT1 before the extension"
    );
    for name in [
        "WEBGL_compressed_texture_s3tc",
        "WEBGL_compressed_texture_etc",
        "WEBGL_compressed_texture_astc",
    ] {
        assert!(ctx.get_supported_extensions().contains(&name));
        assert!(ctx.get_extension(name).is_some(), "{name}");
    }
    let f = formats(&mut ctx);
    assert!(f.contains(&DXT1_RGB) && f.contains(&ETC2_RGB8) && f.contains(&ASTC_8X8));
    assert!(!f.contains(&ETC1), "ETC1's extension is still off");
}

#[test]
fn blocks_decode_to_what_sampling_reads() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    for name in [
        "WEBGL_compressed_texture_s3tc",
        "WEBGL_compressed_texture_etc",
        "WEBGL_compressed_texture_astc",
    ] {
        ctx.get_extension(name);
    }
    let cases: [(u32, &[u8], [u8; 4]); 4] = [
        (DXT1_RGB, &DXT1_RED, [255, 0, 0, 255]),
        (DXT1_RGBA, &DXT1_INDEX3, [0, 0, 0, 0]),
        (DXT1_RGB, &DXT1_INDEX3, [0, 0, 0, 255]),
        (ASTC_4X4, &ASTC_RED, [255, 0, 0, 255]),
    ];
    for (format, block, want) in cases {
        texture(&mut ctx);
        ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, format, 4, 4, 0, block);
        assert_eq!(ctx.get_error(), gl::NO_ERROR, "0x{format:04X}");
        assert_eq!(sample(&mut ctx), want, "0x{format:04X}");
    }
    // ETC2 in individual mode: R = 15 (255) in both halves, modifier +2 from table 0.
    let mut etc = [0u8; 8];
    etc[0] = 0xFF;
    texture(&mut ctx);
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, ETC2_RGB8, 4, 4, 0, &etc);
    let [r, g, b, a] = sample(&mut ctx);
    assert!(
        r == 255 && g <= 8 && b <= 8 && a == 255,
        "{:?}",
        [r, g, b, a]
    );
}

#[test]
fn the_extensions_rules_hold() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    ctx.get_extension("WEBGL_compressed_texture_s3tc");
    ctx.get_extension("WEBGL_compressed_texture_etc1");
    texture(&mut ctx);
    // The data is exactly the blocks: 8 bytes per DXT1 block.
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, DXT1_RGB, 4, 4, 0, &[0; 16]);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE);
    // S3TC level 0 is whole blocks; level 2 of 1×1 is, at level 0's scale.
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, DXT1_RGB, 6, 4, 0, &[0; 16]);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 2, DXT1_RGB, 1, 1, 0, &[0; 8]);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, DXT5, 8, 8, 0, &[0; 64]);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    // A sub-image starts on a block and covers whole blocks, in the level's format.
    ctx.compressed_tex_sub_image_2d(gl::TEXTURE_2D, 0, 2, 0, 4, 4, DXT5, &[0; 16]);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "offset off a block");
    ctx.compressed_tex_sub_image_2d(gl::TEXTURE_2D, 0, 4, 4, 4, 4, DXT1_RGB, &[0; 8]);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION, "another format");
    ctx.compressed_tex_sub_image_2d(gl::TEXTURE_2D, 0, 4, 4, 4, 4, DXT5, &[0; 16]);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.compressed_tex_sub_image_2d(gl::TEXTURE_2D, 0, 4, 4, 8, 4, DXT5, &[0; 32]);
    assert_eq!(ctx.get_error(), gl::INVALID_VALUE, "region past the level");
    // Not written by texSubImage2D, not mipmapped, not renderable.
    ctx.tex_sub_image_2d(
        gl::TEXTURE_2D,
        0,
        0,
        0,
        1,
        1,
        gl::RGBA,
        gl::UNSIGNED_BYTE,
        &[0u8; 4],
    );
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    ctx.generate_mipmap(gl::TEXTURE_2D);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    let fb = ctx.create_framebuffer();
    ctx.bind_framebuffer(gl::FRAMEBUFFER, Some(fb));
    let t = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_2D, Some(t));
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, DXT5, 4, 4, 0, &[0; 16]);
    ctx.framebuffer_texture_2d(
        gl::FRAMEBUFFER,
        gl::COLOR_ATTACHMENT0,
        gl::TEXTURE_2D,
        Some(t),
        0,
    );
    assert_ne!(
        ctx.check_framebuffer_status(gl::FRAMEBUFFER),
        gl::FRAMEBUFFER_COMPLETE
    );
    ctx.bind_framebuffer(gl::FRAMEBUFFER, None);
    // ETC1 takes no sub-images; 3D textures take no compressed format.
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, ETC1, 4, 4, 0, &[0; 8]);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.compressed_tex_sub_image_2d(gl::TEXTURE_2D, 0, 0, 0, 4, 4, ETC1, &[0; 8]);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
    let t3 = ctx.create_texture();
    ctx.bind_texture(gl::TEXTURE_3D, Some(t3));
    ctx.compressed_tex_image_3d(gl::TEXTURE_3D, 0, DXT1_RGB, 4, 4, 1, 0, &[0; 8]);
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
}

#[test]
fn storage_and_pixel_unpack_buffers() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    ctx.get_extension("WEBGL_compressed_texture_s3tc");
    texture(&mut ctx);
    ctx.tex_storage_2d(gl::TEXTURE_2D, 1, DXT1_RGB, 4, 4);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    // Storage starts as zero blocks: opaque black for DXT1.
    assert_eq!(sample(&mut ctx), [0, 0, 0, 255]);
    let b = ctx.create_buffer();
    ctx.bind_buffer(gl::PIXEL_UNPACK_BUFFER, Some(b));
    let mut bytes = vec![0u8; 4];
    bytes.extend_from_slice(&DXT1_RED);
    ctx.buffer_data(gl::PIXEL_UNPACK_BUFFER, &bytes, gl::STATIC_DRAW);
    ctx.compressed_tex_from_buffer(
        "compressedTexSubImage2D",
        gl::TEXTURE_2D,
        0,
        &[0, 0, 4, 4, DXT1_RGB as i64],
        8,
        4,
    );
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    ctx.compressed_tex_from_buffer(
        "compressedTexSubImage2D",
        gl::TEXTURE_2D,
        0,
        &[0, 0, 4, 4, DXT1_RGB as i64],
        8,
        5,
    );
    assert_eq!(
        ctx.get_error(),
        gl::INVALID_OPERATION,
        "past the buffer's end"
    );
    ctx.bind_buffer(gl::PIXEL_UNPACK_BUFFER, None);
    assert_eq!(sample(&mut ctx), [255, 0, 0, 255]);
}

/// A BC6H block in mode 11 (one region, 10-bit endpoints, no deltas) whose every texel is
/// endpoint 0, (512, 512, 512).
fn bc6h_512() -> [u8; 16] {
    let bits: u128 = 0b00011 | 512 << 5 | 512 << 15 | 512 << 25;
    bits.to_le_bytes()
}

/// The value BC6H's unsigned decoding gives a 10-bit endpoint `v`: unquantised to 16 bits,
/// scaled by 31/64 into a half float's bits (the format's specification).
fn bc6h_unsigned_value(v: u32) -> f32 {
    let q = ((v << 16) + 0x8000) >> 10;
    let h = (q * 31) >> 6;
    let (e, m) = ((h >> 10) as i32, (h & 0x3FF) as f32);
    2f32.powi(e - 15) * (1.0 + m / 1024.0)
}

/// A BC7 block in mode 6 (one subset, 7-bit RGBA endpoints and a p-bit each): endpoint 0 is
/// (0x7F, 0x00, 0x40, 0x7F) with p-bit 1, every index 0: (255, 1, 129, 255).
fn bc7_mode6() -> [u8; 16] {
    let bits: u128 = 1 << 6 | 0x7F << 7 | 0x40 << 35 | 0x7F << 49 | 1 << 63;
    bits.to_le_bytes()
}

/// A signed BC4 block with red0 = 127, red1 = −127 and every index 1: −1.
const BC4_SIGNED_MINUS_ONE: [u8; 8] = [0x7F, 0x81, 0x49, 0x92, 0x24, 0x49, 0x92, 0x24];

/// The texture's centre drawn into a 1×1 RGBA32F framebuffer, as floats.
fn sample_float(ctx: &mut Context) -> [f32; 4] {
    let target = ctx.create_texture();
    ctx.active_texture(gl::TEXTURE1);
    ctx.bind_texture(gl::TEXTURE_2D, Some(target));
    ctx.tex_storage_2d(gl::TEXTURE_2D, 1, gl::RGBA32F, 1, 1);
    common::colour_framebuffer(ctx, target);
    ctx.active_texture(gl::TEXTURE0);
    let p = common::program(ctx, VS, &FS.replace("mediump", "highp"));
    ctx.use_program(Some(p));
    common::float_attribute(ctx, 0, 2, &common::QUAD);
    ctx.viewport(0, 0, 1, 1);
    ctx.draw_arrays(gl::TRIANGLES, 0, 6);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    let mut out = [0f32; 4];
    ctx.read_pixels(0, 0, 1, 1, gl::RGBA, gl::FLOAT, &mut out);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    out
}

#[test]
fn rgtc_and_bptc_keep_signed_and_high_dynamic_range_values() {
    let Some(mut ctx) = common::context(2, 2) else {
        return;
    };
    for name in [
        "EXT_texture_compression_rgtc",
        "EXT_texture_compression_bptc",
        "EXT_color_buffer_float",
    ] {
        assert!(ctx.get_extension(name).is_some(), "{name}");
    }
    // BC6H: a value past 1 stays a half float.
    texture(&mut ctx);
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, 0x8E8F, 4, 4, 0, &bc6h_512());
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    let want = bc6h_unsigned_value(512);
    assert!(want > 1.5, "{want}");
    let got = sample_float(&mut ctx);
    for c in &got[..3] {
        assert!((c - want).abs() < 1e-3, "{got:?} against {want}");
    }
    assert_eq!(got[3], 1.0);
    // Signed RGTC: −1 in red, 0 in green and blue, 1 in alpha.
    texture(&mut ctx);
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, 0x8DBC, 4, 4, 0, &BC4_SIGNED_MINUS_ONE);
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_eq!(sample_float(&mut ctx), [-1.0, 0.0, 0.0, 1.0]);
    // BC7 into the default framebuffer.
    ctx.bind_framebuffer(gl::FRAMEBUFFER, None);
    ctx.viewport(0, 0, 2, 2);
    texture(&mut ctx);
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, 0x8E8C, 4, 4, 0, &bc7_mode6());
    assert_eq!(ctx.get_error(), gl::NO_ERROR);
    assert_eq!(sample(&mut ctx), [255, 1, 129, 255]);
    // Level 0 must be whole blocks, as for S3TC.
    texture(&mut ctx);
    ctx.compressed_tex_image_2d(gl::TEXTURE_2D, 0, 0x8E8C, 2, 2, 0, &bc7_mode6());
    assert_eq!(ctx.get_error(), gl::INVALID_OPERATION);
}
