//! Rings lying on each other, against the oracle: copies of a ring (the same way round or
//! reversed, from any start), copies with a zero-width spike out of or into the ring,
//! copies inside a third ring, a ring touching itself where another ring touches it, and
//! a ring winding twice round a triangle that a hole cancels.
//! `raw_rings` found such inputs where polytri's nesting and the oracle's disagreed.
//!
//! For every configuration, in four exact rotations, with every ring in both windings and
//! with both nesting conventions (automatic, and earcut's first-is-outer):
//! strict mode triangulates exactly the inputs the oracle finds valid (and the oracle
//! accepts the result), and lenient mode always gives a result, a valid one where the input
//! is valid.
//!
//! Figure eights whose lobes turn opposite ways, one lobe cancelled by another ring, are
//! valid too, and so is a ring with a lobe inside its other lobe, sharing an edge, the
//! outer lobe cancelled by another ring; there only lenient mode is held to a result
//! (strict mode may refuse them).

mod common;

use common::{assert_no_failures, run};
use polytri::Strategy;
use polytri_oracle::{check_with, CheckOptions, Input, Nesting};

type Ring = Vec<[f64; 2]>;

fn triangle() -> Ring {
    vec![[1.0, 0.0], [3.0, 2.0], [1.0, 1.0]]
}

fn square() -> Ring {
    vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]
}

/// A square with a notch cut into its bottom edge: every corner of [`square`] is its
/// corner too.
fn notched_square() -> Ring {
    vec![
        [0.0, 0.0],
        [1.0, 0.0],
        [2.0, 1.0],
        [3.0, 0.0],
        [4.0, 0.0],
        [4.0, 4.0],
        [0.0, 4.0],
    ]
}

/// `ring` from its `k`-th vertex on.
fn from(ring: &Ring, k: usize) -> Ring {
    let k = k % ring.len();
    ring[k..].iter().chain(&ring[..k]).copied().collect()
}

fn reversed(ring: &Ring) -> Ring {
    ring.iter().rev().copied().collect()
}

/// `ring` with a zero-width spike from its vertex `k` to `tip` and back.
fn spiked(ring: &Ring, k: usize, tip: [f64; 2]) -> Ring {
    let mut out = ring[..=k].to_vec();
    out.push(tip);
    out.extend_from_slice(&ring[k..]);
    out
}

