//! Stage 3b, *touch*: join rings properly where they touch.
//!
//! Rings may touch at vertices (clean turned every touch into shared vertices). Bridging
//! and clipping need every polygon boundary to be weakly simple: where a boundary passes a
//! position several times, its corners there must not overlap. A hole touching its outer
//! ring, or another hole, away from the bridge would break that. So at every shared
//! position the edges are re-linked as a planar face walk does: with every ring's interior
//! on its left (nest made it so), an edge arriving at X continues along the first edge
//! leaving X clockwise from the way it came. Rings touching there become one ring (a
//! zero-length bridge), a ring touching itself splits into two, and edges running both
//! ways along one segment (a hole sharing an edge with its outer ring) pair up into
//! zero-width rings that enclose nothing.
//!
//! Afterwards the rings are traced again. Each is either the outer boundary of a polygon
//! (its interior on the inside) or a hole boundary (its polygon around it); which one is
//! read at its rightmost-lowest position: a hole's boundary turns clockwise there at one
//! of its visits, an outer boundary never does.

use crate::geom::{bundle_end, clockwise_before, inside_along, pair_alternating, RightmostVisit};
use crate::structures::NodeId;
use core::cmp::Ordering;

use crate::context::{net_boundary_counter_clockwise, Context, NetEdge, Ring};
use crate::geom::{approx_cross, cmp_around, cmp_xy, on_segment, orient2d, Orientation, Point};
use crate::Error;

/// Two cycles `c` < `d` of one input ring at one depth, meeting at node `at`.
#[derive(Clone, Copy, Debug)]
struct LobePair {
    c: u32,
    d: u32,
    at: NodeId,
}

/// A live ring through one position: its input ring, its depth, its number, and its
/// node there.
#[derive(Clone, Copy, Debug)]
struct LobeAt {
    input: u32,
    depth: u32,
    ring: u32,
    node: NodeId,
}

/// Scratch buffers of the touch stage, kept between calls.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// The new successor of each node of one shared position: (node, successor).
    relink: Vec<(NodeId, NodeId)>,
    /// The edge ends at one shared position: far end, node there, whether it arrives.
    ends: Vec<(Point, NodeId, bool)>,
    /// At a position many nodes share: the edges leaving it (far end, place among the
    /// nodes there, far node), by direction.
    leaving: Vec<(Point, u32, NodeId)>,
    /// Those edges' far ends, by position.
    far: Vec<Point>,
    /// Pairs of rings one input ring was cut into, and a node where they meet.
    lobe_pairs: Vec<LobePair>,
    /// The rings through one position, with their input ring and depth.
    lobe_meet: Vec<LobeAt>,
    /// The rays and their net walks of a crack test.
    nets: Vec<(Point, i32)>,
    /// A ring's segments with their net walks (see `net_boundary_counter_clockwise`).
    net_edges: Vec<NetEdge>,
}

/// Re-links every shared position and re-traces the rings; returns the number of holes.
pub(crate) fn join(cx: &mut Context, s: &mut Scratch) -> usize {
    if !cx.shared.is_empty() {
        // relinking changes which node an edge starts at
        cx.edge_index.invalidate();
        let mut i = 0;
        while i < cx.shared.len() {
            let j = cx.same_position_end(i);
            relink(cx, s, i, j);
            i = j;
        }
        retrace(cx, s);
    }
    cx.rings
        .iter()
        .filter(|r| r.alive && r.depth % 2 == 1)
        .count()
}

