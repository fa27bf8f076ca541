//! How long `triangulate_many` takes on threads that have been idle: a measuring tool for
//! the parallel column of `polytri bench` (no timing is ever asserted).
//!
//! ```text
//! cargo run --release -p polytri --features threads --example idle_threads -- SHAPES.json [RUNS] [THREADS]
//! ```
//!
//! SHAPES.json is a list of polygons, each a list of rings (`[[[[x, y], …], …], …]`), as
//! `polytri bench` reads a page of glyphs. The page goes to `triangulate_many` on one
//! thread and on THREADS (default 2), RUNS times each (default 100) after an idle gap of
//! 0, 1, 5 and 20 ms, and the median milliseconds per call are printed. Called back to
//! back, the pool's threads are awake; after a gap they have gone to sleep, and the call
//! pays for waking them (on the 2-core virtual machine of `docs/performance.md`, a thread
//! asleep for 20 ms took about 2 ms to start its first job, one idle for 5 ms 0.07 ms).

use std::time::{Duration, Instant};

use polytri::{Nesting, Options, Triangulator};

type Rings = Vec<Vec<[f64; 2]>>;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let Some(path) = args.get(1) else {
        return Err("usage: idle_threads SHAPES.json [RUNS] [THREADS]".into());
    };
    let runs: usize = args.get(2).map_or(Ok(100), |r| r.parse())?.max(1);
    let threads: usize = args.get(3).map_or(Ok(2), |t| t.parse())?;
    let shapes: Vec<Rings> = serde_json::from_str(&std::fs::read_to_string(path)?)?;
    let flat: Vec<(Vec<[f64; 2]>, Vec<usize>)> = shapes
        .iter()
        .map(|rings| {
            let starts = (rings.iter())
                .scan(0, |at, ring| {
                    let start = *at;
                    *at += ring.len();
                    Some(start)
                })
                .collect();
            (rings.concat(), starts)
        })
        .collect();
    let page: Vec<(&[[f64; 2]], &[usize])> = flat.iter().map(|(v, s)| (&v[..], &s[..])).collect();
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    println!("gap ms   1 thread ms   {threads} threads ms");
    for gap in [0, 1, 5, 20] {
        let mut row = format!("{gap:>6}");
        for count in [1, threads] {
            let options = Options::new()
                .with_nesting(Nesting::Auto)
                .with_threads(count);
            // warm: the workers' buffers are allocated on their first use
            tri.triangulate_many(&page, &options, &mut out);
            let mut times = Vec::with_capacity(runs);
            for _ in 0..runs {
                std::thread::sleep(Duration::from_millis(gap));
                let began = Instant::now();
                let results = tri.triangulate_many(&page, &options, &mut out);
                times.push(began.elapsed().as_secs_f64() * 1e3);
                if let Some(Err(e)) = results.into_iter().find(Result::is_err) {
                    return Err(format!("a polygon failed: {e}").into());
                }
            }
            times.sort_by(f64::total_cmp);
            row += &format!("   {:>11.3}", times[times.len() / 2]);
        }
        println!("{row}");
    }
    Ok(())
}
