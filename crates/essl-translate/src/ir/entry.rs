//! The entry point's own lines as a WGSL author writes them:
//! - `gl_Position.z = (gl_Position.z + gl_Position.w) * 0.5;` and
//!   `gl_FragCoord.y = height - frag_coord.y;` rather than a new vector of four components;
//! - `let matrix = mat4x4f(matrix_0, …)` for an input that takes several locations, rather
//!   than a store per column;
//! - `-> @location(0) vec4f` and `return color;` for a stage with one output, rather than a
//!   struct of one member.

use naga::{Expression, Handle, Module, Statement};

/// The name essl gives the clip position with its depth remapped.
const DEPTH_REMAP: &str = "clip_position_depth_0_to_w";

/// `return Out(vec4(p.x, p.y, (p.z + p.w) * 0.5, p.w), …)` as `p.z = (p.z + p.w) * 0.5;
/// return Out(p, …)`: the remap is one line on the variable the shader wrote.
pub(crate) fn depth_remap_in_place(module: &mut Module, ep: usize) -> bool {
    let f = &mut module.entry_points[ep].function;
    let Some((&remap, _)) = f.named_expressions.iter().find(|(_, n)| *n == DEPTH_REMAP) else {
        return false;
    };
    let Expression::Compose { ref components, .. } = f.expressions[remap] else {
        return false;
    };
    let [x, y, nz, w] = components[..] else {
        return false;
    };
    let component = |h: Handle<Expression>, k: u32| match f.expressions[h] {
        Expression::AccessIndex { base, index } if index == k => Some(base),
        _ => None,
    };
    let (Some(vx), Some(vy), Some(vw)) = (component(x, 0), component(y, 1), component(w, 3)) else {
        return false;
    };
    let Expression::Load { pointer } = f.expressions[vx] else {
        return false;
    };
    if vx != vy || vx != vw {
        return false;
    }
    let variable = f.expressions[pointer].clone();
    if !matches!(
        variable,
        Expression::LocalVariable(_) | Expression::GlobalVariable(_)
    ) {
        return false;
    }
    let Some(Statement::Return { value: Some(ret) }) = f.body.last() else {
        return false;
    };
    let ret = *ret;
    let Expression::Compose { ty, ref components } = f.expressions[ret] else {
        return false;
    };
    let Some(k) = components.iter().position(|c| *c == remap) else {
        return false;
    };
    let mut components = components.clone();
    let span = f
        .body
        .span_iter()
        .last()
        .map_or(naga::Span::UNDEFINED, |(_, s)| *s);
    let var = f.expressions.append(variable, naga::Span::UNDEFINED);
    let z = f.expressions.append(
        Expression::AccessIndex {
            base: var,
            index: 2,
        },
        naga::Span::UNDEFINED,
    );
    let value = f
        .expressions
        .append(Expression::Load { pointer: var }, naga::Span::UNDEFINED);
    components[k] = value;
    let out = f.expressions.append(
        Expression::Compose { ty, components },
        naga::Span::UNDEFINED,
    );
    f.named_expressions.shift_remove(&remap);
    f.named_expressions.insert(nz, DEPTH_REMAP.into());
    let last = f.body.len() - 1;
    f.body.cull(last..);
    f.body
        .push(Statement::Emit(naga::Range::new_from_bounds(z, z)), span);
    f.body.push(
        Statement::Store {
            pointer: z,
            value: nz,
        },
        span,
    );
    f.body.push(
        Statement::Emit(naga::Range::new_from_bounds(value, out)),
        span,
    );
    f.body.push(Statement::Return { value: Some(out) }, span);
    true
}

/// An entry point returning a struct of one member returns that member itself
/// (`-> @location(0) vec4f`, `return color;`).
pub(crate) fn single_output(module: &mut Module, ep: usize) -> bool {
    let f = &mut module.entry_points[ep].function;
    let Some(result) = &f.result else {
        return false;
    };
    let out = result.ty;
    let naga::TypeInner::Struct { members, .. } = &module.types[out].inner else {
        return false;
    };
    let [member] = &members[..] else {
        return false;
    };
    let mut values = Vec::new();
    if !returned_members(&f.body, &f.expressions, out, &mut values) {
        return false;
    }
    f.result = Some(naga::FunctionResult {
        ty: member.ty,
        binding: member.binding.clone(),
    });
    let mut k = 0;
    set_returns(&mut f.body, &values, &mut k);
    true
}

/// The member each `return` of `b` gives the one-member struct `out`; false when a `return`
/// is not such a constructor.
fn returned_members(
    b: &naga::Block,
    exprs: &naga::Arena<Expression>,
    out: Handle<naga::Type>,
    values: &mut Vec<Handle<Expression>>,
) -> bool {
    b.iter().all(|s| match s {
        Statement::Return { value: Some(v) } => match &exprs[*v] {
            Expression::Compose { ty, components } if *ty == out && components.len() == 1 => {
                values.push(components[0]);
                true
            }
            _ => false,
        },
        Statement::Return { value: None } => false,
        Statement::Block(b) => returned_members(b, exprs, out, values),
        Statement::If { accept, reject, .. } => {
            returned_members(accept, exprs, out, values)
                && returned_members(reject, exprs, out, values)
        }
        Statement::Switch { cases, .. } => cases
            .iter()
            .all(|c| returned_members(&c.body, exprs, out, values)),
        Statement::Loop {
            body, continuing, ..
        } => {
            returned_members(body, exprs, out, values)
                && returned_members(continuing, exprs, out, values)
        }
        _ => true,
    })
}

