//! A large polygon with many holes, the first few of them overlapping their neighbours,
//! triangulated with the even-odd fill rule and, for comparison, in lenient mode:
//!
//! ```text
//! cargo run --release -p polytri --example fill_big -- [OUTER_VERTICES] [HOLES] [CROSSING_HOLES]
//! ```
//!
//! The defaults (1,000,000, 60,000, 300) make 1.72 million vertices. One run, one core,
//! wall time: a single measurement, not a benchmark.
use polytri::{FillRule, Options, Triangulator};
use std::time::Instant;

fn main() {
    let n_outer: usize = std::env::args()
        .nth(1)
        .map_or(1_000_000, |s| s.parse().unwrap());
    let holes: usize = std::env::args()
        .nth(2)
        .map_or(60_000, |s| s.parse().unwrap());
    let crossing: usize = std::env::args().nth(3).map_or(300, |s| s.parse().unwrap());
    let mut v: Vec<[f64; 2]> = Vec::new();
    let mut starts = vec![0];
    let r = 1000.0;
    for i in 0..n_outer {
        let t = i as f64 / n_outer as f64 * std::f64::consts::TAU;
        let wob = 1.0 + 0.01 * (t * 97.0).sin();
        v.push([r * wob * t.cos(), r * wob * t.sin()]);
    }
    let side = (holes as f64).sqrt().ceil() as usize;
    let cell = 1200.0 / side as f64;
    let mut k = 0;
    'outer: for i in 0..side {
        for j in 0..side {
            if k == holes {
                break 'outer;
            }
            let cx = -600.0 + (i as f64 + 0.5) * cell;
            let cy = -600.0 + (j as f64 + 0.5) * cell;
            // holes crossing their right neighbour for the first `crossing` of them
            let rad = if k < crossing { 0.7 * cell } else { 0.3 * cell };
            starts.push(v.len());
            for m in 0..12 {
                let t = -(m as f64) / 12.0 * std::f64::consts::TAU;
                v.push([cx + rad * t.cos(), cy + rad * t.sin()]);
            }
            k += 1;
        }
    }
    eprintln!("{} vertices, {} rings", v.len(), starts.len());
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    for rule in [Some(FillRule::EvenOdd), None] {
        let mut opts = Options::new();
        if let Some(r) = rule {
            opts = opts.with_fill_rule(r);
        } else {
            opts = opts.with_lenient(true);
        }
        let t = Instant::now();
        let rep = tri.triangulate(&v, &starts, &opts, &mut out);
        eprintln!(
            "{rule:?}: {:?} triangles {} added {} in {:.2} s",
            rep.as_ref().err(),
            out.len(),
            rep.map_or(0, |r| r.added.len()),
            t.elapsed().as_secs_f64()
        );
    }
}
