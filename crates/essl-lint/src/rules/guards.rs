//! The guards of an expression: what the `if`s around it, the branches of `c ? a : b` it
//! alone feeds and the `if (…) return;` before it say about the values it reads.

use rustc_hash::FxHashMap as HashMap;

use naga::{
    BinaryOperator as Bo, Block, Expression as E, Function, Handle, MathFunction as Mf, Statement,
};

use super::context::{users, User};
use super::Cx;
use crate::analysis::{diverges, refine_num, relation, Refinement};
use crate::interval::Interval;
use crate::symbolic;
use crate::value::Num;

/// How many disjunctions deep [`Cx::guards`] reads a condition.
const MAX_DISJUNCTIONS: u32 = 4;

/// What the conditions under which an expression runs say: the `if`s around it, the branches
/// of `c ? a : b` it alone feeds, and the `if (…) return;` before it.
#[derive(Debug, Default)]
pub struct Guards {
    /// Bounds on compared expressions (`x > 0.0`, `dot(v, v) > 1e-12`).
    pub facts: Vec<(Handle<E>, Refinement)>,
    /// `a OP b` between two expressions, normalised to hold (`Less`, `Greater`, `NotEqual`, …).
    pub relations: Vec<(Bo, Handle<E>, Handle<E>)>,
    /// Expressions known not to be 0 (`x != 0.0`, `abs(x) > c`).
    pub nonzero: Vec<Handle<E>>,
}

/// The `if` conditions (with the branch taken) around each emitted expression, and after
/// `if (c) { …; return; }` the negation for the rest of the block.
fn enclosing(f: &Function) -> HashMap<Handle<E>, Vec<(Handle<E>, bool)>> {
    fn walk(
        b: &Block,
        stack: &mut Vec<(Handle<E>, bool)>,
        out: &mut HashMap<Handle<E>, Vec<(Handle<E>, bool)>>,
    ) {
        let depth = stack.len();
        for s in b.iter() {
            match s {
                Statement::Emit(r) => {
                    for h in r.clone() {
                        out.insert(h, stack.clone());
                    }
                }
                Statement::Block(b) => walk(b, stack, out),
                Statement::If {
                    condition,
                    accept,
                    reject,
                } => {
                    stack.push((*condition, true));
                    walk(accept, stack, out);
                    stack.pop();
                    stack.push((*condition, false));
                    walk(reject, stack, out);
                    stack.pop();
                    let (ad, rd) = (diverges(accept), diverges(reject));
                    if ad != rd {
                        stack.push((*condition, rd));
                    }
                }
                Statement::Switch { cases, .. } => {
                    for c in cases {
                        walk(&c.body, stack, out);
                    }
                }
                Statement::Loop {
                    body, continuing, ..
                } => {
                    walk(body, stack, out);
                    walk(continuing, stack, out);
                }
                _ => {}
            }
        }
        stack.truncate(depth);
    }
    let mut out = HashMap::default();
    walk(&f.body, &mut Vec::new(), &mut out);
    out
}

