//! `polytri triangulate` end to end: the built binary on small files written per test.

mod common;

use std::fs;
use std::path::Path;

use serde_json::Value;

use common::{polytri, scratch, write};

/// Runs `polytri triangulate FILE EXTRA…`, expects success and returns the result JSON
/// and stderr.
fn triangulate(file: &Path, extra: &[&str]) -> (Value, String) {
    let mut args = vec!["triangulate", file.to_str().expect("utf-8 path")];
    args.extend_from_slice(extra);
    let out = polytri(&args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "polytri {args:?} failed: {stderr}");
    let json = serde_json::from_slice(&out.stdout).expect("stdout is JSON");
    (json, stderr)
}

/// Runs `polytri triangulate FILE EXTRA…`, expects exit status 1 and returns the one line
/// of stderr.
fn refused(file: &Path, extra: &[&str]) -> String {
    let mut args = vec!["triangulate", file.to_str().expect("utf-8 path")];
    args.extend_from_slice(extra);
    let out = polytri(&args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(1), "polytri {args:?}: {stderr}");
    assert!(out.stdout.is_empty(), "no result on failure");
    assert_eq!(stderr.lines().count(), 1, "one line: {stderr:?}");
    assert!(stderr.starts_with("polytri: error: "), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    stderr
}

fn vertices(json: &Value) -> Vec<[f64; 2]> {
    json["vertices"]
        .as_array()
        .expect("vertices array")
        .iter()
        .map(|v| [v[0].as_f64().expect("x"), v[1].as_f64().expect("y")])
        .collect()
}

fn triangles(json: &Value) -> Vec<[usize; 3]> {
    json["triangles"]
        .as_array()
        .expect("triangles array")
        .iter()
        .map(|t| {
            let i = |k: usize| usize::try_from(t[k].as_u64().expect("index")).expect("fits");
            [i(0), i(1), i(2)]
        })
        .collect()
}

/// Twice the signed area of a triangle: positive when counter-clockwise with y up.
fn doubled_area(v: &[[f64; 2]], t: [usize; 3]) -> f64 {
    let [a, b, c] = [v[t[0]], v[t[1]], v[t[2]]];
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

const SQUARE: &str = "[[[0,0],[10,0],[10,10],[0,10]]]";
const SQUARE_WITH_HOLE: &str = "[[[0,0],[10,0],[10,10],[0,10]],[[3,3],[3,7],[7,7],[7,3]]]";

#[test]
fn rings_json_square() {
    let dir = scratch("triangulate", "rings_json_square");
    let (json, stderr) = triangulate(&write(&dir, "square.json", SQUARE), &[]);
    assert_eq!(
        vertices(&json),
        vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]
    );
    let tris = triangles(&json);
    assert_eq!(tris.len(), 2);
    let v = vertices(&json);
    assert!(
        tris.iter().all(|&t| doubled_area(&v, t) > 0.0),
        "counter-clockwise: {tris:?}"
    );
    assert_eq!(
        stderr.trim(),
        "polytri: square.json: 1 polygon, 0 holes, 2 triangles, 0 dropped vertices, 0 repairs"
            .replace(
                "square.json",
                &dir.join("square.json").display().to_string()
            )
    );
}

#[test]
fn rings_json_square_with_hole() {
    let dir = scratch("triangulate", "rings_json_square_with_hole");
    let file = write(&dir, "hole.json", SQUARE_WITH_HOLE);
    for strategy in ["fast", "quality"] {
        for nesting in ["auto", "first-outer"] {
            let (json, stderr) =
                triangulate(&file, &["--strategy", strategy, "--nesting", nesting]);
            assert_eq!(vertices(&json).len(), 8);
            assert_eq!(triangles(&json).len(), 8, "{strategy} {nesting}");
            assert!(stderr.contains("1 hole,"), "{stderr}");
        }
    }
}

#[test]
fn closing_point_is_dropped() {
    let dir = scratch("triangulate", "closing_point_is_dropped");
    let file = write(&dir, "closed.json", "[[[0,0],[10,0],[10,10],[0,10],[0,0]]]");
    let (json, _) = triangulate(&file, &[]);
    assert_eq!(vertices(&json).len(), 4, "closing point dropped");
    assert_eq!(triangles(&json).len(), 2);
    assert!(triangles(&json).iter().flatten().all(|&i| i < 4));
}

#[test]
fn extra_coordinates_are_ignored() {
    let dir = scratch("triangulate", "extra_coordinates_are_ignored");
    let file = write(&dir, "z.json", "[[[0,0,5],[10,0,5],[10,10,5],[0,10,5]]]");
    let (json, _) = triangulate(&file, &[]);
    assert_eq!(vertices(&json)[2], [10.0, 10.0]);
    assert_eq!(triangles(&json).len(), 2);
}

/// Two polygons, the second with a hole: every triangle must stay within one polygon's
/// vertices, whether triangulated in one call (auto) or one call per polygon (offsets).
#[test]
fn shapes_json_triangulates_every_polygon_with_offsets() {
    let dir = scratch("triangulate", "shapes_json_offsets");
    let text = format!(
        "[{SQUARE_WITH_HOLE}, [[[20,0],[30,0],[30,10],[20,10]]], \
         [[[40,0],[50,0],[50,10],[40,10]],[[43,3],[43,7],[47,7],[47,3]]]]"
    );
    let file = write(&dir, "shapes.json", &text);
    for nesting in ["auto", "first-outer"] {
        let (json, stderr) = triangulate(&file, &["--nesting", nesting]);
        let v = vertices(&json);
        let tris = triangles(&json);
        assert_eq!(v.len(), 8 + 4 + 8);
        assert_eq!(tris.len(), 8 + 2 + 8, "{nesting}");
        let polygon_of = |i: usize| match i {
            0..=7 => 0,
            8..=11 => 1,
            _ => 2,
        };
        for t in &tris {
            assert!(
                t.iter().all(|&i| polygon_of(i) == polygon_of(t[0])),
                "{nesting}: {t:?} spans polygons"
            );
            assert!(doubled_area(&v, *t) > 0.0);
        }
        for p in 0..3 {
            assert!(
                tris.iter().any(|t| polygon_of(t[0]) == p),
                "{nesting}: polygon {p} has triangles"
            );
        }
        assert!(
            stderr.contains("3 polygons, 2 holes, 18 triangles"),
            "{nesting}: {stderr}"
        );
    }
}

#[test]
fn geojson_collections_and_skipped_geometries() {
    let dir = scratch("triangulate", "geojson_collections");
    let text = r#"{"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"name": "hole"}, "geometry":
            {"type": "Polygon", "coordinates": [
                [[0,0],[10,0],[10,10],[0,10],[0,0]], [[3,3],[3,7],[7,7],[7,3],[3,3]]]}},
        {"type": "Feature", "properties": {}, "geometry":
            {"type": "MultiPolygon", "coordinates": [[[[20,0,1],[30,0,1],[30,10,1],[20,10,1],[20,0,1]]]]}},
        {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [1, 2]}}
    ]}"#;
    let (json, stderr) = triangulate(&write(&dir, "features.geojson", text), &[]);
    assert_eq!(vertices(&json).len(), 12);
    assert_eq!(triangles(&json).len(), 10);
    assert!(
        stderr.contains("warning") && stderr.contains("Point"),
        "{stderr}"
    );

    let text = r#"{"type": "GeometryCollection", "geometries": [
        {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,10],[0,10],[0,0]]]},
        {"type": "LineString", "coordinates": [[0,0],[1,1]]}]}"#;
    let (json, _) = triangulate(&write(&dir, "collection.json", text), &[]);
    assert_eq!(triangles(&json).len(), 2);

    let text = r#"{"type": "Feature", "properties": null, "geometry":
        {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,10],[0,10],[0,0]]]}}"#;
    let (json, _) = triangulate(&write(&dir, "feature.json", text), &[]);
    assert_eq!(triangles(&json).len(), 2);
}

