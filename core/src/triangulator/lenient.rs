//! How a call runs the pipeline — and lenient mode's reruns on crossing input.
//!
//! One small polygon (up to 128 nodes, a few holes) goes to the `small` stage alone,
//! which gives the pipeline's result or hands the input back. Otherwise strict mode, and
//! lenient mode on input whose edges do not cross, run the pipeline once ([`run`]); in
//! lenient mode, a second time with every ring whole when cutting rings into their lobes
//! made two rings double each other (see [`prepare`]). Crossing edges have no exact
//! triangulation; lenient mode then looks for the best effort, judged by earcut's
//! deviation (how far the triangles' area is from the input's, [`crate::deviation`]).
//! The policy:
//!
//! 1. **The plain run**: bow ties as given, and clipping twice from the same bridged
//!    rings — once as usual, once with ears at crossed edges deferred until nothing else
//!    can be cut ([`clip_best_effort`]); the closer result is kept.
//! 2. **Untwisted**: bow ties uncrossed first (`clean`'s `untwist`), clipped once. Skipped
//!    when there is no bow tie to uncross.
//! 3. **Careful bridges**: only when a bridge of the plain run left the polygon (a hole's
//!    rightmost vertex poking into a hole bridged before): the plain run again from its
//!    state just before bridging (kept in a [`Snapshot`]), bridging such holes from a
//!    vertex that sees its target properly.
//!
//! The result closest to the input's area wins; a run that covers it exactly cannot be
//! beaten, so the rest are skipped. Each kind of run wins on some corpus input (earcut's
//! water fixtures), which is why all three are kept.

use super::pipeline::{self, Stages};
use crate::context::{Context, Ring};
use crate::crossings::{proof, sweep};
use crate::geom::{approx_cross, approx_double_area, Coord, Point};
use crate::report::{Dropped, Repair, RepairKind};
use crate::stages::bridge::{self, Careful};
use crate::stages::clip;
use crate::structures::{Node, NodeId, Pool};
use crate::{Error, Options, Strategy};

/// A copy of the node pool and the ring table, to try again from the same point.
#[derive(Debug, Default)]
pub(crate) struct Snapshot {
    nodes: Vec<Node>,
    rings: Vec<Ring>,
}

impl Snapshot {
    fn save(&mut self, pool: &Pool, rings: &[Ring]) {
        copy_into(&mut self.nodes, &pool.nodes);
        copy_into(&mut self.rings, rings);
    }

    fn restore(&self, pool: &mut Pool, rings: &mut Vec<Ring>) {
        copy_into(&mut pool.nodes, &self.nodes);
        copy_into(rings, &self.rings);
    }
}

/// Makes `to` a copy of `from`, keeping `to`'s buffer.
fn copy_into<T: Copy>(to: &mut Vec<T>, from: &[T]) {
    to.clear();
    to.extend_from_slice(from);
}

/// What lenient mode keeps between the runs of one call, and their buffers.
#[derive(Debug, Default)]
pub(crate) struct Reruns {
    /// The careful-bridges switch for the bridge stage, and what it reported.
    careful: Careful,
    /// Twice the input's area (outer rings minus holes, by the shoelace formula, as
    /// earcut measures it).
    area: f64,
    /// The deviation of the last run's result from `area`.
    deviation: f64,
    /// The bridged rings, for the second clipping try.
    before_clip: Snapshot,
    saved_repairs: Vec<Repair>,
    /// The plain run's state before bridging, for the careful run.
    before_bridge: Snapshot,
    before_bridge_dropped: Vec<Dropped>,
    before_bridge_repairs: Vec<Repair>,
    before_bridge_crossings: Vec<sweep::Crossing>,
    before_bridge_holes: usize,
    /// The best run's report so far.
    best_dropped: Vec<Dropped>,
    best_repairs: Vec<Repair>,
    /// Other runs' triangles.
    alt_out: Vec<[u32; 3]>,
    alt_untwisted: Vec<[u32; 3]>,
    /// Finding the crossed edges: ring starts, the quick scan's buffers, flagged edges.
    starts: Vec<NodeId>,
    proof: proof::ProofScratch,
    flagged: Vec<NodeId>,
}

/// What one call made, besides its triangles.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Outcome {
    pub polygons: usize,
    pub holes: usize,
    /// earcut's deviation of the triangles' area from the input's.
    pub deviation: f64,
}

