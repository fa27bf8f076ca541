//! The small stage (one polygon of at most 128 nodes, holes and their bridges' copies
//! counted, either strategy; a narrow form up to 64 nodes, a wide one beyond) must give
//! exactly what the whole pipeline gives: the same triangles in the same order, the same
//! report (dropped vertices, repairs, deviation to the bit) and the same errors — where it
//! takes the input and where it hands it back. Each input runs twice, with the stage and
//! without (`Triangulator::set_small_rings`), on random rings built to hit every branch:
//! valid rings in both windings, repeated and straight vertices, closing points, spikes,
//! rings that cross or touch themselves, non-finite coordinates; polygons with holes,
//! nested otherwise or touching; the glyph datasets and the corpus; f64 and f32, strict
//! and lenient.

use polytri::{Coord, Dropped, Error, Nesting, Options, Repair, Strategy, Triangulator};

/// What one call gives, owned.
#[derive(Debug, PartialEq)]
struct Outcome {
    triangles: Vec<[u32; 3]>,
    polygons: usize,
    holes: usize,
    deviation: u64,
    dropped: Vec<Dropped>,
    repairs: Vec<Repair>,
}

fn run<T: Coord>(
    tri: &mut Triangulator<T>,
    vertices: &[[T; 2]],
    starts: &[usize],
    opts: &Options,
) -> Result<Outcome, Error> {
    let mut out = Vec::new();
    let report = tri.triangulate(vertices, starts, opts, &mut out)?;
    Ok(Outcome {
        polygons: report.polygons,
        holes: report.holes,
        deviation: report.deviation.to_bits(),
        dropped: report.dropped.to_vec(),
        repairs: report.repairs.to_vec(),
        triangles: out,
    })
}

/// xorshift64*, seeded: the same rings on every run.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A ring of `n` vertices: star-shaped around the origin (angles rising, radii random),
/// snapped to a grid of `grid` steps, which makes repeated and straight vertices and
/// sometimes crossings; then some of the defects the pipeline treats specially. Says
/// whether it added one that leaves no simple ring (the stage handles closing points,
/// repeated and straight vertices itself).
fn ring(rng: &mut Rng, n: usize, grid: f64) -> (Vec<[f64; 2]>, bool) {
    // one angle in each of n equal sectors, away from its edges: consecutive vertices
    // are less than a half-turn apart round the origin (for n > 3), so the ring winds
    // round it once without crossing itself (before snapping)
    let sector = core::f64::consts::TAU / n as f64;
    let mut v: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let a = (k as f64 + 0.1 + 0.8 * rng.unit()) * sector;
            let r = 0.2 + 0.8 * rng.unit();
            [(r * a.cos() * grid).round(), (r * a.sin() * grid).round()]
        })
        .collect();
    if rng.below(2) == 0 {
        v.reverse();
    }
    let k = rng.below(n);
    v.rotate_left(k);
    // defects, each now and then
    let defect = rng.below(12);
    match defect {
        0 => v.push(v[0]), // a closing point
        1 => {
            let i = rng.below(v.len());
            v.insert(i, v[i]); // a repeated vertex
        }
        2 => {
            // a straight vertex halfway along an edge (where that is a grid point)
            let i = rng.below(v.len());
            let (a, b) = (v[i], v[(i + 1) % v.len()]);
            v.insert(
                i + 1,
                [((a[0] + b[0]) / 2.0).floor(), ((a[1] + b[1]) / 2.0).floor()],
            );
        }
        3 => {
            // a spike: out from a vertex and straight back
            let i = rng.below(v.len());
            let a = v[i];
            v.insert(i + 1, [a[0] * 1.5, a[1] * 1.5]);
            v.insert(i + 2, a);
        }
        4 if v.len() > 3 => {
            // two vertices swapped: usually a crossing
            let (i, j) = (rng.below(v.len()), rng.below(v.len()));
            v.swap(i, j);
        }
        5 => {
            // a vertex moved onto another's position: the ring touches itself
            let (i, j) = (rng.below(v.len()), rng.below(v.len()));
            v[i] = v[j];
        }
        6 => {
            let i = rng.below(v.len());
            v[i][rng.below(2)] = [f64::NAN, f64::INFINITY][rng.below(2)];
        }
        7 => {
            // a coordinate beyond the exact range of the signs (2^-480 to 2^500), or the
            // whole ring scaled there (a ring of 1e300 or 1e-300, an f32 of 0 or infinity)
            let scale = [1e300, 1e-300, 1e-200][rng.below(3)];
            if rng.below(2) == 0 {
                let i = rng.below(v.len());
                v[i][rng.below(2)] *= scale;
            } else {
                v.iter_mut().flatten().for_each(|c| *c *= scale);
            }
        }
        _ => {}
    }
    (v, (3..=7).contains(&defect))
}

/// Of the four runs of [`compare_rings`] (two strategies, strict and lenient), how many
/// the stage takes on a valid polygon of `nodes` nodes: all up to 128, none beyond.
fn runs_taken(nodes: usize) -> usize {
    match nodes {
        0..=128 => 4,
        _ => 0,
    }
}

