//! Framebuffer objects: `create_framebuffer`, `bind_framebuffer`, `framebuffer_texture_2d`,
//! `framebuffer_texture_layer`, `framebuffer_renderbuffer`, `draw_buffers`, `read_buffer`,
//! `invalidate_framebuffer`, `delete_framebuffer`.
//!
//! Split by concern: [`object`] (a framebuffer object's attachments and buffers),
//! [`default`] (the default framebuffer and the context attributes that shape it), and the
//! calls: [`status`] (WebGL2's completeness rules, `check_framebuffer_status`),
//! [`attachment`] (`get_framebuffer_attachment_parameter`), [`drawing_buffer`] (`present`,
//! `drawing_buffer_storage`) and [`target`] (what a draw, a clear or a read reaches: the
//! attachments' GPU views). The calls add methods to [`Context`]: its `impl` is spread over
//! these files on purpose.

mod attachment;
mod default;
mod drawing_buffer;
mod object;
mod status;
mod target;

pub(crate) use default::DefaultFramebuffer;
pub use default::{ContextAttributes, COLOR_FORMAT};
pub use object::MAX_COLOR_ATTACHMENTS;
pub(crate) use object::{Attachment, FramebufferObject};
pub(crate) use target::{sample_view_key, DrawFormats, DrawImages, ReadSurface, SurfaceImage};

use crate::context::Context;
use crate::gl;
use crate::objects::{Framebuffer, Id};

/// Which framebuffer bindings a `target` argument names: (draw, read).
fn target_slots(target: u32) -> Option<(bool, bool)> {
    match target {
        gl::FRAMEBUFFER => Some((true, true)),
        gl::DRAW_FRAMEBUFFER => Some((true, false)),
        gl::READ_FRAMEBUFFER => Some((false, true)),
        _ => None,
    }
}

impl Context {
    /// Creates a framebuffer (`createFramebuffer`).
    pub fn create_framebuffer(&mut self) -> Framebuffer {
        Framebuffer {
            ctx: self.id,
            id: self
                .objects
                .framebuffers
                .insert(FramebufferObject::default()),
        }
    }

    /// Whether `framebuffer` names a live framebuffer that was bound once (`isFramebuffer`).
    pub fn is_framebuffer(&self, framebuffer: Framebuffer) -> bool {
        framebuffer.ctx == self.id
            && self
                .objects
                .framebuffers
                .get(framebuffer.id)
                .is_some_and(|f| f.bound_once)
    }

    /// Binds a framebuffer (`bindFramebuffer`) to `FRAMEBUFFER` (both the draw and the read
    /// binding), `DRAW_FRAMEBUFFER` or `READ_FRAMEBUFFER`; `None` binds the default one.
    pub fn bind_framebuffer(&mut self, target: u32, framebuffer: Option<Framebuffer>) {
        const F: &str = "bindFramebuffer";
        if self.webgl1_refuses("bindFramebuffer", &[target]) {
            return;
        }
        let Some((draw, read)) = target_slots(target) else {
            return self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
        };
        let id = match framebuffer {
            None => None,
            Some(f) => {
                if !self.owns(f.ctx, F) {
                    return;
                }
                let Some(obj) = self.objects.framebuffers.get_mut(f.id) else {
                    return self.error(gl::INVALID_OPERATION, F, "deleted framebuffer");
                };
                obj.bound_once = true;
                Some(f.id)
            }
        };
        self.bindings.bind_framebuffer(draw, read, id);
    }

    /// Deletes a framebuffer (`deleteFramebuffer`); a bound one is unbound (the default
    /// framebuffer takes its place).
    pub fn delete_framebuffer(&mut self, framebuffer: Framebuffer) {
        if !self.owns(framebuffer.ctx, "deleteFramebuffer")
            || !self.objects.framebuffers.is_live(framebuffer.id)
        {
            return;
        }
        self.bindings.forget_framebuffer(framebuffer.id);
        self.objects.delete_framebuffer(framebuffer.id);
    }

