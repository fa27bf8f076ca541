//! Fill rules: the rule's region of crossing and overlapping rings, resolved into valid
//! rings (`stages::resolve`) and triangulated by the usual pipeline, strict. Input that
//! strict mode reads as the rule does (no crossing, rings wound as they nest) skips the
//! resolving: strict mode's triangles are the rule's region ([`strict_first`]).

use super::lenient::{self, Outcome, Reruns};
use super::pipeline::{self, Stages};
use crate::context::Context;
use crate::geom::{orient2d, Coord, Orientation, Point, SnapGrid};
use crate::report::{Added, DropReason, Dropped};
use crate::stages::{clean, load, resolve, seidel, small};
use crate::structures::positions;
use crate::{Error, FillRule, Nesting, Options, Strategy};

/// The fill path's buffers.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    vertices: Vec<[f64; 2]>,
    resolve: resolve::Scratch,
    seidel: seidel::Scratch,
    /// Which output vertices the triangles use.
    used: Vec<bool>,
    /// The unused input vertices' positions, once each, and whether a used vertex holds
    /// each; and the table that finds them by position.
    unused: Vec<([f64; 2], bool)>,
    table: Vec<u32>,
    /// Checked input for Seidel: each pool node's position's first vertex (for nodes at
    /// shared positions), the rings, and the edges between shared positions.
    canon: Vec<u32>,
    ids: Vec<u32>,
    pairs: Vec<(u32, u32)>,
    starts: Vec<usize>,
}

/// The seed of `Strategy::Seidel`'s random order: fixed, so the same input always gives
/// the same triangles.
const SEIDEL_SEED: u64 = 0x5e1d_e12c;

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
    // Most real input is valid (a layer's polygons, a glyph without overlapping strokes):
    // where strict mode reads it as the rule does, its result is the rule's region,
    // without resolving anything (see [`strict_first`]).
    let tried = strict_first(
        cx,
        st,
        re,
        fs,
        vertices,
        ring_starts,
        rule,
        options.strategy,
        out,
    );
    let mut crossed = matches!(tried, Strict::Crossed);
    let uncrossed = match tried {
        Strict::Made(made) => {
            cx.added.clear();
            report_unused_input(&mut cx.dropped, fs, vertices, ring_starts, out);
            return Ok(made);
        }
        Strict::Crossed => false,
        Strict::Checked => true,
        Strict::Unsure => false,
        Strict::Declined => {
            // the input's own errors (non-finite coordinates, ring starts), as strict
            // mode gives them; and strict mode's crossing check (a sweep, O(n log n)):
            // where it passes, no two edges cross and `resolve` need not search for
            // crossings, which costs more where many long edges share the cells of its
            // grid
            cx.reset(false);
            cx.probe = true;
            load::load(cx, vertices, ring_starts)?;
            let cleaned = clean::clean(cx, &mut st.clean, false);
            // (abs ≥ 2, which strict mode never reads as the rule does, crossing: the
            // short way)
            crossed = matches!(cleaned, Err(Error::EdgesCross { .. }));
            cleaned.is_ok() && !cx.hidden_unchecked
        }
    };
    out.clear();
    fs.vertices.clear();
    fs.vertices
        .extend(vertices.iter().map(|v| [v[0].to_f64(), v[1].to_f64()]));
    let grid = SnapGrid { f32: T::IS_F32 };
    let mut added = core::mem::take(&mut cx.added);
    added.clear();
    // where edges only cross: the short way (crossings split and relinked), if it takes
    // the input
    if crossed {
        let made = short_way(
            cx,
            st,
            re,
            fs,
            vertices,
            ring_starts,
            grid,
            rule,
            options,
            &mut added,
            out,
        );
        match made {
            Ok(Some(made)) => {
                cx.added = added;
                return Ok(made);
            }
            Ok(None) => {
                out.clear();
                added.clear();
            }
            Err(e) => {
                cx.added = added;
                return Err(e);
            }
        }
    }
    let resolved = resolve::resolve(
        &mut fs.resolve,
        &fs.vertices,
        ring_starts,
        rule,
        grid,
        uncrossed,
        &mut added,
    );
    if let Err(e) = resolved {
        cx.added = added;
        return Err(e);
    }
    let made = triangulate_resolved(cx, st, re, fs, ring_starts, options.strategy, out);
    cx.added = added;
    made.map_err(|e| match e {
        Error::TooManyVertices { .. } => e,
        _ => Error::Internal { stage: "resolve" },
    })
}

