//! Strict and lenient mode on earcut's fixtures and on inputs judged here: strict mode
//! refuses crossing edges with an error that names edges which really cross, lenient mode
//! never refuses and says what it repaired, the degenerate fixtures finish, and
//! `Triangulator::check` agrees with strict `triangulate`. (`core/tests/strict.rs` holds
//! the error tests that need no corpus and no judge.)

mod common;

use std::cmp::Ordering;
use std::time::Duration;

use common::{
    assert_no_failures, earcut_fixture, earcut_fixtures, guarded_triangulate, SELF_INTERSECTING,
};
use polytri::{Error, Nesting, Options, Strategy, Triangulator};
use polytri_oracle::exact::{cross_properly, orient};
use polytri_oracle::replay::Precision;
use polytri_oracle::{check, Input, Nesting as OracleNesting};

const TIMEOUT: Duration = Duration::from_secs(120);

/// Fixtures expecting no triangles from earcut: degenerate on purpose.
// Not here: `infinite-loop-jhl`, whose hole leaves a sliver of exact area 1.5e-28 between
// (0, 0) and (0, 1e-28). earcut rounds it away; polytri triangulates it (two triangles),
// and the corpus replay (`corpus.rs`) judges them.
const DEGENERATE: [&str; 4] = ["degenerate", "empty-square", "issue83", "issue107"];

fn strict(strategy: Strategy) -> Options {
    Options::default()
        .with_strategy(strategy)
        .with_nesting(Nesting::FirstIsOuter)
}

/// The ring holding input vertex `v`.
fn ring_of(input: &Input, v: usize) -> usize {
    input
        .ring_starts
        .iter()
        .rposition(|&s| s <= v)
        .expect("vertex in a ring")
}

/// The segments an edge named by its start vertex may be: from it to the next vertex at
/// another position, and on through successors collinear with that first segment (the core
/// names an edge by its start and runs it to the next *kept* vertex).
fn edge_segments(input: &Input, ring: usize, start: usize) -> Vec<([f64; 2], [f64; 2])> {
    let r: Vec<usize> = input.ring_range(ring).collect();
    let Some(k0) = r.iter().position(|&v| v == start) else {
        return vec![];
    };
    let p = input.vertices[start];
    let mut out = Vec::new();
    let mut first: Option<[f64; 2]> = None;
    for step in 1..=r.len() {
        let q = input.vertices[r[(k0 + step) % r.len()]];
        if q == p {
            continue;
        }
        match first {
            None => first = Some(q),
            Some(f) if orient(p, f, q) != Ordering::Equal => break,
            Some(_) => {}
        }
        out.push((p, q));
    }
    out
}

/// Checks an `EdgesCross` error against the input: rings and vertices in range, the Display
/// naming them, and the named edges really crossing (by the oracle's exact predicate).
fn check_edge_error(input: &Input, err: &Error, shown: &str) -> Result<(), String> {
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
        if ring >= input.ring_count() || v >= input.vertices.len() || ring_of(input, v) != ring {
            return Err(format!("{err:?}: vertex {v} is not in ring {ring}"));
        }
        for needle in [format!("ring {ring}"), format!("vertex {v}")] {
            if !shown.contains(&needle) {
                return Err(format!("Display {shown:?} does not mention {needle:?}"));
            }
        }
    }
    let sa = edge_segments(input, ring_a, edge_a);
    let sb = edge_segments(input, ring_b, edge_b);
    let crossing = sa
        .iter()
        .any(|&(a, b)| sb.iter().any(|&(c, d)| cross_properly(a, b, c, d)));
    if !crossing {
        return Err(format!("{err:?}: the named edges do not cross"));
    }
    Ok(())
}

#[test]
fn strict_refuses_self_intersecting_fixtures() {
    let mut failures = Vec::new();
    for name in SELF_INTERSECTING {
        let input = earcut_fixture(name);
        for strategy in [Strategy::Fast, Strategy::Quality] {
            let tag = format!("{name} {strategy:?} strict");
            match guarded_triangulate(&input, strict(strategy), Precision::F64, TIMEOUT) {
                Err(e) => failures.push(format!("{tag}: {e}")),
                Ok(Ok(run)) => failures.push(format!(
                    "{tag}: Ok with {} triangles, expected EdgesCross",
                    run.triangles.len()
                )),
                Ok(Err(err)) => {
                    if let Err(e) = check_edge_error(&input, &err, &err.to_string()) {
                        failures.push(format!("{tag}: expected a truthful EdgesCross: {e}"));
                    }
                }
            }
        }
    }
    assert_no_failures(&failures);
}

