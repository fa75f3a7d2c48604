//! Built-in functions: math, geometry, matrices, relations and derivatives, one method per
//! group of the specification; texture lookups are in `texture`.

mod cube_int;
mod texture;

use naga::{Expression, Handle, Literal, MathFunction as Mf};

use super::func::FnCx;
use super::{unsupported, LowerError};
use crate::builtins::BuiltinFn;
use crate::hir::Expr;
use crate::source::Span;
use crate::types::{ScalarKind, Type};

/// A call of a built-in function, its arguments lowered.
#[derive(Clone, Copy)]
struct Call<'e> {
    op: BuiltinFn,
    /// The arguments.
    args: &'e [Expr],
    /// Their lowered values.
    vals: &'e [Handle<Expression>],
    /// The call's type.
    ret: &'e Type,
    span: Span,
}

impl Call<'_> {
    /// The error for a built-in essl does not lower.
    fn unsupported(&self) -> LowerError {
        unsupported(format!("built-in `{}`", self.op.name()), self.span)
    }
}

impl FnCx<'_, '_> {
    /// Widens scalar arguments to the vector size of the result, as naga's math functions
    /// want identical argument types.
    fn widen(
        &mut self,
        v: Handle<Expression>,
        from: &Type,
        to: &Type,
        span: Span,
    ) -> Handle<Expression> {
        match (from, to) {
            (Type::Scalar(_), Type::Vector(_, n)) => self.splat(v, *n, span),
            _ => v,
        }
    }

    /// Lowers a call of a built-in function (`ret`: the call's type).
    pub(crate) fn builtin(
        &mut self,
        op: BuiltinFn,
        args: &[Expr],
        ret: &Type,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        use BuiltinFn::*;
        if op.is_texture() {
            return self.texture(op, args, ret, span);
        }
        let vals: Vec<Handle<Expression>> = args
            .iter()
            .map(|a| self.expr(a))
            .collect::<Result<_, _>>()?;
        let call = Call {
            op,
            args,
            vals: &vals,
            ret,
            span,
        };
        match op {
            Radians | Degrees | Sin | Cos | Tan | Asin | Acos | Atan | Sinh | Cosh | Tanh
            | Asinh | Acosh | Atanh | Pow | Exp | Log | Exp2 | Log2 | Sqrt | InverseSqrt => {
                self.exponential(call)
            }
            Abs | Sign | Floor | Trunc | Round | RoundEven | Ceil | Fract | Mod | Modf | Min
            | Max | Clamp | Mix | Step | SmoothStep | IsNan | IsInf | FloatBitsToInt
            | FloatBitsToUint | IntBitsToFloat | UintBitsToFloat => self.common(call),
            PackSnorm2x16 | UnpackSnorm2x16 | PackUnorm2x16 | UnpackUnorm2x16 | PackHalf2x16
            | UnpackHalf2x16 => self.packing(call),
            Length | Distance | Dot | Cross | Normalize | FaceForward | Reflect | Refract => {
                self.geometric(call)
            }
            MatrixCompMult | OuterProduct | Transpose | Determinant | Inverse => self.matrix(call),
            LessThan | LessThanEqual | GreaterThan | GreaterThanEqual | Equal | NotEqual | Any
            | All | Not => self.relational(call),
            DFdx | DFdy | Fwidth => self.derivative(call),
            _ => Err(call.unsupported()),
        }
    }

    /// Angle, trigonometry and exponential functions: one naga math function each.
    fn exponential(&mut self, call: Call) -> Result<Handle<Expression>, LowerError> {
        use BuiltinFn::*;
        let Call { op, vals, span, .. } = call;
        let unary = |fx: &mut Self, f: Mf| fx.math(f, &[vals[0]], span);
        Ok(match op {
            Radians => unary(self, Mf::Radians),
            Degrees => unary(self, Mf::Degrees),
            Sin => unary(self, Mf::Sin),
            Cos => unary(self, Mf::Cos),
            Tan => unary(self, Mf::Tan),
            Asin => unary(self, Mf::Asin),
            Acos => unary(self, Mf::Acos),
            Atan if vals.len() == 2 => self.math(Mf::Atan2, &[vals[0], vals[1]], span),
            Atan => unary(self, Mf::Atan),
            Sinh => unary(self, Mf::Sinh),
            Cosh => unary(self, Mf::Cosh),
            Tanh => unary(self, Mf::Tanh),
            Asinh => unary(self, Mf::Asinh),
            Acosh => unary(self, Mf::Acosh),
            Atanh => unary(self, Mf::Atanh),
            Pow => self.math(Mf::Pow, &[vals[0], vals[1]], span),
            Exp => unary(self, Mf::Exp),
            Log => unary(self, Mf::Log),
            Exp2 => unary(self, Mf::Exp2),
            Log2 => unary(self, Mf::Log2),
            Sqrt => unary(self, Mf::Sqrt),
            InverseSqrt => unary(self, Mf::InverseSqrt),
            _ => return Err(call.unsupported()),
        })
    }

