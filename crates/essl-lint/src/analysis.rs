//! The value-range analysis: abstract interpretation of a validated naga module.
//!
//! Every expression of every function gets a [`Val`]: intervals per component and [`Facts`].
//! Memory is flow-insensitive: each variable (a local, a private global, a pointer parameter)
//! holds the join of every value ever stored into it, and a load reads that join. Calls are
//! context-insensitive: a function's parameters hold the join of the arguments of every call,
//! its result the join of every `return`, and a pointer parameter shares its cell with the
//! variables callers pass. The whole module is iterated to a fixpoint, with widening after a
//! few rounds so that loops terminate.
//!
//! External values are unknown: uniforms, the entry point's inputs and texels are `(−∞, ∞)`
//! in [`Mode::Sound`]. [`Mode::Typical`] runs the same analysis with external values of
//! ordinary magnitude and the signs formulas expect (`[0, 10]`, matrix entries and texels in
//! `[0, 1]`): what the
//! `mediump` rule needs to ask "does this overflow for ordinary parameter values?".

use rustc_hash::FxHashMap as HashMap;

use naga::{
    BinaryOperator as Bo, Block, Expression as E, Function, Handle, Literal, MathFunction as Mf,
    ScalarKind, Statement, TypeInner, UnaryOperator as Uo,
};

use crate::interval::Interval;
use crate::value::{norm_of, Facts, Num, Val};

/// The magnitude of an ordinary external value in [`Mode::Typical`]: modest, so that what
/// overflows there overflows for values any scene uses (larger magnitudes are the runtime
/// check's to judge, with the actual values).
pub const TYPICAL: f64 = 10.0;
/// The magnitude of an ordinary external matrix entry in [`Mode::Typical`] (rotations, scales
/// and normal matrices; translations reach vectors through `M * vec4(p, 1.0)`).
pub const TYPICAL_MATRIX: f64 = 1.0;

/// Relative slack for GPU approximations of transcendental functions (a few ulps of `highp`).
pub const EPS: f64 = 1.0 / (1u64 << 20) as f64;

/// Rounds before joins become widenings.
const WIDEN_AFTER: usize = 6;
/// A bound on rounds (widening converges long before).
const MAX_ROUNDS: usize = 40;

/// What external values are assumed to be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Anything: the analysis is sound for every value.
    Sound,
    /// Ordinary magnitudes (`[0, TYPICAL]`, matrix entries and texels in `[0, 1]`).
    Typical,
}

/// A variable the analysis tracks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Root {
    /// A local variable: (function, local index).
    Local(usize, usize),
    /// A global variable.
    Global(usize),
    /// The cell behind a pointer parameter: (function, argument index).
    Arg(usize, usize),
}

/// A path step standing for any index (a dynamic index into a vector or matrix).
pub const ANY: u32 = u32::MAX;

/// A part of a variable: its root and the member / column / component indices to it (array
/// elements are summarised: their index is always 0).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Place {
    /// The variable.
    pub root: Root,
    /// The indices.
    pub path: Vec<u32>,
}

/// What the analysis knows about one function.
#[derive(Clone, Debug, Default)]
pub struct FnFacts {
    /// The value of each expression (by handle index).
    pub values: Vec<Val>,
    /// The place each pointer expression points to.
    pub places: Vec<Option<Place>>,
    /// The `Emit` statement that evaluates each expression (0: none).
    pub emit: Vec<u32>,
    /// Locals stored exactly once, outside loops, never passed by pointer: the stored value.
    pub single_store: HashMap<usize, Handle<E>>,
    /// Every value stored whole into a local that is never stored in part or passed by pointer.
    pub stores: HashMap<usize, Vec<Handle<E>>>,
    /// Whether this is an entry point (the wrapper essl generates, not user code).
    pub entry: bool,
}

/// The analysis of a whole module.
#[derive(Debug)]
pub struct Analysis {
    /// The assumption about external values.
    pub mode: Mode,
    /// Per function (module functions by handle index, then entry points).
    pub functions: Vec<FnFacts>,
    memory: HashMap<Root, Val>,
    args: Vec<Vec<Val>>,
    results: Vec<Val>,
    changed: bool,
    widening: bool,
    emit_counter: u32,
    /// What the enclosing `if` conditions say about scalar places, where they hold.
    refine: Vec<(Place, Refinement)>,
}

/// The function with index `id` (module functions first, then entry points).
pub fn function(module: &naga::Module, id: usize) -> &Function {
    match function_handle(module, id) {
        Some(h) => &module.functions[h],
        None => &module.entry_points[id - module.functions.len()].function,
    }
}

/// The handle of function `id` when it is a module function (`None` for an entry point).
fn function_handle(module: &naga::Module, id: usize) -> Option<naga::Handle<Function>> {
    module.functions.iter().nth(id).map(|(h, _)| h)
}

/// The validator's information about function `id`.
pub fn function_info<'a>(
    module: &naga::Module,
    info: &'a naga::valid::ModuleInfo,
    id: usize,
) -> &'a naga::valid::FunctionInfo {
    match function_handle(module, id) {
        Some(h) => &info[h],
        None => info.get_entry_point(id - module.functions.len()),
    }
}

/// The type an expression's pointer points to (or the type itself for a value).
fn pointee<'a>(module: &'a naga::Module, inner: &'a TypeInner) -> TypeInner {
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
fn shape(module: &naga::Module, inner: &TypeInner, leaf: &dyn Fn(u8, ScalarKind) -> Num) -> Val {
    shape_m(module, inner, &|n, k, _| leaf(n, k))
}

