//! The verdict on a triangulation of a fill rule's region ([`polytri::FillRule`]): rings
//! that may cross and overlap anywhere, a region made of the points whose winding number
//! the rule accepts, and triangles over the input's vertices followed by the vertices the
//! triangulator added where edges cross.
//!
//! Nothing here uses `polytri`'s geometry: orientations come from the oracle's [`exact`]
//! module, winding numbers from its exact probes, areas from exact rationals and dyadic
//! sums of its own. The checks, in order:
//!
//! | check         | what it asks                                                          |
//! |---------------|-----------------------------------------------------------------------|
//! | `input`       | ring starts sound (first 0, strictly increasing, in range), every coordinate (input and added) finite and in the exactly computable range |
//! | `indices`     | every triangle index names an input or added vertex                   |
//! | `orientation` | every triangle is strictly counter-clockwise (exact)                  |
//! | `overlap`     | no two triangles' interiors meet (exact)                              |
//! | `inside`      | the winding number of the input rings at every triangle's centroid is one the rule accepts (exact); where edges cross properly (rounded crossings), a centroid within δ of an input edge is excused |
//! | `area`        | Σ triangle areas (exact) = the region's area by a slab decomposition: exactly where no edges cross properly, within `2 · δ · (length of the input's edges passing within 2δ of a vertex not their own)` where some do |
//!
//! δ is `4 · ulp(M)`, `M` the largest coordinate magnitude of the input, the ulp of `f32`
//! when every coordinate (input and added) is an `f32` value and of `f64` otherwise: snap
//! rounding moves the boundary by about a pixel's diagonal at most.
//!
//! Why these: counter-clockwise triangles with disjoint interiors cover each point at most
//! once; every centroid inside and equal areas then leave room only for a triangle that
//! straddles the region's boundary with its centroid inside, its excess matched by an
//! uncovered part of equal area elsewhere (the checks do not compare the triangles'
//! outline with the region's). Where edges cross, the area tolerance also admits
//! leaving out triangles smaller than it. `overlap` is a sweep in the manner of Shamos and
//! Hoey, each pair that becomes adjacent tested exactly. A centroid lying exactly on an input
//! edge has no winding number: the triangle then passes when the rule accepts the
//! winding number of every sector of the arrangement around the centroid (an edge with
//! the same winding on both sides bounds nothing).
//!
//! The region's area ([`fill_area`]) is computed independently of the triangles: every
//! vertex x and every crossing x (exact rationals) cut the plane into vertical slabs; in
//! each slab the edges are ordered by y inside it and walked from below, accumulating the
//! winding number (an edge running right raises it by one, one running left lowers it);
//! the trapezoids between consecutive edges whose winding the rule accepts are summed.
//! Inputs with more than [`EXACT_MAX_EDGES`] edges or [`EXACT_MAX_CROSSINGS`] crossings
//! use the same method in `f64` ([`fill_area_float`]) and a relative tolerance of `1e-9`.
//!
//! [`exact`]: crate::exact

use std::cmp::Ordering;
use std::collections::{BTreeSet, HashMap};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use polytri::FillRule;

use super::{Check, Failures, Verdict};
use crate::exact::{
    cross_properly, orient, winding_step, Exact, Probe, MAX_COORDINATE, MIN_COORDINATE, P,
};
use crate::grid::{bbox_of, SegmentIndex, Stamps};
use crate::metrics;

/// Above this many non-vertical edges, [`fill_area`] computes in `f64`.
pub const EXACT_MAX_EDGES: usize = 3000;

/// Above this many crossings between non-vertical edges, [`fill_area`] computes in `f64`.
pub const EXACT_MAX_CROSSINGS: usize = 5_000;

/// The relative tolerance of the `area` check when the area was computed in `f64`.
pub const FLOAT_RELATIVE_TOLERANCE: f64 = 1e-9;

/// The most edge–slab pairs the `f64` slab decomposition visits; beyond, the area is not
/// computed (the `area` check says so and passes).
const FLOAT_MAX_WORK: u64 = 500_000_000;

/// The most crossings the slab decomposition handles at all.
const MAX_CROSSINGS: usize = 5_000_000;

// ------------------------------------------------------------------------------------------
// The public entry points
// ------------------------------------------------------------------------------------------

/// Judges `triangles` as a triangulation of the region that `rule` selects from the rings
/// `vertices` and `ring_starts` describe (ring `k` runs from `ring_starts[k]` to the next
/// start, the last to the end; a closing point equal to the first is allowed; each ring
/// winds as given, counter-clockwise counting +1).
///
/// `added` are the vertices the triangulator added where edges cross; triangles index
/// `vertices`, then `added`. Where no two edges cross properly the result must be exact;
/// where some do, the `inside` and `area` checks allow for the rounding of the crossings
/// (see the module docs for δ), even without added vertices: a crossing may round onto
/// an input vertex. Never panics, whatever the arguments hold: a broken input fails the
/// `input` check and the checks that need geometry are skipped.
///
/// ```
/// use polytri::FillRule;
/// // a bow tie: the left wing winds +1, the right one −1; they cross at (1, 1)
/// let bow_tie = [[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
/// let added = [[1.0, 1.0]];
/// let wings = [[0, 4, 3], [2, 1, 4]];
/// let v = polytri_oracle::check_fill(&bow_tie, &[0], FillRule::NonZero, &added, &wings);
/// assert!(v.valid, "{:?}", v.failures());
/// // Positive keeps only the left wing: the right one is outside
/// let v = polytri_oracle::check_fill(&bow_tie, &[0], FillRule::Positive, &added, &wings);
/// assert!(v.failures()[0].starts_with("inside: the centroid of triangle 1 "));
/// ```
pub fn check_fill(
    vertices: &[[f64; 2]],
    ring_starts: &[usize],
    rule: FillRule,
    added: &[[f64; 2]],
    triangles: &[[u32; 3]],
) -> Verdict {
    let mut verdict = Verdict {
        valid: false,
        input_valid: false,
        checks: Vec::new(),
        triangles: triangles.len(),
        expected_triangles: None,
        deviation: 0.0,
        min_angle_deg: 0.0,
        worst_aspect: 0.0,
        total_edge_length: 0.0,
        cdt: None,
    };
    let input = FillInput::build(vertices, ring_starts, added);
    let mut input_fails = Failures::default();
    if let Err(why) = &input {
        input_fails.note(|| why.clone());
    }
    verdict.checks.push(input_fails.check("input"));
    verdict.input_valid = input.is_ok();

    let n = vertices.len().saturating_add(added.len());
    let mut bad_index = Failures::default();
    let mut good: Vec<(usize, [u32; 3])> = Vec::with_capacity(triangles.len());
    for (k, t) in triangles.iter().enumerate() {
        match t.iter().find(|&&i| i as usize >= n) {
            Some(&i) => bad_index.note(|| {
                format!(
                    "triangle {k} ({}, {}, {}) names vertex {i}, but there are {n} ({} input, {} added)",
                    t[0],
                    t[1],
                    t[2],
                    vertices.len(),
                    added.len()
                )
            }),
            None => good.push((k, *t)),
        }
    }
    verdict.checks.push(bad_index.check("indices"));

    if let Ok(input) = input {
        judge(&mut verdict, &input, rule, &good);
    }
    verdict.valid = verdict.checks.iter().all(|c| c.passed);
    verdict
}