    /// Common functions (`abs` … `smoothstep`, `isnan`, `isinf`) and the bit casts between
    /// floats and integers; scalar arguments widened where naga wants vectors.
    fn common(&mut self, call: Call) -> Result<Handle<Expression>, LowerError> {
        use BuiltinFn::*;
        let Call {
            op,
            args,
            vals,
            span,
            ..
        } = call;
        let t0 = args[0].ty.clone();
        let unary = |fx: &mut Self, f: Mf| fx.math(f, &[vals[0]], span);
        Ok(match op {
            Abs => unary(self, Mf::Abs),
            Sign => unary(self, Mf::Sign),
            Floor => unary(self, Mf::Floor),
            Trunc => unary(self, Mf::Trunc),
            Round | RoundEven => unary(self, Mf::Round),
            Ceil => unary(self, Mf::Ceil),
            Fract => unary(self, Mf::Fract),
            Mod => {
                // GLSL: x - y * floor(x / y).
                let y = self.widen(vals[1], &args[1].ty, &t0, span);
                let q = self.binop(naga::BinaryOperator::Divide, vals[0], y, span);
                let fl = self.math(Mf::Floor, &[q], span);
                let p = self.binop(naga::BinaryOperator::Multiply, y, fl, span);
                self.binop(naga::BinaryOperator::Subtract, vals[0], p, span)
            }
            Modf => {
                // modf(x, out i): i = trunc(x), and the result is x - i.
                let whole = self.math(Mf::Trunc, &[vals[0]], span);
                self.store_to(&args[1], whole, span)?;
                self.binop(naga::BinaryOperator::Subtract, vals[0], whole, span)
            }
            Min | Max => {
                let b = self.widen(vals[1], &args[1].ty, &t0, span);
                self.math(
                    if op == Min { Mf::Min } else { Mf::Max },
                    &[vals[0], b],
                    span,
                )
            }
            Clamp => {
                let lo = self.widen(vals[1], &args[1].ty, &t0, span);
                let hi = self.widen(vals[2], &args[2].ty, &t0, span);
                self.math(Mf::Clamp, &[vals[0], lo, hi], span)
            }
            Mix if args[2].ty.scalar_kind() == Some(ScalarKind::Bool) => {
                // mix(x, y, b) picks y where b is true.
                self.add(
                    Expression::Select {
                        condition: vals[2],
                        accept: vals[1],
                        reject: vals[0],
                    },
                    span,
                )
            }
            Mix => {
                let a = self.widen(vals[2], &args[2].ty, &t0, span);
                self.math(Mf::Mix, &[vals[0], vals[1], a], span)
            }
            Step => {
                let e = self.widen(vals[0], &args[0].ty, &args[1].ty, span);
                self.math(Mf::Step, &[e, vals[1]], span)
            }
            SmoothStep => {
                let e0 = self.widen(vals[0], &args[0].ty, &args[2].ty, span);
                let e1 = self.widen(vals[1], &args[1].ty, &args[2].ty, span);
                self.math(Mf::SmoothStep, &[e0, e1, vals[2]], span)
            }
            IsNan | IsInf => {
                // By the bits (exponent all ones; a mantissa for NaN, none for infinity), which
                // every target can say: WGSL has no isnan or isinf.
                let n = match &args[0].ty {
                    Type::Vector(_, n) => Some(*n),
                    _ => None,
                };
                let bits = self.add(
                    Expression::As {
                        expr: vals[0],
                        kind: naga::ScalarKind::Uint,
                        convert: None,
                    },
                    span,
                );
                let constant = |fx: &mut Self, v: u32| {
                    let l = fx.lit(Literal::U32(v));
                    match n {
                        Some(n) => fx.splat(l, n, span),
                        None => l,
                    }
                };
                let mask = constant(self, 0x7fff_ffff);
                let magnitude = self.binop(naga::BinaryOperator::And, bits, mask, span);
                let infinity = constant(self, 0x7f80_0000);
                let compare = if op == IsNan {
                    naga::BinaryOperator::Greater
                } else {
                    naga::BinaryOperator::Equal
                };
                self.binop(compare, magnitude, infinity, span)
            }
            FloatBitsToInt => self.add(
                Expression::As {
                    expr: vals[0],
                    kind: naga::ScalarKind::Sint,
                    convert: None,
                },
                span,
            ),
            FloatBitsToUint => self.add(
                Expression::As {
                    expr: vals[0],
                    kind: naga::ScalarKind::Uint,
                    convert: None,
                },
                span,
            ),
            IntBitsToFloat | UintBitsToFloat => self.add(
                Expression::As {
                    expr: vals[0],
                    kind: naga::ScalarKind::Float,
                    convert: None,
                },
                span,
            ),
            _ => return Err(call.unsupported()),
        })
    }

