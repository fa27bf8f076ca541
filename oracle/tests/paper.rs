//! The paper's figures (`corpus/paper`) and the paper-shaped datasets (`corpus/datasets`):
//! valid inputs, so every run — both strategies, both precisions, strict and lenient — must
//! succeed, pass the oracle's exact checks and give the expected number of triangles.
//!
//! `corpus.rs` replays both folders too, in strict mode; here lenient mode runs on them as
//! well, the paper's figures also with every ring reversed and (earcut's convention) with
//! automatic nesting, each dataset's shapes also one at a time, and the report must list
//! no repairs and account for every vertex left out of the count.
//!
//! Failures are collected and reported together, one line each.

mod common;

use std::collections::HashMap;
use std::time::Duration;

use common::{assert_no_failures, corpus_dir, guarded_triangulate, seen, Run};
use polytri::{Dropped, Nesting as TriNesting, Options, Strategy};
use polytri_oracle::exact::strictly_inside_segment;
use polytri_oracle::gen::Case;
use polytri_oracle::replay::{load_file, rotate, Expect, Precision, ROTATIONS};
use polytri_oracle::{check_with, CheckOptions, Input, Nesting, Role};

const TIMEOUT: Duration = Duration::from_secs(300);
const STRATEGIES: [Strategy; 2] = [Strategy::Fast, Strategy::Quality];

/// One guarded run; a panic, hang or refusal as its failure line.
fn run(input: &Input, opts: Options, precision: Precision) -> Result<Run, String> {
    match guarded_triangulate(input, opts, precision, TIMEOUT) {
        Err(e) => Err(e),
        Ok(Err(e)) => Err(format!("Err({e:?}): {e}")),
        Ok(Ok(r)) => Ok(r),
    }
}

/// The oracle's failures for `triangles` over the coordinates a run in `precision` saw,
/// or the smallest angle when it finds none.
fn judge(input: &Input, precision: Precision, triangles: &[[u32; 3]]) -> Result<f64, String> {
    let verdict = check_with(&seen(input, precision), triangles, &CheckOptions::fast());
    if verdict.valid {
        Ok(verdict.min_angle_deg)
    } else {
        Err(verdict.failures().join("; "))
    }
}

/// Triangulates a valid input and judges the result: a panic, hang, refusal, invalid
/// result or reported repair is a failure line under `tag`. The run (for its count) and,
/// when valid, its smallest angle.
fn run_valid(
    input: &Input,
    opts: Options,
    precision: Precision,
    tag: &str,
    failures: &mut Vec<String>,
) -> Option<(Run, Option<f64>)> {
    let r = run(input, opts, precision)
        .map_err(|e| failures.push(format!("{tag}: {e}")))
        .ok()?;
    let min_angle_deg = judge(input, precision, &r.triangles)
        .map_err(|e| failures.push(format!("{tag}: invalid: {e}")))
        .ok();
    if r.repairs != 0 {
        failures.push(format!(
            "{tag}: {} repairs reported for a valid input",
            r.repairs
        ));
    }
    Some((r, min_angle_deg))
}

// ------------------------------------------------------------------------------------------
// corpus/paper
// ------------------------------------------------------------------------------------------

struct PaperCase {
    name: String,
    input: Input,
    triangles: usize,
}

fn paper_cases() -> Vec<PaperCase> {
    let dir = corpus_dir().join("paper");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .expect("corpus/paper")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".json"))
        .collect();
    names.sort();
    assert!(
        names.len() >= 10,
        "expected the paper cases in {}",
        dir.display()
    );
    names
        .into_iter()
        .map(|file| {
            let text = std::fs::read_to_string(dir.join(&file)).expect("paper case");
            let case = Case::from_json(&text).unwrap_or_else(|e| panic!("{file}: {e}"));
            let name = case.name;
            assert_eq!(format!("{name}.json"), file, "case name matches its file");
            for (field, value) in [("description", &case.description), ("source", &case.source)] {
                assert!(!value.is_empty(), "{name}: {field}");
            }
            assert!(
                matches!(case.input.nesting, Nesting::Auto | Nesting::FirstIsOuter),
                "{name}: nesting {:?}",
                case.input.nesting
            );
            let expect =
                Expect::from_json(case.expect.as_ref()).unwrap_or_else(|e| panic!("{name}: {e}"));
            PaperCase {
                name,
                input: case.input,
                triangles: expect.triangles.expect("expect.triangles"),
            }
        })
        .collect()
}

