//! A quick proof for the common case of `clean`'s input check: no two edges meet, except
//! adjacent edges at their shared vertex. Then the sweep of `super::sweep` would find no
//! crossing and no T-junction, and no two nodes share a position, so `clean` skips it.
//!
//! A few hundred edges are sorted into columns and rows of their bounding box, and each
//! is compared with the edges whose columns and rows overlap its own; more go into a
//! uniform grid (or their x-monotone chains are paired through one), and edges sharing a
//! cell are compared. Box comparisons only narrow the candidates down;
//! every pair whose boxes overlap is decided by exact `orient2d` signs. Both scans have a
//! budget linear in the edges: when many long edges lie over each other they give up, say
//! "not proved", and the full sweep runs as before. Either way the result is the sweep's.
//!
//! Rings that touch (a hole's vertex on its polygon's boundary, two holes sharing a
//! corner, a hole running along its polygon's edge) meet, but only where the sweep would
//! hand on what it found as it is: nodes sharing a position, vertices inside edges (and
//! no crossing). [`edges_meet_at_vertices`] lists those instead of giving up; only
//! crossings leave the job to the sweep.
//!
//! The same scans find the crossing edges of lenient input ([`mark_crossed`]).

use super::sweep::Touch;
use crate::geom::Orientation;
use crate::geom::{boxed_segments_meet, cmp_xy, greatest, least, orient2d, within_box};
use crate::structures::{scale, shape, slot};
use crate::structures::{NodeId, Pool};

/// Box comparisons allowed per edge (plus a constant) before the proof gives up.
const BUDGET_PER_EDGE: usize = 16;

/// The same for [`mark_crossed`]: crossing input has many boxes over each other, and giving
/// up costs a second, slower pass over the edges.
const CROSSED_BUDGET_PER_EDGE: usize = 256;

/// Pairs of edges whose boxes overlap that [`edges_meet_at_vertices`] decides per edge
/// (plus a constant) before it gives up: a valid input's proof decides about one per edge
/// (1.0–1.3 on the earcut fixtures it proves), a grid of squares touching along their
/// sides (earcut's touching-holes3–5) more than ten, each with exact signs on collinear
/// edges, where the sweep is faster.
const CONTACTS_PER_EDGE: usize = 4;

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

/// Reusable buffers of [`edges_meet_at_vertices`].
#[derive(Debug, Default)]
pub(crate) struct ProofScratch {
    boxes: Vec<EdgeBox>,
    /// Grid scan: where each cell's entries start, and the entries (edge indices).
    start: Vec<u32>,
    entries: Vec<u32>,
    /// [`mark_crossed`]: start nodes of the crossing edges found.
    flagged: Vec<NodeId>,
    /// Chain scan: the x-monotone chains of the rings.
    chains: Vec<Chain>,
    /// By node: listed in `shared` already (each node once, however many pairs of edges
    /// meet at it; false again after each proof).
    listed: Vec<bool>,
}

/// The nodes at shared positions as [`contact`] finds them, each listed once.
struct Shared<'a> {
    nodes: &'a mut Vec<NodeId>,
    listed: &'a mut [bool],
}

impl Shared<'_> {
    fn push(&mut self, n: NodeId) {
        let listed = &mut self.listed[n.0 as usize];
        if !*listed {
            *listed = true;
            self.nodes.push(n);
        }
    }
}

/// A run of consecutive edges of one ring along which x never decreases or never
/// increases, with no two vertical edges in a row, and its bounding box. Within such a
/// chain only neighbouring edges' boxes can overlap, and edges on either side of a vertical
/// one: the others lie at different x.
#[derive(Clone, Copy, Debug)]
struct Chain {
    /// Index of its first edge (in ring order) in `boxes`, and the number of edges.
    start: u32,
    len: u32,
    /// Ring order runs towards smaller x.
    falling: bool,
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
}

/// Above [`SMALL`] edges, the chain scan is used while the rings have at most one chain per
/// this many edges (curves have few, long chains; a comb or a zigzag has one per edge or
/// two, and takes the grid).
const EDGES_PER_CHAIN: usize = 4;

/// Up to this many edges, comparing every pair of boxes is cheaper than banding them.
const TINY: usize = 32;

/// Up to this many edges, bands ([`scan_banded`]) are cheaper than a grid or chains.
const SMALL: usize = 512;

/// What [`edges_meet_at_vertices`] proved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Contact {
    /// No two edges meet, except adjacent edges at their shared vertex.
    Apart,
    /// Edges meet only at vertices: nodes that share a position, and vertices inside
    /// edges (T-junctions), as listed.
    AtVertices,
    /// Not proved: some edges cross or overlap, or the budget ran out.
    NotProved,
    /// The edges starting at these two nodes cross properly (found within the budget).
    Crossed(NodeId, NodeId),
}

