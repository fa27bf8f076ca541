//! Fill rules end to end: every crossing family, over several seeds, under every fill rule,
//! in both strategies and both precisions, triangulated by polytri and judged by the
//! oracle's independent `check_fill` (on the coordinates as triangulated: in `f32`, the
//! rounded ones).

use polytri::{Coord, Error, FillRule, Options, Strategy, Triangulator};
use polytri_oracle::check_fill;
use polytri_oracle::gen::crossing::{generate_crossing, CrossingFamily};

/// Seeds per family; seed `s` is generated at size `SIZES[s % SIZES.len()]`.
const SEEDS: u64 = 24;
const SIZES: [usize; 6] = [8, 24, 64, 13, 40, 120];

/// Triangles, and the added vertices widened to `f64`.
type Triangulation = (Vec<[u32; 3]>, Vec<[f64; 2]>);

/// A failed run: what went wrong, and the input as rings JSON.
type Failure = (String, String);

/// Triangulates with `options` (a fill rule).
fn run<T: Coord>(
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    options: &Options,
) -> Result<Triangulation, Error> {
    let mut tri = Triangulator::<T>::new();
    let mut out = Vec::new();
    let report = tri.triangulate(vertices, ring_starts, options, &mut out)?;
    let added = report.added.iter().map(|a| a.position).collect();
    Ok((out, added))
}

/// The input as rings JSON (`[[[x, y], …], …]`), to paste into a file for `polytri
/// triangulate --fill-rule`.
fn rings_json(vertices: &[[f64; 2]], ring_starts: &[usize]) -> String {
    let rings: Vec<&[[f64; 2]]> = (0..ring_starts.len())
        .map(|r| {
            let end = ring_starts.get(r + 1).copied().unwrap_or(vertices.len());
            &vertices[ring_starts[r]..end]
        })
        .collect();
    serde_json::to_string(&rings).unwrap_or_default()
}

/// Triangulates and judges one input in one rule, strategy and precision; `None` when
/// valid, else what went wrong.
fn judge(
    vertices: &[[f64; 2]],
    ring_starts: &[usize],
    rule: FillRule,
    strategy: Strategy,
    f32: bool,
) -> Option<String> {
    let options = Options::new().with_strategy(strategy).with_fill_rule(rule);
    let rounded: Vec<[f64; 2]>;
    let (judged, result) = if f32 {
        let narrow: Vec<[f32; 2]> = vertices.iter().map(|v| v.map(|c| c as f32)).collect();
        rounded = narrow.iter().map(|v| v.map(f64::from)).collect();
        (&rounded[..], run(&narrow, ring_starts, &options))
    } else {
        (vertices, run(vertices, ring_starts, &options))
    };
    match result {
        Err(e) => Some(format!("refused: {e} ({e:?})")),
        Ok((triangles, added)) => {
            let verdict = check_fill(judged, ring_starts, rule, &added, &triangles);
            (!verdict.valid).then(|| {
                format!(
                    "{} triangles, {} added: {}",
                    triangles.len(),
                    added.len(),
                    verdict.failures().join("; ")
                )
            })
        }
    }
}

/// Every seed of `family` in every rule, strategy and precision: how many runs, and the
/// failures with their inputs.
fn family_runs(family: CrossingFamily) -> (usize, Vec<Failure>) {
    let mut failures = Vec::new();
    let mut runs = 0;
    for seed in 0..SEEDS {
        let size = SIZES[seed as usize % SIZES.len()];
        let (vertices, ring_starts) = generate_crossing(family, seed, size);
        for rule in FillRule::ALL {
            for strategy in [Strategy::Fast, Strategy::Quality] {
                for f32 in [false, true] {
                    runs += 1;
                    if let Some(what) = judge(&vertices, &ring_starts, rule, strategy, f32) {
                        let precision = if f32 { "f32" } else { "f64" };
                        failures.push((
                            format!(
                                "{family} seed {seed} size {size}, {} {strategy:?} {precision}: {what}",
                                rule.name()
                            ),
                            rings_json(&vertices, &ring_starts),
                        ));
                    }
                }
            }
        }
    }
    (runs, failures)
}

#[test]
fn every_crossing_family_under_every_fill_rule() {
    // one thread per family: the judge is the slow part, and debug builds are slow
    let results: Vec<(usize, Vec<Failure>)> = std::thread::scope(|scope| {
        let handles: Vec<_> = (CrossingFamily::ALL.iter())
            .map(|&family| scope.spawn(move || family_runs(family)))
            .collect();
        (handles.into_iter())
            .map(|h| h.join().expect("no panic"))
            .collect()
    });
    let runs: usize = results.iter().map(|r| r.0).sum();
    let failures: Vec<Failure> = results.into_iter().flat_map(|r| r.1).collect();
    if !failures.is_empty() {
        let mut message = format!("{} of {runs} runs failed:\n", failures.len());
        for (k, (what, input)) in failures.iter().enumerate() {
            message.push_str(what);
            message.push('\n');
            // the input of the first few, once each
            if k < 12 && failures[..k].iter().all(|(_, seen)| seen != input) {
                message.push_str(&format!("  input (rings JSON): {input}\n"));
            }
        }
        panic!("{message}");
    }
}

