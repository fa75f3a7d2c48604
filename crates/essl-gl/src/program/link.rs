//! Linking: the essl front end links and lowers the attached shaders to a [`ProgramLayout`],
//! an optional filter rewrites it, and the layout is installed as the program's
//! [`LinkedProgram`]; `use_program` makes it current.

use essl::program::ProgramLayout;

use super::interface::{outputs, shader_inputs};
use super::shader::compile;
use super::LinkedProgram;
use crate::context::ProgramFilter;
use crate::context::{Context, MAX_TEXTURE_UNITS};
use crate::gl;
use crate::objects::Program;
use crate::shader_patch::{output_needs_widening, wrap_entry_point};

/// Why a link failed; its text is the program's info log.
#[derive(Debug, thiserror::Error)]
pub(crate) enum LinkError {
    /// `linkProgram` without both shaders.
    #[error("a vertex and a fragment shader must be attached")]
    MissingShader,
    /// `linkProgram` with a shader whose last compile failed (or that was never compiled).
    #[error("an attached shader is not compiled")]
    NotCompiled,
    /// The front end refused to link the shaders: its WebGL-style log.
    #[error("{0}")]
    Front(String),
    /// The front end could not lower the linked program.
    #[error(transparent)]
    Lower(#[from] essl::lower::LowerError),
    /// The program filter ([`Context::set_program_filter`]) refused the layout.
    #[error("{0}")]
    Filter(String),
    /// More sampler slots than the device binds.
    #[error("{0} samplers: more than the device supports")]
    TooManySamplers(usize),
    /// An attribute at a location past `MAX_VERTEX_ATTRIBS`.
    #[error("attribute location {0} ≥ MAX_VERTEX_ATTRIBS")]
    AttributeLocation(u32),
    /// More uniform blocks than the device binds.
    #[error("{0} uniform blocks: more than the device supports")]
    TooManyBlocks(usize),
    /// A uniform block larger than the device's largest uniform binding.
    #[error("uniform block {name} of {size} bytes is too large")]
    BlockTooLarge {
        /// The block's name.
        name: String,
        /// Its size in bytes.
        size: u32,
    },
    /// A default uniform block larger than the device's largest uniform binding.
    #[error("default uniform block of {0} bytes is too large")]
    DefaultBlockTooLarge(u32),
    /// The transform feedback varyings do not fit (ES 3.0's link errors for them).
    #[error("{0}")]
    Feedback(String),
    /// wgpu's validation refused the lowered modules.
    #[error("the lowered shaders were rejected by wgpu: {0}")]
    Rejected(String),
}

/// The linker's settings and counter: the serial that tells links apart (it keys pipelines
/// and uniform locations), the step between lowering and installing
/// ([`Context::set_program_filter`]) and the WebGL version shaders are compiled for
/// ([`Context::set_shader_target`]).
#[derive(Default)]
pub(crate) struct Linker {
    serial: u64,
    pub(crate) filter: Option<ProgramFilter>,
    /// How shaders are compiled: the WebGL version and the WebGL 1 extensions turned on.
    pub(crate) shaders: essl::CompileOptions,
}

impl Linker {
    /// A serial no earlier link of the context had.
    fn next_serial(&mut self) -> u64 {
        self.serial += 1;
        self.serial
    }
}

impl Context {
    /// Links the attached shaders (`linkProgram`): the essl front end links them as WebGL2
    /// does and lowers them to a [`ProgramLayout`], which
    /// [`Context::link_program_from_layout`] installs. Failures set `LINK_STATUS` false with
    /// the reason in [`Context::get_program_info_log`].
    pub fn link_program(&mut self, program: Program) {
        let Some(p) = self.program_id(program, "linkProgram") else {
            return;
        };
        if self
            .feedback_object()
            .session
            .is_some_and(|s| s.program == p)
        {
            return self.error(
                gl::INVALID_OPERATION,
                "linkProgram",
                "the program is in use by active transform feedback",
            );
        }
        let obj = self.objects.programs.get_any(p).expect("live");
        let shader = |ty: u32| {
            obj.attached
                .iter()
                .filter_map(|&s| self.objects.shaders.get_any(s))
                .find(|s| s.ty == ty)
        };
        let mut sources = None;
        let result = match (shader(gl::VERTEX_SHADER), shader(gl::FRAGMENT_SHADER)) {
            (None, _) | (_, None) => Err(LinkError::MissingShader),
            (Some(vs), Some(fs)) => match (&vs.compiled, &fs.compiled) {
                (Some((v, true)), Some((f, true))) => {
                    sources = Some(Box::new(crate::validation::LinkedSources {
                        vertex: (vs.name.clone(), v.clone()),
                        fragment: (fs.name.clone(), f.clone()),
                        options: self.linker.shaders.clone(),
                    }));
                    let v = &compile(&self.linker.shaders, essl::Stage::Vertex, v);
                    let f = &compile(&self.linker.shaders, essl::Stage::Fragment, f);
                    let linked = essl::link::link_with_bindings(v, f, &obj.attrib_bindings);
                    let mut options = crate::LOWER_OPTIONS;
                    options.transform_feedback = obj.feedback_varyings.0.clone();
                    if linked.ok {
                        essl::lower::lower_program(v, f, &linked, &options)
                            .map_err(LinkError::from)
                            .and_then(|layout| match &mut self.linker.filter {
                                Some(filter) => filter(layout).map_err(LinkError::Filter),
                                None => Ok(layout),
                            })
                    } else {
                        Err(LinkError::Front(linked.log))
                    }
                }
                _ => Err(LinkError::NotCompiled),
            },
        };
        match result {
            Ok(layout) => {
                self.link_program_from_layout(program, layout);
                if let Some(linked) = self.objects.linked_mut(p) {
                    linked.sources = sources;
                }
            }
            Err(e) => {
                let obj = self.objects.programs.get_any_mut(p).expect("live");
                obj.link_status = false;
                obj.validate_status = false;
                obj.info_log = e.to_string();
            }
        }
    }

