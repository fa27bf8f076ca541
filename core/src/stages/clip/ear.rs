//! The exact geometry of the clipper's repairs: whether a direction leaves a node into the
//! polygon, and the winding number next to a vertex. (Which vertex spoils an ear is
//! `geom::interferes`, shared with the small stage.)

use crate::geom::{corner_contains, orient2d, Orientation, Point};
use crate::structures::{NodeId, Pool};

/// Whether the direction from node `n` towards `q` leaves `n` into the polygon (strictly
/// inside its corner, or along one of its sides).
pub(super) fn sees(pool: &Pool, n: NodeId, q: Point) -> bool {
    let o = pool.p(n);
    corner_contains(o, pool.p(pool.next(n)), pool.p(pool.prev(n)), q) != Some(false)
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
