//! Where `f32` and `f64` triangulations stay valid: the engine of `polytri precision`.
//!
//! A [`Plan`] is a grid of cases — every generator [`Family`], plus two feature-size
//! families ([`Source::Gap`], [`Source::Spike`]), at every coordinate scale and offset (and
//! feature size) — and [`run`] triangulates each case with every [`Config`]: polytri's two
//! strategies, earcut and i_triangle, each in `f32` and `f64`. Every mesh is judged twice in
//! exact arithmetic ([`check_with`]):
//!
//! - **seen**: on the coordinates as the precision sees them ([`Input::to_f32`] for `f32`).
//!   Did the algorithm do its job? polytri promises yes whenever that input is valid.
//! - **user**: on the coordinates the user gave. Is the mesh valid where it will be used?
//!
//! Whether `f32` rounding already broke the input (made it non-simple) is recorded per case
//! and counted apart ([`Tally::broken`]): that is not the triangulator's fault.
//!
//! Results do not depend on the number of threads: cases are numbered up front and each
//! case's runs are deterministic.
//!
//! ```
//! use polytri_oracle::precision::{run, Plan};
//! use polytri_oracle::Family;
//! let mut plan = Plan::quick(1);
//! plan.sources.truncate(1); // star only
//! plan.scales = vec![1.0];
//! plan.offsets = vec![0.0, 1e6];
//! let results = run(&plan, 1, &|_, _| {});
//! assert_eq!(results.cases.len(), 2);
//! assert!(results.broken_promises().is_empty());
//! ```
//!
//! [`Family`]: crate::Family

use std::cmp::{Ordering, Reverse};
use std::collections::BTreeMap;
use std::fmt;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicUsize, Ordering as AtomicOrdering};
use std::sync::Mutex;

use crate::check::region::Region;
use crate::check::{check_with, CheckOptions};
use crate::exact::orient;
use crate::gen::{generate, Case, Family, Params};
use crate::input::Input;
use crate::peers::{self, Peer};

mod feature;
mod stats;

pub use stats::{quantile, rate, Limit, Tally};

/// Where a case's polygon comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Source {
    /// A generator family ([`generate`]): integer grid, scaled by a power of two.
    Generator(Family),
    /// A 16-gon with a 16-gon hole whose corners come within `d` (the feature size,
    /// relative to the polygon) of the outer edges.
    Gap,
    /// A square with a spike of base width `d`, its sides near-collinear chains.
    Spike,
}

impl Source {
    /// Every generator family in declaration order, then the feature-size families.
    pub fn all() -> Vec<Source> {
        Family::ALL
            .into_iter()
            .map(Source::Generator)
            .chain([Source::Gap, Source::Spike])
            .collect()
    }

    /// The kebab-case name.
    pub fn name(self) -> &'static str {
        match self {
            Source::Generator(family) => family.name(),
            Source::Gap => "gap",
            Source::Spike => "spike",
        }
    }

    /// One sentence on the polygons.
    pub fn describe(self) -> &'static str {
        match self {
            Source::Generator(family) => family.describe(),
            Source::Gap => "a 16-gon hole whose corners come within d of the outer 16-gon",
            Source::Spike => "a square with a spike of base width d (sliver triangles)",
        }
    }

    /// Whether the source has a feature size (and so runs over [`Plan::features`]).
    pub fn has_feature(self) -> bool {
        matches!(self, Source::Gap | Source::Spike)
    }
}

impl PartialOrd for Source {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// Report order: the generator families as [`Family::ALL`] lists them, then gap, spike.
impl Ord for Source {
    fn cmp(&self, other: &Self) -> Ordering {
        let rank = |s: &Source| match s {
            Source::Generator(f) => Family::ALL.iter().position(|g| g == f).unwrap_or(0),
            Source::Gap => Family::ALL.len(),
            Source::Spike => Family::ALL.len() + 1,
        };
        rank(self).cmp(&rank(other))
    }
}

impl fmt::Display for Source {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The coordinate type a triangulator computes in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Precision {
    /// Coordinates rounded to `f32` first, as a GPU pipeline would.
    F32,
    /// The coordinates as given.
    F64,
}

impl Precision {
    /// Both, `f32` first.
    pub const ALL: [Precision; 2] = [Precision::F32, Precision::F64];

