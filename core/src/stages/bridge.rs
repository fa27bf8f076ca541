//! Stage 4, *bridge*: merge every hole into the ring around it through a two-way bridge
//! between mutually visible vertices (Eberly's method, with the clarifications of
//! Kotsarenko 2024 §3.2).
//!
//! Holes go by descending rightmost x (ties: lower y first). From a hole's rightmost vertex
//! M a ray runs towards +x; the nearest edge it hits, among rings already merged, belongs
//! to the polygon around the hole (everything left of M is still unmerged, everything
//! merged and hit first is this polygon's boundary). Then:
//!
//! - the ray hits a vertex: that vertex is visible;
//! - it hits an edge inside at I: P is the edge's endpoint with the larger x (ties: lower
//!   y); any vertex inside the triangle M, I, P (or on segment MP) may block the view, and
//!   the one at the smallest angle to the ray, then nearest, is visible instead.
//! - it hits M itself (a ring touching the hole at M): a zero-length bridge.
//!
//! Where the chosen position has several nodes (earlier bridges, rings touching there), the
//! node whose corner contains the direction to M is the one to connect (the paper's Fig. 6c:
//! several edges at the hit vertex). A ray along two coincident bridge edges hits only the
//! one that has M on its inner side (Fig. 6a/b): with every ring's interior on the left,
//! only upward edges with M strictly left of them count.
//!
//! All decisions are exact orientation tests. The searches use the edge index of
//! `context`: in its grid the ray walks one row of cells from M and stops past its nearest
//! hit, the triangle search looks at the cells of the triangle's box, so a hole costs a
//! few cells, not the polygon; a few edges with a hole or two are only listed, and every
//! search looks at all of them.

use core::cmp::Ordering;

use crate::context::Context;
use crate::geom::{compare_hits, corner_contains, on_ray, LeastAngle};
use crate::geom::{left_of, Point};
use crate::structures::NodeId;
use crate::Error;

/// Scratch buffers of the bridge stage, kept between calls.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// The holes, by descending rightmost x (ties: lower y, then ring number).
    order: Vec<u32>,
}

/// How a lenient run bridges holes whose rightmost vertex pokes into a hole bridged
/// before, and what it found.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Careful {
    /// Bridge such a hole from one of its vertices that sees its target properly (a
    /// costly search: only the careful rerun asks for it).
    pub bridges: bool,
    /// Set when some bridge left the polygon (the careful rerun may then do better).
    pub bridge_left: bool,
}

/// Merges every live hole (odd depth) into the ring around it.
pub(crate) fn bridge(
    cx: &mut Context,
    s: &mut Scratch,
    careful: &mut Careful,
) -> Result<(), Error> {
    careful.bridge_left = false;
    s.order.clear();
    for r in 0..cx.rings.len() {
        let ring = &mut cx.rings[r];
        ring.merged = ring.alive && ring.depth % 2 == 0;
        ring.component = r as u32;
        if ring.alive && ring.depth % 2 == 1 {
            s.order.push(r as u32);
        }
    }
    if s.order.is_empty() {
        return Ok(());
    }
    cx.edge_index.ensure(&cx.pool, &cx.rings, s.order.len());
    let (pool, rings) = (&cx.pool, &cx.rings);
    s.order.sort_unstable_by(|&a, &b| {
        let (pa, pb) = (
            pool.p(rings[a as usize].rightmost),
            pool.p(rings[b as usize].rightmost),
        );
        pb.x.total_cmp(&pa.x)
            .then(pa.y.total_cmp(&pb.y))
            .then(a.cmp(&b))
    });
    for k in 0..s.order.len() {
        let hole = s.order[k] as usize;
        eliminate_hole(cx, careful, hole)?;
    }
    Ok(())
}

