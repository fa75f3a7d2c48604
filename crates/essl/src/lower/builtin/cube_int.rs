//! `texture()` on an integer cube sampler (`isamplerCube`, `usamplerCube`). GL filters integer
//! textures with NEAREST only, but naga (like WGSL and SPIR-V's sampled integer cubes) cannot
//! sample or load an integer cube map; it can gather. So the lookup gathers each of the four
//! components of the 2×2 texels around the sample point on the face the direction selects,
//! works out which of them is nearest the point, as the hardware would for a 2D texture,
//! and keeps that one. Level 0; a point on a face's edge may take its neighbour on the same
//! face where GL would take the adjacent face's.
//!
//! With `LowerOptions::integer_cube_as_array` (essl-gl's) the cube is declared as a 2D array
//! of its faces instead, which naga can load from at any level: the lookup loads the texel
//! under the point on the face and level it selects ([`FnCx::integer_cube_load`]).

use naga::{BinaryOperator as Op, Expression, Handle, Literal, MathFunction as Mf};

use crate::lower::func::FnCx;
use crate::source::Span;
use crate::types::{ScalarKind, Type};

impl FnCx<'_, '_> {
    /// The texel of the integer cube `image` (through `sampler`) nearest the direction `dir`.
    pub(super) fn integer_cube(
        &mut self,
        image: Handle<Expression>,
        sampler: Handle<Expression>,
        kind: ScalarKind,
        dir: Handle<Expression>,
        span: Span,
    ) -> Handle<Expression> {
        let axes = self.cube_axes(dir, span);
        let uv = self.cube_face_uv(&axes, span);
        let level = self.lit(Literal::I32(0));
        let size = self.add(
            Expression::ImageQuery {
                image,
                query: naga::ImageQuery::Size { level: Some(level) },
            },
            span,
        );
        let size = self.cast(size, naga::ScalarKind::Float, span);
        let scaled = self.binop(Op::Multiply, uv, size, span);
        let half = self.lit(Literal::F32(0.5));
        let half2 = self.splat(half, 2, span);
        let corner = self.binop(Op::Subtract, scaled, half2, span);
        let f = self.math(Mf::Fract, &[corner], span);
        let hi = self.binop(Op::GreaterEqual, f, half2, span);
        let (hi_x, hi_y) = (
            self.access_index(hi, 0, span),
            self.access_index(hi, 1, span),
        );
        let mut channels = Vec::new();
        for component in [
            naga::SwizzleComponent::X,
            naga::SwizzleComponent::Y,
            naga::SwizzleComponent::Z,
            naga::SwizzleComponent::W,
        ] {
            let g = self.add(
                Expression::ImageSample {
                    image,
                    sampler,
                    gather: Some(component),
                    coordinate: dir,
                    array_index: None,
                    offset: None,
                    level: naga::SampleLevel::Zero,
                    depth_ref: None,
                    clamp_to_edge: false,
                },
                span,
            );
            // Gathered in the order (i0, j1), (i1, j1), (i1, j0), (i0, j0).
            let [x, y, z, w] = [0, 1, 2, 3].map(|k| self.access_index(g, k, span));
            let low_row = self.select(hi_x, z, w, span);
            let high_row = self.select(hi_x, y, x, span);
            channels.push(self.select(hi_y, high_row, low_row, span));
        }
        self.compose(&Type::Vector(kind, 4), channels, span)
    }

    /// The texel of the integer cube `image`, declared as a 2D array of its six faces
    /// ([`LowerOptions::integer_cube_as_array`](crate::program::LowerOptions)), nearest the
    /// direction `dir`: the face the major axis selects, at the level `lod` selects
    /// (`NEAREST_MIPMAP_NEAREST`'s `ceil(lod + 0.5) - 1`, clamped to the view's levels;
    /// level 0 without one), the texel under the point clamped to the face's edge.
    pub(super) fn integer_cube_load(
        &mut self,
        image: Handle<Expression>,
        dir: Handle<Expression>,
        lod: Option<Handle<Expression>>,
        span: Span,
    ) -> Handle<Expression> {
        let axes = self.cube_axes(dir, span);
        let uv = self.cube_face_uv(&axes, span);
        let face = self.cube_face_index(&axes, span);
        let zero = self.lit(Literal::I32(0));
        let level = match lod {
            Some(lod) => {
                let half = self.lit(Literal::F32(0.5));
                let up = self.binop(Op::Add, lod, half, span);
                let ceil = self.math(Mf::Ceil, &[up], span);
                let one = self.lit(Literal::F32(1.0));
                let d = self.binop(Op::Subtract, ceil, one, span);
                let d = self.cast(d, naga::ScalarKind::Sint, span);
                let levels = self.add(
                    Expression::ImageQuery {
                        image,
                        query: naga::ImageQuery::NumLevels,
                    },
                    span,
                );
                let levels = self.cast(levels, naga::ScalarKind::Sint, span);
                let one = self.lit(Literal::I32(1));
                let last = self.binop(Op::Subtract, levels, one, span);
                self.math(Mf::Clamp, &[d, zero, last], span)
            }
            None => zero,
        };
        let texel = super::texture::NearestTexel {
            coords: uv,
            components: 2,
            level,
            offset: None,
            array_index: Some(face),
        };
        self.nearest_texel_load(image, texel, span)
    }

