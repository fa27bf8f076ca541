//! Stage *small*, in place of all the others for one small polygon: an outer ring and
//! up to [`RINGS`]` - 1` holes directly inside it, of at most [`MAX`] nodes with the
//! bridges' copies (a county, a building, nearly every glyph; rings touching at vertices
//! may make it several polygons) in one pass over a few
//! compact arrays: up to 64 nodes on `u64` masks ([`Narrow`]), up to 128 on `u128`
//! ([`Wide`]), the same code for both.
//!
//! The pipeline's stages are built for any number of rings of any size; on a polygon of
//! a dozen vertices their set-up costs more than their work. This stage does what they do
//! for such a polygon, in the same order and with the same exact predicates, and gives the
//! same result: the same triangles in the same order, the same dropped vertices.
//!
//! 1. **Load** the vertices, widened to `f64` (exact), each ring linked by one-byte indices.
//! 2. **Filter** repeated and straight vertices, and in strict mode spikes' tips, exactly
//!    as `clean` does, in its order (after a spike, a crossing of the input's edges that
//!    the tip hid hands the input back, as `clean` refuses it).
//! 3. **Prove** that no two edges cross, and list where they meet other than neighbours
//!    at their shared vertex (`touch`): every pair whose boxes overlap is decided by
//!    exact signs (a lone ring star-shaped from its vertices' mean first passes an O(n)
//!    certificate). Where a vertex lies inside an edge, the edge is split there; the
//!    nodes at a shared position take the lowest vertex index there.
//! 4. **Orient** every ring counter-clockwise by the turn at its rightmost-lowest vertex.
//! 5. **Nest** (`holes`): one ring must contain all the others, and none of those another
//!    (by exact crossing parity at a vertex no other ring touches, or, where every vertex
//!    of a ring is touched, at one off the ring it is tested against); the holes are
//!    turned clockwise; rings must not cross where they touch.
//! 6. **Join and bridge**: rings touching are joined as `touch` joins them (`touch`), and
//!    every hole left is bridged (`holes`) to the polygon around it as `bridge` does: by
//!    descending rightmost x, the ray's nearest hit, the same visible vertex, the same two
//!    copies.
//! 7. **Clip** each polygon, in ring order, with the strategy's walk (`walk`): the fast
//!    one with the same start, the same "not an ear" marks, the same order of ears and
//!    the same fan at the end; the quality one with the same queue order (smallest angle
//!    rank, then node). Reflex and marked nodes are bit masks. A cut that would need the
//!    clipper's tidying (where a bridge's or a touch's nodes come together) hands the
//!    polygon back.
//!
//! Whatever the pipeline would treat specially makes the stage give up (`false`) before
//! writing anything the pipeline would not: non-finite coordinates or ones outside the
//! exact range of the signs (`geom::orient_exact`), a spike in lenient
//! mode or one hiding a crossing, a ring left with fewer than three vertices (but for the
//! only ring in strict mode, dropped whole as `clean` drops it), two edges crossing, more
//! than eight nodes at one position, a ring touching itself at its rightmost vertex or
//! (lenient mode) anywhere, touching rings joined in a way `touch` decides by another
//! rule, a ring with every vertex on others whose vertices disagree on its nesting, rings
//! nested otherwise, a bridge target the pipeline would choose by a fallback, a clockwise last
//! triangle or a ring the walk cannot finish. The triangulator then runs the pipeline
//! from the start, which finds and reports the same things as without this stage.
//! `core/tests/small.rs` holds the two to the same output.

use crate::context::Context;
use crate::geom::{
    approx_cross, boxed_segments_meet, crosses, greatest, least, orient2d, orient_exact,
    ray_crossing, within_box, Coord, Orientation, Point,
};
use crate::report::{DropReason, Dropped};
use crate::structures::{scale, slot};
use crate::Nesting;

mod holes;
mod touch;
mod walk;

pub(crate) use walk::clip_ring;

/// The most nodes the stage holds: the input's vertices (a closing point included) and
/// two copies per hole, in its wide form; its node masks fit one `u128`, its links one
/// byte each. The narrow form ([`Narrow`]) holds up to 64, on `u64` masks, which most
/// polygons fit and which runs faster.
pub(crate) const MAX: usize = 128;

/// The most nodes the narrow form holds.
pub(crate) const NARROW_MAX: usize = 64;

/// The narrow form of the stage's scratch: up to [`NARROW_MAX`] nodes.
pub(crate) type Narrow = Scratch<NARROW_MAX, u64>;