/// Strict mode, after [`join`]: refuses a ring that winds twice round part of the plane.
///
/// Nesting checked whole rings; joining cuts a ring touching itself into cycles, and those
/// must nest as outer and hole boundaries do. Two cycles of one ring that meet at a
/// position and turn the same way must lie outside each other: one inside the other is a
/// lobe inside the rest of the ring turning the same way, where the winding number is 2.
/// (Lobes turning the other way are holes; another ring cancelling a lobe pairs with it
/// into walls, which enclose nothing.) Each pair is decided by crossing parity at a vertex
/// of one off the other's boundary. The pairs and the scans are bounded by budgets linear
/// in the nodes; past them the rest goes unchecked.
pub(crate) fn refuse_rings_winding_twice(cx: &mut Context, s: &mut Scratch) -> Result<(), Error> {
    if cx.lenient || cx.shared.is_empty() {
        return Ok(());
    }
    // each pair of rings once; at most `limit` of them
    let mut pairs = core::mem::take(&mut s.lobe_pairs);
    let mut meet = core::mem::take(&mut s.lobe_meet);
    pairs.clear();
    let limit = 4 * cx.pool.len() + 1024;
    let mut i = 0;
    while i < cx.shared.len() && pairs.len() < limit {
        let j = cx.same_position_end(i);
        // the live rings through this position, by (input ring, depth), each once
        meet.clear();
        for &n in &cx.shared[i..j] {
            if live(cx, n) {
                let ring = cx.pool.get(n).ring;
                let r = cx.rings[ring as usize];
                meet.push(LobeAt {
                    input: r.input,
                    depth: r.depth,
                    ring,
                    node: n,
                });
            }
        }
        meet.sort_unstable_by_key(|m| (m.input, m.depth, m.ring));
        meet.dedup_by_key(|m| m.ring);
        'meet: for (k, m) in meet.iter().enumerate() {
            let same = meet[k + 1..]
                .iter()
                .take_while(|o| o.input == m.input && o.depth == m.depth);
            for o in same {
                if pairs.len() >= limit {
                    break 'meet;
                }
                pairs.push(LobePair {
                    c: m.ring.min(o.ring),
                    d: m.ring.max(o.ring),
                    at: m.node,
                });
            }
        }
        i = j;
    }
    pairs.sort_unstable_by_key(|p| (p.c, p.d));
    pairs.dedup_by_key(|p| (p.c, p.d));
    let mut result = Ok(());
    let mut budget = 16 * cx.pool.len() + 4096;
    'pairs: for &LobePair { c, d, at } in &pairs {
        for (inner, outer) in [(c as usize, d as usize), (d as usize, c as usize)] {
            match lies_inside(cx, inner, outer, &mut budget) {
                Some(true) => {
                    result = Err(Error::RingWindsTwice {
                        ring: cx.rings[inner].input as usize,
                        vertex: cx.pool.get(at).vertex as usize,
                    });
                    break 'pairs;
                }
                Some(false) => {}
                None => break 'pairs,
            }
        }
    }
    s.lobe_pairs = pairs;
    s.lobe_meet = meet;
    result
}

/// Whether ring `inner` lies inside ring `outer`, by crossing parity at the first vertex of
/// `inner` off `outer`'s boundary (`Some(false)` when there is none); `None` when the
/// `budget` of edge visits runs out first.
fn lies_inside(cx: &Context, inner: usize, outer: usize, budget: &mut usize) -> Option<bool> {
    let pool = &cx.pool;
    let outer_len = cx.rings[outer].len as usize;
    for n in pool.ring(cx.rings[inner].start) {
        *budget = budget.checked_sub(outer_len)?;
        let p = pool.p(n);
        let mut odd = false;
        let mut on = false;
        for m in pool.ring(cx.rings[outer].start) {
            let (a, b) = (pool.p(m), pool.p(pool.next(m)));
            if on_segment(a, b, p) {
                on = true;
                break;
            }
            // the ray from p towards +x, half-open in y
            if (a.y > p.y) != (b.y > p.y) {
                let side = orient2d(a, b, p);
                let up = b.y > a.y;
                if (up && side == Orientation::CounterClockwise)
                    || (!up && side == Orientation::Clockwise)
                {
                    odd = !odd;
                }
            }
        }
        if !on {
            return Some(odd);
        }
    }
    Some(false)
}

/// Whether node `n` is part of the triangulation's input still.
fn live(cx: &Context, n: NodeId) -> bool {
    let node = cx.pool.get(n);
    !node.removed && cx.rings[node.ring as usize].alive
}

/// Re-links the nodes `cx.shared[i..j]`, all at one position, by the face-walk rule.
/// Leaves them as they are when the rule does not give a one-to-one pairing (only for
/// invalid, lenient input).
fn relink(cx: &mut Context, s: &mut Scratch, i: usize, j: usize) {
    s.relink.clear();
    let o = cx.pool.p(cx.shared[i]);
    let doubled = if j - i > FEW_AT_ONE_POSITION && sort_ends(cx, s, i, j) {
        relink_sorted(cx, s, i, j)
    } else {
        relink_by_pairs(cx, s, i, j, o);
        any_doubled(cx, i, j)
    };
    // one-to-one? every successor used once
    let pairs = &mut s.relink;
    pairs.sort_unstable_by_key(|&(_, t)| t);
    let conflict = pairs.windows(2).any(|w| w[0].1 == w[1].1);
    // (lenient mode on crossing input keeps the rings as they are there: its repairs
    // were tuned so)
    let exact = !cx.lenient || cx.crossings.is_empty();
    if exact && (conflict || doubled) {
        // Edges of one direction need ordering: the rule above sends an edge straight
        // back first, which closes a wall, but a crack into the region is walked along.
        if !relink_bundles(cx, s, i, j) {
            return;
        }
    } else if conflict {
        return;
    }
    for k in 0..s.relink.len() {
        let (n, target) = s.relink[k];
        cx.pool.get_mut(n).next = target;
        cx.pool.get_mut(target).prev = n;
        cx.pool.touch(n);
    }
}

