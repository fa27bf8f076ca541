//! Stage 2, *clean*: make every ring a proper one and every position one vertex.
//!
//! 1. Drop repeated vertices, collinear vertices and zero-width spikes from each ring
//!    (earcut's `filterPoints`); a ring left with fewer than three vertices encloses no area
//!    and is dropped.
//! 2. Sweep all edges (`crossings::sweep`): crossing edges are refused in strict mode (lenient
//!    mode may uncross bow ties, see [`Triangulator`](crate::Triangulator)); vertices
//!    lying inside another edge ("T-junctions", e.g. a hole touching the outer ring in the
//!    middle of an edge) are found in both modes.
//! 3. Give every position one vertex index: where rings touch, all nodes there use the
//!    lowest input index, so the output mesh is consistent by index.
//! 4. Split each touched edge at the vertices lying on it: touching happens only at
//!    vertices from here on.
//! 5. ([`orient_rings`], after lenient mode's `lobes` split) Find each ring's rightmost
//!    vertex (ties: lowest y), its winding from the turn there, and make every ring
//!    counter-clockwise. No winding order is assumed from the caller.

use crate::context::{
    lowest_net_arrives, net_boundary_counter_clockwise, Context, LoadedRing, NetEdge,
};
use crate::crossings::proof;
use crate::crossings::proof::{Contact, ProofScratch};
use crate::crossings::sweep::{self, Crossing, SweepScratch, Touch};
use crate::geom::{cmp_xy, crosses, on_segment, orient2d, within_box, Orientation, Point};
use crate::report::{DropReason, Dropped, RepairKind};
use crate::structures::NodeId;
use crate::Error;

/// Scratch buffers of the clean stage, kept between calls (and between the runs of one
/// lenient call, which reuse the first run's sweep order).
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// A start node of each ring swept.
    starts: Vec<NodeId>,
    /// Edges (by start node) found crossing among the rings as loaded.
    flagged: Vec<NodeId>,
    /// Vertices the sweep found inside edges.
    touches: Vec<Touch>,
    /// Nodes at shared positions, as the quick proof lists them (see
    /// [`proof::edges_meet_at_vertices`]).
    shared: Vec<NodeId>,
    /// The sweep's buffers; its order of the nodes by position is read afterwards.
    sweep: SweepScratch,
    /// The quick proof's buffers.
    proof: ProofScratch,
    /// A ring's segments with their net walks (see `net_boundary_counter_clockwise`).
    net_edges: Vec<NetEdge>,
    /// Tests: always search the rings as loaded in full where the filter dropped geometry
    /// (the way before [`lost_edges_apart`]), and how often each way was taken: the lost
    /// edges proved apart, the full search before the sweep, and after it.
    #[cfg(test)]
    full_search: bool,
    #[cfg(test)]
    searches: [usize; 3],
}

/// Runs the clean stage over every loaded ring. With `untwist` (lenient mode, the second
/// run over an input whose first run found crossings), bow ties are uncrossed first.
/// Returns false when untwisting changed nothing: that run would repeat the first exactly,
/// so the stage stops there.
pub(crate) fn clean(cx: &mut Context, s: &mut Scratch, untwist: bool) -> Result<bool, Error> {
    // every ring as loaded: its first node and node count
    cx.as_loaded.clear();
    let as_loaded = (cx.rings.iter()).map(|r| LoadedRing {
        first: r.start.0,
        len: r.len,
    });
    cx.as_loaded.extend(as_loaded);
    let dropped_before = cx.dropped.len();
    for r in 0..cx.rings.len() {
        filter_ring(cx, r);
    }
    // (strict mode, dropped geometry: see `refuse_hidden_crossing`; where no edge the
    // filter took away crosses another, any crossing is one of the filtered rings' too, and
    // the full search waits until the sweep finds one: its error names the same pair)
    let dropped = !cx.lenient && dropped_geometry(cx, dropped_before);
    // (a caller that only asks whether the input passes does without that search, and is
    // told so: a crossing hidden there is `resolve`'s to find)
    let hidden = dropped && !cx.probe;
    cx.hidden_unchecked |= dropped && cx.probe;
    #[cfg(test)]
    let shortcut = !s.full_search;
    #[cfg(not(test))]
    let shortcut = true;
    let deferred = hidden && shortcut && few_lost_edges(cx, s) && lost_edges_apart(cx, s);
    if hidden && !deferred {
        #[cfg(test)]
        {
            s.searches[1] += 1;
        }
        refuse_hidden_crossing(cx, s, dropped_before)?;
    }
    let swept = sweep_filtered(cx, s, untwist);
    #[cfg(test)]
    {
        s.searches[0] += usize::from(deferred);
        s.searches[2] += usize::from(deferred && swept.is_err());
    }
    if deferred && matches!(swept, Err(Error::EdgesCross { .. })) {
        refuse_hidden_crossing(cx, s, dropped_before)?;
    }
    let apart = match swept? {
        Some(apart) => apart,
        None if untwist => return Ok(false),
        None => {
            // Two edges cross where one of them had a vertex the filter dropped: at that
            // vertex the input only touched. Filter again, keeping straight vertices
            // (for this run and the following ones of this call), and sweep again.
            cx.keep_collinear = true;
            refilter(cx, dropped_before);
            sweep_filtered(cx, s, untwist)?.unwrap_or(false)
        }
    };
    if apart {
        // no two nodes share a position and no vertex lies on an edge
        cx.shared.clear();
    } else {
        canonical_vertices(cx, s);
        // nodes from here on are the ones edge splits add
        let first_split = cx.pool.len();
        split_touched_edges(cx, s);
        collect_shared(cx, s, first_split);
    }
    Ok(true)
}

