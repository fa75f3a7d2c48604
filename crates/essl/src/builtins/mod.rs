//! The built-in functions (chapter 8), variables and constants (chapter 7) of GLSL ES 3.00 and
//! 1.00.

// The overload table reads best with owned `t.clone()` arguments throughout.
#![allow(clippy::cloned_ref_to_slice_refs)]

use rustc_hash::FxHashMap as HashMap;
use std::sync::OnceLock;

mod es100;
mod signatures;
mod texture;

use crate::hir::ParamMode;
use crate::target::Extension;
use crate::types::{Precision, ScalarKind, Type};
use crate::Stage;

/// A built-in variable.
#[non_exhaustive]
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
    /// `mediump vec4 gl_FragColor` (GLSL ES 1.00 fragment): the color output.
    FragColor,
    /// `mediump vec4 gl_FragData[gl_MaxDrawBuffers]` (GLSL ES 1.00 fragment): the color outputs.
    FragData,
    /// `highp float gl_ClipDistance[gl_MaxClipDistances]` (`GL_ANGLE_clip_cull_distance`): a
    /// vertex output, and the interpolated values as a fragment input.
    ClipDistance,
    /// `highp float gl_CullDistance[…]` (`GL_ANGLE_clip_cull_distance`): essl offers no cull
    /// distances (`gl_MaxCullDistances` is 0), so it exists only for code that tests that
    /// constant first; writes are kept nowhere and reads give 0.
    CullDistance,
    /// `in highp int gl_DrawID` (vertex, `GL_ANGLE_multi_draw`): the index of the draw within
    /// a multi-draw call, 0 for any other draw.
    DrawId,
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
            BuiltinVar::FragColor => "gl_FragColor",
            BuiltinVar::FragData => "gl_FragData",
            BuiltinVar::ClipDistance => "gl_ClipDistance",
            BuiltinVar::CullDistance => "gl_CullDistance",
            BuiltinVar::DrawId => "gl_DrawID",
        }
    }

    /// The variable called `name` in a shader of `stage` in `lang`: GLSL ES 1.00 has
    /// `gl_FragColor` and `gl_FragData` (and `gl_FragDepthEXT`, which is `gl_FragDepth`, with
    /// `EXT_frag_depth`) but not `gl_VertexID`, `gl_InstanceID` or `gl_FragDepth`; GLSL ES 3.00
    /// has `gl_ClipDistance` and `gl_CullDistance` with `GL_ANGLE_clip_cull_distance`; both
    /// have `gl_DrawID` in vertex shaders with `GL_ANGLE_multi_draw`.
    pub fn lookup_in(
        name: &str,
        stage: Stage,
        lang: &crate::target::Language,
        at: u32,
    ) -> Option<BuiltinVar> {
        if name == "gl_DrawID" {
            return (stage == Stage::Vertex && lang.has_at(Extension::WebglMultiDraw, at))
                .then_some(BuiltinVar::DrawId);
        }
        if !lang.es100 {
            return match name {
                "gl_ClipDistance" | "gl_CullDistance"
                    if lang.has_at(Extension::WebglClipCullDistance, at) =>
                {
                    Some(if name == "gl_ClipDistance" {
                        BuiltinVar::ClipDistance
                    } else {
                        BuiltinVar::CullDistance
                    })
                }
                _ => BuiltinVar::lookup(name, stage),
            };
        }
        use BuiltinVar::*;
        let v = match name {
            "gl_FragColor" => FragColor,
            "gl_FragData" => FragData,
            "gl_FragDepthEXT" if lang.has_at(Extension::ExtFragDepth, at) => FragDepth,
            "gl_VertexID" | "gl_InstanceID" | "gl_FragDepth" => return None,
            _ => return BuiltinVar::lookup(name, stage),
        };
        (stage == Stage::Fragment).then_some(v)
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
            Position | PointSize | VertexId | InstanceId | DrawId => Some(Stage::Vertex),
            FragCoord | FrontFacing | FragDepth | PointCoord | FragColor | FragData => {
                Some(Stage::Fragment)
            }
            DepthRange | ClipDistance | CullDistance => None,
        }
    }

    /// Its type (`gl_DepthRange` is typed by the checker's built-in struct).
    pub fn ty(self) -> Type {
        use BuiltinVar::*;
        match self {
            Position | FragCoord => Type::Vector(ScalarKind::Float, 4),
            PointSize | FragDepth => Type::FLOAT,
            VertexId | InstanceId | DrawId => Type::INT,
            FrontFacing => Type::BOOL,
            PointCoord => Type::Vector(ScalarKind::Float, 2),
            DepthRange => Type::Void,
            FragColor => Type::Vector(ScalarKind::Float, 4),
            FragData => Type::Array(Box::new(Type::Vector(ScalarKind::Float, 4)), 1),
            ClipDistance | CullDistance => Type::Array(Box::new(Type::FLOAT), MAX_CLIP_DISTANCES),
        }
    }

    /// Its precision.
    pub fn precision(self) -> Option<Precision> {
        match self {
            BuiltinVar::FrontFacing => None,
            BuiltinVar::PointCoord | BuiltinVar::FragColor | BuiltinVar::FragData => {
                Some(Precision::Medium)
            }
            _ => Some(Precision::High),
        }
    }

    /// Whether a shader of `stage` may write it (the clip and cull distances are vertex
    /// outputs and fragment inputs).
    pub fn writable_in(self, stage: Stage) -> bool {
        match self {
            BuiltinVar::Position
            | BuiltinVar::PointSize
            | BuiltinVar::FragDepth
            | BuiltinVar::FragColor
            | BuiltinVar::FragData => true,
            BuiltinVar::ClipDistance | BuiltinVar::CullDistance => stage == Stage::Vertex,
            _ => false,
        }
    }
}

