//! Generated inputs of growing size for the scaling benchmarks: `cargo bench -p
//! polytri-oracle --bench peers` and `polytri bench --scaling` time the same polygons.
//!
//! Every [`Series`] makes an input of about `n` vertices for any `n` from a few dozen to
//! 10⁶ and beyond, deterministically (seeded by `n`), valid by construction: simple rings,
//! holes inside the outer ring and apart from each other (but for the pinwheel's, which
//! touch at one point), first ring outer ([`Nesting::FirstIsOuter`]).
//!
//! ```
//! use polytri_oracle::series::Series;
//!
//! let input = Series::Circles.input(10_000);
//! assert!(input.vertices.len().abs_diff(10_000) < 100);
//! assert_eq!(input.ring_count(), 1 + 10_000 / 32);
//! ```

use std::fmt;
use std::str::FromStr;

use crate::gen::{self, Family, Rng};
use crate::input::{Input, Nesting};

/// The sizes of a scaling run: 10³ to 10⁶ vertices by half decades (1, 3, 10, 30, …).
pub const SIZES: [usize; 7] = [1_000, 3_000, 10_000, 30_000, 100_000, 300_000, 1_000_000];

/// A family of generated inputs whose size is a parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Series {
    /// A random simple polygon through random points, by Auer & Held's space-partitioning
    /// heuristic ([`Family::SpacePartition`] without its size limit): non-convex everywhere,
    /// with spikes and pockets at every scale.
    Random,
    /// A star-shaped polygon: evenly spread angles, random radii in [0.2, 1].
    Star,
    /// A rectangle with 32-gon holes on a grid, about `n / 32` of them (31,250 at 10⁶): the
    /// paper's `rect_circles` grown into one huge polygon with tens of thousands of holes.
    Circles,
    /// A comb: thin teeth on a spine, every gap a pair of reflex vertices.
    Comb,
    /// A square with about `n / 3` thin triangular holes meeting at its centre: every hole
    /// touches every other at one point, and their sides are long edges running across
    /// much of the input (the shape of a pie chart's slices, or a fan).
    Pinwheel,
}

/// Sides of every hole of [`Series::Circles`].
const CIRCLE_SIDES: usize = 32;

impl Series {
    /// Every series, in the order tables show them.
    pub const ALL: [Series; 5] = [
        Series::Random,
        Series::Star,
        Series::Circles,
        Series::Comb,
        Series::Pinwheel,
    ];

    /// The name, as [`Display`](fmt::Display) writes and [`FromStr`] reads it.
    pub const fn name(self) -> &'static str {
        match self {
            Series::Random => "random",
            Series::Star => "star",
            Series::Circles => "circles",
            Series::Comb => "comb",
            Series::Pinwheel => "pinwheel",
        }
    }

    /// One line on what the inputs look like.
    pub const fn describe(self) -> &'static str {
        match self {
            Series::Random => "a random polygon (space partitioning)",
            Series::Star => "a star-shaped polygon with random radii",
            Series::Circles => "a rectangle with n/32 holes, each a 32-gon",
            Series::Comb => "a comb with n/4 thin teeth",
            Series::Pinwheel => "a square with n/3 thin triangular holes meeting at its centre",
        }
    }

    /// The input of about `n` vertices (at least a few, whatever `n`).
    pub fn input(self, n: usize) -> Input {
        let rings = match self {
            Series::Random => gen::grid_rings(Family::SpacePartition, n as u64, n),
            Series::Star => vec![star(n)],
            Series::Circles => circles(n),
            Series::Comb => vec![comb(n)],
            Series::Pinwheel => pinwheel(n),
        };
        Input::from_rings(&rings, Nesting::FirstIsOuter)
    }
}

impl fmt::Display for Series {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Series {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        crate::by_name(s, &Series::ALL, Series::name, "series")
    }
}

/// `n` evenly spread angles (at least 3), random radii in [0.2, 1].
fn star(n: usize) -> Vec<[f64; 2]> {
    let n = n.max(3);
    let mut rng = Rng::new(n as u64);
    (0..n)
        .map(|k| {
            let angle = std::f64::consts::TAU * k as f64 / n as f64;
            let radius = rng.float(0.2, 1.0);
            [radius * angle.cos(), radius * angle.sin()]
        })
        .collect()
}

