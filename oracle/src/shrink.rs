//! Shrinking a failing case: the smallest input found that still fails, and is still
//! valid.
//!
//! [`shrink`] drops rings, then runs of vertices, halving the run length down to single
//! vertices (delta debugging), and repeats while anything changed. A candidate is kept
//! only when it is valid in the same sense as the original — exactly valid by
//! [`validate`], without touching rings if the original had none, else the oracle's
//! broader test ([`Verdict::input_valid`](crate::Verdict::input_valid)) — and still fails.
//! So a failure is never reported on an input the triangulator may rightly refuse.
//!
//! Unlike [`strategy`](crate::strategy)'s one-at-a-time proptest shrinking, chunks make
//! cases of thousands of vertices small in a few hundred attempts, and a budget bounds the
//! number of attempts ([`shrink_within`]).
//!
//! ```
//! use polytri_oracle::gen::{generate, Family, Params};
//! use polytri_oracle::shrink::shrink;
//!
//! // "Fails" while it has at least two rings: shrinks to an outer ring and one hole.
//! let case = generate(Family::ManyHoles, 3, &Params::new(400));
//! let small = shrink(&case, |c| c.input.ring_count() >= 2);
//! assert_eq!(small.input.ring_count(), 2);
//! assert!(small.input.vertices.len() < 20);
//! ```

use crate::check::{check_with, CheckOptions};
use crate::gen::{validate, Case};
use crate::input::{Input, Nesting, Role};

/// The attempt budget of [`shrink`]: calls of `still_fails`.
pub const DEFAULT_ATTEMPTS: usize = 3000;

/// Which validity a shrunk candidate must keep: the strictest the original has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Validity {
    /// [`validate`] accepts it, with rings touching at vertices if `touching`.
    Exact { touching: bool },
    /// Only the oracle's region test accepts it (or nothing does: then nothing is kept).
    Oracle,
}

impl Validity {
    /// The strictest class `input` belongs to.
    fn of(input: &Input) -> Validity {
        if validate(input, false).is_ok() {
            Validity::Exact { touching: false }
        } else if validate(input, true).is_ok() {
            Validity::Exact { touching: true }
        } else {
            Validity::Oracle
        }
    }

    /// Whether `input` belongs to this class.
    fn accepts(self, input: &Input) -> bool {
        match self {
            Validity::Exact { touching } => validate(input, touching).is_ok(),
            Validity::Oracle => check_with(input, &[], &CheckOptions::fast()).input_valid,
        }
    }
}

/// Shrinks `case` while `still_fails` says it fails, within [`DEFAULT_ATTEMPTS`] calls.
///
/// Returns the smallest failing case found (`case` itself when nothing smaller fails);
/// only its input changes. `still_fails` is only called on valid candidates.
pub fn shrink(case: &Case, still_fails: impl FnMut(&Case) -> bool) -> Case {
    shrink_within(case, DEFAULT_ATTEMPTS, still_fails)
}

/// [`shrink`] with a budget of `max_attempts` calls of `still_fails`.
pub fn shrink_within(
    case: &Case,
    max_attempts: usize,
    still_fails: impl FnMut(&Case) -> bool,
) -> Case {
    let mut shrinker = Shrinker {
        best: case.clone(),
        rings: Rings::of(&case.input),
        validity: Validity::of(&case.input),
        attempts_left: max_attempts,
        still_fails,
    };
    loop {
        let dropped_rings = shrinker.drop_rings();
        let dropped_vertices = shrinker.drop_vertices();
        if !(dropped_rings || dropped_vertices) || shrinker.attempts_left == 0 {
            return shrinker.best;
        }
    }
}

/// The rings of an input with their roles (when the nesting lists them), so that pieces can
/// be cut out and the input rebuilt.
#[derive(Clone, Debug)]
struct Rings {
    points: Vec<Vec<[f64; 2]>>,
    roles: Option<Vec<Role>>,
    nesting: Nesting,
}

impl Rings {
    fn of(input: &Input) -> Rings {
        let roles = match &input.nesting {
            Nesting::Roles(roles) => Some(roles.clone()),
            _ => None,
        };
        Rings {
            points: input.rings(),
            roles,
            nesting: input.nesting.clone(),
        }
    }