#[test]
fn wkt_by_extension_and_by_content() {
    let dir = scratch("triangulate", "wkt");
    let text = "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (3 3, 3 7, 7 7, 7 3, 3 3))";
    let (json, _) = triangulate(&write(&dir, "hole.wkt", text), &[]);
    assert_eq!(vertices(&json).len(), 8);
    assert_eq!(triangles(&json).len(), 8);

    let text = "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((20 0, 30 0, 30 10, 20 10, 20 0)))";
    let (json, _) = triangulate(&write(&dir, "multi.txt", text), &[]);
    assert_eq!(triangles(&json).len(), 4);

    let text = "GEOMETRYCOLLECTION (POINT Z (1 2 3), POLYGON Z ((0 0 1, 10 0 1, 10 10 1, 0 0 1)))";
    let (json, stderr) = triangulate(&write(&dir, "collection.wkt", text), &[]);
    assert_eq!(vertices(&json), vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0]]);
    assert_eq!(triangles(&json).len(), 1);
    assert!(stderr.contains("Point"), "{stderr}");
}

#[test]
fn f32_precision_triangulates_and_keeps_the_parsed_vertices() {
    let dir = scratch("triangulate", "f32");
    let file = write(
        &dir,
        "hole.json",
        "[[[0.1,0],[10,0],[10,10],[0,10]],[[3,3],[3,7],[7,7],[7,3]]]",
    );
    let (json, _) = triangulate(&file, &["--precision", "f32"]);
    assert_eq!(triangles(&json).len(), 8);
    // The output has the file's f64 value, not 0.1f32 widened.
    assert_eq!(vertices(&json)[0], [0.1, 0.0]);

    // Finite in f64, infinite in f32: refused with the reason.
    let file = write(&dir, "huge.json", "[[[0,0],[1e300,0],[1,1]]]");
    let message = refused(&file, &["--precision", "f32"]);
    assert!(
        message.contains("ring 0, vertex 1: coordinate out of f32 range"),
        "{message}"
    );
}

