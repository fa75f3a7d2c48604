//! The GPU objects a context renders with. Every part that creates or writes GPU resources
//! takes a [`Gpu`]; none of them needs the whole [`Context`](crate::Context).

/// The wgpu device and queue of a context, and what the adapter reported.
pub(crate) struct Gpu {
    pub(crate) device: wgpu::Device,
    pub(crate) queue: wgpu::Queue,
    pub(crate) info: wgpu::AdapterInfo,
    pub(crate) limits: wgpu::Limits,
}
