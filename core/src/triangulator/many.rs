//! [`Triangulator::triangulate_many`]: many independent inputs (a page of glyphs, a layer
//! of counties), spread over threads.
//!
//! Each input is triangulated exactly as [`Triangulator::triangulate`] would, by a worker
//! that reuses its buffers; which worker takes which input does not change the result,
//! since a worker keeps buffers between calls, never decisions. With the `threads` feature
//! and n > 1 threads, the caller's thread and n − 1 threads of a rayon pool take runs of
//! a few inputs in turn until none is left, each thread with its own worker (allocated on
//! first use and kept). The caller starts at once: a pool thread that wakes up late finds
//! less to do, and one that finds nothing leaves (the call returns once it has).

use super::lenient::Outcome;
use super::{Triangulator, Worker};
use crate::geom::Coord;
use crate::report::{Added, Dropped, Repair, Report};
use crate::{Error, Options};
#[cfg(feature = "threads")]
use std::sync::atomic::Ordering;

/// Below this many vertices in all, the inputs run on the caller's thread: the call waits
/// for the pool's threads to take up their share (they may find it done), and waking a
/// sleeping thread costs more than a handful of glyphs (a page of 54 glyphs, 1,783
/// vertices, 0.10–0.12 ms on two threads against 0.12–0.13 ms on one, interleaved with
/// other work).
const PARALLEL_MIN_VERTICES: usize = 1024;

/// Inputs a thread takes at a time from a parallel `triangulate_many`.
#[cfg(feature = "threads")]
const RUN: usize = 4;

/// How long the caller of a parallel `triangulate_many` waits awake for the pool threads'
/// last runs before it sleeps until they end: longer than a run of glyphs takes.
#[cfg(feature = "threads")]
const SPIN: std::time::Duration = std::time::Duration::from_micros(50);

/// One input's outcome, kept so that its [`Report`] can borrow from the triangulator.
#[derive(Debug, Default)]
struct Kept {
    /// The error, or `None` when it was triangulated.
    error: Option<Error>,
    polygons: usize,
    holes: usize,
    deviation: f64,
    triangles: usize,
    dropped: Vec<Dropped>,
    repairs: Vec<Repair>,
    added: Vec<Added>,
}

impl Kept {
    /// Records what `worker` made of one input.
    fn record(&mut self, worker: &Worker, result: Result<Outcome, Error>, triangles: usize) {
        self.error = result.as_ref().err().copied();
        (self.polygons, self.holes, self.deviation) =
            result.map_or((0, 0, 0.0), |o| (o.polygons, o.holes, o.deviation));
        self.triangles = triangles;
        self.dropped.clear();
        self.dropped.extend_from_slice(&worker.cx.dropped);
        self.repairs.clear();
        self.repairs.extend_from_slice(&worker.cx.repairs);
        self.added.clear();
        self.added.extend_from_slice(&worker.cx.added);
    }

    fn report(&self) -> Result<Report<'_>, Error> {
        match self.error {
            Some(error) => Err(error),
            None => Ok(Report {
                triangles: self.triangles,
                polygons: self.polygons,
                holes: self.holes,
                deviation: self.deviation,
                dropped: &self.dropped,
                repairs: &self.repairs,
                added: &self.added,
            }),
        }
    }
}

/// The outcomes of the last `triangulate_many` call, and the threads with their workers.
#[derive(Debug, Default)]
pub(super) struct Many {
    outcomes: Vec<Kept>,
    /// [`Triangulator::set_mark_and_cut`]'s sizes (ring, chunk), if set.
    mark_and_cut: Option<(usize, usize)>,
    #[cfg(feature = "threads")]
    pool: Option<Pool>,
}

/// A thread pool and one worker per thread, indexed by rayon's thread index.
#[cfg(feature = "threads")]
#[derive(Debug)]
struct Pool {
    /// (shared with the clip stage, for mark-and-cut on one large polygon)
    threads: std::sync::Arc<rayon::ThreadPool>,
    workers: Vec<std::sync::Mutex<Worker>>,
}

