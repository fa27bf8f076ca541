//! Replaying the regression corpus: every case of a corpus folder through polytri in both
//! strategies, both precisions and four exact rotations, judged by the oracle.
//!
//! One implementation serves `oracle/tests/corpus.rs` (which pins each [`CaseSnapshot`] as
//! an insta snapshot) and `polytri replay` (which prints the [`Row`]s as a table).
//!
//! A folder is one of:
//!
//! - **earcut's suite** (it holds `expected.json` and `fixtures/`): every fixture named in
//!   `expected.json`, `Nesting::FirstIsOuter`, deviation bounded by earcut's `errors` /
//!   `errors-with-rotation` — or by our own tighter `bounds.json` beside it, same shape;
//! - **cases**: every `*.json` file, each either a [`Case`] (an object with `rings`), a
//!   rings JSON (`[[[x, y], …], …]`, earcut's convention) or a shapes JSON (a list of
//!   polygons, each polygon's first ring outer: one input with [`Nesting::Roles`]).
//!
//! What a replay demands (each broken demand is a [`Replay::failures`] line):
//!
//! - no run panics, and lenient runs never return an error;
//! - an input the oracle finds valid (`input_valid`) is triangulated in strict mode and
//!   the verdict is valid, with the case's `expect.triangles` where given;
//! - an invalid input is refused in strict mode with an error message, and the lenient
//!   result stays within the case's deviation bound (earcut's, ours, `expect.max_deviation`);
//! - an `f32` run whose input rounding changed and made invalid is only recorded, as
//!   `f32 input invalid`;
//! - `expect.input_valid`, where given, matches the oracle's judgement of the input;
//! - every [`KNOWN_GAPS`] entry is still a gap (else it must go, so the bound tightens);
//! - a case in [`KNOWN_FAILURES`] still fails (its failures are expected until then).

use std::collections::BTreeMap;
use std::fmt;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

use polytri::{Options, Strategy, Triangulator};
use serde::Serialize;
use serde_json::Value;

use crate::check::{check_with, CheckOptions, Verdict};
use crate::gen::Case;
use crate::input::{Grouping, Input, Nesting};

/// Where polytri's lenient result is further from the input's area than earcut's bound
/// allows. The one place such gaps are listed: each replaces earcut's bound at its rotation
/// (every strategy and precision) until the gap closes, and a replay fails once no run
/// needs it any more — delete the entry then, so the bound tightens.
///
/// Empty: the last one, `water-huge2` at rotation 0 with quality (3.91e-3 against earcut's
/// 3e-3), closed when lenient splits came to require diagonals the ring winds around (a
/// split across a peninsula of land had filled it); it measures 9.6e-4 since.
pub const KNOWN_GAPS: [KnownGap; 0] = [];

/// Cases polytri still gets wrong, with the issue tracking each: their failures are
/// reported as [`Replay::known_failures`] instead of [`Replay::failures`] (the snapshot
/// still records what happens), and a replay fails once such a case passes — delete its
/// entry then, so the case guards the fix.
///
/// The weakly simple cases `polytri precision` found
/// (`cases/ring_doubles_back_along_its_own_edge`, `cases/zero_area_hole_of_collinear_points`,
/// `cases/spiral_collapsed_by_f32_rounding`) pass since the oracle's contract says
/// zero-width boundary parts enclose nothing and touch orders edges of one direction; the
/// rings lying on each other that `raw_rings` found (`cases/hole_equal_to_its_outer_ring_with_spikes`,
/// `cases/ring_touching_a_triangle_at_all_its_corners`) since nesting counts winding
/// numbers next to shared vertices exactly.
pub const KNOWN_FAILURES: [KnownFailure; 0] = [];

/// A case polytri still gets wrong; see [`KNOWN_FAILURES`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct KnownFailure {
    /// `folder/name` of the case.
    pub case: &'static str,
    /// The strategies that fail it (`fast`, `quality`).
    pub strategies: &'static [&'static str],
    /// The issue tracking it.
    pub issue: &'static str,
}

/// A deviation bound polytri does not meet yet; see [`KNOWN_GAPS`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KnownGap {
    /// `folder/name` of the case.
    pub case: &'static str,
    /// The strategies that need it (`fast`, `quality`).
    pub strategies: &'static [&'static str],
    /// The rotation in degrees.
    pub rotation: u32,
    /// The bound that replaces earcut's there.
    pub deviation: f64,
}

/// Slack for floating-point round-off in the deviation where coordinates are not all
/// integers (the measure itself is computed in floating point).
pub const ROUND_OFF: f64 = 1e-13;

/// Cases with fewer vertices than this get their triangle list in the snapshot; larger
/// ones only its hash.
pub const LIST_TRIANGLES_BELOW: usize = 200;

/// Inputs with fewer vertices than this are judged with every check
/// ([`CheckOptions::full`]: geo and spade's CDT too); larger ones with the exact checks only.
pub const FULL_CHECKS_BELOW: usize = 5_000;

/// The rotations every case is replayed in, degrees counter-clockwise. Exact in floating
/// point: 90° maps (x, y) to (−y, x), as earcut's own test suite does.
pub const ROTATIONS: [u32; 4] = [0, 90, 180, 270];

/// The two ear-clipping strategies, in replay order.
pub const STRATEGIES: [Strategy; 2] = [Strategy::Fast, Strategy::Quality];

