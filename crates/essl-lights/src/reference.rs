//! A float64 reference renderer: the same draw a GPU makes of an [`essl_scene::Scene`], with
//! every number in float64, to measure GPU images against.
//!
//! For each pixel centre a ray is cast through the scene's triangle mesh (the model, view and
//! projection matrices of the scene, inverted in float64): the ray from the near to the far
//! plane through the pixel centre, intersected with every triangle whose screen bounding box
//! holds the pixel (Möller–Trumbore). The nearest hit wins (GL's `LESS` depth test: on a tie
//! the earlier triangle), back faces are skipped when the scene culls them, and the facing is
//! GL's (counter-clockwise in window space). The ray's barycentric coordinates *are* GL's
//! perspective-correct barycentrics, so the vertex stage's outputs are interpolated exactly as
//! GL interpolates varyings: the reference measures the shader maths, not a different geometry.
//!
//! Shaders are [`RefShader`]s: a vertex stage (object-space attributes to float64 varyings) and
//! a fragment stage (interpolated varyings, `gl_FragCoord`, `gl_FrontFacing` to RGBA). Phong
//! shading interpolates normals and normalises per pixel; Gouraud evaluates the light at the
//! vertices and interpolates colours — whatever the stages say.
//!
//! [`Geometry::Exact`] replaces the mesh by the analytic surface it tessellates (sphere, plane,
//! cube) and runs the vertex stage at the exact hit point with the exact normal — per-pixel
//! evaluation of the true surface, to show the geometric error of a coarse tessellation.

use glam::{DVec2, DVec3, DVec4};

use essl_scene::{Filter, Mat4, MeshSpec, RgbaImage, Scene, Wrap};

use crate::error::LightsError;

/// A vertex's attributes, object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexIn {
    /// `position` stream.
    pub position: DVec3,
    /// `normal` stream (zero when the mesh has none).
    pub normal: DVec3,
    /// `uv` stream (zero when the mesh has none).
    pub uv: DVec2,
}

/// What a fragment stage sees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FragmentIn<'a> {
    /// The interpolated varyings.
    pub varyings: &'a [f64],
    /// `gl_FragCoord.xy`: window coordinates of the pixel centre (y up).
    pub frag_coord: DVec2,
    /// `gl_FrontFacing`.
    pub front_facing: bool,
}

/// A shader evaluated in float64.
pub trait RefShader {
    /// The vertex stage: attributes to varyings (any number, all interpolated).
    fn vertex(&self, v: &VertexIn) -> Vec<f64>;
    /// The fragment stage: the colour written (before the framebuffer's clamp).
    fn fragment(&self, f: &FragmentIn<'_>) -> DVec4;
}

/// A [`RefShader`] made of two closures.
pub struct FnShader<V, F> {
    /// The vertex stage.
    pub vertex: V,
    /// The fragment stage.
    pub fragment: F,
}

impl<V, F> RefShader for FnShader<V, F>
where
    V: Fn(&VertexIn) -> Vec<f64>,
    F: Fn(&FragmentIn<'_>) -> DVec4,
{
    fn vertex(&self, v: &VertexIn) -> Vec<f64> {
        (self.vertex)(v)
    }
    fn fragment(&self, f: &FragmentIn<'_>) -> DVec4 {
        (self.fragment)(f)
    }
}

/// Which surface the rays hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Geometry {
    /// The scene's triangle mesh, varyings interpolated (what the GPU draws).
    Mesh,
    /// The analytic surface the mesh approximates (`sphere`, `grid`, `cube`), the vertex stage
    /// run at the exact hit point with the exact normal and uv (a cube's uv is left zero).
    Exact,
}

/// A float64 image: linear RGBA as the fragment stage wrote it (not clamped), and which pixels
/// a surface covers (the others hold the clear colour).
#[derive(Clone, Debug, PartialEq)]
pub struct RefImage {
    /// Width.
    pub width: u32,
    /// Height.
    pub height: u32,
    /// RGBA, top row first.
    pub pixels: Vec<DVec4>,
    /// Coverage, top row first.
    pub coverage: Vec<bool>,
}

impl RefImage {
    /// The value at `(x, y)`, `y` from the top.
    pub fn pixel(&self, x: u32, y: u32) -> DVec4 {
        self.pixels[(y * self.width + x) as usize]
    }

