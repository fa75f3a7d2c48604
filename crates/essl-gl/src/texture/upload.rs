//! Specifying level images from client data: `tex_image_2d`, `tex_image_3d`,
//! `tex_sub_image_2d`, `tex_sub_image_3d`, with GL's checks of level, size and format.

use super::format::{
    format_channels, internal_format, is_pixel_type, pixel_size, Comp, InternalFormat,
};
use super::image_target;
use super::object::Level;
use super::pixels::{convert_pixels, unpack_layout};
use crate::array::{array_mismatch, ArrayElement, ArrayType, ArrayView};
use crate::context::Context;
use crate::gl;

/// What `texImage2D` and `texImage3D` specify: a level of the texture bound to `target` (or
/// of a cube map face), its internal format and size, and the client data (zeros for `None`).
pub(super) struct TexImage<'a> {
    pub(super) target: u32,
    pub(super) level: i32,
    pub(super) internalformat: i32,
    /// Width, height, depth (1 in 2D).
    pub(super) size: [i32; 3],
    pub(super) border: i32,
    pub(super) format: u32,
    pub(super) ty: u32,
    pub(super) pixels: Option<&'a [u8]>,
    /// The typed array the pixels came in (`None`: from a `PIXEL_UNPACK_BUFFER`).
    pub(super) array: Option<ArrayType>,
    pub(super) function: &'static str,
}

/// What `texSubImage2D` and `texSubImage3D` replace: a box of a level, and the client data.
pub(super) struct TexSubImage<'a> {
    pub(super) target: u32,
    pub(super) level: i32,
    /// x, y, z of the box's first texel (z is 0 in 2D).
    pub(super) offset: [i32; 3],
    /// Width, height, depth of the box (depth is 1 in 2D).
    pub(super) size: [i32; 3],
    pub(super) format: u32,
    pub(super) ty: u32,
    pub(super) pixels: &'a [u8],
    /// The typed array the pixels came in (`None`: from a `PIXEL_UNPACK_BUFFER`).
    pub(super) array: Option<ArrayType>,
    pub(super) function: &'static str,
}

/// A block of client pixel data to read: its bytes, size in pixels, `(format, type)`, and
/// whether the 3D unpack parameters (`UNPACK_IMAGE_HEIGHT`, `UNPACK_SKIP_IMAGES`) apply.
struct ClientPixels<'a> {
    src: &'a [u8],
    size: [u32; 3],
    format: u32,
    ty: u32,
    three_d: bool,
}

impl Context {
    /// Specifies a level of a 2D texture or of a cube map face (`texImage2D`) from
    /// `width` × `height` pixels of `(format, ty)` data, laid out by the `UNPACK_*` pixel
    /// storage parameters, or zeros for `None`. Row 0 of the data is row 0 of the texture.
    ///
    /// Supported internal formats: `RGBA`, `RGB`, `LUMINANCE_ALPHA`, `LUMINANCE`, `ALPHA`
    /// (unsigned bytes and the packed 16-bit types), and the sized colour formats of
    /// ES 3.0 except `R11F_G11F_B10F`, `RGB9_E5`, `RGB10_A2`, `RGB10_A2UI` (those and depth
    /// formats record `INVALID_ENUM`).
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_image_2d<T: ArrayElement>(
        &mut self,
        target: u32,
        level: i32,
        internalformat: i32,
        width: i32,
        height: i32,
        border: i32,
        format: u32,
        ty: u32,
        pixels: Option<&[T]>,
    ) {
        let pixels = pixels.map(ArrayView::of);
        self.tex_image_2d_view(
            target,
            level,
            internalformat,
            width,
            height,
            border,
            format,
            ty,
            pixels,
        );
    }

