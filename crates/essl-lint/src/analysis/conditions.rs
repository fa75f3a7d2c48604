//! What conditions say: the bounds a comparison that holds (or fails) puts on the values it
//! compares (`x > 0.0`, `abs(y) <= c`, `dot(v, v) > 1e-12`), through `!`, `&&` and `||`, and
//! the places whose loads an enclosing `if` bounds.

use naga::{
    BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf, Statement,
    UnaryOperator as Uo,
};

use super::statements::writes;
use super::{Analysis, Place, Site, ANY};
use crate::interval::Interval;
use crate::value::{Num, Val};

impl Analysis {
    /// What `condition` being `polarity` says about places that `region` (statements) does not
    /// write: `x > 0.0` bounds the loads of `x` there, `dot(v, v) > 0.0` the length of `v`.
    pub(super) fn refinements(
        &self,
        s: Site,
        condition: Handle<E>,
        polarity: bool,
        region: &[&[&Statement]],
    ) -> Vec<(Place, Refinement)> {
        let (module, f, id) = (s.module, s.f, s.id);
        let mut out = Vec::new();
        for (subject, r) in self.conditions(f, id, condition, polarity) {
            let E::Load { pointer } = f.expressions[subject] else {
                continue;
            };
            let Some(place) = self.functions[id].places[pointer.index()].clone() else {
                continue;
            };
            if place.path.contains(&ANY)
                || region
                    .iter()
                    .any(|stmts| writes(module, f, stmts, place.root))
            {
                continue;
            }
            out.push((place, r));
        }
        out
    }

    /// What `condition` being `polarity` says about the expressions it compares.
    pub fn conditions(
        &self,
        f: &Function,
        id: usize,
        condition: Handle<E>,
        polarity: bool,
    ) -> Vec<(Handle<E>, Refinement)> {
        let mut out = Vec::new();
        self.collect_conditions(f, id, condition, polarity, &mut out);
        out
    }

    fn collect_conditions(
        &self,
        f: &Function,
        id: usize,
        c: Handle<E>,
        polarity: bool,
        out: &mut Vec<(Handle<E>, Refinement)>,
    ) {
        condition_atoms(f, c, polarity, &mut |atom, polarity| {
            self.atom_refinements(f, id, atom, polarity, out)
        });
    }

    /// The refinements one comparison implies when it holds (`polarity`) or fails.
    fn atom_refinements(
        &self,
        f: &Function,
        id: usize,
        c: Handle<E>,
        polarity: bool,
        out: &mut Vec<(Handle<E>, Refinement)>,
    ) {
        let E::Binary { op, left, right } = f.expressions[c] else {
            return;
        };
        for (x, bound, x_left) in [(left, right, true), (right, left, false)] {
            let Some(b) = self.nm(id, bound).filter(|n| n.n == 1) else {
                continue;
            };
            let Some(i) = relation(op, polarity, x_left, b.c[0]) else {
                continue;
            };
            if self.nm(id, x).is_some_and(|n| n.n == 1) {
                out.push((x, Refinement::Value(i)));
            }
            // `length(v) > c`, `dot(v, v) > c`: a bound on the length of `v`;
            // `abs(y) <= c`: a bound on `y`.
            match f.expressions[x] {
                E::Math {
                    fun: Mf::Abs, arg, ..
                } if i.hi.is_finite() && self.nm(id, arg).is_some_and(|n| n.n == 1) => {
                    out.push((
                        arg,
                        Refinement::Value(Interval {
                            lo: -i.hi,
                            hi: i.hi,
                        }),
                    ));
                }
                E::Math {
                    fun: Mf::Length,
                    arg,
                    ..
                } => out.push((arg, Refinement::Norm(i.meet(Interval::NON_NEGATIVE)))),
                E::Math {
                    fun: Mf::Dot,
                    arg,
                    arg1: Some(b2),
                    ..
                } if self.same(f, id, arg, b2) => {
                    let sq = i.meet(Interval::NON_NEGATIVE);
                    if !sq.is_empty() {
                        out.push((
                            arg,
                            Refinement::Norm(Interval {
                                lo: sq.lo.sqrt(),
                                hi: sq.hi.sqrt(),
                            }),
                        ));
                    }
                }
                _ => {}
            }
        }
    }

    /// The refinement of a load of `place`, if an enclosing condition bounds it.
    /// (An `integer` value bounded by `count > 0` is at least 1.)
    pub(super) fn refined(&self, place: &Place, v: Val, integer: bool) -> Val {
        let Val::Num(n) = v else { return v };
        let rs: Vec<Refinement> = self
            .refine
            .iter()
            .filter(|(p, _)| p == place)
            .map(|(_, r)| *r)
            .collect();
        let r = refine_num(n, &rs);
        Val::Num(if integer { integral(r) } else { r })
    }
}

