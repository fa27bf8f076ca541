//! Verifies a triangulation given as JSON files, the way `polytri check` does, through the
//! library: `cargo run -p polytri-oracle --example verify -- RINGS.json TRIANGLES.json`,
//! where RINGS.json is `[[[x, y], …], …]` (any ring order and winding) and TRIANGLES.json
//! `[[a, b, c], …]` (indices into the rings' points, in order). Prints every failed check;
//! exits with 1 when the triangulation is not one of the polygon.

use std::process::ExitCode;

fn read<T: serde::de::DeserializeOwned>(path: &str) -> Result<T, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    serde_json::from_str(&text).map_err(|e| format!("{path}: {e}"))
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [rings, triangles] = args.as_slice() else {
        eprintln!("usage: verify RINGS.json TRIANGLES.json");
        return ExitCode::from(2);
    };
    let (rings, triangles): (Vec<Vec<[f64; 2]>>, Vec<[u32; 3]>) =
        match (read(rings), read(triangles)) {
            (Ok(r), Ok(t)) => (r, t),
            (Err(e), _) | (_, Err(e)) => {
                eprintln!("verify: {e}");
                return ExitCode::from(2);
            }
        };
    let mut vertices = Vec::new();
    let mut ring_starts = Vec::new();
    for ring in &rings {
        ring_starts.push(vertices.len());
        vertices.extend_from_slice(ring);
    }
    let verdict =
        polytri_oracle::verify(&vertices, &ring_starts, polytri::Nesting::Auto, &triangles);
    for failure in verdict.failures() {
        println!("{failure}");
    }
    println!(
        "{}",
        if verdict.valid {
            "valid"
        } else {
            "not a triangulation of the polygon"
        }
    );
    if verdict.valid {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
