//! The campaign: random cases of every generator family, triangulated in every strategy
//! and precision, judged by the oracle; failures shrunk and written as corpus cases.
//!
//! Case `k` of a campaign with seed `S` is generated from seed `S + k` alone — its family
//! (round robin over [`Config::families`]), size and placement too — so results do not
//! depend on how many threads ran or in which order: a `--cases N` campaign is reproducible
//! to the last number (timings aside), a time-limited one runs a prefix of the same
//! sequence.
//!
//! For each case the engine runs the [`Subject`] (polytri by default, [`Polytri`]) in
//! [`Strategy::Fast`] and [`Strategy::Quality`], on the `f64` input and on the same input
//! rounded to `f32`. Every run must succeed and pass [`check_with`]; the fast `f64` run also
//! builds spade's constrained Delaunay triangulation, whose minimum angle is the quality
//! target the table compares against.
//!
//! The `f32` runs happen only where the rounded input is still valid by the generators'
//! exact test ([`validate`], rings allowed to touch at vertices, as rounding may make
//! them): rounding can collapse a ring to a segment, fold an edge back into a zero-width
//! spike or make rings cross. Such an input is no longer the polygon that was generated
//! and lies outside polytri's contract (every ring simple), though the oracle's broader
//! region test may still accept it; it is counted in [`FamilyStats::f32_invalid`], not as
//! a failure. Where rounding changes nothing (the unit square's grid is exact in `f32`)
//! and the `f32` triangles equal the `f64` ones, the `f64` verdict stands for both.
//!
//! With [`Config::peers`], every peer runs on the same `f64` input and is judged by the
//! same oracle. A peer that refuses or panics on the (valid) input fails; a peer whose
//! output has vertices of its own (lyon and i_triangle when their rounded points no
//! longer match an input vertex, or added ones) cannot be judged against the input and
//! counts as "n/a" ([`PeerStats::not_judged`]) — judging a mapped copy would judge the
//! mapping as much as the peer.
//!
//! ```
//! use polytri_oracle::campaign::{self, Budget, Config, Polytri};
//! use polytri_oracle::Family;
//!
//! let config = Config {
//!     budget: Budget::Cases(6),
//!     families: vec![Family::Star, Family::Comb],
//!     max_vertices: 50,
//!     out_dir: None,
//!     ..Config::default()
//! };
//! let report = campaign::run(&config, &Polytri, &|_| {});
//! assert_eq!(report.cases(), 6);
//! assert!(report.failures.is_empty());
//! ```

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;

pub use polytri::Strategy;

use crate::check::{check_with, CheckOptions, Verdict};
use crate::gen::{generate, validate, Case, Family, Params};
use crate::input::Input;
use crate::peers::{self, Peer};
use crate::shrink;
use crate::threaded;

/// The coordinate type of a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Precision {
    /// The input as generated.
    F64,
    /// The input rounded to `f32` ([`Input::to_f32`]), triangulated in `f32`.
    F32,
}

impl Precision {
    /// `"f64"` or `"f32"`.
    pub fn name(self) -> &'static str {
        match self {
            Precision::F64 => "f64",
            Precision::F32 => "f32",
        }
    }
}

/// One way of triangulating a case: a strategy in a precision.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Run {
    /// The ear-clipping strategy.
    pub strategy: Strategy,
    /// The coordinate type.
    pub precision: Precision,
    /// Threads: 1 runs on the caller's thread; more clip by mark-and-cut on that many,
    /// lowered as [`crate::threaded`] lowers it (see [`Config::threads`]).
    pub threads: usize,
}

impl Run {
    /// The four runs of every case, in the order they are tried and reported.
    pub const ALL: [Run; 4] = [
        Run::new(Strategy::Fast, Precision::F64),
        Run::new(Strategy::Quality, Precision::F64),
        Run::new(Strategy::Fast, Precision::F32),
        Run::new(Strategy::Quality, Precision::F32),
    ];

