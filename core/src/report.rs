//! What the triangulator left out, repaired or skipped.

/// Why an input vertex is not used by any triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum DropReason {
    /// Same position as the vertex before it in its ring (this includes a repeated closing
    /// point).
    Repeated,
    /// Lies on the straight line between its neighbours; the edge runs through it.
    Collinear,
    /// Same position as another input vertex further on in its ring or in another ring
    /// (rings touching there); triangles use the lowest-numbered vertex at that position.
    Coincident,
    /// The tip of a zero-width spike: the ring runs out to it and straight back.
    Spike,
    /// Its ring has fewer than three distinct, non-collinear points and encloses no area.
    DegenerateRing,
    /// A coordinate is NaN or infinite (lenient mode; strict mode refuses the input).
    NonFinite,
    /// Its ring was skipped (lenient mode), see [`RepairKind`].
    RingSkipped,
    /// With a fill rule: no corner of the rule's region — inside or outside it, or on a
    /// straight stretch of its boundary.
    OffBoundary,
}

/// An input vertex that no triangle uses, and why.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Dropped {
    /// Index into the input `vertices`.
    pub vertex: u32,
    /// The ring it belongs to (position in `ring_starts`).
    pub ring: u32,
    /// Why it was left out.
    pub reason: DropReason,
}

/// What lenient mode changed to make a result.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum RepairKind {
    /// Ring starts that were out of order or out of range were ignored.
    RingStartIgnored,
    /// Edges of the input cross; they were left as they are and the result may overlap or
    /// leave gaps near them.
    EdgesCross,
    /// With `FirstIsOuter`, a hole lies outside the outer ring; it was still bridged in.
    HoleOutside,
    /// No proper ear was left (the input was not a valid polygon): a triangle was cut by
    /// force to finish.
    ForcedEar,
    /// A piece of the polygon enclosing no area was dropped.
    DegeneratePiece,
    /// With `Nesting::Auto`, rings lie on each other without crossing (a ring given twice,
    /// a ring along another's edges inside it: strict mode refuses them as
    /// `Error::RingsOverlap`) or cross each other at a vertex they share
    /// (`Error::RingsCrossAtVertex`), so that containment cannot order them: they were
    /// read by the even–odd rule, as [`FillRule::EvenOdd`](crate::FillRule::EvenOdd)
    /// reads them, which adds no vertex where no edges cross. `ring` and `vertex` are 0.
    ReadEvenOdd,
}

/// A repair made in lenient mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Repair {
    /// What was done.
    pub kind: RepairKind,
    /// The ring concerned (position in `ring_starts`).
    pub ring: u32,
    /// The input vertex concerned, where one is meaningful.
    pub vertex: u32,
}

/// A vertex added where input edges cross (with a fill rule only): the crossing point,
/// rounded to the coordinate type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Added {
    /// Its index in the triangles: the number of input vertices plus its position in
    /// [`Report::added`].
    pub vertex: u32,
    /// Its coordinates (exactly the coordinate type's value, widened to `f64`).
    pub position: [f64; 2],
    /// Two input edges crossing there, each named by the input vertex it starts at (more
    /// may pass through the same point).
    pub edges: [u32; 2],
}

/// The outcome of a successful triangulation, borrowed from the
/// [`Triangulator`](crate::Triangulator) that made it.
#[derive(Clone, Copy, Debug)]
pub struct Report<'a> {
    /// Number of triangles written.
    pub triangles: usize,
    /// Number of polygons (outer rings with their holes) triangulated.
    pub polygons: usize,
    /// Number of holes bridged into their polygons.
    pub holes: usize,
    /// earcut's deviation ([`deviation`]) of the triangles' area from the input's (outer
    /// rings minus holes, by the shoelace formula). Strict mode: 0, exactly — a strict
    /// result covers its input exactly. Lenient mode: measured (rounding only for a valid
    /// input; on crossing input, the measure lenient mode minimises).
    pub deviation: f64,
    /// Input vertices no triangle uses, and why.
    pub dropped: &'a [Dropped],
    /// What lenient mode repaired or skipped; always empty in strict mode.
    pub repairs: &'a [Repair],
    /// Vertices added where edges cross, with a fill rule
    /// ([`Options::with_fill_rule`](crate::Options::with_fill_rule)); always empty
    /// without one. The triangles index the input's vertices, then these.
    pub added: &'a [Added],
}

impl Report<'_> {
    /// True when nothing was repaired: in strict mode always.
    pub fn is_clean(&self) -> bool {
        self.repairs.is_empty()
    }
}

/// earcut's deviation: `|area(polygon) − Σ area(triangles)| / area(polygon)`, 0 when both
/// areas are 0 and 1 when only the polygon's is (or when the quotient is not finite).
///
/// The one formula that polytri's lenient mode, its oracle and its tests use to compare a
/// triangulation's area with its input's. Both areas are taken as given (unsigned, or
/// signed alike); only their relative difference is computed.
///
/// ```
/// assert_eq!(polytri::deviation(4.0, 3.0), 0.25);
/// assert_eq!(polytri::deviation(0.0, 0.0), 0.0);
/// assert_eq!(polytri::deviation(0.0, 2.0), 1.0);
/// ```
pub fn deviation(polygon_area: f64, triangles_area: f64) -> f64 {
    let d = if polygon_area == 0.0 && triangles_area == 0.0 {
        0.0
    } else if polygon_area == 0.0 {
        1.0
    } else {
        ((polygon_area - triangles_area) / polygon_area).abs()
    };
    if d.is_finite() {
        d
    } else {
        1.0
    }
}
