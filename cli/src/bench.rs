//! `polytri bench`: polytri against its peers on the same inputs, in one process.
//!
//! Fairness: every input is converted into each library's format before timing
//! ([`Prepared`]); every implementation keeps its buffers between runs ([`Runner`]); the
//! implementations take turns sample by sample (round robin, starting one further each
//! round), so machine noise falls on all of them alike; each sample repeats a run often
//! enough to last about a millisecond, so the timer's resolution does not matter; the
//! median of the samples is reported.
//!
//! Three reports: the default table of medians and ratios (`--per-second` turns times into
//! triangles per second, the paper's Table 1), and with `--scaling` the generated series of
//! [`polytri_oracle::series`] with fitted growth exponents and log-log plots ([`scaling`]).
//! Each prints as aligned text, as Markdown (`--markdown`, the README's tables) or as JSON.

mod scaling;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use polytri_oracle::peers::{Implementation, Peer, Prepared, Runner};
use polytri_oracle::series::Series;
use polytri_oracle::{Grouping, Input};
use serde::Serialize;

use crate::polygon_args::PolygonArgs;
use crate::{input, say, Failure};

/// earcut's benchmark fixtures, under `corpus/earcut/fixtures/`.
const FIXTURES: [&str; 6] = [
    "building",
    "dude",
    "water",
    "water-huge",
    "water-huge2",
    "water3",
];

/// The paper-shaped datasets, under `corpus/datasets/`.
const DATASETS: [&str; 7] = [
    "letter_a",
    "lorem_latin",
    "lorem_japanese",
    "lorem_japanese_noto",
    "rect_circles",
    "chinese_text",
    "cjk_page",
];

/// A real layer, under `docs/gis/` (beside `corpus/`): many small polygons, each on its own.
const LAYERS: [&str; 1] = ["texas-counties"];

/// How long one sample should last: long against the timer's resolution, short against
/// the time budget.
const SAMPLE: Duration = Duration::from_millis(1);

/// Arguments of `polytri bench`.
#[derive(Debug, clap::Args)]
#[command(after_help = "\
Without FILES: earcut's benchmark fixtures (building, dude, water, water-huge, \
water-huge2, water3), the paper datasets of corpus/datasets/ and a real layer, the 254 \
counties of Texas (docs/gis/texas-counties.geojson; only the datasets with --paper), \
found from the current directory upwards or from where polytri was built.

Columns: per implementation the median time of one run in milliseconds and, in \
parentheses, its ratio to the fastest peer on that input (polytri columns too: below 1 \
means polytri is faster than every peer). Peers: earcut, earcutr, i-triangle, lyon, spade \
(i-triangle and lyon read every ring at once by the even-odd rule; on request \
i-triangle-nonzero and lyon-nonzero read them by the nonzero rule). \
Two references, no peers (never the fastest peer): earcut-exact is earcut 0.4.12 with \
exact predicates — its code vendored, the signed area of three points and the \
point-in-triangle test decided by the exact sign of orient2d, everything else unchanged — \
and earcut-vendored the same vendored code with earcut's own floating-point predicates. \
earcut-exact over earcut-vendored is the price of exactness in earcut's code; \
earcut-vendored over earcut what the copy itself costs (in part its safe node access). \
polytri-fast is strict: it refuses crossing edges \
(rings touching at vertices are fine). polytri-lenient repairs them instead of refusing; it still sweeps the edges \
to find them, and runs extra passes on input that has some. polytri-check is strict mode's \
input check alone (loading, the edge sweep, nesting), no triangulation: compare it with \
polytri-fast for the check's share. polytri-threads is polytri-fast with the polygons of a \
file spread over every core (triangulate_many; one polygon of 262,144 vertices or more is clipped by mark-and-cut on them). On \
request (--polytri): even-odd and seidel-even-odd read all of a file's rings at once by \
the even-odd fill rule (crossing edges split at exactly rounded points), with the fast \
ear clipper or Seidel's trapezoidation, as lyon and i-triangle read them (nonzero and \
seidel-nonzero likewise by the nonzero rule, as lyon-nonzero and i-triangle-nonzero); even-odd-each \
takes a file's polygons one at a time by the same rule, as polytri-fast takes them (nonzero-each \
by the nonzero rule); seidel is \
Seidel's trapezoidation in strict mode; check-floor is a reference, not polytri's code: the \
least an exact input check costs (every vertex read, one exact orientation per edge: the \
star-shaped certificate from each ring's vertex mean, counted as done whether or not it \
holds), to set beside polytri-check. The last \
row is the geometric mean of the ratios. Files with several polygons go to earcut and \
polytri one polygon at a time, to the others all at once.