    /// Packing and unpacking of two 16-bit values in a 32-bit integer.
    fn packing(&mut self, call: Call) -> Result<Handle<Expression>, LowerError> {
        use BuiltinFn::*;
        let Call { op, vals, span, .. } = call;
        let unary = |fx: &mut Self, f: Mf| fx.math(f, &[vals[0]], span);
        Ok(match op {
            PackSnorm2x16 => unary(self, Mf::Pack2x16snorm),
            UnpackSnorm2x16 => unary(self, Mf::Unpack2x16snorm),
            PackUnorm2x16 => unary(self, Mf::Pack2x16unorm),
            UnpackUnorm2x16 => unary(self, Mf::Unpack2x16unorm),
            PackHalf2x16 => self.pack_half(vals[0], span),
            UnpackHalf2x16 => self.unpack_half(vals[0], span),
            _ => return Err(call.unsupported()),
        })
    }

    /// Geometric functions; on scalars, those naga only takes on vectors are built by hand.
    fn geometric(&mut self, call: Call) -> Result<Handle<Expression>, LowerError> {
        use BuiltinFn::*;
        let Call {
            op,
            args,
            vals,
            span,
            ..
        } = call;
        let t0 = args[0].ty.clone();
        let unary = |fx: &mut Self, f: Mf| fx.math(f, &[vals[0]], span);
        Ok(match op {
            Length => unary(self, Mf::Length),
            Distance => self.math(Mf::Distance, &[vals[0], vals[1]], span),
            Dot if t0.is_scalar() => {
                self.binop(naga::BinaryOperator::Multiply, vals[0], vals[1], span)
            }
            Dot => self.math(Mf::Dot, &[vals[0], vals[1]], span),
            Cross => self.math(Mf::Cross, &[vals[0], vals[1]], span),
            Normalize if t0.is_scalar() => unary(self, Mf::Sign),
            Normalize => unary(self, Mf::Normalize),
            FaceForward if t0.is_scalar() => {
                // dot(Nref, I) < 0 ? N : -N, for scalars (naga's FaceForward takes vectors).
                let d = self.binop(naga::BinaryOperator::Multiply, vals[2], vals[1], span);
                let zero = self.lit(Literal::F32(0.0));
                let negative = self.binop(naga::BinaryOperator::Less, d, zero, span);
                let minus_n = self.add(
                    Expression::Unary {
                        op: naga::UnaryOperator::Negate,
                        expr: vals[0],
                    },
                    span,
                );
                self.add(
                    Expression::Select {
                        condition: negative,
                        accept: vals[0],
                        reject: minus_n,
                    },
                    span,
                )
            }
            FaceForward => self.math(Mf::FaceForward, &[vals[0], vals[1], vals[2]], span),
            Reflect if t0.is_scalar() => {
                // I - 2 * dot(N, I) * N for scalars.
                let d = self.binop(naga::BinaryOperator::Multiply, vals[1], vals[0], span);
                let two = self.lit(Literal::F32(2.0));
                let t = self.binop(naga::BinaryOperator::Multiply, two, d, span);
                let t = self.binop(naga::BinaryOperator::Multiply, t, vals[1], span);
                self.binop(naga::BinaryOperator::Subtract, vals[0], t, span)
            }
            Reflect => self.math(Mf::Reflect, &[vals[0], vals[1]], span),
            Refract if t0.is_scalar() => {
                // k = 1 - eta² (1 - (N·I)²); k < 0 ? 0 : eta I - (eta N·I + sqrt(k)) N, for
                // scalars (naga's Refract takes vectors).
                use naga::BinaryOperator::{Add, Less, Multiply, Subtract};
                let (i, n, eta) = (vals[0], vals[1], vals[2]);
                let d = self.binop(Multiply, n, i, span);
                let one = self.lit(Literal::F32(1.0));
                let zero = self.lit(Literal::F32(0.0));
                let d2 = self.binop(Multiply, d, d, span);
                let one_minus_d2 = self.binop(Subtract, one, d2, span);
                let eta2 = self.binop(Multiply, eta, eta, span);
                let t = self.binop(Multiply, eta2, one_minus_d2, span);
                let k = self.binop(Subtract, one, t, span);
                let total = self.binop(Less, k, zero, span);
                let root = self.math(Mf::Sqrt, &[k], span);
                let eta_d = self.binop(Multiply, eta, d, span);
                let coef = self.binop(Add, eta_d, root, span);
                let eta_i = self.binop(Multiply, eta, i, span);
                let coef_n = self.binop(Multiply, coef, n, span);
                let refracted = self.binop(Subtract, eta_i, coef_n, span);
                self.add(
                    Expression::Select {
                        condition: total,
                        accept: zero,
                        reject: refracted,
                    },
                    span,
                )
            }
            Refract => self.math(Mf::Refract, &[vals[0], vals[1], vals[2]], span),
            _ => return Err(call.unsupported()),
        })
    }

