//! The bodies of the cargo-fuzz targets in `fuzz/`.
//!
//! Each target is one function from the fuzzer's bytes to `Ok(())` or a [`Finding`]; the
//! targets in `fuzz/fuzz_targets/` only panic on a finding. Keeping the bodies here means
//! stable `cargo test` replays the fuzz corpus, the crashes (`fuzz/artifacts`) and the kept
//! regressions (`fuzz/regressions`) through exactly the code the fuzzer ran
//! (`oracle/tests/fuzz_replay.rs`).
//!
//! Every finding carries the input as a corpus case, so its `Display` is a JSON file that
//! can be dropped into `corpus/cases/`.
//!
//! `raw_rings` and `nested_valid` also run the fast strategy on two threads, with
//! mark-and-cut lowered to rings of 16 nodes in chunks of 8, so that the fuzzed inputs
//! take its rounds and their ears straddle chunk boundaries.

use std::fmt;

use arbitrary::Unstructured;
use polytri::{FillRule, Nesting as TriNesting, Options, Strategy, Triangulator};

use crate::exact::{MAX_COORDINATE, MIN_COORDINATE};
use crate::gen::crossing::{generate_crossing, CrossingFamily};
use crate::gen::{generate, Case, Family, Params};
use crate::threaded::{self, KeptCoord};
use crate::{check, check_fill, check_with, CheckOptions, Input, Nesting};

/// A target body: the fuzzer's bytes to `Ok(())` or what was found.
pub type Target = fn(&[u8]) -> Result<(), Finding>;

/// The fuzz targets, by name, as `fuzz/Cargo.toml` lists them.
pub const TARGETS: [(&str, Target); 7] = [
    ("raw_rings", raw_rings),
    ("small_vs_pipeline", small_vs_pipeline),
    ("nested_valid", nested_valid),
    ("precision", precision),
    ("quality_vs_cdt", quality_vs_cdt),
    ("check_never_panics", check_never_panics),
    ("fill_rules", fill_rules),
];

/// Runs the target called `name` on `data`; `None` when there is no such target.
pub fn run_target(name: &str, data: &[u8]) -> Option<Result<(), Finding>> {
    TARGETS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, target)| target(data))
}

/// What a fuzz target found: which target, what went wrong, and the input as a corpus case.
#[derive(Clone, Debug)]
pub struct Finding {
    /// The target that found it.
    pub target: &'static str,
    /// What went wrong, in one line.
    pub what: String,
    /// The input, ready for `corpus/cases/` (boxed: findings are rare, results are not).
    pub case: Box<Case>,
}

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "fuzz target {}: {}", self.target, self.what)?;
        writeln!(f, "as a corpus case:")?;
        f.write_str(&self.case.to_json())
    }
}

/// The polytri options a target tries, with a label for messages.
#[derive(Clone, Copy, Debug)]
struct Run {
    strategy: Strategy,
    f32: bool,
    lenient: bool,
    /// Two threads, with mark-and-cut lowered as [`crate::threaded`] lowers it, so that
    /// fuzzed inputs (a few hundred vertices) take its rounds.
    threads: bool,
}

impl fmt::Display for Run {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:?} {} {}{}",
            self.strategy,
            if self.f32 { "f32" } else { "f64" },
            if self.lenient { "lenient" } else { "strict" },
            if self.threads {
                " on 2 threads (mark-and-cut)"
            } else {
                ""
            }
        )
    }
}

/// Triangulates `input` with polytri as `run` says; also whether every vertex was kept.
fn triangulate(
    input: &Input,
    nesting: TriNesting,
    run: Run,
) -> Result<(Vec<[u32; 3]>, bool), polytri::Error> {
    let opts = Options::default()
        .with_strategy(run.strategy)
        .with_nesting(nesting)
        .with_lenient(run.lenient)
        .with_threads(if run.threads { 2 } else { 1 });
    let mut out = Vec::new();
    let kept_all = if run.f32 {
        let vertices = input.vertices_f32();
        with_triangulator(run.threads, |tri| {
            let report = tri.triangulate(&vertices, &input.ring_starts, &opts, &mut out)?;
            Ok(report.dropped.is_empty())
        })?
    } else {
        with_triangulator(run.threads, |tri| {
            let report = tri.triangulate(&input.vertices, &input.ring_starts, &opts, &mut out)?;
            Ok(report.dropped.is_empty())
        })?
    };
    Ok((out, kept_all))
}

