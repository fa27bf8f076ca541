//! The input check: a plane sweep over all ring edges (Shamos–Hoey), O(n log n).
//!
//! The sweep visits the nodes in lexicographic order (x, then y). That is the order in which
//! a sweep line tilted infinitesimally off the vertical meets them, so a vertical edge is an
//! ordinary edge whose lower endpoint is its left one, and at any moment the edges crossing
//! the line have a bottom-to-top order: the *status*, a sorted `Vec` while short, [`Blocks`]
//! once it grows long, so that a line crossing Θ(n) edges still costs about O(log n) per
//! event.
//!
//! At each event point p (all nodes at one position) the edges through p form one contiguous
//! run of the status: edges strictly below p come before it, edges strictly above come after.
//! That run is where every T-junction at p shows up, so touches are found at the events, not
//! by neighbour tests. Edges ending at p leave the run, edges starting at p join it, and the
//! run is re-sorted by direction beyond p. Pairs that become adjacent are tested for a proper
//! crossing; two edges through p that both continue past p and differ in direction cross at
//! p. As in Shamos–Hoey, the status order is right up to the leftmost crossing point, so
//! every touch before it is reported and a crossing there is always found (unless the sweep
//! stopped at another crossing first). Beyond it the order may be wrong and touches are best
//! effort: the sweep still never reports a false or repeated touch, and always terminates.
//!
//! Every geometric decision is an exact `orient2d` sign or a coordinate comparison.

use core::cmp::Ordering;

use crate::crossings::status::{Blocks, Sequence};
use crate::geom::{cmp_xy, on_segment, orient2d, Orientation, Point};
use crate::structures::EdgeGrid;
use crate::structures::{NodeId, Pool};

/// Node `vertex` lies in the relative interior of the edge `edge → next(edge)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Touch {
    pub vertex: NodeId,
    pub edge: NodeId,
}

/// The edges `a → next(a)` and `b → next(b)` cross at a point interior to both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Crossing {
    pub a: NodeId,
    pub b: NodeId,
}

/// Reusable buffers of the sweep. After [`sweep`], `order` holds every node of the swept
/// rings sorted by position (x, then y, with −0.0 read as +0.0), ties by node id.
#[derive(Debug, Default)]
pub(crate) struct SweepScratch {
    pub order: Vec<NodeId>,
    /// Set by the caller when `order` already holds the nodes of the rings to sweep, sorted
    /// (the same nodes at the same positions as the last sweep, only linked differently):
    /// the next sweep skips collecting and sorting them, and clears the flag.
    pub order_is_sorted: bool,
    /// `order` with its sort keys while it is sorted (see [`sort_key`]).
    keyed: Vec<(i64, i64, NodeId)>,
    /// The edges crossing the sweep line, bottom to top, while few.
    status: Vec<Seg>,
    /// The same once many (see [`CHUNK_AT`]).
    blocks: Blocks<Seg>,
    /// The edges through the current event point while they are re-sorted.
    run: Vec<Seg>,
    /// Keeps the status flat however long it grows, to compare with chunking.
    #[cfg(test)]
    flat_only: bool,
}

/// One edge as the sweep sees it: its start node and its endpoints in sweep order (`l < r`).
#[derive(Clone, Copy, Debug)]
struct Seg {
    edge: NodeId,
    l: Point,
    r: Point,
}

/// Sweeps the edges of the rings through `starts`, pushing every T-junction to `touches`
/// and crossings to `crossings` (at least one if any exist; only the first when
/// `stop_at_first_crossing`).
pub(crate) fn sweep(
    pool: &Pool,
    starts: &[NodeId],
    scratch: &mut SweepScratch,
    stop_at_first_crossing: bool,
    touches: &mut Vec<Touch>,
    crossings: &mut Vec<Crossing>,
) {
    #[cfg(test)]
    let chunk_at = if scratch.flat_only {
        usize::MAX
    } else {
        CHUNK_AT
    };
    #[cfg(not(test))]
    let chunk_at = CHUNK_AT;
    let SweepScratch {
        order,
        order_is_sorted,
        keyed,
        status,
        blocks,
        run,
        ..
    } = scratch;
    if !core::mem::take(order_is_sorted) {
        collect_nodes(pool, starts, order);
        // Sorted by [`key_cmp`], then ids: the keys sit beside the ids, so the sort compares
        // integers instead of looking every node up in the pool.
        keyed.clear();
        keyed.extend(order.iter().map(|&n| {
            let p = pool.p(n);
            (sort_key(p.x), sort_key(p.y), n)
        }));
        keyed.sort_unstable();
        order.clear();
        order.extend(keyed.iter().map(|k| k.2));
    }
    run.clear();
    // There are at most as many edges as nodes: reserving that much up front means a
    // warmed-up scratch never allocates during the sweep.
    status.clear();
    status.reserve(order.len());
    run.reserve(order.len());
    let first_crossing = crossings.len();
    let mut status = Status {
        flat: status,
        blocks,
        chunked: false,
        chunk_at,
        room: order.len(),
    };
    let mut sw = Sweep {
        pool,
        run,
        stop_at_first_crossing,
        touches,
        crossings,
        ordered: true,
    };
    let mut i = 0;
    while let Some(&n) = order.get(i) {
        let p = pool.p(n);
        // All nodes at p are consecutive in `order`: they make one event.
        let rest = &order[i..];
        let len = rest
            .iter()
            .position(|&m| key_cmp(pool.p(m), p) != Ordering::Equal);
        let group = &rest[..len.unwrap_or(rest.len())];
        if sw.event(&mut status, group, p) {
            break;
        }
        // The group holds at least node n itself, so the sweep always advances.
        i += group.len().max(1);
    }
    dedup_crossings(crossings, first_crossing);
}

