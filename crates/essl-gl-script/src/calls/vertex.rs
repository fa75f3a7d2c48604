//! Buffers, vertex arrays, vertex attributes and draws.

use essl_gl::{Buffer, Context, VertexArray};

use super::{boolean, num, unsupported, void};
use crate::args::{Args, CallError};
use crate::value::{with_elements, Object, TypedArray, Value};

pub(super) fn call(ctx: &mut Context, f: &str, a: &mut Args) -> Result<Option<Value>, CallError> {
    let v = match f {
        // Buffers.
        "createBuffer" => Value::Object(Object::Buffer(ctx.create_buffer())),
        "isBuffer" => boolean(a.object::<Buffer>()?.is_some_and(|b| ctx.is_buffer(b))),
        "deleteBuffer" => void!(a.object::<Buffer>()?.map(|b| ctx.delete_buffer(b))),
        "bindBuffer" => void!(ctx.bind_buffer(a.u32()?, a.object()?)),
        "bindBufferBase" => void!(ctx.bind_buffer_base(a.u32()?, a.u32()?, a.object()?)),
        "bindBufferRange" => {
            void!(ctx.bind_buffer_range(a.u32()?, a.u32()?, a.object()?, a.i64()?, a.i64()?))
        }
        "bufferData" => buffer_data(ctx, a)?,
        "bufferSubData" => {
            let (target, offset) = (a.u32()?, a.i64()?);
            let data = source(f, a)?;
            with_elements!(&data, s => ctx.buffer_sub_data(target, offset, s));
            Value::Undefined
        }
        "getBufferSubData" => {
            let (target, offset) = (a.u32()?, a.i64()?);
            let (dst_offset, length) = (a.opt_u32_at(3) as usize, a.opt_u32_at(4) as usize);
            let Some(dst) = a.view()? else {
                return Err(CallError::Type("getBufferSubData: null destination".into()));
            };
            let end = if length == 0 {
                dst.len()
            } else {
                dst_offset + length
            };
            if dst_offset > dst.len() || end > dst.len() {
                return Err(unsupported(f, "a dstOffset or length past the end"));
            }
            with_elements!(dst, s => ctx.get_buffer_sub_data(target, offset, &mut s[dst_offset..end]));
            Value::Undefined
        }
        "copyBufferSubData" => {
            void!(ctx.copy_buffer_sub_data(a.u32()?, a.u32()?, a.i64()?, a.i64()?, a.i64()?))
        }
        "getBufferParameter" => Value::from(ctx.get_buffer_parameter(a.u32()?, a.u32()?)),

        // Vertex arrays and attributes.
        "createVertexArray" => Value::Object(Object::VertexArray(ctx.create_vertex_array())),
        "isVertexArray" => boolean(
            a.object::<VertexArray>()?
                .is_some_and(|v| ctx.is_vertex_array(v)),
        ),
        "deleteVertexArray" => {
            void!(a
                .object::<VertexArray>()?
                .map(|v| ctx.delete_vertex_array(v)))
        }
        "bindVertexArray" => void!(ctx.bind_vertex_array(a.object()?)),
        "enableVertexAttribArray" => void!(ctx.enable_vertex_attrib_array(a.u32()?)),
        "disableVertexAttribArray" => void!(ctx.disable_vertex_attrib_array(a.u32()?)),
        "vertexAttribPointer" => void!(ctx.vertex_attrib_pointer(
            a.u32()?,
            a.i32()?,
            a.u32()?,
            a.bool()?,
            a.i32()?,
            a.i64()?
        )),
        "vertexAttribIPointer" => {
            void!(ctx.vertex_attrib_i_pointer(a.u32()?, a.i32()?, a.u32()?, a.i32()?, a.i64()?))
        }
        "vertexAttribDivisor" => void!(ctx.vertex_attrib_divisor(a.u32()?, a.u32()?)),
        "vertexAttrib1f" => void!(ctx.vertex_attrib1f(a.u32()?, a.f32()?)),
        "vertexAttrib2f" => void!(ctx.vertex_attrib2f(a.u32()?, a.f32()?, a.f32()?)),
        "vertexAttrib3f" => void!(ctx.vertex_attrib3f(a.u32()?, a.f32()?, a.f32()?, a.f32()?)),
        "vertexAttrib4f" => {
            void!(ctx.vertex_attrib4f(a.u32()?, a.f32()?, a.f32()?, a.f32()?, a.f32()?))
        }
        "vertexAttrib1fv" | "vertexAttrib2fv" | "vertexAttrib3fv" | "vertexAttrib4fv" => {
            let index = a.u32()?;
            let TypedArray::F32(v) = a.list("f32")? else {
                return Err(CallError::Type(format!("{f}: not a Float32List")));
            };
            match f {
                "vertexAttrib1fv" => ctx.vertex_attrib1fv(index, &v),
                "vertexAttrib2fv" => ctx.vertex_attrib2fv(index, &v),
                "vertexAttrib3fv" => ctx.vertex_attrib3fv(index, &v),
                _ => ctx.vertex_attrib4fv(index, &v),
            }
            Value::Undefined
        }
        "vertexAttribI4i" => {
            void!(ctx.vertex_attrib_i4i(a.u32()?, a.i32()?, a.i32()?, a.i32()?, a.i32()?))
        }
        "vertexAttribI4ui" => {
            void!(ctx.vertex_attrib_i4ui(a.u32()?, a.u32()?, a.u32()?, a.u32()?, a.u32()?))
        }
        "vertexAttribI4iv" => {
            let index = a.u32()?;
            let TypedArray::I32(v) = a.list("i32")? else {
                return Err(CallError::Type(format!("{f}: not an Int32List")));
            };
            void!(ctx.vertex_attrib_i4iv(index, &v))
        }
        "vertexAttribI4uiv" => {
            let index = a.u32()?;
            let TypedArray::U32(v) = a.list("u32")? else {
                return Err(CallError::Type(format!("{f}: not a Uint32List")));
            };
            void!(ctx.vertex_attrib_i4uiv(index, &v))
        }
        "getVertexAttrib" => Value::from(ctx.get_vertex_attrib(a.u32()?, a.u32()?)),
        "getVertexAttribOffset" => num(ctx.get_vertex_attrib_offset(a.u32()?, a.u32()?) as f64),

        // Draws.
        "drawArrays" => void!(ctx.draw_arrays(a.u32()?, a.i32()?, a.i32()?)),
        "drawArraysInstanced" => {
            void!(ctx.draw_arrays_instanced(a.u32()?, a.i32()?, a.i32()?, a.i32()?))
        }
        "drawElements" => void!(ctx.draw_elements(a.u32()?, a.i32()?, a.u32()?, a.i64()?)),
        "drawElementsInstanced" => {
            void!(ctx.draw_elements_instanced(a.u32()?, a.i32()?, a.u32()?, a.i64()?, a.i32()?))
        }
        "drawRangeElements" => void!(ctx.draw_range_elements(
            a.u32()?,
            a.u32()?,
            a.u32()?,
            a.i32()?,
            a.u32()?,
            a.i64()?
        )),
        _ => return Ok(None),
    };
    Ok(Some(v))
}

