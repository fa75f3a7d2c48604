//! What draws, clears and reads reach: the GPU views of the bound framebuffer's images.
//!
//! Building a draw target brings every attached texture level's GPU copy up to date first
//! (its CPU texels uploaded in the batch's order) and then marks it as held by the GPU: the
//! draw about to be recorded makes the GPU's texels the newer ones.

use super::Attachment;
use crate::context::Context;
use crate::frame::{ColorTarget, DepthTarget, PassTarget};
use crate::gl;
use crate::texture::{internal_format, InternalFormat, ViewKey};

/// One image of a framebuffer, as a GPU texture subresource.
#[derive(Clone, Debug)]
pub(crate) struct SurfaceImage {
    pub(crate) texture: wgpu::Texture,
    /// The mip of `texture` and the array layer (or 3D slice) that hold the image.
    pub(crate) mip: u32,
    pub(crate) layer: u32,
    pub(crate) format: InternalFormat,
    pub(crate) width: u32,
    pub(crate) height: u32,
    /// Samples per pixel (1: single-sampled).
    pub(crate) samples: u32,
    /// For an image of a 3D texture: the layer is a depth slice.
    pub(crate) slice_3d: bool,
    /// A view of the image for a render pass attachment (the whole level of a 3D texture,
    /// drawn at `depth_slice`), made once and kept so that passes can be compared.
    pub(crate) view: wgpu::TextureView,
    pub(crate) depth_slice: Option<u32>,
}

/// What a draw writes to, for its checks: the draw buffers' formats, whether there is a
/// stencil buffer, and the size.
pub(crate) struct DrawFormats {
    pub(crate) colors: Vec<Option<InternalFormat>>,
    pub(crate) stencil: bool,
    pub(crate) size: [u32; 2],
}

/// The images a draw or blit writes: by draw buffer, and depth and stencil (the same image
/// when the format has both).
pub(crate) struct DrawImages {
    pub(crate) colors: Vec<Option<SurfaceImage>>,
    pub(crate) depth: Option<SurfaceImage>,
    pub(crate) stencil: Option<SurfaceImage>,
}

/// What a read (`read_pixels`, `copy_tex_image_2d`, a blit's source) reads from.
#[derive(Clone, Debug)]
pub(crate) struct ReadSurface {
    /// The colour read buffer (`None` for `readBuffer(NONE)` or no image there).
    pub(crate) color: Option<SurfaceImage>,
    pub(crate) depth: Option<SurfaceImage>,
    pub(crate) stencil: Option<SurfaceImage>,
    /// Whether the read framebuffer is the default one.
    pub(crate) default: bool,
}

impl Context {
    /// The image an attachment names, made ready on the GPU; `mark_written` marks a texture
    /// level as held by the GPU (a draw or copy into it follows).
    pub(crate) fn attachment_image(
        &mut self,
        a: Attachment,
        mark_written: bool,
    ) -> Option<SurfaceImage> {
        match a {
            Attachment::Renderbuffer(id) => {
                let s = self.objects.renderbuffers.get_any(id)?.storage.as_ref()?;
                let (texture, view) = s.gpu.clone()?;
                Some(SurfaceImage {
                    texture,
                    mip: 0,
                    layer: 0,
                    format: s.format,
                    width: s.width,
                    height: s.height,
                    samples: s.samples.max(1),
                    slice_3d: false,
                    view,
                    depth_slice: None,
                })
            }
            Attachment::Texture { id, level, layer } => {
                if !self.sync_texture(id, level..level + 1) {
                    return None;
                }
                let t = self.objects.textures.get_any_mut(id)?;
                let cube = t.face_count() == 6;
                let slice_3d = t.target == Some(gl::TEXTURE_3D);
                let face = if cube { layer as usize } else { 0 };
                t.level(face, level)?;
                let aspect = wgpu::TextureAspect::All;
                let g = t.gpu.as_mut()?;
                let mip = level - g.anchor;
                let view = g.view(ViewKey {
                    mips: (mip, 1),
                    layer: (!slice_3d).then_some(layer),
                    dimension: if slice_3d {
                        wgpu::TextureViewDimension::D3
                    } else {
                        wgpu::TextureViewDimension::D2
                    },
                    aspect,
                });
                let texture = g.texture.clone();
                let l = t.level_mut(face, level)?;
                if mark_written {
                    l.data = None;
                    l.uploaded = true;
                }
                Some(SurfaceImage {
                    texture,
                    mip,
                    layer,
                    format: l.format,
                    width: l.width,
                    height: l.height,
                    samples: 1,
                    slice_3d,
                    view,
                    depth_slice: slice_3d.then_some(layer),
                })
            }
        }
    }

