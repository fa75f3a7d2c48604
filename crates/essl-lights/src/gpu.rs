//! Drawing generated programs through essl-gl (WebGL2's API on wgpu; Mesa's software
//! rasteriser lavapipe here) and measuring the pictures against the float64 reference.
//!
//! - [`render`] draws a [`Scene`] once and reads it back; [`Timer`] keeps a scene set up and
//!   times frames as `webgl2-render.py --times N` does (clear + draw + `readPixels` of one
//!   pixel, which waits for the GPU).
//! - [`probe_program`] makes the **NaN probe** of a program. An RGBA8 framebuffer cannot hold a
//!   NaN or an infinity: the conversion to bytes turns them into some byte (lavapipe: 0 for
//!   NaN, 255 for +∞), so a NaN pixel can look right. The probe is the same program with two
//!   changes in the fragment shader: every `texture(s, uv)` goes through a helper that records
//!   whether `uv` was NaN or infinite (GLSL leaves `texture()` of such coordinates undefined, and
//!   the texture unit turns them into an ordinary texel), and the final
//!   `o_color = vec4(color, 1.0);` becomes a flag: [`PROBE_NON_FINITE`] when
//!   `any(isnan(color)) || any(isinf(color))` or a coordinate was, [`PROBE_FINITE`] otherwise.
//!   Everything before that line is the program's own code, so the probe sees the values the
//!   program computes. [`count_probe`] counts the flags. The probe itself is checked by a
//!   program that is NaN everywhere (`tests/it/gpu_stiff.rs`).
//! - [`hard_edge`] and [`reference_band`]: the float64 reference of a lit scene, as a band
//!   where the picture has a hard edge (see [`crate::reference::BandImage`]).

use std::time::Instant;

use glam::{DVec2, DVec3};

use essl_gl::scene::{SceneRenderError, SceneRenderer};
use essl_scene::{RgbaImage, Scene};

use crate::error::LightsError;
use crate::program::ShaderPair;
use crate::reference::{band, BandImage, Geometry, LitShader, RefShader};
use crate::scene::{EdgeProfile, LightShape, LitScene, MAX_EDGE_SLOPE};
use crate::uniforms::View;

/// The probe's colour for a fragment whose colour (or a texture coordinate) was NaN or
/// infinite.
pub const PROBE_NON_FINITE: [u8; 4] = [255, 0, 255, 255];
/// The probe's colour for a finite fragment.
pub const PROBE_FINITE: [u8; 4] = [0, 255, 0, 255];

/// The line every generated fragment shader (library and seed programs) ends its `main` with.
pub const OUTPUT_LINE: &str = "o_color = vec4(color, 1.0);";

fn gpu_err(e: SceneRenderError) -> LightsError {
    LightsError::Gpu(e.to_string())
}

/// The adapter essl-gl renders with (`"llvmpipe (LLVM 15.0.6, 256 bits)"` for lavapipe) and
/// its driver description, or an error when the machine has no Vulkan adapter.
pub fn adapter() -> Result<(String, String), LightsError> {
    let ctx = essl_gl::Context::new(1, 1).map_err(|e| LightsError::Gpu(e.to_string()))?;
    let info = ctx.adapter_info();
    let driver = format!("{} {}", info.driver, info.driver_info)
        .trim()
        .to_string();
    Ok((info.name.clone(), driver))
}

/// Draws `scene` once through essl-gl and reads the picture back (top row first).
pub fn render(scene: &Scene) -> Result<RgbaImage, LightsError> {
    Ok(essl_gl::scene::render_scene(scene, 0)
        .map_err(gpu_err)?
        .image)
}

/// A scene set up on its own context, for timing frames.
pub struct Timer {
    renderer: SceneRenderer,
}

impl Timer {
    /// Sets `scene` up (context, program, uniforms, buffers) and draws one untimed frame.
    pub fn new(scene: &Scene) -> Result<Timer, LightsError> {
        let mut renderer = SceneRenderer::new(scene).map_err(gpu_err)?;
        renderer.frame();
        renderer.read_image().map_err(gpu_err)?;
        Ok(Timer { renderer })
    }

