//! Immutable textures: `tex_storage_2d`, `tex_storage_3d`.

use super::format::{internal_format, Expand};
use super::object::{mip_size, Level};
use crate::context::Context;
use crate::gl;

impl Context {
    /// Allocates all levels of an immutable 2D or cube map texture (`texStorage2D`).
    pub fn tex_storage_2d(
        &mut self,
        target: u32,
        levels: i32,
        internalformat: u32,
        width: i32,
        height: i32,
    ) {
        const F: &str = "texStorage2D";
        if !matches!(target, gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        self.tex_storage(target, levels, internalformat, [width, height, 1], F);
    }

    /// Allocates all levels of an immutable 3D or 2D array texture (`texStorage3D`).
    pub fn tex_storage_3d(
        &mut self,
        target: u32,
        levels: i32,
        internalformat: u32,
        width: i32,
        height: i32,
        depth: i32,
    ) {
        const F: &str = "texStorage3D";
        if !matches!(target, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        self.tex_storage(target, levels, internalformat, [width, height, depth], F);
    }

    /// `texStorage2D` and `texStorage3D` after their target checks; `size` is width,
    /// height, depth (1 in 2D).
    fn tex_storage(
        &mut self,
        target: u32,
        levels: i32,
        internal: u32,
        size: [i32; 3],
        function: &str,
    ) {
        let [w, h, d] = size;
        let Some(compressed) = self.compressed_storage(target, internal, size, function) else {
            return;
        };
        let f = match compressed
            .map(|c| Ok(c.internal()))
            .unwrap_or_else(|| internal_format(internal))
        {
            Ok(f) if f.base == super::compressed::COMPRESSED_BASE => f,
            Ok(f) if f.expand == Expand::None && !matches!(internal, gl::RGBA | gl::RGB) => f,
            Err(true) => {
                return self.error(
                    gl::INVALID_ENUM,
                    function,
                    "internal format not supported by essl-gl",
                )
            }
            _ => {
                return self.error(
                    gl::INVALID_ENUM,
                    function,
                    "texStorage needs a sized internal format",
                )
            }
        };
        if w < 1 || h < 1 || d < 1 || levels < 1 {
            return self.error(gl::INVALID_VALUE, function, "sizes and levels must be ≥ 1");
        }
        if !self.check_level_size(target, 0, w, h, d, function) {
            return;
        }
        let largest = if target == gl::TEXTURE_3D {
            w.max(h).max(d)
        } else {
            w.max(h)
        } as u32;
        if levels as u32 > 32 - largest.leading_zeros() {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "too many levels for the size",
            );
        }
        let Some(id) = self.bound_texture(target, function) else {
            return;
        };
        let t = self
            .objects
            .textures
            .get_mut(id)
            .expect("bound textures are live");
        if t.immutable_levels.is_some() {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "texture is already immutable",
            );
        }
        let faces = if target == gl::TEXTURE_CUBE_MAP { 6 } else { 1 };
        for level in 0..levels as u32 {
            let (lw, lh) = (mip_size(w as u32, level), mip_size(h as u32, level));
            let ld = if target == gl::TEXTURE_3D {
                mip_size(d as u32, level)
            } else {
                d as u32
            };
            for face in 0..faces {
                let blank = match compressed {
                    Some(c) => c.blank([lw, lh, ld]),
                    None => Level::blank([lw, lh, ld], f),
                };
                t.set_level(face, level, blank);
            }
        }
        t.immutable_levels = Some(levels as u32);
    }
}
