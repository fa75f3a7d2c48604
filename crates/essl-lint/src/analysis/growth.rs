//! Accumulators that loops with a bounded count of iterations grow: a bound widening cannot
//! find.
//!
//! A ray march advances along its ray by a step that grows with the distance
//! (`t += max(0.075, 0.02 * t)`), in loops that each run a fixed number of times
//! (`for (int i = 0; i < 20; i++)`). Widening sends `t` to infinity after a few rounds, and with
//! it every position along the ray, so a `mediump` overflow the march reaches with ordinary
//! values (a noise lattice index `113.0 * p.z`) goes unreported. The distance is in fact bounded:
//! a store of a value `v` with `|v| ≤ a·|t| + b`, made at most `n` times, leaves `|t|` below
//! the larger of `|t₀|` and `aⁿ·|t₀| + b·(aⁿ − 1)/(a − 1)` (`|t₀| + n·b` for `a = 1`; the
//! sequence is monotone, so its largest term is its first or its last), where `|·|` is the
//! largest magnitude of any component.
//!
//! [`find`] recognises the shape syntactically, per function; what it requires makes the bound
//! sound:
//! - the accumulator `t`, a local never stored in part nor passed by pointer, has its initial
//!   value (the local's initialiser, or one store outside loops before every other store), and
//!   its other whole stores are in loops no other loop encloses;
//! - each such loop runs a bounded number of times: its body starts with the exit test essl
//!   lowers a `for` condition to, `if (!(i < N)) { break; }` (`<=`, or either side of an `&&`),
//!   for a local integer `i` with a literal `N`, whose only stores are a literal before the loop
//!   and `i = i + k` for a literal `k > 0` directly in the loop's continuing block; and no other
//!   test that reads `i` leaves the loop (`if (i >= u_steps) break;` sets the count itself);
//! - each value stored is made of sums, differences, negations, `abs`, `max` and `min` of `t`
//!   and of values that do not read `t`, products with such values and quotients by them, or a
//!   `clamp` to bounds that do not read `t` ([`Analysis::step_bound`]); anything else gives no
//!   bound.
//!
//! The analysis meets what each such store stores with the bound
//! ([`Analysis::growth_bound`]), computed from the values the analysis has for the parts that
//! do not read `t`; a change in them after the bound used them asks for another round, so the
//! fixpoint is sound, and a bound that changes more than [`MAX_CHANGES`] times is dropped (the
//! variable then widens as any other). The bound is the count's: a march that leaves its loop early stays below
//! it, and one that misses every surface reaches it.

use rustc_hash::FxHashMap as HashMap;

use naga::{
    BinaryOperator as Op, Expression as E, Function, Handle, Literal, MathFunction as Mf,
    Statement, UnaryOperator,
};

use super::series::{loads, whole_local, Walk};
use super::statements::{operands, root_local};
use super::{Analysis, Place, Site};
use crate::interval::Interval;

/// Deepest step expression [`Analysis::step_bound`] follows.
const MAX_DEPTH: usize = 12;
/// Most expressions [`reads`] looks at before it takes an expression to read the variable.
const MAX_STEPS: usize = 256;
/// How many times a variable's bound may change before it is dropped.
const MAX_CHANGES: u8 = 3;
/// Largest bound kept: past it the bound tells nothing widening does not.
const MAX_BOUND: f64 = 1e30;

/// The step bound `(a, b)` an accumulator's bound last used (`None`: none), and how many times
/// it changed.
pub(super) type Steps = (Option<(f64, f64)>, u8);

/// An accumulator that loops with bounded iteration counts grow, found by [`find`].
#[derive(Clone, Debug)]
pub(crate) struct Growth {
    /// The value each store inside a loop stores (`t + d`).
    steps: Vec<Handle<E>>,
    /// The initial value.
    init: Handle<E>,
    /// How many steps are taken at most: the iterations of every storing loop, summed.
    count: u64,
}