/// The pentagram {5/2}, counter-clockwise: winding number 1 in the five points, 2 in the
/// pentagon at its centre, whose five corners are the added vertices.
#[test]
fn pentagram_under_each_rule() {
    let corners: Vec<[f64; 2]> = (0..5)
        .map(|i| {
            let a = std::f64::consts::FRAC_PI_2 + f64::from(i * 2) * std::f64::consts::TAU / 5.0;
            [(100.0 * a.cos()).round(), (100.0 * a.sin()).round()]
        })
        .collect();
    // (triangles, added vertices used) per rule: the points alone (5 triangles); the
    // decagon outline (8); nothing; the inner pentagon (3)
    let expected = [
        (FillRule::EvenOdd, 5),
        (FillRule::NonZero, 8),
        (FillRule::Positive, 8),
        (FillRule::Negative, 0),
        (FillRule::AbsGeqTwo, 3),
    ];
    for (rule, count) in expected {
        for strategy in [Strategy::Fast, Strategy::Quality] {
            let options = Options::new().with_strategy(strategy).with_fill_rule(rule);
            let (triangles, added) =
                run(&corners, &[0], &options).unwrap_or_else(|e| panic!("{rule:?}: {e}"));
            assert_eq!(added.len(), 5, "{rule:?} {strategy:?}");
            assert_eq!(
                triangles.len(),
                count,
                "{rule:?} {strategy:?}: {triangles:?}"
            );
            let verdict = check_fill(&corners, &[0], rule, &added, &triangles);
            assert!(verdict.valid, "{rule:?}: {:?}", verdict.failures());
        }
    }
}

/// A hole whose edge runs out through its outer ring and straight back (a spike's tip
/// outside): the edges as given cross, the region is the outer ring less the hole, the
/// spike enclosing nothing. Every rule, strategy and precision gives the oracle's region.
/// The outer ring has 200 vertices, past the small stage: there a fill rule's first try
/// (strict mode's check of the filtered rings, which passes) triangulates the rings
/// without searching the input's edges for the crossing the spike hid, and even–odd adds
/// nothing; `resolve` would add the point where the spike crosses.
#[test]
fn a_spike_through_another_ring_encloses_nothing() {
    let outer = (0..200).map(|k| {
        let t = std::f64::consts::TAU * f64::from(k) / 200.0;
        [2.0 + 8.0 * t.cos(), 2.0 + 8.0 * t.sin()]
    });
    // the hole clockwise, its spike from (3, 1) up to (3, 20) and back down to (3, 2)
    let hole = [[1.0, 1.0], [1.0, 2.0], [3.0, 2.0], [3.0, 20.0], [3.0, 1.0]];
    let vertices: Vec<[f64; 2]> = outer.chain(hole).collect();
    for rule in FillRule::ALL {
        for strategy in [Strategy::Fast, Strategy::Quality, Strategy::Seidel] {
            for f32 in [false, true] {
                let failure = judge(&vertices, &[0, 200], rule, strategy, f32);
                assert_eq!(failure, None, "{rule:?} {strategy:?} f32 {f32}");
            }
        }
    }
    let options = Options::new().with_fill_rule(FillRule::EvenOdd);
    let (_, added) = run(&vertices, &[0, 200], &options).expect("even-odd");
    assert!(added.is_empty(), "{added:?}");
}

/// A ring passing (0, 0) many times, along the axes, whose edges cross at points that
/// round to (0, 0) from below: rounded in floating point they came out as (−0.0, −0.0),
/// which `==` calls equal to the vertex at (0, 0) but the sort of points by `total_cmp`
/// took for another point, so that the ways round the vertex included one of no
/// length and the sort of them by angle panicked (not a total order). `small_vs_pipeline`
/// found it, through lenient mode reading rings by even–odd. Every rule, strategy and
/// precision gives the oracle's region.
#[test]
fn crossings_rounded_to_minus_zero_are_the_vertex_at_zero() {
    let ring = [
        [2.0, 0.0],
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, -1.0],
        [0.0, 14.0],
        [-6.0, -6.0],
        [-6.0, -6.0],
        [0.0, 8.0],
        [0.0, 10.0],
        [11.0, 10.0],
        [11.0, 11.0],
        [10.0, 10.0],
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, -6.0],
        [0.0, 3.0],
        [10.0, 0.0],
        [-1.0, 0.0],
        [0.0, 0.0],
        [0.0, 1.0],
        [0.0, -14.0],
        [14.0, 0.0],
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, 1.0],
        [-1.0, 0.0],
        [14.0, 0.0],
        [-11.0, 0.0],
    ];
    for rule in FillRule::ALL {
        for strategy in [Strategy::Fast, Strategy::Quality, Strategy::Seidel] {
            for f32 in [false, true] {
                let failure = judge(&ring, &[0], rule, strategy, f32);
                assert_eq!(failure, None, "{rule:?} {strategy:?} f32 {f32}");
            }
        }
    }
}
