//! The trapezoidal map and its history DAG (Seidel 1991): segments inserted one at a time,
//! each new endpoint located (in the DAG, or by a walk along the segment from its other
//! end) and cut in, the trapezoids the segment crosses split and merged.
//!
//! Everything lives in index arenas (`Vec`s): trapezoids, DAG nodes, segments. A trapezoid
//! keeps its index for its whole life — a split reuses it for one of the pieces — so the
//! map never frees anything, and its size is fixed by the input: one trapezoid to start,
//! one more per point and one more per segment.
//!
//! See the module documentation of [`super`] for the degeneracies (the symbolic shear,
//! shared endpoints).

use crate::geom::{orient2d, Orientation, Point};
use crate::Error;

/// No index: an unbounded side of a trapezoid, a missing neighbour, a point not inserted.
pub(super) const NONE: u32 = u32::MAX;

/// The error every broken invariant gives.
pub(super) const BROKEN: Error = Error::Internal { stage: "seidel" };

/// A ring edge as the map sees it: its upper and lower endpoints (in the sheared order)
/// and whether the ring runs upward along it (from `lo` to `hi`).
#[derive(Clone, Copy, Debug)]
pub(super) struct Seg {
    pub hi: u32,
    pub lo: u32,
    pub up: bool,
}

/// A trapezoid of the map: between the horizontal lines through `top` and `bot` (points;
/// [`NONE`] for ±∞) and between the segments `lseg` and `rseg` ([`NONE`]: unbounded).
/// `u` and `d` are its neighbours above and below that share a stretch of positive width
/// with it, left one first ([`NONE`] where there are fewer than two); `sink` is its leaf in
/// the DAG.
#[derive(Clone, Copy, Debug)]
pub(super) struct Trap {
    pub top: u32,
    pub bot: u32,
    pub lseg: u32,
    pub rseg: u32,
    pub u: [u32; 2],
    pub d: [u32; 2],
    pub sink: u32,
}

/// A node of the history DAG, 16 bytes: `key` holds the kind in its top two bits and a
/// point or trapezoid index below.
/// - X-node: above or below the point `key`? (`left`: below, `right`: above)
/// - Y-node: left or right of the segment from the point `key` (lower end) to the point
///   `hi`? (Keeping the ends saves a look-up of the segment on the search path.)
/// - leaf: the trapezoid `key`.
#[derive(Clone, Copy, Debug)]
struct Node {
    key: u32,
    hi: u32,
    left: u32,
    right: u32,
}

const X_NODE: u32 = 0;
const Y_NODE: u32 = 1 << 30;
const LEAF: u32 = 2 << 30;
const KIND: u32 = 3 << 30;

/// The DAG's root.
const ROOT: u32 = 0;

/// The most points, segments or trapezoids the node keys can name.
pub(super) const MAX_INDEX: usize = (1 << 30) - 1;

/// The trapezoidal map, the DAG, and each point's DAG entries.
#[derive(Debug, Default)]
pub(super) struct Map {
    /// The segments (ring edges), in ring order.
    pub segs: Vec<Seg>,
    /// Every trapezoid ever made (all alive: indices are reused, never freed).
    pub traps: Vec<Trap>,
    nodes: Vec<Node>,
    /// Per point: the X-node made when it was inserted, or [`NONE`].
    xnode: Vec<u32>,
}

/// The position of point `i`.
#[inline]
pub(super) fn point(pts: &[[f64; 2]], i: u32) -> Result<Point, Error> {
    let p = pts.get(i as usize).ok_or(BROKEN)?;
    Ok(Point::new(p[0], p[1]))
}

/// The sheared order: `a` lies above `b` when higher, or as high and further right.
#[inline]
pub(super) fn above(a: Point, b: Point) -> bool {
    a.y > b.y || (a.y == b.y && a.x > b.x)
}

/// The number of entries of a neighbour pair.
#[inline]
fn count(pair: [u32; 2]) -> usize {
    usize::from(pair[0] != NONE) + usize::from(pair[1] != NONE)
}