/// Calls `f` with this thread's kept two-thread triangulator when `threads`, else with a
/// new one.
fn with_triangulator<T: KeptCoord, R>(
    threads: bool,
    f: impl FnOnce(&mut Triangulator<T>) -> R,
) -> R {
    if threads {
        threaded::with_kept(2, f)
    } else {
        f(&mut Triangulator::new())
    }
}

/// Every combination of strategy, precision and mode, and the fast strategy's strict runs
/// on two threads (mark-and-cut; the quality strategy is sequential whatever the count,
/// and lenient mode clips valid input as strict mode does). Each round wakes the pool's
/// threads, which costs more than a small input's ear tests: two such runs, not four.
fn all_runs() -> impl Iterator<Item = Run> {
    [
        (Strategy::Fast, false),
        (Strategy::Quality, false),
        (Strategy::Fast, true),
    ]
    .into_iter()
    .flat_map(|(strategy, threads)| {
        [false, true].into_iter().flat_map(move |f32| {
            [false, true].into_iter().map(move |lenient| Run {
                strategy,
                f32,
                lenient,
                threads,
            })
        })
    })
    .filter(|run| !(run.threads && run.lenient))
}

/// Coordinates the oracle can judge exactly (finite, products neither overflow nor
/// underflow).
fn judgeable(input: &Input) -> bool {
    input.vertices.iter().flatten().all(|&c| {
        c.is_finite() && c.abs() <= MAX_COORDINATE && (c == 0.0 || c.abs() >= MIN_COORDINATE)
    })
}

/// A finding on `input`; `origin` is the generated case it came from, if any (its family
/// and seed travel along so the case can be regenerated).
fn finding(target: &'static str, what: String, origin: Option<&Case>, input: &Input) -> Finding {
    let name = match origin {
        Some(case) => format!("fuzz_{target}_{}", case.name.replace(['-', ' '], "_")),
        None => format!("fuzz_{target}"),
    };
    Finding {
        target,
        what: what.clone(),
        case: Box::new(Case {
            name,
            family: origin.and_then(|c| c.family),
            seed: origin.and_then(|c| c.seed),
            description: what,
            source: format!("fuzz:{target}"),
            input: input.clone(),
            expect: None,
        }),
    }
}

/// The input a target builds from `data`, as a corpus case: how a crash file becomes a
/// regression case (`polytri promote --fuzz-target`). `None` for an unknown target.
pub fn decode_case(target: &str, data: &[u8]) -> Option<Case> {
    let (input, origin) = match target {
        "raw_rings" | "small_vs_pipeline" => (decode_raw(data).0, None),
        "check_never_panics" => (decode_raw(check_split(data).0).0, None),
        "nested_valid" => {
            let case = generated(&mut Unstructured::new(data), NESTED_MAX);
            (case.input.clone(), Some(case))
        }
        "quality_vs_cdt" => {
            let case = generated(&mut Unstructured::new(data), CDT_MAX);
            (case.input.clone(), Some(case))
        }
        "precision" => {
            let (case, _, _) = precision_case(&mut Unstructured::new(data));
            (case.input.clone(), Some(case))
        }
        "fill_rules" => (fill_case(data).input, None),
        _ => return None,
    };
    let target = TARGETS.iter().find(|(n, _)| *n == target)?.0;
    let what = format!("decoded from a {target} fuzz input");
    Some(*finding(target, what, origin.as_ref(), &input).case)
}

// ---------------------------------------------------------------------------------------
// raw_rings

