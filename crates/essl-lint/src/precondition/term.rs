//! Terms: values computed from uniforms and constants only, with the operators and built-in
//! functions a condition may use, and their evaluation with the values a draw uses.

use std::fmt;

use naga::MathFunction as Mf;

use super::value::num;
use super::{Precision, UniformRef, Value};

/// A binary arithmetic operator.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BinOp {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*` (component-wise; no matrices)
    Mul,
    /// `/`
    Div,
}

/// A built-in function a [`Term`] may call.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum Func {
    Abs,
    Sign,
    Floor,
    Ceil,
    Fract,
    Trunc,
    Sqrt,
    InverseSqrt,
    Exp,
    Exp2,
    Log,
    Log2,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Atan2,
    Radians,
    Degrees,
    Normalize,
    Length,
    Distance,
    Dot,
    Cross,
    Min,
    Max,
    Pow,
    Step,
    Clamp,
    Mix,
    SmoothStep,
}

impl Func {
    pub(super) fn of(f: Mf) -> Option<Func> {
        Some(match f {
            Mf::Abs => Func::Abs,
            Mf::Sign => Func::Sign,
            Mf::Floor => Func::Floor,
            Mf::Ceil => Func::Ceil,
            Mf::Fract => Func::Fract,
            Mf::Trunc => Func::Trunc,
            Mf::Sqrt => Func::Sqrt,
            Mf::InverseSqrt => Func::InverseSqrt,
            Mf::Exp => Func::Exp,
            Mf::Exp2 => Func::Exp2,
            Mf::Log => Func::Log,
            Mf::Log2 => Func::Log2,
            Mf::Sin => Func::Sin,
            Mf::Cos => Func::Cos,
            Mf::Tan => Func::Tan,
            Mf::Asin => Func::Asin,
            Mf::Acos => Func::Acos,
            Mf::Atan => Func::Atan,
            Mf::Atan2 => Func::Atan2,
            Mf::Radians => Func::Radians,
            Mf::Degrees => Func::Degrees,
            Mf::Normalize => Func::Normalize,
            Mf::Length => Func::Length,
            Mf::Distance => Func::Distance,
            Mf::Dot => Func::Dot,
            Mf::Cross => Func::Cross,
            Mf::Min => Func::Min,
            Mf::Max => Func::Max,
            Mf::Pow => Func::Pow,
            Mf::Step => Func::Step,
            Mf::Clamp => Func::Clamp,
            Mf::Mix => Func::Mix,
            Mf::SmoothStep => Func::SmoothStep,
            _ => return None,
        })
    }

    /// The GLSL name.
    pub fn name(self) -> &'static str {
        match self {
            Func::Abs => "abs",
            Func::Sign => "sign",
            Func::Floor => "floor",
            Func::Ceil => "ceil",
            Func::Fract => "fract",
            Func::Trunc => "trunc",
            Func::Sqrt => "sqrt",
            Func::InverseSqrt => "inversesqrt",
            Func::Exp => "exp",
            Func::Exp2 => "exp2",
            Func::Log => "log",
            Func::Log2 => "log2",
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Asin => "asin",
            Func::Acos => "acos",
            Func::Atan | Func::Atan2 => "atan",
            Func::Radians => "radians",
            Func::Degrees => "degrees",
            Func::Normalize => "normalize",
            Func::Length => "length",
            Func::Distance => "distance",
            Func::Dot => "dot",
            Func::Cross => "cross",
            Func::Min => "min",
            Func::Max => "max",
            Func::Pow => "pow",
            Func::Step => "step",
            Func::Clamp => "clamp",
            Func::Mix => "mix",
            Func::SmoothStep => "smoothstep",
        }
    }
}

/// A value computed from uniforms and constants only: the same for every vertex and pixel of
/// a draw, so a renderer can compute it from the values it is about to draw with.
#[non_exhaustive]
#[derive(Clone, Debug, PartialEq)]
pub enum Term {
    /// A constant.
    Const(Value),
    /// A scalar or vector uniform (or a member or element of one).
    Uniform(UniformRef),
    /// `-x`
    Neg(Box<Term>),
    /// `a op b`, component-wise, a scalar operand broadcast.
    Binary(BinOp, Box<Term>, Box<Term>),
    /// A built-in function.
    Call(Func, Vec<Term>),
    /// `v.xz`: the components of `v` at these indices.
    Swizzle(Box<Term>, Vec<u8>),
    /// `vecN(a, b, …)`: the components of the parts, in order.
    Compose(Vec<Term>),
    /// `vecN(x)` of a scalar.
    Splat(Box<Term>, u8),
}

