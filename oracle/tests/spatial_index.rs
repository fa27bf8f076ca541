//! Inputs shaped to exercise the spatial indexes behind nesting, bridging and the ear test:
//! many holes (ear tests ask the reflex grid, ray casts walk the edge grid), islands in
//! holes (depths read off the nearest edge), reflex vertices on one line and extents that
//! overflow `f64` (the grids degenerate to one row or column). Every result goes through
//! the oracle's exact checks and the triangle count `n − 2·polygons + 2·holes`.

mod common;

use common::triangulate;
use polytri::{Options, Strategy, Triangulator};
use polytri_oracle::replay::{rotate, Precision, ROTATIONS};
use polytri_oracle::{check_with, CheckOptions, Input, Nesting};

const STRATEGIES: [Strategy; 2] = [Strategy::Fast, Strategy::Quality];

type Rings = Vec<Vec<[f64; 2]>>;

/// A `cols` × `rows` grid of `sides`-gon holes in a rectangle, jittered by a seeded
/// xorshift inside their cells so that no two meet.
fn holes_grid(cols: usize, rows: usize, sides: usize, seed: u64) -> Rings {
    let mut state = seed;
    let mut random = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let cell = 16.0;
    let (w, h) = (cols as f64 * cell, rows as f64 * cell);
    let mut rings = vec![vec![[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]]];
    for j in 0..rows {
        for i in 0..cols {
            let r = cell * (0.15 + 0.2 * random());
            let slack = cell / 2.0 - r - 1.0;
            let cx = (i as f64 + 0.5) * cell + slack * (2.0 * random() - 1.0);
            let cy = (j as f64 + 0.5) * cell + slack * (2.0 * random() - 1.0);
            // round to 1/64: exact in f32 too, so both precisions see the same shape
            let round = |v: f64| (v * 64.0).round() / 64.0;
            let phase = random();
            rings.push(
                (0..sides)
                    .map(|s| {
                        let a = (phase + s as f64) * std::f64::consts::TAU / sides as f64;
                        [round(cx + r * a.cos()), round(cy + r * a.sin())]
                    })
                    .collect(),
            );
        }
    }
    rings
}

/// Triangulates in f64 and f32 with both strategies (automatic nesting); the oracle judges
/// every result with the first ring outer and the rest holes.
fn check_all(input: &Input, polygons: usize, holes: usize, tag: &str) {
    let want = input.vertices.len() - 2 * polygons + 2 * holes;
    for strategy in STRATEGIES {
        let opts = Options::default().with_strategy(strategy);
        for precision in Precision::ALL {
            let tag = format!("{tag} {strategy:?} {precision}");
            let run = triangulate(input, &opts, precision).unwrap_or_else(|e| panic!("{tag}: {e}"));
            let seen = common::seen(input, precision);
            let verdict = check_with(&seen, &run.triangles, &CheckOptions::fast());
            assert!(verdict.valid, "{tag}: {:?}", verdict.failures());
            assert_eq!(run.triangles.len(), want, "{tag}");
        }
    }
}

/// `rings`, first ring outer, in every exact rotation through [`check_all`].
fn check_rotations(rings: &[Vec<[f64; 2]>], polygons: usize, holes: usize) {
    let input = Input::from_rings(rings, Nesting::FirstIsOuter);
    for rotation in ROTATIONS {
        let tag = format!("rotation {rotation}");
        check_all(&rotate(&input, rotation), polygons, holes, &tag);
    }
}

#[test]
fn many_circular_holes_in_every_rotation() {
    let rings = holes_grid(14, 9, 20, 0x5eed_0001);
    check_rotations(&rings, 1, rings.len() - 1);
}

#[test]
fn many_square_holes_share_rows_and_columns() {
    // aligned holes: ray casts run along rows of vertices and hit vertices exactly
    let mut rings: Rings = vec![vec![[0.0, 0.0], [200.0, 0.0], [200.0, 120.0], [0.0, 120.0]]];
    for j in 0..12 {
        for i in 0..20 {
            let (x, y) = (i as f64 * 10.0 + 3.0, j as f64 * 10.0 + 3.0);
            rings.push(vec![[x, y], [x, y + 4.0], [x + 4.0, y + 4.0], [x + 4.0, y]]);
        }
    }
    check_rotations(&rings, 1, rings.len() - 1);
}

