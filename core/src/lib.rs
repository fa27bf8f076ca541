//! # polytri
//!
//! Triangulates polygons with any number of holes, and islands inside holes, by ear
//! clipping with hole bridging after Kotsarenko (2024), *Simple yet robust triangulation for
//! polygons containing multiple holes*. Every geometric decision is made with exact
//! predicates, so a valid input always gives a valid triangulation — or an [`Error`] that
//! says what is wrong and where.
//!
//! ```
//! # fn main() -> Result<(), polytri::Error> {
//! // A square with a square hole; rings in any winding order.
//! let vertices: Vec<[f64; 2]> = vec![
//!     [0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0], // outer
//!     [3.0, 3.0], [3.0, 7.0], [7.0, 7.0], [7.0, 3.0],     // hole
//! ];
//! let ring_starts = [0, 4];
//!
//! let mut tri = polytri::Triangulator::<f64>::new();
//! let mut out: Vec<[u32; 3]> = Vec::new();
//! let report = tri.triangulate(&vertices, &ring_starts, &polytri::Options::default(), &mut out)?;
//! assert_eq!(out.len(), 8); // n - 2 + 2h = 8 - 2 + 2
//! assert_eq!(report.holes, 1);
//! # Ok(())
//! # }
//! ```
//!
//! The pipeline, one module per stage: `load` → `clean` (and, lenient, `lobes`) → `nest` (and `touch`) → `bridge` →
//! `clip`.
//! See `ARCHITECTURE.md` in the repository for the layers and the invariants of each stage.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod context;
mod crossings;
mod error;
#[cfg(feature = "geo-types")]
pub mod geo;
mod geom;
mod options;
mod planar;
mod report;
mod stages;
mod structures;
#[cfg(test)]
mod testing;
mod triangulator;

pub use error::Error;
pub use geom::Coord;
pub use options::{FillRule, Nesting, Options, Strategy};
pub use planar::{Projection, PLANAR_TOLERANCE};
pub use report::{deviation, Added, DropReason, Dropped, Repair, RepairKind, Report};
pub use triangulator::Triangulator;