    /// Whether a surface covers `(x, y)`.
    pub fn covered(&self, x: u32, y: u32) -> bool {
        self.coverage[(y * self.width + x) as usize]
    }

    /// The image as an 8-bit framebuffer stores it: clamped to [0, 1], `round(v · 255)`.
    pub fn to_rgba8(&self) -> RgbaImage {
        let data = self
            .pixels
            .iter()
            .flat_map(|p| {
                p.to_array()
                    .map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8)
            })
            .collect();
        RgbaImage {
            width: self.width,
            height: self.height,
            data,
        }
    }

    /// Pixels within `radius` pixels (Chebyshev distance) of a coverage change: the
    /// silhouettes, where a GPU's rasteriser may legitimately cover a pixel the reference does
    /// not (or the reverse) by rounding.
    pub fn silhouette_mask(&self, radius: u32) -> Vec<bool> {
        let (w, h) = (self.width as i64, self.height as i64);
        let r = i64::from(radius);
        let mut out = vec![false; self.coverage.len()];
        for y in 0..h {
            for x in 0..w {
                let c = self.coverage[(y * w + x) as usize];
                'search: for dy in -r..=r {
                    for dx in -r..=r {
                        let (nx, ny) = (x + dx, y + dy);
                        if nx < 0 || ny < 0 || nx >= w || ny >= h {
                            continue;
                        }
                        if self.coverage[(ny * w + nx) as usize] != c {
                            out[(y * w + x) as usize] = true;
                            break 'search;
                        }
                    }
                }
            }
        }
        out
    }
}

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

