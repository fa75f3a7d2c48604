//! Where each local variable is declared.
//!
//! naga's IR declares every local at the top of its function; GLSL (and a person writing
//! WGSL) declares it where its value is first given: `vec3 norm = normalize(Normal);` is
//! `let norm = normalize(Normal);`. A local is declared:
//! - **at its first store**, as `let` when nothing else stores to it or takes its address
//!   (and no dynamic index reads it: WGSL indexes a matrix value only by a constant), as
//!   `var` otherwise — when that store is the first statement to use it in the innermost
//!   block holding all its uses, and its value does not read the local;
//! - else as `var NAME: T;` just before that statement — or before the outermost loop around
//!   it, when that statement is inside a loop (a declaration inside the loop would start the
//!   value afresh on each iteration, where the IR's variable carries it over);
//! - as the entry point's **argument** itself when its only store copies that argument in
//!   (the entry point's inputs: `@location(0) aPos: vec3f` is read as `aPos`).

use std::collections::HashMap;

use naga::{Expression, Handle, LocalVariable, Statement};

use super::analysis::{operands, BlockId, Pos, Root, Shape};
use super::bake::{Bakes, Fate};

/// How a local is declared.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Decl {
    /// Never used: not written.
    Unused,
    /// `var NAME: T;` before the statement at this position.
    Before(Pos),
    /// `let NAME = value;` (or `var`, unless `constant`) at the store at this position.
    At { at: Pos, constant: bool },
    /// The entry point's argument of this index, named as the local; its store is not
    /// written.
    Argument { at: Pos, argument: u32 },
}

/// The declarations of a function's locals.
pub(crate) struct Decls {
    pub decl: HashMap<Handle<LocalVariable>, Decl>,
    /// The locals declared before each statement.
    pub before: HashMap<Pos, Vec<Handle<LocalVariable>>>,
    /// The locals whose declaring store is at each statement.
    pub at: HashMap<Pos, Handle<LocalVariable>>,
    /// Where each local is referenced (the statements whose text names it).
    pub refs: HashMap<Handle<LocalVariable>, Vec<Pos>>,
}

impl Decls {
    /// Plans the declarations.
    pub(crate) fn new(shape: &Shape, bakes: &Bakes) -> Decls {
        let mut refs: HashMap<Handle<LocalVariable>, Vec<Pos>> = HashMap::new();
        for (h, e) in shape.function.expressions.iter() {
            if let Expression::LocalVariable(l) = *e {
                refs.entry(l)
                    .or_default()
                    .extend(bakes.anchors[h.index()].iter().copied());
            }
        }
        let mut decls = Decls {
            decl: HashMap::new(),
            before: HashMap::new(),
            at: HashMap::new(),
            refs: HashMap::new(),
        };
        for (l, _) in shape.function.local_variables.iter() {
            let mut r = refs.remove(&l).unwrap_or_default();
            r.sort();
            r.dedup();
            let d = plan(shape, bakes, l, &r);
            match d {
                Decl::Before(p) => decls.before.entry(p).or_default().push(l),
                Decl::At { at, .. } | Decl::Argument { at, .. } => {
                    decls.at.insert(at, l);
                }
                Decl::Unused => {}
            }
            decls.decl.insert(l, d);
            decls.refs.insert(l, r);
        }
        decls
    }

    /// The block a local's declaration is in (its scope), with the statement it starts at.
    pub(crate) fn scope(&self, l: Handle<LocalVariable>) -> Option<Pos> {
        match self.decl.get(&l)? {
            Decl::Before(p) | Decl::At { at: p, .. } | Decl::Argument { at: p, .. } => Some(*p),
            Decl::Unused => None,
        }
    }
}

fn plan(shape: &Shape, bakes: &Bakes, l: Handle<LocalVariable>, refs: &[Pos]) -> Decl {
    let Some(&first_ref) = refs.first() else {
        return Decl::Unused;
    };
    if never_read(shape, bakes, l) {
        return Decl::Unused;
    }
    let lca = refs
        .iter()
        .fold(first_ref.block, |b, r| common_block(shape, b, r.block));
    let first = refs
        .iter()
        .filter_map(|r| shape.holder(*r, lca))
        .min()
        .unwrap_or(0);
    let at = Pos {
        block: lca,
        index: first,
    };
    let init = shape.function.local_variables[l].init;
    if let (Some(Statement::Store { pointer, value }), None) = (shape.statement(at), init) {
        let whole = matches!(shape.expr(*pointer), Expression::LocalVariable(v) if *v == l);
        if whole && refs.contains(&at) && !reads_local(shape, bakes, *value, l) {
            let constant = constant(shape, l);
            if constant && lca == 0 {
                if let Expression::FunctionArgument(argument) = *shape.expr(*value) {
                    return Decl::Argument { at, argument };
                }
            }
            return Decl::At { at, constant };
        }
    }
    Decl::Before(outside_loops(shape, declared_at(shape, l, at)))
}