impl Map {
    /// Empties the map: one unbounded trapezoid, the root, for `npoints` points.
    pub fn reset(&mut self, npoints: usize) {
        self.traps.clear();
        self.nodes.clear();
        self.xnode.clear();
        self.xnode.resize(npoints, NONE);
        self.traps.push(Trap {
            top: NONE,
            bot: NONE,
            lseg: NONE,
            rseg: NONE,
            u: [NONE; 2],
            d: [NONE; 2],
            sink: 0,
        });
        self.nodes.push(Node {
            key: LEAF,
            hi: NONE,
            left: NONE,
            right: NONE,
        });
    }

    #[inline]
    pub fn trap(&self, t: u32) -> Result<Trap, Error> {
        self.traps.get(t as usize).copied().ok_or(BROKEN)
    }

    #[inline]
    fn trap_mut(&mut self, t: u32) -> Result<&mut Trap, Error> {
        self.traps.get_mut(t as usize).ok_or(BROKEN)
    }

    #[inline]
    pub fn seg(&self, s: u32) -> Result<Seg, Error> {
        self.segs.get(s as usize).copied().ok_or(BROKEN)
    }

    #[inline]
    fn node_mut(&mut self, n: u32) -> Result<&mut Node, Error> {
        self.nodes.get_mut(n as usize).ok_or(BROKEN)
    }

    /// A new leaf for trapezoid `t`.
    fn new_sink(&mut self, t: u32) -> Result<u32, Error> {
        // node indices are u32, and NONE is not one
        if self.nodes.len() >= NONE as usize {
            return Err(BROKEN);
        }
        self.nodes.push(Node {
            key: LEAF | t,
            hi: NONE,
            left: NONE,
            right: NONE,
        });
        Ok((self.nodes.len() - 1) as u32)
    }

    /// In trapezoid `t`'s upper neighbours, `from` becomes `to`.
    fn relink_up(&mut self, t: u32, from: u32, to: u32) -> Result<(), Error> {
        if from == to {
            return Ok(());
        }
        let tr = self.trap_mut(t)?;
        let k = tr.u.iter().position(|&x| x == from).ok_or(BROKEN)?;
        tr.u[k] = to;
        Ok(())
    }

    /// In trapezoid `t`'s lower neighbours, `from` becomes `to`.
    fn relink_down(&mut self, t: u32, from: u32, to: u32) -> Result<(), Error> {
        if from == to {
            return Ok(());
        }
        let tr = self.trap_mut(t)?;
        let k = tr.d.iter().position(|&x| x == from).ok_or(BROKEN)?;
        tr.d[k] = to;
        Ok(())
    }

    /// The trapezoid containing point `p` moved an infinitesimal step towards `q` (the
    /// other end of its segment), searched from DAG node `start`. At an X-node of `p`
    /// itself the step decides (is `q` above `p`?); at a Y-node of a segment through `p`
    /// (one ending there) `q`'s side decides.
    pub fn locate(&self, pts: &[[f64; 2]], start: u32, p: u32, q: u32) -> Result<u32, Error> {
        let (pp, qp) = (point(pts, p)?, point(pts, q)?);
        let mut n = start;
        // a path in a DAG visits each node at most once
        for _ in 0..=self.nodes.len() {
            let node = self.nodes.get(n as usize).ok_or(BROKEN)?;
            let key = node.key & !KIND;
            n = match node.key & KIND {
                LEAF => return Ok(key),
                X_NODE => {
                    let v = point(pts, key)?;
                    let up = if key == p { above(qp, v) } else { above(pp, v) };
                    if up {
                        node.right
                    } else {
                        node.left
                    }
                }
                Y_NODE => {
                    let (lo, hi) = (point(pts, key)?, point(pts, node.hi)?);
                    let side = match orient2d(lo, hi, pp) {
                        Orientation::Collinear => orient2d(lo, hi, qp),
                        o => o,
                    };
                    match side {
                        Orientation::CounterClockwise => node.left,
                        Orientation::Clockwise => node.right,
                        Orientation::Collinear => return Err(BROKEN),
                    }
                }
                _ => return Err(BROKEN),
            };
        }
        Err(BROKEN)
    }

