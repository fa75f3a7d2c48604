//! Abstract values: what the analysis knows about one value of the shader.
//!
//! A scalar or vector is a [`Num`]: an [`Interval`] per component, an interval for its
//! Euclidean length, and [`Facts`] that intervals cannot say. Matrices and structs are
//! [`Val::Agg`]s of their columns or members, arrays one summary element ([`Val::Arr`]).
//!
//! The facts are relative to the shader's *external* values — uniforms, inputs, texels, the
//! parameters the caller passes: "if every external value were non-negative, this would be"
//! ([`Facts::NN`]). They separate a hazard the shader's own arithmetic creates (a dot product is
//! negative for perfectly good unit vectors) from one that only a bad external value could cause
//! (`pow(u_base, 2.0)` with a negative `u_base`), which is the runtime check's business.

use crate::interval::Interval;

/// Facts about a value, as bits. The first group holds for every value joined into it (they
/// are intersected when values join); the second records where a value may come from (they are
/// united).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Facts(pub u16);

impl Facts {
    /// Non-negative (every component) whenever every external value is non-negative.
    pub const NN: Facts = Facts(1);
    /// Positive (every component) whenever every external value is positive.
    pub const POS: Facts = Facts(2);
    /// Not zero (a vector: not the zero vector) whenever every external vector is non-zero and
    /// every external matrix invertible.
    pub const NZ: Facts = Facts(4);
    /// Every component in `[-1, 1]` whenever every external value is in `[-1, 1]`.
    pub const UNIT: Facts = Facts(8);
    /// A difference `a - b` (through copies and swizzles).
    pub const DIFF: Facts = Facts(16);
    /// An external value itself (through copies, swizzles, conversions and negation).
    pub const EXT: Facts = Facts(32);
    /// The first three components are not all zero (as [`Facts::NZ`]): what `.xyz` of a
    /// transformed direction `M * vec4(d, 0.0)` keeps.
    pub const NZ3: Facts = Facts(64);
    /// Not positive (every component) whenever every external value is non-negative:
    /// `-x`, `-k * d` (what `exp` turns into a value in (0, 1]).
    pub const NP: Facts = Facts(2048);
    /// Every component an integer (for every value, not only ordinary ones): an `int`, a
    /// `floor`, a whole constant, and sums and products of those.
    pub const INTEGRAL: Facts = Facts(4096);
    /// The facts that are intersected on joins.
    pub const ALL_AND: Facts = Facts(127 | 2048 | 4096);

    /// May be zero because it is a cross product (of vectors that may be parallel).
    pub const CROSS: Facts = Facts(128);
    /// Depends on a uniform's value.
    pub const UNIFORM: Facts = Facts(256);
    /// Depends on a shader input (attribute, varying, built-in input) other than through a
    /// texture read's coordinates: a value that varies from pixel to pixel.
    pub const INPUT: Facts = Facts(512);
    /// Depends on a texel, or on an input whose name says it holds a colour or a normal: a value
    /// that holds over whole regions of the picture.
    pub const TEXTURE: Facts = Facts(1024);
    /// Depends on a fragment's window coordinates (`gl_FragCoord`), which are pixels: an
    /// ordinary value of hundreds or thousands, not the modest magnitude of other inputs.
    pub const WINDOW: Facts = Facts(8192);
    /// Depends on an input or uniform whose name says it holds a position in a scene's space
    /// (`vViewPosition`, `u_globe_position`): hundreds or thousands of units in scenes measured
    /// in pixels or metres, not the modest magnitude of other inputs.
    pub const SCENE: Facts = Facts(16384);
    /// Depends on a uniform whose name says it holds the time since the animation started
    /// (`iTime`, `u_time`): thousands of seconds once a page has been open an hour.
    pub const TIME: Facts = Facts(32768);
    /// The bits that say an ordinary value is larger than a modest one (what a unit vector,
    /// `normalize`'s result, no longer carries).
    pub const MAGNITUDE: Facts = Facts(8192 | 16384 | 32768);
    /// The dependency bits.
    pub const DEPS: Facts = Facts(256 | 512 | 1024 | 8192 | 16384 | 32768);
    /// The facts that are united on joins.
    pub const ALL_OR: Facts = Facts(128 | 256 | 512 | 1024 | 8192 | 16384 | 32768);

