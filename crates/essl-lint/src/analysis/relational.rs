//! Relations between values that intervals lose, in two shapes tone mappers use (Khronos PBR
//! Neutral, three.js's `NeutralToneMapping`):
//!
//! - subtracting at most the smallest component of a non-negative vector keeps it
//!   non-negative: `color -= offset` with `x = min(color.r, min(color.g, color.b))` and
//!   `offset = x < 0.08 ? x - 6.25 * x * x : 0.04` (each branch at most `x` where it is taken);
//! - a function of one variable whose derivative keeps one sign on the variable's range lies
//!   between its values at the range's ends: `1 - 1 / (k * (p - q(p)) + 1)` with
//!   `q(p) = 1 - d * d / (p + d - s)` is not negative for `p ≥ s`, although intervals, which
//!   take `p` and `q(p)` as independent, give it a negative lower bound.

use naga::{
    BinaryOperator as Bo, Expression as E, Handle, MathFunction as Mf, UnaryOperator as Uo,
};

use super::conditions::{condition_atoms, relation};
use super::{Analysis, Site};
use crate::interval::Interval;
use crate::symbolic::resolve;
use crate::value::Facts;

/// How deep the shapes are followed.
const DEPTH: u32 = 8;

impl Analysis {
    /// Whether scalar `b` is at most every component of vector `a`, a non-negative value.
    pub(super) fn at_most_smallest(&self, s: Site, b: Handle<E>, a: Handle<E>) -> bool {
        self.at_most(s, b, a, None, 0)
    }

    fn at_most(
        &self,
        s: Site,
        b: Handle<E>,
        a: Handle<E>,
        guard: Option<(Handle<E>, bool)>,
        depth: u32,
    ) -> bool {
        if depth > DEPTH {
            return false;
        }
        let f = s.f;
        let rb = resolve(f, self, s.id, b);
        if self.is_smallest(s, rb, a) {
            return true;
        }
        match f.expressions[rb] {
            E::Select {
                condition,
                accept,
                reject,
            } => {
                self.at_most(s, accept, a, Some((condition, true)), depth + 1)
                    && self.at_most(s, reject, a, Some((condition, false)), depth + 1)
            }
            E::Binary {
                op: Bo::Subtract,
                left,
                right,
            } => {
                self.at_most(s, left, a, guard, depth + 1)
                    && self.nm(s.id, right).is_some_and(|n| n.facts.has(Facts::NN))
            }
            _ => {
                let Some(c) = self.nm(s.id, rb).and_then(|n| n.hull().as_point()) else {
                    return false;
                };
                c <= 0.0 || guard.is_some_and(|(g, pol)| self.smallest_at_least(s, a, g, pol, c))
            }
        }
    }

    /// Whether condition `g` being `pol` keeps the smallest component of `a` at least `c`.
    fn smallest_at_least(&self, s: Site, a: Handle<E>, g: Handle<E>, pol: bool, c: f64) -> bool {
        let f = s.f;
        let mut ok = false;
        condition_atoms(f, g, pol, &mut |atom, p| {
            let E::Binary { op, left, right } = f.expressions[atom] else {
                return;
            };
            for (x, bound, x_left) in [(left, right, true), (right, left, false)] {
                if !self.is_smallest(s, resolve(f, self, s.id, x), a) {
                    continue;
                }
                let Some(b) = self.nm(s.id, bound).filter(|n| n.n == 1) else {
                    continue;
                };
                if relation(op, p, x_left, b.c[0]).is_some_and(|r| r.lo >= c) {
                    ok = true;
                }
            }
        });
        ok
    }

    /// Whether `x` is the smallest component of `a`: nested `min`s of all of them.
    fn is_smallest(&self, s: Site, x: Handle<E>, a: Handle<E>) -> bool {
        let Some(n) = self
            .nm(s.id, a)
            .filter(|v| v.facts.has(Facts::NN))
            .map(|v| v.n)
        else {
            return false;
        };
        let mut seen = [false; 4];
        n > 1 && self.min_of(s, x, a, &mut seen, 0) && seen[..n as usize].iter().all(|b| *b)
    }

    fn min_of(
        &self,
        s: Site,
        x: Handle<E>,
        a: Handle<E>,
        seen: &mut [bool; 4],
        depth: u32,
    ) -> bool {
        if depth > DEPTH {
            return false;
        }
        match s.f.expressions[resolve(s.f, self, s.id, x)] {
            E::Math {
                fun: Mf::Min,
                arg,
                arg1: Some(y),
                ..
            } => self.min_of(s, arg, a, seen, depth + 1) && self.min_of(s, y, a, seen, depth + 1),
            E::AccessIndex { base, index } if index < 4 && self.same(s.f, s.id, base, a) => {
                seen[index as usize] = true;
                true
            }
            _ => false,
        }
    }

