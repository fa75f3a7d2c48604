//! The entry point in the shape a WGSL author gives it.
//!
//! essl lowers a shader to an entry point that copies each input into a private variable,
//! calls the shader's `main`, and returns the outputs read from their private variables —
//! right for running GLSL, but in WGSL that is a `var<private>` per input and output, a copy
//! of each, and a function called once. A person writes one entry point whose arguments are
//! the inputs and which returns its outputs. So, where `main` is called once and returns only
//! at its end:
//! - `main`'s body takes the place of its call in the entry point;
//! - each private variable that no other function uses becomes a local variable of the entry
//!   point (an input is then read from its argument, an output is a local the entry point
//!   returns: [`crate::wgsl`] writes both with their GLSL names);
//! - what is no longer used goes ([`naga::compact`]).
//!
//! The result is validated again; when it does not validate (it always did on the corpora),
//! the module is written as lowered.

use std::collections::HashSet;

use naga::{Expression, Function, GlobalVariable, Handle, Module, Statement};

use super::Maps;

/// The module with its entry points restructured, and its validation info; `None` when
/// nothing changed or the result does not validate.
pub(crate) fn restructure(module: &Module) -> Option<(Module, naga::valid::ModuleInfo)> {
    let mut m = module.clone();
    let mut changed = false;
    for i in 0..m.entry_points.len() {
        changed |= inline_main(&mut m, i);
    }
    // The inlined function is called no more: it goes, and with it its uses of globals.
    naga::compact::compact(&mut m, naga::compact::KeepUnused::No);
    for i in 0..m.entry_points.len() {
        changed |= privates_to_locals(&mut m, i);
        changed |= super::entry::depth_remap_in_place(&mut m, i);
        changed |= super::entry::flip_in_place(&mut m, i);
        changed |= super::entry::compose_inputs(&mut m, i);
        changed |= super::entry::single_output(&mut m, i);
    }
    if !changed {
        return None;
    }
    naga::compact::compact(&mut m, naga::compact::KeepUnused::No);
    let info = super::validate(&m)?;
    Some((m, info))
}

/// Inlines the function the entry point calls once, when nothing else calls it, it takes and
/// returns nothing, and returns only at its end.
fn inline_main(module: &mut Module, ep: usize) -> bool {
    let body = &module.entry_points[ep].function.body;
    let calls: Vec<(usize, Handle<Function>)> = body
        .iter()
        .enumerate()
        .filter_map(|(k, s)| match s {
            Statement::Call {
                function,
                arguments,
                result: None,
            } if arguments.is_empty() => Some((k, *function)),
            _ => None,
        })
        .collect();
    let [(at, callee)] = calls[..] else {
        return false;
    };
    let f = &module.functions[callee];
    if !f.arguments.is_empty() || f.result.is_some() || call_count(module, callee) != 1 {
        return false;
    }
    let last = f.body.len().saturating_sub(1);
    let mut body = f.body.clone();
    if matches!(body.last(), Some(Statement::Return { value: None })) {
        body.cull(last..);
    }
    if returns(&body) {
        return false;
    }
    let ep_fn = &module.entry_points[ep].function;
    let mut new = ep_fn.clone();
    let mut maps = Maps::default();
    for (l, local) in f.local_variables.iter() {
        maps.locals.push(
            new.local_variables
                .append(local.clone(), f.local_variables.get_span(l)),
        );
    }
    for (h, e) in f.expressions.iter() {
        let Some(mapped) = maps.expression(e) else {
            return false;
        };
        maps.exprs
            .push(new.expressions.append(mapped, f.expressions.get_span(h)));
    }
    // Local initializers point into the expressions just copied.
    for (l, local) in f.local_variables.iter() {
        if let Some(init) = local.init {
            new.local_variables.get_mut(maps.locals[l.index()]).init =
                Some(maps.exprs[init.index()]);
        }
    }
    for (h, name) in f.named_expressions.iter() {
        new.named_expressions
            .insert(maps.exprs[h.index()], name.clone());
    }
    let Some(inlined) = maps.block(&body) else {
        return false;
    };
    let mut out = naga::Block::with_capacity(ep_fn.body.len() + inlined.len());
    for (k, (s, span)) in ep_fn.body.span_iter().enumerate() {
        if k == at {
            for (s, span) in inlined.span_iter() {
                out.push(s.clone(), *span);
            }
        } else {
            out.push(s.clone(), *span);
        }
    }
    new.body = out;
    module.entry_points[ep].function = new;
    true
}