    /// Inserts the new point `p` into the trapezoid `t` containing it: `t` is cut by the
    /// horizontal line through `p`. Returns the lower half (the upper half keeps the
    /// index `t`).
    fn insert_point(&mut self, pts: &[[f64; 2]], t: u32, p: u32) -> Result<u32, Error> {
        let old = self.trap(t)?;
        let pp = point(pts, p)?;
        if (old.top != NONE && !above(point(pts, old.top)?, pp))
            || (old.bot != NONE && !above(pp, point(pts, old.bot)?))
        {
            return Err(BROKEN);
        }
        let lower = self.traps.len() as u32;
        let sink_lower = self.new_sink(lower)?;
        let sink_upper = self.new_sink(t)?;
        self.traps.push(Trap {
            top: p,
            bot: old.bot,
            lseg: old.lseg,
            rseg: old.rseg,
            u: [t, NONE],
            d: old.d,
            sink: sink_lower,
        });
        for x in old.d {
            if x != NONE {
                self.relink_up(x, t, lower)?;
            }
        }
        let upper = self.trap_mut(t)?;
        upper.bot = p;
        upper.d = [lower, NONE];
        upper.sink = sink_upper;
        *self.node_mut(old.sink)? = Node {
            key: X_NODE | p,
            hi: NONE,
            left: sink_lower,
            right: sink_upper,
        };
        *self.xnode.get_mut(p as usize).ok_or(BROKEN)? = old.sink;
        Ok(lower)
    }

    /// Inserts segment `s`: its new endpoints, then the segment through every trapezoid
    /// it crosses.
    pub fn insert_segment(&mut self, pts: &[[f64; 2]], s: u32) -> Result<(), Error> {
        let seg = self.seg(s)?;
        let (p, q) = (seg.hi, seg.lo);
        let xp = *self.xnode.get(p as usize).ok_or(BROKEN)?;
        let xq = *self.xnode.get(q as usize).ok_or(BROKEN)?;
        // `first`: the trapezoid just below p that s runs into. A new end is found by
        // walking along s from the other end where that one is known: through the
        // trapezoids the thread is about to split, instead of down the DAG.
        let first = match (xp == NONE, xq == NONE) {
            (true, true) => {
                let t = self.locate(pts, ROOT, p, q)?;
                // the lower half lies just below p, across the whole width: where s
                // starts (cutting it at q keeps this index for the part above q)
                let first = self.insert_point(pts, t, p)?;
                let t = self.walk(pts, first, p, q)?;
                self.insert_point(pts, t, q)?;
                first
            }
            (true, false) => {
                let t = self.locate(pts, xq, q, p)?;
                let t = self.walk(pts, t, q, p)?;
                self.insert_point(pts, t, p)?
            }
            (false, true) => {
                let first = self.locate(pts, xp, p, q)?;
                let t = self.walk(pts, first, p, q)?;
                self.insert_point(pts, t, q)?;
                first
            }
            (false, false) => self.locate(pts, xp, p, q)?,
        };
        self.thread(pts, s, seg, first)
    }

