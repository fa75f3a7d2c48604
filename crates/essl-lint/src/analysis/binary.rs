//! The binary operators: comparisons and logic, the arithmetic of scalars and vectors (with
//! the facts each operation keeps: sign, non-zero, unit range, length), and the products and
//! sums of matrices.

use naga::{BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf};
use naga::{ScalarKind, TypeInner};

use super::memory::shape;
use super::{Analysis, Mode, Site, EPS};
use crate::interval::Interval;
use crate::value::{Facts, Num, Val};

/// The operands of an arithmetic operator on scalars and vectors: the expressions and their
/// numbers.
struct Operands<'a> {
    op: Bo,
    /// The left and right expressions.
    l: Handle<E>,
    r: Handle<E>,
    /// Their numbers.
    a: &'a Num,
    b: &'a Num,
    /// Where the operands come from.
    deps: Facts,
    /// Whether the result is an integer.
    is_int: bool,
}

impl Operands<'_> {
    /// Whether both operands are integers ([`Facts::INTEGRAL`]).
    fn integral(&self) -> bool {
        self.a.facts.has(Facts::INTEGRAL) && self.b.facts.has(Facts::INTEGRAL)
    }
}

impl Operands<'_> {
    /// Whether the result is a vector.
    fn vector_result(&self) -> bool {
        self.a.n.max(self.b.n) > 1
    }

    /// Whether a scalar meets a vector.
    fn mixed(&self) -> bool {
        (self.a.n == 1) != (self.b.n == 1)
    }
}

impl Analysis {
    /// Whether `e` is `x - y * floor(x / y)`: GLSL's `mod` as essl lowers it.
    fn is_mod(f: &Function, left: Handle<E>, right: Handle<E>) -> Option<Handle<E>> {
        let E::Binary {
            op: Bo::Multiply,
            left: y,
            right: fl,
        } = f.expressions[right]
        else {
            return None;
        };
        let E::Math {
            fun: Mf::Floor,
            arg: q,
            ..
        } = f.expressions[fl]
        else {
            return None;
        };
        let E::Binary {
            op: Bo::Divide,
            left: x2,
            right: y2,
        } = f.expressions[q]
        else {
            return None;
        };
        (x2 == left && y2 == y).then_some(y)
    }

    /// The modulus `k` of `x - floor(x * c) * k` with `c = 1 / k` (`mod289` of noise
    /// functions, `x - floor(x * (1.0 / 289.0)) * 289.0`): `mod(x, k)` written out.
    fn reciprocal_mod(&self, s: Site, left: Handle<E>, right: Handle<E>) -> Option<Num> {
        let product = |h: Handle<E>| match s.f.expressions[h] {
            E::Binary {
                op: Bo::Multiply,
                left,
                right,
            } => Some((left, right)),
            _ => None,
        };
        let point = |h: Handle<E>| self.nm(s.id, h).and_then(|v| v.hull().as_point());
        let (p, q) = product(right)?;
        let (fl, k) = [(p, q), (q, p)]
            .into_iter()
            .find(|&(fl, _)| matches!(s.f.expressions[fl], E::Math { fun: Mf::Floor, .. }))?;
        let E::Math { arg, .. } = s.f.expressions[fl] else {
            return None;
        };
        let (u, v) = product(arg)?;
        let c = [(u, v), (v, u)]
            .into_iter()
            .find(|&(x, _)| self.same(s.f, s.id, x, left))
            .and_then(|(_, c)| point(c))?;
        let kv = self.nm(s.id, k)?;
        let kk = kv.hull().as_point()?;
        ((c * kk - 1.0).abs() <= 1e-6).then_some(kv)
    }