/// The configurations, each a list of rings.
fn configurations() -> Vec<(String, Vec<Ring>)> {
    let mut out = Vec::new();
    for (name, base, outside, inside) in [
        ("triangle", triangle(), [0.0, 0.0], [2.0, 1.0]),
        ("square", square(), [-2.0, -2.0], [2.0, 2.0]),
    ] {
        for k in 0..base.len() {
            out.push((
                format!("{name} twice from {k}"),
                vec![base.clone(), from(&base, k)],
            ));
            out.push((
                format!("{name} and its reverse from {k}"),
                vec![base.clone(), reversed(&from(&base, k))],
            ));
        }
        for (side, tip) in [("out", outside), ("in", inside)] {
            let spike = spiked(&base, 0, tip);
            out.push((
                format!("{name} and a copy spiked {side}"),
                vec![base.clone(), spike.clone()],
            ));
            out.push((
                format!("{name} spiked {side} and a copy"),
                vec![spike.clone(), base.clone()],
            ));
            out.push((
                format!("{name} and a reversed copy spiked {side}"),
                vec![base.clone(), reversed(&spike)],
            ));
            let frame = vec![[-10.0, -10.0], [10.0, -10.0], [10.0, 10.0], [-10.0, 10.0]];
            out.push((
                format!("{name} and a copy spiked {side}, in a frame"),
                vec![frame.clone(), base.clone(), spike],
            ));
        }
        out.push((
            format!("{name} three times"),
            vec![base.clone(), from(&base, 1), from(&base, 2)],
        ));
    }
    out.push((
        "square and a notched square".into(),
        vec![square(), notched_square()],
    ));
    out.push((
        "notched square and a square".into(),
        vec![notched_square(), square()],
    ));
    // a triangle with a spike, and a copy with spikes along the first one's and out
    // (raw_rings, seed 21): the first spike's tip lies on the copy, so it decides nothing
    let spiked_triangle = vec![[0.0, 15.0], [0.0, 0.0], [1.0, 0.0], [0.0, 10.0]];
    let copy = vec![
        [0.0, 0.0],
        [1.0, 0.0],
        [0.0, 10.0],
        [0.0, 0.0],
        [0.0, 15.0],
        [0.0, 0.0],
        [-5.0, 13.0],
    ];
    out.push((
        "spiked triangle and a copy spiked along it".into(),
        vec![spiked_triangle.clone(), copy.clone()],
    ));
    out.push((
        "copy spiked along a spiked triangle".into(),
        vec![copy, spiked_triangle],
    ));
    // several rings through one point: a ring pinched into two lobes at (0, 0), a hole in
    // one lobe touching the pinch, an island in that hole touching it there too
    let pinched = vec![
        [0.0, 0.0],
        [8.0, -4.0],
        [8.0, 4.0],
        [0.0, 0.0],
        [-8.0, 4.0],
        [-8.0, -4.0],
    ];
    let hole = vec![[0.0, 0.0], [6.0, 2.0], [6.0, -2.0]];
    let island = vec![[0.0, 0.0], [5.0, -1.0], [5.0, 1.0]];
    out.push((
        "pinched lobes, a hole at the pinch".into(),
        vec![pinched.clone(), hole.clone()],
    ));
    out.push((
        "pinched lobes, a hole and an island at the pinch".into(),
        vec![island.clone(), pinched.clone(), hole.clone()],
    ));
    // two holes of a square touching each other and the square at one corner
    let corner_holes = vec![
        square(),
        vec![[0.0, 0.0], [3.0, 1.0], [1.0, 1.0]],
        vec![[0.0, 0.0], [1.0, 3.0], [1.0, 2.0]],
    ];
    out.push(("two holes at a corner".into(), corner_holes));
    // an island in the other lobe's mirror: lobes of a pinched ring, each holding a
    // triangle that touches the pinch (the second triangle crosses nothing either)
    out.push((
        "pinched lobes with a triangle in each".into(),
        vec![
            pinched,
            hole,
            vec![[0.0, 0.0], [-6.0, -2.0], [-6.0, 2.0]],
            island,
        ],
    ));
    // a ring touching itself at (0, -1), where a triangle touches both of its lobes along
    // an edge each (raw_rings, seed 13)
    let lobes = vec![
        [0.0, 9.0],
        [0.0, -1.0],
        [10.0, 11.0],
        [-1.0, -8.0],
        [0.0, -1.0],
        [-1.0, 15.0],
    ];
    let wedge = vec![[-1.0, -8.0], [0.0, -1.0], [-1.0, 15.0]];
    out.push((
        "lobes and a wedge".into(),
        vec![wedge.clone(), lobes.clone()],
    ));
    out.push(("wedge and lobes".into(), vec![lobes, wedge]));
    // The ray from a ring's rightmost vertex running exactly through another ring's vertex
    // (a grid of round holes does this at every hole): the vertex's corner decides
    let diamond =
        |cx: f64, cy: f64, r: f64| vec![[cx + r, cy], [cx, cy + r], [cx - r, cy], [cx, cy - r]];
    let frame = vec![[0.0, 0.0], [16.0, 0.0], [16.0, 12.0], [0.0, 12.0]];
    out.push((
        "a hole whose ray meets the next hole's vertex".into(),
        vec![
            frame.clone(),
            diamond(3.0, 6.0, 2.0),
            diamond(8.0, 6.0, 2.0),
        ],
    ));
    out.push((
        "a hole whose ray meets the outer ring's vertex".into(),
        vec![diamond(8.0, 6.0, 6.0), diamond(7.0, 6.0, 2.0)],
    ));
    // the outer ring's reflex vertices (8, 6) and (12, 6), tips of notches from the left and
    // from the top; the hole at (4, 6) lies in the left notch, outside the outer ring
    let notched = vec![
        [0.0, 0.0],
        [16.0, 0.0],
        [16.0, 12.0],
        [12.0, 6.0],
        [14.0, 12.0],
        [0.0, 12.0],
        [8.0, 6.0],
    ];
    out.push((
        "holes whose rays meet reflex vertices of the outer ring".into(),
        vec![
            notched.clone(),
            diamond(4.0, 6.0, 1.0),
            diamond(10.0, 6.0, 1.0),
        ],
    ));
    // the ray meets another hole's edge first, and the outer ring's vertex (12, 6) beyond it
    out.push((
        "a hole whose ray meets an edge before a vertex".into(),
        vec![
            notched,
            diamond(9.0, 6.0, 0.5),
            vec![[10.0, 4.0], [11.0, 4.0], [11.0, 8.0], [10.0, 8.0]],
        ],
    ));
    out.push((
        "an island whose ray meets its hole's vertex".into(),
        vec![frame, diamond(8.0, 6.0, 5.0), diamond(7.0, 6.0, 2.0)],
    ));
    // Three holes touching at (5, 2), (5, 3) and (6, 2) enclose an island, the triangle
    // between them; the left hole's ray meets their shared vertex (5, 3), where the
    // island's edge ties with the holes' (precision fuzz target, seed 2424).
    out.push((
        "a hole whose ray meets a vertex holes share around an island".into(),
        vec![
            vec![[1.0, 6.0], [1.0, 2.0], [4.0, 0.0], [8.0, 3.0]],
            vec![[5.0, 2.0], [5.0, 1.0], [6.0, 2.0]],
            vec![[2.0, 3.0], [3.0, 3.0], [2.0, 2.0]],
            vec![[5.0, 3.0], [5.0, 2.0], [4.0, 2.0]],
            vec![[6.0, 3.0], [5.0, 3.0], [6.0, 2.0]],
        ],
    ));
    // Zero-width parts that cross the outer ring's edge x = 10: a hole's spike out to
    // (12, 2), and a ring of two points. Cleaning drops both, and with them the crossing,
    // which the input has all the same (precision fuzz target, seeds 2424 and 3131).
    let square10 = vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]];
    out.push((
        "a hole's spike across the outer ring".into(),
        vec![
            square10.clone(),
            vec![[3.0, 4.0], [2.0, 2.0], [12.0, 2.0], [4.0, 2.0]],
        ],
    ));
    out.push((
        "a hole's spike inside the outer ring".into(),
        vec![
            square10.clone(),
            vec![[3.0, 4.0], [2.0, 2.0], [8.0, 2.0], [4.0, 2.0]],
        ],
    ));
    out.push((
        "a ring of two points across the outer ring".into(),
        vec![square10.clone(), vec![[5.0, 5.0], [15.0, 5.0]]],
    ));
    out.push((
        "a ring of two points inside the outer ring".into(),
        vec![square10, vec![[5.0, 5.0], [8.0, 5.0]]],
    ));
    // An outer ring A B C A D C E winding twice round the triangle A B C, B on A–D, and a
    // hole B C A: the region is A D C E (raw_rings, seed 7171). Lenient mode cut the ring
    // into lobes that overlapped, depending on which copy of a repeated vertex survived
    // cleaning: so every start, with A repeated and without.
    let (a, b, c, d, e) = (
        [-12.0, -12.0],
        [-12.0, 1.0],
        [0.0, 0.0],
        [-12.0, 15.0],
        [1.0, 0.0],
    );
    for (name, outer) in [
        ("", vec![a, b, c, a, d, c, e]),
        (", A repeated", vec![a, b, c, a, a, d, c, e]),
    ] {
        for k in 0..outer.len() {
            out.push((
                format!("a ring twice round a triangle a hole cancels{name}, from {k}"),
                vec![vec![b, c, a], from(&outer, k)],
            ));
        }
    }
    // One ring: a lower part A B C along y = 0 to D, up round an upper lobe D E F G H, back
    // along y = 0 from H to O, and down round a notch O I J (raw_rings, seed 9696). The
    // segment O–D is walked both ways. Lenient mode cut it into lobes, one of them with a
    // wall J–D left on it whose tip was its rightmost vertex, read that tip's (straight)
    // turn as counter-clockwise, and made the notch part of the region.
    let ring = vec![
        [2.0, -6.0],
        [-6.0, -6.0],
        [-6.0, 0.0],
        [8.0, 0.0],
        [10.0, 11.0],
        [11.0, 11.0],
        [11.0, 10.0],
        [10.0, 0.0],
        [0.0, 0.0],
        [-1.0, -4.0],
        [3.0, 0.0],
    ];
    for k in 0..ring.len() {
        out.push((
            format!("a lobe with a wall whose tip is rightmost, from {k}"),
            vec![from(&ring, k)],
        ));
    }
    out
}