/// Bridges one hole into the ring around it.
fn eliminate_hole(cx: &mut Context, careful: &mut Careful, hole: usize) -> Result<(), Error> {
    let mut m = cx.rings[hole].rightmost;
    let target = match find_touching(cx, m) {
        Some(x) => Target::Touching(x),
        None => match find_hole_bridge(cx, m) {
            Some(x) if cx.lenient && bridge_leaves_polygon(cx, m, x) => {
                // M pokes into a hole bridged before (their edges cross): the bridge runs
                // inside that hole, or out of it across its boundary, and turns the hole
                // inside out. The careful run bridges from a vertex of the hole that sees
                // its target properly; the others keep the ray's choice (see `triangulate`).
                careful.bridge_left = true;
                // (only the careful run looks for that vertex: the search is costly)
                let elsewhere = if careful.bridges {
                    bridge_from_elsewhere(cx, m, true)
                } else {
                    None
                };
                match elsewhere {
                    Some((other, x)) => {
                        m = other;
                        Target::Visible(x)
                    }
                    None => Target::Visible(x),
                }
            }
            Some(x) => Target::Visible(x),
            None if cx.lenient => match bridge_from_elsewhere(cx, m, false) {
                Some((other, x)) => {
                    m = other;
                    Target::Visible(x)
                }
                None => {
                    cx.skip_ring(hole);
                    return Ok(());
                }
            },
            // Every hole of a valid input has a boundary around it, so the ray from M
            // always meets one. Here the hole is a lobe of a ring that winds both ways.
            None => {
                let node = cx.pool.get(m);
                return Err(Error::LobesWindOpposite {
                    ring: cx.rings[node.ring as usize].input as usize,
                    vertex: node.vertex as usize,
                });
            }
        },
    };
    let x = match target {
        Target::Touching(x) | Target::Visible(x) => x,
    };
    let component = cx.rings[cx.pool.get(x).ring as usize].component;
    let x2 = cx.pool.next(x); // becomes the copy's successor after the split
    let m2 = cx.pool.split(x, m);
    let x_copy = cx.pool.next(m2);
    debug_assert_eq!(cx.pool.next(x_copy), x2);
    if let Target::Touching(_) = target {
        // zero-length bridge: x and m coincide, as do m2 and x_copy; both nodes of each pair
        // carry the same vertex index (clean made it so), so dropping one loses nothing
        cx.pool.remove(m);
        cx.pool.remove(x_copy);
        register(cx, x);
        register(cx, m2);
    } else {
        register(cx, x);
        register(cx, m2);
        register(cx, x_copy);
    }
    let len = cx.rings[hole].len;
    let ring = &mut cx.rings[hole];
    ring.merged = true;
    ring.component = component;
    let outer = &mut cx.rings[component as usize];
    outer.len += len + 2;
    if let Target::Touching(_) = target {
        outer.len -= 2;
    }
    Ok(())
}

/// Lenient mode: the ray from the hole's rightmost vertex hits nothing (the hole sticks
/// out of its polygon, say), or, with `clear_of_merged`, its bridge would cross a merged
/// edge. Tries the hole's other vertices, keeping a bridge that crosses none of the hole's
/// own edges (nor, with `clear_of_merged`, a merged one); returns the hole vertex and its
/// target.
fn bridge_from_elsewhere(
    cx: &Context,
    m: NodeId,
    clear_of_merged: bool,
) -> Option<(NodeId, NodeId)> {
    let mut v = cx.pool.next(m);
    while v != m {
        if let Some(x) = find_hole_bridge(cx, v) {
            if clear_of_merged && bridge_leaves_polygon(cx, v, x) {
                v = cx.pool.next(v);
                continue;
            }
            let (pv, px) = (cx.pool.p(v), cx.pool.p(x));
            let mut e = cx.pool.next(v);
            let mut clear = true;
            while cx.pool.next(e) != v {
                let (a, b) = (cx.pool.p(e), cx.pool.p(cx.pool.next(e)));
                if crate::geom::crosses(pv, px, a, b) {
                    clear = false;
                    break;
                }
                e = cx.pool.next(e);
            }
            if clear {
                return Some((v, x));
            }
        }
        v = cx.pool.next(v);
    }
    None
}