    /// `"f32"` or `"f64"`.
    pub fn name(self) -> &'static str {
        match self {
            Precision::F32 => "f32",
            Precision::F64 => "f64",
        }
    }
}

/// What triangulates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Subject {
    /// polytri, fast strategy, strict.
    PolytriFast,
    /// polytri, quality strategy, strict.
    PolytriQuality,
    /// earcut (the georust port of mapbox/earcut), floating-point predicates.
    Earcut,
    /// i_triangle, on its own integer grid.
    ITriangle,
}

impl Subject {
    /// Every subject, polytri first.
    pub const ALL: [Subject; 4] = [
        Subject::PolytriFast,
        Subject::PolytriQuality,
        Subject::Earcut,
        Subject::ITriangle,
    ];

    /// The kebab-case name.
    pub fn name(self) -> &'static str {
        match self {
            Subject::PolytriFast => "polytri-fast",
            Subject::PolytriQuality => "polytri-quality",
            Subject::Earcut => "earcut",
            Subject::ITriangle => "i-triangle",
        }
    }

    /// Whether this is polytri (whose promise the report checks).
    pub fn is_polytri(self) -> bool {
        matches!(self, Subject::PolytriFast | Subject::PolytriQuality)
    }
}

/// A subject in a precision: one line in the charts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Config {
    /// What triangulates.
    pub subject: Subject,
    /// In which coordinate type.
    pub precision: Precision,
}

impl Config {
    /// Every subject in both precisions, subject by subject, `f32` first.
    pub fn all() -> Vec<Config> {
        Subject::ALL
            .into_iter()
            .flat_map(|subject| Precision::ALL.map(|precision| Config { subject, precision }))
            .collect()
    }
}

impl fmt::Display for Config {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.subject.name(), self.precision.name())
    }
}

/// One point of the grid: which polygon, how large and where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CaseSpec {
    /// Where the polygon comes from.
    pub source: Source,
    /// The generator's seed.
    pub seed: u64,
    /// The requested side of the polygon's square (rounded to a power of two).
    pub scale: f64,
    /// Added to both coordinates.
    pub offset: f64,
    /// The feature size relative to the polygon, for [`Source::has_feature`] sources.
    pub feature: Option<f64>,
}

impl CaseSpec {
    /// A case of a generator family.
    pub fn generated(family: Family, seed: u64, scale: f64, offset: f64) -> Self {
        CaseSpec {
            source: Source::Generator(family),
            seed,
            scale,
            offset,
            feature: None,
        }
    }

    /// The scale actually used: the power of two nearest to [`scale`](Self::scale).
    pub fn effective_scale(&self) -> f64 {
        Params::new(3).with_scale(self.scale).effective_scale()
    }

    /// `offset / effective scale`: how far from the origin, in polygon sizes.
    pub fn offset_ratio(&self) -> f64 {
        self.offset.abs() / self.effective_scale()
    }

    /// The largest coordinate magnitude (offset or size) over the feature's length
    /// (`size · d`, or the size for generator families): how many feature lengths the
    /// coordinates' rounding error is measured against.
    pub fn feature_ratio(&self) -> f64 {
        let size = self.effective_scale();
        self.offset.abs().max(size) / (size * self.feature.unwrap_or(1.0))
    }

    /// A name saying what the case is: source, feature size, seed, scale and offset.
    pub fn name(&self) -> String {
        let feature = self
            .feature
            .map(|d| format!("-d{}", short(d)))
            .unwrap_or_default();
        format!(
            "{}{feature}-seed{}-scale{}-offset{}",
            self.source,
            self.seed,
            short(self.scale),
            short(self.offset)
        )
    }