/// [`check_fill`] on coordinates of a triangulator's type (`f32` or `f64`), widened to
/// `f64` exactly: `vertices` the input's, `added` the vertices the triangulator added
/// ([`polytri::Triangulator::added_vertices`]).
///
/// ```
/// use polytri::FillRule;
/// let square = [[0.0f32, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let v = polytri_oracle::verify_fill(&square, &[0], FillRule::EvenOdd, &[], &[[0, 1, 2], [0, 2, 3]]);
/// assert!(v.valid, "{:?}", v.failures());
/// ```
pub fn verify_fill<T: polytri::Coord>(
    vertices: &[[T; 2]],
    ring_starts: &[usize],
    rule: FillRule,
    added: &[[T; 2]],
    triangles: &[[u32; 3]],
) -> Verdict {
    let widen = |v: &[[T; 2]]| -> Vec<[f64; 2]> {
        v.iter().map(|p| [p[0].to_f64(), p[1].to_f64()]).collect()
    };
    check_fill(
        &widen(vertices),
        ring_starts,
        rule,
        &widen(added),
        triangles,
    )
}

/// The area of a fill rule's region, by the slab decomposition (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct FillArea {
    /// The area, rounded to `f64` (or as the `f64` method found it).
    pub area: f64,
    /// The exact area, when the exact method ran: not necessarily in lowest terms (its
    /// denominator is positive; `==` and `cmp` compare values).
    pub exact: Option<BigRational>,
    /// The number of non-vertical edges the slabs cut (vertical ones bound no slab area).
    pub edges: usize,
    /// The number of proper crossings between non-vertical edges (those on vertical edges
    /// lie at vertex x's and cut no slab).
    pub crossings: usize,
    /// For the `f64` method: the sum of the magnitudes of the terms summed, a scale for
    /// the rounding of [`FillArea::area`] (0 for the exact method).
    pub magnitude: f64,
}

/// The area of the region `rule` selects from the rings `vertices` and `ring_starts`
/// (read as in [`check_fill`]): exact, in rationals, for up to [`EXACT_MAX_EDGES`] edges
/// and [`EXACT_MAX_CROSSINGS`] crossings; otherwise as [`fill_area_float`] computes it.
/// `Err` says why the input cannot be measured (bad ring starts, coordinates not finite or
/// outside the exact range, too large for the slab method).
///
/// ```
/// use polytri::FillRule;
/// // a square given twice: winding 2 inside
/// let twice = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0],
///              [0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let area = |rule| polytri_oracle::fill_area(&twice, &[0, 4], rule).unwrap().area;
/// assert_eq!(area(FillRule::AbsGeqTwo), 1.0);
/// assert_eq!(area(FillRule::EvenOdd), 0.0);
/// ```
pub fn fill_area(
    vertices: &[[f64; 2]],
    ring_starts: &[usize],
    rule: FillRule,
) -> Result<FillArea, String> {
    let input = FillInput::build(vertices, ring_starts, &[])?;
    area_of(&input, rule, false)
}

/// [`fill_area`] by the same slab decomposition in `f64` arithmetic, whatever the input's
/// size: [`FillArea::exact`] is `None`, and the result is close to the exact area (relative
/// error far below [`FLOAT_RELATIVE_TOLERANCE`] of [`FillArea::magnitude`] on inputs
/// whose crossings are not nearly degenerate).
pub fn fill_area_float(
    vertices: &[[f64; 2]],
    ring_starts: &[usize],
    rule: FillRule,
) -> Result<FillArea, String> {
    let input = FillInput::build(vertices, ring_starts, &[])?;
    area_of(&input, rule, true)
}

// ------------------------------------------------------------------------------------------
// The input
// ------------------------------------------------------------------------------------------

/// The input prepared for the checks: every point (input, then added) and the ring edges.
struct FillInput {
    /// The input's vertices, then the added ones.
    pts: Vec<P>,
    /// How many of `pts` are the input's.
    inputs: usize,
    /// Every ring edge of non-zero length, as the rings direct it.
    edges: Vec<(P, P)>,
    /// The tolerance δ of the module docs.
    delta: f64,
    /// The largest coordinate magnitude of any point.
    magnitude: f64,
}

impl FillInput {
    /// Checks the structure and coordinates; never panics.
    fn build(vertices: &[P], ring_starts: &[usize], added: &[P]) -> Result<FillInput, String> {
        let n = vertices.len();
        if n.saturating_add(added.len()) > u32::MAX as usize {
            return Err(format!(
                "{n} input and {} added vertices are more than u32 indices can address",
                added.len()
            ));
        }
        if n > 0 {
            match ring_starts.first() {
                Some(0) => {}
                Some(&s) => return Err(format!("ring 0 starts at vertex {s}, not 0")),
                None => return Err(format!("{n} vertices but no ring starts")),
            }
            if let Some(r) = (1..ring_starts.len()).find(|&r| ring_starts[r] <= ring_starts[r - 1])
            {
                return Err(format!(
                    "ring starts are not strictly increasing at ring {r}"
                ));
            }
            if let Some(&last) = ring_starts.last() {
                if last >= n {
                    return Err(format!(
                        "the last ring starts at {last}, beyond the {n} vertices"
                    ));
                }
            }
        }
        let unusable = |c: f64| {
            !c.is_finite() || c.abs() > MAX_COORDINATE || (c != 0.0 && c.abs() < MIN_COORDINATE)
        };
        for (what, list) in [("vertex", vertices), ("added vertex", added)] {
            if let Some(v) = list.iter().position(|p| p.iter().any(|&c| unusable(c))) {
                let p = list[v];
                return Err(format!(
                    "{what} {v} ({}, {}) is not finite or outside the exactly computable range \
                     [{MIN_COORDINATE:e}, {MAX_COORDINATE:e}]",
                    p[0], p[1]
                ));
            }
        }
        let mut edges = Vec::new();
        if n > 0 {
            for (r, &start) in ring_starts.iter().enumerate() {
                let end = ring_starts.get(r + 1).copied().unwrap_or(n);
                for i in start..end {
                    let j = if i + 1 == end { start } else { i + 1 };
                    if vertices[i] != vertices[j] {
                        edges.push((vertices[i], vertices[j]));
                    }
                }
            }
        }
        let input_magnitude = max_magnitude(vertices);
        let all_f32 = vertices
            .iter()
            .chain(added)
            .flatten()
            .all(|&c| f64::from(c as f32) == c);
        let delta = 4.0
            * if all_f32 {
                ulp_f32(input_magnitude)
            } else {
                ulp_f64(input_magnitude)
            };
        let mut pts = Vec::with_capacity(n + added.len());
        pts.extend_from_slice(vertices);
        pts.extend_from_slice(added);
        let magnitude = max_magnitude(&pts);
        Ok(FillInput {
            pts,
            inputs: n,
            edges,
            delta,
            magnitude,
        })
    }