/// [`shape`] whose `leaf` also learns whether it makes a matrix column.
fn shape_m(
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
fn read(v: &Val, path: &[u32]) -> Val {
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
fn write(v: &mut Val, path: &[u32], new: &Val, widen: bool) -> bool {
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
    /// Analyses a validated module.
    pub fn run(module: &naga::Module, info: &naga::valid::ModuleInfo, mode: Mode) -> Analysis {
        let count = module.functions.len() + module.entry_points.len();
        let mut a = Analysis {
            mode,
            functions: vec![FnFacts::default(); count],
            memory: HashMap::default(),
            args: (0..count)
                .map(|id| vec![Val::Bot; function(module, id).arguments.len()])
                .collect(),
            results: vec![Val::Bot; count],
            changed: false,
            widening: false,
            emit_counter: 0,
            refine: Vec::new(),
        };
        for id in 0..count {
            let f = function(module, id);
            let (single, stores) = single_stores(f);
            a.functions[id].single_store = single;
            a.functions[id].stores = stores;
            a.functions[id].entry = id >= module.functions.len();
        }
        // Private globals start with their initialiser.
        for (h, g) in module.global_variables.iter() {
            if let Some(init) = g.init {
                let v = const_value(module, init);
                let root = Root::Global(h.index());
                let mut cell = a.cell(module, root);
                write(&mut cell, &[], &v, false);
                a.memory.insert(root, cell);
            }
        }
        for round in 0..MAX_ROUNDS {
            a.changed = false;
            a.widening = round >= WIDEN_AFTER;
            // Callers after callees is the order naga keeps; entry points last. Walking the
            // entry points first gives the inputs their values before `main_` reads them.
            let order: Vec<usize> = (module.functions.len()..count)
                .chain(0..module.functions.len())
                .collect();
            for id in order {
                a.run_function(module, info, id);
            }
            if !a.changed {
                break;
            }
        }
        a
    }

    /// The value of expression `h` of function `id`.
    pub fn value(&self, id: usize, h: Handle<E>) -> &Val {
        self.functions[id]
            .values
            .get(h.index())
            .unwrap_or(&Val::Bot)
    }

    /// The scalar or vector value of expression `h` of function `id`, if it has one.
    pub fn num(&self, id: usize, h: Handle<E>) -> Option<&Num> {
        self.value(id, h).num().filter(|n| !n.is_bottom())
    }

    /// The memory cell of a root, created with its type's shape when new.
    fn cell(&self, module: &naga::Module, root: Root) -> Val {
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

    fn store(&mut self, module: &naga::Module, place: &Place, v: &Val) {
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
        if write(&mut cell, &place.path, v, self.widening) {
            self.changed = true;
        }
        self.memory.insert(place.root, cell);
    }

    fn load(&self, module: &naga::Module, place: &Place, ty: &TypeInner) -> Val {
        if let Root::Global(g) = place.root {
            let h = module
                .global_variables
                .iter()
                .nth(g)
                .map(|(h, _)| h)
                .expect("global");
            if module.global_variables[h].space != naga::AddressSpace::Private {
                return self.external(module, ty, Facts::UNIFORM);
            }
        }
        read(&self.cell(module, place.root), &place.path)
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
            Num::splat(
                i,
                n,
                Facts::NN
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
    fn unknown(module: &naga::Module, ty: &TypeInner, deps: Facts) -> Val {
        shape(module, ty, &|n, kind| {
            let i = match kind {
                ScalarKind::Bool => Interval::UNIT,
                ScalarKind::Uint => Interval::NON_NEGATIVE,
                _ => Interval::FULL,
            };
            Num::splat(i, n, deps.only(Facts::DEPS))
        })
    }

    fn join_into(slot: &mut Val, v: &Val, widen: bool, changed: &mut bool) {
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

    fn run_function(&mut self, module: &naga::Module, info: &naga::valid::ModuleInfo, id: usize) {
        let f = function(module, id);
        let n = f.expressions.len();
        {
            let ff = &mut self.functions[id];
            ff.values = vec![Val::Bot; n];
            ff.places = vec![None; n];
            ff.emit = vec![0; n];
        }
        let finfo = function_info(module, info, id);
        for (h, e) in f.expressions.iter() {
            if e.needs_pre_emit() || matches!(e, E::CallResult(_)) {
                self.eval(module, finfo, f, id, h);
            }
        }
        for (lh, l) in f.local_variables.iter() {
            if let Some(init) = l.init {
                let v = self.functions[id].values[init.index()].clone();
                self.store(
                    module,
                    &Place {
                        root: Root::Local(id, lh.index()),
                        path: Vec::new(),
                    },
                    &v,
                );
            }
        }
        self.block(module, finfo, f, id, &f.body);
    }

    fn block(
        &mut self,
        module: &naga::Module,
        finfo: &naga::valid::FunctionInfo,
        f: &Function,
        id: usize,
        b: &Block,
    ) {
        let depth = self.refine.len();
        let stmts: Vec<&Statement> = b.iter().collect();
        for (i, s) in stmts.iter().enumerate() {
            if let Statement::If {
                condition,
                accept,
                reject,
            } = s
            {
                let d = self.refine.len();
                fn inside(blk: &Block) -> Vec<&Statement> {
                    blk.iter().collect()
                }
                for (blk, polarity) in [(accept, true), (reject, false)] {
                    let rs = self.refinements(module, f, id, *condition, polarity, &[&inside(blk)]);
                    self.refine.extend(rs);
                    self.block(module, finfo, f, id, blk);
                    self.refine.truncate(d);
                }
                // After `if (c) { …; return; }` the rest of the block has `!c` (and the mirror).
                let rest: Vec<&Statement> = stmts[i + 1..].to_vec();
                let (ad, rd) = (diverges(accept), diverges(reject));
                if ad != rd {
                    let other = if ad { reject } else { accept };
                    let rs =
                        self.refinements(module, f, id, *condition, rd, &[&rest, &inside(other)]);
                    self.refine.extend(rs);
                }
                continue;
            }
            match s {
                Statement::Emit(r) => {
                    self.emit_counter += 1;
                    for h in r.clone() {
                        self.functions[id].emit[h.index()] = self.emit_counter;
                        self.eval(module, finfo, f, id, h);
                    }
                }
                Statement::Block(b) => self.block(module, finfo, f, id, b),
                Statement::Switch { cases, .. } => {
                    for c in cases {
                        self.block(module, finfo, f, id, &c.body);
                    }
                }
                Statement::Loop {
                    body, continuing, ..
                } => {
                    self.block(module, finfo, f, id, body);
                    self.block(module, finfo, f, id, continuing);
                }
                Statement::Return { value: Some(v) } => {
                    let val = self.functions[id].values[v.index()].clone();
                    let mut changed = false;
                    Self::join_into(&mut self.results[id], &val, self.widening, &mut changed);
                    self.changed |= changed;
                }
                Statement::Store { pointer, value } => {
                    if let Some(p) = self.functions[id].places[pointer.index()].clone() {
                        let v = self.functions[id].values[value.index()].clone();
                        self.store(module, &p, &v);
                    }
                }
                Statement::Call {
                    function: callee,
                    arguments,
                    result,
                } => {
                    let c = callee.index();
                    for (i, a) in arguments.iter().enumerate() {
                        if let Some(p) = self.functions[id].places[a.index()].clone() {
                            // A pointer argument: the caller's variable and the parameter's cell
                            // hold the same values (copy-in for `inout`, copy-out after).
                            let arg_root = Place {
                                root: Root::Arg(c, i),
                                path: Vec::new(),
                            };
                            let ty = pointee(module, finfo[*a].ty.inner_with(&module.types));
                            let mine = self.load(module, &p, &ty);
                            self.store(module, &arg_root, &mine);
                            let theirs = self.cell(module, Root::Arg(c, i));
                            self.store(module, &p, &theirs);
                        } else {
                            let v = self.functions[id].values[a.index()].clone();
                            let mut changed = false;
                            if let Some(slot) = self.args[c].get_mut(i) {
                                Self::join_into(slot, &v, self.widening, &mut changed);
                            }
                            self.changed |= changed;
                        }
                    }
                    if let Some(r) = result {
                        self.functions[id].values[r.index()] = self.results[c].clone();
                    }
                }
                _ => {}
            }
        }
        self.refine.truncate(depth);
    }

    /// What `condition` being `polarity` says about places that `region` (statements) does not
    /// write: `x > 0.0` bounds the loads of `x` there, `dot(v, v) > 0.0` the length of `v`.
    #[allow(clippy::too_many_arguments)]
    fn refinements(
        &self,
        module: &naga::Module,
        f: &Function,
        id: usize,
        condition: Handle<E>,
        polarity: bool,
        region: &[&[&Statement]],
    ) -> Vec<(Place, Refinement)> {
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
    fn refined(&self, place: &Place, v: Val) -> Val {
        let Val::Num(n) = v else { return v };
        let rs: Vec<Refinement> = self
            .refine
            .iter()
            .filter(|(p, _)| p == place)
            .map(|(_, r)| *r)
            .collect();
        Val::Num(refine_num(n, &rs))
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

/// The length of `a ± b` from the lengths of `a` and `b`.
fn triangle(a: Interval, b: Interval) -> Interval {
    if a.is_empty() || b.is_empty() {
        return Interval::NON_NEGATIVE;
    }
    let lo = (a.lo - b.hi).max(b.lo - a.hi).max(0.0);
    Interval::new(lo, a.hi + b.hi).slack(EPS)
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

/// Locals stored exactly once (the whole variable), outside loops, never passed by pointer; and
/// the whole stores of every local never stored in part or passed by pointer.
#[allow(clippy::type_complexity)]
fn single_stores(f: &Function) -> (HashMap<usize, Handle<E>>, HashMap<usize, Vec<Handle<E>>>) {
    #[derive(Default)]
    struct Count {
        whole: Vec<(usize, Handle<E>, bool)>,
        spoiled: rustc_hash::FxHashSet<usize>,
    }
    fn root_local(f: &Function, mut p: Handle<E>) -> Option<(usize, bool)> {
        let mut whole = true;
        loop {
            match f.expressions[p] {
                E::LocalVariable(l) => return Some((l.index(), whole)),
                E::Access { base, .. } | E::AccessIndex { base, .. } => {
                    whole = false;
                    p = base;
                }
                _ => return None,
            }
        }
    }
    fn walk(f: &Function, b: &Block, in_loop: bool, c: &mut Count) {
        for s in b.iter() {
            match s {
                Statement::Block(b) => walk(f, b, in_loop, c),
                Statement::If { accept, reject, .. } => {
                    walk(f, accept, in_loop, c);
                    walk(f, reject, in_loop, c);
                }
                Statement::Switch { cases, .. } => {
                    for k in cases {
                        walk(f, &k.body, in_loop, c);
                    }
                }
                Statement::Loop {
                    body, continuing, ..
                } => {
                    walk(f, body, true, c);
                    walk(f, continuing, true, c);
                }
                Statement::Store { pointer, value } => {
                    if let Some((l, whole)) = root_local(f, *pointer) {
                        if whole {
                            c.whole.push((l, *value, in_loop));
                        } else {
                            c.spoiled.insert(l);
                        }
                    }
                }
                Statement::Call { arguments, .. } => {
                    for a in arguments {
                        if let Some((l, _)) = root_local(f, *a) {
                            c.spoiled.insert(l);
                        }
                    }
                }
                _ => {}
            }
        }
    }
    let mut c = Count::default();
    walk(f, &f.body, false, &mut c);
    let mut counts: HashMap<usize, usize> = HashMap::default();
    for (l, _, _) in &c.whole {
        *counts.entry(*l).or_default() += 1;
    }
    let mut out = HashMap::default();
    let mut all: HashMap<usize, Vec<Handle<E>>> = HashMap::default();
    for (l, v, in_loop) in c.whole {
        let has_init = f
            .local_variables
            .iter()
            .nth(l)
            .is_some_and(|(_, lv)| lv.init.is_some());
        if counts[&l] == 1 && !in_loop && !c.spoiled.contains(&l) && !has_init {
            out.insert(l, v);
        }
        if !c.spoiled.contains(&l) && !has_init {
            all.entry(l).or_default().push(v);
        }
    }
    (out, all)
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

/// Whether a block ends every path through it with `break`, `continue`, `return` or `discard`.
fn diverges(b: &Block) -> bool {
    match b.last() {
        Some(
            Statement::Break | Statement::Continue | Statement::Return { .. } | Statement::Kill,
        ) => true,
        Some(Statement::Block(inner)) => diverges(inner),
        Some(Statement::If { accept, reject, .. }) => diverges(accept) && diverges(reject),
        _ => false,
    }
}

/// Whether statements may write variable `root` (a call may write any private global).
fn writes(module: &naga::Module, f: &Function, stmts: &[&Statement], root: Root) -> bool {
    fn is_root(f: &Function, mut p: Handle<E>, root: Root) -> bool {
        loop {
            match f.expressions[p] {
                E::LocalVariable(l) => return matches!(root, Root::Local(_, x) if x == l.index()),
                E::GlobalVariable(g) => return root == Root::Global(g.index()),
                E::FunctionArgument(i) => return matches!(root, Root::Arg(_, x) if x == i as usize),
                E::Access { base, .. } | E::AccessIndex { base, .. } => p = base,
                _ => return false,
            }
        }
    }
    let private_global = match root {
        Root::Global(g) => {
            let h = module
                .global_variables
                .iter()
                .nth(g)
                .map(|(h, _)| h)
                .expect("global");
            if module.global_variables[h].space != naga::AddressSpace::Private {
                return false; // uniforms are never written
            }
            true
        }
        _ => false,
    };
    fn all(b: &Block) -> Vec<&Statement> {
        b.iter().collect()
    }
    stmts.iter().any(|s| match s {
        Statement::Store { pointer, .. } => is_root(f, *pointer, root),
        Statement::Call { arguments, .. } => {
            private_global || arguments.iter().any(|a| is_root(f, *a, root))
        }
        Statement::Block(b) => writes(module, f, &all(b), root),
        Statement::If { accept, reject, .. } => {
            writes(module, f, &all(accept), root) || writes(module, f, &all(reject), root)
        }
        Statement::Switch { cases, .. } => {
            cases.iter().any(|c| writes(module, f, &all(&c.body), root))
        }
        Statement::Loop {
            body, continuing, ..
        } => writes(module, f, &all(body), root) || writes(module, f, &all(continuing), root),
        _ => false,
    })
}

/// What a condition says about a value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Refinement {
    /// A scalar is in this interval.
    Value(Interval),
    /// A vector's length is in this interval.
    Norm(Interval),
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

/// Evaluation of expressions.
impl Analysis {
    fn v(&self, id: usize, h: Handle<E>) -> &Val {
        &self.functions[id].values[h.index()]
    }

    fn nm(&self, id: usize, h: Handle<E>) -> Option<Num> {
        self.functions[id].values[h.index()]
            .num()
            .copied()
            .filter(|n| !n.is_bottom())
    }

    /// Whether two expressions of a function certainly have the same value.
    pub fn same(&self, f: &Function, id: usize, a: Handle<E>, b: Handle<E>) -> bool {
        self.same_depth(f, id, a, b, 0)
    }

    fn same_depth(&self, f: &Function, id: usize, a: Handle<E>, b: Handle<E>, depth: u32) -> bool {
        if a == b {
            return true;
        }
        if depth > 6 {
            return false;
        }
        let ff = &self.functions[id];
        let s = |x: Handle<E>, y: Handle<E>| self.same_depth(f, id, x, y, depth + 1);
        match (&f.expressions[a], &f.expressions[b]) {
            (E::Load { pointer: pa }, E::Load { pointer: pb }) => {
                let (Some(x), Some(y)) = (&ff.places[pa.index()], &ff.places[pb.index()]) else {
                    return false;
                };
                if x != y || x.path.contains(&ANY) {
                    return false;
                }
                if let Root::Local(_, l) = x.root {
                    if x.path.is_empty() && ff.single_store.contains_key(&l) {
                        return true;
                    }
                }
                let same_emit = ff.emit[a.index()] != 0 && ff.emit[a.index()] == ff.emit[b.index()];
                same_emit
                    || self.functions[id].values[a.index()].facts().has(Facts::EXT)
                        && matches!(x.root, Root::Global(_))
            }
            (
                E::Binary {
                    op: o1,
                    left: l1,
                    right: r1,
                },
                E::Binary {
                    op: o2,
                    left: l2,
                    right: r2,
                },
            ) => o1 == o2 && s(*l1, *l2) && s(*r1, *r2),
            (E::Unary { op: o1, expr: x1 }, E::Unary { op: o2, expr: x2 }) => {
                o1 == o2 && s(*x1, *x2)
            }
            (
                E::Math {
                    fun: f1,
                    arg: a1,
                    arg1: b1,
                    arg2: c1,
                    ..
                },
                E::Math {
                    fun: f2,
                    arg: a2,
                    arg1: b2,
                    arg2: c2,
                    ..
                },
            ) => {
                let opt = |x: &Option<Handle<E>>, y: &Option<Handle<E>>| match (x, y) {
                    (None, None) => true,
                    (Some(x), Some(y)) => s(*x, *y),
                    _ => false,
                };
                f1 == f2 && s(*a1, *a2) && opt(b1, b2) && opt(c1, c2)
            }
            (
                E::AccessIndex {
                    base: b1,
                    index: i1,
                },
                E::AccessIndex {
                    base: b2,
                    index: i2,
                },
            ) => i1 == i2 && s(*b1, *b2),
            (
                E::Swizzle {
                    size: z1,
                    vector: v1,
                    pattern: p1,
                },
                E::Swizzle {
                    size: z2,
                    vector: v2,
                    pattern: p2,
                },
            ) => z1 == z2 && p1 == p2 && s(*v1, *v2),
            (
                E::Splat {
                    size: z1,
                    value: v1,
                },
                E::Splat {
                    size: z2,
                    value: v2,
                },
            ) => z1 == z2 && s(*v1, *v2),
            (
                E::As {
                    expr: x1,
                    kind: k1,
                    convert: c1,
                },
                E::As {
                    expr: x2,
                    kind: k2,
                    convert: c2,
                },
            ) => k1 == k2 && c1 == c2 && s(*x1, *x2),
            (E::Literal(x), E::Literal(y)) => x == y,
            (E::Constant(x), E::Constant(y)) => x == y,
            (E::FunctionArgument(x), E::FunctionArgument(y)) => x == y,
            _ => false,
        }
    }

    fn eval(
        &mut self,
        module: &naga::Module,
        finfo: &naga::valid::FunctionInfo,
        f: &Function,
        id: usize,
        h: Handle<E>,
    ) {
        let ty = finfo[h].ty.inner_with(&module.types);
        let entry = self.functions[id].entry;
        let e = &f.expressions[h];
        let mut place = None;
        let deps_of = |s: &Self, hs: &[Handle<E>]| {
            hs.iter().fold(Facts::NONE, |acc, x| {
                acc.with(s.v(id, *x).facts().only(Facts::DEPS))
            })
        };
        let val = match e {
            E::Literal(l) => Val::Num(Num::constant(&[literal(l)])),
            E::Constant(c) => const_value(module, module.constants[*c].init),
            E::ZeroValue(_) => shape(module, ty, &|n, _| Num::constant(&vec![0.0; n as usize])),
            E::Override(_) => self.external(module, ty, Facts::UNIFORM),
            E::FunctionArgument(i) => {
                if matches!(
                    ty,
                    TypeInner::Pointer { .. } | TypeInner::ValuePointer { .. }
                ) {
                    place = Some(Place {
                        root: Root::Arg(id, *i as usize),
                        path: Vec::new(),
                    });
                    Val::Any
                } else if entry {
                    self.external(module, ty, Facts::INPUT)
                } else {
                    self.args[id].get(*i as usize).cloned().unwrap_or(Val::Any)
                }
            }
            E::GlobalVariable(g) => {
                place = Some(Place {
                    root: Root::Global(g.index()),
                    path: Vec::new(),
                });
                Val::Any
            }
            E::LocalVariable(l) => {
                place = Some(Place {
                    root: Root::Local(id, l.index()),
                    path: Vec::new(),
                });
                Val::Any
            }
            E::CallResult(fh) => self.results[fh.index()].clone(),
            _ if entry => {
                // The entry point only moves data between the pipeline and private variables.
                match e {
                    E::Access { base, .. } | E::AccessIndex { base, .. }
                        if self.functions[id].places[base.index()].is_some() =>
                    {
                        place = self.access_place(module, finfo, id, e);
                        Val::Any
                    }
                    _ => self.external(module, ty, Facts::INPUT),
                }
            }
            E::Access { base, .. } | E::AccessIndex { base, .. }
                if self.functions[id].places[base.index()].is_some() =>
            {
                place = self.access_place(module, finfo, id, e);
                Val::Any
            }
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
                    let v = self.load(module, &p, ty);
                    if self.refine.is_empty() {
                        v
                    } else {
                        self.refined(&p, v)
                    }
                }
                None => Self::unknown(module, ty, Facts::NONE),
            },
            E::Splat { size, value } => match self.nm(id, *value) {
                Some(x) => {
                    let n = *size as u8;
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
            },
            E::Swizzle {
                size,
                vector,
                pattern,
            } => match self.nm(id, *vector) {
                Some(x) => {
                    let idx: Vec<usize> = pattern[..*size as usize]
                        .iter()
                        .map(|c| *c as usize)
                        .collect();
                    let comps: Vec<Interval> =
                        idx.iter().map(|&i| x.c[i.min(x.n as usize - 1)]).collect();
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
                None => Val::Bot,
            },
            E::Compose { components, .. } => self.compose(module, f, ty, id, components),
            E::Unary { op, expr } => match (op, self.nm(id, *expr)) {
                (Uo::Negate, Some(x)) => {
                    let keep = x.facts.only(
                        Facts::NZ
                            .with(Facts::NZ3)
                            .with(Facts::UNIT)
                            .with(Facts::DIFF)
                            .with(Facts::EXT)
                            .with(Facts::ALL_OR),
                    );
                    let mut r = Num::from_components(&x.map(Interval::neg), keep);
                    r.norm = r.norm.meet(x.norm);
                    Val::Num(r.settle())
                }
                (Uo::LogicalNot, Some(x)) => {
                    Val::Num(Num::splat(Interval::UNIT, x.n, x.facts.only(Facts::DEPS)))
                }
                (_, Some(x)) => Self::unknown(module, ty, x.facts),
                (_, None) => Val::Bot,
            },
            E::Binary { op, left, right } => self.binary(module, f, id, ty, *op, *left, *right),
            E::Select { accept, reject, .. } => self.v(id, *accept).join(self.v(id, *reject)),
            E::Derivative { axis, expr, .. } => match self.nm(id, *expr) {
                Some(x) => {
                    let deps = x.facts.only(Facts::DEPS);
                    if x.comps().iter().all(|c| c.as_point().is_some()) {
                        Val::Num(Num::splat(Interval::point(0.0), x.n, deps))
                    } else if *axis == naga::DerivativeAxis::Width {
                        Val::Num(Num::splat(Interval::NON_NEGATIVE, x.n, deps))
                    } else {
                        Val::Num(Num::splat(Interval::FULL, x.n, deps))
                    }
                }
                None => Val::Bot,
            },
            E::Relational { argument, .. } => {
                let deps = deps_of(self, &[*argument]);
                shape(module, ty, &|n, _| Num::splat(Interval::UNIT, n, deps))
            }
            E::As {
                expr,
                kind,
                convert,
            } => self.convert(module, ty, id, *expr, *kind, *convert),
            E::Math {
                fun,
                arg,
                arg1,
                arg2,
                arg3,
            } => self.math(module, f, id, ty, *fun, *arg, *arg1, *arg2, *arg3),
            E::ImageSample {
                coordinate,
                depth_ref,
                ..
            } => {
                let deps = deps_of(self, &[*coordinate]).with(Facts::TEXTURE);
                if depth_ref.is_some() {
                    Val::Num(Num::scalar(Interval::UNIT, deps.with(Facts::EXT)))
                } else {
                    self.texel(module, ty, deps)
                }
            }
            E::ImageLoad { coordinate, .. } => {
                let deps = deps_of(self, &[*coordinate]).with(Facts::TEXTURE);
                self.texel(module, ty, deps)
            }
            E::ImageQuery { .. } => shape(module, ty, &|n, _| {
                Num::splat(Interval::NON_NEGATIVE, n, Facts::NONE)
            }),
            _ => Self::unknown(module, ty, Facts::NONE),
        };
        let ff = &mut self.functions[id];
        ff.values[h.index()] = val;
        ff.places[h.index()] = place;
    }

    fn texel(&self, module: &naga::Module, ty: &TypeInner, deps: Facts) -> Val {
        match self.mode {
            Mode::Sound => self.external(module, ty, deps),
            Mode::Typical => shape(module, ty, &|n, _| {
                Num::splat(Interval::UNIT, n, Facts::EXT.with(deps))
            }),
        }
    }

    fn access_place(
        &self,
        module: &naga::Module,
        finfo: &naga::valid::FunctionInfo,
        id: usize,
        e: &E,
    ) -> Option<Place> {
        let (base, index) = match e {
            E::Access { base, .. } => (*base, ANY),
            E::AccessIndex { base, index } => (*base, *index),
            _ => return None,
        };
        let mut p = self.functions[id].places[base.index()].clone()?;
        let pointee = pointee(module, finfo[base].ty.inner_with(&module.types));
        let step = match pointee {
            TypeInner::Array { .. } => 0,
            _ => index,
        };
        p.path.push(step);
        Some(p)
    }

    fn compose(
        &self,
        module: &naga::Module,
        f: &Function,
        ty: &TypeInner,
        id: usize,
        components: &[Handle<E>],
    ) -> Val {
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
            _ => x.comps().to_vec(),
        };
        let keep = if kind == ScalarKind::Float {
            x.facts
        } else {
            x.facts.without(Facts::POS).without(Facts::NZ)
        };
        Val::Num(Num::from_components(&comps, keep.without(Facts::DIFF)))
    }

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

    #[allow(clippy::too_many_arguments)]
    fn binary(
        &self,
        module: &naga::Module,
        f: &Function,
        id: usize,
        ty: &TypeInner,
        op: Bo,
        l: Handle<E>,
        r: Handle<E>,
    ) -> Val {
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
            Bo::And | Bo::InclusiveOr | Bo::ExclusiveOr | Bo::ShiftLeft | Bo::ShiftRight => {
                return Self::unknown(module, ty, deps);
            }
            _ => {}
        }
        match (lv, rv) {
            (Val::Num(a), Val::Num(b)) => {
                Val::Num(self.num_binary(f, id, ty, op, l, r, a, b, deps))
            }
            (Val::Agg(m), Val::Num(v)) if op == Bo::Multiply && v.n > 1 => {
                // Matrix times column vector.
                let cols: Vec<Num> = m.iter().filter_map(|c| c.num().copied()).collect();
                if cols.len() != m.len() || cols.len() != v.n as usize {
                    return Self::unknown(module, ty, deps);
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
                // A direction (w = 0) keeps a non-zero xyz through an invertible (affine or
                // projective) transform.
                let nz3 = invertible
                    && rows == 4
                    && v.n == 4
                    && v.c[3].as_point() == Some(0.0)
                    && v.facts.has(Facts::NZ3);
                Val::Num(Num::from_components(
                    &comps,
                    deps.set(Facts::NZ, nz).set(Facts::NZ3, nz3),
                ))
            }
            (Val::Num(v), Val::Agg(m)) if op == Bo::Multiply && v.n > 1 => {
                // Row vector times matrix.
                let cols: Vec<Num> = m.iter().filter_map(|c| c.num().copied()).collect();
                if cols.len() != m.len() {
                    return Self::unknown(module, ty, deps);
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
                Val::Num(Num::from_components(
                    &comps,
                    deps.set(Facts::NZ, invertible && v.facts.has(Facts::NZ)),
                ))
            }
            (Val::Agg(a), Val::Agg(b)) if op == Bo::Multiply => {
                // Matrix product: each column of the result is A times a column of B.
                let acols: Vec<Num> = a.iter().filter_map(|c| c.num().copied()).collect();
                if acols.len() != a.len() || acols.is_empty() {
                    return Self::unknown(module, ty, deps);
                }
                let rows = acols[0].n as usize;
                let inv = acols.iter().all(|c| c.facts.has(Facts::NZ))
                    && b.iter().all(|c| c.facts().has(Facts::NZ));
                let cols = b
                    .iter()
                    .map(|bc| match bc.num() {
                        Some(v) => {
                            let comps: Vec<Interval> = (0..rows)
                                .map(|row| {
                                    acols.iter().enumerate().fold(
                                        Interval::point(0.0),
                                        |s, (c, col)| {
                                            s.add(col.c[row].mul(v.c[c.min(v.n as usize - 1)]))
                                        },
                                    )
                                })
                                .collect();
                            Val::Num(Num::from_components(&comps, deps.set(Facts::NZ, inv)))
                        }
                        None => Val::Any,
                    })
                    .collect();
                Val::Agg(cols)
            }
            (Val::Agg(a), Val::Agg(b))
                if a.len() == b.len() && matches!(op, Bo::Add | Bo::Subtract) =>
            {
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
            (Val::Agg(m), Val::Num(s)) | (Val::Num(s), Val::Agg(m)) if s.n == 1 => {
                let scale_nz = s.facts.has(Facts::NZ);
                Val::Agg(
                    m.iter()
                        .map(|c| match c.num() {
                            Some(c) => {
                                let comps = c.map(|x| match op {
                                    Bo::Multiply => x.mul(s.c[0]),
                                    Bo::Divide if matches!(lv, Val::Agg(_)) => x.div(s.c[0]),
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
            _ => Self::unknown(module, ty, deps),
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn num_binary(
        &self,
        f: &Function,
        id: usize,
        ty: &TypeInner,
        op: Bo,
        l: Handle<E>,
        r: Handle<E>,
        a: &Num,
        b: &Num,
        deps: Facts,
    ) -> Num {
        let fa = a.facts;
        let fb = b.facts;
        let is_int = matches!(ty.scalar_kind(), Some(ScalarKind::Sint | ScalarKind::Uint));
        let vector_result = a.n.max(b.n) > 1;
        let mixed = (a.n == 1) != (b.n == 1);
        match op {
            Bo::Add => {
                let comps = a.zip(b, Interval::add);
                let nn = fa.has(Facts::NN) && fb.has(Facts::NN);
                let pos = (fa.has(Facts::POS) && fb.has(Facts::NN))
                    || (fa.has(Facts::NN) && fb.has(Facts::POS));
                let nz = if vector_result {
                    nn && (fa.has(Facts::NZ) || fb.has(Facts::NZ))
                } else {
                    pos
                };
                let facts = deps
                    .set(Facts::NN, nn)
                    .set(Facts::POS, pos)
                    .set(Facts::NZ, nz);
                let mut out = Num::from_components(&comps, facts);
                if !mixed && vector_result {
                    out.norm = out.norm.meet(triangle(a.norm, b.norm));
                }
                out.settle()
            }
            Bo::Subtract => {
                if self.same(f, id, l, r) {
                    return Num::from_components(
                        &vec![Interval::point(0.0); a.n.max(b.n) as usize],
                        deps,
                    );
                }
                if let Some(y) = Self::is_mod(f, l, r) {
                    if let Some(yv) = self.nm(id, y) {
                        let comps = a.zip(&yv, Interval::modulo);
                        return Num::from_components(
                            &comps,
                            deps.set(Facts::NN, yv.facts.has(Facts::NN)),
                        );
                    }
                }
                let comps = a.zip(b, Interval::sub);
                let mut out = Num::from_components(&comps, deps.with(Facts::DIFF));
                if !mixed && vector_result {
                    out.norm = out.norm.meet(triangle(a.norm, b.norm));
                }
                out.settle()
            }
            Bo::Multiply => {
                if self.same(f, id, l, r) && a.n == b.n {
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
                let comps = a.zip(b, Interval::mul);
                let nn = fa.has(Facts::NN) && fb.has(Facts::NN);
                let pos = fa.has(Facts::POS) && fb.has(Facts::POS);
                let nz = fa.has(Facts::NZ) && fb.has(Facts::NZ) && (mixed || !vector_result);
                let unit = fa.has(Facts::UNIT) && fb.has(Facts::UNIT);
                let cross = mixed && (fa.any(Facts::CROSS) || fb.any(Facts::CROSS));
                let facts = deps
                    .set(Facts::NN, nn)
                    .set(Facts::POS, pos)
                    .set(Facts::NZ, nz)
                    .set(Facts::UNIT, unit)
                    .set(Facts::CROSS, cross);
                let mut out = Num::from_components(&comps, facts);
                if mixed {
                    let (s, v) = if a.n == 1 { (a, b) } else { (b, a) };
                    out.norm = out.norm.meet(s.c[0].abs().mul(v.norm));
                }
                out.settle()
            }
            Bo::Divide => {
                let comps = a.zip(b, |x, y| if is_int { x.div(y).trunc() } else { x.div(y) });
                let nn = fa.has(Facts::NN) && fb.has(Facts::NN);
                let pos = fa.has(Facts::POS) && fb.has(Facts::POS) && !is_int;
                let nz = fa.has(Facts::NZ) && !is_int && (b.n == 1 || !vector_result);
                let cross = b.n == 1 && fa.any(Facts::CROSS);
                let facts = deps
                    .set(Facts::NN, nn)
                    .set(Facts::POS, pos)
                    .set(Facts::NZ, nz)
                    .set(Facts::CROSS, cross);
                let mut out = Num::from_components(&comps, facts);
                if b.n == 1 && a.n > 1 && !is_int {
                    out.norm = out.norm.meet(a.norm.div(b.c[0].abs()));
                }
                out.settle()
            }
            Bo::Modulo => {
                let comps = a.zip(b, |x, y| {
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
                Num::from_components(&comps, deps.set(Facts::NN, fa.has(Facts::NN)))
            }
            _ => Num::from_components(&vec![Interval::FULL; a.n.max(b.n) as usize], deps),
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn math(
        &self,
        module: &naga::Module,
        f: &Function,
        id: usize,
        ty: &TypeInner,
        fun: Mf,
        arg: Handle<E>,
        arg1: Option<Handle<E>>,
        arg2: Option<Handle<E>>,
        _arg3: Option<Handle<E>>,
    ) -> Val {
        let args: Vec<Handle<E>> = [Some(arg), arg1, arg2].into_iter().flatten().collect();
        if args.iter().any(|a| self.v(id, *a).is_bot()) {
            return Val::Bot;
        }
        let deps = args.iter().fold(Facts::NONE, |acc, a| {
            acc.with(self.v(id, *a).facts().only(Facts::DEPS))
        });
        let nums: Vec<Num> = args.iter().filter_map(|a| self.nm(id, *a)).collect();
        if nums.len() != args.len() {
            // Matrix functions and others on aggregates.
            return match fun {
                Mf::Transpose | Mf::Inverse => {
                    let inv = self.v(id, arg).facts().has(Facts::NZ);
                    shape(module, ty, &|n, _| {
                        Num::splat(Interval::FULL, n, deps.set(Facts::NZ, inv))
                    })
                }
                Mf::Determinant => {
                    let inv = self.v(id, arg).facts().has(Facts::NZ);
                    Val::Num(Num::scalar(Interval::FULL, deps.set(Facts::NZ, inv)))
                }
                _ => Self::unknown(module, ty, deps),
            };
        }
        let x = nums[0];
        let fx = x.facts;
        let unary = |g: fn(Interval) -> Interval, slack: bool, facts: Facts| {
            let comps = x.map(|c| if slack { g(c).slack(EPS) } else { g(c) });
            Val::Num(Num::from_components(&comps, facts.with(deps)))
        };
        let keep_sign = |f: Facts| {
            Facts::NONE
                .set(Facts::NN, f.has(Facts::NN))
                .set(Facts::POS, f.has(Facts::POS))
                .set(Facts::NZ, f.has(Facts::NZ) && x.n == 1)
        };
        match fun {
            Mf::Abs => {
                let facts = Facts::NN
                    .set(
                        Facts::POS,
                        fx.has(Facts::POS) || (x.n == 1 && fx.has(Facts::NZ)),
                    )
                    .set(Facts::NZ, fx.has(Facts::NZ))
                    .set(Facts::UNIT, fx.has(Facts::UNIT));
                let mut r = Num::from_components(&x.map(Interval::abs), facts.with(deps));
                r.norm = r.norm.meet(x.norm);
                Val::Num(r.settle())
            }
            Mf::Min | Mf::Max => {
                let y = nums[1];
                let fy = y.facts;
                let comps = x.zip(
                    &y,
                    if fun == Mf::Min {
                        Interval::min
                    } else {
                        Interval::max
                    },
                );
                let (nn, pos) = if fun == Mf::Min {
                    (
                        fx.has(Facts::NN) && fy.has(Facts::NN),
                        fx.has(Facts::POS) && fy.has(Facts::POS),
                    )
                } else {
                    (
                        fx.has(Facts::NN) || fy.has(Facts::NN),
                        fx.has(Facts::POS) || fy.has(Facts::POS),
                    )
                };
                let unit = fx.has(Facts::UNIT) && fy.has(Facts::UNIT);
                let facts = deps
                    .set(Facts::NN, nn)
                    .set(Facts::POS, pos)
                    .set(Facts::NZ, pos)
                    .set(Facts::UNIT, unit);
                Val::Num(Num::from_components(&comps, facts))
            }
            Mf::Clamp | Mf::Saturate => {
                let (lo, hi) = if fun == Mf::Clamp {
                    (nums[1], nums[2])
                } else {
                    (Num::constant(&[0.0]), Num::constant(&[1.0]))
                };
                let comps: Vec<Interval> = (0..x.n as usize)
                    .map(|i| {
                        let pick = |n: &Num| {
                            if n.n == 1 {
                                n.c[0]
                            } else {
                                n.c[i.min(n.n as usize - 1)]
                            }
                        };
                        x.c[i].clamp(pick(&lo), pick(&hi))
                    })
                    .collect();
                let nn = (fx.has(Facts::NN) || lo.facts.has(Facts::NN)) && hi.facts.has(Facts::NN);
                let pos =
                    (fx.has(Facts::POS) || lo.facts.has(Facts::POS)) && hi.facts.has(Facts::POS);
                let unit =
                    fx.has(Facts::UNIT) && lo.facts.has(Facts::UNIT) && hi.facts.has(Facts::UNIT);
                Val::Num(Num::from_components(
                    &comps,
                    deps.set(Facts::NN, nn)
                        .set(Facts::POS, pos)
                        .set(Facts::NZ, pos)
                        .set(Facts::UNIT, unit),
                ))
            }
            Mf::Sin | Mf::Cos => unary(
                if fun == Mf::Sin {
                    Interval::sin
                } else {
                    Interval::cos
                },
                false,
                Facts::UNIT,
            ),
            Mf::Tan => unary(Interval::tan, true, Facts::NONE),
            Mf::Sinh => unary(Interval::sinh, true, keep_sign(fx)),
            Mf::Cosh => unary(
                Interval::cosh,
                true,
                Facts::NN.with(Facts::POS).with(Facts::NZ),
            ),
            Mf::Tanh => unary(Interval::tanh, true, keep_sign(fx)),
            Mf::Asin => unary(Interval::asin, true, keep_sign(fx)),
            Mf::Acos => unary(Interval::acos, true, Facts::NN),
            Mf::Atan => unary(Interval::atan, true, keep_sign(fx)),
            Mf::Atan2 => Val::Num(Num::splat(
                Interval::new(-std::f64::consts::PI, std::f64::consts::PI),
                x.n,
                deps,
            )),
            Mf::Asinh | Mf::Atanh => {
                Val::Num(Num::splat(Interval::FULL, x.n, deps.with(keep_sign(fx))))
            }
            Mf::Acosh => Val::Num(Num::splat(Interval::NON_NEGATIVE, x.n, deps)),
            Mf::Radians | Mf::Degrees => {
                let k = if fun == Mf::Radians {
                    std::f64::consts::PI / 180.0
                } else {
                    180.0 / std::f64::consts::PI
                };
                let comps = x.map(|c| c.mul(Interval::new(k, k)));
                Val::Num(Num::from_components(&comps, deps.with(keep_sign(fx))))
            }
            Mf::Ceil => unary(
                Interval::ceil,
                false,
                keep_sign(fx).with(fx.only(Facts::UNIT)),
            ),
            Mf::Floor | Mf::Round | Mf::Trunc => {
                let g = match fun {
                    Mf::Floor => Interval::floor,
                    Mf::Round => Interval::round,
                    _ => Interval::trunc,
                };
                unary(
                    g,
                    false,
                    Facts::NONE
                        .set(Facts::NN, fx.has(Facts::NN))
                        .with(fx.only(Facts::UNIT)),
                )
            }
            Mf::Fract => unary(Interval::fract, false, Facts::NN.with(Facts::UNIT)),
            Mf::Exp | Mf::Exp2 => unary(
                if fun == Mf::Exp {
                    Interval::exp
                } else {
                    Interval::exp2
                },
                true,
                Facts::NN.with(Facts::POS).with(Facts::NZ),
            ),
            Mf::Log | Mf::Log2 => unary(
                if fun == Mf::Log {
                    Interval::log
                } else {
                    Interval::log2
                },
                true,
                Facts::NONE,
            ),
            Mf::Sqrt => unary(
                Interval::sqrt,
                true,
                Facts::NN
                    .set(Facts::POS, fx.has(Facts::POS))
                    .set(Facts::NZ, fx.has(Facts::POS) && x.n == 1)
                    .set(Facts::UNIT, fx.has(Facts::UNIT) && fx.has(Facts::NN)),
            ),
            Mf::InverseSqrt => unary(
                Interval::inverse_sqrt,
                true,
                Facts::NN.with(Facts::POS).with(Facts::NZ),
            ),
            Mf::Pow => {
                let y = nums[1];
                let comps = x.zip(&y, |p, q| p.pow(q).slack(EPS));
                let facts = Facts::NN
                    .set(Facts::POS, fx.has(Facts::POS))
                    .set(Facts::NZ, fx.has(Facts::POS) && x.n == 1)
                    .set(
                        Facts::UNIT,
                        fx.has(Facts::UNIT) && fx.has(Facts::NN) && y.facts.has(Facts::NN),
                    );
                Val::Num(Num::from_components(&comps, facts.with(deps)))
            }
            Mf::Sign => unary(Interval::sign, false, keep_sign(fx).with(Facts::UNIT)),
            Mf::Step => {
                let y = nums[1];
                let comps = x.zip(&y, Interval::step);
                Val::Num(Num::from_components(
                    &comps,
                    deps.with(Facts::NN).with(Facts::UNIT),
                ))
            }
            Mf::SmoothStep => {
                let (e1, v) = (nums[1], nums[2]);
                let comps: Vec<Interval> = (0..v.n as usize)
                    .map(|i| {
                        let pick = |n: &Num| {
                            if n.n == 1 {
                                n.c[0]
                            } else {
                                n.c[i.min(n.n as usize - 1)]
                            }
                        };
                        Interval::smoothstep(pick(&x), pick(&e1), v.c[i])
                    })
                    .collect();
                Val::Num(Num::from_components(
                    &comps,
                    deps.with(Facts::NN).with(Facts::UNIT),
                ))
            }
            Mf::Mix => {
                let (b, t) = (nums[1], nums[2]);
                let comps: Vec<Interval> = (0..x.n.max(b.n) as usize)
                    .map(|i| {
                        let pick = |n: &Num| {
                            if n.n == 1 {
                                n.c[0]
                            } else {
                                n.c[i.min(n.n as usize - 1)]
                            }
                        };
                        Interval::mix(pick(&x), pick(&b), pick(&t))
                    })
                    .collect();
                let convex = t.comps().iter().all(|c| c.within(Interval::UNIT));
                let fb = b.facts;
                let facts = Facts::NONE
                    .set(Facts::NN, convex && fx.has(Facts::NN) && fb.has(Facts::NN))
                    .set(
                        Facts::POS,
                        convex && fx.has(Facts::POS) && fb.has(Facts::POS),
                    )
                    .set(
                        Facts::UNIT,
                        convex && fx.has(Facts::UNIT) && fb.has(Facts::UNIT),
                    );
                Val::Num(Num::from_components(&comps, facts.with(deps)))
            }
            Mf::Fma => {
                let comps: Vec<Interval> = (0..x.n as usize)
                    .map(|i| {
                        x.c[i]
                            .mul(nums[1].c[i.min(nums[1].n as usize - 1)])
                            .add(nums[2].c[i.min(nums[2].n as usize - 1)])
                    })
                    .collect();
                Val::Num(Num::from_components(&comps, deps))
            }
            Mf::Dot => {
                let y = nums[1];
                let slack = EPS * (x.n as f64 + 2.0);
                if self.same(f, id, arg, args[1]) {
                    let r = x.norm.sqr().slack(slack).meet(Interval::NON_NEGATIVE);
                    let facts = Facts::NN
                        .set(Facts::POS, fx.has(Facts::NZ))
                        .set(Facts::NZ, fx.has(Facts::NZ));
                    return Val::Num(Num::scalar(r, facts.with(deps)));
                }
                let by_comps = (0..x.n as usize).fold(Interval::point(0.0), |s, i| {
                    s.add(x.c[i].mul(y.c[i.min(y.n as usize - 1)]))
                });
                let m = x.norm.hi * y.norm.hi;
                let by_norm = Interval::new(-m, m).slack(slack);
                let r = by_comps.meet(by_norm);
                Val::Num(Num::scalar(if r.is_empty() { by_comps } else { r }, deps))
            }
            Mf::Cross => {
                let y = nums[1];
                if x.n != 3 || y.n != 3 {
                    return Self::unknown(module, ty, deps);
                }
                let c = |i: usize, j: usize| x.c[i].mul(y.c[j]).sub(x.c[j].mul(y.c[i]));
                let comps = [c(1, 2), c(2, 0), c(0, 1)];
                // Parallel vectors are an ordinary configuration when one of them is fixed for
                // the draw (an `up` vector, a uniform direction); two per-vertex mesh vectors
                // (normal, tangent) are taken to be a valid frame.
                let per_pixel = Facts::INPUT.with(Facts::TEXTURE);
                let fixed = !x.facts.any(per_pixel) || !y.facts.any(per_pixel);
                let mut r = Num::from_components(&comps, deps.set(Facts::CROSS, fixed));
                r.norm = r
                    .norm
                    .meet(Interval::new(0.0, x.norm.hi * y.norm.hi).slack(EPS * 4.0));
                Val::Num(r.settle())
            }
            Mf::Length => {
                let r = x.norm.slack(EPS).meet(Interval::NON_NEGATIVE);
                let facts = Facts::NN
                    .set(Facts::POS, fx.has(Facts::NZ))
                    .set(Facts::NZ, fx.has(Facts::NZ));
                Val::Num(Num::scalar(r, facts.with(deps)))
            }
            Mf::Distance => {
                let y = nums[1];
                let comps = x.zip(&y, Interval::sub);
                let d = if x.n == 1 {
                    comps[0].abs()
                } else {
                    norm_of(&comps).meet(triangle(x.norm, y.norm))
                };
                Val::Num(Num::scalar(
                    d.slack(EPS).meet(Interval::NON_NEGATIVE),
                    deps.with(Facts::NN),
                ))
            }
            Mf::Normalize => {
                let one = Interval::new(1.0 - EPS, 1.0 + EPS);
                let comps = x.map(|c| {
                    let lo = if c.lo >= 0.0 { 0.0 } else { -one.hi };
                    let hi = if c.hi <= 0.0 { 0.0 } else { one.hi };
                    Interval::new(lo, hi)
                });
                let facts = Facts::NZ
                    .set(Facts::NN, fx.has(Facts::NN))
                    .set(Facts::POS, fx.has(Facts::POS));
                let mut r = Num::from_components(&comps, facts.with(deps));
                r.norm = one;
                Val::Num(r.settle())
            }
            Mf::FaceForward => {
                let comps = x.map(|c| c.hull(c.neg()));
                let mut r = Num::from_components(
                    &comps,
                    deps.set(Facts::NZ, fx.has(Facts::NZ))
                        .set(Facts::UNIT, fx.has(Facts::UNIT)),
                );
                r.norm = r.norm.meet(x.norm);
                Val::Num(r.settle())
            }
            Mf::Reflect => {
                let nrm = nums[1];
                let unit_n = nrm
                    .norm
                    .within(Interval::new(1.0 - 4.0 * EPS, 1.0 + 4.0 * EPS));
                if unit_n {
                    let len = x.norm.slack(EPS * 8.0);
                    let comps = x.map(|_| Interval::new(-len.hi, len.hi));
                    let mut r =
                        Num::from_components(&comps, deps.set(Facts::NZ, fx.has(Facts::NZ)));
                    r.norm = r.norm.meet(len);
                    Val::Num(r.settle())
                } else {
                    let d = (0..x.n as usize).fold(Interval::point(0.0), |s, i| {
                        s.add(x.c[i].mul(nrm.c[i.min(nrm.n as usize - 1)]))
                    });
                    let k = d.mul(Interval::point(2.0));
                    let comps: Vec<Interval> = (0..x.n as usize)
                        .map(|i| x.c[i].sub(k.mul(nrm.c[i.min(nrm.n as usize - 1)])))
                        .collect();
                    Val::Num(Num::from_components(&comps, deps))
                }
            }
            Mf::QuantizeToF16 => Val::Num(Num::from_components(x.comps(), fx)),
            Mf::Unpack2x16unorm | Mf::Unpack4x8unorm => {
                shape(module, ty, &|n, _| Num::splat(Interval::UNIT, n, deps))
            }
            Mf::Unpack2x16snorm | Mf::Unpack4x8snorm => shape(module, ty, &|n, _| {
                Num::splat(Interval::SIGNED_UNIT, n, deps)
            }),
            _ => Self::unknown(module, ty, deps),
        }
    }
}
