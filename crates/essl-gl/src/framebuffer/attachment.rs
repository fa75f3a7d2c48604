//! `get_framebuffer_attachment_parameter`: what is attached where, and its format's sizes,
//! component type and colour encoding.

use super::Attachment;
use crate::context::Context;
use crate::gl;
use crate::objects::{Renderbuffer, Texture};
use crate::query::Parameter;
use crate::texture::{bit_sizes, internal_format, InternalFormat, SampleKind};

/// GL's `FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE` of a format, whichever point it is attached
/// at: a combined depth-stencil format answers its depth's type at `STENCIL_ATTACHMENT` too
/// (Chromium's answer, and ANGLE's format table), `STENCIL_INDEX8` answers `UNSIGNED_INT`.
fn component_type(f: &InternalFormat) -> u32 {
    use crate::texture::Comp;
    if f.packing == crate::texture::Packing::Stencil8 {
        return gl::UNSIGNED_INT;
    }
    match f.kind() {
        SampleKind::Sint => gl::INT,
        SampleKind::Uint => gl::UNSIGNED_INT,
        _ if f.has_depth() => match f.packing {
            crate::texture::Packing::Depth32F | crate::texture::Packing::Depth32FStencil8 => {
                gl::FLOAT
            }
            _ => gl::UNSIGNED_NORMALIZED,
        },
        _ => match (f.packing, f.comp) {
            (crate::texture::Packing::Rgb10A2, _) => gl::UNSIGNED_NORMALIZED,
            (crate::texture::Packing::None, Comp::Snorm8) => gl::SIGNED_NORMALIZED,
            (crate::texture::Packing::None, Comp::Unorm8) => gl::UNSIGNED_NORMALIZED,
            _ => gl::FLOAT,
        },
    }
}

impl Context {
    /// A parameter of what is attached at `attachment` of the framebuffer bound to `target`
    /// (`getFramebufferAttachmentParameter`): `FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE` (`NONE`,
    /// `TEXTURE`, `RENDERBUFFER`, or `FRAMEBUFFER_DEFAULT`), `_OBJECT_NAME`, `_TEXTURE_LEVEL`,
    /// `_TEXTURE_CUBE_MAP_FACE`, `_TEXTURE_LAYER`, the bit sizes `_RED_SIZE` …
    /// `_STENCIL_SIZE`, `_COMPONENT_TYPE` and `_COLOR_ENCODING`. With nothing attached only
    /// the object type and name may be asked (`INVALID_OPERATION` otherwise), as in ES 3.0.
    pub fn get_framebuffer_attachment_parameter(
        &self,
        target: u32,
        attachment: u32,
        pname: u32,
    ) -> Option<Parameter> {
        const F: &str = "getFramebufferAttachmentParameter";
        if self.webgl1_refuses(
            "getFramebufferAttachmentParameter",
            &[target, attachment, pname],
        ) {
            return None;
        }
        let [d, r] = self.bindings.framebuffers();
        let bound = match target {
            gl::FRAMEBUFFER | gl::DRAW_FRAMEBUFFER => d,
            gl::READ_FRAMEBUFFER => r,
            _ => {
                self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
                return None;
            }
        };
        let Some(fb) = bound else {
            return self.default_attachment_parameter(attachment, pname);
        };
        let point_ok = matches!(
            attachment,
            gl::DEPTH_ATTACHMENT | gl::STENCIL_ATTACHMENT | gl::DEPTH_STENCIL_ATTACHMENT
        ) || (gl::COLOR_ATTACHMENT0
            ..gl::COLOR_ATTACHMENT0 + self.limits.max_color_attachments)
            .contains(&attachment);
        if !point_ok {
            self.error(
                gl::INVALID_ENUM,
                F,
                format_args!("attachment 0x{attachment:04X}"),
            );
            return None;
        }
        let f = self.objects.framebuffers.get_any(fb)?;
        if attachment == gl::DEPTH_STENCIL_ATTACHMENT && f.depth != f.stencil {
            self.error(
                gl::INVALID_OPERATION,
                F,
                "different images are attached to depth and stencil",
            );
            return None;
        }
        let image = f.attachment(attachment);
        let ctx = self.id;
        let object = match image {
            None => Parameter::Null,
            Some(Attachment::Texture { id, .. }) => Parameter::Texture(Some(Texture { ctx, id })),
            Some(Attachment::Renderbuffer(id)) => {
                Parameter::Renderbuffer(Some(Renderbuffer { ctx, id }))
            }
        };
        match (pname, image) {
            (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, None) => {
                return Some(Parameter::Enum(gl::NONE))
            }
            // ES 2.0 answers only OBJECT_TYPE where nothing is attached (below).
            (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, _) if image.is_some() || !self.webgl1.on => {
                return Some(object)
            }
            (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Some(Attachment::Texture { .. })) => {
                return Some(Parameter::Enum(gl::TEXTURE))
            }
            (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Some(Attachment::Renderbuffer(_))) => {
                return Some(Parameter::Enum(gl::RENDERBUFFER))
            }
            _ => {}
        }
        let Some(image) = image else {
            // ES 2.0 answers only OBJECT_TYPE where nothing is attached (INVALID_ENUM); WebGL 2,
            // as Chromium, INVALID_OPERATION whatever else is asked.
            if self.webgl1.on {
                self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
            } else {
                self.error(gl::INVALID_OPERATION, F, "nothing is attached");
            }
            return None;
        };
        let format = self.image_info(image).map(|i| i.format);
        let texture = match image {
            Attachment::Texture { id, level, layer } => Some((id, level, layer)),
            Attachment::Renderbuffer(_) => None,
        };
        let value = match pname {
            gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL => texture.map(|t| Parameter::Int(t.1 as i64)),
            gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE => texture.map(|(id, _, layer)| {
                let cube = self
                    .objects
                    .textures
                    .get_any(id)
                    .is_some_and(|t| t.face_count() == 6);
                Parameter::Enum(if cube {
                    gl::TEXTURE_CUBE_MAP_POSITIVE_X + layer
                } else {
                    gl::NONE
                })
            }),
            gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER => texture.map(|(id, _, layer)| {
                let layered = self.objects.textures.get_any(id).is_some_and(|t| {
                    matches!(t.target, Some(gl::TEXTURE_3D | gl::TEXTURE_2D_ARRAY))
                });
                Parameter::Int(if layered { layer as i64 } else { 0 })
            }),
            gl::FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE
                if attachment == gl::DEPTH_STENCIL_ATTACHMENT =>
            {
                self.error(
                    gl::INVALID_OPERATION,
                    F,
                    "COMPONENT_TYPE of DEPTH_STENCIL_ATTACHMENT",
                );
                return None;
            }
            _ => format.and_then(|f| format_parameter(&f, pname)),
        };
        if value.is_none() {
            self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
        }
        value
    }

