//! Single random rings through random points: star-shaped, and Auer & Held's
//! space-partitioning and 2-opt heuristics (*Heuristics for the generation of random
//! polygons*, CCCG 1996).

use super::geom::{
    cross_properly, orient, polar_ring, star_order, to_f64, Cells, FastSet, Pt, Ring,
};
use super::rng::Rng;
use super::{validate, Shape, GRID};
use crate::input::{Input, Nesting};

/// The grid's centre.
const CENTRE: Pt = [GRID / 2, GRID / 2];

/// A star-shaped ring: `n` angles around the centre, random radii.
pub(super) fn star(rng: &mut Rng, n: usize) -> Shape {
    let r_max = (GRID / 2 - 2) as f64;
    // Sometimes spiky (radii anywhere down to 5 %), sometimes nearly round.
    let r_min = r_max * rng.float(0.05, 0.9);
    // Jitter below 0.5 keeps every angular gap below π even for three vertices.
    let ring = polar_ring(rng, CENTRE, n, 0.45, |rng, angle| {
        let r = rng.float(r_min, r_max);
        [r * angle.cos(), r * angle.sin()]
    });
    Shape {
        description: format!("{} vertices, radii {:.0}..{:.0}", ring.len(), r_min, r_max),
        rings: vec![ring],
    }
}

/// `n` distinct random grid points.
fn random_points(rng: &mut Rng, n: usize) -> Vec<Pt> {
    let mut seen = FastSet::with_capacity_and_hasher(n, Default::default());
    let mut points = Vec::with_capacity(n);
    while points.len() < n {
        let p = [rng.int(0, GRID), rng.int(0, GRID)];
        if seen.insert(p) {
            points.push(p);
        }
    }
    points
}

/// A ring through (most of) `n` random points by space partitioning.
pub(super) fn space_partition(rng: &mut Rng, n: usize) -> Shape {
    let points = random_points(rng, n.max(3));
    let ring = space_partition_ring(rng, &points);
    let ring = if ring.len() >= 3 {
        ring
    } else {
        star_order(CENTRE, &points).unwrap_or_else(|| super::geom::square_around(CENTRE, GRID / 4))
    };
    Shape {
        description: format!("{} of {} random points", ring.len(), points.len()),
        rings: vec![ring],
    }
}

/// The space-partitioning heuristic: the line through two random points `a b` splits the
/// rest; each side becomes a chain from `a` to `b` by recursive splitting with a random
/// line through a random point `c` of the side that separates the chain's ends. Chains of
/// different sub-problems lie in disjoint convex regions and meet only at shared ends, so
/// the ring is simple. Points exactly on a splitting line are dropped.
fn space_partition_ring(rng: &mut Rng, points: &[Pt]) -> Ring {
    let (a, b) = (points[0], points[1]);
    let (mut left, mut right) = (Vec::new(), Vec::new());
    for &p in &points[2..] {
        match orient(a, b, p).signum() {
            1 => left.push(p),
            -1 => right.push(p),
            _ => {}
        }
    }
    if left.is_empty() && right.is_empty() {
        return Vec::new();
    }
    let mut ring = vec![a];
    chain(rng, a, b, right, &mut ring);
    ring.push(b);
    chain(rng, b, a, left, &mut ring);
    ring
}

/// Appends a chain from `a` to `b` (both excluded) through `points`, which lie strictly on
/// one side of `a b`. An explicit stack: the recursion can be as deep as the point count.
fn chain(rng: &mut Rng, a: Pt, b: Pt, points: Vec<Pt>, out: &mut Ring) {
    enum Task {
        Solve(Pt, Pt, Vec<Pt>),
        Emit(Pt),
    }
    let mut stack = vec![Task::Solve(a, b, points)];
    while let Some(task) = stack.pop() {
        let (a, b, mut points) = match task {
            Task::Emit(p) => {
                out.push(p);
                continue;
            }
            Task::Solve(a, b, points) if points.is_empty() => {
                let _ = (a, b);
                continue;
            }
            Task::Solve(a, b, points) => (a, b, points),
        };
        let c = points.swap_remove(rng.below(points.len()));
        let (near_a, near_b) = split(rng, a, b, c, points);
        // Last pushed runs first: a..c, then c, then c..b.
        stack.push(Task::Solve(c, b, near_b));
        stack.push(Task::Emit(c));
        stack.push(Task::Solve(a, c, near_a));
    }
}

