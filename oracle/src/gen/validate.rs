//! The generators' exact validity check: every ring simple, rings pairwise non-crossing,
//! and every ring's containment depth.
//!
//! Independent of `polytri` and of the triangulation checks: it judges inputs, not results.
//! Exact for finite coordinates (orientation signs by `robust::orient2d`, everything else
//! comparisons); near-linear time through a uniform grid of cells.

use super::geom::{bbox, Cells, FastMap};
use crate::input::{Input, Nesting, Role};

/// What a valid input looks like: the containment depth of every ring.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Layout {
    /// For each ring, how many other rings contain it: even for an outer boundary (an
    /// island is a polygon of its own), odd for a hole.
    pub depths: Vec<u32>,
}

impl Layout {
    /// The deepest nesting: 0 for polygons without holes, 1 with holes, 2 with islands in
    /// holes, and so on.
    pub fn max_depth(&self) -> u32 {
        self.depths.iter().copied().max().unwrap_or(0)
    }
}

type P = [f64; 2];

/// The sign of the orientation of `a b c`: 1 counter-clockwise, −1 clockwise, 0 collinear.
fn orient(a: P, b: P, c: P) -> i8 {
    let det = robust::orient2d(
        robust::Coord { x: a[0], y: a[1] },
        robust::Coord { x: b[0], y: b[1] },
        robust::Coord { x: c[0], y: c[1] },
    );
    if det > 0.0 {
        1
    } else if det < 0.0 {
        -1
    } else {
        0
    }
}

/// `p` lies on the closed segment `a b`, given that `a b p` are collinear.
fn within(a: P, b: P, p: P) -> bool {
    a[0].min(b[0]) <= p[0]
        && p[0] <= a[0].max(b[0])
        && a[1].min(b[1]) <= p[1]
        && p[1] <= a[1].max(b[1])
}

/// One edge of a cleaned ring.
#[derive(Clone, Copy)]
struct Seg {
    ring: usize,
    edge: usize,
    a: P,
    b: P,
}

/// Checks that `input` is valid: finite coordinates, well-formed ring starts, every ring
/// simple (at least three distinct points; repeated consecutive points are ignored,
/// collinear consecutive points allowed), no two rings crossing or overlapping, and the
/// nesting convention consistent with containment.
///
/// With `allow_touching`, rings of different rings may share vertex positions (never a
/// vertex on another ring's edge interior) as long as they do not cross there.
///
/// # Errors
///
/// A sentence saying which rule fails and where (ring and edge indices count from 0, in the
/// ring with repeated points removed).
pub fn validate(input: &Input, allow_touching: bool) -> Result<Layout, String> {
    let rings = cleaned_rings(input)?;
    let segs: Vec<Seg> = rings
        .iter()
        .enumerate()
        .flat_map(|(r, ring)| {
            let n = ring.len();
            (0..n).map(move |i| Seg {
                ring: r,
                edge: i,
                a: ring[i],
                b: ring[(i + 1) % n],
            })
        })
        .collect();
    check_pairs(&rings, &segs, allow_touching)?;
    let shared = shared_positions(&rings);
    if allow_touching {
        check_wedges(&rings, &shared)?;
    }
    let depths = depths(&rings, &segs, &shared)?;
    check_nesting(&input.nesting, &depths)?;
    Ok(Layout { depths })
}

/// The rings with repeated consecutive points removed, after the structural checks.
fn cleaned_rings(input: &Input) -> Result<Vec<Vec<P>>, String> {
    let starts = &input.ring_starts;
    if starts.first().is_some_and(|&s| s != 0) || starts.windows(2).any(|w| w[0] >= w[1]) {
        return Err("ring starts must begin at 0 and increase strictly".into());
    }
    if starts.last().is_some_and(|&s| s >= input.vertices.len()) {
        return Err("the last ring is empty".into());
    }
    if let Some(v) = input
        .vertices
        .iter()
        .position(|p| !p.iter().all(|c| c.is_finite()))
    {
        return Err(format!("vertex {v} is not finite"));
    }
    let mut rings = Vec::with_capacity(starts.len());
    for r in 0..input.ring_count() {
        let mut ring: Vec<P> = Vec::new();
        for &p in &input.vertices[input.ring_range(r)] {
            if ring.last() != Some(&p) {
                ring.push(p);
            }
        }
        while ring.len() > 1 && ring.first() == ring.last() {
            ring.pop();
        }
        if ring.len() < 3 {
            return Err(format!("ring {r} has fewer than three distinct points"));
        }
        rings.push(ring);
    }
    if rings.is_empty() {
        return Err("no rings".into());
    }
    Ok(rings)
}