    fn input(&self) -> Input {
        let nesting = match &self.roles {
            Some(roles) => Nesting::Roles(roles.clone()),
            None => self.nesting.clone(),
        };
        Input::from_rings(&self.points, nesting)
    }

    /// Without rings `range`.
    fn without_rings(&self, range: std::ops::Range<usize>) -> Rings {
        let mut smaller = self.clone();
        smaller.points.drain(range.clone());
        if let Some(roles) = &mut smaller.roles {
            let end = range.end.min(roles.len());
            roles.drain(range.start.min(end)..end);
        }
        smaller
    }

    /// Without vertices `range` of ring `r`.
    fn without_vertices(&self, r: usize, range: std::ops::Range<usize>) -> Rings {
        let mut smaller = self.clone();
        smaller.points[r].drain(range);
        smaller
    }
}

/// The state of one shrinking run.
struct Shrinker<F> {
    best: Case,
    rings: Rings,
    validity: Validity,
    attempts_left: usize,
    still_fails: F,
}

impl<F: FnMut(&Case) -> bool> Shrinker<F> {
    /// Keeps `candidate` if it is valid and still fails.
    fn try_keep(&mut self, candidate: Rings) -> bool {
        if self.attempts_left == 0 {
            return false;
        }
        let input = candidate.input();
        if !self.validity.accepts(&input) {
            return false;
        }
        self.attempts_left -= 1;
        let mut case = self.best.clone();
        case.input = input;
        if (self.still_fails)(&case) {
            self.best = case;
            self.rings = candidate;
            true
        } else {
            false
        }
    }

    /// Drops runs of rings, halving the run length down to one; true if any went.
    fn drop_rings(&mut self) -> bool {
        let mut changed = false;
        let mut run = self.rings.points.len() / 2;
        while run >= 1 {
            let mut start = 0;
            while start < self.rings.points.len() && self.rings.points.len() > 1 {
                let end = (start + run).min(self.rings.points.len());
                if end - start >= self.rings.points.len() {
                    break;
                }
                if self.try_keep(self.rings.without_rings(start..end)) {
                    // The same index now names the next rings: try them next.
                    changed = true;
                } else {
                    start = end;
                }
            }
            run /= 2;
        }
        changed
    }

    /// Drops runs of consecutive vertices of every ring (each keeps three), halving the
    /// run length down to one; true if any went.
    fn drop_vertices(&mut self) -> bool {
        let mut changed = false;
        for r in 0..self.rings.points.len() {
            let mut run = self.rings.points[r].len() / 2;
            while run >= 1 {
                let mut start = 0;
                while start < self.rings.points[r].len() {
                    let len = self.rings.points[r].len();
                    let end = (start + run).min(len);
                    if len - (end - start) < 3 {
                        break;
                    }
                    if self.try_keep(self.rings.without_vertices(r, start..end)) {
                        changed = true;
                    } else {
                        start = end;
                    }
                }
                run /= 2;
            }
        }
        changed
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::{generate, Family, Params};

    #[test]
    fn shrinks_to_a_triangle_when_everything_fails() {
        let case = generate(Family::NestedIslands, 5, &Params::new(300));
        let small = shrink(&case, |_| true);
        assert_eq!(small.input.ring_count(), 1);
        assert_eq!(small.input.vertices.len(), 3);
        assert_eq!(small.name, case.name);
    }

    #[test]
    fn keeps_what_the_failure_needs_and_stays_valid() {
        let case = generate(Family::Circles, 2, &Params::new(500));
        let touching = case.family.is_some_and(Family::allows_touching);
        let mut calls = 0;
        let small = shrink(&case, |c| {
            calls += 1;
            assert!(validate(&c.input, touching).is_ok());
            c.input.ring_count() >= 3 && c.input.vertices.len() >= 12
        });
        assert_eq!(small.input.ring_count(), 3);
        assert!(
            small.input.vertices.len() <= 13,
            "{}",
            small.input.vertices.len()
        );
        assert!(calls < DEFAULT_ATTEMPTS);
    }

    #[test]
    fn respects_the_budget_and_nothing_failing_changes_nothing() {
        let case = generate(Family::Star, 9, &Params::new(200));
        assert_eq!(shrink(&case, |_| false), case);
        let mut calls = 0;
        let _ = shrink_within(&case, 5, |_| {
            calls += 1;
            true
        });
        assert_eq!(calls, 5);
    }
}
