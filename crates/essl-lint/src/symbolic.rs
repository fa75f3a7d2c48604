//! Symbolic reasoning on one function's naga expressions, where intervals lose the relation
//! between two values: `u + 0.1 > u` whatever `u` is, `max(a, b) ≥ b`.
//!
//! Values are written as linear forms over *atoms* (a uniform or input read, a parameter, or an
//! expression the forms do not look into); two forms whose difference is a constant compare
//! exactly. Locals stored once (outside loops) stand for their stored value.

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use naga::{
    BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf,
    UnaryOperator as Uo,
};

use crate::analysis::{literal, Analysis, Place, Root, ANY};

/// A value a linear form is built on.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum Atom {
    /// A variable that never changes while the shader runs (a uniform, an input).
    Place(Place),
    /// A by-value parameter.
    Arg(u32),
    /// An expression the forms do not look into.
    Expr(usize),
}

/// `Σ coefficient × atom + constant`; each atom with the expression it was first met at.
#[derive(Clone, Debug, PartialEq)]
struct Lin {
    terms: Vec<(Atom, f64)>,
    at: Vec<Handle<E>>,
    c: f64,
}

impl Lin {
    fn constant(c: f64) -> Lin {
        Lin {
            terms: Vec::new(),
            at: Vec::new(),
            c,
        }
    }

    fn atom(a: Atom, h: Handle<E>) -> Lin {
        Lin {
            terms: vec![(a, 1.0)],
            at: vec![h],
            c: 0.0,
        }
    }

    fn add(mut self, o: &Lin, k: f64) -> Lin {
        for ((a, x), h) in o.terms.iter().zip(&o.at) {
            match self.terms.iter_mut().find(|(b, _)| b == a) {
                Some((_, y)) => *y += k * x,
                None => {
                    self.terms.push((a.clone(), k * x));
                    self.at.push(*h);
                }
            }
        }
        self.drop_zeros();
        self.c += k * o.c;
        self
    }

    fn scale(mut self, k: f64) -> Lin {
        for (_, x) in &mut self.terms {
            *x *= k;
        }
        self.drop_zeros();
        self.c *= k;
        self
    }

    fn drop_zeros(&mut self) {
        let keep: Vec<bool> = self.terms.iter().map(|(_, x)| *x != 0.0).collect();
        let mut i = 0;
        self.at.retain(|_| {
            i += 1;
            keep[i - 1]
        });
        self.terms.retain(|(_, x)| *x != 0.0);
    }

    fn as_constant(&self) -> Option<f64> {
        self.terms.is_empty().then_some(self.c)
    }
}

/// Symbolic facts about the expressions of one function.
pub struct Sym<'a> {
    module: &'a naga::Module,
    f: &'a Function,
    id: usize,
    an: &'a Analysis,
    /// Private globals some user function writes (not stable across a function).
    written: &'a HashSet<usize>,
    /// The expressions standing for atoms met so far: an expression with the same value as
    /// one of them is that atom.
    seen: std::cell::RefCell<Vec<Handle<E>>>,
}

/// The operand `h` stands for: through loads of locals stored once, or whose last store on
/// every path to the load is known, and splats.
pub fn resolve(f: &Function, an: &Analysis, id: usize, mut h: Handle<E>) -> Handle<E> {
    let single: &HashMap<usize, Handle<E>> = &an.functions[id].single_store;
    for _ in 0..16 {
        match f.expressions[h] {
            E::Load { pointer } => match f.expressions[pointer] {
                E::LocalVariable(l) => match single
                    .get(&l.index())
                    .copied()
                    .or_else(|| an.reaching_store(id, h))
                {
                    Some(v) => h = v,
                    None => return h,
                },
                _ => return h,
            },
            E::Splat { value, .. } => h = value,
            _ => return h,
        }
    }
    h
}

