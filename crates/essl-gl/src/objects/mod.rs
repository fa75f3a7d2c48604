//! The objects of a context and the references between them.
//!
//! [`Objects`] owns one [`Table`] per kind of object and the default vertex array. Objects
//! refer to each other — a vertex array to its buffers, a program to its shaders, a
//! framebuffer to its attached images, and the context to the program in use — and such a
//! reference keeps a deleted object alive, as GL requires. The methods here are the only ones that set or drop such a reference (a table's
//! counting methods are private to this module), so the counts always match the references
//! held: an object is freed exactly when it is deleted and nothing refers to it any more.
//!
//! What is *bound* (buffer targets, texture units, the vertex array) is
//! [`Bindings`](crate::bindings::Bindings)' business; a binding of the context holds no count
//! because deleting an object unbinds it.

mod handles;
mod table;

pub(crate) use handles::{next_context_id, Id};
pub use handles::{
    Buffer, Framebuffer, Program, Query, Renderbuffer, Sampler, Shader, Sync, Texture,
    TransformFeedback, UniformLocation, VertexArray,
};
pub(crate) use table::Table;

use crate::buffer::BufferObject;
use crate::framebuffer::{Attachment, FramebufferObject};
use crate::program::{LinkedProgram, ProgramObject, ShaderObject};
use crate::query_object::QueryObject;
use crate::renderbuffer::RenderbufferObject;
use crate::sampler::SamplerObject;
use crate::sync::SyncObject;
use crate::texture::TextureObject;
use crate::transform_feedback::TransformFeedbackObject;
use crate::vertex_array::VertexArrayObject;

/// Every object of a context.
pub(crate) struct Objects {
    pub(crate) buffers: Table<BufferObject>,
    pub(crate) textures: Table<TextureObject>,
    pub(crate) vertex_arrays: Table<VertexArrayObject>,
    pub(crate) programs: Table<ProgramObject>,
    pub(crate) shaders: Table<ShaderObject>,
    pub(crate) framebuffers: Table<FramebufferObject>,
    pub(crate) renderbuffers: Table<RenderbufferObject>,
    pub(crate) samplers: Table<SamplerObject>,
    pub(crate) queries: Table<QueryObject>,
    pub(crate) syncs: Table<SyncObject>,
    pub(crate) transform_feedbacks: Table<TransformFeedbackObject>,
    /// The transform feedback object in use when none is bound.
    default_transform_feedback: TransformFeedbackObject,
    /// The vertex array in use when none is bound (WebGL's default vertex array object).
    default_vertex_array: VertexArrayObject,
}

impl Objects {
    /// No objects yet; vertex arrays have `max_vertex_attribs` attributes.
    pub(crate) fn new(max_vertex_attribs: u32) -> Self {
        Objects {
            buffers: Table::default(),
            textures: Table::default(),
            vertex_arrays: Table::default(),
            programs: Table::default(),
            shaders: Table::default(),
            framebuffers: Table::default(),
            renderbuffers: Table::default(),
            samplers: Table::default(),
            queries: Table::default(),
            syncs: Table::default(),
            transform_feedbacks: Table::default(),
            default_transform_feedback: TransformFeedbackObject::default(),
            default_vertex_array: VertexArrayObject::new(max_vertex_attribs),
        }
    }

    /// The vertex array `bound` names (the default one for `None`, or for a vertex array that
    /// is gone).
    pub(crate) fn vertex_array(&self, bound: Option<Id>) -> &VertexArrayObject {
        match bound.and_then(|id| self.vertex_arrays.get_any(id)) {
            Some(v) => v,
            None => &self.default_vertex_array,
        }
    }

    /// Mutable [`Objects::vertex_array`], for the attribute state that holds no reference
    /// (use [`Objects::set_attrib_buffer`] and [`Objects::set_element_buffer`] for buffers).
    pub(crate) fn vertex_array_mut(&mut self, bound: Option<Id>) -> &mut VertexArrayObject {
        match bound {
            Some(id) if self.vertex_arrays.get_any(id).is_some() => {
                self.vertex_arrays.get_any_mut(id).expect("checked above")
            }
            _ => &mut self.default_vertex_array,
        }
    }

    /// Points attribute `index` of vertex array `vao` at `buffer`, moving the reference.
    pub(crate) fn set_attrib_buffer(&mut self, vao: Option<Id>, index: usize, buffer: Option<Id>) {
        let mut slot = self.vertex_array(vao).attribs[index].buffer;
        self.buffers.retarget(&mut slot, buffer);
        self.vertex_array_mut(vao).attribs[index].buffer = slot;
    }

    /// Sets the element array buffer of vertex array `vao`, moving the reference.
    pub(crate) fn set_element_buffer(&mut self, vao: Option<Id>, buffer: Option<Id>) {
        let mut slot = self.vertex_array(vao).element_buffer;
        self.buffers.retarget(&mut slot, buffer);
        self.vertex_array_mut(vao).element_buffer = slot;
    }

