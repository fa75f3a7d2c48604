//! Uniformity on the checked module (essl's HIR): which values may differ between the pixels
//! of one draw, and which code runs under control flow that depends on them — where
//! derivatives, and the texture lookups that take their level of detail from derivatives, are
//! undefined (GLSL ES 3.00 §8.9: "implicit derivatives … in non-uniform control flow").
//!
//! A value varies between pixels when it reads an input, `gl_FragCoord`, `gl_FrontFacing` or
//! `gl_PointCoord`, a texel at a varying coordinate, a variable that is ever given such a value
//! or written under such control flow, a parameter some call passes such a value, or the result
//! of a function that computes one. Control flow is non-uniform inside an `if`, a loop, a
//! `switch`, a `?:` or the right side of `&&`/`||` whose condition varies; after a `return`,
//! `break` or `continue` taken under non-uniform control flow (until the function ends, or the
//! loop, whose every iteration then runs for fewer pixels); and in a function called from
//! non-uniform control flow. Uniforms, constants and loop counters with uniform bounds are the
//! same for every pixel. Code after `if (…) discard;` with a varying condition is reported
//! apart ([`Finding::after_discard`], the walk in `discard.rs`): the specification leaves its
//! derivatives undefined where the discarded pixels of a quad stop, but most GPUs keep them
//! running as helpers, so alpha-tested shaders work in practice; and a variable written after
//! it is not taken to vary.

mod discard;

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use essl::hir::visit::{self, Visitor};
use essl::hir::{self, BinaryOp, BuiltinFn, BuiltinVar, Cond, Expr, ExprKind, GlobalKind};
use essl::hir::{ParamMode, Stmt, StmtKind};
use essl::source::Span;

/// Why control flow is non-uniform at a point: the span to show and what it is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Reason {
    /// The condition, jump or call.
    pub span: Span,
    /// What it is, in a few words.
    pub what: &'static str,
}

/// A derivative or an implicit-LOD texture lookup under non-uniform control flow.
#[derive(Clone, Debug)]
pub struct Finding {
    /// The call of the built-in.
    pub span: Span,
    /// The built-in.
    pub op: BuiltinFn,
    /// Why the control flow there is non-uniform.
    pub why: Reason,
    /// Whether it is non-uniform only because a `discard` some pixels of the quad take runs
    /// before it ([`Reason::what`] says so); under a varying condition otherwise.
    pub after_discard: bool,
}

/// Whether a built-in takes derivatives of its arguments: `dFdx`, `dFdy`, `fwidth`, and the
/// texture lookups whose level of detail comes from derivatives of the coordinates.
pub fn takes_derivatives(op: BuiltinFn) -> bool {
    matches!(
        op,
        BuiltinFn::DFdx
            | BuiltinFn::DFdy
            | BuiltinFn::Fwidth
            | BuiltinFn::Texture
            | BuiltinFn::TextureProj
            | BuiltinFn::TextureOffset
            | BuiltinFn::TextureProjOffset
    )
}

/// Every derivative and implicit-LOD lookup of a fragment shader under non-uniform control
/// flow.
pub fn divergent_derivatives(m: &hir::Module) -> Vec<Finding> {
    if m.stage != essl::Stage::Fragment || !may_diverge(m) {
        return Vec::new();
    }
    let mut u = Uniformity {
        m,
        vars: HashSet::default(),
        params: HashSet::default(),
        results: HashSet::default(),
        called: HashMap::default(),
        changed: false,
        record: false,
        found: Vec::new(),
        fid: 0,
        walked_after: HashSet::default(),
    };
    for _ in 0..16 {
        u.changed = false;
        u.pass();
        if !u.changed {
            break;
        }
    }
    u.record = true;
    u.pass();
    u.after_discards();
    u.found
}

/// Whether the used functions of `m` hold both a built-in that takes derivatives and a
/// statement or operator whose control flow could vary (`if`, loop, `switch`, `?:`, `&&`,
/// `||`, `discard`): without either, nothing can be found, and the passes are skipped.
fn may_diverge(m: &hir::Module) -> bool {
    let mut shape = Shape::default();
    for f in m.functions.iter().filter(|f| f.used) {
        shape.visit_stmts(&f.body);
        if shape.derivative && shape.branch {
            return true;
        }
    }
    false
}

