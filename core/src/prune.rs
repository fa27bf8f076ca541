//! A quick proof for the common case of `clean`'s input check: no two edges meet, except
//! adjacent edges at their shared vertex. Then the sweep of `validate` would find no
//! crossing and no T-junction, and no two nodes share a position, so `clean` skips it.
//!
//! Sweep and prune: the edges' bounding boxes sorted by their left sides, each box compared
//! with the boxes that start before it ends. Box comparisons only narrow the candidates
//! down; every pair whose boxes overlap is decided by exact `orient2d` signs. The scan has a
//! budget linear in the edges: when many long edges lie over each other it gives up, says
//! "not proved", and the full sweep runs as before. Either way the result is the sweep's.

use crate::pool::{NodeId, Pool};
use crate::predicates::{orient2d, within_box, Orientation, Point};

/// Box comparisons allowed per edge (plus a constant) before the proof gives up.
const BUDGET_PER_EDGE: usize = 16;

/// One edge `from → to` with its bounding box.
#[derive(Clone, Copy, Debug)]
struct EdgeBox {
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
    from: NodeId,
    to: NodeId,
}

/// Reusable buffers of [`edges_apart`].
#[derive(Debug, Default)]
pub(crate) struct PruneScratch {
    boxes: Vec<EdgeBox>,
    sorted: Vec<EdgeBox>,
    keys: Vec<(u64, u32)>,
}

/// Up to this many edges, sorting the boxes themselves is cheapest.
const SMALL: usize = 20;

/// An unsigned integer ordered as `total_cmp` orders finite x.
fn order_key(x: f64) -> u64 {
    let bits = x.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | 1 << 63
    }
}

/// Whether the edges of the rings through `starts` are proved apart: no two meet, except
/// adjacent ones at their shared vertex and nowhere else. `false` means "not proved" (some
/// pair meets, or the budget ran out). `nodes` is filled with the rings' nodes either way.
pub(crate) fn edges_apart(
    pool: &Pool,
    starts: &[NodeId],
    scratch: &mut PruneScratch,
    nodes: &mut Vec<NodeId>,
) -> bool {
    let boxes = &mut scratch.boxes;
    boxes.clear();
    nodes.clear();
    for &start in starts {
        if start.idx() >= pool.len() {
            continue;
        }
        let mut n = start;
        // bounded like the sweep's walk, in case a start was unlinked
        for _ in 0..pool.len() {
            let next = pool.next(n);
            let (a, b) = (pool.p(n), pool.p(next));
            nodes.push(n);
            boxes.push(EdgeBox {
                x0: a.x.min(b.x),
                x1: a.x.max(b.x),
                y0: a.y.min(b.y),
                y1: a.y.max(b.y),
                from: n,
                to: next,
            });
            n = next;
            if n == start {
                break;
            }
        }
    }
    // Coordinates are finite here (load dropped or refused the others) and −0.0 was made
    // +0.0, so the bits of a non-negative x order like x. Insertion sort for a glyph's
    // few edges; otherwise sort small keys, then move the boxes once.
    if boxes.len() <= SMALL {
        boxes.sort_by(|s, t| s.x0.total_cmp(&t.x0));
    } else {
        let keys = &mut scratch.keys;
        keys.clear();
        keys.extend(
            boxes
                .iter()
                .enumerate()
                .map(|(i, b)| (order_key(b.x0), i as u32)),
        );
        keys.sort_unstable();
        let sorted = &mut scratch.sorted;
        sorted.clear();
        sorted.extend(keys.iter().map(|&(_, i)| boxes[i as usize]));
        core::mem::swap(boxes, sorted);
    }
    let boxes = &scratch.boxes;
    let mut budget = BUDGET_PER_EDGE * boxes.len() + 64;
    for (i, e) in boxes.iter().enumerate() {
        for f in &boxes[i + 1..] {
            if f.x0 > e.x1 {
                break;
            }
            if budget == 0 {
                return false;
            }
            budget -= 1;
            if f.y0 > e.y1 || e.y0 > f.y1 {
                continue;
            }
            if meet(pool, e, f) {
                return false;
            }
        }
    }
    true
}

