//! The winding numbers on both sides of every edge of a planar arrangement, by a sweep,
//! and the edges where the fill rule's region begins or ends.
//!
//! The sweep visits the vertices in lexicographic order (x, then y), which is a vertical
//! sweep line tilted by an infinitesimal angle: an edge runs from its lexicographically
//! smaller end `p` to its larger end `q`, its *upper* side is its left side seen from `p`
//! (for a vertical edge, the side of smaller x), and the status lists the edges the line
//! crosses from bottom to top. The edges meet only at their ends (the arrangement is
//! planar), so the status order never changes between events, and every comparison is one
//! [`orient2d`] sign. Below the lowest edge the winding number is 0; crossing an edge
//! upward adds its net count (taken from `p` to `q`: a counter-clockwise ring has the
//! inside on its left).

use core::cmp::Ordering;

use crate::crossings::status::{Blocks, Sequence};
use crate::geom::{orient2d, overlaps, segments_meet, Orientation, Point};
use crate::FillRule;

/// An edge from its smaller end `p` to its larger `q`, with its net count from p to q.
#[derive(Clone, Copy, Debug)]
struct Edge {
    p: u32,
    q: u32,
    count: i32,
}

/// The sweep's buffers, and its result.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    edges: Vec<Edge>,
    /// Winding number just above each edge.
    above: Vec<i64>,
    /// The vertices in sweep order.
    order: Vec<u32>,
    /// The vertices after the sorted run `hot` starts with, sorted.
    tail: Vec<u32>,
    /// Edges by their smaller end, in compressed rows.
    first: Vec<u32>,
    starting: Vec<u32>,
    status: Blocks<u32>,
    new: Vec<u32>,
    /// The result: the region's boundary edges, directed with the region on their left.
    pub boundary: Vec<(u32, u32)>,
}

fn lex(a: [f64; 2], b: [f64; 2]) -> Ordering {
    a[0].partial_cmp(&b[0])
        .unwrap_or(Ordering::Equal)
        .then(a[1].partial_cmp(&b[1]).unwrap_or(Ordering::Equal))
}

/// The points of `hot` (distinct) in lexicographic order, into `s.order`. `resolve` lists
/// the input's positions sorted, then the added crossings: only the run after the sorted
/// one is sorted, and merged with it.
fn sweep_order(s: &mut Scratch, hot: &[[f64; 2]]) {
    let n = hot.len();
    let less = |a: u32, b: u32| lex(hot[a as usize], hot[b as usize]) == Ordering::Less;
    let run = 1 + (1..n as u32).take_while(|&i| less(i - 1, i)).count();
    s.tail.clear();
    s.tail.extend(run.min(n) as u32..n as u32);
    s.tail
        .sort_unstable_by(|&a, &b| lex(hot[a as usize], hot[b as usize]));
    s.order.clear();
    let (mut i, mut tail) = (0, s.tail.iter().copied().peekable());
    while i < run.min(n) as u32 {
        match tail.peek() {
            Some(&t) if less(t, i) => {
                s.order.push(t);
                tail.next();
            }
            _ => {
                s.order.push(i);
                i += 1;
            }
        }
    }
    s.order.extend(tail);
}

fn pt(p: [f64; 2]) -> Point {
    Point::new(p[0], p[1])
}