    /// The total length of the input's edges that snap rounding may have moved: those
    /// passing within 2δ of a vertex (input or added) other than their own ends — a
    /// rounded edge is rerouted only through pixels it meets. On inputs too large for the
    /// pairwise scan, every edge.
    fn edge_length(&self) -> f64 {
        if self.edges.len().saturating_mul(self.pts.len()) > 50_000_000 {
            return self.edges.iter().map(|&(a, b)| dist(a, b)).sum();
        }
        let reach = 2.0 * self.delta;
        let moved = |&(a, b): &(P, P)| {
            self.pts.iter().any(|&q| {
                q != a && q != b && {
                    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                    let len2 = dx * dx + dy * dy;
                    let t = (((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / len2).clamp(0.0, 1.0);
                    dist(q, [a[0] + t * dx, a[1] + t * dy]) <= reach
                }
            })
        };
        self.edges
            .iter()
            .filter(|e| moved(e))
            .map(|&(a, b)| dist(a, b))
            .sum()
    }
}

fn max_magnitude(pts: &[P]) -> f64 {
    pts.iter()
        .flatten()
        .fold(0.0, |m: f64, &c| if c.abs() > m { c.abs() } else { m })
}

/// The gap from `m ≥ 0` to the next larger `f64`.
fn ulp_f64(m: f64) -> f64 {
    f64::from_bits(m.to_bits() + 1) - m
}

/// The gap from `m ≥ 0` (an `f32` value) to the next larger `f32`.
fn ulp_f32(m: f64) -> f64 {
    let f = m as f32;
    if !f.is_finite() || f == f32::MAX {
        return ulp_f64(m);
    }
    f64::from(f32::from_bits(f.to_bits() + 1)) - f64::from(f)
}

fn dist(a: P, b: P) -> f64 {
    (b[0] - a[0]).hypot(b[1] - a[1])
}

/// Every check that needs coordinates.
fn judge(verdict: &mut Verdict, input: &FillInput, rule: FillRule, good: &[(usize, [u32; 3])]) {
    let pts = &input.pts;
    let corners = |t: [u32; 3]| t.map(|i| pts[i as usize]);

    // orientation
    let mut fails = Failures::default();
    let mut ccw = Vec::with_capacity(good.len());
    for &(k, t) in good {
        let [a, b, c] = corners(t);
        match orient(a, b, c) {
            Ordering::Greater => ccw.push((k, t)),
            o => fails.note(|| {
                let how = if o == Ordering::Equal {
                    "has zero area"
                } else {
                    "is clockwise"
                };
                format!("triangle {k} ({}, {}, {}) {how}", t[0], t[1], t[2])
            }),
        }
    }
    verdict.checks.push(fails.check("orientation"));
    verdict.checks.push(overlap(pts, &ccw));
    // Rounding happens only where edges cross properly, and may add no vertex (a crossing
    // can round onto an input vertex); elsewhere the result must be exact.
    let rounded = pts.len() > input.inputs || !for_each_crossing(&input.edges, |_, _| false);
    verdict.checks.push(inside(input, rule, good, rounded));

    // area
    let mut twice = Dyadic::default();
    for &(_, t) in good {
        let [a, b, c] = corners(t);
        for (p, q) in [(a, b), (b, c), (c, a)] {
            twice.add_product(p[0], q[1]);
            twice.add_product(-p[1], q[0]);
        }
    }
    let covered = twice.fraction(1);
    let region = area_of(input, rule, false);
    if let Ok(region) = &region {
        let covered_f = BigRational::new_raw(covered.0.clone(), covered.1.clone());
        verdict.deviation = polytri::deviation(region.area, covered_f.to_f64().unwrap_or(0.0));
    }
    verdict
        .checks
        .push(area_check(input, &covered, region, rounded));

    let quality_corners: Vec<[([f64; 2], u32); 3]> = good
        .iter()
        .map(|&(_, t)| t.map(|v| (pts[v as usize], v)))
        .collect();
    let quality = metrics::measure(&quality_corners);
    verdict.min_angle_deg = quality.min_angle_deg;
    verdict.worst_aspect = quality.worst_aspect;
    verdict.total_edge_length = quality.total_edge_length;
}

/// The `area` check: the triangles' exact area (numerator, positive denominator) against
/// the region's.
fn area_check(
    input: &FillInput,
    covered: &(BigInt, BigInt),
    region: Result<FillArea, String>,
    rounded: bool,
) -> Check {
    let mut fails = Failures::default();
    let covered_f = BigRational::new_raw(covered.0.clone(), covered.1.clone())
        .to_f64()
        .unwrap_or(f64::NAN);
    let tolerance = if rounded {
        2.0 * input.delta * input.edge_length()
    } else {
        0.0
    };
    let region = match region {
        Ok(region) => region,
        Err(why) => {
            return Check {
                name: "area".to_owned(),
                passed: true,
                detail: Some(format!("not checked: {why}")),
            };
        }
    };
    let mut note = None;
    match &region.exact {
        Some(exact) => {
            // covered − exact, by cross-multiplying (no gcd of the large denominators)
            let diff = BigRational::new_raw(
                &covered.0 * exact.denom() - exact.numer() * &covered.1,
                &covered.1 * exact.denom(),
            );
            let ok = if rounded {
                diff.to_f64().is_some_and(|d| d.abs() <= tolerance)
            } else {
                diff.numer().is_zero()
            };
            if !ok {
                fails.note(|| {
                    let within = if rounded {
                        format!(", more than the tolerance {tolerance:e}")
                    } else {
                        String::new()
                    };
                    format!(
                        "the triangles cover an area of {covered_f:e}, the region has {:e} (difference {:e}{within})",
                        region.area,
                        diff.to_f64().unwrap_or(f64::NAN)
                    )
                });
            }
        }
        None => {
            let scale = region.area.abs().max(covered_f.abs());
            let float_tolerance = FLOAT_RELATIVE_TOLERANCE * scale
                + 64.0 * f64::EPSILON * region.magnitude
                + tolerance;
            let diff = covered_f - region.area;
            let within = matches!(
                diff.abs().partial_cmp(&float_tolerance),
                Some(Ordering::Less | Ordering::Equal)
            );
            if !within {
                fails.note(|| {
                    format!(
                        "the triangles cover an area of {covered_f:e}, the region has {:e} by the f64 slab method (difference {diff:e}, more than the tolerance {float_tolerance:e})",
                        region.area
                    )
                });
            }
            note = Some(format!(
                "the region's area by the slab method in f64 ({} edges, {} crossings: too many for exact rationals), relative tolerance {FLOAT_RELATIVE_TOLERANCE:e}",
                region.edges, region.crossings
            ));
        }
    }
    let mut check = fails.check("area");
    if check.passed {
        check.detail = note;
    }
    check
}

// ------------------------------------------------------------------------------------------
// Exact sums of products of f64 values
// ------------------------------------------------------------------------------------------

/// An exact sum of `f64` products as a big integer times a power of two.
#[derive(Clone, Debug, Default)]
struct Dyadic {
    mantissa: BigInt,
    exponent: i32,
}

/// `f` as `m · 2^e` with `|m| < 2^53` (finite `f`).
fn decode(f: f64) -> (i64, i32) {
    let bits = f.to_bits();
    let negative = bits >> 63 == 1;
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = (bits & ((1u64 << 52) - 1)) as i64;
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1i64 << 52), exp - 1075)
    };
    (if negative { -m } else { m }, e)
}

impl Dyadic {
    /// Adds `a · b` exactly.
    fn add_product(&mut self, a: f64, b: f64) {
        let (ma, ea) = decode(a);
        let (mb, eb) = decode(b);
        self.add(BigInt::from(i128::from(ma) * i128::from(mb)), ea + eb);
    }

    fn add(&mut self, m: BigInt, e: i32) {
        if m.is_zero() {
            return;
        }
        if self.mantissa.is_zero() {
            self.mantissa = m;
            self.exponent = e;
        } else if e < self.exponent {
            let shift = (self.exponent - e) as usize;
            self.mantissa = std::mem::take(&mut self.mantissa) << shift;
            self.mantissa += m;
            self.exponent = e;
        } else {
            self.mantissa += m << ((e - self.exponent) as usize);
        }
    }

