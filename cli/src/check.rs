//! `polytri check`: judge a triangulation of a file's polygons with the oracle, and print
//! the verdict.

use std::io::{self, Write};
use std::path::PathBuf;

use polytri_oracle::{
    check_fill, check_with, CheckOptions, Input as OracleInput, Nesting, Verdict,
};
use serde::Deserialize;

use crate::input;
use crate::layout::Layout;
use crate::polygon_args::{NestingArg, PolygonArgs};
use crate::triangulate::{FillRuleArg, Precision};
use crate::Failure;

/// Arguments of `polytri check`.
#[derive(Debug, clap::Args)]
#[command(after_help = "\
INPUT is read like `polytri triangulate` reads it. RESULT is result JSON, \
{\"vertices\": [[x, y], …], \"triangles\": [[a, b, c], …]}, as `polytri triangulate -o` \
writes it: its vertices must be INPUT's points in file order, and the triangles index them.

Each polygon is judged on its own, with the triangles on its vertices (--merge: all rings \
together, as `triangulate --merge` makes them). The verdict is printed as JSON on standard \
output: every check with a detail naming the first offending triangle or edge, in RESULT's \
numbers (with several polygons: \"polygon P: …\"), the expected \
triangle count, earcut's deviation, quality metrics and spade's constrained Delaunay \
triangulation for comparison. Exit status: 0 when valid, 1 when not (the failed checks \
are named on standard error) or when a file cannot be read, 2 on bad usage.

With --fill-rule RULE, RESULT is judged as `polytri triangulate --fill-rule RULE` makes \
it: its vertices are INPUT's points, then the vertices added where edges cross (its \
\"added\" list says which polygon's edges each splits), and the triangles must cover \
RULE's region of each polygon (--merge: of all rings) exactly, up to the rounding of the \
added points, without overlapping (the oracle's check_fill: every triangle inside by the \
exact winding number, their area against the region's by an exact slab decomposition). \
Where a polygon added vertices, its failures are in its own numbers: its points, then \
its added vertices.

With --precision f32, INPUT is judged as `polytri triangulate --precision f32` reads it: \
every coordinate rounded to the nearest f32 (RESULT's vertices may be INPUT's points as \
written, which is what triangulate writes, or as rounded).")]
pub struct Args {
    /// The polygons (`-` reads standard input)
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,

    /// The triangulation to judge, as result JSON
    #[arg(value_name = "RESULT")]
    pub result: PathBuf,

    /// --nesting and --merge, as `polytri triangulate` reads the file
    #[command(flatten)]
    pub polygons: PolygonArgs,

    /// Only the exact checks and metrics: skip geo's tests and spade's triangulation
    #[arg(long)]
    pub fast: bool,

    /// Judge the region of this fill rule, as `polytri triangulate --fill-rule` makes it
    /// (RESULT's vertices: INPUT's points, then the added ones)
    #[arg(long, value_enum, value_name = "RULE")]
    pub fill_rule: Option<FillRuleArg>,

    /// The precision RESULT was triangulated in (`polytri triangulate --precision`):
    /// with f32, INPUT's coordinates are rounded to f32 before judging
    #[arg(long, value_enum, default_value_t = Precision::F64)]
    pub precision: Precision,
}

/// Result JSON as read: non-finite vertices were written as `null`.
#[derive(Debug, Deserialize)]
struct ResultJson {
    vertices: Vec<[Option<f64>; 2]>,
    triangles: Vec<[u32; 3]>,
    /// With a fill rule: the added vertices and the (file) edges each splits.
    #[serde(default)]
    added: Vec<AddedJson>,
}

/// One entry of RESULT's `"added"` list.
#[derive(Debug, Deserialize)]
struct AddedJson {
    vertex: usize,
    edges: [usize; 2],
}