impl Cx<'_> {
    /// The conditions under which `h` is evaluated for its use.
    pub fn guards(&self, f: &Function, id: usize, h: Handle<E>) -> Guards {
        let mut conds: Vec<(Handle<E>, bool)> = Vec::new();
        // `c ? …h… : …`: the branch `h` alone feeds (through pure expressions).
        let us = users(f);
        let mut cur = h;
        for _ in 0..32 {
            let Some([User::Expr(u)]) = us.get(&cur).map(|v| v.as_slice()) else {
                break;
            };
            let u = *u;
            if let E::Select {
                condition,
                accept,
                reject,
            } = f.expressions[u]
            {
                if accept == cur && reject != cur {
                    conds.push((condition, true));
                } else if reject == cur && accept != cur {
                    conds.push((condition, false));
                } else {
                    break;
                }
            }
            cur = u;
        }
        // The `if`s around the statement that evaluates `h` (or what uses it).
        let enc = enclosing(f);
        if let Some(c) = enc.get(&h).or_else(|| enc.get(&cur)) {
            conds.extend(c.iter().copied());
        }
        let mut g = Guards::default();
        for (c, pol) in conds {
            g.facts.extend(self.sound().conditions(f, id, c, pol));
            self.relations(f, id, c, pol, &mut g, 0);
        }
        g
    }

    /// What condition `c` says when it holds (`pol`) or fails; `depth`: how many disjunctions
    /// enclose it (each side of one is read on its own, so a shared operand is read once per
    /// path: the depth bounds the work).
    fn relations(
        &self,
        f: &Function,
        id: usize,
        c: Handle<E>,
        pol: bool,
        g: &mut Guards,
        depth: u32,
    ) {
        crate::analysis::condition_atoms(f, c, pol, &mut |atom, pol| {
            self.atom_relations(f, id, atom, pol, g, depth)
        });
    }

    /// What one comparison says when it holds (`pol`) or fails: an ordering, a non-zero value.
    fn atom_relations(
        &self,
        f: &Function,
        id: usize,
        c: Handle<E>,
        pol: bool,
        g: &mut Guards,
        depth: u32,
    ) {
        // `all(greaterThanEqual(p, q))` holding: `p >= q` in every component.
        if let E::Relational {
            fun: naga::RelationalFunction::All,
            argument,
        } = f.expressions[c]
        {
            if let (true, E::Binary { op, left, right }) = (pol, &f.expressions[argument]) {
                g.relations.push((*op, *left, *right));
            }
            return;
        }
        let E::Binary { op, left, right } = f.expressions[c] else {
            return;
        };
        // One of two holds (`!(a && b)`, `a || b`): what each alone keeps from 0 is not 0
        // (`if (… || (det > -EPS && det < EPS)) return;`).
        if matches!((op, pol), (Bo::LogicalAnd, false) | (Bo::LogicalOr, true)) {
            if depth >= MAX_DISJUNCTIONS {
                return;
            }
            let (mut a, mut b) = (Guards::default(), Guards::default());
            self.relations(f, id, left, pol, &mut a, depth + 1);
            self.relations(f, id, right, pol, &mut b, depth + 1);
            let same = |x: Handle<E>, y: Handle<E>| self.sound().same(f, id, x, y);
            for x in a.nonzero {
                if b.nonzero.iter().any(|&y| same(x, y)) {
                    g.nonzero.push(x);
                }
            }
            return;
        }
        let op = if pol {
            op
        } else {
            match op {
                Bo::Less => Bo::GreaterEqual,
                Bo::LessEqual => Bo::Greater,
                Bo::Greater => Bo::LessEqual,
                Bo::GreaterEqual => Bo::Less,
                Bo::Equal => Bo::NotEqual,
                Bo::NotEqual => Bo::Equal,
                other => other,
            }
        };
        if !matches!(
            op,
            Bo::Less | Bo::LessEqual | Bo::Greater | Bo::GreaterEqual | Bo::Equal | Bo::NotEqual
        ) {
            return;
        }
        g.relations.push((op, left, right));
        // `x != 0.0`, `abs(x) > c ≥ 0`, `x > c ≥ 0`, `x < c ≤ 0`: x is not 0.
        for (x, b, x_left) in [(left, right, true), (right, left, false)] {
            let Some(bound) = self.sound().num(id, b).filter(|n| n.n == 1).map(|n| n.c[0]) else {
                continue;
            };
            let Some(rel) = relation(op, true, x_left, bound) else {
                if op == Bo::NotEqual && bound.as_point() == Some(0.0) {
                    g.nonzero.push(x);
                }
                continue;
            };
            if !rel.contains(0.0) {
                g.nonzero.push(x);
                if let E::Math {
                    fun: Mf::Abs, arg, ..
                } = f.expressions[x]
                {
                    g.nonzero.push(arg);
                }
            }
        }
    }

    /// `x`'s value under the guards (`None`: no value, or the guarded code cannot run): the
    /// guards bound `x` itself, or a value `x` is computed from (`x < 0.0 ? -pow(-x, p) :
    /// pow(x, p)`: under `x < 0.0`, `-x` is positive).
    pub fn refined(&self, f: &Function, id: usize, x: Handle<E>, g: &Guards) -> Option<Num> {
        let n = *self.sound().num(id, x)?;
        let rs: Vec<Refinement> = g
            .facts
            .iter()
            .filter(|(s, _)| self.sound().same(f, id, *s, x))
            .map(|(_, r)| *r)
            .collect();
        let mut r = refine_num(n, &rs);
        if matches!(
            self.kind(id, x),
            Some(naga::ScalarKind::Sint | naga::ScalarKind::Uint)
        ) {
            r = crate::analysis::integral(r);
        }
        if r.is_bottom() {
            return None;
        }
        if r.n == 1 && rs.is_empty() && !g.facts.is_empty() {
            if let Some(i) = self.refined_scalar(f, id, x, g, 0) {
                r.c[0] = r.c[0].meet(i);
                if r.c[0].is_empty() {
                    return None;
                }
                r.norm = r.c[0].abs();
                r = r.settle();
            }
        }
        Some(r)
    }

    /// The range of scalar `x` when the guards bound a value it is computed from through
    /// negation and arithmetic (`None`: they bound none).
    fn refined_scalar(
        &self,
        f: &Function,
        id: usize,
        x: Handle<E>,
        g: &Guards,
        depth: u32,
    ) -> Option<Interval> {
        let hull = |h: Handle<E>| self.sound().num(id, h).filter(|n| n.n == 1).map(|n| n.c[0]);
        let own = hull(x)?;
        let direct: Vec<Interval> = g
            .facts
            .iter()
            .filter(|(s, _)| self.sound().same(f, id, *s, x))
            .filter_map(|(_, r)| match r {
                Refinement::Value(i) => Some(*i),
                Refinement::Norm(_) => None,
            })
            .collect();
        if !direct.is_empty() {
            return Some(direct.iter().fold(own, |a, i| a.meet(*i)));
        }
        if depth >= 4 {
            return None;
        }
        let sub = |h: Handle<E>| self.refined_scalar(f, id, h, g, depth + 1);
        match f.expressions[symbolic::resolve(f, self.sound(), id, x)] {
            E::Unary {
                op: naga::UnaryOperator::Negate,
                expr,
            } => sub(expr).map(Interval::neg),
            E::Binary { op, left, right } => {
                let (a, b) = (sub(left), sub(right));
                if a.is_none() && b.is_none() {
                    return None;
                }
                let (a, b) = (a.or_else(|| hull(left))?, b.or_else(|| hull(right))?);
                match op {
                    Bo::Add => Some(a.add(b)),
                    Bo::Subtract => Some(a.sub(b)),
                    Bo::Multiply => Some(a.mul(b)),
                    // `a / b` under `a ≥ 0` and `a < b`: in [0, 1) (`1.0 - blend / range`
                    // under `blend > 0.0` and `blend < range`).
                    Bo::Divide if a.lo >= 0.0 && self.ordered(f, id, left, right, g) => {
                        Some(a.div(b).meet(Interval::UNIT))
                    }
                    Bo::Divide => Some(a.div(b)),
                    _ => None,
                }
            }
            _ => None,
        }
    }

    /// Whether the guards say `a < b`: they compare the two, or `a` is a constant of at most 1
    /// and `b` a quotient `p / q` under `q < p` with `q ≥ 0` (`smoothstep(0.0, r / d, t)` inside
    /// `if (d < r)`, `d` a length: `r / d > 1`, or +∞ where `d` is 0).
    pub fn ordered(&self, f: &Function, id: usize, a: Handle<E>, b: Handle<E>, g: &Guards) -> bool {
        let same = |x: Handle<E>, y: Handle<E>| self.sound().same(f, id, x, y);
        let compared = |a: Handle<E>, b: Handle<E>| {
            g.relations.iter().any(|&(op, l, r)| match op {
                Bo::Less => same(l, a) && same(r, b),
                Bo::Greater => same(l, b) && same(r, a),
                _ => false,
            })
        };
        if compared(a, b) {
            return true;
        }
        let at_most_one = self
            .sound()
            .num(id, a)
            .and_then(|n| n.hull().as_point())
            .is_some_and(|c| c <= 1.0);
        if !at_most_one {
            return false;
        }
        let E::Binary {
            op: Bo::Divide,
            left,
            right,
        } = f.expressions[symbolic::resolve(f, self.sound(), id, b)]
        else {
            return false;
        };
        let non_negative = self
            .sound()
            .num(id, right)
            .is_some_and(|n| n.hull().lo >= 0.0);
        non_negative && compared(right, left)
    }

    /// Whether guards `g` keep `x` from 0: they say it is not 0, or bound it away from 0
    /// (`if (x > 1e-6)`, `abs(d) > 1e-6 ? y / d : 0.0`).
    pub fn kept_from_zero(&self, f: &Function, id: usize, x: Handle<E>, g: &Guards) -> bool {
        self.nonzero(f, id, x, g)
            || self
                .refined(f, id, x, g)
                .is_none_or(|v| !v.comps().iter().any(|c| c.contains(0.0)))
    }

    /// Whether the guards say `x != 0`, or `a != b` for `x = a - b`, or each factor of a
    /// product is not 0.
    pub fn nonzero(&self, f: &Function, id: usize, x: Handle<E>, g: &Guards) -> bool {
        let same = |p: Handle<E>, q: Handle<E>| self.sound().same(f, id, p, q);
        if g.nonzero.iter().any(|&y| same(y, x)) {
            return true;
        }
        let r = symbolic::resolve(f, self.sound(), id, x);
        // A copy the guard did not name: `if (b == 0.0) return; float duration = b; … / duration`.
        if r != x
            && g.nonzero
                .iter()
                .any(|&y| same(symbolic::resolve(f, self.sound(), id, y), r))
        {
            return true;
        }
        // An integer the guards keep from 0, converted: `float(n)` after `if (n == 0) return;`
        // (a float converted to an integer can truncate to 0, so only this way).
        if let E::As {
            expr,
            kind: naga::ScalarKind::Float,
            ..
        } = f.expressions[r]
        {
            let integer = matches!(
                self.kind(id, expr),
                Some(naga::ScalarKind::Sint | naga::ScalarKind::Uint)
            );
            return integer && self.nonzero(f, id, expr, g);
        }
        // A product of factors the guards (or constants) keep from 0: `nl * nv` under
        // `nl > 0.0 && nv > 0.0`.
        if let E::Binary {
            op: Bo::Multiply,
            left,
            right,
        } = f.expressions[r]
        {
            let factor = |h: Handle<E>| {
                self.sound()
                    .num(id, h)
                    .is_some_and(|n| !n.comps().iter().any(|c| c.contains(0.0)))
                    || self.nonzero(f, id, h, g)
            };
            return factor(left) && factor(right);
        }
        let E::Binary {
            op: Bo::Subtract,
            left,
            right,
        } = f.expressions[r]
        else {
            return false;
        };
        g.relations.iter().any(|&(op, l, rr)| {
            matches!(op, Bo::Less | Bo::Greater | Bo::NotEqual)
                && ((same(l, left) && same(rr, right)) || (same(l, right) && same(rr, left)))
        })
    }
}
