//! Shaders and programs: compiling, linking, attributes, uniform and block queries.

use essl_gl::{Program, Shader, UniformLocation};
use napi_derive::napi;

use crate::answer::Answer;
use crate::context::NativeContext;
use crate::registry::Handle;

#[napi]
impl NativeContext {
    /// `createShader`: the id, or 0 (`null`) for a bad type.
    #[napi(catch_unwind)]
    pub fn create_shader(&mut self, ty: u32) -> napi::Result<u32> {
        Ok(match self.gl()?.create_shader(ty) {
            Some(s) => self.register(Handle::Shader(s)),
            None => 0,
        })
    }

    /// `isShader`.
    #[napi(catch_unwind)]
    pub fn is_shader(&mut self, shader: u32) -> napi::Result<bool> {
        let s = self.arg::<Shader>(shader, "isShader").flatten();
        Ok(s.is_some_and(|s| self.ctx.as_ref().is_some_and(|c| c.is_shader(s))))
    }

    /// `deleteShader`.
    #[napi(catch_unwind)]
    pub fn delete_shader(&mut self, shader: u32) -> napi::Result<()> {
        if let Some(s) = self.arg::<Shader>(shader, "deleteShader").flatten() {
            self.gl()?.delete_shader(s);
        }
        Ok(())
    }

    /// `shaderSource`.
    #[napi(catch_unwind)]
    pub fn shader_source(&mut self, shader: u32, source: String) -> napi::Result<()> {
        if let Some(s) = self.req(shader, "shaderSource") {
            self.gl()?.shader_source(s, &source);
        }
        Ok(())
    }

    /// `getShaderSource`.
    #[napi(catch_unwind)]
    pub fn get_shader_source(&mut self, shader: u32) -> napi::Result<Answer> {
        let Some(s) = self.req(shader, "getShaderSource") else {
            return Ok(Answer::Null);
        };
        Ok(Answer::string(self.gl()?.get_shader_source(s)))
    }

    /// `WEBGL_debug_shaders.getTranslatedShaderSource`.
    #[napi(catch_unwind)]
    pub fn get_translated_shader_source(&mut self, shader: u32) -> napi::Result<Answer> {
        let Some(s) = self.req(shader, "getTranslatedShaderSource") else {
            return Ok(Answer::Null);
        };
        Ok(Answer::string(self.gl()?.get_translated_shader_source(s)))
    }

    /// `compileShader`.
    #[napi(catch_unwind)]
    pub fn compile_shader(&mut self, shader: u32) -> napi::Result<()> {
        if let Some(s) = self.req(shader, "compileShader") {
            self.gl()?.compile_shader(s);
        }
        Ok(())
    }

    /// `getShaderParameter`.
    #[napi(catch_unwind)]
    pub fn get_shader_parameter(&mut self, shader: u32, pname: u32) -> napi::Result<Answer> {
        let Some(s) = self.req(shader, "getShaderParameter") else {
            return Ok(Answer::Null);
        };
        Ok(self.gl()?.get_shader_parameter(s, pname).into())
    }

    /// `getShaderInfoLog`.
    #[napi(catch_unwind)]
    pub fn get_shader_info_log(&mut self, shader: u32) -> napi::Result<Answer> {
        let Some(s) = self.req(shader, "getShaderInfoLog") else {
            return Ok(Answer::Null);
        };
        Ok(Answer::string(self.gl()?.get_shader_info_log(s)))
    }

    /// `getShaderPrecisionFormat`.
    #[napi(catch_unwind)]
    pub fn get_shader_precision_format(
        &mut self,
        shader: u32,
        precision: u32,
    ) -> napi::Result<Answer> {
        let p = self.gl()?.get_shader_precision_format(shader, precision);
        Ok(p.map_or(Answer::Null, Answer::Precision))
    }

    /// `createProgram`.
    #[napi(catch_unwind)]
    pub fn create_program(&mut self) -> napi::Result<u32> {
        let p = self.gl()?.create_program();
        Ok(self.register(Handle::Program(p)))
    }

    /// `isProgram`.
    #[napi(catch_unwind)]
    pub fn is_program(&mut self, program: u32) -> napi::Result<bool> {
        let p = self.arg::<Program>(program, "isProgram").flatten();
        Ok(p.is_some_and(|p| self.ctx.as_ref().is_some_and(|c| c.is_program(p))))
    }

    /// `deleteProgram`.
    #[napi(catch_unwind)]
    pub fn delete_program(&mut self, program: u32) -> napi::Result<()> {
        if let Some(p) = self.arg::<Program>(program, "deleteProgram").flatten() {
            self.gl()?.delete_program(p);
        }
        Ok(())
    }