/// Finds the boundary edges of `rule`'s region among `fragments` (pairs of distinct
/// points of `hot`, no pair twice, with net counts from the first to the second), which
/// must meet only at their ends.
///
/// With `verify`, the sweep also proves that they do, as Shamos and Hoey's sweep does:
/// it returns false (its boundary then means nothing) where a fragment passes through a
/// vertex, two run along each other from one, or two that become neighbours in the
/// status meet other than at an end they share. The first point (in sweep order) where
/// two fragments meet otherwise is one of these: the status is in order before it, so two
/// fragments through it are neighbours there or one of them ends there.
pub(crate) fn boundary(
    s: &mut Scratch,
    hot: &[[f64; 2]],
    fragments: &[super::Edge],
    rule: FillRule,
    verify: bool,
) -> bool {
    s.boundary.clear();
    s.edges.clear();
    for &super::Edge { a, b, count: c, .. } in fragments {
        let e = if lex(hot[a as usize], hot[b as usize]) == Ordering::Less {
            Edge {
                p: a,
                q: b,
                count: c,
            }
        } else {
            Edge {
                p: b,
                q: a,
                count: -c,
            }
        };
        s.edges.push(e);
    }
    // edges by their smaller end
    let n = hot.len();
    super::rows(
        &mut s.first,
        &mut s.starting,
        n,
        s.edges.iter().map(|e| e.p),
    );
    sweep_order(s, hot);
    s.above.clear();
    s.above.resize(s.edges.len(), 0);
    s.status.assign(&[], s.edges.len());
    let edges = &s.edges;
    for &v in &s.order {
        let pv = pt(hot[v as usize]);
        // the edges below v, then those ending at v (no edge passes through v)
        let below = |&e: &u32| {
            let e = edges[e as usize];
            orient2d(pt(hot[e.p as usize]), pt(hot[e.q as usize]), pv)
                == Orientation::CounterClockwise
        };
        let lo = s.status.search(below);
        let hi = s.status.walk(lo, |&e| edges[e as usize].q == v);
        let under = s.status.before(lo).and_then(|c| s.status.item(c));
        let over = s.status.item(hi);
        // (the first fragment above those ending at v passes strictly above v)
        let passes_above = |e: u32| {
            let e = edges[e as usize];
            orient2d(pt(hot[e.p as usize]), pt(hot[e.q as usize]), pv) == Orientation::Clockwise
        };
        if verify && over.is_some_and(|e| !passes_above(e)) {
            return false;
        }
        let mut w = under.map_or(0, |e| s.above[e as usize]);
        // the edges starting at v, bottom to top
        s.new.clear();
        let (f0, f1) = (
            s.first[v as usize] as usize,
            s.first[v as usize + 1] as usize,
        );
        s.new.extend_from_slice(&s.starting[f0..f1]);
        let turn = |a: u32, b: u32| {
            let (qa, qb) = (
                hot[edges[a as usize].q as usize],
                hot[edges[b as usize].q as usize],
            );
            orient2d(pv, pt(qa), pt(qb))
        };
        s.new.sort_unstable_by(|&a, &b| match turn(a, b) {
            Orientation::CounterClockwise => Ordering::Less,
            Orientation::Clockwise => Ordering::Greater,
            Orientation::Collinear => Ordering::Equal,
        });
        if verify {
            // (two leaving v to the right in one direction run along each other)
            let along = (s.new.windows(2)).any(|w| turn(w[0], w[1]) == Orientation::Collinear);
            // the new neighbours: below and above the fragments starting at v, or each
            // other where none does
            let (first, last) = (s.new.first().copied(), s.new.last().copied());
            let apart = |e: Option<u32>, f: Option<u32>| match (e, f) {
                (Some(e), Some(f)) => !improper(hot, edges[e as usize], edges[f as usize]),
                _ => true,
            };
            let fine = if first.is_some() {
                apart(under, first) && apart(last, over)
            } else {
                apart(under, over)
            };
            if along || !fine {
                return false;
            }
        }
        for &e in &s.new {
            let edge = edges[e as usize];
            let below_w = w;
            w += i64::from(edge.count);
            s.above[e as usize] = w;
            let (inside_above, inside_below) = (rule.contains(w), rule.contains(below_w));
            if inside_above != inside_below {
                s.boundary.push(if inside_above {
                    (edge.p, edge.q)
                } else {
                    (edge.q, edge.p)
                });
            }
        }
        s.status.replace(lo, hi, &s.new);
    }
    true
}

/// Whether fragments `e` and `f` (distinct, between distinct points) meet other than at
/// an end they share: cross, touch, or run along each other.
fn improper(hot: &[[f64; 2]], e: Edge, f: Edge) -> bool {
    let [a, b, c, d] = [e.p, e.q, f.p, f.q].map(|v| pt(hot[v as usize]));
    if e.p == f.p || e.p == f.q || e.q == f.p || e.q == f.q {
        overlaps(a, b, c, d)
    } else {
        segments_meet(a, b, c, d)
    }
}