    /// `getFramebufferAttachmentParameter` on the default framebuffer: `BACK`, `DEPTH`,
    /// `STENCIL`.
    fn default_attachment_parameter(&self, attachment: u32, pname: u32) -> Option<Parameter> {
        const F: &str = "getFramebufferAttachmentParameter";
        if self.webgl1.on {
            // WebGL 1 queries framebuffer objects only.
            self.error(
                gl::INVALID_OPERATION,
                F,
                "no framebuffer is bound (WebGL 1)",
            );
            return None;
        }
        let a = self.fb.attributes;
        let format = match attachment {
            gl::BACK => Some(if a.alpha { gl::RGBA8 } else { gl::RGB8 }),
            gl::DEPTH => a.depth.then_some(gl::DEPTH_COMPONENT24),
            gl::STENCIL => a.stencil.then_some(gl::STENCIL_INDEX8),
            _ => {
                self.error(
                    gl::INVALID_ENUM,
                    F,
                    format_args!("attachment 0x{attachment:04X}"),
                );
                return None;
            }
        };
        let value = match (pname, format) {
            (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Some(_)) => {
                Some(Parameter::Enum(gl::FRAMEBUFFER_DEFAULT))
            }
            (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, None) => Some(Parameter::Enum(gl::NONE)),
            (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, _) => Some(Parameter::Null),
            // Chromium: the default stencil buffer is part of a normalized depth-stencil one.
            (gl::FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, Some(gl::STENCIL_INDEX8)) => {
                Some(Parameter::Enum(gl::UNSIGNED_NORMALIZED))
            }
            (_, None) if is_attachment_pname(pname) => {
                self.error(gl::INVALID_OPERATION, F, "the default framebuffer has none");
                return None;
            }
            (_, Some(f)) => {
                let f = internal_format(f).expect("a supported format");
                format_parameter(&f, pname)
            }
            _ => None,
        };
        if value.is_none() {
            self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
        }
        value
    }
}

/// Whether `pname` is one of `getFramebufferAttachmentParameter`'s.
fn is_attachment_pname(pname: u32) -> bool {
    matches!(
        pname,
        gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL
            | gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE
            | gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER
            | gl::FRAMEBUFFER_ATTACHMENT_RED_SIZE
            | gl::FRAMEBUFFER_ATTACHMENT_GREEN_SIZE
            | gl::FRAMEBUFFER_ATTACHMENT_BLUE_SIZE
            | gl::FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE
            | gl::FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE
            | gl::FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE
            | gl::FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE
            | gl::FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING
    )
}

/// The format-derived parameters: bit sizes, component type, colour encoding — of the
/// attached image's format, whichever aspect the point uses (`DEPTH_ATTACHMENT` of a
/// `DEPTH24_STENCIL8` image answers `STENCIL_SIZE` 8, as Chromium does).
fn format_parameter(f: &InternalFormat, pname: u32) -> Option<Parameter> {
    let b = bit_sizes(f);
    let int = |v: u32| Some(Parameter::Int(v as i64));
    match pname {
        gl::FRAMEBUFFER_ATTACHMENT_RED_SIZE => int(b.red),
        gl::FRAMEBUFFER_ATTACHMENT_GREEN_SIZE => int(b.green),
        gl::FRAMEBUFFER_ATTACHMENT_BLUE_SIZE => int(b.blue),
        gl::FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE => int(b.alpha),
        gl::FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE => int(b.depth),
        gl::FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE => int(b.stencil),
        gl::FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE => Some(Parameter::Enum(component_type(f))),
        gl::FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING => {
            Some(Parameter::Enum(if f.srgb { gl::SRGB } else { gl::LINEAR }))
        }
        _ => None,
    }
}
