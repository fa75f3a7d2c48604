//! Which expressions get a `let` of their own and which are written where they are used.
//!
//! naga's writer bakes every load and every value used twice into `let _eN = …;`. A person
//! writes `gl_Position = projection * view * vec4f(pos, 1.0);`. The rules here write an
//! expression where it is used (each use, for a load or an access that is cheap to repeat)
//! unless that could change what it computes:
//! - a **load** moves to its use only when nothing in between may store to what it reads:
//!   `float old = x; x = 5.0; y = old;` keeps `old`'s load where it was;
//! - a **call** moves only past `Emit`s (and other calls moved with it), and only where the
//!   order of the calls, and of each call and the loads of what it may write, stays the same
//!   in the text as in naga's IR;
//! - nothing that reads memory moves into a nested block (a loop would read it again on
//!   every iteration: a loop-carried value);
//! - nothing that needs uniform control flow (`textureSample`, `dpdx`) and no call moves into
//!   the right operand of `&&` or `||`, which WGSL evaluates only sometimes;
//! - a value used more than once is computed once, unless it is a load or an access, which
//!   reads the same variable again.
//!
//! The rules are applied until nothing changes: each `let` added only shortens how far the
//! others move.

use std::collections::{HashMap, HashSet};

use naga::{BinaryOperator, Expression, Handle, SampleLevel, Statement};

use super::analysis::{operands, Pos, Root, Shape, User};

/// What becomes of an expression in the text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Fate {
    /// Written where it is used (at each use).
    Inline,
    /// `let NAME = …;` where naga evaluates it.
    Bake,
    /// Part of a constructor's swizzle run.
    Run,
    /// Not used (a call's result: the call is written alone).
    Unused,
}

/// The globals each function of the module may store to, itself or through its callees.
pub(crate) type Writes = HashMap<Handle<naga::Function>, HashSet<Handle<naga::GlobalVariable>>>;

/// The globals every function may store to.
pub(crate) fn function_writes(module: &naga::Module) -> Writes {
    let mut writes: Writes = HashMap::new();
    // Callees come first in the arena (naga forbids recursion and forward calls).
    for (h, f) in module.functions.iter() {
        let mut set = HashSet::new();
        collect_writes(&f.body, f, &writes, &mut set);
        writes.insert(h, set);
    }
    writes
}

fn collect_writes(
    block: &naga::Block,
    f: &naga::Function,
    writes: &Writes,
    set: &mut HashSet<Handle<naga::GlobalVariable>>,
) {
    for s in block.iter() {
        match s {
            Statement::Store { pointer, .. } => {
                let mut h = *pointer;
                loop {
                    match f.expressions[h] {
                        Expression::Access { base, .. } | Expression::AccessIndex { base, .. } => {
                            h = base
                        }
                        Expression::GlobalVariable(g) => {
                            set.insert(g);
                            break;
                        }
                        _ => break,
                    }
                }
            }
            Statement::Call { function, .. } => {
                if let Some(w) = writes.get(function) {
                    set.extend(w.iter().copied());
                }
            }
            Statement::Block(b) => collect_writes(b, f, writes, set),
            Statement::If { accept, reject, .. } => {
                collect_writes(accept, f, writes, set);
                collect_writes(reject, f, writes, set);
            }
            Statement::Switch { cases, .. } => {
                for c in cases {
                    collect_writes(&c.body, f, writes, set);
                }
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                collect_writes(body, f, writes, set);
                collect_writes(continuing, f, writes, set);
            }
            _ => {}
        }
    }
}

/// The fate of every expression of a function.
pub(crate) struct Bakes {
    pub fate: Vec<Fate>,
    /// The statements where an expression's text ends up (its own `let` when baked).
    pub anchors: Vec<Vec<Pos>>,
}

/// Decides the fate of every expression of the function.
pub(crate) fn bakes(shape: &Shape, writes: &Writes) -> Bakes {
    let statics = Statics::new(shape);
    let mut forced = HashSet::new();
    loop {
        let bakes = decide(shape, &statics, &forced);
        let more = Hazards::new(shape, writes, &bakes).find();
        let before = forced.len();
        forced.extend(more);
        if forced.len() == before {
            return bakes;
        }
    }
}

