//! Stage *small*, in place of all the others for one small ring: a polygon without holes
//! of at most [`MAX`] vertices (a county, a building, most strokes of a glyph) in one
//! pass over a few compact arrays.
//!
//! The pipeline's stages are built for any number of rings of any size; on a ring of a
//! dozen vertices their set-up costs more than their work. This stage does what they do
//! for such a ring, in the same order and with the same exact predicates, and gives the
//! same result: the same triangles in the same order, the same dropped vertices.
//!
//! 1. **Load** the vertices, widened to `f64` (exact), linked by one-byte indices.
//! 2. **Filter** repeated and straight vertices exactly as `clean` does, in its order.
//! 3. **Prove** that no two edges meet, other than neighbours at their shared vertex:
//!    every pair whose boxes overlap is decided by exact signs.
//! 4. **Orient** the ring counter-clockwise by the turn at its rightmost-lowest vertex.
//! 5. **Clip** with the strategy's walk (`clip`): the fast one with the same start, the
//!    same "not an ear" marks, the same order of ears and the same fan at the end; the
//!    quality one with the same queue order (smallest angle rank, then vertex). The
//!    reflex vertices are a 64-bit mask.
//!
//! Whatever the pipeline would treat specially makes the stage give up (`false`) before
//! writing anything the pipeline would not: non-finite coordinates, a spike or a ring
//! left with fewer than three vertices, two edges meeting (a crossing, a touch, a
//! repeated position), a clockwise last triangle or a ring the walk cannot finish. The
//! triangulator then runs the pipeline from the start, which finds and reports the same
//! things as without this stage. `core/tests/small.rs` holds the two to the same output.

use crate::context::Context;
use crate::geom::{
    approx_angle_rank, approx_cross, bounds, boxed_segments_meet, interferes, near, orient2d,
    within_box, Coord, Orientation, Point,
};
use crate::report::{DropReason, Dropped};

/// The most vertices (a closing point included) a ring may have to take this stage: its
/// reflex vertices fit one `u64`, its links one byte each.
pub(crate) const MAX: usize = 64;

/// The stage's arrays, by vertex index (which is the node index: one node per vertex).
#[derive(Debug)]
pub(crate) struct Scratch {
    p: [Point; MAX],
    next: [u8; MAX],
    prev: [u8; MAX],
    /// A live vertex of the filtered ring (where the pipeline's ring starts), and the
    /// number of live vertices.
    start: usize,
    len: usize,
    /// The edges' boxes for the proof, in ring order from `start`: x0, x1, y0, y1.
    boxes: [[f64; 4]; MAX],
    /// The start vertex of each of those edges.
    from: [u8; MAX],
    /// The vertices turning left (counter-clockwise) on the filtered ring, as it runs
    /// before `orient`; every other live vertex turns right (none is straight).
    left: u64,
    /// `orient` reversed the ring (it ran clockwise).
    reversed: bool,
    /// Declines every input, for tests holding the stage to the pipeline.
    pub off: bool,
    /// The last call was the stage's (for tests: that it takes what it should).
    pub took: bool,
}

impl Default for Scratch {
    fn default() -> Self {
        Scratch {
            p: [Point::new(0.0, 0.0); MAX],
            next: [0; MAX],
            prev: [0; MAX],
            start: 0,
            len: 0,
            boxes: [[0.0; 4]; MAX],
            from: [0; MAX],
            left: 0,
            reversed: false,
            off: false,
            took: false,
        }
    }
}

impl Scratch {
    fn next(&self, v: usize) -> usize {
        usize::from(self.next[v])
    }

    fn prev(&self, v: usize) -> usize {
        usize::from(self.prev[v])
    }

    /// Unlinks `v` from the ring.
    fn unlink(&mut self, v: usize) {
        let (p, n) = (self.prev[v], self.next[v]);
        self.next[usize::from(p)] = n;
        self.prev[usize::from(n)] = p;
    }
}

/// Whether the stage can take this input: one ring of 3 to [`MAX`] vertices.
pub(crate) fn fits(s: &Scratch, vertices: usize, ring_starts: &[usize]) -> bool {
    !s.off && ring_starts == [0] && (3..=MAX).contains(&vertices)
}

