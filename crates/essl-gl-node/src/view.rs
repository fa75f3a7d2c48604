//! `ArrayBufferView`s as essl-gl takes them: a typed array or `DataView` from JavaScript,
//! borrowed for the length of one call (no copy), with its type ([`ArrayType`]) so that
//! essl-gl checks it against a pixel type as WebGL does.

use std::ptr;

use essl_gl::{ArrayType, ArrayView, ArrayViewMut};
use napi::bindgen_prelude::{FromNapiValue, TypeName, ValidateNapiValue, ValueType};
use napi::sys;

/// A typed array or `DataView` borrowed from JavaScript for one call.
pub struct View {
    /// Which typed array it is.
    pub array: ArrayType,
    /// Bytes per element (1 for a `DataView`).
    pub element: usize,
    data: *mut u8,
    len: usize,
}

impl View {
    /// The view's bytes.
    pub fn bytes(&self) -> &[u8] {
        if self.len == 0 {
            return &[];
        }
        // SAFETY: N-API gave a pointer to `len` bytes of the view's ArrayBuffer, which the
        // caller's JavaScript holds for the length of the call that borrowed it.
        unsafe { std::slice::from_raw_parts(self.data, self.len) }
    }

    /// The view's bytes, to write.
    pub fn bytes_mut(&mut self) -> &mut [u8] {
        if self.len == 0 {
            return &mut [];
        }
        // SAFETY: as in `bytes`; JavaScript does not run while the call writes.
        unsafe { std::slice::from_raw_parts_mut(self.data, self.len) }
    }

    /// Elements `offset..offset + length` (`length` 0: to the end), as WebGL 2's `srcOffset`
    /// and `srcLength` pick them; `None` past the end.
    pub fn window(&self, offset: u32, length: u32) -> Option<ArrayView<'_>> {
        let bytes = self.bytes();
        let (start, end) = self.range(offset, length)?;
        Some(ArrayView {
            array: self.array,
            bytes: &bytes[start..end],
        })
    }

    /// [`View::window`] to write into (`readPixels`' `dstOffset`, `getBufferSubData`).
    pub fn window_mut(&mut self, offset: u32, length: u32) -> Option<ArrayViewMut<'_>> {
        let (start, end) = self.range(offset, length)?;
        let array = self.array;
        Some(ArrayViewMut {
            array,
            bytes: &mut self.bytes_mut()[start..end],
        })
    }

    fn range(&self, offset: u32, length: u32) -> Option<(usize, usize)> {
        let count = self.len / self.element;
        let offset = offset as usize;
        let end = if length == 0 {
            count
        } else {
            offset.checked_add(length as usize)?
        };
        (offset <= count && end <= count).then_some((offset * self.element, end * self.element))
    }
}

impl TypeName for View {
    fn type_name() -> &'static str {
        "ArrayBufferView"
    }

    fn value_type() -> ValueType {
        ValueType::Object
    }
}

impl ValidateNapiValue for View {}

impl FromNapiValue for View {
    unsafe fn from_napi_value(env: sys::napi_env, value: sys::napi_value) -> napi::Result<Self> {
        let mut is_typed = false;
        unsafe { sys::napi_is_typedarray(env, value, &mut is_typed) };
        if is_typed {
            let (mut kind, mut length, mut data) = (0, 0, ptr::null_mut());
            let (mut buffer, mut offset) = (ptr::null_mut(), 0);
            let status = unsafe {
                sys::napi_get_typedarray_info(
                    env,
                    value,
                    &mut kind,
                    &mut length,
                    &mut data,
                    &mut buffer,
                    &mut offset,
                )
            };
            if status != sys::Status::napi_ok {
                return Err(napi::Error::from_reason("not a readable typed array"));
            }
            let (array, element) = typed_array_type(kind);
            return Ok(View {
                array,
                element,
                data: data.cast(),
                len: length * element,
            });
        }
        let mut is_view = false;
        unsafe { sys::napi_is_dataview(env, value, &mut is_view) };
        if is_view {
            let (mut length, mut data, mut buffer, mut offset) =
                (0, ptr::null_mut(), ptr::null_mut(), 0);
            let status = unsafe {
                sys::napi_get_dataview_info(
                    env,
                    value,
                    &mut length,
                    &mut data,
                    &mut buffer,
                    &mut offset,
                )
            };
            if status != sys::Status::napi_ok {
                return Err(napi::Error::from_reason("not a readable DataView"));
            }
            return Ok(View {
                array: ArrayType::Other,
                element: 1,
                data: data.cast(),
                len: length,
            });
        }
        Err(napi::Error::new(
            napi::Status::InvalidArg,
            "not an ArrayBufferView",
        ))
    }
}

/// essl-gl's array type and the element size of N-API's typed array kind.
fn typed_array_type(kind: sys::napi_typedarray_type) -> (ArrayType, usize) {
    use sys::TypedarrayType as T;
    match kind {
        T::int8_array => (ArrayType::Int8, 1),
        T::uint8_array => (ArrayType::Uint8, 1),
        T::uint8_clamped_array => (ArrayType::Uint8Clamped, 1),
        T::int16_array => (ArrayType::Int16, 2),
        T::uint16_array => (ArrayType::Uint16, 2),
        T::int32_array => (ArrayType::Int32, 4),
        T::uint32_array => (ArrayType::Uint32, 4),
        T::float32_array => (ArrayType::Float32, 4),
        // Float16Array (11) where Node reports it.
        11 => (ArrayType::Other, 2),
        // Float64Array, BigInt64Array, BigUint64Array.
        _ => (ArrayType::Other, 8),
    }
}
