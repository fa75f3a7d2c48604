//! What a call returns to JavaScript: the IDL's `any` answers of essl-gl ([`Parameter`]) as
//! JavaScript values — numbers, booleans, strings, typed arrays, arrays, and WebGL objects as
//! `{ webglObjectId }` records that the JavaScript side turns back into the objects it made.

use std::ptr;

use essl_gl::{ActiveInfo, Parameter, ShaderPrecisionFormat};
use napi::bindgen_prelude::ToNapiValue;
use napi::sys;

use crate::registry::{id_of, Handle};

/// A JavaScript value to return.
#[derive(Debug)]
pub enum Answer {
    /// `null`.
    Null,
    /// A boolean.
    Bool(bool),
    /// A number.
    Number(f64),
    /// A string.
    Str(String),
    /// An `Int32Array`.
    Int32s(Vec<i32>),
    /// A `Uint32Array`.
    Uint32s(Vec<u32>),
    /// A `Float32Array`.
    Float32s(Vec<f32>),
    /// An array of booleans (`COLOR_WRITEMASK`).
    Bools(Vec<bool>),
    /// An array of numbers (`getUniformIndices`).
    Numbers(Vec<f64>),
    /// An array of strings (`getSupportedExtensions`).
    Strs(Vec<String>),
    /// A WebGL object, by its id.
    Object(u32),
    /// An array of WebGL objects (`getAttachedShaders`).
    Objects(Vec<u32>),
    /// `WebGLActiveInfo`'s fields as `{ name, size, type }`.
    ActiveInfo(ActiveInfo),
    /// `WebGLShaderPrecisionFormat`'s fields as `{ rangeMin, rangeMax, precision }`.
    Precision(ShaderPrecisionFormat),
}

impl Answer {
    /// A nullable object.
    pub(crate) fn object(h: Option<Handle>) -> Answer {
        h.map_or(Answer::Null, |h| Answer::Object(id_of(h)))
    }

    /// An optional string (`null` for `None`).
    pub(crate) fn string(s: Option<String>) -> Answer {
        s.map_or(Answer::Null, Answer::Str)
    }
}

impl From<Option<Parameter>> for Answer {
    fn from(p: Option<Parameter>) -> Answer {
        let Some(p) = p else {
            return Answer::Null;
        };
        match p {
            Parameter::Bool(b) => Answer::Bool(b),
            Parameter::Int(i) => Answer::Number(i as f64),
            Parameter::Enum(e) => Answer::Number(f64::from(e)),
            Parameter::Float(f) => Answer::Number(f64::from(f)),
            Parameter::Ints(v) => Answer::Int32s(v),
            Parameter::Uints(v) => Answer::Uint32s(v),
            Parameter::Floats(v) => Answer::Float32s(v),
            Parameter::Bools(v) => Answer::Bools(v),
            Parameter::String(s) => Answer::Str(s),
            Parameter::Program(o) => Answer::object(o.map(Handle::Program)),
            Parameter::Buffer(o) => Answer::object(o.map(Handle::Buffer)),
            Parameter::Texture(o) => Answer::object(o.map(Handle::Texture)),
            Parameter::VertexArray(o) => Answer::object(o.map(Handle::VertexArray)),
            Parameter::Framebuffer(o) => Answer::object(o.map(Handle::Framebuffer)),
            Parameter::Renderbuffer(o) => Answer::object(o.map(Handle::Renderbuffer)),
            Parameter::Sampler(o) => Answer::object(o.map(Handle::Sampler)),
            Parameter::TransformFeedback(o) => Answer::object(o.map(Handle::TransformFeedback)),
            Parameter::Query(o) => Answer::object(o.map(Handle::Query)),
            // `Parameter` may grow; a kind this binding does not know answers null.
            _ => Answer::Null,
        }
    }
}

/// Checks a N-API status: any failure becomes a JavaScript `Error`.
fn check(status: sys::napi_status, what: &str) -> napi::Result<()> {
    if status == sys::Status::napi_ok {
        Ok(())
    } else {
        Err(napi::Error::from_reason(format!(
            "N-API {what} failed ({status})"
        )))
    }
}

unsafe fn number(env: sys::napi_env, n: f64) -> napi::Result<sys::napi_value> {
    let mut v = ptr::null_mut();
    check(
        unsafe { sys::napi_create_double(env, n, &mut v) },
        "create_double",
    )?;
    Ok(v)
}

unsafe fn string(env: sys::napi_env, s: &str) -> napi::Result<sys::napi_value> {
    let mut v = ptr::null_mut();
    let status =
        unsafe { sys::napi_create_string_utf8(env, s.as_ptr().cast(), s.len() as isize, &mut v) };
    check(status, "create_string")?;
    Ok(v)
}