/// Decodes raw bytes into vertices and ring starts, nonsense included.
///
/// The first byte chooses how: coordinates as any `f64` or `f32` bit pattern (NaN,
/// infinities, subnormals, huge values), or as small integers (so that repeated,
/// collinear, touching and crossing vertices are common); ring starts as sensible ring
/// sizes or as any numbers at all.
pub fn decode_raw(data: &[u8]) -> (Input, bool) {
    let mut u = Unstructured::new(data);
    let flags = u.arbitrary::<u8>().unwrap_or(0);
    let f32 = flags & 1 != 0;
    let coords = (flags >> 1) & 3;
    let nonsense_starts = flags & 0x80 != 0;
    let rings = usize::from(u.arbitrary::<u8>().unwrap_or(0) % 8) + 1;
    let mut starts = Vec::with_capacity(rings);
    if nonsense_starts {
        for _ in 0..rings {
            starts.push(u.arbitrary::<u16>().map(usize::from).unwrap_or(0));
        }
    } else {
        let mut at = 0;
        for _ in 0..rings {
            starts.push(at);
            at += usize::from(u.arbitrary::<u8>().unwrap_or(0) % 16);
        }
    }
    let mut vertices = Vec::new();
    while !u.is_empty() && vertices.len() < 1024 {
        let point = match coords {
            0 if f32 => [
                f64::from(f32::from_bits(u.arbitrary().unwrap_or(0))),
                f64::from(f32::from_bits(u.arbitrary().unwrap_or(0))),
            ],
            0 => [
                f64::from_bits(u.arbitrary().unwrap_or(0)),
                f64::from_bits(u.arbitrary().unwrap_or(0)),
            ],
            1 => [
                f64::from(u.arbitrary::<i8>().unwrap_or(0) % 16),
                f64::from(u.arbitrary::<i8>().unwrap_or(0) % 16),
            ],
            2 => [
                f64::from(u.arbitrary::<i16>().unwrap_or(0)) / 64.0,
                f64::from(u.arbitrary::<i16>().unwrap_or(0)) / 64.0,
            ],
            _ => {
                // a small grid at a huge offset: rounding-sensitive in f32
                let e = i32::from(u.arbitrary::<u8>().unwrap_or(0) % 40);
                let off = 2f64.powi(e);
                [
                    off + f64::from(u.arbitrary::<i8>().unwrap_or(0)),
                    off + f64::from(u.arbitrary::<i8>().unwrap_or(0)),
                ]
            }
        };
        let point = if f32 {
            [f64::from(point[0] as f32), f64::from(point[1] as f32)]
        } else {
            point
        };
        vertices.push(point);
    }
    (
        Input {
            vertices,
            ring_starts: starts,
            nesting: Nesting::Auto,
        },
        f32,
    )
}

