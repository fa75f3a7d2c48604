//! Function bodies: statements, expressions, places (pointers) and the entry-point wrapper.

use naga::proc::Emitter;
use naga::{Expression, Handle, Literal, Span as NSpan, Statement};

use super::layout::{vsize, Repr};
use super::{nspan, unsupported, GlobalLower, LowerError, ModuleCx, StagePlan};
use crate::ast::BinaryOp;
use crate::builtins::BuiltinVar;
use crate::hir::{self, ConstValue, Expr, ExprKind, FuncId, ParamMode, Scalar, Stmt, StmtKind};
use crate::reflect::PathStep;
use crate::source::Span;
use crate::types::{ScalarKind, Type};
use crate::Stage;

/// How a HIR parameter is reached inside the lowered function.
#[derive(Clone, Copy, Debug)]
enum ParamLower {
    /// An `in` parameter copied into a local (GLSL lets functions write their parameters).
    Local(Handle<naga::LocalVariable>),
    /// An `out`/`inout` parameter: a pointer argument.
    Pointer(u32),
    /// A sampler parameter: texture and sampler arguments.
    Sampler(u32, u32),
}

/// A pointer to a variable or part of one, with how its stored form differs.
#[derive(Clone, Debug)]
pub(crate) struct Place {
    pub ptr: Handle<Expression>,
    pub repr: Repr,
    pub ty: Type,
}

/// A write target.
enum LValue {
    Place(Place),
    /// Some components of a vector place.
    Swizzle(Place, Vec<u8>),
    /// Not lowered (dead code reading an inactive variable): writes are dropped.
    Nowhere,
}

pub(crate) struct FnCx<'c, 'a> {
    pub cx: &'c mut ModuleCx<'a>,
    pub f: naga::Function,
    emitter: Emitter,
    blocks: Vec<naga::Block>,
    locals: Vec<Option<Handle<naga::LocalVariable>>>,
    params: Vec<ParamLower>,
    hir_fn: Option<&'a hir::Function>,
}

/// Builds a constant in the module's constant-expression arena.
pub(crate) fn global_constant(cx: &mut ModuleCx, c: &ConstValue, ty: &Type) -> Handle<Expression> {
    let e = match (c, ty) {
        (ConstValue::Basic(v), Type::Scalar(_)) => Expression::Literal(literal(v[0])),
        (ConstValue::Basic(v), Type::Vector(k, n)) => {
            let comps = v
                .iter()
                .map(|s| {
                    cx.module
                        .global_expressions
                        .append(Expression::Literal(literal(*s)), NSpan::UNDEFINED)
                })
                .collect();
            let ty = cx.types.logical(&mut cx.module, &Type::Vector(*k, *n));
            Expression::Compose {
                ty,
                components: comps,
            }
        }
        (ConstValue::Basic(v), Type::Matrix { cols, rows }) => {
            let col_ty = Type::Vector(ScalarKind::Float, *rows);
            let comps = (0..*cols as usize)
                .map(|c| {
                    let col =
                        ConstValue::Basic(v[c * *rows as usize..(c + 1) * *rows as usize].to_vec());
                    global_constant(cx, &col, &col_ty)
                })
                .collect();
            let ty = cx.types.logical(&mut cx.module, ty);
            Expression::Compose {
                ty,
                components: comps,
            }
        }
        (ConstValue::Composite(elems), Type::Array(el, _)) => {
            let comps = elems.iter().map(|e| global_constant(cx, e, el)).collect();
            let ty = cx.types.logical(&mut cx.module, ty);
            Expression::Compose {
                ty,
                components: comps,
            }
        }
        (ConstValue::Composite(members), Type::Struct(id)) => {
            let mtys: Vec<Type> = cx.hir.structs[id.0 as usize]
                .members
                .iter()
                .map(|m| m.ty.clone())
                .collect();
            let comps = members
                .iter()
                .zip(&mtys)
                .map(|(e, t)| global_constant(cx, e, t))
                .collect();
            let ty = cx.types.logical(&mut cx.module, ty);
            Expression::Compose {
                ty,
                components: comps,
            }
        }
        _ => {
            let ty = cx.types.logical(&mut cx.module, ty);
            Expression::ZeroValue(ty)
        }
    };
    cx.module.global_expressions.append(e, NSpan::UNDEFINED)
}

pub(crate) fn literal(s: Scalar) -> Literal {
    match s {
        Scalar::F(v) => Literal::F32(v),
        Scalar::I(v) => Literal::I32(v),
        Scalar::U(v) => Literal::U32(v),
        Scalar::B(v) => Literal::Bool(v),
    }
}

/// Lowers a user function.
pub(crate) fn lower_function(cx: &mut ModuleCx, id: FuncId) -> Result<naga::Function, LowerError> {
    let hir_fn = &cx.hir.functions[id];
    let mut f = naga::Function {
        name: Some(format!("{}_", hir_fn.name)),
        ..Default::default()
    };
    let mut params = Vec::new();
    let mut copies = Vec::new();
    for p in &hir_fn.params {
        match &p.ty {
            Type::Sampler(st) => {
                let (img, smp) = super::sampler_types(&mut cx.module, *st);
                let i = f.arguments.len() as u32;
                f.arguments.push(naga::FunctionArgument {
                    name: Some(p.name.to_string()),
                    ty: img,
                    binding: None,
                });
                f.arguments.push(naga::FunctionArgument {
                    name: Some(format!("{}_sampler", p.name)),
                    ty: smp,
                    binding: None,
                });
                params.push(ParamLower::Sampler(i, i + 1));
            }
            t if t.contains_sampler(&cx.hir.structs) => {
                return Err(unsupported(
                    "a struct or array of samplers as a function parameter",
                    p.span,
                ));
            }
            t => {
                let ty = cx.types.logical(&mut cx.module, t);
                let i = f.arguments.len() as u32;
                match p.mode {
                    ParamMode::In => {
                        f.arguments.push(naga::FunctionArgument {
                            name: Some(p.name.to_string()),
                            ty,
                            binding: None,
                        });
                        let local = f.local_variables.append(
                            naga::LocalVariable {
                                name: Some(p.name.to_string()),
                                ty,
                                init: None,
                            },
                            nspan(p.span),
                        );
                        copies.push((i, local));
                        params.push(ParamLower::Local(local));
                    }
                    _ => {
                        let ptr = cx.module.types.insert(
                            naga::Type {
                                name: None,
                                inner: naga::TypeInner::Pointer {
                                    base: ty,
                                    space: naga::AddressSpace::Function,
                                },
                            },
                            NSpan::UNDEFINED,
                        );
                        f.arguments.push(naga::FunctionArgument {
                            name: Some(p.name.to_string()),
                            ty: ptr,
                            binding: None,
                        });
                        params.push(ParamLower::Pointer(i));
                    }
                }
            }
        }
    }
    if hir_fn.ret != Type::Void {
        let ty = cx.types.logical(&mut cx.module, &hir_fn.ret);
        f.result = Some(naga::FunctionResult { ty, binding: None });
    }
    let mut fx = FnCx {
        cx,
        f,
        emitter: Emitter::default(),
        blocks: vec![naga::Block::new()],
        locals: vec![None; hir_fn.locals.len()],
        params,
        hir_fn: Some(hir_fn),
    };
    fx.emitter.start(&fx.f.expressions);
    for (arg, local) in copies {
        let a = fx.add(Expression::FunctionArgument(arg), Span::default());
        let l = fx.add(Expression::LocalVariable(local), Span::default());
        fx.push(
            Statement::Store {
                pointer: l,
                value: a,
            },
            Span::default(),
        );
    }
    fx.stmts(&hir_fn.body)?;
    fx.flush();
    let body = fx.blocks.pop().expect("body");
    let mut f = fx.f;
    f.body = body;
    Ok(f)
}

impl<'c, 'a> FnCx<'c, 'a> {
    // ----- plumbing -----

    pub(crate) fn add(&mut self, e: Expression, span: Span) -> Handle<Expression> {
        if e.needs_pre_emit() {
            self.flush_only();
            let h = self.f.expressions.append(e, nspan(span));
            self.emitter.start(&self.f.expressions);
            h
        } else {
            self.f.expressions.append(e, nspan(span))
        }
    }

    fn flush_only(&mut self) {
        if let Some((stmt, span)) = self.emitter.finish(&self.f.expressions) {
            self.blocks.last_mut().expect("block").push(stmt, span);
        }
    }

    /// Ends the current run of expressions with an `Emit`, and starts a new run.
    pub(crate) fn flush(&mut self) {
        self.flush_only();
        self.emitter.start(&self.f.expressions);
    }

    /// Pushes a statement after the expressions emitted so far.
    pub(crate) fn push(&mut self, s: Statement, span: Span) {
        self.flush_only();
        self.blocks.last_mut().expect("block").push(s, nspan(span));
        self.emitter.start(&self.f.expressions);
    }

    /// Lowers statements into a new block and returns it.
    fn block_of(&mut self, stmts: &[Stmt]) -> Result<naga::Block, LowerError> {
        self.flush();
        self.blocks.push(naga::Block::new());
        self.stmts(stmts)?;
        self.flush();
        Ok(self.blocks.pop().expect("pushed"))
    }

