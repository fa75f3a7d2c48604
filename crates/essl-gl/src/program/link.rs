//! Linking: the essl front end links and lowers the attached shaders to a [`ProgramLayout`],
//! an optional filter rewrites it, and the layout is installed as the program's
//! [`LinkedProgram`]; `use_program` makes it current.

use essl::program::ProgramLayout;

use super::interface::{outputs, shader_inputs};
use super::linker::LinkError;
use super::shader::compile;
use super::LinkedProgram;
use crate::context::{Context, MAX_TEXTURE_UNITS};
use crate::gl;
use crate::objects::Program;
use crate::shader_patch::{output_needs_widening, wrap_entry_point};

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
                    options.clip_control = self.extensions.clip_control;
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
                // WebGL, unlike GL ES, keeps no executable from an earlier link: a current
                // program whose link failed draws nothing and takes no uniforms
                // (INVALID_OPERATION), as in Chromium.
                let obj = self.objects.programs.get_any_mut(p).expect("live");
                obj.linked = None;
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
        let feedback = super::feedback_layout::feedback_layout(&layout, names, *mode)?;
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
