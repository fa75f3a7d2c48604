//! The GPU copy of a texture: one wgpu texture holding a chain of GL levels (which chain, and
//! keeping it in step, is [`gpu_sync`](super::gpu_sync)'s), its views, and the upload of
//! texels into a box of it.

use std::collections::HashMap;

use crate::frame::Frame;
use crate::gpu::Gpu;

/// What a view of the GPU copy shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct ViewKey {
    /// First mip of the view (GL level minus the anchor) and the number of mips.
    pub(crate) mips: (u32, u32),
    /// One array layer (a cube face, a 2D array layer) for an attachment; `None`: all.
    pub(crate) layer: Option<u32>,
    pub(crate) dimension: wgpu::TextureViewDimension,
    pub(crate) aspect: wgpu::TextureAspect,
}

/// The wgpu texture of a GL texture.
pub(crate) struct GpuTexture {
    pub(crate) texture: wgpu::Texture,
    /// The GL level that is mip 0.
    pub(crate) anchor: u32,
    /// Mips of the texture.
    pub(crate) levels: u32,
    views: HashMap<ViewKey, wgpu::TextureView>,
}

impl GpuTexture {
    /// The GPU copy of GL levels `anchor..anchor + levels`, held by `texture`.
    pub(super) fn new(texture: wgpu::Texture, anchor: u32, levels: u32) -> Self {
        GpuTexture {
            texture,
            anchor,
            levels,
            views: HashMap::new(),
        }
    }

    /// A view, made on first use.
    pub(crate) fn view(&mut self, key: ViewKey) -> wgpu::TextureView {
        let texture = &self.texture;
        self.views
            .entry(key)
            .or_insert_with(|| {
                texture.create_view(&wgpu::TextureViewDescriptor {
                    label: Some("essl-gl texture view"),
                    dimension: Some(key.dimension),
                    aspect: key.aspect,
                    base_mip_level: key.mips.0,
                    mip_level_count: Some(key.mips.1),
                    base_array_layer: key.layer.unwrap_or(0),
                    array_layer_count: key.layer.map(|_| 1),
                    ..Default::default()
                })
            })
            .clone()
    }

    /// Whether GL level `level` is in the chain.
    pub(crate) fn holds(&self, level: u32) -> bool {
        (self.anchor..self.anchor + self.levels).contains(&level)
    }
}

/// The usages a texture of `format` gets: sampled, copied both ways, and drawn into when
/// the device can render to the format.
pub(super) fn usages(gpu: &Gpu, format: wgpu::TextureFormat) -> wgpu::TextureUsages {
    let allowed = format
        .guaranteed_format_features(gpu.device.features())
        .allowed_usages;
    let mut usage = wgpu::TextureUsages::TEXTURE_BINDING;
    for u in [
        wgpu::TextureUsages::COPY_SRC,
        wgpu::TextureUsages::COPY_DST,
        wgpu::TextureUsages::RENDER_ATTACHMENT,
    ] {
        if allowed.contains(u) {
            usage |= u;
        }
    }
    usage
}

/// A box of one mip of a texture that texels are uploaded to.
pub(crate) struct TexelBox<'a> {
    pub(crate) texture: &'a wgpu::Texture,
    pub(crate) mip: u32,
    /// x, y and the first array layer (or 3D slice).
    pub(crate) origin: [u32; 3],
    pub(crate) size: [u32; 3],
    /// Bytes per texel.
    pub(crate) texel: u32,
}

/// Records a copy of `data` (texels of the box, tightly packed rows) into the box, through
/// the arena, in the batch's order.
pub(crate) fn upload_image(gpu: &Gpu, frame: &mut Frame, dst: &TexelBox, data: &[u8]) {
    let TexelBox {
        texture,
        mip,
        origin,
        size,
        texel,
    } = *dst;
    let [w, h, d] = size;
    if w == 0 || h == 0 || d == 0 {
        return;
    }
    let row = (w * texel) as usize;
    let padded = row.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT as usize)
        * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT as usize;
    let rows = (h * d) as usize;
    let bytes: std::borrow::Cow<[u8]> = if padded == row {
        std::borrow::Cow::Borrowed(&data[..row * rows])
    } else {
        let mut v = vec![0u8; padded * rows];
        for r in 0..rows {
            v[r * padded..r * padded + row].copy_from_slice(&data[r * row..(r + 1) * row]);
        }
        std::borrow::Cow::Owned(v)
    };
    let alloc = frame
        .arena
        .push(gpu, &bytes, wgpu::COPY_BUFFER_ALIGNMENT.max(256));
    frame.commands(gpu).copy_buffer_to_texture(
        wgpu::TexelCopyBufferInfo {
            buffer: &alloc.buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: alloc.offset,
                bytes_per_row: Some(padded as u32),
                rows_per_image: Some(h),
            },
        },
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: mip,
            origin: wgpu::Origin3d {
                x: origin[0],
                y: origin[1],
                z: origin[2],
            },
            aspect: wgpu::TextureAspect::All,
        },
        wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: d,
        },
    );
}
