//! The reusable [`Triangulator`]: owns every buffer the pipeline needs, so a warmed-up
//! triangulator allocates nothing on an input of the same size.

use core::marker::PhantomData;

use crate::crossings::sweep::SweepScratch;
use crate::report::{Dropped, Repair, RepairKind, Report};
use crate::structures::EdgeGrid;
use crate::structures::{NodeId, Pool};
use crate::{bridge, clean, clip, load, nest, touch, Error, Options};

/// A coordinate type the triangulator accepts: `f32` or `f64`.
///
/// Coordinates are widened to `f64` when loaded, which is exact, so every predicate gives
/// the exact answer for the coordinates the caller gave.
pub trait Coord: Copy + sealed::Sealed {
    /// The value as `f64` (exact for both implementations).
    fn to_f64(self) -> f64;
}

impl Coord for f64 {
    #[inline]
    fn to_f64(self) -> f64 {
        self
    }
}

impl Coord for f32 {
    #[inline]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
}

/// One ring after loading. Rings are indexed in load order, which is input order.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ring {
    /// Position in the caller's `ring_starts`.
    pub input: u32,
    /// A live node of the ring.
    pub start: NodeId,
    /// Live nodes in the ring.
    pub len: u32,
    /// Rightmost node (ties: lowest y); the paper's M for holes.
    pub rightmost: NodeId,
    /// Containment depth: even for outer boundaries, odd for holes.
    pub depth: u32,
    /// Still part of the input (not degenerate, not skipped).
    pub alive: bool,
    /// Part of an outer boundary's ring by now: an outer ring, or a hole bridged into one.
    pub merged: bool,
    /// The outer ring whose polygon this ring belongs to once bridged (itself for outers).
    pub component: u32,
}

