//! `polytri replay` and `polytri promote` end to end: the built binary on the corpus and on
//! scratch folders.

mod common;

use std::fs;
use std::path::{Path, PathBuf};

use polytri_oracle::Case;

use common::{polytri, scratch};

fn corpus() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../corpus")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

/// A square with a square hole, valid: 8 triangles.
const SQUARE_WITH_HOLE: &str = r#"{
  "name": "square_with_square_hole",
  "description": "a square with a square hole",
  "source": "polytri",
  "nesting": "first-outer",
  "rings": [[[0,0],[10,0],[10,10],[0,10]], [[3,3],[3,7],[7,7],[7,3]]],
  "expect": {"triangles": 8}
}"#;

#[test]
fn replays_the_papers_figures() {
    let paper = corpus().join("paper");
    let out = polytri(&["replay", s(&paper)]);
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{}\n{}", stdout, text(&out.stderr));
    let header = stdout.lines().next().expect("a header");
    for column in [
        "case",
        "strategy",
        "precision",
        "verdict",
        "deviation",
        "min angle",
    ] {
        assert!(header.contains(column), "{header}");
    }
    let mut cases = 0;
    for entry in fs::read_dir(&paper).expect("corpus/paper") {
        let name = entry
            .expect("entry")
            .file_name()
            .to_string_lossy()
            .into_owned();
        let Some(stem) = name.strip_suffix(".json") else {
            continue;
        };
        cases += 1;
        // One row per strategy and precision, each valid.
        let rows: Vec<&str> = stdout
            .lines()
            .filter(|l| l.starts_with(&format!("paper/{stem} ")))
            .collect();
        assert_eq!(rows.len(), 4, "{stem}: {rows:?}");
        assert!(rows.iter().all(|r| r.contains(" valid ")), "{rows:?}");
    }
    assert!(cases >= 10);
    assert!(
        text(&out.stderr).contains("all passed"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn a_broken_case_fails_the_replay() {
    let dir = scratch("replay", "broken").join("cases");
    fs::create_dir_all(&dir).unwrap();
    fs::write(dir.join("square_with_square_hole.json"), SQUARE_WITH_HOLE).unwrap();
    // Wrong count.
    let wrong_count = SQUARE_WITH_HOLE
        .replace("square_with_square_hole", "wrong_count")
        .replace("\"triangles\": 8", "\"triangles\": 9");
    fs::write(dir.join("wrong_count.json"), wrong_count).unwrap();
    let out = polytri(&["replay", s(&dir)]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stdout));
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("wrong_count fast f64 rot 0 strict: 8 triangles, expect.triangles says 9"),
        "{stderr}"
    );
    assert!(!stderr.contains("square_with_square_hole"), "{stderr}");
    let stdout = text(&out.stdout);
    let rows = |case: &str| -> Vec<&str> {
        stdout
            .lines()
            .filter(|l| l.starts_with(&format!("cases/{case} ")))
            .collect()
    };
    assert_eq!(rows("wrong_count").len(), 4, "{stdout}");
    assert!(
        rows("wrong_count").iter().all(|r| r.contains("FAIL")),
        "{stdout}"
    );
    assert!(
        rows("square_with_square_hole")
            .iter()
            .all(|r| r.contains(" valid ")),
        "{stdout}"
    );
    assert!(
        stderr
            .lines()
            .last()
            .unwrap_or("")
            .starts_with("polytri: error:"),
        "{stderr}"
    );
}

#[test]
fn a_crossing_input_said_to_be_valid_fails_the_replay() {
    let dir = scratch("replay", "crossing").join("cases");
    fs::create_dir_all(&dir).unwrap();
    // A bow tie: strict refuses it (right for an invalid input), but the case says the
    // input is valid.
    let bow_tie = r#"{"name": "bow_tie", "nesting": "auto",
        "rings": [[[0,0],[2,2],[2,0],[0,2]]], "expect": {"input_valid": true}}"#;
    fs::write(dir.join("bow_tie.json"), bow_tie).unwrap();
    let out = polytri(&["replay", s(&dir)]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stdout));
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("expect.input_valid is true, the oracle finds the input invalid"),
        "{stderr}"
    );
    // Without the claim, refusing in strict mode and repairing in lenient mode passes.
    fs::write(dir.join("bow_tie.json"), bow_tie.replace("true", "false")).unwrap();
    let out = polytri(&["replay", s(&dir)]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).contains("refused, lenient ok"),
        "{}",
        text(&out.stdout)
    );
}

