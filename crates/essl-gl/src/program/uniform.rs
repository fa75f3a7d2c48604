//! A linked program's default-block uniform storage: the `uniform*` calls with WebGL's type
//! checks, and the low-level setters that write words at byte offsets.

use essl::program::UniformStorage;
use essl::types::GlType;

use super::interface::uniform_shape;
use crate::context::{Context, MAX_TEXTURE_UNITS};
use crate::gl;
use crate::objects::UniformLocation;

/// What a `uniform*` call provides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Call {
    Float(u8),
    Int(u8),
    Uint(u8),
    Matrix(u8, u8),
}

/// The values of a `uniform*` call.
#[derive(Clone, Copy)]
pub(super) enum Values<'a> {
    F(&'a [f32]),
    I(&'a [i32]),
    U(&'a [u32]),
}

impl Values<'_> {
    pub(super) fn len(&self) -> usize {
        match self {
            Values::F(v) => v.len(),
            Values::I(v) => v.len(),
            Values::U(v) => v.len(),
        }
    }

    /// Value `i` as the 32-bit word stored for a uniform of kind `ty`.
    pub(super) fn word(&self, i: usize, boolean: bool) -> u32 {
        match (self, boolean) {
            (Values::F(v), true) => (v[i] != 0.0) as u32,
            (Values::I(v), true) => (v[i] != 0) as u32,
            (Values::U(v), true) => (v[i] != 0) as u32,
            (Values::F(v), false) => v[i].to_bits(),
            (Values::I(v), false) => v[i] as u32,
            (Values::U(v), false) => v[i],
        }
    }
}

/// Whether a `uniform*` call may set a uniform of type `ty` (WebGL's type rules).
pub(super) fn call_matches(call: Call, ty: GlType) -> bool {
    use GlType::*;
    let (n, matrix, boolean) = uniform_shape(ty);
    match call {
        Call::Matrix(c, r) => matrix == Some((c, r)),
        _ if matrix.is_some() => false,
        Call::Int(1) if ty.is_sampler() => true,
        _ if ty.is_sampler() => false,
        Call::Float(k) => {
            k == n && (boolean || matches!(ty, FLOAT | FLOAT_VEC2 | FLOAT_VEC3 | FLOAT_VEC4))
        }
        Call::Int(k) => k == n && (boolean || matches!(ty, INT | INT_VEC2 | INT_VEC3 | INT_VEC4)),
        Call::Uint(k) => {
            k == n
                && (boolean
                    || matches!(
                        ty,
                        UNSIGNED_INT | UNSIGNED_INT_VEC2 | UNSIGNED_INT_VEC3 | UNSIGNED_INT_VEC4
                    ))
        }
    }
}

impl Context {
    /// Stores the values of a `uniform*` call, with WebGL's checks.
    pub(super) fn uniform_impl(
        &mut self,
        location: Option<UniformLocation>,
        call: Call,
        values: Values<'_>,
        array_call: bool,
        transpose: bool,
        function: &str,
    ) {
        let Some(loc) = location else { return };
        if !self.owns(loc.ctx, function) {
            return;
        }
        let Some(current) = self.bindings.program() else {
            return self.error(gl::INVALID_OPERATION, function, "no current program");
        };
        let linked = match self.objects.linked(current) {
            Some(l) if loc.program == current && l.serial == loc.link => l,
            _ => {
                return self.error(
                    gl::INVALID_OPERATION,
                    function,
                    "location is not from the current program",
                );
            }
        };
        let u = &linked.layout.uniforms[loc.uniform as usize];
        if !call_matches(call, u.ty) {
            let msg = format!("function does not match the uniform's type {}", u.ty);
            return self.error(gl::INVALID_OPERATION, function, msg);
        }
        let per = match call {
            Call::Float(n) | Call::Int(n) | Call::Uint(n) => n as usize,
            Call::Matrix(c, r) => c as usize * r as usize,
        };
        let len = values.len();
        if len == 0 || len % per != 0 {
            return self.error(
                gl::INVALID_VALUE,
                function,
                "value count is not a multiple of the type's size",
            );
        }
        let count = len / per;
        if count > 1 && u.size == 1 && array_call {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "several values for a non-array uniform",
            );
        }
        let (_, matrix, boolean) = uniform_shape(u.ty);
        let last = (loc.element as usize + count).min(u.size as usize);
        let storage = u.storage.clone();
        let is_sampler = u.ty.is_sampler();
        if is_sampler {
            let Values::I(v) = values else {
                unreachable!("checked by call_matches")
            };
            if v.iter()
                .take(last - loc.element as usize)
                .any(|&unit| unit < 0 || unit as u32 >= MAX_TEXTURE_UNITS)
            {
                return self.error(gl::INVALID_VALUE, function, "texture unit out of range");
            }
        }
        let linked = self.objects.linked_mut(current).expect("checked");
        match storage {
            UniformStorage::Block { .. } => {}
            UniformStorage::Sampler { first_slot } => {
                let Values::I(v) = values else { return };
                for (k, e) in (loc.element as usize..last).enumerate() {
                    linked.sampler_units[first_slot as usize + e] = v[k] as u32;
                }
            }
            UniformStorage::Buffer {
                offset,
                array_stride,
                matrix_stride,
            } => {
                for (k, e) in (loc.element as usize..last).enumerate() {
                    let base = offset as usize + e * array_stride as usize;
                    let mut put = |at: usize, word: u32| {
                        if let Some(dst) = linked.uniform_data.get_mut(at..at + 4) {
                            dst.copy_from_slice(&word.to_ne_bytes());
                        }
                    };
                    match matrix {
                        Some((cols, rows)) => {
                            let (cols, rows) = (cols as usize, rows as usize);
                            for c in 0..cols {
                                for r in 0..rows {
                                    let src = if transpose {
                                        r * cols + c
                                    } else {
                                        c * rows + r
                                    };
                                    put(
                                        base + c * matrix_stride as usize + r * 4,
                                        values.word(k * per + src, false),
                                    );
                                }
                            }
                        }
                        None => {
                            for i in 0..per {
                                put(base + i * 4, values.word(k * per + i, boolean));
                            }
                        }
                    }
                }
                linked.uniform_version += 1;
            }
        }
    }
}