    /// The case itself, with about `vertices` vertices (generator families).
    pub fn case(&self, vertices: usize) -> Case {
        let scale = self.effective_scale();
        let (input, description) = match self.source {
            Source::Generator(family) => {
                let params = Params::new(vertices)
                    .with_scale(self.scale)
                    .with_offset([self.offset; 2]);
                let case = generate(family, self.seed, &params);
                (case.input, case.description)
            }
            Source::Gap | Source::Spike => {
                let d = self.feature.unwrap_or(1e-3);
                let unit = match self.source {
                    Source::Gap => feature::gap(self.seed, d),
                    _ => feature::spike(self.seed, d),
                };
                let rings = feature::place(unit, scale, self.offset);
                let input = Input::from_rings(&rings, crate::input::Nesting::Auto);
                (input, format!("{}, d = {d:e}", self.source.describe()))
            }
        };
        Case {
            name: self.name(),
            family: match self.source {
                Source::Generator(family) => Some(family),
                _ => None,
            },
            seed: Some(self.seed),
            description,
            source: "polytri precision".to_owned(),
            input,
            expect: None,
        }
    }
}

/// `1e3`, `1e-5`, `0`, `1.5e2`: a short form of a grid value.
fn short(x: f64) -> String {
    if x == 0.0 {
        "0".to_owned()
    } else {
        format!("{x:e}")
    }
}

/// The decade of a positive ratio: `round(log10 x)`.
pub fn decade(x: f64) -> i32 {
    if x > 0.0 {
        x.log10().round() as i32
    } else {
        i32::MIN
    }
}

/// The grid of cases to run.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    /// The sources, in report order.
    pub sources: Vec<Source>,
    /// Coordinate scales (sides of the polygon's square).
    pub scales: Vec<f64>,
    /// Offsets added to both coordinates.
    pub offsets: Vec<f64>,
    /// Feature sizes relative to the polygon, for the feature-size sources.
    pub features: Vec<f64>,
    /// Seeds; every combination runs once per seed.
    pub seeds: Vec<u64>,
    /// About how many vertices a generator family's case has.
    pub vertices: usize,
}

impl Plan {
    /// The grid `--quick` runs: every source, scales 10⁻³, 1, 10³ and 10⁹, every offset,
    /// five feature sizes, one seed, about 60 vertices. A few seconds in release.
    pub fn quick(seed: u64) -> Plan {
        Plan {
            sources: Source::all(),
            scales: vec![1e-3, 1.0, 1e3, 1e9],
            offsets: Plan::offsets(),
            features: vec![1e-1, 1e-3, 1e-5, 1e-7, 1e-9],
            seeds: vec![seed],
            vertices: 60,
        }
    }

    /// The full grid: scales 10⁻³ … 10⁹ in decades, offsets 0 and 10³ … 10⁸, feature sizes
    /// 10⁻¹ … 10⁻⁹, three seeds, about 150 vertices.
    pub fn full(seed: u64) -> Plan {
        Plan {
            sources: Source::all(),
            scales: (-3..=9).map(|e| 10f64.powi(e)).collect(),
            offsets: Plan::offsets(),
            features: (1..=9).map(|e| 10f64.powi(-e)).collect(),
            seeds: (0..3).map(|k| seed.wrapping_add(k)).collect(),
            vertices: 150,
        }
    }

    /// 0, then 10³ … 10⁸.
    fn offsets() -> Vec<f64> {
        std::iter::once(0.0)
            .chain((3..=8).map(|e| 10f64.powi(e)))
            .collect()
    }

    /// Every case of the grid, in a fixed order.
    pub fn cases(&self) -> Vec<CaseSpec> {
        let mut cases = Vec::new();
        for &source in &self.sources {
            let features: Vec<Option<f64>> = if source.has_feature() {
                self.features.iter().copied().map(Some).collect()
            } else {
                vec![None]
            };
            for &seed in &self.seeds {
                for &scale in &self.scales {
                    for &offset in &self.offsets {
                        for &feature in &features {
                            cases.push(CaseSpec {
                                source,
                                seed,
                                scale,
                                offset,
                                feature,
                            });
                        }
                    }
                }
            }
        }
        cases
    }
}

