//! Constant folding: GLSL ES 3.00 constant expressions evaluated in 32-bit arithmetic
//! (floats as `f32`, integers wrapping), as a GPU would.

use crate::ast::BinaryOp;
use crate::builtins::BuiltinFn;
use crate::hir::{ConstValue, Scalar, UnaryOp};
use crate::types::{ScalarKind, Type};

/// Why a constant could not be folded.
#[derive(Debug, PartialEq, Eq)]
pub enum FoldError {
    /// Integer division or remainder by zero (the result is undefined).
    DivideByZero,
    /// Not foldable (left to run time).
    Unsupported,
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

fn scalar_op(op: BinaryOp, a: Scalar, b: Scalar) -> Result<Scalar, FoldError> {
    use BinaryOp::*;
    use Scalar::*;
    Ok(match (a, b) {
        (F(x), F(y)) => match op {
            Add => F(x + y),
            Sub => F(x - y),
            Mul => F(x * y),
            Div => F(x / y),
            _ => return Err(FoldError::Unsupported),
        },
        (I(x), I(y)) => match op {
            Add => I(x.wrapping_add(y)),
            Sub => I(x.wrapping_sub(y)),
            Mul => I(x.wrapping_mul(y)),
            Div | Mod if y == 0 => return Err(FoldError::DivideByZero),
            Div => I(x.wrapping_div(y)),
            Mod => I(x.wrapping_rem(y)),
            BitAnd => I(x & y),
            BitOr => I(x | y),
            BitXor => I(x ^ y),
            _ => return Err(FoldError::Unsupported),
        },
        (U(x), U(y)) => match op {
            Add => U(x.wrapping_add(y)),
            Sub => U(x.wrapping_sub(y)),
            Mul => U(x.wrapping_mul(y)),
            Div | Mod if y == 0 => return Err(FoldError::DivideByZero),
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

/// Folds a binary operation whose result type is `rt`.
pub fn binary(
    op: BinaryOp,
    a: &ConstValue,
    at: &Type,
    b: &ConstValue,
    bt: &Type,
    rt: &Type,
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
            _ => scalar_op(op, p, q)?,
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

/// Folds a constructor.
pub fn construct(ty: &Type, args: &[&ConstValue], arg_tys: &[&Type]) -> Option<ConstValue> {
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

fn floats(c: &ConstValue) -> Option<Vec<f32>> {
    Some(basic(c)?.iter().map(|s| f(*s)).collect())
}

fn fvec(v: Vec<f32>) -> ConstValue {
    ConstValue::Basic(v.into_iter().map(Scalar::F).collect())
}

/// Applies `g` per component, broadcasting scalar arguments.
fn map_f(args: &[&ConstValue], n: usize, g: impl Fn(&[f32]) -> f32) -> Option<ConstValue> {
    let vs: Vec<Vec<f32>> = args.iter().map(|a| floats(a)).collect::<Option<_>>()?;
    let mut out = Vec::with_capacity(n);
    let mut xs = vec![0.0; vs.len()];
    for i in 0..n {
        for (j, v) in vs.iter().enumerate() {
            xs[j] = if v.len() == 1 { v[0] } else { v[i] };
        }
        out.push(g(&xs));
    }
    Some(fvec(out))
}

fn map_scalars(
    args: &[&ConstValue],
    n: usize,
    g: impl Fn(&[Scalar]) -> Option<Scalar>,
) -> Option<ConstValue> {
    let vs: Vec<&[Scalar]> = args.iter().map(|a| basic(a)).collect::<Option<_>>()?;
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let xs: Vec<Scalar> = vs
            .iter()
            .map(|v| if v.len() == 1 { v[0] } else { v[i] })
            .collect();
        out.push(g(&xs)?);
    }
    Some(ConstValue::Basic(out))
}

fn dot(a: &[f32], b: &[f32]) -> f32 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn determinant(m: &[f32], n: usize) -> f32 {
    match n {
        2 => m[0] * m[3] - m[2] * m[1],
        3 => {
            m[0] * (m[4] * m[8] - m[7] * m[5]) - m[3] * (m[1] * m[8] - m[7] * m[2])
                + m[6] * (m[1] * m[5] - m[4] * m[2])
        }
        _ => {
            let mut det = 0.0;
            for c in 0..4 {
                let minor: Vec<f32> = (0..4)
                    .filter(|&cc| cc != c)
                    .flat_map(|cc| (1..4).map(move |r| (cc, r)))
                    .map(|(cc, r)| m[cc * 4 + r])
                    .collect();
                let sign = if c % 2 == 0 { 1.0 } else { -1.0 };
                det += sign * m[c * 4] * determinant(&minor, 3);
            }
            det
        }
    }
}

fn inverse(m: &[f32], n: usize) -> Vec<f32> {
    let det = determinant(m, n);
    let mut out = vec![0.0; n * n];
    for c in 0..n {
        for r in 0..n {
            // Cofactor of element (row r, col c), transposed into (row c, col r).
            let minor: Vec<f32> = (0..n)
                .filter(|&cc| cc != c)
                .flat_map(|cc| (0..n).filter(move |&rr| rr != r).map(move |rr| (cc, rr)))
                .map(|(cc, rr)| m[cc * n + rr])
                .collect();
            let sign = if (r + c) % 2 == 0 { 1.0 } else { -1.0 };
            let cof = if n == 2 {
                minor[0]
            } else {
                determinant(&minor, n - 1)
            };
            out[r * n + c] = sign * cof / det;
        }
    }
    out
}

fn half_to_f32(h: u16) -> f32 {
    let sign = if h & 0x8000 != 0 { -1.0 } else { 1.0 };
    let exp = ((h >> 10) & 0x1f) as i32;
    let mant = (h & 0x3ff) as f32;
    sign * match exp {
        0 => mant * 2f32.powi(-24),
        31 => {
            if mant == 0.0 {
                f32::INFINITY
            } else {
                f32::NAN
            }
        }
        e => (1.0 + mant / 1024.0) * 2f32.powi(e - 15),
    }
}

fn f32_to_half(v: f32) -> u16 {
    let bits = v.to_bits();
    let sign = ((bits >> 16) & 0x8000) as u16;
    let exp = ((bits >> 23) & 0xff) as i32 - 127 + 15;
    let mant = bits & 0x7f_ffff;
    if (bits & 0x7fff_ffff) > 0x7f80_0000 {
        return sign | 0x7e00;
    }
    if exp >= 31 {
        return sign | 0x7c00;
    }
    if exp <= 0 {
        if exp < -10 {
            return sign;
        }
        let m = (mant | 0x80_0000) >> (1 - exp);
        let round = (m >> 12) & 1;
        return sign | ((m >> 13) + round) as u16;
    }
    let half = sign as u32 | ((exp as u32) << 10) | (mant >> 13);
    let round = (mant >> 12) & 1;
    (half + round) as u16
}

/// Folds a built-in function call (not texture functions or derivatives).
pub fn builtin(
    op: BuiltinFn,
    args: &[&ConstValue],
    tys: &[&Type],
    ret: &Type,
) -> Option<ConstValue> {
    use BuiltinFn::*;
    let n = ret.component_count().unwrap_or(1) as usize;
    let n0 = tys.first().and_then(|t| t.component_count()).unwrap_or(1) as usize;
    let kind0 = tys.first().and_then(|t| t.scalar_kind());
    let v = match op {
        Radians => map_f(args, n, |x| x[0].to_radians())?,
        Degrees => map_f(args, n, |x| x[0].to_degrees())?,
        Sin => map_f(args, n, |x| x[0].sin())?,
        Cos => map_f(args, n, |x| x[0].cos())?,
        Tan => map_f(args, n, |x| x[0].tan())?,
        Asin => map_f(args, n, |x| x[0].asin())?,
        Acos => map_f(args, n, |x| x[0].acos())?,
        Atan if args.len() == 2 => map_f(args, n, |x| x[0].atan2(x[1]))?,
        Atan => map_f(args, n, |x| x[0].atan())?,
        Sinh => map_f(args, n, |x| x[0].sinh())?,
        Cosh => map_f(args, n, |x| x[0].cosh())?,
        Tanh => map_f(args, n, |x| x[0].tanh())?,
        Asinh => map_f(args, n, |x| x[0].asinh())?,
        Acosh => map_f(args, n, |x| x[0].acosh())?,
        Atanh => map_f(args, n, |x| x[0].atanh())?,
        Pow => map_f(args, n, |x| x[0].powf(x[1]))?,
        Exp => map_f(args, n, |x| x[0].exp())?,
        Log => map_f(args, n, |x| x[0].ln())?,
        Exp2 => map_f(args, n, |x| x[0].exp2())?,
        Log2 => map_f(args, n, |x| x[0].log2())?,
        Sqrt => map_f(args, n, |x| x[0].sqrt())?,
        InverseSqrt => map_f(args, n, |x| 1.0 / x[0].sqrt())?,
        Floor => map_f(args, n, |x| x[0].floor())?,
        Trunc => map_f(args, n, |x| x[0].trunc())?,
        Round | RoundEven => map_f(args, n, |x| x[0].round_ties_even())?,
        Ceil => map_f(args, n, |x| x[0].ceil())?,
        Fract => map_f(args, n, |x| x[0] - x[0].floor())?,
        Mod => map_f(args, n, |x| x[0] - x[1] * (x[0] / x[1]).floor())?,
        Abs | Sign | Min | Max | Clamp if kind0 != Some(ScalarKind::Float) => {
            map_scalars(args, n, |x| {
                Some(match op {
                    Abs => match x[0] {
                        Scalar::I(v) => Scalar::I(v.wrapping_abs()),
                        s => s,
                    },
                    Sign => match x[0] {
                        Scalar::I(v) => Scalar::I(v.signum()),
                        s => s,
                    },
                    Min => match (x[0], x[1]) {
                        (Scalar::I(a), Scalar::I(b)) => Scalar::I(a.min(b)),
                        (Scalar::U(a), Scalar::U(b)) => Scalar::U(a.min(b)),
                        _ => return None,
                    },
                    Max => match (x[0], x[1]) {
                        (Scalar::I(a), Scalar::I(b)) => Scalar::I(a.max(b)),
                        (Scalar::U(a), Scalar::U(b)) => Scalar::U(a.max(b)),
                        _ => return None,
                    },
                    _ => match (x[0], x[1], x[2]) {
                        (Scalar::I(a), Scalar::I(lo), Scalar::I(hi)) => {
                            Scalar::I(a.max(lo).min(hi))
                        }
                        (Scalar::U(a), Scalar::U(lo), Scalar::U(hi)) => {
                            Scalar::U(a.max(lo).min(hi))
                        }
                        _ => return None,
                    },
                })
            })?
        }
        Abs => map_f(args, n, |x| x[0].abs())?,
        Sign => map_f(args, n, |x| {
            if x[0] > 0.0 {
                1.0
            } else if x[0] < 0.0 {
                -1.0
            } else {
                0.0
            }
        })?,
        Min => map_f(args, n, |x| x[0].min(x[1]))?,
        Max => map_f(args, n, |x| x[0].max(x[1]))?,
        Clamp => map_f(args, n, |x| x[0].max(x[1]).min(x[2]))?,
        Mix if tys[2].scalar_kind() == Some(ScalarKind::Bool) => map_scalars(args, n, |x| {
            Some(if matches!(x[2], Scalar::B(true)) {
                x[1]
            } else {
                x[0]
            })
        })?,
        Mix => map_f(args, n, |x| x[0] * (1.0 - x[2]) + x[1] * x[2])?,
        Step => map_f(args, n, |x| if x[1] < x[0] { 0.0 } else { 1.0 })?,
        SmoothStep => map_f(args, n, |x| {
            let t = ((x[2] - x[0]) / (x[1] - x[0])).clamp(0.0, 1.0);
            t * t * (3.0 - 2.0 * t)
        })?,
        IsNan => map_scalars(args, n, |x| Some(Scalar::B(f(x[0]).is_nan())))?,
        IsInf => map_scalars(args, n, |x| Some(Scalar::B(f(x[0]).is_infinite())))?,
        FloatBitsToInt => map_scalars(args, n, |x| Some(Scalar::I(f(x[0]).to_bits() as i32)))?,
        FloatBitsToUint => map_scalars(args, n, |x| Some(Scalar::U(f(x[0]).to_bits())))?,
        IntBitsToFloat | UintBitsToFloat => map_scalars(args, n, |x| {
            Some(Scalar::F(f32::from_bits(match x[0] {
                Scalar::I(v) => v as u32,
                Scalar::U(v) => v,
                _ => return None,
            })))
        })?,
        PackSnorm2x16 | PackUnorm2x16 | PackHalf2x16 => {
            let v = floats(args[0])?;
            let enc = |x: f32| -> u32 {
                match op {
                    PackSnorm2x16 => {
                        ((x.clamp(-1.0, 1.0) * 32767.0).round() as i32 as i16) as u16 as u32
                    }
                    PackUnorm2x16 => (x.clamp(0.0, 1.0) * 65535.0).round() as u32,
                    _ => f32_to_half(x) as u32,
                }
            };
            ConstValue::Basic(vec![Scalar::U(enc(v[0]) | (enc(v[1]) << 16))])
        }
        UnpackSnorm2x16 | UnpackUnorm2x16 | UnpackHalf2x16 => {
            let Scalar::U(p) = basic(args[0])?[0] else {
                return None;
            };
            let dec = |h: u32| -> f32 {
                match op {
                    UnpackSnorm2x16 => ((h as u16 as i16) as f32 / 32767.0).clamp(-1.0, 1.0),
                    UnpackUnorm2x16 => h as f32 / 65535.0,
                    _ => half_to_f32(h as u16),
                }
            };
            fvec(vec![dec(p & 0xffff), dec(p >> 16)])
        }
        Length => fvec(vec![dot(&floats(args[0])?, &floats(args[0])?).sqrt()]),
        Distance => {
            let (a, b) = (floats(args[0])?, floats(args[1])?);
            let d: Vec<f32> = a.iter().zip(&b).map(|(x, y)| x - y).collect();
            fvec(vec![dot(&d, &d).sqrt()])
        }
        Dot => fvec(vec![dot(&floats(args[0])?, &floats(args[1])?)]),
        Cross => {
            let (a, b) = (floats(args[0])?, floats(args[1])?);
            fvec(vec![
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ])
        }
        Normalize => {
            let a = floats(args[0])?;
            let l = dot(&a, &a).sqrt();
            fvec(a.iter().map(|x| x / l).collect())
        }
        FaceForward => {
            let (nn, i, nref) = (floats(args[0])?, floats(args[1])?, floats(args[2])?);
            let s = if dot(&nref, &i) < 0.0 { 1.0 } else { -1.0 };
            fvec(nn.iter().map(|x| x * s).collect())
        }
        Reflect => {
            let (i, nn) = (floats(args[0])?, floats(args[1])?);
            let d = dot(&nn, &i);
            fvec(i.iter().zip(&nn).map(|(a, b)| a - 2.0 * d * b).collect())
        }
        Refract => {
            let (i, nn, eta) = (floats(args[0])?, floats(args[1])?, floats(args[2])?[0]);
            let d = dot(&nn, &i);
            let k = 1.0 - eta * eta * (1.0 - d * d);
            if k < 0.0 {
                fvec(vec![0.0; n0])
            } else {
                fvec(
                    i.iter()
                        .zip(&nn)
                        .map(|(a, b)| eta * a - (eta * d + k.sqrt()) * b)
                        .collect(),
                )
            }
        }
        MatrixCompMult => map_f(args, n, |x| x[0] * x[1])?,
        OuterProduct => {
            let (c, r) = (floats(args[0])?, floats(args[1])?);
            let mut out = Vec::new();
            for rj in &r {
                for ci in &c {
                    out.push(ci * rj);
                }
            }
            fvec(out)
        }
        Transpose => {
            let Type::Matrix { cols, rows } = tys[0] else {
                return None;
            };
            let (c, r) = (*cols as usize, *rows as usize);
            let m = floats(args[0])?;
            let mut out = Vec::with_capacity(c * r);
            for i in 0..r {
                for j in 0..c {
                    out.push(m[j * r + i]);
                }
            }
            fvec(out)
        }
        Determinant => {
            let Type::Matrix { cols, .. } = tys[0] else {
                return None;
            };
            fvec(vec![determinant(&floats(args[0])?, *cols as usize)])
        }
        Inverse => {
            let Type::Matrix { cols, .. } = tys[0] else {
                return None;
            };
            fvec(inverse(&floats(args[0])?, *cols as usize))
        }
        LessThan | LessThanEqual | GreaterThan | GreaterThanEqual | Equal | NotEqual => {
            map_scalars(args, n, |x| {
                let ord = match (x[0], x[1]) {
                    (Scalar::F(a), Scalar::F(b)) => a.partial_cmp(&b),
                    (Scalar::I(a), Scalar::I(b)) => Some(a.cmp(&b)),
                    (Scalar::U(a), Scalar::U(b)) => Some(a.cmp(&b)),
                    (Scalar::B(a), Scalar::B(b)) => Some(a.cmp(&b)),
                    _ => return None,
                };
                Some(Scalar::B(match (op, ord) {
                    (NotEqual, None) => true,
                    (_, None) => false,
                    (LessThan, Some(o)) => o.is_lt(),
                    (LessThanEqual, Some(o)) => o.is_le(),
                    (GreaterThan, Some(o)) => o.is_gt(),
                    (GreaterThanEqual, Some(o)) => o.is_ge(),
                    (Equal, Some(o)) => o.is_eq(),
                    (_, Some(o)) => o.is_ne(),
                }))
            })?
        }
        Any => ConstValue::Basic(vec![Scalar::B(
            basic(args[0])?.iter().any(|s| matches!(s, Scalar::B(true))),
        )]),
        All => ConstValue::Basic(vec![Scalar::B(
            basic(args[0])?.iter().all(|s| matches!(s, Scalar::B(true))),
        )]),
        Not => map_scalars(args, n, |x| match x[0] {
            Scalar::B(b) => Some(Scalar::B(!b)),
            _ => None,
        })?,
        _ => return None,
    };
    Some(v)
}

#[cfg(test)]
mod tests {
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

    #[test]
    fn integer_division_by_zero_is_reported() {
        let one = ConstValue::Basic(vec![Scalar::I(1)]);
        let zero = ConstValue::Basic(vec![Scalar::I(0)]);
        assert_eq!(
            binary(
                BinaryOp::Div,
                &one,
                &Type::INT,
                &zero,
                &Type::INT,
                &Type::INT
            ),
            Err(FoldError::DivideByZero)
        );
    }
}
