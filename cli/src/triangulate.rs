//! `polytri triangulate`: read a file of polygons, triangulate them all, write the result.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use clap::ValueEnum;
use polytri::{Coord, Error, Nesting, Options, Strategy, Triangulator};

use crate::input::{self, Input};
use crate::layout::Layout;
use crate::{output, say, Failure};

/// Arguments of `polytri triangulate`.
#[derive(Debug, clap::Args)]
#[command(after_help = "\
Input formats, recognised from the file: rings JSON [[[x, y], …], …] (first ring outer, \
the rest holes), shapes JSON (a list of such polygons), GeoJSON (Polygon, MultiPolygon, \
Feature, FeatureCollection, GeometryCollection) and WKT (POLYGON, MULTIPOLYGON, \
GEOMETRYCOLLECTION; by content or a .wkt name). Extra coordinates (z, m) are ignored, a \
repeated closing point is dropped, and other geometry types are skipped with a warning.

Output JSON: {\"vertices\": [[x, y], …], \"triangles\": [[a, b, c], …]}, the vertices in \
file order, triangles counter-clockwise with y up.

Errors name the place in the file: polygon (when there are several), ring and vertex, \
each counted from 0. Exit status: 0 on success, 1 on bad input, 2 on bad usage.")]
pub struct Args {
    /// The input file (`-` reads standard input)
    #[arg(value_name = "INPUT")]
    pub input: PathBuf,

    /// Write the result to FILE instead of standard output
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Output format [default: svg when FILE ends in .svg, else json]
    #[arg(long, value_enum)]
    pub format: Option<OutputFormat>,

    /// Which ear to clip next: as they come (fast) or the sharpest first (quality)
    #[arg(long, value_enum, default_value_t = StrategyArg::Fast)]
    pub strategy: StrategyArg,

    /// Coordinate type to triangulate in; the file is always read as f64
    #[arg(long, value_enum, default_value_t = Precision::F64)]
    pub precision: Precision,

    /// Which rings are holes: by containment (auto), or each polygon's first ring is its
    /// outer boundary and the others its holes (first-outer, earcut's convention)
    #[arg(long, value_enum, default_value_t = NestingArg::Auto)]
    pub nesting: NestingArg,

    /// Repair what can be repaired (crossing edges, misplaced holes, NaN points) instead of
    /// refusing the input; the summary counts the repairs
    #[arg(long)]
    pub lenient: bool,

    /// Threads for files of several polygons (with --nesting first-outer each polygon is
    /// triangulated on its own); 0 uses every core. The result does not depend on it
    #[arg(long, value_name = "N", default_value_t = 0)]
    pub threads: usize,

    /// Print nothing on standard error but errors
    #[arg(short, long)]
    pub quiet: bool,
}

/// What to write.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum OutputFormat {
    /// The result JSON (the README's "The command line").
    Json,
    /// A picture of the triangles and the input rings.
    Svg,
}

/// `--strategy`, mirroring [`polytri::Strategy`] (which is not a clap type).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum StrategyArg {
    /// Clip ears as they come.
    Fast,
    /// Clip the ear with the smallest angle first.
    Quality,
}

/// `--precision`: the coordinate type the triangulator works in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Precision {
    /// Triangulate the coordinates as read.
    F64,
    /// Round the coordinates to f32 first, as a GPU pipeline would.
    F32,
}

/// `--nesting`, mirroring [`polytri::Nesting`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum NestingArg {
    /// Containment decides which rings are holes.
    Auto,
    /// Each polygon's first ring is outer, the rest are its holes.
    FirstOuter,
}

impl Args {
    fn options(&self) -> Options {
        let strategy = match self.strategy {
            StrategyArg::Fast => Strategy::Fast,
            StrategyArg::Quality => Strategy::Quality,
        };
        let nesting = match self.nesting {
            NestingArg::Auto => Nesting::Auto,
            NestingArg::FirstOuter => Nesting::FirstIsOuter,
        };
        Options::new()
            .with_strategy(strategy)
            .with_nesting(nesting)
            .with_lenient(self.lenient)
            .with_threads(self.threads)
    }

