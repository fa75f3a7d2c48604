//! The one error type of the crate: parameters the library refuses to turn into a shader (they
//! would render NaN, infinities, or an undefined picture) and failures of the reference tools.

use thiserror::Error;

/// Why a lit scene, a view or a comparison was refused.
#[derive(Clone, Debug, Error)]
#[non_exhaustive]
pub enum LightsError {
    /// A number that must be finite is NaN or infinite.
    #[error("{what} must be finite, got {value}")]
    NonFinite {
        /// Which parameter (`lights[0].position.x`).
        what: String,
        /// The value given.
        value: f64,
    },
    /// A colour component is negative (colours are linear RGB, 0 and above; above 1 is allowed
    /// as intensity).
    #[error("{what} must not be negative, got {value}")]
    NegativeColor {
        /// Which colour component.
        what: String,
        /// The value given.
        value: f64,
    },
    /// A direction or up vector has zero length, so it names no direction.
    #[error("{what} has zero length: it names no direction")]
    ZeroVector {
        /// Which vector.
        what: String,
    },
    /// A spot light's inner cone is wider than its outer cone.
    #[error(
        "{what}: the inner cone ({inner_deg}°) is wider than the outer cone ({outer_deg}°); \
         give half-angles in degrees with inner ≤ outer (passing cosines instead of angles \
         reverses the order)"
    )]
    InnerWiderThanOuter {
        /// Which light.
        what: String,
        /// The inner half-angle given, degrees.
        inner_deg: f64,
        /// The outer half-angle given, degrees.
        outer_deg: f64,
    },
    /// A cone half-angle outside 0°..=180°.
    #[error("{what}: a cone half-angle must be in 0°..=180°, got {deg}°")]
    ConeOutOfRange {
        /// Which angle.
        what: String,
        /// The value given, degrees.
        deg: f64,
    },
    /// A projected-texture spot light with an outer cone of 0°: the image would be scaled by
    /// 1/0.
    #[error("{what}: a projected cookie needs an outer cone wider than 0°")]
    CookieConeZero {
        /// Which light.
        what: String,
    },
    /// The up vector of a projected-texture spot light is (nearly) parallel to its direction,
    /// so the image's orientation is undefined (`cross(up, direction)` is zero).
    #[error(
        "{what}: the up vector is {angle_deg:e}° from the spot direction; it must be at least \
         {min_deg:e}° away, or the projected image has no orientation"
    )]
    UpParallelToDirection {
        /// Which light.
        what: String,
        /// The angle between up and the direction (or its opposite), degrees.
        angle_deg: f64,
        /// The smallest angle accepted, degrees.
        min_deg: f64,
    },
    /// Shininess outside the range the library evaluates stably.
    #[error("material shininess {value}: {reason}")]
    Shininess {
        /// The value given.
        value: f64,
        /// Why it is refused.
        reason: &'static str,
    },
    /// More lights than a specialised shader takes.
    #[error("{count} lights: a shader takes at most {max}")]
    TooManyLights {
        /// Lights given.
        count: usize,
        /// The limit.
        max: usize,
    },
    /// A cookie image whose texel buffer does not match its size.
    #[error("{what}: a {width}x{height} cookie needs {expected} bytes of RGBA8, got {got}")]
    CookieSize {
        /// Which light.
        what: String,
        /// Width in texels.
        width: u32,
        /// Height in texels.
        height: u32,
        /// `width * height * 4`.
        expected: usize,
        /// Bytes given.
        got: usize,
    },
    /// A view the uniforms cannot be computed for (a singular model matrix, an empty viewport).
    #[error("view: {0}")]
    View(String),
    /// The reference renderer cannot do what was asked (no analytic surface for this mesh, …).
    #[error("reference: {0}")]
    Reference(String),
    /// Two images of different sizes.
    #[error("image sizes differ: {a_width}x{a_height} vs {b_width}x{b_height}")]
    SizeMismatch {
        /// First image's width.
        a_width: u32,
        /// First image's height.
        a_height: u32,
        /// Second image's width.
        b_width: u32,
        /// Second image's height.
        b_height: u32,
    },
    /// essl-gl could not render (no Vulkan adapter, a shader that does not compile, a GL
    /// error); the message is essl-gl's.
    #[error("gpu: {0}")]
    Gpu(String),
    /// Writing a report file failed.
    #[error("{path}: {message}")]
    Io {
        /// The file.
        path: String,
        /// What went wrong.
        message: String,
    },
    /// An error of the scene format crate.
    #[error(transparent)]
    Scene(#[from] std::sync::Arc<essl_scene::SceneError>),
}

impl From<essl_scene::SceneError> for LightsError {
    fn from(e: essl_scene::SceneError) -> Self {
        LightsError::Scene(std::sync::Arc::new(e))
    }
}
