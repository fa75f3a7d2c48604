//! Three extensions of rasterization, each offered where the adapter has what it needs:
//! `EXT_polygon_offset_clamp` (`polygonOffsetClampEXT`: wgpu's depth-bias clamp),
//! `EXT_depth_clamp` (`DEPTH_CLAMP_EXT`: depth clamped instead of clipped, wgpu's
//! `unclipped_depth`) and `WEBGL_polygon_mode` (`polygonModeWEBGL`: triangles drawn as their
//! edges, wgpu's `PolygonMode::Line`, with `POLYGON_OFFSET_LINE_WEBGL` as the polygon offset's
//! switch in that mode).

use crate::context::Context;
use crate::gl;
use crate::Parameter;

/// `EXT_polygon_offset_clamp`'s `getParameter` name.
pub(crate) const POLYGON_OFFSET_CLAMP: u32 = 0x8E1B;
/// `EXT_depth_clamp`'s capability.
pub(crate) const DEPTH_CLAMP: u32 = 0x864F;
/// `WEBGL_polygon_mode`'s `getParameter` name.
pub(crate) const POLYGON_MODE: u32 = 0x0B40;
/// `WEBGL_polygon_mode`'s capability: polygon offset for triangles drawn as lines.
pub(crate) const POLYGON_OFFSET_LINE: u32 = 0x2A02;
/// `WEBGL_polygon_mode`'s modes.
pub(crate) const LINE: u32 = 0x1B01;
/// See [`LINE`].
pub(crate) const FILL: u32 = 0x1B02;

impl Context {
    /// `polygonOffsetClampEXT` (`EXT_polygon_offset_clamp`): [`Context::polygon_offset`] whose
    /// offset is at most `clamp` in size (0: not clamped). `INVALID_OPERATION` while the
    /// extension is off.
    pub fn polygon_offset_clamp_ext(&mut self, factor: f32, units: f32, clamp: f32) {
        if !self.extensions.polygon_offset_clamp {
            let f = "polygonOffsetClampEXT";
            return self.error(gl::INVALID_OPERATION, f, "EXT_polygon_offset_clamp is off");
        }
        self.polygon_offset(factor, units);
        self.state.polygon_offset_clamp = clamp;
    }

    /// `polygonModeWEBGL` (`WEBGL_polygon_mode`): `face` must be `FRONT_AND_BACK`, `mode`
    /// `LINE_WEBGL` or `FILL_WEBGL` (`INVALID_ENUM` otherwise); `INVALID_OPERATION` while the
    /// extension is off.
    pub fn polygon_mode_webgl(&mut self, face: u32, mode: u32) {
        const F: &str = "polygonModeWEBGL";
        if !self.extensions.polygon_mode {
            return self.error(gl::INVALID_OPERATION, F, "WEBGL_polygon_mode is off");
        }
        if face != gl::FRONT_AND_BACK {
            return self.error(gl::INVALID_ENUM, F, format_args!("face 0x{face:04X}"));
        }
        match mode {
            LINE | FILL => self.state.polygon_line = mode == LINE,
            _ => self.error(gl::INVALID_ENUM, F, format_args!("mode 0x{mode:04X}")),
        }
    }

    /// The switch of an extension's capability (`DEPTH_CLAMP_EXT`,
    /// `POLYGON_OFFSET_LINE_WEBGL`) when the extension is on.
    pub(super) fn raster_capability(&mut self, cap: u32) -> Option<&mut bool> {
        let x = self.extensions;
        match cap {
            DEPTH_CLAMP if x.depth_clamp => Some(&mut self.state.depth_clamp),
            POLYGON_OFFSET_LINE if x.polygon_mode => Some(&mut self.state.polygon_offset_line),
            _ => None,
        }
    }

    /// [`Context::raster_capability`]'s value, for `isEnabled`.
    pub(super) fn raster_capability_on(&self, cap: u32) -> Option<bool> {
        let x = self.extensions;
        match cap {
            DEPTH_CLAMP if x.depth_clamp => Some(self.state.depth_clamp),
            POLYGON_OFFSET_LINE if x.polygon_mode => Some(self.state.polygon_offset_line),
            _ => None,
        }
    }

    /// `getParameter` of the three extensions' names, while their extension is on.
    pub(crate) fn raster_parameter(&self, pname: u32) -> Option<Parameter> {
        let (x, s) = (self.extensions, &self.state);
        match pname {
            POLYGON_OFFSET_CLAMP if x.polygon_offset_clamp => {
                Some(Parameter::Float(s.polygon_offset_clamp))
            }
            POLYGON_MODE if x.polygon_mode => {
                Some(Parameter::Enum(if s.polygon_line { LINE } else { FILL }))
            }
            DEPTH_CLAMP | POLYGON_OFFSET_LINE => {
                self.raster_capability_on(pname).map(Parameter::Bool)
            }
            _ => None,
        }
    }
}
