//! Stage 3, *nest*: which rings are outer boundaries and which are holes.
//!
//! `Nesting::Auto`: the containment depth of every ring decides — even: outer boundary,
//! odd: hole. An island inside a hole is a polygon of its own, to any depth. The depth of
//! ring B is the number of rings containing it, computed at one vertex V of B as a winding
//! number: with every ring counter-clockwise (the clean stage made them so), the signed
//! crossings of a ray from V with all other rings' edges count the rings around V. Rings
//! passing through V (touching B there) are decided locally instead, by whether B's corner
//! at V lies inside theirs. The edges come from a grid index; the ray runs along the grid
//! row or column with the fewest cells to the border, so a ring costs those cells, not the
//! whole input. (A few dozen edges are only listed, and every ray meets all of them.)
//!
//! Usually it costs less: rings go by descending rightmost x, and when the first edge the
//! ray from B's rightmost vertex meets is unambiguous (met inside, alone, no ring through
//! V, no crossings), B's depth is that edge's ring's depth, plus one if V lies on its inner
//! side. The ray then stops at that edge, a cell or two away. And a few small rings that
//! meet nowhere (a glyph), or only at points (a hole touching its polygon's corner), skip
//! the grid: each one's depth is counted directly, from the others' winding numbers
//! around one of its vertices that lies on no other ring. More rings, each with such a
//! vertex (they may also lie along each other, holes along their polygon's edge, or touch
//! themselves where each winds once round the others' vertices), are counted in one pass
//! along them all (`swept_depths`): with those vertices sorted by height, each edge meets
//! the ones whose height it spans.
//!
//! `Nesting::FirstIsOuter` (earcut's convention) takes ring 0 as the outer boundary and the
//! rest as its holes; strict mode checks that this is true.
//!
//! Finally holes are turned clockwise, so that in every ring the polygon's interior lies to
//! the left of each edge — the convention `bridge` and `clip` rely on.

use crate::context::{Context, LoadedRing};
use crate::geom::{cmp_around, cmp_xy, on_segment, orient2d, Orientation, Point};
use crate::geom::{compare_hits, corner_contains, on_ray, ray_crossing as crossing};
use crate::structures::NodeId;
use crate::{Error, Nesting};
use core::cmp::Ordering;

/// Scratch buffers of the nest stage, kept between calls.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// Rings by descending rightmost x.
    ring_order: Vec<u32>,
    /// Per ring: whether its depth is known yet.
    depth_known: Vec<bool>,
    /// The winding number of each ring touching a vertex, away from it.
    touch_winding: Vec<i64>,
    /// The rings passing through a position.
    probe_rings: Vec<u32>,
    /// Per ring, its place among the rings through the position being decided, or
    /// `NO_SLOT`.
    ring_slot: Vec<u32>,
    /// The edges through the position being decided, of the rings there.
    hub_edges: Vec<HubEdge>,
    /// Edges met along the ray in along lists (each counted once).
    along_seen: Vec<NodeId>,
    /// Ring pairs `(b, q)` where ring b lies on ring q's boundary, inside it.
    overlaps: Vec<(u32, u32)>,
    /// Edges that cleaning dropped, with their rings.
    dropped_edges: Vec<RingEdge>,
    /// The rings still to decide at the position being looked at.
    order: Vec<u32>,
    /// [`swept_depths`]: each ring's test point (y, x, ring) by y, and each ring's sum.
    probes: Vec<(f64, f64, u32)>,
    sums: Vec<i64>,
    /// [`swept_depths`] where a ring touches itself: the winding of the ring being walked
    /// round each ring's test point, and the rings whose winding it changed.
    ring_sums: Vec<i64>,
    wound: Vec<u32>,
    /// Tests: never count depths by [`swept_depths`] (to exercise the grid), and whether
    /// it counted them last.
    #[cfg(test)]
    no_sweep: bool,
    #[cfg(test)]
    swept: bool,
    /// The rays of `check_shared_positions`.
    touch_nets: Vec<(Point, i32)>,
    /// [`decide_hub`]: the corners at the hub (start direction, end direction, ring), the
    /// ends of the corners in angular order (direction, corner, whether it starts there),
    /// and how many corners hold each one.
    hub_corners: Vec<(Point, Point, u32)>,
    hub_ends: Vec<(Point, u32, bool)>,
    hub_inner: Vec<u32>,
}

/// An edge through the position being decided, of a ring listed there: the ring's place
/// in the list, and the edge's ends turned by the ray (see `Ray::turn`).
#[derive(Clone, Copy, Debug)]
struct HubEdge {
    slot: u32,
    from: Point,
    to: Point,
}

/// An edge of ring `ring` from `a` to `b`.
#[derive(Clone, Copy, Debug)]
struct RingEdge {
    ring: u32,
    a: Point,
    b: Point,
}

/// Decides every live ring's depth and turns holes clockwise.
pub(crate) fn nest(cx: &mut Context, s: &mut Scratch, nesting: Nesting) -> Result<(), Error> {
    let alive = cx.rings.iter().filter(|r| r.alive).count();
    match nesting {
        Nesting::Auto if alive > 1 => compute_depths(cx, s)?,
        Nesting::Auto => {}
        // Lobes of one ring have no ring number of their own to give them a role:
        // containment decides, which for a valid input is what the roles would say.
        Nesting::FirstIsOuter if cx.split_lobes => compute_depths(cx, s)?,
        Nesting::FirstIsOuter => first_is_outer(cx, s)?,
    }
    let mut reversed = false;
    for r in 0..cx.rings.len() {
        let ring = cx.rings[r];
        if ring.alive && ring.depth % 2 == 1 {
            cx.pool.reverse(ring.start);
            reversed = true;
        }
    }
    if reversed && cx.edge_index.is_current() {
        // the edge grid `compute_depths` built stays of use to `bridge`: in a reversed
        // ring, the edge listed as n (to its old successor) now starts at that node
        let (pool, rings) = (&cx.pool, &cx.rings);
        cx.edge_index.rename(|n| {
            let node = pool.get(n);
            if rings[node.ring as usize].depth % 2 == 1 {
                node.prev
            } else {
                n
            }
        });
    }
    if !cx.lenient {
        check_shared_positions(cx, s)
    } else {
        // Lenient mode: rings crossing at a shared vertex overlap there as rings lying on
        // each other do (containment cannot order them), and the triangulator reads them
        // by even–odd too (where no edges cross, so that it adds no vertex)
        let read_by_containment = nesting == Nesting::Auto && cx.crossings.is_empty();
        if read_by_containment && !cx.rings_overlap && check_shared_positions(cx, s).is_err() {
            cx.rings_overlap = true;
        }
        Ok(())
    }
}

/// Around every position several nodes share, the polygon's winding number
/// (outer rings counter-clockwise, holes clockwise by now) may take only two consecutive
/// values in the sectors between the edges there. Rings that cross each other at a shared
/// vertex (an X of two rings, or of one ring's two visits) give three; the sweep sees no
/// crossing there, since neither edge passes through the other's interior.
fn check_shared_positions(cx: &mut Context, s: &mut Scratch) -> Result<(), Error> {
    let mut rays = core::mem::take(&mut s.touch_nets);
    let mut result = Ok(());
    let mut i = 0;
    while i < cx.shared.len() {
        let o = cx.pool.p(cx.shared[i]);
        let j = cx.same_position_end(i);
        // each edge at o, as the direction away from o: +1 leaving, −1 arriving
        rays.clear();
        for &n in &cx.shared[i..j] {
            let node = cx.pool.get(n);
            if node.removed || !cx.rings[node.ring as usize].alive {
                continue;
            }
            rays.push((cx.pool.p(node.next), 1));
            rays.push((cx.pool.p(node.prev), -1));
        }
        rays.sort_unstable_by(|a, b| cmp_around(o, a.0, b.0));
        // the winding number of each sector relative to the one before the first ray;
        // rays along one direction bound no sector between them
        let (mut w, mut lo, mut hi) = (0i64, 0i64, 0i64);
        for (k, &(d, step)) in rays.iter().enumerate() {
            w += i64::from(step);
            let sector_ends =
                !matches!(rays.get(k + 1), Some(&(e, _)) if cmp_around(o, d, e).is_eq());
            if sector_ends {
                (lo, hi) = (lo.min(w), hi.max(w));
            }
        }
        if hi - lo > 1 {
            let (a, b) = (cx.pool.get(cx.shared[i]), cx.pool.get(cx.shared[j - 1]));
            result = Err(Error::RingsCrossAtVertex {
                ring_a: cx.rings[a.ring as usize].input as usize,
                ring_b: cx.rings[b.ring as usize].input as usize,
                vertex: a.vertex as usize,
            });
            break;
        }
        i = j;
    }
    s.touch_nets = rays;
    result
}

/// earcut's convention; in strict mode, checked against the computed depths.
fn first_is_outer(cx: &mut Context, s: &mut Scratch) -> Result<(), Error> {
    let outer_alive = cx.rings.first().is_some_and(|r| r.alive && r.input == 0);
    if !cx.lenient && cx.rings.len() > 1 {
        compute_depths(cx, s)?;
        for r in 0..cx.rings.len() {
            let ring = cx.rings[r];
            let expected = u32::from(r != 0);
            if ring.alive && (ring.depth != expected || !outer_alive) {
                let ring = if r == 0 { 1 } else { ring.input as usize };
                return Err(Error::HoleOutside { ring });
            }
        }
    }
    for r in 0..cx.rings.len() {
        cx.rings[r].depth = u32::from(r != 0 || !outer_alive);
    }
    if !outer_alive {
        // no outer boundary: nothing to triangulate (earcut returns nothing too)
        for r in 0..cx.rings.len() {
            cx.skip_ring(r);
        }
    }
    Ok(())
}