/// Target `raw_rings`: any bytes, through both strategies, strict and lenient, in the
/// precision the bytes choose, with both nesting conventions.
///
/// Must hold: no panic (the fuzzer sees it), lenient mode always returns a result, and any
/// result on an input the oracle calls valid passes the oracle.
pub fn raw_rings(data: &[u8]) -> Result<(), Finding> {
    const NAME: &str = "raw_rings";
    let (mut input, f32) = decode_raw(data);
    let judge = judgeable(&input);
    for (nesting, oracle_nesting) in [
        (TriNesting::Auto, Nesting::Auto),
        (TriNesting::FirstIsOuter, Nesting::FirstIsOuter),
    ] {
        input.nesting = oracle_nesting;
        for run in all_runs().filter(|r| r.f32 == f32) {
            match triangulate(&input, nesting, run) {
                Err(e) if run.lenient => {
                    return Err(finding(
                        NAME,
                        format!("{run}: lenient mode refused: {e}"),
                        None,
                        &input,
                    ))
                }
                Err(_) => {}
                Ok((triangles, _)) => {
                    if !judge {
                        continue;
                    }
                    let verdict = check_with(&input, &triangles, &CheckOptions::fast());
                    if verdict.input_valid && !verdict.valid {
                        return Err(finding(
                            NAME,
                            format!("{run}: {}", verdict.failures().join("; ")),
                            None,
                            &input,
                        ));
                    }
                }
            }
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------
// small_vs_pipeline

/// What one call gives, owned, to compare two triangulators' calls.
#[derive(Debug, PartialEq)]
struct Outcome {
    triangles: Vec<[u32; 3]>,
    polygons: usize,
    holes: usize,
    deviation: u64,
    dropped: Vec<polytri::Dropped>,
    repairs: Vec<polytri::Repair>,
}

/// One call of `tri`, owned (the deviation by its bits: the two must agree exactly).
fn outcome<T: polytri::Coord>(
    tri: &mut Triangulator<T>,
    vertices: &[[T; 2]],
    starts: &[usize],
    options: &Options,
) -> Result<Outcome, polytri::Error> {
    let mut triangles = Vec::new();
    let report = tri.triangulate(vertices, starts, options, &mut triangles)?;
    Ok(Outcome {
        triangles,
        polygons: report.polygons,
        holes: report.holes,
        deviation: report.deviation.to_bits(),
        dropped: report.dropped.to_vec(),
        repairs: report.repairs.to_vec(),
    })
}

/// The first call on which a triangulator taking the small stage and one never taking it
/// disagree: both strategies, strict and lenient, both nesting conventions, and the check.
fn stage_disagrees<T: polytri::Coord + fmt::Debug>(
    vertices: &[[T; 2]],
    starts: &[usize],
) -> Option<String> {
    let mut with = Triangulator::<T>::new();
    let mut without = Triangulator::<T>::new();
    without.set_small_rings(false);
    for nesting in [TriNesting::Auto, TriNesting::FirstIsOuter] {
        for strategy in [Strategy::Fast, Strategy::Quality] {
            for lenient in [false, true] {
                let options = Options::default()
                    .with_strategy(strategy)
                    .with_nesting(nesting)
                    .with_lenient(lenient);
                let (a, b) = (
                    outcome(&mut with, vertices, starts, &options),
                    outcome(&mut without, vertices, starts, &options),
                );
                if a != b {
                    let mode = if lenient { "lenient" } else { "strict" };
                    return Some(format!(
                        "{strategy:?} {mode} {nesting:?}: with the small stage {a:?}, \
                         through the pipeline {b:?}"
                    ));
                }
            }
        }
        let (a, b) = (
            with.check(vertices, starts, nesting),
            without.check(vertices, starts, nesting),
        );
        if a != b {
            return Some(format!(
                "check {nesting:?}: with the small stage {a:?}, through the pipeline {b:?}"
            ));
        }
    }
    None
}

/// Target `small_vs_pipeline`: any bytes as rings (as `raw_rings` decodes them), through a
/// triangulator that may take the small stage and one that never does.
///
/// Must hold: the two give the same triangles in the same order, the same report (dropped
/// vertices, repairs, deviation to the bit) and the same errors, in both strategies,
/// strict and lenient, both nesting conventions, and the same check — the stage's promise
/// (`core/src/stages/small`), which the stage's own tests hold on generated families.
/// Coordinates of any size are compared: beyond the range where polytri's signs are
/// exact, strict mode refuses the input (`CoordinateRange`) and the stage hands it back,
/// so that the two paths ask the same questions.
pub fn small_vs_pipeline(data: &[u8]) -> Result<(), Finding> {
    const NAME: &str = "small_vs_pipeline";
    let (input, f32) = decode_raw(data);
    let disagreement = if f32 {
        stage_disagrees(&input.vertices_f32(), &input.ring_starts)
    } else {
        stage_disagrees(&input.vertices, &input.ring_starts)
    };
    match disagreement {
        Some(what) => Err(finding(NAME, what, None, &input)),
        None => Ok(()),
    }
}

// ---------------------------------------------------------------------------------------
// generated inputs

/// A generated case chosen by the fuzzer's bytes: family, seed, size and placement.
fn generated(u: &mut Unstructured<'_>, max_vertices: usize) -> Case {
    let family = Family::ALL[usize::from(u.arbitrary::<u8>().unwrap_or(0)) % Family::ALL.len()];
    let seed = u.arbitrary::<u64>().unwrap_or(0);
    let size = 3 + usize::from(u.arbitrary::<u16>().unwrap_or(0)) % max_vertices.max(1);
    generate(family, seed, &Params::new(size))
}

/// Target `nested_valid`: the generators' valid nested polygons must triangulate, in every
/// strategy, precision and mode, and pass the oracle (in f32 wherever the f32-rounded input
/// is still valid).
pub fn nested_valid(data: &[u8]) -> Result<(), Finding> {
    const NAME: &str = "nested_valid";
    let mut u = Unstructured::new(data);
    let case = generated(&mut u, NESTED_MAX);
    let input = &case.input;
    let rounded = input.to_f32();
    let f32_valid = check_with(&rounded, &[], &CheckOptions::fast()).input_valid;
    for run in all_runs() {
        if run.f32 && !f32_valid {
            continue;
        }
        let judged = if run.f32 { &rounded } else { input };
        match triangulate(input, TriNesting::Auto, run) {
            Err(e) => {
                return Err(finding(
                    NAME,
                    format!("{run}: refused a valid input: {e}"),
                    Some(&case),
                    judged,
                ))
            }
            Ok((triangles, _)) => {
                let verdict = check_with(judged, &triangles, &CheckOptions::fast());
                if !verdict.valid {
                    return Err(finding(
                        NAME,
                        format!("{run}: {}", verdict.failures().join("; ")),
                        Some(&case),
                        judged,
                    ));
                }
            }
        }
    }
    Ok(())
}

/// The largest generated cases `nested_valid` and `quality_vs_cdt` ask for: small enough
/// for thousands of executions per second.
const NESTED_MAX: usize = 400;
const CDT_MAX: usize = 300;

/// `precision`'s case: a small generated polygon at the scale and offset the bytes choose.
fn precision_case(u: &mut Unstructured<'_>) -> (Case, f64, f64) {
    let family = Family::ALL[usize::from(u.arbitrary::<u8>().unwrap_or(0)) % Family::ALL.len()];
    let seed = u.arbitrary::<u64>().unwrap_or(0);
    let size = 3 + usize::from(u.arbitrary::<u8>().unwrap_or(0));
    let scale = 10f64.powi(i32::from(u.arbitrary::<u8>().unwrap_or(0) % 13) - 3);
    let offset = match u.arbitrary::<u8>().unwrap_or(0) % 7 {
        0 => 0.0,
        k => 10f64.powi(i32::from(k) + 2),
    };
    let params = Params::new(size)
        .with_scale(scale)
        .with_offset([offset, -offset]);
    (generate(family, seed, &params), scale, offset)
}

/// Target `precision`: one generated polygon at a scale (10⁻³ … 10⁹) and offset (0,
/// 10³ … 10⁸) the bytes choose. Scaling by a power of ten and moving far from the origin
/// round the coordinates, which can make thin parts cross, so the oracle judges the input
/// in each precision first: where it is valid, strict mode must triangulate it validly
/// (in f32, valid in the f32 coordinates); where it is not, strict mode must refuse it.
pub fn precision(data: &[u8]) -> Result<(), Finding> {
    const NAME: &str = "precision";
    let (case, scale, offset) = precision_case(&mut Unstructured::new(data));
    let rounded = case.input.to_f32();
    let valid = |input: &Input| check_with(input, &[], &CheckOptions::fast()).input_valid;
    let (f64_valid, f32_valid) = (valid(&case.input), valid(&rounded));
    for strategy in [Strategy::Fast, Strategy::Quality] {
        for f32 in [false, true] {
            let run = Run {
                strategy,
                f32,
                lenient: false,
                threads: false,
            };
            let (judged, input_valid) = if f32 {
                (&rounded, f32_valid)
            } else {
                (&case.input, f64_valid)
            };
            let what = match triangulate(&case.input, TriNesting::Auto, run) {
                Err(_) if !input_valid => continue,
                Err(e) => format!("{run} at scale {scale:e}, offset {offset:e}: refused: {e}"),
                Ok((triangles, _)) => {
                    let verdict = check_with(judged, &triangles, &CheckOptions::fast());
                    if verdict.valid {
                        continue;
                    }
                    format!(
                        "{run} at scale {scale:e}, offset {offset:e}: {}",
                        verdict.failures().join("; ")
                    )
                }
            };
            return Err(finding(NAME, what, Some(&case), judged));
        }
    }
    Ok(())
}

/// Target `quality_vs_cdt`: the quality strategy against spade's constrained Delaunay
/// triangulation of the same rings. Same area and, where polytri kept every vertex, the
/// same count, and a minimum angle never above the CDT's: the CDT maximises the minimum
/// angle over all triangulations of the same vertices and boundary, so a larger one means
/// a broken triangulation or a broken oracle.
pub fn quality_vs_cdt(data: &[u8]) -> Result<(), Finding> {
    const NAME: &str = "quality_vs_cdt";
    let mut u = Unstructured::new(data);
    let case = generated(&mut u, CDT_MAX);
    let run = Run {
        strategy: Strategy::Quality,
        f32: false,
        lenient: false,
        threads: false,
    };
    let (triangles, kept_all) = match triangulate(&case.input, TriNesting::Auto, run) {
        Ok(result) => result,
        Err(e) => {
            return Err(finding(
                NAME,
                format!("{run}: refused: {e}"),
                Some(&case),
                &case.input,
            ))
        }
    };
    let opts = CheckOptions {
        geo: false,
        cdt: true,
    };
    let verdict = check_with(&case.input, &triangles, &opts);
    let mut problems = verdict.failures();
    match &verdict.cdt {
        None => problems.push("no CDT comparison".to_owned()),
        Some(cdt) => {
            let area = cdt.area;
            let ours: f64 = triangle_area(&case.input, &triangles);
            if (area - ours).abs() > 1e-9 * area.abs().max(ours.abs()) {
                problems.push(format!("area {ours} but the CDT's is {area}"));
            }
            if kept_all {
                if cdt.triangles != verdict.triangles {
                    problems.push(format!(
                        "{} triangles but the CDT has {}",
                        verdict.triangles, cdt.triangles
                    ));
                }
                if verdict.min_angle_deg > cdt.min_angle_deg + 1e-9 {
                    problems.push(format!(
                        "minimum angle {}° above the CDT's {}°",
                        verdict.min_angle_deg, cdt.min_angle_deg
                    ));
                }
            }
        }
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(finding(NAME, problems.join("; "), Some(&case), &case.input))
    }
}

/// Splits `check_never_panics`'s bytes into the input's part and the triangles' part.
fn check_split(data: &[u8]) -> (&[u8], &[u8]) {
    let split = usize::from(data.first().copied().unwrap_or(0)) * 2;
    data.split_at(split.min(data.len()))
}

/// The summed area of `triangles` (floating point, for comparison with the CDT's).
fn triangle_area(input: &Input, triangles: &[[u32; 3]]) -> f64 {
    let at = |i: u32| {
        input
            .vertices
            .get(i as usize)
            .copied()
            .unwrap_or([0.0, 0.0])
    };
    triangles
        .iter()
        .map(|t| {
            let (a, b, c) = (at(t[0]), at(t[1]), at(t[2]));
            0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
        })
        .sum()
}

/// Target `check_never_panics`: the oracle itself on garbage — any input `raw_rings`
/// decodes, and triangles made of any indices. It must not panic, and its verdict must be
/// consistent: valid exactly when every check passed, and never valid with an index out of
/// range.
pub fn check_never_panics(data: &[u8]) -> Result<(), Finding> {
    const NAME: &str = "check_never_panics";
    let (rings, tris) = check_split(data);
    let (input, _) = decode_raw(rings);
    let mut u = Unstructured::new(tris);
    let n = input.vertices.len() as u32;
    let mut triangles = Vec::new();
    while !u.is_empty() && triangles.len() < 512 {
        let mut t = [0u32; 3];
        for i in &mut t {
            let raw = u.arbitrary::<u16>().unwrap_or(0);
            // mostly in range, sometimes far out
            *i = if raw & 0x8000 != 0 {
                u32::from(raw) * 65_537
            } else {
                u32::from(raw) % n.max(1)
            };
        }
        triangles.push(t);
    }
    let verdict = check(&input, &triangles);
    let all_passed = verdict.checks.iter().all(|c| c.passed);
    let out_of_range = triangles.iter().flatten().any(|&i| i >= n);
    let what = if verdict.valid != all_passed {
        format!(
            "verdict valid = {} but every check passed = {all_passed}",
            verdict.valid
        )
    } else if verdict.valid && out_of_range {
        "valid verdict with a triangle index out of range".to_owned()
    } else {
        return Ok(());
    };
    Err(finding(NAME, what, None, &input))
}

// ---------------------------------------------------------------------------------------
// fill_rules

/// The largest generated cases `fill_rules` asks for: crossings grow quadratically in the
/// worst families, and `check_fill` must judge every input well within libFuzzer's timeout.
const FILL_MAX: usize = 64;
/// At most this many bytes of `fill_rules`' raw rings are decoded (up to about 60
/// vertices), for the same reason.
const FILL_RAW_BYTES: usize = 128;

/// What `fill_rules` triangulates, as the fuzzer's bytes choose it.
#[derive(Clone, Debug)]
pub struct FillCase {
    /// The rings (as generated or decoded; rounded to `f32` only when run).
    pub input: Input,
    /// Where the rings come from: a crossing family with its seed and size, or raw bytes.
    pub origin: String,
    /// The fill rule.
    pub rule: FillRule,
    /// The ear-clipping strategy.
    pub strategy: Strategy,
    /// Whether to triangulate in `f32` (else `f64`).
    pub f32: bool,
}

impl fmt::Display for FillCase {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} {:?} {} on {}",
            self.rule.name(),
            self.strategy,
            if self.f32 { "f32" } else { "f64" },
            self.origin
        )
    }
}

