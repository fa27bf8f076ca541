//! Aggregation: validity rates, deviation quantiles and minimum angles over groups of runs.

use super::{CaseResult, Run};

/// The `q`-quantile (`0 ≤ q ≤ 1`) of `values` by linear interpolation between the nearest
/// ranks (NaN values ignored); `None` when there is nothing to rank.
///
/// ```
/// use polytri_oracle::precision::quantile;
/// assert_eq!(quantile(&[3.0, 1.0, 2.0], 0.5), Some(2.0));
/// assert_eq!(quantile(&[0.0, 10.0], 0.9), Some(9.0));
/// assert_eq!(quantile(&[], 0.5), None);
/// ```
pub fn quantile(values: &[f64], q: f64) -> Option<f64> {
    let mut sorted: Vec<f64> = values.iter().copied().filter(|v| !v.is_nan()).collect();
    if sorted.is_empty() {
        return None;
    }
    sorted.sort_by(f64::total_cmp);
    let rank = q.clamp(0.0, 1.0) * (sorted.len() - 1) as f64;
    let (lo, hi) = (rank.floor() as usize, rank.ceil() as usize);
    let t = rank - lo as f64;
    Some(if lo == hi {
        sorted[lo]
    } else {
        sorted[lo] * (1.0 - t) + sorted[hi] * t
    })
}

/// `part / whole`, or `None` for an empty whole.
pub fn rate(part: usize, whole: usize) -> Option<f64> {
    (whole > 0).then(|| part as f64 / whole as f64)
}

/// What a group of runs (one configuration on some cases) came to.
///
/// Only cases whose input is valid as the user gave it count; among them, those whose
/// input the configuration's precision broke (rounding made it non-simple) are counted
/// apart in [`broken`](Self::broken) and left out of [`seen_rate`](Self::seen_rate).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tally {
    /// Runs on inputs valid as given.
    pub runs: usize,
    /// Of those, runs whose input is invalid as the precision sees it (f32 rounding broke
    /// it; never for f64).
    pub broken: usize,
    /// Runs the triangulator refused (or the peer failed on, or that moved vertices).
    pub refused: usize,
    /// Runs on unbroken inputs whose mesh is valid in the coordinates the precision sees.
    pub valid_seen: usize,
    /// Runs whose mesh is valid in the coordinates the user gave.
    pub valid_user: usize,
    /// Runs on unbroken inputs invalid in the coordinates the precision sees.
    pub invalid_seen: usize,
    /// Every mesh's deviation (earcut's measure, in the user's coordinates).
    pub deviations: Vec<f64>,
    /// The minimum angle of every mesh valid in the user's coordinates, in degrees.
    pub min_angles: Vec<f64>,
}

impl Tally {
    /// Counts `run`, made on `case`.
    pub fn add(&mut self, case: &CaseResult, run: &Run) {
        if !case.input_valid {
            return;
        }
        self.runs += 1;
        let broken = !case.seen_input_valid(run.config.precision);
        if broken {
            self.broken += 1;
        }
        if run.refused.is_some() {
            self.refused += 1;
        } else {
            self.deviations.push(run.deviation);
        }
        if !broken {
            if run.seen_valid {
                self.valid_seen += 1;
            } else {
                self.invalid_seen += 1;
            }
        }
        if run.user_valid {
            self.valid_user += 1;
            self.min_angles.push(run.min_angle_deg);
        }
    }

    /// Merges another tally into this one.
    pub fn merge(&mut self, other: &Tally) {
        self.runs += other.runs;
        self.broken += other.broken;
        self.refused += other.refused;
        self.valid_seen += other.valid_seen;
        self.valid_user += other.valid_user;
        self.invalid_seen += other.invalid_seen;
        self.deviations.extend_from_slice(&other.deviations);
        self.min_angles.extend_from_slice(&other.min_angles);
    }

    /// The share of runs valid in the user's coordinates.
    pub fn user_rate(&self) -> Option<f64> {
        rate(self.valid_user, self.runs)
    }

    /// The share of runs not valid in the user's coordinates (refusals included).
    pub fn failure_rate(&self) -> Option<f64> {
        self.user_rate().map(|r| 1.0 - r)
    }

    /// The share of runs on unbroken inputs that are valid in the coordinates the
    /// precision sees: did the algorithm do its job?
    pub fn seen_rate(&self) -> Option<f64> {
        rate(self.valid_seen, self.runs - self.broken)
    }

    /// The share of runs on unbroken inputs that are invalid in the coordinates the
    /// precision sees.
    pub fn seen_failure_rate(&self) -> Option<f64> {
        self.seen_rate().map(|r| 1.0 - r)
    }

    /// The share of runs whose input the precision broke.
    pub fn broken_rate(&self) -> Option<f64> {
        rate(self.broken, self.runs)
    }

    /// The `q`-quantile of the deviations.
    pub fn deviation(&self, q: f64) -> Option<f64> {
        quantile(&self.deviations, q)
    }

    /// The smallest minimum angle among valid meshes, in degrees.
    pub fn min_angle(&self) -> Option<f64> {
        self.min_angles.iter().copied().reduce(f64::min)
    }

    /// The median minimum angle among valid meshes, in degrees.
    pub fn median_min_angle(&self) -> Option<f64> {
        quantile(&self.min_angles, 0.5)
    }
}