/// Whether the edges of the rings through `starts` are proved to meet nowhere but at
/// vertices: [`Contact::Apart`] when no two meet, except adjacent ones at their shared
/// vertex; [`Contact::AtVertices`] when some also meet where nodes share a position or a
/// vertex lies inside an edge, and nowhere else. Then `shared` gets every node at a
/// position held by more than one node, sorted by position (then id), and `touches` every
/// node lying inside an edge, once per (edge, node), sorted — what the sweep of
/// `super::sweep` finds there, so that `clean` goes on as after the sweep.
/// [`Contact::Crossed`] when a pair found crosses properly; [`Contact::NotProved`] when
/// some pair meets otherwise than at vertices, or the budget ran out. `nodes` is filled
/// with the rings' nodes either way.
///
/// `turns_proper` says that no node's turn is collinear (as `clean`'s filter leaves every
/// ring): then adjacent edges meet only at their shared vertex, and no pair of them needs
/// a predicate.
///
/// Every pair of nodes at one position is seen: the edges leaving them have boxes that
/// overlap at that position, and no two adjacent nodes share one (`clean`'s filter drops
/// repeats). Every vertex inside an edge is seen the same way, through its own edges.
pub(crate) fn edges_meet_at_vertices(
    pool: &Pool,
    starts: &[NodeId],
    scratch: &mut ProofScratch,
    nodes: &mut Vec<NodeId>,
    turns_proper: bool,
    touches: &mut Vec<Touch>,
    shared: &mut Vec<NodeId>,
) -> Contact {
    collect_boxes(pool, starts, &mut scratch.boxes, Some(nodes));
    touches.clear();
    shared.clear();
    let mut listed = core::mem::take(&mut scratch.listed);
    if listed.len() < pool.len() {
        listed.resize(pool.len(), false);
    }
    let mut nodes = Shared {
        nodes: shared,
        listed: &mut listed,
    };
    // pairs of overlapping boxes decided by signs: past a few per edge (many rings lying
    // along each other), the sweep does it for less
    let mut contacts = CONTACTS_PER_EDGE * scratch.boxes.len() + 64;
    let mut crossed = None;
    let scan = scan(pool, scratch, BUDGET_PER_EDGE, |e, f| {
        if contacts == 0 {
            return true;
        }
        contacts -= 1;
        contact(pool, e, f, turns_proper, touches, &mut nodes, &mut crossed)
    });
    for &n in shared.iter() {
        listed[n.0 as usize] = false;
    }
    scratch.listed = listed;
    if scan != Scan::Done {
        return crossed.map_or(Contact::NotProved, |(a, b)| Contact::Crossed(a, b));
    }
    if touches.is_empty() && shared.is_empty() {
        return Contact::Apart;
    }
    // (each node once already)
    shared.sort_unstable_by(|&a, &b| cmp_xy(pool.p(a), pool.p(b)).then(a.cmp(&b)));
    touches.sort_unstable_by_key(|t| (t.edge, t.vertex));
    touches.dedup();
    Contact::AtVertices
}

/// The visitor of [`edges_meet_at_vertices`]: whether edges `e` and `f`, whose boxes
/// overlap, meet other than at vertices (stop: not proved; `crossed` names them where
/// they cross properly). Where they meet at a vertex, records the nodes there (`shared`)
/// or the vertex inside the other edge (`touches`).
fn contact(
    pool: &Pool,
    e: &EdgeBox,
    f: &EdgeBox,
    turns_proper: bool,
    touches: &mut Vec<Touch>,
    shared: &mut Shared,
    crossed: &mut Option<(NodeId, NodeId)>,
) -> bool {
    use Orientation::Collinear;
    if e.to == f.from || f.to == e.from {
        // adjacent edges (or a ring of two): as in the plain proof
        return meet(pool, e, f, turns_proper);
    }
    let (a, b, c, d) = (pool.p(e.from), pool.p(e.to), pool.p(f.from), pool.p(f.to));
    // An end in common (rings touching at a vertex; no edge has both ends at one
    // position): unless f runs on along e's line, they meet there only, and the nodes
    // there are listed without the four signs below (two of which would be of a repeated
    // point). On one line, the collinear case below lists the rest.
    let common = if a == c || a == d {
        Some((a, if a == c { d } else { c }))
    } else if b == c || b == d {
        Some((b, if b == c { d } else { c }))
    } else {
        None
    };
    if let Some((x, far)) = common {
        let other = if x == a { b } else { a };
        if orient2d(x, other, far) != Collinear {
            for n in [e.from, e.to, f.from, f.to] {
                if pool.p(n) == x {
                    shared.push(n);
                }
            }
            return false;
        }
    }
    let (o1, o2) = (orient2d(a, b, c), orient2d(a, b, d));
    if o1 != Collinear && o1 == o2 {
        return false; // f lies strictly on one side of e's line
    }
    if o1 == Collinear && o2 == Collinear {
        // On one line, with overlapping boxes: they touch end to end or overlap, and
        // meet where an endpoint of one lies on the other (closed) edge.
        for (v, g) in [(f.from, e), (f.to, e), (e.from, f), (e.to, f)] {
            let (p, g0, g1) = (pool.p(v), pool.p(g.from), pool.p(g.to));
            if p == g0 || p == g1 {
                shared.push(v);
                shared.push(if p == g0 { g.from } else { g.to });
            } else if within_box(g0, g1, p) {
                touches.push(Touch {
                    vertex: v,
                    edge: g.from,
                });
            }
        }
        return false;
    }
    let (o3, o4) = (orient2d(c, d, a), orient2d(c, d, b));
    if o3 != Collinear && o3 == o4 {
        return false;
    }
    // The lines meet in one point x, an endpoint lying on the other edge's line, or
    // none is (a proper crossing: the sweep's job).
    let x = match (o1, o2, o3, o4) {
        (Collinear, _, _, _) => c,
        (_, Collinear, _, _) => d,
        (_, _, Collinear, _) => a,
        (_, _, _, Collinear) => b,
        _ => {
            *crossed = Some((e.from, f.from));
            return true;
        }
    };
    if !(within_box(a, b, x) && within_box(c, d, x)) {
        return false; // x lies on one edge's line outside that edge: they do not meet
    }
    let at = |n: NodeId| pool.p(n) == x;
    let vertex_of = |g: &EdgeBox| {
        if at(g.from) {
            Some(g.from)
        } else if at(g.to) {
            Some(g.to)
        } else {
            None
        }
    };
    match (vertex_of(e), vertex_of(f)) {
        (Some(_), Some(_)) => {
            for n in [e.from, e.to, f.from, f.to] {
                if at(n) {
                    shared.push(n);
                }
            }
        }
        (None, Some(v)) => touches.push(Touch {
            vertex: v,
            edge: e.from,
        }),
        (Some(v), None) => touches.push(Touch {
            vertex: v,
            edge: f.from,
        }),
        // (x is an endpoint of e or f by its choice above)
        (None, None) => return true,
    }
    false
}

