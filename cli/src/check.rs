//! `polytri check`: judge a triangulation of a file's polygons with the oracle, and print
//! the verdict.

use std::io::{self, Write};
use std::path::PathBuf;

use clap::ValueEnum;
use polytri_oracle::{check_with, CheckOptions, Input as OracleInput, Nesting, Role, Verdict};
use serde::Deserialize;

use crate::input;
use crate::layout::Layout;
use crate::Failure;

/// Arguments of `polytri check`.
#[derive(Debug, clap::Args)]
#[command(after_help = "\
INPUT is read like `polytri triangulate` reads it. RESULT is result JSON, \
{\"vertices\": [[x, y], …], \"triangles\": [[a, b, c], …]}, as `polytri triangulate -o` \
writes it: its vertices must be INPUT's points in file order, and the triangles index them.

The verdict is printed as JSON on standard output: every check with a detail naming the \
first offending triangle or edge (vertex indices into RESULT's vertices), the expected \
triangle count, earcut's deviation, quality metrics and spade's constrained Delaunay \
triangulation for comparison. Exit status: 0 when valid, 1 when not (the failed checks \
are named on standard error) or when a file cannot be read, 2 on bad usage.")]
pub struct Args {
    /// The polygons (`-` reads standard input)
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,

    /// The triangulation to judge, as result JSON
    #[arg(value_name = "RESULT")]
    pub result: PathBuf,

    /// Which rings are holes: each polygon's first ring is outer and the others its holes
    /// (polygons, as the file says), or containment decides (auto)
    #[arg(long, value_enum, default_value_t = NestingArg::Polygons)]
    pub nesting: NestingArg,

    /// Only the exact checks and metrics: skip geo's tests and spade's triangulation
    #[arg(long)]
    pub fast: bool,
}

/// `--nesting`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum NestingArg {
    /// Each polygon's first ring is outer, the rest are its holes.
    Polygons,
    /// Containment depth decides: even outer, odd hole.
    Auto,
}

/// Result JSON as read: non-finite vertices were written as `null`.
#[derive(Debug, Deserialize)]
struct ResultJson {
    vertices: Vec<[Option<f64>; 2]>,
    triangles: Vec<[u32; 3]>,
}

/// Runs `polytri check`.
///
/// # Errors
///
/// A [`Failure`] when a file cannot be read or parsed, when RESULT's vertices are not
/// INPUT's points, or when the triangulation is not valid (after printing the verdict).
pub fn run(args: &Args) -> Result<(), Failure> {
    let input = input::read(&args.input)?;
    let layout = Layout::new(&input.polygons);
    let result = read_result(&args.result)?;
    compare_vertices(args, &layout.vertices, &result.vertices)?;
    let oracle_input = to_oracle(&layout, args.nesting);
    let options = if args.fast {
        CheckOptions::fast()
    } else {
        CheckOptions::full()
    };
    let verdict = check_with(&oracle_input, &result.triangles, &options);
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
    if expected.len() != got.len() {
        return Err(Failure(format!(
            "{result} has {} vertices but {input} has {} points: the result is not of this input",
            got.len(),
            expected.len()
        )));
    }
    // null stands for a non-finite coordinate; NaN equals nothing, so compare it by kind.
    let same = |e: f64, g: Option<f64>| match g {
        Some(g) => e == g || (e.is_nan() && g.is_nan()),
        None => !e.is_finite(),
    };
    if let Some(v) = (0..expected.len())
        .find(|&v| !(same(expected[v][0], got[v][0]) && same(expected[v][1], got[v][1])))
    {
        return Err(Failure(format!(
            "{result}: vertex {v} is {:?}, but point {v} of {input} is {:?}: the result is not of this input",
            got[v], expected[v]
        )));
    }
    Ok(())
}

/// The file's polygons as the oracle's input.
fn to_oracle(layout: &Layout, nesting: NestingArg) -> OracleInput {
    let nesting = match nesting {
        NestingArg::Auto => Nesting::Auto,
        NestingArg::Polygons => Nesting::Roles(
            layout
                .ring_origins
                .iter()
                .map(|o| if o.is_hole() { Role::Hole } else { Role::Outer })
                .collect(),
        ),
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
    fn polygons_give_roles_per_ring() {
        let square = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let hole = vec![[1.0, 1.0], [1.0, 2.0], [2.0, 2.0]];
        let layout = Layout::new(&[vec![square.clone(), vec![], hole], vec![square]]);
        let oracle = to_oracle(&layout, NestingArg::Polygons);
        assert_eq!(
            oracle.nesting,
            Nesting::Roles(vec![Role::Outer, Role::Hole, Role::Outer])
        );
        assert_eq!(oracle.ring_starts, vec![0, 4, 7]);
    }
}