/// Every pair of edges near each other, tested exactly.
fn check_pairs(rings: &[Vec<P>], segs: &[Seg], allow_touching: bool) -> Result<(), String> {
    let cells = Cells::new(bbox(segs.iter().map(|s| s.a)), 4 * segs.len());
    let mut buckets: Vec<Vec<u32>> = vec![Vec::new(); cells.len()];
    for (i, s) in segs.iter().enumerate() {
        cells.along(s.a, s.b, |c| buckets[c].push(i as u32));
    }
    let xmin = |i: u32| segs[i as usize].a[0].min(segs[i as usize].b[0]);
    let xmax = |i: u32| segs[i as usize].a[0].max(segs[i as usize].b[0]);
    let (ymin, ymax) = (|s: &Seg| s.a[1].min(s.b[1]), |s: &Seg| s.a[1].max(s.b[1]));
    for bucket in &mut buckets {
        // Sorted by left end, each edge meets only the following ones that start before
        // it ends: combs and stripes have many edges per cell but few overlapping boxes.
        bucket.sort_unstable_by(|&i, &j| xmin(i).total_cmp(&xmin(j)));
        for (k, &i) in bucket.iter().enumerate() {
            let s = segs[i as usize];
            for &j in &bucket[k + 1..] {
                if xmin(j) > xmax(i) {
                    break;
                }
                let t = segs[j as usize];
                if ymin(&t) > ymax(&s) || ymin(&s) > ymax(&t) {
                    continue;
                }
                check_pair(rings, s, t, allow_touching)?;
            }
        }
    }
    Ok(())
}

fn describe(s: Seg) -> String {
    format!("ring {} edge {} ({:?} → {:?})", s.ring, s.edge, s.a, s.b)
}

/// Edges `s` and `t` meet only as the rules allow.
fn check_pair(rings: &[Vec<P>], s: Seg, t: Seg, allow_touching: bool) -> Result<(), String> {
    if s.ring == t.ring {
        let n = rings[s.ring].len();
        if (s.edge + 1) % n == t.edge {
            return check_adjacent(s.b, s.a, t.b).map_err(|e| format!("{e} at {}", describe(s)));
        }
        if (t.edge + 1) % n == s.edge {
            return check_adjacent(t.b, t.a, s.b).map_err(|e| format!("{e} at {}", describe(t)));
        }
    }
    let (o1, o2) = (orient(s.a, s.b, t.a), orient(s.a, s.b, t.b));
    let (o3, o4) = (orient(t.a, t.b, s.a), orient(t.a, t.b, s.b));
    let fail = |what: &str| Err(format!("{} {what} {}", describe(s), describe(t)));
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return fail("crosses");
    }
    let s_on_t = |p: P, o: i8| o == 0 && within(t.a, t.b, p);
    let t_on_s = |p: P, o: i8| o == 0 && within(s.a, s.b, p);
    let touches = [
        (t.a, t_on_s(t.a, o1)),
        (t.b, t_on_s(t.b, o2)),
        (s.a, s_on_t(s.a, o3)),
        (s.b, s_on_t(s.b, o4)),
    ];
    if !touches.iter().any(|&(_, on)| on) {
        return Ok(());
    }
    if s.ring == t.ring {
        return fail("touches (ring not simple):");
    }
    if o1 == 0 && o2 == 0 {
        // Collinear: at most one shared end, the edges leaving it in opposite directions.
        let shared = [s.a, s.b]
            .iter()
            .filter(|p| **p == t.a || **p == t.b)
            .count();
        let interior = touches
            .iter()
            .any(|&(p, on)| on && p != t.a && p != t.b || on && p != s.a && p != s.b);
        if shared != 1 || interior || !allow_touching {
            return fail("overlaps");
        }
        return Ok(());
    }
    // Not collinear: they meet at exactly one point, which must be a vertex of both.
    let at_vertex_of_both = touches
        .iter()
        .filter(|&&(_, on)| on)
        .all(|&(p, _)| (p == s.a || p == s.b) && (p == t.a || p == t.b));
    if !at_vertex_of_both {
        return fail("has a vertex on the interior of");
    }
    if !allow_touching {
        return fail("touches");
    }
    Ok(())
}

