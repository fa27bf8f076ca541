//! polytri (fast strict, fast lenient, quality) against every peer, side by side.
//!
//! Inputs: earcut's benchmark fixtures, the paper-shaped datasets of `corpus/datasets/`
//! (each shape a polygon: polytri and earcut take them one by one, the others all at
//! once), and generated series of 10³ to 10⁶ vertices ([`polytri_oracle::series`]: a
//! random polygon, a star, a rectangle with many circular holes, a comb — the same inputs
//! `polytri bench --scaling` times). Each bench runs one input, one row per implementation;
//! inputs are converted into every library's format before timing
//! ([`Prepared`]), and every implementation keeps its buffers between runs ([`Runner`]).
//! polytri-check is strict mode's input check alone, without triangulating.
//!
//! `cargo bench -p polytri-oracle --bench peers -- water` runs the benches whose name
//! contains `water`. Some peers are quadratic on some generated families: from 10⁵
//! vertices on, an implementation whose run is predicted to exceed a few seconds (from its
//! times at the two smaller sizes) is left out of that bench, with a line on stderr.

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::{Mutex, OnceLock};

use divan::Bencher;
use polytri_oracle::peers::{Implementation, Prepared, Runner};
use polytri_oracle::series::Series;
use polytri_oracle::{Input, Nesting, Role};

fn main() {
    divan::main();
}

/// Every implementation, as bench arguments.
fn implementations() -> Vec<Implementation> {
    Implementation::all()
}

fn corpus() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../corpus")
}

/// An earcut fixture: one polygon, first ring outer.
fn fixture(name: &str) -> Input {
    let path = corpus().join(format!("earcut/fixtures/{name}.json"));
    let text = std::fs::read_to_string(&path).expect("read fixture");
    let rings: Vec<Vec<[f64; 2]>> = serde_json::from_str(&text).expect("rings JSON");
    Input::from_rings(&rings, Nesting::FirstIsOuter)
}

/// A paper dataset: shapes JSON, each shape's first ring outer.
fn dataset(name: &str) -> Input {
    let path = corpus().join(format!("datasets/{name}.json"));
    let text = std::fs::read_to_string(&path).expect("read dataset");
    let shapes: Vec<Vec<Vec<[f64; 2]>>> = serde_json::from_str(&text).expect("shapes JSON");
    let roles = shapes
        .iter()
        .flat_map(|shape| (0..shape.len()).map(|k| if k == 0 { Role::Outer } else { Role::Hole }))
        .collect();
    let rings: Vec<Vec<[f64; 2]>> = shapes.into_iter().flatten().collect();
    Input::from_rings(&rings, Nesting::Roles(roles))
}

/// Prepared inputs, made once per process however many benches use them.
fn prepared(name: &str, make: impl FnOnce() -> Input) -> &'static Prepared {
    static CACHE: OnceLock<Mutex<HashMap<String, &'static Prepared>>> = OnceLock::new();
    let mut cache = CACHE
        .get_or_init(Default::default)
        .lock()
        .expect("cache lock");
    cache
        .entry(name.to_owned())
        .or_insert_with(|| Box::leak(Box::new(Prepared::new(&make()))))
}

/// Times `imp` on the input; an implementation that refuses it is left out (said once on
/// stderr) rather than timed failing.
fn bench(bencher: Bencher, imp: Implementation, name: &str, make: impl FnOnce() -> Input) {
    let input = prepared(name, make);
    let mut runner = Runner::new();
    if let Err(e) = runner.run(imp, input) {
        eprintln!("{name}: {imp} skipped: {e}");
        return;
    }
    bencher.bench_local(|| runner.run(imp, divan::black_box(input)));
}

macro_rules! fixtures {
    ($($fn_name:ident => $file:literal),* $(,)?) => {
        /// earcut's benchmark fixtures.
        mod earcut_fixtures {
            use super::*;
            $(
                #[divan::bench(args = implementations())]
                fn $fn_name(bencher: Bencher, imp: Implementation) {
                    bench(bencher, imp, $file, || fixture($file));
                }
            )*
        }
    };
}

fixtures! {
    building => "building",
    dude => "dude",
    water => "water",
    water_huge => "water-huge",
    water_huge2 => "water-huge2",
    water3 => "water3",
}

