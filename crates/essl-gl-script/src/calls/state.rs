//! Fixed-function state, clears, the context's own queries and extensions.

use essl_gl::Context;

use super::{boolean, num, unsupported, void};
use crate::args::{Args, CallError};
use crate::value::{Object, TypedArray, Value};

pub(super) fn call(ctx: &mut Context, f: &str, a: &mut Args) -> Result<Option<Value>, CallError> {
    let v = match f {
        // Capabilities and fixed-function state.
        "enable" => void!(ctx.enable(a.u32()?)),
        "disable" => void!(ctx.disable(a.u32()?)),
        "isEnabled" => boolean(ctx.is_enabled(a.u32()?)),
        "viewport" => void!(ctx.viewport(a.i32()?, a.i32()?, a.i32()?, a.i32()?)),
        "scissor" => void!(ctx.scissor(a.i32()?, a.i32()?, a.i32()?, a.i32()?)),
        "clearColor" => void!(ctx.clear_color(a.f32()?, a.f32()?, a.f32()?, a.f32()?)),
        "clearDepth" => void!(ctx.clear_depth(a.f32()?)),
        "clearStencil" => void!(ctx.clear_stencil(a.i32()?)),
        "depthFunc" => void!(ctx.depth_func(a.u32()?)),
        "depthMask" => void!(ctx.depth_mask(a.bool()?)),
        "depthRange" => void!(ctx.depth_range(a.f32()?, a.f32()?)),
        "cullFace" => void!(ctx.cull_face(a.u32()?)),
        "frontFace" => void!(ctx.front_face(a.u32()?)),
        "blendFunc" => void!(ctx.blend_func(a.u32()?, a.u32()?)),
        "blendFuncSeparate" => {
            void!(ctx.blend_func_separate(a.u32()?, a.u32()?, a.u32()?, a.u32()?))
        }
        "blendEquation" => void!(ctx.blend_equation(a.u32()?)),
        "blendEquationSeparate" => void!(ctx.blend_equation_separate(a.u32()?, a.u32()?)),
        "blendColor" => void!(ctx.blend_color(a.f32()?, a.f32()?, a.f32()?, a.f32()?)),
        "colorMask" => void!(ctx.color_mask(a.bool()?, a.bool()?, a.bool()?, a.bool()?)),
        "polygonOffset" => void!(ctx.polygon_offset(a.f32()?, a.f32()?)),
        "sampleCoverage" => void!(ctx.sample_coverage(a.f32()?, a.bool()?)),
        "hint" => void!(ctx.hint(a.u32()?, a.u32()?)),
        "lineWidth" => void!(ctx.line_width(a.f32()?)),
        "pixelStorei" => void!(ctx.pixel_storei(a.u32()?, a.i32()?)),
        "stencilFunc" => void!(ctx.stencil_func(a.u32()?, a.i32()?, a.u32()?)),
        "stencilFuncSeparate" => {
            void!(ctx.stencil_func_separate(a.u32()?, a.u32()?, a.i32()?, a.u32()?))
        }
        "stencilOp" => void!(ctx.stencil_op(a.u32()?, a.u32()?, a.u32()?)),
        "stencilOpSeparate" => {
            void!(ctx.stencil_op_separate(a.u32()?, a.u32()?, a.u32()?, a.u32()?))
        }
        "stencilMask" => void!(ctx.stencil_mask(a.u32()?)),
        "stencilMaskSeparate" => void!(ctx.stencil_mask_separate(a.u32()?, a.u32()?)),

        // Clears.
        "clear" => void!(ctx.clear(a.u32()?)),
        "clearBufferfv" | "clearBufferiv" | "clearBufferuiv" => {
            let (buffer, drawbuffer) = (a.u32()?, a.i32()?);
            let kind = match f {
                "clearBufferfv" => "f32",
                "clearBufferiv" => "i32",
                _ => "u32",
            };
            let values = a.list(kind)?;
            let offset = a.opt_u32()? as usize;
            let Some(values) = values.window(offset, 0) else {
                return Err(unsupported(f, "a srcOffset past the end"));
            };
            match values {
                TypedArray::F32(v) if kind == "f32" => ctx.clear_bufferfv(buffer, drawbuffer, &v),
                TypedArray::I32(v) if kind == "i32" => ctx.clear_bufferiv(buffer, drawbuffer, &v),
                TypedArray::U32(v) if kind == "u32" => ctx.clear_bufferuiv(buffer, drawbuffer, &v),
                _ => return Err(CallError::Type(format!("{f}: an array of another type"))),
            }
            Value::Undefined
        }
        "clearBufferfi" => void!(ctx.clear_bufferfi(a.u32()?, a.i32()?, a.f32()?, a.i32()?)),

        // The context.
        "getError" => num(ctx.get_error()),
        "finish" => void!(ctx.finish()),
        "flush" => void!(ctx.flush()),
        "isContextLost" => boolean(ctx.is_context_lost()),
        "getParameter" => Value::from(ctx.get_parameter(a.u32()?)),
        "getContextAttributes" => {
            let c = ctx.get_context_attributes();
            let b = |k: &str, v: bool| (k.to_string(), Value::Bool(v));
            Value::Dict(vec![
                b("alpha", c.alpha),
                b("depth", c.depth),
                b("stencil", c.stencil),
                b("antialias", c.antialias),
                b("premultipliedAlpha", c.premultiplied_alpha),
                b("preserveDrawingBuffer", c.preserve_drawing_buffer),
                b(
                    "failIfMajorPerformanceCaveat",
                    c.fail_if_major_performance_caveat,
                ),
            ])
        }
        "getSupportedExtensions" => Value::List(
            ctx.get_supported_extensions()
                .into_iter()
                .map(|e| Value::Str(e.to_string()))
                .collect(),
        ),
        "getExtension" => {
            let name = a.string()?;
            match ctx.get_extension(&name) {
                Some(e) => Value::Object(Object::Extension(e.name())),
                None => Value::Null,
            }
        }
        "drawingBufferStorage" => void!(ctx.drawing_buffer_storage(a.u32()?, a.u32()?, a.u32()?)),
        _ => return Ok(None),
    };
    Ok(Some(v))
}
