//! Blending and colour masks, one set per draw buffer ([`DrawBufferState`]): the core calls
//! (`blendFunc`, `blendEquation`, `colorMask`, `enable(BLEND)`) set every draw buffer's;
//! `OES_draw_buffers_indexed` (WebGL 2) sets one draw buffer's (`blendFunciOES`, …,
//! `colorMaskiOES`, `enableiOES(BLEND, i)`) and reads them back with `getIndexedParameter`.
//! The non-indexed queries answer draw buffer 0's, as ES 3.2 does.

use super::{is_blend_equation, is_blend_factor};
use crate::context::Context;
use crate::framebuffer::MAX_COLOR_ATTACHMENTS;
use crate::gl;
use crate::Parameter;

/// The draw buffers a context has (`MAX_DRAW_BUFFERS`).
pub(crate) const DRAW_BUFFERS: usize = MAX_COLOR_ATTACHMENTS as usize;

/// How draws blend into one draw buffer and which of its channels they write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct DrawBufferState {
    /// `BLEND`.
    pub(crate) blend: bool,
    /// Source and destination factors of colour, then of alpha (`blendFuncSeparate`).
    pub(crate) factors: [u32; 4],
    /// Colour and alpha equations (`blendEquationSeparate`).
    pub(crate) equations: [u32; 2],
    /// `colorMask`: red, green, blue, alpha.
    pub(crate) color_mask: [bool; 4],
}

impl Default for DrawBufferState {
    /// GL's initial state: no blending, `ONE`/`ZERO`, `FUNC_ADD`, every channel written.
    fn default() -> DrawBufferState {
        DrawBufferState {
            blend: false,
            factors: [gl::ONE, gl::ZERO, gl::ONE, gl::ZERO],
            equations: [gl::FUNC_ADD; 2],
            color_mask: [true; 4],
        }
    }
}

impl DrawBufferState {
    /// wgpu's blend state, where blending is on.
    pub(crate) fn wgpu_blend(&self) -> Option<wgpu::BlendState> {
        use crate::draw::blend_component;
        let [sr, dr, sa, da] = self.factors;
        let [er, ea] = self.equations;
        self.blend.then(|| wgpu::BlendState {
            color: blend_component(sr, dr, er),
            alpha: blend_component(sa, da, ea),
        })
    }

    /// Whether a factor reads the constant colour's alpha (`CONSTANT_ALPHA` and its
    /// complement).
    pub(crate) fn uses_constant_alpha(&self) -> bool {
        self.blend && self.factors.into_iter().any(uses_constant_alpha)
    }
}

fn uses_constant_color(f: u32) -> bool {
    matches!(f, gl::CONSTANT_COLOR | gl::ONE_MINUS_CONSTANT_COLOR)
}

fn uses_constant_alpha(f: u32) -> bool {
    matches!(f, gl::CONSTANT_ALPHA | gl::ONE_MINUS_CONSTANT_ALPHA)
}

/// The draw buffers a call sets: one, or all of them.
#[derive(Clone, Copy)]
enum Which {
    All,
    One(usize),
}

impl Context {
    /// Sets the blend factors for colour and alpha (`blendFunc`).
    pub fn blend_func(&mut self, sfactor: u32, dfactor: u32) {
        let f = [sfactor, dfactor, sfactor, dfactor];
        self.set_blend_func(Which::All, f, "blendFunc");
    }

    /// Sets separate blend factors for colour and alpha (`blendFuncSeparate`).
    pub fn blend_func_separate(
        &mut self,
        src_rgb: u32,
        dst_rgb: u32,
        src_alpha: u32,
        dst_alpha: u32,
    ) {
        let f = [src_rgb, dst_rgb, src_alpha, dst_alpha];
        self.set_blend_func(Which::All, f, "blendFuncSeparate");
    }

    /// Sets the blend equation for colour and alpha (`blendEquation`): `FUNC_ADD`,
    /// `FUNC_SUBTRACT`, `FUNC_REVERSE_SUBTRACT`, `MIN`, `MAX`.
    pub fn blend_equation(&mut self, mode: u32) {
        if self.webgl1_refuses("blendEquation", &[mode]) {
            return;
        }
        self.set_blend_equation(Which::All, [mode, mode], "blendEquation");
    }

    /// Sets separate blend equations for colour and alpha (`blendEquationSeparate`).
    pub fn blend_equation_separate(&mut self, mode_rgb: u32, mode_alpha: u32) {
        if self.webgl1_refuses("blendEquationSeparate", &[mode_rgb, mode_alpha]) {
            return;
        }
        let e = [mode_rgb, mode_alpha];
        self.set_blend_equation(Which::All, e, "blendEquationSeparate");
    }

    /// Enables or disables writing of each colour component (`colorMask`).
    pub fn color_mask(&mut self, red: bool, green: bool, blue: bool, alpha: bool) {
        for b in &mut self.state.draw_buffers {
            b.color_mask = [red, green, blue, alpha];
        }
    }

    /// `enableiOES` / `disableiOES` (`OES_draw_buffers_indexed`): turns blending into draw
    /// buffer `index` on or off; a `target` other than `BLEND` → `INVALID_ENUM`, an index
    /// past `MAX_DRAW_BUFFERS` → `INVALID_VALUE`.
    pub fn set_enabled_indexed(&mut self, target: u32, index: u32, on: bool) {
        let f = if on { "enableiOES" } else { "disableiOES" };
        if target != gl::BLEND {
            return self.error(gl::INVALID_ENUM, f, format_args!("target 0x{target:04X}"));
        }
        if let Some(i) = self.draw_buffer_index(index, f) {
            self.state.draw_buffers[i].blend = on;
        }
    }

