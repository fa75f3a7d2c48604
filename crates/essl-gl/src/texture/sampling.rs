//! What draws bind for textures: wgpu samplers cached by parameters, and the placeholder
//! textures an incomplete or missing texture reads.

use std::collections::HashMap;

use super::format::SampleKind;
use crate::gpu::Gpu;

/// A sampler's parameters, as a hashable key.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct SamplerKey {
    pub(super) min: wgpu::FilterMode,
    pub(super) mag: wgpu::FilterMode,
    pub(super) mip: wgpu::MipmapFilterMode,
    pub(super) wrap: [wgpu::AddressMode; 3],
    pub(super) lod_min: u32,
    pub(super) lod_max: u32,
    pub(super) compare: Option<wgpu::CompareFunction>,
    /// wgpu's anisotropy clamp (1: none).
    pub(super) anisotropy: u16,
}

impl SamplerKey {
    /// The sampler of a blit: clamping, nearest or linear, base level only.
    pub(crate) fn blit(linear: bool) -> Self {
        let filter = if linear {
            wgpu::FilterMode::Linear
        } else {
            wgpu::FilterMode::Nearest
        };
        SamplerKey {
            min: filter,
            mag: filter,
            mip: wgpu::MipmapFilterMode::Nearest,
            wrap: [wgpu::AddressMode::ClampToEdge; 3],
            lod_min: 0.0f32.to_bits(),
            lod_max: 0.0f32.to_bits(),
            compare: None,
            anisotropy: 1,
        }
    }

    /// A nearest, clamping sampler (for placeholder textures).
    pub(crate) fn placeholder(comparison: bool) -> Self {
        SamplerKey {
            min: wgpu::FilterMode::Nearest,
            mag: wgpu::FilterMode::Nearest,
            mip: wgpu::MipmapFilterMode::Nearest,
            wrap: [wgpu::AddressMode::ClampToEdge; 3],
            lod_min: 0.0f32.to_bits(),
            lod_max: 0.25f32.to_bits(),
            compare: comparison.then_some(wgpu::CompareFunction::LessEqual),
            anisotropy: 1,
        }
    }
}

/// wgpu samplers by parameters.
#[derive(Default)]
pub(crate) struct SamplerCache {
    samplers: HashMap<SamplerKey, wgpu::Sampler>,
}

impl SamplerCache {
    pub(crate) fn get(&mut self, device: &wgpu::Device, key: SamplerKey) -> wgpu::Sampler {
        self.samplers
            .entry(key)
            .or_insert_with(|| {
                device.create_sampler(&wgpu::SamplerDescriptor {
                    label: Some("essl-gl sampler"),
                    address_mode_u: key.wrap[0],
                    address_mode_v: key.wrap[1],
                    address_mode_w: key.wrap[2],
                    mag_filter: key.mag,
                    min_filter: key.min,
                    mipmap_filter: key.mip,
                    lod_min_clamp: f32::from_bits(key.lod_min),
                    lod_max_clamp: f32::from_bits(key.lod_max),
                    compare: key.compare,
                    anisotropy_clamp: key.anisotropy,
                    border_color: None,
                })
            })
            .clone()
    }
}

/// 1×1 textures reading (0, 0, 0, 1), bound where a sampler's unit has no complete texture.
#[derive(Default)]
pub(crate) struct Dummies {
    views: HashMap<(wgpu::TextureViewDimension, SampleKind), wgpu::TextureView>,
}

impl Dummies {
    pub(crate) fn get(
        &mut self,
        gpu: &Gpu,
        dim: wgpu::TextureViewDimension,
        kind: SampleKind,
    ) -> wgpu::TextureView {
        self.views
            .entry((dim, kind))
            .or_insert_with(|| {
                let (format, texel): (_, Vec<u8>) = match kind {
                    SampleKind::Float => (wgpu::TextureFormat::Rgba8Unorm, vec![0, 0, 0, 255]),
                    SampleKind::Sint => (
                        wgpu::TextureFormat::Rgba32Sint,
                        bytemuck::cast_slice(&[0i32, 0, 0, 1]).to_vec(),
                    ),
                    SampleKind::Uint => (
                        wgpu::TextureFormat::Rgba32Uint,
                        bytemuck::cast_slice(&[0u32, 0, 0, 1]).to_vec(),
                    ),
                    SampleKind::Depth => (wgpu::TextureFormat::Depth16Unorm, vec![0xFF, 0xFF]),
                };
                let layers = if dim == wgpu::TextureViewDimension::Cube {
                    6
                } else {
                    1
                };
                let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
                    label: Some("essl-gl placeholder texture"),
                    size: wgpu::Extent3d {
                        width: 1,
                        height: 1,
                        depth_or_array_layers: layers,
                    },
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: if dim == wgpu::TextureViewDimension::D3 {
                        wgpu::TextureDimension::D3
                    } else {
                        wgpu::TextureDimension::D2
                    },
                    format,
                    usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                    view_formats: &[],
                });
                for layer in 0..layers {
                    gpu.queue.write_texture(
                        wgpu::TexelCopyTextureInfo {
                            texture: &texture,
                            mip_level: 0,
                            origin: wgpu::Origin3d {
                                x: 0,
                                y: 0,
                                z: layer,
                            },
                            aspect: wgpu::TextureAspect::All,
                        },
                        &texel,
                        wgpu::TexelCopyBufferLayout {
                            offset: 0,
                            bytes_per_row: None,
                            rows_per_image: None,
                        },
                        wgpu::Extent3d {
                            width: 1,
                            height: 1,
                            depth_or_array_layers: 1,
                        },
                    );
                }
                texture.create_view(&wgpu::TextureViewDescriptor {
                    dimension: Some(dim),
                    ..Default::default()
                })
            })
            .clone()
    }
}