    /// `l OP r`.
    pub(super) fn binary(
        &self,
        s: Site,
        ty: &TypeInner,
        op: Bo,
        l: Handle<E>,
        r: Handle<E>,
    ) -> Val {
        let (module, id) = (s.module, s.id);
        let (lv, rv) = (self.v(id, l), self.v(id, r));
        if lv.is_bot() || rv.is_bot() {
            return Val::Bot;
        }
        let deps = lv.facts().with(rv.facts()).only(Facts::DEPS);
        match op {
            Bo::Equal
            | Bo::NotEqual
            | Bo::Less
            | Bo::LessEqual
            | Bo::Greater
            | Bo::GreaterEqual
            | Bo::LogicalAnd
            | Bo::LogicalOr => {
                return shape(module, ty, &|n, _| Num::splat(Interval::UNIT, n, deps));
            }
            Bo::And | Bo::ShiftRight => {
                return match (&lv, &rv) {
                    (Val::Num(a), Val::Num(b)) => Val::Num(bits(op, a, b, deps)),
                    _ => Self::unknown(module, ty, deps),
                };
            }
            Bo::InclusiveOr | Bo::ExclusiveOr | Bo::ShiftLeft => {
                return Self::unknown(module, ty, deps);
            }
            _ => {}
        }
        let unknown = || Self::unknown(module, ty, deps);
        match (lv, rv) {
            (Val::Num(a), Val::Num(b)) => {
                let o = Operands {
                    op,
                    l,
                    r,
                    a,
                    b,
                    deps,
                    is_int: matches!(ty.scalar_kind(), Some(ScalarKind::Sint | ScalarKind::Uint)),
                };
                Val::Num(self.num_binary(s, &o))
            }
            (Val::Agg(m), Val::Num(v)) if op == Bo::Multiply && v.n > 1 => {
                matrix_times_vector(m, v, deps).unwrap_or_else(unknown)
            }
            (Val::Num(v), Val::Agg(m)) if op == Bo::Multiply && v.n > 1 => {
                vector_times_matrix(v, m, deps).unwrap_or_else(unknown)
            }
            (Val::Agg(a), Val::Agg(b)) if op == Bo::Multiply => {
                let ext = |m: &[Val]| m.iter().all(|c| c.facts().has(Facts::EXT));
                if self.mode == Mode::Typical && ext(a) && ext(b) {
                    // Ordinary transforms compose to an ordinary transform (a view matrix
                    // times a model matrix), not to one with entries the sum of products.
                    Val::Agg(a.to_vec())
                } else {
                    matrix_product(a, b, deps).unwrap_or_else(unknown)
                }
            }
            (Val::Agg(a), Val::Agg(b))
                if a.len() == b.len() && matches!(op, Bo::Add | Bo::Subtract) =>
            {
                matrix_sum(op, a, b, deps)
            }
            (Val::Agg(m), Val::Num(s)) | (Val::Num(s), Val::Agg(m)) if s.n == 1 => {
                matrix_scale(op, matches!(lv, Val::Agg(_)), m, s, deps)
            }
            _ => unknown(),
        }
    }

    /// An arithmetic operator on scalars and vectors.
    fn num_binary(&self, s: Site, o: &Operands) -> Num {
        match o.op {
            Bo::Add => self.interpolation(s, o).unwrap_or_else(|| add(o)),
            Bo::Subtract => self.subtract(s, o),
            Bo::Multiply => self.multiply(s, o),
            Bo::Divide => divide(o),
            Bo::Modulo => modulo(o),
            _ => Num::from_components(&vec![Interval::FULL; o.a.n.max(o.b.n) as usize], o.deps),
        }
    }