/// Everything the stages share: the node pool, the ring table, the report and scratch
/// buffers. Stages are functions over this context.
#[derive(Debug, Default)]
pub(crate) struct Context {
    pub pool: Pool,
    pub rings: Vec<Ring>,
    pub dropped: Vec<Dropped>,
    pub repairs: Vec<Repair>,
    pub lenient: bool,
    /// Lenient mode: bridge holes whose rightmost vertex pokes into another hole from
    /// elsewhere (see `bridge`); set for one extra run only.
    pub careful_bridges: bool,
    /// Lenient mode: some bridge of this run left the polygon (the careful run may help).
    pub bridge_left: bool,
    /// Scratch: ring order for bridging, ring start nodes for the sweep.
    pub order: Vec<u32>,
    pub starts: Vec<NodeId>,
    /// Scratch of `nest`: rings by descending rightmost x, and whose depth is known yet.
    pub ring_order: Vec<u32>,
    pub depth_known: Vec<bool>,
    /// Scratch of `nest`: the winding number of each ring touching a vertex, away from it.
    pub touch_winding: Vec<i64>,
    /// Scratch of `nest`: the rings passing through a position.
    pub probe_rings: Vec<u32>,
    /// Scratch of `nest`: per ring, its place among the rings through the position being
    /// decided, or `u32::MAX`; and those rings' edges through it (place, turned ends).
    pub ring_slot: Vec<u32>,
    pub hub_edges: Vec<(u32, crate::geom::Point, crate::geom::Point)>,
    /// Scratch of `nest`'s winding numbers: edges met along the ray in along lists.
    pub along_seen: Vec<NodeId>,
    /// Scratch of `nest`: (b, q) where ring b lies on ring q's boundary, inside it.
    pub overlaps: Vec<(u32, u32)>,
    /// Per ring as loaded: its first node and node count (its nodes lie together, in
    /// input order).
    pub blocks: Vec<(u32, u32)>,
    /// Clean keeps straight vertices: the first try dropped one where edges then crossed.
    /// Set for the rest of the call.
    pub keep_collinear: bool,
    /// Scratch of `nest`: edges that cleaning dropped, with their rings.
    pub dropped_edges: Vec<(u32, crate::geom::Point, crate::geom::Point)>,
    /// Scratch: edges by start node (lenient crossing flags).
    pub edges: Vec<NodeId>,
    pub touches: Vec<crate::crossings::sweep::Touch>,
    /// Nodes at positions held by several nodes, sorted by position (see `touch`).
    pub shared: Vec<NodeId>,
    /// Scratch of `touch`: the new successor of each node of one shared position.
    pub relink: Vec<(NodeId, NodeId)>,
    pub touch_ends: Vec<(crate::geom::Point, NodeId, bool)>,
    /// Scratch of `touch` at a position many nodes share: the edges leaving it (far end,
    /// place among the nodes there, far node) by direction, and their far ends by position.
    pub touch_leaving: Vec<(crate::geom::Point, u32, NodeId)>,
    pub touch_far: Vec<crate::geom::Point>,
    /// Scratch: one ring's edges with the segments walked both ways cancelled (see
    /// `clean::net_boundary_counter_clockwise`).
    pub net_edges: Vec<(crate::geom::Point, crate::geom::Point, i64)>,
    /// Scratch: pairs of rings one ring was cut into (see `touch::refuse_rings_winding_twice`).
    pub lobe_pairs: Vec<(u32, u32, NodeId)>,
    /// Scratch: the rings through one position, with their input ring and depth.
    pub lobe_meet: Vec<(u32, u32, u32, NodeId)>,
    pub touch_nets: Vec<(crate::geom::Point, i32)>,
    pub crossings: Vec<crate::crossings::sweep::Crossing>,
    pub sweep: SweepScratch,
    pub prune: crate::crossings::proof::ProofScratch,
    pub edge_grid: EdgeGrid,
    /// Lenient mode with crossings: the input's area (outer rings minus holes, by the
    /// shoelace formula as earcut measures it) and snapshots for a second clipping try.
    pub area: f64,
    /// Lenient mode with crossings: the deviation of the last run's result from `area`.
    pub deviation: f64,
    /// The bridged rings, for the second clipping try.
    pub before_clip: Snapshot,
    pub saved_repairs: Vec<Repair>,
    /// The first run's state before bridging, for the careful run (see [`run`]).
    pub before_bridge: Snapshot,
    pub before_bridge_dropped: Vec<Dropped>,
    pub before_bridge_repairs: Vec<Repair>,
    pub before_bridge_crossings: Vec<crate::crossings::sweep::Crossing>,
    pub before_bridge_holes: usize,
    pub first_dropped: Vec<Dropped>,
    pub first_repairs: Vec<Repair>,
    pub alt_out: Vec<[u32; 3]>,
    pub alt_untwisted: Vec<[u32; 3]>,
    pub clip: clip::ClipScratch,
    /// `edge_grid` lists every live edge of the live rings as they are linked now (set by
    /// `nest::index_all_edges`; whatever relinks nodes before `bridge` clears it).
    pub grid_current: bool,
    /// Lenient mode: some ring touching itself was split into its lobes (see `lobes`).
    pub split_lobes: bool,
    pub lobes: crate::lobes::LobeScratch,
}

/// A copy of the node pool and the ring table, to try again from the same point.
#[derive(Debug, Default)]
pub(crate) struct Snapshot {
    nodes: Vec<crate::structures::Node>,
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

impl Context {
    fn reset(&mut self, lenient: bool) {
        self.pool.clear();
        self.rings.clear();
        self.dropped.clear();
        self.repairs.clear();
        self.lenient = lenient;
        self.bridge_left = false;
        self.split_lobes = false;
        self.grid_current = false;
    }

