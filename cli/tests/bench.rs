//! `polytri bench` end to end: the tables' shape on small inputs, never their timings.

mod common;

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

use common::scratch;

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("../corpus/earcut/fixtures/{name}.json"))
}

/// Runs `polytri bench --quick ARGS`; its stdout and stderr, after asserting success.
fn run(args: &[&str]) -> (String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_polytri"))
        .arg("bench")
        .arg("--quick")
        .args(args)
        .output()
        .expect("run polytri bench");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "polytri bench failed: {stderr}");
    (String::from_utf8(out.stdout).expect("UTF-8 output"), stderr)
}

/// `polytri bench --quick ARGS building.json`: its stdout.
fn bench(extra: &[&str]) -> String {
    let building = fixture("building");
    let mut args = extra.to_vec();
    args.push(building.to_str().expect("UTF-8 path"));
    let (stdout, stderr) = run(&args);
    assert!(stderr.contains("building"), "progress on stderr: {stderr}");
    stdout
}

#[test]
fn table_has_every_column_and_a_geometric_mean() {
    let table = bench(&[]);
    let lines: Vec<&str> = table.lines().collect();
    assert_eq!(
        lines.len(),
        3,
        "header, one input, geometric mean:\n{table}"
    );
    let header = lines[0];
    for column in [
        "input",
        "polygons",
        "vertices",
        "triangles",
        "polytri-fast ms",
        "polytri-lenient ms",
        "polytri-quality ms",
        "polytri-check ms",
        "polytri-threads ms",
        "earcut ms",
        "earcutr ms",
        "i-triangle ms",
        "lyon ms",
        "spade ms",
        "earcut-exact ms",
        "earcut-vendored ms",
        "fastest peer",
    ] {
        assert!(
            header.contains(column),
            "no column {column:?} in {header:?}"
        );
    }
    let row: Vec<&str> = lines[1].split_whitespace().collect();
    assert_eq!(row[..3], ["building", "1", "15"]);
    assert!(row[3].parse::<usize>().is_ok_and(|t| t > 10), "{row:?}");
    // every implementation: a time and a ratio, none failed; then the fastest peer's name,
    // never one of the references
    assert_eq!(row.len(), 4 + 2 * 12 + 1, "{row:?}");
    assert!(
        ["earcut", "earcutr", "i-triangle", "lyon", "spade"].contains(&row[row.len() - 1]),
        "{row:?}"
    );
    assert_eq!(lines[2].matches('×').count(), 12, "{}", lines[2]);
}

#[test]
fn json_lists_chosen_peers() {
    let text = bench(&["--json", "--peers", "earcut,i_triangle"]);
    let json: Value = serde_json::from_str(&text).expect("JSON on stdout");
    let names: Vec<&str> = json["implementations"]
        .as_array()
        .expect("implementations")
        .iter()
        .filter_map(|v| v.as_str())
        .collect();
    assert_eq!(
        names,
        [
            "polytri-fast",
            "polytri-lenient",
            "polytri-quality",
            "polytri-check",
            "polytri-threads",
            "earcut",
            "i-triangle"
        ]
    );
    let timings = &json["rows"][0]["timings"];
    assert_eq!(timings.as_array().map(Vec::len), Some(7));
    // whichever peer is faster has ratio exactly 1
    let ones = (5..7)
        .filter(|&k| timings[k]["ratio"].as_f64() == Some(1.0))
        .count();
    assert_eq!(ones, 1, "{timings}");
}

#[test]
fn check_columns_time_the_check_alone_and_are_no_peers() {
    let args = [
        "--json",
        "--polytri",
        "check,fast,check-floor",
        "--peers",
        "earcut",
    ];
    let text = bench(&args);
    let json: Value = serde_json::from_str(&text).expect("JSON on stdout");
    let timings = &json["rows"][0]["timings"];
    assert_eq!(timings[0]["implementation"], "polytri-check");
    assert_eq!(timings[1]["implementation"], "polytri-fast");
    assert_eq!(timings[2]["implementation"], "polytri-check-floor");
    // the check and its floor ran, but made no triangles; the row's count is
    // polytri-fast's
    for k in [0, 2] {
        assert!(timings[k]["median_ms"].is_number(), "{timings}");
        assert!(timings[k]["triangles"].is_null(), "{timings}");
    }
    assert!(
        timings[1]["triangles"].as_u64().is_some_and(|t| t > 10),
        "{timings}"
    );
    assert_eq!(json["rows"][0]["triangles"], timings[1]["triangles"]);
    // however fast the check is, the ratios are to the only peer
    assert_eq!(timings[3]["ratio"].as_f64(), Some(1.0), "{timings}");
}