    /// A run of `strategy` in `precision`.
    pub const fn new(strategy: Strategy, precision: Precision) -> Run {
        Run {
            strategy,
            precision,
            threads: 1,
        }
    }

    /// The fast strategy in `f64` on `threads` threads (see [`Config::threads`]).
    pub const fn on_threads(threads: usize) -> Run {
        Run {
            threads,
            ..Run::new(Strategy::Fast, Precision::F64)
        }
    }

    /// `fast_f64`, `quality_f32`, …: how case names and tables spell it.
    pub fn name(self) -> String {
        let strategy = match self.strategy {
            Strategy::Fast => "fast",
            Strategy::Quality => "quality",
            Strategy::Seidel => "seidel",
        };
        let name = format!("{strategy}_{}", self.precision.name());
        if self.threads > 1 {
            format!("{name}_threads{}", self.threads)
        } else {
            name
        }
    }
}

/// What the campaign triangulates: polytri, or in tests a deliberately broken stand-in.
pub trait Subject: Sync {
    /// Triangulates `input` as `run` says. For [`Precision::F32`] the input is already
    /// rounded ([`Input::to_f32`]), so its coordinates convert to `f32` exactly.
    ///
    /// # Errors
    ///
    /// What the triangulator said when it refused the input.
    fn triangulate(&self, input: &Input, run: Run) -> Result<Vec<[u32; 3]>, String>;
}

impl<F> Subject for F
where
    F: Fn(&Input, Run) -> Result<Vec<[u32; 3]>, String> + Sync,
{
    fn triangulate(&self, input: &Input, run: Run) -> Result<Vec<[u32; 3]>, String> {
        self(input, run)
    }
}

/// polytri itself: a strict [`polytri::Triangulator`] with the input's nesting
/// ([`polytri::Nesting::Auto`] for generated cases and for per-ring roles).
#[derive(Clone, Copy, Debug, Default)]
pub struct Polytri;

impl Subject for Polytri {
    fn triangulate(&self, input: &Input, run: Run) -> Result<Vec<[u32; 3]>, String> {
        let nesting = input.nesting.to_polytri().unwrap_or(polytri::Nesting::Auto);
        let options = polytri::Options::new()
            .with_strategy(run.strategy)
            .with_nesting(nesting)
            .with_threads(run.threads);
        let mut out = Vec::new();
        let result = match run.precision {
            Precision::F64 if run.threads > 1 => {
                threaded::with_kept::<f64, _>(run.threads, |tri| {
                    tri.triangulate(&input.vertices, &input.ring_starts, &options, &mut out)
                        .map(|_| ())
                })
            }
            Precision::F64 => polytri::Triangulator::<f64>::new()
                .triangulate(&input.vertices, &input.ring_starts, &options, &mut out)
                .map(|_| ()),
            Precision::F32 => polytri::Triangulator::<f32>::new()
                .triangulate(
                    &input.vertices_f32(),
                    &input.ring_starts,
                    &options,
                    &mut out,
                )
                .map(|_| ()),
        };
        result.map(|()| out).map_err(|e| e.to_string())
    }
}

/// How long a campaign runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Budget {
    /// Start new cases until this much time has passed (cases under way finish, failures
    /// are still shrunk).
    Time(Duration),
    /// Exactly this many cases.
    Cases(u64),
}