    /// Runs `f` with its statements collected into a new block.
    fn capture(
        &mut self,
        f: impl FnOnce(&mut Self) -> Result<(), LowerError>,
    ) -> Result<naga::Block, LowerError> {
        self.flush();
        self.blocks.push(naga::Block::new());
        f(self)?;
        self.flush();
        Ok(self.blocks.pop().expect("pushed"))
    }

    pub(crate) fn ty(&mut self, t: &Type) -> Handle<naga::Type> {
        self.cx.types.logical(&mut self.cx.module, t)
    }

    pub(crate) fn new_local(&mut self, name: &str, t: &Type) -> Handle<naga::LocalVariable> {
        let ty = self.ty(t);
        self.f.local_variables.append(
            naga::LocalVariable {
                name: Some(name.to_string()),
                ty,
                init: None,
            },
            NSpan::UNDEFINED,
        )
    }

    pub(crate) fn lit(&mut self, l: Literal) -> Handle<Expression> {
        self.add(Expression::Literal(l), Span::default())
    }

    pub(crate) fn zero(&mut self, t: &Type) -> Handle<Expression> {
        let ty = self.ty(t);
        self.add(Expression::ZeroValue(ty), Span::default())
    }

    pub(crate) fn splat(&mut self, v: Handle<Expression>, n: u8, span: Span) -> Handle<Expression> {
        self.add(
            Expression::Splat {
                size: vsize(n),
                value: v,
            },
            span,
        )
    }

    pub(crate) fn compose(
        &mut self,
        t: &Type,
        components: Vec<Handle<Expression>>,
        span: Span,
    ) -> Handle<Expression> {
        let ty = self.ty(t);
        self.add(Expression::Compose { ty, components }, span)
    }

    pub(crate) fn access_index(
        &mut self,
        base: Handle<Expression>,
        index: u32,
        span: Span,
    ) -> Handle<Expression> {
        self.add(Expression::AccessIndex { base, index }, span)
    }

    pub(crate) fn binop(
        &mut self,
        op: naga::BinaryOperator,
        left: Handle<Expression>,
        right: Handle<Expression>,
        span: Span,
    ) -> Handle<Expression> {
        self.add(Expression::Binary { op, left, right }, span)
    }

    pub(crate) fn math(
        &mut self,
        fun: naga::MathFunction,
        args: &[Handle<Expression>],
        span: Span,
    ) -> Handle<Expression> {
        self.add(
            Expression::Math {
                fun,
                arg: args[0],
                arg1: args.get(1).copied(),
                arg2: args.get(2).copied(),
                arg3: args.get(3).copied(),
            },
            span,
        )
    }

    pub(crate) fn cast(
        &mut self,
        v: Handle<Expression>,
        kind: naga::ScalarKind,
        span: Span,
    ) -> Handle<Expression> {
        let convert = if kind == naga::ScalarKind::Bool {
            Some(naga::BOOL_WIDTH)
        } else {
            Some(4)
        };
        self.add(
            Expression::As {
                expr: v,
                kind,
                convert,
            },
            span,
        )
    }

    pub(crate) fn stage(&self) -> Stage {
        self.cx.stage
    }

    // ----- statements -----

    fn stmts(&mut self, stmts: &[Stmt]) -> Result<(), LowerError> {
        for s in stmts {
            if self.stmt(s)? {
                // Code after a return, discard, break or continue in the same block is dead.
                break;
            }
        }
        Ok(())
    }

    /// Lowers a statement; returns whether it ends the block's control flow.
    fn stmt(&mut self, s: &Stmt) -> Result<bool, LowerError> {
        match &s.kind {
            StmtKind::Expr(e) => {
                self.effect(e)?;
            }
            StmtKind::Local(l, init) => {
                let local = self.local_handle(*l);
                if let Some(e) = init {
                    let v = self.expr(e)?;
                    let p = self.add(Expression::LocalVariable(local), s.span);
                    self.push(
                        Statement::Store {
                            pointer: p,
                            value: v,
                        },
                        s.span,
                    );
                }
            }
            StmtKind::Block(b) => {
                let block = self.block_of(b)?;
                self.push(Statement::Block(block), s.span);
            }
            StmtKind::If(c, t, e) => {
                if let Some(b) = const_bool(c) {
                    let chosen = if b { t } else { e };
                    let block = self.block_of(chosen)?;
                    self.push(Statement::Block(block), s.span);
                    return Ok(false);
                }
                let cond = self.expr(c)?;
                let accept = self.block_of(t)?;
                let reject = self.block_of(e)?;
                self.push(
                    Statement::If {
                        condition: cond,
                        accept,
                        reject,
                    },
                    s.span,
                );
            }
            StmtKind::Loop {
                init,
                cond,
                step,
                body,
                do_while,
            } => {
                for st in init {
                    if self.stmt(st)? {
                        return Ok(true);
                    }
                }
                let cond = cond.clone();
                let body_block = self.capture(|fx| {
                    if !do_while {
                        if let Some(c) = &cond {
                            let v = fx.loop_cond(c)?;
                            let not = fx.add(
                                Expression::Unary {
                                    op: naga::UnaryOperator::LogicalNot,
                                    expr: v,
                                },
                                s.span,
                            );
                            fx.push(
                                Statement::If {
                                    condition: not,
                                    accept: naga::Block::from_vec(vec![Statement::Break]),
                                    reject: naga::Block::new(),
                                },
                                s.span,
                            );
                        }
                    }
                    fx.stmts(body)
                })?;
                let mut break_if = None;
                let continuing = self.capture(|fx| {
                    if let Some(st) = step {
                        fx.effect(st)?;
                    }
                    if *do_while {
                        if let Some(c) = &cond {
                            let v = fx.loop_cond(c)?;
                            let not = fx.add(
                                Expression::Unary {
                                    op: naga::UnaryOperator::LogicalNot,
                                    expr: v,
                                },
                                s.span,
                            );
                            break_if = Some(not);
                        }
                    }
                    Ok(())
                })?;
                self.push(
                    Statement::Loop {
                        body: body_block,
                        continuing,
                        break_if,
                    },
                    s.span,
                );
            }
            StmtKind::Switch(sel, cases) => {
                let selector = self.expr(sel)?;
                let unsigned = sel.ty == Type::UINT;
                let mut ncases = Vec::new();
                let mut has_default = false;
                for (i, c) in cases.iter().enumerate() {
                    // A case with statements that falls through gets the statements of the
                    // cases it falls into, up to one that does not fall through: WGSL has no
                    // fall-through (an empty case that falls through shares the next one's
                    // body in every target). Each copy is lowered anew, with its own
                    // expressions.
                    let copies = c.fall_through && !c.body.is_empty();
                    let body = if copies {
                        let mut stmts = c.body.clone();
                        for next in &cases[i + 1..] {
                            stmts.extend(next.body.iter().cloned());
                            if !next.fall_through {
                                break;
                            }
                        }
                        self.block_of(&stmts)?
                    } else {
                        self.block_of(&c.body)?
                    };
                    let value = match c.value {
                        None => {
                            has_default = true;
                            naga::SwitchValue::Default
                        }
                        Some(v) if unsigned => naga::SwitchValue::U32(v as u32),
                        Some(v) => naga::SwitchValue::I32(v as i32),
                    };
                    ncases.push(naga::SwitchCase {
                        value,
                        body,
                        fall_through: c.fall_through && !copies,
                    });
                }
                if let Some(last) = ncases.last_mut() {
                    last.fall_through = false;
                }
                if !has_default {
                    ncases.push(naga::SwitchCase {
                        value: naga::SwitchValue::Default,
                        body: naga::Block::new(),
                        fall_through: false,
                    });
                }
                self.push(
                    Statement::Switch {
                        selector,
                        cases: ncases,
                    },
                    s.span,
                );
            }
            StmtKind::Break => {
                self.push(Statement::Break, s.span);
                return Ok(true);
            }
            StmtKind::Continue => {
                self.push(Statement::Continue, s.span);
                return Ok(true);
            }
            StmtKind::Return(v) => {
                let value = match v {
                    Some(e) => Some(self.expr(e)?),
                    None => None,
                };
                self.push(Statement::Return { value }, s.span);
                return Ok(true);
            }
            StmtKind::Discard => {
                self.push(Statement::Kill, s.span);
                return Ok(true);
            }
        }
        Ok(false)
    }

    fn loop_cond(&mut self, c: &hir::Cond) -> Result<Handle<Expression>, LowerError> {
        match c {
            hir::Cond::Expr(e) => self.expr(e),
            hir::Cond::Decl(l, init) => {
                let v = self.expr(init)?;
                let local = self.local_handle(*l);
                let p = self.add(Expression::LocalVariable(local), init.span);
                self.push(
                    Statement::Store {
                        pointer: p,
                        value: v,
                    },
                    init.span,
                );
                Ok(v)
            }
        }
    }

    fn local_handle(&mut self, l: usize) -> Handle<naga::LocalVariable> {
        if let Some(h) = self.locals[l] {
            return h;
        }
        let local = &self.hir_fn.expect("in a function").locals[l];
        let (name, ty) = (local.name.to_string(), local.ty.clone());
        let h = self.new_local(&name, &ty);
        self.locals[l] = Some(h);
        h
    }

    // ----- expressions evaluated for effects -----

    fn effect(&mut self, e: &Expr) -> Result<(), LowerError> {
        match &e.kind {
            ExprKind::Comma(a, b) => {
                self.effect(a)?;
                self.effect(b)
            }
            ExprKind::Const(_)
            | ExprKind::Local(_)
            | ExprKind::Global(_)
            | ExprKind::Param(_)
            | ExprKind::BuiltinVar(_) => Ok(()),
            _ => self.expr(e).map(|_| ()),
        }
    }

