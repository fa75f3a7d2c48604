//! Vertex arrays and vertex attributes: `create_vertex_array`, `bind_vertex_array`,
//! `vertex_attrib_pointer`, `enable_vertex_attrib_array`, `vertex_attrib4f`, … The state
//! they set is [`object`]'s.

mod object;

pub(crate) use object::{type_size, GenericAttrib, VertexArrayObject, VertexAttrib};

use crate::context::Context;
use crate::gl;
use crate::objects::VertexArray;

/// An attribute array as `vertexAttribPointer` / `vertexAttribIPointer` describe it.
struct AttribPointer {
    index: u32,
    size: i32,
    ty: u32,
    normalized: bool,
    /// Set by `vertexAttribIPointer`: the values stay integers.
    integer: bool,
    stride: i32,
    offset: i64,
}

impl Context {
    /// Creates a vertex array object (`createVertexArray`).
    pub fn create_vertex_array(&mut self) -> VertexArray {
        let vao = VertexArrayObject::new(self.limits.max_vertex_attribs);
        VertexArray {
            ctx: self.id,
            id: self.objects.vertex_arrays.insert(vao),
        }
    }

    /// Binds a vertex array object (`bindVertexArray`); `None` binds the default one.
    pub fn bind_vertex_array(&mut self, vertex_array: Option<VertexArray>) {
        const F: &str = "bindVertexArray";
        match vertex_array {
            None => self.bindings.bind_vertex_array(None),
            Some(v) => {
                if !self.owns(v.ctx, F) {
                    return;
                }
                let Some(obj) = self.objects.vertex_arrays.get_mut(v.id) else {
                    return self.error(gl::INVALID_OPERATION, F, "deleted vertex array");
                };
                obj.bound_once = true;
                self.bindings.bind_vertex_array(Some(v.id));
            }
        }
    }

    /// Whether `vertex_array` names a live vertex array that was bound once (`isVertexArray`).
    pub fn is_vertex_array(&self, vertex_array: VertexArray) -> bool {
        vertex_array.ctx == self.id
            && self
                .objects
                .vertex_arrays
                .get(vertex_array.id)
                .is_some_and(|v| v.bound_once)
    }

    /// Deletes a vertex array object (`deleteVertexArray`); if bound, the default one is bound.
    pub fn delete_vertex_array(&mut self, vertex_array: VertexArray) {
        if !self.owns(vertex_array.ctx, "deleteVertexArray") {
            return;
        }
        if !self.objects.vertex_arrays.is_live(vertex_array.id) {
            return;
        }
        self.bindings.forget_vertex_array(vertex_array.id);
        self.objects.delete_vertex_array(vertex_array.id);
    }

    fn attrib_index(&mut self, index: u32, function: &str) -> Option<usize> {
        if index >= self.limits.max_vertex_attribs {
            let msg = format!(
                "index {index} ≥ MAX_VERTEX_ATTRIBS ({})",
                self.limits.max_vertex_attribs
            );
            self.error(gl::INVALID_VALUE, function, msg);
            return None;
        }
        Some(index as usize)
    }

    /// Makes attribute `index` read from its array (`enableVertexAttribArray`).
    pub fn enable_vertex_attrib_array(&mut self, index: u32) {
        if let Some(i) = self.attrib_index(index, "enableVertexAttribArray") {
            self.vao_mut().attribs[i].enabled = true;
        }
    }

    /// Makes attribute `index` use its generic value (`disableVertexAttribArray`).
    pub fn disable_vertex_attrib_array(&mut self, index: u32) {
        if let Some(i) = self.attrib_index(index, "disableVertexAttribArray") {
            self.vao_mut().attribs[i].enabled = false;
        }
    }

    /// Describes attribute `index`'s array in the buffer bound to `ARRAY_BUFFER`
    /// (`vertexAttribPointer`): `size` 1–4 components of `ty` (`FLOAT`, `BYTE`,
    /// `UNSIGNED_BYTE`, `SHORT`, `UNSIGNED_SHORT`, `INT`, `UNSIGNED_INT`, `HALF_FLOAT`),
    /// converted to floats (mapped to −1..1 or 0..1 when `normalized`).
    ///
    /// WebGL's rules: `stride` 0..=255 and `offset` ≥ 0 (`INVALID_VALUE`), both multiples of
    /// the type's size, and a nonzero `offset` needs a bound buffer (`INVALID_OPERATION`).
    pub fn vertex_attrib_pointer(
        &mut self,
        index: u32,
        size: i32,
        ty: u32,
        normalized: bool,
        stride: i32,
        offset: i64,
    ) {
        const F: &str = "vertexAttribPointer";
        if self.webgl1_refuses_vertex_type(ty) {
            return;
        }
        let float_types = [
            gl::INT_2_10_10_10_REV,
            gl::UNSIGNED_INT_2_10_10_10_REV,
            gl::BYTE,
            gl::UNSIGNED_BYTE,
            gl::SHORT,
            gl::UNSIGNED_SHORT,
            gl::INT,
            gl::UNSIGNED_INT,
            gl::FLOAT,
            gl::HALF_FLOAT,
        ];
        let array = AttribPointer {
            index,
            size,
            ty,
            normalized,
            integer: false,
            stride,
            offset,
        };
        self.attrib_pointer(array, &float_types, F);
    }