/// Fills every live ring's `depth` with the number of rings containing it.
///
/// Rings go by descending rightmost x: the ring whose depth [`depth_from_nearest`] builds
/// on reaches further right than the ring asking, so it is done by then.
fn compute_depths(cx: &mut Context, s: &mut Scratch) -> Result<(), Error> {
    if direct_depths(cx) || swept_depths(cx, s) {
        return Ok(());
    }
    cx.edge_index
        .rebuild_or_list(&cx.pool, &cx.rings, LISTED_EDGES);
    s.ring_slot.clear();
    s.ring_slot.resize(cx.rings.len(), NO_SLOT);
    s.depth_known.clear();
    s.depth_known.resize(cx.rings.len(), false);
    s.overlaps.clear();
    let mut order = core::mem::take(&mut s.ring_order);
    order.clear();
    order.extend((0..cx.rings.len() as u32).filter(|&r| cx.rings[r as usize].alive));
    let (pool, rings) = (&cx.pool, &cx.rings);
    let x = |r: u32| pool.p(rings[r as usize].rightmost).x;
    order.sort_unstable_by(|&a, &b| x(b).total_cmp(&x(a)).then(a.cmp(&b)));
    if !cx.lenient && cx.crossings.is_empty() {
        decide_hubs(cx, s);
    }
    for &r in &order {
        if s.depth_known[r as usize] {
            continue; // decided at a hub
        }
        cx.rings[r as usize].depth = depth_of(cx, s, r as usize);
        s.depth_known[r as usize] = true;
    }
    s.ring_order = order;
    // b lies on q's boundary, inside q: valid only when q bounds b's region from outside
    // and b bounds a hole in q's region (or the other way round), so that their windings
    // cancel. Equal depths (the same ring twice, each inside the other, say) double it.
    let rings = &cx.rings;
    let overlapping = s
        .overlaps
        .iter()
        .find(|&&(b, q)| rings[b as usize].depth != rings[q as usize].depth + 1);
    match overlapping {
        Some(&(b, _)) if !cx.lenient => {
            let ring = cx.rings[b as usize];
            Err(Error::RingsOverlap {
                ring: ring.input as usize,
                vertex: cx.pool.get(ring.rightmost).vertex as usize,
            })
        }
        // lenient mode goes on, and says where two rings double each other (equal depths,
        // each inside the other): the triangulator may try again another way
        Some(_) => {
            let doubled = |&(b, q): &(u32, u32)| rings[b as usize].depth == rings[q as usize].depth;
            cx.rings_doubled = s.overlaps.iter().any(doubled);
            cx.rings_overlap = true;
            Ok(())
        }
        None => Ok(()),
    }
}

/// Up to this many edges, [`compute_depths`] only lists them, without a grid: every
/// winding number and ray scans them all, which costs less than building the grid and
/// walking its cells (measured on earcut's fixtures of rings lying along each other).
const LISTED_EDGES: usize = 64;

/// Strict mode, no crossings: the rings through each position where more than
/// [`FEW_AT_A_HUB`] nodes lie, decided there all at once (see [`decide_hub`]).
fn decide_hubs(cx: &mut Context, s: &mut Scratch) {
    let mut i = 0;
    while i < cx.shared.len() {
        let end = cx.same_position_end(i);
        if end - i > FEW_AT_A_HUB {
            decide_hub(cx, s, i, end);
        }
        i = end;
    }
}

/// The depths of the rings through a hub H (the nodes `cx.shared[from..to]`), when each
/// passes it once and no two of their edges there point the same way; else nothing.
///
/// Valid rings do not cross, so near H each ring's corner there (its interior, swept
/// counter-clockwise from its edge out to its edge in: every ring is counter-clockwise
/// here) and another's are apart or one holds the other. A ring through H contains ring
/// q exactly when its corner holds q's; a ring not through H contains q exactly when it
/// contains H, and counting those is one winding number. Sorting the corners' ends round
/// H and sweeping them once counts, for every corner, the corners holding it: those open
/// where it starts. Rings deciding each other this way cost time in their number once,
/// where [`depth_of`] would look at all of them for each (a pinwheel's wedges, a pie's
/// slices). Input whose corners cross is refused later by `check_shared_positions`
/// whatever depths it gets here.
fn decide_hub(cx: &mut Context, s: &mut Scratch, from: usize, to: usize) {
    let pool = &cx.pool;
    let h = pool.p(cx.shared[from]);
    let mut corners = core::mem::take(&mut s.hub_corners);
    let mut ends = core::mem::take(&mut s.hub_ends);
    let mut inner = core::mem::take(&mut s.hub_inner);
    let mut order = core::mem::take(&mut s.order);
    corners.clear();
    ends.clear();
    order.clear();
    let mut once = true;
    for &m in &cx.shared[from..to] {
        let node = pool.get(m);
        let ring = node.ring as usize;
        // (rings already decided at another hub count here too: they may hold the others)
        if node.removed || !cx.rings[ring].alive {
            continue;
        }
        // each ring once (its slot marks it)
        once &= s.ring_slot[ring] == NO_SLOT;
        s.ring_slot[ring] = corners.len() as u32;
        corners.push((pool.p(node.next), pool.p(node.prev), ring as u32));
        order.push(ring as u32);
    }
    for (k, &(out, into, _)) in corners.iter().enumerate() {
        ends.push((out, k as u32, true));
        ends.push((into, k as u32, false));
    }
    ends.sort_unstable_by(|a, b| cmp_around(h, a.0, b.0));
    let apart = ends
        .windows(2)
        .all(|w| cmp_around(h, w[0].0, w[1].0) != Ordering::Equal);
    if once && apart && !corners.is_empty() {
        // the rings not through H around it (the hub's own edges count apart)
        let mut beyond = core::mem::take(&mut s.touch_winding);
        beyond.clear();
        beyond.resize(order.len(), 0);
        let mut along = core::mem::take(&mut s.along_seen);
        let b = order[0] as usize;
        let (winding, _) = winding_number(cx, b, h, &mut beyond, &s.ring_slot, &mut along);
        s.along_seen = along;
        s.touch_winding = beyond;
        // the corners holding the ray's start (+x) are open from the beginning
        let mut open = (corners.iter())
            .filter(|&&(out, into, _)| cmp_around(h, out, into) == Ordering::Greater)
            .count() as u32;
        inner.clear();
        inner.resize(corners.len(), 0);
        for &(_, k, starts) in &ends {
            if starts {
                inner[k as usize] = open;
                open += 1;
            } else {
                open = open.saturating_sub(1);
            }
        }
        for (k, &(_, _, ring)) in corners.iter().enumerate() {
            cx.rings[ring as usize].depth = winding.max(0) as u32 + inner[k];
            s.depth_known[ring as usize] = true;
        }
    }
    clear_slots(&order, &mut s.ring_slot);
    order.clear();
    (s.hub_corners, s.hub_ends, s.hub_inner, s.order) = (corners, ends, inner, order);
}

/// [`direct_depths`] decides rings that meet at most at points while their number times
/// their edges is at most this: a walk over every edge per ring then costs less than
/// listing the edges in the grid (a glyph: an outer ring and a hole or two).
const DIRECT_WORK: usize = 512;

/// Where no two edges cross, the rings meet only at points ([`meet_at_points`]) and they
/// are few and small (see [`DIRECT_WORK`]): each ring's depth, counted directly as the
/// rings whose winding number around one of its nodes is not zero, a node at no shared
/// position. Such a node lies on no other ring (`clean` split every edge through a
/// vertex, which makes a shared position there), so its winding numbers are exact; and
/// rings that only touch have disjoint insides or one inside the other, so it decides
/// for the whole ring. The node is the ring's rightmost, as [`depth_of`] decides; strict
/// mode may take any other, since rings crossing at a shared vertex, which it could tell
/// apart, are refused anyway (by `check_shared_positions`, or as a hole outside). False,
/// deciding nothing, where a ring has no such node, or the rings are many.
fn direct_depths(cx: &mut Context) -> bool {
    if !cx.crossings.is_empty() {
        return false;
    }
    let (mut alive, mut edges) = (0, 0);
    for ring in cx.rings.iter().filter(|r| r.alive) {
        (alive, edges) = (alive + 1, edges + ring.len as usize);
    }
    // (the size first: it is cheaper to learn than where the rings meet)
    if alive * edges > DIRECT_WORK || !meet_at_points(cx) {
        return false;
    }
    for b in 0..cx.rings.len() {
        if !cx.rings[b].alive {
            continue;
        }
        let pool = &cx.pool;
        let Some(v) = test_node(cx, cx.rings[b].rightmost) else {
            return false;
        };
        let v = pool.p(v);
        let around = |ring: &crate::context::Ring| {
            let winding: i64 = pool
                .ring(ring.start)
                .map(|n| crossing(pool.p(n), pool.p(pool.next(n)), v))
                .sum();
            winding != 0
        };
        let depth = (cx.rings.iter().enumerate())
            .filter(|&(r, ring)| r != b && ring.alive && around(ring))
            .count();
        cx.rings[b].depth = depth as u32;
    }
    true
}

/// The node of a ring whose winding numbers decide its depth where rings meet only at
/// points ([`direct_depths`], [`swept_depths`]): its rightmost node `first`, or (strict
/// mode) the first after it at no shared position, which lies on no other ring; `None`
/// where there is none (lenient mode: where the rightmost is shared).
fn test_node(cx: &Context, first: NodeId) -> Option<NodeId> {
    let off = |n: NodeId| nodes_at(cx, cx.pool.p(n)) == 0;
    if cx.shared.is_empty() || off(first) {
        Some(first)
    } else if cx.lenient {
        None
    } else {
        cx.pool.ring(first).find(|&n| off(n))
    }
}