#[test]
fn islands_in_holes_nest_by_the_nearest_edge() {
    // squares nested four deep, side by side: outer, hole, island, hole in the island
    let mut rings: Rings = Vec::new();
    for i in 0..30 {
        let x = i as f64 * 20.0;
        for (d, inset) in [0.0, 2.0, 4.0, 6.0].into_iter().enumerate() {
            let (a, b) = (x + inset, x + 16.0 - inset);
            let (c, e) = (inset + d as f64 * 0.25, 16.0 - inset);
            rings.push(vec![[a, c], [b, c], [b, e], [a, e]]);
        }
    }
    // Judged with roles by containment depth, what automatic nesting promises.
    let input = Input::from_rings(&rings, Nesting::Auto);
    let (polygons, holes) = (60, 60);
    let want = input.vertices.len() - 2 * polygons + 2 * holes;
    for rotation in ROTATIONS {
        let input = rotate(&input, rotation);
        for strategy in STRATEGIES {
            let tag = format!("rotation {rotation} {strategy:?}");
            let opts = Options::default().with_strategy(strategy);
            let mut out = Vec::new();
            let report = Triangulator::<f64>::new()
                .triangulate(&input.vertices, &input.ring_starts, &opts, &mut out)
                .map(|r| (r.polygons, r.holes))
                .unwrap_or_else(|e| panic!("{tag}: {e}"));
            assert_eq!(report, (polygons, holes), "{tag}");
            let verdict = check_with(&input, &out, &CheckOptions::fast());
            assert!(verdict.valid, "{tag}: {:?}", verdict.failures());
            assert_eq!(out.len(), want, "{tag}");
        }
    }
}

#[test]
fn comb_with_reflex_vertices_on_one_line() {
    // every reflex vertex at y = 0: the reflex grid has a single row
    let teeth = 120;
    let mut ring = vec![[0.0, -10.0], [teeth as f64 * 2.0, -10.0]];
    for t in (0..teeth).rev() {
        let x = t as f64 * 2.0;
        ring.extend([[x + 2.0, 0.0], [x + 1.0, 8.0]]);
    }
    ring.push([0.0, 0.0]);
    check_rotations(&[ring], 1, 0);
}

#[test]
fn long_teeth_with_holes() {
    // long thin edges (listed per row or column, not per cell) next to small holes
    let teeth = 60;
    let mut outer = vec![[0.0, 0.0]];
    for t in 0..teeth {
        let y = 2.0 * t as f64;
        outer.extend([[1000.0, y], [1000.0, y + 1.0]]);
        if t + 1 < teeth {
            outer.extend([[2.0, y + 1.0], [2.0, y + 2.0]]);
        }
    }
    outer.push([0.0, 2.0 * teeth as f64 - 1.0]);
    let mut rings = vec![outer];
    for t in 0..teeth {
        for k in 0..6 {
            let (x, y) = (10.0 + 150.0 * k as f64 + t as f64, 2.0 * t as f64);
            rings.push(vec![
                [x + 0.25, y + 0.25],
                [x + 0.75, y + 0.25],
                [x + 0.75, y + 0.75],
                [x + 0.25, y + 0.75],
            ]);
        }
    }
    check_rotations(&rings, 1, rings.len() - 1);
}

#[test]
fn huge_coordinates_still_triangulate() {
    // far from the origin and huge (still exact in f32, and far from overflowing the
    // determinants): the grids scale to the extents
    let rings = holes_grid(6, 4, 12, 0x5eed_0002);
    let scale = 2f64.powi(100);
    let offset = 2f64.powi(110);
    let huge: Rings = rings
        .iter()
        .map(|r| {
            r.iter()
                .map(|&[x, y]| [x * scale - offset, y * scale + offset])
                .collect()
        })
        .collect();
    let input = Input::from_rings(&huge, Nesting::FirstIsOuter);
    check_all(&input, 1, huge.len() - 1, "huge");
}

#[test]
fn extents_overflowing_f64_do_not_panic() {
    // coordinates near ±f64::MAX: widths and heights overflow to infinity and the grids
    // fall back to one row and column. (Determinants overflow too, so no triangulation is
    // promised here; only an answer.)
    let rings = holes_grid(6, 4, 12, 0x5eed_0003);
    let scale = f64::MAX / 64.0;
    let huge: Rings = rings
        .iter()
        .map(|r| {
            r.iter()
                .map(|&[x, y]| [(x - 48.0) * scale, (y - 32.0) * scale])
                .collect()
        })
        .collect();
    let input = Input::from_rings(&huge, Nesting::Auto);
    for strategy in STRATEGIES {
        for lenient in [false, true] {
            let opts = Options::default()
                .with_strategy(strategy)
                .with_lenient(lenient);
            let mut out = Vec::new();
            let _ = Triangulator::<f64>::new().triangulate(
                &input.vertices,
                &input.ring_starts,
                &opts,
                &mut out,
            );
        }
    }
}
