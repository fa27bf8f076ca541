//! Stage 2b, lenient mode: split every ring that touches itself into its lobes.
//!
//! A ring passing a position X several times is a chain of loops from X back to X (its
//! *lobes*). Orienting the whole ring by the turn at its rightmost vertex assumes all its
//! lobes turn the same way round their inside. They need not: a figure eight whose two
//! lobes turn opposite ways, one of them cancelled by another ring lying on it, is a valid
//! input (`raw_rings` found one). Cut into lobes, each is a ring of its own, oriented by its
//! own rightmost turn and given its depth by containment. That is the even–odd rule, and
//! for a valid input it gives the region the winding numbers give: their sum is 0 or 1
//! everywhere and changes by one across each boundary edge (or by nothing across two
//! lying on each other), so it is the parity of the edges crossed.
//!
//! The cut keeps every edge and only re-pairs, at a position the ring passes more than
//! once, which edge leaves after which edge arrives. It must not make lobes that cross
//! there, or the lobes overlap and the even–odd rule counts their overlap twice. So the
//! edges at such a position X are taken in their order around X, and each visit's pair
//! (the edge arriving, the edge leaving) is a chord of that circle. Where no two chords
//! cross, the ring only touches itself at X and is left as it is there. Where two cross,
//! the ring crosses itself at X (a figure eight whose lobes turn opposite ways does), and
//! the edges are paired again as nested brackets, arriving edges opening: no two of the
//! new chords cross. Edges lying on one another (a segment walked twice) have no order
//! around X of their own; they are ordered by a lane (the edge's first node), one way at
//! one end of the segment and the other way at the other end, as if each were bowed
//! aside by its lane, so that the choices at the two ends agree and the strands do not
//! cross between them. With no crossing left anywhere, the rings can be drawn apart into
//! disjoint simple curves, and nesting them by containment is the even–odd rule.
//!
//! The cycles that gives may still pass a position twice where they only touch
//! themselves. Each is then cut in two there, by swapping the two visits' arriving edges,
//! wherever the swapped chords cross none there: so a lobe hanging on a wall comes off it,
//! and no cycle's rightmost vertex is the tip of a wall it runs out along and back (whose
//! turn would say nothing). Cutting tries the visits in pairs, so a position passed more
//! than [`MOST_VISITS_CUT`] times by one ring is not cut. Every cycle becomes a ring entry
//! with the same input ring number, and `touch` joins them again properly once nesting has
//! turned them. Input with crossing edges is left whole: it has no region to keep, and its
//! repairs were tuned on whole rings. So is input whose lobes, once cut, lie on another
//! ring, doubling it (`nest` finds them at equal depths, each inside the other: a lobe
//! and a ring lying on it the same way round): the triangulator then runs
//! again with every ring whole (`Context::keep_lobes`), as strict mode reads them, where
//! the other ring is the lobe's hole.
//!
//! Strict mode keeps rings whole: a ring whose lobes turn opposite ways is refused there
//! (as `Error::LobesWindOpposite`, or as rings crossing at a vertex), cancelled lobe or
//! not, and a lobe inside the rest turning the same way, where no other ring cancels it,
//! as `Error::RingWindsTwice` (see `touch`).

use crate::context::{Context, Ring};
use crate::geom::{cmp_around, cmp_xy, Point};
use crate::structures::NodeId;
use core::cmp::Ordering;

/// An edge end at a position a ring passes several times.
#[derive(Clone, Copy, Debug)]
struct EdgeEnd {
    /// The edge's other end.
    far: Point,
    /// Orders edges lying on one another (the edge's first node).
    lane: u32,
    /// The edge arrives at the position (else it leaves).
    arrives: bool,
    /// The visit (chord) it belongs to.
    chord: u32,
    /// The edge, by its first node.
    edge: NodeId,
}

/// Scratch buffers of the lobe split, kept between calls.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// Per node: the index into `cx.shared` of its position's first node, or `NONE`.
    group: Vec<u32>,
    /// Per position (by its first index into `cx.shared`): how often the ring being split
    /// passes it, or `NONE`.
    visits: Vec<u32>,
    /// The positions the ring being split passes more than once.
    pinches: Vec<u32>,
    /// The edge ends at one position, sorted around it.
    ends: Vec<EdgeEnd>,
    /// Open chords, or the ends of arriving edges, while pairing the ends at one position.
    stack: Vec<u32>,
    /// New links: (edge arriving, by its first node; node whose edge leaves next).
    pairs: Vec<(NodeId, NodeId)>,
    /// One ring's nodes in order.
    walk: Vec<NodeId>,
    /// Rings that pass some position more than once.
    candidates: Vec<u32>,
    /// The ring's visits at one position (its nodes there).
    at: Vec<NodeId>,
    /// Per visit at one position, the place of its arriving edge's end in `ends`.
    arrival: Vec<u32>,
    /// Per node of the ring being split: the cycle it lies on, or `NONE`.
    cycle: Vec<u32>,
    /// Cycle labels handed out so far.
    labels: u32,
}

