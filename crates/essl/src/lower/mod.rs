//! Lowering a checked shader (or a linked program) to naga IR.
//!
//! The lowered module follows the conventions in [`crate::program`]: an entry point `main`
//! wraps the shader's own `main` (called as a function) and copies inputs, outputs and
//! built-ins between the pipeline and private variables; loose uniforms live in one std140
//! uniform buffer; each sampler is a texture plus a sampler binding. Only what the entry
//! point uses is lowered: unused functions, uniforms, samplers, inputs and outputs are left
//! out, so nothing is compiled or bound that the shader does not need.

mod builtin;
mod func;
pub mod layout;

use std::collections::HashMap;

use naga::{Handle, Span as NSpan};
use thiserror::Error;

use crate::builtins::BuiltinVar;
use crate::hir::{self, GlobalId, GlobalKind};
use crate::link;
use crate::program::{self, InternalUniform, LowerOptions, ProgramLayout};
use crate::reflect::PathStep;
use crate::source::Span;
use crate::types::{ScalarKind, StructDef, Type};
use crate::{Shader, Stage};
use layout::{Repr, Types};

/// Why lowering failed: a construct essl cannot express in naga IR (a limitation of essl,
/// not an error in the shader), or naga's validator rejecting what essl produced (a bug).
#[derive(Debug, Error, Clone, PartialEq, Eq)]
pub enum LowerError {
    /// A valid construct essl does not lower yet.
    #[error("not supported by essl's lowering yet: {message}")]
    Unsupported {
        /// What.
        message: String,
        /// Where in the source.
        span: Span,
    },
    /// naga's validator rejected the lowered module (a bug in essl).
    #[error("naga rejected the lowered {stage} shader: {message}")]
    Invalid {
        /// The stage.
        stage: &'static str,
        /// naga's message.
        message: String,
        /// Where in the source, if naga said.
        span: Span,
    },
}

impl LowerError {
    /// Where in the source the problem is.
    pub fn span(&self) -> Span {
        match self {
            LowerError::Unsupported { span, .. } | LowerError::Invalid { span, .. } => *span,
        }
    }
}

pub(crate) fn unsupported(message: impl Into<String>, span: Span) -> LowerError {
    LowerError::Unsupported {
        message: message.into(),
        span,
    }
}

/// A member of the program's default uniform block.
#[derive(Clone, Debug)]
struct BlockMember {
    name: String,
    offset: u32,
}

/// What one stage's lowering needs to know about the program.
#[derive(Clone, Debug, Default)]
struct StagePlan {
    /// Inputs to declare (used ones): global → first location.
    inputs: Vec<(GlobalId, u32)>,
    /// Outputs to declare: global → first location. Outputs not listed are written to
    /// private variables only (a varying the fragment shader does not read).
    outputs: Vec<(GlobalId, u32)>,
    /// Default-block members this stage reads: global → index in `block_members`.
    uniforms: Vec<(GlobalId, usize)>,
    /// Sampler slots: (global, path to the sampler) → slot.
    samplers: Vec<(GlobalId, Vec<PathStep>, u32)>,
    /// Uniform blocks: block index → binding in group 0.
    blocks: Vec<(usize, u32)>,
    /// Whether each varying output is sampled at the centroid: the fragment shader's
    /// `centroid` decides for both ends (GLSL ES 3.00 lets the stages differ; the GPU APIs
    /// want the two ends of a varying to agree). Outputs not listed follow their own
    /// declaration.
    output_centroid: HashMap<GlobalId, bool>,
}

/// The program-wide part of the plan.
#[derive(Clone, Debug, Default)]
struct ProgramPlan {
    block_members: Vec<BlockMember>,
    block_size: u32,
    internal: Vec<(InternalUniform, u32)>,
}

