//! Batching: the command encoder that draws, clears and copies are recorded into, the render
//! pass open on the current draw target, and the per-batch arena for uniforms, constant
//! attributes, generated indices and texel uploads.
//!
//! GL executes commands in order; wgpu executes a command buffer after the queue writes made
//! before its submission. Commands are therefore recorded into one encoder and submitted
//! together ("a batch") only when the results are needed. Nothing the batch uses is written
//! in place by a queue write: buffers are replaced, and per-draw data and texel uploads go to
//! the arena, which is written just before the submit and read by commands recorded in GL's
//! order (a texel upload is a buffer-to-texture copy in the encoder).
//!
//! Draws go into a render pass on a [`PassTarget`]; a draw on another target, a copy, or a
//! clear of whole attachments ends the pass, and the next draw begins one (loading what the
//! attachments hold). The pass, its target and the dynamic state set in it are one value,
//! begun and ended together. While an occlusion query is active every pass counts its
//! samples into a slot of the query's set ([`Frame::begin_occlusion`],
//! [`Frame::end_occlusion`]).

use crate::gpu::Gpu;

/// Bytes of one arena chunk (larger allocations get a chunk of their own size).
const CHUNK_SIZE: u64 = 1 << 18;

/// One GPU buffer of the arena and the bytes it will receive at the next submit.
struct Chunk {
    /// Unique within the arena, so bind groups made for a chunk can be cached by it.
    id: u64,
    buffer: wgpu::Buffer,
    data: Vec<u8>,
}

/// A linear allocator of per-draw data, uploaded at each submit.
pub(crate) struct Arena {
    chunks: Vec<Chunk>,
    current: usize,
    next_id: u64,
}

/// Where an arena allocation lives.
#[derive(Clone, Debug)]
pub(crate) struct Allocation {
    /// The chunk's [`Chunk::id`].
    pub(crate) chunk: u64,
    pub(crate) buffer: wgpu::Buffer,
    pub(crate) offset: u64,
}

impl Arena {
    fn new() -> Self {
        Arena {
            chunks: Vec::new(),
            current: 0,
            next_id: 0,
        }
    }

    /// Copies `bytes` into the arena at an `align`ed offset.
    pub(crate) fn push(&mut self, gpu: &Gpu, bytes: &[u8], align: u64) -> Allocation {
        let size = (bytes.len() as u64).max(4).div_ceil(4) * 4;
        loop {
            if let Some(chunk) = self.chunks.get_mut(self.current) {
                let offset = (chunk.data.len() as u64).div_ceil(align) * align;
                if offset + size <= chunk.buffer.size() {
                    chunk.data.resize(offset as usize, 0);
                    chunk.data.extend_from_slice(bytes);
                    chunk.data.resize((offset + size) as usize, 0);
                    return Allocation {
                        chunk: chunk.id,
                        buffer: chunk.buffer.clone(),
                        offset,
                    };
                }
                if !chunk.data.is_empty() || chunk.buffer.size() >= size {
                    self.current += 1;
                    continue;
                }
            }
            // A new chunk (or a larger one replacing an empty, too-small one).
            let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("essl-gl arena"),
                size: CHUNK_SIZE.max(size.next_power_of_two()),
                usage: wgpu::BufferUsages::UNIFORM
                    | wgpu::BufferUsages::VERTEX
                    | wgpu::BufferUsages::INDEX
                    | wgpu::BufferUsages::COPY_SRC
                    | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            self.next_id += 1;
            let chunk = Chunk {
                id: self.next_id,
                buffer,
                data: Vec::new(),
            };
            if self.current < self.chunks.len() {
                self.chunks[self.current] = chunk;
            } else {
                self.chunks.push(chunk);
            }
        }
    }

    /// The buffer of the chunk [`Allocation::chunk`] names, while the batch lasts.
    pub(crate) fn chunk_buffer(&self, chunk: u64) -> Option<wgpu::Buffer> {
        self.chunks
            .iter()
            .find(|c| c.id == chunk)
            .map(|c| c.buffer.clone())
    }

