//! Precision qualifiers, which naga IR does not have: computed on essl's checked tree (HIR) by
//! GLSL's rules and looked up by span.
//!
//! GLSL ES 3.00 §4.5.2: an operation is carried out at the highest precision of its operands
//! that have one (constants have none); a built-in function's result has the precision of its
//! arguments, a texture lookup that of its sampler; a user function's result is its declared
//! return precision. Every naga expression essl lowers from a HIR expression carries that
//! expression's span, so the span finds the precision.

use rustc_hash::FxHashMap as HashMap;

use essl::hir::visit::Visitor;
use essl::hir::{Expr, ExprKind, Function, Module};
use essl::source::Span;
use essl::types::{Precision, Type};

/// The precision of each HIR expression that has one, by span.
#[derive(Debug, Default)]
pub struct Precisions {
    by_span: HashMap<(u32, u32), Precision>,
}

impl Precisions {
    /// Computes the precisions of every expression of the module's functions.
    pub fn of(module: &Module) -> Precisions {
        // Room for a short shader's expressions: the first rehashes cost more than the walk.
        let mut p = Precisions {
            by_span: HashMap::with_capacity_and_hasher(64, Default::default()),
        };
        for f in &module.functions {
            let mut w = Walker {
                m: module,
                f,
                out: &mut p.by_span,
            };
            w.visit_stmts(&f.body);
        }
        p
    }

    /// The precision of the expression at `span`, if it has one.
    pub fn at(&self, span: Span) -> Option<Precision> {
        self.by_span.get(&(span.start, span.end)).copied()
    }

    /// Whether the expression at `span` is computed in `mediump` or `lowp`.
    pub fn is_low(&self, span: Span) -> bool {
        matches!(self.at(span), Some(Precision::Medium | Precision::Low))
    }
}

struct Walker<'a> {
    m: &'a Module,
    f: &'a Function,
    out: &'a mut HashMap<(u32, u32), Precision>,
}

/// Whether a shader's text may compute anything below `highp`: it names `mediump` or `lowp`,
/// or reads `gl_PointCoord` (itself `mediump`). Without these words every float is `highp`.
pub(crate) fn names_low_precision(text: &str) -> bool {
    ["mediump", "lowp", "gl_PointCoord"]
        .iter()
        .any(|w| text.contains(w))
}

fn highest(a: Option<Precision>, b: Option<Precision>) -> Option<Precision> {
    match (a, b) {
        (Some(x), Some(y)) => Some(x.max(y)),
        (x, None) => x,
        (None, y) => y,
    }
}

/// Statements are walked as everywhere else; each expression statement, initialiser and
/// condition is a root whose precision [`Walker::expr`] computes bottom-up.
impl Visitor for Walker<'_> {
    fn visit_expr(&mut self, e: &Expr) {
        self.expr(e);
    }
}

impl Walker<'_> {
    fn member_precision(&self, base: &Expr, m: usize) -> Option<Precision> {
        match &base.ty {
            Type::Struct(id) => self
                .m
                .structs
                .get(id.0 as usize)
                .and_then(|s| s.members.get(m))
                .and_then(|mm| mm.precision),
            _ => None,
        }
    }

    /// Records and returns the precision of `e` (and of its subexpressions).
    fn expr(&mut self, e: &Expr) -> Option<Precision> {
        let p = match &e.kind {
            ExprKind::Const(_) => None,
            ExprKind::Local(l) => self.f.locals.get(*l).and_then(|x| x.precision),
            ExprKind::Param(i) => self.f.params.get(*i).and_then(|x| x.precision),
            ExprKind::Global(g) => self.m.globals.get(*g).and_then(|x| x.precision),
            ExprKind::BuiltinVar(v) => v.precision(),
            ExprKind::Unary(_, a) => self.expr(a),
            ExprKind::Binary(op, a, b) => {
                let (x, y) = (self.expr(a), self.expr(b));
                use essl::hir::BinaryOp as B;
                if matches!(
                    op,
                    B::Less
                        | B::Greater
                        | B::LessEq
                        | B::GreaterEq
                        | B::Eq
                        | B::NotEq
                        | B::And
                        | B::Xor
                        | B::Or
                ) {
                    None
                } else {
                    highest(x, y)
                }
            }
            ExprKind::Assign(_, l, r) => {
                let x = self.expr(l);
                self.expr(r);
                x
            }
            ExprKind::IncDec(_, _, t) => self.expr(t),
            ExprKind::Select(c, a, b) => {
                self.expr(c);
                let (x, y) = (self.expr(a), self.expr(b));
                highest(x, y)
            }
            ExprKind::Comma(a, b) => {
                self.expr(a);
                self.expr(b)
            }
            ExprKind::Index(b, i) => {
                self.expr(i);
                self.expr(b)
            }
            ExprKind::Member(b, m) => {
                let x = self.expr(b);
                self.member_precision(b, *m).or(x)
            }
            ExprKind::Swizzle(b, _) => self.expr(b),
            ExprKind::Call(f, args) => {
                for a in args {
                    self.expr(a);
                }
                self.m.functions.get(*f).and_then(|x| x.ret_precision)
            }
            ExprKind::Builtin(op, args) => {
                let ps: Vec<Option<Precision>> = args.iter().map(|a| self.expr(a)).collect();
                if op.is_texture() {
                    ps.first().copied().flatten()
                } else {
                    ps.into_iter().fold(None, highest)
                }
            }
            ExprKind::Construct(args) => args
                .iter()
                .map(|a| self.expr(a))
                .collect::<Vec<_>>()
                .into_iter()
                .fold(None, highest),
            ExprKind::BlockMember(b, idx, m) => {
                if let Some(i) = idx {
                    self.expr(i);
                }
                self.m
                    .blocks
                    .get(*b)
                    .and_then(|bl| bl.members.get(*m))
                    .and_then(|x| x.2)
            }
            // An expression kind added to essl later: no precision known.
            _ => None,
        };
        if let Some(p) = p {
            if e.ty.scalar_kind().is_some() {
                self.out.entry((e.span.start, e.span.end)).or_insert(p);
            }
        }
        p
    }
}