/// [`direct_depths`] for more rings and edges, in strict mode: every ring turns
/// counter-clockwise (as `clean` left it), and one that does not touch itself is a simple
/// closed curve, whose winding number round a point on no ring is 1 inside and 0 outside;
/// one that touches itself is the same where its input is valid (its lobes turn one way
/// and it winds once), which its winding round every test node, 0 or 1, must confirm. So
/// the depth of ring b, the number of rings round its test node (chosen as
/// [`direct_depths`] does), is the sum of the winding numbers of all the other rings there:
/// the signed crossings of the ray from it with their edges. Rings may meet at points or
/// lie along each other (holes along their outer ring, walls between holes): no two
/// cross, so each lies on one side of every other, the side of its test node, which lies
/// on no other ring. (Where rings cross at a shared vertex, strict mode refuses the input
/// after nesting, by `check_shared_positions`, whatever the depths; a ring with every
/// node on other rings has no test node and goes to the grid, which decides rings lying
/// wholly on others.)
///
/// One pass along every ring counts them for every test node at once: with the test
/// nodes sorted by height, a cursor follows the ring's height, and the nodes it passes
/// over along an edge are those whose rays may cross the edge. False, deciding nothing,
/// where that does not apply, or when the edges pass over more test nodes than a few per
/// edge and a hundred per ring (tall edges over many rings: the grid's rays cost less).
fn swept_depths(cx: &mut Context, s: &mut Scratch) -> bool {
    #[cfg(test)]
    {
        s.swept = false;
        if s.no_sweep {
            return false;
        }
    }
    if cx.lenient || !cx.crossings.is_empty() {
        return false;
    }
    // A ring touching itself may wind twice round a point, or its lobe may wind against
    // the way its rightmost vertex says: each ring's winding round each test node is then
    // kept apart, and any but 0 or 1 leaves the depths to the grid.
    let apart = touches_itself(cx);
    let pool = &cx.pool;
    s.probes.clear();
    let mut edges = 0;
    for (b, ring) in cx.rings.iter().enumerate().filter(|(_, r)| r.alive) {
        edges += ring.len as usize;
        let Some(v) = test_node(cx, ring.rightmost) else {
            return false;
        };
        let p = pool.p(v);
        s.probes.push((p.y, p.x, b as u32));
    }
    s.probes
        .sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.2.cmp(&b.2)));
    s.sums.clear();
    s.sums.resize(cx.rings.len(), 0);
    if apart {
        s.ring_sums.clear();
        s.ring_sums.resize(cx.rings.len(), 0);
        s.wound.clear();
    }
    // (a grid ray costs a few thousand instructions, a test node passed over a dozen)
    let budget = 4 * edges + 128 * s.probes.len() + 64;
    // (two copies of the walk: keeping windings apart costs the others nothing)
    let counted = if apart {
        count_windings::<true>(cx, s, budget)
    } else {
        count_windings::<false>(cx, s, budget)
    };
    if !counted {
        return false;
    }
    for (b, ring) in cx.rings.iter_mut().enumerate() {
        if ring.alive {
            ring.depth = s.sums[b].unsigned_abs() as u32;
        }
    }
    #[cfg(test)]
    {
        s.swept = true;
    }
    true
}

/// [`swept_depths`]'s pass along every ring: each test node's sum of the windings of the
/// other rings round it (`s.sums`), with `APART` each ring's winding round each node
/// first summed on its own and required to be 0 or 1. False where that fails, or the
/// edges pass over more than `budget` test nodes.
fn count_windings<const APART: bool>(cx: &Context, s: &mut Scratch, mut budget: usize) -> bool {
    let pool = &cx.pool;
    let Scratch {
        probes,
        sums,
        ring_sums,
        wound,
        ..
    } = s;
    for (q, ring) in cx.rings.iter().enumerate().filter(|(_, r)| r.alive) {
        // the cursor: the test nodes below the current vertex's height
        let mut at = probes.partition_point(|t| t.0 < pool.p(ring.start).y);
        for n in pool.ring(ring.start) {
            let (a, b) = (pool.p(n), pool.p(pool.next(n)));
            // upwards, the nodes at heights a.y <= y < b.y, whose rays the edge crosses
            // where they lie left of it; downwards, those at b.y <= y < a.y, where they lie
            // right of the edge's direction (`ray_crossing`'s half-open rule)
            let (from, up) = (at, a.y < b.y);
            if up {
                while at < probes.len() && probes[at].0 < b.y {
                    at += 1;
                }
            } else {
                while at > 0 && probes[at - 1].0 >= b.y {
                    at -= 1;
                }
            }
            let (first, end) = if up { (from, at) } else { (at, from) };
            if end - first > budget {
                return false;
            }
            budget -= end - first;
            let right = if a.x < b.x { b.x } else { a.x };
            for &(y, x, r) in &probes[first..end] {
                if x > right || r as usize == q {
                    continue;
                }
                let step = match orient2d(a, b, Point::new(x, y)) {
                    Orientation::CounterClockwise if up => 1,
                    Orientation::Clockwise if !up => -1,
                    _ => continue,
                };
                let r = r as usize;
                if !APART {
                    sums[r] += step;
                } else {
                    if ring_sums[r] == 0 {
                        wound.push(r as u32);
                    }
                    ring_sums[r] += step;
                }
            }
        }
        // (a ring listed twice counts once: its sum is 0 the second time)
        for r in wound.drain(..) {
            let w = core::mem::take(&mut ring_sums[r as usize]);
            if !(0..=1).contains(&w) {
                return false;
            }
            sums[r as usize] += w;
        }
    }
    true
}

/// Whether some ring passes a position twice (touches itself there).
fn touches_itself(cx: &Context) -> bool {
    let pool = &cx.pool;
    any_pair_at_a_position(cx, |n, m| pool.get(n).ring == pool.get(m).ring)
}

/// Whether the rings meet, if at all, only at isolated points: no two rings (nor two
/// stretches of one) share an edge, lying along each other (`clean` split overlapping
/// edges where they end, so such edges have both ends in common). Then two rings that do
/// not cross at a shared point lie each on one side of the other, whether or not they
/// touch themselves too.
fn meet_at_points(cx: &Context) -> bool {
    let pool = &cx.pool;
    !any_pair_at_a_position(cx, |n, m| {
        let ahead = pool.p(pool.next(n));
        let along = [pool.next(m), pool.prev(m)].map(|e| pool.p(e));
        // (and m's edge ahead along n's edge behind; n's ahead along m's behind is
        // `along`)
        along.contains(&ahead) || pool.p(pool.prev(n)) == pool.p(pool.next(m))
    })
}

/// Whether `test` holds for two nodes at one shared position (each pair once).
fn any_pair_at_a_position(cx: &Context, test: impl Fn(NodeId, NodeId) -> bool) -> bool {
    let mut i = 0;
    while i < cx.shared.len() {
        let j = cx.same_position_end(i);
        let group = &cx.shared[i..j];
        for (k, &n) in group.iter().enumerate() {
            if group[k + 1..].iter().any(|&m| test(n, m)) {
                return true;
            }
        }
        i = j;
    }
    false
}

/// The number of rings containing ring `b`, decided at its rightmost vertex — or, for the
/// rings along both of b's edges there, at the next vertex of b that decides them, or at
/// one of b's input vertices that cleaning dropped.
fn depth_of(cx: &mut Context, s: &mut Scratch, b: usize) -> u32 {
    let first = cx.rings[b].rightmost;
    if nodes_at(cx, cx.pool.p(first)) > FEW_AT_A_HUB {
        // Many rings meet there, and deciding b there costs time in their number, for
        // each of them (petals or slices round one point, say): a vertex of b where few
        // meet decides as well, if one comes soon (any vertex does, unless b's edges
        // there run along the rings through it).
        let mut v = cx.pool.next(first);
        for _ in 0..HUB_DETOUR {
            if v == first {
                break;
            }
            if nodes_at(cx, cx.pool.p(v)) <= FEW_AT_A_HUB {
                if let Some(depth) = depth_at(cx, s, b, v) {
                    return depth;
                }
            }
            v = cx.pool.next(v);
        }
    }
    let mut depth = decide_at(cx, s, b, first);
    // A ring left open at the rightmost vertex is decided at the next vertex of b that
    // can, each decision kept (b a lobe lying on another ring, with a third ring through
    // some of its vertices, decides the third ring elsewhere than the second).
    let mut v = cx.pool.next(first);
    while v != first && !s.order.is_empty() {
        depth += decide_open_at(cx, s, b, v, Probe::Clear);
        v = cx.pool.next(v);
    }
    // Rings no vertex decided with a clear probe: at the first vertex with an edge off them.
    let mut v = first;
    while !s.order.is_empty() {
        depth += decide_open_at(cx, s, b, v, Probe::OffRing);
        v = cx.pool.next(v);
        if v == first {
            break;
        }
    }
    if s.order.is_empty() {
        depth
    } else {
        depth + depth_by_dropped(cx, s, b)
    }
}