/// Lenient mode: flags every edge (by its start node) of the rings through `starts` that
/// properly crosses another, exactly as `super::sweep::mark_crossed` does, but comparing only
/// edges whose boxes overlap. Returns false, with some of the flags set, when the budget ran
/// out first; the caller must then finish the job another way.
pub(crate) fn mark_crossed(pool: &mut Pool, starts: &[NodeId], scratch: &mut ProofScratch) -> bool {
    let mut flagged = core::mem::take(&mut scratch.flagged);
    let done = crossings(pool, starts, scratch, &mut flagged, false);
    for &n in &flagged {
        pool.get_mut(n).crossed = true;
    }
    scratch.flagged = flagged;
    done
}

/// Strict mode: puts into `pair` the start nodes of two edges of the rings through `starts`
/// that properly cross, if any do (the first pair the scan meets), comparing only edges
/// whose boxes overlap. Returns false when the budget ran out first; the caller must then
/// look another way.
pub(crate) fn crossing_pair(
    pool: &Pool,
    starts: &[NodeId],
    scratch: &mut ProofScratch,
    pair: &mut Vec<NodeId>,
) -> bool {
    crossings(pool, starts, scratch, pair, true)
}

/// The start nodes of properly crossing edges, pair by pair, into `out` (only the first
/// pair with `first_only`); false when the budget ran out first.
fn crossings(
    pool: &Pool,
    starts: &[NodeId],
    scratch: &mut ProofScratch,
    out: &mut Vec<NodeId>,
    first_only: bool,
) -> bool {
    collect_boxes(pool, starts, &mut scratch.boxes, None);
    out.clear();
    scan(pool, scratch, CROSSED_BUDGET_PER_EDGE, |e, f| {
        // edges meeting at a node share an endpoint, which no proper crossing does (the
        // scans visit every pair of neighbours: spare them the predicates)
        if e.to == f.from || f.to == e.from {
            return false;
        }
        let (a, b, c, d) = (pool.p(e.from), pool.p(e.to), pool.p(f.from), pool.p(f.to));
        // (an edge of no length, a repeated vertex as loaded, crosses nothing properly,
        // and nor do edges with an end at one position, a border two rings share: their
        // signs would be zero, decided by exact arithmetic)
        let apart_ends = a != c && a != d && b != c && b != d;
        if a != b && c != d && apart_ends && crate::geom::crosses(a, b, c, d) {
            out.push(e.from);
            out.push(f.from);
            return first_only;
        }
        false
    }) != Scan::OutOfBudget
}

/// Fills `boxes` with the edges of the rings through `starts`, and `nodes` (if given) with
/// their start nodes.
fn collect_boxes(
    pool: &Pool,
    starts: &[NodeId],
    boxes: &mut Vec<EdgeBox>,
    mut nodes: Option<&mut Vec<NodeId>>,
) {
    boxes.clear();
    if let Some(nodes) = nodes.as_deref_mut() {
        nodes.clear();
    }
    for &start in starts {
        if start.idx() >= pool.len() {
            continue;
        }
        let mut n = start;
        // bounded like the sweep's walk, in case a start was unlinked
        for _ in 0..pool.len() {
            let next = pool.next(n);
            let (a, b) = (pool.p(n), pool.p(next));
            if let Some(nodes) = nodes.as_deref_mut() {
                nodes.push(n);
            }
            // coordinates are finite (load dropped or refused the others): plain
            // comparisons, without `f64::min`'s NaN handling
            let (x0, x1) = if b.x < a.x { (b.x, a.x) } else { (a.x, b.x) };
            let (y0, y1) = if b.y < a.y { (b.y, a.y) } else { (a.y, b.y) };
            boxes.push(EdgeBox {
                x0,
                x1,
                y0,
                y1,
                from: n,
                to: next,
            });
            n = next;
            if n == start {
                break;
            }
        }
    }
}

/// How a scan over the pairs of edges with overlapping boxes ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Scan {
    /// Every such pair was visited (some possibly twice).
    Done,
    /// The visitor asked to stop.
    Stopped,
    /// The budget ran out.
    OutOfBudget,
}

/// Visits the pairs of `scratch.boxes` whose boxes overlap until `visit` returns true,
/// allowing `per_edge` box comparisons (and cell listings) per edge. `scratch.boxes` must
/// hold the rings' edges in ring order, as [`collect_boxes`] leaves them.
fn scan(
    pool: &Pool,
    scratch: &mut ProofScratch,
    per_edge: usize,
    visit: impl FnMut(&EdgeBox, &EdgeBox) -> bool,
) -> Scan {
    let budget = per_edge * scratch.boxes.len() + 64;
    let n = scratch.boxes.len();
    if n <= TINY && n * n.saturating_sub(1) / 2 <= budget {
        scan_pairs(&scratch.boxes, visit)
    } else if n <= SMALL {
        scan_banded(&scratch.boxes, budget, visit)
    } else if collect_chains(pool, &scratch.boxes, &mut scratch.chains) {
        scan_chains(scratch, budget, visit)
    } else {
        scan_grid(scratch, budget, visit)
    }
}

