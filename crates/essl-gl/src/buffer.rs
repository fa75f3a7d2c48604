//! Buffer objects: `create_buffer`, `bind_buffer`, `buffer_data`, `buffer_sub_data`, …
//!
//! Every buffer keeps a CPU copy of its contents: WebGL's draw-time checks (a vertex or an
//! index past a buffer's end) read it, `get_buffer_sub_data` answers from it, and the GPU copy
//! is brought up to date lazily, when a draw uses the buffer.

use std::ops::Range;

use crate::bindings::BufferRange;
use crate::context::{Context, MAX_UNIFORM_BUFFER_BINDINGS};
use crate::gl;
use crate::gpu::Gpu;
use crate::objects::{Buffer, Id};

/// Bytes of zeros after a buffer's contents on the GPU, so that a vertex format wider than the
/// data it reads (a 3-component byte attribute read as 4 components) stays in bounds.
pub(crate) const GPU_PADDING: u64 = 16;

/// What a buffer may be bound to, fixed by its first binding (WebGL's buffer type).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum BufferKind {
    /// Bound to `ELEMENT_ARRAY_BUFFER` first: only indices.
    Element,
    /// Bound to any other target first.
    Other,
}

/// The GPU copy of a buffer.
pub(crate) struct GpuBuffer {
    pub(crate) buffer: wgpu::Buffer,
    /// The batch (see `Frame::serial`) that last used it: it may not be written in place
    /// while that batch is being recorded.
    pub(crate) last_batch: u64,
}

/// A buffer derived from a buffer's contents (8-bit indices widened to 16 bits, a vertex
/// attribute re-packed for wgpu's alignment rules), valid for one version of the contents.
pub(crate) struct Derived {
    pub(crate) key: DerivedKey,
    pub(crate) version: u64,
    pub(crate) buffer: wgpu::Buffer,
}

/// What a [`Derived`] buffer holds.
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

/// An index range of a version of a buffer: (type, offset, count, version).
pub(crate) type IndexRange = (u32, u64, u64, u64);

/// A buffer object.
pub(crate) struct BufferObject {
    pub(crate) data: Vec<u8>,
    pub(crate) usage: u32,
    pub(crate) kind: Option<BufferKind>,
    /// Bumped on every change of the contents.
    pub(crate) version: u64,
    pub(crate) gpu: Option<GpuBuffer>,
    /// The bytes that changed since the GPU copy was last written.
    pub(crate) dirty: Option<Range<usize>>,
    pub(crate) derived: Vec<Derived>,
    /// The last index range scanned, its largest index (restart excluded), and whether it
    /// holds the restart index.
    pub(crate) max_index_cache: Option<(IndexRange, Option<u32>, bool)>,
    /// Whether the GPU copy holds newer bytes than `data` (transform feedback wrote it):
    /// [`Context::buffer_to_cpu`] brings them back before the CPU copy is read or written.
    pub(crate) gpu_newer: bool,
}

impl BufferObject {
    fn new() -> Self {
        BufferObject {
            data: Vec::new(),
            usage: gl::STATIC_DRAW,
            kind: None,
            version: 0,
            gpu: None,
            dirty: None,
            derived: Vec::new(),
            max_index_cache: None,
            gpu_newer: false,
        }
    }

    pub(crate) fn mark_dirty(&mut self, range: Range<usize>) {
        self.version += 1;
        self.dirty = Some(match self.dirty.take() {
            Some(d) => d.start.min(range.start)..d.end.max(range.end),
            None => range,
        });
    }

    /// The GPU copy, brought up to date. Writes in place unless the current batch (`serial`)
    /// already uses the old contents, in which case a new GPU buffer replaces it (the pending
    /// commands keep the old one alive), so draws keep GL's order without a submit.
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

