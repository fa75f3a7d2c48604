//! Constructors: building scalars, vectors, matrices, arrays and structs from the components
//! of their arguments, with the conversions between scalar kinds.

use naga::{Expression, Handle, Literal};

use super::FnCx;
use crate::hir::Expr;
use crate::lower::{unsupported, LowerError};
use crate::source::Span;
use crate::types::{ScalarKind, Type};

impl<'c, 'a> FnCx<'c, 'a> {
    pub(super) fn construct(
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
}