/// Decodes `fill_rules`' bytes: a rule, a strategy and precision, and either a
/// [`CrossingFamily`] case (seed, size below 64) or raw rings as [`decode_raw`] reads them
/// (about two in nine inputs).
pub fn fill_case(data: &[u8]) -> FillCase {
    let mut u = Unstructured::new(data);
    let rule = FillRule::ALL[usize::from(u.arbitrary::<u8>().unwrap_or(0)) % FillRule::ALL.len()];
    let flags = u.arbitrary::<u8>().unwrap_or(0);
    let strategy = if flags & 1 == 0 {
        Strategy::Fast
    } else {
        Strategy::Quality
    };
    let f32 = flags & 2 != 0;
    let families = CrossingFamily::ALL.len();
    let source = usize::from(flags >> 2) % (families + 2);
    let (input, origin) = match CrossingFamily::ALL.get(source) {
        Some(&family) => {
            let seed = u.arbitrary::<u64>().unwrap_or(0);
            let size = usize::from(u.arbitrary::<u16>().unwrap_or(0)) % FILL_MAX;
            let (vertices, ring_starts) = generate_crossing(family, seed, size);
            (
                Input::new(vertices, ring_starts, Nesting::Auto),
                format!("{family} seed {seed} size {size}"),
            )
        }
        None => {
            let rest = u.take_rest();
            let (input, _) = decode_raw(&rest[..rest.len().min(FILL_RAW_BYTES)]);
            (input, "raw rings".to_owned())
        }
    };
    FillCase {
        input,
        origin,
        rule,
        strategy,
        f32,
    }
}

