//! The exact geometry of the ear test: which reflex vertex spoils an ear, whether a
//! direction leaves a node into the polygon, and the winding number next to a vertex.

use crate::geom::{corner_contains, left_of, orient2d, Orientation, Point};
use crate::structures::{NodeId, Pool};

use super::PLANTED_BUG;

/// Whether the direction from node `n` towards `q` leaves `n` into the polygon (strictly
/// inside its corner, or along one of its sides).
pub(super) fn sees(pool: &Pool, n: NodeId, q: Point) -> bool {
    let o = pool.p(n);
    corner_contains(o, pool.p(pool.next(n)), pool.p(pool.prev(n)), q) != Some(false)
}

/// The bounding box of a, b, c (finite: plain comparisons, without `f64::min`'s NaN
/// handling).
#[inline(always)]
pub(super) fn bounds(a: Point, b: Point, c: Point) -> (Point, Point) {
    let min = |s: f64, t: f64| if t < s { t } else { s };
    let max = |s: f64, t: f64| if t > s { t } else { s };
    let lo = Point::new(min(min(a.x, b.x), c.x), min(min(a.y, b.y), c.y));
    let hi = Point::new(max(max(a.x, b.x), c.x), max(max(a.y, b.y), c.y));
    (lo, hi)
}

/// Whether `q` lies in the box `lo..=hi`, as the ear test's candidates must.
#[inline(always)]
pub(super) fn near(lo: Point, hi: Point, q: Point) -> bool {
    q.x >= lo.x && q.x <= hi.x && !(PLANTED_BUG && q.x == hi.x) && q.y >= lo.y && q.y <= hi.y
}

/// Signed crossing of edge e → f with the ray towards +x from the point just past `o` on
/// the way to `q` (o + ε·(q − o), ε → 0+): +1 upwards, −1 downwards, else 0. Half-open in
/// y like `nest`'s crossing, so the sum over a ring is its winding number around the point
/// (when no edge runs through it). Exact without computing the point: a tie in y goes by
/// the direction to `q`, and where `o` lies on the edge's line, the point lies on `q`'s
/// side of it.
pub(super) fn crossing_past(e: Point, f: Point, o: Point, q: Point) -> i32 {
    let above = |p: Point| p.y > o.y || (p.y == o.y && q.y < o.y);
    let (ae, af) = (above(e), above(f));
    if ae == af {
        // the edge stays on one side of the ray's line
        return 0;
    }
    let side = match orient2d(e, f, o) {
        Orientation::Collinear => orient2d(e, f, q),
        side => side,
    };
    match (ae, af, side) {
        (false, true, Orientation::CounterClockwise) => 1,
        (true, false, Orientation::Clockwise) => -1,
        _ => 0,
    }
}

/// Whether node `r` spoils the ear triangle a, b, c (counter-clockwise): it lies strictly
/// inside, inside the diagonal a–c, or on the boundary with an edge running inside.
/// `q` is the position of `r`.
#[inline]
pub(super) fn interferes(pool: &Pool, r: NodeId, q: Point, a: Point, b: Point, c: Point) -> bool {
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
    let enters = |inside: &dyn Fn(Point) -> bool| {
        inside(pool.p(pool.prev(r))) || inside(pool.p(pool.next(r)))
    };
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Winding number of `ring` around the point just past `o` towards `q`.
    fn winding_past(ring: &[(f64, f64)], o: (f64, f64), q: (f64, f64)) -> i32 {
        let p = |(x, y): (f64, f64)| Point::new(x, y);
        (0..ring.len())
            .map(|i| crossing_past(p(ring[i]), p(ring[(i + 1) % ring.len()]), p(o), p(q)))
            .sum()
    }

    #[test]
    fn crossing_past_counts_the_winding_next_to_a_vertex() {
        let square = [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)];
        let clockwise: Vec<_> = square.iter().rev().copied().collect();
        // (from, towards, winding of the counter-clockwise square there)
        let cases = [
            ((0.0, 0.0), (4.0, 4.0), 1),
            ((0.0, 0.0), (-1.0, -1.0), 0),
            ((0.0, 0.0), (1.0, -1.0), 0),
            ((4.0, 0.0), (0.0, 4.0), 1),
            ((4.0, 4.0), (0.0, 1.0), 1),
            ((0.0, 4.0), (3.0, 4.0), 0), // along the top edge: counted as just above it
            ((0.0, 4.0), (3.0, 3.0), 1),
            ((2.0, 2.0), (9.0, 2.0), 1), // from inside, out across an edge: still inside
            ((2.0, 4.0), (2.0, 0.0), 1), // from the middle of an edge, inwards
            ((2.0, 4.0), (2.0, 9.0), 0), // and outwards
            ((4.0, 2.0), (3.0, 2.0), 1),
            ((4.0, 2.0), (5.0, 2.0), 0),
        ];
        for (o, q, winding) in cases {
            assert_eq!(winding_past(&square, o, q), winding, "{o:?} -> {q:?}");
            assert_eq!(winding_past(&clockwise, o, q), -winding, "{o:?} -> {q:?}");
        }
    }
}
