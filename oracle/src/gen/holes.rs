//! Families with several rings: circular holes, many holes, touching holes, nested islands
//! and glyph-like outlines with counters.
//!
//! Rings are kept apart by construction: every hole lives in its own cell of a grid inside
//! a box that the outer ring provably contains (a star-shaped ring contains the disc of its
//! inscribed radius, measured exactly enough with a unit of slack).

use std::f64::consts::{FRAC_1_SQRT_2, PI, TAU};

use super::geom::{inscribed_radius, polar_ring, square_around, star_order, Pt, Ring};
use super::rng::Rng;
use super::{Shape, GRID};

const CENTRE: Pt = [GRID / 2, GRID / 2];

/// A regular-ish polygon with `k` vertices around `c`, radius `r` (a "circle").
fn circle(rng: &mut Rng, c: Pt, k: usize, r: f64) -> Ring {
    polar_ring(rng, c, k, 0.0, |_, a| [r * a.cos(), r * a.sin()])
}

/// A small random star-shaped ring with `k` vertices inside the disc of radius `r`
/// around `c`.
fn blob(rng: &mut Rng, c: Pt, k: usize, r: f64) -> Ring {
    let r_min = r * rng.float(0.3, 0.9);
    polar_ring(rng, c, k, 0.45, |rng, a| {
        let r = rng.float(r_min, r);
        [r * a.cos(), r * a.sin()]
    })
}

/// The centres and half-sides of `count` square cells in a grid filling the square of
/// half-side `h` around `c`, in row order.
fn cells(c: Pt, h: i64, count: usize) -> (Vec<Pt>, i64) {
    let side = (count as f64).sqrt().ceil().max(1.0) as i64;
    let size = (2 * h) / side;
    let centres = (0..count as i64)
        .map(|k| {
            let (col, row) = (k % side, k / side);
            [
                c[0] - h + col * size + size / 2,
                c[1] - h + row * size + size / 2,
            ]
        })
        .collect();
    (centres, size / 2)
}

/// Rings in cells: for each cell centre, a ring drawn within `fill` of the cell's
/// half-side, jittered inside the cell.
fn holes_in_cells(
    rng: &mut Rng,
    centres: &[Pt],
    half: i64,
    mut ring_at: impl FnMut(&mut Rng, Pt, f64) -> Ring,
) -> Vec<Ring> {
    centres
        .iter()
        .map(|&c| {
            // A ring within radius r of a centre jittered by at most half − r − 2 stays
            // strictly inside the cell; cells are disjoint.
            let r = (half as f64 * 0.9 - 2.0).max(1.0);
            let room = rng.float(0.4, 1.0) * r;
            let slack = (half as f64 - room - 2.0).max(0.0) as i64;
            let c = [c[0] + rng.int(-slack, slack), c[1] + rng.int(-slack, slack)];
            ring_at(rng, c, room)
        })
        .collect()
}

/// Circular holes, nearly all reflex, in a rectangle or a rounded rectangle.
pub(super) fn circles(rng: &mut Rng, n: usize) -> Shape {
    if n < 10 {
        let ring = circle(rng, CENTRE, n, (GRID / 2 - 2) as f64);
        return Shape {
            description: format!("one circle of {} vertices", ring.len()),
            rings: vec![ring],
        };
    }
    let rounded = rng.chance(0.5);
    let outer = if rounded {
        rounded_square(rng, (n / 10).clamp(8, 400))
    } else {
        square_around(CENTRE, GRID / 2)
    };
    let per_hole = rng.int(6, 48).min(n as i64 / 3).max(3) as usize;
    let holes = (n.saturating_sub(outer.len()) / per_hole).max(1);
    // The inner 80 % of the square: inside the rounded corners (radius ≤ 10 %).
    let (centres, half) = cells(CENTRE, GRID * 2 / 5, holes);
    let mut rings = vec![outer];
    rings.extend(holes_in_cells(rng, &centres, half, |rng, c, r| {
        circle(rng, c, per_hole, r)
    }));
    Shape {
        description: format!(
            "{holes} circles of {per_hole} vertices in a {}",
            if rounded { "rounded square" } else { "square" }
        ),
        rings,
    }
}

