//! Plans: what each stage's lowering declares and where — input and output locations, the
//! members of the default uniform block and their offsets, sampler slots and uniform-block
//! bindings — for a shader on its own or for a linked program (whose two stages share one
//! default block and one set of sampler slots), with the program's reflection built beside.

use rustc_hash::FxHashMap as HashMap;

use crate::builtins::BuiltinVar;
use crate::hir::{self, GlobalId, GlobalKind};
use crate::link;
use crate::link::location_count;
use crate::lower::layout;
use crate::program::{self, CaptureSource, CapturedOutput, InternalUniform, LowerOptions};
use crate::reflect::{PathStep, UniformSource};
use crate::types::{SamplerType, StructDef, Type};
use crate::Stage;

/// A member of the program's default uniform block.
#[derive(Clone, Debug)]
pub(super) struct BlockMember {
    pub(super) name: String,
    pub(super) offset: u32,
}

/// What one stage's lowering needs to know about the program.
#[derive(Clone, Debug, Default)]
pub(crate) struct StagePlan {
    /// Inputs to declare (used ones): global → first location.
    pub(super) inputs: Vec<(GlobalId, u32)>,
    /// Outputs to declare: global → first location. Outputs not listed are written to
    /// private variables only (a varying the fragment shader does not read).
    pub(super) outputs: Vec<(GlobalId, u32)>,
    /// Default-block members this stage reads: global → index in `block_members`.
    pub(super) uniforms: Vec<(GlobalId, usize)>,
    /// Sampler slots: (global, path to the sampler) → slot.
    pub(super) samplers: Vec<(GlobalId, Vec<PathStep>, u32)>,
    /// Uniform blocks: block index → binding in group 0.
    pub(super) blocks: Vec<(usize, u32)>,
    /// Whether each varying output is sampled at the centroid: the fragment shader's
    /// `centroid` decides for both ends (GLSL ES 3.00 lets the stages differ; the GPU APIs
    /// want the two ends of a varying to agree). Outputs not listed follow their own
    /// declaration.
    pub(super) output_centroid: HashMap<GlobalId, bool>,
    /// The first of the two locations of the `vec4` varyings that carry `gl_ClipDistance` to a
    /// fragment shader that reads it (written by the vertex stage, read by the fragment
    /// stage: the GPU APIs' clip distances are vertex outputs only).
    pub(super) clip_varying: Option<u32>,
}

/// The program-wide part of the plan.
#[derive(Clone, Debug, Default)]
pub(super) struct ProgramPlan {
    /// The outputs kept for transform feedback, and where they are.
    pub(super) captured: Vec<CapturedOutput>,
    pub(super) block_members: Vec<BlockMember>,
    pub(super) block_size: u32,
    pub(super) internal: Vec<(InternalUniform, u32)>,
}

/// Which built-in variables the program's stages use that the renderer feeds through the
/// default uniform block.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct InternalUses {
    /// The fragment stage reads `gl_FragCoord`.
    pub(super) frag_coord: bool,
    /// The vertex stage writes `gl_ClipDistance`.
    pub(super) clip_distance: bool,
    /// The vertex stage reads `gl_DrawID`.
    pub(super) draw_id: bool,
}

impl InternalUses {
    /// What a vertex module `vm` and a fragment module `fm` use (either may be absent).
    pub(super) fn of(vm: Option<&hir::Module>, fm: Option<&hir::Module>) -> InternalUses {
        let v = |b| vm.is_some_and(|m| m.used_builtins.contains(&b));
        InternalUses {
            frag_coord: fm.is_some_and(|m| m.used_builtins.contains(&BuiltinVar::FragCoord)),
            clip_distance: v(BuiltinVar::ClipDistance),
            draw_id: v(BuiltinVar::DrawId),
        }
    }
}

impl ProgramPlan {
    /// Reserves after `offset` the values the renderer provides that the stages use: the
    /// framebuffer height when the fragment stage reads `gl_FragCoord` and the options flip
    /// it, the clip-distance switches when the vertex stage writes `gl_ClipDistance` and the
    /// options read them, the draw index when the vertex stage reads `gl_DrawID`; sets the
    /// block's size (whole 16-byte rows).
    fn finish_block(&mut self, mut offset: u32, uses: InternalUses, options: &LowerOptions) {
        let wanted = [
            (
                InternalUniform::FramebufferHeight,
                options.flip_frag_coord_y && uses.frag_coord,
            ),
            (
                InternalUniform::ClipDistancesEnabled,
                options.clip_distance_switches && uses.clip_distance,
            ),
            (InternalUniform::DrawId, uses.draw_id),
        ];
        for (what, _) in wanted.into_iter().filter(|&(_, on)| on) {
            // Each is 4 bytes (an f32, u32 or i32).
            offset = offset.div_ceil(4) * 4;
            self.internal.push((what, offset));
            offset += 4;
        }
        self.block_size = offset.div_ceil(16) * 16;
    }
}

