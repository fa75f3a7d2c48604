//! Texture parameters: `tex_parameteri`, `tex_parameterf`, `get_tex_parameter`.

use super::is_texture_target;
use crate::context::Context;
use crate::gl;
use crate::query::Parameter;
use crate::sampler::ParamError;

/// `WEBGL_stencil_texturing`'s texture parameter: which aspect of a depth-stencil texture is
/// sampled.
pub(crate) const DEPTH_STENCIL_TEXTURE_MODE: u32 = 0x90EA;
/// `WEBGL_stencil_texturing`'s value of [`DEPTH_STENCIL_TEXTURE_MODE`] for the stencil.
pub(crate) const STENCIL_INDEX: u32 = 0x1901;

impl Context {
    /// Sets an integer texture parameter of the texture bound to `target` (`texParameteri`):
    /// `TEXTURE_MIN_FILTER`, `TEXTURE_MAG_FILTER`, `TEXTURE_WRAP_S/T/R`,
    /// `TEXTURE_BASE_LEVEL`, `TEXTURE_MAX_LEVEL`, `TEXTURE_COMPARE_MODE`,
    /// `TEXTURE_COMPARE_FUNC`, `TEXTURE_MIN_LOD`, `TEXTURE_MAX_LOD`; with
    /// `WEBGL_stencil_texturing`, `DEPTH_STENCIL_TEXTURE_MODE_WEBGL` (`DEPTH_COMPONENT` or
    /// `STENCIL_INDEX_WEBGL`: a depth-stencil texture sampled for its stencil, through an
    /// unsigned integer sampler).
    pub fn tex_parameteri(&mut self, target: u32, pname: u32, param: i32) {
        if self.webgl1_refuses("texParameteri", &[target, pname]) {
            return;
        }
        self.tex_parameter(target, pname, param as f32, "texParameteri");
    }

    /// Sets a float texture parameter (`texParameterf`); see [`Context::tex_parameteri`].
    pub fn tex_parameterf(&mut self, target: u32, pname: u32, param: f32) {
        if self.webgl1_refuses("texParameterf", &[target, pname]) {
            return;
        }
        self.tex_parameter(target, pname, param, "texParameterf");
    }

    pub(super) fn tex_parameter(&mut self, target: u32, pname: u32, value: f32, function: &str) {
        if !is_texture_target(target) {
            return self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("target 0x{target:04X}"),
            );
        }
        let Some(id) = self.bound_texture(target, function) else {
            return;
        };
        let gated = self.anisotropy_refused(pname);
        let stencil_texturing = self.extensions.stencil_texturing;
        let p = &mut self
            .objects
            .textures
            .get_mut(id)
            .expect("bound textures are live")
            .params;
        let result = match pname {
            gl::TEXTURE_BASE_LEVEL | gl::TEXTURE_MAX_LEVEL if value < 0.0 => {
                return self.error(gl::INVALID_VALUE, function, "negative level");
            }
            gl::TEXTURE_BASE_LEVEL => {
                p.base_level = value as u32;
                Ok(())
            }
            gl::TEXTURE_MAX_LEVEL => {
                p.max_level = value as u32;
                Ok(())
            }
            DEPTH_STENCIL_TEXTURE_MODE if stencil_texturing => match value as u32 {
                gl::DEPTH_COMPONENT => {
                    p.stencil_mode = false;
                    Ok(())
                }
                STENCIL_INDEX => {
                    p.stencil_mode = true;
                    Ok(())
                }
                _ => Err(ParamError::Value),
            },
            _ if gated => Err(ParamError::Pname),
            _ => p.sampling.set(pname, value),
        };
        match result {
            Ok(()) => {}
            Err(ParamError::Pname) => self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("pname 0x{pname:04X}"),
            ),
            Err(ParamError::Value) => self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("value {value} for pname 0x{pname:04X}"),
            ),
            Err(ParamError::Range) => self.error(
                gl::INVALID_VALUE,
                function,
                format_args!("value {value} for pname 0x{pname:04X}"),
            ),
        }
    }

    /// A parameter of the texture bound to `target` (`getTexParameter`): the sampling
    /// parameters, `TEXTURE_BASE_LEVEL`, `TEXTURE_MAX_LEVEL`, `TEXTURE_IMMUTABLE_FORMAT`,
    /// `TEXTURE_IMMUTABLE_LEVELS`. No texture bound → `INVALID_OPERATION`; another `pname` →
    /// `INVALID_ENUM`.
    pub fn get_tex_parameter(&self, target: u32, pname: u32) -> Option<Parameter> {
        const F: &str = "getTexParameter";
        if self.webgl1_refuses("getTexParameter", &[target, pname]) {
            return None;
        }
        if !is_texture_target(target) {
            self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
            return None;
        }
        let id = self.bound_texture(target, F)?;
        let t = self.objects.textures.get(id)?;
        let p = &t.params;
        let value = match pname {
            gl::TEXTURE_BASE_LEVEL => Some(Parameter::Int(p.base_level as i64)),
            gl::TEXTURE_MAX_LEVEL => Some(Parameter::Int(p.max_level as i64)),
            gl::TEXTURE_IMMUTABLE_FORMAT => Some(Parameter::Bool(t.immutable_levels.is_some())),
            DEPTH_STENCIL_TEXTURE_MODE if self.extensions.stencil_texturing => {
                Some(Parameter::Enum(if p.stencil_mode {
                    STENCIL_INDEX
                } else {
                    gl::DEPTH_COMPONENT
                }))
            }
            gl::TEXTURE_IMMUTABLE_LEVELS => {
                Some(Parameter::Int(t.immutable_levels.unwrap_or(0) as i64))
            }
            _ if self.anisotropy_refused(pname) => None,
            _ => p.sampling.get(pname),
        };
        if value.is_none() {
            self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
        }
        value
    }
}
