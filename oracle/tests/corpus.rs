//! The regression corpus (`corpus/earcut`, `corpus/paper`, `corpus/cases`,
//! `corpus/datasets`) replayed through polytri — both strategies, both precisions, rotations
//! 0/90/180/270°, strict and (for invalid inputs) lenient — judged by the oracle and pinned
//! as insta snapshots under `corpus/snapshots/`, one per case and strategy.
//!
//! What each run must satisfy is `polytri_oracle::replay`'s list; a changed triangulation
//! that still satisfies it shows up as a snapshot diff (`cargo insta review`, or
//! `INSTA_UPDATE=always cargo test -p polytri-oracle --test corpus` to accept all).
//! A new case file in one of the folders is picked up with no code change.

use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

use polytri_oracle::replay::{load_dir, replay_all, CorpusCase, Replay, STRATEGIES};
use serde_json::Value;

/// The corpus folders replayed, in order.
const FOLDERS: [&str; 4] = ["earcut", "paper", "cases", "datasets"];

/// Where the snapshots live, relative to this file (insta's convention).
const SNAPSHOT_PATH: &str = "../../corpus/snapshots";

fn corpus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../corpus")
}

fn cases() -> Vec<CorpusCase> {
    FOLDERS
        .iter()
        .flat_map(|folder| {
            load_dir(&corpus_dir().join(folder)).unwrap_or_else(|e| panic!("corpus/{folder}: {e}"))
        })
        .collect()
}

fn insta_settings() -> insta::Settings {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path(SNAPSHOT_PATH);
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    settings
}

/// Asserts every snapshot, collecting mismatches instead of stopping at the first, so one
/// run shows (and, with `INSTA_UPDATE`, writes) every change.
fn assert_snapshots(replays: &[Replay]) -> Vec<String> {
    let mut mismatched = Vec::new();
    insta_settings().bind(|| {
        for r in replays {
            let name = snapshot_name(r);
            let snapshot = &r.snapshot;
            let outcome = catch_unwind(AssertUnwindSafe(|| {
                insta::assert_json_snapshot!(name.clone(), snapshot);
            }));
            if outcome.is_err() {
                mismatched.push(name);
            }
        }
    });
    mismatched
}

fn snapshot_name(r: &Replay) -> String {
    // "folder/name" → "folder__name__strategy"
    format!(
        "{}__{}",
        r.snapshot.case.replacen('/', "__", 1),
        r.snapshot.strategy
    )
}

#[test]
fn corpus_replays_and_matches_its_snapshots() {
    let cases = cases();
    assert!(
        cases.iter().filter(|c| c.folder == "earcut").count() >= 59,
        "earcut's fixtures"
    );
    let replays = replay_all(&cases);
    print_notes(&replays);
    let mismatched = assert_snapshots(&replays);
    let failures: Vec<&String> = replays.iter().flat_map(|r| &r.failures).collect();
    let mut report = String::new();
    if !failures.is_empty() {
        report += &format!(
            "{} failure(s):\n{}\n",
            failures.len(),
            failures
                .iter()
                .map(|f| f.as_str())
                .collect::<Vec<_>>()
                .join("\n")
        );
    }
    if !mismatched.is_empty() {
        report += &format!(
            "{} snapshot(s) changed (review with `cargo insta review`): {}\n",
            mismatched.len(),
            mismatched.join(", ")
        );
    }
    assert!(report.is_empty(), "{report}");
}

/// Known failures, and the deviations measured on invalid inputs (what
/// `corpus/earcut/bounds.json` may be tightened to).
fn print_notes(replays: &[Replay]) {
    for r in replays.iter().filter(|r| !r.known_failures.is_empty()) {
        eprintln!(
            "known failure: {} {}: {} run(s) fail, first: {}",
            r.snapshot.case,
            r.snapshot.strategy,
            r.known_failures.len(),
            r.known_failures[0]
        );
    }
    let mut worst: BTreeMap<&str, [f64; 2]> = BTreeMap::new();
    for r in replays {
        for (&rotation, &dev) in &r.lenient_deviation {
            let w = worst.entry(&r.snapshot.case).or_default();
            let k = usize::from(rotation != 0);
            w[k] = w[k].max(dev);
        }
    }
    for (case, [rot0, rotated]) in worst {
        eprintln!(
            "note: {case}: lenient deviation at most {rot0:.3e} at 0°, {rotated:.3e} rotated"
        );
    }
}

/// Every snapshot file belongs to a case: a deleted or renamed case takes its snapshots
/// along.
#[test]
fn no_orphaned_snapshots() {
    let wanted: Vec<String> = cases()
        .iter()
        .flat_map(|c| STRATEGIES.map(|s| format!("{}.snap", c.snapshot_name(s))))
        .collect();
    let dir = corpus_dir().join("snapshots");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        return;
    };
    let mut orphans: Vec<String> = entries
        .filter_map(Result::ok)
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".snap") && !wanted.contains(n))
        .collect();
    orphans.sort();
    assert!(
        orphans.is_empty(),
        "snapshots without a case in corpus/ (delete them): {}",
        orphans.join(", ")
    );
}

/// `corpus/earcut/bounds.json` only ever tightens earcut's `expected.json`: each of our
/// bounds names a fixture and is below earcut's.
#[test]
fn our_bounds_only_tighten_earcuts() {
    let read = |file: &str| -> Value {
        let path = corpus_dir().join("earcut").join(file);
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{file}: {e}"));
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("{file}: {e}"))
    };
    let earcut = read("expected.json");
    let ours = read("bounds.json");
    let mut wrong = Vec::new();
    for table in ["errors", "errors-with-rotation"] {
        let Some(entries) = ours[table].as_object() else {
            continue;
        };
        for (name, bound) in entries {
            let earcut_bound = earcut[table]
                .get(name)
                .or_else(|| earcut["errors"].get(name))
                .and_then(Value::as_f64)
                .unwrap_or(0.0);
            if earcut["triangles"].get(name).is_none() {
                wrong.push(format!("{table}.{name}: no such fixture"));
            }
            match bound.as_f64() {
                Some(b) if b < earcut_bound => {}
                _ => wrong.push(format!(
                    "{table}.{name}: {bound} is not below earcut's {earcut_bound}"
                )),
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