/// Step 5 of the stage, after `lobes` (which splits rings before they are oriented):
/// finds each live ring's rightmost vertex and winding, and turns it counter-clockwise.
pub(crate) fn orient_rings(cx: &mut Context, s: &mut Scratch) {
    for r in 0..cx.rings.len() {
        if cx.rings[r].alive {
            orient_ring(cx, s, r);
        }
    }
}

/// Drops repeated, collinear and spike vertices from ring `r`; kills it when fewer than
/// three vertices remain.
fn filter_ring(cx: &mut Context, r: usize) {
    let ring_id = cx.rings[r].input;
    let mut len = cx.rings[r].len;
    let mut n = cx.rings[r].start;
    // `stop` is the last node known good; a full lap without removal ends the loop.
    let mut stop = cx.pool.prev(n);
    while len >= 3 {
        let (prev, next) = (cx.pool.prev(n), cx.pool.next(n));
        let (pp, pn, px) = (cx.pool.p(prev), cx.pool.p(n), cx.pool.p(next));
        let reason = if pp == pn {
            Some(DropReason::Repeated)
        } else if pn == px {
            // drop the later of two repeated vertices (a closing point, typically)
            drop_node(cx, next, ring_id, DropReason::Repeated);
            len -= 1;
            stop = prev;
            continue;
        } else if orient2d(pp, pn, px) != Orientation::Collinear {
            None
        } else if within_box(pp, px, pn) {
            (!cx.keep_collinear).then_some(DropReason::Collinear)
        } else {
            Some(DropReason::Spike)
        };
        match reason {
            Some(reason) => {
                drop_node(cx, n, ring_id, reason);
                len -= 1;
                // the previous vertex may have become collinear or a spike: look again
                n = prev;
                stop = cx.pool.prev(prev);
            }
            None => {
                if n == stop {
                    break;
                }
                n = next;
            }
        }
    }
    let ring = &mut cx.rings[r];
    ring.len = len;
    ring.start = n;
    if len < 3 {
        ring.alive = false;
        ring.len = 0;
        for _ in 0..len {
            let next = cx.pool.next(n);
            drop_node(cx, n, ring_id, DropReason::DegenerateRing);
            n = next;
        }
    }
}

/// Links every ring as loaded again, all its nodes live.
fn relink_as_loaded(cx: &mut Context) {
    for r in 0..cx.rings.len() {
        let LoadedRing { first, len: count } = cx.as_loaded[r];
        for n in &mut cx.pool.nodes[first as usize..(first + count) as usize] {
            n.removed = false;
        }
        cx.pool.link_run(first, count);
        let ring = &mut cx.rings[r];
        (ring.start, ring.len, ring.alive) = (NodeId(first), count, true);
    }
}

/// Filters every ring again from its loaded nodes, forgetting the drops since
/// `dropped_before`.
fn refilter(cx: &mut Context, dropped_before: usize) {
    cx.dropped.truncate(dropped_before);
    relink_as_loaded(cx);
    for r in 0..cx.rings.len() {
        filter_ring(cx, r);
    }
}

/// Whether the filter dropped geometry since `dropped_before`: a spike's tip or a ring
/// enclosing nothing, whose edges are gone from the rings the sweep sees. (Repeated and
/// straight vertices leave the rings' point sets as they were.)
fn dropped_geometry(cx: &Context, dropped_before: usize) -> bool {
    cx.dropped[dropped_before..]
        .iter()
        .any(|d| matches!(d.reason, DropReason::Spike | DropReason::DegenerateRing))
}

/// Strict mode, after the filter dropped a spike or a degenerate ring: an edge crossing it
/// crosses the input's boundary, although not the filtered rings'. Looks for a proper
/// crossing among the edges as loaded and refuses the input if there is one; else filters
/// again (the same drops). Only inputs with such drops pay for it.
fn refuse_hidden_crossing(
    cx: &mut Context,
    s: &mut Scratch,
    dropped_before: usize,
) -> Result<(), Error> {
    relink_as_loaded(cx);
    s.starts.clear();
    // (load makes no ring of zero nodes)
    s.starts.extend(cx.rings.iter().map(|r| r.start));
    let mut flagged = core::mem::take(&mut s.flagged);
    if !proof::crossing_pair(&cx.pool, &s.starts, &mut s.proof, &mut flagged) {
        // too many long edges over each other for the pairwise scan: the grid finds them
        // (the rings as loaded, not as filtered: the index is stale once they are filtered
        // again below)
        cx.edge_index.rebuild(&cx.pool, &cx.rings);
        cx.edge_index.invalidate();
        sweep::crossing_pairs(&cx.pool, cx.edge_index.grid(), &s.starts, &mut flagged);
    }
    let first = flagged.first().copied().zip(flagged.get(1).copied());
    s.flagged = flagged;
    if let Some((a, b)) = first {
        return Err(edges_cross(cx, a, b));
    }
    refilter(cx, dropped_before);
    Ok(())
}

