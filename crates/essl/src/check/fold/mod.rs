//! Constant folding: GLSL ES 3.00 constant expressions evaluated in 32-bit arithmetic
//! (floats as `f32`, integers wrapping), as a GPU would.

use crate::ast::BinaryOp;
use crate::hir::{ConstValue, Scalar, UnaryOp};
use crate::types::{ScalarKind, Type};

mod functions;

pub use functions::builtin;

/// Why a constant could not be folded.
#[derive(Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum FoldError {
    /// Not foldable (left to run time).
    Unsupported,
}

/// An undefined or non-finite result a fold gave a value anyway, as ANGLE's folding does
/// (`TIntermConstantUnion::foldBinary`), which Chromium reports as a warning and compiles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FoldWarning {
    /// An integer `/` or `%` by 0: folded to the type's largest value.
    IntegerDivideByZero,
    /// A non-zero float divided by 0: folded to ±∞.
    FloatDivideByZero,
    /// `0.0 / 0.0`: folded to NaN.
    ZeroByZero,
    /// An operation of infinities whose result is NaN: `∞ / ∞`, `∞ - ∞`, `∞ * 0`.
    NotANumber,
    /// An addition, subtraction, multiplication or division of finite floats whose result is
    /// past the largest float: ±∞.
    Overflow,
    /// An integer `%` with a negative operand: folded to 0.
    NegativeModulus,
    /// A built-in function whose result is undefined for its arguments (`sqrt(-1.0)`): the
    /// components concerned folded to 0.
    UndefinedCall,
    /// A negative float converted to `uint` (`uint(-1.0)`): folded through `int`, 4294967295.
    NegativeToUint,
}

fn basic(c: &ConstValue) -> Option<&[Scalar]> {
    c.scalars()
}

fn f(s: Scalar) -> f32 {
    match s {
        Scalar::F(v) => v,
        Scalar::I(v) => v as f32,
        Scalar::U(v) => v as f32,
        Scalar::B(v) => v as u8 as f32,
    }
}

/// Folds a unary operation.
pub fn unary(op: UnaryOp, c: &ConstValue) -> Option<ConstValue> {
    let v = basic(c)?;
    let out = v
        .iter()
        .map(|s| match (op, *s) {
            (UnaryOp::Neg, Scalar::F(x)) => Some(Scalar::F(-x)),
            (UnaryOp::Neg, Scalar::I(x)) => Some(Scalar::I(x.wrapping_neg())),
            (UnaryOp::Neg, Scalar::U(x)) => Some(Scalar::U(x.wrapping_neg())),
            (UnaryOp::Not, Scalar::B(x)) => Some(Scalar::B(!x)),
            (UnaryOp::BitNot, Scalar::I(x)) => Some(Scalar::I(!x)),
            (UnaryOp::BitNot, Scalar::U(x)) => Some(Scalar::U(!x)),
            _ => None,
        })
        .collect::<Option<Vec<_>>>()?;
    Some(ConstValue::Basic(out))
}

fn scalar_op(
    op: BinaryOp,
    a: Scalar,
    b: Scalar,
    warnings: &mut Vec<FoldWarning>,
) -> Result<Scalar, FoldError> {
    use BinaryOp::*;
    use Scalar::*;
    let mut warn = |w| {
        if !warnings.contains(&w) {
            warnings.push(w);
        }
    };
    Ok(match (a, b) {
        (F(x), F(y)) => match op {
            Add => F(checked(x + y, x, y, &mut warn)),
            Sub => F(checked(x - y, x, y, &mut warn)),
            Mul => F(checked(x * y, x, y, &mut warn)),
            Div => F(float_div(x, y, &mut warn)),
            _ => return Err(FoldError::Unsupported),
        },
        (I(x), I(y)) => match op {
            Add => I(x.wrapping_add(y)),
            Sub => I(x.wrapping_sub(y)),
            Mul => I(x.wrapping_mul(y)),
            Div | Mod if y == 0 => {
                warn(FoldWarning::IntegerDivideByZero);
                I(i32::MAX)
            }
            Div if x == i32::MIN && y == -1 => I(i32::MAX),
            Div => I(x / y),
            Mod if x < 0 || y < 0 => {
                warn(FoldWarning::NegativeModulus);
                I(0)
            }
            Mod => I(x % y),
            BitAnd => I(x & y),
            BitOr => I(x | y),
            BitXor => I(x ^ y),
            _ => return Err(FoldError::Unsupported),
        },
        (U(x), U(y)) => match op {
            Add => U(x.wrapping_add(y)),
            Sub => U(x.wrapping_sub(y)),
            Mul => U(x.wrapping_mul(y)),
            Div | Mod if y == 0 => {
                warn(FoldWarning::IntegerDivideByZero);
                U(u32::MAX)
            }
            Div => U(x / y),
            Mod => U(x % y),
            BitAnd => U(x & y),
            BitOr => U(x | y),
            BitXor => U(x ^ y),
            _ => return Err(FoldError::Unsupported),
        },
        _ => return Err(FoldError::Unsupported),
    })
}

