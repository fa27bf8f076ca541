//! Stage `resolve` (fill rules only): crossing and overlapping rings become valid rings
//! bounding exactly the region a [`FillRule`] selects, for the usual pipeline to
//! triangulate.
//!
//! 1. **Crossings.** Groups of edges between the same two points whose directions
//!    cancel (a border two rings share) are dropped first: they change no winding number
//!    ([`drop_cancelling_edges`]). Every pair of the other edges crossing at a point
//!    interior to both is found (a bucket grid proposes pairs, [`crosses`] decides) and
//!    the crossing point is rounded to the coordinate type's grid, exactly
//!    ([`SnapGrid::crossing`]).
//! 2. **Snap rounding** (Hobby; Guibas and Marimont), only when some edges cross. The
//!    *hot pixels* are the pixels (the points rounding to a grid point) of the input's
//!    vertices and of the rounded crossings. Each edge becomes the polyline through the
//!    centres of every hot pixel it meets ([`SnapGrid::meets_pixel`]), in order along the
//!    edge. On a grid of equal pixels the rounded arrangement is topologically
//!    consistent with the exact one (Guibas and Marimont): a fragment stays within a
//!    pixel's reach of its edge, where no hot centre lies that the edge's own path does
//!    not visit. A floating-point grid's pixels differ in size (they double from one
//!    binade to the next, and differ between the axes), so a fragment between two tall
//!    pixels can pass on the wrong side of a short one's centre, and cross an edge from
//!    it (found by the `fill_rules` fuzz target). Each point still moves by less than
//!    its pixel's diagonal. Without crossings nothing is rounded and no vertex is added.
//!
//!    **2b. Again where fragments cross.** After splitting (step 3), the winding sweep
//!    proves the fragments planar (`verify`, as Shamos and Hoey's sweep does). Where it
//!    fails, fragments cross properly (splitting left no other way to meet): their
//!    crossings are found, rounded and made hot, and every fragment is snapped as the
//!    edges were ([`snap_again`]). It ends. Each edge's path is monotone in x and in y
//!    (the pixels a segment meets form a staircase, and a fragment meets no pixel whose
//!    centre lies outside the box of its ends), so it visits a hot point once, and a
//!    fragment meets the pixel of no other point of its path. A crossing x of fragments
//!    f and g rounds to a hot h whose pixel both meet, and h ends at most one of them: the
//!    path of each edge through the other gains h. So the (edge, hot point) incidences
//!    grow every round, bounded by the edges times the grid points in the input's box
//!    (crossings inside it round into it). Each round moves a fragment by less than a
//!    pixel's diagonal; every case found needed one round more. After [`SNAPS`] snaps
//!    the stage returns `Error::Internal` instead (a guard against a flaw in this
//!    argument, never reached).
//! 3. **Splitting** at vertices lying exactly on a fragment (a vertex on another ring's
//!    edge, collinear overlaps, and the rare fragment that snap rounding drew across a
//!    hot centre): pure subdivision, no point moves. Fragments between the same two
//!    vertices are then merged, their directions summed into a *net count*; net zero
//!    edges separate nothing and are dropped.
//! 4. **Winding** ([`winding`]): a sweep over the now planar edges gives each edge the
//!    winding numbers on its two sides; an edge is on the region's boundary when the
//!    rule accepts one side and not the other, and is directed with the region on its
//!    left.
//! 5. **Rings** ([`trace`]): the boundary edges are linked at each vertex as the region's
//!    face walk does (each arriving edge leaves by the next boundary edge clockwise) and
//!    cut into simple rings where a walk revisits a vertex. Their even–odd region is the
//!    rule's region; they touch only at vertices and never cross.
//!
//! The rings' vertices are the input's (the lowest index at each position) and the added
//! crossings; `map` gives the output index of each.

mod cells;
mod trace;
mod uncross;
mod winding;

pub(crate) use uncross::{rewind, uncross};

use cells::Cells;

use crate::geom::{crosses, in_range, on_segment, Point, SnapGrid};
use crate::report::Added;
use crate::structures::positions;
use crate::{Error, FillRule};

/// An edge (of the input, or a fragment of one): its ends as hot points, its net count
/// from `a` to `b` (how many times the rings run that way, less the other way), and the
/// input edge it lies on, named by its start vertex (the short way, which reports its
/// crossings before it splits, leaves that [`u32::MAX`] on its fragments).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Edge {
    from: u32,
    a: u32,
    b: u32,
    count: i32,
}