/// Consecutive edges `v → a` and `v → b` at vertex `v` must not fold back onto each other.
fn check_adjacent(v: P, a: P, b: P) -> Result<(), String> {
    if orient(v, a, b) != 0 {
        return Ok(());
    }
    let same_side = |k: usize| (a[k] - v[k]).signum() == (b[k] - v[k]).signum() && a[k] != v[k];
    if same_side(0) || same_side(1) {
        Err("a spike (consecutive edges overlap)".into())
    } else {
        Ok(())
    }
}

/// Vertex positions that more than one ring uses: for each, `(ring, vertex)` pairs.
fn shared_positions(rings: &[Vec<P>]) -> FastMap<[u64; 2], Vec<(usize, usize)>> {
    let key = |p: P| [p[0].to_bits(), p[1].to_bits()];
    let mut all: FastMap<[u64; 2], Vec<(usize, usize)>> = FastMap::default();
    for (r, ring) in rings.iter().enumerate() {
        for (i, &p) in ring.iter().enumerate() {
            // -0.0 and 0.0 are one position.
            let p = [p[0] + 0.0, p[1] + 0.0];
            all.entry(key(p)).or_default().push((r, i));
        }
    }
    all.retain(|_, users| users.iter().any(|u| u.0 != users[0].0));
    all
}

/// `q` lies strictly inside the counter-clockwise sweep from ray `v→r1` to ray `v→r2`.
fn in_sweep(v: P, r1: P, r2: P, q: P) -> bool {
    let turn = orient(v, r1, r2);
    let after_r1 = orient(v, r1, q) > 0;
    let before_r2 = orient(v, q, r2) > 0;
    if turn > 0 {
        after_r1 && before_r2
    } else if turn < 0 {
        after_r1 || before_r2
    } else {
        // A straight angle (r1 and r2 opposite; equal directions are overlaps, refused
        // earlier): the left half-plane of v→r1.
        after_r1
    }
}

/// Rings sharing a position must not cross there: the two edges of one lie on the same
/// side of the other's two edges.
fn check_wedges(
    rings: &[Vec<P>],
    shared: &FastMap<[u64; 2], Vec<(usize, usize)>>,
) -> Result<(), String> {
    let around = |(r, i): (usize, usize)| {
        let n = rings[r].len();
        (
            rings[r][(i + n - 1) % n],
            rings[r][i],
            rings[r][(i + 1) % n],
        )
    };
    for users in shared.values() {
        for (k, &u) in users.iter().enumerate() {
            for &w in &users[k + 1..] {
                let (p, v, q) = around(u);
                let (a, _, b) = around(w);
                if in_sweep(v, p, q, a) != in_sweep(v, p, q, b) {
                    return Err(format!("rings {} and {} cross at {v:?}", u.0, w.0));
                }
            }
        }
    }
    Ok(())
}

