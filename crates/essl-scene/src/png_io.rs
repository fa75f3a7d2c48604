//! PNG helpers: an RGBA8 image type, writing `readPixels` output (row 0 = bottom) as a PNG whose
//! first row is the top (8-bit RGBA, colour type 6, non-interlaced, filter 0 on every row, zlib
//! level 9, as `webgl2-render.py` writes), and reading any PNG into RGBA8.

use std::io::{BufReader, Cursor};
use std::path::Path;

use crate::error::ImageError;

/// An 8-bit RGBA image, rows stored **top row first** (PNG order).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RgbaImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height * 4` bytes, top row first, no padding.
    pub data: Vec<u8>,
}

fn check_len(width: u32, height: u32, len: usize) -> Result<(), ImageError> {
    if width == 0 || height == 0 || len != width as usize * height as usize * 4 {
        return Err(ImageError::BufferSize { width, height, len });
    }
    Ok(())
}

/// The rows of `data` in reverse order (`stride` bytes each).
fn flip_rows(data: &[u8], stride: usize) -> Vec<u8> {
    data.rchunks_exact(stride).flatten().copied().collect()
}

impl RgbaImage {
    /// An image from top-first rows.
    pub fn new(width: u32, height: u32, data: Vec<u8>) -> Result<RgbaImage, ImageError> {
        check_len(width, height, data.len())?;
        Ok(RgbaImage {
            width,
            height,
            data,
        })
    }

    /// An image from GL-order rows (row 0 = bottom, as `readPixels` returns them).
    pub fn from_gl_rows(width: u32, height: u32, data: &[u8]) -> Result<RgbaImage, ImageError> {
        check_len(width, height, data.len())?;
        Ok(RgbaImage {
            width,
            height,
            data: flip_rows(data, width as usize * 4),
        })
    }

    /// The pixels in GL row order (row 0 = bottom).
    pub fn to_gl_rows(&self) -> Vec<u8> {
        flip_rows(&self.data, self.width as usize * 4)
    }

    /// The RGBA of pixel (x, y), y counted from the top row.
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 4] {
        let i = (y as usize * self.width as usize + x as usize) * 4;
        [
            self.data[i],
            self.data[i + 1],
            self.data[i + 2],
            self.data[i + 3],
        ]
    }

    /// Encodes as PNG bytes: 8-bit RGBA, non-interlaced, filter 0 on every row, zlib level 9.
    pub fn encode_png(&self) -> Result<Vec<u8>, ImageError> {
        check_len(self.width, self.height, self.data.len())?;
        let mut out = Vec::new();
        {
            let mut enc = png::Encoder::new(&mut out, self.width, self.height);
            enc.set_color(png::ColorType::Rgba);
            enc.set_depth(png::BitDepth::Eight);
            enc.set_deflate_compression(png::DeflateCompression::Level(9));
            enc.set_filter(png::Filter::NoFilter);
            let mut writer = enc.write_header()?;
            writer.write_image_data(&self.data)?;
            writer.finish()?;
        }
        Ok(out)
    }

    /// Writes the image as a PNG file (see [`RgbaImage::encode_png`]).
    pub fn write_png(&self, path: &Path) -> Result<(), ImageError> {
        let bytes = self.encode_png()?;
        std::fs::write(path, bytes).map_err(|source| ImageError::Io {
            path: path.to_path_buf(),
            source,
        })
    }

    /// Decodes PNG bytes of any colour type and depth into RGBA8 (grey and RGB get alpha 255,
    /// palettes are expanded, 16-bit samples keep their high byte).
    pub fn decode_png(bytes: &[u8]) -> Result<RgbaImage, ImageError> {
        let mut dec = png::Decoder::new(BufReader::new(Cursor::new(bytes)));
        dec.set_transformations(png::Transformations::normalize_to_color8());
        let mut reader = dec.read_info()?;
        let size = reader
            .output_buffer_size()
            .ok_or_else(|| ImageError::Unsupported("image too large".into()))?;
        let mut buf = vec![0; size];
        let info = reader.next_frame(&mut buf)?;
        buf.truncate(info.buffer_size());
        let (w, h) = (info.width, info.height);
        let px = w as usize * h as usize;
        let data = match info.color_type {
            png::ColorType::Rgba => buf,
            png::ColorType::Rgb => buf
                .chunks_exact(3)
                .flat_map(|c| [c[0], c[1], c[2], 255])
                .collect(),
            png::ColorType::GrayscaleAlpha => buf
                .chunks_exact(2)
                .flat_map(|c| [c[0], c[0], c[0], c[1]])
                .collect(),
            png::ColorType::Grayscale => buf.iter().flat_map(|&g| [g, g, g, 255]).collect(),
            png::ColorType::Indexed => {
                return Err(ImageError::Unsupported("palette not expanded".into()))
            }
        };
        if data.len() != px * 4 || info.bit_depth != png::BitDepth::Eight {
            return Err(ImageError::Unsupported(format!(
                "{:?} {:?} after conversion",
                info.color_type, info.bit_depth
            )));
        }
        RgbaImage::new(w, h, data)
    }

    /// Reads a PNG file into RGBA8 (see [`RgbaImage::decode_png`]).
    pub fn read_png(path: &Path) -> Result<RgbaImage, ImageError> {
        let bytes = std::fs::read(path).map_err(|source| ImageError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        RgbaImage::decode_png(&bytes)
    }
}

/// Writes `readPixels` output (RGBA8, row 0 = bottom of the framebuffer) as a PNG whose first row
/// is the top: PNG row `r` is GL row `height - 1 - r`.
pub fn write_png_gl_rows(
    path: &Path,
    width: u32,
    height: u32,
    gl_rows: &[u8],
) -> Result<(), ImageError> {
    RgbaImage::from_gl_rows(width, height, gl_rows)?.write_png(path)
}

/// Reads a PNG file into RGBA8, top row first.
pub fn read_png(path: &Path) -> Result<RgbaImage, ImageError> {
    RgbaImage::read_png(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gl_rows_are_flipped_and_round_trip() {
        // 1x2: GL row 0 (bottom) red, row 1 (top) green.
        let gl = [255, 0, 0, 255, 0, 255, 0, 128];
        let img = RgbaImage::from_gl_rows(1, 2, &gl).unwrap();
        assert_eq!(img.pixel(0, 0), [0, 255, 0, 128]);
        assert_eq!(img.to_gl_rows(), gl.to_vec());
        let bytes = img.encode_png().unwrap();
        // IHDR: 8-bit, colour type 6, compression 0, filter 0, no interlace.
        assert_eq!(&bytes[24..29], &[8, 6, 0, 0, 0]);
        assert_eq!(RgbaImage::decode_png(&bytes).unwrap(), img);
    }

    #[test]
    fn bad_buffer_is_an_error() {
        assert!(RgbaImage::from_gl_rows(2, 2, &[0; 15]).is_err());
        assert!(RgbaImage::new(0, 1, vec![]).is_err());
        assert!(RgbaImage::decode_png(b"not a png").is_err());
    }

    #[test]
    fn grey_and_rgb_decode_to_rgba() {
        let mut out = Vec::new();
        {
            let mut enc = png::Encoder::new(&mut out, 2, 1);
            enc.set_color(png::ColorType::Rgb);
            enc.set_depth(png::BitDepth::Sixteen);
            let mut w = enc.write_header().unwrap();
            w.write_image_data(&[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12])
                .unwrap();
        }
        let img = RgbaImage::decode_png(&out).unwrap();
        assert_eq!(img.data, vec![1, 3, 5, 255, 7, 9, 11, 255]);
    }
}
