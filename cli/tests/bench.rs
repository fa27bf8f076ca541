//! `polytri bench` end to end: the table's shape on one small fixture, not its timings.

use std::path::PathBuf;
use std::process::Command;

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("../corpus/earcut/fixtures/{name}.json"))
}

fn bench(extra: &[&str]) -> String {
    let building = fixture("building");
    let out = Command::new(env!("CARGO_BIN_EXE_polytri"))
        .arg("bench")
        .arg("--quick")
        .args(extra)
        .arg(&building)
        .output()
        .expect("run polytri bench");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "polytri bench failed: {stderr}");
    assert!(stderr.contains("building"), "progress on stderr: {stderr}");
    String::from_utf8(out.stdout).expect("UTF-8 output")
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
        "vertices",
        "triangles",
        "polytri-fast ms",
        "polytri-lenient ms",
        "polytri-quality ms",
        "earcut ms",
        "earcutr ms",
        "i-triangle ms",
        "lyon ms",
        "spade ms",
    ] {
        assert!(
            header.contains(column),
            "no column {column:?} in {header:?}"
        );
    }
    let row: Vec<&str> = lines[1].split_whitespace().collect();
    assert_eq!(row[0], "building");
    assert_eq!(row[1], "15");
    // every implementation: a time and a ratio, none failed
    assert_eq!(row.len(), 3 + 2 * 8, "{row:?}");
    assert_eq!(lines[2].matches('×').count(), 8, "{}", lines[2]);
}

#[test]
fn json_lists_chosen_peers() {
    let text = bench(&["--json", "--peers", "earcut,i_triangle"]);
    let json: serde_json::Value = serde_json::from_str(&text).expect("JSON on stdout");
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
            "earcut",
            "i-triangle"
        ]
    );
    let timings = &json["rows"][0]["timings"];
    assert_eq!(timings.as_array().map(Vec::len), Some(5));
    // whichever peer is faster has ratio exactly 1
    let ones = (3..5)
        .filter(|&k| timings[k]["ratio"].as_f64() == Some(1.0))
        .count();
    assert_eq!(ones, 1, "{timings}");
}

#[test]
fn unknown_peer_is_a_usage_error() {
    let out = Command::new(env!("CARGO_BIN_EXE_polytri"))
        .args(["bench", "--peers", "triangle"])
        .output()
        .expect("run polytri bench");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown peer"));
}