    pub(crate) fn link(
        &mut self,
        layout: ProgramLayout,
        (names, mode): &(Vec<String>, u32),
    ) -> Result<LinkedProgram, LinkError> {
        let feedback = super::feedback::feedback_layout(&layout, names, *mode)?;
        let limits = &self.gpu.limits;
        if layout.samplers.len() as u32
            > limits
                .max_sampled_textures_per_shader_stage
                .min(MAX_TEXTURE_UNITS)
        {
            return Err(LinkError::TooManySamplers(layout.samplers.len()));
        }
        let inputs = shader_inputs(&layout.vertex);
        if let Some(i) = inputs
            .iter()
            .find(|i| i.location >= self.limits.max_vertex_attribs)
        {
            return Err(LinkError::AttributeLocation(i.location));
        }
        if layout.blocks.len() as u32 + 1 > limits.max_uniform_buffers_per_shader_stage {
            return Err(LinkError::TooManyBlocks(layout.blocks.len()));
        }
        if let Some(b) = layout
            .blocks
            .iter()
            .find(|b| b.size as u64 > limits.max_uniform_buffer_binding_size)
        {
            return Err(LinkError::BlockTooLarge {
                name: b.name.clone(),
                size: b.size,
            });
        }
        if let Some(block) = &layout.uniform_block {
            if block.size > limits.max_uniform_buffer_binding_size as u32 {
                return Err(LinkError::DefaultBlockTooLarge(block.size));
            }
        }
        let device = &self.gpu.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let vertex_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("essl-gl vertex"),
            source: wgpu::ShaderSource::Naga(std::borrow::Cow::Owned(layout.vertex.clone())),
        });
        // An RGBA target needs a vec4 output: widen a narrower one (alpha 1).
        let fragment = if output_needs_widening(&layout.fragment) {
            wrap_entry_point(&layout.fragment, &[], true)
        } else {
            layout.fragment.clone()
        };
        let fragment_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("essl-gl fragment"),
            source: wgpu::ShaderSource::Naga(std::borrow::Cow::Owned(fragment)),
        });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(LinkError::Rejected(e.to_string()));
        }
        let serial = self.linker.next_serial();
        let size = layout.uniform_block.as_ref().map_or(0, |b| b.size as usize);
        Ok(LinkedProgram {
            serial,
            outputs: outputs(&layout.fragment),
            inputs,
            uniform_data: vec![0; size],
            uniform_version: 0,
            sampler_units: vec![0; layout.samplers.len()],
            block_bindings: vec![0; layout.blocks.len()],
            uploaded: None,
            sources: None,
            checks: None,
            feedback,
            vertex_module,
            fragment_module,
            layout,
        })
    }

    /// The program in use (`getParameter(CURRENT_PROGRAM)`).
    pub fn get_current_program(&self) -> Option<Program> {
        self.bindings
            .program()
            .map(|id| Program { ctx: self.id, id })
    }

    /// Makes a linked program current (`useProgram`); `None` for none. A program whose last
    /// link failed → `INVALID_OPERATION`.
    pub fn use_program(&mut self, program: Option<Program>) {
        const F: &str = "useProgram";
        if self.capturing().is_some() {
            return self.error(gl::INVALID_OPERATION, F, "transform feedback is active");
        }
        let id = match program {
            None => None,
            Some(p) => {
                if !self.owns(p.ctx, F) {
                    return;
                }
                // Unlike most program functions, useProgram refuses a program marked for
                // deletion (Chromium's ValidateNullableWebGLObject).
                if !self.objects.programs.is_live(p.id) {
                    return self.error(gl::INVALID_OPERATION, F, "attempt to use a deleted object");
                }
                if !self
                    .objects
                    .programs
                    .get(p.id)
                    .is_some_and(|p| p.link_status)
                {
                    return self.error(gl::INVALID_OPERATION, F, "program is not linked");
                }
                Some(p.id)
            }
        };
        self.bindings.use_program(id, &mut self.objects);
    }
}
