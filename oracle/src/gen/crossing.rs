//! Seeded generators of crossing input, for fill rules: rings that cross themselves and
//! each other, overlap, run along each other and pass many times through one point.
//!
//! Unlike the [`Family`](super::Family) generators, nothing here is valid for the strict
//! triangulator: these inputs only have a meaning under a [`polytri::FillRule`], which
//! reads the region off the winding numbers. Each [`CrossingFamily`] stresses one way of
//! crossing; [`generate_crossing`] makes a case of it from a seed, deterministically.
//!
//! # Coordinates
//!
//! Every family builds its rings on an integer grid (side at most 2²⁰) and then places them
//! in one of four ways, chosen by the seed: as integers (crossing points sometimes exact,
//! collinear and concurrent edges kept), divided by a power of two (exact, not integers),
//! scaled by a random factor and moved by a random offset (rounded: degeneracies mostly
//! broken, crossing points never exact), or rotated by a random angle. Half the cases are
//! mirrored, which turns every ring's winding around, so the positive and negative fill
//! rules both see filled regions. Coordinates stay below 2²² in magnitude.
//!
//! ```
//! use polytri_oracle::gen::crossing::{generate_crossing, CrossingFamily};
//! let (vertices, ring_starts) = generate_crossing(CrossingFamily::StarPolygon, 7, 40);
//! assert!(vertices.len() <= 40 && ring_starts[0] == 0);
//! assert_eq!("figure-eight".parse(), Ok(CrossingFamily::FigureEight));
//! ```

use std::f64::consts::{PI, TAU};
use std::fmt;
use std::str::FromStr;

use super::geom::Pt;
use super::rng::Rng;

/// The fewest vertices a case has room for: sizes below are raised to it.
pub const MIN_VERTICES: usize = 8;
/// The most vertices a case has: sizes above are lowered to it.
pub const MAX_VERTICES: usize = 100_000;

/// Side of the largest grid the families build on.
const SIDE: i64 = 1 << 20;
/// Half of it: the centre of most shapes.
const HALF: i64 = SIDE / 2;

/// A named kind of crossing input.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CrossingFamily {
    /// Star polygons {p/k}: p points on a circle joined every k-th (the pentagram is
    /// {5/2}); when p and k share a factor d, a compound of d rings (the hexagram {6/2} is
    /// two triangles). Sometimes two or three stars, less regular, overlapping.
    StarPolygon,
    /// Figure eights: a lemniscate crossing itself at its centre, sometimes with Lissajous
    /// curves (1:2, 1:3, 2:3, …) as further rings crossing it and themselves.
    FigureEight,
    /// One ring running round the same loop two or three times: either the very same
    /// vertices again (every edge covered twice, winding number 2 inside, no proper
    /// crossing) or a smaller copy each pass, as a spiral whose closing edges cross.
    WoundTwice,
    /// One ring repeated as separate rings: some reversed (cancelling), some with another
    /// start vertex, some moved so that their boundaries cross.
    OverlappingCopies,
    /// Random closed polylines: random points on small sizes (many crossings), noisy loops
    /// on larger ones (crossings spread along them).
    SegmentSoup,
    /// Glyph-like outlines with overlapping strokes, as a font's contours: rectangles,
    /// capsules and rings (O with a clockwise counter) crossing each other in glyph cells,
    /// mostly counter-clockwise, a few reversed.
    Strokes,
    /// Collinear overlaps on a lattice: rectangles sharing edge stretches (with every
    /// lattice point on their sides sometimes, and reversed duplicates), and spokes whose
    /// edges all pass through one hub point, some ending or turning there.
    CollinearOverlaps,
}

impl CrossingFamily {
    /// Every crossing family, in declaration order.
    pub const ALL: [CrossingFamily; 7] = [
        CrossingFamily::StarPolygon,
        CrossingFamily::FigureEight,
        CrossingFamily::WoundTwice,
        CrossingFamily::OverlappingCopies,
        CrossingFamily::SegmentSoup,
        CrossingFamily::Strokes,
        CrossingFamily::CollinearOverlaps,
    ];