/// Compares a GPU image (rows top first, as [`RgbaImage`] stores them) with a reference.
pub fn compare_rgba8(
    gpu: &RgbaImage,
    reference: &RefImage,
    options: CompareOptions,
) -> Result<RefDiff, LightsError> {
    if gpu.width != reference.width || gpu.height != reference.height {
        return Err(LightsError::SizeMismatch {
            a_width: gpu.width,
            a_height: gpu.height,
            b_width: reference.width,
            b_height: reference.height,
        });
    }
    let mask = if options.ignore_silhouettes {
        reference.silhouette_mask(1)
    } else {
        vec![false; reference.pixels.len()]
    };
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
    if gpu.width != band.width || gpu.height != band.height {
        return Err(LightsError::SizeMismatch {
            a_width: gpu.width,
            a_height: gpu.height,
            b_width: band.width,
            b_height: band.height,
        });
    }
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
    if gpu.width != reference.width || gpu.height != reference.height {
        return Err(LightsError::SizeMismatch {
            a_width: gpu.width,
            a_height: gpu.height,
            b_width: reference.width,
            b_height: reference.height,
        });
    }
    let mask = if options.ignore_silhouettes {
        reference.silhouette_mask(1)
    } else {
        vec![false; reference.pixels.len()]
    };
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

/// Samples an RGBA8 texture as GL does with `filter` and `wrap` (no mipmaps), in float64;
/// NaN for non-finite coordinates.
pub fn sample_texture(
    width: u32,
    height: u32,
    texels: &[u8],
    filter: Filter,
    wrap: Wrap,
    uv: DVec2,
) -> DVec4 {
    if !uv.is_finite() {
        return DVec4::NAN;
    }
    let wrap_i = |i: i64, n: i64| -> i64 {
        match wrap {
            Wrap::Clamp => i.clamp(0, n - 1),
            Wrap::Repeat => i.rem_euclid(n),
            Wrap::Mirror => {
                let m = i.rem_euclid(2 * n);
                if m >= n {
                    2 * n - 1 - m
                } else {
                    m
                }
            }
        }
    };
    let (w, h) = (i64::from(width), i64::from(height));
    let texel = |x: i64, y: i64| -> DVec4 {
        let i = ((wrap_i(y, h) * w + wrap_i(x, w)) * 4) as usize;
        DVec4::new(
            f64::from(texels[i]),
            f64::from(texels[i + 1]),
            f64::from(texels[i + 2]),
            f64::from(texels[i + 3]),
        ) / 255.0
    };
    // Far outside any texture: the wrap of a huge coordinate (avoid i64 overflow).
    let (su, sv) = (
        (uv.x * width as f64).clamp(-1e15, 1e15),
        (uv.y * height as f64).clamp(-1e15, 1e15),
    );
    match filter {
        Filter::Nearest => texel(su.floor() as i64, sv.floor() as i64),
        Filter::Linear => {
            let (x, y) = (su - 0.5, sv - 0.5);
            let (x0, y0) = (x.floor(), y.floor());
            let (fx, fy) = (x - x0, y - y0);
            let (x0, y0) = (x0 as i64, y0 as i64);
            let a = texel(x0, y0).lerp(texel(x0 + 1, y0), fx);
            let b = texel(x0, y0 + 1).lerp(texel(x0 + 1, y0 + 1), fx);
            a.lerp(b, fy)
        }
    }
}

fn mat(m: &Mat4) -> glam::DMat4 {
    glam::DMat4::from_cols_array(&m.0)
}

/// A triangle prepared for intersection.
struct Tri {
    idx: [usize; 3],
    p0: DVec3,
    e1: DVec3,
    e2: DVec3,
}

/// Renders `scene`'s geometry (mesh, matrices, canvas, culling, depth test, clear colour)
/// through `shader`, in float64.
pub fn render(
    scene: &Scene,
    shader: &dyn RefShader,
    geometry: Geometry,
) -> Result<RefImage, LightsError> {
    render_offset(scene, shader, geometry, DVec2::ZERO)
}

/// [`render`] with every ray moved by `offset` pixels from the pixel centre (x right, y down),
/// `gl_FragCoord` left at the centre: the picture a rasteriser draws when it snaps the
/// vertices by `-offset` (lavapipe snaps window coordinates to 1/256 pixel). The reference
/// bands of [`band`] use it.
pub fn render_offset(
    scene: &Scene,
    shader: &dyn RefShader,
    geometry: Geometry,
    offset: DVec2,
) -> Result<RefImage, LightsError> {
    let (w, h) = (scene.width(), scene.height());
    let mvp = mat(&scene.matrices.model_view_projection);
    let inv = mvp.inverse();
    if !inv.is_finite() || mvp.determinant() == 0.0 {
        return Err(LightsError::Reference(
            "the model-view-projection matrix is singular".into(),
        ));
    }
    // GL decides facing in window space; in object space that is the orientation seen from the
    // eye, reversed when the model-view mirrors.
    let mv3 = glam::DMat3::from_mat4(mat(&scene.matrices.model_view));
    let mirror = mv3.determinant() < 0.0;
    let clear = DVec4::from_array(scene.clear_color());
    let mut image = RefImage {
        width: w,
        height: h,
        pixels: vec![clear; (w * h) as usize],
        coverage: vec![false; (w * h) as usize],
    };
    let ray = |x: u32, row: u32| -> (DVec3, DVec3) {
        let ndc_x = 2.0 * (f64::from(x) + 0.5 + offset.x) / f64::from(w) - 1.0;
        let win_y = f64::from(h - 1 - row) + 0.5 - offset.y;
        let ndc_y = 2.0 * win_y / f64::from(h) - 1.0;
        let a = inv * DVec4::new(ndc_x, ndc_y, -1.0, 1.0);
        let b = inv * DVec4::new(ndc_x, ndc_y, 1.0, 1.0);
        let a = a.truncate() / a.w;
        let b = b.truncate() / b.w;
        (a, b - a)
    };
    let frag = |x: u32, row: u32| DVec2::new(f64::from(x) + 0.5, f64::from(h - 1 - row) + 0.5);
    match geometry {
        Geometry::Mesh => render_mesh(scene, shader, &mvp, mirror, &mut image, &ray, &frag)?,
        Geometry::Exact => render_exact(scene, shader, mirror, &mut image, &ray, &frag)?,
    }
    Ok(image)
}

#[allow(clippy::too_many_arguments)]
fn render_mesh(
    scene: &Scene,
    shader: &dyn RefShader,
    mvp: &glam::DMat4,
    mirror: bool,
    image: &mut RefImage,
    ray: &dyn Fn(u32, u32) -> (DVec3, DVec3),
    frag: &dyn Fn(u32, u32) -> DVec2,
) -> Result<(), LightsError> {
    let mesh = &scene.mesh;
    let pos = mesh
        .position
        .as_ref()
        .ok_or_else(|| LightsError::Reference("the mesh has no positions".into()))?;
    let n = mesh.vertex_count();
    let get3 = |s: &Option<Vec<f64>>, i: usize| -> DVec3 {
        s.as_ref()
            .map(|v| DVec3::new(v[3 * i], v[3 * i + 1], v[3 * i + 2]))
            .unwrap_or(DVec3::ZERO)
    };
    let verts: Vec<VertexIn> = (0..n)
        .map(|i| VertexIn {
            position: DVec3::new(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]),
            normal: get3(&mesh.normal, i),
            uv: mesh
                .uv
                .as_ref()
                .map(|v| DVec2::new(v[2 * i], v[2 * i + 1]))
                .unwrap_or(DVec2::ZERO),
        })
        .collect();
    let varyings: Vec<Vec<f64>> = verts.iter().map(|v| shader.vertex(v)).collect();
    let nv = varyings.first().map_or(0, Vec::len);
    let tris: Vec<Tri> = mesh
        .triangles()
        .into_iter()
        .map(|t| {
            let idx = t.map(|i| i as usize);
            let p0 = verts[idx[0]].position;
            Tri {
                idx,
                p0,
                e1: verts[idx[1]].position - p0,
                e2: verts[idx[2]].position - p0,
            }
        })
        .collect();
    // Bin triangles into 8x8-pixel tiles by their window bounding box (all tiles when a vertex
    // is behind the eye).
    let (w, h) = (image.width, image.height);
    const TILE: u32 = 8;
    let (tw, th) = (w.div_ceil(TILE), h.div_ceil(TILE));
    let mut bins: Vec<Vec<usize>> = vec![Vec::new(); (tw * th) as usize];
    for (ti, t) in tris.iter().enumerate() {
        let mut lo = DVec2::splat(f64::INFINITY);
        let mut hi = DVec2::splat(f64::NEG_INFINITY);
        let mut behind = 0;
        for &i in &t.idx {
            let c = *mvp * verts[i].position.extend(1.0);
            if c.w <= 0.0 {
                behind += 1;
                continue;
            }
            let win = DVec2::new(
                (c.x / c.w + 1.0) * 0.5 * f64::from(w),
                (1.0 - (c.y / c.w + 1.0) * 0.5) * f64::from(h),
            );
            lo = lo.min(win);
            hi = hi.max(win);
        }
        if behind == 3 {
            // Wholly behind the eye: clipped away.
            continue;
        }
        let (x0, x1, y0, y1) = if behind > 0 {
            (0, tw - 1, 0, th - 1)
        } else {
            if hi.x < -1.0 || hi.y < -1.0 || lo.x > f64::from(w) + 1.0 || lo.y > f64::from(h) + 1.0
            {
                continue;
            }
            let tx = |v: f64, n: u32| ((v.max(0.0) / f64::from(TILE)) as u32).min(n - 1);
            (
                tx(lo.x - 1.0, tw),
                tx(hi.x + 1.0, tw),
                tx(lo.y - 1.0, th),
                tx(hi.y + 1.0, th),
            )
        };
        for ty in y0..=y1 {
            for tx in x0..=x1 {
                bins[(ty * tw + tx) as usize].push(ti);
            }
        }
    }
    let cull = scene.cull_face();
    let depth = scene.depth_test();
    let mut interp = vec![0.0; nv];
    for row in 0..h {
        for x in 0..w {
            let (origin, dir) = ray(x, row);
            let bin = &bins[((row / TILE) * tw + x / TILE) as usize];
            let mut best: Option<(f64, usize, f64, f64, bool)> = None;
            for &ti in bin {
                let t = &tris[ti];
                let pvec = dir.cross(t.e2);
                let det = t.e1.dot(pvec);
                if det == 0.0 || !det.is_finite() {
                    continue;
                }
                let front = (det > 0.0) != mirror;
                if cull && !front {
                    continue;
                }
                let inv_det = 1.0 / det;
                let tvec = origin - t.p0;
                let u = tvec.dot(pvec) * inv_det;
                if !(0.0..=1.0).contains(&u) {
                    continue;
                }
                let qvec = tvec.cross(t.e1);
                let v = dir.dot(qvec) * inv_det;
                if v < 0.0 || u + v > 1.0 {
                    continue;
                }
                let s = t.e2.dot(qvec) * inv_det;
                if !(0.0..=1.0).contains(&s) {
                    continue;
                }
                let better = match best {
                    None => true,
                    Some((bs, bi, ..)) => {
                        if depth {
                            s < bs || (s == bs && ti < bi)
                        } else {
                            ti > bi
                        }
                    }
                };
                if better {
                    best = Some((s, ti, u, v, front));
                }
            }
            if let Some((_, ti, u, v, front)) = best {
                let t = &tris[ti];
                let b = [1.0 - u - v, u, v];
                for (k, slot) in interp.iter_mut().enumerate() {
                    *slot = b[0] * varyings[t.idx[0]][k]
                        + b[1] * varyings[t.idx[1]][k]
                        + b[2] * varyings[t.idx[2]][k];
                }
                let c = shader.fragment(&FragmentIn {
                    varyings: &interp,
                    frag_coord: frag(x, row),
                    front_facing: front,
                });
                let i = (row * w + x) as usize;
                image.pixels[i] = c;
                image.coverage[i] = true;
            }
        }
    }
    Ok(())
}

