//! `WEBGL_multi_draw`'s calls: the lists arrive as `Int32Array`s (the JS side converts a
//! sequence), with the offsets and `drawcount` essl-gl checks.

use essl_gl::DrawList;
use napi_derive::napi;

use crate::context::NativeContext;

#[napi]
impl NativeContext {
    /// `multiDrawArraysWEBGL`.
    #[napi(catch_unwind)]
    pub fn multi_draw_arrays(
        &mut self,
        mode: u32,
        firsts: &[i32],
        firsts_offset: u32,
        counts: &[i32],
        counts_offset: u32,
        drawcount: i32,
    ) -> napi::Result<()> {
        self.gl()?.multi_draw_arrays(
            mode,
            DrawList::new(firsts, firsts_offset),
            DrawList::new(counts, counts_offset),
            drawcount,
        );
        Ok(())
    }

    /// `multiDrawArraysInstancedWEBGL` (the IDL's eight arguments).
    #[allow(clippy::too_many_arguments)]
    #[napi(catch_unwind)]
    pub fn multi_draw_arrays_instanced(
        &mut self,
        mode: u32,
        firsts: &[i32],
        firsts_offset: u32,
        counts: &[i32],
        counts_offset: u32,
        instance_counts: &[i32],
        instance_counts_offset: u32,
        drawcount: i32,
    ) -> napi::Result<()> {
        self.gl()?.multi_draw_arrays_instanced(
            mode,
            DrawList::new(firsts, firsts_offset),
            DrawList::new(counts, counts_offset),
            DrawList::new(instance_counts, instance_counts_offset),
            drawcount,
        );
        Ok(())
    }

    /// `multiDrawElementsWEBGL`.
    #[allow(clippy::too_many_arguments)]
    #[napi(catch_unwind)]
    pub fn multi_draw_elements(
        &mut self,
        mode: u32,
        counts: &[i32],
        counts_offset: u32,
        ty: u32,
        offsets: &[i32],
        offsets_offset: u32,
        drawcount: i32,
    ) -> napi::Result<()> {
        self.gl()?.multi_draw_elements(
            mode,
            DrawList::new(counts, counts_offset),
            ty,
            DrawList::new(offsets, offsets_offset),
            drawcount,
        );
        Ok(())
    }

    /// `multiDrawElementsInstancedWEBGL` (the IDL's nine arguments).
    #[allow(clippy::too_many_arguments)]
    #[napi(catch_unwind)]
    pub fn multi_draw_elements_instanced(
        &mut self,
        mode: u32,
        counts: &[i32],
        counts_offset: u32,
        ty: u32,
        offsets: &[i32],
        offsets_offset: u32,
        instance_counts: &[i32],
        instance_counts_offset: u32,
        drawcount: i32,
    ) -> napi::Result<()> {
        self.gl()?.multi_draw_elements_instanced(
            mode,
            DrawList::new(counts, counts_offset),
            ty,
            DrawList::new(offsets, offsets_offset),
            DrawList::new(instance_counts, instance_counts_offset),
            drawcount,
        );
        Ok(())
    }
}