unsafe fn boolean(env: sys::napi_env, b: bool) -> napi::Result<sys::napi_value> {
    let mut v = ptr::null_mut();
    check(
        unsafe { sys::napi_get_boolean(env, b, &mut v) },
        "get_boolean",
    )?;
    Ok(v)
}

/// A typed array of `kind` holding a copy of `bytes`.
unsafe fn typed(
    env: sys::napi_env,
    kind: sys::napi_typedarray_type,
    bytes: &[u8],
    len: usize,
) -> napi::Result<sys::napi_value> {
    let (mut data, mut buffer, mut array) = (ptr::null_mut(), ptr::null_mut(), ptr::null_mut());
    let status = unsafe { sys::napi_create_arraybuffer(env, bytes.len(), &mut data, &mut buffer) };
    check(status, "create_arraybuffer")?;
    if !bytes.is_empty() {
        unsafe { ptr::copy_nonoverlapping(bytes.as_ptr(), data.cast(), bytes.len()) };
    }
    let status = unsafe { sys::napi_create_typedarray(env, kind, len, buffer, 0, &mut array) };
    check(status, "create_typedarray")?;
    Ok(array)
}

/// An array of the values `each` makes.
unsafe fn array<T>(
    env: sys::napi_env,
    items: &[T],
    each: impl Fn(&T) -> napi::Result<sys::napi_value>,
) -> napi::Result<sys::napi_value> {
    let mut a = ptr::null_mut();
    check(
        unsafe { sys::napi_create_array_with_length(env, items.len(), &mut a) },
        "create_array",
    )?;
    for (i, item) in items.iter().enumerate() {
        let v = each(item)?;
        check(
            unsafe { sys::napi_set_element(env, a, i as u32, v) },
            "set_element",
        )?;
    }
    Ok(a)
}

/// An object with the given properties.
unsafe fn record(
    env: sys::napi_env,
    fields: &[(&str, sys::napi_value)],
) -> napi::Result<sys::napi_value> {
    let mut o = ptr::null_mut();
    check(
        unsafe { sys::napi_create_object(env, &mut o) },
        "create_object",
    )?;
    for (k, v) in fields {
        let key = unsafe { string(env, k)? };
        check(
            unsafe { sys::napi_set_property(env, o, key, *v) },
            "set_property",
        )?;
    }
    Ok(o)
}

unsafe fn object(env: sys::napi_env, id: u32) -> napi::Result<sys::napi_value> {
    let id = unsafe { number(env, f64::from(id))? };
    unsafe { record(env, &[("webglObjectId", id)]) }
}

impl ToNapiValue for Answer {
    unsafe fn to_napi_value(env: sys::napi_env, val: Self) -> napi::Result<sys::napi_value> {
        use sys::TypedarrayType as T;
        unsafe {
            match val {
                Answer::Null => {
                    let mut v = ptr::null_mut();
                    check(sys::napi_get_null(env, &mut v), "get_null")?;
                    Ok(v)
                }
                Answer::Bool(b) => boolean(env, b),
                Answer::Number(n) => number(env, n),
                Answer::Str(s) => string(env, &s),
                Answer::Int32s(v) => typed(env, T::int32_array, bytes(&v), v.len()),
                Answer::Uint32s(v) => typed(env, T::uint32_array, bytes(&v), v.len()),
                Answer::Float32s(v) => typed(env, T::float32_array, bytes(&v), v.len()),
                Answer::Bools(v) => array(env, &v, |b| boolean(env, *b)),
                Answer::Numbers(v) => array(env, &v, |n| number(env, *n)),
                Answer::Strs(v) => array(env, &v, |s| string(env, s)),
                Answer::Object(id) => object(env, id),
                Answer::Objects(v) => array(env, &v, |id| object(env, *id)),
                Answer::ActiveInfo(info) => record(
                    env,
                    &[
                        ("name", string(env, &info.name)?),
                        ("size", number(env, f64::from(info.size))?),
                        ("type", number(env, f64::from(info.ty))?),
                    ],
                ),
                Answer::Precision(p) => record(
                    env,
                    &[
                        ("rangeMin", number(env, f64::from(p.range_min))?),
                        ("rangeMax", number(env, f64::from(p.range_max))?),
                        ("precision", number(env, f64::from(p.precision))?),
                    ],
                ),
            }
        }
    }
}

/// The bytes of a slice of 4-byte numbers.
fn bytes<T: essl_gl::bytemuck::NoUninit>(v: &[T]) -> &[u8] {
    essl_gl::bytemuck::cast_slice(v)
}
