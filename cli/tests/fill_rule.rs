//! `polytri triangulate --fill-rule`: crossing rings read by their winding numbers, with the
//! vertices added where edges cross in every output format.

mod common;

use std::fs;
use std::path::Path;

use serde_json::Value;

use common::{polytri, scratch, write};

/// The pentagram {5/2}, counter-clockwise: every second corner of a regular pentagon.
const PENTAGRAM: &str = "[[[0, 100], [-59, -81], [95, 31], [-95, 31], [59, -81]]]";

/// Runs `polytri triangulate FILE EXTRA…`, expects success, returns stdout and stderr.
fn triangulate(file: &Path, extra: &[&str]) -> (String, String) {
    let mut args = vec!["triangulate", file.to_str().expect("utf-8 path")];
    args.extend_from_slice(extra);
    let out = polytri(&args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "polytri {args:?} failed: {stderr}");
    (String::from_utf8(out.stdout).expect("utf-8"), stderr)
}

fn json(file: &Path, extra: &[&str]) -> Value {
    serde_json::from_str(&triangulate(file, extra).0).expect("stdout is JSON")
}

fn len(json: &Value, key: &str) -> usize {
    json[key].as_array().map_or(0, Vec::len)
}

/// Every index of the JSON's triangles, and of its added vertices' `vertex` and `edges`.
fn indices(json: &Value) -> (Vec<u64>, Vec<(u64, [u64; 2])>) {
    let triangles = (json["triangles"].as_array().expect("triangles").iter())
        .flat_map(|t| t.as_array().expect("triangle").iter())
        .map(|i| i.as_u64().expect("index"))
        .collect();
    let added = (json["added"].as_array().expect("added").iter())
        .map(|a| {
            let e = |k: usize| a["edges"][k].as_u64().expect("edge");
            (a["vertex"].as_u64().expect("vertex"), [e(0), e(1)])
        })
        .collect();
    (triangles, added)
}

