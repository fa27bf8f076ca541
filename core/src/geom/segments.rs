//! Exact tests on segments: do two cross, meet, overlap; which of two meets a horizontal
//! line further left. Built on [`orient2d`](super::orient2d) alone.

use core::cmp::Ordering;

use super::predicates::{greatest, least, orient2d, within_box, Orientation, Point};

/// Whether segments a–b and c–d cross at a point interior to both. (Always inlined: the
/// crossing searches call it for every pair of overlapping boxes.)
#[inline(always)]
pub(crate) fn crosses(a: Point, b: Point, c: Point, d: Point) -> bool {
    use Orientation::*;
    if boxes_apart(a, b, c, d) {
        return false;
    }
    // (each sign only where the ones before leave the answer open: most pairs whose
    // boxes overlap have both ends of one edge on one side of the other)
    let o1 = orient2d(a, b, c);
    o1 != Collinear && {
        let o2 = orient2d(a, b, d);
        o2 != Collinear && o1 != o2 && {
            let o3 = orient2d(c, d, a);
            o3 != Collinear && {
                let o4 = orient2d(c, d, b);
                o4 != Collinear && o3 != o4
            }
        }
    }
}

/// Whether the bounding boxes of segments a–b and c–d are disjoint (comparisons only,
/// exact): then the segments have no point in common, and no predicate is needed.
#[inline]
fn boxes_apart(a: Point, b: Point, c: Point, d: Point) -> bool {
    greatest(a.x, b.x) < least(c.x, d.x)
        || greatest(c.x, d.x) < least(a.x, b.x)
        || greatest(a.y, b.y) < least(c.y, d.y)
        || greatest(c.y, d.y) < least(a.y, b.y)
}

/// Whether closed segments a–b and c–d have a point in common.
#[inline]
pub(crate) fn segments_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    !boxes_apart(a, b, c, d) && boxed_segments_meet(a, b, c, d)
}

/// [`segments_meet`] for segments whose bounding boxes are known to overlap (the input
/// check's candidates): the same answer without comparing the boxes again.
#[inline]
pub(crate) fn boxed_segments_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    use Orientation::Collinear;
    let (o1, o2) = (orient2d(a, b, c), orient2d(a, b, d));
    let (o3, o4) = (orient2d(c, d, a), orient2d(c, d, b));
    if o1 != Collinear && o1 == o2 || o3 != Collinear && o3 == o4 {
        return false; // one segment lies strictly on one side of the other's line
    }
    if o1 != Collinear && o2 != Collinear && o3 != Collinear && o4 != Collinear {
        return true; // a proper crossing
    }
    (o1 == Collinear && within_box(a, b, c))
        || (o2 == Collinear && within_box(a, b, d))
        || (o3 == Collinear && within_box(c, d, a))
        || (o4 == Collinear && within_box(c, d, b))
}

/// For segments sharing an endpoint: whether they run along each other for a while.
#[inline]
pub(crate) fn overlaps(a: Point, b: Point, c: Point, d: Point) -> bool {
    orient2d(a, b, c) == Orientation::Collinear
        && orient2d(a, b, d) == Orientation::Collinear
        && ((c != a && c != b && within_box(a, b, c))
            || (d != a && d != b && within_box(a, b, d))
            || (a != c && a != d && within_box(c, d, a))
            || (b != c && b != d && within_box(c, d, b)))
}

/// Compares where two upward edges a → b and c → d, both spanning height `y`, meet the
/// line at `y`: `Less` when c → d meets it further left (nearer), exactly.
///
/// A point left of an upward line has a smaller x at the same height. If c and d lie on
/// one side of the line through a, b, so does the hit of c → d; otherwise, for
/// non-crossing edges, a and b lie on one side of the line through c, d.
pub(crate) fn compare_hits(y: f64, a: Point, b: Point, c: Point, d: Point) -> Ordering {
    if let Some(ord) = side_of_line(y, a, b, c, d) {
        return ord;
    }
    if let Some(ord) = side_of_line(y, c, d, a, b) {
        return ord.reverse();
    }
    // the edges cross (lenient input only): no exact answer exists, estimate
    let hit = |p: Point, q: Point| p.x + (y - p.y) / (q.y - p.y) * (q.x - p.x);
    hit(c, d).total_cmp(&hit(a, b))
}

/// Where c → d meets height `y` relative to the line a → b there, when c and d are on one
/// side of that line (or on it): `Less` left, `Greater` right, `Equal` on it.
fn side_of_line(y: f64, a: Point, b: Point, c: Point, d: Point) -> Option<Ordering> {
    let (oc, od) = (orient2d(a, b, c), orient2d(a, b, d));
    use Orientation::*;
    let ord = match (oc, od) {
        (Collinear, Collinear) => return Some(Ordering::Equal),
        (CounterClockwise, Clockwise) | (Clockwise, CounterClockwise) => return None,
        (CounterClockwise, _) | (_, CounterClockwise) => Ordering::Less,
        _ => Ordering::Greater,
    };
    // one endpoint on the line exactly at height y: that endpoint is the hit of both
    if (oc == Collinear && c.y == y) || (od == Collinear && d.y == y) {
        return Some(Ordering::Equal);
    }
    Some(ord)
}

/// Signed crossing of the ray from `v` towards +x with the edge a → b (half-open in y, so
/// a vertex on the ray counts once): +1 upwards, −1 downwards, 0 when missed. Summed over
/// a ring, the ring's winding number round `v` (for `v` on none of its edges).
#[inline]
pub(crate) fn ray_crossing(a: Point, b: Point, v: Point) -> i64 {
    if a.y <= v.y && v.y < b.y && orient2d(a, b, v) == Orientation::CounterClockwise {
        1
    } else if b.y <= v.y && v.y < a.y && orient2d(a, b, v) == Orientation::Clockwise {
        -1
    } else {
        0
    }
}