const NONE: u32 = u32::MAX;

/// Re-pairs every ring that crosses itself at a position it passes more than once
/// (lenient mode), splitting it into lobes. Returns whether any ring was re-paired.
pub(crate) fn split(cx: &mut Context, s: &mut Scratch) -> bool {
    cx.lobe_rings.clear();
    s.candidates.clear();
    // rings visiting one position twice, from the groups of shared nodes
    let mut i = 0;
    while i < cx.shared.len() {
        let j = cx.same_position_end(i);
        for a in i..j {
            let ra = cx.pool.get(cx.shared[a]).ring;
            let repeats = cx.shared[a + 1..j]
                .iter()
                .any(|&n| cx.pool.get(n).ring == ra);
            if repeats && !cx.pool.get(cx.shared[a]).removed && !s.candidates.contains(&ra) {
                s.candidates.push(ra);
            }
        }
        i = j;
    }
    if !s.candidates.is_empty() {
        s.group.clear();
        s.group.resize(cx.pool.len(), NONE);
        s.visits.clear();
        s.visits.resize(cx.shared.len(), NONE);
        s.cycle.clear();
        s.cycle.resize(cx.pool.len(), NONE);
        let mut i = 0;
        while i < cx.shared.len() {
            let j = cx.same_position_end(i);
            for &n in &cx.shared[i..j] {
                s.group[n.idx()] = i as u32;
            }
            i = j;
        }
        for k in 0..s.candidates.len() {
            let r = s.candidates[k];
            if split_ring(cx, s, r as usize) {
                cx.lobe_rings.push(r);
            }
        }
    }
    cx.split_lobes = !cx.lobe_rings.is_empty();
    cx.split_lobes
}

/// Re-pairs ring `r` where it crosses itself, cuts the cycles that gives apart where they
/// touch themselves (where that crosses nothing), then gives each cycle a ring entry of
/// its own. Returns whether anything was re-paired or cut.
fn split_ring(cx: &mut Context, s: &mut Scratch, r: usize) -> bool {
    let ring = cx.rings[r];
    if !ring.alive {
        return false;
    }
    s.walk.clear();
    s.walk.extend(cx.pool.ring(ring.start));
    s.pinches.clear();
    for &w in &s.walk {
        let g = s.group[w.idx()];
        if g == NONE {
            continue;
        }
        let v = &mut s.visits[g as usize];
        *v = if *v == NONE { 1 } else { *v + 1 };
        if *v == 2 {
            s.pinches.push(g);
        }
    }
    for &w in &s.walk {
        let g = s.group[w.idx()];
        if g != NONE {
            s.visits[g as usize] = NONE;
        }
    }
    let r32 = r as u32;
    // 1. where the ring crosses itself, pair its edges there again
    s.pairs.clear();
    for k in 0..s.pinches.len() {
        let g = s.pinches[k] as usize;
        repair(cx, s, g, r32);
    }
    // every pair's edge ends at its own position, so no link is set twice
    for &(a, d) in &s.pairs {
        cx.pool.get_mut(a).next = d;
        cx.pool.get_mut(d).prev = a;
    }
    let mut changed = !s.pairs.is_empty();
    // 2. label the cycles, then cut each apart where it passes a position twice
    // (`split` sized `s.cycle` once, all `NONE`; only this ring's nodes are set below,
    // and reset before returning)
    s.labels = 0;
    for k in 0..s.walk.len() {
        let v = s.walk[k];
        if s.cycle[v.idx()] == NONE {
            label(cx, &mut s.cycle, v, s.labels);
            s.labels += 1;
        }
    }
    for k in 0..s.pinches.len() {
        let g = s.pinches[k] as usize;
        changed |= cut(cx, s, g, r32);
    }
    for &w in &s.walk {
        s.cycle[w.idx()] = NONE;
    }
    if !changed {
        return false;
    }
    // each cycle a ring: the first keeps number r
    for &w in &s.walk {
        cx.pool.get_mut(w).ring = NONE;
    }
    let mut first = true;
    for k in 0..s.walk.len() {
        let v = s.walk[k];
        if cx.pool.get(v).ring != NONE {
            continue;
        }
        let index = if first { r32 } else { cx.rings.len() as u32 };
        let mut len = 0;
        let mut n = v;
        loop {
            cx.pool.get_mut(n).ring = index;
            len += 1;
            n = cx.pool.next(n);
            if n == v {
                break;
            }
        }
        let lobe = Ring {
            start: v,
            len,
            rightmost: v,
            depth: 0,
            alive: true,
            merged: false,
            component: index,
            ..ring
        };
        if first {
            cx.rings[r] = lobe;
            first = false;
        } else {
            cx.rings.push(lobe);
        }
    }
    true
}

