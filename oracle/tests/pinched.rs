//! Rings that touch themselves, made from rings that touch each other, against the oracle.
//!
//! `touching-holes` cases have holes touching each other and the outer ring at single
//! vertices. Two rings sharing a vertex X can be spliced into one ring that passes X twice:
//! the first ring up to X, the second all the way round from X back to X, then the rest of
//! the first. With the outer ring counter-clockwise and the holes clockwise, the spliced
//! ring has the same edges, so it bounds the same region: two holes become a figure eight
//! of holes, a hole and the outer ring an outer ring with a hole lobe (an "inverted hole").
//! Splicing again gives rings through a position three or four times.
//!
//! For seeded cases with random splices, random ring starts, random windings of the whole
//! input and random quarter turns, the oracle must call the input valid, and both
//! strategies, strict and lenient, must return a triangulation it accepts. (Lenient mode
//! cuts such rings into lobes; strict mode keeps them whole: both routes are covered.)

mod common;

use common::{assert_no_failures, run, shuffled, Rng};
use polytri::Strategy;
use polytri_oracle::{check_with, generate, CheckOptions, Family, Input, Nesting, Params};

type Ring = Vec<[f64; 2]>;

/// Twice the signed area (the coordinates are on a grid: exact enough for a sign).
fn area2(ring: &Ring) -> f64 {
    let n = ring.len();
    (0..n)
        .map(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            a[0] * b[1] - a[1] * b[0]
        })
        .sum()
}

fn oriented(ring: &Ring, counter_clockwise: bool) -> Ring {
    let mut ring = ring.clone();
    if (area2(&ring) > 0.0) != counter_clockwise {
        ring.reverse();
    }
    ring
}

/// `a` and `b` spliced at their first shared position, if they share one.
fn splice(a: &Ring, b: &Ring) -> Option<Ring> {
    let (i, j) = a
        .iter()
        .enumerate()
        .find_map(|(i, p)| b.iter().position(|q| q == p).map(|j| (i, j)))?;
    let mut out = a[..=i].to_vec();
    out.extend_from_slice(&b[j + 1..]);
    out.extend_from_slice(&b[..=j]);
    out.extend_from_slice(&a[i + 1..]);
    Some(out)
}

/// The case's rings, outer (the largest) counter-clockwise and holes clockwise, with up to
/// `splices` random pairs of touching rings spliced; also the number of splices made.
///
/// With `cancel`, each splice takes a hole touching the outer ring, reversed, into the
/// outer ring, and keeps the hole as well: the outer ring then winds twice round the hole
/// (its lobe there turns the same way as the rest), and the hole cancels one turn. Inside
/// it the winding number goes from 1 − 1 to 2 − 1: the hole becomes part of the region,
/// and the input stays valid. (A hole ring cannot host such a lobe: the copy would lie
/// inside two rings and count as outer, as nesting by containment has it.)
fn pinched(rings: &[Ring], rng: &mut Rng, splices: usize, cancel: bool) -> (Vec<Ring>, usize) {
    let outer = (0..rings.len())
        .max_by(|&i, &j| area2(&rings[i]).abs().total_cmp(&area2(&rings[j]).abs()))
        .unwrap_or(0);
    let mut rings: Vec<Ring> = rings
        .iter()
        .enumerate()
        .map(|(r, ring)| oriented(ring, r == outer))
        .collect();
    // with `cancel`: which rings are holes as generated and not yet cancelled
    let mut fresh_hole: Vec<bool> = (0..rings.len()).map(|r| r != outer).collect();
    let mut made = 0;
    for _ in 0..splices {
        let touching: Vec<(usize, usize)> = (0..rings.len())
            .flat_map(|a| (0..rings.len()).map(move |b| (a, b)))
            .filter(|&(a, b)| a != b && (!cancel || (a == outer && fresh_hole[b])))
            .filter(|&(a, b)| rings[a].iter().any(|p| rings[b].contains(p)))
            .collect();
        if touching.is_empty() {
            break;
        }
        let (a, b) = touching[rng.below(touching.len())];
        let second = if cancel {
            rings[b].iter().rev().copied().collect()
        } else {
            rings[b].clone()
        };
        let Some(joined) = splice(&rings[a], &second) else {
            continue;
        };
        rings[a] = joined;
        if cancel {
            fresh_hole[a] = false;
            fresh_hole[b] = false;
        } else {
            rings.remove(b);
            fresh_hole.remove(b);
        }
        made += 1;
    }
    (shuffled(rings, rng), made)
}

/// What [`splice_cases`] saw.
#[derive(Default)]
struct Tally {
    cases: usize,
    splices: usize,
    most: usize,
    failures: Vec<String>,
}

impl Tally {
    /// Asserts there were no failures, and enough cases spliced enough times that the
    /// property is not vacuous.
    fn assert_passed(&self) {
        let (cases, splices, most) = (self.cases, self.splices, self.most);
        assert!(
            cases >= 200 && most >= 3,
            "{cases} cases, {splices} splices, at most {most}"
        );
        assert_no_failures(&self.failures);
    }
}

/// 300 seeded `touching-holes` cases, spliced by [`pinched`] (up to `most_splices` times,
/// `cancel` as there), through both strategies, strict and lenient: the oracle must call
/// every input valid and accept every result.
fn splice_cases(mix: u64, most_splices: usize, cancel: bool) -> Tally {
    let mut t = Tally::default();
    for seed in 0..300u64 {
        let case = generate(
            Family::TouchingHoles,
            seed,
            &Params::new(40 + 10 * (seed as usize % 12)),
        );
        let mut rng = Rng(seed ^ mix);
        let splices_wanted = 1 + rng.below(most_splices);
        let (rings, made) = pinched(&case.input.rings(), &mut rng, splices_wanted, cancel);
        if made == 0 {
            continue;
        }
        t.cases += 1;
        t.splices += made;
        t.most = t.most.max(made);
        let input = Input::from_rings(&rings, Nesting::Auto);
        let judged = check_with(&input, &[], &CheckOptions::fast());
        if !judged.input_valid {
            let why = judged.failures();
            t.failures
                .push(format!("{}: input invalid: {why:?}", case.name));
            continue;
        }
        for strategy in [Strategy::Fast, Strategy::Quality] {
            for lenient in [false, true] {
                let what = format!(
                    "{}, {made} splices, {strategy:?}, lenient {lenient}",
                    case.name
                );
                match run(&input, strategy, lenient) {
                    Ok(tris) => {
                        let verdict = check_with(&input, &tris, &CheckOptions::fast());
                        if !verdict.valid {
                            t.failures.push(format!("{what}: {:?}", verdict.failures()));
                        }
                    }
                    Err(e) => t.failures.push(format!("{what}: refused: {e}")),
                }
            }
        }
    }
    t
}

#[test]
fn rings_spliced_where_they_touch_triangulate_validly() {
    splice_cases(0x5EED, 6, false).assert_passed();
}

#[test]
fn an_outer_ring_winding_twice_round_a_hole_that_cancels_a_turn_triangulates_validly() {
    splice_cases(0xCA9CE1, 4, true).assert_passed();
}