    /// Describes attribute `index`'s array of integers (`vertexAttribIPointer`) for an
    /// `int`/`uint` shader input: `ty` is `BYTE`, `UNSIGNED_BYTE`, `SHORT`, `UNSIGNED_SHORT`,
    /// `INT` or `UNSIGNED_INT`. Same rules as [`Context::vertex_attrib_pointer`].
    pub fn vertex_attrib_i_pointer(
        &mut self,
        index: u32,
        size: i32,
        ty: u32,
        stride: i32,
        offset: i64,
    ) {
        const F: &str = "vertexAttribIPointer";
        let int_types = [
            gl::BYTE,
            gl::UNSIGNED_BYTE,
            gl::SHORT,
            gl::UNSIGNED_SHORT,
            gl::INT,
            gl::UNSIGNED_INT,
        ];
        let array = AttribPointer {
            index,
            size,
            ty,
            normalized: false,
            integer: true,
            stride,
            offset,
        };
        self.attrib_pointer(array, &int_types, F);
    }

    /// `vertexAttribPointer` and `vertexAttribIPointer`: WebGL's checks (`ty` among
    /// `types`), then the array's description.
    fn attrib_pointer(&mut self, array: AttribPointer, types: &[u32], function: &str) {
        let AttribPointer {
            index,
            size,
            ty,
            normalized,
            integer,
            stride,
            offset,
        } = array;
        let Some(i) = self.attrib_index(index, function) else {
            return;
        };
        if !types.contains(&ty) {
            return self.error(gl::INVALID_ENUM, function, format_args!("type 0x{ty:04X}"));
        }
        if !(1..=4).contains(&size) {
            return self.error(gl::INVALID_VALUE, function, "size must be 1, 2, 3 or 4");
        }
        if packed(ty) && size != 4 {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "a packed 2_10_10_10 type has size 4",
            );
        }
        if !(0..=255).contains(&stride) {
            return self.error(
                gl::INVALID_VALUE,
                function,
                "stride must be between 0 and 255",
            );
        }
        if offset < 0 {
            return self.error(gl::INVALID_VALUE, function, "negative offset");
        }
        let ts = type_size(ty).expect("checked") as i64;
        if offset % ts != 0 || stride as i64 % ts != 0 {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "offset and stride must be multiples of the type's size",
            );
        }
        let array_buffer = self.bindings.buffer(gl::ARRAY_BUFFER);
        if array_buffer.is_none() && offset != 0 {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "no ARRAY_BUFFER bound and offset ≠ 0",
            );
        }
        let vao = self.bindings.vertex_array();
        self.objects.set_attrib_buffer(vao, i, array_buffer);
        let a = &mut self.vao_mut().attribs[i];
        a.size = size as u8;
        a.ty = ty;
        a.normalized = normalized;
        a.integer = integer;
        a.stride = stride as u32;
        a.offset = offset as u64;
    }

    /// Sets how many instances share one element of attribute `index` (`vertexAttribDivisor`);
    /// 0 advances per vertex.
    pub fn vertex_attrib_divisor(&mut self, index: u32, divisor: u32) {
        if let Some(i) = self.attrib_index(index, "vertexAttribDivisor") {
            self.vao_mut().attribs[i].divisor = divisor;
        }
    }

    fn set_generic(&mut self, index: u32, value: GenericAttrib, function: &str) {
        if let Some(i) = self.attrib_index(index, function) {
            self.state.generic_attribs[i] = value;
        }
    }

    /// Sets the generic value of attribute `index` to `(x, 0, 0, 1)` (`vertexAttrib1f`).
    pub fn vertex_attrib1f(&mut self, index: u32, x: f32) {
        self.set_generic(
            index,
            GenericAttrib::Float([x, 0.0, 0.0, 1.0]),
            "vertexAttrib1f",
        );
    }

    /// Sets the generic value of attribute `index` to `(x, y, 0, 1)` (`vertexAttrib2f`).
    pub fn vertex_attrib2f(&mut self, index: u32, x: f32, y: f32) {
        self.set_generic(
            index,
            GenericAttrib::Float([x, y, 0.0, 1.0]),
            "vertexAttrib2f",
        );
    }

    /// Sets the generic value of attribute `index` to `(x, y, z, 1)` (`vertexAttrib3f`).
    pub fn vertex_attrib3f(&mut self, index: u32, x: f32, y: f32, z: f32) {
        self.set_generic(
            index,
            GenericAttrib::Float([x, y, z, 1.0]),
            "vertexAttrib3f",
        );
    }

    /// Sets the generic value of attribute `index` to `(x, y, z, w)` (`vertexAttrib4f`).
    pub fn vertex_attrib4f(&mut self, index: u32, x: f32, y: f32, z: f32, w: f32) {
        self.set_generic(index, GenericAttrib::Float([x, y, z, w]), "vertexAttrib4f");
    }

    /// `vertexAttrib1fv`: the first value of `values` (`INVALID_VALUE` when empty).
    pub fn vertex_attrib1fv(&mut self, index: u32, values: &[f32]) {
        self.vertex_attrib_nfv(index, values, 1, "vertexAttrib1fv");
    }

    /// `vertexAttrib2fv`: the first two values (`INVALID_VALUE` when fewer).
    pub fn vertex_attrib2fv(&mut self, index: u32, values: &[f32]) {
        self.vertex_attrib_nfv(index, values, 2, "vertexAttrib2fv");
    }

    /// `vertexAttrib3fv`: the first three values (`INVALID_VALUE` when fewer).
    pub fn vertex_attrib3fv(&mut self, index: u32, values: &[f32]) {
        self.vertex_attrib_nfv(index, values, 3, "vertexAttrib3fv");
    }

    fn vertex_attrib_nfv(&mut self, index: u32, values: &[f32], n: usize, function: &str) {
        if values.len() < n {
            return self.error(
                gl::INVALID_VALUE,
                function,
                format_args!("{n} values needed"),
            );
        }
        let mut v = [0.0, 0.0, 0.0, 1.0];
        v[..n].copy_from_slice(&values[..n]);
        self.set_generic(index, GenericAttrib::Float(v), function);
    }

    /// `vertexAttribI4iv`: four signed integers (`INVALID_VALUE` when fewer).
    pub fn vertex_attrib_i4iv(&mut self, index: u32, values: &[i32]) {
        match values.get(..4) {
            Some(v) => self.set_generic(
                index,
                GenericAttrib::Int([v[0], v[1], v[2], v[3]]),
                "vertexAttribI4iv",
            ),
            None => self.error(gl::INVALID_VALUE, "vertexAttribI4iv", "4 values needed"),
        }
    }

    /// `vertexAttribI4uiv`: four unsigned integers (`INVALID_VALUE` when fewer).
    pub fn vertex_attrib_i4uiv(&mut self, index: u32, values: &[u32]) {
        match values.get(..4) {
            Some(v) => self.set_generic(
                index,
                GenericAttrib::Uint([v[0], v[1], v[2], v[3]]),
                "vertexAttribI4uiv",
            ),
            None => self.error(gl::INVALID_VALUE, "vertexAttribI4uiv", "4 values needed"),
        }
    }

    /// `vertexAttrib4fv`: the first four values (`INVALID_VALUE` when fewer).
    pub fn vertex_attrib4fv(&mut self, index: u32, values: &[f32]) {
        self.vertex_attrib_nfv(index, values, 4, "vertexAttrib4fv");
    }

    /// Sets the generic value of an `ivec4` attribute (`vertexAttribI4i`).
    pub fn vertex_attrib_i4i(&mut self, index: u32, x: i32, y: i32, z: i32, w: i32) {
        self.set_generic(index, GenericAttrib::Int([x, y, z, w]), "vertexAttribI4i");
    }

    /// Sets the generic value of a `uvec4` attribute (`vertexAttribI4ui`).
    pub fn vertex_attrib_i4ui(&mut self, index: u32, x: u32, y: u32, z: u32, w: u32) {
        self.set_generic(index, GenericAttrib::Uint([x, y, z, w]), "vertexAttribI4ui");
    }
}

/// Whether `ty` packs four components in 32 bits (`INT_2_10_10_10_REV`,
/// `UNSIGNED_INT_2_10_10_10_REV`).
pub(crate) fn packed(ty: u32) -> bool {
    matches!(ty, gl::INT_2_10_10_10_REV | gl::UNSIGNED_INT_2_10_10_10_REV)
}