/// Every ring's containment depth, by counting crossings of a ray to +x from one of its
/// vertices that no other ring touches.
fn depths(
    rings: &[Vec<P>],
    segs: &[Seg],
    shared: &FastMap<[u64; 2], Vec<(usize, usize)>>,
) -> Result<Vec<u32>, String> {
    if rings.len() == 1 {
        return Ok(vec![0]);
    }
    let key = |p: P| [(p[0] + 0.0).to_bits(), (p[1] + 0.0).to_bits()];
    let b = bbox(segs.iter().map(|s| s.a));
    let bands = (segs.len() / 4).clamp(1, 1 << 16);
    let height = (b[3] - b[1]).max(f64::MIN_POSITIVE) / bands as f64;
    let band = |y: f64| (((y - b[1]) / height).floor().max(0.0) as usize).min(bands - 1);
    let mut by_band: Vec<Vec<u32>> = vec![Vec::new(); bands];
    for (i, s) in segs.iter().enumerate() {
        let (lo, hi) = (band(s.a[1].min(s.b[1])), band(s.a[1].max(s.b[1])));
        // One band of slack on each side: `band` rounds.
        for list in &mut by_band[lo.saturating_sub(1)..=(hi + 1).min(bands - 1)] {
            list.push(i as u32);
        }
    }
    let mut odd = vec![false; rings.len()];
    let mut depths = Vec::with_capacity(rings.len());
    for (r, ring) in rings.iter().enumerate() {
        let Some(&q) = ring.iter().find(|&&p| !shared.contains_key(&key(p))) else {
            return Err(format!(
                "ring {r} has no vertex of its own to test containment"
            ));
        };
        for &i in &by_band[band(q[1])] {
            let s = segs[i as usize];
            if s.ring == r || (s.a[1] > q[1]) == (s.b[1] > q[1]) {
                continue;
            }
            let side = orient(s.a, s.b, q);
            if (s.b[1] > q[1] && side > 0) || (s.a[1] > q[1] && side < 0) {
                odd[s.ring] = !odd[s.ring];
            }
        }
        depths.push(odd.iter().filter(|&&o| o).count() as u32);
        odd.iter_mut().for_each(|o| *o = false);
    }
    Ok(depths)
}

/// The nesting convention agrees with containment.
fn check_nesting(nesting: &Nesting, depths: &[u32]) -> Result<(), String> {
    match nesting {
        Nesting::Auto => Ok(()),
        Nesting::FirstIsOuter => {
            if depths[0] != 0 {
                return Err("ring 0 is not outermost".into());
            }
            match depths.iter().skip(1).position(|&d| d != 1) {
                Some(r) => Err(format!("ring {} is not a hole of ring 0", r + 1)),
                None => Ok(()),
            }
        }
        Nesting::Roles(roles) => {
            for (r, (&d, role)) in depths.iter().zip(roles).enumerate() {
                if (d % 2 == 0) != (*role == Role::Outer) {
                    return Err(format!("ring {r} is {role:?} but has depth {d}"));
                }
            }
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(rings: &[&[[f64; 2]]]) -> Input {
        let rings: Vec<Vec<P>> = rings.iter().map(|r| r.to_vec()).collect();
        Input::from_rings(&rings, Nesting::Auto)
    }

    const SQUARE: [P; 4] = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]];

    #[test]
    fn a_square_with_a_hole_and_an_island() {
        let hole = [[2.0, 2.0], [8.0, 2.0], [8.0, 8.0], [2.0, 8.0]];
        let island = [[4.0, 4.0], [6.0, 4.0], [5.0, 6.0]];
        let layout = validate(&input(&[&island, &SQUARE, &hole]), false).unwrap();
        assert_eq!(layout.depths, vec![2, 0, 1]);
    }

    #[test]
    fn crossings_touches_and_spikes_are_refused() {
        let bow_tie = [[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
        assert!(validate(&input(&[&bow_tie]), false).is_err());
        let spike = [[0.0, 0.0], [4.0, 0.0], [2.0, 0.0], [2.0, 2.0]];
        assert!(validate(&input(&[&spike]), false).is_err());
        let touching = [[10.0, 10.0], [12.0, 10.0], [12.0, 12.0]];
        assert!(validate(&input(&[&SQUARE, &touching]), false).is_err());
        assert!(validate(&input(&[&SQUARE, &touching]), true).is_ok());
        let t_junction = [[10.0, 5.0], [12.0, 4.0], [12.0, 6.0]];
        assert!(validate(&input(&[&SQUARE, &t_junction]), true).is_err());
        // A hole touching the outer ring from inside at a corner, and one crossing there.
        let inside = [[10.0, 10.0], [5.0, 9.0], [9.0, 5.0]];
        assert!(validate(&input(&[&SQUARE, &inside]), true).is_ok());
        let across = [[10.0, 10.0], [5.0, 9.0], [12.0, 12.0]];
        assert!(validate(&input(&[&SQUARE, &across]), true).is_err());
    }

    #[test]
    fn repeated_and_collinear_points_are_fine() {
        let ring = [
            [0.0, 0.0],
            [0.0, 0.0],
            [5.0, 0.0],
            [10.0, 0.0],
            [10.0, 10.0],
            [0.0, 0.0],
        ];
        assert!(validate(&input(&[&ring]), false).is_ok());
    }
}