/// Lenient mode, crossing input: whether the bridge from hole vertex `m` to merged node
/// `x` leaves the polygon: `x`'s corner does not hold M, or the bridge crosses an edge of
/// a merged ring. Only asked where `m`'s own edges cross another edge: elsewhere the ray's
/// nearest hit leaves nothing between M and its target.
fn bridge_leaves_polygon(cx: &Context, m: NodeId, x: NodeId) -> bool {
    let pool = &cx.pool;
    if !(pool.get(m).crossed || pool.get(pool.prev(m)).crossed) {
        return false;
    }
    let (pm, px) = (pool.p(m), pool.p(x));
    if corner_contains(px, pool.p(pool.next(x)), pool.p(pool.prev(x)), pm) == Some(false) {
        return true;
    }
    let lo = Point::new(pm.x.min(px.x), pm.y.min(px.y));
    let hi = Point::new(pm.x.max(px.x), pm.y.max(px.y));
    cx.edge_index
        .query(lo, hi)
        .any(|e| is_merged(cx, e) && crate::geom::crosses(pm, px, pool.p(e), pool.p(pool.next(e))))
}

/// How a hole connects.
#[derive(Clone, Copy)]
enum Target {
    /// A merged node at M's own position.
    Touching(NodeId),
    /// A merged node visible from M.
    Visible(NodeId),
}

/// Lists the current edge starting at `n` in the grid index again.
fn register(cx: &mut Context, n: NodeId) {
    let (a, b) = (cx.pool.p(n), cx.pool.p(cx.pool.next(n)));
    cx.edge_index.insert(n, a, b);
}

/// Whether node `n` is on a ring that is merged already (and still linked).
#[inline]
fn is_merged(cx: &Context, n: NodeId) -> bool {
    let node = cx.pool.get(n);
    !node.removed && cx.rings[node.ring as usize].merged
}

/// A merged node at the hole vertex `m`'s own position whose corner holds the hole there:
/// the hole touches its polygon at M. The hole fits when one of its edges at M runs
/// strictly inside the node's corner, or when the hole fills that corner exactly (both
/// edges along the corner's sides: the hole cancels a lobe of the polygon).
fn find_touching(cx: &Context, m: NodeId) -> Option<NodeId> {
    let pm = cx.pool.p(m);
    let (mn, mp) = (cx.pool.p(cx.pool.next(m)), cx.pool.p(cx.pool.prev(m)));
    cx.edge_index.query(pm, pm).find(|&x| {
        if !is_merged(cx, x) || cx.pool.p(x) != pm {
            return false;
        }
        let (xn, xp) = (cx.pool.p(cx.pool.next(x)), cx.pool.p(cx.pool.prev(x)));
        match corner_contains(pm, xn, xp, mn).or_else(|| corner_contains(pm, xn, xp, mp)) {
            Some(inside) => inside,
            // The hole's corner and the polygon's coincide: a hole cancelling a lobe of its
            // polygon, or an island inside the hole touching it there. Only the first is
            // the hole's polygon, as nesting depth tells.
            None => {
                on_ray(pm, mn, xp) && on_ray(pm, mp, xn) && input_depth(cx, x) < input_depth(cx, m)
            }
        }
    })
}

/// The nesting depth of the input ring node `n` came from (rings re-traced by `touch`
/// keep their input's number; the first ring of that number holds the depth `nest` gave).
fn input_depth(cx: &Context, n: NodeId) -> u32 {
    let input = cx.rings[cx.pool.get(n).ring as usize].input;
    cx.rings
        .iter()
        .find(|r| r.input == input)
        .map_or(0, |r| r.depth)
}

/// The node M connects to, found by the ray cast and the triangle search; `None` when the
/// ray hits nothing (the hole lies outside every polygon).
fn find_hole_bridge(cx: &Context, m: NodeId) -> Option<NodeId> {
    let pm = cx.pool.p(m);
    let (a, b) = nearest_hit(cx, pm)?;
    let (pa, pb) = (cx.pool.p(a), cx.pool.p(b));
    let component = cx.rings[cx.pool.get(a).ring as usize].component;
    let target = if pa.y == pm.y {
        pa
    } else if pb.y == pm.y {
        pb
    } else {
        // P: the endpoint with larger x; for a vertical edge the lower one, which for an
        // upward edge is a
        let p = if pb.x > pa.x { pb } else { pa };
        least_angle_in_triangle(cx, pm, pa, pb, p, component)
    };
    visible_node_at(cx, target, pm, component)
}

