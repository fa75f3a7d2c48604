//! Whether a value is 0 over the unlit side of a surface: a product with a clamped cosine
//! (`max(dot(n, l), 0.0)`, `saturate(dot(n, v))`), or a sum, difference or `mix` of such
//! values. A BRDF's visibility term divides by one: the Smith–GGX `0.5 / (lambdaV + lambdaL)`
//! with `lambdaV = NoL * …` and `lambdaL = NoV * …` (for a roughness of 0, `2 NoL NoV`),
//! Neubelt's `1.0 / (4.0 * (dotNL + dotNV - dotNL * dotNV))`, Cook–Torrance's
//! `/ (4.0 * NdotL * NdotV)`; each is 0 on every pixel that faces away from the light (or,
//! with a normal map, from the viewer), where the quotient is ±∞ or, over a numerator with the
//! same factor, NaN.
//!
//! A clamped cosine is 0 over a region where its dot product is negative; a raw `dot` of
//! per-pixel vectors crosses 0 on a line of pixels only, and a clamp of per-draw values is the
//! runtime check's. A function's parameter is such a cosine where a call passes one, or — for
//! an input as such, which the analysis knows nothing of — where its name is one the
//! physically based shading literature gives the clamped cosines of the light and view
//! directions (`NoL`, `NdotV`, `dotNL`): every caller in the corpora computes them with
//! `saturate` or `max(…, 0.0)` (`docs/lints/corpus.md`). A sum is taken to be 0 where each of
//! its terms is: the terms' regions are the same unlit side in every shader seen, which the
//! analysis does not prove.
//!
//! The same walk finds a value that is 0 wherever a texel it reads is black or transparent: a
//! sum, product, `dot` or matrix product of texels as such — Cesium's `X + Y + Z` of a colour
//! converted to XYZ, a luminance `dot(c.rgb, w)` — which a tone mapping or a chromaticity
//! divides by, and which is 0 over every black region of the picture.

use naga::{BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf};

use super::Cx;
use crate::analysis;
use crate::value::Facts;

/// How deep the walk follows operands.
const DEPTH: u32 = 10;

/// Names of parameters that hold the clamped cosine of a light or view direction with the
/// normal, lower-cased.
const COSINES: &[&str] = &[
    "nol", "nov", "ndotl", "ndotv", "dotnl", "dotnv", "ndl", "ndv",
];

/// What makes the value 0 over a region.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Zero {
    /// A clamped cosine: the unlit side of a surface.
    Unlit,
    /// A texel as such at the bottom of its range: a black or transparent region.
    Black,
}

/// A call the walk went through from its result into the callee: the caller and the call's
/// arguments.
struct Call<'a> {
    id: usize,
    f: &'a Function,
    args: &'a [Handle<E>],
    up: Option<&'a Call<'a>>,
}

