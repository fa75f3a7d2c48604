//! Encoding a checked draw: the vertex buffers (re-packed or bound directly, generic values
//! from the arena), the index buffer (widened or generated), the textures and samplers, and
//! the uniform data, brought up to date on the GPU and gathered into the bind groups the
//! pipeline takes. [`super::record`] then builds the pipeline and records the draw.

use essl::program::InternalUniform;

use super::topology::{emulate, repack, Emulated};
use super::{DrawCall, Feed, Indices, SlotPlan, Source};
use crate::buffer::{index_size, read_indices, DerivedKey};
use crate::context::Context;
use crate::framebuffer::sample_view_key;
use crate::gl;
use crate::objects::Id;
use crate::pipeline::{SlotBinding, VertexSlot};
use crate::program::ShaderInput;
use crate::shader_patch::InputPatch;
use crate::texture::{SampleKind, SamplerKey};
use crate::vertex_array::{GenericAttrib, VertexAttrib};

/// The vertex side of a draw: the pipeline's vertex slots, the conversions the vertex entry
/// point must make, and the buffer (and offset) bound to each slot.
#[derive(Default)]
pub(super) struct VertexInputs {
    pub(super) slots: Vec<VertexSlot>,
    pub(super) patches: Vec<InputPatch>,
    pub(super) bindings: Vec<(wgpu::Buffer, u64)>,
}

/// The index buffer (buffer, offset, format, index range) of a draw.
pub(super) type IndexBuffer = (wgpu::Buffer, u64, wgpu::IndexFormat, std::ops::Range<u32>);

/// What a draw reads its vertices with: an index buffer, or the range of vertices.
pub(super) struct DrawRange {
    pub(super) index: Option<IndexBuffer>,
    pub(super) vertices: std::ops::Range<u32>,
}

/// The resources a draw binds: group 0 (uniform data, with the dynamic offset of the
/// default block), group 1 (textures and samplers) and the sampler slots' layout.
pub(super) struct Groups {
    pub(super) group0: Option<(wgpu::BindGroup, Option<u32>)>,
    pub(super) group1: Option<wgpu::BindGroup>,
    /// Transform feedback's storage buffers and parameters.
    pub(super) group2: Option<wgpu::BindGroup>,
    pub(super) slot_bindings: Vec<SlotBinding>,
}

/// Whether wgpu takes an enabled array as it is (its stride and offset), or it must be
/// re-packed on the CPU.
fn binds_directly(a: &VertexAttrib, feed: &Feed) -> bool {
    let stride = a.effective_stride();
    let fmt_size = feed.format.size();
    let rel = a.offset & 3;
    stride % 4 == 0 && rel % fmt_size.min(4) == 0 && rel + fmt_size <= stride && a.divisor <= 1
}

impl Context {
    /// Brings in step, before anything is bound, what could submit the batch while the draw
    /// is encoded: the CPU copies of the buffers the draw reads on the CPU (re-packed arrays,
    /// indices), which transform feedback may have written on the GPU, and the GPU copies of
    /// the textures it samples, whose remade chain may read levels back. A submit between
    /// two bindings would leave the first in the submitted batch and the draw in the next,
    /// where a later write could land in place under it.
    pub(super) fn settle_reads(&mut self, call: &DrawCall) {
        let (gpu, frame) = (&self.gpu, &mut self.frame);
        for (_, source) in &call.sources {
            if let Source::Array {
                buffer,
                attrib,
                feed,
            } = source
            {
                if !binds_directly(attrib, feed) {
                    let b = self.objects.buffers.get_any_mut(*buffer);
                    b.expect("attached buffers are alive").cpu_bytes(gpu, frame);
                }
            }
        }
        if let Indices::Elements { buffer, .. } = call.indices {
            let b = self.objects.buffers.get_any_mut(buffer);
            b.expect("bound buffers are alive").cpu_bytes(gpu, frame);
        }
        for plan in &call.slot_plans {
            if let Some((id, c, _)) = plan.texture {
                self.sync_texture(id, c.base..c.base + c.levels);
            }
        }
    }

    /// The vertex buffers and slots of the draw's inputs.
    pub(super) fn bind_vertex_inputs(&mut self, call: &DrawCall) -> VertexInputs {
        let mut out = VertexInputs::default();
        for (input, source) in &call.sources {
            match source {
                Source::Array {
                    buffer,
                    attrib,
                    feed,
                } => self.bind_array(&mut out, input, *buffer, attrib, feed, call.instances),
                Source::Constant(g) => self.bind_constant(&mut out, input, g),
            }
        }
        out
    }