    /// Queues the writes of everything pushed since the last submit, and starts over.
    fn upload(&mut self, queue: &wgpu::Queue) {
        for chunk in &mut self.chunks {
            if !chunk.data.is_empty() {
                queue.write_buffer(&chunk.buffer, 0, &chunk.data);
                chunk.data.clear();
            }
        }
        self.current = 0;
    }
}

/// Dynamic state already set in the open render pass, which a draw need not set again.
#[derive(Default)]
pub(crate) struct PassState {
    pub(crate) pipeline: Option<u64>,
    pub(crate) viewport: Option<[u32; 6]>,
    pub(crate) scissor: Option<[u32; 4]>,
    pub(crate) blend_constant: Option<[u32; 4]>,
    pub(crate) stencil_reference: Option<u32>,
    pub(crate) group0: Option<(wgpu::BindGroup, Option<u32>)>,
    pub(crate) group1: Option<wgpu::BindGroup>,
    pub(crate) vertex_buffers: Vec<Option<(wgpu::Buffer, u64)>>,
    pub(crate) index_buffer: Option<(wgpu::Buffer, u64, wgpu::IndexFormat)>,
}

/// A colour attachment of a render pass.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct ColorTarget {
    /// A view of one level and layer (a 3D texture's view is the whole level, with
    /// `depth_slice`).
    pub(crate) view: wgpu::TextureView,
    pub(crate) depth_slice: Option<u32>,
    /// The single-sample view a multisampled attachment is resolved into at the end of
    /// every pass (the default framebuffer with `antialias`).
    pub(crate) resolve: Option<wgpu::TextureView>,
    pub(crate) format: wgpu::TextureFormat,
}

/// The depth and stencil attachment of a render pass.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct DepthTarget {
    pub(crate) view: wgpu::TextureView,
    pub(crate) format: wgpu::TextureFormat,
}

impl DepthTarget {
    /// Whether the format has depth.
    pub(crate) fn has_depth(&self) -> bool {
        self.format.has_depth_aspect()
    }

    /// Whether the format has stencil.
    pub(crate) fn has_stencil(&self) -> bool {
        self.format.has_stencil_aspect()
    }
}

/// What a render pass draws into: colour attachments by draw buffer (GL's
/// `drawBuffers[i]` is location `i`), and depth/stencil.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct PassTarget {
    pub(crate) colors: Vec<Option<ColorTarget>>,
    pub(crate) depth: Option<DepthTarget>,
    /// Samples per pixel of every attachment.
    pub(crate) samples: u32,
    /// Width and height of the area every attachment covers.
    pub(crate) size: [u32; 2],
}

/// What a pass begins by clearing, per attachment (`None`: load what is there).
#[derive(Clone, Debug, Default)]
pub(crate) struct PassClears {
    pub(crate) colors: Vec<Option<wgpu::Color>>,
    pub(crate) depth: Option<f32>,
    pub(crate) stencil: Option<u32>,
}

/// The render pass open on a target, and the dynamic state already set in it.
struct OpenPass {
    pass: wgpu::RenderPass<'static>,
    target: PassTarget,
    state: PassState,
    /// Whether the pass began an occlusion query, which ends with it.
    counts: bool,
}

/// The occlusion query in progress: every render pass counts the samples that pass into a
/// slot of its own of `set`; `next` is the next free slot.
struct Occlusion {
    set: wgpu::QuerySet,
    next: u32,
}

/// Slots of one occlusion query's set: render passes counted while it is active.
const OCCLUSION_SLOTS: u32 = 4096;

/// What an ended occlusion query counted: the per-pass counts are copied into `buffer` by
/// the batch that ended it ([`Frame::any_samples`] reads them).
pub(crate) struct OcclusionCounts {
    buffer: wgpu::Buffer,
    slots: u32,
}