/// Up to this many nodes at one position, [`relink`] compares every edge arriving there
/// with every edge leaving; past it, it sorts them by direction first.
const FEW_AT_ONE_POSITION: usize = 8;

/// The face-walk rule at the position of `cx.shared[i..j]`, edge by edge: each arriving
/// edge against every leaving one (quadratic in the nodes there, fastest for a few).
fn relink_by_pairs(cx: &mut Context, s: &mut Scratch, i: usize, j: usize, o: Point) {
    for a in i..j {
        let n = cx.shared[a];
        if !live(cx, n) {
            continue;
        }
        let back = cx.pool.p(cx.pool.prev(n));
        let mut best: Option<NodeId> = None;
        for b in i..j {
            let m = cx.shared[b];
            if !live(cx, m) {
                continue;
            }
            let q = cx.pool.next(m);
            best = match best {
                Some(c) if !clockwise_before(o, back, cx.pool.p(q), cx.pool.p(c)) => Some(c),
                _ => Some(q),
            };
        }
        if let Some(target) = best {
            s.relink.push((n, target));
        }
    }
}

/// Fills `s.leaving` with the edges leaving the position `o` of `cx.shared[i..j]`,
/// counter-clockwise from the +x direction, those of one direction in the order of their
/// nodes in `cx.shared`, and `s.far` with their far ends by position. False when
/// an edge there has no length (its far end at `o`: no direction to sort by).
fn sort_ends(cx: &mut Context, s: &mut Scratch, i: usize, j: usize) -> bool {
    let o = cx.pool.p(cx.shared[i]);
    let (pool, rings, shared) = (&cx.pool, &cx.rings, &cx.shared);
    let (leaving, far) = (&mut s.leaving, &mut s.far);
    leaving.clear();
    far.clear();
    for (place, &m) in shared[i..j].iter().enumerate() {
        let node = pool.get(m);
        if node.removed || !rings[node.ring as usize].alive {
            continue;
        }
        let (q, back) = (pool.next(m), pool.p(pool.prev(m)));
        if pool.p(q) == o || back == o {
            return false;
        }
        leaving.push((pool.p(q), place as u32, q));
        far.push(pool.p(q));
    }
    leaving.sort_unstable_by(|a, b| cmp_around(o, a.0, b.0).then(a.1.cmp(&b.1)));
    far.sort_unstable_by(|&a, &b| cmp_xy(a, b));
    true
}

/// The face-walk rule at the position of `cx.shared[i..j]` from the edges sorted by
/// [`sort_ends`]: each arriving edge continues along the leaving edge of greatest angle
/// not past its own way back (the first one clockwise from it, the way back itself
/// first), or else along the one of greatest angle; of several leaving in one direction,
/// the first in `cx.shared`, as [`relink_by_pairs`] picks. O(k log k) for k nodes there.
/// Returns whether an edge arrives from where another one leaves to (see [`any_doubled`]).
fn relink_sorted(cx: &mut Context, s: &mut Scratch, i: usize, j: usize) -> bool {
    let o = cx.pool.p(cx.shared[i]);
    let (leaving, far) = (&s.leaving, &s.far);
    let mut doubled = false;
    for &n in &cx.shared[i..j] {
        if !live(cx, n) {
            continue;
        }
        let back = cx.pool.p(cx.pool.prev(n));
        let Some(&last) = leaving.last() else {
            break;
        };
        // the directions up to the way back, then the last of them (wrapping round)
        let up_to = leaving.partition_point(|e| cmp_around(o, e.0, back) != Ordering::Greater);
        let group = if up_to == 0 { last } else { leaving[up_to - 1] };
        let first = leaving.partition_point(|e| cmp_around(o, e.0, group.0) == Ordering::Less);
        if let Some(&(_, _, target)) = leaving.get(first) {
            s.relink.push((n, target));
        }
        doubled |= far.binary_search_by(|&p| cmp_xy(p, back)).is_ok();
    }
    doubled
}