/// One configuration's run on one case, judged twice.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// Who triangulated, in which precision.
    pub config: Config,
    /// Why there is no mesh: polytri's error, a peer's failure, or a peer that moved or
    /// added vertices (its mesh is then not over the input's points).
    pub refused: Option<String>,
    /// The mesh is valid in the coordinates the precision sees.
    pub seen_valid: bool,
    /// The mesh is valid in the coordinates the user gave.
    pub user_valid: bool,
    /// The first failed check in the seen coordinates.
    pub seen_failure: Option<String>,
    /// The first failed check in the user's coordinates.
    pub user_failure: Option<String>,
    /// The number of triangles.
    pub triangles: usize,
    /// earcut's deviation, in the user's coordinates.
    pub deviation: f64,
    /// The smallest angle in degrees, in the user's coordinates.
    pub min_angle_deg: f64,
    /// Triangles clockwise or degenerate in the user's coordinates.
    pub flipped: usize,
}

/// One case and every configuration's run on it.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseResult {
    /// The grid point.
    pub spec: CaseSpec,
    /// The case's name.
    pub name: String,
    /// Its number of vertices.
    pub vertices: usize,
    /// The input is valid as given (in `f64`); when not, nothing ran.
    pub input_valid: bool,
    /// What is wrong with the input as given.
    pub input_problem: Option<String>,
    /// The input is still valid after rounding to `f32`.
    pub f32_input_valid: bool,
    /// What rounding to `f32` broke.
    pub f32_problem: Option<String>,
    /// One run per configuration, in [`Config::all`] order.
    pub runs: Vec<Run>,
}

impl CaseResult {
    /// Whether the input is valid as `precision` sees it.
    pub fn seen_input_valid(&self, precision: Precision) -> bool {
        match precision {
            Precision::F32 => self.f32_input_valid,
            Precision::F64 => self.input_valid,
        }
    }

    /// Whether `run` breaks polytri's promise: a polytri run on an input valid as its
    /// precision sees it, whose mesh is not valid there (a refusal counts).
    pub fn breaks_promise(&self, run: &Run) -> bool {
        run.config.subject.is_polytri()
            && self.input_valid
            && self.seen_input_valid(run.config.precision)
            && !run.seen_valid
    }
}

/// Everything a [`run`] found.
#[derive(Clone, Debug, PartialEq)]
pub struct Results {
    /// The plan that ran.
    pub plan: Plan,
    /// One result per case, in [`Plan::cases`] order.
    pub cases: Vec<CaseResult>,
}

/// A reference to one run: `(case index, run index)` into [`Results::cases`].
pub type RunRef = (usize, usize);

impl Results {
    /// Tallies every run for which `key` gives a group.
    pub fn tally<K: Ord>(
        &self,
        mut key: impl FnMut(&CaseResult, &Run) -> Option<K>,
    ) -> BTreeMap<K, Tally> {
        let mut groups: BTreeMap<K, Tally> = BTreeMap::new();
        for case in &self.cases {
            for run in &case.runs {
                if let Some(k) = key(case, run) {
                    groups.entry(k).or_default().add(case, run);
                }
            }
        }
        groups
    }

    /// How far `config` stays valid in the user's coordinates on `source`, along the
    /// decades of [`CaseSpec::feature_ratio`].
    pub fn limit(&self, source: Source, config: Config) -> Limit {
        let by_decade = self.tally(|case, run| {
            (case.spec.source == source && run.config == config)
                .then(|| decade(case.spec.feature_ratio()))
        });
        Limit::from_decades(
            by_decade
                .iter()
                .filter(|(_, t)| t.runs > 0)
                .map(|(&d, t)| (d, t.valid_user == t.runs)),
        )
    }

    /// The first decade of [`CaseSpec::feature_ratio`] at which rounding to `f32` broke an
    /// input of `source`, if any did.
    pub fn first_broken(&self, source: Source) -> Option<i32> {
        self.cases
            .iter()
            .filter(|c| c.spec.source == source && c.input_valid && !c.f32_input_valid)
            .map(|c| decade(c.spec.feature_ratio()))
            .min()
    }

