//! Reading images back: `read_pixels` from the read framebuffer's read buffer in every
//! `(format, type)` WebGL2 allows for its format ([`convert`]), into client memory or a
//! `PIXEL_PACK_BUFFER`, with GL's row order (row 0 is the bottom, which is also how essl-gl
//! stores every image).

mod convert;

pub(crate) use convert::native_pair;

use crate::array::{array_mismatch, ArrayElement, ArrayType, ArrayViewMut};
use crate::context::Context;
use crate::framebuffer::SurfaceImage;
use crate::gl;
use crate::texture::is_pixel_type;

/// wgpu's row pitch alignment for copies to buffers.
const ROW_ALIGN: u32 = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;

/// A box of one mip of a texture, to copy back to the CPU.
pub(crate) struct ImageRegion<'a> {
    pub(crate) texture: &'a wgpu::Texture,
    pub(crate) mip: u32,
    pub(crate) origin: [u32; 3],
    pub(crate) size: [u32; 3],
    /// Bytes per texel of the aspect read.
    pub(crate) texel: u32,
    pub(crate) aspect: wgpu::TextureAspect,
}

/// What a `read_pixels` call asked for.
pub(crate) struct ReadRequest {
    pub(crate) x: i32,
    pub(crate) y: i32,
    pub(crate) width: i32,
    pub(crate) height: i32,
    pub(crate) format: u32,
    pub(crate) ty: u32,
    /// The typed array read into (`None`: a `PIXEL_PACK_BUFFER`).
    pub(crate) array: Option<ArrayType>,
}