fn render_exact(
    scene: &Scene,
    shader: &dyn RefShader,
    mirror: bool,
    image: &mut RefImage,
    ray: &dyn Fn(u32, u32) -> (DVec3, DVec3),
    frag: &dyn Fn(u32, u32) -> DVec2,
) -> Result<(), LightsError> {
    let spec = scene.file.mesh.clone();
    if matches!(spec, MeshSpec::Arrays { .. }) {
        return Err(LightsError::Reference(
            "an arrays mesh has no analytic surface for the exact mode".into(),
        ));
    }
    let cull = scene.cull_face();
    let (w, h) = (image.width, image.height);
    for row in 0..h {
        for x in 0..w {
            let (o, d) = ray(x, row);
            let hit = match spec {
                MeshSpec::Sphere { radius, .. } => hit_sphere(o, d, radius, cull, mirror),
                MeshSpec::Grid { size, .. } => hit_plane(o, d, size, cull, mirror),
                MeshSpec::Cube { size } => hit_cube(o, d, size, cull, mirror),
                MeshSpec::Arrays { .. } => None,
            };
            if let Some((p, n, uv, front)) = hit {
                let v = shader.vertex(&VertexIn {
                    position: p,
                    normal: n,
                    uv,
                });
                let c = shader.fragment(&FragmentIn {
                    varyings: &v,
                    frag_coord: frag(x, row),
                    front_facing: front,
                });
                let i = (row * w + x) as usize;
                image.pixels[i] = c;
                image.coverage[i] = true;
            }
        }
    }
    Ok(())
}

