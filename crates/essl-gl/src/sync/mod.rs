//! Sync objects: `fence_sync`, `client_wait_sync`, `wait_sync`, `get_sync_parameter`,
//! `delete_sync`, `is_sync`.
//!
//! A fence is signalled when the GPU has executed everything recorded before it. As WebGL
//! requires, its status changes only after control returns to the caller's event loop, which
//! [`Context::present`] stands for, and `client_wait_sync` never blocks (WebGL's
//! `MAX_CLIENT_WAIT_TIMEOUT_WEBGL` is 0 here): it answers `ALREADY_SIGNALED` or
//! `TIMEOUT_EXPIRED`. A fence's state is [`object`]'s.

mod object;

pub(crate) use object::SyncObject;

use crate::context::Context;
use crate::gl;
use crate::objects::{Id, Sync};
use crate::query::Parameter;

impl Context {
    /// Inserts a fence after everything recorded so far (`fenceSync`): `condition` must be
    /// `SYNC_GPU_COMMANDS_COMPLETE` (`INVALID_ENUM`) and `flags` 0 (`INVALID_VALUE`).
    pub fn fence_sync(&mut self, condition: u32, flags: u32) -> Option<Sync> {
        const F: &str = "fenceSync";
        if condition != gl::SYNC_GPU_COMMANDS_COMPLETE {
            self.error(
                gl::INVALID_ENUM,
                F,
                format_args!("condition 0x{condition:04X}"),
            );
            return None;
        }
        if flags != 0 {
            self.error(gl::INVALID_VALUE, F, "flags must be 0");
            return None;
        }
        self.flush();
        let id = self.objects.syncs.insert(SyncObject::new(self.presents));
        Some(Sync { ctx: self.id, id })
    }

    /// Whether `sync` names a live sync object (`isSync`).
    pub fn is_sync(&self, sync: Sync) -> bool {
        sync.ctx == self.id && self.objects.syncs.is_live(sync.id)
    }

    /// Deletes a sync object (`deleteSync`).
    pub fn delete_sync(&mut self, sync: Sync) {
        if self.owns(sync.ctx, "deleteSync") {
            self.objects.delete_sync(sync.id);
        }
    }

    fn sync_id(&mut self, sync: Sync, function: &str) -> Option<Id> {
        if !self.owns(sync.ctx, function) {
            return None;
        }
        if !self.objects.syncs.is_live(sync.id) {
            self.error(gl::INVALID_OPERATION, function, "deleted sync object");
            return None;
        }
        Some(sync.id)
    }

    fn signalled(&self, id: Id) -> bool {
        self.objects
            .syncs
            .get(id)
            .is_some_and(|s| s.signalled(self.presents))
    }

    /// Whether the fence is signalled, without blocking (`clientWaitSync`): `flags` may only
    /// be `SYNC_FLUSH_COMMANDS_BIT` (`INVALID_VALUE`), `timeout` must not exceed
    /// `MAX_CLIENT_WAIT_TIMEOUT_WEBGL`, which is 0 (`INVALID_OPERATION`). Answers
    /// `ALREADY_SIGNALED` or `TIMEOUT_EXPIRED` (`WAIT_FAILED` after an error).
    pub fn client_wait_sync(&mut self, sync: Sync, flags: u32, timeout: u64) -> u32 {
        const F: &str = "clientWaitSync";
        let Some(id) = self.sync_id(sync, F) else {
            return gl::WAIT_FAILED;
        };
        if flags & !gl::SYNC_FLUSH_COMMANDS_BIT != 0 {
            self.error(gl::INVALID_VALUE, F, "flags");
            return gl::WAIT_FAILED;
        }
        if timeout > 0 {
            self.error(
                gl::INVALID_OPERATION,
                F,
                "timeout above MAX_CLIENT_WAIT_TIMEOUT_WEBGL (0)",
            );
            return gl::WAIT_FAILED;
        }
        if flags & gl::SYNC_FLUSH_COMMANDS_BIT != 0 {
            self.flush();
        }
        if self.signalled(id) {
            gl::ALREADY_SIGNALED
        } else {
            gl::TIMEOUT_EXPIRED
        }
    }

    /// Makes the GPU wait for the fence (`waitSync`): a no-op, since essl-gl's commands run
    /// in order on one queue. `flags` must be 0 and `timeout` `TIMEOUT_IGNORED`
    /// (`INVALID_VALUE`).
    pub fn wait_sync(&mut self, sync: Sync, flags: u32, timeout: i64) {
        const F: &str = "waitSync";
        if self.sync_id(sync, F).is_none() {
            return;
        }
        if flags != 0 || timeout != gl::TIMEOUT_IGNORED {
            self.error(
                gl::INVALID_VALUE,
                F,
                "flags must be 0 and timeout TIMEOUT_IGNORED",
            );
        }
    }

    /// A sync object's parameter (`getSyncParameter`): `OBJECT_TYPE` (`SYNC_FENCE`),
    /// `SYNC_STATUS` (`SIGNALED` or `UNSIGNALED`), `SYNC_CONDITION`, `SYNC_FLAGS`.
    pub fn get_sync_parameter(&mut self, sync: Sync, pname: u32) -> Option<Parameter> {
        const F: &str = "getSyncParameter";
        let id = self.sync_id(sync, F)?;
        Some(match pname {
            gl::OBJECT_TYPE => Parameter::Enum(gl::SYNC_FENCE),
            gl::SYNC_STATUS => Parameter::Enum(if self.signalled(id) {
                gl::SIGNALED
            } else {
                gl::UNSIGNALED
            }),
            gl::SYNC_CONDITION => Parameter::Enum(gl::SYNC_GPU_COMMANDS_COMPLETE),
            gl::SYNC_FLAGS => Parameter::Int(0),
            _ => {
                self.error(gl::INVALID_ENUM, F, format_args!("pname 0x{pname:04X}"));
                return None;
            }
        })
    }
}
