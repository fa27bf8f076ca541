//! Stage 5, *clip*: cut ears until every polygon is triangles.
//!
//! After bridging, each polygon is one counter-clockwise ring, weakly simple: bridges and
//! touching rings make it visit some positions more than once. An ear a → b → c (tip b) is
//! cut when b turns strictly left and no other vertex interferes with the triangle:
//!
//! - none lies strictly inside it, or inside the diagonal a–c;
//! - none sits on its boundary (at a corner, or inside edge a–b or b–c) with an edge
//!   running into the triangle.
//!
//! Only reflex vertices (including straight ones) need checking: if any vertex interferes,
//! a reflex one does (the interfering chain's extreme vertex towards b turns right). That is
//! the classic argument, and it holds at touching points because each extra occurrence of a
//! position is its own corner.
//!
//! `Strategy::Fast` walks the ring (paper §3.3): a tip that failed is marked "not an ear"
//! until a neighbour changes, and once at most one reflex vertex is left the rest is a fan
//! from it. After a cut the walk goes on past the new corner, as earcut does, unless the
//! node past it is marked: then it tries the corner first. `Strategy::Quality` always
//! cuts the ear with the smallest angle at its tip (Mei et al.), from a priority queue of
//! convex tips: a cut changes the angles of its two neighbours only, so only they are
//! queued again, and a tip gets its ear test when it comes up (most queued tips are
//! touched again before that, and skipped).
//!
//! A ring with no ear left is not a valid polygon (or this is a bug): strict mode reports an
//! internal error, lenient mode cuts a best-effort triangle and says so.

use crate::context::Context;
use crate::geom::{approx_angle_rank, bounds, interferes, near, orient2d, Orientation, Point};
use crate::structures::Cells;
use crate::structures::NodeId;
use crate::structures::Tips;
use crate::{Error, Strategy};

mod ear;
#[cfg(feature = "threads")]
mod marks;
#[cfg(feature = "threads")]
pub(crate) use marks::{Lent, MARK_AND_CUT_CHUNK, MARK_AND_CUT_MIN};
mod queue;
mod repair;

use queue::{ear, ear_node, EarQueue};

/// Polygons with fewer reflex vertices than this scan them all in an ear test; more, and
/// building the grid pays (earcut's threshold is 80 vertices in all).
const GRID_MIN_REFLEX: usize = 32;

/// The fast walk steps over marked tips one by one until it has taken this many steps per
/// node of the ring (plus `WALK_STEPS_MIN`); then it keeps the tips in `Scratch::tips`
/// and jumps over marked ones, to the same tip. Most rings never get there, and the
/// bookkeeping would cost them more than it saves; a ring whose ears all lie behind the
/// walk (a comb's spine, fanned from a corner: a lap per cut) gets there after a few laps.
const WALK_STEPS_PER_NODE: usize = 16;
const WALK_STEPS_MIN: usize = 256;

/// Reusable buffers of the clip stage.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// Reflex (or straight) nodes of the polygon being clipped. With the grid, entries go
    /// stale when a node turns convex or is cut (the grid forgets it, the list is not read
    /// again but to find the last reflex node); without it, such a node leaves the list at
    /// once, so that every entry an ear test scans is live.
    reflex: Vec<(NodeId, Point)>,
    /// The same nodes by grid cell, when there are many (see `GRID_MIN_REFLEX`).
    cells: Cells,
    /// Fast strategy: the ring's nodes by position, and the tips not marked "not an ear".
    tips: Tips,
    /// Quality strategy: candidate ears (convex tips) by angle at the tip (see [`ear`]).
    heap: EarQueue,
    /// Quality strategy, by node: its stamp when last queued; an entry popped is current
    /// only if the stamp has not moved since.
    queued: Vec<u32>,
    /// Quality strategy, by node: the reflex node that spoiled its last long ear test,
    /// looked at first next time (see `Clipper::is_ear_remembering`); any id, or none.
    spoiler: Vec<NodeId>,
    /// Rings still to clip: pieces of a polygon split by a diagonal (lenient fallback).
    pending: Vec<NodeId>,
    /// Scratch of [`lay_out`]: new node ids by old, the polygons' starts, the node buffer.
    renamed: Vec<u32>,
    starts: Vec<NodeId>,
    spare: Vec<crate::structures::Node>,
    /// Edge tests the lenient split search may still spend in this `clip` call. One budget
    /// for the whole call, not one per split: on garbage input every stuck piece tries a
    /// split, and a per-split budget multiplied by the number of pieces is unbounded in
    /// practice (seconds on a hundred vertices).
    split_budget: usize,
    /// The threads of mark-and-cut, for the fast strategy on a large polygon (see
    /// [`marks`]); `None` clips on the caller's thread.
    #[cfg(feature = "threads")]
    pub threads: Option<Lent>,
    /// Mark-and-cut's marks, one buffer per chunk of the ring.
    #[cfg(feature = "threads")]
    marks: Vec<marks::Marks>,
    /// Mark-and-cut's log of the last call: `[first, end, thread, round]` per chunk that
    /// cut triangles `first..end` of the output.
    #[cfg(feature = "threads")]
    log: Vec<[u32; 4]>,
}

