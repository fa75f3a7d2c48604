//! What each name in a shader refers to: a walk of the checked tree ([`essl::hir`]) that
//! records every use of a variable, parameter, function or built-in with its span, and every
//! expression's type, for hover, go to definition, references and completion.

use essl::hir::visit::{self, Visitor};
use essl::hir::{BuiltinFn, BuiltinVar, Expr, ExprKind, Module};
use essl::source::{SourceFile, Span};
use essl::types::Type;

/// What a name refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sym {
    /// A global variable.
    Global(usize),
    /// A local variable: (function, local).
    Local(usize, usize),
    /// A parameter: (function, parameter).
    Param(usize, usize),
    /// A user function.
    Func(usize),
    /// A built-in function.
    BuiltinFn(BuiltinFn),
    /// A built-in variable.
    BuiltinVar(BuiltinVar),
}

/// The uses and types of one shader.
#[derive(Debug, Default)]
pub struct Index {
    /// Every use of a name (its span covers the name only), in walk order.
    pub uses: Vec<(Span, Sym)>,
    /// Every expression's span and type.
    pub types: Vec<(Span, Type)>,
}

impl Index {
    /// Indexes a checked module; `file` is the text its spans point into.
    pub fn build(module: &Module, file: &SourceFile) -> Index {
        let mut walk = Walk {
            index: Index::default(),
            file,
            func: 0,
        };
        for (f, function) in module.functions.iter().enumerate() {
            walk.func = f;
            walk.visit_stmts(&function.body);
        }
        walk.index
    }

    /// The symbol at `offset`: a use, or a declaration's name.
    pub fn symbol_at(&self, module: &Module, offset: u32) -> Option<(Span, Sym)> {
        let inside = |s: Span| s.start <= offset && offset <= s.end;
        self.uses
            .iter()
            .copied()
            .filter(|(s, _)| inside(*s))
            .min_by_key(|(s, _)| s.len())
            .or_else(|| declarations(module).into_iter().find(|(s, _)| inside(*s)))
    }

    /// The type of the smallest expression around `offset`.
    pub fn type_at(&self, offset: u32) -> Option<(Span, &Type)> {
        self.types
            .iter()
            .filter(|(s, _)| s.start <= offset && offset <= s.end)
            .min_by_key(|(s, _)| s.len())
            .map(|(s, t)| (*s, t))
    }
}

/// Every declaration's name span and symbol.
pub fn declarations(module: &Module) -> Vec<(Span, Sym)> {
    let mut out: Vec<(Span, Sym)> = module
        .globals
        .iter()
        .enumerate()
        .map(|(i, g)| (g.span, Sym::Global(i)))
        .collect();
    for (f, function) in module.functions.iter().enumerate() {
        out.push((function.span, Sym::Func(f)));
        out.extend(
            function
                .params
                .iter()
                .enumerate()
                .map(|(p, param)| (param.span, Sym::Param(f, p))),
        );
        out.extend(
            function
                .locals
                .iter()
                .enumerate()
                .map(|(l, local)| (local.span, Sym::Local(f, l))),
        );
    }
    out
}

/// The span of a symbol's declaration (`None` for built-ins).
pub fn definition(module: &Module, sym: Sym) -> Option<Span> {
    match sym {
        Sym::Global(g) => module.globals.get(g).map(|g| g.span),
        Sym::Local(f, l) => module.functions.get(f)?.locals.get(l).map(|l| l.span),
        Sym::Param(f, p) => module.functions.get(f)?.params.get(p).map(|p| p.span),
        Sym::Func(f) => module.functions.get(f).map(|f| f.span),
        Sym::BuiltinFn(_) | Sym::BuiltinVar(_) => None,
    }
}

struct Walk<'a> {
    index: Index,
    file: &'a SourceFile,
    func: usize,
}

impl Walk<'_> {
    /// A call's name: the span's start, as long as the name is written there.
    fn name_at(&self, span: Span, name: &str) -> Option<Span> {
        let end = span.start + name.len() as u32;
        let text = self.file.text();
        (text.get(span.start as usize..end as usize) == Some(name))
            .then(|| Span::new(span.start, end))
    }

    /// Records an expression's type and the name it uses, if any.
    fn record(&mut self, e: &Expr) {
        if !matches!(e.ty, Type::Void) {
            self.index.types.push((e.span, e.ty.clone()));
        }
        let f = self.func;
        let sym = match &e.kind {
            ExprKind::Local(l) => Some((e.span, Sym::Local(f, *l))),
            ExprKind::Param(p) => Some((e.span, Sym::Param(f, *p))),
            ExprKind::Global(g) => Some((e.span, Sym::Global(*g))),
            ExprKind::BuiltinVar(v) => Some((e.span, Sym::BuiltinVar(*v))),
            ExprKind::Call(id, _) => self.call_name(e.span).map(|n| (n, Sym::Func(*id))),
            ExprKind::Builtin(op, _) => self
                .name_at(e.span, op.name())
                .map(|n| (n, Sym::BuiltinFn(*op))),
            _ => None,
        };
        self.index.uses.extend(sym);
    }

    /// The name of a user function's call: the identifier at the call's start.
    fn call_name(&self, span: Span) -> Option<Span> {
        let text = self.file.text().get(span.start as usize..)?;
        let len = text
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(text.len());
        (len > 0).then(|| Span::new(span.start, span.start + len as u32))
    }
}

impl Visitor for Walk<'_> {
    fn visit_expr(&mut self, e: &Expr) {
        self.record(e);
        visit::walk_expr(self, e);
    }
}
