//! Transform feedback capture: a vertex entry point rewritten so that, besides returning its
//! outputs, it stores the captured ones in storage buffers, one record per vertex.
//!
//! wgpu has no transform feedback; a vertex shader that writes storage buffers
//! (`VERTEX_WRITABLE_STORAGE`) does the same job for `draw_arrays`, the only draws WebGL2
//! captures: vertex `i` of instance `j` of a draw of `count` vertices from `first` writes
//! record `base + j × count + (i − first)`, which is GL's order for `POINTS`, `LINES` and
//! `TRIANGLES`. The buffers are `@group(2) @binding(b)` (`array<u32>`, each value's
//! components bitcast to words) and the parameters a uniform block at `@group(2)
//! @binding(4)`: `first`, `count`, and the first record's word of each buffer.

use naga::{
    AddressSpace, Arena, ArraySize, Binding, Block, BuiltIn, Expression, Function,
    FunctionArgument, GlobalVariable, Handle, Literal, Module, ResourceBinding, Scalar, Span,
    Statement, StorageAccess, StructMember, Type, TypeInner, UnaryOperator, VectorSize,
};

use super::{main_index, move_body_to_function, Builder};

/// The binding of the parameters' uniform block in group 2.
pub(crate) const PARAMS_BINDING: u32 = 4;

/// Where a captured value is among the vertex outputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum CaptureSource {
    /// The output at a location.
    Location(u32),
    /// `gl_Position`, captured as GL's (the remapping to the API's clip space undone).
    Position,
    /// `gl_PointSize`.
    PointSize,
}

/// One captured output (one location of a matrix or array), and where its words go.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct CaptureValue {
    pub(crate) source: CaptureSource,
    /// Components captured (1 to 4).
    pub(crate) words: u32,
    /// The buffer (binding) written.
    pub(crate) buffer: u32,
    /// Word offset of the value in a record, and words per record of that buffer.
    pub(crate) offset: u32,
    pub(crate) stride: u32,
}

/// What a draw captures.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct CaptureSpec {
    pub(crate) values: Vec<CaptureValue>,
    /// Buffers written: 1 interleaved, or one per varying separate (at most 4).
    pub(crate) buffers: u32,
}

/// The u32, vec4<u32> and params struct types, and a runtime array of u32.
struct Types {
    u32: Handle<Type>,
    words: Handle<Type>,
}

fn types(m: &mut Module) -> Types {
    let u32 = m.types.insert(
        Type {
            name: None,
            inner: TypeInner::Scalar(Scalar::U32),
        },
        Span::UNDEFINED,
    );
    let words = m.types.insert(
        Type {
            name: None,
            inner: TypeInner::Array {
                base: u32,
                size: ArraySize::Dynamic,
                stride: 4,
            },
        },
        Span::UNDEFINED,
    );
    Types { u32, words }
}

/// The parameters block: `first`, `count`, two words of padding, `base: vec4<u32>`.
fn params_type(m: &mut Module, u32: Handle<Type>) -> Handle<Type> {
    let vec4 = m.types.insert(
        Type {
            name: None,
            inner: TypeInner::Vector {
                size: VectorSize::Quad,
                scalar: Scalar::U32,
            },
        },
        Span::UNDEFINED,
    );
    let member = |name: &str, ty, offset| StructMember {
        name: Some(name.into()),
        ty,
        binding: None,
        offset,
    };
    m.types.insert(
        Type {
            name: Some("EsslGlCapture".into()),
            inner: TypeInner::Struct {
                members: vec![
                    member("first", u32, 0),
                    member("count", u32, 4),
                    member("base", vec4, 16),
                ],
                span: 32,
            },
        },
        Span::UNDEFINED,
    )
}

fn global(
    m: &mut Module,
    name: &str,
    space: AddressSpace,
    binding: u32,
    ty: Handle<Type>,
) -> Handle<GlobalVariable> {
    m.global_variables.append(
        GlobalVariable {
            name: Some(name.into()),
            space,
            binding: Some(ResourceBinding { group: 2, binding }),
            ty,
            init: None,
            memory_decorations: Default::default(),
        },
        Span::UNDEFINED,
    )
}

/// The index of the argument bound to `builtin`, adding one when the entry point has none.
fn builtin_arg(
    arguments: &mut Vec<FunctionArgument>,
    builtin: BuiltIn,
    ty: Handle<Type>,
    name: &str,
) -> u32 {
    if let Some(i) = arguments
        .iter()
        .position(|a| a.binding == Some(Binding::BuiltIn(builtin)))
    {
        return i as u32;
    }
    arguments.push(FunctionArgument {
        name: Some(name.into()),
        ty,
        binding: Some(Binding::BuiltIn(builtin)),
    });
    arguments.len() as u32 - 1
}