/// How many of the rings still open (`s.order`) contain ring `b`, every corner of which
/// lies on them with both its edges: each is decided at the first of b's input vertices
/// off it, the ones cleaning dropped included (the tip of a zero-width spike, say, may
/// leave a ring that b otherwise lies on). "Off" counts the edges cleaning dropped, as the
/// oracle does. An open ring holding all of them has b's boundary on its own, with b's
/// corners inside its corners: it contains b ([`compute_depths`] checks that their depths
/// then differ by one, from `s.overlaps`).
fn depth_by_dropped(cx: &mut Context, s: &mut Scratch, b: usize) -> u32 {
    let mut depth = 0;
    // the edges of the open rings that cleaning dropped: each has a dropped end
    let mut dropped = core::mem::take(&mut s.dropped_edges);
    dropped.clear();
    for &q in &s.order {
        let block = loaded(cx, q as usize);
        let node = |i: usize| &cx.pool.nodes[i];
        for i in block.clone() {
            let after = if i == *block.end() {
                *block.start()
            } else {
                i + 1
            };
            if node(i).removed || node(after).removed {
                dropped.push(RingEdge {
                    ring: q,
                    a: node(i).p,
                    b: node(after).p,
                });
            }
        }
    }
    let mut counts = core::mem::take(&mut s.touch_winding);
    let mut through = core::mem::take(&mut s.probe_rings);
    for i in loaded(cx, b) {
        if s.order.is_empty() {
            break;
        }
        let p = cx.pool.nodes[i].p;
        let mut slot = core::mem::take(&mut s.ring_slot);
        // (a dropped vertex: no edge was split there, so the grid's)
        rings_through(cx, b, p, false, &mut through, &mut slot);
        clear_slots(&through, &mut slot);
        through.sort_unstable();
        counts.clear();
        counts.resize(s.order.len(), 0);
        set_slots(&s.order, &mut slot);
        let mut along = core::mem::take(&mut s.along_seen);
        winding_number(cx, b, p, &mut counts, &slot, &mut along);
        s.along_seen = along;
        clear_slots(&s.order, &mut slot);
        s.ring_slot = slot;
        let mut k = 0;
        s.order.retain(|q| {
            let on_q = through.binary_search(q).is_ok()
                || dropped
                    .iter()
                    .any(|e| e.ring == *q && on_segment(e.a, e.b, p));
            depth += u32::from(!on_q && counts[k] > 0);
            k += 1;
            on_q
        });
    }
    s.probe_rings = through;
    s.touch_winding = counts;
    s.dropped_edges = dropped;
    // Two rings with one boundary each lie on the other, and both count the other: strict
    // mode refuses that below (the oracle, too, sees the region covered twice). Lenient
    // mode makes the one decided first the inside one, so that they cancel, as the
    // even-odd rule has it; that is also what the input means where the two are lobes
    // of rings cut by `lobes` (the same lobe of two figure eights).
    if cx.lenient {
        let overlaps = &s.overlaps;
        let before = s.order.len();
        s.order.retain(|&q| !overlaps.contains(&(q, b as u32)));
        cx.rings_overlap |= s.order.len() < before;
    }
    for &q in &s.order {
        s.overlaps.push((b as u32, q));
    }
    depth + s.order.len() as u32
}

/// Past this many nodes at a ring's rightmost position, [`depth_of`] looks for a vertex
/// of the ring where at most this many lie, and decides there.
const FEW_AT_A_HUB: usize = 8;

/// How many vertices of the ring [`depth_of`] looks at for one where few nodes lie.
const HUB_DETOUR: usize = 16;

/// How many nodes lie at position `p`, when several do (`cx.shared` lists those, sorted
/// by position); 0 when at most one does.
fn nodes_at(cx: &Context, p: Point) -> usize {
    shared_at(cx, p).len()
}

/// The nodes at position `p` when several lie there (from `cx.shared`); none otherwise.
fn shared_at(cx: &Context, p: Point) -> &[NodeId] {
    let (pool, shared) = (&cx.pool, &cx.shared);
    let from = shared.partition_point(|&n| cmp_xy(pool.p(n), p) == Ordering::Less);
    let rest = &shared[from..];
    &rest[..rest.partition_point(|&n| cmp_xy(pool.p(n), p) == Ordering::Equal)]
}

/// The edges (by start node) through position `p`, and maybe some more. At a live node's
/// position (`at_vertex`) without crossings, an edge through it ends there (`clean` split
/// every edge at the live vertices lying inside it), at a node sharing the position: the
/// edges at the nodes of `cx.shared` there, found by a binary search however many edges
/// lie near (a grid cell holds many where vertices crowd together, as the tips of a
/// pinwheel's wedges on their circle). Elsewhere, the edge grid's.
fn edges_through(cx: &Context, p: Point, at_vertex: bool) -> impl Iterator<Item = NodeId> + '_ {
    let (listed, grid) = if at_vertex && cx.crossings.is_empty() {
        (shared_at(cx, p), None)
    } else {
        (&[][..], Some(cx.edge_index.query(p, p)))
    };
    let pool = &cx.pool;
    (listed.iter())
        .flat_map(move |&m| [m, pool.prev(m)])
        .chain(grid.into_iter().flatten())
}

/// The pool indices of the nodes loaded for ring `r`, in input order; none for a ring
/// split into lobes (its loaded nodes now lie on several rings).
fn loaded(cx: &Context, r: usize) -> core::ops::RangeInclusive<usize> {
    if cx.is_lobe(r) {
        #[allow(clippy::reversed_empty_ranges)]
        return 1..=0;
    }
    let LoadedRing { first, len: count } =
        (cx.as_loaded.get(r).copied()).unwrap_or(LoadedRing { first: 0, len: 0 });
    let first = first as usize;
    first..=(first + count as usize).saturating_sub(1).max(first)
}

/// No place: the ring does not pass the position being decided (see `s.ring_slot`).
const NO_SLOT: u32 = u32::MAX;

/// The live rings other than `b` with an edge through `p`, into `out`, each once, in the
/// order the grid lists them. `slot` must hold [`NO_SLOT`] for every ring; it is left
/// holding each listed ring's place in `out` (see [`clear_slots`]), so that a position
/// many rings pass costs time linear in them.
fn rings_through(
    cx: &Context,
    b: usize,
    p: Point,
    at_vertex: bool,
    out: &mut Vec<u32>,
    slot: &mut [u32],
) {
    out.clear();
    for n in edges_through(cx, p, at_vertex) {
        let node = cx.pool.get(n);
        let ring = node.ring;
        if ring as usize == b || node.removed || !cx.rings[ring as usize].alive {
            continue;
        }
        if slot[ring as usize] == NO_SLOT && on_segment(node.p, cx.pool.p(node.next), p) {
            slot[ring as usize] = out.len() as u32;
            out.push(ring);
        }
    }
}

/// Gives each ring of `rings` its place in it in `slot`.
fn set_slots(rings: &[u32], slot: &mut [u32]) {
    for (k, &r) in rings.iter().enumerate() {
        slot[r as usize] = k as u32;
    }
}

/// Takes the places of `rings` out of `slot` again.
fn clear_slots(rings: &[u32], slot: &mut [u32]) {
    for &r in rings {
        slot[r as usize] = NO_SLOT;
    }
}

/// The depth of ring `b` decided at its node `v`, or `None` when both of b's edges at v
/// run along rings passing through v's position.
fn depth_at(cx: &mut Context, s: &mut Scratch, b: usize, v: NodeId) -> Option<u32> {
    let depth = decide_at(cx, s, b, v);
    s.order.is_empty().then_some(depth)
}

/// How many rings contain ring `b`, among those that decide it at its node `v`: every ring
/// off v's position by the winding number, the rings passing through it locally. The rings
/// along both of b's edges at v decide nothing there and are left open in `s.order`.
fn decide_at(cx: &mut Context, s: &mut Scratch, b: usize, v: NodeId) -> u32 {
    let pv = cx.pool.p(v);
    // Rings passing through V: decided locally, their windings kept apart.
    let mut touching = core::mem::take(&mut s.order);
    let mut slot = core::mem::take(&mut s.ring_slot);
    rings_through(cx, b, pv, true, &mut touching, &mut slot);
    s.order = touching;
    s.ring_slot = slot;
    if s.order.is_empty() && v == cx.rings[b].rightmost && cx.crossings.is_empty() {
        if let Some(depth) = depth_from_nearest(cx, s, b, pv) {
            return depth;
        }
    }
    let (winding, depth) = decide_listed(cx, s, b, v, Probe::Clear);
    winding.max(0) as u32 + depth
}

/// Which of b's edges at a vertex v may tell whether b lies inside a ring r passing
/// through v (see [`locally_inside`]).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Probe {
    /// Only an edge along no other ring through v. Along another ring q, b's boundary may
    /// be cancelled by q's (b and q bounding one region from both sides), and r may cross
    /// the two of them there at once, as valid input allows: b then lies partly inside r.
    Clear,
    /// Any edge not along r: where no vertex of b has a clear probe.
    OffRing,
}

/// How many of the rings still open (`s.order`) contain ring `b`, decided at b's node `v`
/// as [`decide_at`] decides them; those it cannot decide there stay in `s.order`.
fn decide_open_at(cx: &mut Context, s: &mut Scratch, b: usize, v: NodeId, probe: Probe) -> u32 {
    set_slots(&s.order, &mut s.ring_slot);
    decide_listed(cx, s, b, v, probe).1
}