    // ----- places -----

    /// A pointer to what `e` names, if it is a variable or a part of one.
    fn place(&mut self, e: &Expr) -> Result<Option<Place>, LowerError> {
        let span = e.span;
        Ok(Some(match &e.kind {
            ExprKind::Local(l) => {
                let h = self.local_handle(*l);
                Place {
                    ptr: self.add(Expression::LocalVariable(h), span),
                    repr: Repr::Same,
                    ty: e.ty.clone(),
                }
            }
            ExprKind::Param(i) => match self.params[*i] {
                ParamLower::Local(h) => Place {
                    ptr: self.add(Expression::LocalVariable(h), span),
                    repr: Repr::Same,
                    ty: e.ty.clone(),
                },
                ParamLower::Pointer(a) => Place {
                    ptr: self.add(Expression::FunctionArgument(a), span),
                    repr: Repr::Same,
                    ty: e.ty.clone(),
                },
                ParamLower::Sampler(..) => return Ok(None),
            },
            ExprKind::Global(g) => match self.cx.globals[*g].clone() {
                GlobalLower::Private(h) => Place {
                    ptr: self.add(Expression::GlobalVariable(h), span),
                    repr: Repr::Same,
                    ty: e.ty.clone(),
                },
                GlobalLower::Uniform {
                    block,
                    member,
                    repr,
                }
                | GlobalLower::BlockMember {
                    block,
                    member,
                    repr,
                } => {
                    let b = self.add(Expression::GlobalVariable(block), span);
                    Place {
                        ptr: self.access_index(b, member, span),
                        repr,
                        ty: e.ty.clone(),
                    }
                }
                GlobalLower::None => return Ok(None),
            },
            ExprKind::BuiltinVar(v) => {
                if *v == BuiltinVar::DepthRange {
                    return Ok(None);
                }
                let h = match self.cx.builtins.get(v) {
                    Some(h) => *h,
                    None => {
                        let ty = self.cx.types.logical(&mut self.cx.module, &v.ty());
                        let h = self.cx.private(v.name(), ty, None);
                        self.cx.builtins.insert(*v, h);
                        h
                    }
                };
                Place {
                    ptr: self.add(Expression::GlobalVariable(h), span),
                    repr: Repr::Same,
                    ty: e.ty.clone(),
                }
            }
            ExprKind::BlockMember(b, idx, m) => {
                let Some((gv, reprs)) = self.cx.blocks[*b].clone() else {
                    return Ok(None);
                };
                let mut base = self.add(Expression::GlobalVariable(gv), span);
                if let Some(i) = idx {
                    let iv = self.expr(i)?;
                    base = self.add(Expression::Access { base, index: iv }, span);
                }
                Place {
                    ptr: self.access_index(base, *m as u32, span),
                    repr: reprs[*m].clone(),
                    ty: e.ty.clone(),
                }
            }
            ExprKind::Index(b, i) => {
                let Some(base) = self.place(b)? else {
                    return Ok(None);
                };
                let repr = base.repr.index();
                let ptr = match i.as_const().and_then(|c| c.as_int()) {
                    Some(k) => self.access_index(base.ptr, k as u32, span),
                    None => {
                        let iv = self.expr(i)?;
                        self.add(
                            Expression::Access {
                                base: base.ptr,
                                index: iv,
                            },
                            span,
                        )
                    }
                };
                // A padded element: its value is the struct's only member.
                let (ptr, repr) = match repr {
                    Repr::Padded(inner) => (self.access_index(ptr, 0, span), *inner),
                    r => (ptr, r),
                };
                Place {
                    ptr,
                    repr,
                    ty: e.ty.clone(),
                }
            }
            ExprKind::Member(b, m) => {
                let Some(base) = self.place(b)? else {
                    return Ok(None);
                };
                let (index, repr) = match &base.repr {
                    Repr::Struct(members) => match &members[*m] {
                        Some((si, r)) => (*si, r.clone()),
                        None => return Ok(None),
                    },
                    _ => (*m as u32, Repr::Same),
                };
                Place {
                    ptr: self.access_index(base.ptr, index, span),
                    repr,
                    ty: e.ty.clone(),
                }
            }
            _ => return Ok(None),
        }))
    }

    /// Loads a place, converting from its stored form.
    fn load(&mut self, p: &Place, span: Span) -> Handle<Expression> {
        let v = self.add(Expression::Load { pointer: p.ptr }, span);
        self.convert(v, &p.repr, &p.ty, span)
    }

    /// Converts a value read from a uniform buffer to its GLSL type.
    fn convert(
        &mut self,
        v: Handle<Expression>,
        repr: &Repr,
        ty: &Type,
        span: Span,
    ) -> Handle<Expression> {
        match repr {
            Repr::Same => v,
            Repr::Bool(size) => {
                let zero = self.lit(Literal::U32(0));
                let zero = match size {
                    Some(s) => self.add(
                        Expression::Splat {
                            size: *s,
                            value: zero,
                        },
                        span,
                    ),
                    None => zero,
                };
                self.binop(naga::BinaryOperator::NotEqual, v, zero, span)
            }
            Repr::Columns { cols, .. } => {
                let comps = (0..*cols as u32)
                    .map(|i| {
                        let padded = self.access_index(v, i, span);
                        self.access_index(padded, 0, span)
                    })
                    .collect();
                self.compose(ty, comps, span)
            }
            Repr::Padded(inner) => {
                let x = self.access_index(v, 0, span);
                self.convert(x, inner, ty, span)
            }
            Repr::Array(el) => {
                let Type::Array(elty, n) = ty else { return v };
                let comps = (0..*n).map(|i| {
                    let x = self.access_index(v, i, span);
                    self.convert(x, el, elty, span)
                });
                let comps: Vec<_> = comps.collect();
                self.compose(ty, comps, span)
            }
            Repr::Struct(members) => {
                let Type::Struct(id) = ty else { return v };
                let mtys: Vec<Type> = self.cx.hir.structs[id.0 as usize]
                    .members
                    .iter()
                    .map(|m| m.ty.clone())
                    .collect();
                let mut comps = Vec::new();
                for (m, mty) in members.iter().zip(&mtys) {
                    comps.push(match m {
                        Some((si, r)) => {
                            let x = self.access_index(v, *si, span);
                            self.convert(x, r, mty, span)
                        }
                        None => {
                            let t = self.cx.types.logical(&mut self.cx.module, mty);
                            self.add(Expression::ZeroValue(t), span)
                        }
                    });
                }
                self.compose(ty, comps, span)
            }
        }
    }

    fn lvalue(&mut self, e: &Expr) -> Result<LValue, LowerError> {
        if let ExprKind::Swizzle(b, comps) = &e.kind {
            let Some(base) = self.place(b)? else {
                return Ok(LValue::Nowhere);
            };
            if comps.len() == 1 {
                let ptr = self.access_index(base.ptr, comps[0] as u32, e.span);
                return Ok(LValue::Place(Place {
                    ptr,
                    repr: Repr::Same,
                    ty: e.ty.clone(),
                }));
            }
            return Ok(LValue::Swizzle(base, comps.clone()));
        }
        Ok(match self.place(e)? {
            Some(p) => LValue::Place(p),
            None => LValue::Nowhere,
        })
    }

    fn load_lvalue(&mut self, lv: &LValue, ty: &Type, span: Span) -> Handle<Expression> {
        match lv {
            LValue::Place(p) => self.load(p, span),
            LValue::Swizzle(p, comps) => {
                let v = self.load(p, span);
                self.swizzle(v, comps, span)
            }
            LValue::Nowhere => self.zero(ty),
        }
    }

    fn store(&mut self, lv: &LValue, value: Handle<Expression>, span: Span) {
        match lv {
            LValue::Place(p) => self.push(
                Statement::Store {
                    pointer: p.ptr,
                    value,
                },
                span,
            ),
            LValue::Swizzle(p, comps) => {
                let old = self.load(p, span);
                let Type::Vector(_, n) = p.ty else { return };
                let mut parts = Vec::new();
                for i in 0..n {
                    parts.push(match comps.iter().position(|c| *c == i) {
                        Some(k) => self.access_index(value, k as u32, span),
                        None => self.access_index(old, i as u32, span),
                    });
                }
                let ty = p.ty.clone();
                let v = self.compose(&ty, parts, span);
                self.push(
                    Statement::Store {
                        pointer: p.ptr,
                        value: v,
                    },
                    span,
                );
            }
            LValue::Nowhere => {}
        }
    }

    /// Stores a value into the l-value `target` (for `out` parameters of built-ins).
    pub(crate) fn store_to(
        &mut self,
        target: &Expr,
        value: Handle<Expression>,
        span: Span,
    ) -> Result<(), LowerError> {
        let lv = self.lvalue(target)?;
        self.store(&lv, value, span);
        Ok(())
    }

