//! A program's two stages as one module, as WebGPU code usually keeps a pipeline's shaders:
//! one file, both entry points (`vs_main`, `fs_main`), the structs written once.
//!
//! The fragment stage's types, constants, globals, functions and entry point are copied into
//! the vertex stage's module. What both declare is declared once: equal types (naga's type
//! arena makes them one), the globals of one binding (a uniform block, a texture, a sampler:
//! the program's layout gives each slot one binding), and functions that are the same in
//! both. The loose uniforms, which each stage lowers as a struct of only the members it
//! reads, become one struct of every member at its offset — the program's uniform buffer as
//! the binding map describes it; each stage's member indices are mapped to it.

use naga::valid::ModuleInfo;
use naga::{AddressSpace, Expression, Handle, Module, TypeInner};

use super::{import_global_expressions, import_types, Maps, ModuleMaps};

/// The names of the two entry points.
pub(crate) const ENTRY_POINTS: [&str; 2] = ["vs_main", "fs_main"];

/// Which stage each function of the merged module came from (0 vertex, 1 fragment).
pub(crate) struct Merged {
    pub module: Module,
    pub info: ModuleInfo,
    pub function_files: Vec<usize>,
}

/// The two stages as one validated module; `None` when the copy meets what it does not
/// handle or the result does not validate.
pub(crate) fn merge(vertex: &Module, fragment: &Module) -> Option<Merged> {
    let mut out = vertex.clone();
    let types = import_types(fragment, &mut out);
    let mut maps = Maps {
        module: Some(ModuleMaps {
            types,
            ..ModuleMaps::default()
        }),
        ..Maps::default()
    };
    import_global_expressions(fragment, &mut out, &mut maps)?;
    // The loose uniforms: one struct of both stages' members.
    let buffer = |m: &Module| {
        m.global_variables.iter().find_map(|(h, g)| {
            (g.space == AddressSpace::Uniform && g.name.as_deref() == Some("_essl_uniforms"))
                .then_some(h)
        })
    };
    let (vertex_buffer, fragment_buffer) = (buffer(vertex), buffer(fragment));
    let mut fragment_members = Vec::new();
    if let (Some(vb), Some(fb)) = (vertex_buffer, fragment_buffer) {
        let fragment_ty = maps.ty(fragment.global_variables[fb].ty);
        let vertex_ty = out.global_variables[vb].ty;
        let (merged, vertex_members, f_members) = union(&mut out, vertex_ty, fragment_ty)?;
        out.global_variables.get_mut(vb).ty = merged;
        for (_, f) in out.functions.iter_mut() {
            remap_members(f, vb, &vertex_members);
        }
        for ep in out.entry_points.iter_mut() {
            remap_members(&mut ep.function, vb, &vertex_members);
        }
        fragment_members = f_members;
    }
    // Globals: one per binding.
    let mut globals = Vec::with_capacity(fragment.global_variables.len());
    for (h, g) in fragment.global_variables.iter() {
        let ty = maps.ty(g.ty);
        let same = out.global_variables.iter().find_map(|(oh, og)| {
            (g.binding.is_some()
                && og.binding == g.binding
                && (og.ty == ty || Some(h) == fragment_buffer))
                .then_some(oh)
        });
        let new = match same {
            Some(oh) => oh,
            None => {
                let init = g.init.map(|i| maps.exprs[i.index()]);
                out.global_variables.append(
                    naga::GlobalVariable {
                        name: g.name.clone(),
                        space: g.space,
                        binding: g.binding,
                        ty,
                        init,
                        memory_decorations: g.memory_decorations,
                    },
                    fragment.global_variables.get_span(h),
                )
            }
        };
        globals.push(new);
    }
    // The fragment stage's accesses, once copied, are into the merged buffer's global.
    let merged_buffer = fragment_buffer.map(|fb| globals[fb.index()]);
    maps.module.as_mut()?.globals = globals;
    // Functions: one of each. A function calls only functions before it in the arena, so
    // the map is complete for each one as it is copied.
    let mut function_files = vec![0; out.functions.len()];
    maps.module.as_mut()?.functions = Vec::new();
    for (h, f) in fragment.functions.iter() {
        let mut copy = maps.function_from(f)?;
        if let Some(b) = merged_buffer {
            remap_members(&mut copy, b, &fragment_members);
        }
        let key = shape_of(&copy);
        let same = out
            .functions
            .iter()
            .find_map(|(oh, of)| (of.name == copy.name && shape_of(of) == key).then_some(oh));
        let new = match same {
            Some(oh) => oh,
            None => {
                function_files.push(1);
                out.functions.append(copy, fragment.functions.get_span(h))
            }
        };
        maps.module.as_mut()?.functions.push(Some(new));
    }
    for ep in fragment.entry_points.iter() {
        let mut function = maps.function_from(&ep.function)?;
        if let Some(b) = merged_buffer {
            remap_members(&mut function, b, &fragment_members);
        }
        out.entry_points.push(naga::EntryPoint {
            function,
            ..ep.clone()
        });
    }
    for (ep, name) in out.entry_points.iter_mut().zip(ENTRY_POINTS) {
        ep.name = name.to_owned();
    }
    let before: Vec<(Option<String>, naga::Span, usize)> = out
        .functions
        .iter()
        .zip(&function_files)
        .map(|((h, f), file)| (f.name.clone(), out.functions.get_span(h), *file))
        .collect();
    naga::compact::compact(&mut out, naga::compact::KeepUnused::No);
    let info = super::validate(&out)?;
    let function_files = out
        .functions
        .iter()
        .map(|(h, f)| {
            let span = out.functions.get_span(h);
            before
                .iter()
                .find(|(n, s, _)| *n == f.name && *s == span)
                .map_or(0, |(_, _, file)| *file)
        })
        .collect();
    Some(Merged {
        module: out,
        info,
        function_files,
    })
}

