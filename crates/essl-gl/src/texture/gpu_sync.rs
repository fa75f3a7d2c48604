//! Keeping a texture's GPU copy (a [`GpuTexture`], one wgpu texture holding a chain of GL
//! levels) in step with the level images, in GL's order.
//!
//! A GL texture is mutable: its levels may be specified in any order, with sizes that do not
//! (yet) form a mipmap chain. The GPU copy holds the chain that starts at one GL level — the
//! *anchor*, the base level when it can — and runs on while each level has the next mip size
//! and the same format. Levels outside the chain live only on the CPU until a later chain
//! takes them in.
//!
//! A level's texels are either on the CPU ([`Level::data`], uploaded when the GPU copy needs
//! them) or newer on the GPU (drawn into, copied into: `data` is `None`). Uploads are
//! buffer-to-texture copies recorded in the batch, so they land between the draws that came
//! before and after them; when the chain must be remade, GPU-held levels move to the new
//! texture by texture-to-texture copies, or come back to the CPU when the new chain has no
//! place for them.
//!
//! The calls here: `sync_texture` brings in the levels a use needs (remaking the chain when
//! it must), and `read_texture_level` brings a level the GPU holds back to the CPU.

use std::ops::Range;

use super::format::InternalFormat;
use super::gpu::{upload_image, usages, GpuTexture, TexelBox};
use super::object::{mip_size, Level, TextureObject};
use crate::context::Context;
use crate::gl;
use crate::objects::Id;

impl Context {
    /// Brings texture `id`'s GPU copy up to date so that it holds GL levels `want` (which
    /// must form one chain: the caller has checked completeness or attachment completeness).
    /// Returns false, doing nothing, when they do not.
    pub(crate) fn sync_texture(&mut self, id: Id, want: Range<u32>) -> bool {
        let Some(t) = self.objects.textures.get_any(id) else {
            return false;
        };
        let Some(chain) = t.wanted_chain(&want) else {
            return false;
        };
        if !t.gpu_is(&chain) {
            self.remake_gpu_texture(id, chain);
        }
        self.upload_levels(id);
        true
    }