/// What a campaign runs.
#[derive(Clone, Debug)]
pub struct Config {
    /// How long. Default: 20 seconds.
    pub budget: Budget,
    /// Case `k` is generated from seed `seed + k`. Default: 1.
    pub seed: u64,
    /// The families, taken in turn. Default: [`Family::ALL`].
    pub families: Vec<Family>,
    /// Sizes are drawn log-uniformly between 3 and this many vertices; one case in 32 is
    /// drawn between this and four times as many (at most 100 000). Default: 2000.
    pub max_vertices: usize,
    /// Run the peers on every case too. Default: false.
    pub peers: bool,
    /// Worker threads. Default: the available parallelism.
    pub jobs: usize,
    /// With 2 or more, every case also runs the fast strategy in `f64` on this many
    /// threads, clipping by mark-and-cut from rings of 16 nodes on, in chunks of 8 (see
    /// [`crate::threaded`]): judged by the oracle, and its triangles compared with the
    /// same run on one thread more, which must give the same ones. Default: 1 (no such
    /// run).
    pub threads: usize,
    /// Where failing cases are written after shrinking (`None`: not written). Default:
    /// `None`.
    pub out_dir: Option<PathBuf>,
    /// The most `still fails?` attempts spent shrinking one failure. Default:
    /// [`shrink::DEFAULT_ATTEMPTS`].
    pub shrink_attempts: usize,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            budget: Budget::Time(Duration::from_secs(20)),
            seed: 1,
            families: Family::ALL.to_vec(),
            max_vertices: 2000,
            peers: false,
            jobs: std::thread::available_parallelism().map_or(1, |n| n.get()),
            threads: 1,
            out_dir: None,
            shrink_attempts: shrink::DEFAULT_ATTEMPTS,
        }
    }
}

impl Config {
    /// The family, seed and size of case `k` (see the module documentation).
    pub fn plan(&self, k: u64) -> Plan {
        let families = if self.families.is_empty() {
            &Family::ALL[..]
        } else {
            &self.families[..]
        };
        let family = families[(k % families.len() as u64) as usize];
        let seed = self.seed.wrapping_add(k);
        // Its own stream, apart from the generator's (which is seeded with `seed` too).
        let mut rng = Pcg64::seed_from_u64(seed ^ 0x6361_6d70_6169_676e);
        let max = self.max_vertices.clamp(3, 100_000) as f64;
        let (lo, hi) = if rng.random_range(0..32) == 0 {
            (max, (4.0 * max).min(100_000.0))
        } else {
            (3.0, max)
        };
        let vertices = log_uniform(&mut rng, lo, hi).round() as usize;
        let params = place(&mut rng, Params::new(vertices));
        Plan {
            family,
            seed,
            params,
        }
    }
}

/// `lo · (hi/lo)^u` for a uniform `u`: every order of magnitude equally likely.
fn log_uniform(rng: &mut Pcg64, lo: f64, hi: f64) -> f64 {
    if hi <= lo {
        return lo;
    }
    lo * (hi / lo).powf(rng.random::<f64>())
}

/// Where a case lies: mostly the unit square, sometimes tiny, huge or far from the origin
/// (offsets up to 1e9, where `f32` cannot tell neighbouring vertices apart any more).
/// Every choice keeps [`Params::is_exact`], so the `f64` case is valid by construction.
fn place(rng: &mut Pcg64, params: Params) -> Params {
    let pick: f64 = rng.random();
    if pick < 0.7 {
        params
    } else if pick < 0.8 {
        params.with_scale(2f64.powi(rng.random_range(-40..=-4)))
    } else if pick < 0.9 {
        params.with_scale(2f64.powi(rng.random_range(4..=60)))
    } else {
        let mut offset = [0.0; 2];
        for o in &mut offset {
            let sign = if rng.random::<bool>() { 1.0 } else { -1.0 };
            *o = sign * 10f64.powf(rng.random_range(2.0..9.0));
        }
        params.with_offset(offset)
    }
}

/// What case `k` is: its family, generator seed and parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plan {
    /// The generator family.
    pub family: Family,
    /// The generator seed (the campaign's seed plus `k`).
    pub seed: u64,
    /// Size, scale and offset.
    pub params: Params,
}

/// How a run failed.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Fault {
    /// The triangulator refused a valid input.
    Refused(String),
    /// The triangulator panicked.
    Panicked(String),
    /// The oracle rejected the result; the name of the first failing check.
    Rejected(String),
}

