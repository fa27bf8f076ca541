//! The oracle's `check` on polytri's own results and on triangulations made by hand:
//! accepted when right, and rejected with the right check's name when broken on purpose.

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
            // The hole's edge (3, 0)–(1, 0) runs along part of the outer ring's bottom edge:
            // collinear edges overlapping along a segment are allowed.
            "hole along the outer ring's edge",
            Input::from_rings(
                &[
                    square(0.0, 0.0, 4.0),
                    vec![[1.0, 0.0], [2.0, 1.0], [3.0, 0.0]],
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

/// A 10×10 square with a 4×4 hole given clockwise — vertices 4 (3, 3), 5 (3, 7), 6 (7, 7),
/// 7 (7, 3) — and a triangulation of it made by hand: 8 triangles, area 84.
fn hand_made_frame() -> (Vec<Vec<[f64; 2]>>, Vec<[u32; 3]>) {
    let rings = vec![
        square(0.0, 0.0, 10.0),
        vec![[3.0, 3.0], [3.0, 7.0], [7.0, 7.0], [7.0, 3.0]],
    ];
    let triangles = vec![
        [0, 1, 7],
        [0, 7, 4],
        [1, 2, 6],
        [1, 6, 7],
        [2, 3, 5],
        [2, 5, 6],
        [3, 0, 4],
        [3, 4, 5],
    ];
    (rings, triangles)
}

#[test]
fn accepts_a_hand_made_frame_in_every_nesting_convention() {
    let (rings, triangles) = hand_made_frame();
    for nesting in [
        Nesting::Auto,
        Nesting::FirstIsOuter,
        Nesting::Roles(vec![Role::Outer, Role::Hole]),
    ] {
        let what = format!("{nesting:?}");
        let verdict = check(&Input::from_rings(&rings, nesting), &triangles);
        assert!(verdict.valid, "{what}: {:?}", verdict.failures());
        assert_eq!(verdict.triangles, 8, "{what}");
        assert_eq!(verdict.expected_triangles, Some(8), "{what}");
        assert_eq!(verdict.deviation, 0.0, "{what}");
        assert!(
            verdict.min_angle_deg > 0.0 && verdict.min_angle_deg <= 60.0,
            "{what}: {}",
            verdict.min_angle_deg
        );
        assert_eq!(verdict.cdt.map(|c| c.area), Some(84.0), "{what}");
    }
}

#[test]
fn rejects_a_degenerate_triangle() {
    let (rings, mut triangles) = hand_made_frame();
    let input = Input::from_rings(&rings, Nesting::FirstIsOuter);
    triangles.push([0, 1, 1]);
    assert_rejected("degenerate", &input, &triangles, &["orientation"]);
    let verdict = check_with(&input, &triangles, &CheckOptions::fast());
    let detail = verdict.check("orientation").and_then(|c| c.detail.clone());
    assert!(
        detail.as_deref().is_some_and(|d| d.contains("zero area")),
        "{detail:?}"
    );
}

/// Moving an input vertex moves the polygon: the hole's corner (7, 3) moved within the
/// star of its triangles keeps the triangulation valid; moved outside the outer ring, it
/// makes the input invalid.
#[test]
fn moving_an_input_vertex_moves_the_polygon() {
    let (rings, triangles) = hand_made_frame();
    let mut input = Input::from_rings(&rings, Nesting::FirstIsOuter);
    input.vertices[7] = [8.0, 2.0];
    let verdict = check(&input, &triangles);
    assert!(verdict.valid, "{:?}", verdict.failures());
    input.vertices[7] = [11.0, 5.0];
    let verdict = check(&input, &triangles);
    assert!(!verdict.valid && !verdict.input_valid);
}

#[test]
fn rejects_triangles_over_a_reflex_notch() {
    // An arrow: the notch at vertex 3 is reflex.
    let arrow = Input::from_rings(
        &[vec![
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [2.0, 1.0],
            [0.0, 4.0],
        ]],
        Nesting::Auto,
    );
    let verdict = check(&arrow, &[[0, 1, 3], [1, 2, 3], [0, 3, 4]]);
    assert!(verdict.valid, "{:?}", verdict.failures());
    // Two triangles covering the notch, which lies outside the polygon.
    let over = [[0, 1, 2], [0, 2, 4]];
    assert_rejected("over the notch", &arrow, &over, &["edges", "containment"]);
}

#[test]
fn accepts_either_index_of_a_repeated_point_and_dropped_collinear_vertices() {
    // (2, 0) lies on the bottom edge and (4, 4) is repeated; neither need be used.
    let square = Input::from_rings(
        &[vec![
            [0.0, 0.0],
            [2.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [4.0, 4.0],
            [0.0, 4.0],
        ]],
        Nesting::Auto,
    );
    for (what, triangles) in [
        ("collinear vertex dropped", vec![[0, 2, 3], [0, 3, 5]]),
        ("the repeat's other index", vec![[0, 2, 4], [0, 3, 5]]),
        (
            "collinear vertex kept",
            vec![[0, 1, 5], [1, 2, 3], [1, 3, 5]],
        ),
    ] {
        let verdict = check(&square, &triangles);
        assert!(verdict.valid, "{what}: {:?}", verdict.failures());
    }
}

#[test]
fn accepts_a_hole_touching_the_outer_ring_with_either_index() {
    // A triangular hole whose corner is the outer ring's corner (4, 0), given as a vertex
    // of its own (4): six positions, one hole touching the outer ring, 5 triangles.
    let input = Input::from_rings(
        &[
            square(0.0, 0.0, 4.0),
            vec![[4.0, 0.0], [2.0, 1.0], [3.0, 2.0]],
        ],
        Nesting::FirstIsOuter,
    );
    for triangles in [
        [[0, 1, 5], [0, 5, 3], [5, 6, 3], [6, 2, 3], [6, 1, 2]],
        [[0, 4, 5], [0, 5, 3], [5, 6, 3], [6, 2, 3], [6, 4, 2]],
    ] {
        let verdict = check(&input, &triangles);
        assert!(verdict.valid, "{triangles:?}: {:?}", verdict.failures());
        assert_eq!(verdict.expected_triangles, Some(5));
    }
}

/// An island in a hole is an outer ring by its depth: the polygon has area
/// 100 − 36 + 4 = 68, and leaving the island out leaves a gap.
#[test]
fn an_island_in_a_hole_is_outer_by_depth() {
    let rings = [
        square(0.0, 0.0, 10.0),
        square(2.0, 2.0, 6.0),
        square(4.0, 4.0, 2.0),
    ];
    let triangles = [
        // the frame between the outer ring and the hole
        [0, 1, 5],
        [0, 5, 4],
        [1, 2, 6],
        [1, 6, 5],
        [2, 3, 7],
        [2, 7, 6],
        [3, 0, 4],
        [3, 4, 7],
        // the island
        [8, 9, 10],
        [8, 10, 11],
    ];
    let input = Input::from_rings(&rings, Nesting::Auto);
    let verdict = check(&input, &triangles);
    assert!(verdict.valid, "{:?}", verdict.failures());
    assert_eq!(verdict.cdt.map(|c| c.area), Some(68.0));
    assert_rejected(
        "island left out",
        &input,
        &triangles[..8],
        &["boundary", "area"],
    );
    // Declared a hole, the island contradicts its depth.
    let misdeclared = Input::from_rings(
        &rings,
        Nesting::Roles(vec![Role::Outer, Role::Hole, Role::Hole]),
    );
    assert!(!check(&misdeclared, &triangles).input_valid);
}

#[test]
fn is_exact_for_non_integer_coordinates() {
    // A fan over a convex heptagon with decimal coordinates: the exact area identity holds.
    let ring: Vec<[f64; 2]> = (0..7)
        .map(|k| {
            let a = k as f64 * std::f64::consts::TAU / 7.0;
            [0.1 + 3.3 * a.cos(), 0.7 + 2.9 * a.sin()]
        })
        .collect();
    let fan: Vec<[u32; 3]> = (1..6).map(|k| [0, k, k + 1]).collect();
    let verdict = check(&Input::from_rings(&[ring], Nesting::Auto), &fan);
    assert!(verdict.valid, "{:?}", verdict.failures());
}

/// The verdict's deviation is earcut's measure (`polytri::deviation`): the share of the
/// polygon's area the triangles miss, and 0 where polygon and triangles have no area.
#[test]
fn deviation_is_earcuts_measure() {
    let (rings, triangles) = hand_made_frame();
    let input = Input::from_rings(&rings, Nesting::FirstIsOuter);
    // Triangle 0, (0, 0) (10, 0) (7, 3), has area 15 of the 84.
    let verdict = check_with(&input, &triangles[1..], &CheckOptions::fast());
    assert_eq!(verdict.deviation, 15.0 / 84.0);
    let collinear = Input::from_rings(&[vec![[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]], Nesting::Auto);
    assert_eq!(check(&collinear, &[]).deviation, 0.0);
    let flat = Input::from_rings(&[vec![[0.0, 0.0], [1.0, 0.0], [0.0, 0.0]]], Nesting::Auto);
    assert_eq!(check(&flat, &[[0, 1, 2]]).deviation, 0.0);
}