#[cfg(feature = "threads")]
impl Scratch {
    /// Which thread marked which triangles in the last call (see `Scratch::log`).
    pub fn log(&self) -> &[[u32; 4]] {
        &self.log
    }
}

/// One polygon being clipped.
struct Clipper<'a> {
    cx: &'a mut Context,
    s: &'a mut Scratch,
    out: &'a mut Vec<[u32; 3]>,
    /// Live nodes left.
    len: usize,
    /// Live reflex nodes left.
    reflex_count: usize,
    /// The fan shortcut failed once (a degenerate ring): don't try again.
    no_fan: bool,
    /// Ear tests ask `Scratch::cells` for candidates rather than scanning `Scratch::reflex`.
    indexed: bool,
    /// Lenient mode with crossing edges: ears using a crossed edge wait until nothing else
    /// can be cut, so that overlaps stay where the input crosses itself.
    avoid_crossed: bool,
    /// The fast walk jumps: `Scratch::tips` holds the ring, and every tip whose mark is
    /// cleared must go in (marked ones drop out when the walk comes across them).
    walking: bool,
}

/// A quality ear test that looked at more candidates than this before one spoiled the
/// ear keeps that one, to look at first next time (see `Clipper::is_ear_remembering`).
const SPOILER_AFTER: usize = 16;

/// Edge tests the lenient split search may spend per `clip` call (see
/// `Scratch::split_budget`): a few milliseconds.
const SPLIT_BUDGET: usize = 1 << 22;

/// Clips every polygon; returns how many there were.
/// With `avoid_crossed`, ears at edges flagged as crossing wait until nothing else can be
/// cut (lenient mode only).
pub(crate) fn clip(
    cx: &mut Context,
    s: &mut Scratch,
    strategy: Strategy,
    avoid_crossed: bool,
    out: &mut Vec<[u32; 3]>,
) -> Result<usize, Error> {
    let mut polygons = 0;
    s.split_budget = SPLIT_BUDGET;
    #[cfg(feature = "threads")]
    s.log.clear();
    // (mark-and-cut needs the layout: its chunks are ranges of ids)
    #[cfg(feature = "threads")]
    let lay_out_min = (s.threads.as_ref()).map_or(LAY_OUT_MIN, |t| t.min.min(LAY_OUT_MIN));
    #[cfg(not(feature = "threads"))]
    let lay_out_min = LAY_OUT_MIN;
    if strategy == Strategy::Fast && cx.pool.len() >= lay_out_min {
        lay_out(cx, s);
    }
    for r in 0..cx.rings.len() {
        let ring = cx.rings[r];
        if !ring.alive || !ring.merged || ring.component != r as u32 {
            continue;
        }
        polygons += 1;
        s.pending.clear();
        s.pending.push(ring.start);
        while let Some(start) = s.pending.pop() {
            let (mut clipper, start) = Clipper::new(cx, s, out, start, avoid_crossed);
            match strategy {
                // (Seidel never comes here: the triangulator gives it its own stage)
                Strategy::Fast | Strategy::Seidel => {
                    #[cfg(feature = "threads")]
                    let start = clipper.mark_and_cut(start);
                    clipper.fast(start)?
                }
                Strategy::Quality => clipper.quality(start)?,
            }
        }
    }
    Ok(polygons)
}

/// From this many nodes on, the fast strategy first lays the pool out in ring order: its
/// walk laps the ring several times, and in a pool larger than the caches each step to a
/// node elsewhere in memory waits for it. (The quality strategy breaks ties between equal
/// angles by node id, so its nodes stay where they are.)
const LAY_OUT_MIN: usize = 1 << 14;

