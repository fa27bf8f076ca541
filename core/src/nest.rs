//! Stage 3, *nest*: which rings are outer boundaries and which are holes.
//!
//! `Nesting::Auto`: the containment depth of every ring decides — even: outer boundary,
//! odd: hole. An island inside a hole is a polygon of its own, to any depth. The depth of
//! ring B is the number of rings containing it, computed at one vertex V of B as a winding
//! number: with every ring counter-clockwise (the clean stage made them so), the signed
//! crossings of the ray from V towards +x with all other rings' edges count the rings
//! around V. Rings passing through V (touching B there) are decided locally instead, by
//! whether B's corner at V lies inside theirs. The edges come from a band index, so a ring
//! costs one band, not the whole input.
//!
//! `Nesting::FirstIsOuter` (earcut's convention) takes ring 0 as the outer boundary and the
//! rest as its holes; strict mode checks that this is true.
//!
//! Finally holes are turned clockwise, so that in every ring the polygon's interior lies to
//! the left of each edge — the convention `bridge` and `clip` rely on.

use crate::pool::NodeId;
use crate::predicates::{left_of, on_segment, orient2d, Orientation, Point};
use crate::report::{DropReason, Dropped, RepairKind};
use crate::triangulator::Context;
use crate::{Error, Nesting};

/// Decides every live ring's depth and turns holes clockwise.
pub(crate) fn nest(cx: &mut Context, nesting: Nesting) -> Result<(), Error> {
    let alive = cx.rings.iter().filter(|r| r.alive).count();
    match nesting {
        Nesting::Auto if alive > 1 => compute_depths(cx)?,
        Nesting::Auto => {}
        Nesting::FirstIsOuter => first_is_outer(cx)?,
    }
    for r in 0..cx.rings.len() {
        let ring = cx.rings[r];
        if ring.alive && ring.depth % 2 == 1 {
            cx.pool.reverse(ring.start);
        }
    }
    Ok(())
}

/// earcut's convention; in strict mode, checked against the computed depths.
fn first_is_outer(cx: &mut Context) -> Result<(), Error> {
    let outer_alive = cx.rings.first().is_some_and(|r| r.alive && r.input == 0);
    if !cx.lenient && cx.rings.len() > 1 {
        compute_depths(cx)?;
        for r in 0..cx.rings.len() {
            let ring = cx.rings[r];
            let expected = u32::from(r != 0);
            if ring.alive && (ring.depth != expected || !outer_alive) {
                let ring = if r == 0 { 1 } else { ring.input as usize };
                return Err(Error::HoleOutside { ring });
            }
        }
    }
    for r in 0..cx.rings.len() {
        cx.rings[r].depth = u32::from(r != 0 || !outer_alive);
    }
    if !outer_alive {
        // no outer boundary: nothing to triangulate (earcut returns nothing too)
        for r in 0..cx.rings.len() {
            skip_ring(cx, r);
        }
    }
    Ok(())
}

/// Takes a ring out of the triangulation (lenient mode), reporting its vertices.
pub(crate) fn skip_ring(cx: &mut Context, r: usize) {
    let ring = cx.rings[r];
    if !ring.alive {
        return;
    }
    cx.rings[r].alive = false;
    cx.repair(
        RepairKind::HoleOutside,
        ring.input,
        cx.pool.get(ring.start).vertex,
    );
    let start = ring.start;
    let mut n = start;
    loop {
        let vertex = cx.pool.get(n).vertex;
        cx.dropped.push(Dropped {
            vertex,
            ring: ring.input,
            reason: DropReason::RingSkipped,
        });
        n = cx.pool.next(n);
        if n == start {
            break;
        }
    }
}

/// Fills every live ring's `depth` with the number of rings containing it.
fn compute_depths(cx: &mut Context) -> Result<(), Error> {
    index_all_edges(cx);
    for r in 0..cx.rings.len() {
        if cx.rings[r].alive {
            cx.rings[r].depth = depth_of(cx, r)?;
        }
    }
    Ok(())
}