    /// The kebab-case name (as on the command line).
    pub fn name(self) -> &'static str {
        match self {
            CrossingFamily::StarPolygon => "star-polygon",
            CrossingFamily::FigureEight => "figure-eight",
            CrossingFamily::WoundTwice => "wound-twice",
            CrossingFamily::OverlappingCopies => "overlapping-copies",
            CrossingFamily::SegmentSoup => "segment-soup",
            CrossingFamily::Strokes => "strokes",
            CrossingFamily::CollinearOverlaps => "collinear-overlaps",
        }
    }

    /// One sentence on what the family's inputs look like.
    pub fn describe(self) -> &'static str {
        match self {
            CrossingFamily::StarPolygon => "star polygons {p/k} and compounds of them",
            CrossingFamily::FigureEight => "figure eights and Lissajous curves",
            CrossingFamily::WoundTwice => "one ring running round the same loop twice or more",
            CrossingFamily::OverlappingCopies => "copies of one ring, reversed, restarted, moved",
            CrossingFamily::SegmentSoup => "random closed polylines with many crossings",
            CrossingFamily::Strokes => "glyph-like outlines of overlapping strokes",
            CrossingFamily::CollinearOverlaps => {
                "rings sharing edge stretches, many edges through one point"
            }
        }
    }

    /// Whether every case of the family has two edges crossing properly (at one point
    /// inside both) — all but [`CrossingFamily::WoundTwice`], whose exact repetitions only
    /// overlap. (For sizes up to a few thousand vertices: on the largest sizes rounding to
    /// the grid may flatten the regular stars.)
    pub fn always_crosses(self) -> bool {
        !matches!(self, CrossingFamily::WoundTwice)
    }
}

impl fmt::Display for CrossingFamily {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for CrossingFamily {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        crate::by_name(
            s,
            &CrossingFamily::ALL,
            CrossingFamily::name,
            "crossing family",
        )
    }
}

/// A seeded case of `family` with about `size` vertices (clamped to
/// [`MIN_VERTICES`]`..=`[`MAX_VERTICES`], never more): the vertices and the ring starts,
/// as [`polytri::Triangulator::triangulate`] takes them. Every ring has at least three
/// vertices; every coordinate is finite and below 2²² in magnitude.
///
/// Deterministic: the same family, seed and size always give the same case.
pub fn generate_crossing(
    family: CrossingFamily,
    seed: u64,
    size: usize,
) -> (Vec<[f64; 2]>, Vec<usize>) {
    let n = size.clamp(MIN_VERTICES, MAX_VERTICES);
    let mut rng = Rng::new(seed ^ salt(family));
    let rings = match family {
        CrossingFamily::StarPolygon => star_polygons(&mut rng, n),
        CrossingFamily::FigureEight => figure_eights(&mut rng, n),
        CrossingFamily::WoundTwice => wound_twice(&mut rng, n),
        CrossingFamily::OverlappingCopies => copies(&mut rng, n),
        CrossingFamily::SegmentSoup => soup(&mut rng, n),
        CrossingFamily::Strokes => strokes(&mut rng, n),
        CrossingFamily::CollinearOverlaps => collinear(&mut rng, n),
    };
    let rings: Vec<Vec<Pt>> = rings.into_iter().filter(|r| r.len() >= 3).collect();
    debug_assert!(
        rings.iter().map(Vec::len).sum::<usize>() <= n,
        "{family} seed {seed}: over {n} vertices"
    );
    place(rings, family, &mut rng)
}

/// Separates the families' random streams (and from the valid families' streams).
fn salt(family: CrossingFamily) -> u64 {
    let index = CrossingFamily::ALL
        .iter()
        .position(|&f| f == family)
        .unwrap_or(0) as u64;
    (index + 101).wrapping_mul(0x9e37_79b9_7f4a_7c15)
}

/// A point rounded to the grid.
fn grid(x: f64, y: f64) -> Pt {
    [x.round() as i64, y.round() as i64]
}

/// `c + v` for a grid point and an offset in grid units, rounded.
fn at(c: Pt, v: [f64; 2]) -> Pt {
    [c[0] + v[0].round() as i64, c[1] + v[1].round() as i64]
}

/// `x` rounded to the nearest integer, at least `min` (for counts).
fn count(x: f64, min: usize) -> usize {
    (x.round().max(0.0) as usize).max(min)
}

/// A star-shaped ring of `m ≥ 3` vertices around `c`: angles increasing with jitter below
/// half the spacing (so every angular gap stays below π), radii in `[r_min, r_max]`.
fn star_loop(rng: &mut Rng, c: Pt, m: usize, r_min: f64, r_max: f64) -> Vec<Pt> {
    let m = m.max(3);
    let spacing = TAU / m as f64;
    let phase = rng.float(0.0, TAU);
    (0..m)
        .map(|j| {
            let angle = phase + spacing * (j as f64 + rng.float(-0.45, 0.45));
            let r = rng.float(r_min, r_max);
            at(c, [r * angle.cos(), r * angle.sin()])
        })
        .collect()
}