    /// No facts.
    pub const NONE: Facts = Facts(0);

    /// Whether every bit of `o` is set.
    pub fn has(self, o: Facts) -> bool {
        self.0 & o.0 == o.0
    }

    /// Whether any bit of `o` is set.
    pub fn any(self, o: Facts) -> bool {
        self.0 & o.0 != 0
    }

    /// Both sets of bits.
    pub fn with(self, o: Facts) -> Facts {
        Facts(self.0 | o.0)
    }

    /// Without the bits of `o`.
    pub fn without(self, o: Facts) -> Facts {
        Facts(self.0 & !o.0)
    }

    /// The bits of `o` set as `on` says.
    pub fn set(self, o: Facts, on: bool) -> Facts {
        if on {
            self.with(o)
        } else {
            self.without(o)
        }
    }

    /// Whether a value with these facts is the same for every vertex and pixel of a draw:
    /// uniforms reach it, inputs and texels do not.
    pub fn per_draw(self) -> bool {
        self.any(Facts::UNIFORM) && !self.any(Facts::INPUT.with(Facts::TEXTURE))
    }

    /// Only the bits of `o`.
    pub fn only(self, o: Facts) -> Facts {
        Facts(self.0 & o.0)
    }

    /// The facts of a value that may be either: intersect the first group, unite the second.
    pub fn join(self, o: Facts) -> Facts {
        Facts((self.0 & o.0 & Facts::ALL_AND.0) | ((self.0 | o.0) & Facts::ALL_OR.0))
    }
}

/// A scalar or vector (of up to four components).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Num {
    /// Number of components (1 for a scalar).
    pub n: u8,
    /// The components (those past `n` are unused).
    pub c: [Interval; 4],
    /// The Euclidean length of a vector, or `|x|` of a scalar.
    pub norm: Interval,
    /// What is known beyond intervals.
    pub facts: Facts,
}

/// An abstract value of any type.
#[derive(Clone, Debug, PartialEq)]
pub enum Val {
    /// No value yet (never stored, unreachable).
    Bot,
    /// A scalar or vector.
    Num(Num),
    /// A matrix (columns) or struct (members).
    Agg(Vec<Val>),
    /// An array: one element standing for every element.
    Arr(Box<Val>),
    /// A value the analysis does not follow (textures, samplers).
    Any,
}

/// The length of a vector with components in `c`.
pub fn norm_of(c: &[Interval]) -> Interval {
    let mut s = Interval::point(0.0);
    for x in c {
        s = s.add(x.sqr());
    }
    s.sqrt()
}

impl Num {
    /// The value with no possible values, the identity of [`Num::join`].
    pub fn bottom(n: u8) -> Num {
        Num {
            n,
            c: [Interval::EMPTY; 4],
            norm: Interval::EMPTY,
            facts: Facts::ALL_AND,
        }
    }

    /// A value with components `c` (its length follows from them), before facts.
    pub fn from_components(c: &[Interval], facts: Facts) -> Num {
        let mut out = Num::bottom(c.len().clamp(1, 4) as u8);
        for (i, x) in c.iter().take(4).enumerate() {
            out.c[i] = *x;
        }
        // `settle` sets the length from the components (of a value with some).
        out.norm = if out.is_bottom() {
            norm_of(c)
        } else {
            Interval::NON_NEGATIVE
        };
        out.facts = facts;
        out.settle()
    }

    /// A constant.
    pub fn constant(v: &[f64]) -> Num {
        let mut c = [Interval::EMPTY; 4];
        for (i, x) in v.iter().take(4).enumerate() {
            c[i] = Interval::point(*x);
        }
        Num::from_components(&c[..v.len().min(4)], Facts::NONE)
    }

    /// A scalar in `i`, with `facts`.
    pub fn scalar(i: Interval, facts: Facts) -> Num {
        Num::from_components(&[i], facts)
    }

    /// `n` components each in `i`, with `facts`.
    pub fn splat(i: Interval, n: u8, facts: Facts) -> Num {
        Num::from_components(&[i; 4][..(n as usize).min(4)], facts)
    }

