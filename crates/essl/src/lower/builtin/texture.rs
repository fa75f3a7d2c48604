//! Texture lookups: `texture*` with projection, explicit level, gradients, offsets and bias;
//! `texelFetch*`, `textureSize`, shadow comparisons, and integer samplers (loaded texel by
//! texel, as naga cannot filter them; integer cube maps gathered, in [`super::cube_int`]).

use naga::{Expression, Handle, Literal, MathFunction as Mf, SampleLevel};

use crate::builtins::BuiltinFn;
use crate::hir::Expr;
use crate::lower::func::FnCx;
use crate::lower::{unsupported, LowerError};
use crate::source::Span;
use crate::types::{SamplerDim, SamplerType, ScalarKind, Type};
use crate::Stage;

/// The arguments of a lookup after the coordinates: `[lod | dPdx, dPdy] [offset] [bias]`.
#[derive(Clone, Copy)]
struct LookupArgs {
    level: Option<Handle<Expression>>,
    grads: Option<(Handle<Expression>, Handle<Expression>)>,
    offset: Option<Handle<Expression>>,
    bias: Option<Handle<Expression>>,
}

/// Where a lookup reads: the coordinates proper, the array layer and the depth reference.
#[derive(Clone, Copy)]
struct TexelAddress {
    coords: Handle<Expression>,
    array_index: Option<Handle<Expression>>,
    depth_ref: Option<Handle<Expression>>,
}

impl FnCx<'_, '_> {
    /// Lowers a texture built-in (`ret`: the call's type).
    pub(super) fn texture(
        &mut self,
        op: BuiltinFn,
        args: &[Expr],
        ret: &Type,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        use BuiltinFn::*;
        if let Some(r) =
            self.per_sampler_element(args, ret, span, &|fx, a| fx.texture(op, a, ret, span))
        {
            return r;
        }
        let Type::Sampler(st) = args[0].ty else {
            return Err(unsupported("a texture call without a sampler", span));
        };
        if !self.sampler_available(&args[0]) {
            // An inactive sampler only appears in code the entry point never runs.
            return Ok(self.zero(ret));
        }
        let (image, sampler) = self.sampler(&args[0])?;
        let vals: Vec<Handle<Expression>> = args[1..]
            .iter()
            .map(|a| self.expr(a))
            .collect::<Result<_, _>>()?;
        if op == TextureSize {
            return Ok(self.texture_size(image, st, vals[0], span));
        }
        if matches!(op, TexelFetch | TexelFetchOffset) {
            return Ok(self.texel_fetch(op, image, st, &vals, span));
        }
        let lod = matches!(
            op,
            TextureLod | TextureLodOffset | TextureProjLod | TextureProjLodOffset
        );
        let grad = matches!(
            op,
            TextureGrad | TextureGradOffset | TextureProjGrad | TextureProjGradOffset
        );
        let extra = lookup_args(&vals, lod, grad, op.has_offset());
        let addr = self.texel_address(st, op.is_projective(), vals[0], &args[1].ty, span);
        if st.kind != ScalarKind::Float && st.dim == SamplerDim::Cube {
            if self.cx.options.integer_cube_as_array {
                return Ok(self.integer_cube_load(image, addr.coords, extra.level, span));
            }
            return Ok(self.integer_cube(image, sampler, st.kind, addr.coords, span));
        }
        if st.kind != ScalarKind::Float {
            return self.integer_texture(image, st, addr, extra, span);
        }
        let vertex = self.stage() == Stage::Vertex;
        let level = if st.shadow {
            // naga compares depth only at the implicit level or level 0.
            if vertex || lod || grad {
                SampleLevel::Zero
            } else {
                SampleLevel::Auto
            }
        } else if let Some(l) = extra.level {
            SampleLevel::Exact(l)
        } else if let Some((x, y)) = extra.grads {
            SampleLevel::Gradient { x, y }
        } else if let Some(b) = extra.bias {
            SampleLevel::Bias(if self.cx.options.clamp_lod_bias {
                let limit = crate::program::MAX_TEXTURE_LOD_BIAS;
                let (lo, hi) = (
                    self.lit(Literal::F32(-limit)),
                    self.lit(Literal::F32(limit)),
                );
                self.math(naga::MathFunction::Clamp, &[b, lo, hi], span)
            } else {
                b
            })
        } else if vertex {
            SampleLevel::Zero
        } else {
            SampleLevel::Auto
        };
        let offset = match extra.offset {
            Some(_) => Some(self.const_offset(
                &args[1 + if lod {
                    2
                } else if grad {
                    3
                } else {
                    1
                }],
                span,
            )?),
            None => None,
        };
        let sampled = self.add(
            Expression::ImageSample {
                image,
                sampler,
                gather: None,
                coordinate: addr.coords,
                array_index: addr.array_index,
                offset,
                level,
                depth_ref: addr.depth_ref,
                clamp_to_edge: false,
            },
            span,
        );
        Ok(sampled)
    }

