//! The description of a lit scene: lights, material, shading and reflection model — what the
//! generator turns into shaders, the uniforms into values and the reference into pixels.
//!
//! All quantities are float64 and in **world space**. Colours are linear RGB, 0 and above
//! (above 1 acts as intensity). Cone angles are **half-angles in degrees** (the angle between
//! the spot's axis and the cone's edge, as three.js's `angle`), `0 ≤ inner ≤ outer ≤ 180`.
//!
//! [`LitScene::validate`] refuses what would render NaN or an undefined picture (see
//! `docs/numerical-stability.md` and [`LightsError`]); [`LitScene::prepare`] computes, in
//! float64, the values the shaders receive (unit directions, cone cosines and slopes, the
//! projector basis).

use glam::DVec3;

use essl_scene::{Filter, Wrap};

use crate::error::LightsError;

/// The most lights one specialised shader takes (each spot light needs up to 6 uniform vectors
/// and, in Gouraud shading with a screen-space cookie, one varying).
pub const MAX_LIGHTS: usize = 8;

/// The largest shininess accepted: above it, the float32 rounding of `N·H` (about `1e-7`) times
/// the exponent exceeds 1/255 in the highlight.
pub const MAX_SHININESS: f64 = 1.0e4;

/// The smallest angle (radians, as a sine) between a projector's up vector and its direction.
pub const MIN_UP_SINE: f64 = 1.0e-6;

/// The steepest edge ramp sent to a shader, in 1 / (unit of cosine): a cone whose inner and
/// outer cosines are closer than `1 / MAX_EDGE_SLOPE` (inner == outer included) gets this slope,
/// which is a step for every float32 input (see `docs/numerical-stability.md`, "inner == outer").
pub const MAX_EDGE_SLOPE: f64 = 1_099_511_627_776.0; // 2^40

/// Where lighting is evaluated.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Shading {
    /// Per vertex, the colour interpolated (article 002's Gouraud).
    Gouraud,
    /// Per fragment, the normal interpolated (article 002's Phong shading).
    Phong,
}

/// The reflection model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Reflection {
    /// Diffuse only: `max(N·L, 0)`.
    Lambert,
    /// Diffuse plus Phong's specular `max(R·V, 0)^n`, `R = reflect(-L, N)`.
    Phong,
    /// Diffuse plus Blinn's specular `max(N·H, 0)^n`, `H = normalize(L + V)`.
    BlinnPhong,
}

impl Reflection {
    /// Whether the model has a specular term.
    pub fn has_specular(self) -> bool {
        !matches!(self, Reflection::Lambert)
    }
}

/// How a spot light's intensity falls from the inner to the outer cone.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EdgeProfile {
    /// Hard edge at the outer cone: `d >= cos(outer)` (article 001's `step`); `inner` unused.
    Step,
    /// Linear in the cosine from outer (0) to inner (1) (article 001's clamp).
    Linear,
    /// Hermite `t²(3 − 2t)` of the linear ramp (article 000's `smoothstep`).
    Smooth,
}

/// An RGBA8 image used as a cookie (light filter); only its RGB is used.
#[derive(Clone, Debug, PartialEq)]
pub struct CookieImage {
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// `width * height * 4` bytes, row 0 first (sampled at `t ∈ [0, 1/height]`).
    pub texels: Vec<u8>,
    /// Minification and magnification filter.
    pub filter: Filter,
    /// Wrap mode for S and T.
    pub wrap: Wrap,
}

impl CookieImage {
    /// A `size`×`size` checker of `cells`×`cells` squares, white at texel (0, 0) and black.
    pub fn checker(size: u32, cells: u32, filter: Filter, wrap: Wrap) -> CookieImage {
        let texels =
            essl_scene::checker_texels(size, cells, &[[255, 255, 255, 255], [0, 0, 0, 255]]);
        CookieImage {
            width: size,
            height: size,
            texels,
            filter,
            wrap,
        }
    }

    /// A 1×1 image of one colour.
    pub fn solid(rgba: [u8; 4]) -> CookieImage {
        CookieImage {
            width: 1,
            height: 1,
            texels: rgba.to_vec(),
            filter: Filter::Nearest,
            wrap: Wrap::Clamp,
        }
    }
}

