//! The pipelines of clears that masks or the scissor box restrict: a full-screen triangle
//! whose fragment shader writes the clear value of each cleared draw buffer (float, signed
//! or unsigned, as the attachment takes), depth from the uniform block and stencil by the
//! reference value.

use super::{create_module, PipelineCache};
use crate::gpu::Gpu;

/// What a clear value is: what the attachment's format takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum ClearKind {
    Float,
    Int,
    Uint,
}

/// Everything a clear pipeline depends on.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct ClearKey {
    /// Per draw buffer: the attachment's format, the kind of the value it is cleared to
    /// (`None`: not cleared) and the channels written.
    pub(crate) colors: Vec<Option<(wgpu::TextureFormat, Option<ClearKind>, wgpu::ColorWrites)>>,
    pub(crate) depth: Option<wgpu::TextureFormat>,
    pub(crate) write_depth: bool,
    /// Stencil bits written (0: stencil untouched).
    pub(crate) stencil_mask: u32,
    pub(crate) samples: u32,
}

/// The WGSL of a clear: the uniform block holds depth in its first 16 bytes and the value of
/// draw buffer `i` in the 16 bytes after `16 * (i + 1)`.
fn source(key: &ClearKey) -> String {
    let mut outputs = Vec::new();
    let mut body = Vec::new();
    for (i, c) in key.colors.iter().enumerate() {
        let Some((_, Some(kind), _)) = c else {
            continue;
        };
        let (ty, value) = match kind {
            ClearKind::Float => (
                "vec4<f32>",
                format!("bitcast<vec4<f32>>(clear.values[{}])", i + 1),
            ),
            ClearKind::Int => (
                "vec4<i32>",
                format!("bitcast<vec4<i32>>(clear.values[{}])", i + 1),
            ),
            ClearKind::Uint => ("vec4<u32>", format!("clear.values[{}]", i + 1)),
        };
        outputs.push(format!("@location({i}) c{i}: {ty}"));
        body.push(format!("o.c{i} = {value};"));
    }
    let out_struct = if outputs.is_empty() {
        String::new()
    } else {
        format!("struct Out {{ {} }}", outputs.join(", "))
    };
    let fragment = if outputs.is_empty() {
        "@fragment fn fs() {}".to_owned()
    } else {
        format!(
            "@fragment fn fs() -> Out {{ var o: Out; {} return o; }}",
            body.join(" ")
        )
    };
    format!(
        "struct Clear {{ values: array<vec4<u32>, {n}> }}
         @group(0) @binding(0) var<uniform> clear: Clear;
         {out_struct}
         @vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {{
             let x = f32((i << 1u) & 2u) * 2.0 - 1.0;
             let y = f32(i & 2u) * 2.0 - 1.0;
             return vec4(x, y, bitcast<f32>(clear.values[0].x), 1.0);
         }}
         {fragment}",
        n = 1 + crate::MAX_COLOR_ATTACHMENTS
    )
}

impl PipelineCache {
    /// The pipeline for a masked or scissored clear.
    pub(crate) fn clear_pipeline(&mut self, gpu: &Gpu, key: &ClearKey) -> wgpu::RenderPipeline {
        if let Some(p) = self.clear.get(key) {
            return p.clone();
        }
        let module = naga::front::wgsl::parse_str(&source(key)).expect("the clear shader parses");
        let module =
            create_module(gpu, module, "essl-gl clear").expect("the clear shader is valid");
        let group0 = self.group0_layout(gpu, true, 0);
        let layout = gpu
            .device
            .create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("essl-gl clear"),
                bind_group_layouts: &[Some(&group0)],
                immediate_size: 0,
            });
        let targets: Vec<Option<wgpu::ColorTargetState>> = key
            .colors
            .iter()
            .map(|c| {
                c.map(|(format, kind, mask)| wgpu::ColorTargetState {
                    format,
                    blend: None,
                    write_mask: if kind.is_some() {
                        mask
                    } else {
                        wgpu::ColorWrites::empty()
                    },
                })
            })
            .collect();
        let stencil_face = wgpu::StencilFaceState {
            compare: wgpu::CompareFunction::Always,
            fail_op: wgpu::StencilOperation::Replace,
            depth_fail_op: wgpu::StencilOperation::Replace,
            pass_op: wgpu::StencilOperation::Replace,
        };
        let pipeline = gpu
            .device
            .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("essl-gl clear"),
                layout: Some(&layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs"),
                    compilation_options: Default::default(),
                    buffers: &[],
                },
                primitive: Default::default(),
                depth_stencil: key.depth.map(|format| wgpu::DepthStencilState {
                    format,
                    depth_write_enabled: Some(key.write_depth && format.has_depth_aspect()),
                    depth_compare: Some(wgpu::CompareFunction::Always),
                    stencil: if format.has_stencil_aspect() && key.stencil_mask != 0 {
                        wgpu::StencilState {
                            front: stencil_face,
                            back: stencil_face,
                            read_mask: 0xFF,
                            write_mask: key.stencil_mask,
                        }
                    } else {
                        wgpu::StencilState::default()
                    },
                    bias: Default::default(),
                }),
                multisample: wgpu::MultisampleState {
                    count: key.samples,
                    ..Default::default()
                },
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs"),
                    compilation_options: Default::default(),
                    targets: &targets,
                }),
                multiview_mask: None,
                cache: None,
            });
        self.clear.insert(key.clone(), pipeline.clone());
        pipeline
    }
}
