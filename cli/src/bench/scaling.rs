//! `polytri bench --scaling`: every implementation on the generated series of
//! [`polytri_oracle::series`] at growing sizes, the growth exponent of each fitted by least
//! squares on log time against log vertices, and a log-log plot per series.
//!
//! Each size is measured as `polytri bench` measures a file ([`measure`]: round robin,
//! medians). Some peers are quadratic on some series, and a run at 10⁶ vertices would then
//! take hours: an implementation whose next run is predicted to take longer than
//! [`LIMIT`] seconds is skipped at that size and every larger one, and the skip is said on
//! stderr and shown in the table.

mod chart;

use std::io::IsTerminal;
use std::path::Path;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};
use polytri_oracle::peers::Implementation;
use polytri_oracle::series::{self, Series};
use serde::Serialize;

use super::{failures, format_ms, measure, print_json, render, Args, Row, Style, Timing};
use crate::{say, Failure};

/// Longest predicted single run still timed, in seconds.
const LIMIT: f64 = 3.0;

/// The sizes of `--quick`: a minute's look rather than ten.
const QUICK_SIZES: [usize; 3] = [1_000, 3_000, 10_000];

/// The growth of one implementation's time on one series.
#[derive(Debug, Clone, Serialize)]
struct Exponent {
    implementation: String,
    /// The slope of log time against log vertices, least squares; `None` below two sizes.
    exponent: Option<f64>,
    /// How many sizes the fit used.
    sizes: usize,
    /// The largest size (vertices) it ran at.
    largest: Option<usize>,
}

/// One series: a row per size (skipped implementations included, with the reason as their
/// error) and an exponent per implementation.
#[derive(Debug, Clone, Serialize)]
struct SeriesReport {
    series: String,
    description: String,
    rows: Vec<Row>,
    exponents: Vec<Exponent>,
}

/// The whole report, as `--json` prints it.
#[derive(Debug, Serialize)]
struct Report {
    implementations: Vec<String>,
    series: Vec<SeriesReport>,
}

/// Runs `polytri bench --scaling`.
///
/// # Errors
///
/// A [`Failure`] when a plot cannot be drawn or written.
pub(super) fn run(
    args: &Args,
    implementations: &[Implementation],
    budget: Duration,
    min_samples: usize,
    style: Style,
) -> Result<(), Failure> {
    let chosen = args.series.clone().unwrap_or_else(|| Series::ALL.to_vec());
    let mut sizes = args.sizes.clone().unwrap_or_else(|| {
        if args.quick {
            QUICK_SIZES.to_vec()
        } else {
            series::SIZES.to_vec()
        }
    });
    sizes.sort_unstable();
    sizes.dedup();
    let progress = Progress::new(chosen.len() * sizes.len());
    let reports: Vec<SeriesReport> = chosen
        .iter()
        .map(|&s| measure_series(s, &sizes, implementations, budget, min_samples, &progress))
        .collect();
    progress.finish();
    if let Some(dir) = &args.out {
        write_plots(dir, &reports)?;
    }
    let report = Report {
        implementations: implementations.iter().map(ToString::to_string).collect(),
        series: reports,
    };
    if args.json {
        return print_json(&report);
    }
    print!("{}", tables(&report, style));
    if args.out.is_none() {
        say(format_args!(
            "polytri bench: no --out DIR given, so no plots written"
        ));
    }
    Ok(())
}

/// Every size of one series, implementations skipped once they are predicted too slow.
fn measure_series(
    series: Series,
    sizes: &[usize],
    implementations: &[Implementation],
    budget: Duration,
    min_samples: usize,
    progress: &Progress,
) -> SeriesReport {
    // (vertices, seconds) per implementation, at the sizes where it ran
    let mut history: Vec<Vec<(f64, f64)>> = vec![Vec::new(); implementations.len()];
    let mut skipped: Vec<Option<String>> = vec![None; implementations.len()];
    let mut rows = Vec::with_capacity(sizes.len());
    for &n in sizes {
        let input = series.input(n);
        let vertices = input.vertices.len();
        let name = format!("{series}-{n}");
        progress.step(format_args!("{name} ({vertices} vertices)"));
        for (k, imp) in implementations.iter().enumerate() {
            if skipped[k].is_some() {
                continue;
            }
            if let Some(seconds) = predicted_seconds(&history[k], vertices as f64) {
                if seconds > LIMIT {
                    let reason = format!("skipped: predicted {seconds:.3} s a run, over {LIMIT} s");
                    progress.note(format_args!("{name}: {imp} {reason} (and larger sizes)"));
                    skipped[k] = Some(reason);
                }
            }
        }
        let live: Vec<Implementation> = implementations
            .iter()
            .zip(&skipped)
            .filter(|(_, s)| s.is_none())
            .map(|(&imp, _)| imp)
            .collect();
        let measured = measure(&name, &input, &live, budget, min_samples);
        for (timing, error) in failures(&measured) {
            progress.note(format_args!(
                "{name}: {} failed: {error}",
                timing.implementation
            ));
        }
        let row = with_skipped(measured, implementations, &skipped);
        for (k, timing) in row.timings.iter().enumerate() {
            if let Some(ms) = timing.median_ms {
                history[k].push((vertices as f64, ms / 1e3));
            }
        }
        rows.push(row);
    }
    let exponents = implementations
        .iter()
        .zip(&history)
        .map(|(imp, points)| Exponent {
            implementation: imp.to_string(),
            exponent: fit_exponent(points),
            sizes: points.len(),
            largest: points.last().map(|&(v, _)| v as usize),
        })
        .collect();
    SeriesReport {
        series: series.to_string(),
        description: series.describe().to_owned(),
        rows,
        exponents,
    }
}