/// How the lowering reaches a HIR global.
#[derive(Clone, Debug)]
pub(crate) enum GlobalLower {
    /// Not lowered (unused, or a constant folded away).
    None,
    /// A private variable (plain globals, inputs, outputs).
    Private(Handle<naga::GlobalVariable>),
    /// A member of the default uniform block.
    Uniform {
        block: Handle<naga::GlobalVariable>,
        member: u32,
        repr: Repr,
    },
    /// A member of a uniform block without instance name.
    BlockMember {
        block: Handle<naga::GlobalVariable>,
        member: u32,
        repr: Repr,
    },
}

/// The texture and sampler globals of one sampler slot.
pub(crate) type TextureAndSampler = (Handle<naga::GlobalVariable>, Handle<naga::GlobalVariable>);

/// Module-level lowering state shared by function lowering.
pub(crate) struct ModuleCx<'a> {
    pub hir: &'a hir::Module,
    pub module: naga::Module,
    pub types: Types<'a>,
    pub globals: Vec<GlobalLower>,
    pub builtins: HashMap<BuiltinVar, Handle<naga::GlobalVariable>>,
    pub functions: Vec<Option<Handle<naga::Function>>>,
    /// Uniform blocks with instance names: (global, per-member reprs).
    pub blocks: Vec<Option<(Handle<naga::GlobalVariable>, Vec<Repr>)>>,
    /// Sampler slots: (global, path) → (texture, sampler).
    pub samplers: HashMap<(GlobalId, Vec<PathStep>), TextureAndSampler>,
    pub stage: Stage,
    pub options: LowerOptions,
    /// The default uniform block global and the framebuffer-height member, for gl_FragCoord.
    pub fb_height: Option<(Handle<naga::GlobalVariable>, u32)>,
}

fn nspan(s: Span) -> NSpan {
    s.into()
}

impl ModuleCx<'_> {
    pub(crate) fn private(
        &mut self,
        name: &str,
        ty: Handle<naga::Type>,
        init: Option<Handle<naga::Expression>>,
    ) -> Handle<naga::GlobalVariable> {
        self.module.global_variables.append(
            naga::GlobalVariable {
                name: Some(name.to_string()),
                space: naga::AddressSpace::Private,
                binding: None,
                ty,
                init,
                memory_decorations: Default::default(),
            },
            NSpan::UNDEFINED,
        )
    }
}

/// Lowers one compiled shader on its own (validation and reflection of a single stage):
/// inputs and outputs get locations in declaration order, uniforms a block of their own.
pub fn lower_shader(
    shader: &Shader,
    options: &LowerOptions,
) -> Result<(naga::Module, naga::valid::ModuleInfo), LowerError> {
    let m = &shader.module;
    let mut plan = StagePlan {
        inputs: assign_locations(m, GlobalKind::Input)
            .into_iter()
            .filter(|(g, _)| m.globals[*g].used)
            .collect(),
        outputs: assign_locations(m, GlobalKind::Output),
        ..StagePlan::default()
    };
    let mut pplan = ProgramPlan::default();
    let mut offset = 0u32;
    let mut slot = 0u32;
    for (gi, g) in m.globals.iter().enumerate() {
        if g.kind != GlobalKind::Uniform || !g.used {
            continue;
        }
        if layout::has_data(&g.ty, &m.structs) {
            let (size, align) = layout::std140(&g.ty, &m.structs);
            offset = offset.div_ceil(align) * align;
            plan.uniforms.push((gi, pplan.block_members.len()));
            pplan.block_members.push(BlockMember {
                name: g.name.to_string(),
                offset,
            });
            offset += size;
        }
        for path in sampler_paths(&g.ty, &m.structs) {
            plan.samplers.push((gi, path, slot));
            slot += 1;
        }
    }
    if options.flip_frag_coord_y
        && shader.stage == Stage::Fragment
        && m.used_builtins.contains(&BuiltinVar::FragCoord)
    {
        offset = offset.div_ceil(4) * 4;
        pplan
            .internal
            .push((InternalUniform::FramebufferHeight, offset));
        offset += 4;
    }
    pplan.block_size = offset.div_ceil(16) * 16;
    for (bi, b) in m.blocks.iter().enumerate() {
        if b.used {
            plan.blocks.push((bi, 1 + bi as u32));
        }
    }
    let module = lower_stage(m, &plan, &pplan, options)?;
    let info = validate(&module, shader.stage)?;
    Ok((module, info))
}