/// Fills `order` with every node of the rings through `starts`, in ring order.
fn collect_nodes(pool: &Pool, starts: &[NodeId], order: &mut Vec<NodeId>) {
    order.clear();
    for &start in starts {
        if start.idx() >= pool.len() {
            continue;
        }
        let mut n = start;
        // No ring is longer than the pool: the bound stops a walk from a start that was
        // unlinked (its ring never leads back to it) instead of looping forever.
        for _ in 0..pool.len() {
            order.push(n);
            n = pool.next(n);
            if n == start {
                break;
            }
        }
    }
}

/// The sweep order of points: [`cmp_xy`] with −0.0 read as +0.0. They are the same point to
/// `orient2d`, and `total_cmp` alone would put other points between them.
fn key_cmp(a: Point, b: Point) -> Ordering {
    // Adding +0.0 is exact; it only turns −0.0 into +0.0.
    let unsigned = |p: Point| Point::new(p.x + 0.0, p.y + 0.0);
    cmp_xy(unsigned(a), unsigned(b))
}

/// An integer ordered as [`key_cmp`] orders coordinates: `total_cmp`'s order of x + 0.0.
fn sort_key(x: f64) -> i64 {
    let bits = (x + 0.0).to_bits() as i64;
    // negative values: flip all but the sign bit, so that more negative sorts lower
    bits ^ (((bits >> 63) as u64) >> 1) as i64
}

/// True when `a` and `b` are the same point.
fn same(a: Point, b: Point) -> bool {
    key_cmp(a, b) == Ordering::Equal
}

/// True when `p` lies on `s` but is neither of its endpoints.
fn in_interior(s: &Seg, p: Point) -> bool {
    on_segment(s.l, s.r, p) && !same(p, s.l) && !same(p, s.r)
}

/// True when the interiors of `s` and `t` cross at one point: each one's endpoints lie
/// strictly on opposite sides of the other's line.
// inlined into the sweep's hot loops, where most calls return at the box test
#[inline(always)]
fn properly_cross(s: &Seg, t: &Seg) -> bool {
    // edges whose boxes are apart (most neighbours in the status) cannot cross: compared
    // exactly, and without four orientation tests
    let apart =
        |a0: f64, a1: f64, b0: f64, b1: f64| a0.max(a1) < b0.min(b1) || b0.max(b1) < a0.min(a1);
    if apart(s.l.x, s.r.x, t.l.x, t.r.x) || apart(s.l.y, s.r.y, t.l.y, t.r.y) {
        return false;
    }
    straddles(s, t) && straddles(t, s)
}

/// True when the endpoints of `t` lie strictly on opposite sides of the line through `s`.
fn straddles(s: &Seg, t: &Seg) -> bool {
    use Orientation::{Clockwise, CounterClockwise};
    matches!(
        (orient2d(s.l, s.r, t.l), orient2d(s.l, s.r, t.r)),
        (CounterClockwise, Clockwise) | (Clockwise, CounterClockwise)
    )
}

/// True when `a` lies below `b` just after the event point `p`, both passing through `p`.
fn below_after(p: Point, a: &Seg, b: &Seg) -> bool {
    // Both right endpoints are after p, so both directions lie in one half-plane (angles in
    // (−90°, 90°]) and the orientation sign orders them by angle. Collinear edges overlap
    // beyond p and are interchangeable; ids make the order total.
    match orient2d(p, a.r, b.r) {
        Orientation::CounterClockwise => true,
        Orientation::Clockwise => false,
        Orientation::Collinear => a.edge < b.edge,
    }
}

/// Sorts `v` by `less` in place: a heapsort, which allocates nothing and, unlike the standard
/// sorts, cannot panic should overflowing coordinates ever make `less` inconsistent.
fn heapsort<T: Copy>(v: &mut [T], less: impl Fn(&T, &T) -> bool) {
    let sift_down = |v: &mut [T], mut root: usize, end: usize| loop {
        let mut child = 2 * root + 1;
        if child >= end {
            break;
        }
        if child + 1 < end && less(&v[child], &v[child + 1]) {
            child += 1;
        }
        if !less(&v[root], &v[child]) {
            break;
        }
        v.swap(root, child);
        root = child;
    };
    let n = v.len();
    for root in (0..n / 2).rev() {
        sift_down(v, root, n);
    }
    for end in (1..n).rev() {
        v.swap(0, end);
        sift_down(v, 0, end);
    }
}

/// Normalises the crossings pushed since `from` (smaller id first), sorts and deduplicates
/// them: in lenient mode one pair can become adjacent, and be tested, more than once.
fn dedup_crossings(crossings: &mut Vec<Crossing>, from: usize) {
    let Some(tail) = crossings.get_mut(from..) else {
        return;
    };
    for c in tail.iter_mut() {
        if c.b < c.a {
            core::mem::swap(&mut c.a, &mut c.b);
        }
    }
    tail.sort_unstable_by_key(|c| (c.a, c.b));
    let mut kept = from;
    for i in from..crossings.len() {
        let c = crossings[i];
        if kept == from || crossings[kept - 1] != c {
            crossings[kept] = c;
            kept += 1;
        }
    }
    crossings.truncate(kept);
}

/// Statuses longer than this are split into blocks while the sweep is in order: below it,
/// shifting a flat `Vec` is cheaper. (Unit tests chunk almost every status.)
const CHUNK_AT: usize = if cfg!(test) {
    3
} else {
    4 * crate::crossings::status::BLOCK
};

/// The status, in one of its two forms.
struct Status<'a> {
    flat: &'a mut Vec<Seg>,
    blocks: &'a mut Blocks<Seg>,
    /// The edges are in `blocks`, not `flat`.
    chunked: bool,
    /// A flat status longer than this is chunked while in order ([`CHUNK_AT`]).
    chunk_at: usize,
    /// The most edges the status will hold.
    room: usize,
}

