//! The reference `earcut-exact` (earcut 0.4.12 with exact predicates) on earcut's fixtures,
//! judged by the oracle: wherever the input is valid and plain earcut's triangulation is
//! valid, earcut-exact's is valid too, with as many triangles — exact predicates cost
//! earcut time, never a triangulation it had. Its baseline `earcut-vendored` (the same
//! copy with earcut's own predicates) makes plain earcut's very triangles.

mod common;

use common::earcut_fixtures;
use polytri_oracle::peers::{self, Peer};
use polytri_oracle::{check_with, CheckOptions};

#[test]
fn earcut_exact_is_valid_wherever_earcut_is() {
    let mut failures = Vec::new();
    let mut judged = 0;
    for case in earcut_fixtures() {
        let input = &case.input;
        let earcut = peers::triangulate(Peer::Earcut, input).expect("earcut runs");
        let options = CheckOptions::fast();
        let verdict = check_with(input, &earcut.triangles, &options);
        if !(verdict.input_valid && verdict.valid) {
            continue;
        }
        judged += 1;
        let exact = match peers::triangulate(Peer::EarcutExact, input) {
            Ok(out) => out,
            Err(e) => {
                failures.push(format!("{}: earcut-exact failed: {e}", case.name));
                continue;
            }
        };
        assert_eq!(exact.vertices, None, "{}: the input's vertices", case.name);
        let exact_verdict = check_with(input, &exact.triangles, &options);
        if !exact_verdict.valid {
            failures.push(format!(
                "{}: earcut-exact's triangulation is invalid: {}",
                case.name,
                exact_verdict.failures().join("; ")
            ));
        }
        if exact.triangles.len() != earcut.triangles.len() {
            failures.push(format!(
                "{}: earcut-exact made {} triangles, earcut {}",
                case.name,
                exact.triangles.len(),
                earcut.triangles.len()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    // of the 59 fixtures, 34 are valid and validly triangulated by earcut (when written)
    assert!(judged >= 30, "only {judged} fixtures judged");
}

#[test]
fn earcut_vendored_makes_earcuts_triangles() {
    for case in earcut_fixtures() {
        let earcut = peers::triangulate(Peer::Earcut, &case.input);
        let vendored = peers::triangulate(Peer::EarcutVendored, &case.input);
        assert_eq!(vendored, earcut, "{}", case.name);
    }
}

#[test]
fn references_are_named_but_are_no_peers() {
    for peer in Peer::REFERENCES {
        assert!(peer.is_reference(), "{peer}");
        assert!(!Peer::ALL.contains(&peer), "{peer}");
        assert_eq!(peer.name().parse::<Peer>(), Ok(peer));
    }
    assert!(Peer::ALL.iter().all(|p| !p.is_reference()));
    assert_eq!("earcut-exact".parse::<Peer>(), Ok(Peer::EarcutExact));
}
