//! `polytri triangulate`: read a file of polygons, triangulate them all, write the result.

use std::borrow::Cow;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::ops::Range;
use std::path::{Path, PathBuf};

use clap::ValueEnum;
use polytri::{Coord, Error, FillRule, Options, Strategy, Triangulator};

use crate::input::{self, Input};
use crate::layout::Layout;
use crate::polygon_args::PolygonArgs;
use crate::{output, say, Failure};

/// Arguments of `polytri triangulate`.
#[derive(Debug, clap::Args)]
#[command(after_help = "\
Input formats, recognised from the file: rings JSON [[[x, y], …], …] (first ring outer, \
the rest holes), shapes JSON (a list of such polygons), GeoJSON (Polygon, MultiPolygon, \
Feature, FeatureCollection, GeometryCollection) and WKT (POLYGON, MULTIPOLYGON, \
GEOMETRYCOLLECTION; by content or a .wkt name). A polygon whose every point has a third \
coordinate (rings JSON, GeoJSON, WKT Z) is a planar polygon in 3D: triangulated in its own plane, \
z kept in the output (JSON, OBJ, GeoJSON); in a file where some polygons have z, the \
others lie in the plane z = 0. Further coordinates are ignored. A \
repeated closing point is dropped, and other geometry types are skipped with a warning.

Output JSON: {\"vertices\": [[x, y], …], \"triangles\": [[a, b, c], …]}, the vertices in \
file order, triangles counter-clockwise with y up. With --fill-rule, the vertices added \
where edges cross follow the file's in \"vertices\", and \"added\": [{\"vertex\": i, \
\"edges\": [a, b]}, …] names each one's index and two edges crossing there (each by the \
vertex it starts at); SVG marks them with red dots, OBJ and GeoJSON use them as vertices.

Fill rules (--fill-rule): the rings may cross themselves and each other and overlap \
anywhere; a point's winding number counts how often the rings, each in its own direction, \
wind counter-clockwise round it, and the region is where the rule accepts it: even-odd \
(odd), nonzero (not 0), positive (above 0), negative (below 0), abs-geq-two (2 or more \
either way: where rings overlap). Which ring is a hole then follows from the windings \
alone: a hole must run the other way round from its outer ring, except with even-odd.

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

    /// --nesting and --merge
    #[command(flatten)]
    pub polygons: PolygonArgs,

    /// Repair what can be repaired (crossing edges, misplaced holes, NaN points) instead of
    /// refusing the input; the summary counts the repairs
    #[arg(long)]
    pub lenient: bool,

    /// Read the rings by a fill rule: they may cross and overlap anywhere, and the region is
    /// where the winding number (how often the rings, each in its own direction, wind
    /// counter-clockwise round a point) satisfies RULE. Crossing points are added as
    /// vertices after the file's. --nesting does not apply
    #[arg(long, value_enum, value_name = "RULE", conflicts_with = "lenient")]
    pub fill_rule: Option<FillRuleArg>,

    /// Strict mode: triangulate every polygon that can be, report each one that cannot,
    /// write the rest, and exit with status 1 if any failed
    #[arg(long)]
    pub keep_going: bool,

    /// With --format geojson: one Feature per triangle instead of one MultiPolygon per
    /// input feature
    #[arg(long)]
    pub per_triangle: bool,

    /// Threads for files of several polygons, and for a polygon of 262,144 vertices or
    /// more (mark-and-cut, fast strategy); 0 uses every core. The result is the same for
    /// every count from 2 on (a polygon that large gets other, equally valid, triangles
    /// with 1)
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
    /// A GeoJSON FeatureCollection: per input feature its triangles as a MultiPolygon,
    /// with the feature's id and properties.
    Geojson,
    /// Wavefront OBJ for graphics tools: `v x y z` lines (z 0 for rings in the plane),
    /// then `f a b c` faces (1-based).
    Obj,
}