/// A float quotient as ANGLE folds it: `x / 0` is ±∞ by the signs (even for a NaN `x`), `0 / 0`
/// and `∞ / ∞` NaN, each with its warning, as is a finite quotient that overflows.
fn float_div(x: f32, y: f32, warn: &mut impl FnMut(FoldWarning)) -> f32 {
    if y == 0.0 {
        if x == 0.0 {
            warn(FoldWarning::ZeroByZero);
            return f32::NAN;
        }
        warn(FoldWarning::FloatDivideByZero);
        return if x.is_sign_negative() != y.is_sign_negative() {
            f32::NEG_INFINITY
        } else {
            f32::INFINITY
        };
    }
    if x.is_infinite() && y.is_infinite() {
        warn(FoldWarning::NotANumber);
        return f32::NAN;
    }
    let q = x / y;
    if !x.is_infinite() && q.is_infinite() {
        warn(FoldWarning::Overflow);
    }
    q
}

/// The result `r` of `x + y`, `x - y` or `x * y`, warned of as ANGLE's `CheckedSum`,
/// `CheckedDiff` and `CheckedMul` do: NaN from numbers, ±∞ from finite numbers.
fn checked(r: f32, x: f32, y: f32, warn: &mut impl FnMut(FoldWarning)) -> f32 {
    if r.is_nan() && !x.is_nan() && !y.is_nan() {
        warn(FoldWarning::NotANumber);
    } else if r.is_infinite() && !x.is_infinite() && !y.is_infinite() {
        warn(FoldWarning::Overflow);
    }
    r
}

/// A constant shift. An amount outside 0..32 is undefined in GLSL; Chromium folds it with a
/// warning, and essl takes it modulo 32, as the lowering does at run time.
fn shift(op: BinaryOp, a: Scalar, b: Scalar) -> Result<Scalar, FoldError> {
    let amount = match b {
        Scalar::I(v) => (v as u32) & 31,
        Scalar::U(v) => v & 31,
        _ => return Err(FoldError::Unsupported),
    };
    Ok(match (a, op) {
        (Scalar::I(x), BinaryOp::Shl) => Scalar::I(x.wrapping_shl(amount)),
        (Scalar::I(x), _) => Scalar::I(x >> amount),
        (Scalar::U(x), BinaryOp::Shl) => Scalar::U(x.wrapping_shl(amount)),
        (Scalar::U(x), _) => Scalar::U(x >> amount),
        _ => return Err(FoldError::Unsupported),
    })
}

