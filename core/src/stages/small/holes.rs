//! Steps 5 and 6 of the small stage: which ring is the polygon's boundary and which are
//! its holes (as `nest` decides them, for rings that meet nowhere or only touch), and the
//! bridges from the holes to the ring around them (as `bridge` chooses them). Whatever the
//! pipeline would decide by a rule this stage does not repeat — a hole inside a hole,
//! several outer rings, a target picked by a fallback — hands the input back.

use core::cmp::Ordering;

use super::touch::{group_end, ring_of};
use super::{bit, members, reverse, ring_mask, ring_masks, winding, Mask, Scratch, RINGS};
use crate::geom::{cmp_around, compare_hits, corner_contains, left_of, on_ray, LeastAngle, Point};
use crate::Nesting;

/// Step 5: decides the rings' roles by containment — exactly one ring contains every
/// other, and no other contains another — and turns the holes clockwise. `false`
/// otherwise, or when `FirstIsOuter` names another ring the boundary (the pipeline then
/// reports or repairs it). A ring with vertices no other ring touches is tested against
/// the others by crossing parity at them ([`off_side`]); one whose every vertex another
/// ring touches, by [`contains`].
pub(super) fn nest<const N: usize, M: Mask>(s: &mut Scratch<N, M>, nesting: Nesting) -> bool {
    let meets = Meets::of(s);
    let mut outer = None;
    for b in 0..s.rings {
        // (a vertex no other ring touches lies on no other ring: parity there decides)
        let untouched = s.ring(b).find(|&v| s.touched & bit(v) == M::NONE);
        // the rings b meets at shared positions (itself among them, if it does)
        let met = match meets {
            Some(ref meets) => s.ring(b).fold(0, |m, v| m | meets.rings[v]),
            None => 0,
        };
        let mut depth = 0;
        for r in (0..s.rings).filter(|&r| r != b) {
            let within = match (untouched, &meets) {
                (Some(v), Some(meets)) if met & 1 << r != 0 => off_side(s, meets, r, b, v),
                (Some(v), _) => Some(inside(s, r, s.p[v])),
                (None, _) => contains(s, r, b),
            };
            match within {
                Some(within) => depth += usize::from(within),
                None => return false,
            }
        }
        match depth {
            0 if outer.is_none() => outer = Some(b),
            1 => {}
            _ => return false,
        }
    }
    let Some(outer) = outer else {
        return false;
    };
    if nesting == Nesting::FirstIsOuter && outer != 0 {
        return false;
    }
    // (every hole has depth 1, so it lies in the outer ring: one hole inside another
    // would have depth 2)
    s.outer = outer;
    for r in (0..s.rings).filter(|&r| r != outer) {
        reverse(s, r);
        s.hole_rings |= 1 << r;
    }
    true
}

/// Where rings meet, for [`off_side`]: per node at a shared position, the rings with a
/// node there (one bit each), its own ring and where its position's nodes start in
/// `s.shared`.
struct Meets<const N: usize> {
    rings: [u8; N],
    ring: [u8; N],
    group: [u8; N],
}

impl<const N: usize> Meets<N> {
    /// `None` where no rings meet.
    fn of<M: Mask>(s: &Scratch<N, M>) -> Option<Self> {
        if s.shared_len == 0 {
            return None;
        }
        let masks = ring_masks(s);
        let mut meets = Meets {
            rings: [0; N],
            ring: [0; N],
            group: [0; N],
        };
        let mut i = 0;
        while i < s.shared_len {
            let j = group_end(s, i);
            let group = &s.shared[i..j];
            let here = (group.iter()).fold(M::NONE, |m, &v| m | bit::<M>(v.into()));
            let rings = (0..s.rings)
                .filter(|&r| masks[r] & here != M::NONE)
                .fold(0u8, |m, r| m | 1 << r);
            for &v in group {
                let v = usize::from(v);
                meets.rings[v] = rings;
                meets.ring[v] = ring_of(s, v) as u8;
                meets.group[v] = i as u8;
            }
            i = j;
        }
        Some(meets)
    }
}