    /// The sum divided by `2^halvings`, as a numerator and a positive denominator.
    fn fraction(&self, halvings: i32) -> (BigInt, BigInt) {
        let e = self.exponent - halvings;
        if e >= 0 {
            (self.mantissa.clone() << (e as usize), BigInt::one())
        } else {
            (self.mantissa.clone(), BigInt::one() << ((-e) as usize))
        }
    }
}

/// `f` as an exact rational (0 for a non-finite `f`, which the input check refuses).
fn rational(f: f64) -> BigRational {
    BigRational::from_float(f).unwrap_or_else(BigRational::zero)
}

// ------------------------------------------------------------------------------------------
// A grid for candidates
// ------------------------------------------------------------------------------------------

// ------------------------------------------------------------------------------------------
// overlap
// ------------------------------------------------------------------------------------------

/// The interiors of the counter-clockwise triangles `t` and `u` meet (exact). Disjoint
/// convex polygons are separated by a line through an edge of one of them: the other lies
/// in the closed half-plane right of that edge.
fn interiors_meet(t: [P; 3], u: [P; 3]) -> bool {
    let separates = |s: [P; 3], o: [P; 3]| {
        (0..3).any(|i| {
            let (a, b) = (s[i], s[(i + 1) % 3]);
            o.iter().all(|&x| orient(a, b, x) != Ordering::Greater)
        })
    };
    !separates(t, u) && !separates(u, t)
}

/// A triangle for the sweep: its corners sorted by x then y (`l`, `m`, `r`; `l.x < r.x`
/// for a triangle of positive area), and whether `m` lies above the line `l r`. Its
/// vertical cross-section at `l.x < x < r.x` is the open interval between its lower and
/// upper chains: the edge `l r` on one side, `l m` then `m r` on the other.
#[derive(Clone, Copy)]
struct Swept {
    l: P,
    m: P,
    r: P,
    m_above: bool,
}

impl Swept {
    fn new(t: [P; 3]) -> Swept {
        let mut s = t;
        s.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        let [l, m, r] = s;
        Swept {
            l,
            m,
            r,
            m_above: orient(l, r, m) == Ordering::Greater,
        }
    }

    /// The edge of the bent chain just right (`right`) or just left of `x`: never
    /// vertical, running rightwards.
    fn bend(&self, x: f64, right: bool) -> (P, P) {
        if x < self.m[0] || (!right && x == self.m[0]) {
            (self.l, self.m)
        } else {
            (self.m, self.r)
        }
    }

    fn lower(&self, x: f64, right: bool) -> (P, P) {
        if self.m_above {
            (self.l, self.r)
        } else {
            self.bend(x, right)
        }
    }

    fn upper(&self, x: f64, right: bool) -> (P, P) {
        if self.m_above {
            self.bend(x, right)
        } else {
            (self.l, self.r)
        }
    }
}

/// Compares, just right of `f`'s left end, the heights of the rightward edges `e` (which
/// spans that place) and `f`: `Less` when `e` is below (exact).
fn cmp_right_of(e: (P, P), f: (P, P)) -> Ordering {
    match orient(e.0, e.1, f.0) {
        Ordering::Equal => orient(e.0, e.1, f.1).reverse(),
        o => o.reverse(),
    }
}

/// Compares, just left of `f`'s right end, the heights of the rightward edges `e` (which
/// spans that place) and `f`: `Less` when `e` is below (exact).
fn cmp_left_of(e: (P, P), f: (P, P)) -> Ordering {
    match orient(e.0, e.1, f.1) {
        Ordering::Equal => orient(e.0, e.1, f.0).reverse(),
        o => o.reverse(),
    }
}

/// No two counter-clockwise triangles (`ccw`: caller's index and corners) overlap.
///
/// A sweep from left to right in the manner of Shamos and Hoey: the triangles the sweep
/// line crosses are kept in order of their cross-sections (lower chain, then upper), and
/// every two that become neighbours — when one is inserted at its left corner, or when
/// the one between them ends at its right corner — are tested exactly by separating edges
/// (disjoint convex polygons are separated by the line of an edge of one of them). While
/// no two interiors meet, the cross-sections are disjoint intervals whose order cannot
/// change; the first two that meet are neighbours by then. O(n log n) comparisons, plus
/// moves in the list of crossed triangles. Only overlaps confirmed by the exact test are
/// reported; after the first, the sweep's order may be wrong, so the count is a lower
/// bound.
fn overlap(pts: &[P], ccw: &[(usize, [u32; 3])]) -> Check {
    let tri = |i: usize| ccw[i].1.map(|v| pts[v as usize]);
    let swept: Vec<Swept> = (0..ccw.len()).map(|i| Swept::new(tri(i))).collect();
    let mut found: BTreeSet<(usize, usize)> = BTreeSet::new();
    let mut test = |i: usize, j: usize| {
        if interiors_meet(tri(i), tri(j)) {
            found.insert((i.min(j), i.max(j)));
        }
    };
    let mut starts: Vec<usize> = (0..ccw.len()).collect();
    starts.sort_by(|&i, &j| swept[i].l[0].total_cmp(&swept[j].l[0]));
    let mut ends: Vec<usize> = (0..ccw.len()).collect();
    ends.sort_by(|&i, &j| swept[i].r[0].total_cmp(&swept[j].r[0]));
    let mut list: Vec<usize> = Vec::new();
    let (mut next_start, mut next_end) = (0, 0);
    while next_end < ends.len() {
        let x_end = swept[ends[next_end]].r[0];
        let starting = starts
            .get(next_start)
            .map(|&k| swept[k].l[0])
            .filter(|&x| x < x_end);
        if let Some(x) = starting {
            // insert at its left corner, ordered just right of x
            let k = starts[next_start];
            next_start += 1;
            let b = swept[k];
            let pos = list.partition_point(|&a| {
                let a = swept[a];
                cmp_right_of(a.lower(x, true), b.lower(x, true))
                    .then_with(|| cmp_right_of(a.upper(x, true), b.upper(x, true)))
                    == Ordering::Less
            });
            list.insert(pos, k);
            if pos > 0 {
                test(list[pos - 1], k);
            }
            if pos + 1 < list.len() {
                test(k, list[pos + 1]);
            }
        } else {
            // remove at its right corner, found in the order just left of x_end
            let k = ends[next_end];
            next_end += 1;
            let (x, b) = (x_end, swept[k]);
            let cmp = |a: usize| {
                let a = swept[a];
                cmp_left_of(a.lower(x, false), b.lower(x, false))
                    .then_with(|| cmp_left_of(a.upper(x, false), b.upper(x, false)))
            };
            let from = list.partition_point(|&a| cmp(a) == Ordering::Less);
            let near = list[from..]
                .iter()
                .take_while(|&&a| cmp(a) == Ordering::Equal)
                .position(|&a| a == k)
                .map(|p| from + p);
            // after an overlap the order may be broken: then look everywhere
            let Some(pos) = near.or_else(|| list.iter().position(|&a| a == k)) else {
                continue;
            };
            list.remove(pos);
            if pos > 0 && pos < list.len() {
                test(list[pos - 1], list[pos]);
            }
        }
    }

    let mut fails = Failures::default();
    for &(i, j) in &found {
        let ((ki, ti), (kj, tj)) = (ccw[i], ccw[j]);
        fails.note(|| {
            format!(
                "triangle {ki} ({}, {}, {}) overlaps triangle {kj} ({}, {}, {})",
                ti[0], ti[1], ti[2], tj[0], tj[1], tj[2]
            )
        });
    }
    fails.check("overlap")
}

