//! Shader and program queries: `get_shader_parameter`, `get_program_parameter`, and
//! `validate_program`, which stores its answer for `VALIDATE_STATUS`.

use super::Parameter;
use crate::context::Context;
use crate::gl;
use crate::objects::{Program, Shader};

impl Context {
    /// A shader's parameter (`getShaderParameter`): `SHADER_TYPE` ([`Parameter::Enum`]),
    /// `COMPILE_STATUS` and `DELETE_STATUS` ([`Parameter::Bool`]).
    ///
    /// Another `pname` → `INVALID_ENUM` (WebGL dropped GL's `INFO_LOG_LENGTH` and
    /// `SHADER_SOURCE_LENGTH`); a shader that no longer exists → `INVALID_VALUE`; one of another
    /// context → `INVALID_OPERATION`; all return `None`. A shader marked for deletion but
    /// still attached to a program can be queried (`DELETE_STATUS` is then true).
    pub fn get_shader_parameter(&self, shader: Shader, pname: u32) -> Option<Parameter> {
        const F: &str = "getShaderParameter";
        if self.webgl1_refuses("getShaderParameter", &[pname]) {
            return None;
        }
        let id = self.shader_id(shader, F)?;
        let s = self.objects.shaders.get_any(id)?;
        match pname {
            gl::SHADER_TYPE => Some(Parameter::Enum(s.ty)),
            gl::COMPILE_STATUS => Some(Parameter::Bool(
                s.compiled.as_ref().is_some_and(|(_, ok)| *ok),
            )),
            gl::DELETE_STATUS => Some(Parameter::Bool(self.objects.shaders.is_marked_deleted(id))),
            _ => {
                self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
                None
            }
        }
    }

    /// A program's parameter (`getProgramParameter`): `LINK_STATUS`, `DELETE_STATUS`,
    /// `VALIDATE_STATUS` ([`Parameter::Bool`]); `ATTACHED_SHADERS`, `ACTIVE_UNIFORMS`,
    /// `ACTIVE_ATTRIBUTES`, `ACTIVE_UNIFORM_BLOCKS`, `TRANSFORM_FEEDBACK_VARYINGS`
    /// ([`Parameter::Int`]; the active counts are 0 unless the last link succeeded);
    /// `TRANSFORM_FEEDBACK_BUFFER_MODE` ([`Parameter::Enum`]).
    ///
    /// Another `pname` → `INVALID_ENUM`; a program that no longer exists → `INVALID_VALUE`;
    /// one of another context → `INVALID_OPERATION`; all return `None`. A deleted program
    /// that is still current can be queried (`DELETE_STATUS` is then true).
    pub fn get_program_parameter(&self, program: Program, pname: u32) -> Option<Parameter> {
        const F: &str = "getProgramParameter";
        if self.webgl1_refuses("getProgramParameter", &[pname]) {
            return None;
        }
        let id = self.program_id(program, F)?;
        let p = self.objects.programs.get_any(id)?;
        let active = |n: fn(&essl::program::ProgramLayout) -> usize| {
            Parameter::Int(p.linked.as_ref().map_or(0, |l| n(&l.layout)) as i64)
        };
        match pname {
            gl::LINK_STATUS => Some(Parameter::Bool(p.link_status)),
            gl::DELETE_STATUS => Some(Parameter::Bool(self.objects.programs.is_marked_deleted(id))),
            gl::VALIDATE_STATUS => Some(Parameter::Bool(p.validate_status)),
            gl::ATTACHED_SHADERS => Some(Parameter::Int(p.attached.len() as i64)),
            gl::ACTIVE_UNIFORMS => Some(active(|l| l.uniforms.len())),
            gl::ACTIVE_ATTRIBUTES => Some(active(|l| l.attributes.len())),
            gl::ACTIVE_UNIFORM_BLOCKS => Some(active(|l| l.blocks.len())),
            gl::TRANSFORM_FEEDBACK_VARYINGS => Some(Parameter::Int(
                p.linked
                    .as_ref()
                    .and_then(|l| l.feedback.as_ref())
                    .map_or(0, |f| f.varyings.len()) as i64,
            )),
            gl::TRANSFORM_FEEDBACK_BUFFER_MODE => Some(Parameter::Enum(
                p.linked
                    .as_ref()
                    .and_then(|l| l.feedback.as_ref())
                    .map_or(p.feedback_varyings.1, |f| f.mode),
            )),
            _ => {
                self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
                None
            }
        }
    }

    /// Checks whether the program could draw with the current state (`validateProgram`) and
    /// stores the answer as `VALIDATE_STATUS`, with the reason in the info log (which it
    /// replaces, as ANGLE does). A program fails when its last link failed or when samplers
    /// of different types read the same texture unit.
    pub fn validate_program(&mut self, program: Program) {
        let Some(id) = self.program_id(program, "validateProgram") else {
            return;
        };
        let p = self.objects.programs.get_any_mut(id).expect("checked");
        let problem = match &p.linked {
            Some(linked) if p.link_status => sampler_conflict(linked),
            _ => Some("Program has not been successfully linked.".to_owned()),
        };
        p.validate_status = problem.is_none();
        p.info_log = problem.unwrap_or_default();
    }
}

/// Why a linked program cannot draw with its sampler units, if it cannot: samplers of
/// different types on one texture unit.
fn sampler_conflict(linked: &crate::program::LinkedProgram) -> Option<String> {
    let samplers = &linked.layout.samplers;
    for (i, a) in samplers.iter().enumerate() {
        for (j, b) in samplers.iter().enumerate().skip(i + 1) {
            let (ua, ub) = (linked.sampler_units[i], linked.sampler_units[j]);
            if ua == ub && a.ty != b.ty {
                return Some(format!(
                    "Samplers of conflicting types refer to the same texture image unit ({ua})."
                ));
            }
        }
    }
    None
}
