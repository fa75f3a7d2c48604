//! Uniform values as a renderer supplies them (scalars and vectors of up to 4 components),
//! and the precision a condition is evaluated in.

use std::fmt;

/// A scalar or vector value (1 to 4 components).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Value {
    /// The number of components.
    pub n: u8,
    /// The components (those past `n` are 0).
    pub c: [f64; 4],
}

impl Value {
    /// A scalar.
    pub fn scalar(x: f64) -> Value {
        Value {
            n: 1,
            c: [x, 0.0, 0.0, 0.0],
        }
    }

    /// A vector of the given components (1 to 4; more are dropped).
    pub fn new(c: &[f64]) -> Value {
        let mut v = Value {
            n: c.len().clamp(1, 4) as u8,
            c: [0.0; 4],
        };
        for (i, x) in c.iter().take(4).enumerate() {
            v.c[i] = *x;
        }
        v
    }

    /// The used components.
    pub fn comps(&self) -> &[f64] {
        &self.c[..self.n as usize]
    }

    pub(super) fn map(self, f: impl Fn(f64) -> f64) -> Value {
        let mut v = self;
        for x in &mut v.c[..self.n as usize] {
            *x = f(*x);
        }
        v
    }

    /// Component `i`, or the scalar itself for a scalar (GLSL's scalar-vector broadcast).
    pub(super) fn at(&self, i: usize) -> f64 {
        if self.n == 1 {
            self.c[0]
        } else {
            self.c[i]
        }
    }

    pub(super) fn dot(&self, o: &Value) -> f64 {
        (0..self.n.max(o.n) as usize)
            .map(|i| self.at(i) * o.at(i))
            .sum()
    }
}

/// Writes a number as the `f32` it came from (`0.9`, not `0.8999999761581421`).
pub(super) fn num(x: f64) -> String {
    if x.is_nan() {
        "NaN".into()
    } else if x.is_infinite() {
        if x > 0.0 { "+inf" } else { "-inf" }.into()
    } else {
        format!("{}", x as f32)
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.n == 1 {
            return f.write_str(&num(self.c[0]));
        }
        let parts: Vec<String> = self.comps().iter().map(|x| num(*x)).collect();
        write!(f, "({})", parts.join(", "))
    }
}

/// The precision a condition is evaluated in: each operation's result is rounded to it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Precision {
    /// `highp`: 32-bit floats.
    High,
    /// `mediump` or `lowp`: 16-bit floats, as phones compute them (desktop GPUs and lavapipe
    /// use 32 bits, so the hazard shows on some devices only).
    Low,
}

impl Precision {
    /// `x` rounded to this precision (to nearest, ties to even; 16-bit overflow is ±∞).
    pub fn round(self, x: f64) -> f64 {
        match self {
            Precision::High => x as f32 as f64,
            Precision::Low => round_f16(x),
        }
    }

    /// The smallest normal number: a squared length below it may flush to 0.
    pub fn min_normal(self) -> f64 {
        match self {
            Precision::High => f32::MIN_POSITIVE as f64,
            Precision::Low => 6.103515625e-5,
        }
    }

    /// The relative rounding error of one operation.
    pub fn epsilon(self) -> f64 {
        match self {
            Precision::High => f32::EPSILON as f64,
            Precision::Low => 1.0 / 1024.0,
        }
    }

    /// `"highp"` or `"mediump"`.
    pub fn name(self) -> &'static str {
        match self {
            Precision::High => "highp",
            Precision::Low => "mediump",
        }
    }
}

/// `x` rounded to the nearest IEEE binary16 value (subnormals kept, overflow to ±∞).
pub(super) fn round_f16(x: f64) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x;
    }
    let a = x.abs();
    if a >= 65520.0 {
        return f64::INFINITY.copysign(x);
    }
    let e = (((a.to_bits() >> 52) & 0x7ff) as i32 - 1023).max(-14);
    let q = 2f64.powi(e - 10);
    (x / q).round_ties_even() * q
}
