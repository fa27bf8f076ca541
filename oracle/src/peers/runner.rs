//! Reusable state for benchmarks: every implementation on a prepared input, buffers kept.

use std::fmt;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::str::FromStr;

use i_triangle::float::triangulation::Triangulation;
use lyon_tessellation::path::Path;
use lyon_tessellation::{BuffersBuilder, FillTessellator, FillVertex, VertexBuffers};

use super::earcut_exact::{exact, vendored};
use super::floor::Floor;
use super::group::{polygons, Polygon};
use super::spade::Constraints;
use super::{check_finite, panic_message, Peer};
use crate::input::Input;
use polytri::FillRule::{EvenOdd, NonZero};

/// Something a benchmark times: a polytri configuration or a peer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Implementation {
    /// polytri, fast strategy, strict (the input is checked for crossings first).
    PolytriFast,
    /// polytri, fast strategy, lenient: crossing and touching input is repaired instead of
    /// refused. It still sweeps the edges to find crossings and touching points, and on
    /// input that has some it runs more passes (see the README's "Speed").
    PolytriLenient,
    /// polytri, quality strategy (smallest angle first), strict.
    PolytriQuality,
    /// polytri's strict input check alone ([`polytri::Triangulator::check`]: loading, the
    /// edge sweep that refuses crossings, nesting), no triangulation: what the check costs
    /// of [`PolytriFast`](Self::PolytriFast)'s time. Makes no triangles ([`Runner::run`]
    /// returns 0).
    PolytriCheck,
    /// polytri, fast strategy, strict, on every core: the polygons of a file of several
    /// spread over threads ([`polytri::Triangulator::triangulate_many`]); a single
    /// polygon runs as [`PolytriFast`](Self::PolytriFast) does.
    PolytriThreads,
    /// polytri, fast strategy, with the even–odd fill rule on all the input's rings at
    /// once: crossing edges split at rounded crossing points, the region exactly the
    /// even–odd one (as lyon and i_triangle read their input here). Not in the default
    /// set: ask for it with `--polytri even-odd`.
    PolytriEvenOdd,
    /// polytri, fast strategy, with the even–odd fill rule one polygon at a time, as
    /// [`PolytriFast`](Self::PolytriFast) takes them (a layer's polygons each on its own,
    /// as `polytri triangulate --fill-rule even-odd` reads a file). Not in the default
    /// set: `--polytri even-odd-each`.
    PolytriEvenOddEach,
    /// polytri with [`polytri::Strategy::Seidel`] (trapezoidation), strict. Not in the
    /// default set: ask for it with `--polytri seidel`.
    PolytriSeidel,
    /// [`PolytriEvenOdd`](Self::PolytriEvenOdd) with [`polytri::Strategy::Seidel`]: the
    /// resolved region trapezoidated. Not in the default set: `--polytri seidel-even-odd`.
    PolytriSeidelEvenOdd,
    /// [`PolytriEvenOdd`](Self::PolytriEvenOdd) by the nonzero fill rule (as
    /// [`Peer::LyonNonZero`] and [`Peer::ITriangleNonZero`] read their input). Not in the
    /// default set: `--polytri nonzero`.
    PolytriNonZero,
    /// [`PolytriNonZero`](Self::PolytriNonZero) with [`polytri::Strategy::Seidel`]. Not
    /// in the default set: `--polytri seidel-nonzero`.
    PolytriSeidelNonZero,
    /// [`PolytriEvenOddEach`](Self::PolytriEvenOddEach) by the nonzero rule: one polygon
    /// at a time. Not in the default set: `--polytri nonzero-each`.
    PolytriNonZeroEach,
    /// A reference beside [`PolytriCheck`](Self::PolytriCheck), not polytri's code: the
    /// least an exact input check costs — every vertex read and one exact orientation per
    /// edge, the star-shaped certificate from each ring's vertex mean, counted as done
    /// whether or not it holds (`oracle/src/peers/floor.rs`). Makes no triangles. Not in
    /// the default set: `--polytri check-floor`.
    PolytriCheckFloor,
    /// Another triangulator.
    Peer(Peer),
}