    pub(crate) fn swizzle(
        &mut self,
        v: Handle<Expression>,
        comps: &[u8],
        span: Span,
    ) -> Handle<Expression> {
        if comps.len() == 1 {
            return self.access_index(v, comps[0] as u32, span);
        }
        let mut pattern = [naga::SwizzleComponent::X; 4];
        for (i, c) in comps.iter().enumerate() {
            pattern[i] = match c {
                0 => naga::SwizzleComponent::X,
                1 => naga::SwizzleComponent::Y,
                2 => naga::SwizzleComponent::Z,
                _ => naga::SwizzleComponent::W,
            };
        }
        self.add(
            Expression::Swizzle {
                size: vsize(comps.len() as u8),
                vector: v,
                pattern,
            },
            span,
        )
    }

    // ----- expressions -----

    /// Lowers an expression to a value.
    pub(crate) fn expr(&mut self, e: &Expr) -> Result<Handle<Expression>, LowerError> {
        let span = e.span;
        Ok(match &e.kind {
            ExprKind::Const(c) => self.constant(c, &e.ty, span),
            ExprKind::Local(_)
            | ExprKind::Param(_)
            | ExprKind::Global(_)
            | ExprKind::BuiltinVar(_)
            | ExprKind::BlockMember(..)
            | ExprKind::Member(..)
            | ExprKind::Index(..) => match self.place(e)? {
                Some(p) => self.load(&p, span),
                None => self.value_access(e)?,
            },
            ExprKind::Swizzle(b, comps) => {
                let v = self.expr(b)?;
                self.swizzle(v, comps, span)
            }
            ExprKind::Unary(op, a) => {
                let v = self.expr(a)?;
                match op {
                    hir::UnaryOp::Not => self.add(
                        Expression::Unary {
                            op: naga::UnaryOperator::LogicalNot,
                            expr: v,
                        },
                        span,
                    ),
                    hir::UnaryOp::BitNot => self.add(
                        Expression::Unary {
                            op: naga::UnaryOperator::BitwiseNot,
                            expr: v,
                        },
                        span,
                    ),
                    hir::UnaryOp::Neg => self.negate(v, &a.ty, span),
                }
            }
            ExprKind::Binary(op, a, b) => self.binary(*op, a, b, &e.ty, span)?,
            ExprKind::Assign(op, l, r) => {
                let lv = self.lvalue(l)?;
                let value = match op {
                    None => self.expr(r)?,
                    Some(o) if int_zero_divisor(*o, r) => self.zero(&e.ty),
                    Some(o) => {
                        let old = self.load_lvalue(&lv, &l.ty, span);
                        let rv = self.expr(r)?;
                        self.arith(*o, old, &l.ty, rv, &r.ty, &e.ty, span)?
                    }
                };
                self.store(&lv, value, span);
                value
            }
            ExprKind::IncDec(inc, pre, t) => {
                let lv = self.lvalue(t)?;
                let old = self.load_lvalue(&lv, &t.ty, span);
                let one = self.one_like(&t.ty, span);
                let op = if *inc { BinaryOp::Add } else { BinaryOp::Sub };
                let new = self.arith(op, old, &t.ty, one, &t.ty, &t.ty, span)?;
                self.store(&lv, new, span);
                if *pre {
                    new
                } else {
                    old
                }
            }
            ExprKind::Select(c, a, b) => {
                let simple = (a.ty.is_scalar_or_vector()) && !has_effects(a) && !has_effects(b);
                if simple {
                    let cv = self.expr(c)?;
                    let av = self.expr(a)?;
                    let bv = self.expr(b)?;
                    self.add(
                        Expression::Select {
                            condition: cv,
                            accept: av,
                            reject: bv,
                        },
                        span,
                    )
                } else {
                    let tmp = self.new_local("_essl_select", &e.ty);
                    let cv = self.expr(c)?;
                    let accept = self.capture(|fx| {
                        let v = fx.expr(a)?;
                        let p = fx.add(Expression::LocalVariable(tmp), span);
                        fx.push(
                            Statement::Store {
                                pointer: p,
                                value: v,
                            },
                            span,
                        );
                        Ok(())
                    })?;
                    let reject = self.capture(|fx| {
                        let v = fx.expr(b)?;
                        let p = fx.add(Expression::LocalVariable(tmp), span);
                        fx.push(
                            Statement::Store {
                                pointer: p,
                                value: v,
                            },
                            span,
                        );
                        Ok(())
                    })?;
                    self.push(
                        Statement::If {
                            condition: cv,
                            accept,
                            reject,
                        },
                        span,
                    );
                    let p = self.add(Expression::LocalVariable(tmp), span);
                    self.add(Expression::Load { pointer: p }, span)
                }
            }
            ExprKind::Comma(a, b) => {
                self.effect(a)?;
                self.expr(b)?
            }
            ExprKind::Call(f, args) => self.call(*f, args, &e.ty, span)?,
            ExprKind::Builtin(op, args) => self.builtin(*op, args, &e.ty, span)?,
            ExprKind::Construct(args) => self.construct(&e.ty, args, span)?,
        })
    }

    /// `x[i]`, `s.m` on values that are not variables (function results, constructors), and
    /// reads of variables that are not lowered (dead code: a zero value).
    fn value_access(&mut self, e: &Expr) -> Result<Handle<Expression>, LowerError> {
        let span = e.span;
        match &e.kind {
            ExprKind::Index(b, i) => {
                let base_is_var = self.is_unlowered_variable(b);
                if base_is_var {
                    return Ok(self.zero(&e.ty));
                }
                let bv = self.expr(b)?;
                if let Some(k) = i.as_const().and_then(|c| c.as_int()) {
                    return Ok(self.access_index(bv, k as u32, span));
                }
                let iv = self.expr(i)?;
                if matches!(b.ty, Type::Matrix { .. } | Type::Array(..)) {
                    // A dynamic index into a matrix (or array) value goes through a variable.
                    let tmp = self.new_local("_essl_index", &b.ty);
                    let p = self.add(Expression::LocalVariable(tmp), span);
                    self.push(
                        Statement::Store {
                            pointer: p,
                            value: bv,
                        },
                        span,
                    );
                    let ep = self.add(Expression::Access { base: p, index: iv }, span);
                    return Ok(self.add(Expression::Load { pointer: ep }, span));
                }
                Ok(self.add(
                    Expression::Access {
                        base: bv,
                        index: iv,
                    },
                    span,
                ))
            }
            ExprKind::Member(b, m) => {
                if self.is_unlowered_variable(b) {
                    return Ok(self.zero(&e.ty));
                }
                let bv = self.expr(b)?;
                if let ExprKind::BuiltinVar(BuiltinVar::DepthRange) = b.kind {
                    return Ok(bv);
                }
                Ok(self.access_index(bv, *m as u32, span))
            }
            ExprKind::BuiltinVar(BuiltinVar::DepthRange) => {
                // WebGL's default depth range: near 0, far 1, diff 1.
                let c = ConstValue::Composite(vec![
                    ConstValue::Basic(vec![Scalar::F(0.0)]),
                    ConstValue::Basic(vec![Scalar::F(1.0)]),
                    ConstValue::Basic(vec![Scalar::F(1.0)]),
                ]);
                Ok(self.constant(&c, &e.ty, span))
            }
            _ => Ok(self.zero(&e.ty)),
        }
    }