/// Triangulates the rings `resolve` left in `fs.resolve` (valid, bounding the rule's
/// region) by `strategy`, into `out` as output indices, and reports the input vertices
/// no triangle uses.
fn triangulate_resolved(
    cx: &mut Context,
    st: &mut Stages,
    re: &mut Reruns,
    fs: &mut Scratch,
    ring_starts: &[usize],
    strategy: Strategy,
    out: &mut Vec<[u32; 3]>,
) -> Result<Outcome, Error> {
    let r = &fs.resolve;
    let made = if strategy == Strategy::Seidel {
        let (ids, starts) = (&r.ring_ids, &r.ring_starts);
        seidel::triangulate(&mut fs.seidel, &r.hot, starts, ids, SEIDEL_SEED, out)?;
        for v in out.iter_mut().flatten() {
            *v = r.hot_out[*v as usize];
        }
        let (polygons, holes) = count_rings(&r.hot, starts, ids);
        Outcome {
            polygons,
            holes,
            deviation: 0.0,
        }
    } else {
        // valid rings: strict, containment decides
        let strict = Options::new()
            .with_strategy(strategy)
            .with_nesting(Nesting::Auto);
        let made = lenient::triangulate(cx, st, re, &r.rings, &r.ring_starts, &strict, out)?;
        for v in out.iter_mut().flatten() {
            *v = r.map[*v as usize];
        }
        made
    };
    // the vertices the pipeline left out are the resolved rings', not the input's
    report_unused(&mut cx.dropped, &mut fs.used, r, ring_starts, out);
    Ok(made)
}

/// The short way where edges cross ([`resolve::uncross`]): the crossings rounded and
/// both edges split there. By even–odd (ear clipping), the split rings relinked at each
/// crossing to touch there and triangulated by strict mode; where strict mode refuses
/// them, and for the other rules and Seidel, the rings bounding the rule's region of the
/// split edges, as `resolve` traces them. The triangles into `out` (output indices), the
/// added vertices into `added`; `None` where the short way declines or the split edges
/// meet other than at their ends (then `resolve` decides).
#[allow(clippy::too_many_arguments)] // the call's input, its state and its output
fn short_way<T: Coord>(
    cx: &mut Context,
    st: &mut Stages,
    re: &mut Reruns,
    fs: &mut Scratch,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    grid: SnapGrid,
    rule: FillRule,
    options: &Options,
    added: &mut Vec<Added>,
    out: &mut Vec<[u32; 3]>,
) -> Result<Option<Outcome>, Error> {
    let relinking = rule == FillRule::EvenOdd && options.strategy != Strategy::Seidel;
    let way = (!relinking).then_some(rule);
    if !resolve::uncross(&mut fs.resolve, &fs.vertices, ring_starts, grid, added, way)? {
        return Ok(None);
    }
    if relinking {
        let r = &fs.resolve;
        let strict = Options::new()
            .with_strategy(options.strategy)
            .with_nesting(Nesting::Auto);
        match lenient::triangulate(cx, st, re, &r.rings, &r.ring_starts, &strict, out) {
            Ok(made) => {
                for v in out.iter_mut().flatten() {
                    *v = r.map[*v as usize];
                }
                report_unused_input(&mut cx.dropped, fs, vertices, ring_starts, out);
                return Ok(Some(made));
            }
            // (split edges that cross, which rounding made: the winding sweep would
            // find them too)
            Err(Error::EdgesCross { .. }) => return Ok(None),
            Err(_) => {}
        }
        out.clear();
        if !resolve::rewind(&mut fs.resolve, rule) {
            return Ok(None);
        }
    }
    Ok(triangulate_resolved(cx, st, re, fs, ring_starts, options.strategy, out).ok())
}