/// Runs `polytri check`.
///
/// # Errors
///
/// A [`Failure`] when a file cannot be read or parsed, when RESULT's vertices are not
/// INPUT's points, or when the triangulation is not valid (after printing the verdict).
pub fn run(args: &Args) -> Result<(), Failure> {
    let input = input::read(&args.input)?;
    let mut layout = Layout::new(&input.polygons);
    let result = read_result(&args.result)?;
    // RESULT's first vertices are INPUT's points as written (or, with --precision f32, as
    // rounded); the triangles are judged on the points as triangulated
    let n = layout.vertices.len();
    let file = &result.vertices[..n.min(result.vertices.len())];
    compare_count(args, &layout.vertices, file)?;
    let rounded = narrowed(args.precision, &layout.vertices);
    let as_rounded = args.precision == Precision::F32 && same_points(&rounded, file);
    if !as_rounded {
        compare_vertices(args, &layout.vertices, file)?;
    }
    layout.vertices = rounded;
    if let Some(rule) = args.fill_rule {
        return run_fill(args, &layout, &result, rule);
    }
    // (and no added ones)
    compare_count(args, &layout.vertices, &result.vertices)?;
    let options = if args.fast {
        CheckOptions::fast()
    } else {
        CheckOptions::full()
    };
    let nesting = args.polygons.nesting;
    let verdict = if args.polygons.merge {
        check_with(&to_oracle(&layout, nesting), &result.triangles, &options)
    } else {
        check_each_polygon(&layout, nesting, &result.triangles, &options)
    };
    print_verdict(&verdict)?;
    if verdict.valid {
        Ok(())
    } else {
        Err(Failure(format!(
            "{}: not a valid triangulation of {}: {}",
            input::display_name(&args.result),
            input::display_name(&args.input),
            verdict.failures().join("; ")
        )))
    }
}

/// `polytri check --fill-rule`: each polygon's (or with --merge all rings') region by the
/// rule, judged by the oracle's `check_fill`.
fn run_fill(
    args: &Args,
    layout: &Layout,
    result: &ResultJson,
    rule: FillRuleArg,
) -> Result<(), Failure> {
    let n = layout.vertices.len();
    // (the input's points were compared by `run`)
    let points = &result.vertices[n.min(result.vertices.len())..];
    let name = input::display_name(&args.result);
    let added: Vec<[f64; 2]> = (points.iter().enumerate())
        .map(|(k, p)| match p {
            [Some(x), Some(y)] if x.is_finite() && y.is_finite() => Ok([*x, *y]),
            _ => Err(Failure(format!(
                "{name}: added vertex {} is not a finite point",
                n + k
            ))),
        })
        .collect::<Result<_, _>>()?;
    let rule = rule.rule();
    let verdict = if args.polygons.merge {
        check_fill(
            &layout.vertices,
            &layout.ring_starts,
            rule,
            &added,
            &result.triangles,
        )
    } else {
        check_fill_per_polygon(layout, result, &added, rule)
            .map_err(|e| Failure(format!("{name}: {e}")))?
    };
    print_verdict(&verdict)?;
    if verdict.valid {
        Ok(())
    } else {
        Err(Failure(format!(
            "{name}: not a valid triangulation of the {} region of {}: {}",
            rule.name(),
            input::display_name(&args.input),
            verdict.failures().join("; ")
        )))
    }
}

