//! The stencil test's calls: `stencil_func`, `stencil_op`, `stencil_mask` and their
//! `_separate` forms, which set [`StencilState`](super::values::StencilState).
//!
//! wgpu has one reference value and one read and write mask for both faces; WebGL2 requires
//! the front and back values to agree at a draw (`INVALID_OPERATION` otherwise), so nothing
//! is lost.

use super::is_compare_func;
use crate::context::Context;
use crate::gl;

/// Which faces a `face` argument names: `FRONT`, `BACK` or `FRONT_AND_BACK`.
fn faces(face: u32) -> Option<&'static [usize]> {
    match face {
        gl::FRONT => Some(&[0]),
        gl::BACK => Some(&[1]),
        gl::FRONT_AND_BACK => Some(&[0, 1]),
        _ => None,
    }
}

fn is_stencil_op(op: u32) -> bool {
    matches!(
        op,
        gl::KEEP
            | gl::ZERO
            | gl::REPLACE
            | gl::INCR
            | gl::DECR
            | gl::INVERT
            | gl::INCR_WRAP
            | gl::DECR_WRAP
    )
}

impl Context {
    /// Sets the stencil test of both faces (`stencilFunc`): comparison `func`, reference
    /// `reference`, and the mask both are ANDed with.
    pub fn stencil_func(&mut self, func: u32, reference: i32, mask: u32) {
        self.stencil_func_separate_impl(gl::FRONT_AND_BACK, func, reference, mask, "stencilFunc");
    }

    /// [`Context::stencil_func`] for `FRONT`, `BACK` or `FRONT_AND_BACK` faces
    /// (`stencilFuncSeparate`).
    pub fn stencil_func_separate(&mut self, face: u32, func: u32, reference: i32, mask: u32) {
        self.stencil_func_separate_impl(face, func, reference, mask, "stencilFuncSeparate");
    }

    fn stencil_func_separate_impl(
        &mut self,
        face: u32,
        func: u32,
        reference: i32,
        mask: u32,
        f: &str,
    ) {
        let Some(faces) = faces(face) else {
            return self.error(gl::INVALID_ENUM, f, format_args!("face 0x{face:04X}"));
        };
        if !is_compare_func(func) {
            return self.error(gl::INVALID_ENUM, f, format_args!("func 0x{func:04X}"));
        }
        let s = &mut self.state.stencil;
        for &i in faces {
            s.func[i] = func;
            s.reference[i] = reference;
            s.value_mask[i] = mask;
        }
    }

    /// Sets what the stencil test does to the stencil buffer for both faces (`stencilOp`):
    /// when the stencil test fails, when it passes but the depth test fails, when both pass.
    pub fn stencil_op(&mut self, fail: u32, zfail: u32, zpass: u32) {
        self.stencil_op_separate_impl(gl::FRONT_AND_BACK, [fail, zfail, zpass], "stencilOp");
    }

    /// [`Context::stencil_op`] for chosen faces (`stencilOpSeparate`).
    pub fn stencil_op_separate(&mut self, face: u32, fail: u32, zfail: u32, zpass: u32) {
        self.stencil_op_separate_impl(face, [fail, zfail, zpass], "stencilOpSeparate");
    }

    fn stencil_op_separate_impl(&mut self, face: u32, ops: [u32; 3], f: &str) {
        let Some(faces) = faces(face) else {
            return self.error(gl::INVALID_ENUM, f, format_args!("face 0x{face:04X}"));
        };
        if !ops.iter().all(|&o| is_stencil_op(o)) {
            return self.error(gl::INVALID_ENUM, f, "not a stencil operation");
        }
        let s = &mut self.state.stencil;
        for &i in faces {
            (s.fail[i], s.depth_fail[i], s.pass[i]) = (ops[0], ops[1], ops[2]);
        }
    }

    /// Sets the stencil bits draws and clears may write, both faces (`stencilMask`).
    pub fn stencil_mask(&mut self, mask: u32) {
        self.state.stencil.writemask = [mask; 2];
    }

    /// [`Context::stencil_mask`] for chosen faces (`stencilMaskSeparate`).
    pub fn stencil_mask_separate(&mut self, face: u32, mask: u32) {
        let Some(faces) = faces(face) else {
            return self.error(
                gl::INVALID_ENUM,
                "stencilMaskSeparate",
                format_args!("face 0x{face:04X}"),
            );
        };
        for &i in faces {
            self.state.stencil.writemask[i] = mask;
        }
    }
}