/// `p` turned `turn` quarter turns counter-clockwise round the origin (exactly).
fn turned([x, y]: [f64; 2], turn: usize) -> [f64; 2] {
    match turn % 4 {
        0 => [x, y],
        1 => [-y, x],
        2 => [-x, -y],
        _ => [y, -x],
    }
}

/// The rings one after the other: their vertices and where each starts.
fn flattened(rings: impl IntoIterator<Item = Vec<[f64; 2]>>) -> (Vec<[f64; 2]>, Vec<usize>) {
    let (mut vertices, mut starts) = (Vec::new(), Vec::new());
    for ring in rings {
        starts.push(vertices.len());
        vertices.extend(ring);
    }
    (vertices, starts)
}

/// The square of side `10 n` from the origin, with a vertex every 10 along each side.
fn grid_square(n: usize) -> Vec<[f64; 2]> {
    let side = 10.0 * n as f64;
    let steps = (0..n).map(|k| 10.0 * k as f64);
    let bottom = steps.clone().map(|t| [t, 0.0]);
    let right = steps.clone().map(|t| [side, t]);
    let top = steps.clone().map(|t| [side - t, side]);
    let left = steps.map(|t| [0.0, side - t]);
    bottom.chain(right).chain(top).chain(left).collect()
}

/// The pairs of triangulators of [`pair`], in f64 and in f32 (only f64 coordinates: the
/// f32 ones are converted).
type Precisions = (
    (Triangulator<f64>, Triangulator<f64>),
    (Triangulator<f32>, Triangulator<f32>),
);

/// Runs `rings` (the outer one first) with each ring either way round, in one quarter
/// turn, nested both ways (the outer ring first for `FirstIsOuter`, anywhere for
/// `Auto`), in f64 and f32: the stage must give what the pipeline gives. Returns in how
/// many of the two nestings the stage took all four f64 runs (both strategies, strict
/// and lenient).
fn shuffled_agree(
    ((with64, without64), (with32, without32)): &mut Precisions,
    rng: &mut Rng,
    mut rings: Vec<Vec<[f64; 2]>>,
    tag: &str,
) -> usize {
    for ring in rings.iter_mut() {
        if rng.below(2) == 0 {
            ring.reverse();
        }
    }
    let turn = rng.below(4);
    let k = rng.below(rings.len());
    let mut taken = 0;
    for (nesting, first) in [(Nesting::FirstIsOuter, 0), (Nesting::Auto, k)] {
        let mut order = rings.clone();
        order.swap(0, first);
        let (vertices, starts) = flattened(
            order
                .iter()
                .map(|r| r.iter().map(|&p| turned(p, turn)).collect()),
        );
        let (_, took) = compare_rings(with64, without64, &vertices, &starts, nesting, tag);
        let v32: Vec<[f32; 2]> = (vertices.iter())
            .map(|p| [p[0] as f32, p[1] as f32])
            .collect();
        compare_rings(with32, without32, &v32, &starts, nesting, tag);
        taken += usize::from(took == 4);
    }
    taken
}

/// Two triangulators: one that may take the small stage, one that never does.
fn pair<T: Coord>() -> (Triangulator<T>, Triangulator<T>) {
    let mut without = Triangulator::new();
    without.set_small_rings(false);
    (Triangulator::new(), without)
}

/// Runs `vertices` both ways, with both strategies, strict and lenient, and checks both
/// ways agree; returns how many of the four runs gave triangles, and how many of those
/// the stage made alone.
fn compare<T: Coord + core::fmt::Debug>(
    with: &mut Triangulator<T>,
    without: &mut Triangulator<T>,
    vertices: &[[T; 2]],
    tag: &str,
) -> (usize, usize) {
    // (one ring: both conventions make it the outer boundary; each call flips which)
    let nesting = [Nesting::Auto, Nesting::FirstIsOuter][vertices.len() % 2];
    compare_rings(with, without, vertices, &[0], nesting, tag)
}

/// [`compare`] for rings starting at `starts`, nested by `nesting`.
fn compare_rings<T: Coord + core::fmt::Debug>(
    with: &mut Triangulator<T>,
    without: &mut Triangulator<T>,
    vertices: &[[T; 2]],
    starts: &[usize],
    nesting: Nesting,
    tag: &str,
) -> (usize, usize) {
    let (mut ok, mut took) = (0, 0);
    for strategy in [Strategy::Fast, Strategy::Quality] {
        for lenient in [false, true] {
            let opts = Options::default()
                .with_strategy(strategy)
                .with_nesting(nesting)
                .with_lenient(lenient);
            let (a, b) = (
                run(with, vertices, starts, &opts),
                run(without, vertices, starts, &opts),
            );
            assert!(!without.small_ring_took_last());
            // (lenient mode reading rings by even–odd ran the fill rule's way last, which
            // may take the stage whatever the first run did)
            let read_even_odd = a.as_ref().is_ok_and(|a| {
                (a.repairs.iter()).any(|r| r.kind == polytri::RepairKind::ReadEvenOdd)
            });
            took += usize::from(with.small_ring_took_last() && !read_even_odd);
            assert_eq!(
                a, b,
                "{tag}, {strategy:?}, lenient {lenient}, {nesting:?}: {vertices:?} {starts:?}"
            );
            ok += usize::from(a.is_ok());
        }
    }
    assert_eq!(
        with.check(vertices, starts, nesting),
        without.check(vertices, starts, nesting),
        "{tag}, check, {nesting:?}: {vertices:?} {starts:?}"
    );
    (ok, took)
}