impl Implementation {
    /// The polytri configurations, in the order tables show them.
    pub const POLYTRI: [Implementation; 5] = [
        Implementation::PolytriFast,
        Implementation::PolytriLenient,
        Implementation::PolytriQuality,
        Implementation::PolytriCheck,
        Implementation::PolytriThreads,
    ];

    /// Every polytri configuration: the default ones, then the optional ones.
    pub const POLYTRI_ALL: [Implementation; 13] = [
        Implementation::PolytriFast,
        Implementation::PolytriLenient,
        Implementation::PolytriQuality,
        Implementation::PolytriCheck,
        Implementation::PolytriThreads,
        Implementation::PolytriEvenOdd,
        Implementation::PolytriEvenOddEach,
        Implementation::PolytriSeidel,
        Implementation::PolytriSeidelEvenOdd,
        Implementation::PolytriNonZero,
        Implementation::PolytriSeidelNonZero,
        Implementation::PolytriNonZeroEach,
        Implementation::PolytriCheckFloor,
    ];

    /// Every default polytri configuration, then every peer, then the references.
    pub fn all() -> Vec<Implementation> {
        (Self::POLYTRI.into_iter())
            .chain(Peer::ALL.into_iter().map(Implementation::Peer))
            .chain(Peer::REFERENCES.into_iter().map(Implementation::Peer))
            .collect()
    }

    /// Whether this is polytri (as opposed to a peer or a reference).
    pub const fn is_polytri(self) -> bool {
        !matches!(self, Implementation::Peer(_))
    }

    /// Whether this is a peer, one polytri is compared with: not polytri, not a reference
    /// ([`Peer::REFERENCES`]).
    pub const fn is_peer(self) -> bool {
        matches!(self, Implementation::Peer(peer) if !peer.is_reference())
    }

    /// Whether this makes triangles: all but [`PolytriCheck`](Self::PolytriCheck) and
    /// [`PolytriCheckFloor`](Self::PolytriCheckFloor).
    pub const fn triangulates(self) -> bool {
        !matches!(
            self,
            Implementation::PolytriCheck | Implementation::PolytriCheckFloor
        )
    }

    /// The kebab-case name, as [`Display`](fmt::Display) writes and [`FromStr`] reads it.
    pub const fn name(self) -> &'static str {
        match self {
            Implementation::PolytriFast => "polytri-fast",
            Implementation::PolytriLenient => "polytri-lenient",
            Implementation::PolytriQuality => "polytri-quality",
            Implementation::PolytriCheck => "polytri-check",
            Implementation::PolytriThreads => "polytri-threads",
            Implementation::PolytriEvenOdd => "polytri-even-odd",
            Implementation::PolytriEvenOddEach => "polytri-even-odd-each",
            Implementation::PolytriSeidel => "polytri-seidel",
            Implementation::PolytriSeidelEvenOdd => "polytri-seidel-even-odd",
            Implementation::PolytriNonZero => "polytri-nonzero",
            Implementation::PolytriSeidelNonZero => "polytri-seidel-nonzero",
            Implementation::PolytriNonZeroEach => "polytri-nonzero-each",
            Implementation::PolytriCheckFloor => "polytri-check-floor",
            Implementation::Peer(peer) => peer.name(),
        }
    }
}

impl fmt::Display for Implementation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Implementation {
    type Err = String;

    /// Reads a name as [`Implementation::name`] gives it, or a peer's.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::POLYTRI_ALL
            .into_iter()
            .find(|imp| imp.name().eq_ignore_ascii_case(s.trim()))
            .map_or_else(|| s.parse().map(Implementation::Peer), Ok)
    }
}

/// An input converted once into every implementation's input format, so that timing
/// leaves the conversion out.
#[derive(Clone, Debug)]
pub struct Prepared {
    input: Input,
    /// The polygons, outer ring first (earcut and its copies, earcutr; polytri for `Roles`
    /// inputs).
    polygons: Vec<Polygon>,
    /// Each polygon's hole starts as earcut takes them.
    holes: Vec<Vec<u32>>,
    /// Each polygon flat, as earcutr takes it.
    flat: Vec<Vec<f64>>,
    /// Every ring (i_triangle).
    rings: Vec<Vec<[f64; 2]>>,
    /// Every ring, closed (lyon).
    path: Path,
    /// Distinct points and constraint edges (spade).
    constraints: Constraints,
}

