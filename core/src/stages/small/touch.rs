//! Rings of the small stage touching at vertices: a hole's vertex on a vertex of the
//! outer ring or of another hole, two nodes at one position, as `clean`, `nest` and
//! `touch` handle them in the pipeline.
//!
//! - The proof ([`record`]) lets two edges of different rings meet where they share an
//!   endpoint and nowhere else (on one line, only leaving it in opposite directions), and
//!   lists the two nodes there; a vertex inside another edge (of any ring) splits it there
//!   as `clean` does ([`split`]). Anything else that meets (edges along each other, a
//!   third node at the position) hands the polygon back.
//! - Both nodes then take the lower vertex index (`super::canonical_vertices`), and strict
//!   mode checks that the rings do not cross there ([`proper`], `nest`'s check of shared
//!   positions).
//! - Before bridging, [`join`] re-links each position by the face-walk rule (`touch`'s
//!   `relink`) and traces the rings again as `touch` does: a hole touching the outer ring
//!   becomes part of it, two touching holes one hole, a ring touching itself two (lobes,
//!   or a polygon and its hole), a hole touching the outer ring twice cuts it in two
//!   polygons; each ring starts at its lowest node. Whatever `touch` would decide by a
//!   rule this does not repeat (a conflict, a wall, a ring wound twice) hands the polygon
//!   back.

use super::{bit, Mask, Scratch, RINGS, TOUCHES};
use crate::geom::{
    clockwise_before, cmp_around, cmp_xy, orient2d, ray_crossing, same_ray, within_box,
    Orientation, Point, RightmostVisit,
};

/// The proof found edges `k` and `m` (indices into `s.boxes`) meeting: whether only at an
/// endpoint they share, of two different rings, and not along one line; then the two
/// nodes there are listed (once per position). False, to hand the polygon back, for any
/// other contact, or too many.
pub(super) fn record<const N: usize, M: Mask>(s: &mut Scratch<N, M>, k: usize, m: usize) -> bool {
    let (e, f) = (usize::from(s.from[k]), usize::from(s.from[m]));
    let (e2, f2) = (s.next(e), s.next(f));
    let mut shared = None;
    for (x, x_other) in [(e, e2), (e2, e)] {
        for (y, y_other) in [(f, f2), (f2, f)] {
            if s.p[x] == s.p[y] {
                if shared.is_some() {
                    return false; // the same segment twice
                }
                shared = Some((x, x_other, y, y_other));
            }
        }
    }
    let Some((x, x_other, y, y_other)) = shared else {
        // a vertex inside the other edge (or a crossing)
        return match tee(s, e, f) {
            Some(listed) => listed,
            None => tee(s, f, e) == Some(true),
        };
    };
    // two lines meet in one point; on one line the edges overlap unless they leave x
    // in opposite directions
    let (o, a, b) = (s.p[x], s.p[x_other], s.p[y_other]);
    if orient2d(o, a, b) == Orientation::Collinear && same_ray(o, a, b) {
        return false;
    }
    let pair = [x.min(y) as u8, x.max(y) as u8];
    if s.touch[..s.touches].contains(&pair) {
        return true;
    }
    let both = bit::<M>(x) | bit(y);
    if s.touched & both != M::NONE || s.touches + s.tees == TOUCHES {
        return false; // a third node at the position
    }
    s.touch[s.touches] = pair;
    s.touches += 1;
    s.touched |= both;
    true
}

/// The input ring of input node `v`.
fn ring<const N: usize, M: Mask>(s: &Scratch<N, M>, v: usize) -> usize {
    (0..s.rings)
        .rfind(|&r| usize::from(s.first[r]) <= v)
        .unwrap_or(0)
}

/// The input ring of node `v`: an input node's, or for a node splitting an edge, the
/// edge's.
fn ring_of<const N: usize, M: Mask>(s: &Scratch<N, M>, v: usize) -> usize {
    let n = usize::from(s.first[s.rings]);
    match v.checked_sub(n) {
        Some(k) if k < TOUCHES => ring(s, usize::from(s.split_of[k])),
        _ => ring(s, v),
    }
}

/// The other node at touched node `v`'s position.
fn partner<const N: usize, M: Mask>(s: &Scratch<N, M>, v: usize) -> Option<usize> {
    s.touch[..s.touches].iter().find_map(|&[a, b]| {
        let (a, b) = (usize::from(a), usize::from(b));
        (a == v).then_some(b).or((b == v).then_some(a))
    })
}

/// Whether touched node `v`'s position is another visit of its own ring.
pub(super) fn touches_own_ring<const N: usize, M: Mask>(s: &Scratch<N, M>, v: usize) -> bool {
    partner(s, v).is_some_and(|w| ring_of(s, w) == ring_of(s, v))
}