#[test]
fn the_small_ring_stage_gives_what_the_pipeline_gives() {
    let mut rng = Rng(0x5eed_5a11);
    let (mut with64, mut without64) = pair::<f64>();
    let (mut with32, mut without32) = pair::<f32>();
    let (mut triangulated, mut taken, mut clean) = (0, 0, 0);
    for case in 0..4000 {
        // up to 132 vertices with defects: both forms of the stage (up to 64 nodes, up
        // to 128), and past its limit
        let n = 3 + rng.below(127);
        let grid = [4.0, 12.0, 100.0, 1e4, 1e9][rng.below(5)];
        let (v, defect) = ring(&mut rng, n, grid);
        let tag = format!("case {case}");
        let (ok, took) = compare(&mut with64, &mut without64, &v, &tag);
        // f32 rounds the larger grids: other repeats and crossings
        let v32: Vec<[f32; 2]> = v.iter().map(|p| [p[0] as f32, p[1] as f32]).collect();
        let (ok32, took32) = compare(&mut with32, &mut without32, &v32, &tag);
        (triangulated, taken) = (triangulated + ok + ok32, taken + took + took32);
        if !defect && grid == 1e9 && v.len() <= 128 {
            // simple (a star on a fine grid), at most repeated or straight vertices: the
            // stage's own case
            assert_eq!(took, runs_taken(v.len()), "{tag}: the stage declined {v:?}");
            clean += 1;
        }
    }
    // most rings are valid or repaired, most of those the stage's: the comparison is
    // neither all errors nor all hand-backs
    assert!(
        triangulated > 16000 && taken > 8000 && clean > 200,
        "{triangulated} {taken} {clean}"
    );
}

/// Valid rings on a coarse grid, where ear triangles and reflex vertices often share an x
/// or a y (a vertex on the edge of an ear's box): the bottom of a box and a top of random
/// heights, stepped or straight from one column to the next, in both windings, from any
/// vertex.
#[test]
fn histograms_agree_and_take_the_stage() {
    let mut rng = Rng(0x0415_7e57);
    let (mut with, mut without) = pair::<f64>();
    for case in 0..3000 {
        let columns = 1 + rng.below(64);
        let stepped = rng.below(2) == 0;
        let mut v = vec![[0.0, 0.0], [columns as f64, 0.0]];
        for i in (0..columns).rev() {
            let h = 1.0 + rng.below(6) as f64;
            if stepped {
                v.push([(i + 1) as f64, h]);
            }
            v.push([i as f64, h]);
        }
        if rng.below(2) == 0 {
            v.reverse();
        }
        let k = rng.below(v.len());
        v.rotate_left(k);
        let tag = format!("histogram {case}");
        let (ok, took) = compare(&mut with, &mut without, &v, &tag);
        if v.len() <= 128 {
            assert_eq!((ok, took), (4, runs_taken(v.len())), "{tag}: {v:?}");
        }
    }
}

/// Tiny rings on a tiny grid: nearly every ring is degenerate, touching or crossing, so
/// this covers the hand-backs (and the rare valid ring of a few vertices).
#[test]
fn tiny_rings_on_a_tiny_grid_agree() {
    let mut rng = Rng(0x0007_1e57);
    let (mut with, mut without) = pair::<f64>();
    for case in 0..20000 {
        let n = 3 + rng.below(6);
        let v: Vec<[f64; 2]> = (0..n)
            .map(|_| [rng.below(4) as f64, rng.below(4) as f64])
            .collect();
        compare(&mut with, &mut without, &v, &format!("tiny {case}"));
    }
}