impl Fault {
    /// A short word for names: `refused`, `panicked` or the failing check's name.
    pub fn tag(&self) -> &str {
        match self {
            Fault::Refused(_) => "refused",
            Fault::Panicked(_) => "panicked",
            Fault::Rejected(check) => check,
        }
    }
}

/// One failing run of a case.
#[derive(Clone, Debug, PartialEq)]
pub struct RunFailure {
    /// Which run.
    pub run: Run,
    /// How it failed.
    pub fault: Fault,
    /// The whole story: the error, or every failed check with its detail.
    pub detail: String,
    /// The names of the checks that failed (empty unless [`Fault::Rejected`]).
    pub failed_checks: Vec<String>,
}

/// A failing case, shrunk, and where it was written.
#[derive(Clone, Debug)]
pub struct Found {
    /// Index of the case in the campaign.
    pub k: u64,
    /// What was generated.
    pub plan: Plan,
    /// Every failing run of the generated case.
    pub runs: Vec<RunFailure>,
    /// The generated case's vertex and ring counts.
    pub original_size: (usize, usize),
    /// The shrunk case, failing the first failing run the same way; named
    /// `campaign_<family>_seed<seed>_<run>_<fault>`.
    pub case: Case,
    /// The file it was written to, or why it could not be; `None` without an output
    /// directory.
    pub written: Option<Result<PathBuf, String>>,
}

/// One peer's record over a family's cases.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PeerStats {
    /// Outputs judged (triangles indexing the input's vertices).
    pub judged: usize,
    /// Failures: a refusal or panic, or an output the oracle rejects.
    pub failed: usize,
    /// Outputs with vertices of their own, not judged.
    pub not_judged: usize,
}

/// Everything the campaign learned about one family.
#[derive(Clone, Debug)]
pub struct FamilyStats {
    /// The family.
    pub family: Family,
    /// Cases generated.
    pub cases: usize,
    /// Triangulations run and judged.
    pub runs: usize,
    /// Cases with at least one failing run.
    pub failed_cases: usize,
    /// Failing runs.
    pub failed_runs: usize,
    /// Cases whose `f64` input the oracle found invalid (nothing ran); only asked when the
    /// placement is not exact ([`Params::is_exact`]), which the default plans always are.
    pub invalid: usize,
    /// Cases whose `f32`-rounded input is not valid by the exact test (a ring collapsed,
    /// a spike, a crossing): the `f32` runs were skipped.
    pub f32_invalid: usize,
    /// The smallest angle (degrees) of every passing fast `f64` triangulation.
    pub fast_min_angles: Vec<f64>,
    /// The same for quality.
    pub quality_min_angles: Vec<f64>,
    /// The same for spade's constrained Delaunay triangulation of the input.
    pub cdt_min_angles: Vec<f64>,
    /// Vertices of the cases, summed.
    pub vertices: usize,
    /// Time spent on the family's cases (generation, runs, checks, peers, shrinking),
    /// summed over threads.
    pub time: Duration,
    /// Per peer, in [`Peer::ALL`] order (empty without [`Config::peers`]).
    pub peers: Vec<(Peer, PeerStats)>,
}

impl FamilyStats {
    fn new(family: Family, with_peers: bool) -> Self {
        FamilyStats {
            family,
            cases: 0,
            runs: 0,
            failed_cases: 0,
            failed_runs: 0,
            invalid: 0,
            f32_invalid: 0,
            fast_min_angles: Vec::new(),
            quality_min_angles: Vec::new(),
            cdt_min_angles: Vec::new(),
            vertices: 0,
            time: Duration::ZERO,
            peers: if with_peers {
                Peer::ALL.map(|p| (p, PeerStats::default())).to_vec()
            } else {
                Vec::new()
            },
        }
    }