// ------------------------------------------------------------------------------------------
// inside
// ------------------------------------------------------------------------------------------

/// The winding number of the input rings at a probe.
#[derive(Debug, PartialEq)]
enum Winding {
    /// Off every edge: the winding number.
    At(i64),
    /// On one or more edges: the winding numbers of the sectors around the probe.
    Around(Vec<i64>),
}

/// Winding numbers of the input rings, exactly, with a grid of the edges for the rays.
struct Windings<'a> {
    edges: &'a [(P, P)],
    index: SegmentIndex,
    stamps: Stamps,
    margin: f64,
}

impl<'a> Windings<'a> {
    fn new(input: &'a FillInput) -> Windings<'a> {
        let bbox = bbox_of(input.edges.iter().flat_map(|&(a, b)| [a, b]));
        Windings {
            edges: &input.edges,
            index: SegmentIndex::new(&input.edges, bbox),
            stamps: Stamps::new(input.edges.len()),
            // the rounded mean of probe points is within a few ulps of the magnitude
            margin: 16.0 * f64::EPSILON * input.magnitude,
        }
    }

    fn at(&mut self, probe: &Probe) -> Winding {
        let p = probe.approx();
        let (lo, hi) = (
            [p[0] - self.margin, p[1] - self.margin],
            [p[0] + self.margin, p[1] + self.margin],
        );
        let ray = self.index.shortest_ray(lo, hi);
        // In a frame turned (exactly) so the ray runs towards +x.
        let turned = probe.map(|q| ray.to_right(q));
        let mut w = 0;
        let mut on = Vec::new();
        let edges = self.edges;
        self.index.near_ray(lo, hi, ray, &mut self.stamps, |i| {
            let (a, b) = (ray.to_right(edges[i].0), ray.to_right(edges[i].1));
            match winding_step(a, b, &turned) {
                Some(s) => w += s,
                None => on.push((a, b)),
            }
        });
        if on.is_empty() {
            Winding::At(w)
        } else {
            Winding::Around(sectors(&turned, w, &on))
        }
    }
}

/// The probe is the point `q`, exactly.
fn is_at(probe: &Probe, q: P) -> bool {
    probe.cmp_coord(0, q[0]) == Ordering::Equal && probe.cmp_coord(1, q[1]) == Ordering::Equal
}

/// A ray from the probe along edge `a → b` through it: towards `b` (`sign` +1, direction
/// `b − a`) or towards `a` (`sign` −1, direction `a − b`). Turning counter-clockwise past
/// it moves from the edge's right to its left (towards `b`: the winding number rises by
/// one) or the other way (towards `a`: it falls by one), so `sign` is also the jump.
#[derive(Clone, Copy)]
struct Spoke {
    a: P,
    b: P,
    sign: i64,
}

impl Spoke {
    fn sign_of(x: f64, y: f64, sign: i64) -> Ordering {
        let o = y.partial_cmp(&x).unwrap_or(Ordering::Equal);
        if sign < 0 {
            o.reverse()
        } else {
            o
        }
    }

    /// 0 for directions in the upper half-plane or along +x, 1 for the rest.
    fn half(&self) -> u8 {
        let dy = Self::sign_of(self.a[1], self.b[1], self.sign);
        let dx = Self::sign_of(self.a[0], self.b[0], self.sign);
        u8::from(!(dy == Ordering::Greater || (dy == Ordering::Equal && dx == Ordering::Greater)))
    }

    /// Along +x exactly.
    fn east(&self) -> bool {
        Self::sign_of(self.a[1], self.b[1], self.sign) == Ordering::Equal
            && Self::sign_of(self.a[0], self.b[0], self.sign) == Ordering::Greater
    }

    /// Counter-clockwise from +x: `Less` when `self` comes first.
    fn cmp(&self, other: &Spoke) -> Ordering {
        self.half().cmp(&other.half()).then_with(|| {
            // (b1 − a1) × (b2 − a2) = b1×b2 + a2×b1 + b2×a1 + a1×a2
            let mut e = Exact::default();
            e.add_cross(self.b, other.b);
            e.add_cross(other.a, self.b);
            e.add_cross(other.b, self.a);
            e.add_cross(self.a, other.a);
            let cross = e.sign();
            let cross = if self.sign * other.sign < 0 {
                cross.reverse()
            } else {
                cross
            };
            cross.reverse()
        })
    }
}

/// The winding numbers of the sectors round a probe lying on the edges `on`, given `east`,
/// the sum of Sunday's steps of every other edge. That sum is the winding number just
/// counter-clockwise of the +x direction: at the probe moved by `ε (1, η)`, `0 < η ≪ 1`,
/// the edges through the probe are all crossed left of it, and the other edges' steps are
/// unchanged (the half-open rule already counts the probe as slightly above).
fn sectors(probe: &Probe, east: i64, on: &[(P, P)]) -> Vec<i64> {
    let mut spokes = Vec::with_capacity(2 * on.len());
    for &(a, b) in on {
        if !is_at(probe, a) {
            spokes.push(Spoke { a, b, sign: -1 });
        }
        if !is_at(probe, b) {
            spokes.push(Spoke { a, b, sign: 1 });
        }
    }
    spokes.sort_by(|s, t| s.cmp(t));
    let mut values = vec![east];
    let mut w = east;
    let mut k = 0;
    while k < spokes.len() {
        let mut jump = 0;
        let mut j = k;
        while j < spokes.len() && spokes[j].cmp(&spokes[k]) == Ordering::Equal {
            jump += spokes[j].sign;
            j += 1;
        }
        if !spokes[k].east() {
            w += jump;
            values.push(w);
        }
        k = j;
    }
    values
}

/// Segments near a point, for the rounding excuse.
struct NearEdges<'a> {
    edges: &'a [(P, P)],
    index: SegmentIndex,
    stamps: Stamps,
}

impl<'a> NearEdges<'a> {
    fn new(edges: &'a [(P, P)]) -> NearEdges<'a> {
        let bbox = bbox_of(edges.iter().flat_map(|&(a, b)| [a, b]));
        NearEdges {
            edges,
            index: SegmentIndex::new(edges, bbox),
            stamps: Stamps::new(edges.len()),
        }
    }

    /// Whether some edge passes within `r` of `p` (floating point).
    fn within(&mut self, p: P, r: f64) -> bool {
        let mut hit = false;
        let edges = self.edges;
        let (lo, hi) = ([p[0] - r, p[1] - r], [p[0] + r, p[1] + r]);
        self.index.near_box(lo, hi, &mut self.stamps, |i| {
            if !hit {
                let (a, b) = edges[i];
                hit = point_segment_distance(p, a, b) <= r;
            }
        });
        hit
    }
}

fn point_segment_distance(p: P, a: P, b: P) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    dist(p, [a[0] + t * dx, a[1] + t * dy])
}

