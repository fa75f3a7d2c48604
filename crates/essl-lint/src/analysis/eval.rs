//! The value of each expression: constants, arguments, variables and their parts, loads
//! (bounded by the enclosing conditions), vector construction, conversions and texels; the
//! operators and built-in functions have modules of their own.

use naga::{Expression as E, Handle, ScalarKind, TypeInner, UnaryOperator as Uo};

use super::memory::{const_value, literal, pointee, read, shape};
use super::{names, Analysis, Mode, Place, Root, Site, ANY, EPS};
use crate::interval::Interval;
use crate::value::{Facts, Num, Val};

impl Analysis {
    /// `v.z / length(v)`, a component of a vector over the vector's length: in [-1, 1] in exact
    /// arithmetic, and a few ulps past it after rounding.
    fn part_over_length(&self, s: Site, e: &E, v: Val) -> Val {
        let E::Binary {
            op: naga::BinaryOperator::Divide,
            left,
            right,
        } = *e
        else {
            return v;
        };
        let right = crate::symbolic::resolve(s.f, self, s.id, right);
        let E::Math {
            fun: naga::MathFunction::Length,
            arg,
            ..
        } = s.f.expressions[right]
        else {
            return v;
        };
        let base = match s.f.expressions[left] {
            E::AccessIndex { base, .. } => base,
            E::Load { pointer } => match s.f.expressions[pointer] {
                E::AccessIndex { base, .. } => match s.f.expressions[base] {
                    E::LocalVariable(_) | E::FunctionArgument(_) => base,
                    _ => return v,
                },
                _ => return v,
            },
            _ => return v,
        };
        let same = self.same(s.f, s.id, base, arg)
            || matches!(s.f.expressions[arg], E::Load { pointer } if pointer == base);
        match v {
            Val::Num(mut n) if same && !n.is_bottom() => {
                let unit = Interval::new(-1.0 - 1e-6, 1.0 + 1e-6);
                for c in &mut n.c[..n.n as usize] {
                    let m = c.meet(unit);
                    if !m.is_empty() {
                        *c = m;
                    }
                }
                Val::Num(n.settle())
            }
            other => other,
        }
    }

    /// The value of expression `h` of function `id` (evaluated already).
    pub(super) fn v(&self, id: usize, h: Handle<E>) -> &Val {
        &self.functions[id].values[h.index()]
    }

    /// The number `h` of function `id` is, if it is a scalar or vector with a value.
    pub(super) fn nm(&self, id: usize, h: Handle<E>) -> Option<Num> {
        self.functions[id].values[h.index()]
            .num()
            .copied()
            .filter(|n| !n.is_bottom())
    }

    /// Evaluates expression `h`: its value, and the place it points to when it is a pointer.
    pub(super) fn eval(&mut self, s: Site, h: Handle<E>) {
        let ty = s.ty(h);
        let e = &s.f.expressions[h];
        let (val, place) = match self.variable(s, h, e, ty) {
            Some(vp) => vp,
            None => (self.operation(s, e, ty), None),
        };
        let val = within_type(val, ty);
        let val = self.part_over_length(s, e, val);
        if let E::Load { pointer } = *e {
            if let Some(p) = self.functions[s.id].places[pointer.index()].clone() {
                let v = self.load_version(&p);
                self.functions[s.id].load_version[h.index()] = v;
            }
        }
        let ff = &mut self.functions[s.id];
        ff.values[h.index()] = val;
        ff.places[h.index()] = place;
    }

    /// The facts about where the values of `hs` come from.
    fn deps_of(&self, id: usize, hs: &[Handle<E>]) -> Facts {
        hs.iter().fold(Facts::NONE, |acc, x| {
            acc.with(self.v(id, *x).facts().only(Facts::DEPS))
        })
    }

    /// Where a texel read at `coordinate` comes from: a texture, and the uniforms the coordinate
    /// reads. Not the coordinate's inputs: the texel is constant over whole regions of the
    /// picture (where the texture is), not a value that varies per pixel as the inputs do.
    fn texel_deps(&self, id: usize, coordinate: Handle<E>) -> Facts {
        // A texel's magnitude is the texture's, not its coordinates' (window coordinates).
        self.deps_of(id, &[coordinate])
            .without(Facts::INPUT.with(Facts::MAGNITUDE))
            .with(Facts::TEXTURE)
    }