    /// Whether an expression is (part of) a variable the lowering left out.
    fn is_unlowered_variable(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Global(g) => matches!(self.cx.globals[*g], GlobalLower::None),
            ExprKind::Index(b, _) | ExprKind::Member(b, _) => self.is_unlowered_variable(b),
            _ => false,
        }
    }

    pub(crate) fn constant(&mut self, c: &ConstValue, ty: &Type, span: Span) -> Handle<Expression> {
        if !all_finite(c) {
            return self.runtime_constant(c, ty, span);
        }
        match (c, ty) {
            (ConstValue::Basic(v), Type::Scalar(_)) => {
                self.add(Expression::Literal(literal(v[0])), span)
            }
            _ => {
                let init = global_constant(self.cx, c, ty);
                let nty = self.ty(ty);
                let h = self.cx.module.constants.append(
                    naga::Constant {
                        name: None,
                        ty: nty,
                        init,
                    },
                    NSpan::UNDEFINED,
                );
                self.add(Expression::Constant(h), span)
            }
        }
    }

    /// A constant holding an infinity or NaN, which naga literals cannot: built at run time
    /// from the float's bits.
    fn runtime_constant(&mut self, c: &ConstValue, ty: &Type, span: Span) -> Handle<Expression> {
        match (c, ty) {
            (ConstValue::Basic(v), Type::Scalar(_)) => match v[0] {
                Scalar::F(f) if !f.is_finite() => {
                    let bits = self.lit(Literal::U32(f.to_bits()));
                    self.add(
                        Expression::As {
                            expr: bits,
                            kind: naga::ScalarKind::Float,
                            convert: None,
                        },
                        span,
                    )
                }
                s => self.add(Expression::Literal(literal(s)), span),
            },
            (ConstValue::Basic(v), Type::Vector(k, _)) => {
                let parts: Vec<_> = v
                    .iter()
                    .map(|s| {
                        self.runtime_constant(&ConstValue::Basic(vec![*s]), &Type::Scalar(*k), span)
                    })
                    .collect();
                self.compose(ty, parts, span)
            }
            (ConstValue::Basic(v), Type::Matrix { cols, rows }) => {
                let col_ty = Type::Vector(ScalarKind::Float, *rows);
                let parts: Vec<_> = (0..*cols as usize)
                    .map(|c| {
                        self.runtime_constant(
                            &ConstValue::Basic(
                                v[c * *rows as usize..(c + 1) * *rows as usize].to_vec(),
                            ),
                            &col_ty,
                            span,
                        )
                    })
                    .collect();
                self.compose(ty, parts, span)
            }
            (ConstValue::Composite(elems), Type::Array(el, _)) => {
                let el = (**el).clone();
                let parts: Vec<_> = elems
                    .iter()
                    .map(|e| self.runtime_constant(e, &el, span))
                    .collect();
                self.compose(ty, parts, span)
            }
            (ConstValue::Composite(members), Type::Struct(id)) => {
                let mtys: Vec<Type> = self.cx.hir.structs[id.0 as usize]
                    .members
                    .iter()
                    .map(|m| m.ty.clone())
                    .collect();
                let parts: Vec<_> = members
                    .iter()
                    .zip(&mtys)
                    .map(|(e, t)| self.runtime_constant(e, t, span))
                    .collect();
                self.compose(ty, parts, span)
            }
            _ => self.zero(ty),
        }
    }

    fn one_like(&mut self, ty: &Type, span: Span) -> Handle<Expression> {
        let one = match ty.scalar_kind() {
            Some(ScalarKind::Int) => Literal::I32(1),
            Some(ScalarKind::Uint) => Literal::U32(1),
            _ => Literal::F32(1.0),
        };
        let o = self.lit(one);
        match ty {
            Type::Vector(_, n) => self.splat(o, *n, span),
            Type::Matrix { cols, rows } => {
                let col = self.splat(o, *rows, span);
                let cols = vec![col; *cols as usize];
                self.compose(ty, cols, span)
            }
            _ => o,
        }
    }

    fn negate(&mut self, v: Handle<Expression>, ty: &Type, span: Span) -> Handle<Expression> {
        match ty {
            Type::Matrix { cols, rows } => {
                let col_ty = Type::Vector(ScalarKind::Float, *rows);
                let parts: Vec<_> = (0..*cols as u32)
                    .map(|i| {
                        let c = self.access_index(v, i, span);
                        self.negate(c, &col_ty, span)
                    })
                    .collect();
                self.compose(ty, parts, span)
            }
            t if t.scalar_kind() == Some(ScalarKind::Uint) => {
                let zero = self.zero(t);
                self.binop(naga::BinaryOperator::Subtract, zero, v, span)
            }
            _ => self.add(
                Expression::Unary {
                    op: naga::UnaryOperator::Negate,
                    expr: v,
                },
                span,
            ),
        }
    }

    fn binary(
        &mut self,
        op: BinaryOp,
        a: &Expr,
        b: &Expr,
        rt: &Type,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        use naga::BinaryOperator as Bo;
        match op {
            BinaryOp::And | BinaryOp::Or if has_effects(b) => {
                // Short-circuit: evaluate `b` only when needed.
                let tmp = self.new_local("_essl_logic", &Type::BOOL);
                let av = self.expr(a)?;
                let p = self.add(Expression::LocalVariable(tmp), span);
                self.push(
                    Statement::Store {
                        pointer: p,
                        value: av,
                    },
                    span,
                );
                let eval_b = self.capture(|fx| {
                    let bv = fx.expr(b)?;
                    let p = fx.add(Expression::LocalVariable(tmp), span);
                    fx.push(
                        Statement::Store {
                            pointer: p,
                            value: bv,
                        },
                        span,
                    );
                    Ok(())
                })?;
                let (accept, reject) = if op == BinaryOp::And {
                    (eval_b, naga::Block::new())
                } else {
                    (naga::Block::new(), eval_b)
                };
                self.push(
                    Statement::If {
                        condition: av,
                        accept,
                        reject,
                    },
                    span,
                );
                let p = self.add(Expression::LocalVariable(tmp), span);
                Ok(self.add(Expression::Load { pointer: p }, span))
            }
            BinaryOp::And | BinaryOp::Or | BinaryOp::Xor => {
                let av = self.expr(a)?;
                let bv = self.expr(b)?;
                let o = match op {
                    BinaryOp::And => Bo::LogicalAnd,
                    BinaryOp::Or => Bo::LogicalOr,
                    _ => Bo::NotEqual,
                };
                Ok(self.binop(o, av, bv, span))
            }
            BinaryOp::Eq | BinaryOp::NotEq => {
                let av = self.expr(a)?;
                let bv = self.expr(b)?;
                let eq = self.equal(av, bv, &a.ty, span);
                Ok(if op == BinaryOp::Eq {
                    eq
                } else {
                    self.add(
                        Expression::Unary {
                            op: naga::UnaryOperator::LogicalNot,
                            expr: eq,
                        },
                        span,
                    )
                })
            }
            BinaryOp::Less | BinaryOp::Greater | BinaryOp::LessEq | BinaryOp::GreaterEq => {
                let av = self.expr(a)?;
                let bv = self.expr(b)?;
                let o = match op {
                    BinaryOp::Less => Bo::Less,
                    BinaryOp::Greater => Bo::Greater,
                    BinaryOp::LessEq => Bo::LessEqual,
                    _ => Bo::GreaterEqual,
                };
                Ok(self.binop(o, av, bv, span))
            }
            _ => {
                let av = self.expr(a)?;
                if int_zero_divisor(op, b) {
                    // Undefined in GLSL (the checker warned); naga rejects it outright.
                    return Ok(self.zero(rt));
                }
                let bv = self.expr(b)?;
                self.arith(op, av, &a.ty, bv, &b.ty, rt, span)
            }
        }
    }

    /// Deep equality of two values of the same type, as one `bool`.
    fn equal(
        &mut self,
        a: Handle<Expression>,
        b: Handle<Expression>,
        ty: &Type,
        span: Span,
    ) -> Handle<Expression> {
        use naga::BinaryOperator as Bo;
        match ty {
            Type::Scalar(_) => self.binop(Bo::Equal, a, b, span),
            Type::Vector(..) => {
                let v = self.binop(Bo::Equal, a, b, span);
                self.add(
                    Expression::Relational {
                        fun: naga::RelationalFunction::All,
                        argument: v,
                    },
                    span,
                )
            }
            Type::Matrix { cols, rows } => {
                let col = Type::Vector(ScalarKind::Float, *rows);
                self.fold_and(*cols as u32, a, b, &col, span)
            }
            Type::Array(el, n) => {
                let el = (**el).clone();
                self.fold_and(*n, a, b, &el, span)
            }
            Type::Struct(id) => {
                let mtys: Vec<Type> = self.cx.hir.structs[id.0 as usize]
                    .members
                    .iter()
                    .map(|m| m.ty.clone())
                    .collect();
                let mut acc: Option<Handle<Expression>> = None;
                for (i, t) in mtys.iter().enumerate() {
                    let x = self.access_index(a, i as u32, span);
                    let y = self.access_index(b, i as u32, span);
                    let e = self.equal(x, y, t, span);
                    acc = Some(match acc {
                        Some(p) => self.binop(Bo::LogicalAnd, p, e, span),
                        None => e,
                    });
                }
                acc.unwrap_or_else(|| self.lit(Literal::Bool(true)))
            }
            _ => self.lit(Literal::Bool(false)),
        }
    }

    fn fold_and(
        &mut self,
        n: u32,
        a: Handle<Expression>,
        b: Handle<Expression>,
        el: &Type,
        span: Span,
    ) -> Handle<Expression> {
        let mut acc: Option<Handle<Expression>> = None;
        for i in 0..n {
            let x = self.access_index(a, i, span);
            let y = self.access_index(b, i, span);
            let e = self.equal(x, y, el, span);
            acc = Some(match acc {
                Some(p) => self.binop(naga::BinaryOperator::LogicalAnd, p, e, span),
                None => e,
            });
        }
        acc.unwrap_or_else(|| self.lit(Literal::Bool(true)))
    }

    /// Arithmetic and bitwise operators with GLSL's scalar/vector/matrix mixing.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn arith(
        &mut self,
        op: BinaryOp,
        a: Handle<Expression>,
        at: &Type,
        b: Handle<Expression>,
        bt: &Type,
        rt: &Type,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        use naga::BinaryOperator as Bo;
        let nop = match op {
            BinaryOp::Add => Bo::Add,
            BinaryOp::Sub => Bo::Subtract,
            BinaryOp::Mul => Bo::Multiply,
            BinaryOp::Div => Bo::Divide,
            BinaryOp::Mod => Bo::Modulo,
            BinaryOp::BitAnd => Bo::And,
            BinaryOp::BitOr => Bo::InclusiveOr,
            BinaryOp::BitXor => Bo::ExclusiveOr,
            BinaryOp::Shl => Bo::ShiftLeft,
            BinaryOp::Shr => Bo::ShiftRight,
            _ => {
                return Err(unsupported(
                    format!("operator `{}` here", op.as_str()),
                    span,
                ))
            }
        };
        // Shifts: the amount is unsigned, and a vector when the value is. It is taken modulo 32:
        // GLSL leaves a shift by 32 or more undefined (Chromium compiles `3 >> 40u` with a
        // warning), and naga rejects a constant one.
        if matches!(op, BinaryOp::Shl | BinaryOp::Shr) {
            let mut amount = b;
            if bt.scalar_kind() == Some(ScalarKind::Int) {
                amount = self.cast(amount, naga::ScalarKind::Uint, span);
            }
            let mut mask = self.lit(naga::Literal::U32(31));
            if let Type::Vector(_, n) = bt {
                mask = self.splat(mask, *n, span);
            }
            amount = self.binop(Bo::And, amount, mask, span);
            if let (Type::Vector(_, n), true) = (at, bt.is_scalar()) {
                amount = self.splat(amount, *n, span);
            }
            return Ok(self.binop(nop, a, amount, span));
        }
        match (at, bt) {
            (Type::Matrix { cols, rows }, _) | (_, Type::Matrix { cols, rows })
                if matches!((at, bt), (Type::Matrix { .. }, Type::Matrix { .. }))
                    && op != BinaryOp::Mul =>
            {
                if matches!(op, BinaryOp::Add | BinaryOp::Sub) {
                    return Ok(self.binop(nop, a, b, span));
                }
                // Component-wise division of matrices: column by column.
                let col = Type::Vector(ScalarKind::Float, *rows);
                let parts: Vec<_> = (0..*cols as u32)
                    .map(|i| {
                        let x = self.access_index(a, i, span);
                        let y = self.access_index(b, i, span);
                        self.binop(nop, x, y, span)
                    })
                    .collect();
                let _ = col;
                Ok(self.compose(rt, parts, span))
            }
            (Type::Matrix { cols, rows }, Type::Scalar(_))
            | (Type::Scalar(_), Type::Matrix { cols, rows })
                if op != BinaryOp::Mul =>
            {
                let scalar_left = at.is_scalar();
                let s = if scalar_left { a } else { b };
                let m = if scalar_left { b } else { a };
                let sv = self.splat(s, *rows, span);
                let parts: Vec<_> = (0..*cols as u32)
                    .map(|i| {
                        let c = self.access_index(m, i, span);
                        if scalar_left {
                            self.binop(nop, sv, c, span)
                        } else {
                            self.binop(nop, c, sv, span)
                        }
                    })
                    .collect();
                Ok(self.compose(rt, parts, span))
            }
            (Type::Vector(_, n), Type::Scalar(_)) if op != BinaryOp::Mul => {
                let bs = self.splat(b, *n, span);
                Ok(self.binop(nop, a, bs, span))
            }
            (Type::Scalar(_), Type::Vector(_, n)) if op != BinaryOp::Mul => {
                let as_ = self.splat(a, *n, span);
                Ok(self.binop(nop, as_, b, span))
            }
            _ => Ok(self.binop(nop, a, b, span)),
        }
    }

    // ----- calls and constructors -----

    fn call(
        &mut self,
        f: FuncId,
        args: &[Expr],
        ret: &Type,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let callee = &self.cx.hir.functions[f];
        let Some(function) = self.cx.functions[f] else {
            return Err(unsupported(
                "a call to a function that was not lowered",
                span,
            ));
        };
        let mut arguments = Vec::new();
        let mut writebacks = Vec::new();
        for (arg, p) in args.iter().zip(callee.params.clone()) {
            if let Type::Sampler(_) = p.ty {
                let (img, smp) = self.sampler(arg)?;
                arguments.push(img);
                arguments.push(smp);
                continue;
            }
            match p.mode {
                ParamMode::In => arguments.push(self.expr(arg)?),
                mode => {
                    let tmp = self.new_local(&format!("_essl_{}", p.name), &p.ty);
                    let lv = self.lvalue(arg)?;
                    if mode == ParamMode::InOut {
                        let v = self.load_lvalue(&lv, &arg.ty, span);
                        let tp = self.add(Expression::LocalVariable(tmp), span);
                        self.push(
                            Statement::Store {
                                pointer: tp,
                                value: v,
                            },
                            span,
                        );
                    }
                    let tp = self.add(Expression::LocalVariable(tmp), span);
                    arguments.push(tp);
                    writebacks.push((lv, tmp));
                }
            }
        }
        self.flush_only();
        let result = if *ret != Type::Void {
            Some(
                self.f
                    .expressions
                    .append(Expression::CallResult(function), nspan(span)),
            )
        } else {
            None
        };
        self.blocks.last_mut().expect("block").push(
            Statement::Call {
                function,
                arguments,
                result,
            },
            nspan(span),
        );
        self.emitter.start(&self.f.expressions);
        for (lv, tmp) in writebacks {
            let tp = self.add(Expression::LocalVariable(tmp), span);
            let v = self.add(Expression::Load { pointer: tp }, span);
            self.store(&lv, v, span);
        }
        Ok(match result {
            Some(r) => r,
            None => self.lit(Literal::Bool(false)),
        })
    }

    /// The texture and sampler a sampler-typed expression denotes (resolved statically).
    pub(crate) fn sampler(
        &mut self,
        e: &Expr,
    ) -> Result<(Handle<Expression>, Handle<Expression>), LowerError> {
        let mut path = Vec::new();
        let mut cur = e;
        loop {
            match &cur.kind {
                ExprKind::Index(b, i) => {
                    let Some(k) = i.as_const().and_then(|c| c.as_int()) else {
                        return Err(unsupported("a sampler selected at run time", e.span));
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
                    return Ok(match self.cx.samplers.get(&(*g, path)).copied() {
                        Some((t, s)) => (
                            self.add(Expression::GlobalVariable(t), e.span),
                            self.add(Expression::GlobalVariable(s), e.span),
                        ),
                        None => return Err(unsupported("an inactive sampler", e.span)),
                    });
                }
                ExprKind::Param(i) => {
                    if let ParamLower::Sampler(t, s) = self.params[*i] {
                        if path.is_empty() {
                            return Ok((
                                self.add(Expression::FunctionArgument(t), e.span),
                                self.add(Expression::FunctionArgument(s), e.span),
                            ));
                        }
                    }
                    return Err(unsupported("a sampler inside a parameter", e.span));
                }
                _ => return Err(unsupported("this sampler expression", e.span)),
            }
        }
    }

    /// Whether every sampler an expression names is bound (not an inactive one in dead code).
    pub(crate) fn sampler_available(&self, e: &Expr) -> bool {
        let mut path = Vec::new();
        let mut cur = e;
        loop {
            match &cur.kind {
                ExprKind::Index(b, i) => {
                    let Some(k) = i.as_const().and_then(|c| c.as_int()) else {
                        return true;
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
                    return self.cx.samplers.contains_key(&(*g, path));
                }
                _ => return true,
            }
        }
    }

    fn construct(
        &mut self,
        ty: &Type,
        args: &[Expr],
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let vals: Vec<Handle<Expression>> = args
            .iter()
            .map(|a| self.expr(a))
            .collect::<Result<_, _>>()?;
        match ty {
            Type::Array(..) | Type::Struct(_) => Ok(self.compose(ty, vals, span)),
            Type::Scalar(k) => {
                let a = &args[0];
                let first = self.first_component(vals[0], &a.ty, span);
                Ok(self.convert_scalar(
                    first,
                    a.ty.scalar_kind().unwrap_or(ScalarKind::Float),
                    *k,
                    span,
                ))
            }
            Type::Vector(k, n) => {
                if args.len() == 1 && args[0].ty.is_scalar() {
                    let s = self.convert_scalar(
                        vals[0],
                        args[0].ty.scalar_kind().unwrap_or(*k),
                        *k,
                        span,
                    );
                    return Ok(self.splat(s, *n, span));
                }
                if args.len() == 1
                    && args[0].ty == Type::Vector(args[0].ty.scalar_kind().unwrap_or(*k), *n)
                {
                    return Ok(self.convert_vector(vals[0], &args[0].ty, *k, span));
                }
                let comps = self.components(&vals, args, *n as usize, *k, span);
                Ok(self.compose(ty, comps, span))
            }
            Type::Matrix { cols, rows } => {
                let (cols, rows) = (*cols, *rows);
                let col_ty = Type::Vector(ScalarKind::Float, rows);
                if args.len() == 1 && args[0].ty.is_scalar() {
                    let s = self.convert_scalar(
                        vals[0],
                        args[0].ty.scalar_kind().unwrap_or(ScalarKind::Float),
                        ScalarKind::Float,
                        span,
                    );
                    let zero = self.lit(Literal::F32(0.0));
                    let mut columns = Vec::new();
                    for c in 0..cols {
                        let comps: Vec<_> =
                            (0..rows).map(|r| if r == c { s } else { zero }).collect();
                        columns.push(self.compose(&col_ty, comps, span));
                    }
                    return Ok(self.compose(ty, columns, span));
                }
                if let (1, Type::Matrix { cols: c2, rows: r2 }) = (args.len(), &args[0].ty) {
                    let (c2, r2) = (*c2, *r2);
                    let m = vals[0];
                    let zero = self.lit(Literal::F32(0.0));
                    let one = self.lit(Literal::F32(1.0));
                    let mut columns = Vec::new();
                    for c in 0..cols {
                        if c < c2 && rows == r2 {
                            columns.push(self.access_index(m, c as u32, span));
                            continue;
                        }
                        let src = if c < c2 {
                            Some(self.access_index(m, c as u32, span))
                        } else {
                            None
                        };
                        let comps: Vec<_> = (0..rows)
                            .map(|r| match src {
                                Some(col) if r < r2 => self.access_index(col, r as u32, span),
                                _ if r == c => one,
                                _ => zero,
                            })
                            .collect();
                        columns.push(self.compose(&col_ty, comps, span));
                    }
                    return Ok(self.compose(ty, columns, span));
                }
                let comps =
                    self.components(&vals, args, (cols * rows) as usize, ScalarKind::Float, span);
                let mut columns = Vec::new();
                for c in 0..cols as usize {
                    let part = comps[c * rows as usize..(c + 1) * rows as usize].to_vec();
                    columns.push(self.compose(&col_ty, part, span));
                }
                Ok(self.compose(ty, columns, span))
            }
            _ => Err(unsupported("this constructor", span)),
        }
    }

    fn first_component(
        &mut self,
        v: Handle<Expression>,
        ty: &Type,
        span: Span,
    ) -> Handle<Expression> {
        match ty {
            Type::Vector(..) => self.access_index(v, 0, span),
            Type::Matrix { .. } => {
                let c = self.access_index(v, 0, span);
                self.access_index(c, 0, span)
            }
            _ => v,
        }
    }

    /// The first `n` scalar components of the arguments, converted to `kind`.
    fn components(
        &mut self,
        vals: &[Handle<Expression>],
        args: &[Expr],
        n: usize,
        kind: ScalarKind,
        span: Span,
    ) -> Vec<Handle<Expression>> {
        let mut out = Vec::new();
        for (v, a) in vals.iter().zip(args) {
            let from = a.ty.scalar_kind().unwrap_or(kind);
            match &a.ty {
                Type::Scalar(_) => out.push(self.convert_scalar(*v, from, kind, span)),
                Type::Vector(_, m) => {
                    for i in 0..*m {
                        if out.len() == n {
                            break;
                        }
                        let c = self.access_index(*v, i as u32, span);
                        out.push(self.convert_scalar(c, from, kind, span));
                    }
                }
                Type::Matrix { cols, rows } => {
                    for c in 0..*cols {
                        let col = self.access_index(*v, c as u32, span);
                        for r in 0..*rows {
                            if out.len() == n {
                                break;
                            }
                            let x = self.access_index(col, r as u32, span);
                            out.push(self.convert_scalar(x, from, kind, span));
                        }
                    }
                }
                _ => {}
            }
            if out.len() >= n {
                break;
            }
        }
        out.truncate(n);
        out
    }

    pub(crate) fn convert_scalar(
        &mut self,
        v: Handle<Expression>,
        from: ScalarKind,
        to: ScalarKind,
        span: Span,
    ) -> Handle<Expression> {
        if from == to {
            return v;
        }
        self.convert_kind(v, from, to, None, span)
    }

    fn convert_vector(
        &mut self,
        v: Handle<Expression>,
        from_ty: &Type,
        to: ScalarKind,
        span: Span,
    ) -> Handle<Expression> {
        let from = from_ty.scalar_kind().unwrap_or(to);
        if from == to {
            return v;
        }
        self.convert_kind(v, from, to, from_ty.vector_size(), span)
    }

    /// GLSL conversions between kinds: to bool is `!= 0`; from bool is 0/1.
    fn convert_kind(
        &mut self,
        v: Handle<Expression>,
        from: ScalarKind,
        to: ScalarKind,
        n: Option<u8>,
        span: Span,
    ) -> Handle<Expression> {
        let n = n.filter(|n| *n > 1);
        if to == ScalarKind::Bool {
            let zero = match from {
                ScalarKind::Float => Literal::F32(0.0),
                ScalarKind::Int => Literal::I32(0),
                _ => Literal::U32(0),
            };
            let z = self.lit(zero);
            let z = match n {
                Some(n) => self.splat(z, n, span),
                None => z,
            };
            return self.binop(naga::BinaryOperator::NotEqual, v, z, span);
        }
        let kind = match to {
            ScalarKind::Float => naga::ScalarKind::Float,
            ScalarKind::Int => naga::ScalarKind::Sint,
            _ => naga::ScalarKind::Uint,
        };
        if from == ScalarKind::Float && to == ScalarKind::Uint {
            // GLSL leaves negative floats to uint undefined; go through int as GPUs do.
            let i = self.cast(v, naga::ScalarKind::Sint, span);
            return self.cast(i, naga::ScalarKind::Uint, span);
        }
        self.cast(v, kind, span)
    }

    // ----- built-ins live in builtin.rs -----
}

/// Whether evaluating an expression has side effects (writes or user calls).
pub(crate) fn has_effects(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Assign(..) | ExprKind::IncDec(..) | ExprKind::Call(..) => true,
        ExprKind::Builtin(op, args) => {
            *op == crate::builtins::BuiltinFn::Modf || args.iter().any(has_effects)
        }
        ExprKind::Unary(_, a) | ExprKind::Member(a, _) | ExprKind::Swizzle(a, _) => has_effects(a),
        ExprKind::Binary(_, a, b) | ExprKind::Comma(a, b) | ExprKind::Index(a, b) => {
            has_effects(a) || has_effects(b)
        }
        ExprKind::Select(c, a, b) => has_effects(c) || has_effects(a) || has_effects(b),
        ExprKind::Construct(args) => args.iter().any(has_effects),
        ExprKind::BlockMember(_, Some(i), _) => has_effects(i),
        _ => false,
    }
}

