//! The pipelines that copy one image into others by drawing: `blit_framebuffer` (scaled,
//! flipped, filtered, resolved, with format conversion) and `copy_tex_image_2d` /
//! `copy_tex_sub_image_*` (which also spread channels into luminance and alpha formats).
//!
//! A full-screen triangle covers the destination rectangle (the scissor box limits it);
//! each fragment maps its centre back into the source rectangle and reads the source there —
//! `textureLoad` of the texel under it for `NEAREST`, a bilinear sample for `LINEAR` — and
//! discards itself when that point lies outside the source image, as GL leaves such pixels
//! alone.

use super::{create_module, PipelineCache};
use crate::gpu::Gpu;
use crate::pipeline::ClearKind;

/// How a source image is read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum BlitSource {
    /// Colour of a kind, `samples` per pixel (more than 1: sample 0 is read).
    Color { kind: ClearKind, samples: u32 },
    /// Depth (written to the destination's depth).
    Depth { samples: u32 },
    /// One stencil bit: the fragment is kept where the bit is set (the blit of stencil
    /// draws once per bit).
    StencilBit { samples: u32 },
}

/// Where the destination's channels come from (copyTexImage into formats with fewer or
/// other channels).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Channels {
    /// RGBA as read.
    Rgba,
    /// RGB as read, alpha 1 (`RGB` formats).
    Rgb1,
    /// `LUMINANCE`: (R, R, R, 1).
    Luminance,
    /// `LUMINANCE_ALPHA`: (R, R, R, A).
    LuminanceAlpha,
    /// `ALPHA`: (0, 0, 0, A).
    Alpha,
}

/// Everything a blit pipeline depends on.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct BlitKey {
    pub(crate) source: BlitSource,
    pub(crate) linear: bool,
    pub(crate) channels: Channels,
    /// The colour targets (format and the kind written; `None` for none).
    pub(crate) colors: Vec<Option<(wgpu::TextureFormat, ClearKind)>>,
    pub(crate) depth: Option<wgpu::TextureFormat>,
    /// Stencil bits written (the stencil blit), 0 otherwise.
    pub(crate) stencil_mask: u32,
}

fn wgsl_type(kind: ClearKind) -> &'static str {
    match kind {
        ClearKind::Float => "vec4<f32>",
        ClearKind::Int => "vec4<i32>",
        ClearKind::Uint => "vec4<u32>",
    }
}