/// The accumulators of function `f` (`w`: its [`Walk`]) that loops with bounded iteration
/// counts grow, by local index.
pub(super) fn find(f: &Function, w: &Walk) -> HashMap<usize, Growth> {
    let mut out = HashMap::default();
    let mut by_local: HashMap<usize, Vec<usize>> = HashMap::default();
    for (k, s) in w.stores.iter().enumerate() {
        by_local.entry(s.local).or_default().push(k);
    }
    let mut counts: HashMap<usize, Option<u64>> = HashMap::default();
    'locals: for (&t, stores) in &by_local {
        if w.spoiled.contains(&t) {
            continue;
        }
        let declared = f.local_variables.iter().nth(t).and_then(|(_, l)| l.init);
        let (inside, outside): (Vec<usize>, Vec<usize>) = stores
            .iter()
            .partition(|&&k| w.stores[k].innermost.is_some());
        if inside.is_empty() {
            continue;
        }
        let first_inside = inside.iter().map(|&k| w.stores[k].order).min();
        let init = match (declared, &outside[..]) {
            (Some(h), []) => h,
            (None, &[k]) if Some(w.stores[k].order) < first_inside => w.stores[k].value,
            _ => continue,
        };
        let mut steps = Vec::new();
        let mut count = 0u64;
        for &k in &inside {
            let s = &w.stores[k];
            let Some(l) = s.innermost else {
                continue 'locals;
            };
            let lp = &w.loops[l];
            let n = *counts
                .entry(l)
                .or_insert_with(|| (!lp.nested).then(|| iterations(f, w, l)).flatten());
            let Some(n) = n else {
                continue 'locals;
            };
            steps.push(s.value);
            count = count.saturating_add(n);
        }
        out.insert(t, Growth { steps, init, count });
    }
    out
}

/// An integer literal.
fn int_literal(f: &Function, h: Handle<E>) -> Option<i64> {
    match f.expressions[h] {
        E::Literal(Literal::I32(v)) => Some(v.into()),
        E::Literal(Literal::U32(v)) => Some(v.into()),
        _ => None,
    }
}

/// How many times loop `l` of the walk runs its body at most, when its exit test compares a counter with
/// a literal (see the module's documentation).
fn iterations(f: &Function, w: &Walk, l: usize) -> Option<u64> {
    let first = w.loops[l]
        .body
        .iter()
        .find(|s| !matches!(s, Statement::Emit(_)))?;
    let Statement::If {
        condition,
        accept,
        reject,
    } = first
    else {
        return None;
    };
    if !reject.is_empty() || !matches!(accept.first(), Some(Statement::Break)) {
        return None;
    }
    let E::Unary {
        op: UnaryOperator::LogicalNot,
        expr,
    } = f.expressions[*condition]
    else {
        return None;
    };
    let tests = match f.expressions[expr] {
        E::Binary {
            op: Op::LogicalAnd,
            left,
            right,
        } => vec![left, right],
        _ => vec![expr],
    };
    tests.into_iter().filter_map(|c| counted(f, w, l, c)).min()
}

