//! Framebuffer completeness as WebGL2 has it (ES 3.0 §4.4.4 with WebGL's additions: every
//! image the same size, depth and stencil one image, no image attached twice), and
//! `check_framebuffer_status`.

use super::{Attachment, FramebufferObject};
use crate::context::Context;
use crate::gl;
use crate::objects::Id;
use crate::texture::InternalFormat;

/// What an attached image is, for the completeness rules.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ImageInfo {
    pub(crate) format: InternalFormat,
    pub(crate) width: u32,
    pub(crate) height: u32,
    /// Samples of a renderbuffer (0: single-sampled; textures are 0).
    pub(crate) samples: u32,
    pub(crate) renderbuffer: bool,
}

impl Context {
    /// The image an attachment names, if it exists: a texture level that has an image (for a
    /// 3D or array texture, a level with that layer) or a renderbuffer with storage.
    pub(crate) fn image_info(&self, a: Attachment) -> Option<ImageInfo> {
        match a {
            Attachment::Texture { id, level, layer } => {
                let t = self.objects.textures.get_any(id)?;
                let cube = t.face_count() == 6;
                let face = if cube { layer as usize } else { 0 };
                let l = t.level(face, level)?;
                if !cube && t.target != Some(gl::TEXTURE_2D) && layer >= l.depth {
                    return None;
                }
                if !self.webgl1.on && !t.attachable_level(level) {
                    return None;
                }
                Some(ImageInfo {
                    format: l.format,
                    width: l.width,
                    height: l.height,
                    samples: 0,
                    renderbuffer: false,
                })
            }
            Attachment::Renderbuffer(id) => {
                let s = self.objects.renderbuffers.get_any(id)?.storage.as_ref()?;
                Some(ImageInfo {
                    format: s.format,
                    width: s.width,
                    height: s.height,
                    samples: s.samples,
                    renderbuffer: true,
                })
            }
        }
    }

    /// WebGL2's completeness status of framebuffer `id`.
    pub(crate) fn framebuffer_status(&self, id: Id) -> u32 {
        let Some(f) = self.objects.framebuffers.get_any(id) else {
            return gl::FRAMEBUFFER_UNSUPPORTED;
        };
        self.status_of(f)
    }

    fn status_of(&self, f: &FramebufferObject) -> u32 {
        let float_ok = self.extensions.color_buffer_float;
        let mut images = Vec::new();
        for (point, a) in f.attachments() {
            let Some(info) = self.image_info(a) else {
                return gl::FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            };
            let mut fits = match point {
                gl::DEPTH_ATTACHMENT => info.format.has_depth(),
                gl::STENCIL_ATTACHMENT => info.format.has_stencil(),
                _ => info.format.color_renderable(float_ok),
            };
            // WebGL 1 (§6.6): a depth-and-stencil image goes to DEPTH_STENCIL_ATTACHMENT, not
            // to DEPTH_ATTACHMENT alone. (A stencil point holding one alone is left complete:
            // the points share slots here, and that is what a DEPTH_STENCIL attachment leaves
            // when a later DEPTH_ATTACHMENT is removed.)
            if self.webgl1.on && point == gl::DEPTH_ATTACHMENT && info.format.has_stencil() {
                fits &= f.depth == f.stencil;
            }
            if !fits || info.width == 0 || info.height == 0 {
                return gl::FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            }
            images.push(info);
        }
        let Some(first) = images.first() else {
            return gl::FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT;
        };
        if images
            .iter()
            .any(|i| (i.width, i.height) != (first.width, first.height))
        {
            return gl::FRAMEBUFFER_INCOMPLETE_DIMENSIONS;
        }
        let samples: Vec<u32> = images.iter().map(|i| i.samples).collect();
        let mixed = images.iter().any(|i| !i.renderbuffer) && samples.iter().any(|&s| s > 0);
        if mixed || samples.iter().any(|&s| s != samples[0]) {
            return gl::FRAMEBUFFER_INCOMPLETE_MULTISAMPLE;
        }
        if f.depth.is_some() && f.stencil.is_some() && f.depth != f.stencil {
            return gl::FRAMEBUFFER_UNSUPPORTED;
        }
        let colors: Vec<Attachment> = f.colors.iter().flatten().copied().collect();
        for (i, a) in colors.iter().enumerate() {
            if colors[i + 1..].contains(a) {
                return gl::FRAMEBUFFER_UNSUPPORTED;
            }
        }
        gl::FRAMEBUFFER_COMPLETE
    }

    /// Whether the framebuffer bound for drawing (`draw`) or reading is complete; records
    /// `INVALID_FRAMEBUFFER_OPERATION` when it is not.
    pub(crate) fn require_complete(&mut self, draw: bool, function: &str) -> bool {
        let [d, r] = self.bindings.framebuffers();
        let Some(id) = (if draw { d } else { r }) else {
            return true;
        };
        let status = self.framebuffer_status(id);
        if status != gl::FRAMEBUFFER_COMPLETE {
            self.error(
                gl::INVALID_FRAMEBUFFER_OPERATION,
                function,
                format_args!("the framebuffer is incomplete (0x{status:04X})"),
            );
            return false;
        }
        true
    }

    /// The completeness of the framebuffer bound to `target` (`checkFramebufferStatus`):
    /// `FRAMEBUFFER_COMPLETE` for the default framebuffer; an unknown target →
    /// `INVALID_ENUM` and 0.
    pub fn check_framebuffer_status(&self, target: u32) -> u32 {
        if self.webgl1_refuses("checkFramebufferStatus", &[target]) {
            return 0;
        }
        let [d, r] = self.bindings.framebuffers();
        let id = match target {
            gl::FRAMEBUFFER | gl::DRAW_FRAMEBUFFER => d,
            gl::READ_FRAMEBUFFER => r,
            _ => {
                self.error(
                    gl::INVALID_ENUM,
                    "checkFramebufferStatus",
                    format_args!("target 0x{target:04X}"),
                );
                return 0;
            }
        };
        id.map_or(gl::FRAMEBUFFER_COMPLETE, |id| self.framebuffer_status(id))
    }
}
