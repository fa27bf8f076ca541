//! Strict mode (the default) refuses bad input with an error that says what and where;
//! lenient mode never refuses it and reports what it repaired or dropped.

mod common;

use std::time::Duration;

use common::{
    check_with_roles, first_is_outer, flatten, guarded, read_json, rings_from_json, to_f32, widen,
    Flat,
};
use polytri::{DropReason, Error, Nesting, Options, Strategy, Triangulator};

const TIMEOUT: Duration = Duration::from_secs(120);

/// The earcut fixtures with crossing edges (found independently by `input_defects`; see
/// `earcut_fixtures::fixture_classification_matches_the_data`).
const SELF_INTERSECTING: [&str; 6] = [
    "water",
    "water-huge",
    "water-huge2",
    "bad-hole",
    "issue142",
    "simplified-us-border",
];

/// Fixtures expecting no triangles from earcut: degenerate on purpose.
// Not here: `infinite-loop-jhl`, whose hole leaves a sliver of exact area 1.5e-28 between
// (0, 0) and (0, 1e-28). earcut rounds it away; polytri triangulates it (two triangles),
// and `strict_accepts_valid_fixtures` checks them exactly.
const DEGENERATE: [&str; 4] = ["degenerate", "empty-square", "issue83", "issue107"];

fn fixture_names() -> Vec<String> {
    let expected = read_json("earcut/expected.json");
    let mut names: Vec<String> = expected["triangles"]
        .as_object()
        .expect("triangles")
        .keys()
        .cloned()
        .collect();
    names.sort();
    names
}

fn fixture(name: &str) -> Flat {
    flatten(&rings_from_json(&read_json(&format!(
        "earcut/fixtures/{name}.json"
    ))))
}

fn strict(strategy: Strategy) -> Options {
    Options::default()
        .with_strategy(strategy)
        .with_nesting(Nesting::FirstIsOuter)
}

/// A guarded run: `Err` for a panic or hang, else the triangles or the error with its
/// Display.
type Outcome = Result<Result<Vec<[u32; 3]>, (Error, String)>, String>;

/// Triangulates in a guarded thread.
fn run_f64(flat: &Flat, opts: Options) -> Outcome {
    let (v, s) = (flat.vertices.clone(), flat.ring_starts.clone());
    guarded(TIMEOUT, move || {
        let mut out = Vec::new();
        match Triangulator::<f64>::new().triangulate(&v, &s, &opts, &mut out) {
            Ok(_) => Ok(out),
            Err(e) => Err((e, e.to_string())),
        }
    })
}

fn run_f32(flat: &Flat, opts: Options) -> Outcome {
    let (v, s) = (to_f32(&flat.vertices), flat.ring_starts.clone());
    guarded(TIMEOUT, move || {
        let mut out = Vec::new();
        match Triangulator::<f32>::new().triangulate(&v, &s, &opts, &mut out) {
            Ok(_) => Ok(out),
            Err(e) => Err((e, e.to_string())),
        }
    })
}

/// The ring holding input vertex `v`.
fn ring_of(flat: &Flat, v: usize) -> usize {
    flat.ring_starts
        .iter()
        .rposition(|&s| s <= v)
        .expect("vertex in a ring")
}

/// The segments an edge named by its start vertex may be: from it to the next vertex at
/// another position, and on through successors collinear with that first segment (the core
/// names an edge by its start and runs it to the next *kept* vertex).
fn edge_segments(flat: &Flat, ring: usize, start: usize) -> Vec<([f64; 2], [f64; 2])> {
    let r = &flat.rings[ring];
    let Some(k0) = r.iter().position(|&v| v == start) else {
        return vec![];
    };
    let p = flat.vertices[start];
    let mut out = Vec::new();
    let mut first: Option<[f64; 2]> = None;
    for step in 1..=r.len() {
        let q = flat.vertices[r[(k0 + step) % r.len()]];
        if q == p {
            continue;
        }
        match first {
            None => first = Some(q),
            Some(f) => {
                let o = robust::orient2d(
                    robust::Coord { x: p[0], y: p[1] },
                    robust::Coord { x: f[0], y: f[1] },
                    robust::Coord { x: q[0], y: q[1] },
                );
                if o != 0.0 {
                    break;
                }
            }
        }
        out.push((p, q));
    }
    out
}