    fn add(&mut self, outcome: &Outcome) {
        self.cases += 1;
        self.runs += outcome.runs;
        self.failed_runs += outcome.failures.len();
        self.failed_cases += usize::from(!outcome.failures.is_empty());
        self.invalid += usize::from(outcome.invalid);
        self.f32_invalid += usize::from(outcome.f32_invalid);
        self.vertices += outcome.vertices;
        self.time += outcome.time;
        self.fast_min_angles.extend(outcome.fast_min_angle);
        self.quality_min_angles.extend(outcome.quality_min_angle);
        self.cdt_min_angles.extend(outcome.cdt_min_angle);
        for ((_, stats), (_, peer)) in self.peers.iter_mut().zip(&outcome.peers) {
            stats.judged += usize::from(*peer == PeerResult::Passed || *peer == PeerResult::Failed);
            stats.failed += usize::from(*peer == PeerResult::Failed);
            stats.not_judged += usize::from(*peer == PeerResult::NotJudged);
        }
    }
}

/// The median and the smallest of `values` (`None` when empty).
pub fn median_and_worst(values: &[f64]) -> Option<(f64, f64)> {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let median = *sorted.get(sorted.len() / 2)?;
    Some((median, sorted[0]))
}

/// What a campaign found.
#[derive(Clone, Debug)]
pub struct Report {
    /// One entry per family, in [`Config::families`] order.
    pub families: Vec<FamilyStats>,
    /// Every failing case, in case order.
    pub failures: Vec<Found>,
    /// Wall-clock time of the whole campaign.
    pub elapsed: Duration,
    /// Worker threads used.
    pub jobs: usize,
}

impl Report {
    /// Cases run, over all families.
    pub fn cases(&self) -> usize {
        self.families.iter().map(|f| f.cases).sum()
    }

    /// Triangulations run, over all families.
    pub fn runs(&self) -> usize {
        self.families.iter().map(|f| f.runs).sum()
    }

    /// Whether every run of every case passed.
    pub fn passed(&self) -> bool {
        self.failures.is_empty()
    }
}

/// How far a campaign has got, for a progress bar.
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    /// Cases finished.
    pub cases: u64,
    /// Failing cases so far.
    pub failures: u64,
    /// Time since the start.
    pub elapsed: Duration,
    /// The budget.
    pub budget: Budget,
}

/// The result of one peer on one case.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum PeerResult {
    Passed,
    Failed,
    NotJudged,
}

/// Everything about one case.
#[derive(Debug)]
struct Outcome {
    k: u64,
    family: Family,
    vertices: usize,
    runs: usize,
    failures: Vec<RunFailure>,
    invalid: bool,
    f32_invalid: bool,
    fast_min_angle: Option<f64>,
    quality_min_angle: Option<f64>,
    cdt_min_angle: Option<f64>,
    peers: Vec<(Peer, PeerResult)>,
    time: Duration,
    found: Option<Found>,
}

/// Runs a campaign: `subject` on the cases `config` describes, `progress` called after
/// every case (from worker threads).
pub fn run(
    config: &Config,
    subject: &dyn Subject,
    progress: &(dyn Fn(&Progress) + Sync),
) -> Report {
    let start = Instant::now();
    let next = AtomicU64::new(0);
    let done = AtomicU64::new(0);
    let failed = AtomicU64::new(0);
    let outcomes = Mutex::new(Vec::new());
    let jobs = config.jobs.max(1);
    std::thread::scope(|scope| {
        for _ in 0..jobs {
            scope.spawn(|| loop {
                let k = next.fetch_add(1, Ordering::Relaxed);
                let more = match config.budget {
                    Budget::Cases(n) => k < n,
                    Budget::Time(limit) => start.elapsed() < limit,
                };
                if !more {
                    break;
                }
                let outcome = run_case(config, subject, k);
                if outcome.found.is_some() {
                    failed.fetch_add(1, Ordering::Relaxed);
                }
                // A poisoned lock only means another worker panicked: its cases are lost,
                // these are not.
                outcomes
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .push(outcome);
                progress(&Progress {
                    cases: done.fetch_add(1, Ordering::Relaxed) + 1,
                    failures: failed.load(Ordering::Relaxed),
                    elapsed: start.elapsed(),
                    budget: config.budget,
                });
            });
        }
    });
    let mut outcomes = outcomes.into_inner().unwrap_or_else(|e| e.into_inner());
    outcomes.sort_by_key(|o| o.k);
    summarize(config, outcomes, start.elapsed(), jobs)
}