/// The WGSL of a blit. Uniforms: source rectangle (x0, y0, x1, y1), destination rectangle,
/// source size, and the stencil bit.
fn source(key: &BlitKey) -> String {
    let (texture, read) = match key.source {
        BlitSource::Color { kind, samples } => {
            let scalar = match kind {
                ClearKind::Float => "f32",
                ClearKind::Int => "i32",
                ClearKind::Uint => "u32",
            };
            if samples > 1 && kind == ClearKind::Float {
                // GL resolves a float image's samples to one value: their mean.
                let sum = (0..samples)
                    .map(|i| format!("textureLoad(src, texel, {i})"))
                    .collect::<Vec<_>>()
                    .join(" + ");
                (
                    format!("texture_multisampled_2d<{scalar}>"),
                    format!("(({sum}) / {samples}.0)"),
                )
            } else if samples > 1 {
                (
                    format!("texture_multisampled_2d<{scalar}>"),
                    "textureLoad(src, texel, 0)".to_owned(),
                )
            } else if key.linear {
                (
                    format!("texture_2d<{scalar}>"),
                    "textureSampleLevel(src, samp, pos / b.size.xy, 0.0)".to_owned(),
                )
            } else {
                (
                    format!("texture_2d<{scalar}>"),
                    "textureLoad(src, texel, 0)".to_owned(),
                )
            }
        }
        BlitSource::Depth { samples } if samples > 1 => (
            "texture_depth_multisampled_2d".to_owned(),
            "textureLoad(src, texel, 0)".to_owned(),
        ),
        BlitSource::Depth { .. } => (
            "texture_depth_2d".to_owned(),
            "textureLoad(src, texel, 0)".to_owned(),
        ),
        BlitSource::StencilBit { samples } if samples > 1 => (
            "texture_multisampled_2d<u32>".to_owned(),
            "textureLoad(src, texel, 0).x".to_owned(),
        ),
        BlitSource::StencilBit { .. } => (
            "texture_2d<u32>".to_owned(),
            "textureLoad(src, texel, 0).x".to_owned(),
        ),
    };
    // Abstract-integer literals, so that the swizzles build vectors of float, signed and
    // unsigned integer sources alike.
    let swizzle = match key.channels {
        Channels::Rgba => "v",
        Channels::Rgb1 => "vec4(v.rgb, 1)",
        Channels::Luminance => "vec4(v.rrr, 1)",
        Channels::LuminanceAlpha => "vec4(v.rrr, v.a)",
        Channels::Alpha => "vec4(0, 0, 0, v.a)",
    };
    let mut outputs = Vec::new();
    let mut writes = Vec::new();
    for (i, c) in key.colors.iter().enumerate() {
        let Some((_, kind)) = c else { continue };
        outputs.push(format!("@location({i}) c{i}: {}", wgsl_type(*kind)));
        writes.push(format!("o.c{i} = {}(w);", wgsl_type(*kind)));
    }
    let depth_out = matches!(key.source, BlitSource::Depth { .. });
    if depth_out {
        outputs.push("@builtin(frag_depth) depth: f32".to_owned());
    }
    let body = match key.source {
        BlitSource::Color { .. } => {
            format!("let v = {read}; let w = {swizzle}; {}", writes.join(" "))
        }
        BlitSource::Depth { .. } => format!("o.depth = {read};"),
        BlitSource::StencilBit { .. } => {
            format!("if b.bit.x != 0u && (({read}) & b.bit.x) == 0u {{ discard; }}")
        }
    };
    let none = outputs.is_empty();
    let out_struct = if none {
        String::new()
    } else {
        format!("struct Out {{ {} }}", outputs.join(", "))
    };
    let (returns, var, ret) = if none {
        ("", "", "")
    } else {
        ("-> Out", "var o: Out;", "return o;")
    };
    format!(
        "struct Blit {{ src: vec4<f32>, dst: vec4<f32>, size: vec4<f32>, bit: vec4<u32> }}
         @group(0) @binding(0) var<uniform> b: Blit;
         @group(1) @binding(0) var src: {texture};
         @group(1) @binding(1) var samp: sampler;
         {out_struct}
         @vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {{
             let x = f32((i << 1u) & 2u) * 2.0 - 1.0;
             let y = f32(i & 2u) * 2.0 - 1.0;
             return vec4(x, y, 0.0, 1.0);
         }}
         @fragment fn fs(@builtin(position) p: vec4<f32>) {returns} {{
             {var}
             let t = (p.xy - b.dst.xy) / (b.dst.zw - b.dst.xy);
             let pos = b.src.xy + t * (b.src.zw - b.src.xy);
             if any(pos < vec2(0.0)) || any(pos >= b.size.xy) {{ discard; }}
             let texel = vec2<i32>(floor(pos));
             {body}
             {ret}
         }}"
    )
}