/// Folds a binary operation whose result type is `rt`; each kind of undefined or non-finite
/// result it gave a value (ANGLE's) is added to `warnings` once.
pub fn binary(
    op: BinaryOp,
    a: &ConstValue,
    at: &Type,
    b: &ConstValue,
    bt: &Type,
    rt: &Type,
    warnings: &mut Vec<FoldWarning>,
) -> Result<ConstValue, FoldError> {
    use BinaryOp::*;
    match op {
        Eq | NotEq => {
            let eq = const_eq(a, b);
            return Ok(ConstValue::Basic(vec![Scalar::B(if op == Eq {
                eq
            } else {
                !eq
            })]));
        }
        And | Or | Xor => {
            let (Some([Scalar::B(x)]), Some([Scalar::B(y)])) = (basic(a), basic(b)) else {
                return Err(FoldError::Unsupported);
            };
            let v = match op {
                And => *x && *y,
                Or => *x || *y,
                _ => *x != *y,
            };
            return Ok(ConstValue::Basic(vec![Scalar::B(v)]));
        }
        Less | Greater | LessEq | GreaterEq => {
            let (Some([x]), Some([y])) = (basic(a), basic(b)) else {
                return Err(FoldError::Unsupported);
            };
            let ord = match (x, y) {
                (Scalar::F(x), Scalar::F(y)) => x.partial_cmp(y),
                (Scalar::I(x), Scalar::I(y)) => Some(x.cmp(y)),
                (Scalar::U(x), Scalar::U(y)) => Some(x.cmp(y)),
                _ => return Err(FoldError::Unsupported),
            };
            let v = match ord {
                None => false,
                Some(o) => match op {
                    Less => o.is_lt(),
                    Greater => o.is_gt(),
                    LessEq => o.is_le(),
                    _ => o.is_ge(),
                },
            };
            return Ok(ConstValue::Basic(vec![Scalar::B(v)]));
        }
        _ => {}
    }
    let (Some(x), Some(y)) = (basic(a), basic(b)) else {
        return Err(FoldError::Unsupported);
    };
    if op == Mul {
        match (at, bt) {
            (Type::Matrix { cols, rows }, Type::Vector(_, _)) => {
                let (c, r) = (*cols as usize, *rows as usize);
                let out = (0..r)
                    .map(|i| Scalar::F((0..c).map(|k| f(x[k * r + i]) * f(y[k])).sum()))
                    .collect();
                return Ok(ConstValue::Basic(out));
            }
            (Type::Vector(_, _), Type::Matrix { cols, rows }) => {
                let (c, r) = (*cols as usize, *rows as usize);
                let out = (0..c)
                    .map(|j| Scalar::F((0..r).map(|k| f(x[k]) * f(y[j * r + k])).sum()))
                    .collect();
                return Ok(ConstValue::Basic(out));
            }
            (Type::Matrix { cols: c1, rows: r1 }, Type::Matrix { cols: c2, .. }) => {
                let (c1, r1, c2) = (*c1 as usize, *r1 as usize, *c2 as usize);
                let mut out = Vec::with_capacity(c2 * r1);
                for j in 0..c2 {
                    for i in 0..r1 {
                        out.push(Scalar::F(
                            (0..c1).map(|k| f(x[k * r1 + i]) * f(y[j * c1 + k])).sum(),
                        ));
                    }
                }
                return Ok(ConstValue::Basic(out));
            }
            _ => {}
        }
    }
    let n = rt.component_count().unwrap_or(1) as usize;
    let get = |v: &[Scalar], i: usize| if v.len() == 1 { v[0] } else { v[i] };
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let (p, q) = (get(x, i), get(y, i));
        out.push(match op {
            Shl | Shr => shift(op, p, q)?,
            _ => scalar_op(op, p, q, warnings)?,
        });
    }
    Ok(ConstValue::Basic(out))
}

fn const_eq(a: &ConstValue, b: &ConstValue) -> bool {
    match (a, b) {
        (ConstValue::Basic(x), ConstValue::Basic(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(p, q)| p == q)
        }
        (ConstValue::Composite(x), ConstValue::Composite(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(p, q)| const_eq(p, q))
        }
        _ => false,
    }
}

/// Folds `c[i]` on an array, matrix or vector constant.
pub fn index(c: &ConstValue, ty: &Type, i: usize) -> Option<ConstValue> {
    match (c, ty) {
        (ConstValue::Composite(elems), Type::Array(..)) => elems.get(i).cloned(),
        (ConstValue::Basic(v), Type::Matrix { rows, .. }) => {
            let r = *rows as usize;
            Some(ConstValue::Basic(v.get(i * r..i * r + r)?.to_vec()))
        }
        (ConstValue::Basic(v), Type::Vector(..)) => Some(ConstValue::Basic(vec![*v.get(i)?])),
        _ => None,
    }
}

/// Folds a swizzle.
pub fn swizzle(c: &ConstValue, comps: &[u8]) -> Option<ConstValue> {
    let v = basic(c)?;
    Some(ConstValue::Basic(
        comps
            .iter()
            .map(|&i| v.get(i as usize).copied())
            .collect::<Option<Vec<_>>>()?,
    ))
}

/// Converts a scalar to a kind, as constructors do.
pub fn convert(s: Scalar, to: ScalarKind) -> Scalar {
    match to {
        ScalarKind::Float => Scalar::F(f(s)),
        ScalarKind::Int => Scalar::I(match s {
            Scalar::F(v) => float_to_i32(v),
            Scalar::I(v) => v,
            Scalar::U(v) => v as i32,
            Scalar::B(v) => v as i32,
        }),
        ScalarKind::Uint => Scalar::U(match s {
            Scalar::F(v) => float_to_u32(v),
            Scalar::I(v) => v as u32,
            Scalar::U(v) => v,
            Scalar::B(v) => v as u32,
        }),
        ScalarKind::Bool => Scalar::B(match s {
            Scalar::F(v) => v != 0.0,
            Scalar::I(v) => v != 0,
            Scalar::U(v) => v != 0,
            Scalar::B(v) => v,
        }),
    }
}

fn float_to_i32(v: f32) -> i32 {
    v as i32
}