/// The stage's buffers and its result.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// Distinct positions: the input's (sorted), then the added crossings.
    pub hot: Vec<[f64; 2]>,
    /// The output vertex index of each hot point.
    pub hot_out: Vec<u32>,
    /// Each input vertex's hot point.
    pub vertex_hot: Vec<u32>,
    edges: Vec<Edge>,
    /// The input's vertices by position ([`ordered_bits`] of x and y), then index.
    keyed: Vec<([u64; 2], u32)>,
    /// The edges by their ends (the lower hot point above the higher), then index.
    by_ends: Vec<(u64, u32)>,
    /// Per edge: cancelled by others between the same two points.
    cancelled: Vec<bool>,
    /// Per input position: how many input vertices lie there (up to 255).
    shared_at: Vec<u8>,
    cells: Cells,
    crossings: Vec<([f64; 2], u32, u32)>,
    /// The pairs of edges found crossing (each once after sorting).
    pairs: Vec<(u32, u32)>,
    on_edge: Vec<u32>,
    /// The fragments of the edges (after merging: from the lower hot point to the
    /// higher, no two between the same points, no net count zero).
    fragments: Vec<Edge>,
    /// Twice the edges' mean extent (the longer side of an edge's box): the widest cell
    /// of the grids.
    typical: f64,
    /// The fragments split at vertices, before they are copied back.
    split: Vec<Edge>,
    /// Every hot point by position, where snap rounding runs again.
    table: Vec<u32>,
    /// How many times snap rounding ran on the last input (0 where no edges cross).
    snaps: u32,
    winding: winding::Scratch,
    trace: trace::Scratch,
    uncross: uncross::Scratch,
    /// The result: rings of positions, their starts, and each position's output index;
    /// and the same rings as distinct points (`hot`, whose output indices are `hot_out`).
    pub rings: Vec<[f64; 2]>,
    pub ring_ids: Vec<u32>,
    pub ring_starts: Vec<usize>,
    pub map: Vec<u32>,
}

/// Resolves `vertices` (finite, widened to `f64`) and `ring_starts` (checked by `load`)
/// into rings bounding `rule`'s region, rounding crossings to `grid`; the added vertices
/// go to `added`. `uncrossed`: the caller has proved that no two edges cross (strict
/// mode's check passed), so the crossing search is skipped.
pub(crate) fn resolve(
    s: &mut Scratch,
    vertices: &[[f64; 2]],
    ring_starts: &[usize],
    rule: FillRule,
    grid: SnapGrid,
    uncrossed: bool,
    added: &mut Vec<Added>,
) -> Result<(), Error> {
    s.rings.clear();
    s.ring_ids.clear();
    s.ring_starts.clear();
    s.map.clear();
    if let Some(v) = vertices
        .iter()
        .position(|p| !in_range(p[0]) || !in_range(p[1]))
    {
        return Err(Error::CoordinateRange { vertex: v });
    }
    distinct_positions(s, vertices);
    collect_edges(s, vertices, ring_starts);
    drop_cancelling_edges(s);
    s.typical = typical_extent(&s.edges, &s.hot);
    let (lo, hi) = bounds(&s.hot);
    let reach = reach(grid, lo, hi);
    if uncrossed {
        s.crossings.clear();
    } else {
        find_crossings(s, lo, hi, grid, reach, None, [usize::MAX; 3]);
    }
    add_crossings(s, vertices.len(), added, false)?;
    s.snaps = 0;
    if s.crossings.is_empty() {
        s.fragments.clear();
        s.fragments.extend_from_slice(&s.edges);
    } else {
        snap(s, lo, hi, grid, reach);
    }
    loop {
        split_at_vertices(s, lo, hi, reach);
        merge_fragments(&mut s.fragments);
        // (planar without crossings: the edges meet only at vertices, now split there)
        let verify = !s.crossings.is_empty();
        if winding::boundary(&mut s.winding, &s.hot, &s.fragments, rule, verify) {
            break;
        }
        snap_again(s, lo, hi, grid, reach, vertices.len(), added)?;
    }
    trace::rings(&mut s.trace, &s.hot, &s.winding.boundary)?;
    take_traced(s);
    Ok(())
}

/// The traced rings as the result: their positions, points, starts and output indices.
fn take_traced(s: &mut Scratch) {
    for ring in s.trace.rings() {
        s.ring_starts.push(s.rings.len());
        for &h in ring {
            s.rings.push(s.hot[h as usize]);
            s.ring_ids.push(h);
            s.map.push(s.hot_out[h as usize]);
        }
    }
}

/// The input's distinct positions, sorted, each with the lowest input index there.
fn distinct_positions(s: &mut Scratch, vertices: &[[f64; 2]]) {
    // sorted by integer keys in the order of the coordinates (−0.0 read as +0.0), then
    // by index: fewer instructions than comparing the coordinates through the indices
    s.keyed.clear();
    s.keyed.extend((vertices.iter().enumerate()).map(|(i, p)| {
        let key = |x: f64| ordered_bits(x + 0.0);
        ([key(p[0]), key(p[1])], i as u32)
    }));
    s.keyed.sort_unstable();
    s.hot.clear();
    s.hot_out.clear();
    s.vertex_hot.clear();
    s.vertex_hot.resize(vertices.len(), 0);
    for &(_, i) in &s.keyed {
        let p = vertices[i as usize];
        let p = [p[0] + 0.0, p[1] + 0.0];
        if s.hot.last() != Some(&p) {
            s.hot.push(p);
            s.hot_out.push(i);
        }
        s.vertex_hot[i as usize] = (s.hot.len() - 1) as u32;
    }
}