/// `rings` turned by `quarter` quarter turns (exact) with ring `r` reversed where bit r of
/// `flips` is set.
fn variant(rings: &[Ring], quarter: u32, flips: u32, nesting: Nesting) -> Input {
    let turn = |[x, y]: [f64; 2]| match quarter % 4 {
        0 => [x, y],
        1 => [-y, x],
        2 => [-x, -y],
        _ => [y, -x],
    };
    let mut vertices = Vec::new();
    let mut starts = Vec::new();
    for (r, ring) in rings.iter().enumerate() {
        starts.push(vertices.len());
        let ring = if flips >> r & 1 == 1 {
            reversed(ring)
        } else {
            ring.clone()
        };
        vertices.extend(ring.into_iter().map(turn));
    }
    Input::new(vertices, starts, nesting)
}

/// Every variant of `rings`: four rotations, both nesting conventions, each ring in both
/// windings; with a name saying which.
fn variants(rings: &[Ring]) -> impl Iterator<Item = (String, Input)> + '_ {
    (0..4)
        .flat_map(|q| [(q, Nesting::Auto), (q, Nesting::FirstIsOuter)])
        .flat_map(move |(quarter, nesting)| {
            (0..1u32 << rings.len()).map(move |flips| {
                (
                    format!("{quarter} quarter turns, flips {flips:b}, {nesting:?}"),
                    variant(rings, quarter, flips, nesting.clone()),
                )
            })
        })
}