type Hit = (DVec3, DVec3, DVec2, bool);

fn facing(d: DVec3, n: DVec3, mirror: bool) -> bool {
    (d.dot(n) < 0.0) != mirror
}

fn hit_sphere(o: DVec3, d: DVec3, r: f64, cull: bool, mirror: bool) -> Option<Hit> {
    // |o + t d|^2 = r^2, t in [0, 1].
    let a = d.dot(d);
    let b = o.dot(d);
    let c = o.dot(o) - r * r;
    let disc = b * b - a * c;
    if disc < 0.0 {
        return None;
    }
    let sq = disc.sqrt();
    // Numerically stable roots.
    let q = -(b + sq.copysign(b));
    let mut ts = [q / a, if q != 0.0 { c / q } else { q / a }];
    ts.sort_by(|x, y| x.total_cmp(y));
    for t in ts {
        if !(0.0..=1.0).contains(&t) {
            continue;
        }
        let p = o + d * t;
        let n = p / r;
        let front = facing(d, n, mirror);
        if cull && !front {
            continue;
        }
        let theta = (n.y.clamp(-1.0, 1.0)).acos();
        let phi = n.x.atan2(n.z).rem_euclid(std::f64::consts::TAU);
        let uv = DVec2::new(phi / std::f64::consts::TAU, theta / std::f64::consts::PI);
        return Some((p, n, uv, front));
    }
    None
}

