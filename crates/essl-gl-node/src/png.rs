//! The drawing buffer as pixels and as a PNG file.

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
