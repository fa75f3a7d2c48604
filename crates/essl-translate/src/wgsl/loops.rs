//! Loops in the form their GLSL had: naga has one `loop` (a body, a `continuing` block and a
//! `break if`); essl lowers `for (init; cond; step)` to `init; loop { if !cond { break; } …
//! continuing { step } }` and `while (cond)` likewise without the step. These are written
//! `for (var i = 0; i < n; i++) { … }` and `while cond { … }` again, where nothing else stands
//! between the parts (the condition's and the step's expressions all written inside them,
//! the declaration used by nothing after the loop).

use std::collections::HashMap;

use naga::{Expression, Handle, Statement};

use super::analysis::{Pos, Shape};
use super::bake::{Bakes, Fate};
use super::decls::{Decl, Decls};

/// How a loop statement is written, when it is a `for` or a `while`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct LoopForm {
    /// The declaring store folded into a `for`'s first part.
    pub init: Option<Pos>,
    /// The condition, and whether it is the negation of this expression.
    pub cond: (Handle<Expression>, bool),
    /// How many statements of the body the header stands for.
    pub skip: usize,
    /// The `continuing` statement written as the `for`'s step.
    pub update: Option<Pos>,
}

/// The `for` and `while` loops of the function, by the position of their `loop` statement.
pub(crate) fn loop_forms(shape: &Shape, bakes: &Bakes, decls: &Decls) -> HashMap<Pos, LoopForm> {
    let mut out = HashMap::new();
    for (block, statements) in shape.statements.iter().enumerate() {
        for (index, s) in statements.iter().enumerate() {
            let Statement::Loop {
                body,
                continuing,
                break_if: None,
            } = s
            else {
                continue;
            };
            let pos = Pos { block, index };
            let body_id = shape.id(body);
            let Some((cond, skip)) = condition(shape, bakes, body, body_id) else {
                continue;
            };
            let Some(update) = step(shape, bakes, decls, continuing) else {
                continue;
            };
            let init = init(shape, bakes, decls, pos);
            out.insert(
                pos,
                LoopForm {
                    init,
                    cond,
                    skip,
                    update,
                },
            );
        }
    }
    out
}

/// Whether an `Emit` writes nothing (all its expressions go where they are used).
fn silent(bakes: &Bakes, s: &Statement) -> bool {
    match s {
        Statement::Emit(range) => range.clone().all(|h| bakes.fate[h.index()] != Fate::Bake),
        _ => false,
    }
}

/// `if !cond { break; }` at the top of the body: (the condition, negated?) and the number of
/// statements up to it.
fn condition(
    shape: &Shape,
    bakes: &Bakes,
    body: &naga::Block,
    _: usize,
) -> Option<((Handle<Expression>, bool), usize)> {
    let j = body.iter().position(|s| !matches!(s, Statement::Emit(_)))?;
    if !body.iter().take(j).all(|s| silent(bakes, s)) {
        return None;
    }
    let Statement::If {
        condition,
        accept,
        reject,
    } = &body[j]
    else {
        return None;
    };
    if !reject.is_empty() || accept.len() != 1 || !matches!(accept[0], Statement::Break) {
        return None;
    }
    let cond = match *shape.expr(*condition) {
        Expression::Unary {
            op: naga::UnaryOperator::LogicalNot,
            expr,
        } if bakes.fate[condition.index()] == Fate::Inline => (expr, false),
        _ => (*condition, true),
    };
    Some((cond, j + 1))
}

/// The step: `Some(None)` for an empty `continuing`, `Some(Some(pos))` for one statement
/// after silent `Emit`s, `None` otherwise.
fn step(
    shape: &Shape,
    bakes: &Bakes,
    decls: &Decls,
    continuing: &naga::Block,
) -> Option<Option<Pos>> {
    if continuing.is_empty() {
        return Some(None);
    }
    let id = shape.id(continuing);
    let last = continuing.len() - 1;
    if !continuing.iter().take(last).all(|s| silent(bakes, s)) {
        return None;
    }
    let pos = Pos {
        block: id,
        index: last,
    };
    match &continuing[last] {
        Statement::Store { .. } if !decls.at.contains_key(&pos) => Some(Some(pos)),
        Statement::Call { result, .. }
            if result.is_none_or(|r| bakes.fate[r.index()] == Fate::Unused) =>
        {
            Some(Some(pos))
        }
        _ => None,
    }
}

/// The declaration right before the loop that only the loop uses.
fn init(shape: &Shape, bakes: &Bakes, decls: &Decls, pos: Pos) -> Option<Pos> {
    let statements = &shape.statements[pos.block];
    let mut k = pos.index.checked_sub(1)?;
    while matches!(statements[k], Statement::Emit(_)) {
        if !silent(bakes, statements[k]) {
            return None;
        }
        k = k.checked_sub(1)?;
    }
    let store = Pos {
        block: pos.block,
        index: k,
    };
    let local = *decls.at.get(&store)?;
    if !matches!(decls.decl.get(&local), Some(Decl::At { .. })) {
        return None;
    }
    let only_here = decls.refs[&local].iter().all(|r| {
        shape
            .holder(*r, pos.block)
            .is_some_and(|i| i == k || i == pos.index)
    });
    only_here.then_some(store)
}
