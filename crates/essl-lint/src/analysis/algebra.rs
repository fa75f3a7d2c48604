//! Signs that intervals lose in polynomial shapes, because they take each occurrence of a
//! variable as independent of the others:
//!
//! - a product holding a square, `m * x * x` with `m ≥ 0` (an SDF's `m2 * (q.x + s) * (q.x +
//!   s)`), and `(x - y * x) * x = x² (1 - y)` with `y ≤ 1` (the correlated Smith visibility
//!   term, `(NoV - a2 * NoV) * NoV + a2`);
//! - a completed square: `x² + r - k x y ≥ r - k² y² / 4`, so Henyey–Greenstein's
//!   `1 + g² - 2 g μ` is not negative for `|μ| ≤ 1` whatever `g` is;
//! - a difference `c - k y` with `c ≥ |k|` and `|y| ≤ 1` (the same phase function with a
//!   constant `g`).
//!
//! The bounds on `y` are the facts' (`Facts::UNIT`: within `[-1, 1]` whenever the external
//! values are), so what these shapes prove holds whenever the external values are ordinary, as
//! every fact does.

use naga::{BinaryOperator as Bo, Expression as E, Handle, UnaryOperator as Uo};

use super::{Analysis, Site};
use crate::symbolic::resolve;
use crate::value::Facts;

/// How many factors or terms a product or a sum is flattened into.
const MAX_PARTS: usize = 8;

impl Analysis {
    /// A bound on the magnitude of `h` whenever the external values are ordinary: its interval's,
    /// 1 for a value with [`Facts::UNIT`], and the product of its factors' for a product.
    pub(super) fn unit_mag(&self, s: Site, h: Handle<E>, depth: u32) -> Option<f64> {
        let v = self.nm(s.id, h)?;
        let hull = v.hull();
        let mut m = if hull.is_bounded() {
            hull.mag()
        } else {
            f64::INFINITY
        };
        if v.facts.has(Facts::UNIT) {
            m = m.min(1.0);
        }
        if m.is_finite() {
            return Some(m);
        }
        if depth > 4 {
            return None;
        }
        match s.f.expressions[resolve(s.f, self, s.id, h)] {
            E::Binary {
                op: Bo::Multiply,
                left,
                right,
            } => Some(self.unit_mag(s, left, depth + 1)? * self.unit_mag(s, right, depth + 1)?),
            E::Unary {
                op: Uo::Negate,
                expr,
            } => self.unit_mag(s, expr, depth + 1),
            _ => None,
        }
    }

    /// Whether `l * r` holds a square whose cofactor is not negative: `(m * x) * x` with `m ≥
    /// 0`, or `(x - y * x) * x` with `y ≤ 1` (either operand order).
    pub(super) fn holds_square(&self, s: Site, l: Handle<E>, r: Handle<E>) -> bool {
        let same = |a: Handle<E>, b: Handle<E>| self.same(s.f, s.id, a, b);
        let nn = |h: Handle<E>| self.nm(s.id, h).is_some_and(|v| v.facts.has(Facts::NN));
        let at_most_one = |h: Handle<E>| {
            self.nm(s.id, h)
                .is_some_and(|v| v.facts.has(Facts::UNIT) || v.hull().hi <= 1.0)
        };
        let product = |h: Handle<E>| match s.f.expressions[resolve(s.f, self, s.id, h)] {
            E::Binary {
                op: Bo::Multiply,
                left,
                right,
            } => Some((left, right)),
            _ => None,
        };
        [(l, r), (r, l)].into_iter().any(|(p, x)| {
            match s.f.expressions[resolve(s.f, self, s.id, p)] {
                E::Binary {
                    op: Bo::Multiply,
                    left,
                    right,
                } => (same(left, x) && nn(right)) || (same(right, x) && nn(left)),
                E::Binary {
                    op: Bo::Subtract,
                    left,
                    right,
                } if same(left, x) => product(right).is_some_and(|(a, b)| {
                    (same(a, x) && at_most_one(b)) || (same(b, x) && at_most_one(a))
                }),
                _ => false,
            }
        })
    }

    /// Whether `l - r` is not negative as a completed square: `l` a sum holding `x * x`, `r` a
    /// product holding `x`, and the other terms of `l` at least `k² / 4` where `k` bounds the
    /// magnitude of the other factors of `r` ([`Analysis::unit_mag`]).
    pub(super) fn completes_square(&self, s: Site, l: Handle<E>, r: Handle<E>) -> bool {
        let terms = self.flatten(s, l, Bo::Add);
        let factors = self.flatten(s, r, Bo::Multiply);
        if terms.len() < 2 || factors.len() < 2 {
            return false;
        }
        let same = |a: Handle<E>, b: Handle<E>| self.same(s.f, s.id, a, b);
        for (ti, &t) in terms.iter().enumerate() {
            let E::Binary {
                op: Bo::Multiply,
                left: x,
                right: x2,
            } = s.f.expressions[resolve(s.f, self, s.id, t)]
            else {
                continue;
            };
            if !same(x, x2) {
                continue;
            }
            let Some(fi) = factors.iter().position(|&f| same(f, x)) else {
                continue;
            };
            let k: Option<f64> = factors
                .iter()
                .enumerate()
                .filter(|&(i, _)| i != fi)
                .map(|(_, &f)| self.unit_mag(s, f, 0))
                .product();
            let rest: Option<f64> = terms
                .iter()
                .enumerate()
                .filter(|&(i, _)| i != ti)
                .map(|(_, &t)| {
                    let v = self.nm(s.id, t)?;
                    let lo = v.hull().lo;
                    Some(if v.facts.has(Facts::NN) {
                        lo.max(0.0)
                    } else {
                        lo
                    })
                })
                .sum();
            if let (Some(k), Some(rest)) = (k, rest) {
                if rest >= k * k / 4.0 {
                    return true;
                }
            }
        }
        false
    }

    /// The operands of the tree of `op` (`Add` or `Multiply`) rooted at `h`, at most
    /// [`MAX_PARTS`].
    fn flatten(&self, s: Site, h: Handle<E>, op: Bo) -> Vec<Handle<E>> {
        let mut out = Vec::new();
        let mut stack = vec![h];
        while let Some(x) = stack.pop() {
            if out.len() + stack.len() >= MAX_PARTS {
                out.push(x);
                continue;
            }
            match s.f.expressions[resolve(s.f, self, s.id, x)] {
                E::Binary { op: o, left, right } if o == op => {
                    stack.push(right);
                    stack.push(left);
                }
                _ => out.push(x),
            }
        }
        out
    }
}