/// The pool of `threads` threads in `slot`, started on first use (or again for another
/// count); `None` when no pool could be started.
#[cfg(feature = "threads")]
fn started(slot: &mut Option<Pool>, threads: usize) -> Option<&Pool> {
    if slot.as_ref().map(|p| p.workers.len()) != Some(threads) {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .ok()?;
        let workers = (0..threads).map(|_| Default::default()).collect();
        *slot = Some(Pool {
            threads: std::sync::Arc::new(pool),
            workers,
        });
    }
    slot.as_ref()
}

/// Gives `worker`'s clip stage `threads` for mark-and-cut (from rings of `min` nodes on,
/// in chunks of `chunk`) when the input of `vertices` vertices may make such a ring, and
/// none otherwise.
#[cfg(feature = "threads")]
fn lend(
    worker: &mut Worker,
    threads: Option<&std::sync::Arc<rayon::ThreadPool>>,
    vertices: usize,
    (min, chunk): (usize, usize),
) {
    use crate::stages::clip::Lent;
    worker.stages.clip.threads = threads
        .filter(|_| may_mark_and_cut(vertices, min))
        .map(|pool| Lent {
            pool: pool.clone(),
            min,
            chunk,
        });
}

/// Whether an input of `vertices` vertices may make a ring of `min` nodes, which the clip
/// stage then gives to mark-and-cut: bridging adds two nodes per hole (of three vertices
/// or more), so a ring has fewer than twice the input's vertices. The same test for an
/// input alone and in a batch, so that both give the same triangles.
#[cfg(feature = "threads")]
fn may_mark_and_cut(vertices: usize, min: usize) -> bool {
    vertices.saturating_mul(2) >= min
}

/// The number of threads `options` asks for: 0 means every available core (asked once:
/// the answer reads the process's CPU quota, which costs more than a small polygon).
fn thread_count(options: &Options) -> usize {
    static CORES: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    match options.threads {
        0 => *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, |n| n.get())),
        n => n,
    }
}

impl<T: Coord> Triangulator<T> {
    /// Triangulates many independent inputs, each as [`Triangulator::triangulate`] would:
    /// one entry of `out` and one result per input, in input order. With
    /// [`Options::with_threads`] (and the crate's `threads` feature) the inputs are spread
    /// over that many threads (an input large enough for mark-and-cut, see
    /// [`Options::threads`], is clipped on them too); the results are the same as
    /// `triangulate` gives each input with the same options, and the same for every thread
    /// count from 2 on.
    ///
    /// Each input is `(vertices, ring_starts)`; its triangles index its own vertices.
    /// `out` is resized to one entry per input, keeping the entries' buffers.
    ///
    /// ```
    /// # fn main() -> Result<(), polytri::Error> {
    /// let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
    /// let framed = [
    ///     [0.0, 0.0], [9.0, 0.0], [9.0, 9.0], [0.0, 9.0],
    ///     [3.0, 3.0], [3.0, 6.0], [6.0, 6.0], [6.0, 3.0],
    /// ];
    /// let bow_tie = [[0.0, 0.0], [4.0, 4.0], [4.0, 0.0], [0.0, 4.0]];
    /// let inputs: [(&[[f64; 2]], &[usize]); 3] =
    ///     [(&square, &[0]), (&framed, &[0, 4]), (&bow_tie, &[0])];
    ///
    /// let mut tri = polytri::Triangulator::<f64>::new();
    /// let opts = polytri::Options::default().with_threads(0); // every core
    /// let mut out = Vec::new();
    /// let results = tri.triangulate_many(&inputs, &opts, &mut out);
    /// assert_eq!(results[0].as_ref().map(|r| r.triangles), Ok(2));
    /// assert_eq!(out[1].len(), 8);
    /// assert!(matches!(results[2], Err(polytri::Error::EdgesCross { .. })));
    /// # Ok(())
    /// # }
    /// ```
    pub fn triangulate_many(
        &mut self,
        polygons: &[(&[[T; 2]], &[usize])],
        options: &Options,
        out: &mut Vec<Vec<[u32; 3]>>,
    ) -> Vec<Result<Report<'_>, Error>> {
        out.resize_with(polygons.len(), Vec::new);
        let many = &mut self.many;
        many.outcomes.resize_with(polygons.len(), Kept::default);
        let threads = thread_count(options);
        let work: usize = polygons.iter().map(|(vertices, _)| vertices.len()).sum();
        let done = threads > 1
            && polygons.len() > 1
            && work >= PARALLEL_MIN_VERTICES
            && many.in_parallel(&mut self.worker, polygons, options, threads, out);
        if !done {
            #[cfg(feature = "threads")]
            let (pool, sizes) = {
                let largest = polygons.iter().map(|(v, _)| v.len()).max().unwrap_or(0);
                (many.pool_for(options, largest), many.mark_and_cut())
            };
            let jobs = polygons.iter().zip(out.iter_mut()).zip(&mut many.outcomes);
            for ((&(vertices, ring_starts), out), outcome) in jobs {
                #[cfg(feature = "threads")]
                lend(&mut self.worker, pool.as_ref(), vertices.len(), sizes);
                let result = self.worker.run(vertices, ring_starts, options, out);
                outcome.record(&self.worker, result, out.len());
            }
        }
        many.outcomes[..polygons.len()]
            .iter()
            .map(Kept::report)
            .collect()
    }
}

