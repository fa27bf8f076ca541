//! Rings of the small stage touching: a hole's vertex on a vertex of the outer ring or
//! of another hole, or inside an edge, a ring's vertex on its own, edges lying along each
//! other, up to eight nodes at one position, as `clean`, `nest` and `touch` handle them
//! in the pipeline.
//!
//! - The proof ([`record`]) lists what the pipeline's proof lists where two edges meet
//!   other than crossing: the two nodes of a shared endpoint, and a vertex inside another
//!   edge (of any ring), which splits it there as `clean` does ([`split`]); on one line,
//!   every endpoint of either edge on the other. Edges lying along each other become one
//!   segment walked twice once split.
//! - The nodes at a position then take the lowest vertex index there
//!   (`super::canonical_vertices`), and strict mode checks that the rings do not cross
//!   there ([`proper`], `nest`'s check of shared positions).
//! - Before bridging, [`join`] re-links each position by the face-walk rule (`touch`'s
//!   `relink`; where a segment is walked both ways or the rule pairs two edges with one,
//!   by bundles of edges of one direction, [`relink_bundles`]) and traces the rings again
//!   as `touch` does: a hole touching the outer ring becomes part of it, two touching
//!   holes one hole, a ring touching itself two (lobes, or a polygon and its hole), a
//!   hole touching the outer ring twice cuts it in two polygons, a segment walked both
//!   ways between two parts of the outside closes into a wall, which is dead; each ring
//!   starts at its lowest node. Where every edge at a position is walked both ways, the
//!   far ends tell a wall from a crack into the region, as `touch` reads them. Whatever
//!   `touch` would decide by a rule this does not repeat (a ring it reads by its net
//!   boundary, a ring wound twice) hands the polygon back.

use core::cmp::Ordering;

use super::{bit, ring_mask, ring_masks, winding, Mask, Scratch, RINGS, TOUCHES};
use crate::geom::{
    bundle_end, clockwise_before, cmp_around, cmp_xy, inside_along, orient2d, pair_alternating,
    within_box, Orientation, Point, RightmostVisit,
};

/// The most nodes at one position that [`join`] relinks (`touch` pairs every edge
/// there with every other up to as many, then sorts them by direction).
const FEW_AT_ONE_POSITION: usize = 8;

/// The proof found edges `k` and `m` (indices into `s.boxes`) meeting: lists what the
/// pipeline's proof (`crossings::proof`'s `contact`) finds there — the two nodes of a
/// shared endpoint (each pair once), or a vertex inside the other edge (for [`split`]).
/// On one line (edges along each other) every endpoint of either on the other counts.
/// False, to hand the polygon back, where they cross, or for too many contacts.
pub(super) fn record<const N: usize, M: Mask>(s: &mut Scratch<N, M>, k: usize, m: usize) -> bool {
    let (e, f) = (usize::from(s.from[k]), usize::from(s.from[m]));
    let (e2, f2) = (s.next(e), s.next(f));
    let (a, b) = (s.p[e], s.p[e2]);
    let collinear = |q: Point| orient2d(a, b, q) == Orientation::Collinear;
    if collinear(s.p[f]) && collinear(s.p[f2]) {
        for (v, g) in [(f, e), (f2, e), (e, f), (e2, f)] {
            let (q, g2) = (s.p[v], s.next(g));
            let listed = if q == s.p[g] {
                pair(s, v, g)
            } else if q == s.p[g2] {
                pair(s, v, g2)
            } else if within_box(s.p[g], s.p[g2], q) {
                list_tee(s, g, v)
            } else {
                true
            };
            if !listed {
                return false;
            }
        }
        return true;
    }
    // not on one line: they meet at one point, an endpoint of one at least
    for x in [e, e2] {
        for y in [f, f2] {
            if s.p[x] == s.p[y] {
                return pair(s, x, y);
            }
        }
    }
    // a vertex inside the other edge (or a crossing)
    match tee(s, e, f) {
        Some(listed) => listed,
        None => tee(s, f, e) == Some(true),
    }
}

