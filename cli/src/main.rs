//! `polytri`: the command-line face of the polytri triangulator and its harness.
//!
//! Each subcommand lives in its own module; this file only parses the command line and
//! turns a [`Failure`] into one line on stderr and exit status 1.

use std::fmt;
use std::io::Write;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod bench;
mod campaign;
mod check;
mod generate;
mod input;
mod layout;
mod output;
mod polygon_args;
mod precision;
mod promote;
mod replay;
mod triangulate;

/// Triangulate polygons with holes, and check the results.
#[derive(Debug, Parser)]
#[command(name = "polytri", version, about, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// The subcommands; campaign, replay, precision and bench will join `triangulate`.
#[derive(Debug, Subcommand)]
enum Command {
    /// Triangulate the polygons of a JSON, GeoJSON or WKT file.
    Triangulate(triangulate::Args),
    /// Where f32 and f64 triangulations stay valid: a report over scales, offsets and
    /// feature sizes, polytri against earcut and i_triangle.
    Precision(precision::Args),
    /// Time polytri against earcut, earcutr, i_triangle, lyon and spade on the same inputs,
    /// or on generated series of growing size (--scaling).
    Bench(bench::Args),
    /// Judge a triangulation of a file's polygons with the oracle's independent checks.
    Check(check::Args),
    /// Random cases of every generator family through polytri and the oracle; failing
    /// cases are shrunk and written to the corpus.
    Campaign(campaign::Args),
    /// Replay corpus folders through polytri in every strategy, precision and rotation,
    /// judged by the oracle, as a table.
    Replay(replay::Args),
    /// Turn a campaign case or a fuzz input into a corpus regression case.
    Promote(promote::Args),
    /// Write one input of the harness's generators (valid families, crossing families,
    /// scaling series) as a rings JSON file.
    Generate(generate::Args),
}

/// A failure the user should hear about: printed as one line on stderr, exit status 1.
///
/// A plain message, not an error enum: nothing inspects it, it is only shown, and each
/// producer knows best how to say where the problem is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Failure(pub String);

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Messages from dependencies may span lines; the contract is one line per failure,
        // so scripts and CI logs can grep for it.
        let mut lines = self
            .0
            .lines()
            .map(str::trim)
            .filter(|line| !line.is_empty());
        if let Some(first) = lines.next() {
            f.write_str(first)?;
            for line in lines {
                write!(f, " {line}")?;
            }
        }
        Ok(())
    }
}

/// Writes one line to stderr. Unlike `eprintln!` it does not panic when stderr is closed:
/// there is nobody to tell then, and the exit status still says how it went.
pub fn say(line: fmt::Arguments<'_>) {
    let _ = writeln!(std::io::stderr().lock(), "{line}");
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Triangulate(args) => triangulate::run(&args),
        Command::Precision(args) => precision::run(&args),
        Command::Bench(args) => bench::run(&args),
        Command::Check(args) => check::run(&args),
        Command::Campaign(args) => campaign::run(&args),
        Command::Replay(args) => replay::run(&args),
        Command::Promote(args) => promote::run(&args),
        Command::Generate(args) => generate::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => {
            say(format_args!("polytri: error: {failure}"));
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn command_line_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn failure_prints_on_one_line() {
        let failure = Failure("bad\ninput:\n  line 2".to_owned());
        assert_eq!(failure.to_string(), "bad input: line 2");
    }
}