impl Term {
    /// Every uniform the term reads, in order, each once.
    pub fn uniforms(&self) -> Vec<&UniformRef> {
        let mut out = Vec::new();
        self.collect(&mut out);
        out
    }

    pub(super) fn collect<'a>(&'a self, out: &mut Vec<&'a UniformRef>) {
        match self {
            Term::Const(_) => {}
            Term::Uniform(u) => {
                if !out.contains(&u) {
                    out.push(u);
                }
            }
            Term::Neg(x) | Term::Swizzle(x, _) | Term::Splat(x, _) => x.collect(out),
            Term::Binary(_, a, b) => {
                a.collect(out);
                b.collect(out);
            }
            Term::Call(_, xs) | Term::Compose(xs) => xs.iter().for_each(|x| x.collect(out)),
        }
    }

    /// Whether the term is a uniform as such.
    pub fn is_uniform(&self) -> bool {
        matches!(self, Term::Uniform(_))
    }

    /// The value, with uniform values from `uniforms` and every operation rounded to
    /// `precision`; `None` when a uniform has no value or the shapes do not fit.
    pub fn eval(
        &self,
        precision: Precision,
        uniforms: &mut dyn FnMut(&UniformRef) -> Option<Value>,
    ) -> Option<Value> {
        let r = |v: Value| v.map(|x| precision.round(x));
        Some(match self {
            Term::Const(v) => *v,
            Term::Uniform(u) => r(uniforms(u)?),
            Term::Neg(x) => x.eval(precision, uniforms)?.map(|x| -x),
            Term::Binary(op, a, b) => {
                let (a, b) = (a.eval(precision, uniforms)?, b.eval(precision, uniforms)?);
                let f = match op {
                    BinOp::Add => |x: f64, y: f64| x + y,
                    BinOp::Sub => |x: f64, y: f64| x - y,
                    BinOp::Mul => |x: f64, y: f64| x * y,
                    BinOp::Div => |x: f64, y: f64| x / y,
                };
                r(zip(&[a, b], |v| f(v[0], v[1]))?)
            }
            Term::Call(func, args) => {
                let mut vs = Vec::with_capacity(args.len());
                for a in args {
                    vs.push(a.eval(precision, uniforms)?);
                }
                r(call(*func, &vs)?)
            }
            Term::Swizzle(x, idx) => {
                let v = x.eval(precision, uniforms)?;
                let c: Option<Vec<f64>> = idx
                    .iter()
                    .map(|&i| (i < v.n).then(|| v.c[i as usize]))
                    .collect();
                Value::new(&c?)
            }
            Term::Compose(parts) => {
                let mut c = Vec::new();
                for p in parts {
                    c.extend_from_slice(p.eval(precision, uniforms)?.comps());
                }
                Value::new(&c)
            }
            Term::Splat(x, n) => {
                let v = x.eval(precision, uniforms)?;
                Value::new(&vec![v.c[0]; *n as usize])
            }
        })
    }

    pub(super) fn fmt_prec(&self, f: &mut fmt::Formatter<'_>, parent: u8) -> fmt::Result {
        match self {
            Term::Const(v) => {
                if v.n == 1 {
                    f.write_str(&num(v.c[0]))
                } else {
                    let parts: Vec<String> = v.comps().iter().map(|x| num(*x)).collect();
                    write!(f, "vec{}({})", v.n, parts.join(", "))
                }
            }
            Term::Uniform(u) => write!(f, "{u}"),
            Term::Neg(x) => {
                f.write_str("-")?;
                x.fmt_prec(f, 3)
            }
            Term::Binary(op, a, b) => {
                let (p, s) = match op {
                    BinOp::Add => (1, " + "),
                    BinOp::Sub => (1, " - "),
                    BinOp::Mul => (2, " * "),
                    BinOp::Div => (2, " / "),
                };
                if p < parent {
                    f.write_str("(")?;
                }
                a.fmt_prec(f, p)?;
                f.write_str(s)?;
                b.fmt_prec(f, p + 1)?;
                if p < parent {
                    f.write_str(")")?;
                }
                Ok(())
            }
            Term::Call(func, args) => {
                write!(f, "{}(", func.name())?;
                for (i, a) in args.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    a.fmt_prec(f, 0)?;
                }
                f.write_str(")")
            }
            Term::Swizzle(x, idx) => {
                x.fmt_prec(f, 4)?;
                f.write_str(".")?;
                for &i in idx {
                    f.write_str(["x", "y", "z", "w"][i.min(3) as usize])?;
                }
                Ok(())
            }
            Term::Compose(parts) => {
                let n: usize = parts.len();
                write!(f, "vec(")?;
                for (i, a) in parts.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    a.fmt_prec(f, 0)?;
                }
                let _ = n;
                f.write_str(")")
            }
            Term::Splat(x, n) => {
                write!(f, "vec{n}(")?;
                x.fmt_prec(f, 0)?;
                f.write_str(")")
            }
        }
    }
}