/// The most edges the filter took away (loaded edges at a dropped node) that
/// [`lost_edges_apart`] compares with every loaded edge, and the most such pairs; more go
/// to the full search.
const LOST_MAX: usize = 32;
const LOST_PAIRS_MAX: usize = 1 << 22;

/// Lists in `s.flagged` the start node of every loaded edge the filtered rings lost: each
/// run of dropped nodes between two kept ones, u and v, whose nodes do not all lie on the
/// segment u–v that replaced them (a spike's tip, say: its edges lie outside that
/// segment), and every edge of a ring dropped whole. False when there are more than
/// [`LOST_MAX`], or more than [`LOST_PAIRS_MAX`] pairs with the loaded edges to compare.
fn few_lost_edges(cx: &Context, s: &mut Scratch) -> bool {
    s.flagged.clear();
    let pool = &cx.pool;
    let removed = |i: u32| pool.get(NodeId(i)).removed;
    for &ring in &cx.as_loaded {
        let next = |i: u32| ring.next(i);
        // (an edge of no length crosses nothing properly: a ring of one repeated point
        // loses none that matters)
        let lengthy = |i: u32| pool.p(NodeId(i)) != pool.p(NodeId(next(i)));
        let Some(start) = ring.nodes().find(|&i| !removed(i)) else {
            for e in ring.nodes().filter(|&i| lengthy(i)) {
                if s.flagged.len() == LOST_MAX {
                    return false;
                }
                s.flagged.push(NodeId(e));
            }
            continue;
        };
        // from kept node to kept node, round the ring once
        let mut u = start;
        loop {
            let mut v = next(u);
            while removed(v) {
                v = next(v);
            }
            let (a, b) = (pool.p(NodeId(u)), pool.p(NodeId(v)));
            let mut d = next(u);
            while d != v && on_segment(a, b, pool.p(NodeId(d))) {
                d = next(d);
            }
            if d != v {
                let mut e = u;
                while e != v {
                    if lengthy(e) {
                        if s.flagged.len() == LOST_MAX {
                            return false;
                        }
                        s.flagged.push(NodeId(e));
                    }
                    e = next(e);
                }
            }
            u = v;
            if u == start {
                break;
            }
        }
    }
    let loaded: usize = cx.as_loaded.iter().map(|r| r.len as usize).sum();
    s.flagged.len().saturating_mul(loaded) <= LOST_PAIRS_MAX
}

/// Whether no edge listed by [`few_lost_edges`] crosses a loaded edge properly: then the
/// filter hid no crossing (every other loaded edge lies on an edge of the filtered rings).
fn lost_edges_apart(cx: &Context, s: &Scratch) -> bool {
    let pool = &cx.pool;
    let edge = |ring: LoadedRing, i: u32| (pool.p(NodeId(i)), pool.p(NodeId(ring.next(i))));
    let mut lost = [(Point::new(0.0, 0.0), Point::new(0.0, 0.0)); LOST_MAX];
    for (k, l) in s.flagged.iter().enumerate().take(LOST_MAX) {
        lost[k] = edge(cx.as_loaded[pool.get(*l).ring as usize], l.0);
    }
    let lost = &lost[..s.flagged.len().min(LOST_MAX)];
    cx.as_loaded.iter().all(|&ring| {
        ring.nodes().all(|i| {
            let (c, d) = edge(ring, i);
            lost.iter().all(|&(a, b)| !crosses(a, b, c, d))
        })
    })
}

/// The error for the edges starting at `a` and `b`, which cross.
fn edges_cross(cx: &Context, a: NodeId, b: NodeId) -> Error {
    let (na, nb) = (cx.pool.get(a), cx.pool.get(b));
    Error::EdgesCross {
        ring_a: cx.rings[na.ring as usize].input as usize,
        edge_a: na.vertex as usize,
        ring_b: cx.rings[nb.ring as usize].input as usize,
        edge_b: nb.vertex as usize,
    }
}

/// Unlinks node `n` and records its vertex as dropped.
fn drop_node(cx: &mut Context, n: NodeId, ring: u32, reason: DropReason) {
    let vertex = cx.pool.get(n).vertex;
    cx.pool.remove(n);
    cx.dropped.push(Dropped {
        vertex,
        ring,
        reason,
    });
}

/// The sweep after filtering (see [`sweep`]); with `untwist`, bow ties are uncrossed first
/// (`Ok(None)` when there were none: the caller stops).
fn sweep_filtered(cx: &mut Context, s: &mut Scratch, untwist: bool) -> Result<Option<bool>, Error> {
    if untwist {
        // Loading and filtering are deterministic, so these are the first run's nodes and
        // `cx.crossings` still holds what its sweep found in them: report those crossings
        // as that sweep did, without sweeping again.
        report_crossings(cx);
        if !untwist_bow_ties(cx) {
            return Ok(None);
        }
        // Untwisting relinks nodes but keeps them and their positions, so the first run's
        // sweep order holds. A crossing it found that untwisting left alone means no proof
        // of edges apart can succeed; without trying one, that order is still in place.
        let pool = &cx.pool;
        let crossed = |a: NodeId| (pool.p(a), pool.p(pool.next(a)));
        let still_crossed = cx.crossings.iter().any(|c| {
            let ((a, b), (p, q)) = (crossed(c.a), crossed(c.b));
            crosses(a, b, p, q)
        });
        // (relinking may have left collinear turns)
        if still_crossed {
            s.sweep.order_is_sorted = true;
            sweep(cx, s, None, false)
        } else {
            sweep(cx, s, Some(false), false)
        }
    } else {
        // the filter left no collinear turn, unless told to keep them
        sweep(cx, s, Some(!cx.keep_collinear), true)
    }
}

