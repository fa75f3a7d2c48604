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
        if !self.valid_name(name, true, "getUniformLocation") {
            return None;
        }
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
        if !self.valid_name(name, false, "getUniformBlockIndex") {
            return gl::INVALID_INDEX;
        }
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
        if !self.valid_name(name, true, F) || self.program_id(program, F).is_none() {
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

    /// WebGL's checks of a name a program is asked about: characters outside GLSL ES's
    /// character set (`"`, `$`, `'`, `@`, `\`, `` ` ``, controls other than whitespace,
    /// non-ASCII) and, where `length` applies, more than 256 characters (WebGL 1) or 1024
    /// (WebGL 2) → `INVALID_VALUE`.
    pub(crate) fn valid_name(&self, name: &str, length: bool, function: &str) -> bool {
        let max = if self.linker.shaders.target == essl::Target::WebGl1 {
            256
        } else {
            1024
        };
        if length && name.len() > max {
            self.error(
                gl::INVALID_VALUE,
                function,
                format_args!("name longer than {max} characters"),
            );
            return false;
        }
        let bad = |c: char| {
            !(c.is_ascii_graphic() || matches!(c, ' ' | '\t' | '\n' | '\x0B' | '\x0C' | '\r'))
                || matches!(c, '"' | '$' | '\'' | '@' | '\\' | '`')
        };
        if name.chars().any(bad) {
            self.error(
                gl::INVALID_VALUE,
                function,
                "name has a character outside GLSL ES's character set",
            );
            return false;
        }
        true
    }
}
