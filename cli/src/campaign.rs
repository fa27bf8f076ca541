//! `polytri campaign`: random cases of every generator family through polytri and the
//! oracle, with a progress bar and a table per family. The engine is
//! [`polytri_oracle::campaign`]; this is its command line: arguments, progress, table.

use std::io::{self, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};
use polytri_oracle::campaign::{self, median_and_worst, Budget, Config, Polytri, Progress, Report};
use polytri_oracle::Family;

use crate::{say, Failure};

/// Arguments of `polytri campaign`.
#[derive(Debug, clap::Args)]
#[command(after_help = "\
Case k is generated from seed S+k alone (family in turn, size log-uniform between 3 and \
--max-vertices, one case in 32 up to four times larger, sometimes a tiny or huge scale or an \
offset up to 1e9), so the results do not depend on --jobs; with --cases they are the same \
every run. Each case runs polytri (strict, automatic nesting) fast and quality, in f64 and \
in f32 (f32 only where the rounded input is still valid: column 'f32 invalid'), and with \
--threads N fast in f64 on N threads (mark-and-cut lowered so that every case takes its \
rounds; it must give the same triangles on N + 1), and the oracle judges every result.

Columns: min angle = median / smallest over the cases of the smallest triangle angle in \
degrees, of fast, of quality and of spade's constrained Delaunay triangulation (the best \
any triangulation of those vertices can do). With --peers, a column per peer: failures / \
outputs judged on the f64 inputs; outputs with vertices of their own cannot be judged and \
are counted as n/a below the table.

Failing cases are shrunk (rings, then vertices, staying valid, still failing the same way) \
and written as corpus JSON named campaign_<family>_seed<seed>_<run>_<check>. Exit status: \
0 when everything passed, 1 on any failure, 2 on bad usage.")]
pub struct Args {
    /// Time budget in seconds [default: 20, unless --cases is given]
    #[arg(long, value_name = "N", conflicts_with = "cases")]
    pub seconds: Option<f64>,

    /// Run exactly N cases instead of a time budget
    #[arg(long, value_name = "N")]
    pub cases: Option<u64>,

    /// Case k is generated from seed S+k
    #[arg(long, value_name = "S", default_value_t = 1)]
    pub seed: u64,

    /// Generator families, comma-separated [default: all]
    #[arg(long, value_delimiter = ',', value_name = "FAMILIES", value_parser = parse_family)]
    pub families: Option<Vec<Family>>,

    /// Largest usual case size in vertices
    #[arg(long, value_name = "N", default_value_t = 2000)]
    pub max_vertices: usize,

    /// Where to write shrunk failing cases [default: corpus/cases of the repository]
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,

    /// Also run earcut, earcutr, i_triangle, lyon and spade and judge them by the same oracle
    #[arg(long)]
    pub peers: bool,

    /// Worker threads [default: available parallelism]
    #[arg(long, value_name = "N")]
    pub jobs: Option<usize>,

    /// Also run the fast strategy in f64 on N threads per case (N ≥ 2), clipping by
    /// mark-and-cut from rings of 16 nodes in chunks of 8; judged, and compared with
    /// N + 1 threads, which must give the same triangles [default: 1, no such run]
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub threads: usize,

    /// No progress bar
    #[arg(short, long)]
    pub quiet: bool,
}

fn parse_family(s: &str) -> Result<Family, String> {
    s.trim().parse()
}

impl Args {
    fn config(&self) -> Result<Config, Failure> {
        let budget = match (self.cases, self.seconds) {
            (Some(n), _) => Budget::Cases(n),
            (None, Some(s)) if s.is_finite() && s >= 0.0 => {
                Budget::Time(Duration::from_secs_f64(s))
            }
            (None, Some(s)) => return Err(Failure(format!("--seconds {s}: not a duration"))),
            (None, None) => Budget::Time(Duration::from_secs(20)),
        };
        let defaults = Config::default();
        Ok(Config {
            budget,
            seed: self.seed,
            families: self.families.clone().unwrap_or(defaults.families),
            max_vertices: self.max_vertices,
            peers: self.peers,
            jobs: self.jobs.unwrap_or(defaults.jobs).max(1),
            threads: self.threads.max(1),
            out_dir: Some(self.out.clone().unwrap_or_else(default_out)),
            shrink_attempts: defaults.shrink_attempts,
        })
    }
}

