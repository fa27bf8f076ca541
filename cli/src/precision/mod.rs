//! `polytri precision`: where f32 and f64 triangulations stay valid, as a report.
//!
//! The engine is `polytri_oracle::precision`; this module writes what it found:
//! `report.md` and `report.html` (tables, SVG charts drawn with plotters, pictures of the
//! worst meshes), the charts and pictures as separate SVG files, and every case that broke
//! polytri's promise as corpus JSON under `cases/`.

use std::fs;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use polytri_oracle::precision::{self, Plan};

use crate::{say, Failure};

mod charts;
mod doc;
mod picture;
mod report;

/// Arguments of `polytri precision`.
#[derive(Debug, clap::Args)]
#[command(after_help = "\
Every generator family, and two feature-size families (gap: a hole near the outer ring; \
spike: a sliver), at coordinate scales 1e-3 … 1e9 and offsets 0, 1e3 … 1e8, triangulated \
by polytri (fast, quality), earcut and i_triangle in f32 and f64. Each mesh is judged \
exactly on the coordinates its precision saw and on the coordinates given.

Writes DIR/report.md, DIR/report.html, DIR/precision-*.svg (charts), DIR/worst-*.svg \
(pictures) and, for any polytri run that failed on an input valid in its precision, \
DIR/cases/*.json. Exit status 0 even then: the report says what went wrong.")]
pub struct Args {
    /// The small grid (4 scales, 5 feature sizes, one seed): a few seconds in release
    #[arg(long)]
    pub quick: bool,

    /// Directory for the report (created if missing)
    #[arg(long, value_name = "DIR", default_value = "precision-report")]
    pub out: PathBuf,

    /// First generator seed (the full grid uses three consecutive seeds)
    #[arg(long, value_name = "S", default_value_t = 1)]
    pub seed: u64,

    /// Worker threads [default: one per core]
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,

    /// Print nothing on standard error but errors
    #[arg(short, long)]
    pub quiet: bool,
}

/// Prints a progress line at most every few seconds.
struct Progress {
    quiet: bool,
    start: Instant,
    last: Mutex<Instant>,
}

impl Progress {
    const EVERY: Duration = Duration::from_secs(3);

    fn new(quiet: bool) -> Self {
        let now = Instant::now();
        Progress {
            quiet,
            start: now,
            last: Mutex::new(now),
        }
    }

    fn tick(&self, done: usize, total: usize) {
        if self.quiet {
            return;
        }
        let Ok(mut last) = self.last.lock() else {
            return;
        };
        if last.elapsed() >= Self::EVERY || done == total {
            *last = Instant::now();
            say(format_args!(
                "polytri: precision: {done}/{total} cases ({:.0} s)",
                self.start.elapsed().as_secs_f64()
            ));
        }
    }
}

/// Runs `polytri precision`.
///
/// # Errors
///
/// A [`Failure`] when the output directory or a file in it cannot be written.
pub fn run(args: &Args) -> Result<(), Failure> {
    // Fail before the work, not after it.
    fs::create_dir_all(&args.out)
        .map_err(|e| Failure(format!("cannot create {}: {e}", args.out.display())))?;
    let plan = if args.quick {
        Plan::quick(args.seed)
    } else {
        Plan::full(args.seed)
    };
    let threads = args.threads.unwrap_or_else(|| {
        std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
    });
    let progress = Progress::new(args.quiet);
    let results = precision::run(&plan, threads, &|done, total| progress.tick(done, total));
    let elapsed = progress.start.elapsed().as_secs_f64();

    let report = report::build(&results, elapsed, args.quick);
    write(&args.out, "report.md", &report.doc.markdown())?;
    write(
        &args.out,
        "report.html",
        &report.doc.html("polytri precision report"),
    )?;
    for extra in &report.extras {
        write(&args.out, &extra.file, &extra.content)?;
    }
    let broken = results.broken_promises().len();
    if !args.quiet {
        say(format_args!(
            "polytri: precision: {} cases in {elapsed:.1} s; report in {}",
            results.cases.len(),
            args.out.join("report.md").display()
        ));
        if broken > 0 {
            say(format_args!(
                "polytri: warning: {broken} polytri run(s) failed on inputs valid in their precision: a core bug, cases in {}",
                args.out.join("cases").display()
            ));
        }
    }
    Ok(())
}

/// Writes `content` to `dir/name`, creating directories as needed.
fn write(dir: &Path, name: &str, content: &str) -> Result<(), Failure> {
    let path = dir.join(name);
    if let Some(parent) = path.parent() {
        fs::create_dir_all(parent)
            .map_err(|e| Failure(format!("cannot create {}: {e}", parent.display())))?;
    }
    fs::write(&path, content).map_err(|e| Failure(format!("cannot write {}: {e}", path.display())))
}