/// Locations for a shader's inputs or outputs on its own: explicit ones first (unless they
/// collide), then the lowest free run for the others, in declaration order — the linker's
/// rule, without its errors (aliasing is a link error, not a compile error).
fn assign_locations(m: &hir::Module, kind: GlobalKind) -> Vec<(GlobalId, u32)> {
    let vars: Vec<(GlobalId, u32, Option<u32>)> = m
        .globals
        .iter()
        .enumerate()
        .filter(|(_, g)| g.kind == kind)
        .map(|(i, g)| (i, link::location_count(&g.ty, &m.structs), g.location))
        .collect();
    let mut taken = vec![false; 256];
    let mut out = Vec::new();
    let free = |taken: &[bool], s: u32, n: u32| {
        (s..s + n).all(|l| !taken.get(l as usize).copied().unwrap_or(true))
    };
    for &(g, n, loc) in &vars {
        if let Some(l) = loc {
            if free(&taken, l, n) {
                (l..l + n).for_each(|x| taken[x as usize] = true);
                out.push((g, l));
            }
        }
    }
    for &(g, n, _) in &vars {
        if out.iter().any(|(x, _)| *x == g) {
            continue;
        }
        if let Some(s) = (0..200u32).find(|&s| free(&taken, s, n)) {
            (s..s + n).for_each(|x| taken[x as usize] = true);
            out.push((g, s));
        }
    }
    out
}

/// Paths to every sampler inside a value of type `ty` (an array of samplers: each element).
pub fn sampler_paths(ty: &Type, structs: &[StructDef]) -> Vec<Vec<PathStep>> {
    let mut out = Vec::new();
    fn walk(
        ty: &Type,
        structs: &[StructDef],
        path: &mut Vec<PathStep>,
        out: &mut Vec<Vec<PathStep>>,
    ) {
        match ty {
            Type::Sampler(_) => out.push(path.clone()),
            Type::Array(el, n) if el.contains_sampler(structs) => {
                for i in 0..*n {
                    path.push(PathStep::Index(i));
                    walk(el, structs, path, out);
                    path.pop();
                }
            }
            Type::Struct(id) => {
                for (i, m) in structs[id.0 as usize].members.iter().enumerate() {
                    path.push(PathStep::Member(i as u32));
                    walk(&m.ty, structs, path, out);
                    path.pop();
                }
            }
            _ => {}
        }
    }
    walk(ty, structs, &mut Vec::new(), &mut out);
    out
}

fn sampler_type_at(
    ty: &Type,
    path: &[PathStep],
    structs: &[StructDef],
) -> Option<crate::types::SamplerType> {
    let mut t = ty.clone();
    for step in path {
        t = match (step, &t) {
            (PathStep::Index(_), Type::Array(el, _)) => (**el).clone(),
            (PathStep::Member(i), Type::Struct(id)) => {
                structs[id.0 as usize].members[*i as usize].ty.clone()
            }
            _ => return None,
        };
    }
    match t {
        Type::Sampler(s) => Some(s),
        _ => None,
    }
}

/// Validates a lowered module the way wgpu will.
fn validate(module: &naga::Module, stage: Stage) -> Result<naga::valid::ModuleInfo, LowerError> {
    let mut v = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::default(),
    );
    v.validate(module).map_err(|e| {
        let span = e
            .spans()
            .next()
            .map(|(s, _)| Span::from(*s))
            .unwrap_or_default();
        let mut message = e.as_inner().to_string();
        let mut source: Option<&dyn std::error::Error> = std::error::Error::source(e.as_inner());
        while let Some(s) = source {
            message.push_str(": ");
            message.push_str(&s.to_string());
            source = s.source();
        }
        LowerError::Invalid {
            stage: stage.as_str(),
            message,
            span,
        }
    })
}

