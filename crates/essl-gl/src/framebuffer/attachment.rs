//! `get_framebuffer_attachment_parameter`: what is attached where, and its format's sizes,
//! component type and colour encoding.

use super::Attachment;
use crate::context::Context;
use crate::gl;
use crate::objects::{Renderbuffer, Texture};
use crate::query::Parameter;
use crate::texture::{bit_sizes, internal_format, InternalFormat, SampleKind};

/// GL's `FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE` of a format.
fn component_type(f: &InternalFormat) -> u32 {
    use crate::texture::Comp;
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
        &mut self,
        target: u32,
        attachment: u32,
        pname: u32,
    ) -> Option<Parameter> {
        const F: &str = "getFramebufferAttachmentParameter";
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
            ..gl::COLOR_ATTACHMENT0 + super::MAX_COLOR_ATTACHMENTS)
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
            (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, _) => return Some(object),
            (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Some(Attachment::Texture { .. })) => {
                return Some(Parameter::Enum(gl::TEXTURE))
            }
            (gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Some(Attachment::Renderbuffer(_))) => {
                return Some(Parameter::Enum(gl::RENDERBUFFER))
            }
            _ => {}
        }
        let Some(image) = image else {
            if is_attachment_pname(pname) {
                self.error(gl::INVALID_OPERATION, F, "nothing is attached");
            } else {
                self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
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
            _ => format.and_then(|f| format_parameter(&f, pname, attachment)),
        };
        if value.is_none() {
            self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
        }
        value
    }

    /// `getFramebufferAttachmentParameter` on the default framebuffer: `BACK`, `DEPTH`,
    /// `STENCIL`.
    fn default_attachment_parameter(&mut self, attachment: u32, pname: u32) -> Option<Parameter> {
        const F: &str = "getFramebufferAttachmentParameter";
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
            (_, None) if is_attachment_pname(pname) => {
                self.error(gl::INVALID_OPERATION, F, "the default framebuffer has none");
                return None;
            }
            (_, Some(f)) => {
                let f = internal_format(f).expect("a supported format");
                format_parameter(&f, pname, attachment)
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

/// The format-derived parameters: bit sizes (of the attachment point's aspect), component
/// type, colour encoding.
fn format_parameter(f: &InternalFormat, pname: u32, attachment: u32) -> Option<Parameter> {
    let b = bit_sizes(f);
    let depth_point = matches!(attachment, gl::DEPTH_ATTACHMENT | gl::DEPTH);
    let stencil_point = matches!(attachment, gl::STENCIL_ATTACHMENT | gl::STENCIL);
    let int = |v: u32| Some(Parameter::Int(v as i64));
    match pname {
        gl::FRAMEBUFFER_ATTACHMENT_RED_SIZE => int(b.red),
        gl::FRAMEBUFFER_ATTACHMENT_GREEN_SIZE => int(b.green),
        gl::FRAMEBUFFER_ATTACHMENT_BLUE_SIZE => int(b.blue),
        gl::FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE => int(b.alpha),
        gl::FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE => int(if stencil_point { 0 } else { b.depth }),
        gl::FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE => int(if depth_point { 0 } else { b.stencil }),
        gl::FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE => Some(Parameter::Enum(if stencil_point {
            gl::UNSIGNED_INT
        } else {
            component_type(f)
        })),
        gl::FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING => {
            Some(Parameter::Enum(if f.srgb { gl::SRGB } else { gl::LINEAR }))
        }
        _ => None,
    }
}
