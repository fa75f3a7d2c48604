//! Transform feedback, query and sync objects, and indexed parameters.

use essl_gl::{Query, Sync, TransformFeedback};
use napi_derive::napi;

use crate::answer::Answer;
use crate::context::NativeContext;
use crate::registry::Handle;

#[napi]
impl NativeContext {
    /// `createTransformFeedback`.
    #[napi(catch_unwind)]
    pub fn create_transform_feedback(&mut self) -> napi::Result<u32> {
        let t = self.gl()?.create_transform_feedback();
        Ok(self.register(Handle::TransformFeedback(t)))
    }

    /// `isTransformFeedback`.
    #[napi(catch_unwind)]
    pub fn is_transform_feedback(&mut self, tf: u32) -> napi::Result<bool> {
        let t = self
            .arg::<TransformFeedback>(tf, "isTransformFeedback")
            .flatten();
        Ok(t.is_some_and(|t| {
            self.ctx
                .as_ref()
                .is_some_and(|c| c.is_transform_feedback(t))
        }))
    }

    /// `deleteTransformFeedback`.
    #[napi(catch_unwind)]
    pub fn delete_transform_feedback(&mut self, tf: u32) -> napi::Result<()> {
        if let Some(t) = self
            .arg::<TransformFeedback>(tf, "deleteTransformFeedback")
            .flatten()
        {
            self.gl()?.delete_transform_feedback(t);
        }
        Ok(())
    }

    /// `bindTransformFeedback`.
    #[napi(catch_unwind)]
    pub fn bind_transform_feedback(&mut self, target: u32, tf: u32) -> napi::Result<()> {
        if let Some(t) = self.arg(tf, "bindTransformFeedback") {
            self.gl()?.bind_transform_feedback(target, t);
        }
        Ok(())
    }

    /// `beginTransformFeedback`.
    #[napi(catch_unwind)]
    pub fn begin_transform_feedback(&mut self, mode: u32) -> napi::Result<()> {
        self.gl()?.begin_transform_feedback(mode);
        Ok(())
    }

    /// `endTransformFeedback`.
    #[napi(catch_unwind)]
    pub fn end_transform_feedback(&mut self) -> napi::Result<()> {
        self.gl()?.end_transform_feedback();
        Ok(())
    }

    /// `pauseTransformFeedback`.
    #[napi(catch_unwind)]
    pub fn pause_transform_feedback(&mut self) -> napi::Result<()> {
        self.gl()?.pause_transform_feedback();
        Ok(())
    }

    /// `resumeTransformFeedback`.
    #[napi(catch_unwind)]
    pub fn resume_transform_feedback(&mut self) -> napi::Result<()> {
        self.gl()?.resume_transform_feedback();
        Ok(())
    }

    /// `transformFeedbackVaryings`.
    #[napi(catch_unwind)]
    pub fn transform_feedback_varyings(
        &mut self,
        program: u32,
        varyings: Vec<String>,
        mode: u32,
    ) -> napi::Result<()> {
        if let Some(p) = self.req(program, "transformFeedbackVaryings") {
            let names: Vec<&str> = varyings.iter().map(String::as_str).collect();
            self.gl()?.transform_feedback_varyings(p, &names, mode);
        }
        Ok(())
    }

    /// `getTransformFeedbackVarying`.
    #[napi(catch_unwind)]
    pub fn get_transform_feedback_varying(
        &mut self,
        program: u32,
        index: u32,
    ) -> napi::Result<Answer> {
        let Some(p) = self.req(program, "getTransformFeedbackVarying") else {
            return Ok(Answer::Null);
        };
        let info = self.gl()?.get_transform_feedback_varying(p, index);
        Ok(info.map_or(Answer::Null, Answer::ActiveInfo))
    }

    /// `getIndexedParameter`.
    #[napi(catch_unwind)]
    pub fn get_indexed_parameter(&mut self, target: u32, index: u32) -> napi::Result<Answer> {
        Ok(self.gl()?.get_indexed_parameter(target, index).into())
    }

