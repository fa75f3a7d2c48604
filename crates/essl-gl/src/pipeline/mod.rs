//! Render pipelines, built on demand and cached by everything they depend on: the program,
//! the vertex layout (and the shader patches it needs), the primitive topology, the
//! fixed-function state and the formats of the pass's attachments. Bind group layouts and
//! bind groups are cached here too; [`clear`] holds the pipelines of masked clears.

mod blit;
mod clear;

pub(crate) use blit::{BlitKey, BlitSource, Channels};
pub(crate) use clear::{ClearKey, ClearKind};

use std::borrow::Cow;
use std::collections::HashMap;

use crate::gpu::Gpu;
use crate::program::LinkedProgram;
use crate::shader_patch::{
    capture_outputs, output_needs_widening, with_scissor_discard, without_frag_depth,
    wrap_entry_point, CaptureSpec, InputPatch,
};
use crate::texture::SampleKind;

/// Bind groups kept at most before the caches are emptied.
const MAX_CACHED_BIND_GROUPS: usize = 4096;

/// One vertex buffer slot: one attribute.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct VertexSlot {
    pub(crate) stride: u64,
    pub(crate) step: wgpu::VertexStepMode,
    pub(crate) format: wgpu::VertexFormat,
    pub(crate) offset: u64,
    pub(crate) location: u32,
}

/// How a sampler slot is bound (what the bind group layout says about it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct SlotBinding {
    pub(crate) dim: wgpu::TextureViewDimension,
    pub(crate) kind: SampleKind,
    /// Whether the texture may be filtered (and the sampler may filter).
    pub(crate) filterable: bool,
}

/// Everything a render pipeline depends on.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct PipelineKey {
    pub(crate) program: u64,
    pub(crate) vertex: Vec<VertexSlot>,
    pub(crate) patches: Vec<InputPatch>,
    pub(crate) topology: wgpu::PrimitiveTopology,
    pub(crate) strip_index_format: Option<wgpu::IndexFormat>,
    pub(crate) cull_mode: Option<wgpu::Face>,
    pub(crate) front_face: wgpu::FrontFace,
    pub(crate) depth_write: bool,
    pub(crate) depth_compare: wgpu::CompareFunction,
    /// Constant, slope-scale and clamp (as bits) depth bias.
    pub(crate) depth_bias: (i32, u32, u32),
    /// Depth clamped rather than clipped (`EXT_depth_clamp`).
    pub(crate) unclipped_depth: bool,
    /// Triangles drawn as their edges (`WEBGL_polygon_mode`).
    pub(crate) polygon_line: bool,
    /// Each draw buffer's blend state and write mask, as `targets` lists them.
    pub(crate) blends: Vec<(Option<wgpu::BlendState>, wgpu::ColorWrites)>,
    /// Draw buffers whose image is RGB (stored with a fourth channel), bit `i` for draw
    /// buffer `i`: draws leave their alpha alone (1, as GL reads it).
    pub(crate) rgb_targets: u32,
    pub(crate) slots: Vec<SlotBinding>,
    /// The format of each colour attachment, by draw buffer (`None`: nothing there).
    pub(crate) targets: Vec<Option<wgpu::TextureFormat>>,
    /// The depth/stencil attachment's format.
    pub(crate) depth_format: Option<wgpu::TextureFormat>,
    pub(crate) stencil: wgpu::StencilState,
    pub(crate) samples: u32,
    pub(crate) alpha_to_coverage: bool,
    /// The samples a draw may write (`SAMPLE_COVERAGE`), bit `i` for sample `i`.
    pub(crate) sample_mask: u64,
    /// `EXT_float_blend`: 32-bit float attachments blend.
    pub(crate) float_blend: bool,
    /// What transform feedback captures (the vertex stage writes storage buffers).
    pub(crate) capture: Option<CaptureSpec>,
    /// Whether fragments are made (false: `RASTERIZER_DISCARD` while capturing; the pass
    /// has a placeholder depth target and the pipeline no fragment stage).
    pub(crate) rasterize: bool,
    /// `EXT_clip_control`'s (upper-left origin, zero-to-one depth) for a program whose vertex
    /// stage declares them; (false, false) for another.
    pub(crate) clip_control: (bool, bool),
    /// The scissor box the fragment stage tests itself, where it does (left, top, right,
    /// bottom; `shader_patch::with_scissor_discard`).
    pub(crate) scissor_discard: Option<[u32; 4]>,
}

