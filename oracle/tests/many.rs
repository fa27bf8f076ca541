//! `Triangulator::triangulate_many`: every input gets what `triangulate` gives it alone,
//! whatever the thread count, and the oracle accepts every triangulation.

use polytri::{Error, Options, Strategy, Triangulator};
use polytri_oracle::gen::{generate, Family, Params};
use polytri_oracle::{check, Input, Nesting};

/// One input's outcome as a plain value: triangles and report, or the error.
#[derive(Debug, PartialEq)]
struct Outcome {
    triangles: Vec<[u32; 3]>,
    result: Result<Report, Error>,
}

/// A `polytri::Report`, owned.
#[derive(Debug, PartialEq)]
struct Report {
    triangles: usize,
    polygons: usize,
    holes: usize,
    deviation: f64,
    dropped: Vec<polytri::Dropped>,
    repairs: Vec<polytri::Repair>,
}

/// Seeded inputs of every generator family and size, plus inputs strict mode refuses
/// (a bow tie, one ring twice) and an empty one, interleaved. Every input is nested by
/// containment (`Nesting::Auto`, the default), which generated inputs satisfy.
fn inputs() -> Vec<Input> {
    let mut inputs = Vec::new();
    for (k, family) in Family::ALL.into_iter().enumerate() {
        for seed in 0..6u64 {
            let size = [12, 40, 150, 600][(seed as usize + k) % 4];
            inputs.push(generate(family, 7000 + seed, &Params::new(size)).input);
        }
    }
    let bow_tie = Input::from_rings(
        &[vec![[0.0, 0.0], [4.0, 4.0], [4.0, 0.0], [0.0, 4.0]]],
        Nesting::Auto,
    );
    let square = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
    let twice = Input::from_rings(&[square.clone(), square], Nesting::Auto);
    for (k, odd) in [bow_tie, twice].into_iter().enumerate() {
        inputs.insert(5 + 17 * k, odd);
    }
    inputs.insert(30, Input::from_rings(&[], Nesting::Auto));
    inputs
}

fn outcome(triangles: &[[u32; 3]], report: Result<polytri::Report<'_>, Error>) -> Outcome {
    Outcome {
        triangles: triangles.to_vec(),
        result: report.map(|r| Report {
            triangles: r.triangles,
            polygons: r.polygons,
            holes: r.holes,
            deviation: r.deviation,
            dropped: r.dropped.to_vec(),
            repairs: r.repairs.to_vec(),
        }),
    }
}

/// Each input alone, each on a fresh triangulator: the reference.
fn one_by_one(inputs: &[Input], options: &Options) -> Vec<Outcome> {
    inputs
        .iter()
        .map(|input| {
            let mut out = Vec::new();
            let mut tri = Triangulator::<f64>::new();
            let report = tri.triangulate(&input.vertices, &input.ring_starts, options, &mut out);
            outcome(&out, report)
        })
        .collect()
}

fn many(tri: &mut Triangulator<f64>, inputs: &[Input], options: &Options) -> Vec<Outcome> {
    let polygons: Vec<(&[[f64; 2]], &[usize])> = inputs
        .iter()
        .map(|i| (&i.vertices[..], &i.ring_starts[..]))
        .collect();
    let mut out = vec![vec![[7, 7, 7]]; 3]; // stale entries: they must be replaced
    let results = tri.triangulate_many(&polygons, options, &mut out);
    assert_eq!(results.len(), inputs.len());
    assert_eq!(out.len(), inputs.len());
    results
        .into_iter()
        .zip(&out)
        .map(|(report, triangles)| outcome(triangles, report))
        .collect()
}

#[test]
fn every_thread_count_gives_what_each_input_gets_alone() {
    let inputs = inputs();
    for options in [
        Options::default(),
        Options::default().with_strategy(Strategy::Quality),
        Options::default().with_lenient(true),
    ] {
        let reference = one_by_one(&inputs, &options);
        // one triangulator for every run: its workers' buffers carry over, decisions not
        let mut tri = Triangulator::<f64>::new();
        for threads in [1, 2, 3, 0, 2] {
            let got = many(&mut tri, &inputs, &options.with_threads(threads));
            for (k, (got, want)) in got.iter().zip(&reference).enumerate() {
                assert_eq!(got, want, "input {k}, {threads} threads, {options:?}");
            }
        }
        // reversed order: each result still follows its input
        let mut reversed = inputs.clone();
        reversed.reverse();
        let got = many(&mut tri, &reversed, &options.with_threads(2));
        for (got, want) in got.iter().rev().zip(&reference) {
            assert_eq!(got, want);
        }
    }
}

#[test]
fn the_oracle_accepts_every_parallel_triangulation() {
    let inputs = inputs();
    let mut tri = Triangulator::<f64>::new();
    let options = Options::default().with_threads(2);
    let mut refused = 0;
    for (k, (input, got)) in inputs
        .iter()
        .zip(many(&mut tri, &inputs, &options))
        .enumerate()
    {
        match got.result {
            Ok(report) => {
                assert_eq!(report.triangles, got.triangles.len());
                let verdict = check(input, &got.triangles);
                assert!(verdict.valid, "input {k}: {:?}", verdict.failures());
            }
            Err(e) => {
                refused += 1;
                assert!(
                    !check(input, &[]).input_valid,
                    "input {k} is valid, refused: {e}"
                );
            }
        }
    }
    // the bow tie and the ring twice, nothing else
    assert_eq!(refused, 2);
}

#[test]
fn no_inputs_give_no_results() {
    let mut tri = Triangulator::<f32>::new();
    let mut out = vec![vec![[0, 1, 2]]];
    let results = tri.triangulate_many(&[], &Options::default().with_threads(0), &mut out);
    assert!(results.is_empty() && out.is_empty());
}

/// The whole regression corpus through `triangulate_many` on two threads gives each case
/// what `triangulate` gives it alone, in strict and lenient mode, each case with its own
/// nesting convention (one call per convention).
#[test]
fn the_corpus_on_two_threads_equals_one_by_one() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../corpus");
    let mut cases = Vec::new();
    for folder in ["earcut", "datasets", "paper", "cases"] {
        let loaded = polytri_oracle::replay::load_dir(&root.join(folder))
            .unwrap_or_else(|e| panic!("corpus/{folder}: {e}"));
        cases.extend(loaded.into_iter().map(|c| c.input));
    }
    assert!(cases.len() > 100, "{} corpus cases", cases.len());
    let mut tri = Triangulator::<f64>::new();
    for nesting in [polytri::Nesting::Auto, polytri::Nesting::FirstIsOuter] {
        let inputs: Vec<Input> = (cases.iter())
            .filter(|c| c.nesting.to_polytri().unwrap_or(polytri::Nesting::Auto) == nesting)
            .cloned()
            .collect();
        for lenient in [false, true] {
            let options = Options::default()
                .with_nesting(nesting)
                .with_lenient(lenient);
            let reference = one_by_one(&inputs, &options);
            let got = many(&mut tri, &inputs, &options.with_threads(2));
            for (k, (got, want)) in got.iter().zip(&reference).enumerate() {
                assert_eq!(got, want, "case {k}, {options:?}");
            }
        }
    }
}