--nesting and --merge read FILES and the datasets as `polytri triangulate` reads a file. \
auto (the default): containment decides which rings of each polygon are holes, decided \
once before timing with the oracle's exact grouping, so that every implementation gets the \
same polygons, each outer ring followed by its holes (a file whose polygons list their \
outer ring first is timed exactly as with first-outer). first-outer: each polygon's first \
ring is outer, the rest its holes. --merge: all rings of a file as one input; with auto \
polytri decides the nesting itself, within the timing, and earcut gets the rings grouped \
by containment; with first-outer the file's first ring is outer, every other a hole. \
earcut's fixtures, without FILES, keep earcut's convention (first ring outer, the rest \
holes), as `polytri replay` reads earcut's suite: in water-huge and water-huge2 \
containment would find rings inside holes and outside the outer ring, and make polygons \
of them; name their files as FILES for that.

--per-second: triangles per second instead (in millions; the input's triangle count, as \
polytri-fast makes it, over each implementation's median time, so rates compare like \
times), and in parentheses the rate over the fastest peer's (above 1: polytri is faster).

--scaling: the generated series (random polygon, star, circles, comb) at 10^3 to 10^6 \
vertices instead of FILES; a table of medians, the growth exponent of every implementation \
per series (least squares of log time on log vertices) and, with --out, a log-log plot per \
series (scaling-SERIES.svg). An implementation whose next run is predicted (from its three \
largest sizes so far) to exceed 3 s is skipped at that size and above, and said so.")]
pub struct Args {
    /// Inputs: rings JSON, shapes JSON, GeoJSON or WKT
    #[arg(value_name = "FILES", conflicts_with_all = ["paper", "scaling"])]
    pub files: Vec<PathBuf>,

    /// Peers to compare with, comma-separated, and the references earcut-exact and
    /// earcut-vendored [default: all but lyon-nonzero and i-triangle-nonzero]
    #[arg(long, value_delimiter = ',', value_name = "PEERS",
          value_parser = parse_peer)]
    pub peers: Option<Vec<Peer>>,

    /// polytri configurations, comma-separated: fast, lenient, quality, check, threads,
    /// even-odd, even-odd-each, seidel, seidel-even-odd, nonzero, seidel-nonzero,
    /// nonzero-each, and the reference check-floor
    /// [default: the first five; --scaling: the first four]
    #[arg(long, value_delimiter = ',', value_name = "CONFIGS",
          value_parser = parse_polytri)]
    pub polytri: Option<Vec<Implementation>>,

    /// --nesting and --merge: how each file's rings make polygons (not for --scaling)
    #[command(flatten)]
    pub polygons: PolygonArgs,

    /// Time budget per input, shared by all implementations
    #[arg(long, value_name = "S", default_value_t = 1.0)]
    pub seconds: f64,

    /// A quick look: 0.05 s per input, at least 3 samples each (with --scaling: sizes
    /// 10^3 to 10^4 only)
    #[arg(long)]
    pub quick: bool,

    /// Only the paper datasets (Table 1 of Kotsarenko 2024 and the larger CJK inputs)
    #[arg(long)]
    pub paper: bool,

    /// Triangles per second (millions) instead of milliseconds
    #[arg(long)]
    pub per_second: bool,

    /// The generated scaling series instead of FILES (see below)
    #[arg(long)]
    pub scaling: bool,

    /// With --scaling: the series to run, comma-separated [default: all]
    #[arg(long, value_delimiter = ',', value_name = "SERIES", requires = "scaling",
          value_parser = parse_series)]
    pub series: Option<Vec<Series>>,

    /// With --scaling: the sizes in vertices, comma-separated [default: 10^3 to 10^6 by
    /// half decades]
    #[arg(long, value_delimiter = ',', value_name = "N", requires = "scaling")]
    pub sizes: Option<Vec<usize>>,

    /// With --scaling: write a log-log plot per series here, as scaling-SERIES.svg
    #[arg(long, value_name = "DIR", requires = "scaling")]
    pub out: Option<PathBuf>,

    /// Print the tables as Markdown (as in the README)
    #[arg(long, conflicts_with = "json")]
    pub markdown: bool,

    /// Print the results as JSON on stdout instead of a table
    #[arg(long)]
    pub json: bool,
}