/// `check_fill` on each polygon with its triangles: those whose corners are its points and
/// the points added on its edges (RESULT's `"added"` list says whose), in the polygon's
/// own numbers (its points, then its added ones).
fn check_fill_per_polygon(
    layout: &Layout,
    result: &ResultJson,
    added: &[[f64; 2]],
    rule: polytri::FillRule,
) -> Result<Verdict, String> {
    let n = layout.vertices.len();
    let polygons = layout.polygon_rings.len();
    // each added vertex's polygon (that of the first edge it splits) and local number
    let mut owner = vec![None; added.len()];
    let mut own_added: Vec<Vec<[f64; 2]>> = vec![Vec::new(); polygons];
    for entry in &result.added {
        let k = (entry.vertex.checked_sub(n))
            .filter(|&k| k < added.len())
            .ok_or_else(|| format!("\"added\" names vertex {}, not an added one", entry.vertex))?;
        let p = (layout.locate(entry.edges[0]))
            .ok_or_else(|| {
                format!(
                    "added vertex {} splits edge {}, which is no edge of the input",
                    entry.vertex, entry.edges[0]
                )
            })?
            .polygon;
        let span = layout.polygon_vertices(p);
        owner[k] = Some((p, span.len() + own_added[p].len()));
        own_added[p].push(added[k]);
    }
    if let Some(k) = owner.iter().position(Option::is_none) {
        return Err(format!(
            "vertex {} follows the input's points but is not in the \"added\" list (say whose edges it splits, or use --merge)",
            n + k
        ));
    }
    let local = |v: u32| -> Option<(usize, u32)> {
        let v = v as usize;
        if v < n {
            let at = layout.locate(v)?;
            Some((
                at.polygon,
                (v - layout.polygon_vertices(at.polygon).start) as u32,
            ))
        } else {
            owner
                .get(v - n)
                .copied()
                .flatten()
                .map(|(p, i)| (p, i as u32))
        }
    };
    let mut by_polygon: Vec<Vec<[u32; 3]>> = vec![Vec::new(); polygons];
    let mut numbers: Vec<Vec<usize>> = vec![Vec::new(); polygons];
    let mut joining = Vec::new();
    for (k, t) in result.triangles.iter().enumerate() {
        match t.map(local) {
            [Some((a, x)), Some((b, y)), Some((c, z))] if a == b && b == c => {
                by_polygon[a].push([x, y, z]);
                numbers[a].push(k);
            }
            _ => joining.push(k),
        }
    }
    let mut verdicts = Vec::new();
    for p in 0..polygons {
        let rings = layout.polygon_rings[p].clone();
        if rings.is_empty() {
            continue;
        }
        let span = layout.polygon_vertices(p);
        let starts = layout.ring_starts_from(rings.clone(), span.start);
        let mut verdict = check_fill(
            &layout.vertices[span.clone()],
            &starts,
            rule,
            &own_added[p],
            &by_polygon[p],
        );
        if own_added[p].is_empty() {
            for check in &mut verdict.checks {
                if let Some(detail) = &mut check.detail {
                    *detail = file_numbers(detail, &numbers[p], span.start, rings.start);
                }
            }
        }
        verdicts.push((p, verdict));
    }
    let mut verdict = sum_verdicts(&verdicts, polygons > 1);
    flag_joining(
        &mut verdict,
        &joining,
        &result.triangles,
        "different polygons or no vertex",
    );
    Ok(verdict)
}

fn read_result(path: &std::path::Path) -> Result<ResultJson, Failure> {
    let name = input::display_name(path);
    let text =
        std::fs::read_to_string(path).map_err(|e| Failure(format!("{name}: cannot read: {e}")))?;
    serde_json::from_str(&text).map_err(|e| {
        Failure(format!(
            "{name}: not result JSON {{\"vertices\": [[x, y], …], \"triangles\": [[a, b, c], …]}}: {e}"
        ))
    })
}

/// The points as `polytri triangulate --precision` triangulates them: as read, or each
/// coordinate rounded to the nearest `f32` (beyond its range: infinite, as there).
fn narrowed(precision: Precision, points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    match precision {
        Precision::F64 => points.to_vec(),
        Precision::F32 => (points.iter())
            .map(|p| p.map(|c| f64::from(c as f32)))
            .collect(),
    }
}

/// Whether `got` lists the points `expected` (as many, each equal).
fn same_points(expected: &[[f64; 2]], got: &[[Option<f64>; 2]]) -> bool {
    expected.len() == got.len() && expected.iter().zip(got).all(|(&e, &g)| same_point(e, g))
}

/// Whether a vertex of RESULT is the point `expected`: null stands for a non-finite
/// coordinate; NaN equals nothing, so it is compared by kind.
fn same_point(expected: [f64; 2], got: [Option<f64>; 2]) -> bool {
    let same = |e: f64, g: Option<f64>| match g {
        Some(g) => e == g || (e.is_nan() && g.is_nan()),
        None => !e.is_finite(),
    };
    same(expected[0], got[0]) && same(expected[1], got[1])
}

