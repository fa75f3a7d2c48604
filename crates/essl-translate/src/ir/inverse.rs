//! `inverse()` by cofactors, for the targets without one.
//!
//! GLSL ES 3.00 has `inverse(m)`; SPIR-V and desktop GLSL have it too, but WGSL, MSL and
//! HLSL do not, and naga 30's MSL and HLSL writers refuse it (its WGSL writer adds a helper of
//! its own). The helpers are written in WGSL (`inverse.wgsl`: the 3×3 and 4×4 cases by
//! cross products of the columns, which are the cofactors), read by naga's WGSL front end,
//! copied into the module before the functions that call them, and each `inverse(m)` becomes
//! a call of the one for its size. Every target then writes them as it writes any function.

use std::collections::HashMap;

use naga::{Expression, Function, Handle, MathFunction, Module, Statement, TypeInner};

use super::{import_types, Maps, ModuleMaps};

const SOURCE: &str = include_str!("inverse.wgsl");

/// The names of the helpers, by matrix size.
pub(crate) const HELPERS: [&str; 3] = ["inverse2x2", "inverse3x3", "inverse4x4"];

/// Replaces every `inverse()` of the module by a call; whether there was one. `None` when
/// the module holds what the copy does not handle (never for a lowered WebGL shader).
pub(crate) fn lower_inverse(module: &mut Module) -> Option<bool> {
    let info = super::validate(module)?;
    let sizes_of =
        |f: &Function, fi: &naga::valid::FunctionInfo| -> HashMap<Handle<Expression>, usize> {
            f.expressions
                .iter()
                .filter_map(|(h, e)| match *e {
                    Expression::Math {
                        fun: MathFunction::Inverse,
                        arg,
                        ..
                    } => match *fi[arg].ty.inner_with(&module.types) {
                        TypeInner::Matrix { columns, .. } => Some((h, columns as usize)),
                        _ => None,
                    },
                    _ => None,
                })
                .collect()
        };
    let functions: Vec<_> = module
        .functions
        .iter()
        .map(|(h, f)| sizes_of(f, &info[h]))
        .collect();
    let entries: Vec<_> = module
        .entry_points
        .iter()
        .enumerate()
        .map(|(i, e)| sizes_of(&e.function, info.get_entry_point(i)))
        .collect();
    let mut sizes = [false; 3];
    for n in functions.iter().chain(&entries).flat_map(|m| m.values()) {
        sizes[n - 2] = true;
    }
    if !sizes.contains(&true) {
        return Some(false);
    }
    let helpers = naga::front::wgsl::parse_str(SOURCE).ok()?;
    let types = import_types(&helpers, module);
    let wanted: Vec<(usize, Handle<Function>)> = helpers
        .functions
        .iter()
        .filter_map(|(h, f)| {
            let n = HELPERS
                .iter()
                .position(|name| f.name.as_deref() == Some(name))?;
            sizes[n].then_some((n, h))
        })
        .collect();
    let mut maps = Maps {
        module: Some(ModuleMaps {
            types,
            globals: Vec::new(),
            constants: Vec::new(),
            functions: vec![None; helpers.functions.len()],
        }),
        ..Maps::default()
    };
    let mut copies = Vec::new();
    for (n, h) in wanted {
        copies.push((n, maps.function_from(&helpers.functions[h])?));
    }
    let count = copies.len();
    let by_size = prepend(module, copies)?;
    for (i, (_, f)) in module.functions.iter_mut().enumerate().skip(count) {
        replace(f, &functions[i - count], &by_size);
    }
    for (i, ep) in module.entry_points.iter_mut().enumerate() {
        replace(&mut ep.function, &entries[i], &by_size);
    }
    Some(true)
}

/// Puts `helpers` before the module's functions (a function calls only those before it);
/// their handles by matrix size.
fn prepend(
    module: &mut Module,
    helpers: Vec<(usize, Function)>,
) -> Option<[Option<Handle<Function>>; 3]> {
    let old = std::mem::take(&mut module.functions);
    let mut by_size = [None; 3];
    for (n, f) in helpers {
        by_size[n] = Some(module.functions.append(f, naga::Span::UNDEFINED));
    }
    let mut maps = Maps {
        module: Some(ModuleMaps {
            types: module.types.iter().map(|(h, _)| h).collect(),
            globals: module.global_variables.iter().map(|(h, _)| h).collect(),
            constants: module.constants.iter().map(|(h, _)| h).collect(),
            functions: Vec::new(),
        }),
        ..Maps::default()
    };
    for (h, f) in old.iter() {
        let copy = maps.function_from(f)?;
        let new = module.functions.append(copy, old.get_span(h));
        maps.module.as_mut()?.functions.push(Some(new));
    }
    for ep in &mut module.entry_points {
        ep.function = maps.function_from(&ep.function)?;
    }
    Some(by_size)
}

/// Replaces the function's `inverse()`s (with their sizes) by calls, splitting the `Emit`s
/// around them.
fn replace(
    f: &mut Function,
    sizes: &HashMap<Handle<Expression>, usize>,
    by_size: &[Option<Handle<Function>>; 3],
) {
    let mut calls = HashMap::new();
    for (&h, &n) in sizes {
        if let (Some(helper), Expression::Math { arg, .. }) = (by_size[n - 2], &f.expressions[h]) {
            calls.insert(h, (helper, *arg));
        }
    }
    if calls.is_empty() {
        return;
    }
    for (&h, &(helper, _)) in &calls {
        *f.expressions.get_mut(h) = Expression::CallResult(helper);
    }
    let body = std::mem::take(&mut f.body);
    f.body = split(body, &calls);
}

fn split(
    block: naga::Block,
    calls: &HashMap<Handle<Expression>, (Handle<Function>, Handle<Expression>)>,
) -> naga::Block {
    let mut out = naga::Block::new();
    for (s, span) in block.span_into_iter() {
        match s {
            Statement::Emit(range) => {
                let mut start: Option<Handle<Expression>> = None;
                let mut last: Option<Handle<Expression>> = None;
                for h in range.clone() {
                    if let Some(&(function, arg)) = calls.get(&h) {
                        if let (Some(a), Some(b)) = (start, last) {
                            out.push(Statement::Emit(naga::Range::new_from_bounds(a, b)), span);
                        }
                        start = None;
                        last = None;
                        out.push(
                            Statement::Call {
                                function,
                                arguments: vec![arg],
                                result: Some(h),
                            },
                            span,
                        );
                    } else {
                        start = start.or(Some(h));
                        last = Some(h);
                    }
                }
                if let (Some(a), Some(b)) = (start, last) {
                    out.push(Statement::Emit(naga::Range::new_from_bounds(a, b)), span);
                }
            }
            Statement::Block(b) => out.push(Statement::Block(split(b, calls)), span),
            Statement::If {
                condition,
                accept,
                reject,
            } => out.push(
                Statement::If {
                    condition,
                    accept: split(accept, calls),
                    reject: split(reject, calls),
                },
                span,
            ),
            Statement::Switch { selector, cases } => out.push(
                Statement::Switch {
                    selector,
                    cases: cases
                        .into_iter()
                        .map(|c| naga::SwitchCase {
                            body: split(c.body, calls),
                            ..c
                        })
                        .collect(),
                },
                span,
            ),
            Statement::Loop {
                body,
                continuing,
                break_if,
            } => out.push(
                Statement::Loop {
                    body: split(body, calls),
                    continuing: split(continuing, calls),
                    break_if,
                },
                span,
            ),
            other => out.push(other, span),
        }
    }
    out
}