/// `gl_MaxClipDistances` with `GL_ANGLE_clip_cull_distance`: the size of `gl_ClipDistance`
/// (the extension's minimum, and the most naga's back ends take).
pub const MAX_CLIP_DISTANCES: u32 = 8;

/// Built-in constants of GLSL ES 3.00, with the values Chromium 156 (ANGLE on SwiftShader)
/// gives them in a WebGL 2 context (`tests/oracle/ES100.md`, "Built-in constants").
pub fn constant(name: &str) -> Option<i32> {
    Some(match name {
        "gl_MaxVertexAttribs" => 16,
        "gl_MaxVertexUniformVectors" => 4096,
        "gl_MaxVertexOutputVectors" => 32,
        "gl_MaxFragmentInputVectors" => 32,
        "gl_MaxVertexTextureImageUnits" => 32,
        "gl_MaxCombinedTextureImageUnits" => 64,
        "gl_MaxTextureImageUnits" => 32,
        "gl_MaxFragmentUniformVectors" => 4096,
        "gl_MaxDrawBuffers" => 8,
        "gl_MinProgramTexelOffset" => -8,
        "gl_MaxProgramTexelOffset" => 7,
        _ => return None,
    })
}

/// Built-in constants of the language: GLSL ES 1.00 has `gl_MaxVaryingVectors` instead of
/// the vertex output and fragment input counts, no texel offsets, and `gl_MaxDrawBuffers` 1 in
/// a WebGL 1 context without `WEBGL_draw_buffers`.
pub fn constant_in(name: &str, lang: &crate::target::Language) -> Option<i32> {
    if !lang.es100 {
        return match name {
            "gl_MaxClipDistances"
            | "gl_MaxCullDistances"
            | "gl_MaxCombinedClipAndCullDistances"
                if !lang.context_has(Extension::WebglClipCullDistance) =>
            {
                None
            }
            "gl_MaxClipDistances" => Some(MAX_CLIP_DISTANCES as i32),
            "gl_MaxCullDistances" | "gl_MaxCombinedClipAndCullDistances" => Some(0),
            _ => constant(name),
        };
    }
    match name {
        "gl_MaxClipDistances" | "gl_MaxCullDistances" | "gl_MaxCombinedClipAndCullDistances" => {
            None
        }
        "gl_MaxVaryingVectors" => Some(31),
        "gl_MaxDrawBuffers"
            if lang.target == crate::target::Target::WebGl1
                && !lang.context_has(Extension::WebglDrawBuffers) =>
        {
            Some(1)
        }
        "gl_MaxVertexOutputVectors"
        | "gl_MaxFragmentInputVectors"
        | "gl_MinProgramTexelOffset"
        | "gl_MaxProgramTexelOffset" => None,
        _ => constant(name),
    }
}

macro_rules! ops {
    ($($op:ident = $name:literal,)*) => {
        /// A built-in function.
        #[non_exhaustive]
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

    /// Whether this is a projective lookup, which divides the coordinates by their last
    /// component (`textureProj` and its variants).
    pub fn is_projective(self) -> bool {
        use BuiltinFn::*;
        matches!(
            self,
            TextureProj
                | TextureProjOffset
                | TextureProjLod
                | TextureProjLodOffset
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
    /// Only available in vertex shaders (GLSL ES 1.00's `texture2DLod`, …).
    pub vertex_only: bool,
    /// The WebGL 1 extension it needs (GLSL ES 1.00).
    pub extension: Option<Extension>,
}

/// All overloads of the GLSL ES 3.00 built-in function `name`.
pub fn overloads(name: &str) -> Option<&'static [Signature]> {
    table().get(name).map(|v| v.as_slice())
}

/// All overloads of the built-in function `name` in GLSL ES 1.00 (`es100`) or 3.00, whatever
/// extension they need.
pub fn overloads_in(name: &str, es100: bool) -> Option<&'static [Signature]> {
    if es100 {
        table_es100().get(name).map(|v| v.as_slice())
    } else {
        overloads(name)
    }
}

/// The names of the built-in functions of GLSL ES 1.00 (`es100`) or 3.00.
pub fn function_names(es100: bool) -> impl Iterator<Item = &'static str> {
    let table = if es100 { table_es100() } else { table() };
    table.keys().copied()
}

/// Whether `name` is a built-in function of GLSL ES 3.00.
pub fn is_builtin_function(name: &str) -> bool {
    table().contains_key(name)
}

fn table() -> &'static HashMap<&'static str, Vec<Signature>> {
    static TABLE: OnceLock<HashMap<&'static str, Vec<Signature>>> = OnceLock::new();
    TABLE.get_or_init(signatures::build)
}

fn table_es100() -> &'static HashMap<&'static str, Vec<Signature>> {
    static TABLE: OnceLock<HashMap<&'static str, Vec<Signature>>> = OnceLock::new();
    TABLE.get_or_init(es100::build)
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
