//! Uniform preconditions: what the static rules leave to run time, as conditions on uniform
//! values that a renderer can evaluate with the values it is about to draw with.
//!
//! The static rules take a uniform's value to be valid — `normalize(u_lightDirection)`,
//! `pow(…, u_shininess)` and `acos(u_coneCos)` are not reported, and
//! `smoothstep(u_outerLimit, u_innerLimit, d)` is reported but cannot be decided. For each such
//! expression [`preconditions`] runs the same analysis ([`crate::analysis`], the guards and
//! the symbolic facts the rules use) and, where the value at risk is computed from uniforms and
//! constants only, exports it as a [`Term`] over the uniforms it reads, in a [`Condition`]:
//!
//! | rule | condition | from |
//! |---|---|---|
//! | `smoothstep-edges` | [`Condition::Less`]`(edge0, edge1)` | `smoothstep` whose edges the shader does not order |
//! | `division-by-difference` | [`Condition::NotEqual`]`(a, b)` | `x / (a - b)` not kept away from 0 |
//! | `division-by-zero` | [`Condition::NonZero`]`(d)` | any other divisor computed from uniforms (`gl_FragCoord.xy / u_viewport`) |
//! | `normalize-zero` | [`Condition::NonZeroVector`]`(v)`, [`Condition::NotParallel`]`(a, b)` | `normalize(v)`, `normalize(cross(a, b))` |
//! | `pow-zero-base` | [`Condition::Positive`]`(y)`, [`Condition::PowBaseZero`] | `pow(x, y)` with a base that can be 0 |
//! | `pow-negative-base` | [`Condition::NonNegative`]`(x)` | `pow(x, y)` with a base from uniforms |
//! | `acos-domain`, `asin-domain` | [`Condition::WithinUnit`]`(x)` | `acos(x)`, `asin(x)` of a value from uniforms |
//! | `non-finite-uniform` | [`Condition::Finite`]`(u)` | every uniform the shader reads |
//!
//! Values passed to a function are followed through its call sites (one precondition per call
//! site whose arguments differ), so three.js's `getSpotAttenuation(spotLight.coneCos,
//! spotLight.penumbraCos, …)` gives `spotLights[0].coneCos < spotLights[0].penumbraCos`.
//! A dynamic index (`u_lights[i]`) becomes [`PathStep::AnyIndex`]: the condition holds for
//! every element.
//!
//! ```
//! use essl::source::SourceFile;
//! use essl::{compile, CompileOptions, Stage};
//!
//! let text = "#version 300 es\nprecision highp float;\nin float d;\nuniform float u_inner;\n\
//!             uniform float u_outer;\nout vec4 o;\n\
//!             void main() { o = vec4(smoothstep(u_outer, u_inner, d)); }\n";
//! let shader = compile(SourceFile::new("a.frag", text), Stage::Fragment, &CompileOptions::default());
//! let pre = essl_lint::preconditions(&shader);
//! let edges = pre.iter().find(|p| p.rule == "smoothstep-edges").unwrap();
//! assert_eq!(edges.condition.to_string(), "u_outer < u_inner");
//! assert_eq!(edges.uniform_names(), ["u_outer", "u_inner"]);
//! ```

use std::collections::HashMap;
use std::fmt;

use essl::source::{SourceFile, Span};
use essl::{Shader, Stage};
use naga::{
    BinaryOperator as Bo, Expression as E, Function, Handle, Literal, MathFunction as Mf,
    ScalarKind, Statement, TypeInner, UnaryOperator as Uo,
};

use crate::analysis::{self, literal};
use crate::interval::Interval;
use crate::rules::{Cx, RULES};
use crate::symbolic::resolve;

/// The name essl's lowering gives the struct that holds the default uniform block.
const DEFAULT_BLOCK: &str = "_essl_uniforms";
/// The most call-site contexts followed for one function.
const MAX_CONTEXTS: usize = 32;
/// The deepest call chain followed.
const MAX_CALL_DEPTH: u32 = 6;

/// The rule id of the runtime-only check of a divisor computed from uniforms.
pub const DIVISION_BY_ZERO: &str = "division-by-zero";
/// The rule id of the runtime-only check that every uniform value is finite.
pub const NON_FINITE_UNIFORM: &str = "non-finite-uniform";

/// One step from a uniform to a part of it.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum PathStep {
    /// A struct member (`.cutOff`).
    Member(String),
    /// A constant array index (`[2]`).
    Index(u32),
    /// A dynamic array index (`[i]`): any element.
    AnyIndex,
}

/// A uniform or a part of it, as WebGL names it: `u_innerLimit`, `light.cutOff`,
/// `spotLights[0].coneCos`, `u_lights[*].position` (any element).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct UniformRef {
    /// The uniform's declared name.
    pub base: String,
    /// Members and indices from it.
    pub path: Vec<PathStep>,
}

impl UniformRef {
    /// A uniform itself.
    pub fn new(base: impl Into<String>) -> UniformRef {
        UniformRef {
            base: base.into(),
            path: Vec::new(),
        }
    }

    /// Whether a step is [`PathStep::AnyIndex`].
    pub fn has_any_index(&self) -> bool {
        self.path.contains(&PathStep::AnyIndex)
    }

