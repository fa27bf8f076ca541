//! The winding of a ring that walks some segments several times (walls, cracks, rings
//! spliced where they touch): read on its *net* boundary, the segments left when walks
//! in opposite directions cancel. Shared by `clean` (orienting rings) and `touch`
//! (re-tracing them).

use crate::geom::{cmp_xy, orient2d, Orientation, Point};
use crate::structures::{NodeId, Pool};

/// A segment of a ring with its ends sorted (`lower` before `upper` by x, then y) and
/// how often the ring walks it from `lower` to `upper`, minus the walks back.
#[derive(Clone, Copy, Debug)]
pub(crate) struct NetEdge {
    pub lower: Point,
    pub upper: Point,
    pub net: i64,
}

/// Whether the ring through `start` winds counter-clockwise, read on its net boundary: its
/// edges with every segment walked both ways cancelled (walls, spikes and cracks enclose
/// nothing), at the rightmost-lowest position the rest reaches, by the outermost direction
/// there that more edges arrive along than leave, or fewer (see `clean::outermost_edge_arrives`).
/// `None` when nothing is left (the ring encloses nothing). For rings whose extreme
/// position lies on walls only, where the turns there say nothing. Exact.
pub(crate) fn net_boundary_counter_clockwise(
    pool: &Pool,
    start: NodeId,
    edges: &mut Vec<NetEdge>,
) -> Option<bool> {
    edges.clear();
    for n in pool.ring(start) {
        let (a, b) = (pool.p(n), pool.p(pool.next(n)));
        // (lower end, upper end, +1 from lower to upper, −1 back)
        edges.push(if cmp_xy(a, b) == core::cmp::Ordering::Less {
            NetEdge {
                lower: a,
                upper: b,
                net: 1,
            }
        } else {
            NetEdge {
                lower: b,
                upper: a,
                net: -1,
            }
        });
    }
    edges.sort_unstable_by(|e, f| cmp_xy(e.lower, f.lower).then(cmp_xy(e.upper, f.upper)));
    // sum the walks of each segment; keep those not cancelled
    let mut kept = 0;
    let mut i = 0;
    while i < edges.len() {
        let NetEdge {
            lower: a,
            upper: b,
            mut net,
        } = edges[i];
        let mut j = i + 1;
        while j < edges.len() && edges[j].lower == a && edges[j].upper == b {
            net += edges[j].net;
            j += 1;
        }
        if net != 0 {
            edges[kept] = NetEdge {
                lower: a,
                upper: b,
                net,
            };
            kept += 1;
        }
        i = j;
    }
    edges.truncate(kept);
    // the rightmost-lowest end (of either kind: a lower end may be it, below an upper end
    // straight above)
    let x = edges
        .iter()
        .flat_map(|e| [e.lower, e.upper])
        .reduce(|b, p| {
            if p.x > b.x || (p.x == b.x && p.y < b.y) {
                p
            } else {
                b
            }
        });
    let result = x.and_then(|x| {
        // (far end, net arrivals at x along it)
        let at_x = edges.iter().filter_map(
            |&NetEdge {
                 lower: a,
                 upper: b,
                 net,
             }| {
                if b == x {
                    Some((a, net))
                } else if a == x {
                    Some((b, -net))
                } else {
                    None
                }
            },
        );
        let along = |q: Point| -> i64 {
            at_x.clone()
                .filter(|&(f, _)| orient2d(x, q, f) == Orientation::Collinear)
                .map(|(_, d)| d)
                .sum()
        };
        lowest_net_arrives(x, at_x.clone().map(|(q, _)| q), along)
    });
    result
}

/// Of the directions from `x` towards `ends`, all in the closed left half-plane (`x` is a
/// rightmost-lowest position), the lowest whose `net` arrivals are not zero: whether they
/// are more than zero. `None` when every direction nets zero.
pub(crate) fn lowest_net_arrives(
    x: Point,
    ends: impl Iterator<Item = Point>,
    net: impl Fn(Point) -> i64,
) -> Option<bool> {
    let mut lowest: Option<(Point, i64)> = None;
    for q in ends {
        // within a half-plane, counter-clockwise of the lowest means lower still
        let lower = lowest.map_or(true, |(e, _)| {
            orient2d(x, e, q) == Orientation::CounterClockwise
        });
        if lower {
            let d = net(q);
            if d != 0 {
                lowest = Some((q, d));
            }
        }
    }
    lowest.map(|(_, d)| d > 0)
}

#[cfg(test)]
mod tests {
    use super::net_boundary_counter_clockwise;
    use crate::structures::Pool;

    /// The ring's winding read on its net boundary, in both directions and from every start.
    fn net_winding(ring: &[(f64, f64)]) -> Option<bool> {
        let mut answers = Vec::new();
        for reversed in [false, true] {
            for start in 0..ring.len() {
                let mut r: Vec<(f64, f64)> = ring.to_vec();
                if reversed {
                    r.reverse();
                }
                r.rotate_left(start);
                let (pool, starts) = Pool::from_rings(&[r]);
                let got = net_boundary_counter_clockwise(&pool, starts[0], &mut Vec::new());
                answers.push(if reversed { got.map(|ccw| !ccw) } else { got });
            }
        }
        assert!(answers.windows(2).all(|w| w[0] == w[1]), "{answers:?}");
        answers[0]
    }

    #[test]
    fn walls_do_not_decide_the_winding() {
        // a counter-clockwise square with a wall out to (6, 1) from its right side: the
        // wall's tip is the rightmost-lowest vertex, where the ring turns straight back
        let spiked = [
            (0.0, 0.0),
            (4.0, 0.0),
            (4.0, 1.0),
            (6.0, 1.0),
            (4.0, 1.0),
            (4.0, 4.0),
            (0.0, 4.0),
        ];
        assert_eq!(net_winding(&spiked), Some(true));
        // precision fuzz target, seed 8181 (shrunk): a pentagon, the same pentagon walked back
        // round a larger one, a triangle back; only the quadrilateral F A D G is left, and
        // it turns clockwise as given
        let (a, b, c, d, e, f, g) = (
            (1.0, 0.0),
            (2.0, 1.0),
            (2.0, 2.0),
            (1.0, 2.0),
            (0.0, 1.0),
            (0.0, 0.0),
            (0.0, 2.0),
        );
        let spiral = [a, b, c, d, e, a, f, e, g, d, c, b, a, e, d];
        assert_eq!(net_winding(&spiral), Some(false));
        // a ring walking one segment out and back encloses nothing
        assert_eq!(net_winding(&[(0.0, 0.0), (1.0, 1.0)]), None);
    }
}
