//! Lowering a checked shader (or a linked program) to naga IR.
//!
//! The lowered module follows the conventions in [`crate::program`]: an entry point `main`
//! wraps the shader's own `main` (called as a function) and copies inputs, outputs and
//! built-ins between the pipeline and private variables; loose uniforms live in one std140
//! uniform buffer; each sampler is a texture plus a sampler binding. Only what the entry
//! point uses is lowered: unused functions, uniforms, samplers, inputs and outputs are left
//! out, so nothing is compiled or bound that the shader does not need.

//!
//! The work is done in steps, each in its module: `plan` decides what each stage declares
//! and where (for a shader on its own or a linked program), `stage` builds a stage's module
//! from its plan, `func` lowers function bodies and the entry point, `builtin` the built-in
//! functions, and [`layout`] maps GLSL types to naga types and std140 layouts. This module
//! holds the entry points, the error type and the state the steps share.
//!
//! The lowering reads a shader through its checked module (`AsRef<hir::Module>`, which
//! [`crate::Shader`] implements), so it does not depend on how a shader is compiled.

mod builtin;
mod func;
pub mod layout;
mod plan;
mod stage;
mod typed;

use rustc_hash::FxHashMap as HashMap;

use naga::{Handle, Span as NSpan};
use thiserror::Error;

use crate::builtins::BuiltinVar;
use crate::hir::{self, GlobalId};
use crate::link;
use crate::program::{self, InternalUniform, LowerOptions, ProgramLayout};
use crate::reflect::PathStep;
use crate::source::Span;
use crate::Stage;
use layout::{Repr, Types};
pub use plan::sampler_paths;
use plan::ProgramPlanner;
pub(crate) use stage::sampler_types;
pub use typed::{FunctionTypes, Lowered};

/// Why lowering failed: a construct essl cannot express in naga IR (a limitation of essl,
/// not an error in the shader), or naga's validator rejecting what essl produced (a bug).
#[derive(Debug, Error, Clone, PartialEq, Eq)]
#[non_exhaustive]
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
    /// The lowering met what the checker rejects (an [`crate::hir::ExprKind::Error`]): a
    /// shader with errors was handed to it, which is a bug in the caller or in essl.
    #[error("internal error: {message}")]
    Internal {
        /// What.
        message: String,
        /// Where in the source.
        span: Span,
    },
}

impl LowerError {
    /// Where in the source the problem is.
    pub fn span(&self) -> Span {
        match self {
            LowerError::Unsupported { span, .. }
            | LowerError::Invalid { span, .. }
            | LowerError::Internal { span, .. } => *span,
        }
    }
}

/// A uniform block's lowering: one global per element (one for a block that is no array) and
/// the stored form of each member.
pub(crate) type BlockLower = (Vec<Handle<naga::GlobalVariable>>, Vec<Repr>);

pub(crate) fn unsupported(message: impl Into<String>, span: Span) -> LowerError {
    LowerError::Unsupported {
        message: message.into(),
        span,
    }
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
    pub blocks: Vec<Option<BlockLower>>,
    /// Sampler slots: (global, path) → (texture, sampler).
    pub samplers: HashMap<(GlobalId, Vec<PathStep>), TextureAndSampler>,
    pub stage: Stage,
    pub options: LowerOptions,
    /// The values the renderer provides that this stage reads: the default uniform block
    /// global and the member holding each.
    pub internal: HashMap<InternalUniform, (Handle<naga::GlobalVariable>, u32)>,
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
                name: Some(name.to_owned()),
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
/// `shader` is anything holding a checked module, as [`crate::Shader`] does.
pub fn lower_shader<S: AsRef<hir::Module> + ?Sized>(
    shader: &S,
    options: &LowerOptions,
) -> Result<(naga::Module, naga::valid::ModuleInfo), LowerError> {
    let m = shader.as_ref();
    let (plan, pplan) = plan::shader_plan(m, options);
    let module = stage::lower_stage(m, &plan, &pplan, options)?;
    let info = validate(&module, m.stage)?;
    Ok((module, info))
}

/// [`lower_shader`] without validation: the module typed by naga's typifier, for tools that
/// read it without translating it ([`Lowered::typified`]).
pub fn lower_shader_typed<S: AsRef<hir::Module> + ?Sized>(
    shader: &S,
    options: &LowerOptions,
) -> Result<Lowered, LowerError> {
    let m = shader.as_ref();
    let (plan, pplan) = plan::shader_plan(m, options);
    let module = stage::lower_stage(m, &plan, &pplan, options)?;
    Lowered::typified(module, m.stage)
}

/// The naga capabilities lowered modules use and are validated with: naga's defaults (what
/// wgpu grants every device) and clip distances (`gl_ClipDistance`, wgpu's `CLIP_DISTANCES`).
/// Tools that validate lowered or rewritten modules again take the same set.
pub fn capabilities() -> naga::valid::Capabilities {
    naga::valid::Capabilities::default() | naga::valid::Capabilities::CLIP_DISTANCES
}

/// A validator with wgpu's flags and [`capabilities`].
fn validator() -> naga::valid::Validator {
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities())
}