/// Lowers a linked program for a GPU API: both stages share one default uniform block and one
/// set of sampler slots; varyings and attributes get the linker's locations.
pub fn lower_program(
    vs: &Shader,
    fs: &Shader,
    program: &link::Program,
    options: &LowerOptions,
) -> Result<ProgramLayout, LowerError> {
    crate::shader::with_stack(|| lower_program_here(vs, fs, program, options))
}

fn lower_program_here(
    vs: &Shader,
    fs: &Shader,
    program: &link::Program,
    options: &LowerOptions,
) -> Result<ProgramLayout, LowerError> {
    let (vm, fm) = (&vs.module, &fs.module);
    let mut pplan = ProgramPlan::default();
    let mut vplan = StagePlan::default();
    let mut fplan = StagePlan::default();
    // Default block: the data of active uniforms, in active-list order of their variables.
    let mut offset = 0u32;
    let mut member_of: HashMap<String, usize> = HashMap::new();
    let mut slots: Vec<program::SamplerSlot> = Vec::new();
    let mut uniforms_out: Vec<program::ActiveUniform> = Vec::new();
    let mut offsets: Vec<(usize, u32)> = Vec::new(); // (member index, offset) by member
    for u in &program.uniforms {
        for (stage_src, module, plan) in
            [(&u.vertex, vm, &mut vplan), (&u.fragment, fm, &mut fplan)]
        {
            let Some(crate::reflect::UniformSource::Default { global, .. }) = stage_src else {
                continue;
            };
            let g = &module.globals[*global];
            if !layout::has_data(&g.ty, &module.structs) {
                continue;
            }
            let name = g.name.to_string();
            let idx = match member_of.get(&name) {
                Some(&i) => i,
                None => {
                    let (size, align) = layout::std140(&g.ty, &module.structs);
                    offset = offset.div_ceil(align) * align;
                    let i = pplan.block_members.len();
                    pplan.block_members.push(BlockMember {
                        name: name.clone(),
                        offset,
                    });
                    offsets.push((i, offset));
                    offset += size;
                    member_of.insert(name, i);
                    i
                }
            };
            if g.used && !plan.uniforms.iter().any(|(x, _)| x == global) {
                plan.uniforms.push((*global, idx));
            }
        }
    }
    let frag_coord = fm.used_builtins.contains(&BuiltinVar::FragCoord);
    if options.flip_frag_coord_y && frag_coord {
        offset = offset.div_ceil(4) * 4;
        pplan
            .internal
            .push((InternalUniform::FramebufferHeight, offset));
        offset += 4;
    }
    pplan.block_size = offset.div_ceil(16) * 16;
    // Active uniforms with their storage.
    for u in &program.uniforms {
        let src = u
            .vertex
            .as_ref()
            .map(|s| (s, vm))
            .or(u.fragment.as_ref().map(|s| (s, fm)));
        let Some((crate::reflect::UniformSource::Default { global, path }, module)) = src else {
            if let Some((crate::reflect::UniformSource::Block { .. }, _)) = src {
                uniforms_out.push(program::ActiveUniform {
                    name: u.name.clone(),
                    ty: u.ty,
                    size: u.size,
                    storage: program::UniformStorage::Block,
                });
            }
            continue;
        };
        let g = &module.globals[*global];
        if u.ty.is_sampler() {
            let first = slots.len() as u32;
            for i in 0..u.size {
                let mut p = path.clone();
                if matches!(u.ty.to_type(), Type::Sampler(_))
                    && (u.size > 1 || leaf_is_array(&g.ty, path, &module.structs))
                {
                    p.push(PathStep::Index(i));
                }
                let st = sampler_type_at(&g.ty, &p, &module.structs).expect("sampler path");
                let slot = slots.len() as u32;
                let name = if u.size > 1 || leaf_is_array(&g.ty, path, &module.structs) {
                    format!("{}[{i}]", u.name.trim_end_matches("[0]"))
                } else {
                    u.name.clone()
                };
                slots.push(program::SamplerSlot {
                    name,
                    ty: u.ty,
                    comparison: st.shadow,
                });
                for (stage_src, plan) in [(&u.vertex, &mut vplan), (&u.fragment, &mut fplan)] {
                    if let Some(crate::reflect::UniformSource::Default { global, .. }) = stage_src {
                        plan.samplers.push((*global, p.clone(), slot));
                    }
                }
            }
            uniforms_out.push(program::ActiveUniform {
                name: u.name.clone(),
                ty: u.ty,
                size: u.size,
                storage: program::UniformStorage::Sampler { first_slot: first },
            });
            continue;
        }
        let member = member_of[&*g.name];
        let base = pplan.block_members[member].offset;
        let (leaf_offset, array_stride, matrix_stride) =
            layout::leaf_layout(&g.ty, path, &module.structs);
        uniforms_out.push(program::ActiveUniform {
            name: u.name.clone(),
            ty: u.ty,
            size: u.size,
            storage: program::UniformStorage::Buffer {
                offset: base + leaf_offset,
                array_stride,
                matrix_stride,
            },
        });
    }
    // Samplers of a used uniform that a stage uses but whose leaf is inactive cannot happen:
    // activity is per variable.
    // Attributes and varyings.
    for &(gi, loc) in &program.attribute_locations {
        if vm.globals[gi].used {
            vplan.inputs.push((gi, loc));
        }
    }
    for v in &program.varyings {
        vplan.outputs.push((v.vertex, v.location));
        vplan
            .output_centroid
            .insert(v.vertex, fm.globals[v.fragment].centroid);
        if fm.globals[v.fragment].used {
            fplan.inputs.push((v.fragment, v.location));
        }
    }
    fplan.outputs = program.fragment_outputs.clone();
    // Uniform blocks: vertex ones first, then fragment-only ones, by name.
    let mut block_names: Vec<String> = Vec::new();
    let mut blocks_out = Vec::new();
    for (module, plan) in [(vm, &mut vplan), (fm, &mut fplan)] {
        for (bi, b) in module.blocks.iter().enumerate() {
            let pos = match block_names.iter().position(|n| *n == *b.name) {
                Some(p) => p,
                None => {
                    block_names.push(b.name.to_string());
                    let size = b.members.iter().fold(0u32, |off, (_, ty, _, _)| {
                        let (s, a) = layout::std140(ty, &module.structs);
                        off.div_ceil(a) * a + s
                    });
                    blocks_out.push(program::UniformBlockBinding {
                        name: b.name.to_string(),
                        size: size.div_ceil(16) * 16,
                    });
                    block_names.len() - 1
                }
            };
            if b.used {
                plan.blocks.push((bi, 1 + pos as u32));
            }
        }
    }
    let vertex = lower_stage(vm, &vplan, &pplan, options)?;
    let fragment = lower_stage(fm, &fplan, &pplan, options)?;
    let vertex_info = validate(&vertex, Stage::Vertex)?;
    let fragment_info = validate(&fragment, Stage::Fragment)?;
    let _ = offsets;
    Ok(ProgramLayout {
        vertex,
        vertex_info,
        fragment,
        fragment_info,
        uniform_block: (pplan.block_size > 0).then(|| program::UniformBlock {
            size: pplan.block_size,
            internal: pplan.internal.clone(),
        }),
        uniforms: uniforms_out,
        attributes: program
            .attributes
            .iter()
            .map(|a| program::ActiveAttribute {
                name: a.name.clone(),
                ty: a.ty,
                size: a.size,
                location: a.location.max(0) as u32,
            })
            .collect(),
        samplers: slots,
        blocks: blocks_out,
        fragment_outputs: program
            .fragment_outputs
            .iter()
            .filter_map(|(g, loc)| Some((*loc, fm.globals[*g].ty.gl_type()?)))
            .collect(),
    })
}