/// Steps 1–4: loads, filters, proves and orients the ring (strict mode's input check).
/// Records the dropped vertices in `cx.dropped` (cleared first). `false` when the ring
/// needs the pipeline; then `cx` holds nothing the pipeline reads (it resets it).
pub(crate) fn check<T: Coord>(cx: &mut Context, s: &mut Scratch, vertices: &[[T; 2]]) -> bool {
    let n = vertices.len();
    if !(3..=MAX).contains(&n) {
        return false;
    }
    cx.dropped.clear();
    cx.repairs.clear();
    // 1. load, as `load` does (−0.0 read as +0.0)
    for (i, v) in vertices.iter().enumerate() {
        let p = Point::new(v[0].to_f64() + 0.0, v[1].to_f64() + 0.0);
        if !(p.x.is_finite() && p.y.is_finite()) {
            return false;
        }
        s.p[i] = p;
        // (n ≤ 64: every index fits a byte)
        s.next[i] = (i + 1) as u8;
        s.prev[i] = i.wrapping_sub(1) as u8;
    }
    (s.next[n - 1], s.prev[0]) = (0, (n - 1) as u8);
    filter(cx, s, n) && (star_shaped(s) || apart(s)) && {
        orient(s);
        true
    }
}

/// Step 2, `clean`'s filter (`filter_ring`) move for move: the same vertices dropped, in
/// the same order, and the same start. `false` on a spike, or when fewer than three
/// vertices are left.
fn filter(cx: &mut Context, s: &mut Scratch, n: usize) -> bool {
    let mut len = n;
    let mut v = 0;
    // the last vertex known good; a full lap without a drop ends the loop
    let mut stop = s.prev(0);
    let drop = |cx: &mut Context, s: &mut Scratch, v: usize, reason: DropReason| {
        s.unlink(v);
        cx.dropped.push(Dropped {
            vertex: v as u32,
            ring: 0,
            reason,
        });
    };
    while len >= 3 {
        let (prev, next) = (s.prev(v), s.next(v));
        let (pp, pn, px) = (s.p[prev], s.p[v], s.p[next]);
        let reason = if pp == pn {
            DropReason::Repeated
        } else if pn == px {
            // the later of two repeated vertices (a closing point, typically)
            drop(cx, s, next, DropReason::Repeated);
            len -= 1;
            stop = prev;
            continue;
        } else if let Some(left) = left_turn(orient2d(pp, pn, px)) {
            // the last turn taken at each vertex is its turn on the filtered ring: once
            // nothing is dropped any more, the walk goes round once more
            s.left = (s.left & !bit(v)) | (u64::from(left) << v);
            if v == stop {
                break;
            }
            v = next;
            continue;
        } else if within_box(pp, px, pn) {
            DropReason::Collinear
        } else {
            // a spike: strict mode looks for a crossing it hid
            return false;
        };
        drop(cx, s, v, reason);
        len -= 1;
        // the previous vertex may have become straight: look again
        v = prev;
        stop = s.prev(prev);
    }
    s.start = v;
    s.len = len;
    len >= 3
}

/// Whether a turn is to the left; `None` when straight.
fn left_turn(o: Orientation) -> Option<bool> {
    match o {
        Orientation::CounterClockwise => Some(true),
        Orientation::Clockwise => Some(false),
        Orientation::Collinear => None,
    }
}

