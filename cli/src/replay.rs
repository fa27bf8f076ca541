//! `polytri replay`: replay corpus folders through polytri, judged by the oracle, as a
//! table — the same replay as `oracle/tests/corpus.rs`, without the snapshots.

use std::io::{self, Write};
use std::path::{Path, PathBuf};

use polytri_oracle::replay::{load_dir_grouped, replay_all, CorpusCase, Row};
use polytri_oracle::Grouping;

use crate::polygon_args::PolygonArgs;
use crate::{say, Failure};

/// Arguments of `polytri replay`.
#[derive(Debug, clap::Args)]
#[command(after_help = "\
A DIR is a corpus folder: earcut's suite (expected.json and fixtures/), or a folder of \
case files — corpus case JSON (as `polytri campaign` and `polytri promote` write), rings \
JSON or shapes JSON. A DIR holding only folders (like corpus/) replays each of them but \
snapshots/.

--nesting and --merge say how the rings of a rings JSON or shapes JSON file make polygons \
(by default containment decides within each polygon). They do not apply to corpus case \
JSON, which carries its own nesting, nor to earcut's suite, whose counts and deviation \
bounds are for earcut's convention (first ring outer).

Every case runs in both strategies, f64 and f32, rotated by 0, 90, 180 and 270 degrees: \
strict mode for valid inputs (the triangulation must be valid, with the case's \
expect.triangles), strict and lenient for invalid ones (strict must refuse, lenient must \
stay within the case's deviation bound). One row per case, strategy and precision; \
failures are listed on standard error. Exit status 1 on any failure.")]
pub struct Args {
    /// Corpus folders to replay [default: corpus]
    #[arg(value_name = "DIR")]
    pub dirs: Vec<PathBuf>,

    /// --nesting and --merge: how the rings of rings JSON and shapes JSON files make
    /// polygons (not of corpus case JSON, which carries its own nesting)
    #[command(flatten)]
    pub polygons: PolygonArgs,

    /// Print only the rows that failed
    #[arg(long)]
    pub failures_only: bool,
}

/// Runs `polytri replay`.
///
/// # Errors
///
/// A [`Failure`] when a folder cannot be read, or when any replay demand failed (after
/// printing the table and the failures).
pub fn run(args: &Args) -> Result<(), Failure> {
    let dirs = if args.dirs.is_empty() {
        vec![PathBuf::from("corpus")]
    } else {
        args.dirs.clone()
    };
    let mut cases = Vec::new();
    for dir in &dirs {
        cases.extend(load(dir, args.polygons.grouping())?);
    }
    if cases.is_empty() {
        return Err(Failure(format!(
            "no cases found in {}",
            dirs.iter()
                .map(|d| d.display().to_string())
                .collect::<Vec<_>>()
                .join(", ")
        )));
    }
    let replays = replay_all(&cases);
    let rows: Vec<&Row> = replays
        .iter()
        .flat_map(|r| &r.rows)
        .filter(|r| !args.failures_only || !r.passed)
        .collect();
    print_table(&rows).map_err(|e| Failure(format!("writing the table: {e}")))?;
    let failures: Vec<&String> = replays.iter().flat_map(|r| &r.failures).collect();
    for f in &failures {
        say(format_args!("FAIL {f}"));
    }
    let runs: usize = replays.iter().map(|r| r.snapshot.runs.len()).sum();
    if failures.is_empty() {
        say(format_args!(
            "replayed {} cases, {runs} runs: all passed",
            cases.len()
        ));
        Ok(())
    } else {
        Err(Failure(format!(
            "{} failure(s) in {} cases, {runs} runs",
            failures.len(),
            cases.len()
        )))
    }
}

/// The cases of `dir`, rings and shapes JSON read as `grouping` says; a folder of folders
/// (like `corpus/`) gives those of each subfolder but `snapshots`.
fn load(dir: &Path, grouping: Grouping) -> Result<Vec<CorpusCase>, Failure> {
    let entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| Failure(format!("{}: {e}", dir.display())))?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .collect();
    let has_cases = dir.join("expected.json").is_file()
        || entries
            .iter()
            .any(|p| p.is_file() && p.extension().is_some_and(|x| x == "json"));
    if has_cases {
        return load_dir_grouped(dir, grouping).map_err(Failure);
    }
    let mut subdirs: Vec<&PathBuf> = entries
        .iter()
        .filter(|p| p.is_dir() && p.file_name().is_some_and(|n| n != "snapshots"))
        .collect();
    subdirs.sort();
    let mut cases = Vec::new();
    for sub in subdirs {
        cases.extend(load_dir_grouped(sub, grouping).map_err(Failure)?);
    }
    Ok(cases)
}

/// The header of the table.
const HEADER: [&str; 6] = [
    "case",
    "strategy",
    "precision",
    "verdict",
    "deviation",
    "min angle",
];

fn cells(row: &Row) -> [String; 6] {
    [
        row.case.clone(),
        row.strategy.to_owned(),
        row.precision.to_string(),
        row.verdict.clone(),
        match row.deviation {
            None => "-".to_owned(),
            Some(0.0) => "0".to_owned(),
            Some(d) => format!("{d:.2e}"),
        },
        row.min_angle_deg
            .map_or_else(|| "-".to_owned(), |a| format!("{a:.3}°")),
    ]
}

/// Prints the rows as an aligned table on standard output.
fn print_table(rows: &[&Row]) -> io::Result<()> {
    let body: Vec<[String; 6]> = rows.iter().map(|r| cells(r)).collect();
    let mut widths = HEADER.map(|h| h.chars().count());
    for line in &body {
        for (w, cell) in widths.iter_mut().zip(line) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let mut out = io::stdout().lock();
    let mut print = |cells: &[String]| -> io::Result<()> {
        let mut line = String::new();
        for (k, (cell, w)) in cells.iter().zip(widths).enumerate() {
            if k > 0 {
                line.push_str("  ");
            }
            // Numbers right-aligned, text left-aligned.
            let pad = " ".repeat(w.saturating_sub(cell.chars().count()));
            if k >= 4 {
                line.push_str(&pad);
                line.push_str(cell);
            } else {
                line.push_str(cell);
                line.push_str(&pad);
            }
        }
        writeln!(out, "{}", line.trim_end())
    };
    print(&HEADER.map(str::to_owned))?;
    for line in &body {
        print(line)?;
    }
    Ok(())
}