/// A rectangle around a grid of unit cells, a 32-gon of random radius in [0.3, 0.45] in
/// each of `n / 32` cells (at least one): the holes never touch.
fn circles(n: usize) -> Vec<Vec<[f64; 2]>> {
    let holes = (n / CIRCLE_SIDES).max(1);
    let columns = (holes as f64).sqrt().ceil() as usize;
    let rows = holes.div_ceil(columns);
    let mut rng = Rng::new(n as u64 ^ 0xC1C1);
    let (width, height) = (columns as f64, rows as f64);
    let mut rings = Vec::with_capacity(holes + 1);
    rings.push(vec![
        [0.0, 0.0],
        [width, 0.0],
        [width, height],
        [0.0, height],
    ]);
    for h in 0..holes {
        let center = [(h % columns) as f64 + 0.5, (h / columns) as f64 + 0.5];
        let radius = rng.float(0.3, 0.45);
        rings.push(
            (0..CIRCLE_SIDES)
                .map(|k| {
                    let angle = std::f64::consts::TAU * k as f64 / CIRCLE_SIDES as f64;
                    [
                        center[0] + radius * angle.cos(),
                        center[1] + radius * angle.sin(),
                    ]
                })
                .collect(),
        );
    }
    rings
}

/// About `n / 4` teeth of width 1, height 9 and gap 1 on a spine: four vertices a tooth,
/// two for the spine's bottom corners.
fn comb(n: usize) -> Vec<[f64; 2]> {
    let teeth = (n.saturating_sub(2) / 4).max(1);
    let mut ring = Vec::with_capacity(4 * teeth + 2);
    for t in 0..teeth {
        let x = 2.0 * t as f64;
        ring.extend_from_slice(&[[x, 1.0], [x, 10.0], [x + 1.0, 10.0], [x + 1.0, 1.0]]);
    }
    let end = 2.0 * teeth as f64 - 1.0;
    ring.extend_from_slice(&[[end, 0.0], [0.0, 0.0]]);
    ring
}

/// A square of side 4 round the origin, and about `n / 3` clockwise triangles from the
/// origin out to radius 1, each over half of its share of the full turn (at least one).
fn pinwheel(n: usize) -> Vec<Vec<[f64; 2]>> {
    let holes = (n.saturating_sub(4) / 3).max(1);
    let at = |turns: f64| {
        let angle = std::f64::consts::TAU * turns / holes as f64;
        [angle.cos(), angle.sin()]
    };
    let square = vec![[-2.0, -2.0], [2.0, -2.0], [2.0, 2.0], [-2.0, 2.0]];
    let wedges = (0..holes).map(|i| vec![[0.0, 0.0], at(i as f64 + 0.5), at(i as f64)]);
    std::iter::once(square).chain(wedges).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for series in Series::ALL {
            assert_eq!(series.to_string().parse::<Series>(), Ok(series));
        }
        assert!("square".parse::<Series>().is_err());
    }

    #[test]
    fn sizes_are_about_right_and_inputs_valid() {
        for series in Series::ALL {
            for n in [3, 100, 2_000] {
                let input = series.input(n);
                let got = input.vertices.len();
                // space partitioning drops points that fall exactly on a splitting line;
                // the smallest comb has 6 vertices, the smallest circles 36, the smallest
                // pinwheel 7
                assert!(got.abs_diff(n) <= n / 10 + 33, "{series} {n}: {got}");
                // the pinwheel's holes touch at its centre, by design
                gen::validate(&input, series == Series::Pinwheel)
                    .unwrap_or_else(|e| panic!("{series} at {n} invalid: {e}"));
            }
        }
    }

    #[test]
    fn inputs_repeat_for_their_size() {
        for series in Series::ALL {
            assert_eq!(series.input(500), series.input(500), "{series}");
        }
    }

    #[test]
    fn a_million_circle_vertices_are_tens_of_thousands_of_holes() {
        let holes = 1_000_000 / CIRCLE_SIDES;
        assert!((10_000..100_000).contains(&holes));
        assert_eq!(circles(1_000_000).len(), holes + 1);
    }
}