/// Decides at b's node `v` which rings of `s.order` (their places set in `s.ring_slot`,
/// cleared here) contain ring `b`: one off v's position by its winding number, one through
/// it by its corner there ([`locally_inside`]); those undecided stay in `s.order`.
/// Returns the winding number of the other rings, and how many of `s.order` contain b.
fn decide_listed(
    cx: &mut Context,
    s: &mut Scratch,
    b: usize,
    v: NodeId,
    probe: Probe,
) -> (i64, u32) {
    let pv = cx.pool.p(v);
    let mut slot = core::mem::take(&mut s.ring_slot);
    let mut beyond = core::mem::take(&mut s.touch_winding);
    beyond.clear();
    beyond.resize(s.order.len(), 0);
    let mut along = core::mem::take(&mut s.along_seen);
    let (winding, ray) = winding_number(cx, b, pv, &mut beyond, &slot, &mut along);
    s.along_seen = along;
    // the listed rings' edges through V, turned, grouped by ring
    let mut edges = core::mem::take(&mut s.hub_edges);
    edges.clear();
    // whether b's edges at v (to its successor, from its predecessor) run along another
    // ring's edge through v
    let (vn, vp) = (cx.pool.p(cx.pool.next(v)), cx.pool.p(cx.pool.prev(v)));
    let mut shared = [false; 2];
    for n in edges_through(cx, pv, true) {
        let node = cx.pool.get(n);
        let (k, next) = (slot[node.ring as usize], cx.pool.p(node.next));
        if node.removed || !on_segment(node.p, next, pv) {
            continue;
        }
        if k != NO_SLOT {
            edges.push(HubEdge {
                slot: k,
                from: ray.turn(node.p),
                to: ray.turn(next),
            });
        }
        if probe == Probe::Clear && node.ring as usize != b {
            for (d, along) in [vn, vp].into_iter().zip(&mut shared) {
                *along |= [node.p, next].into_iter().any(|e| on_ray(pv, e, d));
            }
        }
    }
    edges.sort_unstable_by_key(|e| e.slot);
    clear_slots(&s.order, &mut slot);
    s.ring_slot = slot;
    let mut depth = 0;
    let mut open = 0;
    let mut from = 0;
    for (k, &base) in beyond.iter().enumerate() {
        let r = s.order[k];
        let to = from + edges[from..].partition_point(|e| e.slot == k as u32);
        let decided = if from == to {
            Some(base > 0)
        } else {
            locally_inside(cx, v, &edges[from..to], ray, base, shared)
        };
        match decided {
            Some(inside) => depth += u32::from(inside),
            None => {
                s.order[open] = r;
                open += 1;
            }
        }
        from = to;
    }
    s.order.truncate(open);
    s.touch_winding = beyond;
    s.hub_edges = edges;
    (winding, depth)
}

/// The depth of ring `b` read off the nearest edge e (of ring R) that the ray from `pv`,
/// b's rightmost vertex, towards +x meets — when that is decisive: no ring passes through
/// `pv`, no edges cross, the ray meets e alone there and inside e, and R's depth is known.
/// Then nothing lies between `pv` and e, so `pv` is inside the rings R is inside, and inside
/// R too when e runs upwards (every ring is counter-clockwise here: interior on the left).
/// `None` leaves the case to the winding number. A ray meeting nothing: depth 0.
///
/// The walk along the grid row stops as in `bridge::nearest_hit`: edges not seen yet lie
/// wholly in later columns.
fn depth_from_nearest(cx: &Context, s: &Scratch, b: usize, pv: Point) -> Option<u32> {
    let mut near = Nearest::default();
    if let Some(edges) = cx.edge_index.listed() {
        for &n in edges {
            near.visit(cx, b, pv, n);
        }
        return near.depth(cx, s, pv);
    }
    let grid = &cx.edge_index.grid();
    let row = grid.row(pv.y);
    let east = Point::new(f64::INFINITY, pv.y);
    for n in grid.long(pv, east).chain(grid.row_list(row)) {
        near.visit(cx, b, pv, n);
    }
    for column in grid.column(pv.x)..grid.columns() {
        let listed = grid.cell(row, column).chain(grid.column_list(column));
        for n in listed.chain(grid.along(row, column)) {
            near.visit(cx, b, pv, n);
        }
        let hit_done = near
            .best
            .is_some_and(|h| grid.column(h.lo.x.max(h.hi.x)) <= column);
        if hit_done || (near.touch_x.is_finite() && grid.column(near.touch_x) <= column) {
            break;
        }
    }
    near.depth(cx, s, pv)
}

/// The depth of ring `b` when the nearest thing the ray from `pv` meets is a vertex W at
/// `touch`, of ring R: `pv` lies in the region just west of W, which is inside R exactly
/// when that direction lies inside W's corner (R is counter-clockwise here). `None` when
/// that is not decisive: several nodes at `touch`, an edge along the ray, the ray through
/// the origin, or R's depth not known yet.
fn depth_from_vertex(
    cx: &Context,
    s: &Scratch,
    near: &Nearest,
    pv: Point,
    touch: Point,
) -> Option<u32> {
    let w = near
        .touch_node
        .filter(|_| !near.touch_shared && !near.through_origin)?;
    let ring = cx.pool.get(w).ring as usize;
    if touch.x <= pv.x || !s.depth_known[ring] {
        return None;
    }
    let (next, prev) = (cx.pool.p(cx.pool.next(w)), cx.pool.p(cx.pool.prev(w)));
    if next == touch || prev == touch {
        return None;
    }
    let inside = corner_contains(touch, next, prev, pv)?;
    Some(cx.rings[ring].depth + u32::from(inside))
}

/// The nearest edge met by a ray towards +x, as [`depth_from_nearest`] collects it.
struct Nearest {
    best: Option<Hit>,
    /// Another edge meets the ray exactly where `best` does.
    tie: bool,
    /// An edge passes through the ray's origin.
    through_origin: bool,
    /// The smallest x (at or right of the ray's origin) where an edge meets the ray's line
    /// at an endpoint or runs along it; infinity when none does.
    touch_x: f64,
    /// The node at (`touch_x`, the ray's y), and whether another node lies there too or an
    /// edge there runs along the ray's line.
    touch_node: Option<NodeId>,
    touch_shared: bool,
}

/// An edge crossing the ray's line strictly between its endpoints `lo` (below) and `hi`.
#[derive(Clone, Copy)]
struct Hit {
    edge: NodeId,
    lo: Point,
    hi: Point,
    ring: usize,
    /// The edge runs from `lo` to `hi`.
    upward: bool,
}

impl Default for Nearest {
    fn default() -> Self {
        Nearest {
            best: None,
            tie: false,
            through_origin: false,
            touch_x: f64::INFINITY,
            touch_node: None,
            touch_shared: false,
        }
    }
}

impl Nearest {
    /// The depth of ring `b` from what the ray from its rightmost vertex `pv` met (every
    /// edge it may meet visited), as [`depth_from_nearest`] decides it.
    fn depth(&self, cx: &Context, s: &Scratch, pv: Point) -> Option<u32> {
        let touch = Point::new(self.touch_x, pv.y);
        let Some(hit) = self.best else {
            if self.touch_x.is_infinite() {
                return (!self.through_origin).then_some(0);
            }
            return depth_from_vertex(cx, s, self, pv, touch);
        };
        if self.tie || self.through_origin || !s.depth_known[hit.ring] {
            return None;
        }
        if self.touch_x.is_finite() {
            // a point where an edge meets the ray's line at an endpoint: nearer than the
            // hit, the vertex there decides (if alone); on the hit's edge, nothing does
            match orient2d(hit.lo, hit.hi, touch) {
                Orientation::CounterClockwise => return depth_from_vertex(cx, s, self, pv, touch),
                Orientation::Collinear => return None,
                Orientation::Clockwise => {}
            }
        }
        Some(cx.rings[hit.ring].depth + u32::from(hit.upward))
    }

    /// Takes the edge starting at `n` into account.
    fn visit(&mut self, cx: &Context, b: usize, pv: Point, n: NodeId) {
        let node = cx.pool.get(n);
        let ring = node.ring as usize;
        if ring == b || node.removed || !cx.rings[ring].alive {
            return;
        }
        let (p, q) = (node.p, cx.pool.p(node.next));
        let upward = p.y <= q.y;
        let (lo, hi) = if upward { (p, q) } else { (q, p) };
        if hi.y < pv.y || lo.y > pv.y || self.best.is_some_and(|h| h.edge == n) {
            return;
        }
        if lo.y == pv.y || hi.y == pv.y {
            let along = lo.y == hi.y;
            for (e, at) in [(p, n), (q, node.next)] {
                if e.y != pv.y || e.x < pv.x || e.x > self.touch_x {
                    continue;
                }
                if e.x < self.touch_x {
                    self.touch_x = e.x;
                    self.touch_node = Some(at);
                    self.touch_shared = along;
                } else {
                    self.touch_shared |= along || self.touch_node != Some(at);
                }
            }
            return;
        }
        match orient2d(lo, hi, pv) {
            Orientation::CounterClockwise => {}
            // behind the ray's origin
            Orientation::Clockwise => return,
            // through the origin: not decided here
            Orientation::Collinear => {
                self.through_origin = true;
                return;
            }
        }
        let hit = Hit {
            edge: n,
            lo,
            hi,
            ring,
            upward,
        };
        match self.best {
            None => self.best = Some(hit),
            Some(h) => match compare_hits(pv.y, h.lo, h.hi, lo, hi) {
                core::cmp::Ordering::Less => {
                    self.best = Some(hit);
                    self.tie = false;
                }
                core::cmp::Ordering::Equal => self.tie = true,
                core::cmp::Ordering::Greater => {}
            },
        }
    }
}