/// Lists nodes `x` and `y`, at one position (once); false when the stage holds no more.
fn pair<const N: usize, M: Mask>(s: &mut Scratch<N, M>, x: usize, y: usize) -> bool {
    let pair = [x.min(y) as u8, x.max(y) as u8];
    if s.touch[..s.touches].contains(&pair) {
        return true;
    }
    if s.touches + s.tees == TOUCHES {
        return false;
    }
    s.touch[s.touches] = pair;
    s.touches += 1;
    s.touched |= bit::<M>(x) | bit(y);
    true
}

/// Lists vertex `y` inside edge `e` (once) for [`split`]; false when the stage holds no
/// more.
fn list_tee<const N: usize, M: Mask>(s: &mut Scratch<N, M>, e: usize, y: usize) -> bool {
    let listed = [e as u8, y as u8];
    if s.tee[..s.tees].contains(&listed) {
        return true;
    }
    if s.touches + s.tees == TOUCHES {
        return false;
    }
    s.tee[s.tees] = listed;
    s.tees += 1;
    s.touched |= bit(y);
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
pub(super) fn ring_of<const N: usize, M: Mask>(s: &Scratch<N, M>, v: usize) -> usize {
    let n = usize::from(s.first[s.rings]);
    match v.checked_sub(n) {
        Some(k) if k < TOUCHES => ring(s, usize::from(s.split_of[k])),
        _ => ring(s, v),
    }
}

/// The other nodes at touched node `v`'s position.
fn others<const N: usize, M: Mask>(
    s: &Scratch<N, M>,
    v: usize,
) -> impl Iterator<Item = usize> + '_ {
    let shared = &s.shared[..s.shared_len];
    let at = shared.iter().position(|&w| s.p[usize::from(w)] == s.p[v]);
    let group = at.map_or(&shared[..0], |i| &shared[i..group_end(s, i)]);
    group
        .iter()
        .map(|&w| usize::from(w))
        .filter(move |&w| w != v)
}

/// Whether touched node `v`'s position is another visit of its own ring.
pub(super) fn touches_own_ring<const N: usize, M: Mask>(s: &Scratch<N, M>, v: usize) -> bool {
    others(s, v).any(|w| ring_of(s, w) == ring_of(s, v))
}

/// Lists every node of the touches by position, then node, each once (`cx.shared`).
pub(super) fn list_shared<const N: usize, M: Mask>(s: &mut Scratch<N, M>) {
    let mut len = 0;
    for t in 0..s.touches {
        for v in s.touch[t] {
            if !s.shared[..len].contains(&v) {
                s.shared[len] = v;
                len += 1;
            }
        }
    }
    let p = &s.p;
    s.shared[..len]
        .sort_unstable_by(|&a, &b| cmp_xy(p[usize::from(a)], p[usize::from(b)]).then(a.cmp(&b)));
    s.shared_len = len;
}

/// The end of the group of `s.shared` at the position of `s.shared[i]`.
pub(super) fn group_end<const N: usize, M: Mask>(s: &Scratch<N, M>, i: usize) -> usize {
    let o = s.p[usize::from(s.shared[i])];
    let mut j = i + 1;
    while j < s.shared_len && s.p[usize::from(s.shared[j])] == o {
        j += 1;
    }
    j
}

/// [`record`] where edges e and f (by start node), not on one line, share no endpoint:
/// `None` when no endpoint of f lies inside e; else it is listed for [`split`] (whether
/// there was room).
fn tee<const N: usize, M: Mask>(s: &mut Scratch<N, M>, e: usize, f: usize) -> Option<bool> {
    let (a, b) = (s.p[e], s.p[s.next(e)]);
    let y = [f, s.next(f)].into_iter().find(|&y| {
        let q = s.p[y];
        orient2d(a, b, q) == Orientation::Collinear && within_box(a, b, q)
    })?;
    Some(list_tee(s, e, y))
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
            k += 1;
            if s.p[after] == s.p[y] {
                // a second vertex where the edge was just split (the two share the
                // position already): one node there, as `clean` splits
                if s.touches == TOUCHES {
                    return false;
                }
                s.touch[s.touches] = [y as u8, after as u8];
                s.touches += 1;
                continue;
            }
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
        }
    }
    // (by position, as the pipeline lists shared nodes)
    list_shared(s);
    true
}

