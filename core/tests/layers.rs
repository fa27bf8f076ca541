//! The crate's architecture, checked: the modules of `core/src` form layers that import
//! only downward, no stage imports another stage, and the import graph has no cycle.
//! (`ARCHITECTURE.md` draws the layers; this test keeps the drawing true.)
//!
//! Library code only: unit-test modules (`#[cfg(test)] mod tests`) and `testing.rs` may
//! set up a stage's input by running the stages before it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A module of the crate as the rules see it: the top-level module, or for `stages` the
/// stage itself (`stages::clip`).
type Unit = String;

/// The layer of each top-level module, from the bottom.
fn layer(top: &str) -> Option<u32> {
    Some(match top {
        "error" | "options" | "report" => 0,
        "geom" => 1,
        "structures" => 2,
        "crossings" => 3,
        "context" => 4,
        "stages" => 5,
        "triangulator" => 6,
        "geo" | "planar" => 7,
        _ => return None,
    })
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Every `.rs` file under `dir`, with its path relative to `src/`.
fn files(dir: &Path, out: &mut Vec<(String, String)>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|e| e.expect("a directory entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            files(&path, out);
        } else if path.extension().is_some_and(|x| x == "rs") {
            let rel = path.strip_prefix(src()).expect("under src");
            let text = std::fs::read_to_string(&path).expect("readable source");
            out.push((rel.to_string_lossy().replace('\\', "/"), text));
        }
    }
}

/// The unit a file belongs to: `stages/clip/fast.rs` → `stages::clip`, `geom/mod.rs` →
/// `geom`, `lib.rs` → none.
fn unit_of(rel: &str) -> Option<Unit> {
    let parts: Vec<&str> = rel.trim_end_matches(".rs").split('/').collect();
    let top = parts[0];
    if top == "lib" || top == "testing" {
        return None;
    }
    if top == "stages" && parts.len() > 1 && parts[1] != "mod" {
        return Some(format!("stages::{}", parts[1]));
    }
    Some(top.to_string())
}

/// The source without comments and without its unit-test module (from
/// `#[cfg(test)]` followed by `mod` to the end of the file).
fn library_code(text: &str) -> String {
    let mut code = String::new();
    let lines: Vec<&str> = text.lines().collect();
    for (i, line) in lines.iter().enumerate() {
        let t = line.trim_start();
        if t.starts_with("#[cfg(test)]")
            && lines
                .get(i + 1)
                .is_some_and(|l| l.trim_start().starts_with("mod "))
        {
            break;
        }
        let line = match line.find("//") {
            Some(k) => &line[..k],
            None => line,
        };
        code.push_str(line);
        code.push('\n');
    }
    code
}

/// The units a piece of library code refers to through `crate::…` paths (grouped imports
/// `crate::{a, b::c}` included), and stage siblings through `super::…` in a stage file.
fn references(code: &str, rel: &str) -> BTreeSet<Unit> {
    let mut found = BTreeSet::new();
    let mut add = |path: &str| {
        let mut parts = path.split("::").map(str::trim).filter(|p| !p.is_empty());
        let Some(top) = parts.next() else { return };
        if top == "stages" {
            if let Some(stage) = parts.next() {
                let stage: String = stage
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                found.insert(format!("stages::{stage}"));
                return;
            }
        }
        let top: String = top
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if layer(&top).is_some() {
            found.insert(top);
        }
    };
    for (k, _) in code.match_indices("crate::") {
        let rest = &code[k + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            // (nested groups `a::{b, c}` name their module first: enough here)
            for item in group[..end].split(',') {
                add(item);
            }
        } else {
            let end = rest
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .unwrap_or(rest.len());
            add(&rest[..end]);
        }
    }
    // in `stages/x.rs`, `super::y` is the sibling stage y
    if rel.starts_with("stages/") && rel.matches('/').count() == 1 {
        for (k, _) in code.match_indices("super::") {
            let rest = &code[k + "super::".len()..];
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() {
                found.insert(format!("stages::{name}"));
            }
        }
    }
    found
}

