//! Compressed textures: `compressedTexImage2D/3D`, `compressedTexSubImage2D/3D` and
//! `texStorage*` with the formats of `WEBGL_compressed_texture_s3tc` (DXT1, DXT3, DXT5),
//! `WEBGL_compressed_texture_s3tc_srgb`, `WEBGL_compressed_texture_etc` (ETC2 and EAC) and
//! `WEBGL_compressed_texture_etc1` and `WEBGL_compressed_texture_astc` (the LDR profile), each
//! refused (`INVALID_ENUM`) until its extension is on.
//!
//! The blocks are decoded on upload — by `texture2ddecoder`, whose block decoders are what no
//! GPU-independent path in wgpu offers (wgpu's compressed formats need an adapter feature that
//! lavapipe and most desktop GPUs lack for ETC2, and the others for BC) — into an RGBA8 level
//! (sRGB for the sRGB formats, signed normalised for the signed EAC formats): sampling then
//! reads what the compressed texture holds, on every adapter. A compressed level keeps its
//! compressed internal format, so it is neither colour-renderable nor a target of
//! `texSubImage*`, `copyTex*` or `generateMipmap`.
//!
//! Validation follows the extensions' specifications and WebGL 2.0 §5.37: the data's length
//! is exactly the blocks' (`INVALID_VALUE`); S3TC levels are whole blocks at level 0's scale
//! (`width << level` a multiple of 4, else `INVALID_OPERATION`); a sub-image starts on a block
//! and covers whole blocks or reaches the level's edge (`INVALID_OPERATION`; ETC1 takes no
//! sub-images), and its format
//! is the level's (`INVALID_OPERATION`); 3D textures take none of these formats.

use super::format::{Comp, Expand, InternalFormat, Packing};
use super::image_target;
use super::object::Level;
use crate::extensions::Extension;
use crate::{gl, Context};

/// A block codec.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Codec {
    Bc1,
    Bc1a,
    Bc2,
    Bc3,
    Etc1,
    Etc2Rgb,
    Etc2Rgba1,
    Etc2Rgba8,
    EacR,
    EacRSigned,
    EacRg,
    EacRgSigned,
    /// ASTC LDR with its block's width and height.
    Astc(u8, u8),
}

/// A compressed internal format essl-gl decodes.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Compressed {
    gl: u32,
    codec: Codec,
    srgb: bool,
    /// The extension that offers it.
    pub(crate) extension: Extension,
}