/// Folds the outcomes, in case order, into the report.
fn summarize(config: &Config, outcomes: Vec<Outcome>, elapsed: Duration, jobs: usize) -> Report {
    let mut families: Vec<FamilyStats> = Vec::new();
    let order = if config.families.is_empty() {
        Family::ALL.to_vec()
    } else {
        config.families.clone()
    };
    for family in order {
        if !families.iter().any(|f| f.family == family) {
            families.push(FamilyStats::new(family, config.peers));
        }
    }
    let mut failures = Vec::new();
    for mut outcome in outcomes {
        if let Some(stats) = families.iter_mut().find(|f| f.family == outcome.family) {
            stats.add(&outcome);
        }
        failures.extend(outcome.found.take());
    }
    Report {
        families,
        failures,
        elapsed,
        jobs,
    }
}

/// Generates, runs, judges and (on failure) shrinks and writes case `k`.
fn run_case(config: &Config, subject: &dyn Subject, k: u64) -> Outcome {
    let started = Instant::now();
    let plan = config.plan(k);
    let case = generate(plan.family, plan.seed, &plan.params);
    let mut outcome = Outcome {
        k,
        family: plan.family,
        vertices: case.input.vertices.len(),
        runs: 0,
        failures: Vec::new(),
        invalid: false,
        f32_invalid: false,
        fast_min_angle: None,
        quality_min_angle: None,
        cdt_min_angle: None,
        peers: Vec::new(),
        time: Duration::ZERO,
        found: None,
    };
    // Exact placement keeps the generators' validity by construction (and the verdicts'
    // `input` check would still tell); otherwise ask the oracle first.
    if !plan.params.is_exact() && !input_valid(&case.input) {
        outcome.invalid = true;
        outcome.time = started.elapsed();
        return outcome;
    }
    let narrow = f32_input(&case.input);
    outcome.f32_invalid = narrow.is_none();
    let exact_in_f32 = narrow.as_ref() == Some(&case.input);
    // The f64 triangles per strategy, when they passed: equal f32 triangles of an
    // unchanged input need no second verdict.
    let mut passed: Vec<(Strategy, Vec<[u32; 3]>)> = Vec::new();
    for run in Run::ALL {
        let input = match (run.precision, &narrow) {
            (Precision::F64, _) => &case.input,
            (Precision::F32, Some(narrow)) => narrow,
            (Precision::F32, None) => continue,
        };
        outcome.runs += 1;
        let triangles = match triangulate(subject, input, run) {
            Ok(triangles) => triangles,
            Err(failure) => {
                outcome.failures.push(failure);
                continue;
            }
        };
        let same = exact_in_f32
            && passed
                .iter()
                .any(|(strategy, t)| *strategy == run.strategy && *t == triangles);
        if same {
            continue;
        }
        let cdt = run == Run::ALL[0];
        match judge(input, run, &triangles, cdt) {
            Ok(verdict) => {
                if run == Run::ALL[0] {
                    outcome.fast_min_angle = Some(verdict.min_angle_deg);
                    outcome.cdt_min_angle = verdict.cdt.map(|c| c.min_angle_deg);
                } else if run == Run::ALL[1] {
                    outcome.quality_min_angle = Some(verdict.min_angle_deg);
                }
                if run.precision == Precision::F64 {
                    passed.push((run.strategy, triangles));
                }
            }
            Err(failure) => outcome.failures.push(failure),
        }
    }
    if config.threads > 1 {
        outcome.runs += 1;
        if let Err(failure) = attempt(subject, &case.input, Run::on_threads(config.threads)) {
            outcome.failures.push(failure);
        }
    }
    if config.peers {
        outcome.peers = Peer::ALL.map(|p| (p, judge_peer(p, &case.input))).to_vec();
    }
    if let Some(first) = outcome.failures.first().cloned() {
        let mut found = shrink_and_write(config, subject, &plan, &case, first, &outcome.failures);
        found.k = k;
        outcome.found = Some(found);
    }
    outcome.time = started.elapsed();
    outcome
}

