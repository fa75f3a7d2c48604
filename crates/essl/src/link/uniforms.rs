//! Uniforms: those declared in both stages must agree in type and precision (uniform blocks
//! in members, layout and precision); the active list in ANGLE's order.

use crate::diagnostic_code::Code;
use rustc_hash::FxHashMap as HashMap;

use super::{field_names_differ, same_precision, same_type, static_uses, ActiveUniform, Linker};
use crate::hir::{GlobalId, GlobalKind, Module};
use crate::reflect::{self, UniformSource};
use crate::types::{GlType, Precision, Type};
use crate::Stage;

impl Linker<'_> {
    /// Checks the uniforms declared in both stages and lists the active ones: the default
    /// block's in ANGLE's order, then every uniform block member.
    pub(super) fn link_uniforms(&mut self) -> Vec<ActiveUniform> {
        self.check_shared_uniforms();
        let (vm, fm) = (&self.vs.module, &self.fs.module);
        let vr = reflect::reflect(vm);
        let fr = reflect::reflect(fm);
        let mut out = active_default_uniforms(vm, fm, &vr, &fr);
        append_block_uniforms(&mut out, &vr, &fr);
        out
    }

    /// A uniform declared in both stages is one variable: one type, and one precision where
    /// both stages use it.
    fn check_shared_uniforms(&mut self) {
        let (vm, fm) = (&self.vs.module, &self.fs.module);
        let (vuse, fuse) = (static_uses(vm), static_uses(fm));
        for (fi, fg) in fm.globals.iter().enumerate() {
            if fg.kind != GlobalKind::Uniform {
                continue;
            }
            let Some((vi, vg)) = vm
                .globals
                .iter()
                .enumerate()
                .find(|(_, g)| g.kind == GlobalKind::Uniform && g.name == fg.name)
            else {
                continue;
            };
            let name = fg.name.clone();
            if !same_type(&vg.ty, &vm.structs, &fg.ty, &fm.structs) {
                let names = field_names_differ(&vg.ty, &vm.structs, &fg.ty, &fm.structs);
                let (vt, ft) = (
                    vg.ty.display(&vm.structs).to_string(),
                    fg.ty.display(&fm.structs).to_string(),
                );
                let line = if names {
                    format!("Field names of uniform '{name}' differ between VERTEX and FRAGMENT shaders.")
                } else {
                    format!("Types of uniform '{name}' differ between VERTEX and FRAGMENT shaders.")
                };
                let d = self.error(
                    Some(Stage::Fragment),
                    fg.span,
                    Code::UniformTypeMismatch,
                    format!("uniform `{name}` is `{vt}` in the vertex shader but `{ft}` here"),
                    line,
                );
                d.label = "declared differently in the two shaders".into();
                d.notes.push(
                    "a uniform declared in both stages is one variable and must have one type"
                        .into(),
                );
                continue;
            }
            if vuse[vi]
                && fuse[fi]
                && !same_precision(
                    &vg.ty,
                    vg.precision,
                    &vm.structs,
                    &fg.ty,
                    fg.precision,
                    &fm.structs,
                )
            {
                let d = self.error(
                    Some(Stage::Fragment),
                    fg.span,
                    Code::UniformPrecisionMismatch,
                    format!("uniform `{name}` has different precisions in the two shaders"),
                    format!("Precisions of uniform '{name}' differ between VERTEX and FRAGMENT shaders."),
                );
                d.label = format!("{} here", fg.precision.map_or("no precision", |p| p.name()));
                d.notes.push(format!(
                    "the vertex shader declares it {}",
                    vg.precision.map_or("without precision", |p| p.name())
                ));
                d.help = Some("give it the same precision qualifier in both shaders".into());
            }
        }
    }

    /// A uniform block declared in both stages must have the same members, types, layout and
    /// precisions.
    pub(super) fn link_blocks(&mut self) {
        let (vm, fm) = (&self.vs.module, &self.fs.module);
        for fb in &fm.blocks {
            let Some(vb) = vm.blocks.iter().find(|b| b.name == fb.name) else {
                continue;
            };
            let name = fb.name.clone();
            let names_differ = vb.members.len() != fb.members.len()
                || vb.members.iter().zip(&fb.members).any(|(a, b)| a.0 != b.0);
            let types_differ = !names_differ
                && vb
                    .members
                    .iter()
                    .zip(&fb.members)
                    .any(|(a, b)| !same_type(&a.1, &vm.structs, &b.1, &fm.structs));
            let layout_differs = vb.layout != fb.layout
                || vb.members.iter().zip(&fb.members).any(|(a, b)| a.3 != b.3);
            let precision_differs = vb
                .members
                .iter()
                .zip(&fb.members)
                .any(|(a, b)| !same_precision(&a.1, a.2, &vm.structs, &b.1, b.2, &fm.structs));
            let (what, code) = if names_differ {
                ("Field names", Code::BlockMemberMismatch)
            } else if types_differ {
                ("Types", Code::BlockTypeMismatch)
            } else if layout_differs {
                ("Layout qualifiers", Code::BlockLayoutMismatch)
            } else if precision_differs {
                ("Precisions", Code::BlockPrecisionMismatch)
            } else {
                continue;
            };
            let d = self.error(
                Some(Stage::Fragment),
                fb.span,
                code,
                format!("uniform block `{name}` is declared differently in the two shaders"),
                format!(
                    "{what} of uniform block '{name}' differ between VERTEX and FRAGMENT shaders."
                ),
            );
            d.label = format!(
                "{} differ from the vertex shader's `{name}`",
                what.to_lowercase()
            );
        }
    }
}