/// The plan of one shader lowered on its own: inputs and outputs get locations in declaration
/// order, uniforms a block of their own.
pub(super) fn shader_plan(m: &hir::Module, options: &LowerOptions) -> (StagePlan, ProgramPlan) {
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
                name: g.name.as_str().to_owned(),
                offset,
            });
            offset += size;
        }
        for path in sampler_paths(&g.ty, &m.structs) {
            plan.samplers.push((gi, path, slot));
            slot += 1;
        }
    }
    let (vm, fm) = match m.stage {
        Stage::Vertex => (Some(m), None),
        Stage::Fragment => (None, Some(m)),
    };
    pplan.finish_block(offset, InternalUses::of(vm, fm), options);
    if m.stage == Stage::Fragment && m.used_builtins.contains(&BuiltinVar::ClipDistance) {
        plan.clip_varying = Some(next_location(m, &plan.inputs));
    }
    let mut binding = 1;
    for (bi, b) in m.blocks.iter().enumerate() {
        if b.used {
            plan.blocks.push((bi, binding));
        }
        binding += b.array.unwrap_or(1);
    }
    (plan, pplan)
}

/// The first location after `vars` (globals of `m` at their first locations).
fn next_location(m: &hir::Module, vars: &[(GlobalId, u32)]) -> u32 {
    vars.iter()
        .map(|&(g, loc)| loc + location_count(&m.globals[g].ty, &m.structs))
        .max()
        .unwrap_or(0)
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

/// The plans of a linked program's two stages, with the reflection the program reports.
pub(super) struct ProgramPlanner<'m> {
    vm: &'m hir::Module,
    fm: &'m hir::Module,
    pub(super) pplan: ProgramPlan,
    pub(super) vplan: StagePlan,
    pub(super) fplan: StagePlan,
    /// Default-block member of each uniform variable, by name.
    member_of: HashMap<String, usize>,
    pub(super) slots: Vec<program::SamplerSlot>,
    pub(super) uniforms: Vec<program::ActiveUniform>,
    pub(super) blocks: Vec<program::UniformBlockBinding>,
}

impl<'m> ProgramPlanner<'m> {
    /// Plans both stages of `program`.
    pub(super) fn plan(
        vm: &'m hir::Module,
        fm: &'m hir::Module,
        program: &link::Program,
        options: &LowerOptions,
    ) -> Self {
        let mut p = ProgramPlanner {
            vm,
            fm,
            pplan: ProgramPlan::default(),
            vplan: StagePlan::default(),
            fplan: StagePlan::default(),
            member_of: HashMap::default(),
            slots: Vec::new(),
            uniforms: Vec::new(),
            blocks: Vec::new(),
        };
        let offset = p.default_block(program);
        let uses = InternalUses::of(Some(vm), Some(fm));
        p.pplan.finish_block(offset, uses, options);
        p.uniform_blocks();
        p.active_uniforms(program);
        // Samplers of a used uniform that a stage uses but whose leaf is inactive cannot
        // happen: activity is per variable.
        p.inputs_and_outputs(program);
        p.captured_outputs(&options.transform_feedback);
        if fm.used_builtins.contains(&BuiltinVar::ClipDistance) {
            let at = next_location(vm, &p.vplan.outputs);
            p.vplan.clip_varying = Some(at);
            p.fplan.clip_varying = Some(at);
        }
        p
    }

