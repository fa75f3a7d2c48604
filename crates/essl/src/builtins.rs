//! GLSL ES 3.00's built-in functions (chapter 8), variables and constants (chapter 7).

// The overload table reads best with owned `t.clone()` arguments throughout.
#![allow(clippy::cloned_ref_to_slice_refs)]

use std::collections::HashMap;
use std::sync::OnceLock;

use crate::hir::ParamMode;
use crate::types::{Precision, SamplerDim, SamplerType, ScalarKind, Type};
use crate::Stage;

/// A built-in variable.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum BuiltinVar {
    /// `out highp vec4 gl_Position` (vertex)
    Position,
    /// `out highp float gl_PointSize` (vertex)
    PointSize,
    /// `in highp int gl_VertexID` (vertex)
    VertexId,
    /// `in highp int gl_InstanceID` (vertex)
    InstanceId,
    /// `in highp vec4 gl_FragCoord` (fragment)
    FragCoord,
    /// `in bool gl_FrontFacing` (fragment)
    FrontFacing,
    /// `out highp float gl_FragDepth` (fragment)
    FragDepth,
    /// `in mediump vec2 gl_PointCoord` (fragment)
    PointCoord,
    /// `uniform gl_DepthRangeParameters gl_DepthRange` (both): near, far, diff.
    DepthRange,
}

impl BuiltinVar {
    /// The GLSL name.
    pub fn name(self) -> &'static str {
        match self {
            BuiltinVar::Position => "gl_Position",
            BuiltinVar::PointSize => "gl_PointSize",
            BuiltinVar::VertexId => "gl_VertexID",
            BuiltinVar::InstanceId => "gl_InstanceID",
            BuiltinVar::FragCoord => "gl_FragCoord",
            BuiltinVar::FrontFacing => "gl_FrontFacing",
            BuiltinVar::FragDepth => "gl_FragDepth",
            BuiltinVar::PointCoord => "gl_PointCoord",
            BuiltinVar::DepthRange => "gl_DepthRange",
        }
    }

    /// The variable called `name` in `stage`.
    pub fn lookup(name: &str, stage: Stage) -> Option<BuiltinVar> {
        use BuiltinVar::*;
        let v = match name {
            "gl_Position" => Position,
            "gl_PointSize" => PointSize,
            "gl_VertexID" => VertexId,
            "gl_InstanceID" => InstanceId,
            "gl_FragCoord" => FragCoord,
            "gl_FrontFacing" => FrontFacing,
            "gl_FragDepth" => FragDepth,
            "gl_PointCoord" => PointCoord,
            "gl_DepthRange" => DepthRange,
            _ => return None,
        };
        (v.stage().is_none() || v.stage() == Some(stage)).then_some(v)
    }

    /// The stage that has it (`None`: both).
    pub fn stage(self) -> Option<Stage> {
        use BuiltinVar::*;
        match self {
            Position | PointSize | VertexId | InstanceId => Some(Stage::Vertex),
            FragCoord | FrontFacing | FragDepth | PointCoord => Some(Stage::Fragment),
            DepthRange => None,
        }
    }

    /// Its type (`gl_DepthRange` is typed by the checker's built-in struct).
    pub fn ty(self) -> Type {
        use BuiltinVar::*;
        match self {
            Position | FragCoord => Type::Vector(ScalarKind::Float, 4),
            PointSize | FragDepth => Type::FLOAT,
            VertexId | InstanceId => Type::INT,
            FrontFacing => Type::BOOL,
            PointCoord => Type::Vector(ScalarKind::Float, 2),
            DepthRange => Type::Void,
        }
    }

    /// Its precision.
    pub fn precision(self) -> Option<Precision> {
        match self {
            BuiltinVar::FrontFacing => None,
            BuiltinVar::PointCoord => Some(Precision::Medium),
            _ => Some(Precision::High),
        }
    }

    /// Whether the shader may write it.
    pub fn writable(self) -> bool {
        matches!(
            self,
            BuiltinVar::Position | BuiltinVar::PointSize | BuiltinVar::FragDepth
        )
    }
}