fn set_returns(b: &mut naga::Block, values: &[Handle<Expression>], k: &mut usize) {
    for s in b.iter_mut() {
        match s {
            Statement::Return { value: Some(v) } => {
                *v = values[*k];
                *k += 1;
            }
            Statement::Block(b) => set_returns(b, values, k),
            Statement::If { accept, reject, .. } => {
                set_returns(accept, values, k);
                set_returns(reject, values, k);
            }
            Statement::Switch { cases, .. } => {
                for c in cases {
                    set_returns(&mut c.body, values, k);
                }
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                set_returns(body, values, k);
                set_returns(continuing, values, k);
            }
            _ => {}
        }
    }
}

/// The name essl gives `gl_FragCoord` with its y flipped.
const FLIP: &str = "frag_coord_y_up";

/// `v = vec4(a.x, h - a.y, a.z, a.w)` as `v = a; v.y = h - a.y;`.
pub(crate) fn flip_in_place(module: &mut Module, ep: usize) -> bool {
    let f = &mut module.entry_points[ep].function;
    let Some((&flip, _)) = f.named_expressions.iter().find(|(_, n)| *n == FLIP) else {
        return false;
    };
    let Expression::Compose { ref components, .. } = f.expressions[flip] else {
        return false;
    };
    let [x, y, z, w] = components[..] else {
        return false;
    };
    let base = |h: Handle<Expression>, k: u32| match f.expressions[h] {
        Expression::AccessIndex { base, index } if index == k => Some(base),
        _ => None,
    };
    let (Some(a), Some(az), Some(aw)) = (base(x, 0), base(z, 2), base(w, 3)) else {
        return false;
    };
    let Expression::Binary {
        op: naga::BinaryOperator::Subtract,
        right,
        ..
    } = f.expressions[y]
    else {
        return false;
    };
    if base(right, 1) != Some(a) || az != a || aw != a {
        return false;
    }
    let Some(at) = f
        .body
        .iter()
        .position(|s| matches!(s, Statement::Store { value, .. } if *value == flip))
    else {
        return false;
    };
    let Statement::Store { pointer, .. } = f.body[at] else {
        return false;
    };
    let span = f
        .body
        .span_iter()
        .nth(at)
        .map_or(naga::Span::UNDEFINED, |(_, s)| *s);
    let component = f.expressions.append(
        Expression::AccessIndex {
            base: pointer,
            index: 1,
        },
        span,
    );
    f.named_expressions.shift_remove(&flip);
    f.named_expressions.insert(y, FLIP.into());
    let mut with_spans = naga::Block::new();
    for s in [
        Statement::Store { pointer, value: a },
        Statement::Emit(naga::Range::new_from_bounds(component, component)),
        Statement::Store {
            pointer: component,
            value: y,
        },
    ] {
        with_spans.push(s, span);
    }
    f.body.splice(at..at + 1, with_spans);
    true
}

/// An input of several locations (a matrix, an array), stored column by column from the
/// entry point's arguments, as one constructor of its arguments.
pub(crate) fn compose_inputs(module: &mut Module, ep: usize) -> bool {
    let types = &module.types;
    let f = &mut module.entry_points[ep].function;
    let mut changed = false;
    for (l, local) in f.local_variables.iter() {
        let count = match types[local.ty].inner {
            naga::TypeInner::Matrix { columns, .. } => columns as usize,
            naga::TypeInner::Array {
                size: naga::ArraySize::Constant(n),
                ..
            } => n.get() as usize,
            naga::TypeInner::Struct { ref members, .. } => members.len(),
            _ => continue,
        };
        // The top-level stores of arguments into element `i` of the local, in order.
        let mut stores: Vec<(usize, Handle<Expression>)> = Vec::new();
        let mut other = false;
        let is_local = |h: Handle<Expression>| f.expressions[h] == Expression::LocalVariable(l);
        for (k, s) in f.body.iter().enumerate() {
            if let Statement::Store { pointer, value } = *s {
                match f.expressions[pointer] {
                    Expression::AccessIndex { base, index }
                        if is_local(base)
                            && index as usize == stores.len()
                            && matches!(f.expressions[value], Expression::FunctionArgument(_)) =>
                    {
                        stores.push((k, value));
                    }
                    _ if is_local(pointer) || root_is(&f.expressions, pointer, l) => other = true,
                    _ => {}
                }
            }
        }
        if other || stores.len() != count || count == 0 {
            continue;
        }
        let span = f
            .body
            .span_iter()
            .nth(stores[0].0)
            .map_or(naga::Span::UNDEFINED, |(_, s)| *s);
        let var = f.expressions.append(Expression::LocalVariable(l), span);
        let compose = f.expressions.append(
            Expression::Compose {
                ty: local.ty,
                components: stores.iter().map(|(_, v)| *v).collect(),
            },
            span,
        );
        let first = stores[0].0;
        for &(k, _) in stores.iter().rev() {
            f.body.cull(k..k + 1);
        }
        let mut replacement = naga::Block::new();
        replacement.push(
            Statement::Emit(naga::Range::new_from_bounds(compose, compose)),
            span,
        );
        replacement.push(
            Statement::Store {
                pointer: var,
                value: compose,
            },
            span,
        );
        f.body.splice(first..first, replacement);
        changed = true;
    }
    changed
}

/// Whether a pointer expression points into local `l`.
fn root_is(
    exprs: &naga::Arena<Expression>,
    mut h: Handle<Expression>,
    l: Handle<naga::LocalVariable>,
) -> bool {
    loop {
        match exprs[h] {
            Expression::Access { base, .. } | Expression::AccessIndex { base, .. } => h = base,
            Expression::LocalVariable(v) => return v == l,
            _ => return false,
        }
    }
}