    /// The value (and place) of a constant, an argument, a variable, a call's result, a part of
    /// a variable, or of anything the entry point computes; `None` for other operations.
    fn variable(
        &self,
        s: Site,
        h: Handle<E>,
        e: &E,
        ty: &TypeInner,
    ) -> Option<(Val, Option<Place>)> {
        let (module, id) = (s.module, s.id);
        let entry = self.functions[id].entry;
        let at = |root: Root| {
            Some((
                Val::Any,
                Some(Place {
                    root,
                    path: Vec::new(),
                }),
            ))
        };
        let val = match e {
            E::Literal(l) => Val::Num(Num::constant(&[literal(l)])),
            E::Constant(c) => const_value(module, module.constants[*c].init),
            // essl reads a variable it does not lower (one only dead code uses: an inactive
            // input, uniform or sampler) as a zero with no span: a value the shader never
            // computes, not a zero vector to report.
            E::ZeroValue(_) if not_computed(s, h, ty) => Val::Bot,
            E::ZeroValue(_) => shape(module, ty, &|n, _| Num::constant(&vec![0.0; n as usize])),
            E::Override(_) => self.external(module, ty, Facts::UNIFORM),
            E::FunctionArgument(i) => {
                if matches!(
                    ty,
                    TypeInner::Pointer { .. } | TypeInner::ValuePointer { .. }
                ) {
                    return at(Root::Arg(id, *i as usize));
                } else {
                    let kind = self.arg_names[id]
                        .get(*i as usize)
                        .and_then(|said| said.kind(ty));
                    if entry {
                        let binding = s.f.arguments[*i as usize].binding.as_ref();
                        match kind {
                            Some(k) => self.named(module, ty, k, Facts::INPUT),
                            None if frag_coord(module, binding) => match self.mode {
                                Mode::Typical => frag_coord_value(),
                                Mode::Sound => {
                                    self.external(module, ty, Facts::INPUT.with(Facts::WINDOW))
                                }
                            },
                            None => self.external(module, ty, Facts::INPUT),
                        }
                    } else {
                        self.reads.borrow_mut().args.insert(id);
                        let v = self.args[id].get(*i as usize).cloned().unwrap_or(Val::Any);
                        match kind {
                            // What the callers pass already says its magnitude (window
                            // coordinates): the name adds nothing.
                            Some(names::Kind::Position | names::Kind::Time)
                                if v.facts().any(Facts::MAGNITUDE) =>
                            {
                                v
                            }
                            Some(k) if names::as_such(&v) => {
                                self.named(module, ty, k, Facts::INPUT)
                            }
                            _ => v,
                        }
                    }
                }
            }
            E::GlobalVariable(g) => return at(Root::Global(g.index())),
            E::LocalVariable(l) => return at(Root::Local(id, l.index())),
            E::CallResult(fh) => self.results[fh.index()].clone(),
            E::Access { base, .. } | E::AccessIndex { base, .. }
                if self.functions[id].places[base.index()].is_some() =>
            {
                return Some((Val::Any, self.access_place(s, e)));
            }
            // The entry point only moves data between the pipeline and private variables
            // (`gl_FragCoord` with its `y` flipped, composed again).
            _ if entry => {
                let parts: Vec<Handle<E>> = match e {
                    E::Compose { components, .. } => components.clone(),
                    E::Binary { left, right, .. } => vec![*left, *right],
                    E::AccessIndex { base, .. } => vec![*base],
                    _ => Vec::new(),
                };
                let window = self.deps_of(id, &parts).only(Facts::WINDOW);
                match self.mode {
                    Mode::Typical if window.has(Facts::WINDOW) && parts.len() == 4 => {
                        frag_coord_value()
                    }
                    _ => self.external(module, ty, Facts::INPUT.with(window)),
                }
            }
            _ => return None,
        };
        Some((val, None))
    }