    /// The range of scalar `t` as a function of the one variable it is computed from (through
    /// constants, locals stored once and arithmetic), where its derivative keeps one sign on
    /// that variable's range: between its values at the ends. A derivative that is negative by
    /// a rounding error only next to the lower end (`q'(s) = 1` where `p - q(p)` touches 0) is
    /// bounded on a short first piece by the mean value theorem. `None` otherwise.
    pub(super) fn monotone_range(&self, s: Site, t: Handle<E>) -> Option<Interval> {
        let mut var = None;
        self.dual(s, t, &mut var, Interval::FULL, 0)?;
        let v = var?;
        let range = self.nm(s.id, v)?.c[0];
        let eval = |x: Interval| self.dual(s, t, &mut Some(v), x, 0);
        let (value, slope) = eval(range)?;
        let at = |x: f64| x.is_finite().then(|| eval(Interval::point(x))).flatten();
        if slope.hi <= 0.0 {
            let lo = at(range.hi).map_or(value.lo, |e| e.0.lo);
            let hi = at(range.lo).map_or(value.hi, |e| e.0.hi);
            return Some(Interval::new(lo, hi).meet(value));
        }
        let hi = at(range.hi).map_or(value.hi, |e| e.0.hi);
        let lo = if slope.lo >= 0.0 {
            at(range.lo)?.0.lo
        } else {
            // A first piece [lo, lo + step] where the slope may dip below 0 by rounding, then
            // a rest where it must not.
            let step = 1e-3 * range.lo.abs().max(1.0);
            let split = range.lo + step;
            let (_, first) = eval(Interval::new(range.lo, split))?;
            let (_, rest) = eval(Interval::new(split, range.hi))?;
            if rest.lo < 0.0 || first.lo < -1e-6 {
                return None;
            }
            at(range.lo)?.0.lo + first.lo.min(0.0) * step
        };
        Some(Interval::new(lo, hi).meet(value))
    }

    /// `t` and its derivative with respect to `var` (the first non-constant leaf found, when
    /// `var` is `None`) for `var` in `x`; `None` for another leaf or an operation left out.
    fn dual(
        &self,
        s: Site,
        t: Handle<E>,
        var: &mut Option<Handle<E>>,
        x: Interval,
        depth: u32,
    ) -> Option<(Interval, Interval)> {
        if depth > DEPTH * 2 {
            return None;
        }
        let r = self.arithmetic(s, t);
        let n = self.nm(s.id, r).filter(|n| n.n == 1)?;
        if let Some(p) = n.c[0].as_point() {
            return Some((Interval::point(p), Interval::point(0.0)));
        }
        match s.f.expressions[r] {
            E::Binary { op, left, right } => {
                let (a, da) = self.dual(s, left, var, x, depth + 1)?;
                let (b, db) = self.dual(s, right, var, x, depth + 1)?;
                Some(match op {
                    Bo::Add => (a.add(b), da.add(db)),
                    Bo::Subtract => (a.sub(b), da.sub(db)),
                    Bo::Multiply => (a.mul(b), da.mul(b).add(a.mul(db))),
                    Bo::Divide => (a.div(b), da.mul(b).sub(a.mul(db)).div(b.sqr())),
                    _ => return None,
                })
            }
            E::Unary {
                op: Uo::Negate,
                expr,
            } => self
                .dual(s, expr, var, x, depth + 1)
                .map(|(a, da)| (a.neg(), da.neg())),
            // Anything else is the variable (a load keeps what the guards say of it).
            _ => match *var {
                None => {
                    *var = Some(r);
                    Some((x, Interval::point(1.0)))
                }
                Some(v) if self.same(s.f, s.id, v, r) => Some((x, Interval::point(1.0))),
                Some(_) => None,
            },
        }
    }

    /// `t` through splats and loads of locals stored once whose value is arithmetic or a
    /// constant; a load of one holding anything else stays a load.
    fn arithmetic(&self, s: Site, mut t: Handle<E>) -> Handle<E> {
        for _ in 0..16 {
            match s.f.expressions[t] {
                E::Splat { value, .. } => t = value,
                E::Load { .. } => {
                    let r = resolve(s.f, self, s.id, t);
                    let through = matches!(
                        s.f.expressions[r],
                        E::Binary { .. } | E::Unary { .. } | E::Literal(_) | E::Constant(_)
                    );
                    if !through || r == t {
                        return t;
                    }
                    t = r;
                }
                _ => return t,
            }
        }
        t
    }
}
