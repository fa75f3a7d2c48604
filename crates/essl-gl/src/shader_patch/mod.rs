//! Rewrites a lowered module's entry point so that wgpu accepts the vertex data WebGL feeds
//! it and the fragment outputs fit the draw buffers, and ([`capture`]) so that the vertex
//! stage writes what transform feedback captures.
//!
//! wgpu accepts a vertex format *narrower* than the shader input of the same scalar kind
//! (Vulkan fills the missing components with 0, 0, 1 — GL's defaults), but rejects one that
//! is wider, of another kind (GL converts unnormalized integers to floats), or that does not
//! exist (no 3-component 8/16-bit formats, no normalized 32-bit integers). For those, the
//! entry point `main` becomes an ordinary function and a new `main` takes the inputs as the
//! formats deliver them, converts them to the declared types, and calls it. The same wrapper
//! widens a `float`/`vec2`/`vec3` fragment output at location 0 to `vec4` (alpha 1), which an
//! RGBA target requires.

use naga::{
    Arena, BinaryOperator, Binding, Block, Expression, Function, FunctionArgument, FunctionResult,
    Handle, Literal, MathFunction, Module, Scalar, Span, Statement, StructMember, SwizzleComponent,
    Type, TypeInner, VectorSize,
};

mod capture;
mod depth;
mod scissor;

pub(crate) use capture::{
    capture_outputs, CaptureSource, CaptureSpec, CaptureValue,
    PARAMS_BINDING as CAPTURE_PARAMS_BINDING,
};
pub(crate) use depth::without_frag_depth;
pub(crate) use scissor::with_scissor_discard;

use crate::program::{type_shape, ValueKind};

/// How to scale a normalized 32-bit integer (which no vertex format normalizes).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Norm32 {
    /// `max(x / (2³¹ − 1), −1)`
    Signed,
    /// `x / (2³² − 1)`
    Unsigned,
}

/// A packed `2_10_10_10` vertex word: x, y, z in 10 bits each from bit 0, w in the top 2.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Packed {
    /// `INT_2_10_10_10_REV` (two's complement fields) rather than `UNSIGNED_…`.
    pub(crate) signed: bool,
    /// Scaled to [0, 1] (or [−1, 1]) as GL normalizes.
    pub(crate) normalized: bool,
}

/// How one vertex input is fed, when that differs from what the shader declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct InputPatch {
    pub(crate) location: u32,
    /// The kind the vertex format delivers.
    pub(crate) fed_kind: ValueKind,
    /// The components the vertex format delivers.
    pub(crate) fed_count: u8,
    /// The components that hold data (3 for a 3-component attribute read as 4).
    pub(crate) used: u8,
    pub(crate) norm: Option<Norm32>,
    /// A packed word the wrapper takes apart into four floats.
    pub(crate) packed: Option<Packed>,
}

pub(super) fn scalar(kind: ValueKind) -> Scalar {
    match kind {
        ValueKind::Float => Scalar::F32,
        ValueKind::Sint => Scalar::I32,
        ValueKind::Uint => Scalar::U32,
    }
}

fn vector_size(n: u8) -> VectorSize {
    match n {
        2 => VectorSize::Bi,
        3 => VectorSize::Tri,
        _ => VectorSize::Quad,
    }
}

fn shape_type(module: &mut Module, kind: ValueKind, n: u8) -> Handle<Type> {
    let inner = if n == 1 {
        TypeInner::Scalar(scalar(kind))
    } else {
        TypeInner::Vector {
            size: vector_size(n),
            scalar: scalar(kind),
        }
    };
    module
        .types
        .insert(Type { name: None, inner }, Span::UNDEFINED)
}

