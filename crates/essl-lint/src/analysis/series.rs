//! Sums of geometric series in loops: a bound widening cannot find.
//!
//! Fractal noise (`value += amplitude * noise(p); amplitude *= 0.5;`), the radical inverse of
//! Hammersley points (`value += r * invBi; invBi *= invBase;`) and weighted blurs accumulate a
//! term times a weight the loop shrinks by a fixed ratio. Widening sends the sum to infinity
//! after a few rounds; the sum is in fact bounded: with `|w|` at most `w₀` and `|q| < 1`,
//! `Σ |w₀ qᵏ| ≤ w₀ / (1 − |q|)`, so the accumulator stays within its initial value plus that
//! times the term's factor — `[0, 1]` for the radical inverse of bits in `{0, 1}` weighted
//! `1/2, 1/4, …`.
//!
//! [`find`] recognises the shape syntactically, per function; what it requires makes the bound
//! sound:
//! - the accumulator `acc` has exactly two whole stores, neither in part nor through a pointer:
//!   its initial value (the local's initialiser, or one store outside loops before the loop) and
//!   `acc = acc + t` inside a loop that no other loop encloses, not inside a nested loop (at
//!   most one term per iteration);
//! - `t` is `a * w`, `w * a` or `w` for a local `w` with exactly two whole stores: its initial
//!   value (as above) and `w = w * q` (or `q * w`) directly in the same loop's body or
//!   continuing block, not under an `if` (once every iteration), and when in the body, with no
//!   `continue` in the loop (which could add a term and skip the update).
//!
//! The analysis meets the value each iteration stores with the bound, computed from the values
//! of `a`, `q`, the initial value and `w`'s cell ([`Analysis::series_bound`]); a `q` that changes
//! after the bound used it asks for another round, so the fixpoint is sound.

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use naga::{BinaryOperator as Op, Block, Expression as E, Function, Handle, Statement};

use super::statements::root_local;
use super::{Analysis, Place, Root, Site};
use crate::interval::Interval;
use crate::value::{Num, Val};

/// An accumulator of a geometric series, found by [`find`].
#[derive(Clone, Debug)]
pub(crate) struct Series {
    /// The value the accumulating store stores (`acc + t`).
    add: Handle<E>,
    /// The factor of the term besides the weight (`None`: the term is the weight).
    factor: Option<Handle<E>>,
    /// The weight's local.
    weight: usize,
    /// The value the weight's update stores (`w * q`).
    update: Handle<E>,
    /// The ratio `q`.
    ratio: Handle<E>,
    /// The accumulator's initial value.
    init: Handle<E>,
    /// The weight's initial value.
    weight_init: Handle<E>,
}

/// A whole store of a local, where it is.
pub(super) struct Store {
    pub(super) local: usize,
    pub(super) value: Handle<E>,
    /// The innermost loop around it (its order in the walk), if any.
    pub(super) innermost: Option<usize>,
    /// Directly in that loop's body or continuing block.
    pub(super) direct: bool,
    /// In the continuing block.
    pub(super) continuing: bool,
    /// Its order in the walk.
    pub(super) order: usize,
}

/// A loop: whether another loop encloses it, whether its body continues, its blocks.
pub(super) struct LoopInfo<'f> {
    pub(super) nested: bool,
    continues: bool,
    pub(super) body: &'f Block,
    /// Its order in the walk.
    pub(super) order: usize,
}

/// The whole stores of a function's locals and its loops, in the order of its statements.
#[derive(Default)]
pub(super) struct Walk<'f> {
    pub(super) stores: Vec<Store>,
    /// Locals stored in part or passed by pointer.
    pub(super) spoiled: HashSet<usize>,
    pub(super) loops: Vec<LoopInfo<'f>>,
    order: usize,
}

/// Whether expression `h` loads the whole local `l`.
pub(super) fn loads(f: &Function, h: Handle<E>, l: usize) -> bool {
    matches!(f.expressions[h], E::Load { pointer } if root_local(f, pointer) == Some((l, true)))
}

/// Whether a block continues the loop it is in (not counting nested loops).
fn continues(b: &Block) -> bool {
    b.iter().any(|s| match s {
        Statement::Continue => true,
        Statement::Block(b) => continues(b),
        Statement::If { accept, reject, .. } => continues(accept) || continues(reject),
        Statement::Switch { cases, .. } => cases.iter().any(|c| continues(&c.body)),
        _ => false,
    })
}

impl<'f> Walk<'f> {
    /// The walk of function `f`.
    pub(super) fn of(f: &'f Function) -> Self {
        let mut w = Walk::default();
        w.block(f, &f.body, None);
        w
    }