/// Checks an `EdgesCross` error against the input: rings and vertices in range, the Display
/// naming them, and the named edges really crossing.
fn check_edge_error(flat: &Flat, err: &Error, shown: &str) -> Result<(), String> {
    let Error::EdgesCross {
        ring_a,
        edge_a,
        ring_b,
        edge_b,
    } = *err
    else {
        return Err(format!("not EdgesCross: {err:?}"));
    };
    for (ring, v) in [(ring_a, edge_a), (ring_b, edge_b)] {
        if ring >= flat.rings.len() || v >= flat.vertices.len() || ring_of(flat, v) != ring {
            return Err(format!("{err:?}: vertex {v} is not in ring {ring}"));
        }
        for needle in [format!("ring {ring}"), format!("vertex {v}")] {
            if !shown.contains(&needle) {
                return Err(format!("Display {shown:?} does not mention {needle:?}"));
            }
        }
    }
    let sa = edge_segments(flat, ring_a, edge_a);
    let sb = edge_segments(flat, ring_b, edge_b);
    let crossing = sa
        .iter()
        .any(|&(a, b)| sb.iter().any(|&(c, d)| common::segments_cross(a, b, c, d)));
    if !crossing {
        return Err(format!("{err:?}: the named edges do not cross"));
    }
    Ok(())
}

