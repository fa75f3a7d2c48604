//! Measuring a GPU picture against the float64 reference: per-pixel error statistics, the
//! reference *band* (the spread of several renders), and a picture of the error.

use glam::{DVec2, DVec4};

use essl_scene::{RgbaImage, Scene};

use super::{render_offset, Geometry, RefImage, RefShader};
use crate::error::LightsError;

/// Options of [`compare_rgba8`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct CompareOptions {
    /// Leave out pixels within 1 pixel of a silhouette (a coverage change of the reference).
    pub ignore_silhouettes: bool,
}

/// How far an RGBA8 image is from a float64 reference, in 1/255 units: per channel
/// `|byte − 255 · clamp(reference, 0, 1)|`, so rounding alone costs up to 0.5.
#[derive(Clone, Debug, PartialEq)]
pub struct RefDiff {
    /// Pixels compared.
    pub compared: usize,
    /// Pixels left out (silhouettes).
    pub ignored: usize,
    /// The largest channel error.
    pub max: f64,
    /// Root mean square over every compared channel value (RGBA).
    pub rms: f64,
    /// The 99th percentile of the per-pixel (largest-channel) error.
    pub p99: f64,
    /// Pixels whose largest channel error exceeds 1 (more than 1/255 off).
    pub over_one: usize,
    /// `over_one` as a percentage of `compared`.
    pub over_one_percent: f64,
    /// A pixel (x, y from the top) with the largest error.
    pub worst: Option<(u32, u32)>,
}

/// An error unless `gpu` is `width` × `height`.
fn same_size(gpu: &RgbaImage, width: u32, height: u32) -> Result<(), LightsError> {
    if gpu.width != width || gpu.height != height {
        return Err(LightsError::SizeMismatch {
            a_width: gpu.width,
            a_height: gpu.height,
            b_width: width,
            b_height: height,
        });
    }
    Ok(())
}

/// The pixels a comparison with `reference` leaves out: its silhouettes when `options` ask,
/// none otherwise.
fn left_out(reference: &RefImage, options: CompareOptions) -> Vec<bool> {
    if options.ignore_silhouettes {
        reference.silhouette_mask(1)
    } else {
        vec![false; reference.pixels.len()]
    }
}

/// Compares a GPU image (rows top first, as [`RgbaImage`] stores them) with a reference.
pub fn compare_rgba8(
    gpu: &RgbaImage,
    reference: &RefImage,
    options: CompareOptions,
) -> Result<RefDiff, LightsError> {
    same_size(gpu, reference.width, reference.height)?;
    let mask = left_out(reference, options);
    let mut stats = ErrorStats::new(reference.width, reference.pixels.len());
    for (i, r) in reference.pixels.iter().enumerate() {
        if mask[i] {
            stats.ignore();
            continue;
        }
        let mut errors = [0.0f64; 4];
        for (c, e) in errors.iter_mut().enumerate() {
            let want = r[c].clamp(0.0, 1.0) * 255.0;
            *e = if want.is_nan() {
                f64::INFINITY
            } else {
                (f64::from(gpu.data[4 * i + c]) - want).abs()
            };
        }
        stats.add(i, errors);
    }
    Ok(stats.finish())
}

/// Accumulates per-pixel channel errors (in 1/255 units) into a [`RefDiff`].
struct ErrorStats {
    width: usize,
    compared: usize,
    ignored: usize,
    over: usize,
    sum2: f64,
    max: f64,
    worst: Option<(u32, u32)>,
    per_pixel: Vec<f64>,
}

impl ErrorStats {
    fn new(width: u32, pixels: usize) -> ErrorStats {
        ErrorStats {
            width: width as usize,
            compared: 0,
            ignored: 0,
            over: 0,
            sum2: 0.0,
            max: 0.0,
            worst: None,
            per_pixel: Vec::with_capacity(pixels),
        }
    }

    /// A pixel left out of the comparison.
    fn ignore(&mut self) {
        self.ignored += 1;
    }

    /// Pixel `i`'s four channel errors.
    fn add(&mut self, i: usize, errors: [f64; 4]) {
        self.compared += 1;
        let px = errors.iter().fold(0.0f64, |m, e| m.max(*e));
        self.sum2 += errors.iter().map(|e| e * e).sum::<f64>();
        self.per_pixel.push(px);
        if px > 1.0 {
            self.over += 1;
        }
        if self.worst.is_none() || px > self.max {
            self.max = px;
            self.worst = Some(((i % self.width) as u32, (i / self.width) as u32));
        }
    }

    fn finish(mut self) -> RefDiff {
        self.per_pixel.sort_by(|a, b| a.total_cmp(b));
        let p99 = if self.per_pixel.is_empty() {
            0.0
        } else {
            self.per_pixel[((self.per_pixel.len() - 1) as f64 * 0.99).round() as usize]
        };
        let n = self.compared as f64;
        RefDiff {
            compared: self.compared,
            ignored: self.ignored,
            max: self.max,
            rms: if self.compared == 0 {
                0.0
            } else {
                (self.sum2 / (n * 4.0)).sqrt()
            },
            p99,
            over_one: self.over,
            over_one_percent: if self.compared == 0 {
                0.0
            } else {
                100.0 * self.over as f64 / n
            },
            worst: self.worst,
        }
    }
}

/// A reference *band*: per pixel the lowest and highest value, clamped to [0, 1], of a set of
/// float64 renders of one picture (cone cosines moved by a few float32 ulps, rays moved by a
/// fraction of a pixel), with the coverage of the first render. Where the model is continuous
/// the band is a point; across a hard edge (a step spot edge, `inner == outer`) it spans both
/// sides for the pixels that a float32 GPU may legitimately put on either side.
#[derive(Clone, Debug, PartialEq)]
pub struct BandImage {
    /// Width.
    pub width: u32,
    /// Height.
    pub height: u32,
    /// The lowest value of each pixel, RGBA, top row first.
    pub lo: Vec<DVec4>,
    /// The highest value of each pixel.
    pub hi: Vec<DVec4>,
    /// The coverage of the first render (the unmoved one).
    pub coverage: Vec<bool>,
}