/// The bits of `x` (not NaN, not −0.0) as an integer of the same order: a positive
/// number's bits with the sign bit set, a negative number's all flipped.
fn ordered_bits(x: f64) -> u64 {
    let bits = x.to_bits();
    if bits >> 63 == 0 {
        bits | 1 << 63
    } else {
        !bits
    }
}

/// The number whose [`ordered_bits`] are `k`.
fn unordered_bits(k: u64) -> f64 {
    f64::from_bits(if k >> 63 == 1 { k & !(1 << 63) } else { !k })
}

/// Every ring's edges between distinct positions.
fn collect_edges(s: &mut Scratch, vertices: &[[f64; 2]], ring_starts: &[usize]) {
    s.edges.clear();
    let n = vertices.len();
    for (r, &start) in ring_starts.iter().enumerate() {
        // (`load` accepts any ring starts when there are no vertices)
        let end = ring_starts.get(r + 1).copied().unwrap_or(n).min(n);
        for i in start.min(end)..end {
            let j = if i + 1 < end { i + 1 } else { start };
            let (a, b) = (s.vertex_hot[i], s.vertex_hot[j]);
            if a != b {
                s.edges.push(Edge {
                    from: i as u32,
                    a,
                    b,
                    count: 1,
                });
            }
        }
    }
}

/// Drops every group of edges between the same two points whose directions cancel (a
/// border two rings share, run once each way): they change no winding number. Snap
/// rounding the other edges alone is snap rounding of a set of segments with every input
/// position still hot, so the argument holds as it is; only crossings of the dropped edges
/// are not rounded and added, which moves nothing. Groups that do not cancel stay whole.
fn drop_cancelling_edges(s: &mut Scratch) {
    // (only edges with both ends where several input vertices lie can have company: where
    // few positions are shared, few edges are sorted)
    s.shared_at.clear();
    s.shared_at.resize(s.hot.len(), 0);
    for &h in &s.vertex_hot {
        let count = &mut s.shared_at[h as usize];
        *count = count.saturating_add(1);
    }
    let shared = |h: u32| s.shared_at[h as usize] > 1;
    s.by_ends.clear();
    s.by_ends.extend(
        (s.edges.iter().enumerate())
            .filter(|(_, e)| shared(e.a) && shared(e.b))
            .map(|(i, e)| {
                let (lo, hi) = (e.a.min(e.b), e.a.max(e.b));
                (u64::from(lo) << 32 | u64::from(hi), i as u32)
            }),
    );
    if s.by_ends.len() < 2 {
        return;
    }
    s.by_ends.sort_unstable();
    s.cancelled.clear();
    s.cancelled.resize(s.edges.len(), false);
    let mut any = false;
    for group in s.by_ends.chunk_by(|x, y| x.0 == y.0) {
        if group.len() < 2 {
            continue;
        }
        let net: i64 = (group.iter())
            .map(|&(_, i)| {
                let e = s.edges[i as usize];
                if e.a < e.b {
                    1
                } else {
                    -1
                }
            })
            .sum();
        if net == 0 {
            any = true;
            for &(_, i) in group {
                s.cancelled[i as usize] = true;
            }
        }
    }
    if any {
        let mut k = 0;
        s.edges.retain(|_| {
            k += 1;
            !s.cancelled[k - 1]
        });
    }
}

/// Twice the mean extent of `edges` (the longer side of each one's box); infinite when
/// there are none.
fn typical_extent(edges: &[Edge], hot: &[[f64; 2]]) -> f64 {
    if edges.is_empty() {
        return f64::INFINITY;
    }
    let sum: f64 = (edges.iter())
        .map(|e| {
            let (a, b) = (hot[e.a as usize], hot[e.b as usize]);
            (a[0] - b[0]).abs().max((a[1] - b[1]).abs())
        })
        .sum();
    2.0 * sum / edges.len() as f64
}

fn bounds(points: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    if lo[0] > hi[0] {
        return ([0.0; 2], [0.0; 2]);
    }
    (lo, hi)
}

/// A bound on the half-width of every pixel of `grid` within the box `lo..=hi` (that of
/// its largest coordinate).
fn reach(grid: SnapGrid, lo: [f64; 2], hi: [f64; 2]) -> f64 {
    grid.half_width(
        lo[0]
            .abs()
            .max(lo[1].abs())
            .max(hi[0].abs())
            .max(hi[1].abs()),
    )
}

fn point(p: [f64; 2]) -> Point {
    Point::new(p[0], p[1])
}

