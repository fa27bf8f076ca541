//! Helpers shared by the integration tests (each test uses some of them).
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

use polytri::{Dropped, Error, Options, Strategy, Triangulator};
use polytri_oracle::replay::{load_dir, load_file, CorpusCase, Precision};
use polytri_oracle::Input;

/// The earcut fixtures whose edges cross (`earcut_fixtures.rs` checks the list against the
/// oracle's input check).
pub const SELF_INTERSECTING: [&str; 6] = [
    "water",
    "water-huge",
    "water-huge2",
    "bad-hole",
    "issue142",
    "simplified-us-border",
];

/// The repository's `corpus/` folder.
pub fn corpus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../corpus")
}

/// earcut's fixtures (`corpus/earcut`, first ring outer) with their deviation bounds,
/// sorted by name.
pub fn earcut_fixtures() -> Vec<CorpusCase> {
    load_dir(&corpus_dir().join("earcut")).unwrap_or_else(|e| panic!("corpus/earcut: {e}"))
}

/// One of earcut's fixtures by name.
pub fn earcut_fixture(name: &str) -> Input {
    let path = corpus_dir().join(format!("earcut/fixtures/{name}.json"));
    load_file(&path, "earcut")
        .unwrap_or_else(|e| panic!("{e}"))
        .input
}

/// The coordinates a run in `precision` computes with, as `f64` (exact for `f32`).
pub fn seen(input: &Input, precision: Precision) -> Input {
    match precision {
        Precision::F64 => input.clone(),
        Precision::F32 => input.to_f32(),
    }
}

/// What one triangulation gave: the triangles and the report's lists.
#[derive(Clone, Debug)]
pub struct Run {
    pub triangles: Vec<[u32; 3]>,
    pub dropped: Vec<Dropped>,
    pub repairs: usize,
    pub clean: bool,
}

/// Triangulates `input` with `options` in `precision` (`f32`: the input rounded).
pub fn triangulate(input: &Input, options: &Options, precision: Precision) -> Result<Run, Error> {
    let mut out = Vec::new();
    let lists = |r: polytri::Report<'_>| (r.dropped.to_vec(), r.repairs.len(), r.is_clean());
    let (dropped, repairs, clean) = match precision {
        Precision::F64 => Triangulator::<f64>::new()
            .triangulate(&input.vertices, &input.ring_starts, options, &mut out)
            .map(lists)?,
        Precision::F32 => Triangulator::<f32>::new()
            .triangulate(&input.vertices_f32(), &input.ring_starts, options, &mut out)
            .map(lists)?,
    };
    Ok(Run {
        triangles: out,
        dropped,
        repairs,
        clean,
    })
}

/// [`triangulate`] on a thread of its own: a panic, or no result after `timeout`, is an
/// `Err` with what happened.
pub fn guarded_triangulate(
    input: &Input,
    options: Options,
    precision: Precision,
    timeout: Duration,
) -> Result<Result<Run, Error>, String> {
    let input = input.clone();
    guarded(timeout, move || triangulate(&input, &options, precision))
}

/// Runs `f` on its own thread: a panic or a run longer than `timeout` becomes an `Err`
/// (a hung thread is left behind and ends with the test process).
pub fn guarded<T: Send + 'static>(
    timeout: Duration,
    f: impl FnOnce() -> T + Send + 'static,
) -> Result<T, String> {
    let (tx, rx) = mpsc::channel();
    std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(move || {
            let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
            let _ = tx.send(r);
        })
        .expect("spawn");
    match rx.recv_timeout(timeout) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(payload)) => {
            let msg = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "non-string panic payload".into());
            Err(format!("PANIC: {msg}"))
        }
        Err(_) => Err(format!("HANG: no result after {timeout:?}")),
    }
}

/// Triangulates `input` in f64 with the nesting convention it names (`Auto` for explicit
/// roles), in `strategy`, strict or lenient; the error as its message.
pub fn run(input: &Input, strategy: Strategy, lenient: bool) -> Result<Vec<[u32; 3]>, String> {
    let nesting = input.nesting.to_polytri().unwrap_or(polytri::Nesting::Auto);
    let options = Options::default()
        .with_strategy(strategy)
        .with_nesting(nesting)
        .with_lenient(lenient);
    triangulate(input, &options, Precision::F64)
        .map(|r| r.triangles)
        .map_err(|e| e.to_string())
}

/// splitmix64: a small seeded generator for the tests' choices.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number below `n` (0 for `n` = 0).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// `rings` with random starts, either winding for all of them, in a random quarter turn
/// (exact): which vertex is rightmost-lowest changes.
pub fn shuffled(mut rings: Vec<Vec<[f64; 2]>>, rng: &mut Rng) -> Vec<Vec<[f64; 2]>> {
    for ring in &mut rings {
        let k = rng.below(ring.len());
        ring.rotate_left(k);
    }
    if rng.below(2) == 1 {
        for ring in &mut rings {
            ring.reverse();
        }
    }
    let quarter = rng.below(4);
    for p in rings.iter_mut().flatten() {
        let [x, y] = *p;
        *p = match quarter {
            0 => [x, y],
            1 => [-y, x],
            2 => [-x, -y],
            _ => [y, -x],
        };
    }
    rings
}

/// Fails, listing them, when there are failures.
pub fn assert_no_failures(failures: &[String]) {
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
