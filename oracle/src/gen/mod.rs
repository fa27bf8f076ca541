//! Seeded generators of valid nested polygons, one per named [`Family`].
//!
//! Every generator is deterministic for its seed (a [`rand_pcg::Pcg64`] seeded with
//! `seed_from_u64`) and valid by construction: each ring simple, rings pairwise
//! non-crossing, properly nested (only [`Family::TouchingHoles`] lets rings share a vertex
//! position). [`validate`] checks this exactly; the tests run it on every family.
//!
//! # Coordinates
//!
//! Generators work on the integer grid `0..=2^20` ([`GRID`]). The case's coordinates are
//! `i · step + offset` with `step = scale · 2^-20`, where [`Params::scale`] is rounded to a
//! power of two and [`Params::offset`] to a multiple of `step`. Both operations are then
//! exact in `f64` — the transformed polygon is exactly a similar copy of the integer one, so
//! every orientation sign, and so validity, survives — as long as `|offset| / step < 2^52`
//! (for example offsets up to 1e9 at scale 1, or any scale at offset 0).
//! [`Params::is_exact`] says whether this holds; beyond it coordinates are rounded and
//! validity is no longer guaranteed.
//!
//! ```
//! use polytri_oracle::gen::{generate, validate, Family, Params};
//! let case = generate(Family::ManyHoles, 7, &Params::new(500).with_offset([1e9, -1e9]));
//! let layout = validate(&case.input, false).expect("valid by construction");
//! assert!(layout.depths.iter().filter(|&&d| d == 1).count() > 1);
//! ```

mod case;
pub mod crossing;
mod geom;
mod holes;
mod outlines;
mod random_polygons;
mod rng;
mod validate;

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

use crate::input::{Input, Nesting};
pub use case::Case;
use geom::Ring;
pub(crate) use rng::Rng;
pub use validate::{validate, Layout};

/// Bits of the generators' integer grid: coordinates before scaling lie in `0..=GRID`.
pub const GRID_BITS: i32 = 20;
/// Side of the generators' integer grid, `2^GRID_BITS`.
pub const GRID: i64 = 1 << GRID_BITS;

/// A named kind of random polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Family {
    /// One star-shaped ring: random radii at increasing angles around a centre.
    Star,
    /// One ring by Auer & Held's space-partitioning heuristic (RPG): random lines through
    /// random points split the point set recursively.
    SpacePartition,
    /// One ring by Auer & Held's 2-opt heuristic: a tour through random points, crossing
    /// edge pairs swapped until none cross.
    TwoOpt,
    /// One orthogonal ring around a random tree of grid cells, with every grid point of its
    /// runs kept (collinear vertices) and some vertices repeated.
    Orthogonal,
    /// Circular holes (regular polygons, nearly all reflex) in a rectangle or rounded
    /// rectangle, like the paper's `rect_circles`.
    Circles,
    /// One comb: a bar with many thin teeth, some with pointed tips.
    Comb,
    /// One thick spiral band with several turns.
    Spiral,
    /// Up to thousands of small star-shaped holes in one jagged outer ring.
    ManyHoles,
    /// Diamond-shaped holes on a lattice touching each other and the outer ring at single
    /// vertices (weakly simple where they meet).
    TouchingHoles,
    /// Islands in holes in islands, four to six rings deep (containment depth 3 to 5), rings shuffled and winding either way.
    NestedIslands,
    /// Needle-thin x-monotone bands with near-collinear chains, alone or as holes.
    Slivers,
    /// Glyph-like outlines flattened from cubic Bézier curves, with counters (holes) and
    /// separate dots.
    FontLike,
}

impl Family {
    /// Every family, in declaration order.
    pub const ALL: [Family; 12] = [
        Family::Star,
        Family::SpacePartition,
        Family::TwoOpt,
        Family::Orthogonal,
        Family::Circles,
        Family::Comb,
        Family::Spiral,
        Family::ManyHoles,
        Family::TouchingHoles,
        Family::NestedIslands,
        Family::Slivers,
        Family::FontLike,
    ];