    /// Keeps the outputs transform feedback captures, at locations after the linked
    /// varyings when the fragment shader does not read them, and records where each is.
    fn captured_outputs(&mut self, names: &[String]) {
        let vm = self.vm;
        let mut next = next_location(vm, &self.vplan.outputs);
        for name in names {
            let (base, element) = match name.strip_suffix(']').and_then(|n| n.split_once('[')) {
                Some((b, i)) => match i.parse::<u32>() {
                    Ok(i) => (b, Some(i)),
                    Err(_) => continue,
                },
                None => (name.as_str(), None),
            };
            let builtin = match (base, element) {
                ("gl_Position", None) => Some((
                    CaptureSource::Position,
                    Type::Vector(crate::types::ScalarKind::Float, 4),
                )),
                ("gl_PointSize", None) if vm.used_builtins.contains(&BuiltinVar::PointSize) => {
                    Some((CaptureSource::PointSize, Type::FLOAT))
                }
                _ => None,
            };
            if let Some((source, ty)) = builtin {
                if let Some(ty) = ty.gl_type() {
                    self.pplan.captured.push(CapturedOutput {
                        name: name.clone(),
                        ty,
                        size: 1,
                        source,
                    });
                }
                continue;
            }
            let Some(gi) = vm
                .globals
                .iter()
                .position(|g| g.kind == GlobalKind::Output && *g.name == *base)
            else {
                continue;
            };
            let g = &vm.globals[gi];
            let first = match self.vplan.outputs.iter().find(|(o, _)| *o == gi) {
                Some(&(_, loc)) => loc,
                None => {
                    let loc = next;
                    next += location_count(&g.ty, &vm.structs);
                    self.vplan.outputs.push((gi, loc));
                    loc
                }
            };
            let (elem, size) = match &g.ty {
                Type::Array(el, n) => ((**el).clone(), *n),
                t => (t.clone(), 1),
            };
            let per = location_count(&elem, &vm.structs);
            let (first, size) = match element {
                Some(i) if i < size => (first + i * per, 1),
                Some(_) => continue,
                None => (first, size),
            };
            let Some(ty) = elem.gl_type() else { continue };
            self.pplan.captured.push(CapturedOutput {
                name: name.clone(),
                ty,
                size,
                source: CaptureSource::Location {
                    first,
                    count: per * size,
                },
            });
        }
    }

    /// The default block: the data of active uniforms, in active-list order of their
    /// variables (one member per variable, shared by the stages). Returns the end offset.
    fn default_block(&mut self, program: &link::Program) -> u32 {
        let (vm, fm) = (self.vm, self.fm);
        let mut offset = 0u32;
        for u in &program.uniforms {
            for (stage_src, module, plan) in [
                (&u.vertex, vm, &mut self.vplan),
                (&u.fragment, fm, &mut self.fplan),
            ] {
                let Some(UniformSource::Default { global, .. }) = stage_src else {
                    continue;
                };
                let g = &module.globals[*global];
                if !layout::has_data(&g.ty, &module.structs) {
                    continue;
                }
                let name = g.name.as_str().to_owned();
                let idx = match self.member_of.get(&name) {
                    Some(&i) => i,
                    None => {
                        let (size, align) = layout::std140(&g.ty, &module.structs);
                        offset = offset.div_ceil(align) * align;
                        let i = self.pplan.block_members.len();
                        self.pplan.block_members.push(BlockMember {
                            name: name.clone(),
                            offset,
                        });
                        offset += size;
                        self.member_of.insert(name, i);
                        i
                    }
                };
                if g.used && !plan.uniforms.iter().any(|(x, _)| x == global) {
                    plan.uniforms.push((*global, idx));
                }
            }
        }
        offset
    }