/// A polygon with holes: an outer star ring of radius about `grid` round the origin and
/// up to `holes` small star rings in the cells of a 3 × 3 block inside it, snapped to the
/// grid (which makes repeated and straight vertices, and on coarse grids touches and
/// crossings); now and then a defect: a hole moved onto the outer ring, out of it, or
/// inside another hole, and the rings in any order (the outer one not first). Returns the
/// vertices, the ring starts, and for a polygon the stage should take (an outer ring
/// first, holes inside it, no defect, a fine grid) how many runs it takes
/// ([`runs_taken`]).
fn holed(rng: &mut Rng, holes: usize, grid: f64) -> (Vec<[f64; 2]>, Vec<usize>, Option<usize>) {
    let scaled = |ring: Vec<[f64; 2]>, scale: f64, at: [f64; 2]| -> Vec<[f64; 2]> {
        let g = grid / 1e9;
        (ring.iter())
            .map(|p| {
                let q = [p[0] / 1e9 * scale + at[0], p[1] / 1e9 * scale + at[1]];
                [(q[0] / g).round() * g, (q[1] / g).round() * g]
            })
            .collect()
    };
    // a star of radii 0.2–1 (rounded to 1e-9): the outer one, radii pushed out to 0.8–1
    let star = |rng: &mut Rng, n: usize| loop {
        let (v, defect) = ring(rng, n, 1e9);
        if !defect && v.len() == n {
            break v;
        }
    };
    let n = 8 + rng.below(80);
    let outer: Vec<[f64; 2]> = star(rng, n)
        .iter()
        .map(|p| {
            let r = (p[0] * p[0] + p[1] * p[1]).sqrt();
            let k = (0.8 + 0.2 * (r / 1e9 - 0.2) / 0.8) / (r / 1e9);
            [p[0] * k, p[1] * k]
        })
        .collect();
    let mut rings = vec![scaled(outer, grid, [0.0, 0.0])];
    let mut cells: Vec<usize> = (0..9).collect();
    for _ in 0..holes {
        let cell = cells.swap_remove(rng.below(cells.len()));
        let at = [
            ((cell % 3) as f64 - 1.0) * 0.35 * grid,
            ((cell / 3) as f64 - 1.0) * 0.35 * grid,
        ];
        let m = 3 + rng.below(6);
        rings.push(scaled(star(rng, m), 0.16 * grid, at));
    }
    let mut takes = grid >= 1e4;
    if rings.len() > 1 {
        match rng.below(10) {
            0 => {
                // a hole moved onto the outer ring's first vertex
                let (h, o) = (1 + rng.below(rings.len() - 1), rings[0][0]);
                let d = [o[0] - rings[h][0][0], o[1] - rings[h][0][1]];
                for p in &mut rings[h] {
                    *p = [p[0] + d[0], p[1] + d[1]];
                }
                takes = false;
            }
            1 => {
                // a hole moved out of the polygon
                let h = 1 + rng.below(rings.len() - 1);
                for p in &mut rings[h] {
                    p[0] += 3.0 * grid;
                }
                takes = false;
            }
            2 => {
                // a hole inside another, scaled down round its centre
                let h = 1 + rng.below(rings.len() - 1);
                let mut inner = rings[h].clone();
                let c = [
                    inner.iter().map(|p| p[0]).sum::<f64>() / inner.len() as f64,
                    inner.iter().map(|p| p[1]).sum::<f64>() / inner.len() as f64,
                ];
                for p in &mut inner {
                    *p = [c[0] + (p[0] - c[0]) * 0.1, c[1] + (p[1] - c[1]) * 0.1];
                }
                rings.push(inner);
                takes = false;
            }
            3 => {
                // the rings in another order: Auto nesting still finds the outer one
                let k = rng.below(rings.len());
                rings.swap(0, k);
                takes &= k == 0;
            }
            _ => {}
        }
    }
    let mut vertices = Vec::new();
    let mut starts = Vec::new();
    for r in &rings {
        starts.push(vertices.len());
        vertices.extend_from_slice(r);
    }
    let nodes = vertices.len() + 2 * (rings.len() - 1);
    (vertices, starts, takes.then_some(runs_taken(nodes)))
}

#[test]
fn polygons_with_holes_agree_and_take_the_stage() {
    let mut rng = Rng(0x4013_5eed);
    let (mut with64, mut without64) = pair::<f64>();
    let (mut with32, mut without32) = pair::<f32>();
    let (mut taken, mut expected) = (0, 0);
    for case in 0..3000 {
        let holes = 1 + rng.below(5);
        let grid = [8.0, 30.0, 1e4, 1e6][rng.below(4)];
        let (v, starts, takes) = holed(&mut rng, holes, grid);
        for nesting in [Nesting::Auto, Nesting::FirstIsOuter] {
            let tag = format!("holed {case}");
            let (_, took) = compare_rings(&mut with64, &mut without64, &v, &starts, nesting, &tag);
            let v32: Vec<[f32; 2]> = v.iter().map(|p| [p[0] as f32, p[1] as f32]).collect();
            compare_rings(&mut with32, &mut without32, &v32, &starts, nesting, &tag);
            if let Some(runs) = takes {
                assert_eq!(
                    took, runs,
                    "{tag}, {nesting:?}: the stage declined {v:?} {starts:?}"
                );
                expected += 1;
            }
            taken += took;
        }
    }
    assert!(expected > 1000 && taken > 8000, "{expected} {taken}");
}

/// Holes touching the outer ring and each other at vertices: an n × n grid of 10 × 10
/// cells in a square whose ring has a vertex at every cell corner on its sides (straight
/// ones, which the filter drops: the holes touch inside its edges then); in a cell, maybe
/// a triangular hole from its lower left corner (on the outer ring, or another hole's
/// corner) through a point inside to its upper right corner, now and then pulled off the
/// corner, and always where that lies on the outer ring (a hole touching it twice would
/// cut the polygon in two). So the holes touch in chains, each touching the outer ring
/// at most once: one polygon, which the stage takes in strict mode. The rings in any order
/// and winding, in four rotations.
#[test]
fn holes_touching_at_vertices_agree_and_take_the_stage() {
    let mut rng = Rng(0x70c4_5eed);
    let mut both = (pair(), pair());
    let (mut cases, mut taken) = (0, 0);
    for case in 0..2000 {
        let n = 2 + rng.below(2);
        let side = 10.0 * n as f64;
        let mut rings = vec![grid_square(n)];
        for cell in 0..n * n {
            if rng.below(10) < 3 {
                continue;
            }
            let (x, y) = ((cell % n) as f64 * 10.0, (cell / n) as f64 * 10.0);
            let a = 3.0 + rng.below(5) as f64;
            // (on the outer ring, the hole would touch it twice, and cut the polygon)
            let end = if x + 10.0 == side || y + 10.0 == side || rng.below(3) == 0 {
                [x + 9.5, y + 9.75]
            } else {
                [x + 10.0, y + 10.0]
            };
            rings.push(vec![[x, y], [x + 9.0, y + a], end]);
        }
        if rings.len() == 1 {
            continue;
        }
        let took = shuffled_agree(
            &mut both,
            &mut rng,
            rings.clone(),
            &format!("touching {case}"),
        );
        // (the stage holds up to eight rings)
        if rings.len() <= 8 {
            cases += 2;
            taken += took;
        }
    }
    assert!(
        cases > 2000 && taken == cases,
        "the stage took {taken} of {cases}"
    );
}