/// Renumbers the nodes so that each polygon's ring runs through consecutive ids (see
/// [`crate::structures::Pool::lay_out`]), and the ring table with them.
fn lay_out(cx: &mut Context, clip: &mut Scratch) {
    clip.starts.clear();
    clip.starts.extend(
        (cx.rings.iter().enumerate())
            .filter(|&(r, ring)| ring.alive && ring.merged && ring.component == r as u32)
            .map(|(_, ring)| ring.start),
    );
    cx.pool
        .lay_out(&mut clip.starts, &mut clip.renamed, &mut clip.spare);
    let renamed = &clip.renamed;
    for ring in &mut cx.rings {
        for n in [&mut ring.start, &mut ring.rightmost] {
            if let Some(&id) = renamed.get(n.idx()) {
                *n = NodeId(id);
            }
        }
    }
}

impl<'a> Clipper<'a> {
    /// Collapses zero-width walls, classifies the ring through `start` and lists its
    /// reflex nodes. Returns the clipper and a live node to start from.
    fn new(
        cx: &'a mut Context,
        s: &'a mut Scratch,
        out: &'a mut Vec<[u32; 3]>,
        start: NodeId,
        avoid_crossed: bool,
    ) -> (Self, NodeId) {
        // Walls and repeats come only from bridging and joining touching rings: the
        // classifying walk looks for them on the way, and only a ring that has some is
        // tidied (and walked again).
        // (from the node `remove_walls` ends a lap at when it removes nothing)
        let mut from = cx.pool.prev(start);
        let (mut len, walls) = classify(cx, s, from);
        if walls {
            from = remove_walls(cx, start);
            (len, _) = classify(cx, s, from);
        }
        let start = from;
        let reflex_count = s.reflex.len();
        let indexed = reflex_count >= GRID_MIN_REFLEX;
        if indexed {
            s.cells.build(&s.reflex, cx.pool.len());
        }
        (
            Clipper {
                cx,
                s,
                out,
                len,
                reflex_count,
                no_fan: false,
                indexed,
                avoid_crossed,
                walking: false,
            },
            start,
        )
    }

    /// The paper's high-performance walk.
    fn fast(&mut self, start: NodeId) -> Result<(), Error> {
        // the walk ends a lap at `stop`, so it must be on the ring: the quality strategy
        // hands over to this walk after a repair, which may have removed its node
        let mut ear = self.live(start);
        let mut stop = ear;
        let mut rescanned = false;
        // marked tips the walk may step over one by one before it starts `Scratch::tips`
        let steps_allowed = WALK_STEPS_PER_NODE * self.len + WALK_STEPS_MIN;
        let mut steps = 0;
        while self.len > 3 {
            if self.reflex_count <= 1 && !self.no_fan && self.try_fan(ear) {
                return Ok(());
            }
            if !self.cx.pool.get(ear).not_ear {
                if self.is_ear(ear) {
                    let next = self.cx.pool.next(ear);
                    ear = self.cut(ear);
                    ear = if self.cx.pool.get(next).removed {
                        ear
                    } else {
                        self.past_new_corner(next)
                    };
                    // `cut` may have tidied away both neighbours: the walk must start, and
                    // stop, at a live node or it never comes round to `stop`
                    ear = self.live(ear);
                    stop = ear;
                    rescanned = false;
                    continue;
                }
                self.cx.pool.get_mut(ear).not_ear = true;
            }
            // On to the next tip not marked "not an ear": until a cut, nothing the loop
            // looks at changes, so marked tips need no more than a step.
            if self.walking {
                ear = self.step(ear, stop);
            } else {
                let pool = &self.cx.pool;
                ear = pool.next(ear);
                while ear != stop && pool.get(ear).not_ear {
                    ear = pool.next(ear);
                    // at most `len` a step, and the count stops once it is over
                    steps += 1;
                }
                if steps > steps_allowed {
                    self.start_walk(ear);
                }
            }
            if ear == stop {
                if !rescanned && self.may_rescan() {
                    // A lap without an ear. "Not an ear" holds until a neighbour changes,
                    // but a cut elsewhere can turn a reflex vertex inside a marked tip's
                    // triangle convex, or (where positions repeat) change a tip that is no
                    // neighbour: clear the marks and look once more, at most once per cut.
                    rescanned = true;
                    self.clear_not_ear(ear);
                    continue;
                }
                ear = self.stuck(ear)?;
                ear = self.live(ear);
                stop = ear;
            }
        }
        self.finish(ear)?;
        Ok(())
    }

