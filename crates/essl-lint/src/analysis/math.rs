//! The built-in functions (`MathFunction`), one method per family: what each does to the
//! intervals of its arguments, and which facts (sign, non-zero, unit range, length) it keeps.

use naga::{Expression as E, Handle, MathFunction as Mf, TypeInner};

use super::binary::triangle;
use super::memory::shape;
use super::{Analysis, Site, EPS};
use crate::interval::Interval;
use crate::value::{norm_of, Facts, Num, Val};

/// A call of a built-in function whose arguments are all numbers.
struct Call<'a> {
    /// The function it is in.
    s: Site<'a>,
    /// The result type.
    ty: &'a TypeInner,
    /// The built-in.
    fun: Mf,
    /// The argument expressions.
    args: Vec<Handle<E>>,
    /// Their numbers.
    nums: Vec<Num>,
    /// The first argument's number.
    x: Num,
    /// Where the arguments come from.
    deps: Facts,
}

impl Analysis {
    /// The value of a built-in function call `e` (an `Expression::Math`) of result type `ty`.
    pub(super) fn math(&self, s: Site, ty: &TypeInner, e: &E) -> Val {
        let E::Math {
            fun,
            arg,
            arg1,
            arg2,
            ..
        } = *e
        else {
            return Self::unknown(s.module, ty, Facts::NONE);
        };
        let (module, id) = (s.module, s.id);
        let args: Vec<Handle<E>> = [Some(arg), arg1, arg2].into_iter().flatten().collect();
        if args.iter().any(|a| self.v(id, *a).is_bot()) {
            return Val::Bot;
        }
        let deps = args.iter().fold(Facts::NONE, |acc, a| {
            acc.with(self.v(id, *a).facts().only(Facts::DEPS))
        });
        let nums: Vec<Num> = args.iter().filter_map(|a| self.nm(id, *a)).collect();
        if nums.len() != args.len() {
            // Matrix functions and others on aggregates.
            return match fun {
                Mf::Transpose | Mf::Inverse => {
                    let inv = self.v(id, arg).facts().has(Facts::NZ);
                    shape(module, ty, &|n, _| {
                        Num::splat(Interval::FULL, n, deps.set(Facts::NZ, inv))
                    })
                }
                Mf::Determinant => {
                    let inv = self.v(id, arg).facts().has(Facts::NZ);
                    Val::Num(Num::scalar(Interval::FULL, deps.set(Facts::NZ, inv)))
                }
                _ => Self::unknown(module, ty, deps),
            };
        }
        let call = Call {
            s,
            ty,
            fun,
            x: nums[0],
            args,
            nums,
            deps,
        };
        match fun {
            Mf::Abs | Mf::Min | Mf::Max | Mf::Clamp | Mf::Saturate => call.range(),
            Mf::Sin
            | Mf::Cos
            | Mf::Tan
            | Mf::Sinh
            | Mf::Cosh
            | Mf::Tanh
            | Mf::Asin
            | Mf::Acos
            | Mf::Atan
            | Mf::Atan2
            | Mf::Asinh
            | Mf::Atanh
            | Mf::Acosh
            | Mf::Radians
            | Mf::Degrees => call.trigonometric(),
            Mf::Ceil | Mf::Floor | Mf::Round | Mf::Trunc | Mf::Fract | Mf::Sign => call.rounding(),
            Mf::Exp | Mf::Exp2 | Mf::Log | Mf::Log2 | Mf::Sqrt | Mf::InverseSqrt | Mf::Pow => {
                call.exponential()
            }
            Mf::Step | Mf::SmoothStep | Mf::Mix | Mf::Fma => call.interpolation(self),
            Mf::Dot
            | Mf::Cross
            | Mf::Length
            | Mf::Distance
            | Mf::Normalize
            | Mf::FaceForward
            | Mf::Reflect => call.geometric(self),
            Mf::QuantizeToF16
            | Mf::Unpack2x16unorm
            | Mf::Unpack4x8unorm
            | Mf::Unpack2x16snorm
            | Mf::Unpack4x8snorm => call.packing(),
            _ => call.unknown(),
        }
    }
}

