//! polytri (fast strict, fast lenient, quality) against every peer, side by side.
//!
//! Inputs: earcut's benchmark fixtures, the paper-shaped datasets of `corpus/datasets/`
//! (each shape a polygon: polytri and earcut take them one by one, the others all at
//! once), and generated series of 10³ to 10⁶ vertices (a random star, a rectangle with
//! many circular holes, a comb). Each bench runs one input, one row per implementation;
//! inputs are converted into every library's format before timing
//! ([`Prepared`]), and every implementation keeps its buffers between runs ([`Runner`]).
//! polytri-fast against polytri-lenient is the cost of the strict input check.
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

/// A small seeded generator (SplitMix64): benchmarks need the same inputs every run, not
/// good randomness.
struct SplitMix(u64);

impl SplitMix {
    /// A uniform float in `[0, 1)`.
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A star-shaped polygon of `n` vertices: evenly spread angles, random radii in [0.2, 1].
fn star(n: usize) -> Input {
    let mut rng = SplitMix(n as u64);
    let ring: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let angle = std::f64::consts::TAU * k as f64 / n as f64;
            let radius = 0.2 + 0.8 * rng.next();
            [radius * angle.cos(), radius * angle.sin()]
        })
        .collect();
    Input::from_rings(&[ring], Nesting::FirstIsOuter)
}

/// A rectangle with 32-gon holes on a grid, about `n` vertices in all.
fn circles(n: usize) -> Input {
    const SIDES: usize = 32;
    let holes = (n / SIDES).max(1);
    let columns = (holes as f64).sqrt().ceil() as usize;
    let rows = holes.div_ceil(columns);
    let mut rng = SplitMix(n as u64 ^ 0xC1C1);
    let mut rings = vec![vec![
        [0.0, 0.0],
        [columns as f64, 0.0],
        [columns as f64, rows as f64],
        [0.0, rows as f64],
    ]];
    for h in 0..holes {
        let center = [(h % columns) as f64 + 0.5, (h / columns) as f64 + 0.5];
        let radius = 0.3 + 0.15 * rng.next();
        rings.push(
            (0..SIDES)
                .map(|k| {
                    let angle = std::f64::consts::TAU * k as f64 / SIDES as f64;
                    [
                        center[0] + radius * angle.cos(),
                        center[1] + radius * angle.sin(),
                    ]
                })
                .collect(),
        );
    }
    Input::from_rings(&rings, Nesting::FirstIsOuter)
}

/// A comb: about `n / 4` thin teeth on a spine, every tooth tip a reflex-free spike and
/// every gap a reflex pair — the worst shape for naive ear search.
fn comb(n: usize) -> Input {
    let teeth = (n.saturating_sub(2) / 4).max(1);
    let mut ring = Vec::with_capacity(4 * teeth + 2);
    for t in 0..teeth {
        let x = 2.0 * t as f64;
        ring.extend_from_slice(&[[x, 1.0], [x, 10.0], [x + 1.0, 10.0], [x + 1.0, 1.0]]);
    }
    let end = 2.0 * teeth as f64 - 1.0;
    ring.extend_from_slice(&[[end, 0.0], [0.0, 0.0]]);
    Input::from_rings(&[ring], Nesting::FirstIsOuter)
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

/// The seconds of one run of `imp` (the fastest of three) on `family` at size `n` (`None` when it refuses the
/// input or was left out as too slow), measured once per process.
fn single_run(
    family: &str,
    make: fn(usize) -> Input,
    n: usize,
    imp: Implementation,
) -> Option<f64> {
    type Key = (String, usize, Implementation);
    static TIMES: OnceLock<Mutex<HashMap<Key, Option<f64>>>> = OnceLock::new();
    let key = (family.to_owned(), n, imp);
    if let Some(&known) = TIMES
        .get_or_init(Default::default)
        .lock()
        .expect("lock")
        .get(&key)
    {
        return known;
    }
    let seconds = if too_slow(family, make, n, imp) {
        None
    } else {
        let input = prepared(&format!("{family}-{n}"), || make(n));
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
fn too_slow(family: &str, make: fn(usize) -> Input, n: usize, imp: Implementation) -> bool {
    if n < 100_000 {
        return false;
    }
    let (Some(small), Some(smaller)) = (
        single_run(family, make, n / 10, imp),
        single_run(family, make, n / 100, imp),
    ) else {
        return true;
    };
    let growth = (small / smaller.max(1e-9)).max(10.0);
    small * growth > SERIES_LIMIT
}

macro_rules! series {
    ($family:ident: $($fn_name:ident => $n:literal),* $(,)?) => {
        /// A generated family at growing sizes.
        mod $family {
            use super::*;
            $(
                #[divan::bench(args = implementations(), sample_count = 10, max_time = 3)]
                fn $fn_name(bencher: Bencher, imp: Implementation) {
                    let family = stringify!($family);
                    if too_slow(family, super::$family, $n, imp) {
                        eprintln!("{family}-{}: {imp} skipped: predicted over {SERIES_LIMIT} s a run", $n);
                        return;
                    }
                    let name = format!("{family}-{}", $n);
                    bench(bencher, imp, &name, || super::$family($n));
                }
            )*
        }
    };
}

series!(star: n_1e3 => 1_000, n_1e4 => 10_000, n_1e5 => 100_000, n_1e6 => 1_000_000);
series!(circles: n_1e3 => 1_000, n_1e4 => 10_000, n_1e5 => 100_000, n_1e6 => 1_000_000);
series!(comb: n_1e3 => 1_000, n_1e4 => 10_000, n_1e5 => 100_000, n_1e6 => 1_000_000);