/// The wide form: up to [`MAX`] nodes.
pub(crate) type Wide = Scratch<MAX, u128>;

/// A set of nodes, one bit each: `u64` for up to 64 nodes, `u128` for up to 128.
pub(crate) trait Mask:
    Copy
    + Eq
    + core::fmt::Debug
    + core::ops::BitOr<Output = Self>
    + core::ops::BitAnd<Output = Self>
    + core::ops::Not<Output = Self>
    + core::ops::BitOrAssign
    + core::ops::BitAndAssign
    + core::ops::BitXorAssign
{
    /// The empty set.
    const NONE: Self;
    /// The set of node `v` alone.
    fn bit(v: usize) -> Self;
    /// The lowest node of a set that is not empty.
    fn lowest(self) -> usize;
    /// A set that is not empty without its lowest node.
    fn without_lowest(self) -> Self;
    /// The number of nodes in the set.
    fn count(self) -> u32;
    /// The set with node `v` in it or not, as `on` says (without a branch).
    fn with(self, v: usize, on: bool) -> Self;
}

macro_rules! mask {
    ($t:ty) => {
        impl Mask for $t {
            const NONE: Self = 0;
            #[inline(always)]
            fn bit(v: usize) -> Self {
                1 << v
            }
            #[inline(always)]
            fn lowest(self) -> usize {
                self.trailing_zeros() as usize
            }
            #[inline(always)]
            fn without_lowest(self) -> Self {
                self & (self - 1)
            }
            #[inline(always)]
            fn count(self) -> u32 {
                self.count_ones()
            }
            #[inline(always)]
            fn with(self, v: usize, on: bool) -> Self {
                (self & !(1 << v)) | (<$t>::from(on) << v)
            }
        }
    };
}
mask!(u64);
mask!(u128);

/// The most rings: the outer one and its holes.
pub(crate) const RINGS: usize = 8;

/// The stage's arrays, by node index: the input's vertices first (node i is vertex i),
/// then the copies the bridges make.
#[derive(Debug)]
pub(crate) struct Scratch<const N: usize, M> {
    p: [Point; N],
    next: [u8; N],
    prev: [u8; N],
    /// The input vertex of each node (a copy repeats its original's).
    vertex: [u8; N],
    /// The nodes in use: the vertices, then the bridges' copies.
    nodes: usize,
    /// The rings: how many, where each starts in the input (and the end), a live node
    /// where the filtered ring starts, its live vertices and its rightmost-lowest node.
    rings: usize,
    first: [u8; RINGS + 1],
    start: [u8; RINGS],
    len: [u8; RINGS],
    rightmost: [u8; RINGS],
    /// The ring containing the others (before joining touching rings).
    outer: usize,
    /// The rings that are holes, one bit each (every ring but `outer`, until joining
    /// touching rings makes them cycles of either kind; the others are polygons).
    hole_rings: u8,
    /// The edges' boxes for the proof, ring after ring, each in ring order from its start:
    /// x0, x1, y0, y1.
    boxes: [[f64; 4]; N],
    /// The start node of each of those edges.
    from: [u8; N],
    /// The nodes turning left (counter-clockwise) on their filtered ring, as it ran before
    /// `orient`; every other live node turns right (none is straight).
    left: M,
    /// The nodes whose ring runs against its input order now (turned by `orient`, or as a
    /// hole), so that they turn the other way.
    reversed: M,
    /// The nodes whose turn the bridges changed (their ends and the ends' copies).
    fresh: M,
    /// Twice the polygon's area as lenient mode sums it (see [`double_area`]).
    area: f64,
    /// Pairs of nodes at one position (rings touching there, or a ring touching itself;
    /// see [`touch`]), how many, and all their nodes.
    touch: [[u8; 2]; TOUCHES],
    touches: usize,
    touched: M,
    /// Vertices found inside another ring's edge: the edge (its start node) and the
    /// vertex, until [`touch::split`] splits the edge there (a touch then).
    tee: [[u8; 2]; TOUCHES],
    tees: usize,
    /// The edge (start node) each split node splits, by its place after the input's.
    split_of: [u8; TOUCHES],
    /// Every node at a position several share, by position then node (`cx.shared`), and
    /// how many (see [`touch::list_shared`]).
    shared: [u8; 2 * TOUCHES],
    shared_len: usize,
}

/// The most pairs of nodes at shared positions (and vertices inside edges) that the
/// stage takes.
const TOUCHES: usize = 16;