    /// The last successful link of program `id` (deleted but in use included).
    pub(crate) fn linked(&self, id: Id) -> Option<&LinkedProgram> {
        self.programs.get_any(id).and_then(|p| p.linked.as_ref())
    }

    /// Mutable [`Objects::linked`].
    pub(crate) fn linked_mut(&mut self, id: Id) -> Option<&mut LinkedProgram> {
        self.programs
            .get_any_mut(id)
            .and_then(|p| p.linked.as_mut())
    }

    /// The transform feedback object `bound` names (the default one for `None`).
    pub(crate) fn feedback(&self, bound: Option<Id>) -> &TransformFeedbackObject {
        match bound.and_then(|id| self.transform_feedbacks.get_any(id)) {
            Some(t) => t,
            None => &self.default_transform_feedback,
        }
    }

    /// Whether `buffer` is at an indexed binding of a transform feedback object whose session
    /// is active (bound or not, paused or not).
    pub(crate) fn captures_into(&self, buffer: Id) -> bool {
        std::iter::once(&self.default_transform_feedback)
            .chain(self.transform_feedbacks.values())
            .filter(|tf| tf.session.is_some())
            .any(|tf| tf.buffers.iter().flatten().any(|r| r.buffer == buffer))
    }

    /// Mutable [`Objects::feedback`] (for the state that holds no reference).
    pub(crate) fn feedback_mut(&mut self, bound: Option<Id>) -> &mut TransformFeedbackObject {
        match bound {
            Some(id) if self.transform_feedbacks.get_any(id).is_some() => self
                .transform_feedbacks
                .get_any_mut(id)
                .expect("checked above"),
            _ => &mut self.default_transform_feedback,
        }
    }

    /// Sets indexed binding `index` of transform feedback object `tf`, moving the reference.
    pub(crate) fn set_feedback_buffer(
        &mut self,
        tf: Option<Id>,
        index: usize,
        range: Option<crate::buffer::BufferRange>,
    ) {
        let mut slot = self.feedback(tf).buffers[index].map(|r| r.buffer);
        self.buffers.retarget(&mut slot, range.map(|r| r.buffer));
        self.feedback_mut(tf).buffers[index] = range;
    }

    /// Deletes a transform feedback object (the caller has unbound it), dropping its
    /// buffers' references.
    pub(crate) fn delete_transform_feedback(&mut self, id: Id) {
        if let Some(freed) = self.transform_feedbacks.delete_freeing(id) {
            for r in freed.buffers.iter().flatten() {
                self.buffers.release(r.buffer);
            }
        }
    }

    /// Deletes a buffer: detached from the vertex array `bound_vao` and the transform
    /// feedback object `bound_tf` (GL detaches a deleted buffer only from the bound ones),
    /// freed when nothing else uses it.
    pub(crate) fn delete_buffer(&mut self, id: Id, bound_vao: Option<Id>, bound_tf: Option<Id>) {
        for i in 0..4 {
            if self.feedback(bound_tf).buffers[i].is_some_and(|r| r.buffer == id) {
                self.set_feedback_buffer(bound_tf, i, None);
            }
        }
        if self.vertex_array(bound_vao).element_buffer == Some(id) {
            self.set_element_buffer(bound_vao, None);
        }
        for i in 0..self.vertex_array(bound_vao).attribs.len() {
            if self.vertex_array(bound_vao).attribs[i].buffer == Some(id) {
                self.set_attrib_buffer(bound_vao, i, None);
            }
        }
        self.buffers.delete(id);
    }

    /// Deletes a vertex array (the caller has unbound it), dropping its buffers' references.
    pub(crate) fn delete_vertex_array(&mut self, id: Id) {
        if let Some(freed) = self.vertex_arrays.delete_freeing(id) {
            let held = freed.attribs.iter().filter_map(|a| a.buffer);
            for buffer in held.chain(freed.element_buffer) {
                self.buffers.release(buffer);
            }
        }
    }

    /// Deletes a texture (the caller has unbound it from the texture units): detached from
    /// the bound framebuffers `bound` (GL detaches it only from those), freed when no other
    /// framebuffer has it attached.
    pub(crate) fn delete_texture(&mut self, id: Id, bound: [Option<Id>; 2]) {
        self.detach_everywhere(
            bound,
            |a| matches!(a, Attachment::Texture { id: t, .. } if t == id),
        );
        self.textures.delete(id);
    }

    /// Deletes a renderbuffer (the caller has unbound it): detached from the bound
    /// framebuffers, freed when no other framebuffer has it attached.
    pub(crate) fn delete_renderbuffer(&mut self, id: Id, bound: [Option<Id>; 2]) {
        self.detach_everywhere(bound, |a| a == Attachment::Renderbuffer(id));
        self.renderbuffers.delete(id);
    }