/// Every compressed format, in the order `COMPRESSED_TEXTURE_FORMATS` lists them.
const FORMATS: &[(u32, Codec, bool, Extension)] = &[
    (0x83F0, Codec::Bc1, false, Extension::CompressedS3tc),
    (0x83F1, Codec::Bc1a, false, Extension::CompressedS3tc),
    (0x83F2, Codec::Bc2, false, Extension::CompressedS3tc),
    (0x83F3, Codec::Bc3, false, Extension::CompressedS3tc),
    (0x8C4C, Codec::Bc1, true, Extension::CompressedS3tcSrgb),
    (0x8C4D, Codec::Bc1a, true, Extension::CompressedS3tcSrgb),
    (0x8C4E, Codec::Bc2, true, Extension::CompressedS3tcSrgb),
    (0x8C4F, Codec::Bc3, true, Extension::CompressedS3tcSrgb),
    (0x9270, Codec::EacR, false, Extension::CompressedEtc),
    (0x9271, Codec::EacRSigned, false, Extension::CompressedEtc),
    (0x9272, Codec::EacRg, false, Extension::CompressedEtc),
    (0x9273, Codec::EacRgSigned, false, Extension::CompressedEtc),
    (0x9274, Codec::Etc2Rgb, false, Extension::CompressedEtc),
    (0x9275, Codec::Etc2Rgb, true, Extension::CompressedEtc),
    (0x9276, Codec::Etc2Rgba1, false, Extension::CompressedEtc),
    (0x9277, Codec::Etc2Rgba1, true, Extension::CompressedEtc),
    (0x9278, Codec::Etc2Rgba8, false, Extension::CompressedEtc),
    (0x9279, Codec::Etc2Rgba8, true, Extension::CompressedEtc),
    (0x8D64, Codec::Etc1, false, Extension::CompressedEtc1),
    (0x93B0, Codec::Astc(4, 4), false, Extension::CompressedAstc),
    (0x93B1, Codec::Astc(5, 4), false, Extension::CompressedAstc),
    (0x93B2, Codec::Astc(5, 5), false, Extension::CompressedAstc),
    (0x93B3, Codec::Astc(6, 5), false, Extension::CompressedAstc),
    (0x93B4, Codec::Astc(6, 6), false, Extension::CompressedAstc),
    (0x93B5, Codec::Astc(8, 5), false, Extension::CompressedAstc),
    (0x93B6, Codec::Astc(8, 6), false, Extension::CompressedAstc),
    (0x93B7, Codec::Astc(8, 8), false, Extension::CompressedAstc),
    (0x93B8, Codec::Astc(10, 5), false, Extension::CompressedAstc),
    (0x93B9, Codec::Astc(10, 6), false, Extension::CompressedAstc),
    (0x93BA, Codec::Astc(10, 8), false, Extension::CompressedAstc),
    (
        0x93BB,
        Codec::Astc(10, 10),
        false,
        Extension::CompressedAstc,
    ),
    (
        0x93BC,
        Codec::Astc(12, 10),
        false,
        Extension::CompressedAstc,
    ),
    (
        0x93BD,
        Codec::Astc(12, 12),
        false,
        Extension::CompressedAstc,
    ),
    (0x93D0, Codec::Astc(4, 4), true, Extension::CompressedAstc),
    (0x93D1, Codec::Astc(5, 4), true, Extension::CompressedAstc),
    (0x93D2, Codec::Astc(5, 5), true, Extension::CompressedAstc),
    (0x93D3, Codec::Astc(6, 5), true, Extension::CompressedAstc),
    (0x93D4, Codec::Astc(6, 6), true, Extension::CompressedAstc),
    (0x93D5, Codec::Astc(8, 5), true, Extension::CompressedAstc),
    (0x93D6, Codec::Astc(8, 6), true, Extension::CompressedAstc),
    (0x93D7, Codec::Astc(8, 8), true, Extension::CompressedAstc),
    (0x93D8, Codec::Astc(10, 5), true, Extension::CompressedAstc),
    (0x93D9, Codec::Astc(10, 6), true, Extension::CompressedAstc),
    (0x93DA, Codec::Astc(10, 8), true, Extension::CompressedAstc),
    (0x93DB, Codec::Astc(10, 10), true, Extension::CompressedAstc),
    (0x93DC, Codec::Astc(12, 10), true, Extension::CompressedAstc),
    (0x93DD, Codec::Astc(12, 12), true, Extension::CompressedAstc),
];

/// The compressed format `internal` names, whatever extensions are on.
pub(crate) fn compressed(internal: u32) -> Option<Compressed> {
    FORMATS
        .iter()
        .find(|f| f.0 == internal)
        .map(|&(gl, codec, srgb, extension)| Compressed {
            gl,
            codec,
            srgb,
            extension,
        })
}

impl Compressed {
    /// Bytes per block.
    fn block_bytes(self) -> usize {
        match self.codec {
            Codec::Bc1
            | Codec::Bc1a
            | Codec::Etc1
            | Codec::Etc2Rgb
            | Codec::Etc2Rgba1
            | Codec::EacR
            | Codec::EacRSigned => 8,
            _ => 16,
        }
    }

    /// A block's width and height in texels.
    fn block_size(self) -> (u32, u32) {
        match self.codec {
            Codec::Astc(w, h) => (u32::from(w), u32::from(h)),
            _ => (4, 4),
        }
    }

    /// Bytes of a `w × h × d` image.
    fn data_size(self, w: u32, h: u32, d: u32) -> u64 {
        let (bw, bh) = self.block_size();
        u64::from(w.div_ceil(bw))
            * u64::from(h.div_ceil(bh))
            * u64::from(d)
            * self.block_bytes() as u64
    }

    fn s3tc(self) -> bool {
        matches!(
            self.codec,
            Codec::Bc1 | Codec::Bc1a | Codec::Bc2 | Codec::Bc3
        )
    }

    fn signed(self) -> bool {
        matches!(self.codec, Codec::EacRSigned | Codec::EacRgSigned)
    }

    /// The level format: RGBA8 storage under the compressed enum (no `format` matches it).
    pub(crate) fn internal(self) -> InternalFormat {
        InternalFormat {
            gl: self.gl,
            base: COMPRESSED_BASE,
            channels: 4,
            comp: if self.signed() {
                Comp::Snorm8
            } else {
                Comp::Unorm8
            },
            srgb: self.srgb,
            expand: Expand::None,
            packing: Packing::None,
        }
    }

