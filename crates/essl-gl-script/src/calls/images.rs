//! Textures, samplers, renderbuffers, framebuffers, blits, copies and `readPixels`.

use essl_gl::{Context, Framebuffer, Renderbuffer, Sampler, Texture};

use super::{boolean, num, unsupported, void};
use crate::args::{Args, CallError};
use crate::value::{with_elements, Object, TypedArray, Value};

pub(super) fn call(ctx: &mut Context, f: &str, a: &mut Args) -> Result<Option<Value>, CallError> {
    if let Some(v) = textures(ctx, f, a)? {
        return Ok(Some(v));
    }
    framebuffers(ctx, f, a)
}

/// Textures and samplers.
fn textures(ctx: &mut Context, f: &str, a: &mut Args) -> Result<Option<Value>, CallError> {
    let v = match f {
        // Textures.
        "createTexture" => Value::Object(Object::Texture(ctx.create_texture())),
        "isTexture" => boolean(a.object::<Texture>()?.is_some_and(|t| ctx.is_texture(t))),
        "deleteTexture" => void!(a.object::<Texture>()?.map(|t| ctx.delete_texture(t))),
        "activeTexture" => void!(ctx.active_texture(a.u32()?)),
        "bindTexture" => void!(ctx.bind_texture(a.u32()?, a.object()?)),
        "texParameteri" => void!(ctx.tex_parameteri(a.u32()?, a.u32()?, a.i32()?)),
        "texParameterf" => void!(ctx.tex_parameterf(a.u32()?, a.u32()?, a.f32()?)),
        "getTexParameter" => Value::from(ctx.get_tex_parameter(a.u32()?, a.u32()?)),
        "generateMipmap" => void!(ctx.generate_mipmap(a.u32()?)),
        "texStorage2D" => {
            void!(ctx.tex_storage_2d(a.u32()?, a.i32()?, a.u32()?, a.i32()?, a.i32()?))
        }
        "texStorage3D" => {
            void!(ctx.tex_storage_3d(a.u32()?, a.i32()?, a.u32()?, a.i32()?, a.i32()?, a.i32()?))
        }
        "texImage2D" | "texImage3D" | "texSubImage2D" | "texSubImage3D" => tex_image(ctx, f, a)?,
        "copyTexImage2D" => void!(ctx.copy_tex_image_2d(
            a.u32()?,
            a.i32()?,
            a.u32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?
        )),
        "copyTexSubImage2D" => void!(ctx.copy_tex_sub_image_2d(
            a.u32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?
        )),
        "copyTexSubImage3D" => void!(ctx.copy_tex_sub_image_3d(
            a.u32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?
        )),
        "compressedTexImage2D"
        | "compressedTexImage3D"
        | "compressedTexSubImage2D"
        | "compressedTexSubImage3D" => compressed(ctx, f, a)?,

        // Samplers.
        "createSampler" => Value::Object(Object::Sampler(ctx.create_sampler())),
        "isSampler" => boolean(a.object::<Sampler>()?.is_some_and(|s| ctx.is_sampler(s))),
        "deleteSampler" => void!(a.object::<Sampler>()?.map(|s| ctx.delete_sampler(s))),
        "bindSampler" => void!(ctx.bind_sampler(a.u32()?, a.object()?)),
        "samplerParameteri" => {
            void!(ctx.sampler_parameteri(a.required()?, a.u32()?, a.i32()?))
        }
        "samplerParameterf" => {
            void!(ctx.sampler_parameterf(a.required()?, a.u32()?, a.f32()?))
        }
        "getSamplerParameter" => Value::from(ctx.get_sampler_parameter(a.required()?, a.u32()?)),
        _ => return Ok(None),
    };
    Ok(Some(v))
}

