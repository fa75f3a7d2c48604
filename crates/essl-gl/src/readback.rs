//! Reading the framebuffer back: `read_pixels`, with GL's row order (row 0 is the bottom).

use crate::context::Context;
use crate::gl;

/// wgpu's row pitch alignment for copies to buffers.
const ROW_ALIGN: u32 = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;

impl Context {
    /// Reads a rectangle of the framebuffer into `dst` (`readPixels`): `x`, `y` from the
    /// bottom-left corner, rows written bottom first, laid out by `PACK_ALIGNMENT`,
    /// `PACK_ROW_LENGTH`, `PACK_SKIP_ROWS` and `PACK_SKIP_PIXELS`.
    ///
    /// `format`/`ty` must be `RGBA`/`UNSIGNED_BYTE` (also the implementation's colour read
    /// format); other valid combinations → `INVALID_OPERATION`, unknown enums →
    /// `INVALID_ENUM`, a negative size → `INVALID_VALUE`, a `dst` too small →
    /// `INVALID_OPERATION`. Pixels outside the framebuffer are left untouched. Submits the
    /// recorded commands and waits for them.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn read_pixels(
        &mut self,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        dst: &mut [u8],
    ) {
        const F: &str = "readPixels";
        let known_format = matches!(
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
        );
        let known_type = matches!(
            ty,
            gl::UNSIGNED_BYTE
                | gl::BYTE
                | gl::UNSIGNED_SHORT
                | gl::SHORT
                | gl::UNSIGNED_INT
                | gl::INT
                | gl::HALF_FLOAT
                | gl::FLOAT
                | gl::UNSIGNED_SHORT_5_6_5
                | gl::UNSIGNED_SHORT_4_4_4_4
                | gl::UNSIGNED_SHORT_5_5_5_1
        );
        if !known_format || !known_type {
            return self.error(
                gl::INVALID_ENUM,
                F,
                format_args!("format 0x{format:04X} / type 0x{ty:04X}"),
            );
        }
        if (format, ty) != (gl::RGBA, gl::UNSIGNED_BYTE) {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "only RGBA/UNSIGNED_BYTE can be read",
            );
        }
        if width < 0 || height < 0 {
            return self.error(gl::INVALID_VALUE, F, "negative width or height");
        }
        let p = &self.pixel_store;
        let row_len = if p.pack_row_length > 0 {
            p.pack_row_length as usize
        } else {
            width as usize
        };
        let align = p.pack_alignment as usize;
        let stride = (row_len * 4).div_ceil(align) * align;
        let start = p.pack_skip_rows as usize * stride + p.pack_skip_pixels as usize * 4;
        let needed = if width == 0 || height == 0 {
            0
        } else {
            start + (height as usize - 1) * stride + width as usize * 4
        };
        if dst.len() < needed {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                format_args!("{} bytes given, {needed} needed", dst.len()),
            );
        }
        // The part inside the framebuffer.
        let (fw, fh) = (self.fb.width as i64, self.fb.height as i64);
        let (x0, x1) = (
            (x as i64).clamp(0, fw),
            (x as i64 + width as i64).clamp(0, fw),
        );
        let (y0, y1) = (
            (y as i64).clamp(0, fh),
            (y as i64 + height as i64).clamp(0, fh),
        );
        if x1 <= x0 || y1 <= y0 {
            return;
        }
        let (w, h) = ((x1 - x0) as u32, (y1 - y0) as u32);
        let pixels = self.read_rgba8(x0 as u32, y0 as u32, w, h);
        for row in 0..h as usize {
            let gy = y0 as usize + row - y as usize;
            let at = start + gy * stride + (x0 - x as i64) as usize * 4;
            let src = &pixels[row * w as usize * 4..(row + 1) * w as usize * 4];
            dst[at..at + src.len()].copy_from_slice(src);
        }
    }

    /// Reads a rectangle that lies inside the framebuffer as tightly packed RGBA8 rows,
    /// bottom row first (GL's order). A convenience over [`Context::read_pixels`].
    pub fn read_pixels_rgba8(&mut self, x: u32, y: u32, width: u32, height: u32) -> Vec<u8> {
        let (fw, fh) = (self.fb.width, self.fb.height);
        if x.saturating_add(width) > fw || y.saturating_add(height) > fh {
            self.error(
                gl::INVALID_VALUE,
                "readPixels",
                "rectangle outside the framebuffer",
            );
            return Vec::new();
        }
        if width == 0 || height == 0 {
            return Vec::new();
        }
        self.read_rgba8(x, y, width, height)
    }

    /// Submits everything recorded, copies the rectangle (GL coordinates, inside the
    /// framebuffer) to a buffer, waits, and returns it bottom row first.
    fn read_rgba8(&mut self, x: u32, y: u32, w: u32, h: u32) -> Vec<u8> {
        let padded = (w * 4).div_ceil(ROW_ALIGN) * ROW_ALIGN;
        let size = padded as u64 * h as u64;
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
        let color = &self.fb.color;
        self.frame.submit(&self.gpu, &self.fb, |encoder| {
            encoder.copy_texture_to_buffer(
                wgpu::TexelCopyTextureInfo {
                    texture: color,
                    mip_level: 0,
                    origin: wgpu::Origin3d { x, y, z: 0 },
                    aspect: wgpu::TextureAspect::All,
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
                    depth_or_array_layers: 1,
                },
            );
        });
        let slice = buffer.slice(..size);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        let _ = self.gpu.device.poll(wgpu::PollType::wait_indefinitely());
        let mut out = vec![0u8; (w * h * 4) as usize];
        if let (Ok(Ok(())), Ok(view)) = (rx.recv(), slice.get_mapped_range()) {
            let row = (w * 4) as usize;
            for r in 0..h as usize {
                // Framebuffers store GL's row order: row r is GL row r of the rectangle.
                let src = &view[r * padded as usize..r * padded as usize + row];
                out[r * row..(r + 1) * row].copy_from_slice(src);
            }
            drop(view);
            buffer.unmap();
        }
        out
    }
}
