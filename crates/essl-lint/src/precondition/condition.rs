//! Conditions on terms (`a < b`, `v != 0`, `|x| <= 1`, …): what must hold for an expression
//! to be defined, their evaluation with a draw's values, and how they read.

use std::fmt;

use super::term::{call, not_below};
use super::value::num;
use super::{Func, Precision, Term, UniformRef, Value};

/// A condition on uniform values under which an expression of the shader is defined.
#[non_exhaustive]
#[derive(Clone, Debug, PartialEq)]
pub enum Condition {
    /// `a < b` in every component (`smoothstep`'s edges).
    Less(Term, Term),
    /// `a != b` in every component, so that `a - b` is not 0 (a divisor).
    NotEqual(Term, Term),
    /// No component is 0 (a divisor).
    NonZero(Term),
    /// Not the zero vector, nor so short that its squared length flushes to 0
    /// (`normalize(v)`).
    NonZeroVector(Term),
    /// Two vectors that are not parallel and not zero (`normalize(cross(a, b))`).
    NotParallel(Term, Term),
    /// Every component `> 0` (an exponent where the base can be 0).
    Positive(Term),
    /// Every component `>= 0` (a `pow` base).
    NonNegative(Term),
    /// Not `base == 0` with `exponent <= 0` in any component (`pow`).
    PowBaseZero {
        /// The base.
        base: Term,
        /// The exponent.
        exponent: Term,
    },
    /// Every component in `[-1, 1]` (`acos`, `asin`).
    WithinUnit(Term),
    /// Every component of the uniform (every member and element of a struct or array) is
    /// finite: no NaN, no ±∞.
    Finite(UniformRef),
}

/// The result of evaluating a [`Condition`].
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// The condition holds.
    Holds,
    /// It does not: what is wrong, with the values (`` `u_innerLimit` = 0.9 equals
    /// `u_outerLimit` = 0.9 ``).
    Violated(String),
    /// It cannot be evaluated (a uniform without a value, shapes that do not fit).
    Unknown,
}

impl Condition {
    /// The terms the condition compares.
    pub fn terms(&self) -> Vec<&Term> {
        match self {
            Condition::Less(a, b)
            | Condition::NotEqual(a, b)
            | Condition::NotParallel(a, b)
            | Condition::PowBaseZero {
                base: a,
                exponent: b,
            } => vec![a, b],
            Condition::NonZero(a)
            | Condition::NonZeroVector(a)
            | Condition::Positive(a)
            | Condition::NonNegative(a)
            | Condition::WithinUnit(a) => vec![a],
            Condition::Finite(_) => Vec::new(),
        }
    }

    /// Every uniform the condition reads, in order, each once.
    pub fn uniforms(&self) -> Vec<&UniformRef> {
        if let Condition::Finite(u) = self {
            return vec![u];
        }
        let mut out = Vec::new();
        for t in self.terms() {
            t.collect(&mut out);
        }
        out
    }

    /// Evaluates the condition with the uniform values `uniforms` gives, every operation
    /// rounded to `precision` (a mediump `u_a - u_b` is 0 when both round to the same 16-bit
    /// float).
    pub fn check(
        &self,
        precision: Precision,
        uniforms: &mut dyn FnMut(&UniformRef) -> Option<Value>,
    ) -> Outcome {
        match self.check_inner(precision, uniforms) {
            Some(Some(why)) => Outcome::Violated(why),
            Some(None) => Outcome::Holds,
            None => Outcome::Unknown,
        }
    }

