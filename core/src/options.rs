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
    /// Seidel's randomized incremental trapezoidation (seeded: the same input always gives
    /// the same triangles), then monotone pieces triangulated in linear time: near-linear
    /// on every input, where ear clipping can go quadratic (stars, pinwheels). Triangulates
    /// the even–odd region of the rings — for valid input, the polygon with its holes
    /// (strict mode still refuses invalid input; lenient mode reads crossing rings by
    /// even–odd, adding vertices where edges cross, as a fill rule does) — or, with a fill
    /// rule, that rule's region.
    Seidel,
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

/// Which points a set of rings covers, by their winding number (libtess2's five rules).
///
/// The winding number of a point is how many times the rings, taken as given (each with
/// its own orientation), wind counter-clockwise round it. With a fill rule the rings may
/// cross and overlap themselves and each other in any way; the region is exactly the set
/// of points whose winding number the rule accepts.
///
/// ```
/// use polytri::FillRule;
/// assert!(FillRule::EvenOdd.contains(-3));
/// assert!(!FillRule::EvenOdd.contains(2));
/// assert!(FillRule::NonZero.contains(2));
/// assert!(FillRule::Positive.contains(1) && !FillRule::Positive.contains(-1));
/// assert!(FillRule::AbsGeqTwo.contains(-2) && !FillRule::AbsGeqTwo.contains(1));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FillRule {
    /// Odd winding numbers: inside an odd number of rings, whatever their orientation.
    EvenOdd,
    /// Every winding number but 0.
    NonZero,
    /// Winding numbers above 0.
    Positive,
    /// Winding numbers below 0.
    Negative,
    /// Winding numbers of absolute value 2 or more (where rings overlap).
    AbsGeqTwo,
}

impl FillRule {
    /// All five rules.
    pub const ALL: [FillRule; 5] = [
        FillRule::EvenOdd,
        FillRule::NonZero,
        FillRule::Positive,
        FillRule::Negative,
        FillRule::AbsGeqTwo,
    ];

    /// Whether a point of this winding number is inside.
    pub const fn contains(self, winding: i64) -> bool {
        match self {
            FillRule::EvenOdd => winding % 2 != 0,
            FillRule::NonZero => winding != 0,
            FillRule::Positive => winding > 0,
            FillRule::Negative => winding < 0,
            FillRule::AbsGeqTwo => winding >= 2 || winding <= -2,
        }
    }

    /// The rule's name as the CLI spells it: `even-odd`, `nonzero`, `positive`,
    /// `negative`, `abs-geq-two`.
    pub const fn name(self) -> &'static str {
        match self {
            FillRule::EvenOdd => "even-odd",
            FillRule::NonZero => "nonzero",
            FillRule::Positive => "positive",
            FillRule::Negative => "negative",
            FillRule::AbsGeqTwo => "abs-geq-two",
        }
    }
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
    /// Threads for [`Triangulator::triangulate_many`](crate::Triangulator::triangulate_many)
    /// (inputs spread over them) and for the fast strategy on one polygon of hundreds of
    /// thousands of vertices (mark-and-cut: ear tests in parallel rounds): 1 (default) runs
    /// on the caller's thread, 0 uses every available core. Results are the same for every
    /// count from 2 on; a polygon large enough for mark-and-cut gets other (equally valid)
    /// triangles with 1. Without the crate's `threads` feature, every count runs on one
    /// thread.
    pub threads: usize,
    /// `None` (default): the rings are a polygon with holes, read by [`Nesting`], and
    /// crossing edges are refused (strict) or worked round (lenient). `Some(rule)`: the
    /// rings may cross and overlap anywhere, and the region is the set of points whose
    /// winding number `rule` accepts ([`FillRule`]); edges are split where they cross, the
    /// crossing points rounded to the coordinate type and added after the input's vertices
    /// ([`Report::added`](crate::Report::added),
    /// [`Triangulator::added_vertices`](crate::Triangulator::added_vertices)). `nesting`
    /// and `lenient` do not apply.
    pub fill_rule: Option<FillRule>,
}

impl Options {
    /// The defaults: fast, automatic nesting, strict.
    pub const fn new() -> Self {
        Options {
            strategy: Strategy::Fast,
            nesting: Nesting::Auto,
            lenient: false,
            threads: 1,
            fill_rule: None,
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

    /// Sets the thread count ([`Options::threads`]): 1 (default) sequential, 0 every
    /// available core.
    pub const fn with_threads(mut self, threads: usize) -> Self {
        self.threads = threads;
        self
    }
}

impl Options {
    /// Triangulates the region of `rule` ([`Options::fill_rule`]): crossing and overlapping
    /// rings allowed.
    ///
    /// ```
    /// # fn main() -> Result<(), polytri::Error> {
    /// use polytri::{FillRule, Options, Triangulator};
    /// // A pentagram: a star ring crossing itself five times.
    /// let star: Vec<[f64; 2]> = (0..5)
    ///     .map(|k| {
    ///         let a = std::f64::consts::FRAC_PI_2 + 4.0 * std::f64::consts::PI * k as f64 / 5.0;
    ///         [100.0 * a.cos(), 100.0 * a.sin()]
    ///     })
    ///     .collect();
    /// let mut tri = Triangulator::<f64>::new();
    /// let mut out = Vec::new();
    /// // even-odd: the five points, not the pentagon in the middle
    /// let report = tri.triangulate(&star, &[0], &Options::new().with_fill_rule(FillRule::EvenOdd), &mut out)?;
    /// assert_eq!(report.added.len(), 5);
    /// assert_eq!(out.len(), 5);
    /// // nonzero: the whole star, points and pentagon
    /// tri.triangulate(&star, &[0], &Options::new().with_fill_rule(FillRule::NonZero), &mut out)?;
    /// assert_eq!(out.len(), 8);
    /// # Ok(())
    /// # }
    /// ```
    pub const fn with_fill_rule(mut self, rule: FillRule) -> Self {
        self.fill_rule = Some(rule);
        self
    }
}

impl Default for Options {
    fn default() -> Self {
        Options::new()
    }
}