/// The grid's square with corners rounded by quarter circles of radius 10 %, `k` vertices;
/// star-shaped around the centre.
fn rounded_square(rng: &mut Rng, k: usize) -> Ring {
    let per_corner = (k / 4).max(2);
    let rho = (GRID / 10) as f64;
    let lo = rho;
    let hi = GRID as f64 - rho;
    let mut points = Vec::new();
    for (corner, (cx, cy)) in [(hi, lo), (hi, hi), (lo, hi), (lo, lo)]
        .into_iter()
        .enumerate()
    {
        let start = -PI / 2.0 + corner as f64 * PI / 2.0;
        for i in 0..per_corner {
            let a = start + PI / 2.0 * i as f64 / (per_corner - 1) as f64;
            points.push([
                (cx + rho * a.cos()).round() as i64,
                (cy + rho * a.sin()).round() as i64,
            ]);
        }
    }
    let _ = rng;
    star_order(CENTRE, &points).unwrap_or_else(|| square_around(CENTRE, GRID / 2))
}

/// Up to thousands of small star-shaped holes in a jagged star-shaped outer ring.
pub(super) fn many_holes(rng: &mut Rng, n: usize) -> Shape {
    if n < 12 {
        let ring = blob(rng, CENTRE, n, (GRID / 2 - 2) as f64);
        return Shape {
            description: "too small for holes: one ring".into(),
            rings: vec![ring],
        };
    }
    let outer_k = (n / 10).clamp(16, 5000).min(n / 2);
    let r_max = (GRID / 2 - 2) as f64;
    let outer = polar_ring(rng, CENTRE, outer_k, 0.2, |rng, a| {
        let r = rng.float(0.93, 1.0) * r_max;
        [r * a.cos(), r * a.sin()]
    });
    let box_half = (inscribed_radius(CENTRE, &outer) * FRAC_1_SQRT_2 - 2.0) as i64;
    let budget = n - outer.len().min(n);
    let holes = (budget / 4).clamp(1, 8000);
    let per_hole = (budget / holes).max(3);
    let (centres, half) = cells(CENTRE, box_half, holes);
    let mut rings = vec![outer];
    rings.extend(holes_in_cells(rng, &centres, half, |rng, c, r| {
        let k = rng.int(3, 2 * per_hole as i64 - 3).max(3) as usize;
        blob(rng, c, k, r)
    }));
    Shape {
        description: format!("{holes} holes of about {per_hole} vertices"),
        rings,
    }
}

