//! Fixed-function state: viewport, scissor, clear values, depth, culling, blending, masks,
//! and pixel storage (`pixel_storei`). The values live in [`values`]; this file,
//! [`blend`] (blending and colour masks, per draw buffer) and [`stencil`] hold the calls that
//! check and set them.

mod blend;
mod clip_control;
mod clip_distance;
mod raster;
mod stencil;
mod values;

pub(crate) use blend::{draw_buffer_parameter, DrawBufferState};
pub(crate) use values::{compare_function, is_compare_func, PixelStore, RenderState};

use crate::context::Context;
use crate::gl;

fn is_blend_factor(f: u32) -> bool {
    matches!(
        f,
        gl::ZERO
            | gl::ONE
            | gl::SRC_COLOR
            | gl::ONE_MINUS_SRC_COLOR
            | gl::DST_COLOR
            | gl::ONE_MINUS_DST_COLOR
            | gl::SRC_ALPHA
            | gl::ONE_MINUS_SRC_ALPHA
            | gl::DST_ALPHA
            | gl::ONE_MINUS_DST_ALPHA
            | gl::CONSTANT_COLOR
            | gl::ONE_MINUS_CONSTANT_COLOR
            | gl::CONSTANT_ALPHA
            | gl::ONE_MINUS_CONSTANT_ALPHA
            | gl::SRC_ALPHA_SATURATE
    )
}

fn is_blend_equation(e: u32) -> bool {
    matches!(
        e,
        gl::FUNC_ADD | gl::FUNC_SUBTRACT | gl::FUNC_REVERSE_SUBTRACT | gl::MIN | gl::MAX
    )
}

/// The flag of capability `cap` in a `State` (`&mut` with a trailing `mut`), or `None` for a
/// name that is not a capability.
macro_rules! capability_flag {
    ($s:expr, $cap:expr $(, $m:ident)?) => {
        match $cap {
            gl::CULL_FACE => Some(&$($m)? $s.cull_face),
            gl::DEPTH_TEST => Some(&$($m)? $s.depth_test),
            gl::DITHER => Some(&$($m)? $s.dither),
            gl::POLYGON_OFFSET_FILL => Some(&$($m)? $s.polygon_offset_fill),
            gl::RASTERIZER_DISCARD => Some(&$($m)? $s.rasterizer_discard),
            gl::SAMPLE_ALPHA_TO_COVERAGE => Some(&$($m)? $s.sample_alpha_to_coverage),
            gl::SAMPLE_COVERAGE => Some(&$($m)? $s.sample_coverage),
            gl::SCISSOR_TEST => Some(&$($m)? $s.scissor_test),
            gl::STENCIL_TEST => Some(&$($m)? $s.stencil_test),
            _ => None,
        }
    };
}

impl Context {
    /// Sets the viewport (`viewport`): `x`, `y` from the bottom-left corner, in pixels.
    /// Negative `width` or `height` → `INVALID_VALUE`.
    pub fn viewport(&mut self, x: i32, y: i32, width: i32, height: i32) {
        if width < 0 || height < 0 {
            return self.error(gl::INVALID_VALUE, "viewport", "negative width or height");
        }
        let max = self.gpu.limits.max_texture_dimension_2d as i32;
        self.state.viewport = [x, y, width.min(max), height.min(max)];
    }

    /// Sets the scissor box (`scissor`), from the bottom-left corner.
    pub fn scissor(&mut self, x: i32, y: i32, width: i32, height: i32) {
        if width < 0 || height < 0 {
            return self.error(gl::INVALID_VALUE, "scissor", "negative width or height");
        }
        self.state.scissor = [x, y, width, height];
    }

    /// Sets the colour [`Context::clear`] writes (`clearColor`).
    pub fn clear_color(&mut self, red: f32, green: f32, blue: f32, alpha: f32) {
        self.state.clear_color = [red, green, blue, alpha];
    }

    /// Sets the depth [`Context::clear`] writes (`clearDepth`), clamped to 0..1.
    pub fn clear_depth(&mut self, depth: f32) {
        self.state.clear_depth = depth.clamp(0.0, 1.0);
    }

    /// Sets the stencil value [`Context::clear`] writes (`clearStencil`).
    pub fn clear_stencil(&mut self, s: i32) {
        self.state.clear_stencil = s;
    }

    /// Sets capability `cap`; an unknown one → `INVALID_ENUM`.
    fn capability(&mut self, cap: u32, value: bool, function: &str) {
        if let Some(i) = self.clip_distance_switch(cap) {
            return self.set_clip_distance(i, value);
        }
        if cap == gl::BLEND {
            for b in &mut self.state.draw_buffers {
                b.blend = value;
            }
            return;
        }
        if let Some(flag) = self.raster_capability(cap) {
            *flag = value;
            return;
        }
        match capability_flag!(self.state, cap, mut) {
            Some(flag) => *flag = value,
            None => self.error(
                gl::INVALID_ENUM,
                function,
                format_args!("capability 0x{cap:04X}"),
            ),
        }
    }