    /// Records a lenient-mode repair.
    pub fn repair(&mut self, kind: RepairKind, ring: u32, vertex: u32) {
        self.repairs.push(Repair { kind, ring, vertex });
    }
}

/// The whole pipeline once; returns the numbers of polygons and holes. `None` when asked
/// to `untwist` and there was no bow tie to untwist: the run would repeat the last one.
/// Bridges are chosen carefully when `cx.careful_bridges` says so; that run starts from
/// the first run's state before bridging, which [`prepare`] kept.
fn run<T: Coord>(
    cx: &mut Context,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    options: &Options,
    untwist: bool,
    out: &mut Vec<[u32; 3]>,
) -> Result<Option<(usize, usize)>, Error> {
    out.clear();
    cx.reset(options.lenient);
    let holes = if cx.careful_bridges {
        // The careful run is the first run up to the bridges: start from its state there
        // (load, clean, nest, touch and the crossing flags are deterministic).
        cx.before_bridge.restore(&mut cx.pool, &mut cx.rings);
        cx.grid_current = false;
        copy_into(&mut cx.dropped, &cx.before_bridge_dropped);
        copy_into(&mut cx.repairs, &cx.before_bridge_repairs);
        copy_into(&mut cx.crossings, &cx.before_bridge_crossings);
        cx.before_bridge_holes
    } else {
        match prepare(cx, vertices, ring_starts, options.nesting, untwist)? {
            Some(holes) => holes,
            None => return Ok(None),
        }
    };
    bridge::bridge(cx)?;
    let polygons = if cx.lenient && !cx.crossings.is_empty() {
        clip_best_effort(cx, vertices, options.strategy, out)?
    } else {
        let polygons = clip::clip(cx, options.strategy, false, out)?;
        if untwist {
            // untwisting uncrossed every crossing edge: one clip, measured all the same
            cx.deviation = deviation(cx.area, vertices, out);
        }
        polygons
    };
    Ok(Some((polygons, holes)))
}

/// The pipeline up to bridging: load, clean, nest, join touching rings and, on crossing
/// lenient input, flag the crossed edges. Returns the number of holes; `None` as [`run`].
/// The first run on crossing input with holes keeps its state for the careful run.
fn prepare<T: Coord>(
    cx: &mut Context,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    nesting: crate::Nesting,
    untwist: bool,
) -> Result<Option<usize>, Error> {
    load::load(cx, vertices, ring_starts)?;
    if !clean::clean(cx, untwist)? {
        return Ok(None);
    }
    nest::nest(cx, nesting)?;
    let crossing = cx.lenient && !cx.crossings.is_empty();
    // Every run is measured against the input's area, as earcut measures: untwisting
    // relinks the rings and changes their shoelace sum, so that run keeps the area of
    // the run before it (always one without untwisting).
    if crossing && !untwist {
        cx.area = signed_area(cx);
    }
    let holes = touch::join(cx);
    touch::refuse_rings_winding_twice(cx)?;
    if crossing {
        cx.starts.clear();
        cx.starts
            .extend(cx.rings.iter().filter(|r| r.alive).map(|r| r.start));
        // comparing the edges whose boxes overlap usually suffices; where that gives up
        // (many long edges over each other), the grid of the edges as they are now (bridge
        // builds its own afterwards) finds the rest
        if !crate::crossings::proof::mark_crossed(&mut cx.pool, &cx.starts, &mut cx.prune) {
            nest::index_all_edges(cx);
            crate::crossings::sweep::mark_crossed(
                &mut cx.pool,
                &cx.edge_grid,
                &cx.starts,
                &mut cx.edges,
            );
        }
    }
    // only a bridge can leave the polygon, which is what a careful run may follow
    let has_holes = || cx.rings.iter().any(|r| r.alive && r.depth % 2 == 1);
    if crossing && !untwist && has_holes() {
        cx.before_bridge.save(&cx.pool, &cx.rings);
        copy_into(&mut cx.before_bridge_dropped, &cx.dropped);
        copy_into(&mut cx.before_bridge_repairs, &cx.repairs);
        copy_into(&mut cx.before_bridge_crossings, &cx.crossings);
        cx.before_bridge_holes = holes;
    }
    Ok(Some(holes))
}

/// Lenient mode, input with crossing edges: no triangulation covers it exactly, so clip
/// twice from the same bridged rings — with ears at crossed edges deferred and without —
/// and keep the result whose area is closer to the input's (earcut's deviation measure),
/// recorded in `cx.deviation`. A first result covering the area exactly cannot be beaten,
/// so then the second clip is skipped.
fn clip_best_effort<T: Coord>(
    cx: &mut Context,
    vertices: &[[T; 2]],
    strategy: crate::Strategy,
    out: &mut Vec<[u32; 3]>,
) -> Result<usize, Error> {
    cx.before_clip.save(&cx.pool, &cx.rings);
    let repairs_before = cx.repairs.len();
    let polygons = clip::clip(cx, strategy, false, out)?;
    let plain = deviation(cx.area, vertices, out);
    cx.deviation = plain;
    if plain == 0.0 {
        return Ok(polygons);
    }
    // keep the first try's repairs aside, restore the rings, try again
    copy_into(&mut cx.saved_repairs, &cx.repairs[repairs_before..]);
    cx.repairs.truncate(repairs_before);
    cx.before_clip.restore(&mut cx.pool, &mut cx.rings);
    let mut alt = core::mem::take(&mut cx.alt_out);
    alt.clear();
    let result = clip::clip(cx, strategy, true, &mut alt);
    let deferred = if result.is_ok() {
        deviation(cx.area, vertices, &alt)
    } else {
        f64::INFINITY
    };
    if deferred < plain {
        // copy, not swap: the caller's buffer keeps its capacity
        copy_into(out, &alt);
        cx.deviation = deferred;
    } else {
        cx.repairs.truncate(repairs_before);
        cx.repairs.extend_from_slice(&cx.saved_repairs);
    }
    cx.alt_out = alt;
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
        crate::geom::Point::new(x, y)
    };
    let covered: f64 = triangles
        .iter()
        .map(|t| crate::geom::approx_double_area(p(t[0]), p(t[1]), p(t[2])).abs())
        .sum();
    crate::deviation(area, covered)
}