/// Step 3 for most small rings in O(n): whether the filtered ring is star-shaped from the
/// mean of its vertices, c, which proves it simple. If every edge turns strictly the same
/// way round c and the edges wind round c exactly once, their angular sectors (each less
/// than a half-turn) tile the turn round c without overlapping: edges that are no
/// neighbours lie in disjoint sectors and cannot meet, and neighbours meet only on the
/// ray through their shared vertex, at that vertex. (The mean is only a guess at a point
/// of the kernel; the signs decide.) Counting the winding is exact too: with every edge
/// going counter-clockwise round c, exactly the edges from below (or on) c's horizontal
/// line to above it cross that line right of c.
fn star_shaped(s: &Scratch) -> bool {
    let mut v = s.start;
    let (mut sx, mut sy) = (0.0, 0.0);
    for _ in 0..s.len {
        (sx, sy) = (sx + s.p[v].x, sy + s.p[v].y);
        v = s.next(v);
    }
    let c = Point::new(sx / s.len as f64, sy / s.len as f64);
    if !(c.x.is_finite() && c.y.is_finite()) {
        return false;
    }
    let first = orient2d(c, s.p[v], s.p[s.next(v)]);
    if first == Orientation::Collinear {
        return false;
    }
    // counted for the ring as it runs: crossings upwards if it runs counter-clockwise
    // round c, downwards if clockwise
    let up = first == Orientation::CounterClockwise;
    let mut crossings = 0;
    for _ in 0..s.len {
        let (a, b) = (s.p[v], s.p[s.next(v)]);
        if orient2d(c, a, b) != first {
            return false;
        }
        let (low, high) = if up { (a, b) } else { (b, a) };
        crossings += usize::from(low.y <= c.y && c.y < high.y);
        v = s.next(v);
    }
    crossings == 1
}

/// Step 3: whether no two edges of the filtered ring meet, other than neighbours at their
/// shared vertex (which, with no straight turn left, is all neighbours have in common).
/// Then no two vertices share a position either.
fn apart(s: &mut Scratch) -> bool {
    let len = s.len;
    let mut v = s.start;
    for k in 0..len {
        let (a, b) = (s.p[v], s.p[s.next(v)]);
        s.boxes[k] = [a.x.min(b.x), a.x.max(b.x), a.y.min(b.y), a.y.max(b.y)];
        s.from[k] = v as u8;
        v = s.next(v);
    }
    for k in 0..len {
        let [x0, x1, y0, y1] = s.boxes[k];
        // not the next edge, nor (for the first) the last: neighbours
        let end = if k == 0 { len - 1 } else { len };
        for m in k + 2..end {
            let [u0, u1, w0, w1] = s.boxes[m];
            if u0 <= x1 && x0 <= u1 && w0 <= y1 && y0 <= w1 {
                let (e, f) = (usize::from(s.from[k]), usize::from(s.from[m]));
                let (a, b) = (s.p[e], s.p[s.next(e)]);
                let (c, d) = (s.p[f], s.p[s.next(f)]);
                if boxed_segments_meet(a, b, c, d) {
                    return false;
                }
            }
        }
    }
    true
}

/// Step 4, as `clean` orients a ring: the turn at the rightmost-lowest vertex (there is
/// one: no two vertices share a position) says whether the ring runs clockwise; then
/// every link is reversed.
fn orient(s: &mut Scratch) {
    let (mut best, mut v) = (s.start, s.start);
    for _ in 0..s.len {
        let (p, b) = (s.p[v], s.p[best]);
        if p.x > b.x || (p.x == b.x && p.y < b.y) {
            best = v;
        }
        v = s.next(v);
    }
    // (its turn, as the filter took it)
    s.reversed = s.left & bit(best) == 0;
    if s.reversed {
        for _ in 0..s.len {
            let next = s.next(v);
            core::mem::swap(&mut s.next[v], &mut s.prev[v]);
            v = next;
        }
    }
}

/// Twice the ring's area, summed as lenient mode sums it (the shoelace formula from the
/// ring's start, in floating point): what the deviation is measured against.
pub(crate) fn double_area(s: &Scratch) -> f64 {
    let mut sum = 0.0;
    let mut v = s.start;
    for _ in 0..s.len {
        let w = s.next(v);
        sum += approx_cross(s.p[v], s.p[w]);
        v = w;
    }
    sum.abs()
}

/// Step 5: clips the checked ring into `out` (cleared first) with the strategy's walk,
/// the fast one or the quality one. `false` when the walk gets stuck or the last triangle
/// turns clockwise (in strict mode): the pipeline's repairs or errors decide then.
pub(crate) fn clip(s: &Scratch, quality: bool, lenient: bool, out: &mut Vec<[u32; 3]>) -> bool {
    out.clear();
    let mut w = Walk {
        s,
        next: s.next,
        prev: s.prev,
        reflex: 0,
        not_ear: 0,
        len: s.len,
        no_fan: false,
        out,
    };
    let start = w.classify();
    let last = if quality {
        w.quality(start)
    } else {
        w.fast(start)
    };
    match last {
        Some(Some(last)) => w.finish(last, lenient),
        Some(None) => true,
        None => false,
    }
}

