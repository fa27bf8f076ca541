//! Runs polytri on one rings or shapes JSON file many times, for a profiler:
//! `cargo run --release -p polytri --example profile -- FILE [RUNS] [fast|lenient|quality|check|even-odd|nonzero|threads:N] [first|auto]`
//! (`threads:N` needs `--features threads`).
//! With `NO_SMALL` set in the environment every input takes the whole pipeline, never
//! the small stage.
//! Shapes go one polygon at a time (first ring outer, unless `auto` asks for nesting by
//! containment), as `polytri bench` gives them.

use polytri::{Nesting, Options, Strategy, Triangulator};

type Rings = Vec<Vec<[f64; 2]>>;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = args
        .get(1)
        .expect("usage: profile FILE [RUNS] [fast|lenient|quality|check|threads:N|[seidel-]RULE]");
    let runs: usize = args.get(2).map_or(100, |r| r.parse().expect("RUNS"));
    let mode = args.get(3).map_or("lenient", String::as_str);
    let nesting = match args.get(4).map_or("first", String::as_str) {
        "first" => Nesting::FirstIsOuter,
        "auto" => Nesting::Auto,
        other => panic!("unknown nesting {other}"),
    };
    let text = std::fs::read_to_string(path).expect("readable file");
    let value: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let shapes: Vec<Rings> = if value[0][0][0].is_array() {
        serde_json::from_value(value).expect("shapes JSON")
    } else {
        vec![serde_json::from_value(value).expect("rings JSON")]
    };
    let flat: Vec<(Vec<[f64; 2]>, Vec<usize>)> = shapes
        .iter()
        .map(|rings| {
            let mut starts = Vec::new();
            let mut vertices = Vec::new();
            for ring in rings {
                starts.push(vertices.len());
                vertices.extend_from_slice(ring);
            }
            (vertices, starts)
        })
        .collect();
    let options = Options::new().with_nesting(nesting);
    // `threads:N`: the fast strategy through `triangulate_many` on N threads (0: every core)
    let threads = mode
        .strip_prefix("threads:")
        .map(|n| n.parse().expect("threads:N"));
    let options = match mode {
        // `check` takes only the nesting convention
        "fast" | "check" => options,
        _ if threads.is_some() => options.with_threads(threads.unwrap_or(1)),
        "lenient" => options.with_lenient(true),
        "quality" => options.with_strategy(Strategy::Quality),
        // a fill rule by name, through Seidel's trapezoidation with `seidel-` before it
        other => {
            let (options, rule) = match other.strip_prefix("seidel-") {
                Some(rule) => (options.with_strategy(Strategy::Seidel), rule),
                None => (options, other),
            };
            let rule = match rule {
                "even-odd" => polytri::FillRule::EvenOdd,
                "nonzero" => polytri::FillRule::NonZero,
                "positive" => polytri::FillRule::Positive,
                "negative" => polytri::FillRule::Negative,
                "abs-geq-two" => polytri::FillRule::AbsGeqTwo,
                _ => panic!("unknown mode {other}"),
            };
            options.with_fill_rule(rule)
        }
    };
    let mut tri = Triangulator::<f64>::new();
    tri.set_small_rings(std::env::var_os("NO_SMALL").is_none());
    let mut out = Vec::new();
    let mut triangles = 0;
    let many: Vec<(&[[f64; 2]], &[usize])> = flat.iter().map(|(v, s)| (&v[..], &s[..])).collect();
    let mut many_out = Vec::new();
    let began = std::time::Instant::now();
    for _ in 0..runs {
        if threads.is_some() {
            let results = tri.triangulate_many(&many, &options, &mut many_out);
            triangles += results
                .iter()
                .map(|r| r.as_ref().map_or(0, |r| r.triangles))
                .sum::<usize>();
            continue;
        }
        for (vertices, starts) in &flat {
            if mode == "check" {
                triangles += usize::from(tri.check(vertices, starts, nesting).is_ok());
                continue;
            }
            triangles += tri
                .triangulate(vertices, starts, &options, &mut out)
                .map_or(0, |r| r.triangles);
        }
    }
    let per_run = began.elapsed().as_secs_f64() / runs as f64;
    println!(
        "{path}: {} triangles per run, {:.9} ms per run",
        triangles / runs.max(1),
        per_run * 1e3
    );
}
