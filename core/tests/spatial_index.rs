//! Inputs shaped to exercise the spatial indexes behind nesting, bridging and the ear test:
//! many holes (ear tests ask the reflex grid, ray casts walk the edge grid), islands in
//! holes (depths read off the nearest edge), reflex vertices on one line and extents that
//! overflow `f64` (the grids degenerate to one row or column). Every result goes through
//! the exact checker and the triangle count `n − 2·polygons + 2·holes`.

mod common;

use common::{check, check_with_roles, first_is_outer, flatten, rotate, to_f32, widen, Rings};
use polytri::{Options, Strategy, Triangulator};

const STRATEGIES: [Strategy; 2] = [Strategy::Fast, Strategy::Quality];

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

/// Triangulates in f64 and f32 with both strategies; checks every result exactly.
fn check_all(rings: &Rings, polygons: usize, holes: usize, tag: &str) {
    let flat = flatten(rings);
    let roles = first_is_outer(flat.rings.len());
    let want = flat.vertices.len() - 2 * polygons + 2 * holes;
    for strategy in STRATEGIES {
        let opts = Options::default().with_strategy(strategy);
        let mut out = Vec::new();
        let mut tri = Triangulator::<f64>::new();
        tri.triangulate(&flat.vertices, &flat.ring_starts, &opts, &mut out)
            .unwrap_or_else(|e| panic!("{tag} {strategy:?} f64: {e}"));
        check_with_roles(&flat.vertices, &flat.rings, &roles, &out)
            .unwrap_or_else(|e| panic!("{tag} {strategy:?} f64: {e}"));
        assert_eq!(out.len(), want, "{tag} {strategy:?} f64");

        let v32 = to_f32(&flat.vertices);
        let mut tri = Triangulator::<f32>::new();
        tri.triangulate(&v32, &flat.ring_starts, &opts, &mut out)
            .unwrap_or_else(|e| panic!("{tag} {strategy:?} f32: {e}"));
        check_with_roles(&widen(&v32), &flat.rings, &roles, &out)
            .unwrap_or_else(|e| panic!("{tag} {strategy:?} f32: {e}"));
        assert_eq!(out.len(), want, "{tag} {strategy:?} f32");
    }
}

#[test]
fn many_circular_holes_in_every_rotation() {
    let rings = holes_grid(14, 9, 20, 0x5eed_0001);
    for k in 0..4 {
        check_all(
            &rotate(&rings, k),
            1,
            rings.len() - 1,
            &format!("rotation {k}"),
        );
    }
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
    for k in 0..4 {
        check_all(
            &rotate(&rings, k),
            1,
            rings.len() - 1,
            &format!("rotation {k}"),
        );
    }
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
    let flat = flatten(&rings);
    let (polygons, holes) = (60, 60);
    let want = flat.vertices.len() - 2 * polygons + 2 * holes;
    for k in 0..4 {
        let flat = flatten(&rotate(&rings, k));
        for strategy in STRATEGIES {
            let opts = Options::default().with_strategy(strategy);
            let mut out = Vec::new();
            let report = Triangulator::<f64>::new()
                .triangulate(&flat.vertices, &flat.ring_starts, &opts, &mut out)
                .map(|r| (r.polygons, r.holes))
                .unwrap_or_else(|e| panic!("rotation {k} {strategy:?}: {e}"));
            assert_eq!(report, (polygons, holes), "rotation {k} {strategy:?}");
            check(&flat.vertices, &flat.rings, &out)
                .unwrap_or_else(|e| panic!("rotation {k} {strategy:?}: {e}"));
            assert_eq!(out.len(), want, "rotation {k} {strategy:?}");
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
    for k in 0..4 {
        check_all(&rotate(&[ring.clone()], k), 1, 0, &format!("rotation {k}"));
    }
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
    for k in 0..4 {
        check_all(
            &rotate(&rings, k),
            1,
            rings.len() - 1,
            &format!("rotation {k}"),
        );
    }
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
    check_all(&huge, 1, huge.len() - 1, "huge");
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
    let flat = flatten(&huge);
    for strategy in STRATEGIES {
        for lenient in [false, true] {
            let opts = Options::default()
                .with_strategy(strategy)
                .with_lenient(lenient);
            let mut out = Vec::new();
            let _ = Triangulator::<f64>::new().triangulate(
                &flat.vertices,
                &flat.ring_starts,
                &opts,
                &mut out,
            );
        }
    }
}