/// Holes lying along the outer ring and along each other (walls: segments walked both
/// ways once the edges are split), on a grid of cells: a square filling its cell (sharing
/// whole sides with its neighbours and the outer ring), a triangle on the cell's bottom
/// side, or a smaller square standing on it; every ring either way round, in any order,
/// in every quarter turn, f64 and f32. The stage must give what the pipeline gives, take
/// every grid without full squares, and nineteen in twenty with them (a full square may
/// have every vertex on its neighbours and the outer ring).
#[test]
fn holes_along_edges_agree_and_mostly_take_the_stage() {
    let mut rng = Rng(0xa1_0e6e);
    let mut both = (pair(), pair());
    let (mut cases, mut taken) = ([0; 2], [0; 2]);
    for case in 0..1500 {
        let full = case % 2 == 1;
        let n = 2 + rng.below(2);
        let mut rings = vec![grid_square(n)];
        for cell in 0..n * n {
            let (x, y) = ((cell % n) as f64 * 10.0, (cell / n) as f64 * 10.0);
            let (a, b) = (rng.below(4) as f64, 6.0 + rng.below(5) as f64);
            match rng.below(6) {
                0 if full => rings.push(vec![
                    [x, y],
                    [x + 10.0, y],
                    [x + 10.0, y + 10.0],
                    [x, y + 10.0],
                ]),
                1 => rings.push(vec![[x + a, y], [x + b, y], [x + 5.0, y + 7.0]]),
                2 => rings.push(vec![
                    [x + a, y],
                    [x + b, y],
                    [x + b, y + 5.0],
                    [x + a, y + 5.0],
                ]),
                _ => {}
            }
        }
        if rings.len() == 1 {
            continue;
        }
        let took = shuffled_agree(&mut both, &mut rng, rings.clone(), &format!("along {case}"));
        if rings.len() <= 8 {
            cases[usize::from(full)] += 2;
            taken[usize::from(full)] += took;
        }
    }
    // (without full squares every grid is taken; a full square may have every vertex on
    // its neighbours and the outer ring, and is nested at a vertex off the ring it is
    // tested against; the few left go to the pipeline for other reasons)
    assert!(
        cases[0] > 1000 && taken[0] == cases[0] && 20 * taken[1] > 19 * cases[1],
        "the stage took {taken:?} of {cases:?}"
    );
}

/// Holes with every vertex on the outer ring: triangles and quadrilaterals on the points
/// of a grid square's sides (edges along the sides, or across the square), and polygons
/// on the vertices of a ring pinched into two lobes (a hole cancelling a lobe, a triangle
/// across one), in two cases of five now and then with a vertex inside; in any order,
/// either way round, every quarter turn, f64 and f32. Many cross each other (both refuse
/// them); the stage must give what the pipeline gives, and take a fair share of the rest.
#[test]
fn holes_on_their_outer_ring_agree_and_take_the_stage() {
    let mut rng = Rng(0x0e_417e);
    let mut both = (pair(), pair());
    let lobes = vec![
        [10.0, 0.0],
        [20.0, 0.0],
        [20.0, 10.0],
        [30.0, 10.0],
        [30.0, 20.0],
        [20.0, 20.0],
        [20.0, 10.0],
        [10.0, 10.0],
    ];
    let (mut cases, mut taken) = (0, 0);
    for case in 0..4000 {
        let outer = if case % 3 == 2 {
            lobes.clone()
        } else {
            grid_square(2 + case % 2)
        };
        let mut rings = vec![outer.clone()];
        for _ in 0..1 + rng.below(2) {
            let n = 3 + rng.below(2);
            let mut hole: Vec<[f64; 2]> = Vec::new();
            while hole.len() < n {
                // now and then a point inside, on no other ring (or on another hole's)
                let p = if case % 5 < 2 && rng.below(4) == 0 {
                    [
                        1.0 + 2.0 * rng.below(9) as f64,
                        1.0 + 2.0 * rng.below(9) as f64,
                    ]
                } else {
                    outer[rng.below(outer.len())]
                };
                if !hole.contains(&p) {
                    hole.push(p);
                }
            }
            rings.push(hole);
        }
        let took = shuffled_agree(&mut both, &mut rng, rings, &format!("on outer {case}"));
        cases += 2;
        taken += took;
    }
    assert!(5 * taken > cases, "the stage took {taken} of {cases}");
}

