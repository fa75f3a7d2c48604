//! Intervals of reals with bounds a shader's `float` can hold, and GLSL's arithmetic on them.
//!
//! An [`Interval`] `[lo, hi]` says that a value lies between two bounds. Every operation returns
//! an interval that contains the operation applied to any points of its inputs: the exact result
//! rounded outward to the nearest `f32` bounds, so that a correctly rounded `f32` operation (or
//! one that is monotone, as GPUs' are) cannot leave it. Transcendental functions, which GPUs
//! only approximate, get a relative slack on top ([`Interval::slack`]).
//!
//! The empty interval stands for "no value" (unreachable code, a variable never stored), the
//! full one for "anything". NaN is not a value of the domain: an operation that is undefined on
//! part of its input (GLSL's `sqrt` of a negative, `pow` of a negative base) returns the image of
//! the part where it is defined, and the rules report the undefined part.

use std::f64::consts::{FRAC_PI_2, PI};

/// A closed interval of the extended reals, with `f32`-representable bounds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The lower bound (may be −∞).
    pub lo: f64,
    /// The upper bound (may be +∞).
    pub hi: f64,
}

/// The largest `f32` value not above `x`, as `f64`.
fn down(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NEG_INFINITY;
    }
    let f = x as f32;
    if (f as f64) > x {
        next_down32(f) as f64
    } else {
        f as f64
    }
}

/// The smallest `f32` value not below `x`, as `f64`.
fn up(x: f64) -> f64 {
    if x.is_nan() {
        return f64::INFINITY;
    }
    let f = x as f32;
    if (f as f64) < x {
        next_up32(f) as f64
    } else {
        f as f64
    }
}

fn next_up32(f: f32) -> f32 {
    if f.is_nan() || f == f32::INFINITY {
        return f;
    }
    if f == 0.0 {
        return f32::from_bits(1);
    }
    let b = f.to_bits();
    f32::from_bits(if f > 0.0 { b + 1 } else { b - 1 })
}

fn next_down32(f: f32) -> f32 {
    -next_up32(-f)
}

/// `x * y` with `0 * ∞ = 0`, the convention of interval arithmetic on the extended reals.
fn mul0(x: f64, y: f64) -> f64 {
    if x == 0.0 || y == 0.0 {
        0.0
    } else {
        x * y
    }
}