    /// The kebab-case name (as in JSON and on the command line).
    pub fn name(self) -> &'static str {
        match self {
            Family::Star => "star",
            Family::SpacePartition => "space-partition",
            Family::TwoOpt => "two-opt",
            Family::Orthogonal => "orthogonal",
            Family::Circles => "circles",
            Family::Comb => "comb",
            Family::Spiral => "spiral",
            Family::ManyHoles => "many-holes",
            Family::TouchingHoles => "touching-holes",
            Family::NestedIslands => "nested-islands",
            Family::Slivers => "slivers",
            Family::FontLike => "font-like",
        }
    }

    /// One sentence on what the family's polygons look like.
    pub fn describe(self) -> &'static str {
        match self {
            Family::Star => "a star-shaped ring with random radii",
            Family::SpacePartition => "a random ring by space partitioning (Auer & Held)",
            Family::TwoOpt => "a random ring by 2-opt moves (Auer & Held)",
            Family::Orthogonal => "an orthogonal ring with collinear runs and repeated vertices",
            Family::Circles => "circular holes, nearly all reflex, in a (rounded) rectangle",
            Family::Comb => "a comb with many thin teeth",
            Family::Spiral => "a thick spiral band",
            Family::ManyHoles => "many small holes in one jagged outer ring",
            Family::TouchingHoles => {
                "holes touching each other and the outer ring at single vertices"
            }
            Family::NestedIslands => "islands in holes in islands, four to six rings deep",
            Family::Slivers => "needle-thin bands with near-collinear vertices",
            Family::FontLike => "glyph-like Bézier outlines with counters",
        }
    }

    /// Whether rings of this family may share vertex positions (the validity check must
    /// then accept touching at vertices).
    pub fn allows_touching(self) -> bool {
        matches!(self, Family::TouchingHoles)
    }
}

impl fmt::Display for Family {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Family {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Family::ALL
            .into_iter()
            .find(|f| f.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
                format!("unknown family {s:?}; expected one of {}", names.join(", "))
            })
    }
}

/// How large, and where, a generated case is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Params {
    /// The approximate number of vertices, `3..=100_000` (clamped). Families with a
    /// minimum structure (a hole needs an outer ring) may give a few more at tiny sizes.
    pub vertices: usize,
    /// The side of the square the case fits in; rounded to a power of two (see the module
    /// documentation). Default 1.
    pub scale: f64,
    /// Added to every coordinate after scaling; rounded to a multiple of the grid step.
    /// Default `[0, 0]`.
    pub offset: [f64; 2],
}

impl Default for Params {
    fn default() -> Self {
        Params::new(100)
    }
}

impl Params {
    /// About `vertices` vertices at scale 1, offset 0.
    pub fn new(vertices: usize) -> Self {
        Params {
            vertices,
            scale: 1.0,
            offset: [0.0, 0.0],
        }
    }

    /// The same with another scale.
    pub fn with_scale(mut self, scale: f64) -> Self {
        self.scale = scale;
        self
    }

    /// The same with another offset.
    pub fn with_offset(mut self, offset: [f64; 2]) -> Self {
        self.offset = offset;
        self
    }

    /// The vertex target actually used: `vertices` clamped to `3..=100_000`.
    pub fn target(&self) -> usize {
        self.vertices.clamp(3, 100_000)
    }

    /// The scale actually used: the power of two nearest to `scale` (1 when `scale` is not
    /// a positive finite number), so that scaling is exact.
    pub fn effective_scale(&self) -> f64 {
        if !(self.scale.is_finite() && self.scale > 0.0) {
            return 1.0;
        }
        // Keep step = scale · 2^-20 and the grid's largest coordinate normal and finite.
        let exponent = self.scale.log2().round().clamp(-1000.0, 1000.0) as i32;
        pow2(exponent)
    }

    /// The distance between neighbouring grid points: `effective_scale · 2^-20`.
    pub fn step(&self) -> f64 {
        self.effective_scale() * pow2(-GRID_BITS)
    }

    /// The offset actually used, in grid steps: `offset / step`, rounded (0 when not
    /// finite).
    fn offset_steps(&self) -> [f64; 2] {
        let step = self.step();
        self.offset.map(|o| {
            let steps = (o / step).round();
            if steps.is_finite() {
                steps
            } else {
                0.0
            }
        })
    }

    /// Whether every coordinate is exactly the grid point's scaled and offset image, so
    /// that validity by construction holds: `|offset| / step + 2^20 ≤ 2^53`.
    pub fn is_exact(&self) -> bool {
        self.offset_steps()
            .iter()
            .all(|s| s.abs() + GRID as f64 <= pow2(53))
    }

