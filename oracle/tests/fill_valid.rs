//! Fill rules on input without crossings: every valid generator family, earcut's fixtures
//! and the corpus's own cases, each also with its rings' orientations flipped at random,
//! under every fill rule, in every strategy and both precisions, judged by
//! the oracle's independent `check_fill`. Where strict mode reads the input as the rule
//! does (even–odd on rings that do not cross; nonzero, positive and negative where every
//! ring winds the way containment nests it), the triangulator takes strict mode's path
//! instead of resolving the rings: no vertex is added, and the report still lists every
//! unused input vertex as a fill rule's report does.

mod common;

use common::{corpus_dir, earcut_fixtures, seen, Rng};
use polytri::{Coord, DropReason, FillRule, Nesting, Options, Strategy, Triangulator};
use polytri_oracle::replay::{load_dir, Precision};
use polytri_oracle::{check_fill, generate, Family, Input, Params};

/// Seeds per family and size.
const SEEDS: u64 = 3;
const SIZES: [usize; 3] = [12, 60, 300];

/// One triangulation with a fill rule: `None` when the oracle accepts it and the report
/// is as a fill rule's must be, else what went wrong.
fn judge<T: Coord>(
    vertices: &[[T; 2]],
    judged: &[[f64; 2]],
    ring_starts: &[usize],
    rule: FillRule,
    strategy: Strategy,
) -> Option<String> {
    let options = Options::new().with_strategy(strategy).with_fill_rule(rule);
    let mut tri = Triangulator::<T>::new();
    let mut out = Vec::new();
    let report = match tri.triangulate(vertices, ring_starts, &options, &mut out) {
        Ok(report) => report,
        Err(e) => return Some(format!("refused: {e}")),
    };
    let added: Vec<[f64; 2]> = report.added.iter().map(|a| a.position).collect();
    let verdict = check_fill(judged, ring_starts, rule, &added, &out);
    if !verdict.valid {
        return Some(format!(
            "{} triangles: {}",
            out.len(),
            verdict.failures().join("; ")
        ));
    }
    // a fill rule's report: every vertex no triangle uses is listed, once, and only those;
    // a listed vertex stands for another at its position that a triangle uses, or is no
    // corner of the region
    let mut listed = vec![0; vertices.len()];
    for d in report.dropped {
        let Some(n) = listed.get_mut(d.vertex as usize) else {
            return Some(format!("dropped vertex {} out of range", d.vertex));
        };
        *n += 1;
        if !matches!(d.reason, DropReason::Coincident | DropReason::OffBoundary) {
            return Some(format!("vertex {} dropped as {:?}", d.vertex, d.reason));
        }
    }
    let mut used = vec![false; vertices.len() + added.len()];
    for &v in out.iter().flatten() {
        used[v as usize] = true;
    }
    for (v, &n) in listed.iter().enumerate() {
        if n != usize::from(!used[v]) {
            return Some(format!("vertex {v}: used {}, listed {n} times", used[v]));
        }
    }
    for d in report.dropped {
        let p = judged[d.vertex as usize];
        let held = (0..vertices.len()).any(|w| used[w] && judged[w] == p);
        if held != (d.reason == DropReason::Coincident) {
            return Some(format!("vertex {} dropped as {:?}", d.vertex, d.reason));
        }
    }
    None
}

/// Every rule, strategy and precision on one input; failures named after `name`.
fn judge_all(name: &str, input: &Input, failures: &mut Vec<String>) {
    for precision in [Precision::F64, Precision::F32] {
        let seen = seen(input, precision);
        for rule in FillRule::ALL {
            for strategy in [Strategy::Fast, Strategy::Quality, Strategy::Seidel] {
                let what = match precision {
                    Precision::F64 => judge(
                        &input.vertices,
                        &seen.vertices,
                        &input.ring_starts,
                        rule,
                        strategy,
                    ),
                    Precision::F32 => judge(
                        &input.vertices_f32(),
                        &seen.vertices,
                        &input.ring_starts,
                        rule,
                        strategy,
                    ),
                };
                if let Some(what) = what {
                    failures.push(format!(
                        "{name} {} {strategy:?} {precision}: {what}",
                        rule.name()
                    ));
                }
            }
        }
    }
}

/// `input` with each ring reversed or not at random: rings both ways round, which only
/// `resolve` reads right under the rules other than even–odd.
fn flipped(input: &Input, rng: &mut Rng) -> Input {
    let mut rings = input.rings();
    for ring in &mut rings {
        if rng.below(2) == 1 {
            ring.reverse();
        }
    }
    Input::from_rings(&rings, input.nesting.clone())
}