/// The face-walk rule where edges at X share directions (segments walked several times,
/// as when rounding collapses a spiral), which the rule above cannot order.
///
/// Around a position of a weakly simple boundary, arriving and leaving edges alternate;
/// edges of one direction (a bundle) lie on one another, so their order within the bundle
/// is free, and the sequence must alternate across bundles. With the sequence fixed, each
/// arriving edge continues along the leaving edge just clockwise of it, as the rule says.
/// Fills `s.relink`; false when the edges around X cannot alternate (invalid input).
fn relink_bundles(cx: &mut Context, s: &mut Scratch, i: usize, j: usize) -> bool {
    let o = cx.pool.p(cx.shared[i]);
    // (far end, node arriving at X or target leaving X, arrives), counter-clockwise
    let mut ends = core::mem::take(&mut s.ends);
    ends.clear();
    for &n in &cx.shared[i..j] {
        if live(cx, n) {
            let (prev, next) = (cx.pool.prev(n), cx.pool.next(n));
            ends.push((cx.pool.p(prev), n, true));
            ends.push((cx.pool.p(next), next, false));
        }
    }
    ends.sort_by(|a, b| cmp_around(o, a.0, b.0));
    // Where every bundle is doubled both starts alternate: arriving first makes cracks,
    // leaving first walls, and only the far ends can tell which it is. Elsewhere the
    // bundles that are not doubled decide, and only one start alternates.
    let mut all_doubled = true;
    let mut k = 0;
    while k < ends.len() {
        let e = bundle_end(o, &ends, k);
        let ins = ends[k..e].iter().filter(|x| x.2).count();
        all_doubled &= 2 * ins == e - k;
        k = e;
    }
    let crack = !all_doubled || is_crack(cx, s, i, j);
    let relinked = &mut s.relink;
    let paired = [crack, !crack].into_iter().any(|first_arrives| {
        relinked.clear();
        pair_alternating(o, &ends, first_arrives, |n, target| {
            relinked.push((n, target));
            true
        })
    });
    s.ends = ends;
    paired
}

/// Whether some edge at the position of `cx.shared[i..j]` arrives from where another one
/// leaves to: a segment walked both ways, a wall or a crack. Allocates nothing.
fn any_doubled(cx: &Context, i: usize, j: usize) -> bool {
    let nodes = &cx.shared[i..j];
    nodes.iter().filter(|&&n| live(cx, n)).any(|&n| {
        let from = cx.pool.p(cx.pool.prev(n));
        nodes
            .iter()
            .filter(|&&m| live(cx, m))
            .any(|&m| cx.pool.p(cx.pool.next(m)) == from)
    })
}

/// Whether the region lies on both sides of the doubled edge from `x` to `y` — a crack
/// into it rather than a wall between two parts of the outside — read at `y`, where an
/// edge that is not doubled says which sectors are inside. `None` when every edge at `y`
/// is doubled too.
fn crack_at(cx: &Context, y_node: NodeId, x: Point, nets: &mut Vec<(Point, i32)>) -> Option<bool> {
    let y = cx.pool.p(y_node);
    let shared = &cx.shared;
    let from = shared.partition_point(|&n| cmp_xy(cx.pool.p(n), y) == Ordering::Less);
    let to = shared.partition_point(|&n| cmp_xy(cx.pool.p(n), y) != Ordering::Greater);
    let nodes = &shared[from..to];
    // (far end, +1 arriving / -1 leaving), counter-clockwise around y
    nets.clear();
    let mut add = |n: NodeId| {
        nets.push((cx.pool.p(cx.pool.prev(n)), 1));
        nets.push((cx.pool.p(cx.pool.next(n)), -1));
    };
    if nodes.is_empty() {
        add(y_node); // y is visited once
    } else {
        nodes.iter().filter(|&&n| live(cx, n)).for_each(|&n| add(n));
    }
    inside_along(y, nets, x)
}

/// Whether the doubled edges through the position of `cx.shared[i..j]` are cracks into the
/// region (its inside on both sides) rather than walls, as read at their far ends; walls
/// when no far end tells.
fn is_crack(cx: &mut Context, s: &mut Scratch, i: usize, j: usize) -> bool {
    let x = cx.pool.p(cx.shared[i]);
    let mut nets = core::mem::take(&mut s.nets);
    let crack = cx.shared[i..j]
        .iter()
        .filter(|&&n| live(cx, n))
        .find_map(|&n| crack_at(cx, cx.pool.prev(n), x, &mut nets))
        .unwrap_or(false);
    s.nets = nets;
    crack
}

