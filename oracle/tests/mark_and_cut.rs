//! Mark-and-cut: the fast strategy clipping one large polygon on several threads gives the
//! same triangles for every thread count from two on, alone or in a batch, and the oracle
//! accepts them. The sizes it runs from and chunks by are lowered so that inputs of a few
//! thousand vertices take it, in many chunks (its defaults suit much larger ones).

use polytri::{Options, Triangulator};
use polytri_oracle::gen::{generate, Family, Params};
use polytri_oracle::series::Series;
use polytri_oracle::{check_with, CheckOptions, Input};

const SIZE: usize = 12_000;

/// Rings of at least this many nodes take mark-and-cut here, in chunks of this many.
const MIN: usize = 2_000;
const CHUNK: usize = 500;

fn inputs() -> Vec<(String, Input)> {
    let mut inputs: Vec<(String, Input)> = Series::ALL
        .into_iter()
        .map(|s| (format!("series {s}"), s.input(SIZE)))
        .collect();
    for (k, family) in Family::ALL.into_iter().enumerate() {
        inputs.push((
            format!("family {family}"),
            generate(family, 40 + k as u64, &Params::new(SIZE)).input,
        ));
    }
    inputs
}

fn options(input: &Input, threads: usize) -> Options {
    let nesting = input.nesting.to_polytri().expect("one polygon");
    Options::new().with_nesting(nesting).with_threads(threads)
}

fn triangulate(input: &Input, threads: usize) -> Vec<[u32; 3]> {
    let mut tri = Triangulator::<f64>::new();
    tri.set_mark_and_cut(MIN, CHUNK);
    let mut out = Vec::new();
    tri.triangulate(
        &input.vertices,
        &input.ring_starts,
        &options(input, threads),
        &mut out,
    )
    .expect("valid input");
    // the log names disjoint runs of the output, in order, marked by one of the threads
    let log = tri.mark_and_cut_log();
    assert!(threads > 1 || log.is_empty());
    let mut end = 0;
    for &[first, last, thread, _] in log {
        assert!(end <= first && first < last && last as usize <= out.len());
        assert!((thread as usize) < threads);
        end = last;
    }
    out
}

#[test]
fn the_same_triangles_for_every_thread_count_and_valid() {
    let mut differed = Vec::new();
    for (name, input) in inputs() {
        let one = triangulate(&input, 1);
        let two = triangulate(&input, 2);
        for threads in [3, 4] {
            assert!(
                triangulate(&input, threads) == two,
                "{name}: {threads} threads cut other triangles than 2"
            );
        }
        for (threads, tris) in [(1, &one), (2, &two)] {
            let verdict = check_with(&input, tris, &CheckOptions::fast());
            assert!(
                verdict.valid,
                "{name}, {threads} thread(s): {:?}",
                verdict.failures()
            );
        }
        if one != two {
            differed.push(name);
        }
    }
    // the rounds cut ears in another order than the walk: where that shows, mark-and-cut ran
    for name in [
        "series random",
        "series star",
        "family spiral",
        "family many-holes",
    ] {
        assert!(
            differed.iter().any(|n| n == name),
            "mark-and-cut did not run on {name} (it did on {differed:?})"
        );
    }
}

/// In a batch, each large input is clipped by mark-and-cut as it would be alone.
#[test]
fn a_batch_clips_each_input_as_alone() {
    // the series, every one nested first ring outer
    let inputs: Vec<Input> = inputs().into_iter().map(|(_, i)| i).take(5).collect();
    let batch: Vec<(&[[f64; 2]], &[usize])> = inputs
        .iter()
        .map(|i| (&i.vertices[..], &i.ring_starts[..]))
        .collect();
    let mut tri = Triangulator::<f64>::new();
    tri.set_mark_and_cut(MIN, CHUNK);
    let mut out = Vec::new();
    let results = tri.triangulate_many(&batch, &options(&inputs[0], 2), &mut out);
    for (k, input) in inputs.iter().enumerate() {
        assert!(results[k].is_ok(), "input {k}: {:?}", results[k]);
        assert!(out[k] == triangulate(input, 2), "input {k}");
    }
}