/// `row` (measured on the live implementations) with a timing for every implementation,
/// in `implementations`' order: the skipped ones carry the reason as their error.
fn with_skipped(
    mut row: Row,
    implementations: &[Implementation],
    skipped: &[Option<String>],
) -> Row {
    let mut measured = std::mem::take(&mut row.timings).into_iter();
    row.timings = implementations
        .iter()
        .zip(skipped)
        .filter_map(|(imp, reason)| match reason {
            Some(reason) => Some(Timing {
                implementation: imp.to_string(),
                median_ms: None,
                ratio: None,
                triangles: None,
                samples: 0,
                error: Some(reason.clone()),
            }),
            None => measured.next(),
        })
        .collect();
    row
}

/// The time of one run at `vertices`, extrapolated from the largest size so far with the
/// growth fitted over the last three sizes (at least linear; from one size, linear);
/// `None` before any. Three sizes rather than two: one noisy median on a busy machine
/// should not skip an implementation that would have run.
fn predicted_seconds(history: &[(f64, f64)], vertices: f64) -> Option<f64> {
    let &(v, t) = history.last()?;
    let recent = &history[history.len().saturating_sub(3)..];
    let slope = fit_exponent(recent).map_or(1.0, |k| k.max(1.0));
    Some(t * (vertices / v).powf(slope))
}

/// The least-squares slope of `ln t` against `ln v` over `(v, t)` points; `None` below two
/// distinct sizes.
fn fit_exponent(points: &[(f64, f64)]) -> Option<f64> {
    let logs: Vec<(f64, f64)> = points
        .iter()
        .filter(|&&(v, t)| v > 0.0 && t > 0.0)
        .map(|&(v, t)| (v.ln(), t.ln()))
        .collect();
    let n = logs.len() as f64;
    let mean_x = logs.iter().map(|p| p.0).sum::<f64>() / n;
    let mean_y = logs.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = logs.iter().map(|p| (p.0 - mean_x).powi(2)).sum();
    let sxy: f64 = logs.iter().map(|p| (p.0 - mean_x) * (p.1 - mean_y)).sum();
    (logs.len() >= 2 && sxx > 0.0).then(|| sxy / sxx)
}

/// The median table (a line per series and size) and the exponent table (a line per
/// series).
fn tables(report: &Report, style: Style) -> String {
    let mut header: Vec<String> = ["series", "vertices"].map(str::to_owned).to_vec();
    header.extend(report.implementations.iter().map(|i| format!("{i} ms")));
    let mut medians = vec![header];
    for s in &report.series {
        for row in &s.rows {
            let mut line = vec![s.series.clone(), row.vertices.to_string()];
            line.extend(row.timings.iter().map(median_cell));
            medians.push(line);
        }
    }
    let mut header = vec!["series".to_owned()];
    header.extend(report.implementations.iter().cloned());
    let mut exponents = vec![header];
    for s in &report.series {
        let largest = s.rows.last().map(|row| row.vertices);
        let mut line = vec![s.series.clone()];
        line.extend(s.exponents.iter().map(|e| exponent_cell(e, largest)));
        exponents.push(line);
    }
    format!(
        "{}\ngrowth exponent k in time ∝ vertices^k (least squares over the sizes run; \
         \"to N\": skipped above N vertices):\n\n{}",
        render(&medians, style),
        render(&exponents, style)
    )
}

/// A median in ms, or why there is none.
fn median_cell(timing: &Timing) -> String {
    match (timing.median_ms, &timing.error) {
        (Some(ms), _) => format_ms(ms),
        (None, Some(e)) if e.starts_with("skipped") => "skipped".to_owned(),
        (None, _) => "failed".to_owned(),
    }
}