/// The oracle's verdict on the input alone.
fn input_valid(input: &Input) -> bool {
    check_with(input, &[], &CheckOptions::fast()).input_valid
}

/// The input the `f32` runs see: `input` rounded to `f32`, if that is still valid by the
/// exact test with rings allowed to touch at vertices (see the module documentation).
pub fn f32_input(input: &Input) -> Option<Input> {
    let narrow = input.to_f32();
    (narrow == *input || validate(&narrow, true).is_ok()).then_some(narrow)
}

/// A failure of `run` before the oracle had anything to say.
fn fault(run: Run, fault: Fault, detail: String) -> RunFailure {
    RunFailure {
        run,
        fault,
        detail,
        failed_checks: Vec::new(),
    }
}

/// Runs `subject` once, catching refusals and panics.
fn triangulate(
    subject: &dyn Subject,
    input: &Input,
    run: Run,
) -> Result<Vec<[u32; 3]>, RunFailure> {
    match catch_unwind(AssertUnwindSafe(|| subject.triangulate(input, run))) {
        Ok(Ok(triangles)) => Ok(triangles),
        Ok(Err(why)) => Err(fault(
            run,
            Fault::Refused(why.clone()),
            format!("refused: {why}"),
        )),
        Err(panic) => {
            let why = panic_text(&*panic);
            Err(fault(
                run,
                Fault::Panicked(why.clone()),
                format!("panicked: {why}"),
            ))
        }
    }
}

/// The oracle's verdict on `triangles`; `cdt` adds spade's CDT comparison.
fn judge(
    input: &Input,
    run: Run,
    triangles: &[[u32; 3]],
    cdt: bool,
) -> Result<Verdict, RunFailure> {
    let options = CheckOptions { geo: false, cdt };
    let verdict = check_with(input, triangles, &options);
    if verdict.valid {
        return Ok(verdict);
    }
    let failed_checks: Vec<String> = verdict
        .checks
        .iter()
        .filter(|c| !c.passed)
        .map(|c| c.name.clone())
        .collect();
    let first = failed_checks
        .first()
        .cloned()
        .unwrap_or_else(|| "unknown".to_owned());
    Err(RunFailure {
        failed_checks,
        ..fault(run, Fault::Rejected(first), verdict.failures().join("; "))
    })
}

/// Runs and judges `run` on `input` (already rounded for `f32` runs).
/// On more than one thread, the triangles must also equal those of one thread more
/// (check `threads_agree`).
fn attempt(subject: &dyn Subject, input: &Input, run: Run) -> Result<Verdict, RunFailure> {
    let triangles = triangulate(subject, input, run)?;
    let verdict = judge(input, run, &triangles, false)?;
    if run.threads > 1 {
        let more = Run {
            threads: run.threads + 1,
            ..run
        };
        let again = triangulate(subject, input, more)?;
        if again != triangles {
            let differ = (triangles.iter().zip(&again))
                .position(|(t, u)| t != u)
                .unwrap_or(triangles.len().min(again.len()));
            return Err(RunFailure {
                run,
                fault: Fault::Rejected(THREADS_AGREE.to_owned()),
                detail: format!(
                    "{THREADS_AGREE}: {} and {} threads give different triangles \
                     ({} and {}; the first difference at triangle {differ})",
                    run.threads,
                    more.threads,
                    triangles.len(),
                    again.len()
                ),
                failed_checks: vec![THREADS_AGREE.to_owned()],
            });
        }
    }
    Ok(verdict)
}