    /// Every run that breaks polytri's promise ([`CaseResult::breaks_promise`]).
    pub fn broken_promises(&self) -> Vec<RunRef> {
        let mut found = Vec::new();
        for (c, case) in self.cases.iter().enumerate() {
            for (r, run) in case.runs.iter().enumerate() {
                if case.breaks_promise(run) {
                    found.push((c, r));
                }
            }
        }
        found
    }

    /// The run at `at`.
    pub fn run_at(&self, at: RunRef) -> (&CaseResult, &Run) {
        let case = &self.cases[at.0];
        (case, &case.runs[at.1])
    }

    /// Up to `count` meshes worth a picture: the worst run of each configuration that
    /// made a mesh invalid in the user's coordinates — broken promises first, then meshes
    /// over inputs rounding left valid, then by flipped triangles and deviation.
    pub fn worst(&self, count: usize) -> Vec<RunRef> {
        let score = |at: RunRef| {
            let (case, run) = self.run_at(at);
            (
                case.breaks_promise(run),
                case.seen_input_valid(run.config.precision),
                run.flipped,
                OrdF64(run.deviation),
                Reverse(at),
            )
        };
        let mut best: BTreeMap<Config, RunRef> = BTreeMap::new();
        for (c, case) in self.cases.iter().enumerate() {
            if !case.input_valid {
                continue;
            }
            for (r, run) in case.runs.iter().enumerate() {
                if run.user_valid || run.refused.is_some() {
                    continue;
                }
                let slot = best.entry(run.config).or_insert((c, r));
                if score((c, r)) > score(*slot) {
                    *slot = (c, r);
                }
            }
        }
        let mut picked: Vec<RunRef> = best.into_values().collect();
        picked.sort_by_key(|&at| Reverse(score(at)));
        // Keep the picture set varied: one per subject first, then the rest.
        let mut varied = Vec::new();
        let mut seen_subjects = Vec::new();
        for &at in &picked {
            let subject = self.run_at(at).1.config.subject;
            if !seen_subjects.contains(&subject) {
                seen_subjects.push(subject);
                varied.push(at);
            }
        }
        let rest: Vec<RunRef> = picked
            .into_iter()
            .filter(|at| !varied.contains(at))
            .collect();
        varied.extend(rest);
        varied.truncate(count);
        varied
    }
}

/// An `f64` ordered by `total_cmp`, for sort keys.
#[derive(Clone, Copy, Debug, PartialEq)]
struct OrdF64(f64);

impl Eq for OrdF64 {}

impl PartialOrd for OrdF64 {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for OrdF64 {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.total_cmp(&other.0)
    }
}

/// One worker's reusable triangulators.
#[derive(Default)]
struct Worker {
    f32: polytri::Triangulator<f32>,
    f64: polytri::Triangulator<f64>,
    out: Vec<[u32; 3]>,
}

impl Worker {
    /// Triangulates `input` (given in `f64`) with `config`: rounded to `f32` first for
    /// [`Precision::F32`]. Triangles index `input`'s vertices.
    fn triangulate(&mut self, config: Config, input: &Input) -> Result<Vec<[u32; 3]>, String> {
        let strategy = match config.subject {
            Subject::PolytriFast => polytri::Strategy::Fast,
            Subject::PolytriQuality => polytri::Strategy::Quality,
            Subject::Earcut | Subject::ITriangle => return peer(config, input),
        };
        let options = polytri::Options::new()
            .with_strategy(strategy)
            .with_nesting(input.nesting.to_polytri().unwrap_or_default());
        let outcome = catch_unwind(AssertUnwindSafe(|| match config.precision {
            Precision::F32 => self
                .f32
                .triangulate(
                    &input.vertices_f32(),
                    &input.ring_starts,
                    &options,
                    &mut self.out,
                )
                .map(|_| ()),
            Precision::F64 => self
                .f64
                .triangulate(&input.vertices, &input.ring_starts, &options, &mut self.out)
                .map(|_| ()),
        }));
        match outcome {
            Ok(Ok(())) => Ok(self.out.clone()),
            Ok(Err(error)) => Err(format!("polytri refused: {error}")),
            Err(_) => {
                // A panic is a bug; start the next run from fresh state.
                *self = Worker::default();
                Err("polytri panicked".to_owned())
            }
        }
    }
}