/// Lenient mode never errors on the self-intersecting fixtures, and says it repaired them.
#[test]
fn lenient_never_errors_and_reports_repairs() {
    let mut failures = Vec::new();
    for name in SELF_INTERSECTING {
        let input = earcut_fixture(name);
        for strategy in [Strategy::Fast, Strategy::Quality] {
            let opts = strict(strategy).with_lenient(true);
            let tag = format!("{name} {strategy:?} lenient");
            match guarded_triangulate(&input, opts, Precision::F64, TIMEOUT) {
                Err(e) => failures.push(format!("{tag}: {e}")),
                Ok(Err(e)) => failures.push(format!("{tag}: Err({e:?}): {e}")),
                Ok(Ok(run)) => {
                    if run.repairs == 0 || run.clean {
                        failures.push(format!("{tag}: crossing input but no repair reported"));
                    }
                }
            }
        }
    }
    assert_no_failures(&failures);
}

/// The degenerate fixtures finish in every mode and triangulate to nothing (their polygons
/// have no area), except `issue107`, whose hole lies outside its zero-area outer ring.
#[test]
fn degenerate_fixtures_finish() {
    let mut failures = Vec::new();
    for name in DEGENERATE {
        let input = earcut_fixture(name);
        for strategy in [Strategy::Fast, Strategy::Quality] {
            for lenient in [false, true] {
                let tag = format!(
                    "{name} {strategy:?} {}",
                    if lenient { "lenient" } else { "strict" }
                );
                let opts = strict(strategy).with_lenient(lenient);
                match guarded_triangulate(&input, opts, Precision::F64, TIMEOUT) {
                    Err(e) => failures.push(format!("{tag}: {e}")),
                    Ok(Err(e)) if lenient => failures.push(format!("{tag}: Err({e:?}): {e}")),
                    Ok(Err(_)) => {}
                    Ok(Ok(run)) => {
                        if !run.triangles.is_empty() && name != "issue107" {
                            failures.push(format!(
                                "{tag}: {} triangles on a zero-area input",
                                run.triangles.len()
                            ));
                        }
                    }
                }
            }
        }
    }
    assert_no_failures(&failures);
}

/// Two triangles pinched at their shared rightmost vertex (3, 1), one ring. The turn at a
/// visit of the rightmost vertex may pair an edge of one lobe with an edge of the other,
/// so it cannot tell the winding; the lowest edge there can. Found by `polytri precision`
/// (a spiral collapsed by f32 rounding), where one start vertex made the ring a "hole".
/// Every start and both windings: two triangles, which the oracle accepts, covering both
/// lobes (area 1 + 5.5).
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
    let area = 6.5;
    for reversed in [false, true] {
        for start in 0..ring.len() {
            let mut turned: Vec<[f64; 2]> = (0..ring.len())
                .map(|k| ring[(start + k) % ring.len()])
                .collect();
            if reversed {
                turned.reverse();
            }
            let what = format!("start {start}, reversed {reversed}");
            let input = Input::from_rings(&[turned], OracleNesting::FirstIsOuter);
            for strategy in [Strategy::Fast, Strategy::Quality] {
                let mut out = Vec::new();
                Triangulator::<f64>::new()
                    .triangulate(&input.vertices, &[0], &strict(strategy), &mut out)
                    .unwrap_or_else(|e| panic!("{what}, {strategy:?}: {e}"));
                assert_eq!(out.len(), 2, "{what}, {strategy:?}");
                let verdict = check(&input, &out);
                assert!(
                    verdict.valid,
                    "{what}, {strategy:?}: {:?}",
                    verdict.failures()
                );
                let cdt = verdict.cdt.expect("the CDT comparison ran");
                assert_eq!(cdt.area, area, "{what}, {strategy:?}");
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
    for case in earcut_fixtures() {
        let (name, input) = (&case.name, &case.input);
        let checked = tri.check(&input.vertices, &input.ring_starts, Nesting::FirstIsOuter);
        let triangulated = tri
            .triangulate(&input.vertices, &input.ring_starts, &opts, &mut out)
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