/// Built-in constants (WebGL2's minimums, which ANGLE reports on SwiftShader too).
pub fn constant(name: &str) -> Option<i32> {
    Some(match name {
        "gl_MaxVertexAttribs" => 16,
        "gl_MaxVertexUniformVectors" => 256,
        "gl_MaxVertexOutputVectors" => 16,
        "gl_MaxFragmentInputVectors" => 15,
        "gl_MaxVertexTextureImageUnits" => 16,
        "gl_MaxCombinedTextureImageUnits" => 32,
        "gl_MaxTextureImageUnits" => 16,
        "gl_MaxFragmentUniformVectors" => 224,
        "gl_MaxDrawBuffers" => 4,
        "gl_MinProgramTexelOffset" => -8,
        "gl_MaxProgramTexelOffset" => 7,
        _ => return None,
    })
}

macro_rules! ops {
    ($($op:ident = $name:literal,)*) => {
        /// A built-in function.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        #[allow(missing_docs)]
        pub enum BuiltinFn { $($op,)* }

        impl BuiltinFn {
            /// The GLSL name.
            pub fn name(self) -> &'static str {
                match self { $(BuiltinFn::$op => $name,)* }
            }
        }
    };
}

ops! {
    Radians = "radians", Degrees = "degrees", Sin = "sin", Cos = "cos", Tan = "tan",
    Asin = "asin", Acos = "acos", Atan = "atan", Sinh = "sinh", Cosh = "cosh", Tanh = "tanh",
    Asinh = "asinh", Acosh = "acosh", Atanh = "atanh",
    Pow = "pow", Exp = "exp", Log = "log", Exp2 = "exp2", Log2 = "log2", Sqrt = "sqrt",
    InverseSqrt = "inversesqrt",
    Abs = "abs", Sign = "sign", Floor = "floor", Trunc = "trunc", Round = "round",
    RoundEven = "roundEven", Ceil = "ceil", Fract = "fract", Mod = "mod", Modf = "modf",
    Min = "min", Max = "max", Clamp = "clamp", Mix = "mix", Step = "step",
    SmoothStep = "smoothstep", IsNan = "isnan", IsInf = "isinf",
    FloatBitsToInt = "floatBitsToInt", FloatBitsToUint = "floatBitsToUint",
    IntBitsToFloat = "intBitsToFloat", UintBitsToFloat = "uintBitsToFloat",
    PackSnorm2x16 = "packSnorm2x16", UnpackSnorm2x16 = "unpackSnorm2x16",
    PackUnorm2x16 = "packUnorm2x16", UnpackUnorm2x16 = "unpackUnorm2x16",
    PackHalf2x16 = "packHalf2x16", UnpackHalf2x16 = "unpackHalf2x16",
    Length = "length", Distance = "distance", Dot = "dot", Cross = "cross",
    Normalize = "normalize", FaceForward = "faceforward", Reflect = "reflect",
    Refract = "refract",
    MatrixCompMult = "matrixCompMult", OuterProduct = "outerProduct", Transpose = "transpose",
    Determinant = "determinant", Inverse = "inverse",
    LessThan = "lessThan", LessThanEqual = "lessThanEqual", GreaterThan = "greaterThan",
    GreaterThanEqual = "greaterThanEqual", Equal = "equal", NotEqual = "notEqual",
    Any = "any", All = "all", Not = "not",
    TextureSize = "textureSize", Texture = "texture", TextureProj = "textureProj",
    TextureLod = "textureLod", TextureOffset = "textureOffset", TexelFetch = "texelFetch",
    TexelFetchOffset = "texelFetchOffset", TextureProjOffset = "textureProjOffset",
    TextureLodOffset = "textureLodOffset", TextureProjLod = "textureProjLod",
    TextureProjLodOffset = "textureProjLodOffset", TextureGrad = "textureGrad",
    TextureGradOffset = "textureGradOffset", TextureProjGrad = "textureProjGrad",
    TextureProjGradOffset = "textureProjGradOffset",
    DFdx = "dFdx", DFdy = "dFdy", Fwidth = "fwidth",
}

impl BuiltinFn {
    /// Whether this is a texture lookup or query (not allowed in constant expressions).
    pub fn is_texture(self) -> bool {
        use BuiltinFn::*;
        matches!(
            self,
            TextureSize
                | Texture
                | TextureProj
                | TextureLod
                | TextureOffset
                | TexelFetch
                | TexelFetchOffset
                | TextureProjOffset
                | TextureLodOffset
                | TextureProjLod
                | TextureProjLodOffset
                | TextureGrad
                | TextureGradOffset
                | TextureProjGrad
                | TextureProjGradOffset
        )
    }

