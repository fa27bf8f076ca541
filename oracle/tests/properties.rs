//! Property tests: polytri triangulates every generated case, in both strategies and both
//! precisions, and the oracle accepts the result. Failures shrink to smaller valid inputs
//! (see `polytri_oracle::strategy`).
//!
//! Case counts are small so that the suite stays well under 30 s in debug builds; set
//! `PROPTEST_CASES` for longer runs (it replaces every count here).

use polytri::{Options, Strategy as Clip, Triangulator};
use polytri_oracle::gen::{generate, validate, Case, Family, Params};
use polytri_oracle::strategy::{any_case, family_case};
use polytri_oracle::{check, check_with, CheckOptions, Input};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// `cases` unless `PROPTEST_CASES` says otherwise; seeded (`PROPTEST_RNG_SEED` picks
/// another seed for longer local runs), so CI runs the same cases every time.
fn config(cases: u32) -> ProptestConfig {
    let mut config = if std::env::var_os("PROPTEST_CASES").is_some() {
        ProptestConfig::default()
    } else {
        ProptestConfig::with_cases(cases)
    };
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = proptest::test_runner::RngSeed::Fixed(0x0070_6f6c_7974_7269);
    }
    config
}

/// Triangulates `input` with polytri in precision `T` and strategy `clip`, automatic
/// nesting, strict; an error is a failure (the input is valid).
fn triangulate<T: polytri::Coord>(
    vertices: &[[T; 2]],
    input: &Input,
    clip: Clip,
) -> Result<Vec<[u32; 3]>, String> {
    let options = Options::default().with_strategy(clip);
    let mut out = Vec::new();
    Triangulator::<T>::new()
        .triangulate(vertices, &input.ring_starts, &options, &mut out)
        .map_err(|e| format!("polytri refused a valid input: {e}"))?;
    Ok(out)
}

/// Every strategy and precision on `case`, judged by the oracle (`full` adds geo and the
/// CDT comparison).
fn judge(case: &Case, full: bool) -> Result<(), TestCaseError> {
    let touching = case.family.is_some_and(Family::allows_touching);
    let narrow = case.input.to_f32();
    let f32_valid = validate(&narrow, touching).is_ok();
    let options = if full {
        CheckOptions::full()
    } else {
        CheckOptions::fast()
    };
    for clip in [Clip::Fast, Clip::Quality] {
        let runs = [
            (
                "f64",
                Some(triangulate(&case.input.vertices, &case.input, clip)),
                &case.input,
            ),
            (
                "f32",
                f32_valid.then(|| triangulate(&case.input.vertices_f32(), &narrow, clip)),
                &narrow,
            ),
        ];
        for (precision, result, input) in runs {
            let Some(result) = result else { continue };
            let triangles = result.map_err(|e| {
                TestCaseError::fail(format!("{} {precision} {clip:?}: {e}", case.name))
            })?;
            let verdict = check_with(input, &triangles, &options);
            prop_assert!(
                verdict.valid,
                "{} {precision} {clip:?}: {:?}\n{}",
                case.name,
                verdict.failures(),
                case.to_json()
            );
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(96))]

    /// Any family, up to 300 vertices, exact checks.
    #[test]
    fn polytri_triangulates_any_generated_case(case in any_case()) {
        judge(&case, false)?;
    }
}

proptest! {
    #![proptest_config(config(8))]

    /// Every family on its own, so none goes untested by chance, with every check.
    #[test]
    fn star(case in family_case(Family::Star, 200)) { judge(&case, true)?; }
    #[test]
    fn space_partition(case in family_case(Family::SpacePartition, 200)) { judge(&case, true)?; }
    #[test]
    fn two_opt(case in family_case(Family::TwoOpt, 200)) { judge(&case, true)?; }
    #[test]
    fn orthogonal(case in family_case(Family::Orthogonal, 200)) { judge(&case, true)?; }
    #[test]
    fn circles(case in family_case(Family::Circles, 400)) { judge(&case, true)?; }
    #[test]
    fn comb(case in family_case(Family::Comb, 200)) { judge(&case, true)?; }
    #[test]
    fn spiral(case in family_case(Family::Spiral, 200)) { judge(&case, true)?; }
    #[test]
    fn many_holes(case in family_case(Family::ManyHoles, 400)) { judge(&case, true)?; }
    #[test]
    fn touching_holes(case in family_case(Family::TouchingHoles, 300)) { judge(&case, true)?; }
    #[test]
    fn nested_islands(case in family_case(Family::NestedIslands, 300)) { judge(&case, true)?; }
    #[test]
    fn slivers(case in family_case(Family::Slivers, 200)) { judge(&case, true)?; }
    #[test]
    fn font_like(case in family_case(Family::FontLike, 400)) { judge(&case, true)?; }
}

/// Far from the origin and at tiny scales the grid stays exact: same verdicts.
#[test]
fn offsets_and_scales() {
    for family in Family::ALL {
        for (scale, offset) in [(1.0, [1e9, -1e9]), (2f64.powi(-30), [0.0, 0.0])] {
            let params = Params::new(150).with_scale(scale).with_offset(offset);
            let case = generate(family, 11, &params);
            if let Err(e) = judge(&case, false) {
                panic!("{e}");
            }
        }
    }
}

/// The oracle is not a rubber stamp: a triangulation missing one triangle is rejected.
#[test]
fn the_oracle_rejects_a_dropped_triangle() {
    for family in Family::ALL {
        let case = generate(family, 2, &Params::new(120));
        let mut triangles = triangulate(&case.input.vertices, &case.input, Clip::Fast)
            .unwrap_or_else(|e| panic!("{}: {e}", case.name));
        assert!(check(&case.input, &triangles).valid, "{}", case.name);
        triangles.remove(triangles.len() / 2);
        let verdict = check(&case.input, &triangles);
        assert!(
            !verdict.valid,
            "{}: a missing triangle went unnoticed",
            case.name
        );
        assert!(!verdict.failures().is_empty());
    }
}

/// A failing property is reported on a minimal valid case: here "fewer than two rings"
/// fails on every nested case and must shrink to two triangles.
#[test]
fn failures_shrink_to_small_valid_cases() {
    use proptest::test_runner::{RngAlgorithm, TestError, TestRng, TestRunner};
    // seeded, and enough shrink steps to reach the minimum (the default budget scales
    // with the case count, and four cases leave only 16 steps)
    let config = ProptestConfig {
        max_shrink_iters: 10_000,
        ..ProptestConfig::with_cases(4)
    };
    let rng = TestRng::deterministic_rng(RngAlgorithm::ChaCha);
    let mut runner = TestRunner::new_with_rng(config, rng);
    let result = runner.run(&family_case(Family::NestedIslands, 200), |case| {
        prop_assert!(case.input.ring_count() < 2);
        Ok(())
    });
    let Err(TestError::Fail(_, smallest)) = result else {
        panic!("the property should fail: {result:?}");
    };
    assert_eq!(smallest.input.ring_count(), 2);
    assert_eq!(smallest.input.vertices.len(), 6);
    assert!(validate(&smallest.input, false).is_ok());
}