/// An exponent with two decimals, and the largest size it covers when that is not the
/// series' largest.
fn exponent_cell(e: &Exponent, series_largest: Option<usize>) -> String {
    match (e.exponent, e.largest) {
        (Some(k), Some(largest)) if Some(largest) != series_largest => {
            format!("{k:.2} (to {largest})")
        }
        (Some(k), _) => format!("{k:.2}"),
        (None, _) => "–".to_owned(),
    }
}

/// Writes `scaling-SERIES.svg` into `dir` for every series.
fn write_plots(dir: &Path, reports: &[SeriesReport]) -> Result<(), Failure> {
    std::fs::create_dir_all(dir)
        .map_err(|e| Failure(format!("cannot create {}: {e}", dir.display())))?;
    for s in reports {
        let lines: Vec<chart::Line> = s
            .exponents
            .iter()
            .enumerate()
            .map(|(k, e)| chart::Line {
                name: match e.exponent {
                    Some(x) => format!("{} (n^{x:.2})", e.implementation),
                    None => e.implementation.clone(),
                },
                implementation: e.implementation.clone(),
                points: s
                    .rows
                    .iter()
                    .filter_map(|row| row.timings[k].median_ms.map(|ms| (row.vertices as f64, ms)))
                    .collect(),
            })
            .collect();
        let title = format!("{}: {} — median time per run", s.series, s.description);
        let svg = chart::draw(&title, &lines).map_err(Failure)?;
        let path = dir.join(format!("scaling-{}.svg", s.series));
        std::fs::write(&path, svg)
            .map_err(|e| Failure(format!("cannot write {}: {e}", path.display())))?;
        say(format_args!("polytri bench: wrote {}", path.display()));
    }
    Ok(())
}

/// Progress on stderr: a bar on a terminal, else a line per step.
struct Progress {
    bar: Option<ProgressBar>,
}

impl Progress {
    fn new(steps: usize) -> Self {
        if !std::io::stderr().is_terminal() {
            return Progress { bar: None };
        }
        let bar = ProgressBar::new(steps as u64);
        if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} {elapsed} {msg}") {
            bar.set_style(style);
        }
        bar.enable_steady_tick(Duration::from_millis(200));
        Progress { bar: Some(bar) }
    }

    /// The next series and size begins.
    fn step(&self, what: std::fmt::Arguments<'_>) {
        match &self.bar {
            Some(bar) => {
                bar.set_message(what.to_string());
                bar.inc(1);
            }
            None => say(format_args!("polytri bench: {what}")),
        }
    }

    /// A line that must stay: a skip or a failure.
    fn note(&self, what: std::fmt::Arguments<'_>) {
        let line = format!("polytri bench: {what}");
        match &self.bar {
            Some(bar) => bar.suspend(|| say(format_args!("{line}"))),
            None => say(format_args!("{line}")),
        }
    }

    fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponent_of_a_power_law_is_its_power() {
        let points: Vec<(f64, f64)> = [1e3, 1e4, 1e5]
            .iter()
            .map(|&v: &f64| (v, 2e-9 * v.powf(1.5)))
            .collect();
        let k = fit_exponent(&points).expect("three sizes");
        assert!((k - 1.5).abs() < 1e-9, "{k}");
        assert_eq!(fit_exponent(&points[..1]), None);
        assert_eq!(fit_exponent(&[]), None);
    }

    #[test]
    fn prediction_extrapolates_at_least_linearly() {
        assert_eq!(predicted_seconds(&[], 1e6), None);
        let one = predicted_seconds(&[(1e3, 0.001)], 1e4).expect("one size");
        assert!((one - 0.01).abs() < 1e-12);
        // quadratic so far: a tenfold size is predicted a hundredfold time
        let quadratic = predicted_seconds(&[(1e3, 0.001), (1e4, 0.1)], 1e5).expect("two sizes");
        assert!((quadratic - 10.0).abs() < 1e-9, "{quadratic}");
        // faster than linear so far (noise): still predicted linear
        let flat = predicted_seconds(&[(1e3, 0.01), (1e4, 0.01)], 1e5).expect("two sizes");
        assert!((flat - 0.1).abs() < 1e-12, "{flat}");
        // one slow median among three sizes moves the growth less than between two
        let noisy = [(1e3, 0.001), (1e4, 0.01), (1e5, 0.2)];
        let three = predicted_seconds(&noisy, 1e6).expect("three sizes");
        let two = predicted_seconds(&noisy[1..], 1e6).expect("two sizes");
        assert!(2.0 < three && three < two, "{three} {two}");
    }
}
