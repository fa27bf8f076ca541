//! What can go wrong, and where.

use core::fmt;

/// Why a triangulation was refused.
///
/// Every variant but [`Error::Internal`] describes bad input and says where it is: input
/// vertex indices (into the `vertices` slice) and ring numbers (positions in `ring_starts`).
/// [`Error::Internal`] is a bug in polytri, never the caller's fault.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Error {
    /// A coordinate is NaN or infinite.
    NonFinite {
        /// Index of the offending vertex.
        vertex: usize,
    },
    /// `ring_starts` is empty while there are vertices, or its first entry is not 0.
    FirstRingStart {
        /// The first entry, or `None` when `ring_starts` is empty.
        start: Option<usize>,
    },
    /// A ring start is not greater than the one before it.
    RingStartsNotIncreasing {
        /// The ring whose start is out of order.
        ring: usize,
        /// Its start.
        start: usize,
        /// The start of the ring before it.
        previous: usize,
    },
    /// A ring start lies beyond the end of `vertices`.
    RingStartOutOfRange {
        /// The ring whose start is out of range.
        ring: usize,
        /// Its start.
        start: usize,
        /// The number of vertices.
        len: usize,
    },
    /// More vertices than `u32` triangle indices can address.
    TooManyVertices {
        /// The number of vertices given.
        count: usize,
    },
    /// Two edges cross (strict mode only). Each edge is named by the input vertex it starts
    /// at and its ring; the edge runs to the next kept vertex of that ring.
    EdgesCross {
        /// Ring of the first edge.
        ring_a: usize,
        /// Start vertex of the first edge.
        edge_a: usize,
        /// Ring of the second edge.
        ring_b: usize,
        /// Start vertex of the second edge.
        edge_b: usize,
    },
    /// A ring lies on another ring's boundary, every corner of it inside a corner of the
    /// other, without the two bounding a region together (as an outer ring and its hole
    /// cancelling each other do): the same ring twice, say, which would cover its inside
    /// twice (strict mode only).
    RingsOverlap {
        /// The ring all of whose corners are shared.
        ring: usize,
        /// One of its vertices.
        vertex: usize,
    },
    /// Rings cross each other at a vertex of one of them that the other passes through (at
    /// a vertex of its own, or inside an edge), as an X: going round the vertex, the
    /// polygon's winding number takes three values (strict mode only). No two edges cross
    /// at a point inside both, so it is not [`Error::EdgesCross`]. The two rings may be one
    /// ring passing the vertex twice.
    RingsCrossAtVertex {
        /// One ring through the vertex.
        ring_a: usize,
        /// Another ring through it (or `ring_a` again).
        ring_b: usize,
        /// The vertex (one of the input vertices at that position).
        vertex: usize,
    },
    /// With [`Nesting::FirstIsOuter`](crate::Nesting::FirstIsOuter): a hole is not inside the
    /// outer ring, or lies inside another hole (strict mode only).
    HoleOutside {
        /// The misplaced hole.
        ring: usize,
    },
    /// A ring winds both ways: it touches itself (at a vertex, or along a stretch it runs
    /// twice in opposite directions) so that one of its lobes turns clockwise and another
    /// counter-clockwise, side by side — a figure eight. Which lobe is inside is undefined
    /// (strict mode only).
    LobesWindOpposite {
        /// The ring.
        ring: usize,
        /// A vertex of the lobe that winds the other way.
        vertex: usize,
    },
    /// A ring runs round part of the plane twice: it touches itself, and a lobe of it lies
    /// inside the rest of it turning the same way, so the winding number there is 2 (strict
    /// mode only).
    RingWindsTwice {
        /// The ring.
        ring: usize,
        /// A vertex where the lobe touches the rest of the ring.
        vertex: usize,
    },
    /// A 3D polygon ([`Triangulator::triangulate_3d`](crate::Triangulator::triangulate_3d))
    /// is not planar: this vertex lies further from the polygon's plane than
    /// [`PLANAR_TOLERANCE`](crate::PLANAR_TOLERANCE) times the polygon's size (strict
    /// mode only).
    NotPlanar {
        /// The vertex furthest from the plane.
        vertex: usize,
    },
    /// A 3D polygon ([`Triangulator::triangulate_3d`](crate::Triangulator::triangulate_3d))
    /// whose edges cross, with a fill rule (or `Strategy::Seidel` in lenient mode): the
    /// vertex added where they cross would have no z for the triangles to index.
    /// Triangulate the polygon's projection in 2D to have the crossing points, or take
    /// lenient mode without a fill rule, which adds none.
    CrossingIn3d {
        /// The two crossing edges, each named by the input vertex it starts at.
        edge_a: usize,
        /// See `edge_a`.
        edge_b: usize,
    },
    /// A coordinate is too large or too small for exact computation (strict mode): without
    /// a fill rule, a magnitude of 2⁵⁰⁰ or more or, nonzero, below 2⁻⁴⁸⁰, where orientation
    /// signs would overflow or lose bits; with a fill rule, above 2¹⁰⁰ or, nonzero, below
    /// 2⁻²⁴⁸, for crossing points to be computed exactly (every `f32` value is fine
    /// without a fill rule).
    CoordinateRange {
        /// The offending vertex.
        vertex: usize,
    },
    /// polytri failed where it should not have: **this is a bug, please report it** with the
    /// input at <https://github.com/polytri/polytri/issues>.
    Internal {
        /// The pipeline stage that gave up.
        stage: &'static str,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::NonFinite { vertex } => {
                write!(f, "vertex {vertex} has a coordinate that is NaN or infinite")
            }
            Error::FirstRingStart { start: None } => {
                write!(f, "ring_starts is empty but there are vertices; it must start with 0")
            }
            Error::FirstRingStart { start: Some(s) } => {
                write!(f, "ring_starts must start with 0, not {s}")
            }
            Error::RingStartsNotIncreasing { ring, start, previous } => write!(
                f,
                "ring {ring} starts at vertex {start}, not after ring {}'s start {previous}",
                ring.saturating_sub(1)
            ),
            Error::RingStartOutOfRange { ring, start, len } => {
                write!(f, "ring {ring} starts at vertex {start} but there are only {len} vertices")
            }
            Error::TooManyVertices { count } => {
                write!(f, "{count} vertices are more than u32 triangle indices can address")
            }
            Error::EdgesCross { ring_a, edge_a, ring_b, edge_b } => write!(
                f,
                "edges cross: ring {ring_a} edge from vertex {edge_a} and ring {ring_b} edge from vertex {edge_b}"
            ),
            Error::RingsOverlap { ring, vertex } => write!(
                f,
                "ring {ring} overlaps another ring: it lies on that ring's boundary (e.g. at vertex {vertex}) and would cover its inside twice"
            ),
            Error::RingsCrossAtVertex {
                ring_a,
                ring_b,
                vertex,
            } if ring_a == ring_b => write!(
                f,
                "ring {ring_a} crosses itself at vertex {vertex}, where it passes twice"
            ),
            Error::RingsCrossAtVertex {
                ring_a,
                ring_b,
                vertex,
            } => write!(
                f,
                "rings {ring_a} and {ring_b} cross each other at vertex {vertex}, where both pass"
            ),
            Error::HoleOutside { ring } => write!(
                f,
                "ring {ring} is given as a hole but is not inside the outer ring (or lies in another hole)"
            ),
            Error::LobesWindOpposite { ring, vertex } => write!(
                f,
                "ring {ring} winds both ways: the lobe at vertex {vertex} turns the other way round than the rest (a figure eight)"
            ),
            Error::RingWindsTwice { ring, vertex } => write!(
                f,
                "ring {ring} winds twice: the lobe touching the rest of it at vertex {vertex} lies inside the rest and turns the same way"
            ),
            Error::NotPlanar { vertex } => write!(
                f,
                "the polygon is not planar: vertex {vertex} lies off its plane by more than the tolerance"
            ),
            Error::CrossingIn3d { edge_a, edge_b } => write!(
                f,
                "the edges from vertex {edge_a} and from vertex {edge_b} cross: a fill rule adds a vertex there, which a 3D polygon's triangles cannot index (it has no z)"
            ),
            Error::CoordinateRange { vertex } => write!(
                f,
                "vertex {vertex} has a coordinate outside the range computed exactly (0, or a magnitude from 2^-480 to below 2^500; with a fill rule, from 2^-248 to 2^100)"
            ),
            Error::Internal { stage } => write!(
                f,
                "internal error in stage `{stage}`: this is a bug in polytri, please report it with the input"
            ),
        }
    }
}

impl std::error::Error for Error {}