/// Every pair of edges crossing inside both, with the crossing rounded to the grid. With
/// `contacts`, also where other pairs of edges (no neighbours) meet at a vertex: each
/// vertex lying inside another edge, as (vertex, that edge's start), and each two
/// vertices at one position, each as (vertex, `u32::MAX`). Stops, returning false, once
/// more than `most[0]` crossing pairs or `most[1]` contacts are found (counted in every
/// cell two edges share, so up to a few times each), or more than `most[2]` distinct
/// crossing pairs.
fn find_crossings(
    s: &mut Scratch,
    lo: [f64; 2],
    hi: [f64; 2],
    grid: SnapGrid,
    reach: f64,
    mut contacts: Option<&mut Vec<(u32, u32)>>,
    most: [usize; 3],
) -> bool {
    s.crossings.clear();
    s.cells.reset(lo, hi, s.edges.len(), 8.0 * reach, s.typical);
    let frame = s.cells.frame;
    let pad = 8.0 * reach;
    let (edges, hot) = (&s.edges, &s.hot);
    s.cells.fill(edges.len(), |i, push| {
        let e = edges[i];
        frame.along(hot[e.a as usize], hot[e.b as usize], pad, &mut *push);
    });
    let pairs = &mut s.pairs;
    pairs.clear();
    for c in 0..s.cells.len() {
        let list = s.cells.cell(c);
        for (k, &i) in list.iter().enumerate() {
            let e = edges[i as usize];
            let (a, b) = (hot[e.a as usize], hot[e.b as usize]);
            for &j in &list[k + 1..] {
                let f = edges[j as usize];
                // (edges with an end in common cross nowhere inside both: a border two
                // rings share, say, whose signs would all be exact zeros)
                if e.a == f.a || e.a == f.b || e.b == f.a || e.b == f.b {
                    continue;
                }
                let (c, d) = (hot[f.a as usize], hot[f.b as usize]);
                // (boxes first: in a crowded cell most pairs lie apart)
                let apart = a[0].max(b[0]) < c[0].min(d[0])
                    || c[0].max(d[0]) < a[0].min(b[0])
                    || a[1].max(b[1]) < c[1].min(d[1])
                    || c[1].max(d[1]) < a[1].min(b[1]);
                if apart {
                    continue;
                }
                // (the limits read only where something was found)
                if crosses(point(a), point(b), point(c), point(d)) {
                    pairs.push((i.min(j), i.max(j)));
                    if pairs.len() > most[0] {
                        return false;
                    }
                } else if let Some(contacts) = contacts.as_deref_mut() {
                    let ends = ([(e.a, a), (e.b, b)], [(f.a, c), (f.b, d)]);
                    meet_at_vertices(contacts, ends.0, e.from, ends.1, f.from);
                    if contacts.len() > most[1] {
                        return false;
                    }
                }
            }
        }
    }
    pairs.sort_unstable();
    pairs.dedup();
    // (before the rounding, which costs more than the search)
    if pairs.len() > most[2] {
        return false;
    }
    for &(i, j) in pairs.iter() {
        let (e, f) = (edges[i as usize], edges[j as usize]);
        let p = grid.crossing(
            hot[e.a as usize],
            hot[e.b as usize],
            hot[f.a as usize],
            hot[f.b as usize],
        );
        s.crossings.push((p, e.from, f.from));
    }
    true
}

/// Where edges `e` and `f` (their ends: vertex and position; no neighbours, crossing
/// nowhere inside both) meet at a vertex, into `contacts` (see [`find_crossings`]).
fn meet_at_vertices(
    contacts: &mut Vec<(u32, u32)>,
    e: [(u32, [f64; 2]); 2],
    e_from: u32,
    f: [(u32, [f64; 2]); 2],
    f_from: u32,
) {
    for (ends, from, other) in [(e, e_from, f), (f, f_from, e)] {
        let (a, b) = (point(ends[0].1), point(ends[1].1));
        for (v, q) in other {
            if q == ends[0].1 || q == ends[1].1 {
                // (the vertex of this edge there is pushed from the other side)
                contacts.push((v, u32::MAX));
            } else if on_segment(a, b, point(q)) {
                contacts.push((v, from));
            }
        }
    }
}