/// The input vertices no triangle uses, and why, into `dropped`: another vertex at the
/// same position stands for it ([`DropReason::Coincident`]), or it is no corner of the
/// rule's region ([`DropReason::OffBoundary`]).
fn report_unused(
    dropped: &mut Vec<Dropped>,
    used: &mut Vec<bool>,
    r: &resolve::Scratch,
    ring_starts: &[usize],
    out: &[[u32; 3]],
) {
    mark_used(used, r.vertex_hot.len(), out);
    let used = &*used;
    list_unused(dropped, used, ring_starts, |i| {
        let stands_for = r.hot_out.get(r.vertex_hot[i] as usize).map(|&o| o as usize);
        match stands_for {
            Some(o) if o != i && used.get(o) == Some(&true) => DropReason::Coincident,
            _ => DropReason::OffBoundary,
        }
    });
}

/// `used[v]`: whether a triangle of `out` uses vertex `v`, for the first `n` vertices.
fn mark_used(used: &mut Vec<bool>, n: usize, out: &[[u32; 3]]) {
    used.clear();
    used.resize(n, false);
    for &v in out.iter().flatten() {
        if let Some(u) = used.get_mut(v as usize) {
            *u = true;
        }
    }
}

/// Every input vertex not `used` into `dropped` (cleared first), with its ring and the
/// `reason` for it.
fn list_unused(
    dropped: &mut Vec<Dropped>,
    used: &[bool],
    ring_starts: &[usize],
    reason: impl Fn(usize) -> DropReason,
) {
    dropped.clear();
    let mut ring = 0;
    for i in (0..used.len()).filter(|&i| !used[i]) {
        while ring + 1 < ring_starts.len() && ring_starts[ring + 1] <= i {
            ring += 1;
        }
        dropped.push(Dropped {
            vertex: i as u32,
            ring: ring as u32,
            reason: reason(i),
        });
    }
}

/// What [`strict_first`] found.
enum Strict {
    /// Strict mode's triangles, the rule's region.
    Made(Outcome),
    /// Edges cross.
    Crossed,
    /// No edges cross, but strict mode refused the input or reads it otherwise.
    Checked,
    /// No edges of the filtered rings cross, and strict mode refused the input or reads it
    /// otherwise; edges of the input as loaded may cross where the filter dropped a
    /// spike's tip (not searched).
    Unsure,
    /// Not known whether edges cross: strict mode refused the input before its check
    /// passed for another reason (a bad number, say, or a small input refused as it was
    /// triangulated), or the rule is abs ≥ 2.
    Declined,
}