impl PipelineCache {
    /// The pipeline of a blit or copy, and the layout of its texture group.
    pub(crate) fn blit_pipeline(
        &mut self,
        gpu: &Gpu,
        key: &BlitKey,
    ) -> (wgpu::RenderPipeline, wgpu::BindGroupLayout) {
        if let Some(p) = self.blit.get(key) {
            return p.clone();
        }
        let module = naga::front::wgsl::parse_str(&source(key)).expect("the blit shader parses");
        let module = create_module(gpu, module, "essl-gl blit").expect("the blit shader is valid");
        let group0 = self.group0_layout(gpu, true, 0);
        let (sample_type, multisampled) = match key.source {
            BlitSource::Color { kind, samples } => (
                match kind {
                    ClearKind::Float => wgpu::TextureSampleType::Float {
                        filterable: key.linear && samples <= 1,
                    },
                    ClearKind::Int => wgpu::TextureSampleType::Sint,
                    ClearKind::Uint => wgpu::TextureSampleType::Uint,
                },
                samples > 1,
            ),
            BlitSource::Depth { samples } => (wgpu::TextureSampleType::Depth, samples > 1),
            BlitSource::StencilBit { samples } => (wgpu::TextureSampleType::Uint, samples > 1),
        };
        let group1 = gpu
            .device
            .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("essl-gl blit source"),
                entries: &[
                    wgpu::BindGroupLayoutEntry {
                        binding: 0,
                        visibility: wgpu::ShaderStages::FRAGMENT,
                        ty: wgpu::BindingType::Texture {
                            sample_type,
                            view_dimension: wgpu::TextureViewDimension::D2,
                            multisampled,
                        },
                        count: None,
                    },
                    wgpu::BindGroupLayoutEntry {
                        binding: 1,
                        visibility: wgpu::ShaderStages::FRAGMENT,
                        ty: wgpu::BindingType::Sampler(if key.linear {
                            wgpu::SamplerBindingType::Filtering
                        } else {
                            wgpu::SamplerBindingType::NonFiltering
                        }),
                        count: None,
                    },
                ],
            });
        let layout = gpu
            .device
            .create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("essl-gl blit"),
                bind_group_layouts: &[Some(&group0), Some(&group1)],
                immediate_size: 0,
            });
        let targets: Vec<Option<wgpu::ColorTargetState>> = key
            .colors
            .iter()
            .map(|c| {
                c.map(|(format, _)| wgpu::ColorTargetState {
                    format,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                })
            })
            .collect();
        let replace = wgpu::StencilFaceState {
            compare: wgpu::CompareFunction::Always,
            fail_op: wgpu::StencilOperation::Keep,
            depth_fail_op: wgpu::StencilOperation::Replace,
            pass_op: wgpu::StencilOperation::Replace,
        };
        let depth_stencil = key.depth.map(|format| wgpu::DepthStencilState {
            format,
            depth_write_enabled: Some(matches!(key.source, BlitSource::Depth { .. })),
            depth_compare: Some(wgpu::CompareFunction::Always),
            stencil: if key.stencil_mask != 0 && format.has_stencil_aspect() {
                wgpu::StencilState {
                    front: replace,
                    back: replace,
                    read_mask: 0xFF,
                    write_mask: key.stencil_mask,
                }
            } else {
                Default::default()
            },
            bias: Default::default(),
        });
        let pipeline = gpu
            .device
            .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("essl-gl blit"),
                layout: Some(&layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs"),
                    compilation_options: Default::default(),
                    buffers: &[],
                },
                primitive: Default::default(),
                depth_stencil,
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs"),
                    compilation_options: Default::default(),
                    targets: &targets,
                }),
                multiview_mask: None,
                cache: None,
            });
        self.blit
            .insert(key.clone(), (pipeline.clone(), group1.clone()));
        (pipeline, group1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every channel layout builds a valid shader from float, signed and unsigned sources
    /// (copyTexImage2D from an integer framebuffer into an `RGB` integer format included).
    #[test]
    fn every_blit_shader_parses_and_validates() {
        let channels = [
            Channels::Rgba,
            Channels::Rgb1,
            Channels::Luminance,
            Channels::LuminanceAlpha,
            Channels::Alpha,
        ];
        let formats = [
            (ClearKind::Float, wgpu::TextureFormat::Rgba8Unorm),
            (ClearKind::Int, wgpu::TextureFormat::Rgba8Sint),
            (ClearKind::Uint, wgpu::TextureFormat::Rgba8Uint),
        ];
        for channels in channels {
            for (kind, format) in formats {
                for samples in [1, 4] {
                    let key = BlitKey {
                        source: BlitSource::Color { kind, samples },
                        linear: false,
                        channels,
                        colors: vec![Some((format, kind))],
                        depth: None,
                        stencil_mask: 0,
                    };
                    let module = naga::front::wgsl::parse_str(&source(&key))
                        .unwrap_or_else(|e| panic!("{key:?}: {e}"));
                    naga::valid::Validator::new(
                        naga::valid::ValidationFlags::all(),
                        naga::valid::Capabilities::all(),
                    )
                    .validate(&module)
                    .unwrap_or_else(|e| panic!("{key:?}: {e:?}"));
                }
            }
        }
    }
}
