//! Which functions, globals, blocks and built-ins the entry point actually uses — WebGL's
//! notion of "active", which is more than static use: ANGLE folds constant `if`/`?:`
//! conditions, drops code after `return`, drops the declaration of a local that nothing but
//! its declaration names — and then the declarations only those name, a chain — while a local
//! assigned anywhere (`x = u;`, `c.a = u;`, `x++`) is kept with everything stored in it, read
//! or not (measured: `tests/oracle/PROBES.md` §1), and drops values that are computed and discarded
//! without a side effect — an expression statement such as `1.0 + u;`, the left operand of
//! `,` (`tests/oracle/ES100.md`, "Active uniforms"). Loops are not evaluated and `x * 0.0` is
//! not folded. A global's non-constant initializer (GLSL ES 1.00 in WebGL) runs at the start of
//! `main`: what it reads is used when the global is.

use crate::builtins::BuiltinVar;
use crate::hir::{
    Cond, Expr, ExprKind, Function, GlobalId, LocalId, Module, Scalar, Stmt, StmtKind,
};

/// One thing that code reads or calls.
#[derive(Clone, Copy)]
enum Use {
    Global(GlobalId),
    Block(usize),
    Builtin(BuiltinVar),
    Call(usize),
    Local(LocalId),
}

/// What a piece of code reads or calls, in the order met, repeats included: appending is all
/// the walk does, and the few consumers below skip what they have seen. A function's list is
/// as long as its expressions, so this stays linear where sets of each kind cost an
/// allocation per kind and per store.
#[derive(Default)]
struct Uses(Vec<Use>);

impl Uses {
    fn push(&mut self, u: Use) {
        self.0.push(u);
    }

    fn locals(&self) -> impl Iterator<Item = LocalId> + '_ {
        self.0.iter().filter_map(|u| match *u {
            Use::Local(l) => Some(l),
            _ => None,
        })
    }
}

/// Marks `used` on functions, globals and blocks, and fills `used_builtins`.
pub fn mark(m: &mut Module) {
    let Some(entry) = m.entry else { return };
    let mut fn_used = vec![false; m.functions.len()];
    let mut all = Uses::default();
    let mut stack = vec![entry];
    fn_used[entry] = true;
    while let Some(f) = stack.pop() {
        let uses = analyze(&m.functions[f]);
        for u in &uses.0 {
            if let Use::Call(c) = *u {
                if !fn_used[c] {
                    fn_used[c] = true;
                    stack.push(c);
                }
            }
        }
        all.0.extend(uses.0);
    }
    for (f, used) in m.functions.iter_mut().zip(fn_used) {
        f.used = used;
    }
    initializer_uses(m, &mut all);
    let mut builtins = Vec::new();
    for u in all.0 {
        match u {
            Use::Global(g) => {
                m.globals[g].used = true;
                if let crate::hir::GlobalKind::BlockMember(b, _) = m.globals[g].kind {
                    m.blocks[b].used = true;
                }
            }
            Use::Block(b) => m.blocks[b].used = true,
            Use::Builtin(v) => builtins.push(v),
            Use::Call(_) | Use::Local(_) => {}
        }
    }
    builtins.sort_unstable();
    builtins.dedup();
    m.used_builtins = builtins;
}

/// Adds what the non-constant initializers of the used globals read, until nothing changes.
fn initializer_uses(m: &Module, all: &mut Uses) {
    let mut seen = vec![false; m.globals.len()];
    let mut pending: Vec<GlobalId> = Vec::new();
    let mut visit = |u: &Use, pending: &mut Vec<GlobalId>| {
        if let Use::Global(g) = *u {
            if !seen[g] {
                seen[g] = true;
                pending.push(g);
            }
        }
    };
    for u in &all.0 {
        visit(u, &mut pending);
    }
    while let Some(g) = pending.pop() {
        let Some(crate::hir::Init::Expr(e)) = &m.globals[g].init else {
            continue;
        };
        let mut u = Uses::default();
        expr(e, &mut u);
        for x in &u.0 {
            visit(x, &mut pending);
        }
        all.0.extend(u.0);
    }
}

/// A local's declaration: what its initializer reads counts only if something else names the
/// local.
struct Store {
    target: LocalId,
    uses: Uses,
}

struct Walker {
    live: Uses,
    stores: Vec<Store>,
}

fn analyze(f: &Function) -> Uses {
    let mut w = Walker {
        live: Uses::default(),
        stores: Vec::new(),
    };
    w.block(&f.body);
    // Locals read in live code make the stores to them live, which may read more locals: a
    // worklist over locals, each store visited once.
    let mut stores_of: rustc_hash::FxHashMap<LocalId, Vec<usize>> =
        rustc_hash::FxHashMap::default();
    for (i, st) in w.stores.iter().enumerate() {
        stores_of.entry(st.target).or_default().push(i);
    }
    let mut pending: Vec<LocalId> = w.live.locals().collect();
    let mut done = rustc_hash::FxHashSet::default();
    while let Some(l) = pending.pop() {
        if !done.insert(l) {
            continue;
        }
        for &i in stores_of.get(&l).map(|v| v.as_slice()).unwrap_or(&[]) {
            for &u in &w.stores[i].uses.0 {
                match u {
                    Use::Local(nl) => {
                        if !done.contains(&nl) {
                            pending.push(nl);
                        }
                    }
                    u => w.live.push(u),
                }
            }
        }
    }
    w.live
}