#[test]
fn strict_refuses_self_intersecting_fixtures() {
    let mut failures = Vec::new();
    for name in SELF_INTERSECTING {
        let flat = fixture(name);
        for strategy in [Strategy::Fast, Strategy::Quality] {
            let tag = format!("{name} {strategy:?} strict");
            match run_f64(&flat, strict(strategy)) {
                Err(e) => failures.push(format!("{tag}: {e}")),
                Ok(Ok(t)) => failures.push(format!(
                    "{tag}: Ok with {} triangles, expected EdgesCross",
                    t.len()
                )),
                Ok(Err((err, shown))) => {
                    if let Err(e) = check_edge_error(&flat, &err, &shown) {
                        failures.push(format!("{tag}: expected a truthful EdgesCross: {e}"));
                    }
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failure(s):\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The valid fixtures come out valid in strict mode, in both precisions where `f32` holds the
/// coordinates exactly. (Several have collinear edges that partly overlap, e.g. a hole along
/// the outer ring: still a valid polygon.)
#[test]
fn strict_accepts_valid_fixtures() {
    let mut failures = Vec::new();
    for name in fixture_names() {
        if SELF_INTERSECTING.contains(&name.as_str()) || DEGENERATE.contains(&name.as_str()) {
            continue;
        }
        let flat = fixture(&name);
        let roles = first_is_outer(flat.rings.len());
        let f32_exact = widen(&to_f32(&flat.vertices)) == flat.vertices;
        for strategy in [Strategy::Fast, Strategy::Quality] {
            let mut runs = vec![("F64", run_f64(&flat, strict(strategy)))];
            if f32_exact {
                runs.push(("F32", run_f32(&flat, strict(strategy))));
            }
            for (precision, result) in runs {
                let tag = format!("{name} {strategy:?} {precision} strict");
                match result {
                    Err(e) => failures.push(format!("{tag}: {e}")),
                    Ok(Ok(t)) => {
                        if let Err(e) = check_with_roles(&flat.vertices, &flat.rings, &roles, &t) {
                            failures.push(format!("{tag}: invalid: {e}"));
                        }
                    }
                    Ok(Err((err, shown))) => failures.push(format!("{tag}: Err({err:?}): {shown}")),
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failure(s):\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// Lenient mode never errors on the self-intersecting fixtures, and says it repaired them.
#[test]
fn lenient_never_errors_and_reports_repairs() {
    let mut failures = Vec::new();
    for name in SELF_INTERSECTING {
        let flat = fixture(name);
        for strategy in [Strategy::Fast, Strategy::Quality] {
            let opts = strict(strategy).with_lenient(true);
            let (v, s) = (flat.vertices.clone(), flat.ring_starts.clone());
            let r = guarded(TIMEOUT, move || {
                let mut out = Vec::new();
                let mut tri = Triangulator::<f64>::new();
                tri.triangulate(&v, &s, &opts, &mut out)
                    .map(|r| (r.repairs.len(), r.is_clean()))
            });
            let tag = format!("{name} {strategy:?} lenient");
            match r {
                Err(e) => failures.push(format!("{tag}: {e}")),
                Ok(Err(e)) => failures.push(format!("{tag}: Err({e:?}): {e}")),
                Ok(Ok((repairs, clean))) => {
                    if repairs == 0 || clean {
                        failures.push(format!("{tag}: crossing input but no repair reported"));
                    }
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failure(s):\n{}",
        failures.len(),
        failures.join("\n")
    );
}

fn tri_f64(vertices: &[[f64; 2]], starts: &[usize], opts: Options) -> Result<usize, Error> {
    let mut out = Vec::new();
    Triangulator::<f64>::new()
        .triangulate(vertices, starts, &opts, &mut out)
        .map(|_| out.len())
}

const SQUARE: [[f64; 2]; 4] = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];

#[test]
fn non_finite_coordinates_are_named() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for (vertex, axis) in [(0, 0), (2, 1), (5, 0)] {
            let mut v: Vec<[f64; 2]> = SQUARE.to_vec();
            v.extend([[1.0, 1.0], [1.0, 2.0], [2.0, 1.0]]);
            v[vertex][axis] = bad;
            let err = tri_f64(&v, &[0, 4], Options::default()).unwrap_err();
            assert_eq!(err, Error::NonFinite { vertex }, "{bad} at vertex {vertex}");
            assert!(
                err.to_string().contains(&format!("vertex {vertex}")),
                "{err}"
            );
        }
    }
    // f32 too.
    let mut v32 = to_f32(&SQUARE);
    v32[3][1] = f32::NAN;
    let mut out = Vec::new();
    let err = Triangulator::<f32>::new()
        .triangulate(&v32, &[0], &Options::default(), &mut out)
        .unwrap_err();
    assert_eq!(err, Error::NonFinite { vertex: 3 });
}

#[test]
fn malformed_ring_starts_are_refused() {
    let mut v: Vec<[f64; 2]> = SQUARE.to_vec();
    v.extend([[1.0, 1.0], [1.0, 2.0], [2.0, 1.0]]);
    let o = Options::default();
    assert_eq!(
        tri_f64(&v, &[1, 4], o),
        Err(Error::FirstRingStart { start: Some(1) })
    );
    assert_eq!(
        tri_f64(&v, &[], o),
        Err(Error::FirstRingStart { start: None })
    );
    assert_eq!(
        tri_f64(&v, &[0, 4, 4], o),
        Err(Error::RingStartsNotIncreasing {
            ring: 2,
            start: 4,
            previous: 4
        })
    );
    assert_eq!(
        tri_f64(&v, &[0, 5, 3], o),
        Err(Error::RingStartsNotIncreasing {
            ring: 2,
            start: 3,
            previous: 5
        })
    );
    assert_eq!(
        tri_f64(&v, &[0, 9], o),
        Err(Error::RingStartOutOfRange {
            ring: 1,
            start: 9,
            len: 7
        })
    );
    assert_eq!(
        tri_f64(&v, &[0, 7], o),
        Err(Error::RingStartOutOfRange {
            ring: 1,
            start: 7,
            len: 7
        })
    );
    for e in [
        Error::FirstRingStart { start: Some(1) },
        Error::RingStartsNotIncreasing {
            ring: 2,
            start: 3,
            previous: 5,
        },
        Error::RingStartOutOfRange {
            ring: 1,
            start: 9,
            len: 7,
        },
    ] {
        assert!(!e.to_string().is_empty());
    }
}

#[test]
fn empty_input_gives_no_triangles() {
    for strategy in [Strategy::Fast, Strategy::Quality] {
        for lenient in [false, true] {
            let o = Options::default()
                .with_strategy(strategy)
                .with_lenient(lenient);
            assert_eq!(tri_f64(&[], &[], o), Ok(0));
            let mut out = vec![[9u32, 9, 9]];
            Triangulator::<f32>::new()
                .triangulate(&[], &[], &o, &mut out)
                .expect("empty f32");
            assert!(out.is_empty(), "out is cleared");
        }
    }
}

/// Lenient mode accepts what strict mode refuses, drops what it cannot use, and says so.
#[test]
fn lenient_repairs_bad_input() {
    let lenient = Options::default().with_lenient(true);
    // A NaN vertex in a pentagon: dropped as NonFinite, the rest triangulated.
    let v = [
        [0.0, 0.0],
        [4.0, 0.0],
        [f64::NAN, 2.0],
        [4.0, 4.0],
        [0.0, 4.0],
    ];
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    let report = tri
        .triangulate(&v, &[0], &lenient, &mut out)
        .expect("lenient NaN");
    assert!(
        report
            .dropped
            .iter()
            .any(|d| d.vertex == 2 && d.reason == DropReason::NonFinite),
        "NaN vertex reported: {:?}",
        report.dropped
    );
    assert!(out.iter().flatten().all(|&i| i != 2), "NaN vertex unused");
    assert_eq!(out.len(), 2);

    // Malformed ring starts: a result anyway, and a RingStartIgnored repair.
    let mut v: Vec<[f64; 2]> = SQUARE.to_vec();
    v.extend([[1.0, 1.0], [1.0, 2.0], [2.0, 1.0]]);
    for starts in [&[0, 4, 4][..], &[0, 9], &[0, 5, 3]] {
        let report = tri.triangulate(&v, starts, &lenient, &mut out);
        let report = report.unwrap_or_else(|e| panic!("lenient {starts:?}: {e}"));
        assert!(
            report
                .repairs
                .iter()
                .any(|r| r.kind == polytri::RepairKind::RingStartIgnored),
            "{starts:?}: {:?}",
            report.repairs
        );
    }

    // A bow-tie: strict refuses, lenient repairs.
    let bow = [[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
    assert!(matches!(
        tri_f64(&bow, &[0], Options::default()),
        Err(Error::EdgesCross { .. })
    ));
    let report = tri
        .triangulate(&bow, &[0], &lenient, &mut out)
        .expect("lenient bow-tie");
    assert!(!report.is_clean(), "bow-tie repaired");

    // Repeated and collinear vertices are dropped with their reasons, strict or not.
    let v = [
        [0.0, 0.0],
        [2.0, 0.0],
        [4.0, 0.0],
        [4.0, 4.0],
        [4.0, 4.0],
        [0.0, 4.0],
        [0.0, 0.0],
    ];
    for o in [Options::default(), lenient] {
        let report = tri.triangulate(&v, &[0], &o, &mut out).expect("repeats");
        let mut reasons: Vec<(u32, DropReason)> = report
            .dropped
            .iter()
            .map(|d| (d.vertex, d.reason))
            .collect();
        reasons.sort_by_key(|r| r.0);
        assert_eq!(out.len(), 2, "{reasons:?}");
        assert!(reasons.contains(&(1, DropReason::Collinear)), "{reasons:?}");
        assert!(
            reasons
                .iter()
                .any(|&(v, r)| (v == 3 || v == 4) && r == DropReason::Repeated),
            "{reasons:?}"
        );
        assert!(
            reasons
                .iter()
                .any(|&(v, r)| (v == 0 || v == 6) && r == DropReason::Repeated),
            "{reasons:?}"
        );
    }

    // A ring of fewer than three distinct points encloses nothing.
    let v = [[0.0, 0.0], [1.0, 1.0], [0.0, 0.0]];
    let report = tri
        .triangulate(&v, &[0], &lenient, &mut out)
        .expect("degenerate ring");
    assert!(out.is_empty());
    assert_eq!(report.dropped.len(), 3, "{:?}", report.dropped);
}

/// The degenerate fixtures finish in every mode and triangulate to nothing (their polygons
/// have no area), except `issue107`, whose hole lies outside its zero-area outer ring.
#[test]
fn degenerate_fixtures_finish() {
    let mut failures = Vec::new();
    for name in DEGENERATE {
        let flat = fixture(name);
        for strategy in [Strategy::Fast, Strategy::Quality] {
            for lenient in [false, true] {
                let tag = format!(
                    "{name} {strategy:?} {}",
                    if lenient { "lenient" } else { "strict" }
                );
                match run_f64(&flat, strict(strategy).with_lenient(lenient)) {
                    Err(e) => failures.push(format!("{tag}: {e}")),
                    Ok(Err((e, shown))) if lenient => {
                        failures.push(format!("{tag}: Err({e:?}): {shown}"))
                    }
                    Ok(Err(_)) => {}
                    Ok(Ok(t)) => {
                        if !t.is_empty() && name != "issue107" {
                            failures
                                .push(format!("{tag}: {} triangles on a zero-area input", t.len()));
                        }
                    }
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failure(s):\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// A figure eight whose lobes meet along a wall the ring runs down and later up again
/// (x = -1, y from -1 to 0): the upper lobe turns counter-clockwise, the lower one
/// clockwise. No edges cross, yet no region is bounded consistently. Found by the
/// `raw_rings` fuzz target, where strict mode reported an internal error.
#[test]
fn lobes_winding_opposite_ways_along_a_wall_are_refused() {
    let ring = [
        [-1.0, 1.0],
        [-1.0, -1.0],
        [0.0, -2.0],
        [-1.0, -5.0],
        [-1.0, 0.0],
        [0.0, 0.0],
    ];
    for rotation in 0..4 {
        let turned: Vec<[f64; 2]> = ring
            .iter()
            .map(|&p| (0..rotation).fold(p, |[x, y], _| [-y, x]))
            .collect();
        for strategy in [Strategy::Fast, Strategy::Quality] {
            let err = match tri_f64(&turned, &[0], strict(strategy)) {
                Ok(n) => panic!("rotation {rotation}, {strategy:?}: Ok with {n} triangles"),
                Err(e) => e,
            };
            let Error::LobesWindOpposite { ring: 0, vertex } = err else {
                panic!("rotation {rotation}, {strategy:?}: {err:?}");
            };
            assert!(vertex < ring.len(), "{err}");
            assert!(err.to_string().contains("winds both ways"), "{err}");
            let mut out = Vec::new();
            let err32 = Triangulator::<f32>::new()
                .triangulate(&to_f32(&turned), &[0], &strict(strategy), &mut out)
                .unwrap_err();
            assert!(
                matches!(err32, Error::LobesWindOpposite { ring: 0, .. }),
                "{err32:?}"
            );
            // Lenient mode makes the best of it: a result, never an error.
            let lenient = strict(strategy).with_lenient(true);
            assert!(tri_f64(&turned, &[0], lenient).is_ok());
        }
    }
}

/// A quadrilateral with a wall from B down to C and a triangle C D E inside it turning the
/// same way, one ring (precision fuzz target, seed 8282): the winding number in the
/// triangle is 2. Strict mode refuses it in every rotation and start; the same lobe turned
/// the other way is a hole, which it triangulates (quadrilateral minus triangle).
#[test]
fn a_lobe_inside_its_ring_turning_the_same_way_is_refused() {
    let (a, b, c, d, e, f, g) = (
        [6.0, 13.0],
        [2.0, 10.0],
        [2.0, 9.0],
        [4.0, 8.0],
        [3.0, 9.0],
        [1.0, 9.0],
        [2.0, 0.0],
    );
    let same_way = [a, b, c, d, e, c, b, f, g];
    let other_way = [a, b, c, e, d, c, b, f, g];
    for rotation in 0..4 {
        let turn = |ring: &[[f64; 2]]| -> Vec<[f64; 2]> {
            ring.iter()
                .map(|&p| (0..rotation).fold(p, |[x, y], _| [-y, x]))
                .collect()
        };
        for start in 0..same_way.len() {
            let mut twice = turn(&same_way);
            twice.rotate_left(start);
            let mut hole = turn(&other_way);
            hole.rotate_left(start);
            for strategy in [Strategy::Fast, Strategy::Quality] {
                let what = format!("rotation {rotation}, start {start}, {strategy:?}");
                match tri_f64(&twice, &[0], strict(strategy)) {
                    Err(Error::RingWindsTwice { ring: 0, vertex }) => {
                        assert!(vertex < twice.len(), "{what}")
                    }
                    other => panic!("{what}: {other:?}"),
                }
                // 4 + 3 corners and one hole: 4 + 3 + 2 - 2 triangles
                assert_eq!(tri_f64(&hole, &[0], strict(strategy)), Ok(7), "{what}");
            }
        }
    }
}

/// Two triangles pinched at their shared rightmost vertex (3, 1), one ring. The turn at a
/// visit of the rightmost vertex may pair an edge of one lobe with an edge of the other,
/// so it cannot tell the winding; the lowest edge there can. Found by `polytri precision`
/// (a spiral collapsed by f32 rounding), where one start vertex made the ring a "hole".
#[test]
fn ring_touching_itself_at_its_rightmost_vertex_keeps_both_lobes() {
    let ring = [
        [3.0, 1.0],
        [2.0, 4.0],
        [3.0, 3.0],
        [3.0, 1.0],
        [0.0, 0.0],
        [1.0, 4.0],
    ];
    // twice the area of both lobes: 2 + 11
    let twice_area = 13.0;
    for reversed in [false, true] {
        for start in 0..ring.len() {
            let mut turned: Vec<[f64; 2]> = (0..ring.len())
                .map(|k| ring[(start + k) % ring.len()])
                .collect();
            if reversed {
                turned.reverse();
            }
            for strategy in [Strategy::Fast, Strategy::Quality] {
                let mut out = Vec::new();
                Triangulator::<f64>::new()
                    .triangulate(&turned, &[0], &strict(strategy), &mut out)
                    .unwrap_or_else(|e| panic!("start {start}, reversed {reversed}: {e}"));
                let sum: f64 = out
                    .iter()
                    .map(|t| {
                        let [a, b, c] = t.map(|i| turned[i as usize]);
                        let twice = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
                        assert!(twice > 0.0, "start {start}: clockwise triangle {t:?}");
                        twice
                    })
                    .sum();
                assert_eq!(out.len(), 2, "start {start}, reversed {reversed}");
                assert_eq!(sum, twice_area, "start {start}, reversed {reversed}");
            }
        }
    }
}

/// `Triangulator::check` runs the strict input check alone: on every earcut fixture it
/// refuses exactly what strict `triangulate` refuses for crossing edges or misplaced holes,
/// with the same error, and accepts everything strict `triangulate` triangulates.
#[test]
fn check_alone_agrees_with_strict_triangulate() {
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    let opts = strict(Strategy::Fast);
    for name in fixture_names() {
        let flat = fixture(&name);
        let checked = tri.check(&flat.vertices, &flat.ring_starts, Nesting::FirstIsOuter);
        let triangulated = tri
            .triangulate(&flat.vertices, &flat.ring_starts, &opts, &mut out)
            .map(|_| ());
        match (&checked, &triangulated) {
            (Ok(()), Ok(())) => {}
            // defects of weakly simple rings only show while clipping
            (Ok(()), Err(Error::LobesWindOpposite { .. })) => {}
            (Err(a), Err(b)) => assert_eq!(a, b, "{name}: check and triangulate disagree"),
            _ => panic!("{name}: check says {checked:?}, triangulate {triangulated:?}"),
        }
        if SELF_INTERSECTING.contains(&name.as_str()) {
            assert!(checked.is_err(), "{name}: crossing edges passed the check");
        }
    }
}
