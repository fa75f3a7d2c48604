//! A buffer object's contents, kept in two copies that the buffer alone keeps in step.
//!
//! The CPU copy answers WebGL's draw-time checks (a vertex or an index past the end),
//! `getBufferSubData`, and the conversions made on the CPU (8-bit indices widened, attributes
//! re-packed); the GPU copy is brought up to date when a draw uses the buffer. Transform
//! feedback writes only the GPU copy ([`BufferObject::mark_gpu_written`]): from then on every
//! read or write of the CPU copy ([`BufferObject::cpu_bytes`], [`BufferObject::write`],
//! [`BufferObject::derived`], [`BufferObject::index_range`]) first submits the batch and
//! copies the GPU's bytes back, so no caller reads stale bytes or writes over the GPU's.

use std::ops::Range;

use crate::frame::Frame;
use crate::gl;
use crate::gpu::Gpu;
use crate::objects::Id;

/// Bytes of zeros after a buffer's contents on the GPU, so that a vertex format wider than the
/// data it reads (a 3-component byte attribute read as 4 components) stays in bounds.
const GPU_PADDING: u64 = 16;

/// What a buffer may be bound to, fixed by its first binding (WebGL's buffer type).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum BufferKind {
    /// Bound to `ELEMENT_ARRAY_BUFFER` first: only indices.
    Element,
    /// Bound to any other target first.
    Other,
}

/// A range of a buffer bound to an indexed binding point (`bindBufferRange`; the whole buffer
/// for `bindBufferBase`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct BufferRange {
    pub(crate) buffer: Id,
    pub(crate) offset: u64,
    /// `None`: to the end of the buffer.
    pub(crate) size: Option<u64>,
}

/// What a buffer derived from a buffer's contents holds (see [`BufferObject::derived`]).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) enum DerivedKey {
    /// All of the buffer's bytes as 16-bit indices (`0xFF` becomes the restart index `0xFFFF`).
    WideIndices,
    /// One vertex attribute's elements, re-packed tightly.
    Repacked {
        /// Byte offset of element 0.
        offset: u64,
        /// GL's effective stride.
        stride: u64,
        /// Bytes of one element in the source.
        element: u64,
        /// Bytes of one element in the result (a multiple of 4).
        packed: u64,
        /// For an instanced attribute with divisor > 1: the divisor and the instance count;
        /// the result then holds one element per instance.
        per_instance: Option<(u32, u32)>,
    },
}

/// What a range of indices holds: its largest index, restart excluded (`None`: only
/// restarts), and whether it holds the restart index.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct IndexRange {
    pub(crate) max: Option<u32>,
    pub(crate) restarts: bool,
}

/// The GPU copy of a buffer.
struct GpuBuffer {
    buffer: wgpu::Buffer,
    /// The batch (see [`Frame::serial`]) that last used it: it may not be written in place
    /// while that batch is being recorded.
    last_batch: u64,
}

/// A buffer derived from one version of a buffer's contents.
struct Derived {
    key: DerivedKey,
    version: u64,
    buffer: wgpu::Buffer,
}

/// The last index range scanned: (type, offset, count, version) and what it holds.
type IndexScan = ((u32, u64, u64, u64), IndexRange);

/// A buffer object.
pub(crate) struct BufferObject {
    /// The CPU copy; stale while `gpu_newer`.
    data: Vec<u8>,
    usage: u32,
    kind: Option<BufferKind>,
    /// Bumped on every change of the contents: keys `derived` and `index_scan`.
    version: u64,
    gpu: Option<GpuBuffer>,
    /// The bytes of `data` that changed since the GPU copy was last written.
    dirty: Option<Range<usize>>,
    derived: Vec<Derived>,
    index_scan: Option<IndexScan>,
    /// Whether the GPU copy holds newer bytes than `data` (transform feedback wrote it).
    gpu_newer: bool,
}

impl BufferObject {
    /// A buffer with no data store, never bound.
    pub(crate) fn new() -> Self {
        BufferObject {
            data: Vec::new(),
            usage: gl::STATIC_DRAW,
            kind: None,
            version: 0,
            gpu: None,
            dirty: None,
            derived: Vec::new(),
            index_scan: None,
            gpu_newer: false,
        }
    }

    /// The size of the data store in bytes (`BUFFER_SIZE`), whichever copy is newer.
    pub(crate) fn len(&self) -> usize {
        self.data.len()
    }

    /// The usage hint of the last `bufferData` (`BUFFER_USAGE`).
    pub(crate) fn usage(&self) -> u32 {
        self.usage
    }

