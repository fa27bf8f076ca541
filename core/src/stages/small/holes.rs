//! Steps 5 and 6 of the small stage: which ring is the polygon's boundary and which are
//! its holes (as `nest` decides them, for rings that meet nowhere or only touch), and the
//! bridges from the holes to the ring around them (as `bridge` chooses them). Whatever the
//! pipeline would decide by a rule this stage does not repeat — a hole inside a hole,
//! several outer rings, a target picked by a fallback — hands the input back.

use core::cmp::Ordering;

use super::{bit, members, reverse, ring_mask, winding, Mask, Scratch, RINGS};
use crate::geom::{cmp_around, compare_hits, corner_contains, left_of, on_ray, LeastAngle, Point};
use crate::Nesting;

/// Step 5: decides the rings' roles by containment — exactly one ring contains every
/// other, and no other contains another — and turns the holes clockwise. `false`
/// otherwise, or when `FirstIsOuter` names another ring the boundary (the pipeline then
/// reports or repairs it). The rings do not cross, so one vertex of a ring on no other
/// ring decides for all of it (crossing parity is exact there); a ring every vertex of
/// which another touches is decided against each ring by [`contains`].
pub(super) fn nest<const N: usize, M: Mask>(s: &mut Scratch<N, M>, nesting: Nesting) -> bool {
    let mut outer = None;
    for b in 0..s.rings {
        // (a vertex where no other ring touches: it lies on no other ring)
        let untouched = s.ring(b).find(|&v| s.touched & bit(v) == M::NONE);
        let mut depth = 0;
        for r in (0..s.rings).filter(|&r| r != b) {
            let within = match untouched {
                Some(v) => inside(s, r, s.p[v]),
                None => match contains(s, r, b) {
                    Some(within) => within,
                    None => return false,
                },
            };
            depth += usize::from(within);
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

/// Whether ring `r` contains ring `b`, every vertex of which some other ring touches: by
/// crossing parity at b's first vertex at no position of r, which lies on none of r's
/// edges (a vertex inside an edge split it); the rings do not cross, so it decides for
/// all of b. Where every vertex of b lies at a position of r, as `nest` decides a ring
/// lying on another ([`on_ring`]). `None` where the stage does not decide.
fn contains<const N: usize, M: Mask>(s: &Scratch<N, M>, r: usize, b: usize) -> Option<bool> {
    let on_r = |v: usize| s.ring(r).any(|w| s.p[w] == s.p[v]);
    match s.ring(b).find(|&v| !on_r(v)) {
        Some(v) => Some(inside(s, r, s.p[v])),
        None => on_ring(s, r, b),
    }
}

/// `nest`'s `depth_of` for ring `r` and ring `b`, every vertex of which lies at a
/// position of r: decided at b's rightmost vertex, then at each one after it, by b's first
/// edge there off r and off every other ring ([`locally_inside`]); then again from the
/// rightmost by b's first edge off r alone. Where no vertex decides, b lies on r's
/// boundary with its corners inside r's: r contains it (the pipeline then requires their
/// depths to differ by one, as the stage's roles do) — unless cleaning dropped a vertex of
/// b, which `nest` would look at: `None`.
fn on_ring<const N: usize, M: Mask>(s: &Scratch<N, M>, r: usize, b: usize) -> Option<bool> {
    let first = usize::from(s.rightmost[b]);
    for clear in [true, false] {
        let mut v = first;
        loop {
            if let Some(inside) = locally_inside(s, r, b, v, clear) {
                return Some(inside);
            }
            v = s.next(v);
            if v == first {
                break;
            }
        }
    }
    let input = usize::from(s.first[s.rings]);
    let loaded = usize::from(s.first[b + 1] - s.first[b]);
    (s.ring(b).filter(|&v| v < input).count() == loaded).then_some(true)
}

/// `nest`'s `locally_inside` for ring `r` at b's vertex `v`, on r's position: by b's first
/// edge at v (to its successor, then from its predecessor) not along r — and, if `clear`,
/// along no other ring — whether the sector just counter-clockwise of it lies inside r.
/// With both of b's edges along r: outside if r leaves any part of b's corner there.
/// `None` where v does not decide.
fn locally_inside<const N: usize, M: Mask>(
    s: &Scratch<N, M>,
    r: usize,
    b: usize,
    v: usize,
    clear: bool,
) -> Option<bool> {
    let o = s.p[v];
    let (vn, vp) = (s.p[s.next(v)], s.p[s.prev(v)]);
    // the far ends of ring q's edges through o
    let ends = |q: usize| {
        (s.ring(q))
            .filter(move |&w| s.p[w] == o)
            .flat_map(move |w| [s.p[s.next(w)], s.p[s.prev(w)]])
    };
    let along = |q: usize, d: Point| ends(q).any(|e| on_ray(o, e, d));
    // r's winding number just above the ray from o towards +x: its edges through o
    // cross no such ray (nor count in `winding`: o lies on their lines)
    let base = winding(s, r, o);
    let mut blocked = false;
    for d in [vn, vp] {
        if along(r, d) {
            continue;
        }
        if !(clear && (0..s.rings).any(|q| q != b && q != r && along(q, d))) {
            return Some(winding_after(s, r, o, d, base) > 0);
        }
        blocked = true;
    }
    if blocked {
        return None;
    }
    // both along r: every sector of b's corner, from its first edge and from each of r's
    // edges inside the corner, must lie inside r
    let inside_corner = |e: Point| e != o && corner_contains(o, vn, vp, e) == Some(true);
    let mut sectors = core::iter::once(vn).chain(ends(r).filter(|&e| inside_corner(e)));
    sectors
        .any(|d| winding_after(s, r, o, d, base) <= 0)
        .then_some(false)
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