/// What a triangulation with a fill rule gave.
struct FillRun {
    triangles: Vec<[u32; 3]>,
    /// The added vertices, widened to `f64`.
    added: Vec<[f64; 2]>,
    /// What is wrong with the report: added vertices numbered out of order, naming edges
    /// that do not exist, or differing from `added_vertices()`.
    problems: Vec<String>,
}

/// Triangulates `vertices` with `options` (a fill rule).
fn fill_triangulate<T: polytri::Coord>(
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    options: &Options,
    widen: impl Fn(T) -> f64,
) -> Result<FillRun, polytri::Error> {
    let mut tri = Triangulator::<T>::new();
    let mut out = Vec::new();
    let report = tri.triangulate(vertices, ring_starts, options, &mut out)?;
    let added: Vec<polytri::Added> = report.added.to_vec();
    let n = vertices.len();
    let mut problems = Vec::new();
    for (k, a) in added.iter().enumerate() {
        if a.vertex as usize != n + k {
            problems.push(format!(
                "added vertex {k} is numbered {}, not {}",
                a.vertex,
                n + k
            ));
        }
        if a.edges.iter().any(|&e| e as usize >= n) {
            problems.push(format!("added vertex {k} names edges {:?} of {n}", a.edges));
        }
    }
    let positions: Vec<[f64; 2]> = added.iter().map(|a| a.position).collect();
    let typed: Vec<[f64; 2]> = (tri.added_vertices().iter())
        .map(|&[x, y]| [widen(x), widen(y)])
        .collect();
    if typed != positions {
        problems.push("added_vertices() differs from Report::added".to_owned());
    }
    Ok(FillRun {
        triangles: out,
        added: positions,
        problems,
    })
}

