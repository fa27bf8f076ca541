//! Step 7 of the small stage: the clipper's walks (`clip`'s `Clipper::fast` and
//! `Clipper::quality`) on the one ring the polygon is after bridging, over byte links and
//! node masks. A bridge repeats the positions of its ends; a cut that would bring two
//! nodes of one position next to each other, or make a wall (out and straight back),
//! needs the clipper's tidying, and hands the polygon back instead (the fixtures, glyphs
//! and generated polygons of `core/tests/small.rs` never get there).

use super::{bit, members, Mask, Scratch};
use crate::geom::{approx_angle_rank, bounds, greatest, interferes, least, near, orient2d};
use crate::geom::{Orientation, Point};
use crate::structures::{scale, slot};

/// Clips the checked (and bridged) polygon into `out` (cleared first) with the strategy's
/// walk. `false` when the walk gets stuck or needs tidying, the bridges left a wall to
/// remove first, or the last triangle turns clockwise (in strict mode): the pipeline's
/// tidying, repairs or errors decide then.
pub(crate) fn clip_ring<const N: usize, M: Mask>(
    s: &Scratch<N, M>,
    quality: bool,
    lenient: bool,
    out: &mut Vec<[u32; 3]>,
) -> bool {
    out.clear();
    let holes = s.hole_rings.count_ones() as usize;
    let mut w = Walk {
        s,
        next: s.next,
        prev: s.prev,
        reflex: M::NONE,
        not_ear: M::NONE,
        len: 0,
        no_fan: false,
        bands: None,
        out,
    };
    // the polygons in ring order, as the clipper takes them
    for r in (0..s.rings).filter(|&r| s.hole_rings & 1 << r == 0) {
        let first = usize::from(s.start[r]);
        w.len = if s.rings - holes == 1 {
            // (one polygon: its rings and two bridge copies per hole)
            (0..s.rings).map(|r| usize::from(s.len[r])).sum::<usize>() + 2 * holes
        } else {
            let mut len = 1;
            let mut v = w.next(first);
            while v != first && len <= N {
                (len, v) = (len + 1, w.next(v));
            }
            len
        };
        (w.reflex, w.not_ear, w.no_fan) = (M::NONE, M::NONE, false);
        let Some(start) = w.classify(first) else {
            return false;
        };
        if w.bands.is_none() && w.len > 2 * BANDED as usize && w.reflex.count() > BANDED {
            w.bands = Some(Bands::new(s));
        }
        let last = if quality {
            w.quality(start)
        } else {
            w.fast(start)
        };
        let done = match last {
            Some(Some(last)) => w.finish(last, lenient),
            Some(None) => true,
            None => false,
        };
        if !done {
            return false;
        }
    }
    true
}

/// The ring while it is clipped: its links, reflex vertices and marks.
struct Walk<'a, const N: usize, M> {
    s: &'a Scratch<N, M>,
    next: [u8; N],
    prev: [u8; N],
    /// Live nodes turning right or straight.
    reflex: M,
    /// Tips that failed the ear test since a neighbour last changed (and reflex ones).
    not_ear: M,
    len: usize,
    /// The fan failed once: don't try again.
    no_fan: bool,
    /// The nodes sorted into bands, once a polygon of more than twice [`BANDED`] nodes
    /// has more than [`BANDED`] reflex nodes (with fewer, sorting costs more than it
    /// saves).
    bands: Option<Bands<N, M>>,
    out: &'a mut Vec<[u32; 3]>,
}

/// Each node's column and row among [`BANDS`] of each across the nodes' bounding box, and
/// by column (row) k the nodes in the columns (rows) before k: an ear test looks only at
/// the reflex nodes in the columns and rows its triangle spans (the bands are monotone in
/// the coordinates, so every node in the triangle's box is among them).
struct Bands<const N: usize, M> {
    band: [[u8; 2]; N],
    before: [[M; BANDS + 1]; 2],
}

