//! What a variable holds at each point of the walk: strong updates along the statements.
//!
//! The cells of [`Analysis`] hold the join of every value ever stored into a variable, which is
//! what a load inside a loop, or in another function, may see. Along straight-line code the
//! walk knows more: after `x = max(x, 0.0);` a load of `x` sees that value and no other, and
//! after `gl_FragColor = vec4(c, 1.0);` the next `linearToOutputTexel(gl_FragColor)` reads
//! `vec4(c, 1.0)`, not the join with what the call later stores back. The walk keeps such a
//! value per variable (`current`) for the locals of the function it walks and the private
//! globals: a store replaces it (a store into a part replaces that part), the two branches of an
//! `if` join theirs (a branch that returns, discards, breaks or continues adds nothing), a loop
//! or `switch` forgets what it writes, and a call forgets what its pointer arguments point to
//! and the globals it may write. A variable the walk knows nothing of reads its cell.

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use naga::{Block, Expression as E, Function, Handle, Statement};

use super::memory::write;
use super::statements::each_statement;
use super::{function, Analysis, Place, Root, ANY};
use crate::value::{norm_of, Facts, Val};

/// What the walk knows at a point: the values variables hold, and a version per variable
/// that two loads share when no store came between them (so that the `x` that `x < 0.0`
/// compares is the `x` of `-pow(-x, p)` under it).
#[derive(Clone, Debug, Default)]
pub(super) struct Current {
    values: HashMap<Root, Val>,
    versions: HashMap<Root, u32>,
}

impl Current {
    /// Knows nothing.
    pub(super) fn clear(&mut self) {
        self.values.clear();
        self.versions.clear();
    }

    fn forget(&mut self, root: &Root) {
        self.values.remove(root);
        self.versions.remove(root);
    }
}

/// Writes `new` into the part of `v` at `path`, replacing what was there (an array element,
/// standing for every element, and a dynamic index only join); `false` when the path does not
/// fit the value.
fn write_strong(v: &mut Val, path: &[u32], new: &Val) -> bool {
    let Some((&step, rest)) = path.split_first() else {
        *v = new.clone();
        return true;
    };
    match v {
        Val::Arr(x) => {
            write(x, rest, new, false);
            true
        }
        Val::Agg(xs) if step == ANY => {
            for x in xs.iter_mut() {
                write(x, rest, new, false);
            }
            true
        }
        Val::Agg(xs) => match xs.get_mut(step as usize) {
            Some(x) => write_strong(x, rest, new),
            None => false,
        },
        Val::Num(n) if rest.is_empty() && step != ANY => {
            let Some(s) = new.num() else { return false };
            let i = step as usize;
            if i >= n.n as usize || s.is_bottom() {
                return false;
            }
            n.c[i] = s.c[0];
            n.facts = n.facts.join(s.facts).without(Facts::NZ).without(Facts::EXT);
            n.norm = norm_of(n.comps());
            *n = n.settle();
            true
        }
        Val::Num(_) if rest.is_empty() => {
            write(v, path, new, false);
            true
        }
        _ => false,
    }
}

/// The variable at the root of a pointer expression.
fn root_of(f: &Function, id: usize, mut p: Handle<E>) -> Option<Root> {
    loop {
        match f.expressions[p] {
            E::LocalVariable(l) => return Some(Root::Local(id, l.index())),
            E::GlobalVariable(g) => return Some(Root::Global(g.index())),
            E::FunctionArgument(i) => return Some(Root::Arg(id, i as usize)),
            E::Access { base, .. } | E::AccessIndex { base, .. } => p = base,
            _ => return None,
        }
    }
}

/// The index of the global variable pointer `p` of `f` points into, if it points into one.
pub(crate) fn root_global(f: &Function, p: Handle<E>) -> Option<usize> {
    match root_of(f, 0, p) {
        Some(Root::Global(g)) => Some(g),
        _ => None,
    }
}

/// The private globals each function writes, itself or through the functions it calls
/// (module functions by handle index, then entry points).
pub(super) fn global_writes(module: &naga::Module) -> Vec<HashSet<usize>> {
    let count = module.functions.len() + module.entry_points.len();
    let mut out: Vec<HashSet<usize>> = vec![HashSet::default(); count];
    // A function only calls functions declared before it, so one pass in order suffices.
    for id in 0..count {
        let f = function(module, id);
        let mut set = HashSet::default();
        let global = |p: Handle<E>| root_global(f, p);
        each_statement(&f.body, &mut |s| match s {
            Statement::Store { pointer, .. } => set.extend(global(*pointer)),
            Statement::Call {
                function: callee,
                arguments,
                ..
            } => {
                set.extend(arguments.iter().filter_map(|a| global(*a)));
                if let Some(w) = out.get(callee.index()) {
                    set.extend(w.iter().copied());
                }
            }
            _ => {}
        });
        out[id] = set;
    }
    out
}