/// As many vertices as points.
fn compare_count(
    args: &Args,
    expected: &[[f64; 2]],
    got: &[[Option<f64>; 2]],
) -> Result<(), Failure> {
    if expected.len() == got.len() {
        return Ok(());
    }
    Err(Failure(format!(
        "{} has {} vertices but {} has {} points: the result is not of this input",
        input::display_name(&args.result),
        got.len(),
        input::display_name(&args.input),
        expected.len()
    )))
}

/// RESULT's vertices must be INPUT's points, else the indices mean something else.
fn compare_vertices(
    args: &Args,
    expected: &[[f64; 2]],
    got: &[[Option<f64>; 2]],
) -> Result<(), Failure> {
    let (result, input) = (
        input::display_name(&args.result),
        input::display_name(&args.input),
    );
    compare_count(args, expected, got)?;
    if let Some(v) = (0..expected.len()).find(|&v| !same_point(expected[v], got[v])) {
        return Err(Failure(format!(
            "{result}: vertex {v} is {:?}, but point {v} of {input} is {:?}: the result is not of this input",
            got[v], expected[v]
        )));
    }
    Ok(())
}

/// Judges each polygon of the file on its own, with the triangles whose corners are all
/// its vertices (a triangle joining two polygons fails `indices`), and sums the verdicts
/// up: valid when every polygon's is, each failed check naming its polygon.
fn check_each_polygon(
    layout: &Layout,
    nesting: NestingArg,
    triangles: &[[u32; 3]],
    options: &CheckOptions,
) -> Verdict {
    let mut verdicts = Vec::new();
    let mut joining = Vec::new();
    // (a binary search over the ring starts)
    let polygon_of = |v: u32| layout.locate(v as usize).map(|at| at.polygon);
    let mut by_polygon: Vec<Vec<[u32; 3]>> = vec![Vec::new(); layout.polygon_rings.len()];
    // each polygon's triangles' numbers in RESULT
    let mut numbers: Vec<Vec<usize>> = vec![Vec::new(); layout.polygon_rings.len()];
    for (k, t) in triangles.iter().enumerate() {
        match t.map(polygon_of) {
            [Some(a), Some(b), Some(c)] if a == b && b == c => {
                let first = layout.polygon_vertices(a).start as u32;
                by_polygon[a].push(t.map(|v| v - first));
                numbers[a].push(k);
            }
            _ => joining.push(k),
        }
    }
    for (p, triangles) in by_polygon.iter().enumerate() {
        let rings = layout.polygon_rings[p].clone();
        let span = layout.polygon_vertices(p);
        if rings.is_empty() {
            continue;
        }
        let starts = layout.ring_starts_from(rings.clone(), span.start);
        let nesting = match nesting {
            NestingArg::Auto => Nesting::Auto,
            NestingArg::FirstOuter => Nesting::FirstIsOuter,
        };
        let input = OracleInput::new(layout.vertices[span.clone()].to_vec(), starts, nesting);
        let mut verdict = check_with(&input, triangles, options);
        // the details in RESULT's numbers: triangles, vertices and rings of the file
        for check in &mut verdict.checks {
            if let Some(detail) = &mut check.detail {
                *detail = file_numbers(detail, &numbers[p], span.start, rings.start);
            }
        }
        verdicts.push((p, verdict));
    }
    let mut verdict = sum_verdicts(&verdicts, layout.polygon_rings.len() > 1);
    flag_joining(&mut verdict, &joining, triangles, "different polygons");
    verdict
}

