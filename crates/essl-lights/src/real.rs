//! Arithmetic in a GPU's precisions on the CPU, so a shader formula written once (generic over
//! [`Real`]) can be evaluated in float64, in float32 (`highp`) and in a `mediump` emulation.
//!
//! - [`f64`]: the formula in double precision.
//! - [`F32`]: IEEE binary32, each operation rounded to nearest (what `highp` is on every GPU
//!   WebGL2 runs on). Transcendentals use the platform's `f32` functions (about 1 ulp), which is
//!   kinder than GPUs are allowed to be (Vulkan allows 3 ulp for `exp2`/`log2`, 4096 for `atan`).
//! - [`F16`]: `mediump` as mobile GPUs implement it, IEEE binary16: every value and every
//!   operation's result rounded to 11 significant bits (ties to even), magnitudes above 65504
//!   overflow to infinity, below `2^-24` flush to zero.
//!
//! GLSL semantics where they matter: `pow(x, y)` is `exp2(y · log2(x))` (NaN for `x < 0`,
//! NaN for `0^0`), `normalize(v)` is `v · inversesqrt(dot(v, v))` (NaN for a zero vector),
//! `max`/`min`/`clamp` propagate NaN (GLSL leaves them undefined), `step(e, x)` is
//! `x < e ? 0 : 1`, `smoothstep` is the spec's `t = clamp((x − e0) / (e1 − e0), 0, 1)`,
//! `t²(3 − 2t)`.

use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A floating-point format a shader can run in.
pub trait Real:
    Copy
    + Debug
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// A short name (`f64`, `highp`, `mediump`).
    const NAME: &'static str;
    /// `x` rounded to this format (a uniform or varying upload).
    fn of(x: f64) -> Self;
    /// The value as float64 (exact).
    fn to_f64(self) -> f64;
    /// `sqrt`.
    fn sqrt(self) -> Self;
    /// `exp2`.
    fn exp2(self) -> Self;
    /// `log2`.
    fn log2(self) -> Self;
    /// `atan(y, x)` with `self` as `y`.
    fn atan2(self, x: Self) -> Self;
    /// `acos` (NaN outside [−1, 1]).
    fn acos(self) -> Self;

    /// `inversesqrt`: `1 / sqrt(x)`, two roundings.
    fn inversesqrt(self) -> Self {
        Self::of(1.0) / self.sqrt()
    }
    /// `abs`.
    fn abs(self) -> Self {
        if self < Self::of(0.0) {
            -self
        } else {
            self
        }
    }
    /// Whether the value is NaN.
    fn is_nan(self) -> bool {
        self.to_f64().is_nan()
    }
    /// `max`, NaN-propagating.
    fn max(self, o: Self) -> Self {
        if self.is_nan() || o.is_nan() {
            Self::of(f64::NAN)
        } else if self < o {
            o
        } else {
            self
        }
    }
    /// `min`, NaN-propagating.
    fn min(self, o: Self) -> Self {
        if self.is_nan() || o.is_nan() {
            Self::of(f64::NAN)
        } else if o < self {
            o
        } else {
            self
        }
    }
    /// `clamp(x, lo, hi) = min(max(x, lo), hi)`.
    fn clamp(self, lo: Self, hi: Self) -> Self {
        self.max(lo).min(hi)
    }
    /// GLSL `pow` as GPUs compute it: `exp2(y · log2(x))`.
    fn pow(self, y: Self) -> Self {
        (y * self.log2()).exp2()
    }
    /// GLSL `step(edge, x)` with `self` as `x`.
    fn step_from(self, edge: Self) -> Self {
        if self < edge {
            Self::of(0.0)
        } else {
            Self::of(1.0)
        }
    }
    /// GLSL `smoothstep(e0, e1, x)` with `self` as `x`, by the spec's formula.
    fn smoothstep(self, e0: Self, e1: Self) -> Self {
        let t = ((self - e0) / (e1 - e0)).clamp(Self::of(0.0), Self::of(1.0));
        t * t * (Self::of(3.0) - Self::of(2.0) * t)
    }
}