/// Every triangle's centroid has a winding number the rule accepts.
fn inside(input: &FillInput, rule: FillRule, good: &[(usize, [u32; 3])], rounded: bool) -> Check {
    let pts = &input.pts;
    let mut windings = Windings::new(input);
    let mut near = rounded.then(|| NearEdges::new(&input.edges));
    // δ plus the rounding of the centroid and of the distance, a few ulps of the magnitude
    let reach = input.delta + 8.0 * f64::EPSILON * input.magnitude;
    let mut fails = Failures::default();
    let mut excused = 0usize;
    for &(k, t) in good {
        let [a, b, c] = t.map(|i| pts[i as usize]);
        let probe = Probe::centroid(a, b, c);
        let w = windings.at(&probe);
        let ok = match &w {
            Winding::At(w) => rule.contains(*w),
            Winding::Around(ws) => ws.iter().all(|&w| rule.contains(w)),
        };
        if ok {
            continue;
        }
        if let Some(near) = near.as_mut() {
            if near.within(probe.approx(), reach) {
                excused += 1;
                continue;
            }
        }
        fails.note(|| {
            let what = match &w {
                Winding::At(w) => format!("has winding number {w}"),
                Winding::Around(ws) => {
                    format!("lies on an input edge, with winding numbers {ws:?} round it")
                }
            };
            format!(
                "the centroid of triangle {k} ({}, {}, {}) {what}, which {} does not accept",
                t[0],
                t[1],
                t[2],
                rule.name()
            )
        });
    }
    let mut check = fails.check("inside");
    if check.passed && excused > 0 {
        check.detail = Some(format!(
            "{excused} triangle(s) outside by their centroid but within δ = {:e} of an input edge (rounded crossings)",
            input.delta
        ));
    }
    check
}

// ------------------------------------------------------------------------------------------
// area: the slab decomposition
// ------------------------------------------------------------------------------------------

/// A non-vertical input edge from left to right, with its direction in the ring: +1 when
/// the ring runs it rightwards (crossing it upwards raises the winding number by one).
#[derive(Clone, Copy, Debug)]
struct Seg {
    a: P,
    b: P,
    dir: i64,
}

/// The non-vertical edges and the pairs of them that cross properly.
/// Pairs of indices into a list of segments that cross properly.
type Crossings = Vec<(u32, u32)>;

fn segments_and_crossings(input: &FillInput) -> Result<(Vec<Seg>, Crossings), String> {
    let segs: Vec<Seg> = input
        .edges
        .iter()
        .filter(|(a, b)| a[0] != b[0])
        .map(|&(a, b)| {
            if a[0] < b[0] {
                Seg { a, b, dir: 1 }
            } else {
                Seg {
                    a: b,
                    b: a,
                    dir: -1,
                }
            }
        })
        .collect();
    let ends: Vec<(P, P)> = segs.iter().map(|s| (s.a, s.b)).collect();
    let mut crossings = Vec::new();
    let complete = for_each_crossing(&ends, |i, j| {
        crossings.push((i as u32, j as u32));
        crossings.len() <= MAX_CROSSINGS
    });
    if !complete {
        return Err(format!(
            "more than {MAX_CROSSINGS} crossings between edges: too many for the slab method"
        ));
    }
    Ok((segs, crossings))
}

/// Calls `f(i, j)` with `i < j` for every pair of `segments` that cross properly, until `f`
/// returns false; returns whether every pair was seen.
fn for_each_crossing(segments: &[(P, P)], mut f: impl FnMut(usize, usize) -> bool) -> bool {
    let bbox = bbox_of(segments.iter().flat_map(|&(a, b)| [a, b]));
    let index = SegmentIndex::new(segments, bbox);
    let mut stamps = Stamps::new(segments.len());
    let mut go_on = true;
    for (i, &(a, b)) in segments.iter().enumerate() {
        index.near_segment(a, b, &mut stamps, |j| {
            if go_on && j > i && cross_properly(a, b, segments[j].0, segments[j].1) {
                go_on = f(i, j);
            }
        });
        if !go_on {
            return false;
        }
    }
    true
}

/// The region's area, exactly when small enough (and `float` is false), else in `f64`.
fn area_of(input: &FillInput, rule: FillRule, float: bool) -> Result<FillArea, String> {
    let (segs, crossings) = segments_and_crossings(input)?;
    if !float && segs.len() <= EXACT_MAX_EDGES && crossings.len() <= EXACT_MAX_CROSSINGS {
        Ok(exact_area(&segs, &crossings, rule))
    } else {
        float_area(&segs, &crossings, rule)
    }
}

/// The x of the crossing of two segments that cross properly, exactly: in integers (the
/// eight coordinates scaled by a common power of two), one fraction reduced once.
fn crossing_x(s: &Seg, t: &Seg) -> BigRational {
    let coords = [s.a, s.b, t.a, t.b].map(|p| p.map(decode));
    let low = coords
        .iter()
        .flatten()
        .filter(|c| c.0 != 0)
        .map(|c| c.1)
        .min()
        .unwrap_or(0);
    let int = |(m, e): (i64, i32)| BigInt::from(m) << ((e - low) as usize);
    let [[ax, ay], [bx, by], [cx, cy], [dx, dy]] = coords.map(|p| p.map(int));
    let (ex, ey) = (dx - &cx, dy - &cy);
    let num = (cx - &ax) * &ey - (cy - &ay) * &ex;
    let mut den = (&bx - &ax) * &ey - (by - ay) * &ex;
    if den.is_zero() {
        // parallel segments do not cross properly: unreachable, but never divide by zero
        return rational(s.a[0]);
    }
    let mut top = &ax * &den + (bx - ax) * num;
    if den.is_negative() {
        top = -top;
        den = -den;
    }
    if low >= 0 {
        top <<= low as usize;
    } else {
        den <<= (-low) as usize;
    }
    BigRational::new(top, den)
}

/// The f64 crossing x of two segments that cross properly, clamped to their common span.
fn crossing_x_f64(s: &Seg, t: &Seg) -> f64 {
    let (ex, ey) = (t.b[0] - t.a[0], t.b[1] - t.a[1]);
    let num = (t.a[0] - s.a[0]) * ey - (t.a[1] - s.a[1]) * ex;
    let den = (s.b[0] - s.a[0]) * ey - (s.b[1] - s.a[1]) * ex;
    let x = s.a[0] + (num / den) * (s.b[0] - s.a[0]);
    let (lo, hi) = (s.a[0].max(t.a[0]), s.b[0].min(t.b[0]));
    if lo > hi {
        return lo;
    }
    if x.is_finite() {
        x.clamp(lo, hi)
    } else {
        (lo + hi) / 2.0
    }
}

/// y of `s` at `x` (inside its span), in floating point.
fn y_at(s: &Seg, x: f64) -> f64 {
    let t = (x - s.a[0]) / (s.b[0] - s.a[0]);
    s.a[1] + (s.b[1] - s.a[1]) * t
}

/// A bound on the rounding of [`y_at`] for `x` inside the segment's span (generous).
fn y_error(s: &Seg) -> f64 {
    16.0 * f64::EPSILON * (s.a[1].abs() + s.b[1].abs())
}

/// Which side of `t` segment `s` lies in slab `j`, both spanning it and crossing nowhere
/// inside it: `Less` when `s` is below. Exact: the difference `L = y_t − y_s` is linear
/// in x; its signs at the ends of the common span come from orientations, and when they
/// differ the segments cross at an x that is a slab boundary, `cross_slab` (the index of
/// that x), which says which end's sign holds in the slab.
fn exact_side(s: &Seg, t: &Seg, j: usize, cross_slab: Option<usize>) -> Ordering {
    let (a, b, c, d) = (s.a, s.b, t.a, t.b);
    let left = if a[0] >= c[0] {
        orient(c, d, a).reverse()
    } else {
        orient(a, b, c)
    };
    let right = if b[0] <= d[0] {
        orient(c, d, b).reverse()
    } else {
        orient(a, b, d)
    };
    let l = match (left, right) {
        (x, y) if x == y => x,
        (Ordering::Equal, y) => y,
        (x, Ordering::Equal) => x,
        (x, y) => match cross_slab {
            Some(k) if j < k => x,
            Some(_) => y,
            None => Ordering::Equal,
        },
    };
    l.reverse()
}