    /// The images of the bound draw framebuffer, marked as drawn into: its draw buffers'
    /// and depth/stencil. The caller has checked completeness.
    pub(crate) fn draw_images(&mut self) -> DrawImages {
        let [draw, _] = self.bindings.framebuffers();
        let Some(fb) = draw
            .and_then(|id| self.objects.framebuffers.get_any(id))
            .cloned()
        else {
            let read = self.default_read_surface();
            return DrawImages {
                colors: vec![read.color.filter(|_| self.fb.draw_buffer == gl::BACK)],
                depth: read.depth,
                stencil: read.stencil,
            };
        };
        let mut colors = Vec::new();
        for (i, &buffer) in fb.draw_buffers.iter().enumerate() {
            let image = fb
                .colors
                .get(i)
                .copied()
                .flatten()
                .filter(|_| buffer == gl::COLOR_ATTACHMENT0 + i as u32)
                .and_then(|a| self.attachment_image(a, true));
            colors.push(image);
        }
        while colors.last().is_some_and(|c| c.is_none()) {
            colors.pop();
        }
        let depth = fb.depth.and_then(|a| self.attachment_image(a, true));
        let stencil = fb.stencil.and_then(|a| self.attachment_image(a, true));
        DrawImages {
            colors,
            depth,
            stencil,
        }
    }

    /// The render pass target of the bound draw framebuffer: its draw buffers' images and
    /// depth/stencil. The caller has checked completeness.
    pub(crate) fn draw_target(&mut self) -> PassTarget {
        if self.bindings.framebuffers()[0].is_none() {
            return self.default_target();
        }
        let images = self.draw_images();
        let mut size = [0, 0];
        let mut samples = 1;
        let colors = images
            .colors
            .iter()
            .map(|c| {
                c.as_ref().map(|img| {
                    size = [img.width, img.height];
                    samples = img.samples;
                    ColorTarget {
                        view: img.view.clone(),
                        depth_slice: img.depth_slice,
                        resolve: None,
                        format: img.format.gpu_format(),
                    }
                })
            })
            .collect();
        let depth = images.depth.or(images.stencil).map(|img| {
            size = [img.width, img.height];
            samples = img.samples;
            DepthTarget {
                view: img.view,
                format: img.format.gpu_format(),
            }
        });
        PassTarget {
            colors,
            depth,
            samples,
            size,
        }
    }

    /// The target of a draw that makes no fragments: a 1×1 depth image nothing reads.
    pub(crate) fn discard_target(&mut self) -> PassTarget {
        let gpu = &self.gpu;
        let view = self
            .caches
            .discard
            .get_or_insert_with(|| {
                gpu.device
                    .create_texture(&wgpu::TextureDescriptor {
                        label: Some("essl-gl no fragments"),
                        size: wgpu::Extent3d {
                            width: 1,
                            height: 1,
                            depth_or_array_layers: 1,
                        },
                        mip_level_count: 1,
                        sample_count: 1,
                        dimension: wgpu::TextureDimension::D2,
                        format: wgpu::TextureFormat::Depth16Unorm,
                        usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                        view_formats: &[],
                    })
                    .create_view(&Default::default())
            })
            .clone();
        PassTarget {
            colors: Vec::new(),
            depth: Some(DepthTarget {
                view,
                format: wgpu::TextureFormat::Depth16Unorm,
            }),
            samples: 1,
            size: [1, 1],
        }
    }

    /// The default framebuffer as a render pass target.
    pub(crate) fn default_target(&self) -> PassTarget {
        self.default_target_with(self.fb.draw_buffer == gl::BACK)
    }

    /// The default framebuffer as a pass target, its colour image included or not (the
    /// compositor clears it whatever `drawBuffers` says).
    pub(crate) fn default_target_with(&self, color: bool) -> PassTarget {
        let fb = &self.fb;
        let color = color.then(|| match &fb.msaa {
            Some((t, v)) => ColorTarget {
                view: v.clone(),
                depth_slice: None,
                resolve: Some(fb.color_view.clone()),
                format: t.format(),
            },
            None => ColorTarget {
                view: fb.color_view.clone(),
                depth_slice: None,
                resolve: None,
                format: fb.color.format(),
            },
        });
        PassTarget {
            colors: color.map(|c| vec![Some(c)]).unwrap_or_default(),
            depth: fb.depth_stencil.as_ref().map(|(t, v)| DepthTarget {
                view: v.clone(),
                format: t.format(),
            }),
            samples: fb.samples(),
            size: [fb.width, fb.height],
        }
    }