/// `--strategy`, mirroring [`polytri::Strategy`] (which is not a clap type).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum StrategyArg {
    /// Clip ears as they come.
    Fast,
    /// Clip the ear with the smallest angle first.
    Quality,
    /// Seidel's trapezoidation: near-linear on every input (the region read even-odd).
    Seidel,
}

/// `--precision`: the coordinate type the triangulator works in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Precision {
    /// Triangulate the coordinates as read.
    F64,
    /// Round the coordinates to f32 first, as a GPU pipeline would.
    F32,
}

/// `--fill-rule`, mirroring [`polytri::FillRule`] (names as [`FillRule::name`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum FillRuleArg {
    /// Inside where the winding number is odd: an overlap of two rings is empty.
    EvenOdd,
    /// Inside where the winding number is not 0: rings winding the same way merge, one
    /// winding the other way inside them cuts a hole.
    #[value(name = "nonzero")]
    NonZero,
    /// Inside where the winding number is above 0: counter-clockwise rings add,
    /// clockwise ones subtract.
    Positive,
    /// Inside where the winding number is below 0: the clockwise rings' side.
    Negative,
    /// Inside where the winding number is 2 or more, or -2 or less: where rings overlap.
    AbsGeqTwo,
}

impl FillRuleArg {
    /// The rule.
    pub fn rule(self) -> FillRule {
        match self {
            FillRuleArg::EvenOdd => FillRule::EvenOdd,
            FillRuleArg::NonZero => FillRule::NonZero,
            FillRuleArg::Positive => FillRule::Positive,
            FillRuleArg::Negative => FillRule::Negative,
            FillRuleArg::AbsGeqTwo => FillRule::AbsGeqTwo,
        }
    }
}

impl Args {
    fn options(&self) -> Options {
        let strategy = match self.strategy {
            StrategyArg::Fast => Strategy::Fast,
            StrategyArg::Quality => Strategy::Quality,
            StrategyArg::Seidel => Strategy::Seidel,
        };
        let options = Options::new()
            .with_strategy(strategy)
            .with_nesting(self.polygons.nesting.nesting())
            .with_lenient(self.lenient)
            .with_threads(self.threads);
        match self.fill_rule {
            Some(rule) => options.with_fill_rule(rule.rule()),
            None => options,
        }
    }