fn hit_plane(o: DVec3, d: DVec3, size: f64, cull: bool, mirror: bool) -> Option<Hit> {
    if d.y == 0.0 {
        return None;
    }
    let t = -o.y / d.y;
    if !(0.0..=1.0).contains(&t) {
        return None;
    }
    let p = o + d * t;
    let half = size / 2.0;
    if p.x.abs() > half || p.z.abs() > half {
        return None;
    }
    let n = DVec3::Y;
    let front = facing(d, n, mirror);
    if cull && !front {
        return None;
    }
    let uv = DVec2::new((p.x + half) / size, (p.z + half) / size);
    Some((DVec3::new(p.x, 0.0, p.z), n, uv, front))
}

fn hit_cube(o: DVec3, d: DVec3, size: f64, cull: bool, mirror: bool) -> Option<Hit> {
    let h = size / 2.0;
    let mut best: Option<(f64, Hit)> = None;
    for axis in 0..3 {
        for sign in [1.0, -1.0] {
            if d[axis] == 0.0 {
                continue;
            }
            let t = (sign * h - o[axis]) / d[axis];
            if !(0.0..=1.0).contains(&t) {
                continue;
            }
            let p = o + d * t;
            let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
            if p[a].abs() > h || p[b].abs() > h {
                continue;
            }
            let mut n = DVec3::ZERO;
            n[axis] = sign;
            let front = facing(d, n, mirror);
            if cull && !front {
                continue;
            }
            if best.as_ref().is_none_or(|(bt, _)| t < *bt) {
                best = Some((t, (p, n, DVec2::ZERO, front)));
            }
        }
    }
    best.map(|(_, hit)| hit)
}

/// The float64 reference of a library scene: [`crate::ideal`]'s model as a [`RefShader`],
/// staged like the generated shaders — Phong shading interpolates the world position and
/// normal and evaluates per pixel; Gouraud evaluates at the vertices (world position
/// `model · p`, normal `normalize(normalMatrix · n)`) and interpolates the colours, screen
/// cookies applied per pixel.
pub struct LitShader {
    scene: crate::LitScene,
    prepared: crate::PreparedScene,
    model: glam::DMat4,
    normal: glam::DMat3,
    eye: DVec3,
    inv_viewport: DVec2,
    shift: f64,
    offset: DVec3,
}

