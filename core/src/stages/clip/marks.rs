//! Mark-and-cut (Eder, Held & Palfrader 2018): the fast strategy's ear clipping of one
//! large polygon on several threads, without locks or atomics.
//!
//! A round has two phases. **Mark**, in parallel and read-only: the ring, whose nodes run
//! through consecutive ids (the clip stage laid the pool out in ring order), is cut into
//! chunks of [`MARK_AND_CUT_CHUNK`] ids; a task walks its chunk and tests every tip not
//! marked "not an ear", skipping the successor of a tip it just marked, so that no two
//! marked ears share an edge. **Cut**, on the caller's thread: the failed tips are marked
//! "not an ear", then the marked ears are cut in ring order, each only if its neighbours
//! are still the ones its test saw (an ear at a chunk's start whose predecessor was cut at
//! the previous chunk's end waits for the next round). Ears whose tips are not adjacent
//! do not overlap, so each cut leaves the others ears. Marking is the ear tests, the
//! larger part where they are costly; cutting is a few pointer updates and the reflex
//! grid's bookkeeping.
//!
//! Rounds go on while they cut at least one ear per [`FEW`] nodes left and their ear tests
//! are costly (see [`LOOKED_MIN`]); then the sequential walk finishes (as the paper does),
//! so a polygon whose ears appear one at a time (a spiral, a comb's spine) costs a round
//! or two more, never a round per ear. Both counts are of the work, not of time: the
//! rounds run, and the triangles come out, the same way on every machine.
//!
//! Chunks are fixed by id, not by thread count, and cut in order: the triangles are the
//! same for every number of threads.

use crate::structures::NodeId;

use super::Clipper;

/// Ids per chunk of the ring, one task each (unless [`Lent::chunk`] says otherwise).
pub(crate) const MARK_AND_CUT_CHUNK: usize = 1 << 12;

/// Rings with fewer nodes clip on the caller's thread (unless [`Lent::min`] says
/// otherwise): below it the rounds cost as much as the walk, or more (see
/// `docs/performance.md`, "Threads").
pub(crate) const MARK_AND_CUT_MIN: usize = 1 << 18;

/// Threads lent to the clip stage for mark-and-cut, the ring size from which it runs and
/// the ids per chunk.
#[derive(Clone, Debug)]
pub(crate) struct Lent {
    pub pool: std::sync::Arc<rayon::ThreadPool>,
    pub min: usize,
    pub chunk: usize,
}

/// A round that cuts fewer than one ear per this many nodes ends mark-and-cut.
const FEW: usize = 4;

/// A round whose ear tests looked at fewer reflex nodes than this on average ends
/// mark-and-cut: such tests are too cheap to gain from threads, and the walk, which cuts
/// where it just cut, keeps the memory it works on in cache (round holes and combs look
/// at one or two, random polygons at 15 to 30, stars at hundreds).
const LOOKED_MIN: usize = 8;

/// One chunk's marks: ears to cut (predecessor, tip, successor as tested), tips that
/// failed their test, how many tests looked at how many reflex nodes, and the pool thread
/// that marked them.
#[derive(Debug, Default)]
pub(super) struct Marks {
    ears: Vec<[NodeId; 3]>,
    failed: Vec<NodeId>,
    tests: usize,
    looked: usize,
    thread: u32,
}

impl Clipper<'_> {
    /// Rounds of mark-and-cut on the ring through `start` while they pay, when the clip
    /// stage has threads and the ring is large; returns a live node, where the sequential
    /// walk takes over.
    pub(super) fn mark_and_cut(&mut self, start: NodeId) -> NodeId {
        let Some(Lent {
            pool: threads,
            min,
            chunk,
        }) = self.s.threads.clone()
        else {
            return start;
        };
        if self.len < min || self.avoid_crossed || self.crossing_input() {
            return start;
        }
        let Some((lo, hi)) = self.id_range(start) else {
            return start;
        };
        let mut marks = core::mem::take(&mut self.s.marks);
        let chunks = (hi - lo).div_ceil(chunk);
        if marks.len() < chunks {
            marks.resize_with(chunks, Marks::default);
        }
        let mut round = 0;
        while self.len >= min && self.reflex_count > 1 {
            let me = &*self;
            threads.install(|| {
                use rayon::prelude::*;
                marks[..chunks]
                    .par_iter_mut()
                    .enumerate()
                    .for_each(|(k, m)| {
                        let from = lo + k * chunk;
                        me.mark(from, (from + chunk).min(hi), m);
                    });
            });
            let before = self.len;
            self.cut_marked(&marks[..chunks], round);
            round += 1;
            let tests: usize = marks[..chunks].iter().map(|m| m.tests).sum();
            let looked: usize = marks[..chunks].iter().map(|m| m.looked).sum();
            if (before - self.len) * FEW < before || looked < LOOKED_MIN * tests {
                break;
            }
        }
        self.s.marks = marks;
        self.live(start)
    }

    /// The ids `lo..hi` of the ring through `start` when its nodes run through them in ring
    /// order (wrapping once from its largest id to its smallest) and every live node there
    /// is on the ring; else `None`, and the ring is clipped sequentially.
    fn id_range(&self, start: NodeId) -> Option<(usize, usize)> {
        let pool = &self.cx.pool;
        let (mut lo, mut hi, mut descents) = (start.idx(), start.idx(), 0);
        let mut n = start;
        for _ in 0..self.len {
            let next = pool.next(n);
            descents += usize::from(next.idx() <= n.idx());
            (lo, hi) = (lo.min(next.idx()), hi.max(next.idx()));
            n = next;
        }
        let live = (lo..=hi)
            .filter(|&i| !pool.get(NodeId(i as u32)).removed)
            .count();
        (n == start && descents == 1 && live == self.len).then_some((lo, hi + 1))
    }

    /// The mark phase on the ids `from..to` (read-only: runs on any thread).
    fn mark(&self, from: usize, to: usize, m: &mut Marks) {
        m.ears.clear();
        m.failed.clear();
        (m.tests, m.looked) = (0, 0);
        m.thread = rayon::current_thread_index().unwrap_or(0) as u32;
        let pool = &self.cx.pool;
        let mut last = NodeId(u32::MAX);
        for i in from..to {
            let b = NodeId(i as u32);
            let node = pool.get(b);
            // (reflex tips are always marked "not an ear")
            if node.removed || node.not_ear || node.prev == last {
                continue;
            }
            m.tests += 1;
            if self.ear_test(b, || m.looked += 1) {
                m.ears.push([node.prev, b, node.next]);
                last = b;
            } else {
                m.failed.push(b);
            }
        }
    }

    /// The cut phase of round `round`: marks the failed tips, then cuts every marked ear
    /// whose neighbours are still those it was tested with, logging which thread marked
    /// which triangles.
    fn cut_marked(&mut self, marks: &[Marks], round: u32) {
        for m in marks {
            for &n in &m.failed {
                self.cx.pool.get_mut(n).not_ear = true;
            }
        }
        for m in marks {
            let first = self.out.len() as u32;
            for &[a, b, c] in &m.ears {
                let pool = &self.cx.pool;
                let node = pool.get(b);
                if self.len > 3 && !node.removed && node.prev == a && node.next == c {
                    self.cut(b);
                }
            }
            let end = self.out.len() as u32;
            if end > first {
                self.s.log.push([first, end, m.thread, round]);
            }
        }
    }
}