/// The winding number of the rings other than `b` and those in `s.order` (touching V)
/// around `pv`, by a ray along the grid row or column with the fewest cells to the edge,
/// and that ray. The crossings with the edges of `s.order[k]` go to `touching[k]`
/// instead (edges through `pv` cross nothing). `along` is scratch: the edges listed along
/// their segments in the walk's cells, each counted once.
fn winding_number(
    cx: &Context,
    b: usize,
    pv: Point,
    touching: &mut [i64],
    slot: &[u32],
    along: &mut Vec<NodeId>,
) -> (i64, Ray) {
    // the edges of a ring that counts, and those of b's own ring or dead, which do not
    let counts = |node: &crate::structures::Node| {
        node.ring as usize != b && !node.removed && cx.rings[node.ring as usize].alive
    };
    if let Some(edges) = cx.edge_index.listed() {
        // every edge, once, against the ray towards +x
        let mut winding = 0;
        for &n in edges {
            let node = cx.pool.get(n);
            if counts(node) {
                let step = crossing(node.p, cx.pool.p(node.next), pv);
                match slot[node.ring as usize] {
                    NO_SLOT => winding += step,
                    k => touching[k as usize] += step,
                }
            }
        }
        return (winding, Ray::East);
    }
    let grid = &cx.edge_index.grid();
    let (row, column) = (grid.row(pv.y), grid.column(pv.x));
    let (nx, ny) = (grid.columns(), grid.rows());
    let ray = [
        (Ray::East, nx - column),
        (Ray::West, column + 1),
        (Ray::North, ny - row),
        (Ray::South, row + 1),
    ]
    .into_iter()
    .min_by_key(|&(_, cells)| cells)
    .map_or(Ray::East, |(ray, _)| ray);
    let v = ray.turn(pv);
    let mut winding = 0;
    // `at`: the cell of the walk, for a listed edge; an edge is listed in every cell its
    // box spans, so it counts in the first one of the walk only
    let mut count = |n: NodeId, at: Option<usize>| {
        let node = cx.pool.get(n);
        let ring = node.ring;
        let (p, next) = (node.p, cx.pool.p(node.next));
        let first = match ray {
            Ray::East => grid.column(p.x.min(next.x)).max(column),
            Ray::West => grid.column(p.x.max(next.x)).min(column),
            Ray::North => grid.row(p.y.min(next.y)).max(row),
            Ray::South => grid.row(p.y.max(next.y)).min(row),
        };
        if !counts(node) || at.is_some_and(|k| k != first) {
            return;
        }
        let step = crossing(ray.turn(p), ray.turn(next), v);
        match slot[ring as usize] {
            NO_SLOT => winding += step,
            k => touching[k as usize] += step,
        }
    };
    // (the long edges whose boxes meet the ray)
    let (inf, ninf) = (f64::INFINITY, f64::NEG_INFINITY);
    let (lo, hi) = match ray {
        Ray::East => (pv, Point::new(inf, pv.y)),
        Ray::West => (Point::new(ninf, pv.y), pv),
        Ray::North => (pv, Point::new(pv.x, inf)),
        Ray::South => (Point::new(pv.x, ninf), pv),
    };
    for n in grid.long(lo, hi) {
        count(n, None);
    }
    // the lists along the walk's own row (column) hold an edge once; cells and the lists
    // across it hold an edge in every column (row) it spans; the along lists, in the
    // cells its segment passes, which the walk gathers first
    along.clear();
    match ray {
        Ray::East | Ray::West => {
            grid.row_list(row).for_each(|n| count(n, None));
            let columns = if ray == Ray::East {
                column..nx
            } else {
                0..column + 1
            };
            for c in columns {
                let listed = grid.cell(row, c).chain(grid.column_list(c));
                listed.for_each(|n| count(n, Some(c)));
                along.extend(grid.along(row, c));
            }
        }
        Ray::North | Ray::South => {
            grid.column_list(column).for_each(|n| count(n, None));
            let rows = if ray == Ray::North {
                row..ny
            } else {
                0..row + 1
            };
            for r in rows {
                let listed = grid.cell(r, column).chain(grid.row_list(r));
                listed.for_each(|n| count(n, Some(r)));
                along.extend(grid.along(r, column));
            }
        }
    }
    along.sort_unstable();
    along.dedup();
    along.iter().for_each(|&n| count(n, None));
    (winding, ray)
}

/// A direction for the ray of a winding number.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Ray {
    East,
    West,
    North,
    South,
}

impl Ray {
    /// The quarter turn taking this direction to +x: exact (swaps and negations only) and
    /// orientation-preserving, so [`crossing`] on turned points counts along this ray.
    fn turn(self, p: Point) -> Point {
        match self {
            Ray::East => p,
            Ray::West => Point::new(-p.x, -p.y),
            Ray::North => Point::new(p.y, -p.x),
            Ray::South => Point::new(-p.y, p.x),
        }
    }
}