    /// `attachShader`.
    #[napi(catch_unwind)]
    pub fn attach_shader(&mut self, program: u32, shader: u32) -> napi::Result<()> {
        let p = self.req(program, "attachShader");
        let s = self.req(shader, "attachShader");
        if let (Some(p), Some(s)) = (p, s) {
            self.gl()?.attach_shader(p, s);
        }
        Ok(())
    }

    /// `detachShader`.
    #[napi(catch_unwind)]
    pub fn detach_shader(&mut self, program: u32, shader: u32) -> napi::Result<()> {
        let p = self.req(program, "detachShader");
        let s = self.req(shader, "detachShader");
        if let (Some(p), Some(s)) = (p, s) {
            self.gl()?.detach_shader(p, s);
        }
        Ok(())
    }

    /// `getAttachedShaders`: ids, or `null` for an invalid program.
    #[napi(catch_unwind)]
    pub fn get_attached_shaders(&mut self, program: u32) -> napi::Result<Answer> {
        let Some(p) = self.req::<Program>(program, "getAttachedShaders") else {
            return Ok(Answer::Null);
        };
        let c = self.gl()?;
        if !c.is_program(p) {
            // What WebGL answers for a deleted program, after getAttachedShaders' own error.
            let _ = c.get_attached_shaders(p);
            return Ok(Answer::Null);
        }
        let shaders = c.get_attached_shaders(p);
        let ids = shaders
            .into_iter()
            .map(|s| crate::registry::id_of(Handle::Shader(s)))
            .collect();
        Ok(Answer::Objects(ids))
    }

    /// `bindAttribLocation`.
    #[napi(catch_unwind)]
    pub fn bind_attrib_location(
        &mut self,
        program: u32,
        index: u32,
        name: String,
    ) -> napi::Result<()> {
        if let Some(p) = self.req(program, "bindAttribLocation") {
            self.gl()?.bind_attrib_location(p, index, &name);
        }
        Ok(())
    }

    /// `linkProgram`.
    #[napi(catch_unwind)]
    pub fn link_program(&mut self, program: u32) -> napi::Result<()> {
        if let Some(p) = self.req(program, "linkProgram") {
            self.gl()?.link_program(p);
        }
        Ok(())
    }

    /// `validateProgram`.
    #[napi(catch_unwind)]
    pub fn validate_program(&mut self, program: u32) -> napi::Result<()> {
        if let Some(p) = self.req(program, "validateProgram") {
            self.gl()?.validate_program(p);
        }
        Ok(())
    }

    /// `useProgram`.
    #[napi(catch_unwind)]
    pub fn use_program(&mut self, program: u32) -> napi::Result<()> {
        if let Some(p) = self.arg(program, "useProgram") {
            self.gl()?.use_program(p);
        }
        Ok(())
    }

    /// `getProgramParameter`.
    #[napi(catch_unwind)]
    pub fn get_program_parameter(&mut self, program: u32, pname: u32) -> napi::Result<Answer> {
        let Some(p) = self.req(program, "getProgramParameter") else {
            return Ok(Answer::Null);
        };
        Ok(self.gl()?.get_program_parameter(p, pname).into())
    }

    /// `getProgramInfoLog`.
    #[napi(catch_unwind)]
    pub fn get_program_info_log(&mut self, program: u32) -> napi::Result<Answer> {
        let Some(p) = self.req(program, "getProgramInfoLog") else {
            return Ok(Answer::Null);
        };
        Ok(Answer::string(self.gl()?.get_program_info_log(p)))
    }

    /// `getAttribLocation`.
    #[napi(catch_unwind)]
    pub fn get_attrib_location(&mut self, program: u32, name: String) -> napi::Result<i32> {
        let Some(p) = self.req(program, "getAttribLocation") else {
            return Ok(-1);
        };
        Ok(self.gl()?.get_attrib_location(p, &name))
    }

    /// `getFragDataLocation`.
    #[napi(catch_unwind)]
    pub fn get_frag_data_location(&mut self, program: u32, name: String) -> napi::Result<i32> {
        let Some(p) = self.req(program, "getFragDataLocation") else {
            return Ok(-1);
        };
        Ok(self.gl()?.get_frag_data_location(p, &name))
    }

    /// `getActiveAttrib`.
    #[napi(catch_unwind)]
    pub fn get_active_attrib(&mut self, program: u32, index: u32) -> napi::Result<Answer> {
        let Some(p) = self.req(program, "getActiveAttrib") else {
            return Ok(Answer::Null);
        };
        let info = self.gl()?.get_active_attrib(p, index);
        Ok(info.map_or(Answer::Null, Answer::ActiveInfo))
    }