impl Real for f64 {
    const NAME: &'static str = "f64";
    fn of(x: f64) -> Self {
        x
    }
    fn to_f64(self) -> f64 {
        self
    }
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
    fn exp2(self) -> Self {
        f64::exp2(self)
    }
    fn log2(self) -> Self {
        f64::log2(self)
    }
    fn atan2(self, x: Self) -> Self {
        f64::atan2(self, x)
    }
    fn acos(self) -> Self {
        f64::acos(self)
    }
}

/// IEEE binary32 arithmetic (`highp`).
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct F32(pub f32);

macro_rules! ops {
    ($t:ident, $wrap:expr, $get:expr) => {
        impl Add for $t {
            type Output = $t;
            fn add(self, o: $t) -> $t {
                $wrap($get(self) + $get(o))
            }
        }
        impl Sub for $t {
            type Output = $t;
            fn sub(self, o: $t) -> $t {
                $wrap($get(self) - $get(o))
            }
        }
        impl Mul for $t {
            type Output = $t;
            fn mul(self, o: $t) -> $t {
                $wrap($get(self) * $get(o))
            }
        }
        impl Div for $t {
            type Output = $t;
            fn div(self, o: $t) -> $t {
                $wrap($get(self) / $get(o))
            }
        }
        impl Neg for $t {
            type Output = $t;
            fn neg(self) -> $t {
                $wrap(-$get(self))
            }
        }
    };
}

ops!(F32, F32, |x: F32| x.0);

impl Real for F32 {
    const NAME: &'static str = "highp";
    fn of(x: f64) -> Self {
        F32(x as f32)
    }
    fn to_f64(self) -> f64 {
        f64::from(self.0)
    }
    fn sqrt(self) -> Self {
        F32(self.0.sqrt())
    }
    fn exp2(self) -> Self {
        F32(self.0.exp2())
    }
    fn log2(self) -> Self {
        F32(self.0.log2())
    }
    fn atan2(self, x: Self) -> Self {
        F32(self.0.atan2(x.0))
    }
    fn acos(self) -> Self {
        F32(self.0.acos())
    }
}

/// Rounds a float64 to the nearest IEEE binary16 value (ties to even), as float64: infinity
/// beyond 65504 (after rounding), subnormals down to `2^-24`.
pub fn round_f16(x: f64) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x;
    }
    let bits = x.abs().to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32 - 1023;
    let e = exp.max(-14);
    let quantum = 2f64.powi(e - 10);
    let r = (x / quantum).round_ties_even() * quantum;
    if r.abs() > 65504.0 {
        f64::INFINITY.copysign(x)
    } else {
        r
    }
}

/// IEEE binary16 arithmetic (`mediump` on mobile GPUs): the value is kept as a float64 that is
/// always a binary16 value; each operation is exact in float64 and then rounded.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct F16(f64);

impl F16 {
    /// The value.
    pub fn value(self) -> f64 {
        self.0
    }
}

fn f16(x: f64) -> F16 {
    F16(round_f16(x))
}

ops!(F16, f16, |x: F16| x.0);

impl Real for F16 {
    const NAME: &'static str = "mediump";
    fn of(x: f64) -> Self {
        f16(x)
    }
    fn to_f64(self) -> f64 {
        self.0
    }
    fn sqrt(self) -> Self {
        f16(self.0.sqrt())
    }
    fn exp2(self) -> Self {
        f16(self.0.exp2())
    }
    fn log2(self) -> Self {
        f16(self.0.log2())
    }
    fn atan2(self, x: Self) -> Self {
        f16(self.0.atan2(x.0))
    }
    fn acos(self) -> Self {
        f16(self.0.acos())
    }
}

/// A 3-vector of [`Real`]s with GLSL's operations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct V3<R> {
    /// x
    pub x: R,
    /// y
    pub y: R,
    /// z
    pub z: R,
}