/// Traces the rings again after re-linking: each cycle becomes a ring of its own, an outer
/// boundary (depth 0) or a hole (depth 1). The old ring entries stay, dead, for reporting.
fn retrace(cx: &mut Context, s: &mut Scratch) {
    let old = cx.rings.len();
    let crossing = cx.lenient && !cx.crossings.is_empty();
    for k in 0..cx.pool.len() {
        let n = NodeId(k as u32);
        let ring = cx.pool.get(n).ring as usize;
        if ring >= old || !live(cx, n) {
            continue;
        }
        let index = cx.rings.len() as u32;
        let input = cx.rings[ring].input;
        let mut len = 0;
        let mut area = 0.0;
        let mut at = RightmostVisit::new(n, cx.pool.p(n));
        let mut m = n;
        loop {
            cx.pool.get_mut(m).ring = index;
            len += 1;
            area += approx_cross(cx.pool.p(m), cx.pool.p(cx.pool.next(m)));
            at.visit(m, cx.pool.p(m), turn(cx, m));
            m = cx.pool.next(m);
            if m == n {
                break;
            }
        }
        let RightmostVisit {
            node: rightmost,
            mut hole,
            turns,
            flat,
            ..
        } = at;
        if !turns && !flat {
            // Every visit there is the tip of a wall the ring runs out along and back
            // (joining rings leaves such walls where a hole cancelled a lobe): decide on
            // the ring's net boundary.
            hole = net_boundary_counter_clockwise(&cx.pool, n, &mut s.net_edges) == Some(false);
        }
        if cx.lenient && area != 0.0 {
            // With crossing edges the turn at one vertex may not tell the winding of the
            // whole; the (approximate) signed area does better for such input.
            hole = area < 0.0;
        }
        cx.rings.push(Ring {
            input,
            start: n,
            len,
            rightmost,
            depth: u32::from(hole),
            // A cycle that never turns is a zero-width wall (edges walked both ways):
            // it encloses nothing, and no hole may bridge to it. (Lenient mode keeps it
            // on crossing input: its repairs there were tuned with such walls in place.)
            alive: !flat || crossing,
            merged: false,
            component: index,
        });
    }
    for ring in &mut cx.rings[..old] {
        ring.alive = false;
    }
}