    /// Binds an enabled array: directly when wgpu accepts its stride and offset, else a
    /// re-packed copy; notes the conversion the shader must make of what it is fed.
    fn bind_array(
        &mut self,
        out: &mut VertexInputs,
        input: &ShaderInput,
        buffer: Id,
        a: &VertexAttrib,
        feed: &Feed,
        instances: u32,
    ) {
        let stride = a.effective_stride();
        let fmt_size = feed.format.size();
        let rel = a.offset & 3;
        let direct = binds_directly(a, feed);
        let serial = self.frame.serial();
        let gpu = &self.gpu;
        let b = self
            .objects
            .buffers
            .get_any_mut(buffer)
            .expect("attached buffers are alive");
        let step = if a.divisor == 0 {
            wgpu::VertexStepMode::Vertex
        } else {
            wgpu::VertexStepMode::Instance
        };
        if direct {
            out.bindings
                .push((b.gpu_buffer(gpu, serial), a.offset - rel));
            out.slots.push(VertexSlot {
                stride,
                step,
                format: feed.format,
                offset: rel,
                location: input.location,
            });
        } else {
            let packed = fmt_size.div_ceil(4) * 4;
            let key = DerivedKey::Repacked {
                offset: a.offset,
                stride,
                element: a.element_size(),
                packed,
                per_instance: (a.divisor > 1).then_some((a.divisor, instances)),
            };
            let frame = &mut self.frame;
            let buffer = b.derived(gpu, frame, key.clone(), |data| repack(data, &key));
            out.bindings.push((buffer, 0));
            out.slots.push(VertexSlot {
                stride: packed,
                step,
                format: feed.format,
                offset: 0,
                location: input.location,
            });
        }
        let needs_patch = feed.kind != input.kind
            || feed.count > input.components
            || feed.used < feed.count
            || feed.norm.is_some()
            || feed.packed.is_some();
        if needs_patch {
            out.patches.push(InputPatch {
                location: input.location,
                fed_kind: feed.kind,
                fed_count: feed.count,
                used: feed.used,
                norm: feed.norm,
                packed: feed.packed,
            });
        }
    }

    /// Binds the generic value of a disabled array, from the arena at stride 0.
    fn bind_constant(&mut self, out: &mut VertexInputs, input: &ShaderInput, g: &GenericAttrib) {
        let n = input.components as usize;
        let (bytes, formats): (Vec<u8>, [wgpu::VertexFormat; 4]) = match g {
            GenericAttrib::Float(v) => (
                bytemuck::cast_slice(&v[..n]).to_vec(),
                [
                    wgpu::VertexFormat::Float32,
                    wgpu::VertexFormat::Float32x2,
                    wgpu::VertexFormat::Float32x3,
                    wgpu::VertexFormat::Float32x4,
                ],
            ),
            GenericAttrib::Int(v) => (
                bytemuck::cast_slice(&v[..n]).to_vec(),
                [
                    wgpu::VertexFormat::Sint32,
                    wgpu::VertexFormat::Sint32x2,
                    wgpu::VertexFormat::Sint32x3,
                    wgpu::VertexFormat::Sint32x4,
                ],
            ),
            GenericAttrib::Uint(v) => (
                bytemuck::cast_slice(&v[..n]).to_vec(),
                [
                    wgpu::VertexFormat::Uint32,
                    wgpu::VertexFormat::Uint32x2,
                    wgpu::VertexFormat::Uint32x3,
                    wgpu::VertexFormat::Uint32x4,
                ],
            ),
        };
        let alloc = self.frame.arena.push(&self.gpu, &bytes, 4);
        out.bindings.push((alloc.buffer, alloc.offset));
        // Stride 0: every vertex reads the same value.
        out.slots.push(VertexSlot {
            stride: 0,
            step: wgpu::VertexStepMode::Vertex,
            format: formats[n - 1],
            offset: 0,
            location: input.location,
        });
    }