    /// Splits the trapezoids segment `s` crosses, from `first` (just below its upper end)
    /// down to the one above its lower end, into a left and a right piece each; pieces on
    /// a side where no point separates them merge.
    fn thread(&mut self, pts: &[[f64; 2]], s: u32, seg: Seg, first: u32) -> Result<(), Error> {
        let (p, q) = (seg.hi, seg.lo);
        let (hi, lo) = (point(pts, p)?, point(pts, q)?);
        let mut t = first;
        // the previous trapezoid (its index and fields before the split), its pieces, and
        // the side of the point between it and the current one
        let mut prev_t = NONE;
        let mut prev_old = self.trap(first)?;
        let (mut prev_l, mut prev_r) = (NONE, NONE);
        let mut v_left = false;
        for _ in 0..self.traps.len() {
            let old = self.trap(t)?;
            let (l, r);
            if prev_t == NONE {
                if old.top != p {
                    return Err(BROKEN);
                }
                l = t;
                r = self.traps.len() as u32;
                self.traps.push(old);
                let sl = self.new_sink(l)?;
                let sr = self.new_sink(r)?;
                *self.trap_mut(l)? = Trap {
                    rseg: s,
                    u: [NONE; 2],
                    d: [NONE; 2],
                    sink: sl,
                    ..old
                };
                *self.trap_mut(r)? = Trap {
                    lseg: s,
                    u: [NONE; 2],
                    d: [NONE; 2],
                    sink: sr,
                    ..old
                };
                self.link_top(p, t, &old, l, r)?;
            } else if v_left {
                // the point between lies left of s: the right pieces merge
                r = prev_r;
                l = t;
                if self.trap(r)?.rseg != old.rseg {
                    return Err(BROKEN);
                }
                let sl = self.new_sink(l)?;
                let u = match (old.u, count(old.u)) {
                    ([other, x], 2) if x == prev_t => [other, prev_l],
                    ([x, NONE], 1) if x == prev_t => [prev_l, NONE],
                    _ => return Err(BROKEN),
                };
                *self.trap_mut(l)? = Trap {
                    rseg: s,
                    u,
                    d: [NONE; 2],
                    sink: sl,
                    ..old
                };
                let d = match (prev_old.d, count(prev_old.d)) {
                    ([other, x], 2) if x == t => {
                        self.relink_up(other, prev_t, prev_l)?;
                        [other, l]
                    }
                    ([x, NONE], 1) if x == t => [l, NONE],
                    _ => return Err(BROKEN),
                };
                self.trap_mut(prev_l)?.d = d;
                self.trap_mut(r)?.bot = old.bot;
            } else {
                // right of s: the left pieces merge
                l = prev_l;
                r = t;
                if self.trap(l)?.lseg != old.lseg {
                    return Err(BROKEN);
                }
                let sr = self.new_sink(r)?;
                let u = match (old.u, count(old.u)) {
                    ([x, other], 2) if x == prev_t => [prev_r, other],
                    ([x, NONE], 1) if x == prev_t => [prev_r, NONE],
                    _ => return Err(BROKEN),
                };
                *self.trap_mut(r)? = Trap {
                    lseg: s,
                    u,
                    d: [NONE; 2],
                    sink: sr,
                    ..old
                };
                let d = match (prev_old.d, count(prev_old.d)) {
                    ([x, other], 2) if x == t => {
                        self.relink_up(other, prev_t, prev_r)?;
                        [r, other]
                    }
                    ([x, NONE], 1) if x == t => [r, NONE],
                    _ => return Err(BROKEN),
                };
                self.trap_mut(prev_r)?.d = d;
                self.trap_mut(l)?.bot = old.bot;
            }
            // the old leaf asks for the side of s
            let (sl, sr) = (self.trap(l)?.sink, self.trap(r)?.sink);
            *self.node_mut(old.sink)? = Node {
                key: Y_NODE | q,
                hi: p,
                left: sl,
                right: sr,
            };
            if old.bot == q {
                return self.link_bottom(q, t, &old, l, r);
            }
            if old.bot == NONE {
                return Err(BROKEN);
            }
            v_left = match orient2d(lo, hi, point(pts, old.bot)?) {
                Orientation::CounterClockwise => true,
                Orientation::Clockwise => false,
                Orientation::Collinear => return Err(BROKEN),
            };
            let next = match count(old.d) {
                2 if v_left => old.d[1],
                2 => old.d[0],
                1 => old.d[0],
                _ => return Err(BROKEN),
            };
            prev_t = t;
            prev_old = old;
            prev_l = l;
            prev_r = r;
            t = next;
        }
        Err(BROKEN)
    }