    /// The WebGL name (`getUniformLocation`'s), with `index` for every
    /// [`PathStep::AnyIndex`] (`*` for `None`).
    pub fn name(&self, index: Option<u32>) -> String {
        let mut s = self.base.clone();
        for step in &self.path {
            match step {
                PathStep::Member(m) => {
                    s.push('.');
                    s.push_str(m);
                }
                PathStep::Index(i) => s.push_str(&format!("[{i}]")),
                PathStep::AnyIndex => match index {
                    Some(i) => s.push_str(&format!("[{i}]")),
                    None => s.push_str("[*]"),
                },
            }
        }
        s
    }

    /// Whether the value WebGL names `name` (a leaf such as `spotLights[0].coneCos` or
    /// `u_weights[3]`) is this uniform or a part of it; `[*]` matches any index.
    pub fn covers(&self, name: &str) -> bool {
        let pattern = self.name(None);
        let (mut p, mut n) = (pattern.as_str(), name);
        loop {
            match p.find("[*]") {
                Some(i) => {
                    if n.len() < i || p[..i] != n[..i] {
                        return false;
                    }
                    let rest = &n[i..];
                    let Some(after) = rest.strip_prefix('[') else {
                        return false;
                    };
                    let digits = after.bytes().take_while(u8::is_ascii_digit).count();
                    if digits == 0 || !after[digits..].starts_with(']') {
                        return false;
                    }
                    n = &after[digits + 1..];
                    p = &p[i + 3..];
                }
                None => {
                    return n == p
                        || (n.starts_with(p)
                            && matches!(n.as_bytes().get(p.len()), Some(b'.' | b'[')));
                }
            }
        }
    }
}

impl fmt::Display for UniformRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name(None))
    }
}

/// A scalar or vector value (1 to 4 components).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Value {
    /// The number of components.
    pub n: u8,
    /// The components (those past `n` are 0).
    pub c: [f64; 4],
}

impl Value {
    /// A scalar.
    pub fn scalar(x: f64) -> Value {
        Value {
            n: 1,
            c: [x, 0.0, 0.0, 0.0],
        }
    }

    /// A vector of the given components (1 to 4; more are dropped).
    pub fn new(c: &[f64]) -> Value {
        let mut v = Value {
            n: c.len().clamp(1, 4) as u8,
            c: [0.0; 4],
        };
        for (i, x) in c.iter().take(4).enumerate() {
            v.c[i] = *x;
        }
        v
    }

    /// The used components.
    pub fn comps(&self) -> &[f64] {
        &self.c[..self.n as usize]
    }

    fn map(self, f: impl Fn(f64) -> f64) -> Value {
        let mut v = self;
        for x in &mut v.c[..self.n as usize] {
            *x = f(*x);
        }
        v
    }

    /// Component `i`, or the scalar itself for a scalar (GLSL's scalar-vector broadcast).
    fn at(&self, i: usize) -> f64 {
        if self.n == 1 {
            self.c[0]
        } else {
            self.c[i]
        }
    }

    fn dot(&self, o: &Value) -> f64 {
        (0..self.n.max(o.n) as usize)
            .map(|i| self.at(i) * o.at(i))
            .sum()
    }
}

/// Writes a number as the `f32` it came from (`0.9`, not `0.8999999761581421`).
fn num(x: f64) -> String {
    if x.is_nan() {
        "NaN".into()
    } else if x.is_infinite() {
        if x > 0.0 { "+inf" } else { "-inf" }.into()
    } else {
        format!("{}", x as f32)
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.n == 1 {
            return f.write_str(&num(self.c[0]));
        }
        let parts: Vec<String> = self.comps().iter().map(|x| num(*x)).collect();
        write!(f, "({})", parts.join(", "))
    }
}

/// The precision a condition is evaluated in: each operation's result is rounded to it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Precision {
    /// `highp`: 32-bit floats.
    High,
    /// `mediump` or `lowp`: 16-bit floats, as phones compute them (desktop GPUs and lavapipe
    /// use 32 bits, so the hazard shows on some devices only).
    Low,
}

impl Precision {
    /// `x` rounded to this precision (to nearest, ties to even; 16-bit overflow is ±∞).
    pub fn round(self, x: f64) -> f64 {
        match self {
            Precision::High => x as f32 as f64,
            Precision::Low => round_f16(x),
        }
    }

    /// The smallest normal number: a squared length below it may flush to 0.
    pub fn min_normal(self) -> f64 {
        match self {
            Precision::High => f32::MIN_POSITIVE as f64,
            Precision::Low => 6.103515625e-5,
        }
    }

    /// The relative rounding error of one operation.
    pub fn epsilon(self) -> f64 {
        match self {
            Precision::High => f32::EPSILON as f64,
            Precision::Low => 1.0 / 1024.0,
        }
    }

    /// `"highp"` or `"mediump"`.
    pub fn name(self) -> &'static str {
        match self {
            Precision::High => "highp",
            Precision::Low => "mediump",
        }
    }
}

