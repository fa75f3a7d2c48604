//! The walk over a function's statements: which expressions each `Emit` evaluates, what
//! stores, calls and returns join into memory, parameters and results, and which places the
//! enclosing `if` conditions bound; and the facts about statements the walk needs (locals stored
//! once, blocks that never fall through, statements that write a variable).

use rustc_hash::FxHashMap as HashMap;

use naga::{Block, Expression as E, Function, Handle, Statement};

use super::flow;
use super::memory::pointee;
use super::series;
use super::{function, Analysis, Place, Root, Site};
use crate::value::Val;

impl Analysis {
    /// Walks function `id` once: evaluates its expressions and joins what it stores, returns
    /// and passes into the cells, results and parameters.
    pub(super) fn run_function(
        &mut self,
        module: &naga::Module,
        info: &essl::lower::Lowered,
        id: usize,
    ) {
        let f = function(module, id);
        let n = f.expressions.len();
        self.walking_entry = id >= module.functions.len();
        self.at_call.walked[id] = true;
        {
            let ff = &mut self.functions[id];
            ff.values = vec![Val::Bot; n];
            ff.places = vec![None; n];
            ff.emit = vec![0; n];
            ff.load_version = vec![0; n];
        }
        let s = Site {
            module,
            info,
            types: info.function(id),
            f,
            id,
        };
        for (h, e) in f.expressions.iter() {
            if e.needs_pre_emit() || matches!(e, E::CallResult(_)) {
                self.eval(s, h);
            }
        }
        self.current.clear();
        for (lh, l) in f.local_variables.iter() {
            if let Some(init) = l.init {
                let v = self.functions[id].values[init.index()].clone();
                let place = Place {
                    root: Root::Local(id, lh.index()),
                    path: Vec::new(),
                };
                self.store(module, &place, &v);
                self.assign(module, &place, &v);
                self.note_store(&place, init);
            }
        }
        self.block(s, &f.body);
    }

    /// Walks a block, with what the enclosing `if` conditions say about the places it loads.
    fn block(&mut self, s: Site, b: &Block) {
        let depth = self.refine.len();
        let stmts: Vec<&Statement> = b.iter().collect();
        for (i, st) in stmts.iter().enumerate() {
            match st {
                Statement::If {
                    condition,
                    accept,
                    reject,
                } => self.if_statement(s, *condition, accept, reject, &stmts[i + 1..]),
                Statement::Emit(r) => {
                    self.emit_counter += 1;
                    for h in r.clone() {
                        self.functions[s.id].emit[h.index()] = self.emit_counter;
                        self.eval(s, h);
                    }
                }
                Statement::Block(b) => self.block(s, b),
                Statement::Switch { cases, .. } => self.switch(s, cases),
                Statement::Loop {
                    body, continuing, ..
                } => {
                    self.forget_written(s.f, s.id, &[body, continuing]);
                    let entry = self.current.clone();
                    self.block(s, body);
                    self.current = entry.clone();
                    self.block(s, continuing);
                    self.current = entry;
                }
                Statement::Return { value: Some(v) } => {
                    let val = self.functions[s.id].values[v.index()].clone();
                    let mut changed = false;
                    let slot = match self.calls.results.last_mut() {
                        Some(r) => r,
                        None => &mut self.results[s.id],
                    };
                    Self::join_into(slot, &val, false, &mut changed);
                    if !self.calls.walking() {
                        self.changed |= changed;
                        self.stale |= changed && self.reads.borrow().results.contains(&s.id);
                    }
                    break;
                }
                Statement::Store { pointer, value } => {
                    if let Some(p) = self.functions[s.id].places[pointer.index()].clone() {
                        let v = self.functions[s.id].values[value.index()].clone();
                        let bound = self
                            .series_bound(s, &p, *value)
                            .or_else(|| self.growth_bound(s, &p, *value));
                        let v = match &bound {
                            Some(b) => series::clamp(&v, b),
                            None => v,
                        };
                        self.store_within(s.module, &p, &v, bound.as_deref());
                        self.assign(s.module, &p, &v);
                        self.note_store(&p, *value);
                    }
                }
                Statement::Call {
                    function: callee,
                    arguments,
                    result,
                } => {
                    self.call(s, callee.index(), arguments, *result);
                    self.forget_call(s.f, s.id, callee.index(), arguments);
                }
                Statement::Return { .. }
                | Statement::Kill
                | Statement::Break
                | Statement::Continue => break,
                _ => {}
            }
        }
        self.refine.truncate(depth);
    }