#[test]
fn check_column_refuses_what_strict_mode_refuses() {
    let dir = scratch("bench", "bow-tie");
    let bow_tie = dir.join("bow_tie.json");
    fs::write(&bow_tie, "[[[0,0],[4,4],[4,0],[0,4]]]").expect("write input");
    let (table, stderr) = run(&[
        "--polytri",
        "fast,lenient,check",
        "--peers",
        "earcut",
        bow_tie.to_str().expect("UTF-8 path"),
    ]);
    let row: Vec<&str> = table
        .lines()
        .nth(1)
        .expect("a row")
        .split_whitespace()
        .collect();
    assert_eq!(row[0], "bow_tie");
    // fast and check refuse, lenient repairs (a time and a ratio), earcut runs
    assert_eq!(row[4], "refused", "{row:?}");
    assert!(row[5].parse::<f64>().is_ok(), "{row:?}");
    assert_eq!(row[7], "refused", "{row:?}");
    assert!(row[8].parse::<f64>().is_ok(), "{row:?}");
    assert!(stderr.contains("polytri-check failed"), "{stderr}");
}

#[test]
fn per_second_markdown_is_the_papers_table() {
    let (table, _) = run(&[
        "--paper",
        "--polytri",
        "fast,quality",
        "--peers",
        "earcut",
        "--per-second",
        "--markdown",
    ]);
    let lines: Vec<&str> = table.lines().collect();
    assert_eq!(
        lines[0],
        "| input               | polygons | vertices | triangles | polytri-fast M tri/s \
         | polytri-quality M tri/s | earcut M tri/s | fastest peer |"
    );
    assert!(
        lines[1].starts_with("| ------------------- | -------: |"),
        "{}",
        lines[1]
    );
    // the seven datasets, then the geometric mean
    assert_eq!(lines.len(), 2 + 7 + 1, "{table}");
    let letter_a: Vec<&str> = lines[2].split('|').map(str::trim).collect();
    assert_eq!(letter_a[1..5], ["letter_a", "1", "11", "11"]);
    assert!(letter_a[5].ends_with("×)"), "{letter_a:?}");
    assert_eq!(letter_a[8], "earcut");
    assert!(lines[9].starts_with("| **geometric mean**"), "{}", lines[9]);
}

#[test]
fn quick_scaling_prints_medians_and_exponents_and_plots_each_series() {
    let dir = scratch("bench", "scaling");
    let (text, stderr) = run(&[
        "--scaling",
        "--sizes",
        "200,400,800",
        "--series",
        "circles,comb",
        "--out",
        dir.to_str().expect("UTF-8 path"),
    ]);
    for series in ["circles", "comb"] {
        let path = dir.join(format!("scaling-{series}.svg"));
        let svg = fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path:?}: {e}"));
        assert!(svg.starts_with("<svg"), "{}", &svg[..80.min(svg.len())]);
        assert!(svg.trim_end().ends_with("</svg>"));
        for text in ["vertices", "polytri-fast (n^", "spade (n^"] {
            assert!(svg.contains(text), "{series}: no {text:?} in the plot");
        }
        assert!(
            stderr.contains(&format!("{series}-800")),
            "progress: {stderr}"
        );
    }
    let (medians, exponents) = text
        .split_once("growth exponent")
        .expect("an exponent table after the medians");
    let medians: Vec<&str> = medians.lines().filter(|l| !l.is_empty()).collect();
    assert!(medians[0].starts_with("series"), "{}", medians[0]);
    assert!(medians[0].contains("polytri-check ms"), "{}", medians[0]);
    assert_eq!(
        medians.len(),
        1 + 2 * 3,
        "a line per series and size:\n{text}"
    );
    for line in exponents.lines().filter(|l| l.starts_with("c")) {
        let cells: Vec<&str> = line.split_whitespace().collect();
        // every implementation ran at three sizes: an exponent each
        assert_eq!(cells.len(), 1 + 11, "{line}");
        for cell in &cells[1..] {
            let k: f64 = cell
                .parse()
                .unwrap_or_else(|_| panic!("{cell:?} in {line}"));
            assert!(k.is_finite(), "{line}");
        }
    }
    assert_eq!(exponents.lines().filter(|l| l.starts_with("c")).count(), 2);
}

#[test]
fn unknown_peer_is_a_usage_error() {
    for args in [
        ["bench", "--peers", "triangle"],
        ["bench", "--polytri", "slow"],
        ["bench", "--series", "square"],
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_polytri"))
            .args(args)
            .output()
            .expect("run polytri bench");
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            String::from_utf8_lossy(&out.stderr).contains("unknown"),
            "{args:?}"
        );
    }
}

