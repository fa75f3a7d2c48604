//! `WEBGL_clip_cull_distance`: the eight `CLIP_DISTANCEi_WEBGL` switches and the extension's
//! limits. The switches are state only here; a draw hands them to the vertex shader through
//! the default uniform block ([`essl::program::InternalUniform::ClipDistancesEnabled`]),
//! which writes a disabled distance as 0 (clips nothing) — wgpu's pipelines have no switch of
//! their own. Cull distances are not offered (wgpu has none): `MAX_CULL_DISTANCES_WEBGL` and
//! `MAX_COMBINED_CLIP_AND_CULL_DISTANCES_WEBGL` are 0, as the extension allows.

use crate::context::Context;
use crate::query::Parameter;

/// `MAX_CLIP_DISTANCES_WEBGL`.
pub(crate) const MAX_CLIP_DISTANCES_WEBGL: u32 = 0x0D32;
/// `MAX_CULL_DISTANCES_WEBGL`.
pub(crate) const MAX_CULL_DISTANCES_WEBGL: u32 = 0x82F9;
/// `MAX_COMBINED_CLIP_AND_CULL_DISTANCES_WEBGL`.
pub(crate) const MAX_COMBINED_CLIP_AND_CULL_DISTANCES_WEBGL: u32 = 0x82FA;
/// `CLIP_DISTANCE0_WEBGL`; the others follow it.
pub(crate) const CLIP_DISTANCE0_WEBGL: u32 = 0x3000;

impl Context {
    /// The switch `cap` names (`CLIP_DISTANCEi_WEBGL` → i) once the extension is on.
    pub(super) fn clip_distance_switch(&self, cap: u32) -> Option<u32> {
        let i = cap.checked_sub(CLIP_DISTANCE0_WEBGL)?;
        (i < essl::MAX_CLIP_DISTANCES && self.extensions.clip_cull_distance).then_some(i)
    }

    /// Turns switch `i` on or off.
    pub(super) fn set_clip_distance(&mut self, i: u32, on: bool) {
        if on {
            self.state.clip_distances |= 1 << i;
        } else {
            self.state.clip_distances &= !(1 << i);
        }
    }

    /// Whether switch `i` is on.
    pub(super) fn clip_distance_on(&self, i: u32) -> bool {
        self.state.clip_distances & (1 << i) != 0
    }

    /// The extension's `getParameter` names, once it is on: its limits and its switches.
    pub(crate) fn clip_distance_parameter(&self, pname: u32) -> Option<Parameter> {
        if !self.extensions.clip_cull_distance {
            return None;
        }
        match pname {
            MAX_CLIP_DISTANCES_WEBGL => Some(Parameter::Int(essl::MAX_CLIP_DISTANCES as i64)),
            MAX_CULL_DISTANCES_WEBGL | MAX_COMBINED_CLIP_AND_CULL_DISTANCES_WEBGL => {
                Some(Parameter::Int(0))
            }
            _ => {
                let i = self.clip_distance_switch(pname)?;
                Some(Parameter::Bool(self.clip_distance_on(i)))
            }
        }
    }

    /// The switches a draw hands to the vertex shader: bit i is `CLIP_DISTANCEi_WEBGL`.
    pub(crate) fn clip_distances_enabled(&self) -> u32 {
        u32::from(self.state.clip_distances)
    }
}
