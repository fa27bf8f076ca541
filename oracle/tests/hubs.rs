//! Many rings, or many visits of one ring, at one point, against the oracle.
//!
//! Past a handful of nodes at one position, `touch` pairs the edges there by sorting them
//! around it, and `nest` decides a ring whose rightmost vertex is such a hub at a vertex
//! where fewer meet. These inputs have 9 to 60 nodes at their centre:
//!
//! - a pie: slices as outer rings, sharing their sides (nesting by containment);
//! - a pinwheel: thin triangular holes meeting at the centre of a square;
//! - a flower: one ring through the centre once per petal, or the petals dealt out to a
//!   few rings that touch there;
//! - a wheel: a disk with every other slice a hole, the holes touching at the centre and
//!   lying along the rim;
//! - a corner fan: thin wedge holes fanning out from a corner of a square, touching it
//!   there;
//! - slits: thin parallelograms across a square, along its diagonal.
//!
//! The last two, and all of them with 150 to 600 spokes, have many edges long both ways,
//! which the edge grid lists in the cells their segments pass. Each input is given with
//! random ring starts, either winding, in a random quarter turn; both strategies, strict
//! and lenient, must return a triangulation the oracle accepts.

mod common;

use common::{assert_no_failures, run, shuffled, Rng};
use polytri::Strategy;
use polytri_oracle::{check_with, CheckOptions, Input, Nesting};

type Ring = Vec<[f64; 2]>;

/// `k` points on a circle of radius 100 round the origin, counter-clockwise, at uneven
/// angles (each computed once, so that rings sharing a point share it exactly).
fn rim(k: usize, rng: &mut Rng) -> Ring {
    (0..k)
        .map(|i| {
            let jitter = (rng.below(1000) as f64 / 1000.0 - 0.5) * 0.6;
            let angle = std::f64::consts::TAU * (i as f64 + jitter) / k as f64;
            [100.0 * angle.cos(), 100.0 * angle.sin()]
        })
        .collect()
}

const CENTRE: [f64; 2] = [0.0, 0.0];

/// The slice from rim point `i` to the next, counter-clockwise.
fn slice(rim: &Ring, i: usize) -> Ring {
    vec![CENTRE, rim[i], rim[(i + 1) % rim.len()]]
}

/// A thin petal inside the slice from rim point `i` to the next: the centre, then two
/// points a third and two thirds of the way between them, pulled in.
fn petal(rim: &Ring, i: usize) -> Ring {
    let (a, b) = (rim[i], rim[(i + 1) % rim.len()]);
    let at = |t: f64| {
        [
            0.9 * (a[0] + t * (b[0] - a[0])),
            0.9 * (a[1] + t * (b[1] - a[1])),
        ]
    };
    vec![CENTRE, at(1.0 / 3.0), at(2.0 / 3.0)]
}

/// The input of kind `kind` (0 pie, 1 pinwheel, 2 flower, 3 wheel, 4 corner fan, 5 slits)
/// with `k` spokes, and its nesting convention.
fn hub(kind: usize, k: usize, rng: &mut Rng) -> (Vec<Ring>, Nesting) {
    let rim = rim(k, rng);
    match kind {
        0 => ((0..k).map(|i| slice(&rim, i)).collect(), Nesting::Auto),
        1 => {
            let square = vec![
                [-200.0, -200.0],
                [200.0, -200.0],
                [200.0, 200.0],
                [-200.0, 200.0],
            ];
            let holes = (0..k).map(|i| {
                let mut p = petal(&rim, i);
                p.reverse();
                p
            });
            let nesting = if rng.below(2) == 0 {
                Nesting::FirstIsOuter
            } else {
                Nesting::Auto
            };
            (std::iter::once(square).chain(holes).collect(), nesting)
        }
        2 => {
            // petals dealt out to 1–3 rings, each passing the centre once per petal
            let rings = 1 + rng.below(3);
            let mut out = vec![Ring::new(); rings];
            for i in 0..k {
                out[rng.below(rings)].extend(petal(&rim, i));
            }
            out.retain(|r| !r.is_empty());
            (out, Nesting::Auto)
        }
        4 => {
            let square = vec![[0.0, 0.0], [100.0, 0.0], [100.0, 100.0], [0.0, 100.0]];
            let at = |t: f64| {
                let angle = std::f64::consts::FRAC_PI_2 * t / k as f64;
                [90.0 * angle.cos(), 90.0 * angle.sin()]
            };
            // clockwise wedges, each within its own share of the right angle
            let holes = (0..k).map(|i| vec![[0.0, 0.0], at(i as f64 + 0.85), at(i as f64 + 0.15)]);
            (
                std::iter::once(square).chain(holes).collect(),
                Nesting::FirstIsOuter,
            )
        }
        5 => {
            let square = vec![[0.0, 0.0], [1000.0, 0.0], [1000.0, 1000.0], [0.0, 1000.0]];
            // along the lines x − y = offset, 10 from the square's sides, clockwise
            let gap = 1400.0 / (k + 1) as f64;
            let holes = (0..k).filter_map(|i| {
                let offset = -700.0 + gap * (i + 1) as f64;
                let (x0, x1) = ((10.0 + offset).max(10.0), (990.0 + offset).min(990.0));
                // narrower than the gap, and short of the square's side
                let width = (0.2 * gap).min(5.0);
                (x1 - x0 >= 20.0).then(|| {
                    let (a, b) = ([x0, x0 - offset], [x1, x1 - offset]);
                    vec![a, [a[0] + width, a[1]], [b[0] + width, b[1]], b]
                })
            });
            (
                std::iter::once(square).chain(holes).collect(),
                Nesting::FirstIsOuter,
            )
        }
        _ => {
            let holes = (0..k).step_by(2).map(|i| {
                let mut s = slice(&rim, i);
                s.reverse();
                s
            });
            (
                std::iter::once(rim.clone()).chain(holes).collect(),
                Nesting::FirstIsOuter,
            )
        }
    }
}

/// Every seed's input, with spokes from `spokes`, through both strategies, strict and
/// lenient, against the oracle; the failures.
fn judge(seeds: std::ops::Range<u64>, spokes: std::ops::Range<usize>) -> Vec<String> {
    let mut failures = Vec::new();
    for seed in seeds {
        let mut rng = Rng(seed ^ 0x48_5542);
        let kind = seed as usize % 6;
        let k = spokes.start + rng.below(spokes.len());
        let (rings, nesting) = hub(kind, k, &mut rng);
        let input = Input::from_rings(&shuffled(rings, &mut rng), nesting);
        let what = format!("seed {seed}, kind {kind}, {k} spokes");
        let judged = check_with(&input, &[], &CheckOptions::fast());
        if !judged.input_valid {
            failures.push(format!("{what}: input invalid: {:?}", judged.failures()));
            continue;
        }
        for strategy in [Strategy::Fast, Strategy::Quality] {
            for lenient in [false, true] {
                match run(&input, strategy, lenient) {
                    Ok(tris) => {
                        let verdict = check_with(&input, &tris, &CheckOptions::fast());
                        if !verdict.valid {
                            let why = verdict.failures();
                            failures.push(format!("{what}, {strategy:?}, {lenient}: {why:?}"));
                        }
                    }
                    Err(e) => failures.push(format!("{what}, {strategy:?}, {lenient}: {e}")),
                }
            }
        }
    }
    failures
}

#[test]
fn many_rings_at_one_point_triangulate_validly() {
    assert_no_failures(&judge(0..180, 9..61));
}

#[test]
fn many_long_edges_triangulate_validly() {
    assert_no_failures(&judge(1000..1024, 150..601));
}