impl<T: Coord> Triangulator<T> {
    /// Sets the ring size (nodes after bridging) from which the fast strategy clips one
    /// polygon by mark-and-cut when [`Options::with_threads`] asks for several threads,
    /// and the nodes per chunk of a round. The defaults are measured on the machines the
    /// project benchmarks on; tests and the fuzzer lower both to take small inputs through
    /// the rounds and across chunk boundaries. Not part of the stable API.
    #[doc(hidden)]
    pub fn set_mark_and_cut(&mut self, min_nodes: usize, chunk: usize) {
        self.many.mark_and_cut = Some((min_nodes, chunk.max(1)));
    }

    /// Which thread marked which triangles in the last call's mark-and-cut rounds: each
    /// entry `[first, end, thread, round]` says that triangles `first..end` of the output
    /// were ears marked by pool thread `thread` in round `round`; triangles no entry names
    /// were cut by the sequential walk. For pictures (`examples/mark_and_cut_svg.rs`); not
    /// part of the stable API.
    #[doc(hidden)]
    pub fn mark_and_cut_log(&self) -> &[[u32; 4]] {
        #[cfg(feature = "threads")]
        {
            self.worker.stages.clip.log()
        }
        #[cfg(not(feature = "threads"))]
        {
            &[]
        }
    }
}

