//! Texture parameters: `tex_parameteri`, `tex_parameterf`.

use super::is_texture_target;
use crate::context::Context;
use crate::gl;
use crate::state::is_compare_func;

impl Context {
    /// Sets an integer texture parameter of the texture bound to `target` (`texParameteri`):
    /// `TEXTURE_MIN_FILTER`, `TEXTURE_MAG_FILTER`, `TEXTURE_WRAP_S/T/R`,
    /// `TEXTURE_BASE_LEVEL`, `TEXTURE_MAX_LEVEL`, `TEXTURE_COMPARE_MODE`,
    /// `TEXTURE_COMPARE_FUNC`, `TEXTURE_MIN_LOD`, `TEXTURE_MAX_LOD`.
    pub fn tex_parameteri(&mut self, target: u32, pname: u32, param: i32) {
        self.tex_parameter(target, pname, param as f32, "texParameteri");
    }

    /// Sets a float texture parameter (`texParameterf`); see [`Context::tex_parameteri`].
    pub fn tex_parameterf(&mut self, target: u32, pname: u32, param: f32) {
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
        let e = value as i64 as u32;
        let ok_enum = match pname {
            gl::TEXTURE_MIN_FILTER => matches!(
                e,
                gl::NEAREST
                    | gl::LINEAR
                    | gl::NEAREST_MIPMAP_NEAREST
                    | gl::LINEAR_MIPMAP_NEAREST
                    | gl::NEAREST_MIPMAP_LINEAR
                    | gl::LINEAR_MIPMAP_LINEAR
            ),
            gl::TEXTURE_MAG_FILTER => matches!(e, gl::NEAREST | gl::LINEAR),
            gl::TEXTURE_WRAP_S | gl::TEXTURE_WRAP_T | gl::TEXTURE_WRAP_R => {
                matches!(e, gl::REPEAT | gl::CLAMP_TO_EDGE | gl::MIRRORED_REPEAT)
            }
            gl::TEXTURE_COMPARE_MODE => matches!(e, gl::NONE | gl::COMPARE_REF_TO_TEXTURE),
            gl::TEXTURE_COMPARE_FUNC => is_compare_func(e),
            gl::TEXTURE_BASE_LEVEL | gl::TEXTURE_MAX_LEVEL => {
                if value < 0.0 {
                    return self.error(gl::INVALID_VALUE, function, "negative level");
                }
                true
            }
            gl::TEXTURE_MIN_LOD | gl::TEXTURE_MAX_LOD => true,
            _ => {
                return self.error(
                    gl::INVALID_ENUM,
                    function,
                    format_args!("pname 0x{pname:04X}"),
                )
            }
        };
        if !ok_enum {
            return self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("value {value} for pname 0x{pname:04X}"),
            );
        }
        let p = &mut self
            .objects
            .textures
            .get_mut(id)
            .expect("bound textures are live")
            .params;
        match pname {
            gl::TEXTURE_MIN_FILTER => p.min_filter = e,
            gl::TEXTURE_MAG_FILTER => p.mag_filter = e,
            gl::TEXTURE_WRAP_S => p.wrap_s = e,
            gl::TEXTURE_WRAP_T => p.wrap_t = e,
            gl::TEXTURE_WRAP_R => p.wrap_r = e,
            gl::TEXTURE_COMPARE_MODE => p.compare_mode = e,
            gl::TEXTURE_COMPARE_FUNC => p.compare_func = e,
            gl::TEXTURE_BASE_LEVEL => p.base_level = value as u32,
            gl::TEXTURE_MAX_LEVEL => p.max_level = value as u32,
            gl::TEXTURE_MIN_LOD => p.min_lod = value,
            _ => p.max_lod = value,
        }
    }
}