fn literal(kind: ValueKind, one: bool) -> Literal {
    match (kind, one) {
        (ValueKind::Float, false) => Literal::F32(0.0),
        (ValueKind::Float, true) => Literal::F32(1.0),
        (ValueKind::Sint, false) => Literal::I32(0),
        (ValueKind::Sint, true) => Literal::I32(1),
        (ValueKind::Uint, false) => Literal::U32(0),
        (ValueKind::Uint, true) => Literal::U32(1),
    }
}

/// Appends expressions to a function, emitting those that need it.
pub(super) struct Builder {
    pub(super) expressions: Arena<Expression>,
    pub(super) body: Block,
}

impl Builder {
    /// An expression that is evaluated where it is emitted.
    pub(super) fn emit(&mut self, e: Expression) -> Handle<Expression> {
        let len = self.expressions.len();
        let h = self.expressions.append(e, Span::UNDEFINED);
        self.body.push(
            Statement::Emit(self.expressions.range_from(len)),
            Span::UNDEFINED,
        );
        h
    }

    /// An expression that needs no emitting (literals, arguments, call results).
    pub(super) fn plain(&mut self, e: Expression) -> Handle<Expression> {
        self.expressions.append(e, Span::UNDEFINED)
    }

    /// `value` (of `have` components, kind `kind`) widened to `want` components with GL's
    /// defaults (0, 0, 1 for y/z/w), as a value of type `ty`.
    fn widen(
        &mut self,
        value: Handle<Expression>,
        have: u8,
        want: u8,
        kind: ValueKind,
        ty: Handle<Type>,
    ) -> Handle<Expression> {
        if have >= want {
            return value;
        }
        let mut components = vec![value];
        for i in have..want {
            components.push(self.plain(Expression::Literal(literal(kind, i == 3))));
        }
        self.emit(Expression::Compose { ty, components })
    }

    /// The first `n` components of a vector of `have` components.
    fn take(&mut self, value: Handle<Expression>, have: u8, n: u8) -> Handle<Expression> {
        if n >= have {
            value
        } else if n == 1 {
            self.emit(Expression::AccessIndex {
                base: value,
                index: 0,
            })
        } else {
            self.emit(Expression::Swizzle {
                size: vector_size(n),
                vector: value,
                pattern: [
                    SwizzleComponent::X,
                    SwizzleComponent::Y,
                    SwizzleComponent::Z,
                    SwizzleComponent::W,
                ],
            })
        }
    }
}

/// Whether the module's fragment output at location 0 needs widening to `vec4`.
pub(crate) fn output_needs_widening(module: &Module) -> bool {
    let Some(ep) = crate::program::main_entry(module) else {
        return false;
    };
    let Some(result) = &ep.function.result else {
        return false;
    };
    let narrow = |ty| matches!(type_shape(module, ty), Some((_, n)) if n < 4);
    if let Some(Binding::Location { .. }) = result.binding {
        return narrow(result.ty);
    }
    if let TypeInner::Struct { members, .. } = &module.types[result.ty].inner {
        return members
            .iter()
            .any(|m| matches!(m.binding, Some(Binding::Location { .. })) && narrow(m.ty));
    }
    false
}

