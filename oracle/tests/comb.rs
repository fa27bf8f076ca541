//! A comb (the scaling benchmarks' worst case for the fast walk): after its teeth are cut,
//! the spine is a straight run of reflex vertices fanned from a bottom corner, every fan
//! ear behind the walk and its triangle spanning the whole spine. The walk then jumps over
//! marked tips and the ear test looks only along the triangle (their debug assertions
//! check the jumps against the step-by-step walk); the result must stay a valid
//! triangulation, in every rotation and strategy.

use polytri::{Nesting, Options, Strategy, Triangulator};
use polytri_oracle::replay::{rotate, ROTATIONS};
use polytri_oracle::series::Series;
use polytri_oracle::{check_with, CheckOptions};

#[test]
fn a_long_comb_triangulates_validly_in_every_rotation() {
    let teeth = 600;
    // 4 vertices a tooth and the spine's two bottom corners.
    let comb = Series::Comb.input(4 * teeth + 2);
    assert_eq!(comb.vertices.len(), 4 * teeth + 2);
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    for strategy in [Strategy::Fast, Strategy::Quality] {
        for rotation in ROTATIONS {
            let input = rotate(&comb, rotation);
            let options = Options::default()
                .with_strategy(strategy)
                .with_nesting(Nesting::FirstIsOuter);
            tri.triangulate(&input.vertices, &input.ring_starts, &options, &mut out)
                .expect("a comb is valid input");
            let verdict = check_with(&input, &out, &CheckOptions::fast());
            assert!(
                verdict.valid,
                "{strategy:?}, rotation {rotation}: {:?}",
                verdict.failures()
            );
            // n − 2 triangles for n = 4·teeth + 2 vertices, less two for (0, 1) and
            // (end, 1): straight on the comb's sides, dropped as collinear before clipping
            assert_eq!(
                out.len(),
                4 * teeth - 2,
                "{strategy:?}, rotation {rotation}"
            );
            assert_eq!(verdict.deviation, 0.0);
        }
    }
}
