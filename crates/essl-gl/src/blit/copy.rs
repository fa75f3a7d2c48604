//! `copy_tex_image_2d`, `copy_tex_sub_image_2d` and `copy_tex_sub_image_3d`: a rectangle of
//! the read buffer drawn into a texture level (or a layer of one), its channels spread as
//! the texture's format has them.

use super::{color_source, BlitDraw, Corners};
use crate::context::Context;
use crate::framebuffer::Attachment;
use crate::gl;
use crate::pipeline::{Channels, ClearKind};
use crate::texture::{bit_sizes, image_target, internal_format, Expand, InternalFormat, Level};

/// Where a copy goes: a texture level (a cube face or a layer) and the box's corner in it.
struct CopyDest {
    target: u32,
    level: i32,
    offset: [i32; 3],
}

/// The channel spreading for a destination format.
fn channels(f: &InternalFormat) -> Channels {
    match (f.expand, f.channels) {
        (Expand::Luminance, _) => Channels::Luminance,
        (Expand::LuminanceAlpha, _) => Channels::LuminanceAlpha,
        (Expand::Alpha, _) => Channels::Alpha,
        (_, 3) => Channels::Rgb1,
        _ => Channels::Rgba,
    }
}

/// Whether a read buffer of `src` can be copied into `dst` (ES 3.0 §3.8.5, table 3.15): the
/// same kind of values, and every channel `dst` has present in `src`.
fn copyable(src: &InternalFormat, dst: &InternalFormat) -> bool {
    let kind = |f: &InternalFormat| match f.kind() {
        crate::texture::SampleKind::Sint => ClearKind::Int,
        crate::texture::SampleKind::Uint => ClearKind::Uint,
        _ => ClearKind::Float,
    };
    if kind(src) != kind(dst)
        || dst.has_depth()
        || dst.srgb != src.srgb
        || dst.base == crate::texture::COMPRESSED_BASE
    {
        return false;
    }
    let src_has_alpha = src.channels == 4 || src.expand == Expand::LuminanceAlpha;
    let needs_alpha =
        dst.channels == 4 || matches!(dst.expand, Expand::Alpha | Expand::LuminanceAlpha);
    let needs = match dst.expand {
        Expand::None => dst.channels.min(3),
        _ => 1,
    };
    if !((!needs_alpha || src_has_alpha) && src.channels.min(3) >= needs) {
        return false;
    }
    // ES 3.0 §3.8.5: a sized internal format's components must have the read buffer's
    // sizes (RGB565 from RGBA8 is INVALID_OPERATION); the unsized ones take any.
    let unsized_format = matches!(
        dst.gl,
        gl::RGBA | gl::RGB | gl::LUMINANCE_ALPHA | gl::LUMINANCE | gl::ALPHA
    );
    let (s, d) = (bit_sizes(src), bit_sizes(dst));
    unsized_format
        || [
            (s.red, d.red),
            (s.green, d.green),
            (s.blue, d.blue),
            (s.alpha, d.alpha),
        ]
        .iter()
        .all(|&(s, d)| d == 0 || s == d)
}

/// Whether a format holds floats (`R16F` … `RGBA32F`, `R11F_G11F_B10F`).
fn is_float(f: &InternalFormat) -> bool {
    use crate::texture::Comp;
    matches!(f.comp, Comp::F16 | Comp::F32) || f.packing == crate::texture::Packing::Rg11B10F
}

