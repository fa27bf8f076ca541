//! `Strategy::Seidel` end to end, judged by the oracle: every generator family over
//! several seeds and sizes, every earcut fixture the oracle finds valid (in every
//! rotation), every valid case of the corpus's own folders, the scaling series at 10⁴
//! vertices, in `f64` and `f32` — and, with fill
//! rules, every crossing family, judged by `check_fill`. Plus determinism: the same input
//! twice gives the same triangles.

mod common;

use std::time::Duration;

use common::{assert_no_failures, earcut_fixtures, guarded_triangulate, seen, SELF_INTERSECTING};
use polytri::{Coord, FillRule, Nesting, Options, Strategy, Triangulator};
use polytri_oracle::gen::crossing::{generate_crossing, CrossingFamily};
use polytri_oracle::replay::{load_dir, rotate, Precision, ROTATIONS};
use polytri_oracle::series::Series;
use polytri_oracle::{check_fill, check_with, generate, CheckOptions, Family, Input, Params};

/// Longest one triangulation may take (test build) before it counts as a hang.
const TIMEOUT: Duration = Duration::from_secs(120);

/// Seeds per family and size.
const SEEDS: u64 = 6;
const SIZES: [usize; 4] = [10, 60, 400, 2500];

fn options(input: &Input) -> Options {
    Options::new()
        .with_strategy(Strategy::Seidel)
        .with_nesting(input.nesting.to_polytri().unwrap_or(Nesting::Auto))
}

/// Triangulates `input` with Seidel in `precision` and judges it on the coordinates the
/// triangulator saw: `None` when valid (or when the rounded `f32` input is itself
/// invalid, which strict mode may refuse), else what went wrong.
fn judge(input: &Input, precision: Precision) -> Option<String> {
    let run = match guarded_triangulate(input, options(input), precision, TIMEOUT) {
        Err(e) => return Some(e),
        Ok(run) => run,
    };
    let seen = seen(input, precision);
    match run {
        Err(e) => {
            if precision == Precision::F32
                && !check_with(&seen, &[], &CheckOptions::fast()).input_valid
            {
                return None;
            }
            Some(format!("refused: {e} ({e:?})"))
        }
        Ok(run) => {
            let verdict = check_with(&seen, &run.triangles, &CheckOptions::fast());
            if verdict.valid || (precision == Precision::F32 && !verdict.input_valid) {
                None
            } else {
                Some(format!(
                    "{} triangles: {}",
                    run.triangles.len(),
                    verdict.failures().join("; ")
                ))
            }
        }
    }
}

fn every_family(precision: Precision) {
    let mut failures = Vec::new();
    for family in Family::ALL {
        for &size in &SIZES {
            for seed in 0..SEEDS {
                let case = generate(family, seed, &Params::new(size));
                if let Some(what) = judge(&case.input, precision) {
                    failures.push(format!("{} {precision}: {what}", case.name));
                }
            }
        }
    }
    assert_no_failures(&failures);
}

#[test]
fn every_family_f64() {
    every_family(Precision::F64);
}

#[test]
fn every_family_f32() {
    every_family(Precision::F32);
}

/// Generated cases moved far from the origin and scaled: the same polygons, exactly.
#[test]
fn every_family_placed_far_away() {
    let mut failures = Vec::new();
    for family in Family::ALL {
        for (seed, placement) in [(1.0, [1e6, -1e6]), (1024.0, [1e9, 3e8]), (1e-6, [0.0, 0.0])]
            .into_iter()
            .enumerate()
        {
            let params = Params::new(300)
                .with_scale(placement.0)
                .with_offset(placement.1);
            let case = generate(family, seed as u64, &params);
            if let Some(what) = judge(&case.input, Precision::F64) {
                failures.push(format!("{} at {placement:?}: {what}", case.name));
            }
        }
    }
    assert_no_failures(&failures);
}

fn earcut(precision: Precision) {
    let mut failures = Vec::new();
    let mut judged = 0;
    for case in earcut_fixtures() {
        let expects_triangles = case.bounds.is_some_and(|b| b.earcut_triangles > 0);
        if SELF_INTERSECTING.contains(&case.name.as_str())
            || !expects_triangles
            || !check_with(&case.input, &[], &CheckOptions::fast()).input_valid
        {
            continue;
        }
        for rotation in ROTATIONS {
            let rotated = rotate(&case.input, rotation);
            judged += 1;
            if let Some(what) = judge(&rotated, precision) {
                failures.push(format!("{} rot {rotation} {precision}: {what}", case.name));
            }
        }
    }
    assert!(judged >= 100, "only {judged} fixture runs");
    assert_no_failures(&failures);
}

#[test]
fn earcut_fixtures_f64() {
    earcut(Precision::F64);
}

#[test]
fn earcut_fixtures_f32() {
    earcut(Precision::F32);
}