    /// Grid point `p` in case coordinates.
    fn place(&self, p: [i64; 2], steps: [f64; 2], step: f64) -> [f64; 2] {
        // `p + steps` is an integer below 2^53 when `is_exact`, and `step` a power of two:
        // both operations are exact.
        [
            (p[0] as f64 + steps[0]) * step,
            (p[1] as f64 + steps[1]) * step,
        ]
    }
}

/// `2^e` for `-1022 <= e <= 1023`, exactly.
fn pow2(e: i32) -> f64 {
    f64::from_bits(((e + 1023).clamp(1, 2046) as u64) << 52)
}

/// What a family's generator hands back: rings on the integer grid and a description.
struct Shape {
    rings: Vec<Ring>,
    description: String,
}

/// A seeded random case of `family` with about `params.vertices` vertices.
///
/// Deterministic: the same family, seed and params always give the same case. Nesting is
/// [`Nesting::Auto`]: ring order and windings are part of the randomness.
pub fn generate(family: Family, seed: u64, params: &Params) -> Case {
    let mut rng = Rng::new(seed ^ family_salt(family));
    let n = params.target();
    let shape = shape(family, &mut rng, n);
    let input = place(shape.rings, &mut rng, params);
    debug_assert!(
        input.vertices.len() > 2000 || !params.is_exact() || {
            let checked = validate(&input, family.allows_touching());
            if let Err(e) = &checked {
                eprintln!("{family} seed {seed} size {n}: {e}");
            }
            checked.is_ok()
        },
        "generator {family} made an invalid case (seed {seed}, {n} vertices)"
    );
    Case {
        name: format!("{family}-{seed}-{n}"),
        family: Some(family),
        seed: Some(seed),
        description: format!("{}: {}", family.describe(), shape.description),
        source: "polytri-oracle generator".to_string(),
        input,
        expect: None,
    }
}

/// The rings of a seeded case of `family` with about `vertices` vertices, on the integer
/// grid, in the order and winding the generator made them: like [`generate`] but without
/// its 100,000-vertex clamp, for the benchmark series ([`crate::series`]) that go to 10⁶.
/// Only for families whose generator is near-linear (not [`Family::TwoOpt`]).
pub(crate) fn grid_rings(family: Family, seed: u64, vertices: usize) -> Vec<Vec<[f64; 2]>> {
    let mut rng = Rng::new(seed ^ family_salt(family));
    shape(family, &mut rng, vertices.max(3))
        .rings
        .into_iter()
        .map(|ring| ring.iter().map(|&[x, y]| [x as f64, y as f64]).collect())
        .collect()
}

/// What `family`'s generator makes of `rng` at about `n` vertices.
fn shape(family: Family, rng: &mut Rng, n: usize) -> Shape {
    match family {
        Family::Star => random_polygons::star(rng, n),
        Family::SpacePartition => random_polygons::space_partition(rng, n),
        Family::TwoOpt => random_polygons::two_opt(rng, n),
        Family::Orthogonal => outlines::orthogonal(rng, n),
        Family::Circles => holes::circles(rng, n),
        Family::Comb => outlines::comb(rng, n),
        Family::Spiral => outlines::spiral(rng, n),
        Family::ManyHoles => holes::many_holes(rng, n),
        Family::TouchingHoles => holes::touching_holes(rng, n),
        Family::NestedIslands => holes::nested_islands(rng, n),
        Family::Slivers => outlines::slivers(rng, n),
        Family::FontLike => holes::font_like(rng, n),
    }
}

/// Separates the families' random streams, so that seed 0 of two families is unrelated.
fn family_salt(family: Family) -> u64 {
    let index = Family::ALL.iter().position(|&f| f == family).unwrap_or(0) as u64;
    (index + 1).wrapping_mul(0x9e37_79b9_7f4a_7c15)
}

/// Rotates every ring's start, reverses some windings, and maps the grid to case
/// coordinates.
fn place(rings: Vec<Ring>, rng: &mut Rng, params: &Params) -> Input {
    let step = params.step();
    let steps = params.offset_steps();
    let rings: Vec<Vec<[f64; 2]>> = rings
        .into_iter()
        .filter(|ring| !ring.is_empty())
        .map(|mut ring| {
            // The triangulator assumes no winding and no start vertex: vary both.
            let start = rng.below(ring.len());
            ring.rotate_left(start);
            if rng.chance(0.5) {
                ring.reverse();
            }
            ring.iter().map(|&p| params.place(p, steps, step)).collect()
        })
        .collect();
    Input::from_rings(&rings, Nesting::Auto)
}