/// Whether ring `r` contains ring `b`, which has vertices no ring touches (`v` the first)
/// and meets r; `None` where b's parts do not agree. b's boundary off r lies on one side
/// of r piece by piece (the rings do not cross, and a vertex inside an edge was split
/// there), so each piece is read once: a stretch of vertices off r by crossing parity at
/// its first vertex, an edge between two vertices on r but not along r (a chord) by b's
/// corner at its start ([`locally_inside`]). One vertex's answer would do for valid
/// rings; but b may lie partly inside r where r cancels lobes of b, or b crosses r at vertices they share,
/// which the pipeline decides at b's rightmost vertex and refuses, while one vertex's
/// answer may make that pass here.
fn off_side<const N: usize, M: Mask>(
    s: &Scratch<N, M>,
    meets: &Meets<N>,
    r: usize,
    b: usize,
    v: usize,
) -> Option<bool> {
    // (a node at no shared position meets no ring)
    let on_r = |u: usize| meets.rings[u] & 1 << r != 0;
    let within = inside(s, r, s.p[v]);
    for u in s.ring(b).filter(|&u| u != v) {
        let side = if !on_r(u) {
            // (the first vertex of a stretch off r)
            if !on_r(s.prev(u)) {
                continue;
            }
            inside(s, r, s.p[u])
        } else if on_r(s.next(u)) {
            // (along an edge of r it says nothing: r has a node at u's position whose
            // edge in or out ends where b's edge out of u does)
            let ahead = s.p[s.next(u)];
            let group = &s.shared[usize::from(meets.group[u])..s.shared_len];
            let here = group.iter().map(|&w| usize::from(w));
            let mut at_u = here.take_while(|&w| s.p[w] == s.p[u]);
            let along = |w: usize| s.p[s.next(w)] == ahead || s.p[s.prev(w)] == ahead;
            if at_u.any(|w| usize::from(meets.ring[w]) == r && along(w)) {
                continue;
            }
            match locally_inside(s, r, u)[0] {
                Some(side) => side,
                None => continue,
            }
        } else {
            continue;
        };
        if side != within {
            return None;
        }
    }
    Some(within)
}

/// Whether ring `r` contains ring `b`, as `nest` decides it; `None` where the stage does
/// not decide.
///
/// Where b touches r nowhere, b's boundary lies inside r or outside it (the rings do not
/// cross), and crossing parity at any vertex of b decides (exact: it lies on none of r's
/// edges). Where they touch, `nest` decides at the first vertex of b, from its rightmost,
/// that can: at a vertex off r by parity, at one on r by b's edges there
/// ([`locally_inside`]); where none can, b lies on r's boundary with its corners inside
/// r's, and r contains it (unless cleaning dropped a vertex of b, which `nest` would look
/// at). Here every vertex on r is asked, and one off r, and they must agree, or the input
/// goes back: where b's boundary is partly inside r (holes overlapping at a corner of
/// their outer ring, say, which the check of shared positions does not see), `nest`'s
/// answer is its first vertex's, and the pipeline refuses what follows from it. That
/// suffices: between two vertices on r, b's boundary stays on one side of r, the side
/// its edges at those vertices give.
fn contains<const N: usize, M: Mask>(s: &Scratch<N, M>, r: usize, b: usize) -> Option<bool> {
    let on_r = |v: usize| s.touched & bit(v) != M::NONE && s.ring(r).any(|w| s.p[w] == s.p[v]);
    let (mut answer, mut off, mut touching) = (None, None, false);
    for v in s.ring(b) {
        if !on_r(v) {
            off = off.or(Some(v));
            continue;
        }
        touching = true;
        for within in locally_inside(s, r, v).into_iter().flatten() {
            if *answer.get_or_insert(within) != within {
                return None;
            }
        }
    }
    if let Some(v) = off {
        let within = inside(s, r, s.p[v]);
        if !touching {
            return Some(within);
        }
        if *answer.get_or_insert(within) != within {
            return None;
        }
    }
    if answer.is_some() {
        return answer;
    }
    let input = usize::from(s.first[s.rings]);
    let loaded = usize::from(s.first[b + 1] - s.first[b]);
    (s.ring(b).filter(|&v| v < input).count() == loaded).then_some(true)
}

