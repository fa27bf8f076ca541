//! `--nesting` and `--merge`: how the rings of a file make polygons, defined once for every
//! command that reads polygons (triangulate, check, bench, replay).

use clap::ValueEnum;
use polytri_oracle::Grouping;

/// How the rings of a file make polygons: `--nesting` and `--merge`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::Args)]
pub struct PolygonArgs {
    /// Which rings of a polygon are holes: by containment (auto: any order and winding),
    /// or its first ring is the outer boundary and the others its holes (first-outer,
    /// earcut's convention)
    #[arg(long, value_enum, default_value_t = NestingArg::Auto)]
    pub nesting: NestingArg,

    /// All rings of the file as one set of rings (glyph outlines that come as one soup
    /// across the file), instead of each polygon on its own
    #[arg(long)]
    pub merge: bool,
}

impl PolygonArgs {
    /// The same, as the oracle reads a file of polygons ([`polytri_oracle::Input::from_polygons`]).
    pub fn grouping(self) -> Grouping {
        Grouping {
            nesting: self.nesting.nesting(),
            merge: self.merge,
        }
    }
}

/// `--nesting`, mirroring [`polytri::Nesting`] (which is not a clap type).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum NestingArg {
    /// Containment depth decides: even outer, odd hole.
    #[default]
    Auto,
    /// Each polygon's first ring is outer, the rest are its holes.
    #[value(alias = "polygons")]
    FirstOuter,
}

impl NestingArg {
    /// The triangulator's option.
    pub fn nesting(self) -> polytri::Nesting {
        match self {
            NestingArg::Auto => polytri::Nesting::Auto,
            NestingArg::FirstOuter => polytri::Nesting::FirstIsOuter,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Debug, Parser)]
    struct Cli {
        #[command(flatten)]
        polygons: PolygonArgs,
    }

    #[test]
    fn defaults_are_auto_without_merge() {
        let cli = Cli::try_parse_from(["polytri"]).expect("no arguments needed");
        assert_eq!(cli.polygons, PolygonArgs::default());
        assert_eq!(
            cli.polygons.grouping(),
            Grouping {
                nesting: polytri::Nesting::Auto,
                merge: false
            }
        );
    }

    #[test]
    fn first_outer_has_its_alias() {
        for name in ["first-outer", "polygons"] {
            let cli = Cli::try_parse_from(["polytri", "--nesting", name, "--merge"])
                .expect("a known value");
            assert_eq!(cli.polygons.nesting, NestingArg::FirstOuter);
            assert_eq!(
                cli.polygons.grouping(),
                Grouping {
                    nesting: polytri::Nesting::FirstIsOuter,
                    merge: true
                }
            );
        }
    }
}