/// A texture that filters a spot light.
#[derive(Clone, Debug, PartialEq)]
pub enum Cookie {
    /// Projected from the light along its cone (article 003): the image's `t` axis points along
    /// `up`, and the texture coordinates are the angles off the axis, scaled so the outer cone
    /// spans `[0, 1]`. `up` is orthonormalised against the direction on the CPU.
    Projected {
        /// The image's up direction (need not be perpendicular to the spot direction, must not
        /// be parallel to it).
        up: DVec3,
        /// The image.
        image: CookieImage,
    },
    /// Laid over the screen (article 004's flashlight): texture coordinates are the fragment's
    /// position in the viewport, `s` from left to right and `t` from top (0) to bottom (1).
    Screen {
        /// The image.
        image: CookieImage,
    },
}

impl Cookie {
    /// The image.
    pub fn image(&self) -> &CookieImage {
        match self {
            Cookie::Projected { image, .. } | Cookie::Screen { image } => image,
        }
    }

    /// The kind, without the image.
    pub fn kind(&self) -> CookieKind {
        match self {
            Cookie::Projected { .. } => CookieKind::Projected,
            Cookie::Screen { .. } => CookieKind::Screen,
        }
    }
}

/// Which kind of cookie, for the shader's shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CookieKind {
    /// [`Cookie::Projected`].
    Projected,
    /// [`Cookie::Screen`].
    Screen,
}

/// A light infinitely far away.
#[derive(Clone, Debug, PartialEq)]
pub struct DirectionalLight {
    /// The direction the light travels (any length but zero).
    pub direction: DVec3,
    /// Diffuse colour.
    pub color: DVec3,
    /// Specular colour (unused by [`Reflection::Lambert`]).
    pub specular: DVec3,
}

/// A light at a point, shining in every direction (no distance attenuation, as the articles).
#[derive(Clone, Debug, PartialEq)]
pub struct PointLight {
    /// Position.
    pub position: DVec3,
    /// Diffuse colour.
    pub color: DVec3,
    /// Specular colour.
    pub specular: DVec3,
}

/// A light at a point shining in a cone, optionally through a cookie.
#[derive(Clone, Debug, PartialEq)]
pub struct SpotLight {
    /// Position.
    pub position: DVec3,
    /// The direction of the cone's axis, the way the light travels (any length but zero).
    pub direction: DVec3,
    /// Inner half-angle, degrees: full intensity inside.
    pub inner_deg: f64,
    /// Outer half-angle, degrees: no light outside.
    pub outer_deg: f64,
    /// The fall-off between the cones.
    pub edge: EdgeProfile,
    /// A texture filtering the light, if any.
    pub cookie: Option<Cookie>,
    /// Diffuse colour.
    pub color: DVec3,
    /// Specular colour.
    pub specular: DVec3,
}

/// One light.
#[derive(Clone, Debug, PartialEq)]
pub enum Light {
    /// [`DirectionalLight`].
    Directional(DirectionalLight),
    /// [`PointLight`].
    Point(PointLight),
    /// [`SpotLight`].
    Spot(SpotLight),
}

/// The surface's colours.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Reflects the ambient light.
    pub ambient: DVec3,
    /// Reflects the lights' diffuse colour.
    pub diffuse: DVec3,
    /// Reflects the lights' specular colour.
    pub specular: DVec3,
    /// The specular exponent: 0 (a constant highlight), or 1..=[`MAX_SHININESS`].
    pub shininess: f64,
}

impl Default for Material {
    fn default() -> Self {
        Material {
            ambient: DVec3::splat(1.0),
            diffuse: DVec3::splat(0.8),
            specular: DVec3::splat(1.0),
            shininess: 32.0,
        }
    }
}

/// A lit scene: everything the shaders depend on except the geometry and the camera.
#[derive(Clone, Debug, PartialEq)]
pub struct LitScene {
    /// Where lighting is evaluated.
    pub shading: Shading,
    /// The reflection model.
    pub reflection: Reflection,
    /// The surface.
    pub material: Material,
    /// The ambient light's colour; `None` leaves the ambient term (and its uniforms) out.
    pub ambient_light: Option<DVec3>,
    /// The lights, in order (light `i`'s uniforms are `u_light{i}_…`).
    pub lights: Vec<Light>,
}