/// Touches the stage must take or leave exactly as the pipeline does: a hole crossing
/// its outer ring at two shared vertices (partly outside it: strict mode refuses it); two
/// holes touching at the rightmost vertex of both (the hole they make is bridged from
/// its clockwise visit there); holes running along their outer ring's edge (from a shared
/// vertex, inside the edge, along all of it) or along each other (a whole edge, part of
/// one), which leave walls; a crack into a hole; a square hole in the outer ring's corner
/// (every edge there walked both ways) and a triangle filling it (every vertex on the outer
/// ring); holes with every vertex on their outer ring: cancelling a lobe (earcut's issue149
/// among them), and handed back — a spike out of such a hole, a pinched ring's lobe laid
/// in, a triangle filling a notch, two holes overlapping at the outer ring's corner; a
/// ring touching itself: pinched into two polygons,
/// crossing itself round a lobe turning the same way (refused), or round a hole (once at
/// the hole's rightmost vertex, where the face walk keeps it one boundary); three holes
/// meeting at one point; two holes touching each other inside the outer ring's edge
/// (split there once); a hole touching its outer ring twice, which cuts it in two
/// polygons. Each in every quarter turn and winding, both nesting conventions.
#[test]
fn touches_decided_as_the_pipeline_decides() {
    let square = vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]];
    // a ring pinched into two squares touching at a corner
    let lobes = vec![
        [1.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [3.0, 1.0],
        [3.0, 2.0],
        [2.0, 2.0],
        [2.0, 1.0],
        [1.0, 1.0],
    ];
    type Rings = Vec<Vec<[f64; 2]>>;
    let cases: [(&str, Rings, bool); 23] = [
        (
            "crossing",
            vec![
                square.clone(),
                vec![[5.0, 5.0], [0.0, 0.0], [5.0, -2.0], [10.0, 0.0]],
            ],
            false,
        ),
        (
            "bow tie",
            vec![
                square.clone(),
                vec![[7.0, 5.0], [2.0, 6.0], [2.0, 8.0]],
                vec![[7.0, 5.0], [2.0, 2.0], [2.0, 4.0]],
            ],
            true,
        ),
        (
            "along from a shared vertex",
            vec![square.clone(), vec![[0.0, 0.0], [4.0, 0.0], [2.0, 3.0]]],
            true,
        ),
        (
            "along inside the outer ring's edge",
            vec![square.clone(), vec![[3.0, 0.0], [7.0, 0.0], [5.0, 3.0]]],
            true,
        ),
        (
            "along the whole of the outer ring's edge",
            vec![square.clone(), vec![[0.0, 0.0], [10.0, 0.0], [5.0, 3.0]]],
            true,
        ),
        (
            "two holes sharing an edge",
            vec![
                square.clone(),
                vec![[2.0, 2.0], [5.0, 2.0], [5.0, 5.0], [2.0, 5.0]],
                vec![[5.0, 2.0], [8.0, 2.0], [8.0, 5.0], [5.0, 5.0]],
            ],
            true,
        ),
        (
            "two holes sharing part of an edge",
            vec![
                square.clone(),
                vec![[2.0, 2.0], [5.0, 2.0], [5.0, 6.0]],
                vec![[5.0, 3.0], [8.0, 3.0], [5.0, 8.0]],
            ],
            true,
        ),
        (
            "a crack into a hole",
            vec![vec![
                [0.0, 0.0],
                [10.0, 0.0],
                [10.0, 10.0],
                [5.0, 10.0],
                [5.0, 4.0],
                [6.0, 2.0],
                [4.0, 2.0],
                [5.0, 4.0],
                [5.0, 10.0],
                [0.0, 10.0],
            ]],
            true,
        ),
        (
            // (every edge at the corner is walked both ways: a wall or a crack, as the
            // far ends tell)
            "a square hole in the outer ring's corner",
            vec![
                square.clone(),
                vec![[0.0, 0.0], [3.0, 0.0], [3.0, 2.0], [0.0, 2.0]],
            ],
            true,
        ),
        (
            // (every vertex of the hole on the outer ring)
            "a hole filling a corner",
            vec![square.clone(), vec![[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]]],
            true,
        ),
        (
            "a hole cancelling a lobe",
            vec![
                lobes.clone(),
                vec![[2.0, 1.0], [3.0, 1.0], [3.0, 2.0], [2.0, 2.0]],
            ],
            true,
        ),
        (
            "a hole cancelling a lobe, with a spike poking out of it",
            vec![
                lobes.clone(),
                vec![
                    [2.0, 1.0],
                    [3.0, 1.0],
                    [3.0, 2.0],
                    [4.0, 3.0],
                    [3.0, 2.0],
                    [2.0, 2.0],
                ],
            ],
            false,
        ),
        (
            "the lobe of a ring pinched round it, laid in",
            vec![
                vec![
                    [0.0, 0.0],
                    [5.0, 0.0],
                    [3.0, 3.0],
                    [7.0, 3.0],
                    [5.0, 0.0],
                    [10.0, 0.0],
                    [10.0, 10.0],
                    [0.0, 10.0],
                ],
                vec![[5.0, 0.0], [3.0, 3.0], [7.0, 3.0]],
            ],
            false,
        ),
        (
            "a triangle filling a notch",
            vec![
                vec![
                    [0.0, 0.0],
                    [10.0, 0.0],
                    [10.0, 10.0],
                    [5.0, 5.0],
                    [0.0, 10.0],
                ],
                vec![[0.0, 10.0], [5.0, 5.0], [10.0, 10.0]],
            ],
            false,
        ),
        (
            "two holes overlapping at a corner of their outer ring",
            vec![
                vec![
                    [-10.0, 0.0],
                    [-20.0, 0.0],
                    [-20.0, 10.0],
                    [-20.0, 20.0],
                    [-10.0, 20.0],
                    [0.0, 20.0],
                    [0.0, 10.0],
                    [0.0, 0.0],
                ],
                vec![[0.0, 10.0], [0.0, 20.0], [-20.0, 20.0], [0.0, 0.0]],
                vec![[0.0, 0.0], [-20.0, 0.0], [-20.0, 20.0], [-10.0, 20.0]],
            ],
            false,
        ),
        (
            "earcut's issue149: a hole cancelling a lobe behind a spike",
            vec![
                vec![
                    [1888.0, 5504.0],
                    [1872.0, 5504.0],
                    [1872.0, 5536.0],
                    [1856.0, 5536.0],
                    [1856.0, 5520.0],
                    [1840.0, 5520.0],
                    [1840.0, 5504.0],
                    [1856.0, 5504.0],
                    [1856.0, 5520.0],
                    [1872.0, 5520.0],
                    [1872.0, 5504.0],
                    [1888.0, 5504.0],
                ],
                vec![
                    [1856.0, 5520.0],
                    [1856.0, 5536.0],
                    [1872.0, 5536.0],
                    [1872.0, 5520.0],
                ],
            ],
            true,
        ),
        (
            "pinched into two polygons",
            vec![vec![
                [0.0, 0.0],
                [4.0, 0.0],
                [2.0, 2.0],
                [4.0, 4.0],
                [0.0, 4.0],
                [2.0, 2.0],
            ]],
            true,
        ),
        (
            "crossing itself round a lobe",
            vec![vec![
                [0.0, 0.0],
                [5.0, 0.0],
                [7.0, 3.0],
                [3.0, 3.0],
                [5.0, 0.0],
                [10.0, 0.0],
                [10.0, 10.0],
                [0.0, 10.0],
            ]],
            false,
        ),
        (
            "pinched round its hole",
            vec![vec![
                [0.0, 0.0],
                [5.0, 0.0],
                [3.0, 3.0],
                [7.0, 3.0],
                [5.0, 0.0],
                [10.0, 0.0],
                [10.0, 10.0],
                [0.0, 10.0],
            ]],
            true,
        ),
        (
            "pinched round its hole at the hole's rightmost vertex",
            vec![vec![
                [0.0, 0.0],
                [5.0, 0.0],
                [2.0, 1.0],
                [2.0, 3.0],
                [5.0, 0.0],
                [10.0, 0.0],
                [10.0, 10.0],
                [0.0, 10.0],
            ]],
            true,
        ),
        (
            "three holes at one point",
            vec![
                square.clone(),
                vec![[5.0, 5.0], [8.0, 6.0], [7.0, 8.0]],
                vec![[5.0, 5.0], [3.0, 7.0], [2.0, 4.0]],
                vec![[5.0, 5.0], [4.0, 2.0], [7.0, 3.0]],
            ],
            true,
        ),
        (
            "two holes touching inside the outer ring's edge",
            vec![
                square.clone(),
                vec![[5.0, 0.0], [4.0, 3.0], [2.0, 2.0]],
                vec![[5.0, 0.0], [8.0, 2.0], [6.0, 3.0]],
            ],
            true,
        ),
        (
            "cut in two by a hole",
            vec![
                vec![
                    [0.0, 0.0],
                    [5.0, 0.0],
                    [10.0, 0.0],
                    [10.0, 10.0],
                    [5.0, 10.0],
                    [0.0, 10.0],
                ],
                vec![[5.0, 0.0], [6.0, 5.0], [5.0, 10.0], [4.0, 5.0]],
            ],
            true,
        ),
    ];
    let (mut with, mut without) = pair::<f64>();
    for (name, rings, takes) in cases {
        for turn in 0..4 {
            for flip in 0..4 {
                let (vertices, starts) = flattened(rings.iter().enumerate().map(|(r, ring)| {
                    let mut ring: Vec<[f64; 2]> = ring.iter().map(|&p| turned(p, turn)).collect();
                    if flip >> (r % 2) & 1 == 1 {
                        ring.reverse();
                    }
                    ring
                }));
                for nesting in [Nesting::FirstIsOuter, Nesting::Auto] {
                    let tag = format!("{name}, turn {turn}, flip {flip}");
                    let (_, took) =
                        compare_rings(&mut with, &mut without, &vertices, &starts, nesting, &tag);
                    assert_eq!(took > 0, takes, "{tag}");
                }
            }
        }
    }
}

