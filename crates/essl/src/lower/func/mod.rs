//! Function bodies: lowering one HIR function (or the entry-point wrapper) into a naga function.
//!
//! [`FnCx`] holds the state of the function being built; this module defines it, with the
//! plumbing every part shares (emitting expressions, pushing statements, nested blocks). Its
//! `impl` is deliberately spread over the submodules, one per concern: statements (`stmt`),
//! places and stores (`place`), expressions (`expr`), operators (`operators`), constructors
//! (`construct`) and the entry point (`entry`); the built-in functions are in
//! [`super::builtin`].

mod construct;
mod entry;
mod expr;
mod operators;
mod params;
mod place;
mod sampler;
mod stmt;

pub(crate) use entry::entry_point;

use naga::proc::Emitter;
use naga::{Expression, Handle, Literal, Span as NSpan, Statement};

use super::layout::{vsize, Repr};
use super::{nspan, GlobalLower, LowerError, ModuleCx};
use crate::ast::BinaryOp;
use crate::hir::{self, ConstValue, Expr, FuncId, ParamMode, Scalar, Stmt};
use crate::source::Span;
use crate::types::{ScalarKind, Type};
use crate::Stage;

/// How a HIR parameter is reached inside the lowered function.
#[derive(Clone, Copy, Debug)]
enum ParamLower {
    /// An `in` parameter copied into a local (GLSL lets functions write their parameters).
    Local(Handle<naga::LocalVariable>),
    /// An `in` parameter the body never writes: each read is its argument (an expression per
    /// read, so that each keeps its own span).
    Value(u32),
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
    /// The texture and sampler arguments of samplers inside struct and array parameters.
    param_samplers: sampler::ParamSamplers,
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
        name: Some([hir_fn.name.as_str(), "_"].concat()),
        ..Default::default()
    };
    let mut params = Vec::new();
    let mut copies = Vec::new();
    let mut sampler_args = Vec::new();
    let in_place = params::read_in_place(cx.hir, hir_fn);
    for (pi, p) in hir_fn.params.iter().enumerate() {
        match &p.ty {
            Type::Sampler(st) => {
                let (img, smp) =
                    super::sampler_types(&mut cx.module, *st, cx.options.integer_cube_as_array);
                let i = f.arguments.len() as u32;
                f.arguments.push(naga::FunctionArgument {
                    name: Some(p.name.as_str().to_owned()),
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
            t => {
                // A struct or array holding samplers: its value (samplers as placeholders), then
                // a texture and a sampler argument per sampler in it.
                for path in crate::lower::plan::sampler_paths(t, &cx.hir.structs) {
                    let Some(st) = crate::lower::plan::sampler_type_at(t, &path, &cx.hir.structs)
                    else {
                        continue;
                    };
                    sampler_args.push((params.len(), path, st));
                }
                let ty = cx.types.logical(&mut cx.module, t);
                let i = f.arguments.len() as u32;
                match p.mode {
                    ParamMode::In => {
                        f.arguments.push(naga::FunctionArgument {
                            name: Some(p.name.as_str().to_owned()),
                            ty,
                            binding: None,
                        });
                        if in_place[pi] {
                            params.push(ParamLower::Value(i));
                        } else {
                            let local = f.local_variables.append(
                                naga::LocalVariable {
                                    name: Some(p.name.as_str().to_owned()),
                                    ty,
                                    init: None,
                                },
                                nspan(p.span),
                            );
                            copies.push((i, local));
                            params.push(ParamLower::Local(local));
                        }
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
                            name: Some(p.name.as_str().to_owned()),
                            ty: ptr,
                            binding: None,
                        });
                        params.push(ParamLower::Pointer(i));
                    }
                }
            }
        }
    }
    let mut param_samplers = sampler::ParamSamplers::default();
    for (param, path, st) in sampler_args {
        let (img, smp) = super::sampler_types(&mut cx.module, st, cx.options.integer_cube_as_array);
        let i = f.arguments.len() as u32;
        let name = format!("{}_{}", hir_fn.params[param].name, i);
        f.arguments.push(naga::FunctionArgument {
            name: Some(name.clone()),
            ty: img,
            binding: None,
        });
        f.arguments.push(naga::FunctionArgument {
            name: Some(format!("{name}_sampler")),
            ty: smp,
            binding: None,
        });
        param_samplers.insert((param, path), (i, i + 1));
    }
    if hir_fn.ret != Type::Void {
        let ty = cx.types.logical(&mut cx.module, &hir_fn.ret);
        f.result = Some(naga::FunctionResult { ty, binding: None });
    }
    // About two statements per source statement (an `Emit` and the statement).
    let body = naga::Block::with_capacity(2 * (hir_fn.body.len() + copies.len()));
    let mut fx = FnCx {
        cx,
        f,
        emitter: Emitter::default(),
        blocks: vec![body],
        locals: vec![None; hir_fn.locals.len()],
        params,
        param_samplers,
        hir_fn: Some(hir_fn),
    };
    fx.emitter.start(&fx.f.expressions);
    for (arg, local) in copies {
        let a = fx.add(Expression::FunctionArgument(arg), Span::default());
        fx.store_local(local, a, Span::default());
    }
    if fx.cx.hir.entry == Some(id) {
        fx.global_initializers()?;
    }
    fx.stmts(&hir_fn.body)?;
    fx.flush();
    let body = fx.blocks.pop().expect("body");
    let mut f = fx.f;
    f.body = body;
    Ok(f)
}