/// The struct of both stages' uniform members at their offsets, and each stage's member
/// index → merged index.
fn union(
    out: &mut Module,
    a: Handle<naga::Type>,
    b: Handle<naga::Type>,
) -> Option<(Handle<naga::Type>, Vec<u32>, Vec<u32>)> {
    let (
        TypeInner::Struct {
            members: ma,
            span: sa,
        },
        TypeInner::Struct {
            members: mb,
            span: sb,
        },
    ) = (&out.types[a].inner, &out.types[b].inner)
    else {
        return None;
    };
    let mut all: Vec<naga::StructMember> = ma.clone();
    for m in mb {
        match all.iter().find(|x| x.offset == m.offset) {
            Some(x) if x.name == m.name && x.ty == m.ty => {}
            Some(_) => return None,
            None => all.push(m.clone()),
        }
    }
    all.sort_by_key(|m| m.offset);
    let index = |ms: &[naga::StructMember]| -> Vec<u32> {
        ms.iter()
            .map(|m| all.iter().position(|x| x.offset == m.offset).unwrap_or(0) as u32)
            .collect()
    };
    let (ia, ib) = (index(ma), index(mb));
    let span = (*sa).max(*sb);
    let name = out.types[a].name.clone();
    let merged = out.types.insert(
        naga::Type {
            name,
            inner: TypeInner::Struct { members: all, span },
        },
        naga::Span::UNDEFINED,
    );
    Some((merged, ia, ib))
}

/// In one function: `AccessIndex { base: buffer, index }` gets the merged index.
fn remap_members(f: &mut naga::Function, buffer: Handle<naga::GlobalVariable>, members: &[u32]) {
    let bases: Vec<Handle<Expression>> = f
        .expressions
        .iter()
        .filter_map(|(h, e)| {
            matches!(e, Expression::GlobalVariable(g) if *g == buffer).then_some(h)
        })
        .collect();
    for (_, e) in f.expressions.iter_mut() {
        if let Expression::AccessIndex { base, index } = e {
            if bases.contains(base) {
                *index = members.get(*index as usize).copied().unwrap_or(*index);
            }
        }
    }
}

/// A function without its spans, to compare two.
fn shape_of(f: &naga::Function) -> String {
    fn strip(b: &naga::Block) -> Vec<String> {
        b.iter()
            .map(|s| match s {
                naga::Statement::Block(b) => format!("Block{:?}", strip(b)),
                naga::Statement::If {
                    condition,
                    accept,
                    reject,
                } => format!("If({condition:?}){:?}{:?}", strip(accept), strip(reject)),
                naga::Statement::Switch { selector, cases } => format!(
                    "Switch({selector:?}){:?}",
                    cases
                        .iter()
                        .map(|c| (format!("{:?}{}", c.value, c.fall_through), strip(&c.body)))
                        .collect::<Vec<_>>()
                ),
                naga::Statement::Loop {
                    body,
                    continuing,
                    break_if,
                } => format!("Loop{:?}{:?}{break_if:?}", strip(body), strip(continuing)),
                other => format!("{other:?}"),
            })
            .collect()
    }
    format!(
        "{:?}{:?}{:?}{:?}{:?}{:?}",
        f.arguments,
        f.result,
        f.local_variables,
        f.expressions,
        f.named_expressions,
        strip(&f.body)
    )
}
