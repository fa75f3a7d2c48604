//! The table of built-in function overloads (GLSL ES 3.00 chapter 8), built once, one
//! function per family of built-ins; texture functions are in [`super::texture`].

use rustc_hash::FxHashMap as HashMap;

use super::{BuiltinFn, Signature};
use crate::hir::ParamMode;
use crate::types::{ScalarKind, Type};

/// Collects the overloads by name.
pub(super) struct Builder {
    map: HashMap<&'static str, Vec<Signature>>,
}

impl Builder {
    /// Adds an overload whose parameters are all `in`.
    pub(super) fn add(&mut self, op: BuiltinFn, params: &[Type], ret: Type) {
        self.add_full(
            op,
            params.iter().map(|t| (t.clone(), ParamMode::In)).collect(),
            ret,
            false,
        );
    }

    /// Adds an overload with parameter modes, maybe only for fragment shaders.
    pub(super) fn add_full(
        &mut self,
        op: BuiltinFn,
        params: Vec<(Type, ParamMode)>,
        ret: Type,
        fragment_only: bool,
    ) {
        self.add_named(
            op.name(),
            Signature {
                op,
                params,
                ret,
                fragment_only,
                vertex_only: false,
                extension: None,
            },
        );
    }

    /// Adds an overload under a name other than its operation's (GLSL ES 1.00's `texture2D`
    /// is `texture` on a `sampler2D`).
    pub(super) fn add_named(&mut self, name: &'static str, sig: Signature) {
        self.map.entry(name).or_default().push(sig);
    }

    /// The overloads collected, by name.
    pub(super) fn finish(self) -> HashMap<&'static str, Vec<Signature>> {
        self.map
    }
}

/// An empty table.
pub(super) fn builder() -> Builder {
    Builder {
        map: HashMap::default(),
    }
}

/// `n` = 1: the scalar type of `kind`; else the vector.
pub(super) fn v(kind: ScalarKind, n: u8) -> Type {
    Type::vec(kind, n)
}

/// All overloads of all built-in functions, by name. The overloads of one name stay in the
/// order the families add them.
pub(super) fn build() -> HashMap<&'static str, Vec<Signature>> {
    let mut b = builder();
    component_wise(&mut b);
    angle_exponential(&mut b);
    common(&mut b);
    geometric(&mut b);
    vector_relational(&mut b);
    packing(&mut b);
    matrix(&mut b);
    super::texture::add_all(&mut b);
    b.map
}

/// 8.1 Angle and trigonometry, 8.2 exponential: genType → genType.
fn component_wise(b: &mut Builder) {
    use BuiltinFn::*;
    use ScalarKind::*;
    for op in [
        Radians,
        Degrees,
        Sin,
        Cos,
        Tan,
        Asin,
        Acos,
        Sinh,
        Cosh,
        Tanh,
        Asinh,
        Acosh,
        Atanh,
        Exp,
        Log,
        Exp2,
        Log2,
        Sqrt,
        InverseSqrt,
        Floor,
        Trunc,
        Round,
        RoundEven,
        Ceil,
        Fract,
        Normalize,
        DFdx,
        DFdy,
        Fwidth,
    ] {
        for n in 1..=4 {
            let t = v(Float, n);
            let fragment_only = matches!(op, DFdx | DFdy | Fwidth);
            b.add_full(op, vec![(t.clone(), ParamMode::In)], t, fragment_only);
        }
    }
}

/// 8.1, 8.2: `atan(y, x)`, `atan`, `pow` (the one-argument ones are in [`component_wise`]).
fn angle_exponential(b: &mut Builder) {
    use BuiltinFn::*;
    use ScalarKind::*;
    for n in 1..=4 {
        let t = v(Float, n);
        b.add(Atan, &[t.clone(), t.clone()], t.clone());
        b.add(Atan, &[t.clone()], t.clone());
        b.add(Pow, &[t.clone(), t.clone()], t.clone());
    }
}

