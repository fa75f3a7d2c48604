//! The extraction of terms from the shader: the value of an expression as a [`Term`] over the
//! uniforms it reads, followed through loads, struct parts and the parameters of functions (one
//! context per call site that reaches them).

use std::collections::HashMap;

use essl::source::Span;
use essl::Stage;
use naga::{
    BinaryOperator as Bo, Expression as E, Function, Handle, Literal, MathFunction as Mf,
    ScalarKind, Statement, TypeInner, UnaryOperator as Uo,
};

use super::{
    BinOp, Func, PathStep, Term, UniformRef, Value, DEFAULT_BLOCK, MAX_CALL_DEPTH, MAX_CONTEXTS,
};
use crate::analysis::{self, literal};
use crate::rules::Cx;

/// A value the extraction follows: a term, an aggregate of them (a struct built by the
/// shader), or a uniform place not yet read down to a scalar or vector.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum X {
    Num(Term),
    Agg(Vec<Option<X>>),
    Place(UniformRef, Handle<naga::Type>),
}

#[derive(Clone, Copy, Debug)]
pub(super) enum Step {
    Index(u32),
    Dynamic,
}

/// The values of a function's parameters at one call site (and the calls that lead there).
#[derive(Clone, Debug, Default)]
pub(super) struct Context {
    pub(super) args: Vec<Option<X>>,
    pub(super) sites: Vec<Span>,
}

pub(super) struct CallSite {
    caller: usize,
    args: Vec<Handle<E>>,
    span: Span,
}

pub(super) struct Extractor<'a> {
    pub(super) cx: &'a Cx<'a>,
    pub(super) module: &'a naga::Module,
    pub(super) stage: Stage,
    calls: HashMap<usize, Vec<CallSite>>,
    contexts: std::cell::RefCell<HashMap<usize, Vec<Context>>>,
}