/// Calls `visit(atom, polarity)` for each comparison a condition implies when it holds
/// (`polarity`) or when it fails (`!polarity`): through `!`, through `&&` when it holds and
/// through `||` when it fails (a bounded depth: conditions are small).
pub(crate) fn condition_atoms(
    f: &Function,
    c: Handle<E>,
    polarity: bool,
    visit: &mut dyn FnMut(Handle<E>, bool),
) {
    fn walk(
        f: &Function,
        c: Handle<E>,
        polarity: bool,
        visit: &mut dyn FnMut(Handle<E>, bool),
        depth: u32,
    ) {
        if depth > 8 {
            return;
        }
        match f.expressions[c] {
            E::Unary {
                op: Uo::LogicalNot,
                expr,
            } => walk(f, expr, !polarity, visit, depth + 1),
            E::Binary {
                op: Bo::LogicalAnd,
                left,
                right,
            } if polarity => {
                walk(f, left, true, visit, depth + 1);
                walk(f, right, true, visit, depth + 1);
            }
            E::Binary {
                op: Bo::LogicalOr,
                left,
                right,
            } if !polarity => {
                walk(f, left, false, visit, depth + 1);
                walk(f, right, false, visit, depth + 1);
            }
            _ => visit(c, polarity),
        }
    }
    walk(f, c, polarity, visit, 0);
}

/// The values `x` can have when `x OP bound` is `polarity` (`x_left`: `x` is the left operand);
/// NaN aside.
pub fn relation(op: Bo, polarity: bool, x_left: bool, bound: Interval) -> Option<Interval> {
    if bound.is_empty() {
        return None;
    }
    let mirrored = if x_left {
        op
    } else {
        match op {
            Bo::Less => Bo::Greater,
            Bo::LessEqual => Bo::GreaterEqual,
            Bo::Greater => Bo::Less,
            Bo::GreaterEqual => Bo::LessEqual,
            other => other,
        }
    };
    let op = if polarity {
        mirrored
    } else {
        match mirrored {
            Bo::Less => Bo::GreaterEqual,
            Bo::LessEqual => Bo::Greater,
            Bo::Greater => Bo::LessEqual,
            Bo::GreaterEqual => Bo::Less,
            Bo::Equal => Bo::NotEqual,
            Bo::NotEqual => Bo::Equal,
            other => other,
        }
    };
    match op {
        Bo::Greater => Some(Interval::above(bound.lo)),
        Bo::GreaterEqual => Some(Interval {
            lo: bound.lo,
            hi: f64::INFINITY,
        }),
        Bo::Less => Some(Interval::below(bound.hi)),
        Bo::LessEqual => Some(Interval {
            lo: f64::NEG_INFINITY,
            hi: bound.hi,
        }),
        Bo::Equal => Some(bound),
        _ => None,
    }
}

/// What a condition says about a value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Refinement {
    /// A scalar is in this interval.
    Value(Interval),
    /// A vector's length is in this interval.
    Norm(Interval),
}

/// An integer value's bounds rounded inwards to integers: a strict bound (`count > 0`, kept as
/// the next float above 0) becomes the next integer.
pub fn integral(mut n: Num) -> Num {
    if n.is_bottom() {
        return n;
    }
    for c in &mut n.c[..n.n as usize] {
        *c = Interval {
            lo: c.lo.ceil(),
            hi: c.hi.floor(),
        };
    }
    if n.comps().iter().any(|c| c.lo > c.hi) {
        return Num::bottom(n.n);
    }
    n.norm = if n.n == 1 {
        n.c[0].abs()
    } else {
        crate::value::norm_of(n.comps())
    };
    n.settle()
}

/// `n` where the refinements hold (no value when they cannot: the guarded code does not run).
pub fn refine_num(mut n: Num, rs: &[Refinement]) -> Num {
    if n.is_bottom() || rs.is_empty() {
        return n;
    }
    for r in rs {
        match *r {
            Refinement::Value(i) if n.n == 1 => {
                n.c[0] = n.c[0].meet(i);
                n.norm = n.c[0].abs();
            }
            Refinement::Norm(i) => n.norm = n.norm.meet(i),
            _ => {}
        }
    }
    if n.c[0].is_empty() || n.norm.is_empty() {
        return Num::bottom(n.n);
    }
    n.settle()
}
