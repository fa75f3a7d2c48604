//! Batching: the command encoder and render pass that draws are recorded into, the pending
//! clears, and the per-batch arena for uniforms, constant attributes and generated indices.
//!
//! GL executes commands in order; wgpu executes a command buffer after the queue writes made
//! before its submission. Draws are therefore recorded into one open render pass and
//! submitted together ("a batch") only when the results are needed: resources a batch uses
//! are never written in place while it is open (buffers and textures are replaced instead,
//! and per-draw data goes to the arena, which is written just before the submit).

use crate::context::{Context, DefaultFramebuffer, Gpu};

/// Bytes of one arena chunk (larger allocations get a chunk of their own size).
const CHUNK_SIZE: u64 = 1 << 18;

/// One GPU buffer of the arena and the bytes it will receive at the next submit.
pub(crate) struct Chunk {
    /// Unique within the arena, so bind groups made for a chunk can be cached by it.
    pub(crate) id: u64,
    pub(crate) buffer: wgpu::Buffer,
    data: Vec<u8>,
}

/// A linear allocator of per-draw data, uploaded at each submit.
pub(crate) struct Arena {
    pub(crate) chunks: Vec<Chunk>,
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

/// Dynamic state already set in the open render pass.
#[derive(Default)]
pub(crate) struct PassState {
    pub(crate) pipeline: Option<u64>,
    pub(crate) viewport: Option<[u32; 6]>,
    pub(crate) scissor: Option<[u32; 4]>,
    pub(crate) blend_constant: Option<[u32; 4]>,
    pub(crate) group0: Option<(wgpu::BindGroup, Option<u32>)>,
    pub(crate) group1: Option<wgpu::BindGroup>,
    pub(crate) vertex_buffers: Vec<Option<(wgpu::Buffer, u64)>>,
    pub(crate) index_buffer: Option<(wgpu::Buffer, u64, wgpu::IndexFormat)>,
}

/// The batch being recorded.
pub(crate) struct Frame {
    /// Identifies the batch; bumped at every submit.
    pub(crate) serial: u64,
    encoder: Option<wgpu::CommandEncoder>,
    pub(crate) pass: Option<wgpu::RenderPass<'static>>,
    pub(crate) pass_state: PassState,
    pending_color: Option<wgpu::Color>,
    pending_depth: Option<f32>,
    pub(crate) arena: Arena,
    /// Draws recorded in the batch (for statistics).
    pub(crate) draws: u64,
}

impl Frame {
    pub(crate) fn new(_gpu: &Gpu) -> Self {
        Frame {
            serial: 1,
            encoder: None,
            pass: None,
            pass_state: PassState::default(),
            pending_color: None,
            pending_depth: None,
            arena: Arena::new(),
            draws: 0,
        }
    }

    fn encoder(&mut self, gpu: &Gpu) -> &mut wgpu::CommandEncoder {
        self.encoder.get_or_insert_with(|| {
            gpu.device
                .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("essl-gl batch"),
                })
        })
    }

    /// Ends the open render pass, if any.
    pub(crate) fn end_pass(&mut self) {
        self.pass = None;
    }

    /// The open render pass on the default framebuffer, beginning one (with the pending
    /// clears as load operations) if needed.
    pub(crate) fn pass(
        &mut self,
        gpu: &Gpu,
        fb: &DefaultFramebuffer,
    ) -> &mut wgpu::RenderPass<'static> {
        if self.pass.is_none() {
            let color = self.pending_color.take();
            let depth = self.pending_depth.take();
            let encoder = self.encoder(gpu);
            let pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("essl-gl pass"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &fb.color_view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: color.map_or(wgpu::LoadOp::Load, wgpu::LoadOp::Clear),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &fb.depth_view,
                    depth_ops: Some(wgpu::Operations {
                        load: depth.map_or(wgpu::LoadOp::Load, wgpu::LoadOp::Clear),
                        store: wgpu::StoreOp::Store,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            self.pass = Some(pass.forget_lifetime());
            self.pass_state = PassState::default();
        }
        self.pass.as_mut().expect("just opened")
    }

    /// Records a clear of whole attachments: it becomes the load operation of the next pass.
    pub(crate) fn clear(&mut self, color: Option<wgpu::Color>, depth: Option<f32>) {
        self.end_pass();
        if color.is_some() {
            self.pending_color = color;
        }
        if depth.is_some() {
            self.pending_depth = depth;
        }
    }

    /// Submits the batch: pending clears are applied, the arena is uploaded, `extra` records
    /// commands after the batch's (a readback's copy).
    pub(crate) fn submit(
        &mut self,
        gpu: &Gpu,
        fb: &DefaultFramebuffer,
        extra: impl FnOnce(&mut wgpu::CommandEncoder),
    ) -> wgpu::SubmissionIndex {
        if self.pending_color.is_some() || self.pending_depth.is_some() {
            self.pass(gpu, fb);
        }
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
        self.encoder.is_none() && self.pending_color.is_none() && self.pending_depth.is_none()
    }
}

impl Context {
    /// Submits the recorded commands to the GPU without waiting (`flush`).
    pub fn flush(&mut self) {
        if !self.frame.is_empty() {
            self.frame.submit(&self.gpu, &self.fb, |_| {});
        }
    }

    /// Submits the recorded commands and waits until the GPU has executed them (`finish`).
    pub fn finish(&mut self) {
        self.flush();
        let _ = self.gpu.device.poll(wgpu::PollType::wait_indefinitely());
    }
}