/// A copy of `module` whose entry point `main` takes its inputs as `patches` say and, if
/// `widen_output`, returns its location-0 output as `vec4`.
///
/// The steps: the original entry point's body becomes the function `essl_gl_main`
/// ([`move_body_to_function`]); a new body converts each patched input
/// ([`Builder::convert_input`]), calls it, and widens the output ([`widen_result`]).
pub(crate) fn wrap_entry_point(
    module: &Module,
    patches: &[InputPatch],
    widen_output: bool,
) -> Module {
    let mut m = module.clone();
    let Some(ep_index) = main_index(&m) else {
        return m;
    };
    let original = std::mem::take(&mut m.entry_points[ep_index].function);
    let inner_handle = move_body_to_function(&mut m, &original);

    let mut b = Builder {
        expressions: Arena::new(),
        body: Block::new(),
    };
    let mut arguments = Vec::new();
    let mut call_args = Vec::new();
    for (i, arg) in original.arguments.iter().enumerate() {
        let patch = match arg.binding {
            Some(Binding::Location { location, .. }) => {
                patches.iter().find(|p| p.location == location)
            }
            _ => None,
        };
        let declared = type_shape(&m, arg.ty);
        let (Some(p), Some(shape)) = (patch, declared) else {
            arguments.push(arg.clone());
            call_args.push(b.plain(Expression::FunctionArgument(i as u32)));
            continue;
        };
        let fed_ty = shape_type(&mut m, p.fed_kind, p.fed_count);
        let vec4 = shape_type(&mut m, ValueKind::Float, 4);
        arguments.push(FunctionArgument {
            name: arg.name.clone(),
            ty: fed_ty,
            binding: arg.binding.clone(),
        });
        call_args.push(b.convert_input(i as u32, arg.ty, p, shape, vec4));
    }

    let result_expr = original
        .result
        .as_ref()
        .map(|_| b.plain(Expression::CallResult(inner_handle)));
    b.body.push(
        Statement::Call {
            function: inner_handle,
            arguments: call_args,
            result: result_expr,
        },
        Span::UNDEFINED,
    );

    let (result, value) = match (widen_output, &original.result, result_expr) {
        (true, Some(r), Some(res)) => widen_result(&mut b, &mut m, r, res),
        _ => (original.result.clone(), result_expr),
    };
    b.body.push(Statement::Return { value }, Span::UNDEFINED);

    m.entry_points[ep_index].function = Function {
        name: original.name.clone(),
        arguments,
        result,
        local_variables: Arena::new(),
        expressions: b.expressions,
        named_expressions: Default::default(),
        body: b.body,
        diagnostic_filter_leaf: None,
    };
    m
}

/// The index of the entry point named `main` (else the first one), `None` without any.
pub(super) fn main_index(m: &Module) -> Option<usize> {
    m.entry_points
        .iter()
        .position(|e| e.name == "main")
        .or(if m.entry_points.is_empty() {
            None
        } else {
            Some(0)
        })
}

/// Adds the entry point's body to the module as the ordinary function `essl_gl_main`,
/// without bindings.
pub(super) fn move_body_to_function(m: &mut Module, original: &Function) -> Handle<Function> {
    let mut inner = original.clone();
    inner.name = Some("essl_gl_main".into());
    for arg in &mut inner.arguments {
        arg.binding = None;
    }
    if let Some(r) = &mut inner.result {
        r.binding = None;
    }
    m.functions.append(inner, Span::UNDEFINED)
}

impl Builder {
    /// Argument `index`, fed as `p` says, converted to the declared `(kind, n)` of type
    /// `declared_ty`: extra components dropped, the kind converted, normalized 32-bit
    /// integers scaled, missing components filled with GL's defaults.
    fn convert_input(
        &mut self,
        index: u32,
        declared_ty: Handle<Type>,
        p: &InputPatch,
        (kind, n): (ValueKind, u8),
        vec4: Handle<Type>,
    ) -> Handle<Expression> {
        let mut v = self.plain(Expression::FunctionArgument(index));
        if let Some(packed) = p.packed {
            let unpacked = self.unpack(v, packed, vec4);
            return self.take(unpacked, 4, n);
        }
        let k = p.used.min(n).min(p.fed_count);
        v = self.take(v, p.fed_count, k);
        if p.fed_kind != kind {
            let convert = if kind == ValueKind::Float || p.fed_kind == ValueKind::Float {
                Some(4)
            } else {
                None
            };
            v = self.emit(Expression::As {
                expr: v,
                kind: scalar(kind).kind,
                convert,
            });
        }
        if let Some(norm) = p.norm {
            v = self.normalize(v, norm, k);
        }
        self.widen(v, k, n, kind, declared_ty)
    }