/// How the tables are printed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Style {
    /// Columns aligned with spaces.
    Text,
    /// Markdown tables.
    Markdown,
}

fn parse_peer(s: &str) -> Result<Peer, String> {
    s.parse()
}

/// A polytri configuration by its short name (`fast`) or its full one (`polytri-fast`).
fn parse_polytri(s: &str) -> Result<Implementation, String> {
    let s = s.trim();
    let full = if s.starts_with("polytri-") {
        s.to_owned()
    } else {
        format!("polytri-{s}")
    };
    Implementation::POLYTRI_ALL
        .into_iter()
        .find(|imp| imp.name().eq_ignore_ascii_case(&full))
        .ok_or_else(|| {
            format!("unknown polytri configuration '{s}' (known: fast, lenient, quality, check, threads, even-odd, even-odd-each, seidel, seidel-even-odd, nonzero, seidel-nonzero, nonzero-each, check-floor)")
        })
}

fn parse_series(s: &str) -> Result<Series, String> {
    s.parse()
}

/// One implementation's result on one input.
#[derive(Debug, Clone, Serialize)]
struct Timing {
    implementation: String,
    /// Median milliseconds per run; `None` when it refused the input.
    median_ms: Option<f64>,
    /// `median_ms` over the fastest peer's.
    ratio: Option<f64>,
    triangles: Option<usize>,
    samples: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<String>,
}

/// Every implementation's result on one input.
#[derive(Debug, Clone, Serialize)]
struct Row {
    input: String,
    /// Polygons (outer rings with their holes).
    polygons: usize,
    vertices: usize,
    /// polytri-fast's triangle count (or the first implementation's that succeeded).
    triangles: Option<usize>,
    timings: Vec<Timing>,
}

/// The whole report, as `--json` prints it.
#[derive(Debug, Serialize)]
struct Report {
    implementations: Vec<String>,
    rows: Vec<Row>,
    /// Per implementation, the geometric mean of its ratios over the inputs it ran.
    geometric_mean: Vec<Option<f64>>,
}

/// Runs `polytri bench`.
///
/// # Errors
///
/// A [`Failure`] when an input cannot be read, the corpus cannot be found or a plot cannot
/// be written.
pub fn run(args: &Args) -> Result<(), Failure> {
    if !(args.seconds >= 0.0 && args.seconds.is_finite()) {
        return Err(Failure(format!(
            "--seconds must be a finite number ≥ 0, not {}",
            args.seconds
        )));
    }
    let implementations = implementations(args);
    let (budget, min_samples) = if args.quick {
        (Duration::from_millis(50), 3)
    } else {
        (Duration::from_secs_f64(args.seconds), 5)
    };
    let style = if args.markdown {
        Style::Markdown
    } else {
        Style::Text
    };
    if args.scaling {
        return scaling::run(args, &implementations, budget, min_samples, style);
    }
    let inputs = load_inputs(&args.files, args.paper, args.polygons.grouping())?;
    let mut rows = Vec::with_capacity(inputs.len());
    for (k, (name, input)) in inputs.iter().enumerate() {
        say(format_args!(
            "polytri bench: [{}/{}] {name} ({} vertices)",
            k + 1,
            inputs.len(),
            input.vertices.len()
        ));
        let row = measure(name, input, &implementations, budget, min_samples);
        for (timing, error) in failures(&row) {
            say(format_args!(
                "polytri bench: {name}: {} failed: {error}",
                timing.implementation
            ));
        }
        rows.push(row);
    }
    let report = Report {
        implementations: implementations.iter().map(ToString::to_string).collect(),
        geometric_mean: (0..implementations.len())
            .map(|i| geometric_mean(rows.iter().filter_map(|row| row.timings[i].ratio)))
            .collect(),
        rows,
    };
    if args.json {
        print_json(&report)
    } else {
        print!("{}", table(&report, args.per_second, style));
        Ok(())
    }
}