/// Renderbuffers, framebuffers, blits and reads.
fn framebuffers(ctx: &mut Context, f: &str, a: &mut Args) -> Result<Option<Value>, CallError> {
    let v = match f {
        // Renderbuffers.
        "createRenderbuffer" => Value::Object(Object::Renderbuffer(ctx.create_renderbuffer())),
        "isRenderbuffer" => boolean(
            a.object::<Renderbuffer>()?
                .is_some_and(|r| ctx.is_renderbuffer(r)),
        ),
        "deleteRenderbuffer" => {
            void!(a
                .object::<Renderbuffer>()?
                .map(|r| ctx.delete_renderbuffer(r)))
        }
        "bindRenderbuffer" => void!(ctx.bind_renderbuffer(a.u32()?, a.object()?)),
        "renderbufferStorage" => {
            void!(ctx.renderbuffer_storage(a.u32()?, a.u32()?, a.i32()?, a.i32()?))
        }
        "renderbufferStorageMultisample" => void!(ctx.renderbuffer_storage_multisample(
            a.u32()?,
            a.i32()?,
            a.u32()?,
            a.i32()?,
            a.i32()?
        )),
        "getRenderbufferParameter" => {
            Value::from(ctx.get_renderbuffer_parameter(a.u32()?, a.u32()?))
        }
        "getInternalformatParameter" => {
            Value::from(ctx.get_internalformat_parameter(a.u32()?, a.u32()?, a.u32()?))
        }

        // Framebuffers.
        "createFramebuffer" => Value::Object(Object::Framebuffer(ctx.create_framebuffer())),
        "isFramebuffer" => boolean(
            a.object::<Framebuffer>()?
                .is_some_and(|fb| ctx.is_framebuffer(fb)),
        ),
        "deleteFramebuffer" => {
            void!(a
                .object::<Framebuffer>()?
                .map(|fb| ctx.delete_framebuffer(fb)))
        }
        "bindFramebuffer" => void!(ctx.bind_framebuffer(a.u32()?, a.object()?)),
        "framebufferTexture2D" => {
            void!(ctx.framebuffer_texture_2d(a.u32()?, a.u32()?, a.u32()?, a.object()?, a.i32()?))
        }
        "framebufferTextureLayer" => void!(ctx.framebuffer_texture_layer(
            a.u32()?,
            a.u32()?,
            a.object()?,
            a.i32()?,
            a.i32()?
        )),
        "framebufferRenderbuffer" => {
            void!(ctx.framebuffer_renderbuffer(a.u32()?, a.u32()?, a.u32()?, a.object()?))
        }
        "checkFramebufferStatus" => num(ctx.check_framebuffer_status(a.u32()?)),
        "getFramebufferAttachmentParameter" => {
            Value::from(ctx.get_framebuffer_attachment_parameter(a.u32()?, a.u32()?, a.u32()?))
        }
        "drawBuffers" => {
            let TypedArray::U32(buffers) = a.list("u32")? else {
                return Err(CallError::Type("drawBuffers: not a sequence".into()));
            };
            void!(ctx.draw_buffers(&buffers))
        }
        "readBuffer" => void!(ctx.read_buffer(a.u32()?)),
        "invalidateFramebuffer" => {
            let target = a.u32()?;
            let TypedArray::U32(list) = a.list("u32")? else {
                return Err(CallError::Type(format!("{f}: not a sequence")));
            };
            void!(ctx.invalidate_framebuffer(target, &list))
        }
        "invalidateSubFramebuffer" => {
            let target = a.u32()?;
            let TypedArray::U32(list) = a.list("u32")? else {
                return Err(CallError::Type(format!("{f}: not a sequence")));
            };
            void!(ctx.invalidate_sub_framebuffer(
                target,
                &list,
                a.i32()?,
                a.i32()?,
                a.i32()?,
                a.i32()?
            ))
        }
        "blitFramebuffer" => void!(ctx.blit_framebuffer(
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.i32()?,
            a.u32()?,
            a.u32()?
        )),
        "readPixels" => {
            let (x, y, w, h) = (a.i32()?, a.i32()?, a.i32()?, a.i32()?);
            let (format, ty) = (a.u32()?, a.u32()?);
            if a.is_number(6) {
                ctx.read_pixels_to_buffer(x, y, w, h, format, ty, a.i64()?);
                return Ok(Some(Value::Undefined));
            }
            let offset = a.opt_u32_at(7) as usize;
            let Some(dst) = a.view()? else {
                return Err(unsupported(f, "a null destination"));
            };
            if offset > dst.len() {
                return Err(unsupported(f, "a dstOffset past the end"));
            }
            with_elements!(dst, s => ctx.read_pixels(x, y, w, h, format, ty, &mut s[offset..]));
            Value::Undefined
        }
        _ => return Ok(None),
    };
    Ok(Some(v))
}