/// The coordinate type polytri runs in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Precision {
    /// `Triangulator<f64>` on the input as given.
    #[default]
    F64,
    /// `Triangulator<f32>` on the input rounded to `f32`.
    F32,
}

impl Precision {
    /// Both, in replay order.
    pub const ALL: [Precision; 2] = [Precision::F64, Precision::F32];
}

impl fmt::Display for Precision {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Precision::F64 => "f64",
            Precision::F32 => "f32",
        })
    }
}

/// Strict or lenient mode (see [`polytri::Options::lenient`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Mode {
    /// Refuse bad input.
    #[default]
    Strict,
    /// Make the best of any input.
    Lenient,
}

/// The lower-case name of a strategy: `fast`, `quality` or `seidel`.
pub fn strategy_name(strategy: Strategy) -> &'static str {
    match strategy {
        Strategy::Quality => "quality",
        Strategy::Seidel => "seidel",
        _ => "fast",
    }
}

/// What a case promises beyond validity: its `expect` object.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Expect {
    /// `expect.triangles`: the count of every strict triangulation.
    pub triangles: Option<usize>,
    /// `expect.input_valid`: the oracle's judgement of the input.
    pub input_valid: Option<bool>,
    /// `expect.max_deviation`: the bound for lenient runs on an invalid input.
    pub max_deviation: Option<f64>,
}

impl Expect {
    /// Reads the known keys of an `expect` object; others are ignored.
    ///
    /// # Errors
    ///
    /// A known key of the wrong type.
    pub fn from_json(value: Option<&Value>) -> Result<Expect, String> {
        let Some(v) = value else {
            return Ok(Expect::default());
        };
        let field = |key: &str| v.get(key).filter(|f| !f.is_null());
        let bad = |key: &str, what: &str| format!("expect.{key} must be {what}");
        Ok(Expect {
            triangles: match field("triangles") {
                None => None,
                Some(t) => Some(t.as_u64().ok_or_else(|| bad("triangles", "a count"))? as usize),
            },
            input_valid: match field("input_valid") {
                None => None,
                Some(b) => Some(
                    b.as_bool()
                        .ok_or_else(|| bad("input_valid", "true or false"))?,
                ),
            },
            max_deviation: match field("max_deviation") {
                None => None,
                Some(d) => Some(d.as_f64().ok_or_else(|| bad("max_deviation", "a number"))?),
            },
        })
    }
}

/// Deviation bounds of an earcut fixture: earcut's, tightened by ours.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DeviationBounds {
    /// earcut's triangle count at rotation 0 (recorded, not enforced: polytri may keep
    /// other vertices).
    pub earcut_triangles: usize,
    /// earcut's bound at rotation 0 (`errors`, missing: 0).
    pub earcut: f64,
    /// earcut's bound at 90°, 180° and 270° (`errors-with-rotation`, else `errors`).
    pub earcut_rotated: f64,
    /// Our bound at rotation 0 from `bounds.json`, when we record a tighter one.
    pub ours: Option<f64>,
    /// Our bound at the other rotations from `bounds.json`.
    pub ours_rotated: Option<f64>,
}

impl DeviationBounds {
    /// The bound in force at `rotation`: ours where recorded, else earcut's.
    ///
    /// ```
    /// use polytri_oracle::replay::DeviationBounds;
    /// let b = DeviationBounds { earcut: 3e-3, earcut_rotated: 3e-2, ours_rotated: Some(5e-3), ..Default::default() };
    /// assert_eq!((b.at(0), b.at(90)), (3e-3, 5e-3));
    /// ```
    pub fn at(&self, rotation: u32) -> f64 {
        // Ours only ever tightens earcut's; at 90°, 180° and 270° only ours for rotations
        // applies (earcut's `errors` may be overridden by a looser `errors-with-rotation`).
        let (ours, earcut) = if rotation == 0 {
            (self.ours, self.earcut)
        } else {
            (self.ours_rotated, self.earcut_rotated)
        };
        ours.map_or(earcut, |o| o.min(earcut))
    }

    /// earcut's bound at `rotation`.
    pub fn earcut_at(&self, rotation: u32) -> f64 {
        if rotation == 0 {
            self.earcut
        } else {
            self.earcut_rotated
        }
    }
}

/// One input of the corpus with what it must satisfy.
#[derive(Clone, Debug, PartialEq)]
pub struct CorpusCase {
    /// The folder's name (`earcut`, `paper`, `cases`, `datasets`, …).
    pub folder: String,
    /// The case's name: the fixture's or file's name without `.json`.
    pub name: String,
    /// What is triangulated.
    pub input: Input,
    /// What the case promises.
    pub expect: Expect,
    /// Deviation bounds (earcut fixtures).
    pub bounds: Option<DeviationBounds>,
}

impl CorpusCase {
    /// `folder/name`.
    pub fn id(&self) -> String {
        format!("{}/{}", self.folder, self.name)
    }

    /// The insta snapshot name for `strategy`: `folder__name__strategy`.
    pub fn snapshot_name(&self, strategy: Strategy) -> String {
        format!(
            "{}__{}__{}",
            self.folder,
            self.name,
            strategy_name(strategy)
        )
    }
}

