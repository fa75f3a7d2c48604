//! `ALIASED_POINT_SIZE_RANGE`'s upper bound: the largest point the device draws, measured.
//!
//! wgpu reports no point size limit (its WGSL has no point size at all); essl's lowering
//! writes `gl_PointSize` to Vulkan's `PointSize`, which devices honour up to their own
//! `pointSizeRange`. The bound is what one point of size 1024 covers on a 1024-texel row,
//! drawn once per context the first time it is asked for: an answer the device gives, not a
//! figure taken on trust. Where the probe cannot run, the bound is 1 (what every device draws).

use crate::gpu::Gpu;

/// The size the probe asks for, and the row it is drawn on.
const PROBE: u32 = 1024;

/// The largest point size the device draws, in pixels (at least 1).
pub(crate) fn largest_point(gpu: &Gpu) -> f32 {
    measure(gpu).map_or(1.0, |n| n.max(1) as f32)
}

fn measure(gpu: &Gpu) -> Option<u32> {
    let options = essl::CompileOptions::default();
    let source = |stage: essl::Stage, text: &str| {
        essl::compile(
            essl::source::SourceFile::new(stage.as_str(), text),
            stage,
            &options,
        )
    };
    let vs = source(
        essl::Stage::Vertex,
        "#version 300 es\nvoid main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); gl_PointSize = 1024.0; }",
    );
    let fs = source(
        essl::Stage::Fragment,
        "#version 300 es\nprecision mediump float; out vec4 c; void main() { c = vec4(1.0); }",
    );
    let linked = essl::link::link(&vs, &fs);
    if !linked.ok {
        return None;
    }
    let layout = essl::lower::lower_program(&vs, &fs, &linked, &crate::LOWER_OPTIONS).ok()?;
    let device = &gpu.device;
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let vertex = crate::pipeline::create_module(gpu, layout.vertex, "point size probe").ok()?;
    let fragment = crate::pipeline::create_module(gpu, layout.fragment, "point size probe").ok()?;
    let format = wgpu::TextureFormat::Rgba8Unorm;
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("point size probe"),
        layout: None,
        vertex: wgpu::VertexState {
            module: &vertex,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        primitive: wgpu::PrimitiveState {
            topology: wgpu::PrimitiveTopology::PointList,
            ..Default::default()
        },
        depth_stencil: None,
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &fragment,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            targets: &[Some(format.into())],
        }),
        multiview_mask: None,
        cache: None,
    });
    let target = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("point size probe"),
        size: wgpu::Extent3d {
            width: PROBE,
            height: 1,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let bytes = u64::from(PROBE) * 4;
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("point size probe"),
        size: bytes,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let view = target.create_view(&Default::default());
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("point size probe"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                    store: wgpu::StoreOp::Store,
                },
            })],
            ..Default::default()
        });
        pass.set_pipeline(&pipeline);
        pass.draw(0..1, 0..1);
    }
    encoder.copy_texture_to_buffer(
        target.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &readback,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(PROBE * 4),
                rows_per_image: None,
            },
        },
        target.size(),
    );
    gpu.queue.submit([encoder.finish()]);
    if pollster::block_on(scope.pop()).is_some() {
        return None;
    }
    let view = gpu.read_mapped(readback.slice(..))?;
    let lit = view.chunks_exact(4).filter(|px| px[0] > 127).count() as u32;
    Some(lit)
}
