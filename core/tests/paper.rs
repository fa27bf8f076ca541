//! The paper's figures (`corpus/paper`) and the paper-shaped datasets (`corpus/datasets`):
//! valid inputs, so every run — both strategies, both precisions, strict and lenient — must
//! succeed, pass the exact validity check and give the expected number of triangles.
//!
//! Failures are collected and reported together, one line each.

mod common;

use std::collections::HashMap;
use std::time::Duration;

use common::{
    check_with_roles, first_is_outer, flatten, guarded, read_json, reverse_windings,
    rings_from_json, roles_by_containment, rotate, shape_roles, shapes_from_json, to_f32, widen,
    Rings, Role,
};
use polytri::{Dropped, Nesting, Options, Strategy, Triangulator};

const TIMEOUT: Duration = Duration::from_secs(300);
const STRATEGIES: [Strategy; 2] = [Strategy::Fast, Strategy::Quality];

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Precision {
    F64,
    F32,
}
const PRECISIONS: [Precision; 2] = [Precision::F64, Precision::F32];

/// What one run gave: triangles and the report's dropped vertices and repair count.
struct Run {
    triangles: Vec<[u32; 3]>,
    dropped: Vec<Dropped>,
    repairs: usize,
}

fn run(
    vertices: Vec<[f64; 2]>,
    ring_starts: Vec<usize>,
    opts: Options,
    precision: Precision,
) -> Result<Result<Run, polytri::Error>, String> {
    guarded(TIMEOUT, move || {
        let mut out = Vec::new();
        let report = match precision {
            Precision::F64 => {
                let mut tri = Triangulator::<f64>::new();
                let r = tri.triangulate(&vertices, &ring_starts, &opts, &mut out)?;
                (r.dropped.to_vec(), r.repairs.len())
            }
            Precision::F32 => {
                let mut tri = Triangulator::<f32>::new();
                let r = tri.triangulate(&to_f32(&vertices), &ring_starts, &opts, &mut out)?;
                (r.dropped.to_vec(), r.repairs.len())
            }
        };
        Ok(Run {
            triangles: out,
            dropped: report.0,
            repairs: report.1,
        })
    })
}

/// The coordinates a run in `precision` sees, as `f64`.
fn seen(vertices: &[[f64; 2]], precision: Precision) -> Vec<[f64; 2]> {
    match precision {
        Precision::F64 => vertices.to_vec(),
        Precision::F32 => widen(&to_f32(vertices)),
    }
}

// ------------------------------------------------------------------------------------------
// corpus/paper
// ------------------------------------------------------------------------------------------

struct Case {
    name: String,
    nesting: Nesting,
    rings: Rings,
    triangles: usize,
}

fn paper_cases() -> Vec<Case> {
    let dir = common::corpus_dir().join("paper");
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
            let v = read_json(&format!("paper/{file}"));
            let name = v["name"].as_str().expect("name").to_string();
            assert_eq!(format!("{name}.json"), file, "case name matches its file");
            for field in ["description", "source"] {
                assert!(
                    v[field].as_str().is_some_and(|s| !s.is_empty()),
                    "{name}: {field}"
                );
            }
            let nesting = match v["nesting"].as_str().expect("nesting") {
                "auto" => Nesting::Auto,
                "first-outer" => Nesting::FirstIsOuter,
                other => panic!("{name}: unknown nesting {other:?}"),
            };
            Case {
                name,
                nesting,
                rings: rings_from_json(&v["rings"]),
                triangles: v["expect"]["triangles"].as_u64().expect("expect.triangles") as usize,
            }
        })
        .collect()
}