/// What b's vertex `v`, at a position of ring `r`, can tell of whether r contains b, as
/// `nest`'s `locally_inside` reads it there: for each of b's edges at v (to its
/// successor, from its predecessor) not along r, whether the sector just
/// counter-clockwise of it lies inside r (`nest` asks the first such edge that runs along
/// no other ring, or failing that, anywhere, the first); with both along r, "outside"
/// where r leaves some part of b's corner, else nothing.
fn locally_inside<const N: usize, M: Mask>(
    s: &Scratch<N, M>,
    r: usize,
    v: usize,
) -> [Option<bool>; 2] {
    let o = s.p[v];
    let (vn, vp) = (s.p[s.next(v)], s.p[s.prev(v)]);
    // the far ends of r's edges through o
    let ends = || {
        (s.ring(r))
            .filter(move |&w| s.p[w] == o)
            .flat_map(move |w| [s.p[s.next(w)], s.p[s.prev(w)]])
    };
    // r's winding number just above the ray from o towards +x: its edges through o
    // cross no such ray (nor count in `winding`: o lies on their lines)
    let base = winding(s, r, o);
    let off = [vn, vp].map(|d| {
        let along = ends().any(|e| on_ray(o, e, d));
        (!along).then(|| winding_after(s, r, o, d, base) > 0)
    });
    if off.iter().any(Option::is_some) {
        return off;
    }
    // both along r: every sector of b's corner, from its first edge and from each of r's
    // edges inside the corner, must lie inside r
    let inside_corner = |e: Point| e != o && corner_contains(o, vn, vp, e) == Some(true);
    let mut sectors = core::iter::once(vn).chain(ends().filter(|&e| inside_corner(e)));
    let outside = sectors.any(|d| winding_after(s, r, o, d, base) <= 0);
    [outside.then_some(false), None]
}

/// The winding number of ring `r` in the sector just counter-clockwise of the direction
/// from `o`, a position of r, to `d`: `base`, r's winding number just above the ray from
/// `o` towards +x, plus one for each edge of r leaving o, minus one for each arriving,
/// whose direction lies counter-clockwise from that ray up to d's (as `nest`'s
/// `locally_inside` counts).
fn winding_after<const N: usize, M: Mask>(
    s: &Scratch<N, M>,
    r: usize,
    o: Point,
    d: Point,
    base: i64,
) -> i64 {
    let counts =
        |e: Point| i64::from(e != o && !(e.y == o.y && e.x > o.x) && cmp_around(o, e, d).is_le());
    let mut w = base;
    for v in s.ring(r).filter(|&v| s.p[v] == o) {
        w += counts(s.p[s.next(v)]) - counts(s.p[s.prev(v)]);
    }
    w
}

/// Whether `q`, on no edge of ring `r`, lies inside it: the ring winds round it (`nest`'s
/// count).
fn inside<const N: usize, M: Mask>(s: &Scratch<N, M>, r: usize, q: Point) -> bool {
    winding(s, r, q) != 0
}