/// The batch being recorded.
pub(crate) struct Frame {
    /// Identifies the batch; bumped at every submit.
    serial: u64,
    encoder: Option<wgpu::CommandEncoder>,
    /// The open render pass; ending it drops its target and state with it.
    open: Option<OpenPass>,
    pub(crate) arena: Arena,
    occlusion: Option<Occlusion>,
}

impl Frame {
    pub(crate) fn new() -> Self {
        Frame {
            serial: 1,
            encoder: None,
            open: None,
            arena: Arena::new(),
            occlusion: None,
        }
    }

    /// Identifies the batch being recorded; changes at every submit.
    pub(crate) fn serial(&self) -> u64 {
        self.serial
    }

    fn encoder(&mut self, gpu: &Gpu) -> &mut wgpu::CommandEncoder {
        self.encoder.get_or_insert_with(|| {
            gpu.device
                .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("essl-gl batch"),
                })
        })
    }

    /// Ends the open render pass, if any (and the occlusion query it began).
    pub(crate) fn end_pass(&mut self) {
        if let Some(mut open) = self.open.take() {
            if open.counts {
                open.pass.end_occlusion_query();
            }
        }
    }

    /// The encoder, for commands outside a render pass (copies): ends the open pass.
    pub(crate) fn commands(&mut self, gpu: &Gpu) -> &mut wgpu::CommandEncoder {
        self.end_pass();
        self.encoder(gpu)
    }

    /// The render pass open on `target` and the state already set in it, beginning a pass
    /// that loads the attachments if the open one (if any) has another target.
    pub(crate) fn pass(
        &mut self,
        gpu: &Gpu,
        target: &PassTarget,
    ) -> (&mut wgpu::RenderPass<'static>, &mut PassState) {
        if self.open.as_ref().is_none_or(|o| o.target != *target) {
            self.begin(gpu, target, &PassClears::default());
        }
        let open = self.open.as_mut().expect("just opened");
        (&mut open.pass, &mut open.state)
    }

    /// [`Frame::pass`] for a draw of essl-gl's own (a clear or a blit through a pipeline),
    /// which sets its pipeline, viewport, scissor, bind groups and stencil reference itself:
    /// the state the pass remembers is forgotten, so the next draw sets it all again.
    pub(crate) fn internal_pass(
        &mut self,
        gpu: &Gpu,
        target: &PassTarget,
    ) -> &mut wgpu::RenderPass<'static> {
        let (pass, state) = self.pass(gpu, target);
        *state = PassState::default();
        pass
    }

    /// Ends the open pass and begins one on `target` that clears what `clears` says (whole
    /// attachments) and loads the rest.
    pub(crate) fn clear_pass(&mut self, gpu: &Gpu, target: &PassTarget, clears: &PassClears) {
        self.begin(gpu, target, clears);
    }

    fn begin(&mut self, gpu: &Gpu, target: &PassTarget, clears: &PassClears) {
        self.end_pass();
        let colors: Vec<Option<wgpu::RenderPassColorAttachment>> = target
            .colors
            .iter()
            .enumerate()
            .map(|(i, c)| {
                c.as_ref().map(|c| {
                    let clear = clears.colors.get(i).copied().flatten();
                    wgpu::RenderPassColorAttachment {
                        view: &c.view,
                        depth_slice: c.depth_slice,
                        resolve_target: c.resolve.as_ref(),
                        ops: wgpu::Operations {
                            load: clear.map_or(wgpu::LoadOp::Load, wgpu::LoadOp::Clear),
                            store: wgpu::StoreOp::Store,
                        },
                    }
                })
            })
            .collect();
        let depth = target.depth.as_ref().map(|d| {
            let ops = |clear: Option<f32>| wgpu::Operations {
                load: clear.map_or(wgpu::LoadOp::Load, wgpu::LoadOp::Clear),
                store: wgpu::StoreOp::Store,
            };
            wgpu::RenderPassDepthStencilAttachment {
                view: &d.view,
                depth_ops: d.has_depth().then(|| ops(clears.depth)),
                stencil_ops: d.has_stencil().then(|| wgpu::Operations {
                    load: clears
                        .stencil
                        .map_or(wgpu::LoadOp::Load, wgpu::LoadOp::Clear),
                    store: wgpu::StoreOp::Store,
                }),
            }
        });
        let slot = match &mut self.occlusion {
            Some(o) if o.next < OCCLUSION_SLOTS => {
                o.next += 1;
                Some((o.set.clone(), o.next - 1))
            }
            _ => None,
        };
        let encoder = self.encoder(gpu);
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("essl-gl pass"),
            color_attachments: &colors,
            depth_stencil_attachment: depth,
            timestamp_writes: None,
            occlusion_query_set: slot.as_ref().map(|(set, _)| set),
            multiview_mask: None,
        });
        if let Some((_, index)) = &slot {
            pass.begin_occlusion_query(*index);
        }
        self.open = Some(OpenPass {
            pass: pass.forget_lifetime(),
            target: target.clone(),
            state: PassState::default(),
            counts: slot.is_some(),
        });
    }

    /// Starts counting samples: every render pass from the next one on counts into a slot
    /// of a new query set.
    pub(crate) fn begin_occlusion(&mut self, gpu: &Gpu) {
        self.end_pass();
        let set = gpu.device.create_query_set(&wgpu::QuerySetDescriptor {
            label: Some("essl-gl occlusion query"),
            ty: wgpu::QueryType::Occlusion,
            count: OCCLUSION_SLOTS,
        });
        self.occlusion = Some(Occlusion { set, next: 0 });
    }

    /// Stops counting samples, and records the copy of the counts into a buffer that
    /// [`Frame::any_samples`] reads once the batch has run.
    pub(crate) fn end_occlusion(&mut self, gpu: &Gpu) -> OcclusionCounts {
        self.end_pass();
        let occlusion = self.occlusion.take();
        let slots = occlusion.as_ref().map_or(0, |o| o.next);
        let size = 8 * slots.max(1) as u64;
        let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("essl-gl occlusion result"),
            size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        if let (Some(o), true) = (occlusion, slots > 0) {
            let resolve = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("essl-gl occlusion counts"),
                size,
                usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            });
            let encoder = self.commands(gpu);
            encoder.resolve_query_set(&o.set, 0..slots, &resolve, 0);
            encoder.copy_buffer_to_buffer(&resolve, 0, &buffer, 0, size);
        }
        OcclusionCounts { buffer, slots }
    }

    /// Whether any pass counted a sample: submits the batch if it holds anything (the copy
    /// of the counts among it) and waits for the GPU.
    pub(crate) fn any_samples(&mut self, gpu: &Gpu, counts: &OcclusionCounts) -> bool {
        if counts.slots == 0 {
            return false;
        }
        if !self.is_empty() {
            self.submit(gpu, |_| {});
        }
        let slice = counts.buffer.slice(..8 * counts.slots as u64);
        let counts_read: Vec<u64> = match gpu.read_mapped(slice) {
            Some(view) => bytemuck::pod_collect_to_vec(&view[..]),
            None => Vec::new(),
        };
        counts.buffer.unmap();
        counts_read.iter().any(|&c| c > 0)
    }

    /// Submits the batch: the arena is uploaded, `extra` records commands after the batch's
    /// (a readback's copy).
    pub(crate) fn submit(
        &mut self,
        gpu: &Gpu,
        extra: impl FnOnce(&mut wgpu::CommandEncoder),
    ) -> wgpu::SubmissionIndex {
        self.end_pass();
        extra(self.encoder(gpu));
        self.arena.upload(&gpu.queue);
        let encoder = self.encoder.take().expect("made above");
        let index = gpu.queue.submit([encoder.finish()]);
        self.serial += 1;
        index
    }

    /// Whether anything is waiting to be submitted.
    pub(crate) fn is_empty(&self) -> bool {
        self.encoder.is_none()
    }
}