    /// Whether the function takes a constant `offset` argument (the last, or second to last
    /// before a bias).
    pub fn has_offset(self) -> bool {
        use BuiltinFn::*;
        matches!(
            self,
            TextureOffset
                | TexelFetchOffset
                | TextureProjOffset
                | TextureLodOffset
                | TextureProjLodOffset
                | TextureGradOffset
                | TextureProjGradOffset
        )
    }
}

/// One overload of a built-in function.
#[derive(Clone, Debug)]
pub struct Signature {
    /// The function.
    pub op: BuiltinFn,
    /// Parameter types and modes.
    pub params: Vec<(Type, ParamMode)>,
    /// The return type.
    pub ret: Type,
    /// Only available in fragment shaders (bias variants, derivatives).
    pub fragment_only: bool,
}

/// All overloads of the built-in function `name`.
pub fn overloads(name: &str) -> Option<&'static [Signature]> {
    table().get(name).map(|v| v.as_slice())
}

/// Whether `name` is a built-in function.
pub fn is_builtin_function(name: &str) -> bool {
    table().contains_key(name)
}

fn table() -> &'static HashMap<&'static str, Vec<Signature>> {
    static TABLE: OnceLock<HashMap<&'static str, Vec<Signature>>> = OnceLock::new();
    TABLE.get_or_init(build)
}

struct Builder {
    map: HashMap<&'static str, Vec<Signature>>,
}

impl Builder {
    fn add(&mut self, op: BuiltinFn, params: &[Type], ret: Type) {
        self.add_full(
            op,
            params.iter().map(|t| (t.clone(), ParamMode::In)).collect(),
            ret,
            false,
        );
    }

    fn add_full(
        &mut self,
        op: BuiltinFn,
        params: Vec<(Type, ParamMode)>,
        ret: Type,
        fragment_only: bool,
    ) {
        self.map.entry(op.name()).or_default().push(Signature {
            op,
            params,
            ret,
            fragment_only,
        });
    }
}

fn v(kind: ScalarKind, n: u8) -> Type {
    Type::vec(kind, n)
}