/// A peer's mesh over `input`'s vertices, or why there is none.
fn peer(config: Config, input: &Input) -> Result<Vec<[u32; 3]>, String> {
    let which = match config.subject {
        Subject::Earcut => Peer::Earcut,
        _ => Peer::ITriangle,
    };
    let out = match config.precision {
        Precision::F32 => peers::triangulate_f32(which, input),
        Precision::F64 => peers::triangulate(which, input),
    }?;
    match out.vertices {
        None => Ok(out.triangles),
        Some(_) => Err(format!("{which} moved or added vertices")),
    }
}

/// The first problem of `input` by the oracle's exact test, if it has one.
fn input_problem(input: &Input) -> Option<String> {
    let region = Region::build(input);
    if region.problems.is_empty() && region.problem_count == 0 {
        None
    } else {
        Some(
            region
                .problems
                .first()
                .cloned()
                .unwrap_or_else(|| "invalid".to_owned()),
        )
    }
}

/// Judges `triangles` on the seen and the user's coordinates.
fn judge(config: Config, user: &Input, seen: &Input, triangles: &[[u32; 3]]) -> Run {
    let opts = CheckOptions::fast();
    let seen_verdict = check_with(seen, triangles, &opts);
    let user_verdict = match config.precision {
        Precision::F64 => seen_verdict.clone(),
        Precision::F32 => check_with(user, triangles, &opts),
    };
    Run {
        config,
        refused: None,
        seen_valid: seen_verdict.valid,
        user_valid: user_verdict.valid,
        seen_failure: seen_verdict.failures().into_iter().next(),
        user_failure: user_verdict.failures().into_iter().next(),
        triangles: triangles.len(),
        deviation: user_verdict.deviation,
        min_angle_deg: user_verdict.min_angle_deg,
        flipped: flipped(&user.vertices, triangles).len(),
    }
}

/// The triangles of `triangles` that are clockwise or degenerate over `points` (indices
/// into `triangles`; out-of-range ones are skipped).
pub fn flipped(points: &[[f64; 2]], triangles: &[[u32; 3]]) -> Vec<usize> {
    triangles
        .iter()
        .enumerate()
        .filter(|(_, t)| {
            let p = t.map(|v| points.get(v as usize).copied());
            match p {
                [Some(a), Some(b), Some(c)] => orient(a, b, c) != Ordering::Greater,
                _ => false,
            }
        })
        .map(|(k, _)| k)
        .collect()
}

/// Builds, checks and triangulates one case with every configuration.
fn run_case(spec: CaseSpec, vertices: usize, worker: &mut Worker) -> CaseResult {
    let case = spec.case(vertices);
    let user = &case.input;
    let rounded = user.to_f32();
    let problem = input_problem(user);
    // An input invalid as given stays invalid as far as this report is concerned.
    let f32_problem = problem.clone().or_else(|| input_problem(&rounded));
    let mut result = CaseResult {
        spec,
        name: case.name.clone(),
        vertices: user.vertices.len(),
        input_valid: problem.is_none(),
        input_problem: problem,
        f32_input_valid: f32_problem.is_none(),
        f32_problem,
        runs: Vec::new(),
    };
    if !result.input_valid {
        return result;
    }
    for config in Config::all() {
        let seen = match config.precision {
            Precision::F32 => &rounded,
            Precision::F64 => user,
        };
        let run = match worker.triangulate(config, user) {
            Ok(triangles) => judge(config, user, seen, &triangles),
            Err(why) => Run {
                config,
                refused: Some(why.clone()),
                seen_valid: false,
                user_valid: false,
                seen_failure: Some(why.clone()),
                user_failure: Some(why),
                triangles: 0,
                deviation: 1.0,
                min_angle_deg: 0.0,
                flipped: 0,
            },
        };
        result.runs.push(run);
    }
    result
}