/// Gives every node on the cycle through `v` the label `l`.
fn label(cx: &Context, cycle: &mut [u32], v: NodeId, l: u32) {
    let mut n = v;
    loop {
        cycle[n.idx()] = l;
        n = cx.pool.next(n);
        if n == v {
            break;
        }
    }
}

/// Fills `s.at` with ring `r`'s nodes at the position whose nodes start at `cx.shared[g]`
/// (its visits there) and `s.ends` with their edges' ends, sorted around the position;
/// edges lying on one another by lane, reversed at the segment's other end.
fn sorted_ends(cx: &Context, s: &mut Scratch, g: usize, r: u32) -> Point {
    let o = cx.pool.p(cx.shared[g]);
    let end = cx.same_position_end(g);
    s.at.clear();
    s.ends.clear();
    for &m in &cx.shared[g..end] {
        let node = cx.pool.get(m);
        if node.ring != r || node.removed {
            continue;
        }
        let (prev, next) = (node.prev, node.next);
        let visit = s.at.len() as u32;
        s.at.push(m);
        s.ends.push(EdgeEnd {
            far: cx.pool.p(prev),
            lane: prev.idx() as u32,
            arrives: true,
            chord: visit,
            edge: prev,
        });
        s.ends.push(EdgeEnd {
            far: cx.pool.p(next),
            lane: m.idx() as u32,
            arrives: false,
            chord: visit,
            edge: m,
        });
    }
    s.ends.sort_unstable_by(|a, b| {
        cmp_around(o, a.far, b.far).then_with(|| match cmp_xy(o, a.far) {
            Ordering::Less => b.lane.cmp(&a.lane),
            _ => a.lane.cmp(&b.lane),
        })
    });
    o
}

/// Whether the chords the ends belong to nest like brackets (read from any start): that
/// is, whether no two cross.
fn nested(ends: &[EdgeEnd], stack: &mut Vec<u32>) -> bool {
    stack.clear();
    for &EdgeEnd { chord, .. } in ends {
        if stack.last() == Some(&chord) {
            stack.pop();
        } else {
            stack.push(chord);
        }
    }
    stack.is_empty()
}

/// At the position whose nodes start at `cx.shared[g]`, pairs ring `r`'s edges again as
/// nested brackets if two of its visits cross there; the new links go to `s.pairs`.
fn repair(cx: &Context, s: &mut Scratch, g: usize, r: u32) {
    sorted_ends(cx, s, g, r);
    if nested(&s.ends, &mut s.stack) {
        return;
    }
    // brackets from just after the lowest running sum (arriving +1, leaving −1), so that
    // every leaving edge finds an arriving edge open
    let (mut sum, mut lowest, mut from) = (0i64, 0i64, 0);
    for (k, e) in s.ends.iter().enumerate() {
        sum += if e.arrives { 1 } else { -1 };
        if sum < lowest {
            (lowest, from) = (sum, k + 1);
        }
    }
    s.stack.clear();
    let count = s.ends.len();
    for k in 0..count {
        let at = (from + k) % count;
        let EdgeEnd { arrives, edge, .. } = s.ends[at];
        if arrives {
            s.stack.push(at as u32);
        } else if let Some(a) = s.stack.pop() {
            s.pairs.push((s.ends[a as usize].edge, edge));
        }
    }
}

/// Most visits of one ring at one position that `cut` tries in pairs (it takes time
/// cubic in their number); past it, cycles through the position stay whole there.
const MOST_VISITS_CUT: usize = 64;

