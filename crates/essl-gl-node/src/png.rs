//! The drawing buffer as pixels and as a PNG file, and PNG files decoded for texture uploads.

use napi::bindgen_prelude::Buffer;
use napi_derive::napi;

use crate::context::NativeContext;
use crate::error::BindingError;

/// RGBA8 pixels, top row first, as a PNG file.
pub(crate) fn encode(width: u32, height: u32, rgba: &[u8]) -> Result<Vec<u8>, BindingError> {
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, width, height);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder
        .write_header()
        .map_err(|e| BindingError::Png(e.to_string()))?;
    writer
        .write_image_data(rgba)
        .map_err(|e| BindingError::Png(e.to_string()))?;
    writer
        .finish()
        .map_err(|e| BindingError::Png(e.to_string()))?;
    Ok(out)
}

#[napi]
impl NativeContext {
    /// The drawing buffer as RGBA8 pixels, top row first (what a canvas shows).
    #[napi(catch_unwind)]
    pub fn drawing_buffer_pixels(&mut self) -> napi::Result<Buffer> {
        Ok(self.gl()?.read_drawing_buffer().into())
    }

    /// The drawing buffer as a PNG file.
    #[napi(catch_unwind)]
    pub fn to_png(&mut self) -> napi::Result<Buffer> {
        let c = self.gl()?;
        let (w, h) = (c.drawing_buffer_width(), c.drawing_buffer_height());
        let rgba = c.read_drawing_buffer();
        Ok(encode(w, h, &rgba)?.into())
    }
}

/// An image decoded from a file: RGBA8 pixels, top row first, colour not multiplied by alpha.
#[napi(object)]
pub struct DecodedImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height * 4` bytes.
    pub data: Buffer,
}

/// Decodes a PNG file as a browser decodes an image for a WebGL upload: every colour type and
/// depth to RGBA8 (palettes and `tRNS` expanded, 16-bit channels to their high byte, as
/// libpng strips them), colour not multiplied by alpha, the `gAMA` chunk not applied. A
/// 2D canvas (the `canvas` package) stores premultiplied colour, which loses the colour of
/// nearly transparent pixels; this keeps it. A file that is not a PNG, or one over 256 MiB
/// decoded, is an `Error`.
#[napi(catch_unwind)]
pub fn decode_png(bytes: Buffer) -> napi::Result<DecodedImage> {
    let (width, height, data) = decode(&bytes).map_err(|e| BindingError::Png(e.to_string()))?;
    Ok(DecodedImage {
        width,
        height,
        data: data.into(),
    })
}

/// (width, height, RGBA8 pixels) of a PNG file.
fn decode(bytes: &[u8]) -> Result<(u32, u32, Vec<u8>), png::DecodingError> {
    let mut decoder = png::Decoder::new_with_limits(
        std::io::Cursor::new(bytes),
        png::Limits { bytes: 256 << 20 },
    );
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder.read_info()?;
    let size = reader
        .output_buffer_size()
        .ok_or(png::DecodingError::LimitsExceeded)?;
    let mut buf = vec![0; size];
    let frame = reader.next_frame(&mut buf)?;
    let (w, h) = (frame.width as usize, frame.height as usize);
    let channels = frame.color_type.samples();
    let mut rgba = Vec::with_capacity(w * h * 4);
    for y in 0..h {
        let row = &buf[y * frame.line_size..][..w * channels];
        for px in row.chunks_exact(channels) {
            rgba.extend_from_slice(&match *px {
                [g] => [g, g, g, 255],
                [g, a] => [g, g, g, a],
                [r, g, b] => [r, g, b, 255],
                [r, g, b, a] => [r, g, b, a],
                _ => [0, 0, 0, 0],
            });
        }
    }
    Ok((frame.width, frame.height, rgba))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_encoded_image_decodes_to_the_same_pixels_alpha_not_applied() {
        let rgba = [255, 192, 128, 1, 0, 0, 255, 255, 10, 20, 30, 0, 1, 2, 3, 4];
        let file = encode(2, 2, &rgba).expect("encodes");
        assert_eq!(decode(&file).expect("decodes"), (2, 2, rgba.to_vec()));
        assert!(decode(b"not a png").is_err());
    }
}
