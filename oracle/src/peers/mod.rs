//! Other triangulators on the same inputs: earcut, earcutr, i_triangle, lyon and spade —
//! and two references, which are no competitors ([`Peer::REFERENCES`]): earcut with exact
//! predicates, and its baseline, the same copy of earcut's code with earcut's own
//! predicates; together they show what exactness costs earcut's own code.
//!
//! Two faces:
//!
//! - [`triangulate`] and [`triangulate_f32`] run one peer once and return its triangles as
//!   indices into the input (or into the peer's own vertices, where it made new ones), for
//!   the oracles and for comparisons. They never panic: peers that may (spade on crossing
//!   constraints, i_triangle on coordinates its integer grid cannot hold, earcut on
//!   malformed rings) run under `catch_unwind`.
//! - [`Runner`] keeps every implementation's reusable state (earcut's buffers, polytri's
//!   `Triangulator`, lyon's tessellator) and runs any of them on a [`Prepared`] input, so
//!   benchmarks time the triangulation alone and not the conversion into each library's
//!   input format.
//!
//! Input conventions: earcut (and the references) and earcutr take one polygon at a time,
//! outer ring first —
//! they get the input's polygons ([`polygons`]), grouped by containment when the input
//! says [`Nesting::Auto`](crate::Nesting::Auto). i_triangle and lyon take every ring at once
//! with the even-odd fill rule, spade takes every ring as a constraint and keeps the faces
//! at odd depth: for properly nested rings all three mean the same as polytri's nesting.
//!
//! ```
//! use polytri_oracle::peers::{self, Peer};
//! use polytri_oracle::{Input, Nesting};
//!
//! let square = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
//! let input = Input::from_rings(&[square], Nesting::FirstIsOuter);
//! for peer in Peer::ALL.into_iter().chain(Peer::REFERENCES) {
//!     let out = peers::triangulate(peer, &input).expect("a square is easy");
//!     assert_eq!(out.triangles.len(), 2, "{peer}");
//! }
//! ```

use std::fmt;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::str::FromStr;

use crate::input::Input;

mod earcut;
mod earcut_exact;
mod floor;
pub(crate) mod group;
mod i_triangle;
mod lyon;
mod runner;
mod spade;

pub use group::{polygons, Polygon};
pub use runner::{Implementation, Prepared, Runner};

/// A triangulator other than polytri.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Peer {
    /// `earcut`, the georust port of mapbox/earcut: ear clipping with z-order hashing.
    Earcut,
    /// `earcutr`, an older line-by-line port of mapbox/earcut.
    Earcutr,
    /// `i_triangle`: sweep-line monotone triangulation on an integer grid.
    ITriangle,
    /// `lyon_tessellation`'s fill tessellator (sweep line, `f32`), even-odd fill rule.
    Lyon,
    /// `spade`'s constrained Delaunay triangulation of the rings, kept where the nesting
    /// depth is odd.
    Spade,
    /// [`Peer::Lyon`] with the nonzero fill rule (on request, for fill-rule benchmarks:
    /// one of [`Peer::NONZERO`]).
    LyonNonZero,
    /// [`Peer::ITriangle`] with the nonzero fill rule (on request, as
    /// [`Peer::LyonNonZero`]).
    ITriangleNonZero,
    /// A reference, not a competitor: earcut 0.4.12 vendored with its two geometric
    /// predicates (a triangle's signed area, a point in a triangle) decided by the exact
    /// sign of `robust::orient2d`, everything else unchanged
    /// (`oracle/src/peers/earcut_exact/README.md`).
    EarcutExact,
    /// A reference, not a competitor: the same copy of earcut 0.4.12 with earcut's own
    /// floating-point predicates — [`Peer::EarcutExact`]'s baseline. EarcutExact over it is
    /// the price of the exact predicates alone; it over [`Peer::Earcut`], what the copy
    /// itself costs (in part its safe node access).
    EarcutVendored,
}

