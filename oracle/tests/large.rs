//! Inputs larger than the pool size from which the fast strategy first lays its nodes out
//! in ring order (2¹⁴ nodes, `clip::LAY_OUT_MIN`): scaling series at 40 000 vertices, fast
//! strategy (the quality strategy keeps its layout), judged by the oracle's exact checks.
//! The series are valid by construction (simple rings, holes apart, first ring outer).
//!
//! The star is left out (the exact check of its long thin triangles takes seconds in a debug
//! build, and its walk never laps), and so is lenient mode on the comb (the same walk, with
//! jumps, as strict mode there: the input has no crossings).

use polytri::{Nesting as TriNesting, Options, Triangulator};
use polytri_oracle::series::Series;
use polytri_oracle::{check_with, CheckOptions};

#[test]
fn large_series_inputs_triangulate_validly() {
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    for (series, lenient) in [
        (Series::Random, false),
        (Series::Random, true),
        (Series::Circles, false),
        (Series::Circles, true),
        (Series::Comb, false),
    ] {
        let input = series.input(40_000);
        assert!(input.vertices.len() > 1 << 14, "{series}: too small");
        let options = Options::new()
            .with_nesting(TriNesting::FirstIsOuter)
            .with_lenient(lenient);
        let what = format!("{series}, lenient {lenient}");
        if let Err(e) = tri.triangulate(&input.vertices, &input.ring_starts, &options, &mut out) {
            panic!("{what}: refused a valid input: {e}");
        }
        let verdict = check_with(&input, &out, &CheckOptions::fast());
        assert!(verdict.valid, "{what}: {:?}", verdict.failures());
    }
}