/// The nearest edge a → b hit by the ray from `pm` towards +x: among merged rings' edges,
/// upward ones (a.y <= M.y <= b.y, a.y < b.y) with M strictly on their left, i.e. seen
/// from the polygon's interior.
///
/// The ray walks the grid row of M column by column (the long edges and those listed for
/// the whole row first). Every edge not seen yet lies wholly in later columns (or meets
/// the row's band only there, for one listed along its segment), so once the best hit's
/// edge ends within the columns walked, no later edge can be hit nearer (columns are
/// monotone in x), and the walk stops.
fn nearest_hit(cx: &Context, pm: Point) -> Option<(NodeId, NodeId)> {
    let mut best = None;
    if let Some(edges) = cx.edge_index.listed() {
        for &a in edges {
            consider_hit(cx, pm, a, &mut best);
        }
        return best;
    }
    let grid = &cx.edge_index.grid();
    let row = grid.row(pm.y);
    let east = Point::new(f64::INFINITY, pm.y);
    for a in grid.long(pm, east).chain(grid.row_list(row)) {
        consider_hit(cx, pm, a, &mut best);
    }
    for column in grid.column(pm.x)..grid.columns() {
        let listed = grid.cell(row, column).chain(grid.column_list(column));
        for a in listed.chain(grid.along(row, column)) {
            consider_hit(cx, pm, a, &mut best);
        }
        if let Some((a, b)) = best {
            if grid.column(cx.pool.p(a).x.max(cx.pool.p(b).x)) <= column {
                break;
            }
        }
    }
    best
}

/// Keeps the edge starting at `a` as `best` when the ray from `pm` hits it (see
/// [`nearest_hit`]) nearer than `best`.
fn consider_hit(cx: &Context, pm: Point, a: NodeId, best: &mut Option<(NodeId, NodeId)>) {
    if !is_merged(cx, a) {
        return;
    }
    let b = cx.pool.next(a);
    let (pa, pb) = (cx.pool.p(a), cx.pool.p(b));
    if !(pa.y <= pm.y && pm.y <= pb.y && pa.y < pb.y && left_of(pa, pb, pm)) {
        return;
    }
    let nearer = match *best {
        Some((c, d)) => compare_hits(pm.y, cx.pool.p(c), cx.pool.p(d), pa, pb) == Ordering::Less,
        None => true,
    };
    if nearer {
        *best = Some((a, b));
    }
}

/// Among the vertices of `component` inside triangle M, I, P (I: the hit on edge a → b) or
/// on segment MP, the one at the smallest angle to the ray, then the nearest; P if none
/// (see [`LeastAngle`]).
fn least_angle_in_triangle(
    cx: &Context,
    pm: Point,
    pa: Point,
    pb: Point,
    p: Point,
    component: u32,
) -> Point {
    let mut search = LeastAngle::new(pm, pa, pb, p);
    let (lo, hi) = search.bounds();
    for r in cx.edge_index.query(lo, hi) {
        // the position first: most candidates fail there, without a look at their ring
        let node = cx.pool.get(r);
        if !search.near(node.p) {
            continue;
        }
        if node.removed || cx.rings[node.ring as usize].component != component {
            continue;
        }
        search.offer(node.p);
    }
    search.best()
}

