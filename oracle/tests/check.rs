//! The oracle's `check` on polytri's own results: accepted when right, and rejected with
//! the right check's name when broken on purpose.

use std::path::PathBuf;
use std::time::Instant;

use polytri::{Options, Triangulator};
use polytri_oracle::{check, check_with, CheckOptions, Input, Nesting, Role, Verdict};

fn corpus(parts: &[&str]) -> PathBuf {
    let mut path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "..", "corpus"]
        .iter()
        .collect();
    path.extend(parts);
    path
}

/// An earcut fixture (rings JSON: first ring outer, the rest holes).
fn fixture(name: &str) -> Input {
    let path = corpus(&["earcut", "fixtures", name]);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let rings: Vec<Vec<[f64; 2]>> = serde_json::from_str(&text).expect("rings JSON");
    Input::from_rings(&rings, Nesting::FirstIsOuter)
}

/// A shapes-JSON dataset as one input: each polygon's first ring outer, the rest holes.
fn dataset(name: &str) -> Input {
    let path = corpus(&["datasets", name]);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let shapes: Vec<Vec<Vec<[f64; 2]>>> = serde_json::from_str(&text).expect("shapes JSON");
    let mut rings = Vec::new();
    let mut roles = Vec::new();
    for shape in shapes {
        for (r, ring) in shape.into_iter().enumerate() {
            roles.push(if r == 0 { Role::Outer } else { Role::Hole });
            rings.push(ring);
        }
    }
    Input::from_rings(&rings, Nesting::Roles(roles))
}

/// polytri's strict triangulation of `input` (`Roles` inputs with automatic nesting,
/// which agrees with them for valid inputs).
fn triangulate(input: &Input) -> Vec<[u32; 3]> {
    let nesting = input.nesting.to_polytri().unwrap_or(polytri::Nesting::Auto);
    let options = Options::new().with_nesting(nesting);
    let mut out = Vec::new();
    Triangulator::<f64>::new()
        .triangulate(&input.vertices, &input.ring_starts, &options, &mut out)
        .expect("polytri triangulates it");
    out
}

fn failed(verdict: &Verdict) -> Vec<String> {
    verdict
        .checks
        .iter()
        .filter(|c| !c.passed)
        .map(|c| c.name.clone())
        .collect()
}

fn square(x: f64, y: f64, s: f64) -> Vec<[f64; 2]> {
    vec![[x, y], [x + s, y], [x + s, y + s], [x, y + s]]
}

/// The inputs polytri must triangulate and the oracle must accept.
fn accepted_inputs() -> Vec<(&'static str, Input)> {
    let mut cases = vec![
        (
            "square with hole",
            Input::from_rings(
                &[square(0.0, 0.0, 10.0), square(3.0, 3.0, 4.0)],
                Nesting::Auto,
            ),
        ),
        (
            "nested islands",
            Input::from_rings(
                &[
                    square(0.0, 0.0, 20.0),
                    square(2.0, 2.0, 16.0),
                    square(4.0, 4.0, 12.0),
                    square(6.0, 6.0, 8.0),
                    square(8.0, 8.0, 4.0),
                ],
                Nesting::Auto,
            ),
        ),
        (
            "touching holes",
            Input::from_rings(
                &[
                    square(0.0, 0.0, 10.0),
                    square(2.0, 2.0, 3.0),
                    square(5.0, 2.0, 3.0),
                    // Touches the outer ring at its corner (0, 0) and the first hole at
                    // its corner (2, 2); the first two holes share an edge.
                    vec![[0.0, 0.0], [2.0, 1.0], [2.0, 2.0], [1.0, 2.0]],
                ],
                Nesting::FirstIsOuter,
            ),
        ),
        (
            // The outer ring runs round the triangle A B C twice and the hole cancels one
            // turn: geo, reading each ring by the even-odd rule, calls A B C outside; the
            // triangles there are skipped, not failed.
            "ring winding twice round a triangle",
            Input::from_rings(
                &[
                    vec![[-12.0, 1.0], [0.0, 0.0], [-12.0, -12.0]],
                    vec![
                        [-12.0, -12.0],
                        [-12.0, 1.0],
                        [0.0, 0.0],
                        [-12.0, -12.0],
                        [-12.0, 15.0],
                        [0.0, 0.0],
                        [1.0, 0.0],
                    ],
                ],
                Nesting::Auto,
            ),
        ),
    ];
    for name in [
        "hole-touching-outer.json",
        "touching-holes.json",
        "self-touching.json",
        "issue149.json",
        "eberly-6.json",
        "water3.json",
        "infinite-loop-jhl.json",
        "collinear-diagonal.json",
    ] {
        cases.push((name, fixture(name)));
    }
    cases
}

#[test]
fn accepts_polytri_results() {
    for (name, input) in accepted_inputs() {
        let triangles = triangulate(&input);
        let verdict = check(&input, &triangles);
        assert!(verdict.input_valid, "{name}: {:?}", verdict.failures());
        assert!(verdict.valid, "{name}: {:?}", verdict.failures());
        assert_eq!(verdict.expected_triangles, Some(triangles.len()), "{name}");
        // Floating-point areas of its 1e-28-thin region cancel to nothing, so geo's
        // deviation says 1 there; the exact area check passed.
        if name != "infinite-loop-jhl.json" {
            assert!(verdict.deviation < 1e-12, "{name}: {}", verdict.deviation);
        }
        assert!(verdict.cdt.is_some(), "{name}");
    }
}