#[test]
fn pentagram_even_odd_and_nonzero() {
    let dir = scratch("fill", "pentagram");
    let file = write(&dir, "pentagram.json", PENTAGRAM);
    // even-odd: the five points (the centre winds twice); nonzero: the whole star
    for (rule, triangles) in [("even-odd", 5), ("nonzero", 8)] {
        for strategy in ["fast", "quality"] {
            for precision in ["f64", "f32"] {
                let args = [
                    "--fill-rule",
                    rule,
                    "--strategy",
                    strategy,
                    "--precision",
                    precision,
                ];
                let out = json(&file, &args);
                assert_eq!(len(&out, "triangles"), triangles, "{args:?}: {out}");
                assert_eq!(len(&out, "added"), 5, "{args:?}: {out}");
                assert_eq!(len(&out, "vertices"), 10, "{args:?}: {out}");
                let (used, added) = indices(&out);
                assert!(used.iter().all(|&i| i < 10), "{out}");
                for (k, (vertex, edges)) in added.iter().enumerate() {
                    assert_eq!(*vertex, 5 + k as u64, "{out}");
                    assert!(edges.iter().all(|&e| e < 5), "{out}");
                }
                if rule == "even-odd" {
                    // every point of the star is a triangle with two added corners
                    for t in out["triangles"].as_array().expect("triangles") {
                        let added = (t.as_array().expect("triangle").iter())
                            .filter(|i| i.as_u64() >= Some(5))
                            .count();
                        assert_eq!(added, 2, "{out}");
                    }
                }
            }
        }
    }
    // the other rules: the star again, nothing (it winds counter-clockwise), the centre
    for (rule, triangles) in [("positive", 8), ("negative", 0), ("abs-geq-two", 3)] {
        let out = json(&file, &["--fill-rule", rule]);
        assert_eq!(len(&out, "triangles"), triangles, "{rule}: {out}");
    }
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn without_a_fill_rule_the_json_is_unchanged_and_the_pentagram_refused() {
    let dir = scratch("fill", "unchanged");
    let square = write(&dir, "square.json", "[[[0, 0], [2, 0], [2, 2], [0, 2]]]");
    let out = json(&square, &[]);
    assert!(out.get("added").is_none(), "{out}");
    // with a fill rule and nothing crossing: an empty list, nothing added
    let out = json(&square, &["--fill-rule", "nonzero"]);
    assert_eq!(out["added"], Value::Array(Vec::new()), "{out}");
    assert_eq!(len(&out, "vertices"), 4);
    assert_eq!(len(&out, "triangles"), 2);
    let pentagram = write(&dir, "pentagram.json", PENTAGRAM);
    let refused = polytri(&["triangulate", pentagram.to_str().expect("utf-8")]);
    assert_eq!(refused.status.code(), Some(1));
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn added_vertices_follow_all_the_file_s_vertices_across_polygons() {
    let dir = scratch("fill", "pieces");
    // shapes JSON: the pentagram, then a bow tie far away (its crossing at (501, 1))
    let shapes = format!("[{PENTAGRAM}, [[[500, 0], [502, 2], [502, 0], [500, 2]]]]");
    let file = write(&dir, "shapes.json", &shapes);
    for merge in [false, true] {
        let extra: &[&str] = if merge {
            &["--fill-rule", "nonzero", "--merge"]
        } else {
            &["--fill-rule", "nonzero"]
        };
        let out = json(&file, extra);
        // 9 file vertices, 5 + 1 added
        assert_eq!(len(&out, "vertices"), 15, "{out}");
        assert_eq!(len(&out, "triangles"), 8 + 2, "{out}");
        let (used, added) = indices(&out);
        assert!(used.iter().all(|&i| i < 15));
        let numbers: Vec<u64> = added.iter().map(|a| a.0).collect();
        assert_eq!(numbers, (9..15).collect::<Vec<_>>(), "{out}");
        // the bow tie's crossing, and its edges named by the file's vertex numbers
        let bow_tie = added
            .iter()
            .find(|(v, _)| out["vertices"][*v as usize] == serde_json::json!([501.0, 1.0]))
            .expect("the bow tie's crossing");
        let mut edges = bow_tie.1;
        edges.sort_unstable();
        assert_eq!(edges, [5, 7], "{out}");
        // both bow-tie triangles use it
        let at = bow_tie.0;
        let uses = (out["triangles"].as_array().expect("triangles").iter())
            .filter(|t| {
                t.as_array()
                    .is_some_and(|t| t.iter().any(|i| i.as_u64() == Some(at)))
            })
            .count();
        assert_eq!(uses, 2, "{out}");
    }
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn svg_obj_and_geojson_use_the_added_vertices() {
    let dir = scratch("fill", "formats");
    let file = write(&dir, "pentagram.json", PENTAGRAM);
    let (svg, _) = triangulate(&file, &["--fill-rule", "even-odd", "--format", "svg"]);
    let dots = svg
        .split(r#"<g class="added">"#)
        .nth(1)
        .expect("added group");
    let dots = &dots[..dots.find("</g>").expect("closed")];
    assert_eq!(dots.matches("<circle ").count(), 5, "{svg}");
    assert_eq!(svg.matches("<polygon ").count(), 5, "{svg}");

    let (obj, _) = triangulate(&file, &["--fill-rule", "nonzero", "--format", "obj"]);
    assert_eq!(
        obj.lines().filter(|l| l.starts_with("v ")).count(),
        10,
        "{obj}"
    );
    let faces: Vec<&str> = obj.lines().filter(|l| l.starts_with("f ")).collect();
    assert_eq!(faces.len(), 8, "{obj}");
    assert!(
        faces
            .iter()
            .any(|f| f.split(' ').any(|i| i.parse() == Ok(10))),
        "{obj}"
    );

    let (geojson, _) = triangulate(
        &file,
        &["--fill-rule", "abs-geq-two", "--format", "geojson"],
    );
    let geojson: Value = serde_json::from_str(&geojson).expect("GeoJSON");
    let polygons = &geojson["features"][0]["geometry"]["coordinates"];
    assert_eq!(polygons.as_array().map(Vec::len), Some(3), "{geojson}");
    // the centre pentagon's corners are all crossing points, none a corner of the star
    let corners: Vec<[i64; 2]> = vec![[0, 100], [-59, -81], [95, 31], [-95, 31], [59, -81]];
    for triangle in polygons.as_array().expect("polygons") {
        for p in triangle[0].as_array().expect("ring") {
            let p = [p[0].as_f64().expect("x"), p[1].as_f64().expect("y")];
            assert!(
                !corners.iter().any(|c| [c[0] as f64, c[1] as f64] == p),
                "{p:?}"
            );
        }
    }
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn usage_help_and_conflicts() {
    let help = polytri(&["triangulate", "--help"]);
    let help = String::from_utf8_lossy(&help.stdout);
    for word in [
        "--fill-rule",
        "even-odd",
        "nonzero",
        "positive",
        "negative",
        "abs-geq-two",
    ] {
        assert!(help.contains(word), "{word} not in {help}");
    }
    assert!(help.contains("winding number"), "{help}");

    let dir = scratch("fill", "usage");
    let file = write(&dir, "pentagram.json", PENTAGRAM);
    let path = file.to_str().expect("utf-8");
    // --lenient does not apply with a fill rule; an unknown rule is bad usage
    for bad in [
        &["triangulate", path, "--fill-rule", "nonzero", "--lenient"][..],
        &["triangulate", path, "--fill-rule", "odd"][..],
    ] {
        assert_eq!(polytri(bad).status.code(), Some(2), "{bad:?}");
    }
    // rings in 3D have no fill rule: the added points would have no z
    let wall = write(
        &dir,
        "wall.json",
        "[[[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]]",
    );
    let out = polytri(&[
        "triangulate",
        wall.to_str().expect("utf-8"),
        "--fill-rule",
        "nonzero",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("--fill-rule takes rings in the plane"),
        "{stderr}"
    );
    // a NaN is still refused, without the --lenient hint
    let nan = write(&dir, "nan.wkt", "POLYGON ((0 0, 10 0, -nan 10, 0 10))");
    let out = polytri(&[
        "triangulate",
        nan.to_str().expect("utf-8"),
        "--fill-rule",
        "nonzero",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(!stderr.contains("--lenient"), "{stderr}");
    let _ = fs::remove_dir_all(dir);
}

/// `polytri check --fill-rule` judges what `triangulate --fill-rule` wrote, per polygon and
/// merged, and rejects it under the other rule or with a triangle taken away.
#[test]
fn check_judges_fill_rule_results() {
    let dir = scratch("fill", "check");
    let shapes = format!("[{PENTAGRAM}, [[[500, 0], [502, 2], [502, 0], [500, 2]]]]");
    let file = write(&dir, "shapes.json", &shapes);
    let path = |p: &Path| p.to_str().expect("utf-8 path").to_owned();
    for merge in [false, true] {
        let mut extra = vec!["--fill-rule", "nonzero"];
        if merge {
            extra.push("--merge");
        }
        let (text, _) = triangulate(&file, &extra);
        let result = write(&dir, "result.json", &text);
        let check = |rule: &str, result: &Path| {
            let mut args = vec!["check".to_owned(), path(&file), path(result)];
            args.extend(["--fast", "--fill-rule", rule].map(str::to_owned));
            if merge {
                args.push("--merge".to_owned());
            }
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            polytri(&args)
        };
        let ok = check("nonzero", &result);
        let stderr = String::from_utf8_lossy(&ok.stderr);
        assert!(ok.status.success(), "merge {merge}: {stderr}");
        let verdict: Value = serde_json::from_slice(&ok.stdout).expect("verdict JSON");
        assert_eq!(verdict["valid"], true, "{verdict}");
        // even-odd leaves the pentagon out: the nonzero triangles cover too much
        let wrong = check("even-odd", &result);
        assert_eq!(wrong.status.code(), Some(1), "merge {merge}");
        // one triangle fewer: the region is not covered
        let mut json: Value = serde_json::from_str(&text).expect("result JSON");
        json["triangles"].as_array_mut().expect("triangles").pop();
        let short = write(&dir, "short.json", &json.to_string());
        let short = check("nonzero", &short);
        assert_eq!(short.status.code(), Some(1), "merge {merge}");
        assert!(
            String::from_utf8_lossy(&short.stderr).contains("area"),
            "{}",
            String::from_utf8_lossy(&short.stderr)
        );
    }
    let _ = fs::remove_dir_all(dir);
}

/// A result of `triangulate --precision f32` is judged against the input as rounded to
/// `f32` (`check --precision f32`): the crossing points were found between the rounded
/// points, so against the points as written their triangles cover the wrong area.
#[test]
fn check_judges_f32_results_against_the_rounded_input() {
    let dir = scratch("fill", "check_f32");
    // a pentagram whose points are no f32 values: rounding moves every one of them
    let shapes = "[[[0.1, 100.3], [-59.3, -81.7], [95.1, 31.3], [-95.1, 31.7], [59.3, -81.1]]]";
    let file = write(&dir, "shapes.json", shapes);
    let path = |p: &Path| p.to_str().expect("utf-8 path").to_owned();
    for rule in [None, Some("even-odd"), Some("nonzero")] {
        let mut extra = vec!["--precision", "f32"];
        extra.extend(rule.map(|r| ["--fill-rule", r]).into_iter().flatten());
        if rule.is_none() {
            // strict mode refuses the crossing star: lenient takes it
            extra.push("--lenient");
        }
        let (text, _) = triangulate(&file, &extra);
        let result = write(&dir, "result.json", &text);
        let check = |precision: &str| {
            let mut args = vec!["check".to_owned(), path(&file), path(&result)];
            args.extend(["--fast", "--precision", precision].map(str::to_owned));
            args.extend(
                rule.map(|r| ["--fill-rule".to_owned(), r.to_owned()])
                    .into_iter()
                    .flatten(),
            );
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            polytri(&args)
        };
        let f32 = check("f32");
        let stderr = String::from_utf8_lossy(&f32.stderr);
        if let Some(rule) = rule {
            assert!(f32.status.success(), "{rule}: {stderr}");
            let wrong = check("f64");
            let stderr = String::from_utf8_lossy(&wrong.stderr);
            assert_eq!(wrong.status.code(), Some(1), "{rule}: {stderr}");
            assert!(stderr.contains("area"), "{rule}: {stderr}");
        } else {
            // lenient triangles of crossing input are no valid triangulation of it, but
            // they are judged: the vertices are the input's, as rounded
            assert!(!stderr.contains("not of this input"), "{stderr}");
        }
    }
    // a result listing the points as rounded is of this input too
    let (text, _) = triangulate(&file, &["--precision", "f32", "--fill-rule", "even-odd"]);
    let mut json: Value = serde_json::from_str(&text).expect("result JSON");
    for v in json["vertices"].as_array_mut().expect("vertices") {
        for c in v.as_array_mut().expect("vertex") {
            *c = Value::from(f64::from(c.as_f64().expect("coordinate") as f32));
        }
    }
    let result = write(&dir, "rounded.json", &json.to_string());
    let (file, result) = (path(&file), path(&result));
    let check = |extra: &[&str]| {
        let mut args = vec!["check", &file, &result, "--fast", "--fill-rule", "even-odd"];
        args.extend_from_slice(extra);
        polytri(&args)
    };
    let out = check(&["--precision", "f32"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // but not without --precision f32
    let out = check(&[]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("vertex 0 is"), "{stderr}");
    let _ = fs::remove_dir_all(dir);
}
