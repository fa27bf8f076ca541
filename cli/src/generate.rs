//! `polytri generate`: one input of the harness's generators as a rings JSON file — a valid
//! family, a crossing family or a scaling series — to triangulate, check or bench.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::PathBuf;

use polytri_oracle::gen::crossing::{generate_crossing, CrossingFamily};
use polytri_oracle::series::Series;
use polytri_oracle::{generate, Family, Params};

use crate::{say, Failure};

/// Arguments of `polytri generate`.
#[derive(Debug, clap::Args)]
#[command(after_help = "\
GENERATOR is one of the harness's seeded generators, by kind and name:

  family:NAME    valid nested polygons (the campaign's families): star, space-partition, \
two-opt, orthogonal, circles, comb, spiral, many-holes, touching-holes, nested-islands, \
slivers, font-like
  crossing:NAME  self-crossing and overlapping rings, for --fill-rule: star-polygon, \
figure-eight, wound-twice, overlapping-copies, segment-soup, strokes, collinear-overlaps
  series:NAME    the scaling series of `polytri bench --scaling`: random, star, circles, \
comb, pinwheel

The kind may be left out where the name is one kind's only (`strokes`, `pinwheel`). The \
same generator, seed and size always give the same file. The output is a rings JSON file \
(an array of rings, each an array of [x, y]), which `polytri triangulate` reads with \
--nesting auto (any order and winding).

Example, the fill-rule bench on overlapping strokes:
  polytri generate crossing:strokes --size 20000 -o strokes.json
  polytri bench strokes.json --polytri even-odd --peers lyon,i-triangle")]
pub struct Args {
    /// The generator: KIND:NAME (see below)
    #[arg(value_name = "GENERATOR")]
    pub generator: String,

    /// About how many vertices (crossing families: at most 100000)
    #[arg(long, value_name = "N", default_value_t = 1000)]
    pub size: usize,

    /// The seed (series have none: they are the same at every seed)
    #[arg(long, default_value_t = 1)]
    pub seed: u64,

    /// Write to FILE instead of standard output
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// A generator by kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Generator {
    Family(Family),
    Crossing(CrossingFamily),
    Series(Series),
}

impl Generator {
    fn name(self) -> String {
        match self {
            Generator::Family(f) => format!("family:{f}"),
            Generator::Crossing(c) => format!("crossing:{c}"),
            Generator::Series(s) => format!("series:{s}"),
        }
    }
}

/// Reads `kind:name`, or a bare name of one kind only.
fn parse(text: &str) -> Result<Generator, String> {
    let text = text.trim();
    let (kind, name) = match text.split_once(':') {
        Some((kind, name)) => (Some(kind.trim()), name.trim()),
        None => (None, text),
    };
    let family = || name.parse().map(Generator::Family);
    let crossing = || name.parse().map(Generator::Crossing);
    let series = || name.parse().map(Generator::Series);
    match kind {
        Some("family") => family(),
        Some("crossing") => crossing(),
        Some("series") => series(),
        Some(other) => Err(format!(
            "unknown kind '{other}' (known: family, crossing, series)"
        )),
        None => {
            let found: Vec<Generator> = [family(), crossing(), series()]
                .into_iter()
                .filter_map(Result::ok)
                .collect();
            match found[..] {
                [one] => Ok(one),
                [] => Err(format!(
                    "unknown generator '{name}' (see `polytri generate --help` for the names)"
                )),
                _ => Err(format!(
                    "'{name}' names several generators: {}; say which",
                    found
                        .iter()
                        .map(|g| g.name())
                        .collect::<Vec<_>>()
                        .join(", ")
                )),
            }
        }
    }
}

/// The rings of one generated input.
fn rings(generator: Generator, seed: u64, size: usize) -> Vec<Vec<[f64; 2]>> {
    let (vertices, starts) = match generator {
        Generator::Family(family) => {
            let case = generate(family, seed, &Params::new(size));
            return case.input.rings();
        }
        Generator::Series(series) => return series.input(size).rings(),
        Generator::Crossing(family) => generate_crossing(family, seed, size),
    };
    let ends = starts.iter().skip(1).copied().chain([vertices.len()]);
    starts
        .iter()
        .zip(ends)
        .map(|(&a, b)| vertices[a..b].to_vec())
        .collect()
}

/// Runs `polytri generate`.
///
/// # Errors
///
/// A [`Failure`] for an unknown generator or when the output cannot be written.
pub fn run(args: &Args) -> Result<(), Failure> {
    let generator = parse(&args.generator).map_err(Failure)?;
    if args.size == 0 {
        return Err(Failure("--size must be at least 1".to_owned()));
    }
    let rings = rings(generator, args.seed, args.size);
    let vertices: usize = rings.iter().map(Vec::len).sum();
    let write = |w: &mut dyn Write| -> io::Result<()> {
        serde_json::to_writer(&mut *w, &rings)?;
        writeln!(w)?;
        w.flush()
    };
    match &args.output {
        None => write(&mut io::stdout().lock()),
        Some(path) => {
            let file =
                File::create(path).map_err(|e| Failure(format!("{}: {e}", path.display())))?;
            write(&mut BufWriter::new(file))
        }
    }
    .map_err(|e| Failure(format!("writing the rings: {e}")))?;
    say(format_args!(
        "{}: seed {}, {} rings, {vertices} vertices",
        generator.name(),
        args.seed,
        rings.len()
    ));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_resolve_by_kind_and_alone_when_unique() {
        assert_eq!(
            parse("crossing:strokes"),
            Ok(Generator::Crossing(CrossingFamily::Strokes))
        );
        assert_eq!(parse("pinwheel"), Ok(Generator::Series(Series::Pinwheel)));
        assert_eq!(parse("family:star"), Ok(Generator::Family(Family::Star)));
        // "star" is a family and a series
        let err = parse("star").unwrap_err();
        assert!(
            err.contains("family:star") && err.contains("series:star"),
            "{err}"
        );
        assert!(parse("shape:star").is_err());
        assert!(parse("hexagon").is_err());
    }

    #[test]
    fn rings_have_about_the_size_asked_for() {
        for generator in [
            Generator::Crossing(CrossingFamily::StarPolygon),
            Generator::Family(Family::Comb),
            Generator::Series(Series::Circles),
        ] {
            let rings = rings(generator, 3, 2000);
            let n: usize = rings.iter().map(Vec::len).sum();
            assert!((1500..=2500).contains(&n), "{}: {n}", generator.name());
            assert!(rings.iter().all(|r| r.len() >= 3), "{}", generator.name());
        }
    }
}