/// Runs one call: the small stage, or the pipeline once, and on crossing lenient
/// input the reruns the policy above allows.
pub(crate) fn triangulate<T: Coord>(
    cx: &mut Context,
    st: &mut Stages,
    re: &mut Reruns,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    options: &Options,
    out: &mut Vec<[u32; 3]>,
) -> Result<Outcome, Error> {
    let quality = options.strategy == Strategy::Quality;
    if (quality || options.strategy == Strategy::Fast)
        && pipeline::small_ring(
            cx,
            st,
            vertices,
            ring_starts,
            options.nesting,
            quality,
            options.lenient,
            out,
        )
    {
        // valid input: a lenient run is measured all the same, as the pipeline's is
        let (polygons, holes, area) = st.small.counts_and_area();
        let deviation = if options.lenient {
            deviation(area, vertices, out)
        } else {
            0.0
        };
        return Ok(Outcome {
            polygons,
            holes,
            deviation,
        });
    }
    re.careful.bridges = false;
    cx.keep_collinear = false;
    cx.keep_lobes = false;
    // without `untwist` the pipeline always runs to the end
    let (mut polygons, mut holes) = run(cx, st, re, vertices, ring_starts, options, false, out)?
        .ok_or(Error::Internal { stage: "clean" })?;
    if !cx.lenient || cx.crossings.is_empty() {
        // a strict result covers the input exactly: its deviation is 0, whatever rounding
        // the floating-point measure would add
        let deviation = if cx.lenient {
            deviation(re.area, vertices, out)
        } else {
            0.0
        };
        return Ok(Outcome {
            polygons,
            holes,
            deviation,
        });
    }
    let mut best = re.deviation;
    // Bridges are chosen carefully only where one leaves the polygon, so without that in
    // this run (bow ties as given) the careful run would repeat it.
    let careful_may_help = re.careful.bridge_left;
    copy_into(&mut re.best_dropped, &cx.dropped);
    copy_into(&mut re.best_repairs, &cx.repairs);
    let mut alt = core::mem::take(&mut re.alt_untwisted);
    for untwist in [true, false] {
        if best == 0.0 || (!untwist && !careful_may_help) {
            break;
        }
        // Careful bridges, bow ties as given: which of the two kinds of run goes better
        // with them varies, and one more run is enough here.
        re.careful.bridges = !untwist;
        let next = run(
            cx,
            st,
            re,
            vertices,
            ring_starts,
            options,
            untwist,
            &mut alt,
        );
        re.careful.bridges = false;
        match next {
            Ok(Some(counts)) if re.deviation < best => {
                best = re.deviation;
                (polygons, holes) = counts;
                // copy, not swap: the caller's buffer keeps its capacity
                copy_into(out, &alt);
                copy_into(&mut re.best_dropped, &cx.dropped);
                copy_into(&mut re.best_repairs, &cx.repairs);
            }
            _ => {}
        }
    }
    copy_into(&mut cx.dropped, &re.best_dropped);
    copy_into(&mut cx.repairs, &re.best_repairs);
    re.alt_untwisted = alt;
    Ok(Outcome {
        polygons,
        holes,
        deviation: best,
    })
}

/// Lenient mode, rings read by containment (`Nesting::Auto`) whose edges cross nowhere but
/// which lie on each other (a ring given twice, a ring along another's edges inside it:
/// strict mode refuses them as `Error::RingsOverlap`) or cross each other at a vertex
/// they share (`Error::RingsCrossAtVertex`): containment cannot order them, and the
/// triangles of [`triangulate`] (`made`, in `out`) may cover a region twice. The even–odd
/// rule reads such rings exactly where some choice of outer rings and holes makes every
/// winding number 0 or 1 (as the oracle reads rings by containment: the winding number
/// and the count of rings round a point then have the same parity), covers nothing twice
/// where none does (two rings crossing as an X), and adds no vertex where no edges cross:
/// `even_odd` runs it (into its buffer), and its triangles replace `made`'s when it added
/// no vertex, with a [`RepairKind::ReadEvenOdd`] repair. Otherwise `made` stands, its
/// report restored.
pub(crate) fn read_even_odd_where_rings_overlap<T: Coord>(
    cx: &mut Context,
    re: &mut Reruns,
    vertices: &[[T; 2]],
    made: Outcome,
    out: &mut Vec<[u32; 3]>,
    even_odd: impl FnOnce(&mut Context, &mut Reruns, &mut Vec<[u32; 3]>) -> Result<Outcome, Error>,
) -> Outcome {
    if !cx.rings_overlap || !cx.crossings.is_empty() {
        return made;
    }
    let area = re.area;
    copy_into(&mut re.best_dropped, &cx.dropped);
    copy_into(&mut re.best_repairs, &cx.repairs);
    let mut alt = core::mem::take(&mut re.alt_out);
    let mut kept = None;
    if let Ok(read) = even_odd(cx, re, &mut alt) {
        if cx.added.is_empty() {
            copy_into(out, &alt);
            cx.repairs.clear();
            cx.repair(RepairKind::ReadEvenOdd, 0, 0);
            // (measured against the input's area as the containment reading has it)
            let deviation = deviation(area, vertices, out);
            kept = Some(Outcome { deviation, ..read });
        }
    }
    re.alt_out = alt;
    kept.unwrap_or_else(|| {
        cx.added.clear();
        copy_into(&mut cx.dropped, &re.best_dropped);
        copy_into(&mut cx.repairs, &re.best_repairs);
        made
    })
}