/// Reads every case of a corpus folder, sorted by name.
///
/// # Errors
///
/// A message naming the file that could not be read or parsed.
pub fn load_dir(dir: &Path) -> Result<Vec<CorpusCase>, String> {
    load_cases(dir, None)
}

/// Reads every case of a corpus folder as [`load_dir`] does, but its rings JSON and shapes
/// JSON files as `grouping` says ([`Input::from_polygons`]): `polytri replay --nesting
/// --merge`. Corpus case files carry their own nesting, and earcut's suite keeps earcut's
/// convention (its counts and deviation bounds are for it).
///
/// # Errors
///
/// As [`load_dir`].
pub fn load_dir_grouped(dir: &Path, grouping: Grouping) -> Result<Vec<CorpusCase>, String> {
    load_cases(dir, Some(grouping))
}

fn load_cases(dir: &Path, grouping: Option<Grouping>) -> Result<Vec<CorpusCase>, String> {
    let folder = dir
        .canonicalize()
        .ok()
        .and_then(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .unwrap_or_else(|| dir.display().to_string());
    if dir.join("expected.json").is_file() && dir.join("fixtures").is_dir() {
        return load_earcut(dir, &folder);
    }
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    (files.iter())
        .map(|path| load_file_grouped(path, &folder, grouping))
        .collect()
}

fn read_json(path: &Path) -> Result<Value, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))
}

/// One case file: a [`Case`], rings JSON or shapes JSON.
///
/// # Errors
///
/// A message naming the file, when it cannot be read or parsed.
pub fn load_file(path: &Path, folder: &str) -> Result<CorpusCase, String> {
    load_file_grouped(path, folder, None)
}

/// One case file, its rings or shapes JSON read as `grouping` says where given.
fn load_file_grouped(
    path: &Path,
    folder: &str,
    grouping: Option<Grouping>,
) -> Result<CorpusCase, String> {
    let name = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let value = read_json(path)?;
    let at = |e: String| format!("{}: {e}", path.display());
    let (input, expect) = if value.get("rings").is_some() {
        let case: Case = serde_json::from_value(value).map_err(|e| at(e.to_string()))?;
        (
            case.input,
            Expect::from_json(case.expect.as_ref()).map_err(at)?,
        )
    } else {
        (
            input_from_array(&value, grouping).map_err(at)?,
            Expect::default(),
        )
    };
    Ok(CorpusCase {
        folder: folder.to_owned(),
        name,
        input,
        expect,
        bounds: None,
    })
}

/// Rings JSON (depth 3: one polygon) or shapes JSON (depth 4: a list of polygons), read as
/// `grouping` says, or else by earcut's convention: a rings JSON's first ring outer
/// ([`Nesting::FirstIsOuter`]), each shape's first ring outer and the rest its holes
/// ([`Nesting::Roles`]).
fn input_from_array(value: &Value, grouping: Option<Grouping>) -> Result<Input, String> {
    let depth = {
        let mut d = 0;
        let mut v = value;
        while let Some(first) = v.as_array().and_then(|a| a.first()) {
            d += 1;
            v = first;
        }
        d
    };
    let polygons: Vec<Vec<Vec<[f64; 2]>>> = match depth {
        3 => vec![serde_json::from_value(value.clone()).map_err(|e| e.to_string())?],
        4 => serde_json::from_value(value.clone()).map_err(|e| e.to_string())?,
        _ => {
            return Err(
                "neither a case (an object with \"rings\"), rings JSON nor shapes JSON".into(),
            )
        }
    };
    if let Some(grouping) = grouping {
        return Ok(Input::from_polygons(&polygons, grouping));
    }
    let rings: Vec<Vec<[f64; 2]>> = polygons.iter().flatten().cloned().collect();
    if depth == 3 {
        return Ok(Input::from_rings(&rings, Nesting::FirstIsOuter));
    }
    Ok(Input::from_rings(
        &rings,
        Nesting::first_ring_outer(&polygons),
    ))
}

/// earcut's suite: the fixtures `expected.json` names, with their bounds.
fn load_earcut(dir: &Path, folder: &str) -> Result<Vec<CorpusCase>, String> {
    let expected = read_json(&dir.join("expected.json"))?;
    let ours = match dir.join("bounds.json") {
        p if p.is_file() => read_json(&p)?,
        _ => Value::Null,
    };
    let bound = |v: &Value, table: &str, name: &str| v[table].get(name).and_then(Value::as_f64);
    let counts = expected["triangles"]
        .as_object()
        .ok_or("expected.json: no \"triangles\" object")?;
    let mut cases = Vec::new();
    for (name, count) in counts {
        let rings: Vec<Vec<[f64; 2]>> =
            serde_json::from_value(read_json(&dir.join(format!("fixtures/{name}.json")))?)
                .map_err(|e| format!("fixtures/{name}.json: {e}"))?;
        let earcut = bound(&expected, "errors", name).unwrap_or(0.0);
        cases.push(CorpusCase {
            folder: folder.to_owned(),
            name: name.clone(),
            input: Input::from_rings(&rings, Nesting::FirstIsOuter),
            expect: Expect::default(),
            bounds: Some(DeviationBounds {
                earcut_triangles: count.as_u64().unwrap_or(0) as usize,
                earcut,
                earcut_rotated: bound(&expected, "errors-with-rotation", name).unwrap_or(earcut),
                ours: bound(&ours, "errors", name),
                ours_rotated: bound(&ours, "errors-with-rotation", name),
            }),
        });
    }
    cases.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(cases)
}