/// 8.3 Common functions: `abs` … `uintBitsToFloat`, for float, int and uint where defined.
fn common(b: &mut Builder) {
    use BuiltinFn::*;
    use ScalarKind::*;
    let f = Type::FLOAT;
    let i = Type::INT;
    let u = Type::UINT;
    for n in 1..=4 {
        let t = v(Float, n);
        let it = v(Int, n);
        let ut = v(Uint, n);
        let bt = v(Bool, n);
        b.add(Abs, &[t.clone()], t.clone());
        b.add(Abs, &[it.clone()], it.clone());
        b.add(Sign, &[t.clone()], t.clone());
        b.add(Sign, &[it.clone()], it.clone());
        b.add(Mod, &[t.clone(), f.clone()], t.clone());
        if n > 1 {
            b.add(Mod, &[t.clone(), t.clone()], t.clone());
        }
        b.add_full(
            Modf,
            vec![(t.clone(), ParamMode::In), (t.clone(), ParamMode::Out)],
            t.clone(),
            false,
        );
        for (ty, s) in [(&t, &f), (&it, &i), (&ut, &u)] {
            b.add(Min, &[ty.clone(), ty.clone()], ty.clone());
            b.add(Max, &[ty.clone(), ty.clone()], ty.clone());
            b.add(Clamp, &[ty.clone(), ty.clone(), ty.clone()], ty.clone());
            if n > 1 {
                b.add(Min, &[ty.clone(), s.clone()], ty.clone());
                b.add(Max, &[ty.clone(), s.clone()], ty.clone());
                b.add(Clamp, &[ty.clone(), s.clone(), s.clone()], ty.clone());
            }
        }
        b.add(Mix, &[t.clone(), t.clone(), t.clone()], t.clone());
        if n > 1 {
            b.add(Mix, &[t.clone(), t.clone(), f.clone()], t.clone());
        }
        b.add(Mix, &[t.clone(), t.clone(), bt.clone()], t.clone());
        b.add(Step, &[t.clone(), t.clone()], t.clone());
        if n > 1 {
            b.add(Step, &[f.clone(), t.clone()], t.clone());
        }
        b.add(SmoothStep, &[t.clone(), t.clone(), t.clone()], t.clone());
        if n > 1 {
            b.add(SmoothStep, &[f.clone(), f.clone(), t.clone()], t.clone());
        }
        b.add(IsNan, &[t.clone()], bt.clone());
        b.add(IsInf, &[t.clone()], bt.clone());
        b.add(FloatBitsToInt, &[t.clone()], it.clone());
        b.add(FloatBitsToUint, &[t.clone()], ut.clone());
        b.add(IntBitsToFloat, &[it.clone()], t.clone());
        b.add(UintBitsToFloat, &[ut.clone()], t.clone());
    }
}

/// 8.4 Geometric functions: `length` … `refract`, `cross`.
fn geometric(b: &mut Builder) {
    use BuiltinFn::*;
    use ScalarKind::*;
    let f = Type::FLOAT;
    for n in 1..=4 {
        let t = v(Float, n);
        b.add(Length, &[t.clone()], f.clone());
        b.add(Distance, &[t.clone(), t.clone()], f.clone());
        b.add(Dot, &[t.clone(), t.clone()], f.clone());
        b.add(FaceForward, &[t.clone(), t.clone(), t.clone()], t.clone());
        b.add(Reflect, &[t.clone(), t.clone()], t.clone());
        b.add(Refract, &[t.clone(), t.clone(), f.clone()], t.clone());
    }
    let v3 = v(Float, 3);
    b.add(Cross, &[v3.clone(), v3.clone()], v3.clone());
}

/// 8.6 Vector relational functions: `lessThan` … `not`.
fn vector_relational(b: &mut Builder) {
    use BuiltinFn::*;
    use ScalarKind::*;
    for n in 1..=4 {
        let t = v(Float, n);
        let it = v(Int, n);
        let ut = v(Uint, n);
        let bt = v(Bool, n);
        if n > 1 {
            for ty in [&t, &it, &ut] {
                for op in [
                    LessThan,
                    LessThanEqual,
                    GreaterThan,
                    GreaterThanEqual,
                    Equal,
                    NotEqual,
                ] {
                    b.add(op, &[ty.clone(), ty.clone()], bt.clone());
                }
            }
            b.add(Equal, &[bt.clone(), bt.clone()], bt.clone());
            b.add(NotEqual, &[bt.clone(), bt.clone()], bt.clone());
            b.add(Any, &[bt.clone()], Type::BOOL);
            b.add(All, &[bt.clone()], Type::BOOL);
            b.add(Not, &[bt.clone()], bt.clone());
        }
    }
}

/// 8.3 Floating-point pack and unpack functions.
fn packing(b: &mut Builder) {
    use BuiltinFn::*;
    let u = Type::UINT;
    let v2 = v(ScalarKind::Float, 2);
    b.add(PackSnorm2x16, &[v2.clone()], u.clone());
    b.add(UnpackSnorm2x16, &[u.clone()], v2.clone());
    b.add(PackUnorm2x16, &[v2.clone()], u.clone());
    b.add(UnpackUnorm2x16, &[u.clone()], v2.clone());
    b.add(PackHalf2x16, &[v2.clone()], u.clone());
    b.add(UnpackHalf2x16, &[u.clone()], v2.clone());
}

/// 8.5 Matrix functions: `matrixCompMult`, `outerProduct`, `transpose`, `determinant`,
/// `inverse`.
fn matrix(b: &mut Builder) {
    use BuiltinFn::*;
    use ScalarKind::*;
    let f = Type::FLOAT;
    for cols in 2..=4u8 {
        for rows in 2..=4u8 {
            let m = Type::Matrix { cols, rows };
            b.add(MatrixCompMult, &[m.clone(), m.clone()], m.clone());
            b.add(OuterProduct, &[v(Float, rows), v(Float, cols)], m.clone());
            b.add(
                Transpose,
                &[m.clone()],
                Type::Matrix {
                    cols: rows,
                    rows: cols,
                },
            );
            if cols == rows {
                b.add(Determinant, &[m.clone()], f.clone());
                b.add(Inverse, &[m.clone()], m.clone());
            }
        }
    }
}