    /// Where the walk goes on after a cut whose new corner (the ear's successor) is
    /// `corner`, a live node. Past it, as earcut does: cutting at the corner next would fan
    /// from the ear's predecessor. But where the node past it is marked, the walk would only
    /// step over marked tips (on a ring of round holes, a whole lap per cut), so it tries
    /// the corner first. On crossing (lenient) input the walk keeps earcut's order, which
    /// its repairs were tuned against.
    fn past_new_corner(&self, corner: NodeId) -> NodeId {
        let pool = &self.cx.pool;
        let after = pool.next(corner);
        if pool.get(after).not_ear && !self.crossing_input() {
            corner
        } else {
            after
        }
    }

    /// Whether a lap without an ear may look once more. Not for crossing (lenient) input:
    /// there the repairs of [`Clipper::stuck`] decide, as tuned against earcut's bounds.
    fn may_rescan(&self) -> bool {
        !self.crossing_input()
    }

    /// Lenient mode on input with crossing edges, whose repairs keep earcut's walk.
    fn crossing_input(&self) -> bool {
        self.cx.lenient && !self.cx.crossings.is_empty()
    }

    /// Clears the "not an ear" marks of the ring through `start`.
    fn clear_not_ear(&mut self, start: NodeId) {
        let mut n = start;
        for _ in 0..self.len {
            self.cx.pool.get_mut(n).not_ear = false;
            n = self.cx.pool.next(n);
        }
        if self.walking {
            let (pool, tips) = (&self.cx.pool, &mut self.s.tips);
            tips.fill(|n| !pool.get(n).removed);
        }
    }

    /// Hands out ring positions from `start` (live) on, for [`Clipper::step`]; from now on
    /// the walk jumps. Out of line, as rare.
    #[cold]
    #[inline(never)]
    fn start_walk(&mut self, start: NodeId) {
        let (pool, tips) = (&self.cx.pool, &mut self.s.tips);
        tips.clear(pool.len());
        let mut n = start;
        for _ in 0..self.len {
            tips.push(n);
            n = pool.next(n);
        }
        tips.fill(|n| !pool.get(n).not_ear);
        self.walking = true;
    }

    /// The walk's next tip after `ear`: the first live node after it not marked "not an
    /// ear", or `stop` (live) if that comes first.
    ///
    /// `Scratch::tips` holds every such node, and maybe some that were marked or removed
    /// since they went in: those are dropped here, when the walk comes across them.
    #[inline(never)]
    fn step(&mut self, ear: NodeId, stop: NodeId) -> NodeId {
        let (pool, tips) = (&self.cx.pool, &mut self.s.tips);
        let (Some(e), Some(s)) = (tips.position(ear), tips.position(stop)) else {
            return stop;
        };
        // steps from `e` to position `p` along the ring, 1 to len (a whole lap to itself)
        let len = tips.len();
        let steps = |p: usize| if p > e { p - e } else { p + len - e };
        let mut tip = stop;
        // each round drops a member, so this ends
        while let Some(m) = tips.next_after(e) {
            if steps(m) >= steps(s) {
                break;
            }
            let node = pool.get(tips.node(m));
            if !node.removed && !node.not_ear {
                tip = tips.node(m);
                break;
            }
            tips.remove(tips.node(m));
        }
        debug_assert_eq!(
            tip,
            self.step_by_step(ear, stop),
            "the walk jumped elsewhere"
        );
        tip
    }

    /// [`Clipper::step`] the slow way, to check it.
    fn step_by_step(&self, mut ear: NodeId, stop: NodeId) -> NodeId {
        let pool = &self.cx.pool;
        ear = pool.next(ear);
        while ear != stop && pool.get(ear).not_ear {
            ear = pool.next(ear);
        }
        ear
    }