thread_local! {
    /// Each thread's validator: `validate` resets it but keeps the capacity of its tables, so a
    /// thread that validates many modules allocates them once (about 0.8 % of `essl lint`'s
    /// instructions on dEQP).
    static VALIDATOR: std::cell::RefCell<naga::valid::Validator> =
        std::cell::RefCell::new(validator());
}

/// Validates a lowered module the way wgpu will.
fn validate(module: &naga::Module, stage: Stage) -> Result<naga::valid::ModuleInfo, LowerError> {
    VALIDATOR.with(|v| {
        match v.try_borrow_mut() {
            Ok(mut v) => v.validate(module),
            Err(_) => validator().validate(module), // not reached: validation does not re-enter
        }
        .map_err(|e| invalid(&e, stage))
    })
}

/// A validation error as a [`LowerError`]: naga's message with its causes, at its first span.
fn invalid(e: &naga::WithSpan<naga::valid::ValidationError>, stage: Stage) -> LowerError {
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
}

/// Lowers a linked program for a GPU API: both stages share one default uniform block and one
/// set of sampler slots; varyings and attributes get the linker's locations. `vs` and `fs` are
/// anything holding a checked module, as [`crate::Shader`] does.
pub fn lower_program<S: AsRef<hir::Module> + ?Sized>(
    vs: &S,
    fs: &S,
    program: &link::Program,
    options: &LowerOptions,
) -> Result<ProgramLayout, LowerError> {
    crate::stack::with_stack(|| lower_program_here(vs.as_ref(), fs.as_ref(), program, options))
}

fn lower_program_here(
    vm: &hir::Module,
    fm: &hir::Module,
    program: &link::Program,
    options: &LowerOptions,
) -> Result<ProgramLayout, LowerError> {
    let planner = ProgramPlanner::plan(vm, fm, program, options);
    let vertex = stage::lower_stage(vm, &planner.vplan, &planner.pplan, options)?;
    let fragment = stage::lower_stage(fm, &planner.fplan, &planner.pplan, options)?;
    let vertex_info = validate(&vertex, Stage::Vertex)?;
    let fragment_info = validate(&fragment, Stage::Fragment)?;
    let pplan = &planner.pplan;
    Ok(ProgramLayout {
        vertex,
        vertex_info,
        fragment,
        fragment_info,
        uniform_block: (pplan.block_size > 0).then(|| program::UniformBlock {
            size: pplan.block_size,
            internal: pplan.internal.clone(),
        }),
        uniforms: planner.uniforms,
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
        samplers: planner.slots,
        blocks: planner.blocks,
        fragment_outputs: program
            .fragment_outputs
            .iter()
            .filter_map(|(g, loc)| Some((*loc, fm.globals[*g].ty.gl_type()?)))
            .collect(),
        fragment_output_names: program
            .fragment_outputs
            .iter()
            .map(|(g, loc)| {
                let glob = &fm.globals[*g];
                let size = match &glob.ty {
                    crate::types::Type::Array(_, n) => *n,
                    _ => 1,
                };
                (glob.name.as_str().to_owned(), *loc, size)
            })
            .collect(),
        captured: pplan.captured.clone(),
    })
}