    /// The milliseconds of `n` frames, each `clear` + draw + `readPixels` of one pixel.
    pub fn frames(&mut self, n: usize) -> Vec<f64> {
        self.renderer.time_frames(n)
    }

    /// The milliseconds of `n` frames, timed together (one `readPixels` of one pixel at the
    /// end), divided by `n`: for very short frames.
    pub fn batch(&mut self, n: usize) -> f64 {
        let t0 = Instant::now();
        for _ in 0..n.saturating_sub(1) {
            self.renderer.frame();
        }
        self.renderer.time_frames(1);
        t0.elapsed().as_secs_f64() * 1000.0 / n.max(1) as f64
    }
}

/// The median (the mean of the middle two for an even count); `None` when empty.
pub fn median(values: &[f64]) -> Option<f64> {
    if values.is_empty() {
        return None;
    }
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    Some(if n % 2 == 1 {
        v[n / 2]
    } else {
        (v[n / 2 - 1] + v[n / 2]) / 2.0
    })
}

const PROBE_HELPER: &str = "\
// NaN probe (essl-lights gpu::probe_program): texture() of a NaN or infinite coordinate is
// undefined, so it is recorded; the output is a flag instead of the colour.
bool el_probeNonFinite = false;
vec4 el_probeTexture(sampler2D s, vec2 uv) {
  el_probeNonFinite = el_probeNonFinite || any(isnan(uv)) || any(isinf(uv));
  return texture(s, uv);
}
";

/// Replaces every call of `texture(` (not `textureSize(` or an identifier ending in
/// `texture`) by `el_probeTexture(`.
fn wrap_texture_calls(src: &str) -> String {
    let mut out = String::with_capacity(src.len() + 64);
    let bytes = src.as_bytes();
    let mut i = 0;
    while i < src.len() {
        if src[i..].starts_with("texture(") {
            let before = if i == 0 { b' ' } else { bytes[i - 1] };
            if !(before.is_ascii_alphanumeric() || before == b'_') {
                out.push_str("el_probeTexture(");
                i += "texture(".len();
                continue;
            }
        }
        let c = src[i..].chars().next().expect("in bounds");
        out.push(c);
        i += c.len_utf8();
    }
    out
}

/// The NaN probe of `program` (see the module docs): its fragment shader must end its `main`
/// with [`OUTPUT_LINE`] exactly once, as every generated program does.
pub fn probe_program(program: &ShaderPair) -> Result<ShaderPair, LightsError> {
    let fs = &program.fragment;
    if fs.matches(OUTPUT_LINE).count() != 1 {
        return Err(LightsError::Gpu(format!(
            "the probe needs exactly one `{OUTPUT_LINE}` in the fragment shader"
        )));
    }
    let decl = "out vec4 o_color;\n";
    let at = fs
        .find(decl)
        .ok_or_else(|| LightsError::Gpu("the fragment shader declares no o_color".into()))?
        + decl.len();
    let (head, body) = fs.split_at(at);
    let flag = |c: [u8; 4]| {
        format!(
            "vec4({:.1}, {:.1}, {:.1}, 1.0)",
            f64::from(c[0]) / 255.0,
            f64::from(c[1]) / 255.0,
            f64::from(c[2]) / 255.0
        )
    };
    let body = wrap_texture_calls(body).replace(
        OUTPUT_LINE,
        &format!(
            "o_color = (el_probeNonFinite || any(isnan(color)) || any(isinf(color))) ? {} : {};",
            flag(PROBE_NON_FINITE),
            flag(PROBE_FINITE)
        ),
    );
    let mut p = program.clone();
    p.fragment = format!("{head}{PROBE_HELPER}{body}");
    Ok(p)
}

/// What a probe picture shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct ProbeCount {
    /// Fragments flagged NaN or infinite.
    pub non_finite: usize,
    /// Fragments flagged finite.
    pub finite: usize,
    /// Other pixels (the clear colour: no fragment).
    pub background: usize,
}