/// Whether `op` is an integer division or remainder by a constant with a zero component.
fn int_zero_divisor(op: BinaryOp, b: &Expr) -> bool {
    matches!(op, BinaryOp::Div | BinaryOp::Mod)
        && b.as_const()
            .and_then(|c| c.scalars())
            .is_some_and(|v| v.iter().any(|s| matches!(s, Scalar::I(0) | Scalar::U(0))))
}

/// Whether a constant has only finite floats (naga literals must be finite).
pub(crate) fn all_finite(c: &ConstValue) -> bool {
    match c {
        ConstValue::Basic(v) => v
            .iter()
            .all(|s| !matches!(s, Scalar::F(f) if !f.is_finite())),
        ConstValue::Composite(v) => v.iter().all(all_finite),
    }
}

fn const_bool(e: &Expr) -> Option<bool> {
    match e.as_const()?.scalars()? {
        [Scalar::B(b)] => Some(*b),
        _ => None,
    }
}

/// IO leaves of a value: (path of struct members / array elements / matrix columns, leaf type).
fn io_leaves(ty: &Type, structs: &[crate::types::StructDef]) -> Vec<(Vec<u32>, Type)> {
    let mut out = Vec::new();
    fn walk(
        ty: &Type,
        structs: &[crate::types::StructDef],
        path: &mut Vec<u32>,
        out: &mut Vec<(Vec<u32>, Type)>,
    ) {
        match ty {
            Type::Matrix { cols, rows } => {
                for c in 0..*cols as u32 {
                    path.push(c);
                    out.push((path.clone(), Type::Vector(ScalarKind::Float, *rows)));
                    path.pop();
                }
            }
            Type::Array(el, n) => {
                for i in 0..*n {
                    path.push(i);
                    walk(el, structs, path, out);
                    path.pop();
                }
            }
            Type::Struct(id) => {
                for (i, m) in structs[id.0 as usize].members.iter().enumerate() {
                    path.push(i as u32);
                    walk(&m.ty, structs, path, out);
                    path.pop();
                }
            }
            t => out.push((path.clone(), t.clone())),
        }
    }
    walk(ty, structs, &mut Vec::new(), &mut out);
    out
}

