//! What is bound: the generic buffer targets, the indexed `UNIFORM_BUFFER` ranges, the vertex
//! array, the texture units, the program in use, the draw and read framebuffers and the
//! renderbuffer.
//!
//! [`Bindings`] keeps one invariant: nothing bound names a deleted object. Deleting an object
//! unbinds it here (`forget_*`) — with one exception GL makes, the program in use, which stays
//! bound and alive until it is replaced; [`Bindings::use_program`] counts that reference in
//! [`Objects`]. The element array buffer is state of the vertex array, so it lives with the
//! vertex array in [`Objects`].

use crate::buffer::BufferRange;
use crate::gl;
use crate::objects::{Id, Objects};

/// The textures bound to one texture unit, one per target.
#[derive(Clone, Debug, Default)]
struct TextureUnit {
    d2: Option<Id>,
    cube: Option<Id>,
    d3: Option<Id>,
    d2_array: Option<Id>,
}

impl TextureUnit {
    /// The texture bound to `target` (a texture target the caller has checked).
    fn get(&self, target: u32) -> Option<Id> {
        match target {
            gl::TEXTURE_2D => self.d2,
            gl::TEXTURE_CUBE_MAP => self.cube,
            gl::TEXTURE_3D => self.d3,
            _ => self.d2_array,
        }
    }

    /// The binding of `target`, to set.
    fn slot(&mut self, target: u32) -> &mut Option<Id> {
        match target {
            gl::TEXTURE_2D => &mut self.d2,
            gl::TEXTURE_CUBE_MAP => &mut self.cube,
            gl::TEXTURE_3D => &mut self.d3,
            _ => &mut self.d2_array,
        }
    }

    /// Unbinds `id` from every target of the unit.
    fn forget(&mut self, id: Id) {
        for slot in [
            &mut self.d2,
            &mut self.cube,
            &mut self.d3,
            &mut self.d2_array,
        ] {
            if *slot == Some(id) {
                *slot = None;
            }
        }
    }
}

/// The context's bindings, with GL's initial values (nothing bound, unit 0 active).
pub(crate) struct Bindings {
    array_buffer: Option<Id>,
    copy_read_buffer: Option<Id>,
    copy_write_buffer: Option<Id>,
    uniform_buffer: Option<Id>,
    pixel_pack_buffer: Option<Id>,
    pixel_unpack_buffer: Option<Id>,
    transform_feedback_buffer: Option<Id>,
    uniform_ranges: Vec<Option<BufferRange>>,
    vertex_array: Option<Id>,
    active_unit: u32,
    texture_units: Vec<TextureUnit>,
    sampler_units: Vec<Option<Id>>,
    program: Option<Id>,
    draw_framebuffer: Option<Id>,
    read_framebuffer: Option<Id>,
    renderbuffer: Option<Id>,
    /// The active queries: occlusion, transform feedback primitives.
    queries: [Option<Id>; 2],
    transform_feedback: Option<Id>,
}

impl Bindings {
    /// Nothing bound, with `uniform_bindings` indexed uniform buffer points and `units`
    /// texture units.
    pub(crate) fn new(uniform_bindings: u32, units: u32) -> Self {
        Bindings {
            array_buffer: None,
            copy_read_buffer: None,
            copy_write_buffer: None,
            uniform_buffer: None,
            pixel_pack_buffer: None,
            pixel_unpack_buffer: None,
            transform_feedback_buffer: None,
            uniform_ranges: vec![None; uniform_bindings as usize],
            vertex_array: None,
            active_unit: 0,
            texture_units: vec![TextureUnit::default(); units as usize],
            sampler_units: vec![None; units as usize],
            program: None,
            draw_framebuffer: None,
            read_framebuffer: None,
            renderbuffer: None,
            queries: [None; 2],
            transform_feedback: None,
        }
    }