impl Context {
    /// Reads a rectangle of the read framebuffer's read buffer into `dst` (`readPixels`), a
    /// typed array whose element type must suit `ty` (`u8` for `UNSIGNED_BYTE`, `f32` for
    /// `FLOAT`, `u16` for the packed 16-bit types, …; another → `INVALID_OPERATION`):
    /// `x`, `y` from the bottom-left corner, rows written bottom first, laid out by
    /// `PACK_ALIGNMENT`, `PACK_ROW_LENGTH`, `PACK_SKIP_ROWS` and `PACK_SKIP_PIXELS`.
    ///
    /// `(format, ty)` must be one the read buffer accepts: `RGBA`/`UNSIGNED_BYTE` for
    /// normalized formats, `RGBA`/`FLOAT` for float ones, `RGBA_INTEGER` with `INT` or
    /// `UNSIGNED_INT` for integer ones, or the implementation's pair for the format
    /// (`IMPLEMENTATION_COLOR_READ_FORMAT`/`_TYPE`); another valid pair →
    /// `INVALID_OPERATION`, unknown enums → `INVALID_ENUM`, a negative size →
    /// `INVALID_VALUE`, a `dst` too small, a bound `PIXEL_PACK_BUFFER`, no read buffer or a
    /// multisampled framebuffer object → `INVALID_OPERATION`, an incomplete one →
    /// `INVALID_FRAMEBUFFER_OPERATION`. Pixels outside the framebuffer are left untouched.
    /// Submits the recorded commands and waits for them.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn read_pixels<T: ArrayElement>(
        &mut self,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        dst: &mut [T],
    ) {
        let dst = ArrayViewMut {
            array: T::TYPE,
            bytes: bytemuck::cast_slice_mut(dst),
        };
        self.read_pixels_view(x, y, width, height, format, ty, dst);
    }

    /// [`Context::read_pixels`] into a typed array of any kind (a binding's
    /// `ArrayBufferView`): the array's type is checked against `ty` as WebGL does.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn read_pixels_view(
        &mut self,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        dst: ArrayViewMut,
    ) {
        const F: &str = "readPixels";
        if self.webgl1_refuses(F, &[format, ty]) {
            return;
        }
        let ty = self.webgl1_read_type(ty);
        if self.bindings.buffer(gl::PIXEL_PACK_BUFFER).is_some() {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "a PIXEL_PACK_BUFFER is bound: read into it with an offset",
            );
        }
        let request = ReadRequest {
            x,
            y,
            width,
            height,
            format,
            ty,
            array: Some(dst.array),
        };
        self.read_into(&request, dst.bytes, F);
    }

    /// `readPixels` into the bound `PIXEL_PACK_BUFFER` at byte `offset` (WebGL2's overload
    /// with a `GLintptr`): no buffer bound, or data past its end → `INVALID_OPERATION`; a
    /// negative offset → `INVALID_VALUE`. The other rules are [`Context::read_pixels`]'s.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn read_pixels_to_buffer(
        &mut self,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        offset: i64,
    ) {
        const F: &str = "readPixels";
        let Some(id) = self.bindings.buffer(gl::PIXEL_PACK_BUFFER) else {
            return self.error(gl::INVALID_OPERATION, F, "no PIXEL_PACK_BUFFER bound");
        };
        if self.refuse_double_bound(id, F) {
            return;
        }
        if offset < 0 {
            return self.error(gl::INVALID_VALUE, F, "negative offset");
        }
        // The bytes from `offset` on, up to date, which the pixels are written over.
        let b = self.objects.buffers.get_any_mut(id).expect("bound");
        let bytes = b.cpu_bytes(&self.gpu, &mut self.frame);
        let start = (offset as usize).min(bytes.len());
        let mut data = bytes[start..].to_vec();
        let request = ReadRequest {
            x,
            y,
            width,
            height,
            format,
            ty,
            array: None,
        };
        if let Some(range) = self.read_into(&request, &mut data, F) {
            let b = self.objects.buffers.get_any_mut(id).expect("bound");
            b.write(
                &self.gpu,
                &mut self.frame,
                start + range.start,
                &data[range],
            );
        }
    }

    /// Checks a read and copies it into `dst`; the byte range of `dst` written, if any.
    pub(crate) fn read_into(
        &mut self,
        r: &ReadRequest,
        dst: &mut [u8],
        f: &str,
    ) -> Option<std::ops::Range<usize>> {
        if !is_read_format(r.format) || !is_read_type(r.ty) {
            self.error(
                gl::INVALID_ENUM,
                f,
                format_args!("format 0x{:04X} / type 0x{:04X}", r.format, r.ty),
            );
            return None;
        }
        if let Some(why) = r.array.and_then(|a| array_mismatch(r.ty, a)) {
            self.error(gl::INVALID_OPERATION, f, why);
            return None;
        }
        if !self.require_complete(false, f) {
            return None;
        }
        let surface = self.read_surface();
        let Some(image) = surface.color.clone() else {
            self.error(gl::INVALID_OPERATION, f, "no colour buffer to read");
            return None;
        };
        if image.samples > 1 && !surface.default {
            self.error(gl::INVALID_OPERATION, f, "the framebuffer is multisampled");
            return None;
        }
        if !convert::accepts(&image.format, r.format, r.ty) {
            self.error(
                gl::INVALID_OPERATION,
                f,
                format_args!(
                    "format 0x{:04X} / type 0x{:04X} cannot read this buffer",
                    r.format, r.ty
                ),
            );
            return None;
        }
        if r.width < 0 || r.height < 0 {
            self.error(gl::INVALID_VALUE, f, "negative width or height");
            return None;
        }
        let pixel = convert::pixel_bytes(r.format, r.ty);
        let p = &self.pixel_store;
        let row_len = if p.pack_row_length > 0 {
            p.pack_row_length as usize
        } else {
            r.width as usize
        };
        // WebGL 2's pixel store constraint: rows do not overlap.
        if p.pack_skip_pixels as usize + r.width as usize > row_len {
            self.error(
                gl::INVALID_OPERATION,
                f,
                "PACK_SKIP_PIXELS + width is past PACK_ROW_LENGTH",
            );
            return None;
        }
        let align = p.pack_alignment as usize;
        let stride = (row_len * pixel).div_ceil(align) * align;
        let start = p.pack_skip_rows as usize * stride + p.pack_skip_pixels as usize * pixel;
        let needed = if r.width == 0 || r.height == 0 {
            0
        } else {
            start + (r.height as usize - 1) * stride + r.width as usize * pixel
        };
        if dst.len() < needed {
            self.error(
                gl::INVALID_OPERATION,
                f,
                format_args!("{} bytes given, {needed} needed", dst.len()),
            );
            return None;
        }
        // The part inside the image.
        let (fw, fh) = (image.width as i64, image.height as i64);
        let (x, y) = (r.x as i64, r.y as i64);
        let (x0, x1) = (x.clamp(0, fw), (x + r.width as i64).clamp(0, fw));
        let (y0, y1) = (y.clamp(0, fh), (y + r.height as i64).clamp(0, fh));
        if x1 <= x0 || y1 <= y0 {
            return None;
        }
        let (w, h) = ((x1 - x0) as u32, (y1 - y0) as u32);
        let texel = image.format.texel_size();
        let texels = self.read_surface_image(&image, [x0 as u32, y0 as u32], [w, h])?;
        for row in 0..h as usize {
            let gy = y0 as usize + row - y as usize;
            let mut at = start + gy * stride + (x0 - x) as usize * pixel;
            for col in 0..w as usize {
                let src = &texels[(row * w as usize + col) * texel..];
                convert::encode(
                    convert::decode(&image.format, src),
                    r.format,
                    r.ty,
                    &mut dst[at..at + pixel],
                );
                at += pixel;
            }
        }
        Some(start..needed)
    }

    /// The drawing buffer's colour as 8-bit RGBA, top row first (an image file's order),
    /// whatever framebuffer is bound and whatever its read buffer: what a canvas shows, as an
    /// image file or a 2D canvas's `ImageData` holds it. Colours are converted from the
    /// drawing buffer's format (`RGBA16F` is clamped); with `alpha: false` alpha reads 1;
    /// with `premultipliedAlpha` (the default) colour is divided by alpha, as a browser does
    /// when it encodes or copies the canvas. Submits the recorded commands and waits for them.
    pub fn read_drawing_buffer(&mut self) -> Vec<u8> {
        let mut surface = self.default_read_surface();
        let fb = &self.fb;
        let (w, h) = (fb.width, fb.height);
        let format = fb.format;
        let image = surface.color.take().unwrap_or_else(|| SurfaceImage {
            texture: fb.color.clone(),
            mip: 0,
            layer: 0,
            format,
            width: w,
            height: h,
            samples: 1,
            slice_3d: false,
            view: fb.color_view.clone(),
            depth_slice: None,
        });
        let opaque = !fb.attributes.alpha;
        let premultiplied = fb.attributes.premultiplied_alpha;
        let texel = image.format.texel_size();
        let texels = self
            .read_surface_image(&image, [0, 0], [w, h])
            .unwrap_or_default();
        let mut out = vec![0u8; (w * h * 4) as usize];
        for (i, px) in out.chunks_exact_mut(4).enumerate() {
            let (x, y) = (i % w as usize, i / w as usize);
            // Row 0 of the image file is the top: GL's last row.
            let src = (h as usize - 1 - y) * w as usize + x;
            if let Some(t) = texels.get(src * texel..(src + 1) * texel) {
                let rgba = convert::decode(&image.format, t);
                convert::encode(rgba, gl::RGBA, gl::UNSIGNED_BYTE, px);
            }
            if opaque {
                px[3] = 255;
            } else if premultiplied {
                unpremultiply(px);
            }
        }
        out
    }

    /// The texels of a rectangle of a framebuffer image, tightly packed, row 0 first.
    pub(crate) fn read_surface_image(
        &mut self,
        image: &SurfaceImage,
        origin: [u32; 2],
        size: [u32; 2],
    ) -> Option<Vec<u8>> {
        let region = ImageRegion {
            texture: &image.texture.clone(),
            mip: image.mip,
            origin: [origin[0], origin[1], image.layer],
            size: [size[0], size[1], 1],
            texel: image.format.texel_size() as u32,
            aspect: wgpu::TextureAspect::All,
        };
        self.read_image(&region)
    }

    /// Submits everything recorded, copies a region of a texture to the readback buffer,
    /// waits, and returns its texels tightly packed (rows in memory order: GL's).
    pub(crate) fn read_image(&mut self, r: &ImageRegion) -> Option<Vec<u8>> {
        let [w, h, d] = r.size;
        let row = w * r.texel;
        let padded = row.div_ceil(ROW_ALIGN) * ROW_ALIGN;
        let size = padded as u64 * h as u64 * d as u64;
        if size == 0 {
            return Some(Vec::new());
        }
        if self
            .caches
            .readback
            .as_ref()
            .is_none_or(|b| b.size() < size)
        {
            self.caches.readback = Some(self.gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("essl-gl readback"),
                size: size.next_power_of_two(),
                usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                mapped_at_creation: false,
            }));
        }
        let buffer = self.caches.readback.clone().expect("made above");
        self.frame.submit(&self.gpu, |encoder| {
            encoder.copy_texture_to_buffer(
                wgpu::TexelCopyTextureInfo {
                    texture: r.texture,
                    mip_level: r.mip,
                    origin: wgpu::Origin3d {
                        x: r.origin[0],
                        y: r.origin[1],
                        z: r.origin[2],
                    },
                    aspect: r.aspect,
                },
                wgpu::TexelCopyBufferInfo {
                    buffer: &buffer,
                    layout: wgpu::TexelCopyBufferLayout {
                        offset: 0,
                        bytes_per_row: Some(padded),
                        rows_per_image: Some(h),
                    },
                },
                wgpu::Extent3d {
                    width: w,
                    height: h,
                    depth_or_array_layers: d,
                },
            );
        });
        let mut out = vec![0u8; (row * h * d) as usize];
        let view = self.gpu.read_mapped(buffer.slice(..size))?;
        let row = row as usize;
        for r in 0..(h * d) as usize {
            let src = &view[r * padded as usize..r * padded as usize + row];
            out[r * row..(r + 1) * row].copy_from_slice(src);
        }
        drop(view);
        buffer.unmap();
        Some(out)
    }
}

/// Whether `format` is one `readPixels` knows.
fn is_read_format(format: u32) -> bool {
    matches!(
        format,
        gl::RGBA
            | gl::RGB
            | gl::ALPHA
            | gl::RED
            | gl::RG
            | gl::RGBA_INTEGER
            | gl::RED_INTEGER
            | gl::RG_INTEGER
            | gl::RGB_INTEGER
    )
}

/// Whether `ty` is one `readPixels` knows: the pixel types of uploads but the packed
/// depth-stencil ones.
fn is_read_type(ty: u32) -> bool {
    is_pixel_type(ty)
        && !matches!(
            ty,
            gl::UNSIGNED_INT_24_8 | gl::FLOAT_32_UNSIGNED_INT_24_8_REV
        )
}

/// A premultiplied 8-bit RGBA pixel divided by its alpha, rounded (black where alpha is 0).
fn unpremultiply(px: &mut [u8]) {
    let a = u32::from(px[3]);
    if a == 255 {
        return;
    }
    for c in &mut px[..3] {
        let v = (u32::from(*c) * 255 + a / 2).checked_div(a).unwrap_or(0);
        *c = v.min(255) as u8;
    }
}