    /// `isEnablediOES`: whether blending into draw buffer `index` is on.
    pub fn is_enabled_indexed(&self, target: u32, index: u32) -> bool {
        const F: &str = "isEnablediOES";
        if target != gl::BLEND {
            self.error(gl::INVALID_ENUM, F, format_args!("target 0x{target:04X}"));
            return false;
        }
        self.draw_buffer_index(index, F)
            .is_some_and(|i| self.state.draw_buffers[i].blend)
    }

    /// `blendEquationSeparateiOES` (and `blendEquationiOES` with `rgb` = `alpha`).
    pub fn blend_equation_separate_indexed(&mut self, index: u32, rgb: u32, alpha: u32) {
        const F: &str = "blendEquationSeparateiOES";
        if let Some(i) = self.draw_buffer_index(index, F) {
            self.set_blend_equation(Which::One(i), [rgb, alpha], F);
        }
    }

    /// `blendFuncSeparateiOES` (and `blendFunciOES` with the colour factors for alpha too).
    pub fn blend_func_separate_indexed(&mut self, index: u32, factors: [u32; 4]) {
        const F: &str = "blendFuncSeparateiOES";
        if let Some(i) = self.draw_buffer_index(index, F) {
            self.set_blend_func(Which::One(i), factors, F);
        }
    }

    /// `colorMaskiOES`: the channels draws write into draw buffer `index`.
    pub fn color_mask_indexed(&mut self, index: u32, mask: [bool; 4]) {
        if let Some(i) = self.draw_buffer_index(index, "colorMaskiOES") {
            self.state.draw_buffers[i].color_mask = mask;
        }
    }

    /// `getIndexedParameter` of `OES_draw_buffers_indexed`'s names (`BLEND_EQUATION_RGB`, …,
    /// `COLOR_WRITEMASK`) for draw buffer `index`: `None` for another name; `Some(None)`
    /// (with the error) for an index past `MAX_DRAW_BUFFERS`.
    pub(crate) fn indexed_blend_parameter(
        &self,
        pname: u32,
        index: u32,
    ) -> Option<Option<Parameter>> {
        if !self.extensions.draw_buffers_indexed {
            return None;
        }
        // Whether `pname` is one of the draw buffers' names, before the index is checked.
        draw_buffer_parameter(&DrawBufferState::default(), pname)?;
        let i = self.draw_buffer_index(index, "getIndexedParameter")?;
        Some(draw_buffer_parameter(&self.state.draw_buffers[i], pname))
    }

    /// `index` as a draw buffer, or `INVALID_VALUE` past `MAX_DRAW_BUFFERS`.
    fn draw_buffer_index(&self, index: u32, function: &str) -> Option<usize> {
        if index as usize >= DRAW_BUFFERS {
            self.error(gl::INVALID_VALUE, function, "index ≥ MAX_DRAW_BUFFERS");
            return None;
        }
        Some(index as usize)
    }

    fn set_blend_func(&mut self, which: Which, f: [u32; 4], function: &str) {
        if !f.into_iter().all(is_blend_factor) {
            return self.error(gl::INVALID_ENUM, function, "not a blend factor");
        }
        let [sr, dr, ..] = f;
        // WebGL: constant colour and constant alpha cannot be combined as source and
        // destination factors.
        if (uses_constant_color(sr) && uses_constant_alpha(dr))
            || (uses_constant_alpha(sr) && uses_constant_color(dr))
        {
            return self.error(
                gl::INVALID_OPERATION,
                function,
                "CONSTANT_COLOR and CONSTANT_ALPHA cannot be used together",
            );
        }
        self.each_draw_buffer(which, |b| b.factors = f);
    }

    fn set_blend_equation(&mut self, which: Which, e: [u32; 2], function: &str) {
        if !e.into_iter().all(is_blend_equation) {
            return self.error(gl::INVALID_ENUM, function, "not a blend equation");
        }
        self.each_draw_buffer(which, |b| b.equations = e);
    }

    fn each_draw_buffer(&mut self, which: Which, f: impl Fn(&mut DrawBufferState)) {
        match which {
            Which::All => self.state.draw_buffers.iter_mut().for_each(f),
            Which::One(i) => f(&mut self.state.draw_buffers[i]),
        }
    }
}

/// What a draw buffer's state answers for `pname` (`BLEND_SRC_RGB`, …, `BLEND_EQUATION_ALPHA`,
/// `COLOR_WRITEMASK`); `None` for another name.
pub(crate) fn draw_buffer_parameter(b: &DrawBufferState, pname: u32) -> Option<Parameter> {
    let [sr, dr, sa, da] = b.factors;
    let [er, ea] = b.equations;
    Some(match pname {
        gl::BLEND_SRC_RGB => Parameter::Enum(sr),
        gl::BLEND_DST_RGB => Parameter::Enum(dr),
        gl::BLEND_SRC_ALPHA => Parameter::Enum(sa),
        gl::BLEND_DST_ALPHA => Parameter::Enum(da),
        gl::BLEND_EQUATION_RGB => Parameter::Enum(er),
        gl::BLEND_EQUATION_ALPHA => Parameter::Enum(ea),
        gl::COLOR_WRITEMASK => Parameter::Bools(b.color_mask.to_vec()),
        _ => return None,
    })
}