/// The ring while it is clipped: its links, reflex vertices and marks.
struct Walk<'a> {
    s: &'a Scratch,
    next: [u8; MAX],
    prev: [u8; MAX],
    /// Vertices turning right or straight (only live ones).
    reflex: u64,
    /// Tips that failed the ear test since a neighbour last changed (and reflex ones).
    not_ear: u64,
    len: usize,
    /// The fan failed once: don't try again.
    no_fan: bool,
    out: &'a mut Vec<[u32; 3]>,
}

const fn bit(v: usize) -> u64 {
    1 << v
}

impl Walk<'_> {
    fn next(&self, v: usize) -> usize {
        usize::from(self.next[v])
    }

    fn prev(&self, v: usize) -> usize {
        usize::from(self.prev[v])
    }

    fn p(&self, v: usize) -> Point {
        self.s.p[v]
    }

    fn turns_left(&self, a: usize, b: usize, c: usize) -> bool {
        orient2d(self.p(a), self.p(b), self.p(c)) == Orientation::CounterClockwise
    }

    /// Marks the reflex vertices, as the clipper classifies a ring (a reflex tip is marked
    /// "not an ear" at once), from the turns the filter took: right turns, or left ones on
    /// a reversed ring. Returns where the clipper starts.
    fn classify(&mut self) -> usize {
        let start = self.prev(self.s.start);
        let mut v = start;
        for _ in 0..self.len {
            let left = self.s.left & bit(v) != 0;
            if left == self.s.reversed {
                self.reflex |= bit(v);
            }
            v = self.next(v);
        }
        self.not_ear = self.reflex;
        start
    }

    /// The fast walk (`Clipper::fast` on a ring with no repeated position and no crossed
    /// edge): the vertex to finish at, `Some(None)` when a fan finished, `None` when stuck.
    fn fast(&mut self, start: usize) -> Option<Option<usize>> {
        let (mut ear, mut stop, mut rescanned) = (start, start, false);
        while self.len > 3 {
            if self.reflex.count_ones() <= 1 && !self.no_fan && self.try_fan(ear) {
                return Some(None);
            }
            if self.not_ear & bit(ear) == 0 {
                if self.is_ear(ear) {
                    let c = self.cut(ear);
                    // past the new corner, unless the vertex there is marked
                    let after = self.next(c);
                    ear = if self.not_ear & bit(after) != 0 {
                        c
                    } else {
                        after
                    };
                    (stop, rescanned) = (ear, false);
                    continue;
                }
                self.not_ear |= bit(ear);
            }
            ear = self.next(ear);
            while ear != stop && self.not_ear & bit(ear) != 0 {
                ear = self.next(ear);
            }
            if ear == stop {
                if rescanned {
                    return None;
                }
                // a lap without an ear: a cut elsewhere may have freed a marked tip
                rescanned = true;
                self.not_ear = 0;
            }
        }
        Some(Some(ear))
    }

    /// The quality strategy (`Clipper::quality`): always the ear with the smallest angle
    /// at its tip, from a queue of convex tips by angle rank, then vertex (here one entry
    /// per vertex, the smallest found by a scan). A tip is tested when it comes up. (The
    /// clipper also skips tips whose neighbour was cut since they were queued; here both
    /// neighbours of every cut are queued again, or turn reflex and fail the test, so
    /// every entry is current.)
    fn quality(&mut self, start: usize) -> Option<Option<usize>> {
        // by vertex: its entry, `u64::MAX` for none
        let mut queue = [u64::MAX; MAX];
        let push = |w: &Self, v: usize, queue: &mut [u64; MAX]| {
            if w.reflex & bit(v) == 0 {
                let rank = approx_angle_rank(w.p(w.prev(v)), w.p(v), w.p(w.next(v)));
                // as the clipper packs it: the rank's top bits above the vertex
                queue[v] = (rank.to_bits() << 1) >> 32 << 32 | v as u64;
            }
        };
        let seed = |w: &Self, from: usize, queue: &mut [u64; MAX]| {
            let mut v = from;
            for _ in 0..w.len {
                push(w, v, queue);
                v = w.next(v);
            }
        };
        seed(self, start, &mut queue);
        let (mut last, mut rescanned) = (start, false);
        while self.len > 3 {
            let (item, v) = (queue.iter().zip(0..).min()).map_or((u64::MAX, 0), |(&k, v)| (k, v));
            if item == u64::MAX {
                // none queued: once more over the whole ring, then the pipeline decides
                if rescanned {
                    return None;
                }
                rescanned = true;
                seed(self, last, &mut queue);
                continue;
            }
            queue[v] = u64::MAX;
            if !self.is_ear(v) {
                continue;
            }
            let a = self.prev(v);
            let c = self.cut(v);
            rescanned = false;
            for m in [a, c] {
                push(self, m, &mut queue);
            }
            last = c;
        }
        Some(Some(last))
    }

    /// The last triangle, when it has area; a clockwise one is strict mode's error.
    fn finish(&mut self, last: usize, lenient: bool) -> bool {
        let (a, c) = (self.prev(last), self.next(last));
        match orient2d(self.p(a), self.p(last), self.p(c)) {
            Orientation::CounterClockwise => self.emit(a, last, c),
            Orientation::Clockwise if !lenient => return false,
            _ => {}
        }
        true
    }

    /// Whether the tip `b` can be cut: it turns left and no reflex vertex spoils the
    /// triangle (the clipper's test, `geom::interferes`).
    fn is_ear(&self, b: usize) -> bool {
        if self.reflex & bit(b) != 0 {
            return false;
        }
        let (a, c) = (self.prev(b), self.next(b));
        let (pa, pb, pc) = (self.p(a), self.p(b), self.p(c));
        let (lo, hi) = bounds(pa, pb, pc);
        let mut candidates = self.reflex & !bit(a) & !bit(c);
        while candidates != 0 {
            let r = candidates.trailing_zeros() as usize;
            candidates &= candidates - 1;
            let q = self.p(r);
            let around = || [self.p(self.prev(r)), self.p(self.next(r))];
            if near(lo, hi, q) && interferes(q, around, pa, pb, pc) {
                return false;
            }
        }
        true
    }

    /// Cuts the ear at `b`; returns its successor. The neighbours' marks are cleared and
    /// their turns taken again.
    fn cut(&mut self, b: usize) -> usize {
        let (a, c) = (self.prev(b), self.next(b));
        self.emit(a, b, c);
        self.next[a] = c as u8;
        self.prev[c] = a as u8;
        self.len -= 1;
        self.not_ear &= !(bit(a) | bit(c));
        let (ta, tc) = (
            self.turns_left(self.prev(a), a, c),
            self.turns_left(a, c, self.next(c)),
        );
        for (v, left) in [(a, ta), (c, tc)] {
            if left {
                self.reflex &= !bit(v);
            } else {
                self.reflex |= bit(v);
                self.not_ear |= bit(v);
            }
        }
        c
    }

    /// With at most one reflex vertex left, the ring is star-shaped from it: fans out
    /// from it (or from `any`), if every fan triangle turns left.
    fn try_fan(&mut self, any: usize) -> bool {
        let center = if self.reflex == 0 {
            any
        } else {
            self.reflex.trailing_zeros() as usize
        };
        let mut v = self.next(center);
        while self.next(v) != center {
            if !self.turns_left(center, v, self.next(v)) {
                self.no_fan = true;
                return false;
            }
            v = self.next(v);
        }
        let mut v = self.next(center);
        while self.next(v) != center {
            let w = self.next(v);
            self.emit(center, v, w);
            v = w;
        }
        true
    }

    fn emit(&mut self, a: usize, b: usize, c: usize) {
        self.out.push([a as u32, b as u32, c as u32]);
    }
}
