//! WebGL2's rules for `blit_framebuffer`, checked before anything is drawn.

use super::{kind_of, BlitPlan, Corners};
use crate::context::Context;
use crate::framebuffer::{DrawImages, ReadSurface, SurfaceImage};
use crate::gl;
use crate::pipeline::ClearKind;
use crate::texture::{bit_sizes, InternalFormat};

/// Whether two images are the same subresource.
fn same_image(a: &SurfaceImage, b: &SurfaceImage) -> bool {
    a.texture == b.texture && a.mip == b.mip && a.layer == b.layer
}

impl Context {
    /// The blit's plan, or the WebGL error it makes (recorded).
    #[allow(clippy::too_many_arguments)] // the blit's arguments, already taken apart
    pub(super) fn check_blit(
        &mut self,
        read: &ReadSurface,
        draw: &DrawImages,
        src: Corners,
        dst: Corners,
        mask: u32,
        linear: bool,
        f: &str,
    ) -> Option<BlitPlan> {
        let fail = |ctx: &mut Context, why: &str| -> Option<BlitPlan> {
            ctx.error(gl::INVALID_OPERATION, f, why);
            None
        };
        let draw_samples = draw
            .colors
            .iter()
            .flatten()
            .chain(&draw.depth)
            .chain(&draw.stencil)
            .map(|i| i.samples)
            .max()
            .unwrap_or(1);
        let default_draw = self.bindings.framebuffers()[0].is_none();
        if draw_samples > 1 || (default_draw && self.fb.attributes.antialias) {
            return fail(self, "the draw framebuffer is multisampled");
        }
        let read_samples = if read.default && self.fb.attributes.antialias {
            4
        } else {
            [&read.color, &read.depth, &read.stencil]
                .into_iter()
                .flatten()
                .map(|i| i.samples)
                .max()
                .unwrap_or(1)
        };
        let [sx0, sy0, sx1, sy1] = src.0;
        let [dx0, dy0, dx1, dy1] = dst.0;
        if read_samples > 1 && [sx0, sy0, sx1, sy1] != [dx0, dy0, dx1, dy1] {
            return fail(
                self,
                "a multisampled read framebuffer needs the same rectangle in both",
            );
        }
        let mut plan = BlitPlan {
            color: None,
            draw_colors: Vec::new(),
            depth: None,
            stencil: None,
        };
        if mask & gl::COLOR_BUFFER_BIT != 0 {
            if let Some(from) = &read.color {
                let kind = kind_of(from);
                if linear && kind != ClearKind::Float {
                    return fail(self, "integer colour can only be blitted with NEAREST");
                }
                for to in draw.colors.iter().flatten() {
                    if kind_of(to) != kind {
                        return fail(
                            self,
                            "the read and draw buffers' formats are of other kinds",
                        );
                    }
                    if read_samples > 1 && !same_format(&from.format, &to.format) {
                        return fail(self, "a resolve needs the same format");
                    }
                    if same_image(from, to) {
                        return fail(self, "the same image is read and drawn");
                    }
                }
                plan.color = Some(from.clone());
                plan.draw_colors = draw.colors.clone();
            }
        }
        for (bit, from, to) in [
            (gl::DEPTH_BUFFER_BIT, &read.depth, &draw.depth),
            (gl::STENCIL_BUFFER_BIT, &read.stencil, &draw.stencil),
        ] {
            if mask & bit == 0 {
                continue;
            }
            let (Some(from), Some(to)) = (from, to) else {
                continue;
            };
            if from.format.gpu_format() != to.format.gpu_format() {
                return fail(self, "the depth or stencil formats differ");
            }
            if same_image(from, to) {
                return fail(self, "the same image is read and drawn");
            }
            let pair = Some((from.clone(), to.clone()));
            if bit == gl::DEPTH_BUFFER_BIT {
                plan.depth = pair;
            } else {
                plan.stencil = pair;
            }
        }
        Some(plan)
    }
}

/// Whether two formats are the same for a resolve (ES 3.0 §4.3.3: "identical"): the same
/// base format, bit sizes, component type and encoding, whatever the GPU stores them in.
fn same_format(a: &InternalFormat, b: &InternalFormat) -> bool {
    a.gpu_format() == b.gpu_format()
        && a.base == b.base
        && a.srgb == b.srgb
        && bit_sizes(a) == bit_sizes(b)
}