#[test]
fn the_same_input_gives_the_same_triangles() {
    for family in Family::ALL {
        let case = generate(family, 7, &Params::new(800));
        let input = &case.input;
        let options = options(input);
        let mut tri = Triangulator::<f64>::new();
        let (mut a, mut b, mut c) = (Vec::new(), Vec::new(), Vec::new());
        tri.triangulate(&input.vertices, &input.ring_starts, &options, &mut a)
            .unwrap_or_else(|e| panic!("{}: {e}", case.name));
        // the same triangulator again (warm scratch) and a fresh one
        tri.triangulate(&input.vertices, &input.ring_starts, &options, &mut b)
            .unwrap_or_else(|e| panic!("{}: {e}", case.name));
        Triangulator::<f64>::new()
            .triangulate(&input.vertices, &input.ring_starts, &options, &mut c)
            .unwrap_or_else(|e| panic!("{}: {e}", case.name));
        assert!(!a.is_empty(), "{}", case.name);
        assert_eq!(a, b, "{}: warm run differs", case.name);
        assert_eq!(a, c, "{}: fresh run differs", case.name);
    }
}

/// The scaling series (random, star, circles, comb, pinwheel) at 10⁴ vertices.
#[test]
fn the_scaling_series_at_ten_thousand() {
    let mut failures = Vec::new();
    for series in Series::ALL {
        let input = series.input(10_000);
        for precision in [Precision::F64, Precision::F32] {
            if let Some(what) = judge(&input, precision) {
                failures.push(format!("{series} 10^4 {precision}: {what}"));
            }
        }
    }
    assert_no_failures(&failures);
}

/// Every valid case of the corpus's own folders (named cases, the paper's figures, the
/// paper's datasets), in every rotation and both precisions, with the case's nesting.
#[test]
fn corpus_cases() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../corpus");
    let (mut failures, mut judged) = (Vec::new(), 0);
    for folder in ["cases", "paper", "datasets"] {
        let cases = load_dir(&root.join(folder)).unwrap_or_else(|e| panic!("{folder}: {e}"));
        for case in cases {
            if case.expect.input_valid == Some(false)
                || !check_with(&case.input, &[], &CheckOptions::fast()).input_valid
            {
                continue;
            }
            for rotation in ROTATIONS {
                let rotated = rotate(&case.input, rotation);
                for precision in [Precision::F64, Precision::F32] {
                    judged += 1;
                    if let Some(what) = judge(&rotated, precision) {
                        failures.push(format!(
                            "{folder}/{} rot {rotation} {precision}: {what}",
                            case.name
                        ));
                    }
                }
            }
        }
    }
    assert!(judged >= 200, "only {judged} runs");
    assert_no_failures(&failures);
}

/// Seeds per crossing family; seed `s` is generated at size `FILL_SIZES[s % 3]`.
const FILL_SEEDS: u64 = 6;
const FILL_SIZES: [usize; 3] = [8, 30, 90];

/// The triangles and the added vertices (widened) of a run with a fill rule.
type FillRun = (Vec<[u32; 3]>, Vec<[f64; 2]>);

/// Triangulates with Seidel under `rule`.
fn run_fill<T: Coord>(
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    rule: FillRule,
) -> Result<FillRun, polytri::Error> {
    let options = Options::new()
        .with_strategy(Strategy::Seidel)
        .with_fill_rule(rule);
    let mut out = Vec::new();
    let mut tri = Triangulator::<T>::new();
    let report = tri.triangulate(vertices, ring_starts, &options, &mut out)?;
    let added = report.added.iter().map(|a| a.position).collect();
    Ok((out, added))
}

#[test]
fn every_crossing_family_under_every_fill_rule() {
    let mut failures = Vec::new();
    for family in CrossingFamily::ALL {
        for seed in 0..FILL_SEEDS {
            let size = FILL_SIZES[seed as usize % FILL_SIZES.len()];
            let (vertices, ring_starts) = generate_crossing(family, seed, size);
            let narrow: Vec<[f32; 2]> = vertices.iter().map(|v| v.map(|c| c as f32)).collect();
            let rounded: Vec<[f64; 2]> = narrow.iter().map(|v| v.map(f64::from)).collect();
            for rule in FillRule::ALL {
                for f32 in [false, true] {
                    let (judged, result) = if f32 {
                        (&rounded, run_fill(&narrow, &ring_starts, rule))
                    } else {
                        (&vertices, run_fill(&vertices, &ring_starts, rule))
                    };
                    let tag = format!(
                        "{family} seed {seed} size {size} {} {}",
                        rule.name(),
                        if f32 { "f32" } else { "f64" }
                    );
                    match result {
                        Err(e) => failures.push(format!("{tag}: refused: {e} ({e:?})")),
                        Ok((triangles, added)) => {
                            let v = check_fill(judged, &ring_starts, rule, &added, &triangles);
                            if !v.valid {
                                failures.push(format!("{tag}: {}", v.failures().join("; ")));
                            }
                        }
                    }
                }
            }
        }
    }
    assert_no_failures(&failures);
}
