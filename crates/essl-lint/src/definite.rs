//! Definite assignment on the checked module (essl's HIR, whose statements keep the shader's
//! structure): which reads of a variable may come before any write to it, on some path.
//!
//! Tracked are the locals declared without an initializer, `out` parameters (undefined until
//! the function writes them), and — in `main` — plain globals without an initializer and the
//! shader's outputs, declared or built-in (`gl_FragColor`, `gl_FragData`, `gl_Position`,
//! `gl_PointSize`, `gl_FragDepth`). A vector's components are tracked one by one (`v.xy = …; v.z = …;`
//! writes all of a `vec3`; `v[i] = …` in a loop whose counter `i` takes 0..=2 writes `v.xyz`,
//! [`counters`], and through any other dynamic index every component), and so are a struct's
//! members (up to 8; a read of the whole struct needs the members some path has written
//! before it written on every path); an array, matrix or larger struct counts
//! as written once any part of it is (dynamic indices make anything finer guesswork). The
//! state at a point is the set of
//! variables written on *every* path to it: branches intersect, a branch that returns,
//! discards, breaks or continues adds nothing, a loop body may run zero times unless its bounds
//! are constant and let it run once (`for (int i = 0; i < 4; i++)`), the right side of `&&` and
//! `||` and the branches of `?:` may not run — but an `if` runs its first branch only where
//! its condition is true, which for `a && f(x, out m)` means `f` ran and wrote `m`, and the
//! same holds through a `bool` local set once at the top of the function (`bool rotate = !b &&
//! f(x, out m); … if (rotate) { … m … }`). A call reads what the callee reads of the tracked
//! globals before writing them, and then counts as writing what the callee may write.

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use essl::hir::{
    self, BinaryOp, BuiltinFn, BuiltinVar, Cond, Expr, ExprKind, GlobalKind, ParamMode, Stmt,
    StmtKind,
};
use essl::source::Span;
use essl::types::Type;

mod conditions;
mod counters;
mod places;
mod state;

use places::full_mask;
use state::{Layout, State};

/// A variable the analysis tracks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Var {
    /// A local of the function.
    Local(usize),
    /// An `out` parameter of the function.
    Param(usize),
    /// A global (in `main` and through the functions it calls).
    Global(usize),
    /// A built-in output (in `main` and through the functions it calls).
    Builtin(BuiltinVar),
    /// The function's result, where control can reach the end of a function that returns a
    /// value without a `return`: its callers read an undefined value.
    Result,
}

impl Var {
    /// Whether it is a global or built-in output: tracked in `main` and through its calls.
    fn global(self) -> bool {
        matches!(self, Var::Global(_) | Var::Builtin(_))
    }
}

/// The built-in outputs, with their full masks ([`full_mask`]): `gl_FragData` is an array.
const BUILTIN_OUTPUTS: [(BuiltinVar, u8); 5] = [
    (BuiltinVar::FragColor, 0b1111),
    (BuiltinVar::FragData, 1),
    (BuiltinVar::FragDepth, 1),
    (BuiltinVar::Position, 0b1111),
    (BuiltinVar::PointSize, 1),
];

/// A read that may come before any write.
#[derive(Clone, Debug)]
pub struct Read {
    /// The function the read is in.
    pub function: usize,
    /// The variable.
    pub var: Var,
    /// The read.
    pub span: Span,
    /// For a global read in a called function: the call in `main` it is reached through.
    pub through: Option<Span>,
    /// For a struct read whole: the members some path leaves unwritten (empty where no member
    /// is written).
    pub members: Vec<String>,
}

/// Every read of a tracked variable that may come before any write, one per variable and
/// function (the first met).
pub fn uninitialised_reads(m: &hir::Module) -> Vec<Read> {
    let mut summaries: HashMap<usize, Summary> = HashMap::default();
    let mut out = Vec::new();
    for (fid, f) in m.functions.iter().enumerate() {
        if !f.used {
            continue;
        }
        let main = m.entry == Some(fid);
        let mut w = Walk::new(m, fid, main, &mut summaries);
        let mut st = w.start();
        w.run(&f.body, &mut st);
        out.extend(w.reads);
    }
    out
}