    /// Mei et al.: always the ear with the smallest angle at its tip.
    fn quality(&mut self, start: NodeId) -> Result<(), Error> {
        let nodes = self.cx.pool.len();
        self.s.heap.clear(nodes);
        if self.s.queued.len() < nodes {
            self.s.queued.resize(nodes, 0);
            self.s.spoiler.resize(nodes, NodeId(u32::MAX));
        }
        self.seed_heap(start);
        let mut last = start;
        let mut rescanned = false;
        while self.len > 3 {
            let Some(item) = self.s.heap.pop() else {
                if self.avoid_crossed {
                    // only ears at crossed edges are left: allow them, look again
                    self.avoid_crossed = false;
                    self.seed_heap(last);
                    continue;
                }
                // No ear queued. Where positions repeat (weakly simple rings), cutting an
                // ear can make an ear of a node that is no neighbour of it, so look once
                // more over the whole ring, at most once per cut.
                if !rescanned && self.may_rescan() {
                    rescanned = true;
                    self.seed_heap(last);
                    continue;
                }
                // Still none: invalid input (or a bug). Re-seeding the queue after every
                // repair would cost a full scan each time; the walk finishes such rings.
                last = self.stuck(last)?;
                return self.fast(last);
            };
            // A candidate is tested when it comes up, not when queued: a tip that was no
            // ear when queued may have become one. One touched since and not queued again
            // (it turned reflex, say) is skipped.
            let n = NodeId(ear_node(item) as u32);
            let node = self.cx.pool.get(n);
            let current = self.s.queued.get(n.idx()) == Some(&node.stamp);
            if node.removed || !current || !self.is_ear_remembering(n) {
                continue;
            }
            let prev = self.cx.pool.prev(n);
            last = self.cut(n);
            rescanned = false;
            for m in [prev, last] {
                let node = self.cx.pool.get(m);
                if !node.removed {
                    self.push_if_convex(m);
                }
            }
            // `cut` may have tidied away both neighbours of the ear
            last = self.live(if self.cx.pool.get(last).removed {
                prev
            } else {
                last
            });
        }
        self.finish(last)?;
        Ok(())
    }

    /// Queues every convex tip of the ring through `start`.
    fn seed_heap(&mut self, start: NodeId) {
        let mut n = start;
        for _ in 0..self.len {
            self.push_if_convex(n);
            n = self.cx.pool.next(n);
        }
    }

    /// Queues `n` by its tip angle when it is convex (the ear test waits until it comes up).
    fn push_if_convex(&mut self, n: NodeId) {
        if self.cx.pool.get(n).reflex {
            return;
        }
        let (a, b, c) = self.corner(n);
        let stamp = self.cx.pool.get(n).stamp;
        if let Some(queued) = self.s.queued.get_mut(n.idx()) {
            *queued = stamp;
            self.s.heap.set(ear(approx_angle_rank(a, b, c), n));
        }
    }

    /// Positions of `n`'s predecessor, `n` and its successor.
    fn corner(&self, n: NodeId) -> (Point, Point, Point) {
        let pool = &self.cx.pool;
        (pool.p(pool.prev(n)), pool.p(n), pool.p(pool.next(n)))
    }

    /// The neighbours of `ear` when its tip may be cut, before looking for reflex nodes in
    /// the way: `None` when it turns right or straight (`reflex`, the exact turn, kept up
    /// to date by `reclassify`) or uses a crossed edge that is to wait.
    #[inline(always)]
    fn may_be_ear(&self, ear: NodeId) -> Option<(NodeId, NodeId)> {
        let pool = &self.cx.pool;
        let (an, cn) = (pool.prev(ear), pool.next(ear));
        let waits = self.avoid_crossed && (pool.get(an).crossed || pool.get(ear).crossed);
        (!pool.get(ear).reflex && !waits).then_some((an, cn))
    }

    /// Whether a → b → c, with b = `ear`, can be cut (see the module docs). Out of line,
    /// so that `interferes` stays inlined in it (measured: the other way round is slower).
    #[inline(never)]
    fn is_ear(&self, ear: NodeId) -> bool {
        self.ear_test(ear, || {})
    }

    /// [`Clipper::is_ear`], calling `looked` for every reflex node it looks at.
    #[inline(always)]
    fn ear_test(&self, ear: NodeId, mut looked: impl FnMut()) -> bool {
        let Some((an, cn)) = self.may_be_ear(ear) else {
            return false;
        };
        let pool = &self.cx.pool;
        let (a, b, c) = (pool.p(an), pool.p(ear), pool.p(cn));
        !self.any_reflex_near(a, b, c, |r, q| {
            looked();
            r != an && r != ear && r != cn && interferes(q, around(pool, r), a, b, c)
        })
    }

