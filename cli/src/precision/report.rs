//! The report's content: conclusion, charts, tables and pictures, built from [`Results`].

use std::cmp::Reverse;
use std::collections::BTreeMap;

use polytri_oracle::precision::{
    decade, degeneracy, replay, shrink_failure, CaseResult, Config, Degeneracy, Limit, Precision,
    Results, Run, RunRef, Source, Subject, Tally,
};

use super::charts::{self, Chart, Series};
use super::doc::{Doc, Table};
use super::picture;

/// How many worst cases get a picture.
const PICTURES: usize = 6;

/// A file the report refers to, besides `report.md` and `report.html`.
pub struct Extra {
    /// File name inside the output directory.
    pub file: String,
    /// Its content.
    pub content: String,
}

/// The report and the files it refers to.
pub struct Report {
    /// The report itself.
    pub doc: Doc,
    /// Charts, pictures and cases written beside it.
    pub extras: Vec<Extra>,
}

/// `97.5%`, `100%`, or `—` for an empty group.
fn pct(rate: Option<f64>) -> String {
    match rate {
        None => "—".to_owned(),
        Some(1.0) => "100%".to_owned(),
        Some(0.0) => "0%".to_owned(),
        Some(r) => format!("{:.1}%", 100.0 * r),
    }
}

/// A deviation: `0`, `3.1e-9`.
fn sci(x: Option<f64>) -> String {
    match x {
        None => "—".to_owned(),
        Some(0.0) => "0".to_owned(),
        Some(v) => format!("{v:.1e}"),
    }
}

/// An angle in degrees.
fn deg(x: Option<f64>) -> String {
    match x {
        None => "—".to_owned(),
        Some(v) if v >= 0.01 => format!("{v:.2}°"),
        Some(v) => format!("{v:.1e}°"),
    }
}

/// `1e6` for a decade.
fn power(d: i32) -> String {
    format!("1e{d}")
}

/// A limit in words: `≤ 1e6`, `none`, or `all (≤ 1e11)`.
fn limit_text(limit: Limit) -> String {
    match (limit.valid_up_to, limit.first_failure) {
        (_, None) => match limit.measured_up_to {
            Some(max) => format!("all (to {})", power(max)),
            None => "—".to_owned(),
        },
        (None, Some(first)) => format!("none (fails at {})", power(first)),
        (Some(up_to), Some(first)) => format!("{} (fails at {})", power(up_to), power(first)),
    }
}

/// `user% (seen%)`.
fn both(t: Option<&Tally>) -> String {
    match t {
        None => "—".to_owned(),
        Some(t) => format!("{} ({})", pct(t.user_rate()), pct(t.seen_rate())),
    }
}

fn is_generator(source: Source) -> bool {
    !source.has_feature()
}

/// The x value of a case in the offset chart: the decade of offset / scale, or `zero_at`
/// for offset 0.
fn offset_x(case: &CaseResult, zero_at: i32) -> i32 {
    if case.spec.offset == 0.0 {
        zero_at
    } else {
        decade(case.spec.offset_ratio())
    }
}

/// The offset chart's "0" position: one decade left of the smallest non-zero ratio.
fn zero_position(results: &Results) -> i32 {
    results
        .cases
        .iter()
        .filter(|c| c.spec.offset != 0.0)
        .map(|c| decade(c.spec.offset_ratio()))
        .min()
        .unwrap_or(0)
        - 1
}

/// Builds the whole report; `elapsed` is the run's duration in seconds.
pub fn build(results: &Results, elapsed: f64, quick: bool) -> Report {
    let mut doc = Doc::default();
    let mut extras = Vec::new();
    doc.heading(1, "polytri precision report: where f32 and f64 stay valid");
    intro(&mut doc, results, elapsed, quick);
    let broken = broken_promises(results);
    conclusion(&mut doc, results, &broken);
    chart_section(&mut doc, results, &mut extras);
    ratio_table(&mut doc, results);
    family_table(&mut doc, results);
    feature_table(&mut doc, results);
    promise_section(&mut doc, results, &broken, &mut extras);
    worst_section(&mut doc, results, &mut extras);
    detail_table(&mut doc, results);
    Report { doc, extras }
}