impl<const N: usize, M: Mask> Default for Scratch<N, M> {
    fn default() -> Self {
        Scratch {
            p: [Point::new(0.0, 0.0); N],
            next: [0; N],
            prev: [0; N],
            vertex: [0; N],
            nodes: 0,
            rings: 0,
            first: [0; RINGS + 1],
            start: [0; RINGS],
            len: [0; RINGS],
            rightmost: [0; RINGS],
            outer: 0,
            hole_rings: 0,
            boxes: [[0.0; 4]; N],
            from: [0; N],
            left: M::NONE,
            reversed: M::NONE,
            fresh: M::NONE,
            area: 0.0,
            touch: [[0; 2]; TOUCHES],
            touches: 0,
            touched: M::NONE,
            tee: [[0; 2]; TOUCHES],
            tees: 0,
            split_of: [0; TOUCHES],
            shared: [0; 2 * TOUCHES],
            shared_len: 0,
        }
    }
}

impl<const N: usize, M: Mask> Scratch<N, M> {
    fn next(&self, v: usize) -> usize {
        usize::from(self.next[v])
    }

    fn prev(&self, v: usize) -> usize {
        usize::from(self.prev[v])
    }

    /// Unlinks `v` from its ring.
    fn unlink(&mut self, v: usize) {
        let (p, n) = (self.prev[v], self.next[v]);
        self.next[usize::from(p)] = n;
        self.prev[usize::from(n)] = p;
    }

    /// The live nodes of ring `r`, from its start.
    fn ring(&self, r: usize) -> impl Iterator<Item = usize> + '_ {
        let mut v = usize::from(self.start[r]);
        (0..self.len[r]).map(move |_| {
            let at = v;
            v = self.next(v);
            at
        })
    }
}

/// The set of node `v` alone.
fn bit<M: Mask>(v: usize) -> M {
    M::bit(v)
}

/// The nodes of a set, lowest first.
fn members<M: Mask>(mut mask: M) -> impl Iterator<Item = usize> {
    core::iter::from_fn(move || {
        (mask != M::NONE).then(|| {
            let v = mask.lowest();
            mask = mask.without_lowest();
            v
        })
    })
}

/// The live nodes of ring `r` (before it is bridged).
fn ring_mask<const N: usize, M: Mask>(s: &Scratch<N, M>, r: usize) -> M {
    s.ring(r).fold(M::NONE, |mask, v| mask | bit(v))
}

/// [`ring_mask`] of every ring, by ring (empty past the last).
fn ring_masks<const N: usize, M: Mask>(s: &Scratch<N, M>) -> [M; RINGS] {
    core::array::from_fn(|r| {
        if r < s.rings {
            ring_mask(s, r)
        } else {
            M::NONE
        }
    })
}

/// The winding number of ring `r` round `q`, a point on none of its edges
/// ([`ray_crossing`], as `nest` counts).
fn winding<const N: usize, M: Mask>(s: &Scratch<N, M>, r: usize, q: Point) -> i64 {
    (s.ring(r))
        .map(|v| ray_crossing(s.p[v], s.p[s.next(v)], q))
        .sum()
}

/// The nodes the stage needs for this input (its vertices and two copies per hole) when
/// it may take it: one ring of 3 to [`MAX`] vertices, or up to [`RINGS`] rings of at
/// least three vertices each whose nodes number at most [`MAX`]. A scratch of `N` nodes
/// takes an input of up to `N`.
pub(crate) fn nodes(vertices: usize, ring_starts: &[usize]) -> Option<usize> {
    if ring_starts.first() != Some(&0) || ring_starts.len() > RINGS {
        return None;
    }
    let rings = ring_starts.len();
    let nodes = vertices + 2 * (rings - 1);
    let proper = rings == 1
        || (ring_starts.windows(2).all(|w| w[1] >= w[0] + 3)
            && ring_starts[rings - 1] + 3 <= vertices);
    (proper && (3..=MAX).contains(&nodes)).then_some(nodes)
}