    /// Walks the cases of a `switch`, each from the state before it when it is
    /// self-contained, and joins the states they leave it with.
    fn switch(&mut self, s: Site, cases: &[naga::SwitchCase]) {
        if !cases.iter().all(flow::self_contained) {
            let bodies: Vec<&Block> = cases.iter().map(|c| &c.body).collect();
            self.forget_written(s.f, s.id, &bodies);
        }
        let entry = self.current.clone();
        let mut after: Option<flow::Current> = None;
        for c in cases {
            self.current = entry.clone();
            self.block(s, &c.body);
            let leaves = !matches!(
                c.body.last(),
                Some(Statement::Return { .. } | Statement::Kill | Statement::Continue)
            );
            if leaves {
                let end = std::mem::take(&mut self.current);
                after = Some(match after {
                    None => end,
                    Some(a) => flow::merge(a, &end),
                });
            }
        }
        self.current = after.unwrap_or(entry);
    }

    /// Walks both branches of an `if`, each under its condition; after `if (c) { …; return; }`
    /// the `rest` of the block has `!c` (and the mirror).
    fn if_statement(
        &mut self,
        s: Site,
        condition: Handle<E>,
        accept: &Block,
        reject: &Block,
        rest: &[&Statement],
    ) {
        let d = self.refine.len();
        fn inside(blk: &Block) -> Vec<&Statement> {
            blk.iter().collect()
        }
        let before = self.current.clone();
        let mut after: Option<flow::Current> = None;
        for (blk, polarity) in [(accept, true), (reject, false)] {
            self.current = before.clone();
            let rs = self.refinements(s, condition, polarity, &[&inside(blk)]);
            self.refine.extend(rs);
            self.block(s, blk);
            self.refine.truncate(d);
            if !diverges(blk) {
                let end = std::mem::take(&mut self.current);
                after = Some(match after {
                    None => end,
                    Some(a) => flow::merge(a, &end),
                });
            }
        }
        self.current = after.unwrap_or(before);
        let (ad, rd) = (diverges(accept), diverges(reject));
        if ad != rd {
            let other = if ad { reject } else { accept };
            let rs = self.refinements(s, condition, rd, &[rest, &inside(other)]);
            self.refine.extend(rs);
        }
    }

    /// A call of function `c`: the arguments join into its parameters (a pointer argument
    /// shares its cell: copy-in, the callee's walk when this is its only call, copy-out), its
    /// result into `result`.
    fn call(&mut self, s: Site, c: usize, arguments: &[Handle<E>], result: Option<Handle<E>>) {
        let (module, id) = (s.module, s.id);
        for (i, a) in arguments.iter().enumerate() {
            if let Some(p) = self.functions[id].places[a.index()].clone() {
                // A pointer argument: the caller's variable and the parameter's cell
                // hold the same values (copy-in for `inout`, copy-out after).
                let arg_root = Place {
                    root: Root::Arg(c, i),
                    path: Vec::new(),
                };
                let ty = pointee(module, s.ty(*a));
                let mine = self
                    .current_value(&p)
                    .unwrap_or_else(|| self.load(module, &p, &ty));
                self.store(module, &arg_root, &mine);
            } else if !self.calls.walking() {
                let v = self.functions[id].values[a.index()].clone();
                let mut changed = false;
                if let Some(slot) = self.args[c].get_mut(i) {
                    Self::join_into(slot, &v, false, &mut changed);
                }
                self.changed |= changed;
                self.stale |= changed && self.reads.borrow().args.contains(&c);
            }
        }
        self.walk_at_call(s, c);
        for (i, a) in arguments.iter().enumerate() {
            if let Some(p) = self.functions[id].places[a.index()].clone() {
                // Copy-out: what the callee left in the parameter's cell.
                self.note_read(Root::Arg(c, i));
                let theirs = self.cell(module, Root::Arg(c, i));
                self.store(module, &p, &theirs);
            }
        }
        if let Some(r) = result {
            let v = self.call_result(s, c, arguments).unwrap_or_else(|| {
                if !self.walking_entry {
                    self.reads.borrow_mut().results.insert(c);
                }
                self.results[c].clone()
            });
            self.functions[id].values[r.index()] = v;
        }
    }
}