impl<'c, 'a> FnCx<'c, 'a> {
    /// Stores `value` into local variable `local`; the variable's pointer.
    pub(super) fn store_local(
        &mut self,
        local: Handle<naga::LocalVariable>,
        value: Handle<Expression>,
        span: Span,
    ) -> Handle<Expression> {
        let pointer = self.add(Expression::LocalVariable(local), span);
        self.push(Statement::Store { pointer, value }, span);
        pointer
    }

    /// The initializers that the private variables could not hold, stored at the start of
    /// `main` in declaration order: those that are not constant expressions (GLSL ES 1.00 as
    /// WebGL takes it: `float f = u_zero < 0.1 ? green : 0.0;`) and constants holding an
    /// infinity or NaN.
    fn global_initializers(&mut self) -> Result<(), LowerError> {
        let m = self.cx.hir;
        for (gi, g) in m.globals.iter().enumerate() {
            let GlobalLower::Private(var) = self.cx.globals[gi] else {
                continue;
            };
            let value = match &g.init {
                Some(hir::Init::Expr(e)) => self.expr(e)?,
                Some(hir::Init::Const(c)) if !all_finite(c) => self.constant(c, &g.ty, g.span),
                _ => continue,
            };
            let pointer = self.add(Expression::GlobalVariable(var), g.span);
            self.push(Statement::Store { pointer, value }, g.span);
        }
        Ok(())
    }

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
        // About two statements per source statement (an `Emit` and the statement).
        self.blocks
            .push(naga::Block::with_capacity(2 * stmts.len()));
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
        self.new_local_at(name, t, Span::default())
    }

    /// A local declared at `span` of the source.
    pub(crate) fn new_local_at(
        &mut self,
        name: &str,
        t: &Type,
        span: Span,
    ) -> Handle<naga::LocalVariable> {
        let ty = self.ty(t);
        self.f.local_variables.append(
            naga::LocalVariable {
                name: Some(name.to_owned()),
                ty,
                init: None,
            },
            nspan(span),
        )
    }

    /// `accept` where `condition` holds, else `reject`.
    pub(crate) fn select(
        &mut self,
        condition: Handle<Expression>,
        accept: Handle<Expression>,
        reject: Handle<Expression>,
        span: Span,
    ) -> Handle<Expression> {
        self.add(
            Expression::Select {
                condition,
                accept,
                reject,
            },
            span,
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
}

/// Whether evaluating an expression has side effects (writes or user calls).
pub(crate) fn has_effects(e: &Expr) -> bool {
    e.has_effects()
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