fn const_bool(e: &Expr) -> Option<bool> {
    match &e.kind {
        ExprKind::Const(c) => match c.scalars()? {
            [Scalar::B(b)] => Some(*b),
            _ => None,
        },
        _ => None,
    }
}

impl Walker {
    /// Walks statements; returns true when the block ends control flow (later code is dead).
    fn block(&mut self, stmts: &[Stmt]) -> bool {
        for s in stmts {
            if self.stmt(s) {
                return true;
            }
        }
        false
    }

    fn stmt(&mut self, s: &Stmt) -> bool {
        match &s.kind {
            StmtKind::Expr(e) => self.effect(e),
            StmtKind::Local(l, init) => {
                if let Some(e) = init {
                    let mut u = Uses::default();
                    expr(e, &mut u);
                    if e.has_effects() {
                        // A call or a store in the initializer runs whether or not the local
                        // is named again.
                        self.live.0.extend(u.0);
                    } else {
                        self.stores.push(Store {
                            target: *l,
                            uses: u,
                        });
                    }
                }
            }
            StmtKind::Block(b) => return self.block(b),
            StmtKind::If(c, t, e) => match const_bool(c) {
                Some(true) => return self.block(t),
                Some(false) => return self.block(e),
                None => {
                    expr(c, &mut self.live);
                    let a = self.block(t);
                    let b = self.block(e);
                    return a && b;
                }
            },
            StmtKind::Loop {
                init,
                cond,
                step,
                body,
                do_while,
            } => {
                self.block(init);
                let never =
                    matches!(cond.as_deref(), Some(Cond::Expr(c)) if const_bool(c) == Some(false));
                if let Some(c) = cond {
                    match &**c {
                        Cond::Expr(e) => expr(e, &mut self.live),
                        Cond::Decl(l, e) => {
                            self.live.push(Use::Local(*l));
                            expr(e, &mut self.live);
                        }
                    }
                }
                if never && !do_while {
                    return false;
                }
                if let Some(st) = step {
                    self.effect(st);
                }
                self.block(body);
            }
            StmtKind::Switch(sel, cases) => {
                expr(sel, &mut self.live);
                for c in cases {
                    self.block(&c.body);
                }
            }
            StmtKind::Return(v) => {
                if let Some(e) = v {
                    expr(e, &mut self.live);
                }
                return true;
            }
            StmtKind::Discard => return true,
            StmtKind::Break | StmtKind::Continue => return true,
        }
        false
    }

    /// An expression statement: a store to a local names it, which keeps the local (and what
    /// its declaration reads) whether or not it is read later.
    fn effect(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Comma(a, b) => {
                self.effect(a);
                self.effect(b);
            }
            // A value computed and discarded without a side effect: ANGLE drops it.
            _ if !e.has_effects() => {}
            _ => expr(e, &mut self.live),
        }
    }
}

/// Collects everything an expression reads or calls.
fn expr(e: &Expr, u: &mut Uses) {
    match &e.kind {
        ExprKind::Error | ExprKind::Const(_) => {}
        ExprKind::Local(l) => {
            u.push(Use::Local(*l));
        }
        ExprKind::Param(_) => {}
        ExprKind::Global(g) => {
            u.push(Use::Global(*g));
        }
        ExprKind::BuiltinVar(v) => {
            u.push(Use::Builtin(*v));
        }
        ExprKind::Unary(_, a)
        | ExprKind::IncDec(_, _, a)
        | ExprKind::Member(a, _)
        | ExprKind::Swizzle(a, _) => expr(a, u),
        ExprKind::Binary(_, a, b) | ExprKind::Assign(_, a, b) | ExprKind::Index(a, b) => {
            expr(a, u);
            expr(b, u);
        }
        // The left operand's value is discarded: only its side effects count.
        ExprKind::Comma(a, b) => {
            if a.has_effects() {
                expr(a, u);
            }
            expr(b, u);
        }
        ExprKind::Select(c, a, b) => {
            expr(c, u);
            expr(a, u);
            expr(b, u);
        }
        ExprKind::Call(f, args) => {
            u.push(Use::Call(*f));
            for a in args {
                expr(a, u);
            }
        }
        ExprKind::Builtin(_, args) | ExprKind::Construct(args) => {
            for a in args {
                expr(a, u);
            }
        }
        ExprKind::BlockMember(b, idx, _) => {
            u.push(Use::Block(*b));
            if let Some(i) = idx {
                expr(i, u);
            }
        }
    }
}