/// The merged node at position `target` whose corner contains the direction towards M:
/// the occurrence M can connect to without crossing its edges. Nodes of `component` (the
/// polygon of the edge the ray hit) come first; but where the ray hits a vertex that
/// several polygons share, the hit edge may be another polygon's (holes touching at
/// vertices around an island of polygon: the ray from a hole further left meets one of
/// their shared vertices, where the island's edge ties with its surroundings'), and then
/// the node whose corner holds M is of the polygon around M.
fn visible_node_at(cx: &Context, target: Point, pm: Point, component: u32) -> Option<NodeId> {
    let (mut on_side, mut fallback, mut elsewhere, mut tip) = (None, None, None, None);
    for x in cx.edge_index.query(target, target) {
        let node = cx.pool.get(x);
        if node.removed || node.p != target || !cx.rings[node.ring as usize].merged {
            continue;
        }
        let ours = cx.rings[node.ring as usize].component == component;
        let (xn, xp) = (cx.pool.p(node.next), cx.pool.p(node.prev));
        match corner_contains(target, xn, xp, pm) {
            Some(true) if ours => return Some(x),
            Some(true) => elsewhere = elsewhere.or(Some(x)),
            // M straight along one of the corner's sides (collinear edges overlap there)
            None if ours => on_side = on_side.or(Some(x)),
            // The tip of a wall the ring runs out along and back (joining rings where
            // they touch leaves such walls where a hole cancelled a lobe): its corner
            // is empty or the whole turn, and the ray reached it from the region.
            Some(false) if ours && on_ray(target, xn, xp) => tip = tip.or(Some(x)),
            Some(false) if ours => fallback = fallback.or(Some(x)),
            _ => {}
        }
    }
    // No corner contains M: M lies outside the boundary it sees, which only invalid
    // input allows (a lobe winding the other way). Strict mode refuses it.
    match on_side.or(elsewhere).or(tip) {
        Some(x) => Some(x),
        None if cx.lenient => fallback,
        None => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Runs the stages up to bridging; returns the outer ring's vertex sequence.
    fn bridged(vertices: &[[f64; 2]], starts: &[usize]) -> Vec<u32> {
        let (mut cx, mut st) = crate::testing::nested(vertices, starts, false);
        bridge(&mut cx, &mut st.bridge, &mut Careful::default()).unwrap();
        let start = cx.rings[0].start;
        cx.pool.ring(start).map(|n| cx.pool.get(n).vertex).collect()
    }

    /// The vertex the hole vertex `m` was bridged to (its predecessor in the merged ring).
    fn bridge_target(vertices: &[[f64; 2]], starts: &[usize], m: u32) -> u32 {
        let ring = bridged(vertices, starts);
        let k = ring
            .iter()
            .position(|&v| v == m)
            .expect("hole vertex in the merged ring");
        ring[(k + ring.len() - 1) % ring.len()]
    }

    /// Rotates by 90° k times, exactly.
    fn rotated(vertices: &[[f64; 2]], k: usize) -> Vec<[f64; 2]> {
        vertices
            .iter()
            .map(|&[x, y]| match k % 4 {
                0 => [x, y],
                1 => [-y, x],
                2 => [-x, -y],
                _ => [y, -x],
            })
            .collect()
    }

    const SQUARE: [[f64; 2]; 4] = [[0., 0.], [10., 0.], [10., 10.], [0., 10.]];

    #[test]
    fn ray_hits_edge_inside_then_endpoint_with_larger_x_lower_y() {
        // the ray from M = (6,5) hits the vertical edge x = 10 at (10,5): both endpoints
        // have x = 10, so P is the lower one, vertex 1
        let mut v = SQUARE.to_vec();
        v.extend([[4., 4.], [6., 5.], [4., 6.]]);
        assert_eq!(bridge_target(&v, &[0, 4], 5), 1);
    }

    #[test]
    fn ray_hits_vertex_exactly() {
        let v = [
            [0., 0.],
            [10., 0.],
            [12., 5.],
            [10., 10.],
            [0., 10.],
            [4., 4.],
            [6., 5.],
            [4., 6.],
        ];
        assert_eq!(bridge_target(&v, &[0, 5], 6), 2);
    }

    #[test]
    fn reflex_vertex_inside_triangle_blocks_p() {
        // notch tip (8,3) lies inside triangle M(6,5), I(10,5), P(10,0)
        let v = [
            [0., 0.],
            [7., 0.],
            [8., 3.],
            [9., 0.],
            [10., 0.],
            [10., 10.],
            [0., 10.],
            [4., 4.],
            [6., 5.],
            [4., 6.],
        ];
        assert_eq!(bridge_target(&v, &[0, 7], 8), 2);
    }

    #[test]
    fn smallest_angle_to_the_ray_wins() {
        // (8,3) at 45° and (9,4.5) at about 9.5° below the ray: the smaller angle wins
        let v = [
            [0., 0.],
            [7., 0.],
            [8., 3.],
            [8.5, 0.],
            [9., 4.5],
            [9.5, 0.],
            [10., 0.],
            [10., 10.],
            [0., 10.],
            [4., 4.],
            [6., 5.],
            [4., 6.],
        ];
        assert_eq!(bridge_target(&v, &[0, 9], 10), 4);
    }

    #[test]
    fn equal_angles_pick_the_nearest() {
        // (8,4) and (9,3.5) lie on one ray from M = (6,5): the nearer one hides the other
        let v = [
            [0., 0.],
            [7., 0.],
            [8., 4.],
            [8.5, 0.],
            [9., 3.5],
            [9.5, 0.],
            [10., 0.],
            [10., 10.],
            [0., 10.],
            [4., 4.],
            [6., 5.],
            [4., 6.],
        ];
        assert_eq!(bridge_target(&v, &[0, 9], 10), 2);
    }

    #[test]
    fn rules_hold_in_every_rotation_and_winding() {
        // the same configuration rotated and with the outer ring reversed: still bridged to
        // the smallest-angle vertex, whose index does not change
        let v = [
            [0., 0.],
            [7., 0.],
            [8., 3.],
            [8.5, 0.],
            [9., 4.5],
            [9.5, 0.],
            [10., 0.],
            [10., 10.],
            [0., 10.],
            [4., 4.],
            [6., 5.],
            [4., 6.],
        ];
        for k in 0..4 {
            let r = rotated(&v, k);
            // after a rotation another hole vertex is rightmost and the ray runs elsewhere:
            // check that exactly one two-way bridge merged the hole
            let ring = bridged(&r, &[0, 9]);
            assert_eq!(ring.len(), 9 + 3 + 2, "rotation {k}");
        }
        let mut reversed = v[..9].to_vec();
        reversed.reverse();
        reversed.extend_from_slice(&v[9..]);
        // reversed outer: vertex i of the input is now 8 - i
        assert_eq!(bridge_target(&reversed, &[0, 9], 10), 8 - 4);
    }

    #[test]
    fn coincident_bridge_edges_take_the_one_facing_m() {
        // hole A (rightmost (15,10)) is bridged first, to (20,0); hole B's ray from (10,5)
        // hits that bridge at (17.5,5), where two copies run in opposite directions. Only
        // the upward copy has M on its inner side; P is its endpoint (20,0), vertex 1.
        let v = [
            [0., 0.],
            [20., 0.],
            [20., 20.],
            [0., 20.],
            [13., 9.],
            [15., 10.],
            [13., 11.],
            [8., 4.],
            [10., 5.],
            [8., 6.],
        ];
        let ring = bridged(&v, &[0, 4, 7]);
        assert_eq!(ring.len(), 4 + 3 + 3 + 4);
        let k = ring.iter().position(|&x| x == 8).unwrap();
        assert_eq!(ring[(k + ring.len() - 1) % ring.len()], 1);
        // and the ring stays consistent: (20,0) appears three times, once per bridge side
        assert_eq!(ring.iter().filter(|&&x| x == 1).count(), 3);
    }

    #[test]
    fn compare_hits_is_exact() {
        let y = 0.1;
        // two upward edges crossing y = 0.1 at x values that differ by one ulp or so
        let a = Point::new(1.0, 0.0);
        let b = Point::new(1.0 + 3.0 * f64::EPSILON, 0.3);
        let c = Point::new(1.0, -0.1);
        let d = Point::new(1.0, 0.3);
        // c→d is the vertical line x = 1; a→b leans right, so at y = 0.1 it is right of x=1
        assert_eq!(compare_hits(y, a, b, c, d), Ordering::Less);
        assert_eq!(compare_hits(y, c, d, a, b), Ordering::Greater);
        assert_eq!(compare_hits(y, c, d, c, d), Ordering::Equal);
        // edges sharing their endpoint on the line: equal hits
        let e = Point::new(2.0, 0.1);
        assert_eq!(
            compare_hits(y, Point::new(1., -1.), e, e, Point::new(3., 1.)),
            Ordering::Equal
        );
    }
}
