//! Renderbuffers, framebuffers, blits and `readPixels`.

use essl_gl::{Framebuffer, Renderbuffer};
use napi_derive::napi;

use crate::answer::Answer;
use crate::context::NativeContext;
use crate::registry::Handle;
use crate::view::View;

#[napi]
impl NativeContext {
    /// `createRenderbuffer`.
    #[napi(catch_unwind)]
    pub fn create_renderbuffer(&mut self) -> napi::Result<u32> {
        let r = self.gl()?.create_renderbuffer();
        Ok(self.register(Handle::Renderbuffer(r)))
    }

    /// `isRenderbuffer`.
    #[napi(catch_unwind)]
    pub fn is_renderbuffer(&mut self, renderbuffer: u32) -> napi::Result<bool> {
        let r = self
            .arg::<Renderbuffer>(renderbuffer, "isRenderbuffer")
            .flatten();
        Ok(r.is_some_and(|r| self.ctx.as_ref().is_some_and(|c| c.is_renderbuffer(r))))
    }

    /// `deleteRenderbuffer`.
    #[napi(catch_unwind)]
    pub fn delete_renderbuffer(&mut self, renderbuffer: u32) -> napi::Result<()> {
        if let Some(r) = self
            .arg::<Renderbuffer>(renderbuffer, "deleteRenderbuffer")
            .flatten()
        {
            self.gl()?.delete_renderbuffer(r);
        }
        Ok(())
    }

    /// `bindRenderbuffer`.
    #[napi(catch_unwind)]
    pub fn bind_renderbuffer(&mut self, target: u32, renderbuffer: u32) -> napi::Result<()> {
        if let Some(r) = self.arg(renderbuffer, "bindRenderbuffer") {
            self.gl()?.bind_renderbuffer(target, r);
        }
        Ok(())
    }

    /// `renderbufferStorage`.
    #[napi(catch_unwind)]
    pub fn renderbuffer_storage(
        &mut self,
        target: u32,
        format: u32,
        width: i32,
        height: i32,
    ) -> napi::Result<()> {
        self.gl()?
            .renderbuffer_storage(target, format, width, height);
        Ok(())
    }

    /// `renderbufferStorageMultisample`.
    #[napi(catch_unwind)]
    pub fn renderbuffer_storage_multisample(
        &mut self,
        target: u32,
        samples: i32,
        format: u32,
        width: i32,
        height: i32,
    ) -> napi::Result<()> {
        self.gl()?
            .renderbuffer_storage_multisample(target, samples, format, width, height);
        Ok(())
    }

    /// `getRenderbufferParameter`.
    #[napi(catch_unwind)]
    pub fn get_renderbuffer_parameter(&mut self, target: u32, pname: u32) -> napi::Result<Answer> {
        Ok(self.gl()?.get_renderbuffer_parameter(target, pname).into())
    }

    /// `getInternalformatParameter`.
    #[napi(catch_unwind)]
    pub fn get_internalformat_parameter(
        &mut self,
        target: u32,
        format: u32,
        pname: u32,
    ) -> napi::Result<Answer> {
        Ok(self
            .gl()?
            .get_internalformat_parameter(target, format, pname)
            .into())
    }

    /// `createFramebuffer`.
    #[napi(catch_unwind)]
    pub fn create_framebuffer(&mut self) -> napi::Result<u32> {
        let f = self.gl()?.create_framebuffer();
        Ok(self.register(Handle::Framebuffer(f)))
    }

    /// `isFramebuffer`.
    #[napi(catch_unwind)]
    pub fn is_framebuffer(&mut self, framebuffer: u32) -> napi::Result<bool> {
        let f = self
            .arg::<Framebuffer>(framebuffer, "isFramebuffer")
            .flatten();
        Ok(f.is_some_and(|f| self.ctx.as_ref().is_some_and(|c| c.is_framebuffer(f))))
    }

    /// `deleteFramebuffer`.
    #[napi(catch_unwind)]
    pub fn delete_framebuffer(&mut self, framebuffer: u32) -> napi::Result<()> {
        if let Some(f) = self
            .arg::<Framebuffer>(framebuffer, "deleteFramebuffer")
            .flatten()
        {
            self.gl()?.delete_framebuffer(f);
        }
        Ok(())
    }

    /// `bindFramebuffer`.
    #[napi(catch_unwind)]
    pub fn bind_framebuffer(&mut self, target: u32, framebuffer: u32) -> napi::Result<()> {
        if let Some(f) = self.arg(framebuffer, "bindFramebuffer") {
            self.gl()?.bind_framebuffer(target, f);
        }
        Ok(())
    }

