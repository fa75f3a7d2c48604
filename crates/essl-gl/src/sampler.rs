//! Sampler objects (`create_sampler`, `bind_sampler`, `sampler_parameteri/f`,
//! `get_sampler_parameter`) and the sampling parameters they share with textures: filters,
//! wrap modes, level-of-detail range and depth comparison. A sampler bound to a texture unit
//! replaces the unit's textures' own sampling parameters, completeness included (ES 3.0
//! §3.8.2).

use crate::context::Context;
use crate::gl;
use crate::objects::{Id, Sampler};
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
        }
    }
}

/// Why a sampling parameter was refused: the GL error to record.
pub(crate) enum ParamError {
    /// Not a sampling parameter (`INVALID_ENUM`).
    Pname,
    /// Not a value the parameter takes (`INVALID_ENUM`).
    Value,
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
            _ => return None,
        })
    }
}

/// A sampler object.
#[derive(Default)]
pub(crate) struct SamplerObject {
    pub(crate) params: SamplerParams,
}

impl Context {
    /// Creates a sampler (`createSampler`).
    pub fn create_sampler(&mut self) -> Sampler {
        Sampler {
            ctx: self.id,
            id: self.objects.samplers.insert(SamplerObject::default()),
        }
    }

    /// Whether `sampler` names a live sampler (`isSampler`).
    pub fn is_sampler(&self, sampler: Sampler) -> bool {
        sampler.ctx == self.id && self.objects.samplers.is_live(sampler.id)
    }

    /// Deletes a sampler (`deleteSampler`), unbinding it from every unit.
    pub fn delete_sampler(&mut self, sampler: Sampler) {
        if !self.owns(sampler.ctx, "deleteSampler") || !self.objects.samplers.is_live(sampler.id) {
            return;
        }
        self.bindings.forget_sampler(sampler.id);
        self.objects.delete_sampler(sampler.id);
    }

    /// Binds a sampler to texture unit `unit` (`bindSampler`; the unit is a number, not
    /// `TEXTURE0 + i`); `None` unbinds. A unit ≥ `MAX_COMBINED_TEXTURE_IMAGE_UNITS` →
    /// `INVALID_VALUE`, a deleted sampler → `INVALID_OPERATION`.
    pub fn bind_sampler(&mut self, unit: u32, sampler: Option<Sampler>) {
        const F: &str = "bindSampler";
        if unit >= crate::MAX_TEXTURE_UNITS {
            return self.error(
                gl::INVALID_VALUE,
                F,
                "unit ≥ MAX_COMBINED_TEXTURE_IMAGE_UNITS",
            );
        }
        let id = match sampler {
            None => None,
            Some(s) => match self.sampler_id(s, F) {
                Some(id) => Some(id),
                None => return,
            },
        };
        self.bindings.bind_sampler(unit, id);
    }

    fn sampler_id(&self, s: Sampler, function: &str) -> Option<Id> {
        if !self.owns(s.ctx, function) {
            return None;
        }
        if !self.objects.samplers.is_live(s.id) {
            self.error(gl::INVALID_OPERATION, function, "deleted sampler");
            return None;
        }
        Some(s.id)
    }

    /// Sets an integer parameter of a sampler (`samplerParameteri`): the sampling parameters
    /// of [`Context::tex_parameteri`] (not the level range).
    pub fn sampler_parameteri(&mut self, sampler: Sampler, pname: u32, param: i32) {
        self.sampler_parameter(sampler, pname, param as f32, "samplerParameteri");
    }

    /// Sets a float parameter of a sampler (`samplerParameterf`).
    pub fn sampler_parameterf(&mut self, sampler: Sampler, pname: u32, param: f32) {
        self.sampler_parameter(sampler, pname, param, "samplerParameterf");
    }

    fn sampler_parameter(&mut self, sampler: Sampler, pname: u32, value: f32, f: &str) {
        let Some(id) = self.sampler_id(sampler, f) else {
            return;
        };
        let s = self.objects.samplers.get_mut(id).expect("checked");
        match s.params.set(pname, value) {
            Ok(()) => {}
            Err(ParamError::Pname) => {
                self.error(gl::INVALID_ENUM, f, format_args!("pname 0x{pname:04X}"))
            }
            Err(ParamError::Value) => self.error(
                gl::INVALID_ENUM,
                f,
                format_args!("value {value} for pname 0x{pname:04X}"),
            ),
        }
    }

    /// A parameter of a sampler (`getSamplerParameter`); another `pname` → `INVALID_ENUM`.
    pub fn get_sampler_parameter(&self, sampler: Sampler, pname: u32) -> Option<Parameter> {
        const F: &str = "getSamplerParameter";
        let id = self.sampler_id(sampler, F)?;
        let value = self.objects.samplers.get(id)?.params.get(pname);
        if value.is_none() {
            self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
        }
        value
    }

    /// The sampling parameters that apply to texture `texture` on unit `unit`: the bound
    /// sampler's if there is one, else the texture's own.
    pub(crate) fn sampling_for(&self, unit: u32, texture: Id) -> Option<SamplerParams> {
        if let Some(s) = self
            .bindings
            .sampler(unit)
            .and_then(|s| self.objects.samplers.get_any(s))
        {
            return Some(s.params);
        }
        self.objects
            .textures
            .get_any(texture)
            .map(|t| t.params.sampling)
    }
}