/// Diamonds on a lattice of square cells, each with its corners at the midpoints of its
/// cell's sides: where two neighbouring diamonds both keep that corner they touch there,
/// and a zigzag outer ring touches border diamonds at its reflex vertices. Diamonds lie
/// inside their closed cells, meeting a cell side only at its midpoint, so touching is
/// only ever at single shared vertices with the wedges on opposite sides.
pub(super) fn touching_holes(rng: &mut Rng, n: usize) -> Shape {
    let count = (n / 10).max(1);
    let side = ((count as f64).sqrt().ceil() as i64).max(1);
    // Cell size divisible by 4: integer midpoints and zigzag depth.
    let size = ((GRID - 8) / (side + 1)) / 4 * 4;
    let depth = size / 4;
    let origin = [depth + 2, depth + 2];
    let corner = |col: i64, row: i64| [origin[0] + col * size, origin[1] + row * size];
    // Which corners of each cell's diamond sit exactly at the side midpoint (touching).
    let present: Vec<bool> = (0..side * side).map(|_| rng.chance(0.8)).collect();
    let at = |col: i64, row: i64| {
        (0..side).contains(&col) && (0..side).contains(&row) && present[(row * side + col) as usize]
    };
    // touch[cell][dir]: dir 0 east, 1 north, 2 west, 3 south.
    let mut touch = vec![[false; 4]; (side * side) as usize];
    let (mut shared, mut with_outer) = (0, 0);
    for row in 0..side {
        for col in 0..side {
            if !at(col, row) {
                continue;
            }
            let i = (row * side + col) as usize;
            // East and north neighbours decide the shared corner for both cells.
            if at(col + 1, row) && rng.chance(0.7) {
                touch[i][0] = true;
                touch[i + 1][2] = true;
                shared += 1;
            }
            if at(col, row + 1) && rng.chance(0.7) {
                touch[i][1] = true;
                touch[i + side as usize][3] = true;
                shared += 1;
            }
            let border = [col == side - 1, row == side - 1, col == 0, row == 0];
            for dir in 0..4 {
                if border[dir] && rng.chance(0.5) {
                    touch[i][dir] = true;
                    with_outer += 1;
                }
            }
        }
    }
    let mut rings = vec![zigzag_outer(corner(0, 0), size, side, depth)];
    let extra = (n / count.max(1)).saturating_sub(4).min(40);
    for row in 0..side {
        for col in 0..side {
            if at(col, row) {
                let c = corner(col, row);
                let centre = [c[0] + size / 2, c[1] + size / 2];
                rings.push(diamond(
                    rng,
                    centre,
                    size / 2,
                    touch[(row * side + col) as usize],
                    extra,
                ));
            }
        }
    }
    Shape {
        description: format!(
            "{} diamonds on a {side}×{side} lattice, {shared} touching pairs, {with_outer} touching the outer ring",
            rings.len() - 1
        ),
        rings,
    }
}

/// The outer ring around a `side × side` lattice of cells of `size` from `origin`: a
/// zigzag whose reflex vertices are the midpoints of the border cells' outer sides and
/// whose convex vertices are `depth` outside.
fn zigzag_outer(origin: Pt, size: i64, side: i64, depth: i64) -> Ring {
    let (x0, y0) = (origin[0], origin[1]);
    let (x1, y1) = (x0 + side * size, y0 + side * size);
    let mut ring = vec![[x0 - depth, y0 - depth]];
    for k in 0..side {
        if k > 0 {
            ring.push([x0 + k * size, y0 - depth]);
        }
        ring.push([x0 + k * size + size / 2, y0]);
    }
    ring.push([x1 + depth, y0 - depth]);
    for k in 0..side {
        if k > 0 {
            ring.push([x1 + depth, y0 + k * size]);
        }
        ring.push([x1, y0 + k * size + size / 2]);
    }
    ring.push([x1 + depth, y1 + depth]);
    for k in (0..side).rev() {
        if k < side - 1 {
            ring.push([x0 + (k + 1) * size, y1 + depth]);
        }
        ring.push([x0 + k * size + size / 2, y1]);
    }
    ring.push([x0 - depth, y1 + depth]);
    for k in (0..side).rev() {
        if k < side - 1 {
            ring.push([x0 - depth, y0 + (k + 1) * size]);
        }
        ring.push([x0, y0 + k * size + size / 2]);
    }
    ring
}