/// Makes the rounded crossings hot points; those at new positions become added vertices.
/// `again`: hot points were added before (else the hot points are the input's positions,
/// sorted).
fn add_crossings(
    s: &mut Scratch,
    inputs: usize,
    added: &mut Vec<Added>,
    again: bool,
) -> Result<(), Error> {
    s.crossings
        .sort_unstable_by(|x, y| x.partial_cmp(y).unwrap_or(core::cmp::Ordering::Equal));
    let earlier = s.hot.len();
    if again {
        positions::reset_table(&mut s.table, earlier + s.crossings.len());
        for h in 0..earlier as u32 {
            let i = positions::slot(&s.table, s.hot[h as usize], |k| s.hot[k as usize]);
            s.table[i] = h;
        }
    }
    let mut last: Option<[f64; 2]> = None;
    for &(p, e1, e2) in &s.crossings {
        if last == Some(p) {
            continue;
        }
        last = Some(p);
        // (−0.0 is no coordinate here: `distinct_positions` and the rounding give +0.0)
        let known = if again {
            let i = positions::slot(&s.table, p, |k| s.hot[k as usize]);
            s.table[i] != positions::EMPTY
        } else {
            (s.hot[..earlier])
                .binary_search_by(|q| q.partial_cmp(&p).unwrap_or(core::cmp::Ordering::Equal))
                .is_ok()
        };
        if known {
            continue;
        }
        let vertex = inputs + added.len();
        let vertex = u32::try_from(vertex).map_err(|_| Error::TooManyVertices { count: vertex })?;
        added.push(Added {
            vertex,
            position: p,
            edges: [e1, e2],
        });
        s.hot.push(p);
        s.hot_out.push(vertex);
    }
    Ok(())
}

/// Snap rounding: each edge through the centres of the hot pixels it meets.
fn snap(s: &mut Scratch, lo: [f64; 2], hi: [f64; 2], grid: SnapGrid, reach: f64) {
    s.snaps += 1;
    s.cells.reset(lo, hi, s.hot.len(), 8.0 * reach, s.typical);
    s.cells.fill_points(&s.hot);
    s.fragments.clear();
    let frame = s.cells.frame;
    let pad = 8.0 * reach;
    for e in &s.edges {
        let (a, b) = (s.hot[e.a as usize], s.hot[e.b as usize]);
        s.on_edge.clear();
        frame.along(a, b, pad, |c| {
            for &q in s.cells.cell(c) {
                let qp = s.hot[q as usize];
                if q != e.a && q != e.b && near(a, b, qp, 2.0 * reach) && grid.meets_pixel(a, b, qp)
                {
                    s.on_edge.push(q);
                }
            }
        });
        push_path(&mut s.fragments, &mut s.on_edge, &s.hot, *e);
    }
}

/// How many times snap rounding may run on one input (step 2b: a guard, never reached).
const SNAPS: u32 = 64;

/// Snap rounding again where the fragments cross (step 2b): their crossings are rounded
/// and made hot, and every fragment is snapped as the edges were.
fn snap_again(
    s: &mut Scratch,
    lo: [f64; 2],
    hi: [f64; 2],
    grid: SnapGrid,
    reach: f64,
    inputs: usize,
    added: &mut Vec<Added>,
) -> Result<(), Error> {
    // (copied, not swapped: each buffer keeps its own size from call to call)
    s.edges.clear();
    s.edges.extend_from_slice(&s.fragments);
    s.typical = typical_extent(&s.edges, &s.hot);
    find_crossings(s, lo, hi, grid, reach, None, [usize::MAX; 3]);
    if s.crossings.is_empty() || s.snaps >= SNAPS {
        // (split and merged, fragments that meet other than at their ends cross)
        return Err(Error::Internal { stage: "resolve" });
    }
    add_crossings(s, inputs, added, true)?;
    snap(s, lo, hi, grid, reach);
    Ok(())
}

/// Whether the pixel of grid point `q` may meet segment a–b (a float filter: `false`
/// only when it certainly does not), `w` bounding the pixel's half-width (every pixel's:
/// twice that of the largest coordinate).
#[inline]
fn near(a: [f64; 2], b: [f64; 2], q: [f64; 2], w: f64) -> bool {
    if q[0] + w < a[0].min(b[0])
        || q[0] - w > a[0].max(b[0])
        || q[1] + w < a[1].min(b[1])
        || q[1] - w > a[1].max(b[1])
    {
        return false;
    }
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let (qx, qy) = (q[0] - a[0], q[1] - a[1]);
    let det = dx * qy - dy * qx;
    let err = 8.0 * f64::EPSILON * ((dx * qy).abs() + (dy * qx).abs());
    det.abs() <= (dx.abs() + dy.abs()) * w * 2.0 + err + w * f64::EPSILON
}

/// Adds the fragments of the path along `e` from hot point `e.a` through `mid` (in any
/// order) to `e.b`, sorting `mid` along the direction a → b.
fn push_path(fragments: &mut Vec<Edge>, mid: &mut Vec<u32>, hot: &[[f64; 2]], e: Edge) {
    let (a, b) = (e.a, e.b);
    let (pa, pb) = (hot[a as usize], hot[b as usize]);
    let sx = if pb[0] >= pa[0] { 1.0 } else { -1.0 };
    let sy = if pb[1] >= pa[1] { 1.0 } else { -1.0 };
    // columns and rows of the pixels met are monotone along the segment: lexicographic
    // order by (sx·x, sy·y) is the order along it
    mid.sort_unstable_by(|&i, &j| {
        let (p, q) = (hot[i as usize], hot[j as usize]);
        (sx * p[0], sy * p[1])
            .partial_cmp(&(sx * q[0], sy * q[1]))
            .unwrap_or(core::cmp::Ordering::Equal)
    });
    mid.dedup();
    let mut prev = a;
    for &m in mid.iter().chain(core::iter::once(&b)) {
        if m != prev {
            fragments.push(Edge { a: prev, b: m, ..e });
            prev = m;
        }
    }
}

