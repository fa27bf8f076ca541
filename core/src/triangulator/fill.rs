//! Fill rules: the rule's region of crossing and overlapping rings, resolved into valid
//! rings (`stages::resolve`) and triangulated by the usual pipeline, strict.

use super::lenient::{self, Outcome, Reruns};
use super::pipeline::Stages;
use crate::context::Context;
use crate::geom::{Coord, SnapGrid};
use crate::stages::{load, resolve};
use crate::{Error, FillRule, Nesting, Options};

/// The fill path's buffers.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    vertices: Vec<[f64; 2]>,
    resolve: resolve::Scratch,
}

/// Triangulates the region of `rule`: the triangles index `vertices`, then the vertices
/// added where edges cross (`cx.added`).
#[allow(clippy::too_many_arguments)] // the call's input, its state and its output
pub(crate) fn triangulate<T: Coord>(
    cx: &mut Context,
    st: &mut Stages,
    re: &mut Reruns,
    fs: &mut Scratch,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    rule: FillRule,
    options: &Options,
    out: &mut Vec<[u32; 3]>,
) -> Result<Outcome, Error> {
    out.clear();
    // the input's own errors (non-finite coordinates, ring starts), as strict mode gives them
    cx.reset(false);
    load::load(cx, vertices, ring_starts)?;
    fs.vertices.clear();
    fs.vertices
        .extend(vertices.iter().map(|v| [v[0].to_f64(), v[1].to_f64()]));
    let grid = SnapGrid { f32: T::IS_F32 };
    let mut added = core::mem::take(&mut cx.added);
    added.clear();
    let resolved = resolve::resolve(
        &mut fs.resolve,
        &fs.vertices,
        ring_starts,
        rule,
        grid,
        &mut added,
    );
    if let Err(e) = resolved {
        cx.added = added;
        return Err(e);
    }
    // valid rings: strict, containment decides
    let inner = Options::new()
        .with_strategy(options.strategy)
        .with_nesting(Nesting::Auto);
    let r = &fs.resolve;
    let made = lenient::triangulate(cx, st, re, &r.rings, &r.ring_starts, &inner, out);
    cx.added = added;
    let made = made.map_err(|e| match e {
        Error::TooManyVertices { .. } => e,
        _ => Error::Internal { stage: "resolve" },
    })?;
    for t in out.iter_mut() {
        for v in t.iter_mut() {
            *v = r.map[*v as usize];
        }
    }
    // the vertices left out are the resolved rings', not the input's
    cx.dropped.clear();
    Ok(made)
}