impl Peer {
    /// Every peer, in the order tables show them: the triangulators polytri is compared
    /// with (the references are in [`Peer::REFERENCES`]).
    pub const ALL: [Peer; 5] = [
        Peer::Earcut,
        Peer::Earcutr,
        Peer::ITriangle,
        Peer::Lyon,
        Peer::Spade,
    ];

    /// The references: peers altered to measure a cost, shown beside the peers but never
    /// one of them (not the fastest peer of a benchmark, not judged by campaigns).
    pub const REFERENCES: [Peer; 2] = [Peer::EarcutExact, Peer::EarcutVendored];

    /// The peers that read their input by the nonzero fill rule, for benchmarks of
    /// polytri's nonzero configurations (on request only: not in [`Peer::ALL`], whose
    /// readings match polytri's nesting on valid input).
    pub const NONZERO: [Peer; 2] = [Peer::ITriangleNonZero, Peer::LyonNonZero];

    /// Whether this is one of [`Peer::REFERENCES`].
    pub const fn is_reference(self) -> bool {
        matches!(self, Peer::EarcutExact | Peer::EarcutVendored)
    }

    /// The kebab-case name, as [`Display`](fmt::Display) writes and [`FromStr`] reads it.
    pub const fn name(self) -> &'static str {
        match self {
            Peer::Earcut => "earcut",
            Peer::EarcutExact => "earcut-exact",
            Peer::EarcutVendored => "earcut-vendored",
            Peer::Earcutr => "earcutr",
            Peer::ITriangle => "i-triangle",
            Peer::Lyon => "lyon",
            Peer::Spade => "spade",
            Peer::LyonNonZero => "lyon-nonzero",
            Peer::ITriangleNonZero => "i-triangle-nonzero",
        }
    }
}

impl fmt::Display for Peer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Peer {
    type Err = String;

    /// Reads a kebab-case name, of a peer or a reference (`i_triangle` with an underscore
    /// is accepted too).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let named: Vec<Peer> = (Peer::ALL.into_iter())
            .chain(Peer::REFERENCES)
            .chain(Peer::NONZERO)
            .collect();
        crate::by_name(&s.replace('_', "-"), &named, Peer::name, "peer")
    }
}

/// What a peer made of an input.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PeerOutput {
    /// `None`: `triangles` index the input's vertices. `Some`: the peer's own vertex list,
    /// which `triangles` index — when it added vertices (lyon and i_triangle at crossings)
    /// or moved them so that they no longer match an input vertex.
    pub vertices: Option<Vec<[f64; 2]>>,
    /// Triangles, counter-clockwise with y up (degenerate ones as the peer gave them).
    pub triangles: Vec<[u32; 3]>,
}

impl PeerOutput {
    /// The positions `triangles` index: the peer's own, or else `input`'s.
    pub fn positions<'a>(&'a self, input: &'a Input) -> &'a [[f64; 2]] {
        self.vertices.as_deref().unwrap_or(&input.vertices)
    }

    /// Turns every clockwise triangle counter-clockwise (exact orientation test).
    fn orient_ccw(mut self, input: &Input) -> Self {
        let positions = self.vertices.as_deref().unwrap_or(&input.vertices);
        let at = |v: u32| {
            let [x, y] = positions[v as usize];
            robust::Coord { x, y }
        };
        for t in &mut self.triangles {
            if robust::orient2d(at(t[0]), at(t[1]), at(t[2])) < 0.0 {
                t.swap(1, 2);
            }
        }
        self
    }
}

/// The coordinate type a peer computes in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Precision {
    F64,
    F32,
}

/// Triangulates `input` with `peer`, in `f64` (lyon, which only has `f32`, rounds to it).
///
/// # Errors
///
/// A message when the peer refuses the input, or panics on it, or the input has
/// non-finite coordinates (no peer promises anything for those, and some loop).
pub fn triangulate(peer: Peer, input: &Input) -> Result<PeerOutput, String> {
    run_once(peer, input, Precision::F64)
}