/// `corpus/cases/` of the repository: found from the current directory upwards, else where
/// polytri was built; else `corpus/cases` here.
fn default_out() -> PathBuf {
    let marker = |dir: &Path| dir.join("cases").is_dir();
    let here = std::env::current_dir().ok();
    here.iter()
        .flat_map(|dir| dir.ancestors())
        .map(|dir| dir.join("corpus"))
        .chain(std::iter::once(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../corpus"),
        ))
        .find(|dir| marker(dir))
        .map_or_else(|| PathBuf::from("corpus/cases"), |dir| dir.join("cases"))
}

/// Runs `polytri campaign`.
///
/// # Errors
///
/// A [`Failure`] when any case failed (after the table and the list of written cases), or a
/// failing case could not be written.
pub fn run(args: &Args) -> Result<(), Failure> {
    let config = args.config()?;
    let bar = progress_bar(&config, args.quiet);
    let report = campaign::run(&config, &Polytri, &|p: &Progress| update(&bar, p));
    bar.finish_and_clear();

    let table = table(&report);
    let mut stdout = io::stdout().lock();
    stdout
        .write_all(table.as_bytes())
        .and_then(|()| stdout.flush())
        .map_err(|e| Failure(format!("cannot write to standard output: {e}")))?;

    for found in &report.failures {
        let first = &found.runs[0];
        let place = match &found.written {
            Some(Ok(path)) => path.display().to_string(),
            Some(Err(why)) => format!("not written: {why}"),
            None => "not written".to_owned(),
        };
        say(format_args!(
            "polytri: campaign: {} seed {}: {} {}: {}; shrunk from {} to {} vertices: {place}",
            found.plan.family,
            found.plan.seed,
            first.run.name(),
            first.fault.tag(),
            first.detail,
            found.original_size.0,
            found.case.input.vertices.len(),
        ));
    }
    if report.passed() {
        Ok(())
    } else {
        Err(Failure(format!(
            "{} of {} cases failed",
            report.failures.len(),
            report.cases()
        )))
    }
}

/// A bar over the budget on stderr, hidden when stderr is not a terminal or with `-q`.
fn progress_bar(config: &Config, quiet: bool) -> ProgressBar {
    if quiet || !io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let (len, template) = match config.budget {
        Budget::Cases(n) => (n, "{bar:40} {pos}/{len} cases {msg}"),
        Budget::Time(t) => (
            t.as_millis().try_into().unwrap_or(u64::MAX),
            "{bar:40} {elapsed}/{duration} {msg}",
        ),
    };
    let bar = ProgressBar::new(len);
    if let Ok(style) = ProgressStyle::with_template(template) {
        bar.set_style(style);
    }
    bar.enable_steady_tick(Duration::from_millis(200));
    bar
}

fn update(bar: &ProgressBar, p: &Progress) {
    match p.budget {
        Budget::Cases(_) => bar.set_position(p.cases),
        Budget::Time(_) => bar.set_position(p.elapsed.as_millis().try_into().unwrap_or(u64::MAX)),
    }
    bar.set_message(format!("{} cases, {} failing", p.cases, p.failures));
}

/// An angle in degrees, readable from 60° down to slivers.
fn degrees(a: f64) -> String {
    if a >= 0.1 || a == 0.0 {
        format!("{a:.1}")
    } else {
        format!("{a:.1e}")
    }
}

/// `median / worst` of a column of angles, `-` when empty.
fn angles(values: &[f64]) -> String {
    median_and_worst(values).map_or_else(
        || "-".to_owned(),
        |(median, worst)| format!("{} / {}", degrees(median), degrees(worst)),
    )
}