impl Context {
    /// Specifies a level of a 2D texture or cube face from a rectangle of the read buffer
    /// (`copyTexImage2D`); pixels outside the read framebuffer read as 0. The internal format
    /// must suit the read buffer's (same kind of values, no channel it lacks:
    /// `INVALID_OPERATION`).
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn copy_tex_image_2d(
        &mut self,
        target: u32,
        level: i32,
        internalformat: u32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        border: i32,
    ) {
        const F: &str = "copyTexImage2D";
        let unsized_format = matches!(
            internalformat,
            gl::ALPHA | gl::LUMINANCE | gl::LUMINANCE_ALPHA | gl::RGB | gl::RGBA
        );
        if self.webgl1_refuses(F, &[target]) {
            return;
        }
        if self.webgl1.on && !unsized_format {
            return self.error(gl::INVALID_ENUM, F, "not an internal format of WebGL 1");
        }
        let Some((bind, face)) = image_target(target)
            .filter(|(b, _)| matches!(*b, gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP))
        else {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        };
        // Chromium takes float formats only where they can be rendered
        // (`EXT_color_buffer_float`): otherwise they are unknown enums here; the SNORM
        // formats, which no framebuffer holds, are refused the same way.
        let format = internal_format(internalformat)
            .ok()
            .filter(|f| !is_float(f) || self.extensions.color_buffer_float)
            .filter(|f| f.comp != crate::texture::Comp::Snorm8);
        let Some(format) = format else {
            return self.error(
                gl::INVALID_ENUM,
                F,
                format_args!("internal format 0x{internalformat:04X}"),
            );
        };
        if !self.check_level_size(bind, level, width, height, 1, F) {
            return;
        }
        if border != 0 {
            return self.error(gl::INVALID_VALUE, F, "border must be 0");
        }
        let Some(id) = self.bound_texture(bind, F) else {
            return;
        };
        if self
            .objects
            .textures
            .get(id)
            .is_some_and(|t| t.immutable_levels.is_some())
        {
            return self.error(gl::INVALID_OPERATION, F, "immutable texture");
        }
        if !self.check_copy_source(&format, F) {
            return;
        }
        if self.reads_image(id, level as u32, face as u32) {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "the read buffer is the destination image: a feedback loop",
            );
        }
        let (w, h) = (width as u32, height as u32);
        let data = vec![0; w as usize * h as usize * format.texel_size()];
        let t = self
            .objects
            .textures
            .get_mut(id)
            .expect("bound textures are live");
        t.set_level(face, level as u32, Level::new([w, h, 1], format, data));
        let dest = CopyDest {
            target,
            level,
            offset: [0, 0, 0],
        };
        self.copy_rect(id, &dest, [x, y, width, height]);
    }

    /// Replaces a rectangle of a level of a 2D texture or cube face by one of the read
    /// buffer (`copyTexSubImage2D`); pixels outside the read framebuffer are left alone.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn copy_tex_sub_image_2d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
    ) {
        const F: &str = "copyTexSubImage2D";
        if !image_target(target)
            .is_some_and(|(b, _)| matches!(b, gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP))
        {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        let dest = CopyDest {
            target,
            level,
            offset: [xoffset, yoffset, 0],
        };
        self.copy_sub(dest, [x, y, width, height], F);
    }

    /// [`Context::copy_tex_sub_image_2d`] into layer `zoffset` of a 3D or 2D array texture
    /// (`copyTexSubImage3D`).
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn copy_tex_sub_image_3d(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        zoffset: i32,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
    ) {
        const F: &str = "copyTexSubImage3D";
        if !matches!(target, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        let dest = CopyDest {
            target,
            level,
            offset: [xoffset, yoffset, zoffset],
        };
        self.copy_sub(dest, [x, y, width, height], F);
    }

    fn copy_sub(&mut self, dest: CopyDest, rect: [i32; 4], f: &str) {
        let (bind, face) = image_target(dest.target).expect("checked by the caller");
        let Some(id) = self.bound_texture(bind, f) else {
            return;
        };
        if dest.level < 0 {
            return self.error(gl::INVALID_VALUE, f, "negative level");
        }
        let Some(l) = self
            .objects
            .textures
            .get(id)
            .and_then(|t| t.level(face, dest.level as u32))
            .cloned()
        else {
            return self.error(gl::INVALID_OPERATION, f, "the level has no image");
        };
        let [ox, oy, oz] = dest.offset;
        let [_, _, w, h] = rect;
        if ox < 0
            || oy < 0
            || oz < 0
            || w < 0
            || h < 0
            || ox as i64 + w as i64 > l.width as i64
            || oy as i64 + h as i64 > l.height as i64
            || oz as u32 >= l.depth.max(1)
        {
            return self.error(gl::INVALID_VALUE, f, "region outside the level");
        }
        if !self.check_copy_source(&l.format, f) {
            return;
        }
        let layer = if l.depth > 1 || matches!(bind, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY) {
            oz as u32
        } else {
            face as u32
        };
        if self.reads_image(id, dest.level as u32, layer) {
            return self.error(
                gl::INVALID_OPERATION,
                f,
                "the read buffer is the destination image: a feedback loop",
            );
        }
        self.copy_rect(id, &dest, rect);
    }

    /// Whether the read framebuffer's read buffer is `layer` (cube face or layer) of `level`
    /// of texture `id`.
    fn reads_image(&self, id: crate::objects::Id, level: u32, layer: u32) -> bool {
        let [_, read] = self.bindings.framebuffers();
        let Some(fb) = read.and_then(|fb| self.objects.framebuffers.get_any(fb)) else {
            return false;
        };
        let attached = fb
            .read_buffer
            .checked_sub(gl::COLOR_ATTACHMENT0)
            .and_then(|i| fb.colors.get(i as usize).copied().flatten());
        attached == Some(Attachment::Texture { id, level, layer })
    }

    /// Checks the read framebuffer for a copy into a texture of format `dst`.
    fn check_copy_source(&mut self, dst: &InternalFormat, f: &str) -> bool {
        if !self.require_complete(false, f) {
            return false;
        }
        let read = self.read_surface();
        let Some(src) = read.color else {
            self.error(gl::INVALID_OPERATION, f, "no colour buffer to read");
            return false;
        };
        if src.samples > 1 && !read.default {
            self.error(
                gl::INVALID_OPERATION,
                f,
                "the read framebuffer is multisampled",
            );
            return false;
        }
        if !copyable(&src.format, dst) {
            self.error(
                gl::INVALID_OPERATION,
                f,
                "the texture's format does not suit the read buffer's",
            );
            return false;
        }
        true
    }

    /// Draws read-buffer rectangle `[x, y, w, h]` into the destination level.
    fn copy_rect(&mut self, id: crate::objects::Id, dest: &CopyDest, rect: [i32; 4]) {
        let [x, y, w, h] = rect;
        if w == 0 || h == 0 {
            return;
        }
        let (bind, face) = image_target(dest.target).expect("checked");
        let layer = if bind == gl::TEXTURE_CUBE_MAP {
            face as u32
        } else {
            dest.offset[2] as u32
        };
        let attachment = Attachment::Texture {
            id,
            level: dest.level as u32,
            layer,
        };
        let Some(image) = self.attachment_image(attachment, true) else {
            return;
        };
        let read = self.read_surface();
        let Some(src) = read.color else { return };
        let source = self.single_sampled(&src);
        let [ox, oy, _] = dest.offset;
        let draw = BlitDraw {
            read: color_source(&source),
            source: &source,
            src: Corners([x, y, x + w, y + h]),
            dst: Corners([ox, oy, ox + w, oy + h]),
            linear: false,
            channels: channels(&image.format),
            colors: vec![Some(image)],
            depth: None,
            bit: 0,
            scissor: false,
        };
        self.blit_draw(&draw);
    }
}