/// A diamond around `c` with half-diagonal `h`: corner `dir` at the cell side's midpoint
/// where `touch[dir]`, pulled in otherwise; `extra` points between corners, pulled
/// towards the centre (the ring stays star-shaped and strictly inside the diamond).
fn diamond(rng: &mut Rng, c: Pt, h: i64, touch: [bool; 4], extra: usize) -> Ring {
    let dirs = [[1, 0], [0, 1], [-1, 0], [0, -1]];
    let corners: Vec<[f64; 2]> = (0..4)
        .map(|d| {
            let f = if touch[d] { 1.0 } else { rng.float(0.5, 0.85) };
            [
                dirs[d][0] as f64 * h as f64 * f,
                dirs[d][1] as f64 * h as f64 * f,
            ]
        })
        .collect();
    // Corners first: on equal directions `star_order` keeps them.
    let mut points: Vec<Pt> = corners
        .iter()
        .map(|v| [c[0] + v[0].round() as i64, c[1] + v[1].round() as i64])
        .collect();
    // A ring whose every corner touches needs one vertex of its own (so containment can
    // be decided from a point no other ring has): at least one extra point.
    let extra = if touch.iter().all(|&t| t) {
        extra.max(1)
    } else {
        extra
    };
    for k in 0..extra {
        let d = k % 4;
        let (a, b) = (corners[d], corners[(d + 1) % 4]);
        let t = rng.float(0.1, 0.9);
        let f = rng.float(0.5, 0.9);
        let p = [
            (a[0] + (b[0] - a[0]) * t) * f,
            (a[1] + (b[1] - a[1]) * t) * f,
        ];
        points.push([c[0] + p[0].round() as i64, c[1] + p[1].round() as i64]);
    }
    star_order(c, &points).unwrap_or_else(|| square_around(c, h / 4))
}

/// Islands in holes in islands: each ring star-shaped in its box, its children in a grid
/// of boxes inside the disc it contains. Four to six levels when the size allows, rings
/// shuffled.
pub(super) fn nested_islands(rng: &mut Rng, n: usize) -> Shape {
    // Four levels and more: outer ⊃ hole ⊃ island ⊃ hole at least, when the size allows.
    let levels = match n {
        0..=8 => 1,
        9..=11 => 3,
        _ => rng.int(4, 6).min(n as i64 / 3) as usize,
    };
    // Children per ring at each level, grown while the ring count leaves ≥ 12 vertices
    // per ring.
    let mut fan = vec![1usize; levels - 1];
    let ring_count = |fan: &[usize]| {
        let mut total = 1usize;
        let mut width = 1usize;
        for &f in fan {
            width *= f;
            total += width;
        }
        total
    };
    for _ in 0..64 {
        if fan.is_empty() {
            break;
        }
        let l = rng.below(fan.len());
        fan[l] += 1;
        if fan[l] > 9 || ring_count(&fan) * 12 > n {
            fan[l] -= 1;
        }
    }
    let per_ring = (n / ring_count(&fan)).max(3);
    let mut rings = Vec::new();
    let mut stack = vec![(CENTRE, (GRID / 2 - 2) as f64, 0usize)];
    while let Some((c, r, level)) = stack.pop() {
        let ring = blob_at_least(rng, c, per_ring, r);
        let inner = inscribed_radius(c, &ring) * FRAC_1_SQRT_2 - 2.0;
        rings.push(ring);
        if level + 1 < levels && inner >= 8.0 {
            let (centres, half) = cells(c, inner as i64, fan[level]);
            for child in centres {
                stack.push((child, (half - 1) as f64, level + 1));
            }
        }
    }
    rng.shuffle(&mut rings);
    Shape {
        description: format!("{levels} levels, fan-out {fan:?}, {} rings", rings.len()),
        rings,
    }
}

/// A blob whose radii stay above 70 % of `r`, so that it has room for children.
fn blob_at_least(rng: &mut Rng, c: Pt, k: usize, r: f64) -> Ring {
    let jitter = if k >= 8 { 0.3 } else { 0.0 };
    polar_ring(rng, c, k, jitter, |rng, a| {
        let r = rng.float(0.7, 1.0) * r;
        [r * a.cos(), r * a.sin()]
    })
}