    /// The active uniforms with their storage: a block member, sampler slots, or a range of
    /// the default block.
    fn active_uniforms(&mut self, program: &link::Program) {
        let (vm, fm) = (self.vm, self.fm);
        for u in &program.uniforms {
            let src = u
                .vertex
                .as_ref()
                .map(|s| (s, vm))
                .or(u.fragment.as_ref().map(|s| (s, fm)));
            let Some((UniformSource::Default { global, path }, module)) = src else {
                if let Some((
                    UniformSource::Block {
                        block,
                        member,
                        path,
                    },
                    module,
                )) = src
                {
                    let storage = self.block_member_storage(module, *block, *member, path);
                    self.uniforms.push(program::ActiveUniform {
                        name: u.name.clone(),
                        ty: u.ty,
                        size: u.size,
                        storage,
                    });
                }
                continue;
            };
            let g = &module.globals[*global];
            if u.ty.is_sampler() {
                self.sampler_uniform(u, g, path, module);
                continue;
            }
            let member = self.member_of[&*g.name];
            let base = self.pplan.block_members[member].offset;
            let (leaf_offset, array_stride, matrix_stride) =
                layout::leaf_layout(&g.ty, path, &module.structs);
            self.uniforms.push(program::ActiveUniform {
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
    }

    /// A sampler uniform (of global `g`, at `path`): one slot per element, planned in each
    /// stage that declares it.
    fn sampler_uniform(
        &mut self,
        u: &link::ActiveUniform,
        g: &hir::Global,
        path: &[PathStep],
        module: &hir::Module,
    ) {
        let first = self.slots.len() as u32;
        let leaf_array = leaf_is_array(&g.ty, path, &module.structs);
        for i in 0..u.size {
            let mut p = path.to_vec();
            if matches!(u.ty.to_type(), Type::Sampler(_)) && (u.size > 1 || leaf_array) {
                p.push(PathStep::Index(i));
            }
            let st = sampler_type_at(&g.ty, &p, &module.structs).expect("sampler path");
            let slot = self.slots.len() as u32;
            let name = if u.size > 1 || leaf_array {
                format!("{}[{i}]", u.name.trim_end_matches("[0]"))
            } else {
                u.name.clone()
            };
            self.slots.push(program::SamplerSlot {
                name,
                ty: u.ty,
                comparison: st.shadow,
            });
            for (stage_src, plan) in [(&u.vertex, &mut self.vplan), (&u.fragment, &mut self.fplan)]
            {
                if let Some(UniformSource::Default { global, .. }) = stage_src {
                    plan.samplers.push((*global, p.clone(), slot));
                }
            }
        }
        self.uniforms.push(program::ActiveUniform {
            name: u.name.clone(),
            ty: u.ty,
            size: u.size,
            storage: program::UniformStorage::Sampler { first_slot: first },
        });
    }

    /// Attributes and varyings at the linker's locations; the fragment shader's `centroid`
    /// decides for both ends of a varying.
    fn inputs_and_outputs(&mut self, program: &link::Program) {
        let (vm, fm) = (self.vm, self.fm);
        for &(gi, loc) in &program.attribute_locations {
            if vm.globals[gi].used {
                self.vplan.inputs.push((gi, loc));
            }
        }
        for v in &program.varyings {
            self.vplan.outputs.push((v.vertex, v.location));
            self.vplan
                .output_centroid
                .insert(v.vertex, fm.globals[v.fragment].centroid);
            if fm.globals[v.fragment].used {
                self.fplan.inputs.push((v.fragment, v.location));
            }
        }
        self.fplan.outputs = program.fragment_outputs.clone();
    }

    /// Where a leaf of member `member` of block `block` of `module` lies in the block
    /// (std140).
    fn block_member_storage(
        &self,
        module: &hir::Module,
        block: usize,
        member: usize,
        path: &[PathStep],
    ) -> program::UniformStorage {
        let b = &module.blocks[block];
        let mut offset = 0u32;
        for (i, (_, ty, _, _)) in b.members.iter().enumerate() {
            let (size, align) = layout::std140(ty, &module.structs);
            offset = offset.div_ceil(align) * align;
            if i == member {
                break;
            }
            offset += size;
        }
        let (_, ty, _, row_major) = &b.members[member];
        let (leaf, array_stride, matrix_stride) = layout::leaf_layout(ty, path, &module.structs);
        let index = self
            .blocks
            .iter()
            .position(|x| {
                x.name == *b.name
                    || (b.array.is_some()
                        && x.name
                            .strip_prefix(&*b.name)
                            .is_some_and(|r| r.starts_with('[')))
            })
            .unwrap_or(0);
        program::UniformStorage::Block {
            block: index as u32,
            offset: offset + leaf,
            array_stride,
            matrix_stride,
            row_major: *row_major,
        }
    }

    /// Uniform blocks: vertex ones first, then fragment-only ones, by name; an array of blocks
    /// takes one binding per element (`Lights[0]`, `Lights[1]`, as WebGL names them).
    fn uniform_blocks(&mut self) {
        let mut block_names: Vec<String> = Vec::new();
        for (module, plan) in [(self.vm, &mut self.vplan), (self.fm, &mut self.fplan)] {
            for (bi, b) in module.blocks.iter().enumerate() {
                let pos = match block_names.iter().position(|n| *n == *b.name) {
                    Some(p) => p,
                    None => {
                        let size = b.members.iter().fold(0u32, |off, (_, ty, _, _)| {
                            let (s, a) = layout::std140(ty, &module.structs);
                            off.div_ceil(a) * a + s
                        });
                        let first = self.blocks.len();
                        let names: Vec<String> = match b.array {
                            Some(n) => (0..n).map(|k| format!("{}[{k}]", b.name)).collect(),
                            None => vec![b.name.as_str().to_owned()],
                        };
                        for name in names {
                            block_names.push(b.name.as_str().to_owned());
                            self.blocks.push(program::UniformBlockBinding {
                                name,
                                size: size.div_ceil(16) * 16,
                                vertex: false,
                                fragment: false,
                            });
                        }
                        first
                    }
                };
                if b.used {
                    plan.blocks.push((bi, 1 + pos as u32));
                    for binding in &mut self.blocks[pos..pos + b.array.unwrap_or(1) as usize] {
                        if module.stage == Stage::Vertex {
                            binding.vertex = true;
                        } else {
                            binding.fragment = true;
                        }
                    }
                }
            }
        }
    }
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

/// The sampler type at `path` inside a value of type `ty`, if a sampler is there.
pub(crate) fn sampler_type_at(
    ty: &Type,
    path: &[PathStep],
    structs: &[StructDef],
) -> Option<SamplerType> {
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