    /// The value of an operation on values.
    fn operation(&self, s: Site, e: &E, ty: &TypeInner) -> Val {
        let (module, id) = (s.module, s.id);
        match e {
            E::Access { base, .. } => match self.v(id, *base) {
                Val::Arr(x) => (**x).clone(),
                Val::Agg(xs) => xs.iter().fold(Val::Bot, |a, x| a.join(x)),
                Val::Num(n) => read(&Val::Num(*n), &[ANY]),
                other => other.clone(),
            },
            E::AccessIndex { base, index } => match self.v(id, *base) {
                Val::Arr(x) => (**x).clone(),
                Val::Agg(xs) => xs.get(*index as usize).cloned().unwrap_or(Val::Any),
                Val::Num(n) => Val::Num(n.component(*index as usize)),
                other => other.clone(),
            },
            E::Load { pointer } => match self.functions[id].places[pointer.index()].clone() {
                Some(p) => {
                    let v = self
                        .current_value(&p)
                        .unwrap_or_else(|| self.load(module, &p, ty));
                    if self.refine.is_empty() {
                        v
                    } else {
                        let integer =
                            matches!(ty.scalar_kind(), Some(ScalarKind::Sint | ScalarKind::Uint));
                        self.refined(&p, v, integer)
                    }
                }
                None => Self::unknown(module, ty, Facts::NONE),
            },
            E::Splat { size, value } => self.splat(id, *size as u8, *value),
            E::Swizzle {
                size,
                vector,
                pattern,
            } => self.swizzle(id, &pattern[..*size as usize], *vector),
            E::Compose { components, .. } => self.compose(s, ty, components),
            E::Unary { op, expr } => self.unary(s, ty, *op, *expr),
            E::Binary { op, left, right } => self.binary(s, ty, *op, *left, *right),
            E::Select { accept, reject, .. } => self.v(id, *accept).join(self.v(id, *reject)),
            E::Derivative { axis, expr, .. } => self.derivative(id, *axis, *expr),
            E::Relational { argument, .. } => {
                let deps = self.deps_of(id, &[*argument]);
                shape(module, ty, &|n, _| Num::splat(Interval::UNIT, n, deps))
            }
            E::As {
                expr,
                kind,
                convert,
            } => self.convert(module, ty, id, *expr, *kind, *convert),
            E::Math { .. } => self.math(s, ty, e),
            E::ImageSample {
                coordinate,
                depth_ref,
                ..
            } => {
                let deps = self.texel_deps(id, *coordinate);
                if depth_ref.is_some() {
                    Val::Num(Num::scalar(Interval::UNIT, deps.with(Facts::EXT)))
                } else {
                    self.texel(module, ty, deps)
                }
            }
            E::ImageLoad { coordinate, .. } => {
                let deps = self.texel_deps(id, *coordinate);
                self.texel(module, ty, deps)
            }
            // Sizes, levels, layers and samples of a bound (complete) texture: at least 1.
            E::ImageQuery { .. } => shape(module, ty, &|n, _| {
                Num::splat(Interval::new(1.0, f64::INFINITY), n, Facts::NONE)
            }),
            _ => Self::unknown(module, ty, Facts::NONE),
        }
    }

    /// A scalar repeated `n` times.
    fn splat(&self, id: usize, n: u8, value: Handle<E>) -> Val {
        match self.nm(id, value) {
            Some(x) => {
                let mut r = Num::splat(x.c[0], n, x.facts);
                r.norm = r.norm.meet(
                    x.c[0]
                        .abs()
                        .mul(Interval::point((n as f64).sqrt()))
                        .slack(EPS),
                );
                Val::Num(r.settle())
            }
            None => Val::Bot,
        }
    }

    /// The components `pattern` of `vector`: a permutation keeps the length and its facts.
    fn swizzle(&self, id: usize, pattern: &[naga::SwizzleComponent], vector: Handle<E>) -> Val {
        let Some(x) = self.nm(id, vector) else {
            return Val::Bot;
        };
        let idx: Vec<usize> = pattern.iter().map(|c| *c as usize).collect();
        let comps: Vec<Interval> = idx.iter().map(|&i| x.c[i.min(x.n as usize - 1)]).collect();
        let mut sorted = idx.clone();
        sorted.sort_unstable();
        sorted.dedup();
        let permutation = sorted.len() == x.n as usize && idx.len() == x.n as usize;
        let xyz = idx.len() == 3 && sorted == [0, 1, 2];
        let nz = x.facts.has(Facts::NZ) && (permutation || x.facts.has(Facts::EXT))
            || xyz && x.facts.has(Facts::NZ3);
        let facts = x
            .facts
            .set(Facts::NZ, nz)
            .set(Facts::NZ3, permutation && x.facts.has(Facts::NZ3))
            .set(Facts::CROSS, permutation && x.facts.any(Facts::CROSS));
        let mut r = Num::from_components(&comps, facts);
        if permutation {
            r.norm = r.norm.meet(x.norm);
        }
        Val::Num(r.settle())
    }