    /// The index buffer or vertex range of the draw; `None` when an emulated topology
    /// leaves nothing to draw.
    pub(super) fn bind_indices(&mut self, call: &DrawCall) -> Option<DrawRange> {
        let serial = self.frame.serial();
        let gpu = &self.gpu;
        let count = call.count;
        let mut index: Option<IndexBuffer> = None;
        let mut vertices = 0..count;
        match (&call.indices, call.emulated) {
            (Indices::None { first }, Emulated::None) => vertices = *first..*first + count,
            (Indices::None { first }, how) => {
                let generated = emulate(*first..*first + count, how);
                if generated.is_empty() {
                    return None;
                }
                let alloc = self
                    .frame
                    .arena
                    .push(gpu, bytemuck::cast_slice(&generated), 4);
                index = Some((
                    alloc.buffer,
                    alloc.offset,
                    wgpu::IndexFormat::Uint32,
                    0..generated.len() as u32,
                ));
            }
            (Indices::Elements { buffer, ty, offset }, Emulated::None) => {
                let b = self
                    .objects
                    .buffers
                    .get_any_mut(*buffer)
                    .expect("bound buffers are alive");
                let size = index_size(*ty).expect("checked");
                let first = (offset / size) as u32;
                let (buf, format) = match *ty {
                    gl::UNSIGNED_BYTE => (
                        b.derived(gpu, &mut self.frame, DerivedKey::WideIndices, |data| {
                            let wide: Vec<u16> = data
                                .iter()
                                .map(|&i| if i == 0xFF { 0xFFFF } else { i as u16 })
                                .collect();
                            bytemuck::cast_slice(&wide).to_vec()
                        }),
                        wgpu::IndexFormat::Uint16,
                    ),
                    gl::UNSIGNED_SHORT => (b.gpu_buffer(gpu, serial), wgpu::IndexFormat::Uint16),
                    _ => (b.gpu_buffer(gpu, serial), wgpu::IndexFormat::Uint32),
                };
                index = Some((buf, 0, format, first..first + count));
            }
            (Indices::Elements { buffer, ty, offset }, how) => {
                let b = self
                    .objects
                    .buffers
                    .get_any_mut(*buffer)
                    .expect("bound buffers are alive");
                let data = b.cpu_bytes(gpu, &mut self.frame);
                let generated = emulate(read_indices(data, *ty, *offset, count as u64), how);
                if generated.is_empty() {
                    return None;
                }
                let alloc = self
                    .frame
                    .arena
                    .push(gpu, bytemuck::cast_slice(&generated), 4);
                index = Some((
                    alloc.buffer,
                    alloc.offset,
                    wgpu::IndexFormat::Uint32,
                    0..generated.len() as u32,
                ));
            }
        }
        Some(DrawRange { index, vertices })
    }

    /// The view and sampler for each sampler slot (a placeholder for an incomplete or
    /// missing texture), and the slots' layout.
    fn bind_textures(
        &mut self,
        slot_plans: &[SlotPlan],
    ) -> (Vec<SlotBinding>, Vec<(wgpu::TextureView, wgpu::Sampler)>) {
        let mut slot_bindings = Vec::new();
        let mut resources = Vec::new();
        for plan in slot_plans {
            let shadow = plan.kind == SampleKind::Depth;
            match plan.texture {
                Some((id, c, sampling)) => {
                    self.sync_texture(id, c.base..c.base + c.levels);
                    let gpu = &self.gpu;
                    let t = self
                        .objects
                        .textures
                        .get_any_mut(id)
                        .expect("bound textures are alive");
                    let target = t.target.expect("complete textures have a target");
                    let g = t.gpu.as_mut().expect("synced above");
                    let mut key = sample_view_key(target, g.anchor, c.base, c.levels, &c.format);
                    key.dimension = plan.dim;
                    if c.stencil {
                        key.aspect = wgpu::TextureAspect::StencilOnly;
                    }
                    let view = g.view(key);
                    let mut sampling = sampling;
                    if c.format.has_depth() && !shadow {
                        // A depth value is not filtered: WebGL 1's LINEAR reads as NEAREST.
                        sampling.mag_filter = gl::NEAREST;
                        sampling.min_filter = match sampling.min_filter {
                            gl::NEAREST | gl::LINEAR => gl::NEAREST,
                            _ => gl::NEAREST_MIPMAP_NEAREST,
                        };
                    }
                    let key = crate::texture::TextureObject::sampler_key(&sampling, shadow);
                    let sampler = self.caches.samplers.get(&gpu.device, key);
                    slot_bindings.push(SlotBinding {
                        dim: plan.dim,
                        kind: plan.kind,
                        // A depth texture sampled for its values (no comparison) is an
                        // unfilterable float texture to wgpu.
                        filterable: (!c.format.has_depth() || shadow)
                            && (c.format.filterable()
                                || (self.extensions.texture_float_linear
                                    && c.format.comp == crate::texture::Comp::F32)),
                    });
                    resources.push((view, sampler));
                }
                None => {
                    let gpu = &self.gpu;
                    let view = self.caches.dummies.get(gpu, plan.dim, plan.kind);
                    let sampler = self
                        .caches
                        .samplers
                        .get(&gpu.device, SamplerKey::placeholder(shadow));
                    slot_bindings.push(SlotBinding {
                        dim: plan.dim,
                        kind: plan.kind,
                        filterable: true,
                    });
                    resources.push((view, sampler));
                }
            }
        }
        (slot_bindings, resources)
    }

