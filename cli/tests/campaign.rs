//! `polytri campaign` end to end: a short reproducible campaign passes and prints a row
//! for every family.

use std::path::PathBuf;
use std::process::{Command, Output};

use polytri_oracle::Family;

fn campaign(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_polytri"))
        .arg("campaign")
        .args(args)
        .output()
        .expect("run polytri campaign")
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("polytri-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn forty_cases_pass_with_a_row_per_family() {
    let out = scratch("campaign");
    let out_dir = out.display().to_string();
    let result = campaign(&["--cases", "40", "--max-vertices", "300", "--out", &out_dir]);
    let stdout = String::from_utf8_lossy(&result.stdout);
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(result.status.success(), "{stdout}\n{stderr}");
    let lines: Vec<&str> = stdout.lines().collect();
    for column in [
        "family",
        "cases",
        "runs",
        "failed",
        "f32 invalid",
        "CDT min°",
        "time s",
    ] {
        assert!(lines[0].contains(column), "{column}: {}", lines[0]);
    }
    for family in Family::ALL {
        assert!(
            lines.iter().any(|l| l.starts_with(&format!("{family} "))),
            "{family}:\n{stdout}"
        );
    }
    assert!(lines.iter().any(|l| l.starts_with("all ")), "{stdout}");
    assert!(stdout.contains("40 cases"), "{stdout}");
    assert!(stdout.contains("0 failing case(s)"), "{stdout}");
    // Not a terminal: no progress bar, nothing else on stderr.
    assert!(stderr.is_empty(), "{stderr}");
    // Nothing failed, nothing written.
    assert!(!out.exists() || std::fs::read_dir(&out).unwrap().next().is_none());
}

#[test]
fn peers_get_a_column_each() {
    let result = campaign(&["--cases", "4", "--families", "star,comb", "--peers", "-q"]);
    let stdout = String::from_utf8_lossy(&result.stdout);
    assert!(result.status.success(), "{stdout}");
    let header = stdout.lines().next().unwrap_or_default();
    for peer in ["earcut", "earcutr", "i-triangle", "lyon", "spade"] {
        assert!(header.contains(peer), "{peer}: {header}");
    }
    assert_eq!(stdout.lines().filter(|l| l.starts_with("star ")).count(), 1);
    assert!(!stdout.contains("two-opt"), "{stdout}");
}

#[test]
fn unknown_families_are_usage_errors() {
    let result = campaign(&["--cases", "1", "--families", "stars"]);
    assert_eq!(result.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(stderr.contains("unknown family"), "{stderr}");
}
