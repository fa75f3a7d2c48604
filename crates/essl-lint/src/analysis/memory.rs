//! Memory and the shapes of values: the cell each variable holds (the join of every store),
//! reads and writes of a part of a cell, and the values of constants, external values and
//! values nothing is known about.

use naga::{Expression as E, Handle, Literal, ScalarKind, TypeInner};

use super::{function, Analysis, Mode, Place, Root, ANY, TYPICAL, TYPICAL_MATRIX};
use crate::interval::Interval;
use crate::value::{norm_of, Facts, Num, Val};

/// The type an expression's pointer points to (or the type itself for a value).
pub(super) fn pointee<'a>(module: &'a naga::Module, inner: &'a TypeInner) -> TypeInner {
    match inner {
        TypeInner::Pointer { base, .. } => module.types[*base].inner.clone(),
        TypeInner::ValuePointer {
            size: Some(size),
            scalar,
            ..
        } => TypeInner::Vector {
            size: *size,
            scalar: *scalar,
        },
        TypeInner::ValuePointer {
            size: None, scalar, ..
        } => TypeInner::Scalar(*scalar),
        other => other.clone(),
    }
}

/// A value of type `inner` whose scalars and vectors are made by `leaf(components, kind)`.
pub(super) fn shape(
    module: &naga::Module,
    inner: &TypeInner,
    leaf: &dyn Fn(u8, ScalarKind) -> Num,
) -> Val {
    shape_m(module, inner, &|n, k, _| leaf(n, k))
}

/// [`shape`] whose `leaf` also learns whether it makes a matrix column.
pub(super) fn shape_m(
    module: &naga::Module,
    inner: &TypeInner,
    leaf: &dyn Fn(u8, ScalarKind, bool) -> Num,
) -> Val {
    match inner {
        TypeInner::Scalar(s) => Val::Num(leaf(1, s.kind, false)),
        TypeInner::Vector { size, scalar } => Val::Num(leaf(*size as u8, scalar.kind, false)),
        TypeInner::Matrix {
            columns,
            rows,
            scalar,
        } => Val::Agg(
            (0..*columns as u8)
                .map(|_| Val::Num(leaf(*rows as u8, scalar.kind, true)))
                .collect(),
        ),
        TypeInner::Array { base, .. } => {
            Val::Arr(Box::new(shape_m(module, &module.types[*base].inner, leaf)))
        }
        TypeInner::Struct { members, .. } => Val::Agg(
            members
                .iter()
                .map(|m| shape_m(module, &module.types[m.ty].inner, leaf))
                .collect(),
        ),
        _ => Val::Any,
    }
}

/// Reads the part of `v` at `path`.
pub(super) fn read(v: &Val, path: &[u32]) -> Val {
    let Some((&step, rest)) = path.split_first() else {
        return v.clone();
    };
    match v {
        Val::Arr(x) => read(x, rest),
        Val::Agg(xs) if step == ANY => xs.iter().fold(Val::Bot, |a, x| a.join(&read(x, rest))),
        Val::Agg(xs) => xs
            .get(step as usize)
            .map(|x| read(x, rest))
            .unwrap_or(Val::Any),
        Val::Num(n) if rest.is_empty() => {
            if step == ANY {
                let h = n.hull();
                Val::Num(Num::scalar(h, n.component(0).facts))
            } else {
                Val::Num(n.component(step as usize))
            }
        }
        Val::Bot => Val::Bot,
        _ => Val::Any,
    }
}

/// Joins (or widens) `new` into the part of `v` at `path`; returns whether `v` changed.
pub(super) fn write(v: &mut Val, path: &[u32], new: &Val, widen: bool) -> bool {
    let Some((&step, rest)) = path.split_first() else {
        let j = if widen {
            v.widen(&v.join(new))
        } else {
            v.join(new)
        };
        let changed = j != *v;
        *v = j;
        return changed;
    };
    match v {
        Val::Arr(x) => write(x, rest, new, widen),
        Val::Agg(xs) if step == ANY => {
            let mut c = false;
            for x in xs.iter_mut() {
                c |= write(x, rest, new, widen);
            }
            c
        }
        Val::Agg(xs) => match xs.get_mut(step as usize) {
            Some(x) => write(x, rest, new, widen),
            None => false,
        },
        Val::Num(n) if rest.is_empty() => {
            let Some(s) = new.num() else { return false };
            if s.is_bottom() {
                return false;
            }
            let old = *n;
            let targets: Vec<usize> = if step == ANY {
                (0..n.n as usize).collect()
            } else {
                vec![step as usize]
            };
            for i in targets {
                if i < n.n as usize {
                    let j = n.c[i].hull(s.c[0]);
                    n.c[i] = if widen { n.c[i].widen(j) } else { j };
                }
            }
            // A vector changed in one component keeps no length fact.
            n.facts = n.facts.join(s.facts).without(Facts::NZ).without(Facts::EXT);
            n.norm = norm_of(n.comps());
            *n = n.settle();
            *n != old
        }
        _ => false,
    }
}