/// The polytri configurations and peers chosen, polytri first.
fn implementations(args: &Args) -> Vec<Implementation> {
    // (the scaling series are one polygon each: there polytri-threads is polytri-fast)
    let polytri = args.polytri.clone().unwrap_or_else(|| {
        (Implementation::POLYTRI.into_iter())
            .filter(|&imp| !(args.scaling && imp == Implementation::PolytriThreads))
            .collect()
    });
    let peers = (args.peers.clone())
        .unwrap_or_else(|| Peer::ALL.into_iter().chain(Peer::REFERENCES).collect());
    let mut chosen: Vec<Implementation> = Vec::new();
    for imp in polytri
        .into_iter()
        .chain(peers.into_iter().map(Implementation::Peer))
    {
        if !chosen.contains(&imp) {
            chosen.push(imp);
        }
    }
    chosen
}

/// The implementations that failed on a row's input, with their messages.
fn failures(row: &Row) -> impl Iterator<Item = (&Timing, &str)> {
    row.timings
        .iter()
        .filter_map(|t| t.error.as_deref().map(|e| (t, e)))
}

/// Prints `value` as pretty JSON on stdout.
fn print_json(value: &impl Serialize) -> Result<(), Failure> {
    let text = serde_json::to_string_pretty(value)
        .map_err(|e| Failure(format!("cannot write JSON: {e}")))?;
    println!("{text}");
    Ok(())
}

/// The inputs by name: the files given, or else the default fixtures (unless `paper`) and
/// datasets, each file's rings made polygons as `grouping` says — but earcut's fixtures by
/// earcut's convention, each a polygon whose first ring is outer ([`EARCUT_CONVENTION`]).
fn load_inputs(
    files: &[PathBuf],
    paper: bool,
    grouping: Grouping,
) -> Result<Vec<(String, Input)>, Failure> {
    let paths: Vec<(PathBuf, Grouping)> = if files.is_empty() {
        let corpus = find_corpus().ok_or_else(|| {
            Failure(
                "no FILES given and no corpus/ directory found from here upwards; \
                 run from the repository or name the files"
                    .to_owned(),
            )
        })?;
        let fixtures: &[&str] = if paper { &[] } else { &FIXTURES };
        let fixtures = (fixtures.iter()).map(|f| {
            let path = corpus.join("earcut/fixtures").join(format!("{f}.json"));
            (path, EARCUT_CONVENTION)
        });
        let datasets = (DATASETS.iter())
            .map(|d| (corpus.join("datasets").join(format!("{d}.json")), grouping));
        let layers: &[&str] = if paper { &[] } else { &LAYERS };
        let gis = corpus.join("../docs/gis");
        let layers = (layers.iter()).map(|l| (gis.join(format!("{l}.geojson")), grouping));
        fixtures.chain(datasets).chain(layers).collect()
    } else {
        files.iter().map(|f| (f.clone(), grouping)).collect()
    };
    paths
        .iter()
        .map(|(path, grouping)| {
            let read = input::read(path)?;
            Ok((
                short_name(path),
                Input::from_polygons(&read.polygons, *grouping),
            ))
        })
        .collect()
}

/// How the default inputs read earcut's fixtures, whatever `--nesting` says: as earcut's
/// suite defines them (and `polytri replay` reads them), the first ring outer, every other
/// a hole. Containment would read two of them otherwise: water-huge and water-huge2 (whose
/// edges cross) have rings inside holes and outside the outer ring, which `--nesting auto`
/// makes polygons of their own (44 and 85 polygons instead of 1).
const EARCUT_CONVENTION: Grouping = Grouping {
    nesting: polytri::Nesting::FirstIsOuter,
    merge: false,
};

/// The corpus directory: `corpus/` in the current directory or one above it, else the
/// repository polytri was built from.
fn find_corpus() -> Option<PathBuf> {
    let marker = |dir: &Path| dir.join("earcut/fixtures").is_dir();
    let here = std::env::current_dir().ok();
    here.iter()
        .flat_map(|dir| dir.ancestors())
        .map(|dir| dir.join("corpus"))
        .chain(std::iter::once(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../corpus"),
        ))
        .find(|dir| marker(dir))
}

/// A file's name without directory and `.json` extension.
fn short_name(path: &Path) -> String {
    let name = input::display_name(path);
    let base = Path::new(&name)
        .file_name()
        .map_or(name.clone(), |f| f.to_string_lossy().into_owned());
    let base = base.strip_suffix(".json").unwrap_or(&base);
    base.strip_suffix(".geojson").unwrap_or(base).to_owned()
}