/// `at`, or an earlier statement of its block where the GLSL declared the local (`vec2 p;`
/// stays where the author put it).
fn declared_at(shape: &Shape, l: Handle<LocalVariable>, at: Pos) -> Pos {
    let Some(declared) = shape.function.local_variables.get_span(l).to_range() else {
        return at;
    };
    let spans = &shape.spans[at.block];
    let index = (0..at.index)
        .find(|&k| {
            spans[k]
                .to_range()
                .is_some_and(|r| r.start >= declared.start)
        })
        .unwrap_or(at.index);
    Pos {
        block: at.block,
        index,
    }
}

/// Whether a local is only stored to, with values that call nothing (its stores are then
/// not written: `gl_PointSize` in WGSL).
pub(crate) fn never_read(shape: &Shape, bakes: &Bakes, l: Handle<LocalVariable>) -> bool {
    let root = Some(Root::Local(l));
    let f = shape.function;
    let mut stored = Vec::new();
    let uses_ok = f.expressions.iter().all(|(h, e)| match *e {
        Expression::LocalVariable(v) if v == l => shape.users[h.index()].iter().all(|u| match *u {
            super::analysis::User::Stmt(p) => match shape.statement(p) {
                Some(Statement::Store { pointer, value }) if *pointer == h => {
                    stored.push(*value);
                    true
                }
                _ => false,
            },
            super::analysis::User::Expr(_) => false,
        }),
        Expression::Load { pointer } | Expression::AccessIndex { base: pointer, .. } => {
            shape.root(pointer) != root
                || !matches!(shape.expr(pointer), Expression::LocalVariable(v) if *v == l)
        }
        _ => true,
    });
    uses_ok && !stored.is_empty() && stored.iter().all(|v| !calls(shape, bakes, *v))
}

/// Whether the text of `h` holds a call.
fn calls(shape: &Shape, bakes: &Bakes, h: Handle<Expression>) -> bool {
    if bakes.fate[h.index()] == Fate::Bake {
        return false;
    }
    match shape.expr(h) {
        Expression::CallResult(_) => true,
        e => operands(e).into_iter().any(|o| calls(shape, bakes, o)),
    }
}

/// The innermost block holding both.
fn common_block(shape: &Shape, a: BlockId, b: BlockId) -> BlockId {
    let mut x = a;
    loop {
        if shape.within(b, x) {
            return x;
        }
        match shape.blocks[x].parent {
            Some(p) => x = p.block,
            None => return 0,
        }
    }
}

/// `at`, or the outermost loop statement around it.
fn outside_loops(shape: &Shape, at: Pos) -> Pos {
    let mut out = at;
    let mut b = at.block;
    while let Some(parent) = shape.blocks[b].parent {
        if shape.blocks[b].in_loop {
            out = parent;
        }
        b = parent.block;
    }
    out
}

/// Whether the written text of `h` names local `l`.
fn reads_local(
    shape: &Shape,
    bakes: &Bakes,
    h: Handle<Expression>,
    l: Handle<LocalVariable>,
) -> bool {
    if bakes.fate[h.index()] == Fate::Bake {
        return false;
    }
    match *shape.expr(h) {
        Expression::LocalVariable(v) => v == l,
        ref e => operands(e)
            .into_iter()
            .any(|o| reads_local(shape, bakes, o, l)),
    }
}

/// Whether a local can be a `let`: one store (its declaration), no address taken, no
/// dynamic index.
fn constant(shape: &Shape, l: Handle<LocalVariable>) -> bool {
    let root = Some(Root::Local(l));
    let mut stores = 0;
    count_stores(shape, &shape.function.body, root, &mut stores);
    if stores != 1 {
        return false;
    }
    shape.function.expressions.iter().all(|(_, e)| match *e {
        Expression::Access { base, .. } => shape.root(base) != root,
        _ => true,
    })
}

fn count_stores(shape: &Shape, block: &naga::Block, root: Option<Root>, n: &mut usize) {
    for s in block.iter() {
        match s {
            Statement::Store { pointer, .. } if shape.root(*pointer) == root => *n += 1,
            Statement::Call { arguments, .. } => {
                for a in arguments {
                    if shape.is_pointer(*a) && shape.root(*a) == root {
                        *n += 2;
                    }
                }
            }
            Statement::Block(b) => count_stores(shape, b, root, n),
            Statement::If { accept, reject, .. } => {
                count_stores(shape, accept, root, n);
                count_stores(shape, reject, root, n);
            }
            Statement::Switch { cases, .. } => {
                for c in cases {
                    count_stores(shape, &c.body, root, n);
                }
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                count_stores(shape, body, root, n);
                count_stores(shape, continuing, root, n);
            }
            _ => {}
        }
    }
}