    fn output_format(&self) -> OutputFormat {
        let svg_name = self
            .output
            .as_deref()
            .and_then(Path::extension)
            .is_some_and(|ext| ext.eq_ignore_ascii_case("svg"));
        self.format.unwrap_or(if svg_name {
            OutputFormat::Svg
        } else {
            OutputFormat::Json
        })
    }
}

/// Runs `polytri triangulate`.
///
/// # Errors
///
/// A [`Failure`] naming the file and the problem: unreadable or unparseable input, input
/// the triangulator refuses (with the place in the file), or an unwritable output.
pub fn run(args: &Args) -> Result<(), Failure> {
    let name = input::display_name(&args.input);
    let input = input::read(&args.input)?;
    if !args.quiet {
        warn_skipped(&name, &input);
    }
    let layout = Layout::new(&input.polygons);
    if !args.quiet && layout.empty_rings > 0 {
        say(format_args!(
            "polytri: warning: {name}: left out {} empty ring(s)",
            layout.empty_rings
        ));
    }
    // The triangles are u32 indices into all vertices, also when polygons are triangulated
    // one by one; beyond that the offsets would wrap.
    if u32::try_from(layout.vertices.len()).is_err() {
        return Err(Failure(format!(
            "{name}: {} vertices are more than u32 triangle indices can address",
            layout.vertices.len()
        )));
    }

    let options = args.options();
    let outcome = match args.precision {
        Precision::F64 => triangulate_all(&layout.vertices, &layout, &options),
        Precision::F32 => {
            // Rounding is the point of --precision f32; values beyond f32's range become
            // infinite, which the triangulator reports (strict) or drops (lenient).
            let narrow: Vec<[f32; 2]> = layout
                .vertices
                .iter()
                .map(|v| [v[0] as f32, v[1] as f32])
                .collect();
            triangulate_all(&narrow, &layout, &options)
        }
    }
    .map_err(|refused| {
        Failure(format!(
            "{name}: {}",
            describe_error(&refused, &layout, args.precision)
        ))
    })?;

    write_result(args, &layout, &outcome)?;
    if !args.quiet {
        say(format_args!("polytri: {name}: {}", summary(&outcome)));
    }
    Ok(())
}

fn warn_skipped(name: &str, input: &Input) {
    if input.skipped.is_empty() {
        return;
    }
    let list: Vec<String> = input
        .skipped
        .iter()
        .map(|(kind, n)| format!("{n} × {kind}"))
        .collect();
    say(format_args!(
        "polytri: warning: {name}: skipped what is not a polygon: {}",
        list.join(", ")
    ));
}

/// All triangulations of one run, with indices into the layout's vertices.
#[derive(Debug, Default)]
struct Outcome {
    triangles: Vec<[u32; 3]>,
    polygons: usize,
    holes: usize,
    /// Flat indices of the vertices no triangle uses.
    dropped: Vec<usize>,
    repairs: usize,
}

/// An error of the triangulator with what to add to its indices to make them flat: with
/// `first-outer` each polygon is triangulated on its own, and numbered from 0.
#[derive(Debug)]
struct Refusal {
    error: Error,
    vertex_offset: usize,
    ring_offset: usize,
}