/// Whether ring `b` lies inside ring `r`, which passes through the position of b's node
/// `v` along the edges `r_edges` (their ends turned by `ray`; `decide_at` gathers them for
/// every ring there at once), judged by the winding number of `r` next to v, where it is
/// exact however often `r` passes through v (a ring touching itself there has several
/// corners at v, none of which alone tells):
///
/// - on one of b's edges at v that does not run along `r` (a point of b's boundary off r,
///   as the oracle probes it), and along no other ring through v (`shared`, filled for
///   [`Probe::Clear`]): where one of them does and the other runs along `r`, nothing is
///   decided here (`None`);
/// - else, with both of b's edges along `r`, in every sector between r's edges inside b's
///   corner: one outside `r` shows that b is not inside it; all inside leave it open
///   (`None`), since b's corner may be r's very corner (a hole cancelling a lobe).
///
/// In the frame `ray` turns into, the direction d₀ just counter-clockwise of +x sees
/// `base`: the crossings of the ray with r's edges that miss v, as [`winding_number`]
/// counts them. From d₀ counter-clockwise, every ray from v along an edge of `r` changes
/// the winding number by one: +1 where the edge leaves v (its left side, the inside,
/// follows), −1 where it arrives.
fn locally_inside(
    cx: &Context,
    v: NodeId,
    r_edges: &[HubEdge],
    ray: Ray,
    base: i64,
    shared: [bool; 2],
) -> Option<bool> {
    let pv = cx.pool.p(v);
    let o = ray.turn(pv);
    // r's edges through v, as turned points: the edge's start and end
    let edges = || r_edges.iter().map(|e| (e.from, e.to));
    let along_r = |d: Point| {
        edges().any(|(from, to)| [from, to].into_iter().any(|e| e != o && on_ray(o, e, d)))
    };
    // The winding number just counter-clockwise of the direction o → d: every ray up to
    // and along it counts; rays along +x lie before d₀ and never count.
    let winding_after = |d: Point| {
        let counts = |e: Point| e != o && !(e.y == o.y && e.x > o.x) && cmp_around(o, e, d).is_le();
        edges().fold(base, |w, (from, to)| {
            w + i64::from(counts(to)) - i64::from(counts(from))
        })
    };
    let (vn, vp) = (
        ray.turn(cx.pool.p(cx.pool.next(v))),
        ray.turn(cx.pool.p(cx.pool.prev(v))),
    );
    let off_r = [vn, vp]
        .into_iter()
        .zip(shared)
        .filter(|&(d, _)| !along_r(d));
    let mut blocked = false;
    for (d, along_other) in off_r {
        if !along_other {
            return Some(winding_after(d) > 0);
        }
        blocked = true;
    }
    if blocked {
        // b's only edges off r run along other rings: decided elsewhere (see `Probe`)
        return None;
    }
    let inside_corner = |e: Point| e != o && corner_contains(o, vn, vp, e) == Some(true);
    let sectors = core::iter::once(vn).chain(
        edges()
            .flat_map(|(from, to)| [from, to])
            .filter(|&e| inside_corner(e)),
    );
    let mut sectors = sectors.map(winding_after);
    if sectors.any(|w| w <= 0) {
        Some(false)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{cleaned, flatten, turn_at_rightmost};

    /// A square from (x, y) with side `s`, counter-clockwise or clockwise.
    fn square(x: f64, y: f64, s: f64, ccw: bool) -> Vec<[f64; 2]> {
        let mut v = vec![[x, y], [x + s, y], [x + s, y + s], [x, y + s]];
        if !ccw {
            v.reverse();
        }
        v
    }

    /// Nests `rings` by `nesting`; each input ring's depth (`None` when not alive) and
    /// whether it turns clockwise now.
    fn depths(
        rings_in: &[&[[f64; 2]]],
        nesting: Nesting,
        lenient: bool,
    ) -> Result<Vec<Option<(u32, bool)>>, Error> {
        let (vertices, starts) = flatten(rings_in);
        let (mut cx, mut st) = cleaned(&vertices, &starts, lenient);
        nest(&mut cx, &mut st.nest, nesting)?;
        let mut out = vec![None; rings_in.len()];
        for ring in cx.rings.iter().filter(|r| r.alive) {
            let clockwise = turn_at_rightmost(&cx, ring) == Orientation::Clockwise;
            out[ring.input as usize] = Some((ring.depth, clockwise));
        }
        Ok(out)
    }

    #[test]
    fn depth_is_containment_in_any_order_and_winding() {
        let outer = square(0.0, 0.0, 12.0, true);
        let hole = square(2.0, 2.0, 8.0, true);
        let island = square(4.0, 4.0, 4.0, false);
        let lake = square(5.0, 5.0, 2.0, true);
        let apart = square(20.0, 0.0, 2.0, false);
        let expected = [
            Some((0, false)),
            Some((1, true)),
            Some((2, false)),
            Some((3, true)),
            Some((0, false)),
        ];
        let all = [&outer[..], &hole, &island, &lake, &apart];
        assert_eq!(depths(&all, Nesting::Auto, false), Ok(expected.to_vec()));
        // listed inside out: the same depths
        let reversed = [&apart[..], &lake, &island, &hole, &outer];
        let mut want = expected.to_vec();
        want.reverse();
        assert_eq!(depths(&reversed, Nesting::Auto, false), Ok(want));
    }

    #[test]
    fn rings_through_a_shared_vertex_are_decided_locally() {
        // a triangular hole whose corner is the outer square's corner, and one touching
        // the outer ring in the middle of an edge
        let outer = square(0.0, 0.0, 8.0, true);
        let corner_hole = [[0.0, 0.0], [3.0, 1.0], [1.0, 3.0]];
        let edge_hole = [[8.0, 4.0], [6.0, 5.0], [6.0, 3.0]];
        let got = depths(&[&outer, &corner_hole, &edge_hole], Nesting::Auto, false);
        assert_eq!(
            got,
            Ok(vec![Some((0, false)), Some((1, true)), Some((1, true))])
        );
        // a square touching the outer square from outside at a corner is no hole
        let outside = square(8.0, 8.0, 2.0, true);
        let got = depths(&[&outer, &outside], Nesting::Auto, false);
        assert_eq!(got, Ok(vec![Some((0, false)), Some((0, false))]));
    }

    /// The rings containing each triangle (h, a, b) of `rings`, at a point just inside its
    /// edge a–b (off any triangle nested in it, which reaches less far from h), by a
    /// plain crossing test: the expected depths, independent of the stage.
    fn brute_depths(rings: &[Vec<[f64; 2]>]) -> Vec<u32> {
        let inside = |ring: &[[f64; 2]], p: [f64; 2]| {
            let mut odd = false;
            for (k, a) in ring.iter().enumerate() {
                let b = ring[(k + 1) % ring.len()];
                if (a[1] > p[1]) != (b[1] > p[1])
                    && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
                {
                    odd = !odd;
                }
            }
            odd
        };
        (0..rings.len())
            .map(|i| {
                let r = &rings[i];
                let mid = [(r[1][0] + r[2][0]) / 2.0, (r[1][1] + r[2][1]) / 2.0];
                let c = [
                    mid[0] + (r[0][0] - mid[0]) * 0.01,
                    mid[1] + (r[0][1] - mid[1]) * 0.01,
                ];
                (0..rings.len())
                    .filter(|&j| j != i && inside(&rings[j], c))
                    .count() as u32
            })
            .collect()
    }

    #[test]
    fn many_rings_through_one_point_are_decided_there_at_once() {
        // Inside a square, a square hole, an island in it: the hub (20, 20) lies inside
        // three rings. Through the hub: 12 thin wedges, every third with a smaller wedge
        // inside it, and a wedge round the +x direction (where the sweep starts) with one
        // inside it on either side: 19 rings through one point, decided there at once.
        let (h, tau) = ([20.0, 20.0], core::f64::consts::TAU);
        let at = |angle: f64, r: f64| [h[0] + r * angle.cos(), h[1] + r * angle.sin()];
        let mut rings = vec![
            vec![[0.0, 0.0], [40.0, 0.0], [40.0, 40.0], [0.0, 40.0]],
            vec![[2.0, 2.0], [38.0, 2.0], [38.0, 38.0], [2.0, 38.0]],
            vec![[4.0, 4.0], [36.0, 4.0], [36.0, 36.0], [4.0, 36.0]],
        ];
        let wedge = |from: f64, to: f64, r: f64| vec![h, at(from, r), at(to, r)];
        for i in 0..12 {
            let t = (f64::from(i) + 1.0) * tau / 14.0;
            rings.push(wedge(t, t + 0.2, 10.0));
            if i % 3 == 0 {
                rings.push(wedge(t + 0.05, t + 0.15, 6.0));
            }
        }
        rings.push(wedge(-0.15, 0.15, 12.0));
        rings.push(wedge(-0.1, -0.02, 8.0));
        rings.push(wedge(0.02, 0.1, 8.0));
        // the first three rings are squares: their depths by hand
        let mut want = vec![0, 1, 2];
        want.extend(brute_depths(&rings[3..]).into_iter().map(|d| d + 3));
        assert!(want.contains(&4) && want.contains(&3));
        for quarter_turns in 0..4 {
            let turned: Vec<Vec<[f64; 2]>> = (rings.iter())
                .map(|ring| {
                    (ring.iter())
                        .map(|&p| (0..quarter_turns).fold(p, |[x, y], _| [-y, x]))
                        .collect()
                })
                .collect();
            let refs: Vec<&[[f64; 2]]> = turned.iter().map(Vec::as_slice).collect();
            let got = depths(&refs, Nesting::Auto, false).expect("valid");
            let got: Vec<u32> = got.iter().map(|d| d.map_or(u32::MAX, |d| d.0)).collect();
            assert_eq!(got, want, "{quarter_turns} quarter turns");
        }
    }

    #[test]
    fn first_is_outer_is_verified() {
        let outer = square(0.0, 0.0, 8.0, true);
        let hole = square(2.0, 2.0, 2.0, true);
        let away = square(10.0, 0.0, 2.0, true);
        let got = depths(&[&outer, &hole], Nesting::FirstIsOuter, false);
        assert_eq!(got, Ok(vec![Some((0, false)), Some((1, true))]));
        // a "hole" outside its outer ring is refused
        let err = depths(&[&outer, &away], Nesting::FirstIsOuter, false);
        assert!(
            matches!(err, Err(Error::HoleOutside { ring: 1, .. })),
            "{err:?}"
        );
        // lenient mode takes the roles as given (bridging skips a hole it cannot reach)
        let got = depths(&[&outer, &away], Nesting::FirstIsOuter, true);
        assert_eq!(got, Ok(vec![Some((0, false)), Some((1, true))]));
    }

    #[test]
    fn the_same_ring_twice_overlaps() {
        let a = square(0.0, 0.0, 4.0, true);
        let got = depths(&[&a, &a], Nesting::Auto, false);
        assert!(matches!(got, Err(Error::RingsOverlap { .. })), "{got:?}");
        // a hole sharing an edge with its outer ring lies on it, but bounds a hole: valid
        let outer = square(0.0, 0.0, 4.0, true);
        let hole = [[0.0, 0.0], [2.0, 0.0], [1.0, 1.0]];
        let got = depths(&[&outer, &hole], Nesting::Auto, false);
        assert_eq!(got, Ok(vec![Some((0, false)), Some((1, true))]));
    }

    /// The rings each maybe reversed, shuffled (the outer ring anywhere) and all turned by
    /// the same random number of quarter turns, flattened: the order (input ring k is
    /// `rings[order[k]]`), the vertices and the ring starts.
    fn scrambled(
        rings: &mut [Vec<[f64; 2]>],
        pick: &mut impl FnMut(u64) -> u64,
    ) -> (Vec<usize>, Vec<[f64; 2]>, Vec<usize>) {
        for ring in rings.iter_mut() {
            if pick(2) == 0 {
                ring.reverse();
            }
        }
        let mut order: Vec<usize> = (0..rings.len()).collect();
        for k in (1..order.len()).rev() {
            order.swap(k, pick(k as u64 + 1) as usize);
        }
        let turns = pick(4);
        let turn = |p: [f64; 2]| (0..turns).fold(p, |[x, y], _| [-y, x]);
        let shuffled: Vec<Vec<[f64; 2]>> = (order.iter())
            .map(|&r| rings[r].iter().map(|&p| turn(p)).collect())
            .collect();
        let refs: Vec<&[[f64; 2]]> = shuffled.iter().map(Vec::as_slice).collect();
        let (vertices, starts) = flatten(&refs);
        (order, vertices, starts)
    }

    /// Nests the rings `scrambled` made (never by the sweep with `no_sweep`) and checks
    /// every ring's depth against `want`, by the ring's place before scrambling; the
    /// context, and whether the sweep counted the depths.
    fn nested_as_built(
        vertices: &[[f64; 2]],
        starts: &[usize],
        no_sweep: bool,
        (order, want): (&[usize], &[u32]),
        case: usize,
    ) -> (Context, bool) {
        let (mut cx, mut st) = cleaned(vertices, starts, false);
        st.nest.no_sweep = no_sweep;
        nest(&mut cx, &mut st.nest, Nesting::Auto).expect("valid");
        for ring in cx.rings.iter().filter(|r| r.alive) {
            let r = ring.input as usize;
            assert_eq!(ring.depth, want[order[r]], "case {case}, ring {r}");
        }
        (cx, st.nest.swept)
    }

    /// Holes touching the outer ring, each other and their islands at vertices, in any
    /// order, winding and quarter turn: the depths by construction, whether the rings are
    /// few (counted directly) or many (by the sweep, and without it through the grid).
    #[test]
    fn touching_rings_nest_by_construction_directly_swept_and_through_the_grid() {
        let mut pick = crate::testing::random(0x7e57_1e55);
        let (mut direct, mut swept, mut grid) = (0, 0, 0);
        for case in 0..400 {
            // an n × n grid of 10 × 10 cells in a square: in a cell at (x, y), maybe a
            // triangular hole from its lower left corner (on the outer ring in the first
            // row and column) to a point inside and to its upper right corner (another
            // hole's lower left corner, or on the outer ring), and maybe an island in the
            // hole from the same lower left corner
            let n = if case % 4 == 3 { 5 } else { 2 };
            let side = 10.0 * n as f64;
            let mut rings = vec![vec![[0.0, 0.0], [side, 0.0], [side, side], [0.0, side]]];
            let mut want = vec![0];
            for cell in 0..n * n {
                let (x, y) = ((cell % n) as f64 * 10.0, (cell / n) as f64 * 10.0);
                if pick(10) < 3 {
                    continue;
                }
                let a = 3.0 + pick(5) as f64;
                rings.push(vec![[x, y], [x + 9.0, y + a], [x + 10.0, y + 10.0]]);
                want.push(1);
                if pick(2) == 0 {
                    rings.push(vec![[x, y], [x + 5.0, y + 4.0], [x + 6.0, y + 5.5]]);
                    want.push(2);
                }
            }
            let (order, vertices, starts) = scrambled(&mut rings, &mut pick);
            // each input twice: as it comes, and never by the sweep
            for no_sweep in [false, true] {
                let (cx, swept_now) =
                    nested_as_built(&vertices, &starts, no_sweep, (&order, &want), case);
                // the grid is built only when the depths were not counted directly
                if cx.edge_index.is_current() {
                    grid += 1;
                } else if swept_now {
                    swept += 1;
                } else {
                    direct += 1;
                }
            }
        }
        assert!(
            direct > 50 && swept > 50 && grid > 50,
            "{direct} direct, {swept} swept, {grid} through the grid"
        );
    }

    /// An outer ring touching itself (two square lobes pinched at a corner, one with a
    /// notch), with a hole in each lobe, one of them at the pinch: counted directly,
    /// without the grid, in every quarter turn.
    #[test]
    fn a_ring_touching_itself_nests_its_holes_directly() {
        let outer = [
            [0.0, 0.0],
            [10.0, 0.0],
            [10.0, 10.0],
            [20.0, 10.0],
            [20.0, 20.0],
            [10.0, 20.0],
            [10.0, 10.0],
            [0.0, 10.0],
            [0.0, 6.0],
            [4.0, 5.0],
            [0.0, 4.0],
        ];
        let at_pinch = [[10.0, 10.0], [13.0, 12.0], [12.0, 13.0]];
        let inside = [[6.0, 2.0], [8.0, 2.0], [8.0, 4.0]];
        for turns in 0..4 {
            let turn = |ring: &[[f64; 2]]| -> Vec<[f64; 2]> {
                ring.iter()
                    .map(|&p| (0..turns).fold(p, |[x, y], _| [-y, x]))
                    .collect()
            };
            let rings = [turn(&outer), turn(&at_pinch), turn(&inside)];
            let refs: Vec<&[[f64; 2]]> = rings.iter().map(Vec::as_slice).collect();
            let (vertices, starts) = flatten(&refs);
            let (mut cx, mut st) = cleaned(&vertices, &starts, false);
            nest(&mut cx, &mut st.nest, Nesting::FirstIsOuter).expect("valid");
            assert!(
                !cx.edge_index.is_current(),
                "{turns} turns: through the grid"
            );
            let depth = |input: u32| {
                let ring = cx.rings.iter().find(|r| r.alive && r.input == input);
                ring.map(|r| r.depth)
            };
            assert_eq!([depth(0), depth(1), depth(2)], [Some(0), Some(1), Some(1)]);
        }
    }

    /// Rings lying along each other (a hole along part of its polygon's edge, and one
    /// sharing a whole edge with the first) are few, but take the general rule.
    #[test]
    fn rings_lying_along_each_other_take_the_general_rule() {
        let outer = square(0.0, 0.0, 10.0, true);
        let along = [[0.0, 0.0], [5.0, 0.0], [2.0, 3.0]];
        let beside = [[5.0, 0.0], [2.0, 3.0], [6.0, 3.0]];
        let refs = [&outer[..], &along, &beside];
        let (vertices, starts) = flatten(&refs);
        let (mut cx, mut st) = cleaned(&vertices, &starts, false);
        nest(&mut cx, &mut st.nest, Nesting::FirstIsOuter).expect("valid");
        assert!(
            cx.edge_index.is_current(),
            "the general rule, not counted directly"
        );
        let depths: Vec<u32> = (cx.rings.iter())
            .filter(|r| r.alive)
            .map(|r| r.depth)
            .collect();
        assert_eq!(depths, [0, 1, 1]);
    }

    /// Holes lying along the outer ring and along each other (pairs of triangles sharing
    /// an edge, the first along its cell's lower side, which is the outer ring's in the
    /// first row), in any order, winding and quarter turn: the depths by construction,
    /// counted by the sweep (every ring has a node on no other), or without it through
    /// the edges, few (only listed) or many (the grid); and through the edges where a
    /// ring lies on others at every node (a triangle of the first row or column, whose
    /// first node lies on the outer ring, with its neighbour).
    #[test]
    fn rings_lying_along_each_other_nest_swept_listed_and_through_the_grid() {
        let mut pick = crate::testing::random(0x1157_ed00);
        let (mut swept, mut listed, mut grid, mut on_others) = (0, 0, 0, 0);
        for case in 0..300 {
            let n = if case % 3 == 2 { 4 } else { 2 };
            let side = 10.0 * n as f64;
            let mut rings = vec![vec![[0.0, 0.0], [side, 0.0], [side, side], [0.0, side]]];
            let mut want = vec![0];
            // a triangle of the first row or column with its neighbour has every node on
            // other rings
            let mut covered = false;
            for cell in 0..n * n {
                let (x, y) = ((cell % n) as f64 * 10.0, (cell / n) as f64 * 10.0);
                if pick(10) < 2 {
                    continue;
                }
                let (a, h) = (2.0 + pick(6) as f64, 2.0 + pick(6) as f64);
                rings.push(vec![[x, y], [x + 8.0, y], [x + a, y + h]]);
                want.push(1);
                // (every other case keeps the first row and column free of such pairs)
                let edge_cell = x == 0.0 || y == 0.0;
                if pick(3) > 0 && (case % 2 == 1 || !edge_cell) {
                    rings.push(vec![[x + 8.0, y], [x + a, y + h], [x + 9.0, y + h]]);
                    want.push(1);
                    covered |= edge_cell;
                }
            }
            let (order, vertices, starts) = scrambled(&mut rings, &mut pick);
            for no_sweep in [false, true] {
                let (cx, swept_now) =
                    nested_as_built(&vertices, &starts, no_sweep, (&order, &want), case);
                let through_edges = cx.edge_index.is_current();
                if swept_now {
                    swept += 1;
                } else if cx.edge_index.listed().is_some() {
                    listed += 1;
                } else if through_edges {
                    grid += 1;
                }
                // the edges decide exactly where a ring has every node on others (else
                // the sweep, or where no two rings lie along each other and they are few,
                // the direct count)
                if !no_sweep {
                    assert_eq!(through_edges, covered, "case {case}");
                    on_others += usize::from(covered);
                }
            }
        }
        assert!(
            swept > 50 && listed > 50 && grid > 50 && on_others > 50,
            "{swept} swept, {listed} listed, {grid} through the grid, {on_others} on others"
        );
    }

    /// Outer rings pinched into two square lobes touching at a corner (figure eights, a
    /// ring touching itself), several in a row (past the direct count), each with a hole
    /// in its first lobe and maybe one in its second: counted by the sweep (or, few,
    /// directly), the depths by construction, in any order, winding and quarter turn.
    /// And with the second lobe turned against the first (a ring crossing itself at the
    /// pinch, around one hole), the sweep leaves the depths to the grid and nesting fails
    /// or passes as without it.
    #[test]
    fn rings_touching_themselves_nest_by_the_sweep_where_they_wind_once() {
        let mut pick = crate::testing::random(0x8ea7_0001);
        let (mut swept, mut left) = (0, 0);
        for case in 0..200 {
            let twisted = case % 4 == 3;
            let mut rings = Vec::new();
            let mut want = Vec::new();
            for k in 0..4 + pick(4) {
                let x = 30.0 * k as f64;
                let first = [[x, 0.0], [x + 10.0, 0.0], [x + 10.0, 10.0], [x, 10.0]];
                // the second lobe from the pinch at (x + 10, 10), one way or the other
                let mut second = vec![[x + 20.0, 10.0], [x + 20.0, 20.0], [x + 10.0, 20.0]];
                if twisted && k == 0 {
                    second.reverse();
                }
                let mut eight = first[..3].to_vec();
                eight.extend(second);
                eight.push([x + 10.0, 10.0]);
                eight.push([x, 10.0]);
                rings.push(eight);
                want.push(0);
                rings.push(square(x + 2.0, 2.0, 3.0 + pick(4) as f64, true));
                want.push(1);
                if pick(2) == 0 || (twisted && k == 0) {
                    rings.push(square(x + 12.0, 12.0, 3.0 + pick(4) as f64, false));
                    want.push(1);
                }
            }
            let (order, vertices, starts) = scrambled(&mut rings, &mut pick);
            if !twisted {
                let (cx, swept_now) =
                    nested_as_built(&vertices, &starts, false, (&order, &want), case);
                // (few rings are counted directly)
                assert!(!cx.edge_index.is_current(), "case {case}: not by the grid");
                swept += usize::from(swept_now);
                continue;
            }
            let run = |no_sweep: bool| {
                let (mut cx, mut st) = cleaned(&vertices, &starts, false);
                st.nest.no_sweep = no_sweep;
                let result = nest(&mut cx, &mut st.nest, Nesting::Auto);
                let depths: Vec<u32> = cx.rings.iter().map(|r| r.depth).collect();
                (result.map(|()| depths), st.nest.swept)
            };
            let ((with, swept_now), (without, _)) = (run(false), run(true));
            assert!(!swept_now, "case {case}: a lobe winds against its ring");
            assert_eq!(with, without, "case {case}");
            left += 1;
        }
        assert!(swept > 50 && left > 30, "{swept} swept, {left} left");
    }

    #[test]
    fn many_small_rings_the_sweep_and_the_grid_agree() {
        // a row of nested squares: few enough for the direct count, then as many again
        // (past `DIRECT_WORK`) for the sweep and the grid
        for count in [3, 40] {
            let squares: Vec<Vec<[f64; 2]>> = (0..count)
                .map(|k| {
                    let k = k as f64;
                    square(k, k, 4.0 * count as f64 - 2.0 * k, k as usize % 2 == 0)
                })
                .collect();
            let refs: Vec<&[[f64; 2]]> = squares.iter().map(|s| &s[..]).collect();
            let got = depths(&refs, Nesting::Auto, false).expect("valid");
            for (k, d) in got.into_iter().enumerate() {
                assert_eq!(d, Some((k as u32, k % 2 == 1)), "ring {k} of {count}");
            }
            // and without the sweep, through the grid
            let (vertices, starts) = flatten(&refs);
            let (mut cx, mut st) = cleaned(&vertices, &starts, false);
            st.nest.no_sweep = true;
            nest(&mut cx, &mut st.nest, Nesting::Auto).expect("valid");
            assert_eq!(cx.edge_index.is_current(), count > 3);
            for ring in cx.rings.iter().filter(|r| r.alive) {
                let k = ring.input;
                assert_eq!(ring.depth, k, "ring {k} of {count}, through the grid");
            }
        }
    }
}