    /// Detaches the images `matches` picks from the framebuffers `bound`.
    fn detach_everywhere(&mut self, bound: [Option<Id>; 2], matches: impl Fn(Attachment) -> bool) {
        for fb in bound.into_iter().flatten() {
            let Some(f) = self.framebuffers.get_any(fb) else {
                continue;
            };
            let points: Vec<u32> = f
                .attachments()
                .filter(|(_, a)| matches(*a))
                .map(|(p, _)| p)
                .collect();
            for p in points {
                self.attach(fb, p, None);
            }
        }
    }

    /// Attaches `image` (or nothing) at attachment point `point` of framebuffer `fb`
    /// (`DEPTH_STENCIL_ATTACHMENT` sets both depth and stencil, as WebGL2 has it), moving
    /// the references the attachments hold.
    pub(crate) fn attach(&mut self, fb: Id, point: u32, image: Option<Attachment>) {
        let points: &[u32] = if point == crate::gl::DEPTH_STENCIL_ATTACHMENT {
            &[crate::gl::DEPTH_ATTACHMENT, crate::gl::STENCIL_ATTACHMENT]
        } else {
            std::slice::from_ref(&point)
        };
        for &p in points {
            let Some(f) = self.framebuffers.get_any_mut(fb) else {
                return;
            };
            let slot = match p {
                crate::gl::DEPTH_ATTACHMENT => &mut f.depth,
                crate::gl::STENCIL_ATTACHMENT => &mut f.stencil,
                _ => match f
                    .colors
                    .get_mut((p - crate::gl::COLOR_ATTACHMENT0) as usize)
                {
                    Some(s) => s,
                    None => return,
                },
            };
            let old = std::mem::replace(slot, image);
            if let Some(new) = image {
                self.hold_image(new);
            }
            if let Some(old) = old {
                self.release_image(old);
            }
        }
    }

    fn hold_image(&mut self, a: Attachment) {
        match a {
            Attachment::Texture { id, .. } => self.textures.add_ref(id),
            Attachment::Renderbuffer(id) => self.renderbuffers.add_ref(id),
        }
    }

    fn release_image(&mut self, a: Attachment) {
        match a {
            Attachment::Texture { id, .. } => self.textures.release(id),
            Attachment::Renderbuffer(id) => self.renderbuffers.release(id),
        }
    }

    /// Deletes a query (the caller has ended it).
    pub(crate) fn delete_query(&mut self, id: Id) {
        self.queries.delete(id);
    }

    /// Deletes a sync object.
    pub(crate) fn delete_sync(&mut self, id: Id) {
        self.syncs.delete(id);
    }

    /// Deletes a sampler (the caller has unbound it).
    pub(crate) fn delete_sampler(&mut self, id: Id) {
        self.samplers.delete(id);
    }

    /// Deletes a framebuffer (the caller has unbound it), dropping its attachments'
    /// references.
    pub(crate) fn delete_framebuffer(&mut self, id: Id) {
        if let Some(freed) = self.framebuffers.delete_freeing(id) {
            for (_, a) in freed.attachments() {
                self.release_image(a);
            }
        }
    }

    /// Attaches shader `s` to program `p`, which keeps it alive.
    pub(crate) fn attach_shader(&mut self, p: Id, s: Id) {
        if let Some(program) = self.programs.get_any_mut(p) {
            program.attached.push(s);
            self.shaders.add_ref(s);
        }
    }

    /// Detaches shader `s` from program `p`; false when it was not attached.
    pub(crate) fn detach_shader(&mut self, p: Id, s: Id) -> bool {
        let Some(program) = self.programs.get_any_mut(p) else {
            return false;
        };
        let Some(i) = program.attached.iter().position(|&a| a == s) else {
            return false;
        };
        program.attached.remove(i);
        self.shaders.release(s);
        true
    }

    /// Deletes a shader: freed now, or when the last program it is attached to lets go.
    pub(crate) fn delete_shader(&mut self, id: Id) {
        self.shaders.delete(id);
    }

    /// Deletes a program: freed now unless it is in use ([`Objects::hold_program`]).
    pub(crate) fn delete_program(&mut self, id: Id) {
        if let Some(freed) = self.programs.delete_freeing(id) {
            self.free_program(freed);
        }
    }

    /// Counts a reference to program `id` (the context's program in use).
    pub(crate) fn hold_program(&mut self, id: Id) {
        self.programs.add_ref(id);
    }

    /// Drops a reference taken by [`Objects::hold_program`]; a program deleted meanwhile is
    /// freed, and its shaders with it when nothing else holds them.
    pub(crate) fn release_program(&mut self, id: Id) {
        if let Some(freed) = self.programs.release_freeing(id) {
            self.free_program(freed);
        }
    }

    /// Drops the references a freed program held on its shaders.
    fn free_program(&mut self, freed: ProgramObject) {
        for s in freed.attached {
            self.shaders.release(s);
        }
    }
}