impl Prepared {
    /// Converts `input` for every implementation (grouping rings into polygons by
    /// containment when it says [`Nesting::Auto`](crate::Nesting::Auto)).
    pub fn new(input: &Input) -> Self {
        let polygons = polygons(input);
        Prepared {
            input: input.clone(),
            holes: polygons.iter().map(Polygon::hole_indices).collect(),
            flat: polygons
                .iter()
                .map(|p| p.vertices.iter().flatten().copied().collect())
                .collect(),
            polygons,
            rings: input.rings(),
            path: super::lyon::path(input).0,
            constraints: Constraints::new(input),
        }
    }

    /// The input this was prepared from.
    pub fn input(&self) -> &Input {
        &self.input
    }

    /// How many polygons (outer rings with their holes) the input has, as earcut gets them.
    pub fn polygon_count(&self) -> usize {
        self.polygons.len()
    }
}

/// Every implementation's reusable state: a benchmark calls [`Runner::run`] in a loop and
/// after the first call nothing is set up again that the library lets its caller keep.
///
/// earcutr and spade have no reusable state (their APIs build fresh results); spade's
/// input is cloned per run because it takes its vectors by value.
pub struct Runner {
    polytri: polytri::Triangulator<f64>,
    polytri_out: Vec<[u32; 3]>,
    polytri_many_out: Vec<Vec<[u32; 3]>>,
    earcut: earcut::Earcut<f64>,
    earcut_exact: exact::Earcut,
    earcut_vendored: vendored::Earcut,
    earcut_out: Vec<u32>,
    floor: Floor,
    i_triangle: i_triangle::float::triangulator::Triangulator<u32, i32>,
    i_triangle_nonzero: i_triangle::float::triangulator::Triangulator<u32, i32>,
    i_triangle_out: Triangulation<[f64; 2], u32>,
    lyon: FillTessellator,
    lyon_out: VertexBuffers<[f32; 2], u32>,
}

impl Default for Runner {
    fn default() -> Self {
        Self::new()
    }
}

impl fmt::Debug for Runner {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Runner").finish_non_exhaustive()
    }
}

impl Runner {
    /// Fresh state for every implementation.
    pub fn new() -> Self {
        Runner {
            polytri: polytri::Triangulator::new(),
            polytri_out: Vec::new(),
            polytri_many_out: Vec::new(),
            earcut: earcut::Earcut::new(),
            earcut_exact: exact::Earcut::new(),
            earcut_vendored: vendored::Earcut::new(),
            earcut_out: Vec::new(),
            floor: Floor::default(),
            i_triangle: super::i_triangle::triangulator(64, false),
            i_triangle_nonzero: super::i_triangle::triangulator(64, true),
            i_triangle_out: Triangulation::with_capacity(64),
            lyon: FillTessellator::new(),
            lyon_out: VertexBuffers::new(),
        }
    }

    /// Triangulates `prepared` with `imp` and returns the number of triangles (0 for
    /// [`Implementation::PolytriCheck`], which only checks).
    ///
    /// # Errors
    ///
    /// A message when the implementation refuses the input or panics on it (its state is
    /// then replaced by a fresh one), or the input has non-finite coordinates.
    pub fn run(&mut self, imp: Implementation, prepared: &Prepared) -> Result<usize, String> {
        check_finite(&prepared.input)?;
        // Peers panic on some inputs (see `peers::triangulate`); a benchmark reports that
        // and goes on with the other implementations.
        match catch_unwind(AssertUnwindSafe(|| self.run_unchecked(imp, prepared))) {
            Ok(result) => result,
            Err(panic) => {
                *self = Runner::new();
                Err(format!("{imp} panicked: {}", panic_message(&*panic)))
            }
        }
    }

