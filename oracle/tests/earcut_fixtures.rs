//! mapbox/earcut's regression fixtures (`corpus/earcut`) in lenient mode, run the way
//! earcut's own test runs them — every fixture rotated by 0°, 90°, 180° and 270° — through
//! both strategies and both precisions, with earcut's convention (`Nesting::FirstIsOuter`).
//!
//! `corpus.rs` replays the same fixtures in strict mode, and in lenient mode only those the
//! oracle finds invalid; here every fixture goes through lenient mode. Checked per run: no
//! panic or hang and no error; the deviation within the fixture's bound (earcut's
//! `expected.json`, tightened by our `bounds.json`), for the fixtures where earcut expects
//! triangles; and, where the oracle finds the input valid, a valid triangulation. Failures
//! are collected and reported together, one line each.

mod common;

use std::time::Duration;

use common::{assert_no_failures, earcut_fixtures, guarded_triangulate, seen, SELF_INTERSECTING};
use polytri::{Nesting, Options, Strategy};
use polytri_oracle::replay::{rotate, strategy_name, Precision, KNOWN_GAPS, ROTATIONS, ROUND_OFF};
use polytri_oracle::{check_with, CheckOptions, Input};

/// Longest a single triangulation may take (debug build) before it counts as a hang.
const TIMEOUT: Duration = Duration::from_secs(120);

/// Every coordinate is an integer: the deviation has no round-off then.
fn integral(input: &Input) -> bool {
    input.vertices.iter().flatten().all(|c| c.fract() == 0.0)
}

fn run_all(strategy: Strategy, precision: Precision) {
    let mut failures = Vec::new();
    let mut notes = Vec::new();
    let options = Options::default()
        .with_strategy(strategy)
        .with_nesting(Nesting::FirstIsOuter)
        .with_lenient(true);
    for case in earcut_fixtures() {
        let bounds = case.bounds.expect("earcut fixtures have deviation bounds");
        for rotation in ROTATIONS {
            let rotated = rotate(&case.input, rotation);
            let tag = format!("{} rot {rotation} {strategy:?} {precision}", case.name);
            let run = match guarded_triangulate(&rotated, options, precision, TIMEOUT) {
                Err(e) => {
                    failures.push(format!("{tag}: {e}"));
                    continue;
                }
                Ok(Err(e)) => {
                    failures.push(format!("{tag}: lenient mode returned Err({e:?}): {e}"));
                    continue;
                }
                Ok(Ok(run)) => run,
            };
            // The coordinates the triangulator saw, as f64 (exact for f32).
            let seen = seen(&rotated, precision);
            let verdict = check_with(&seen, &run.triangles, &CheckOptions::fast());

            // The rounded input may be invalid where the f64 one is not.
            if seen != rotated && !verdict.input_valid {
                notes.push(format!(
                    "{tag}: f32-rounded input is invalid; only no panic and no error checked"
                ));
                continue;
            }

            if bounds.earcut_triangles > 0 {
                let dev = verdict.deviation;
                let mut bound = bounds.at(rotation);
                if !integral(&seen) {
                    bound = bound.max(ROUND_OFF);
                }
                if let Some(gap) = KNOWN_GAPS.iter().find(|g| {
                    g.case == case.id()
                        && g.rotation == rotation
                        && g.strategies.contains(&strategy_name(strategy))
                }) {
                    bound = bound.max(gap.deviation);
                }
                if dev.is_nan() || dev > bound {
                    failures.push(format!(
                        "{tag}: deviation {dev:e} > bound {bound:e} ({} triangles, earcut {})",
                        run.triangles.len(),
                        bounds.earcut_triangles
                    ));
                }
            }

            if verdict.input_valid && !verdict.valid {
                failures.push(format!(
                    "{tag}: invalid triangulation: {}",
                    verdict.failures().join("; ")
                ));
            }
        }
    }
    for n in &notes {
        eprintln!("note: {n}");
    }
    assert_no_failures(&failures);
}

#[test]
fn fast_f64() {
    run_all(Strategy::Fast, Precision::F64);
}

#[test]
fn fast_f32() {
    run_all(Strategy::Fast, Precision::F32);
}

#[test]
fn quality_f64() {
    run_all(Strategy::Quality, Precision::F64);
}

#[test]
fn quality_f32() {
    run_all(Strategy::Quality, Precision::F32);
}

/// The split into valid and self-intersecting fixtures is what the data says: exactly the
/// listed fixtures fail the oracle's input check for crossing edges (the first problem it
/// reports for inputs whose structure is sound). The others it finds valid, except the
/// degenerate ones earcut expects no triangles from.
#[test]
fn fixture_classification_matches_the_data() {
    let mut wrong = Vec::new();
    for case in earcut_fixtures() {
        let verdict = check_with(&case.input, &[], &CheckOptions::fast());
        let problem = verdict
            .check("input")
            .and_then(|c| c.detail.as_deref())
            .unwrap_or("");
        let crossing = problem.starts_with("edges ") && problem.contains(" cross");
        let listed = SELF_INTERSECTING.contains(&case.name.as_str());
        let expects_triangles = case.bounds.is_some_and(|b| b.earcut_triangles > 0);
        if listed != crossing || (!listed && expects_triangles && !verdict.input_valid) {
            wrong.push(format!(
                "{}: listed self-intersecting = {listed}, input check: {}",
                case.name,
                if problem.is_empty() { "valid" } else { problem }
            ));
        }
    }
    assert_no_failures(&wrong);
}
