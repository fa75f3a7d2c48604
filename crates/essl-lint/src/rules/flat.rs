//! Whether a value takes one particular value over a whole region of ordinary inputs, not only
//! at isolated points: what separates `log(max(dot(n, l), 0.0))`, which is `log(0)` on the
//! whole unlit side of every object, from `inversesqrt(dot(d, d))` of a per-pixel difference,
//! which is zero at most at the one pixel where the two points meet.
//!
//! A value is *flat at* `v` when it equals `v` on a region: a per-draw value (uniforms and
//! constants only) that can be `v` is `v` for every pixel of the draw; a clamp, `max`, `min`,
//! `step` or `smoothstep` saturates at its bound; a texel is 0 or 1 wherever the texture is
//! black or white; `floor`, `sign` and integers are piecewise constant; and arithmetic carries
//! it (`a * b` is 0 where `a` is, `1.0 - t` is 0 where `t` is 1). A continuous per-pixel value
//! crossing `v` (a difference of varyings, a dot product at the terminator) is not flat there.

use naga::{BinaryOperator as Bo, Expression as E, Function, Handle, MathFunction as Mf};

use super::Cx;
use crate::analysis;
use crate::value::Facts;

/// How deep the walk follows operands.
const DEPTH: u32 = 12;

impl Cx<'_> {
    /// Whether expression `h` of function `id` equals `v` (some component of it) on a region of
    /// ordinary inputs, or for a whole draw.
    pub fn flat_at(&self, f: &Function, id: usize, h: Handle<E>, v: f64) -> bool {
        self.flat(f, id, h, v, 0)
    }

    fn flat(&self, f: &Function, id: usize, h: Handle<E>, v: f64, depth: u32) -> bool {
        let Some(n) = self.sound().num(id, h) else {
            return false;
        };
        if !n.comps().iter().any(|c| c.contains(v)) {
            return false;
        }
        // Per-draw: the same value for every pixel of the draw.
        if !n.facts.any(Facts::INPUT.with(Facts::TEXTURE)) {
            return true;
        }
        if depth > DEPTH {
            return false;
        }
        let d = depth + 1;
        let flat = |x: Handle<E>, w: f64| self.flat(f, id, x, w, d);
        let can = |x: Handle<E>, test: &dyn Fn(f64, f64) -> bool| {
            self.sound()
                .num(id, x)
                .is_some_and(|n| n.comps().iter().any(|c| test(c.lo, c.hi)))
        };
        let point = |x: Handle<E>| {
            self.sound()
                .num(id, x)
                .and_then(|n| n.hull().as_point())
                .filter(|p| p.is_finite())
        };
        match f.expressions[h] {
            E::ImageSample { .. } | E::ImageLoad { .. } => v == 0.0 || v == 1.0,
            E::AccessIndex { base, .. } | E::Swizzle { vector: base, .. } => flat(base, v),
            E::Splat { value, .. } => flat(value, v),
            E::Compose { ref components, .. } => components.iter().any(|c| flat(*c, v)),
            E::Load { pointer } => self.stored(f, id, pointer).iter().any(|x| flat(*x, v)),
            E::CallResult(callee) => self.returned_flat(callee.index(), v, d),
            E::Select { accept, reject, .. } => flat(accept, v) || flat(reject, v),
            E::As { expr, .. } => {
                let integer = matches!(
                    self.kind(id, expr),
                    Some(naga::ScalarKind::Sint | naga::ScalarKind::Uint | naga::ScalarKind::Bool)
                );
                integer || flat(expr, v)
            }
            E::Derivative { .. } => v == 0.0,
            E::Unary {
                op: naga::UnaryOperator::Negate,
                expr,
            } => flat(expr, -v),
            E::Binary { op, left, right } => match (op, point(left), point(right)) {
                (Bo::Add, _, Some(c)) => flat(left, v - c),
                (Bo::Add, Some(c), _) => flat(right, v - c),
                (Bo::Add, None, None) => v == 0.0 && flat(left, 0.0) && flat(right, 0.0),
                (Bo::Subtract, _, Some(c)) => flat(left, v + c),
                (Bo::Subtract, Some(c), _) => flat(right, c - v),
                (Bo::Subtract, None, None) => v == 0.0 && self.sound().same(f, id, left, right),
                (Bo::Multiply, _, Some(c)) if c != 0.0 => flat(left, v / c),
                (Bo::Multiply, Some(c), _) if c != 0.0 => flat(right, v / c),
                (Bo::Multiply, _, _) => v == 0.0 && (flat(left, 0.0) || flat(right, 0.0)),
                (Bo::Divide, _, Some(c)) if c != 0.0 => flat(left, v * c),
                (Bo::Divide, _, _) => v == 0.0 && flat(left, 0.0),
                _ => false,
            },
            E::Math {
                fun,
                arg,
                arg1,
                arg2,
                ..
            } => {
                let (a1, a2) = (arg1.unwrap_or(arg), arg2.unwrap_or(arg));
                match fun {
                    Mf::Max => {
                        flat(arg, v) && can(a1, &|lo, _| lo <= v)
                            || flat(a1, v) && can(arg, &|lo, _| lo <= v)
                    }
                    Mf::Min => {
                        flat(arg, v) && can(a1, &|_, hi| hi >= v)
                            || flat(a1, v) && can(arg, &|_, hi| hi >= v)
                    }
                    Mf::Clamp => {
                        flat(arg, v)
                            || flat(a1, v) && can(arg, &|lo, _| lo <= v)
                            || flat(a2, v) && can(arg, &|_, hi| hi >= v)
                    }
                    Mf::Saturate => {
                        flat(arg, v)
                            || v == 0.0 && can(arg, &|lo, _| lo <= 0.0)
                            || v == 1.0 && can(arg, &|_, hi| hi >= 1.0)
                    }
                    Mf::Abs => flat(arg, v) || flat(arg, -v),
                    Mf::Step | Mf::SmoothStep => v == 0.0 || v == 1.0,
                    Mf::Floor | Mf::Ceil | Mf::Round | Mf::Trunc | Mf::Sign => true,
                    Mf::Mix => {
                        flat(arg, v) && flat(a1, v)
                            || flat(a2, 0.0) && flat(arg, v)
                            || flat(a2, 1.0) && flat(a1, v)
                    }
                    Mf::Dot => v == 0.0 && (flat(arg, 0.0) || flat(a1, 0.0)),
                    Mf::Length | Mf::Sqrt => v == 0.0 && flat(arg, 0.0),
                    Mf::Distance => v == 0.0 && self.sound().same(f, id, arg, a1),
                    Mf::Pow => {
                        v == 0.0 && flat(arg, 0.0) || v == 1.0 && (flat(arg, 1.0) || flat(a1, 0.0))
                    }
                    Mf::Exp | Mf::Exp2 => v == 1.0 && flat(arg, 0.0),
                    Mf::Normalize | Mf::Cross => flat(arg, v) || fun == Mf::Cross && flat(a1, v),
                    _ => false,
                }
            }
            _ => false,
        }
    }

    /// The values stored whole into the local a load reads (nothing for other variables).
    pub(super) fn stored(&self, f: &Function, id: usize, pointer: Handle<E>) -> Vec<Handle<E>> {
        let E::LocalVariable(l) = f.expressions[pointer] else {
            return Vec::new();
        };
        let mut out: Vec<Handle<E>> = self.sound().functions[id]
            .stores
            .get(&l.index())
            .cloned()
            .unwrap_or_default();
        if let Some(init) = f.local_variables[l].init {
            out.push(init);
        }
        // A constant start value (`float r = 0.0;`) that other stores replace is not what a read
        // after them sees: keep the computed values only.
        let constant = |h: &Handle<E>| {
            matches!(
                f.expressions[*h],
                E::Literal(_) | E::Constant(_) | E::ZeroValue(_)
            )
        };
        if out.iter().any(|h| !constant(h)) {
            out.retain(|h| !constant(h));
        }
        out
    }

    /// Whether some value function `callee` returns is flat at `v`.
    fn returned_flat(&self, callee: usize, v: f64, depth: u32) -> bool {
        if callee >= self.module.functions.len() {
            return false;
        }
        let g = analysis::function(self.module, callee);
        self.flows()
            .returns(callee)
            .iter()
            .any(|x| self.flat(g, callee, *x, v, depth + 1))
    }
}
