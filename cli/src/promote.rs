//! `polytri promote`: turn a case written by `polytri campaign`, or an input found by
//! fuzzing, into a regression case of the corpus with one command.

use std::path::{Path, PathBuf};

use polytri_oracle::replay::load_file;
use polytri_oracle::Case;

use crate::{say, Failure};

/// Arguments of `polytri promote`.
#[derive(Debug, clap::Args)]
#[command(after_help = "\
FILE is a corpus case JSON file (as `polytri campaign` writes failing cases), or with \
--fuzz-target a raw input of that cargo-fuzz target (a crash file from fuzz/artifacts/, \
an entry of its corpus), decoded into the polygons the target triangulated.

The case is written to DIR/NAME.json, where `cargo test -p polytri-oracle --test corpus` \
and `polytri replay` pick it up with no code change; accept its new snapshot with \
`cargo insta review`. Name a case after what it exercises \
(two_holes_share_bridge_vertex), never after a counter.")]
pub struct Args {
    /// The case JSON file, or a raw fuzz input with --fuzz-target
    #[arg(value_name = "FILE")]
    pub file: PathBuf,

    /// The case's name and file name (default: the name inside the case)
    #[arg(long)]
    pub name: Option<String>,

    /// FILE is a raw input of this fuzz target (raw_rings, nested_valid, precision, …)
    #[arg(long, value_name = "TARGET")]
    pub fuzz_target: Option<String>,

    /// The corpus folder to write to
    #[arg(long, value_name = "DIR", default_value = "corpus/cases")]
    pub to: PathBuf,

    /// Replace a case of the same name
    #[arg(long)]
    pub force: bool,
}

/// Runs `polytri promote`.
///
/// # Errors
///
/// A [`Failure`] when FILE cannot be read or is not a case (or a fuzz input of the named
/// target), when the name is not a plain file name, or when the case exists already
/// (without `--force`).
pub fn run(args: &Args) -> Result<(), Failure> {
    let mut case = match &args.fuzz_target {
        None => read_case(&args.file)?,
        Some(target) => decode_fuzz_input(&args.file, target)?,
    };
    if let Some(name) = &args.name {
        case.name = name.clone();
    }
    check_name(&case.name)?;
    if let Some(v) = case
        .input
        .vertices
        .iter()
        .position(|p| !p.iter().all(|c| c.is_finite()))
    {
        return Err(Failure(format!(
            "vertex {v} has a non-finite coordinate, which corpus JSON cannot hold; \
             write the regression as a unit test instead"
        )));
    }
    let path = args.to.join(format!("{}.json", case.name));
    if path.exists() && !args.force {
        return Err(Failure(format!(
            "{} exists already: choose another --name, or --force to replace it",
            path.display()
        )));
    }
    std::fs::create_dir_all(&args.to)
        .map_err(|e| Failure(format!("{}: {e}", args.to.display())))?;
    std::fs::write(&path, case.to_json() + "\n")
        .map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    // Read it back as the replay will, so a promoted case always loads.
    let folder = args
        .to
        .file_name()
        .map_or_else(|| "cases".to_owned(), |n| n.to_string_lossy().into_owned());
    let loaded = load_file(&path, &folder).map_err(Failure)?;
    say(format_args!(
        "promoted {} to {} ({} vertices, {} rings); replay it with `cargo test -p polytri-oracle --test corpus` and accept its snapshot with `cargo insta review`",
        case.name,
        path.display(),
        loaded.input.vertices.len(),
        loaded.input.ring_count()
    ));
    Ok(())
}

/// A corpus case JSON file.
fn read_case(file: &Path) -> Result<Case, Failure> {
    let text =
        std::fs::read_to_string(file).map_err(|e| Failure(format!("{}: {e}", file.display())))?;
    Case::from_json(&text).map_err(|e| {
        Failure(format!(
            "{}: not a corpus case ({e}); a raw fuzz input needs --fuzz-target",
            file.display()
        ))
    })
}

/// A raw input of fuzz target `target`, decoded as the target decodes it.
fn decode_fuzz_input(file: &Path, target: &str) -> Result<Case, Failure> {
    let bytes = std::fs::read(file).map_err(|e| Failure(format!("{}: {e}", file.display())))?;
    polytri_oracle::fuzz::decode_case(target, &bytes).ok_or_else(|| {
        let known: Vec<&str> = polytri_oracle::fuzz::TARGETS.iter().map(|t| t.0).collect();
        Failure(format!(
            "unknown fuzz target '{target}' (known: {})",
            known.join(", ")
        ))
    })
}

/// A case name must be a plain file name: letters, digits, `_` and `-`.
fn check_name(name: &str) -> Result<(), Failure> {
    let plain = !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
    if plain {
        Ok(())
    } else {
        Err(Failure(format!(
            "case name {name:?} must be a plain file name (letters, digits, '_', '-'): pass --name"
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_plain_file_names() {
        assert!(check_name("two_holes_share_bridge_vertex").is_ok());
        assert!(check_name("star-7-100").is_ok());
        for bad in ["", "../x", "a b", "a/b", "x.json"] {
            assert!(check_name(bad).is_err(), "{bad:?}");
        }
    }
}