/// `input` rotated by `degrees` (a multiple of 90) counter-clockwise, exactly.
pub fn rotate(input: &Input, degrees: u32) -> Input {
    let quarter = |[x, y]: [f64; 2]| [-y, x];
    let mut out = input.clone();
    for _ in 0..(degrees / 90) % 4 {
        for p in &mut out.vertices {
            *p = quarter(*p);
        }
    }
    out
}

/// FNV-1a (64 bit) of a triangle list, each index as 4 little-endian bytes: a stable
/// fingerprint across runs and machines.
pub fn fnv1a(triangles: &[[u32; 3]]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in triangles.iter().flatten().flat_map(|i| i.to_le_bytes()) {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    format!("{h:016x}")
}

/// `x` rounded to `digits` significant digits, so snapshots do not churn on the last bits
/// of a floating-point sum (0 stays exactly 0; NaN and infinities become `None`).
pub fn round_sig(x: f64, digits: usize) -> Option<f64> {
    if !x.is_finite() {
        return None;
    }
    if x == 0.0 {
        return Some(0.0);
    }
    format!("{x:.*e}", digits.saturating_sub(1)).parse().ok()
}

/// One triangulation of a case, as its snapshot records it.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct RunSnapshot {
    /// `f64` or `f32`.
    pub precision: Precision,
    /// Degrees.
    pub rotation: u32,
    /// Strict or lenient.
    pub mode: Mode,
    /// Why the run was not judged (`f32 input invalid`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skipped: Option<String>,
    /// polytri's error, when it refused.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// The panic message, when it panicked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub panic: Option<String>,
    /// The number of triangles.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub triangles: Option<usize>,
    /// The oracle's expected count (valid inputs).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub expected_triangles: Option<usize>,
    /// The verdict: every check passed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub valid: Option<bool>,
    /// The names of the checks that failed.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub failed_checks: Vec<String>,
    /// earcut's deviation measure, 4 significant digits.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub deviation: Option<f64>,
    /// The smallest angle in degrees, 5 significant digits.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_angle_deg: Option<f64>,
    /// spade's CDT's smallest angle (the quality target), when the full checks ran.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cdt_min_angle_deg: Option<f64>,
    /// Input vertices no triangle uses, counted by reason.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub dropped: BTreeMap<String, usize>,
    /// Lenient repairs, counted by kind.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub repairs: BTreeMap<String, usize>,
    /// FNV-1a of the triangle list ([`fnv1a`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub triangles_fnv1a: Option<String>,
}

/// Everything one strategy did with one case: the content of its insta snapshot.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CaseSnapshot {
    /// `folder/name`.
    pub case: String,
    /// `fast` or `quality`.
    pub strategy: &'static str,
    /// Input vertices.
    pub vertices: usize,
    /// Input rings.
    pub rings: usize,
    /// The oracle's judgement of the input (rotation 0, `f64`).
    pub input_valid: bool,
    /// The triangles of the first run that made any (`f64`, rotation 0), one `"a b c"`
    /// string each, for inputs under [`LIST_TRIANGLES_BELOW`] vertices.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub triangle_list: Option<Vec<String>>,
    /// Every run, by precision, rotation and mode.
    pub runs: Vec<RunSnapshot>,
}

/// One line of `polytri replay`'s table: a case in one strategy and precision, every
/// rotation and mode summed up.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Row {
    /// `folder/name`.
    pub case: String,
    /// `fast` or `quality`.
    pub strategy: &'static str,
    /// `f64` or `f32`.
    pub precision: Precision,
    /// `valid`; `refused, lenient ok` (an invalid input); `refused` (strict refused, nothing
    /// else ran); `f32 input invalid`; `known failure (issue …)` ([`KNOWN_FAILURES`]); or
    /// `FAIL (n)` with the number of failures.
    pub verdict: String,
    /// No demand failed.
    pub passed: bool,
    /// The largest deviation of any judged run.
    pub deviation: Option<f64>,
    /// The smallest angle of any judged run that made triangles.
    pub min_angle_deg: Option<f64>,
}

/// The outcome of replaying one case in one strategy.
#[derive(Clone, Debug, PartialEq)]
pub struct Replay {
    /// The snapshot to pin.
    pub snapshot: CaseSnapshot,
    /// One row per precision.
    pub rows: Vec<Row>,
    /// Broken demands, one line each, naming case, strategy, precision, rotation and mode.
    pub failures: Vec<String>,
    /// Broken demands of a case in [`KNOWN_FAILURES`]: expected until its issue is fixed.
    pub known_failures: Vec<String>,
    /// The largest deviation of a lenient run on an invalid input, per rotation (earcut
    /// fixtures expecting triangles), for tightening `bounds.json`.
    pub lenient_deviation: BTreeMap<u32, f64>,
}

/// The raw result of one polytri run.
struct Outcome {
    result: Result<Vec<[u32; 3]>, String>,
    dropped: BTreeMap<String, usize>,
    repairs: BTreeMap<String, usize>,
}

