//! Every peer, and the references, on small known polygons and on earcut's fixtures:
//! triangle counts and area sums, computed here from the rings.

use std::path::PathBuf;

use polytri_oracle::peers::{self, Implementation, Peer, PeerOutput, Prepared, Runner};
use polytri_oracle::{Input, Nesting, Role};

fn square(x: f64, y: f64, size: f64) -> Vec<[f64; 2]> {
    vec![[x, y], [x + size, y], [x + size, y + size], [x, y + size]]
}

/// A 10×10 square with a 4×4 hole: area 84, 8 triangles.
fn square_with_hole() -> Input {
    let mut hole = square(3.0, 3.0, 4.0);
    hole.reverse();
    Input::from_rings(&[square(0.0, 0.0, 10.0), hole], Nesting::FirstIsOuter)
}

fn ring_area(ring: &[[f64; 2]]) -> f64 {
    let twice: f64 = (0..ring.len())
        .map(|k| {
            let [x0, y0] = ring[k];
            let [x1, y1] = ring[(k + 1) % ring.len()];
            x0 * y1 - x1 * y0
        })
        .sum();
    (twice / 2.0).abs()
}

/// The area of a first-is-outer polygon: the outer ring's less its holes'.
fn polygon_area(rings: &[Vec<[f64; 2]>]) -> f64 {
    ring_area(&rings[0]) - rings[1..].iter().map(|r| ring_area(r)).sum::<f64>()
}

/// The summed area of the triangles, each counted with its sign (all should be
/// counter-clockwise, so positive).
fn triangle_area(out: &PeerOutput, input: &Input) -> f64 {
    let p = out.positions(input);
    out.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| p[v as usize]);
            ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])) / 2.0
        })
        .sum()
}

/// Runs `peer`, checks the area against `area` (relative `tolerance`), returns the output.
fn run(peer: Peer, input: &Input, area: f64, tolerance: f64) -> PeerOutput {
    let out = peers::triangulate(peer, input).unwrap_or_else(|e| panic!("{peer}: {e}"));
    let got = triangle_area(&out, input);
    assert!(
        (got - area).abs() <= tolerance * area,
        "{peer}: area {got}, expected {area}"
    );
    out
}

/// Every peer, then the references (earcut with exact predicates, and its baseline).
fn every_peer() -> impl Iterator<Item = Peer> {
    Peer::ALL.into_iter().chain(Peer::REFERENCES)
}

/// lyon computes in f32: its areas are only that close.
fn tolerance(peer: Peer) -> f64 {
    if peer == Peer::Lyon {
        1e-5
    } else {
        1e-9
    }
}

#[test]
fn every_peer_triangulates_a_square_with_a_hole() {
    let input = square_with_hole();
    for peer in every_peer() {
        let out = run(peer, &input, 84.0, 1e-12);
        assert_eq!(out.triangles.len(), 8, "{peer}");
        assert_eq!(
            out.vertices, None,
            "{peer} should keep the input's vertices"
        );
    }
}

#[test]
fn every_peer_with_f32_or_unsupported() {
    let input = square_with_hole();
    for peer in every_peer() {
        match peers::triangulate_f32(peer, &input) {
            Ok(out) => {
                assert_eq!(out.triangles.len(), 8, "{peer}");
                assert!((triangle_area(&out, &input) - 84.0).abs() < 1e-9, "{peer}");
            }
            Err(e) => {
                assert_eq!(peer, Peer::Spade);
                assert_eq!(e, "unsupported");
            }
        }
    }
}

#[test]
fn auto_nesting_and_roles_give_islands_to_every_peer() {
    // 10×10 outer, 6×6 hole, 2×2 island in the hole, a separate 1×1 square:
    // 100 − 36 + 4 + 1 = 69
    let rings = vec![
        square(4.0, 4.0, 2.0),
        square(0.0, 0.0, 10.0),
        square(2.0, 2.0, 6.0),
        square(20.0, 0.0, 1.0),
    ];
    let auto = Input::from_rings(&rings, Nesting::Auto);
    let roles = Input::from_rings(
        &[
            rings[1].clone(),
            rings[2].clone(),
            rings[0].clone(),
            rings[3].clone(),
        ],
        Nesting::Roles(vec![Role::Outer, Role::Hole, Role::Outer, Role::Outer]),
    );
    for input in [&auto, &roles] {
        for peer in every_peer() {
            let out = run(peer, input, 69.0, 1e-12);
            assert_eq!(out.triangles.len(), 8 + 2 + 2, "{peer}");
        }
    }
}

#[test]
fn peers_refuse_instead_of_panicking() {
    let nan = Input::from_rings(
        &[vec![[0.0, 0.0], [f64::NAN, 0.0], [1.0, 1.0]]],
        Nesting::FirstIsOuter,
    );
    // two squares whose edges cross: spade's constraints conflict
    let crossing = Input::from_rings(
        &[square(0.0, 0.0, 4.0), square(2.0, 2.0, 4.0)],
        Nesting::Auto,
    );
    let huge = Input::from_rings(
        &[vec![[0.0, 0.0], [1e300, 0.0], [1e300, 1e300]]],
        Nesting::FirstIsOuter,
    );
    for peer in every_peer() {
        assert!(peers::triangulate(peer, &nan).is_err(), "{peer}");
        // anything but a panic will do
        let _ = peers::triangulate(peer, &crossing);
        let _ = peers::triangulate(peer, &huge);
        let _ = peers::triangulate_f32(peer, &huge);
    }
}

