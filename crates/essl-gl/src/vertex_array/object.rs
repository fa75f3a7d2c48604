//! A vertex array object's state (each attribute's array and the element array buffer) and
//! the generic values of disabled attributes, which are context state.

use crate::gl;
use crate::objects::Id;

/// One vertex attribute's array state (part of a vertex array object).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct VertexAttrib {
    pub(crate) enabled: bool,
    /// Components per element, 1..=4.
    pub(crate) size: u8,
    /// The component type (`FLOAT`, `UNSIGNED_BYTE`, …).
    pub(crate) ty: u32,
    pub(crate) normalized: bool,
    /// Set by `vertex_attrib_i_pointer`: the values stay integers.
    pub(crate) integer: bool,
    /// The stride as given (0 means tightly packed).
    pub(crate) stride: u32,
    pub(crate) offset: u64,
    pub(crate) buffer: Option<Id>,
    pub(crate) divisor: u32,
}

impl Default for VertexAttrib {
    fn default() -> Self {
        VertexAttrib {
            enabled: false,
            size: 4,
            ty: gl::FLOAT,
            normalized: false,
            integer: false,
            stride: 0,
            offset: 0,
            buffer: None,
            divisor: 0,
        }
    }
}

impl VertexAttrib {
    /// Bytes of one element.
    pub(crate) fn element_size(&self) -> u64 {
        if super::packed(self.ty) {
            return 4; // four components in one 32-bit word
        }
        self.size as u64 * type_size(self.ty).unwrap_or(4) as u64
    }

    /// The distance between elements: the stride, or the element size for stride 0.
    pub(crate) fn effective_stride(&self) -> u64 {
        if self.stride == 0 {
            self.element_size()
        } else {
            self.stride as u64
        }
    }
}

/// A vertex array object: the attribute arrays and the element array buffer.
#[derive(Clone, Debug)]
pub(crate) struct VertexArrayObject {
    pub(crate) attribs: Vec<VertexAttrib>,
    pub(crate) element_buffer: Option<Id>,
    /// `isVertexArray` is false until the object is bound once.
    pub(crate) bound_once: bool,
}

impl VertexArrayObject {
    pub(crate) fn new(max_attribs: u32) -> Self {
        VertexArrayObject {
            attribs: vec![VertexAttrib::default(); max_attribs as usize],
            element_buffer: None,
            bound_once: false,
        }
    }
}

/// A generic (constant) attribute value, used when an attribute's array is disabled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum GenericAttrib {
    /// Set by `vertex_attrib*f`.
    Float([f32; 4]),
    /// Set by `vertex_attrib_i4i`.
    Int([i32; 4]),
    /// Set by `vertex_attrib_i4ui`.
    Uint([u32; 4]),
}

impl Default for GenericAttrib {
    fn default() -> Self {
        GenericAttrib::Float([0.0, 0.0, 0.0, 1.0])
    }
}

/// Bytes of one component of a vertex attribute type; `None` for an unknown type.
pub(crate) fn type_size(ty: u32) -> Option<u32> {
    match ty {
        gl::BYTE | gl::UNSIGNED_BYTE => Some(1),
        gl::SHORT | gl::UNSIGNED_SHORT | gl::HALF_FLOAT => Some(2),
        gl::INT
        | gl::UNSIGNED_INT
        | gl::FLOAT
        | gl::INT_2_10_10_10_REV
        | gl::UNSIGNED_INT_2_10_10_10_REV => Some(4),
        _ => None,
    }
}