    fn check_inner(
        &self,
        p: Precision,
        uniforms: &mut dyn FnMut(&UniformRef) -> Option<Value>,
    ) -> Option<Option<String>> {
        let terms = self.terms();
        let mut vals = Vec::with_capacity(terms.len());
        for t in &terms {
            vals.push(t.eval(p, uniforms)?);
        }
        // Shown as set (a mediump comparison rounds them; the message says "in mediump").
        let mut shown_vals = vals.clone();
        if p == Precision::Low {
            for (v, t) in shown_vals.iter_mut().zip(&terms) {
                if let Some(x) = t.eval(Precision::High, uniforms) {
                    *v = x;
                }
            }
        }
        let shown = |i: usize| format!("`{}` = {}", terms[i], shown_vals[i]);
        let wide = |a: &Value, b: &Value| -> Option<usize> {
            let n = a.n.max(b.n);
            (a.n == 1 || b.n == 1 || a.n == b.n).then_some(n as usize)
        };
        let in_p = if p == Precision::Low {
            " in mediump"
        } else {
            ""
        };
        Some(match self {
            Condition::Less(..) => {
                let (a, b) = (&vals[0], &vals[1]);
                let n = wide(a, b)?;
                let bad = (0..n).find(|&i| not_below(a.at(i), b.at(i)));
                bad.map(|i| {
                    let (x, y) = (a.at(i), b.at(i));
                    let how = if x.is_nan() || y.is_nan() {
                        "NaN"
                    } else if x == y {
                        "equal"
                    } else {
                        "swapped"
                    };
                    format!("{} is not below {} ({how}{in_p})", shown(0), shown(1))
                })
            }
            Condition::NotEqual(..) => {
                let (a, b) = (&vals[0], &vals[1]);
                let n = wide(a, b)?;
                (0..n)
                    .any(|i| p.round(a.at(i) - b.at(i)) == 0.0)
                    .then(|| format!("{} equals {}{in_p}", shown(0), shown(1)))
            }
            Condition::NonZero(_) => vals[0]
                .comps()
                .contains(&0.0)
                .then(|| format!("{} is 0{in_p}", shown(0))),
            Condition::NonZeroVector(_) => {
                let v = &vals[0];
                let len2 = p.round(v.dot(v));
                if v.comps().iter().all(|x| *x == 0.0) {
                    Some(format!("{} is the zero vector", shown(0)))
                } else if len2 < p.min_normal() {
                    Some(format!(
                        "{} is too short to normalise{in_p}: its squared length {} is below {}",
                        shown(0),
                        num(len2),
                        num(p.min_normal())
                    ))
                } else {
                    None
                }
            }
            Condition::NotParallel(..) => {
                let (a, b) = (&vals[0], &vals[1]);
                if a.n != 3 || b.n != 3 {
                    return None;
                }
                let c = call(Func::Cross, &[*a, *b])?.map(|x| p.round(x));
                let c2 = c.dot(&c);
                let limit = (p.epsilon() * p.epsilon()) * a.dot(a) * b.dot(b);
                if a.comps().iter().all(|x| *x == 0.0) || b.comps().iter().all(|x| *x == 0.0) {
                    Some(format!(
                        "{} and {}: one is the zero vector, so their cross product is",
                        shown(0),
                        shown(1)
                    ))
                } else if c2 < p.min_normal() || c2 <= limit {
                    Some(format!(
                        "{} and {} are parallel{in_p}: their cross product is {}",
                        shown(0),
                        shown(1),
                        c
                    ))
                } else {
                    None
                }
            }
            Condition::Positive(_) => vals[0]
                .comps()
                .iter()
                .any(|x| x.is_nan() || *x <= 0.0)
                .then(|| format!("{} is not > 0", shown(0))),
            Condition::NonNegative(_) => vals[0]
                .comps()
                .iter()
                .any(|x| x.is_nan() || *x < 0.0)
                .then(|| format!("{} is negative", shown(0))),
            Condition::PowBaseZero { .. } => {
                let (a, b) = (&vals[0], &vals[1]);
                let n = wide(a, b)?;
                (0..n)
                    .any(|i| a.at(i) == 0.0 && (b.at(i).is_nan() || b.at(i) <= 0.0))
                    .then(|| {
                        format!(
                            "the base {} is 0 and the exponent {} is not > 0",
                            shown(0),
                            shown(1)
                        )
                    })
            }
            Condition::WithinUnit(_) => vals[0]
                .comps()
                .iter()
                .any(|x| !(-1.0..=1.0).contains(x))
                .then(|| format!("{} is outside [-1, 1]", shown(0))),
            Condition::Finite(u) => {
                let v = uniforms(u)?;
                (!v.comps().iter().all(|x| x.is_finite()))
                    .then(|| format!("`{u}` = {v} is not finite"))
            }
        })
    }
}

impl fmt::Display for Condition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Condition::Less(a, b) => write!(f, "{a} < {b}"),
            Condition::NotEqual(a, b) => write!(f, "{a} != {b}"),
            Condition::NonZero(a) => write!(f, "{a} != 0"),
            Condition::NonZeroVector(a) => write!(f, "length({a}) > 0"),
            Condition::NotParallel(a, b) => write!(f, "length(cross({a}, {b})) > 0"),
            Condition::Positive(a) => write!(f, "{a} > 0"),
            Condition::NonNegative(a) => write!(f, "{a} >= 0"),
            Condition::PowBaseZero { base, exponent } => {
                write!(f, "{base} != 0 || {exponent} > 0")
            }
            Condition::WithinUnit(a) => write!(f, "-1 <= {a} <= 1"),
            Condition::Finite(u) => write!(f, "isfinite({u})"),
        }
    }
}