/// Triangulates `input` with `peer` in `f32`: the coordinates rounded to `f32` first.
/// Triangles index [`Input::to_f32`]'s vertices when `vertices` is `None`.
///
/// Supported by earcut, earcutr, i_triangle and lyon (lyon always computes in `f32`), and
/// by the references earcut-exact and earcut-vendored (on the rounded coordinates, in
/// `f64`).
///
/// # Errors
///
/// `"unsupported"` for spade; otherwise as [`triangulate`].
pub fn triangulate_f32(peer: Peer, input: &Input) -> Result<PeerOutput, String> {
    if peer == Peer::Spade {
        return Err("unsupported".to_owned());
    }
    run_once(peer, &input.to_f32(), Precision::F32)
}

fn run_once(peer: Peer, input: &Input, precision: Precision) -> Result<PeerOutput, String> {
    check_finite(input)?;
    // The peers panic on some inputs (spade on constraints that cross or overlap, i_triangle
    // on bounds its integer grid cannot hold, earcut on malformed hole indices): the oracle
    // must report that as a refusal, never go down with it.
    let result = catch_unwind(AssertUnwindSafe(|| match peer {
        Peer::Earcut => earcut::earcut(input, precision),
        Peer::EarcutExact => Ok(earcut::earcut_exact(input)),
        Peer::EarcutVendored => Ok(earcut::earcut_vendored(input)),
        Peer::Earcutr => earcut::earcutr(input, precision),
        Peer::ITriangle => i_triangle::triangulate(input, precision, false),
        Peer::ITriangleNonZero => i_triangle::triangulate(input, precision, true),
        Peer::Lyon => lyon::triangulate(input, false),
        Peer::LyonNonZero => lyon::triangulate(input, true),
        Peer::Spade => spade::triangulate(input),
    }));
    match result {
        Ok(out) => out.map(|out| out.orient_ccw(input)),
        Err(panic) => Err(format!("{peer} panicked: {}", panic_message(&*panic))),
    }
}

/// Refuses NaN and infinite coordinates.
fn check_finite(input: &Input) -> Result<(), String> {
    match input
        .vertices
        .iter()
        .position(|p| !(p[0].is_finite() && p[1].is_finite()))
    {
        Some(v) => Err(format!("vertex {v} has a non-finite coordinate")),
        None => Ok(()),
    }
}

/// The text of a panic payload, where it is one.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_owned()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "(no message)".to_owned()
    }
}

/// Maps `points` (a peer's own vertices) to input vertices within `tolerance` of them, the
/// nearest where several are: `None` when some point has no input vertex that close.
fn snap_to_input(points: &[[f64; 2]], input: &[[f64; 2]], tolerance: f64) -> Option<Vec<u32>> {
    use std::collections::HashMap;
    if tolerance.is_nan() || tolerance <= 0.0 {
        return None;
    }
    let cell = |p: [f64; 2]| {
        (
            (p[0] / tolerance).floor() as i64,
            (p[1] / tolerance).floor() as i64,
        )
    };
    let mut grid: HashMap<(i64, i64), Vec<u32>> = HashMap::with_capacity(input.len());
    for (v, &p) in input.iter().enumerate() {
        grid.entry(cell(p)).or_default().push(v as u32);
    }
    let distance = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).abs().max((a[1] - b[1]).abs());
    points
        .iter()
        .map(|&p| {
            let (cx, cy) = cell(p);
            (cx - 1..=cx + 1)
                .flat_map(|x| (cy - 1..=cy + 1).map(move |y| (x, y)))
                .filter_map(|key| grid.get(&key))
                .flatten()
                .copied()
                .map(|v| (distance(p, input[v as usize]), v))
                .filter(|&(d, _)| d <= tolerance)
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .map(|(_, v)| v)
        })
        .collect()
}

/// The larger side of the bounding box of `points` (0 when empty).
fn extent(points: &[[f64; 2]]) -> f64 {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (hi[0] - lo[0]).max(hi[1] - lo[1]).max(0.0)
}