    /// `texelFetch` and `texelFetchOffset`: a load at integer coordinates and level.
    fn texel_fetch(
        &mut self,
        op: BuiltinFn,
        image: Handle<Expression>,
        st: SamplerType,
        vals: &[Handle<Expression>],
        span: Span,
    ) -> Handle<Expression> {
        let mut coord = vals[0];
        if op == BuiltinFn::TexelFetchOffset {
            coord = self.binop(naga::BinaryOperator::Add, coord, vals[2], span);
        }
        let (coordinate, array_index) = self.split_array_coord_int(coord, st, span);
        self.add(
            Expression::ImageLoad {
                image,
                coordinate,
                array_index,
                sample: None,
                level: Some(vals[1]),
            },
            span,
        )
    }

    /// Splits a lookup's coordinates `coords` (of type `coord_ty`) into the coordinates
    /// proper, the array layer and the depth reference; a projective lookup divides by the
    /// last component first.
    fn texel_address(
        &mut self,
        st: SamplerType,
        proj: bool,
        mut coords: Handle<Expression>,
        coord_ty: &Type,
        span: Span,
    ) -> TexelAddress {
        let n = coord_ty.vector_size().unwrap_or(1);
        let dims = st.dim.coord_dims();
        let mut depth_ref = None;
        let mut array_index = None;
        if proj {
            // Divide by the last component: textureProj(s2D, vec3) uses .xy/.z; with vec4,
            // .xy/.w (and for shadow, .z/.w is the reference).
            let q = self.access_index(coords, n as u32 - 1, span);
            let keep = if st.shadow { 3 } else { dims };
            let parts: Vec<u8> = (0..keep).collect();
            let xyz = self.swizzle(coords, &parts, span);
            let qv = if keep > 1 {
                self.splat(q, keep, span)
            } else {
                q
            };
            coords = self.binop(naga::BinaryOperator::Divide, xyz, qv, span);
            if st.shadow {
                depth_ref = Some(self.access_index(coords, 2, span));
                let xy: Vec<u8> = (0..2).collect();
                coords = self.swizzle(coords, &xy, span);
            }
        } else {
            let total = n;
            let mut k = dims;
            if st.dim == SamplerDim::D2Array {
                let layer = self.access_index(coords, 2, span);
                array_index = Some(self.layer_index(layer, span));
                k = 2;
            }
            if st.shadow {
                let ref_index = if st.dim == SamplerDim::D2Array {
                    3
                } else {
                    total - 1
                };
                depth_ref = Some(self.access_index(coords, ref_index as u32, span));
            }
            if total != k {
                let parts: Vec<u8> = (0..k).collect();
                coords = self.swizzle(coords, &parts, span);
            }
        }
        TexelAddress {
            coords,
            array_index,
            depth_ref,
        }
    }

    /// A texel offset as a constant expression.
    fn const_offset(&mut self, e: &Expr, span: Span) -> Result<Handle<Expression>, LowerError> {
        match e.as_const() {
            Some(c) => Ok(self.constant(c, &e.ty, span)),
            None => Err(unsupported("a texel offset that is not a constant", span)),
        }
    }

    /// The array layer of a float coordinate: `floor(z + 0.5)` as an integer, as GLSL says.
    fn layer_index(&mut self, layer: Handle<Expression>, span: Span) -> Handle<Expression> {
        let half = self.lit(Literal::F32(0.5));
        let l = self.binop(naga::BinaryOperator::Add, layer, half, span);
        let l = self.math(Mf::Floor, &[l], span);
        let zero = self.lit(Literal::F32(0.0));
        let l = self.math(Mf::Max, &[l, zero], span);
        self.cast(l, naga::ScalarKind::Sint, span)
    }

    fn split_array_coord_int(
        &mut self,
        coord: Handle<Expression>,
        st: SamplerType,
        span: Span,
    ) -> (Handle<Expression>, Option<Handle<Expression>>) {
        if st.dim == SamplerDim::D2Array {
            let xy = self.swizzle(coord, &[0, 1], span);
            let layer = self.access_index(coord, 2, span);
            (xy, Some(layer))
        } else {
            (coord, None)
        }
    }