/// A rings JSON whose first ring, a 4×4 square, lies inside its second, a 10×10 square.
const HOLE_FIRST: &str = "[[[3,3],[7,3],[7,7],[3,7]], [[0,0],[10,0],[10,10],[0,10]]]";

/// `polytri replay ARGS`: its exit status, stdout and stderr.
fn replay(args: &[&str]) -> (Option<i32>, String, String) {
    let out = polytri(&[&["replay"], args].concat());
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

/// The verdicts of `case`'s rows in a replay's table, one per strategy and precision.
fn verdicts<'a>(stdout: &'a str, case: &str) -> Vec<&'a str> {
    let rows: Vec<&str> = stdout
        .lines()
        .filter(|l| l.starts_with(&format!("cases/{case} ")))
        .collect();
    assert_eq!(rows.len(), 4, "{case}: {stdout}");
    rows
}

#[test]
fn nesting_applies_to_rings_files_not_to_cases() {
    let dir = scratch("replay", "nesting").join("cases");
    fs::create_dir_all(&dir).unwrap();
    fs::write(dir.join("hole_first.json"), HOLE_FIRST).unwrap();
    // the same rings as a case, which says its nesting itself
    let case = format!(
        r#"{{"name": "hole_first_case", "nesting": "first-outer", "rings": {HOLE_FIRST}}}"#
    );
    fs::write(dir.join("hole_first_case.json"), case).unwrap();
    // auto, the default: containment makes the big square outer and the small one its
    // hole; first-outer: the small square is outer and the big one a hole outside it, an
    // invalid input that strict mode refuses. The case keeps its first-outer either way.
    let refused = "refused, lenient ok";
    for (args, rings_file) in [
        (&[][..], " valid "),
        (&["--nesting", "first-outer"][..], refused),
    ] {
        let (status, stdout, stderr) = replay(&[args, &[s(&dir)]].concat());
        assert_eq!(status, Some(0), "{args:?}: {stdout}\n{stderr}");
        let rows = verdicts(&stdout, "hole_first");
        assert!(
            rows.iter().all(|r| r.contains(rings_file)),
            "{args:?}: {stdout}"
        );
        let rows = verdicts(&stdout, "hole_first_case");
        assert!(
            rows.iter().all(|r| r.contains(refused)),
            "{args:?}: {stdout}"
        );
    }
}

#[test]
fn merge_takes_the_rings_of_a_shapes_file_as_one_set() {
    let dir = scratch("replay", "merge").join("cases");
    fs::create_dir_all(&dir).unwrap();
    // two polygons, the second inside the first
    let shapes = "[[[[0,0],[10,0],[10,10],[0,10]]], [[[3,3],[7,3],[7,7],[3,7]]]]";
    fs::write(dir.join("square_in_square.json"), shapes).unwrap();
    // each polygon on its own: two overlapping polygons, which one input cannot hold;
    // polytri (automatic nesting on the whole input) makes the inner one a hole, and the
    // replay says that strict mode should have refused
    let (status, stdout, stderr) = replay(&[s(&dir)]);
    assert_eq!(status, Some(1), "{stdout}");
    assert!(
        stderr.contains("strict mode accepted an invalid input"),
        "{stderr}"
    );
    // merged: one set of rings, the inner square a hole
    let (status, stdout, stderr) = replay(&["--merge", s(&dir)]);
    assert_eq!(status, Some(0), "{stdout}\n{stderr}");
    let rows = verdicts(&stdout, "square_in_square");
    assert!(rows.iter().all(|r| r.contains(" valid ")), "{stdout}");
}

