//! `EXT_clip_control`: `clipControlEXT(origin, depth)` and its two `getParameter` names. A
//! program linked while the extension is on declares the state as two pipeline-overridable
//! constants of its vertex stage ([`essl::program::LowerOptions::clip_control`]); a draw sets
//! them in the pipeline it builds. `UPPER_LEFT_EXT` draws without the vertical flip essl-gl
//! otherwise draws with, so that the image lands upside down in GL's rows as GL puts it; GL
//! negates the polygon area under that origin, so a triangle faces as it does under
//! `LOWER_LEFT_EXT`, and the pipeline takes GL's winding unswapped. Programs linked before the
//! extension was turned on keep GL's default.

use crate::context::Context;
use crate::gl;
use crate::query::Parameter;

/// `LOWER_LEFT_EXT`.
pub(crate) const LOWER_LEFT_EXT: u32 = 0x8CA1;
/// `UPPER_LEFT_EXT`.
pub(crate) const UPPER_LEFT_EXT: u32 = 0x8CA2;
/// `NEGATIVE_ONE_TO_ONE_EXT`.
pub(crate) const NEGATIVE_ONE_TO_ONE_EXT: u32 = 0x935E;
/// `ZERO_TO_ONE_EXT`.
pub(crate) const ZERO_TO_ONE_EXT: u32 = 0x935F;
/// `CLIP_ORIGIN_EXT`.
pub(crate) const CLIP_ORIGIN_EXT: u32 = 0x935C;
/// `CLIP_DEPTH_MODE_EXT`.
pub(crate) const CLIP_DEPTH_MODE_EXT: u32 = 0x935D;
/// GL's initial `[CLIP_ORIGIN_EXT, CLIP_DEPTH_MODE_EXT]`.
pub(crate) const DEFAULT_CLIP_CONTROL: [u32; 2] = [LOWER_LEFT_EXT, NEGATIVE_ONE_TO_ONE_EXT];

impl Context {
    /// `EXT_clip_control`'s `clipControlEXT`: the clip-space origin (`LOWER_LEFT_EXT`,
    /// `UPPER_LEFT_EXT`) and depth range (`NEGATIVE_ONE_TO_ONE_EXT`, `ZERO_TO_ONE_EXT`);
    /// another value → `INVALID_ENUM`, and nothing without the extension.
    pub fn clip_control_ext(&mut self, origin: u32, depth: u32) {
        if !self.extensions.clip_control {
            return self.error(
                gl::INVALID_OPERATION,
                "clipControlEXT",
                "EXT_clip_control is not enabled",
            );
        }
        if !matches!(origin, LOWER_LEFT_EXT | UPPER_LEFT_EXT) {
            return self.error(
                gl::INVALID_ENUM,
                "clipControlEXT",
                format_args!("origin 0x{origin:04X}"),
            );
        }
        if !matches!(depth, NEGATIVE_ONE_TO_ONE_EXT | ZERO_TO_ONE_EXT) {
            return self.error(
                gl::INVALID_ENUM,
                "clipControlEXT",
                format_args!("depth 0x{depth:04X}"),
            );
        }
        self.state.clip_control = [origin, depth];
    }

    /// The state a draw's pipeline takes: (origin `UPPER_LEFT_EXT`, depth `ZERO_TO_ONE_EXT`).
    pub(crate) fn clip_control_flags(&self) -> (bool, bool) {
        let [origin, depth] = self.state.clip_control;
        (origin == UPPER_LEFT_EXT, depth == ZERO_TO_ONE_EXT)
    }

    /// `CLIP_ORIGIN_EXT` and `CLIP_DEPTH_MODE_EXT`, once the extension is on.
    pub(crate) fn clip_control_parameter(&self, pname: u32) -> Option<Parameter> {
        if !self.extensions.clip_control {
            return None;
        }
        let [origin, depth] = self.state.clip_control;
        match pname {
            CLIP_ORIGIN_EXT => Some(Parameter::Enum(origin)),
            CLIP_DEPTH_MODE_EXT => Some(Parameter::Enum(depth)),
            _ => None,
        }
    }
}