    /// `a - b`: 0 when they are the same, `mod(x, y)` as essl lowers it.
    fn subtract(&self, s: Site, o: &Operands) -> Num {
        let (a, b, deps) = (o.a, o.b, o.deps);
        if self.same(s.f, s.id, o.l, o.r) {
            return Num::from_components(&vec![Interval::point(0.0); a.n.max(b.n) as usize], deps);
        }
        if let Some(yv) = Self::is_mod(s.f, o.l, o.r)
            .and_then(|y| self.nm(s.id, y))
            .or_else(|| self.reciprocal_mod(s, o.l, o.r))
        {
            // The remainder of integers by an integer `k` is at most `k - 1`.
            let whole = a.facts.has(Facts::INTEGRAL) && yv.facts.has(Facts::INTEGRAL);
            let comps = a.zip(&yv, |x, y| {
                let r = Interval::modulo(x, y);
                match y.as_point() {
                    Some(k) if whole && k >= 1.0 => r.meet(Interval::new(0.0, k - 1.0)),
                    _ => r,
                }
            });
            return Num::from_components(
                &comps,
                deps.set(Facts::NN, yv.facts.has(Facts::NN))
                    .set(Facts::INTEGRAL, whole),
            );
        }
        // `x - floor(x)`, written out (`level0 = floor(blend); blend -= level0;`): `fract(x)`.
        if let E::Math {
            fun: Mf::Floor,
            arg,
            ..
        } = s.f.expressions[crate::symbolic::resolve(s.f, self, s.id, o.r)]
        {
            if self.same(s.f, s.id, o.l, arg) {
                let comps = a.map(Interval::fract);
                return Num::from_components(&comps, deps.with(Facts::NN).with(Facts::UNIT));
            }
        }
        let comps = a.zip(b, Interval::sub);
        // `1.0 - x` of an `x` in [-1, 1] whenever the external values are (a weight, a
        // colour channel, `metalness`): not negative for valid external values either, and
        // in [0, 1] when `x` is also not negative.
        // More generally `c - k * y` with `c ≥ |k|` and `y` in [-1, 1].
        let from_one = self
            .unit_mag(s, o.r, 0)
            .is_some_and(|m| a.comps().iter().all(|c| c.lo >= m))
            || a.n > 1 && self.at_most_smallest(s, o.r, o.l);
        let unit = from_one && b.facts.has(Facts::NN) && a.comps().iter().all(|c| c.hi <= 1.0);
        let nn = from_one || self.completes_square(s, o.l, o.r);
        let facts = deps
            .with(Facts::DIFF)
            .set(Facts::NN, nn)
            .set(Facts::UNIT, unit)
            .set(Facts::INTEGRAL, o.integral());
        let mut out = Num::from_components(&comps, facts);
        if !o.mixed() && o.vector_result() {
            out.norm = out.norm.meet(triangle(a.norm, b.norm));
        }
        out.settle()
    }

    /// `a + (b - a) * t` with `t` in [0, 1]: `mix(a, b, t)` written out (Schlick's
    /// `F0 + (1.0 - F0) * pow(1.0 - VdotH, 5.0)`), between `a` and `b`.
    fn interpolation(&self, s: Site, o: &Operands) -> Option<Num> {
        let f = s.f;
        for (a, prod) in [(o.l, o.r), (o.r, o.l)] {
            let E::Binary {
                op: Bo::Multiply,
                left,
                right,
            } = f.expressions[prod]
            else {
                continue;
            };
            for (d, t) in [(left, right), (right, left)] {
                let E::Binary {
                    op: Bo::Subtract,
                    left: b,
                    right: a2,
                } = f.expressions[d]
                else {
                    continue;
                };
                let Some(tv) = self.nm(s.id, t) else { continue };
                let weight = tv.facts.has(Facts::NN.with(Facts::UNIT))
                    || tv.comps().iter().all(|c| c.within(Interval::UNIT));
                if !weight || !self.same(f, s.id, a, a2) {
                    continue;
                }
                let (Some(av), Some(bv)) = (self.nm(s.id, a), self.nm(s.id, b)) else {
                    continue;
                };
                let both = |x: Facts| av.facts.has(x) && bv.facts.has(x);
                let facts = o
                    .deps
                    .set(Facts::NN, both(Facts::NN))
                    .set(Facts::POS, both(Facts::POS))
                    .set(Facts::UNIT, both(Facts::UNIT));
                let n = av.n.max(bv.n).max(o.a.n).max(o.b.n);
                let pick = |v: &Num, i: usize| v.c[i.min(v.n as usize - 1)];
                let comps: Vec<Interval> = (0..n as usize)
                    .map(|i| pick(&av, i).hull(pick(&bv, i)))
                    .collect();
                return Some(Num::from_components(&comps, facts));
            }
        }
        None
    }

