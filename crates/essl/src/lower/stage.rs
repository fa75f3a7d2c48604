//! Building one stage's naga module from its plan: the default uniform block, uniform blocks,
//! texture and sampler bindings, private variables for globals and built-ins, the functions
//! `main` calls (callees first) and the entry point that wraps `main`.

use rustc_hash::FxHashMap as HashMap;

use naga::{Handle, Span as NSpan};

use super::func;
use super::layout::{self, Repr, Types};
use super::plan::{sampler_type_at, ProgramPlan, StagePlan};
use super::{nspan, unsupported, GlobalLower, LowerError, ModuleCx};
use crate::builtins::BuiltinVar;
use crate::hir::{self, GlobalId, GlobalKind};
use crate::program::{InternalUniform, LowerOptions};
use crate::reflect::PathStep;
use crate::source::Span;
use crate::types::{SamplerDim, SamplerType, ScalarKind, StructDef, Type};
use crate::Stage;

/// Builds the naga module of one stage.
pub(super) fn lower_stage(
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
        builtins: HashMap::default(),
        functions: vec![None; m.functions.len()],
        blocks: vec![None; m.blocks.len()],
        samplers: HashMap::default(),
        stage: m.stage,
        options: options.clone(),
        internal: HashMap::default(),
    };
    cx.default_uniform_block(plan, pplan);
    cx.uniform_blocks(plan)?;
    cx.sampler_bindings(plan);
    cx.private_globals(plan);
    cx.builtin_privates();
    let Some(entry) = m.entry else {
        return Err(unsupported("a shader without `main`", Span::default()));
    };
    cx.functions_called_from(entry)?;
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