/// Twice the input's area: outer rings minus holes (by nesting depth), shoelace formula.
fn signed_area(cx: &Context) -> f64 {
    let mut total = 0.0;
    for ring in cx.rings.iter().filter(|r| r.alive) {
        let mut s = 0.0;
        for n in cx.pool.ring(ring.start) {
            s += crate::geom::approx_cross(cx.pool.p(n), cx.pool.p(cx.pool.next(n)));
        }
        total += if ring.depth % 2 == 0 {
            s.abs()
        } else {
            -s.abs()
        };
    }
    total
}

/// Triangulates polygons with holes and islands; reuse it to avoid allocation.
///
/// `T` is the coordinate type, `f32` or `f64`.
///
/// ```
/// # fn main() -> Result<(), polytri::Error> {
/// let mut tri = polytri::Triangulator::<f32>::new();
/// let opts = polytri::Options::default()
///     .with_strategy(polytri::Strategy::Quality)
///     .with_nesting(polytri::Nesting::FirstIsOuter)
///     .with_lenient(true);
/// let vertices = [[0.0f32, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]];
/// let mut out: Vec<[u32; 3]> = Vec::new();
/// let report = tri.triangulate(&vertices, &[0], &opts, &mut out)?;
/// assert_eq!(out.len(), 2);
/// assert!(report.dropped.is_empty());
/// # Ok(())
/// # }
/// ```
#[derive(Debug)]
pub struct Triangulator<T: Coord> {
    cx: Context,
    _coord: PhantomData<fn(T)>,
}

impl<T: Coord> Default for Triangulator<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Coord> Triangulator<T> {
    /// A triangulator with empty buffers; they grow on first use and are kept.
    pub fn new() -> Self {
        Triangulator {
            cx: Context::default(),
            _coord: PhantomData,
        }
    }

