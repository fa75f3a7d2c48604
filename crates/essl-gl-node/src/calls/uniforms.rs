//! `uniform*` and `uniformMatrix*`: scalars, and lists with WebGL 2's `srcOffset` and
//! `srcLength`.

use essl_gl::UniformLocation;
use napi_derive::napi;

use crate::context::NativeContext;

/// Elements `offset..offset + length` of `values` (`length` 0: to the end).
fn window<T>(values: &[T], offset: u32, length: u32) -> Option<&[T]> {
    let offset = offset as usize;
    let end = if length == 0 {
        values.len()
    } else {
        offset.checked_add(length as usize)?
    };
    values.get(offset..end)
}

macro_rules! scalars {
    ($($(#[$doc:meta])* $js:literal $name:ident($($a:ident: $t:ty => $c:ty),+);)*) => {
        #[napi]
        impl NativeContext {
            $(
                $(#[$doc])*
                #[napi(js_name = $js, catch_unwind)]
                pub fn $name(&mut self, location: u32, $($a: $t),+) -> napi::Result<()> {
                    if let Some(l) = self.arg::<UniformLocation>(location, $js) {
                        self.gl()?.$name(l, $($a as $c),+);
                    }
                    Ok(())
                }
            )*
        }
    };
}

scalars! {
    /// `uniform1f`.
    "uniform1f" uniform1f(x: f64 => f32);
    /// `uniform2f`.
    "uniform2f" uniform2f(x: f64 => f32, y: f64 => f32);
    /// `uniform3f`.
    "uniform3f" uniform3f(x: f64 => f32, y: f64 => f32, z: f64 => f32);
    /// `uniform4f`.
    "uniform4f" uniform4f(x: f64 => f32, y: f64 => f32, z: f64 => f32, w: f64 => f32);
    /// `uniform1i`.
    "uniform1i" uniform1i(x: i32 => i32);
    /// `uniform2i`.
    "uniform2i" uniform2i(x: i32 => i32, y: i32 => i32);
    /// `uniform3i`.
    "uniform3i" uniform3i(x: i32 => i32, y: i32 => i32, z: i32 => i32);
    /// `uniform4i`.
    "uniform4i" uniform4i(x: i32 => i32, y: i32 => i32, z: i32 => i32, w: i32 => i32);
    /// `uniform1ui`.
    "uniform1ui" uniform1ui(x: u32 => u32);
    /// `uniform2ui`.
    "uniform2ui" uniform2ui(x: u32 => u32, y: u32 => u32);
    /// `uniform3ui`.
    "uniform3ui" uniform3ui(x: u32 => u32, y: u32 => u32, z: u32 => u32);
    /// `uniform4ui`.
    "uniform4ui" uniform4ui(x: u32 => u32, y: u32 => u32, z: u32 => u32, w: u32 => u32);
}

#[napi]
impl NativeContext {
    /// `uniform[1234]fv` (`n` components) with `srcOffset` and `srcLength`.
    #[napi(js_name = "uniformFv", catch_unwind)]
    pub fn uniform_fv(
        &mut self,
        n: u32,
        location: u32,
        values: &[f32],
        offset: u32,
        length: u32,
    ) -> napi::Result<()> {
        let f =
            ["uniform1fv", "uniform2fv", "uniform3fv", "uniform4fv"][(n as usize).clamp(1, 4) - 1];
        let Some(l) = self.arg::<UniformLocation>(location, f) else {
            return Ok(());
        };
        let Some(v) = window(values, offset, length) else {
            self.past_end(f);
            return Ok(());
        };
        let c = self.gl()?;
        match n {
            1 => c.uniform1fv(l, v),
            2 => c.uniform2fv(l, v),
            3 => c.uniform3fv(l, v),
            _ => c.uniform4fv(l, v),
        }
        Ok(())
    }

    /// `uniform[1234]iv` with `srcOffset` and `srcLength`.
    #[napi(js_name = "uniformIv", catch_unwind)]
    pub fn uniform_iv(
        &mut self,
        n: u32,
        location: u32,
        values: &[i32],
        offset: u32,
        length: u32,
    ) -> napi::Result<()> {
        let f =
            ["uniform1iv", "uniform2iv", "uniform3iv", "uniform4iv"][(n as usize).clamp(1, 4) - 1];
        let Some(l) = self.arg::<UniformLocation>(location, f) else {
            return Ok(());
        };
        let Some(v) = window(values, offset, length) else {
            self.past_end(f);
            return Ok(());
        };
        let c = self.gl()?;
        match n {
            1 => c.uniform1iv(l, v),
            2 => c.uniform2iv(l, v),
            3 => c.uniform3iv(l, v),
            _ => c.uniform4iv(l, v),
        }
        Ok(())
    }

    /// `uniform[1234]uiv` with `srcOffset` and `srcLength`.
    #[napi(js_name = "uniformUiv", catch_unwind)]
    pub fn uniform_uiv(
        &mut self,
        n: u32,
        location: u32,
        values: &[u32],
        offset: u32,
        length: u32,
    ) -> napi::Result<()> {
        let f = ["uniform1uiv", "uniform2uiv", "uniform3uiv", "uniform4uiv"]
            [(n as usize).clamp(1, 4) - 1];
        let Some(l) = self.arg::<UniformLocation>(location, f) else {
            return Ok(());
        };
        let Some(v) = window(values, offset, length) else {
            self.past_end(f);
            return Ok(());
        };
        let c = self.gl()?;
        match n {
            1 => c.uniform1uiv(l, v),
            2 => c.uniform2uiv(l, v),
            3 => c.uniform3uiv(l, v),
            _ => c.uniform4uiv(l, v),
        }
        Ok(())
    }

    /// `uniformMatrix{C}x{R}fv` (`shape` is `"2"`, `"3"`, `"4"`, `"2x3"`, …) with
    /// `srcOffset` and `srcLength`.
    #[napi(js_name = "uniformMatrixFv", catch_unwind)]
    pub fn uniform_matrix_fv(
        &mut self,
        shape: u32,
        location: u32,
        transpose: bool,
        values: &[f32],
        offset: u32,
        length: u32,
    ) -> napi::Result<()> {
        let f = "uniformMatrix";
        let Some(l) = self.arg::<UniformLocation>(location, f) else {
            return Ok(());
        };
        let Some(v) = window(values, offset, length) else {
            self.past_end(f);
            return Ok(());
        };
        let c = self.gl()?;
        // `shape` is columns × 10 + rows.
        match shape {
            22 => c.uniform_matrix2fv(l, transpose, v),
            33 => c.uniform_matrix3fv(l, transpose, v),
            44 => c.uniform_matrix4fv(l, transpose, v),
            23 => c.uniform_matrix2x3fv(l, transpose, v),
            24 => c.uniform_matrix2x4fv(l, transpose, v),
            32 => c.uniform_matrix3x2fv(l, transpose, v),
            34 => c.uniform_matrix3x4fv(l, transpose, v),
            42 => c.uniform_matrix4x2fv(l, transpose, v),
            _ => c.uniform_matrix4x3fv(l, transpose, v),
        }
        Ok(())
    }
}
