//! mapbox/earcut's regression fixtures (`corpus/earcut`), run the way earcut's own test runs
//! them — every fixture rotated by 0°, 90°, 180° and 270° — through both strategies and both
//! precisions, with earcut's convention (`Nesting::FirstIsOuter`) in lenient mode.
//!
//! Checked per run: no panic or hang; `deviation` within earcut's recorded bound
//! (`expected.json`); and, for the fixtures that are valid polygons, the exact validity
//! check of `common::check_with_roles`. Failures are collected and reported together, one
//! line each.

mod common;

use std::time::Duration;

use common::{
    check_with_roles, deviation, first_is_outer, flatten, guarded, has_non_integer, input_defects,
    read_json, rings_from_json, rotate, to_f32, widen, Rings,
};
use polytri::{Nesting, Options, Strategy, Triangulator};
use serde_json::Value;

/// Fixtures whose edges cross: only the deviation bound applies to them.
const SELF_INTERSECTING: [&str; 6] = [
    "water",
    "water-huge",
    "water-huge2",
    "bad-hole",
    "issue142",
    "simplified-us-border",
];

/// Where polytri's lenient result is still further from the input's area than earcut's
/// (fixture, rotation, our measured deviation): these bounds replace earcut's until the gap
/// is closed, so they can only tighten. Tracked in issue 2's note. Empty since lenient
/// splits require diagonals the ring winds around (`water-huge2` at 0° with quality was
/// the last, 3.91e-3 against earcut's 3e-3, now 9.6e-4).
const KNOWN_GAPS: [(&str, u32, f64); 0] = [];

/// The slack allowed for round-off where coordinates are not integers.
const ROUND_OFF: f64 = 1e-13;

/// Longest a single triangulation may take (debug build) before it counts as a hang.
const TIMEOUT: Duration = Duration::from_secs(120);

struct Fixture {
    name: String,
    rings: Rings,
    expected_triangles: u64,
    /// Deviation bound at rotation 0, and at 90°/180°/270°.
    bound: f64,
    bound_rotated: f64,
}

fn fixtures() -> Vec<Fixture> {
    let expected = read_json("earcut/expected.json");
    let errors = &expected["errors"];
    let rotated = &expected["errors-with-rotation"];
    let mut names: Vec<&String> = expected["triangles"]
        .as_object()
        .expect("triangles")
        .keys()
        .collect();
    names.sort();
    names
        .into_iter()
        .map(|name| {
            let bound = errors.get(name).and_then(Value::as_f64).unwrap_or(0.0);
            Fixture {
                name: name.clone(),
                rings: rings_from_json(&read_json(&format!("earcut/fixtures/{name}.json"))),
                expected_triangles: expected["triangles"][name].as_u64().expect("count"),
                bound,
                bound_rotated: rotated.get(name).and_then(Value::as_f64).unwrap_or(bound),
            }
        })
        .collect()
}

#[derive(Clone, Copy, Debug)]
enum Precision {
    F64,
    F32,
}

/// Triangulates with lenient `FirstIsOuter` in the given precision.
fn triangulate(
    vertices: &[[f64; 2]],
    ring_starts: &[usize],
    strategy: Strategy,
    precision: Precision,
) -> Result<Vec<[u32; 3]>, polytri::Error> {
    let opts = Options::default()
        .with_strategy(strategy)
        .with_nesting(Nesting::FirstIsOuter)
        .with_lenient(true);
    let mut out = Vec::new();
    match precision {
        Precision::F64 => {
            Triangulator::<f64>::new().triangulate(vertices, ring_starts, &opts, &mut out)?;
        }
        Precision::F32 => {
            let v32 = to_f32(vertices);
            Triangulator::<f32>::new().triangulate(&v32, ring_starts, &opts, &mut out)?;
        }
    }
    Ok(out)
}

fn run_all(strategy: Strategy, precision: Precision) {
    let mut failures = Vec::new();
    let mut notes = Vec::new();
    for fx in fixtures() {
        for rotation in 0..4 {
            let flat = flatten(&rotate(&fx.rings, rotation));
            // The coordinates the triangulator sees, as f64 (exact for f32).
            let seen = match precision {
                Precision::F64 => flat.vertices.clone(),
                Precision::F32 => widen(&to_f32(&flat.vertices)),
            };
            let tag = format!(
                "{} rot {} {strategy:?} {precision:?}",
                fx.name,
                rotation * 90
            );
            let (v, s) = (flat.vertices.clone(), flat.ring_starts.clone());
            let tris = match guarded(TIMEOUT, move || triangulate(&v, &s, strategy, precision)) {
                Err(e) => {
                    failures.push(format!("{tag}: {e}"));
                    continue;
                }
                Ok(Err(e)) => {
                    failures.push(format!("{tag}: lenient mode returned Err({e:?}): {e}"));
                    continue;
                }
                Ok(Ok(t)) => t,
            };

            // The rounded input may cross where the f64 one does not.
            let rounded_changed = seen != flat.vertices;
            let rounded_defects = rounded_changed && !input_defects(&seen, &flat.rings).is_empty();
            if rounded_defects {
                notes.push(format!("{tag}: f32-rounded input has crossing/overlapping edges; only no-panic checked"));
                continue;
            }

            if fx.expected_triangles > 0 {
                let dev = deviation(&seen, &flat.ring_starts, &tris);
                let mut bound = if rotation == 0 {
                    fx.bound
                } else {
                    fx.bound_rotated
                };
                if has_non_integer(&seen) {
                    bound = bound.max(ROUND_OFF);
                }
                if let Some(&(_, _, gap)) = KNOWN_GAPS
                    .iter()
                    .find(|(n, r, _)| *n == fx.name && *r == rotation)
                {
                    bound = bound.max(gap);
                }
                if dev.is_nan() || dev > bound {
                    failures.push(format!(
                        "{tag}: deviation {dev:e} > bound {bound:e} ({} triangles, earcut {})",
                        tris.len(),
                        fx.expected_triangles
                    ));
                }
            }

            let valid = fx.expected_triangles > 0 && !SELF_INTERSECTING.contains(&fx.name.as_str());
            if valid {
                let roles = first_is_outer(flat.rings.len());
                if let Err(e) = check_with_roles(&seen, &flat.rings, &roles, &tris) {
                    failures.push(format!("{tag}: invalid triangulation: {e}"));
                }
            }
        }
    }
    for n in &notes {
        eprintln!("note: {n}");
    }
    assert!(
        failures.is_empty(),
        "{} failure(s):\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn fast_f64() {
    run_all(Strategy::Fast, Precision::F64);
}

#[test]
fn fast_f32() {
    run_all(Strategy::Fast, Precision::F32);
}

#[test]
fn quality_f64() {
    run_all(Strategy::Quality, Precision::F64);
}

#[test]
fn quality_f32() {
    run_all(Strategy::Quality, Precision::F32);
}

/// The split into valid and self-intersecting fixtures is what the data says, found by an
/// exact segment test independent of polytri.
#[test]
fn fixture_classification_matches_the_data() {
    let mut wrong = Vec::new();
    for fx in fixtures() {
        let flat = flatten(&fx.rings);
        let d = input_defects(&flat.vertices, &flat.rings);
        let listed = SELF_INTERSECTING.contains(&fx.name.as_str());
        if listed == d.crossings.is_empty() {
            wrong.push(format!(
                "{}: listed self-intersecting = {listed}, crossings found = {} (overlaps {})",
                fx.name,
                d.crossings.len(),
                d.overlaps.len()
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