/// Breaks a valid triangulation in one way and expects `names` among the failed checks.
fn assert_rejected(name: &str, input: &Input, broken: &[[u32; 3]], names: &[&str]) {
    let verdict = check_with(input, broken, &CheckOptions::fast());
    assert!(!verdict.valid, "{name}: accepted");
    assert!(verdict.input_valid, "{name}");
    let failed = failed(&verdict);
    for n in names {
        assert!(
            failed.iter().any(|f| f == n),
            "{name}: {n} not in {failed:?}"
        );
    }
    for f in verdict.failures() {
        assert!(
            f.contains("triangle") || f.contains("edge") || f.contains("area"),
            "{name}: detail {f}"
        );
    }
}

#[test]
fn rejects_broken_triangulations() {
    for (name, input) in accepted_inputs() {
        let good = triangulate(&input);
        if good.len() < 2 {
            continue;
        }
        let mid = good.len() / 2;

        let mut dropped = good.clone();
        dropped.remove(mid);
        assert_rejected(
            &format!("{name}, dropped"),
            &input,
            &dropped,
            &["count", "area"],
        );

        let mut duplicated = good.clone();
        duplicated.push(good[mid]);
        assert_rejected(
            &format!("{name}, duplicated"),
            &input,
            &duplicated,
            &["edges", "count"],
        );

        let mut flipped = good.clone();
        flipped[mid].swap(1, 2);
        assert_rejected(
            &format!("{name}, flipped"),
            &input,
            &flipped,
            &["orientation"],
        );

        let mut out_of_range = good.clone();
        out_of_range[mid][0] = input.vertices.len() as u32 + 5;
        assert_rejected(
            &format!("{name}, out of range"),
            &input,
            &out_of_range,
            &["indices"],
        );

        // One corner moved onto another vertex, a neighbour's: overlaps and gaps, or a
        // flat or flipped triangle; the edges never match any more.
        let mut moved = good.clone();
        let neighbour = good
            .iter()
            .enumerate()
            .find(|&(k, t)| k != mid && t.iter().any(|v| good[mid].contains(v)))
            .map(|(_, t)| *t)
            .expect("a neighbour");
        let other = *neighbour
            .iter()
            .find(|v| !good[mid].contains(v))
            .expect("a vertex the triangle lacks");
        moved[mid][0] = other;
        assert_rejected(&format!("{name}, moved"), &input, &moved, &["edges"]);
    }
}

#[test]
fn bow_tie_input_is_invalid() {
    let bow_tie = Input::from_rings(
        &[vec![[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]],
        Nesting::Auto,
    );
    // What a lenient triangulator might make of it: the two lobes.
    let verdict = check(&bow_tie, &[[0, 2, 1], [0, 1, 3]]);
    assert!(!verdict.input_valid);
    assert!(!verdict.valid);
    assert_eq!(verdict.expected_triangles, None);
    assert!(
        verdict.failures()[0].starts_with("input: edges"),
        "{:?}",
        verdict.failures()
    );
    assert!(verdict.cdt.is_none());
}

#[test]
fn garbage_never_panics() {
    let nan = Input::new(
        vec![[f64::NAN, 1.0], [1.0, f64::INFINITY], [0.0, 1e300]],
        vec![0],
        Nesting::Auto,
    );
    for input in [nan, Input::default(), fixture("degenerate.json")] {
        for tris in [
            vec![],
            vec![[0, 1, 2]],
            vec![[u32::MAX, 0, 0], [2, 1, 0], [1, 1, 1]],
        ] {
            let verdict = check(&input, &tris);
            serde_json::to_string(&verdict).expect("the verdict is JSON");
        }
    }
}

/// Speed: the exact checks on the 100k-vertex CJK page. Timed, so only in release builds
/// (`cargo test --release -p polytri-oracle --test check -- --ignored`).
#[test]
#[ignore = "timing; run in release"]
fn checks_a_large_page_quickly() {
    let input = dataset("cjk_page.json");
    let triangles = triangulate(&input);
    let start = Instant::now();
    let verdict = check_with(&input, &triangles, &CheckOptions::fast());
    let fast = start.elapsed();
    let start = Instant::now();
    let geo = check_with(
        &input,
        &triangles,
        &CheckOptions {
            geo: true,
            cdt: false,
        },
    );
    let with_geo = start.elapsed();
    println!(
        "{} vertices, {} triangles: exact {fast:?}, with geo {with_geo:?}",
        input.vertices.len(),
        triangles.len()
    );
    assert!(verdict.valid, "{:?}", verdict.failures());
    assert!(geo.valid, "{:?}", geo.failures());
}

/// A spike walked out and back (zero width, the same winding on both sides) bounds nothing:
/// a triangulation may cross it, but must still cover the square exactly.
#[test]
fn zero_width_spikes_may_be_crossed() {
    let ring = vec![
        [0.0, 0.0],
        [4.0, 0.0],
        [4.0, 4.0],
        [2.0, 4.0],
        [2.0, 1.0],
        [2.0, 4.0],
        [0.0, 4.0],
    ];
    let input = Input::from_rings(&[ring], Nesting::Auto);
    // Two triangles over the corners, the diagonal 1–6 crossing the spike 3–4.
    let verdict = check(&input, &[[0, 1, 6], [1, 2, 6]]);
    assert!(verdict.input_valid, "{:?}", verdict.failures());
    assert!(verdict.valid, "{:?}", verdict.failures());
    // Still a triangulation of the square: half of it is not.
    let verdict = check(&input, &[[0, 1, 6]]);
    assert!(!verdict.valid);
}