    /// The used components.
    pub fn comps(&self) -> &[Interval] {
        &self.c[..self.n as usize]
    }

    /// Whether nothing is known to be possible (some component empty).
    pub fn is_bottom(&self) -> bool {
        self.comps().iter().any(|c| c.is_empty())
    }

    /// The hull of every component.
    pub fn hull(&self) -> Interval {
        self.comps().iter().fold(Interval::EMPTY, |a, b| a.hull(*b))
    }

    /// Component `i` as a scalar (a component of a non-zero vector may be zero).
    pub fn component(&self, i: usize) -> Num {
        let c = if i < self.n as usize {
            self.c[i]
        } else {
            Interval::EMPTY
        };
        let keep_nz = self.facts.has(Facts::EXT) || self.n == 1;
        Num::scalar(
            c,
            self.facts
                .set(Facts::NZ, keep_nz && self.facts.has(Facts::NZ))
                .without(Facts::CROSS),
        )
    }

    /// Whether it may be zero: a scalar may equal 0, a vector may be the zero vector.
    pub fn may_be_zero(&self) -> bool {
        self.comps().iter().all(|c| c.contains(0.0)) && self.norm.contains(0.0)
    }

    /// Sets the facts that the intervals prove, and tightens the length from the components.
    pub fn settle(mut self) -> Num {
        if self.is_bottom() {
            return self;
        }
        let n = self.n as usize;
        let from = if n == 1 {
            self.c[0].abs()
        } else {
            norm_of(&self.c[..n])
        };
        let m = self.norm.meet(from);
        self.norm = if m.is_empty() { from } else { m };
        let comps = &self.c[..n];
        if comps.iter().all(|c| c.lo >= 0.0) {
            self.facts = self.facts.with(Facts::NN);
        }
        if comps.iter().all(|c| c.lo > 0.0) {
            self.facts = self.facts.with(Facts::POS).with(Facts::NN);
        }
        if comps.iter().all(|c| c.hi <= 0.0) {
            self.facts = self.facts.with(Facts::NP);
        }
        if self.norm.lo > 0.0 || comps.iter().any(|c| !c.contains(0.0)) {
            self.facts = self.facts.with(Facts::NZ).without(Facts::CROSS);
        }
        if comps.iter().all(|c| c.within(Interval::SIGNED_UNIT)) {
            self.facts = self.facts.with(Facts::UNIT);
        }
        if comps
            .iter()
            .all(|c| c.as_point().is_some_and(|x| x.fract() == 0.0))
        {
            self.facts = self.facts.with(Facts::INTEGRAL);
        }
        if self.n == 3 && self.facts.has(Facts::NZ)
            || self.n >= 3 && comps[..3].iter().any(|c| !c.contains(0.0))
        {
            self.facts = self.facts.with(Facts::NZ3);
        }
        self
    }

    /// A value that may be either.
    pub fn join(&self, o: &Num) -> Num {
        if self.is_bottom() && self.comps().iter().all(|c| c.is_empty()) {
            return *o;
        }
        if o.is_bottom() && o.comps().iter().all(|c| c.is_empty()) {
            return *self;
        }
        let n = self.n.max(o.n);
        let mut r = Num::bottom(n);
        for i in 0..n as usize {
            r.c[i] = self.c[i].hull(o.c[i]);
        }
        r.norm = self.norm.hull(o.norm);
        r.facts = self.facts.join(o.facts);
        r
    }

    /// [`Num::join`], with bounds that grew since `self` jumping to infinity.
    pub fn widen(&self, o: &Num) -> Num {
        let j = self.join(o);
        let mut r = j;
        for i in 0..r.n as usize {
            r.c[i] = self.c[i].widen(j.c[i]);
        }
        r.norm = self.norm.widen(j.norm);
        r
    }

    /// Applies `f` to each component (pairs with `o`'s, a scalar `o` applying to each).
    pub fn zip(&self, o: &Num, f: impl Fn(Interval, Interval) -> Interval) -> Comps {
        let n = self.n.max(o.n).clamp(1, 4);
        let mut out = Comps {
            n,
            c: [Interval::EMPTY; 4],
        };
        for i in 0..n as usize {
            let a = self.c[i.min(self.n as usize - 1)];
            let b = o.c[i.min(o.n as usize - 1)];
            out.c[i] = f(a, b);
        }
        out
    }