/// Splits the edges in `boxes` (ring order) into x-monotone chains; false, leaving the job
/// to the other scans, when there are too many (see [`EDGES_PER_CHAIN`]).
fn collect_chains(pool: &Pool, boxes: &[EdgeBox], chains: &mut Vec<Chain>) -> bool {
    chains.clear();
    let limit = boxes.len() / EDGES_PER_CHAIN;
    // the direction of each edge: -1 towards smaller x, 1 towards larger, 0 vertical
    let direction = |e: &EdgeBox| {
        let (a, b) = (pool.p(e.from).x, pool.p(e.to).x);
        i8::from(b > a) - i8::from(b < a)
    };
    // the last edge's direction, and the current chain's (0 while it is one vertical edge)
    let (mut last, mut along) = (0, 0);
    for (i, e) in boxes.iter().enumerate() {
        let dir = direction(e);
        let extends = chains.last_mut().filter(|c| {
            let joins = if dir == 0 {
                last != 0
            } else {
                along == 0 || along == dir
            };
            // the same ring (edges follow each other)
            joins && boxes[i - 1].to == e.from && c.len < u32::MAX
        });
        match extends {
            Some(c) => {
                c.len += 1;
                if along == 0 && dir != 0 {
                    along = dir;
                    c.falling = dir < 0;
                }
                (c.x0, c.x1) = (least(c.x0, e.x0), greatest(c.x1, e.x1));
                (c.y0, c.y1) = (least(c.y0, e.y0), greatest(c.y1, e.y1));
            }
            None => {
                if chains.len() >= limit {
                    return false;
                }
                along = dir;
                chains.push(Chain {
                    start: i as u32,
                    len: 1,
                    falling: dir < 0,
                    x0: e.x0,
                    x1: e.x1,
                    y0: e.y0,
                    y1: e.y1,
                });
            }
        }
        last = dir;
    }
    true
}