/// Strict mode's triangulation (`Nesting::Auto`, the strategy; for `Strategy::Seidel`,
/// the trapezoidation of strict mode's checked rings) where it is the rule's region,
/// which is so on most real input.
///
/// Where strict mode's check passes, no two edges cross, and strict mode fills the
/// faces of the rings' arrangement at even depth: the even–odd rule's region. For the
/// other rules: a ring strict mode takes winds once round its inside (its lobes turn one
/// way, a lobe inside another turning the other way bounds a hole of it, and rings
/// winding twice are refused), so its winding number is its orientation (±1) inside and
/// 0 outside; and rings that do not cross, touching or not, have insides apart or one
/// inside the other (rings doubling each other are refused), so the rings round a point
/// form a chain, each inside the one before, of depths 0, 1, 2, …. A face's winding
/// number is the sum of their orientations. If every ring runs as given the way the
/// check turned it (outer rings counter-clockwise, holes clockwise), the sum alternates
/// 1, 0, 1, … down the chain: 1 inside the rings of even depth and 0 elsewhere, which
/// nonzero and positive read as even–odd does; if every ring runs against it, −1 and 0,
/// for nonzero and negative. Anything else (rings both ways, abs ≥ 2) is left to
/// `resolve`, and so is input whose nodes mostly lie where rings touch (a layer's
/// polygons sharing their borders, all at once): joining so many touching rings costs
/// strict mode more than `resolve` takes.
#[allow(clippy::too_many_arguments)] // the call's input, its state and its output
fn strict_first<T: Coord>(
    cx: &mut Context,
    st: &mut Stages,
    re: &mut Reruns,
    fs: &mut Scratch,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    rule: FillRule,
    strategy: Strategy,
    out: &mut Vec<[u32; 3]>,
) -> Strict {
    if rule == FillRule::AbsGeqTwo {
        return Strict::Declined;
    }
    let seidel = strategy == Strategy::Seidel;
    // a small input: the small stage checks and triangulates in one pass (the pipeline
    // where it declines); for the rules other than even–odd it says first how the rings
    // run (and where it declines, the pipeline's check below decides)
    if !seidel && small::nodes(vertices.len(), ring_starts).is_some() {
        let reads = if rule == FillRule::EvenOdd {
            Some(true)
        } else {
            pipeline::small_ring_valid(cx, st, vertices, ring_starts, Nesting::Auto, false)
                .then(|| reads_as_nested(rule, st.small.rings_run()))
        };
        match reads {
            // (checked already: the small stage's clip, where it takes the input)
            Some(true)
                if rule != FillRule::EvenOdd
                    && pipeline::small_ring_checked(
                        st,
                        vertices,
                        strategy == Strategy::Quality,
                        out,
                    ) =>
            {
                let (polygons, holes, _) = st.small.counts_and_area();
                return Strict::Made(Outcome {
                    polygons,
                    holes,
                    deviation: 0.0,
                });
            }
            Some(true) => {
                let strict = Options::new()
                    .with_strategy(strategy)
                    .with_nesting(Nesting::Auto);
                return match lenient::triangulate(cx, st, re, vertices, ring_starts, &strict, out) {
                    Ok(made) => Strict::Made(made),
                    Err(Error::EdgesCross { .. }) => Strict::Crossed,
                    // (refused after its crossing check passed: by nesting, joining,
                    // bridging or clipping)
                    Err(
                        Error::RingsCrossAtVertex { .. }
                        | Error::HoleOutside { .. }
                        | Error::RingsOverlap { .. }
                        | Error::RingWindsTwice { .. }
                        | Error::LobesWindOpposite { .. },
                    ) => Strict::Checked,
                    Err(_) => Strict::Declined,
                };
            }
            Some(false) => return Strict::Checked,
            None => {}
        }
    }
    cx.keep_collinear = false;
    cx.keep_lobes = false;
    cx.reset(false);
    // (a crossing means `resolve`, whichever pair it is)
    cx.probe = true;
    match pipeline::load_and_clean(cx, st, vertices, ring_starts, false) {
        Ok(_) => {}
        Err(Error::EdgesCross { .. }) => return Strict::Crossed,
        Err(_) => return Strict::Declined,
    }
    // (where the check passed: strict mode's triangles of the filtered rings are the
    // rule's region all the same, a spike's tip enclosing nothing; but only where no
    // spike was dropped is it known that no input edges cross)
    let unsure = cx.hidden_unchecked;
    let refused = || {
        if unsure {
            Strict::Unsure
        } else {
            Strict::Checked
        }
    };
    let shared = cx.shared.len();
    if shared > cx.pool.len() / SHARED_MAX {
        return refused();
    }
    if pipeline::nest(cx, st, Nesting::Auto).is_err() {
        return refused();
    }
    if rule != FillRule::EvenOdd {
        // (a ring's nodes as loaded lie in the pool in input order: a live ring runs as
        // given where the numbers of three of them in a row increase round it, wrapping
        // once; nodes that split an edge where a vertex of another ring lies come after
        // every ring's)
        let (pool, loaded) = (&cx.pool, &cx.as_loaded);
        let given = |r: usize| {
            let ours = loaded[r].nodes();
            let mut nodes = (pool.ring(cx.rings[r].start)).filter(|n| ours.contains(&n.0));
            let (a, b, c) = (nodes.next()?, nodes.next()?, nodes.next()?);
            Some(usize::from(a.0 < b.0) + usize::from(b.0 < c.0) + usize::from(c.0 < a.0) == 2)
        };
        let mut runs = (0..cx.rings.len())
            .filter(|&r| cx.rings[r].alive)
            .map(given);
        let run = match runs.next().flatten() {
            Some(first) => runs.all(|g| g == Some(first)).then_some(first),
            None => None,
        };
        if !reads_as_nested(rule, run) {
            return refused();
        }
    }
    if seidel {
        // the checked rings as `Strategy::Seidel` takes valid input without a fill rule
        // (rings winding twice are strict mode's error, found where rings touch)
        let Some(counts) = checked_rings(cx, fs) else {
            return refused();
        };
        if !cx.shared.is_empty() && pipeline::join(cx, st).is_err() {
            return refused();
        }
        return match seidel_checked(fs, vertices, counts, out) {
            Ok(made) => Strict::Made(made),
            Err(_) => refused(),
        };
    }
    match lenient::finish_checked(cx, st, re, strategy, out) {
        Ok(made) => Strict::Made(made),
        Err(_) => refused(),
    }
}