/// Strict mode's call from where [`pipeline::check_input`] passed on `cx`: joins touching
/// rings, bridges the holes and clips, as [`triangulate`] would go on (the fill rules'
/// way for input strict mode reads as they do).
pub(crate) fn finish_checked(
    cx: &mut Context,
    st: &mut Stages,
    re: &mut Reruns,
    strategy: Strategy,
    out: &mut Vec<[u32; 3]>,
) -> Result<Outcome, Error> {
    out.clear();
    re.careful.bridges = false;
    let holes = pipeline::join(cx, st)?;
    bridge::bridge(cx, &mut st.bridge, &mut re.careful)?;
    let polygons = clip::clip(cx, &mut st.clip, strategy, false, out)?;
    Ok(Outcome {
        polygons,
        holes,
        deviation: 0.0,
    })
}

/// The whole pipeline once; returns the numbers of polygons and holes. `None` when asked
/// to `untwist` and there was no bow tie to untwist: the run would repeat the last one.
/// Bridges are chosen carefully when `re.careful` says so; that run starts from the plain
/// run's state before bridging, which [`prepare`] kept.
#[allow(clippy::too_many_arguments)] // the call's input, its state and its output
fn run<T: Coord>(
    cx: &mut Context,
    st: &mut Stages,
    re: &mut Reruns,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    options: &Options,
    untwist: bool,
    out: &mut Vec<[u32; 3]>,
) -> Result<Option<(usize, usize)>, Error> {
    out.clear();
    cx.reset(options.lenient);
    let holes = if re.careful.bridges {
        // The careful run is the plain run up to the bridges: start from its state there
        // (load, clean, nest, touch and the crossing flags are deterministic).
        re.before_bridge.restore(&mut cx.pool, &mut cx.rings);
        cx.edge_index.invalidate();
        copy_into(&mut cx.dropped, &re.before_bridge_dropped);
        copy_into(&mut cx.repairs, &re.before_bridge_repairs);
        copy_into(&mut cx.crossings, &re.before_bridge_crossings);
        re.before_bridge_holes
    } else {
        match prepare(cx, st, re, vertices, ring_starts, options.nesting, untwist)? {
            Some(holes) => holes,
            None => return Ok(None),
        }
    };
    bridge::bridge(cx, &mut st.bridge, &mut re.careful)?;
    let polygons = if cx.lenient && !cx.crossings.is_empty() {
        clip_best_effort(cx, st, re, vertices, options.strategy, out)?
    } else {
        let polygons = clip::clip(cx, &mut st.clip, options.strategy, false, out)?;
        if untwist {
            // untwisting uncrossed every crossing edge: one clip, measured all the same
            re.deviation = deviation(re.area, vertices, out);
        }
        polygons
    };
    Ok(Some((polygons, holes)))
}

/// The pipeline up to bridging: load, clean, nest, join touching rings and, on crossing
/// lenient input, flag the crossed edges. Returns the number of holes; `None` as [`run`].
/// The plain run on crossing input with holes keeps its state for the careful run.
fn prepare<T: Coord>(
    cx: &mut Context,
    st: &mut Stages,
    re: &mut Reruns,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    nesting: crate::Nesting,
    untwist: bool,
) -> Result<Option<usize>, Error> {
    if !pipeline::check_input(cx, st, vertices, ring_starts, nesting, untwist)? {
        return Ok(None);
    }
    if cx.split_lobes && cx.rings_doubled {
        // Cut into lobes, a ring's lobe lies on another ring, both holes (or both outer),
        // each inside the other, where whole the ring may well have been cancelled by it:
        // the rings whole, as strict mode reads them, for the rest of the call — unless
        // whole they double each other too; then the lobes stay cut.
        cx.keep_lobes = true;
        cx.reset(true);
        pipeline::check_input(cx, st, vertices, ring_starts, nesting, untwist)?;
        if cx.rings_doubled {
            cx.keep_lobes = false;
            cx.reset(true);
            pipeline::check_input(cx, st, vertices, ring_starts, nesting, untwist)?;
        }
    }
    let crossing = cx.lenient && !cx.crossings.is_empty();
    // Every lenient run is measured against the input's area, as earcut measures (the
    // report's deviation, and on crossing input the choice between runs): untwisting
    // relinks the rings and changes their shoelace sum, so that run keeps the area of
    // the run before it (always one without untwisting).
    if cx.lenient && !untwist {
        re.area = signed_area(cx);
    }
    let holes = pipeline::join(cx, st)?;
    if crossing {
        mark_crossed(cx, re);
    }
    // only a bridge can leave the polygon, which is what a careful run may follow
    let has_holes = || cx.rings.iter().any(|r| r.alive && r.depth % 2 == 1);
    if crossing && !untwist && has_holes() {
        re.before_bridge.save(&cx.pool, &cx.rings);
        copy_into(&mut re.before_bridge_dropped, &cx.dropped);
        copy_into(&mut re.before_bridge_repairs, &cx.repairs);
        copy_into(&mut re.before_bridge_crossings, &cx.crossings);
        re.before_bridge_holes = holes;
    }
    Ok(Some(holes))
}