/// Triangulates with polytri, catching panics (`Err` holds the panic message).
fn triangulate(
    input: &Input,
    strategy: Strategy,
    precision: Precision,
    mode: Mode,
) -> Result<Outcome, String> {
    let nesting = input.nesting.to_polytri().unwrap_or(polytri::Nesting::Auto);
    let opts = Options::default()
        .with_strategy(strategy)
        .with_nesting(nesting)
        .with_lenient(mode == Mode::Lenient);
    let run = || {
        let mut out = Vec::new();
        let counted = |r: polytri::Report<'_>| {
            let mut dropped = BTreeMap::new();
            for d in r.dropped {
                *dropped.entry(format!("{:?}", d.reason)).or_insert(0) += 1;
            }
            let mut repairs = BTreeMap::new();
            for r in r.repairs {
                *repairs.entry(format!("{:?}", r.kind)).or_insert(0) += 1;
            }
            (dropped, repairs)
        };
        let report = match precision {
            Precision::F64 => Triangulator::<f64>::new()
                .triangulate(&input.vertices, &input.ring_starts, &opts, &mut out)
                .map(counted),
            Precision::F32 => Triangulator::<f32>::new()
                .triangulate(&input.vertices_f32(), &input.ring_starts, &opts, &mut out)
                .map(counted),
        };
        match report {
            Ok((dropped, repairs)) => Outcome {
                result: Ok(out),
                dropped,
                repairs,
            },
            Err(e) => Outcome {
                result: Err(e.to_string()),
                dropped: BTreeMap::new(),
                repairs: BTreeMap::new(),
            },
        }
    };
    catch_unwind(AssertUnwindSafe(run)).map_err(|payload| {
        payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic".to_owned())
    })
}

/// Whether every coordinate is an integer (no round-off in the deviation measure then).
fn integral(input: &Input) -> bool {
    input.vertices.iter().flatten().all(|c| c.fract() == 0.0)
}

/// What the input of a run is, as the run sees it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// A valid polygon set: strict must triangulate it validly.
    Valid,
    /// Invalid as given: strict must refuse, lenient stay within the bound.
    Invalid,
    /// Valid or not as given, invalid (differently) once rounded to f32: only recorded.
    RoundedInvalid,
}

/// A run of polytri and the oracle's verdict, before it is judged.
struct Executed {
    mode: Mode,
    panic: Option<String>,
    error: Option<String>,
    verdict: Option<Verdict>,
    triangles: Vec<[u32; 3]>,
    snap: RunSnapshot,
}

/// One precision and rotation of a case.
struct RunContext<'a> {
    rotated: &'a Input,
    seen: &'a Input,
    precision: Precision,
    rotation: u32,
    kind: Kind,
}

/// The context of one case × strategy replay.
struct Replayer<'a> {
    case: &'a CorpusCase,
    strategy: Strategy,
    opts: CheckOptions,
    /// The oracle's judgement of the input (any exact rotation), once known.
    input_valid: Option<bool>,
    /// The same for the input rounded to `f32`, where rounding changes it.
    rounded_valid: Option<bool>,
    failures: Vec<String>,
    runs: Vec<RunSnapshot>,
    lenient_deviation: BTreeMap<u32, f64>,
    /// Per rotation: whether any run exceeded earcut's own bound (known gaps).
    beyond_earcut: BTreeMap<u32, bool>,
    first_triangles: Option<Vec<[u32; 3]>>,
}

/// Replays `case` in `strategy`: every precision, rotation and mode it needs.
pub fn replay_case(case: &CorpusCase, strategy: Strategy) -> Replay {
    let opts = if case.input.vertices.len() < FULL_CHECKS_BELOW {
        CheckOptions::full()
    } else {
        CheckOptions::fast()
    };
    let mut r = Replayer {
        case,
        strategy,
        opts,
        input_valid: None,
        rounded_valid: None,
        failures: Vec::new(),
        runs: Vec::new(),
        lenient_deviation: BTreeMap::new(),
        beyond_earcut: BTreeMap::new(),
        first_triangles: None,
    };
    let mut rows = Vec::new();
    for precision in Precision::ALL {
        let (runs_before, failures_before) = (r.runs.len(), r.failures.len());
        for rotation in ROTATIONS {
            r.replay_rotation(precision, rotation);
        }
        if precision == Precision::F64 {
            r.check_expected_validity();
        } else {
            r.check_known_gaps();
        }
        rows.push(r.row(precision, runs_before, failures_before));
    }
    let input_valid = r.input_valid.unwrap_or(false);
    let known_failures = r.known_failures(&mut rows);
    let small = case.input.vertices.len() < LIST_TRIANGLES_BELOW;
    let triangle_list = r
        .first_triangles
        .take()
        .filter(|_| small)
        .map(|t| t.iter().map(|[a, b, c]| format!("{a} {b} {c}")).collect());
    Replay {
        snapshot: CaseSnapshot {
            case: case.id(),
            strategy: strategy_name(strategy),
            vertices: case.input.vertices.len(),
            rings: case.input.ring_count(),
            input_valid,
            triangle_list,
            runs: r.runs,
        },
        rows,
        failures: r.failures,
        known_failures,
        lenient_deviation: r.lenient_deviation,
    }
}