/// Every ring's winding reversed (its first point kept first).
fn reverse_windings(input: &Input) -> Input {
    let rings: Vec<Vec<[f64; 2]>> = input
        .rings()
        .into_iter()
        .map(|mut ring| {
            ring[1..].reverse();
            ring
        })
        .collect();
    Input::from_rings(&rings, input.nesting.clone())
}

/// Every paper case × rotations × windings × strategies × precisions × strict/lenient, with
/// its own nesting and (for `first-outer` cases) with `Auto` too. The oracle judges every
/// result with roles by containment depth.
#[test]
fn paper_cases_are_triangulated_validly() {
    let mut failures = Vec::new();
    for case in paper_cases() {
        // The hand-written roles agree with exact containment: the oracle finds the input
        // valid with them, and with roles by depth.
        let by_depth = Input {
            nesting: Nesting::Auto,
            ..case.input.clone()
        };
        for input in [&case.input, &by_depth] {
            let verdict = check_with(input, &[], &CheckOptions::fast());
            assert!(
                verdict.input_valid,
                "{}: roles: {:?}",
                case.name,
                verdict.failures()
            );
        }
        let mut nestings = vec![case
            .input
            .nesting
            .to_polytri()
            .expect("auto or first-outer")];
        if case.input.nesting == Nesting::FirstIsOuter {
            nestings.push(TriNesting::Auto);
        }
        for rotation in ROTATIONS {
            for reversed in [false, true] {
                let mut input = rotate(&by_depth, rotation);
                if reversed {
                    input = reverse_windings(&input);
                }
                for &nesting in &nestings {
                    for strategy in STRATEGIES {
                        for precision in Precision::ALL {
                            for lenient in [false, true] {
                                let tag = format!(
                                    "{} rot {rotation} {} {nesting:?} {strategy:?} {precision} {}",
                                    case.name,
                                    if reversed { "reversed" } else { "as-given" },
                                    if lenient { "lenient" } else { "strict" }
                                );
                                let opts = Options::default()
                                    .with_strategy(strategy)
                                    .with_nesting(nesting)
                                    .with_lenient(lenient);
                                let Some((r, _)) =
                                    run_valid(&input, opts, precision, &tag, &mut failures)
                                else {
                                    continue;
                                };
                                if r.triangles.len() != case.triangles {
                                    failures.push(format!(
                                        "{tag}: {} triangles, expected {} (dropped: {:?})",
                                        r.triangles.len(),
                                        case.triangles,
                                        r.dropped
                                    ));
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    assert_no_failures(&failures);
}

// ------------------------------------------------------------------------------------------
// corpus/datasets
// ------------------------------------------------------------------------------------------

/// Per ring, how many distinct positions of other vertices lie strictly inside its edges
/// (T-junctions, where shapes touch). Exact test by the oracle's predicate; a uniform grid
/// of cells about one mean edge long keeps it near-linear.
fn t_junctions(vertices: &[[f64; 2]], ring_starts: &[usize]) -> Vec<usize> {
    let n = vertices.len();
    let rings = ring_starts.len();
    let edges: Vec<(usize, usize, usize)> = (0..rings)
        .flat_map(|k| {
            let (s, e) = (ring_starts[k], ring_starts.get(k + 1).copied().unwrap_or(n));
            (s..e).map(move |i| (k, i, if i + 1 == e { s } else { i + 1 }))
        })
        .collect();
    let (mut x0, mut y0, mut x1, mut y1) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
    let mut total = 0.0;
    for &[x, y] in vertices {
        (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
    }
    for &(_, a, b) in &edges {
        let (p, q) = (vertices[a], vertices[b]);
        total += (q[0] - p[0]).abs() + (q[1] - p[1]).abs();
    }
    let cell = (total / edges.len().max(1) as f64).max(1e-9);
    let nx = (((x1 - x0) / cell) as usize + 1).min(4096);
    let ny = (((y1 - y0) / cell) as usize + 1).min(4096);
    let at = |x: f64, y: f64| {
        let i = (((x - x0) / cell) as usize).min(nx - 1);
        let j = (((y - y0) / cell) as usize).min(ny - 1);
        (i, j)
    };
    let mut grid: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    for (v, &[x, y]) in vertices.iter().enumerate() {
        grid.entry(at(x, y)).or_default().push(v);
    }
    let mut inserted = vec![0; rings];
    for &(k, a, b) in &edges {
        let (p, q) = (vertices[a], vertices[b]);
        let (lo, hi) = (
            at(p[0].min(q[0]), p[1].min(q[1])),
            at(p[0].max(q[0]), p[1].max(q[1])),
        );
        let mut found: Vec<[u64; 2]> = Vec::new();
        for i in lo.0..=hi.0 {
            for j in lo.1..=hi.1 {
                for &v in grid.get(&(i, j)).into_iter().flatten() {
                    let r = vertices[v];
                    let key = [r[0].to_bits(), r[1].to_bits()];
                    if strictly_inside_segment(p, q, r) && !found.contains(&key) {
                        found.push(key);
                    }
                }
            }
        }
        inserted[k] += found.len();
    }
    inserted
}

/// `INDEX.tsv`: file → (rings, holes, vertices, triangles).
fn dataset_index() -> HashMap<String, [usize; 4]> {
    let text = std::fs::read_to_string(corpus_dir().join("datasets/INDEX.tsv"))
        .expect("datasets/INDEX.tsv");
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().expect("header").split('\t').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).expect(name);
    let cols = [
        col("rings"),
        col("holes"),
        col("vertices"),
        col("triangles"),
    ];
    lines
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            (
                f[col("file")].to_string(),
                cols.map(|c| f[c].parse().expect("number")),
            )
        })
        .collect()
}

/// The count a valid triangulation must have given what was dropped:
/// Σ over outer rings (kept − 2) + Σ over holes (kept + 2), rings with < 3 kept vertices
/// left out. With nothing dropped this is Σ per polygon (n − 2 + 2h).
fn expected_count(ring_starts: &[usize], n: usize, roles: &[Role], dropped: &[Dropped]) -> usize {
    expected_count_with(ring_starts, n, roles, dropped, &[])
}

/// As [`expected_count`], plus `inserted[k]` vertices of other rings lying inside ring k's
/// edges: the triangulator splits those edges there, so ring k gains that many vertices.
fn expected_count_with(
    ring_starts: &[usize],
    n: usize,
    roles: &[Role],
    dropped: &[Dropped],
    inserted: &[usize],
) -> usize {
    let mut kept: Vec<usize> = (0..ring_starts.len())
        .map(|k| ring_starts.get(k + 1).copied().unwrap_or(n) - ring_starts[k])
        .collect();
    for d in dropped {
        kept[d.ring as usize] -= 1;
    }
    for (k, extra) in inserted.iter().enumerate() {
        kept[k] += extra;
    }
    let mut count = 0isize;
    for (k, &role) in kept.iter().zip(roles) {
        if *k >= 3 {
            count += *k as isize + if role == Role::Outer { -2 } else { 2 };
        }
    }
    count as usize
}

/// A dataset: each polygon's first ring outer, the rest its holes.
fn dataset(file: &str) {
    let path = corpus_dir().join("datasets").join(file);
    let input = load_file(&path, "datasets")
        .unwrap_or_else(|e| panic!("{e}"))
        .input;
    let Nesting::Roles(roles) = input.nesting.clone() else {
        panic!("{file}: shapes JSON gives one role per ring");
    };
    // The shapes again: each starts at an outer ring.
    let mut shapes: Vec<Vec<Vec<[f64; 2]>>> = Vec::new();
    for (ring, role) in input.rings().into_iter().zip(&roles) {
        match (role, shapes.last_mut()) {
            (Role::Hole, Some(shape)) => shape.push(ring),
            _ => shapes.push(vec![ring]),
        }
    }
    let index = dataset_index();
    let [rings_n, holes_n, vertices_n, triangles_n] = index[file];
    assert_eq!(input.ring_count(), rings_n, "{file}: INDEX rings");
    assert_eq!(
        roles.iter().filter(|r| **r == Role::Hole).count(),
        holes_n,
        "{file}: INDEX holes"
    );
    assert_eq!(input.vertices.len(), vertices_n, "{file}: INDEX vertices");
    assert_eq!(
        expected_count(&input.ring_starts, vertices_n, &roles, &[]),
        triangles_n,
        "{file}: INDEX triangles"
    );

    let inserted = t_junctions(&input.vertices, &input.ring_starts);

    let mut failures = Vec::new();
    let mut notes = Vec::new();
    // All rings at once, nesting found by the triangulator.
    for strategy in STRATEGIES {
        for precision in Precision::ALL {
            for lenient in [false, true] {
                let tag = format!(
                    "{file} all-rings Auto {strategy:?} {precision} {}",
                    if lenient { "lenient" } else { "strict" }
                );
                let opts = Options::default()
                    .with_strategy(strategy)
                    .with_lenient(lenient);
                let Some((r, min_angle_deg)) =
                    run_valid(&input, opts, precision, &tag, &mut failures)
                else {
                    continue;
                };
                if let Some(angle) = min_angle_deg {
                    notes.push(format!(
                        "{tag}: {} triangles, {} dropped, min angle {angle:.3}°",
                        r.triangles.len(),
                        r.dropped.len(),
                    ));
                }
                let want = expected_count_with(
                    &input.ring_starts,
                    input.vertices.len(),
                    &roles,
                    &r.dropped,
                    &inserted,
                );
                if r.triangles.len() != want {
                    failures.push(format!(
                        "{tag}: {} triangles, expected {want} (INDEX {triangles_n}, {} dropped)",
                        r.triangles.len(),
                        r.dropped.len()
                    ));
                }
            }
        }
    }
    // Each shape alone, earcut's convention.
    for strategy in STRATEGIES {
        let mut bad = 0;
        for (s, shape) in shapes.iter().enumerate() {
            let shape = Input::from_rings(shape, Nesting::FirstIsOuter);
            let roles: Vec<Role> = (0..shape.ring_count())
                .map(|k| if k == 0 { Role::Outer } else { Role::Hole })
                .collect();
            let opts = Options::default()
                .with_strategy(strategy)
                .with_nesting(TriNesting::FirstIsOuter);
            let tag = format!("{file} shape {s} FirstIsOuter {strategy:?} f64 strict");
            let problem = match run(&shape, opts, Precision::F64) {
                Err(e) => Some(e),
                Ok(r) => {
                    let n = shape.vertices.len();
                    let want = expected_count(&shape.ring_starts, n, &roles, &r.dropped);
                    match judge(&shape, Precision::F64, &r.triangles) {
                        Err(e) => Some(format!("invalid: {e}")),
                        Ok(_) if r.triangles.len() != want => {
                            Some(format!("{} triangles, expected {want}", r.triangles.len()))
                        }
                        Ok(_) => None,
                    }
                }
            };
            if let Some(p) = problem {
                bad += 1;
                if bad <= 10 {
                    failures.push(format!("{tag}: {p}"));
                }
            }
        }
        if bad > 10 {
            failures.push(format!(
                "{file} FirstIsOuter {strategy:?}: {} more shapes failed",
                bad - 10
            ));
        }
    }
    for n in &notes {
        eprintln!("note: {n}");
    }
    assert_no_failures(&failures);
}

#[test]
fn dataset_letter_a() {
    dataset("letter_a.json");
}

#[test]
fn dataset_lorem_latin() {
    dataset("lorem_latin.json");
}

#[test]
fn dataset_lorem_japanese() {
    dataset("lorem_japanese.json");
}

#[test]
fn dataset_lorem_japanese_noto() {
    dataset("lorem_japanese_noto.json");
}

#[test]
fn dataset_rect_circles() {
    dataset("rect_circles.json");
}

#[test]
fn dataset_chinese_text() {
    dataset("chinese_text.json");
}

#[test]
fn dataset_cjk_page() {
    dataset("cjk_page.json");
}

/// Every dataset file in `INDEX.tsv` has a test above.
#[test]
fn every_dataset_is_tested() {
    let mut files: Vec<String> = dataset_index().into_keys().collect();
    files.sort();
    let tested = [
        "chinese_text.json",
        "cjk_page.json",
        "letter_a.json",
        "lorem_japanese.json",
        "lorem_japanese_noto.json",
        "lorem_latin.json",
        "rect_circles.json",
    ];
    assert_eq!(files, tested);
}
