//! What the CLI's end-to-end tests share: a scratch directory per test, fixture files,
//! and running the built binary.
// (each test file uses some of these)
#![allow(dead_code)]

use std::ffi::OsStr;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// A fresh directory for one test of `suite`, so tests running in parallel never share
/// files.
pub fn scratch(suite: &str, test: &str) -> PathBuf {
    let dir =
        std::env::temp_dir().join(format!("polytri-cli-{suite}-{}-{test}", std::process::id()));
    // Left over from an earlier run with the same pid: start clean.
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).expect("create scratch directory");
    dir
}

/// Writes `text` to `dir/name`; its path.
pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    fs::write(&path, text).expect("write fixture");
    path
}

/// Runs the built `polytri` with `args`.
pub fn polytri<S: AsRef<OsStr>>(args: &[S]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_polytri"))
        .args(args)
        .output()
        .expect("run polytri")
}