/// `x` rounded to the nearest IEEE binary16 value (subnormals kept, overflow to ±∞).
fn round_f16(x: f64) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x;
    }
    let a = x.abs();
    if a >= 65520.0 {
        return f64::INFINITY.copysign(x);
    }
    let e = (((a.to_bits() >> 52) & 0x7ff) as i32 - 1023).max(-14);
    let q = 2f64.powi(e - 10);
    (x / q).round_ties_even() * q
}

/// A binary arithmetic operator.
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
    fn of(f: Mf) -> Option<Func> {
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

    fn collect<'a>(&'a self, out: &mut Vec<&'a UniformRef>) {
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

    fn fmt_prec(&self, f: &mut fmt::Formatter<'_>, parent: u8) -> fmt::Result {
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
fn zip(vs: &[Value], f: impl Fn(&[f64]) -> f64) -> Option<Value> {
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
fn not_below(x: f64, y: f64) -> bool {
    x.partial_cmp(&y) != Some(std::cmp::Ordering::Less)
}

fn call(func: Func, v: &[Value]) -> Option<Value> {
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

/// A condition on uniform values under which an expression of the shader is defined.
#[derive(Clone, Debug, PartialEq)]
pub enum Condition {
    /// `a < b` in every component (`smoothstep`'s edges).
    Less(Term, Term),
    /// `a != b` in every component, so that `a - b` is not 0 (a divisor).
    NotEqual(Term, Term),
    /// No component is 0 (a divisor).
    NonZero(Term),
    /// Not the zero vector, nor so short that its squared length flushes to 0
    /// (`normalize(v)`).
    NonZeroVector(Term),
    /// Two vectors that are not parallel and not zero (`normalize(cross(a, b))`).
    NotParallel(Term, Term),
    /// Every component `> 0` (an exponent where the base can be 0).
    Positive(Term),
    /// Every component `>= 0` (a `pow` base).
    NonNegative(Term),
    /// Not `base == 0` with `exponent <= 0` in any component (`pow`).
    PowBaseZero {
        /// The base.
        base: Term,
        /// The exponent.
        exponent: Term,
    },
    /// Every component in `[-1, 1]` (`acos`, `asin`).
    WithinUnit(Term),
    /// Every component of the uniform (every member and element of a struct or array) is
    /// finite: no NaN, no ±∞.
    Finite(UniformRef),
}

/// The result of evaluating a [`Condition`].
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// The condition holds.
    Holds,
    /// It does not: what is wrong, with the values (`` `u_innerLimit` = 0.9 equals
    /// `u_outerLimit` = 0.9 ``).
    Violated(String),
    /// It cannot be evaluated (a uniform without a value, shapes that do not fit).
    Unknown,
}

impl Condition {
    /// The terms the condition compares.
    pub fn terms(&self) -> Vec<&Term> {
        match self {
            Condition::Less(a, b)
            | Condition::NotEqual(a, b)
            | Condition::NotParallel(a, b)
            | Condition::PowBaseZero {
                base: a,
                exponent: b,
            } => vec![a, b],
            Condition::NonZero(a)
            | Condition::NonZeroVector(a)
            | Condition::Positive(a)
            | Condition::NonNegative(a)
            | Condition::WithinUnit(a) => vec![a],
            Condition::Finite(_) => Vec::new(),
        }
    }

    /// Every uniform the condition reads, in order, each once.
    pub fn uniforms(&self) -> Vec<&UniformRef> {
        if let Condition::Finite(u) = self {
            return vec![u];
        }
        let mut out = Vec::new();
        for t in self.terms() {
            t.collect(&mut out);
        }
        out
    }

    /// Evaluates the condition with the uniform values `uniforms` gives, every operation
    /// rounded to `precision` (a mediump `u_a - u_b` is 0 when both round to the same 16-bit
    /// float).
    pub fn check(
        &self,
        precision: Precision,
        uniforms: &mut dyn FnMut(&UniformRef) -> Option<Value>,
    ) -> Outcome {
        match self.check_inner(precision, uniforms) {
            Some(Some(why)) => Outcome::Violated(why),
            Some(None) => Outcome::Holds,
            None => Outcome::Unknown,
        }
    }

    fn check_inner(
        &self,
        p: Precision,
        uniforms: &mut dyn FnMut(&UniformRef) -> Option<Value>,
    ) -> Option<Option<String>> {
        let terms = self.terms();
        let mut vals = Vec::with_capacity(terms.len());
        for t in &terms {
            vals.push(t.eval(p, uniforms)?);
        }
        // Shown as set (a mediump comparison rounds them; the message says "in mediump").
        let mut shown_vals = vals.clone();
        if p == Precision::Low {
            for (v, t) in shown_vals.iter_mut().zip(&terms) {
                if let Some(x) = t.eval(Precision::High, uniforms) {
                    *v = x;
                }
            }
        }
        let shown = |i: usize| format!("`{}` = {}", terms[i], shown_vals[i]);
        let wide = |a: &Value, b: &Value| -> Option<usize> {
            let n = a.n.max(b.n);
            (a.n == 1 || b.n == 1 || a.n == b.n).then_some(n as usize)
        };
        let in_p = if p == Precision::Low {
            " in mediump"
        } else {
            ""
        };
        Some(match self {
            Condition::Less(..) => {
                let (a, b) = (&vals[0], &vals[1]);
                let n = wide(a, b)?;
                let bad = (0..n).find(|&i| not_below(a.at(i), b.at(i)));
                bad.map(|i| {
                    let (x, y) = (a.at(i), b.at(i));
                    let how = if x.is_nan() || y.is_nan() {
                        "NaN"
                    } else if x == y {
                        "equal"
                    } else {
                        "swapped"
                    };
                    format!("{} is not below {} ({how}{in_p})", shown(0), shown(1))
                })
            }
            Condition::NotEqual(..) => {
                let (a, b) = (&vals[0], &vals[1]);
                let n = wide(a, b)?;
                (0..n)
                    .any(|i| p.round(a.at(i) - b.at(i)) == 0.0)
                    .then(|| format!("{} equals {}{in_p}", shown(0), shown(1)))
            }
            Condition::NonZero(_) => vals[0]
                .comps()
                .contains(&0.0)
                .then(|| format!("{} is 0{in_p}", shown(0))),
            Condition::NonZeroVector(_) => {
                let v = &vals[0];
                let len2 = p.round(v.dot(v));
                if v.comps().iter().all(|x| *x == 0.0) {
                    Some(format!("{} is the zero vector", shown(0)))
                } else if len2 < p.min_normal() {
                    Some(format!(
                        "{} is too short to normalise{in_p}: its squared length {} is below {}",
                        shown(0),
                        num(len2),
                        num(p.min_normal())
                    ))
                } else {
                    None
                }
            }
            Condition::NotParallel(..) => {
                let (a, b) = (&vals[0], &vals[1]);
                if a.n != 3 || b.n != 3 {
                    return None;
                }
                let c = call(Func::Cross, &[*a, *b])?.map(|x| p.round(x));
                let c2 = c.dot(&c);
                let limit = (p.epsilon() * p.epsilon()) * a.dot(a) * b.dot(b);
                if a.comps().iter().all(|x| *x == 0.0) || b.comps().iter().all(|x| *x == 0.0) {
                    Some(format!(
                        "{} and {}: one is the zero vector, so their cross product is",
                        shown(0),
                        shown(1)
                    ))
                } else if c2 < p.min_normal() || c2 <= limit {
                    Some(format!(
                        "{} and {} are parallel{in_p}: their cross product is {}",
                        shown(0),
                        shown(1),
                        c
                    ))
                } else {
                    None
                }
            }
            Condition::Positive(_) => vals[0]
                .comps()
                .iter()
                .any(|x| x.is_nan() || *x <= 0.0)
                .then(|| format!("{} is not > 0", shown(0))),
            Condition::NonNegative(_) => vals[0]
                .comps()
                .iter()
                .any(|x| x.is_nan() || *x < 0.0)
                .then(|| format!("{} is negative", shown(0))),
            Condition::PowBaseZero { .. } => {
                let (a, b) = (&vals[0], &vals[1]);
                let n = wide(a, b)?;
                (0..n)
                    .any(|i| a.at(i) == 0.0 && (b.at(i).is_nan() || b.at(i) <= 0.0))
                    .then(|| {
                        format!(
                            "the base {} is 0 and the exponent {} is not > 0",
                            shown(0),
                            shown(1)
                        )
                    })
            }
            Condition::WithinUnit(_) => vals[0]
                .comps()
                .iter()
                .any(|x| !(-1.0..=1.0).contains(x))
                .then(|| format!("{} is outside [-1, 1]", shown(0))),
            Condition::Finite(u) => {
                let v = uniforms(u)?;
                (!v.comps().iter().all(|x| x.is_finite()))
                    .then(|| format!("`{u}` = {v} is not finite"))
            }
        })
    }
}

impl fmt::Display for Condition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Condition::Less(a, b) => write!(f, "{a} < {b}"),
            Condition::NotEqual(a, b) => write!(f, "{a} != {b}"),
            Condition::NonZero(a) => write!(f, "{a} != 0"),
            Condition::NonZeroVector(a) => write!(f, "length({a}) > 0"),
            Condition::NotParallel(a, b) => write!(f, "length(cross({a}, {b})) > 0"),
            Condition::Positive(a) => write!(f, "{a} > 0"),
            Condition::NonNegative(a) => write!(f, "{a} >= 0"),
            Condition::PowBaseZero { base, exponent } => {
                write!(f, "{base} != 0 || {exponent} > 0")
            }
            Condition::WithinUnit(a) => write!(f, "-1 <= {a} <= 1"),
            Condition::Finite(u) => write!(f, "isfinite({u})"),
        }
    }
}

