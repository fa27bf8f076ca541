//! The geometry of the ear test, shared by the clip stage and the small stage: the
//! box an ear's candidates must lie in, and whether a vertex spoils an ear.

use super::predicates::{greatest, least, left_of, orient2d, Orientation, Point};

/// The fuzzing experiment, never enabled otherwise: built with
/// `RUSTFLAGS="--cfg polytri_planted_bug"`, the ear test misses reflex vertices on the
/// right edge of the ear's bounding box (an off-by-one, `<` for `<=`; the clip stage's grid
/// does not use [`near`], so only unindexed tests, as for small polygons, have the bug), and
/// the fuzz targets must find it (see `docs/harness.md`). A cfg rather than a feature, so
/// that `--all-features` never plants it.
const PLANTED_BUG: bool = cfg!(polytri_planted_bug);

/// The bounding box of a, b, c (finite: plain comparisons, without `f64::min`'s NaN
/// handling).
#[inline(always)]
pub(crate) fn bounds(a: Point, b: Point, c: Point) -> (Point, Point) {
    let (min, max) = (least, greatest);
    let lo = Point::new(min(min(a.x, b.x), c.x), min(min(a.y, b.y), c.y));
    let hi = Point::new(max(max(a.x, b.x), c.x), max(max(a.y, b.y), c.y));
    (lo, hi)
}

/// Whether `q` lies in the box `lo..=hi`, as the ear test's candidates must.
#[inline(always)]
pub(crate) fn near(lo: Point, hi: Point, q: Point) -> bool {
    q.x >= lo.x && q.x <= hi.x && !(PLANTED_BUG && q.x == hi.x) && q.y >= lo.y && q.y <= hi.y
}

/// Whether a vertex at `q` spoils the ear triangle a, b, c (counter-clockwise): it lies
/// strictly inside, inside the diagonal a–c, or on the boundary with an edge running
/// inside. `around` gives the positions of the vertex's two neighbours on its ring (only
/// asked for when `q` lies on the boundary).
#[inline]
pub(crate) fn interferes(
    q: Point,
    around: impl Fn() -> [Point; 2],
    a: Point,
    b: Point,
    c: Point,
) -> bool {
    use Orientation::*;
    // most candidates lie outside: stop at the first side that says so
    let oab = orient2d(a, b, q);
    if oab == Clockwise {
        return false;
    }
    let obc = orient2d(b, c, q);
    if obc == Clockwise {
        return false;
    }
    let oca = orient2d(c, a, q);
    if oca == Clockwise {
        return false;
    }
    if oab == CounterClockwise && obc == CounterClockwise && oca == CounterClockwise {
        return true;
    }
    // on the boundary: which part of it?
    let enters = |inside: &dyn Fn(Point) -> bool| around().into_iter().any(inside);
    if q == a {
        enters(&|p| left_of(a, b, p) && left_of(c, a, p))
    } else if q == b {
        enters(&|p| left_of(a, b, p) && left_of(b, c, p))
    } else if q == c {
        enters(&|p| left_of(b, c, p) && left_of(c, a, p))
    } else if oca == Collinear {
        // inside the diagonal: cutting would leave a vertex inside an edge
        true
    } else if oab == Collinear {
        enters(&|p| left_of(a, b, p))
    } else {
        enters(&|p| left_of(b, c, p))
    }
}