    /// Enables a capability (`DEPTH_TEST`, `CULL_FACE`, `BLEND`, `SCISSOR_TEST`,
    /// `STENCIL_TEST`, `POLYGON_OFFSET_FILL`, `RASTERIZER_DISCARD`, `SAMPLE_ALPHA_TO_COVERAGE`,
    /// `SAMPLE_COVERAGE`, …, and `CLIP_DISTANCEi_WEBGL` once `WEBGL_clip_cull_distance` is on);
    /// an unknown one → `INVALID_ENUM`. `DITHER` is state only.
    pub fn enable(&mut self, cap: u32) {
        if self.webgl1_refuses("enable", &[cap]) {
            return;
        }
        self.capability(cap, true, "enable");
    }

    /// Disables a capability; see [`Context::enable`].
    pub fn disable(&mut self, cap: u32) {
        if self.webgl1_refuses("disable", &[cap]) {
            return;
        }
        self.capability(cap, false, "disable");
    }

    /// Whether a capability is enabled (`isEnabled`); an unknown one → `INVALID_ENUM`, false.
    pub fn is_enabled(&self, cap: u32) -> bool {
        if self.webgl1_refuses("isEnabled", &[cap]) {
            return false;
        }
        if let Some(i) = self.clip_distance_switch(cap) {
            return self.clip_distance_on(i);
        }
        if cap == gl::BLEND {
            return self.state.draw_buffers[0].blend;
        }
        if let Some(on) = self.raster_capability_on(cap) {
            return on;
        }
        match capability_flag!(self.state, cap) {
            Some(flag) => *flag,
            None => {
                self.error(
                    gl::INVALID_ENUM,
                    "isEnabled",
                    format_args!("capability 0x{cap:04X}"),
                );
                false
            }
        }
    }

    /// Sets the depth comparison (`depthFunc`): `NEVER`, `LESS`, … `ALWAYS`.
    pub fn depth_func(&mut self, func: u32) {
        if !is_compare_func(func) {
            return self.error(gl::INVALID_ENUM, "depthFunc", format_args!("0x{func:04X}"));
        }
        self.state.depth_func = func;
    }

    /// Enables or disables writing to the depth buffer (`depthMask`).
    pub fn depth_mask(&mut self, flag: bool) {
        self.state.depth_mask = flag;
    }

    /// Maps normalized device depth to window depth (`depthRange`); values are clamped to
    /// 0..1 and `z_near > z_far` → `INVALID_OPERATION` (WebGL's rule).
    pub fn depth_range(&mut self, z_near: f32, z_far: f32) {
        if z_near > z_far {
            return self.error(gl::INVALID_OPERATION, "depthRange", "zNear > zFar");
        }
        self.state.depth_range = [z_near.clamp(0.0, 1.0), z_far.clamp(0.0, 1.0)];
    }

    /// Chooses which faces `CULL_FACE` culls (`cullFace`): `FRONT`, `BACK`, `FRONT_AND_BACK`.
    pub fn cull_face(&mut self, mode: u32) {
        if !matches!(mode, gl::FRONT | gl::BACK | gl::FRONT_AND_BACK) {
            return self.error(gl::INVALID_ENUM, "cullFace", format_args!("0x{mode:04X}"));
        }
        self.state.cull_face_mode = mode;
    }

    /// Chooses the winding of front faces (`frontFace`): `CCW` (the default) or `CW`.
    pub fn front_face(&mut self, mode: u32) {
        if !matches!(mode, gl::CW | gl::CCW) {
            return self.error(gl::INVALID_ENUM, "frontFace", format_args!("0x{mode:04X}"));
        }
        self.state.front_face = mode;
    }

    /// Sets the constant blend colour (`blendColor`).
    pub fn blend_color(&mut self, red: f32, green: f32, blue: f32, alpha: f32) {
        self.state.blend_color = [red, green, blue, alpha];
    }

    /// Sets the depth offset of `POLYGON_OFFSET_FILL` (`polygonOffset`), not clamped (see
    /// [`Context::polygon_offset_clamp_ext`]).
    pub fn polygon_offset(&mut self, factor: f32, units: f32) {
        self.state.polygon_offset_factor = factor;
        self.state.polygon_offset_units = units;
        self.state.polygon_offset_clamp = 0.0;
    }

    /// Sets how many samples `SAMPLE_COVERAGE` keeps (`sampleCoverage`): with the capability
    /// enabled, draws into a multisampled framebuffer write the first `round(value · samples)`
    /// samples of each pixel, or the others with `invert`. Clears are not masked.
    pub fn sample_coverage(&mut self, value: f32, invert: bool) {
        self.state.sample_coverage_value = (value.clamp(0.0, 1.0), invert);
    }