    /// [`Clipper::is_ear`], for the quality strategy: the node that spoiled this tip's last
    /// long test usually still does, and is looked at first. Quality tests a tip again
    /// whenever a neighbour moves, and its sharpest tips may be large triangles whose boxes
    /// hold thousands of reflex nodes before the first that spoils them (a square's corner
    /// over a ring of holes: 300 a test on average, where fast's tests see one). Only the
    /// order of the search changes, not its answer.
    #[inline(never)]
    fn is_ear_remembering(&mut self, ear: NodeId) -> bool {
        if !self.indexed {
            // few reflex nodes: every test is short
            return self.is_ear(ear);
        }
        let Some((an, cn)) = self.may_be_ear(ear) else {
            return false;
        };
        let pool = &self.cx.pool;
        let (a, b, c) = (pool.p(an), pool.p(ear), pool.p(cn));
        let spoils = |r: NodeId, q: Point| {
            r != an && r != ear && r != cn && interferes(q, around(pool, r), a, b, c)
        };
        let last = self.s.spoiler.get(ear.idx()).copied();
        if let Some(r) = last.filter(|r| r.idx() < pool.len()) {
            let (node, (lo, hi)) = (pool.get(r), bounds(a, b, c));
            if !node.removed && node.reflex && near(lo, hi, node.p) && spoils(r, node.p) {
                return false;
            }
        }
        let (mut looked, mut spoiler) = (0, None);
        let spoilt = self.any_reflex_near(a, b, c, |r, q| {
            looked += 1;
            let spoilt = spoils(r, q);
            if spoilt {
                spoiler = Some(r);
            }
            spoilt
        });
        // (kept where the search was long: storing costs more than it saves otherwise)
        if looked > SPOILER_AFTER {
            if let (Some(r), Some(slot)) = (spoiler, self.s.spoiler.get_mut(ear.idx())) {
                *slot = r;
            }
        }
        !spoilt
    }

    /// Whether `test` holds for a live reflex node (id and position) in the bounding box of
    /// a, b, c.
    fn any_reflex_near(
        &self,
        a: Point,
        b: Point,
        c: Point,
        mut test: impl FnMut(NodeId, Point) -> bool,
    ) -> bool {
        let pool = &self.cx.pool;
        let (lo, hi) = bounds(a, b, c);
        let near = |q: Point| near(lo, hi, q);
        let live = |r: NodeId| {
            let node = pool.get(r);
            !node.removed && node.reflex
        };
        if self.indexed {
            let cells = &self.s.cells;
            // the grid's own entries are live reflex nodes (it forgets the others), so
            // only nodes added after building need looking up
            cells.any_in_triangle([a, b, c], lo, hi, |r, q| {
                debug_assert!(!pool.get(r).removed && pool.get(r).reflex);
                test(r, q)
            }) || cells.extra().iter().any(|&r| {
                let q = pool.p(r);
                near(q) && live(r) && test(r, q)
            })
        } else {
            // positions are listed with the nodes: most fail the box test without a look
            // at the node (every entry is live: see `Scratch::reflex`)
            (self.s.reflex.iter()).any(|&(r, q)| {
                near(q) && {
                    debug_assert!(live(r), "a stale reflex entry");
                    test(r, q)
                }
            })
        }
    }

    /// Cuts the ear at `ear`, tidies its neighbours; returns the successor.
    fn cut(&mut self, ear: NodeId) -> NodeId {
        let pool = &self.cx.pool;
        let (a, c) = (pool.prev(ear), pool.next(ear));
        self.emit(a, ear, c);
        self.unlink(ear);
        // Usually neither neighbour repeats a position next to it: then tidying them only
        // reclassifies both, and their two turns are computed side by side (independent
        // chains of arithmetic, which the processor overlaps).
        let pool = &self.cx.pool;
        let (pp, pa, pc, pn) = (
            pool.p(pool.prev(a)),
            pool.p(a),
            pool.p(c),
            pool.p(pool.next(c)),
        );
        if self.len > 2 && pa != pc && pp != pc && pc != pn && pa != pn {
            let (ta, tc) = (orient2d(pp, pa, pc), orient2d(pa, pc, pn));
            self.set_reflex(a, ta != Orientation::CounterClockwise);
            self.set_reflex(c, tc != Orientation::CounterClockwise);
        } else {
            self.tidy(a);
            self.tidy(c);
        }
        if self.cx.pool.get(c).removed {
            self.cx.pool.next(a)
        } else {
            c
        }
    }