/// The table: one row per family in the order asked for, then all of them together, then
/// a line of totals (and the peers' unjudged outputs).
fn table(report: &Report) -> String {
    let mut header: Vec<String> = [
        "family",
        "cases",
        "vertices",
        "runs",
        "failed",
        "f32 invalid",
        "fast min° med / worst",
        "quality min° med / worst",
        "CDT min° med / worst",
        "time s",
    ]
    .map(str::to_owned)
    .to_vec();
    let peers: Vec<_> = report
        .families
        .first()
        .map(|f| f.peers.iter().map(|(p, _)| *p).collect())
        .unwrap_or_default();
    header.extend(peers.iter().map(|p| p.to_string()));

    let mut rows = Vec::new();
    for f in &report.families {
        let mut row = vec![
            f.family.to_string(),
            f.cases.to_string(),
            f.vertices.to_string(),
            f.runs.to_string(),
            f.failed_runs.to_string(),
            f.f32_invalid.to_string(),
            angles(&f.fast_min_angles),
            angles(&f.quality_min_angles),
            angles(&f.cdt_min_angles),
            format!("{:.1}", f.time.as_secs_f64()),
        ];
        row.extend(
            f.peers
                .iter()
                .map(|(_, s)| format!("{}/{}", s.failed, s.judged)),
        );
        rows.push(row);
    }
    let all = |pick: fn(&campaign::FamilyStats) -> &Vec<f64>| -> Vec<f64> {
        report
            .families
            .iter()
            .flat_map(|f| pick(f).iter().copied())
            .collect()
    };
    let sum = |pick: fn(&campaign::FamilyStats) -> usize| -> String {
        report.families.iter().map(pick).sum::<usize>().to_string()
    };
    let mut total = vec![
        "all".to_owned(),
        sum(|f| f.cases),
        sum(|f| f.vertices),
        sum(|f| f.runs),
        sum(|f| f.failed_runs),
        sum(|f| f.f32_invalid),
        angles(&all(|f| &f.fast_min_angles)),
        angles(&all(|f| &f.quality_min_angles)),
        angles(&all(|f| &f.cdt_min_angles)),
        format!(
            "{:.1}",
            report
                .families
                .iter()
                .map(|f| f.time.as_secs_f64())
                .sum::<f64>()
        ),
    ];
    let mut not_judged = Vec::new();
    for (i, peer) in peers.iter().enumerate() {
        let stat = |pick: fn(&campaign::PeerStats) -> usize| -> usize {
            report.families.iter().map(|f| pick(&f.peers[i].1)).sum()
        };
        total.push(format!("{}/{}", stat(|s| s.failed), stat(|s| s.judged)));
        let n = stat(|s| s.not_judged);
        if n > 0 {
            not_judged.push(format!("{peer} {n}"));
        }
    }
    rows.push(total);

    let mut widths: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for row in &rows {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let line = |cells: &[String]| -> String {
        let padded: Vec<String> = cells
            .iter()
            .zip(&widths)
            .enumerate()
            .map(|(i, (cell, &w))| {
                let pad = " ".repeat(w - cell.chars().count());
                if i == 0 {
                    format!("{cell}{pad}")
                } else {
                    format!("{pad}{cell}")
                }
            })
            .collect();
        padded.join("  ").trim_end().to_owned() + "\n"
    };
    let mut out = line(&header);
    let rule: Vec<String> = widths.iter().map(|&w| "-".repeat(w)).collect();
    out += &line(&rule);
    let last = rows.len() - 1;
    for (i, row) in rows.iter().enumerate() {
        if i == last {
            out += &line(&rule);
        }
        out += &line(row);
    }
    out += &format!(
        "\n{} cases, {} runs in {:.1} s on {} threads; {} failing case(s)\n",
        report.cases(),
        report.runs(),
        report.elapsed.as_secs_f64(),
        report.jobs,
        report.failures.len()
    );
    if !not_judged.is_empty() {
        out += &format!(
            "peer outputs with vertices of their own, not judged (n/a): {}\n",
            not_judged.join(", ")
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_read_well() {
        assert_eq!(degrees(45.04), "45.0");
        assert_eq!(degrees(0.0012), "1.2e-3");
        assert_eq!(angles(&[]), "-");
        assert_eq!(angles(&[30.0, 10.0, 50.0]), "30.0 / 10.0");
    }
}