    /// What the bound read framebuffer reads from. The caller has checked completeness.
    pub(crate) fn read_surface(&mut self) -> ReadSurface {
        let [_, read] = self.bindings.framebuffers();
        let Some(fb) = read
            .and_then(|id| self.objects.framebuffers.get_any(id))
            .cloned()
        else {
            return self.default_read_surface();
        };
        let color = fb
            .read_buffer
            .checked_sub(gl::COLOR_ATTACHMENT0)
            .and_then(|i| fb.colors.get(i as usize).copied().flatten())
            .and_then(|a| self.attachment_image(a, false));
        let depth = fb.depth.and_then(|a| self.attachment_image(a, false));
        let stencil = fb.stencil.and_then(|a| self.attachment_image(a, false));
        ReadSurface {
            color,
            depth,
            stencil,
            default: false,
        }
    }

    /// The default framebuffer as a read source (its resolved colour image).
    pub(crate) fn default_read_surface(&self) -> ReadSurface {
        let fb = &self.fb;
        let rgba8 = fb.format;
        let image = |texture: &wgpu::Texture, view: &wgpu::TextureView, format| SurfaceImage {
            texture: texture.clone(),
            mip: 0,
            layer: 0,
            format,
            width: fb.width,
            height: fb.height,
            samples: texture.sample_count(),
            slice_3d: false,
            view: view.clone(),
            depth_slice: None,
        };
        let color = (fb.read_buffer == gl::BACK).then(|| image(&fb.color, &fb.color_view, rgba8));
        let depth_stencil = fb.depth_stencil.as_ref().map(|(t, v)| {
            let gl_format = match t.format() {
                wgpu::TextureFormat::Depth24PlusStencil8 => gl::DEPTH24_STENCIL8,
                wgpu::TextureFormat::Stencil8 => gl::STENCIL_INDEX8,
                _ => gl::DEPTH_COMPONENT24,
            };
            image(
                t,
                v,
                internal_format(gl_format).expect("a supported format"),
            )
        });
        ReadSurface {
            color,
            depth: depth_stencil.clone().filter(|i| i.format.has_depth()),
            stencil: depth_stencil.filter(|i| i.format.has_stencil()),
            default: true,
        }
    }

    /// The formats of the draw framebuffer's draw buffers, its depth/stencil format and its
    /// size, read from the images without touching the GPU (for a draw's checks).
    pub(crate) fn draw_formats(&self) -> DrawFormats {
        let [draw, _] = self.bindings.framebuffers();
        let Some(fb) = draw.and_then(|id| self.objects.framebuffers.get_any(id)) else {
            let fb = &self.fb;
            return DrawFormats {
                colors: vec![(fb.draw_buffer == gl::BACK).then_some(fb.format)],
                stencil: fb.attributes.stencil,
                size: [fb.width, fb.height],
            };
        };
        let mut size = [0, 0];
        let colors = fb
            .draw_buffers
            .iter()
            .enumerate()
            .map(|(i, &b)| {
                let a = fb.colors.get(i).copied().flatten();
                let info = a
                    .filter(|_| b == gl::COLOR_ATTACHMENT0 + i as u32)
                    .and_then(|a| self.image_info(a));
                info.map(|i| {
                    size = [i.width, i.height];
                    i.format
                })
            })
            .collect();
        let depth = fb.depth.or(fb.stencil).and_then(|a| self.image_info(a));
        if let Some(d) = &depth {
            size = [d.width, d.height];
        }
        DrawFormats {
            colors,
            stencil: fb
                .stencil
                .and_then(|a| self.image_info(a))
                .is_some_and(|i| i.format.has_stencil()),
            size,
        }
    }

    /// Whether the draw framebuffer's images include level `levels` of texture `id` (a
    /// feedback loop if the draw also samples them).
    pub(crate) fn draws_into(&self, id: crate::objects::Id, levels: std::ops::Range<u32>) -> bool {
        let [draw, _] = self.bindings.framebuffers();
        let Some(fb) = draw.and_then(|d| self.objects.framebuffers.get_any(d)) else {
            return false;
        };
        let drawn = fb
            .colors
            .iter()
            .enumerate()
            .filter(|(i, _)| fb.draw_buffers.get(*i) == Some(&(gl::COLOR_ATTACHMENT0 + *i as u32)))
            .filter_map(|(_, a)| *a)
            .chain(fb.depth)
            .chain(fb.stencil);
        for a in drawn {
            if let Attachment::Texture { id: t, level, .. } = a {
                if t == id && levels.contains(&level) {
                    return true;
                }
            }
        }
        false
    }
}

/// The view key for sampling levels `base..base + count` of a texture whose GPU chain
/// starts at GL level `anchor`.
pub(crate) fn sample_view_key(
    target: u32,
    anchor: u32,
    base: u32,
    count: u32,
    format: &InternalFormat,
) -> ViewKey {
    ViewKey {
        mips: (base - anchor, count),
        layer: None,
        dimension: crate::texture::view_dimension(target),
        aspect: if format.has_depth() {
            wgpu::TextureAspect::DepthOnly
        } else {
            wgpu::TextureAspect::All
        },
    }
}
