mod common;
use std::time::{Duration, Instant};
#[test]
fn probe() {
    let strat = match std::env::var("STRAT").as_deref() {
        Ok("fast") => polytri::Strategy::Fast,
        _ => polytri::Strategy::Quality,
    };
    let mut names: Vec<String> = std::fs::read_dir(common::corpus_dir().join("earcut/fixtures"))
        .unwrap()
        .map(|e| {
            e.unwrap()
                .path()
                .file_stem()
                .unwrap()
                .to_str()
                .unwrap()
                .to_string()
        })
        .collect();
    names.sort();
    for name in names {
        let rings =
            common::rings_from_json(&common::read_json(&format!("earcut/fixtures/{name}.json")));
        for rot in 0..4 {
            let flat = common::flatten(&common::rotate(&rings, rot));
            let t = Instant::now();
            let (v, s) = (flat.vertices.clone(), flat.ring_starts.clone());
            let r = common::guarded(Duration::from_secs(10), move || {
                let opts = polytri::Options::default()
                    .with_strategy(strat)
                    .with_nesting(polytri::Nesting::FirstIsOuter)
                    .with_lenient(true);
                let mut out = Vec::new();
                polytri::Triangulator::<f64>::new()
                    .triangulate(&v, &s, &opts, &mut out)
                    .map(|_| out.len())
            });
            let el = t.elapsed();
            if el > Duration::from_millis(200) || r.is_err() {
                println!(
                    "{name} rot {rot}: {:?} {:?}",
                    el,
                    r.as_ref()
                        .map(|x| x.as_ref().map(|_| ()).map_err(|e| e.to_string()))
                );
            }
        }
    }
}
