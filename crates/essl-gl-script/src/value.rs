//! The values a replay passes and returns: JavaScript's numbers, strings, arrays, typed arrays
//! and WebGL objects, and how a returned value is recorded as JSON (the table "Recorded values"
//! of `docs/gl-scripts.md`).

use essl_gl::{
    ActiveInfo, Buffer, Framebuffer, Parameter, Program, Query, Renderbuffer, Sampler, Shader,
    ShaderPrecisionFormat, Sync, Texture, TransformFeedback, UniformLocation, VertexArray,
};
use serde_json::Value as Json;

/// A typed array (`Float32Array`, `Uint8Array`, …) and its elements.
#[derive(Clone, Debug, PartialEq)]
pub enum TypedArray {
    /// `Int8Array`.
    I8(Vec<i8>),
    /// `Uint8Array`.
    U8(Vec<u8>),
    /// `Int16Array`.
    I16(Vec<i16>),
    /// `Uint16Array`.
    U16(Vec<u16>),
    /// `Int32Array`.
    I32(Vec<i32>),
    /// `Uint32Array`.
    U32(Vec<u32>),
    /// `Float32Array`.
    F32(Vec<f32>),
}

/// Runs `$body` with `$s` bound to the array's elements as a slice of their own type.
macro_rules! with_elements {
    ($array:expr, $s:ident => $body:expr) => {
        match $array {
            $crate::value::TypedArray::I8($s) => $body,
            $crate::value::TypedArray::U8($s) => $body,
            $crate::value::TypedArray::I16($s) => $body,
            $crate::value::TypedArray::U16($s) => $body,
            $crate::value::TypedArray::I32($s) => $body,
            $crate::value::TypedArray::U32($s) => $body,
            $crate::value::TypedArray::F32($s) => $body,
        }
    };
}
pub(crate) use with_elements;

impl TypedArray {
    /// A typed array of kind `kind` (`"f32"`, `"u8"`, `"i8"`, `"u16"`, `"i16"`, `"u32"`,
    /// `"i32"`) holding `values`: `f32` rounds to the nearest float32, the integer kinds
    /// require integers in their range.
    pub fn from_values(kind: &str, values: &[f64]) -> Result<TypedArray, String> {
        fn ints<T: TryFrom<i64>>(kind: &str, values: &[f64]) -> Result<Vec<T>, String> {
            values
                .iter()
                .map(|&v| {
                    if v.fract() != 0.0 || !v.is_finite() {
                        return Err(format!("`{kind}` value {v} is not an integer"));
                    }
                    T::try_from(v as i64).map_err(|_| format!("`{kind}` value {v} out of range"))
                })
                .collect()
        }
        Ok(match kind {
            "f32" => TypedArray::F32(values.iter().map(|&v| v as f32).collect()),
            "u8" => TypedArray::U8(ints(kind, values)?),
            "i8" => TypedArray::I8(ints(kind, values)?),
            "u16" => TypedArray::U16(ints(kind, values)?),
            "i16" => TypedArray::I16(ints(kind, values)?),
            "u32" => TypedArray::U32(ints(kind, values)?),
            "i32" => TypedArray::I32(ints(kind, values)?),
            _ => return Err(format!("`{kind}` is not a typed array kind")),
        })
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        with_elements!(self, s => s.len())
    }

    /// Whether the array has no elements.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Element `i` as a JavaScript number.
    pub fn get(&self, i: usize) -> f64 {
        with_elements!(self, s => f64::from(s[i]))
    }

    /// The elements as a JSON array.
    pub fn to_json(&self) -> Json {
        Json::Array((0..self.len()).map(|i| number(self.get(i))).collect())
    }

    /// Elements `offset..offset + length` (`length` 0: to the end), as WebGL 2's `srcOffset`
    /// and `srcLength` pick them; `None` past the end.
    pub fn window(&self, offset: usize, length: usize) -> Option<TypedArray> {
        let end = if length == 0 {
            self.len()
        } else {
            offset.checked_add(length)?
        };
        if offset > self.len() || end > self.len() {
            return None;
        }
        Some(match self {
            TypedArray::I8(s) => TypedArray::I8(s[offset..end].to_vec()),
            TypedArray::U8(s) => TypedArray::U8(s[offset..end].to_vec()),
            TypedArray::I16(s) => TypedArray::I16(s[offset..end].to_vec()),
            TypedArray::U16(s) => TypedArray::U16(s[offset..end].to_vec()),
            TypedArray::I32(s) => TypedArray::I32(s[offset..end].to_vec()),
            TypedArray::U32(s) => TypedArray::U32(s[offset..end].to_vec()),
            TypedArray::F32(s) => TypedArray::F32(s[offset..end].to_vec()),
        })
    }
}

