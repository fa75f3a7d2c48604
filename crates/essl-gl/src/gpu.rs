//! The GPU objects a context renders with. Every part that creates or writes GPU resources
//! takes a [`Gpu`]; none of them needs the whole [`Context`](crate::Context).

/// The wgpu device and queue of a context, and what the adapter reported.
pub(crate) struct Gpu {
    pub(crate) device: wgpu::Device,
    pub(crate) queue: wgpu::Queue,
    pub(crate) info: wgpu::AdapterInfo,
    pub(crate) limits: wgpu::Limits,
    /// What the adapter can do beyond WebGPU's baseline that no feature names (a clamped
    /// depth bias).
    pub(crate) downlevel: wgpu::DownlevelFlags,
}

impl Gpu {
    /// Maps `slice` for reading and waits for the GPU: a view of its bytes, `None` where
    /// mapping failed. The caller unmaps the buffer once the view is dropped, if it reuses it.
    pub(crate) fn read_mapped(&self, slice: wgpu::BufferSlice) -> Option<wgpu::BufferView> {
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        let _ = self.device.poll(wgpu::PollType::wait_indefinitely());
        rx.recv().ok()?.ok()?;
        slice.get_mapped_range().ok()
    }
}