/// What a group-0 bind group holds: the default block's arena chunk and size, and the
/// uniform blocks' buffer ranges.
type Group0Key = (Option<(u64, u64)>, Vec<(wgpu::Buffer, u64, u64)>);

/// A pipeline and the id draws compare to skip redundant `set_pipeline` calls.
#[derive(Clone)]
pub(crate) struct CachedPipeline {
    pub(crate) id: u64,
    pub(crate) pipeline: wgpu::RenderPipeline,
}

/// Pipelines, layouts and bind groups.
#[derive(Default)]
pub(crate) struct PipelineCache {
    pipelines: HashMap<PipelineKey, Result<CachedPipeline, Rejected>>,
    next_id: u64,
    group0_layouts: HashMap<(bool, usize), wgpu::BindGroupLayout>,
    group1_layouts: HashMap<Vec<SlotBinding>, wgpu::BindGroupLayout>,
    group0_groups: HashMap<Group0Key, wgpu::BindGroup>,
    #[allow(clippy::type_complexity)]
    group1_groups:
        HashMap<(Vec<SlotBinding>, Vec<(wgpu::TextureView, wgpu::Sampler)>), wgpu::BindGroup>,
    #[allow(clippy::type_complexity)]
    modules:
        HashMap<(u64, Vec<InputPatch>, Option<CaptureSpec>), Result<wgpu::ShaderModule, Rejected>>,
    /// Fragment modules patched for a draw: (program, the target has depth, the scissor box
    /// the module tests) → the module.
    #[allow(clippy::type_complexity)]
    fragment_modules: HashMap<(u64, bool, Option<[u32; 4]>), Result<wgpu::ShaderModule, Rejected>>,
    capture_layouts: HashMap<u32, wgpu::BindGroupLayout>,
    clear: HashMap<ClearKey, wgpu::RenderPipeline>,
    blit: HashMap<BlitKey, (wgpu::RenderPipeline, wgpu::BindGroupLayout)>,
    /// Pipelines created (for statistics and tests).
    pub(crate) created: u64,
}

/// Why wgpu refused a shader module or a pipeline: its validation message, kept as text
/// because the cache keeps results and wgpu's error is not `Clone`.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub(crate) enum Rejected {
    /// wgpu's validation refused a shader module.
    #[error("{0}")]
    Module(String),
    /// wgpu's validation refused a pipeline layout or a render pipeline.
    #[error("{0}")]
    Pipeline(String),
}

/// A shader module from a naga module, or wgpu's complaint.
pub(crate) fn create_module(
    gpu: &Gpu,
    module: naga::Module,
    label: &str,
) -> Result<wgpu::ShaderModule, Rejected> {
    let scope = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
    let m = gpu
        .device
        .create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(label),
            source: wgpu::ShaderSource::Naga(Cow::Owned(module)),
        });
    match pollster::block_on(scope.pop()) {
        Some(e) => Err(Rejected::Module(e.to_string())),
        None => Ok(m),
    }
}