/// A copy of vertex module `module` that also stores the outputs `spec` captures.
pub(crate) fn capture_outputs(module: &Module, spec: &CaptureSpec) -> Module {
    let mut m = module.clone();
    let Some(ep_index) = main_index(&m) else {
        return m;
    };
    let t = types(&mut m);
    let params_ty = params_type(&mut m, t.u32);
    let buffers: Vec<Handle<GlobalVariable>> = (0..spec.buffers)
        .map(|b| {
            global(
                &mut m,
                &format!("essl_gl_capture{b}"),
                AddressSpace::Storage {
                    access: StorageAccess::LOAD | StorageAccess::STORE,
                },
                b,
                t.words,
            )
        })
        .collect();
    let params = global(
        &mut m,
        "essl_gl_capture_params",
        AddressSpace::Uniform,
        PARAMS_BINDING,
        params_ty,
    );
    let original = std::mem::take(&mut m.entry_points[ep_index].function);
    let inner = move_body_to_function(&mut m, &original);
    let mut arguments = original.arguments.clone();
    let vertex = builtin_arg(
        &mut arguments,
        BuiltIn::VertexIndex,
        t.u32,
        "essl_gl_vertex",
    );
    let instance = builtin_arg(
        &mut arguments,
        BuiltIn::InstanceIndex,
        t.u32,
        "essl_gl_instance",
    );
    let mut b = Builder {
        expressions: Arena::new(),
        body: Block::new(),
    };
    let call_args: Vec<_> = (0..original.arguments.len() as u32)
        .map(|i| b.plain(Expression::FunctionArgument(i)))
        .collect();
    let result = original
        .result
        .as_ref()
        .map(|_| b.plain(Expression::CallResult(inner)));
    b.body.push(
        Statement::Call {
            function: inner,
            arguments: call_args,
            result,
        },
        Span::UNDEFINED,
    );
    if let (Some(r), Some(res)) = (&original.result, result) {
        let record = record_index(&mut b, params, vertex, instance);
        for v in &spec.values {
            let Some(value) = output_value(&mut b, &m, r.ty, &r.binding, res, v.source) else {
                continue;
            };
            store_value(&mut b, buffers[v.buffer as usize], params, record, v, value);
        }
    }
    b.body
        .push(Statement::Return { value: result }, Span::UNDEFINED);
    m.entry_points[ep_index].function = Function {
        name: original.name.clone(),
        arguments,
        result: original.result.clone(),
        local_variables: Arena::new(),
        expressions: b.expressions,
        named_expressions: Default::default(),
        body: b.body,
        diagnostic_filter_leaf: None,
    };
    m
}

/// `instance × count + (vertex − first)`.
fn record_index(
    b: &mut Builder,
    params: Handle<GlobalVariable>,
    vertex: u32,
    instance: u32,
) -> Handle<Expression> {
    let p = b.plain(Expression::GlobalVariable(params));
    let first_ptr = b.emit(Expression::AccessIndex { base: p, index: 0 });
    let first = b.emit(Expression::Load { pointer: first_ptr });
    let count_ptr = b.emit(Expression::AccessIndex { base: p, index: 1 });
    let count = b.emit(Expression::Load { pointer: count_ptr });
    let vi = b.plain(Expression::FunctionArgument(vertex));
    let ii = b.plain(Expression::FunctionArgument(instance));
    let within = b.emit(Expression::Binary {
        op: naga::BinaryOperator::Subtract,
        left: vi,
        right: first,
    });
    let before = b.emit(Expression::Binary {
        op: naga::BinaryOperator::Multiply,
        left: ii,
        right: count,
    });
    b.emit(Expression::Binary {
        op: naga::BinaryOperator::Add,
        left: before,
        right: within,
    })
}