    /// The components of a cube direction, their magnitudes and signs, and which is the major
    /// axis (GLSL ES 3.00 §3.8.10: x where |x| is the largest, then y, then z), shared by
    /// [`Self::cube_face_index`] and [`Self::cube_face_uv`].
    fn cube_axes(&mut self, dir: Handle<Expression>, span: Span) -> CubeAxes {
        let c = [0, 1, 2].map(|k| self.access_index(dir, k, span));
        let a = c.map(|x| self.math(Mf::Abs, &[x], span));
        let x_ge_y = self.binop(Op::GreaterEqual, a[0], a[1], span);
        let x_ge_z = self.binop(Op::GreaterEqual, a[0], a[2], span);
        let x_major = self.binop(Op::LogicalAnd, x_ge_y, x_ge_z, span);
        let y_major = self.binop(Op::GreaterEqual, a[1], a[2], span);
        let zero = self.lit(Literal::F32(0.0));
        let pos = c.map(|x| self.binop(Op::Greater, x, zero, span));
        CubeAxes {
            c,
            a,
            pos,
            x_major,
            y_major,
        }
    }

    /// The face a cube direction selects, as GL numbers the faces from 0: +X, −X, +Y, −Y,
    /// +Z, −Z.
    fn cube_face_index(&mut self, axes: &CubeAxes, span: Span) -> Handle<Expression> {
        let [x_pos, y_pos, z_pos] = axes.pos;
        let (x_major, y_major) = (axes.x_major, axes.y_major);
        let [f0, f1, f2, f3, f4, f5] = [0, 1, 2, 3, 4, 5].map(|i| self.lit(Literal::I32(i)));
        let fx = self.select(x_pos, f0, f1, span);
        let fy = self.select(y_pos, f2, f3, span);
        let fz = self.select(z_pos, f4, f5, span);
        let fyz = self.select(y_major, fy, fz, span);
        self.select(x_major, fx, fyz, span)
    }

    /// The 0..1 coordinates on the face a cube direction selects (GLSL ES 3.00 §3.8.10's
    /// table of major axes: `sc`, `tc` over `|ma|`).
    fn cube_face_uv(&mut self, axes: &CubeAxes, span: Span) -> Handle<Expression> {
        let [x, y, z] = axes.c;
        let [ax, ay, az] = axes.a;
        let [x_pos, y_pos, z_pos] = axes.pos;
        let (x_major, y_major) = (axes.x_major, axes.y_major);
        let [nx, ny, nz] = [x, y, z].map(|c| {
            self.add(
                Expression::Unary {
                    op: naga::UnaryOperator::Negate,
                    expr: c,
                },
                span,
            )
        });
        // +X: (-z, -y); -X: (z, -y); +Y: (x, z); -Y: (x, -z); +Z: (x, -y); -Z: (-x, -y).
        let sc_x = self.select(x_pos, nz, z, span);
        let sc_z = self.select(z_pos, x, nx, span);
        let tc_y = self.select(y_pos, z, nz, span);
        let sc_yz = self.select(y_major, x, sc_z, span);
        let sc = self.select(x_major, sc_x, sc_yz, span);
        let tc_yz = self.select(y_major, tc_y, ny, span);
        let tc = self.select(x_major, ny, tc_yz, span);
        let ma_yz = self.select(y_major, ay, az, span);
        let ma = self.select(x_major, ax, ma_yz, span);
        let st = self.compose(&Type::Vector(ScalarKind::Float, 2), vec![sc, tc], span);
        let ma2 = self.splat(ma, 2, span);
        let ratio = self.binop(Op::Divide, st, ma2, span);
        let one = self.lit(Literal::F32(1.0));
        let one2 = self.splat(one, 2, span);
        let shifted = self.binop(Op::Add, ratio, one2, span);
        let half = self.lit(Literal::F32(0.5));
        let half2 = self.splat(half, 2, span);
        self.binop(Op::Multiply, shifted, half2, span)
    }
}

/// A cube direction's components (`c`), their magnitudes (`a`), whether each is positive
/// (`pos`), and which is the major axis.
struct CubeAxes {
    c: [Handle<Expression>; 3],
    a: [Handle<Expression>; 3],
    pos: [Handle<Expression>; 3],
    x_major: Handle<Expression>,
    y_major: Handle<Expression>,
}