impl PipelineCache {
    /// The layout of group 0: the default uniform block at binding 0 (with a dynamic offset)
    /// if `default`, and `blocks` uniform blocks at bindings `1..`.
    pub(crate) fn group0_layout(
        &mut self,
        gpu: &Gpu,
        default: bool,
        blocks: usize,
    ) -> wgpu::BindGroupLayout {
        self.group0_layouts
            .entry((default, blocks))
            .or_insert_with(|| {
                let entry = |binding: u32, dynamic: bool| wgpu::BindGroupLayoutEntry {
                    binding,
                    visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: dynamic,
                        min_binding_size: None,
                    },
                    count: None,
                };
                let mut entries = Vec::new();
                if default {
                    entries.push(entry(0, true));
                }
                entries.extend((0..blocks).map(|i| entry(1 + i as u32, false)));
                gpu.device
                    .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                        label: Some("essl-gl uniforms"),
                        entries: &entries,
                    })
            })
            .clone()
    }

    /// The layout of group 1 for these sampler slots.
    fn group1_layout(&mut self, gpu: &Gpu, slots: &[SlotBinding]) -> wgpu::BindGroupLayout {
        if let Some(l) = self.group1_layouts.get(slots) {
            return l.clone();
        }
        let mut entries = Vec::new();
        for (i, s) in slots.iter().enumerate() {
            let sample_type = match s.kind {
                SampleKind::Float => wgpu::TextureSampleType::Float {
                    filterable: s.filterable,
                },
                SampleKind::Sint => wgpu::TextureSampleType::Sint,
                SampleKind::Uint => wgpu::TextureSampleType::Uint,
                SampleKind::Depth => wgpu::TextureSampleType::Depth,
            };
            let sampler = match s.kind {
                SampleKind::Depth => wgpu::SamplerBindingType::Comparison,
                SampleKind::Float if s.filterable => wgpu::SamplerBindingType::Filtering,
                _ => wgpu::SamplerBindingType::NonFiltering,
            };
            entries.push(wgpu::BindGroupLayoutEntry {
                binding: 2 * i as u32,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Texture {
                    sample_type,
                    view_dimension: s.dim,
                    multisampled: false,
                },
                count: None,
            });
            entries.push(wgpu::BindGroupLayoutEntry {
                binding: 2 * i as u32 + 1,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Sampler(sampler),
                count: None,
            });
        }
        let layout = gpu
            .device
            .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("essl-gl textures"),
                entries: &entries,
            });
        self.group1_layouts.insert(slots.to_vec(), layout.clone());
        layout
    }

    /// The group-0 bind group: `size` bytes of default-block uniforms in an arena chunk (if
    /// any) and the buffer ranges of the uniform blocks.
    pub(crate) fn group0(
        &mut self,
        gpu: &Gpu,
        default: Option<(u64, &wgpu::Buffer, u64)>,
        blocks: &[(wgpu::Buffer, u64, u64)],
    ) -> wgpu::BindGroup {
        let key = (
            default.map(|(chunk, _, size)| (chunk, size)),
            blocks.to_vec(),
        );
        if let Some(g) = self.group0_groups.get(&key) {
            return g.clone();
        }
        if self.group0_groups.len() >= MAX_CACHED_BIND_GROUPS {
            self.group0_groups.clear();
        }
        let layout = self.group0_layout(gpu, default.is_some(), blocks.len());
        let mut entries = Vec::new();
        if let Some((_, buffer, size)) = default {
            entries.push(wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer,
                    offset: 0,
                    size: wgpu::BufferSize::new(size),
                }),
            });
        }
        // A block reads at most MAX_UNIFORM_BLOCK_SIZE bytes (the device's binding limit),
        // however large the range GL bound: bind no more than that.
        let max = gpu.limits.max_uniform_buffer_binding_size;
        for (i, (buffer, offset, size)) in blocks.iter().enumerate() {
            entries.push(wgpu::BindGroupEntry {
                binding: 1 + i as u32,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer,
                    offset: *offset,
                    size: wgpu::BufferSize::new((*size).min(max)),
                }),
            });
        }
        let group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("essl-gl uniforms"),
            layout: &layout,
            entries: &entries,
        });
        self.group0_groups.insert(key, group.clone());
        group
    }

    /// The group-1 bind group for these textures and samplers.
    pub(crate) fn group1(
        &mut self,
        gpu: &Gpu,
        slots: &[SlotBinding],
        resources: Vec<(wgpu::TextureView, wgpu::Sampler)>,
    ) -> wgpu::BindGroup {
        let key = (slots.to_vec(), resources);
        if let Some(g) = self.group1_groups.get(&key) {
            return g.clone();
        }
        if self.group1_groups.len() >= MAX_CACHED_BIND_GROUPS {
            self.group1_groups.clear();
        }
        let layout = self.group1_layout(gpu, slots);
        let mut entries = Vec::new();
        for (i, (view, sampler)) in key.1.iter().enumerate() {
            entries.push(wgpu::BindGroupEntry {
                binding: 2 * i as u32,
                resource: wgpu::BindingResource::TextureView(view),
            });
            entries.push(wgpu::BindGroupEntry {
                binding: 2 * i as u32 + 1,
                resource: wgpu::BindingResource::Sampler(sampler),
            });
        }
        let group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("essl-gl textures"),
            layout: &layout,
            entries: &entries,
        });
        self.group1_groups.insert(key, group.clone());
        group
    }

    /// The vertex module for a set of input patches, capturing what `capture` says.
    fn vertex_module(
        &mut self,
        gpu: &Gpu,
        program: &LinkedProgram,
        patches: &[InputPatch],
        capture: &Option<CaptureSpec>,
    ) -> Result<wgpu::ShaderModule, Rejected> {
        if patches.is_empty() && capture.is_none() {
            return Ok(program.vertex_module.clone());
        }
        self.modules
            .entry((program.serial, patches.to_vec(), capture.clone()))
            .or_insert_with(|| {
                let mut module = program.layout.vertex.clone();
                if !patches.is_empty() {
                    module = wrap_entry_point(&module, patches, false);
                }
                if let Some(spec) = capture {
                    module = capture_outputs(&module, spec);
                }
                create_module(gpu, module, "essl-gl vertex (patched)")
            })
            .clone()
    }

    /// The fragment module for a draw: into a target without a depth attachment (`!depth`),
    /// a shader that writes `gl_FragDepth` has the output taken out, as GL ignores it; with
    /// `scissor`, the module discards fragments outside that box itself
    /// ([`with_scissor_discard`]).
    fn fragment_module(
        &mut self,
        gpu: &Gpu,
        program: &LinkedProgram,
        depth: bool,
        scissor: Option<[u32; 4]>,
    ) -> Result<wgpu::ShaderModule, Rejected> {
        if depth && scissor.is_none() {
            return Ok(program.fragment_module.clone());
        }
        self.fragment_modules
            .entry((program.serial, depth, scissor))
            .or_insert_with(|| {
                let fragment = &program.layout.fragment;
                let mut module = if output_needs_widening(fragment) {
                    wrap_entry_point(fragment, &[], true)
                } else {
                    fragment.clone()
                };
                if !depth {
                    match without_frag_depth(&module) {
                        Some(m) => module = m,
                        None if scissor.is_none() => return Ok(program.fragment_module.clone()),
                        None => {}
                    }
                }
                if let Some(rect) = scissor {
                    module = with_scissor_discard(&module, rect);
                }
                create_module(gpu, module, "essl-gl fragment (patched)")
            })
            .clone()
    }

    /// The layout of group 2 for transform feedback: `buffers` storage buffers at bindings
    /// `0..`, the capture parameters at binding 4.
    pub(crate) fn capture_layout(&mut self, gpu: &Gpu, buffers: u32) -> wgpu::BindGroupLayout {
        self.capture_layouts
            .entry(buffers)
            .or_insert_with(|| {
                let mut entries: Vec<wgpu::BindGroupLayoutEntry> = (0..buffers)
                    .map(|b| wgpu::BindGroupLayoutEntry {
                        binding: b,
                        visibility: wgpu::ShaderStages::VERTEX,
                        ty: wgpu::BindingType::Buffer {
                            ty: wgpu::BufferBindingType::Storage { read_only: false },
                            has_dynamic_offset: false,
                            min_binding_size: None,
                        },
                        count: None,
                    })
                    .collect();
                entries.push(wgpu::BindGroupLayoutEntry {
                    binding: crate::shader_patch::CAPTURE_PARAMS_BINDING,
                    visibility: wgpu::ShaderStages::VERTEX,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                });
                gpu.device
                    .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                        label: Some("essl-gl transform feedback"),
                        entries: &entries,
                    })
            })
            .clone()
    }

    /// The pipeline for `key`, created on first use. An `Err` says why wgpu refused it.
    pub(crate) fn pipeline(
        &mut self,
        gpu: &Gpu,
        key: &PipelineKey,
        program: &LinkedProgram,
    ) -> Result<CachedPipeline, Rejected> {
        if let Some(p) = self.pipelines.get(key) {
            return p.clone();
        }
        let result = self.create(gpu, key, program);
        self.pipelines.insert(key.clone(), result.clone());
        result
    }

    fn create(
        &mut self,
        gpu: &Gpu,
        key: &PipelineKey,
        program: &LinkedProgram,
    ) -> Result<CachedPipeline, Rejected> {
        let vertex_module = self.vertex_module(gpu, program, &key.patches, &key.capture)?;
        let fragment_module = self.fragment_module(
            gpu,
            program,
            key.depth_format.is_some(),
            key.scissor_discard,
        )?;
        let (default, blocks) = (
            program.layout.uniform_block.is_some(),
            program.layout.blocks.len(),
        );
        let group0 = (default || blocks > 0).then(|| self.group0_layout(gpu, default, blocks));
        let group1 = (!key.slots.is_empty()).then(|| self.group1_layout(gpu, &key.slots));
        let group2 = key
            .capture
            .as_ref()
            .map(|c| self.capture_layout(gpu, c.buffers));
        let mut groups: Vec<Option<&wgpu::BindGroupLayout>> = vec![group0.as_ref()];
        if group1.is_some() || group2.is_some() {
            groups.push(group1.as_ref());
        }
        if group2.is_some() {
            groups.push(group2.as_ref());
        }
        let targets = color_targets(key);
        let scope = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let layout = gpu
            .device
            .create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("essl-gl"),
                bind_group_layouts: &groups,
                immediate_size: 0,
            });
        let attributes: Vec<[wgpu::VertexAttribute; 1]> = key
            .vertex
            .iter()
            .map(|s| {
                [wgpu::VertexAttribute {
                    format: s.format,
                    offset: s.offset,
                    shader_location: s.location,
                }]
            })
            .collect();
        let buffers: Vec<Option<wgpu::VertexBufferLayout>> = key
            .vertex
            .iter()
            .zip(&attributes)
            .map(|(s, a)| {
                Some(wgpu::VertexBufferLayout {
                    array_stride: s.stride,
                    step_mode: s.step,
                    attributes: a,
                })
            })
            .collect();
        // Only values that differ from the constants' defaults: a program without them (a
        // layout of its own) then never gets a name its module lacks.
        let (upper_left, zero_to_one) = key.clip_control;
        let constants: Vec<(&str, f64)> = [
            (essl::program::CLIP_UPPER_LEFT, upper_left),
            (essl::program::CLIP_ZERO_TO_ONE, zero_to_one),
        ]
        .into_iter()
        .filter(|(_, on)| *on)
        .map(|(name, _)| (name, 1.0))
        .collect();
        let pipeline = gpu
            .device
            .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("essl-gl"),
                layout: Some(&layout),
                vertex: wgpu::VertexState {
                    module: &vertex_module,
                    entry_point: Some("main"),
                    compilation_options: wgpu::PipelineCompilationOptions {
                        constants: &constants,
                        ..Default::default()
                    },
                    buffers: &buffers,
                },
                primitive: wgpu::PrimitiveState {
                    topology: key.topology,
                    strip_index_format: key.strip_index_format,
                    front_face: key.front_face,
                    cull_mode: key.cull_mode,
                    unclipped_depth: key.unclipped_depth,
                    polygon_mode: if key.polygon_line {
                        wgpu::PolygonMode::Line
                    } else {
                        wgpu::PolygonMode::Fill
                    },
                    conservative: false,
                },
                depth_stencil: key.depth_format.map(|format| wgpu::DepthStencilState {
                    format,
                    depth_write_enabled: Some(key.depth_write && format.has_depth_aspect()),
                    depth_compare: Some(if format.has_depth_aspect() {
                        key.depth_compare
                    } else {
                        wgpu::CompareFunction::Always
                    }),
                    stencil: if format.has_stencil_aspect() {
                        key.stencil.clone()
                    } else {
                        Default::default()
                    },
                    bias: wgpu::DepthBiasState {
                        constant: key.depth_bias.0,
                        slope_scale: f32::from_bits(key.depth_bias.1),
                        clamp: f32::from_bits(key.depth_bias.2),
                    },
                }),
                multisample: wgpu::MultisampleState {
                    count: key.samples,
                    mask: key.sample_mask,
                    alpha_to_coverage_enabled: key.alpha_to_coverage && key.samples > 1,
                },
                fragment: key.rasterize.then(|| wgpu::FragmentState {
                    module: &fragment_module,
                    entry_point: Some("main"),
                    compilation_options: Default::default(),
                    targets: &targets,
                }),
                multiview_mask: None,
                cache: None,
            });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(Rejected::Pipeline(e.to_string()));
        }
        self.next_id += 1;
        self.created += 1;
        Ok(CachedPipeline {
            id: self.next_id,
            pipeline,
        })
    }
}

/// The colour targets of a draw pipeline: blending only where the format can blend (not
/// integer formats, as GL ignores blending there, nor 32-bit floats without
/// `EXT_float_blend`).
fn color_targets(key: &PipelineKey) -> Vec<Option<wgpu::ColorTargetState>> {
    key.targets
        .iter()
        .enumerate()
        .map(|(i, t)| {
            t.map(|format| {
                let (blend, mask) = key
                    .blends
                    .get(i)
                    .copied()
                    .unwrap_or((None, wgpu::ColorWrites::ALL));
                let write_mask = if key.rgb_targets & (1 << i) != 0 {
                    mask - wgpu::ColorWrites::ALPHA
                } else {
                    mask
                };
                let blendable = format
                    .sample_type(None, None)
                    .is_some_and(|s| matches!(s, wgpu::TextureSampleType::Float { .. }))
                    && (key.float_blend
                        || !matches!(
                            format,
                            wgpu::TextureFormat::R32Float
                                | wgpu::TextureFormat::Rg32Float
                                | wgpu::TextureFormat::Rgba32Float
                        ));
                wgpu::ColorTargetState {
                    format,
                    blend: if blendable { blend } else { None },
                    write_mask,
                }
            })
        })
        .collect()
}