/// [`record`] where edges e and f (by start node) share no endpoint: `None` when no
/// endpoint of f lies inside e; else whether it may (f leaving e's line there, on another
/// ring), and then it is listed (once) for [`split`].
fn tee<const N: usize, M: Mask>(s: &mut Scratch<N, M>, e: usize, f: usize) -> Option<bool> {
    let (a, b) = (s.p[e], s.p[s.next(e)]);
    for (y, other) in [(f, s.next(f)), (s.next(f), f)] {
        let q = s.p[y];
        if orient2d(a, b, q) != Orientation::Collinear || !within_box(a, b, q) {
            continue;
        }
        // (q is no endpoint of e: they share none)
        if orient2d(a, b, s.p[other]) == Orientation::Collinear {
            return Some(false); // along e
        }
        let listed = [e as u8, y as u8];
        if s.tee[..s.tees].contains(&listed) {
            return Some(true);
        }
        if s.touched & bit(y) != M::NONE || s.touches + s.tees == TOUCHES {
            return Some(false);
        }
        s.tee[s.tees] = listed;
        s.tees += 1;
        s.touched |= bit(y);
        return Some(true);
    }
    None
}

/// `clean`'s `split_touched_edges`: a node inserted into every edge at each vertex found
/// inside it ([`tee`]), in the order of the edges' start nodes and along each edge; the new
/// nodes follow the input's, and each touches its vertex. False when they would leave
/// too little room for the bridges' copies.
pub(super) fn split<const N: usize, M: Mask>(s: &mut Scratch<N, M>) -> bool {
    if s.nodes + s.tees + 2 * (s.rings - 1) > N || s.touches + s.tees > TOUCHES {
        return false;
    }
    let tees = &mut s.tee[..s.tees];
    let p = &s.p;
    let next = &s.next;
    let along = |t: &[u8; 2], u: &[u8; 2]| {
        let e = usize::from(t[0]);
        let (a, b) = (p[e], p[usize::from(next[e])]);
        let ord = cmp_xy(p[usize::from(t[1])], p[usize::from(u[1])]);
        t[0].cmp(&u[0]).then(if cmp_xy(a, b).is_le() {
            ord
        } else {
            ord.reverse()
        })
    };
    tees.sort_unstable_by(along);
    let mut k = 0;
    while k < s.tees {
        let e = usize::from(s.tee[k][0]);
        let mut after = e;
        while k < s.tees && usize::from(s.tee[k][0]) == e {
            let y = usize::from(s.tee[k][1]);
            let new = s.nodes;
            s.nodes += 1;
            (s.p[new], s.vertex[new]) = (s.p[y], s.vertex[y]);
            let next = s.next(after);
            (s.next[after], s.prev[new], s.next[new], s.prev[next]) =
                (new as u8, after as u8, next as u8, new as u8);
            after = new;
            s.len[ring(s, e)] += 1;
            s.split_of[new - usize::from(s.first[s.rings])] = e as u8;
            s.touch[s.touches] = [y as u8, new as u8];
            s.touches += 1;
            s.touched |= bit::<M>(new);
            k += 1;
        }
    }
    // (by position, as the pipeline lists shared nodes)
    sort_by_position(s);
    true
}

/// Sorts the touches by position.
pub(super) fn sort_by_position<const N: usize, M: Mask>(s: &mut Scratch<N, M>) {
    let at = |s: &Scratch<N, M>, t: usize| s.p[usize::from(s.touch[t][0])];
    // (an insertion sort: a few positions)
    for i in 1..s.touches {
        let mut j = i;
        while j > 0 && cmp_xy(at(s, j - 1), at(s, j)) == core::cmp::Ordering::Greater {
            s.touch.swap(j - 1, j);
            j -= 1;
        }
    }
}

/// Strict mode, after the holes were turned: whether the rings at touch `t` meet without
/// crossing — round the position, the winding number of the sectors between the four
/// edges there takes two consecutive values (`nest`'s `check_shared_positions`; the
/// edges' directions all differ, [`record`] saw to that).
pub(super) fn proper<const N: usize, M: Mask>(s: &Scratch<N, M>, t: usize) -> bool {
    let [a, b] = s.touch[t].map(usize::from);
    let o = s.p[a];
    let mut rays = [
        (s.p[s.next(a)], 1),
        (s.p[s.prev(a)], -1),
        (s.p[s.next(b)], 1),
        (s.p[s.prev(b)], -1),
    ];
    rays.sort_unstable_by(|u, w| cmp_around(o, u.0, w.0));
    let (mut w, mut lo, mut hi) = (0, 0, 0);
    for (_, step) in rays {
        w += step;
        (lo, hi) = (lo.min(w), hi.max(w));
    }
    hi - lo <= 1
}