/// Whether two edges the sweep found crossing (`cx.crossings`) cross where one of them ran
/// through a vertex the filter dropped (a straight one, say): the input only touched
/// there.
fn crossing_at_dropped_vertex(cx: &Context) -> bool {
    let pool = &cx.pool;
    let edge = |e: NodeId| (pool.p(e), pool.p(pool.next(e)));
    // the nodes dropped between e and its successor, in input order
    let gap = |e: NodeId| {
        let LoadedRing { first, len: count } = cx.as_loaded[pool.get(e).ring as usize];
        let (s, t) = (e.0 - first, pool.next(e).0 - first);
        let len = if t > s { t - s - 1 } else { count - s + t - 1 };
        (1..=len).map(move |k| NodeId(first + (s + k) % count))
    };
    cx.crossings.iter().any(|c| {
        [(c.a, c.b), (c.b, c.a)].into_iter().any(|(e, f)| {
            let ((e0, e1), (f0, f1)) = (edge(e), edge(f));
            gap(e).any(|d| {
                let p = pool.p(d);
                on_segment(e0, e1, p) && on_segment(f0, f1, p)
            })
        })
    })
}

/// Sweeps every live edge: crossings are errors in strict mode, repairs in lenient mode.
/// With `prune`, first tries to prove that no two edges meet, or meet only at vertices,
/// which gives the same result faster; `Some(true)` says that no turn is collinear (see
/// [`proof::edges_meet_at_vertices`]). Returns whether the edges were proved apart: then
/// no two nodes share a position either. With
/// `may_retry`, `None` when two edges cross at a vertex the filter dropped (see
/// [`crossing_at_dropped_vertex`]) and straight vertices were not kept yet.
fn sweep(
    cx: &mut Context,
    s: &mut Scratch,
    prune: Option<bool>,
    may_retry: bool,
) -> Result<Option<bool>, Error> {
    s.starts.clear();
    s.starts
        .extend(cx.rings.iter().filter(|r| r.alive).map(|r| r.start));
    s.touches.clear();
    cx.crossings.clear();
    // Usually no two edges meet at all, or only where rings touch at vertices; proving
    // that is cheaper than the sweep and gives its result: no crossings, the touches, and
    // the nodes at shared positions (the order of `sweep.order` only matters for grouping
    // those).
    if let Some(turns_proper) = prune {
        let order = &mut s.sweep.order;
        let (touches, shared) = (&mut s.touches, &mut s.shared);
        let pool = &cx.pool;
        let proof = &mut s.proof;
        match proof::edges_meet_at_vertices(
            pool,
            &s.starts,
            proof,
            order,
            turns_proper,
            touches,
            shared,
        ) {
            Contact::Apart => return Ok(Some(true)),
            Contact::AtVertices => {
                // (copied, not swapped: each buffer keeps the capacity it needs)
                order.clear();
                order.extend_from_slice(shared);
                return Ok(Some(false));
            }
            // (a caller that only asks whether the input passes stops here; others
            // sweep, for the crossing strict mode names and lenient mode's repairs)
            Contact::Crossed(a, b) if cx.probe => return Err(edges_cross(cx, a, b)),
            Contact::NotProved | Contact::Crossed(..) => {}
        }
    }
    sweep::sweep(
        &cx.pool,
        &s.starts,
        &mut s.sweep,
        !cx.lenient,
        &mut s.touches,
        &mut cx.crossings,
    );
    if let Some(&Crossing { a, b }) = cx.crossings.first() {
        if may_retry && !cx.keep_collinear && crossing_at_dropped_vertex(cx) {
            return Ok(None);
        }
        if !cx.lenient {
            return Err(edges_cross(cx, a, b));
        }
        report_crossings(cx);
    }
    Ok(Some(false))
}

/// Lenient mode: records a repair for each crossing in `cx.crossings`.
fn report_crossings(cx: &mut Context) {
    for i in 0..cx.crossings.len() {
        let a = cx.pool.get(cx.crossings[i].a);
        let (ring, vertex) = (cx.rings[a.ring as usize].input, a.vertex);
        cx.repair(RepairKind::EdgesCross, ring, vertex);
    }
}

/// Lenient mode: swaps p and q wherever edge a → p crosses edge q → b two steps on (a
/// bow tie), which uncrosses them (a 2-opt move). Returns whether anything changed.
fn untwist_bow_ties(cx: &mut Context) -> bool {
    let mut any = false;
    for r in 0..cx.rings.len() {
        if !cx.rings[r].alive || cx.rings[r].len < 4 {
            continue;
        }
        let mut p = cx.rings[r].start;
        for _ in 0..cx.rings[r].len {
            let pool = &mut cx.pool;
            let (a, q) = (pool.prev(p), pool.next(p));
            let b = pool.next(q);
            if a != b && crosses(pool.p(a), pool.p(p), pool.p(q), pool.p(b)) {
                pool.get_mut(a).next = q;
                pool.get_mut(q).prev = a;
                pool.get_mut(q).next = p;
                pool.get_mut(p).prev = q;
                pool.get_mut(p).next = b;
                pool.get_mut(b).prev = p;
                let (ring, vertex) = (cx.rings[r].input, pool.get(p).vertex);
                cx.repair(RepairKind::EdgesCross, ring, vertex);
                any = true;
            }
            p = cx.pool.next(p);
        }
        cx.rings[r].start = p;
    }
    any
}