impl Analysis {
    /// The memory cell of a root, created with its type's shape when new.
    pub(super) fn cell(&self, module: &naga::Module, root: Root) -> Val {
        if let Some(v) = self.memory.get(&root) {
            return v.clone();
        }
        let ty = match root {
            Root::Local(f, l) => {
                let func = function(module, f);
                let h = func
                    .local_variables
                    .iter()
                    .nth(l)
                    .map(|(h, _)| h)
                    .expect("local");
                module.types[func.local_variables[h].ty].inner.clone()
            }
            Root::Global(g) => {
                let h = module
                    .global_variables
                    .iter()
                    .nth(g)
                    .map(|(h, _)| h)
                    .expect("global");
                module.types[module.global_variables[h].ty].inner.clone()
            }
            Root::Arg(f, i) => pointee(
                module,
                &module.types[function(module, f).arguments[i].ty].inner,
            ),
        };
        shape(module, &ty, &|n, _| Num::bottom(n))
    }

    pub(super) fn store(&mut self, module: &naga::Module, place: &Place, v: &Val) {
        self.store_within(module, place, v, None);
    }

    /// [`Analysis::store`], the variable then met with `bound` (a series' sum, which widening
    /// would otherwise send to infinity).
    pub(super) fn store_within(
        &mut self,
        module: &naga::Module,
        place: &Place,
        v: &Val,
        bound: Option<&[crate::interval::Interval]>,
    ) {
        if self.calls.walking() {
            return; // a walk for one call changes no cell
        }
        if let Root::Global(g) = place.root {
            let h = module
                .global_variables
                .iter()
                .nth(g)
                .map(|(h, _)| h)
                .expect("global");
            if module.global_variables[h].space != naga::AddressSpace::Private {
                return;
            }
        }
        let mut cell = self.cell(module, place.root);
        let changed = match bound {
            Some(b) => {
                let old = cell.clone();
                write(&mut cell, &place.path, v, self.widening);
                cell = super::series::clamp(&cell, b);
                cell != old
            }
            None => write(&mut cell, &place.path, v, self.widening),
        };
        if changed {
            self.changed = true;
            self.stale |= self.reads.borrow().roots.contains(&place.root);
        }
        self.memory.insert(place.root, cell);
    }

    pub(super) fn load(&self, module: &naga::Module, place: &Place, ty: &TypeInner) -> Val {
        if let Root::Global(g) = place.root {
            let h = module
                .global_variables
                .iter()
                .nth(g)
                .map(|(h, _)| h)
                .expect("global");
            let global = &module.global_variables[h];
            if global.space != naga::AddressSpace::Private {
                // A uniform whose name (a block's member's) says it holds a position or a time.
                let said = &self.uniform_names[g];
                let said = match (&module.types[global.ty].inner, place.path.first()) {
                    (TypeInner::Struct { .. }, Some(&m)) => said.get(m as usize + 1),
                    _ => said.first(),
                };
                return match said.and_then(|s| s.kind(ty)) {
                    Some(k @ (super::names::Kind::Position | super::names::Kind::Time)) => {
                        self.named(module, ty, k, Facts::UNIFORM)
                    }
                    _ => self.external(module, ty, Facts::UNIFORM),
                };
            }
        }
        self.note_read(place.root);
        read(&self.cell(module, place.root), &place.path)
    }

    /// Records that a user function read the cell of `root` this round.
    pub(super) fn note_read(&self, root: Root) {
        if !self.walking_entry {
            self.reads.borrow_mut().roots.insert(root);
        }
    }