    /// `v` (of `k` components) scaled as a normalized 32-bit integer: `max(x / (2³¹ − 1), −1)`
    /// or `x / (2³² − 1)`.
    fn normalize(&mut self, v: Handle<Expression>, norm: Norm32, k: u8) -> Handle<Expression> {
        let factor = match norm {
            Norm32::Signed => 1.0 / 2_147_483_647.0,
            Norm32::Unsigned => 1.0 / 4_294_967_295.0,
        };
        let f = self.plain(Expression::Literal(Literal::F32(factor)));
        let mut v = self.emit(Expression::Binary {
            op: BinaryOperator::Multiply,
            left: v,
            right: f,
        });
        if norm == Norm32::Signed {
            let mut lo = self.plain(Expression::Literal(Literal::F32(-1.0)));
            if k > 1 {
                lo = self.emit(Expression::Splat {
                    size: vector_size(k),
                    value: lo,
                });
            }
            v = self.emit(Expression::Math {
                fun: MathFunction::Max,
                arg: v,
                arg1: Some(lo),
                arg2: None,
                arg3: None,
            });
        }
        v
    }
}

/// The wrapper's result and returned value when the location-0 output is widened to `vec4`:
/// a bound `float`/`vec2`/`vec3` result directly, or the member of a result struct (the
/// struct rebuilt as `EsslGlOutput`). Other results are returned as they are.
fn widen_result(
    b: &mut Builder,
    m: &mut Module,
    r: &FunctionResult,
    res: Handle<Expression>,
) -> (Option<FunctionResult>, Option<Handle<Expression>>) {
    if let Some(Binding::Location { .. }) = r.binding {
        if let Some((kind, n)) = type_shape(m, r.ty).filter(|(_, n)| *n < 4) {
            let vec4 = shape_type(m, kind, 4);
            let value = b.widen(res, n, 4, kind, vec4);
            let result = FunctionResult {
                ty: vec4,
                binding: r.binding.clone(),
            };
            return (Some(result), Some(value));
        }
    } else if let TypeInner::Struct { members, .. } = m.types[r.ty].inner.clone() {
        let (value, struct_ty) = widen_struct(b, m, &members, res);
        let result = FunctionResult {
            ty: struct_ty,
            binding: None,
        };
        return (Some(result), Some(value));
    }
    (Some(r.clone()), Some(res))
}

/// A copy of the output struct `res` (of `members`) whose location members are widened to
/// four components: the composed value and its new struct type, laid out again.
fn widen_struct(
    b: &mut Builder,
    m: &mut Module,
    members: &[StructMember],
    res: Handle<Expression>,
) -> (Handle<Expression>, Handle<Type>) {
    let mut new_members = Vec::new();
    let mut components = Vec::new();
    let mut offset = 0u32;
    let mut layouter = naga::proc::Layouter::default();
    let _ = layouter.update(m.to_ctx());
    for (j, member) in members.iter().enumerate() {
        let mut v = b.emit(Expression::AccessIndex {
            base: res,
            index: j as u32,
        });
        let mut ty = member.ty;
        if let (Some(Binding::Location { .. }), Some((kind, n))) =
            (&member.binding, type_shape(m, member.ty))
        {
            if n < 4 {
                let vec4 = shape_type(m, kind, 4);
                v = b.widen(v, n, 4, kind, vec4);
                ty = vec4;
            }
        }
        let _ = layouter.update(m.to_ctx());
        offset = layouter[ty].alignment.round_up(offset);
        let size = layouter[ty].size;
        new_members.push(StructMember {
            name: member.name.clone(),
            ty,
            binding: member.binding.clone(),
            offset,
        });
        offset += size;
        components.push(v);
    }
    let span = offset.div_ceil(16) * 16;
    let struct_ty = m.types.insert(
        Type {
            name: Some("EsslGlOutput".into()),
            inner: TypeInner::Struct {
                members: new_members,
                span,
            },
        },
        Span::UNDEFINED,
    );
    let value = b.emit(Expression::Compose {
        ty: struct_ty,
        components,
    });
    (value, struct_ty)
}