    /// Applies `f` to each component.
    pub fn map(&self, f: impl Fn(Interval) -> Interval) -> Comps {
        let mut out = Comps {
            n: self.n.clamp(1, 4),
            c: [Interval::EMPTY; 4],
        };
        for i in 0..out.n as usize {
            out.c[i] = f(self.c[i]);
        }
        out
    }
}

/// Up to four components, without an allocation (what [`Num::map`] and [`Num::zip`] give):
/// a slice of intervals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comps {
    n: u8,
    c: [Interval; 4],
}

impl std::ops::Deref for Comps {
    type Target = [Interval];

    fn deref(&self) -> &[Interval] {
        &self.c[..self.n as usize]
    }
}

impl Val {
    /// The scalar or vector, if it is one.
    pub fn num(&self) -> Option<&Num> {
        match self {
            Val::Num(n) => Some(n),
            _ => None,
        }
    }

    /// Whether nothing is possible yet.
    pub fn is_bot(&self) -> bool {
        match self {
            Val::Bot => true,
            Val::Num(n) => n.is_bottom(),
            _ => false,
        }
    }

    /// A value that may be either.
    pub fn join(&self, o: &Val) -> Val {
        match (self, o) {
            (Val::Bot, x) | (x, Val::Bot) => x.clone(),
            (Val::Num(a), Val::Num(b)) => Val::Num(a.join(b)),
            (Val::Agg(a), Val::Agg(b)) if a.len() == b.len() => {
                Val::Agg(a.iter().zip(b).map(|(x, y)| x.join(y)).collect())
            }
            (Val::Arr(a), Val::Arr(b)) => Val::Arr(Box::new(a.join(b))),
            _ => Val::Any,
        }
    }

    /// [`Val::join`] with widening.
    pub fn widen(&self, o: &Val) -> Val {
        match (self, o) {
            (Val::Bot, x) | (x, Val::Bot) => x.clone(),
            (Val::Num(a), Val::Num(b)) => Val::Num(a.widen(b)),
            (Val::Agg(a), Val::Agg(b)) if a.len() == b.len() => {
                Val::Agg(a.iter().zip(b).map(|(x, y)| x.widen(y)).collect())
            }
            (Val::Arr(a), Val::Arr(b)) => Val::Arr(Box::new(a.widen(b))),
            _ => Val::Any,
        }
    }

    /// The facts every scalar and vector inside holds (the intersection), and where any of them
    /// comes from (the union).
    pub fn facts(&self) -> Facts {
        match self {
            Val::Bot => Facts::ALL_AND,
            Val::Num(n) => n.facts,
            Val::Agg(v) => v.iter().fold(Facts::ALL_AND, |f, x| f.join(x.facts())),
            Val::Arr(x) => x.facts(),
            Val::Any => Facts::NONE,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn join_intersects_and_facts_and_unites_or_facts() {
        let a = Num::scalar(Interval::new(0.0, 1.0), Facts::UNIFORM);
        let b = Num::scalar(Interval::new(-1.0, 0.5), Facts::INPUT);
        let j = a.join(&b);
        assert_eq!(j.c[0], Interval::new(-1.0, 1.0));
        assert!(!j.facts.has(Facts::NN));
        assert!(j.facts.has(Facts::UNIFORM) && j.facts.has(Facts::INPUT));
        assert_eq!(Num::bottom(1).join(&a), a);
    }

    #[test]
    fn settle_proves_facts_from_intervals() {
        let v = Num::from_components(
            &[Interval::new(0.5, 1.0), Interval::new(0.0, 1.0)],
            Facts::NONE,
        );
        assert!(v.facts.has(Facts::NN) && v.facts.has(Facts::NZ) && v.facts.has(Facts::UNIT));
        assert!(!v.may_be_zero());
        assert!(Num::constant(&[0.0, 0.0, 0.0]).may_be_zero());
    }
}