    /// `a * b`: a square when they are the same.
    fn multiply(&self, s: Site, o: &Operands) -> Num {
        let (a, b, deps) = (o.a, o.b, o.deps);
        let (fa, fb) = (a.facts, b.facts);
        if self.same(s.f, s.id, o.l, o.r) && a.n == b.n {
            let comps = a.map(Interval::sqr);
            let facts = deps
                .with(Facts::NN)
                .set(
                    Facts::POS,
                    fa.has(Facts::POS) || (a.n == 1 && fa.has(Facts::NZ)),
                )
                .set(Facts::UNIT, fa.has(Facts::UNIT));
            return Num::from_components(&comps, facts);
        }
        let mixed = o.mixed();
        let comps = a.zip(b, Interval::mul);
        let nn = fa.has(Facts::NN) && fb.has(Facts::NN)
            || fa.has(Facts::NP) && fb.has(Facts::NP)
            || self.holds_square(s, o.l, o.r);
        let np = fa.has(Facts::NN) && fb.has(Facts::NP) || fa.has(Facts::NP) && fb.has(Facts::NN);
        let pos = fa.has(Facts::POS) && fb.has(Facts::POS);
        let nz = fa.has(Facts::NZ) && fb.has(Facts::NZ) && (mixed || !o.vector_result());
        let unit = fa.has(Facts::UNIT) && fb.has(Facts::UNIT);
        let cross = mixed && (fa.any(Facts::CROSS) || fb.any(Facts::CROSS));
        let facts = deps
            .set(Facts::NN, nn)
            .set(Facts::NP, np)
            .set(Facts::POS, pos)
            .set(Facts::NZ, nz)
            .set(Facts::UNIT, unit)
            .set(Facts::CROSS, cross)
            .set(Facts::INTEGRAL, o.integral());
        let mut out = Num::from_components(&comps, facts);
        if mixed {
            let (s, v) = if a.n == 1 { (a, b) } else { (b, a) };
            out.norm = out.norm.meet(s.c[0].abs().mul(v.norm));
        }
        out.settle()
    }
}

/// `a + b`.
fn add(o: &Operands) -> Num {
    let (a, b) = (o.a, o.b);
    let (fa, fb) = (a.facts, b.facts);
    let comps = a.zip(b, Interval::add);
    let nn = fa.has(Facts::NN) && fb.has(Facts::NN);
    let pos =
        (fa.has(Facts::POS) && fb.has(Facts::NN)) || (fa.has(Facts::NN) && fb.has(Facts::POS));
    let nz = if o.vector_result() {
        nn && (fa.has(Facts::NZ) || fb.has(Facts::NZ))
    } else {
        pos
    };
    let facts = o
        .deps
        .set(Facts::NN, nn)
        .set(Facts::POS, pos)
        .set(Facts::NZ, nz)
        .set(Facts::INTEGRAL, o.integral());
    let mut out = Num::from_components(&comps, facts);
    if !o.mixed() && o.vector_result() {
        out.norm = out.norm.meet(triangle(a.norm, b.norm));
    }
    out.settle()
}

/// `a / b` (truncated for integers).
fn divide(o: &Operands) -> Num {
    let (a, b, is_int) = (o.a, o.b, o.is_int);
    let fa = a.facts;
    let fb = b.facts;
    let comps = a.zip(b, |x, y| if is_int { x.div(y).trunc() } else { x.div(y) });
    let nn = fa.has(Facts::NN) && fb.has(Facts::NN);
    let pos = fa.has(Facts::POS) && fb.has(Facts::POS) && !is_int;
    let nz = fa.has(Facts::NZ) && !is_int && (b.n == 1 || !o.vector_result());
    let cross = b.n == 1 && fa.any(Facts::CROSS);
    let facts = o
        .deps
        .set(Facts::NN, nn)
        .set(Facts::POS, pos)
        .set(Facts::NZ, nz)
        .set(Facts::CROSS, cross)
        .set(Facts::INTEGRAL, is_int);
    let mut out = Num::from_components(&comps, facts);
    if b.n == 1 && a.n > 1 && !is_int {
        out.norm = out.norm.meet(a.norm.div(b.c[0].abs()));
    }
    out.settle()
}