/// Calls `visit` on every statement of `block`, nested blocks included: a statement, then
/// the statements of the blocks it holds.
pub(crate) fn each_statement(block: &Block, visit: &mut impl FnMut(&Statement)) {
    for st in block.iter() {
        visit(st);
        match st {
            Statement::Block(b) => each_statement(b, visit),
            Statement::If { accept, reject, .. } => {
                each_statement(accept, visit);
                each_statement(reject, visit);
            }
            Statement::Switch { cases, .. } => {
                for c in cases {
                    each_statement(&c.body, visit);
                }
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                each_statement(body, visit);
                each_statement(continuing, visit);
            }
            _ => {}
        }
    }
}

/// The local a pointer expression points into, and whether it points to the whole local
/// (not a member, component or element of it).
pub(super) fn root_local(f: &Function, mut p: Handle<E>) -> Option<(usize, bool)> {
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

/// Locals stored exactly once (the whole variable), outside loops, never passed by pointer; and
/// the whole stores of every local never stored in part or passed by pointer.
#[allow(clippy::type_complexity)]
pub(super) fn single_stores(
    f: &Function,
) -> (HashMap<usize, Handle<E>>, HashMap<usize, Vec<Handle<E>>>) {
    #[derive(Default)]
    struct Count {
        whole: Vec<(usize, Handle<E>, bool)>,
        spoiled: rustc_hash::FxHashSet<usize>,
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

/// Whether a block ends every path through it with `break`, `continue`, `return` or `discard`.
pub(crate) fn diverges(b: &Block) -> bool {
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
pub(super) fn writes(
    module: &naga::Module,
    f: &Function,
    stmts: &[&Statement],
    root: Root,
) -> bool {
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

/// The expressions an expression reads.
pub(crate) fn operands(e: &E) -> Vec<Handle<E>> {
    match e {
        E::Compose { components, .. } => components.clone(),
        E::Access { base, index } => vec![*base, *index],
        E::AccessIndex { base, .. } => vec![*base],
        E::Splat { value, .. } => vec![*value],
        E::Swizzle { vector, .. } => vec![*vector],
        E::Load { pointer } => vec![*pointer],
        E::Unary { expr, .. } | E::Derivative { expr, .. } | E::As { expr, .. } => vec![*expr],
        E::Binary { left, right, .. } => vec![*left, *right],
        E::Select {
            condition,
            accept,
            reject,
        } => vec![*condition, *accept, *reject],
        E::Relational { argument, .. } => vec![*argument],
        E::Math {
            arg,
            arg1,
            arg2,
            arg3,
            ..
        } => [Some(*arg), *arg1, *arg2, *arg3]
            .into_iter()
            .flatten()
            .collect(),
        E::ImageSample {
            coordinate,
            depth_ref,
            ..
        } => [Some(*coordinate), *depth_ref]
            .into_iter()
            .flatten()
            .collect(),
        E::ImageLoad { coordinate, .. } => vec![*coordinate],
        _ => Vec::new(),
    }
}