impl<'a> Extractor<'a> {
    pub(super) fn new(cx: &'a Cx<'a>, stage: Stage) -> Extractor<'a> {
        let module = cx.module;
        let count = module.functions.len() + module.entry_points.len();
        let mut calls: HashMap<usize, Vec<CallSite>> = HashMap::new();
        for caller in 0..count {
            let f = analysis::function(module, caller);
            collect_calls(f, &f.body, caller, &mut calls);
        }
        Extractor {
            cx,
            module,
            stage,
            calls,
            contexts: Default::default(),
        }
    }

    fn inner(&self, id: usize, h: Handle<E>) -> &'a TypeInner {
        self.cx.info.ty(id, h)
    }

    fn is_pointer(&self, id: usize, h: Handle<E>) -> bool {
        matches!(
            self.inner(id, h),
            TypeInner::Pointer { .. } | TypeInner::ValuePointer { .. }
        )
    }

    /// The parameter values of function `id` at each call site that reaches it.
    pub(super) fn contexts(&self, id: usize, depth: u32) -> Vec<Context> {
        let f = analysis::function(self.module, id);
        if f.arguments.is_empty() || id >= self.module.functions.len() {
            return vec![Context::default()];
        }
        if let Some(c) = self.contexts.borrow().get(&id) {
            return c.clone();
        }
        let mut out: Vec<Context> = Vec::new();
        if depth < MAX_CALL_DEPTH {
            'sites: for site in self.calls.get(&id).map(|v| v.as_slice()).unwrap_or(&[]) {
                for outer in self.contexts(site.caller, depth + 1) {
                    let args: Vec<Option<X>> = site
                        .args
                        .iter()
                        .map(|a| self.value(site.caller, &outer, *a, 0))
                        .collect();
                    let mut sites = outer.sites.clone();
                    sites.push(site.span);
                    out.push(Context { args, sites });
                    if out.len() >= MAX_CONTEXTS {
                        break 'sites;
                    }
                }
            }
        }
        self.contexts.borrow_mut().insert(id, out.clone());
        out
    }

    /// The term of expression `h` of function `id` in a context, if it is computed from
    /// uniforms and constants only.
    pub(super) fn term(&self, id: usize, ctx: &Context, h: Handle<E>) -> Option<Term> {
        match self.value(id, ctx, h, 0)? {
            X::Num(t) if !t.uniforms().is_empty() => Some(t),
            _ => None,
        }
    }

    pub(super) fn value(&self, id: usize, ctx: &Context, h: Handle<E>, depth: u32) -> Option<X> {
        if depth > 48 {
            return None;
        }
        let d = depth + 1;
        let f = analysis::function(self.module, id);
        let num = |x: Option<X>| match x {
            Some(X::Num(t)) => Some(t),
            _ => None,
        };
        let sub = |x: Handle<E>| num(self.value(id, ctx, x, d));
        Some(match &f.expressions[h] {
            E::Literal(Literal::Bool(_)) => return None,
            E::Literal(l) => X::Num(Term::Const(Value::scalar(literal(l)))),
            E::Constant(_) | E::ZeroValue(_) => {
                let n = self.cx.sound().num(id, h)?;
                let c: Option<Vec<f64>> = n.comps().iter().map(|i| i.as_point()).collect();
                X::Num(Term::Const(Value::new(&c?)))
            }
            E::Splat { size, value } => X::Num(Term::Splat(Box::new(sub(*value)?), *size as u8)),
            E::Swizzle {
                size,
                vector,
                pattern,
            } => X::Num(Term::Swizzle(
                Box::new(sub(*vector)?),
                pattern[..*size as usize].iter().map(|c| *c as u8).collect(),
            )),
            E::Compose { ty, components } => match self.module.types[*ty].inner {
                TypeInner::Vector { .. } => {
                    let parts: Option<Vec<Term>> = components.iter().map(|c| sub(*c)).collect();
                    X::Num(Term::Compose(parts?))
                }
                TypeInner::Struct { .. } | TypeInner::Array { .. } => X::Agg(
                    components
                        .iter()
                        .map(|c| self.value(id, ctx, *c, d))
                        .collect(),
                ),
                _ => return None,
            },
            E::AccessIndex { base, index } => {
                if self.is_pointer(id, h) {
                    return None;
                }
                let x = self.value(id, ctx, *base, d)?;
                self.step(x, Step::Index(*index))?
            }
            E::Access { base, index } => {
                if self.is_pointer(id, h) {
                    return None;
                }
                let x = self.value(id, ctx, *base, d)?;
                self.step(x, self.index_step(id, *index))?
            }
            E::Load { pointer } => self.load(id, ctx, *pointer, d)?,
            E::Unary {
                op: Uo::Negate,
                expr,
            } => X::Num(Term::Neg(Box::new(sub(*expr)?))),
            E::Binary { op, left, right } => {
                let op = match op {
                    Bo::Add => BinOp::Add,
                    Bo::Subtract => BinOp::Sub,
                    Bo::Multiply => BinOp::Mul,
                    Bo::Divide => BinOp::Div,
                    _ => return None,
                };
                let matrix = |x: Handle<E>| matches!(self.inner(id, x), TypeInner::Matrix { .. });
                if matrix(*left) || matrix(*right) {
                    return None;
                }
                X::Num(Term::Binary(
                    op,
                    Box::new(sub(*left)?),
                    Box::new(sub(*right)?),
                ))
            }
            E::Math {
                fun,
                arg,
                arg1,
                arg2,
                ..
            } => {
                let func = match (fun, arg1) {
                    (Mf::Atan2, _) => Func::Atan2,
                    _ => Func::of(*fun)?,
                };
                let mut args = vec![sub(*arg)?];
                for a in [arg1, arg2].into_iter().flatten() {
                    args.push(sub(*a)?);
                }
                X::Num(Term::Call(func, args))
            }
            E::As {
                expr,
                kind,
                convert: Some(_),
            } => {
                let t = sub(*expr)?;
                match kind {
                    ScalarKind::Float => X::Num(t),
                    ScalarKind::Sint | ScalarKind::Uint => X::Num(Term::Call(Func::Trunc, vec![t])),
                    _ => return None,
                }
            }
            E::FunctionArgument(i) => ctx.args.get(*i as usize)?.clone()?,
            _ => return None,
        })
    }

    fn index_step(&self, id: usize, index: Handle<E>) -> Step {
        match self
            .cx
            .sound()
            .num(id, index)
            .and_then(|n| n.hull().as_point())
        {
            Some(k) if k >= 0.0 && k.fract() == 0.0 && k < u32::MAX as f64 => Step::Index(k as u32),
            _ => Step::Dynamic,
        }
    }

    fn load(&self, id: usize, ctx: &Context, pointer: Handle<E>, d: u32) -> Option<X> {
        let f = analysis::function(self.module, id);
        let mut steps = Vec::new();
        let mut p = pointer;
        let mut x = loop {
            match f.expressions[p] {
                E::AccessIndex { base, index } => {
                    steps.push(Step::Index(index));
                    p = base;
                }
                E::Access { base, index } => {
                    steps.push(self.index_step(id, index));
                    p = base;
                }
                E::GlobalVariable(g) => {
                    let gv = &self.module.global_variables[g];
                    if gv.space != naga::AddressSpace::Uniform
                        || gv.name.as_deref() != Some(DEFAULT_BLOCK)
                    {
                        return None;
                    }
                    break X::Place(UniformRef::new(""), gv.ty);
                }
                E::LocalVariable(l) => {
                    let v = *self.cx.sound().functions[id].single_store.get(&l.index())?;
                    break self.value(id, ctx, v, d)?;
                }
                _ => return None,
            }
        };
        for s in steps.into_iter().rev() {
            x = self.step(x, s)?;
        }
        Some(x)
    }

    /// A uniform place of type `ty`: a term for a scalar or vector, the place otherwise.
    fn leaf(&self, r: UniformRef, ty: Handle<naga::Type>) -> Option<X> {
        match self.module.types[ty].inner {
            TypeInner::Scalar(_) | TypeInner::Vector { .. } => Some(X::Num(Term::Uniform(r))),
            TypeInner::Struct { .. } | TypeInner::Array { .. } => Some(X::Place(r, ty)),
            _ => None,
        }
    }

    fn step(&self, x: X, s: Step) -> Option<X> {
        match (x, s) {
            (X::Num(t), Step::Index(i)) => Some(X::Num(Term::Swizzle(Box::new(t), vec![i as u8]))),
            (X::Agg(xs), Step::Index(i)) => xs.get(i as usize)?.clone(),
            (X::Place(mut r, ty), s) => match (&self.module.types[ty].inner, s) {
                (TypeInner::Struct { members, .. }, Step::Index(i)) => {
                    let m = members.get(i as usize)?;
                    let name = m.name.clone()?;
                    if r.base.is_empty() {
                        if name.starts_with("_essl") {
                            return None;
                        }
                        r.base = name;
                    } else if !essl::lower::layout::is_padded(self.module, ty) {
                        r.path.push(PathStep::Member(name));
                    }
                    self.leaf(r, m.ty)
                }
                (TypeInner::Array { base, .. }, s) => {
                    r.path.push(match s {
                        Step::Index(i) => PathStep::Index(i),
                        Step::Dynamic => PathStep::AnyIndex,
                    });
                    self.leaf(r, *base)
                }
                _ => None,
            },
            _ => None,
        }
    }

    /// The uniform a pointer expression reads, through struct members and array elements
    /// (not into vector components or matrix columns).
    pub(super) fn uniform_of_pointer(&self, id: usize, pointer: Handle<E>) -> Option<UniformRef> {
        let f = analysis::function(self.module, id);
        let mut steps = Vec::new();
        let mut p = pointer;
        let ty = loop {
            match f.expressions[p] {
                E::AccessIndex { base, index } => {
                    steps.push(Step::Index(index));
                    p = base;
                }
                E::Access { base, index } => {
                    steps.push(self.index_step(id, index));
                    p = base;
                }
                E::GlobalVariable(g) => {
                    let gv = &self.module.global_variables[g];
                    if gv.space != naga::AddressSpace::Uniform
                        || gv.name.as_deref() != Some(DEFAULT_BLOCK)
                    {
                        return None;
                    }
                    break gv.ty;
                }
                _ => return None,
            }
        };
        let mut r = UniformRef::new("");
        let mut ty = ty;
        for s in steps.into_iter().rev() {
            match (&self.module.types[ty].inner, s) {
                (TypeInner::Struct { members, .. }, Step::Index(i)) => {
                    let m = members.get(i as usize)?;
                    let name = m.name.clone()?;
                    let padded = essl::lower::layout::is_padded(self.module, ty);
                    if r.base.is_empty() {
                        if name.starts_with("_essl") {
                            return None;
                        }
                        r.base = name;
                    } else if !padded {
                        r.path.push(PathStep::Member(name));
                    }
                    ty = m.ty;
                }
                (TypeInner::Array { base, .. }, s) => {
                    r.path.push(match s {
                        Step::Index(i) => PathStep::Index(i),
                        Step::Dynamic => PathStep::AnyIndex,
                    });
                    ty = *base;
                }
                _ => break,
            }
        }
        (!r.base.is_empty()).then_some(r)
    }
}

pub(super) fn as_num(x: X) -> Option<Term> {
    match x {
        X::Num(t) => Some(t),
        _ => None,
    }
}

fn collect_calls(
    f: &Function,
    b: &naga::Block,
    caller: usize,
    out: &mut HashMap<usize, Vec<CallSite>>,
) {
    for (s, span) in b.span_iter() {
        match s {
            Statement::Call {
                function,
                arguments,
                result,
            } => {
                let mut span = Span::from(*span);
                if span.is_empty() {
                    if let Some(r) = result {
                        span = Span::from(f.expressions.get_span(*r));
                    }
                }
                out.entry(function.index()).or_default().push(CallSite {
                    caller,
                    args: arguments.clone(),
                    span,
                });
            }
            Statement::Block(b) => collect_calls(f, b, caller, out),
            Statement::If { accept, reject, .. } => {
                collect_calls(f, accept, caller, out);
                collect_calls(f, reject, caller, out);
            }
            Statement::Switch { cases, .. } => {
                for c in cases {
                    collect_calls(f, &c.body, caller, out);
                }
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                collect_calls(f, body, caller, out);
                collect_calls(f, continuing, caller, out);
            }
            _ => {}
        }
    }
}