/// Splits every fragment at the hot points lying exactly inside it.
fn split_at_vertices(s: &mut Scratch, lo: [f64; 2], hi: [f64; 2], reach: f64) {
    if s.crossings.is_empty() {
        // (else `snap` listed the hot points already)
        s.cells.reset(lo, hi, s.hot.len(), 8.0 * reach, s.typical);
        s.cells.fill_points(&s.hot);
    }
    let frame = s.cells.frame;
    let pad = 8.0 * reach;
    let mut out = core::mem::take(&mut s.split);
    out.clear();
    for &f in &s.fragments {
        let (a, b) = (f.a, f.b);
        let (pa, pb) = (s.hot[a as usize], s.hot[b as usize]);
        s.on_edge.clear();
        frame.along(pa, pb, pad, |c| {
            for &q in s.cells.cell(c) {
                let pq = s.hot[q as usize];
                if q != a && q != b && on_segment(point(pa), point(pb), point(pq)) {
                    s.on_edge.push(q);
                }
            }
        });
        push_path(&mut out, &mut s.on_edge, &s.hot, f);
    }
    // (copied back, not swapped: each buffer keeps its own size from call to call, so
    // that a warm call allocates nothing)
    s.fragments.clear();
    s.fragments.extend_from_slice(&out);
    s.split = out;
}

/// Sorts the items `0..` by their `keys` (each below `n`) into compressed rows: row `k`
/// holds `items[first[k]..first[k + 1]]`, in item order. A counting sort that uses
/// `first[k + 1]` as row k's cursor (ending at row k + 1's start), so it needs no buffer
/// besides its two outputs.
fn rows(
    first: &mut Vec<u32>,
    items: &mut Vec<u32>,
    n: usize,
    keys: impl Iterator<Item = u32> + Clone,
) {
    first.clear();
    first.resize(n + 2, 0);
    for k in keys.clone() {
        first[k as usize + 2] += 1;
    }
    for v in 2..n + 2 {
        first[v] += first[v - 1];
    }
    items.clear();
    items.resize(first[n + 1] as usize, 0);
    for (i, k) in keys.enumerate() {
        let at = &mut first[k as usize + 1];
        items[*at as usize] = i as u32;
        *at += 1;
    }
    first.truncate(n + 1);
}

