//! The `Report`'s deviation is the oracle's: the same formula (`polytri::deviation`), on
//! the input's area and the triangles' area, computed apart. On earcut's fixtures in
//! lenient mode (valid ones, where it is rounding only, and crossing ones, where it is the
//! measure lenient mode minimises), they agree to rounding (1e-9); on valid fixtures with integer
//! coordinates both are exactly 0.

mod common;

use common::earcut_fixtures;
use polytri::{Nesting, Options, Strategy, Triangulator};
use polytri_oracle::{check_with, CheckOptions};

#[test]
fn the_reports_deviation_is_the_oracles() {
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    let mut crossing = 0;
    for case in earcut_fixtures() {
        for strategy in [Strategy::Fast, Strategy::Quality] {
            let options = Options::default()
                .with_strategy(strategy)
                .with_nesting(Nesting::FirstIsOuter)
                .with_lenient(true);
            let input = &case.input;
            let report = tri
                .triangulate(&input.vertices, &input.ring_starts, &options, &mut out)
                .unwrap_or_else(|e| panic!("{}: {e}", case.name));
            let ours = report.deviation;
            let verdict = check_with(input, &out, &CheckOptions::fast());
            let theirs = verdict.deviation;
            let tag = format!("{} {strategy:?}", case.name);
            if out.is_empty() {
                // nothing but zero-width rings (issue107): polytri's area is 0 once they
                // are dropped, the oracle's the rounding of their shoelace sums
                continue;
            }
            assert!(
                (ours - theirs).abs() <= 1e-9 * ours.max(theirs) + 1e-9,
                "{tag}: report {ours:e}, oracle {theirs:e}"
            );
            let integral =
                (input.vertices.iter().flatten()).all(|c| c.fract() == 0.0 && c.abs() < 1e6);
            if verdict.input_valid && integral {
                // twice every area is an exact integer: no rounding at all
                assert_eq!(ours, 0.0, "{tag}: a valid input's deviation");
            } else if ours > 1e-9 {
                crossing += 1;
            }
        }
    }
    assert!(
        crossing > 4,
        "crossing fixtures with a measurable deviation: {crossing}"
    );
}
