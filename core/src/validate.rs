//! The input check: a plane sweep over all edges (Shamos–Hoey), O(n log n).
//! STUB — being implemented.

use crate::pool::{NodeId, Pool};

/// Node `vertex` lies in the relative interior of the edge `edge → next(edge)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Touch {
    pub vertex: NodeId,
    pub edge: NodeId,
}

/// The edges `a → next(a)` and `b → next(b)` cross at a point interior to both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Crossing {
    pub a: NodeId,
    pub b: NodeId,
}

/// Reusable buffers of the sweep. After [`sweep`], `order` holds every node of the swept
/// rings sorted by position (x, then y), ties by node id.
#[derive(Debug, Default)]
pub(crate) struct SweepScratch {
    pub order: Vec<NodeId>,
}

/// Sweeps the edges of the rings through `starts`.
pub(crate) fn sweep(
    pool: &Pool,
    starts: &[NodeId],
    scratch: &mut SweepScratch,
    stop_at_first_crossing: bool,
    touches: &mut Vec<Touch>,
    crossings: &mut Vec<Crossing>,
) {
    let _ = (pool, starts, scratch, stop_at_first_crossing, touches, crossings);
}
