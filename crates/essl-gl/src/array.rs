//! Client arrays typed as WebGL's `ArrayBufferView`s: a `&[f32]` is a `Float32Array`, a
//! `&mut [u16]` a `Uint16Array`. WebGL requires the view's element type to suit a pixel
//! `type` (`readPixels` into a `Float32Array` with `UNSIGNED_BYTE` is `INVALID_OPERATION`), so
//! the calls that read or write pixels take a slice of an [`ArrayElement`] and check it.

use crate::gl;

/// The element type of a typed array (`Uint8Array` … `Float32Array`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ArrayType {
    /// `Int8Array`.
    Int8,
    /// `Uint8Array` (and `Uint8ClampedArray`).
    Uint8,
    /// `Int16Array`.
    Int16,
    /// `Uint16Array`.
    Uint16,
    /// `Int32Array`.
    Int32,
    /// `Uint32Array`.
    Uint32,
    /// `Float32Array`.
    Float32,
    /// `Uint8ClampedArray`: where a `Uint8Array` is allowed, so is it.
    Uint8Clamped,
    /// `Float64Array`, `BigInt64Array`, `BigUint64Array`, `Float16Array` or a `DataView`:
    /// views that no WebGL call accepts for pixel data (`INVALID_OPERATION`).
    Other,
}

impl ArrayType {
    /// The JavaScript name of the array type (`"Float32Array"`).
    pub fn name(self) -> &'static str {
        match self {
            ArrayType::Int8 => "Int8Array",
            ArrayType::Uint8 => "Uint8Array",
            ArrayType::Int16 => "Int16Array",
            ArrayType::Uint16 => "Uint16Array",
            ArrayType::Int32 => "Int32Array",
            ArrayType::Uint32 => "Uint32Array",
            ArrayType::Float32 => "Float32Array",
            ArrayType::Uint8Clamped => "Uint8ClampedArray",
            ArrayType::Other => "ArrayBufferView of another type",
        }
    }
}

mod sealed {
    pub trait Sealed {}
}

/// A Rust element type that stands for a typed array's: `i8`, `u8`, `i16`, `u16`, `i32`,
/// `u32`, `f32`.
pub trait ArrayElement: bytemuck::Pod + sealed::Sealed {
    /// The typed array a slice of this element is.
    const TYPE: ArrayType;
}

macro_rules! elements {
    ($($t:ty => $v:ident),*) => {
        $(
            impl sealed::Sealed for $t {}
            impl ArrayElement for $t {
                const TYPE: ArrayType = ArrayType::$v;
            }
        )*
    };
}

elements!(i8 => Int8, u8 => Uint8, i16 => Int16, u16 => Uint16, i32 => Int32, u32 => Uint32, f32 => Float32);

/// The typed array WebGL 2 requires for pixel data of type `ty` (section 5.14.12 of the WebGL
/// 1 spec, extended by WebGL 2's types); `None` where no array is allowed
/// (`FLOAT_32_UNSIGNED_INT_24_8_REV` takes only `null`) or `ty` is not a pixel type.
pub(crate) fn pixel_array_type(ty: u32) -> Option<ArrayType> {
    Some(match ty {
        gl::BYTE => ArrayType::Int8,
        gl::UNSIGNED_BYTE => ArrayType::Uint8,
        gl::SHORT => ArrayType::Int16,
        gl::UNSIGNED_SHORT
        | gl::UNSIGNED_SHORT_5_6_5
        | gl::UNSIGNED_SHORT_4_4_4_4
        | gl::UNSIGNED_SHORT_5_5_5_1
        | gl::HALF_FLOAT
        | 0x8D61 => ArrayType::Uint16, // WebGL 1's HALF_FLOAT_OES
        gl::INT => ArrayType::Int32,
        gl::UNSIGNED_INT
        | gl::UNSIGNED_INT_2_10_10_10_REV
        | gl::UNSIGNED_INT_10F_11F_11F_REV
        | gl::UNSIGNED_INT_5_9_9_9_REV
        | gl::UNSIGNED_INT_24_8 => ArrayType::Uint32,
        gl::FLOAT => ArrayType::Float32,
        _ => return None,
    })
}

/// The bytes of a typed array and which typed array it is: client data as a binding of
/// JavaScript holds it (a view of any type over an `ArrayBuffer`), for the `_view` forms of
/// the calls that check the array's type against a pixel type.
#[derive(Clone, Copy, Debug)]
pub struct ArrayView<'a> {
    /// Which typed array the bytes are.
    pub array: ArrayType,
    /// The view's bytes, in the machine's order.
    pub bytes: &'a [u8],
}

impl<'a> ArrayView<'a> {
    /// The view of a slice of an [`ArrayElement`] (a `&[f32]` is a `Float32Array`).
    pub fn of<T: ArrayElement>(elements: &'a [T]) -> ArrayView<'a> {
        ArrayView {
            array: T::TYPE,
            bytes: bytemuck::cast_slice(elements),
        }
    }
}

/// A typed array to write into: [`ArrayView`]'s mutable form (`readPixels`).
#[derive(Debug)]
pub struct ArrayViewMut<'a> {
    /// Which typed array the bytes are.
    pub array: ArrayType,
    /// The view's bytes, in the machine's order.
    pub bytes: &'a mut [u8],
}

/// Why pixel data of `array` type cannot go with pixel `ty`, or `None` when it can.
pub(crate) fn array_mismatch(ty: u32, array: ArrayType) -> Option<String> {
    let array = match array {
        ArrayType::Uint8Clamped => ArrayType::Uint8,
        a => a,
    };
    match pixel_array_type(ty) {
        Some(t) if t == array => None,
        Some(t) => Some(format!(
            "type 0x{ty:04X} needs a {}, not a {}",
            t.name(),
            array.name()
        )),
        None => Some(format!("type 0x{ty:04X} takes no client data, only null")),
    }
}