/// A WebGL object, or one of the small interfaces returned by queries.
#[derive(Clone, Debug, PartialEq)]
pub enum Object {
    /// `WebGLBuffer`.
    Buffer(Buffer),
    /// `WebGLFramebuffer`.
    Framebuffer(Framebuffer),
    /// `WebGLProgram`.
    Program(Program),
    /// `WebGLQuery`.
    Query(Query),
    /// `WebGLRenderbuffer`.
    Renderbuffer(Renderbuffer),
    /// `WebGLSampler`.
    Sampler(Sampler),
    /// `WebGLShader`.
    Shader(Shader),
    /// `WebGLSync`.
    Sync(Sync),
    /// `WebGLTexture`.
    Texture(Texture),
    /// `WebGLTransformFeedback`.
    TransformFeedback(TransformFeedback),
    /// `WebGLUniformLocation`.
    UniformLocation(UniformLocation),
    /// `WebGLVertexArrayObject`.
    VertexArray(VertexArray),
    /// `WebGLActiveInfo`.
    ActiveInfo(ActiveInfo),
    /// `WebGLShaderPrecisionFormat`.
    PrecisionFormat(ShaderPrecisionFormat),
    /// An extension's object (`getExtension`).
    Extension(&'static str),
}

impl Object {
    /// The interface's name (`"WebGLTexture"`).
    pub fn interface(&self) -> &'static str {
        match self {
            Object::Buffer(_) => "WebGLBuffer",
            Object::Framebuffer(_) => "WebGLFramebuffer",
            Object::Program(_) => "WebGLProgram",
            Object::Query(_) => "WebGLQuery",
            Object::Renderbuffer(_) => "WebGLRenderbuffer",
            Object::Sampler(_) => "WebGLSampler",
            Object::Shader(_) => "WebGLShader",
            Object::Sync(_) => "WebGLSync",
            Object::Texture(_) => "WebGLTexture",
            Object::TransformFeedback(_) => "WebGLTransformFeedback",
            Object::UniformLocation(_) => "WebGLUniformLocation",
            Object::VertexArray(_) => "WebGLVertexArrayObject",
            Object::ActiveInfo(_) => "WebGLActiveInfo",
            Object::PrecisionFormat(_) => "WebGLShaderPrecisionFormat",
            Object::Extension(name) => name,
        }
    }
}

/// A JavaScript value passed to or returned by a call.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// `undefined` (what a `void` method returns).
    Undefined,
    /// `null`.
    Null,
    /// A boolean.
    Bool(bool),
    /// A number.
    Number(f64),
    /// A string.
    Str(String),
    /// A JavaScript array.
    List(Vec<Value>),
    /// A typed array.
    Typed(TypedArray),
    /// An object.
    Object(Object),
    /// A dictionary (`getContextAttributes`), keys in order.
    Dict(Vec<(String, Value)>),
}

impl Value {
    /// The value as a script records it.
    pub fn to_json(&self) -> Json {
        match self {
            Value::Undefined | Value::Null => Json::Null,
            Value::Bool(b) => Json::Bool(*b),
            Value::Number(n) => number(*n),
            Value::Str(s) => Json::String(s.clone()),
            Value::List(items) => Json::Array(items.iter().map(Value::to_json).collect()),
            Value::Typed(a) => a.to_json(),
            Value::Object(Object::ActiveInfo(info)) => serde_json::json!({
                "object": "WebGLActiveInfo",
                "name": info.name,
                "size": info.size,
                "type": info.ty,
            }),
            Value::Object(Object::PrecisionFormat(p)) => serde_json::json!({
                "object": "WebGLShaderPrecisionFormat",
                "rangeMin": p.range_min,
                "rangeMax": p.range_max,
                "precision": p.precision,
            }),
            Value::Object(o) => serde_json::json!({ "object": o.interface() }),
            Value::Dict(entries) => {
                let mut sorted: Vec<_> = entries.iter().collect();
                sorted.sort_by(|a, b| a.0.cmp(&b.0));
                Json::Object(
                    sorted
                        .into_iter()
                        .map(|(k, v)| (k.clone(), v.to_json()))
                        .collect(),
                )
            }
        }
    }
}

/// A JavaScript number as JSON: an integer where it is one (as `JSON.stringify` writes it),
/// `NaN` and the infinities as strings.
pub fn number(n: f64) -> Json {
    if n.is_nan() {
        Json::String("NaN".into())
    } else if n.is_infinite() {
        Json::String(if n > 0.0 { "Infinity" } else { "-Infinity" }.into())
    } else if n.fract() == 0.0 && n.abs() < 9.007_199_254_740_992e15 {
        Json::from(n as i64)
    } else {
        Json::from(n)
    }
}

impl From<Option<Parameter>> for Value {
    fn from(p: Option<Parameter>) -> Value {
        let Some(p) = p else {
            return Value::Null;
        };
        let object = |o: Option<Object>| o.map_or(Value::Null, Value::Object);
        match p {
            Parameter::Bool(b) => Value::Bool(b),
            Parameter::Int(i) => Value::Number(i as f64),
            Parameter::Enum(e) => Value::Number(f64::from(e)),
            Parameter::Float(f) => Value::Number(f64::from(f)),
            Parameter::Ints(v) => Value::Typed(TypedArray::I32(v)),
            Parameter::Uints(v) => Value::Typed(TypedArray::U32(v)),
            Parameter::Floats(v) => Value::Typed(TypedArray::F32(v)),
            Parameter::Bools(v) => Value::List(v.into_iter().map(Value::Bool).collect()),
            Parameter::String(s) => Value::Str(s),
            Parameter::Program(o) => object(o.map(Object::Program)),
            Parameter::Buffer(o) => object(o.map(Object::Buffer)),
            Parameter::Texture(o) => object(o.map(Object::Texture)),
            Parameter::VertexArray(o) => object(o.map(Object::VertexArray)),
            Parameter::Framebuffer(o) => object(o.map(Object::Framebuffer)),
            Parameter::Renderbuffer(o) => object(o.map(Object::Renderbuffer)),
            Parameter::Sampler(o) => object(o.map(Object::Sampler)),
            Parameter::TransformFeedback(o) => object(o.map(Object::TransformFeedback)),
            Parameter::Query(o) => object(o.map(Object::Query)),
            Parameter::Null => Value::Null,
            // `Parameter` may grow; a kind this replay does not know records as null.
            _ => Value::Null,
        }
    }
}