/// A condition on uniform values that an expression of the shader needs, found by the
/// analysis the static rules use.
#[derive(Clone, Debug, PartialEq)]
pub struct Precondition {
    /// The rule: a static rule's id (`smoothstep-edges`, …), or a runtime-only one
    /// ([`DIVISION_BY_ZERO`], [`NON_FINITE_UNIFORM`]).
    pub rule: &'static str,
    /// What must hold.
    pub condition: Condition,
    /// The expression at risk (the static rule's span where it has a finding): into the
    /// shader's text.
    pub span: Span,
    /// The shader's stage.
    pub stage: Stage,
    /// The calls through which the uniform values reach [`Precondition::span`], outermost
    /// first (empty when the expression reads the uniforms itself).
    pub call_sites: Vec<Span>,
    /// The precision the expression is computed in.
    pub precision: Precision,
    /// What goes wrong when the condition fails, in a sentence.
    pub message: String,
    /// Whether the static lint reports a finding of the same rule at this expression (the
    /// hazard is reported either way; the runtime check says when it happens).
    pub reported: bool,
}

impl Precondition {
    /// The uniforms the condition reads, in order.
    pub fn uniforms(&self) -> Vec<&UniformRef> {
        self.condition.uniforms()
    }

    /// The WebGL names of the uniforms the condition reads (`[*]` for any element).
    pub fn uniform_names(&self) -> Vec<String> {
        self.uniforms().iter().map(|u| u.name(None)).collect()
    }