/// A row of glyphs: smooth outlines flattened from cubic Bézier segments in polar
/// coordinates (radius over angle), with one or two counters, or a stem with a dot.
pub(super) fn font_like(rng: &mut Rng, n: usize) -> Shape {
    let glyphs = (n / 300).clamp(1, 12);
    let per_glyph = (n / glyphs).max(3);
    let cell = GRID / glyphs as i64;
    let mut rings = Vec::new();
    let mut kinds = Vec::new();
    for g in 0..glyphs as i64 {
        let c = [g * cell + cell / 2, GRID / 2];
        // Normalised glyph space [-1, 1]² mapped to the cell (a linear map keeps rings
        // apart and star shapes star-shaped).
        let sx = (cell / 2 - 2) as f64 * 0.9;
        let sy = (GRID / 2 - 2) as f64 * 0.9;
        let kind = if per_glyph < 12 { 0 } else { rng.below(4) };
        let map = |p: [f64; 2]| {
            [
                c[0] + (p[0] * sx).round() as i64,
                c[1] + (p[1] * sy).round() as i64,
            ]
        };
        let outline = |rng: &mut Rng, centre: [f64; 2], r: f64, k: usize| {
            let curve = BezierRadius::new(rng, 0.75, 1.0);
            let phase = rng.float(0.0, TAU);
            let points: Vec<Pt> = (0..k.max(3))
                .map(|i| {
                    let a = phase + TAU * i as f64 / k.max(3) as f64;
                    let rho = r * curve.at(a - phase);
                    map([centre[0] + rho * a.cos(), centre[1] + rho * a.sin()])
                })
                .collect();
            star_order(map(centre), &points).unwrap_or_else(|| square_around(map(centre), 1))
        };
        // Counters fit inside the outline's guaranteed disc: radius 0.75 · cos(gap / 2).
        match kind {
            0 => {
                rings.push(outline(rng, [0.0, 0.0], 1.0, per_glyph));
                kinds.push('l');
            }
            1 => {
                rings.push(outline(rng, [0.0, 0.0], 1.0, per_glyph * 2 / 3));
                rings.push(outline(rng, [0.0, 0.0], 0.45, per_glyph / 3));
                kinds.push('o');
            }
            2 => {
                rings.push(outline(rng, [0.0, 0.0], 1.0, per_glyph / 2));
                rings.push(outline(rng, [0.0, 0.33], 0.28, per_glyph / 4));
                rings.push(outline(rng, [0.0, -0.33], 0.28, per_glyph / 4));
                kinds.push('8');
            }
            _ => {
                rings.push(outline(rng, [0.0, -0.3], 0.65, per_glyph * 3 / 4));
                rings.push(outline(rng, [0.0, 0.77], 0.2, per_glyph / 4));
                kinds.push('i');
            }
        }
    }
    Shape {
        description: format!(
            "glyphs {:?}, about {per_glyph} vertices each",
            kinds.iter().collect::<String>()
        ),
        rings,
    }
}

/// A periodic radius function of the angle: cubic Bézier segments between random control
/// radii at evenly spaced angles, with control points that make it smooth (Catmull-Rom
/// tangents), clamped to `[lo, hi]`.
struct BezierRadius {
    knots: Vec<f64>,
    lo: f64,
    hi: f64,
}

impl BezierRadius {
    fn new(rng: &mut Rng, lo: f64, hi: f64) -> BezierRadius {
        let count = rng.int(4, 9) as usize;
        BezierRadius {
            knots: (0..count).map(|_| rng.float(lo, hi)).collect(),
            lo,
            hi,
        }
    }

    /// The radius at `angle` (any real; the curve has period 2π).
    fn at(&self, angle: f64) -> f64 {
        let m = self.knots.len();
        let x = angle.rem_euclid(TAU) / TAU * m as f64;
        let i = (x.floor() as usize).min(m - 1);
        let t = x - i as f64;
        let k = |j: usize| self.knots[(j + m) % m];
        let (p0, p3) = (k(i), k(i + 1));
        let p1 = p0 + (k(i + 1) - k(i + m - 1)) / 6.0;
        let p2 = p3 - (k(i + 2) - k(i)) / 6.0;
        let s = 1.0 - t;
        let r = s * s * s * p0 + 3.0 * s * s * t * p1 + 3.0 * s * t * t * p2 + t * t * t * p3;
        r.clamp(self.lo, self.hi)
    }
}