/// What one sweep reads and writes, so its steps need not pass many arguments.
struct Sweep<'a> {
    pool: &'a Pool,
    run: &'a mut Vec<Seg>,
    stop_at_first_crossing: bool,
    touches: &'a mut Vec<Touch>,
    crossings: &'a mut Vec<Crossing>,
    /// No crossing seen yet, so the status is in order (Shamos–Hoey: the leftmost crossing
    /// pair becomes adjacent, and is seen, before the sweep reaches the crossing).
    ordered: bool,
}

impl Sweep<'_> {
    /// Handles the event point `p`, where the nodes of `group` lie. Returns true to stop.
    fn event(&mut self, status: &mut Status, group: &[NodeId], p: Point) -> bool {
        if status.chunked && !self.ordered {
            // out of order, searches must probe exactly as over one flat `Vec`
            status.blocks.drain_into(status.flat);
            status.chunked = false;
        } else if !status.chunked && self.ordered && status.flat.len() > status.chunk_at {
            status.blocks.assign(status.flat, status.room);
            status.chunked = true;
        }
        if status.chunked {
            self.event_in(&mut *status.blocks, group, p)
        } else {
            self.event_in(&mut *status.flat, group, p)
        }
    }

    /// [`Self::event`] on the status in either form.
    fn event_in<S: Sequence<Seg>>(&mut self, status: &mut S, group: &[NodeId], p: Point) -> bool {
        let (lo, hi) = self.run_through(status, p);
        if self.take_run(status, group, p, lo, hi) {
            return true;
        }
        self.add_starting(group, p);
        heapsort(self.run, |a, b| below_after(p, a, b));
        let at = status.replace(lo, hi, self.run);
        self.check_neighbours(status, at, self.run.len())
    }

    /// The status range `lo..hi` of the edges through `p`. The status is ordered bottom to
    /// top, so edges strictly below p are a prefix and edges strictly above a suffix.
    fn run_through<S: Sequence<Seg>>(&self, status: &S, p: Point) -> (S::Pos, S::Pos) {
        // Every status edge has l < p <= r in sweep order, so "p left of l → r" means p is
        // above the edge (a vertical edge there always has p on it).
        let lo = status.search(|s| orient2d(s.l, s.r, p) == Orientation::CounterClockwise);
        let through = |s: &Seg| orient2d(s.l, s.r, p) != Orientation::Clockwise;
        let hi = if self.ordered {
            // in order, `through` holds for a prefix of the rest: the edges at p, usually
            // none or two, so walking it is cheaper than a binary search and gives the same
            status.walk(lo, through)
        } else {
            // out of order (the status is flat then), the binary search's answer is the one
            // this sweep has always given (lenient results depend on it)
            status.search_from(lo, through)
        };
        (lo, hi)
    }

    /// Copies the run's edges that continue past `p` into `run`, reporting a touch for every
    /// node at p on each and a crossing for continuing edges of different directions; edges
    /// ending at p are dropped. Returns true to stop.
    fn take_run<S: Sequence<Seg>>(
        &mut self,
        status: &S,
        group: &[NodeId],
        p: Point,
        lo: S::Pos,
        hi: S::Pos,
    ) -> bool {
        self.run.clear();
        let mut through: Option<Seg> = None;
        let mut at = lo;
        while at < hi {
            let Some(s) = status.item(at) else { break };
            at = status.after(at);
            // Ends at p — or, after an undetected crossing, an edge the sweep failed to
            // remove in time: either way it is behind the sweep line now.
            if key_cmp(s.r, p) != Ordering::Greater {
                continue;
            }
            // A status edge may miss p only when the order is already inconsistent.
            if in_interior(&s, p) {
                for &v in group {
                    self.touches.push(Touch {
                        vertex: v,
                        edge: s.edge,
                    });
                }
                match through {
                    None => through = Some(s),
                    // Both pass through p: they cross there unless they are collinear.
                    Some(t) if properly_cross(&t, &s) && self.cross(t.edge, s.edge) => {
                        return true;
                    }
                    Some(_) => {}
                }
            }
            self.run.push(s);
        }
        false
    }

    /// Appends to `run` the edges whose left endpoint is `p`. Each edge is taken once: at its
    /// start node when that comes first in sweep order, else at its end node. Zero-length
    /// edges are never taken.
    #[inline(always)]
    fn add_starting(&mut self, group: &[NodeId], p: Point) {
        let pool = self.pool;
        for &n in group {
            let next = pool.next(n);
            if key_cmp(pool.p(next), p) == Ordering::Greater {
                self.run.push(Seg {
                    edge: n,
                    l: pool.p(n),
                    r: pool.p(next),
                });
            }
            let prev = pool.prev(n);
            if pool.next(prev) == n && key_cmp(pool.p(prev), p) == Ordering::Greater {
                self.run.push(Seg {
                    edge: prev,
                    l: pool.p(n),
                    r: pool.p(prev),
                });
            }
        }
    }

    /// Tests every pair that may have become adjacent at this event: the run of `m` edges
    /// at `at` with its neighbours below and above, and within itself. Returns true to stop.
    fn check_neighbours<S: Sequence<Seg>>(&mut self, status: &S, at: S::Pos, m: usize) -> bool {
        let (mut c, pairs) = match status.before(at) {
            Some(below) => (below, m + 1),
            None => (at, m),
        };
        let Some(mut a) = status.item(c) else {
            return false;
        };
        for _ in 0..pairs {
            c = status.after(c);
            let Some(b) = status.item(c) else { break };
            if properly_cross(&a, &b) && self.cross(a.edge, b.edge) {
                return true;
            }
            a = b;
        }
        false
    }

    /// Records a crossing of the edges `a` and `b`; returns true when the sweep should stop.
    fn cross(&mut self, a: NodeId, b: NodeId) -> bool {
        self.ordered = false;
        self.crossings.push(Crossing { a, b });
        self.stop_at_first_crossing
    }
}