/// What a function does to the tracked globals: the ones it may read before writing (with
/// where), and the ones it may write.
#[derive(Clone, Debug, Default)]
struct Summary {
    reads: Vec<(Var, Span, usize)>,
    writes: HashSet<Var>,
}

/// Where `break` and `continue` go.
struct Target {
    is_loop: bool,
    breaks: Vec<State>,
    continues: Vec<State>,
}

struct Walk<'a> {
    m: &'a hir::Module,
    fid: usize,
    main: bool,
    /// Where each variable has its slot in a [`State`].
    layout: Layout,
    /// By slot, the full mask of each tracked variable; 0 for one not tracked.
    full: Vec<u8>,
    targets: Vec<Target>,
    reported: HashSet<Var>,
    reads: Vec<Read>,
    summaries: &'a mut HashMap<usize, Summary>,
    /// When computing a summary: the globals read before written, and those written.
    summary: Option<Summary>,
    /// Writes made under a condition on uniforms (`if (u_isText) { c = …; }`), by the
    /// condition's uniforms: a later `if` on the same uniforms (`u_isText && u_isHalo`) runs
    /// only where they were made.
    guarded: Vec<(Vec<Key>, usize, u8)>,
    /// The uniforms the enclosing `if`s on uniforms require.
    context: Vec<Key>,
    /// How many enclosing statements are not `if`s on uniforms (loops, switches, other `if`s):
    /// a write under them is not recorded in `guarded`, since a later `if` on the same
    /// uniforms does not run only where they ran.
    loose: usize,
    /// For a local assigned at the top level of the function (outside every branch and
    /// loop) and not written since: what is written wherever its value is true.
    truth: HashMap<usize, State>,
    /// How many statements (branches, loops, switches, blocks) enclose the current one.
    nest: usize,
    /// The counters of the enclosing loops and the values they take there
    /// ([`counters::counter_range`]).
    counters: Vec<(usize, i64, i64)>,
    /// For a struct variable tracked member by member, by slot: the members written so far on
    /// any path. A read needs those written on every path; a member no path has written yet
    /// counts as written once another is, as a struct did before members were tracked (a
    /// struct an engine fills per configuration, passed whole to a function that reads the
    /// members that configuration set).
    ever: Vec<u8>,
}

/// A uniform a condition tests, with the value it requires: a loose uniform, or a member of a
/// uniform block.
type Key = (usize, usize, bool);

/// Whether a global is tracked: a plain global without an initializer, or an output.
fn tracked_global(g: &hir::Global) -> bool {
    match g.kind {
        GlobalKind::Private => g.init.is_none(),
        GlobalKind::Output => true,
        _ => false,
    }
}