/// Counts the flags of a probe picture.
pub fn count_probe(image: &RgbaImage) -> ProbeCount {
    let mut c = ProbeCount::default();
    for px in image.data.chunks_exact(4) {
        if px == PROBE_NON_FINITE {
            c.non_finite += 1;
        } else if px == PROBE_FINITE {
            c.finite += 1;
        } else {
            c.background += 1;
        }
    }
    c
}

/// Whether the scene's picture has a hard edge: a spot light with the step profile, or whose
/// ramp is capped at [`MAX_EDGE_SLOPE`] (inner == outer, a 0° cone).
pub fn hard_edge(scene: &LitScene) -> bool {
    let Ok(p) = scene.prepare() else {
        return false;
    };
    p.lights.iter().any(|l| match l.shape {
        LightShape::Spot { edge, .. } => edge == EdgeProfile::Step || l.inv_range >= MAX_EDGE_SLOPE,
        _ => false,
    })
}

/// How far a hard edge may move in a float32 rasteriser, in pixels: lavapipe snaps window
/// coordinates to 1/256 pixel (at most 1/512 off per axis); the band moves rays by twice that.
pub const BAND_OFFSET_PX: f64 = 1.0 / 256.0;

/// The float64 reference of `lit` drawn on `scene`'s geometry from `view`: a point per pixel
/// where the picture is continuous, and for a scene with a [`hard_edge`] the band of the model
/// with both cone cosines moved by `−δ, 0, +δ` ([`crate::stiff::BAND`]) and the rays moved by
/// `0, ±`[`BAND_OFFSET_PX`] along x and y (15 renders).
pub fn reference_band(
    scene: &Scene,
    lit: &LitScene,
    view: &View,
    geometry: Geometry,
) -> Result<BandImage, LightsError> {
    reference_band_jittered(scene, lit, view, geometry, 0.0)
}

/// [`reference_band`], and with `world_jitter > 0` also the model at every surface point moved
/// by `±world_jitter` along each world axis (6 more renders): a float32 GPU's interpolated
/// position is only that close to the surface, which matters where the model is singular (a
/// light on the surface, where `L` is the direction of a vector of rounding size).
pub fn reference_band_jittered(
    scene: &Scene,
    lit: &LitScene,
    view: &View,
    geometry: Geometry,
    world_jitter: f64,
) -> Result<BandImage, LightsError> {
    let centre = LitShader::new(lit, view)?;
    if world_jitter > 0.0 {
        let mut shaders = vec![centre];
        for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
            for sign in [1.0, -1.0] {
                shaders.push(LitShader::new(lit, view)?.with_offset(axis * sign * world_jitter));
            }
        }
        let refs: Vec<&dyn RefShader> = shaders.iter().map(|s| s as &dyn RefShader).collect();
        return band(scene, &refs, &[DVec2::ZERO], geometry);
    }
    if !hard_edge(lit) {
        return band(scene, &[&centre], &[DVec2::ZERO], geometry);
    }
    let d = crate::stiff::BAND;
    let lo = LitShader::new(lit, view)?.with_shift(-d);
    let hi = LitShader::new(lit, view)?.with_shift(d);
    let shaders: [&dyn RefShader; 3] = [&centre, &lo, &hi];
    let e = BAND_OFFSET_PX;
    let offsets = [
        DVec2::ZERO,
        DVec2::new(e, 0.0),
        DVec2::new(-e, 0.0),
        DVec2::new(0.0, e),
        DVec2::new(0.0, -e),
    ];
    band(scene, &shaders, &offsets, geometry)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texture_calls_are_wrapped() {
        assert_eq!(
            wrap_texture_calls("a = texture(s, uv) + mytexture(x) + textureSize(s, 0);"),
            "a = el_probeTexture(s, uv) + mytexture(x) + textureSize(s, 0);"
        );
    }

    #[test]
    fn medians() {
        assert_eq!(median(&[]), None);
        assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
        assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), Some(2.5));
    }
}