/// Strict mode, after the holes were turned: whether the rings meet without crossing at
/// every shared position — round it, the winding number of the sectors between the edges
/// there takes two consecutive values (`nest`'s `check_shared_positions`).
///
/// False too where one ring's own visits there do so by themselves take more (a figure
/// eight whose lobes turn opposite ways crosses itself at its waist; a lobe inside its
/// ring turning the same way winds twice): another ring may cancel the difference, so
/// that the sum passes, but the pipeline reads such a ring by rules this stage does not
/// repeat (it refuses a ring crossing itself whatever cancels it), so it hands it back.
pub(super) fn proper<const N: usize, M: Mask>(s: &Scratch<N, M>) -> bool {
    if s.shared_len == 0 {
        return true;
    }
    // (with one ring at a position, its own sectors are all the sectors there: `apart_at`
    // is asked only where several rings are)
    let masks = if s.rings > 1 {
        ring_masks(s)
    } else {
        [M::NONE; RINGS]
    };
    let mut i = 0;
    while i < s.shared_len {
        let j = group_end(s, i);
        let o = s.p[usize::from(s.shared[i])];
        let group = &s.shared[i..j];
        if group.len() > FEW_AT_ONE_POSITION || sectors(s, o, group, M::NONE) > 1 {
            return false;
        }
        if s.rings > 1 && !apart_at(s, o, group, &masks[..s.rings]) {
            return false;
        }
        i = j;
    }
    true
}

/// [`proper`] at one position `o` where several rings meet (`masks` their nodes): whether
/// no ring that passes it twice crosses itself there (its own sectors take two values).
#[inline(never)]
fn apart_at<const N: usize, M: Mask>(
    s: &Scratch<N, M>,
    o: Point,
    group: &[u8],
    masks: &[M],
) -> bool {
    let here = (group.iter()).fold(M::NONE, |m, &v| m | bit::<M>(v.into()));
    if masks.iter().filter(|&&m| m & here != M::NONE).count() < 2 {
        return true;
    }
    (masks.iter()).all(|&mask| (mask & here).count() < 2 || sectors(s, o, group, mask) <= 1)
}

/// How many values the winding number takes in the sectors round `o` between the edges
/// of the nodes of `group` (at most [`FEW_AT_ONE_POSITION`], all at `o`), less one: of
/// those in `only` unless it is empty. Rays along one direction bound no sector between
/// them.
#[inline(always)]
fn sectors<const N: usize, M: Mask>(s: &Scratch<N, M>, o: Point, group: &[u8], only: M) -> i32 {
    let mut rays = [(o, 0i32); 2 * FEW_AT_ONE_POSITION];
    let mut len = 0;
    for &v in group {
        let v = usize::from(v);
        if only == M::NONE || only & bit::<M>(v) != M::NONE {
            rays[len] = (s.p[s.next(v)], 1);
            rays[len + 1] = (s.p[s.prev(v)], -1);
            len += 2;
        }
    }
    let rays = &mut rays[..len];
    rays.sort_unstable_by(|u, w| cmp_around(o, u.0, w.0));
    let (mut w, mut lo, mut hi) = (0, 0, 0);
    for (k, &(d, step)) in rays.iter().enumerate() {
        w += step;
        let ends = !matches!(rays.get(k + 1), Some(&(e, _)) if cmp_around(o, d, e).is_eq());
        if ends {
            (lo, hi) = (lo.min(w), hi.max(w));
        }
    }
    hi - lo
}

