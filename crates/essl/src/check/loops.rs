//! Loops that cannot end, which Chromium refuses ("Infinite loop detected in the shader"):
//! ANGLE's `PruneInfiniteLoops` finds a `while` or `for` loop (not a `do … while`) whose
//! condition is missing or always `true` and whose body neither `break`s out of it nor
//! `return`s, and WebGL rejects the shader. "Always `true`" is a constant, or a variable that
//! nothing writes after its constant initializer (`bool run = true; while (run) {}`, a global
//! too), which ANGLE folds by then. A `break` of a loop or `switch` inside does not leave the
//! outer loop; `continue` and `discard` do not either. Rejecting them also keeps such shaders
//! away from essl-gl, where the draw would never finish.
//!
//! Written by hand: the rule is ANGLE's, over essl's checked statements; the cases it settles
//! are in `tests/oracle/PROBES.md` (`c-infinite-loop-*`).

use std::collections::HashSet;

use super::Checker;
use crate::builtins::BuiltinFn;
use crate::diagnostic_code::Code;
use crate::hir::visit::{self, Visitor};
use crate::hir::{
    Cond, ConstValue, Expr, ExprKind, GlobalId, GlobalKind, Init, LocalId, ParamMode, Scalar, Stmt,
    StmtKind,
};

/// The variables something writes (assigns, increments, passes to an `out` or `inout`
/// parameter, or to `modf`), and each local's constant initializer.
#[derive(Default)]
struct Writes<'a> {
    /// The parameter modes of each user function.
    modes: &'a [Vec<ParamMode>],
    locals: HashSet<LocalId>,
    globals: HashSet<GlobalId>,
    /// Locals declared with a constant `true`.
    true_locals: HashSet<LocalId>,
}

impl Writes<'_> {
    fn write(&mut self, target: &Expr) {
        match target.write_root().kind {
            ExprKind::Local(l) => {
                self.locals.insert(l);
            }
            ExprKind::Global(g) => {
                self.globals.insert(g);
            }
            _ => {}
        }
    }
}

impl Visitor for Writes<'_> {
    fn visit_stmt(&mut self, s: &Stmt) {
        if let StmtKind::Local(l, Some(init)) = &s.kind {
            if is_true(init) {
                self.true_locals.insert(*l);
            }
        }
        visit::walk_stmt(self, s);
    }

    fn visit_expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Assign(_, target, _) | ExprKind::IncDec(_, _, target) => self.write(target),
            ExprKind::Call(f, args) => {
                let modes = self.modes.get(*f).map_or(&[][..], Vec::as_slice);
                for (a, m) in args.iter().zip(modes) {
                    if *m != ParamMode::In {
                        self.write(a);
                    }
                }
            }
            ExprKind::Builtin(BuiltinFn::Modf, args) if args.len() == 2 => self.write(&args[1]),
            _ => {}
        }
        visit::walk_expr(self, e);
    }
}

/// Whether `e` is the constant `true`.
fn is_true(e: &Expr) -> bool {
    e.as_const() == Some(&ConstValue::Basic(vec![Scalar::B(true)]))
}

/// Whether `stmts` leave the loop they are the body of: a `break` of that loop (not of a loop
/// or `switch` inside), or a `return` anywhere.
fn escapes(stmts: &[Stmt], nested: bool) -> bool {
    stmts.iter().any(|s| match &s.kind {
        StmtKind::Break => !nested,
        StmtKind::Return(_) => true,
        StmtKind::Block(b) => escapes(b, nested),
        StmtKind::If(_, a, b) => escapes(a, nested) || escapes(b, nested),
        StmtKind::Loop { body, .. } => escapes(body, true),
        StmtKind::Switch(_, cases) => cases.iter().any(|c| escapes(&c.body, true)),
        _ => false,
    })
}

/// A loop that cannot end unless its condition is a variable that something writes.
struct Candidate {
    span: crate::source::Span,
    /// The condition's variable, when it is one (a local of the function, or a global).
    var: Option<Cond0>,
    /// The function it is in.
    func: usize,
}

/// A loop condition that is a variable as such.
#[derive(Clone, Copy)]
enum Cond0 {
    Local(LocalId),
    Global(GlobalId),
}

/// The loops of one function whose condition is missing, the constant `true` or a variable as
/// such, and that nothing leaves. Statements only: an expression holds no loop.
struct Endless {
    func: usize,
    found: Vec<Candidate>,
}