/// The name and location binding of leaf `i` (of `count`) of an input or output `g` whose first
/// location is `location`. `varying` says whether the value travels between the stages (a
/// vertex output or a fragment input): then it is interpolated — perspective-correct, at the
/// centroid when `centroid` says so — unless it is `flat` or not a float.
fn io_binding(
    g: &hir::Global,
    centroid: bool,
    count: usize,
    i: usize,
    leaf_ty: &Type,
    location: u32,
    varying: bool,
) -> (String, naga::Binding) {
    let flat = g.interpolation == Some(crate::ast::Interpolation::Flat)
        || leaf_ty.scalar_kind() != Some(ScalarKind::Float);
    let (interpolation, sampling) = match (varying, flat) {
        (false, _) => (None, None),
        (true, true) => (Some(naga::Interpolation::Flat), None),
        (true, false) => (
            Some(naga::Interpolation::Perspective),
            Some(if centroid {
                naga::Sampling::Centroid
            } else {
                naga::Sampling::Center
            }),
        ),
    };
    let name = if count > 1 {
        format!("{}_{i}", g.name)
    } else {
        g.name.to_string()
    };
    (
        name,
        naga::Binding::Location {
            location: location + i as u32,
            interpolation,
            sampling,
            blend_src: None,
            per_primitive: false,
        },
    )
}

