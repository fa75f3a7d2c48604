//! Folding of built-in function calls, one function per family of built-ins, and the numeric
//! helpers they share (per-component mapping, matrix determinant and inverse, half floats).

use std::cell::Cell;

use super::{basic, f, FoldWarning};
use crate::builtins::BuiltinFn;
use crate::hir::{ConstValue, Scalar};
use crate::types::{ScalarKind, Type};

fn floats(c: &ConstValue) -> Option<Vec<f32>> {
    Some(basic(c)?.iter().map(|s| f(*s)).collect())
}

/// A constant of float components (a scalar, vector or matrix).
pub(super) fn fvec(v: Vec<f32>) -> ConstValue {
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

/// The inverse of an `n`×`n` column-major matrix.
pub(super) fn inverse(m: &[f32], n: usize) -> Vec<f32> {
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

/// A half float's bits as an `f32`.
pub(super) fn half_to_f32(h: u16) -> f32 {
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

/// An `f32` as half float bits, rounded to nearest.
pub(super) fn f32_to_half(v: f32) -> u16 {
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

/// Folds a built-in function call (not texture functions or derivatives). A component whose
/// result GLSL ES leaves undefined for its arguments (`sqrt(-1.0)`, `smoothstep(1.0, 0.0, x)`,
/// `normalize` of the zero vector) is 0, as ANGLE folds it
/// (`TIntermConstantUnion::foldUnaryComponentWise`, `FoldAggregateBuiltIn`), and
/// [`FoldWarning::UndefinedCall`] is added to `warnings`.
///
/// Each family of built-ins has its own function; an operation belongs to one family only, so
/// the first family that folds it gives the value.
pub fn builtin(
    op: BuiltinFn,
    args: &[&ConstValue],
    tys: &[&Type],
    ret: &Type,
    warnings: &mut Vec<FoldWarning>,
) -> Option<ConstValue> {
    let n = ret.component_count().unwrap_or(1) as usize;
    let n0 = tys.first().and_then(|t| t.component_count()).unwrap_or(1) as usize;
    let kind0 = tys.first().and_then(|t| t.scalar_kind());
    let undefined = Cell::new(false);
    let u = Undefined(&undefined);
    let v = angle_exponential(op, args, n, u)
        .or_else(|| common(op, args, tys, n, kind0, u))
        .or_else(|| packing(op, args))
        .or_else(|| geometric(op, args, n0, u))
        .or_else(|| matrix(op, args, tys, n))
        .or_else(|| vector_relational(op, args, n))?;
    if undefined.get() {
        warnings.push(FoldWarning::UndefinedCall);
    }
    Some(v)
}

/// Where a fold records that a component's result is undefined.
#[derive(Clone, Copy)]
struct Undefined<'a>(&'a Cell<bool>);

impl Undefined<'_> {
    /// `value()`, or 0 when `bad` (noted).
    fn or(self, bad: bool, value: impl FnOnce() -> f32) -> f32 {
        if bad {
            self.0.set(true);
            0.0
        } else {
            value()
        }
    }

    /// `value`, or a zero of its kind when `bad` (noted).
    fn or_scalar(self, bad: bool, value: Scalar) -> Scalar {
        if !bad {
            return value;
        }
        self.0.set(true);
        match value {
            Scalar::I(_) => Scalar::I(0),
            Scalar::U(_) => Scalar::U(0),
            Scalar::B(_) => Scalar::B(false),
            Scalar::F(_) => Scalar::F(0.0),
        }
    }
}

/// Folds angle, trigonometry and exponential functions: `radians` … `inversesqrt`.
fn angle_exponential(
    op: BuiltinFn,
    args: &[&ConstValue],
    n: usize,
    u: Undefined,
) -> Option<ConstValue> {
    use BuiltinFn::*;
    Some(match op {
        Radians => map_f(args, n, |x| x[0].to_radians())?,
        Degrees => map_f(args, n, |x| x[0].to_degrees())?,
        Sin => map_f(args, n, |x| x[0].sin())?,
        Cos => map_f(args, n, |x| x[0].cos())?,
        Tan => map_f(args, n, |x| x[0].tan())?,
        Asin => map_f(args, n, |x| u.or(x[0].abs() > 1.0, || x[0].asin()))?,
        Acos => map_f(args, n, |x| u.or(x[0].abs() > 1.0, || x[0].acos()))?,
        Atan if args.len() == 2 => map_f(args, n, |x| {
            u.or(x[0] == 0.0 && x[1] == 0.0, || x[0].atan2(x[1]))
        })?,
        Atan => map_f(args, n, |x| x[0].atan())?,
        Sinh => map_f(args, n, |x| x[0].sinh())?,
        Cosh => map_f(args, n, |x| x[0].cosh())?,
        Tanh => map_f(args, n, |x| x[0].tanh())?,
        Asinh => map_f(args, n, |x| x[0].asinh())?,
        Acosh => map_f(args, n, |x| u.or(x[0] < 1.0, || x[0].acosh()))?,
        Atanh => map_f(args, n, |x| u.or(x[0].abs() >= 1.0, || x[0].atanh()))?,
        Pow => map_f(args, n, |x| {
            let bad = x[0] < 0.0 || (x[0] == 0.0 && x[1] <= 0.0);
            u.or(bad, || x[0].powf(x[1]))
        })?,
        Exp => map_f(args, n, |x| x[0].exp())?,
        Log => map_f(args, n, |x| u.or(x[0] <= 0.0, || x[0].ln()))?,
        Exp2 => map_f(args, n, |x| x[0].exp2())?,
        // ANGLE's `logf(x) / logf(2.0f)`, not a log2: the roundings differ.
        Log2 => map_f(args, n, |x| u.or(x[0] <= 0.0, || x[0].ln() / 2f32.ln()))?,
        Sqrt => map_f(args, n, |x| u.or(x[0] < 0.0, || x[0].sqrt()))?,
        InverseSqrt => map_f(args, n, |x| u.or(x[0] <= 0.0, || 1.0 / x[0].sqrt()))?,
        _ => return None,
    })
}

/// Folds common functions: `floor` … `smoothstep`, `isnan`, `isinf` and the bit casts.
fn common(
    op: BuiltinFn,
    args: &[&ConstValue],
    tys: &[&Type],
    n: usize,
    kind0: Option<ScalarKind>,
    u: Undefined,
) -> Option<ConstValue> {
    use BuiltinFn::*;
    Some(match op {
        Floor => map_f(args, n, |x| x[0].floor())?,
        Trunc => map_f(args, n, |x| x[0].trunc())?,
        // ANGLE's `roundf`: halves away from 0.
        Round => map_f(args, n, |x| x[0].round())?,
        RoundEven => map_f(args, n, |x| x[0].round_ties_even())?,
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
                            u.or_scalar(lo > hi, Scalar::I(a.max(lo).min(hi)))
                        }
                        (Scalar::U(a), Scalar::U(lo), Scalar::U(hi)) => {
                            u.or_scalar(lo > hi, Scalar::U(a.max(lo).min(hi)))
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
        Clamp => map_f(args, n, |x| u.or(x[1] > x[2], || x[0].max(x[1]).min(x[2])))?,
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
            u.or(x[0] >= x[1], || {
                let t = ((x[2] - x[0]) / (x[1] - x[0])).clamp(0.0, 1.0);
                t * t * (3.0 - 2.0 * t)
            })
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
        _ => return None,
    })
}

/// Folds packing functions: `packSnorm2x16` … `unpackHalf2x16`.
fn packing(op: BuiltinFn, args: &[&ConstValue]) -> Option<ConstValue> {
    use BuiltinFn::*;
    Some(match op {
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
        _ => return None,
    })
}

/// Folds geometric functions: `length` … `refract`; `n0` is the first argument's size.
fn geometric(op: BuiltinFn, args: &[&ConstValue], n0: usize, u: Undefined) -> Option<ConstValue> {
    use BuiltinFn::*;
    Some(match op {
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
            fvec(a.iter().map(|x| u.or(l == 0.0, || x / l)).collect())
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
        _ => return None,
    })
}

/// Folds matrix functions: `matrixCompMult`, `outerProduct`, `transpose`, `determinant`, `inverse`.
fn matrix(op: BuiltinFn, args: &[&ConstValue], tys: &[&Type], n: usize) -> Option<ConstValue> {
    use BuiltinFn::*;
    Some(match op {
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
        _ => return None,
    })
}

/// Folds vector relational functions: `lessThan` … `not`.
fn vector_relational(op: BuiltinFn, args: &[&ConstValue], n: usize) -> Option<ConstValue> {
    use BuiltinFn::*;
    Some(match op {
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
    })
}