    fn run_unchecked(&mut self, imp: Implementation, prepared: &Prepared) -> Result<usize, String> {
        match imp {
            Implementation::PolytriFast => self.polytri(prepared, polytri::Options::new()),
            Implementation::PolytriLenient => {
                self.polytri(prepared, polytri::Options::new().with_lenient(true))
            }
            Implementation::PolytriQuality => self.polytri(
                prepared,
                polytri::Options::new().with_strategy(polytri::Strategy::Quality),
            ),
            Implementation::PolytriCheck => self.polytri_check(prepared),
            Implementation::PolytriCheckFloor => self.check_floor(prepared),
            Implementation::PolytriThreads => self.polytri_threads(prepared),
            Implementation::PolytriSeidel => self.polytri(
                prepared,
                polytri::Options::new().with_strategy(polytri::Strategy::Seidel),
            ),
            Implementation::PolytriEvenOdd => {
                self.polytri_fill(prepared, polytri::Strategy::Fast, EvenOdd)
            }
            Implementation::PolytriNonZero => {
                self.polytri_fill(prepared, polytri::Strategy::Fast, NonZero)
            }
            Implementation::PolytriSeidelNonZero => {
                self.polytri_fill(prepared, polytri::Strategy::Seidel, NonZero)
            }
            Implementation::PolytriEvenOddEach => {
                self.polytri(prepared, polytri::Options::new().with_fill_rule(EvenOdd))
            }
            Implementation::PolytriNonZeroEach => {
                self.polytri(prepared, polytri::Options::new().with_fill_rule(NonZero))
            }
            Implementation::PolytriSeidelEvenOdd => {
                self.polytri_fill(prepared, polytri::Strategy::Seidel, EvenOdd)
            }
            Implementation::Peer(
                peer @ (Peer::Earcut | Peer::EarcutExact | Peer::EarcutVendored),
            ) => Ok(self.earcut(prepared, peer)),
            Implementation::Peer(Peer::Earcutr) => earcutr(prepared),
            Implementation::Peer(Peer::ITriangle) => Ok(self.i_triangle(prepared, false)),
            Implementation::Peer(Peer::ITriangleNonZero) => Ok(self.i_triangle(prepared, true)),
            Implementation::Peer(Peer::Lyon) => self.lyon(prepared, false),
            Implementation::Peer(Peer::LyonNonZero) => self.lyon(prepared, true),
            Implementation::Peer(Peer::Spade) => spade(prepared),
        }
    }

    /// polytri with a fill rule on all the input's rings at once.
    fn polytri_fill(
        &mut self,
        prepared: &Prepared,
        strategy: polytri::Strategy,
        rule: polytri::FillRule,
    ) -> Result<usize, String> {
        let input = &prepared.input;
        let options = polytri::Options::new()
            .with_fill_rule(rule)
            .with_strategy(strategy);
        (self.polytri)
            .triangulate(
                &input.vertices,
                &input.ring_starts,
                &options,
                &mut self.polytri_out,
            )
            .map(|report| report.triangles)
            .map_err(|e| e.to_string())
    }

    /// polytri on the whole input for `Auto` and `FirstIsOuter`, else per polygon (each
    /// first-is-outer, exactly as earcut gets it).
    fn polytri(&mut self, prepared: &Prepared, options: polytri::Options) -> Result<usize, String> {
        let out = &mut self.polytri_out;
        polytri_calls(prepared, |vertices, ring_starts, nesting| {
            let options = options.with_nesting(nesting);
            self.polytri
                .triangulate(vertices, ring_starts, &options, out)
                .map(|report| report.triangles)
        })
    }

    /// polytri-fast on every core: the same calls as [`Runner::polytri`], given to
    /// `triangulate_many` at once.
    fn polytri_threads(&mut self, prepared: &Prepared) -> Result<usize, String> {
        let input = &prepared.input;
        let (calls, nesting): (Vec<Call<'_>>, _) = match input.nesting.to_polytri() {
            Some(nesting) => (vec![(&input.vertices, &input.ring_starts)], nesting),
            None => (
                (prepared.polygons.iter())
                    .map(|p| (&p.vertices[..], &p.ring_starts[..]))
                    .collect(),
                polytri::Nesting::FirstIsOuter,
            ),
        };
        let options = polytri::Options::new()
            .with_nesting(nesting)
            .with_threads(0);
        let results = self
            .polytri
            .triangulate_many(&calls, &options, &mut self.polytri_many_out);
        results.into_iter().try_fold(0, |triangles, result| {
            result
                .map(|report| triangles + report.triangles)
                .map_err(|e| e.to_string())
        })
    }