/// Step 6a: re-links every touch by the face-walk rule and traces the rings again
/// (`touch::join`), leaving the ring table as the pipeline's: the rings by their lowest
/// node, each starting there, its rightmost node, and which are holes (the others are
/// polygons). False where `touch` would go by another rule or refuse the rings.
pub(super) fn join<const N: usize, M: Mask>(s: &mut Scratch<N, M>) -> bool {
    let live = (0..s.rings).fold(M::NONE, |mask, r| {
        s.ring(r).fold(mask, |mask, v| mask | bit(v))
    });
    // (by position, as `touch` takes them; `canonical_vertices` sorted them so)
    for t in 0..s.touches {
        let nodes = s.touch[t].map(usize::from);
        let o = s.p[nodes[0]];
        let mut targets = [0usize; 2];
        for (target, &n) in targets.iter_mut().zip(&nodes) {
            let back = s.p[s.prev(n)];
            let mut best: Option<usize> = None;
            for &m in &nodes {
                let q = s.next(m);
                best = match best {
                    Some(c) if !clockwise_before(o, back, s.p[q], s.p[c]) => Some(c),
                    _ => Some(q),
                };
            }
            *target = best.unwrap_or(n);
        }
        if targets[0] == targets[1] {
            return false; // a conflict: `touch` orders bundles then
        }
        for (&n, &target) in nodes.iter().zip(&targets) {
            s.next[n] = target as u8;
            s.prev[target] = n as u8;
        }
        s.fresh |= bit::<M>(nodes[0]) | bit(nodes[1]);
    }
    retrace(s, live)
}

/// `touch::retrace` on the nodes `live`: each cycle a ring, by its lowest node; then
/// `touch::refuse_rings_winding_twice`'s check, and `bridge`'s case of a hole touching a
/// polygon at its rightmost vertex, which this stage does not bridge.
fn retrace<const N: usize, M: Mask>(s: &mut Scratch<N, M>, mut live: M) -> bool {
    let mut cycle = [u8::MAX; N];
    let mut input = [0usize; RINGS];
    let (mut rings, mut holes) = (0, 0u8);
    while live != M::NONE {
        let n = live.lowest();
        if rings == RINGS {
            return false;
        }
        let mut len = 0usize;
        let mut at = RightmostVisit::new(n, s.p[n]);
        let mut m = n;
        loop {
            live &= !bit::<M>(m);
            cycle[m] = rings as u8;
            len += 1;
            at.visit(m, s.p[m], orient2d(s.p[s.prev(m)], s.p[m], s.p[s.next(m)]));
            m = s.next(m);
            if m == n {
                break;
            }
            if len > N {
                return false;
            }
        }
        // (a wall, or a ring `touch` reads by its net boundary)
        if at.flat || !at.turns {
            return false;
        }
        if at.hole {
            holes |= 1 << rings;
        }
        input[rings] = ring_of(s, n);
        s.start[rings] = n as u8;
        s.len[rings] = len as u8;
        s.rightmost[rings] = at.node as u8;
        rings += 1;
    }
    if holes.count_ones() as usize == rings {
        return false;
    }
    (s.rings, s.hole_rings) = (rings, holes);
    let kind = |c: usize| holes >> c & 1;
    for &[a, b] in &s.touch[..s.touches] {
        let (c, d) = (
            usize::from(cycle[usize::from(a)]),
            usize::from(cycle[usize::from(b)]),
        );
        // two cycles of one ring, of one kind, meeting: one inside the other winds twice
        if c != d
            && input[c] == input[d]
            && kind(c) == kind(d)
            && (lies_inside(s, c, d) || lies_inside(s, d, c))
        {
            return false;
        }
    }
    // a hole touching another ring at its rightmost vertex: `bridge` joins it there
    (0..rings).all(|h| {
        let m = usize::from(s.rightmost[h]);
        kind(h) == 0
            || s.touched & bit(m) == M::NONE
            || partner(s, m).is_some_and(|w| usize::from(cycle[w]) == h)
    })
}

/// `touch::lies_inside`: whether cycle `c` lies inside cycle `d`, by crossing parity at
/// its first vertex (from its start) at no position of `d` (no vertex lies inside an
/// edge: such edges were split), false when there is none.
fn lies_inside<const N: usize, M: Mask>(s: &Scratch<N, M>, c: usize, d: usize) -> bool {
    let on_d = |q: Point| s.ring(d).any(|v| s.p[v] == q);
    let Some(v) = s.ring(c).find(|&v| !on_d(s.p[v])) else {
        return false;
    };
    let q = s.p[v];
    let winding: i64 = s
        .ring(d)
        .map(|w| ray_crossing(s.p[w], s.p[s.next(w)], q))
        .sum();
    winding % 2 != 0
}