/// Runs every case of `plan` on up to `threads` threads (at least one), calling
/// `progress(done, total)` after each case (from any thread).
pub fn run(plan: &Plan, threads: usize, progress: &(dyn Fn(usize, usize) + Sync)) -> Results {
    let specs = plan.cases();
    let total = specs.len();
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let slots: Mutex<Vec<Option<CaseResult>>> = Mutex::new(vec![None; total]);
    std::thread::scope(|scope| {
        for _ in 0..threads.max(1) {
            scope.spawn(|| {
                let mut worker = Worker::default();
                loop {
                    let k = next.fetch_add(1, AtomicOrdering::Relaxed);
                    let Some(&spec) = specs.get(k) else { break };
                    let result = run_case(spec, plan.vertices, &mut worker);
                    if let Ok(mut slots) = slots.lock() {
                        slots[k] = Some(result);
                    }
                    progress(done.fetch_add(1, AtomicOrdering::Relaxed) + 1, total);
                }
            });
        }
    });
    let cases = slots
        .into_inner()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
        .into_iter()
        .zip(specs)
        .map(|(slot, spec)| {
            slot.unwrap_or_else(|| run_case(spec, plan.vertices, &mut Worker::default()))
        })
        .collect();
    Results {
        plan: plan.clone(),
        cases,
    }
}

/// What makes an input valid only in the weak sense the oracle accepts: coincident
/// points, vertices lying on other edges, collinear edges overlapping along a segment —
/// typically a tooth or sliver that rounding collapsed to zero width.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Degeneracy {
    /// Pairs of vertices at the same position.
    pub coincident: usize,
    /// (vertex, edge) pairs where the vertex lies inside the edge.
    pub on_edges: usize,
    /// Pairs of edges overlapping along a segment.
    pub overlapping: usize,
}

impl Degeneracy {
    /// Whether there is none of the three.
    pub fn is_none(&self) -> bool {
        *self == Degeneracy::default()
    }
}

impl fmt::Display for Degeneracy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} pairs of coincident vertices, {} vertices inside other edges, {} pairs of overlapping collinear edges",
            self.coincident, self.on_edges, self.overlapping
        )
    }
}

/// Counts `input`'s degeneracies, exactly (quadratic: for small inputs).
pub fn degeneracy(input: &Input) -> Degeneracy {
    let pts = &input.vertices;
    let mut edges = Vec::new();
    for r in 0..input.ring_count() {
        let range = input.ring_range(r);
        for v in range.clone() {
            let w = if v + 1 == range.end {
                range.start
            } else {
                v + 1
            };
            if pts[v] != pts[w] {
                edges.push((pts[v], pts[w]));
            }
        }
    }
    let inside = |a: [f64; 2], b: [f64; 2], p: [f64; 2]| {
        p != a
            && p != b
            && orient(a, b, p) == Ordering::Equal
            && a[0].min(b[0]) <= p[0]
            && p[0] <= a[0].max(b[0])
            && a[1].min(b[1]) <= p[1]
            && p[1] <= a[1].max(b[1])
    };
    let mut d = Degeneracy::default();
    for (i, &p) in pts.iter().enumerate() {
        d.coincident += pts[i + 1..].iter().filter(|&&q| q == p).count();
        d.on_edges += edges.iter().filter(|&&(a, b)| inside(a, b, p)).count();
    }
    for (i, &(a, b)) in edges.iter().enumerate() {
        d.overlapping += edges[i + 1..]
            .iter()
            .filter(|&&(c, e)| {
                orient(a, b, c) == Ordering::Equal
                    && orient(a, b, e) == Ordering::Equal
                    && (inside(a, b, c)
                        || inside(a, b, e)
                        || inside(c, e, a)
                        || inside(c, e, b)
                        || (a == c && b == e)
                        || (a == e && b == c))
            })
            .count();
    }
    d
}

