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

mod compare;
mod lit;
mod raster;
mod surfaces;

use glam::{DVec2, DVec3, DVec4};

use essl_scene::{Filter, Mat4, RgbaImage, Scene, Wrap};

use crate::error::LightsError;

pub use compare::{
    band, compare_band, compare_band_excluding, compare_rgba8, error_image, BandImage,
    CompareOptions, RefDiff,
};
pub use lit::LitShader;

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

pub(crate) fn mat(m: &Mat4) -> glam::DMat4 {
    glam::DMat4::from_cols_array(&m.0)
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
    let camera = raster::Camera::new(scene, offset)?;
    let clear = DVec4::from_array(scene.clear_color());
    let (w, h) = (scene.width(), scene.height());
    let mut image = RefImage {
        width: w,
        height: h,
        pixels: vec![clear; (w * h) as usize],
        coverage: vec![false; (w * h) as usize],
    };
    match geometry {
        Geometry::Mesh => raster::render_mesh(scene, shader, &camera, &mut image)?,
        Geometry::Exact => raster::render_exact(scene, shader, &camera, &mut image)?,
    }
    Ok(image)
}