/// One implementation's state while an input is measured.
struct Contestant {
    implementation: Implementation,
    /// Runs per sample.
    batch: u32,
    /// Seconds per run, one entry per sample.
    samples: Vec<f64>,
    triangles: Option<usize>,
    error: Option<String>,
}

/// Measures every implementation on `input`, round robin, within `budget` (but at least
/// `min_samples` samples each). Failures are in the row's timings, not said.
fn measure(
    name: &str,
    input: &Input,
    implementations: &[Implementation],
    budget: Duration,
    min_samples: usize,
) -> Row {
    let prepared = Prepared::new(input);
    let mut runner = Runner::new();
    let mut contestants: Vec<Contestant> = implementations
        .iter()
        .map(|&imp| calibrate(&mut runner, imp, &prepared))
        .collect();
    let start = Instant::now();
    for round in 0.. {
        let live = contestants.iter().filter(|c| c.error.is_none()).count();
        let enough = contestants
            .iter()
            .all(|c| c.error.is_some() || c.samples.len() >= min_samples);
        if live == 0 || (enough && start.elapsed() >= budget) {
            break;
        }
        let n = contestants.len();
        for k in 0..n {
            let c = &mut contestants[(round + k) % n];
            if c.error.is_some() {
                continue;
            }
            let began = Instant::now();
            for _ in 0..c.batch {
                if let Err(e) = runner.run(c.implementation, std::hint::black_box(&prepared)) {
                    c.error = Some(e);
                    break;
                }
            }
            c.samples
                .push(began.elapsed().as_secs_f64() / f64::from(c.batch));
        }
    }
    row(name, &prepared, contestants)
}

/// Runs `imp` once to warm up and learn its triangle count, then times one run to choose
/// the batch size.
fn calibrate(runner: &mut Runner, imp: Implementation, prepared: &Prepared) -> Contestant {
    let mut contestant = Contestant {
        implementation: imp,
        batch: 1,
        samples: Vec::new(),
        triangles: None,
        error: None,
    };
    match runner.run(imp, prepared) {
        Ok(triangles) => contestant.triangles = imp.triangulates().then_some(triangles),
        Err(e) => {
            contestant.error = Some(e);
            return contestant;
        }
    }
    let began = Instant::now();
    let _ = runner.run(imp, prepared);
    let once = began.elapsed().max(Duration::from_nanos(1));
    contestant.batch = (SAMPLE.as_secs_f64() / once.as_secs_f64()).clamp(1.0, 1e6) as u32;
    contestant
}

/// The row of one input: medians and ratios to the fastest peer.
fn row(name: &str, prepared: &Prepared, contestants: Vec<Contestant>) -> Row {
    let medians: Vec<Option<f64>> = contestants
        .iter()
        .map(|c| c.error.is_none().then(|| median(&c.samples)).flatten())
        .collect();
    let best_peer = contestants
        .iter()
        .zip(&medians)
        .filter(|(c, _)| c.implementation.is_peer())
        .filter_map(|(_, m)| *m)
        .min_by(f64::total_cmp);
    let triangles = contestants
        .iter()
        .find(|c| c.implementation == Implementation::PolytriFast)
        .and_then(|c| c.triangles)
        .or_else(|| contestants.iter().find_map(|c| c.triangles));
    let timings = contestants
        .into_iter()
        .zip(medians)
        .map(|(c, m)| Timing {
            implementation: c.implementation.to_string(),
            median_ms: m.map(|s| s * 1e3),
            ratio: m.zip(best_peer).map(|(m, best)| m / best),
            triangles: c.triangles.filter(|_| c.error.is_none()),
            samples: c.samples.len(),
            error: c.error,
        })
        .collect();
    Row {
        input: name.to_owned(),
        polygons: prepared.polygon_count(),
        vertices: prepared.input().vertices.len(),
        triangles,
        timings,
    }
}

fn median(samples: &[f64]) -> Option<f64> {
    let mut sorted = samples.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    match n {
        0 => None,
        _ if n % 2 == 1 => Some(sorted[n / 2]),
        _ => Some((sorted[n / 2 - 1] + sorted[n / 2]) / 2.0),
    }
}

fn geometric_mean(values: impl Iterator<Item = f64>) -> Option<f64> {
    let (sum, count) = values
        .filter(|v| *v > 0.0)
        .fold((0.0, 0usize), |(s, n), v| (s + v.ln(), n + 1));
    (count > 0).then(|| (sum / count as f64).exp())
}

