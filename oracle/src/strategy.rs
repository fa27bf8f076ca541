//! proptest strategies over the generators, shrinking to smaller valid inputs.
//!
//! A generated [`Case`] shrinks by dropping whole rings (holes, islands, outer rings) first,
//! then single vertices, keeping only candidates that [`validate`] accepts exactly: a
//! failing property is reported on a small input that is still valid, never on one the
//! triangulator may rightly refuse.
//!
//! ```
//! use polytri_oracle::gen::Family;
//! use polytri_oracle::strategy::family_case;
//! use proptest::prelude::*;
//!
//! proptest!(ProptestConfig::with_cases(4), |(case in family_case(Family::Comb, 60))| {
//!     prop_assert!(case.input.vertices.len() >= 3);
//! });
//! ```

use proptest::prelude::Rng as _;
use proptest::strategy::{NewTree, Strategy, ValueTree};
use proptest::test_runner::TestRunner;

use crate::gen::{generate, validate, Case, Family, Params};

/// Cases of every family, up to 300 vertices.
pub fn any_case() -> CaseStrategy {
    CaseStrategy {
        families: Family::ALL.to_vec(),
        max_vertices: 300,
    }
}

/// Cases of `family` with 3 to `max_vertices` vertices (sizes spread evenly on a log
/// scale, so small cases are common).
pub fn family_case(family: Family, max_vertices: usize) -> CaseStrategy {
    CaseStrategy {
        families: vec![family],
        max_vertices,
    }
}

/// The strategy behind [`any_case`] and [`family_case`]: a random family among
/// `families`, a random seed and size, and [`generate`].
#[derive(Clone, Debug)]
pub struct CaseStrategy {
    families: Vec<Family>,
    max_vertices: usize,
}

impl CaseStrategy {
    /// Cases of any of `families` (all of them when empty), up to `max_vertices`.
    pub fn new(families: &[Family], max_vertices: usize) -> Self {
        let families = if families.is_empty() {
            Family::ALL.to_vec()
        } else {
            families.to_vec()
        };
        CaseStrategy {
            families,
            max_vertices,
        }
    }
}

impl Strategy for CaseStrategy {
    type Tree = CaseTree;
    type Value = Case;

    fn new_tree(&self, runner: &mut TestRunner) -> NewTree<Self> {
        let rng = runner.rng();
        let family = self.families[(rng.next_u64() % self.families.len() as u64) as usize];
        let seed = rng.next_u64();
        let max = self.max_vertices.clamp(3, 100_000) as f64;
        let unit = (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        let size = (3.0 * (max / 3.0).powf(unit)).round() as usize;
        let case = generate(family, seed, &Params::new(size));
        Ok(CaseTree::new(case, family.allows_touching()))
    }
}

/// The next shrinking step to try.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Step {
    /// Drop ring `r`.
    Ring(usize),
    /// Drop vertex `v`.
    Vertex(usize),
    /// Nothing left to try.
    Done,
}

impl Step {
    /// The step after this one failed or was undone.
    fn skip(self) -> Step {
        match self {
            Step::Ring(r) => Step::Ring(r + 1),
            Step::Vertex(v) => Step::Vertex(v + 1),
            Step::Done => Step::Done,
        }
    }
}

/// A generated case and its shrinking state: `simplify` drops rings first, then
/// vertices, one at a time, keeping a candidate only when it is still valid; `complicate`
/// puts back the last thing dropped and moves past it.
#[derive(Clone, Debug)]
pub struct CaseTree {
    current: Case,
    /// Earlier cases and the step that led from each to its successor.
    undo: Vec<(Case, Step)>,
    next: Step,
    allow_touching: bool,
}

impl CaseTree {
    /// A tree over `case`, with rings allowed to touch at vertices if `allow_touching`.
    pub fn new(case: Case, allow_touching: bool) -> Self {
        CaseTree {
            current: case,
            undo: Vec::new(),
            next: Step::Ring(0),
            allow_touching,
        }
    }

    /// The candidate for `step`, if it is still valid; `Err` moves to the next phase.
    fn candidate(&self, step: Step) -> Result<Option<Case>, Step> {
        let input = &self.current.input;
        let smaller = match step {
            Step::Ring(r) if input.ring_count() > 1 && r < input.ring_count() => {
                input.without_ring(r)
            }
            Step::Ring(_) => return Err(Step::Vertex(0)),
            Step::Vertex(v) if v < input.vertices.len() => input.without_vertex(v),
            Step::Vertex(_) | Step::Done => return Err(Step::Done),
        };
        if validate(&smaller, self.allow_touching).is_err() {
            return Ok(None);
        }
        let mut case = self.current.clone();
        case.input = smaller;
        Ok(Some(case))
    }
}

impl ValueTree for CaseTree {
    type Value = Case;

    fn current(&self) -> Case {
        self.current.clone()
    }

    fn simplify(&mut self) -> bool {
        loop {
            match self.candidate(self.next) {
                Err(Step::Done) => {
                    self.next = Step::Done;
                    return false;
                }
                Err(phase) => self.next = phase,
                Ok(None) => self.next = self.next.skip(),
                Ok(Some(smaller)) => {
                    let before = std::mem::replace(&mut self.current, smaller);
                    self.undo.push((before, self.next));
                    // The same index now names the next ring or vertex: try it next.
                    return true;
                }
            }
        }
    }

    fn complicate(&mut self) -> bool {
        match self.undo.pop() {
            Some((before, step)) => {
                self.current = before;
                self.next = step.skip();
                true
            }
            None => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shrinks_to_a_valid_triangle_and_undoes() {
        let case = generate(Family::NestedIslands, 3, &Params::new(60));
        let mut tree = CaseTree::new(case.clone(), false);
        let mut steps = 0;
        while tree.simplify() {
            steps += 1;
            assert!(validate(&tree.current().input, false).is_ok());
        }
        let smallest = tree.current();
        assert_eq!(smallest.input.ring_count(), 1);
        assert_eq!(smallest.input.vertices.len(), 3);
        assert!(steps > 3);
        // Undo everything: back to the original.
        while tree.complicate() {}
        assert_eq!(tree.current(), case);
    }
}
