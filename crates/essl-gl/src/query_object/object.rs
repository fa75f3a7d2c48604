//! A query object's state: its target, what its last begin/end pair measured, and the result
//! once read.

use crate::frame::OcclusionCounts;

/// What a query measured at its last `end_query`.
pub(crate) enum Measure {
    /// The samples each render pass counted.
    Samples(OcclusionCounts),
    /// Transform feedback primitives.
    Primitives(u64),
}

/// A query object.
#[derive(Default)]
pub(crate) struct QueryObject {
    /// The target of its first `begin_query`; fixed from then on.
    pub(crate) target: Option<u32>,
    /// What the last begin/end pair measured, and the
    /// [`Context::present`](crate::Context::present) count at its end.
    pub(crate) ended: Option<(Measure, u64)>,
    /// The result, once read.
    pub(crate) result: Option<u64>,
    /// Primitives written while active (transform feedback).
    pub(crate) primitives: u64,
}