    /// Replaces the GPU copy by a texture for `chain`, keeping every level the GPU held newer
    /// than the CPU: copied into the new texture when it has a place for it, else read back.
    fn remake_gpu_texture(&mut self, id: Id, chain: Chain) {
        // Levels held only by the old GPU copy that the new chain has no place for come back
        // to the CPU first.
        let t = self.objects.textures.get_any(id).expect("checked");
        let mut orphans = Vec::new();
        if let Some(g) = &t.gpu {
            for level in g.anchor..g.anchor + g.levels {
                let kept = (chain.anchor..chain.anchor + chain.levels).contains(&level);
                for face in 0..t.face_count() {
                    if t.level(face, level).is_some_and(|l| l.data.is_none()) && !kept {
                        orphans.push((face, level));
                    }
                }
            }
        }
        for (face, level) in orphans {
            let data = self.read_texture_level(id, face, level);
            if let Some(l) = self
                .objects
                .textures
                .get_any_mut(id)
                .and_then(|t| t.level_mut(face, level))
            {
                l.data = Some(data);
                l.uploaded = false;
            }
        }
        let target = self
            .objects
            .textures
            .get_any(id)
            .and_then(|t| t.target)
            .expect("a texture with levels has a target");
        let format = chain.format.gpu_format();
        let texture = self.gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("essl-gl texture"),
            size: wgpu::Extent3d {
                width: chain.width,
                height: chain.height,
                depth_or_array_layers: chain.layers,
            },
            mip_level_count: chain.levels,
            sample_count: 1,
            dimension: if target == gl::TEXTURE_3D {
                wgpu::TextureDimension::D3
            } else {
                wgpu::TextureDimension::D2
            },
            format,
            usage: usages(&self.gpu, format),
            view_formats: &[],
        });
        let t = self.objects.textures.get_any_mut(id).expect("checked");
        let old = t.gpu.take();
        // GPU-held levels the new chain keeps move over, in the batch's order.
        if let Some(old) = &old {
            for level in chain.anchor..chain.anchor + chain.levels {
                let on_gpu = (0..t.face_count())
                    .any(|face| t.level(face, level).is_some_and(|l| l.data.is_none()));
                if !on_gpu || !old.holds(level) {
                    continue;
                }
                let (w, h, d) = {
                    let l = t.level(0, level).expect("in the chain");
                    (l.width, l.height, chain.layers.min(l.depth.max(1)))
                };
                let layers = if t.face_count() == 6 { 6 } else { d };
                self.frame.commands(&self.gpu).copy_texture_to_texture(
                    wgpu::TexelCopyTextureInfo {
                        texture: &old.texture,
                        mip_level: level - old.anchor,
                        origin: wgpu::Origin3d::ZERO,
                        aspect: wgpu::TextureAspect::All,
                    },
                    wgpu::TexelCopyTextureInfo {
                        texture: &texture,
                        mip_level: level - chain.anchor,
                        origin: wgpu::Origin3d::ZERO,
                        aspect: wgpu::TextureAspect::All,
                    },
                    wgpu::Extent3d {
                        width: w,
                        height: h,
                        depth_or_array_layers: layers,
                    },
                );
            }
        }
        for face in t.faces.iter_mut() {
            for l in face.iter_mut().flatten() {
                l.uploaded = false;
            }
        }
        t.gpu = Some(GpuTexture::new(texture, chain.anchor, chain.levels));
        t.version += 1;
    }

    /// Uploads the CPU texels of every level in the chain that the GPU copy does not hold yet.
    fn upload_levels(&mut self, id: Id) {
        let t = self.objects.textures.get_any_mut(id).expect("checked");
        let Some(g) = &t.gpu else { return };
        let texture = g.texture.clone();
        let (anchor, levels) = (g.anchor, g.levels);
        let cube = t.face_count() == 6;
        let mut clears = Vec::new();
        for level in anchor..anchor + levels {
            for face in 0..t.face_count() {
                let Some(l) = t.level_mut(face, level) else {
                    continue;
                };
                if l.uploaded {
                    continue;
                }
                l.uploaded = true;
                let Some(data) = &l.data else { continue };
                let z = if cube { face as u32 } else { 0 };
                if l.format.copyable() {
                    let texel = l.format.texel_size() as u32;
                    let dst = TexelBox {
                        texture: &texture,
                        mip: level - anchor,
                        origin: [0, 0, z],
                        size: [l.width, l.height, l.depth],
                        texel,
                    };
                    upload_image(&self.gpu, &mut self.frame, &dst, data);
                } else {
                    // Depth formats cannot be copied into: their images are cleared to the
                    // value their texels hold when those are all one value (`null` data).
                    clears.push((level - anchor, z, l.depth, depth_clear_value(l)));
                }
            }
        }
        for (mip, z, layers, value) in clears {
            self.clear_depth_image(&texture, mip, z, layers, value);
        }
    }

    /// Clears layers `z..z + layers` of `mip` of a depth texture to `value`.
    fn clear_depth_image(
        &mut self,
        texture: &wgpu::Texture,
        mip: u32,
        z: u32,
        layers: u32,
        value: f32,
    ) {
        let format = texture.format();
        for layer in z..z + layers {
            let view = texture.create_view(&wgpu::TextureViewDescriptor {
                label: Some("essl-gl depth upload"),
                dimension: Some(wgpu::TextureViewDimension::D2),
                base_mip_level: mip,
                mip_level_count: Some(1),
                base_array_layer: layer,
                array_layer_count: Some(1),
                ..Default::default()
            });
            self.clear_depth_view(&view, format, value);
        }
    }

    /// Records a pass that clears a depth view to `depth` (and its stencil, if any, to 0).
    pub(crate) fn clear_depth_view(
        &mut self,
        view: &wgpu::TextureView,
        format: wgpu::TextureFormat,
        depth: f32,
    ) {
        let encoder = self.frame.commands(&self.gpu);
        let pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("essl-gl depth clear"),
            color_attachments: &[],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(depth),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: format.has_stencil_aspect().then_some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(0),
                    store: wgpu::StoreOp::Store,
                }),
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        drop(pass);
    }

    /// Reads one level image of a texture's GPU copy back (submitting the batch and waiting):
    /// texels in the GPU format, tightly packed. Formats wgpu cannot copy out of (depth) read
    /// as zeros.
    pub(crate) fn read_texture_level(&mut self, id: Id, face: usize, level: u32) -> Vec<u8> {
        let Some(t) = self.objects.textures.get_any(id) else {
            return Vec::new();
        };
        let Some(l) = t.level(face, level) else {
            return Vec::new();
        };
        let size = [l.width, l.height, l.depth];
        let texel = l.format.texel_size() as u32;
        let zeros = vec![0u8; (size[0] * size[1] * size[2] * texel) as usize];
        let (Some(g), true) = (&t.gpu, l.format.copyable()) else {
            return zeros;
        };
        if !g.holds(level) {
            return zeros;
        }
        let texture = g.texture.clone();
        let z = if t.face_count() == 6 { face as u32 } else { 0 };
        let image = crate::readback::ImageRegion {
            texture: &texture,
            mip: level - g.anchor,
            origin: [0, 0, z],
            size,
            texel,
            aspect: wgpu::TextureAspect::All,
        };
        self.read_image(&image).unwrap_or(zeros)
    }
}