impl<const N: usize, M: Mask> Bands<N, M> {
    /// Sorts the stage's nodes into columns and rows.
    fn new(s: &Scratch<N, M>) -> Self {
        let nodes = &s.p[..s.nodes];
        let (mut lo, mut hi) = (nodes[0], nodes[0]);
        for p in nodes {
            (lo.x, lo.y) = (least(lo.x, p.x), least(lo.y, p.y));
            (hi.x, hi.y) = (greatest(hi.x, p.x), greatest(hi.y, p.y));
        }
        let (sx, sy) = (scale(BANDS, hi.x - lo.x), scale(BANDS, hi.y - lo.y));
        let mut bands = Bands {
            band: [[0; 2]; N],
            before: [[M::NONE; BANDS + 1]; 2],
        };
        // (first each band's own nodes, one place on: then summed)
        for (v, p) in nodes.iter().enumerate() {
            let (x, y) = (
                slot((p.x - lo.x) * sx, BANDS - 1),
                slot((p.y - lo.y) * sy, BANDS - 1),
            );
            bands.band[v] = [x as u8, y as u8];
            bands.before[0][x + 1] |= bit(v);
            bands.before[1][y + 1] |= bit(v);
        }
        for before in &mut bands.before {
            for k in 1..=BANDS {
                let below = before[k - 1];
                before[k] |= below;
            }
        }
        bands
    }

    /// The nodes in the columns and rows the triangle a, b, c spans.
    fn around(&self, a: usize, b: usize, c: usize) -> M {
        let mut mask = !M::NONE;
        for (axis, before) in self.before.iter().enumerate() {
            let [ba, bb, bc] = [a, b, c].map(|v| usize::from(self.band[v][axis]));
            let (first, last) = (ba.min(bb).min(bc), ba.max(bb).max(bc));
            mask &= before[last + 1] & !before[first];
        }
        mask
    }
}

/// Columns (and rows) the ear test's candidates are sorted into.
const BANDS: usize = 16;

/// The reflex nodes a polygon has before its nodes are sorted into bands ([`Bands`]).
const BANDED: u32 = 16;