/// Makes all nodes at one position use one vertex index, the lowest; reports the others.
fn canonical_vertices(cx: &mut Context, s: &mut Scratch) {
    let order = &s.sweep.order;
    let mut i = 0;
    while i < order.len() {
        let p = cx.pool.p(order[i]);
        let mut j = i + 1;
        while j < order.len() && cx.pool.p(order[j]) == p {
            j += 1;
        }
        if j - i > 1 {
            let min = order[i..j]
                .iter()
                .map(|&n| cx.pool.get(n).vertex)
                .min()
                .unwrap_or(0);
            for &n in &order[i..j] {
                let node = cx.pool.get_mut(n);
                if node.vertex != min {
                    let (vertex, ring) = (node.vertex, node.ring);
                    node.vertex = min;
                    let ring = cx.rings[ring as usize].input;
                    cx.dropped.push(Dropped {
                        vertex,
                        ring,
                        reason: DropReason::Coincident,
                    });
                }
            }
        }
        i = j;
    }
}

/// Inserts a node into every edge at each vertex found lying inside it, in order along the
/// edge, so that rings touch only at shared vertices.
fn split_touched_edges(cx: &mut Context, s: &mut Scratch) {
    if s.touches.is_empty() {
        return;
    }
    let pool = &cx.pool;
    // group by edge, then order along the edge (the points are collinear with it, so
    // comparing coordinates in the edge's direction orders them exactly)
    s.touches.sort_unstable_by(|u, w| {
        u.edge.cmp(&w.edge).then_with(|| {
            let (a, b) = (pool.p(u.edge), pool.p(pool.next(u.edge)));
            let (ps, pt) = (pool.p(u.vertex), pool.p(w.vertex));
            let ord = cmp_xy(ps, pt);
            if cmp_xy(a, b).is_le() {
                ord
            } else {
                ord.reverse()
            }
        })
    });
    let mut k = 0;
    while k < s.touches.len() {
        let edge = s.touches[k].edge;
        let mut after = edge;
        while k < s.touches.len() && s.touches[k].edge == edge {
            let v = s.touches[k].vertex;
            let (p, vertex) = (cx.pool.p(v), cx.pool.get(v).vertex);
            if cx.pool.p(after) != p {
                after = cx.pool.insert_after(after, p, vertex);
                let ring = cx.pool.get(edge).ring as usize;
                cx.rings[ring].len += 1;
            }
            k += 1;
        }
    }
}

/// Lists every node at a position held by more than one node (rings touching there, or a
/// ring touching itself), grouped by position, for `touch` to join them properly.
///
/// `first_split` is the pool's length before `split_touched_edges`: the nodes from there on
/// are the splits. (`sweep.order` holds live nodes only, so its length is no such bound once
/// `filter_ring` dropped vertices.)
fn collect_shared(cx: &mut Context, s: &mut Scratch, first_split: usize) {
    cx.shared.clear();
    let order = &s.sweep.order;
    let mut i = 0;
    while i < order.len() {
        let p = cx.pool.p(order[i]);
        let mut j = i + 1;
        while j < order.len() && cx.pool.p(order[j]) == p {
            j += 1;
        }
        if j - i > 1 {
            cx.shared.extend_from_slice(&order[i..j]);
        }
        i = j;
    }
    // T-junction splits made new nodes at the touching vertices' positions
    for t in &s.touches {
        cx.shared.push(t.vertex);
    }
    let split_nodes = first_split..cx.pool.len();
    cx.shared.extend(split_nodes.map(|n| NodeId(n as u32)));
    let pool = &cx.pool;
    cx.shared
        .sort_unstable_by(|&a, &b| cmp_xy(pool.p(a), pool.p(b)).then(a.cmp(&b)));
    cx.shared.dedup();
}

/// The pool range holding exactly ring `r`'s live nodes (with removed ones between), when
/// there is one: nothing was inserted since loading (the pool ends where the last ring
/// loaded ends) and no ring was cut into lobes. Pool order need not be ring order
/// (untwisting relinks), but reading the range needs no walk along the links, whose every
/// step waits for the last.
fn loaded_range(cx: &Context, r: usize) -> Option<core::ops::Range<usize>> {
    let last = cx.as_loaded.last()?;
    if cx.split_lobes || cx.pool.len() != (last.first + last.len) as usize {
        return None;
    }
    let ring = cx.as_loaded.get(r)?;
    Some(ring.first as usize..(ring.first + ring.len) as usize)
}

