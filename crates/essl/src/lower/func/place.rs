//! Places: pointers to variables and their parts (locals, parameters, globals, uniform
//! members, built-ins), loads and stores through them with the conversion between a value
//! and its stored form, and write targets (lvalues) including swizzles.

use naga::{Expression, Handle, Literal, Statement};

use super::{FnCx, LValue, ParamLower, Place};
use crate::builtins::BuiltinVar;
use crate::hir::{Expr, ExprKind};
use crate::lower::layout::{vsize, Repr};
use crate::lower::{GlobalLower, LowerError};
use crate::source::Span;
use crate::types::Type;

impl<'c, 'a> FnCx<'c, 'a> {
    /// A pointer to what `e` names, if it is a variable or a part of one.
    pub(super) fn place(&mut self, e: &Expr) -> Result<Option<Place>, LowerError> {
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
                ParamLower::Sampler(..) | ParamLower::Value(_) => return Ok(None),
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
                let Some((gvs, reprs)) = self.cx.blocks[*b].clone() else {
                    return Ok(None);
                };
                // The checker allows only constant indices into an array of blocks.
                let k = idx
                    .as_ref()
                    .and_then(|i| i.as_const())
                    .and_then(|c| c.as_int())
                    .unwrap_or(0);
                let gv = gvs[(k.max(0) as usize).min(gvs.len() - 1)];
                let base = self.add(Expression::GlobalVariable(gv), span);
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
    pub(super) fn load(&mut self, p: &Place, span: Span) -> Handle<Expression> {
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

    pub(super) fn lvalue(&mut self, e: &Expr) -> Result<LValue, LowerError> {
        // `(a, v) = x` of an `a` without effects, which Chromium accepts: `v` is written.
        if let ExprKind::Comma(a, b) = &e.kind {
            self.effect(a)?;
            return self.lvalue(b);
        }
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

    pub(super) fn load_lvalue(&mut self, lv: &LValue, ty: &Type, span: Span) -> Handle<Expression> {
        match lv {
            LValue::Place(p) => self.load(p, span),
            LValue::Swizzle(p, comps) => {
                let v = self.load(p, span);
                self.swizzle(v, comps, span)
            }
            LValue::Nowhere => self.zero(ty),
        }
    }

    pub(super) fn store(&mut self, lv: &LValue, value: Handle<Expression>, span: Span) {
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
}