/// Milliseconds with four significant digits (at most nine decimals).
fn format_ms(ms: f64) -> String {
    format_significant(ms, 4)
}

/// `x` with `digits` significant digits (at most nine decimals).
fn format_significant(x: f64, digits: i32) -> String {
    let magnitude = if x > 0.0 { x.log10().floor() } else { 0.0 };
    let decimals = (f64::from(digits - 1) - magnitude).clamp(0.0, 9.0) as usize;
    format!("{x:.decimals$}")
}

fn format_ratio(ratio: Option<f64>) -> String {
    ratio.map_or_else(|| "(–)".to_owned(), |r| format!("({r:.2}×)"))
}

/// The report as a table: per input its counts, then per implementation its time (or
/// rate) and ratio, then the fastest peer; the last line the geometric means.
fn table(report: &Report, per_second: bool, style: Style) -> String {
    let unit = if per_second { "M tri/s" } else { "ms" };
    let mut header: Vec<String> = ["input", "polygons", "vertices", "triangles"]
        .map(str::to_owned)
        .to_vec();
    header.extend(report.implementations.iter().map(|i| format!("{i} {unit}")));
    header.push(FASTEST_PEER.to_owned());
    let mut lines = vec![header];
    for row in &report.rows {
        let mut line = vec![
            row.input.clone(),
            row.polygons.to_string(),
            row.vertices.to_string(),
            row.triangles.map_or("–".to_owned(), |t| t.to_string()),
        ];
        line.extend(
            row.timings
                .iter()
                .map(|t| cell(t, row.triangles, per_second)),
        );
        line.push(fastest_peer(row).unwrap_or("–").to_owned());
        lines.push(line);
    }
    let mut mean = vec!["geometric mean".to_owned()];
    mean.extend(std::iter::repeat_n(String::new(), 3));
    mean.extend(
        report
            .geometric_mean
            .iter()
            .map(|&g| format_ratio(g.map(|g| if per_second { 1.0 / g } else { g }))),
    );
    mean.push(String::new());
    if style == Style::Markdown {
        mean = mean
            .into_iter()
            .map(|c| if c.is_empty() { c } else { format!("**{c}**") })
            .collect();
    }
    lines.push(mean);
    render(&lines, style)
}

/// One implementation's cell: its median time and ratio to the fastest peer, or with
/// `per_second` the input's `triangles` over that time in millions per second and the
/// ratio of rates (the inverse).
fn cell(timing: &Timing, triangles: Option<usize>, per_second: bool) -> String {
    let Some(ms) = timing.median_ms else {
        return if timing.error.is_some() && timing.implementation.starts_with("polytri") {
            "refused".to_owned()
        } else {
            "failed".to_owned()
        };
    };
    if !per_second {
        return format!("{} {}", format_ms(ms), format_ratio(timing.ratio));
    }
    match triangles {
        Some(t) if ms > 0.0 => format!(
            "{} {}",
            format_significant(t as f64 / ms / 1e3, 3),
            format_ratio(timing.ratio.map(|r| 1.0 / r))
        ),
        _ => "–".to_owned(),
    }
}

/// The name of the fastest peer on a row (ratio 1; references are no peers).
fn fastest_peer(row: &Row) -> Option<&str> {
    row.timings
        .iter()
        .filter(|t| (t.implementation.parse()).is_ok_and(Implementation::is_peer))
        .filter_map(|t| t.ratio.map(|r| (r, t.implementation.as_str())))
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, name)| name)
}

/// The header of the column that names the fastest peer.
const FASTEST_PEER: &str = "fastest peer";

