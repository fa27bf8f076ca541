//! The even–odd rule's short way, for rings whose edges only cross each other properly (a
//! simplified border looping over itself, a bow tie): each crossing is rounded to the
//! grid, both edges are split there, and the two passes through the point are relinked
//! so that they touch instead of crossing. The rings then neither cross nor change their
//! even–odd region (beyond the rounding), and the usual pipeline, strict, triangulates
//! them; where it refuses them, the caller resolves the input the long way
//! ([`super::resolve`]).
//!
//! **Why the region stays.** A point's even–odd parity is the parity of the edges a ray
//! from it crosses: it depends on the set of edges, not on how they are linked into
//! rings. Splitting edge a–b at the rounded crossing p′ replaces a–b by a–p′–b: the
//! parity changes only inside the thin triangle a, b, p′, whose height is the rounding
//! (less than a pixel's diagonal). Relinking changes no edge. So the relinked rings'
//! even–odd region is the input's up to those triangles, the same allowance as snap
//! rounding's.
//!
//! **Why they do not cross.** Where a → p → b crosses c → p → d, the four directions
//! round p alternate between the two lines (a, c, b, d or a, d, b, c); the relinked passes
//! a → p → d and c → p → b each take two neighbouring directions, so they touch at p. That
//! holds for the exact crossing; the rounded point may upset it (or make a split edge pass
//! on the other side of a vertex) where edges come within a pixel of each other. Nothing
//! here relies on it: the pipeline's strict check decides exactly whether the relinked
//! rings cross anywhere, and its triangles are then exact for them.
//!
//! The short way declines (the long way runs) where some edges overlap or meet without
//! crossing properly only if no edge crosses at all, where two crossings round to one
//! point, or a crossing rounds onto an end of its edges.

use super::{bounds, find_crossings, typical_extent, Edge, Scratch as Resolve};
use crate::geom::{in_range, SnapGrid};
use crate::report::Added;
use crate::Error;

/// The short way's buffers.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// Each node's successor: the input's vertices first, then the copies of the
    /// crossing points on their edges.
    next: Vec<u32>,
    /// The crossing points on the edges: (the edge's start vertex, the crossing), sorted
    /// along each edge; copy `t` is node `n + t`.
    on_edges: Vec<(u32, u32)>,
    /// Each crossing's two copies.
    copies: Vec<[u32; 2]>,
    seen: Vec<bool>,
}

/// Rings of the input's vertices and its rounded crossings whose even–odd region is the
/// input's (see the module docs), into `r.rings`, `r.ring_starts` and `r.map` (each
/// ring position's output index: an input vertex's own, or an added vertex's, pushed to
/// `added`). `Ok(false)` where the short way declines; `r`'s rings are empty then and
/// `added` is as it was.
pub(crate) fn uncross(
    r: &mut Resolve,
    vertices: &[[f64; 2]],
    ring_starts: &[usize],
    grid: SnapGrid,
    added: &mut Vec<Added>,
) -> Result<bool, Error> {
    let mut s = core::mem::take(&mut r.uncross);
    let made = relink(r, &mut s, vertices, ring_starts, grid, added);
    r.uncross = s;
    made
}