/// `bufferData(target, size, usage)`, `bufferData(target, data, usage)` and
/// `bufferData(target, view, usage, srcOffset, length)`.
fn buffer_data(ctx: &mut Context, a: &mut Args) -> Result<Value, CallError> {
    let target = a.u32()?;
    if a.is_number(1) {
        let size = a.i64()?;
        ctx.buffer_data_size(target, size, a.u32()?);
        return Ok(Value::Undefined);
    }
    let Some(data) = a.view()?.cloned() else {
        return Err(unsupported("bufferData", "null data"));
    };
    let usage = a.u32()?;
    let (offset, length) = (a.opt_u32()? as usize, a.opt_u32()? as usize);
    let Some(data) = data.window(offset, length) else {
        return Err(unsupported(
            "bufferData",
            "a srcOffset or length past the end",
        ));
    };
    with_elements!(&data, s => ctx.buffer_data(target, s, usage));
    Ok(Value::Undefined)
}

/// `bufferSubData`'s data and optional `srcOffset`, `length`.
fn source(f: &str, a: &mut Args) -> Result<TypedArray, CallError> {
    let Some(data) = a.view()?.cloned() else {
        return Err(CallError::Type(format!("{f}: null data")));
    };
    let (offset, length) = (a.opt_u32()? as usize, a.opt_u32()? as usize);
    data.window(offset, length)
        .ok_or_else(|| unsupported(f, "a srcOffset or length past the end"))
}
