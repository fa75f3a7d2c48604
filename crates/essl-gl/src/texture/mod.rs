//! Textures: `create_texture`, `bind_texture`, `active_texture`, `tex_image_2d`,
//! `tex_sub_image_2d`, `tex_image_3d`, `tex_storage_2d`, `tex_parameteri`, `generate_mipmap`,
//! GL's texture completeness, and the samplers and placeholder textures draws bind.
//!
//! Each level image is kept on the CPU in the GPU format's layout; a texture is (re)made on
//! the GPU when a draw samples it, from level `TEXTURE_BASE_LEVEL` to the last level that
//! completeness uses. Data row 0 is texture row 0 (`t = 0`), as in GL, with no flip.
//!
//! The module is split by concern: [`format`] (internal formats), [`pixels`] (client pixel
//! layout and conversion), [`object`] (level images, parameters, completeness), [`gpu`] (the
//! GPU texture, its views, uploads), [`sampling`] (samplers, placeholders), and the GL
//! methods: [`upload`] (`tex_image_*`, `tex_sub_image_*`), [`unpack_buffer`] (the same from
//! a `PIXEL_UNPACK_BUFFER`), [`storage`] (`tex_storage_*`), [`params`] (`tex_parameter*`),
//! [`mipmap`] (`generate_mipmap`), [`source`] (uploads from DOM images) and [`gpu_sync`] (the GPU copy brought up to date for a
//! use). Those add methods to [`Context`]: its `impl` is spread over these files on purpose,
//! one file per group of GL calls.

mod compressed;
pub(crate) use compressed::COMPRESSED_BASE;
mod format;
mod gpu;
mod gpu_sync;
mod mipmap;
mod object;
mod params;
mod pixels;
mod sampling;
mod source;
mod storage;
mod unpack_buffer;
mod upload;

pub(crate) use format::*;
pub(crate) use gpu::{upload_image, TexelBox, ViewKey};
pub(crate) use object::*;
pub(crate) use pixels::f16_to_f32;
pub(crate) use sampling::*;
pub use source::{ImageSource, SourceUpload};

use crate::context::{Context, MAX_TEXTURE_UNITS};
use crate::gl;
use crate::objects::{Id, Texture};

/// The texture binding target and cube face of an image target.
pub(crate) fn image_target(target: u32) -> Option<(u32, usize)> {
    match target {
        gl::TEXTURE_2D => Some((gl::TEXTURE_2D, 0)),
        gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z => Some((
            gl::TEXTURE_CUBE_MAP,
            (target - gl::TEXTURE_CUBE_MAP_POSITIVE_X) as usize,
        )),
        gl::TEXTURE_3D => Some((gl::TEXTURE_3D, 0)),
        gl::TEXTURE_2D_ARRAY => Some((gl::TEXTURE_2D_ARRAY, 0)),
        _ => None,
    }
}

pub(super) fn is_texture_target(target: u32) -> bool {
    matches!(
        target,
        gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP | gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY
    )
}

impl Context {
    /// Creates a texture object (`createTexture`).
    pub fn create_texture(&mut self) -> Texture {
        Texture {
            ctx: self.id,
            id: self.objects.textures.insert(TextureObject::new()),
        }
    }

    /// Whether `texture` names a live texture that was bound once (`isTexture`).
    pub fn is_texture(&self, texture: Texture) -> bool {
        texture.ctx == self.id
            && self
                .objects
                .textures
                .get(texture.id)
                .is_some_and(|t| t.target.is_some())
    }

    /// Selects the texture unit that `bind_texture` and the `tex*` calls address
    /// (`activeTexture`): `TEXTURE0 + i` for `i` below 32, else `INVALID_ENUM`.
    pub fn active_texture(&mut self, texture: u32) {
        match texture.checked_sub(gl::TEXTURE0) {
            Some(i) if i < MAX_TEXTURE_UNITS => self.bindings.set_active_unit(i),
            _ => self.error(
                gl::INVALID_ENUM,
                "activeTexture",
                format_args!("0x{texture:04X}"),
            ),
        }
    }

    /// Binds a texture to a target of the active unit (`bindTexture`): `TEXTURE_2D`,
    /// `TEXTURE_CUBE_MAP`, `TEXTURE_3D`, `TEXTURE_2D_ARRAY`. A texture keeps the target it
    /// was first bound to (`INVALID_OPERATION` for another).
    pub fn bind_texture(&mut self, target: u32, texture: Option<Texture>) {
        const F: &str = "bindTexture";
        if self.webgl1_refuses("bindTexture", &[target]) {
            return;
        }
        if !is_texture_target(target) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        let id = match texture {
            None => None,
            Some(t) => {
                if !self.owns(t.ctx, F) {
                    return;
                }
                let Some(obj) = self.objects.textures.get_mut(t.id) else {
                    return self.error(gl::INVALID_OPERATION, F, "deleted texture");
                };
                match obj.target {
                    None => obj.target = Some(target),
                    Some(have) if have != target => {
                        return self.error(
                            gl::INVALID_OPERATION,
                            F,
                            "texture bound to another target before",
                        );
                    }
                    _ => {}
                }
                Some(t.id)
            }
        };
        self.bindings.bind_texture(target, id);
    }

    /// Deletes a texture (`deleteTexture`), unbinding it from every unit.
    pub fn delete_texture(&mut self, texture: Texture) {
        if !self.owns(texture.ctx, "deleteTexture") || !self.objects.textures.is_live(texture.id) {
            return;
        }
        self.bindings.forget_texture(texture.id);
        let bound = self.bindings.framebuffers();
        self.objects.delete_texture(texture.id, bound);
    }

    /// The texture bound to `target` of the active unit, or `INVALID_OPERATION`.
    pub(crate) fn bound_texture(&self, target: u32, function: &str) -> Option<Id> {
        let id = self.bindings.texture(self.bindings.active_unit(), target);
        if id.is_none() {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "no texture bound to the target",
            );
        }
        id
    }
}
