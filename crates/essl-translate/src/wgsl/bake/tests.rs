//! A unit test of [`super::bakes`] on IR built by hand.

use naga::{
    BinaryOperator, Block, Expression, Function, Literal, LocalVariable, Module, Range, Scalar,
    Span, Statement, Type, TypeInner,
};

use super::{bakes, function_writes, Fate};
use crate::wgsl::analysis::Shape;

/// `var x = 1.0; let v = x; loop { x = v + 1.0; if x > 3.0 { break; } }`, with `v` an
/// unnamed load before the loop: read again in the loop, it would see the stores of the
/// iterations before (a loop-carried value). It must stay where it is.
#[test]
fn a_load_before_a_loop_is_not_moved_into_it() {
    let mut module = Module::default();
    let ty = module.types.insert(
        Type {
            name: None,
            inner: TypeInner::Scalar(Scalar::F32),
        },
        Span::UNDEFINED,
    );
    let mut f = Function::default();
    let x = f.local_variables.append(
        LocalVariable {
            name: Some("x".into()),
            ty,
            init: None,
        },
        Span::UNDEFINED,
    );
    let e = &mut f.expressions;
    let s = Span::UNDEFINED;
    let px = e.append(Expression::LocalVariable(x), s);
    let one = e.append(Expression::Literal(Literal::F32(1.0)), s);
    let three = e.append(Expression::Literal(Literal::F32(3.0)), s);
    let v = e.append(Expression::Load { pointer: px }, s);
    let sum = e.append(
        Expression::Binary {
            op: BinaryOperator::Add,
            left: v,
            right: one,
        },
        s,
    );
    let again = e.append(Expression::Load { pointer: px }, s);
    let done = e.append(
        Expression::Binary {
            op: BinaryOperator::Greater,
            left: again,
            right: three,
        },
        s,
    );
    let mut body = Block::new();
    body.push(Statement::Emit(Range::new_from_bounds(sum, sum)), s);
    body.push(
        Statement::Store {
            pointer: px,
            value: sum,
        },
        s,
    );
    body.push(Statement::Emit(Range::new_from_bounds(again, done)), s);
    body.push(
        Statement::If {
            condition: done,
            accept: Block::from_vec(vec![Statement::Break]),
            reject: Block::new(),
        },
        s,
    );
    f.body.push(
        Statement::Store {
            pointer: px,
            value: one,
        },
        s,
    );
    f.body
        .push(Statement::Emit(Range::new_from_bounds(v, v)), s);
    f.body.push(
        Statement::Loop {
            body,
            continuing: Block::new(),
            break_if: None,
        },
        s,
    );
    let h = module.functions.append(f, s);
    let info = crate::ir::validate(&module).expect("the function validates");
    let shape = Shape::new(&module, &module.functions[h], &info[h]);
    let fates = bakes(&shape, &function_writes(&module));
    assert_eq!(fates.fate[v.index()], Fate::Bake);
    // The load in the loop, used where it is evaluated, is written there.
    assert_eq!(fates.fate[again.index()], Fate::Inline);
}