impl BandImage {
    /// The band of `images` (all of one size; the first gives the coverage). Panics when
    /// `images` is empty or the sizes differ.
    pub fn from_images(images: &[RefImage]) -> BandImage {
        let first = &images[0];
        let clamp = |v: DVec4| v.clamp(DVec4::ZERO, DVec4::ONE);
        let mut lo: Vec<DVec4> = first.pixels.iter().map(|&v| clamp(v)).collect();
        let mut hi = lo.clone();
        for img in &images[1..] {
            assert_eq!((img.width, img.height), (first.width, first.height));
            for (i, &v) in img.pixels.iter().enumerate() {
                lo[i] = lo[i].min(clamp(v));
                hi[i] = hi[i].max(clamp(v));
            }
        }
        BandImage {
            width: first.width,
            height: first.height,
            lo,
            hi,
            coverage: first.coverage.clone(),
        }
    }

    /// A band of one image (a point per pixel).
    pub fn point(image: &RefImage) -> BandImage {
        BandImage::from_images(std::slice::from_ref(image))
    }

    /// The coverage as a [`RefImage`] of the band's midpoint (for [`RefImage::silhouette_mask`]
    /// and pictures).
    pub fn midpoint(&self) -> RefImage {
        RefImage {
            width: self.width,
            height: self.height,
            pixels: self
                .lo
                .iter()
                .zip(&self.hi)
                .map(|(a, b)| (*a + *b) * 0.5)
                .collect(),
            coverage: self.coverage.clone(),
        }
    }
}

/// The band of `shaders` (each a float64 shader of the same picture, e.g. the model with its
/// cone cosines moved) rendered with every ray offset of `offsets` (pixels; include
/// `DVec2::ZERO` first for the coverage).
pub fn band(
    scene: &Scene,
    shaders: &[&dyn RefShader],
    offsets: &[DVec2],
    geometry: Geometry,
) -> Result<BandImage, LightsError> {
    let mut images = Vec::with_capacity(shaders.len() * offsets.len());
    for &o in offsets {
        for s in shaders {
            images.push(render_offset(scene, *s, geometry, o)?);
        }
    }
    if images.is_empty() {
        return Err(LightsError::Reference(
            "a band needs a shader and an offset".into(),
        ));
    }
    Ok(BandImage::from_images(&images))
}

/// Compares a GPU image with a reference band, in 1/255 units: per channel the distance of
/// the byte from `[255 · lo, 255 · hi]` (0 inside), so rounding alone costs up to 0.5. The
/// silhouette mask is the band's coverage's ([`RefImage::silhouette_mask`], radius 1).
pub fn compare_band(
    gpu: &RgbaImage,
    band: &BandImage,
    options: CompareOptions,
) -> Result<RefDiff, LightsError> {
    compare_band_excluding(gpu, band, options, &[])
}

/// [`compare_band`] leaving out, besides the silhouettes, the pixels where `exclude` is true
/// (e.g. those a NaN probe flagged; an empty slice excludes none).
pub fn compare_band_excluding(
    gpu: &RgbaImage,
    band: &BandImage,
    options: CompareOptions,
    exclude: &[bool],
) -> Result<RefDiff, LightsError> {
    same_size(gpu, band.width, band.height)?;
    let mut mask = if options.ignore_silhouettes {
        band.midpoint().silhouette_mask(1)
    } else {
        vec![false; band.lo.len()]
    };
    for (m, &e) in mask.iter_mut().zip(exclude) {
        *m |= e;
    }
    let mut stats = ErrorStats::new(band.width, band.lo.len());
    for (i, &masked) in mask.iter().enumerate() {
        if masked {
            stats.ignore();
            continue;
        }
        let mut errors = [0.0f64; 4];
        for (c, e) in errors.iter_mut().enumerate() {
            let (lo, hi) = (band.lo[i][c] * 255.0, band.hi[i][c] * 255.0);
            let g = f64::from(gpu.data[4 * i + c]);
            *e = if lo.is_nan() || hi.is_nan() {
                f64::INFINITY
            } else {
                (lo - g).max(g - hi).max(0.0)
            };
        }
        stats.add(i, errors);
    }
    Ok(stats.finish())
}

/// A picture of the error: black where within 1/255, then blue (≤ 2), yellow (≤ 8), red
/// (more), grey where left out.
pub fn error_image(
    gpu: &RgbaImage,
    reference: &RefImage,
    options: CompareOptions,
) -> Result<RgbaImage, LightsError> {
    same_size(gpu, reference.width, reference.height)?;
    let mask = left_out(reference, options);
    let mut data = Vec::with_capacity(gpu.data.len());
    for (i, r) in reference.pixels.iter().enumerate() {
        let e = (0..4)
            .map(|c| (f64::from(gpu.data[4 * i + c]) - r[c].clamp(0.0, 1.0) * 255.0).abs())
            .fold(0.0, f64::max);
        let px = if mask[i] {
            [96, 96, 96, 255]
        } else if e <= 1.0 {
            [0, 0, 0, 255]
        } else if e <= 2.0 {
            [0, 64, 255, 255]
        } else if e <= 8.0 {
            [255, 220, 0, 255]
        } else {
            [255, 0, 0, 255]
        };
        data.extend_from_slice(&px);
    }
    Ok(RgbaImage {
        width: gpu.width,
        height: gpu.height,
        data,
    })
}