    /// `n` if it is live, else the first live node its links lead to: a removed node keeps
    /// the links it had when it was unlinked, to nodes that were live then, so following
    /// them reaches the ring (bounded by the pool size, in case nothing is left).
    fn live(&self, mut n: NodeId) -> NodeId {
        let pool = &self.cx.pool;
        for _ in 0..pool.len() {
            if !pool.get(n).removed {
                break;
            }
            n = pool.next(n);
        }
        n
    }

    /// Writes the triangle a, b, c.
    fn emit(&mut self, a: NodeId, b: NodeId, c: NodeId) {
        let pool = &self.cx.pool;
        self.out
            .push([pool.get(a).vertex, pool.get(b).vertex, pool.get(c).vertex]);
    }

    /// Unlinks `n`, keeping the counts.
    #[inline(always)]
    fn unlink(&mut self, n: NodeId) {
        if self.cx.pool.get(n).reflex {
            self.reflex_count -= 1;
            self.unindex(n);
        }
        self.cx.pool.remove(n);
        self.len -= 1;
        if self.walking {
            self.unlink_tip(n);
        }
    }

    /// `Scratch::tips` after unlinking `n`, which cleared its neighbours' marks. Out of
    /// line: most rings never start the walk's bookkeeping, and `unlink` is hot.
    #[cold]
    #[inline(never)]
    fn unlink_tip(&mut self, n: NodeId) {
        let pool = &self.cx.pool;
        let (prev, next) = (pool.prev(n), pool.next(n));
        let tips = &mut self.s.tips;
        tips.insert(prev);
        tips.insert(next);
    }

    /// After a neighbour was cut: drop `n` if it repeats its successor's position or is the
    /// tip of a zero-width wall whose both sides are done, then reclassify what is left.
    fn tidy(&mut self, mut n: NodeId) {
        let mut dropped = false;
        while self.len > 2 && !self.cx.pool.get(n).removed {
            let (prev, next) = (self.cx.pool.prev(n), self.cx.pool.next(n));
            let (pp, pn, px) = (
                self.cx.pool.p(prev),
                self.cx.pool.p(n),
                self.cx.pool.p(next),
            );
            if pn == px {
                // same position, same vertex index (clean made it so)
                self.unlink(next);
            } else if pp == px {
                // a wall: out to n and straight back
                self.unlink(n);
                n = prev;
            } else if dropped {
                break;
            } else {
                // only n's own turn changed (its neighbour on the cut side is new); the
                // other neighbour of the cut is tidied separately
                self.set_reflex(n, orient2d(pp, pn, px) != Orientation::CounterClockwise);
                return;
            }
            dropped = true;
        }
        if !dropped {
            self.reclassify(n);
            return;
        }
        for m in [self.cx.pool.prev(n), n, self.cx.pool.next(n)] {
            self.reclassify(m);
        }
    }

    /// Updates whether `n` is reflex.
    fn reclassify(&mut self, n: NodeId) {
        if !self.cx.pool.get(n).removed {
            let reflex = turn(self.cx, n) != Orientation::CounterClockwise;
            self.set_reflex(n, reflex);
        }
    }

    /// Records whether live node `n` is reflex, keeping the counts and the index.
    #[inline(always)]
    fn set_reflex(&mut self, n: NodeId, reflex: bool) {
        let node = self.cx.pool.get_mut(n);
        // a reflex tip is no ear (the fast walk steps over it); a convex one was just
        // touched, which cleared the mark
        node.not_ear |= reflex;
        if node.reflex != reflex {
            node.reflex = reflex;
            if reflex {
                // only possible around removed walls: list it again
                self.reflex_count += 1;
                let p = self.cx.pool.p(n);
                self.s.reflex.push((n, p));
                if self.indexed {
                    self.s.cells.add(n);
                }
            } else {
                self.reflex_count -= 1;
                self.unindex(n);
            }
        }
    }

    /// Takes a node that is no longer reflex (or no longer linked) out of the grid, or out
    /// of the list the ear tests scan without one (a few dozen entries at most: finding
    /// and removing it costs less than scanning past it in every later test).
    fn unindex(&mut self, n: NodeId) {
        if self.indexed {
            self.s.cells.remove(n);
        } else if let Some(at) = self.s.reflex.iter().position(|&(r, _)| r == n) {
            self.s.reflex.remove(at);
        }
    }

