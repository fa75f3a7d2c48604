//! Program objects: creation, attaching and detaching shaders, deletion (a program in use
//! lives until it is replaced), link status and attribute bindings.

use super::ProgramObject;
use crate::context::Context;
use crate::gl;
use crate::objects::{Id, Program, Shader};

impl Context {
    /// Creates a program object (`createProgram`).
    pub fn create_program(&mut self) -> Program {
        Program {
            ctx: self.id,
            id: self.objects.programs.insert(ProgramObject::default()),
        }
    }

    pub(crate) fn program_id(&self, program: Program, function: &str) -> Option<Id> {
        if !self.owns(program.ctx, function) {
            return None;
        }
        // As for shaders: a program marked for deletion but still current stays usable; one
        // that is gone → INVALID_VALUE.
        if self.objects.programs.get_any(program.id).is_none() {
            self.error(
                gl::INVALID_VALUE,
                function,
                "attempt to use a deleted program",
            );
            return None;
        }
        Some(program.id)
    }

    /// Whether `program` names a live program (`isProgram`).
    pub fn is_program(&self, program: Program) -> bool {
        // A program deleted while in use lives on until replaced, and is one till then.
        program.ctx == self.id && self.objects.programs.get_any(program.id).is_some()
    }

    /// Attaches a shader (`attachShader`); a second shader of the same type, or the same
    /// shader twice → `INVALID_OPERATION`.
    pub fn attach_shader(&mut self, program: Program, shader: Shader) {
        const F: &str = "attachShader";
        let (Some(p), Some(s)) = (self.program_id(program, F), self.shader_id(shader, F)) else {
            return;
        };
        let ty = self.objects.shaders.get_any(s).expect("live").ty;
        let attached = &self.objects.programs.get_any(p).expect("live").attached;
        let clash = attached
            .iter()
            .any(|&a| a == s || self.objects.shaders.get_any(a).is_some_and(|o| o.ty == ty));
        if clash {
            return self.error(
                gl::INVALID_OPERATION,
                F,
                "a shader of that type is already attached",
            );
        }
        self.objects.attach_shader(p, s);
    }

    /// Detaches a shader (`detachShader`); one not attached → `INVALID_OPERATION`.
    pub fn detach_shader(&mut self, program: Program, shader: Shader) {
        const F: &str = "detachShader";
        let (Some(p), Some(s)) = (self.program_id(program, F), self.shader_id(shader, F)) else {
            return;
        };
        if !self.objects.detach_shader(p, s) {
            self.error(gl::INVALID_OPERATION, F, "shader not attached");
        }
    }

    /// The shaders attached to a program (`getAttachedShaders`).
    pub fn get_attached_shaders(&self, program: Program) -> Vec<Shader> {
        let Some(p) = self.program_id(program, "getAttachedShaders") else {
            return Vec::new();
        };
        let ctx = self.id;
        self.objects
            .programs
            .get(p)
            .expect("live")
            .attached
            .iter()
            .map(|&id| Shader { ctx, id })
            .collect()
    }

    /// Deletes a program (`deleteProgram`). The current program is only marked for deletion
    /// (`DELETE_STATUS` true): it stays usable, with its shaders attached, until another
    /// program is made current, as in GL.
    pub fn delete_program(&mut self, program: Program) {
        if !self.owns(program.ctx, "deleteProgram") || !self.objects.programs.is_live(program.id) {
            return;
        }
        self.objects.delete_program(program.id);
    }

    /// Whether the last link succeeded (`getProgramParameter(LINK_STATUS)`).
    pub fn get_program_link_status(&self, program: Program) -> bool {
        self.program_id(program, "getProgramParameter")
            .and_then(|p| self.objects.programs.get_any(p))
            .is_some_and(|p| p.link_status)
    }

    /// The log of the last link (`getProgramInfoLog`).
    pub fn get_program_info_log(&self, program: Program) -> Option<String> {
        let p = self.program_id(program, "getProgramInfoLog")?;
        self.objects.programs.get_any(p).map(|p| p.info_log.clone())
    }

    /// Binds an attribute name to a location for the next link (`bindAttribLocation`).
    /// An index ≥ `MAX_VERTEX_ATTRIBS` → `INVALID_VALUE`; a reserved `gl_`/`webgl_` name →
    /// `INVALID_OPERATION`.
    pub fn bind_attrib_location(&mut self, program: Program, index: u32, name: &str) {
        const F: &str = "bindAttribLocation";
        if !self.valid_name(name, true, F) {
            return;
        }
        let Some(p) = self.program_id(program, F) else {
            return;
        };
        if index >= self.limits.max_vertex_attribs {
            return self.error(gl::INVALID_VALUE, F, "index ≥ MAX_VERTEX_ATTRIBS");
        }
        if name.starts_with("gl_") || name.starts_with("webgl_") || name.starts_with("_webgl_") {
            return self.error(gl::INVALID_OPERATION, F, "reserved name");
        }
        let bindings = &mut self
            .objects
            .programs
            .get_any_mut(p)
            .expect("live")
            .attrib_bindings;
        bindings.retain(|(n, _)| n != name);
        bindings.push((name.to_owned(), index));
    }
}
