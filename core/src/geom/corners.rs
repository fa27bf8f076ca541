//! Exact tests on corners and rays at a vertex: whether a direction leaves a vertex into
//! the corner between two edges, whether points lie on one ray from it, and which vertex
//! a hole's bridge sees at the smallest angle to its ray.

use super::predicates::{cmp_around, left_of, orient2d, Orientation, Point};

/// Whether the direction from `o` to `q` lies inside the corner at `o` swept
/// counter-clockwise from `o → a` to `o → b`: `Some(true)` strictly inside, `Some(false)`
/// strictly outside, `None` along one of its two sides.
#[inline]
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

/// Whether `q` lies on the ray from `o` through `a` (`a`, `q` ≠ `o`). Exact.
pub(crate) fn on_ray(o: Point, a: Point, q: Point) -> bool {
    orient2d(o, a, q) == Orientation::Collinear && same_ray(o, a, q)
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

/// Bridging a hole (Eberly's method): the vertex M sees instead of P when the ray from M
/// towards +x hits edge a → b inside, at I, and P is the edge's endpoint with larger x.
/// Every vertex inside triangle M, I, P or on segment MP may block the view; the one at
/// the smallest angle to the ray, then the nearest, is visible. Offer the candidates
/// with [`LeastAngle::offer`] (after [`LeastAngle::near`], a cheap first look), then read
/// [`LeastAngle::best`]: P if none blocked it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LeastAngle {
    m: Point,
    a: Point,
    b: Point,
    p: Point,
    above: bool,
    /// The triangle's rows.
    ylo: f64,
    yhi: f64,
    /// The side of M → P outside the triangle.
    outside_mp: Orientation,
    best: Point,
}

impl LeastAngle {
    /// The search from `m` over the triangle of the hit on edge `a` → `b`, whose endpoint
    /// with larger x is `p`.
    pub(crate) fn new(m: Point, a: Point, b: Point, p: Point) -> Self {
        let above = p.y > m.y;
        let (ylo, yhi) = if above { (m.y, p.y) } else { (p.y, m.y) };
        // Sides of the triangle: the ray's line (exclusive), the edge's line (exclusive:
        // M's side), and segment MP (inclusive: a vertex on it blocks the bridge).
        let outside_mp = if above {
            Orientation::CounterClockwise
        } else {
            Orientation::Clockwise
        };
        LeastAngle {
            m,
            a,
            b,
            p,
            above,
            ylo,
            yhi,
            outside_mp,
            best: p,
        }
    }

    /// The box the triangle lies in (lower left, upper right), for an index query.
    pub(crate) fn bounds(&self) -> (Point, Point) {
        let hi = Point::new(self.a.x.max(self.b.x), self.yhi);
        (Point::new(self.m.x, self.ylo), hi)
    }

    /// Whether a vertex at `q` may lie in the triangle, by coordinates alone: strictly
    /// beside the ray, within its rows, not left of M, and not P.
    #[inline]
    pub(crate) fn near(&self, q: Point) -> bool {
        let beside = if self.above {
            q.y > self.m.y
        } else {
            q.y < self.m.y
        };
        beside && q.y >= self.ylo && q.y <= self.yhi && q.x >= self.m.x && q != self.p
    }

    /// Keeps a vertex at `q` (one [`LeastAngle::near`] accepted) as the best when it lies
    /// in the triangle at a smaller angle to the ray, or at the same angle nearer.
    pub(crate) fn offer(&mut self, q: Point) {
        if !left_of(self.a, self.b, q) || orient2d(self.m, self.p, q) == self.outside_mp {
            return;
        }
        // smaller angle to the ray: clockwise of the best seen from M when above, else
        // counter-clockwise; the same angle: nearer
        let better = match orient2d(self.m, self.best, q) {
            Orientation::Collinear => q.x < self.best.x,
            t => t == self.outside_mp.reversed(),
        };
        if better {
            self.best = q;
        }
    }

    /// The visible vertex's position.
    pub(crate) fn best(&self) -> Point {
        self.best
    }
}

/// Rotating clockwise around `o` from the direction towards `back`: whether the direction
/// towards `u` comes strictly before the direction towards `w`. An edge straight back comes
/// first: with the arriving edge it forms a zero-width wall (a hole sharing an edge with its
/// outer ring, say), enclosing nothing, which becomes a ring of its own and vanishes.
pub(crate) fn clockwise_before(o: Point, back: Point, u: Point, w: Point) -> bool {
    let (ru, rw) = (rank(o, back, u), rank(o, back, w));
    if ru != rw {
        return ru < rw;
    }
    // same half-plane: u first when w lies clockwise of it
    (ru == 1 || ru == 3) && orient2d(o, u, w) == Orientation::Clockwise
}

/// Where the direction towards `q` lies, seen clockwise from the direction towards `back`:
/// 0 along it, 1 right of it, 2 straight opposite, 3 left of it.
fn rank(o: Point, back: Point, q: Point) -> u8 {
    match orient2d(o, back, q) {
        Orientation::Collinear if same_ray(o, back, q) => 0,
        Orientation::Clockwise => 1,
        Orientation::Collinear => 2,
        Orientation::CounterClockwise => 3,
    }
}