impl<'a> Sym<'a> {
    /// The symbolic view of function `id`.
    pub fn new(
        module: &'a naga::Module,
        f: &'a Function,
        id: usize,
        an: &'a Analysis,
        written: &'a HashSet<usize>,
    ) -> Sym<'a> {
        Sym {
            module,
            f,
            id,
            an,
            written,
            seen: Default::default(),
        }
    }

    /// The atom for expression `h`: an earlier one with the same value, or `h` itself.
    fn expr_atom(&self, h: Handle<E>) -> Lin {
        let mut seen = self.seen.borrow_mut();
        let rep = match seen.iter().find(|r| self.an.same(self.f, self.id, **r, h)) {
            Some(r) => *r,
            None => {
                if seen.len() < 64 {
                    seen.push(h);
                }
                h
            }
        };
        Lin::atom(Atom::Expr(rep.index()), rep)
    }

    fn lin(&self, h: Handle<E>, depth: u32) -> Lin {
        let atom = || self.expr_atom(h);
        if depth > 12 {
            return atom();
        }
        let h = resolve(self.f, self.an, self.id, h);
        match &self.f.expressions[h] {
            E::Literal(l) => Lin::constant(literal(l)),
            E::Constant(_) => match self.an.num(self.id, h).and_then(|n| n.hull().as_point()) {
                Some(c) => Lin::constant(c),
                None => atom(),
            },
            E::Binary {
                op: Bo::Add,
                left,
                right,
            } => self
                .lin(*left, depth + 1)
                .add(&self.lin(*right, depth + 1), 1.0),
            E::Binary {
                op: Bo::Subtract,
                left,
                right,
            } => self
                .lin(*left, depth + 1)
                .add(&self.lin(*right, depth + 1), -1.0),
            E::Binary {
                op: Bo::Multiply,
                left,
                right,
            } => {
                let (a, b) = (self.lin(*left, depth + 1), self.lin(*right, depth + 1));
                match (a.as_constant(), b.as_constant()) {
                    (Some(k), _) => b.scale(k),
                    (_, Some(k)) => a.scale(k),
                    _ => self.expr_atom(h),
                }
            }
            E::Binary {
                op: Bo::Divide,
                left,
                right,
            } => {
                let (a, b) = (self.lin(*left, depth + 1), self.lin(*right, depth + 1));
                match b.as_constant() {
                    Some(k) if k != 0.0 => a.scale(1.0 / k),
                    _ => self.expr_atom(h),
                }
            }
            E::Unary {
                op: Uo::Negate,
                expr,
            } => self.lin(*expr, depth + 1).scale(-1.0),
            E::FunctionArgument(i) => Lin::atom(Atom::Arg(*i), h),
            E::Load { pointer } => match self.an.functions[self.id].places[pointer.index()].clone()
            {
                Some(p) if self.stable(&p) => Lin::atom(Atom::Place(p), h),
                _ => self.expr_atom(h),
            },
            _ => self.expr_atom(h),
        }
    }

    /// Whether a place holds the same value for a whole run of the shader.
    fn stable(&self, p: &Place) -> bool {
        if p.path.contains(&ANY) {
            return false;
        }
        match p.root {
            Root::Global(g) => {
                let h = self
                    .module
                    .global_variables
                    .iter()
                    .nth(g)
                    .map(|(h, _)| h)
                    .expect("global");
                self.module.global_variables[h].space != naga::AddressSpace::Private
                    || !self.written.contains(&g)
            }
            _ => false,
        }
    }

    /// A lower bound of `a - b` (`None` standing for 0), in exact arithmetic.
    pub fn diff_lower(&self, a: Option<Handle<E>>, b: Option<Handle<E>>) -> f64 {
        self.diff_lower_d(a, b, 0)
    }

    fn hull(&self, h: Option<Handle<E>>) -> crate::interval::Interval {
        match h {
            Some(h) => self
                .an
                .num(self.id, h)
                .map(|n| n.hull())
                .unwrap_or(crate::interval::Interval::FULL),
            None => crate::interval::Interval::point(0.0),
        }
    }

    /// A lower bound of a linear form from the ranges of its atoms.
    fn form_lower(&self, form: &Lin) -> f64 {
        let mut lo = form.c;
        for ((_, k), h) in form.terms.iter().zip(&form.at) {
            let Some(i) = self
                .an
                .num(self.id, *h)
                .filter(|n| n.n == 1)
                .map(|n| n.c[0])
            else {
                return f64::NEG_INFINITY;
            };
            lo += if *k > 0.0 { k * i.lo } else { k * i.hi };
        }
        if lo.is_nan() {
            f64::NEG_INFINITY
        } else {
            lo
        }
    }

    fn diff_lower_d(&self, a: Option<Handle<E>>, b: Option<Handle<E>>, depth: u32) -> f64 {
        let (ia, ib) = (self.hull(a), self.hull(b));
        let mut best = if ia.is_empty() || ib.is_empty() {
            f64::NEG_INFINITY
        } else {
            ia.lo - ib.hi
        };
        let la = a.map(|h| self.lin(h, 0)).unwrap_or(Lin::constant(0.0));
        let lb = b.map(|h| self.lin(h, 0)).unwrap_or(Lin::constant(0.0));
        let form = la.add(&lb, -1.0);
        match form.as_constant() {
            Some(c) => best = best.max(c),
            None => best = best.max(self.form_lower(&form)),
        }
        if depth >= 4 {
            return best;
        }
        let d = depth + 1;
        // A scalar constant added to or taken from either side moves the bound by it:
        // `clamp(t, 0.0, 1.0) + 1e-3` over `clamp(t - 0.3, 0.0, 1.0)` is 1e-3 more than the clamps'.
        let shifted = |h: Handle<E>| -> Option<(Handle<E>, f64)> {
            let constant = |x: Handle<E>| {
                self.an
                    .num(self.id, x)
                    .filter(|n| n.n == 1)
                    .and_then(|n| n.c[0].as_point())
            };
            match self.f.expressions[resolve(self.f, self.an, self.id, h)] {
                E::Binary {
                    op: Bo::Add,
                    left,
                    right,
                } => constant(right)
                    .map(|c| (left, c))
                    .or_else(|| constant(left).map(|c| (right, c))),
                E::Binary {
                    op: Bo::Subtract,
                    left,
                    right,
                } => constant(right).map(|c| (left, -c)),
                _ => None,
            }
        };
        if let Some((x, c)) = a.and_then(shifted) {
            best = best.max(c + self.diff_lower_d(Some(x), b, d));
        }
        if let Some((y, c)) = b.and_then(shifted) {
            best = best.max(self.diff_lower_d(a, Some(y), d) - c);
        }
        // clamp is monotone and moves no value further: clamp(x, lo, hi) - clamp(y, lo, hi) is
        // at least min(x - y, 0) — ordered, not apart, where both saturate.
        if let (Some(a), Some(b)) = (a, b) {
            let clamp =
                |h: Handle<E>| match self.f.expressions[resolve(self.f, self.an, self.id, h)] {
                    E::Math {
                        fun: Mf::Clamp,
                        arg,
                        arg1: Some(lo),
                        arg2: Some(hi),
                        ..
                    } => Some((arg, lo, hi)),
                    _ => None,
                };
            if let (Some((x, lo, hi)), Some((y, lo2, hi2))) = (clamp(a), clamp(b)) {
                if self.an.same(self.f, self.id, lo, lo2) && self.an.same(self.f, self.id, hi, hi2)
                {
                    best = best.max(self.diff_lower_d(Some(x), Some(y), d).min(0.0));
                }
            }
        }
        if let Some(a) = a {
            best = best.max(self.diff_lower_left(a, b, d));
        }
        if let Some(b) = b {
            best = best.max(self.diff_lower_right(a, b, d));
        }
        best
    }

    /// [`Self::diff_lower_d`]'s cases on the left operand's shape: `max`, `min`, `clamp`, and a
    /// subtraction standing alone.
    fn diff_lower_left(&self, a: Handle<E>, b: Option<Handle<E>>, d: u32) -> f64 {
        let mut best = f64::NEG_INFINITY;
        let ra = resolve(self.f, self.an, self.id, a);
        match self.f.expressions[ra] {
            E::Math {
                fun: Mf::Max,
                arg,
                arg1: Some(y),
                ..
            } => {
                best = best.max(self.diff_lower_d(Some(arg), b, d).max(self.diff_lower_d(
                    Some(y),
                    b,
                    d,
                )));
            }
            // clamp(x, lo, hi) = min(max(x, lo), hi): at least min(max(x, lo), hi).
            E::Math {
                fun: Mf::Clamp,
                arg: x,
                arg1: Some(lo),
                arg2: Some(hi),
                ..
            } => {
                let low = self
                    .diff_lower_d(Some(x), b, d)
                    .max(self.diff_lower_d(Some(lo), b, d));
                best = best.max(low.min(self.diff_lower_d(Some(hi), b, d)));
            }
            E::Math {
                fun: Mf::Min,
                arg,
                arg1: Some(y),
                ..
            } => {
                best = best.max(self.diff_lower_d(Some(arg), b, d).min(self.diff_lower_d(
                    Some(y),
                    b,
                    d,
                )));
            }
            E::Binary {
                op: Bo::Subtract,
                left,
                right,
            } if b.is_none() => {
                best = best.max(self.diff_lower_d(Some(left), Some(right), d));
            }
            _ => {}
        }
        best
    }

    /// [`Self::diff_lower_d`]'s cases on the right operand's shape: `min`, `max`, `clamp`, and
    /// a subtraction standing alone.
    fn diff_lower_right(&self, a: Option<Handle<E>>, b: Handle<E>, d: u32) -> f64 {
        let mut best = f64::NEG_INFINITY;
        let rb = resolve(self.f, self.an, self.id, b);
        match self.f.expressions[rb] {
            E::Math {
                fun: Mf::Min,
                arg,
                arg1: Some(y),
                ..
            } => {
                best = best.max(self.diff_lower_d(a, Some(arg), d).max(self.diff_lower_d(
                    a,
                    Some(y),
                    d,
                )));
            }
            // a - clamp(y, lo, hi) = max(a - max(y, lo), a - hi).
            E::Math {
                fun: Mf::Clamp,
                arg: y,
                arg1: Some(lo),
                arg2: Some(hi),
                ..
            } => {
                let under = self
                    .diff_lower_d(a, Some(y), d)
                    .min(self.diff_lower_d(a, Some(lo), d));
                best = best.max(under.max(self.diff_lower_d(a, Some(hi), d)));
            }
            E::Math {
                fun: Mf::Max,
                arg,
                arg1: Some(y),
                ..
            } => {
                best = best.max(self.diff_lower_d(a, Some(arg), d).min(self.diff_lower_d(
                    a,
                    Some(y),
                    d,
                )));
            }
            E::Binary {
                op: Bo::Subtract,
                left,
                right,
            } if a.is_none() => {
                best = best.max(self.diff_lower_d(Some(right), Some(left), d));
            }
            _ => {}
        }
        best
    }

    /// `a - b` as `c + k × x` when it is one: the constant `c`, the factor `k` and the
    /// expression `x` (a uniform or input read, a parameter, or an expression the forms do not
    /// look into).
    pub fn single_term(&self, a: Handle<E>, b: Handle<E>) -> Option<(f64, f64, Handle<E>)> {
        let d = self.lin(a, 0).add(&self.lin(b, 0), -1.0);
        match (&d.terms[..], &d.at[..]) {
            ([(_, k)], [x]) => Some((d.c, *k, *x)),
            _ => None,
        }
    }

    /// `h` as a linear form: each atom (by the first expression met for it) with its
    /// coefficient, and the constant.
    pub fn terms(&self, h: Handle<E>) -> (Vec<(Handle<E>, f64)>, f64) {
        let l = self.lin(h, 0);
        let terms = l.at.into_iter().zip(l.terms.into_iter().map(|(_, k)| k));
        (terms.collect(), l.c)
    }

    /// Whether `h` is certainly not zero (a scalar, or every component of a vector).
    pub fn nonzero(&self, h: Handle<E>) -> bool {
        self.diff_lower(Some(h), None) > 0.0 || self.diff_lower(None, Some(h)) > 0.0
    }
}