fn build() -> HashMap<&'static str, Vec<Signature>> {
    use BuiltinFn::*;
    use ScalarKind::*;
    let mut b = Builder {
        map: HashMap::new(),
    };
    let f = Type::FLOAT;
    let i = Type::INT;
    let u = Type::UINT;

    // 8.1 Angle and trigonometry, 8.2 exponential: genType → genType.
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
    for n in 1..=4 {
        let t = v(Float, n);
        let it = v(Int, n);
        let ut = v(Uint, n);
        let bt = v(Bool, n);
        b.add(Atan, &[t.clone(), t.clone()], t.clone());
        b.add(Atan, &[t.clone()], t.clone());
        b.add(Pow, &[t.clone(), t.clone()], t.clone());
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
        // 8.4 Geometric.
        b.add(Length, &[t.clone()], f.clone());
        b.add(Distance, &[t.clone(), t.clone()], f.clone());
        b.add(Dot, &[t.clone(), t.clone()], f.clone());
        b.add(FaceForward, &[t.clone(), t.clone(), t.clone()], t.clone());
        b.add(Reflect, &[t.clone(), t.clone()], t.clone());
        b.add(Refract, &[t.clone(), t.clone(), f.clone()], t.clone());
        // 8.6 Vector relational.
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
    let v2 = v(Float, 2);
    let v3 = v(Float, 3);
    let v4 = v(Float, 4);
    b.add(Cross, &[v3.clone(), v3.clone()], v3.clone());
    // 8.3 Packing.
    b.add(PackSnorm2x16, &[v2.clone()], u.clone());
    b.add(UnpackSnorm2x16, &[u.clone()], v2.clone());
    b.add(PackUnorm2x16, &[v2.clone()], u.clone());
    b.add(UnpackUnorm2x16, &[u.clone()], v2.clone());
    b.add(PackHalf2x16, &[v2.clone()], u.clone());
    b.add(UnpackHalf2x16, &[u.clone()], v2.clone());
    // 8.5 Matrix.
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

    // 8.8 Texture lookup.
    let ivec = |n| v(Int, n);
    for kind in [Float, Int, Uint] {
        let gvec4 = v(kind, 4);
        let s = |dim| {
            Type::Sampler(SamplerType {
                dim,
                kind,
                shadow: false,
            })
        };
        let s2 = s(SamplerDim::D2);
        let s3 = s(SamplerDim::D3);
        let sc = s(SamplerDim::Cube);
        let sa = s(SamplerDim::D2Array);
        tex(
            &mut b,
            TextureSize,
            &[s2.clone(), i.clone()],
            ivec(2),
            false,
        );
        tex(
            &mut b,
            TextureSize,
            &[s3.clone(), i.clone()],
            ivec(3),
            false,
        );
        tex(
            &mut b,
            TextureSize,
            &[sc.clone(), i.clone()],
            ivec(2),
            false,
        );
        tex(
            &mut b,
            TextureSize,
            &[sa.clone(), i.clone()],
            ivec(3),
            false,
        );
        tex(
            &mut b,
            Texture,
            &[s2.clone(), v2.clone()],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            Texture,
            &[s3.clone(), v3.clone()],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            Texture,
            &[sc.clone(), v3.clone()],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            Texture,
            &[sa.clone(), v3.clone()],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            TextureProj,
            &[s2.clone(), v3.clone()],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            TextureProj,
            &[s2.clone(), v4.clone()],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            TextureProj,
            &[s3.clone(), v4.clone()],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            TextureLod,
            &[s2.clone(), v2.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureLod,
            &[s3.clone(), v3.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureLod,
            &[sc.clone(), v3.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureLod,
            &[sa.clone(), v3.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureOffset,
            &[s2.clone(), v2.clone(), ivec(2)],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            TextureOffset,
            &[s3.clone(), v3.clone(), ivec(3)],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            TextureOffset,
            &[sa.clone(), v3.clone(), ivec(2)],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            TexelFetch,
            &[s2.clone(), ivec(2), i.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TexelFetch,
            &[s3.clone(), ivec(3), i.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TexelFetch,
            &[sa.clone(), ivec(3), i.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TexelFetchOffset,
            &[s2.clone(), ivec(2), i.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TexelFetchOffset,
            &[s3.clone(), ivec(3), i.clone(), ivec(3)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TexelFetchOffset,
            &[sa.clone(), ivec(3), i.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjOffset,
            &[s2.clone(), v3.clone(), ivec(2)],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            TextureProjOffset,
            &[s2.clone(), v4.clone(), ivec(2)],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            TextureProjOffset,
            &[s3.clone(), v4.clone(), ivec(3)],
            gvec4.clone(),
            true,
        );
        tex(
            &mut b,
            TextureLodOffset,
            &[s2.clone(), v2.clone(), f.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureLodOffset,
            &[s3.clone(), v3.clone(), f.clone(), ivec(3)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureLodOffset,
            &[sa.clone(), v3.clone(), f.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjLod,
            &[s2.clone(), v3.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjLod,
            &[s2.clone(), v4.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjLod,
            &[s3.clone(), v4.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjLodOffset,
            &[s2.clone(), v3.clone(), f.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjLodOffset,
            &[s2.clone(), v4.clone(), f.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjLodOffset,
            &[s3.clone(), v4.clone(), f.clone(), ivec(3)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureGrad,
            &[s2.clone(), v2.clone(), v2.clone(), v2.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureGrad,
            &[s3.clone(), v3.clone(), v3.clone(), v3.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureGrad,
            &[sc.clone(), v3.clone(), v3.clone(), v3.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureGrad,
            &[sa.clone(), v3.clone(), v2.clone(), v2.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureGradOffset,
            &[s2.clone(), v2.clone(), v2.clone(), v2.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureGradOffset,
            &[s3.clone(), v3.clone(), v3.clone(), v3.clone(), ivec(3)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureGradOffset,
            &[sa.clone(), v3.clone(), v2.clone(), v2.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjGrad,
            &[s2.clone(), v3.clone(), v2.clone(), v2.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjGrad,
            &[s2.clone(), v4.clone(), v2.clone(), v2.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjGrad,
            &[s3.clone(), v4.clone(), v3.clone(), v3.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjGradOffset,
            &[s2.clone(), v3.clone(), v2.clone(), v2.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjGradOffset,
            &[s2.clone(), v4.clone(), v2.clone(), v2.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            &mut b,
            TextureProjGradOffset,
            &[s3.clone(), v4.clone(), v3.clone(), v3.clone(), ivec(3)],
            gvec4.clone(),
            false,
        );
    }
    let shadow = |dim| {
        Type::Sampler(SamplerType {
            dim,
            kind: Float,
            shadow: true,
        })
    };
    let s2s = shadow(SamplerDim::D2);
    let scs = shadow(SamplerDim::Cube);
    let sas = shadow(SamplerDim::D2Array);
    tex(
        &mut b,
        TextureSize,
        &[s2s.clone(), i.clone()],
        ivec(2),
        false,
    );
    tex(
        &mut b,
        TextureSize,
        &[scs.clone(), i.clone()],
        ivec(2),
        false,
    );
    tex(
        &mut b,
        TextureSize,
        &[sas.clone(), i.clone()],
        ivec(3),
        false,
    );
    tex(&mut b, Texture, &[s2s.clone(), v3.clone()], f.clone(), true);
    tex(&mut b, Texture, &[scs.clone(), v4.clone()], f.clone(), true);
    tex(
        &mut b,
        Texture,
        &[sas.clone(), v4.clone()],
        f.clone(),
        false,
    );
    tex(
        &mut b,
        TextureProj,
        &[s2s.clone(), v4.clone()],
        f.clone(),
        true,
    );
    tex(
        &mut b,
        TextureLod,
        &[s2s.clone(), v3.clone(), f.clone()],
        f.clone(),
        false,
    );
    tex(
        &mut b,
        TextureOffset,
        &[s2s.clone(), v3.clone(), ivec(2)],
        f.clone(),
        true,
    );
    tex(
        &mut b,
        TextureProjOffset,
        &[s2s.clone(), v4.clone(), ivec(2)],
        f.clone(),
        true,
    );
    tex(
        &mut b,
        TextureLodOffset,
        &[s2s.clone(), v3.clone(), f.clone(), ivec(2)],
        f.clone(),
        false,
    );
    tex(
        &mut b,
        TextureProjLod,
        &[s2s.clone(), v4.clone(), f.clone()],
        f.clone(),
        false,
    );
    tex(
        &mut b,
        TextureProjLodOffset,
        &[s2s.clone(), v4.clone(), f.clone(), ivec(2)],
        f.clone(),
        false,
    );
    tex(
        &mut b,
        TextureGrad,
        &[s2s.clone(), v3.clone(), v2.clone(), v2.clone()],
        f.clone(),
        false,
    );
    tex(
        &mut b,
        TextureGrad,
        &[scs.clone(), v4.clone(), v3.clone(), v3.clone()],
        f.clone(),
        false,
    );
    tex(
        &mut b,
        TextureGrad,
        &[sas.clone(), v4.clone(), v2.clone(), v2.clone()],
        f.clone(),
        false,
    );
    tex(
        &mut b,
        TextureGradOffset,
        &[s2s.clone(), v3.clone(), v2.clone(), v2.clone(), ivec(2)],
        f.clone(),
        false,
    );
    tex(
        &mut b,
        TextureGradOffset,
        &[sas.clone(), v4.clone(), v2.clone(), v2.clone(), ivec(2)],
        f.clone(),
        false,
    );
    tex(
        &mut b,
        TextureProjGrad,
        &[s2s.clone(), v4.clone(), v2.clone(), v2.clone()],
        f.clone(),
        false,
    );
    tex(
        &mut b,
        TextureProjGradOffset,
        &[s2s.clone(), v4.clone(), v2.clone(), v2.clone(), ivec(2)],
        f.clone(),
        false,
    );
    b.map
}

/// Adds a texture function, and its variant with a trailing `float bias` (fragment shaders
/// only) when `bias` is set.
fn tex(b: &mut Builder, op: BuiltinFn, params: &[Type], ret: Type, bias: bool) {
    b.add(op, params, ret.clone());
    if bias {
        let mut p: Vec<(Type, ParamMode)> =
            params.iter().map(|t| (t.clone(), ParamMode::In)).collect();
        p.push((Type::FLOAT, ParamMode::In));
        b.add_full(op, p, ret, true);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_has_the_expected_overloads() {
        assert_eq!(overloads("dot").unwrap().len(), 4);
        assert_eq!(overloads("texture").unwrap().len(), 3 * 4 * 2 + 2 * 2 + 1);
        assert!(overloads("texture2D").is_none());
        assert_eq!(overloads("transpose").unwrap().len(), 9);
        // min: 3 kinds × (4 same-type + 3 scalar-second).
        assert_eq!(overloads("min").unwrap().len(), 21);
    }
}