    /// `createQuery`.
    #[napi(catch_unwind)]
    pub fn create_query(&mut self) -> napi::Result<u32> {
        let q = self.gl()?.create_query();
        Ok(self.register(Handle::Query(q)))
    }

    /// `isQuery`.
    #[napi(catch_unwind)]
    pub fn is_query(&mut self, query: u32) -> napi::Result<bool> {
        let q = self.arg::<Query>(query, "isQuery").flatten();
        Ok(q.is_some_and(|q| self.ctx.as_ref().is_some_and(|c| c.is_query(q))))
    }

    /// `deleteQuery`.
    #[napi(catch_unwind)]
    pub fn delete_query(&mut self, query: u32) -> napi::Result<()> {
        if let Some(q) = self.arg::<Query>(query, "deleteQuery").flatten() {
            self.gl()?.delete_query(q);
        }
        Ok(())
    }

    /// `beginQuery`.
    #[napi(catch_unwind)]
    pub fn begin_query(&mut self, target: u32, query: u32) -> napi::Result<()> {
        if let Some(q) = self.req(query, "beginQuery") {
            self.gl()?.begin_query(target, q);
        }
        Ok(())
    }

    /// `endQuery`.
    #[napi(catch_unwind)]
    pub fn end_query(&mut self, target: u32) -> napi::Result<()> {
        self.gl()?.end_query(target);
        Ok(())
    }

    /// `getQuery`.
    #[napi(catch_unwind)]
    pub fn get_query(&mut self, target: u32, pname: u32) -> napi::Result<Answer> {
        let q = self.gl()?.get_query(target, pname);
        Ok(Answer::object(q.map(Handle::Query)))
    }

    /// `getQueryParameter`.
    #[napi(catch_unwind)]
    pub fn get_query_parameter(&mut self, query: u32, pname: u32) -> napi::Result<Answer> {
        let Some(q) = self.req(query, "getQueryParameter") else {
            return Ok(Answer::Null);
        };
        Ok(self.gl()?.get_query_parameter(q, pname).into())
    }

    /// `fenceSync`: the id, or 0.
    #[napi(catch_unwind)]
    pub fn fence_sync(&mut self, condition: u32, flags: u32) -> napi::Result<u32> {
        Ok(match self.gl()?.fence_sync(condition, flags) {
            Some(s) => self.register(Handle::Sync(s)),
            None => 0,
        })
    }

    /// `isSync`.
    #[napi(catch_unwind)]
    pub fn is_sync(&mut self, sync: u32) -> napi::Result<bool> {
        let s = self.arg::<Sync>(sync, "isSync").flatten();
        Ok(s.is_some_and(|s| self.ctx.as_ref().is_some_and(|c| c.is_sync(s))))
    }

    /// `deleteSync`.
    #[napi(catch_unwind)]
    pub fn delete_sync(&mut self, sync: u32) -> napi::Result<()> {
        if let Some(s) = self.arg::<Sync>(sync, "deleteSync").flatten() {
            self.gl()?.delete_sync(s);
        }
        Ok(())
    }

    /// `clientWaitSync`.
    #[napi(catch_unwind)]
    pub fn client_wait_sync(&mut self, sync: u32, flags: u32, timeout: f64) -> napi::Result<u32> {
        let Some(s) = self.req(sync, "clientWaitSync") else {
            return Ok(essl_gl::gl::WAIT_FAILED);
        };
        Ok(self.gl()?.client_wait_sync(s, flags, timeout as u64))
    }

    /// `waitSync`.
    #[napi(catch_unwind)]
    pub fn wait_sync(&mut self, sync: u32, flags: u32, timeout: f64) -> napi::Result<()> {
        if let Some(s) = self.req(sync, "waitSync") {
            self.gl()?.wait_sync(s, flags, timeout as i64);
        }
        Ok(())
    }

    /// `getSyncParameter`.
    #[napi(catch_unwind)]
    pub fn get_sync_parameter(&mut self, sync: u32, pname: u32) -> napi::Result<Answer> {
        let Some(s) = self.req(sync, "getSyncParameter") else {
            return Ok(Answer::Null);
        };
        Ok(self.gl()?.get_sync_parameter(s, pname).into())
    }
}