/// Ring `r`'s rightmost-lowest node, and how many of its nodes lie there. Where several
/// do, the first in the walk from the ring's start is the one.
fn rightmost(cx: &Context, r: usize) -> (NodeId, u32) {
    let pool = &cx.pool;
    let start = cx.rings[r].start;
    let pick = |nodes: &mut dyn Iterator<Item = NodeId>| {
        let (mut best, mut b) = (start, pool.p(start));
        let mut visits = 0;
        for n in nodes {
            let p = pool.p(n);
            if p.x > b.x || (p.x == b.x && p.y < b.y) {
                (best, b, visits) = (n, p, 1);
            } else if p == b {
                visits += 1;
            }
        }
        (best, visits)
    };
    if let Some(range) = loaded_range(cx, r) {
        let mut live = range
            .map(|k| NodeId(k as u32))
            .filter(|&n| !pool.get(n).removed);
        let found = pick(&mut live);
        if found.1 == 1 {
            return found;
        }
    }
    pick(&mut pool.ring(start))
}

/// Finds ring `r`'s rightmost vertex and makes the ring counter-clockwise.
fn orient_ring(cx: &mut Context, s: &mut Scratch, r: usize) {
    let start = cx.rings[r].start;
    let (best, visits) = rightmost(cx, r);
    cx.rings[r].rightmost = best;
    // Visited once, the rightmost-lowest vertex is usually a strict turn (no repeats, no
    // spikes, and a split node is never rightmost-lowest), and that turn gives the
    // winding. A ring touching itself there may turn at a visit whose edges belong to
    // different lobes; where every edge there is walked both ways, the ring's net boundary
    // decides. So it does at a wall's tip visited once, which a lobe cut from a ring may
    // keep (the filter ran before the cut): its turn says nothing.
    let pool = &cx.pool;
    let turn = orient2d(
        pool.p(pool.prev(best)),
        pool.p(best),
        pool.p(pool.next(best)),
    );
    let counter_clockwise = if visits > 1 {
        outermost_edge_arrives(cx, best)
            .or_else(|| net_boundary_counter_clockwise(&cx.pool, start, &mut s.net_edges))
    } else if turn == Orientation::Collinear {
        net_boundary_counter_clockwise(&cx.pool, start, &mut s.net_edges)
    } else {
        None
    };
    let counter_clockwise = counter_clockwise.unwrap_or(turn != Orientation::Clockwise);
    if !counter_clockwise {
        match loaded_range(cx, r) {
            Some(range) => cx.pool.reverse_live_in(range),
            None => cx.pool.reverse(start),
        }
    }
}