    /// The slot of a generic buffer target (not `ELEMENT_ARRAY_BUFFER`, which is vertex
    /// array state); `None` for any other enum.
    fn buffer_slot(&mut self, target: u32) -> Option<&mut Option<Id>> {
        match target {
            gl::ARRAY_BUFFER => Some(&mut self.array_buffer),
            gl::COPY_READ_BUFFER => Some(&mut self.copy_read_buffer),
            gl::COPY_WRITE_BUFFER => Some(&mut self.copy_write_buffer),
            gl::UNIFORM_BUFFER => Some(&mut self.uniform_buffer),
            gl::PIXEL_PACK_BUFFER => Some(&mut self.pixel_pack_buffer),
            gl::PIXEL_UNPACK_BUFFER => Some(&mut self.pixel_unpack_buffer),
            gl::TRANSFORM_FEEDBACK_BUFFER => Some(&mut self.transform_feedback_buffer),
            _ => None,
        }
    }

    /// The buffer bound to a generic target (`ARRAY_BUFFER`, `COPY_READ_BUFFER`,
    /// `COPY_WRITE_BUFFER`, `UNIFORM_BUFFER`, `PIXEL_PACK_BUFFER`, `PIXEL_UNPACK_BUFFER`,
    /// `TRANSFORM_FEEDBACK_BUFFER`); `None` when nothing is, or for another enum.
    pub(crate) fn buffer(&self, target: u32) -> Option<Id> {
        match target {
            gl::ARRAY_BUFFER => self.array_buffer,
            gl::COPY_READ_BUFFER => self.copy_read_buffer,
            gl::COPY_WRITE_BUFFER => self.copy_write_buffer,
            gl::UNIFORM_BUFFER => self.uniform_buffer,
            gl::PIXEL_PACK_BUFFER => self.pixel_pack_buffer,
            gl::PIXEL_UNPACK_BUFFER => self.pixel_unpack_buffer,
            gl::TRANSFORM_FEEDBACK_BUFFER => self.transform_feedback_buffer,
            _ => None,
        }
    }

    /// Binds a live buffer (or nothing) to a generic target; other enums are ignored (the
    /// caller has validated the target).
    pub(crate) fn bind_buffer(&mut self, target: u32, buffer: Option<Id>) {
        if let Some(slot) = self.buffer_slot(target) {
            *slot = buffer;
        }
    }

    /// The range bound to indexed `UNIFORM_BUFFER` point `index`.
    pub(crate) fn uniform_range(&self, index: usize) -> Option<BufferRange> {
        self.uniform_ranges.get(index).copied().flatten()
    }

    /// Binds a range of a live buffer (or nothing) to indexed `UNIFORM_BUFFER` point `index`
    /// (the caller has checked the index).
    pub(crate) fn bind_uniform_range(&mut self, index: usize, range: Option<BufferRange>) {
        if let Some(slot) = self.uniform_ranges.get_mut(index) {
            *slot = range;
        }
    }

    /// Unbinds a buffer that is being deleted from every target and indexed point.
    pub(crate) fn forget_buffer(&mut self, id: Id) {
        for slot in [
            &mut self.array_buffer,
            &mut self.copy_read_buffer,
            &mut self.copy_write_buffer,
            &mut self.uniform_buffer,
            &mut self.pixel_pack_buffer,
            &mut self.pixel_unpack_buffer,
            &mut self.transform_feedback_buffer,
        ] {
            if *slot == Some(id) {
                *slot = None;
            }
        }
        for range in &mut self.uniform_ranges {
            if range.is_some_and(|r| r.buffer == id) {
                *range = None;
            }
        }
    }

    /// The bound vertex array (`None`: the default one).
    pub(crate) fn vertex_array(&self) -> Option<Id> {
        self.vertex_array
    }

    /// Binds a live vertex array (`None`: the default one).
    pub(crate) fn bind_vertex_array(&mut self, id: Option<Id>) {
        self.vertex_array = id;
    }

    /// Unbinds a vertex array that is being deleted (the default one becomes current).
    pub(crate) fn forget_vertex_array(&mut self, id: Id) {
        if self.vertex_array == Some(id) {
            self.vertex_array = None;
        }
    }

    /// The active texture unit (`activeTexture` minus `TEXTURE0`).
    pub(crate) fn active_unit(&self) -> u32 {
        self.active_unit
    }

    /// Selects the active texture unit; the caller has checked that it exists.
    pub(crate) fn set_active_unit(&mut self, unit: u32) {
        if (unit as usize) < self.texture_units.len() {
            self.active_unit = unit;
        }
    }

