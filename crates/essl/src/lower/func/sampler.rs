//! Samplers: the texture and sampler bindings a sampler expression denotes, resolved when
//! lowering (naga has no sampler values to compute with). Two cases need more than a lookup:
//!
//! - a sampler array indexed at run time (GLSL ES 1.00 allows a loop index, a vertex shader any
//!   index into a uniform array): the call that uses it is lowered once per element, in a chain
//!   of `if`s on the index (the last element also takes an index out of range);
//! - a struct or array parameter holding samplers: besides the value (where samplers are
//!   placeholders, as in every struct), each sampler in it becomes a texture and a sampler
//!   argument of its own, which the caller fills from its argument at the same path.

use rustc_hash::FxHashMap as HashMap;

use naga::{Expression, Handle, Statement};

use super::{FnCx, ParamLower};
use crate::hir::{ConstValue, Expr, ExprKind, Scalar};
use crate::lower::{unsupported, LowerError};
use crate::reflect::PathStep;
use crate::types::Type;

/// The texture and sampler arguments of the samplers inside a function's parameters: by
/// (parameter, path inside it).
pub(crate) type ParamSamplers = HashMap<(usize, Vec<PathStep>), (u32, u32)>;

/// How a call is lowered for one choice of its sampler arguments.
pub(crate) type LowerCall<'l, 'c, 'a> =
    &'l dyn Fn(&mut FnCx<'c, 'a>, &[Expr]) -> Result<Handle<Expression>, LowerError>;

/// The path of a sampler expression from its variable: the variable (a global or a parameter)
/// and the steps, or the first index that is not a constant.
enum Root<'e> {
    Global(usize, Vec<PathStep>),
    Param(usize, Vec<PathStep>),
    Dynamic(&'e Expr),
    Other,
}

fn root(e: &Expr) -> Root<'_> {
    let mut path = Vec::new();
    let mut cur = e;
    loop {
        match &cur.kind {
            ExprKind::Index(b, i) => {
                let Some(k) = i.as_const().and_then(|c| c.as_int()) else {
                    return Root::Dynamic(cur);
                };
                path.push(PathStep::Index(k as u32));
                cur = b;
            }
            ExprKind::Member(b, m) => {
                path.push(PathStep::Member(*m as u32));
                cur = b;
            }
            ExprKind::Global(g) => {
                path.reverse();
                return Root::Global(*g, path);
            }
            ExprKind::Param(i) => {
                path.reverse();
                return Root::Param(*i, path);
            }
            _ => return Root::Other,
        }
    }
}

/// `e` with its index node `at` (an `Index` of `e`'s chain) given the constant index `k`.
fn with_index(e: &Expr, at: &Expr, k: u32) -> Expr {
    if std::ptr::eq(e, at) {
        if let ExprKind::Index(b, i) = &e.kind {
            let index = Expr {
                kind: ExprKind::Const(ConstValue::Basic(vec![Scalar::I(k as i32)])),
                ty: Type::INT,
                span: i.span,
            };
            return Expr {
                kind: ExprKind::Index(b.clone(), Box::new(index)),
                ..e.clone()
            };
        }
    }
    let kind = match &e.kind {
        ExprKind::Index(b, i) => ExprKind::Index(Box::new(with_index(b, at, k)), i.clone()),
        ExprKind::Member(b, m) => ExprKind::Member(Box::new(with_index(b, at, k)), *m),
        other => other.clone(),
    };
    Expr { kind, ..e.clone() }
}

/// A sampler argument of `args` indexed at run time: its position, the index node and the
/// array's length.
fn dynamic_sampler<'e>(
    args: &'e [Expr],
    structs: &[crate::types::StructDef],
) -> Option<(usize, &'e Expr, u32)> {
    args.iter().enumerate().find_map(|(i, a)| {
        if !a.ty.contains_sampler(structs) && !matches!(a.ty, Type::Sampler(_)) {
            return None;
        }
        match root(a) {
            Root::Dynamic(
                node @ Expr {
                    kind: ExprKind::Index(b, _),
                    ..
                },
            ) => match b.ty {
                Type::Array(_, n) => Some((i, node, n)),
                _ => None,
            },
            _ => None,
        }
    })
}