impl Replayer<'_> {
    fn tag(&self, precision: Precision, rotation: u32, mode: Mode) -> String {
        format!(
            "{} {} {precision} rot {rotation} {}",
            self.case.id(),
            strategy_name(self.strategy),
            match mode {
                Mode::Strict => "strict",
                Mode::Lenient => "lenient",
            }
        )
    }

    /// The runs of one precision and rotation: strict, and lenient for an invalid input.
    fn replay_rotation(&mut self, precision: Precision, rotation: u32) {
        let rotated = rotate(&self.case.input, rotation);
        let seen = match precision {
            Precision::F64 => rotated.clone(),
            Precision::F32 => rotated.to_f32(),
        };
        let exact = seen == rotated;
        let mut ctx = RunContext {
            rotated: &rotated,
            seen: &seen,
            precision,
            rotation,
            kind: Kind::Valid,
        };
        let strict = self.execute(&ctx, Mode::Strict);
        // Exact rotations keep validity, and rounding to f32 commutes with them: each is
        // judged once per case, by the first run's verdict where there is one.
        let cached = if exact {
            &mut self.input_valid
        } else {
            &mut self.rounded_valid
        };
        let valid = *cached.get_or_insert_with(|| match &strict.verdict {
            Some(v) => v.input_valid,
            None => check_with(&seen, &[], &CheckOptions::fast()).input_valid,
        });
        ctx.kind = match (valid, exact) {
            (true, _) => Kind::Valid,
            (false, true) => Kind::Invalid,
            (false, false) => Kind::RoundedInvalid,
        };
        self.finish(&ctx, strict);
        if ctx.kind == Kind::Invalid {
            let lenient = self.execute(&ctx, Mode::Lenient);
            self.finish(&ctx, lenient);
        }
    }

    /// One run of polytri, judged by the oracle when it made triangles.
    fn execute(&self, ctx: &RunContext<'_>, mode: Mode) -> Executed {
        let mut snap = RunSnapshot {
            precision: ctx.precision,
            rotation: ctx.rotation,
            mode,
            ..RunSnapshot::default()
        };
        let mut executed = Executed {
            mode,
            panic: None,
            error: None,
            verdict: None,
            triangles: Vec::new(),
            snap: RunSnapshot::default(),
        };
        match triangulate(ctx.rotated, self.strategy, ctx.precision, mode) {
            Err(panic) => executed.panic = Some(panic),
            Ok(outcome) => {
                snap.dropped = outcome.dropped;
                snap.repairs = outcome.repairs;
                match outcome.result {
                    Err(message) => executed.error = Some(message),
                    Ok(triangles) => {
                        let verdict = check_with(ctx.seen, &triangles, &self.opts);
                        record(&mut snap, &verdict, &triangles);
                        executed.verdict = Some(verdict);
                        executed.triangles = triangles;
                    }
                }
            }
        }
        executed.snap = snap;
        executed
    }

    /// Judges an executed run now that the kind of its input is known, and records it.
    fn finish(&mut self, ctx: &RunContext<'_>, executed: Executed) {
        let Executed {
            mode,
            panic,
            error,
            verdict,
            triangles,
            mut snap,
        } = executed;
        let tag = self.tag(ctx.precision, ctx.rotation, mode);
        if ctx.kind == Kind::RoundedInvalid {
            // The f32-rounded input crosses or collapses where the f64 one does not:
            // nothing to demand beyond finishing.
            snap.skipped = Some("f32 input invalid".into());
        }
        if let Some(panic) = panic {
            self.failures.push(format!("{tag}: panicked: {panic}"));
            snap.panic = Some(panic);
        } else if let Some(message) = error {
            self.judge_error(&tag, ctx.kind, mode, &message);
            snap.error = Some(message);
        } else if let Some(verdict) = verdict.filter(|_| ctx.kind != Kind::RoundedInvalid) {
            self.judge(&tag, &verdict, ctx, mode);
            if self.first_triangles.is_none() && !triangles.is_empty() {
                self.first_triangles = Some(triangles);
            }
        }
        self.runs.push(snap);
    }

    /// A refusal: right for an invalid input in strict mode, wrong otherwise.
    fn judge_error(&mut self, tag: &str, kind: Kind, mode: Mode, message: &str) {
        if mode == Mode::Lenient {
            self.failures
                .push(format!("{tag}: lenient mode returned an error: {message}"));
        } else if message.trim().is_empty() {
            self.failures
                .push(format!("{tag}: refused with an empty message"));
        } else if kind == Kind::Valid {
            self.failures
                .push(format!("{tag}: refused a valid input: {message}"));
        }
    }

    /// The demands on a run that made triangles.
    fn judge(&mut self, tag: &str, verdict: &Verdict, ctx: &RunContext<'_>, mode: Mode) {
        if ctx.kind == Kind::Valid {
            if !verdict.valid {
                self.failures.push(format!(
                    "{tag}: invalid triangulation of a valid input: {}",
                    verdict.failures().join("; ")
                ));
            }
            if let Some(n) = self
                .case
                .expect
                .triangles
                .filter(|&n| n != verdict.triangles)
            {
                self.failures.push(format!(
                    "{tag}: {} triangles, expect.triangles says {n}",
                    verdict.triangles
                ));
            }
        } else if mode == Mode::Strict {
            self.failures.push(format!(
                "{tag}: strict mode accepted an invalid input ({} triangles) instead of refusing it ({})",
                verdict.triangles,
                verdict.check("input").and_then(|c| c.detail.as_deref()).unwrap_or("?")
            ));
        }
        self.judge_deviation(tag, verdict, ctx, mode);
    }

    /// The deviation bound of earcut's fixtures (and `expect.max_deviation`).
    fn judge_deviation(&mut self, tag: &str, verdict: &Verdict, ctx: &RunContext<'_>, mode: Mode) {
        let rotation = ctx.rotation;
        let dev = verdict.deviation;
        let mut bound = match (&self.case.bounds, self.case.expect.max_deviation) {
            (Some(b), _) if b.earcut_triangles > 0 => {
                if dev > b.earcut_at(rotation) {
                    self.beyond_earcut.insert(rotation, true);
                }
                b.at(rotation)
            }
            (_, Some(max)) if mode == Mode::Lenient => max,
            _ => return,
        };
        if mode == Mode::Lenient {
            let worst = self.lenient_deviation.entry(rotation).or_insert(0.0);
            *worst = worst.max(dev);
        }
        if !integral(ctx.seen) {
            bound = bound.max(ROUND_OFF);
        }
        if let Some(gap) = self.known_gaps().find(|g| g.rotation == rotation) {
            bound = bound.max(gap.deviation);
        }
        if dev.is_nan() || dev > bound {
            self.failures
                .push(format!("{tag}: deviation {dev:e} > bound {bound:e}"));
        }
    }

    /// The [`KNOWN_GAPS`] of this case and strategy.
    fn known_gaps(&self) -> impl Iterator<Item = &'static KnownGap> {
        let id = self.case.id();
        let strategy = strategy_name(self.strategy);
        KNOWN_GAPS
            .iter()
            .filter(move |g| g.case == id && g.strategies.contains(&strategy))
    }

    /// `expect.input_valid` against the oracle (known once the f64 runs are done).
    fn check_expected_validity(&mut self) {
        let Some(expected) = self.case.expect.input_valid else {
            return;
        };
        let found = self.input_valid.unwrap_or(false);
        if expected != found {
            self.failures.push(format!(
                "{} {}: expect.input_valid is {expected}, the oracle finds the input {}",
                self.case.id(),
                strategy_name(self.strategy),
                if found { "valid" } else { "invalid" }
            ));
        }
    }

    /// For a case in [`KNOWN_FAILURES`]: its failures, now expected (and marked so in the
    /// rows), or a failure when it passes.
    fn known_failures(&mut self, rows: &mut [Row]) -> Vec<String> {
        let id = self.case.id();
        let strategy = strategy_name(self.strategy);
        let Some(known) = KNOWN_FAILURES
            .iter()
            .find(|k| k.case == id && k.strategies.contains(&strategy))
        else {
            return Vec::new();
        };
        if self.failures.is_empty() {
            self.failures.push(format!(
                "{id} {strategy}: passes now ({}): delete it from KNOWN_FAILURES in oracle/src/replay.rs",
                known.issue
            ));
            return Vec::new();
        }
        for row in rows.iter_mut().filter(|r| !r.passed) {
            row.passed = true;
            row.verdict = format!("known failure ({})", known.issue);
        }
        std::mem::take(&mut self.failures)
    }

    /// A known gap no run needs any more must be deleted (once every run is done).
    fn check_known_gaps(&mut self) {
        let id = self.case.id();
        let gaps: Vec<KnownGap> = self.known_gaps().copied().collect();
        for gap in gaps {
            if !self
                .beyond_earcut
                .get(&gap.rotation)
                .copied()
                .unwrap_or(false)
            {
                self.failures.push(format!(
                    "{id} {} rot {}: the known gap is closed (every run within earcut's bound): delete it from KNOWN_GAPS in oracle/src/replay.rs",
                    strategy_name(self.strategy),
                    gap.rotation
                ));
            }
        }
    }

    /// The table row of one precision from the runs and failures since the given marks.
    fn row(&self, precision: Precision, runs_from: usize, failures_from: usize) -> Row {
        let runs = &self.runs[runs_from..];
        let passed = self.failures.len() == failures_from;
        let judged = || runs.iter().filter(|r| r.skipped.is_none());
        let deviation = judged()
            .filter_map(|r| r.deviation)
            .fold(None, |m: Option<f64>, d| Some(m.map_or(d, |m| m.max(d))));
        let min_angle_deg = judged()
            .filter_map(|r| r.min_angle_deg)
            .fold(None, |m: Option<f64>, a| Some(m.map_or(a, |m| m.min(a))));
        let verdict = if !passed {
            format!("FAIL ({})", self.failures.len() - failures_from)
        } else if runs.iter().any(|r| r.skipped.is_some()) {
            "f32 input invalid".to_owned()
        } else if runs.iter().any(|r| r.mode == Mode::Lenient) {
            "refused, lenient ok".to_owned()
        } else if runs.iter().all(|r| r.error.is_some()) {
            "refused".to_owned()
        } else {
            "valid".to_owned()
        };
        Row {
            case: self.case.id(),
            strategy: strategy_name(self.strategy),
            precision,
            verdict,
            passed,
            deviation,
            min_angle_deg,
        }
    }
}