/// Whether a `switch` case can be walked on its own from the state before the `switch`: it
/// does not fall through into the next case, and its only `break` is its last statement (a
/// `break` inside an `if` leaves the `switch` with a state the walk does not keep).
pub(super) fn self_contained(case: &naga::SwitchCase) -> bool {
    fn inner_break(b: &Block, top: bool) -> bool {
        let n = b.len();
        b.iter().enumerate().any(|(i, s)| match s {
            Statement::Break => !(top && i + 1 == n),
            Statement::Block(b) => inner_break(b, false),
            Statement::If { accept, reject, .. } => {
                inner_break(accept, false) || inner_break(reject, false)
            }
            _ => false,
        })
    }
    !case.fall_through && !inner_break(&case.body, true)
}

/// The two states after an `if`: a variable keeps a value where both branches know one, and
/// its version where both branches left it unchanged.
pub(super) fn merge(a: Current, b: &Current) -> Current {
    Current {
        values: a
            .values
            .into_iter()
            .filter_map(|(root, v)| b.values.get(&root).map(|w| (root, v.join(w))))
            .collect(),
        versions: a
            .versions
            .into_iter()
            .filter(|(root, v)| b.versions.get(root) == Some(v))
            .collect(),
    }
}

impl Analysis {
    /// What the walk knows `place` holds here, if it knows.
    pub(super) fn current_value(&self, place: &Place) -> Option<Val> {
        let v = self.current.values.get(&place.root)?;
        Some(super::memory::read(v, &place.path))
    }

    /// The version of the variable a load of `place` reads here (0: not followed): loads with
    /// the same version read the same value (of the same part: a dynamic index is compared by
    /// [`Analysis::same`]).
    pub(super) fn load_version(&mut self, place: &Place) -> u32 {
        if let Some(v) = self.current.versions.get(&place.root) {
            return *v;
        }
        let v = self.fresh_version();
        self.current.versions.insert(place.root, v);
        v
    }

    /// Records that the version [`Analysis::assign`] just gave `place` holds `value`, where
    /// the store wrote a whole local.
    pub(super) fn note_store(&mut self, place: &Place, value: Handle<E>) {
        if matches!(place.root, Root::Local(..)) && place.path.is_empty() {
            self.version_stores.insert(self.version_counter, value);
        }
    }

    /// The value the store that load `h` of function `id` reads wrote: the last whole store
    /// into the local on every path to the load (`l` in `float l = length(t); t /= l;` where
    /// `l` is written again later).
    pub fn reaching_store(&self, id: usize, h: Handle<E>) -> Option<Handle<E>> {
        let version = *self.functions.get(id)?.load_version.get(h.index())?;
        (version != 0)
            .then(|| self.version_stores.get(&version).copied())
            .flatten()
    }

    fn fresh_version(&mut self) -> u32 {
        self.version_counter += 1;
        self.version_counter
    }

    /// A store of `v` into `place`: the value the walk knows the variable holds from here on.
    pub(super) fn assign(&mut self, module: &naga::Module, place: &Place, v: &Val) {
        let tracked = match place.root {
            Root::Local(..) => true,
            Root::Global(g) => module
                .global_variables
                .iter()
                .nth(g)
                .is_some_and(|(_, gv)| gv.space == naga::AddressSpace::Private),
            Root::Arg(..) => true,
        };
        if !tracked {
            return;
        }
        let version = self.fresh_version();
        self.current.versions.insert(place.root, version);
        if place.path.is_empty() {
            self.current.values.insert(place.root, v.clone());
            return;
        }
        let mut whole = match self.current.values.get(&place.root) {
            Some(c) => c.clone(),
            None => {
                self.note_read(place.root);
                self.cell(module, place.root)
            }
        };
        if write_strong(&mut whole, &place.path, v) {
            self.current.values.insert(place.root, whole);
        } else {
            self.current.values.remove(&place.root);
        }
    }

    /// After a call of function `callee` from function `id`: what its pointer arguments point
    /// to and the globals it may write are no longer known.
    pub(super) fn forget_call(
        &mut self,
        f: &Function,
        id: usize,
        callee: usize,
        args: &[Handle<E>],
    ) {
        for a in args {
            if let Some(root) = root_of(f, id, *a) {
                self.current.forget(&root);
            }
        }
        if let Some(w) = self.global_writes.get(callee) {
            let written = |root: &Root| matches!(root, Root::Global(g) if w.contains(g));
            self.current.values.retain(|root, _| !written(root));
            self.current.versions.retain(|root, _| !written(root));
        }
    }

    /// Forgets every variable that statements of function `id` may write (before a loop or a
    /// `switch`, whose statements run in an order the walk does not follow).
    pub(super) fn forget_written(&mut self, f: &Function, id: usize, blocks: &[&Block]) {
        let mut roots: Vec<Root> = Vec::new();
        for b in blocks {
            self.collect_written(f, id, b, &mut roots);
        }
        for r in roots {
            self.current.forget(&r);
        }
    }

    fn collect_written(&self, f: &Function, id: usize, b: &Block, out: &mut Vec<Root>) {
        each_statement(b, &mut |s| match s {
            Statement::Store { pointer, .. } => out.extend(root_of(f, id, *pointer)),
            Statement::Call {
                function: callee,
                arguments,
                ..
            } => {
                out.extend(arguments.iter().filter_map(|a| root_of(f, id, *a)));
                if let Some(w) = self.global_writes.get(callee.index()) {
                    out.extend(w.iter().map(|g| Root::Global(*g)));
                }
            }
            _ => {}
        });
    }
}