/// Whether the leaf at `path` is an array (of basic types or samplers).
fn leaf_is_array(ty: &Type, path: &[PathStep], structs: &[StructDef]) -> bool {
    let mut t = ty.clone();
    for step in path {
        t = match (step, &t) {
            (PathStep::Index(_), Type::Array(el, _)) => (**el).clone(),
            (PathStep::Member(i), Type::Struct(id)) => {
                structs[id.0 as usize].members[*i as usize].ty.clone()
            }
            _ => return false,
        };
    }
    t.is_array()
}

/// Builds the naga module of one stage.
fn lower_stage(
    m: &hir::Module,
    plan: &StagePlan,
    pplan: &ProgramPlan,
    options: &LowerOptions,
) -> Result<naga::Module, LowerError> {
    let mut cx = ModuleCx {
        hir: m,
        module: naga::Module::default(),
        types: Types::new(&m.structs),
        globals: vec![GlobalLower::None; m.globals.len()],
        builtins: HashMap::new(),
        functions: vec![None; m.functions.len()],
        blocks: vec![None; m.blocks.len()],
        samplers: HashMap::new(),
        stage: m.stage,
        options: options.clone(),
        fb_height: None,
    };
    // The default uniform block: only the members this stage reads, at the program's offsets.
    let mut members = Vec::new();
    let mut member_index: HashMap<GlobalId, (u32, Repr)> = HashMap::new();
    let mut plan_uniforms = plan.uniforms.clone();
    plan_uniforms.sort_by_key(|(_, i)| pplan.block_members[*i].offset);
    for (gi, idx) in &plan_uniforms {
        let g = &m.globals[*gi];
        let (ty, repr) = cx.types.storage(&mut cx.module, &g.ty);
        member_index.insert(*gi, (members.len() as u32, repr));
        members.push(naga::StructMember {
            name: Some(pplan.block_members[*idx].name.clone()),
            ty,
            binding: None,
            offset: pplan.block_members[*idx].offset,
        });
    }
    let wants_height = m.stage == Stage::Fragment
        && options.flip_frag_coord_y
        && m.used_builtins.contains(&BuiltinVar::FragCoord);
    let mut height_member = None;
    if wants_height {
        if let Some((_, off)) = pplan
            .internal
            .iter()
            .find(|(k, _)| *k == InternalUniform::FramebufferHeight)
        {
            let f32_ty = cx.types.logical(&mut cx.module, &Type::FLOAT);
            height_member = Some(members.len() as u32);
            members.push(naga::StructMember {
                name: Some("_essl_framebuffer_height".into()),
                ty: f32_ty,
                binding: None,
                offset: *off,
            });
        }
    }
    if !members.is_empty() {
        let ty = cx.module.types.insert(
            naga::Type {
                name: Some("_essl_DefaultUniforms".into()),
                inner: naga::TypeInner::Struct {
                    members,
                    span: pplan.block_size.max(16),
                },
            },
            NSpan::UNDEFINED,
        );
        let block = cx.module.global_variables.append(
            naga::GlobalVariable {
                name: Some("_essl_uniforms".into()),
                space: naga::AddressSpace::Uniform,
                binding: Some(naga::ResourceBinding {
                    group: 0,
                    binding: 0,
                }),
                ty,
                init: None,
                memory_decorations: Default::default(),
            },
            NSpan::UNDEFINED,
        );
        for (gi, (idx, repr)) in member_index {
            cx.globals[gi] = GlobalLower::Uniform {
                block,
                member: idx,
                repr,
            };
        }
        if let Some(hm) = height_member {
            cx.fb_height = Some((block, hm));
        }
    }
    // Uniform blocks.
    for &(bi, binding) in &plan.blocks {
        let b = &m.blocks[bi];
        let mut members = Vec::new();
        let mut reprs = Vec::new();
        let mut off: u32 = 0;
        for (name, ty, _, _) in &b.members {
            let (h, r) = cx.types.storage(&mut cx.module, ty);
            let (s, a) = layout::std140(ty, &m.structs);
            off = off.div_ceil(a) * a;
            members.push(naga::StructMember {
                name: Some(name.to_string()),
                ty: h,
                binding: None,
                offset: off,
            });
            reprs.push(r);
            off += s;
        }
        let span = off.div_ceil(16).max(1) * 16;
        if b.array.is_some() {
            return Err(unsupported("arrays of uniform blocks", b.span));
        }
        let ty = cx.module.types.insert(
            naga::Type {
                name: Some(b.name.to_string()),
                inner: naga::TypeInner::Struct { members, span },
            },
            NSpan::UNDEFINED,
        );
        let gv = cx.module.global_variables.append(
            naga::GlobalVariable {
                name: Some(b.name.to_string()),
                space: naga::AddressSpace::Uniform,
                binding: Some(naga::ResourceBinding { group: 0, binding }),
                ty,
                init: None,
                memory_decorations: Default::default(),
            },
            NSpan::UNDEFINED,
        );
        if b.instance.is_some() {
            cx.blocks[bi] = Some((gv, reprs));
        } else {
            for (gi, g) in m.globals.iter().enumerate() {
                if let GlobalKind::BlockMember(b2, mi) = g.kind {
                    if b2 == bi {
                        cx.globals[gi] = GlobalLower::BlockMember {
                            block: gv,
                            member: mi as u32,
                            repr: reprs[mi].clone(),
                        };
                    }
                }
            }
        }
    }
    // Samplers.
    for (gi, path, slot) in &plan.samplers {
        let g = &m.globals[*gi];
        let Some(st) = sampler_type_at(&g.ty, path, &m.structs) else {
            continue;
        };
        let (img_ty, smp_ty) = sampler_types(&mut cx.module, st);
        let name = format!("{}{}", g.name, path_suffix(path, &g.ty, &m.structs));
        let tex = cx.module.global_variables.append(
            naga::GlobalVariable {
                name: Some(name.clone()),
                space: naga::AddressSpace::Handle,
                binding: Some(naga::ResourceBinding {
                    group: 1,
                    binding: 2 * slot,
                }),
                ty: img_ty,
                init: None,
                memory_decorations: Default::default(),
            },
            NSpan::UNDEFINED,
        );
        let smp = cx.module.global_variables.append(
            naga::GlobalVariable {
                name: Some(format!("{name}_sampler")),
                space: naga::AddressSpace::Handle,
                binding: Some(naga::ResourceBinding {
                    group: 1,
                    binding: 2 * slot + 1,
                }),
                ty: smp_ty,
                init: None,
                memory_decorations: Default::default(),
            },
            NSpan::UNDEFINED,
        );
        cx.samplers.insert((*gi, path.clone()), (tex, smp));
    }
    // Private variables: plain globals, inputs, outputs.
    for (gi, g) in m.globals.iter().enumerate() {
        let needed = match g.kind {
            GlobalKind::Private => g.used,
            GlobalKind::Input => plan.inputs.iter().any(|(x, _)| *x == gi),
            GlobalKind::Output => true,
            _ => false,
        };
        if !needed {
            continue;
        }
        let ty = cx.types.logical(&mut cx.module, &g.ty);
        let init = match &g.init {
            Some(hir::Init::Const(c)) if func::all_finite(c) => {
                Some(func::global_constant(&mut cx, c, &g.ty))
            }
            _ => None,
        };
        let h = cx.private(&g.name, ty, init);
        cx.globals[gi] = GlobalLower::Private(h);
    }
    // Built-in variables as private variables.
    for &b in &m.used_builtins {
        if b == BuiltinVar::DepthRange {
            continue;
        }
        let ty = cx.types.logical(&mut cx.module, &b.ty());
        let h = cx.private(b.name(), ty, None);
        cx.builtins.insert(b, h);
    }
    if m.stage == Stage::Vertex && !cx.builtins.contains_key(&BuiltinVar::Position) {
        let ty = cx.types.logical(&mut cx.module, &BuiltinVar::Position.ty());
        let h = cx.private("gl_Position", ty, None);
        cx.builtins.insert(BuiltinVar::Position, h);
    }
    // Functions, callees first.
    let Some(entry) = m.entry else {
        return Err(unsupported("a shader without `main`", Span::default()));
    };
    let mut order = Vec::new();
    let mut seen = vec![false; m.functions.len()];
    fn visit(f: usize, m: &hir::Module, seen: &mut [bool], order: &mut Vec<usize>) {
        if seen[f] {
            return;
        }
        seen[f] = true;
        for &c in &m.functions[f].calls {
            visit(c, m, seen, order);
        }
        order.push(f);
    }
    visit(entry, m, &mut seen, &mut order);
    for f in order {
        let lowered = func::lower_function(&mut cx, f)?;
        let h = cx
            .module
            .functions
            .append(lowered, nspan(m.functions[f].span));
        cx.functions[f] = Some(h);
    }
    let main = cx.functions[entry].expect("main lowered");
    let entry_fn = func::entry_point(&mut cx, main, plan)?;
    cx.module.entry_points.push(naga::EntryPoint {
        name: "main".into(),
        stage: match m.stage {
            Stage::Vertex => naga::ShaderStage::Vertex,
            Stage::Fragment => naga::ShaderStage::Fragment,
        },
        early_depth_test: None,
        workgroup_size: [0; 3],
        workgroup_size_overrides: None,
        function: entry_fn,
        mesh_info: None,
        task_payload: None,
        incoming_ray_payload: None,
    });
    Ok(cx.module)
}

