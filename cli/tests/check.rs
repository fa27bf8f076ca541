//! `polytri check` end to end: the built binary judging results of `polytri triangulate`.

mod common;

use std::fs;
use std::path::{Path, PathBuf};

use serde_json::Value;

use common::{polytri, scratch, write};

fn path(s: &str) -> &Path {
    Path::new(s)
}

/// Two polygons, one with a hole touching its outer ring at a vertex.
const SHAPES: &str = "[
    [[[0,0],[10,0],[10,10],[0,10]], [[0,0],[3,2],[2,3]], [[5,5],[5,7],[7,7],[7,5]]],
    [[[20,0],[30,0],[25,8]]]
]";

/// Triangulates `SHAPES` into `dir/result.json` and returns the input and result paths.
fn triangulated(dir: &Path) -> (PathBuf, PathBuf) {
    triangulated_text(dir, SHAPES)
}

/// Writes `text` as `dir/shapes.json`, triangulates it into `dir/result.json` and returns
/// the input and result paths.
fn triangulated_text(dir: &Path, text: &str) -> (PathBuf, PathBuf) {
    let input = write(dir, "shapes.json", text);
    let result = dir.join("result.json");
    let out = polytri(&[
        path("triangulate"),
        &input,
        path("-o"),
        &result,
        path("--quiet"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    (input, result)
}

#[test]
fn accepts_what_triangulate_wrote() {
    let dir = scratch("check", "accepts");
    let (input, result) = triangulated(&dir);
    let out = polytri(&[path("check"), &input, &result]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let verdict: Value = serde_json::from_slice(&out.stdout).expect("verdict JSON");
    assert_eq!(verdict["valid"], true);
    assert_eq!(verdict["input_valid"], true);
    // The first polygon: its outer boundary pinched by the touching hole has 7 corners,
    // the other hole 4: 11 − 2 + 2·1 = 11 triangles. And the triangle.
    assert_eq!(verdict["expected_triangles"], 12);
    assert!(verdict["cdt"].is_object());
    let fast = polytri(&[path("check"), &input, &result, path("--fast")]);
    assert!(fast.status.success());
    let verdict: Value = serde_json::from_slice(&fast.stdout).expect("verdict JSON");
    assert!(verdict["cdt"].is_null());
}

#[test]
fn rejects_a_broken_result_naming_the_check() {
    let dir = scratch("check", "rejects");
    let (input, result) = triangulated(&dir);
    let mut json: Value =
        serde_json::from_str(&fs::read_to_string(&result).expect("read")).expect("JSON");
    // Flip the first triangle.
    let t = json["triangles"][0].as_array_mut().expect("triangle");
    t.swap(1, 2);
    let broken = write(&dir, "broken.json", &json.to_string());
    let out = polytri(&[path("check"), &input, &broken]);
    assert_eq!(out.status.code(), Some(1));
    let verdict: Value = serde_json::from_slice(&out.stdout).expect("verdict JSON on stdout");
    assert_eq!(verdict["valid"], false);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    // judged polygon by polygon: the failure names its polygon
    assert!(
        stderr.contains("orientation: polygon 0: triangle 0"),
        "{stderr}"
    );
}

#[test]
fn says_when_the_result_is_of_another_input() {
    let dir = scratch("check", "mismatch");
    let (input, result) = triangulated(&dir);
    let other = write(&dir, "other.json", "[[[0,0],[1,0],[0,1]]]");
    let out = polytri(&[path("check"), &other, &result]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("not of this input"), "{stderr}");
    let moved = fs::read_to_string(&result)
        .expect("read")
        .replacen("[0.0,0.0]", "[0.5,0.0]", 1);
    let moved = write(&dir, "moved.json", &moved);
    let out = polytri(&[path("check"), &input, &moved]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("vertex 0"), "{stderr}");
    let usage = polytri(&[path("check"), &input]);
    assert_eq!(usage.status.code(), Some(2));
}

#[test]
fn each_polygon_is_judged_on_its_own() {
    let dir = scratch("check", "per_polygon");
    // two overlapping squares, as neighbouring features of a layer often are
    let (input, result) = triangulated_text(
        &dir,
        "[[[[0,0],[10,0],[10,10],[0,10]]], [[[9,-1],[20,-1],[20,11],[9,11]]]]",
    );
    assert!(polytri(&[path("check"), &input, &result]).status.success());
    // judged together, the overlap is an error
    let merged = polytri(&[
        path("check"),
        &input,
        &result,
        path("--merge"),
        path("--fast"),
    ]);
    assert_eq!(merged.status.code(), Some(1));
    // a failure in the second polygon names its triangle and vertices as RESULT numbers them
    let mut json: Value =
        serde_json::from_str(&fs::read_to_string(&result).expect("read")).expect("JSON");
    let last = json["triangles"].as_array().expect("triangles").len() - 1;
    json["triangles"][last]
        .as_array_mut()
        .expect("triangle")
        .swap(1, 2);
    let flipped = write(&dir, "flipped.json", &json.to_string());
    let out = polytri(&[path("check"), &input, &flipped, path("--fast")]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains(&format!("orientation: polygon 1: triangle {last} (")),
        "{stderr}"
    );
    let corner = |v: &Value| v.as_u64().expect("index");
    let t = &json["triangles"][last];
    let named = format!("({}, {}, {})", corner(&t[0]), corner(&t[1]), corner(&t[2]));
    assert!(stderr.contains(&named), "{named} in {stderr}");
    json["triangles"][last]
        .as_array_mut()
        .expect("triangle")
        .swap(1, 2);
    // a triangle joining the two polygons' vertices is no triangle of either
    json["triangles"][0] = serde_json::json!([0, 1, 4]);
    let joined = write(&dir, "joined.json", &json.to_string());
    let out = polytri(&[path("check"), &input, &joined, path("--fast")]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("indices: triangle 0 [0, 1, 4] joins vertices of different polygons"),
        "{stderr}"
    );
}

/// `--merge --nesting first-outer` means the same in `triangulate` and `check`: the file's
/// first ring is outer, every other ring a hole in it.
#[test]
fn merged_first_outer_means_the_same_in_both_commands() {
    let dir = scratch("check", "merged-first-outer");
    // two polygons, the second's square inside the first: merged, a hole
    let file = write(
        &dir,
        "shapes.json",
        "[[[[0,0],[10,0],[10,10],[0,10]]], [[[2,2],[4,2],[4,4],[2,4]]]]",
    );
    let result = dir.join("result.json");
    let flags = [path("--merge"), path("--nesting"), path("first-outer")];
    let mut args = vec![path("triangulate"), &file, path("-o"), &result];
    args.extend(flags);
    let out = polytri(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut args = vec![path("check"), &file, &result, path("--fast")];
    args.extend(flags);
    let out = polytri(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let verdict: Value = serde_json::from_slice(&out.stdout).expect("verdict JSON");
    // 4 + 4 vertices, one hole: 8 triangles
    assert_eq!(verdict["triangles"], 8, "{verdict}");
    let _ = fs::remove_dir_all(dir);
}