    /// polytri's strict input check alone, on the same calls as [`Runner::polytri`].
    fn polytri_check(&mut self, prepared: &Prepared) -> Result<usize, String> {
        polytri_calls(prepared, |vertices, ring_starts, nesting| {
            self.polytri
                .check(vertices, ring_starts, nesting)
                .map(|()| 0)
        })
    }

    /// The check's floor ([`Implementation::PolytriCheckFloor`]) on the same calls as
    /// [`Runner::polytri_check`].
    fn check_floor(&mut self, prepared: &Prepared) -> Result<usize, String> {
        polytri_calls(prepared, |vertices, ring_starts, _| {
            // (the count of certified rings is opaque to the optimiser, so that the
            // certificate is computed)
            core::hint::black_box(self.floor.run(vertices, ring_starts));
            Ok(0)
        })
    }

    /// earcut, or one of its vendored copies (`peer`), on every polygon.
    fn earcut(&mut self, prepared: &Prepared, peer: Peer) -> usize {
        let mut triangles = 0;
        for (polygon, holes) in prepared.polygons.iter().zip(&prepared.holes) {
            let (data, out) = (&polygon.vertices, &mut self.earcut_out);
            match peer {
                Peer::EarcutExact => self.earcut_exact.earcut_slice(data, holes, out),
                Peer::EarcutVendored => self.earcut_vendored.earcut_slice(data, holes, out),
                _ => self.earcut.earcut_slice(data, holes, out),
            }
            triangles += out.len() / 3;
        }
        triangles
    }

    fn i_triangle(&mut self, prepared: &Prepared, nonzero: bool) -> usize {
        let tri = if nonzero {
            &mut self.i_triangle_nonzero
        } else {
            &mut self.i_triangle
        };
        tri.triangulate_into(&prepared.rings, &mut self.i_triangle_out);
        self.i_triangle_out.indices.len() / 3
    }

    fn lyon(&mut self, prepared: &Prepared, nonzero: bool) -> Result<usize, String> {
        self.lyon_out.vertices.clear();
        self.lyon_out.indices.clear();
        let mut builder =
            BuffersBuilder::new(&mut self.lyon_out, |v: FillVertex| v.position().to_array());
        self.lyon
            .tessellate_path(&prepared.path, &super::lyon::options(nonzero), &mut builder)
            .map_err(|e| format!("lyon: {e:?}"))?;
        Ok(self.lyon_out.indices.len() / 3)
    }
}

/// One call of polytri: vertices and ring starts.
type Call<'a> = (&'a [[f64; 2]], &'a [usize]);

/// Calls `call` (vertices, ring starts, nesting; it returns triangles) once on the whole
/// input for `Auto` and `FirstIsOuter`, else once per polygon, first-is-outer; the sum.
fn polytri_calls(
    prepared: &Prepared,
    mut call: impl FnMut(&[[f64; 2]], &[usize], polytri::Nesting) -> Result<usize, polytri::Error>,
) -> Result<usize, String> {
    let input = &prepared.input;
    if let Some(nesting) = input.nesting.to_polytri() {
        return call(&input.vertices, &input.ring_starts, nesting).map_err(|e| e.to_string());
    }
    prepared.polygons.iter().try_fold(0, |triangles, polygon| {
        call(
            &polygon.vertices,
            &polygon.ring_starts,
            polytri::Nesting::FirstIsOuter,
        )
        .map(|t| triangles + t)
        .map_err(|e| e.to_string())
    })
}

fn earcutr(prepared: &Prepared) -> Result<usize, String> {
    let mut triangles = 0;
    for (flat, polygon) in prepared.flat.iter().zip(&prepared.polygons) {
        let out = ::earcutr::earcut(flat, &polygon.ring_starts[1..], 2)
            .map_err(|e| format!("earcutr: {e:?}"))?;
        triangles += out.len() / 3;
    }
    Ok(triangles)
}

fn spade(prepared: &Prepared) -> Result<usize, String> {
    let cdt = prepared.constraints.triangulate()?;
    Ok(super::spade::interior_faces(&cdt, &prepared.constraints.edges).len())
}