#[test]
fn files_and_scaling_exclude_each_other() {
    let building = fixture("building");
    let out = Command::new(env!("CARGO_BIN_EXE_polytri"))
        .args(["bench", "--scaling"])
        .arg(Path::new(&building))
        .output()
        .expect("run polytri bench");
    assert_eq!(out.status.code(), Some(2));
}

/// A shapes JSON of two polygons, a 4×4 square, then a 10×10 square around it.
const SQUARE_THEN_SQUARE_AROUND_IT: &str =
    "[[[[3,3],[7,3],[7,7],[3,7]]], [[[0,0],[10,0],[10,10],[0,10]]]]";

/// `polytri bench --quick --json --polytri fast --peers earcut ARGS FILE`: polytri-fast's
/// timing and the row's polygon and triangle counts.
fn fast_on(file: &Path, extra: &[&str]) -> (Value, u64, Option<u64>) {
    let mut args = vec!["--json", "--polytri", "fast", "--peers", "earcut"];
    args.extend_from_slice(extra);
    args.push(file.to_str().expect("UTF-8 path"));
    let (text, _) = run(&args);
    let json: Value = serde_json::from_str(&text).expect("JSON on stdout");
    let row = &json["rows"][0];
    let timing = row["timings"][0].clone();
    assert_eq!(timing["implementation"], "polytri-fast", "{row}");
    (
        timing,
        row["polygons"].as_u64().expect("a polygon count"),
        row["triangles"].as_u64(),
    )
}

#[test]
fn nesting_and_merge_say_how_rings_make_polygons() {
    let dir = scratch("bench", "nesting");
    let file = dir.join("two_squares.json");
    fs::write(&file, SQUARE_THEN_SQUARE_AROUND_IT).expect("write input");
    // each polygon on its own, whatever the nesting: two squares, two triangles each
    for nesting in ["auto", "first-outer"] {
        let (timing, polygons, triangles) = fast_on(&file, &["--nesting", nesting]);
        assert_eq!((polygons, triangles), (2, Some(4)), "{nesting}: {timing}");
        assert!(timing["median_ms"].is_number(), "{nesting}: {timing}");
    }
    // merged, containment decides: the small square is a hole in the big one
    let (timing, polygons, triangles) = fast_on(&file, &["--merge"]);
    assert_eq!((polygons, triangles), (1, Some(8)), "{timing}");
    assert_eq!(timing["triangles"], 8, "{timing}");
    // merged, the first ring outer: the big square would be a hole outside it, which
    // strict polytri refuses
    let (timing, polygons, _) = fast_on(&file, &["--merge", "--nesting", "first-outer"]);
    assert_eq!(polygons, 1, "{timing}");
    assert!(timing["median_ms"].is_null(), "{timing}");
    assert!(timing["error"].is_string(), "{timing}");
}

#[test]
fn auto_nesting_finds_the_outer_ring_of_a_polygon_listed_second() {
    let dir = scratch("bench", "hole-first");
    let file = dir.join("hole_first.json");
    fs::write(
        &file,
        "[[[3,3],[7,3],[7,7],[3,7]], [[0,0],[10,0],[10,10],[0,10]]]",
    )
    .expect("write input");
    let (timing, polygons, triangles) = fast_on(&file, &[]);
    assert_eq!((polygons, triangles), (1, Some(8)), "{timing}");
    let (timing, _, _) = fast_on(&file, &["--nesting", "first-outer"]);
    assert!(timing["error"].is_string(), "{timing}");
}

#[test]
fn references_are_timed_but_no_ratio_is_to_them() {
    let text = bench(&[
        "--json",
        "--polytri",
        "fast",
        "--peers",
        "earcut-exact,earcut-vendored,spade",
    ]);
    let json: Value = serde_json::from_str(&text).expect("JSON on stdout");
    let timings = &json["rows"][0]["timings"];
    let names: Vec<&str> = (0..4)
        .filter_map(|k| timings[k]["implementation"].as_str())
        .collect();
    assert_eq!(
        names,
        ["polytri-fast", "earcut-exact", "earcut-vendored", "spade"]
    );
    // both references make earcut's count for building (expected.json: 13; polytri drops a
    // collinear vertex and makes 12)
    for k in 1..3 {
        assert_eq!(timings[k]["triangles"], 13, "{timings}");
    }
    // spade, the only peer, is the fastest peer however fast the references are
    assert_eq!(timings[3]["ratio"].as_f64(), Some(1.0), "{timings}");
}