/// What the IR says about each expression, whatever the fates.
struct Statics {
    /// Whether the expression reads memory, calls, samples or differentiates (in its tree).
    reads: Vec<bool>,
    /// Whether it is cheap and pure to write again at each use.
    duplicable: Vec<bool>,
    /// The first component of each swizzle run, pointing at its base.
    leaders: HashSet<Handle<Expression>>,
}

impl Statics {
    fn new(shape: &Shape) -> Statics {
        let n = shape.function.expressions.len();
        let mut reads = vec![false; n];
        let mut duplicable = vec![false; n];
        for (h, e) in shape.function.expressions.iter() {
            let own = matches!(
                e,
                Expression::Load { .. }
                    | Expression::CallResult(_)
                    | Expression::ImageSample { .. }
                    | Expression::ImageLoad { .. }
                    | Expression::ImageQuery { .. }
                    | Expression::Derivative { .. }
            );
            reads[h.index()] = own || operands(e).iter().any(|o| reads[o.index()]);
            duplicable[h.index()] = match *e {
                Expression::Literal(_)
                | Expression::Constant(_)
                | Expression::ZeroValue(_)
                | Expression::GlobalVariable(_)
                | Expression::LocalVariable(_)
                | Expression::FunctionArgument(_) => true,
                Expression::AccessIndex { base, .. } => duplicable[base.index()],
                Expression::Access { base, index } => {
                    duplicable[base.index()] && duplicable[index.index()]
                }
                Expression::Load { pointer } => duplicable[pointer.index()],
                Expression::Compose { ref components, .. } => components
                    .iter()
                    .all(|c| matches!(shape.expr(*c), Expression::Literal(_))),
                _ => false,
            };
        }
        let mut leaders = HashSet::new();
        for (compose, runs) in &shape.runs {
            let Expression::Compose { components, .. } = shape.expr(*compose) else {
                continue;
            };
            for run in runs {
                let first = components[run.start];
                leaders.insert(match (run.load, shape.expr(first)) {
                    (true, Expression::Load { pointer }) => *pointer,
                    _ => first,
                });
            }
        }
        Statics {
            reads,
            duplicable,
            leaders,
        }
    }
}

/// The fates, given the expressions that must be baked.
fn decide(shape: &Shape, statics: &Statics, forced: &HashSet<Handle<Expression>>) -> Bakes {
    let n = shape.function.expressions.len();
    let mut fate = vec![Fate::Inline; n];
    let mut anchors: Vec<Vec<Pos>> = vec![Vec::new(); n];
    for (h, e) in shape.function.expressions.iter().rev() {
        let i = h.index();
        let mut uses = 0usize;
        let mut at = Vec::new();
        for u in &shape.users[i] {
            match *u {
                User::Stmt(p) => {
                    uses += 1;
                    at.push(p);
                }
                User::Expr(u) => {
                    let k = u.index();
                    match fate[k] {
                        Fate::Unused => {}
                        Fate::Bake => {
                            uses += 1;
                            at.extend(shape.evaluated[k]);
                        }
                        Fate::Run if !shape.in_run[i] && !statics.leaders.contains(&u) => {}
                        Fate::Inline | Fate::Run => {
                            uses += anchors[k].len().max(1);
                            at.extend(anchors[k].iter().copied());
                        }
                    }
                }
            }
        }
        anchors[i] = at;
        let here = shape.evaluated[i];
        let crosses = here.is_some_and(|p| anchors[i].iter().any(|a| a.block != p.block));
        fate[i] = if shape.in_run[i] {
            Fate::Run
        } else if here.is_none() && !matches!(e, Expression::CallResult(_)) {
            Fate::Inline
        } else if uses == 0 {
            Fate::Unused
        } else if matches!(e, Expression::CallResult(_)) {
            if forced.contains(&h) || uses > 1 || crosses {
                Fate::Bake
            } else {
                Fate::Inline
            }
        } else if shape.is_pointer(h) {
            Fate::Inline
        } else if forced.contains(&h)
            || (named(shape, h) && !declares(shape, h, uses))
            || (uses > 1 && !statics.duplicable[i])
            || (crosses && statics.reads[i])
        {
            Fate::Bake
        } else {
            Fate::Inline
        };
        if fate[i] == Fate::Bake {
            anchors[i] = here.into_iter().collect();
        }
    }
    Bakes { fate, anchors }
}