impl<const N: usize, M: Mask> Walk<'_, N, M> {
    fn next(&self, v: usize) -> usize {
        usize::from(self.next[v])
    }

    fn prev(&self, v: usize) -> usize {
        usize::from(self.prev[v])
    }

    fn p(&self, v: usize) -> Point {
        self.s.p[v]
    }

    fn is(&self, mask: M, v: usize) -> bool {
        mask & bit(v) != M::NONE
    }

    fn turns_left(&self, a: usize, b: usize, c: usize) -> bool {
        orient2d(self.p(a), self.p(b), self.p(c)) == Orientation::CounterClockwise
    }

    /// Marks the reflex nodes of the polygon whose ring starts at `first`, as the clipper
    /// classifies a ring (a reflex tip is marked "not an ear" at once): from the turns the
    /// filter took (right turns, or left ones on a reversed ring), and at the bridges' and
    /// touches' ends by their new turns. Returns where the clipper starts; `None` where it
    /// would remove walls or repeats first.
    fn classify(&mut self, first: usize) -> Option<usize> {
        let s = self.s;
        let start = self.prev(first);
        let mut v = start;
        for _ in 0..self.len {
            let reflex = if self.is(s.fresh, v) {
                let (pp, pn, px) = (self.p(self.prev(v)), self.p(v), self.p(self.next(v)));
                if pn == px || pp == px {
                    return None;
                }
                orient2d(pp, pn, px) != Orientation::CounterClockwise
            } else {
                self.is(s.left, v) == self.is(s.reversed, v)
            };
            if reflex {
                self.reflex |= bit(v);
            }
            v = self.next(v);
        }
        self.not_ear = self.reflex;
        Some(start)
    }

    /// The fast walk (`Clipper::fast` on a ring with no crossed edge): the node to finish
    /// at, `Some(None)` when a fan finished, `None` when stuck or tidying.
    fn fast(&mut self, start: usize) -> Option<Option<usize>> {
        let (mut ear, mut stop, mut rescanned) = (start, start, false);
        while self.len > 3 {
            if self.reflex.count() <= 1 && !self.no_fan && self.try_fan(ear) {
                return Some(None);
            }
            if !self.is(self.not_ear, ear) {
                if self.is_ear(ear) {
                    let corner = self.cut(ear)?;
                    // past the new corner, unless the node there is marked
                    let after = self.next(corner);
                    ear = if self.is(self.not_ear, after) {
                        corner
                    } else {
                        after
                    };
                    (stop, rescanned) = (ear, false);
                    continue;
                }
                self.not_ear |= bit(ear);
            }
            ear = self.next(ear);
            while ear != stop && self.is(self.not_ear, ear) {
                ear = self.next(ear);
            }
            if ear == stop {
                if rescanned {
                    return None;
                }
                // a lap without an ear: a cut elsewhere may have freed a marked tip
                rescanned = true;
                self.not_ear = M::NONE;
            }
        }
        Some(Some(ear))
    }

    /// The quality strategy (`Clipper::quality`): always the ear with the smallest angle
    /// at its tip, from a queue of convex tips by angle rank, then node (one entry per
    /// node, see [`Queue`]). A tip is tested when it comes up. (The clipper also skips tips
    /// whose neighbour was cut since they were queued; here both neighbours of every cut
    /// are queued again, or turn reflex and fail the test, so every entry is current.)
    fn quality(&mut self, start: usize) -> Option<Option<usize>> {
        let mut queue = Queue::<N>::new(self.s.nodes);
        // a tip's key: as the clipper packs it, the rank's top bits above the node
        let key = |w: &Self, v: usize| {
            let rank = approx_angle_rank(w.p(w.prev(v)), w.p(v), w.p(w.next(v)));
            (rank.to_bits() << 1) >> 32 << 32 | v as u64
        };
        let push = |w: &Self, v: usize, queue: &mut Queue<N>| {
            if !w.is(w.reflex, v) {
                queue.set(v, key(w, v));
            }
        };
        // (every tip's key first, then the queue's order once)
        let seed = |w: &Self, from: usize, queue: &mut Queue<N>| {
            let mut v = from;
            for _ in 0..w.len {
                if !w.is(w.reflex, v) {
                    queue.write(v, key(w, v));
                }
                v = w.next(v);
            }
            queue.settle(w.s.nodes);
        };
        seed(self, start, &mut queue);
        let (mut last, mut rescanned) = (start, false);
        while self.len > 3 {
            let Some(v) = queue.first(self.s.nodes) else {
                // none queued: once more over the whole ring, then the pipeline decides
                if rescanned {
                    return None;
                }
                rescanned = true;
                seed(self, last, &mut queue);
                continue;
            };
            queue.set(v, u64::MAX);
            if !self.is_ear(v) {
                continue;
            }
            let a = self.prev(v);
            last = self.cut(v)?;
            rescanned = false;
            for m in [a, last] {
                push(self, m, &mut queue);
            }
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
        if self.is(self.reflex, b) {
            return false;
        }
        let (a, c) = (self.prev(b), self.next(b));
        let (pa, pb, pc) = (self.p(a), self.p(b), self.p(c));
        let (lo, hi) = bounds(pa, pb, pc);
        let mut candidates = self.reflex & !bit::<M>(a) & !bit::<M>(c);
        if let Some(bands) = &self.bands {
            candidates &= bands.around(a, b, c);
        }
        !members(candidates).any(|r| {
            let q = self.p(r);
            let around = || [self.p(self.prev(r)), self.p(self.next(r))];
            near(lo, hi, q) && interferes(q, around, pa, pb, pc)
        })
    }

    /// Cuts the ear at `b`; returns its successor. The neighbours' marks are cleared and
    /// their turns taken again. `None`, having cut, where the clipper would tidy: a
    /// neighbour repeats the position of the node beyond it, or the two share one.
    fn cut(&mut self, b: usize) -> Option<usize> {
        let (a, c) = (self.prev(b), self.next(b));
        self.emit(a, b, c);
        self.next[a] = c as u8;
        self.prev[c] = a as u8;
        self.len -= 1;
        self.not_ear &= !(bit::<M>(a) | bit(c));
        let (pp, pa, pc, pn) = (
            self.p(self.prev(a)),
            self.p(a),
            self.p(c),
            self.p(self.next(c)),
        );
        // (one ring's positions are all distinct: only bridges and touches repeat some)
        let repeats = (self.s.rings > 1 || self.s.touches > 0)
            && (pa == pc || pp == pc || pc == pn || pa == pn);
        if repeats || self.len <= 2 {
            return None;
        }
        let (ta, tc) = (orient2d(pp, pa, pc), orient2d(pa, pc, pn));
        for (v, turn) in [(a, ta), (c, tc)] {
            if turn == Orientation::CounterClockwise {
                self.reflex &= !bit::<M>(v);
            } else {
                self.reflex |= bit(v);
                self.not_ear |= bit(v);
            }
        }
        Some(c)
    }

    /// With at most one reflex vertex left, the ring is star-shaped from it: fans out
    /// from it (or from `any`), if every fan triangle turns left.
    fn try_fan(&mut self, any: usize) -> bool {
        let center = if self.reflex == M::NONE {
            any
        } else {
            self.reflex.lowest()
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
        let vertex = |v: usize| u32::from(self.s.vertex[v]);
        self.out.push([vertex(a), vertex(b), vertex(c)]);
    }
}

/// The quality walk's queue over `N` nodes: each node's key, `u64::MAX` for none; the
/// keys hold their node in their low bits, so the least key names its node. Up to
/// [`SCANNED`] nodes the least is found by a scan of every key. Up to 64, the keys come in
/// blocks of [`BLOCK`], each block's least kept beside them: a key changes by a scan of
/// its block, and the least of all is found by a scan of the blocks (a scan of every key
/// per cut made the walk quadratic: a fifth of lorem_latin's instructions). More nodes
/// keep a tournament tree, at each inner entry the least key below it, so that the least
/// of all is read at the root and a key changes in log₂ N steps (`N` is a power of two).
struct Queue<const N: usize> {
    /// Entries N.. are the nodes' keys; with the tree, entry 1 is the root, and entry i's
    /// children are 2i and 2i + 1; without it, entry b is block b's least key.
    tree: [[u64; N]; 2],
    /// Without the tree: whether the blocks' least keys are kept (else every key is
    /// scanned, which costs less up to [`SCANNED`] nodes).
    blocked: bool,
}

/// Up to this many nodes, the queue without the tree scans every key (measured: the
/// blocks cost the Texas counties and letter_a 3–5% more time).
const SCANNED: usize = 2 * BLOCK;

/// Keys to a block of the queue without the tree.
const BLOCK: usize = 8;

impl<const N: usize> Queue<N> {
    /// Whether the queue keeps the tree.
    const TREE: bool = N > 64;

    /// An empty queue for `nodes` nodes.
    fn new(nodes: usize) -> Self {
        Queue {
            tree: [[u64::MAX; N]; 2],
            blocked: !Self::TREE && nodes > SCANNED,
        }
    }

    fn get(&self, i: usize) -> u64 {
        self.tree[i / N][i % N]
    }

    /// Sets node `v`'s key.
    fn set(&mut self, v: usize, key: u64) {
        self.write(v, key);
        if !Self::TREE {
            if self.blocked {
                self.settle_block(v / BLOCK);
            }
            return;
        }
        let mut i = N + v;
        while i > 1 {
            i /= 2;
            let least = self.get(2 * i).min(self.get(2 * i + 1));
            self.tree[0][i] = least;
        }
    }

    /// Writes node `v`'s key without ordering the queue: [`Queue::settle`] follows.
    fn write(&mut self, v: usize, key: u64) {
        self.tree[1][v] = key;
    }

    /// Block `b`'s least key, kept beside the keys (without the tree): in pairs, so that
    /// the minima do not wait on each other one by one.
    fn settle_block(&mut self, b: usize) {
        let k = &self.tree[1][b * BLOCK..(b + 1) * BLOCK];
        let least = (k[0].min(k[1]).min(k[2].min(k[3]))).min(k[4].min(k[5]).min(k[6].min(k[7])));
        self.tree[0][b] = least;
    }

    /// Orders the queue again after keys of the first `nodes` were written
    /// ([`Queue::write`]).
    fn settle(&mut self, nodes: usize) {
        if Self::TREE {
            for i in (1..N).rev() {
                let least = self.get(2 * i).min(self.get(2 * i + 1));
                self.tree[0][i] = least;
            }
        } else if self.blocked {
            for b in 0..nodes.div_ceil(BLOCK) {
                self.settle_block(b);
            }
        }
    }

    /// The node with the least key among the first `nodes`, if any has one.
    fn first(&self, nodes: usize) -> Option<usize> {
        let least = if Self::TREE {
            self.tree[0][1]
        } else if self.blocked {
            let blocks = &self.tree[0][..nodes.div_ceil(BLOCK)];
            blocks.iter().min().map_or(u64::MAX, |&k| k)
        } else {
            (self.tree[1][..nodes].iter().min()).map_or(u64::MAX, |&k| k)
        };
        (least != u64::MAX).then_some((least & 0xffff_ffff) as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stages::small::Wide;
    use crate::testing::{random, unit_random};

    #[test]
    fn bands_hold_every_node_in_a_triangles_box() {
        let (mut below, mut unit) = (random(0x5eed_ba9d), unit_random(0xba9d_5eed));
        let (mut around, mut boxed, mut all) = (0, 0, 0);
        for round in 0..300 {
            let mut s = Wide {
                nodes: 3 + below(126) as usize,
                ..Wide::default()
            };
            let span = [1.0, 1e-9, 1e12][round % 3];
            for v in 0..s.nodes {
                let mut coordinate = || {
                    let u = unit();
                    // (a coarse grid now and then: nodes on the bands' edges, repeats)
                    if round % 4 == 0 {
                        (u * 16.0).floor() * span
                    } else {
                        u * span - span / 2.0
                    }
                };
                s.p[v] = Point::new(coordinate(), coordinate());
            }
            let bands = Bands::new(&s);
            for _ in 0..50 {
                let [a, b, c] = [0; 3].map(|_| below(s.nodes as u64) as usize);
                let (lo, hi) = bounds(s.p[a], s.p[b], s.p[c]);
                let mask = bands.around(a, b, c);
                for v in 0..s.nodes {
                    let q = s.p[v];
                    let in_box = q.x >= lo.x && q.x <= hi.x && q.y >= lo.y && q.y <= hi.y;
                    let held = mask & bit::<u128>(v) != 0;
                    assert!(!in_box || held, "round {round}: node {v} in the box");
                    (around, boxed, all) = (
                        around + usize::from(held),
                        boxed + usize::from(in_box),
                        all + 1,
                    );
                }
            }
        }
        // the bands narrow the candidates (a triangle of random nodes spans much of the
        // box, so not by much here)
        assert!(boxed <= around && around < all, "{boxed} {around} {all}");
    }

    /// Every form of the quality walk's queue (keys scanned, in blocks, in the tree) gives
    /// the least key, against a scan of the keys as set, while keys are set, raised,
    /// lowered and cleared at random, with the first keys written directly and settled.
    #[test]
    fn every_queue_gives_the_least_key() {
        fn check<const N: usize>(nodes: usize, below: &mut impl FnMut(u64) -> u64) -> bool {
            let mut queue = Queue::<N>::new(nodes);
            let mut keys = vec![u64::MAX; nodes];
            // (as the walk's seed does: keys first, then the order)
            for (v, key) in keys.iter_mut().enumerate() {
                if below(3) > 0 {
                    *key = below(1 << 20) << 32 | v as u64;
                    queue.write(v, *key);
                }
            }
            queue.settle(nodes);
            for _ in 0..4 * nodes {
                let least = keys.iter().min().copied().filter(|&k| k != u64::MAX);
                let want = least.map(|k| (k & 0xffff_ffff) as usize);
                assert_eq!(queue.first(nodes), want, "{nodes} nodes of {N}");
                let v = below(nodes as u64) as usize;
                keys[v] = match below(4) {
                    0 => u64::MAX,
                    _ => below(1 << 20) << 32 | v as u64,
                };
                queue.set(v, keys[v]);
            }
            queue.blocked
        }
        let mut below = random(0x9_0e0e);
        let mut blocked = 0;
        for nodes in 1..=64 {
            blocked += usize::from(check::<64>(nodes, &mut below));
        }
        for nodes in [65, 100, 128] {
            check::<128>(nodes, &mut below);
        }
        assert_eq!(blocked, 64 - SCANNED);
    }
}