    /// Matrix functions; `matrixCompMult` and `outerProduct` column by column.
    fn matrix(&mut self, call: Call) -> Result<Handle<Expression>, LowerError> {
        use BuiltinFn::*;
        let Call {
            op,
            args,
            vals,
            ret,
            span,
            ..
        } = call;
        let t0 = args[0].ty.clone();
        let unary = |fx: &mut Self, f: Mf| fx.math(f, &[vals[0]], span);
        Ok(match op {
            MatrixCompMult => {
                let Type::Matrix { cols, .. } = t0 else {
                    return Err(unsupported("matrixCompMult", span));
                };
                let parts: Vec<_> = (0..cols as u32)
                    .map(|i| {
                        let x = self.access_index(vals[0], i, span);
                        let y = self.access_index(vals[1], i, span);
                        self.binop(naga::BinaryOperator::Multiply, x, y, span)
                    })
                    .collect();
                self.compose(ret, parts, span)
            }
            OuterProduct => {
                // Column i of outerProduct(c, r) is c * r[i]. Built by hand: naga's `Outer` gives
                // a non-square result the transposed shape.
                let Type::Vector(_, n) = args[1].ty else {
                    return Err(unsupported("outerProduct", span));
                };
                let parts: Vec<_> = (0..n as u32)
                    .map(|i| {
                        let r = self.access_index(vals[1], i, span);
                        self.binop(naga::BinaryOperator::Multiply, vals[0], r, span)
                    })
                    .collect();
                self.compose(ret, parts, span)
            }
            Transpose => unary(self, Mf::Transpose),
            Determinant => unary(self, Mf::Determinant),
            Inverse => unary(self, Mf::Inverse),
            _ => return Err(call.unsupported()),
        })
    }

