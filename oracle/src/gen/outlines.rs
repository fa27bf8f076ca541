//! Single outlines with structure: orthogonal trees of cells, combs, spirals and slivers
//! (the last also as holes).

use super::geom::{FastMap, FastSet, Pt, Ring};
use super::rng::Rng;
use super::{Shape, GRID};

/// The eight neighbours of a cell, counter-clockwise from east: even indices share an
/// edge with it, odd ones a corner.
const AROUND: [(i32, i32); 8] = [
    (1, 0),
    (1, 1),
    (0, 1),
    (-1, 1),
    (-1, 0),
    (-1, -1),
    (0, -1),
    (1, -1),
];

/// Adding `cell` keeps the set's boundary one simple closed curve: the set's cells around
/// it form one contiguous arc that contains an edge neighbour, and no corner neighbour
/// touches it only diagonally (a pinch).
fn is_simple_addition(set: &FastSet<(i32, i32)>, cell: (i32, i32)) -> bool {
    let inside: Vec<bool> = AROUND
        .iter()
        .map(|&(dx, dy)| set.contains(&(cell.0 + dx, cell.1 + dy)))
        .collect();
    let has_edge_neighbour = (0..8).step_by(2).any(|k| inside[k]);
    let pinch = (1..8)
        .step_by(2)
        .any(|k| inside[k] && !inside[k - 1] && !inside[(k + 1) % 8]);
    let arcs = (0..8)
        .filter(|&k| inside[k] && !inside[(k + 1) % 8])
        .count();
    has_edge_neighbour && !pinch && arcs == 1
}