impl Visitor for Endless {
    fn visit_stmt(&mut self, s: &Stmt) {
        if let StmtKind::Loop {
            cond,
            body,
            do_while: false,
            ..
        } = &s.kind
        {
            let var = match cond.as_deref() {
                None => Some(None),
                Some(Cond::Expr(e)) => match e.kind {
                    ExprKind::Local(l) => Some(Some(Cond0::Local(l))),
                    ExprKind::Global(g) => Some(Some(Cond0::Global(g))),
                    _ => is_true(e).then_some(None),
                },
                Some(Cond::Decl(..)) => None,
            };
            if let Some(var) = var {
                if !escapes(body, false) {
                    self.found.push(Candidate {
                        span: s.span,
                        var,
                        func: self.func,
                    });
                }
            }
        }
        visit::walk_stmt(self, s);
    }

    fn visit_expr(&mut self, _: &Expr) {}
}

impl Checker<'_> {
    /// Reports each `while` or `for` loop that can never end, as Chromium refuses it.
    pub(super) fn check_infinite_loops(&mut self) {
        // ANGLE looks for them in a shader that passed every other check (a GLSL ES 1.00
        // `while` is Appendix A's business first).
        if self.diags.iter().any(|d| d.is_error()) {
            return;
        }
        let mut candidates = Vec::new();
        for (func, f) in self.functions.iter().enumerate() {
            let mut endless = Endless {
                func,
                found: Vec::new(),
            };
            endless.visit_stmts(&f.body);
            candidates.extend(endless.found);
        }
        if candidates.is_empty() {
            return;
        }
        // A variable as the condition: always true when its constant initializer is `true` and
        // nothing writes it (the rarer case, so the writes are looked for only then).
        let needs_writes = candidates.iter().any(|c| c.var.is_some());
        let modes: Vec<Vec<ParamMode>> = if needs_writes {
            self.functions
                .iter()
                .map(|f| f.params.iter().map(|p| p.mode).collect())
                .collect()
        } else {
            Vec::new()
        };
        let writes = needs_writes.then(|| self.writes(&modes));
        let found: Vec<crate::source::Span> = candidates
            .into_iter()
            .filter(|c| match (c.var, &writes) {
                (None, _) => true,
                (Some(v), Some((per_function, true_globals))) => match v {
                    Cond0::Local(l) => {
                        let w = &per_function[c.func];
                        w.true_locals.contains(&l) && !w.locals.contains(&l)
                    }
                    Cond0::Global(g) => true_globals.contains(&g),
                },
                (Some(_), None) => false,
            })
            .map(|c| c.span)
            .collect();
        for span in found {
            // The loop's header: up to its body's `{` or the end of its first line.
            let text = self.file.slice(span);
            let header = text.find(['{', '\n']).unwrap_or(text.len());
            let span = crate::source::Span::new(
                span.start,
                span.start + text[..header].trim_end().len() as u32,
            );
            let d = self.error(Code::InfiniteLoop, span, "this loop can never end");
            d.label = "its condition is always true, and nothing in it leaves the loop".into();
            d.notes.push(
                "WebGL implementations built on ANGLE (Chromium) refuse a `while` or `for` loop \
                 whose condition is always true (missing, a constant, or a variable initialized \
                 to `true` that nothing writes) unless a `break` of that loop or a `return` is \
                 inside it"
                    .into(),
            );
            d.help = Some(
                "add a `break` under the condition that ends it, or bound it: `for (int i = 0; i < N; i++)`"
                    .into(),
            );
        }
    }

    /// The writes of each function (`modes`: each function's parameter modes), and the globals
    /// whose constant initializer is `true` and that nothing writes.
    fn writes<'m>(&self, modes: &'m [Vec<ParamMode>]) -> (Vec<Writes<'m>>, HashSet<GlobalId>) {
        let mut global_writes: HashSet<GlobalId> = HashSet::new();
        let mut per_function = Vec::new();
        for f in &self.functions {
            let mut w = Writes {
                modes,
                ..Writes::default()
            };
            w.visit_stmts(&f.body);
            global_writes.extend(w.globals.iter().copied());
            per_function.push(w);
        }
        let true_globals = self
            .globals
            .iter()
            .enumerate()
            .filter(|(g, global)| {
                global.kind == GlobalKind::Private
                    && matches!(&global.init, Some(Init::Const(c))
                        if *c == ConstValue::Basic(vec![Scalar::B(true)]))
                    && !global_writes.contains(g)
            })
            .map(|(g, _)| g)
            .collect();
        (per_function, true_globals)
    }
}