impl Many {
    /// Runs every input on a pool of `threads` threads; false without the `threads`
    /// feature, or when no pool could be started (then the caller runs them itself).
    #[cfg(feature = "threads")]
    fn in_parallel<T: Coord>(
        &mut self,
        caller: &mut Worker,
        polygons: &[(&[[T; 2]], &[usize])],
        options: &Options,
        threads: usize,
        out: &mut [Vec<[u32; 3]>],
    ) -> bool {
        let sizes = self.mark_and_cut();
        let Some(pool) = started(&mut self.pool, threads) else {
            return false;
        };
        // The inputs in runs of a few, handed out in order to whichever thread asks next:
        // the caller's and `threads - 1` of the pool's. The caller starts at once and
        // never waits for a pool thread to wake up (on a machine whose idle cores sleep
        // deeply, that takes longer than a page of glyphs): a thread that comes late
        // finds the runs taken and leaves.
        let outcomes = &mut self.outcomes[..polygons.len()];
        let runs = polygons
            .chunks(RUN)
            .zip(out.chunks_mut(RUN))
            .zip(outcomes.chunks_mut(RUN));
        let runs = std::sync::Mutex::new(runs);
        let take = || match runs.lock() {
            Ok(mut runs) => runs.next(),
            Err(poisoned) => poisoned.into_inner().next(),
        };
        let work = |worker: &mut Worker| {
            while let Some(((polygons, out), outcomes)) = take() {
                let jobs = polygons.iter().zip(out).zip(outcomes);
                for ((&(vertices, ring_starts), out), outcome) in jobs {
                    // a large input clips on the pool's threads, as it would alone
                    lend(worker, Some(&pool.threads), vertices.len(), sizes);
                    let result = worker.run(vertices, ring_starts, options, out);
                    outcome.record(worker, result, out.len());
                }
            }
        };
        // pool threads working on runs now
        let busy = std::sync::atomic::AtomicUsize::new(0);
        pool.threads.in_place_scope(|scope| {
            for _ in 1..threads {
                scope.spawn(|_| {
                    // a pool thread, which has a worker of its own; only this thread
                    // locks it, so it is busy only when this thread is already working
                    // with it further up its stack (waiting in mark-and-cut's rounds, it
                    // may take this job): then it leaves the runs to the others
                    let k = rayon::current_thread_index().unwrap_or(0) % pool.workers.len();
                    let mut worker = match pool.workers[k].try_lock() {
                        Ok(worker) => worker,
                        Err(std::sync::TryLockError::Poisoned(p)) => p.into_inner(),
                        Err(std::sync::TryLockError::WouldBlock) => return,
                    };
                    busy.fetch_add(1, Ordering::AcqRel);
                    work(&mut worker);
                    busy.fetch_sub(1, Ordering::AcqRel);
                });
            }
            work(caller);
            // The runs are all taken, the last ones maybe still running. The scope makes
            // the caller sleep until they end, and waking it again takes longer than the
            // run (several µs, on a machine whose idle cores sleep deeply): so first it
            // waits here, awake, for a while.
            let began = std::time::Instant::now();
            while busy.load(Ordering::Acquire) > 0 && began.elapsed() < SPIN {
                std::hint::spin_loop();
            }
        });
        true
    }

    /// Gives `worker`'s clip stage the threads `options` asks for when the input (of
    /// `vertices` vertices) is large enough for mark-and-cut, and none otherwise.
    pub(super) fn lend_threads(&mut self, worker: &mut Worker, options: &Options, vertices: usize) {
        #[cfg(feature = "threads")]
        {
            let pool = self.pool_for(options, vertices);
            lend(worker, pool.as_ref(), vertices, self.mark_and_cut());
        }
        #[cfg(not(feature = "threads"))]
        let _ = (worker, options, vertices);
    }

    /// The threads for mark-and-cut on inputs of up to `vertices` vertices, when
    /// `options` asks for more than one (the pool started on first use).
    #[cfg(feature = "threads")]
    fn pool_for(
        &mut self,
        options: &Options,
        vertices: usize,
    ) -> Option<std::sync::Arc<rayon::ThreadPool>> {
        let threads = thread_count(options);
        let wanted = threads > 1 && may_mark_and_cut(vertices, self.mark_and_cut().0);
        wanted
            .then(|| started(&mut self.pool, threads).map(|p| p.threads.clone()))
            .flatten()
    }

    /// The ring size from which the fast strategy runs mark-and-cut on several threads,
    /// and the nodes per chunk.
    #[cfg(feature = "threads")]
    fn mark_and_cut(&self) -> (usize, usize) {
        use crate::stages::clip::{MARK_AND_CUT_CHUNK, MARK_AND_CUT_MIN};
        self.mark_and_cut
            .unwrap_or((MARK_AND_CUT_MIN, MARK_AND_CUT_CHUNK))
    }

    /// Without the `threads` feature the caller runs every input itself.
    #[cfg(not(feature = "threads"))]
    fn in_parallel<T: Coord>(
        &mut self,
        _caller: &mut Worker,
        _polygons: &[(&[[T; 2]], &[usize])],
        _options: &Options,
        _threads: usize,
        _out: &mut [Vec<[u32; 3]>],
    ) -> bool {
        false
    }
}