/// A broken promise ([`CaseResult::breaks_promise`]) made small: the input as the
/// precision saw it, shrunk (staying valid) while `config` still gives no valid mesh in
/// those coordinates. Its coordinates are exact in the precision, so it fails the same way
/// when replayed in either.
pub fn shrink_failure(results: &Results, at: RunRef) -> Case {
    let (case, run) = results.run_at(at);
    let config = run.config;
    let replayed = replay(&case.spec, results.plan.vertices, config);
    let mut seen_case = replayed.case;
    seen_case.input = replayed.seen;
    let refused = run.refused.is_some();
    let mut worker = Worker::default();
    // Keep the kind of failure: a refusal shrinks to a refusal, a bad mesh to a bad mesh.
    let mut small =
        crate::shrink::shrink(&seen_case, |c| match worker.triangulate(config, &c.input) {
            Ok(triangles) => {
                !refused && !check_with(&c.input, &triangles, &CheckOptions::fast()).valid
            }
            Err(_) => refused,
        });
    small.name = format!(
        "{}-{}-{}",
        config.subject.name(),
        config.precision.name(),
        case.name
    );
    small
}

/// One run again, with everything needed to draw it.
#[derive(Clone, Debug)]
pub struct Replay {
    /// The case, in the user's coordinates.
    pub case: Case,
    /// The input as the precision sees it.
    pub seen: Input,
    /// The mesh (indices into both inputs' vertices), or why there is none.
    pub triangles: Result<Vec<[u32; 3]>, String>,
}

/// Runs `config` on `spec` again (deterministic: the same mesh as in [`run`]).
pub fn replay(spec: &CaseSpec, vertices: usize, config: Config) -> Replay {
    let case = spec.case(vertices);
    let seen = match config.precision {
        Precision::F32 => case.input.to_f32(),
        Precision::F64 => case.input.clone(),
    };
    let triangles = Worker::default().triangulate(config, &case.input);
    Replay {
        case,
        seen,
        triangles,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tiny_plan() -> Plan {
        Plan {
            sources: vec![Source::Generator(Family::Circles), Source::Gap],
            scales: vec![1.0],
            offsets: vec![0.0, 1e8],
            features: vec![1e-2, 1e-9],
            seeds: vec![5],
            vertices: 40,
        }
    }

    #[test]
    fn plan_enumerates_features_only_where_they_exist() {
        let cases = tiny_plan().cases();
        assert_eq!(cases.len(), 2 + 2 * 2);
        assert!(cases[..2].iter().all(|c| c.feature.is_none()));
        assert!(cases[2..].iter().all(|c| c.feature.is_some()));
        assert_eq!(Plan::full(1).cases().len() % Plan::full(1).seeds.len(), 0);
    }

    #[test]
    fn results_do_not_depend_on_threads() {
        let plan = tiny_plan();
        let one = run(&plan, 1, &|_, _| {});
        let two = run(&plan, 2, &|_, _| {});
        assert_eq!(one, two);
        assert!(one.broken_promises().is_empty());
        // At offset 1e8, f32's spacing is 8: the unit-sized gap polygon collapses, and no
        // f32 mesh covers it where the user has it.
        let last = one.cases.last().expect("cases");
        eprintln!("{last:#?}");
        assert!(last
            .runs
            .iter()
            .all(|r| r.config.precision == Precision::F64 || !r.user_valid));
        // polytri in f64 is valid everywhere the input is.
        for case in one.cases.iter().filter(|c| c.input_valid) {
            for r in case
                .runs
                .iter()
                .filter(|r| r.config.subject.is_polytri() && r.config.precision == Precision::F64)
            {
                assert!(r.user_valid, "{}: {:?}", case.name, r.user_failure);
            }
        }
    }

    #[test]
    fn ratios_use_the_effective_scale() {
        let spec = CaseSpec::generated(Family::Star, 1, 1e3, 1e6);
        assert_eq!(spec.effective_scale(), 1024.0);
        assert_eq!(decade(spec.offset_ratio()), 3);
        assert_eq!(decade(spec.feature_ratio()), 3);
        let spec = CaseSpec {
            feature: Some(1e-4),
            offset: 0.0,
            ..spec
        };
        assert_eq!(decade(spec.feature_ratio()), 4);
        assert!(spec.name().contains("-d1e-4-"), "{}", spec.name());
    }

    #[test]
    fn flipped_finds_clockwise_and_degenerate_triangles() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [2.0, 0.0]];
        assert_eq!(
            flipped(&pts, &[[0, 1, 2], [0, 2, 1], [0, 1, 3], [0, 1, 9]]),
            vec![1, 2]
        );
    }
}