    /// A hint about quality against speed (`hint`): `GENERATE_MIPMAP_HINT` or
    /// `FRAGMENT_SHADER_DERIVATIVE_HINT` to `FASTEST`, `NICEST` or `DONT_CARE`. Kept and
    /// reported; essl-gl does one thing either way, as GL allows.
    pub fn hint(&mut self, target: u32, mode: u32) {
        if self.webgl1_refuses("hint", &[target, mode]) {
            return;
        }
        let slot = match target {
            gl::GENERATE_MIPMAP_HINT => 0,
            gl::FRAGMENT_SHADER_DERIVATIVE_HINT => 1,
            _ => {
                return self.error(
                    gl::INVALID_ENUM,
                    "hint",
                    format_args!("target 0x{target:04X}"),
                )
            }
        };
        if !matches!(mode, gl::FASTEST | gl::NICEST | gl::DONT_CARE) {
            return self.error(gl::INVALID_ENUM, "hint", format_args!("mode 0x{mode:04X}"));
        }
        self.state.hints[slot] = mode;
    }

    /// Sets the line width (`lineWidth`); only 1 is drawn, as on most WebGL implementations.
    /// A width ≤ 0 or NaN → `INVALID_VALUE`.
    pub fn line_width(&mut self, width: f32) {
        if width.is_nan() || width <= 0.0 {
            return self.error(gl::INVALID_VALUE, "lineWidth", "width must be > 0");
        }
        self.state.line_width = width;
    }

    /// Sets a pixel storage parameter (`pixelStorei`): `UNPACK_ALIGNMENT`, `PACK_ALIGNMENT`
    /// (1, 2, 4 or 8), `UNPACK_ROW_LENGTH`, `UNPACK_SKIP_ROWS`, `UNPACK_SKIP_PIXELS`,
    /// `UNPACK_IMAGE_HEIGHT`, `UNPACK_SKIP_IMAGES`, `PACK_ROW_LENGTH`, `PACK_SKIP_ROWS`,
    /// `PACK_SKIP_PIXELS`, `UNPACK_FLIP_Y_WEBGL`, `UNPACK_PREMULTIPLY_ALPHA_WEBGL`,
    /// `UNPACK_COLORSPACE_CONVERSION_WEBGL`.
    pub fn pixel_storei(&mut self, pname: u32, param: i32) {
        if self.webgl1_refuses("pixelStorei", &[pname]) {
            return;
        }
        let p = &mut self.pixel_store;
        let count = |v: i32| u32::try_from(v).ok();
        let ok = match pname {
            gl::UNPACK_ALIGNMENT | gl::PACK_ALIGNMENT => {
                if !matches!(param, 1 | 2 | 4 | 8) {
                    return self.error(
                        gl::INVALID_VALUE,
                        "pixelStorei",
                        "alignment must be 1, 2, 4 or 8",
                    );
                }
                if pname == gl::UNPACK_ALIGNMENT {
                    p.unpack_alignment = param as u32;
                } else {
                    p.pack_alignment = param as u32;
                }
                true
            }
            gl::UNPACK_ROW_LENGTH => count(param).map(|v| p.unpack_row_length = v).is_some(),
            gl::UNPACK_SKIP_ROWS => count(param).map(|v| p.unpack_skip_rows = v).is_some(),
            gl::UNPACK_SKIP_PIXELS => count(param).map(|v| p.unpack_skip_pixels = v).is_some(),
            gl::UNPACK_IMAGE_HEIGHT => count(param).map(|v| p.unpack_image_height = v).is_some(),
            gl::UNPACK_SKIP_IMAGES => count(param).map(|v| p.unpack_skip_images = v).is_some(),
            gl::PACK_ROW_LENGTH => count(param).map(|v| p.pack_row_length = v).is_some(),
            gl::PACK_SKIP_ROWS => count(param).map(|v| p.pack_skip_rows = v).is_some(),
            gl::PACK_SKIP_PIXELS => count(param).map(|v| p.pack_skip_pixels = v).is_some(),
            gl::UNPACK_FLIP_Y_WEBGL => {
                p.unpack_flip_y = param != 0;
                true
            }
            gl::UNPACK_PREMULTIPLY_ALPHA_WEBGL => {
                p.unpack_premultiply_alpha = param != 0;
                true
            }
            gl::UNPACK_COLORSPACE_CONVERSION_WEBGL => {
                if !matches!(param as u32, gl::NONE | gl::BROWSER_DEFAULT_WEBGL) {
                    return self.error(gl::INVALID_ENUM, "pixelStorei", "colorspace conversion");
                }
                p.unpack_colorspace_conversion = param as u32;
                true
            }
            _ => {
                return self.error(
                    gl::INVALID_ENUM,
                    "pixelStorei",
                    format_args!("pname 0x{pname:04X}"),
                )
            }
        };
        if !ok {
            self.error(gl::INVALID_VALUE, "pixelStorei", "negative value");
        }
    }
}