    /// An external value of type `ty` (a uniform, an input), depending on `deps`.
    pub fn external(&self, module: &naga::Module, ty: &TypeInner, deps: Facts) -> Val {
        let mode = self.mode;
        shape_m(module, ty, &|n, kind, matrix| {
            let i = match (kind, mode) {
                (ScalarKind::Bool, _) => Interval::UNIT,
                (ScalarKind::Uint, Mode::Sound) => Interval::NON_NEGATIVE,
                (_, Mode::Sound) => Interval::FULL,
                (_, Mode::Typical) if matrix => Interval::new(0.0, TYPICAL_MATRIX),
                (_, Mode::Typical) => Interval::new(0.0, TYPICAL),
            };
            let int = matches!(kind, ScalarKind::Sint | ScalarKind::Uint);
            Num::splat(
                i,
                n,
                Facts::NONE
                    .set(Facts::INTEGRAL, int)
                    .with(Facts::NN)
                    .with(Facts::POS)
                    .with(Facts::NZ)
                    .with(Facts::NZ3)
                    .with(Facts::UNIT)
                    .with(Facts::EXT)
                    .with(deps),
            )
        })
    }

    /// A value of type `ty` about which nothing is known but where it comes from.
    pub(super) fn unknown(module: &naga::Module, ty: &TypeInner, deps: Facts) -> Val {
        shape(module, ty, &|n, kind| {
            let i = match kind {
                ScalarKind::Bool => Interval::UNIT,
                ScalarKind::Uint => Interval::NON_NEGATIVE,
                _ => Interval::FULL,
            };
            let int = matches!(kind, ScalarKind::Sint | ScalarKind::Uint);
            Num::splat(i, n, deps.only(Facts::DEPS).set(Facts::INTEGRAL, int))
        })
    }

    pub(super) fn join_into(slot: &mut Val, v: &Val, widen: bool, changed: &mut bool) {
        let j = if widen {
            slot.widen(&slot.join(v))
        } else {
            slot.join(v)
        };
        if j != *slot {
            *slot = j;
            *changed = true;
        }
    }
}

/// A literal's value.
pub fn literal(l: &Literal) -> f64 {
    match *l {
        Literal::F64(v) | Literal::AbstractFloat(v) => v,
        Literal::F32(v) => v as f64,
        Literal::U32(v) => v as f64,
        Literal::I32(v) => v as f64,
        Literal::U64(v) => v as f64,
        Literal::I64(v) | Literal::AbstractInt(v) => v as f64,
        Literal::Bool(b) => b as u8 as f64,
        Literal::U16(v) => v as f64,
        Literal::I16(v) => v as f64,
        Literal::F16(v) => f64::from(v),
    }
}

/// The value of a constant expression of the module.
pub fn const_value(module: &naga::Module, h: Handle<E>) -> Val {
    let ty_of = |c: &[Handle<E>]| c.to_vec();
    match &module.global_expressions[h] {
        E::Literal(l) => Val::Num(Num::constant(&[literal(l)])),
        E::Constant(c) => const_value(module, module.constants[*c].init),
        E::ZeroValue(t) => shape(module, &module.types[*t].inner, &|n, _| {
            Num::constant(&vec![0.0; n as usize])
        }),
        E::Splat { size, value } => match const_value(module, *value) {
            Val::Num(x) => Val::Num(Num::splat(x.c[0], *size as u8, x.facts)),
            other => other,
        },
        E::Compose { ty, components } => {
            let parts: Vec<Val> = ty_of(components)
                .iter()
                .map(|c| const_value(module, *c))
                .collect();
            match &module.types[*ty].inner {
                TypeInner::Vector { .. } => {
                    let mut comps = Vec::new();
                    for p in &parts {
                        match p.num() {
                            Some(n) => comps.extend_from_slice(n.comps()),
                            None => return Val::Any,
                        }
                    }
                    Val::Num(Num::from_components(&comps, Facts::NONE))
                }
                TypeInner::Array { .. } => {
                    Val::Arr(Box::new(parts.iter().fold(Val::Bot, |a, p| a.join(p))))
                }
                _ => Val::Agg(parts),
            }
        }
        _ => Val::Any,
    }
}