/// Merges fragments between the same two points, summing their net counts (from the
/// lower index to the higher); drops those that cancel.
fn merge_fragments(fragments: &mut Vec<Edge>) {
    for f in fragments.iter_mut() {
        if f.a > f.b {
            (f.a, f.b, f.count) = (f.b, f.a, -f.count);
        }
    }
    fragments.sort_unstable_by_key(|f| (f.a, f.b));
    let mut out = 0;
    for i in 0..fragments.len() {
        let f = fragments[i];
        if out > 0 && (fragments[out - 1].a, fragments[out - 1].b) == (f.a, f.b) {
            fragments[out - 1].count += f.count;
        } else {
            fragments[out] = f;
            out += 1;
        }
    }
    fragments.truncate(out);
    fragments.retain(|f| f.count != 0);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rules' regions' areas for `rings`, by the shoelace formula over the resolved
    /// rings (directed with the region on their left, so their signed areas add up), and
    /// the number of vertices added.
    fn areas(rings: &[Vec<[f64; 2]>]) -> ([f64; 5], usize) {
        let mut vertices = Vec::new();
        let mut starts = Vec::new();
        for r in rings {
            starts.push(vertices.len());
            vertices.extend_from_slice(r);
        }
        let mut out = [0.0; 5];
        let mut extra = 0;
        for (k, rule) in FillRule::ALL.into_iter().enumerate() {
            let mut s = Scratch::default();
            let mut added = Vec::new();
            let grid = SnapGrid { f32: false };
            resolve(&mut s, &vertices, &starts, rule, grid, false, &mut added).unwrap();
            if s.crossings.is_empty() {
                // without crossings, skipping the search (as after strict mode's check)
                // changes nothing
                let mut skipped = Scratch::default();
                resolve(
                    &mut skipped,
                    &vertices,
                    &starts,
                    rule,
                    grid,
                    true,
                    &mut Vec::new(),
                )
                .unwrap();
                assert_eq!(
                    (&skipped.rings, &skipped.ring_starts),
                    (&s.rings, &s.ring_starts)
                );
            }
            out[k] = signed_area(&s.rings, &s.ring_starts);
            extra = added.len();
        }
        (out, extra)
    }

    /// The resolved rings' signed area (each ring of at least three vertices).
    fn signed_area(rings: &[[f64; 2]], starts: &[usize]) -> f64 {
        let mut twice = 0.0;
        for (i, &start) in starts.iter().enumerate() {
            let end = starts.get(i + 1).copied().unwrap_or(rings.len());
            let ring = &rings[start..end];
            assert!(ring.len() >= 3, "a ring of {} vertices", ring.len());
            for j in 0..ring.len() {
                let (a, b) = (ring[j], ring[(j + 1) % ring.len()]);
                twice += a[0] * b[1] - a[1] * b[0];
            }
        }
        twice / 2.0
    }

    fn square(x: f64, y: f64, side: f64) -> Vec<[f64; 2]> {
        vec![[x, y], [x + side, y], [x + side, y + side], [x, y + side]]
    }

    fn reversed(mut r: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
        r.reverse();
        r
    }

    // order of the areas: even-odd, nonzero, positive, negative, abs ≥ 2

    #[test]
    fn overlapping_squares_give_each_rule_its_region() {
        let (a, added) = areas(&[square(0.0, 0.0, 2.0), square(1.0, 1.0, 2.0)]);
        assert_eq!(a, [6.0, 7.0, 7.0, 0.0, 1.0]);
        assert_eq!(added, 2);
        let (a, _) = areas(&[square(0.0, 0.0, 2.0), reversed(square(1.0, 1.0, 2.0))]);
        assert_eq!(a, [6.0, 6.0, 3.0, 3.0, 0.0]);
    }

    #[test]
    fn a_ring_wound_twice_covers_its_inside_twice() {
        let mut twice = square(0.0, 0.0, 1.0);
        twice.extend(square(0.0, 0.0, 1.0));
        let (a, added) = areas(&[twice]);
        assert_eq!(a, [0.0, 1.0, 1.0, 0.0, 1.0]);
        assert_eq!(added, 0);
        // the same as two copies
        let (b, _) = areas(&[square(0.0, 0.0, 1.0), square(0.0, 0.0, 1.0)]);
        assert_eq!(a, b);
    }

    #[test]
    fn shared_edges_and_vertices_on_edges_need_no_added_vertex() {
        // side by side, one edge shared in part; a third square's corner on an edge
        let (a, added) = areas(&[
            square(0.0, 0.0, 2.0),
            square(2.0, 1.0, 2.0),
            reversed(square(0.0, 2.0, 1.0)),
        ]);
        assert_eq!(added, 0);
        assert_eq!(a, [9.0, 9.0, 8.0, 1.0, 0.0]);
    }

    /// Two squares sharing a side (a layer's neighbours: the side run once each way)
    /// and a thin triangle across that side: the shared side changes no winding number,
    /// so its crossings with the triangle add nothing; one run the same way twice is
    /// kept, and its crossings are added.
    #[test]
    fn a_border_run_both_ways_cancels_before_crossings_are_rounded() {
        let sliver = vec![[1.5, 0.5], [2.5, 0.6], [2.5, 0.7]];
        let (a, added) = areas(&[square(0.0, 0.0, 2.0), square(2.0, 0.0, 2.0), sliver.clone()]);
        assert_eq!(added, 0);
        // the sliver (0.05) inside the union of the squares (8): even-odd cuts it out,
        // it winds twice there
        let near = |x: [f64; 5], y: [f64; 5]| x.iter().zip(&y).all(|(p, q)| (p - q).abs() < 1e-12);
        assert!(near(a, [7.95, 8.0, 8.0, 0.0, 0.05]), "{a:?}");
        // the right square turned round: its left side runs the way the left square's
        // right side does, and both cross the sliver, which gets two added vertices
        let (b, added) = areas(&[
            square(0.0, 0.0, 2.0),
            reversed(square(2.0, 0.0, 2.0)),
            sliver,
        ]);
        assert_eq!(added, 2);
        // (the sliver's part right of x = 2 is 0.0375; it winds 0 there, and 2 on the left)
        assert!(near(b, [7.95, 7.9625, 4.0, 3.9625, 0.0125]), "{b:?}");
    }

    /// A pentagram of radius 100: each edge crosses two others.
    pub(super) fn pentagram() -> Vec<[f64; 2]> {
        (0..5)
            .map(|k| {
                let t = core::f64::consts::FRAC_PI_2 + 4.0 * core::f64::consts::PI * k as f64 / 5.0;
                [100.0 * t.cos(), 100.0 * t.sin()]
            })
            .collect()
    }

    #[test]
    fn a_pentagram_has_points_by_even_odd_and_a_centre_by_nonzero() {
        let (a, added) = areas(&[pentagram()]);
        assert_eq!(added, 5);
        // the pentagram's centre pentagon has winding 2: nonzero − even-odd = abs ≥ 2
        assert!((a[1] - a[0] - a[4]).abs() < 1e-9 * a[1], "{a:?}");
        assert!(a[4] > 0.0 && a[0] > a[4] && a[3] == 0.0 && a[2] == a[1]);
    }

    /// Found by the `fill_rules` fuzz target (collinear overlaps in `f32`): an edge passes
    /// just outside the pixel of a vertex, which is short (y near 232), between two hot
    /// points whose pixels are tall (y near 664 and 752); its rounded fragment between
    /// them crosses an edge from that vertex. Snap rounding runs again on the fragments,
    /// and every rule's region comes out as with `f64`'s far finer grid, up to the
    /// rounding.
    #[test]
    fn fragments_rounded_across_a_vertex_with_a_smaller_pixel_are_snapped_again() {
        let rings: [&[[f32; 2]]; 9] = [
            &[
                [2131.2954, 1652.4354],
                [1637.2043, 2549.3467],
                [-1456.3502, -323.9288],
            ],
            &[
                [7877.8467, -4534.674],
                [4784.292, -7407.949],
                [-7202.9014, 5863.18],
            ],
            &[
                [5095.842, -3729.033],
                [-4238.355, 481.71188],
                [4913.3003, 846.7947],
            ],
            &[
                [9306.587, 5605.1636],
                [-6252.457, -6473.3003],
                [6927.402, 7801.8066],
            ],
            &[
                [1325.6547, -1129.5695],
                [831.5636, -232.6581],
                [-65.347786, -726.74915],
                [-962.25916, -1220.8402],
                [-468.16812, -2117.7515],
                [428.74326, -1623.6605],
            ],
            &[
                [2222.566, -635.47845],
                [1325.6547, -1129.5695],
                [337.47256, 664.2533],
                [1234.3839, 1158.3444],
            ],
            &[
                [-2041.7119, 2860.8965],
                [-2535.803, 3757.8079],
                [-5226.537, 2275.5347],
                [-4732.4463, 1378.6233],
            ],
            &[
                [3119.4775, -141.38739],
                [1143.1133, 3446.258],
                [-650.70953, 2458.0762],
                [1325.6547, -1129.5695],
            ],
            &[
                [246.20186, 2952.167],
                [1143.1133, 3446.258],
                [1637.2043, 2549.3467],
                [740.2929, 2055.2556],
            ],
        ];
        let mut vertices = Vec::new();
        let mut starts = Vec::new();
        for r in rings {
            starts.push(vertices.len());
            vertices.extend(r.iter().map(|p| p.map(f64::from)));
        }
        for rule in FillRule::ALL {
            let mut area = [0.0; 2];
            for (k, f32) in [true, false].into_iter().enumerate() {
                let mut s = Scratch::default();
                let grid = SnapGrid { f32 };
                resolve(
                    &mut s,
                    &vertices,
                    &starts,
                    rule,
                    grid,
                    false,
                    &mut Vec::new(),
                )
                .unwrap_or_else(|e| panic!("{rule:?}, f32 {f32}: {e:?}"));
                if f32 {
                    assert_eq!(s.snaps, 2, "{rule:?}: the first rounding is not planar");
                }
                area[k] = signed_area(&s.rings, &s.ring_starts);
            }
            // (f32's relative precision is 6·10⁻⁸; the rings cover about 3·10⁸)
            assert!(area[1] > 1e6, "{rule:?}: {}", area[1]);
            assert!(
                (area[0] - area[1]).abs() <= 100.0,
                "{rule:?}: {} against {}",
                area[0],
                area[1]
            );
        }
    }

    #[test]
    fn ring_starts_without_vertices_give_nothing() {
        let mut s = Scratch::default();
        let grid = SnapGrid { f32: false };
        for starts in [&[0, 1][..], &[0, 5, 7], &[]] {
            resolve(
                &mut s,
                &[],
                starts,
                FillRule::EvenOdd,
                grid,
                false,
                &mut Vec::new(),
            )
            .unwrap();
            assert!(s.rings.is_empty());
        }
    }

    #[test]
    fn out_of_range_coordinates_are_refused() {
        let mut s = Scratch::default();
        let grid = SnapGrid { f32: false };
        let tiny = [[0.0, 0.0], [1.0, 0.0], [1e-80, 1.0]];
        let err = resolve(
            &mut s,
            &tiny,
            &[0],
            FillRule::NonZero,
            grid,
            false,
            &mut Vec::new(),
        );
        assert_eq!(err, Err(Error::CoordinateRange { vertex: 2 }));
        let huge = [[0.0, 0.0], [1e31, 0.0], [1.0, 1.0]];
        let err = resolve(
            &mut s,
            &huge,
            &[0],
            FillRule::NonZero,
            grid,
            false,
            &mut Vec::new(),
        );
        assert_eq!(err, Err(Error::CoordinateRange { vertex: 1 }));
    }
}
