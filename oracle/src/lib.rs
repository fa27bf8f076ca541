//! # polytri-oracle
//!
//! The harness half of polytri: it judges triangulations independently of the code under
//! test, generates random valid polygons with holes, and runs other triangulators on the
//! same inputs.
//!
//! Its first use outside the harness is [`verify`]: give it any program's triangulation of
//! a polygon with holes, and it says whether it is one — every triangle inside, none
//! overlapping, every boundary edge used once — naming the triangle or edge that fails.
//!
//! - [`input`]: what is triangulated — rings, ring starts and the nesting convention.
//! - `check`: the verdict on a triangulation (exact validity, geo's area and containment,
//!   spade's constrained Delaunay triangulation, quality metrics).
//! - `exact`: the oracle's exact predicates (orientation, points on and crossings of
//!   segments), public for tests that need geometry beside a verdict.
//! - `gen`: seeded generators of valid nested polygons, one per named family.
//! - `strategy`: proptest strategies over the generators, shrinking to smaller valid inputs.
//! - `peers`: earcut, earcutr, i_triangle, lyon and spade on the same inputs, and earcut
//!   with exact predicates as a reference.
//! - `shrink`: a failing case made small, staying valid (ring runs, then vertex runs).
//! - `campaign`: every family × strategy × precision through the oracle, failures shrunk
//!   and written as corpus cases (`polytri campaign`).
//! - `precision`: where `f32` and `f64` triangulations stay valid, over scales, offsets and
//!   feature sizes (`polytri precision`).
//! - `fuzz`: the bodies of the cargo-fuzz targets, so stable tests can replay their corpus.
//! - `replay`: the regression corpus through polytri in every strategy, precision and
//!   rotation, judged here (`oracle/tests/corpus.rs`'s snapshots, `polytri replay`).
//! - [`series`]: generated inputs from 10³ to 10⁶ vertices for the scaling benchmarks
//!   (`cargo bench`, `polytri bench --scaling`).
//!
//! Nothing here shares predicates with `polytri`: the oracle has its own exact arithmetic
//! (`exact`, after Shewchuk). It shares one formula, earcut's deviation
//! ([`polytri::deviation`]), a measure reported beside the verdict.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod campaign;
mod cdt;
pub mod check;
pub mod exact;
pub mod fuzz;
pub mod gen;
mod grid;
pub mod input;
mod metrics;
pub mod peers;
pub mod precision;
pub mod replay;
pub mod series;
pub mod shrink;
pub mod strategy;
pub mod threaded;

pub use check::{
    check, check_fill, check_with, fill_area, fill_area_float, verify, verify_fill, CdtComparison,
    Check, CheckOptions, FillArea, Verdict,
};

/// The item of `all` whose `name` is `s` (trimmed, any case) — the `FromStr` of the
/// harness's named enums; the error lists the known names after `"unknown {what}"`.
pub(crate) fn by_name<T: Copy>(
    s: &str,
    all: &[T],
    name: impl Fn(T) -> &'static str,
    what: &str,
) -> Result<T, String> {
    let wanted = s.trim();
    all.iter()
        .copied()
        .find(|&item| name(item).eq_ignore_ascii_case(wanted))
        .ok_or_else(|| {
            let names: Vec<_> = all.iter().map(|&item| name(item)).collect();
            format!("unknown {what} '{s}' (known: {})", names.join(", "))
        })
}
pub use gen::{generate, Case, Family, Params};
pub use input::{Grouping, Input, Nesting, Role};