/// Splits `points` by a random line through `c` that crosses the segment `a b` at an
/// interior point: those on `a`'s side and those on `b`'s side (exactly on it: dropped).
fn split(rng: &mut Rng, a: Pt, b: Pt, c: Pt, points: Vec<Pt>) -> (Vec<Pt>, Vec<Pt>) {
    // The line through c·K and a·(K−k) + b·k, in coordinates scaled by K so the point on
    // `a b` is a grid point; a and b are on opposite sides since c is off the line `a b`.
    const K: i64 = 1 << 10;
    let scale = |p: Pt| [p[0] * K, p[1] * K];
    let mut best = (Vec::new(), Vec::new());
    for attempt in 0..4 {
        let k = rng.int(1, K - 1);
        let m = [a[0] * (K - k) + b[0] * k, a[1] * (K - k) + b[1] * k];
        let side_a = orient(scale(c), m, scale(a)).signum();
        let (mut near_a, mut near_b) = (Vec::new(), Vec::new());
        let mut on_line = false;
        for &p in &points {
            let s = orient(scale(c), m, scale(p)).signum();
            if s == 0 {
                on_line = true;
            } else if s == side_a {
                near_a.push(p);
            } else {
                near_b.push(p);
            }
        }
        best = (near_a, near_b);
        if !on_line || attempt == 3 {
            break;
        }
    }
    best
}

/// A ring through `n` random points by 2-opt moves from a Hilbert-curve tour: while two
/// edges cross, replace them by the two that do not (reversing the path between). Every
/// move shortens the tour, so it ends; a uniform grid finds crossing pairs.
pub(super) fn two_opt(rng: &mut Rng, n: usize) -> Shape {
    let mut points = random_points(rng, n.max(3));
    points.sort_by_key(|&p| hilbert(p));
    let (ring, moves) = untangle(points.clone());
    // Touching without crossing (a point exactly on another edge, collinear edges) is not
    // removed by 2-opt moves; it is vanishingly rare on this grid. Fall back to a star.
    let as_input = Input::from_rings(&[ring.iter().map(|&p| to_f64(p)).collect()], Nesting::Auto);
    let (ring, how) = match validate(&as_input, false) {
        Ok(_) => (ring, format!("{moves} 2-opt moves")),
        Err(_) => {
            let star = star_order(CENTRE, &points)
                .unwrap_or_else(|| super::geom::square_around(CENTRE, GRID / 4));
            (star, "2-opt left a touch: star order instead".to_string())
        }
    };
    Shape {
        description: format!("{} random points, {how}", ring.len()),
        rings: vec![ring],
    }
}

/// The position of `p` along a Hilbert curve over the grid: a tour in this order has few
/// crossings, all local.
fn hilbert(p: Pt) -> u64 {
    let (mut x, mut y) = (
        p[0].clamp(0, GRID - 1) as u64,
        p[1].clamp(0, GRID - 1) as u64,
    );
    let mut d = 0u64;
    let mut s = (GRID as u64) / 2;
    while s > 0 {
        let rx = u64::from(x & s > 0);
        let ry = u64::from(y & s > 0);
        d += s * s * ((3 * rx) ^ ry);
        if ry == 0 {
            if rx == 1 {
                x = s - 1 - (x & (s - 1));
                y = s - 1 - (y & (s - 1));
            }
            std::mem::swap(&mut x, &mut y);
        }
        x &= s - 1;
        y &= s - 1;
        s /= 2;
    }
    d
}