#[test]
fn promote_round_trips_a_case() {
    let dir = scratch("replay", "promote");
    let found = dir.join("found.json");
    fs::write(&found, SQUARE_WITH_HOLE).unwrap();
    let to = dir.join("cases");
    let out = polytri(&[
        "promote",
        s(&found),
        "--name",
        "hole_in_the_middle",
        "--to",
        s(&to),
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let written = fs::read_to_string(to.join("hole_in_the_middle.json")).expect("promoted");
    let case = Case::from_json(&written).expect("a case");
    let original = Case::from_json(SQUARE_WITH_HOLE).unwrap();
    assert_eq!(case.name, "hole_in_the_middle");
    assert_eq!(case.input, original.input);
    assert_eq!(case.expect, original.expect);
    // The promoted folder replays with no further step.
    let out = polytri(&["replay", s(&to)]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("cases/hole_in_the_middle"));
    // No silent overwrite; --force replaces.
    let again = polytri(&[
        "promote",
        s(&found),
        "--name",
        "hole_in_the_middle",
        "--to",
        s(&to),
    ]);
    assert_eq!(again.status.code(), Some(1));
    assert!(
        text(&again.stderr).contains("exists already"),
        "{}",
        text(&again.stderr)
    );
    let forced = polytri(&[
        "promote",
        s(&found),
        "--name",
        "hole_in_the_middle",
        "--to",
        s(&to),
        "--force",
    ]);
    assert!(forced.status.success(), "{}", text(&forced.stderr));
}

#[test]
fn promote_refuses_what_is_not_a_case() {
    let dir = scratch("replay", "refuse");
    let junk = dir.join("junk.json");
    fs::write(&junk, "[1, 2, 3]").unwrap();
    let out = polytri(&["promote", s(&junk), "--to", s(&dir.join("cases"))]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("not a corpus case"),
        "{}",
        text(&out.stderr)
    );
    let found = dir.join("found.json");
    fs::write(&found, SQUARE_WITH_HOLE).unwrap();
    let out = polytri(&["promote", s(&found), "--name", "../escape", "--to", s(&dir)]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("plain file name"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn promote_decodes_a_fuzz_input() {
    let dir = scratch("replay", "fuzz");
    let raw = dir.join("crash-0123");
    // raw_rings' decoding: flags 2 (f64, small integer coordinates, sensible ring starts),
    // one ring (its size byte ignored), then the points (0, 0), (8, 0), (8, 8), (0, 8).
    let bytes: Vec<u8> = vec![2, 0, 5, 0, 0, 8, 0, 8, 8, 0, 8];
    fs::write(&raw, &bytes).unwrap();
    let to = dir.join("cases");
    let out = polytri(&[
        "promote",
        s(&raw),
        "--fuzz-target",
        "raw_rings",
        "--name",
        "raw_bytes_decode",
        "--to",
        s(&to),
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let case = Case::from_json(&fs::read_to_string(to.join("raw_bytes_decode.json")).unwrap())
        .expect("a case");
    assert_eq!(case.source, "fuzz:raw_rings");
    let expected = polytri_oracle::fuzz::decode_case("raw_rings", &bytes).expect("decodes");
    assert_eq!(case.input, expected.input);
    assert_eq!(
        case.input.vertices,
        [[0.0, 0.0], [8.0, 0.0], [8.0, 8.0], [0.0, 8.0]]
    );
    let out = polytri(&["replay", s(&to)]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let out = polytri(&[
        "promote",
        s(&raw),
        "--fuzz-target",
        "no_such_target",
        "--to",
        s(&to),
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("unknown fuzz target"),
        "{}",
        text(&out.stderr)
    );
}