/// The depth a CPU image of a depth format holds everywhere, as a float (0 for `null` data,
/// and for data with several values, which wgpu cannot upload to a depth texture).
fn depth_clear_value(l: &Level) -> f32 {
    let Some(data) = &l.data else { return 0.0 };
    let first = match l.format.texel_size() {
        2 => data
            .get(..2)
            .map(|b| u16::from_ne_bytes([b[0], b[1]]) as f32 / 65535.0),
        _ => data.get(..4).map(|b| {
            let w = u32::from_ne_bytes([b[0], b[1], b[2], b[3]]);
            match l.format.packing {
                super::format::Packing::Depth32F | super::format::Packing::Depth32FStencil8 => {
                    f32::from_bits(w)
                }
                super::format::Packing::Depth24Stencil8 => (w >> 8) as f32 / 16_777_215.0,
                _ => w as f32 / u32::MAX as f32,
            }
        }),
    };
    first.unwrap_or(0.0).clamp(0.0, 1.0)
}

/// The shape of a chain: GL levels `anchor..anchor + levels` of one format and size.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Chain {
    anchor: u32,
    levels: u32,
    width: u32,
    height: u32,
    /// Array layers (6 for a cube map) or 3D depth.
    layers: u32,
    format: InternalFormat,
}

impl TextureObject {
    /// The level `i` mips below `anchor` would have in a chain starting with `first`.
    fn expected(&self, first: &Level, i: u32) -> (u32, u32, u32) {
        let depth = if self.target == Some(gl::TEXTURE_3D) {
            mip_size(first.depth, i)
        } else {
            first.depth
        };
        (mip_size(first.width, i), mip_size(first.height, i), depth)
    }

    /// The chain starting at GL level `anchor`: as long as every face of every level has the
    /// next mip size and the anchor's format (all the levels of an immutable texture).
    fn chain_at(&self, anchor: u32) -> Option<Chain> {
        let first = self.level(0, anchor)?;
        let faces = self.face_count();
        let mut levels = 0;
        loop {
            let level = anchor + levels;
            let want = self.expected(first, levels);
            let fits = (0..faces).all(|face| {
                self.level(face, level).is_some_and(|l| {
                    (l.width, l.height, l.depth) == want && l.format == first.format
                })
            });
            if !fits {
                break;
            }
            levels += 1;
            if want.0 == 1 && want.1 == 1 && (want.2 == 1 || self.target != Some(gl::TEXTURE_3D)) {
                break;
            }
        }
        (levels > 0).then_some(Chain {
            anchor,
            levels,
            width: first.width,
            height: first.height,
            layers: if faces == 6 { 6 } else { first.depth },
            format: first.format,
        })
    }

    /// The chain the GPU copy should hold so that it has GL levels `want`: the current one
    /// if it still fits, else the one at the base level, else the one at `want.start`.
    fn wanted_chain(&self, want: &Range<u32>) -> Option<Chain> {
        let covers = |c: &Chain| c.anchor <= want.start && want.end <= c.anchor + c.levels;
        let mut candidates = Vec::new();
        if let Some(g) = &self.gpu {
            candidates.push(g.anchor);
        }
        candidates.push(self.level_range().0);
        candidates.push(want.start);
        candidates
            .into_iter()
            .filter_map(|a| self.chain_at(a))
            .find(covers)
    }

    /// Whether the GPU copy is exactly `chain`.
    fn gpu_is(&self, chain: &Chain) -> bool {
        self.gpu.as_ref().is_some_and(|g| {
            let t = &g.texture;
            g.anchor == chain.anchor
                && g.levels == chain.levels
                && t.width() == chain.width
                && t.height() == chain.height
                && t.depth_or_array_layers() == chain.layers
                && t.format() == chain.format.gpu_format()
        })
    }
}