/// The slab sweep shared by both methods: calls `emit(segment, coefficient, from, to)` for
/// every run of slabs `from..to` over which the segment's coefficient in the area sum is
/// constant and non-zero. The area is `Σ coefficient · ∫ y` over the runs: in a slab, the
/// gaps whose winding the rule accepts sum `y_upper − y_lower`, so each edge's `y` counts
/// `rule(below) − rule(above)` times.
///
/// `xm(j)` is an `f64` x inside slab `j` (`None` when none is known to be), and `exact(s,
/// t, j)` orders two segments in slab `j` exactly, where filtered floating point cannot.
#[allow(clippy::too_many_arguments)]
fn sweep(
    segs: &[Seg],
    li: &[usize],
    ri: &[usize],
    slabs: usize,
    rule: FillRule,
    xm: impl Fn(usize) -> (f64, bool),
    exact: Option<&dyn Fn(usize, usize, usize) -> Ordering>,
    mut emit: impl FnMut(usize, i64, usize, usize),
) {
    let mut starting: Vec<usize> = (0..segs.len()).collect();
    starting.sort_by_key(|&i| li[i]);
    let mut next = 0;
    let mut active: Vec<usize> = Vec::new();
    let mut run_c = vec![0i64; segs.len()];
    let mut run_start = vec![0usize; segs.len()];
    let mut ys = vec![0.0f64; segs.len()];
    for j in 0..slabs {
        active.retain(|&k| {
            if ri[k] <= j {
                if run_c[k] != 0 {
                    emit(k, run_c[k], run_start[k], ri[k]);
                }
                false
            } else {
                true
            }
        });
        while next < starting.len() && li[starting[next]] <= j {
            let k = starting[next];
            if ri[k] > j {
                run_c[k] = 0;
                run_start[k] = j;
                active.push(k);
            }
            next += 1;
        }
        let (x, inside) = xm(j);
        for &k in &active {
            ys[k] = y_at(&segs[k], x);
        }
        active.sort_by(|&s, &t| ys[s].total_cmp(&ys[t]));
        if let Some(exact) = exact {
            // insertion sort by the exact order: few moves after the sort by f64
            let cmp = |s: usize, t: usize| -> Ordering {
                if inside {
                    let gap = ys[t] - ys[s];
                    let err = y_error(&segs[s]) + y_error(&segs[t]);
                    if gap > err {
                        return Ordering::Less;
                    }
                    if gap < -err {
                        return Ordering::Greater;
                    }
                }
                exact(s, t, j)
            };
            for m in 1..active.len() {
                let mut p = m;
                while p > 0 && cmp(active[p - 1], active[p]) == Ordering::Greater {
                    active.swap(p - 1, p);
                    p -= 1;
                }
            }
        }
        let mut w = 0i64;
        for &k in &active {
            let below = i64::from(rule.contains(w));
            w += segs[k].dir;
            let c = below - i64::from(rule.contains(w));
            if c != run_c[k] {
                if run_c[k] != 0 {
                    emit(k, run_c[k], run_start[k], j);
                }
                run_c[k] = c;
                run_start[k] = j;
            }
        }
    }
    for &k in &active {
        if run_c[k] != 0 {
            emit(k, run_c[k], run_start[k], ri[k]);
        }
    }
}

fn exact_area(segs: &[Seg], crossings: &[(u32, u32)], rule: FillRule) -> FillArea {
    let cross_x: Vec<BigRational> = crossings
        .iter()
        .map(|&(i, j)| crossing_x(&segs[i as usize], &segs[j as usize]))
        .collect();
    let ends: Vec<[BigRational; 4]> = segs
        .iter()
        .map(|s| [s.a[0], s.a[1], s.b[0], s.b[1]].map(rational))
        .collect();
    let mut xs: Vec<BigRational> = ends
        .iter()
        .flat_map(|e| [e[0].clone(), e[2].clone()])
        .chain(cross_x.iter().cloned())
        .collect();
    xs.sort_unstable();
    xs.dedup();
    let find = |x: &BigRational| xs.binary_search(x).unwrap_or_else(|i| i);
    let (li, ri): (Vec<usize>, Vec<usize>) =
        ends.iter().map(|e| (find(&e[0]), find(&e[2]))).unzip();
    let mut cross_slab: HashMap<(u32, u32), usize> = HashMap::with_capacity(crossings.len());
    for (&(i, j), x) in crossings.iter().zip(&cross_x) {
        let k = xs.binary_search(x).unwrap_or_else(|k| k);
        cross_slab.insert((i, j), k);
    }
    let xs_f: Vec<f64> = xs.iter().map(|x| x.to_f64().unwrap_or(0.0)).collect();
    let xm = |j: usize| -> (f64, bool) {
        let x = xs_f[j] / 2.0 + xs_f[j + 1] / 2.0;
        // strictly between the rounded ends, x is strictly inside (to_f64 rounds to
        // nearest); else ask exactly
        let inside = (xs_f[j] < x && x < xs_f[j + 1]) || {
            let r = rational(x);
            xs[j] < r && r < xs[j + 1]
        };
        (x, inside)
    };
    let exact = |s: usize, t: usize, j: usize| -> Ordering {
        let key = (s.min(t) as u32, s.max(t) as u32);
        exact_side(&segs[s], &segs[t], j, cross_slab.get(&key).copied())
    };
    // ∫_u^v (q + m x) dx = (q v + m v²/2) − (q u + m u²/2): each run adds to the
    // coefficients of its two ends, so A = Σ_i α_i x_i + β_i x_i² / 2 with small α, β,
    // and the few large denominators (the crossings') meet only in the final sum.
    let lines: Vec<(BigRational, BigRational)> = ends
        .iter()
        .map(|[ax, ay, bx, by]| {
            let slope = (by - ay) / (bx - ax);
            (ay - &slope * ax, slope)
        })
        .collect();
    let mut alpha = vec![BigRational::zero(); xs.len()];
    let mut beta = vec![BigRational::zero(); xs.len()];
    sweep(
        segs,
        &li,
        &ri,
        xs.len().saturating_sub(1),
        rule,
        xm,
        Some(&exact),
        |k, c, from, to| {
            let (q, m) = &lines[k];
            for (i, sign) in [(to, c), (from, -c)] {
                if sign > 0 {
                    alpha[i] += q;
                    beta[i] += m;
                } else {
                    alpha[i] -= q;
                    beta[i] -= m;
                }
                // |c| ≤ 1: one addition per end
            }
        },
    );
    let two = BigRational::from_integer(BigInt::from(2));
    let terms: Vec<BigRational> = xs
        .iter()
        .zip(alpha.into_iter().zip(beta))
        .filter(|(_, (a, b))| !a.is_zero() || !b.is_zero())
        .map(|(x, (a, b))| x * (a + b * x / &two))
        .collect();
    let total = sum_balanced(terms);
    FillArea {
        area: total.to_f64().unwrap_or(f64::NAN),
        exact: Some(total),
        edges: segs.len(),
        crossings: crossings.len(),
        magnitude: 0.0,
    }
}