    /// Whether the condition is on every element of an array (a dynamic index).
    pub fn has_any_index(&self) -> bool {
        self.uniforms().iter().any(|u| u.has_any_index())
    }

    /// Evaluates the condition: see [`Condition::check`].
    pub fn check(&self, uniforms: &mut dyn FnMut(&UniformRef) -> Option<Value>) -> Outcome {
        self.condition.check(self.precision, uniforms)
    }

    /// One line: `file:line:col rule: condition (message)`.
    pub fn describe(&self, file: &SourceFile) -> String {
        let lc = file.line_col(self.span.start);
        format!(
            "{}:{}:{} {}: {} — {}",
            file.name(),
            lc.line,
            lc.column,
            self.rule,
            self.condition,
            self.message
        )
    }
}

/// The uniform preconditions of a compiled shader, in source order (a shader that did not
/// compile has none). Every one is a condition on the values of uniforms of the default block
/// (what `uniform*` sets); members of uniform blocks are not followed.
pub fn preconditions(shader: &Shader) -> Vec<Precondition> {
    let Some(cx) = Cx::new(shader) else {
        return Vec::new();
    };
    let ex = Extractor::new(&cx, shader.stage);
    let mut out = Vec::new();
    for (id, f) in cx.functions() {
        ex.function(id, f, &mut out);
    }
    ex.finite(&mut out);
    // What the static rules report, to say which preconditions they also flag.
    let mut found = Vec::new();
    for r in RULES {
        (r.check)(&cx, &mut found);
    }
    for p in &mut out {
        p.reported = found
            .iter()
            .any(|d| d.code == p.rule && d.span.start < p.span.end && p.span.start < d.span.end);
    }
    let mut seen = Vec::new();
    out.retain(|p| {
        let key = (p.rule, p.span, p.condition.clone());
        if seen.contains(&key) {
            false
        } else {
            seen.push(key);
            true
        }
    });
    out.sort_by_key(|p| (p.span.start, p.span.end, p.rule));
    out
}

/// A value the extraction follows: a term, an aggregate of them (a struct built by the
/// shader), or a uniform place not yet read down to a scalar or vector.
#[derive(Clone, Debug, PartialEq)]
enum X {
    Num(Term),
    Agg(Vec<Option<X>>),
    Place(UniformRef, Handle<naga::Type>),
}

#[derive(Clone, Copy, Debug)]
enum Step {
    Index(u32),
    Dynamic,
}

/// The values of a function's parameters at one call site (and the calls that lead there).
#[derive(Clone, Debug, Default)]
struct Context {
    args: Vec<Option<X>>,
    sites: Vec<Span>,
}

struct CallSite {
    caller: usize,
    args: Vec<Handle<E>>,
    span: Span,
}

struct Extractor<'a> {
    cx: &'a Cx<'a>,
    module: &'a naga::Module,
    stage: Stage,
    calls: HashMap<usize, Vec<CallSite>>,
    contexts: std::cell::RefCell<HashMap<usize, Vec<Context>>>,
}