    /// Decodes `w × h × d` texels of blocks into the level format's bytes.
    fn decode(self, w: u32, h: u32, d: u32, data: &[u8]) -> Vec<u8> {
        let (bw, bh) = self.block_size();
        let (w, h, bw, bh) = (w as usize, h as usize, bw as usize, bh as usize);
        let (nx, ny) = (w.div_ceil(bw), h.div_ceil(bh));
        let bytes = self.block_bytes();
        let mut out = vec![0u8; w * h * d as usize * 4];
        let mut block = vec![0u32; bw * bh];
        for z in 0..d as usize {
            for by in 0..ny {
                for bx in 0..nx {
                    let at = ((z * ny + by) * nx + bx) * bytes;
                    block.fill(0);
                    self.decode_block(&data[at..at + bytes], &mut block);
                    for (i, px) in block.iter().enumerate() {
                        let (x, y) = (bx * bw + i % bw, by * bh + i / bw);
                        if x < w && y < h {
                            let o = ((z * h + y) * w + x) * 4;
                            out[o..o + 4].copy_from_slice(&self.texel(*px));
                        }
                    }
                }
            }
        }
        out
    }

    fn decode_block(self, b: &[u8], out: &mut [u32]) {
        use texture2ddecoder as t;
        match self.codec {
            Codec::Bc1 => t::decode_bc1_block(b, out),
            Codec::Bc1a => t::decode_bc1a_block(b, out),
            Codec::Bc2 => t::decode_bc2_block(b, out),
            Codec::Bc3 => t::decode_bc3_block(b, out),
            Codec::Etc1 => t::decode_etc1_block(b, out),
            Codec::Etc2Rgb => t::decode_etc2_rgb_block(b, out),
            Codec::Etc2Rgba1 => t::decode_etc2_rgba1_block(b, out),
            Codec::Etc2Rgba8 => t::decode_etc2_rgba8_block(b, out),
            Codec::EacR => t::decode_eacr_block(b, out),
            Codec::EacRSigned => t::decode_eacr_signed_block(b, out),
            Codec::EacRg => t::decode_eacrg_block(b, out),
            Codec::EacRgSigned => t::decode_eacrg_signed_block(b, out),
            Codec::Astc(w, h) => t::decode_astc_block(b, w as usize, h as usize, out),
        }
    }

    /// One decoded texel (the decoder's BGRA word) as the level's RGBA bytes.
    fn texel(self, px: u32) -> [u8; 4] {
        let [b, g, r, a] = px.to_le_bytes();
        if !self.signed() {
            return [r, g, b, a];
        }
        // The decoder maps EAC's signed range [-1023, 1023] (in eighths) to 0..=255.
        let snorm = |v: u8| {
            let x = (f32::from(v) * 8.0 + 4.0 - 1023.0) / 1023.0;
            ((x.clamp(-1.0, 1.0) * 127.0).round() as i8) as u8
        };
        let green = if self.codec == Codec::EacRgSigned {
            snorm(g)
        } else {
            0
        };
        [snorm(r), green, 0, 127]
    }
}

/// The `base` of a compressed level's format: no `format` argument equals it, so
/// `texSubImage*` refuses the level.
pub(crate) const COMPRESSED_BASE: u32 = 0;

/// The arguments of a compressed upload after the call's own checks.
pub(super) struct CompressedImage<'a> {
    pub(super) target: u32,
    pub(super) level: i32,
    pub(super) format: u32,
    /// The image's size (`texImage`) or the region's (`texSubImage`).
    pub(super) size: [i32; 3],
    /// `Some(offset)` for a sub-image.
    pub(super) offset: Option<[i32; 3]>,
    pub(super) data: &'a [u8],
    pub(super) function: &'static str,
}

impl Context {
    /// The compressed format `internal` names when its extension is on.
    pub(crate) fn enabled_compressed(&self, internal: u32) -> Option<Compressed> {
        compressed(internal).filter(|c| self.extensions.compressed.contains(&c.extension))
    }

    /// The compressed formats the extensions turned on offer (`COMPRESSED_TEXTURE_FORMATS`).
    pub(crate) fn compressed_formats(&self) -> Vec<u32> {
        FORMATS
            .iter()
            .filter(|f| self.extensions.compressed.contains(&f.3))
            .map(|f| f.0)
            .collect()
    }

