//! `polytri precision --quick` end to end: both report files, with charts and a row per
//! family.

use std::fs;
use std::path::PathBuf;
use std::process::Command;

use polytri_oracle::precision::Source;

/// A fresh directory for one test, so parallel runs never share files.
fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "polytri-cli-precision-{}-{test}",
        std::process::id()
    ));
    let _ = fs::remove_dir_all(&dir);
    dir
}

#[test]
fn quick_run_writes_markdown_and_html_reports() {
    let out = scratch("quick");
    let status = Command::new(env!("CARGO_BIN_EXE_polytri"))
        .args(["precision", "--quick", "--quiet", "--out"])
        .arg(&out)
        .status()
        .expect("run polytri");
    assert!(status.success());

    let md = fs::read_to_string(out.join("report.md")).expect("report.md");
    let html = fs::read_to_string(out.join("report.html")).expect("report.html");
    assert!(md.contains("\n## Conclusion\n"), "{md}");
    assert!(html.contains("<svg"), "no chart in the HTML report");
    assert!(html.contains("<h2>Conclusion</h2>"));
    assert!(out.join("precision-offset.svg").is_file());
    for source in Source::all() {
        // A row of the conclusion table and of the family table.
        let row = format!("| {} |", source.name());
        assert!(md.contains(&row), "no row for {source}");
    }
    // Every picture the Markdown links is beside it.
    for line in md.lines().filter(|l| l.starts_with("![")) {
        let file = line
            .rsplit_once("](")
            .and_then(|(_, rest)| rest.strip_suffix(')'))
            .expect("image link");
        assert!(out.join(file).is_file(), "{file} missing");
    }
    let _ = fs::remove_dir_all(&out);
}

#[test]
fn unwritable_output_is_a_failure() {
    let out = scratch("unwritable");
    fs::write(&out, "a file, not a directory").expect("write");
    let output = Command::new(env!("CARGO_BIN_EXE_polytri"))
        .args(["precision", "--quick", "--quiet", "--threads", "1", "--out"])
        .arg(&out)
        .output()
        .expect("run polytri");
    assert_eq!(output.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.starts_with("polytri: error: cannot"), "{stderr}");
    let _ = fs::remove_file(&out);
}