/// At the rightmost-lowest position X of a ring visiting it several times: every edge at X
/// points into the closed left half-plane, and the lowest one (turned furthest clockwise
/// from +x) bounds the outside. A counter-clockwise ring arrives along it, a clockwise one
/// leaves. Segments walked both ways (walls, cracks) have the outside on both sides or on
/// neither, so they are skipped: the lowest direction with more edges arriving than
/// leaving, or fewer, decides. `None` when there is none.
fn outermost_edge_arrives(cx: &Context, at: NodeId) -> Option<bool> {
    let pool = &cx.pool;
    let x = pool.p(at);
    let visits = || pool.ring(at).filter(move |&n| pool.p(n) == x);
    // net arrivals along the direction towards q
    let net = |q: Point| -> i64 {
        visits()
            .map(|n| {
                let along = |m: NodeId| orient2d(x, q, pool.p(m)) == Orientation::Collinear;
                i64::from(along(pool.prev(n))) - i64::from(along(pool.next(n)))
            })
            .sum()
    };
    let ends = visits().flat_map(|n| [pool.p(pool.prev(n)), pool.p(pool.next(n))]);
    lowest_net_arrives(x, ends, net)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{cleaned, turn_at_rightmost};
    use crate::triangulator::pipeline::Stages;

    /// The kept vertices of each live ring, from its least input vertex on.
    fn kept(cx: &Context) -> Vec<Vec<u32>> {
        let mut out = Vec::new();
        for ring in cx.rings.iter().filter(|r| r.alive) {
            let mut v: Vec<u32> = cx
                .pool
                .ring(ring.start)
                .map(|n| cx.pool.get(n).vertex)
                .collect();
            let least = (0..v.len()).min_by_key(|&k| v[k]).unwrap_or(0);
            v.rotate_left(least);
            out.push(v);
        }
        out
    }

    fn reasons(cx: &Context) -> Vec<(u32, DropReason)> {
        let mut d: Vec<_> = cx.dropped.iter().map(|d| (d.vertex, d.reason)).collect();
        d.sort_unstable_by_key(|&(v, _)| v);
        d
    }

    #[test]
    fn repeated_collinear_and_spike_vertices_are_dropped() {
        let vertices = [
            [0.0, 0.0],
            [2.0, 0.0], // collinear: on the bottom edge
            [4.0, 0.0],
            [4.0, 0.0], // repeated
            [4.0, 2.0],
            [6.0, 2.0], // the tip of a spike out and straight back
            [4.0, 2.0],
            [4.0, 4.0],
            [0.0, 4.0],
            [0.0, 0.0], // closing point
        ];
        let (cx, _) = cleaned(&vertices, &[0], false);
        // the square's corners are left (either copy of the closing point); (4, 2), where
        // the spike was, is straight once the spike is gone
        let ring = &kept(&cx)[0];
        let at = |v: u32| vertices[v as usize];
        let corners: Vec<[f64; 2]> = ring.iter().map(|&v| at(v)).collect();
        assert_eq!(corners.len(), 4, "{ring:?}");
        for corner in [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]] {
            assert!(corners.contains(&corner), "{corner:?} in {corners:?}");
        }
        let r = reasons(&cx);
        assert_eq!(r.len(), 6, "{r:?}");
        assert!(r.contains(&(1, DropReason::Collinear)), "{r:?}");
        assert!(r.contains(&(3, DropReason::Repeated)), "{r:?}");
        assert!(r.contains(&(5, DropReason::Spike)), "{r:?}");
        let closing = r
            .iter()
            .filter(|&&(v, d)| (v == 0 || v == 9) && d == DropReason::Repeated);
        assert_eq!(closing.count(), 1, "{r:?}");
    }

    /// Strict mode, spikes and rings of no area dropped: proving that no edge the filter
    /// took away crosses another, and searching the rest only once the sweep finds a
    /// crossing, gives what searching every pair of loaded edges first gives — the same
    /// rings, the same drops, or the same error naming the same edges.
    #[test]
    fn lost_edges_decide_as_the_full_search() {
        let mut below = crate::testing::random(0x5eed_1e55);
        let point = |below: &mut dyn FnMut(u64) -> u64| [below(100) as f64, below(100) as f64];
        let (mut short, mut full) = (Scratch::default(), Scratch::default());
        full.full_search = true;
        let mut outcomes = [0usize; 2];
        for case in 0..3000 {
            // a ring round a centre with random radii, spikes at some of its vertices (out
            // to a random point and back, crossing what lies between or not), maybe a
            // second ring, maybe two vertices swapped (a crossing the filter hides not)
            let m = 4 + below(20) as usize;
            let mut ring: Vec<[f64; 2]> = (0..m)
                .map(|k| {
                    let a = k as f64 / m as f64 * core::f64::consts::TAU;
                    let r = 10.0 + below(30) as f64;
                    [(50.0 + r * a.cos()).round(), (50.0 + r * a.sin()).round()]
                })
                .collect();
            let spikes = if case % 50 == 0 {
                20
            } else {
                1 + below(3) as usize
            };
            for _ in 0..spikes {
                let k = below(ring.len() as u64) as usize;
                let at = ring[k];
                ring.splice(k + 1..k + 1, [point(&mut below), at]);
            }
            if below(4) == 0 {
                let (i, j) = (below(ring.len() as u64), below(ring.len() as u64));
                ring.swap(i as usize, j as usize);
            }
            let mut rings = vec![ring];
            if below(3) == 0 {
                let (c, tip) = (point(&mut below), point(&mut below));
                rings.push(vec![c, [c[0] + 3.0, c[1]], [c[0], c[1] + 3.0], c, tip]);
            }
            let (vertices, starts) =
                crate::testing::flatten(&rings.iter().map(Vec::as_slice).collect::<Vec<_>>());
            let run = |s: &mut Scratch| {
                let mut cx = Context::default();
                cx.reset(false);
                crate::stages::load::load(&mut cx, &vertices, &starts).expect("finite");
                let result = clean(&mut cx, s, false);
                (result, kept(&cx), reasons(&cx))
            };
            let (a, b) = (run(&mut short), run(&mut full));
            assert_eq!(a.0, b.0, "case {case}: {rings:?}");
            if a.0.is_ok() {
                assert_eq!((&a.1, &a.2), (&b.1, &b.2), "case {case}: {rings:?}");
            }
            outcomes[usize::from(a.0.is_ok())] += 1;
        }
        // every way taken: lost edges proved apart (then a crossing the sweep found, the
        // full search after it), and the full search first (lost edges crossing, or many)
        let [apart, first, after] = short.searches;
        assert!(
            apart > 300 && first > 300 && after > 30,
            "{:?}",
            short.searches
        );
        assert!(outcomes.iter().all(|&n| n > 300), "{outcomes:?}");
    }

    #[test]
    fn a_ring_of_no_area_is_dropped() {
        let vertices = [
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [0.0, 4.0],
            [1.0, 1.0],
            [2.0, 2.0],
            [3.0, 3.0],
        ];
        let (cx, _) = cleaned(&vertices, &[0, 4], false);
        assert_eq!(kept(&cx), vec![vec![0, 1, 2, 3]]);
        assert!(reasons(&cx)
            .iter()
            .any(|&(_, r)| r == DropReason::DegenerateRing));
    }

    #[test]
    fn every_ring_comes_out_counter_clockwise() {
        // an outer ring given clockwise, a hole given counter-clockwise
        let vertices = [
            [0.0, 0.0],
            [0.0, 4.0],
            [4.0, 4.0],
            [4.0, 0.0],
            [1.0, 1.0],
            [2.0, 1.0],
            [1.0, 2.0],
        ];
        let (cx, _) = cleaned(&vertices, &[0, 4], false);
        for ring in cx.rings.iter().filter(|r| r.alive) {
            assert_eq!(turn_at_rightmost(&cx, ring), Orientation::CounterClockwise);
            let b = cx.pool.p(ring.rightmost);
            // the rightmost vertex, ties by lowest y
            assert!(cx.pool.ring(ring.start).all(|m| {
                let q = cx.pool.p(m);
                q.x < b.x || (q.x == b.x && q.y >= b.y)
            }));
        }
    }

    #[test]
    fn a_vertex_on_another_rings_edge_splits_it() {
        // a hole whose corner (4, 2) lies inside the outer ring's right edge
        let vertices = [
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [0.0, 4.0],
            [4.0, 2.0],
            [2.0, 3.0],
            [2.0, 1.0],
        ];
        let (cx, _) = cleaned(&vertices, &[0, 4], false);
        let outer = kept(&cx)[0].clone();
        // the outer ring now passes through the hole's vertex 4 between 1 and 2
        assert_eq!(outer, vec![0, 1, 4, 2, 3]);
        // and both nodes at (4, 2) are listed as sharing a position, with one index
        let at: Vec<NodeId> = cx
            .shared
            .iter()
            .copied()
            .filter(|&n| cx.pool.p(n) == Point::new(4.0, 2.0))
            .collect();
        assert_eq!(at.len(), 2);
        assert!(at.iter().all(|&n| cx.pool.get(n).vertex == 4));
    }

    #[test]
    fn crossing_edges_are_refused_in_strict_mode_and_listed_in_lenient() {
        let bow_tie = [[0.0, 0.0], [4.0, 4.0], [4.0, 0.0], [0.0, 4.0]];
        let mut cx = Context::default();
        cx.reset(false);
        let mut s = Scratch::default();
        crate::stages::load::load(&mut cx, &bow_tie, &[0]).unwrap();
        let err = clean(&mut cx, &mut s, false);
        assert!(
            matches!(
                err,
                Err(Error::EdgesCross {
                    ring_a: 0,
                    ring_b: 0,
                    ..
                })
            ),
            "{err:?}"
        );
        let (cx, _) = cleaned(&bow_tie, &[0], true);
        assert_eq!(cx.crossings.len(), 1);
        assert!(cx.repairs.iter().any(|r| r.kind == RepairKind::EdgesCross));
    }

    /// Reading the loaded range finds the node the walk along the links finds, and
    /// reversing a ring off the range keeps it whole: random rings on a small grid
    /// (repeats, spikes, touching and crossing rings, edges split where a vertex touches
    /// them, lobes, several nodes at the rightmost position), strict and lenient.
    #[test]
    fn the_rightmost_node_read_off_the_pool_is_the_walks() {
        let mut random = crate::testing::random(0x5eed_0f71_7e00);
        let (mut ranged, mut fell_back) = (0, 0);
        for case in 0..3000 {
            let rings: Vec<Vec<[f64; 2]>> = (0..1 + random(3))
                .map(|_| {
                    let len = 3 + random(7);
                    (0..len)
                        .map(|_| [random(5) as f64, random(5) as f64])
                        .collect()
                })
                .collect();
            let refs: Vec<&[[f64; 2]]> = rings.iter().map(Vec::as_slice).collect();
            let (vertices, starts) = crate::testing::flatten(&refs);
            for lenient in [false, true] {
                // the pipeline up to `orient_rings` (see `pipeline::load_and_clean`)
                let mut cx = Context::default();
                cx.reset(lenient);
                let mut st = Stages::default();
                if crate::stages::load::load(&mut cx, &vertices, &starts).is_err()
                    || !matches!(clean(&mut cx, &mut st.clean, false), Ok(true))
                {
                    continue;
                }
                if lenient && cx.crossings.is_empty() {
                    crate::stages::lobes::split(&mut cx, &mut st.lobes);
                }
                let alive: Vec<usize> =
                    (0..cx.rings.len()).filter(|&r| cx.rings[r].alive).collect();
                let mut members: Vec<Vec<NodeId>> = Vec::new();
                for &r in &alive {
                    let start = cx.rings[r].start;
                    let (mut best, mut b, mut visits) = (start, cx.pool.p(start), 0);
                    for n in cx.pool.ring(start) {
                        let p = cx.pool.p(n);
                        if p.x > b.x || (p.x == b.x && p.y < b.y) {
                            (best, b, visits) = (n, p, 1);
                        } else if p == b {
                            visits += 1;
                        }
                    }
                    assert_eq!(rightmost(&cx, r), (best, visits), "case {case}: {rings:?}");
                    match loaded_range(&cx, r) {
                        Some(_) if visits == 1 => ranged += 1,
                        _ => fell_back += 1,
                    }
                    let mut nodes: Vec<NodeId> = cx.pool.ring(start).collect();
                    nodes.sort_unstable();
                    members.push(nodes);
                }
                // orienting (reversing some rings off the pool) keeps every ring's nodes,
                // linked both ways
                orient_rings(&mut cx, &mut st.clean);
                for (&r, before) in alive.iter().zip(&members) {
                    let start = cx.rings[r].start;
                    // (bounded: a ring broken by a wrong reversal may never come back)
                    let bound = cx.pool.len() + 1;
                    let mut nodes: Vec<NodeId> = cx.pool.ring(start).take(bound).collect();
                    assert!(nodes.len() < bound, "case {case}: a ring lost its way");
                    for &n in &nodes {
                        assert_eq!(cx.pool.prev(cx.pool.next(n)), n, "case {case}: {rings:?}");
                    }
                    nodes.sort_unstable();
                    assert_eq!(&nodes, before, "case {case}: {rings:?}");
                }
            }
        }
        assert!(
            ranged > 1000 && fell_back > 100,
            "{ranged} read off, {fell_back} walked"
        );
    }
}