/// The value of the output `source` in the entry point's result `res` (of type `ty`, bound
/// as `binding` when it is not a struct), and whether it is a vector; `gl_Position` as GL's.
fn output_value(
    b: &mut Builder,
    m: &Module,
    ty: Handle<Type>,
    binding: &Option<Binding>,
    res: Handle<Expression>,
    source: CaptureSource,
) -> Option<(Handle<Expression>, bool)> {
    let matches = |bind: &Option<Binding>| match (bind, source) {
        (Some(Binding::Location { location, .. }), CaptureSource::Location(l)) => *location == l,
        (Some(Binding::BuiltIn(BuiltIn::Position { .. })), CaptureSource::Position) => true,
        (Some(Binding::BuiltIn(BuiltIn::PointSize)), CaptureSource::PointSize) => true,
        _ => false,
    };
    let (value, value_ty) = if matches(binding) {
        (res, ty)
    } else {
        let TypeInner::Struct { members, .. } = &m.types[ty].inner else {
            return None;
        };
        let i = members.iter().position(|mm| matches(&mm.binding))?;
        let v = b.emit(Expression::AccessIndex {
            base: res,
            index: i as u32,
        });
        (v, members[i].ty)
    };
    let vector = matches!(m.types[value_ty].inner, TypeInner::Vector { .. });
    if source != CaptureSource::Position {
        return Some((value, vector));
    }
    // The lowering maps GL's clip position to the API's: y negated, z to (z + w) / 2.
    let c = |b: &mut Builder, i| {
        b.emit(Expression::AccessIndex {
            base: value,
            index: i,
        })
    };
    let (x, y, z, w) = (c(b, 0), c(b, 1), c(b, 2), c(b, 3));
    let gy = b.emit(Expression::Unary {
        op: UnaryOperator::Negate,
        expr: y,
    });
    let two = b.plain(Expression::Literal(Literal::F32(2.0)));
    let z2 = b.emit(Expression::Binary {
        op: naga::BinaryOperator::Multiply,
        left: z,
        right: two,
    });
    let gz = b.emit(Expression::Binary {
        op: naga::BinaryOperator::Subtract,
        left: z2,
        right: w,
    });
    // Under EXT_clip_control the lowering negated y and mapped z only where its overrides say
    // so: the value as the lowering left it (`lowered`) where override `name` is true, else
    // `undone`; `undone` alone where the module has no such override.
    let unless = |b: &mut Builder, name: &str, lowered, undone| match m
        .overrides
        .iter()
        .find(|(_, o)| o.name.as_deref() == Some(name))
    {
        Some((h, _)) => {
            let condition = b.plain(Expression::Override(h));
            b.emit(Expression::Select {
                condition,
                accept: lowered,
                reject: undone,
            })
        }
        None => undone,
    };
    let gy = unless(b, essl::program::CLIP_UPPER_LEFT, y, gy);
    let gz = unless(b, essl::program::CLIP_ZERO_TO_ONE, z, gz);
    let vec4 = m.types.iter().find_map(|(h, t)| {
        matches!(
            t.inner,
            TypeInner::Vector {
                size: VectorSize::Quad,
                scalar: Scalar::F32
            }
        )
        .then_some(h)
    })?;
    let gl = b.emit(Expression::Compose {
        ty: vec4,
        components: vec![x, gy, gz, w],
    });
    Some((gl, true))
}

/// Stores `value`'s components, bitcast to words, at `base[buffer] + record × stride +
/// offset + c` of the capture buffer.
fn store_value(
    b: &mut Builder,
    buffer: Handle<GlobalVariable>,
    params: Handle<GlobalVariable>,
    record: Handle<Expression>,
    v: &CaptureValue,
    (value, is_vector): (Handle<Expression>, bool),
) {
    let p = b.plain(Expression::GlobalVariable(params));
    let base_ptr = b.emit(Expression::AccessIndex { base: p, index: 2 });
    let slot_ptr = b.emit(Expression::AccessIndex {
        base: base_ptr,
        index: v.buffer,
    });
    let base = b.emit(Expression::Load { pointer: slot_ptr });
    let stride = b.plain(Expression::Literal(Literal::U32(v.stride)));
    let scaled = b.emit(Expression::Binary {
        op: naga::BinaryOperator::Multiply,
        left: record,
        right: stride,
    });
    let start = b.emit(Expression::Binary {
        op: naga::BinaryOperator::Add,
        left: base,
        right: scaled,
    });
    let array = b.plain(Expression::GlobalVariable(buffer));
    for c in 0..v.words {
        let comp = if is_vector {
            b.emit(Expression::AccessIndex {
                base: value,
                index: c,
            })
        } else {
            value
        };
        let word = b.emit(Expression::As {
            expr: comp,
            kind: naga::ScalarKind::Uint,
            convert: None,
        });
        let off = b.plain(Expression::Literal(Literal::U32(v.offset + c)));
        let index = b.emit(Expression::Binary {
            op: naga::BinaryOperator::Add,
            left: start,
            right: off,
        });
        let pointer = b.emit(Expression::Access { base: array, index });
        b.body.push(
            Statement::Store {
                pointer,
                value: word,
            },
            Span::UNDEFINED,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_captured_vertex_shader_validates() {
        let m = naga::front::wgsl::parse_str(
            "struct O { @builtin(position) p: vec4<f32>, @location(0) v: vec3<f32>, @location(1) s: f32 } \
             @vertex fn main(@location(0) a: vec4<f32>) -> O { return O(a, a.xyz, a.w); }",
        )
        .unwrap();
        let spec = CaptureSpec {
            values: vec![
                CaptureValue {
                    source: CaptureSource::Location(0),
                    words: 3,
                    buffer: 0,
                    offset: 0,
                    stride: 8,
                },
                CaptureValue {
                    source: CaptureSource::Location(1),
                    words: 1,
                    buffer: 0,
                    offset: 3,
                    stride: 8,
                },
                CaptureValue {
                    source: CaptureSource::Position,
                    words: 4,
                    buffer: 0,
                    offset: 4,
                    stride: 8,
                },
            ],
            buffers: 1,
        };
        let captured = capture_outputs(&m, &spec);
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::all(),
        )
        .validate(&captured)
        .unwrap_or_else(|e| panic!("{e:?}"));
    }
}