/// What kind of code a light needs: its kind, edge profile and cookie kind, without values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LightShape {
    /// A directional light.
    Directional,
    /// A point light.
    Point,
    /// A spot light with this edge and cookie.
    Spot {
        /// The edge profile.
        edge: EdgeProfile,
        /// The cookie kind, if any.
        cookie: Option<CookieKind>,
    },
}

impl LightShape {
    /// Whether the light has a position (point and spot lights).
    pub fn positional(self) -> bool {
        !matches!(self, LightShape::Directional)
    }
}

/// What code a scene needs: the part of a [`LitScene`] that the shader text depends on. Two
/// scenes with the same shape share a program and differ only in uniform values.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Shape {
    /// Where lighting is evaluated.
    pub shading: Shading,
    /// The reflection model.
    pub reflection: Reflection,
    /// Whether there is an ambient term.
    pub ambient: bool,
    /// The lights, in order.
    pub lights: Vec<LightShape>,
}

impl Shape {
    /// Whether any light has a position (so the surface position is needed).
    pub fn needs_position(&self) -> bool {
        self.lights.iter().any(|l| l.positional())
    }

    /// Whether the view vector is needed (a specular term with at least one light).
    pub fn needs_view(&self) -> bool {
        self.reflection.has_specular() && !self.lights.is_empty()
    }

    /// Whether any light has a screen-space cookie.
    pub fn has_screen_cookie(&self) -> bool {
        self.lights.iter().any(|l| {
            matches!(
                l,
                LightShape::Spot {
                    cookie: Some(CookieKind::Screen),
                    ..
                }
            )
        })
    }
}

impl Light {
    /// The light's shape.
    pub fn shape(&self) -> LightShape {
        match self {
            Light::Directional(_) => LightShape::Directional,
            Light::Point(_) => LightShape::Point,
            Light::Spot(s) => LightShape::Spot {
                edge: s.edge,
                cookie: s.cookie.as_ref().map(Cookie::kind),
            },
        }
    }

    /// Diffuse colour.
    pub fn color(&self) -> DVec3 {
        match self {
            Light::Directional(l) => l.color,
            Light::Point(l) => l.color,
            Light::Spot(l) => l.color,
        }
    }

    /// Specular colour.
    pub fn specular(&self) -> DVec3 {
        match self {
            Light::Directional(l) => l.specular,
            Light::Point(l) => l.specular,
            Light::Spot(l) => l.specular,
        }
    }
}

/// A light's values as the shaders receive them, in float64 (before rounding to float32).
#[derive(Clone, Debug, PartialEq)]
pub struct PreparedLight {
    /// The light's shape.
    pub shape: LightShape,
    /// Diffuse colour.
    pub color: DVec3,
    /// Specular colour.
    pub specular: DVec3,
    /// Position (point and spot lights; zero otherwise).
    pub position: DVec3,
    /// Unit direction the light travels (directional and spot lights; zero otherwise).
    pub direction: DVec3,
    /// `cos(outer)` (spot lights).
    pub cos_outer: f64,
    /// `cos(inner)` (spot lights).
    pub cos_inner: f64,
    /// `1 / (cos(inner) − cos(outer))`, at most [`MAX_EDGE_SLOPE`] (linear and smooth edges).
    pub inv_range: f64,
    /// The projector's basis, columns `left = normalize(cross(forward, up))`, `up` (made
    /// perpendicular to `forward`), `forward` (= `direction`) (projected cookies).
    pub basis: [DVec3; 3],
    /// `1 / (2 · outer in radians)`: texture units per radian off the axis (projected cookies).
    pub cookie_scale: f64,
}

/// A validated scene's values in float64.
#[derive(Clone, Debug, PartialEq)]
pub struct PreparedScene {
    /// The scene's shape.
    pub shape: Shape,
    /// The lights' values, in order.
    pub lights: Vec<PreparedLight>,
}