impl<R: Real> V3<R> {
    /// A vector from components.
    pub fn new(x: R, y: R, z: R) -> Self {
        V3 { x, y, z }
    }
    /// A float64 vector rounded to `R` (an upload).
    pub fn of(v: glam::DVec3) -> Self {
        V3::new(R::of(v.x), R::of(v.y), R::of(v.z))
    }
    /// All components `s`.
    pub fn splat(s: R) -> Self {
        V3::new(s, s, s)
    }
    /// The zero vector.
    pub fn zero() -> Self {
        V3::splat(R::of(0.0))
    }
    /// As float64.
    pub fn to_f64(self) -> glam::DVec3 {
        glam::DVec3::new(self.x.to_f64(), self.y.to_f64(), self.z.to_f64())
    }
    /// `dot` (summed left to right).
    pub fn dot(self, o: Self) -> R {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    /// `cross`.
    pub fn cross(self, o: Self) -> Self {
        V3::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }
    /// `length`: `sqrt(dot(v, v))`.
    pub fn length(self) -> R {
        self.dot(self).sqrt()
    }
    /// GLSL `normalize`: `v · inversesqrt(dot(v, v))`.
    pub fn normalize(self) -> Self {
        self.scale(self.dot(self).inversesqrt())
    }
    /// `v · s`.
    pub fn scale(self, s: R) -> Self {
        V3::new(self.x * s, self.y * s, self.z * s)
    }
    /// Component-wise product.
    pub fn mul_elem(self, o: Self) -> Self {
        V3::new(self.x * o.x, self.y * o.y, self.z * o.z)
    }
    /// `v / s`.
    pub fn div_scalar(self, s: R) -> Self {
        V3::new(self.x / s, self.y / s, self.z / s)
    }
    /// GLSL `reflect(i, n) = i − 2 · dot(n, i) · n`.
    pub fn reflect(self, n: Self) -> Self {
        self - n.scale(R::of(2.0) * n.dot(self))
    }
    /// Whether every component is finite.
    pub fn is_finite(self) -> bool {
        self.to_f64().is_finite()
    }
}

impl<R: Real> Add for V3<R> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        V3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<R: Real> Sub for V3<R> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        V3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<R: Real> Neg for V3<R> {
    type Output = Self;
    fn neg(self) -> Self {
        V3::new(-self.x, -self.y, -self.z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f16_rounding() {
        assert_eq!(round_f16(1.0), 1.0);
        assert_eq!(round_f16(1.0 + 1.0 / 2048.0), 1.0); // tie to even
        assert_eq!(round_f16(1.0 + 3.0 / 2048.0), 1.0 + 2.0 / 1024.0);
        assert_eq!(round_f16(65504.0), 65504.0);
        assert_eq!(round_f16(65519.0), 65504.0);
        assert_eq!(round_f16(65520.0), f64::INFINITY);
        assert_eq!(round_f16(-1.0e6), f64::NEG_INFINITY);
        assert_eq!(round_f16(2f64.powi(-24)), 2f64.powi(-24));
        assert_eq!(round_f16(2f64.powi(-26)), 0.0);
        let x = F16::of(300.0);
        assert_eq!((x * x).value(), f64::INFINITY);
    }

    #[test]
    fn glsl_semantics() {
        assert!(F32(0.0).pow(F32(0.0)).is_nan());
        assert!(F32(-0.5).pow(F32(2.0)).is_nan());
        assert_eq!(F32(0.0).pow(F32(3.0)).0, 0.0);
        assert!(V3::<F32>::zero().normalize().x.is_nan());
        assert_eq!(F32(0.5).step_from(F32(0.5)).0, 1.0);
        assert!(F32(0.5).smoothstep(F32(0.5), F32(0.5)).is_nan());
        assert!(F32(f32::NAN).max(F32(0.0)).is_nan());
    }
}