/// [`strict_first`] leaves input to `resolve` where more than one node in this many lies
/// at a position shared with another (measured: the 254 counties of Texas as one input,
/// three in four nodes shared, take strict mode twice as long; earcut's fixtures of
/// touching rings, at most one node in eight shared, half as long).
const SHARED_MAX: usize = 4;

/// Whether a rule other than even–odd reads rings that run as `run` says (all as given,
/// all against it, or neither: `None`) as containment nests them (see [`strict_first`]).
fn reads_as_nested(rule: FillRule, run: Option<bool>) -> bool {
    matches!(
        (rule, run),
        (FillRule::NonZero, Some(_))
            | (FillRule::Positive, Some(true))
            | (FillRule::Negative, Some(false))
    )
}

/// [`report_unused`] where strict mode triangulated the input itself: every input vertex
/// no triangle uses, [`DropReason::Coincident`] where a vertex the triangles use has its
/// position, else [`DropReason::OffBoundary`] (straight, a spike's tip, a ring of no
/// area).
fn report_unused_input<T: Coord>(
    dropped: &mut Vec<Dropped>,
    fs: &mut Scratch,
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    out: &[[u32; 3]],
) {
    mark_used(&mut fs.used, vertices.len(), out);
    let used = &fs.used;
    let point = |i: usize| vertices[i].map(|c| c.to_f64() + 0.0);
    // the unused vertices' positions, once each, in an open-addressing table, marked
    // where a used vertex is (each used vertex looks its position up: most find an
    // empty slot at once)
    let unused = &mut fs.unused;
    unused.clear();
    let count = used.iter().filter(|&&u| !u).count();
    if count > 0 {
        let table = &mut fs.table;
        positions::reset_table(table, count);
        for i in (0..vertices.len()).filter(|&i| !used[i]) {
            let p = point(i);
            let slot = positions::slot(table, p, |k| unused[k as usize].0);
            if table[slot] == positions::EMPTY {
                table[slot] = unused.len() as u32;
                unused.push((p, false));
            }
        }
        for i in (0..vertices.len()).filter(|&i| used[i]) {
            let p = point(i);
            let k = table[positions::slot(table, p, |k| unused[k as usize].0)];
            if k != positions::EMPTY {
                unused[k as usize].1 = true;
            }
        }
    }
    let (unused, table) = (&*unused, &fs.table);
    list_unused(dropped, used, ring_starts, |i| {
        let k = table[positions::slot(table, point(i), |k| unused[k as usize].0)];
        if unused.get(k as usize).is_some_and(|u| u.1) {
            DropReason::Coincident
        } else {
            DropReason::OffBoundary
        }
    });
}