/// At the position whose nodes start at `cx.shared[g]`, cuts every cycle of ring `r` that
/// passes it twice into two, where the new pairs cross no other there. Returns whether
/// it cut any.
fn cut(cx: &mut Context, s: &mut Scratch, g: usize, r: u32) -> bool {
    sorted_ends(cx, s, g, r);
    let k = s.at.len();
    if !(2..=MOST_VISITS_CUT).contains(&k) {
        return false;
    }
    // per visit, its arriving end's place in `s.ends`
    s.arrival.clear();
    s.arrival.resize(k, 0);
    for (e, end) in s.ends.iter().enumerate() {
        if end.arrives {
            s.arrival[end.chord as usize] = e as u32;
        }
    }
    let mut any = false;
    for i in 0..k {
        for j in i + 1..k {
            let (mi, mj) = (s.at[i], s.at[j]);
            if s.cycle[mi.idx()] != s.cycle[mj.idx()] {
                continue;
            }
            // each visit takes the other's arriving edge
            let (ai, aj) = (s.arrival[i] as usize, s.arrival[j] as usize);
            s.ends[ai].chord = j as u32;
            s.ends[aj].chord = i as u32;
            if !nested(&s.ends, &mut s.stack) {
                s.ends[ai].chord = i as u32;
                s.ends[aj].chord = j as u32;
                continue;
            }
            s.arrival.swap(i, j);
            let (pi, pj) = (cx.pool.prev(mi), cx.pool.prev(mj));
            cx.pool.get_mut(pi).next = mj;
            cx.pool.get_mut(mj).prev = pi;
            cx.pool.get_mut(pj).next = mi;
            cx.pool.get_mut(mi).prev = pj;
            // the cycles are mi … pj and mj … pi: label the shorter one anew
            let (mut a, mut b) = (mi, mj);
            let shorter = loop {
                a = cx.pool.next(a);
                if a == mi {
                    break mi;
                }
                b = cx.pool.next(b);
                if b == mj {
                    break mj;
                }
            };
            label(cx, &mut s.cycle, shorter, s.labels);
            s.labels += 1;
            any = true;
        }
    }
    any
}

#[cfg(test)]
mod tests {

    /// Loads and cleans `rings` in lenient mode; returns each live ring's positions,
    /// checking that its links and ring numbers agree.
    fn lobes(rings: &[&[[f64; 2]]]) -> Vec<Vec<[f64; 2]>> {
        let (vertices, starts) = crate::testing::flatten(rings);
        let (cx, _) = crate::testing::cleaned(&vertices, &starts, true);
        let mut out = Vec::new();
        for (r, ring) in cx.rings.iter().enumerate().filter(|(_, r)| r.alive) {
            let nodes: Vec<_> = cx.pool.ring(ring.start).collect();
            assert_eq!(nodes.len(), ring.len as usize, "ring {r}'s length");
            for &n in &nodes {
                assert_eq!(cx.pool.get(n).ring as usize, r);
                assert_eq!(cx.pool.prev(cx.pool.next(n)), n);
            }
            out.push(
                nodes
                    .iter()
                    .map(|&n| [cx.pool.p(n).x, cx.pool.p(n).y])
                    .collect(),
            );
        }
        out
    }

    /// `lobes` sorted, each turned to start at its least point and walked whichever way
    /// comes first (cleaning orients every ring), for comparing.
    fn canonical(lobes: Vec<Vec<[f64; 2]>>) -> Vec<Vec<[f64; 2]>> {
        let mut lobes: Vec<_> = lobes
            .into_iter()
            .map(|lobe| {
                let mut ways = [lobe.clone(), lobe.into_iter().rev().collect()];
                for way in &mut ways {
                    let least = (0..way.len())
                        .min_by(|&i, &j| way[i].partial_cmp(&way[j]).unwrap())
                        .unwrap();
                    way.rotate_left(least);
                }
                let [a, b] = ways;
                if a <= b {
                    a
                } else {
                    b
                }
            })
            .collect();
        lobes.sort_by(|a, b| a.partial_cmp(b).unwrap());
        lobes
    }

    /// Three petals round the origin, the top one walked the other way round.
    fn petals(top_turns_back: bool) -> Vec<[f64; 2]> {
        let (a, b) = if top_turns_back {
            ([-1.0, 4.0], [1.0, 4.0])
        } else {
            ([1.0, 4.0], [-1.0, 4.0])
        };
        vec![
            [0.0, 0.0],
            [4.0, -1.0],
            [4.0, 1.0],
            [0.0, 0.0],
            a,
            b,
            [0.0, 0.0],
            [-4.0, 1.0],
            [-4.0, -1.0],
        ]
    }