impl Builder {
    /// The four components of a packed `2_10_10_10` word `v` (an `i32` or `u32`) as a `vec4`
    /// of type `vec4`: each field extracted (sign-extended for the signed type), converted,
    /// and scaled as GL normalizes it (`c / (2ᵇ − 1)`, or `max(c / (2ᵇ⁻¹ − 1), −1)`).
    fn unpack(
        &mut self,
        v: Handle<Expression>,
        p: Packed,
        vec4: Handle<Type>,
    ) -> Handle<Expression> {
        let lit = |b: &mut Self, l: Literal| b.plain(Expression::Literal(l));
        let mut components = Vec::new();
        for (offset, bits) in [(0u32, 10u32), (10, 10), (20, 10), (30, 2)] {
            let o = lit(self, Literal::U32(offset));
            let c = lit(self, Literal::U32(bits));
            let field = self.emit(Expression::Math {
                fun: MathFunction::ExtractBits,
                arg: v,
                arg1: Some(o),
                arg2: Some(c),
                arg3: None,
            });
            let mut f = self.emit(Expression::As {
                expr: field,
                kind: naga::ScalarKind::Float,
                convert: Some(4),
            });
            if p.normalized {
                let max = if p.signed {
                    (1u32 << (bits - 1)) - 1
                } else {
                    (1u32 << bits) - 1
                };
                let d = lit(self, Literal::F32(max as f32));
                f = self.emit(Expression::Binary {
                    op: BinaryOperator::Divide,
                    left: f,
                    right: d,
                });
                if p.signed {
                    let lo = lit(self, Literal::F32(-1.0));
                    f = self.emit(Expression::Math {
                        fun: MathFunction::Max,
                        arg: f,
                        arg1: Some(lo),
                        arg2: None,
                        arg3: None,
                    });
                }
            }
            components.push(f);
        }
        self.emit(Expression::Compose {
            ty: vec4,
            components,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn validate(m: &Module) {
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::all(),
        )
        .validate(m)
        .unwrap_or_else(|e| panic!("{e:?}"));
    }

    #[test]
    fn wrapped_vertex_inputs_validate() {
        let m = naga::front::wgsl::parse_str(
            "@vertex fn main(@location(0) p: vec4<f32>, @location(1) c: vec3<f32>, @location(2) i: i32) \
             -> @builtin(position) vec4<f32> { return p + vec4(c, f32(i)); }",
        )
        .unwrap();
        let patches = [
            InputPatch {
                location: 0,
                fed_kind: ValueKind::Sint,
                fed_count: 4,
                used: 3,
                norm: None,
                packed: None,
            },
            InputPatch {
                location: 1,
                fed_kind: ValueKind::Uint,
                fed_count: 2,
                used: 2,
                norm: Some(Norm32::Unsigned),
                packed: None,
            },
            InputPatch {
                location: 2,
                fed_kind: ValueKind::Sint,
                fed_count: 4,
                used: 4,
                norm: None,
                packed: None,
            },
        ];
        validate(&wrap_entry_point(&m, &patches, false));
    }

    #[test]
    fn widened_fragment_outputs_validate() {
        let m = naga::front::wgsl::parse_str(
            "@fragment fn main() -> @location(0) vec3<f32> { return vec3(1.0); }",
        )
        .unwrap();
        assert!(output_needs_widening(&m));
        validate(&wrap_entry_point(&m, &[], true));
        let m = naga::front::wgsl::parse_str(
            "struct O { @location(0) c: vec2<f32>, @location(1) d: vec4<f32> } \
             @fragment fn main() -> O { return O(vec2(1.0), vec4(0.5)); }",
        )
        .unwrap();
        assert!(output_needs_widening(&m));
        validate(&wrap_entry_point(&m, &[], true));
    }
}