    /// What the buffer may be bound to; `None` until its first binding.
    pub(crate) fn kind(&self) -> Option<BufferKind> {
        self.kind
    }

    /// Fixes the kind at the first binding. `kind` is the target's: `None` for the copy
    /// targets, which take either kind (and make a new buffer [`BufferKind::Other`]).
    /// `false` when the buffer already has the other kind.
    pub(crate) fn bind_as(&mut self, kind: Option<BufferKind>) -> bool {
        match (self.kind, kind) {
            (None, k) => {
                self.kind = Some(k.unwrap_or(BufferKind::Other));
                true
            }
            (Some(have), Some(want)) => have == want,
            (Some(_), None) => true,
        }
    }

    /// A new data store (`bufferData`): what the GPU wrote into the old one is dropped.
    pub(crate) fn replace(&mut self, data: Vec<u8>, usage: u32) {
        self.data = data;
        self.usage = usage;
        self.gpu_newer = false;
        self.mark_dirty(0..self.data.len());
    }

    /// The contents, brought back from the GPU first if it wrote them.
    pub(crate) fn cpu_bytes(&mut self, gpu: &Gpu, frame: &mut Frame) -> &[u8] {
        self.sync_to_cpu(gpu, frame);
        &self.data
    }

    /// Replaces the bytes at `offset` with `bytes` (the caller has checked the range), after
    /// bringing the GPU's bytes back so that those around the range are kept.
    pub(crate) fn write(&mut self, gpu: &Gpu, frame: &mut Frame, offset: usize, bytes: &[u8]) {
        self.sync_to_cpu(gpu, frame);
        let range = offset..offset + bytes.len();
        self.data[range.clone()].copy_from_slice(bytes);
        self.mark_dirty(range);
    }

    /// What the `count` indices of type `ty` at byte `offset` hold; `None` when they run past
    /// the end. The last answer is kept for the same range and contents.
    pub(crate) fn index_range(
        &mut self,
        gpu: &Gpu,
        frame: &mut Frame,
        ty: u32,
        offset: u64,
        count: u64,
    ) -> Option<IndexRange> {
        let size = index_size(ty)?;
        if offset + count * size > self.data.len() as u64 {
            return None;
        }
        self.sync_to_cpu(gpu, frame);
        let key = (ty, offset, count, self.version);
        if let Some((k, range)) = self.index_scan {
            if k == key {
                return Some(range);
            }
        }
        let mut range = IndexRange {
            max: None,
            restarts: false,
        };
        for i in read_indices(&self.data, ty, offset, count) {
            if i == u32::MAX {
                range.restarts = true;
            } else {
                range.max = range.max.max(Some(i));
            }
        }
        self.index_scan = Some((key, range));
        Some(range)
    }

    /// The GPU copy, brought up to date, for the batch `serial`. Writes in place unless that
    /// batch already uses the old contents, in which case a new GPU buffer replaces it (the
    /// pending commands keep the old one alive), so draws keep GL's order without a submit.
    pub(crate) fn gpu_buffer(&mut self, gpu: &Gpu, serial: u64) -> wgpu::Buffer {
        // Written by the GPU: the GPU copy is the buffer, in the batch's order.
        if let (true, Some(g)) = (self.gpu_newer, &mut self.gpu) {
            g.last_batch = serial;
            return g.buffer.clone();
        }
        let padded = padded_size(self.data.len() as u64);
        let reusable =
            matches!(&self.gpu, Some(g) if g.buffer.size() == padded && g.last_batch != serial);
        if let (true, Some(g)) = (reusable, &mut self.gpu) {
            if let Some(range) = self.dirty.take() {
                // write_buffer wants 4-byte multiples; the GPU copy is padded past the data.
                let start = range.start & !3;
                let end = range.end.div_ceil(4) * 4;
                if end > start {
                    let mut chunk = vec![0u8; end - start];
                    let avail = self.data.len().min(end).saturating_sub(start);
                    chunk[..avail].copy_from_slice(&self.data[start..start + avail]);
                    gpu.queue.write_buffer(&g.buffer, start as u64, &chunk);
                }
            }
            g.last_batch = serial;
            return g.buffer.clone();
        }
        let buffer = create_buffer_init(gpu, &self.data, padded, "essl-gl buffer");
        self.gpu = Some(GpuBuffer {
            buffer: buffer.clone(),
            last_batch: serial,
        });
        self.dirty = None;
        buffer
    }

    /// The GPU copy, up to date, for a command of batch `serial` that writes it (transform
    /// feedback): from now on the GPU copy is the newer one.
    pub(crate) fn mark_gpu_written(&mut self, gpu: &Gpu, serial: u64) -> wgpu::Buffer {
        let buffer = self.gpu_buffer(gpu, serial);
        self.gpu_newer = true;
        self.version += 1;
        self.derived.clear();
        buffer
    }