/// A default-block uniform leaf, with what ANGLE's order sorts it by.
struct Entry {
    leaf: reflect::UniformLeaf,
    vertex: Option<UniformSource>,
    fragment: Option<UniformSource>,
    stage_rank: u8,
    decl: usize,
    class: u8,
    shape: (u8, u8),
    part: u8,
    used: bool,
}

/// ANGLE's classes: 0 non-highp non-aggregates (sorted by shape), 1 non-highp arrays and
/// structs, 2 highp (declaration order).
fn classify(ty: &Type, precision: Option<Precision>) -> u8 {
    let aggregate = matches!(ty, Type::Array(..) | Type::Struct(_));
    let highp = precision == Some(Precision::High) && !matches!(ty, Type::Struct(_));
    if highp {
        2
    } else if aggregate {
        1
    } else {
        0
    }
}

/// A uniform type's shape (columns, rows) for ANGLE's sort: scalars (1, 1), vectors (1, n).
fn shape(t: GlType) -> (u8, u8) {
    match t.to_type() {
        Type::Vector(_, n) => (1, n),
        Type::Matrix { cols, rows } => (cols, rows),
        _ => (1, 1),
    }
}

/// The active uniforms of the default block (used in either stage), in ANGLE's order:
/// non-samplers before samplers, vertex before fragment, then by class, shape and declaration.
fn active_default_uniforms(
    vm: &Module,
    fm: &Module,
    vr: &reflect::Reflection,
    fr: &reflect::Reflection,
) -> Vec<ActiveUniform> {
    let mut entries: Vec<Entry> = Vec::new();
    let mut index: HashMap<String, usize> = HashMap::default();
    for (stage_rank, (module, refl)) in [(vm, vr), (fm, fr)].into_iter().enumerate() {
        let mut decl_order: HashMap<GlobalId, usize> = HashMap::default();
        for (leaf, used) in &refl.uniforms {
            let UniformSource::Default { global, .. } = &leaf.source else {
                continue;
            };
            let n = decl_order.len();
            let decl = *decl_order.entry(*global).or_insert(n);
            if let Some(&i) = index.get(&leaf.name) {
                if stage_rank == 1 {
                    entries[i].fragment = Some(leaf.source.clone());
                }
                entries[i].used |= *used;
                continue;
            }
            let g = &module.globals[*global];
            index.insert(leaf.name.clone(), entries.len());
            entries.push(Entry {
                shape: shape(leaf.ty),
                leaf: leaf.clone(),
                vertex: (stage_rank == 0).then(|| leaf.source.clone()),
                fragment: (stage_rank == 1).then(|| leaf.source.clone()),
                stage_rank: stage_rank as u8,
                decl,
                class: classify(&g.ty, g.precision),
                part: if leaf.ty.is_sampler() { 1 } else { 0 },
                used: *used,
            });
        }
    }
    let mut active: Vec<&Entry> = entries.iter().filter(|e| e.used).collect();
    active.sort_by_key(|e| {
        let shape = if e.class == 0 { e.shape } else { (0, 0) };
        (e.part, e.stage_rank, e.class, shape, e.decl)
    });
    let out: Vec<ActiveUniform> = active
        .into_iter()
        .map(|e| ActiveUniform {
            name: e.leaf.name.clone(),
            ty: e.leaf.ty,
            size: e.leaf.size,
            vertex: e.vertex.clone(),
            fragment: e.fragment.clone(),
        })
        .collect();
    out
}

/// Appends the uniform block members: all of them, vertex blocks first, then fragment-only
/// ones.
fn append_block_uniforms(
    out: &mut Vec<ActiveUniform>,
    vr: &reflect::Reflection,
    fr: &reflect::Reflection,
) {
    let mut seen: HashMap<String, usize> = HashMap::default();
    for (stage_rank, refl) in [vr, fr].into_iter().enumerate() {
        for leaf in &refl.block_uniforms {
            if let Some(&i) = seen.get(&leaf.name) {
                if stage_rank == 1 {
                    out[i].fragment = Some(leaf.source.clone());
                }
                continue;
            }
            seen.insert(leaf.name.clone(), out.len());
            out.push(ActiveUniform {
                name: leaf.name.clone(),
                ty: leaf.ty,
                size: leaf.size,
                vertex: (stage_rank == 0).then(|| leaf.source.clone()),
                fragment: (stage_rank == 1).then(|| leaf.source.clone()),
            });
        }
    }
}