fn float_to_u32(v: f32) -> u32 {
    if v < 0.0 {
        // Undefined in GLSL; GPUs commonly wrap through int.
        (v as i32) as u32
    } else {
        v as u32
    }
}

/// Folds a constructor; a negative float converted to `uint` adds
/// [`FoldWarning::NegativeToUint`] to `warnings`, as ANGLE warns of it.
pub fn construct(
    ty: &Type,
    args: &[&ConstValue],
    arg_tys: &[&Type],
    warnings: &mut Vec<FoldWarning>,
) -> Option<ConstValue> {
    let mut convert = |s: Scalar, k: ScalarKind| {
        if k == ScalarKind::Uint
            && matches!(s, Scalar::F(v) if v < 0.0)
            && !warnings.contains(&FoldWarning::NegativeToUint)
        {
            warnings.push(FoldWarning::NegativeToUint);
        }
        convert(s, k)
    };
    match ty {
        Type::Array(..) | Type::Struct(_) => Some(ConstValue::Composite(
            args.iter().map(|a| (*a).clone()).collect(),
        )),
        Type::Scalar(k) => Some(ConstValue::Basic(vec![convert(
            *basic(args[0])?.first()?,
            *k,
        )])),
        Type::Vector(k, n) => {
            let n = *n as usize;
            if args.len() == 1 && arg_tys[0].is_scalar() {
                let s = convert(basic(args[0])?[0], *k);
                return Some(ConstValue::Basic(vec![s; n]));
            }
            let comps: Vec<Scalar> = args
                .iter()
                .map(|a| basic(a))
                .collect::<Option<Vec<_>>>()?
                .concat();
            Some(ConstValue::Basic(
                comps.into_iter().take(n).map(|s| convert(s, *k)).collect(),
            ))
        }
        Type::Matrix { cols, rows } => {
            let (c, r) = (*cols as usize, *rows as usize);
            if args.len() == 1 && arg_tys[0].is_scalar() {
                let s = f(basic(args[0])?[0]);
                let out = (0..c * r)
                    .map(|i| Scalar::F(if i / r == i % r { s } else { 0.0 }))
                    .collect();
                return Some(ConstValue::Basic(out));
            }
            if args.len() == 1 {
                if let Type::Matrix { cols: c2, rows: r2 } = arg_tys[0] {
                    let (c2, r2) = (*c2 as usize, *r2 as usize);
                    let v = basic(args[0])?;
                    let out = (0..c * r)
                        .map(|i| {
                            let (col, row) = (i / r, i % r);
                            Scalar::F(if col < c2 && row < r2 {
                                f(v[col * r2 + row])
                            } else if col == row {
                                1.0
                            } else {
                                0.0
                            })
                        })
                        .collect();
                    return Some(ConstValue::Basic(out));
                }
            }
            let comps: Vec<Scalar> = args
                .iter()
                .map(|a| basic(a))
                .collect::<Option<Vec<_>>>()?
                .concat();
            Some(ConstValue::Basic(
                comps
                    .into_iter()
                    .take(c * r)
                    .map(|s| Scalar::F(f(s)))
                    .collect(),
            ))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::functions::{f32_to_half, fvec, half_to_f32, inverse};
    use super::*;

    fn c(v: &[f32]) -> ConstValue {
        fvec(v.to_vec())
    }

    #[test]
    fn matrix_times_vector_is_column_major() {
        // mat2(1, 2, 3, 4): columns (1,2) and (3,4); times (1, 1) = (4, 6).
        let m = c(&[1.0, 2.0, 3.0, 4.0]);
        let v = c(&[1.0, 1.0]);
        let r = binary(
            BinaryOp::Mul,
            &m,
            &Type::Matrix { cols: 2, rows: 2 },
            &v,
            &Type::Vector(ScalarKind::Float, 2),
            &Type::Vector(ScalarKind::Float, 2),
            &mut Vec::new(),
        )
        .unwrap();
        assert_eq!(r, c(&[4.0, 6.0]));
    }

    #[test]
    fn inverse_of_a_3x3() {
        let m = [2.0, 0.0, 0.0, 0.0, 4.0, 0.0, 1.0, 0.0, 1.0];
        let inv = inverse(&m, 3);
        // m * inv = identity.
        for col in 0..3 {
            for row in 0..3 {
                let s: f32 = (0..3).map(|k| m[k * 3 + row] * inv[col * 3 + k]).sum();
                assert!((s - if row == col { 1.0 } else { 0.0 }).abs() < 1e-6);
            }
        }
    }

    #[test]
    fn half_round_trip() {
        for v in [0.0f32, 1.0, -2.5, 65504.0, 0.000061035156] {
            assert_eq!(half_to_f32(f32_to_half(v)), v);
        }
    }

    /// Folds `a op b` of scalars, with the warnings.
    fn fold(op: BinaryOp, a: Scalar, b: Scalar, ty: &Type) -> (Scalar, Vec<FoldWarning>) {
        let mut w = Vec::new();
        let (x, y) = (ConstValue::Basic(vec![a]), ConstValue::Basic(vec![b]));
        let v = binary(op, &x, ty, &y, ty, ty, &mut w).expect("folds");
        (basic(&v).expect("a scalar")[0], w)
    }

    #[test]
    fn divisions_by_zero_fold_as_angle_does() {
        use FoldWarning::*;
        let (i, u, fl) = (&Type::INT, &Type::UINT, &Type::FLOAT);
        let div = BinaryOp::Div;
        let cases = [
            (
                div,
                Scalar::I(1),
                Scalar::I(0),
                i,
                Scalar::I(i32::MAX),
                Some(IntegerDivideByZero),
            ),
            (
                BinaryOp::Mod,
                Scalar::I(7),
                Scalar::I(0),
                i,
                Scalar::I(i32::MAX),
                Some(IntegerDivideByZero),
            ),
            (
                div,
                Scalar::U(1),
                Scalar::U(0),
                u,
                Scalar::U(u32::MAX),
                Some(IntegerDivideByZero),
            ),
            (
                div,
                Scalar::I(i32::MIN),
                Scalar::I(-1),
                i,
                Scalar::I(i32::MAX),
                None,
            ),
            (
                BinaryOp::Mod,
                Scalar::I(-7),
                Scalar::I(3),
                i,
                Scalar::I(0),
                Some(NegativeModulus),
            ),
            (
                BinaryOp::Mod,
                Scalar::I(7),
                Scalar::I(-3),
                i,
                Scalar::I(0),
                Some(NegativeModulus),
            ),
            (
                BinaryOp::Mod,
                Scalar::I(7),
                Scalar::I(3),
                i,
                Scalar::I(1),
                None,
            ),
            (
                div,
                Scalar::F(1.0),
                Scalar::F(0.0),
                fl,
                Scalar::F(f32::INFINITY),
                Some(FloatDivideByZero),
            ),
            (
                div,
                Scalar::F(-2.0),
                Scalar::F(0.0),
                fl,
                Scalar::F(f32::NEG_INFINITY),
                Some(FloatDivideByZero),
            ),
            (
                div,
                Scalar::F(2.0),
                Scalar::F(-0.0),
                fl,
                Scalar::F(f32::NEG_INFINITY),
                Some(FloatDivideByZero),
            ),
            (
                div,
                Scalar::F(1e38),
                Scalar::F(1e-5),
                fl,
                Scalar::F(f32::INFINITY),
                Some(Overflow),
            ),
            (
                div,
                Scalar::F(6.0),
                Scalar::F(3.0),
                fl,
                Scalar::F(2.0),
                None,
            ),
            (
                BinaryOp::Mul,
                Scalar::F(1e38),
                Scalar::F(10.0),
                fl,
                Scalar::F(f32::INFINITY),
                Some(Overflow),
            ),
            (
                BinaryOp::Add,
                Scalar::F(3e38),
                Scalar::F(3e38),
                fl,
                Scalar::F(f32::INFINITY),
                Some(Overflow),
            ),
            (
                BinaryOp::Add,
                Scalar::F(f32::INFINITY),
                Scalar::F(1.0),
                fl,
                Scalar::F(f32::INFINITY),
                None,
            ),
        ];
        for (op, a, b, ty, want, warning) in cases {
            let (got, w) = fold(op, a, b, ty);
            assert_eq!(
                (got, w),
                (want, warning.into_iter().collect::<Vec<_>>()),
                "{a:?} {op:?} {b:?}"
            );
        }
        for (op, a, b, warning) in [
            (div, 0.0, 0.0, ZeroByZero),
            (div, f32::INFINITY, f32::NEG_INFINITY, NotANumber),
            (BinaryOp::Sub, f32::INFINITY, f32::INFINITY, NotANumber),
            (BinaryOp::Mul, f32::INFINITY, 0.0, NotANumber),
        ] {
            let (got, w) = fold(op, Scalar::F(a), Scalar::F(b), fl);
            assert!(matches!(got, Scalar::F(v) if v.is_nan()), "{a} / {b}");
            assert_eq!(w, vec![warning]);
        }
    }
}
