//! Buffer objects: `create_buffer`, `bind_buffer`, `buffer_data`, `buffer_sub_data`, …
//!
//! Every buffer keeps a CPU copy of its contents and a GPU copy, which [`BufferObject`] (in
//! [`object`]) keeps in step: these methods check WebGL's rules and leave the copies to it.

mod object;

pub(crate) use object::{
    index_size, read_indices, BufferKind, BufferObject, BufferRange, DerivedKey,
};

use std::ops::Range;

use crate::context::{Context, MAX_UNIFORM_BUFFER_BINDINGS};
use crate::gl;
use crate::objects::{Buffer, Id};

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
                .is_some_and(|b| b.kind().is_some())
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

    /// [`Context::bound_buffer`] for an operation on the data: `INVALID_OPERATION` too when the
    /// buffer is bound for transform feedback and at another binding point.
    fn data_buffer(&mut self, target: u32, function: &str) -> Option<Id> {
        let id = self.bound_buffer(target, function)?;
        (!self.refuse_double_bound(id, function)).then_some(id)
    }

    /// Binds a buffer to a target (`bindBuffer`): `ARRAY_BUFFER`, `ELEMENT_ARRAY_BUFFER` (state
    /// of the bound vertex array, as in GL), `COPY_READ_BUFFER`, `COPY_WRITE_BUFFER`,
    /// `UNIFORM_BUFFER`, `PIXEL_PACK_BUFFER`, `PIXEL_UNPACK_BUFFER`,
    /// `TRANSFORM_FEEDBACK_BUFFER`. `None` unbinds.
    ///
    /// As WebGL requires, a buffer first bound to `ELEMENT_ARRAY_BUFFER` cannot later be bound
    /// to a target for other data, and the reverse (`INVALID_OPERATION`).
    pub fn bind_buffer(&mut self, target: u32, buffer: Option<Buffer>) {
        if self.webgl1_refuses("bindBuffer", &[target]) {
            return;
        }
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
            if !self
                .objects
                .buffers
                .get_mut(id)
                .expect("live")
                .bind_as(kind)
            {
                let msg = "a buffer cannot hold both indices and other data (WebGL)";
                self.error(gl::INVALID_OPERATION, function, msg);
                return false;
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
        let Some(id) = self.data_buffer(target, F) else {
            return;
        };
        if !is_usage(usage) {
            return self.error(gl::INVALID_ENUM, F, format_args!("usage 0x{usage:04X}"));
        }
        let data = match size {
            Some(n) => vec![0; n],
            None => data.to_vec(),
        };
        self.objects
            .buffers
            .get_any_mut(id)
            .expect("bound buffers are alive")
            .replace(data, usage);
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
        let Some(id) = self.data_buffer(target, F) else {
            return;
        };
        let b = self
            .objects
            .buffers
            .get_any_mut(id)
            .expect("bound buffers are alive");
        let Some(range) = byte_range(dst_byte_offset, bytes.len(), b.len()) else {
            return self.error(gl::INVALID_VALUE, F, "range outside the buffer");
        };
        b.write(&self.gpu, &mut self.frame, range.start, bytes);
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
        let Some(id) = self.data_buffer(target, F) else {
            return;
        };
        let b = self
            .objects
            .buffers
            .get_any_mut(id)
            .expect("bound buffers are alive");
        let Some(range) = byte_range(src_byte_offset, dst.len(), b.len()) else {
            return self.error(gl::INVALID_VALUE, F, "range outside the buffer");
        };
        dst.copy_from_slice(&b.cpu_bytes(&self.gpu, &mut self.frame)[range]);
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
        let Some(src) = self.data_buffer(read_target, F) else {
            return;
        };
        let Some(dst) = self.data_buffer(write_target, F) else {
            return;
        };
        if size < 0 {
            return self.error(gl::INVALID_VALUE, F, "negative size");
        }
        let (src_kind, src_len) = {
            let b = self.objects.buffers.get_any(src).expect("bound");
            (b.kind(), b.len())
        };
        let (dst_kind, dst_len) = {
            let b = self.objects.buffers.get_any(dst).expect("bound");
            (b.kind(), b.len())
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
        let (gpu, frame) = (&self.gpu, &mut self.frame);
        let src = self.objects.buffers.get_any_mut(src).expect("bound");
        let bytes = src.cpu_bytes(gpu, frame)[r].to_vec();
        let dst = self.objects.buffers.get_any_mut(dst).expect("bound");
        dst.write(gpu, frame, w.start, &bytes);
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
        self.objects.buffers.get_any(id).map(|b| b.len() as u64)
    }
}

/// `offset..offset + len` if it lies in `0..size`.
pub(crate) fn byte_range(offset: i64, len: usize, size: usize) -> Option<Range<usize>> {
    let start = usize::try_from(offset).ok()?;
    let end = start.checked_add(len)?;
    (end <= size).then_some(start..end)
}