// The arithmetic is spelled as methods (`a.add(b)`) rather than operators: each call rounds
// its bounds outward, which `+` would hide.
#[allow(clippy::should_implement_trait)]
impl Interval {
    /// No value at all.
    pub const EMPTY: Interval = Interval {
        lo: f64::INFINITY,
        hi: f64::NEG_INFINITY,
    };
    /// Any value.
    pub const FULL: Interval = Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };
    /// `[0, 1]`.
    pub const UNIT: Interval = Interval { lo: 0.0, hi: 1.0 };
    /// `[-1, 1]`.
    pub const SIGNED_UNIT: Interval = Interval { lo: -1.0, hi: 1.0 };
    /// `[0, +∞]`.
    pub const NON_NEGATIVE: Interval = Interval {
        lo: 0.0,
        hi: f64::INFINITY,
    };

    /// `[lo, hi]` rounded outward to `f32` bounds (empty when `lo > hi`).
    pub fn new(lo: f64, hi: f64) -> Interval {
        if lo.is_nan() || hi.is_nan() {
            return Interval::FULL;
        }
        if lo > hi {
            return Interval::EMPTY;
        }
        Interval {
            lo: down(lo),
            hi: up(hi),
        }
    }

    /// The values of an `f32` strictly above `x` (for `x` an `f32`).
    pub fn above(x: f64) -> Interval {
        Interval {
            lo: if x.is_finite() {
                next_up32(x as f32) as f64
            } else {
                x
            },
            hi: f64::INFINITY,
        }
    }

    /// The values of an `f32` strictly below `x` (for `x` an `f32`).
    pub fn below(x: f64) -> Interval {
        Interval {
            lo: f64::NEG_INFINITY,
            hi: if x.is_finite() {
                next_down32(x as f32) as f64
            } else {
                x
            },
        }
    }

    /// The single value `x` (rounded outward when `x` is not an `f32`).
    pub fn point(x: f64) -> Interval {
        Interval::new(x, x)
    }

    /// Whether there is no value.
    pub fn is_empty(self) -> bool {
        self.lo > self.hi
    }

    /// Whether both bounds are finite.
    pub fn is_bounded(self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    /// Whether `x` is in the interval.
    pub fn contains(self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }

    /// Whether every value of `self` is in `other`.
    pub fn within(self, other: Interval) -> bool {
        self.is_empty() || (other.lo <= self.lo && self.hi <= other.hi)
    }

    /// The value, when the interval holds exactly one.
    pub fn as_point(self) -> Option<f64> {
        (self.lo == self.hi).then_some(self.lo)
    }

    /// The largest magnitude of a value in the interval.
    pub fn mag(self) -> f64 {
        if self.is_empty() {
            0.0
        } else {
            self.lo.abs().max(self.hi.abs())
        }
    }

    /// The smallest magnitude of a value in the interval.
    pub fn mig(self) -> f64 {
        if self.is_empty() {
            0.0
        } else if self.lo > 0.0 {
            self.lo
        } else if self.hi < 0.0 {
            -self.hi
        } else {
            0.0
        }
    }

    /// The smallest interval containing both.
    pub fn hull(self, o: Interval) -> Interval {
        if self.is_empty() {
            return o;
        }
        if o.is_empty() {
            return self;
        }
        Interval {
            lo: self.lo.min(o.lo),
            hi: self.hi.max(o.hi),
        }
    }

    /// The values in both.
    pub fn meet(self, o: Interval) -> Interval {
        let r = Interval {
            lo: self.lo.max(o.lo),
            hi: self.hi.min(o.hi),
        };
        if r.is_empty() {
            Interval::EMPTY
        } else {
            r
        }
    }

    /// Widening for fixpoints: a bound that moved since `self` jumps to infinity.
    pub fn widen(self, newer: Interval) -> Interval {
        if self.is_empty() {
            return newer;
        }
        if newer.is_empty() {
            return self;
        }
        Interval {
            lo: if newer.lo < self.lo {
                f64::NEG_INFINITY
            } else {
                self.lo
            },
            hi: if newer.hi > self.hi {
                f64::INFINITY
            } else {
                self.hi
            },
        }
    }

    /// Widens both bounds by `eps` of their magnitude: room for an approximate GPU function.
    pub fn slack(self, eps: f64) -> Interval {
        if self.is_empty() {
            return self;
        }
        Interval::new(self.lo - self.lo.abs() * eps, self.hi + self.hi.abs() * eps)
    }

    /// Applies a non-decreasing function to both bounds.
    fn increasing(self, f: impl Fn(f64) -> f64) -> Interval {
        if self.is_empty() {
            return self;
        }
        Interval::new(f(self.lo), f(self.hi))
    }

    /// Applies a non-increasing function to both bounds.
    fn decreasing(self, f: impl Fn(f64) -> f64) -> Interval {
        if self.is_empty() {
            return self;
        }
        Interval::new(f(self.hi), f(self.lo))
    }

    /// `-x`
    pub fn neg(self) -> Interval {
        if self.is_empty() {
            return self;
        }
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }

    /// `x + y`
    pub fn add(self, o: Interval) -> Interval {
        if self.is_empty() || o.is_empty() {
            return Interval::EMPTY;
        }
        let lo = self.lo + o.lo;
        let hi = self.hi + o.hi;
        Interval::new(
            if lo.is_nan() { f64::NEG_INFINITY } else { lo },
            if hi.is_nan() { f64::INFINITY } else { hi },
        )
    }

    /// `x - y`
    pub fn sub(self, o: Interval) -> Interval {
        self.add(o.neg())
    }

    /// `x * y`
    pub fn mul(self, o: Interval) -> Interval {
        if self.is_empty() || o.is_empty() {
            return Interval::EMPTY;
        }
        let c = [
            mul0(self.lo, o.lo),
            mul0(self.lo, o.hi),
            mul0(self.hi, o.lo),
            mul0(self.hi, o.hi),
        ];
        let lo = c.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = c.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Interval::new(lo, hi)
    }

    /// `x * x`: unlike `x.mul(x)`, knows that both factors are the same value.
    pub fn sqr(self) -> Interval {
        if self.is_empty() {
            return self;
        }
        let (a, b) = (mul0(self.lo, self.lo), mul0(self.hi, self.hi));
        if self.contains(0.0) {
            Interval::new(0.0, a.max(b))
        } else {
            Interval::new(a.min(b), a.max(b))
        }
    }

    /// `1 / x` (a divisor that may be zero gives an unbounded side, or anything).
    pub fn recip(self) -> Interval {
        if self.is_empty() {
            return self;
        }
        if self.lo > 0.0 || self.hi < 0.0 {
            return Interval::new(1.0 / self.hi, 1.0 / self.lo);
        }
        if self.lo == 0.0 && self.hi > 0.0 {
            return Interval::new(1.0 / self.hi, f64::INFINITY);
        }
        if self.hi == 0.0 && self.lo < 0.0 {
            return Interval::new(f64::NEG_INFINITY, 1.0 / self.lo);
        }
        Interval::FULL
    }

    /// `x / y`
    pub fn div(self, o: Interval) -> Interval {
        if self.is_empty() || o.is_empty() {
            return Interval::EMPTY;
        }
        if o.lo > 0.0 || o.hi < 0.0 {
            // Divide directly: one rounding, tighter than `x * (1 / y)`.
            let c = [
                self.lo / o.lo,
                self.lo / o.hi,
                self.hi / o.lo,
                self.hi / o.hi,
            ];
            if c.iter().all(|v| !v.is_nan()) {
                let lo = c.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = c.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                return Interval::new(lo, hi);
            }
        }
        self.mul(o.recip())
    }

    /// `abs(x)`
    pub fn abs(self) -> Interval {
        if self.is_empty() {
            return self;
        }
        Interval {
            lo: self.mig(),
            hi: self.mag(),
        }
    }

    /// `min(x, y)`
    pub fn min(self, o: Interval) -> Interval {
        if self.is_empty() || o.is_empty() {
            return Interval::EMPTY;
        }
        Interval {
            lo: self.lo.min(o.lo),
            hi: self.hi.min(o.hi),
        }
    }

    /// `max(x, y)`
    pub fn max(self, o: Interval) -> Interval {
        if self.is_empty() || o.is_empty() {
            return Interval::EMPTY;
        }
        Interval {
            lo: self.lo.max(o.lo),
            hi: self.hi.max(o.hi),
        }
    }

    /// GLSL's `clamp(x, lo, hi)`, which is undefined when `lo > hi`: the values it has for the
    /// bounds that are in order (`clamp(x, 0, size - 1)` is not negative even if `size - 1`
    /// could be, since then the call means nothing).
    pub fn clamp_ordered(self, lo: Interval, hi: Interval) -> Interval {
        if self.is_empty() || lo.is_empty() || hi.is_empty() {
            return Interval::EMPTY;
        }
        let top = hi.hi.max(lo.lo);
        let bottom = lo.lo.min(hi.hi);
        let l = self.lo.max(bottom).min(hi.lo.max(bottom));
        let h = self.hi.min(top).max(lo.hi.min(top));
        Interval::new(l.min(h), h)
    }

    /// `sqrt(x)` on the part of `x` that is not negative.
    pub fn sqrt(self) -> Interval {
        let d = self.meet(Interval::NON_NEGATIVE);
        if d.is_empty() {
            return Interval::FULL;
        }
        d.increasing(f64::sqrt)
    }

    /// `inversesqrt(x)` on the positive part of `x`.
    pub fn inverse_sqrt(self) -> Interval {
        let d = self.meet(Interval::NON_NEGATIVE);
        if d.is_empty() {
            return Interval::FULL;
        }
        d.decreasing(|x| 1.0 / x.sqrt())
    }

    /// `exp(x)`
    pub fn exp(self) -> Interval {
        self.increasing(f64::exp)
    }

    /// `exp2(x)`
    pub fn exp2(self) -> Interval {
        self.increasing(f64::exp2)
    }

    /// `log(x)` on the part of `x` that is not negative (`log(0)` is −∞).
    pub fn log(self) -> Interval {
        let d = self.meet(Interval::NON_NEGATIVE);
        if d.is_empty() {
            return Interval::FULL;
        }
        d.increasing(f64::ln)
    }

    /// `log2(x)` on the part of `x` that is not negative.
    pub fn log2(self) -> Interval {
        let d = self.meet(Interval::NON_NEGATIVE);
        if d.is_empty() {
            return Interval::FULL;
        }
        d.increasing(f64::log2)
    }

    /// `pow(x, y)` on the part of `x` that is not negative (where GLSL defines it; `pow(0, 0)`
    /// is taken as either 0 or 1).
    pub fn pow(self, y: Interval) -> Interval {
        let x = self.meet(Interval::NON_NEGATIVE);
        if x.is_empty() || y.is_empty() {
            return Interval::FULL;
        }
        // For a fixed y, x^y is monotone in x; for a fixed x, monotone in y: the extremes over
        // the box are at its corners.
        let corner = |a: f64, b: f64| -> (f64, f64) {
            if a == 0.0 {
                if b > 0.0 {
                    (0.0, 0.0)
                } else if b < 0.0 {
                    (f64::INFINITY, f64::INFINITY)
                } else {
                    (0.0, 1.0)
                }
            } else if a.is_infinite() {
                if b > 0.0 {
                    (f64::INFINITY, f64::INFINITY)
                } else if b < 0.0 {
                    (0.0, 0.0)
                } else {
                    (1.0, 1.0)
                }
            } else {
                let v = a.powf(b);
                (v, v)
            }
        };
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for a in [x.lo, x.hi] {
            for b in [y.lo, y.hi] {
                let (l, h) = corner(a, b);
                lo = lo.min(l);
                hi = hi.max(h);
            }
        }
        // x = 1 is where the monotonicity in y changes direction: 1^y = 1.
        if x.contains(1.0) {
            lo = lo.min(1.0);
            hi = hi.max(1.0);
        }
        Interval::new(lo, hi)
    }

    /// `sin(x)`
    pub fn sin(self) -> Interval {
        self.periodic(f64::sin, FRAC_PI_2, -FRAC_PI_2)
    }

    /// `cos(x)`
    pub fn cos(self) -> Interval {
        self.periodic(f64::cos, 0.0, PI)
    }

    /// A 2π-periodic function with values in `[-1, 1]`, its maxima at `max_at + 2kπ` and its
    /// minima at `min_at + 2kπ`, monotone in between.
    fn periodic(self, f: fn(f64) -> f64, max_at: f64, min_at: f64) -> Interval {
        if self.is_empty() {
            return self;
        }
        if !self.is_bounded() || self.hi - self.lo >= 2.0 * PI {
            return Interval::SIGNED_UNIT;
        }
        let (a, b) = (f(self.lo), f(self.hi));
        let mut lo = a.min(b);
        let mut hi = a.max(b);
        let hits =
            |at: f64| ((self.lo - at) / (2.0 * PI)).ceil() <= ((self.hi - at) / (2.0 * PI)).floor();
        if hits(max_at) {
            hi = 1.0;
        }
        if hits(min_at) {
            lo = -1.0;
        }
        Interval::new(lo, hi).meet(Interval::SIGNED_UNIT)
    }

    /// `tan(x)` (anything when a pole may be inside).
    pub fn tan(self) -> Interval {
        if self.is_empty() {
            return self;
        }
        if !self.is_bounded() {
            return Interval::FULL;
        }
        let k0 = ((self.lo - FRAC_PI_2) / PI).ceil();
        let k1 = ((self.hi - FRAC_PI_2) / PI).floor();
        if k0 <= k1 {
            return Interval::FULL;
        }
        self.increasing(f64::tan)
    }

    /// `sinh(x)`
    pub fn sinh(self) -> Interval {
        self.increasing(f64::sinh)
    }

    /// `cosh(x)`: smallest at 0.
    pub fn cosh(self) -> Interval {
        if self.is_empty() {
            return self;
        }
        let hi = self.lo.cosh().max(self.hi.cosh());
        let lo = if self.contains(0.0) {
            1.0
        } else {
            self.lo.cosh().min(self.hi.cosh())
        };
        Interval::new(lo, hi)
    }

    /// `tanh(x)`
    pub fn tanh(self) -> Interval {
        self.increasing(f64::tanh)
    }

    /// `asin(x)` on the part of `x` in `[-1, 1]`.
    pub fn asin(self) -> Interval {
        let d = self.meet(Interval::SIGNED_UNIT);
        if d.is_empty() {
            return Interval::FULL;
        }
        d.increasing(f64::asin)
    }

    /// `acos(x)` on the part of `x` in `[-1, 1]`.
    pub fn acos(self) -> Interval {
        let d = self.meet(Interval::SIGNED_UNIT);
        if d.is_empty() {
            return Interval::FULL;
        }
        d.decreasing(f64::acos)
    }

    /// `atan(x)`
    pub fn atan(self) -> Interval {
        self.increasing(f64::atan)
    }

    /// `floor(x)`
    pub fn floor(self) -> Interval {
        self.increasing(f64::floor)
    }

    /// `ceil(x)`
    pub fn ceil(self) -> Interval {
        self.increasing(f64::ceil)
    }

    /// `trunc(x)`
    pub fn trunc(self) -> Interval {
        self.increasing(f64::trunc)
    }

    /// `round(x)` (either rounding of halves).
    pub fn round(self) -> Interval {
        if self.is_empty() {
            return self;
        }
        Interval::new((self.lo - 0.5).ceil(), (self.hi + 0.5).floor())
    }

    /// `fract(x)` = `x - floor(x)`, in `[0, 1]` (rounding can give 1 for tiny negative `x`).
    pub fn fract(self) -> Interval {
        if self.is_empty() {
            return self;
        }
        if self.is_bounded() && self.lo.floor() == self.hi.floor() && self.lo >= 0.0 {
            return Interval::new(self.lo - self.lo.floor(), self.hi - self.hi.floor());
        }
        Interval::UNIT
    }

    /// GLSL's `mod(x, y)` = `x - y * floor(x / y)`: between 0 and `y`.
    pub fn modulo(self, y: Interval) -> Interval {
        if self.is_empty() || y.is_empty() {
            return Interval::EMPTY;
        }
        if y.lo > 0.0 {
            if self.lo >= 0.0 && self.hi < y.lo {
                return self;
            }
            return Interval::new(0.0, y.hi);
        }
        if y.hi < 0.0 {
            if self.hi <= 0.0 && self.lo > y.hi {
                return self;
            }
            return Interval::new(y.lo, 0.0);
        }
        Interval::FULL
    }

    /// The remainder of a truncating integer division (`%`): smaller than `|y|`, with the
    /// sign of `x`.
    pub fn rem_int(self, y: Interval) -> Interval {
        if self.is_empty() || y.is_empty() {
            return Interval::EMPTY;
        }
        let m = (y.mag() - 1.0).max(0.0);
        let lo = if self.lo >= 0.0 { 0.0 } else { self.lo.max(-m) };
        let hi = if self.hi <= 0.0 { 0.0 } else { self.hi.min(m) };
        Interval::new(lo, hi)
    }

    /// `sign(x)`
    pub fn sign(self) -> Interval {
        if self.is_empty() {
            return self;
        }
        let s = |x: f64| {
            if x > 0.0 {
                1.0
            } else if x < 0.0 {
                -1.0
            } else {
                0.0
            }
        };
        Interval::new(s(self.lo), s(self.hi))
    }

    /// `step(edge, x)`: 0 where `x < edge`, else 1.
    pub fn step(edge: Interval, x: Interval) -> Interval {
        if edge.is_empty() || x.is_empty() {
            return Interval::EMPTY;
        }
        if x.lo >= edge.hi {
            Interval::point(1.0)
        } else if x.hi < edge.lo {
            Interval::point(0.0)
        } else {
            Interval::UNIT
        }
    }

    /// `smoothstep(e0, e1, x)`: in `[0, 1]`, 0 or 1 where `x` is past an edge (for edges
    /// in order).
    pub fn smoothstep(e0: Interval, e1: Interval, x: Interval) -> Interval {
        if e0.is_empty() || e1.is_empty() || x.is_empty() {
            return Interval::EMPTY;
        }
        if e0.hi < e1.lo {
            if x.hi <= e0.lo {
                return Interval::point(0.0);
            }
            if x.lo >= e1.hi {
                return Interval::point(1.0);
            }
        }
        Interval::UNIT
    }

    /// `mix(a, b, t)` = `a * (1 - t) + b * t`.
    pub fn mix(a: Interval, b: Interval, t: Interval) -> Interval {
        if a.is_empty() || b.is_empty() || t.is_empty() {
            return Interval::EMPTY;
        }
        if t.within(Interval::UNIT) {
            // A convex combination stays between its ends (up to rounding).
            return a.hull(b).slack(4.0 * f32::EPSILON as f64);
        }
        a.mul(Interval::point(1.0).sub(t)).add(b.mul(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn iv() -> impl Strategy<Value = Interval> {
        (-1.0e3f64..1.0e3, 0.0f64..1.0e3).prop_map(|(a, w)| Interval::new(a, a + w))
    }

    fn small() -> impl Strategy<Value = Interval> {
        (-4.0f64..4.0, 0.0f64..4.0).prop_map(|(a, w)| Interval::new(a, a + w))
    }

    fn pos() -> impl Strategy<Value = Interval> {
        (0.0f64..20.0, 0.0f64..20.0).prop_map(|(a, w)| Interval::new(a, a + w))
    }

    /// Points of an interval: its bounds and a few inside.
    fn points(i: Interval, t: &[f64]) -> Vec<f64> {
        let mut v = vec![i.lo, i.hi];
        for &s in t {
            v.push(i.lo + (i.hi - i.lo) * s);
        }
        v
    }

    /// `f` of `x` is inside `r`, in `f32` as a shader computes it (NaN: outside the domain).
    fn inside(r: Interval, x: f64) -> bool {
        x.is_nan() || r.contains(x) || r.contains(x as f32 as f64)
    }

    proptest! {
        #[test]
        fn binary_ops_contain_their_samples(a in iv(), b in iv(), t in proptest::collection::vec(0.0f64..1.0, 3)) {
            for x in points(a, &t) {
                for y in points(b, &t) {
                    prop_assert!(inside(a.add(b), x + y));
                    prop_assert!(inside(a.sub(b), x - y));
                    prop_assert!(inside(a.mul(b), x * y));
                    if y != 0.0 {
                        prop_assert!(inside(a.div(b), x / y), "{a:?} / {b:?} at {x} / {y}");
                    }
                    prop_assert!(inside(a.min(b), x.min(y)));
                    prop_assert!(inside(a.max(b), x.max(y)));
                    if y != 0.0 {
                        prop_assert!(inside(a.modulo(b), x - y * (x / y).floor()), "mod {a:?} {b:?} at {x} {y}");
                    }
                    let stepped = if y < x { 0.0 } else { 1.0 };
                    prop_assert!(inside(Interval::step(a, b), stepped));
                }
            }
        }

        #[test]
        fn unary_ops_contain_their_samples(a in iv(), t in proptest::collection::vec(0.0f64..1.0, 4)) {
            for x in points(a, &t) {
                prop_assert!(inside(a.neg(), -x));
                prop_assert!(inside(a.abs(), x.abs()));
                prop_assert!(inside(a.sqr(), x * x));
                prop_assert!(inside(a.sqrt(), x.sqrt()));
                prop_assert!(inside(a.exp().slack(1e-6), x.exp()));
                prop_assert!(inside(a.log(), x.ln()));
                prop_assert!(inside(a.sin(), x.sin()), "sin {a:?} at {x}");
                prop_assert!(inside(a.cos(), x.cos()), "cos {a:?} at {x}");
                prop_assert!(inside(a.tan(), x.tan()), "tan {a:?} at {x}");
                prop_assert!(inside(a.atan(), x.atan()));
                prop_assert!(inside(a.floor(), x.floor()));
                prop_assert!(inside(a.ceil(), x.ceil()));
                prop_assert!(inside(a.round(), x.round()));
                prop_assert!(inside(a.fract(), x - x.floor()));
                let sign = if x > 0.0 { 1.0 } else if x < 0.0 { -1.0 } else { 0.0 };
                prop_assert!(inside(a.sign(), sign));
                if x != 0.0 {
                    prop_assert!(inside(a.recip(), 1.0 / x));
                }
                if x > 0.0 {
                    prop_assert!(inside(a.inverse_sqrt(), 1.0 / x.sqrt()));
                    prop_assert!(inside(a.log2(), x.log2()));
                }
            }
        }

        #[test]
        fn inverse_trig_contains_its_samples(a in -1.0f64..1.0, w in 0.0f64..2.0, t in proptest::collection::vec(0.0f64..1.0, 4)) {
            let i = Interval::new(a, (a + w).min(1.0));
            for x in points(i, &t) {
                prop_assert!(inside(i.asin(), x.asin()));
                prop_assert!(inside(i.acos(), x.acos()));
            }
        }

        #[test]
        fn pow_contains_its_samples(a in pos(), b in small(), t in proptest::collection::vec(0.0f64..1.0, 3)) {
            let r = a.pow(b).slack(1e-6);
            for x in points(a, &t) {
                for y in points(b, &t) {
                    if x == 0.0 && y <= 0.0 {
                        continue;
                    }
                    prop_assert!(inside(r, x.powf(y)), "pow {a:?} {b:?} at {x} {y}");
                }
            }
        }

        #[test]
        fn mix_clamp_smoothstep_contain_their_samples(a in small(), b in small(), c in small(), t in proptest::collection::vec(0.0f64..1.0, 3)) {
            let tt = Interval::new(c.lo.clamp(0.0, 1.0), c.hi.clamp(0.0, 1.0));
            for x in points(a, &t) {
                for y in points(b, &t) {
                    for s in points(tt, &t) {
                        prop_assert!(inside(Interval::mix(a, b, tt), x * (1.0 - s) + y * s));
                    }
                    for z in points(c, &t) {
                        if y <= z {
                            prop_assert!(inside(a.clamp_ordered(b, c), x.max(y).min(z)));
                        }
                        if x < y {
                            let u = ((z - x) / (y - x)).clamp(0.0, 1.0);
                            prop_assert!(inside(Interval::smoothstep(a, b, c), u * u * (3.0 - 2.0 * u)));
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn bounds_round_outward_to_f32() {
        let i = Interval::point(0.1);
        assert!(i.lo <= 0.1 && 0.1 <= i.hi);
        assert_eq!(i.lo as f32 as f64, i.lo);
        assert_eq!(Interval::new(1.0, 1e39).hi, f64::INFINITY);
    }

    #[test]
    fn known_values() {
        assert_eq!(Interval::new(-2.0, 3.0).sqr(), Interval::new(0.0, 9.0));
        assert_eq!(
            Interval::new(0.0, 1.0).recip(),
            Interval::new(1.0, f64::INFINITY)
        );
        assert_eq!(Interval::new(-1.0, 1.0).recip(), Interval::FULL);
        assert_eq!(Interval::new(0.0, 4.0).cos().hi, 1.0);
        assert_eq!(Interval::FULL.sin(), Interval::SIGNED_UNIT);
        assert_eq!(
            Interval::new(0.5, 2.0).pow(Interval::point(2.0)),
            Interval::new(0.25, 4.0)
        );
    }
}