/// Whether edges `e` and `f`, whose boxes overlap, meet other than adjacent edges at their
/// shared vertex only (exact).
fn meet(pool: &Pool, e: &EdgeBox, f: &EdgeBox) -> bool {
    let (a, b, c, d) = (pool.p(e.from), pool.p(e.to), pool.p(f.from), pool.p(f.to));
    if e.to == f.from && f.to == e.from {
        return true; // a ring of two: the edges lie on each other
    }
    if e.to == f.from {
        // a → b → d: they share b and nothing else unless they are collinear
        return orient2d(a, b, d) == Orientation::Collinear;
    }
    if f.to == e.from {
        return orient2d(c, d, b) == Orientation::Collinear;
    }
    segments_meet(a, b, c, d)
}

/// Whether closed segments a–b and c–d have a point in common (exact).
fn segments_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Builds a pool from rings of (x, y) and returns it with one start node per ring.
    fn build(rings: &[&[(f64, f64)]]) -> (Pool, Vec<NodeId>) {
        let mut pool = Pool::default();
        let mut starts = Vec::new();
        for (r, ring) in rings.iter().enumerate() {
            let first = pool.len() as u32;
            for (i, &(x, y)) in ring.iter().enumerate() {
                pool.push(Point::new(x, y), i as u32, r as u32);
            }
            pool.link_run(first, ring.len() as u32);
            starts.push(NodeId(first));
        }
        (pool, starts)
    }

    fn apart(rings: &[&[(f64, f64)]]) -> bool {
        let (pool, starts) = build(rings);
        let mut nodes = Vec::new();
        let ok = edges_apart(&pool, &starts, &mut PruneScratch::default(), &mut nodes);
        assert_eq!(nodes.len(), rings.iter().map(|r| r.len()).sum::<usize>());
        ok
    }

    const SQUARE: &[(f64, f64)] = &[(0., 0.), (10., 0.), (10., 10.), (0., 10.)];

    #[test]
    fn simple_rings_are_apart() {
        assert!(apart(&[SQUARE]));
        assert!(apart(&[SQUARE, &[(3., 3.), (3., 7.), (7., 7.), (7., 3.)]]));
    }

    #[test]
    fn touching_crossing_and_shared_points_are_not() {
        // a hole touching the outer ring inside an edge (a T-junction)
        assert!(!apart(&[SQUARE, &[(0., 5.), (3., 7.), (3., 3.)]]));
        // a hole sharing a vertex with the outer ring
        assert!(!apart(&[SQUARE, &[(0., 0.), (3., 7.), (3., 3.)]]));
        // a bow tie
        assert!(!apart(&[&[(0., 0.), (10., 10.), (10., 0.), (0., 10.)]]));
        // a spike: adjacent edges running back along each other
        assert!(!apart(&[&[(0., 0.), (10., 0.), (5., 0.), (5., 5.)]]));
        // two rings crossing
        assert!(!apart(&[SQUARE, &[(5., 5.), (15., 5.), (15., 6.)]]));
    }

    #[test]
    fn order_keys_order_like_total_cmp() {
        let xs = [-1e300, -1.5, -5e-324, 0.0, 5e-324, 1.0, 1e300];
        for &a in &xs {
            for &b in &xs {
                assert_eq!(order_key(a).cmp(&order_key(b)), a.total_cmp(&b), "{a} {b}");
            }
        }
    }

    #[test]
    fn many_edges_take_the_keyed_sort() {
        // a 64-gon with a 64-gon hole, and the same hole moved onto the outer ring
        let circle = |r: f64, dx: f64| -> Vec<(f64, f64)> {
            (0..64)
                .map(|k| {
                    let t = f64::from(k) * core::f64::consts::TAU / 64.0;
                    (dx + r * t.cos(), r * t.sin())
                })
                .collect()
        };
        assert!(apart(&[&circle(10.0, 0.0), &circle(5.0, 0.0)]));
        assert!(!apart(&[&circle(10.0, 0.0), &circle(5.0, 5.0)]));
    }

    #[test]
    fn near_misses_are_decided_exactly() {
        // the hole's corner sits one ulp right of the outer ring's left edge
        let x = f64::from_bits(0.0f64.to_bits() + 1);
        assert!(apart(&[SQUARE, &[(x, 5.), (3., 7.), (3., 3.)]]));
        assert!(!apart(&[SQUARE, &[(0., 5.), (3., 7.), (3., 3.)]]));
    }
}