/// Step 6: merges every hole into the ring around it (the outer ring, or one of the
/// polygons touching rings make), in `bridge`'s order (descending
/// rightmost x, then lower y, then ring number), each through a two-way bridge from its
/// rightmost vertex M to the node `bridge` connects it to. The bridge's two new nodes
/// follow the others, the copy of the target first, as the pool numbers them. `false`
/// where the pipeline would choose by a fallback.
pub(super) fn bridge<const N: usize, M: Mask>(s: &mut Scratch<N, M>) -> bool {
    let mut order = [0u8; RINGS];
    let mut holes = 0;
    let mut merged = M::NONE;
    for r in 0..s.rings {
        if s.hole_rings & 1 << r == 0 {
            merged |= ring_mask(s, r);
        } else {
            order[holes] = r as u8;
            holes += 1;
        }
    }
    let key = |s: &Scratch<N, M>, r: u8| s.p[usize::from(s.rightmost[usize::from(r)])];
    let order = &mut order[..holes];
    // (an insertion sort: a handful of holes)
    for i in 1..order.len() {
        let mut j = i;
        while j > 0 && {
            let (a, b) = (order[j - 1], order[j]);
            let (pa, pb) = (key(s, a), key(s, b));
            (pb.x
                .total_cmp(&pa.x)
                .then(pa.y.total_cmp(&pb.y))
                .then(a.cmp(&b)))
                == Ordering::Greater
        } {
            order.swap(j - 1, j);
            j -= 1;
        }
    }
    for &hole in order.iter() {
        let hole = usize::from(hole);
        let m = usize::from(s.rightmost[hole]);
        let Some(x) = target(s, merged, m) else {
            return false;
        };
        // (the hole's nodes, before the split links its ring into the outer one)
        let hole_nodes = ring_mask(s, hole);
        // `Pool::split`: x → m … m's predecessor → m2 → x2 → x's old successor
        let (xn, mp) = (s.next(x), s.prev(m));
        let (x2, m2) = (s.nodes, s.nodes + 1);
        s.nodes += 2;
        for (copy, of) in [(x2, x), (m2, m)] {
            s.p[copy] = s.p[of];
            s.vertex[copy] = s.vertex[of];
        }
        s.next[x] = m as u8;
        s.prev[m] = x as u8;
        s.next[mp] = m2 as u8;
        (s.prev[m2], s.next[m2]) = (mp as u8, x2 as u8);
        (s.prev[x2], s.next[x2]) = (m2 as u8, xn as u8);
        s.prev[xn] = x2 as u8;
        merged |= hole_nodes | bit::<M>(x2) | bit(m2);
        s.fresh |= bit::<M>(x) | bit(m) | bit(x2) | bit(m2);
    }
    true
}

/// The merged node hole vertex `m` connects to (`bridge::find_hole_bridge`): the ray from
/// M towards +x hits the nearest upward edge with M on its inner side; at a vertex, that
/// one, else the edge's endpoint P with larger x or the vertex in triangle M, I, P at the
/// least angle to the ray; there, the node whose corner holds the direction to M. `None`
/// when the ray hits nothing, or no node's corner holds M strictly, or more than one does.
fn target<const N: usize, M: Mask>(s: &Scratch<N, M>, merged: M, m: usize) -> Option<usize> {
    let pm = s.p[m];
    let mut best: Option<(Point, Point)> = None;
    for a in members(merged) {
        let (pa, pb) = (s.p[a], s.p[s.next(a)]);
        if !(pa.y <= pm.y && pm.y <= pb.y && pa.y < pb.y && left_of(pa, pb, pm)) {
            continue;
        }
        // (a tie is a hit at one vertex, which both edges give as the target)
        let nearer = match best {
            Some((c, d)) => compare_hits(pm.y, c, d, pa, pb) == Ordering::Less,
            None => true,
        };
        if nearer {
            best = Some((pa, pb));
        }
    }
    let (pa, pb) = best?;
    let target = if pa.y == pm.y {
        pa
    } else if pb.y == pm.y {
        pb
    } else {
        // (`bridge::least_angle_in_triangle` over the merged nodes)
        let p = if pb.x > pa.x { pb } else { pa };
        let mut search = LeastAngle::new(pm, pa, pb, p);
        for q in members(merged).map(|r| s.p[r]) {
            if search.near(q) {
                search.offer(q);
            }
        }
        search.best()
    };
    let mut found = None;
    for x in members(merged).filter(|&x| s.p[x] == target) {
        if corner_contains(target, s.p[s.next(x)], s.p[s.prev(x)], pm) == Some(true) {
            if found.is_some() {
                return None;
            }
            found = Some(x);
        }
    }
    found
}