    /// `around`: the innermost loop and whether `b` is directly its body or continuing block.
    fn block(&mut self, f: &Function, b: &'f Block, around: Option<(usize, bool, bool)>) {
        let inner = around.map(|(l, _, c)| (l, false, c));
        for s in b.iter() {
            self.order += 1;
            match s {
                Statement::Block(b) => self.block(f, b, inner),
                Statement::If { accept, reject, .. } => {
                    self.block(f, accept, inner);
                    self.block(f, reject, inner);
                }
                Statement::Switch { cases, .. } => {
                    for k in cases {
                        self.block(f, &k.body, inner);
                    }
                }
                Statement::Loop {
                    body, continuing, ..
                } => {
                    let id = self.loops.len();
                    self.loops.push(LoopInfo {
                        nested: around.is_some(),
                        continues: continues(body),
                        body,
                        order: self.order,
                    });
                    self.block(f, body, Some((id, true, false)));
                    self.block(f, continuing, Some((id, true, true)));
                }
                Statement::Store { pointer, value } => match root_local(f, *pointer) {
                    Some((local, true)) => self.stores.push(Store {
                        local,
                        value: *value,
                        innermost: around.map(|(l, _, _)| l),
                        direct: around.is_some_and(|(_, d, _)| d),
                        continuing: around.is_some_and(|(_, _, c)| c),
                        order: self.order,
                    }),
                    Some((l, false)) => {
                        self.spoiled.insert(l);
                    }
                    None => {}
                },
                Statement::Call { arguments, .. } => {
                    for a in arguments {
                        if let Some((l, _)) = root_local(f, *a) {
                            self.spoiled.insert(l);
                        }
                    }
                }
                _ => {}
            }
        }
    }
}

/// The accumulators of geometric series in function `f` (`w`: its [`Walk`]), by local index.
pub(super) fn find(f: &Function, w: &Walk) -> HashMap<usize, Series> {
    let mut by_local: HashMap<usize, Vec<&Store>> = HashMap::default();
    for s in &w.stores {
        by_local.entry(s.local).or_default().push(s);
    }
    // The initial value and the one store inside a loop, for a local with exactly those.
    let init_and_loop = |l: usize| -> Option<(Handle<E>, &Store)> {
        if w.spoiled.contains(&l) {
            return None;
        }
        let stores = by_local.get(&l)?;
        let init = f.local_variables.iter().nth(l)?.1.init;
        let (inside, outside): (Vec<&&Store>, Vec<&&Store>) =
            stores.iter().partition(|s| s.innermost.is_some());
        let [looped] = inside[..] else { return None };
        let start = match (init, &outside[..]) {
            (Some(h), []) => h,
            (None, [s]) if s.order < looped.order => s.value,
            _ => return None,
        };
        let lp = &w.loops[looped.innermost?];
        (!lp.nested).then_some((start, *looped))
    };
    let mut out = HashMap::default();
    for &acc in by_local.keys() {
        let Some((init, add)) = init_and_loop(acc) else {
            continue;
        };
        let Some(term) = other_operand(f, add.value, Op::Add, acc) else {
            continue;
        };
        let Some((weight, factor)) = weight_of(f, term, acc) else {
            continue;
        };
        let Some((weight_init, update)) = init_and_loop(weight) else {
            continue;
        };
        let Some(ratio) = other_operand(f, update.value, Op::Multiply, weight) else {
            continue;
        };
        let lp = update.innermost;
        if lp != add.innermost
            || !update.direct
            || (!update.continuing && lp.is_some_and(|l| w.loops[l].continues))
        {
            continue;
        }
        out.insert(
            acc,
            Series {
                add: add.value,
                factor,
                weight,
                update: update.value,
                ratio,
                init,
                weight_init,
            },
        );
    }
    out
}

/// The other operand of `h`, a binary `op` one of whose operands loads local `l`.
fn other_operand(f: &Function, h: Handle<E>, op: Op, l: usize) -> Option<Handle<E>> {
    match f.expressions[h] {
        E::Binary { op: o, left, right } if o == op => {
            if loads(f, left, l) {
                Some(right)
            } else if loads(f, right, l) {
                Some(left)
            } else {
                None
            }
        }
        _ => None,
    }
}

/// Whether a block holds a loop.
pub(super) fn has_loop(b: &Block) -> bool {
    b.iter().any(|s| match s {
        Statement::Loop { .. } => true,
        Statement::Block(b) => has_loop(b),
        Statement::If { accept, reject, .. } => has_loop(accept) || has_loop(reject),
        Statement::Switch { cases, .. } => cases.iter().any(|c| has_loop(&c.body)),
        _ => false,
    })
}