impl Cx<'_> {
    /// The clamped cosine that makes `h` 0 over the unlit side of a surface, if one does: the
    /// clamp's expression, in function `at.0`.
    pub fn unlit_zero(&self, f: &Function, id: usize, h: Handle<E>) -> Option<(usize, Handle<E>)> {
        self.zero_over(Zero::Unlit, f, id, h, None, 0)
    }

    /// The texel as such that makes `h` 0 wherever it is black or transparent, if one does (a
    /// sum, product or `dot` of texels, through locals and calls): the texel's expression, in
    /// function `at.0`.
    pub fn black_zero(&self, f: &Function, id: usize, h: Handle<E>) -> Option<(usize, Handle<E>)> {
        self.zero_over(Zero::Black, f, id, h, None, 0)
    }

    fn zero_over(
        &self,
        kind: Zero,
        f: &Function,
        id: usize,
        h: Handle<E>,
        at: Option<&Call>,
        depth: u32,
    ) -> Option<(usize, Handle<E>)> {
        if depth > DEPTH {
            return None;
        }
        if kind == Zero::Black && self.black_texel(id, h) {
            return Some((id, h));
        }
        let d = depth + 1;
        let go = |x: Handle<E>| self.zero_over(kind, f, id, x, at, d);
        let constant = |x: Handle<E>| {
            self.sound()
                .num(id, x)
                .and_then(|n| n.hull().as_point())
                .filter(|p| p.is_finite())
        };
        match f.expressions[h] {
            E::Math {
                fun,
                arg,
                arg1,
                arg2,
                ..
            } => match (fun, arg1, arg2) {
                (Mf::Dot, Some(b), _) if kind == Zero::Black => go(arg).or_else(|| go(b)),
                // The largest of texels is 0 where all are black (FSR's `max` of a pixel's
                // neighbours), the smallest where one is; a `max` with a constant floor is a
                // guard.
                (Mf::Max, Some(b), _) if kind == Zero::Black => go(arg).and(go(b)),
                (Mf::Min, Some(b), _) if kind == Zero::Black => go(arg).or_else(|| go(b)),
                (Mf::Saturate | Mf::Clamp, _, _) if kind == Zero::Black => None,
                (Mf::Saturate, _, _) => self.cosine(f, id, arg).then_some((id, h)),
                (Mf::Max, Some(b), _) => {
                    let clamps = |x, c: Handle<E>| {
                        self.cosine(f, id, x) && constant(c).is_some_and(|c| c <= 0.0)
                    };
                    (clamps(arg, b) || clamps(b, arg)).then_some((id, h))
                }
                (Mf::Clamp, Some(lo), _) => (self.cosine(f, id, arg)
                    && constant(lo).is_some_and(|c| c <= 0.0))
                .then_some((id, h)),
                (Mf::Mix, Some(b), _) => go(arg).and(go(b)),
                (Mf::Sqrt | Mf::Abs | Mf::Length, _, _) => go(arg),
                (Mf::Pow, Some(e), _) if constant(e).is_some_and(|e| e > 0.0) => go(arg),
                _ => None,
            },
            E::Binary { op, left, right } => match op {
                Bo::Multiply => go(left).or_else(|| go(right)),
                Bo::Divide => go(left),
                // A difference of texels is `division-by-difference`'s own business (0 at an
                // end of the texels' range, not only where they are black).
                Bo::Subtract if kind == Zero::Black => None,
                Bo::Add | Bo::Subtract => go(left).and(go(right)),
                _ => None,
            },
            E::Unary {
                op: naga::UnaryOperator::Negate,
                expr,
            } => go(expr),
            E::Swizzle { vector: base, .. } | E::AccessIndex { base, .. } => go(base),
            E::Splat { value, .. } => go(value),
            E::Load { pointer } => self.stored(f, id, pointer).into_iter().find_map(go),
            E::CallResult(callee) => {
                let c = callee.index();
                if c >= self.module.functions.len() {
                    return None;
                }
                // The callee's parameters are this call's arguments.
                let call = Call {
                    id,
                    f,
                    args: self.flows().arguments(id, h)?,
                    up: at,
                };
                let g = analysis::function(self.module, c);
                self.flows()
                    .returns(c)
                    .iter()
                    .find_map(|x| self.zero_over(kind, g, c, *x, Some(&call), d))
            }
            E::FunctionArgument(i) if id < self.module.functions.len() => {
                let i = i as usize;
                let named = kind == Zero::Unlit
                    && f.arguments[i].name.as_deref().is_some_and(is_cosine_name);
                let from = |caller: usize, g: &Function, a: Handle<E>, up: Option<&Call>| {
                    self.zero_over(kind, g, caller, a, up, d)
                        .or_else(|| (named && self.input_as_such(caller, a)).then_some((id, h)))
                };
                if let Some(call) = at {
                    return from(call.id, call.f, *call.args.get(i)?, call.up);
                }
                self.flows().callers(id).iter().find_map(|(caller, args)| {
                    let g = analysis::function(self.module, *caller);
                    from(*caller, g, *args.get(i)?, None)
                })
            }
            _ => None,
        }
    }

    /// Whether `x` is a texel (or a colour input) as such whose ordinary range ends at 0.
    pub(super) fn black_texel(&self, id: usize, x: Handle<E>) -> bool {
        let Some(n) = self.sound().num(id, x) else {
            return false;
        };
        n.facts.has(Facts::EXT)
            && n.facts.any(Facts::TEXTURE)
            && self
                .typical()
                .num(id, x)
                .is_some_and(|t| t.comps().iter().any(|c| c.lo == 0.0 || c.hi == 0.0))
    }

    /// Whether `x` is a per-pixel dot product that can be negative (through locals).
    fn cosine(&self, f: &Function, id: usize, x: Handle<E>) -> bool {
        let per_pixel_negative = self.sound().num(id, x).is_some_and(|n| {
            n.facts.any(Facts::INPUT.with(Facts::TEXTURE)) && n.comps().iter().any(|c| c.lo < 0.0)
        });
        if !per_pixel_negative {
            return false;
        }
        match f.expressions[x] {
            E::Math { fun: Mf::Dot, .. } => true,
            E::Load { pointer } => {
                let values = self.stored(f, id, pointer);
                !values.is_empty()
                    && values
                        .iter()
                        .all(|v| matches!(f.expressions[*v], E::Math { fun: Mf::Dot, .. }))
            }
            _ => false,
        }
    }

    /// Whether `a` (in function `caller`) is an input as such: a varying or attribute, not a
    /// uniform, through copies only.
    fn input_as_such(&self, caller: usize, a: Handle<E>) -> bool {
        self.sound().num(caller, a).is_some_and(|n| {
            n.facts.has(Facts::EXT) && n.facts.any(Facts::INPUT) && !n.facts.any(Facts::UNIFORM)
        })
    }
}

/// Whether a parameter's name is one of [`COSINES`] (case and underscores aside).
fn is_cosine_name(name: &str) -> bool {
    let n: String = name
        .chars()
        .filter(|c| *c != '_')
        .map(|c| c.to_ascii_lowercase())
        .collect();
    COSINES.contains(&n.as_str())
}
