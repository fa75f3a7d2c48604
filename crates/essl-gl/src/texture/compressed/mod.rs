//! Compressed textures: `compressedTexImage2D/3D`, `compressedTexSubImage2D/3D` and
//! `texStorage*` with the formats of `WEBGL_compressed_texture_s3tc` (DXT1, DXT3, DXT5),
//! `WEBGL_compressed_texture_s3tc_srgb`, `WEBGL_compressed_texture_etc` (ETC2 and EAC),
//! `WEBGL_compressed_texture_etc1`, `WEBGL_compressed_texture_astc` (the LDR profile),
//! `EXT_texture_compression_rgtc` (BC4, BC5) and `EXT_texture_compression_bptc` (BC6H, BC7),
//! each refused (`INVALID_ENUM`) until its extension is on.
//!
//! The blocks are decoded on upload ([`formats`]: block decoders are what no GPU-independent
//! path in wgpu offers — wgpu's compressed formats need an adapter feature that lavapipe and
//! most desktop GPUs lack for ETC2, and the others for BC) into an uncompressed level:
//! sampling then reads what the compressed texture holds, on every adapter. A compressed
//! level keeps its compressed internal format, so it is neither colour-renderable nor a
//! target of `texSubImage*`, `copyTex*` or `generateMipmap`.
//!
//! Validation follows the extensions' specifications and WebGL 2.0 §5.37: the data's length
//! is exactly the blocks' (`INVALID_VALUE`); S3TC, RGTC and BPTC levels are whole blocks at
//! level 0's scale (`width << level` a multiple of 4, else `INVALID_OPERATION`); a sub-image
//! starts on a block and covers whole blocks or reaches the level's edge
//! (`INVALID_OPERATION`; ETC1 takes no sub-images), and its format is the level's
//! (`INVALID_OPERATION`, checked before the data's length); 3D textures take none of these
//! formats.

mod formats;

pub(crate) use formats::{compressed, Compressed};
use formats::{Codec, FORMATS};

use super::image_target;
use super::object::Level;
use crate::{gl, Context};

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
        let Some(id) = self.bound_texture(bind, function) else {
            return;
        };
        let t = self
            .objects
            .textures
            .get(id)
            .expect("bound textures are live");
        // A sub-image of another format is refused before its data's length is checked.
        let other_format = offset.is_some()
            && t.level(face, level as u32)
                .is_some_and(|l| l.format.gl != c.gl);
        if !other_format && data.len() as u64 != c.data_size(w, h, d) {
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
        let Some(offset) = offset else {
            // S3TC, RGTC, BPTC: whole blocks at level 0's scale.
            let whole = |n: u32| (u64::from(n) << level.min(31)) % 4 == 0;
            if c.whole_blocks_at_level_0() && !(whole(w) && whole(h)) {
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
        if c.whole_blocks_at_level_0() && w > 0 && h > 0 && (w % 4 != 0 || h % 4 != 0) {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "S3TC, RGTC and BPTC storage needs a level 0 of whole 4x4 blocks",
            );
            return None;
        }
        Some(Some(c))
    }
}
