//! The texture lookup functions' overloads (GLSL ES 3.00 section 8.8): for every sampler
//! kind (float, int, uint) and dimension, and the shadow samplers; lookups with an implicit
//! level of detail also get a `bias` variant for fragment shaders.

use super::signatures::{v, Builder};
use super::BuiltinFn::{self, *};
use crate::hir::ParamMode;
use crate::types::{
    SamplerDim, SamplerType,
    ScalarKind::{self, *},
    Type,
};

/// Adds all texture functions.
pub(super) fn add_all(b: &mut Builder) {
    texture_lookups(b);
    texture_offsets(b);
    texture_lod_offsets(b);
    texture_gradients(b);
    shadow_textures(b);
}

/// The samplers of one kind (`sampler2D`, `isampler3D`, ...) and the kind's `vec4` result.
struct Samplers {
    s2: Type,
    s3: Type,
    sc: Type,
    sa: Type,
    gvec4: Type,
}

impl Samplers {
    /// The 2D, 3D, cube and 2D array samplers of `kind`.
    fn of(kind: ScalarKind) -> Samplers {
        let s = |dim| {
            Type::Sampler(SamplerType {
                dim,
                kind,
                shadow: false,
            })
        };
        Samplers {
            s2: s(SamplerDim::D2),
            s3: s(SamplerDim::D3),
            sc: s(SamplerDim::Cube),
            sa: s(SamplerDim::D2Array),
            gvec4: v(kind, 4),
        }
    }
}

/// `ivecN`.
fn ivec(n: u8) -> Type {
    v(Int, n)
}