impl Call<'_> {
    /// A value of the result type about which nothing is known.
    fn unknown(&self) -> Val {
        Analysis::unknown(self.s.module, self.ty, self.deps)
    }

    /// `g` of each component of the first argument (`slack`: widened for the GPU's
    /// approximation), with `facts`.
    fn unary(&self, g: fn(Interval) -> Interval, slack: bool, facts: Facts) -> Val {
        let comps = self.x.map(|c| if slack { g(c).slack(EPS) } else { g(c) });
        Val::Num(Num::from_components(&comps, facts.with(self.deps)))
    }

    /// The sign facts of `f` that an odd, increasing function keeps.
    fn keep_sign(&self, f: Facts) -> Facts {
        Facts::NONE
            .set(Facts::NN, f.has(Facts::NN))
            .set(Facts::POS, f.has(Facts::POS))
            .set(Facts::NZ, f.has(Facts::NZ) && self.x.n == 1)
    }

    /// `abs`, `min`, `max`, `clamp`, `saturate`: bounds on the argument.
    fn range(&self) -> Val {
        let (x, fx, deps) = (self.x, self.x.facts, self.deps);
        let nums = &self.nums;
        match self.fun {
            Mf::Abs => {
                // `abs` of an external value as such says the caller passes both signs, so
                // its 0 is an ordinary value: the assumption that the value is positive (or,
                // for a scalar, not 0) is dropped. A vector keeps its assumed non-zero length.
                let ext = fx.has(Facts::EXT);
                let nz = fx.has(Facts::NZ) && !(ext && x.n == 1);
                let facts = Facts::NN
                    .set(
                        Facts::POS,
                        !ext && (fx.has(Facts::POS) || (x.n == 1 && fx.has(Facts::NZ))),
                    )
                    .set(Facts::NZ, nz)
                    .set(Facts::UNIT, fx.has(Facts::UNIT))
                    .set(Facts::INTEGRAL, fx.has(Facts::INTEGRAL));
                let mut r = Num::from_components(&x.map(Interval::abs), facts.with(deps));
                r.norm = r.norm.meet(x.norm);
                Val::Num(r.settle())
            }
            Mf::Min | Mf::Max => {
                let y = nums[1];
                let fy = y.facts;
                let comps = x.zip(
                    &y,
                    if self.fun == Mf::Min {
                        Interval::min
                    } else {
                        Interval::max
                    },
                );
                let (nn, pos) = if self.fun == Mf::Min {
                    (
                        fx.has(Facts::NN) && fy.has(Facts::NN),
                        fx.has(Facts::POS) && fy.has(Facts::POS),
                    )
                } else {
                    (
                        fx.has(Facts::NN) || fy.has(Facts::NN),
                        fx.has(Facts::POS) || fy.has(Facts::POS),
                    )
                };
                // `min(x, 1.0)` of a non-negative x is in [0, 1] too.
                let at_most_one = |n: &Num| n.comps().iter().all(|c| c.hi <= 1.0);
                let unit = fx.has(Facts::UNIT) && fy.has(Facts::UNIT)
                    || self.fun == Mf::Min
                        && nn
                        && (fx.has(Facts::UNIT)
                            || fy.has(Facts::UNIT)
                            || at_most_one(&x)
                            || at_most_one(&y));
                let facts = deps
                    .set(Facts::NN, nn)
                    .set(Facts::POS, pos)
                    .set(Facts::NZ, pos)
                    .set(Facts::UNIT, unit)
                    .set(
                        Facts::INTEGRAL,
                        fx.has(Facts::INTEGRAL) && fy.has(Facts::INTEGRAL),
                    );
                Val::Num(Num::from_components(&comps, facts))
            }
            Mf::Clamp | Mf::Saturate => {
                let (lo, hi) = if self.fun == Mf::Clamp {
                    (nums[1], nums[2])
                } else {
                    (Num::constant(&[0.0]), Num::constant(&[1.0]))
                };
                let comps: Vec<Interval> = (0..x.n as usize)
                    .map(|i| {
                        let pick = |n: &Num| {
                            if n.n == 1 {
                                n.c[0]
                            } else {
                                n.c[i.min(n.n as usize - 1)]
                            }
                        };
                        x.c[i].clamp_ordered(pick(&lo), pick(&hi))
                    })
                    .collect();
                // Bounds in order (the call is undefined otherwise): at least `lo`.
                let nn = fx.has(Facts::NN) && hi.facts.has(Facts::NN) || lo.facts.has(Facts::NN);
                let pos =
                    fx.has(Facts::POS) && hi.facts.has(Facts::POS) || lo.facts.has(Facts::POS);
                let unit =
                    fx.has(Facts::UNIT) && lo.facts.has(Facts::UNIT) && hi.facts.has(Facts::UNIT);
                Val::Num(Num::from_components(
                    &comps,
                    deps.set(Facts::NN, nn)
                        .set(Facts::POS, pos)
                        .set(Facts::NZ, pos)
                        .set(Facts::UNIT, unit),
                ))
            }
            _ => self.unknown(),
        }
    }

    /// The trigonometric and hyperbolic functions, `radians` and `degrees`.
    fn trigonometric(&self) -> Val {
        let (x, fx, deps) = (self.x, self.x.facts, self.deps);
        match self.fun {
            Mf::Sin | Mf::Cos => self.unary(
                if self.fun == Mf::Sin {
                    Interval::sin
                } else {
                    Interval::cos
                },
                false,
                Facts::UNIT,
            ),
            Mf::Tan => self.unary(Interval::tan, true, Facts::NONE),
            Mf::Sinh => self.unary(Interval::sinh, true, self.keep_sign(fx)),
            Mf::Cosh => self.unary(
                Interval::cosh,
                true,
                Facts::NN.with(Facts::POS).with(Facts::NZ),
            ),
            Mf::Tanh => self.unary(Interval::tanh, true, self.keep_sign(fx)),
            Mf::Asin => self.unary(Interval::asin, true, self.keep_sign(fx)),
            Mf::Acos => self.unary(Interval::acos, true, Facts::NN),
            Mf::Atan => self.unary(Interval::atan, true, self.keep_sign(fx)),
            Mf::Atan2 => Val::Num(Num::splat(
                Interval::new(-std::f64::consts::PI, std::f64::consts::PI),
                x.n,
                deps,
            )),
            Mf::Asinh | Mf::Atanh => Val::Num(Num::splat(
                Interval::FULL,
                x.n,
                deps.with(self.keep_sign(fx)),
            )),
            Mf::Acosh => Val::Num(Num::splat(Interval::NON_NEGATIVE, x.n, deps)),
            Mf::Radians | Mf::Degrees => {
                let k = if self.fun == Mf::Radians {
                    std::f64::consts::PI / 180.0
                } else {
                    180.0 / std::f64::consts::PI
                };
                let comps = x.map(|c| c.mul(Interval::new(k, k)));
                Val::Num(Num::from_components(&comps, deps.with(self.keep_sign(fx))))
            }
            _ => self.unknown(),
        }
    }

    /// `ceil`, `floor`, `round`, `trunc`, `fract`, `sign`.
    fn rounding(&self) -> Val {
        let fx = self.x.facts;
        match self.fun {
            Mf::Ceil => self.unary(
                Interval::ceil,
                false,
                self.keep_sign(fx)
                    .with(fx.only(Facts::UNIT))
                    .with(Facts::INTEGRAL),
            ),
            Mf::Floor | Mf::Round | Mf::Trunc => {
                let g = match self.fun {
                    Mf::Floor => Interval::floor,
                    Mf::Round => Interval::round,
                    _ => Interval::trunc,
                };
                self.unary(
                    g,
                    false,
                    Facts::INTEGRAL
                        .set(Facts::NN, fx.has(Facts::NN))
                        .with(fx.only(Facts::UNIT)),
                )
            }
            Mf::Fract => self.unary(Interval::fract, false, Facts::NN.with(Facts::UNIT)),
            Mf::Sign => self.unary(Interval::sign, false, self.keep_sign(fx).with(Facts::UNIT)),
            _ => self.unknown(),
        }
    }

    /// `exp`, `exp2`, `log`, `log2`, `sqrt`, `inversesqrt`, `pow`.
    fn exponential(&self) -> Val {
        let (x, fx, deps) = (self.x, self.x.facts, self.deps);
        let nums = &self.nums;
        match self.fun {
            Mf::Exp | Mf::Exp2 => {
                let g = if self.fun == Mf::Exp {
                    Interval::exp
                } else {
                    Interval::exp2
                };
                // The slack is for the GPU's approximation; every GPU's exponential is exact
                // at 0 and increasing, so that of a value ≤ 0 stays ≤ 1 (`1.0 - exp(-k * d)`
                // is not negative).
                let comps = x.map(|c| {
                    let r = g(c).slack(EPS);
                    if c.hi <= 0.0 {
                        Interval::new(r.lo, r.hi.min(1.0))
                    } else {
                        r
                    }
                });
                // Of a value not positive whenever the external values are not negative
                // (`exp(-k * d)`): in (0, 1] for those values too.
                Val::Num(Num::from_components(
                    &comps,
                    Facts::NN
                        .with(Facts::POS)
                        .with(Facts::NZ)
                        .set(Facts::UNIT, fx.has(Facts::NP))
                        .with(deps),
                ))
            }
            Mf::Log | Mf::Log2 => self.unary(
                if self.fun == Mf::Log {
                    Interval::log
                } else {
                    Interval::log2
                },
                true,
                Facts::NONE,
            ),
            Mf::Sqrt => self.unary(
                Interval::sqrt,
                true,
                Facts::NN
                    .set(Facts::POS, fx.has(Facts::POS))
                    .set(Facts::NZ, fx.has(Facts::POS) && x.n == 1)
                    .set(Facts::UNIT, fx.has(Facts::UNIT) && fx.has(Facts::NN)),
            ),
            Mf::InverseSqrt => self.unary(
                Interval::inverse_sqrt,
                true,
                Facts::NN.with(Facts::POS).with(Facts::NZ),
            ),
            Mf::Pow => {
                let y = nums[1];
                // As `exp2(y * log2(x))`: `log2` is exact at 1 and increasing, `exp2` exact at
                // 0 and increasing, so `x ≥ 1` and `y ≥ 0` keep the result at least 1
                // (`int(pow(256.0, float(k)))` is not 0 for `k ≥ 0`).
                let comps = x.zip(&y, |p, q| {
                    let r = p.pow(q).slack(EPS);
                    if p.lo >= 1.0 && q.lo >= 0.0 {
                        Interval::new(r.lo.max(1.0), r.hi)
                    } else {
                        r
                    }
                });
                let facts = Facts::NN
                    .set(Facts::POS, fx.has(Facts::POS))
                    .set(Facts::NZ, fx.has(Facts::POS) && x.n == 1)
                    .set(
                        Facts::UNIT,
                        fx.has(Facts::UNIT) && fx.has(Facts::NN) && y.facts.has(Facts::NN),
                    );
                Val::Num(Num::from_components(&comps, facts.with(deps)))
            }
            _ => self.unknown(),
        }
    }

    /// `step`, `smoothstep`, `mix`, `fma`.
    fn interpolation(&self, a: &Analysis) -> Val {
        let (x, fx, deps) = (self.x, self.x.facts, self.deps);
        let nums = &self.nums;
        match self.fun {
            Mf::Step => {
                let y = nums[1];
                let comps = x.zip(&y, Interval::step);
                Val::Num(Num::from_components(
                    &comps,
                    deps.with(Facts::NN).with(Facts::UNIT).with(Facts::INTEGRAL),
                ))
            }
            Mf::SmoothStep => {
                let (e1, v) = (nums[1], nums[2]);
                let comps: Vec<Interval> = (0..v.n as usize)
                    .map(|i| {
                        let pick = |n: &Num| {
                            if n.n == 1 {
                                n.c[0]
                            } else {
                                n.c[i.min(n.n as usize - 1)]
                            }
                        };
                        Interval::smoothstep(pick(&x), pick(&e1), v.c[i])
                    })
                    .collect();
                Val::Num(Num::from_components(
                    &comps,
                    deps.with(Facts::NN).with(Facts::UNIT),
                ))
            }
            Mf::Mix => {
                let (b, t) = (nums[1], nums[2]);
                let comps: Vec<Interval> = (0..x.n.max(b.n) as usize)
                    .map(|i| {
                        let pick = |n: &Num| {
                            if n.n == 1 {
                                n.c[0]
                            } else {
                                n.c[i.min(n.n as usize - 1)]
                            }
                        };
                        Interval::mix(pick(&x), pick(&b), pick(&t))
                    })
                    .collect();
                // A weight in [0, 1] but for rounding (`0.5 * dot(n, l) + 0.5`) still mixes.
                let weight = Interval::new(-16.0 * EPS, 1.0 + 16.0 * EPS);
                let convex = t.facts.has(Facts::NN.with(Facts::UNIT))
                    || t.comps().iter().all(|c| c.within(weight))
                    || a.monotone_range(self.s, self.args[2])
                        .is_some_and(|r| r.within(weight));
                let fb = b.facts;
                let facts = Facts::NONE
                    .set(Facts::NN, convex && fx.has(Facts::NN) && fb.has(Facts::NN))
                    .set(
                        Facts::POS,
                        convex && fx.has(Facts::POS) && fb.has(Facts::POS),
                    )
                    .set(
                        Facts::UNIT,
                        convex && fx.has(Facts::UNIT) && fb.has(Facts::UNIT),
                    );
                Val::Num(Num::from_components(&comps, facts.with(deps)))
            }
            Mf::Fma => {
                let comps: Vec<Interval> = (0..x.n as usize)
                    .map(|i| {
                        x.c[i]
                            .mul(nums[1].c[i.min(nums[1].n as usize - 1)])
                            .add(nums[2].c[i.min(nums[2].n as usize - 1)])
                    })
                    .collect();
                Val::Num(Num::from_components(&comps, deps))
            }
            _ => self.unknown(),
        }
    }

    /// `dot`, `cross`, `length`, `distance`, `normalize`, `faceforward`, `reflect`: with the lengths of vectors.
    fn geometric(&self, a: &Analysis) -> Val {
        let (x, fx, deps) = (self.x, self.x.facts, self.deps);
        let nums = &self.nums;
        match self.fun {
            Mf::Dot => {
                let y = nums[1];
                let slack = EPS * (x.n as f64 + 2.0);
                if a.same(self.s.f, self.s.id, self.args[0], self.args[1]) {
                    let r = x.norm.sqr().slack(slack).meet(Interval::NON_NEGATIVE);
                    let facts = Facts::NN
                        .set(Facts::POS, fx.has(Facts::NZ))
                        .set(Facts::NZ, fx.has(Facts::NZ));
                    return Val::Num(Num::scalar(r, facts.with(deps)));
                }
                let by_comps = (0..x.n as usize).fold(Interval::point(0.0), |s, i| {
                    s.add(x.c[i].mul(y.c[i.min(y.n as usize - 1)]))
                });
                // A uniform or input vector dotted with a unit vector is taken to be a
                // direction, as valid as the unit vector (`dot(normal, u_lightDirection)`):
                // one of another length is the runtime check's business.
                let unit = |n: &Num| {
                    n.norm
                        .within(Interval::new(1.0 - 4.0 * EPS, 1.0 + 4.0 * EPS))
                };
                let direction = |n: &Num| n.n > 1 && n.facts.has(Facts::EXT);
                let m = if (unit(&x) && direction(&y)) || (unit(&y) && direction(&x)) {
                    1.0
                } else {
                    x.norm.hi * y.norm.hi
                };
                let by_norm = Interval::new(-m, m).slack(slack);
                let r = by_comps.meet(by_norm);
                // A weighted sum of non-negative terms (`dot(u_attenuation, vec3(1.0, d, d * d))`,
                // a luminance): one side not negative by its values, the other by its facts.
                // Two directions (`dot(normalize(n), normalize(h))`) stay signed.
                let by_values = |n: &Num| n.comps().iter().all(|c| c.lo >= 0.0);
                let nn = (by_values(&x) && y.facts.has(Facts::NN))
                    || (by_values(&y) && fx.has(Facts::NN));
                Val::Num(Num::scalar(
                    if r.is_empty() { by_comps } else { r },
                    deps.set(Facts::NN, nn),
                ))
            }
            Mf::Cross => {
                let y = nums[1];
                if x.n != 3 || y.n != 3 {
                    return self.unknown();
                }
                let c = |i: usize, j: usize| x.c[i].mul(y.c[j]).sub(x.c[j].mul(y.c[i]));
                let comps = [c(1, 2), c(2, 0), c(0, 1)];
                // Parallel vectors are an ordinary configuration when one of them is fixed for
                // the draw (an `up` vector, a uniform direction); two per-vertex mesh vectors
                // (normal, tangent) are taken to be a valid frame.
                let per_pixel = Facts::INPUT.with(Facts::TEXTURE);
                let fixed = !x.facts.any(per_pixel) || !y.facts.any(per_pixel);
                let mut r = Num::from_components(&comps, deps.set(Facts::CROSS, fixed));
                r.norm = r
                    .norm
                    .meet(Interval::new(0.0, x.norm.hi * y.norm.hi).slack(EPS * 4.0));
                Val::Num(r.settle())
            }
            Mf::Length => {
                let r = x.norm.slack(EPS).meet(Interval::NON_NEGATIVE);
                let facts = Facts::NN
                    .set(Facts::POS, fx.has(Facts::NZ))
                    .set(Facts::NZ, fx.has(Facts::NZ));
                Val::Num(Num::scalar(r, facts.with(deps)))
            }
            Mf::Distance => {
                let y = nums[1];
                let comps = x.zip(&y, Interval::sub);
                let d = if x.n == 1 {
                    comps[0].abs()
                } else {
                    norm_of(&comps).meet(triangle(x.norm, y.norm))
                };
                Val::Num(Num::scalar(
                    d.slack(EPS).meet(Interval::NON_NEGATIVE),
                    deps.with(Facts::NN),
                ))
            }
            Mf::Normalize => {
                // A unit vector: however large the ordinary values it was computed from.
                let deps = deps.without(Facts::MAGNITUDE);
                let one = Interval::new(1.0 - EPS, 1.0 + EPS);
                let points: Vec<f64> = x.comps().iter().filter_map(|c| c.as_point()).collect();
                let len = points.iter().map(|p| p * p).sum::<f64>().sqrt();
                if points.len() == x.n as usize && len > 0.0 {
                    // A constant direction: its components, up to rounding.
                    let comps: Vec<Interval> = points
                        .iter()
                        .map(|p| Interval::point(p / len).slack(EPS))
                        .collect();
                    let mut r = Num::from_components(&comps, Facts::NZ.with(deps));
                    r.norm = one;
                    return Val::Num(r.settle());
                }
                let comps = x.map(|c| {
                    let lo = if c.lo >= 0.0 { 0.0 } else { -one.hi };
                    let hi = if c.hi <= 0.0 { 0.0 } else { one.hi };
                    Interval::new(lo, hi)
                });
                let facts = Facts::NZ
                    .set(Facts::NN, fx.has(Facts::NN))
                    .set(Facts::POS, fx.has(Facts::POS));
                let mut r = Num::from_components(&comps, facts.with(deps));
                r.norm = one;
                Val::Num(r.settle())
            }
            Mf::FaceForward => {
                let comps = x.map(|c| c.hull(c.neg()));
                let mut r = Num::from_components(
                    &comps,
                    deps.set(Facts::NZ, fx.has(Facts::NZ))
                        .set(Facts::UNIT, fx.has(Facts::UNIT)),
                );
                r.norm = r.norm.meet(x.norm);
                Val::Num(r.settle())
            }
            Mf::Reflect => {
                let nrm = nums[1];
                let unit_n = nrm
                    .norm
                    .within(Interval::new(1.0 - 4.0 * EPS, 1.0 + 4.0 * EPS));
                if unit_n {
                    let len = x.norm.slack(EPS * 8.0);
                    let comps = x.map(|_| Interval::new(-len.hi, len.hi));
                    let mut r =
                        Num::from_components(&comps, deps.set(Facts::NZ, fx.has(Facts::NZ)));
                    r.norm = r.norm.meet(len);
                    Val::Num(r.settle())
                } else {
                    let d = (0..x.n as usize).fold(Interval::point(0.0), |s, i| {
                        s.add(x.c[i].mul(nrm.c[i.min(nrm.n as usize - 1)]))
                    });
                    let k = d.mul(Interval::point(2.0));
                    let comps: Vec<Interval> = (0..x.n as usize)
                        .map(|i| x.c[i].sub(k.mul(nrm.c[i.min(nrm.n as usize - 1)])))
                        .collect();
                    Val::Num(Num::from_components(&comps, deps))
                }
            }
            _ => self.unknown(),
        }
    }

    /// `quantizeToF16` and the unpacking functions.
    fn packing(&self) -> Val {
        let (x, fx, deps) = (self.x, self.x.facts, self.deps);
        match self.fun {
            Mf::QuantizeToF16 => Val::Num(Num::from_components(x.comps(), fx)),
            Mf::Unpack2x16unorm | Mf::Unpack4x8unorm => shape(self.s.module, self.ty, &|n, _| {
                Num::splat(Interval::UNIT, n, deps)
            }),
            Mf::Unpack2x16snorm | Mf::Unpack4x8snorm => shape(self.s.module, self.ty, &|n, _| {
                Num::splat(Interval::SIGNED_UNIT, n, deps)
            }),
            _ => self.unknown(),
        }
    }
}
