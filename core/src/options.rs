//! How to triangulate: strategy, nesting convention, strict or lenient.

/// Which ear to clip next.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Strategy {
    /// The paper's high-performance walk: clip ears as they come, fan when at most one
    /// reflex vertex is left, and skip tips that failed until a neighbour changes.
    #[default]
    Fast,
    /// Always clip the ear with the smallest interior angle (Mei et al.), kept in a
    /// priority queue. Fewer slivers, somewhat slower.
    Quality,
}

/// How rings relate to each other.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Nesting {
    /// Any set of non-crossing rings, in any order and winding: containment depth decides
    /// (even: outer boundary, odd: hole). An island inside a hole is a polygon of its own.
    #[default]
    Auto,
    /// earcut's convention: the first ring is the outer boundary, every other ring a hole.
    FirstIsOuter,
}

/// Options for [`Triangulator::triangulate`](crate::Triangulator::triangulate).
///
/// Defaults: [`Strategy::Fast`], [`Nesting::Auto`], strict, one thread.
///
/// ```
/// use polytri::{Nesting, Options, Strategy};
/// let opts = Options::default()
///     .with_strategy(Strategy::Quality)
///     .with_nesting(Nesting::FirstIsOuter)
///     .with_lenient(true);
/// assert!(opts.lenient);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub struct Options {
    /// Which ear to clip next. Default: [`Strategy::Fast`].
    pub strategy: Strategy,
    /// How rings relate. Default: [`Nesting::Auto`].
    pub nesting: Nesting,
    /// `false` (default, strict): check the input first and refuse crossing or overlapping
    /// edges with an [`Error`](crate::Error); the result is then a valid triangulation.
    /// `true` (lenient): skip the refusal and make the best of any input — always a result,
    /// with a [`Report`](crate::Report) of what was repaired or skipped.
    pub lenient: bool,
    /// Threads for [`Triangulator::triangulate_many`](crate::Triangulator::triangulate_many):
    /// 1 (default) runs on the caller's thread, 0 uses every available core. Results do not
    /// depend on it. Without the crate's `threads` feature, every count runs on one thread.
    pub threads: usize,
}

impl Options {
    /// The defaults: fast, automatic nesting, strict.
    pub const fn new() -> Self {
        Options {
            strategy: Strategy::Fast,
            nesting: Nesting::Auto,
            lenient: false,
            threads: 1,
        }
    }

    /// Sets the ear-clipping strategy.
    pub const fn with_strategy(mut self, strategy: Strategy) -> Self {
        self.strategy = strategy;
        self
    }

    /// Sets the nesting convention.
    pub const fn with_nesting(mut self, nesting: Nesting) -> Self {
        self.nesting = nesting;
        self
    }

    /// Strict (`false`, default) or lenient (`true`).
    pub const fn with_lenient(mut self, lenient: bool) -> Self {
        self.lenient = lenient;
        self
    }

    /// Sets the thread count for [`Triangulator::triangulate_many`](crate::Triangulator::triangulate_many):
    /// 1 (default) sequential, 0 every available core.
    pub const fn with_threads(mut self, threads: usize) -> Self {
        self.threads = threads;
        self
    }
}

impl Default for Options {
    fn default() -> Self {
        Options::new()
    }
}