/// What [`may_diverge`] looks for.
#[derive(Default)]
struct Shape {
    derivative: bool,
    branch: bool,
}

impl Visitor for Shape {
    fn visit_stmt(&mut self, s: &Stmt) {
        self.branch |= matches!(
            s.kind,
            StmtKind::If(..) | StmtKind::Loop { .. } | StmtKind::Switch(..) | StmtKind::Discard
        );
        visit::walk_stmt(self, s);
    }

    fn visit_expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Builtin(op, _) => self.derivative |= takes_derivatives(*op),
            ExprKind::Select(..) | ExprKind::Binary(BinaryOp::And | BinaryOp::Or, ..) => {
                self.branch = true
            }
            _ => {}
        }
        visit::walk_expr(self, e);
    }
}

/// A variable: a local or parameter of a function, or a global.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Var {
    Local(usize, usize),
    Param(usize, usize),
    Global(usize),
}

/// Ways out of a statement taken under non-uniform control flow.
#[derive(Clone, Copy, Debug, Default)]
struct Exits {
    /// A `return`: the rest of the function runs for fewer pixels.
    ret: Option<Reason>,
    /// A `break` or `continue`: the rest of the loop body, and later iterations, do.
    jump: Option<Reason>,
}

struct Uniformity<'a> {
    m: &'a hir::Module,
    vars: HashSet<Var>,
    params: HashSet<(usize, usize)>,
    results: HashSet<usize>,
    /// Functions called from non-uniform control flow, with the first such call.
    called: HashMap<usize, Reason>,
    changed: bool,
    record: bool,
    found: Vec<Finding>,
    fid: usize,
    /// The functions whose lookups a call after a `discard` has recorded (each once).
    walked_after: HashSet<usize>,
}