impl<'a> Walk<'a> {
    fn new(
        m: &'a hir::Module,
        fid: usize,
        main: bool,
        summaries: &'a mut HashMap<usize, Summary>,
    ) -> Walk<'a> {
        let f = &m.functions[fid];
        let layout = Layout::new(f.locals.len(), f.params.len(), m.globals.len());
        let mut w = Walk {
            m,
            fid,
            main,
            layout,
            full: vec![0; layout.len()],
            targets: Vec::new(),
            reported: HashSet::default(),
            reads: Vec::new(),
            summaries,
            summary: None,
            guarded: Vec::new(),
            context: Vec::new(),
            loose: 0,
            truth: HashMap::default(),
            nest: 0,
            counters: Vec::new(),
            ever: vec![0; layout.len()],
        };
        for (i, p) in f.params.iter().enumerate() {
            if p.mode == ParamMode::Out {
                w.track(Var::Param(i), full_mask(m, &p.ty));
            }
        }
        for (i, l) in f.locals.iter().enumerate() {
            if l.constant.is_none() {
                w.track(Var::Local(i), full_mask(m, &l.ty));
            }
        }
        if main {
            w.track_globals();
        }
        w
    }

    /// Tracks `v`, whose full mask is `mask`.
    fn track(&mut self, v: Var, mask: u8) {
        if let Some(i) = self.layout.slot(v) {
            self.full[i] = mask;
        }
    }

    /// Tracks the globals [`tracked_global`] says, and the built-in outputs the module uses.
    fn track_globals(&mut self) {
        let m = self.m;
        for (i, g) in m.globals.iter().enumerate() {
            if tracked_global(g) {
                self.track(Var::Global(i), full_mask(m, &g.ty));
            }
        }
        for (b, mask) in BUILTIN_OUTPUTS {
            if m.used_builtins.contains(&b) {
                self.track(Var::Builtin(b), mask);
            }
        }
    }

    /// The full mask of `v` where the walk tracks it.
    fn mask(&self, v: Var) -> Option<u8> {
        let i = self.layout.slot(v)?;
        Some(self.full[i]).filter(|&b| b != 0)
    }

    /// The state at the function's start: parameters other than `out` ones are written; locals
    /// are written at their declaration.
    fn start(&self) -> State {
        State::new(self.layout.len())
    }

    fn run(&mut self, body: &[Stmt], st: &mut State) {
        if let Some(end) = self.stmts(body, st.clone()) {
            let f = &self.m.functions[self.fid];
            self.outs_written(&end, f.span);
            // The end reached without `return`: the last statement is where control leaves. A
            // function without statements is one only declared here (Cesium's
            // `czm_computePosition();`, defined by the program it is linked into).
            let returns_value = self.summary.is_none() && f.ret != Type::Void;
            if let Some(last) = body.last().filter(|_| returns_value) {
                self.reads.push(Read {
                    function: self.fid,
                    var: Var::Result,
                    span: last.span,
                    through: None,
                    members: Vec::new(),
                });
            }
        }
    }

    /// At a `return` (or the end of the function): an `out` parameter not written on every
    /// path leaves the caller's variable undefined, which is a read before any write there.
    fn outs_written(&mut self, st: &State, at: Span) {
        let f = &self.m.functions[self.fid];
        // A function that returns a value may say by it that its `out` parameters are not set
        // (`bool hit(…, out float t)`): only a `void` one leaves the caller no way to know.
        if self.summary.is_some() || f.ret != Type::Void {
            return;
        }
        for (i, p) in f.params.iter().enumerate() {
            let v = Var::Param(i);
            if p.mode == ParamMode::Out
                && !self.written(st, v, self.mask(v).unwrap_or(1))
                && self.reported.insert(v)
            {
                self.reads.push(Read {
                    function: self.fid,
                    var: v,
                    span: at,
                    through: None,
                    members: Vec::new(),
                });
            }
        }
    }

    fn read(&mut self, st: &State, v: Var, bits: u8, span: Span) {
        if self.written(st, v, bits) {
            return;
        }
        if let (Some(s), true) = (&mut self.summary, v.global()) {
            if !s.reads.iter().any(|(x, _, _)| *x == v) {
                s.reads.push((v, span, self.fid));
            }
            return;
        }
        if self.reported.insert(v) {
            let members = self.unwritten_members(st, v, bits);
            self.reads.push(Read {
                function: self.fid,
                var: v,
                span,
                through: None,
                members,
            });
        }
    }

    fn write(&mut self, st: &mut State, v: Var, bits: u8) {
        if let (Some(s), true) = (&mut self.summary, v.global()) {
            s.writes.insert(v);
        }
        if let Var::Local(l) = v {
            self.truth.remove(&l);
        }
        if let (Some(i), Some(_)) = (self.layout.slot(v), self.mask(v)) {
            st.add(i, bits);
            self.ever[i] |= bits;
        }
    }

    fn expr(&mut self, e: &Expr, st: &mut State) {
        match &e.kind {
            ExprKind::Local(_)
            | ExprKind::Param(_)
            | ExprKind::Global(_)
            | ExprKind::BuiltinVar(_)
            | ExprKind::Swizzle(..)
            | ExprKind::Index(..)
            | ExprKind::Member(..) => {
                if let Some((v, bits)) = self.place(e, st) {
                    self.read(st, v, bits, e.span);
                }
            }
            ExprKind::Assign(op, lhs, rhs) => {
                self.expr(rhs, st);
                if op.is_some() {
                    self.expr(lhs, st);
                }
                if let Some((v, bits)) = self.place(lhs, st) {
                    self.write(st, v, bits);
                }
            }
            ExprKind::IncDec(_, _, x) => {
                self.expr(x, st);
                if let Some((v, bits)) = self.place(x, st) {
                    self.write(st, v, bits);
                }
            }
            ExprKind::Select(c, a, b) => {
                self.expr(c, st);
                let mut sa = st.clone();
                self.expr(a, &mut sa);
                let mut sb = st.clone();
                self.expr(b, &mut sb);
                *st = sa.meet(&sb);
            }
            ExprKind::Binary(op, a, b) => {
                self.expr(a, st);
                if matches!(op, BinaryOp::And | BinaryOp::Or) {
                    let mut sb = st.clone();
                    self.expr(b, &mut sb);
                } else {
                    self.expr(b, st);
                }
            }
            ExprKind::Call(callee, args) => self.call(*callee, args, e.span, st),
            ExprKind::Builtin(BuiltinFn::Modf, args) if args.len() == 2 => {
                self.expr(&args[0], st);
                if let Some((v, bits)) = self.place(&args[1], st) {
                    self.write(st, v, bits);
                }
            }
            ExprKind::Unary(_, a) => self.expr(a, st),
            ExprKind::Comma(a, b) => {
                self.expr(a, st);
                self.expr(b, st);
            }
            ExprKind::Builtin(_, args) | ExprKind::Construct(args) => {
                for a in args {
                    self.expr(a, st);
                }
            }
            ExprKind::BlockMember(_, Some(i), _) => self.expr(i, st),
            _ => {}
        }
    }

    fn call(&mut self, callee: usize, args: &[Expr], span: Span, st: &mut State) {
        let params = &self.m.functions[callee].params;
        let mut outs = Vec::new();
        for (i, (a, p)) in args.iter().zip(params).enumerate() {
            match p.mode {
                ParamMode::In => self.expr(a, st),
                // `inout` copies the value in: a read only if the callee reads it before
                // writing it.
                ParamMode::InOut if self.reads_param(callee, i) => {
                    self.expr(a, st);
                    outs.push(a);
                }
                ParamMode::InOut | ParamMode::Out => {
                    let _ = self.place(a, st);
                    outs.push(a);
                }
            }
        }
        if self.main || self.summary.is_some() {
            let s = self.summary_of(callee);
            for (g, at, in_fn) in &s.reads {
                let v = *g;
                if self.written(st, v, self.mask(v).unwrap_or(1)) {
                    continue;
                }
                match &mut self.summary {
                    Some(mine) => {
                        if !mine.reads.iter().any(|(x, _, _)| x == g) {
                            mine.reads.push((*g, *at, *in_fn));
                        }
                    }
                    None => {
                        if self.reported.insert(v) {
                            self.reads.push(Read {
                                function: *in_fn,
                                var: v,
                                span: *at,
                                through: Some(span),
                                members: Vec::new(),
                            });
                        }
                    }
                }
            }
            for g in &s.writes {
                let v = *g;
                if let Some(all) = self.mask(v) {
                    self.write(st, v, all);
                }
            }
        }
        for a in outs {
            if let Some((v, bits)) = self.place(a, st) {
                self.write(st, v, bits);
            }
        }
    }

    /// Whether function `f` may read its parameter `i` before writing it.
    fn reads_param(&mut self, f: usize, i: usize) -> bool {
        let m = self.m;
        let mut w = Walk::new(m, f, false, self.summaries);
        let v = Var::Param(i);
        w.track(v, full_mask(m, &m.functions[f].params[i].ty));
        let st = w.start();
        let _ = w.stmts(&m.functions[f].body, st);
        w.reads.iter().any(|r| r.var == v)
    }

    /// What function `f` reads of the tracked globals before writing them, and may write.
    fn summary_of(&mut self, f: usize) -> Summary {
        if let Some(s) = self.summaries.get(&f) {
            return s.clone();
        }
        let m = self.m;
        let mut w = Walk::new(m, f, false, self.summaries);
        w.track_globals();
        w.summary = Some(Summary::default());
        let mut st = w.start();
        w.run(&m.functions[f].body, &mut st);
        let s = w.summary.take().unwrap_or_default();
        self.summaries.insert(f, s.clone());
        s
    }

    /// Walks statements from `st`: the state at their end, `None` when it is not reached.
    fn stmts(&mut self, ss: &[Stmt], mut st: State) -> Option<State> {
        for s in ss {
            st = self.stmt(s, st)?;
        }
        Some(st)
    }

    fn stmt(&mut self, s: &Stmt, st: State) -> Option<State> {
        let nested = matches!(
            s.kind,
            StmtKind::If(..) | StmtKind::Loop { .. } | StmtKind::Switch(..) | StmtKind::Block(_)
        );
        self.nest += usize::from(nested);
        let out = self.stmt_in(s, st);
        self.nest -= usize::from(nested);
        out
    }

    fn stmt_in(&mut self, s: &Stmt, mut st: State) -> Option<State> {
        match &s.kind {
            StmtKind::Expr(e) => {
                let set = match &e.kind {
                    ExprKind::Assign(None, lhs, rhs) if self.nest == 0 => match lhs.kind {
                        ExprKind::Local(l) if self.says_more(rhs) => {
                            Some((l, self.when_true(rhs, &st)))
                        }
                        _ => None,
                    },
                    _ => None,
                };
                self.expr(e, &mut st);
                if let Some((l, Some(t))) = set {
                    self.truth.insert(l, t);
                }
            }
            StmtKind::Local(id, init) => {
                let v = Var::Local(*id);
                match init {
                    Some(e) => {
                        let t = if self.nest == 0 && self.says_more(e) {
                            self.when_true(e, &st)
                        } else {
                            None
                        };
                        self.expr(e, &mut st);
                        if let (Some(i), Some(all)) = (self.layout.slot(v), self.mask(v)) {
                            st.set(i, all);
                        }
                        self.truth.remove(id);
                        if let Some(t) = t {
                            self.truth.insert(*id, t);
                        }
                    }
                    None => {
                        if let Some(i) = self.layout.slot(v) {
                            st.set(i, 0);
                        }
                    }
                }
            }
            StmtKind::Block(b) => return self.stmts(b, st),
            StmtKind::If(c, a, b) => {
                let when = if self.says_more(c) {
                    self.when_true(c, &st)
                } else {
                    None
                };
                self.expr(c, &mut st);
                let (yes, no) = (self.keys(c, true), self.keys(c, false));
                let sa = self.branch(a, when.as_ref().unwrap_or(&st), &yes);
                let sb = self.branch(b, &st, &no);
                let out = meet_opt(sa.clone(), sb.clone());
                for (branch, keys) in [(sa, yes), (sb, no)] {
                    if let (Some(branch), Some(out), false, 0) =
                        (&branch, &out, keys.is_empty(), self.loose)
                    {
                        let mut need = self.context.clone();
                        need.extend(keys);
                        for (i, bits) in branch.iter() {
                            let extra = bits & !out.get(i);
                            if extra != 0 {
                                self.guarded.push((need.clone(), i, extra));
                            }
                        }
                    }
                }
                return out;
            }
            StmtKind::Loop {
                init,
                cond,
                step,
                body,
                do_while,
            } => {
                self.loose += 1;
                let out = self.loop_stmt(init, cond.as_deref(), step.as_ref(), body, *do_while, st);
                self.loose -= 1;
                return out;
            }
            StmtKind::Switch(sel, cases) => {
                self.expr(sel, &mut st);
                self.targets.push(Target {
                    is_loop: false,
                    breaks: Vec::new(),
                    continues: Vec::new(),
                });
                let mut fall: Option<State> = None;
                let mut end = None;
                self.loose += 1;
                for c in cases {
                    let start = meet_opt(Some(st.clone()), fall.take());
                    let e = start.and_then(|s0| self.stmts(&c.body, s0));
                    if c.fall_through {
                        fall = e;
                    } else {
                        end = meet_opt(end, e);
                    }
                }
                self.loose -= 1;
                end = meet_opt(end, fall);
                let t = self.targets.pop().expect("pushed");
                for b in t.breaks {
                    end = meet_opt(end, Some(b));
                }
                if !cases.iter().any(|c| c.value.is_none()) {
                    end = meet_opt(end, Some(st));
                }
                return end;
            }
            StmtKind::Break => {
                if let Some(t) = self.targets.last_mut() {
                    t.breaks.push(st);
                }
                return None;
            }
            StmtKind::Continue => {
                if let Some(t) = self.targets.iter_mut().rev().find(|t| t.is_loop) {
                    t.continues.push(st);
                }
                return None;
            }
            StmtKind::Return(e) => {
                if let Some(e) = e {
                    self.expr(e, &mut st);
                }
                self.outs_written(&st, s.span);
                return None;
            }
            StmtKind::Discard => return None,
            _ => {}
        }
        Some(st)
    }

    fn loop_stmt(
        &mut self,
        init: &[Stmt],
        cond: Option<&Cond>,
        step: Option<&Expr>,
        body: &[Stmt],
        do_while: bool,
        st: State,
    ) -> Option<State> {
        let mut st = self.stmts(init, st)?;
        let once = do_while || cond.is_none() || counters::runs_once(init, cond);
        let mut head = st.clone();
        if !do_while {
            self.cond(cond, &mut head);
            st = head.clone();
        }
        self.targets.push(Target {
            is_loop: true,
            breaks: Vec::new(),
            continues: Vec::new(),
        });
        let counter = counters::counter_range(self.m, init, cond, step, body);
        self.counters.extend(counter);
        let end = self.stmts(body, head);
        if counter.is_some() {
            self.counters.pop();
        }
        let t = self.targets.pop().expect("pushed");
        let mut pre_step = end;
        for c in t.continues {
            pre_step = meet_opt(pre_step, Some(c));
        }
        let after = pre_step.map(|mut s| {
            if let Some(e) = step {
                self.expr(e, &mut s);
            }
            if do_while {
                self.cond(cond, &mut s);
            }
            s
        });
        let mut exit = if cond.is_some() { after } else { None };
        for b in t.breaks {
            exit = meet_opt(exit, Some(b));
        }
        if !once {
            exit = meet_opt(exit, Some(st));
        }
        exit
    }

    fn cond(&mut self, cond: Option<&Cond>, st: &mut State) {
        match cond {
            Some(Cond::Expr(e)) => self.expr(e, st),
            Some(Cond::Decl(id, e)) => {
                self.expr(e, st);
                let v = Var::Local(*id);
                if let (Some(i), Some(all)) = (self.layout.slot(v), self.mask(v)) {
                    st.set(i, all);
                }
            }
            None => {}
        }
    }
}

fn meet_opt(a: Option<State>, b: Option<State>) -> Option<State> {
    match (a, b) {
        (Some(a), Some(b)) => Some(a.meet(&b)),
        (a, None) => a,
        (None, b) => b,
    }
}