fn gcd(a: usize, b: usize) -> usize {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

// ---------------------------------------------------------------------------------------
// the families, on the grid

/// Star polygons {p/k} and compounds (see [`CrossingFamily::StarPolygon`]).
fn star_polygons(rng: &mut Rng, n: usize) -> Vec<Vec<Pt>> {
    let stars = if n >= 30 && rng.chance(0.3) {
        rng.int(2, 3) as usize
    } else {
        1
    };
    let mut rings = Vec::new();
    let mut left = n;
    for s in 0..stars {
        let share = left / (stars - s);
        let p = if n < 16 {
            rng.int(5, share as i64) as usize
        } else {
            share
        };
        left -= p;
        let k_max = ((p - 1) / 2).min(12);
        let k = if rng.chance(0.5) {
            2
        } else {
            rng.int(2, k_max as i64) as usize
        };
        // A radius large enough that the rounded points stay in convex position.
        let r_fit = (8 * p * p).min(1 << 19) as f64;
        let r = if rng.chance(0.3) {
            r_fit.max(32.0)
        } else {
            (1 << 19) as f64
        };
        let (c, regular) = if s == 0 {
            ([HALF, HALF], true)
        } else {
            let d = r * 0.5;
            (
                at([HALF, HALF], [rng.float(-d, d), rng.float(-d, d)]),
                rng.chance(0.3),
            )
        };
        let phase = rng.float(0.0, TAU);
        let points: Vec<Pt> = (0..p)
            .map(|i| {
                let (mut angle, mut radius) = (phase + TAU * i as f64 / p as f64, r);
                if !regular {
                    angle += rng.float(-0.3, 0.3) * TAU / p as f64;
                    radius *= rng.float(0.7, 1.0);
                }
                at(c, [radius * angle.cos(), radius * angle.sin()])
            })
            .collect();
        let d = gcd(p, k);
        let reverse = rng.chance(0.3);
        for first in 0..d {
            let mut ring: Vec<Pt> = (0..p / d).map(|j| points[(first + j * k) % p]).collect();
            if reverse {
                ring.reverse();
            }
            rings.push(ring);
        }
    }
    rings
}

/// A lemniscate of `m` (even, ≥ 4) vertices crossing itself properly at `c`'s vertical:
/// the left lobe is the right one mirrored exactly, so the two edges through the middle
/// are mirror images and meet on the axis.
fn lemniscate(rng: &mut Rng, c: Pt, m: usize, r: f64) -> Vec<Pt> {
    let h = (m / 2).max(2);
    let phase = rng.float(0.25, 0.75);
    let aspect = rng.float(0.6, 2.0);
    let mut right: Vec<Pt> = (0..h)
        .map(|j| {
            let t = -PI / 2.0 + PI * (j as f64 + phase) / h as f64;
            let [x, y] = grid(r * t.cos(), r * aspect * (2.0 * t).sin() / 2.0);
            [x.max(1), y]
        })
        .collect();
    // The edges through the middle must not be horizontal.
    right[0][1] = right[0][1].min(-1);
    right[h - 1][1] = right[h - 1][1].max(1);
    let mut ring: Vec<Pt> = right.iter().map(|p| [c[0] + p[0], c[1] + p[1]]).collect();
    ring.extend(right.iter().map(|p| [c[0] - p[0], c[1] + p[1]]));
    ring
}

/// Figure eights and Lissajous curves (see [`CrossingFamily::FigureEight`]).
fn figure_eights(rng: &mut Rng, n: usize) -> Vec<Vec<Pt>> {
    let rings = if n >= 40 && rng.chance(0.4) {
        rng.int(2, 4) as usize
    } else {
        1
    };
    let each = n / rings;
    let r_fit = (8 * each * each).clamp(16, 1 << 18) as f64;
    let r = if rng.chance(0.3) {
        r_fit
    } else {
        (1 << 18) as f64
    };
    let mut out = vec![lemniscate(rng, [HALF, HALF], each & !1, r)];
    const RATIOS: [(f64, f64); 6] = [
        (1.0, 2.0),
        (2.0, 1.0),
        (1.0, 3.0),
        (3.0, 2.0),
        (2.0, 3.0),
        (3.0, 4.0),
    ];
    for _ in 1..rings {
        let (a, b) = RATIOS[rng.below(RATIOS.len())];
        let delta = rng.float(0.1, PI - 0.1);
        let phase = rng.float(0.0, 1.0);
        let (rx, ry) = (r * rng.float(0.3, 1.0), r * rng.float(0.3, 1.0));
        let c = at(
            [HALF, HALF],
            [rng.float(-r, r) * 0.5, rng.float(-r, r) * 0.5],
        );
        out.push(
            (0..each)
                .map(|j| {
                    let t = TAU * (j as f64 + phase) / each as f64;
                    at(c, [rx * (a * t + delta).sin(), ry * (b * t).sin()])
                })
                .collect(),
        );
    }
    for ring in &mut out {
        if rng.chance(0.5) {
            ring.reverse();
        }
    }
    out
}

/// One ring round the same loop two or three times (see [`CrossingFamily::WoundTwice`]).
fn wound_twice(rng: &mut Rng, n: usize) -> Vec<Vec<Pt>> {
    let passes = if n >= 12 && rng.chance(0.25) { 3 } else { 2 };
    let m = n / passes;
    let r = if rng.chance(0.3) {
        (16 * m).max(64) as f64
    } else {
        (1 << 18) as f64
    };
    let c = [HALF, HALF];
    let r_min = r * rng.float(0.2, 0.8);
    let base = star_loop(rng, c, m, r_min, r);
    let exact = rng.chance(0.5);
    let shrink = rng.float(0.4, 0.85);
    let mut ring = Vec::with_capacity(m * passes);
    let mut scale = 1.0;
    for _ in 0..passes {
        ring.extend(base.iter().map(|p| {
            if exact {
                *p
            } else {
                at(
                    c,
                    [(p[0] - c[0]) as f64 * scale, (p[1] - c[1]) as f64 * scale],
                )
            }
        }));
        scale *= shrink;
    }
    if rng.chance(0.5) {
        ring.reverse();
    }
    vec![ring]
}

/// Copies of one ring (see [`CrossingFamily::OverlappingCopies`]).
fn copies(rng: &mut Rng, n: usize) -> Vec<Vec<Pt>> {
    let copies = (rng.int(2, 5) as usize).min(n / 4);
    let m = n / copies;
    let r = if rng.chance(0.3) {
        (16 * m).max(64) as f64
    } else {
        (1 << 18) as f64
    };
    let r_min = r * rng.float(0.3, 0.8);
    let base = star_loop(rng, [HALF, HALF], m, r_min, r);
    let mut rings = vec![base.clone()];
    for i in 1..copies {
        let mut ring = base.clone();
        if i == 1 || rng.chance(0.6) {
            // moved: by a vector with both components nonzero, less than the ring's size
            let length = r * rng.float(0.05, 0.3);
            let angle = rng.float(0.0, TAU);
            let [dx, dy] = grid(length * angle.cos(), length * angle.sin());
            let (dx, dy) = (if dx == 0 { 1 } else { dx }, if dy == 0 { 1 } else { dy });
            for p in &mut ring {
                *p = [p[0] + dx, p[1] + dy];
            }
        }
        if rng.chance(0.5) {
            let start = rng.below(m);
            ring.rotate_left(start);
        }
        if rng.chance(0.4) {
            ring.reverse();
        }
        rings.push(ring);
    }
    rings
}

/// Random closed polylines (see [`CrossingFamily::SegmentSoup`]).
fn soup(rng: &mut Rng, n: usize) -> Vec<Vec<Pt>> {
    let rings = (rng.int(1, 4) as usize).min(n / 4);
    let side = [16, 1024, SIDE][rng.below(3)];
    let mut out = Vec::with_capacity(rings);
    let mut left = n;
    for i in 0..rings {
        let m = left / (rings - i);
        left -= m;
        let mut ring = Vec::with_capacity(m);
        let loop_ring = m > 64 || (m > 24 && rng.chance(0.5));
        let (c, r) = if loop_ring {
            let r = side as f64 * rng.float(0.15, 0.5);
            let c = at(
                [side / 2, side / 2],
                [rng.float(-0.2, 0.2) * r, rng.float(-0.2, 0.2) * r],
            );
            (c, r)
        } else {
            ([side / 2, side / 2], side as f64 / 2.0)
        };
        if i == 0 {
            // a bow tie first: edges 0-1 and 2-3 cross properly
            let w = ((r / 4.0) as i64).max(2);
            let (x0, y0) = (c[0] - w / 2, c[1] - w / 2);
            let (x1, y1) = (x0 + rng.int(1, w), y0 + rng.int(1, w));
            ring.extend([[x0, y0], [x1, y1], [x1, y0], [x0, y1]]);
        }
        let rest = m - ring.len();
        if loop_ring {
            let jitter = rng.float(0.0, 3.0);
            let (r_min, phase) = (r * rng.float(0.1, 0.8), rng.float(0.0, TAU));
            for j in 0..rest {
                let angle = phase + TAU * (j as f64 + rng.float(-jitter, jitter)) / rest as f64;
                let radius = rng.float(r_min, r);
                ring.push(at(c, [radius * angle.cos(), radius * angle.sin()]));
            }
        } else {
            for _ in 0..rest {
                ring.push([rng.int(0, side), rng.int(0, side)]);
            }
        }
        if rng.chance(0.5) {
            ring.reverse();
        }
        out.push(ring);
    }
    out
}

/// A rectangle stroke of half-length `l` and half-width `w` along `angle`,
/// counter-clockwise.
fn rectangle(c: [f64; 2], angle: f64, l: f64, w: f64) -> Vec<Pt> {
    let (d, p) = ([angle.cos(), angle.sin()], [-angle.sin(), angle.cos()]);
    [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
        .iter()
        .map(|&(s, t)| {
            grid(
                c[0] + s * l * d[0] + t * w * p[0],
                c[1] + s * l * d[1] + t * w * p[1],
            )
        })
        .collect()
}

/// A capsule stroke: a rectangle with half-discs of `q + 1` points on its ends,
/// counter-clockwise.
fn capsule(c: [f64; 2], angle: f64, l: f64, w: f64, q: usize) -> Vec<Pt> {
    let d = [angle.cos(), angle.sin()];
    let ends = [
        [c[0] + l * d[0], c[1] + l * d[1]],
        [c[0] - l * d[0], c[1] - l * d[1]],
    ];
    let mut ring = Vec::with_capacity(2 * q + 2);
    for (k, e) in ends.iter().enumerate() {
        let from = angle - PI / 2.0 + PI * k as f64;
        for j in 0..=q {
            let a = from + PI * j as f64 / q as f64;
            ring.push(grid(e[0] + w * a.cos(), e[1] + w * a.sin()));
        }
    }
    ring
}

/// A circle of `q` points, counter-clockwise.
fn circle(c: [f64; 2], r: f64, q: usize, phase: f64) -> Vec<Pt> {
    (0..q)
        .map(|j| {
            let a = phase + TAU * j as f64 / q as f64;
            grid(c[0] + r * a.cos(), c[1] + r * a.sin())
        })
        .collect()
}

/// Glyph-like outlines of overlapping strokes (see [`CrossingFamily::Strokes`]).
fn strokes(rng: &mut Rng, n: usize) -> Vec<Vec<Pt>> {
    let glyphs = (n / 24).max(1);
    let cols = count((glyphs as f64).sqrt().ceil(), 1);
    let cell = if rng.chance(0.3) {
        64.0
    } else {
        (SIDE / cols as i64) as f64
    };
    let centre = |g: usize| {
        [
            ((g % cols) as f64 + 0.5) * cell,
            ((g / cols) as f64 + 0.5) * cell,
        ]
    };
    // Glyph 0 opens with two strokes crossing as a + or an X.
    let c0 = centre(0);
    let angle = if rng.chance(0.5) {
        0.0
    } else {
        rng.float(0.0, PI)
    };
    let turn = if rng.chance(0.5) {
        PI / 2.0
    } else {
        rng.float(PI / 3.0, 2.0 * PI / 3.0)
    };
    let (l, w) = (0.35 * cell, (0.06 * cell).max(2.0));
    let mut rings = vec![
        rectangle(c0, angle, l, w),
        rectangle(c0, angle + turn, l, w),
    ];
    let mut used = 8;
    while used + 4 <= n {
        let g = rng.below(glyphs);
        let c = centre(g);
        let c = [
            c[0] + rng.float(-0.2, 0.2) * cell,
            c[1] + rng.float(-0.2, 0.2) * cell,
        ];
        let angle = if rng.chance(0.5) {
            PI / 2.0 * rng.below(2) as f64
        } else {
            rng.float(0.0, PI)
        };
        let l = cell * rng.float(0.1, 0.3);
        let w = (cell * rng.float(0.03, 0.1)).max(1.0);
        let kind = rng.unit();
        let mut made = if kind < 0.5 {
            vec![rectangle(c, angle, l, w)]
        } else if kind < 0.8 {
            vec![capsule(c, angle, l, w, rng.int(2, 8) as usize)]
        } else {
            // an O: outer ring and a clockwise counter
            let q = rng.int(6, 16) as usize;
            let r = cell * rng.float(0.12, 0.25);
            let phase = rng.float(0.0, TAU);
            let mut counter = circle(c, r * rng.float(0.5, 0.8), q, phase);
            counter.reverse();
            vec![circle(c, r, q, phase), counter]
        };
        let size: usize = made.iter().map(Vec::len).sum();
        if used + size > n {
            made = vec![rectangle(c, angle, l, w)];
        }
        for ring in &mut made {
            if rng.chance(0.15) {
                ring.reverse();
            }
        }
        used += made.iter().map(Vec::len).sum::<usize>();
        rings.extend(made);
    }
    rings
}

/// Directions of spokes, pairwise not parallel.
const SPOKES: [[i64; 2]; 10] = [
    [1, 0],
    [0, 1],
    [1, 1],
    [1, -1],
    [2, 1],
    [1, 2],
    [2, -1],
    [1, -2],
    [3, 1],
    [1, 3],
];

/// Lattice rectangles and spokes through a hub (see [`CrossingFamily::CollinearOverlaps`]).
fn collinear(rng: &mut Rng, n: usize) -> Vec<Vec<Pt>> {
    let u = [1, 2, 16, 1024][rng.below(4)];
    let hub = [HALF, HALF];
    let mut rings = Vec::new();
    // Spokes: edges through the hub; the first two cross there properly.
    let spokes = (rng.int(2, 8) as usize).min((n * 2 / 5 / 3).max(2));
    let mut dirs = SPOKES;
    rng.shuffle(&mut dirs);
    let mut used = 0;
    for (i, d) in dirs.iter().take(spokes).enumerate() {
        let t = rng.int(1, 4) * u;
        let dd = [d[0] * t, d[1] * t];
        let side = if rng.chance(0.5) { 1 } else { -1 };
        let e = [
            -d[1] * u * side * rng.int(1, 2),
            d[0] * u * side * rng.int(1, 2),
        ];
        let (a, b) = (
            [hub[0] - dd[0], hub[1] - dd[1]],
            [hub[0] + dd[0], hub[1] + dd[1]],
        );
        let c = [b[0] + e[0], b[1] + e[1]];
        let kind = if i < 2 { 0.0 } else { rng.unit() };
        let ring = if kind < 0.6 {
            vec![a, b, c]
        } else if kind < 0.8 {
            vec![a, hub, b, c] // a vertex at the hub, on the straight edge
        } else {
            vec![hub, b, c] // an edge ending at the hub
        };
        if used + ring.len() > n {
            break;
        }
        used += ring.len();
        rings.push(ring);
    }
    // Rectangles on the lattice around the hub, sharing stretches of their sides.
    let expected = (n - used) / 8;
    let half = count((expected as f64).sqrt() * 1.5, 4) as i64;
    let mut made: Vec<[i64; 4]> = Vec::new();
    loop {
        let (mut x0, mut y0) = (rng.int(-half, half), rng.int(-half, half));
        let (mut x1, mut y1) = (x0 + rng.int(1, 4), y0 + rng.int(1, 4));
        let roll = rng.unit();
        if !made.is_empty() && roll < 0.3 {
            let [a, b, c, d] = made[rng.below(made.len())];
            if roll < 0.15 {
                (x0, y0, x1, y1) = (a, b, c, d); // the same rectangle again
            } else {
                // beside it, sharing a side or part of one
                let w = rng.int(1, 4);
                (x0, x1) = if rng.chance(0.5) {
                    (c, c + w)
                } else {
                    (a - w, a)
                };
                (y0, y1) = (b + rng.int(0, d - b - 1), d + rng.int(0, 2));
            }
        }
        let corners = [[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
        let mut ring = Vec::new();
        let dense = rng.chance(0.5);
        for k in 0..4 {
            let (p, q) = (corners[k], corners[(k + 1) % 4]);
            let steps = if dense {
                (q[0] - p[0]).abs().max((q[1] - p[1]).abs())
            } else {
                1
            };
            for s in 0..steps {
                let lx = p[0] + (q[0] - p[0]) * s / steps;
                let ly = p[1] + (q[1] - p[1]) * s / steps;
                ring.push([hub[0] + lx * u, hub[1] + ly * u]);
            }
        }
        if used + ring.len() > n {
            if used + 4 > n {
                break;
            }
            ring = corners
                .iter()
                .map(|p| [hub[0] + p[0] * u, hub[1] + p[1] * u])
                .collect();
        }
        if rng.chance(0.5) {
            ring.reverse();
        }
        used += ring.len();
        made.push([x0, y0, x1, y1]);
        rings.push(ring);
    }
    rings
}

// ---------------------------------------------------------------------------------------
// placement

/// How grid coordinates become the case's.
#[derive(Clone, Copy, Debug)]
enum Coords {
    /// Integers, moved by an integer offset.
    Integer,
    /// Moved by an integer offset and divided by a power of two: exact, not integers.
    Dyadic,
    /// Scaled by a random factor and moved by a random offset: rounded.
    Scaled,
    /// Rotated by a random angle about the grid's centre, then moved: rounded.
    Rotated,
}

/// Rotates each ring's start, mirrors half the cases, and maps the grid to coordinates.
fn place(
    rings: Vec<Vec<Pt>>,
    family: CrossingFamily,
    rng: &mut Rng,
) -> (Vec<[f64; 2]>, Vec<usize>) {
    let weights = match family {
        CrossingFamily::CollinearOverlaps => [45, 35, 10, 10],
        _ => [35, 20, 25, 20],
    };
    let mut roll = rng.below(100);
    let mut mode = Coords::Integer;
    for (w, m) in weights.iter().zip([
        Coords::Integer,
        Coords::Dyadic,
        Coords::Scaled,
        Coords::Rotated,
    ]) {
        if roll < *w {
            mode = m;
            break;
        }
        roll -= w;
    }
    let mirror = rng.chance(0.5);
    let offset = [rng.int(-SIDE, SIDE) - HALF, rng.int(-SIDE, SIDE) - HALF];
    let shift = f64::from(1u32 << rng.int(1, 12));
    let scale = 10f64.powf(rng.float(-3.0, 0.5));
    let float_offset = [rng.float(-1e3, 1e3), rng.float(-1e3, 1e3)];
    let (sin, cos) = rng.float(0.0, TAU).sin_cos();
    let map = |p: Pt| -> [f64; 2] {
        let x = if mirror { SIDE - p[0] } else { p[0] };
        let y = p[1];
        match mode {
            Coords::Integer => [(x + offset[0]) as f64, (y + offset[1]) as f64],
            Coords::Dyadic => [
                (x + offset[0]) as f64 / shift,
                (y + offset[1]) as f64 / shift,
            ],
            Coords::Scaled => [
                x as f64 * scale + float_offset[0],
                y as f64 * scale + float_offset[1],
            ],
            Coords::Rotated => {
                let (dx, dy) = ((x - HALF) as f64, (y - HALF) as f64);
                [
                    dx * cos - dy * sin + float_offset[0],
                    dx * sin + dy * cos + float_offset[1],
                ]
            }
        }
    };
    let mut vertices = Vec::with_capacity(rings.iter().map(Vec::len).sum());
    let mut ring_starts = Vec::with_capacity(rings.len());
    for mut ring in rings {
        let start = rng.below(ring.len());
        ring.rotate_left(start);
        ring_starts.push(vertices.len());
        vertices.extend(ring.into_iter().map(map));
    }
    (vertices, ring_starts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::{cross_properly, orient};

    const SIZES: [usize; 8] = [0, 5, 8, 13, 40, 100, 333, 1000];

    /// The edges of every ring, as point pairs.
    fn edges(vertices: &[[f64; 2]], ring_starts: &[usize]) -> Vec<([f64; 2], [f64; 2])> {
        let mut out = Vec::new();
        for (r, &start) in ring_starts.iter().enumerate() {
            let end = ring_starts.get(r + 1).copied().unwrap_or(vertices.len());
            for i in start..end {
                let j = if i + 1 == end { start } else { i + 1 };
                out.push((vertices[i], vertices[j]));
            }
        }
        out
    }

    /// How many pairs of edges cross properly, by brute force (exact predicates).
    fn proper_crossings(vertices: &[[f64; 2]], ring_starts: &[usize]) -> usize {
        let e = edges(vertices, ring_starts);
        let mut count = 0;
        for i in 0..e.len() {
            for j in i + 1..e.len() {
                if cross_properly(e[i].0, e[i].1, e[j].0, e[j].1) {
                    count += 1;
                }
            }
        }
        count
    }

    #[test]
    fn names_round_trip() {
        for family in CrossingFamily::ALL {
            assert_eq!(family.name().parse(), Ok(family));
            assert_eq!(family.to_string(), family.name());
            assert!(!family.describe().is_empty());
        }
        assert_eq!(" Strokes ".parse(), Ok(CrossingFamily::Strokes));
        let err = "nope".parse::<CrossingFamily>().unwrap_err();
        assert!(err.contains("star-polygon"), "{err}");
    }

    #[test]
    fn deterministic_per_seed() {
        for family in CrossingFamily::ALL {
            for seed in 0..6 {
                let a = generate_crossing(family, seed, 60);
                let b = generate_crossing(family, seed, 60);
                assert_eq!(a, b, "{family} seed {seed}");
            }
            let seeds: Vec<_> = (0..6).map(|s| generate_crossing(family, s, 60)).collect();
            assert!(
                seeds.windows(2).any(|w| w[0] != w[1]),
                "{family}: seeds differ"
            );
        }
    }

    #[test]
    fn sizes_are_respected_and_rings_well_formed() {
        for family in CrossingFamily::ALL {
            for seed in 0..10 {
                for size in SIZES.into_iter().chain([4000]) {
                    let (vertices, starts) = generate_crossing(family, seed, size);
                    let n = size.clamp(MIN_VERTICES, MAX_VERTICES);
                    let what = format!("{family} seed {seed} size {size}");
                    assert!(vertices.len() <= n, "{what}: {} vertices", vertices.len());
                    if n >= 64 {
                        assert!(
                            vertices.len() >= n / 2,
                            "{what}: {} vertices",
                            vertices.len()
                        );
                    }
                    assert_eq!(starts.first(), Some(&0), "{what}");
                    let mut ends = starts[1..].to_vec();
                    ends.push(vertices.len());
                    for (s, e) in starts.iter().zip(ends) {
                        assert!(e >= s + 3, "{what}: a ring of {} vertices", e - s);
                    }
                    assert!(
                        vertices
                            .iter()
                            .flatten()
                            .all(|c| c.is_finite() && c.abs() < 4.2e6),
                        "{what}"
                    );
                }
            }
        }
    }

    #[test]
    fn families_that_promise_crossings_cross() {
        for family in CrossingFamily::ALL {
            let mut crossing_cases = 0;
            let mut cases = 0;
            for seed in 0..24 {
                for size in SIZES {
                    let (vertices, starts) = generate_crossing(family, seed, size);
                    let crossings = proper_crossings(&vertices, &starts);
                    cases += 1;
                    crossing_cases += usize::from(crossings > 0);
                    assert!(
                        crossings > 0 || !family.always_crosses(),
                        "{family} seed {seed} size {size}: no proper crossing in {vertices:?} {starts:?}"
                    );
                }
            }
            // Even the wound-twice rings cross in their spiral variant.
            assert!(
                crossing_cases * 3 >= cases,
                "{family}: {crossing_cases} of {cases}"
            );
        }
    }

    #[test]
    fn coordinates_are_mixed() {
        // Some cases integer (crossings can be exact), some not (they must be rounded).
        for family in CrossingFamily::ALL {
            let integral: Vec<bool> = (0..40)
                .map(|seed| {
                    let (vertices, _) = generate_crossing(family, seed, 30);
                    vertices.iter().flatten().all(|c| c.fract() == 0.0)
                })
                .collect();
            assert!(
                integral.contains(&true) && integral.contains(&false),
                "{family}"
            );
        }
    }

    #[test]
    fn pentagram_at_small_sizes() {
        // A {5/2} star among the small star cases: five vertices, five proper crossings.
        let found = (0..64).any(|seed| {
            let (vertices, starts) = generate_crossing(CrossingFamily::StarPolygon, seed, 5);
            vertices.len() == 5 && starts == [0] && proper_crossings(&vertices, &starts) == 5
        });
        assert!(found);
    }

    #[test]
    fn collinear_overlaps_share_stretches() {
        // Two edges along the same line, overlapping over a stretch of positive length.
        let overlap = |(a, b): ([f64; 2], [f64; 2]), (c, d): ([f64; 2], [f64; 2])| {
            use std::cmp::Ordering::Equal;
            let on_line = orient(a, b, c) == Equal && orient(a, b, d) == Equal;
            let axis = usize::from(a[0] == b[0]);
            let (lo, hi) = (a[axis].min(b[axis]), a[axis].max(b[axis]));
            let (lo2, hi2) = (c[axis].min(d[axis]), c[axis].max(d[axis]));
            a != b && on_line && lo.max(lo2) < hi.min(hi2)
        };
        let mut with_overlaps = 0;
        for seed in 0..20 {
            let (vertices, starts) =
                generate_crossing(CrossingFamily::CollinearOverlaps, seed, 200);
            let e = edges(&vertices, &starts);
            let found = (0..e.len()).any(|i| (i + 1..e.len()).any(|j| overlap(e[i], e[j])));
            with_overlaps += usize::from(found);
        }
        assert!(with_overlaps >= 10, "{with_overlaps} of 20");
    }
}
