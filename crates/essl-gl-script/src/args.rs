//! A call's arguments converted as WebGL's IDL converts JavaScript values: `GLenum` and
//! `GLuint` by ToUint32, `GLint` by ToInt32, `GLintptr` by ToInt64 (all modulo, NaN → 0),
//! `GLfloat` by rounding to float32, `GLboolean` by ToBoolean; a non-nullable object given
//! `null`, or an object of another interface, is a `TypeError` — the exception a browser
//! throws, which stops a script.

use essl_gl::{
    Buffer, Framebuffer, Program, Query, Renderbuffer, Sampler, Shader, Sync, Texture,
    TransformFeedback, UniformLocation, VertexArray,
};

use crate::value::{Object, TypedArray, Value};

/// Why a call could not be made: what a browser reports as an exception.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum CallError {
    /// An argument of the wrong kind, or too few (`TypeError`).
    #[error("TypeError: {0}")]
    Type(String),
    /// An overload the replay cannot express (a `TexImageSource`), or `null` where only a
    /// browser's bindings answer.
    #[error("{0}")]
    Unsupported(String),
    /// A name that is not a method of `WebGL2RenderingContext`.
    #[error("`{0}` is not a method of WebGL2RenderingContext")]
    UnknownMethod(String),
}

/// The arguments of one call, taken in order.
pub(crate) struct Args<'a> {
    values: &'a mut [Value],
    next: usize,
}

/// ToNumber of a JavaScript value as the IDL's numeric conversions start.
fn to_number(v: &Value) -> f64 {
    match v {
        Value::Number(n) => *n,
        Value::Bool(b) => f64::from(u8::from(*b)),
        Value::Null => 0.0,
        Value::Str(s) => s.trim().parse().unwrap_or(f64::NAN),
        _ => f64::NAN,
    }
}

/// ToInt64-style conversion modulo 2^bits: NaN and infinities are 0, others truncate.
fn modulo(n: f64, bits: u32) -> i128 {
    if !n.is_finite() {
        return 0;
    }
    let t = n.trunc() as i128;
    let m = 1i128 << bits;
    t.rem_euclid(m)
}

/// Objects an argument may be, by interface.
pub(crate) trait Handle: Sized {
    const INTERFACE: &'static str;
    fn from_object(o: &Object) -> Option<Self>;
}

macro_rules! handles {
    ($($t:ident => $name:literal),*) => {
        $(impl Handle for $t {
            const INTERFACE: &'static str = $name;
            fn from_object(o: &Object) -> Option<Self> {
                match o {
                    Object::$t(h) => Some(h.clone()),
                    _ => None,
                }
            }
        })*
    };
}

handles!(
    Buffer => "WebGLBuffer",
    Framebuffer => "WebGLFramebuffer",
    Program => "WebGLProgram",
    Query => "WebGLQuery",
    Renderbuffer => "WebGLRenderbuffer",
    Sampler => "WebGLSampler",
    Shader => "WebGLShader",
    Sync => "WebGLSync",
    Texture => "WebGLTexture",
    TransformFeedback => "WebGLTransformFeedback",
    UniformLocation => "WebGLUniformLocation",
    VertexArray => "WebGLVertexArrayObject"
);