    /// `getActiveUniform`.
    #[napi(catch_unwind)]
    pub fn get_active_uniform(&mut self, program: u32, index: u32) -> napi::Result<Answer> {
        let Some(p) = self.req(program, "getActiveUniform") else {
            return Ok(Answer::Null);
        };
        let info = self.gl()?.get_active_uniform(p, index);
        Ok(info.map_or(Answer::Null, Answer::ActiveInfo))
    }

    /// `getUniformLocation`: the location's id, or 0 (`null`).
    #[napi(catch_unwind)]
    pub fn get_uniform_location(&mut self, program: u32, name: String) -> napi::Result<u32> {
        let Some(p) = self.req(program, "getUniformLocation") else {
            return Ok(0);
        };
        Ok(match self.gl()?.get_uniform_location(p, &name) {
            Some(l) => self.register(Handle::UniformLocation(l)),
            None => 0,
        })
    }

    /// `getUniform`.
    #[napi(catch_unwind)]
    pub fn get_uniform(&mut self, program: u32, location: u32) -> napi::Result<Answer> {
        let p = self.req::<Program>(program, "getUniform");
        let l = self.req::<UniformLocation>(location, "getUniform");
        let (Some(p), Some(l)) = (p, l) else {
            return Ok(Answer::Null);
        };
        Ok(self.gl()?.get_uniform(p, l).into())
    }

    /// `getUniformIndices`.
    #[napi(catch_unwind)]
    pub fn get_uniform_indices(
        &mut self,
        program: u32,
        names: Vec<String>,
    ) -> napi::Result<Answer> {
        let Some(p) = self.req(program, "getUniformIndices") else {
            return Ok(Answer::Null);
        };
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        Ok(match self.gl()?.get_uniform_indices(p, &names) {
            Some(v) => Answer::Numbers(v.into_iter().map(f64::from).collect()),
            None => Answer::Null,
        })
    }

    /// `getActiveUniforms`.
    #[napi(catch_unwind)]
    pub fn get_active_uniforms(
        &mut self,
        program: u32,
        indices: &[u32],
        pname: u32,
    ) -> napi::Result<Answer> {
        let Some(p) = self.req(program, "getActiveUniforms") else {
            return Ok(Answer::Null);
        };
        let answer = self.gl()?.get_active_uniforms(p, indices, pname);
        // `sequence<any>`: an array of numbers or booleans rather than a typed array.
        Ok(match answer {
            Some(essl_gl::Parameter::Ints(v)) => {
                Answer::Numbers(v.into_iter().map(f64::from).collect())
            }
            Some(essl_gl::Parameter::Uints(v)) => {
                Answer::Numbers(v.into_iter().map(f64::from).collect())
            }
            other => other.into(),
        })
    }

    /// `getUniformBlockIndex`.
    #[napi(catch_unwind)]
    pub fn get_uniform_block_index(&mut self, program: u32, name: String) -> napi::Result<u32> {
        let Some(p) = self.req(program, "getUniformBlockIndex") else {
            return Ok(u32::MAX);
        };
        Ok(self.gl()?.get_uniform_block_index(p, &name))
    }

    /// `getActiveUniformBlockParameter`.
    #[napi(catch_unwind)]
    pub fn get_active_uniform_block_parameter(
        &mut self,
        program: u32,
        index: u32,
        pname: u32,
    ) -> napi::Result<Answer> {
        let Some(p) = self.req(program, "getActiveUniformBlockParameter") else {
            return Ok(Answer::Null);
        };
        Ok(self
            .gl()?
            .get_active_uniform_block_parameter(p, index, pname)
            .into())
    }

    /// `getActiveUniformBlockName`.
    #[napi(catch_unwind)]
    pub fn get_active_uniform_block_name(
        &mut self,
        program: u32,
        index: u32,
    ) -> napi::Result<Answer> {
        let Some(p) = self.req(program, "getActiveUniformBlockName") else {
            return Ok(Answer::Null);
        };
        Ok(Answer::string(
            self.gl()?.get_active_uniform_block_name(p, index),
        ))
    }

    /// `uniformBlockBinding`.
    #[napi(catch_unwind)]
    pub fn uniform_block_binding(
        &mut self,
        program: u32,
        index: u32,
        binding: u32,
    ) -> napi::Result<()> {
        if let Some(p) = self.req(program, "uniformBlockBinding") {
            self.gl()?.uniform_block_binding(p, index, binding);
        }
        Ok(())
    }
}