macro_rules! datasets {
    ($($fn_name:ident),* $(,)?) => {
        /// The paper-shaped datasets, every shape a polygon.
        mod datasets {
            use super::*;
            $(
                #[divan::bench(args = implementations(), max_time = 3)]
                fn $fn_name(bencher: Bencher, imp: Implementation) {
                    bench(bencher, imp, stringify!($fn_name), || dataset(stringify!($fn_name)));
                }
            )*
        }
    };
}

datasets! {
    letter_a,
    lorem_latin,
    lorem_japanese,
    lorem_japanese_noto,
    rect_circles,
    chinese_text,
    cjk_page,
}

/// Longest predicted single run a series bench still times, in seconds.
const SERIES_LIMIT: f64 = 5.0;

/// The seconds of one run of `imp` (the fastest of three) on `series` at size `n` (`None`
/// when it refuses the input or was left out as too slow), measured once per process.
fn single_run(series: Series, n: usize, imp: Implementation) -> Option<f64> {
    type Key = (Series, usize, Implementation);
    static TIMES: OnceLock<Mutex<HashMap<Key, Option<f64>>>> = OnceLock::new();
    let key = (series, n, imp);
    if let Some(&known) = TIMES
        .get_or_init(Default::default)
        .lock()
        .expect("lock")
        .get(&key)
    {
        return known;
    }
    let seconds = if too_slow(series, n, imp) {
        None
    } else {
        let input = prepared(&format!("{series}-{n}"), || series.input(n));
        let mut runner = Runner::new();
        // the fastest of three, so a cold first run does not flatten the growth
        (0..3)
            .map(|_| {
                let start = std::time::Instant::now();
                runner
                    .run(imp, input)
                    .ok()
                    .map(|_| start.elapsed().as_secs_f64())
            })
            .try_fold(f64::INFINITY, |best, t| t.map(|t| best.min(t)))
    };
    TIMES
        .get_or_init(Default::default)
        .lock()
        .expect("lock")
        .insert(key, seconds);
    seconds
}

/// Whether one run at size `n` is predicted to take longer than [`SERIES_LIMIT`]: the
/// growth from n/100 to n/10 extrapolated one step (at least linear). Some peers are
/// quadratic on some families, and a 10⁶-vertex run would then take hours.
fn too_slow(series: Series, n: usize, imp: Implementation) -> bool {
    if n < 100_000 {
        return false;
    }
    let (Some(small), Some(smaller)) = (
        single_run(series, n / 10, imp),
        single_run(series, n / 100, imp),
    ) else {
        return true;
    };
    let growth = (small / smaller.max(1e-9)).max(10.0);
    small * growth > SERIES_LIMIT
}

macro_rules! series {
    ($module:ident = $series:expr; $($fn_name:ident => $n:literal),* $(,)?) => {
        /// A generated series at growing sizes.
        mod $module {
            use super::*;
            $(
                #[divan::bench(args = implementations(), sample_count = 10, max_time = 3)]
                fn $fn_name(bencher: Bencher, imp: Implementation) {
                    let series: Series = $series;
                    if too_slow(series, $n, imp) {
                        eprintln!("{series}-{}: {imp} skipped: predicted over {SERIES_LIMIT} s a run", $n);
                        return;
                    }
                    let name = format!("{series}-{}", $n);
                    bench(bencher, imp, &name, || series.input($n));
                }
            )*
        }
    };
}

series!(random = Series::Random; n_1e3 => 1_000, n_1e4 => 10_000, n_1e5 => 100_000, n_1e6 => 1_000_000);
series!(star = Series::Star; n_1e3 => 1_000, n_1e4 => 10_000, n_1e5 => 100_000, n_1e6 => 1_000_000);
series!(circles = Series::Circles; n_1e3 => 1_000, n_1e4 => 10_000, n_1e5 => 100_000, n_1e6 => 1_000_000);
series!(comb = Series::Comb; n_1e3 => 1_000, n_1e4 => 10_000, n_1e5 => 100_000, n_1e6 => 1_000_000);
series!(pinwheel = Series::Pinwheel; n_1e3 => 1_000, n_1e4 => 10_000, n_1e5 => 100_000);