fn intro(doc: &mut Doc, results: &Results, elapsed: f64, quick: bool) {
    let plan = &results.plan;
    let runs: usize = results.cases.iter().map(|c| c.runs.len()).sum();
    let invalid = results.cases.iter().filter(|c| !c.input_valid).count();
    let list = |v: &[f64]| {
        v.iter()
            .map(|&x| {
                if x == 0.0 {
                    "0".to_owned()
                } else {
                    format!("{x:e}")
                }
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    doc.text(format!(
        "{} grid{}: {} cases ({} sources × scales {} × offsets {} × seeds {:?}; feature sizes {} for `gap` and `spike`), {} triangulations, {:.1} s. Every case is triangulated by polytri (fast and quality strategies, strict), earcut and i_triangle, each in `f32` (coordinates rounded first) and `f64`.",
        if quick { "Quick" } else { "Full" },
        if quick { " (`--quick`)" } else { "" },
        results.cases.len(),
        plan.sources.len(),
        list(&plan.scales),
        list(&plan.offsets),
        plan.seeds,
        list(&plan.features),
        runs,
        elapsed
    ));
    doc.text(format!(
        "Every mesh is judged twice, exactly: on the coordinates **as its precision sees them** (did the algorithm do its job? — the *seen* rate) and on the coordinates **the user gave** (is the mesh valid where it will be used? — the *user* rate, refusals counted as failures). Cells show `user% (seen%)`; the seen rate leaves out inputs that f32 rounding already broke (made non-simple), which are counted apart as *broken*. Scales are rounded to powers of two, so scaling alone is exact in both precisions: what matters is the ratio of offset to size. {invalid} cases whose input is not valid even in f64 (rounding of the offset in f64) are left out."
    ));
}

/// The f32 configurations, in subject order.
fn configs(precision: Precision) -> Vec<Config> {
    Config::all()
        .into_iter()
        .filter(|c| c.precision == precision)
        .collect()
}

fn conclusion(doc: &mut Doc, results: &Results, broken: &[(RunRef, Degeneracy)]) {
    doc.heading(2, "Conclusion");
    let mut items = Vec::new();

    // polytri's promise.
    let promise = results.tally(|case, run| {
        (run.config.subject.is_polytri() && case.seen_input_valid(run.config.precision))
            .then_some(run.config.precision)
    });
    for precision in Precision::ALL {
        if let Some(t) = promise.get(&precision) {
            let judged = t.runs - t.broken;
            items.push(format!(
                "**polytri's promise, {}**: {} of {} polytri runs on inputs valid as {} sees them are valid in those coordinates ({}).",
                precision.name(),
                t.valid_seen,
                judged,
                precision.name(),
                pct(t.seen_rate())
            ));
        }
    }

    if !broken.is_empty() {
        let simple = broken.iter().filter(|(_, d)| d.is_none()).count();
        let f64_count = broken
            .iter()
            .filter(|(at, _)| results.run_at(*at).1.config.precision == Precision::F64)
            .count();
        items.push(format!(
            "**Exceptions: {} runs ({f64_count} of them in f64), {simple} on inputs without degeneracies** — the rest on inputs that rounding made weakly simple (teeth and slivers collapsed to zero width: vertices on edges, overlapping collinear edges, zero-area rings), which the oracle accepts and polytri's strict mode neither refuses nor triangulates: a core bug, see [polytri's promise](#polytris-promise).",
            broken.len()
        ));
    }

    // How far f32 stays valid, generator families.
    let generators: Vec<Source> = results
        .plan
        .sources
        .iter()
        .copied()
        .filter(|s| is_generator(*s))
        .collect();
    // Per configuration: the worst family's limit, the median family's, and how many
    // families never failed.
    let summary = |config: Config| {
        let mut ups: Vec<Option<i32>> = generators
            .iter()
            .map(|&s| results.limit(s, config).valid_up_to)
            .collect();
        ups.sort();
        let clean = generators
            .iter()
            .filter(|&&s| results.limit(s, config).first_failure.is_none())
            .count();
        let worst = ups.first().copied().flatten();
        let median = ups.get(ups.len() / 2).copied().flatten();
        (worst, median, clean)
    };
    let up_to = |d: Option<i32>| {
        d.map_or("not even offset/scale 1e0".to_owned(), |d| {
            format!("offset/scale {}", power(d))
        })
    };
    for config in configs(Precision::F32) {
        let (worst, median, clean) = summary(config);
        items.push(format!(
            "**{config}**, in the user's coordinates: valid on every generated family up to {}; on the median family up to {}; {clean} of {} families valid on the whole grid.",
            up_to(worst),
            up_to(median),
            generators.len()
        ));
    }
    if let Some(first) = generators
        .iter()
        .filter_map(|&s| results.first_broken(s))
        .min()
    {
        items.push(format!(
            "f32 rounding first breaks a generated input (makes it non-simple) at offset/scale {}.",
            power(first)
        ));
    }
    let overall = results.tally(|case, run| {
        (is_generator(case.spec.source) && run.config.precision == Precision::F32)
            .then_some(run.config.subject)
    });
    let cell = |s: Subject| overall.get(&s).map(|t| (t.user_rate(), t.seen_rate()));
    if let (Some(p), Some(e)) = (cell(Subject::PolytriFast), cell(Subject::Earcut)) {
        items.push(format!(
            "Over the whole grid of generated cases in f32: polytri (fast) {} valid in the user's coordinates and {} in f32's own; earcut {} and {}.",
            pct(p.0),
            pct(p.1),
            pct(e.0),
            pct(e.1)
        ));
    }
    doc.list(items);

    doc.text("How far each configuration stays valid in the user's coordinates, as the largest decade of *ratio* up to which every run was valid (and the decade of the first failure). *ratio* is the largest coordinate magnitude over the feature length: max(offset, size) / size for the generator families, max(offset, size) / (d · size) for `gap` and `spike`.");
    let mut table = Table::new(
        ["family", "f32 rounding breaks input at"]
            .into_iter()
            .map(str::to_owned)
            .chain(configs(Precision::F32).iter().map(|c| c.to_string()))
            .chain(["polytri-fast f64".to_owned(), "earcut f64".to_owned()]),
    );
    for &source in &results.plan.sources {
        let mut row = vec![
            source.name().to_owned(),
            results
                .first_broken(source)
                .map_or("never".to_owned(), power),
        ];
        for config in configs(Precision::F32) {
            row.push(limit_text(results.limit(source, config)));
        }
        for subject in [Subject::PolytriFast, Subject::Earcut] {
            let config = Config {
                subject,
                precision: Precision::F64,
            };
            row.push(limit_text(results.limit(source, config)));
        }
        table.row(row);
    }
    doc.table(table);
}

/// A chart line per configuration from tallies keyed by `(config, x)`.
fn series_from(
    groups: &BTreeMap<(Config, i32), Tally>,
    rate: impl Fn(&Tally) -> Option<f64>,
) -> Vec<Series> {
    Config::all()
        .into_iter()
        .map(|config| {
            let subject = Subject::ALL
                .iter()
                .position(|&s| s == config.subject)
                .unwrap_or(0);
            Series {
                name: config.to_string(),
                color: charts::palette(subject),
                dashed: config.precision == Precision::F64,
                points: groups
                    .iter()
                    .filter(|((c, _), _)| *c == config)
                    .filter_map(|((_, x), t)| rate(t).map(|r| (*x, 100.0 * r)))
                    .collect(),
            }
        })
        .filter(|s| !s.points.is_empty())
        .collect()
}

/// The "input broken by f32 rounding" line.
fn broken_series(groups: &BTreeMap<(Config, i32), Tally>) -> Series {
    let reference = Config {
        subject: Subject::PolytriFast,
        precision: Precision::F32,
    };
    Series {
        name: "f32 rounding broke the input".to_owned(),
        color: charts::palette(4),
        dashed: true,
        points: groups
            .iter()
            .filter(|((c, _), _)| *c == reference)
            .filter_map(|((_, x), t)| t.broken_rate().map(|r| (*x, 100.0 * r)))
            .collect(),
    }
}

fn x_range(groups: &BTreeMap<(Config, i32), Tally>) -> (i32, i32) {
    let xs = groups.keys().map(|(_, x)| *x);
    (xs.clone().min().unwrap_or(0), xs.max().unwrap_or(1))
}

/// The chart files: `(file, title, caption, chart)`.
fn charts_of(results: &Results) -> Vec<(String, String, Chart)> {
    let zero_at = zero_position(results);
    let by_offset = results.tally(|case, run| {
        is_generator(case.spec.source).then(|| (run.config, offset_x(case, zero_at)))
    });
    let by_scale = results.tally(|case, run| {
        is_generator(case.spec.source).then(|| (run.config, decade(case.spec.effective_scale())))
    });
    let by_feature = results.tally(|case, run| {
        (!is_generator(case.spec.source)).then(|| (run.config, decade(case.spec.feature_ratio())))
    });
    let mut user = series_from(&by_offset, Tally::failure_rate);
    user.push(broken_series(&by_offset));
    let seen = series_from(&by_offset, Tally::seen_failure_rate);
    let mut scale = series_from(&by_scale, Tally::failure_rate);
    scale.push(broken_series(&by_scale));
    let mut feature = series_from(&by_feature, Tally::failure_rate);
    feature.push(broken_series(&by_feature));
    vec![
        (
            "precision-offset.svg".to_owned(),
            "Failure rate against offset/scale (generated families, in the user's coordinates; refusals count as failures). Solid: f32, dashed: f64; grey: share of inputs f32 rounding made non-simple.".to_owned(),
            Chart {
                title: "Invalid meshes in the user's coordinates vs offset/scale".to_owned(),
                x_desc: "offset / scale".to_owned(),
                y_desc: "invalid meshes, %".to_owned(),
                x_range: x_range(&by_offset),
                zero_at: Some(zero_at),
                series: user,
            },
        ),
        (
            "precision-seen.svg".to_owned(),
            "Failure rate in the coordinates each precision sees, on inputs its rounding left valid: the algorithm's own failures. polytri's exact predicates keep it at 0.".to_owned(),
            Chart {
                title: "Invalid meshes in the precision's own coordinates vs offset/scale".to_owned(),
                x_desc: "offset / scale".to_owned(),
                y_desc: "invalid meshes, %".to_owned(),
                x_range: x_range(&by_offset),
                zero_at: Some(zero_at),
                series: seen,
            },
        ),
        (
            "precision-scale.svg".to_owned(),
            "Failure rate against the polygon's size, every offset pooled (generated families, user's coordinates).".to_owned(),
            Chart {
                title: "Invalid meshes in the user's coordinates vs scale".to_owned(),
                x_desc: "scale (side of the polygon's square)".to_owned(),
                y_desc: "invalid meshes, %".to_owned(),
                x_range: x_range(&by_scale),
                zero_at: None,
                series: scale,
            },
        ),
        (
            "precision-feature.svg".to_owned(),
            "Failure rate for `gap` and `spike` against max(offset, size) / (d · size): how many feature lengths the coordinates' magnitude spans (user's coordinates).".to_owned(),
            Chart {
                title: "Invalid meshes vs coordinate magnitude / feature size".to_owned(),
                x_desc: "max(offset, size) / feature length".to_owned(),
                y_desc: "invalid meshes, %".to_owned(),
                x_range: x_range(&by_feature),
                zero_at: None,
                series: feature,
            },
        ),
    ]
}

fn chart_section(doc: &mut Doc, results: &Results, extras: &mut Vec<Extra>) {
    doc.heading(2, "Charts");
    for (file, caption, chart) in charts_of(results) {
        if chart.series.iter().all(|s| s.points.is_empty()) {
            continue;
        }
        match charts::draw(&chart) {
            Ok(svg) => {
                extras.push(Extra {
                    file: file.clone(),
                    content: svg.clone(),
                });
                doc.picture(file, svg, caption);
            }
            Err(e) => doc.text(format!("(chart not drawn: {e})")),
        }
    }
}

fn ratio_table(doc: &mut Doc, results: &Results) {
    doc.heading(2, "Validity by offset/scale");
    doc.text("Generated families pooled. Cells: `user% (seen%)` valid.");
    let zero_at = zero_position(results);
    let groups = results.tally(|case, run| {
        is_generator(case.spec.source).then(|| (offset_x(case, zero_at), run.config))
    });
    let configs = Config::all();
    let mut table = Table::new(
        ["offset / scale", "runs", "f32 broke input"]
            .into_iter()
            .map(str::to_owned)
            .chain(configs.iter().map(|c| c.to_string())),
    );
    let xs: Vec<i32> = {
        let mut xs: Vec<i32> = groups.keys().map(|(x, _)| *x).collect();
        xs.dedup();
        xs
    };
    for x in xs {
        let reference = groups.get(&(x, configs[0]));
        let mut row = vec![
            if x == zero_at {
                "0".to_owned()
            } else {
                power(x)
            },
            reference.map_or(0, |t| t.runs).to_string(),
            pct(reference.and_then(Tally::broken_rate)),
        ];
        row.extend(configs.iter().map(|&c| both(groups.get(&(x, c)))));
        table.row(row);
    }
    doc.table(table);
}

/// Runs, broken, refused, rates, deviation quantiles and angles of one tally.
fn stats_cells(t: &Tally) -> Vec<String> {
    vec![
        t.runs.to_string(),
        t.broken.to_string(),
        t.refused.to_string(),
        pct(t.seen_rate()),
        pct(t.user_rate()),
        sci(t.deviation(0.5)),
        sci(t.deviation(0.99)),
        sci(t.deviation(1.0)),
        deg(t.min_angle()),
        deg(t.median_min_angle()),
    ]
}

const STATS_HEADERS: [&str; 10] = [
    "runs",
    "broken",
    "refused",
    "valid (seen)",
    "valid (user)",
    "deviation p50",
    "p99",
    "max",
    "min angle",
    "median min angle",
];

fn family_table(doc: &mut Doc, results: &Results) {
    doc.heading(2, "By family");
    doc.text("Every scale and offset pooled. *broken*: runs whose input f32 rounding made non-simple; *refused*: no mesh (polytri's strict refusal, or a peer that failed or moved vertices). Deviation is earcut's |area(polygon) − Σ area(triangles)| / area(polygon) in the user's coordinates; angles are over meshes valid there.");
    let groups = results
        .tally(|case, run| Some((case.spec.source, run.config.precision, run.config.subject)));
    let mut table = Table::new(
        ["family", "precision", "triangulator"]
            .into_iter()
            .chain(STATS_HEADERS),
    );
    for ((source, precision, subject), t) in &groups {
        let mut row = vec![
            source.name().to_owned(),
            precision.name().to_owned(),
            subject.name().to_owned(),
        ];
        row.extend(stats_cells(t));
        table.row(row);
    }
    doc.table(table);
}

fn feature_table(doc: &mut Doc, results: &Results) {
    let groups = results.tally(|case, run| {
        let d = case.spec.feature?;
        (run.config.precision == Precision::F32).then_some((
            case.spec.source,
            Reverse(OrdKey(d)),
            OrdKey(case.spec.offset),
            run.config.subject,
        ))
    });
    if groups.is_empty() {
        return;
    }
    doc.heading(2, "Feature sizes (f32)");
    doc.text("`gap`: a hole whose corners come within d · size of the outer ring; `spike`: a spike of base width d · size. Every scale pooled (scales are powers of two, so only offset / size matters). Cells: `user% (seen%)` valid.");
    let mut table = Table::new(
        ["family", "d", "offset", "runs", "f32 broke input"]
            .into_iter()
            .map(str::to_owned)
            .chain(Subject::ALL.iter().map(|s| format!("{} f32", s.name()))),
    );
    let mut keys: Vec<_> = groups.keys().map(|(s, d, o, _)| (*s, *d, *o)).collect();
    keys.dedup();
    for (source, d, offset) in keys {
        let first = groups.get(&(source, d, offset, Subject::ALL[0]));
        let mut row = vec![
            source.name().to_owned(),
            format!("{:e}", d.0 .0),
            if offset.0 == 0.0 {
                "0".to_owned()
            } else {
                format!("{:e}", offset.0)
            },
            first.map_or(0, |t| t.runs).to_string(),
            pct(first.and_then(Tally::broken_rate)),
        ];
        row.extend(
            Subject::ALL
                .iter()
                .map(|&s| both(groups.get(&(source, d, offset, s)))),
        );
        table.row(row);
    }
    doc.table(table);
}

/// A non-negative grid value as an ordered key.
#[derive(Clone, Copy, Debug, PartialEq)]
struct OrdKey(f64);

impl Eq for OrdKey {}

impl PartialOrd for OrdKey {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for OrdKey {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0)
    }
}

/// Every broken promise with the degeneracies of its input as the precision saw it.
fn broken_promises(results: &Results) -> Vec<(RunRef, Degeneracy)> {
    results
        .broken_promises()
        .into_iter()
        .map(|at| {
            let (case, run) = results.run_at(at);
            let seen = replay(&case.spec, results.plan.vertices, run.config).seen;
            (at, degeneracy(&seen))
        })
        .collect()
}

fn promise_section(
    doc: &mut Doc,
    results: &Results,
    broken: &[(RunRef, Degeneracy)],
    extras: &mut Vec<Extra>,
) {
    doc.heading(2, "polytri's promise");
    if broken.is_empty() {
        doc.text("Wherever the input is valid as a precision sees it, every polytri mesh in that precision was valid in those coordinates, in both strategies: no exception to explain.");
        return;
    }
    let simple = broken.iter().filter(|(_, d)| d.is_none()).count();
    doc.text(format!(
        "{} polytri runs on inputs valid as their precision sees them gave no valid mesh in those coordinates; {simple} of them on inputs without degeneracies. The oracle accepts weakly simple inputs — coincident vertices, vertices on other edges, collinear edges overlapping along a segment, zero-area rings — and rounding makes exactly those out of thin teeth and slivers. polytri's strict mode neither refuses them nor triangulates them correctly: **a core bug**. The first example of each family and configuration is shrunk (staying valid, still failing) and written beside this report under `cases/`.",
        broken.len()
    ));
    let mut counts: BTreeMap<(Source, Config), (usize, usize)> = BTreeMap::new();
    for &(at, d) in broken {
        let (case, run) = results.run_at(at);
        let entry = counts.entry((case.spec.source, run.config)).or_default();
        entry.0 += 1;
        entry.1 += usize::from(d.is_none());
    }
    let mut table = Table::new([
        "family",
        "configuration",
        "runs without a valid mesh",
        "of which on inputs without degeneracies",
    ]);
    for ((source, config), (n, simple)) in &counts {
        table.row(vec![
            source.name().to_owned(),
            config.to_string(),
            n.to_string(),
            simple.to_string(),
        ]);
    }
    doc.table(table);

    let mut items = Vec::new();
    let mut shown = Vec::new();
    for &(at, weak) in broken {
        let (case, run) = results.run_at(at);
        if shown.contains(&(case.spec.source, run.config)) {
            continue;
        }
        shown.push((case.spec.source, run.config));
        let mut small = shrink_failure(results, at);
        small.description = format!(
            "polytri {} in {} gives no valid mesh on this input, valid as {} sees it by the oracle's test (which accepts weakly simple rings): {}. Shrunk from {} ({}; {}).",
            run.config.subject.name(),
            run.config.precision.name(),
            run.config.precision.name(),
            degeneracy(&small.input),
            case.name,
            match run.config.precision {
                Precision::F32 => "rounded to f32",
                Precision::F64 => "as generated",
            },
            run.seen_failure.as_deref().unwrap_or("invalid")
        );
        let file = format!("cases/{}.json", small.name);
        extras.push(Extra {
            file: file.clone(),
            content: small.to_json(),
        });
        items.push(format!(
            "`{}` on `{}`: {}. The input as {} sees it has {}. Shrunk to {} vertices: [{file}]({file})",
            run.config,
            case.name,
            run.seen_failure.as_deref().unwrap_or("invalid"),
            run.config.precision.name(),
            weak,
            small.input.vertices.len(),
        ));
    }
    doc.list(items);
}

fn worst_section(doc: &mut Doc, results: &Results, extras: &mut Vec<Extra>) {
    doc.heading(2, "Worst cases");
    let worst = results.worst(PICTURES);
    if worst.is_empty() {
        doc.text("No mesh was invalid in the user's coordinates.");
        return;
    }
    doc.text("The worst invalid mesh of each configuration (broken promises first, then meshes over inputs rounding left valid, then by flipped triangles and deviation). Left: the coordinates the triangulator computed with; right: the user's. Both panels show the same window, zoomed to the flipped or degenerate triangles (red), or the whole polygon when none is.");
    for (k, &at) in worst.iter().enumerate() {
        let (case, run) = results.run_at(at);
        let replayed = replay(&case.spec, results.plan.vertices, run.config);
        let Ok(triangles) = replayed.triangles else {
            continue;
        };
        let precision = run.config.precision.name();
        let svg = picture::draw(
            &replayed.case.input,
            &replayed.seen,
            &triangles,
            &format!("as {precision} sees it"),
            "as the user gave it",
        );
        let file = format!("worst-{}.svg", k + 1);
        extras.push(Extra {
            file: file.clone(),
            content: svg.clone(),
        });
        doc.picture(file, svg, caption(case, run));
    }
}

fn caption(case: &CaseResult, run: &Run) -> String {
    let input = if case.seen_input_valid(run.config.precision) {
        format!("the input stays valid in {}", run.config.precision.name())
    } else {
        format!(
            "{} rounding broke the input ({})",
            run.config.precision.name(),
            case.f32_problem.as_deref().unwrap_or("invalid")
        )
    };
    format!(
        "{} on {} ({} vertices): {}; {} flipped or degenerate triangles in the user's coordinates. Seen: {}. User: {}.",
        run.config,
        case.name,
        case.vertices,
        input,
        run.flipped,
        run.seen_failure.as_deref().unwrap_or("valid"),
        run.user_failure.as_deref().unwrap_or("valid")
    )
}

fn detail_table(doc: &mut Doc, results: &Results) {
    doc.heading(2, "Detail");
    let groups = results.tally(|case, run| {
        is_generator(case.spec.source).then_some((
            case.spec.source,
            OrdKey(case.spec.scale),
            OrdKey(case.spec.offset),
            run.config.precision,
            run.config.subject,
        ))
    });
    let mut table = Table::new(
        ["family", "scale", "offset", "precision", "broken"]
            .into_iter()
            .map(str::to_owned)
            .chain(Subject::ALL.iter().map(|s| s.name().to_owned()))
            .chain([
                "polytri-fast deviation max".to_owned(),
                "polytri-fast min angle".to_owned(),
            ]),
    );
    let mut keys: Vec<_> = groups
        .keys()
        .map(|(f, s, o, p, _)| (*f, *s, *o, *p))
        .collect();
    keys.dedup();
    for (family, scale, offset, precision) in keys {
        let get = |s: Subject| groups.get(&(family, scale, offset, precision, s));
        let fast = get(Subject::PolytriFast);
        let mut row = vec![
            family.name().to_owned(),
            format!("{:e}", scale.0),
            if offset.0 == 0.0 {
                "0".to_owned()
            } else {
                format!("{:e}", offset.0)
            },
            precision.name().to_owned(),
            fast.map_or(0, |t| t.broken).to_string(),
        ];
        row.extend(Subject::ALL.iter().map(|&s| both(get(s))));
        row.push(sci(fast.and_then(|t| t.deviation(1.0))));
        row.push(deg(fast.and_then(Tally::min_angle)));
        table.row(row);
    }
    doc.folded(
        "Every family × scale × offset × precision (cells: `user% (seen%)` valid)",
        table,
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_are_short() {
        assert_eq!(pct(Some(1.0)), "100%");
        assert_eq!(pct(Some(0.975)), "97.5%");
        assert_eq!(pct(None), "—");
        assert_eq!(sci(Some(0.0)), "0");
        assert_eq!(sci(Some(3.14e-9)), "3.1e-9");
        assert_eq!(deg(Some(12.345)), "12.35°");
        let limit = Limit::from_decades([(0, true), (3, false)]);
        assert_eq!(limit_text(limit), "1e0 (fails at 1e3)");
        let limit = Limit::from_decades([(0, true), (3, true)]);
        assert_eq!(limit_text(limit), "all (to 1e3)");
    }
}