/// The import graph between units.
fn graph() -> BTreeMap<Unit, BTreeSet<Unit>> {
    let mut all = Vec::new();
    files(&src(), &mut all);
    assert!(all.len() > 20, "found only {} source files", all.len());
    let mut graph: BTreeMap<Unit, BTreeSet<Unit>> = BTreeMap::new();
    for (rel, text) in &all {
        let Some(unit) = unit_of(rel) else { continue };
        let top = unit.split("::").next().unwrap_or_default().to_string();
        assert!(layer(&top).is_some(), "{rel}: module `{top}` has no layer");
        let refs = references(&library_code(text), rel);
        let entry = graph.entry(unit.clone()).or_default();
        entry.extend(refs.into_iter().filter(|r| *r != unit));
    }
    graph
}

fn layer_of(unit: &str) -> u32 {
    layer(unit.split("::").next().unwrap_or_default()).expect("a layer")
}

#[test]
fn layers_import_only_downward() {
    let mut wrong = Vec::new();
    for (unit, refs) in graph() {
        for r in refs {
            if layer_of(&r) > layer_of(&unit) {
                wrong.push(format!(
                    "{unit} (layer {}) imports {r} (layer {})",
                    layer_of(&unit),
                    layer_of(&r)
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "upward imports:\n{}", wrong.join("\n"));
}

#[test]
fn no_stage_imports_another() {
    let mut wrong = Vec::new();
    for (unit, refs) in graph() {
        if unit.starts_with("stages::") {
            for r in refs.iter().filter(|r| r.starts_with("stages")) {
                wrong.push(format!("{unit} imports {r}"));
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "stages importing stages:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn the_import_graph_has_no_cycle() {
    let graph = graph();
    // depth-first search, colouring units grey while on the stack
    fn visit<'a>(
        u: &'a str,
        graph: &'a BTreeMap<Unit, BTreeSet<Unit>>,
        state: &mut BTreeMap<&'a str, bool>,
        stack: &mut Vec<&'a str>,
    ) -> Option<Vec<String>> {
        match state.get(u) {
            Some(true) => {
                let from = stack.iter().position(|s| *s == u).unwrap_or(0);
                let mut cycle: Vec<String> = stack[from..].iter().map(|s| s.to_string()).collect();
                cycle.push(u.to_string());
                return Some(cycle);
            }
            Some(false) => return None,
            None => {}
        }
        state.insert(u, true);
        stack.push(u);
        for v in graph.get(u).into_iter().flatten() {
            if let Some(cycle) = visit(v, graph, state, stack) {
                return Some(cycle);
            }
        }
        stack.pop();
        state.insert(u, false);
        None
    }
    let mut state = BTreeMap::new();
    for u in graph.keys() {
        let mut stack = Vec::new();
        if let Some(cycle) = visit(u, &graph, &mut state, &mut stack) {
            panic!("import cycle: {}", cycle.join(" → "));
        }
    }
}

/// The checker itself: it must see an upward import and a stage importing a stage.
#[test]
fn the_checker_sees_imports() {
    let code = library_code(
        "use crate::stages::nest::x;\nuse crate::{geom::Point, context};\n// crate::triangulator\n\
         #[cfg(test)]\nmod tests {\n use crate::triangulator::y;\n}\n",
    );
    let refs = references(&code, "stages/clean.rs");
    let expected: BTreeSet<Unit> = ["stages::nest", "geom", "context"]
        .into_iter()
        .map(String::from)
        .collect();
    assert_eq!(refs, expected);
    let sibling = references("use super::touch::f;\n", "stages/nest.rs");
    assert!(sibling.contains("stages::touch"));
    // and the real graph has the edges the pipeline needs
    let graph = graph();
    assert!(graph["triangulator"].contains("stages::clip"));
    assert!(graph["stages::clip"].contains("geom"));
}