/// Step 6a: re-links every touch by the face-walk rule and traces the rings again
/// (`touch::join`), leaving the ring table as the pipeline's: the rings by their lowest
/// node, each starting there, its rightmost node, and which are holes (the others are
/// polygons). False where `touch` would go by another rule or refuse the rings.
pub(super) fn join<const N: usize, M: Mask>(s: &mut Scratch<N, M>) -> bool {
    let live = (0..s.rings).fold(M::NONE, |mask, r| mask | ring_mask(s, r));
    // (by position, as `touch` takes them)
    let mut i = 0;
    while i < s.shared_len {
        let j = group_end(s, i);
        // (past this many, `touch` sorts the edges first)
        if j - i > FEW_AT_ONE_POSITION {
            return false;
        }
        let o = s.p[usize::from(s.shared[i])];
        let group = &s.shared[i..j];
        // an edge arriving from where another leaves to (a segment walked both ways):
        // `touch` orders the edges by bundles then, whatever the face-walk rule pairs
        let doubled = (group.iter()).any(|&n| {
            let back = s.p[s.prev(usize::from(n))];
            (group.iter()).any(|&m| s.p[s.next(usize::from(m))] == back)
        });
        let mut targets = [[0u8; 2]; FEW_AT_ONE_POSITION];
        let by_rule = !doubled && {
            for (k, &n) in group.iter().enumerate() {
                let n = usize::from(n);
                let back = s.p[s.prev(n)];
                let mut best: Option<usize> = None;
                for &m in group {
                    let q = s.next(usize::from(m));
                    best = match best {
                        Some(c) if !clockwise_before(o, back, s.p[q], s.p[c]) => Some(c),
                        _ => Some(q),
                    };
                }
                targets[k] = [n as u8, best.unwrap_or(n) as u8];
            }
            // one-to-one? (else a conflict, which `touch` orders by bundles too)
            let targets = &targets[..j - i];
            (1..targets.len()).all(|k| targets[..k].iter().all(|t| t[1] != targets[k][1]))
        };
        if !by_rule && !relink_bundles(s, i, j, &mut targets) {
            return false;
        }
        let targets = &targets[..j - i];
        for &[n, target] in targets {
            let (n, target) = (usize::from(n), usize::from(target));
            s.next[n] = target as u8;
            s.prev[target] = n as u8;
            s.fresh |= bit::<M>(n);
        }
        i = j;
    }
    retrace(s, live)
}

/// `touch::relink_bundles` at the position of `s.shared[i..j]`: the edges around it in
/// counter-clockwise order (those of one direction, a bundle, in the order listed),
/// arranged so that arriving and leaving edges alternate, each arriving one continuing
/// along the leaving one just clockwise of it; the pairs (node, its new successor) into
/// `pairs`. False where they cannot alternate.
fn relink_bundles<const N: usize, M: Mask>(
    s: &Scratch<N, M>,
    i: usize,
    j: usize,
    pairs: &mut [[u8; 2]; FEW_AT_ONE_POSITION],
) -> bool {
    let o = s.p[usize::from(s.shared[i])];
    let mut ends = [(o, 0u8, false); 2 * FEW_AT_ONE_POSITION];
    for (k, &n) in s.shared[i..j].iter().enumerate() {
        let (prev, next) = (s.prev(usize::from(n)), s.next(usize::from(n)));
        ends[2 * k] = (s.p[prev], n, true);
        ends[2 * k + 1] = (s.p[next], next as u8, false);
    }
    let ends = &mut ends[..2 * (j - i)];
    // (stable, as `touch` sorts them: an insertion sort of a few)
    for k in 1..ends.len() {
        let mut m = k;
        while m > 0 && cmp_around(o, ends[m - 1].0, ends[m].0) == Ordering::Greater {
            ends.swap(m - 1, m);
            m -= 1;
        }
    }
    let mut all_doubled = true;
    let mut k = 0;
    while k < ends.len() {
        let e = bundle_end(o, ends, k);
        let ins = ends[k..e].iter().filter(|x| x.2).count();
        all_doubled &= 2 * ins == e - k;
        k = e;
    }
    // where every bundle is doubled both starts alternate: arriving first makes cracks,
    // leaving first walls, and the far ends tell which it is; elsewhere only one does
    let crack = if all_doubled {
        match is_crack(s, i, j) {
            Some(crack) => crack,
            None => return false,
        }
    } else {
        true
    };
    [crack, !crack].into_iter().any(|first_arrives| {
        let mut count = 0;
        let paired = pair_alternating(o, ends, first_arrives, |n, target| {
            let Some(slot) = pairs.get_mut(count) else {
                return false;
            };
            (*slot, count) = ([n, target], count + 1);
            true
        });
        paired && count == j - i
    })
}