/// The face-walk rule where edges at `o` share directions (a segment walked both ways, or
/// several times), as `touch` relinks such positions: `ends` are the edges at `o`, each by
/// its far end, an id (the node at `o` for an arriving edge, the far node for a leaving
/// one) and whether it arrives, sorted counter-clockwise round `o` (the edges of one
/// direction, a bundle, in a fixed order). Around a position of a weakly simple boundary
/// arriving and leaving edges alternate, and the edges of a bundle lie on one another, so
/// their order within it is free: each bundle is arranged so that they alternate, the
/// first edge arriving or not as `first_arrives` says, and each arriving edge continues
/// along the leaving edge just clockwise of it (the one before it), given to `pair`
/// (arriving, leaving). False when they cannot alternate so, or `pair` says stop.
pub(crate) fn pair_alternating<I: Copy>(
    o: Point,
    ends: &[(Point, I, bool)],
    first_arrives: bool,
    mut pair: impl FnMut(I, I) -> bool,
) -> bool {
    let mut expect = first_arrives;
    let mut last_out: Option<I> = None;
    // an arriving edge placed first waits for the last leaving one (the order is cyclic)
    let mut first_in: Option<I> = None;
    let mut k = 0;
    while k < ends.len() {
        let e = bundle_end(o, ends, k);
        let bundle = &ends[k..e];
        let ins = bundle.iter().filter(|x| x.2).count();
        let outs = bundle.len() - ins;
        let (want, other) = if expect { (ins, outs) } else { (outs, ins) };
        if want != other && want != other + 1 {
            return false;
        }
        // the expected kind first, then alternately
        let mut arriving = bundle.iter().filter(|x| x.2);
        let mut leaving = bundle.iter().filter(|x| !x.2);
        for step in 0..bundle.len() {
            if (step % 2 == 0) == expect {
                let Some(&(_, n, _)) = arriving.next() else {
                    return false;
                };
                match last_out {
                    Some(target) if !pair(n, target) => return false,
                    Some(_) => {}
                    None => first_in = Some(n),
                }
            } else {
                let Some(&(_, target, _)) = leaving.next() else {
                    return false;
                };
                last_out = Some(target);
            }
        }
        if want > other {
            expect = !expect;
        }
        k = e;
    }
    if expect != first_arrives {
        return false;
    }
    match (first_in, last_out) {
        (Some(n), Some(target)) => pair(n, target),
        (Some(_), None) => false,
        (None, _) => true,
    }
}

/// Whether the region lies on both sides of a segment walked both ways from `o` towards
/// `x` (a crack into it, not a wall), read at `o` from its edges: `nets` holds each
/// edge's far end with +1 for an edge arriving at `o`, -1 for one leaving. Just
/// counter-clockwise of an arriving edge lies the outside, of a leaving one the inside;
/// edges of one direction count by their sum, and doubled ones (summing to 0) change
/// nothing. `None` when every direction there is doubled, or none runs towards `x` with
/// a sum of 0. Sorts and merges `nets` in place.
pub(crate) fn inside_along(o: Point, nets: &mut [(Point, i32)], x: Point) -> Option<bool> {
    // (the order within a direction does not matter: its edges are summed)
    nets.sort_unstable_by(|a, b| cmp_around(o, a.0, b.0));
    let mut m = 0;
    for k in 0..nets.len() {
        if m > 0 && cmp_around(o, nets[m - 1].0, nets[k].0) == core::cmp::Ordering::Equal {
            nets[m - 1].1 += nets[k].1;
        } else {
            nets[m] = nets[k];
            m += 1;
        }
    }
    let bundles = &nets[..m];
    let last = bundles.iter().rposition(|b| b.1 != 0)?;
    let mut inside = bundles[last].1 < 0;
    for k in 0..bundles.len() {
        let b = bundles[(last + 1 + k) % bundles.len()];
        if b.1 != 0 {
            inside = b.1 < 0;
        } else if cmp_around(o, b.0, x) == core::cmp::Ordering::Equal {
            return Some(inside);
        }
    }
    None
}

/// The end of the bundle starting at `ends[k]`: the run of ends in its direction from `o`.
pub(crate) fn bundle_end<I>(o: Point, ends: &[(Point, I, bool)], k: usize) -> usize {
    let mut e = k + 1;
    while e < ends.len() && cmp_around(o, ends[k].0, ends[e].0) == core::cmp::Ordering::Equal {
        e += 1;
    }
    e
}

/// A ring's rightmost-lowest visit, as `touch` reads a traced ring's role there: of the
/// visits at the rightmost-lowest position, the first, or the first turning clockwise (a
/// hole's M: the ray leaves from its corner); whether that one turns clockwise (a hole),
/// whether any visit there turns, and whether the whole ring is straight (a wall).
#[derive(Clone, Copy, Debug)]
pub(crate) struct RightmostVisit<N> {
    pub node: N,
    p: Point,
    pub hole: bool,
    pub turns: bool,
    pub flat: bool,
}

impl<N: Copy> RightmostVisit<N> {
    /// Before the first visit, which is `node` at `p`.
    pub(crate) fn new(node: N, p: Point) -> Self {
        RightmostVisit {
            node,
            p,
            hole: false,
            turns: false,
            flat: true,
        }
    }

    /// The ring visits `node` at `p`, turning `turn` there.
    pub(crate) fn visit(&mut self, node: N, p: Point, turn: Orientation) {
        self.flat &= turn == Orientation::Collinear;
        let cw = turn == Orientation::Clockwise;
        if p.x > self.p.x || (p.x == self.p.x && p.y < self.p.y) {
            (self.node, self.p) = (node, p);
            (self.hole, self.turns) = (cw, turn != Orientation::Collinear);
        } else if p == self.p {
            self.turns |= turn != Orientation::Collinear;
            if cw && !self.hole {
                (self.node, self.hole) = (node, true);
            }
        }
    }
}