/// Steps 1–5: loads, filters, proves, orients and nests the rings (strict mode's input
/// check). Records the dropped vertices in `cx.dropped` (cleared first). `false` when the
/// input needs the pipeline; then `cx` holds nothing the pipeline reads (it resets it).
/// The caller has asked [`nodes`].
pub(crate) fn check<T: Coord, const N: usize, M: Mask>(
    cx: &mut Context,
    s: &mut Scratch<N, M>,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    nesting: Nesting,
    lenient: bool,
) -> bool {
    let n = vertices.len();
    cx.dropped.clear();
    cx.repairs.clear();
    // 1. load, as `load` does (−0.0 read as +0.0)
    for (i, v) in vertices.iter().enumerate() {
        let p = Point::new(v[0].to_f64() + 0.0, v[1].to_f64() + 0.0);
        // (non-finite, or too large or small for exact signs: the pipeline refuses, or
        // in lenient mode drops or keeps them)
        if !(orient_exact(p.x) && orient_exact(p.y)) {
            return false;
        }
        s.p[i] = p;
        // (n ≤ N ≤ 128: every index fits a byte)
        s.next[i] = (i + 1) as u8;
        s.prev[i] = i.wrapping_sub(1) as u8;
        s.vertex[i] = i as u8;
    }
    s.rings = ring_starts.len();
    s.nodes = n;
    (s.left, s.reversed, s.fresh) = (M::NONE, M::NONE, M::NONE);
    (s.touches, s.touched, s.tees, s.shared_len) = (0, M::NONE, 0, 0);
    for r in 0..s.rings {
        let (f, e) = (ring_starts[r], ring_starts.get(r + 1).copied().unwrap_or(n));
        (s.first[r], s.first[r + 1]) = (f as u8, e as u8);
        (s.next[e - 1], s.prev[f]) = (f as u8, (e - 1) as u8);
        if !filter(cx, s, r, !lenient) {
            return false;
        }
    }
    // (a spike's tip, or a ring of no area, may have hidden a crossing of the input's
    // edges: `clean` refuses that input, with the crossing it names)
    let gone = |d: &Dropped| matches!(d.reason, DropReason::Spike | DropReason::DegenerateRing);
    if cx.dropped.iter().any(gone) && crossed_as_loaded(s) {
        return false;
    }
    if s.len[0] == 0 {
        // the only ring dropped: nothing to triangulate
        (s.rings, s.outer, s.hole_rings) = (0, 0, 0);
        return true;
    }
    let proved = if s.rings == 1 {
        star_shaped(s) || apart(s)
    } else {
        apart(s)
    };
    if !proved {
        return false;
    }
    if s.touches > 0 {
        touch::list_shared(s);
        canonical_vertices(cx, s);
    }
    if s.tees > 0 && !touch::split(s) {
        return false;
    }
    for r in 0..s.rings {
        if !orient(s, r) {
            return false;
        }
    }
    (s.outer, s.hole_rings) = (0, 0);
    (s.rings == 1 || holes::nest(s, nesting)) && touch::proper(s)
}