fn assert_none(failures: &[String]) {
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn every_valid_family_under_every_fill_rule() {
    let mut failures = Vec::new();
    let mut rng = Rng(0xf111_5eed);
    for family in Family::ALL {
        for &size in &SIZES {
            for seed in 0..SEEDS {
                let case = generate(family, seed, &Params::new(size));
                judge_all(&case.name, &case.input, &mut failures);
                let name = format!("{} flipped", case.name);
                judge_all(&name, &flipped(&case.input, &mut rng), &mut failures);
            }
        }
    }
    assert_none(&failures);
}

#[test]
fn corpus_cases_and_earcut_fixtures_under_every_fill_rule() {
    let mut failures = Vec::new();
    let mut rng = Rng(0x0f11_c0de);
    let mut cases = earcut_fixtures();
    for folder in ["cases", "paper"] {
        cases.extend(load_dir(&corpus_dir().join(folder)).expect("corpus folder"));
    }
    for case in cases.iter().filter(|c| c.input.vertices.len() <= 3000) {
        judge_all(&case.id(), &case.input, &mut failures);
        let name = format!("{} flipped", case.id());
        judge_all(&name, &flipped(&case.input, &mut rng), &mut failures);
    }
    assert_none(&failures);
}

/// Rings sharing their sides, all in one input: a grid of squares (nearly every node
/// shared, which even–odd leaves to `resolve`), and the counties of Texas as one set of
/// rings (`docs/gis`).
#[test]
fn rings_sharing_their_sides_under_every_fill_rule() {
    let mut failures = Vec::new();
    let mut rng = Rng(0x5eed_911d);
    let mut squares = Vec::new();
    for i in 0..6 {
        for j in 0..5 {
            let (x, y) = (f64::from(i), f64::from(j));
            squares.push(vec![[x, y], [x + 1.0, y], [x + 1.0, y + 1.0], [x, y + 1.0]]);
        }
    }
    let grid = Input::from_rings(&squares, polytri_oracle::Nesting::Auto);
    judge_all("grid of squares", &grid, &mut failures);
    judge_all("grid flipped", &flipped(&grid, &mut rng), &mut failures);
    let path = corpus_dir().join("../docs/gis/texas-counties.geojson");
    let layer: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect("texas-counties")).unwrap();
    let mut rings: Vec<Vec<[f64; 2]>> = Vec::new();
    for feature in layer["features"].as_array().expect("features") {
        let geometry = &feature["geometry"];
        let polygons = match geometry["type"].as_str() {
            Some("Polygon") => vec![geometry["coordinates"].clone()],
            _ => geometry["coordinates"]
                .as_array()
                .cloned()
                .unwrap_or_default(),
        };
        for polygon in polygons {
            for ring in polygon.as_array().expect("rings") {
                let mut points: Vec<[f64; 2]> = serde_json::from_value(ring.clone()).unwrap();
                points.pop(); // the closing point
                rings.push(points);
            }
        }
    }
    let texas = Input::from_rings(&rings, polytri_oracle::Nesting::Auto);
    for rule in [FillRule::EvenOdd, FillRule::NonZero] {
        let v = &texas.vertices;
        if let Some(what) = judge(v, v, &texas.ring_starts, rule, Strategy::Fast) {
            failures.push(format!("texas {}: {what}", rule.name()));
        }
    }
    assert_none(&failures);
}

/// Triangles and added vertices of one call.
fn triangulate(
    vertices: &[[f64; 2]],
    starts: &[usize],
    options: &Options,
) -> (Vec<[u32; 3]>, usize) {
    let mut tri = Triangulator::<f64>::new();
    let mut out = Vec::new();
    let report = tri
        .triangulate(vertices, starts, options, &mut out)
        .unwrap();
    let added = report.added.len();
    (out, added)
}

/// A square with a square hole and an island in the hole, each ring wound as `turns`
/// says (true: counter-clockwise).
fn nested_squares(turns: [bool; 3]) -> (Vec<[f64; 2]>, Vec<usize>) {
    let mut vertices = Vec::new();
    let mut starts = Vec::new();
    for (k, (size, ccw)) in [(12.0, turns[0]), (8.0, turns[1]), (4.0, turns[2])]
        .into_iter()
        .enumerate()
    {
        let (lo, hi) = (2.0 * k as f64, 2.0 * k as f64 + size);
        let mut ring = vec![[lo, lo], [hi, lo], [hi, hi], [lo, hi]];
        if !ccw {
            ring.reverse();
        }
        starts.push(vertices.len());
        vertices.extend(ring);
    }
    (vertices, starts)
}

