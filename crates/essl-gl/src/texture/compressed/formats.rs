//! The compressed formats essl-gl decodes, their blocks and their decoders.
//!
//! Two libraries decode the blocks: `texture2ddecoder` for S3TC (BC1–3), ETC1, ETC2, EAC and
//! ASTC, and `bcdec_rs` (a port of `bcdec`) for RGTC (BC4, BC5) and BPTC (BC6H, BC7), which
//! `texture2ddecoder` decodes only to 8-bit unsigned colour: `bcdec_rs` gives the signed BC4
//! and BC5 values as floats and BC6H's as half floats. A level holds RGBA8 (sRGB for the sRGB
//! formats), signed normalised RGBA8 for the signed EAC and RGTC formats, and RGBA16F for
//! BC6H.

use super::super::format::{Comp, Expand, InternalFormat, Packing};
use super::super::object::Level;
use super::COMPRESSED_BASE;
use crate::extensions::Extension;

/// A block codec.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Codec {
    Bc1,
    Bc1a,
    Bc2,
    Bc3,
    Bc4,
    Bc4Signed,
    Bc5,
    Bc5Signed,
    Bc6hSigned,
    Bc6hUnsigned,
    Bc7,
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
    pub(super) gl: u32,
    pub(super) codec: Codec,
    srgb: bool,
    /// The extension that offers it.
    pub(crate) extension: Extension,
}