/// Past this many bits in a denominator, [`sum_balanced`] stops reducing fractions: the
/// crossings' denominators have no common factors worth a gcd of that size.
const REDUCE_BELOW_BITS: u64 = 2048;

/// The sum of `terms`, added in pairs, then pairs of pairs, so numbers of similar size
/// meet. Small fractions are added in lowest terms; large ones (the products of the
/// crossings' denominators) are not reduced, as a gcd there costs more than it saves: the
/// result is exact but not necessarily in lowest terms (its denominator is positive).
fn sum_balanced(mut terms: Vec<BigRational>) -> BigRational {
    while terms.len() > 1 {
        let mut next = Vec::with_capacity(terms.len().div_ceil(2));
        let mut it = terms.into_iter();
        while let Some(a) = it.next() {
            next.push(match it.next() {
                Some(b) if a.denom().bits().max(b.denom().bits()) < REDUCE_BELOW_BITS => a + b,
                Some(b) if a.denom() == b.denom() => {
                    BigRational::new_raw(a.numer() + b.numer(), a.denom().clone())
                }
                Some(b) => BigRational::new_raw(
                    a.numer() * b.denom() + b.numer() * a.denom(),
                    a.denom() * b.denom(),
                ),
                None => a,
            });
        }
        terms = next;
    }
    terms.pop().unwrap_or_else(BigRational::zero)
}

fn float_area(segs: &[Seg], crossings: &[(u32, u32)], rule: FillRule) -> Result<FillArea, String> {
    let mut xs: Vec<f64> = segs
        .iter()
        .flat_map(|s| [s.a[0], s.b[0]])
        .chain(
            crossings
                .iter()
                .map(|&(i, j)| crossing_x_f64(&segs[i as usize], &segs[j as usize])),
        )
        .collect();
    xs.sort_unstable_by(f64::total_cmp);
    xs.dedup();
    let find = |x: f64| xs.partition_point(|&v| v < x);
    let (li, ri): (Vec<usize>, Vec<usize>) =
        segs.iter().map(|s| (find(s.a[0]), find(s.b[0]))).unzip();
    let work: u64 = li
        .iter()
        .zip(&ri)
        .map(|(&l, &r)| r.saturating_sub(l) as u64)
        .sum();
    if work > FLOAT_MAX_WORK {
        return Err(format!(
            "the slab decomposition would visit {work} edge–slab pairs (over {FLOAT_MAX_WORK})"
        ));
    }
    // y measured from the lowest point: the same area, smaller terms
    let y0 = segs
        .iter()
        .fold(f64::INFINITY, |m, s| m.min(s.a[1]).min(s.b[1]));
    let (mut total, mut magnitude) = (0.0f64, 0.0f64);
    sweep(
        segs,
        &li,
        &ri,
        xs.len().saturating_sub(1),
        rule,
        |j| (xs[j] / 2.0 + xs[j + 1] / 2.0, true),
        None,
        |k, c, from, to| {
            let (u, v) = (xs[from], xs[to]);
            let s = &segs[k];
            let term = (v - u) * ((y_at(s, u) - y0) + (y_at(s, v) - y0)) / 2.0;
            total += c as f64 * term;
            magnitude += term.abs();
        },
    );
    Ok(FillArea {
        area: total,
        exact: None,
        edges: segs.len(),
        crossings: crossings.len(),
        magnitude,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Probe {
        Probe::point([x, y])
    }

    #[test]
    fn sectors_round_a_crossing() {
        // two diagonals of the bow tie crossing at (1, 1)
        let probe = p(1.0, 1.0);
        let on = [([0.0, 0.0], [2.0, 2.0]), ([2.0, 0.0], [0.0, 2.0])];
        // east of (1, 1), between the diagonals: the right wing (clockwise, −1)
        let values = sectors(&probe, -1, &on);
        assert_eq!(values.len(), 5);
        let mut sorted = values.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted, vec![-1, 0, 1]);
        assert_eq!(values[0], -1);
        assert_eq!(values[4], -1);
    }

    #[test]
    fn dyadic_sums_are_exact() {
        let mut d = Dyadic::default();
        d.add_product(0.1, 0.1);
        d.add_product(-0.1, 0.1);
        let value = |d: &Dyadic| {
            let (n, d) = d.fraction(0);
            BigRational::new(n, d)
        };
        assert!(value(&d).is_zero());
        d.add_product(1e-300, 1e-300);
        d.add_product(3.0, 1e300);
        assert!(value(&d) > rational(2.9e300));
        assert_eq!(decode(-1.5), (-(3i64 << 51), -52));
        assert_eq!(decode(0.0), (0, -1074));
    }

    /// The sweep finds an overlap exactly when some pair overlaps, on random sets of
    /// triangles over a coarse grid: shared corners, shared and collinear edges, vertical
    /// edges, T-junctions, duplicates.
    #[test]
    fn the_overlap_sweep_agrees_with_testing_every_pair() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg64::seed_from_u64(7);
        let mut overlapping = 0;
        for round in 0..4000 {
            let side = 2 + (round % 4) as i32;
            let count = 2 + round % 7;
            let mut pts = Vec::new();
            let mut tris = Vec::new();
            while tris.len() < count {
                let t: [u32; 3] = [0; 3].map(|_| {
                    pts.push([
                        f64::from(rng.random_range(0..=side)),
                        f64::from(rng.random_range(0..=side)),
                    ]);
                    (pts.len() - 1) as u32
                });
                let [a, b, c] = t.map(|i| pts[i as usize]);
                match orient(a, b, c) {
                    Ordering::Greater => tris.push((tris.len(), t)),
                    Ordering::Less => tris.push((tris.len(), [t[0], t[2], t[1]])),
                    Ordering::Equal => {}
                }
            }
            let corners = |i: usize| tris[i].1.map(|v| pts[v as usize]);
            let brute =
                (0..count).any(|i| (i + 1..count).any(|j| interiors_meet(corners(i), corners(j))));
            let swept = !overlap(&pts, &tris).passed;
            assert_eq!(
                swept,
                brute,
                "round {round}: {:?}",
                (0..count).map(corners).collect::<Vec<_>>()
            );
            overlapping += usize::from(brute);
        }
        assert!(overlapping > 500 && overlapping < 3900, "{overlapping}");
    }

    /// Valid meshes (a grid of squares cut into triangles, both diagonals in turn) pass.
    #[test]
    fn the_overlap_sweep_accepts_a_mesh() {
        let n = 12;
        let mut pts = Vec::new();
        for y in 0..=n {
            for x in 0..=n {
                pts.push([f64::from(x), f64::from(y)]);
            }
        }
        let at = |x: u32, y: u32| y * (n + 1) + x;
        let mut tris = Vec::new();
        for y in 0..n {
            for x in 0..n {
                let (a, b, c, d) = (at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y + 1));
                if (x + y) % 2 == 0 {
                    tris.extend([[a, b, c], [a, c, d]]);
                } else {
                    tris.extend([[a, b, d], [b, c, d]]);
                }
            }
        }
        let tris: Vec<(usize, [u32; 3])> = tris.into_iter().enumerate().collect();
        assert!(overlap(&pts, &tris).passed);
        let mut doubled = tris.clone();
        doubled.push((tris.len(), [at(3, 3), at(5, 3), at(4, 5)]));
        assert!(!overlap(&pts, &doubled).passed);
    }
}
