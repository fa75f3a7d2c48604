//! `WEBGL_multi_draw`: several draws in one call, each told its index through `gl_DrawID`.
//!
//! A multi-draw is the draws it lists, in order, each with `gl_DrawID` set to its index: the
//! value goes into the default uniform block before each draw
//! ([`essl::program::InternalUniform::DrawId`]; 0 for every other draw). The call is checked as
//! Chromium and ANGLE check it: a negative `drawcount` is `INVALID_VALUE`, a list shorter than
//! its offset plus `drawcount` is `INVALID_OPERATION`, and when any of the draws breaks a rule of
//! the single draw it stands for, that draw's error is recorded and none of them is drawn.

use super::DrawArgs;
use crate::context::Context;
use crate::gl;

/// One of a multi-draw call's lists (`firstsList`, `countsList`, …) and the offset into it at
/// which the call's values start (`firstsOffset`, …).
#[derive(Clone, Copy, Debug)]
pub struct DrawList<'a> {
    /// The list.
    pub values: &'a [i32],
    /// The index of the first value the call reads.
    pub offset: u32,
}

impl<'a> DrawList<'a> {
    /// `values` from `offset` on.
    pub fn new(values: &'a [i32], offset: u32) -> DrawList<'a> {
        DrawList { values, offset }
    }

    /// The `n` values from the offset; `None` when the list ends before them.
    fn window(self, n: usize) -> Option<&'a [i32]> {
        let start = self.offset as usize;
        self.values.get(start..start.checked_add(n)?)
    }
}

impl Context {
    /// `multiDrawArraysWEBGL`: draw `i` is `drawArrays(mode, firsts[i], counts[i])` with
    /// `gl_DrawID` = `i`, for `i` below `drawcount`.
    pub fn multi_draw_arrays(
        &mut self,
        mode: u32,
        firsts: DrawList,
        counts: DrawList,
        drawcount: i32,
    ) {
        const F: &str = "multiDrawArraysWEBGL";
        let Some([firsts, counts]) =
            self.multi_draw_lists(F, drawcount, [(firsts, "firsts"), (counts, "counts")])
        else {
            return;
        };
        self.multi_draw(drawcount, |i| DrawArgs {
            mode,
            first: firsts[i],
            count: counts[i],
            elements: None,
            instances: 1,
            function: F,
        });
    }

    /// `multiDrawArraysInstancedWEBGL`: [`Context::multi_draw_arrays`] with
    /// `instance_counts[i]` instances of draw `i`.
    pub fn multi_draw_arrays_instanced(
        &mut self,
        mode: u32,
        firsts: DrawList,
        counts: DrawList,
        instance_counts: DrawList,
        drawcount: i32,
    ) {
        const F: &str = "multiDrawArraysInstancedWEBGL";
        let lists = [
            (firsts, "firsts"),
            (counts, "counts"),
            (instance_counts, "instanceCounts"),
        ];
        let Some([firsts, counts, instances]) = self.multi_draw_lists(F, drawcount, lists) else {
            return;
        };
        self.multi_draw(drawcount, |i| DrawArgs {
            mode,
            first: firsts[i],
            count: counts[i],
            elements: None,
            instances: instances[i],
            function: F,
        });
    }

    /// `multiDrawElementsWEBGL`: draw `i` is `drawElements(mode, counts[i], ty, offsets[i])`
    /// with `gl_DrawID` = `i`, for `i` below `drawcount`.
    pub fn multi_draw_elements(
        &mut self,
        mode: u32,
        counts: DrawList,
        ty: u32,
        offsets: DrawList,
        drawcount: i32,
    ) {
        const F: &str = "multiDrawElementsWEBGL";
        let lists = [(counts, "counts"), (offsets, "offsets")];
        let Some([counts, offsets]) = self.multi_draw_lists(F, drawcount, lists) else {
            return;
        };
        if self.webgl1_refuses_index_type(ty, F) {
            return;
        }
        self.multi_draw(drawcount, |i| DrawArgs {
            mode,
            first: 0,
            count: counts[i],
            elements: Some((ty, offsets[i] as i64)),
            instances: 1,
            function: F,
        });
    }

    /// `multiDrawElementsInstancedWEBGL`: [`Context::multi_draw_elements`] with
    /// `instance_counts[i]` instances of draw `i`.
    pub fn multi_draw_elements_instanced(
        &mut self,
        mode: u32,
        counts: DrawList,
        ty: u32,
        offsets: DrawList,
        instance_counts: DrawList,
        drawcount: i32,
    ) {
        const F: &str = "multiDrawElementsInstancedWEBGL";
        let lists = [
            (counts, "counts"),
            (offsets, "offsets"),
            (instance_counts, "instanceCounts"),
        ];
        let Some([counts, offsets, instances]) = self.multi_draw_lists(F, drawcount, lists) else {
            return;
        };
        if self.webgl1_refuses_index_type(ty, F) {
            return;
        }
        self.multi_draw(drawcount, |i| DrawArgs {
            mode,
            first: 0,
            count: counts[i],
            elements: Some((ty, offsets[i] as i64)),
            instances: instances[i],
            function: F,
        });
    }

    /// The `drawcount` values of each list from its offset, or the error recorded: the
    /// extension off (`INVALID_OPERATION`), a negative `drawcount` (`INVALID_VALUE`), a list
    /// that ends before them (`INVALID_OPERATION`).
    fn multi_draw_lists<'a, const N: usize>(
        &mut self,
        function: &'static str,
        drawcount: i32,
        lists: [(DrawList<'a>, &str); N],
    ) -> Option<[&'a [i32]; N]> {
        if !self.extensions.multi_draw {
            self.error(
                gl::INVALID_OPERATION,
                function,
                "WEBGL_multi_draw is not enabled",
            );
            return None;
        }
        let Ok(n) = usize::try_from(drawcount) else {
            self.error(gl::INVALID_VALUE, function, "drawcount < 0");
            return None;
        };
        let mut out = [&[][..]; N];
        for (slot, (list, name)) in out.iter_mut().zip(lists) {
            let Some(w) = list.window(n) else {
                self.error(
                    gl::INVALID_OPERATION,
                    function,
                    format_args!("{name}Offset + drawcount is past the end of {name}List"),
                );
                return None;
            };
            *slot = w;
        }
        Some(out)
    }

    /// Draws `args(i)` for each `i` below `drawcount` with `gl_DrawID` = `i`, once every one
    /// of them has passed the checks of its single draw.
    fn multi_draw(&mut self, drawcount: i32, args: impl Fn(usize) -> DrawArgs) {
        let n = drawcount.max(0) as usize;
        // A single draw is checked as it is drawn.
        if n > 1 && (0..n).any(|i| self.prepare_draw(args(i)).is_none()) {
            return;
        }
        for i in 0..n {
            self.draw_id = i as i32;
            self.draw(args(i));
        }
        self.draw_id = 0;
    }
}