/// Lenient mode, after the sweep saw a crossing: flags every edge (by its start node) that
/// properly crosses another edge of the rings through `starts`. The sweep stops being exact
/// after its first crossing; this pass is exact and complete. `grid` lists the current
/// edges of those rings; each edge is compared with the edges listed in the cells of its
/// bounding box, so it costs about the edges near each edge.
pub(crate) fn mark_crossed(
    pool: &mut Pool,
    grid: &EdgeGrid,
    starts: &[NodeId],
    flagged: &mut Vec<NodeId>,
) {
    crossing_pairs(pool, grid, starts, flagged);
    for &n in flagged.iter() {
        pool.get_mut(n).crossed = true;
    }
}

/// The start nodes of every two edges of the rings through `starts` that properly cross,
/// pair by pair (a pair may come more than once), into `flagged`, as [`mark_crossed`] finds
/// them.
pub(crate) fn crossing_pairs(
    pool: &Pool,
    grid: &EdgeGrid,
    starts: &[NodeId],
    flagged: &mut Vec<NodeId>,
) {
    flagged.clear();
    let seg = |pool: &Pool, n: NodeId| Seg {
        edge: n,
        l: pool.p(n),
        r: pool.p(pool.next(n)),
    };
    for &s in starts {
        let mut m = s;
        for _ in 0..pool.len() {
            let sm = seg(pool, m);
            let lo = Point::new(sm.l.x.min(sm.r.x), sm.l.y.min(sm.r.y));
            let hi = Point::new(sm.l.x.max(sm.r.x), sm.l.y.max(sm.r.y));
            // each pair from its smaller id; a pair listed in several cells is tested
            // again, which only flags the same edges again
            for n in grid.query(lo, hi) {
                if n > m && properly_cross(&sm, &seg(pool, n)) {
                    flagged.push(m);
                    flagged.push(n);
                }
            }
            m = pool.next(m);
            if m == s {
                break;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sort_keys_order_like_key_cmp() {
        let values = [
            f64::NEG_INFINITY,
            -1e300,
            -1.5,
            -f64::MIN_POSITIVE,
            -5e-324,
            -0.0,
            0.0,
            5e-324,
            1.0,
            1.0 + f64::EPSILON,
            1e300,
            f64::INFINITY,
        ];
        for &a in &values {
            for &b in &values {
                let (pa, pb) = (Point::new(a, 0.0), Point::new(b, 0.0));
                assert_eq!(sort_key(a).cmp(&sort_key(b)), key_cmp(pa, pb), "{a} {b}");
            }
        }
    }

    /// A tiny seeded xorshift64* generator, so every run sees the same cases.
    struct Rng(u64);

    impl Rng {
        /// The next 64 random bits.
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
        }

        /// A number in `0..n`.
        fn below(&mut self, n: u64) -> u64 {
            self.next() % n
        }

        /// True with probability 1/2.
        fn coin(&mut self) -> bool {
            self.next() & 1 == 1
        }
    }

    /// Builds a pool from rings of (x, y) and returns it with one start node per ring.
    fn build(rings: &[Vec<(f64, f64)>]) -> (Pool, Vec<NodeId>) {
        Pool::from_rings(rings)
    }

    /// The result of one sweep: touches (sorted by [`run`]), crossings as found, and the
    /// node order.
    struct Found {
        touches: Vec<Touch>,
        crossings: Vec<Crossing>,
        order: Vec<NodeId>,
    }

    /// Runs the sweep on fresh buffers.
    fn run(pool: &Pool, starts: &[NodeId], stop: bool) -> Found {
        let mut found = run_with(pool, starts, stop, false);
        found.touches.sort_unstable_by_key(|t| (t.vertex, t.edge));
        found
    }

    /// Runs the sweep on fresh buffers, with the status kept flat when `flat_only`. Touches
    /// stay in the order found.
    fn run_with(pool: &Pool, starts: &[NodeId], stop: bool, flat_only: bool) -> Found {
        let mut scratch = SweepScratch {
            flat_only,
            ..SweepScratch::default()
        };
        let (mut touches, mut crossings) = (Vec::new(), Vec::new());
        sweep(
            pool,
            starts,
            &mut scratch,
            stop,
            &mut touches,
            &mut crossings,
        );
        Found {
            touches,
            crossings,
            order: scratch.order,
        }
    }

    /// Every node of the rings through `starts`.
    fn all_nodes(pool: &Pool, starts: &[NodeId]) -> Vec<NodeId> {
        starts.iter().flat_map(|&s| pool.ring(s)).collect()
    }

    /// The reference: every (node, edge) with the node strictly inside the edge, sorted.
    fn brute_touches(pool: &Pool, starts: &[NodeId]) -> Vec<Touch> {
        let nodes = all_nodes(pool, starts);
        let mut out = Vec::new();
        for &e in &nodes {
            let (a, b) = (pool.p(e), pool.p(pool.next(e)));
            for &v in &nodes {
                let q = pool.p(v);
                if a != b && on_segment(a, b, q) && q != a && q != b {
                    out.push(Touch { vertex: v, edge: e });
                }
            }
        }
        out.sort_unstable_by_key(|t| (t.vertex, t.edge));
        out
    }

    /// True when the edges starting at `e` and `f` cross at a point interior to both.
    fn brute_cross(pool: &Pool, e: NodeId, f: NodeId) -> bool {
        let (a, b) = (pool.p(e), pool.p(pool.next(e)));
        let (c, d) = (pool.p(f), pool.p(pool.next(f)));
        let sides = |o1: Orientation, o2: Orientation| {
            o1 != Orientation::Collinear && o2 != Orientation::Collinear && o1 != o2
        };
        sides(orient2d(a, b, c), orient2d(a, b, d)) && sides(orient2d(c, d, a), orient2d(c, d, b))
    }

    /// The reference: every crossing pair of edges.
    fn brute_crossings(pool: &Pool, starts: &[NodeId]) -> Vec<(NodeId, NodeId)> {
        let nodes = all_nodes(pool, starts);
        let mut out = Vec::new();
        for (i, &e) in nodes.iter().enumerate() {
            for &f in &nodes[i + 1..] {
                if brute_cross(pool, e, f) {
                    out.push((e, f));
                }
            }
        }
        out
    }

    /// The smallest x at which any crossing can lie: touches left of it must all be found.
    fn crossing_bound(pool: &Pool, crossings: &[(NodeId, NodeId)]) -> f64 {
        let left = |e: NodeId| pool.p(e).x.min(pool.p(pool.next(e)).x);
        crossings
            .iter()
            .map(|&(e, f)| left(e).max(left(f)))
            .fold(f64::INFINITY, f64::min)
    }

    /// Checks `order`: a permutation of the nodes, sorted by position then id.
    fn check_order(pool: &Pool, starts: &[NodeId], order: &[NodeId]) {
        let mut nodes = all_nodes(pool, starts);
        let mut sorted = order.to_vec();
        nodes.sort_unstable();
        sorted.sort_unstable();
        assert_eq!(nodes, sorted, "order is not a permutation of the nodes");
        for w in order.windows(2) {
            let o = key_cmp(pool.p(w[0]), pool.p(w[1])).then(w[0].cmp(&w[1]));
            assert_eq!(o, Ordering::Less, "order not sorted at {w:?}");
        }
    }

    /// What a comparison found, for the statistics the randomized tests assert on.
    #[derive(Default)]
    struct Stats {
        cases: usize,
        crossing_free: usize,
        touches: usize,
        with_crossings: usize,
    }

    /// Compares the sweep (both modes) with the brute force on one case.
    fn compare(rings: &[Vec<(f64, f64)>], stats: &mut Stats) {
        let (pool, starts) = build(rings);
        let want = brute_touches(&pool, &starts);
        let real = brute_crossings(&pool, &starts);
        let is_real = |c: &Crossing| brute_cross(&pool, c.a, c.b);
        for stop in [false, true] {
            // a chunked status finds exactly what a flat one finds, in the same order
            let chunked = run_with(&pool, &starts, stop, false);
            let flat = run_with(&pool, &starts, stop, true);
            assert_eq!(chunked.touches, flat.touches, "{rings:?}");
            assert_eq!(chunked.crossings, flat.crossings, "{rings:?}");
            let got = run(&pool, &starts, stop);
            check_order(&pool, &starts, &got.order);
            assert!(
                got.crossings.iter().all(is_real),
                "false crossing {rings:?}"
            );
            if stop {
                assert!(got.crossings.len() <= 1, "stop mode went on: {rings:?}");
            }
            if real.is_empty() {
                assert_eq!(got.touches, want, "touches differ: {rings:?}");
                assert!(got.crossings.is_empty());
                continue;
            }
            assert!(!got.crossings.is_empty(), "missed all crossings: {rings:?}");
            // Best effort past the leftmost crossing, but never a false or repeated touch,
            // and everything left of any crossing is exact.
            assert!(
                got.touches.windows(2).all(|w| w[0] != w[1]),
                "repeated touch {rings:?}"
            );
            assert!(
                got.touches.iter().all(|t| want.contains(t)),
                "false touch {rings:?}"
            );
            if !stop {
                let bound = crossing_bound(&pool, &real);
                for t in want.iter().filter(|t| pool.p(t.vertex).x < bound) {
                    assert!(
                        got.touches.contains(t),
                        "missed {t:?} left of crossings {rings:?}"
                    );
                }
            }
        }
        stats.cases += 1;
        if real.is_empty() {
            stats.crossing_free += 1;
            stats.touches += want.len();
        } else {
            stats.with_crossings += 1;
        }
    }

    /// Drops repeated consecutive points (also across the wrap); None if fewer than 3 remain.
    fn tidy(mut ring: Vec<(f64, f64)>) -> Option<Vec<(f64, f64)>> {
        ring.dedup();
        while ring.len() > 1 && ring.first() == ring.last() {
            ring.pop();
        }
        (ring.len() >= 3).then_some(ring)
    }

    /// Inserts, at random, lattice points lying inside the edges of `corners`.
    fn with_edge_points(rng: &mut Rng, corners: &[(i64, i64)]) -> Vec<(f64, f64)> {
        let mut ring = Vec::new();
        for (i, &(x0, y0)) in corners.iter().enumerate() {
            let (x1, y1) = corners[(i + 1) % corners.len()];
            ring.push((x0 as f64, y0 as f64));
            let (dx, dy) = (x1 - x0, y1 - y0);
            let g = gcd(dx.abs(), dy.abs());
            for k in 1..g {
                if rng.coin() {
                    ring.push(((x0 + dx / g * k) as f64, (y0 + dy / g * k) as f64));
                }
            }
        }
        ring
    }

    /// Greatest common divisor.
    fn gcd(a: i64, b: i64) -> i64 {
        if b == 0 {
            a
        } else {
            gcd(b, a % b)
        }
    }

    /// A random ring on the grid 0..=6: a free polygon, a rectangle or a triangle, the last
    /// two with extra points on their sides, in a random direction.
    fn random_ring(rng: &mut Rng) -> Vec<(f64, f64)> {
        loop {
            let ring = match rng.below(3) {
                0 => {
                    let n = 3 + rng.below(5) as usize;
                    (0..n)
                        .map(|_| (rng.below(7) as f64, rng.below(7) as f64))
                        .collect()
                }
                1 => {
                    let [x0, x1, y0, y1] = [0; 4].map(|_| rng.below(7) as i64);
                    let corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)];
                    with_edge_points(rng, &corners)
                }
                _ => {
                    let corners = [0; 3].map(|_| (rng.below(7) as i64, rng.below(7) as i64));
                    with_edge_points(rng, &corners)
                }
            };
            if let Some(mut ring) = tidy(ring) {
                if rng.coin() {
                    ring.reverse();
                }
                // Now and then write zeros as −0.0: the same point to the sweep.
                if rng.below(4) == 0 {
                    for q in ring.iter_mut() {
                        q.0 = if q.0 == 0.0 && rng.coin() { -0.0 } else { q.0 };
                        q.1 = if q.1 == 0.0 && rng.coin() { -0.0 } else { q.1 };
                    }
                }
                return ring;
            }
        }
    }

    /// Random ring sets on a small grid: collinear overlaps, shared vertices, T-junctions
    /// and axis-parallel edges are everywhere. Touches must match the brute force exactly
    /// wherever nothing crosses.
    #[test]
    fn random_grid_rings_match_brute_force() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        let mut stats = Stats::default();
        for _ in 0..20_000 {
            let rings: Vec<_> = (0..1 + rng.below(4))
                .map(|_| random_ring(&mut rng))
                .collect();
            compare(&rings, &mut stats);
        }
        eprintln!(
            "{} cases: {} crossing-free with {} touches, {} with crossings",
            stats.cases, stats.crossing_free, stats.touches, stats.with_crossings
        );
        assert!(stats.crossing_free > 3_000 && stats.touches > 3_000);
        assert!(stats.with_crossings > 3_000);
    }

    /// Crossing-free ring sets by construction: each case keeps adding random small rings
    /// that cross nothing so far, so several rings meet in T-junctions and shared edges.
    #[test]
    fn random_crossing_free_sets_match_brute_force() {
        let mut rng = Rng(0x1234_5678_9abc_def1);
        let mut stats = Stats::default();
        for _ in 0..3_000 {
            let mut rings: Vec<Vec<(f64, f64)>> = Vec::new();
            for _ in 0..12 {
                rings.push(random_ring(&mut rng));
                let (pool, starts) = build(&rings);
                if !brute_crossings(&pool, &starts).is_empty() {
                    rings.pop();
                }
            }
            compare(&rings, &mut stats);
        }
        eprintln!(
            "{} crossing-free sets, {} touches",
            stats.crossing_free, stats.touches
        );
        assert_eq!(stats.crossing_free, stats.cases);
        assert!(stats.touches > 10_000);
    }

    /// Random polygons with arbitrary floating-point coordinates (crossings everywhere).
    #[test]
    fn random_float_polygons_match_brute_force() {
        let mut rng = Rng(0xdead_beef_cafe_f00d);
        let mut stats = Stats::default();
        for _ in 0..500 {
            let n = 3 + rng.below(30) as usize;
            let ring: Vec<_> = (0..n)
                .map(|_| {
                    (
                        (rng.next() >> 11) as f64 / 1e12,
                        (rng.next() >> 11) as f64 / 1e12,
                    )
                })
                .collect();
            if let Some(ring) = tidy(ring) {
                compare(&[ring], &mut stats);
            }
        }
        assert!(stats.with_crossings > 100);
    }

    /// Sweeps hand-made rings (stopping at nothing) and returns the result.
    fn sweep_rings(rings: &[Vec<(f64, f64)>]) -> (Pool, Found) {
        let (pool, starts) = build(rings);
        let found = run(&pool, &starts, false);
        check_order(&pool, &starts, &found.order);
        (pool, found)
    }

    /// The touch of node `v` on the edge starting at node `e`.
    fn touch(v: u32, e: u32) -> Touch {
        Touch {
            vertex: NodeId(v),
            edge: NodeId(e),
        }
    }

    /// The crossing of the edges starting at nodes `a` and `b`.
    fn crossing(a: u32, b: u32) -> Crossing {
        Crossing {
            a: NodeId(a),
            b: NodeId(b),
        }
    }

    /// A square 0..10 as an outer ring.
    fn outer() -> Vec<(f64, f64)> {
        vec![(0., 0.), (10., 0.), (10., 10.), (0., 10.)]
    }

    /// A hole sharing one vertex with the outer ring is allowed.
    #[test]
    fn hole_touching_outer_at_shared_vertex_is_fine() {
        let (_, found) = sweep_rings(&[outer(), vec![(0., 0.), (3., 5.), (5., 3.)]]);
        assert!(found.touches.is_empty() && found.crossings.is_empty());
    }

    /// A hole vertex in the middle of an outer edge is a touch.
    #[test]
    fn hole_vertex_on_outer_edge_is_a_touch() {
        let (_, found) = sweep_rings(&[outer(), vec![(5., 0.), (7., 4.), (3., 4.)]]);
        assert_eq!(found.touches, [touch(4, 0)]);
        assert!(found.crossings.is_empty());
    }

    /// Two holes whose vertices both lie at the same point of an outer edge: one touch each.
    #[test]
    fn two_nodes_at_one_point_on_an_edge_touch_twice() {
        let holes = [
            vec![(10., 5.), (7., 7.), (7., 6.)],
            vec![(10., 5.), (7., 4.), (7., 3.)],
        ];
        let (_, found) = sweep_rings(&[outer(), holes[0].clone(), holes[1].clone()]);
        let edge = NodeId(1); // (10,0) → (10,10), a vertical edge
        let want = [
            Touch {
                vertex: NodeId(4),
                edge,
            },
            Touch {
                vertex: NodeId(7),
                edge,
            },
        ];
        assert_eq!(found.touches, want);
        assert!(found.crossings.is_empty());
    }

    /// Two squares sharing a whole edge (in opposite directions) report nothing.
    #[test]
    fn squares_sharing_an_edge_report_nothing() {
        let a = vec![(0., 0.), (2., 0.), (2., 2.), (0., 2.)];
        let b = vec![(2., 0.), (4., 0.), (4., 2.), (2., 2.)];
        let (_, found) = sweep_rings(&[a, b]);
        assert!(found.touches.is_empty() && found.crossings.is_empty());
    }

    /// Partially overlapping collinear edges: each inner endpoint touches the other edge.
    #[test]
    fn overlapping_collinear_edges_touch() {
        let a = vec![(0., 0.), (4., 0.), (4., -2.)];
        let b = vec![(2., 0.), (6., 0.), (6., 2.)];
        let (_, found) = sweep_rings(&[a, b]);
        // (2,0) = node 3 lies inside a's edge 0; (4,0) = node 1 lies inside b's edge 3.
        let want = [touch(1, 3), touch(3, 0)];
        assert_eq!(found.touches, want);
        assert!(found.crossings.is_empty());
    }

    /// An edge contained in another, diagonal: both endpoints of the short one touch.
    #[test]
    fn contained_diagonal_edge_touches_twice() {
        let a = vec![(0., 0.), (6., 6.), (0., 6.)];
        let b = vec![(2., 2.), (4., 4.), (5., 1.)];
        let (_, found) = sweep_rings(&[a, b]);
        let want = [touch(3, 0), touch(4, 0)];
        assert_eq!(found.touches, want);
        assert!(found.crossings.is_empty());
    }

    /// A bow-tie crosses itself; stop mode reports exactly that crossing.
    #[test]
    fn bow_tie_crosses() {
        let (pool, starts) = build(&[vec![(0., 0.), (2., 2.), (2., 0.), (0., 2.)]]);
        for stop in [false, true] {
            let found = run(&pool, &starts, stop);
            assert_eq!(found.crossings, [crossing(0, 2)]);
            assert!(found.touches.is_empty());
        }
    }

    /// Many edges crossing at one point that is no vertex: a crossing is found, and in stop
    /// mode only one.
    #[test]
    fn many_edges_crossing_at_a_non_vertex_point() {
        let dirs = [(2., 0.), (2., 1.), (2., 2.), (1., 2.), (0., 2.), (-1., 2.)];
        let rings: Vec<_> = dirs
            .iter()
            .map(|&(dx, dy)| {
                vec![
                    (3. - dx, 3. - dy),
                    (3. + dx, 3. + dy),
                    (3. + dx / 2., 3.5 + dy),
                ]
            })
            .collect();
        let (pool, starts) = build(&rings);
        let real = brute_crossings(&pool, &starts);
        for stop in [false, true] {
            let found = run(&pool, &starts, stop);
            assert!(!found.crossings.is_empty());
            assert!(found.crossings.iter().all(|c| brute_cross(&pool, c.a, c.b)));
            assert!(found.crossings.len() <= if stop { 1 } else { real.len() });
        }
    }

    /// A self-crossing star polygon {7/3}: crossings everywhere, at least one reported.
    #[test]
    fn star_polygon_crosses() {
        let ring: Vec<_> = (0..7)
            .map(|k| {
                let a = (k * 3 % 7) as f64 * core::f64::consts::TAU / 7.0;
                (a.cos(), a.sin())
            })
            .collect();
        let (pool, starts) = build(&[ring]);
        let found = run(&pool, &starts, false);
        assert!(!found.crossings.is_empty());
        assert!(found.crossings.iter().all(|c| brute_cross(&pool, c.a, c.b)));
    }

    /// A star of edges through (3,3): four triangles of a fan and a hole share it as a
    /// vertex, and it lies inside the top edge of the hole's outer ring. Every node there
    /// touches that edge; nothing else is reported.
    #[test]
    fn star_of_edges_through_one_point() {
        let apex = (3., 3.);
        let rims = [
            [(6., 4.), (6., 5.)],
            [(6., 6.), (4., 6.)],
            [(3., 6.), (1., 6.)],
            [(0., 5.), (0., 4.)],
        ];
        let mut rings: Vec<Vec<(f64, f64)>> = rims.iter().map(|r| vec![apex, r[0], r[1]]).collect();
        let (_, found) = sweep_rings(&rings);
        assert!(found.touches.is_empty() && found.crossings.is_empty());
        rings.push(vec![(0., 3.), (0., -3.), (6., -3.), (6., 3.)]);
        rings.push(vec![apex, (2., 0.), (4., 0.)]);
        let (pool, found) = sweep_rings(&rings);
        let top = NodeId(15); // (6,3) → (0,3)
        let at_apex: Vec<_> = (0..pool.len() as u32)
            .map(NodeId)
            .filter(|&n| pool.p(n) == Point::new(3., 3.))
            .collect();
        assert_eq!(at_apex.len(), 5);
        let want: Vec<_> = at_apex
            .iter()
            .map(|&n| Touch {
                vertex: n,
                edge: top,
            })
            .collect();
        assert_eq!(found.touches, want);
        assert!(found.crossings.is_empty());
    }

    /// Vertical edges: collinear overlaps, T-junctions and a crossing with a horizontal one.
    #[test]
    fn vertical_edges() {
        // Two thin rings on the line x = 2 overlapping on y in 1..3.
        let a = vec![(2., 0.), (2., 3.), (1., 3.)];
        let b = vec![(2., 1.), (3., 4.), (2., 4.)];
        let (_, found) = sweep_rings(&[a, b]);
        // (2,1) lies inside a's edge (2,0)→(2,3); (2,3) lies inside b's edge (2,4)→(2,1).
        let want = [touch(1, 5), touch(3, 0)];
        assert_eq!(found.touches, want);
        assert!(found.crossings.is_empty());
        // A thin triangle across a vertical edge: its edges cross the vertical one between
        // their vertices, and the leftmost crossing, (2, 1.75) on edge 5, is always found.
        let v = vec![(2., 0.), (2., 4.), (2.5, 4.)];
        let h = vec![(0., 2.), (4., 2.), (4., 1.5)];
        let (pool, starts) = build(&[v, h]);
        let found = run(&pool, &starts, false);
        assert!(found.crossings.contains(&crossing(0, 5)));
        assert!(found.crossings.iter().all(|c| brute_cross(&pool, c.a, c.b)));
        assert_eq!(run(&pool, &starts, true).crossings.len(), 1);
    }

    /// A ring whose own vertex lies on its own edge is a touch too.
    #[test]
    fn ring_touching_itself() {
        let ring = vec![(0., 0.), (4., 0.), (4., 4.), (2., 0.), (0., 4.)];
        let (_, found) = sweep_rings(&[ring]);
        assert_eq!(found.touches, [touch(3, 0)]);
        assert!(found.crossings.is_empty());
    }

    /// −0.0 and +0.0 are one point: a shared vertex stays silent, and a point on an edge
    /// with the other zero still touches it.
    #[test]
    fn negative_zero_is_the_same_point() {
        let hole = vec![(-0.0, -0.0), (3., 5.), (5., 3.)];
        let (_, found) = sweep_rings(&[outer(), hole]);
        assert!(found.touches.is_empty() && found.crossings.is_empty());
        let hole = vec![(-0.0, 5.), (3., 6.), (3., 4.)];
        let (_, found) = sweep_rings(&[outer(), hole]);
        assert_eq!(found.touches, [touch(4, 3)]);
    }

    /// Zero-length edges (a repeated point) are skipped, never touched nor crossing.
    #[test]
    fn zero_length_edges_are_skipped() {
        let ring = vec![(0., 0.), (4., 0.), (4., 0.), (2., 3.)];
        let (_, found) = sweep_rings(&[ring]);
        assert!(found.touches.is_empty() && found.crossings.is_empty());
    }

    /// A start that is not a node, or an unlinked one, neither panics nor loops.
    #[test]
    fn broken_starts_terminate() {
        let (mut pool, _) = build(&[outer()]);
        pool.remove(NodeId(1));
        let found = run(&pool, &[NodeId(1), NodeId(99)], false);
        assert_eq!(found.order.len(), pool.len());
    }

    /// Huge coordinates that overflow inside `orient2d` neither panic nor loop.
    #[test]
    fn extreme_coordinates_do_not_panic() {
        let m = f64::MAX;
        let rings = [
            vec![(-m, -m), (m, -m), (m, m), (-m, m)],
            vec![(0., -m), (m, 0.), (0., m), (-m, 0.), (0., 0.), (m, m)],
            vec![(-m, m), (m, -m), (m / 2., m / 3.)],
        ];
        let (pool, starts) = build(&rings);
        for stop in [false, true] {
            let _ = run(&pool, &starts, stop);
        }
    }

    /// A random ring of exactly `len` grid points, no two consecutive ones equal.
    fn fixed_ring(rng: &mut Rng, len: usize) -> Vec<(f64, f64)> {
        let mut ring: Vec<(f64, f64)> = Vec::with_capacity(len);
        while ring.len() < len {
            let q = (rng.below(7) as f64, rng.below(7) as f64);
            let closes = ring.len() + 1 == len && ring.first() == Some(&q);
            if ring.last() != Some(&q) && !closes {
                ring.push(q);
            }
        }
        ring
    }

    /// A second sweep of the same size reuses every buffer: no reallocation.
    #[test]
    fn scratch_is_reused() {
        let mut rng = Rng(7);
        let case = |rng: &mut Rng| (0..4).map(|_| fixed_ring(rng, 6)).collect::<Vec<_>>();
        let (pool, starts) = build(&case(&mut rng));
        let mut scratch = SweepScratch::default();
        let (mut touches, mut crossings) = (Vec::new(), Vec::new());
        sweep(
            &pool,
            &starts,
            &mut scratch,
            false,
            &mut touches,
            &mut crossings,
        );
        let buffers = |s: &SweepScratch| {
            let order = (s.order.as_ptr() as usize, s.order.capacity());
            (
                order,
                (s.status.as_ptr() as usize, s.status.capacity()),
                s.run.capacity(),
            )
        };
        let before = buffers(&scratch);
        for _ in 0..200 {
            let (pool, starts) = build(&case(&mut rng));
            touches.clear();
            crossings.clear();
            sweep(
                &pool,
                &starts,
                &mut scratch,
                false,
                &mut touches,
                &mut crossings,
            );
            assert_eq!(buffers(&scratch), before);
        }
    }

    /// A large star-shaped simple polygon around a hole: nothing to report, quickly.
    #[test]
    fn large_simple_polygon_is_clean() {
        let n = 20_000;
        let ring: Vec<_> = (0..n)
            .map(|k| {
                let a = k as f64 * core::f64::consts::TAU / n as f64;
                let r = if k % 2 == 0 { 1000.0 } else { 900.0 };
                (r * a.cos(), r * a.sin())
            })
            .collect();
        let ring = tidy(ring).unwrap_or_default();
        let (_, found) = sweep_rings(&[ring, vec![(-5., -5.), (5., -5.), (5., 5.), (-5., 5.)]]);
        assert!(found.crossings.is_empty());
    }
}