impl ModuleCx<'_> {
    /// The default uniform block: only the members this stage reads, at the program's
    /// offsets, and the framebuffer height when `gl_FragCoord` is flipped.
    fn default_uniform_block(&mut self, plan: &StagePlan, pplan: &ProgramPlan) {
        let m = self.hir;
        let mut members = Vec::new();
        let mut member_index: HashMap<GlobalId, (u32, Repr)> = HashMap::default();
        let mut plan_uniforms = plan.uniforms.clone();
        plan_uniforms.sort_by_key(|(_, i)| pplan.block_members[*i].offset);
        for (gi, idx) in &plan_uniforms {
            let g = &m.globals[*gi];
            let (ty, repr) = self.types.storage(&mut self.module, &g.ty);
            member_index.insert(*gi, (members.len() as u32, repr));
            members.push(naga::StructMember {
                name: Some(pplan.block_members[*idx].name.clone()),
                ty,
                binding: None,
                offset: pplan.block_members[*idx].offset,
            });
        }
        // The plan holds an internal value only where a stage reads it.
        let internal: Vec<(InternalUniform, u32)> = pplan
            .internal
            .iter()
            .filter(|(what, _)| what.stage() == m.stage)
            .map(|&(what, offset)| (what, self.internal_member(&mut members, what, offset)))
            .collect();
        if members.is_empty() {
            return;
        }
        let ty = self.module.types.insert(
            naga::Type {
                name: Some("_essl_DefaultUniforms".into()),
                inner: naga::TypeInner::Struct {
                    members,
                    span: pplan.block_size.max(16),
                },
            },
            NSpan::UNDEFINED,
        );
        let block = self.module.global_variables.append(
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
            self.globals[gi] = GlobalLower::Uniform {
                block,
                member: idx,
                repr,
            };
        }
        self.internal = internal
            .into_iter()
            .map(|(what, member)| (what, (block, member)))
            .collect();
    }

    /// Appends the member of the default block that holds internal value `what` at `offset`;
    /// its index.
    fn internal_member(
        &mut self,
        members: &mut Vec<naga::StructMember>,
        what: InternalUniform,
        offset: u32,
    ) -> u32 {
        let ty = match what {
            InternalUniform::FramebufferHeight => Type::FLOAT,
            InternalUniform::ClipDistancesEnabled => Type::UINT,
            InternalUniform::DrawId => Type::INT,
        };
        let ty = self.types.logical(&mut self.module, &ty);
        members.push(naga::StructMember {
            name: Some(what.member_name().into()),
            ty,
            binding: None,
            offset,
        });
        members.len() as u32 - 1
    }

    /// The uniform blocks the plan binds, each a std140 struct in group 0.
    fn uniform_blocks(&mut self, plan: &StagePlan) -> Result<(), LowerError> {
        let m = self.hir;
        for &(bi, binding) in &plan.blocks {
            let b = &m.blocks[bi];
            let mut members = Vec::new();
            let mut reprs = Vec::new();
            let mut off: u32 = 0;
            for (name, ty, _, _) in &b.members {
                let (h, r) = self.types.storage(&mut self.module, ty);
                let (s, a) = layout::std140(ty, &m.structs);
                off = off.div_ceil(a) * a;
                members.push(naga::StructMember {
                    name: Some(name.as_str().to_owned()),
                    ty: h,
                    binding: None,
                    offset: off,
                });
                reprs.push(r);
                off += s;
            }
            let span = off.div_ceil(16).max(1) * 16;
            let ty = self.module.types.insert(
                naga::Type {
                    name: Some(b.name.as_str().to_owned()),
                    inner: naga::TypeInner::Struct { members, span },
                },
                NSpan::UNDEFINED,
            );
            // An array of blocks is one block, and one binding, per element.
            let elements = b.array.unwrap_or(1);
            let gvs: Vec<_> = (0..elements)
                .map(|k| {
                    let name = match b.array {
                        Some(_) => format!("{}_{k}", b.name),
                        None => b.name.as_str().to_owned(),
                    };
                    self.module.global_variables.append(
                        naga::GlobalVariable {
                            name: Some(name),
                            space: naga::AddressSpace::Uniform,
                            binding: Some(naga::ResourceBinding {
                                group: 0,
                                binding: binding + k,
                            }),
                            ty,
                            init: None,
                            memory_decorations: Default::default(),
                        },
                        NSpan::UNDEFINED,
                    )
                })
                .collect();
            let gv = gvs[0];
            if b.instance.is_some() {
                self.blocks[bi] = Some((gvs, reprs));
            } else {
                for (gi, g) in m.globals.iter().enumerate() {
                    if let GlobalKind::BlockMember(b2, mi) = g.kind {
                        if b2 == bi {
                            self.globals[gi] = GlobalLower::BlockMember {
                                block: gv,
                                member: mi as u32,
                                repr: reprs[mi].clone(),
                            };
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// A texture and a sampler binding in group 1 for each sampler slot of the plan.
    fn sampler_bindings(&mut self, plan: &StagePlan) {
        let m = self.hir;
        for (gi, path, slot) in &plan.samplers {
            let g = &m.globals[*gi];
            let Some(st) = sampler_type_at(&g.ty, path, &m.structs) else {
                continue;
            };
            let (img_ty, smp_ty) =
                sampler_types(&mut self.module, st, self.options.integer_cube_as_array);
            let name = format!("{}{}", g.name, path_suffix(path, &g.ty, &m.structs));
            let tex = self.module.global_variables.append(
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
            let smp = self.module.global_variables.append(
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
            self.samplers.insert((*gi, path.clone()), (tex, smp));
        }
    }

    /// Private variables for plain globals (used ones), planned inputs and all outputs; a
    /// constant initializer becomes the variable's `init` when naga can hold it.
    fn private_globals(&mut self, plan: &StagePlan) {
        let m = self.hir;
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
            let ty = self.types.logical(&mut self.module, &g.ty);
            let init = match &g.init {
                Some(hir::Init::Const(c)) if func::all_finite(c) => {
                    Some(func::global_constant(self, c, &g.ty))
                }
                _ => None,
            };
            let h = self.private(&g.name, ty, init);
            self.globals[gi] = GlobalLower::Private(h);
        }
    }

    /// Private variables for the built-in variables the shader uses (and `gl_Position`, which
    /// a vertex shader always outputs).
    fn builtin_privates(&mut self) {
        let m = self.hir;
        for &b in &m.used_builtins {
            if b == BuiltinVar::DepthRange {
                continue;
            }
            let ty = match b {
                BuiltinVar::FragData => Type::Array(
                    Box::new(Type::Vector(ScalarKind::Float, 4)),
                    m.frag_data_len.max(1),
                ),
                _ => b.ty(),
            };
            let ty = self.types.logical(&mut self.module, &ty);
            let h = self.private(b.name(), ty, None);
            self.builtins.insert(b, h);
        }
        if m.stage == Stage::Vertex && !self.builtins.contains_key(&BuiltinVar::Position) {
            let ty = self
                .types
                .logical(&mut self.module, &BuiltinVar::Position.ty());
            let h = self.private("gl_Position", ty, None);
            self.builtins.insert(BuiltinVar::Position, h);
        }
    }

    /// Lowers `entry` and every function it calls, callees first.
    fn functions_called_from(&mut self, entry: usize) -> Result<(), LowerError> {
        let m = self.hir;
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
            let lowered = func::lower_function(self, f)?;
            let h = self
                .module
                .functions
                .append(lowered, nspan(m.functions[f].span));
            self.functions[f] = Some(h);
        }
        Ok(())
    }
}

/// The GLSL name of the part at `path` of a value of type `ty` (`[2].member`).
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
/// With `cube_as_array`, an integer cube sampler's image is a 2D array
/// ([`LowerOptions::integer_cube_as_array`](crate::program::LowerOptions)).
pub(crate) fn sampler_types(
    m: &mut naga::Module,
    st: SamplerType,
    cube_as_array: bool,
) -> (Handle<naga::Type>, Handle<naga::Type>) {
    let (dim, arrayed) = match st.dim {
        SamplerDim::D2 => (naga::ImageDimension::D2, false),
        SamplerDim::D3 => (naga::ImageDimension::D3, false),
        SamplerDim::Cube if cube_as_array && st.kind != ScalarKind::Float => {
            (naga::ImageDimension::D2, true)
        }
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