#[cfg(test)]
mod tests {
    use super::{boundary, lex, sweep_order, Scratch};
    use crate::FillRule;

    /// The sweep's proof that fragments meet only at their ends: it passes a square cut
    /// by a diagonal (and finds its boundary), and fails wherever two meet otherwise —
    /// crossing, a vertex inside a fragment, two along each other from one end or one
    /// inside the other — whichever way the fragments are listed.
    #[test]
    fn the_sweep_proves_fragments_meet_only_at_their_ends() {
        let mut hot = vec![
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 2.0],
            [0.0, 2.0],
            [1.0, 1.0],
            [3.0, 3.0],
        ];
        // the square, counter-clockwise
        let square = [(0, 1, 1), (1, 2, 1), (2, 3, 1), (3, 0, 1)];
        let mut s = Scratch::default();
        let mut with = |hot: &[[f64; 2]], extra: &[(u32, u32, i32)]| {
            let mut fragments: Vec<super::super::Edge> = (square.iter().chain(extra))
                .map(|&(a, b, count)| super::super::Edge {
                    from: 0,
                    a,
                    b,
                    count,
                })
                .collect();
            let mut planar = [false; 2];
            for (k, planar) in planar.iter_mut().enumerate() {
                if k == 1 {
                    fragments.reverse();
                }
                *planar = boundary(&mut s, hot, &fragments, FillRule::NonZero, true);
            }
            assert_eq!(planar[0], planar[1], "{extra:?}");
            (planar[0], s.boundary.len())
        };
        // a diagonal in two halves meeting at the centre, run once each way (net 0):
        // planar, the square's 4 edges
        assert_eq!(with(&hot, &[(0, 4, 0), (4, 2, 0)]), (true, 4));
        // the two diagonals, whole: they cross at (1, 1)
        assert!(!with(&hot, &[(0, 2, 0), (1, 3, 0)]).0);
        // from one end along each other (0 → 4 on 0 → 5), or one inside the other
        assert!(!with(&hot, &[(0, 4, 0), (0, 5, 0)]).0);
        assert!(!with(&hot, &[(4, 2, 0), (0, 5, 0)]).0);
        // the centre on a whole diagonal
        assert!(!with(&hot, &[(0, 2, 0), (4, 5, 0)]).0);
        // (1, 0) inside the bottom edge, with an edge from it or alone
        hot.push([1.0, 0.0]);
        assert!(!with(&hot, &[(6, 4, 0)]).0);
        assert!(!with(&hot, &[]).0);
    }
    use crate::testing::random;
    use core::cmp::Ordering;

    /// The merge of a sorted run with the sorted rest is the full sort, whatever the
    /// run's length (none, all, or the input's positions before a few crossings).
    #[test]
    fn sweep_order_sorts_whatever_the_sorted_run() {
        let mut random = random(0x2545_f491_4f6c_dd1d);
        let mut next = || random(1 << 24) as f64;
        for (sorted, rest) in [
            (0, 0),
            (1, 0),
            (0, 5),
            (50, 0),
            (50, 7),
            (3, 40),
            (200, 200),
        ] {
            let mut hot: Vec<[f64; 2]> = (0..sorted + rest).map(|_| [next(), next()]).collect();
            hot[..sorted].sort_by(|a, b| lex(*a, *b));
            hot.dedup();
            let mut s = Scratch::default();
            sweep_order(&mut s, &hot);
            let mut expected: Vec<u32> = (0..hot.len() as u32).collect();
            expected.sort_by(|&a, &b| lex(hot[a as usize], hot[b as usize]));
            assert_eq!(s.order, expected, "{sorted} sorted, {rest} after");
            assert!(s
                .order
                .windows(2)
                .all(|w| lex(hot[w[0] as usize], hot[w[1] as usize]) == Ordering::Less));
        }
    }
}