/// Runs every variant of `rings` in both strategies, strict and lenient, into `failures`:
/// lenient mode must always give a result, valid where the oracle calls the input valid;
/// a strict result must be valid; with `strict_exact`, strict mode must also accept every
/// valid input and refuse every invalid one. Returns the numbers of valid and invalid
/// variants.
fn check_variants(
    name: &str,
    rings: &[Ring],
    strict_exact: bool,
    failures: &mut Vec<String>,
) -> (usize, usize) {
    let (mut valid, mut invalid) = (0, 0);
    for (what, input) in variants(rings) {
        let judged = check_with(&input, &[], &CheckOptions::fast());
        let input_valid = judged.input_valid;
        if input_valid {
            valid += 1;
        } else {
            invalid += 1;
        }
        for strategy in [Strategy::Fast, Strategy::Quality] {
            for lenient in [false, true] {
                let run_name = format!("{name}, {what}, {strategy:?}, lenient {lenient}");
                match run(&input, strategy, lenient) {
                    Ok(triangles) if input_valid => {
                        let verdict = check_with(&input, &triangles, &CheckOptions::fast());
                        if !verdict.valid {
                            failures.push(format!("{run_name}: {:?}", verdict.failures()));
                        }
                    }
                    Ok(_) if !lenient && strict_exact => failures.push(format!(
                        "{run_name}: accepted, but the oracle finds the input invalid: {:?}",
                        judged.failures()
                    )),
                    Ok(_) => {}
                    Err(e) if lenient || (input_valid && strict_exact) => {
                        failures.push(format!("{run_name}: refused: {e}"));
                    }
                    Err(_) => {}
                }
            }
        }
    }
    (valid, invalid)
}

#[test]
fn strict_mode_accepts_exactly_what_the_oracle_calls_valid() {
    let mut failures = Vec::new();
    let (mut valid, mut invalid) = (0, 0);
    for (name, rings) in configurations() {
        let (v, i) = check_variants(&name, &rings, true, &mut failures);
        (valid, invalid) = (valid + v, invalid + i);
    }
    // both kinds occur, so neither half of the property is vacuous
    assert!(
        valid > 50 && invalid > 50,
        "{valid} valid, {invalid} invalid"
    );
    assert_no_failures(&failures);
}