macro_rules! uniform_scalars {
    ($($(#[$doc:meta])* $name:ident($($arg:ident),+): $t:ty => $variant:ident, $call:ident, $n:literal;)*) => {
        impl Context {
            $(
                $(#[$doc])*
                pub fn $name(&mut self, location: Option<UniformLocation>, $($arg: $t),+) {
                    self.uniform_impl(location, Call::$call($n), Values::$variant(&[$($arg),+]), false, false, stringify!($name));
                }
            )*
        }
    };
}

uniform_scalars! {
    /// Sets a `float` (or `bool`) uniform (`uniform1f`).
    uniform1f(x): f32 => F, Float, 1;
    /// Sets a `vec2` (or `bvec2`) uniform (`uniform2f`).
    uniform2f(x, y): f32 => F, Float, 2;
    /// Sets a `vec3` (or `bvec3`) uniform (`uniform3f`).
    uniform3f(x, y, z): f32 => F, Float, 3;
    /// Sets a `vec4` (or `bvec4`) uniform (`uniform4f`).
    uniform4f(x, y, z, w): f32 => F, Float, 4;
    /// Sets an `int`, `bool` or sampler uniform (`uniform1i`); for a sampler, the texture unit.
    uniform1i(x): i32 => I, Int, 1;
    /// Sets an `ivec2` (or `bvec2`) uniform (`uniform2i`).
    uniform2i(x, y): i32 => I, Int, 2;
    /// Sets an `ivec3` (or `bvec3`) uniform (`uniform3i`).
    uniform3i(x, y, z): i32 => I, Int, 3;
    /// Sets an `ivec4` (or `bvec4`) uniform (`uniform4i`).
    uniform4i(x, y, z, w): i32 => I, Int, 4;
    /// Sets a `uint` (or `bool`) uniform (`uniform1ui`).
    uniform1ui(x): u32 => U, Uint, 1;
    /// Sets a `uvec2` (or `bvec2`) uniform (`uniform2ui`).
    uniform2ui(x, y): u32 => U, Uint, 2;
    /// Sets a `uvec3` (or `bvec3`) uniform (`uniform3ui`).
    uniform3ui(x, y, z): u32 => U, Uint, 3;
    /// Sets a `uvec4` (or `bvec4`) uniform (`uniform4ui`).
    uniform4ui(x, y, z, w): u32 => U, Uint, 4;
}

macro_rules! uniform_vectors {
    ($($(#[$doc:meta])* $name:ident: $t:ty => $variant:ident, $call:ident, $n:literal;)*) => {
        impl Context {
            $(
                $(#[$doc])*
                pub fn $name(&mut self, location: Option<UniformLocation>, values: &[$t]) {
                    self.uniform_impl(location, Call::$call($n), Values::$variant(values), true, false, stringify!($name));
                }
            )*
        }
    };
}

uniform_vectors! {
    /// Sets `float` uniforms from the location on (`uniform1fv`).
    uniform1fv: f32 => F, Float, 1;
    /// Sets `vec2` uniforms from the location on (`uniform2fv`).
    uniform2fv: f32 => F, Float, 2;
    /// Sets `vec3` uniforms from the location on (`uniform3fv`).
    uniform3fv: f32 => F, Float, 3;
    /// Sets `vec4` uniforms from the location on (`uniform4fv`).
    uniform4fv: f32 => F, Float, 4;
    /// Sets `int`, `bool` or sampler uniforms from the location on (`uniform1iv`).
    uniform1iv: i32 => I, Int, 1;
    /// Sets `ivec2` uniforms from the location on (`uniform2iv`).
    uniform2iv: i32 => I, Int, 2;
    /// Sets `ivec3` uniforms from the location on (`uniform3iv`).
    uniform3iv: i32 => I, Int, 3;
    /// Sets `ivec4` uniforms from the location on (`uniform4iv`).
    uniform4iv: i32 => I, Int, 4;
    /// Sets `uint` uniforms from the location on (`uniform1uiv`).
    uniform1uiv: u32 => U, Uint, 1;
    /// Sets `uvec2` uniforms from the location on (`uniform2uiv`).
    uniform2uiv: u32 => U, Uint, 2;
    /// Sets `uvec3` uniforms from the location on (`uniform3uiv`).
    uniform3uiv: u32 => U, Uint, 3;
    /// Sets `uvec4` uniforms from the location on (`uniform4uiv`).
    uniform4uiv: u32 => U, Uint, 4;
}

macro_rules! uniform_matrices {
    ($($(#[$doc:meta])* $name:ident: $c:literal x $r:literal;)*) => {
        impl Context {
            $(
                $(#[$doc])*
                ///
                /// Values are column by column unless `transpose`.
                pub fn $name(&mut self, location: Option<UniformLocation>, transpose: bool, values: &[f32]) {
                    self.uniform_impl(location, Call::Matrix($c, $r), Values::F(values), true, transpose, stringify!($name));
                }
            )*
        }
    };
}

uniform_matrices! {
    /// Sets `mat2` uniforms (`uniformMatrix2fv`).
    uniform_matrix2fv: 2 x 2;
    /// Sets `mat3` uniforms (`uniformMatrix3fv`).
    uniform_matrix3fv: 3 x 3;
    /// Sets `mat4` uniforms (`uniformMatrix4fv`).
    uniform_matrix4fv: 4 x 4;
    /// Sets `mat2x3` uniforms (`uniformMatrix2x3fv`).
    uniform_matrix2x3fv: 2 x 3;
    /// Sets `mat2x4` uniforms (`uniformMatrix2x4fv`).
    uniform_matrix2x4fv: 2 x 4;
    /// Sets `mat3x2` uniforms (`uniformMatrix3x2fv`).
    uniform_matrix3x2fv: 3 x 2;
    /// Sets `mat3x4` uniforms (`uniformMatrix3x4fv`).
    uniform_matrix3x4fv: 3 x 4;
    /// Sets `mat4x2` uniforms (`uniformMatrix4x2fv`).
    uniform_matrix4x2fv: 4 x 2;
    /// Sets `mat4x3` uniforms (`uniformMatrix4x3fv`).
    uniform_matrix4x3fv: 4 x 3;
}
