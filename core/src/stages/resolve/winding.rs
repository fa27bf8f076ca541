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
use crate::geom::{orient2d, Orientation, Point};
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

/// Finds the boundary edges of `rule`'s region among `fragments` (pairs of points of
/// `hot`, meeting only at their ends, with net counts from the first to the second).
pub(crate) fn boundary(
    s: &mut Scratch,
    hot: &[[f64; 2]],
    fragments: &[(u32, u32, i32)],
    rule: FillRule,
) {
    s.boundary.clear();
    s.edges.clear();
    for &(a, b, c) in fragments {
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
        let mut w = s
            .status
            .before(lo)
            .and_then(|c| s.status.item(c))
            .map_or(0, |e| s.above[e as usize]);
        // the edges starting at v, bottom to top
        s.new.clear();
        let (f0, f1) = (
            s.first[v as usize] as usize,
            s.first[v as usize + 1] as usize,
        );
        s.new.extend_from_slice(&s.starting[f0..f1]);
        s.new.sort_unstable_by(|&a, &b| {
            let (qa, qb) = (
                hot[edges[a as usize].q as usize],
                hot[edges[b as usize].q as usize],
            );
            match orient2d(pv, pt(qa), pt(qb)) {
                Orientation::CounterClockwise => Ordering::Less,
                Orientation::Clockwise => Ordering::Greater,
                Orientation::Collinear => Ordering::Equal,
            }
        });
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
}

#[cfg(test)]
mod tests {
    use super::{lex, sweep_order, Scratch};
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