    /// [`Context::tex_image_2d`] with the client data as a typed array of any kind (a
    /// binding's `ArrayBufferView`): the array's type is checked against `ty` as WebGL does.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_image_2d_view(
        &mut self,
        target: u32,
        level: i32,
        internalformat: i32,
        width: i32,
        height: i32,
        border: i32,
        format: u32,
        ty: u32,
        pixels: Option<ArrayView>,
    ) {
        const F: &str = "texImage2D";
        if self.webgl1_refuses(F, &[target]) {
            return;
        }
        let Some(ty) = self.webgl1_image_type(F, internalformat, format, ty) else {
            return;
        };
        let (internalformat, format) = self.webgl1_srgb(internalformat, format);
        if self.client_data_refused(F) {
            return;
        }
        match image_target(target) {
            Some((gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP, _)) => {}
            _ => return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}")),
        }
        self.tex_image(TexImage {
            target,
            level,
            internalformat,
            size: [width, height, 1],
            border,
            format,
            ty,
            pixels: pixels.map(|p| p.bytes),
            array: Some(pixels.map_or(ArrayType::Uint8, |p| p.array)),
            function: F,
        });
    }

    /// Specifies a level of a 3D texture or 2D array texture (`texImage3D`); see
    /// [`Context::tex_image_2d`].
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_image_3d<T: ArrayElement>(
        &mut self,
        target: u32,
        level: i32,
        internalformat: i32,
        width: i32,
        height: i32,
        depth: i32,
        border: i32,
        format: u32,
        ty: u32,
        pixels: Option<&[T]>,
    ) {
        let pixels = pixels.map(ArrayView::of);
        self.tex_image_3d_view(
            target,
            level,
            internalformat,
            width,
            height,
            depth,
            border,
            format,
            ty,
            pixels,
        );
    }

    /// [`Context::tex_image_3d`] with the client data as a typed array of any kind.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_image_3d_view(
        &mut self,
        target: u32,
        level: i32,
        internalformat: i32,
        width: i32,
        height: i32,
        depth: i32,
        border: i32,
        format: u32,
        ty: u32,
        pixels: Option<ArrayView>,
    ) {
        const F: &str = "texImage3D";
        if self.client_data_refused(F) {
            return;
        }
        if !matches!(target, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        self.tex_image(TexImage {
            target,
            level,
            internalformat,
            size: [width, height, depth],
            border,
            format,
            ty,
            pixels: pixels.map(|p| p.bytes),
            array: Some(pixels.map_or(ArrayType::Uint8, |p| p.array)),
            function: F,
        });
    }

    /// WebGL2: the calls that take client data are refused (`INVALID_OPERATION`) while a
    /// `PIXEL_UNPACK_BUFFER` is bound; the `_from_buffer` forms read it.
    pub(super) fn client_data_refused(&mut self, function: &str) -> bool {
        if self.bindings.buffer(gl::PIXEL_UNPACK_BUFFER).is_some() {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "a PIXEL_UNPACK_BUFFER is bound: give an offset into it",
            );
            return true;
        }
        false
    }

    /// Checks level and size against GL's limits for the target.
    pub(crate) fn check_level_size(
        &mut self,
        bind: u32,
        level: i32,
        w: i32,
        h: i32,
        d: i32,
        function: &str,
    ) -> bool {
        let max = match bind {
            gl::TEXTURE_3D => self.gpu.limits.max_texture_dimension_3d,
            _ => self.gpu.limits.max_texture_dimension_2d,
        };
        let max_level = 31 - max.leading_zeros();
        if level < 0 || level as u32 > max_level {
            self.error(gl::INVALID_VALUE, function, format_args!("level {level}"));
            return false;
        }
        let lmax = (max >> level) as i32;
        let max_layers = self.gpu.limits.max_texture_array_layers as i32;
        let depth_ok = match bind {
            gl::TEXTURE_3D => d <= lmax,
            gl::TEXTURE_2D_ARRAY => d <= max_layers,
            _ => true,
        };
        if w < 0 || h < 0 || d < 0 || w > lmax || h > lmax || !depth_ok {
            self.error(
                gl::INVALID_VALUE,
                function,
                format_args!("size {w}x{h}x{d} out of range"),
            );
            return false;
        }
        if bind == gl::TEXTURE_CUBE_MAP && w != h {
            self.error(gl::INVALID_VALUE, function, "cube map faces must be square");
            return false;
        }
        // WebGL 1: a mipmap level past 0 has power-of-two sides.
        let pot = |n: i32| n & (n - 1) == 0;
        if self.webgl1.on && level > 0 && !(pot(w) && pot(h)) {
            self.error(
                gl::INVALID_VALUE,
                function,
                format_args!(
                    "level {level} of a WebGL 1 texture must have power-of-two sides, not {w}x{h}"
                ),
            );
            return false;
        }
        true
    }

    /// Checks `(format, ty)` against an internal format.
    pub(super) fn check_format(
        &mut self,
        f: &InternalFormat,
        format: u32,
        ty: u32,
        function: &str,
    ) -> bool {
        if format_channels(format).is_none() || !is_pixel_type(ty) {
            self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("format 0x{format:04X} / type 0x{ty:04X}"),
            );
            return false;
        }
        if !f.accepts(format, ty) {
            self.error(
                gl::INVALID_OPERATION,
                function,
                format_args!(
                    "format 0x{format:04X} / type 0x{ty:04X} do not match the internal format"
                ),
            );
            return false;
        }
        true
    }

    /// Reads `w × h × d` pixels of client data into the storage layout of `f`.
    fn unpack_pixels(
        &mut self,
        pixels: ClientPixels,
        f: &InternalFormat,
        function: &str,
    ) -> Option<Vec<u8>> {
        let ClientPixels {
            src,
            size: [w, h, d],
            format,
            ty,
            three_d,
        } = pixels;
        let store = self.pixel_store;
        // WebGL 2: rows shorter than the rectangle they hold, and images shorter than theirs,
        // are refused (a length of 0 is the width, or the height); a 3D upload is neither
        // flipped nor premultiplied.
        let or = |n: u32, d: u32| if n > 0 { i64::from(n) } else { i64::from(d) };
        if or(store.unpack_row_length, w) < i64::from(w) + i64::from(store.unpack_skip_pixels) {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "UNPACK_ROW_LENGTH is less than width + UNPACK_SKIP_PIXELS",
            );
            return None;
        }
        if three_d
            && or(store.unpack_image_height, h) < i64::from(h) + i64::from(store.unpack_skip_rows)
        {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "UNPACK_IMAGE_HEIGHT is less than height + UNPACK_SKIP_ROWS",
            );
            return None;
        }
        if three_d && (store.unpack_flip_y || store.unpack_premultiply_alpha) {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "UNPACK_FLIP_Y_WEBGL or UNPACK_PREMULTIPLY_ALPHA_WEBGL with a 3D upload",
            );
            return None;
        }
        let u = unpack_layout(&store, w, h, d, pixel_size(format, ty), three_d);
        if src.len() < u.needed {
            self.error(
                gl::INVALID_OPERATION,
                function,
                format_args!("{} bytes of pixel data, {} needed", src.len(), u.needed),
            );
            return None;
        }
        let mut out = Vec::with_capacity(w as usize * h as usize * d as usize * f.texel_size());
        for z in 0..d as usize {
            for y in 0..h as usize {
                let row = if store.unpack_flip_y {
                    h as usize - 1 - y
                } else {
                    y
                };
                let at = u.start + z * u.image_stride + row * u.row_stride;
                convert_pixels(
                    &src[at..at + w as usize * u.pixel],
                    w as usize,
                    f,
                    ty,
                    &mut out,
                );
            }
        }
        if store.unpack_premultiply_alpha && f.comp == Comp::Unorm8 && f.gpu_channels() == 4 {
            for px in out.chunks_exact_mut(4) {
                let a = px[3] as u32;
                for c in &mut px[..3] {
                    *c = ((*c as u32 * a + 127) / 255) as u8;
                }
            }
        }
        Some(out)
    }

    /// `texImage2D` and `texImage3D` after their target checks.
    pub(super) fn tex_image(&mut self, image: TexImage) {
        let TexImage {
            target,
            level,
            internalformat,
            size: [width, height, depth],
            border,
            format,
            ty,
            pixels,
            array,
            function,
        } = image;
        let (bind, face) = image_target(target).expect("checked by the caller");
        if !self.check_level_size(bind, level, width, height, depth, function) {
            return;
        }
        if border != 0 {
            return self.error(gl::INVALID_VALUE, function, "border must be 0");
        }
        let sized = self.webgl1_depth_internal(internalformat as u32, ty);
        let f = match internal_format(sized) {
            Ok(f) if f.has_depth() && self.webgl1.on => {
                let data = pixels.is_some();
                if !self.webgl1_depth_image_ok(target, level, data, function) {
                    return;
                }
                InternalFormat {
                    gl: internalformat as u32,
                    ..f
                }
            }
            Ok(f) if f.texture_format() => self.webgl1_float_format(f, ty),
            Ok(_) => {
                return self.error(
                    gl::INVALID_ENUM,
                    function,
                    "a renderbuffer-only internal format",
                )
            }
            Err(true) => {
                return self.error(
                    gl::INVALID_ENUM,
                    function,
                    "internal format not supported by essl-gl",
                )
            }
            Err(false) => {
                return self.error(
                    gl::INVALID_VALUE,
                    function,
                    format_args!("internal format 0x{internalformat:04X}"),
                )
            }
        };
        if !self.check_format(&f, format, ty, function) {
            return;
        }
        if let Some(why) = pixels.and(array).and_then(|a| array_mismatch(ty, a)) {
            return self.error(gl::INVALID_OPERATION, function, why);
        }
        let Some(id) = self.bound_texture(bind, function) else {
            return;
        };
        if self
            .objects
            .textures
            .get(id)
            .is_some_and(|t| t.immutable_levels.is_some())
        {
            return self.error(gl::INVALID_OPERATION, function, "immutable texture");
        }
        let (w, h, d) = (width as u32, height as u32, depth as u32);
        let level_image = match pixels {
            Some(src) => {
                let three_d = matches!(bind, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY);
                let pixels = ClientPixels {
                    src,
                    size: [w, h, d],
                    format,
                    ty,
                    three_d,
                };
                match self.unpack_pixels(pixels, &f, function) {
                    Some(data) => Level::new([w, h, d], f, data),
                    None => return,
                }
            }
            None => Level::blank([w, h, d], f),
        };
        let t = self
            .objects
            .textures
            .get_mut(id)
            .expect("bound textures are live");
        t.set_level(face, level as u32, level_image);
    }

    /// Replaces a region of a level of a 2D texture or cube map face (`texSubImage2D`).
    /// The region must lie in the level (`INVALID_VALUE`) and `(format, ty)` must suit the
    /// level's internal format (`INVALID_OPERATION`).
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_sub_image_2d<T: ArrayElement>(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        pixels: &[T],
    ) {
        let pixels = ArrayView::of(pixels);
        self.tex_sub_image_2d_view(
            target, level, xoffset, yoffset, width, height, format, ty, pixels,
        );
    }

    /// [`Context::tex_sub_image_2d`] with the client data as a typed array of any kind.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_sub_image_2d_view(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        pixels: ArrayView,
    ) {
        const F: &str = "texSubImage2D";
        if self.webgl1_refuses(F, &[target]) {
            return;
        }
        let Some(ty) = self.webgl1_image_type(F, format as i32, format, ty) else {
            return;
        };
        let (_, format) = self.webgl1_srgb(0, format);
        if self.client_data_refused(F) {
            return;
        }
        match image_target(target) {
            Some((gl::TEXTURE_2D | gl::TEXTURE_CUBE_MAP, _)) => {}
            _ => return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}")),
        }
        self.tex_sub_image(TexSubImage {
            target,
            level,
            offset: [xoffset, yoffset, 0],
            size: [width, height, 1],
            format,
            ty,
            pixels: pixels.bytes,
            array: Some(pixels.array),
            function: F,
        });
    }

    /// Replaces a box of a level of a 3D or 2D array texture (`texSubImage3D`).
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_sub_image_3d<T: ArrayElement>(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        zoffset: i32,
        width: i32,
        height: i32,
        depth: i32,
        format: u32,
        ty: u32,
        pixels: &[T],
    ) {
        let pixels = ArrayView::of(pixels);
        self.tex_sub_image_3d_view(
            target, level, xoffset, yoffset, zoffset, width, height, depth, format, ty, pixels,
        );
    }

    /// [`Context::tex_sub_image_3d`] with the client data as a typed array of any kind.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn tex_sub_image_3d_view(
        &mut self,
        target: u32,
        level: i32,
        xoffset: i32,
        yoffset: i32,
        zoffset: i32,
        width: i32,
        height: i32,
        depth: i32,
        format: u32,
        ty: u32,
        pixels: ArrayView,
    ) {
        const F: &str = "texSubImage3D";
        if self.client_data_refused(F) {
            return;
        }
        if !matches!(target, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY) {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        }
        self.tex_sub_image(TexSubImage {
            target,
            level,
            offset: [xoffset, yoffset, zoffset],
            size: [width, height, depth],
            format,
            ty,
            pixels: pixels.bytes,
            array: Some(pixels.array),
            function: F,
        });
    }

    /// `texSubImage2D` and `texSubImage3D` after their target checks.
    pub(super) fn tex_sub_image(&mut self, image: TexSubImage) {
        let TexSubImage {
            target,
            level,
            offset,
            size,
            format,
            ty,
            pixels,
            array,
            function,
        } = image;
        let (bind, face) = image_target(target).expect("checked by the caller");
        let Some(id) = self.bound_texture(bind, function) else {
            return;
        };
        if level < 0 {
            return self.error(gl::INVALID_VALUE, function, "negative level");
        }
        let Some(l) = self
            .objects
            .textures
            .get(id)
            .and_then(|t| t.level(face, level as u32))
            .cloned()
        else {
            return self.error(gl::INVALID_OPERATION, function, "the level has no image");
        };
        if offset.iter().chain(&size).any(|&v| v < 0)
            || offset[0] as u64 + size[0] as u64 > l.width as u64
            || offset[1] as u64 + size[1] as u64 > l.height as u64
            || offset[2] as u64 + size[2] as u64 > l.depth as u64
        {
            return self.error(gl::INVALID_VALUE, function, "region outside the level");
        }
        if self.webgl1.on && l.format.has_depth() {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "a WebGL 1 depth texture takes no data",
            );
        }
        if !self.check_format(&l.format, format, ty, function) {
            return;
        }
        if let Some(why) = array.and_then(|a| array_mismatch(ty, a)) {
            return self.error(gl::INVALID_OPERATION, function, why);
        }
        let (w, h, d) = (size[0] as u32, size[1] as u32, size[2] as u32);
        let three_d = matches!(bind, gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY);
        let client = ClientPixels {
            src: pixels,
            size: [w, h, d],
            format,
            ty,
            three_d,
        };
        let Some(src) = self.unpack_pixels(client, &l.format, function) else {
            return;
        };
        if w == 0 || h == 0 || d == 0 {
            return;
        }
        let t = self
            .objects
            .textures
            .get_mut(id)
            .expect("bound textures are live");
        let cube = t.face_count() == 6;
        let dst = t.faces[face][level as usize].as_mut().expect("checked");
        let texel = dst.format.texel_size();
        if dst.data.is_none() {
            // The GPU holds the level's newest texels (it was drawn into): the box goes
            // straight to the GPU copy, in the batch's order.
            let g = t
                .gpu
                .as_ref()
                .expect("a level held by the GPU is in its chain");
            let texture = g.texture.clone();
            let mip = level as u32 - g.anchor;
            let z = if cube { face as u32 } else { offset[2] as u32 };
            if dst.format.copyable() {
                let dst = crate::texture::TexelBox {
                    texture: &texture,
                    mip,
                    origin: [offset[0] as u32, offset[1] as u32, z],
                    size: [w, h, d],
                    texel: texel as u32,
                };
                crate::texture::upload_image(&self.gpu, &mut self.frame, &dst, &src);
            }
            return;
        }
        dst.write_box(offset.map(|v| v as u32), [w, h, d], &src);
        t.version += 1;
    }
}
