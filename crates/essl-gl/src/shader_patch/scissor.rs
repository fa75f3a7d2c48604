//! A fragment module that tests the scissor box itself: Mesa 22's lavapipe lets a
//! multisampled draw cover samples of the pixels left of and below the scissor box, so draws
//! into multisampled targets with the scissor test on take a variant whose entry point first
//! discards fragments outside the box. The box is written into the module as constants (one
//! module per box): pipeline-overridable constants would make wgpu evaluate every constant
//! expression of the module again, and a shader's constant division by zero (`textureLod` of
//! an integer cube at `vec3(0)`) then fails the pipeline.

use naga::{
    BinaryOperator, Binding, Block, BuiltIn, Expression, FunctionArgument, Literal, Module, Scalar,
    Span, Statement, Type, TypeInner, VectorSize,
};

/// `module` whose fragment entry point discards fragments outside `[left, top, right,
/// bottom)` of the framebuffer (the coordinates of `@builtin(position)`) before anything else.
pub(crate) fn with_scissor_discard(module: &Module, rect: [u32; 4]) -> Module {
    let mut m = module.clone();
    let vec4 = m.types.insert(
        Type {
            name: None,
            inner: TypeInner::Vector {
                size: VectorSize::Quad,
                scalar: Scalar::F32,
            },
        },
        Span::UNDEFINED,
    );
    let Some(ep) = m
        .entry_points
        .iter_mut()
        .find(|e| e.stage == naga::ShaderStage::Fragment)
    else {
        return m;
    };
    let f = &mut ep.function;
    let position = f
        .arguments
        .iter()
        .position(|a| matches!(a.binding, Some(Binding::BuiltIn(BuiltIn::Position { .. }))))
        .unwrap_or_else(|| {
            f.arguments.push(FunctionArgument {
                name: Some("_essl_position".into()),
                ty: vec4,
                binding: Some(Binding::BuiltIn(BuiltIn::Position { invariant: false })),
            });
            f.arguments.len() - 1
        });
    let e = &mut f.expressions;
    let pos = e.append(
        Expression::FunctionArgument(position as u32),
        Span::UNDEFINED,
    );
    let edges: Vec<_> = rect
        .iter()
        .map(|&v| e.append(Expression::Literal(Literal::F32(v as f32)), Span::UNDEFINED))
        .collect();
    let start = e.len();
    let mut outside = None;
    let tests = [
        (0, BinaryOperator::Less),
        (1, BinaryOperator::Less),
        (0, BinaryOperator::GreaterEqual),
        (1, BinaryOperator::GreaterEqual),
    ];
    for ((axis, op), edge) in tests.into_iter().zip(edges) {
        let p = e.append(
            Expression::AccessIndex {
                base: pos,
                index: axis,
            },
            Span::UNDEFINED,
        );
        let past = e.append(
            Expression::Binary {
                op,
                left: p,
                right: edge,
            },
            Span::UNDEFINED,
        );
        outside = Some(match outside {
            Some(o) => e.append(
                Expression::Binary {
                    op: BinaryOperator::LogicalOr,
                    left: o,
                    right: past,
                },
                Span::UNDEFINED,
            ),
            None => past,
        });
    }
    let condition = outside.expect("four edges");
    let mut test = Block::new();
    test.push(Statement::Emit(e.range_from(start)), Span::UNDEFINED);
    test.push(
        Statement::If {
            condition,
            accept: Block::from_vec(vec![Statement::Kill]),
            reject: Block::new(),
        },
        Span::UNDEFINED,
    );
    f.body.splice(0..0, test);
    m
}