impl fmt::Display for Term {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.fmt_prec(f, 0)
    }
}

/// Component-wise `f` of values of equal width (scalars broadcast).
pub(super) fn zip(vs: &[Value], f: impl Fn(&[f64]) -> f64) -> Option<Value> {
    let n = vs.iter().map(|v| v.n).max()?;
    if vs.iter().any(|v| v.n != 1 && v.n != n) {
        return None;
    }
    let c: Vec<f64> = (0..n as usize)
        .map(|i| f(&vs.iter().map(|v| v.at(i)).collect::<Vec<_>>()))
        .collect();
    Some(Value::new(&c))
}

/// Whether `x < y` fails (NaN included).
pub(super) fn not_below(x: f64, y: f64) -> bool {
    x.partial_cmp(&y) != Some(std::cmp::Ordering::Less)
}

pub(super) fn call(func: Func, v: &[Value]) -> Option<Value> {
    let one = |f: fn(f64) -> f64| v.first().map(|x| x.map(f));
    Some(match func {
        Func::Abs => one(f64::abs)?,
        Func::Sign => one(|x| if x == 0.0 { 0.0 } else { x.signum() })?,
        Func::Floor => one(f64::floor)?,
        Func::Ceil => one(f64::ceil)?,
        Func::Fract => one(|x| x - x.floor())?,
        Func::Trunc => one(f64::trunc)?,
        Func::Sqrt => one(f64::sqrt)?,
        Func::InverseSqrt => one(|x| 1.0 / x.sqrt())?,
        Func::Exp => one(f64::exp)?,
        Func::Exp2 => one(f64::exp2)?,
        Func::Log => one(f64::ln)?,
        Func::Log2 => one(f64::log2)?,
        Func::Sin => one(f64::sin)?,
        Func::Cos => one(f64::cos)?,
        Func::Tan => one(f64::tan)?,
        Func::Asin => one(|x| if x.abs() > 1.0 { f64::NAN } else { x.asin() })?,
        Func::Acos => one(|x| if x.abs() > 1.0 { f64::NAN } else { x.acos() })?,
        Func::Atan => one(f64::atan)?,
        Func::Radians => one(f64::to_radians)?,
        Func::Degrees => one(f64::to_degrees)?,
        Func::Normalize => {
            let x = v.first()?;
            let l = x.dot(x).sqrt();
            x.map(|c| c / l)
        }
        Func::Length => {
            let x = v.first()?;
            Value::scalar(x.dot(x).sqrt())
        }
        Func::Distance => {
            let d = zip(v.get(..2)?, |c| c[0] - c[1])?;
            Value::scalar(d.dot(&d).sqrt())
        }
        Func::Dot => Value::scalar(v.first()?.dot(v.get(1)?)),
        Func::Cross => {
            let (a, b) = (v.first()?, v.get(1)?);
            if a.n != 3 || b.n != 3 {
                return None;
            }
            let (a, b) = (a.c, b.c);
            Value::new(&[
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ])
        }
        Func::Atan2 => zip(v.get(..2)?, |c| c[0].atan2(c[1]))?,
        Func::Min => zip(v.get(..2)?, |c| c[0].min(c[1]))?,
        Func::Max => zip(v.get(..2)?, |c| c[0].max(c[1]))?,
        Func::Pow => zip(v.get(..2)?, |c| {
            if c[0] < 0.0 || (c[0] == 0.0 && c[1] <= 0.0) {
                f64::NAN
            } else {
                c[0].powf(c[1])
            }
        })?,
        Func::Step => zip(v.get(..2)?, |c| if c[1] < c[0] { 0.0 } else { 1.0 })?,
        Func::Clamp => zip(v.get(..3)?, |c| c[0].max(c[1]).min(c[2]))?,
        Func::Mix => zip(v.get(..3)?, |c| c[0] * (1.0 - c[2]) + c[1] * c[2])?,
        Func::SmoothStep => zip(v.get(..3)?, |c| {
            let t = ((c[2] - c[0]) / (c[1] - c[0])).clamp(0.0, 1.0);
            t * t * (3.0 - 2.0 * t)
        })?,
    })
}
