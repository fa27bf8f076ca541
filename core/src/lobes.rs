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
//! The cut keeps every edge and only re-pairs, at each position the ring passes more than
//! once, which edge leaves after which edge arrives: walking the ring once, a position seen
//! before closes the loop walked since then (a stack, as when splitting a closed walk into
//! simple cycles). Each lobe becomes a new ring entry with the same input ring number;
//! `touch` joins them again properly once nesting has turned them. Input with crossing
//! edges is left whole: it has no region to keep, and its repairs were tuned on whole rings.
//!
//! Strict mode keeps rings whole too: a ring whose lobes turn opposite ways is refused
//! there (as `Error::LobesWindOpposite`, or as rings crossing at a vertex), cancelled lobe
//! or not.

use crate::pool::NodeId;
use crate::triangulator::{Context, Ring};

/// Scratch buffers of the lobe split, kept between calls.
#[derive(Debug, Default)]
pub(crate) struct LobeScratch {
    /// Per node: the index into `cx.shared` of its position's first node, or `NONE`.
    group: Vec<u32>,
    /// Per position (by its first index into `cx.shared`): its entry in `stack`, or `NONE`.
    open: Vec<u32>,
    /// The positions visited on the walk so far whose loops are still open, in walk order.
    stack: Vec<(u32, NodeId)>,
    /// One ring's nodes in order.
    walk: Vec<NodeId>,
    /// Rings that pass some position more than once.
    rings: Vec<u32>,
}

const NONE: u32 = u32::MAX;

/// Splits every ring that passes a position more than once into lobes (lenient mode).
/// Returns whether any ring was split.
pub(crate) fn split(cx: &mut Context) -> bool {
    let mut s = core::mem::take(&mut cx.lobes);
    s.rings.clear();
    // rings visiting one position twice, from the groups of shared nodes
    let mut i = 0;
    while i < cx.shared.len() {
        let j = crate::touch::same_position_end(cx, i);
        for a in i..j {
            let ra = cx.pool.get(cx.shared[a]).ring;
            let repeats = cx.shared[a + 1..j]
                .iter()
                .any(|&n| cx.pool.get(n).ring == ra);
            if repeats && !cx.pool.get(cx.shared[a]).removed && !s.rings.contains(&ra) {
                s.rings.push(ra);
            }
        }
        i = j;
    }
    let split_any = !s.rings.is_empty();
    if split_any {
        s.group.clear();
        s.group.resize(cx.pool.len(), NONE);
        s.open.clear();
        s.open.resize(cx.shared.len(), NONE);
        let mut i = 0;
        while i < cx.shared.len() {
            let j = crate::touch::same_position_end(cx, i);
            for &n in &cx.shared[i..j] {
                s.group[n.idx()] = i as u32;
            }
            i = j;
        }
        for k in 0..s.rings.len() {
            let r = s.rings[k] as usize;
            split_ring(cx, &mut s, r);
        }
    }
    cx.lobes = s;
    split_any
}

/// Walks ring `r` once; a position met again closes the loop walked since its last visit.
fn split_ring(cx: &mut Context, s: &mut LobeScratch, r: usize) {
    let ring = cx.rings[r];
    if !ring.alive {
        return;
    }
    s.walk.clear();
    s.walk.extend(cx.pool.ring(ring.start));
    s.stack.clear();
    let mut closed = 0;
    for k in 0..s.walk.len() {
        let w = s.walk[k];
        let g = s.group[w.idx()];
        if g == NONE {
            continue;
        }
        let at = s.open[g as usize];
        if at == NONE {
            s.open[g as usize] = s.stack.len() as u32;
            s.stack.push((g, w));
            continue;
        }
        // the loop from v (the last visit) to just before w becomes a lobe; the walk
        // goes on from w, which takes v's place on the stack
        let at = at as usize;
        for &(h, _) in &s.stack[at + 1..] {
            s.open[h as usize] = NONE;
        }
        s.stack.truncate(at + 1);
        let v = s.stack[at].1;
        s.stack[at].1 = w;
        let (pv, pw) = (cx.pool.prev(v), cx.pool.prev(w));
        cx.pool.get_mut(pw).next = v;
        cx.pool.get_mut(v).prev = pw;
        cx.pool.get_mut(pv).next = w;
        cx.pool.get_mut(w).prev = pv;
        let index = cx.rings.len() as u32;
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
        closed += len;
        cx.rings.push(Ring {
            start: v,
            len,
            rightmost: v,
            depth: 0,
            alive: true,
            merged: false,
            component: index,
            ..ring
        });
    }
    for &(h, _) in &s.stack {
        s.open[h as usize] = NONE;
    }
    // the walk's last node is never inside a closed loop: it is the rest of the ring
    if let Some(&last) = s.walk.last() {
        cx.rings[r].start = last;
        cx.rings[r].len = ring.len - closed;
    }
}

/// Whether ring `r` is a lobe, or what is left of a ring split into lobes.
pub(crate) fn was_split(cx: &Context, r: usize) -> bool {
    cx.split_lobes && (r >= cx.blocks.len() || cx.lobes.rings.contains(&(r as u32)))
}

#[cfg(test)]
mod tests {
    use crate::triangulator::Context;

    /// Loads and cleans `rings` in lenient mode; returns each live ring's positions,
    /// checking that its links and ring numbers agree.
    fn lobes(rings: &[&[[f64; 2]]]) -> Vec<Vec<[f64; 2]>> {
        let mut vertices = Vec::new();
        let mut starts = Vec::new();
        for ring in rings {
            starts.push(vertices.len());
            vertices.extend_from_slice(ring);
        }
        let mut cx = Context {
            lenient: true,
            ..Context::default()
        };
        crate::load::load(&mut cx, &vertices, &starts).unwrap();
        assert!(crate::clean::clean(&mut cx, false).unwrap());
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

    #[test]
    fn a_ring_through_one_point_three_times_gives_three_lobes() {
        let petals = [
            [0.0, 0.0],
            [4.0, -1.0],
            [4.0, 1.0],
            [0.0, 0.0],
            [-1.0, 4.0],
            [1.0, 4.0],
            [0.0, 0.0],
            [-4.0, 1.0],
            [-4.0, -1.0],
        ];
        let lobes = lobes(&[&petals]);
        assert_eq!(lobes.len(), 3);
        for lobe in &lobes {
            assert_eq!(lobe.len(), 3);
            assert!(lobe.contains(&[0.0, 0.0]));
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
        let mut cx = Context::default();
        crate::load::load(&mut cx, &petals, &[0]).unwrap();
        assert!(crate::clean::clean(&mut cx, false).unwrap());
        assert_eq!(cx.rings.iter().filter(|r| r.alive).count(), 1);
        assert!(!cx.split_lobes);
    }
}