/// Fills a run's snapshot from its verdict.
fn record(snap: &mut RunSnapshot, verdict: &Verdict, triangles: &[[u32; 3]]) {
    snap.triangles = Some(triangles.len());
    snap.expected_triangles = verdict.expected_triangles;
    snap.valid = Some(verdict.valid);
    snap.failed_checks = verdict
        .checks
        .iter()
        .filter(|c| !c.passed)
        .map(|c| c.name.clone())
        .collect();
    snap.deviation = round_sig(verdict.deviation, 4);
    if !triangles.is_empty() {
        snap.min_angle_deg = round_sig(verdict.min_angle_deg, 5);
    }
    snap.cdt_min_angle_deg = verdict
        .cdt
        .as_ref()
        .and_then(|c| round_sig(c.min_angle_deg, 5));
    snap.triangles_fnv1a = Some(fnv1a(triangles));
}

/// Replays every case in both strategies, spread over the machine's threads; results in
/// case order, fast before quality.
pub fn replay_all(cases: &[CorpusCase]) -> Vec<Replay> {
    let mut jobs: Vec<(usize, Strategy)> = (0..cases.len())
        .flat_map(|c| STRATEGIES.map(|s| (c, s)))
        .collect();
    // Largest first, so no big case starts last.
    jobs.sort_by_key(|&(c, _)| std::cmp::Reverse(cases[c].input.vertices.len()));
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(jobs.len().max(1));
    let next = std::sync::atomic::AtomicUsize::new(0);
    let mut done: Vec<((usize, usize), Replay)> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..threads)
            .map(|_| {
                scope.spawn(|| {
                    let mut mine = Vec::new();
                    loop {
                        let j = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        let Some(&(c, strategy)) = jobs.get(j) else {
                            break;
                        };
                        let s = usize::from(strategy == Strategy::Quality);
                        mine.push(((c, s), replay_case(&cases[c], strategy)));
                    }
                    mine
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().unwrap_or_default())
            .collect()
    });
    done.sort_by_key(|(key, _)| *key);
    done.into_iter().map(|(_, r)| r).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Role;

    fn case(rings: &[Vec<[f64; 2]>], expect: Expect) -> CorpusCase {
        CorpusCase {
            folder: "cases".into(),
            name: "t".into(),
            input: Input::from_rings(rings, Nesting::Auto),
            expect,
            bounds: None,
        }
    }

    #[test]
    fn rotations_are_exact_quarter_turns() {
        let input = Input::from_rings(&[vec![[1.5, -2.0], [3.0, 4.0]]], Nesting::Auto);
        assert_eq!(rotate(&input, 90).vertices, [[2.0, 1.5], [-4.0, 3.0]]);
        assert_eq!(rotate(&input, 180).vertices, [[-1.5, 2.0], [-3.0, -4.0]]);
        assert_eq!(rotate(&input, 360), input);
    }

    #[test]
    fn fingerprints_and_rounding_are_stable() {
        assert_eq!(fnv1a(&[]), "cbf29ce484222325");
        assert_ne!(fnv1a(&[[0, 1, 2]]), fnv1a(&[[0, 2, 1]]));
        assert_eq!(round_sig(0.000_823_64, 2), Some(0.000_82));
        assert_eq!(round_sig(12.345_67, 5), Some(12.346));
        assert_eq!(round_sig(0.0, 4), Some(0.0));
        assert_eq!(round_sig(f64::NAN, 4), None);
    }

    #[test]
    fn reads_rings_and_shapes_json() {
        let rings = serde_json::json!([[[0, 0], [1, 0], [0, 1]]]);
        assert_eq!(
            input_from_array(&rings, None).unwrap().nesting,
            Nesting::FirstIsOuter
        );
        let shapes = serde_json::json!([[[[0, 0], [4, 0], [0, 4]], [[1, 1], [2, 1], [1, 2]]]]);
        let input = input_from_array(&shapes, None).unwrap();
        assert_eq!(input.nesting, Nesting::Roles(vec![Role::Outer, Role::Hole]));
        assert!(input_from_array(&serde_json::json!([1, 2]), None).is_err());
        let expect = Expect::from_json(Some(&serde_json::json!({"triangles": 2, "x": 1}))).unwrap();
        assert_eq!(expect.triangles, Some(2));
        assert!(Expect::from_json(Some(&serde_json::json!({"triangles": "two"}))).is_err());
    }

    #[test]
    fn judges_valid_and_crossing_inputs() {
        let square = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let good = case(
            std::slice::from_ref(&square),
            Expect {
                triangles: Some(2),
                ..Expect::default()
            },
        );
        let r = replay_case(&good, Strategy::Quality);
        assert!(r.failures.is_empty(), "{:?}", r.failures);
        assert_eq!(r.snapshot.runs.len(), 8);
        assert_eq!(r.snapshot.triangle_list.as_ref().map(Vec::len), Some(2));
        assert!(r.rows.iter().all(|row| row.verdict == "valid"));

        let wrong = case(
            &[square],
            Expect {
                triangles: Some(3),
                ..Expect::default()
            },
        );
        let r = replay_case(&wrong, Strategy::Fast);
        assert_eq!(r.failures.len(), 8, "{:?}", r.failures);
        assert!(r.rows.iter().all(|row| !row.passed));

        let bow_tie = case(
            &[vec![[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]],
            Expect::default(),
        );
        let r = replay_case(&bow_tie, Strategy::Fast);
        assert!(r.failures.is_empty(), "{:?}", r.failures);
        assert!(!r.snapshot.input_valid);
        assert_eq!(r.snapshot.runs.len(), 16, "strict and lenient per run");
        assert!(r
            .rows
            .iter()
            .all(|row| row.verdict == "refused, lenient ok"));
    }
}
