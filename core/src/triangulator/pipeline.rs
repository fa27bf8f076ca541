//! The stages in order, and the scratch each one owns.
//!
//! ```text
//! load ─► clean ─► [lobes] ─► clean::orient_rings ─► nest ─► touch ─► bridge ─► clip
//! ```
//!
//! One polygon of a few dozen vertices (an outer ring and a few holes) takes the `small`
//! stage instead, which does all of that in one pass and hands back to the pipeline
//! whatever it does not handle.
//!
//! Only this module and [`super::lenient`] call stages. Each stage leaves its guarantee
//! in the shared [`Context`] for the next (see `ARCHITECTURE.md`).

use crate::context::Context;
use crate::geom::Coord;
use crate::stages::{bridge, clean, clip, load, lobes, nest, small, touch};
use crate::{Error, Nesting};

/// Every stage's scratch buffers, kept between calls so that a warm triangulator
/// allocates nothing.
#[derive(Debug, Default)]
pub(crate) struct Stages {
    pub clean: clean::Scratch,
    pub lobes: lobes::Scratch,
    pub nest: nest::Scratch,
    pub touch: touch::Scratch,
    pub bridge: bridge::Scratch,
    pub clip: clip::Scratch,
    pub small: Small,
}

/// The small stage's two scratches, and what it did last.
#[derive(Debug, Default)]
pub(crate) struct Small {
    narrow: small::Narrow,
    wide: small::Wide,
    /// The last call used the wide scratch.
    used_wide: bool,
    /// Declines every input, for tests holding the stage to the pipeline.
    pub off: bool,
    /// The last call was the stage's (for tests: that it takes what it should).
    pub took: bool,
}

impl Small {
    /// [`small::rings_run`] for the input the stage checked last.
    pub(crate) fn rings_run(&self) -> Option<bool> {
        if self.used_wide {
            small::rings_run(&self.wide)
        } else {
            small::rings_run(&self.narrow)
        }
    }

    /// The numbers of polygons and holes, and twice the area (as lenient mode measures
    /// it), of the input the stage took last.
    pub(crate) fn counts_and_area(&self) -> (usize, usize, f64) {
        if self.used_wide {
            let s = &self.wide;
            (
                small::polygon_count(s),
                small::hole_count(s),
                small::double_area(s),
            )
        } else {
            let s = &self.narrow;
            (
                small::polygon_count(s),
                small::hole_count(s),
                small::double_area(s),
            )
        }
    }
}

/// The small stage in place of the pipeline, for one small polygon (see [`small::nodes`]):
/// whether it proved the input valid and triangulated it into `out` (with the triangles
/// of the fast strategy, or with `quality` the quality one's). When not, the pipeline
/// must run from the start.
#[allow(clippy::too_many_arguments)] // the call's input, its options and its output
pub(crate) fn small_ring<T: Coord>(
    cx: &mut Context,
    st: &mut Stages,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    nesting: Nesting,
    quality: bool,
    lenient: bool,
    out: &mut Vec<[u32; 3]>,
) -> bool {
    st.small.took = !mark_and_cut_takes(st, vertices.len())
        && small_ring_valid(cx, st, vertices, ring_starts, nesting, lenient)
        && small_clip(st, quality, lenient, out);
    st.small.took
}

/// Whether mark-and-cut would take a ring of `vertices`: then it keeps the pipeline (the
/// harness lowers mark-and-cut's size so that small inputs take its rounds).
fn mark_and_cut_takes(st: &Stages, vertices: usize) -> bool {
    #[cfg(feature = "threads")]
    let rounds = (st.clip.threads.as_ref()).is_some_and(|t| vertices >= t.min);
    #[cfg(not(feature = "threads"))]
    let rounds = {
        let _ = (st, vertices);
        false
    };
    rounds
}

/// The small stage's clip of the input [`small_ring_valid`] took last.
fn small_clip(st: &mut Stages, quality: bool, lenient: bool, out: &mut Vec<[u32; 3]>) -> bool {
    if st.small.used_wide {
        small::clip(&mut st.small.wide, quality, lenient, out)
    } else {
        small::clip(&mut st.small.narrow, quality, lenient, out)
    }
}

/// [`small_ring`] after [`small_ring_valid`] took the input (strict): the clip, where
/// `small_ring` would clip it.
pub(crate) fn small_ring_checked<T: Coord>(
    st: &mut Stages,
    vertices: &[[T; 2]],
    quality: bool,
    out: &mut Vec<[u32; 3]>,
) -> bool {
    st.small.took = !mark_and_cut_takes(st, vertices.len()) && small_clip(st, quality, false, out);
    st.small.took
}

/// The input check by the small stage (its narrow scratch for up to 64 nodes, the wide
/// one for more): `true` when it proved the input valid (in lenient mode: when it takes
/// it); when not, [`check_input`] must decide.
pub(crate) fn small_ring_valid<T: Coord>(
    cx: &mut Context,
    st: &mut Stages,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    nesting: Nesting,
    lenient: bool,
) -> bool {
    let sm = &mut st.small;
    let nodes = (small::nodes(vertices.len(), ring_starts)).filter(|_| !sm.off);
    sm.took = match nodes {
        None => false,
        Some(n) => {
            sm.used_wide = n > small::NARROW_MAX;
            if sm.used_wide {
                small::check(cx, &mut sm.wide, vertices, ring_starts, nesting, lenient)
            } else {
                small::check(cx, &mut sm.narrow, vertices, ring_starts, nesting, lenient)
            }
        }
    };
    sm.took
}

/// Loads and checks the input: `load`, `clean` (and in lenient mode on input without
/// crossings, `lobes`), then `nest`. With `untwist`, bow ties are uncrossed first (see
/// [`super::lenient`]); `Ok(false)` when there was none, so the run would repeat the last.
pub(crate) fn check_input<T: Coord>(
    cx: &mut Context,
    st: &mut Stages,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    nesting: Nesting,
    untwist: bool,
) -> Result<bool, Error> {
    if !load_and_clean(cx, st, vertices, ring_starts, untwist)? {
        return Ok(false);
    }
    nest(cx, st, nesting)?;
    Ok(true)
}

/// `nest`: every live ring's depth, holes turned clockwise (after [`load_and_clean`]).
pub(crate) fn nest(cx: &mut Context, st: &mut Stages, nesting: Nesting) -> Result<(), Error> {
    nest::nest(cx, &mut st.nest, nesting)
}

/// `load`, `clean` and (lenient, no crossings) `lobes`: every ring proper and oriented
/// counter-clockwise. `Ok(false)` as [`check_input`].
pub(crate) fn load_and_clean<T: Coord>(
    cx: &mut Context,
    st: &mut Stages,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    untwist: bool,
) -> Result<bool, Error> {
    load::load(cx, vertices, ring_starts)?;
    if !clean::clean(cx, &mut st.clean, untwist)? {
        return Ok(false);
    }
    // (crossing input has no region to keep, and its repairs, untwisting included, were
    // tuned on whole rings)
    if cx.lenient && !untwist && cx.crossings.is_empty() && !cx.keep_lobes {
        lobes::split(cx, &mut st.lobes);
    }
    clean::orient_rings(cx, &mut st.clean);
    Ok(true)
}

/// `touch`: joins rings where they meet, so that every boundary is weakly simple, and
/// refuses (strict) rings winding twice. Returns the number of holes.
pub(crate) fn join(cx: &mut Context, st: &mut Stages) -> Result<usize, Error> {
    let holes = touch::join(cx, &mut st.touch);
    touch::refuse_rings_winding_twice(cx, &mut st.touch)?;
    Ok(holes)
}