/// Lists every live edge in the band index.
pub(crate) fn index_all_edges(cx: &mut Context) {
    let (mut ymin, mut ymax, mut edges, mut total_dy) = (f64::INFINITY, f64::NEG_INFINITY, 0, 0.0);
    for ring in cx.rings.iter().filter(|r| r.alive) {
        for n in cx.pool.ring(ring.start) {
            let (y, y_next) = (cx.pool.p(n).y, cx.pool.p(cx.pool.next(n)).y);
            ymin = ymin.min(y);
            ymax = ymax.max(y);
            total_dy += (y_next - y).abs();
            edges += 1;
        }
    }
    cx.bands.reset(ymin, ymax, edges, total_dy);
    for ring in cx.rings.iter().filter(|r| r.alive) {
        for n in cx.pool.ring(ring.start) {
            cx.bands.insert(n, cx.pool.p(n), cx.pool.p(cx.pool.next(n)));
        }
    }
}

/// The number of rings containing ring `b`, decided at its rightmost vertex — or, where
/// another ring runs along both of b's edges there, at the next vertex that decides.
fn depth_of(cx: &mut Context, b: usize) -> Result<u32, Error> {
    let first = cx.rings[b].rightmost;
    let mut v = first;
    loop {
        if let Some(depth) = depth_at(cx, b, v) {
            return Ok(depth);
        }
        v = cx.pool.next(v);
        if v == first {
            break;
        }
    }
    // every corner of b coincides with a corner of another ring: the rings overlap
    if cx.lenient {
        return Ok(0);
    }
    let node = cx.pool.get(first);
    Err(Error::RingsOverlap {
        ring: cx.rings[b].input as usize,
        vertex: node.vertex as usize,
    })
}

/// The depth of ring `b` decided at its node `v`, or `None` when a ring passing through
/// v's position has the very same corner there.
fn depth_at(cx: &mut Context, b: usize, v: NodeId) -> Option<u32> {
    let pv = cx.pool.p(v);
    // Rings passing through V: decided locally, left out of the winding number.
    let touching = &mut cx.order;
    touching.clear();
    for n in cx.bands.query(pv.y, pv.y) {
        let node = cx.pool.get(n);
        let ring = node.ring;
        if ring as usize == b || node.removed || !cx.rings[ring as usize].alive {
            continue;
        }
        if on_segment(node.p, cx.pool.p(node.next), pv) && !touching.contains(&ring) {
            touching.push(ring);
        }
    }
    let mut winding: i64 = 0;
    for n in cx.bands.query(pv.y, pv.y) {
        let node = cx.pool.get(n);
        let ring = node.ring;
        if ring as usize == b
            || node.removed
            || !cx.rings[ring as usize].alive
            || touching.contains(&ring)
        {
            continue;
        }
        winding += crossing(node.p, cx.pool.p(node.next), pv);
    }
    let mut depth = winding.max(0) as u32;
    for k in 0..cx.order.len() {
        let r = cx.order[k] as usize;
        if locally_inside(cx, v, r)? {
            depth += 1;
        }
    }
    Some(depth)
}

/// Signed crossing of the ray from `v` towards +x with the edge a → b (half-open in y, so
/// a vertex on the ray counts once): +1 upwards, −1 downwards, 0 when missed.
fn crossing(a: Point, b: Point, v: Point) -> i64 {
    if a.y <= v.y && v.y < b.y && left_of(a, b, v) {
        1
    } else if b.y <= v.y && v.y < a.y && orient2d(a, b, v) == Orientation::Clockwise {
        -1
    } else {
        0
    }
}

