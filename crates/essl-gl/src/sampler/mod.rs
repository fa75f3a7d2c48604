//! Sampler objects: `create_sampler`, `bind_sampler`, `sampler_parameteri/f`,
//! `get_sampler_parameter`. The sampling parameters they share with textures (filters, wrap
//! modes, level-of-detail range, depth comparison) are [`object`]'s. A sampler bound to a
//! texture unit replaces the unit's textures' own sampling parameters, completeness included
//! (ES 3.0 §3.8.2).

mod object;

pub(crate) use object::{ParamError, SamplerObject, SamplerParams};

use crate::context::Context;
use crate::gl;
use crate::objects::{Id, Sampler};
use crate::query::Parameter;

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
        let gated = self.anisotropy_refused(pname);
        let s = self.objects.samplers.get_mut(id).expect("checked");
        let result = if gated {
            Err(ParamError::Pname)
        } else {
            s.params.set(pname, value)
        };
        match result {
            Ok(()) => {}
            Err(ParamError::Pname) => {
                self.error(gl::INVALID_ENUM, f, format_args!("pname 0x{pname:04X}"))
            }
            Err(ParamError::Value) => self.error(
                gl::INVALID_ENUM,
                f,
                format_args!("value {value} for pname 0x{pname:04X}"),
            ),
            Err(ParamError::Range) => self.error(
                gl::INVALID_VALUE,
                f,
                format_args!("value {value} for pname 0x{pname:04X}"),
            ),
        }
    }

    /// A parameter of a sampler (`getSamplerParameter`); another `pname` → `INVALID_ENUM`.
    pub fn get_sampler_parameter(&self, sampler: Sampler, pname: u32) -> Option<Parameter> {
        const F: &str = "getSamplerParameter";
        let id = self.sampler_id(sampler, F)?;
        let value = if self.anisotropy_refused(pname) {
            None
        } else {
            self.objects.samplers.get(id)?.params.get(pname)
        };
        if value.is_none() {
            self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
        }
        value
    }

    /// Whether `pname` is `TEXTURE_MAX_ANISOTROPY_EXT` while its extension is off.
    pub(crate) fn anisotropy_refused(&self, pname: u32) -> bool {
        pname == crate::extensions::TEXTURE_MAX_ANISOTROPY_EXT && !self.extensions.anisotropic
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