fn finite(what: impl FnOnce() -> String, value: f64) -> Result<(), LightsError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(LightsError::NonFinite {
            what: what(),
            value,
        })
    }
}

fn finite3(what: &str, v: DVec3) -> Result<(), LightsError> {
    for (c, x) in ["x", "y", "z"].iter().zip(v.to_array()) {
        finite(|| format!("{what}.{c}"), x)?;
    }
    Ok(())
}

fn color3(what: &str, v: DVec3) -> Result<(), LightsError> {
    for (c, x) in ["r", "g", "b"].iter().zip(v.to_array()) {
        finite(|| format!("{what}.{c}"), x)?;
        if x < 0.0 {
            return Err(LightsError::NegativeColor {
                what: format!("{what}.{c}"),
                value: x,
            });
        }
    }
    Ok(())
}

/// The unit vector of `v`, computed without overflow or underflow for any finite `v`; an error
/// when `v` is zero.
pub fn unit(what: &str, v: DVec3) -> Result<DVec3, LightsError> {
    finite3(what, v)?;
    let m = v.abs().max_element();
    if m == 0.0 {
        return Err(LightsError::ZeroVector {
            what: what.to_string(),
        });
    }
    let s = v / m;
    Ok(s / s.length())
}

fn cone_angle(what: String, deg: f64) -> Result<(), LightsError> {
    finite(|| what.clone(), deg)?;
    if !(0.0..=180.0).contains(&deg) {
        return Err(LightsError::ConeOutOfRange { what, deg });
    }
    Ok(())
}

/// `1 / (cos_inner − cos_outer)`, capped at [`MAX_EDGE_SLOPE`] (also when they are equal).
pub fn edge_slope(cos_inner: f64, cos_outer: f64) -> f64 {
    let range = cos_inner - cos_outer;
    if range * MAX_EDGE_SLOPE > 1.0 {
        1.0 / range
    } else {
        MAX_EDGE_SLOPE
    }
}

/// The projector basis of a spot light: `[left, up, forward]`, orthonormal, with `forward` the
/// unit direction and `up` the given up vector made perpendicular to it (Gram–Schmidt in
/// float64). Refuses an up vector within [`MIN_UP_SINE`] of the direction.
pub fn projector_basis(what: &str, direction: DVec3, up: DVec3) -> Result<[DVec3; 3], LightsError> {
    let forward = unit(&format!("{what}.direction"), direction)?;
    let up_unit = unit(&format!("{what}.cookie.up"), up)?;
    let perp = up_unit - forward * up_unit.dot(forward);
    // |perp| is the sine of the angle between up and the axis (to rounding).
    let sine = perp.length();
    if sine < MIN_UP_SINE {
        return Err(LightsError::UpParallelToDirection {
            what: what.to_string(),
            angle_deg: sine.asin().to_degrees(),
            min_deg: MIN_UP_SINE.asin().to_degrees(),
        });
    }
    // A second Gram–Schmidt pass makes `up` perpendicular to rounding.
    let mut up_o = perp / sine;
    up_o = (up_o - forward * up_o.dot(forward)).normalize();
    let left = forward.cross(up_o).normalize();
    Ok([left, up_o, forward])
}

impl LitScene {
    /// A scene with no lights and no ambient light.
    pub fn new(shading: Shading, reflection: Reflection, material: Material) -> LitScene {
        LitScene {
            shading,
            reflection,
            material,
            ambient_light: None,
            lights: Vec::new(),
        }
    }

    /// Adds a light.
    pub fn with_light(mut self, light: Light) -> LitScene {
        self.lights.push(light);
        self
    }

    /// Sets the ambient light.
    pub fn with_ambient(mut self, color: DVec3) -> LitScene {
        self.ambient_light = Some(color);
        self
    }

    /// The scene's shape (what the shader text depends on).
    pub fn shape(&self) -> Shape {
        Shape {
            shading: self.shading,
            reflection: self.reflection,
            ambient: self.ambient_light.is_some(),
            lights: self.lights.iter().map(Light::shape).collect(),
        }
    }