/// Few chains: compare each chain's neighbouring edges, and each pair of chains whose
/// boxes overlap (found with a grid, see [`overlapping_pairs`]) edge by edge, walking both
/// from left to right (the edges of a chain, in x order, cover its x range one after
/// another, so the edges of one chain meeting an edge of the other form a window that only
/// moves right).
fn scan_chains(
    scratch: &mut ProofScratch,
    mut budget: usize,
    mut visit: impl FnMut(&EdgeBox, &EdgeBox) -> bool,
) -> Scan {
    let ProofScratch {
        boxes,
        chains,
        start,
        entries,
        ..
    } = scratch;
    // the k-th edge of a chain from the left
    let edge = |c: &Chain, k: u32| {
        let i = if c.falling {
            c.start + c.len - 1 - k
        } else {
            c.start + k
        };
        &boxes[i as usize]
    };
    for c in chains.iter() {
        if budget < c.len as usize {
            return Scan::OutOfBudget;
        }
        budget -= c.len as usize;
        for k in 1..c.len {
            let (e, f) = (edge(c, k - 1), edge(c, k));
            if visit(e, f) {
                return Scan::Stopped;
            }
            // the edges on either side of a vertical one share its x
            if f.x0 == f.x1 && k + 1 < c.len {
                let g = edge(c, k + 1);
                if g.y0 <= e.y1 && e.y0 <= g.y1 && visit(e, g) {
                    return Scan::Stopped;
                }
            }
        }
    }
    // the edges of `c` from the first one not ending left of x
    let reaching = |c: &Chain, x: f64| {
        let (mut lo, mut hi) = (0, c.len);
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if edge(c, mid).x1 < x {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        lo
    };
    overlapping_pairs(chains, start, entries, &mut budget, |a, b, budget| {
        let (a, b) = if a.x0 <= b.x0 { (a, b) } else { (b, a) };
        // a's edges from the first reaching b; b's edges from `first` on are those not
        // ending left of a's current edge
        let mut first = reaching(b, a.x0.max(b.x0));
        for k in reaching(a, b.x0)..a.len {
            let e = edge(a, k);
            if e.x0 > b.x1 {
                break;
            }
            while first < b.len && edge(b, first).x1 < e.x0 {
                first += 1;
            }
            let mut m = first;
            while m < b.len {
                let f = edge(b, m);
                if f.x0 > e.x1 {
                    break;
                }
                if *budget == 0 {
                    return Scan::OutOfBudget;
                }
                *budget -= 1;
                if f.y0 <= e.y1 && e.y0 <= f.y1 && visit(e, f) {
                    return Scan::Stopped;
                }
                m += 1;
            }
        }
        Scan::Done
    })
}

/// A handful of edges: compare every pair's boxes, which costs less than banding them.
fn scan_pairs(boxes: &[EdgeBox], mut visit: impl FnMut(&EdgeBox, &EdgeBox) -> bool) -> Scan {
    for (i, e) in boxes.iter().enumerate() {
        for f in &boxes[i + 1..] {
            if f.x0 <= e.x1 && e.x0 <= f.x1 && f.y0 <= e.y1 && e.y0 <= f.y1 && visit(e, f) {
                return Scan::Stopped;
            }
        }
    }
    Scan::Done
}

/// Columns (and rows) of [`scan_banded`].
const BANDS: usize = 32;

/// Words of [`scan_banded`]'s edge sets: one bit per edge, up to [`SMALL`].
const WORDS: usize = SMALL / 64;

/// A few hundred edges: the boxes' bounding box is cut into [`BANDS`] columns and as many
/// rows, each edge's box spans a run of each, and each edge is compared with the later
/// edges whose runs overlap its own in both, read off bit sets (the edges starting in a
/// column up to its last, and ending in one from its first on). The bands are monotone in
/// the coordinates, so every pair of overlapping boxes is among those compared. (Sorting
/// the boxes and comparing each with those starting before it ends cost about twice as
/// much on earcut's fixtures of this size: the sort, and a branch per pair that the
/// processor cannot predict.)
fn scan_banded(
    boxes: &[EdgeBox],
    mut budget: usize,
    mut visit: impl FnMut(&EdgeBox, &EdgeBox) -> bool,
) -> Scan {
    let Some(first) = boxes.first() else {
        return Scan::Done;
    };
    let words = boxes.len().div_ceil(64).min(WORDS);
    let (mut x0, mut x1, mut y0, mut y1) = (first.x0, first.x1, first.y0, first.y1);
    for b in boxes {
        (x0, y0) = (least(x0, b.x0), least(y0, b.y0));
        (x1, y1) = (greatest(x1, b.x1), greatest(y1, b.y1));
    }
    let (sx, sy) = (scale(BANDS, x1 - x0), scale(BANDS, y1 - y0));
    let last = BANDS - 1;
    // per axis, by band k: the edges starting in a band up to k, and those ending in one
    // from k on (first each band's own, then summed)
    let mut starts = [[[0u64; WORDS]; BANDS]; 2];
    let mut ends = [[[0u64; WORDS]; BANDS]; 2];
    let mut runs = [[0u8; 4]; SMALL];
    for (i, b) in boxes.iter().take(SMALL).enumerate() {
        let run = [
            slot((b.x0 - x0) * sx, last),
            slot((b.x1 - x0) * sx, last),
            slot((b.y0 - y0) * sy, last),
            slot((b.y1 - y0) * sy, last),
        ];
        runs[i] = run.map(|c| c as u8);
        let (w, bit) = (i / 64, 1u64 << (i % 64));
        starts[0][run[0]][w] |= bit;
        ends[0][run[1]][w] |= bit;
        starts[1][run[2]][w] |= bit;
        ends[1][run[3]][w] |= bit;
    }
    for axis in 0..2 {
        for k in 1..BANDS {
            for w in 0..words {
                let below = starts[axis][k - 1][w];
                starts[axis][k][w] |= below;
                let above = ends[axis][last - k + 1][w];
                ends[axis][last - k][w] |= above;
            }
        }
    }
    for (i, e) in boxes.iter().take(SMALL).enumerate() {
        let [c0, c1, r0, r1] = runs[i].map(usize::from);
        for w in i / 64..words {
            let mut bits = starts[0][c1][w] & ends[0][c0][w] & starts[1][r1][w] & ends[1][r0][w];
            if w == i / 64 {
                // the later edges only
                bits &= !1u64 << (i % 64);
            }
            while bits != 0 {
                let j = w * 64 + bits.trailing_zeros() as usize;
                bits &= bits - 1;
                if budget == 0 {
                    return Scan::OutOfBudget;
                }
                budget -= 1;
                let f = &boxes[j];
                let overlap = f.x0 <= e.x1 && e.x0 <= f.x1 && f.y0 <= e.y1 && e.y0 <= f.y1;
                if overlap && visit(e, f) {
                    return Scan::Stopped;
                }
            }
        }
    }
    Scan::Done
}

/// Many edges: compare the pairs whose boxes overlap, found with a grid (see
/// [`overlapping_pairs`]).
fn scan_grid(
    scratch: &mut ProofScratch,
    mut budget: usize,
    mut visit: impl FnMut(&EdgeBox, &EdgeBox) -> bool,
) -> Scan {
    let ProofScratch {
        boxes,
        start,
        entries,
        ..
    } = scratch;
    overlapping_pairs(boxes, start, entries, &mut budget, |e, f, _| {
        if visit(e, f) {
            Scan::Stopped
        } else {
            Scan::Done
        }
    })
}

/// An axis-aligned box, as [`overlapping_pairs`] takes them.
trait Bounds {
    /// Left, right, bottom, top.
    fn bounds(&self) -> (f64, f64, f64, f64);
}

impl Bounds for EdgeBox {
    #[inline]
    fn bounds(&self) -> (f64, f64, f64, f64) {
        (self.x0, self.x1, self.y0, self.y1)
    }
}

impl Bounds for Chain {
    #[inline]
    fn bounds(&self) -> (f64, f64, f64, f64) {
        (self.x0, self.x1, self.y0, self.y1)
    }
}

/// Calls `visit` once for each pair of `items` whose (closed) boxes overlap, until it
/// returns anything but [`Scan::Done`], which is then returned. Each item is listed in the
/// cells of a uniform grid its box covers (as many cells as items), and the items sharing
/// a cell are compared: two overlapping boxes share the cell of the lower left corner of
/// their overlap (cells are monotone in x and y), and only that cell visits them. Listing a
/// cell and comparing a pair each cost one unit of `budget`, which `visit` may spend too;
/// when it runs out the scan gives up. `start` and `entries` are scratch.
fn overlapping_pairs<B: Bounds>(
    items: &[B],
    start: &mut Vec<u32>,
    entries: &mut Vec<u32>,
    budget: &mut usize,
    mut visit: impl FnMut(&B, &B, &mut usize) -> Scan,
) -> Scan {
    let (mut x0, mut y0, mut x1, mut y1) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
    for b in items {
        let (l, r, d, u) = b.bounds();
        (x0, y0) = (least(x0, l), least(y0, d));
        (x1, y1) = (greatest(x1, r), greatest(y1, u));
    }
    let (w, h) = (x1 - x0, y1 - y0);
    // (one item per cell: with two, clustered coastlines crowd cells with pairs to compare,
    // and cost earcut's water4 and issue35 5% more; touching-holes6 runs out of budget)
    let (nx, ny) = shape(items.len().max(1), w, h);
    let (sx, sy) = (scale(nx, w), scale(ny, h));
    // `as` saturates: NaN and negative become 0
    let column = |x: f64| crate::structures::slot((x - x0) * sx, nx - 1);
    let row = |y: f64| crate::structures::slot((y - y0) * sy, ny - 1);
    let cells_of = |b: &B| {
        let (l, r, d, u) = b.bounds();
        (column(l), column(r), row(d), row(u))
    };
    // counting sort of (cell, item) entries; give up when long items would list too many
    start.clear();
    start.resize(nx * ny + 2, 0);
    for b in items {
        let (c0, c1, r0, r1) = cells_of(b);
        let listed = (c1 - c0 + 1) * (r1 - r0 + 1);
        if listed > *budget {
            return Scan::OutOfBudget;
        }
        *budget -= listed;
        for r in r0..=r1 {
            for c in c0..=c1 {
                start[r * nx + c + 2] += 1;
            }
        }
    }
    for c in 2..start.len() {
        start[c] += start[c - 1];
    }
    entries.clear();
    entries.resize(start[nx * ny + 1] as usize, 0);
    for (i, b) in items.iter().enumerate() {
        let (c0, c1, r0, r1) = cells_of(b);
        for r in r0..=r1 {
            for c in c0..=c1 {
                let at = &mut start[r * nx + c + 1];
                entries[*at as usize] = i as u32;
                *at += 1;
            }
        }
    }
    // cell c now holds entries[start[c]..start[c + 1]]
    for c in 0..nx * ny {
        let cell = &entries[start[c] as usize..start[c + 1] as usize];
        for (k, &i) in cell.iter().enumerate() {
            let e = &items[i as usize];
            let (el, er, ed, eu) = e.bounds();
            for &j in &cell[k + 1..] {
                if *budget == 0 {
                    return Scan::OutOfBudget;
                }
                *budget -= 1;
                let f = &items[j as usize];
                let (fl, fr, fd, fu) = f.bounds();
                if fl > er || el > fr || fd > eu || ed > fu {
                    continue;
                }
                // the overlap's lower left corner lies in this cell only
                let corner = row(ed.max(fd)) * nx + column(el.max(fl));
                if corner != c {
                    continue;
                }
                match visit(e, f, budget) {
                    Scan::Done => {}
                    other => return other,
                }
            }
        }
    }
    Scan::Done
}

/// Whether edges `e` and `f`, whose boxes overlap, meet other than adjacent edges at their
/// shared vertex only (exact). With `turns_proper`, no turn is collinear (see
/// [`edges_meet_at_vertices`]).
#[inline]
fn meet(pool: &Pool, e: &EdgeBox, f: &EdgeBox, turns_proper: bool) -> bool {
    if e.to == f.from && f.to == e.from {
        return true; // a ring of two: the edges lie on each other
    }
    if turns_proper && (e.to == f.from || f.to == e.from) {
        return false;
    }
    let (a, b, c, d) = (pool.p(e.from), pool.p(e.to), pool.p(f.from), pool.p(f.to));
    if e.to == f.from {
        // a → b → d: they share b and nothing else unless they are collinear
        return orient2d(a, b, d) == Orientation::Collinear;
    }
    if f.to == e.from {
        return orient2d(c, d, b) == Orientation::Collinear;
    }
    boxed_segments_meet(a, b, c, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A seeded xorshift generator: tests need the same numbers every run.
    fn xorshift(mut seed: u64) -> impl FnMut() -> u64 {
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        }
    }

    /// Builds a pool from rings of (x, y) and returns it with one start node per ring.
    fn build(rings: &[&[(f64, f64)]]) -> (Pool, Vec<NodeId>) {
        Pool::from_rings(rings)
    }

    /// A regular `n`-gon of radius `r` centred at (`dx`, 0), counter-clockwise.
    fn circle(n: u32, r: f64, dx: f64) -> Vec<(f64, f64)> {
        (0..n)
            .map(|k| {
                let t = f64::from(k) * core::f64::consts::TAU / f64::from(n);
                (dx + r * t.cos(), r * t.sin())
            })
            .collect()
    }

    /// Whether `edges_meet_at_vertices` proves the edges apart, without assumptions;
    /// where no turn is collinear, also with `turns_proper`, which must agree.
    fn apart(rings: &[&[(f64, f64)]]) -> bool {
        let (pool, starts) = build(rings);
        let mut nodes = Vec::new();
        let mut run = |turns_proper| {
            let scratch = &mut ProofScratch::default();
            let (mut touches, mut shared) = (Vec::new(), Vec::new());
            let contact = edges_meet_at_vertices(
                &pool,
                &starts,
                scratch,
                &mut nodes,
                turns_proper,
                &mut touches,
                &mut shared,
            );
            contact == Contact::Apart
        };
        let ok = run(false);
        let proper = (0..pool.len() as u32).map(NodeId).all(|n| {
            orient2d(pool.p(pool.prev(n)), pool.p(n), pool.p(pool.next(n)))
                != Orientation::Collinear
        });
        if proper {
            let fast = run(true);
            assert_eq!(fast, ok, "turns_proper changed the answer");
        }
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
    fn many_edges_take_the_grid() {
        // a 64-gon with a 64-gon hole, and the same hole moved onto the outer ring
        assert!(apart(&[&circle(64, 10.0, 0.0), &circle(64, 5.0, 0.0)]));
        assert!(!apart(&[&circle(64, 10.0, 0.0), &circle(64, 5.0, 5.0)]));
    }

    /// Runs `mark_crossed` and checks its flags against every pair compared directly: the
    /// same flags when it finished, a subset when it gave up. Returns whether it finished.
    fn marks_like_brute_force(rings: &[&[(f64, f64)]]) -> bool {
        let (mut pool, starts) = build(rings);
        let done = mark_crossed(&mut pool, &starts, &mut ProofScratch::default());
        let edges: Vec<NodeId> = (0..pool.len() as u32).map(NodeId).collect();
        for &e in &edges {
            let (a, b) = (pool.p(e), pool.p(pool.next(e)));
            let crossed = edges.iter().any(|&f| {
                let (c, d) = (pool.p(f), pool.p(pool.next(f)));
                crate::geom::crosses(a, b, c, d)
            });
            let flagged = pool.get(e).crossed;
            assert!(crossed || !flagged, "edge {e:?} flagged without a crossing");
            assert!(!done || crossed == flagged, "edge {e:?}: crossed {crossed}");
        }
        done
    }

    #[test]
    fn crossing_edges_are_flagged() {
        assert!(marks_like_brute_force(&[&[
            (0., 0.),
            (10., 10.),
            (10., 0.),
            (0., 10.)
        ]]));
        assert!(marks_like_brute_force(&[
            SQUARE,
            &[(5., 5.), (15., 5.), (15., 6.)]
        ]));
        // touching is not crossing
        assert!(marks_like_brute_force(&[
            SQUARE,
            &[(0., 5.), (3., 7.), (3., 3.)]
        ]));
        // seeded pseudo-random rings, few and many edges (the banded scan and the grid)
        let mut random = xorshift(0x2545_f491_4f6c_dd1d);
        let mut next = || (random() >> 40) as f64 / f64::from(1u32 << 24) * 100.0;
        // two 400-gons crossing each other: the grid finishes
        assert!(marks_like_brute_force(&[
            &circle(400, 10.0, 0.0),
            &circle(400, 5.0, 8.0)
        ]));
        for len in [6, 40, 300, 700] {
            let ring: Vec<(f64, f64)> = (0..len).map(|_| (next(), next() * 0.05)).collect();
            marks_like_brute_force(&[&ring]);
        }
    }

    #[test]
    fn a_star_of_long_crossing_edges_gives_up_without_false_flags() {
        // {601/300}: every edge crosses almost every other one, far beyond the budget
        let n = 601;
        let ring: Vec<(f64, f64)> = (0..n)
            .map(|k| {
                let t = f64::from(k * 300 % n) * core::f64::consts::TAU / f64::from(n);
                (t.cos(), t.sin())
            })
            .collect();
        assert!(!marks_like_brute_force(&[&ring]));
    }

    /// Two edges by their start nodes, the lower first.
    type Pair = (u32, u32);

    /// Every pair of edges whose boxes overlap, by brute force, as sorted index pairs of
    /// nodes; the same as `scan` visits them (each pair once or more); and whether it took
    /// the chain scan.
    fn overlapping_pairs(rings: &[Vec<(f64, f64)>]) -> (Vec<Pair>, Vec<Pair>, bool) {
        let refs: Vec<&[(f64, f64)]> = rings.iter().map(Vec::as_slice).collect();
        let (pool, starts) = build(&refs);
        let mut scratch = ProofScratch::default();
        collect_boxes(&pool, &starts, &mut scratch.boxes, None);
        let boxes = scratch.boxes.clone();
        let chained = boxes.len() > SMALL && collect_chains(&pool, &boxes, &mut scratch.chains);
        let overlap =
            |e: &EdgeBox, f: &EdgeBox| f.x0 <= e.x1 && e.x0 <= f.x1 && f.y0 <= e.y1 && e.y0 <= f.y1;
        let pair = |e: &EdgeBox, f: &EdgeBox| (e.from.0.min(f.from.0), e.from.0.max(f.from.0));
        let mut expected = Vec::new();
        for (i, e) in boxes.iter().enumerate() {
            for f in &boxes[i + 1..] {
                if overlap(e, f) {
                    expected.push(pair(e, f));
                }
            }
        }
        let mut seen = Vec::new();
        let done = scan(&pool, &mut scratch, 1 << 20, |e, f| {
            assert!(overlap(e, f), "visited a pair whose boxes do not overlap");
            seen.push(pair(e, f));
            false
        });
        assert_eq!(done, Scan::Done);
        expected.sort_unstable();
        seen.sort_unstable();
        seen.dedup();
        (expected, seen, chained)
    }

    #[test]
    fn every_scan_visits_every_overlapping_pair() {
        let mut random = xorshift(0x9e37_79b9_7f4a_7c15);
        let mut next = move || (random() >> 11) as f64 / (1u64 << 53) as f64;
        // wobbly circles (few long chains: the chain scan), with wobbly holes, and random
        // zigzags (a chain per edge: the banded scan and the grid); grid-aligned
        // coordinates give vertical edges and boxes touching at their sides
        let mut chain_scans = 0;
        for round in 0..60 {
            let mut rings = Vec::new();
            let count = 1 + round % 4;
            for r in 0..count {
                let n = 8 + (next() * 600.0) as usize;
                let waves = 1.0 + (next() * 6.0).floor();
                let radius = if r == 0 { 10.0 } else { 1.0 + next() };
                let (cx, cy) = if r == 0 {
                    (0.0, 0.0)
                } else {
                    (next() * 8.0 - 4.0, next() * 8.0 - 4.0)
                };
                let snap = |v: f64| {
                    if round % 3 == 0 {
                        (v * 4.0).round() / 4.0
                    } else {
                        v
                    }
                };
                // every other round mirrored across the diagonal: each shape along x and
                // along y
                let mirror = |(x, y): (f64, f64)| if round % 2 == 0 { (x, y) } else { (y, x) };
                let ring: Vec<(f64, f64)> = (0..n)
                    .map(|k| {
                        let t = k as f64 * core::f64::consts::TAU / n as f64;
                        let rho = radius * (1.0 + 0.3 * (waves * t).sin());
                        mirror((snap(cx + rho * t.cos()), snap(cy + rho * t.sin())))
                    })
                    .collect();
                rings.push(ring);
            }
            if round % 5 == 4 {
                let n = 10 + (next() * 600.0) as usize;
                rings.push(
                    (0..n)
                        .map(|_| (next() * 20.0 - 10.0, next() * 20.0 - 10.0))
                        .collect(),
                );
            }
            let (expected, seen, chained) = overlapping_pairs(&rings);
            assert_eq!(seen, expected, "round {round}");
            chain_scans += usize::from(chained);
        }
        assert!((20..55).contains(&chain_scans), "{chain_scans} chain scans");
    }

    #[test]
    fn near_misses_are_decided_exactly() {
        // the hole's corner sits one ulp right of the outer ring's left edge
        let x = f64::from_bits(0.0f64.to_bits() + 1);
        assert!(apart(&[SQUARE, &[(x, 5.), (3., 7.), (3., 3.)]]));
        assert!(!apart(&[SQUARE, &[(0., 5.), (3., 7.), (3., 3.)]]));
    }

    /// What [`edges_meet_at_vertices`] proves about `rings`, asserted to be what the sweep
    /// finds: no crossing, the same vertices inside edges and the same nodes at shared
    /// positions, unless not proved (which it must be where the sweep finds a crossing).
    fn agrees_with_sweep(rings: &[Vec<(f64, f64)>]) -> Contact {
        use crate::crossings::sweep::{self, SweepScratch};
        let refs: Vec<&[(f64, f64)]> = rings.iter().map(Vec::as_slice).collect();
        let (pool, starts) = build(&refs);
        let (mut touches, mut shared, mut nodes) = (Vec::new(), Vec::new(), Vec::new());
        let contact = edges_meet_at_vertices(
            &pool,
            &starts,
            &mut ProofScratch::default(),
            &mut nodes,
            false,
            &mut touches,
            &mut shared,
        );
        let mut scratch = SweepScratch::default();
        let (mut swept, mut crossings) = (Vec::new(), Vec::new());
        sweep::sweep(
            &pool,
            &starts,
            &mut scratch,
            false,
            &mut swept,
            &mut crossings,
        );
        swept.sort_unstable_by_key(|t| (t.edge, t.vertex));
        swept.dedup();
        // the sweep's nodes at shared positions, grouped as `shared` is
        let order = &scratch.order;
        let mut groups: Vec<NodeId> = (0..order.len())
            .filter(|&i| {
                let p = pool.p(order[i]);
                (i > 0 && pool.p(order[i - 1]) == p)
                    || (i + 1 < order.len() && pool.p(order[i + 1]) == p)
            })
            .map(|i| order[i])
            .collect();
        groups.sort_unstable_by(|&a, &b| cmp_xy(pool.p(a), pool.p(b)).then(a.cmp(&b)));
        let case = format!("{rings:?}");
        match contact {
            Contact::NotProved => {}
            Contact::Crossed(a, b) => {
                // a pair that does cross, where the sweep finds crossings too
                let edge = |n: NodeId| (pool.p(n), pool.p(pool.next(n)));
                let ((p, q), (r, t)) = (edge(a), edge(b));
                assert!(crate::geom::crosses(p, q, r, t), "{case}");
                assert!(!crossings.is_empty(), "{case}");
            }
            Contact::Apart => {
                assert!(crossings.is_empty() && swept.is_empty(), "{case}");
                assert!(groups.is_empty(), "{case}");
            }
            Contact::AtVertices => {
                assert!(crossings.is_empty(), "{case}");
                assert_eq!(touches, swept, "{case}");
                assert_eq!(shared, groups, "{case}");
            }
        }
        if !crossings.is_empty() {
            assert!(
                matches!(contact, Contact::NotProved | Contact::Crossed(..)),
                "{case}"
            );
        }
        contact
    }

    /// Random rings on a 6 × 6 grid (shared vertices, T-junctions, collinear overlaps
    /// and crossings everywhere), with and without collinear turns: wherever the proof
    /// says the edges meet only at vertices, it lists what the sweep finds; where the
    /// sweep finds a crossing, it proves nothing, and a pair it names as crossed does
    /// cross.
    #[test]
    fn contacts_at_vertices_are_what_the_sweep_finds() {
        let mut next = xorshift(0x5eed_cafe_f00d_d00d);
        let (mut apart, mut at_vertices, mut not_proved, mut crossed) = (0, 0, 0, 0);
        for _ in 0..40_000 {
            let mut rings: Vec<Vec<(f64, f64)>> = Vec::new();
            for _ in 0..1 + next() % 3 {
                let mut ring: Vec<(f64, f64)> = Vec::new();
                for _ in 0..3 + next() % 3 {
                    let p = ((next() % 6) as f64, (next() % 6) as f64);
                    if ring.last() != Some(&p) {
                        ring.push(p);
                    }
                }
                while ring.len() > 1 && ring.first() == ring.last() {
                    ring.pop();
                }
                if ring.len() >= 3 {
                    rings.push(ring);
                }
            }
            match agrees_with_sweep(&rings) {
                Contact::NotProved => not_proved += 1,
                Contact::Apart => apart += 1,
                Contact::AtVertices => at_vertices += 1,
                Contact::Crossed(..) => crossed += 1,
            }
        }
        eprintln!(
            "{apart} apart, {at_vertices} at vertices, {crossed} crossed, {not_proved} not proved"
        );
        assert!(apart > 500 && at_vertices > 500 && crossed > 500 && not_proved > 500);
    }

    #[test]
    fn edges_with_an_end_in_common_along_one_line_list_every_contact() {
        // the outer square, and a ring with an edge from one of its corners along its
        // bottom edge (to the other corner, or short of it, either way), or off it
        let square = vec![(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)];
        let cases = [
            vec![(0.0, 0.0), (4.0, 0.0), (2.0, 2.0)],
            vec![(4.0, 0.0), (0.0, 0.0), (2.0, 2.0)],
            vec![(0.0, 0.0), (2.0, 0.0), (2.0, 2.0)],
            vec![(4.0, 0.0), (2.0, 2.0), (2.0, 0.0)],
            vec![(0.0, 0.0), (2.0, 1.0), (1.0, 2.0)],
        ];
        for ring in cases {
            for rings in [
                vec![square.clone(), ring.clone()],
                vec![ring, square.clone()],
            ] {
                assert_eq!(agrees_with_sweep(&rings), Contact::AtVertices, "{rings:?}");
            }
        }
    }
}