    /// Component-wise comparisons and the vector relational functions.
    fn relational(&mut self, call: Call) -> Result<Handle<Expression>, LowerError> {
        use BuiltinFn::*;
        let Call { op, vals, span, .. } = call;
        Ok(match op {
            LessThan | LessThanEqual | GreaterThan | GreaterThanEqual | Equal | NotEqual => {
                let o = match op {
                    LessThan => naga::BinaryOperator::Less,
                    LessThanEqual => naga::BinaryOperator::LessEqual,
                    GreaterThan => naga::BinaryOperator::Greater,
                    GreaterThanEqual => naga::BinaryOperator::GreaterEqual,
                    Equal => naga::BinaryOperator::Equal,
                    _ => naga::BinaryOperator::NotEqual,
                };
                self.binop(o, vals[0], vals[1], span)
            }
            Any => self.add(
                Expression::Relational {
                    fun: naga::RelationalFunction::Any,
                    argument: vals[0],
                },
                span,
            ),
            All => self.add(
                Expression::Relational {
                    fun: naga::RelationalFunction::All,
                    argument: vals[0],
                },
                span,
            ),
            Not => self.add(
                Expression::Unary {
                    op: naga::UnaryOperator::LogicalNot,
                    expr: vals[0],
                },
                span,
            ),
            _ => return Err(call.unsupported()),
        })
    }

    /// Derivatives; `dFdy` negated when `gl_FragCoord` is flipped (GL's y grows upwards).
    fn derivative(&mut self, call: Call) -> Result<Handle<Expression>, LowerError> {
        use BuiltinFn::*;
        let Call { op, vals, span, .. } = call;
        Ok(match op {
            DFdx | DFdy | Fwidth => {
                let axis = match op {
                    DFdx => naga::DerivativeAxis::X,
                    DFdy => naga::DerivativeAxis::Y,
                    _ => naga::DerivativeAxis::Width,
                };
                let mut d = self.add(
                    Expression::Derivative {
                        axis,
                        ctrl: naga::DerivativeControl::None,
                        expr: vals[0],
                    },
                    span,
                );
                if op == DFdy && self.cx.options.flip_frag_coord_y {
                    // GL's y grows upwards; the framebuffer's grows downwards.
                    d = self.add(
                        Expression::Unary {
                            op: naga::UnaryOperator::Negate,
                            expr: d,
                        },
                        span,
                    );
                    // Named so that a translation can point at it (essl-translate's comments).
                    self.f.named_expressions.insert(d, "dFdy_y_up".into());
                }
                d
            }
            _ => return Err(call.unsupported()),
        })
    }

    /// `packHalf2x16` without float16 capabilities: rounds each component to binary16 by
    /// integer arithmetic on its bits.
    fn pack_half(&mut self, v: Handle<Expression>, span: Span) -> Handle<Expression> {
        let x = self.access_index(v, 0, span);
        let y = self.access_index(v, 1, span);
        let hx = self.f32_to_f16_bits(x, span);
        let hy = self.f32_to_f16_bits(y, span);
        let sixteen = self.lit(Literal::U32(16));
        let hy = self.binop(naga::BinaryOperator::ShiftLeft, hy, sixteen, span);
        self.binop(naga::BinaryOperator::InclusiveOr, hx, hy, span)
    }

    fn f32_to_f16_bits(&mut self, f: Handle<Expression>, span: Span) -> Handle<Expression> {
        use naga::BinaryOperator as B;
        // Branch-free conversion of normal numbers (round to nearest), flushing denormals to
        // signed zero and overflow to infinity; NaN stays NaN.
        let bits = self.add(
            Expression::As {
                expr: f,
                kind: naga::ScalarKind::Uint,
                convert: None,
            },
            span,
        );
        let c = |fx: &mut Self, v: u32| fx.lit(Literal::U32(v));
        let k16 = c(self, 16);
        let sign_mask = c(self, 0x8000);
        let sh = self.binop(B::ShiftRight, bits, k16, span);
        let sign = self.binop(B::And, sh, sign_mask, span);
        let abs_mask = c(self, 0x7fff_ffff);
        let abs = self.binop(B::And, bits, abs_mask, span);
        // Rounded: (abs + 0x1000) >> 13, rebased from exponent bias 127 to 15.
        let round = c(self, 0x1000);
        let r = self.binop(B::Add, abs, round, span);
        let k13 = c(self, 13);
        let r = self.binop(B::ShiftRight, r, k13, span);
        let rebias = c(self, (127 - 15) << 10);
        let normal = self.binop(B::Subtract, r, rebias, span);
        // Ranges on |f|'s bits.
        let min_normal = c(self, 0x3880_0000); // 2^-14
        let overflow = c(self, 0x477f_f000); // rounds to 65520 and beyond
        let inf = c(self, 0x7f80_0000);
        let is_small = self.binop(B::Less, abs, min_normal, span);
        let is_big = self.binop(B::GreaterEqual, abs, overflow, span);
        let is_nan = self.binop(B::Greater, abs, inf, span);
        let zero = c(self, 0);
        let h_inf = c(self, 0x7c00);
        let h_nan = c(self, 0x7e00);
        let v = self.add(
            Expression::Select {
                condition: is_small,
                accept: zero,
                reject: normal,
            },
            span,
        );
        let v = self.add(
            Expression::Select {
                condition: is_big,
                accept: h_inf,
                reject: v,
            },
            span,
        );
        let v = self.add(
            Expression::Select {
                condition: is_nan,
                accept: h_nan,
                reject: v,
            },
            span,
        );
        self.binop(B::InclusiveOr, v, sign, span)
    }