/// Triangulates every polygon of `layout`, whose vertices in the wanted precision are
/// `vertices`: in one call when containment decides the nesting, else one call per polygon,
/// as `FirstIsOuter` describes a single polygon.
fn triangulate_all<T: Coord>(
    vertices: &[[T; 2]],
    layout: &Layout,
    options: &Options,
) -> Result<Outcome, Refusal> {
    let pieces: Vec<_> = match options.nesting {
        Nesting::FirstIsOuter => (0..layout.polygon_rings.len())
            .map(|p| (layout.polygon_rings[p].clone(), layout.polygon_vertices(p)))
            .filter(|(rings, span)| !rings.is_empty() && !span.is_empty())
            .collect(),
        Nesting::Auto => vec![(0..layout.ring_starts.len(), 0..vertices.len())],
    };
    // each piece's ring starts, counted from its first vertex
    let starts: Vec<Vec<usize>> = pieces
        .iter()
        .map(|(rings, span)| {
            layout.ring_starts[rings.clone()]
                .iter()
                .map(|s| s - span.start)
                .collect()
        })
        .collect();
    let inputs: Vec<(&[[T; 2]], &[usize])> = pieces
        .iter()
        .zip(&starts)
        .map(|((_, span), starts)| (&vertices[span.clone()], &starts[..]))
        .collect();
    let mut tri = Triangulator::<T>::new();
    let mut out = Vec::new();
    let results = tri.triangulate_many(&inputs, options, &mut out);
    let mut outcome = Outcome::default();
    for (((rings, span), result), triangles) in pieces.iter().zip(results).zip(&out) {
        let report = result.map_err(|error| Refusal {
            error,
            vertex_offset: span.start,
            ring_offset: rings.start,
        })?;
        outcome.polygons += report.polygons;
        outcome.holes += report.holes;
        outcome.repairs += report.repairs.len();
        outcome.dropped.extend(
            report
                .dropped
                .iter()
                .map(|d| d.vertex as usize + span.start),
        );
        // Fits: the caller checked that all vertices are addressable by u32.
        let offset = span.start as u32;
        outcome
            .triangles
            .extend(triangles.iter().map(|t| t.map(|i| i + offset)));
    }
    Ok(outcome)
}

/// Says what the triangulator refused and where in the file.
fn describe_error(refusal: &Refusal, layout: &Layout, precision: Precision) -> String {
    let vertex = |v: usize| layout.describe_vertex(v + refusal.vertex_offset);
    let ring = |r: usize| layout.describe_ring(r + refusal.ring_offset);
    let hint = "(--lenient makes the best of it)";
    match refusal.error {
        Error::NonFinite { vertex: v } => {
            let finite_f64 = layout
                .vertices
                .get(v + refusal.vertex_offset)
                .is_some_and(|p| p[0].is_finite() && p[1].is_finite());
            if finite_f64 && precision == Precision::F32 {
                format!("{}: coordinate out of f32 range {hint}", vertex(v))
            } else {
                format!("{}: coordinate is NaN or infinite {hint}", vertex(v))
            }
        }
        Error::EdgesCross { edge_a, edge_b, .. } => {
            format!(
                "edges cross: the edge from {} and the edge from {} {hint}",
                vertex(edge_a),
                vertex(edge_b)
            )
        }
        Error::RingsOverlap { ring: r, vertex: v } => {
            let corner = layout
                .locate(v + refusal.vertex_offset)
                .map_or(v, |at| at.vertex);
            format!(
                "{} overlaps another ring: it lies on that ring's boundary (e.g. at vertex {corner}) and would cover its inside twice {hint}",
                ring(r)
            )
        }
        Error::RingsCrossAtVertex {
            ring_a,
            ring_b,
            vertex: v,
            ..
        } => {
            if ring_a == ring_b {
                format!(
                    "{} crosses itself at {}, where it passes twice {hint}",
                    ring(ring_a),
                    vertex(v)
                )
            } else {
                format!(
                    "{} and {} cross each other at {}, where both pass {hint}",
                    ring(ring_a),
                    ring(ring_b),
                    vertex(v)
                )
            }
        }
        Error::HoleOutside { ring: r } => {
            format!(
                "{} is a hole outside its outer ring, or inside another hole {hint}",
                ring(r)
            )
        }
        // The rest are not about a place in the file (ring starts are built here), or are
        // bugs of the triangulator; its own words say it best.
        ref other => other.to_string(),
    }
}

