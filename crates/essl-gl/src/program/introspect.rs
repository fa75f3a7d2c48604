//! What a linked program offers: uniform and attribute locations, uniform blocks and their
//! binding points, active attributes and uniforms.

use super::interface::find_uniform;
use super::ActiveInfo;
use crate::context::Context;
use crate::gl;
use crate::objects::{Program, UniformLocation};

impl Context {
    /// The location of an active uniform or of an element of an active uniform array
    /// (`getUniformLocation`): `"u_color"`, `"u_lights[2].position"`, `"u_weights[3]"`.
    /// `None` for a name that is not active; an unlinked program → `INVALID_OPERATION`.
    pub fn get_uniform_location(&self, program: Program, name: &str) -> Option<UniformLocation> {
        let ctx = self.id;
        let linked = self.linked_program(program, "getUniformLocation")?;
        if name.starts_with("gl_") || name.starts_with("webgl_") || name.starts_with("_webgl_") {
            return None;
        }
        let (i, element) = find_uniform(&linked.layout, name)?;
        Some(UniformLocation {
            ctx,
            program: program.id,
            link: linked.serial,
            uniform: i as u32,
            element,
        })
    }

    /// The index of a uniform block by name, or `INVALID_INDEX` (`getUniformBlockIndex`).
    pub fn get_uniform_block_index(&self, program: Program, name: &str) -> u32 {
        let Some(linked) = self.linked_program(program, "getUniformBlockIndex") else {
            return gl::INVALID_INDEX;
        };
        linked
            .layout
            .blocks
            .iter()
            .position(|b| b.name == name)
            .map_or(gl::INVALID_INDEX, |i| i as u32)
    }

    /// Makes uniform block `block_index` read `UNIFORM_BUFFER` binding point `binding`
    /// (`uniformBlockBinding`). An index or binding out of range → `INVALID_VALUE`.
    pub fn uniform_block_binding(&mut self, program: Program, block_index: u32, binding: u32) {
        const F: &str = "uniformBlockBinding";
        let Some(linked) = self.linked_program_mut(program, F) else {
            return;
        };
        match linked.block_bindings.get_mut(block_index as usize) {
            Some(b) if binding < crate::context::MAX_UNIFORM_BUFFER_BINDINGS => *b = binding,
            _ => self.error(gl::INVALID_VALUE, F, "block index or binding out of range"),
        }
    }

    /// The index-th active attribute's name, type and size (`getActiveAttrib`); an index
    /// out of range → `INVALID_VALUE`.
    pub fn get_active_attrib(&self, program: Program, index: u32) -> Option<ActiveInfo> {
        let id = self.program_id(program, "getActiveAttrib")?;
        let linked = self.objects.linked(id)?;
        match linked.layout.attributes.get(index as usize) {
            Some(a) => Some(ActiveInfo {
                name: a.name.clone(),
                size: a.size,
                ty: a.ty as u32,
            }),
            None => {
                self.error(gl::INVALID_VALUE, "getActiveAttrib", "index out of range");
                None
            }
        }
    }

    /// The index-th active uniform's name, type and size (`getActiveUniform`); an index
    /// out of range → `INVALID_VALUE`.
    pub fn get_active_uniform(&self, program: Program, index: u32) -> Option<ActiveInfo> {
        let id = self.program_id(program, "getActiveUniform")?;
        let linked = self.objects.linked(id)?;
        match linked.layout.uniforms.get(index as usize) {
            Some(u) => Some(ActiveInfo {
                name: u.name.clone(),
                size: u.size,
                ty: u.ty as u32,
            }),
            None => {
                self.error(gl::INVALID_VALUE, "getActiveUniform", "index out of range");
                None
            }
        }
    }

    /// The location of an active attribute, or −1 (`getAttribLocation`). Built-in inputs
    /// (`gl_VertexID`, `gl_InstanceID`), which `get_active_attrib` lists, and every reserved
    /// `gl_`/`webgl_` name have none: −1, as in WebGL.
    pub fn get_attrib_location(&self, program: Program, name: &str) -> i32 {
        const F: &str = "getAttribLocation";
        if self.program_id(program, F).is_none() {
            return -1;
        }
        if name.starts_with("gl_") || name.starts_with("webgl_") || name.starts_with("_webgl_") {
            return -1;
        }
        let Some(linked) = self.linked_program(program, F) else {
            return -1;
        };
        linked
            .layout
            .attributes
            .iter()
            .find(|a| a.name == name)
            .map_or(-1, |a| a.location as i32)
    }
}