/// How many `Call` statements of the module call `f`.
fn call_count(module: &Module, f: Handle<Function>) -> usize {
    fn count(b: &naga::Block, f: Handle<Function>) -> usize {
        b.iter()
            .map(|s| match s {
                Statement::Call { function, .. } => usize::from(*function == f),
                Statement::Block(b) => count(b, f),
                Statement::If { accept, reject, .. } => count(accept, f) + count(reject, f),
                Statement::Switch { cases, .. } => cases.iter().map(|c| count(&c.body, f)).sum(),
                Statement::Loop {
                    body, continuing, ..
                } => count(body, f) + count(continuing, f),
                _ => 0,
            })
            .sum()
    }
    module
        .functions
        .iter()
        .map(|(_, g)| count(&g.body, f))
        .chain(
            module
                .entry_points
                .iter()
                .map(|e| count(&e.function.body, f)),
        )
        .sum()
}

/// Whether a block returns anywhere.
fn returns(b: &naga::Block) -> bool {
    b.iter().any(|s| match s {
        Statement::Return { .. } => true,
        Statement::Block(b) => returns(b),
        Statement::If { accept, reject, .. } => returns(accept) || returns(reject),
        Statement::Switch { cases, .. } => cases.iter().any(|c| returns(&c.body)),
        Statement::Loop {
            body, continuing, ..
        } => returns(body) || returns(continuing),
        _ => false,
    })
}

/// Makes each private variable only this entry point uses one of its locals.
fn privates_to_locals(module: &mut Module, ep: usize) -> bool {
    let mut elsewhere: HashSet<Handle<GlobalVariable>> = HashSet::new();
    for (_, f) in module.functions.iter() {
        elsewhere.extend(globals_of(f));
    }
    for (k, e) in module.entry_points.iter().enumerate() {
        if k != ep {
            elsewhere.extend(globals_of(&e.function));
        }
    }
    let here = globals_of(&module.entry_points[ep].function);
    let mut moved: Vec<Handle<GlobalVariable>> = here
        .into_iter()
        .filter(|g| {
            !elsewhere.contains(g)
                && module.global_variables[*g].space == naga::AddressSpace::Private
        })
        .collect();
    moved.sort();
    if moved.is_empty() {
        return false;
    }
    let globals = module.global_variables.clone();
    let global_expressions = module.global_expressions.clone();
    let f = &mut module.entry_points[ep].function;
    for g in moved {
        let var = &globals[g];
        let init = var.init.map(|i| copy_constant(&global_expressions, i, f));
        let local = f.local_variables.append(
            naga::LocalVariable {
                name: var.name.clone(),
                ty: var.ty,
                init,
            },
            globals.get_span(g),
        );
        for (_, e) in f.expressions.iter_mut() {
            if *e == Expression::GlobalVariable(g) {
                *e = Expression::LocalVariable(local);
            }
        }
    }
    true
}

/// The globals a function names.
fn globals_of(f: &Function) -> HashSet<Handle<GlobalVariable>> {
    f.expressions
        .iter()
        .filter_map(|(_, e)| match *e {
            Expression::GlobalVariable(g) => Some(g),
            _ => None,
        })
        .collect()
}

/// A constant expression of the module, copied into the function.
fn copy_constant(
    from: &naga::Arena<Expression>,
    h: Handle<Expression>,
    f: &mut Function,
) -> Handle<Expression> {
    let e = match from[h].clone() {
        Expression::Compose { ty, components } => Expression::Compose {
            ty,
            components: components
                .into_iter()
                .map(|c| copy_constant(from, c, f))
                .collect(),
        },
        Expression::Splat { size, value } => Expression::Splat {
            size,
            value: copy_constant(from, value, f),
        },
        other => other,
    };
    f.expressions.append(e, from.get_span(h))
}