    /// The upper neighbours of the pieces `l` and `r` of trapezoid `t` (fields `old`),
    /// whose top is `p`, the upper end of the new segment.
    fn link_top(&mut self, p: u32, t: u32, old: &Trap, l: u32, r: u32) -> Result<(), Error> {
        let (lu, ru) = match count(old.u) {
            0 => ([NONE; 2], [NONE; 2]),
            // the top edge is split at p: the new segment goes down between the two
            2 => {
                self.relink_down(old.u[0], t, l)?;
                self.relink_down(old.u[1], t, r)?;
                ([old.u[0], NONE], [old.u[1], NONE])
            }
            _ => {
                let above = old.u[0];
                let corner =
                    |seg: u32| -> Result<bool, Error> { Ok(seg != NONE && self.seg(seg)?.hi == p) };
                match (corner(old.lseg)?, corner(old.rseg)?) {
                    // p is the top left corner: the left piece is a triangle below p
                    (true, false) => {
                        self.relink_down(above, t, r)?;
                        ([NONE; 2], [above, NONE])
                    }
                    (false, true) => {
                        self.relink_down(above, t, l)?;
                        ([above, NONE], [NONE; 2])
                    }
                    // p is new, inside the top edge: the trapezoid above has both below
                    (false, false) => {
                        let a = self.trap_mut(above)?;
                        if a.d != [t, NONE] {
                            return Err(BROKEN);
                        }
                        a.d = [l, r];
                        ([above, NONE], [above, NONE])
                    }
                    (true, true) => return Err(BROKEN),
                }
            }
        };
        self.trap_mut(l)?.u = lu;
        self.trap_mut(r)?.u = ru;
        Ok(())
    }

    /// The lower neighbours of the pieces `l` and `r` of trapezoid `t` (fields `old`),
    /// whose bottom is `q`, the lower end of the new segment.
    fn link_bottom(&mut self, q: u32, t: u32, old: &Trap, l: u32, r: u32) -> Result<(), Error> {
        let (ld, rd) = match count(old.d) {
            0 => ([NONE; 2], [NONE; 2]),
            2 => {
                self.relink_up(old.d[0], t, l)?;
                self.relink_up(old.d[1], t, r)?;
                ([old.d[0], NONE], [old.d[1], NONE])
            }
            _ => {
                let below = old.d[0];
                let corner =
                    |seg: u32| -> Result<bool, Error> { Ok(seg != NONE && self.seg(seg)?.lo == q) };
                match (corner(old.lseg)?, corner(old.rseg)?) {
                    (true, false) => {
                        self.relink_up(below, t, r)?;
                        ([NONE; 2], [below, NONE])
                    }
                    (false, true) => {
                        self.relink_up(below, t, l)?;
                        ([below, NONE], [NONE; 2])
                    }
                    (false, false) => {
                        let b = self.trap_mut(below)?;
                        if b.u != [t, NONE] {
                            return Err(BROKEN);
                        }
                        b.u = [l, r];
                        ([below, NONE], [below, NONE])
                    }
                    (true, true) => return Err(BROKEN),
                }
            }
        };
        self.trap_mut(l)?.d = ld;
        self.trap_mut(r)?.d = rd;
        Ok(())
    }

    /// From trapezoid `t` (containing `a`, or `a` moved towards `b`) along the edge `a`–`b`,
    /// which crosses no segment, to the trapezoid containing `b` (not inserted).
    fn walk(&self, pts: &[[f64; 2]], mut t: u32, a: u32, b: u32) -> Result<u32, Error> {
        let (pa, pb) = (point(pts, a)?, point(pts, b)?);
        let up = above(pb, pa);
        let (lo, hi) = if up { (pa, pb) } else { (pb, pa) };
        for _ in 0..self.traps.len() {
            let tr = self.trap(t)?;
            let (v, next) = if up { (tr.top, tr.u) } else { (tr.bot, tr.d) };
            if v == NONE {
                return Ok(t);
            }
            let pv = point(pts, v)?;
            let beyond = if up { above(pv, pb) } else { above(pb, pv) };
            if beyond {
                return Ok(t);
            }
            // across the side at v, into the neighbour the edge passes into
            t = match count(next) {
                2 => match orient2d(lo, hi, pv) {
                    Orientation::CounterClockwise => next[1],
                    Orientation::Clockwise => next[0],
                    Orientation::Collinear => return Err(BROKEN),
                },
                1 => next[0],
                _ => return Err(BROKEN),
            };
        }
        Err(BROKEN)
    }
}