/// How far a configuration stays valid along a ratio axis (decades, ascending).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limit {
    /// The largest decade `k` such that every run at a ratio up to `10^k` was valid;
    /// `None` when the smallest decade already failed.
    pub valid_up_to: Option<i32>,
    /// The first decade with a failure; `None` when nothing failed.
    pub first_failure: Option<i32>,
    /// The largest decade measured.
    pub measured_up_to: Option<i32>,
}

impl Limit {
    /// Walks `(decade, all_valid)` pairs in ascending order of decade.
    pub fn from_decades(decades: impl IntoIterator<Item = (i32, bool)>) -> Limit {
        let mut limit = Limit {
            valid_up_to: None,
            first_failure: None,
            measured_up_to: None,
        };
        for (decade, all_valid) in decades {
            limit.measured_up_to = Some(decade);
            if limit.first_failure.is_some() {
                continue;
            }
            if all_valid {
                limit.valid_up_to = Some(decade);
            } else {
                limit.first_failure = Some(decade);
            }
        }
        limit
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::precision::{CaseSpec, Config, Precision, Source, Subject};
    use crate::Family;

    #[test]
    fn quantiles_interpolate_and_ignore_nan() {
        let v = [5.0, 1.0, f64::NAN, 3.0, 2.0, 4.0];
        assert_eq!(quantile(&v, 0.0), Some(1.0));
        assert_eq!(quantile(&v, 1.0), Some(5.0));
        assert_eq!(quantile(&v, 0.5), Some(3.0));
        assert_eq!(quantile(&v, 0.25), Some(2.0));
        assert_eq!(quantile(&v, 0.125), Some(1.5));
        assert_eq!(quantile(&[7.0], 0.99), Some(7.0));
        assert_eq!(quantile(&[f64::NAN], 0.5), None);
        assert_eq!(quantile(&[1.0, 2.0], 3.0), Some(2.0));
    }

    #[test]
    fn rates_handle_empty_groups() {
        assert_eq!(rate(1, 4), Some(0.25));
        assert_eq!(rate(0, 0), None);
        let t = Tally::default();
        assert_eq!(t.user_rate(), None);
        assert_eq!(t.seen_rate(), None);
        assert_eq!(t.deviation(0.5), None);
        assert_eq!(t.min_angle(), None);
    }

    fn run(precision: Precision, seen: bool, user: bool, refused: bool) -> Run {
        Run {
            config: Config {
                subject: Subject::PolytriFast,
                precision,
            },
            refused: refused.then(|| "refused".to_owned()),
            seen_valid: seen,
            user_valid: user,
            seen_failure: None,
            user_failure: None,
            triangles: 0,
            deviation: if user { 0.0 } else { 0.5 },
            min_angle_deg: 10.0,
            flipped: 0,
        }
    }

    fn case(input_valid: bool, f32_valid: bool) -> CaseResult {
        CaseResult {
            spec: CaseSpec::generated(Family::Star, 1, 1.0, 0.0),
            name: "star".to_owned(),
            vertices: 3,
            input_valid,
            input_problem: None,
            f32_input_valid: f32_valid,
            f32_problem: None,
            runs: Vec::new(),
        }
    }

    #[test]
    fn tally_counts_broken_inputs_apart() {
        let mut t = Tally::default();
        let good = case(true, true);
        let broken = case(true, false);
        let invalid = case(false, false);
        t.add(&good, &run(Precision::F32, true, true, false));
        t.add(&good, &run(Precision::F32, true, false, false));
        t.add(&good, &run(Precision::F32, false, false, false));
        t.add(&broken, &run(Precision::F32, false, false, true));
        t.add(&broken, &run(Precision::F64, true, true, false));
        t.add(&invalid, &run(Precision::F64, true, true, false));
        assert_eq!(t.runs, 5);
        assert_eq!(t.broken, 1);
        assert_eq!(t.refused, 1);
        assert_eq!(t.valid_seen, 3);
        assert_eq!(t.invalid_seen, 1);
        assert_eq!(t.valid_user, 2);
        assert_eq!(t.user_rate(), Some(0.4));
        assert_eq!(t.seen_rate(), Some(0.75));
        assert_eq!(t.broken_rate(), Some(0.2));
        assert_eq!(t.deviations.len(), 4);
        assert_eq!(t.deviation(1.0), Some(0.5));
        let mut merged = Tally::default();
        merged.merge(&t);
        merged.merge(&t);
        assert_eq!(merged.runs, 10);
        assert_eq!(merged.user_rate(), Some(0.4));
        let _ = Source::Gap;
    }

    #[test]
    fn limit_stops_at_the_first_failing_decade() {
        let l = Limit::from_decades([(0, true), (3, true), (4, false), (5, true)]);
        assert_eq!(l.valid_up_to, Some(3));
        assert_eq!(l.first_failure, Some(4));
        assert_eq!(l.measured_up_to, Some(5));
        let l = Limit::from_decades([(0, false)]);
        assert_eq!(l.valid_up_to, None);
        let l = Limit::from_decades([(0, true), (1, true)]);
        assert_eq!((l.valid_up_to, l.first_failure), (Some(1), None));
    }
}