/// Two figure eights sharing a counter-clockwise lobe B, with clockwise lobes A ⊃ A'
/// (raw_rings, seed 41): the region is A minus A', B cancels. Variants pinch at a vertex
/// or inside an edge, share A's edge or not, and come in either ring order.
fn figure_eights() -> Vec<(String, Vec<Ring>)> {
    // pinched inside the edge (−12, −12) → (11, 11), as the fuzzer found it
    let outer_on_edge = vec![
        [11.0, 11.0],
        [-3.0, 0.0],
        [0.0, 0.0],
        [5.0, -12.0],
        [-12.0, -12.0],
    ];
    let hole_on_edge = vec![
        [-12.0, -12.0],
        [11.0, 11.0],
        [-3.0, 0.0],
        [0.0, 0.0],
        [-4.0, -8.0],
    ];
    // pinched at a vertex of both rings, A' touching A only there
    let outer_at_vertex = vec![
        [0.0, 0.0],
        [8.0, 8.0],
        [-2.0, 6.0],
        [0.0, 0.0],
        [6.0, -10.0],
        [-10.0, -10.0],
    ];
    let hole_at_vertex = vec![
        [0.0, 0.0],
        [8.0, 8.0],
        [-2.0, 6.0],
        [0.0, 0.0],
        [1.0, -6.0],
        [-5.0, -6.0],
    ];
    let frame = vec![[-20.0, -20.0], [20.0, -20.0], [20.0, 20.0], [-20.0, 20.0]];
    let mut out = Vec::new();
    for (name, a, b) in [
        ("on an edge", outer_on_edge, hole_on_edge),
        ("at a vertex", outer_at_vertex, hole_at_vertex),
    ] {
        out.push((
            format!("figure eights sharing a lobe, pinched {name}"),
            vec![a.clone(), b.clone()],
        ));
        out.push((
            format!("figure eights sharing a lobe, pinched {name}, hole first"),
            vec![b.clone(), a.clone()],
        ));
        out.push((
            format!("figure eights sharing a lobe, pinched {name}, from 2"),
            vec![from(&a, 2), from(&b, 3)],
        ));
        out.push((
            format!("figure eights sharing a lobe, pinched {name}, in a hole"),
            vec![frame.clone(), a, b],
        ));
    }
    out
}

/// Every variant of every configuration through [`check_variants`], strict mode held to
/// valid results only: no failure, and at least `least_valid` variants the oracle calls
/// valid.
fn assert_lenient_covers(configurations: Vec<(String, Vec<Ring>)>, least_valid: usize) {
    let mut failures = Vec::new();
    let mut valid = 0;
    for (name, rings) in configurations {
        valid += check_variants(&name, &rings, false, &mut failures).0;
    }
    assert!(valid >= least_valid, "only {valid} valid variants");
    assert_no_failures(&failures);
}

#[test]
fn lenient_mode_covers_figure_eights_whose_lobe_another_ring_cancels() {
    assert_lenient_covers(figure_eights(), 32);
}

/// A ring P O T P L T whose lobe P O T lies inside its lobe P L T (O on L–T, the edge
/// P–T walked twice), and a ring P L T lying on the outer lobe (raw_rings, seed 9595:
/// lenient mode filled nothing). Both lobes turn the same way, so the ring winds twice
/// round P O T; the other ring cancels one turn, and the region is P O T. As found, the
/// ring also runs out along walls and back.
fn lobe_in_lobe() -> Vec<(String, Vec<Ring>)> {
    let (p, q, o, t, l, r) = (
        [-1.0, -1.0],
        [-13.0, -1.0],
        [0.0, 0.0],
        [10.0, 0.0],
        [-12.0, 0.0],
        [0.0, -1.0],
    );
    let cancelling = vec![p, l, t];
    let plain = vec![p, o, t, p, l, t];
    let walled = vec![p, q, p, o, t, p, p, l, t, p, q, p, r];
    let mut out = Vec::new();
    for (name, ring) in [("", plain), (", with walls", walled)] {
        for k in 0..ring.len() {
            out.push((
                format!("a lobe in a lobe another ring cancels{name}, from {k}"),
                vec![cancelling.clone(), from(&ring, k)],
            ));
        }
        out.push((
            format!("a lobe in a lobe another ring cancels{name}, that ring last"),
            vec![ring, cancelling.clone()],
        ));
    }
    out
}

#[test]
fn lenient_mode_covers_a_lobe_in_a_lobe_another_ring_cancels() {
    assert_lenient_covers(lobe_in_lobe(), 100);
}