fn write_result(args: &Args, layout: &Layout, outcome: &Outcome) -> Result<(), Failure> {
    let write = |w: &mut dyn Write| -> io::Result<()> {
        match args.output_format() {
            OutputFormat::Json => output::write_json(w, &layout.vertices, &outcome.triangles),
            OutputFormat::Svg => output::write_svg(w, layout, &outcome.triangles, &outcome.dropped),
        }
    };
    match &args.output {
        Some(path) => {
            let fail = |e: io::Error| Failure(format!("{}: cannot write: {e}", path.display()));
            let file = File::create(path).map_err(fail)?;
            write(&mut BufWriter::new(file)).map_err(fail)
        }
        None => write(&mut BufWriter::new(io::stdout().lock()))
            .map_err(|e| Failure(format!("cannot write to standard output: {e}"))),
    }
}

fn plural(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

fn summary(outcome: &Outcome) -> String {
    [
        plural(outcome.polygons, "polygon", "polygons"),
        plural(outcome.holes, "hole", "holes"),
        plural(outcome.triangles.len(), "triangle", "triangles"),
        plural(outcome.dropped.len(), "dropped vertex", "dropped vertices"),
        plural(outcome.repairs, "repair", "repairs"),
    ]
    .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn summary_counts_everything() {
        let outcome = Outcome {
            triangles: vec![[0, 1, 2]],
            polygons: 2,
            holes: 1,
            dropped: vec![4, 5],
            repairs: 0,
        };
        assert_eq!(
            summary(&outcome),
            "2 polygons, 1 hole, 1 triangle, 2 dropped vertices, 0 repairs"
        );
    }

    #[test]
    fn errors_are_mapped_back_to_the_file() {
        let square = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let layout = Layout::new(&[vec![square.clone()], vec![square.clone(), square]]);
        // Polygon 1 triangulated alone: its ring 1 is its own ring 1, flat ring 2.
        let refusal = Refusal {
            error: Error::EdgesCross {
                ring_a: 1,
                edge_a: 5,
                ring_b: 0,
                edge_b: 0,
            },
            vertex_offset: 4,
            ring_offset: 1,
        };
        let message = describe_error(&refusal, &layout, Precision::F64);
        assert!(message.contains("polygon 1, ring 1, vertex 1"), "{message}");
        assert!(message.contains("polygon 1, ring 0, vertex 0"), "{message}");
        let refusal = Refusal {
            error: Error::HoleOutside { ring: 1 },
            vertex_offset: 4,
            ring_offset: 1,
        };
        let message = describe_error(&refusal, &layout, Precision::F64);
        assert!(
            message.starts_with("polygon 1, ring 1 is a hole"),
            "{message}"
        );
        let refusal = Refusal {
            error: Error::RingsCrossAtVertex {
                ring_a: 0,
                ring_b: 1,
                vertex: 6,
            },
            vertex_offset: 4,
            ring_offset: 1,
        };
        let message = describe_error(&refusal, &layout, Precision::F64);
        assert!(
            message.starts_with("polygon 1, ring 0 and polygon 1, ring 1 cross each other at polygon 1, ring 1, vertex 2"),
            "{message}"
        );
    }

    #[test]
    fn f32_overflow_is_told_apart_from_nan() {
        let layout = Layout::new(&[vec![vec![[0.0, 0.0], [1e300, 0.0], [1.0, 1.0]]]]);
        let refusal = Refusal {
            error: Error::NonFinite { vertex: 1 },
            vertex_offset: 0,
            ring_offset: 0,
        };
        let message = describe_error(&refusal, &layout, Precision::F32);
        assert_eq!(
            message,
            "ring 0, vertex 1: coordinate out of f32 range (--lenient makes the best of it)"
        );
    }
}