    fn texture_size(
        &mut self,
        image: Handle<Expression>,
        st: SamplerType,
        lod: Handle<Expression>,
        span: Span,
    ) -> Handle<Expression> {
        let size = self.add(
            Expression::ImageQuery {
                image,
                query: naga::ImageQuery::Size { level: Some(lod) },
            },
            span,
        );
        let size = self.cast(size, naga::ScalarKind::Sint, span);
        if st.dim == SamplerDim::D2Array {
            let layers = self.add(
                Expression::ImageQuery {
                    image,
                    query: naga::ImageQuery::NumLayers,
                },
                span,
            );
            let layers = self.cast(layers, naga::ScalarKind::Sint, span);
            let x = self.access_index(size, 0, span);
            let y = self.access_index(size, 1, span);
            return self.compose(&Type::Vector(ScalarKind::Int, 3), vec![x, y, layers], span);
        }
        size
    }

    /// `texture()` on an integer sampler: naga cannot filter integer textures (neither can GL:
    /// they are only complete with NEAREST filtering), so this loads the nearest texel of the
    /// chosen level with the coordinates clamped to the edge.
    fn integer_texture(
        &mut self,
        image: Handle<Expression>,
        st: SamplerType,
        addr: TexelAddress,
        extra: LookupArgs,
        span: Span,
    ) -> Result<Handle<Expression>, LowerError> {
        let TexelAddress {
            coords,
            array_index,
            ..
        } = addr;
        let level = match extra.level {
            Some(l) => self.cast(l, naga::ScalarKind::Sint, span),
            None => self.lit(Literal::I32(0)),
        };
        let n = if st.dim == SamplerDim::D3 { 3 } else { 2 };
        let texel = NearestTexel {
            coords,
            components: n,
            level,
            offset: extra.offset,
            array_index,
        };
        Ok(self.nearest_texel_load(image, texel, span))
    }

    /// The texel of `image` nearest normalised coordinates at an integer level: the
    /// coordinates scaled by the level's size, floored, offset, clamped to the level's edge,
    /// then loaded (what NEAREST filtering of an integer texture reads).
    pub(super) fn nearest_texel_load(
        &mut self,
        image: Handle<Expression>,
        t: NearestTexel,
        span: Span,
    ) -> Handle<Expression> {
        let size = self.add(
            Expression::ImageQuery {
                image,
                query: naga::ImageQuery::Size {
                    level: Some(t.level),
                },
            },
            span,
        );
        let size = self.cast(size, naga::ScalarKind::Sint, span);
        let fsize = self.cast(size, naga::ScalarKind::Float, span);
        let scaled = self.binop(naga::BinaryOperator::Multiply, t.coords, fsize, span);
        let fl = self.math(Mf::Floor, &[scaled], span);
        let mut texel = self.cast(fl, naga::ScalarKind::Sint, span);
        if let Some(o) = t.offset {
            texel = self.binop(naga::BinaryOperator::Add, texel, o, span);
        }
        let zero = self.lit(Literal::I32(0));
        let zero = self.splat(zero, t.components, span);
        let one = self.lit(Literal::I32(1));
        let one = self.splat(one, t.components, span);
        let max = self.binop(naga::BinaryOperator::Subtract, size, one, span);
        let texel = self.math(Mf::Clamp, &[texel, zero, max], span);
        self.add(
            Expression::ImageLoad {
                image,
                coordinate: texel,
                array_index: t.array_index,
                sample: None,
                level: Some(t.level),
            },
            span,
        )
    }
}

/// Where [`FnCx::nearest_texel_load`] reads: normalised coordinates of `components`
/// components, an integer level, a texel offset and an array layer if any.
pub(super) struct NearestTexel {
    pub(super) coords: Handle<Expression>,
    pub(super) components: u8,
    pub(super) level: Handle<Expression>,
    pub(super) offset: Option<Handle<Expression>>,
    pub(super) array_index: Option<Handle<Expression>>,
}

/// Picks the arguments after the coordinates out of `vals` (the lowered arguments after the
/// sampler).
fn lookup_args(vals: &[Handle<Expression>], lod: bool, grad: bool, has_offset: bool) -> LookupArgs {
    let mut i = 1;
    let level = if lod {
        i += 1;
        Some(vals[1])
    } else {
        None
    };
    let grads = if grad {
        i += 2;
        Some((vals[1], vals[2]))
    } else {
        None
    };
    let offset = if has_offset {
        let o = vals[i];
        i += 1;
        Some(o)
    } else {
        None
    };
    LookupArgs {
        level,
        grads,
        offset,
        bias: vals.get(i).copied(),
    }
}