/// `textureSize`, `texture`, `textureProj` and `textureLod` on the float, int and uint samplers.
fn texture_lookups(b: &mut Builder) {
    let f = Type::FLOAT;
    let i = Type::INT;
    let (v2, v3, v4) = (v(Float, 2), v(Float, 3), v(Float, 4));
    for kind in [Float, Int, Uint] {
        let Samplers {
            s2,
            s3,
            sc,
            sa,
            gvec4,
        } = Samplers::of(kind);
        tex(b, TextureSize, &[s2.clone(), i.clone()], ivec(2), false);
        tex(b, TextureSize, &[s3.clone(), i.clone()], ivec(3), false);
        tex(b, TextureSize, &[sc.clone(), i.clone()], ivec(2), false);
        tex(b, TextureSize, &[sa.clone(), i.clone()], ivec(3), false);
        tex(b, Texture, &[s2.clone(), v2.clone()], gvec4.clone(), true);
        tex(b, Texture, &[s3.clone(), v3.clone()], gvec4.clone(), true);
        tex(b, Texture, &[sc.clone(), v3.clone()], gvec4.clone(), true);
        tex(b, Texture, &[sa.clone(), v3.clone()], gvec4.clone(), true);
        tex(
            b,
            TextureProj,
            &[s2.clone(), v3.clone()],
            gvec4.clone(),
            true,
        );
        tex(
            b,
            TextureProj,
            &[s2.clone(), v4.clone()],
            gvec4.clone(),
            true,
        );
        tex(
            b,
            TextureProj,
            &[s3.clone(), v4.clone()],
            gvec4.clone(),
            true,
        );
        tex(
            b,
            TextureLod,
            &[s2.clone(), v2.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureLod,
            &[s3.clone(), v3.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureLod,
            &[sc.clone(), v3.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureLod,
            &[sa.clone(), v3.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
    }
}

/// `textureOffset`, `texelFetch`, `texelFetchOffset` and `textureProjOffset` on the float, int and uint samplers.
fn texture_offsets(b: &mut Builder) {
    let i = Type::INT;
    let (v2, v3, v4) = (v(Float, 2), v(Float, 3), v(Float, 4));
    for kind in [Float, Int, Uint] {
        let Samplers {
            s2,
            s3,
            sc: _,
            sa,
            gvec4,
        } = Samplers::of(kind);
        tex(
            b,
            TextureOffset,
            &[s2.clone(), v2.clone(), ivec(2)],
            gvec4.clone(),
            true,
        );
        tex(
            b,
            TextureOffset,
            &[s3.clone(), v3.clone(), ivec(3)],
            gvec4.clone(),
            true,
        );
        tex(
            b,
            TextureOffset,
            &[sa.clone(), v3.clone(), ivec(2)],
            gvec4.clone(),
            true,
        );
        tex(
            b,
            TexelFetch,
            &[s2.clone(), ivec(2), i.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TexelFetch,
            &[s3.clone(), ivec(3), i.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TexelFetch,
            &[sa.clone(), ivec(3), i.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TexelFetchOffset,
            &[s2.clone(), ivec(2), i.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TexelFetchOffset,
            &[s3.clone(), ivec(3), i.clone(), ivec(3)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TexelFetchOffset,
            &[sa.clone(), ivec(3), i.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjOffset,
            &[s2.clone(), v3.clone(), ivec(2)],
            gvec4.clone(),
            true,
        );
        tex(
            b,
            TextureProjOffset,
            &[s2.clone(), v4.clone(), ivec(2)],
            gvec4.clone(),
            true,
        );
        tex(
            b,
            TextureProjOffset,
            &[s3.clone(), v4.clone(), ivec(3)],
            gvec4.clone(),
            true,
        );
    }
}

/// `textureLodOffset`, `textureProjLod` and `textureProjLodOffset` on the float, int and uint samplers.
fn texture_lod_offsets(b: &mut Builder) {
    let f = Type::FLOAT;
    let (v2, v3, v4) = (v(Float, 2), v(Float, 3), v(Float, 4));
    for kind in [Float, Int, Uint] {
        let Samplers {
            s2,
            s3,
            sc: _,
            sa,
            gvec4,
        } = Samplers::of(kind);
        tex(
            b,
            TextureLodOffset,
            &[s2.clone(), v2.clone(), f.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureLodOffset,
            &[s3.clone(), v3.clone(), f.clone(), ivec(3)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureLodOffset,
            &[sa.clone(), v3.clone(), f.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjLod,
            &[s2.clone(), v3.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjLod,
            &[s2.clone(), v4.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjLod,
            &[s3.clone(), v4.clone(), f.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjLodOffset,
            &[s2.clone(), v3.clone(), f.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjLodOffset,
            &[s2.clone(), v4.clone(), f.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjLodOffset,
            &[s3.clone(), v4.clone(), f.clone(), ivec(3)],
            gvec4.clone(),
            false,
        );
    }
}

/// `textureGrad`, `textureGradOffset`, `textureProjGrad` and `textureProjGradOffset` on the float, int and uint samplers.
fn texture_gradients(b: &mut Builder) {
    let (v2, v3, v4) = (v(Float, 2), v(Float, 3), v(Float, 4));
    for kind in [Float, Int, Uint] {
        let Samplers {
            s2,
            s3,
            sc,
            sa,
            gvec4,
        } = Samplers::of(kind);
        tex(
            b,
            TextureGrad,
            &[s2.clone(), v2.clone(), v2.clone(), v2.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureGrad,
            &[s3.clone(), v3.clone(), v3.clone(), v3.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureGrad,
            &[sc.clone(), v3.clone(), v3.clone(), v3.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureGrad,
            &[sa.clone(), v3.clone(), v2.clone(), v2.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureGradOffset,
            &[s2.clone(), v2.clone(), v2.clone(), v2.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureGradOffset,
            &[s3.clone(), v3.clone(), v3.clone(), v3.clone(), ivec(3)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureGradOffset,
            &[sa.clone(), v3.clone(), v2.clone(), v2.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjGrad,
            &[s2.clone(), v3.clone(), v2.clone(), v2.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjGrad,
            &[s2.clone(), v4.clone(), v2.clone(), v2.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjGrad,
            &[s3.clone(), v4.clone(), v3.clone(), v3.clone()],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjGradOffset,
            &[s2.clone(), v3.clone(), v2.clone(), v2.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjGradOffset,
            &[s2.clone(), v4.clone(), v2.clone(), v2.clone(), ivec(2)],
            gvec4.clone(),
            false,
        );
        tex(
            b,
            TextureProjGradOffset,
            &[s3.clone(), v4.clone(), v3.clone(), v3.clone(), ivec(3)],
            gvec4.clone(),
            false,
        );
    }
}

/// The shadow samplers' lookups (`sampler2DShadow`, `samplerCubeShadow`,
/// `sampler2DArrayShadow`): a `float` result.
fn shadow_textures(b: &mut Builder) {
    let f = Type::FLOAT;
    let i = Type::INT;
    let (v2, v3, v4) = (v(Float, 2), v(Float, 3), v(Float, 4));
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
    tex(b, TextureSize, &[s2s.clone(), i.clone()], ivec(2), false);
    tex(b, TextureSize, &[scs.clone(), i.clone()], ivec(2), false);
    tex(b, TextureSize, &[sas.clone(), i.clone()], ivec(3), false);
    tex(b, Texture, &[s2s.clone(), v3.clone()], f.clone(), true);
    tex(b, Texture, &[scs.clone(), v4.clone()], f.clone(), true);
    tex(b, Texture, &[sas.clone(), v4.clone()], f.clone(), false);
    tex(b, TextureProj, &[s2s.clone(), v4.clone()], f.clone(), true);
    tex(
        b,
        TextureLod,
        &[s2s.clone(), v3.clone(), f.clone()],
        f.clone(),
        false,
    );
    tex(
        b,
        TextureOffset,
        &[s2s.clone(), v3.clone(), ivec(2)],
        f.clone(),
        true,
    );
    tex(
        b,
        TextureProjOffset,
        &[s2s.clone(), v4.clone(), ivec(2)],
        f.clone(),
        true,
    );
    tex(
        b,
        TextureLodOffset,
        &[s2s.clone(), v3.clone(), f.clone(), ivec(2)],
        f.clone(),
        false,
    );
    tex(
        b,
        TextureProjLod,
        &[s2s.clone(), v4.clone(), f.clone()],
        f.clone(),
        false,
    );
    tex(
        b,
        TextureProjLodOffset,
        &[s2s.clone(), v4.clone(), f.clone(), ivec(2)],
        f.clone(),
        false,
    );
    tex(
        b,
        TextureGrad,
        &[s2s.clone(), v3.clone(), v2.clone(), v2.clone()],
        f.clone(),
        false,
    );
    tex(
        b,
        TextureGrad,
        &[scs.clone(), v4.clone(), v3.clone(), v3.clone()],
        f.clone(),
        false,
    );
    tex(
        b,
        TextureGrad,
        &[sas.clone(), v4.clone(), v2.clone(), v2.clone()],
        f.clone(),
        false,
    );
    tex(
        b,
        TextureGradOffset,
        &[s2s.clone(), v3.clone(), v2.clone(), v2.clone(), ivec(2)],
        f.clone(),
        false,
    );
    tex(
        b,
        TextureGradOffset,
        &[sas.clone(), v4.clone(), v2.clone(), v2.clone(), ivec(2)],
        f.clone(),
        false,
    );
    tex(
        b,
        TextureProjGrad,
        &[s2s.clone(), v4.clone(), v2.clone(), v2.clone()],
        f.clone(),
        false,
    );
    tex(
        b,
        TextureProjGradOffset,
        &[s2s.clone(), v4.clone(), v2.clone(), v2.clone(), ivec(2)],
        f.clone(),
        false,
    );
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