    fn output_format(&self) -> OutputFormat {
        let svg_name = self
            .output
            .as_deref()
            .and_then(Path::extension)
            .is_some_and(|ext| ext.eq_ignore_ascii_case("svg"));
        let extension = |ext: &str| {
            (self.output.as_deref().and_then(Path::extension))
                .is_some_and(|e| e.eq_ignore_ascii_case(ext))
        };
        self.format.unwrap_or(if svg_name {
            OutputFormat::Svg
        } else if extension("geojson") {
            OutputFormat::Geojson
        } else if extension("obj") {
            OutputFormat::Obj
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
    let z = flat_z(&input, &layout);
    if z.is_some() && args.polygons.merge {
        return Err(Failure(format!(
            "{name}: --merge takes rings in the plane; these have z (each polygon is triangulated in its own plane)"
        )));
    }
    if z.is_some() && args.fill_rule.is_some() {
        return Err(Failure(format!(
            "{name}: --fill-rule takes rings in the plane; these have z (added crossing points would have none)"
        )));
    }
    let pieces = pieces(&layout, args.polygons.merge);
    let mut results = match (args.precision, &z) {
        (Precision::F64, Some(z)) => {
            triangulate_pieces_3d(&layout.vertices, z, &layout, &pieces, &options)
        }
        (Precision::F32, Some(z)) => {
            let narrow: Vec<[f32; 2]> = (layout.vertices.iter())
                .map(|v| [v[0] as f32, v[1] as f32])
                .collect();
            let narrow_z: Vec<f32> = z.iter().map(|&z| z as f32).collect();
            triangulate_pieces_3d(&narrow, &narrow_z, &layout, &pieces, &options)
        }
        (Precision::F64, None) => triangulate_pieces(&layout.vertices, &layout, &pieces, &options),
        (Precision::F32, None) => {
            // Rounding is the point of --precision f32; values beyond f32's range become
            // infinite, which the triangulator reports (strict) or drops (lenient).
            let narrow: Vec<[f32; 2]> = layout
                .vertices
                .iter()
                .map(|v| [v[0] as f32, v[1] as f32])
                .collect();
            triangulate_pieces(&narrow, &layout, &pieces, &options)
        }
    };
    number_added(&mut results, layout.vertices.len())
        .map_err(|count| Failure(format!("{name}: {count} vertices with the added ones are more than u32 triangle indices can address")))?;
    let describe = |refused: &Refusal| {
        let hints = if args.fill_rule.is_some() {
            Hints::None
        } else if z.is_some() {
            Hints::Lenient
        } else {
            Hints::FillRule
        };
        let what = describe_error(refused, &layout, args.precision, hints);
        match feature_of(&input, &layout, refused.ring_offset) {
            Some(feature) => format!("{feature}: {what}"),
            None => what,
        }
    };
    let failed: Vec<&Refusal> = results.iter().filter_map(|r| r.as_ref().err()).collect();
    if let Some(first) = failed.first().filter(|_| !args.keep_going) {
        return Err(Failure(format!("{name}: {}", describe(first))));
    }
    for refused in &failed {
        // --keep-going: every refused polygon, then the rest is written
        say(format_args!(
            "polytri: error: {name}: {}",
            describe(refused)
        ));
    }
    let mut outcome = Outcome::gather(&results);
    // with a fill rule the JSON always lists the added vertices (maybe none), else never
    if args.fill_rule.is_some() {
        outcome.added.get_or_insert_with(Vec::new);
    } else {
        outcome.added = None;
    }
    write_result(
        args,
        &input,
        &layout,
        z.as_deref(),
        &pieces,
        &results,
        &outcome,
    )?;
    if !args.quiet {
        say(format_args!("polytri: {name}: {}", summary(&outcome)));
    }
    if failed.is_empty() {
        Ok(())
    } else {
        Err(Failure(format!(
            "{name}: {} of {} refused, the rest written",
            plural(failed.len(), "polygon", "polygons"),
            results.len()
        )))
    }
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

/// What one piece (a polygon, or every ring with --merge) came to, with triangles indexing
/// the layout's vertices.
#[derive(Debug, Default)]
struct Piece {
    triangles: Vec<[u32; 3]>,
    polygons: usize,
    holes: usize,
    /// Flat indices of the vertices no triangle uses.
    dropped: Vec<usize>,
    repairs: usize,
    /// The vertices added where edges cross (with --fill-rule): piece-local in `vertex`
    /// until [`number_added`] numbers them after the file's.
    added: Vec<output::Added>,
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
    /// Pieces refused (with --keep-going).
    refused: usize,
    /// The vertices added where edges cross, numbered after the file's; `None` without
    /// --fill-rule.
    added: Option<Vec<output::Added>>,
}

impl Outcome {
    /// Every piece triangulated, together.
    fn gather(results: &[Result<Piece, Refusal>]) -> Self {
        let mut outcome = Outcome::default();
        for result in results {
            match result {
                Ok(piece) => {
                    outcome.triangles.extend_from_slice(&piece.triangles);
                    outcome.polygons += piece.polygons;
                    outcome.holes += piece.holes;
                    outcome.dropped.extend_from_slice(&piece.dropped);
                    outcome.repairs += piece.repairs;
                    (outcome.added.get_or_insert_with(Vec::new)).extend_from_slice(&piece.added);
                }
                Err(_) => outcome.refused += 1,
            }
        }
        outcome
    }
}

impl Piece {
    /// What the triangulator made of the piece of vertices `span`: its `triangles` and
    /// `report`, indices made flat. Added vertices (with a fill rule) are numbered from
    /// `first_added`, the number of the file's vertices, as if this piece were the only one
    /// to add any: [`number_added`] moves them after the pieces before.
    fn of(
        report: &polytri::Report<'_>,
        triangles: &[[u32; 3]],
        span: &Range<usize>,
        first_added: usize,
    ) -> Self {
        let len = span.len();
        let flat = |i: u32| {
            let i = i as usize;
            // Fits: the caller checked that the file's vertices are addressable by u32, and
            // `number_added` that the added ones are too.
            (if i < len {
                span.start + i
            } else {
                first_added + (i - len)
            })
            .min(u32::MAX as usize) as u32
        };
        Piece {
            triangles: triangles.iter().map(|t| t.map(flat)).collect(),
            polygons: report.polygons,
            holes: report.holes,
            dropped: (report.dropped.iter())
                .map(|d| d.vertex as usize + span.start)
                .collect(),
            repairs: report.repairs.len(),
            added: (report.added.iter().enumerate())
                .map(|(k, a)| output::Added {
                    vertex: k,
                    position: a.position,
                    edges: a.edges.map(|e| e as usize + span.start),
                })
                .collect(),
        }
    }
}

/// Numbers the vertices every piece added after the file's `first` vertices, piece after
/// piece, and points the triangles at them (each piece numbered its own from `first`).
///
/// # Errors
///
/// The number of all vertices, when it is more than `u32` indices address.
fn number_added(results: &mut [Result<Piece, Refusal>], first: usize) -> Result<(), usize> {
    let total = first
        + (results.iter().flatten())
            .map(|p| p.added.len())
            .sum::<usize>();
    if u32::try_from(total).is_err() {
        return Err(total);
    }
    let mut next = first;
    for piece in results.iter_mut().flatten() {
        for i in piece.triangles.iter_mut().flatten() {
            if *i as usize >= first {
                *i += (next - first) as u32;
            }
        }
        for (k, added) in piece.added.iter_mut().enumerate() {
            added.vertex = next + k;
        }
        next += piece.added.len();
    }
    Ok(())
}

/// An error of the triangulator with what to add to its indices to make them flat: each
/// piece is triangulated on its own, and numbered from 0.
#[derive(Debug)]
struct Refusal {
    error: Error,
    vertex_offset: usize,
    ring_offset: usize,
}

impl Refusal {
    /// `error` of the piece of rings `rings` and vertices `span`.
    fn at(error: Error, rings: &Range<usize>, span: &Range<usize>) -> Self {
        Refusal {
            error,
            vertex_offset: span.start,
            ring_offset: rings.start,
        }
    }
}

/// The pieces triangulated on their own, as (rings, vertices) ranges of `layout`: each
/// polygon of the file (or, with `merge`, all rings together), empty ones left out.
fn pieces(layout: &Layout, merge: bool) -> Vec<(Range<usize>, Range<usize>)> {
    if merge {
        return vec![(0..layout.ring_starts.len(), 0..layout.vertices.len())];
    }
    (0..layout.polygon_rings.len())
        .map(|p| (layout.polygon_rings[p].clone(), layout.polygon_vertices(p)))
        .filter(|(rings, span)| !rings.is_empty() && !span.is_empty())
        .collect()
}

/// Triangulates every piece of `layout`, whose vertices in the wanted precision are
/// `vertices`, through `triangulate_many` (spread over `options.threads`).
fn triangulate_pieces<T: Coord>(
    vertices: &[[T; 2]],
    layout: &Layout,
    pieces: &[(Range<usize>, Range<usize>)],
    options: &Options,
) -> Vec<Result<Piece, Refusal>> {
    let starts: Vec<Vec<usize>> = (pieces.iter())
        .map(|(rings, span)| layout.ring_starts_from(rings.clone(), span.start))
        .collect();
    let inputs: Vec<(&[[T; 2]], &[usize])> = pieces
        .iter()
        .zip(&starts)
        .map(|((_, span), starts)| (&vertices[span.clone()], &starts[..]))
        .collect();
    let mut tri = Triangulator::<T>::new();
    let mut out = Vec::new();
    let results = tri.triangulate_many(&inputs, options, &mut out);
    let pieces = pieces.iter().zip(results).zip(&out);
    pieces
        .map(|(((rings, span), result), triangles)| {
            let report = result.map_err(|error| Refusal::at(error, rings, span))?;
            Ok(Piece::of(&report, triangles, span, layout.vertices.len()))
        })
        .collect()
}

/// The z of every vertex of `layout`, in its order, when some polygon of the file has z
/// (rings JSON `[x, y, z]`, GeoJSON positions of three numbers): each polygon is then
/// triangulated in its own plane, and a polygon without z lies in the plane z = 0.
fn flat_z(input: &Input, layout: &Layout) -> Option<Vec<f64>> {
    if input.z.len() != input.polygons.len() || input.z.iter().all(Option::is_none) {
        return None;
    }
    let mut flat = Vec::with_capacity(layout.vertices.len());
    for (polygon, z) in input.polygons.iter().zip(&input.z) {
        // (as `Layout::new`: empty rings left out)
        match z {
            Some(rings) => rings.iter().for_each(|ring| flat.extend_from_slice(ring)),
            None => polygon
                .iter()
                .for_each(|ring| flat.resize(flat.len() + ring.len(), 0.0)),
        }
    }
    (flat.len() == layout.vertices.len()).then_some(flat)
}

/// [`triangulate_pieces`] for polygons in 3D: each piece through `triangulate_3d`, in its
/// own plane, its triangles indexing the layout's (3D) vertices.
fn triangulate_pieces_3d<T: Coord>(
    vertices: &[[T; 2]],
    z: &[T],
    layout: &Layout,
    pieces: &[(Range<usize>, Range<usize>)],
    options: &Options,
) -> Vec<Result<Piece, Refusal>> {
    let mut tri = Triangulator::<T>::new();
    let mut out = Vec::new();
    let mut xyz = Vec::new();
    pieces
        .iter()
        .map(|(rings, span)| {
            xyz.clear();
            xyz.extend(span.clone().map(|i| [vertices[i][0], vertices[i][1], z[i]]));
            let starts = layout.ring_starts_from(rings.clone(), span.start);
            let (report, _) = tri
                .triangulate_3d(&xyz, &starts, options, &mut out)
                .map_err(|error| Refusal::at(error, rings, span))?;
            Ok(Piece::of(&report, &out, span, layout.vertices.len()))
        })
        .collect()
}

/// Which ways out a refusal's message names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Hints {
    /// None: with a fill rule only bad numbers are refused, and --lenient does not apply.
    None,
    /// --lenient (rings with z, which fill rules do not take).
    Lenient,
    /// --fill-rule for rings that cross or overlap, and --lenient.
    FillRule,
}

/// Says what the triangulator refused and where in the file, and what would take it.
fn describe_error(
    refusal: &Refusal,
    layout: &Layout,
    precision: Precision,
    hints: Hints,
) -> String {
    let vertex = |v: usize| layout.describe_vertex(v + refusal.vertex_offset);
    let ring = |r: usize| layout.describe_ring(r + refusal.ring_offset);
    // (bad numbers: lenient mode drops them; rings that cross or overlap: a fill rule
    // reads them exactly, lenient mode makes the best of them)
    let (hint, geometry) = match hints {
        Hints::None => ("", ""),
        Hints::Lenient => (
            " (--lenient makes the best of it)",
            " (--lenient makes the best of it)",
        ),
        Hints::FillRule => (
            " (--lenient makes the best of it)",
            " (--fill-rule even-odd fills what the rings enclose, splitting edges where they cross; --lenient makes the best of it without adding vertices)",
        ),
    };
    match refusal.error {
        Error::NonFinite { vertex: v } => {
            let finite_f64 = layout
                .vertices
                .get(v + refusal.vertex_offset)
                .is_some_and(|p| p[0].is_finite() && p[1].is_finite());
            if finite_f64 && precision == Precision::F32 {
                format!("{}: coordinate out of f32 range{hint}", vertex(v))
            } else {
                format!("{}: coordinate is NaN or infinite{hint}", vertex(v))
            }
        }
        Error::CoordinateRange { vertex: v } => format!(
            "{}: coordinate outside what fill rules compute exactly (0, or a magnitude from 2^-248 to 2^100)",
            vertex(v)
        ),
        Error::EdgesCross { edge_a, edge_b, .. } => {
            format!(
                "edges cross: the edge from {} and the edge from {}{geometry}",
                vertex(edge_a),
                vertex(edge_b)
            )
        }
        Error::RingsOverlap { ring: r, vertex: v } => {
            let corner = layout
                .locate(v + refusal.vertex_offset)
                .map_or(v, |at| at.vertex);
            format!(
                "{} overlaps another ring: it lies on that ring's boundary (e.g. at vertex {corner}) and would cover its inside twice{geometry}",
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
                    "{} crosses itself at {}, where it passes twice{geometry}",
                    ring(ring_a),
                    vertex(v)
                )
            } else {
                format!(
                    "{} and {} cross each other at {}, where both pass{geometry}",
                    ring(ring_a),
                    ring(ring_b),
                    vertex(v)
                )
            }
        }
        Error::HoleOutside { ring: r } => {
            format!(
                "{} is a hole outside its outer ring, or inside another hole{geometry}",
                ring(r)
            )
        }
        // rings that wind both ways or twice: the triangulator's own words, and a way out
        ref other @ (Error::LobesWindOpposite { .. } | Error::RingWindsTwice { .. }) => {
            format!("{other}{geometry}")
        }
        // The rest are not about a place in the file (ring starts are built here), or are
        // bugs of the triangulator; its own words say it best.
        ref other => other.to_string(),
    }
}

#[allow(clippy::too_many_arguments)] // what was read, what was made, and where it goes
fn write_result(
    args: &Args,
    input: &Input,
    layout: &Layout,
    z: Option<&[f64]>,
    pieces: &[(Range<usize>, Range<usize>)],
    results: &[Result<Piece, Refusal>],
    outcome: &Outcome,
) -> Result<(), Failure> {
    // the file's vertices, then those added where edges cross (with --fill-rule)
    let added = outcome.added.as_deref();
    let added_points: Vec<[f64; 2]> = added
        .unwrap_or_default()
        .iter()
        .map(|a| a.position)
        .collect();
    let all_vertices: Cow<'_, [[f64; 2]]> = if added_points.is_empty() {
        Cow::Borrowed(&layout.vertices)
    } else {
        Cow::Owned([&layout.vertices[..], &added_points].concat())
    };
    let write = |w: &mut dyn Write| -> io::Result<()> {
        match args.output_format() {
            OutputFormat::Json => match z {
                Some(z) => output::write_json_3d(w, &layout.vertices, z, &outcome.triangles),
                None => output::write_json(w, &all_vertices, &outcome.triangles, added),
            },
            OutputFormat::Obj => output::write_obj(w, &all_vertices, z, &outcome.triangles),
            OutputFormat::Svg => {
                let groups = groups(input, layout, pieces, results);
                output::write_svg(
                    w,
                    layout,
                    &added_points,
                    &outcome.triangles,
                    groups.as_deref(),
                    &outcome.dropped,
                )
            }
            OutputFormat::Geojson => {
                let features = features(input, layout, pieces, results, args.polygons.merge);
                output::write_geojson(w, &all_vertices, z, &features, args.per_triangle)
            }
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

/// "feature F (id X)" for the GeoJSON feature holding flat ring `ring`.
fn feature_of(input: &Input, layout: &Layout, ring: usize) -> Option<String> {
    let polygon = layout.ring_origins.get(ring)?.polygon;
    let f = *input.polygon_feature.get(polygon)?;
    let id = input
        .features
        .get(f)
        .and_then(|feature| feature.id.as_ref());
    Some(match id {
        Some(geojson::feature::Id::String(id)) => format!("feature {f} (id {id:?})"),
        Some(geojson::feature::Id::Number(id)) => format!("feature {f} (id {id})"),
        None => format!("feature {f}"),
    })
}

/// With several polygons, each triangle's group for colouring a picture: its input
/// feature (GeoJSON), else its polygon; in the order `Outcome::gather` lists them.
fn groups(
    input: &Input,
    layout: &Layout,
    pieces: &[(Range<usize>, Range<usize>)],
    results: &[Result<Piece, Refusal>],
) -> Option<Vec<usize>> {
    if pieces.len() < 2 {
        return None;
    }
    let mut groups = Vec::new();
    for ((rings, _), result) in pieces.iter().zip(results) {
        if let Ok(piece) = result {
            let polygon = layout
                .ring_origins
                .get(rings.start)
                .map_or(0, |o| o.polygon);
            let group = input
                .polygon_feature
                .get(polygon)
                .copied()
                .unwrap_or(polygon);
            groups.extend(std::iter::repeat_n(group, piece.triangles.len()));
        }
    }
    Some(groups)
}

/// The output features: per input feature (GeoJSON) or polygon (other formats) whose every
/// polygon was triangulated, its triangles with its id and properties. With `merge`, one
/// feature of all triangles.
fn features<'a>(
    input: &'a Input,
    layout: &Layout,
    pieces: &[(Range<usize>, Range<usize>)],
    results: &'a [Result<Piece, Refusal>],
    merge: bool,
) -> Vec<output::TriangleFeature<'a>> {
    let blank = output::TriangleFeature::default;
    if merge {
        let mut all = blank();
        all.triangles = results
            .iter()
            .flatten()
            .flat_map(|p| &p.triangles)
            .copied()
            .collect();
        return vec![all];
    }
    // the input feature of each piece's polygon, by the piece's first ring
    let feature_of = |rings: &Range<usize>| {
        let polygon = layout
            .ring_origins
            .get(rings.start)
            .map_or(0, |o| o.polygon);
        input
            .polygon_feature
            .get(polygon)
            .copied()
            .unwrap_or(polygon)
    };
    let count = pieces
        .iter()
        .map(|(rings, _)| feature_of(rings) + 1)
        .max()
        .unwrap_or(0);
    let mut features: Vec<output::TriangleFeature<'a>> = (0..count).map(|_| blank()).collect();
    let mut refused = vec![false; count];
    for ((rings, _), result) in pieces.iter().zip(results) {
        let f = feature_of(rings);
        match result {
            Ok(piece) => features[f].triangles.extend_from_slice(&piece.triangles),
            Err(_) => refused[f] = true,
        }
    }
    for (f, feature) in features.iter_mut().enumerate() {
        if let Some(info) = input.features.get(f) {
            feature.id = info.id.as_ref();
            feature.properties = info.properties.as_ref();
        }
        feature.written = !refused[f] && !feature.triangles.is_empty();
    }
    features
}

fn plural(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

fn summary(outcome: &Outcome) -> String {
    let mut parts = vec![
        plural(outcome.polygons, "polygon", "polygons"),
        plural(outcome.holes, "hole", "holes"),
        plural(outcome.triangles.len(), "triangle", "triangles"),
        plural(outcome.dropped.len(), "dropped vertex", "dropped vertices"),
        plural(outcome.repairs, "repair", "repairs"),
    ];
    if let Some(added) = &outcome.added {
        parts.push(plural(added.len(), "added vertex", "added vertices"));
    }
    if outcome.refused > 0 {
        parts.push(format!("{} refused", outcome.refused));
    }
    parts.join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;
    use output::Added;

    #[test]
    fn summary_counts_everything() {
        let outcome = Outcome {
            triangles: vec![[0, 1, 2]],
            polygons: 2,
            holes: 1,
            dropped: vec![4, 5],
            repairs: 0,
            refused: 0,
            added: None,
        };
        assert_eq!(
            summary(&outcome),
            "2 polygons, 1 hole, 1 triangle, 2 dropped vertices, 0 repairs"
        );
        let with_fill = Outcome {
            added: Some(Vec::new()),
            ..outcome
        };
        assert!(summary(&with_fill).ends_with(", 0 added vertices"));
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
        let message = describe_error(&refusal, &layout, Precision::F64, Hints::FillRule);
        assert!(message.contains("polygon 1, ring 1, vertex 1"), "{message}");
        assert!(message.contains("polygon 1, ring 0, vertex 0"), "{message}");
        // the ways out: a fill rule and lenient mode for rings in the plane, lenient
        // mode alone for rings with z, none with a fill rule already
        assert!(message.contains("--fill-rule even-odd") && message.contains("--lenient"));
        let message = describe_error(&refusal, &layout, Precision::F64, Hints::Lenient);
        assert!(!message.contains("--fill-rule") && message.contains("--lenient"));
        let message = describe_error(&refusal, &layout, Precision::F64, Hints::None);
        assert!(!message.contains("--fill-rule") && !message.contains("--lenient"));
        let refusal = Refusal {
            error: Error::HoleOutside { ring: 1 },
            vertex_offset: 4,
            ring_offset: 1,
        };
        let message = describe_error(&refusal, &layout, Precision::F64, Hints::FillRule);
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
        let message = describe_error(&refusal, &layout, Precision::F64, Hints::FillRule);
        assert!(
            message.starts_with("polygon 1, ring 0 and polygon 1, ring 1 cross each other at polygon 1, ring 1, vertex 2"),
            "{message}"
        );
    }

    #[test]
    fn fill_rule_names_are_the_core_s() {
        let variants = FillRuleArg::value_variants();
        assert_eq!(variants.len(), FillRule::ALL.len());
        for arg in variants {
            let value = arg.to_possible_value().expect("not skipped");
            assert_eq!(value.get_name(), arg.rule().name());
        }
    }

    #[test]
    fn added_vertices_are_numbered_after_the_file_s_piece_by_piece() {
        // two bow ties of 4 vertices each, one crossing each: 8 file vertices, so their
        // crossings are 8 and 9
        let piece = |start: usize| Piece {
            triangles: vec![[start as u32, 8, start as u32 + 3]],
            added: vec![Added {
                vertex: 0,
                position: [1.0, 1.0],
                edges: [start, start + 2],
            }],
            ..Piece::default()
        };
        let mut results = vec![Ok(piece(0)), Ok(piece(4))];
        number_added(&mut results, 8).expect("fits");
        let [Ok(a), Ok(b)] = &results[..] else {
            panic!("pieces")
        };
        assert_eq!(a.triangles, vec![[0, 8, 3]]);
        assert_eq!(b.triangles, vec![[4, 9, 7]]);
        assert_eq!((a.added[0].vertex, b.added[0].vertex), (8, 9));
        assert_eq!(b.added[0].edges, [4, 6]);
        let outcome = Outcome::gather(&results);
        assert_eq!(outcome.added.map(|a| a.len()), Some(2));
    }

    #[test]
    fn f32_overflow_is_told_apart_from_nan() {
        let layout = Layout::new(&[vec![vec![[0.0, 0.0], [1e300, 0.0], [1.0, 1.0]]]]);
        let refusal = Refusal {
            error: Error::NonFinite { vertex: 1 },
            vertex_offset: 0,
            ring_offset: 0,
        };
        let message = describe_error(&refusal, &layout, Precision::F32, Hints::FillRule);
        assert_eq!(
            message,
            "ring 0, vertex 1: coordinate out of f32 range (--lenient makes the best of it)"
        );
    }
}