/// The iterations test `c`, `i < N` or `i <= N`, allows for a counter `i` of loop `l`.
fn counted(f: &Function, w: &Walk, l: usize, c: Handle<E>) -> Option<u64> {
    let E::Binary { op, left, right } = f.expressions[c] else {
        return None;
    };
    let inclusive = match op {
        Op::Less => false,
        Op::LessEqual => true,
        _ => return None,
    };
    let E::Load { pointer } = f.expressions[left] else {
        return None;
    };
    let (i, true) = root_local(f, pointer)? else {
        return None;
    };
    let bound = int_literal(f, right)?;
    if w.spoiled.contains(&i) || breaks_on(f, w.loops[l].body, i, true) {
        return None;
    }
    let stores: Vec<_> = w.stores.iter().filter(|s| s.local == i).collect();
    let declared = f.local_variables.iter().nth(i).and_then(|(_, l)| l.init);
    let (mut start, mut step) = (None, None);
    for s in stores {
        if s.innermost.is_none() && s.order < w.loops[l].order && start.is_none() {
            start = Some(s.value);
        } else if s.continuing && s.direct && s.innermost == Some(l) && step.is_none() {
            step = Some(s.value);
        } else {
            return None;
        }
    }
    let start = match (declared, start) {
        (Some(h), None) | (None, Some(h)) => int_literal(f, h)?,
        _ => return None,
    };
    let E::Binary {
        op: Op::Add,
        left,
        right,
    } = f.expressions[step?]
    else {
        return None;
    };
    let k = match (loads(f, left, i), loads(f, right, i)) {
        (true, _) => int_literal(f, right)?,
        (_, true) => int_literal(f, left)?,
        _ => return None,
    };
    if k <= 0 {
        return None;
    }
    let span = bound - start + i64::from(inclusive);
    Some(if span <= 0 {
        0
    } else {
        (span as u64).div_ceil(k as u64)
    })
}

/// Whether a block (a loop's body, `first` for the body itself, whose exit test is not counted)
/// leaves the loop on a test that reads counter `i` (`if (i >= u_steps) break;`): the count is
/// then the test's, not the bound's.
fn breaks_on(f: &Function, b: &naga::Block, i: usize, first: bool) -> bool {
    let mut tests = b.iter().filter(|s| !matches!(s, Statement::Emit(_)));
    if first {
        tests.next();
    }
    tests.any(|s| match s {
        Statement::If {
            condition,
            accept,
            reject,
        } => {
            let leaves = |b: &naga::Block| b.iter().any(|s| matches!(s, Statement::Break));
            (reads(f, *condition, i) && (leaves(accept) || leaves(reject)))
                || breaks_on(f, accept, i, false)
                || breaks_on(f, reject, i, false)
        }
        Statement::Block(b) => breaks_on(f, b, i, false),
        _ => false,
    })
}

/// Whether expression `h` may read local `t`: a load of it among what `h` is computed from
/// ([`operands`]), or a chain too long to follow.
fn reads(f: &Function, h: Handle<E>, t: usize) -> bool {
    let mut work = vec![h];
    let mut steps = 0;
    while let Some(x) = work.pop() {
        steps += 1;
        if steps > MAX_STEPS {
            return true;
        }
        if let E::Load { pointer } = f.expressions[x] {
            if root_local(f, pointer).is_some_and(|(l, _)| l == t) {
                return true;
            }
        }
        work.extend(operands(&f.expressions[x]));
    }
    false
}

impl Analysis {
    /// The bound, per component, on what the store of `value` into `place` may leave in the
    /// variable, when it takes a step of an accumulator that loops with bounded iteration
    /// counts grow.
    pub(super) fn growth_bound(
        &mut self,
        s: Site,
        place: &Place,
        value: Handle<E>,
    ) -> Option<Vec<Interval>> {
        let (id, local) = whole_local(s, place)?;
        let g = self.functions[id].growth.get(&local)?;
        if !g.steps.contains(&value) {
            return None;
        }
        let g = g.clone();
        let init = self.functions[id].values[g.init.index()].num()?;
        let t0 = init.comps().iter().map(|c| c.mag()).fold(0.0, f64::max);
        let (mut a, mut b) = (0.0f64, 0.0f64);
        let mut known = true;
        for &v in &g.steps {
            match self.step_bound(id, s.f, v, local, 0) {
                Some((ad, bd)) => {
                    a = a.max(ad);
                    b = b.max(bd);
                }
                None => known = false,
            }
        }
        // The bound uses the steps' values as they are now; one that changed asks for a round.
        // A bound that keeps changing (a step that grows with the bound itself, through a
        // function's result) is dropped: the variable then widens as any other.
        let now = known.then_some((a, b));
        let (before, changes) = self
            .growth_step
            .get(&(id, local))
            .copied()
            .unwrap_or((now, 0));
        if changes > MAX_CHANGES {
            return None;
        }
        if before != now && !self.calls.walking() {
            self.changed = true;
            self.stale = true;
            self.growth_step.insert((id, local), (now, changes + 1));
        } else {
            self.growth_step.insert((id, local), (now, changes));
        }
        let (a, b) = now?;
        // Up to n steps of x ↦ a·x + b from t₀: the sequence is monotone (the map is), so its
        // largest term is its first or its last.
        let n = g.count as f64;
        let last = if a == 1.0 {
            t0 + n * b
        } else {
            let an = a.powf(n);
            an * t0 + b * (an - 1.0) / (a - 1.0)
        };
        let bound = last.max(t0);
        (bound.is_finite() && bound <= MAX_BOUND && t0.is_finite())
            .then(|| vec![Interval::new(-bound, bound)])
    }