/// Spikes in strict mode: the stage drops the tip as `clean` does and takes the polygon
/// (or drops the ring whole where the rest has no area), unless the tip crossed an edge
/// of the input (`clean` refuses that, naming the crossing: the stage hands it back). In
/// lenient mode the pipeline takes them all. Every quarter turn, either winding.
#[test]
fn spikes_dropped_as_the_pipeline_drops_them() {
    let spike = vec![
        [0.0, 0.0],
        [10.0, 0.0],
        [10.0, 10.0],
        [5.0, 10.0],
        [4.0, 15.0],
        [5.0, 10.0],
        [0.0, 10.0],
    ];
    let hiding_a_crossing = vec![
        [0.0, 0.0],
        [5.0, 0.0],
        [5.0, 12.0],
        [5.0, 0.0],
        [10.0, 0.0],
        [10.0, 10.0],
        [0.0, 10.0],
    ];
    // (its tip dropped, the rest has no area: dropped whole, nothing to triangulate)
    let no_area = vec![
        [0.0, 0.0],
        [10.0, 0.0],
        [10.0, 10.0],
        [10.0, 0.0],
        [5.0, 0.0],
    ];
    let (mut with, mut without) = pair::<f64>();
    for (ring, valid) in [(spike, true), (no_area, true), (hiding_a_crossing, false)] {
        for turn in 0..4 {
            for flip in [false, true] {
                let mut ring: Vec<[f64; 2]> = ring.iter().map(|&p| turned(p, turn)).collect();
                if flip {
                    ring.reverse();
                }
                let tag = format!("spike, valid {valid}, turn {turn}, flip {flip}");
                // (a polygon with a hole first: nothing of it may stay behind)
                let (holed, starts) = flattened([
                    vec![[0.0, 0.0], [9.0, 0.0], [9.0, 9.0], [0.0, 9.0]],
                    vec![[3.0, 3.0], [3.0, 6.0], [6.0, 6.0], [6.0, 3.0]],
                ]);
                let nesting = Nesting::FirstIsOuter;
                let (_, took) =
                    compare_rings(&mut with, &mut without, &holed, &starts, nesting, &tag);
                assert_eq!(took, 4, "{tag}");
                let (ok, took) =
                    compare_rings(&mut with, &mut without, &ring, &[0], Nesting::Auto, &tag);
                // (strict and lenient, both strategies: the stage takes the strict runs)
                assert_eq!((ok, took), if valid { (4, 2) } else { (2, 0) }, "{tag}");
            }
        }
    }
}

