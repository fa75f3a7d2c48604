//! A fragment module without its `gl_FragDepth` output, for draws into a framebuffer that has
//! no depth attachment: GL drops the depth a shader writes there, wgpu refuses a pipeline
//! whose fragment stage writes depth without a depth target.

use naga::{Binding, Block, BuiltIn, Expression, Module, Statement, Type, TypeInner};

/// `module` with its entry point's `FragDepth` output removed; `None` when it has none, or
/// returns its outputs other than as one composed value.
pub(crate) fn without_frag_depth(module: &Module) -> Option<Module> {
    let mut m = module.clone();
    let ep = m
        .entry_points
        .iter_mut()
        .find(|e| e.stage == naga::ShaderStage::Fragment)?;
    let result = ep.function.result.as_ref()?;
    let TypeInner::Struct { members, span } = &m.types[result.ty].inner else {
        return None;
    };
    let depth = members
        .iter()
        .position(|mb| matches!(mb.binding, Some(Binding::BuiltIn(BuiltIn::FragDepth))))?;
    let (mut kept, span) = (members.clone(), *span);
    kept.remove(depth);
    let name = m.types[result.ty].name.clone();
    let new_ty = (!kept.is_empty()).then(|| {
        let inner = TypeInner::Struct {
            members: kept,
            span,
        };
        m.types.insert(Type { name, inner }, naga::Span::UNDEFINED)
    });
    let f = &mut ep.function;
    if !drop_component(&mut f.body, &mut f.expressions, depth, new_ty) {
        return None;
    }
    f.result = new_ty.map(|ty| naga::FunctionResult { ty, binding: None });
    Some(m)
}

/// Rewrites every `return` of `block` (and of the blocks inside it) to leave out component
/// `index` of the value it composes, as type `ty` (`None`: return nothing). False when a
/// `return` does not compose its value.
fn drop_component(
    block: &mut Block,
    exprs: &mut naga::Arena<Expression>,
    index: usize,
    ty: Option<naga::Handle<Type>>,
) -> bool {
    let mut ok = true;
    for s in block.iter_mut() {
        ok &= match s {
            Statement::Return { value } => match value.map(|v| (v, &mut exprs[v])) {
                Some((_, Expression::Compose { ty: t, components }))
                    if index < components.len() =>
                {
                    // With no output left the value stays as it was, unused.
                    match ty {
                        Some(ty) => {
                            components.remove(index);
                            *t = ty;
                        }
                        None => *value = None,
                    }
                    true
                }
                _ => false,
            },
            Statement::Block(b) => drop_component(b, exprs, index, ty),
            Statement::If { accept, reject, .. } => {
                drop_component(accept, exprs, index, ty) & drop_component(reject, exprs, index, ty)
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                drop_component(body, exprs, index, ty)
                    & drop_component(continuing, exprs, index, ty)
            }
            Statement::Switch { cases, .. } => cases
                .iter_mut()
                .all(|c| drop_component(&mut c.body, exprs, index, ty)),
            _ => true,
        };
    }
    ok
}
