//! Shaders, programs, uniforms and uniform blocks, transform feedback, query and sync
//! objects.

use essl_gl::{Context, Program, Query, Shader, Sync, TransformFeedback, UniformLocation};

use super::{boolean, num, object, string, unsupported, void};
use crate::args::{Args, CallError};
use crate::value::{Object, TypedArray, Value};

pub(super) fn call(ctx: &mut Context, f: &str, a: &mut Args) -> Result<Option<Value>, CallError> {
    if f.starts_with("uniform") && f != "uniformBlockBinding" {
        return uniform(ctx, f, a).map(Some);
    }
    let v = match f {
        // Shaders.
        "createShader" => object(ctx.create_shader(a.u32()?), Object::Shader),
        "isShader" => boolean(a.object::<Shader>()?.is_some_and(|s| ctx.is_shader(s))),
        "deleteShader" => void!(a.object::<Shader>()?.map(|s| ctx.delete_shader(s))),
        "shaderSource" => {
            let shader = a.required::<Shader>()?;
            void!(ctx.shader_source(shader, &a.string()?))
        }
        "getShaderSource" => string(ctx.get_shader_source(a.required()?)),
        "compileShader" => void!(ctx.compile_shader(a.required()?)),
        "getShaderParameter" => Value::from(ctx.get_shader_parameter(a.required()?, a.u32()?)),
        "getShaderInfoLog" => string(ctx.get_shader_info_log(a.required()?)),
        "getShaderPrecisionFormat" => object(
            ctx.get_shader_precision_format(a.u32()?, a.u32()?),
            Object::PrecisionFormat,
        ),

        // Programs.
        "createProgram" => Value::Object(Object::Program(ctx.create_program())),
        "isProgram" => boolean(a.object::<Program>()?.is_some_and(|p| ctx.is_program(p))),
        "deleteProgram" => void!(a.object::<Program>()?.map(|p| ctx.delete_program(p))),
        "attachShader" => void!(ctx.attach_shader(a.required()?, a.required()?)),
        "detachShader" => void!(ctx.detach_shader(a.required()?, a.required()?)),
        "getAttachedShaders" => Value::List(
            ctx.get_attached_shaders(a.required()?)
                .into_iter()
                .map(|s| Value::Object(Object::Shader(s)))
                .collect(),
        ),
        "bindAttribLocation" => {
            let (program, index) = (a.required::<Program>()?, a.u32()?);
            void!(ctx.bind_attrib_location(program, index, &a.string()?))
        }
        "linkProgram" => void!(ctx.link_program(a.required()?)),
        "validateProgram" => void!(ctx.validate_program(a.required()?)),
        "useProgram" => void!(ctx.use_program(a.object()?)),
        "getProgramParameter" => Value::from(ctx.get_program_parameter(a.required()?, a.u32()?)),
        "getProgramInfoLog" => string(ctx.get_program_info_log(a.required()?)),
        "getAttribLocation" => {
            let program = a.required::<Program>()?;
            num(ctx.get_attrib_location(program, &a.string()?))
        }
        "getFragDataLocation" => {
            let program = a.required::<Program>()?;
            num(ctx.get_frag_data_location(program, &a.string()?))
        }
        "getActiveAttrib" => object(
            ctx.get_active_attrib(a.required()?, a.u32()?),
            Object::ActiveInfo,
        ),
        "getActiveUniform" => object(
            ctx.get_active_uniform(a.required()?, a.u32()?),
            Object::ActiveInfo,
        ),
        "getUniformLocation" => {
            let program = a.required::<Program>()?;
            object(
                ctx.get_uniform_location(program, &a.string()?),
                Object::UniformLocation,
            )
        }
        "getUniform" => Value::from(ctx.get_uniform(a.required()?, a.required()?)),
        "getUniformIndices" => {
            let program = a.required::<Program>()?;
            let names = a.strings()?;
            let names: Vec<&str> = names.iter().map(String::as_str).collect();
            match ctx.get_uniform_indices(program, &names) {
                Some(v) => Value::List(v.into_iter().map(num).collect()),
                None => Value::Null,
            }
        }
        "getActiveUniforms" => {
            let program = a.required::<Program>()?;
            let TypedArray::U32(indices) = a.list("u32")? else {
                return Err(CallError::Type(format!("{f}: not a sequence")));
            };
            Value::from(ctx.get_active_uniforms(program, &indices, a.u32()?))
        }
        "getUniformBlockIndex" => {
            let program = a.required::<Program>()?;
            num(ctx.get_uniform_block_index(program, &a.string()?))
        }
        "getActiveUniformBlockParameter" => {
            Value::from(ctx.get_active_uniform_block_parameter(a.required()?, a.u32()?, a.u32()?))
        }
        "getActiveUniformBlockName" => {
            string(ctx.get_active_uniform_block_name(a.required()?, a.u32()?))
        }
        "uniformBlockBinding" => {
            void!(ctx.uniform_block_binding(a.required()?, a.u32()?, a.u32()?))
        }

        // Transform feedback.
        "createTransformFeedback" => {
            Value::Object(Object::TransformFeedback(ctx.create_transform_feedback()))
        }
        "isTransformFeedback" => boolean(
            a.object::<TransformFeedback>()?
                .is_some_and(|t| ctx.is_transform_feedback(t)),
        ),
        "deleteTransformFeedback" => void!(a
            .object::<TransformFeedback>()?
            .map(|t| ctx.delete_transform_feedback(t))),
        "bindTransformFeedback" => void!(ctx.bind_transform_feedback(a.u32()?, a.object()?)),
        "beginTransformFeedback" => void!(ctx.begin_transform_feedback(a.u32()?)),
        "endTransformFeedback" => void!(ctx.end_transform_feedback()),
        "pauseTransformFeedback" => void!(ctx.pause_transform_feedback()),
        "resumeTransformFeedback" => void!(ctx.resume_transform_feedback()),
        "transformFeedbackVaryings" => {
            let program = a.required::<Program>()?;
            let names = a.strings()?;
            let names: Vec<&str> = names.iter().map(String::as_str).collect();
            void!(ctx.transform_feedback_varyings(program, &names, a.u32()?))
        }
        "getTransformFeedbackVarying" => object(
            ctx.get_transform_feedback_varying(a.required()?, a.u32()?),
            Object::ActiveInfo,
        ),
        "getIndexedParameter" => Value::from(ctx.get_indexed_parameter(a.u32()?, a.u32()?)),

        // Queries.
        "createQuery" => Value::Object(Object::Query(ctx.create_query())),
        "isQuery" => boolean(a.object::<Query>()?.is_some_and(|q| ctx.is_query(q))),
        "deleteQuery" => void!(a.object::<Query>()?.map(|q| ctx.delete_query(q))),
        "beginQuery" => void!(ctx.begin_query(a.u32()?, a.required()?)),
        "endQuery" => void!(ctx.end_query(a.u32()?)),
        "getQuery" => object(ctx.get_query(a.u32()?, a.u32()?), Object::Query),
        "getQueryParameter" => Value::from(ctx.get_query_parameter(a.required()?, a.u32()?)),

        // Syncs.
        "fenceSync" => object(ctx.fence_sync(a.u32()?, a.u32()?), Object::Sync),
        "isSync" => boolean(a.object::<Sync>()?.is_some_and(|s| ctx.is_sync(s))),
        "deleteSync" => void!(a.object::<Sync>()?.map(|s| ctx.delete_sync(s))),
        "clientWaitSync" => num(ctx.client_wait_sync(a.required()?, a.u32()?, a.u64()?)),
        "waitSync" => void!(ctx.wait_sync(a.required()?, a.u32()?, a.i64()?)),
        "getSyncParameter" => Value::from(ctx.get_sync_parameter(a.required()?, a.u32()?)),
        _ => return Ok(None),
    };
    Ok(Some(v))
}