/// Every polygon of up to 140 vertices of the glyph datasets, earcut's fixtures and the
/// named corpus cases (bridging's special cases among them), in four rotations: the stage
/// gives what the pipeline gives, and takes every glyph with
/// holes that fits it.
#[test]
fn glyphs_and_earcut_fixtures_agree() {
    let corpus = concat!(env!("CARGO_MANIFEST_DIR"), "/../corpus");
    let mut files: Vec<std::path::PathBuf> = [
        "datasets/lorem_latin.json",
        "datasets/lorem_japanese.json",
        "datasets/letter_a.json",
    ]
    .iter()
    .map(|f| std::path::Path::new(corpus).join(f))
    .collect();
    for folder in ["earcut/fixtures", "paper", "cases"] {
        let mut listed: Vec<_> = std::fs::read_dir(std::path::Path::new(corpus).join(folder))
            .expect("corpus folder")
            .map(|e| e.expect("entry").path())
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
        listed.sort();
        files.extend(listed);
    }
    let (mut with, mut without) = pair::<f64>();
    let (mut with_holes, mut taken) = (0, 0);
    for file in &files {
        let text = std::fs::read_to_string(file).expect("readable");
        let mut value: serde_json::Value = serde_json::from_str(&text).expect("JSON");
        if value.is_object() {
            // a named case: its rings
            value = value["rings"].take();
        }
        let polygons: Vec<Vec<Vec<[f64; 2]>>> = if value[0][0][0].is_array() {
            serde_json::from_value(value).expect("shapes")
        } else {
            vec![serde_json::from_value(value).expect("rings")]
        };
        for (k, rings) in polygons.iter().enumerate() {
            let mut vertices = Vec::new();
            let mut starts = Vec::new();
            for r in rings {
                starts.push(vertices.len());
                vertices.extend_from_slice(r);
            }
            if vertices.len() > 140 {
                continue;
            }
            for turn in 0..4 {
                let v: Vec<[f64; 2]> = vertices.iter().map(|&p| turned(p, turn)).collect();
                let tag = format!("{} polygon {k} turn {turn}", file.display());
                let (_, took) = compare_rings(
                    &mut with,
                    &mut without,
                    &v,
                    &starts,
                    Nesting::FirstIsOuter,
                    &tag,
                );
                compare_rings(&mut with, &mut without, &v, &starts, Nesting::Auto, &tag);
                let glyph = file.starts_with(std::path::Path::new(corpus).join("datasets"));
                if glyph && starts.len() > 1 {
                    with_holes += runs_taken(vertices.len() + 2 * (starts.len() - 1));
                    taken += took;
                }
            }
        }
    }
    // the glyphs are valid: every one with holes that fits is the stage's (earcut's
    // fixtures with holes that fit touch, cross or have degenerate rings, by design)
    assert!(
        with_holes > 200 && taken == with_holes,
        "{taken} of {with_holes}"
    );
}