/// Flags every edge that crosses another (`Node::crossed`), for the clipper to defer.
fn mark_crossed(cx: &mut Context, re: &mut Reruns) {
    re.starts.clear();
    re.starts
        .extend(cx.rings.iter().filter(|r| r.alive).map(|r| r.start));
    // comparing the edges whose boxes overlap usually suffices; where that gives up (many
    // long edges over each other), the grid of the edges as they are now (bridge builds
    // its own afterwards) finds the rest
    if !proof::mark_crossed(&mut cx.pool, &re.starts, &mut re.proof) {
        cx.edge_index.rebuild(&cx.pool, &cx.rings);
        let grid = cx.edge_index.grid();
        sweep::mark_crossed(&mut cx.pool, grid, &re.starts, &mut re.flagged);
    }
}

/// Lenient mode, input with crossing edges: no triangulation covers it exactly, so clip
/// twice from the same bridged rings — with ears at crossed edges deferred and without —
/// and keep the result whose area is closer to the input's (earcut's deviation measure),
/// recorded in `re.deviation`. A first result covering the area exactly cannot be beaten,
/// so then the second clip is skipped.
fn clip_best_effort<T: Coord>(
    cx: &mut Context,
    st: &mut Stages,
    re: &mut Reruns,
    vertices: &[[T; 2]],
    strategy: Strategy,
    out: &mut Vec<[u32; 3]>,
) -> Result<usize, Error> {
    re.before_clip.save(&cx.pool, &cx.rings);
    let repairs_before = cx.repairs.len();
    let polygons = clip::clip(cx, &mut st.clip, strategy, false, out)?;
    let plain = deviation(re.area, vertices, out);
    re.deviation = plain;
    if plain == 0.0 {
        return Ok(polygons);
    }
    // keep the first try's repairs aside, restore the rings, try again
    copy_into(&mut re.saved_repairs, &cx.repairs[repairs_before..]);
    cx.repairs.truncate(repairs_before);
    re.before_clip.restore(&mut cx.pool, &mut cx.rings);
    let mut alt = core::mem::take(&mut re.alt_out);
    alt.clear();
    let result = clip::clip(cx, &mut st.clip, strategy, true, &mut alt);
    let deferred = if result.is_ok() {
        deviation(re.area, vertices, &alt)
    } else {
        f64::INFINITY
    };
    if deferred < plain {
        // copy, not swap: the caller's buffer keeps its capacity
        copy_into(out, &alt);
        re.deviation = deferred;
    } else {
        cx.repairs.truncate(repairs_before);
        cx.repairs.extend_from_slice(&re.saved_repairs);
    }
    re.alt_out = alt;
    Ok(polygons)
}

/// earcut's deviation of triangles from an area, in floating point (a heuristic measure).
fn deviation<T: Coord>(area: f64, vertices: &[[T; 2]], triangles: &[[u32; 3]]) -> f64 {
    let p = |i: u32| {
        let v = vertices
            .get(i as usize)
            .copied()
            .map(|v| [v[0].to_f64(), v[1].to_f64()]);
        let [x, y] = v.unwrap_or([0.0, 0.0]);
        Point::new(x, y)
    };
    let covered: f64 = triangles
        .iter()
        .map(|t| approx_double_area(p(t[0]), p(t[1]), p(t[2])).abs())
        .sum();
    crate::deviation(area, covered)
}

/// Twice the input's area: outer rings minus holes (by nesting depth), shoelace formula.
fn signed_area(cx: &Context) -> f64 {
    let mut total = 0.0;
    for ring in cx.rings.iter().filter(|r| r.alive) {
        let mut s = 0.0;
        for n in cx.pool.ring(ring.start) {
            s += approx_cross(cx.pool.p(n), cx.pool.p(cx.pool.next(n)));
        }
        total += if ring.depth % 2 == 0 {
            s.abs()
        } else {
            -s.abs()
        };
    }
    total
}