/// Fails `verdict` for the triangles `joining` (their numbers in `triangles`), whose
/// corners are of `what`, naming the first.
fn flag_joining(verdict: &mut Verdict, joining: &[usize], triangles: &[[u32; 3]], what: &str) {
    let Some(&k) = joining.first() else {
        return;
    };
    verdict.valid = false;
    verdict.triangles += joining.len();
    verdict.checks.insert(
        0,
        polytri_oracle::Check {
            name: "indices".to_owned(),
            passed: false,
            detail: Some(format!(
                "triangle {k} {:?} joins vertices of {what} (and {} more)",
                triangles[k],
                joining.len() - 1
            )),
        },
    );
}

/// `detail`, about one polygon judged on its own, with its numbers made the file's: a
/// triangle's (`triangle K`) by `triangles` (RESULT's number of each of the polygon's
/// triangles), a vertex's (in `(a, b, c)`, `u→v`, `u–v`, `vertex V`) plus `vertex0`, a
/// ring's (`ring R`) plus `ring0`.
fn file_numbers(detail: &str, triangles: &[usize], vertex0: usize, ring0: usize) -> String {
    let mut out = String::with_capacity(detail.len());
    let mut rest = detail;
    // what the next number is: a triangle, a ring, or (in a triple or edge) a vertex
    let mut kind = ' ';
    while let Some(start) = rest.find(|c: char| c.is_ascii_digit()) {
        let (before, from) = rest.split_at(start);
        let end = from
            .find(|c: char| !c.is_ascii_digit())
            .unwrap_or(from.len());
        let (digits, after) = from.split_at(end);
        out.push_str(before);
        // the word before the number, without an opening bracket ("(ring 0)")
        let word = (before.trim_end().rsplit(' ').next().unwrap_or("")).trim_start_matches('(');
        // an end of an edge u→v or u–v, a corner of a triple (a, b, c), or named
        let in_edge = after.starts_with(['→', '–']) || before.ends_with(['→', '–']);
        let in_triple = before.ends_with('(') || (before == ", " && kind == 'v');
        kind = match word {
            "triangle" => 't',
            "ring" => 'r',
            _ if in_edge || in_triple => 'v',
            "vertex" | "edge" | "edges" => 'v',
            _ => ' ',
        };
        let n: usize = digits.parse().unwrap_or(0);
        let mapped = match kind {
            't' => triangles.get(n).copied(),
            'v' => Some(n + vertex0),
            'r' => Some(n + ring0),
            _ => None,
        };
        match mapped {
            // (a number too long to parse is left as it is)
            Some(m) if digits.len() < 19 => out.push_str(&m.to_string()),
            _ => out.push_str(digits),
        }
        rest = after;
    }
    out.push_str(rest);
    out
}

/// One verdict for several polygons': every check passes where it passes for all (a
/// failure's detail names its polygon when there are several), counts and spade's CDT
/// add up, the deviation and worst aspect are the largest, the smallest angles the
/// smallest.
fn sum_verdicts(verdicts: &[(usize, Verdict)], several: bool) -> Verdict {
    let Some((_, first)) = verdicts.first() else {
        return check_with(
            &OracleInput::new(Vec::new(), Vec::new(), Nesting::Auto),
            &[],
            &CheckOptions::fast(),
        );
    };
    let mut sum = first.clone();
    // spade's CDTs add up when every polygon has one
    sum.cdt = (verdicts.iter())
        .map(|(_, v)| v.cdt.clone())
        .reduce(|a, b| {
            let (a, b) = (a?, b?);
            Some(polytri_oracle::CdtComparison {
                triangles: a.triangles + b.triangles,
                area: a.area + b.area,
                min_angle_deg: a.min_angle_deg.min(b.min_angle_deg),
            })
        })
        .flatten();
    for check in &mut sum.checks {
        check.passed = true;
        check.detail = None;
    }
    sum.triangles = 0;
    sum.expected_triangles = Some(0);
    sum.total_edge_length = 0.0;
    for (p, v) in verdicts {
        sum.valid &= v.valid;
        sum.input_valid &= v.input_valid;
        sum.triangles += v.triangles;
        sum.expected_triangles = sum
            .expected_triangles
            .zip(v.expected_triangles)
            .map(|(a, b)| a + b);
        sum.deviation = sum.deviation.max(v.deviation);
        sum.min_angle_deg = sum.min_angle_deg.min(v.min_angle_deg);
        sum.worst_aspect = sum.worst_aspect.max(v.worst_aspect);
        sum.total_edge_length += v.total_edge_length;
        for check in &v.checks {
            match sum.checks.iter_mut().find(|c| c.name == check.name) {
                Some(c) if c.passed && !check.passed => {
                    c.passed = false;
                    c.detail = check.detail.as_ref().map(|d| {
                        if several {
                            format!("polygon {p}: {d}")
                        } else {
                            d.clone()
                        }
                    });
                }
                Some(_) => {}
                None => sum.checks.push(check.clone()),
            }
        }
    }
    sum
}