    /// A buffer derived from the current contents, made by `make` when missing or stale.
    pub(crate) fn derived(
        &mut self,
        gpu: &Gpu,
        frame: &mut Frame,
        key: DerivedKey,
        make: impl FnOnce(&[u8]) -> Vec<u8>,
    ) -> wgpu::Buffer {
        self.sync_to_cpu(gpu, frame);
        if let Some(d) = self
            .derived
            .iter()
            .find(|d| d.key == key && d.version == self.version)
        {
            return d.buffer.clone();
        }
        let bytes = make(&self.data);
        let buffer = create_buffer_init(
            gpu,
            &bytes,
            padded_size(bytes.len() as u64),
            "essl-gl derived buffer",
        );
        self.derived
            .retain(|d| d.key != key && d.version == self.version);
        self.derived.push(Derived {
            key,
            version: self.version,
            buffer: buffer.clone(),
        });
        buffer
    }

    fn mark_dirty(&mut self, range: Range<usize>) {
        self.version += 1;
        self.dirty = Some(match self.dirty.take() {
            Some(d) => d.start.min(range.start)..d.end.max(range.end),
            None => range,
        });
    }

    /// Brings the GPU-written bytes back into the CPU copy (submitting the batch, which holds
    /// the writes, and waiting); nothing to do unless the GPU copy is newer.
    fn sync_to_cpu(&mut self, gpu: &Gpu, frame: &mut Frame) {
        let (true, Some(g)) = (self.gpu_newer, &self.gpu) else {
            return;
        };
        let len = self.data.len();
        let size = (len as u64).div_ceil(4) * 4;
        if size > 0 {
            let staging = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("essl-gl buffer readback"),
                size,
                usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                mapped_at_creation: false,
            });
            frame.submit(gpu, |encoder| {
                encoder.copy_buffer_to_buffer(&g.buffer, 0, &staging, 0, size);
            });
            if let Some(view) = gpu.read_mapped(staging.slice(..)) {
                self.data.copy_from_slice(&view[..len]);
            }
        }
        // The CPU copy now equals the GPU copy, whose contents `mark_gpu_written` versioned.
        self.gpu_newer = false;
        self.dirty = None;
    }
}

/// The size of a buffer's GPU copy: its contents, [`GPU_PADDING`], a multiple of 4.
fn padded_size(len: u64) -> u64 {
    (len + GPU_PADDING).div_ceil(4) * 4
}

/// A vertex, index and uniform buffer of `size` bytes starting with `data`.
fn create_buffer_init(gpu: &Gpu, data: &[u8], size: u64, label: &str) -> wgpu::Buffer {
    let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size,
        usage: wgpu::BufferUsages::VERTEX
            | wgpu::BufferUsages::INDEX
            | wgpu::BufferUsages::UNIFORM
            | wgpu::BufferUsages::STORAGE
            | wgpu::BufferUsages::COPY_SRC
            | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: true,
    });
    if !data.is_empty() {
        if let Ok(mut view) = buffer.slice(..).get_mapped_range_mut() {
            view.slice(..data.len()).copy_from_slice(data);
        }
    }
    buffer.unmap();
    buffer
}

/// The size in bytes of an index of type `ty`, or `None` for a type that is not one.
pub(crate) fn index_size(ty: u32) -> Option<u64> {
    match ty {
        gl::UNSIGNED_BYTE => Some(1),
        gl::UNSIGNED_SHORT => Some(2),
        gl::UNSIGNED_INT => Some(4),
        _ => None,
    }
}

/// Index `i` of `count` indices of type `ty` at `offset`, as `u32` (`u32::MAX` for the
/// primitive restart index, which WebGL2 always enables).
pub(crate) fn read_indices(
    data: &[u8],
    ty: u32,
    offset: u64,
    count: u64,
) -> impl Iterator<Item = u32> + '_ {
    let size = index_size(ty).unwrap_or(4) as usize;
    let start = offset as usize;
    data[start..start + count as usize * size]
        .chunks_exact(size)
        .map(move |c| match size {
            1 => {
                if c[0] == 0xFF {
                    u32::MAX
                } else {
                    c[0] as u32
                }
            }
            2 => {
                let v = u16::from_ne_bytes([c[0], c[1]]);
                if v == 0xFFFF {
                    u32::MAX
                } else {
                    v as u32
                }
            }
            _ => u32::from_ne_bytes([c[0], c[1], c[2], c[3]]),
        })
}
