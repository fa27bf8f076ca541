//! Layer 6, the triangulator: the public [`Triangulator`], which owns the context and
//! every stage's scratch, and is the only code that runs the stages
//! ([`pipeline`] in order, [`lenient`] for the policy of reruns on crossing input).

mod fill;
mod lenient;
mod many;
pub(crate) mod pipeline;

use core::marker::PhantomData;

use crate::context::Context;
use crate::geom::Coord;
use crate::report::Report;
use crate::{Error, Options};

/// Everything one triangulation needs: the shared context, every stage's scratch and
/// lenient mode's rerun state. A [`Triangulator`] has one, and one per thread of
/// [`Triangulator::triangulate_many`].
#[derive(Debug, Default)]
struct Worker {
    cx: Context,
    stages: pipeline::Stages,
    reruns: lenient::Reruns,
    fill: fill::Scratch,
}

impl Worker {
    /// Triangulates one input into `out`; what it made besides triangles.
    fn run<T: Coord>(
        &mut self,
        vertices: &[[T; 2]],
        ring_starts: &[usize],
        options: &Options,
        out: &mut Vec<[u32; 3]>,
    ) -> Result<lenient::Outcome, Error> {
        let (cx, stages, reruns) = (&mut self.cx, &mut self.stages, &mut self.reruns);
        stages.small.took = false;
        // (a refused call leaves no triangles of an earlier one behind)
        out.clear();
        cx.added.clear();
        let mut fill_rule = options.fill_rule;
        if options.strategy == crate::Strategy::Seidel && fill_rule.is_none() {
            // Seidel reads the rings even–odd: for valid input, the polygon and its holes;
            // strict mode first refuses what is not valid, as the ear clippers would
            if !options.lenient {
                cx.keep_collinear = false;
                cx.reset(false);
                pipeline::check_input(cx, stages, vertices, ring_starts, options.nesting, false)?;
                if let Some(counts) = fill::checked_rings(cx, &mut self.fill) {
                    // rings winding twice round a region are refused, as the ear
                    // clippers do (only rings touching something can)
                    if !cx.shared.is_empty() {
                        pipeline::join(cx, stages)?;
                    }
                    return fill::seidel_checked(&mut self.fill, vertices, counts, out);
                }
                // overlapping edges (a collinear stretch walked both ways) are resolved
                // into simple rings first, as a fill rule's are
            }
            fill_rule = Some(crate::FillRule::EvenOdd);
        }
        match fill_rule {
            Some(rule) => fill::triangulate(
                cx,
                stages,
                reruns,
                &mut self.fill,
                vertices,
                ring_starts,
                rule,
                options,
                out,
            ),
            None => {
                let made =
                    lenient::triangulate(cx, stages, reruns, vertices, ring_starts, options, out)?;
                if !options.lenient || options.nesting != crate::Nesting::Auto || stages.small.took
                {
                    return Ok(made);
                }
                let fill = &mut self.fill;
                let even_odd = options.with_fill_rule(crate::FillRule::EvenOdd);
                Ok(lenient::read_even_odd_where_rings_overlap(
                    cx,
                    reruns,
                    vertices,
                    made,
                    out,
                    |cx, reruns, alt| {
                        let rule = crate::FillRule::EvenOdd;
                        fill::triangulate(
                            cx,
                            stages,
                            reruns,
                            fill,
                            vertices,
                            ring_starts,
                            rule,
                            &even_odd,
                            alt,
                        )
                    },
                ))
            }
        }
    }
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
    worker: Worker,
    many: many::Many,
    /// `triangulate_3d`'s projection of the vertices, kept between calls.
    projected: Vec<[T; 2]>,
    /// The last call's added vertices in the coordinate type.
    added: Vec<[T; 2]>,
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
            worker: Worker::default(),
            many: many::Many::default(),
            projected: Vec::new(),
            added: Vec::new(),
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
        let w = &mut self.worker;
        if pipeline::small_ring_valid(
            &mut w.cx,
            &mut w.stages,
            vertices,
            ring_starts,
            nesting,
            false,
        ) {
            return Ok(());
        }
        w.cx.keep_collinear = false;
        w.cx.reset(false);
        pipeline::check_input(
            &mut w.cx,
            &mut w.stages,
            vertices,
            ring_starts,
            nesting,
            false,
        )?;
        Ok(())
    }

    /// [`Triangulator::triangulate`] on vertices that `fill` writes into the
    /// triangulator's own buffer (kept between calls): `triangulate_3d`'s projection.
    pub(crate) fn triangulate_filled(
        &mut self,
        fill: impl FnOnce(&mut Vec<[T; 2]>),
        ring_starts: &[usize],
        options: &Options,
        out: &mut Vec<[u32; 3]>,
    ) -> Result<Report<'_>, Error> {
        self.projected.clear();
        fill(&mut self.projected);
        (self.many).lend_threads(&mut self.worker, options, self.projected.len());
        let made = (self.worker).run(&self.projected, ring_starts, options, out)?;
        Ok(self.report(made, out.len()))
    }

    /// The vertices the last [`Triangulator::triangulate`] call added where edges cross
    /// (with a fill rule; else none), in the coordinate type: the triangles index the
    /// input's vertices, then these. [`Report::added`] says which edges each splits.
    ///
    /// ```
    /// # fn main() -> Result<(), polytri::Error> {
    /// use polytri::{FillRule, Options, Triangulator};
    /// let bow_tie = [[0.0f32, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
    /// let mut tri = Triangulator::new();
    /// let mut out = Vec::new();
    /// tri.triangulate(&bow_tie, &[0], &Options::new().with_fill_rule(FillRule::NonZero), &mut out)?;
    /// assert_eq!(tri.added_vertices(), &[[1.0, 1.0]]);
    /// assert_eq!(out.len(), 2); // one triangle per wing, both at vertex 4 = the crossing
    /// assert!(out.iter().all(|t| t.contains(&4)));
    /// # Ok(())
    /// # }
    /// ```
    pub fn added_vertices(&self) -> &[[T; 2]] {
        &self.added
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
        (self.many).lend_threads(&mut self.worker, options, vertices.len());
        let made = self.worker.run(vertices, ring_starts, options, out)?;
        Ok(self.report(made, out.len()))
    }

    /// Lets `triangulate` and `check` take one ring of a few dozen vertices through the
    /// small stage (the default), or always through the whole pipeline, which gives
    /// the same result: for tests that hold the two to it. Not part of the stable API.
    #[doc(hidden)]
    pub fn set_small_rings(&mut self, on: bool) {
        self.worker.stages.small.off = !on;
    }

    /// Whether the last `triangulate` or `check` call was the small stage's alone
    /// (see [`Triangulator::set_small_rings`]). Not part of the stable API.
    #[doc(hidden)]
    pub fn small_ring_took_last(&self) -> bool {
        self.worker.stages.small.took
    }

    /// The report of the call that made `made` and `triangles` triangles; keeps its added
    /// vertices in the coordinate type for [`Triangulator::added_vertices`].
    fn report(&mut self, made: lenient::Outcome, triangles: usize) -> Report<'_> {
        self.added.clear();
        (self.added).extend(
            self.worker
                .cx
                .added
                .iter()
                .map(|a| a.position.map(T::from_f64)),
        );
        Report {
            triangles,
            polygons: made.polygons,
            holes: made.holes,
            deviation: made.deviation,
            dropped: &self.worker.cx.dropped,
            repairs: &self.worker.cx.repairs,
            added: &self.worker.cx.added,
        }
    }
}