    #[test]
    fn a_ring_through_one_point_three_times_gives_three_lobes() {
        // whether the top petal turns with the others (the ring touches itself) or
        // against them (it crosses itself there)
        for top_turns_back in [false, true] {
            let lobes = canonical(lobes(&[&petals(top_turns_back)]));
            let want = canonical(vec![
                vec![[0.0, 0.0], [4.0, -1.0], [4.0, 1.0]],
                vec![[0.0, 0.0], [-1.0, 4.0], [1.0, 4.0]],
                vec![[0.0, 0.0], [-4.0, 1.0], [-4.0, -1.0]],
            ]);
            assert_eq!(lobes, want, "top petal turns back: {top_turns_back}");
        }
    }

    #[test]
    fn a_hole_lobe_touching_the_outer_lobe_is_cut_off() {
        // a rectangle whose boundary runs round a triangle inside it from the bottom
        // midpoint: cut there, the triangle is a lobe of its own, which nesting makes a
        // hole
        let (x, t1, t2) = ([0.0, 0.0], [-1.0, 2.0], [1.0, 2.0]);
        let ring = [
            x,
            [4.0, 0.0],
            [4.0, 4.0],
            [-4.0, 4.0],
            [-4.0, 0.0],
            x,
            t1,
            t2,
        ];
        let want = canonical(vec![
            vec![x, [4.0, 0.0], [4.0, 4.0], [-4.0, 4.0], [-4.0, 0.0]],
            vec![x, t1, t2],
        ]);
        assert_eq!(canonical(lobes(&[&ring])), want);
    }

    #[test]
    fn lobes_do_not_overlap_whichever_copy_of_a_repeated_vertex_survives() {
        // fuzz (raw_rings, seed 7171): the outer ring A B C A D C E runs round the triangle
        // A B C twice, B lies on A–D, and a hole B C A cancels one of the turns. The
        // lobes must be A B C and A B D C E, not two that cover A B C both.
        let (a, b, c, d, e) = (
            [-12.0, -12.0],
            [-12.0, 1.0],
            [0.0, 0.0],
            [-12.0, 15.0],
            [1.0, 0.0],
        );
        let hole = [b, c, a];
        let want = canonical(vec![vec![a, b, c], vec![a, b, d, c, e], vec![b, c, a]]);
        for outer in [vec![a, b, c, a, d, c, e], vec![a, b, c, a, a, d, c, e]] {
            for turn in 0..outer.len() {
                let mut outer = outer.clone();
                outer.rotate_left(turn);
                let lobes = lobes(&[&hole, &outer]);
                assert_eq!(canonical(lobes), want, "outer ring {outer:?}");
            }
        }
    }

    #[test]
    fn lobes_inside_lobes_and_pinches_inside_edges_are_cut() {
        // a square whose boundary dents in to touch itself at (2, 2) on the way, from
        // inside (a hole lobe), and a figure eight pinched inside an edge
        let dented = [
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [2.0, 4.0],
            [2.0, 2.0],
            [3.0, 1.0],
            [1.0, 1.0],
            [2.0, 2.0],
            [2.0, 4.0],
            [0.0, 4.0],
        ];
        let eight = [
            [31.0, 11.0],
            [17.0, 0.0],
            [20.0, 0.0],
            [25.0, -12.0],
            [8.0, -12.0],
        ];
        let lobes = lobes(&[&dented, &eight]);
        let mut sizes: Vec<usize> = lobes.iter().map(Vec::len).collect();
        sizes.sort_unstable();
        // the dent's wall (2, 4) – (2, 2) walked both ways is a lobe of its own
        assert_eq!(sizes, [2, 3, 3, 3, 5], "{lobes:?}");
    }

    #[test]
    fn strict_mode_keeps_rings_whole() {
        let petals = [
            [0.0, 0.0],
            [4.0, -1.0],
            [4.0, 1.0],
            [0.0, 0.0],
            [-4.0, 1.0],
            [-4.0, -1.0],
        ];
        let (cx, _) = crate::testing::cleaned(&petals, &[0], false);
        assert_eq!(cx.rings.iter().filter(|r| r.alive).count(), 1);
        assert!(!cx.split_lobes);
    }
}