    /// `-x`, `!x` and the bit operators.
    fn unary(&self, s: Site, ty: &TypeInner, op: Uo, expr: Handle<E>) -> Val {
        match (op, self.nm(s.id, expr)) {
            (Uo::Negate, Some(x)) => {
                let keep = x
                    .facts
                    .only(
                        Facts::NZ
                            .with(Facts::NZ3)
                            .with(Facts::UNIT)
                            .with(Facts::DIFF)
                            .with(Facts::EXT)
                            .with(Facts::INTEGRAL)
                            .with(Facts::ALL_OR),
                    )
                    .set(Facts::NP, x.facts.has(Facts::NN))
                    .set(Facts::NN, x.facts.has(Facts::NP));
                let mut r = Num::from_components(&x.map(Interval::neg), keep);
                r.norm = r.norm.meet(x.norm);
                Val::Num(r.settle())
            }
            (Uo::LogicalNot, Some(x)) => {
                Val::Num(Num::splat(Interval::UNIT, x.n, x.facts.only(Facts::DEPS)))
            }
            (_, Some(x)) => Self::unknown(s.module, ty, x.facts),
            (_, None) => Val::Bot,
        }
    }

    /// `dFdx`, `dFdy`, `fwidth`: 0 for a constant, non-negative for `fwidth`.
    fn derivative(&self, id: usize, axis: naga::DerivativeAxis, expr: Handle<E>) -> Val {
        match self.nm(id, expr) {
            Some(x) => {
                let deps = x.facts.only(Facts::DEPS);
                if x.comps().iter().all(|c| c.as_point().is_some()) {
                    Val::Num(Num::splat(Interval::point(0.0), x.n, deps))
                } else if axis == naga::DerivativeAxis::Width {
                    Val::Num(Num::splat(Interval::NON_NEGATIVE, x.n, deps))
                } else {
                    Val::Num(Num::splat(Interval::FULL, x.n, deps))
                }
            }
            None => Val::Bot,
        }
    }

    /// A texel: unknown in [`Mode::Sound`], in `[0, 1]` in [`Mode::Typical`].
    pub(super) fn texel(&self, module: &naga::Module, ty: &TypeInner, deps: Facts) -> Val {
        match self.mode {
            Mode::Sound => self.external(module, ty, deps),
            Mode::Typical => shape(module, ty, &|n, _| {
                Num::splat(Interval::UNIT, n, Facts::EXT.with(deps))
            }),
        }
    }

    /// The place a part of a variable is (an array element stands for every element).
    fn access_place(&self, s: Site, e: &E) -> Option<Place> {
        let (base, index) = match e {
            E::Access { base, .. } => (*base, ANY),
            E::AccessIndex { base, index } => (*base, *index),
            _ => return None,
        };
        let mut p = self.functions[s.id].places[base.index()].clone()?;
        let pointee = pointee(s.module, s.ty(base));
        let step = match pointee {
            TypeInner::Array { .. } => 0,
            _ => index,
        };
        p.path.push(step);
        Some(p)
    }

    /// A vector, matrix, array or struct built from its parts.
    fn compose(&self, s: Site, ty: &TypeInner, components: &[Handle<E>]) -> Val {
        let (module, f, id) = (s.module, s.f, s.id);
        match ty {
            TypeInner::Vector { .. } | TypeInner::Scalar(_) => {
                let mut comps = Vec::new();
                let mut facts = Facts::ALL_AND.without(Facts::NZ);
                let mut nz = false;
                let mut nz3 = false;
                for c in components {
                    let Some(x) = self.nm(id, *c) else {
                        return Val::Bot;
                    };
                    let start = comps.len();
                    comps.extend_from_slice(x.comps());
                    nz |= x.facts.has(Facts::NZ);
                    nz3 |= (start + x.n as usize <= 3 && x.facts.has(Facts::NZ))
                        || (start == 0 && x.facts.has(Facts::NZ3));
                    facts = facts.join(x.facts.without(Facts::NZ));
                }
                // `vec3(sin(a), y, cos(a))`: a sine and a cosine of one angle are not both 0.
                let trig = |fun: naga::MathFunction| {
                    components
                        .iter()
                        .filter_map(move |c| match f.expressions[*c] {
                            E::Math { fun: g, arg, .. } if g == fun => Some(arg),
                            _ => None,
                        })
                };
                if trig(naga::MathFunction::Sin)
                    .any(|a| trig(naga::MathFunction::Cos).any(|b| self.same(f, id, a, b)))
                {
                    nz = true;
                }
                // `vec3(v)` of a vec4 `v` is lowered as a compose of `v[0]`, `v[1]`, `v[2]`.
                if let [a, b, c] = components {
                    if let (
                        E::AccessIndex { base: b0, index: 0 },
                        E::AccessIndex { base: b1, index: 1 },
                        E::AccessIndex { base: b2, index: 2 },
                    ) = (&f.expressions[*a], &f.expressions[*b], &f.expressions[*c])
                    {
                        if b0 == b1 && b1 == b2 && self.v(id, *b0).facts().has(Facts::NZ3) {
                            nz = true;
                        }
                    }
                }
                Val::Num(Num::from_components(
                    &comps,
                    facts
                        .set(Facts::NZ, nz)
                        .set(Facts::NZ3, nz3)
                        .without(Facts::DIFF)
                        .without(Facts::CROSS),
                ))
            }
            TypeInner::Array { .. } => Val::Arr(Box::new(
                components
                    .iter()
                    .fold(Val::Bot, |a, c| a.join(self.v(id, *c))),
            )),
            TypeInner::Matrix { .. } | TypeInner::Struct { .. } => {
                Val::Agg(components.iter().map(|c| self.v(id, *c).clone()).collect())
            }
            _ => Self::unknown(module, ty, Facts::NONE),
        }
    }

