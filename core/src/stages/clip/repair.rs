//! Lenient mode's repairs when a ring has no ear left (earcut's order): cure local
//! self-intersections, split the ring along a valid diagonal (`split_earcut`), and only
//! then cut the best triangle it can. Strict mode reports the ring instead.

use super::ear::{crossing_past, sees};
use super::{turn, Clipper};
use crate::geom::{crosses, left_of, orient2d, overlaps, segments_meet, Orientation};
use crate::report::RepairKind;
use crate::structures::NodeId;
use crate::Error;

impl Clipper<'_> {
    /// No ear in a whole lap. A ring enclosing no area is done; otherwise the input was not
    /// valid: strict mode gives up; lenient mode, like earcut, first cures local
    /// self-intersections, then splits the ring along a diagonal, and only then cuts the
    /// best triangle it can. Returns a live node to go on from (`len` is 0 when done).
    pub(super) fn stuck(&mut self, at: NodeId) -> Result<NodeId, Error> {
        let at = self.live(at);
        let convex = |c: &Self, n| turn(c.cx, n) == Orientation::CounterClockwise;
        // (the ring is unchanged until the forced ear below, unless a repair returns first)
        let Some(first_convex) = self.first_until_lap(at, at, convex) else {
            // all straight or reflex: no area left (a counter-clockwise ring with area has
            // a left turn), so this piece is done — unless it turns right somewhere: then
            // it is a lobe winding against the rest of its ring, which strict mode refuses
            if !self.cx.lenient {
                let mut n = at;
                for _ in 0..self.len {
                    if turn(self.cx, n) == Orientation::Clockwise {
                        return Err(self.winds_opposite(n));
                    }
                    n = self.cx.pool.next(n);
                }
            }
            self.note(RepairKind::DegeneratePiece, at);
            self.len = 0;
            return Ok(at);
        };
        if !self.cx.lenient {
            return Err(Error::Internal { stage: "clip" });
        }
        if self.avoid_crossed {
            // only ears at crossed edges are left: allow them and walk again
            self.avoid_crossed = false;
            self.clear_not_ear(at);
            return Ok(at);
        }
        if let Some(n) = self.cure_local_intersections(at) {
            return Ok(n);
        }
        if self.split_earcut(at) {
            self.len = 0;
            return Ok(at);
        }
        // the first convex corner with no vertex inside, else the first convex one
        let tip = self
            .first_until_lap(first_convex, at, |c, n| {
                convex(c, n) && !c.has_vertex_inside(n)
            })
            .unwrap_or(first_convex);
        self.note(RepairKind::ForcedEar, tip);
        Ok(self.cut(tip))
    }

    /// The first node from `from` on, before the walk comes round to `at`, that passes
    /// `test`.
    fn first_until_lap(
        &self,
        from: NodeId,
        at: NodeId,
        test: impl Fn(&Self, NodeId) -> bool,
    ) -> Option<NodeId> {
        let mut n = from;
        for _ in 0..self.len {
            if test(self, n) {
                return Some(n);
            }
            n = self.cx.pool.next(n);
            if n == at {
                break;
            }
        }
        None
    }

    /// Records a lenient repair at node `n`.
    fn note(&mut self, kind: RepairKind, n: NodeId) {
        if self.cx.lenient {
            let node = self.cx.pool.get(n);
            let input = self.cx.rings[node.ring as usize].input;
            let vertex = node.vertex;
            self.cx.repair(kind, input, vertex);
        }
    }

    /// earcut's `cureLocalIntersections`: where edge a → p crosses edge q → b two steps
    /// on (a self-intersection as in a bow tie), cut triangle a, p, b and drop p and q.
    /// Returns a node to go on from when anything was cured.
    fn cure_local_intersections(&mut self, start: NodeId) -> Option<NodeId> {
        let mut p = start;
        let mut cured = None;
        for _ in 0..self.len {
            if self.len <= 3 {
                break;
            }
            if let Some((a, q, b)) = self.local_crossing_at(p) {
                let pool = &self.cx.pool;
                match orient2d(pool.p(a), pool.p(p), pool.p(b)) {
                    Orientation::CounterClockwise => self.emit(a, p, b),
                    Orientation::Clockwise => self.emit(a, b, p),
                    Orientation::Collinear => {}
                }
                self.note(RepairKind::ForcedEar, p);
                self.unlink(p);
                self.unlink(q);
                self.tidy(a);
                self.tidy(b);
                cured = Some(if self.cx.pool.get(b).removed { a } else { b });
                p = cured.unwrap_or(a);
            }
            p = self.cx.pool.next(p);
        }
        cured
    }

    /// (a, q, b) = (prev(p), next(p), next(next(p))) where edge a → p crosses edge q → b
    /// and each end sees the other (what [`Clipper::cure_local_intersections`] cures at p).
    fn local_crossing_at(&self, p: NodeId) -> Option<(NodeId, NodeId, NodeId)> {
        let pool = &self.cx.pool;
        let (a, q) = (pool.prev(p), pool.next(p));
        let b = pool.next(q);
        let (pa, pp, pq, pb) = (pool.p(a), pool.p(p), pool.p(q), pool.p(b));
        let crossing =
            pa != pb && crosses(pa, pp, pq, pb) && sees(pool, a, pb) && sees(pool, b, pa);
        crossing.then_some((a, q, b))
    }

    /// earcut's `splitEarcut`: find a diagonal a–b that crosses no edge and leaves both
    /// ends inwards, split the ring there and queue both halves. The search is quadratic
    /// in candidates and linear per check, so it stops after a fixed budget of edge tests
    /// (the forced ear takes over then).
    fn split_earcut(&mut self, start: NodeId) -> bool {
        let mut a = start;
        for _ in 0..self.len {
            let pool = &self.cx.pool;
            let mut b = pool.next(pool.next(a));
            while b != pool.prev(a) {
                if self.s.split_budget < self.len {
                    return false;
                }
                self.s.split_budget -= self.len;
                if self.is_valid_diagonal(a, b) {
                    let c = self.cx.pool.split(a, b);
                    self.note(RepairKind::ForcedEar, a);
                    self.s.pending.push(a);
                    self.s.pending.push(c);
                    return true;
                }
                b = self.cx.pool.next(b);
            }
            a = self.cx.pool.next(a);
        }
        false
    }

    /// A diagonal a–b between distinct positions that leaves both ends inwards, crosses or
    /// touches no edge of the ring, and runs inside it: the ring winds counter-clockwise
    /// around it (earcut's `middleInside`). Where the ring crosses itself, a diagonal can
    /// pass the tests at both ends and still run across a region the ring does not enclose
    /// (a peninsula between two of its arms); both pieces would then wind around that
    /// region, and clipping the counter-clockwise one fills it with triangles. A diagonal
    /// along an edge of the ring has the ring's inside on one side only; it only separates
    /// the loop between the edge's ends, and stays allowed.
    fn is_valid_diagonal(&self, a: NodeId, b: NodeId) -> bool {
        let pool = &self.cx.pool;
        let (pa, pb) = (pool.p(a), pool.p(b));
        if pa == pb || !sees(pool, a, pb) || !sees(pool, b, pa) {
            return false;
        }
        // no edge meets the open diagonal, so the ring winds around all of it as around
        // its first point
        let mut winding = 0;
        let mut along_edge = false;
        let mut e = a;
        // `a` is live, so the walk comes back to it after `len` edges; the bound only keeps
        // a broken ring from looping forever.
        for _ in 0..=self.len {
            let f = pool.next(e);
            let (pe, pf) = (pool.p(e), pool.p(f));
            // edges at a or b may touch the diagonal at its ends only
            if pe != pa && pe != pb && pf != pa && pf != pb && segments_meet(pa, pb, pe, pf) {
                return false;
            }
            if (pe == pa || pe == pb || pf == pa || pf == pb) && overlaps(pa, pb, pe, pf) {
                return false;
            }
            if (pe == pa && pf == pb) || (pe == pb && pf == pa) {
                along_edge = true;
            } else {
                winding += crossing_past(pe, pf, pa, pb);
            }
            e = f;
            if e == a {
                return along_edge || winding > 0;
            }
        }
        false
    }

    /// Lenient fallback test: some reflex vertex strictly inside the triangle at `ear`.
    fn has_vertex_inside(&self, ear: NodeId) -> bool {
        let (a, b, c) = self.corner(ear);
        self.any_reflex_near(a, b, c, |_, q| {
            left_of(a, b, q) && left_of(b, c, q) && left_of(c, a, q)
        })
    }
}
