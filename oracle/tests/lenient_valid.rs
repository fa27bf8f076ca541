//! Lenient mode on valid input must give a valid triangulation, as strict mode does.
//! `corpus.rs` replays our regression cases (`corpus/cases`) and earcut's fixtures in
//! strict mode, and in lenient mode only those the oracle finds invalid; `paper.rs` runs
//! lenient mode on the paper's figures and datasets. Here lenient mode runs on every case
//! and fixture the oracle finds valid — both strategies, both precisions (f32 where the
//! rounded input stays valid), the four exact rotations — and the oracle judges each
//! result. Lenient mode reads rings differently (it cuts a ring touching itself into its
//! lobes), so a valid input can take a path strict mode never does: `raw_rings` found one
//! (`lobe_on_a_ring_of_its_own_cancels_it_whole`).

mod common;

use std::time::Duration;

use common::{assert_no_failures, corpus_dir, guarded_triangulate, seen};
use polytri::{Options, Strategy};
use polytri_oracle::replay::{load_dir, rotate, Precision, ROTATIONS};
use polytri_oracle::{check_with, CheckOptions};

const TIMEOUT: Duration = Duration::from_secs(120);

#[test]
fn lenient_mode_triangulates_every_valid_case_validly() {
    let mut failures = Vec::new();
    let mut judged = 0;
    for folder in ["cases", "earcut"] {
        let cases = load_dir(&corpus_dir().join(folder)).unwrap_or_else(|e| panic!("{e}"));
        for case in cases {
            let nesting = (case.input.nesting.to_polytri()).unwrap_or(polytri::Nesting::Auto);
            for precision in [Precision::F64, Precision::F32] {
                let input = seen(&case.input, precision);
                if !check_with(&input, &[], &CheckOptions::fast()).input_valid {
                    continue;
                }
                for rotation in ROTATIONS {
                    let rotated = rotate(&case.input, rotation);
                    for strategy in [Strategy::Fast, Strategy::Quality] {
                        let tag = format!(
                            "{folder}/{} {strategy:?} {precision} rot {rotation}",
                            case.name
                        );
                        let opts = Options::default()
                            .with_strategy(strategy)
                            .with_nesting(nesting)
                            .with_lenient(true);
                        let run = match guarded_triangulate(&rotated, opts, precision, TIMEOUT) {
                            Ok(Ok(run)) => run,
                            Ok(Err(e)) => {
                                failures.push(format!("{tag}: lenient mode refused: {e}"));
                                continue;
                            }
                            Err(e) => {
                                failures.push(format!("{tag}: {e}"));
                                continue;
                            }
                        };
                        let verdict = check_with(
                            &seen(&rotated, precision),
                            &run.triangles,
                            &CheckOptions::fast(),
                        );
                        judged += 1;
                        if !verdict.valid {
                            failures.push(format!("{tag}: {}", verdict.failures().join("; ")));
                        }
                    }
                }
            }
        }
    }
    assert_no_failures(&failures);
    assert!(judged > 300, "only {judged} runs judged");
}