/// The weight local and the other factor of a term `a * w`, `w * a` or `w`.
fn weight_of(f: &Function, term: Handle<E>, acc: usize) -> Option<(usize, Option<Handle<E>>)> {
    let local = |h: Handle<E>| match f.expressions[h] {
        E::Load { pointer } => match root_local(f, pointer) {
            Some((l, true)) if l != acc => Some(l),
            _ => None,
        },
        _ => None,
    };
    if let Some(l) = local(term) {
        return Some((l, None));
    }
    let E::Binary {
        op: Op::Multiply,
        left,
        right,
    } = f.expressions[term]
    else {
        return None;
    };
    // The weight must be a scalar for the bound to hold per component.
    local(right)
        .map(|l| (l, Some(left)))
        .or_else(|| local(left).map(|l| (l, Some(right))))
}

/// `x · s` for `s ≥ 0`, with `0 · ∞ = 0`.
fn scale(x: f64, s: f64) -> f64 {
    if x == 0.0 || s == 0.0 {
        0.0
    } else {
        x * s
    }
}

/// `v` met with `bound` per component (`v` itself where the meet would be empty).
pub(super) fn clamp(v: &Val, bound: &[Interval]) -> Val {
    let Val::Num(n) = v else { return v.clone() };
    let mut r = *n;
    for i in 0..r.n as usize {
        r.c[i] = r.c[i].meet(bound[i.min(bound.len() - 1)]);
        if r.c[i].is_empty() {
            return v.clone();
        }
    }
    Val::Num(r.settle())
}

/// The function and local of `place` where it is a whole local of the function `s` walks.
pub(super) fn whole_local(s: Site, place: &Place) -> Option<(usize, usize)> {
    match place.root {
        Root::Local(id, local) if place.path.is_empty() && id == s.id => Some((id, local)),
        _ => None,
    }
}

impl Analysis {
    /// The bound, per component, on what the store of `value` into `place` may leave in the
    /// variable, when it adds a term of a geometric series or updates its weight.
    pub(super) fn series_bound(
        &mut self,
        s: Site,
        place: &Place,
        value: Handle<E>,
    ) -> Option<Vec<Interval>> {
        let (id, local) = whole_local(s, place)?;
        let series = &self.functions[id].series;
        if let Some((&acc, update)) = series.iter().find(|(_, x)| x.update == value) {
            // The bound uses the ratio of the last update; one that changed asks for a round.
            let now = self.functions[id].values[update.ratio.index()]
                .num()
                .map(|n| n.c[0]);
            let w0 = self.functions[id].values[update.weight_init.index()]
                .num()
                .map(|n| n.c[0]);
            let before = self.series_ratio.insert((id, acc), now);
            if before != Some(now) && !self.calls.walking() {
                self.changed = true;
                self.stale = true;
            }
            // With |q| < 1 the weight keeps its sign (q ≥ 0) and never grows past its initial
            // value.
            let (q, w0) = (now?, w0?);
            if q.lo.abs().max(q.hi.abs()).partial_cmp(&1.0) != Some(std::cmp::Ordering::Less) {
                return None;
            }
            let m = w0.lo.abs().max(w0.hi.abs());
            return Some(vec![if q.lo >= 0.0 {
                w0.hull(Interval::point(0.0))
            } else {
                Interval::new(-m, m)
            }]);
        }
        let series = series.get(&local).filter(|x| x.add == value).cloned()?;
        let q = (*self.series_ratio.get(&(id, local))?)?;
        self.bound_of(s, &series, q)
    }

    /// The interval each component of the accumulator stays in, per component.
    fn bound_of(&mut self, s: Site, series: &Series, q: Interval) -> Option<Vec<Interval>> {
        let values = &self.functions[s.id].values;
        let qmax = q.lo.abs().max(q.hi.abs());
        let init = *values.get(series.init.index())?.num()?;
        let factor = match series.factor {
            Some(h) => *values.get(h.index())?.num()?,
            None => Num::constant(&[1.0]),
        };
        if qmax.is_nan() || qmax >= 1.0 || init.is_bottom() || factor.is_bottom() {
            return None;
        }
        let root = Root::Local(s.id, series.weight);
        self.note_read(root);
        let w = *self.cell(s.module, root).num()?;
        let (wlo, whi) = (w.c[0].lo, w.c[0].hi);
        let sum = wlo.abs().max(whi.abs()) / (1.0 - qmax);
        if !sum.is_finite() || w.is_bottom() {
            return None;
        }
        let mut out = Vec::new();
        for i in 0..init.n.max(factor.n) as usize {
            let a = factor.c[i.min(factor.n as usize - 1)];
            let c = init.c[i.min(init.n as usize - 1)];
            let (lo, hi) = if wlo >= 0.0 {
                (scale(a.lo.min(0.0), sum), scale(a.hi.max(0.0), sum))
            } else {
                let m = a.lo.abs().max(a.hi.abs());
                (-scale(m, sum), scale(m, sum))
            };
            out.push(Interval::new(c.lo + lo, c.hi + hi));
        }
        Some(out)
    }
}
