//! Layer 1, geometry: the exact predicates and the tests built on them. Every geometric
//! decision in the crate is made here; nothing else computes a determinant
//! ([`predicates::orient2d`] is the one orientation).

mod coord;
mod corners;
mod ears;
mod exact;
mod predicates;
mod segments;

pub use coord::Coord;
pub(crate) use corners::{
    bundle_end, clockwise_before, corner_contains, inside_along, on_ray, pair_alternating,
    LeastAngle, RightmostVisit,
};
pub(crate) use ears::{bounds, interferes, near};
pub(crate) use exact::{in_range, SnapGrid};
pub(crate) use predicates::*;
pub(crate) use segments::{
    boxed_segments_meet, compare_hits, crosses, overlaps, ray_crossing, segments_meet,
};