    /// `(a, b)` with `|v| ≤ a·|t| + b` for a value `v` a store of accumulator `t` stores, or
    /// `None` where it is not of a shape the bound follows.
    fn step_bound(
        &self,
        id: usize,
        f: &Function,
        d: Handle<E>,
        t: usize,
        depth: usize,
    ) -> Option<(f64, f64)> {
        if depth > MAX_DEPTH {
            return None;
        }
        if loads(f, d, t) {
            return Some((1.0, 0.0));
        }
        let mag = |h: Handle<E>| {
            self.functions[id].values[h.index()]
                .num()
                .map(|n| n.comps().iter().map(|c| c.mag()).fold(0.0, f64::max))
                .filter(|m| m.is_finite())
        };
        if !reads(f, d, t) {
            return Some((0.0, mag(d)?));
        }
        let sub = |h: Handle<E>| self.step_bound(id, f, h, t, depth + 1);
        let sum = |(a, b): (f64, f64), (c, e): (f64, f64)| (a + c, b + e);
        let most = |(a, b): (f64, f64), (c, e): (f64, f64)| (a.max(c), b.max(e));
        match f.expressions[d] {
            E::Binary {
                op: Op::Add | Op::Subtract,
                left,
                right,
            } => Some(sum(sub(left)?, sub(right)?)),
            E::Binary {
                op: Op::Multiply,
                left,
                right,
            } => {
                let (x, m) = if reads(f, left, t) {
                    (left, mag(right)?)
                } else {
                    (right, mag(left)?)
                };
                let (a, b) = sub(x)?;
                Some((a * m, b * m))
            }
            E::Binary {
                op: Op::Divide,
                left,
                right,
            } if !reads(f, right, t) => {
                let (a, b) = sub(left)?;
                let n = self.functions[id].values[right.index()].num()?;
                let least = n
                    .comps()
                    .iter()
                    .map(|c| {
                        if c.contains(0.0) {
                            0.0
                        } else {
                            c.lo.abs().min(c.hi.abs())
                        }
                    })
                    .fold(f64::INFINITY, f64::min);
                (least > 0.0).then(|| (a / least, b / least))
            }
            E::Unary {
                op: UnaryOperator::Negate,
                expr,
            }
            | E::Splat { value: expr, .. } => sub(expr),
            E::Math {
                fun: Mf::Abs, arg, ..
            } => sub(arg),
            E::Math {
                fun: Mf::Max | Mf::Min,
                arg,
                arg1: Some(other),
                ..
            } => Some(most(sub(arg)?, sub(other)?)),
            E::Math {
                fun: Mf::Clamp,
                arg1: Some(lo),
                arg2: Some(hi),
                ..
            } if !reads(f, lo, t) && !reads(f, hi, t) => Some((0.0, mag(lo)?.max(mag(hi)?))),
            _ => None,
        }
    }
}