/// Every paper case × rotations × windings × strategies × precisions × strict/lenient, with
/// its own nesting and (for `first-outer` cases) with `Auto` too.
#[test]
fn paper_cases_are_triangulated_validly() {
    let mut failures = Vec::new();
    for case in paper_cases() {
        // The hand-written roles agree with exact containment.
        let flat0 = flatten(&case.rings);
        let by_containment = roles_by_containment(&flat0.vertices, &flat0.rings);
        if case.nesting == Nesting::FirstIsOuter {
            assert_eq!(
                by_containment,
                first_is_outer(flat0.rings.len()),
                "{}: roles",
                case.name
            );
        }
        let mut nestings = vec![case.nesting];
        if case.nesting == Nesting::FirstIsOuter {
            nestings.push(Nesting::Auto);
        }
        for rotation in 0..4 {
            for reversed in [false, true] {
                let mut rings = rotate(&case.rings, rotation);
                if reversed {
                    rings = reverse_windings(&rings);
                }
                let flat = flatten(&rings);
                let roles = roles_by_containment(&flat.vertices, &flat.rings);
                for &nesting in &nestings {
                    for strategy in STRATEGIES {
                        for precision in PRECISIONS {
                            for lenient in [false, true] {
                                let tag = format!(
                                    "{} rot {} {} {nesting:?} {strategy:?} {precision:?} {}",
                                    case.name,
                                    rotation * 90,
                                    if reversed { "reversed" } else { "as-given" },
                                    if lenient { "lenient" } else { "strict" }
                                );
                                let opts = Options::default()
                                    .with_strategy(strategy)
                                    .with_nesting(nesting)
                                    .with_lenient(lenient);
                                let r = match run(
                                    flat.vertices.clone(),
                                    flat.ring_starts.clone(),
                                    opts,
                                    precision,
                                ) {
                                    Err(e) => {
                                        failures.push(format!("{tag}: {e}"));
                                        continue;
                                    }
                                    Ok(Err(e)) => {
                                        failures.push(format!("{tag}: Err({e:?}): {e}"));
                                        continue;
                                    }
                                    Ok(Ok(r)) => r,
                                };
                                let v = seen(&flat.vertices, precision);
                                if let Err(e) =
                                    check_with_roles(&v, &flat.rings, &roles, &r.triangles)
                                {
                                    failures.push(format!("{tag}: invalid: {e}"));
                                }
                                if r.triangles.len() != case.triangles {
                                    failures.push(format!(
                                        "{tag}: {} triangles, expected {} (dropped: {:?})",
                                        r.triangles.len(),
                                        case.triangles,
                                        r.dropped
                                    ));
                                }
                                if r.repairs != 0 {
                                    failures.push(format!(
                                        "{tag}: {} repairs reported for a valid input",
                                        r.repairs
                                    ));
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failure(s):\n{}",
        failures.len(),
        failures.join("\n")
    );
}

// ------------------------------------------------------------------------------------------
// corpus/datasets
// ------------------------------------------------------------------------------------------

/// Per ring, how many distinct positions of other vertices lie strictly inside its edges
/// (T-junctions, where shapes touch). Exact test with `robust`; a uniform grid of cells
/// about one mean edge long keeps it near-linear.
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
                    if r == p || r == q {
                        continue;
                    }
                    let inside_box = r[0] >= p[0].min(q[0])
                        && r[0] <= p[0].max(q[0])
                        && r[1] >= p[1].min(q[1])
                        && r[1] <= p[1].max(q[1]);
                    let on_line = robust::orient2d(
                        robust::Coord { x: p[0], y: p[1] },
                        robust::Coord { x: q[0], y: q[1] },
                        robust::Coord { x: r[0], y: r[1] },
                    ) == 0.0;
                    let key = [r[0].to_bits(), r[1].to_bits()];
                    if inside_box && on_line && !found.contains(&key) {
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
    let text = std::fs::read_to_string(common::corpus_dir().join("datasets/INDEX.tsv"))
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

fn dataset(file: &str) {
    let shapes = shapes_from_json(&read_json(&format!("datasets/{file}")));
    let index = dataset_index();
    let [rings_n, holes_n, vertices_n, triangles_n] = index[file];
    let all: Rings = shapes.iter().flatten().cloned().collect();
    let flat = flatten(&all);
    let roles = shape_roles(&shapes);
    assert_eq!(flat.rings.len(), rings_n, "{file}: INDEX rings");
    assert_eq!(
        roles.iter().filter(|r| **r == Role::Hole).count(),
        holes_n,
        "{file}: INDEX holes"
    );
    assert_eq!(flat.vertices.len(), vertices_n, "{file}: INDEX vertices");
    assert_eq!(
        expected_count(&flat.ring_starts, vertices_n, &roles, &[]),
        triangles_n,
        "{file}: INDEX triangles"
    );

    let inserted = t_junctions(&flat.vertices, &flat.ring_starts);

    let mut failures = Vec::new();
    let mut notes = Vec::new();
    // All rings at once, nesting found by the triangulator.
    for strategy in STRATEGIES {
        for precision in PRECISIONS {
            for lenient in [false, true] {
                let tag = format!(
                    "{file} all-rings Auto {strategy:?} {precision:?} {}",
                    if lenient { "lenient" } else { "strict" }
                );
                let opts = Options::default()
                    .with_strategy(strategy)
                    .with_lenient(lenient);
                let started = std::time::Instant::now();
                let r = match run(
                    flat.vertices.clone(),
                    flat.ring_starts.clone(),
                    opts,
                    precision,
                ) {
                    Err(e) => {
                        failures.push(format!("{tag}: {e}"));
                        continue;
                    }
                    Ok(Err(e)) => {
                        failures.push(format!("{tag}: Err({e:?}): {e}"));
                        continue;
                    }
                    Ok(Ok(r)) => r,
                };
                let elapsed = started.elapsed();
                let v = seen(&flat.vertices, precision);
                match check_with_roles(&v, &flat.rings, &roles, &r.triangles) {
                    Err(e) => failures.push(format!("{tag}: invalid: {e}")),
                    Ok(s) => notes.push(format!(
                        "{tag}: {} triangles, {} dropped, min angle {:.3}°, {elapsed:?}",
                        s.triangles,
                        r.dropped.len(),
                        s.min_angle_deg
                    )),
                }
                let want = expected_count_with(
                    &flat.ring_starts,
                    flat.vertices.len(),
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
                if r.repairs != 0 {
                    failures.push(format!(
                        "{tag}: {} repairs reported for a valid input",
                        r.repairs
                    ));
                }
            }
        }
    }
    // Each shape alone, earcut's convention.
    for strategy in STRATEGIES {
        let mut bad = 0;
        for (s, shape) in shapes.iter().enumerate() {
            let f = flatten(shape);
            let roles = first_is_outer(f.rings.len());
            let opts = Options::default()
                .with_strategy(strategy)
                .with_nesting(Nesting::FirstIsOuter);
            let tag = format!("{file} shape {s} FirstIsOuter {strategy:?} F64 strict");
            let problem = match run(
                f.vertices.clone(),
                f.ring_starts.clone(),
                opts,
                Precision::F64,
            ) {
                Err(e) => Some(e),
                Ok(Err(e)) => Some(format!("Err({e:?}): {e}")),
                Ok(Ok(r)) => {
                    let want = expected_count(&f.ring_starts, f.vertices.len(), &roles, &r.dropped);
                    match check_with_roles(&f.vertices, &f.rings, &roles, &r.triangles) {
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
    assert!(
        failures.is_empty(),
        "{} failure(s):\n{}",
        failures.len(),
        failures.join("\n")
    );
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