#[test]
fn names_round_trip() {
    for imp in Implementation::all() {
        assert_eq!(imp.to_string().parse::<Implementation>(), Ok(imp));
    }
    assert_eq!("i_triangle".parse::<Peer>(), Ok(Peer::ITriangle));
    assert!("triangle".parse::<Peer>().is_err());
}

fn corpus() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../corpus/earcut")
}

fn fixture(name: &str) -> (Vec<Vec<[f64; 2]>>, usize) {
    let text = std::fs::read_to_string(corpus().join(format!("fixtures/{name}.json")))
        .expect("read fixture");
    let rings: Vec<Vec<[f64; 2]>> = serde_json::from_str(&text).expect("rings JSON");
    let expected: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(corpus().join("expected.json")).unwrap())
            .expect("expected.json");
    let count = expected["triangles"][name]
        .as_u64()
        .expect("expected count") as usize;
    (rings, count)
}

#[test]
fn every_peer_on_earcut_fixtures() {
    for name in ["building", "dude", "water3"] {
        let (rings, count) = fixture(name);
        let input = Input::from_rings(&rings, Nesting::FirstIsOuter);
        let area = polygon_area(&rings);
        for peer in every_peer() {
            let out = run(peer, &input, area, tolerance(peer));
            if peer == Peer::ITriangle {
                // i_triangle drops collinear vertices: fewer triangles, same area
                assert!(out.triangles.len() <= count, "{peer} on {name}");
            } else {
                assert_eq!(out.triangles.len(), count, "{peer} on {name}");
            }
        }
    }
}

#[test]
fn runner_counts_match_one_shot_runs() {
    let (rings, count) = fixture("dude");
    let prepared = Prepared::new(&Input::from_rings(&rings, Nesting::FirstIsOuter));
    let mut runner = Runner::new();
    for imp in Implementation::all() {
        // the check alone makes no triangles
        let expected = if imp == Implementation::PolytriCheck {
            0
        } else {
            count
        };
        for _ in 0..2 {
            assert_eq!(runner.run(imp, &prepared), Ok(expected), "{imp}");
        }
    }
}

#[test]
fn runner_check_refuses_what_strict_polytri_refuses() {
    let bow_tie = vec![[0.0, 0.0], [4.0, 4.0], [4.0, 0.0], [0.0, 4.0]];
    let prepared = Prepared::new(&Input::from_rings(&[bow_tie], Nesting::FirstIsOuter));
    let mut runner = Runner::new();
    let check = runner.run(Implementation::PolytriCheck, &prepared);
    let fast = runner.run(Implementation::PolytriFast, &prepared);
    assert!(check.is_err(), "{check:?}");
    assert_eq!(check, fast);
    assert!(runner
        .run(Implementation::PolytriLenient, &prepared)
        .is_ok());
}

/// The nonzero peers read a square wound twice (and a hole wound the same way as its
/// outer ring) as the nonzero rule does — the whole square — where the even–odd peers
/// leave the parts wound twice out; the runner's nonzero configurations of polytri agree.
#[test]
fn nonzero_peers_fill_what_is_wound_twice() {
    let twice = [square(0.0, 0.0, 10.0), square(0.0, 0.0, 10.0)].concat();
    let same_way = [square(0.0, 0.0, 10.0), square(3.0, 3.0, 4.0)];
    for (rings, nonzero, even_odd) in [(vec![twice], 100.0, 0.0), (same_way.to_vec(), 100.0, 84.0)]
    {
        let input = Input::from_rings(&rings, Nesting::Auto);
        for peer in Peer::NONZERO {
            let tolerance = if peer == Peer::LyonNonZero {
                1e-5
            } else {
                1e-9
            };
            run(peer, &input, nonzero, tolerance);
        }
        for peer in [Peer::Lyon, Peer::ITriangle] {
            let out = peers::triangulate(peer, &input).unwrap_or_else(|e| panic!("{peer}: {e}"));
            assert!(
                (triangle_area(&out, &input) - even_odd).abs() < 1e-4,
                "{peer}"
            );
        }
        let prepared = Prepared::new(&input);
        let mut runner = Runner::new();
        let many = |runner: &mut Runner, imp| runner.run(imp, &prepared).map(|t| t > 0);
        let nonzero = [
            Implementation::PolytriNonZero,
            Implementation::PolytriSeidelNonZero,
            Implementation::PolytriNonZeroEach,
        ];
        for imp in nonzero {
            assert_eq!(many(&mut runner, imp), Ok(true), "{imp}");
        }
        for imp in Peer::NONZERO.map(Implementation::Peer) {
            assert!(imp.is_peer());
            assert_eq!(imp.to_string().parse::<Implementation>(), Ok(imp));
        }
    }
}