/// `Strategy::Seidel` without a fill rule, on input strict mode has checked (`load`,
/// `clean`, `nest`): takes the checked rings for the stage (`fs.ids`, `fs.starts`), with
/// the region on their left as `nest` turned them (outer boundaries counter-clockwise,
/// holes clockwise); returns the numbers of outer rings and holes. Nodes at one position
/// (`cx.shared`: rings touching, a vertex on an edge split there) name it by one vertex,
/// as the stage wants distinct positions; any number of edges may meet there. `None`
/// where two edges run between the same two positions (a collinear stretch walked both
/// ways): the stage takes no overlapping edges, so the caller resolves those rings as a
/// fill rule's.
pub(crate) fn checked_rings(cx: &Context, fs: &mut Scratch) -> Option<(usize, usize)> {
    let pool = &cx.pool;
    fs.canon.clear();
    fs.canon.resize(pool.len(), NO_VERTEX);
    let mut i = 0;
    while i < cx.shared.len() {
        let end = cx.same_position_end(i);
        let first = pool.get(cx.shared[i]).vertex;
        for &n in &cx.shared[i..end] {
            fs.canon[n.idx()] = first;
        }
        i = end;
    }
    fs.ids.clear();
    fs.starts.clear();
    fs.pairs.clear();
    let (mut polygons, mut holes) = (0, 0);
    for ring in cx.rings.iter().filter(|r| r.alive) {
        fs.starts.push(fs.ids.len());
        let mut prev = fs.canon[pool.prev(ring.start).idx()];
        for n in pool.ring(ring.start) {
            let c = fs.canon[n.idx()];
            fs.ids.push(if c == NO_VERTEX {
                pool.get(n).vertex
            } else {
                c
            });
            // only an edge between two shared positions can lie on another
            if c != NO_VERTEX && prev != NO_VERTEX {
                fs.pairs.push((c.min(prev), c.max(prev)));
            }
            prev = c;
        }
        if ring.depth % 2 == 1 {
            holes += 1;
        } else {
            polygons += 1;
        }
    }
    fs.pairs.sort_unstable();
    let overlap = fs.pairs.windows(2).any(|w| w[0] == w[1]);
    (!overlap).then_some((polygons, holes))
}

/// Triangulates the rings [`checked_rings`] took, counted as it returned them.
pub(crate) fn seidel_checked<T: Coord>(
    fs: &mut Scratch,
    vertices: &[[T; 2]],
    (polygons, holes): (usize, usize),
    out: &mut Vec<[u32; 3]>,
) -> Result<Outcome, Error> {
    fs.vertices.clear();
    fs.vertices
        .extend(vertices.iter().map(|v| [v[0].to_f64(), v[1].to_f64()]));
    seidel::triangulate(
        &mut fs.seidel,
        &fs.vertices,
        &fs.starts,
        &fs.ids,
        SEIDEL_SEED,
        out,
    )?;
    Ok(Outcome {
        polygons,
        holes,
        deviation: 0.0,
    })
}

/// No vertex: a node at a position no other node holds.
const NO_VERTEX: u32 = u32::MAX;

/// Outer rings (counter-clockwise) and holes (clockwise) among simple rings: the turn at
/// each ring's lowest-leftmost vertex, which is convex.
fn count_rings(points: &[[f64; 2]], starts: &[usize], ids: &[u32]) -> (usize, usize) {
    let (mut outer, mut holes) = (0, 0);
    for (k, &start) in starts.iter().enumerate() {
        let ring = &ids[start..starts.get(k + 1).copied().unwrap_or(ids.len())];
        let p = |i: usize| {
            let q = points[ring[i % ring.len()] as usize];
            Point::new(q[0], q[1])
        };
        let Some(m) = (0..ring.len()).min_by(|&i, &j| {
            let (a, b) = (p(i), p(j));
            (a.x, a.y)
                .partial_cmp(&(b.x, b.y))
                .unwrap_or(core::cmp::Ordering::Equal)
        }) else {
            continue;
        };
        match orient2d(p(m + ring.len() - 1), p(m), p(m + 1)) {
            Orientation::CounterClockwise => outer += 1,
            _ => holes += 1,
        }
    }
    (outer, holes)
}