impl<'c, 'a> FnCx<'c, 'a> {
    /// The texture and sampler a sampler-typed expression denotes (resolved statically).
    pub(crate) fn sampler(
        &mut self,
        e: &Expr,
    ) -> Result<(Handle<Expression>, Handle<Expression>), LowerError> {
        self.sampler_at(e, &[])
    }

    /// The texture and sampler at `path` inside the value `e` denotes (a struct or array of
    /// samplers passed to a parameter), or of `e` itself with an empty path.
    pub(crate) fn sampler_at(
        &mut self,
        e: &Expr,
        path: &[PathStep],
    ) -> Result<(Handle<Expression>, Handle<Expression>), LowerError> {
        match root(e) {
            Root::Global(g, mut full) => {
                full.extend_from_slice(path);
                match self.cx.samplers.get(&(g, full)).copied() {
                    Some((t, s)) => Ok((
                        self.add(Expression::GlobalVariable(t), e.span),
                        self.add(Expression::GlobalVariable(s), e.span),
                    )),
                    None => Err(unsupported("an inactive sampler", e.span)),
                }
            }
            Root::Param(i, mut full) => {
                full.extend_from_slice(path);
                let args = match (&self.params[i], full.is_empty()) {
                    (ParamLower::Sampler(t, s), true) => Some((*t, *s)),
                    _ => self.param_samplers.get(&(i, full)).copied(),
                };
                match args {
                    Some((t, s)) => Ok((
                        self.add(Expression::FunctionArgument(t), e.span),
                        self.add(Expression::FunctionArgument(s), e.span),
                    )),
                    None => Err(unsupported("a sampler inside a parameter", e.span)),
                }
            }
            Root::Dynamic(_) => Err(unsupported("a sampler selected at run time", e.span)),
            Root::Other => Err(unsupported("this sampler expression", e.span)),
        }
    }

    /// Whether every sampler an expression names is bound (not an inactive one in dead code).
    pub(crate) fn sampler_available(&self, e: &Expr) -> bool {
        match root(e) {
            Root::Global(g, path) => self.cx.samplers.contains_key(&(g, path)),
            _ => true,
        }
    }

    /// Lowers `lower(args)` where a sampler argument is indexed at run time: once per element,
    /// in a chain of `if`s on the index, into a temporary of type `ret`. `None` when no
    /// sampler argument is indexed at run time.
    pub(crate) fn per_sampler_element(
        &mut self,
        args: &[Expr],
        ret: &Type,
        span: crate::source::Span,
        lower: LowerCall<'_, 'c, 'a>,
    ) -> Option<Result<Handle<Expression>, LowerError>> {
        let (pos, node, n) = dynamic_sampler(args, &self.cx.hir.structs)?;
        let ExprKind::Index(_, index) = &node.kind else {
            return None;
        };
        Some((|| {
            let tmp = (*ret != Type::Void).then(|| self.new_local("_essl_sampled", ret));
            let iv = self.expr(index)?;
            // From the last element up: the `else` of each test holds the ones before it.
            let mut chain: Option<naga::Block> = None;
            for k in (0..n).rev() {
                let mut with_k = args.to_vec();
                with_k[pos] = with_index(&args[pos], node, k);
                let body = self.capture(|fx| {
                    let v = lower(fx, &with_k)?;
                    if let Some(t) = tmp {
                        fx.store_local(t, v, span);
                    }
                    Ok(())
                })?;
                chain = Some(match chain {
                    None => body,
                    Some(rest) => {
                        let kv = if index.ty == Type::UINT {
                            naga::Literal::U32(k)
                        } else {
                            naga::Literal::I32(k as i32)
                        };
                        self.capture(|fx| {
                            let lit = fx.lit(kv);
                            let c = fx.binop(naga::BinaryOperator::Equal, iv, lit, span);
                            fx.push(
                                Statement::If {
                                    condition: c,
                                    accept: body,
                                    reject: rest,
                                },
                                span,
                            );
                            Ok(())
                        })?
                    }
                });
            }
            if let Some(block) = chain {
                self.push(Statement::Block(block), span);
            }
            Ok(match tmp {
                Some(t) => {
                    let p = self.add(Expression::LocalVariable(t), span);
                    self.add(Expression::Load { pointer: p }, span)
                }
                None => self.lit(naga::Literal::Bool(false)),
            })
        })())
    }
}