impl<'a> Args<'a> {
    pub(crate) fn new(values: &'a mut [Value]) -> Args<'a> {
        Args { values, next: 0 }
    }

    /// How many arguments the call was given.
    pub(crate) fn len(&self) -> usize {
        self.values.len()
    }

    /// Argument `i` without taking it.
    pub(crate) fn peek(&self, i: usize) -> Option<&Value> {
        self.values.get(i)
    }

    fn take(&mut self) -> Result<&mut Value, CallError> {
        let i = self.next;
        self.next += 1;
        self.values
            .get_mut(i)
            .ok_or_else(|| CallError::Type(format!("argument {} is missing", i + 1)))
    }

    /// The next argument, `undefined` when there are no more (for optional ones).
    fn take_optional(&mut self) -> Option<&mut Value> {
        let i = self.next;
        self.next += 1;
        self.values.get_mut(i)
    }

    /// A `GLenum`, `GLuint` or `GLbitfield`.
    pub(crate) fn u32(&mut self) -> Result<u32, CallError> {
        Ok(modulo(to_number(self.take()?), 32) as u32)
    }

    /// A `GLint` or `GLsizei`.
    pub(crate) fn i32(&mut self) -> Result<i32, CallError> {
        Ok(modulo(to_number(self.take()?), 32) as u32 as i32)
    }

    /// A `GLintptr`, `GLsizeiptr` or `GLint64`.
    pub(crate) fn i64(&mut self) -> Result<i64, CallError> {
        Ok(modulo(to_number(self.take()?), 64) as u64 as i64)
    }

    /// A `GLuint64`.
    pub(crate) fn u64(&mut self) -> Result<u64, CallError> {
        Ok(modulo(to_number(self.take()?), 64) as u64)
    }

    /// An optional `GLuint` (`srcOffset`, `srcLengthOverride`): 0 when absent.
    pub(crate) fn opt_u32(&mut self) -> Result<u32, CallError> {
        Ok(self
            .take_optional()
            .map_or(0, |v| modulo(to_number(v), 32) as u32))
    }

    /// Optional `GLuint` argument `i` without taking it: 0 when absent (a `dstOffset` read
    /// before the array it applies to is taken).
    pub(crate) fn opt_u32_at(&self, i: usize) -> u32 {
        self.values
            .get(i)
            .map_or(0, |v| modulo(to_number(v), 32) as u32)
    }

    /// A `GLfloat` or `GLclampf`.
    pub(crate) fn f32(&mut self) -> Result<f32, CallError> {
        Ok(to_number(self.take()?) as f32)
    }

    /// A `GLboolean`.
    pub(crate) fn bool(&mut self) -> Result<bool, CallError> {
        Ok(match self.take()? {
            Value::Bool(b) => *b,
            Value::Number(n) => *n != 0.0 && !n.is_nan(),
            Value::Null | Value::Undefined => false,
            Value::Str(s) => !s.is_empty(),
            _ => true,
        })
    }

    /// A `DOMString`.
    pub(crate) fn string(&mut self) -> Result<String, CallError> {
        Ok(match self.take()? {
            Value::Str(s) => s.clone(),
            Value::Number(n) => crate::value::number(*n).to_string(),
            Value::Null => "null".into(),
            other => return Err(CallError::Type(format!("{other:?} is not a string"))),
        })
    }

    /// A `sequence<DOMString>`.
    pub(crate) fn strings(&mut self) -> Result<Vec<String>, CallError> {
        match self.take()? {
            Value::List(items) => items
                .iter()
                .map(|v| match v {
                    Value::Str(s) => Ok(s.clone()),
                    other => Err(CallError::Type(format!("{other:?} is not a string"))),
                })
                .collect(),
            other => Err(CallError::Type(format!("{other:?} is not a sequence"))),
        }
    }

    /// A nullable object of interface `T`.
    pub(crate) fn object<T: Handle>(&mut self) -> Result<Option<T>, CallError> {
        match self.take()? {
            Value::Null | Value::Undefined => Ok(None),
            Value::Object(o) => T::from_object(o).map(Some).ok_or_else(|| {
                CallError::Type(format!(
                    "a {} where a {} was expected",
                    o.interface(),
                    T::INTERFACE
                ))
            }),
            other => Err(CallError::Type(format!(
                "{other:?} is not a {}",
                T::INTERFACE
            ))),
        }
    }

    /// A non-nullable object of interface `T` (`null` is a `TypeError`).
    pub(crate) fn required<T: Handle>(&mut self) -> Result<T, CallError> {
        self.object()?
            .ok_or_else(|| CallError::Type(format!("null where a {} is required", T::INTERFACE)))
    }

    /// A typed array (an `ArrayBufferView`), or `None` for `null`.
    pub(crate) fn view(&mut self) -> Result<Option<&mut TypedArray>, CallError> {
        match self.take()? {
            Value::Null => Ok(None),
            Value::Typed(a) => Ok(Some(a)),
            other => Err(CallError::Type(format!(
                "{other:?} is not an ArrayBufferView"
            ))),
        }
    }

    /// A `Float32List`, `Int32List` or `Uint32List`: a typed array, or a sequence of
    /// numbers converted to `kind` (`"f32"`, `"i32"`, `"u32"`).
    pub(crate) fn list(&mut self, kind: &str) -> Result<TypedArray, CallError> {
        match self.take()? {
            Value::Typed(a) => Ok(a.clone()),
            Value::List(items) => {
                let numbers: Vec<f64> = items
                    .iter()
                    .map(|v| {
                        let n = to_number(v);
                        match kind {
                            "i32" => modulo(n, 32) as u32 as i32 as f64,
                            "u32" => modulo(n, 32) as u32 as f64,
                            _ => n,
                        }
                    })
                    .collect();
                TypedArray::from_values(kind, &numbers).map_err(CallError::Type)
            }
            other => Err(CallError::Type(format!("{other:?} is not a sequence"))),
        }
    }

    /// Whether argument `i` is a number (an offset into a bound buffer) rather than an array.
    pub(crate) fn is_number(&self, i: usize) -> bool {
        matches!(self.values.get(i), Some(Value::Number(_)))
    }
}
