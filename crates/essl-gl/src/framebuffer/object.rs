//! A framebuffer object's state: its attachments, draw buffers and read buffer.

use crate::gl;
use crate::objects::Id;

/// The most colour attachments and draw buffers essl-gl has: wgpu's 8 colour targets. A
/// context reports fewer (`MAX_COLOR_ATTACHMENTS`, `MAX_DRAW_BUFFERS`; at least WebGL2's 4)
/// where its device cannot write 8 targets of 16 bytes a sample.
pub const MAX_COLOR_ATTACHMENTS: u32 = 8;

/// An image attached to a framebuffer attachment point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Attachment {
    /// A level of a texture: one cube face or one layer of a 3D or 2D array texture.
    Texture {
        id: Id,
        level: u32,
        /// The cube face (0..6) or the layer.
        layer: u32,
    },
    /// A renderbuffer.
    Renderbuffer(Id),
}

/// A framebuffer object.
#[derive(Clone, Debug)]
pub(crate) struct FramebufferObject {
    pub(crate) bound_once: bool,
    /// `COLOR_ATTACHMENT0..`.
    pub(crate) colors: Vec<Option<Attachment>>,
    pub(crate) depth: Option<Attachment>,
    pub(crate) stencil: Option<Attachment>,
    /// `drawBuffers`: `COLOR_ATTACHMENTi` or `NONE` for each draw buffer `i`.
    pub(crate) draw_buffers: Vec<u32>,
    /// `readBuffer`: `COLOR_ATTACHMENTi` or `NONE`.
    pub(crate) read_buffer: u32,
}

impl Default for FramebufferObject {
    fn default() -> Self {
        let mut draw_buffers = vec![gl::NONE; MAX_COLOR_ATTACHMENTS as usize];
        draw_buffers[0] = gl::COLOR_ATTACHMENT0;
        FramebufferObject {
            bound_once: false,
            colors: vec![None; MAX_COLOR_ATTACHMENTS as usize],
            depth: None,
            stencil: None,
            draw_buffers,
            read_buffer: gl::COLOR_ATTACHMENT0,
        }
    }
}

impl FramebufferObject {
    /// Every attachment, with its attachment point.
    pub(crate) fn attachments(&self) -> impl Iterator<Item = (u32, Attachment)> + '_ {
        let colors = self
            .colors
            .iter()
            .enumerate()
            .filter_map(|(i, a)| a.map(|a| (gl::COLOR_ATTACHMENT0 + i as u32, a)));
        colors
            .chain(self.depth.map(|a| (gl::DEPTH_ATTACHMENT, a)))
            .chain(self.stencil.map(|a| (gl::STENCIL_ATTACHMENT, a)))
    }

    /// The attachment at an attachment point (`DEPTH_STENCIL_ATTACHMENT`: the depth one when
    /// depth and stencil are the same image).
    pub(crate) fn attachment(&self, point: u32) -> Option<Attachment> {
        match point {
            gl::DEPTH_ATTACHMENT => self.depth,
            gl::STENCIL_ATTACHMENT => self.stencil,
            gl::DEPTH_STENCIL_ATTACHMENT => self.depth.filter(|_| self.depth == self.stencil),
            _ => {
                let i = point.checked_sub(gl::COLOR_ATTACHMENT0)? as usize;
                self.colors.get(i).copied().flatten()
            }
        }
    }
}
