//! The sampling parameters samplers and textures share, and a sampler object (which holds
//! only them).

use crate::gl;
use crate::query::Parameter;
use crate::state::is_compare_func;

/// How a texture is sampled, with GL's initial values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SamplerParams {
    pub(crate) min_filter: u32,
    pub(crate) mag_filter: u32,
    pub(crate) wrap_s: u32,
    pub(crate) wrap_t: u32,
    pub(crate) wrap_r: u32,
    pub(crate) min_lod: f32,
    pub(crate) max_lod: f32,
    pub(crate) compare_mode: u32,
    pub(crate) compare_func: u32,
    /// `TEXTURE_MAX_ANISOTROPY_EXT`.
    pub(crate) max_anisotropy: f32,
}

impl Default for SamplerParams {
    fn default() -> Self {
        SamplerParams {
            min_filter: gl::NEAREST_MIPMAP_LINEAR,
            mag_filter: gl::LINEAR,
            wrap_s: gl::REPEAT,
            wrap_t: gl::REPEAT,
            wrap_r: gl::REPEAT,
            min_lod: -1000.0,
            max_lod: 1000.0,
            compare_mode: gl::NONE,
            compare_func: gl::LEQUAL,
            max_anisotropy: 1.0,
        }
    }
}

/// Why a sampling parameter was refused: the GL error to record.
pub(crate) enum ParamError {
    /// Not a sampling parameter (`INVALID_ENUM`).
    Pname,
    /// Not a value the parameter takes (`INVALID_ENUM`).
    Value,
    /// A number out of the parameter's range (`INVALID_VALUE`).
    Range,
}

impl SamplerParams {
    /// Whether the minification filter reads mipmaps.
    pub(crate) fn mipmapped(&self) -> bool {
        !matches!(self.min_filter, gl::NEAREST | gl::LINEAR)
    }

    /// Sets one parameter from a value given as a float (`*Parameteri` converts its
    /// integer), as GL checks it.
    pub(crate) fn set(&mut self, pname: u32, value: f32) -> Result<(), ParamError> {
        let e = value as i64 as u32;
        let ok = match pname {
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
            gl::TEXTURE_MIN_LOD | gl::TEXTURE_MAX_LOD => true,
            crate::extensions::TEXTURE_MAX_ANISOTROPY_EXT => {
                if value.is_nan() || value < 1.0 {
                    return Err(ParamError::Range);
                }
                self.max_anisotropy = value;
                return Ok(());
            }
            _ => return Err(ParamError::Pname),
        };
        if !ok {
            return Err(ParamError::Value);
        }
        match pname {
            gl::TEXTURE_MIN_FILTER => self.min_filter = e,
            gl::TEXTURE_MAG_FILTER => self.mag_filter = e,
            gl::TEXTURE_WRAP_S => self.wrap_s = e,
            gl::TEXTURE_WRAP_T => self.wrap_t = e,
            gl::TEXTURE_WRAP_R => self.wrap_r = e,
            gl::TEXTURE_COMPARE_MODE => self.compare_mode = e,
            gl::TEXTURE_COMPARE_FUNC => self.compare_func = e,
            gl::TEXTURE_MIN_LOD => self.min_lod = value,
            _ => self.max_lod = value,
        }
        Ok(())
    }

    /// The value of one parameter, as WebGL returns it (`None`: not a sampling parameter).
    pub(crate) fn get(&self, pname: u32) -> Option<Parameter> {
        Some(match pname {
            gl::TEXTURE_MIN_FILTER => Parameter::Enum(self.min_filter),
            gl::TEXTURE_MAG_FILTER => Parameter::Enum(self.mag_filter),
            gl::TEXTURE_WRAP_S => Parameter::Enum(self.wrap_s),
            gl::TEXTURE_WRAP_T => Parameter::Enum(self.wrap_t),
            gl::TEXTURE_WRAP_R => Parameter::Enum(self.wrap_r),
            gl::TEXTURE_COMPARE_MODE => Parameter::Enum(self.compare_mode),
            gl::TEXTURE_COMPARE_FUNC => Parameter::Enum(self.compare_func),
            gl::TEXTURE_MIN_LOD => Parameter::Float(self.min_lod),
            gl::TEXTURE_MAX_LOD => Parameter::Float(self.max_lod),
            crate::extensions::TEXTURE_MAX_ANISOTROPY_EXT => Parameter::Float(self.max_anisotropy),
            _ => return None,
        })
    }
}

/// A sampler object.
#[derive(Default)]
pub(crate) struct SamplerObject {
    pub(crate) params: SamplerParams,
}