    /// With at most one reflex vertex left, the polygon is star-shaped from it: fan. Every
    /// fan triangle is checked to turn left first; if one does not, nothing is written.
    fn try_fan(&mut self, any: NodeId) -> bool {
        let pool = &self.cx.pool;
        let center = if self.reflex_count == 1 {
            match self.s.reflex.iter().map(|&(r, _)| r).find(|&r| {
                let node = pool.get(r);
                !node.removed && node.reflex
            }) {
                Some(r) => r,
                None => return false,
            }
        } else {
            any
        };
        let pc = pool.p(center);
        let mut v = pool.next(center);
        while pool.next(v) != center {
            if orient2d(pc, pool.p(v), pool.p(pool.next(v))) != Orientation::CounterClockwise {
                self.no_fan = true;
                return false;
            }
            v = pool.next(v);
        }
        let mut v = self.cx.pool.next(center);
        while self.cx.pool.next(v) != center {
            let w = self.cx.pool.next(v);
            self.emit(center, v, w);
            v = w;
        }
        true
    }

    /// The last triangle, when it has area. A clockwise one is a lobe winding against the
    /// rest of its ring: strict mode refuses it, lenient mode drops it.
    fn finish(&mut self, n: NodeId) -> Result<(), Error> {
        if self.len == 3 && !self.cx.pool.get(n).removed {
            let (a, c) = (self.cx.pool.prev(n), self.cx.pool.next(n));
            match orient2d(self.cx.pool.p(a), self.cx.pool.p(n), self.cx.pool.p(c)) {
                Orientation::CounterClockwise => self.emit(a, n, c),
                Orientation::Clockwise if !self.cx.lenient => {
                    return Err(self.winds_opposite(n));
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// The error for a piece around `n` that turns clockwise (strict mode).
    fn winds_opposite(&self, n: NodeId) -> Error {
        let node = self.cx.pool.get(n);
        Error::LobesWindOpposite {
            ring: self.cx.rings[node.ring as usize].input as usize,
            vertex: node.vertex as usize,
        }
    }
}

/// Marks every node of the ring through `start` reflex or not (and reflex ones "not an
/// ear") and lists the reflex ones in `s.reflex`; returns the ring's length and whether
/// [`remove_walls`] would remove anything (a repeated position or a wall's tip). One pass
/// with the three positions of each turn carried along.
fn classify(cx: &mut Context, s: &mut Scratch, start: NodeId) -> (usize, bool) {
    s.reflex.clear();
    let pool = &mut cx.pool;
    let (mut len, mut walls) = (0, false);
    let mut n = start;
    let (mut pp, mut pn) = (pool.p(pool.prev(n)), pool.p(n));
    loop {
        let next = pool.next(n);
        let px = pool.p(next);
        walls |= pn == px || pp == px;
        let reflex = orient2d(pp, pn, px) != Orientation::CounterClockwise;
        let node = pool.get_mut(n);
        node.reflex = reflex;
        // a reflex tip is no ear: the walk steps over it at once
        node.not_ear = reflex;
        if reflex {
            s.reflex.push((n, pn));
        }
        len += 1;
        (pp, pn, n) = (pn, px, next);
        if n == start {
            return (len, walls);
        }
    }
}

/// Removes repeated positions and the tips of zero-width walls (out and straight back,
/// left where a hole cancels a lobe of its polygon) from the ring through `start`; returns
/// a live node. Both kinds enclose no area and no triangle uses them.
fn remove_walls(cx: &mut Context, start: NodeId) -> NodeId {
    let pool = &mut cx.pool;
    let mut n = start;
    let mut stop = pool.prev(n);
    loop {
        let (prev, next) = (pool.prev(n), pool.next(n));
        if next == n || prev == next {
            return n; // fewer than three nodes: nothing to clip
        }
        if pool.p(n) == pool.p(next) {
            pool.remove(next);
            stop = prev;
        } else if pool.p(prev) == pool.p(next) {
            pool.remove(n);
            n = prev;
            stop = pool.prev(prev);
        } else if n == stop {
            return n;
        } else {
            n = next;
        }
    }
}

/// The positions of node `r`'s neighbours, as [`interferes`] asks for them.
fn around(pool: &crate::structures::Pool, r: NodeId) -> impl Fn() -> [Point; 2] + '_ {
    move || [pool.p(pool.prev(r)), pool.p(pool.next(r))]
}

/// The turn prev(n) → n → next(n).
fn turn(cx: &Context, n: NodeId) -> Orientation {
    let pool = &cx.pool;
    orient2d(pool.p(pool.prev(n)), pool.p(n), pool.p(pool.next(n)))
}