impl<'a> Extractor<'a> {
    fn new(cx: &'a Cx<'a>, stage: Stage) -> Extractor<'a> {
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
        analysis::function_info(self.module, self.cx.info, id)[h]
            .ty
            .inner_with(&self.module.types)
    }

    fn is_pointer(&self, id: usize, h: Handle<E>) -> bool {
        matches!(
            self.inner(id, h),
            TypeInner::Pointer { .. } | TypeInner::ValuePointer { .. }
        )
    }

    /// The parameter values of function `id` at each call site that reaches it.
    fn contexts(&self, id: usize, depth: u32) -> Vec<Context> {
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
    fn term(&self, id: usize, ctx: &Context, h: Handle<E>) -> Option<Term> {
        match self.value(id, ctx, h, 0)? {
            X::Num(t) if !t.uniforms().is_empty() => Some(t),
            _ => None,
        }
    }

    fn value(&self, id: usize, ctx: &Context, h: Handle<E>, depth: u32) -> Option<X> {
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
                let n = self.cx.sound.num(id, h)?;
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
            .sound
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
                    let v = *self.cx.sound.functions[id].single_store.get(&l.index())?;
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
    fn uniform_of_pointer(&self, id: usize, pointer: Handle<E>) -> Option<UniformRef> {
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

    fn precondition(
        &self,
        rule: &'static str,
        condition: Condition,
        span: Span,
        ctx: &Context,
        low: bool,
        message: String,
    ) -> Precondition {
        Precondition {
            rule,
            condition,
            span,
            stage: self.stage,
            call_sites: ctx.sites.clone(),
            precision: if low { Precision::Low } else { Precision::High },
            message,
            reported: false,
        }
    }

    fn quote(&self, span: Span) -> String {
        let t: String = self
            .cx
            .text(span)
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        if t.chars().count() > 60 {
            format!("{}…", t.chars().take(59).collect::<String>())
        } else {
            t
        }
    }

    /// The preconditions of the expressions of one function.
    fn function(&self, id: usize, f: &Function, out: &mut Vec<Precondition>) {
        let cx = self.cx;
        let sym = cx.sym(id, f);
        let mut contexts: Option<Vec<Context>> = None;
        let mut ctxs =
            || -> Vec<Context> { contexts.get_or_insert_with(|| self.contexts(id, 0)).clone() };
        let may_be_zero = |x: Handle<E>, g: &crate::rules::Guards| -> bool {
            cx.refined(f, id, x, g)
                .is_some_and(|v| v.comps().iter().any(|c| c.contains(0.0)))
        };
        for (h, e) in f.expressions.iter() {
            let span = cx.span(f, h);
            if span.is_empty() {
                continue;
            }
            let low = cx.prec.is_low(span);
            match *e {
                E::Math {
                    fun: Mf::SmoothStep,
                    arg,
                    arg1: Some(a1),
                    ..
                } => {
                    let (e0, e1) = (cx.operand(f, h, arg), cx.operand(f, h, a1));
                    let constant = |x: Handle<E>| {
                        cx.sound
                            .num(id, x)
                            .is_some_and(|v| v.comps().iter().all(|c| c.as_point().is_some()))
                    };
                    if (constant(e0) && constant(e1))
                        || sym.diff_lower(Some(e1), Some(e0)) > 0.0
                        || cx.ordered(f, id, e0, e1, &cx.guards(f, id, h))
                    {
                        continue;
                    }
                    for ctx in ctxs() {
                        let (Some(t0), Some(t1)) = (
                            self.value(id, &ctx, e0, 0).and_then(as_num),
                            self.value(id, &ctx, e1, 0).and_then(as_num),
                        ) else {
                            continue;
                        };
                        if t0.uniforms().is_empty() && t1.uniforms().is_empty() {
                            continue;
                        }
                        out.push(
                            self.precondition(
                                "smoothstep-edges",
                                Condition::Less(t0, t1),
                                span,
                                &ctx,
                                low,
                                "`smoothstep(edge0, edge1, x)` is undefined unless edge0 < edge1 \
                             (GLSL ES 3.00 §8.3): NaN where x equals the edges, or a hard or \
                             inverted edge"
                                    .into(),
                            ),
                        );
                    }
                }
                E::Binary {
                    op: Bo::Divide,
                    right,
                    ..
                } => {
                    let d = cx.operand(f, h, right);
                    if !matches!(
                        cx.kind(id, d),
                        Some(ScalarKind::Float | ScalarKind::Sint | ScalarKind::Uint)
                    ) || sym.nonzero(d)
                    {
                        continue;
                    }
                    let g = cx.guards(f, id, h);
                    if cx.nonzero(f, id, d, &g) || !may_be_zero(d, &g) {
                        continue;
                    }
                    let dspan = cx.span(f, d);
                    if dspan.is_empty() {
                        continue;
                    }
                    let def = resolve(f, &cx.sound, id, d);
                    for ctx in ctxs() {
                        let Some(t) = self.term(id, &ctx, d) else {
                            continue;
                        };
                        let diff = match f.expressions[def] {
                            E::Binary {
                                op: Bo::Subtract,
                                left,
                                right,
                            } => self
                                .value(id, &ctx, left, 0)
                                .and_then(as_num)
                                .zip(self.value(id, &ctx, right, 0).and_then(as_num)),
                            _ => None,
                        };
                        let p = match diff {
                            Some((a, b)) => {
                                let msg = format!(
                                    "division by `{}` = `{a} - {b}`: ±∞ when they are equal, \
                                     NaN where the numerator is 0 too",
                                    self.quote(dspan)
                                );
                                self.precondition(
                                    "division-by-difference",
                                    Condition::NotEqual(a, b),
                                    dspan,
                                    &ctx,
                                    low,
                                    msg,
                                )
                            }
                            None => {
                                let msg = format!(
                                    "division by `{}`, computed from uniforms: ±∞, or NaN, \
                                     when it is 0",
                                    self.quote(dspan)
                                );
                                self.precondition(
                                    DIVISION_BY_ZERO,
                                    Condition::NonZero(t),
                                    dspan,
                                    &ctx,
                                    low,
                                    msg,
                                )
                            }
                        };
                        out.push(p);
                    }
                }
                E::Math {
                    fun: Mf::Normalize,
                    arg,
                    ..
                } => {
                    let x = cx.operand(f, h, arg);
                    let g = cx.guards(f, id, h);
                    if !cx.refined(f, id, x, &g).is_some_and(|v| v.may_be_zero()) {
                        continue;
                    }
                    let xspan = cx.span(f, x);
                    if xspan.is_empty() {
                        continue;
                    }
                    let def = resolve(f, &cx.sound, id, x);
                    let cross = match f.expressions[def] {
                        E::Math {
                            fun: Mf::Cross,
                            arg: a,
                            arg1: Some(b),
                            ..
                        } if !crate::rules::orthogonal_cross(cx, f, id, x) => Some((a, b)),
                        _ => None,
                    };
                    for ctx in ctxs() {
                        let Some(t) = self.term(id, &ctx, x) else {
                            continue;
                        };
                        let pair = cross.and_then(|(a, b)| {
                            self.value(id, &ctx, a, 0)
                                .and_then(as_num)
                                .zip(self.value(id, &ctx, b, 0).and_then(as_num))
                        });
                        let p = match pair {
                            Some((a, b)) => self.precondition(
                                "normalize-zero",
                                Condition::NotParallel(a, b),
                                xspan,
                                &ctx,
                                low,
                                "`normalize(cross(a, b))` of parallel (or zero) vectors is \
                                 `normalize` of the zero vector: NaN for the whole draw"
                                    .into(),
                            ),
                            None => self.precondition(
                                "normalize-zero",
                                Condition::NonZeroVector(t),
                                xspan,
                                &ctx,
                                low,
                                format!(
                                    "`normalize({})` of the zero vector is 0 / 0: NaN in every \
                                     component, for the whole draw",
                                    self.quote(xspan)
                                ),
                            ),
                        };
                        out.push(p);
                    }
                }
                E::Math {
                    fun: Mf::Pow,
                    arg,
                    arg1: Some(y),
                    ..
                } => {
                    let (base, exp) = (cx.operand(f, h, arg), cx.operand(f, h, y));
                    let g = cx.guards(f, id, h);
                    let (Some(rb), Some(re)) =
                        (cx.refined(f, id, base, &g), cx.refined(f, id, exp, &g))
                    else {
                        continue;
                    };
                    let negative = rb.hull().lo < 0.0;
                    let zero = rb.hull().contains(0.0) && !cx.nonzero(f, id, base, &g);
                    let nonpositive = re.hull().lo <= 0.0;
                    let bspan = cx.span(f, base);
                    for ctx in ctxs() {
                        let tb = self.term(id, &ctx, base);
                        let te = self.term(id, &ctx, exp);
                        if let (Some(tb), true, false) = (&tb, negative, bspan.is_empty()) {
                            out.push(
                                self.precondition(
                                    "pow-negative-base",
                                    Condition::NonNegative(tb.clone()),
                                    bspan,
                                    &ctx,
                                    low,
                                    "`pow(x, y)` is undefined for x < 0 (GLSL ES 3.00 §8.2): NaN"
                                        .into(),
                                ),
                            );
                        }
                        if !(zero && nonpositive) {
                            continue;
                        }
                        let condition = match (tb, te) {
                            (Some(b), Some(e)) => Condition::PowBaseZero {
                                base: b,
                                exponent: e,
                            },
                            (None, Some(e)) => Condition::Positive(e),
                            _ => continue,
                        };
                        out.push(self.precondition(
                            "pow-zero-base",
                            condition,
                            span,
                            &ctx,
                            low,
                            format!(
                                "`pow(x, y)` is undefined for x = 0 and y ≤ 0 (GLSL ES 3.00 §8.2), \
                                 and the base `{}` can be 0: NaN for y = 0, +∞ for y < 0",
                                self.quote(bspan)
                            ),
                        ));
                    }
                }
                E::Math {
                    fun: fun @ (Mf::Acos | Mf::Asin),
                    arg,
                    ..
                } => {
                    let x = cx.operand(f, h, arg);
                    let g = cx.guards(f, id, h);
                    let Some(v) = cx.refined(f, id, x, &g) else {
                        continue;
                    };
                    let xspan = cx.span(f, x);
                    if v.hull().within(Interval::SIGNED_UNIT) || xspan.is_empty() {
                        continue;
                    }
                    let (rule, name) = if fun == Mf::Acos {
                        ("acos-domain", "acos")
                    } else {
                        ("asin-domain", "asin")
                    };
                    for ctx in ctxs() {
                        let Some(t) = self.term(id, &ctx, x) else {
                            continue;
                        };
                        out.push(self.precondition(
                            rule,
                            Condition::WithinUnit(t),
                            xspan,
                            &ctx,
                            low,
                            format!(
                                "`{name}(x)` is undefined for |x| > 1 (GLSL ES 3.00 §8.1): NaN"
                            ),
                        ));
                    }
                }
                _ => {}
            }
        }
    }

    /// [`Condition::Finite`] for every uniform (or part) the shader reads, at its first read.
    fn finite(&self, out: &mut Vec<Precondition>) {
        let mut first: Vec<(UniformRef, Span, bool)> = Vec::new();
        for (id, f) in self.cx.functions() {
            for (h, e) in f.expressions.iter() {
                let E::Load { pointer } = *e else { continue };
                let Some(r) = self.uniform_of_pointer(id, pointer) else {
                    continue;
                };
                let span = self.cx.span(f, h);
                if span.is_empty() {
                    continue;
                }
                let low = self.cx.prec.is_low(span);
                match first.iter_mut().find(|(u, _, _)| *u == r) {
                    Some(slot) if span.start < slot.1.start => *slot = (r, span, low),
                    Some(_) => {}
                    None => first.push((r, span, low)),
                }
            }
        }
        for (r, span, low) in first {
            out.push(
                self.precondition(
                    NON_FINITE_UNIFORM,
                    Condition::Finite(r),
                    span,
                    &Context::default(),
                    low,
                    "a NaN or infinite uniform value spreads through everything computed from it"
                        .into(),
                ),
            );
        }
    }
}

fn as_num(x: X) -> Option<Term> {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f16_rounding() {
        assert_eq!(round_f16(1.0), 1.0);
        assert_eq!(round_f16(65504.0), 65504.0);
        assert_eq!(round_f16(65519.0), 65504.0);
        assert_eq!(round_f16(65520.0), f64::INFINITY);
        assert_eq!(round_f16(0.1), 0.0999755859375);
        // 0.9 and 0.9001 are the same 16-bit float.
        assert_eq!(round_f16(0.9), round_f16(0.9001));
        assert_eq!(round_f16(2f64.powi(-24)), 2f64.powi(-24));
        assert_eq!(round_f16(2f64.powi(-26)), 0.0);
    }

    #[test]
    fn covers_names() {
        let r = UniformRef {
            base: "lights".into(),
            path: vec![PathStep::AnyIndex, PathStep::Member("cutOff".into())],
        };
        assert_eq!(r.name(None), "lights[*].cutOff");
        assert_eq!(r.name(Some(2)), "lights[2].cutOff");
        assert!(r.covers("lights[2].cutOff"));
        assert!(!r.covers("lights[2].cutOffX"));
        assert!(!r.covers("lights[].cutOff"));
        assert!(!r.covers("lights[2].outerCutOff"));
        let whole = UniformRef::new("light");
        assert!(whole.covers("light.cutOff"));
        assert!(whole.covers("light"));
        assert!(!whole.covers("lightColor"));
        assert!(UniformRef::new("u_w").covers("u_w[3]"));
    }

    #[test]
    fn conditions() {
        let u = |n: &str| Term::Uniform(UniformRef::new(n));
        let vals = |a: f64, b: f64| {
            move |r: &UniformRef| Some(Value::scalar(if r.base == "a" { a } else { b }))
        };
        let less = Condition::Less(u("a"), u("b"));
        assert_eq!(
            less.check(Precision::High, &mut vals(0.5, 0.9)),
            Outcome::Holds
        );
        let Outcome::Violated(why) = less.check(Precision::High, &mut vals(0.9, 0.9)) else {
            panic!()
        };
        assert!(why.contains("equal"), "{why}");
        let Outcome::Violated(why) = less.check(Precision::High, &mut vals(0.95, 0.9)) else {
            panic!()
        };
        assert!(why.contains("swapped"), "{why}");
        let ne = Condition::NotEqual(u("a"), u("b"));
        assert_eq!(
            ne.check(Precision::High, &mut vals(0.9, 0.9001)),
            Outcome::Holds
        );
        assert!(matches!(
            ne.check(Precision::Low, &mut vals(0.9, 0.9001)),
            Outcome::Violated(_)
        ));
        let pos = Condition::Positive(u("a"));
        assert!(matches!(
            pos.check(Precision::High, &mut vals(f64::NAN, 0.0)),
            Outcome::Violated(_)
        ));
        assert_eq!(pos.check(Precision::High, &mut |_| None), Outcome::Unknown);
    }

    #[test]
    fn vectors() {
        let u = |n: &str| Term::Uniform(UniformRef::new(n));
        let v = |x: [f64; 3], y: [f64; 3]| {
            move |r: &UniformRef| Some(Value::new(if r.base == "a" { &x } else { &y }))
        };
        let nz = Condition::NonZeroVector(u("a"));
        assert!(matches!(
            nz.check(Precision::High, &mut v([0.0; 3], [0.0; 3])),
            Outcome::Violated(_)
        ));
        assert_eq!(
            nz.check(Precision::High, &mut v([0.0, -1.0, 0.0], [0.0; 3])),
            Outcome::Holds
        );
        // 0.005 is fine in highp; its square flushes in mediump.
        assert_eq!(
            nz.check(Precision::High, &mut v([0.005, 0.0, 0.0], [0.0; 3])),
            Outcome::Holds
        );
        assert!(matches!(
            nz.check(Precision::Low, &mut v([0.005, 0.0, 0.0], [0.0; 3])),
            Outcome::Violated(_)
        ));
        let par = Condition::NotParallel(u("a"), u("b"));
        assert!(matches!(
            par.check(Precision::High, &mut v([0.0, 1.0, 0.0], [0.0, -2.0, 0.0])),
            Outcome::Violated(_)
        ));
        assert_eq!(
            par.check(Precision::High, &mut v([0.0, 1.0, 0.0], [0.0, -1.0, 0.1])),
            Outcome::Holds
        );
        let t = Term::Binary(BinOp::Sub, Box::new(u("a")), Box::new(u("b")));
        assert_eq!(t.to_string(), "a - b");
        let t = Term::Binary(
            BinOp::Mul,
            Box::new(Term::Const(Value::scalar(2.0))),
            Box::new(t),
        );
        assert_eq!(t.to_string(), "2 * (a - b)");
    }
}