/// Target `fill_rules`: crossing input (a [`CrossingFamily`] case or raw rings) under one
/// of the five fill rules, in the strategy and precision the bytes choose.
///
/// Must hold: the triangulation passes [`check_fill`] (on the input as triangulated, so in
/// `f32` on the rounded coordinates), the added vertices are reported consistently, and
/// the only refusals are of bad numbers (`NonFinite`, `CoordinateRange`) or malformed ring
/// starts and sizes. Any other error — above all `Error::Internal` — is a finding.
pub fn fill_rules(data: &[u8]) -> Result<(), Finding> {
    use polytri::Error;
    const NAME: &str = "fill_rules";
    let case = fill_case(data);
    let options = Options::new()
        .with_strategy(case.strategy)
        .with_fill_rule(case.rule);
    let (judged, result) = if case.f32 {
        let result = fill_triangulate(
            &case.input.vertices_f32(),
            &case.input.ring_starts,
            &options,
            f64::from,
        );
        (case.input.to_f32(), result)
    } else {
        let result = fill_triangulate(
            &case.input.vertices,
            &case.input.ring_starts,
            &options,
            |x| x,
        );
        (case.input.clone(), result)
    };
    let what = match result {
        Err(
            Error::NonFinite { .. }
            | Error::CoordinateRange { .. }
            | Error::FirstRingStart { .. }
            | Error::RingStartsNotIncreasing { .. }
            | Error::RingStartOutOfRange { .. }
            | Error::TooManyVertices { .. },
        ) => return Ok(()),
        Err(e) => format!("{case}: refused: {e} ({e:?})"),
        // no vertices, nothing to cover: the ring starts do not matter (as without a rule)
        Ok(run) if judged.vertices.is_empty() && run.triangles.is_empty() => return Ok(()),
        Ok(FillRun {
            triangles,
            added,
            mut problems,
        }) => {
            let verdict = check_fill(
                &judged.vertices,
                &judged.ring_starts,
                case.rule,
                &added,
                &triangles,
            );
            if !verdict.valid {
                let failures = verdict.failures();
                if failures.is_empty() {
                    problems.push("check_fill: invalid".to_owned());
                }
                problems.extend(failures);
            }
            if problems.is_empty() {
                return Ok(());
            }
            format!("{case}: {}", problems.join("; "))
        }
    };
    Err(finding(NAME, what, None, &judged))
}