/// Removes every proper crossing from the tour `points` by 2-opt moves; returns the tour
/// and the number of moves.
fn untangle(mut tour: Vec<Pt>) -> (Ring, usize) {
    let n = tour.len();
    let mut pos: Vec<usize> = (0..n).collect(); // point id → tour position
    let mut at: Vec<usize> = (0..n).collect(); // tour position → point id
    let pts = tour.clone();
    let cells = Cells::new([0.0, 0.0, GRID as f64, GRID as f64], n);
    let mut buckets: Vec<Vec<(u32, u32)>> = vec![Vec::new(); cells.len()];
    let key = |u: usize, v: usize| (u.min(v) as u32, u.max(v) as u32);
    let mut alive: FastSet<(u32, u32)> =
        FastSet::with_capacity_and_hasher(2 * n, Default::default());
    let mut queue: Vec<(u32, u32)> = Vec::with_capacity(n);
    let insert = |e: (u32, u32), buckets: &mut Vec<Vec<(u32, u32)>>, alive: &mut FastSet<_>| {
        alive.insert(e);
        cells.along(to_f64(pts[e.0 as usize]), to_f64(pts[e.1 as usize]), |c| {
            buckets[c].push(e)
        });
    };
    for i in 0..n {
        let e = key(i, (i + 1) % n);
        insert(e, &mut buckets, &mut alive);
        queue.push(e);
    }
    let mut moves = 0;
    // Each move shortens the tour, so this ends; the budget only guards against the
    // unforeseen.
    let budget = 50 * n + 1000;
    while let Some(e) = queue.pop() {
        if !alive.contains(&e) || moves >= budget {
            continue;
        }
        let (p, q) = (pts[e.0 as usize], pts[e.1 as usize]);
        let mut found = None;
        cells.along(to_f64(p), to_f64(q), |c| {
            if found.is_some() {
                return;
            }
            for &f in &buckets[c] {
                let shares = f.0 == e.0 || f.0 == e.1 || f.1 == e.0 || f.1 == e.1;
                if !shares
                    && alive.contains(&f)
                    && cross_properly(p, q, pts[f.0 as usize], pts[f.1 as usize])
                {
                    found = Some(f);
                    return;
                }
            }
        });
        let Some(f) = found else { continue };
        // Orient both edges along the tour: i → i+1 and j → j+1.
        let first = |e: (u32, u32)| {
            let (u, v) = (e.0 as usize, e.1 as usize);
            if pos[v] == (pos[u] + 1) % n {
                pos[u]
            } else {
                pos[v]
            }
        };
        let (i, j) = (first(e), first(f));
        let (a, b) = (at[i], at[(i + 1) % n]);
        let (c, d) = (at[j], at[(j + 1) % n]);
        // Reversing the path b..c (or, equally, d..a) turns a b + c d into a c + b d.
        let len_bc = (j + n - i) % n;
        let (start, len) = if len_bc <= n - len_bc {
            ((i + 1) % n, len_bc)
        } else {
            ((j + 1) % n, n - len_bc)
        };
        for k in 0..len / 2 {
            let (x, y) = ((start + k) % n, (start + len - 1 - k) % n);
            at.swap(x, y);
            pos[at[x]] = x;
            pos[at[y]] = y;
        }
        alive.remove(&e);
        alive.remove(&f);
        for g in [key(a, c), key(b, d)] {
            insert(g, &mut buckets, &mut alive);
            queue.push(g);
        }
        moves += 1;
    }
    tour.clear();
    tour.extend(at.iter().map(|&id| pts[id]));
    (tour, moves)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hilbert_order_is_a_bijection_on_a_small_square() {
        let mut seen = FastSet::default();
        for x in 0..4 {
            for y in 0..4 {
                seen.insert(hilbert([x, y]));
            }
        }
        assert_eq!(seen.len(), 16);
    }
}
