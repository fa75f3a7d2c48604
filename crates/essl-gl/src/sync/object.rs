//! A fence sync object's state.

/// A fence sync object.
pub(crate) struct SyncObject {
    /// The [`Context::present`](crate::Context::present) count when it was made: it is
    /// signalled after the next.
    made_at: u64,
}

impl SyncObject {
    /// A fence made when `presents` presents had run.
    pub(crate) fn new(presents: u64) -> Self {
        SyncObject { made_at: presents }
    }

    /// Whether the fence is signalled once `presents` presents have run: after the first
    /// present that follows it, as WebGL has control return to the event loop first.
    pub(crate) fn signalled(&self, presents: u64) -> bool {
        presents > self.made_at
    }
}