/// `a % b` (integers) or the remainder's range by magnitude (floats).
fn modulo(o: &Operands) -> Num {
    let is_int = o.is_int;
    let comps = o.a.zip(o.b, |x, y| {
        if is_int {
            x.rem_int(y)
        } else {
            let m = y.mag();
            Interval::new(
                if x.lo >= 0.0 { 0.0 } else { x.lo.max(-m) },
                if x.hi <= 0.0 { 0.0 } else { x.hi.min(m) },
            )
        }
    });
    Num::from_components(
        &comps,
        o.deps
            .set(Facts::NN, o.a.facts.has(Facts::NN))
            .set(Facts::INTEGRAL, is_int || o.integral()),
    )
}

/// Matrix times column vector (`None`: a matrix whose columns are not numbers).
fn matrix_times_vector(m: &[Val], v: &Num, deps: Facts) -> Option<Val> {
    let cols: Vec<Num> = m.iter().filter_map(|c| c.num().copied()).collect();
    if cols.len() != m.len() || cols.len() != v.n as usize {
        return None;
    }
    let rows = cols[0].n as usize;
    let comps: Vec<Interval> = (0..rows)
        .map(|row| {
            cols.iter()
                .enumerate()
                .fold(Interval::point(0.0), |s, (c, col)| {
                    s.add(col.c[row].mul(v.c[c]))
                })
        })
        .collect();
    let invertible = cols.iter().all(|c| c.facts.has(Facts::NZ));
    let nz = invertible && v.facts.has(Facts::NZ) && cols.len() == rows;
    let nn = non_negative_entries(&cols) && v.facts.has(Facts::NN);
    // A direction (w = 0) keeps a non-zero xyz through an invertible (affine or
    // projective) transform.
    let nz3 = invertible
        && rows == 4
        && v.n == 4
        && v.c[3].as_point() == Some(0.0)
        && v.facts.has(Facts::NZ3);
    Some(Val::Num(Num::from_components(
        &comps,
        deps.set(Facts::NZ, nz)
            .set(Facts::NZ3, nz3)
            .set(Facts::NN, nn),
    )))
}

/// Whether every entry of a matrix is known to be non-negative by its interval (a colour
/// matrix, a constant): the product with a non-negative vector is then non-negative.
fn non_negative_entries(cols: &[Num]) -> bool {
    cols.iter().all(|c| c.comps().iter().all(|x| x.lo >= 0.0))
}

/// Row vector times matrix (`None`: a matrix whose columns are not numbers).
fn vector_times_matrix(v: &Num, m: &[Val], deps: Facts) -> Option<Val> {
    let cols: Vec<Num> = m.iter().filter_map(|c| c.num().copied()).collect();
    if cols.len() != m.len() {
        return None;
    }
    let comps: Vec<Interval> = cols
        .iter()
        .map(|col| {
            (0..col.n as usize).fold(Interval::point(0.0), |s, r| {
                s.add(col.c[r].mul(v.c[r.min(v.n as usize - 1)]))
            })
        })
        .collect();
    let invertible = cols.iter().all(|c| c.facts.has(Facts::NZ));
    let nn = non_negative_entries(&cols) && v.facts.has(Facts::NN);
    // A direction (w = 0) times an invertible affine matrix, `vec4(n, 0.0) * inverseModel`
    // (the inverse transpose applied to a normal): its xyz is the upper 3×3 block's transpose
    // times `n`, not zero for a non-zero `n`.
    let nz3 = invertible
        && cols.len() == 4
        && v.n == 4
        && v.c[3].as_point() == Some(0.0)
        && v.facts.has(Facts::NZ3);
    Some(Val::Num(Num::from_components(
        &comps,
        deps.set(Facts::NZ, invertible && v.facts.has(Facts::NZ))
            .set(Facts::NZ3, nz3)
            .set(Facts::NN, nn),
    )))
}

