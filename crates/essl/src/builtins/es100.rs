//! The built-in functions of GLSL ES 1.00 (chapter 8 of its specification), with those of the
//! WebGL 1 extensions (`OES_standard_derivatives`, `EXT_shader_texture_lod`). Float functions
//! only (no integer `abs`, `min`…), square matrices only, and the texture functions under their
//! GLSL ES 1.00 names, each recorded as the GLSL ES 3.00 operation it is (`texture2D` is
//! [`BuiltinFn::Texture`] on a `sampler2D`), so that checking, folding and lowering treat both
//! languages alike.

use rustc_hash::FxHashMap as HashMap;

use super::signatures::{builder, v, Builder};
use super::BuiltinFn::{self, *};
use super::Signature;
use crate::hir::ParamMode;
use crate::target::Extension;
use crate::types::{SamplerDim, SamplerType, ScalarKind::*, Type};

/// Where an overload may be used.
#[derive(Clone, Copy, PartialEq)]
enum Only {
    Anywhere,
    Vertex,
    Fragment,
}

fn add(b: &mut Builder, name: &'static str, op: BuiltinFn, params: &[Type], ret: Type) {
    add_in(b, name, op, params, ret, Only::Anywhere, None);
}

fn add_in(
    b: &mut Builder,
    name: &'static str,
    op: BuiltinFn,
    params: &[Type],
    ret: Type,
    only: Only,
    extension: Option<Extension>,
) {
    b.add_named(
        name,
        Signature {
            op,
            params: params.iter().map(|t| (t.clone(), ParamMode::In)).collect(),
            ret,
            fragment_only: only == Only::Fragment,
            vertex_only: only == Only::Vertex,
            extension,
        },
    );
}

/// All GLSL ES 1.00 overloads, by name.
pub(super) fn build() -> HashMap<&'static str, Vec<Signature>> {
    let mut b = builder();
    float_functions(&mut b);
    common(&mut b);
    geometric_and_relational(&mut b);
    textures(&mut b);
    b.finish()
}

/// 8.1 Angle and trigonometry, 8.2 exponential, and the one-argument common functions:
/// genType → genType; the derivatives with `OES_standard_derivatives`.
fn float_functions(b: &mut Builder) {
    for (name, op) in [
        ("radians", Radians),
        ("degrees", Degrees),
        ("sin", Sin),
        ("cos", Cos),
        ("tan", Tan),
        ("asin", Asin),
        ("acos", Acos),
        ("atan", Atan),
        ("exp", Exp),
        ("log", Log),
        ("exp2", Exp2),
        ("log2", Log2),
        ("sqrt", Sqrt),
        ("inversesqrt", InverseSqrt),
        ("abs", Abs),
        ("sign", Sign),
        ("floor", Floor),
        ("ceil", Ceil),
        ("fract", Fract),
        ("normalize", Normalize),
    ] {
        for n in 1..=4 {
            add(b, name, op, &[v(Float, n)], v(Float, n));
        }
    }
    for (name, op) in [("dFdx", DFdx), ("dFdy", DFdy), ("fwidth", Fwidth)] {
        for n in 1..=4 {
            let t = v(Float, n);
            let ext = Some(Extension::OesStandardDerivatives);
            add_in(b, name, op, &[t.clone()], t, Only::Fragment, ext);
        }
    }
    for n in 1..=4 {
        let t = v(Float, n);
        add(b, "atan", Atan, &[t.clone(), t.clone()], t.clone());
        add(b, "pow", Pow, &[t.clone(), t.clone()], t.clone());
    }
}

/// 8.3 Common functions of two and three arguments, with a scalar form where the
/// specification has one.
fn common(b: &mut Builder) {
    let f = Type::FLOAT;
    for n in 1..=4 {
        let t = v(Float, n);
        let two = [t.clone(), t.clone()];
        let three = [t.clone(), t.clone(), t.clone()];
        add(b, "mod", Mod, &two, t.clone());
        add(b, "min", Min, &two, t.clone());
        add(b, "max", Max, &two, t.clone());
        add(b, "clamp", Clamp, &three, t.clone());
        add(b, "mix", Mix, &three, t.clone());
        add(b, "step", Step, &two, t.clone());
        add(b, "smoothstep", SmoothStep, &three, t.clone());
        if n > 1 {
            let scalar_second = [t.clone(), f.clone()];
            add(b, "mod", Mod, &scalar_second, t.clone());
            add(b, "min", Min, &scalar_second, t.clone());
            add(b, "max", Max, &scalar_second, t.clone());
            add(
                b,
                "clamp",
                Clamp,
                &[t.clone(), f.clone(), f.clone()],
                t.clone(),
            );
            add(b, "mix", Mix, &[t.clone(), t.clone(), f.clone()], t.clone());
            add(b, "step", Step, &[f.clone(), t.clone()], t.clone());
            let edges = [f.clone(), f.clone(), t.clone()];
            add(b, "smoothstep", SmoothStep, &edges, t.clone());
        }
    }
}