fn path_suffix(path: &[PathStep], ty: &Type, structs: &[StructDef]) -> String {
    let mut s = String::new();
    let mut t = ty.clone();
    for step in path {
        match (step, &t) {
            (PathStep::Index(i), Type::Array(el, _)) => {
                s.push_str(&format!("[{i}]"));
                t = (**el).clone();
            }
            (PathStep::Member(i), Type::Struct(id)) => {
                let mm = &structs[id.0 as usize].members[*i as usize];
                s.push('.');
                s.push_str(&mm.name);
                t = mm.ty.clone();
            }
            _ => break,
        }
    }
    s
}

/// naga's image and sampler types for a GLSL sampler type.
pub(crate) fn sampler_types(
    m: &mut naga::Module,
    st: crate::types::SamplerType,
) -> (Handle<naga::Type>, Handle<naga::Type>) {
    use crate::types::SamplerDim;
    let (dim, arrayed) = match st.dim {
        SamplerDim::D2 => (naga::ImageDimension::D2, false),
        SamplerDim::D3 => (naga::ImageDimension::D3, false),
        SamplerDim::Cube => (naga::ImageDimension::Cube, false),
        SamplerDim::D2Array => (naga::ImageDimension::D2, true),
    };
    let class = if st.shadow {
        naga::ImageClass::Depth { multi: false }
    } else {
        naga::ImageClass::Sampled {
            kind: match st.kind {
                ScalarKind::Int => naga::ScalarKind::Sint,
                ScalarKind::Uint => naga::ScalarKind::Uint,
                _ => naga::ScalarKind::Float,
            },
            multi: false,
        }
    };
    let img = m.types.insert(
        naga::Type {
            name: None,
            inner: naga::TypeInner::Image {
                dim,
                arrayed,
                class,
            },
        },
        NSpan::UNDEFINED,
    );
    let smp = m.types.insert(
        naga::Type {
            name: None,
            inner: naga::TypeInner::Sampler {
                comparison: st.shadow,
            },
        },
        NSpan::UNDEFINED,
    );
    (img, smp)
}