/// Every compressed format, in the order `COMPRESSED_TEXTURE_FORMATS` lists them.
pub(super) const FORMATS: &[(u32, Codec, bool, Extension)] = &[
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
    (0x8DBB, Codec::Bc4, false, Extension::CompressedRgtc),
    (0x8DBC, Codec::Bc4Signed, false, Extension::CompressedRgtc),
    (0x8DBD, Codec::Bc5, false, Extension::CompressedRgtc),
    (0x8DBE, Codec::Bc5Signed, false, Extension::CompressedRgtc),
    (0x8E8C, Codec::Bc7, false, Extension::CompressedBptc),
    (0x8E8D, Codec::Bc7, true, Extension::CompressedBptc),
    (0x8E8E, Codec::Bc6hSigned, false, Extension::CompressedBptc),
    (
        0x8E8F,
        Codec::Bc6hUnsigned,
        false,
        Extension::CompressedBptc,
    ),
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
    pub(super) fn block_bytes(self) -> usize {
        match self.codec {
            Codec::Bc1
            | Codec::Bc1a
            | Codec::Bc4
            | Codec::Bc4Signed
            | Codec::Etc1
            | Codec::Etc2Rgb
            | Codec::Etc2Rgba1
            | Codec::EacR
            | Codec::EacRSigned => 8,
            _ => 16,
        }
    }

    /// A block's width and height in texels.
    pub(super) fn block_size(self) -> (u32, u32) {
        match self.codec {
            Codec::Astc(w, h) => (u32::from(w), u32::from(h)),
            _ => (4, 4),
        }
    }

    /// Bytes of a `w × h × d` image.
    pub(super) fn data_size(self, w: u32, h: u32, d: u32) -> u64 {
        let (bw, bh) = self.block_size();
        u64::from(w.div_ceil(bw))
            * u64::from(h.div_ceil(bh))
            * u64::from(d)
            * self.block_bytes() as u64
    }

    /// Whether a level must be whole 4×4 blocks at level 0's scale (`width << level` a
    /// multiple of 4): S3TC, RGTC and BPTC.
    pub(super) fn whole_blocks_at_level_0(self) -> bool {
        !matches!(
            self.codec,
            Codec::Etc1
                | Codec::Etc2Rgb
                | Codec::Etc2Rgba1
                | Codec::Etc2Rgba8
                | Codec::EacR
                | Codec::EacRSigned
                | Codec::EacRg
                | Codec::EacRgSigned
                | Codec::Astc(..)
        )
    }

    fn signed(self) -> bool {
        matches!(
            self.codec,
            Codec::EacRSigned | Codec::EacRgSigned | Codec::Bc4Signed | Codec::Bc5Signed
        )
    }

    fn half_float(self) -> bool {
        matches!(self.codec, Codec::Bc6hSigned | Codec::Bc6hUnsigned)
    }

    /// The level format: RGBA storage under the compressed enum (no `format` matches it).
    pub(crate) fn internal(self) -> InternalFormat {
        InternalFormat {
            gl: self.gl,
            base: COMPRESSED_BASE,
            channels: 4,
            comp: if self.half_float() {
                Comp::F16
            } else if self.signed() {
                Comp::Snorm8
            } else {
                Comp::Unorm8
            },
            srgb: self.srgb,
            expand: Expand::None,
            packing: Packing::None,
        }
    }

    /// Bytes of one decoded texel.
    fn texel_bytes(self) -> usize {
        if self.half_float() {
            8
        } else {
            4
        }
    }

    /// Decodes `w × h × d` texels of blocks into the level format's bytes.
    pub(super) fn decode(self, w: u32, h: u32, d: u32, data: &[u8]) -> Vec<u8> {
        let (bw, bh) = self.block_size();
        let (w, h, bw, bh) = (w as usize, h as usize, bw as usize, bh as usize);
        let (nx, ny) = (w.div_ceil(bw), h.div_ceil(bh));
        let bytes = self.block_bytes();
        let tb = self.texel_bytes();
        let mut out = vec![0u8; w * h * d as usize * tb];
        let mut block = vec![0u8; bw * bh * tb];
        for z in 0..d as usize {
            for by in 0..ny {
                for bx in 0..nx {
                    let at = ((z * ny + by) * nx + bx) * bytes;
                    self.decode_block(&data[at..at + bytes], &mut block);
                    for (i, px) in block.chunks_exact(tb).enumerate() {
                        let (x, y) = (bx * bw + i % bw, by * bh + i / bw);
                        if x < w && y < h {
                            let o = ((z * h + y) * w + x) * tb;
                            out[o..o + tb].copy_from_slice(px);
                        }
                    }
                }
            }
        }
        out
    }

    /// One block's texels, row by row, in the level format (`out` holds a block of them).
    fn decode_block(self, b: &[u8], out: &mut [u8]) {
        // Signed normalised bytes of a value in [-1, 1].
        let snorm = |x: f32| ((x.clamp(-1.0, 1.0) * 127.0).round() as i8) as u8;
        match self.codec {
            Codec::Bc4 | Codec::Bc5 => {
                let mut rg = [0u8; 32];
                let two = self.codec == Codec::Bc5;
                if two {
                    bcdec_rs::bc5(b, &mut rg, 8, false);
                } else {
                    bcdec_rs::bc4(b, &mut rg[..16], 4, false);
                }
                for (i, t) in out.chunks_exact_mut(4).enumerate() {
                    let (r, g) = if two {
                        (rg[2 * i], rg[2 * i + 1])
                    } else {
                        (rg[i], 0)
                    };
                    t.copy_from_slice(&[r, g, 0, 255]);
                }
            }
            Codec::Bc4Signed | Codec::Bc5Signed => {
                let mut rg = [0f32; 32];
                let two = self.codec == Codec::Bc5Signed;
                if two {
                    bcdec_rs::bc5_float(b, &mut rg, 8, true);
                } else {
                    bcdec_rs::bc4_float(b, &mut rg[..16], 4, true);
                }
                for (i, t) in out.chunks_exact_mut(4).enumerate() {
                    let (r, g) = if two {
                        (rg[2 * i], rg[2 * i + 1])
                    } else {
                        (rg[i], 0.0)
                    };
                    t.copy_from_slice(&[snorm(r), snorm(g), 0, 127]);
                }
            }
            Codec::Bc6hSigned | Codec::Bc6hUnsigned => {
                let mut rgb = [0u16; 48];
                bcdec_rs::bc6h_half(b, &mut rgb, 12, self.codec == Codec::Bc6hSigned);
                // Half-float 1.0 for alpha.
                const ONE: u16 = 0x3C00;
                for (i, t) in out.chunks_exact_mut(8).enumerate() {
                    let texel = [rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], ONE];
                    for (c, v) in texel.iter().enumerate() {
                        t[2 * c..2 * c + 2].copy_from_slice(&v.to_ne_bytes());
                    }
                }
            }
            Codec::Bc7 => bcdec_rs::bc7(b, out, 16),
            _ => {
                let mut words = [0u32; 144];
                let words = &mut words[..out.len() / 4];
                words.fill(0);
                self.decode_words(b, words);
                for (t, px) in out.chunks_exact_mut(4).zip(words.iter()) {
                    t.copy_from_slice(&self.texel(*px));
                }
            }
        }
    }

    /// `texture2ddecoder`'s codecs: one block as BGRA words.
    fn decode_words(self, b: &[u8], out: &mut [u32]) {
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
            // Decoded by `bcdec_rs` (`decode_block`).
            Codec::Bc4
            | Codec::Bc4Signed
            | Codec::Bc5
            | Codec::Bc5Signed
            | Codec::Bc6hSigned
            | Codec::Bc6hUnsigned
            | Codec::Bc7 => {}
        }
    }

    /// One decoded `texture2ddecoder` texel (its BGRA word) as the level's RGBA bytes.
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

    /// A level of all-zero blocks, decoded (black; opaque where the format's zero block is).
    pub(in crate::texture) fn blank(self, size: [u32; 3]) -> Level {
        // Every texel of a zero block decodes alike: one texel, repeated.
        let texel = self.decode(1, 1, 1, &[0; 16][..self.block_bytes()]);
        let count = size.iter().map(|&n| n as usize).product::<usize>();
        Level::new(size, self.internal(), texel.repeat(count))
    }
}