/// `touch::is_crack`: whether the doubled edges through the position of `s.shared[i..j]`
/// are cracks into the region (its inside on both sides) rather than walls, as read at
/// their far ends ([`crack_at`]); walls when no far end tells. `None` where a far end has
/// more edges than the stage holds.
fn is_crack<const N: usize, M: Mask>(s: &Scratch<N, M>, i: usize, j: usize) -> Option<bool> {
    let x = s.p[usize::from(s.shared[i])];
    for &n in &s.shared[i..j] {
        if let Some(crack) = crack_at(s, s.prev(usize::from(n)), x)? {
            return Some(crack);
        }
    }
    Some(false)
}

/// `touch::crack_at`: whether the region lies on both sides of the doubled edge from `x`
/// to node `y`'s position, read at `y`, where an edge that is not doubled says which
/// sectors are inside; `Some(None)` when every edge there is doubled too, `None` when
/// there are more than the stage holds.
fn crack_at<const N: usize, M: Mask>(
    s: &Scratch<N, M>,
    y: usize,
    x: Point,
) -> Option<Option<bool>> {
    let o = s.p[y];
    // (far end, +1 arriving / -1 leaving) of every edge at y's position
    let mut nets = [(o, 0i32); 2 * FEW_AT_ONE_POSITION];
    let mut len = 0;
    for n in core::iter::once(y).chain(others(s, y)) {
        if len + 2 > nets.len() {
            return None;
        }
        nets[len] = (s.p[s.prev(n)], 1);
        nets[len + 1] = (s.p[s.next(n)], -1);
        len += 2;
    }
    Some(inside_along(o, &mut nets[..len], x))
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
        if at.flat {
            // a wall (a segment walked both ways): it encloses nothing, and `touch` leaves
            // it dead (its nodes in no cycle: `u8::MAX`)
            let mut m = n;
            loop {
                cycle[m] = u8::MAX;
                m = s.next(m);
                if m == n {
                    break;
                }
            }
            continue;
        }
        // (a ring `touch` reads by its net boundary)
        if !at.turns {
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
    let mut i = 0;
    while i < s.shared_len {
        let j = group_end(s, i);
        let group = &s.shared[i..j];
        for (k, &a) in group.iter().enumerate() {
            for &b in &group[k + 1..] {
                let (c, d) = (
                    usize::from(cycle[usize::from(a)]),
                    usize::from(cycle[usize::from(b)]),
                );
                // two cycles of one ring, of one kind, meeting: one inside the other winds
                // twice (walls are dead: none of their nodes meets anything)
                if c != d
                    && c < rings
                    && d < rings
                    && input[c] == input[d]
                    && kind(c) == kind(d)
                    && (lies_inside(s, c, d) || lies_inside(s, d, c))
                {
                    return false;
                }
            }
        }
        i = j;
    }
    // a hole touching another ring at its rightmost vertex: `bridge` joins it there
    (0..rings).all(|h| {
        let m = usize::from(s.rightmost[h]);
        kind(h) == 0
            || s.touched & bit(m) == M::NONE
            || others(s, m).all(|w| usize::from(cycle[w]) == h || cycle[w] == u8::MAX)
    })
}

/// `touch::lies_inside`: whether cycle `c` lies inside cycle `d`, by crossing parity at
/// its first vertex (from its start) at no position of `d` (no vertex lies inside an
/// edge: such edges were split), false when there is none.
fn lies_inside<const N: usize, M: Mask>(s: &Scratch<N, M>, c: usize, d: usize) -> bool {
    // (a node no other node shares a position with lies on no other cycle)
    let on_d = |v: usize| s.touched & bit(v) != M::NONE && s.ring(d).any(|w| s.p[w] == s.p[v]);
    let Some(v) = s.ring(c).find(|&v| !on_d(v)) else {
        return false;
    };
    winding(s, d, s.p[v]) % 2 != 0
}