#[test]
fn strict_mode_answers_where_the_rule_reads_the_rings_as_nested() {
    let strict = |s: Strategy| Options::new().with_strategy(s).with_nesting(Nesting::Auto);
    for strategy in [Strategy::Fast, Strategy::Quality] {
        let with = |rule| Options::new().with_strategy(strategy).with_fill_rule(rule);
        // alternating as nested, counter-clockwise outside: even–odd, nonzero and positive
        // are strict mode's triangles; negative reads nothing
        let (v, s) = nested_squares([true, false, true]);
        let expected = triangulate(&v, &s, &strict(strategy));
        for rule in [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive] {
            assert_eq!(triangulate(&v, &s, &with(rule)), expected, "{rule:?}");
        }
        assert!(triangulate(&v, &s, &with(FillRule::Negative)).0.is_empty());
        // all reversed: negative reads it as nested too, positive reads nothing
        let (v, s) = nested_squares([false, true, false]);
        let expected = triangulate(&v, &s, &strict(strategy));
        for rule in [FillRule::EvenOdd, FillRule::NonZero, FillRule::Negative] {
            assert_eq!(triangulate(&v, &s, &with(rule)), expected, "{rule:?}");
        }
        assert!(triangulate(&v, &s, &with(FillRule::Positive)).0.is_empty());
        // the hole wound like its outer ring: nonzero fills it (winding 2), even–odd
        // does not; the island winds 1 (nonzero) or lies in a hole (even–odd)
        let (v, s) = nested_squares([true, true, false]);
        let area = |t: &[[u32; 3]]| -> f64 {
            t.iter()
                .map(|t| {
                    let [a, b, c] = t.map(|i| v[i as usize]);
                    ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs() / 2.0
                })
                .sum()
        };
        let even_odd = triangulate(&v, &s, &with(FillRule::EvenOdd)).0;
        let nonzero = triangulate(&v, &s, &with(FillRule::NonZero)).0;
        assert_eq!(area(&even_odd), 144.0 - 64.0 + 16.0);
        assert_eq!(area(&nonzero), 144.0);
    }
}

/// Rings that touch take strict mode's path by every rule where they wind as they nest,
/// and not where a hole winds like its outer ring: here a hole whose edge a vertex of the
/// outer ring's notch lies on (so strict mode splits that edge there), in every rotation
/// and both orientations, judged by the oracle and by area (outer 14, hole 3).
#[test]
fn touching_rings_wound_either_way_get_each_rule_s_region() {
    let outer = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [2.0, 3.0], [0.0, 4.0]];
    let hole = [[1.0, 3.0], [1.5, 1.0], [2.5, 1.0], [3.0, 3.0]];
    for turn in 0..hole.len() {
        for counter_clockwise in [true, false] {
            let mut h = hole.to_vec();
            h.rotate_left(turn);
            if !counter_clockwise {
                h.reverse();
            }
            let vertices = [outer.clone(), h].concat();
            let starts = [0, outer.len()];
            for rule in FillRule::ALL {
                // the hole's winding: 2 (nonzero and positive fill it) or 0
                let hole_in = if counter_clockwise {
                    rule.contains(2)
                } else {
                    rule.contains(0)
                };
                let expected = if !rule.contains(1) {
                    if hole_in {
                        3.0
                    } else {
                        0.0
                    }
                } else if hole_in {
                    14.0
                } else {
                    11.0
                };
                for strategy in [Strategy::Fast, Strategy::Quality, Strategy::Seidel] {
                    let name =
                        format!("turn {turn}, ccw {counter_clockwise}, {rule:?}, {strategy:?}");
                    let failure = judge(&vertices, &vertices, &starts, rule, strategy);
                    assert!(failure.is_none(), "{name}: {failure:?}");
                    let options = Options::new().with_strategy(strategy).with_fill_rule(rule);
                    let (t, _) = triangulate(&vertices, &starts, &options);
                    let area: f64 = t
                        .iter()
                        .map(|t| {
                            let [a, b, c] = t.map(|i| vertices[i as usize]);
                            ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2.0
                        })
                        .sum();
                    assert_eq!(area, expected, "{name}");
                }
            }
        }
    }
}
