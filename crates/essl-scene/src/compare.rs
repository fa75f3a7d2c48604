//! Image comparison: per-channel absolute differences of two RGBA8 images, with a tolerance, and
//! a diff-visualisation image.

use std::path::Path;

use crate::error::ImageError;
use crate::png_io::RgbaImage;

/// The result of [`compare`]. Differences are in 1/255 units (raw byte differences).
#[derive(Clone, Debug, PartialEq)]
pub struct ImageDiff {
    /// Width of both images.
    pub width: u32,
    /// Height of both images.
    pub height: u32,
    /// The tolerance used.
    pub tolerance: u8,
    /// Number of pixels (`width * height`).
    pub pixels: usize,
    /// Pixels whose every channel (alpha included) differs by at most `tolerance`.
    pub within_tolerance: usize,
    /// Pixels exactly equal.
    pub identical: usize,
    /// The largest absolute difference over all channels.
    pub max_abs: u8,
    /// The largest absolute difference per channel (R, G, B, A).
    pub max_abs_per_channel: [u8; 4],
    /// Mean absolute difference over all `4 * pixels` channel values.
    pub mean_abs: f64,
    /// The first pixel (x, y from the top row) with a channel differing by `max_abs`, if any
    /// differs.
    pub worst: Option<(u32, u32)>,
}

impl ImageDiff {
    /// Pixels with some channel differing by more than the tolerance.
    pub fn outside_tolerance(&self) -> usize {
        self.pixels - self.within_tolerance
    }

    /// Whether every pixel is within the tolerance.
    pub fn all_within(&self) -> bool {
        self.within_tolerance == self.pixels
    }

    /// `within_tolerance / pixels`.
    pub fn fraction_within(&self) -> f64 {
        self.within_tolerance as f64 / self.pixels as f64
    }
}

fn same_size(a: &RgbaImage, b: &RgbaImage) -> Result<(), ImageError> {
    if a.width != b.width || a.height != b.height {
        return Err(ImageError::SizeMismatch {
            a_width: a.width,
            a_height: a.height,
            b_width: b.width,
            b_height: b.height,
        });
    }
    Ok(())
}

/// Compares two images of the same size channel by channel; `tolerance` is in 1/255 units.
pub fn compare(a: &RgbaImage, b: &RgbaImage, tolerance: u8) -> Result<ImageDiff, ImageError> {
    same_size(a, b)?;
    let pixels = a.width as usize * a.height as usize;
    let (mut within, mut identical, mut sum) = (0usize, 0usize, 0u64);
    let mut max_per = [0u8; 4];
    let (mut max_abs, mut worst) = (0u8, None);
    for (i, (pa, pb)) in a
        .data
        .chunks_exact(4)
        .zip(b.data.chunks_exact(4))
        .enumerate()
    {
        let mut px_max = 0u8;
        for ch in 0..4 {
            let d = pa[ch].abs_diff(pb[ch]);
            sum += u64::from(d);
            max_per[ch] = max_per[ch].max(d);
            px_max = px_max.max(d);
        }
        if px_max <= tolerance {
            within += 1;
        }
        if px_max == 0 {
            identical += 1;
        }
        if px_max > max_abs {
            max_abs = px_max;
            let w = a.width as usize;
            worst = Some(((i % w) as u32, (i / w) as u32));
        }
    }
    Ok(ImageDiff {
        width: a.width,
        height: a.height,
        tolerance,
        pixels,
        within_tolerance: within,
        identical,
        max_abs,
        max_abs_per_channel: max_per,
        mean_abs: sum as f64 / (pixels as f64 * 4.0),
        worst,
    })
}

/// A picture of where two images differ: equal pixels show `a` dimmed to a third of its grey
/// level, pixels within the tolerance (but not equal) blue, pixels outside it red — the brighter,
/// the larger the difference. Opaque.
pub fn diff_image(a: &RgbaImage, b: &RgbaImage, tolerance: u8) -> Result<RgbaImage, ImageError> {
    same_size(a, b)?;
    let mut out = Vec::with_capacity(a.data.len());
    for (pa, pb) in a.data.chunks_exact(4).zip(b.data.chunks_exact(4)) {
        let d = (0..4).map(|c| pa[c].abs_diff(pb[c])).max().unwrap_or(0);
        // 128 + 127·d/255, so any difference is clearly visible.
        let bright = (128 + u32::from(d) * 127 / 255) as u8;
        let px = if d == 0 {
            let grey =
                (u32::from(pa[0]) * 77 + u32::from(pa[1]) * 150 + u32::from(pa[2]) * 29) >> 8;
            let g = (grey / 3) as u8;
            [g, g, g, 255]
        } else if d <= tolerance {
            [0, 0, bright, 255]
        } else {
            [bright, 0, 0, 255]
        };
        out.extend_from_slice(&px);
    }
    RgbaImage::new(a.width, a.height, out)
}

/// Writes [`diff_image`] of `a` and `b` as a PNG file.
pub fn write_diff_png(
    path: &Path,
    a: &RgbaImage,
    b: &RgbaImage,
    tolerance: u8,
) -> Result<(), ImageError> {
    diff_image(a, b, tolerance)?.write_png(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_and_means() {
        let a = RgbaImage::new(2, 1, vec![10, 20, 30, 255, 0, 0, 0, 255]).unwrap();
        let b = RgbaImage::new(2, 1, vec![12, 20, 30, 255, 0, 9, 0, 255]).unwrap();
        let d = compare(&a, &b, 2).unwrap();
        assert_eq!(d.pixels, 2);
        assert_eq!(d.within_tolerance, 1);
        assert_eq!(d.identical, 0);
        assert_eq!(d.max_abs, 9);
        assert_eq!(d.max_abs_per_channel, [2, 9, 0, 0]);
        assert_eq!(d.mean_abs, 11.0 / 8.0);
        assert_eq!(d.worst, Some((1, 0)));
        assert!(!d.all_within());
        assert!(compare(&a, &b, 9).unwrap().all_within());
        let same = compare(&a, &a, 0).unwrap();
        assert_eq!((same.identical, same.max_abs, same.worst), (2, 0, None));
        let v = diff_image(&a, &b, 2).unwrap();
        assert_eq!(v.pixel(0, 0), [0, 0, 128, 255]);
        assert_eq!(v.pixel(1, 0), [132, 0, 0, 255]);
    }

    #[test]
    fn size_mismatch_is_an_error() {
        let a = RgbaImage::new(1, 1, vec![0; 4]).unwrap();
        let b = RgbaImage::new(1, 2, vec![0; 8]).unwrap();
        assert!(matches!(
            compare(&a, &b, 0),
            Err(ImageError::SizeMismatch { .. })
        ));
        assert!(diff_image(&a, &b, 0).is_err());
    }
}