    /// `compressedTexImage*` and `compressedTexSubImage*` after their target checks.
    pub(super) fn compressed_image(&mut self, image: CompressedImage) {
        let CompressedImage {
            target,
            level,
            format,
            size: [width, height, depth],
            offset,
            data,
            function,
        } = image;
        let (bind, face) = image_target(target).expect("checked by the caller");
        let Some(c) = self.enabled_compressed(format) else {
            return self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("0x{format:04X} is no compressed format an enabled extension offers"),
            );
        };
        if bind == gl::TEXTURE_3D {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "3D textures take no compressed format",
            );
        }
        if offset.is_none() && !self.check_level_size(bind, level, width, height, depth, function) {
            return;
        }
        if level < 0 || width < 0 || height < 0 || depth < 0 {
            return self.error(gl::INVALID_VALUE, function, "negative level or size");
        }
        let (w, h, d) = (width as u32, height as u32, depth as u32);
        if data.len() as u64 != c.data_size(w, h, d) {
            return self.error(
                gl::INVALID_VALUE,
                function,
                format_args!(
                    "{} bytes of data, the format's blocks need {}",
                    data.len(),
                    c.data_size(w, h, d)
                ),
            );
        }
        let Some(id) = self.bound_texture(bind, function) else {
            return;
        };
        let t = self
            .objects
            .textures
            .get(id)
            .expect("bound textures are live");
        let Some(offset) = offset else {
            // S3TC: whole blocks at level 0's scale.
            let whole = |n: u32| (u64::from(n) << level.min(31)) % 4 == 0;
            if c.s3tc() && !(whole(w) && whole(h)) {
                return self.error(
                    gl::INVALID_OPERATION,
                    function,
                    format_args!("{w}x{h} at level {level} is not whole 4x4 blocks of level 0"),
                );
            }
            if t.immutable_levels.is_some() {
                return self.error(gl::INVALID_OPERATION, function, "immutable texture");
            }
            let texels = c.decode(w, h, d, data);
            let t = self.objects.textures.get_mut(id).expect("live");
            t.set_level(
                face,
                level as u32,
                Level::new([w, h, d], c.internal(), texels),
            );
            return;
        };
        if c.codec == Codec::Etc1 {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "ETC1 textures take no sub-image updates (WEBGL_compressed_texture_etc1)",
            );
        }
        let Some(l) = t.level(face, level as u32) else {
            return self.error(gl::INVALID_OPERATION, function, "the level has no image");
        };
        let (lw, lh, ld) = (l.width, l.height, l.depth);
        if l.format.gl != c.gl {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "the format is not the level's internal format",
            );
        }
        if offset.iter().any(|&v| v < 0)
            || offset[0] as u64 + u64::from(w) > u64::from(lw)
            || offset[1] as u64 + u64::from(h) > u64::from(lh)
            || offset[2] as u64 + u64::from(d) > u64::from(ld)
        {
            return self.error(gl::INVALID_VALUE, function, "region outside the level");
        }
        let [x, y, z] = offset.map(|v| v as u32);
        let (bw, bh) = c.block_size();
        let edge =
            |at: u32, n: u32, full: u32, b: u32| at % b == 0 && (n % b == 0 || at + n == full);
        if !(edge(x, w, lw, bw) && edge(y, h, lh, bh)) {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "a compressed region starts on a 4x4 block and covers whole blocks or reaches the level's edge",
            );
        }
        if w == 0 || h == 0 || d == 0 {
            return;
        }
        let texels = c.decode(w, h, d, data);
        let t = self.objects.textures.get_mut(id).expect("live");
        if let Some(dst) = t.level_mut(face, level as u32) {
            dst.write_box([x, y, z], [w, h, d], &texels);
        }
        t.version += 1;
    }

    /// `texStorage*` of a compressed format: `Some(None)` for a format that is not one,
    /// `Some(Some(c))` for one the call may allocate, `None` (with the error) where the
    /// format's extension is off or the target or size does not allow it.
    pub(super) fn compressed_storage(
        &mut self,
        target: u32,
        internal: u32,
        size: [i32; 3],
        function: &str,
    ) -> Option<Option<Compressed>> {
        let Some(c) = compressed(internal) else {
            return Some(None);
        };
        if !self.extensions.compressed.contains(&c.extension) {
            self.error(
                gl::INVALID_ENUM,
                function,
                "the compressed format's extension is not enabled",
            );
            return None;
        }
        if target == gl::TEXTURE_3D {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "3D textures take no compressed format",
            );
            return None;
        }
        let [w, h, _] = size;
        if c.s3tc() && w > 0 && h > 0 && (w % 4 != 0 || h % 4 != 0) {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "S3TC storage needs a level 0 of whole 4x4 blocks",
            );
            return None;
        }
        Some(Some(c))
    }
}

impl Compressed {
    /// A level of all-zero blocks, decoded (black; opaque where the format's zero block is).
    pub(super) fn blank(self, size: [u32; 3]) -> Level {
        // Every texel of a zero block decodes alike: one texel, repeated.
        let texel = self.decode(1, 1, 1, &[0; 16][..self.block_bytes()]);
        let count = size.iter().map(|&n| n as usize).product::<usize>();
        Level::new(size, self.internal(), texel.repeat(count))
    }
}