/// Builds the entry point that wraps the shader's `main`.
pub(crate) fn entry_point(
    cx: &mut ModuleCx,
    main: Handle<naga::Function>,
    plan: &StagePlan,
) -> Result<naga::Function, LowerError> {
    let hir = cx.hir;
    let stage = cx.stage;
    let mut fx = FnCx {
        cx,
        f: naga::Function {
            name: Some("main".into()),
            ..Default::default()
        },
        emitter: Emitter::default(),
        blocks: vec![naga::Block::new()],
        locals: Vec::new(),
        params: Vec::new(),
        hir_fn: None,
    };
    fx.emitter.start(&fx.f.expressions);
    let sp = Span::default();
    let store_private =
        |fx: &mut FnCx, var: Handle<naga::GlobalVariable>, value: Handle<Expression>| {
            let p = fx.add(Expression::GlobalVariable(var), sp);
            fx.push(Statement::Store { pointer: p, value }, sp);
        };
    // Inputs.
    for &(gi, loc) in &plan.inputs {
        let g = &hir.globals[gi];
        let GlobalLower::Private(var) = fx.cx.globals[gi] else {
            continue;
        };
        let leaves = io_leaves(&g.ty, &hir.structs);
        for (i, (path, leaf_ty)) in leaves.iter().enumerate() {
            let ty = fx.ty(leaf_ty);
            let (name, binding) = io_binding(
                g,
                g.centroid,
                leaves.len(),
                i,
                leaf_ty,
                loc,
                stage == Stage::Fragment,
            );
            let arg = fx.f.arguments.len() as u32;
            fx.f.arguments.push(naga::FunctionArgument {
                name: Some(name),
                ty,
                binding: Some(binding),
            });
            let value = fx.add(Expression::FunctionArgument(arg), sp);
            let mut p = fx.add(Expression::GlobalVariable(var), sp);
            for &k in path {
                p = fx.access_index(p, k, sp);
            }
            fx.push(Statement::Store { pointer: p, value }, sp);
        }
    }
    // Built-in inputs.
    let builtins: Vec<(BuiltinVar, Handle<naga::GlobalVariable>)> =
        fx.cx.builtins.iter().map(|(k, v)| (*k, *v)).collect();
    let mut builtins = builtins;
    builtins.sort_by_key(|(k, _)| *k);
    let mut frag_coord_arg = None;
    for &(b, var) in &builtins {
        let (builtin, ty) = match b {
            BuiltinVar::VertexId => (naga::BuiltIn::VertexIndex, Type::UINT),
            BuiltinVar::InstanceId => (naga::BuiltIn::InstanceIndex, Type::UINT),
            BuiltinVar::FragCoord => (
                naga::BuiltIn::Position { invariant: false },
                Type::Vector(ScalarKind::Float, 4),
            ),
            BuiltinVar::FrontFacing => (naga::BuiltIn::FrontFacing, Type::BOOL),
            BuiltinVar::PointCoord => (
                naga::BuiltIn::PointCoord,
                Type::Vector(ScalarKind::Float, 2),
            ),
            _ => continue,
        };
        let nty = fx.ty(&ty);
        let arg = fx.f.arguments.len() as u32;
        fx.f.arguments.push(naga::FunctionArgument {
            name: Some(b.name().into()),
            ty: nty,
            binding: Some(naga::Binding::BuiltIn(builtin)),
        });
        let mut value = fx.add(Expression::FunctionArgument(arg), sp);
        match b {
            BuiltinVar::VertexId | BuiltinVar::InstanceId => {
                value = fx.cast(value, naga::ScalarKind::Sint, sp)
            }
            BuiltinVar::FragCoord => {
                frag_coord_arg = Some(value);
                if let (true, Some((block, member))) =
                    (fx.cx.options.flip_frag_coord_y, fx.cx.fb_height)
                {
                    let bp = fx.add(Expression::GlobalVariable(block), sp);
                    let hp = fx.access_index(bp, member, sp);
                    let h = fx.add(Expression::Load { pointer: hp }, sp);
                    let x = fx.access_index(value, 0, sp);
                    let y = fx.access_index(value, 1, sp);
                    let z = fx.access_index(value, 2, sp);
                    let w = fx.access_index(value, 3, sp);
                    let fy = fx.binop(naga::BinaryOperator::Subtract, h, y, sp);
                    value = fx.compose(&Type::Vector(ScalarKind::Float, 4), vec![x, fy, z, w], sp);
                    // Named so that a translation can point at it (essl-translate's comments).
                    fx.f.named_expressions
                        .insert(value, "frag_coord_y_up".into());
                }
            }
            _ => {}
        }
        store_private(&mut fx, var, value);
    }
    // gl_FragDepth defaults to the fragment's depth.
    if let Some(&var) = fx.cx.builtins.get(&BuiltinVar::FragDepth) {
        let fc = match frag_coord_arg {
            Some(v) => v,
            None => {
                let nty = fx.ty(&Type::Vector(ScalarKind::Float, 4));
                let arg = fx.f.arguments.len() as u32;
                fx.f.arguments.push(naga::FunctionArgument {
                    name: Some("gl_FragCoord".into()),
                    ty: nty,
                    binding: Some(naga::Binding::BuiltIn(naga::BuiltIn::Position {
                        invariant: false,
                    })),
                });
                fx.add(Expression::FunctionArgument(arg), sp)
            }
        };
        let z = fx.access_index(fc, 2, sp);
        store_private(&mut fx, var, z);
    }
    // Call the shader's main.
    fx.push(
        Statement::Call {
            function: main,
            arguments: Vec::new(),
            result: None,
        },
        sp,
    );
    // Outputs.
    let mut members = Vec::new();
    let mut values = Vec::new();
    if stage == Stage::Vertex {
        let var = fx.cx.builtins[&BuiltinVar::Position];
        let p = fx.add(Expression::GlobalVariable(var), sp);
        let mut pos = fx.add(Expression::Load { pointer: p }, sp);
        if fx.cx.options.zero_to_one_depth {
            let x = fx.access_index(pos, 0, sp);
            let y = fx.access_index(pos, 1, sp);
            let z = fx.access_index(pos, 2, sp);
            let w = fx.access_index(pos, 3, sp);
            let zw = fx.binop(naga::BinaryOperator::Add, z, w, sp);
            let half = fx.lit(Literal::F32(0.5));
            let nz = fx.binop(naga::BinaryOperator::Multiply, zw, half, sp);
            pos = fx.compose(&Type::Vector(ScalarKind::Float, 4), vec![x, y, nz, w], sp);
            // Named so that a translation can point at it (essl-translate's comments).
            fx.f.named_expressions
                .insert(pos, "clip_position_depth_0_to_w".into());
        }
        let invariant = hir.invariant_all;
        let vec4 = fx.ty(&Type::Vector(ScalarKind::Float, 4));
        members.push(naga::StructMember {
            name: Some("gl_Position".into()),
            ty: vec4,
            binding: Some(naga::Binding::BuiltIn(naga::BuiltIn::Position {
                invariant,
            })),
            offset: 0,
        });
        values.push(pos);
        if let Some(&var) = fx.cx.builtins.get(&BuiltinVar::PointSize) {
            let p = fx.add(Expression::GlobalVariable(var), sp);
            let v = fx.add(Expression::Load { pointer: p }, sp);
            let f32_ty = fx.ty(&Type::FLOAT);
            members.push(naga::StructMember {
                name: Some("gl_PointSize".into()),
                ty: f32_ty,
                binding: Some(naga::Binding::BuiltIn(naga::BuiltIn::PointSize)),
                offset: 0,
            });
            values.push(v);
        }
    }
    for &(gi, loc) in &plan.outputs {
        let g = &hir.globals[gi];
        let GlobalLower::Private(var) = fx.cx.globals[gi] else {
            continue;
        };
        let leaves = io_leaves(&g.ty, &hir.structs);
        for (i, (path, leaf_ty)) in leaves.iter().enumerate() {
            let ty = fx.ty(leaf_ty);
            let mut p = fx.add(Expression::GlobalVariable(var), sp);
            for &k in path {
                p = fx.access_index(p, k, sp);
            }
            let v = fx.add(Expression::Load { pointer: p }, sp);
            let centroid = plan.output_centroid.get(&gi).copied().unwrap_or(g.centroid);
            let (name, binding) = io_binding(
                g,
                centroid,
                leaves.len(),
                i,
                leaf_ty,
                loc,
                stage == Stage::Vertex,
            );
            members.push(naga::StructMember {
                name: Some(name),
                ty,
                binding: Some(binding),
                offset: 0,
            });
            values.push(v);
        }
    }
    if stage == Stage::Fragment {
        if let Some(&var) = fx.cx.builtins.get(&BuiltinVar::FragDepth) {
            let p = fx.add(Expression::GlobalVariable(var), sp);
            let v = fx.add(Expression::Load { pointer: p }, sp);
            let f32_ty = fx.ty(&Type::FLOAT);
            members.push(naga::StructMember {
                name: Some("gl_FragDepth".into()),
                ty: f32_ty,
                binding: Some(naga::Binding::BuiltIn(naga::BuiltIn::FragDepth)),
                offset: 0,
            });
            values.push(v);
        }
    }
    if !members.is_empty() {
        // Offsets: naga wants them laid out even for IO structs.
        let mut off = 0u32;
        for m in &mut members {
            let size = fx.cx.module.types[m.ty].inner.size(fx.cx.module.to_ctx());
            let align = super::layout::naga_align(&fx.cx.module, m.ty);
            off = off.div_ceil(align) * align;
            m.offset = off;
            off += size;
        }
        let span = off.div_ceil(16) * 16;
        let out_ty = fx.cx.module.types.insert(
            naga::Type {
                name: Some(format!(
                    "_essl_{}Output",
                    if stage == Stage::Vertex {
                        "Vertex"
                    } else {
                        "Fragment"
                    }
                )),
                inner: naga::TypeInner::Struct { members, span },
            },
            NSpan::UNDEFINED,
        );
        let r = fx.add(
            Expression::Compose {
                ty: out_ty,
                components: values,
            },
            sp,
        );
        fx.push(Statement::Return { value: Some(r) }, sp);
        fx.f.result = Some(naga::FunctionResult {
            ty: out_ty,
            binding: None,
        });
    }
    fx.flush();
    let body = fx.blocks.pop().expect("body");
    let mut f = fx.f;
    f.body = body;
    Ok(f)
}