/// 8.4 Geometric, 8.5 matrix (`matrixCompMult` of square matrices) and 8.6 vector
/// relational functions.
fn geometric_and_relational(b: &mut Builder) {
    let f = Type::FLOAT;
    for n in 1..=4 {
        let t = v(Float, n);
        add(b, "length", Length, &[t.clone()], f.clone());
        add(b, "distance", Distance, &[t.clone(), t.clone()], f.clone());
        add(b, "dot", Dot, &[t.clone(), t.clone()], f.clone());
        let three = [t.clone(), t.clone(), t.clone()];
        add(b, "faceforward", FaceForward, &three, t.clone());
        add(b, "reflect", Reflect, &[t.clone(), t.clone()], t.clone());
        add(
            b,
            "refract",
            Refract,
            &[t.clone(), t.clone(), f.clone()],
            t.clone(),
        );
    }
    let v3 = v(Float, 3);
    add(b, "cross", Cross, &[v3.clone(), v3.clone()], v3);
    for n in 2..=4u8 {
        let m = Type::Matrix { cols: n, rows: n };
        add(
            b,
            "matrixCompMult",
            MatrixCompMult,
            &[m.clone(), m.clone()],
            m,
        );
    }
    for n in 2..=4 {
        let bt = v(Bool, n);
        for kind in [Float, Int] {
            let t = v(kind, n);
            for (name, op) in [
                ("lessThan", LessThan),
                ("lessThanEqual", LessThanEqual),
                ("greaterThan", GreaterThan),
                ("greaterThanEqual", GreaterThanEqual),
                ("equal", Equal),
                ("notEqual", NotEqual),
            ] {
                add(b, name, op, &[t.clone(), t.clone()], bt.clone());
            }
        }
        add(b, "equal", Equal, &[bt.clone(), bt.clone()], bt.clone());
        add(
            b,
            "notEqual",
            NotEqual,
            &[bt.clone(), bt.clone()],
            bt.clone(),
        );
        add(b, "any", Any, &[bt.clone()], Type::BOOL);
        add(b, "all", All, &[bt.clone()], Type::BOOL);
        add(b, "not", Not, &[bt.clone()], bt.clone());
    }
}

/// 8.7 Texture lookup functions: `texture2D`, `texture2DProj`, `textureCube` (with a bias in
/// fragment shaders), their `Lod` forms in vertex shaders, and `EXT_shader_texture_lod`'s
/// `…LodEXT` and `…GradEXT` forms in fragment shaders.
fn textures(b: &mut Builder) {
    let sampler = |dim| {
        Type::Sampler(SamplerType {
            dim,
            kind: Float,
            shadow: false,
        })
    };
    let (s2, sc) = (sampler(SamplerDim::D2), sampler(SamplerDim::Cube));
    let (f, v2, v3, v4) = (Type::FLOAT, v(Float, 2), v(Float, 3), v(Float, 4));
    let lod = Some(Extension::ExtShaderTextureLod);
    use Only::*;
    for (name, op, s, coord) in [
        ("texture2D", Texture, &s2, &v2),
        ("texture2DProj", TextureProj, &s2, &v3),
        ("texture2DProj", TextureProj, &s2, &v4),
        ("textureCube", Texture, &sc, &v3),
    ] {
        add(b, name, op, &[s.clone(), coord.clone()], v4.clone());
        let bias = [s.clone(), coord.clone(), f.clone()];
        add_in(b, name, op, &bias, v4.clone(), Fragment, None);
    }
    for (name, ext_name, op, s, coord) in [
        ("texture2DLod", "texture2DLodEXT", TextureLod, &s2, &v2),
        (
            "texture2DProjLod",
            "texture2DProjLodEXT",
            TextureProjLod,
            &s2,
            &v3,
        ),
        (
            "texture2DProjLod",
            "texture2DProjLodEXT",
            TextureProjLod,
            &s2,
            &v4,
        ),
        ("textureCubeLod", "textureCubeLodEXT", TextureLod, &sc, &v3),
    ] {
        let params = [s.clone(), coord.clone(), f.clone()];
        add_in(b, name, op, &params, v4.clone(), Vertex, None);
        add_in(b, ext_name, op, &params, v4.clone(), Fragment, lod);
    }
    for (name, op, s, coord, grad) in [
        ("texture2DGradEXT", TextureGrad, &s2, &v2, &v2),
        ("texture2DProjGradEXT", TextureProjGrad, &s2, &v3, &v2),
        ("texture2DProjGradEXT", TextureProjGrad, &s2, &v4, &v2),
        ("textureCubeGradEXT", TextureGrad, &sc, &v3, &v3),
    ] {
        let params = [s.clone(), coord.clone(), grad.clone(), grad.clone()];
        add_in(b, name, op, &params, v4.clone(), Fragment, lod);
    }
}