    /// The texture bound to `target` of texture unit `unit`.
    pub(crate) fn texture(&self, unit: u32, target: u32) -> Option<Id> {
        self.texture_units
            .get(unit as usize)
            .and_then(|u| u.get(target))
    }

    /// Binds a live texture (or nothing) to `target` of the active unit.
    pub(crate) fn bind_texture(&mut self, target: u32, texture: Option<Id>) {
        *self.texture_units[self.active_unit as usize].slot(target) = texture;
    }

    /// Unbinds a texture that is being deleted from every unit.
    pub(crate) fn forget_texture(&mut self, id: Id) {
        for unit in &mut self.texture_units {
            unit.forget(id);
        }
    }

    /// The program in use.
    pub(crate) fn program(&self) -> Option<Id> {
        self.program
    }

    /// Makes a live, linked program current (`None`: none), moving the reference that keeps
    /// the program in use alive; the previous one is freed if it was deleted meanwhile.
    pub(crate) fn use_program(&mut self, id: Option<Id>, objects: &mut Objects) {
        if self.program == id {
            return;
        }
        if let Some(new) = id {
            objects.hold_program(new);
        }
        if let Some(old) = std::mem::replace(&mut self.program, id) {
            objects.release_program(old);
        }
    }

    /// The framebuffers bound for drawing and for reading (`None`: the default one).
    pub(crate) fn framebuffers(&self) -> [Option<Id>; 2] {
        [self.draw_framebuffer, self.read_framebuffer]
    }

    /// Binds a live framebuffer (or the default one) for drawing, reading or both.
    pub(crate) fn bind_framebuffer(&mut self, draw: bool, read: bool, id: Option<Id>) {
        if draw {
            self.draw_framebuffer = id;
        }
        if read {
            self.read_framebuffer = id;
        }
    }

    /// Unbinds a framebuffer that is being deleted (the default one takes its place).
    pub(crate) fn forget_framebuffer(&mut self, id: Id) {
        for slot in [&mut self.draw_framebuffer, &mut self.read_framebuffer] {
            if *slot == Some(id) {
                *slot = None;
            }
        }
    }

    /// The bound renderbuffer.
    pub(crate) fn renderbuffer(&self) -> Option<Id> {
        self.renderbuffer
    }

    /// Binds a live renderbuffer (or none).
    pub(crate) fn bind_renderbuffer(&mut self, id: Option<Id>) {
        self.renderbuffer = id;
    }

    /// Unbinds a renderbuffer that is being deleted.
    pub(crate) fn forget_renderbuffer(&mut self, id: Id) {
        if self.renderbuffer == Some(id) {
            self.renderbuffer = None;
        }
    }

    /// The sampler bound to texture unit `unit`.
    pub(crate) fn sampler(&self, unit: u32) -> Option<Id> {
        self.sampler_units.get(unit as usize).copied().flatten()
    }

    /// Binds a live sampler (or none) to texture unit `unit` (the caller checked the unit).
    pub(crate) fn bind_sampler(&mut self, unit: u32, sampler: Option<Id>) {
        if let Some(slot) = self.sampler_units.get_mut(unit as usize) {
            *slot = sampler;
        }
    }

    /// Unbinds a sampler that is being deleted from every unit.
    pub(crate) fn forget_sampler(&mut self, id: Id) {
        for slot in &mut self.sampler_units {
            if *slot == Some(id) {
                *slot = None;
            }
        }
    }

    /// The active query of a kind (0: occlusion, 1: transform feedback primitives).
    pub(crate) fn query(&self, kind: usize) -> Option<Id> {
        self.queries[kind]
    }

    /// Makes a live query the active one of its kind (or ends it).
    pub(crate) fn begin_query(&mut self, kind: usize, id: Option<Id>) {
        self.queries[kind] = id;
    }

    /// The bound transform feedback object (`None`: the default one).
    pub(crate) fn transform_feedback(&self) -> Option<Id> {
        self.transform_feedback
    }

    /// Binds a live transform feedback object (`None`: the default one).
    pub(crate) fn bind_transform_feedback(&mut self, id: Option<Id>) {
        self.transform_feedback = id;
    }

    /// Unbinds a transform feedback object that is being deleted.
    pub(crate) fn forget_transform_feedback(&mut self, id: Id) {
        if self.transform_feedback == Some(id) {
            self.transform_feedback = None;
        }
    }
}