    /// The framebuffer object bound to a target, or the error WebGL records: `INVALID_ENUM`
    /// for an unknown target, `INVALID_OPERATION` when the default framebuffer is bound.
    pub(crate) fn bound_framebuffer(&mut self, target: u32, function: &str) -> Option<Id> {
        let Some((draw, _)) = target_slots(target) else {
            self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("target 0x{target:04X}"),
            );
            return None;
        };
        let [d, r] = self.bindings.framebuffers();
        let id = if draw { d } else { r };
        if id.is_none() {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "the default framebuffer is bound",
            );
        }
        id
    }

    /// Checks an attachment point: `COLOR_ATTACHMENT0..`, `DEPTH_ATTACHMENT`,
    /// `STENCIL_ATTACHMENT`, `DEPTH_STENCIL_ATTACHMENT`. Anything else, a colour attachment
    /// past `MAX_COLOR_ATTACHMENTS` included, → `INVALID_ENUM`, as Chromium answers (ES 3.0
    /// would give `INVALID_OPERATION` for the latter).
    fn check_attachment_point(&mut self, point: u32, function: &str) -> bool {
        let colors = self.limits.max_color_attachments;
        match point {
            gl::DEPTH_ATTACHMENT | gl::STENCIL_ATTACHMENT | gl::DEPTH_STENCIL_ATTACHMENT => true,
            p if (gl::COLOR_ATTACHMENT0..gl::COLOR_ATTACHMENT0 + colors).contains(&p) => true,
            _ => {
                self.error(
                    gl::INVALID_ENUM,
                    function,
                    format_args!("attachment 0x{point:04X}"),
                );
                false
            }
        }
    }

    /// Attaches a level of a 2D texture or a cube map face (`framebufferTexture2D`);
    /// `None` detaches. The texture's target must match `textarget` (`INVALID_OPERATION`) and
    /// the level be within the texture's range (`INVALID_VALUE`).
    pub fn framebuffer_texture_2d(
        &mut self,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: Option<crate::Texture>,
        level: i32,
    ) {
        const F: &str = "framebufferTexture2D";
        if self.webgl1_refuses("framebufferTexture2D", &[target, attachment]) {
            return;
        }
        let Some(fb) = self.bound_framebuffer(target, F) else {
            return;
        };
        if !self.check_attachment_point(attachment, F) {
            return;
        }
        let (bind, face) = match textarget {
            gl::TEXTURE_2D => (gl::TEXTURE_2D, 0),
            gl::TEXTURE_CUBE_MAP_POSITIVE_X..=gl::TEXTURE_CUBE_MAP_NEGATIVE_Z => (
                gl::TEXTURE_CUBE_MAP,
                textarget - gl::TEXTURE_CUBE_MAP_POSITIVE_X,
            ),
            _ => {
                return self.error(
                    gl::INVALID_ENUM,
                    F,
                    format_args!("textarget 0x{textarget:04X}"),
                )
            }
        };
        let image = match texture {
            None => None,
            Some(t) => {
                let Some(id) = self.attachable_texture(t, bind, level, F) else {
                    return;
                };
                Some(Attachment::Texture {
                    id,
                    level: level as u32,
                    layer: face,
                })
            }
        };
        self.objects.attach(fb, attachment, image);
    }

    /// Attaches a layer of a level of a 3D or 2D array texture (`framebufferTextureLayer`);
    /// `None` detaches. A layer past the texture's limit → `INVALID_VALUE`; another kind of
    /// texture → `INVALID_OPERATION`.
    pub fn framebuffer_texture_layer(
        &mut self,
        target: u32,
        attachment: u32,
        texture: Option<crate::Texture>,
        level: i32,
        layer: i32,
    ) {
        const F: &str = "framebufferTextureLayer";
        let Some(fb) = self.bound_framebuffer(target, F) else {
            return;
        };
        if !self.check_attachment_point(attachment, F) {
            return;
        }
        let image = match texture {
            None => None,
            Some(t) => {
                if !self.owns(t.ctx, F) {
                    return;
                }
                let kind = self.objects.textures.get(t.id).and_then(|o| o.target);
                let Some(kind @ (gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY)) = kind else {
                    return self.error(gl::INVALID_OPERATION, F, "not a 3D or 2D array texture");
                };
                let max = if kind == gl::TEXTURE_3D {
                    self.gpu.limits.max_texture_dimension_3d
                } else {
                    self.gpu.limits.max_texture_array_layers
                };
                if layer < 0 || layer as u32 >= max {
                    return self.error(gl::INVALID_VALUE, F, format_args!("layer {layer}"));
                }
                let Some(id) = self.attachable_texture(t, kind, level, F) else {
                    return;
                };
                Some(Attachment::Texture {
                    id,
                    level: level as u32,
                    layer: layer as u32,
                })
            }
        };
        self.objects.attach(fb, attachment, image);
    }

    /// A texture that may be attached at `level` as a `bind` texture, or the error.
    fn attachable_texture(
        &mut self,
        t: crate::Texture,
        bind: u32,
        level: i32,
        function: &str,
    ) -> Option<Id> {
        if !self.owns(t.ctx, function) {
            return None;
        }
        let Some(obj) = self.objects.textures.get(t.id) else {
            self.error(gl::INVALID_OPERATION, function, "deleted texture");
            return None;
        };
        if obj.target != Some(bind) {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "the texture's target does not match",
            );
            return None;
        }
        let max = match bind {
            gl::TEXTURE_3D => self.gpu.limits.max_texture_dimension_3d,
            _ => self.gpu.limits.max_texture_dimension_2d,
        };
        if level < 0 || level as u32 > 31 - max.leading_zeros() {
            self.error(gl::INVALID_VALUE, function, format_args!("level {level}"));
            return None;
        }
        if self.webgl1.on && level != 0 && !self.webgl1.fbo_render_mipmap {
            let what = "WebGL 1 attaches level 0 only, without OES_fbo_render_mipmap";
            self.error(gl::INVALID_VALUE, function, what);
            return None;
        }
        Some(t.id)
    }

    /// Attaches a renderbuffer (`framebufferRenderbuffer`); `None` detaches.
    pub fn framebuffer_renderbuffer(
        &mut self,
        target: u32,
        attachment: u32,
        renderbuffertarget: u32,
        renderbuffer: Option<crate::Renderbuffer>,
    ) {
        const F: &str = "framebufferRenderbuffer";
        if self.webgl1_refuses(
            "framebufferRenderbuffer",
            &[target, attachment, renderbuffertarget],
        ) {
            return;
        }
        let Some(fb) = self.bound_framebuffer(target, F) else {
            return;
        };
        if !self.check_attachment_point(attachment, F) {
            return;
        }
        if renderbuffertarget != gl::RENDERBUFFER {
            return self.error(
                gl::INVALID_ENUM,
                F,
                format_args!("renderbuffertarget 0x{renderbuffertarget:04X}"),
            );
        }
        let image = match renderbuffer {
            None => None,
            Some(r) => match self.renderbuffer_id(r, F) {
                Some(id) => Some(Attachment::Renderbuffer(id)),
                None => return,
            },
        };
        if let Some(Attachment::Renderbuffer(id)) = image {
            // A renderbuffer is an object only once bound (WebGL, as `bindRenderbuffer`).
            if self
                .objects
                .renderbuffers
                .get(id)
                .is_some_and(|r| !r.bound_once)
            {
                return self.error(gl::INVALID_OPERATION, F, "the renderbuffer was never bound");
            }
        }
        self.objects.attach(fb, attachment, image);
    }

    /// Selects where fragment outputs go (`drawBuffers`): entry `i` is `COLOR_ATTACHMENTi`
    /// or `NONE` for a framebuffer object, `BACK` or `NONE` (one entry) for the default one.
    pub fn draw_buffers(&mut self, buffers: &[u32]) {
        const F: &str = "drawBuffers";
        if buffers.len() > self.limits.max_color_attachments as usize {
            return self.error(gl::INVALID_VALUE, F, "more than MAX_DRAW_BUFFERS buffers");
        }
        let [draw, _] = self.bindings.framebuffers();
        match draw {
            None => {
                if buffers.len() != 1 || !matches!(buffers[0], gl::BACK | gl::NONE) {
                    return self.error(
                        gl::INVALID_OPERATION,
                        F,
                        "the default framebuffer takes one buffer, BACK or NONE",
                    );
                }
                self.fb.draw_buffer = buffers[0];
            }
            Some(id) => {
                for (i, &b) in buffers.iter().enumerate() {
                    if b != gl::NONE && b != gl::COLOR_ATTACHMENT0 + i as u32 {
                        let bad = b == gl::BACK
                            || (gl::COLOR_ATTACHMENT0..=gl::COLOR_ATTACHMENT15).contains(&b);
                        let code = if bad {
                            gl::INVALID_OPERATION
                        } else {
                            gl::INVALID_ENUM
                        };
                        return self.error(code, F, format_args!("buffer {i} is 0x{b:04X}"));
                    }
                }
                let f = self.objects.framebuffers.get_mut(id).expect("bound");
                for (i, slot) in f.draw_buffers.iter_mut().enumerate() {
                    *slot = buffers.get(i).copied().unwrap_or(gl::NONE);
                }
            }
        }
    }

    /// Selects the colour buffer reads come from (`readBuffer`): `BACK` or `NONE` for the
    /// default framebuffer, `COLOR_ATTACHMENTi` or `NONE` for a framebuffer object.
    pub fn read_buffer(&mut self, src: u32) {
        const F: &str = "readBuffer";
        let [_, read] = self.bindings.framebuffers();
        let color = (gl::COLOR_ATTACHMENT0..=gl::COLOR_ATTACHMENT15).contains(&src);
        if !(color || matches!(src, gl::BACK | gl::NONE)) {
            return self.error(gl::INVALID_ENUM, F, format_args!("0x{src:04X}"));
        }
        match read {
            None if color => self.error(
                gl::INVALID_OPERATION,
                F,
                "the default framebuffer reads BACK",
            ),
            None => self.fb.read_buffer = src,
            Some(_) if src == gl::BACK => {
                self.error(gl::INVALID_OPERATION, F, "a framebuffer object has no BACK")
            }
            Some(_) if src >= gl::COLOR_ATTACHMENT0 + self.limits.max_color_attachments => self
                .error(
                    gl::INVALID_OPERATION,
                    F,
                    "attachment ≥ MAX_COLOR_ATTACHMENTS",
                ),
            Some(id) => {
                self.objects
                    .framebuffers
                    .get_mut(id)
                    .expect("bound")
                    .read_buffer = src;
            }
        }
    }

    /// Tells the implementation the contents of attachments are no longer needed
    /// (`invalidateFramebuffer`). essl-gl keeps them, which GL allows; the arguments are
    /// checked as WebGL does.
    pub fn invalidate_framebuffer(&mut self, target: u32, attachments: &[u32]) {
        self.check_invalidate(target, attachments, "invalidateFramebuffer");
    }

    /// [`Context::invalidate_framebuffer`] for a rectangle (`invalidateSubFramebuffer`); a
    /// negative width or height → `INVALID_VALUE`.
    #[allow(clippy::too_many_arguments)] // WebGL2's own argument list
    pub fn invalidate_sub_framebuffer(
        &mut self,
        target: u32,
        attachments: &[u32],
        _x: i32,
        _y: i32,
        width: i32,
        height: i32,
    ) {
        const F: &str = "invalidateSubFramebuffer";
        if width < 0 || height < 0 {
            return self.error(gl::INVALID_VALUE, F, "negative width or height");
        }
        self.check_invalidate(target, attachments, F);
    }

    fn check_invalidate(&mut self, target: u32, attachments: &[u32], function: &str) {
        let Some((draw, _)) = target_slots(target) else {
            return self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("target 0x{target:04X}"),
            );
        };
        let [d, r] = self.bindings.framebuffers();
        let bound = if draw { d } else { r };
        for &a in attachments {
            let ok = match bound {
                None => matches!(a, gl::COLOR | gl::DEPTH | gl::STENCIL),
                Some(_) => {
                    matches!(
                        a,
                        gl::DEPTH_ATTACHMENT
                            | gl::STENCIL_ATTACHMENT
                            | gl::DEPTH_STENCIL_ATTACHMENT
                    ) || (gl::COLOR_ATTACHMENT0..=gl::COLOR_ATTACHMENT15).contains(&a)
                }
            };
            if !ok {
                return self.error(
                    gl::INVALID_ENUM,
                    function,
                    format_args!("attachment 0x{a:04X}"),
                );
            }
            if bound.is_some()
                && (gl::COLOR_ATTACHMENT0 + self.limits.max_color_attachments
                    ..=gl::COLOR_ATTACHMENT15)
                    .contains(&a)
            {
                return self.error(
                    gl::INVALID_OPERATION,
                    function,
                    "attachment ≥ MAX_COLOR_ATTACHMENTS",
                );
            }
        }
    }
}