/// [`uncross`] with its buffers apart from the stage's.
fn relink(
    r: &mut Resolve,
    s: &mut Scratch,
    vertices: &[[f64; 2]],
    ring_starts: &[usize],
    grid: SnapGrid,
    added: &mut Vec<Added>,
) -> Result<bool, Error> {
    r.rings.clear();
    r.ring_ids.clear();
    r.ring_starts.clear();
    r.map.clear();
    let n = vertices.len();
    let in_grid = |p: &[f64; 2]| in_range(p[0]) && in_range(p[1]);
    if n == 0 || u32::try_from(n).is_err() || !vertices.iter().all(in_grid) {
        return Ok(false);
    }
    // every vertex its own point (positions shared by several are the pipeline's)
    r.hot.clear();
    r.hot
        .extend(vertices.iter().map(|p| [p[0] + 0.0, p[1] + 0.0]));
    s.next.clear();
    r.edges.clear();
    for (k, &start) in ring_starts.iter().enumerate() {
        let end = ring_starts.get(k + 1).copied().unwrap_or(n).min(n);
        for i in start.min(end)..end {
            let j = if i + 1 < end { i + 1 } else { start };
            s.next.push(j as u32);
            if r.hot[i] != r.hot[j] {
                let (i, j) = (i as u32, j as u32);
                r.edges.push(Edge {
                    from: i,
                    a: i,
                    b: j,
                });
            }
        }
    }
    if s.next.len() != n || r.edges.is_empty() {
        return Ok(false);
    }
    r.typical = typical_extent(&r.edges, &r.hot);
    let (lo, hi) = bounds(&r.hot);
    let largest = lo[0]
        .abs()
        .max(lo[1].abs())
        .max(hi[0].abs())
        .max(hi[1].abs());
    find_crossings(r, lo, hi, grid, grid.half_width(largest));
    if r.crossings.is_empty() {
        return Ok(false);
    }
    let order = |x: &[f64; 2], y: &[f64; 2]| x[0].total_cmp(&y[0]).then(x[1].total_cmp(&y[1]));
    r.crossings.sort_unstable_by(|x, y| order(&x.0, &y.0));
    let hot = &r.hot;
    let onto_end = |&(p, e, f): &([f64; 2], u32, u32)| {
        [e, f]
            .iter()
            .any(|&e| p == hot[e as usize] || p == hot[s.next[e as usize] as usize])
    };
    let twice = r.crossings.windows(2).any(|w| w[0].0 == w[1].0);
    if twice || r.crossings.iter().any(onto_end) {
        return Ok(false);
    }
    // the crossings on each edge, in order from its start: the points met on a segment
    // have monotone coordinates, so ordering by (±x, ±y) as the edge runs orders them
    // along it
    s.on_edges.clear();
    for (c, &(_, e, f)) in r.crossings.iter().enumerate() {
        s.on_edges.push((e, c as u32));
        s.on_edges.push((f, c as u32));
    }
    if u32::try_from(n + s.on_edges.len()).is_err() {
        return Ok(false);
    }
    let (crossings, next) = (&r.crossings, &s.next);
    s.on_edges.sort_unstable_by(|&(e, c), &(f, d)| {
        e.cmp(&f).then_with(|| {
            let (a, b) = (hot[e as usize], hot[next[e as usize] as usize]);
            let (p, q) = (crossings[c as usize].0, crossings[d as usize].0);
            let along = |p: [f64; 2]| {
                let sx = if b[0] >= a[0] { p[0] } else { -p[0] };
                let sy = if b[1] >= a[1] { p[1] } else { -p[1] };
                [sx, sy]
            };
            order(&along(p), &along(q))
        })
    });
    // split the edges: edge i → j becomes i → copies → j
    let base = n as u32;
    s.copies.clear();
    s.copies.resize(crossings.len(), [u32::MAX; 2]);
    s.next.resize(n + s.on_edges.len(), 0);
    let mut t = 0;
    while t < s.on_edges.len() {
        let e = s.on_edges[t].0;
        let end = s.next[e as usize];
        let mut at = e;
        while t < s.on_edges.len() && s.on_edges[t].0 == e {
            let copy = base + t as u32;
            s.next[at as usize] = copy;
            let slot = &mut s.copies[s.on_edges[t].1 as usize];
            slot[usize::from(slot[0] != u32::MAX)] = copy;
            (at, t) = (copy, t + 1);
        }
        s.next[at as usize] = end;
    }
    // at each crossing, the two passes swap their ways on: they touch there
    for &[u, w] in &s.copies {
        s.next.swap(u as usize, w as usize);
    }
    // the added vertices, one per crossing (none shares a position with another)
    let first_added = n + added.len();
    for &(position, e, f) in crossings.iter() {
        let vertex = n + added.len();
        let vertex = u32::try_from(vertex).map_err(|_| Error::TooManyVertices { count: vertex })?;
        added.push(Added {
            vertex,
            position,
            edges: [e, f],
        });
    }
    // the rings: the cycles of the successors, from every node not yet on one
    let nodes = s.next.len();
    s.seen.clear();
    s.seen.resize(nodes, false);
    for start in 0..nodes {
        if s.seen[start] {
            continue;
        }
        r.ring_starts.push(r.rings.len());
        let mut v = start;
        while !s.seen[v] {
            s.seen[v] = true;
            let (position, id) = if v < n {
                (hot[v], v as u32)
            } else {
                let c = s.on_edges[v - n].1 as usize;
                (crossings[c].0, (first_added + c) as u32)
            };
            r.rings.push(position);
            r.map.push(id);
            v = s.next[v] as usize;
        }
    }
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::FillRule;

    type Rings = Vec<Vec<[f64; 2]>>;

    /// The relinked rings of `rings`, and the vertices added.
    fn relinked(rings: &[Vec<[f64; 2]>]) -> Option<(Rings, Vec<Added>)> {
        let (vertices, starts) = flat(rings);
        let mut r = Resolve::default();
        let mut added = Vec::new();
        let grid = SnapGrid { f32: false };
        if !uncross(&mut r, &vertices, &starts, grid, &mut added).unwrap() {
            assert!(added.is_empty() && r.rings.is_empty());
            return None;
        }
        let ends = r.ring_starts.iter().skip(1).copied().chain([r.rings.len()]);
        let out = (r.ring_starts.iter().zip(ends))
            .map(|(&a, b)| r.rings[a..b].to_vec())
            .collect();
        // each position's output index: an input vertex's own, or an added one's
        for (p, &id) in r.rings.iter().zip(&r.map) {
            let at = if (id as usize) < vertices.len() {
                vertices[id as usize]
            } else {
                added[id as usize - vertices.len()].position
            };
            assert_eq!(*p, at);
        }
        Some((out, added))
    }

    fn flat(rings: &[Vec<[f64; 2]>]) -> (Vec<[f64; 2]>, Vec<usize>) {
        let rings: Vec<&[[f64; 2]]> = rings.iter().map(Vec::as_slice).collect();
        crate::testing::flatten(&rings)
    }

    /// The even–odd area of `rings` and the vertices added, the long way
    /// ([`super::super::resolve`]).
    fn even_odd(rings: &[Vec<[f64; 2]>]) -> (f64, usize) {
        let (vertices, starts) = flat(rings);
        let mut r = Resolve::default();
        let mut added = Vec::new();
        let grid = SnapGrid { f32: false };
        let rule = FillRule::EvenOdd;
        super::super::resolve(&mut r, &vertices, &starts, rule, grid, false, &mut added).unwrap();
        let mut twice = 0.0;
        let ends = r.ring_starts.iter().skip(1).copied().chain([r.rings.len()]);
        for (&a, b) in r.ring_starts.iter().zip(ends) {
            let ring = &r.rings[a..b];
            for (j, p) in ring.iter().enumerate() {
                let q = ring[(j + 1) % ring.len()];
                twice += p[0] * q[1] - p[1] * q[0];
            }
        }
        (twice / 2.0, added.len())
    }

    /// Strict mode's check passes on `rings` (no crossing, also not at a vertex they
    /// share).
    fn assert_valid(rings: &[Vec<[f64; 2]>], name: &str) {
        let (vertices, starts) = flat(rings);
        let checked =
            crate::Triangulator::<f64>::new().check(&vertices, &starts, crate::Nesting::Auto);
        assert_eq!(checked, Ok(()), "{name}: {rings:?}");
    }

    fn square(x: f64, y: f64, side: f64) -> Vec<[f64; 2]> {
        vec![[x, y], [x + side, y], [x + side, y + side], [x, y + side]]
    }

    /// Crossings whose points are exact (no rounding): the relinked rings cross nowhere
    /// (the long way adds no vertex to them) and have the input's even–odd region.
    #[test]
    fn relinked_rings_touch_where_the_input_crossed_and_keep_its_region() {
        let bow_tie = vec![[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
        // a ring crossing itself twice, the way a simplified border does
        let loop_over = vec![
            [0.0, 0.0],
            [8.0, 0.0],
            [8.0, 4.0],
            [2.0, -2.0],
            [4.0, 6.0],
            [0.0, 4.0],
        ];
        let cases: [(&str, Rings, usize); 4] = [
            ("bow tie", vec![bow_tie], 1),
            (
                "overlapping squares",
                vec![square(0.0, 0.0, 2.0), square(1.0, 1.0, 2.0)],
                2,
            ),
            (
                "a hole across its outer ring",
                vec![square(0.0, 0.0, 4.0), square(3.0, 1.0, 2.0)],
                2,
            ),
            ("a ring looping over itself", vec![loop_over], 2),
        ];
        for (name, rings, crossings) in cases {
            let (area, long_way_added) = even_odd(&rings);
            assert_eq!(long_way_added, crossings, "{name}");
            let (relinked, added) = relinked(&rings).unwrap_or_else(|| panic!("{name}: declined"));
            assert_eq!(added.len(), crossings, "{name}");
            let (relinked_area, again) = even_odd(&relinked);
            assert_eq!(again, 0, "{name}: the relinked rings cross");
            assert_valid(&relinked, name);
            assert!(
                (relinked_area - area).abs() < 1e-12,
                "{name}: {relinked_area} against {area}"
            );
            assert!(
                relinked.iter().all(|r| r.len() >= 3),
                "{name}: {relinked:?}"
            );
        }
    }

    #[test]
    fn a_pentagram_becomes_five_points_round_a_pentagon() {
        let star = super::super::tests::pentagram();
        let (relinked, added) = relinked(core::slice::from_ref(&star)).expect("relinked");
        assert_eq!(added.len(), 5);
        let mut sizes: Vec<usize> = relinked.iter().map(Vec::len).collect();
        sizes.sort_unstable();
        // each edge crossed twice: the centre, a pentagon of crossings alone, and the
        // star's outline round it, touching it at every crossing
        assert_eq!(sizes, [5, 10]);
        let (area, _) = even_odd(&[star]);
        let (relinked_area, again) = even_odd(&relinked);
        assert_eq!(again, 0);
        assert_valid(&relinked, "pentagram");
        // (rounded crossings: the regions differ within a pixel of each)
        assert!(
            (relinked_area - area).abs() < 1e-9 * area.abs(),
            "{relinked_area} {area}"
        );
    }

    #[test]
    fn declines_where_nothing_crosses_properly() {
        // apart; touching at a corner; overlapping along an edge
        let apart = [square(0.0, 0.0, 1.0), square(2.0, 0.0, 1.0)];
        let corner = [square(0.0, 0.0, 1.0), square(1.0, 1.0, 1.0)];
        let along = [square(0.0, 0.0, 2.0), square(2.0, 0.0, 2.0)];
        for rings in [&apart[..], &corner, &along, &[]] {
            assert!(relinked(rings).is_none(), "{rings:?}");
        }
    }
}