    /// `framebufferTexture2D`.
    #[napi(js_name = "framebufferTexture2D", catch_unwind)]
    pub fn framebuffer_texture_2d(
        &mut self,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: u32,
        level: i32,
    ) -> napi::Result<()> {
        if let Some(t) = self.arg(texture, "framebufferTexture2D") {
            self.gl()?
                .framebuffer_texture_2d(target, attachment, textarget, t, level);
        }
        Ok(())
    }

    /// `framebufferTextureLayer`.
    #[napi(catch_unwind)]
    pub fn framebuffer_texture_layer(
        &mut self,
        target: u32,
        attachment: u32,
        texture: u32,
        level: i32,
        layer: i32,
    ) -> napi::Result<()> {
        if let Some(t) = self.arg(texture, "framebufferTextureLayer") {
            self.gl()?
                .framebuffer_texture_layer(target, attachment, t, level, layer);
        }
        Ok(())
    }

    /// `framebufferRenderbuffer`.
    #[napi(catch_unwind)]
    pub fn framebuffer_renderbuffer(
        &mut self,
        target: u32,
        attachment: u32,
        rb_target: u32,
        renderbuffer: u32,
    ) -> napi::Result<()> {
        if let Some(r) = self.arg(renderbuffer, "framebufferRenderbuffer") {
            self.gl()?
                .framebuffer_renderbuffer(target, attachment, rb_target, r);
        }
        Ok(())
    }

    /// `checkFramebufferStatus`.
    #[napi(catch_unwind)]
    pub fn check_framebuffer_status(&mut self, target: u32) -> napi::Result<u32> {
        Ok(self.gl()?.check_framebuffer_status(target))
    }

    /// `getFramebufferAttachmentParameter`.
    #[napi(catch_unwind)]
    pub fn get_framebuffer_attachment_parameter(
        &mut self,
        target: u32,
        attachment: u32,
        pname: u32,
    ) -> napi::Result<Answer> {
        Ok(self
            .gl()?
            .get_framebuffer_attachment_parameter(target, attachment, pname)
            .into())
    }

    /// `drawBuffers`.
    #[napi(catch_unwind)]
    pub fn draw_buffers(&mut self, buffers: &[u32]) -> napi::Result<()> {
        self.gl()?.draw_buffers(buffers);
        Ok(())
    }

    /// `readBuffer`.
    #[napi(catch_unwind)]
    pub fn read_buffer(&mut self, src: u32) -> napi::Result<()> {
        self.gl()?.read_buffer(src);
        Ok(())
    }

    /// `invalidateFramebuffer`.
    #[napi(catch_unwind)]
    pub fn invalidate_framebuffer(&mut self, target: u32, attachments: &[u32]) -> napi::Result<()> {
        self.gl()?.invalidate_framebuffer(target, attachments);
        Ok(())
    }

    /// `invalidateSubFramebuffer`.
    #[napi(catch_unwind)]
    pub fn invalidate_sub_framebuffer(
        &mut self,
        target: u32,
        attachments: &[u32],
        x: i32,
        y: i32,
        width: i32,
        height: i32,
    ) -> napi::Result<()> {
        self.gl()?
            .invalidate_sub_framebuffer(target, attachments, x, y, width, height);
        Ok(())
    }

    /// `blitFramebuffer`.
    #[napi(catch_unwind)]
    #[allow(clippy::too_many_arguments)] // WebGL's own argument list
    pub fn blit_framebuffer(
        &mut self,
        src_x0: i32,
        src_y0: i32,
        src_x1: i32,
        src_y1: i32,
        dst_x0: i32,
        dst_y0: i32,
        dst_x1: i32,
        dst_y1: i32,
        mask: u32,
        filter: u32,
    ) -> napi::Result<()> {
        self.gl()?.blit_framebuffer(
            src_x0, src_y0, src_x1, src_y1, dst_x0, dst_y0, dst_x1, dst_y1, mask, filter,
        );
        Ok(())
    }

    /// `readPixels` into an `ArrayBufferView` from element `offset` (`dstOffset`).
    #[napi(catch_unwind)]
    #[allow(clippy::too_many_arguments)] // WebGL's own argument list
    pub fn read_pixels(
        &mut self,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        mut dst: View,
        offset: u32,
    ) -> napi::Result<()> {
        let Some(w) = dst.window_mut(offset, 0) else {
            self.past_end("readPixels");
            return Ok(());
        };
        if let Some(c) = self.ctx.as_mut() {
            c.read_pixels_view(x, y, width, height, format, ty, w);
        }
        Ok(())
    }

    /// `readPixels` into the bound `PIXEL_PACK_BUFFER` at byte `offset`.
    #[napi(catch_unwind)]
    #[allow(clippy::too_many_arguments)] // WebGL's own argument list
    pub fn read_pixels_to_buffer(
        &mut self,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        offset: i64,
    ) -> napi::Result<()> {
        self.gl()?
            .read_pixels_to_buffer(x, y, width, height, format, ty, offset);
        Ok(())
    }
}