    /// Checks every parameter (see the module docs); the first problem is returned.
    pub fn validate(&self) -> Result<(), LightsError> {
        self.prepare().map(|_| ())
    }

    /// Validates and computes the values the shaders receive, in float64.
    pub fn prepare(&self) -> Result<PreparedScene, LightsError> {
        let m = &self.material;
        color3("material.ambient", m.ambient)?;
        color3("material.diffuse", m.diffuse)?;
        color3("material.specular", m.specular)?;
        finite(|| "material.shininess".into(), m.shininess)?;
        if m.shininess < 0.0 {
            return Err(LightsError::Shininess {
                value: m.shininess,
                reason: "must not be negative",
            });
        }
        if m.shininess > 0.0 && m.shininess < 1.0 {
            return Err(LightsError::Shininess {
                value: m.shininess,
                reason: "must be 0 or at least 1: below 1 the highlight max(x, 0)^n jumps from 0 \
                         to about 1 within the float rounding of x near 0",
            });
        }
        if m.shininess > MAX_SHININESS {
            return Err(LightsError::Shininess {
                value: m.shininess,
                reason: "must be at most 1e4: above, float32 rounding of the cosine times the \
                         exponent exceeds 1/255 in the highlight",
            });
        }
        if let Some(a) = self.ambient_light {
            color3("ambient_light", a)?;
        }
        if self.lights.len() > MAX_LIGHTS {
            return Err(LightsError::TooManyLights {
                count: self.lights.len(),
                max: MAX_LIGHTS,
            });
        }
        let lights = self
            .lights
            .iter()
            .enumerate()
            .map(|(i, l)| prepare_light(&format!("lights[{i}]"), l))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(PreparedScene {
            shape: self.shape(),
            lights,
        })
    }
}

fn prepare_light(what: &str, light: &Light) -> Result<PreparedLight, LightsError> {
    color3(&format!("{what}.color"), light.color())?;
    color3(&format!("{what}.specular"), light.specular())?;
    let mut p = PreparedLight {
        shape: light.shape(),
        color: light.color(),
        specular: light.specular(),
        position: DVec3::ZERO,
        direction: DVec3::ZERO,
        cos_outer: 0.0,
        cos_inner: 0.0,
        inv_range: 0.0,
        basis: [DVec3::ZERO; 3],
        cookie_scale: 0.0,
    };
    match light {
        Light::Directional(d) => {
            p.direction = unit(&format!("{what}.direction"), d.direction)?;
        }
        Light::Point(pt) => {
            finite3(&format!("{what}.position"), pt.position)?;
            p.position = pt.position;
        }
        Light::Spot(s) => {
            finite3(&format!("{what}.position"), s.position)?;
            p.position = s.position;
            p.direction = unit(&format!("{what}.direction"), s.direction)?;
            cone_angle(format!("{what}.outer_deg"), s.outer_deg)?;
            cone_angle(format!("{what}.inner_deg"), s.inner_deg)?;
            if s.inner_deg > s.outer_deg {
                return Err(LightsError::InnerWiderThanOuter {
                    what: what.to_string(),
                    inner_deg: s.inner_deg,
                    outer_deg: s.outer_deg,
                });
            }
            p.cos_outer = s.outer_deg.to_radians().cos();
            p.cos_inner = s.inner_deg.to_radians().cos();
            p.inv_range = edge_slope(p.cos_inner, p.cos_outer);
            if let Some(cookie) = &s.cookie {
                let img = cookie.image();
                let expected = img.width as usize * img.height as usize * 4;
                if img.width == 0 || img.height == 0 || img.texels.len() != expected {
                    return Err(LightsError::CookieSize {
                        what: what.to_string(),
                        width: img.width,
                        height: img.height,
                        expected,
                        got: img.texels.len(),
                    });
                }
                if let Cookie::Projected { up, .. } = cookie {
                    if s.outer_deg == 0.0 {
                        return Err(LightsError::CookieConeZero {
                            what: what.to_string(),
                        });
                    }
                    p.basis = projector_basis(what, s.direction, *up)?;
                    p.cookie_scale = 1.0 / (2.0 * s.outer_deg.to_radians());
                }
            }
        }
    }
    Ok(p)
}