/// The check a run on several threads fails when one thread more gives other triangles.
pub const THREADS_AGREE: &str = "threads_agree";

/// The text of a panic payload.
fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_owned()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "(no message)".to_owned()
    }
}

/// One peer on the `f64` input, judged by the exact checks.
fn judge_peer(peer: Peer, input: &Input) -> PeerResult {
    match peers::triangulate(peer, input) {
        Err(_) => PeerResult::Failed,
        Ok(out) if out.vertices.is_some() => PeerResult::NotJudged,
        Ok(out) => {
            if check_with(input, &out.triangles, &CheckOptions::fast()).valid {
                PeerResult::Passed
            } else {
                PeerResult::Failed
            }
        }
    }
}

/// Whether `candidate` fails `first.run` the way `first` did: refused again, panicked
/// again, or rejected with the same check among its failures.
fn fails_alike(subject: &dyn Subject, candidate: &Input, first: &RunFailure) -> bool {
    let Some(input) = run_input(candidate, first.run) else {
        return false;
    };
    match (attempt(subject, &input, first.run), &first.fault) {
        (Ok(_), _) => false,
        (Err(again), Fault::Rejected(check)) => again.failed_checks.contains(check),
        (Err(again), fault) => {
            std::mem::discriminant(&again.fault) == std::mem::discriminant(fault)
        }
    }
}

/// The input `run` sees for the case `input`: itself, or its valid `f32` rounding.
fn run_input(input: &Input, run: Run) -> Option<Input> {
    match run.precision {
        Precision::F64 => Some(input.clone()),
        Precision::F32 => f32_input(input),
    }
}

/// Shrinks the failing `case` for its first failure, names it and writes it.
fn shrink_and_write(
    config: &Config,
    subject: &dyn Subject,
    plan: &Plan,
    case: &Case,
    first: RunFailure,
    all: &[RunFailure],
) -> Found {
    let mut small = shrink::shrink_within(case, config.shrink_attempts, |c| {
        fails_alike(subject, &c.input, &first)
    });
    let family = plan.family.name().replace('-', "_");
    let tag: String = first
        .fault
        .tag()
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    small.name = format!(
        "campaign_{family}_seed{}_{}_{tag}",
        plan.seed,
        first.run.name()
    );
    // What the shrunk case does now, in its own words.
    let now = match run_input(&small.input, first.run).map(|i| attempt(subject, &i, first.run)) {
        Some(Err(f)) => f.detail,
        _ => "passes (shrinking lost the failure)".to_owned(),
    };
    let runs: Vec<String> = all
        .iter()
        .map(|f| format!("{}: {}", f.run.name(), f.detail))
        .collect();
    small.description = format!(
        "polytri campaign: {} fails {} ({}). Shrunk from {} vertices in {} rings to {} in {}. \
         Generated as {} seed {} with {} vertices, scale {}, offset {:?}; the generated case failed {}",
        first.run.name(),
        first.fault.tag(),
        now,
        case.input.vertices.len(),
        case.input.ring_count(),
        small.input.vertices.len(),
        small.input.ring_count(),
        plan.family,
        plan.seed,
        plan.params.vertices,
        plan.params.effective_scale(),
        plan.params.offset,
        runs.join(" | "),
    );
    small.source = "campaign".to_owned();
    small.family = Some(plan.family);
    small.seed = Some(plan.seed);
    small.expect = None;
    let written = config.out_dir.as_ref().map(|dir| {
        let path = dir.join(format!("{}.json", small.name));
        std::fs::create_dir_all(dir)
            .and_then(|()| std::fs::write(&path, small.to_json() + "\n"))
            .map(|()| path.clone())
            .map_err(|e| format!("{}: {e}", path.display()))
    });
    Found {
        k: 0,
        plan: *plan,
        runs: all.to_vec(),
        original_size: (case.input.vertices.len(), case.input.ring_count()),
        case: small,
        written,
    }
}