/// The turn prev(n) → n → next(n).
fn turn(cx: &Context, n: NodeId) -> Orientation {
    let pool = &cx.pool;
    orient2d(pool.p(pool.prev(n)), pool.p(n), pool.p(pool.next(n)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::random;

    /// Nests `rings` and joins them; the number of holes, and the live rings' lengths.
    fn joined(rings: &[&[[f64; 2]]]) -> (usize, Vec<u32>) {
        let (vertices, starts) = crate::testing::flatten(rings);
        let (mut cx, mut st) = crate::testing::nested(&vertices, &starts, false);
        let holes = join(&mut cx, &mut st.touch);
        assert_eq!(refuse_rings_winding_twice(&mut cx, &mut st.touch), Ok(()));
        let mut lens: Vec<u32> = cx.rings.iter().filter(|r| r.alive).map(|r| r.len).collect();
        lens.sort_unstable();
        // every live ring is a closed list again, its nodes numbered with it
        for (r, ring) in cx.rings.iter().enumerate().filter(|(_, r)| r.alive) {
            let nodes: Vec<_> = cx.pool.ring(ring.start).collect();
            assert_eq!(nodes.len(), ring.len as usize);
            assert!(nodes.iter().all(|&n| cx.pool.get(n).ring as usize == r));
        }
        (holes, lens)
    }

    #[test]
    fn holes_touching_at_a_vertex_become_one_boundary() {
        let outer = [[0.0, 0.0], [8.0, 0.0], [8.0, 8.0], [0.0, 8.0]];
        let left = [[4.0, 4.0], [2.0, 5.0], [2.0, 3.0]];
        let right = [[4.0, 4.0], [6.0, 3.0], [6.0, 5.0]];
        // the two holes meet at (4, 4): one hole boundary visiting it twice
        assert_eq!(joined(&[&outer, &left, &right]), (1, vec![4, 6]));
        // apart, they stay two holes
        let right_apart = [[5.0, 4.0], [6.0, 3.0], [6.0, 5.0]];
        assert_eq!(joined(&[&outer, &left, &right_apart]), (2, vec![3, 3, 4]));
    }

    #[test]
    fn a_hole_touching_its_outer_ring_joins_it() {
        // the hole's corner lies on the outer ring's corner: the outer boundary now runs
        // round the hole through that corner (a zero-length bridge)
        let outer = [[0.0, 0.0], [8.0, 0.0], [8.0, 8.0], [0.0, 8.0]];
        let hole = [[0.0, 0.0], [3.0, 1.0], [1.0, 3.0]];
        assert_eq!(joined(&[&outer, &hole]), (0, vec![7]));
    }

    /// Petals round the origin, between directions picked from a small integer grid (so
    /// that some edges leave the origin in one direction, with different lengths), dealt
    /// out to a few rings, each passing the origin once per petal; every ring given either
    /// way round.
    fn petal_rings(next: &mut impl FnMut(u64) -> u64, repeat: bool) -> (Vec<[f64; 2]>, Vec<usize>) {
        let origin = Point::new(0.0, 0.0);
        let mut directions: Vec<Point> = (0..9 + next(40))
            .map(|_| Point::new(next(13) as f64 - 6.0, next(13) as f64 - 6.0))
            .filter(|&d| d != origin)
            .collect();
        directions.sort_by(|&a, &b| cmp_around(origin, a, b).then(cmp_xy(a, b)));
        directions.dedup();
        let rings = 1 + next(4) as usize;
        let mut petals: Vec<Vec<[f64; 2]>> = vec![Vec::new(); rings];
        // petals from each direction to the next, some sharing a direction with the one
        // before (their edges along it lie on one another)
        let mut t = 0;
        while t + 1 < directions.len() {
            let (a, b) = (directions[t], directions[t + 1]);
            t += 1 + next(2) as usize;
            // a proper left turn from a to b, so that petals do not overlap
            if orient2d(origin, a, b) != Orientation::CounterClockwise {
                continue;
            }
            let (ra, rb) = (1 + next(3), 1 + next(3));
            // with `repeat`, some petals twice, in two rings (lenient input)
            for _ in 0..1 + usize::from(repeat && next(3) == 0) {
                let ring = &mut petals[next(rings as u64) as usize];
                ring.push([0.0, 0.0]);
                ring.push([a.x * ra as f64, a.y * ra as f64]);
                ring.push([b.x * rb as f64, b.y * rb as f64]);
            }
        }
        let (mut vertices, mut starts) = (Vec::new(), Vec::new());
        for mut ring in petals.into_iter().filter(|r| r.len() >= 3) {
            if next(2) == 0 {
                ring.reverse();
            }
            starts.push(vertices.len());
            vertices.extend(ring);
        }
        (vertices, starts)
    }

    #[test]
    fn sorted_relink_pairs_edges_as_the_pairwise_rule_does() {
        let mut next = random(0x5eed_2024);
        let mut compared = 0;
        for case in 0..800 {
            let lenient = case % 2 == 1;
            let (vertices, starts) = petal_rings(&mut next, lenient);
            let mut cx = Context::default();
            cx.reset(lenient);
            let mut st = crate::triangulator::pipeline::Stages::default();
            let nesting = crate::Nesting::Auto;
            let checked = crate::triangulator::pipeline::check_input(
                &mut cx, &mut st, &vertices, &starts, nesting, false,
            );
            if !matches!(checked, Ok(true)) {
                continue;
            }
            let s = &mut st.touch;
            let mut i = 0;
            while i < cx.shared.len() {
                let j = cx.same_position_end(i);
                let o = cx.pool.p(cx.shared[i]);
                s.relink.clear();
                relink_by_pairs(&mut cx, s, i, j, o);
                let mut by_pairs = s.relink.clone();
                let doubled = any_doubled(&cx, i, j);
                s.relink.clear();
                assert!(sort_ends(&mut cx, s, i, j));
                assert_eq!(relink_sorted(&mut cx, s, i, j), doubled, "doubled at {o:?}");
                let mut sorted = s.relink.clone();
                by_pairs.sort_unstable();
                sorted.sort_unstable();
                assert_eq!(sorted, by_pairs, "at {o:?} in {vertices:?} {starts:?}");
                compared += usize::from(j - i > FEW_AT_ONE_POSITION);
                i = j;
            }
        }
        assert!(compared > 100, "only {compared} positions with many nodes");
    }
}
