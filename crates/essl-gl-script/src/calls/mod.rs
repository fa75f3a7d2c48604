//! WebGL2's methods by name: each converts its arguments as the IDL does and calls essl-gl.
//! The methods are grouped as essl-gl groups them: state and queries ([`state`]), buffers,
//! vertex arrays and draws ([`vertex`]), textures, samplers, renderbuffers, framebuffers and
//! reads ([`images`]), and shaders, programs, uniforms, transform feedback, queries and syncs
//! ([`programs`]).
//!
//! Every method of WebGL2's IDL is here but the overloads that take a `TexImageSource` (an
//! image or canvas, which a script cannot write down) and `null` where WebGL answers
//! `INVALID_VALUE` for it (`bufferData(target, null, usage)`, `readPixels(…, null)`): those
//! report [`CallError::Unsupported`].

mod images;
mod programs;
mod state;
mod vertex;

use essl_gl::Context;

use crate::args::{Args, CallError};
use crate::value::Value;

/// Calls WebGL2's method `f` (its IDL name, `texImage2D`) with `args`, converted as the IDL
/// converts a script's values; its return value (`Undefined` for `void`), or the exception a
/// browser would throw.
pub fn call(ctx: &mut Context, f: &str, args: &mut [Value]) -> Result<Value, CallError> {
    let a = &mut Args::new(args);
    if let Some(v) = state::call(ctx, f, a)? {
        return Ok(v);
    }
    if let Some(v) = vertex::call(ctx, f, a)? {
        return Ok(v);
    }
    if let Some(v) = images::call(ctx, f, a)? {
        return Ok(v);
    }
    if let Some(v) = programs::call(ctx, f, a)? {
        return Ok(v);
    }
    Err(CallError::UnknownMethod(f.to_string()))
}

/// `Value::Undefined` after evaluating a `void` call.
macro_rules! void {
    ($e:expr) => {{
        $e;
        Value::Undefined
    }};
}
pub(crate) use void;

/// A nullable object as a value.
fn object<T>(o: Option<T>, wrap: impl FnOnce(T) -> crate::value::Object) -> Value {
    o.map_or(Value::Null, |o| Value::Object(wrap(o)))
}

/// A `GLboolean` answer.
fn boolean(b: bool) -> Value {
    Value::Bool(b)
}

/// A number answer.
fn num(n: impl Into<f64>) -> Value {
    Value::Number(n.into())
}

/// A nullable string answer.
fn string(s: Option<String>) -> Value {
    s.map_or(Value::Null, Value::Str)
}

/// The overload WebGL cannot express in a script, or answers for `null` with an error that
/// only a browser's bindings make.
fn unsupported(f: &str, what: &str) -> CallError {
    CallError::Unsupported(format!("{f}: {what} is not supported by the replay"))
}