    /// A derived buffer for the current contents, made by `make` when missing or stale.
    pub(crate) fn derived(
        &mut self,
        gpu: &Gpu,
        key: DerivedKey,
        make: impl FnOnce(&[u8]) -> Vec<u8>,
    ) -> wgpu::Buffer {
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
}

/// The size of a buffer's GPU copy: its contents, [`GPU_PADDING`], a multiple of 4.
pub(crate) fn padded_size(len: u64) -> u64 {
    (len + GPU_PADDING).div_ceil(4) * 4
}

/// A vertex, index and uniform buffer of `size` bytes starting with `data`.
pub(crate) fn create_buffer_init(gpu: &Gpu, data: &[u8], size: u64, label: &str) -> wgpu::Buffer {
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

fn is_usage(usage: u32) -> bool {
    matches!(
        usage,
        gl::STREAM_DRAW
            | gl::STREAM_READ
            | gl::STREAM_COPY
            | gl::STATIC_DRAW
            | gl::STATIC_READ
            | gl::STATIC_COPY
            | gl::DYNAMIC_DRAW
            | gl::DYNAMIC_READ
            | gl::DYNAMIC_COPY
    )
}

impl Context {
    /// Creates a buffer object (`createBuffer`).
    pub fn create_buffer(&mut self) -> Buffer {
        Buffer {
            ctx: self.id,
            id: self.objects.buffers.insert(BufferObject::new()),
        }
    }

    /// Whether `buffer` names a live buffer that has been bound at least once (`isBuffer`).
    pub fn is_buffer(&self, buffer: Buffer) -> bool {
        buffer.ctx == self.id
            && self
                .objects
                .buffers
                .get(buffer.id)
                .is_some_and(|b| b.kind.is_some())
    }

    /// The id behind a handle, recording `INVALID_OPERATION` for a foreign or deleted one.
    pub(crate) fn buffer_id(&mut self, buffer: Buffer, function: &str) -> Option<Id> {
        if !self.owns(buffer.ctx, function) {
            return None;
        }
        if !self.objects.buffers.is_live(buffer.id) {
            self.error(gl::INVALID_OPERATION, function, "deleted buffer");
            return None;
        }
        Some(buffer.id)
    }

    /// The buffer bound to `target`, or the error WebGL records: `INVALID_ENUM` for an unknown
    /// target, `INVALID_OPERATION` for none bound.
    pub(crate) fn bound_buffer(&self, target: u32, function: &str) -> Option<Id> {
        let bound = match target {
            gl::ELEMENT_ARRAY_BUFFER => self.vao().element_buffer,
            gl::ARRAY_BUFFER
            | gl::COPY_READ_BUFFER
            | gl::COPY_WRITE_BUFFER
            | gl::UNIFORM_BUFFER
            | gl::PIXEL_PACK_BUFFER
            | gl::PIXEL_UNPACK_BUFFER
            | gl::TRANSFORM_FEEDBACK_BUFFER => self.bindings.buffer(target),
            _ => {
                self.error(
                    gl::INVALID_ENUM,
                    function,
                    format_args!("target 0x{target:04X}"),
                );
                return None;
            }
        };
        if bound.is_none() {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "no buffer bound to the target",
            );
        }
        bound
    }

    /// Binds a buffer to a target (`bindBuffer`): `ARRAY_BUFFER`, `ELEMENT_ARRAY_BUFFER` (state
    /// of the bound vertex array, as in GL), `COPY_READ_BUFFER`, `COPY_WRITE_BUFFER`,
    /// `UNIFORM_BUFFER`, `PIXEL_PACK_BUFFER`, `PIXEL_UNPACK_BUFFER`,
    /// `TRANSFORM_FEEDBACK_BUFFER`. `None` unbinds.
    ///
    /// As WebGL requires, a buffer first bound to `ELEMENT_ARRAY_BUFFER` cannot later be bound
    /// to a target for other data, and the reverse (`INVALID_OPERATION`).
    pub fn bind_buffer(&mut self, target: u32, buffer: Option<Buffer>) {
        self.bind_buffer_checked(target, buffer, "bindBuffer");
    }

    /// [`Context::bind_buffer`], saying whether it succeeded.
    fn bind_buffer_checked(&mut self, target: u32, buffer: Option<Buffer>, function: &str) -> bool {
        let kind = match target {
            gl::ELEMENT_ARRAY_BUFFER => Some(BufferKind::Element),
            gl::ARRAY_BUFFER
            | gl::UNIFORM_BUFFER
            | gl::PIXEL_PACK_BUFFER
            | gl::PIXEL_UNPACK_BUFFER
            | gl::TRANSFORM_FEEDBACK_BUFFER => Some(BufferKind::Other),
            gl::COPY_READ_BUFFER | gl::COPY_WRITE_BUFFER => None,
            _ => {
                self.error(
                    gl::INVALID_ENUM,
                    function,
                    format_args!("target 0x{target:04X}"),
                );
                return false;
            }
        };
        let id = match buffer {
            Some(b) => match self.buffer_id(b, function) {
                Some(id) => Some(id),
                None => return false,
            },
            None => None,
        };
        if let Some(id) = id {
            let obj = self.objects.buffers.get_mut(id).expect("live");
            match (obj.kind, kind) {
                (None, k) => obj.kind = Some(k.unwrap_or(BufferKind::Other)),
                (Some(have), Some(want)) if have != want => {
                    let msg = "a buffer cannot hold both indices and other data (WebGL)";
                    self.error(gl::INVALID_OPERATION, function, msg);
                    return false;
                }
                _ => {}
            }
        }
        if target == gl::ELEMENT_ARRAY_BUFFER {
            let vao = self.bindings.vertex_array();
            self.objects.set_element_buffer(vao, id);
        } else {
            self.bindings.bind_buffer(target, id);
        }
        true
    }

    /// Creates the data store of the buffer bound to `target` from `data` (`bufferData`).
    /// `usage` must be one of the nine `*_DRAW`/`*_READ`/`*_COPY` hints (`INVALID_ENUM`).
    pub fn buffer_data<T: bytemuck::NoUninit>(&mut self, target: u32, data: &[T], usage: u32) {
        self.buffer_data_impl(target, bytemuck::cast_slice(data), None, usage);
    }

    /// Creates a zero-filled data store of `size` bytes (`bufferData(target, size, usage)`);
    /// a negative size → `INVALID_VALUE`.
    pub fn buffer_data_size(&mut self, target: u32, size: i64, usage: u32) {
        if size < 0 {
            return self.error(gl::INVALID_VALUE, "bufferData", "negative size");
        }
        self.buffer_data_impl(target, &[], Some(size as usize), usage);
    }

    fn buffer_data_impl(&mut self, target: u32, data: &[u8], size: Option<usize>, usage: u32) {
        const F: &str = "bufferData";
        let Some(id) = self.bound_buffer(target, F) else {
            return;
        };
        if !is_usage(usage) {
            return self.error(gl::INVALID_ENUM, F, format_args!("usage 0x{usage:04X}"));
        }
        let b = self
            .objects
            .buffers
            .get_any_mut(id)
            .expect("bound buffers are alive");
        b.data = match size {
            Some(n) => vec![0; n],
            None => data.to_vec(),
        };
        b.gpu_newer = false;
        b.usage = usage;
        let len = b.data.len();
        b.mark_dirty(0..len);
    }

    /// Replaces bytes `dst_byte_offset..` of the buffer bound to `target` (`bufferSubData`).
    /// A negative offset or data past the end → `INVALID_VALUE`.
    pub fn buffer_sub_data<T: bytemuck::NoUninit>(
        &mut self,
        target: u32,
        dst_byte_offset: i64,
        data: &[T],
    ) {
        const F: &str = "bufferSubData";
        let bytes: &[u8] = bytemuck::cast_slice(data);
        let Some(id) = self.bound_buffer(target, F) else {
            return;
        };
        self.buffer_to_cpu(id);
        let b = self
            .objects
            .buffers
            .get_any_mut(id)
            .expect("bound buffers are alive");
        let Some(range) = byte_range(dst_byte_offset, bytes.len(), b.data.len()) else {
            return self.error(gl::INVALID_VALUE, F, "range outside the buffer");
        };
        b.data[range.clone()].copy_from_slice(bytes);
        b.mark_dirty(range);
    }

    /// Reads bytes `src_byte_offset..` of the buffer bound to `target` into `dst`
    /// (`getBufferSubData`). A range past the end → `INVALID_VALUE`.
    pub fn get_buffer_sub_data<T: bytemuck::AnyBitPattern + bytemuck::NoUninit>(
        &mut self,
        target: u32,
        src_byte_offset: i64,
        dst: &mut [T],
    ) {
        const F: &str = "getBufferSubData";
        let dst: &mut [u8] = bytemuck::cast_slice_mut(dst);
        let Some(id) = self.bound_buffer(target, F) else {
            return;
        };
        self.buffer_to_cpu(id);
        let b = self
            .objects
            .buffers
            .get_any(id)
            .expect("bound buffers are alive");
        let Some(range) = byte_range(src_byte_offset, dst.len(), b.data.len()) else {
            return self.error(gl::INVALID_VALUE, F, "range outside the buffer");
        };
        dst.copy_from_slice(&b.data[range]);
    }

    /// Copies `size` bytes between the buffers bound to two targets (`copyBufferSubData`).
    /// Ranges past an end, negative values, or overlapping ranges of one buffer →
    /// `INVALID_VALUE`; an index buffer and a data buffer → `INVALID_OPERATION` (WebGL).
    pub fn copy_buffer_sub_data(
        &mut self,
        read_target: u32,
        write_target: u32,
        read_offset: i64,
        write_offset: i64,
        size: i64,
    ) {
        const F: &str = "copyBufferSubData";
        let Some(src) = self.bound_buffer(read_target, F) else {
            return;
        };
        let Some(dst) = self.bound_buffer(write_target, F) else {
            return;
        };
        if size < 0 {
            return self.error(gl::INVALID_VALUE, F, "negative size");
        }
        self.buffer_to_cpu(src);
        self.buffer_to_cpu(dst);
        let (src_kind, src_len) = {
            let b = self.objects.buffers.get_any(src).expect("bound");
            (b.kind, b.data.len())
        };
        let (dst_kind, dst_len) = {
            let b = self.objects.buffers.get_any(dst).expect("bound");
            (b.kind, b.data.len())
        };
        let (Some(r), Some(w)) = (
            byte_range(read_offset, size as usize, src_len),
            byte_range(write_offset, size as usize, dst_len),
        ) else {
            return self.error(gl::INVALID_VALUE, F, "range outside a buffer");
        };
        if src == dst && r.start < w.end && w.start < r.end {
            return self.error(gl::INVALID_VALUE, F, "overlapping ranges");
        }
        if src_kind.is_some() && dst_kind.is_some() && src_kind != dst_kind {
            return self.error(gl::INVALID_OPERATION, F, "index and non-index buffers");
        }
        let bytes = self.objects.buffers.get_any(src).expect("bound").data[r].to_vec();
        let b = self.objects.buffers.get_any_mut(dst).expect("bound");
        b.data[w.clone()].copy_from_slice(&bytes);
        b.mark_dirty(w);
    }

    /// Deletes a buffer (`deleteBuffer`). It is unbound from this context's targets and from
    /// the bound vertex array; other vertex arrays that use it keep it alive, as in GL.
    /// Deleting a deleted buffer does nothing.
    pub fn delete_buffer(&mut self, buffer: Buffer) {
        if !self.owns(buffer.ctx, "deleteBuffer") || !self.objects.buffers.is_live(buffer.id) {
            return;
        }
        self.bindings.forget_buffer(buffer.id);
        let vao = self.bindings.vertex_array();
        let tf = self.bindings.transform_feedback();
        self.objects.delete_buffer(buffer.id, vao, tf);
    }

    /// Binds a whole buffer to indexed binding point `index` of `UNIFORM_BUFFER` or
    /// `TRANSFORM_FEEDBACK_BUFFER` (and to the generic binding) (`bindBufferBase`). An index
    /// ≥ `MAX_UNIFORM_BUFFER_BINDINGS` (or `MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS`) →
    /// `INVALID_VALUE`.
    pub fn bind_buffer_base(&mut self, target: u32, index: u32, buffer: Option<Buffer>) {
        self.bind_buffer_indexed(target, index, buffer, 0, None, "bindBufferBase");
    }

    /// Binds `size` bytes from `offset` of a buffer to indexed binding point `index` of
    /// `UNIFORM_BUFFER` (`bindBufferRange`). `offset` must be a multiple of
    /// `UNIFORM_BUFFER_OFFSET_ALIGNMENT` and `size` positive (`INVALID_VALUE`).
    pub fn bind_buffer_range(
        &mut self,
        target: u32,
        index: u32,
        buffer: Option<Buffer>,
        offset: i64,
        size: i64,
    ) {
        const F: &str = "bindBufferRange";
        if buffer.is_some() {
            if offset < 0 || size <= 0 {
                return self.error(gl::INVALID_VALUE, F, "negative offset or size ≤ 0");
            }
            let align = self.uniform_buffer_offset_alignment() as i64;
            if target == gl::UNIFORM_BUFFER && offset % align != 0 {
                let msg = format!(
                    "offset is not a multiple of UNIFORM_BUFFER_OFFSET_ALIGNMENT ({align})"
                );
                return self.error(gl::INVALID_VALUE, F, msg);
            }
        }
        self.bind_buffer_indexed(
            target,
            index,
            buffer,
            offset.max(0) as u64,
            Some(size.max(0) as u64),
            F,
        );
    }

    /// `UNIFORM_BUFFER_OFFSET_ALIGNMENT`: the device's uniform offset alignment.
    pub fn uniform_buffer_offset_alignment(&self) -> u32 {
        self.gpu.limits.min_uniform_buffer_offset_alignment
    }

    fn bind_buffer_indexed(
        &mut self,
        target: u32,
        index: u32,
        buffer: Option<Buffer>,
        offset: u64,
        size: Option<u64>,
        function: &str,
    ) {
        let range = buffer.map(|b| BufferRange {
            buffer: b.id,
            offset,
            size,
        });
        match target {
            gl::UNIFORM_BUFFER => {}
            gl::TRANSFORM_FEEDBACK_BUFFER => {
                if buffer.is_none()
                    || self.bind_buffer_checked(gl::TRANSFORM_FEEDBACK_BUFFER, buffer, function)
                {
                    self.bind_feedback_buffer(index, range, function);
                }
                return;
            }
            _ => {
                return self.error(
                    gl::INVALID_ENUM,
                    function,
                    format_args!("target 0x{target:04X}"),
                )
            }
        }
        if index >= MAX_UNIFORM_BUFFER_BINDINGS {
            return self.error(
                gl::INVALID_VALUE,
                function,
                "index ≥ MAX_UNIFORM_BUFFER_BINDINGS",
            );
        }
        // Also binds the generic binding point, with bind_buffer's checks.
        if self.bind_buffer_checked(gl::UNIFORM_BUFFER, buffer, function) {
            self.bindings.bind_uniform_range(index as usize, range);
        }
    }

    /// The size in bytes of the buffer bound to `target` (`getBufferParameter(BUFFER_SIZE)`).
    pub fn get_buffer_size(&self, target: u32) -> Option<u64> {
        let id = self.bound_buffer(target, "getBufferParameter")?;
        self.objects
            .buffers
            .get_any(id)
            .map(|b| b.data.len() as u64)
    }
}

/// `offset..offset + len` if it lies in `0..size`.
pub(crate) fn byte_range(offset: i64, len: usize, size: usize) -> Option<Range<usize>> {
    let start = usize::try_from(offset).ok()?;
    let end = start.checked_add(len)?;
    (end <= size).then_some(start..end)
}

impl Context {
    /// Brings a buffer's GPU-written bytes back into its CPU copy (submitting the batch and
    /// waiting), so that the CPU copy can be read or changed.
    pub(crate) fn buffer_to_cpu(&mut self, id: Id) {
        let Some(b) = self.objects.buffers.get_any(id) else {
            return;
        };
        let (true, Some(g)) = (b.gpu_newer, &b.gpu) else {
            return;
        };
        let gpu_buffer = g.buffer.clone();
        let len = b.data.len() as u64;
        let size = len.div_ceil(4) * 4;
        if size > 0 {
            let staging = self.gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("essl-gl buffer readback"),
                size,
                usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                mapped_at_creation: false,
            });
            self.frame.submit(&self.gpu, |encoder| {
                encoder.copy_buffer_to_buffer(&gpu_buffer, 0, &staging, 0, size);
            });
            let slice = staging.slice(..);
            let (tx, rx) = std::sync::mpsc::channel();
            slice.map_async(wgpu::MapMode::Read, move |r| {
                let _ = tx.send(r);
            });
            let _ = self.gpu.device.poll(wgpu::PollType::wait_indefinitely());
            if let (Ok(Ok(())), Ok(view)) = (rx.recv(), slice.get_mapped_range()) {
                let b = self.objects.buffers.get_any_mut(id).expect("checked");
                b.data.copy_from_slice(&view[..len as usize]);
            }
        }
        let b = self.objects.buffers.get_any_mut(id).expect("checked");
        b.gpu_newer = false;
        b.dirty = None;
        b.version += 1;
        b.derived.clear();
    }
}