    /// A conversion to another scalar kind (`convert`: `None` for a bit cast).
    fn convert(
        &self,
        module: &naga::Module,
        ty: &TypeInner,
        id: usize,
        expr: Handle<E>,
        kind: ScalarKind,
        convert: Option<u8>,
    ) -> Val {
        let Some(x) = self.nm(id, expr) else {
            return Val::Bot;
        };
        let deps = x.facts.only(Facts::DEPS);
        if convert.is_none() {
            return Self::unknown(module, ty, deps);
        }
        if kind == ScalarKind::Bool {
            return Val::Num(Num::splat(Interval::UNIT, x.n, deps));
        }
        let comps = match kind {
            ScalarKind::Sint | ScalarKind::Uint => x.map(|c| {
                let t = c.trunc();
                if kind == ScalarKind::Uint {
                    t.meet(Interval::NON_NEGATIVE).hull(if t.lo < 0.0 {
                        Interval::NON_NEGATIVE
                    } else {
                        Interval::EMPTY
                    })
                } else {
                    t
                }
            }),
            _ => x.map(|c| c),
        };
        let keep = if kind == ScalarKind::Float {
            x.facts
        } else {
            x.facts
                .without(Facts::POS)
                .without(Facts::NZ)
                .with(Facts::INTEGRAL)
        };
        Val::Num(Num::from_components(&comps, keep.without(Facts::DIFF)))
    }
}

/// An integer value within its type's range (`uint` bits times 2^-32 are below 1).
fn within_type(v: Val, ty: &TypeInner) -> Val {
    let range = match ty.scalar_kind() {
        Some(ScalarKind::Uint) => Interval::new(0.0, u32::MAX as f64),
        Some(ScalarKind::Sint) => Interval::new(i32::MIN as f64, i32::MAX as f64),
        _ => return v,
    };
    match v {
        Val::Num(mut n) if !n.is_bottom() => {
            for c in &mut n.c[..n.n as usize] {
                let m = c.meet(range);
                if !m.is_empty() {
                    *c = m;
                }
            }
            Val::Num(n.settle())
        }
        other => other,
    }
}

/// Whether expression `h` (a `ZeroValue`) stands for a variable essl did not lower: no span,
/// and not an integer (essl's own integer zeros, `0u - x`, have no span either).
fn not_computed(s: Site, h: Handle<E>, ty: &TypeInner) -> bool {
    let integer = matches!(ty.scalar_kind(), Some(ScalarKind::Sint | ScalarKind::Uint));
    !integer && s.f.expressions.get_span(h) == naga::Span::default()
}

/// The largest ordinary window coordinate in [`Mode::Typical`]: a canvas of 2048 pixels.
pub(crate) const WINDOW: f64 = 2048.0;

/// Whether an entry point's argument with `binding` is a fragment shader's `gl_FragCoord`.
fn frag_coord(module: &naga::Module, binding: Option<&naga::Binding>) -> bool {
    matches!(
        binding,
        Some(naga::Binding::BuiltIn(naga::BuiltIn::Position { .. }))
    ) && module
        .entry_points
        .first()
        .is_some_and(|e| e.stage == naga::ShaderStage::Fragment)
}

/// `gl_FragCoord` in [`Mode::Typical`]: window coordinates are pixels, not the modest
/// magnitudes of other inputs (`dot(c, c)` of `c = gl_FragCoord.xy` is past `mediump`'s 65504
/// for every pixel 256 from the corner); depth in `[0, 1]`, `1/w` positive.
fn frag_coord_value() -> Val {
    let xy = Interval::new(0.0, WINDOW);
    let c = [xy, xy, Interval::UNIT, Interval::new(0.0, super::TYPICAL)];
    let facts = Facts::NN
        .with(Facts::EXT)
        .with(Facts::INPUT)
        .with(Facts::WINDOW);
    Val::Num(Num::from_components(&c, facts))
}
