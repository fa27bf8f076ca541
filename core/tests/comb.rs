//! A comb (the scaling benchmarks' worst case for the fast walk): after its teeth are cut,
//! the spine is a straight run of reflex vertices fanned from a bottom corner, every fan
//! ear behind the walk and its triangle spanning the whole spine. The walk then jumps over
//! marked tips and the ear test looks only along the triangle (their debug assertions
//! check the jumps against the step-by-step walk); the result must stay a valid
//! triangulation, in every rotation and strategy.

mod common;

use common::{check, flatten, rotate};
use polytri::{Nesting, Options, Strategy, Triangulator};

/// `teeth` teeth of width 1, height 9 and gap 1 on a spine (as `polytri_oracle::series`).
fn comb(teeth: usize) -> Vec<[f64; 2]> {
    let tooth = |x: f64| [[x, 1.0], [x, 10.0], [x + 1.0, 10.0], [x + 1.0, 1.0]];
    let mut ring: Vec<[f64; 2]> = (0..teeth).flat_map(|t| tooth(2.0 * t as f64)).collect();
    ring.extend([[2.0 * teeth as f64 - 1.0, 0.0], [0.0, 0.0]]);
    ring
}

#[test]
fn a_long_comb_triangulates_validly_in_every_rotation() {
    let teeth = 600;
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    for strategy in [Strategy::Fast, Strategy::Quality] {
        for k in 0..4 {
            let flat = flatten(&rotate(&[comb(teeth)], k));
            let options = Options::default()
                .with_strategy(strategy)
                .with_nesting(Nesting::FirstIsOuter);
            tri.triangulate(&flat.vertices, &flat.ring_starts, &options, &mut out)
                .expect("a comb is valid input");
            let stats = check(&flat.vertices, &flat.rings, &out)
                .unwrap_or_else(|e| panic!("{strategy:?}, rotation {k}: {e}"));
            // n − 2 triangles for n = 4·teeth + 2 vertices, less two for (0, 1) and
            // (end, 1): straight on the comb's sides, dropped as collinear before clipping
            assert_eq!(stats.triangles, 4 * teeth - 2, "{strategy:?}, rotation {k}");
            assert_eq!(stats.deviation, 0.0);
        }
    }
}