/// Whether the IR names the expression (essl names what a comment points at).
fn named(shape: &Shape, h: Handle<Expression>) -> bool {
    shape.function.named_expressions.contains_key(&h)
}

/// Whether the expression's only use is the value stored into a variable (whose name then
/// says what the expression's name said).
fn declares(shape: &Shape, h: Handle<Expression>, uses: usize) -> bool {
    let [User::Stmt(p)] = shape.users[h.index()][..] else {
        return false;
    };
    uses == 1 && matches!(shape.statement(p), Some(Statement::Store { value, .. }) if *value == h)
}

/// An evaluation the text could move: a load of a variable, or a call.
#[derive(Clone, Debug)]
enum Event {
    Read(Root, Pos),
    Call {
        writes: HashSet<Root>,
        at: Pos,
        result: Handle<Expression>,
    },
}

struct Hazards<'a> {
    shape: &'a Shape<'a>,
    writes: &'a Writes,
    bakes: &'a Bakes,
    /// The calls written in each statement (their results inlined there).
    moved: HashMap<Pos, Vec<Pos>>,
    /// What each statement may store to (computed once).
    stores: std::cell::RefCell<HashMap<Pos, HashSet<Root>>>,
}

impl<'a> Hazards<'a> {
    fn new(shape: &'a Shape<'a>, writes: &'a Writes, bakes: &'a Bakes) -> Hazards<'a> {
        let mut moved: HashMap<Pos, Vec<Pos>> = HashMap::new();
        for (h, e) in shape.function.expressions.iter() {
            if let (Expression::CallResult(_), Fate::Inline, [to], Some(call)) = (
                e,
                bakes.fate[h.index()],
                &bakes.anchors[h.index()][..],
                shape.evaluated[h.index()],
            ) {
                moved.entry(*to).or_default().push(call);
            }
        }
        Hazards {
            shape,
            writes,
            bakes,
            moved,
            stores: Default::default(),
        }
    }

    /// The expressions that must be baked, given the current fates.
    fn find(&self) -> Vec<Handle<Expression>> {
        let mut out = Vec::new();
        for (h, e) in self.shape.function.expressions.iter() {
            let fate = self.bakes.fate[h.index()];
            if !matches!(fate, Fate::Inline | Fate::Run) {
                continue;
            }
            let Some(here) = self.shape.evaluated[h.index()] else {
                continue;
            };
            match *e {
                Expression::Load { pointer } => {
                    let Some(root) = self.shape.root(pointer).filter(|r| self.writable(*r)) else {
                        continue;
                    };
                    let clash = self.bakes.anchors[h.index()]
                        .iter()
                        .any(|&a| self.stored_between(here, a, root));
                    if clash {
                        out.push(self.bakeable(h));
                    }
                }
                Expression::CallResult(_) => {
                    let [a] = self.bakes.anchors[h.index()][..] else {
                        continue;
                    };
                    if !self.only_emits_between(here, a) {
                        out.push(h);
                    }
                }
                _ => {}
            }
        }
        // The order of the loads and calls within each statement.
        let mut trees: HashSet<Pos> = HashSet::new();
        for a in &self.bakes.anchors {
            trees.extend(a.iter().copied());
        }
        let mut trees: Vec<Pos> = trees.into_iter().collect();
        trees.sort();
        for a in trees {
            out.extend(self.misordered(a));
        }
        out
    }

    /// A run's load is baked by baking its constructor.
    fn bakeable(&self, h: Handle<Expression>) -> Handle<Expression> {
        if self.bakes.fate[h.index()] != Fate::Run {
            return h;
        }
        match self.shape.users[h.index()][..] {
            [User::Expr(c)] => c,
            _ => h,
        }
    }

    fn writable(&self, root: Root) -> bool {
        match root {
            Root::Global(g) => matches!(
                self.shape.module.global_variables[g].space,
                naga::AddressSpace::Private
                    | naga::AddressSpace::WorkGroup
                    | naga::AddressSpace::Storage { .. }
            ),
            _ => true,
        }
    }

    /// Whether a statement after `from` and before `to` (in `from`'s block) may store to
    /// `root`.
    fn stored_between(&self, from: Pos, to: Pos, root: Root) -> bool {
        if to.block != from.block {
            return true;
        }
        (from.index + 1..to.index).any(|s| {
            let pos = Pos {
                block: from.block,
                index: s,
            };
            !self.moved_to(pos, to) && self.statement_writes(pos).contains(&root)
        })
    }

    /// Whether only `Emit`s (and calls moved to the same place) lie between a call and `to`.
    fn only_emits_between(&self, from: Pos, to: Pos) -> bool {
        to.block == from.block
            && (from.index + 1..to.index).all(|s| {
                let pos = Pos {
                    block: from.block,
                    index: s,
                };
                matches!(self.shape.statement(pos), Some(Statement::Emit(_)))
                    || self.moved_to(pos, to)
            })
    }

    /// Whether the statement at `pos` is a call whose result is written at `to`.
    fn moved_to(&self, pos: Pos, to: Pos) -> bool {
        match self.shape.statement(pos) {
            Some(Statement::Call {
                result: Some(r), ..
            }) => {
                self.bakes.fate[r.index()] == Fate::Inline && self.bakes.anchors[r.index()] == [to]
            }
            Some(Statement::Emit(_)) => true,
            _ => false,
        }
    }

    /// What the statement at `pos` may store to, with the calls written inside it.
    fn statement_writes(&self, pos: Pos) -> HashSet<Root> {
        if let Some(w) = self.stores.borrow().get(&pos) {
            return w.clone();
        }
        let mut out = HashSet::new();
        if let Some(s) = self.shape.statement(pos) {
            self.static_writes(s, &mut out);
        }
        for call in self.moved.get(&pos).into_iter().flatten() {
            if let Some(s) = self.shape.statement(*call) {
                self.static_writes(s, &mut out);
            }
        }
        self.stores.borrow_mut().insert(pos, out.clone());
        out
    }

    fn static_writes(&self, s: &Statement, out: &mut HashSet<Root>) {
        match s {
            Statement::Store { pointer, .. } => out.extend(self.shape.root(*pointer)),
            Statement::Call {
                function,
                arguments,
                ..
            } => {
                if let Some(w) = self.writes.get(function) {
                    out.extend(w.iter().map(|g| Root::Global(*g)));
                }
                for a in arguments {
                    if self.shape.is_pointer(*a) {
                        out.extend(self.shape.root(*a));
                    }
                }
            }
            Statement::Block(b) => b.iter().for_each(|s| self.static_writes(s, out)),
            Statement::If { accept, reject, .. } => {
                accept.iter().for_each(|s| self.static_writes(s, out));
                reject.iter().for_each(|s| self.static_writes(s, out));
            }
            Statement::Switch { cases, .. } => {
                for c in cases {
                    c.body.iter().for_each(|s| self.static_writes(s, out));
                }
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                body.iter().for_each(|s| self.static_writes(s, out));
                continuing.iter().for_each(|s| self.static_writes(s, out));
            }
            _ => {}
        }
    }

    /// The calls to bake so that the loads and calls written in the statement at `at` happen
    /// in naga's order, and so that none needing uniform control flow, and no call, is in
    /// the right operand of `&&` or `||`.
    fn misordered(&self, at: Pos) -> Vec<Handle<Expression>> {
        let mut sides: Vec<Vec<Event>> = Vec::new();
        let mut out = Vec::new();
        let roots: Vec<Handle<Expression>> = match self.shape.statement(at) {
            Some(Statement::Store { pointer, value }) => vec![*pointer, *value],
            Some(s) => super::analysis::statement_operands(s),
            None => self.break_if(at).into_iter().collect(),
        };
        for r in roots {
            let mut events = Vec::new();
            self.events(r, false, &mut events, &mut out);
            sides.push(events);
        }
        if matches!(self.shape.statement(at), Some(Statement::Call { .. })) {
            // The arguments of a call are one list, evaluated in order.
            let all: Vec<Event> = sides.concat();
            sides = vec![all];
        }
        // Within one operand, the text's order must be the IR's; across the two sides of an
        // assignment, no pair may conflict at all.
        for side in &sides {
            for (i, a) in side.iter().enumerate() {
                for b in &side[i + 1..] {
                    if let Some(h) = conflict(a, b, true) {
                        out.push(h);
                    }
                }
            }
        }
        for (i, left) in sides.iter().enumerate() {
            for right in &sides[i + 1..] {
                for a in left {
                    for b in right {
                        if let Some(h) = conflict(a, b, false) {
                            out.push(h);
                        }
                    }
                }
            }
        }
        out
    }

    fn break_if(&self, at: Pos) -> Option<Handle<Expression>> {
        let parent = self.shape.blocks[at.block].parent?;
        match self.shape.statement(parent) {
            Some(Statement::Loop { break_if, .. }) => *break_if,
            _ => None,
        }
    }

    /// The loads and calls of the text of `h` at `at`, in the order WGSL evaluates them.
    fn events(
        &self,
        h: Handle<Expression>,
        conditional: bool,
        events: &mut Vec<Event>,
        bake: &mut Vec<Handle<Expression>>,
    ) {
        if matches!(self.bakes.fate[h.index()], Fate::Bake | Fate::Unused) {
            // A `let`'s name: its loads and calls happened where the `let` is.
            return;
        }
        let e = self.shape.expr(h);
        let needs_uniformity = matches!(
            e,
            Expression::ImageSample {
                level: SampleLevel::Auto | SampleLevel::Bias(_),
                ..
            } | Expression::Derivative { .. }
        );
        if conditional && (needs_uniformity || matches!(e, Expression::CallResult(_))) {
            bake.push(h);
            return;
        }
        match *e {
            Expression::Binary {
                op: BinaryOperator::LogicalAnd | BinaryOperator::LogicalOr,
                left,
                right,
            } => {
                self.events(left, conditional, events, bake);
                self.events(right, true, events, bake);
            }
            Expression::Select {
                condition,
                accept,
                reject,
            } => {
                for o in [reject, accept, condition] {
                    self.events(o, conditional, events, bake);
                }
            }
            Expression::CallResult(function) => {
                let Some(call_at) = self.shape.evaluated[h.index()] else {
                    return;
                };
                let mut writes: HashSet<Root> = self
                    .writes
                    .get(&function)
                    .map(|w| w.iter().map(|g| Root::Global(*g)).collect())
                    .unwrap_or_default();
                if let Some(Statement::Call { arguments, .. }) = self.shape.statement(call_at) {
                    for &a in arguments {
                        self.events(a, conditional, events, bake);
                        if self.shape.is_pointer(a) {
                            writes.extend(self.shape.root(a));
                        }
                    }
                }
                events.push(Event::Call {
                    writes,
                    at: call_at,
                    result: h,
                });
            }
            Expression::Load { pointer } => {
                self.events(pointer, conditional, events, bake);
                if let (Some(root), Some(p)) =
                    (self.shape.root(pointer), self.shape.evaluated[h.index()])
                {
                    if self.writable(root) {
                        events.push(Event::Read(root, p));
                    }
                }
            }
            ref other => {
                for o in operands(other) {
                    self.events(o, conditional, events, bake);
                }
            }
        }
    }
}

/// The call to bake when `a` (first in the text) and `b` conflict; `ordered` when the text's
/// order is known (else any conflicting pair is one).
fn conflict(a: &Event, b: &Event, ordered: bool) -> Option<Handle<Expression>> {
    let (a_at, b_at) = (at(a), at(b));
    let clash = match (a, b) {
        (Event::Read(r, ..), Event::Call { writes, .. })
        | (Event::Call { writes, .. }, Event::Read(r, ..)) => writes.contains(r),
        (Event::Call { writes: w1, .. }, Event::Call { writes: w2, .. }) => {
            !w1.is_empty() || !w2.is_empty()
        }
        _ => false,
    };
    if !clash || (ordered && a_at < b_at) {
        return None;
    }
    match (a, b) {
        (_, Event::Call { result, .. }) => Some(*result),
        (Event::Call { result, .. }, _) => Some(*result),
        _ => None,
    }
}

fn at(e: &Event) -> Pos {
    match e {
        Event::Read(_, p) => *p,
        Event::Call { at, .. } => *at,
    }
}

#[cfg(test)]
mod tests;