/// An orthogonal ring around a random tree-like set of grid cells, with every grid point
/// of its boundary kept (long collinear runs), some of them dropped and some repeated.
pub(super) fn orthogonal(rng: &mut Rng, n: usize) -> Shape {
    let cells = grow_cells(rng, n);
    let boundary = trace(&cells);
    let extent = boundary
        .iter()
        .flat_map(|p| [p[0], p[1]])
        .fold((i64::MAX, i64::MIN), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let span = (extent.1 - extent.0).max(1);
    let unit = (GRID / span).max(1);
    let (mut ring, mut repeated, mut dropped) = (Ring::new(), 0, 0);
    let m = boundary.len();
    for (i, &p) in boundary.iter().enumerate() {
        let (prev, next) = (boundary[(i + m - 1) % m], boundary[(i + 1) % m]);
        let straight = (prev[0] == p[0] && p[0] == next[0]) || (prev[1] == p[1] && p[1] == next[1]);
        // Dropping a straight vertex leaves the ring's shape unchanged.
        if straight && rng.chance(0.25) {
            dropped += 1;
            continue;
        }
        let q = [(p[0] - extent.0) * unit, (p[1] - extent.0) * unit];
        ring.push(q);
        if rng.chance(0.05) {
            ring.push(q);
            repeated += 1;
        }
    }
    Shape {
        description: format!(
            "{} cells, {} boundary grid points, {dropped} straight ones dropped, {repeated} repeated",
            cells.len(),
            m
        ),
        rings: vec![ring],
    }
}

/// Grows a set of cells from one whose boundary has about `n` unit edges, preferring cells
/// with a single edge neighbour (thin branches: the perimeter grows by two per cell).
fn grow_cells(rng: &mut Rng, n: usize) -> FastSet<(i32, i32)> {
    let mut set = FastSet::from_iter([(0, 0)]);
    let mut candidates: Vec<(i32, i32)> = vec![(1, 0), (0, 1), (-1, 0), (0, -1)];
    let mut perimeter = 4usize;
    let mut tries = 0usize;
    while perimeter < n && !candidates.is_empty() && tries < 40 * n + 100 {
        tries += 1;
        let cell = candidates.swap_remove(rng.below(candidates.len()));
        if set.contains(&cell) || !is_simple_addition(&set, cell) {
            continue;
        }
        let edge_neighbours = (0..8)
            .step_by(2)
            .filter(|&k| set.contains(&(cell.0 + AROUND[k].0, cell.1 + AROUND[k].1)))
            .count();
        if edge_neighbours > 1 && rng.chance(0.85) {
            // Keep it for later: it may become acceptable, and branches stay thin.
            candidates.push(cell);
            continue;
        }
        set.insert(cell);
        perimeter = perimeter + 4 - 2 * edge_neighbours;
        for k in (0..8).step_by(2) {
            let next = (cell.0 + AROUND[k].0, cell.1 + AROUND[k].1);
            if !set.contains(&next) {
                candidates.push(next);
            }
        }
    }
    set
}

/// The boundary of a simply connected, pinch-free set of cells, counter-clockwise, one
/// vertex per unit of length.
fn trace(set: &FastSet<(i32, i32)>) -> Ring {
    let mut next: FastMap<Pt, Pt> = FastMap::default();
    for &(x, y) in set {
        let (x, y) = (i64::from(x), i64::from(y));
        let out = |dx: i64, dy: i64| !set.contains(&((x + dx) as i32, (y + dy) as i32));
        // Interior on the left of every directed edge.
        if out(0, -1) {
            next.insert([x, y], [x + 1, y]);
        }
        if out(1, 0) {
            next.insert([x + 1, y], [x + 1, y + 1]);
        }
        if out(0, 1) {
            next.insert([x + 1, y + 1], [x, y + 1]);
        }
        if out(-1, 0) {
            next.insert([x, y + 1], [x, y]);
        }
    }
    let Some((&start, _)) = next.iter().min() else {
        return super::geom::square_around([1, 1], 1);
    };
    let mut ring = vec![start];
    let mut p = start;
    while let Some(&q) = next.get(&p) {
        if q == start || ring.len() > next.len() {
            break;
        }
        ring.push(q);
        p = q;
    }
    ring
}

/// A comb: a bar along the bottom and about `n / 5` teeth of random height, some with a
/// pointed tip, separated by narrow gaps.
pub(super) fn comb(rng: &mut Rng, n: usize) -> Shape {
    let teeth = (n.saturating_sub(4) / 5).max(1) as i64;
    let slot = GRID / teeth;
    let bar = rng.int(1, GRID / 8);
    let mut ring: Ring = vec![[0, 0], [GRID, 0], [GRID, bar]];
    let mut tips = 0;
    for k in (0..teeth).rev() {
        // Gaps of at least one unit keep neighbouring teeth apart.
        let left = k * slot + rng.int(1, (slot / 3).max(1));
        let right = (k + 1) * slot - rng.int(1, (slot / 3).max(1));
        let top = rng.int(bar + 2, GRID - 2);
        ring.push([right, bar]);
        ring.push([right, top]);
        if right - left >= 2 && rng.chance(0.5) {
            ring.push([rng.int(left + 1, right - 1), rng.int(top + 1, GRID)]);
            tips += 1;
        }
        ring.push([left, top]);
        ring.push([left, bar]);
    }
    ring.push([0, bar]);
    Shape {
        description: format!("{teeth} teeth ({tips} pointed), bar height {bar}"),
        rings: vec![ring],
    }
}

/// A band between two Archimedean spirals, flattened with about `n / 2` points per side.
pub(super) fn spiral(rng: &mut Rng, n: usize) -> Shape {
    let per_side = (n / 2).max(2) as f64;
    // As many turns as keep each chord's sag well inside the gap between turns: the sag at
    // radius r with k points per turn is about r (π/k)² / 2.
    let mut turns: f64 = 0.25;
    while turns < 60.0 {
        let t = turns + 0.25;
        let k = per_side / t;
        if k < std::f64::consts::PI * ((t + 1.5) / 0.15).sqrt() + 2.0 {
            break;
        }
        turns = t;
    }
    let pitch = (GRID / 2 - 4) as f64 / (turns + 1.5);
    let width = pitch * rng.float(0.3, 0.7);
    let start = pitch * 0.5;
    let phase = rng.float(0.0, std::f64::consts::TAU);
    let mirror = if rng.chance(0.5) { -1.0 } else { 1.0 };
    let steps = per_side as usize - 1;
    let at = |i: usize, extra: f64| {
        let theta = std::f64::consts::TAU * turns * i as f64 / steps as f64;
        let r = start + pitch * theta / std::f64::consts::TAU + extra;
        let angle = phase + mirror * theta;
        [
            GRID / 2 + (r * angle.cos()).round() as i64,
            GRID / 2 + (r * angle.sin()).round() as i64,
        ]
    };
    let mut ring: Ring = (0..=steps).map(|i| at(i, 0.0)).collect();
    ring.extend((0..=steps).rev().map(|i| at(i, width)));
    Shape {
        description: format!("{turns} turns, pitch {pitch:.0}, band width {width:.0}"),
        rings: vec![ring],
    }
}

/// Needle-thin bands: one alone (horizontal, diagonal or vertical), or several as holes in
/// a square.
pub(super) fn slivers(rng: &mut Rng, n: usize) -> Shape {
    if n < 12 || rng.chance(0.5) {
        let thickness = [1, 2, 5][rng.below(3)];
        let mut band = needle(rng, n, [0, GRID / 2], 0, thickness);
        let how = match rng.below(3) {
            0 => "horizontal",
            1 => {
                // y + x is an exact shear: orientations, so validity, are unchanged.
                for p in &mut band {
                    p[1] += p[0];
                }
                "diagonal"
            }
            _ => {
                for p in &mut band {
                    p.swap(0, 1);
                }
                "vertical"
            }
        };
        return Shape {
            description: format!("one {how} needle {thickness} units thick"),
            rings: vec![band],
        };
    }
    let holes = rng.int(1, 8.min((n as i64 - 4) / 4).max(1)) as usize;
    let strip = GRID / holes as i64;
    let mut rings = vec![super::geom::square_around([GRID / 2, GRID / 2], GRID / 2)];
    for h in 0..holes {
        let thickness = rng.int(1, 4);
        let y = h as i64 * strip + rng.int(1, (strip - 2 * thickness - 2).max(1));
        rings.push(needle(rng, (n - 4) / holes, [1, GRID - 1], y, thickness));
    }
    Shape {
        description: format!("{holes} needle holes in a square"),
        rings,
    }
}

/// An x-monotone band over `x_range` with about `n` vertices: a bottom chain with y in
/// `y0 ..= y0 + t` and a top chain with y in `y0 + t + 1 ..= y0 + 2t + 1`. Every top
/// vertex is above every bottom vertex, so the band is simple; each chain is nearly
/// collinear.
fn needle(rng: &mut Rng, n: usize, x_range: [i64; 2], y0: i64, t: i64) -> Ring {
    let per_chain = (n.max(4) / 2).min((x_range[1] - x_range[0]) as usize / 2);
    let xs = |rng: &mut Rng| {
        let mut xs: Vec<i64> = (0..per_chain.saturating_sub(2))
            .map(|_| rng.int(x_range[0] + 1, x_range[1] - 1))
            .collect();
        xs.push(x_range[0]);
        xs.push(x_range[1]);
        xs.sort_unstable();
        xs.dedup();
        xs
    };
    let bottom: Ring = xs(rng)
        .into_iter()
        .map(|x| [x, y0 + rng.int(0, t)])
        .collect();
    let top: Ring = xs(rng)
        .into_iter()
        .rev()
        .map(|x| [x, y0 + t + 1 + rng.int(0, t)])
        .collect();
    bottom.into_iter().chain(top).collect()
}