impl LitShader {
    /// The reference shader of `scene` seen from `view`.
    pub fn new(scene: &crate::LitScene, view: &crate::View) -> Result<LitShader, LightsError> {
        let prepared = scene.prepare()?;
        let nm = view.normal_matrix()?;
        let inv_viewport = if prepared.shape.has_screen_cookie() {
            view.inv_viewport()?
        } else {
            view.inv_viewport().unwrap_or([0.0, 0.0])
        };
        Ok(LitShader {
            scene: scene.clone(),
            prepared,
            model: mat(&view.matrices.model),
            normal: glam::DMat3::from_cols_array(&nm),
            eye: DVec3::from_array(view.matrices.eye),
            inv_viewport: DVec2::from_array(inv_viewport),
            shift: 0.0,
            offset: DVec3::ZERO,
        })
    }

    /// The same shader with every world position moved by `offset` before lighting (the
    /// reference band of a float32 GPU's interpolated position near a singular point, such as a
    /// light on the surface).
    pub fn with_offset(mut self, offset: DVec3) -> LitShader {
        self.offset = offset;
        self
    }

    /// The same shader with both cone cosines of every spot light moved by `shift` (the
    /// reference band of a hard edge: see [`band`] and [`crate::stiff::BAND`]).
    pub fn with_shift(mut self, shift: f64) -> LitShader {
        self.shift = shift;
        self
    }

    fn cookie(&self, i: usize, uv: DVec2) -> DVec3 {
        match &self.scene.lights[i] {
            crate::Light::Spot(s) => match &s.cookie {
                Some(c) => {
                    let img = c.image();
                    sample_texture(img.width, img.height, &img.texels, img.filter, img.wrap, uv)
                        .truncate()
                }
                None => DVec3::ONE,
            },
            _ => DVec3::ONE,
        }
    }
}

impl RefShader for LitShader {
    fn vertex(&self, v: &VertexIn) -> Vec<f64> {
        let p = (self.model * v.position.extend(1.0)).truncate() + self.offset;
        let n = self.normal * v.normal;
        match self.scene.shading {
            crate::Shading::Phong => vec![p.x, p.y, p.z, n.x, n.y, n.z],
            crate::Shading::Gouraud => {
                let s = crate::ideal::Surface {
                    position: p,
                    normal: n,
                    eye: self.eye,
                    frag_coord: DVec2::ZERO,
                };
                let t = crate::ideal::terms(
                    &self.scene,
                    &self.prepared,
                    &s,
                    &|i, uv| self.cookie(i, uv),
                    self.inv_viewport,
                    self.shift,
                    true,
                );
                let mut out = t.base.to_array().to_vec();
                for (_, c) in t.deferred {
                    out.extend(c.to_array());
                }
                out
            }
        }
    }

    fn fragment(&self, f: &FragmentIn<'_>) -> DVec4 {
        let v = f.varyings;
        let rgb = match self.scene.shading {
            crate::Shading::Phong => {
                let s = crate::ideal::Surface {
                    position: DVec3::new(v[0], v[1], v[2]),
                    normal: DVec3::new(v[3], v[4], v[5]),
                    eye: self.eye,
                    frag_coord: f.frag_coord,
                };
                crate::ideal::terms(
                    &self.scene,
                    &self.prepared,
                    &s,
                    &|i, uv| self.cookie(i, uv),
                    self.inv_viewport,
                    self.shift,
                    false,
                )
                .base
            }
            crate::Shading::Gouraud => {
                let mut c = DVec3::new(v[0], v[1], v[2]);
                let screen = self.prepared.lights.iter().enumerate().filter(|(_, l)| {
                    matches!(
                        l.shape,
                        crate::LightShape::Spot {
                            cookie: Some(crate::CookieKind::Screen),
                            ..
                        }
                    )
                });
                for (k, (i, _)) in screen.enumerate() {
                    let o = 3 + 3 * k;
                    let uv = crate::ideal::screen_uv(f.frag_coord, self.inv_viewport);
                    c += self.cookie(i, uv) * DVec3::new(v[o], v[o + 1], v[o + 2]);
                }
                c
            }
        };
        rgb.extend(1.0)
    }
}