    /// Runs strict mode's input check alone, without triangulating: the same loading,
    /// cleaning (the edge sweep that refuses crossings) and nesting (holes inside their
    /// polygons) that [`Triangulator::triangulate`] runs first, with `nesting` as in
    /// [`Options::with_nesting`]. `Ok` means no edges cross and every hole lies inside its
    /// polygon; the error is the one strict `triangulate` gives. (A few defects of weakly
    /// simple rings only show while clipping, such as [`Error::LobesWindOpposite`].) Useful
    /// to validate data once, or to see what the check costs (`polytri bench` times it).
    ///
    /// ```
    /// # fn main() -> Result<(), polytri::Error> {
    /// let mut tri = polytri::Triangulator::<f64>::new();
    /// let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
    /// tri.check(&square, &[0], polytri::Nesting::Auto)?;
    /// let bow_tie = [[0.0, 0.0], [4.0, 4.0], [4.0, 0.0], [0.0, 4.0]];
    /// assert!(tri.check(&bow_tie, &[0], polytri::Nesting::Auto).is_err());
    /// # Ok(())
    /// # }
    /// ```
    ///
    /// # Errors
    ///
    /// Those of strict [`Triangulator::triangulate`] about the input.
    pub fn check(
        &mut self,
        vertices: &[[T; 2]],
        ring_starts: &[usize],
        nesting: crate::Nesting,
    ) -> Result<(), Error> {
        let cx = &mut self.cx;
        cx.careful_bridges = false;
        cx.keep_collinear = false;
        cx.reset(false);
        load::load(cx, vertices, ring_starts)?;
        clean::clean(cx, false)?;
        nest::nest(cx, nesting)
    }

    /// Triangulates the rings given by `vertices` and `ring_starts`.
    ///
    /// `ring_starts[k]` is the index of ring `k`'s first vertex; the first entry is 0 and
    /// each ring runs to the next start (the last to the end). A closing point equal to the
    /// first is allowed. Winding order does not matter.
    ///
    /// `out` is cleared and filled with triangles: indices into `vertices`,
    /// counter-clockwise with y up.
    ///
    /// # Errors
    ///
    /// Bad input is refused with an [`Error`] saying what and where: non-finite coordinates,
    /// malformed `ring_starts`, too many vertices, and in strict mode (the default) crossing
    /// edges or misplaced holes. With [`Options::with_lenient`] only `TooManyVertices` and
    /// `Internal` remain; everything else is repaired and listed in the [`Report`].
    pub fn triangulate(
        &mut self,
        vertices: &[[T; 2]],
        ring_starts: &[usize],
        options: &Options,
        out: &mut Vec<[u32; 3]>,
    ) -> Result<Report<'_>, Error> {
        let cx = &mut self.cx;
        cx.careful_bridges = false;
        cx.keep_collinear = false;
        // without `untwist` the pipeline always runs to the end
        let (mut polygons, mut holes) = run(cx, vertices, ring_starts, options, false, out)?
            .ok_or(Error::Internal { stage: "clean" })?;
        if cx.lenient && !cx.crossings.is_empty() {
            // Crossing edges have no exact triangulation: try again with bow ties
            // uncrossed, and where a bridge left the polygon, with bridges chosen
            // carefully; keep whichever covers the input's area most closely. A run
            // covering it exactly cannot be beaten: then the others are skipped.
            let mut best = cx.deviation;
            // Bridges are chosen carefully only where one leaves the polygon, so without
            // that in this run (bow ties as given) the careful run would repeat it.
            let careful_may_help = cx.bridge_left;
            copy_into(&mut cx.first_dropped, &cx.dropped);
            copy_into(&mut cx.first_repairs, &cx.repairs);
            let mut alt = core::mem::take(&mut cx.alt_untwisted);
            for untwist in [true, false] {
                if best == 0.0 || (!untwist && !careful_may_help) {
                    break;
                }
                // Careful bridges, bow ties as given: which of the two kinds of run goes
                // better with them varies, and one more run is enough here.
                cx.careful_bridges = !untwist;
                let next = run(cx, vertices, ring_starts, options, untwist, &mut alt);
                cx.careful_bridges = false;
                match next {
                    Ok(Some(counts)) if cx.deviation < best => {
                        best = cx.deviation;
                        (polygons, holes) = counts;
                        // copy, not swap: the caller's buffer keeps its capacity
                        copy_into(out, &alt);
                        copy_into(&mut cx.first_dropped, &cx.dropped);
                        copy_into(&mut cx.first_repairs, &cx.repairs);
                    }
                    _ => {}
                }
            }
            copy_into(&mut cx.dropped, &cx.first_dropped);
            copy_into(&mut cx.repairs, &cx.first_repairs);
            cx.alt_untwisted = alt;
        }
        Ok(Report {
            triangles: out.len(),
            polygons,
            holes,
            dropped: &cx.dropped,
            repairs: &cx.repairs,
        })
    }
}