    /// Writes the values the renderer provides into program `pid`'s default uniform block
    /// and puts the block in the arena (once per batch and version): chunk, buffer, offset
    /// and size; `None` for a program without one.
    fn upload_default_block(&mut self, pid: Id) -> Option<(u64, wgpu::Buffer, u32, u64)> {
        let serial = self.frame.serial();
        let gpu = &self.gpu;
        let height = self.fb.height as f32;
        let clip_distances = self.clip_distances_enabled();
        let draw_id = self.draw_id;
        let linked = self
            .objects
            .linked_mut(pid)
            .expect("current programs are linked");
        let block = linked.layout.uniform_block.as_ref()?;
        for (what, offset) in &block.internal {
            let value = match what {
                InternalUniform::FramebufferHeight => height.to_ne_bytes(),
                InternalUniform::ClipDistancesEnabled => clip_distances.to_ne_bytes(),
                InternalUniform::DrawId => draw_id.to_ne_bytes(),
            };
            let at = *offset as usize;
            if let Some(dst) = linked.uniform_data.get_mut(at..at + 4) {
                if dst != value {
                    dst.copy_from_slice(&value);
                    linked.uniform_version += 1;
                }
            }
        }
        let (chunk, buffer, offset) = match &linked.uploaded {
            Some((batch, version, chunk, offset))
                if *batch == serial && *version == linked.uniform_version =>
            {
                let buffer = self.frame.arena.chunk_buffer(*chunk);
                (
                    *chunk,
                    buffer.expect("chunks live for the batch"),
                    *offset as u64,
                )
            }
            _ => {
                let align = gpu.limits.min_uniform_buffer_offset_alignment as u64;
                let alloc = self.frame.arena.push(gpu, &linked.uniform_data, align);
                linked.uploaded = Some((
                    serial,
                    linked.uniform_version,
                    alloc.chunk,
                    alloc.offset as u32,
                ));
                (alloc.chunk, alloc.buffer, alloc.offset)
            }
        };
        Some((chunk, buffer, offset as u32, block.size as u64))
    }

    /// The draw's bind groups: textures and samplers, the default uniform block and the
    /// uniform blocks' buffer ranges.
    pub(super) fn bind_groups(&mut self, call: &DrawCall) -> Groups {
        let (slot_bindings, resources) = self.bind_textures(&call.slot_plans);
        let default = self.upload_default_block(call.program);
        let serial = self.frame.serial();
        let gpu = &self.gpu;
        let block_buffers: Vec<(wgpu::Buffer, u64, u64)> = call
            .blocks
            .iter()
            .map(|&(id, offset, size)| {
                let b = self
                    .objects
                    .buffers
                    .get_any_mut(id)
                    .expect("bound buffers are alive");
                (b.gpu_buffer(gpu, serial), offset, size)
            })
            .collect();
        let mut group0 = None;
        if default.is_some() || !block_buffers.is_empty() {
            let arena = default
                .as_ref()
                .map(|(chunk, buffer, _, size)| (*chunk, buffer, *size));
            let group = self.caches.pipelines.group0(gpu, arena, &block_buffers);
            group0 = Some((group, default.as_ref().map(|d| d.2)));
        }
        let group1 = (!slot_bindings.is_empty())
            .then(|| self.caches.pipelines.group1(gpu, &slot_bindings, resources));
        let group2 = call.capture.as_ref().map(|c| self.capture_group(c));
        Groups {
            group0,
            group1,
            group2,
            slot_bindings,
        }
    }

    /// The bind group of a capturing draw: its buffers' GPU copies (which the draw makes the
    /// newer ones) and the parameters (first vertex, vertices per instance, each buffer's
    /// first word).
    fn capture_group(&mut self, c: &super::feedback::CaptureDraw) -> wgpu::BindGroup {
        let serial = self.frame.serial();
        let mut buffers = Vec::new();
        for &id in &c.buffers {
            let b = self
                .objects
                .buffers
                .get_any_mut(id)
                .expect("bound buffers are alive");
            buffers.push(b.mark_gpu_written(&self.gpu, serial));
        }
        let mut params = [0u32; 8];
        params[0] = c.first;
        params[1] = c.count;
        params[4..8].copy_from_slice(&c.base);
        let align = self.gpu.limits.min_uniform_buffer_offset_alignment as u64;
        let alloc = self
            .frame
            .arena
            .push(&self.gpu, bytemuck::cast_slice(&params), align);
        let layout = self
            .caches
            .pipelines
            .capture_layout(&self.gpu, c.spec.buffers);
        let mut entries: Vec<wgpu::BindGroupEntry> = buffers
            .iter()
            .enumerate()
            .map(|(b, buffer)| wgpu::BindGroupEntry {
                binding: b as u32,
                resource: buffer.as_entire_binding(),
            })
            .collect();
        entries.push(wgpu::BindGroupEntry {
            binding: crate::shader_patch::CAPTURE_PARAMS_BINDING,
            resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                buffer: &alloc.buffer,
                offset: alloc.offset,
                size: wgpu::BufferSize::new(32),
            }),
        });
        self.gpu
            .device
            .create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("essl-gl transform feedback"),
                layout: &layout,
                entries: &entries,
            })
    }
}