/// Step 2 for ring `r`, `clean`'s filter (`filter_ring`) move for move: the same vertices
/// dropped, in the same order, and the same start. `false` on a spike unless `spikes`
/// (strict mode: the tip is dropped, as `clean` drops it), or when fewer than three
/// vertices are left — but for the only ring in strict mode, which is then dropped whole
/// (its length 0).
fn filter<const N: usize, M: Mask>(
    cx: &mut Context,
    s: &mut Scratch<N, M>,
    r: usize,
    spikes: bool,
) -> bool {
    let mut len = usize::from(s.first[r + 1] - s.first[r]);
    let mut v = usize::from(s.first[r]);
    // the last vertex known good; a full lap without a drop ends the loop
    let mut stop = s.prev(v);
    let drop = |cx: &mut Context, s: &mut Scratch<N, M>, v: usize, reason: DropReason| {
        s.unlink(v);
        cx.dropped.push(Dropped {
            vertex: v as u32,
            ring: r as u32,
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
            s.left = s.left.with(v, left);
            if v == stop {
                break;
            }
            v = next;
            continue;
        } else if within_box(pp, px, pn) {
            DropReason::Collinear
        } else if spikes {
            DropReason::Spike
        } else {
            // (lenient mode's repairs were tuned on the pipeline's rings)
            return false;
        };
        drop(cx, s, v, reason);
        len -= 1;
        // the previous vertex may have become straight: look again
        v = prev;
        stop = s.prev(prev);
    }
    s.start[r] = v as u8;
    s.len[r] = len as u8;
    if len < 3 && spikes && s.rings == 1 {
        // strict mode, the only ring: dropped whole, as `clean` drops a ring of no area
        for _ in 0..len {
            let next = s.next(v);
            drop(cx, s, v, DropReason::DegenerateRing);
            v = next;
        }
        s.len[r] = 0;
        return true;
    }
    len >= 3
}

/// Whether two edges of the rings as loaded (repeated and straight vertices, spikes
/// included) cross properly, neighbours on a ring aside: what `clean` looks for once the
/// filter dropped a spike's tip (`refuse_hidden_crossing`), comparing every pair whose
/// boxes overlap.
fn crossed_as_loaded<const N: usize, M: Mask>(s: &Scratch<N, M>) -> bool {
    // each loaded edge: its box, its start and its end (a ring's last vertex to its first)
    let mut edges = [([0.0; 4], 0u8, 0u8); N];
    let mut k = 0;
    for r in 0..s.rings {
        let (f, e) = (usize::from(s.first[r]), usize::from(s.first[r + 1]));
        for i in f..e {
            let end = if i + 1 == e { f } else { i + 1 };
            let (a, b) = (s.p[i], s.p[end]);
            let bounds = edge_box(a, b);
            edges[k] = (bounds, i as u8, end as u8);
            k += 1;
        }
    }
    // by their left sides: each compared with those starting before it ends
    let edges = &mut edges[..k];
    edges.sort_unstable_by(|e, f| e.0[0].total_cmp(&f.0[0]));
    let edges = &*edges;
    edges
        .iter()
        .enumerate()
        .any(|(k, &([_, x1, y0, y1], a, b))| {
            let starting = edges[k + 1..].iter().take_while(|f| f.0[0] <= x1);
            starting.into_iter().any(|&([_, _, w0, w1], c, d)| {
                // (neighbours share a vertex, which no proper crossing does)
                w0 <= y1 && y0 <= w1 && b != c && d != a && {
                    let [a, b, c, d] = [a, b, c, d].map(|v| s.p[usize::from(v)]);
                    crosses(a, b, c, d)
                }
            })
        })
}

/// The box of the edge from `a` to `b`, finite points: left, right, bottom, top (one
/// plain comparison per axis, without `f64::min`'s NaN handling).
#[inline(always)]
fn edge_box(a: Point, b: Point) -> [f64; 4] {
    let (x0, x1) = if b.x < a.x { (b.x, a.x) } else { (a.x, b.x) };
    let (y0, y1) = if b.y < a.y { (b.y, a.y) } else { (a.y, b.y) };
    [x0, x1, y0, y1]
}

/// Whether a turn is to the left; `None` when straight.
fn left_turn(o: Orientation) -> Option<bool> {
    match o {
        Orientation::CounterClockwise => Some(true),
        Orientation::Clockwise => Some(false),
        Orientation::Collinear => None,
    }
}

/// Step 3 for most single small rings in O(n): whether the filtered ring is star-shaped
/// from the mean of its vertices, c, which proves it simple. If every edge turns strictly
/// the same way round c and the edges wind round c exactly once, their angular sectors
/// (each less than a half-turn) tile the turn round c without overlapping: edges that are
/// no neighbours lie in disjoint sectors and cannot meet, and neighbours meet only on the
/// ray through their shared vertex, at that vertex. (The mean is only a guess at a point
/// of the kernel; the signs decide.) Counting the winding is exact too: with every edge
/// going counter-clockwise round c, exactly the edges from below (or on) c's horizontal
/// line to above it cross that line right of c.
fn star_shaped<const N: usize, M: Mask>(s: &Scratch<N, M>) -> bool {
    let len = usize::from(s.len[0]);
    let (mut sx, mut sy) = (0.0, 0.0);
    for v in s.ring(0) {
        (sx, sy) = (sx + s.p[v].x, sy + s.p[v].y);
    }
    let c = Point::new(sx / len as f64, sy / len as f64);
    // (a mean of tiny coordinates may need bits below those of the coordinates: its signs
    // would not be exact)
    if !(orient_exact(c.x) && orient_exact(c.y)) {
        return false;
    }
    let v = usize::from(s.start[0]);
    let first = orient2d(c, s.p[v], s.p[s.next(v)]);
    if first == Orientation::Collinear {
        return false;
    }
    // counted for the ring as it runs: crossings upwards if it runs counter-clockwise
    // round c, downwards if clockwise
    let up = first == Orientation::CounterClockwise;
    let mut crossings = 0;
    for v in s.ring(0) {
        let (a, b) = (s.p[v], s.p[s.next(v)]);
        if orient2d(c, a, b) != first {
            return false;
        }
        let (low, high) = if up { (a, b) } else { (b, a) };
        crossings += usize::from(low.y <= c.y && c.y < high.y);
    }
    crossings == 1
}

/// Step 3: whether no two edges of the filtered rings meet, other than neighbours on one
/// ring at their shared vertex (which, with no straight turn left, is all neighbours have
/// in common). Then no two vertices share a position either. Every pair of edges whose
/// boxes overlap is decided by exact signs: up to [`PAIRS_MAX`] edges, found by comparing
/// every pair of boxes; more, through bands of the bounding box ([`apart_banded`]).
fn apart<const N: usize, M: Mask>(s: &mut Scratch<N, M>) -> bool {
    // the rings' edges one after the other, each with its neighbours on its ring
    let mut around = [[0u8; 2]; N];
    let mut k = 0;
    for r in 0..s.rings {
        let (first, len) = (k, usize::from(s.len[r]));
        let mut v = usize::from(s.start[r]);
        for i in 0..len {
            let (a, b) = (s.p[v], s.p[s.next(v)]);
            s.boxes[k] = edge_box(a, b);
            s.from[k] = v as u8;
            let before = if i == 0 { len - 1 } else { i - 1 };
            let after = if i + 1 == len { 0 } else { i + 1 };
            around[k] = [(first + before) as u8, (first + after) as u8];
            v = s.next(v);
            k += 1;
        }
    }
    let edges = k;
    if edges > PAIRS_MAX {
        return apart_banded(s, &around, edges);
    }
    for (k, around) in around.iter().enumerate().take(edges) {
        let [x0, x1, y0, y1] = s.boxes[k];
        let [before, after] = around.map(usize::from);
        for m in k + 1..edges {
            let [u0, u1, w0, w1] = s.boxes[m];
            let overlap = u0 <= x1 && x0 <= u1 && w0 <= y1 && y0 <= w1;
            if overlap && m != after && m != before && !apart_pair(s, k, m) {
                return false;
            }
        }
    }
    true
}

/// Up to this many edges, [`apart`] compares every pair of boxes; more, it goes through
/// bands (measured: from 25 edges on, the bands cost less).
const PAIRS_MAX: usize = 24;

/// The columns (and rows) of [`apart_banded`].
const PROOF_BANDS: usize = 16;

/// [`apart`] for more edges: only the pairs [`EdgeBands`] offers, which every pair of
/// overlapping boxes is among. (A scan of every pair of boxes mispredicts about one
/// branch per pair; here the masks leave a few candidates per edge.)
fn apart_banded<const N: usize, M: Mask>(
    s: &mut Scratch<N, M>,
    around: &[[u8; 2]; N],
    edges: usize,
) -> bool {
    let bands = EdgeBands::<N, M>::new(&s.boxes[..edges]);
    let mut later = !M::NONE;
    for (k, around) in around.iter().enumerate().take(edges) {
        later &= !bit::<M>(k);
        let [before, after] = around.map(usize::from);
        let candidates = later & bands.meeting(k) & !(bit::<M>(before) | bit::<M>(after));
        let [x0, x1, y0, y1] = s.boxes[k];
        for m in members(candidates) {
            let [u0, u1, w0, w1] = s.boxes[m];
            let overlap = u0 <= x1 && x0 <= u1 && w0 <= y1 && y0 <= w1;
            if overlap && !apart_pair(s, k, m) {
                return false;
            }
        }
    }
    true
}

/// Edge boxes (left, right, bottom, top) sorted into bands: the boxes' bounding box cut
/// into [`PROOF_BANDS`] columns and as many rows, each box spanning a run of each. Two
/// boxes that overlap have runs that overlap in both (the bands are monotone in the
/// coordinates), read off node masks: by band, the boxes starting in a band up to it and
/// those ending in one from it on.
struct EdgeBands<const N: usize, M> {
    runs: [[u8; 4]; N],
    starts: [[M; PROOF_BANDS]; 2],
    ends: [[M; PROOF_BANDS]; 2],
}

impl<const N: usize, M: Mask> EdgeBands<N, M> {
    /// Sorts `boxes` (at most `N`, finite, not empty) into bands.
    #[inline(always)]
    fn new(boxes: &[[f64; 4]]) -> Self {
        let (mut lo, mut hi) = (boxes[0], boxes[0]);
        for b in boxes {
            (lo[0], lo[2]) = (least(lo[0], b[0]), least(lo[2], b[2]));
            (hi[1], hi[3]) = (greatest(hi[1], b[1]), greatest(hi[3], b[3]));
        }
        let (sx, sy) = (
            scale(PROOF_BANDS, hi[1] - lo[0]),
            scale(PROOF_BANDS, hi[3] - lo[2]),
        );
        let last = PROOF_BANDS - 1;
        let mut bands = EdgeBands {
            runs: [[0u8; 4]; N],
            starts: [[M::NONE; PROOF_BANDS]; 2],
            ends: [[M::NONE; PROOF_BANDS]; 2],
        };
        // (first each band's own, then summed)
        for (k, b) in boxes.iter().enumerate() {
            let run = [
                slot((b[0] - lo[0]) * sx, last),
                slot((b[1] - lo[0]) * sx, last),
                slot((b[2] - lo[2]) * sy, last),
                slot((b[3] - lo[2]) * sy, last),
            ];
            bands.runs[k] = run.map(|c| c as u8);
            bands.starts[0][run[0]] |= bit(k);
            bands.ends[0][run[1]] |= bit(k);
            bands.starts[1][run[2]] |= bit(k);
            bands.ends[1][run[3]] |= bit(k);
        }
        for axis in 0..2 {
            for k in 1..PROOF_BANDS {
                let below = bands.starts[axis][k - 1];
                bands.starts[axis][k] |= below;
                let above = bands.ends[axis][last - k + 1];
                bands.ends[axis][last - k] |= above;
            }
        }
        bands
    }

    /// The boxes whose runs overlap box `k`'s in both directions (`k` among them).
    fn meeting(&self, k: usize) -> M {
        let [c0, c1, r0, r1] = self.runs[k].map(usize::from);
        self.starts[0][c1] & self.ends[0][c0] & self.starts[1][r1] & self.ends[1][r0]
    }
}

/// Edges `k` and `m` of [`apart`], no neighbours, whose boxes overlap: true when they do
/// not meet, or meet at a vertex the stage lists ([`touch::record`]); false when they
/// cross or the stage cannot list the contact.
fn apart_pair<const N: usize, M: Mask>(s: &mut Scratch<N, M>, k: usize, m: usize) -> bool {
    let (e, f) = (usize::from(s.from[k]), usize::from(s.from[m]));
    let (a, b) = (s.p[e], s.p[s.next(e)]);
    let (c, d) = (s.p[f], s.p[s.next(f)]);
    // (edges with an end in common meet: no signs needed to know)
    let meet = a == c || a == d || b == c || b == d || boxed_segments_meet(a, b, c, d);
    !meet || touch::record(s, k, m)
}

/// Where rings touch, `clean`'s canonical vertices: all nodes at a position take the
/// lowest vertex index there, and the others are reported (`Coincident`), by position,
/// then node.
fn canonical_vertices<const N: usize, M: Mask>(cx: &mut Context, s: &mut Scratch<N, M>) {
    let mut i = 0;
    while i < s.shared_len {
        let j = touch::group_end(s, i);
        let group = &s.shared[i..j];
        let min = (group.iter()).map(|&v| s.vertex[usize::from(v)]).min();
        let min = min.unwrap_or(0);
        for k in i..j {
            let v = usize::from(s.shared[k]);
            if s.vertex[v] != min {
                cx.dropped.push(Dropped {
                    vertex: u32::from(s.vertex[v]),
                    ring: touch::ring_of(s, v) as u32,
                    reason: DropReason::Coincident,
                });
                s.vertex[v] = min;
            }
        }
        i = j;
    }
}

/// Step 4 for ring `r`, as `clean` orients a ring: the turn at the rightmost-lowest vertex
/// says whether the ring runs clockwise; then every link is reversed. False where the
/// ring touches itself there (`clean` then reads the edges there).
fn orient<const N: usize, M: Mask>(s: &mut Scratch<N, M>, r: usize) -> bool {
    let start = usize::from(s.start[r]);
    let mut best = start;
    for v in s.ring(r) {
        let (p, b) = (s.p[v], s.p[best]);
        if p.x > b.x || (p.x == b.x && p.y < b.y) {
            best = v;
        }
    }
    s.rightmost[r] = best as u8;
    // (where the ring touches itself there, `clean` orients it by the edges there: the
    // pipeline's)
    if s.touched & bit(best) != M::NONE && touch::touches_own_ring(s, best) {
        return false;
    }
    // (its turn, as the filter took it)
    if s.left & bit(best) == M::NONE {
        reverse(s, r);
    }
    true
}

/// Reverses ring `r`'s links.
fn reverse<const N: usize, M: Mask>(s: &mut Scratch<N, M>, r: usize) {
    let mut v = usize::from(s.start[r]);
    for _ in 0..s.len[r] {
        let next = s.next(v);
        core::mem::swap(&mut s.next[v], &mut s.prev[v]);
        s.reversed ^= bit(v);
        v = next;
    }
}

/// For the rings checked last: `Some(true)` when every ring runs as given, in input
/// order, the way the check turned it (the outer ring counter-clockwise, holes
/// clockwise), `Some(false)` when every ring runs against it; `None` where some run each
/// way. (Rings are the input's until the walk joins touching ones; a node splitting an
/// edge turned with its ring.)
pub(crate) fn rings_run<const N: usize, M: Mask>(s: &Scratch<N, M>) -> Option<bool> {
    if s.rings == 0 {
        return None;
    }
    let given = |r: usize| s.reversed & bit(usize::from(s.start[r])) == M::NONE;
    let first = given(0);
    (1..s.rings).all(|r| given(r) == first).then_some(first)
}

/// The number of holes of the polygon checked last.
pub(crate) fn hole_count<const N: usize, M: Mask>(s: &Scratch<N, M>) -> usize {
    s.hole_rings.count_ones() as usize
}

/// The number of polygons of the input clipped last: one, or several where touching rings
/// cut it into pieces.
pub(crate) fn polygon_count<const N: usize, M: Mask>(s: &Scratch<N, M>) -> usize {
    s.rings - hole_count(s)
}

/// Twice the polygon's area as lenient mode sums it (outer ring minus holes, each by the
/// shoelace formula from the ring's start, in floating point, in ring order): what the
/// deviation is measured against. Set by [`clip`].
pub(crate) fn double_area<const N: usize, M: Mask>(s: &Scratch<N, M>) -> f64 {
    s.area
}

/// Steps 6 and 7: bridges the checked polygon's holes and clips it into `out` (cleared
/// first) with the strategy's walk, the fast one or the quality one. `false` when a
/// bridge or the walk needs the pipeline, or the last triangle turns clockwise (in strict
/// mode): its repairs or errors decide then.
pub(crate) fn clip<const N: usize, M: Mask>(
    s: &mut Scratch<N, M>,
    quality: bool,
    lenient: bool,
    out: &mut Vec<[u32; 3]>,
) -> bool {
    if lenient {
        // (measured before touching rings are joined, as the pipeline measures)
        s.area = 0.0;
        for r in 0..s.rings {
            let mut sum = 0.0;
            for v in s.ring(r) {
                sum += approx_cross(s.p[v], s.p[s.next(v)]);
            }
            s.area += if r == s.outer { sum.abs() } else { -sum.abs() };
        }
    }
    // (lenient mode cuts a ring touching itself into lobes first, and its repairs were
    // tuned on them: the pipeline's)
    let self_touch = |s: &Scratch<N, M>| {
        (0..s.shared_len).any(|i| touch::touches_own_ring(s, usize::from(s.shared[i])))
    };
    if s.touches > 0 && ((lenient && self_touch(s)) || !touch::join(s)) {
        return false;
    }
    if s.hole_rings != 0 && !holes::bridge(s) {
        return false;
    }
    clip_ring(s, quality, lenient, out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{random, unit_random};

    #[test]
    fn edge_bands_offer_every_pair_of_overlapping_boxes() {
        let (mut below, mut unit) = (random(0x0bad_5eed), unit_random(0x5eed_0bad));
        let (mut offered, mut pairs) = (0, 0);
        for round in 0..400 {
            let n = 2 + below(127) as usize;
            // coordinates on a coarse grid now and then (boxes touching at their sides,
            // flat boxes), else spread over a range that changes with the round
            let span = [1.0, 1e-6, 1e9, 3.0][round % 4];
            let mut coordinate = || {
                let u = unit();
                if round % 3 == 0 {
                    (u * 8.0).floor() * span
                } else {
                    u * span
                }
            };
            let boxes: Vec<[f64; 4]> = (0..n)
                .map(|_| {
                    let a = Point::new(coordinate(), coordinate());
                    let b = Point::new(coordinate(), coordinate());
                    edge_box(a, b)
                })
                .collect();
            let bands = EdgeBands::<128, u128>::new(&boxes);
            for (k, e) in boxes.iter().enumerate() {
                let meeting = bands.meeting(k);
                assert!(
                    meeting & bit::<u128>(k) != 0,
                    "round {round}: box {k} itself"
                );
                for (m, f) in boxes.iter().enumerate() {
                    let overlap = f[0] <= e[1] && e[0] <= f[1] && f[2] <= e[3] && e[2] <= f[3];
                    let offers = meeting & bit::<u128>(m) != 0;
                    assert!(
                        !overlap || offers,
                        "round {round}: boxes {k} and {m} overlap"
                    );
                    offered += usize::from(offers);
                    pairs += 1;
                }
            }
        }
        // (and the bands narrow: not every pair is offered)
        assert!(offered < pairs * 3 / 4, "{offered} of {pairs} offered");
    }
}