/// `texImage2D`, `texImage3D`, `texSubImage2D` and `texSubImage3D` with client data (a
/// typed array or `null`, and an optional `srcOffset`) or an offset into the bound
/// `PIXEL_UNPACK_BUFFER`.
fn tex_image(ctx: &mut Context, f: &str, a: &mut Args) -> Result<Value, CallError> {
    let three_d = f.ends_with("3D");
    let sub = f.starts_with("texSub");
    // Arguments before the data: target, level, then the image's or box's numbers.
    let before = match (sub, three_d) {
        (false, false) => 8,
        (false, true) => 9,
        (true, false) => 8,
        (true, true) => 10,
    };
    if a.len() < before + 1 {
        return Err(unsupported(f, "the TexImageSource overload"));
    }
    let target = a.u32()?;
    let level = a.i32()?;
    // texImage: internalformat, w, h, [d], border; texSub: x, y, [z], w, h, [d].
    let mut n = [0i32; 7];
    let count = before - 4;
    for v in n.iter_mut().take(count) {
        *v = a.i32()?;
    }
    let (format, ty) = (a.u32()?, a.u32()?);
    if a.is_number(before) {
        let offset = a.i64()?;
        match (sub, three_d) {
            (false, false) => ctx.tex_image_2d_from_buffer(
                target, level, n[0], n[1], n[2], n[3], format, ty, offset,
            ),
            (false, true) => ctx.tex_image_3d_from_buffer(
                target, level, n[0], n[1], n[2], n[3], n[4], format, ty, offset,
            ),
            (true, false) => ctx.tex_sub_image_2d_from_buffer(
                target, level, n[0], n[1], n[2], n[3], format, ty, offset,
            ),
            (true, true) => ctx.tex_sub_image_3d_from_buffer(
                target, level, n[0], n[1], n[2], n[3], n[4], n[5], format, ty, offset,
            ),
        }
        return Ok(Value::Undefined);
    }
    let data = a.view()?.cloned();
    let offset = a.opt_u32()? as usize;
    let data = match data {
        Some(d) => Some(
            d.window(offset, 0)
                .ok_or_else(|| unsupported(f, "a srcOffset past the end"))?,
        ),
        None if sub => return Err(unsupported(f, "null pixels")),
        None => None,
    };
    match (&data, sub, three_d) {
        (None, _, false) => ctx.tex_image_2d(
            target,
            level,
            n[0],
            n[1],
            n[2],
            n[3],
            format,
            ty,
            None::<&[u8]>,
        ),
        (None, _, true) => ctx.tex_image_3d(
            target,
            level,
            n[0],
            n[1],
            n[2],
            n[3],
            n[4],
            format,
            ty,
            None::<&[u8]>,
        ),
        (Some(d), false, false) => with_elements!(d, s => ctx.tex_image_2d(
            target, level, n[0], n[1], n[2], n[3], format, ty, Some(&s[..])
        )),
        (Some(d), false, true) => with_elements!(d, s => ctx.tex_image_3d(
            target, level, n[0], n[1], n[2], n[3], n[4], format, ty, Some(&s[..])
        )),
        (Some(d), true, false) => with_elements!(d, s => ctx.tex_sub_image_2d(
            target, level, n[0], n[1], n[2], n[3], format, ty, &s[..]
        )),
        (Some(d), true, true) => with_elements!(d, s => ctx.tex_sub_image_3d(
            target, level, n[0], n[1], n[2], n[3], n[4], n[5], format, ty, &s[..]
        )),
    }
    Ok(Value::Undefined)
}

/// The compressed-texture entry points (essl-gl offers no compressed format, so each
/// answers `INVALID_ENUM`); the `imageSize, offset` overloads pass no data.
fn compressed(ctx: &mut Context, f: &str, a: &mut Args) -> Result<Value, CallError> {
    let (target, level) = (a.u32()?, a.i32()?);
    let count = match f {
        "compressedTexImage2D" => 4,
        "compressedTexImage3D" => 5,
        "compressedTexSubImage2D" => 5,
        _ => 7,
    };
    // texImage: internalformat, w, h, [d], border; texSub: x, y, [z], w, h, [d], format.
    let mut n = [0i64; 7];
    for v in n.iter_mut().take(count) {
        *v = a.i64()?;
    }
    let data: Vec<u8> = match a.peek(2 + count) {
        Some(Value::Typed(d)) => with_elements!(d, s => bytemuck_bytes(s)),
        _ => Vec::new(),
    };
    let i = |k: usize| n[k] as i32;
    let u = |k: usize| n[k] as u32;
    match f {
        "compressedTexImage2D" => {
            ctx.compressed_tex_image_2d(target, level, u(0), i(1), i(2), i(3), &data)
        }
        "compressedTexImage3D" => {
            ctx.compressed_tex_image_3d(target, level, u(0), i(1), i(2), i(3), i(4), &data)
        }
        "compressedTexSubImage2D" => {
            ctx.compressed_tex_sub_image_2d(target, level, i(0), i(1), i(2), i(3), u(4), &data)
        }
        _ => ctx.compressed_tex_sub_image_3d(
            target,
            level,
            i(0),
            i(1),
            i(2),
            i(3),
            i(4),
            i(5),
            u(6),
            &data,
        ),
    }
    Ok(Value::Undefined)
}

/// The bytes of a slice of numbers, in the machine's order (as a typed array's buffer).
fn bytemuck_bytes<T: essl_gl::bytemuck::NoUninit>(s: &[T]) -> Vec<u8> {
    essl_gl::bytemuck::cast_slice(s).to_vec()
}