    fn unpack_half(&mut self, p: Handle<Expression>, span: Span) -> Handle<Expression> {
        use naga::BinaryOperator as B;
        let mask = self.lit(Literal::U32(0xffff));
        let k16 = self.lit(Literal::U32(16));
        let lo = self.binop(B::And, p, mask, span);
        let hi = self.binop(B::ShiftRight, p, k16, span);
        let x = self.f16_bits_to_f32(lo, span);
        let y = self.f16_bits_to_f32(hi, span);
        self.compose(&Type::Vector(ScalarKind::Float, 2), vec![x, y], span)
    }

    fn f16_bits_to_f32(&mut self, h: Handle<Expression>, span: Span) -> Handle<Expression> {
        use naga::BinaryOperator as B;
        let c = |fx: &mut Self, v: u32| fx.lit(Literal::U32(v));
        let k15 = c(self, 15);
        let one = c(self, 1);
        let sign = self.binop(B::ShiftRight, h, k15, span);
        let k10 = c(self, 10);
        let m31 = c(self, 31);
        let e = self.binop(B::ShiftRight, h, k10, span);
        let e = self.binop(B::And, e, m31, span);
        let m3ff = c(self, 0x3ff);
        let mant = self.binop(B::And, h, m3ff, span);
        // value = (e == 0 ? mant * 2^-24 : e == 31 ? (mant == 0 ? inf : nan) : (1 + mant/1024) * 2^(e-15))
        let fm = self.cast(mant, naga::ScalarKind::Float, span);
        let fe = self.cast(e, naga::ScalarKind::Sint, span);
        let bias = self.lit(Literal::I32(15));
        let fe = self.binop(B::Subtract, fe, bias, span);
        let fe = self.cast(fe, naga::ScalarKind::Float, span);
        let two = self.lit(Literal::F32(2.0));
        let scale = self.math(Mf::Pow, &[two, fe], span);
        let k1024 = self.lit(Literal::F32(1024.0));
        let frac = self.binop(B::Divide, fm, k1024, span);
        let onef = self.lit(Literal::F32(1.0));
        let norm = self.binop(B::Add, onef, frac, span);
        let normal = self.binop(B::Multiply, norm, scale, span);
        let tiny = self.lit(Literal::F32(5.960_464_5e-8));
        let sub = self.binop(B::Multiply, fm, tiny, span);
        let zero_u = c(self, 0);
        let is_sub = self.binop(B::Equal, e, zero_u, span);
        let v = self.add(
            Expression::Select {
                condition: is_sub,
                accept: sub,
                reject: normal,
            },
            span,
        );
        let is_special = self.binop(B::Equal, e, m31, span);
        // naga's literals are finite: the two are built from their bits.
        let inf = self.f32_from_bits(f32::INFINITY.to_bits(), span);
        let nan = self.f32_from_bits(f32::NAN.to_bits(), span);
        let mant_zero = self.binop(B::Equal, mant, zero_u, span);
        let special = self.add(
            Expression::Select {
                condition: mant_zero,
                accept: inf,
                reject: nan,
            },
            span,
        );
        let v = self.add(
            Expression::Select {
                condition: is_special,
                accept: special,
                reject: v,
            },
            span,
        );
        let is_neg = self.binop(B::Equal, sign, one, span);
        let neg = self.add(
            Expression::Unary {
                op: naga::UnaryOperator::Negate,
                expr: v,
            },
            span,
        );
        self.add(
            Expression::Select {
                condition: is_neg,
                accept: neg,
                reject: v,
            },
            span,
        )
    }
}