#[test]
fn svg_output_to_a_file_and_to_stdout() {
    let dir = scratch("triangulate", "svg");
    let file = write(&dir, "hole.json", SQUARE_WITH_HOLE);
    let svg = dir.join("out.svg");
    let out = polytri(&[
        "triangulate",
        file.to_str().unwrap(),
        "-o",
        svg.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(out.status.success());
    assert!(
        out.stdout.is_empty() && out.stderr.is_empty(),
        "quiet, result in the file"
    );
    let text = fs::read_to_string(&svg).expect("svg written");
    assert!(text.starts_with("<svg "), "{text}");
    assert!(text.trim_end().ends_with("</svg>"));
    assert_eq!(
        text.matches("<polygon ").count(),
        8,
        "one polygon per triangle"
    );
    assert_eq!(text.matches("<path class=\"outer\"").count(), 1);
    assert_eq!(text.matches("<path class=\"hole\"").count(), 1);
    assert_eq!(
        text.matches('<').count(),
        text.matches('>').count(),
        "balanced tags"
    );

    let out = polytri(&["triangulate", file.to_str().unwrap(), "--format", "svg"]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("<svg "));

    // --format wins over the file name.
    let json = dir.join("out2.svg");
    let out = polytri(&[
        "triangulate",
        file.to_str().unwrap(),
        "-o",
        json.to_str().unwrap(),
        "--format",
        "json",
    ]);
    assert!(out.status.success());
    assert!(fs::read_to_string(&json)
        .expect("written")
        .starts_with("{\"vertices\""));
}

#[test]
fn shared_fixture_building_as_svg() {
    let fixture = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/fixtures/earcut/fixtures/building.json");
    if !fixture.exists() {
        eprintln!("skipped: {} is not here", fixture.display());
        return;
    }
    let dir = scratch("triangulate", "building");
    let svg = dir.join("building.svg");
    let out = polytri(&[
        "triangulate",
        fixture.to_str().unwrap(),
        "--format",
        "svg",
        "-o",
        svg.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = fs::read_to_string(&svg).expect("svg written");
    // 15 points, no holes: n - 2 triangles over the n vertices kept (earcut keeps a
    // collinear one and makes 13; polytri may drop it, drawn as a dot).
    let dropped = text.matches("<circle ").count();
    assert_eq!(text.matches("<polygon ").count(), 15 - dropped - 2);
    assert_eq!(text.matches("<path class=\"outer\"").count(), 1);
}

#[test]
fn missing_file_is_one_line() {
    let dir = scratch("triangulate", "missing");
    let message = refused(&dir.join("no-such-file.json"), &[]);
    assert!(
        message.contains("no-such-file.json: cannot read"),
        "{message}"
    );
}

#[test]
fn malformed_json_names_line_and_column() {
    let dir = scratch("triangulate", "malformed");
    let message = refused(&write(&dir, "bad.json", "[[[0,0],\n[1,0],,[1,1]]]"), &[]);
    assert!(
        message.contains("bad.json: invalid JSON") && message.contains("line 2 column"),
        "{message}"
    );

    let message = refused(
        &write(
            &dir,
            "string.geojson",
            r#"{"type":"Polygon","coordinates":[[[0,0],[1,"NaN"],[1,1]]]}"#,
        ),
        &[],
    );
    assert!(
        message.contains("invalid GeoJSON") && message.contains("column"),
        "{message}"
    );

    let message = refused(&write(&dir, "short.json", "[[[0,0],[1],[1,1]]]"), &[]);
    assert!(message.contains("invalid rings JSON"), "{message}");
}

#[test]
fn nan_coordinates_are_refused() {
    let dir = scratch("triangulate", "nan");
    let message = refused(
        &write(&dir, "nan.wkt", "POLYGON ((0 0, 10 0, nan 10, 0 0))"),
        &[],
    );
    assert!(
        message.contains("line 1, column 22: `nan` where a number belongs"),
        "{message}"
    );

    // A sign makes the wkt crate read `-nan` as a number; then the triangulator refuses it.
    let message = refused(
        &write(&dir, "signed.wkt", "POLYGON ((0 0, 10 0, -nan 10, 0 10))"),
        &[],
    );
    assert!(
        message.contains("ring 0, vertex 2: coordinate is NaN or infinite"),
        "{message}"
    );
}

#[test]
fn bow_tie_is_refused_strictly_and_repaired_leniently() {
    let dir = scratch("triangulate", "bow_tie");
    let file = write(&dir, "bowtie.json", "[[[0,0],[10,10],[10,0],[0,10]]]");
    let message = refused(&file, &[]);
    assert!(
        message.contains("edges cross") && message.contains("ring 0, vertex"),
        "{message}"
    );
    assert!(message.contains("--lenient"), "{message}");
    assert!(message.contains("--fill-rule even-odd"), "{message}");

    let (json, stderr) = triangulate(&file, &["--lenient"]);
    assert!(!triangles(&json).is_empty());
    assert!(stderr.contains("repair"), "{stderr}");
}

#[test]
fn misplaced_hole_names_polygon_and_ring() {
    let dir = scratch("triangulate", "misplaced_hole");
    let text = format!("[{SQUARE}, [[[20,0],[30,0],[30,10],[20,10]], [[40,0],[41,0],[41,1]]]]");
    let file = write(&dir, "shapes.json", &text);
    let message = refused(&file, &["--nesting", "first-outer"]);
    assert!(message.contains("polygon 1, ring 1"), "{message}");
    let (json, _) = triangulate(&file, &["--nesting", "first-outer", "--lenient"]);
    assert!(triangles(&json).len() >= 4);
}

#[test]
fn unwritable_output_is_one_line() {
    let dir = scratch("triangulate", "unwritable");
    let file = write(&dir, "square.json", SQUARE);
    let out = polytri(&[
        "triangulate",
        file.to_str().unwrap(),
        "-o",
        dir.join("no/such/dir.json").to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.contains("cannot write"), "{stderr}");
}

#[test]
fn bad_usage_exits_2() {
    assert_eq!(polytri(&["triangulate"]).status.code(), Some(2));
    assert_eq!(
        polytri(&["triangulate", "x.json", "--strategy", "slow"])
            .status
            .code(),
        Some(2)
    );
}

/// Odd but readable inputs: exit 0 or 1, never a panic or a crash.
#[test]
fn odd_inputs_never_panic() {
    let dir = scratch("triangulate", "odd");
    let cases = [
        "",
        "[]",
        "[[]]",
        "[[[]]]",
        "[[[1,2]]]",
        "[[[0,0],[1,1],[2,2]]]",
        "[[[0,0],[0,0],[0,0],[0,0]]]",
        "[[[1e308,1e308],[-1e308,1e308],[0,-1e308]]]",
        "[[[[[[0,0]]]]]]",
        "{}",
        "null",
        r#"{"type":"Polygon","coordinates":[]}"#,
        r#"{"type":"Polygon","coordinates":[[[0,0]]]}"#,
        r#"{"type":"FeatureCollection","features":[]}"#,
        "POLYGON EMPTY",
        "POLYGON ((0 0, 1 1))",
        "POLYGON ((0 0, 1 0, +inf 1, 0 0))",
        "MULTIPOLYGON (((",
        ")",
    ];
    for (k, text) in cases.iter().enumerate() {
        let file = write(&dir, &format!("case{k}.json"), text);
        for extra in [
            &[][..],
            &["--lenient"],
            &["--precision", "f32", "--format", "svg"],
        ] {
            let mut args = vec!["triangulate", file.to_str().unwrap()];
            args.extend_from_slice(extra);
            let out = polytri(&args);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert!(
                matches!(out.status.code(), Some(0 | 1)),
                "{text:?} {extra:?}: {:?} {stderr}",
                out.status
            );
            assert!(!stderr.contains("panicked"), "{text:?} {extra:?}: {stderr}");
            if out.status.code() == Some(1) {
                assert_eq!(stderr.lines().count(), 1, "{text:?} {extra:?}: {stderr}");
            }
        }
    }
}

#[test]
fn threads_do_not_change_the_result() {
    // the paper's page of Latin text: 54 glyph polygons, each triangulated on its own
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../corpus/datasets/lorem_latin.json");
    let runs: Vec<Value> = ["1", "2", "0"]
        .into_iter()
        .map(|threads| triangulate(&file, &["--nesting", "first-outer", "--threads", threads]).0)
        .collect();
    assert!(triangles(&runs[0]).len() > 1000);
    assert!(runs.iter().all(|r| r == &runs[0]));
    // and an error names the same polygon whichever thread met it
    let dir = scratch("triangulate", "threads");
    let text = format!(
        "[{SQUARE}, {SQUARE}, [[[20,0],[30,0],[30,10],[20,10]], [[40,0],[41,0],[41,1]]], {SQUARE}]"
    );
    let file = write(&dir, "shapes.json", &text);
    for threads in ["1", "2"] {
        let message = refused(&file, &["--nesting", "first-outer", "--threads", threads]);
        assert!(message.contains("polygon 2, ring 1"), "{message}");
    }
}

/// A FeatureCollection of features, each `(id, name, polygon coordinates JSON)`.
fn collection(features: &[(&str, &str, &str)]) -> String {
    let features: Vec<String> = features
        .iter()
        .map(|(id, name, coordinates)| {
            format!(
                r#"{{"type": "Feature", "id": "{id}", "properties": {{"name": "{name}"}},
                    "geometry": {{"type": "Polygon", "coordinates": {coordinates}}}}}"#
            )
        })
        .collect();
    format!(
        r#"{{"type": "FeatureCollection", "features": [{}]}}"#,
        features.join(",")
    )
}

#[test]
fn each_polygon_on_its_own_unless_merged() {
    let dir = scratch("triangulate", "per_polygon");
    // two overlapping squares, as neighbouring counties of a layer often are
    let text = collection(&[
        ("a", "West", "[[[0,0],[10,0],[10,10],[0,10],[0,0]]]"),
        ("b", "East", "[[[9,-1],[20,-1],[20,11],[9,11],[9,-1]]]"),
    ]);
    let file = write(&dir, "layer.geojson", &text);
    let (json, _) = triangulate(&file, &[]);
    assert_eq!(triangles(&json).len(), 4);
    let message = refused(&file, &["--merge"]);
    assert!(message.contains("edges cross"), "{message}");
    // within a polygon, rings in any order: the hole first, both wound alike
    let text = r#"[[[3,3],[7,3],[7,7],[3,7]], [[0,0],[10,0],[10,10],[0,10]]]"#;
    let file = write(&dir, "hole_first.json", text);
    let (json, _) = triangulate(&file, &[]);
    assert_eq!(triangles(&json).len(), 8);
}

#[test]
fn keep_going_writes_the_valid_features_as_geojson() {
    let dir = scratch("triangulate", "keep_going");
    let text = collection(&[
        ("a", "First", "[[[0,0],[10,0],[10,10],[0,10],[0,0]]]"),
        ("bad", "Bow tie", "[[[20,0],[30,10],[30,0],[20,10],[20,0]]]"),
        (
            "c",
            "Framed",
            "[[[40,0],[50,0],[50,10],[40,10],[40,0]], [[43,3],[43,7],[47,7],[47,3],[43,3]]]",
        ),
    ]);
    let file = write(&dir, "layer.geojson", &text);
    let out_path = dir.join("out.geojson");
    let out = polytri(&[
        "triangulate",
        file.to_str().expect("utf-8"),
        "--keep-going",
        "-o",
        out_path.to_str().expect("utf-8"),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("polygon 1") && stderr.contains("edges cross"),
        "{stderr}"
    );
    assert!(stderr.contains("1 polygon of 3 refused"), "{stderr}");
    let written: Value =
        serde_json::from_str(&std::fs::read_to_string(&out_path).expect("output")).expect("JSON");
    let features = written["features"].as_array().expect("features");
    let ids: Vec<&str> = features.iter().filter_map(|f| f["id"].as_str()).collect();
    assert_eq!(ids, ["a", "c"]);
    assert_eq!(features[1]["properties"]["name"], "Framed");
    let count = |f: &Value| f["geometry"]["coordinates"].as_array().map_or(0, Vec::len);
    assert_eq!((count(&features[0]), count(&features[1])), (2, 8));
    // every triangle a closed ring of four positions, its area the polygon's share
    let area: f64 = features[1]["geometry"]["coordinates"]
        .as_array()
        .expect("polygons")
        .iter()
        .map(|polygon| {
            let p: Vec<[f64; 2]> = serde_json::from_value(polygon[0].clone()).expect("ring");
            assert_eq!((p.len(), p[0]), (4, p[3]));
            ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]))
                / 2.0
        })
        .sum();
    assert_eq!(area, 100.0 - 16.0);
    // without --keep-going the first refusal stops everything
    let message = refused(&file, &[]);
    assert!(message.contains("polygon 1"), "{message}");
}

#[test]
fn per_triangle_features_keep_their_properties() {
    let dir = scratch("triangulate", "per_triangle");
    let text = collection(&[("sq", "Square", "[[[0,0],[10,0],[10,10],[0,10],[0,0]]]")]);
    let file = write(&dir, "one.geojson", &text);
    let (json, _) = triangulate(&file, &["--format", "geojson", "--per-triangle"]);
    let features = json["features"].as_array().expect("features");
    assert_eq!(features.len(), 2);
    assert!(features
        .iter()
        .all(|f| f["id"] == "sq" && f["properties"]["name"] == "Square"));
    assert!(features.iter().all(|f| f["geometry"]["type"] == "Polygon"));
}

#[test]
fn a_wall_in_3d_keeps_its_z_in_json_obj_and_geojson() {
    let dir = scratch("triangulate", "wall_3d");
    // a wall in the plane x = 2, with a window
    let wall = "[[[2,0,0],[2,6,0],[2,6,3],[2,0,3]], [[2,2,1],[2,2,2],[2,4,2],[2,4,1]]]";
    let file = write(&dir, "wall.json", wall);
    let (json, stderr) = triangulate(&file, &[]);
    assert!(stderr.contains("8 triangles"), "{stderr}");
    let v = json["vertices"].as_array().expect("vertices");
    assert_eq!(v[2], serde_json::json!([2.0, 6.0, 3.0]));
    assert_eq!(triangles(&json).len(), 8);
    // OBJ: every vertex with its z, faces 1-based
    let obj = dir.join("wall.obj");
    let out = polytri(&[
        "triangulate",
        file.to_str().expect("utf-8"),
        "-o",
        obj.to_str().expect("utf-8"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&obj).expect("obj");
    assert_eq!(text.lines().filter(|l| l.starts_with("v ")).count(), 8);
    assert!(text.lines().any(|l| l == "v 2 6 3"), "{text}");
    let faces: Vec<&str> = text.lines().filter(|l| l.starts_with("f ")).collect();
    assert_eq!(faces.len(), 8);
    assert!(faces.iter().all(|f| !f.split(' ').any(|i| i == "0")));
    // a bent wall is refused, or triangulated anyway with --lenient
    let bent = "[[[2,0,0],[2,6,0],[2,6,3],[2.5,0,3]]]";
    let file = write(&dir, "bent.json", bent);
    assert!(refused(&file, &[]).contains("not planar"));
    let (json, _) = triangulate(&file, &["--lenient"]);
    assert_eq!(triangles(&json).len(), 2);
    // WKT with Z
    let wkt =
        "POLYGON Z ((2 0 0, 2 6 0, 2 6 3, 2 0 3, 2 0 0), (2 2 1, 2 2 2, 2 4 2, 2 4 1, 2 2 1))";
    let file = write(&dir, "wall.wkt", wkt);
    let (json, _) = triangulate(&file, &[]);
    assert_eq!(triangles(&json).len(), 8);
    assert_eq!(json["vertices"][2], serde_json::json!([2.0, 6.0, 3.0]));
    // GeoJSON positions of three numbers
    let text = collection(&[("w", "Wall", "[[[2,0,0],[2,6,0],[2,6,3],[2,0,3],[2,0,0]]]")]);
    let file = write(&dir, "wall.geojson", &text);
    let (json, _) = triangulate(&file, &["--format", "geojson"]);
    let first = &json["features"][0]["geometry"]["coordinates"][0][0][0];
    assert_eq!(first.as_array().map(Vec::len), Some(3));
    // a layer mixing a wall with z and a footprint without: each in its own plane, the
    // footprint in z = 0
    let text = collection(&[
        ("w", "Wall", "[[[2,0,0],[2,6,0],[2,6,3],[2,0,3],[2,0,0]]]"),
        ("f", "Footprint", "[[[10,0],[14,0],[14,4],[10,4],[10,0]]]"),
    ]);
    let file = write(&dir, "mixed.geojson", &text);
    let (json, stderr) = triangulate(&file, &["--format", "geojson"]);
    assert!(stderr.contains("4 triangles"), "{stderr}");
    let polygons = |k: usize| {
        json["features"][k]["geometry"]["coordinates"]
            .as_array()
            .map(Vec::len)
    };
    assert_eq!((polygons(0), polygons(1)), (Some(2), Some(2)), "{json}");
}

#[test]
fn a_county_layer_by_the_defaults() {
    // the worked example of docs/gis: 254 counties, each triangulated on its own
    let layer = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/gis/texas-counties.geojson");
    let dir = scratch("triangulate", "county_layer");
    let result = dir.join("texas.json");
    let out = polytri(&[
        "triangulate",
        layer.to_str().expect("utf-8"),
        "-o",
        result.to_str().expect("utf-8"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // the oracle, county by county: every county's triangles exactly cover it
    let out = polytri(&[
        "check",
        layer.to_str().expect("utf-8"),
        result.to_str().expect("utf-8"),
        "--fast",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let verdict: Value = serde_json::from_slice(&out.stdout).expect("verdict");
    assert_eq!(verdict["valid"], true);
    assert_eq!(verdict["triangles"], verdict["expected_triangles"]);
    // GeoJSON out: one feature per county, in order, with its id and properties
    let (json, _) = triangulate(&layer, &["--format", "geojson"]);
    let input: Value =
        serde_json::from_str(&std::fs::read_to_string(&layer).expect("layer")).expect("JSON");
    let ids = |v: &Value| -> Vec<Value> {
        v["features"]
            .as_array()
            .expect("features")
            .iter()
            .map(|f| f["id"].clone())
            .collect()
    };
    assert_eq!(ids(&json).len(), 254);
    assert_eq!(ids(&json), ids(&input));
    assert_eq!(
        json["features"][0]["properties"],
        input["features"][0]["properties"]
    );
}