/// Matrix product: each column of the result is A times a column of B (`None`: an A whose
/// columns are not numbers).
fn matrix_product(a: &[Val], b: &[Val], deps: Facts) -> Option<Val> {
    let acols: Vec<Num> = a.iter().filter_map(|c| c.num().copied()).collect();
    if acols.len() != a.len() || acols.is_empty() {
        return None;
    }
    let rows = acols[0].n as usize;
    let inv =
        acols.iter().all(|c| c.facts.has(Facts::NZ)) && b.iter().all(|c| c.facts().has(Facts::NZ));
    let cols = b
        .iter()
        .map(|bc| match bc.num() {
            Some(v) => {
                let comps: Vec<Interval> = (0..rows)
                    .map(|row| {
                        acols
                            .iter()
                            .enumerate()
                            .fold(Interval::point(0.0), |s, (c, col)| {
                                s.add(col.c[row].mul(v.c[c.min(v.n as usize - 1)]))
                            })
                    })
                    .collect();
                Val::Num(Num::from_components(&comps, deps.set(Facts::NZ, inv)))
            }
            None => Val::Any,
        })
        .collect();
    Some(Val::Agg(cols))
}

/// The sum or difference of two matrices, column by column.
fn matrix_sum(op: Bo, a: &[Val], b: &[Val], deps: Facts) -> Val {
    Val::Agg(
        a.iter()
            .zip(b)
            .map(|(x, y)| match (x.num(), y.num()) {
                (Some(x), Some(y)) => Val::Num(Num::from_components(
                    &x.zip(y, |p, q| if op == Bo::Add { p.add(q) } else { p.sub(q) }),
                    deps,
                )),
                _ => Val::Any,
            })
            .collect(),
    )
}

/// A matrix times a scalar, or divided by one (`matrix_left`: the matrix is the left operand).
fn matrix_scale(op: Bo, matrix_left: bool, m: &[Val], s: &Num, deps: Facts) -> Val {
    let scale_nz = s.facts.has(Facts::NZ);
    Val::Agg(
        m.iter()
            .map(|c| match c.num() {
                Some(c) => {
                    let comps = c.map(|x| match op {
                        Bo::Multiply => x.mul(s.c[0]),
                        Bo::Divide if matrix_left => x.div(s.c[0]),
                        _ => Interval::FULL,
                    });
                    Val::Num(Num::from_components(
                        &comps,
                        deps.set(
                            Facts::NZ,
                            scale_nz && c.facts.has(Facts::NZ) && op == Bo::Multiply,
                        ),
                    ))
                }
                None => Val::Any,
            })
            .collect(),
    )
}

/// The length of `a ± b` from the lengths of `a` and `b`.
pub(super) fn triangle(a: Interval, b: Interval) -> Interval {
    if a.is_empty() || b.is_empty() {
        return Interval::NON_NEGATIVE;
    }
    let lo = (a.lo - b.hi).max(b.lo - a.hi).max(0.0);
    Interval::new(lo, a.hi + b.hi).slack(EPS)
}

/// `a >> b` and `a & b` of integers: a right shift keeps a non-negative value between 0 and
/// itself (and is non-negative whenever `a` is), `&` with a non-negative mask (either side) is
/// between 0 and the mask (`(x >> 8) & 0xff` is in [0, 255]); otherwise unknown.
fn bits(op: Bo, a: &Num, b: &Num, deps: Facts) -> Num {
    let n = a.n.max(b.n);
    let at = |x: &Num, i: usize| x.c[if x.n == 1 { 0 } else { i }];
    let comps: Vec<Interval> = (0..n as usize)
        .map(|i| {
            let (x, y) = (at(a, i), at(b, i));
            match op {
                Bo::ShiftRight => Interval::new(x.lo.min(0.0), x.hi.max(0.0)),
                _ if y.lo >= 0.0 && x.lo >= 0.0 => Interval::new(0.0, x.hi.min(y.hi)),
                _ if y.lo >= 0.0 => Interval::new(0.0, y.hi),
                _ if x.lo >= 0.0 => Interval::new(0.0, x.hi),
                _ => Interval::FULL,
            }
        })
        .collect();
    let nn = match op {
        Bo::ShiftRight => a.facts.has(Facts::NN),
        _ => a.facts.has(Facts::NN) || b.facts.has(Facts::NN),
    };
    Num::from_components(&comps, deps.with(Facts::INTEGRAL).set(Facts::NN, nn)).settle()
}