/// `lines` (the first the header) as aligned text, names left (the first column and
/// [`FASTEST_PEER`]) and numbers right, or as a Markdown table.
fn render(lines: &[Vec<String>], style: Style) -> String {
    let columns = lines.first().map_or(0, Vec::len);
    let left: Vec<bool> = (0..columns)
        .map(|c| c == 0 || lines[0][c] == FASTEST_PEER)
        .collect();
    let width: Vec<usize> = (0..columns)
        .map(|c| {
            lines
                .iter()
                .map(|l| l[c].chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    for (k, line) in lines.iter().enumerate() {
        let cells: Vec<String> = line
            .iter()
            .enumerate()
            .map(|(c, cell)| {
                let pad = " ".repeat(width[c] - cell.chars().count());
                if left[c] {
                    format!("{cell}{pad}")
                } else {
                    format!("{pad}{cell}")
                }
            })
            .collect();
        match style {
            Style::Text => out.push_str(cells.join("  ").trim_end()),
            Style::Markdown => {
                out.push_str(&format!("| {} |", cells.join(" | ")));
                if k == 0 {
                    let rule: Vec<String> = width
                        .iter()
                        .enumerate()
                        .map(|(c, &w)| {
                            let dashes = "-".repeat(w.max(3) - usize::from(!left[c]));
                            if left[c] {
                                dashes
                            } else {
                                format!("{dashes}:")
                            }
                        })
                        .collect();
                    out.push_str(&format!("\n| {} |", rule.join(" | ")));
                }
            }
        }
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use polytri_oracle::peers::polygons;

    #[test]
    fn auto_nesting_gives_the_default_inputs_first_outer_polygons() {
        // the datasets list each polygon's outer ring first, and earcut's fixtures keep
        // earcut's convention: the default run times the same polygons either way
        let auto = load_inputs(&[], false, Grouping::default()).expect("the corpus");
        let given = load_inputs(&[], false, EARCUT_CONVENTION).expect("the corpus");
        assert_eq!(auto.len(), FIXTURES.len() + DATASETS.len() + LAYERS.len());
        for ((name, auto), (_, given)) in auto.iter().zip(&given) {
            assert_eq!(auto.vertices, given.vertices, "{name}");
            assert_eq!(polygons(auto), polygons(given), "{name}");
        }
    }

    #[test]
    fn median_and_geometric_mean() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
        assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), Some(2.5));
        assert_eq!(median(&[]), None);
        let g = geometric_mean([2.0, 8.0].into_iter()).expect("two values");
        assert!((g - 4.0).abs() < 1e-12);
        assert_eq!(geometric_mean(std::iter::empty()), None);
    }

    #[test]
    fn milliseconds_keep_four_digits() {
        assert_eq!(format_ms(0.000_412_34), "0.0004123");
        assert_eq!(format_ms(1.234_56), "1.235");
        assert_eq!(format_ms(1234.6), "1235");
    }

    #[test]
    fn ratios_are_to_the_fastest_peer() {
        let contestant = |implementation, samples: Vec<f64>| Contestant {
            implementation,
            batch: 1,
            samples,
            triangles: Some(2),
            error: None,
        };
        let row = row(
            "square",
            &Prepared::new(&Input::default()),
            vec![
                contestant(Implementation::PolytriFast, vec![1.0]),
                contestant(Implementation::Peer(Peer::Earcut), vec![2.0]),
                contestant(Implementation::Peer(Peer::Lyon), vec![4.0]),
                // faster than every peer, but a reference: no peer
                contestant(Implementation::Peer(Peer::EarcutVendored), vec![0.5]),
            ],
        );
        let ratios: Vec<_> = row.timings.iter().map(|t| t.ratio).collect();
        assert_eq!(ratios, vec![Some(0.5), Some(1.0), Some(2.0), Some(0.25)]);
        assert_eq!(fastest_peer(&row), Some("earcut"));
    }

    #[test]
    fn rates_are_the_inputs_triangles_over_each_time() {
        let timing = |ms: Option<f64>, ratio: Option<f64>| Timing {
            implementation: "polytri-fast".to_owned(),
            median_ms: ms,
            ratio,
            triangles: None,
            samples: 5,
            error: ms.is_none().then(|| "edges cross".to_owned()),
        };
        // 2,000 triangles in 0.5 ms: 4 M/s, twice the fastest peer's rate
        assert_eq!(
            cell(&timing(Some(0.5), Some(0.5)), Some(2_000), true),
            "4.00 (2.00×)"
        );
        assert_eq!(
            cell(&timing(Some(0.5), Some(0.5)), Some(2_000), false),
            "0.5000 (0.50×)"
        );
        assert_eq!(cell(&timing(None, None), Some(2_000), true), "refused");
    }

    #[test]
    fn markdown_tables_right_align_numbers() {
        let lines = vec![
            vec!["input".to_owned(), "ms".to_owned()],
            vec!["dude".to_owned(), "0.25".to_owned()],
        ];
        assert_eq!(
            render(&lines, Style::Markdown),
            "| input |   ms |\n| ----- | ---: |\n| dude  | 0.25 |\n"
        );
        assert_eq!(render(&lines, Style::Text), "input    ms\ndude   0.25\n");
    }
}