impl Uniformity<'_> {
    fn pass(&mut self) {
        for (fid, f) in self.m.functions.iter().enumerate() {
            if !f.used {
                continue;
            }
            self.fid = fid;
            let flow = self.called.get(&fid).copied();
            let _ = self.stmts(&f.body, flow);
        }
    }

    fn mark(&mut self, v: Var) {
        if self.vars.insert(v) {
            self.changed = true;
        }
    }

    /// Whether an expression's value may differ between pixels.
    fn varies(&self, e: &Expr) -> bool {
        let fid = self.fid;
        match &e.kind {
            ExprKind::Const(_) | ExprKind::Error => false,
            ExprKind::Local(i) => self.vars.contains(&Var::Local(fid, *i)),
            ExprKind::Param(i) => self.params.contains(&(fid, *i)),
            ExprKind::Global(g) => match self.m.globals[*g].kind {
                GlobalKind::Input => true,
                GlobalKind::Private | GlobalKind::Output => self.vars.contains(&Var::Global(*g)),
                _ => false,
            },
            ExprKind::BuiltinVar(b) => !matches!(b, BuiltinVar::DepthRange),
            ExprKind::Call(f, args) => {
                self.results.contains(f) || args.iter().any(|a| self.varies(a))
            }
            ExprKind::BlockMember(_, i, _) => i.as_ref().is_some_and(|i| self.varies(i)),
            ExprKind::Unary(_, a) | ExprKind::Member(a, _) | ExprKind::Swizzle(a, _) => {
                self.varies(a)
            }
            ExprKind::IncDec(_, _, a) => self.varies(a),
            ExprKind::Binary(_, a, b)
            | ExprKind::Assign(_, a, b)
            | ExprKind::Comma(a, b)
            | ExprKind::Index(a, b) => self.varies(a) || self.varies(b),
            ExprKind::Select(c, a, b) => self.varies(c) || self.varies(a) || self.varies(b),
            ExprKind::Builtin(_, args) | ExprKind::Construct(args) => {
                args.iter().any(|a| self.varies(a))
            }
            _ => true,
        }
    }

    /// The variable a place expression writes.
    fn root(&self, e: &Expr) -> Option<Var> {
        match &e.write_root().kind {
            ExprKind::Local(i) => Some(Var::Local(self.fid, *i)),
            ExprKind::Param(i) => Some(Var::Param(self.fid, *i)),
            ExprKind::Global(g) => Some(Var::Global(*g)),
            _ => None,
        }
    }

    /// A write of a value that varies (`value`), or under non-uniform control flow.
    fn assign(&mut self, place: &Expr, value: bool, flow: Option<Reason>) {
        if !(value || flow.is_some()) {
            return;
        }
        match self.root(place) {
            Some(Var::Param(f, i)) if self.params.insert((f, i)) => self.changed = true,
            Some(Var::Param(..)) | None => {}
            Some(v) => self.mark(v),
        }
    }

    fn expr(&mut self, e: &Expr, flow: Option<Reason>) {
        match &e.kind {
            ExprKind::Assign(_, lhs, rhs) => {
                self.expr(rhs, flow);
                self.expr(lhs, flow);
                let v = self.varies(rhs) || self.varies(lhs);
                self.assign(lhs, v, flow);
            }
            ExprKind::IncDec(_, _, x) => {
                self.expr(x, flow);
                let v = self.varies(x);
                self.assign(x, v, flow);
            }
            ExprKind::Select(c, a, b) => {
                self.expr(c, flow);
                let inner = flow.or_else(|| {
                    self.varies(c).then_some(Reason {
                        span: c.span,
                        what: "this `?:` condition varies between pixels",
                    })
                });
                self.expr(a, inner);
                self.expr(b, inner);
            }
            ExprKind::Binary(op @ (BinaryOp::And | BinaryOp::Or), a, b) => {
                self.expr(a, flow);
                let inner = flow.or_else(|| {
                    self.varies(a).then_some(Reason {
                        span: a.span,
                        what: if *op == BinaryOp::And {
                            "the right side of `&&` runs only where this holds, which varies between pixels"
                        } else {
                            "the right side of `||` runs only where this fails, which varies between pixels"
                        },
                    })
                });
                self.expr(b, inner);
            }
            ExprKind::Call(f, args) => self.call(*f, args, e.span, flow),
            ExprKind::Builtin(op, args) => {
                for a in args {
                    self.expr(a, flow);
                }
                if *op == BuiltinFn::Modf && args.len() == 2 {
                    let v = self.varies(&args[0]);
                    self.assign(&args[1], v, flow);
                }
                if let (true, true, Some(why)) = (self.record, takes_derivatives(*op), flow) {
                    self.found.push(Finding {
                        span: e.span,
                        op: *op,
                        why,
                        after_discard: false,
                    });
                }
            }
            ExprKind::Unary(_, a) | ExprKind::Member(a, _) | ExprKind::Swizzle(a, _) => {
                self.expr(a, flow)
            }
            ExprKind::Binary(_, a, b) | ExprKind::Comma(a, b) | ExprKind::Index(a, b) => {
                self.expr(a, flow);
                self.expr(b, flow);
            }
            ExprKind::Construct(args) => {
                for a in args {
                    self.expr(a, flow);
                }
            }
            ExprKind::BlockMember(_, Some(i), _) => self.expr(i, flow),
            _ => {}
        }
    }

    fn call(&mut self, f: usize, args: &[Expr], span: Span, flow: Option<Reason>) {
        for a in args {
            self.expr(a, flow);
        }
        let params = &self.m.functions[f].params;
        let mut any = false;
        for (i, (a, p)) in args.iter().zip(params).enumerate() {
            let v = self.varies(a);
            any |= v;
            if v && p.mode != ParamMode::Out && self.params.insert((f, i)) {
                self.changed = true;
            }
        }
        let result = self.results.contains(&f);
        for (a, p) in args.iter().zip(params) {
            if p.mode != ParamMode::In {
                self.assign(a, any || result, flow);
            }
        }
        if flow.is_some() && !self.called.contains_key(&f) {
            let why = Reason {
                span,
                what: "called here under control flow that varies between pixels",
            };
            self.called.insert(f, why);
            self.changed = true;
        }
    }

    /// Walks statements under `flow`: the ways out taken under non-uniform control flow.
    fn stmts(&mut self, ss: &[Stmt], flow: Option<Reason>) -> Exits {
        let mut cur = flow;
        let mut out = Exits::default();
        for s in ss {
            let x = self.stmt(s, cur);
            if let Some(r) = x.ret {
                out.ret = out.ret.or(Some(r));
                cur = cur.or(Some(r));
            }
            if let Some(j) = x.jump {
                out.jump = out.jump.or(Some(j));
                cur = cur.or(Some(j));
            }
        }
        out
    }

    fn stmt(&mut self, s: &Stmt, flow: Option<Reason>) -> Exits {
        let jump = |what: &'static str| Exits {
            ret: None,
            jump: flow.map(|_| Reason { span: s.span, what }),
        };
        match &s.kind {
            StmtKind::Expr(e) => self.expr(e, flow),
            StmtKind::Local(id, Some(e)) => {
                self.expr(e, flow);
                if self.varies(e) || flow.is_some() {
                    self.mark(Var::Local(self.fid, *id));
                }
            }
            StmtKind::Block(b) => return self.stmts(b, flow),
            StmtKind::If(c, a, b) => {
                self.expr(c, flow);
                let inner = flow.or_else(|| {
                    self.varies(c).then_some(Reason {
                        span: c.span,
                        what: "this condition varies between pixels",
                    })
                });
                let xa = self.stmts(a, inner);
                let xb = self.stmts(b, inner);
                return Exits {
                    ret: xa.ret.or(xb.ret),
                    jump: xa.jump.or(xb.jump),
                };
            }
            StmtKind::Loop {
                init,
                cond,
                step,
                body,
                ..
            } => return self.loop_stmt(init, cond.as_deref(), step.as_ref(), body, flow),
            StmtKind::Switch(sel, cases) => {
                self.expr(sel, flow);
                let inner = flow.or_else(|| {
                    self.varies(sel).then_some(Reason {
                        span: sel.span,
                        what: "this `switch` selector varies between pixels",
                    })
                });
                let mut out = Exits::default();
                for c in cases {
                    let x = self.stmts(&c.body, inner);
                    out.ret = out.ret.or(x.ret);
                    // A `break` leaves the `switch`; a `continue` is the loop's (kept as a jump).
                    if c.body.iter().any(|s| matches!(s.kind, StmtKind::Continue)) {
                        out.jump = out.jump.or(x.jump);
                    }
                }
                return out;
            }
            StmtKind::Return(e) => {
                if let Some(e) = e {
                    self.expr(e, flow);
                    if (self.varies(e) || flow.is_some()) && self.results.insert(self.fid) {
                        self.changed = true;
                    }
                }
                return Exits {
                    ret: flow.map(|_| Reason {
                        span: s.span,
                        what: "this `return` is taken by some pixels only",
                    }),
                    jump: None,
                };
            }
            StmtKind::Break => return jump("this `break` is taken by some pixels only"),
            StmtKind::Continue => return jump("this `continue` is taken by some pixels only"),
            _ => {}
        }
        Exits::default()
    }

    fn loop_stmt(
        &mut self,
        init: &[Stmt],
        cond: Option<&Cond>,
        step: Option<&Expr>,
        body: &[Stmt],
        flow: Option<Reason>,
    ) -> Exits {
        let mut out = self.stmts(init, flow);
        let cond_expr = match cond {
            Some(Cond::Expr(e)) | Some(Cond::Decl(_, e)) => Some(e),
            None => None,
        };
        // Two rounds: what the first learns (a counter written under a varying `break`)
        // decides the flow of the second.
        let mut inner = flow;
        for _ in 0..2 {
            if let Some(e) = cond_expr {
                self.expr(e, inner);
                if let Some(Cond::Decl(id, _)) = cond {
                    if self.varies(e) || inner.is_some() {
                        self.mark(Var::Local(self.fid, *id));
                    }
                }
                if inner.is_none() && self.varies(e) {
                    inner = Some(Reason {
                        span: e.span,
                        what: "this loop condition varies between pixels",
                    });
                }
            }
            let x = self.stmts(body, inner);
            if let Some(e) = step {
                self.expr(e, inner.or(x.jump));
            }
            out.ret = out.ret.or(x.ret);
            match (inner, x.jump) {
                (None, Some(j)) => inner = Some(j),
                _ => break,
            }
        }
        out.jump = None;
        out
    }
}