/// `uniform[1234][fiu]`, `uniform[1234][fiu]v` and `uniformMatrix*fv`, with WebGL 2's
/// optional `srcOffset` and `srcLength`.
fn uniform(ctx: &mut Context, f: &str, a: &mut Args) -> Result<Value, CallError> {
    let location = a.object::<UniformLocation>()?;
    if let Some(shape) = f.strip_prefix("uniformMatrix") {
        let transpose = a.bool()?;
        let TypedArray::F32(v) = window(f, a, "f32")? else {
            return Err(CallError::Type(format!("{f}: not a Float32List")));
        };
        match shape {
            "2fv" => ctx.uniform_matrix2fv(location, transpose, &v),
            "3fv" => ctx.uniform_matrix3fv(location, transpose, &v),
            "4fv" => ctx.uniform_matrix4fv(location, transpose, &v),
            "2x3fv" => ctx.uniform_matrix2x3fv(location, transpose, &v),
            "2x4fv" => ctx.uniform_matrix2x4fv(location, transpose, &v),
            "3x2fv" => ctx.uniform_matrix3x2fv(location, transpose, &v),
            "3x4fv" => ctx.uniform_matrix3x4fv(location, transpose, &v),
            "4x2fv" => ctx.uniform_matrix4x2fv(location, transpose, &v),
            "4x3fv" => ctx.uniform_matrix4x3fv(location, transpose, &v),
            _ => return Err(unsupported(f, "this method")),
        }
        return Ok(Value::Undefined);
    }
    let l = location;
    match f {
        "uniform1f" => ctx.uniform1f(l, a.f32()?),
        "uniform2f" => ctx.uniform2f(l, a.f32()?, a.f32()?),
        "uniform3f" => ctx.uniform3f(l, a.f32()?, a.f32()?, a.f32()?),
        "uniform4f" => ctx.uniform4f(l, a.f32()?, a.f32()?, a.f32()?, a.f32()?),
        "uniform1i" => ctx.uniform1i(l, a.i32()?),
        "uniform2i" => ctx.uniform2i(l, a.i32()?, a.i32()?),
        "uniform3i" => ctx.uniform3i(l, a.i32()?, a.i32()?, a.i32()?),
        "uniform4i" => ctx.uniform4i(l, a.i32()?, a.i32()?, a.i32()?, a.i32()?),
        "uniform1ui" => ctx.uniform1ui(l, a.u32()?),
        "uniform2ui" => ctx.uniform2ui(l, a.u32()?, a.u32()?),
        "uniform3ui" => ctx.uniform3ui(l, a.u32()?, a.u32()?, a.u32()?),
        "uniform4ui" => ctx.uniform4ui(l, a.u32()?, a.u32()?, a.u32()?, a.u32()?),
        _ => {
            let kind = if f.ends_with("uiv") {
                "u32"
            } else if f.ends_with("iv") {
                "i32"
            } else {
                "f32"
            };
            match (&f[..f.len() - kind.len().min(f.len())], window(f, a, kind)?) {
                (_, TypedArray::F32(v)) if kind == "f32" => match f {
                    "uniform1fv" => ctx.uniform1fv(l, &v),
                    "uniform2fv" => ctx.uniform2fv(l, &v),
                    "uniform3fv" => ctx.uniform3fv(l, &v),
                    "uniform4fv" => ctx.uniform4fv(l, &v),
                    _ => return Err(unsupported(f, "this method")),
                },
                (_, TypedArray::I32(v)) if kind == "i32" => match f {
                    "uniform1iv" => ctx.uniform1iv(l, &v),
                    "uniform2iv" => ctx.uniform2iv(l, &v),
                    "uniform3iv" => ctx.uniform3iv(l, &v),
                    "uniform4iv" => ctx.uniform4iv(l, &v),
                    _ => return Err(unsupported(f, "this method")),
                },
                (_, TypedArray::U32(v)) if kind == "u32" => match f {
                    "uniform1uiv" => ctx.uniform1uiv(l, &v),
                    "uniform2uiv" => ctx.uniform2uiv(l, &v),
                    "uniform3uiv" => ctx.uniform3uiv(l, &v),
                    "uniform4uiv" => ctx.uniform4uiv(l, &v),
                    _ => return Err(unsupported(f, "this method")),
                },
                _ => return Err(CallError::Type(format!("{f}: an array of another type"))),
            }
        }
    }
    Ok(Value::Undefined)
}

/// A `Float32List`/`Int32List`/`Uint32List` and its optional `srcOffset`, `srcLength`.
fn window(f: &str, a: &mut Args, kind: &str) -> Result<TypedArray, CallError> {
    let list = a.list(kind)?;
    let (offset, length) = (a.opt_u32()? as usize, a.opt_u32()? as usize);
    list.window(offset, length)
        .ok_or_else(|| unsupported(f, "a srcOffset or srcLength past the end"))
}
