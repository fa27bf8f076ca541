//! Times the triangulator on corpus files and on a generated stress input; a measuring
//! tool, not a test (no timing is ever asserted).
//!
//! ```text
//! cargo run --release -p polytri --example timing -- [FILE.json …] [--stress HOLES] [--reps N]
//!     [--only fast|quality|strict|lenient …]
//! ```
//!
//! A file is rings JSON (`[[[x, y], …], …]`, first ring outer) or shapes JSON (a list of
//! such polygons); all rings go to one call with `Nesting::Auto`. `--stress HOLES` adds a
//! rectangle with that many small circular holes on a jittered grid (seeded, no overlaps).
//! Each input runs Fast and Quality, strict and lenient (or only those named by `--only`);
//! the best of `--reps` runs on a warmed-up triangulator is printed in ms and million
//! triangles per second (wall-clock time: on a busy machine, raise `--reps`). Each result
//! line ends with a hash of the triangles, to check that two builds give the same output.

use std::time::Instant;

use polytri::{Options, Strategy, Triangulator};
use serde_json::Value;

/// Vertices and ring starts, as the triangulator takes them.
struct Input {
    name: String,
    vertices: Vec<[f64; 2]>,
    ring_starts: Vec<usize>,
}

fn main() {
    let mut inputs = Vec::new();
    let mut reps = 5;
    let mut only: Vec<String> = Vec::new();
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--reps" => reps = args.next().and_then(|s| s.parse().ok()).unwrap_or(reps),
            "--only" => only.extend(args.next()),
            "--stress" => {
                let holes = args.next().and_then(|s| s.parse().ok()).unwrap_or(60_000);
                inputs.push(stress(holes, 24, 2024));
            }
            path => inputs.push(read(path)),
        }
    }
    for input in &inputs {
        println!(
            "{}: {} vertices, {} rings",
            input.name,
            input.vertices.len(),
            input.ring_starts.len()
        );
        for strategy in [Strategy::Fast, Strategy::Quality] {
            for lenient in [false, true] {
                let names = [
                    if strategy == Strategy::Fast {
                        "fast"
                    } else {
                        "quality"
                    },
                    if lenient { "lenient" } else { "strict" },
                ];
                let wanted = |group: &[&str]| {
                    let named: Vec<_> = only
                        .iter()
                        .filter(|o| group.contains(&o.as_str()))
                        .collect();
                    named.is_empty() || named.iter().any(|o| names.contains(&o.as_str()))
                };
                if !wanted(&["fast", "quality"]) || !wanted(&["strict", "lenient"]) {
                    continue;
                }
                let opts = Options::default()
                    .with_strategy(strategy)
                    .with_lenient(lenient);
                time(input, &opts, reps);
            }
        }
    }
}

/// Best-of-`reps` time of one configuration on a warmed-up triangulator.
fn time(input: &Input, opts: &Options, reps: usize) {
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    let mut best = f64::INFINITY;
    let mut result = String::new();
    for _ in 0..reps.max(1) {
        let started = Instant::now();
        let r = tri.triangulate(&input.vertices, &input.ring_starts, opts, &mut out);
        let ms = started.elapsed().as_secs_f64() * 1e3;
        best = best.min(ms);
        result = match r {
            Ok(report) => format!("{} triangles, hash {:016x}", report.triangles, hash(&out)),
            Err(e) => format!("error: {e}"),
        };
    }
    let rate = out.len() as f64 / best / 1e3;
    println!(
        "  {:<8} {:<8} {:>10.3} ms {:>8.2} Mtri/s  {result}",
        format!("{:?}", opts.strategy),
        if opts.lenient { "lenient" } else { "strict" },
        best,
        rate
    );
}

/// FNV-1a over the triangles: tells whether two builds give the very same output.
fn hash(triangles: &[[u32; 3]]) -> u64 {
    let mut h = 0xcbf2_9ce4_8422_2325_u64;
    for &i in triangles.iter().flatten() {
        for byte in i.to_le_bytes() {
            h = (h ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
        }
    }
    h
}

/// Reads rings JSON or shapes JSON.
fn read(path: &str) -> Input {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let json: Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut input = Input {
        name: path.rsplit('/').next().unwrap_or(path).to_string(),
        vertices: Vec::new(),
        ring_starts: Vec::new(),
    };
    add_rings(&mut input, &json);
    input
}

/// Adds rings (or, recursively, shapes) from JSON; empty rings are skipped.
fn add_rings(input: &mut Input, json: &Value) {
    let Some(items) = json.as_array() else { return };
    let is_ring = items
        .first()
        .and_then(|p| p.as_array())
        .and_then(|p| p.first())
        .is_some_and(|c| c.is_number());
    if !is_ring {
        for item in items {
            add_rings(input, item);
        }
        return;
    }
    if items.is_empty() {
        return;
    }
    input.ring_starts.push(input.vertices.len());
    for p in items {
        let c = p.as_array().map(|c| c.as_slice()).unwrap_or(&[]);
        let x = c.first().and_then(|v| v.as_f64()).unwrap_or(f64::NAN);
        let y = c.get(1).and_then(|v| v.as_f64()).unwrap_or(f64::NAN);
        input.vertices.push([x, y]);
    }
}

/// A rectangle with `holes` circular holes of `sides` vertices each, one per cell of a
/// square grid, jittered inside the cell so that no two holes meet (seeded xorshift).
fn stress(holes: usize, sides: usize, seed: u64) -> Input {
    let cols = (holes as f64).sqrt().ceil() as usize;
    let rows = holes.div_ceil(cols);
    let cell = 10.0;
    let mut state = seed.max(1);
    let mut random = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let (w, h) = (cols as f64 * cell, rows as f64 * cell);
    let mut input = Input {
        name: format!("stress: {holes} holes × {sides}"),
        vertices: vec![[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]],
        ring_starts: vec![0],
    };
    for k in 0..holes {
        let (i, j) = (k % cols, k / cols);
        let radius = cell * (0.2 + 0.15 * random());
        let slack = cell / 2.0 - radius - 0.5;
        let cx = (i as f64 + 0.5) * cell + slack * (2.0 * random() - 1.0);
        let cy = (j as f64 + 0.5) * cell + slack * (2.0 * random() - 1.0);
        let phase = random() * std::f64::consts::TAU;
        input.ring_starts.push(input.vertices.len());
        for s in 0..sides {
            let a = phase + s as f64 * std::f64::consts::TAU / sides as f64;
            input
                .vertices
                .push([cx + radius * a.cos(), cy + radius * a.sin()]);
        }
    }
    input
}
