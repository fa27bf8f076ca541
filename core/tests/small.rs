//! The small-ring stage (one ring of at most 64 vertices, either strategy) must give exactly
//! what the whole pipeline gives: the same triangles in the same order, the same report
//! (dropped vertices, repairs, deviation to the bit) and the same errors — where it takes
//! the input and where it hands it back. Each input runs twice, with the stage and
//! without (`Triangulator::set_small_rings`), on random rings built to hit every branch:
//! valid rings in both windings, repeated and straight vertices, closing points, spikes,
//! rings that cross or touch themselves, non-finite coordinates; f64 and f32, strict and
//! lenient.

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
    opts: &Options,
) -> Result<Outcome, Error> {
    let mut out = Vec::new();
    let report = tri.triangulate(vertices, &[0], opts, &mut out)?;
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
        _ => {}
    }
    (v, (3..=6).contains(&defect))
}

/// Two triangulators: one that may take the small-ring stage, one that never does.
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
    let (mut ok, mut took) = (0, 0);
    // (one ring: both conventions make it the outer boundary; each call flips which)
    let nesting = [Nesting::Auto, Nesting::FirstIsOuter][vertices.len() % 2];
    for strategy in [Strategy::Fast, Strategy::Quality] {
        for lenient in [false, true] {
            let opts = Options::default()
                .with_strategy(strategy)
                .with_nesting(nesting)
                .with_lenient(lenient);
            let (a, b) = (run(with, vertices, &opts), run(without, vertices, &opts));
            assert!(!without.small_ring_took_last());
            took += usize::from(with.small_ring_took_last());
            assert_eq!(a, b, "{tag}, {strategy:?}, lenient {lenient}: {vertices:?}");
            ok += usize::from(a.is_ok());
        }
    }
    assert_eq!(
        with.check(vertices, &[0], nesting),
        without.check(vertices, &[0], nesting),
        "{tag}, check: {vertices:?}"
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
        // up to 66 vertices with defects: past the stage's limit too
        let n = 3 + rng.below(62);
        let grid = [4.0, 12.0, 100.0, 1e4, 1e9][rng.below(5)];
        let (v, defect) = ring(&mut rng, n, grid);
        let tag = format!("case {case}");
        let (ok, took) = compare(&mut with64, &mut without64, &v, &tag);
        // f32 rounds the larger grids: other repeats and crossings
        let v32: Vec<[f32; 2]> = v.iter().map(|p| [p[0] as f32, p[1] as f32]).collect();
        let (ok32, took32) = compare(&mut with32, &mut without32, &v32, &tag);
        (triangulated, taken) = (triangulated + ok + ok32, taken + took + took32);
        if !defect && grid == 1e9 && v.len() <= 64 {
            // simple (a star on a fine grid), at most repeated or straight vertices: the
            // stage's own case
            assert_eq!(took, 4, "{tag}: the stage declined {v:?}");
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
        let columns = 1 + rng.below(20);
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
        if v.len() <= 64 {
            assert_eq!((ok, took), (4, 4), "{tag}: {v:?}");
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