/// The file's polygons as the oracle's input, all together (`--merge`), as `polytri
/// triangulate --merge` reads them: containment decides, or (first-outer) the file's
/// first ring is outer and every other ring a hole.
fn to_oracle(layout: &Layout, nesting: NestingArg) -> OracleInput {
    let nesting = match nesting {
        NestingArg::Auto => Nesting::Auto,
        NestingArg::FirstOuter => Nesting::FirstIsOuter,
    };
    OracleInput::new(layout.vertices.clone(), layout.ring_starts.clone(), nesting)
}

fn print_verdict(verdict: &Verdict) -> Result<(), Failure> {
    let write = || -> io::Result<()> {
        let mut out = io::stdout().lock();
        serde_json::to_writer_pretty(&mut out, verdict)?;
        out.write_all(b"\n")?;
        out.flush()
    };
    write().map_err(|e| Failure(format!("cannot write to standard output: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn merged_first_outer_makes_the_file_s_first_ring_outer() {
        // as `triangulate --merge --nesting first-outer` reads the file
        let square = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let hole = vec![[1.0, 1.0], [1.0, 2.0], [2.0, 2.0]];
        let layout = Layout::new(&[vec![square.clone(), vec![], hole], vec![square]]);
        let oracle = to_oracle(&layout, NestingArg::FirstOuter);
        assert_eq!(oracle.nesting, Nesting::FirstIsOuter);
        assert_eq!(oracle.ring_starts, vec![0, 4, 7]);
        assert_eq!(to_oracle(&layout, NestingArg::Auto).nesting, Nesting::Auto);
    }

    #[test]
    fn details_get_the_files_numbers() {
        let numbers = [10, 11, 12];
        let f = |d: &str| file_numbers(d, &numbers, 100, 7);
        assert_eq!(
            f("triangle 0 (3, 6, 0) is clockwise"),
            "triangle 10 (103, 106, 100) is clockwise"
        );
        assert_eq!(
            f("edge 3→6 is used by 2 triangles in the same direction (first: triangle 1) (and 3 more)"),
            "edge 103→106 is used by 2 triangles in the same direction (first: triangle 11) (and 3 more)"
        );
        assert_eq!(
            f("edge 1–2 of triangle 2 crosses ring 1 edge 4→5"),
            "edge 101–102 of triangle 12 crosses ring 8 edge 104→105"
        );
        assert_eq!(
            f("the triangles cover an area of 7.35e1, the polygon has 9.35e1 (difference -2e1)"),
            "the triangles cover an area of 7.35e1, the polygon has 9.35e1 (difference -2e1)"
        );
        assert_eq!(
            f("the centroid of triangle 2 (1, 2, 3) has winding number 2, not 1"),
            "the centroid of triangle 12 (101, 102, 103) has winding number 2, not 1"
        );
        assert_eq!(
            f("edges 4→5 (ring 0) and 20→9 (ring 1) cross"),
            "edges 104→105 (ring 7) and 120→109 (ring 8) cross"
        );
        assert_eq!(
            f("edge 9→5 of triangle 0 has no twin 5→9 and is not a boundary edge"),
            "edge 109→105 of triangle 10 has no twin 105→109 and is not a boundary edge"
        );
    }
}