/// Whether ring `b`'s corner at node `v` lies inside ring `r`, which passes through `v`'s
/// position: inside one of `r`'s corners there, or on the inner side of an edge of `r`
/// running through it. `None` when a corner of `r` there is the very same corner.
fn locally_inside(cx: &Context, v: NodeId, r: usize) -> Option<bool> {
    let pv = cx.pool.p(v);
    let (vn, vp) = (cx.pool.p(cx.pool.next(v)), cx.pool.p(cx.pool.prev(v)));
    let mut inside = false;
    for n in cx.bands.query(pv.y, pv.y) {
        let node = cx.pool.get(n);
        if node.ring as usize != r || node.removed {
            continue;
        }
        let next = cx.pool.p(node.next);
        if node.p == pv {
            let prev = cx.pool.p(node.prev);
            match corner_contains(pv, next, prev, vn)
                .or_else(|| corner_contains(pv, next, prev, vp))
            {
                Some(true) => inside = true,
                Some(false) => {}
                // b's edges run along both of r's: complementary corners are disjoint,
                // identical ones undecidable here
                None if same_ray(pv, vn, prev) => {}
                None => return None,
            }
        } else if next != pv && on_segment(node.p, next, pv) {
            // V inside an edge of r (only after a lenient repair): the edge's left side
            inside |= left_of(node.p, next, vn) || left_of(node.p, next, vp);
        }
    }
    Some(inside)
}

/// Whether the direction from `o` to `q` lies inside the corner at `o` swept
/// counter-clockwise from `o → a` to `o → b`: `Some(true)` strictly inside, `Some(false)`
/// strictly outside, `None` along one of its two sides.
pub(crate) fn corner_contains(o: Point, a: Point, b: Point, q: Point) -> Option<bool> {
    let qa = orient2d(o, a, q);
    let qb = orient2d(o, b, q);
    if (qa == Orientation::Collinear && same_ray(o, a, q))
        || (qb == Orientation::Collinear && same_ray(o, b, q))
    {
        return None;
    }
    let inside = match orient2d(o, a, b) {
        // convex corner: left of o→a and right of o→b
        Orientation::CounterClockwise => {
            qa == Orientation::CounterClockwise && qb == Orientation::Clockwise
        }
        // reflex corner: the complement of the convex corner from o→b to o→a
        Orientation::Clockwise => {
            qa == Orientation::CounterClockwise || qb == Orientation::Clockwise
        }
        // straight corner (a, o, b on a line, opposite rays): the left half-plane of o→a;
        // a zero-width corner (same ray) contains nothing
        Orientation::Collinear => !same_ray(o, a, b) && qa == Orientation::CounterClockwise,
    };
    Some(inside)
}

/// For points known to be collinear with `o`: whether `a` and `q` lie on the same ray from
/// `o` (exact: coordinate comparisons only).
pub(crate) fn same_ray(o: Point, a: Point, q: Point) -> bool {
    let sx = |p: Point| p.x.partial_cmp(&o.x);
    let sy = |p: Point| p.y.partial_cmp(&o.y);
    sx(a) == sx(q) && sy(a) == sy(q) && (a != o) && (q != o)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn corner_tests() {
        let o = p(0., 0.);
        // convex corner from +x to +y
        assert_eq!(
            corner_contains(o, p(1., 0.), p(0., 1.), p(1., 1.)),
            Some(true)
        );
        assert_eq!(
            corner_contains(o, p(1., 0.), p(0., 1.), p(-1., -1.)),
            Some(false)
        );
        assert_eq!(corner_contains(o, p(1., 0.), p(0., 1.), p(2., 0.)), None);
        // reflex corner from +y to +x (270°)
        assert_eq!(
            corner_contains(o, p(0., 1.), p(1., 0.), p(-1., -1.)),
            Some(true)
        );
        assert_eq!(
            corner_contains(o, p(0., 1.), p(1., 0.), p(1., 1.)),
            Some(false)
        );
        assert_eq!(
            corner_contains(o, p(0., 1.), p(1., 0.), p(-1., 0.)),
            Some(true)
        );
        assert_eq!(
            corner_contains(o, p(0., 1.), p(1., 0.), p(0., -1.)),
            Some(true)
        );
        // straight corner from +x to -x: the upper half-plane
        assert_eq!(
            corner_contains(o, p(1., 0.), p(-1., 0.), p(0., 1.)),
            Some(true)
        );
        assert_eq!(
            corner_contains(o, p(1., 0.), p(-1., 0.), p(0., -1.)),
            Some(false)
        );
    }
}
