//! The input as the checks see it: which points coincide, the boundary cut into atomic
//! pieces, the winding function, and whether the input is a valid polygon set at all.
//!
//! ## Validity
//!
//! Every ring `r` gets a factor `f_r = ±1`: its role's sign (outer +1, hole −1) times the
//! sign of its exact shoelace area (+1 for a ring of zero area). The region's winding
//! function is `w(p) = Σ_r f_r · winding_r(p)`; the region is where `w = 1`. An input is
//! valid when
//!
//! 1. the structure is sound (ring starts from 0, strictly increasing, in range; one role
//!    per ring) and every coordinate is finite and within the exact range
//!    ([`MAX_COORDINATE`], [`MIN_COORDINATE`]);
//! 2. no two ring edges cross at a point interior to both (touching at vertices, T-junctions
//!    and edges overlapping along a segment are all allowed);
//! 3. each ring of non-zero area has a role that agrees with its containment depth (the
//!    number of other such rings it lies inside): even for outer rings, odd for holes. With
//!    [`Nesting::Auto`] the depth assigns the role;
//! 4. around every vertex, the values of `w` in the sectors between the boundary edges
//!    through it span at most two consecutive integers;
//! 5. and those values are 0 or 1.
//!
//! (2) and (3) make the rings a laminar family whose signed windings alternate
//! 1, 0, 1, … with depth; (4) rules out rings that wind twice or touch themselves with lobes
//! of opposite orientation (a bow tie pinched at a vertex) with a message that says where;
//! (5) also catches lobes of opposite orientation joined by a wall the ring runs along in
//! both directions, where every vertex sees only two consecutive values but one lobe has
//! `w = −1`. Every face of the arrangement has a vertex on its boundary, so together they
//! give `w ∈ {0, 1}` everywhere, and the region's area is exactly `½ Σ_r f_r · shoelace_r`.

use std::cmp::Ordering;
use std::collections::HashMap;
use std::f64::consts::PI;

use crate::exact::{
    cmp_around, cross_properly, orient, strictly_inside_segment, winding_step, Exact, Probe,
    MAX_COORDINATE, MIN_COORDINATE, P,
};
use crate::grid::{bbox_of, PointIndex, SegmentIndex, Stamps};
use crate::input::{Input, Nesting, Role};

/// How many problems of the input are spelled out; the rest are only counted.
const MAX_PROBLEMS: usize = 1;

/// Per position, its sectors as [`Region::vertex_star`] found them.
#[derive(Default)]
struct Stars {
    /// Per sorted star entry: the index of its direction group at its position.
    group: Vec<u32>,
    /// Per position, consecutively: the value of each sector relative to the sector
    /// before the first ray.
    sums: Vec<i64>,
    first_sum: HashMap<u32, usize>,
    first_sum_end: HashMap<u32, usize>,
}

/// A ring's points without repeats (cyclically) and without the tips of zero-width
/// spikes (a point whose two neighbours lie on one ray from it), removed until none is
/// left; fewer than three points when nothing encloses area.
fn without_spikes(mut ring: Vec<P>) -> Vec<P> {
    let mut k = 0;
    let mut steady = 0;
    while ring.len() >= 3 && steady < ring.len() {
        let len = ring.len();
        let (u, c, w) = (
            ring[(k + len - 1) % len],
            ring[k % len],
            ring[(k + 1) % len],
        );
        let spike = c == w
            || (orient(u, c, w) == Ordering::Equal
                && (u[0] - c[0]).signum() == (w[0] - c[0]).signum()
                && (u[1] - c[1]).signum() == (w[1] - c[1]).signum());
        if spike {
            ring.remove(k % len);
            // the point before may have become a tip: look again from there
            k = (k + len - 2) % (len - 1);
            steady = 0;
        } else {
            k = (k + 1) % len;
            steady += 1;
        }
    }
    ring
}

/// `a` before `b` by x, then y.
fn lex_less(a: P, b: P) -> bool {
    (a[0], a[1]) < (b[0], b[1])
}

/// One ring edge of non-zero length, as vertex indices into the input.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RingEdge {
    pub a: u32,
    pub b: u32,
    pub ring: u32,
}

/// The input prepared for the checks.
#[derive(Debug)]
pub(crate) struct Region {
    /// The input's points.
    pub pts: Vec<P>,
    /// For every vertex, the smallest index of a vertex at the same position: positions
    /// are named by that representative, so messages still speak of input indices.
    pub rep: Vec<u32>,
    /// Everything can be computed exactly: the structure is sound and the coordinates in
    /// range. When false, only checks that need no geometry run.
    pub usable: bool,
    /// What makes the input invalid (empty when valid).
    pub problems: Vec<String>,
    /// How many problems there were (only the first few are spelled out).
    pub problem_count: usize,
    /// Per ring: its factor `f_r` (see the module docs).
    pub factor: Vec<i32>,
    /// Per ring: its role, given or by depth.
    pub roles: Vec<Role>,
    /// Every ring edge of non-zero length.
    pub edges: Vec<RingEdge>,
    /// Atomic boundary pieces (consecutive positions along ring edges), keyed by
    /// `(min rep, max rep)`, with the net jump of `w` across them in that direction
    /// (`w` left of `min → max` minus `w` right of it).
    pub pieces: HashMap<(u32, u32), i32>,
    /// Per edge of [`Region::edges`]: every piece of it has net jump 0 — a wall or spike
    /// walked both ways, or an edge of a zero-area ring. Such an edge bounds nothing
    /// (`w` is the same on both sides), so a triangulation may cross it.
    pub zero_width: Vec<bool>,
    /// Per edge of [`Region::edges`], its positions from end to end with those lying on it
    /// in between (representatives): `chains[chain_starts[i]..chain_starts[i + 1]]`.
    chains: Vec<u32>,
    chain_starts: Vec<usize>,
    /// Per representative: the region's angle there in radians (`NaN` for positions on no
    /// boundary piece; `2π` stands for "same value all around", see [`Region::angle_sum`]).
    pub theta: Vec<f64>,
    /// Twice the region's area, exactly: `Σ_r f_r · shoelace_r`.
    pub area2: Exact,
    points: Option<PointIndex>,
    segments: Option<SegmentIndex>,
    /// Largest coordinate magnitude, for filter bounds.
    magnitude: f64,
}

impl Region {
    /// Prepares `input`; never panics, whatever it holds.
    pub(crate) fn build(input: &Input) -> Region {
        let mut region = Region {
            pts: input.vertices.clone(),
            rep: Vec::new(),
            usable: false,
            problems: Vec::new(),
            problem_count: 0,
            factor: Vec::new(),
            roles: Vec::new(),
            edges: Vec::new(),
            pieces: HashMap::new(),
            zero_width: Vec::new(),
            chains: Vec::new(),
            chain_starts: Vec::new(),
            theta: Vec::new(),
            area2: Exact::default(),
            points: None,
            segments: None,
            magnitude: 0.0,
        };
        region.rep = representatives(&region.pts);
        if !region.check_structure(input) {
            return region;
        }
        region.usable = true;
        region.collect_edges(input);
        let bbox = bbox_of(region.pts.iter().copied());
        region.magnitude = bbox.iter().fold(0.0, |m: f64, v| m.max(v.abs()));
        region.points = Some(PointIndex::new(&region.pts, bbox));
        let segments: Vec<(P, P)> = region
            .edges
            .iter()
            .map(|e| (region.pts[e.a as usize], region.pts[e.b as usize]))
            .collect();
        region.segments = Some(SegmentIndex::new(&segments, bbox));
        region.find_crossings();
        let areas = region.ring_areas(input);
        region.assign_roles(input, &areas);
        region.build_pieces();
        for (r, area) in areas.iter().enumerate() {
            region.area2.add_exact(area, f64::from(region.factor[r]));
        }
        region
    }

    fn problem(&mut self, what: impl FnOnce() -> String) {
        if self.problems.len() < MAX_PROBLEMS {
            self.problems.push(what());
        }
        self.problem_count += 1;
    }

    /// Condition 1; true when the geometry can be computed with.
    fn check_structure(&mut self, input: &Input) -> bool {
        let n = self.pts.len();
        let starts = &input.ring_starts;
        if u32::try_from(n).is_err() {
            self.problem(|| format!("{n} vertices are more than u32 indices can address"));
            return false;
        }
        if starts.is_empty() && n > 0 {
            self.problem(|| format!("{n} vertices but no ring starts"));
            return false;
        }
        if let Some(&first) = starts.first() {
            if first != 0 {
                self.problem(|| format!("ring 0 starts at vertex {first}, not 0"));
                return false;
            }
        }
        if let Some(r) = (1..starts.len()).find(|&r| starts[r] <= starts[r - 1]) {
            self.problem(|| format!("ring starts are not strictly increasing at ring {r}"));
            return false;
        }
        if let Some(&last) = starts.last() {
            if last >= n {
                self.problem(|| format!("the last ring starts at {last}, beyond the {n} vertices"));
                return false;
            }
        }
        if let Nesting::Roles(roles) = &input.nesting {
            if roles.len() != starts.len() {
                let (given, rings) = (roles.len(), starts.len());
                self.problem(|| format!("{given} roles for {rings} rings"));
                return false;
            }
        }
        let bad = self.pts.iter().position(|p| {
            p.iter().any(|&c| {
                !c.is_finite() || c.abs() > MAX_COORDINATE || (c != 0.0 && c.abs() < MIN_COORDINATE)
            })
        });
        if let Some(v) = bad {
            let p = self.pts[v];
            self.problem(|| {
                format!(
                    "vertex {v} ({}, {}) is not finite or outside the exactly computable range \
                     [{MIN_COORDINATE:e}, {MAX_COORDINATE:e}]",
                    p[0], p[1]
                )
            });
            return false;
        }
        true
    }

    fn collect_edges(&mut self, input: &Input) {
        for r in 0..input.ring_count() {
            let range = input.ring_range(r);
            for i in range.clone() {
                let j = if i + 1 == range.end {
                    range.start
                } else {
                    i + 1
                };
                let (a, b) = (self.rep[i], self.rep[j]);
                if a != b {
                    // Fits: check_structure made sure every index fits in u32.
                    self.edges.push(RingEdge {
                        a: i as u32,
                        b: j as u32,
                        ring: r as u32,
                    });
                }
            }
        }
    }

    /// Condition 2: no two ring edges cross properly.
    fn find_crossings(&mut self) {
        let Some(index) = &self.segments else { return };
        let mut stamps = Stamps::new(self.edges.len());
        let mut found = None;
        let mut count = 0;
        for (i, e) in self.edges.iter().enumerate() {
            let (a, b) = (self.pts[e.a as usize], self.pts[e.b as usize]);
            index.near_segment(a, b, &mut stamps, |j| {
                if j > i {
                    let f = self.edges[j];
                    if cross_properly(a, b, self.pts[f.a as usize], self.pts[f.b as usize]) {
                        count += 1;
                        found.get_or_insert((*e, f));
                    }
                }
            });
        }
        if let Some((e, f)) = found {
            self.problem(|| {
                format!(
                    "edges {}→{} (ring {}) and {}→{} (ring {}) cross",
                    e.a, e.b, e.ring, f.a, f.b, f.ring
                )
            });
            self.problem_count += count - 1;
        }
    }

    /// Twice each ring's signed area, exactly.
    fn ring_areas(&self, input: &Input) -> Vec<Exact> {
        (0..input.ring_count())
            .map(|r| {
                let range = input.ring_range(r);
                let mut e = Exact::default();
                for i in range.clone() {
                    let j = if i + 1 == range.end {
                        range.start
                    } else {
                        i + 1
                    };
                    e.add_cross(self.pts[i], self.pts[j]);
                }
                e
            })
            .collect()
    }

    /// Condition 3, and the factors.
    fn assign_roles(&mut self, input: &Input, areas: &[Exact]) {
        let rings = input.ring_count();
        let signs: Vec<i32> = areas
            .iter()
            .map(|a| match a.clone().sign() {
                Ordering::Less => -1,
                Ordering::Equal => 0,
                Ordering::Greater => 1,
            })
            .collect();
        let depth = self.depths(input, &signs);
        self.roles = (0..rings)
            .map(|r| match &input.nesting {
                Nesting::Auto => {
                    if depth[r].is_multiple_of(2) {
                        Role::Outer
                    } else {
                        Role::Hole
                    }
                }
                Nesting::FirstIsOuter if r == 0 => Role::Outer,
                Nesting::FirstIsOuter => Role::Hole,
                Nesting::Roles(roles) => roles[r],
            })
            .collect();
        for r in 0..rings {
            let even = depth[r].is_multiple_of(2);
            if signs[r] != 0 && (self.roles[r] == Role::Outer) != even {
                let (role, d) = (self.roles[r], depth[r]);
                self.problem(|| format!("ring {r} is {role:?} but lies inside {d} other ring(s)"));
            }
        }
        self.factor = (0..rings)
            .map(|r| {
                let role = if self.roles[r] == Role::Outer { 1 } else { -1 };
                role * if signs[r] == 0 { 1 } else { signs[r] }
            })
            .collect();
    }

    /// The containment depth of every ring of non-zero area among the others (0 for rings
    /// of zero area, which contain nothing).
    fn depths(&mut self, input: &Input, signs: &[i32]) -> Vec<usize> {
        let rings = input.ring_count();
        let mut depth = vec![0; rings];
        let mut stamps = Stamps::new(self.edges.len());
        for r in 0..rings {
            if signs[r] == 0 {
                continue;
            }
            let range = input.ring_range(r);
            let len = range.len();
            // Probes: the ring's vertices, then its edge midpoints. A probe decides ring q
            // when it is not on q; rings do not cross, so any such probe gives the answer.
            // Last, for a ring lying entirely on another one (a hole cancelling a lobe of
            // its outer ring): a point inside the ring, off its boundary.
            let probes = (0..2 * len)
                .map(|k| {
                    let i = range.start + k % len;
                    if k < len {
                        Probe::point(self.pts[i])
                    } else {
                        let j = if i + 1 == range.end {
                            range.start
                        } else {
                            i + 1
                        };
                        Probe::mid(self.pts[i], self.pts[j])
                    }
                })
                .chain(std::iter::once_with(|| self.inner_probe(range.clone())).flatten());
            let mut unresolved: Option<Vec<u32>> = None;
            for probe in probes {
                let windings = self.windings_by_ring(&probe, &mut stamps);
                let pending = match &unresolved {
                    None => windings
                        .iter()
                        .filter(|&(&q, w)| q as usize != r && signs[q as usize] != 0 && w.is_none())
                        .map(|(&q, _)| q)
                        .collect::<Vec<_>>(),
                    Some(u) => u
                        .iter()
                        .copied()
                        .filter(|q| windings.get(q).is_some_and(Option::is_none))
                        .collect(),
                };
                for (&q, w) in &windings {
                    let newly = unresolved.as_ref().is_none_or(|u| u.contains(&q));
                    if q as usize != r
                        && signs[q as usize] != 0
                        && newly
                        && w.is_some_and(|w| w != 0)
                    {
                        depth[r] += 1;
                    }
                }
                let done = pending.is_empty();
                unresolved = Some(pending);
                if done {
                    break;
                }
            }
            if let Some(&q) = unresolved.as_ref().and_then(|u| u.first()) {
                self.problem(|| format!("ring {r} lies entirely on ring {q}"));
            }
        }
        depth
    }

    /// A point strictly inside the ring `range` and off its boundary, when the corner
    /// triangle at its lowest (then leftmost) vertex is empty: then no ring edge enters
    /// that triangle (it would have to cross one of the corner's edges or end inside), so
    /// the triangle's centroid lies inside. Zero-width spikes enclose nothing, so the
    /// corner is taken on the ring without them (a spike's tip may be the lowest point).
    fn inner_probe(&self, range: std::ops::Range<usize>) -> Option<Probe> {
        let pts = &self.pts;
        let ring = without_spikes(range.clone().map(|i| pts[i]).collect());
        let low = |p: &P| (p[1], p[0]);
        let k = (0..ring.len()).min_by(|&i, &j| {
            low(&ring[i])
                .partial_cmp(&low(&ring[j]))
                .unwrap_or(Ordering::Equal)
        })?;
        let len = ring.len();
        let (u, c, w) = (ring[(k + len - 1) % len], ring[k], ring[(k + 1) % len]);
        let turn = orient(u, c, w);
        if turn == Ordering::Equal {
            return None;
        }
        let inside_or_on_uw = |p: P| {
            let o = [orient(u, c, p), orient(c, w, p), orient(w, u, p)];
            o.iter().all(|&s| s == turn || s == Ordering::Equal)
                && o[0] != Ordering::Equal
                && o[1] != Ordering::Equal
        };
        let blocked = range.clone().any(|i| {
            let p = pts[i];
            p != u && p != c && p != w && inside_or_on_uw(p)
        });
        (!blocked).then(|| Probe::centroid(u, c, w))
    }

    /// The winding number of every ring whose edges the ray from `probe` may meet; `None`
    /// for rings the probe lies on. Rings left out have winding 0 there.
    pub(crate) fn windings_by_ring(
        &self,
        probe: &Probe,
        stamps: &mut Stamps,
    ) -> HashMap<u32, Option<i64>> {
        let mut out: HashMap<u32, Option<i64>> = HashMap::new();
        self.for_each_step(probe, stamps, |_, e, step| {
            let slot = out.entry(e.ring).or_insert(Some(0));
            *slot = match (*slot, step) {
                (Some(w), Some(s)) => Some(w + s),
                _ => None,
            };
        });
        out
    }

    /// Calls `f` with every ring edge the ray from `probe` may meet and its winding step
    /// (`None`: the probe lies on it). The ray runs along the axis direction that leaves
    /// the grid soonest; the winding number does not depend on it.
    fn for_each_step(
        &self,
        probe: &Probe,
        stamps: &mut Stamps,
        mut f: impl FnMut(usize, RingEdge, Option<i64>),
    ) {
        let Some(index) = &self.segments else { return };
        let p = probe.approx();
        // The rounded mean is within a few ulps of the magnitude; a wide margin is cheap.
        let margin = if probe.exact_point().is_some() {
            0.0
        } else {
            16.0 * f64::EPSILON * self.magnitude
        };
        let (lo, hi) = (
            [p[0] - margin, p[1] - margin],
            [p[0] + margin, p[1] + margin],
        );
        let ray = index.shortest_ray(lo, hi);
        let turned = probe.map(|q| ray.to_right(q));
        // The box in the turned frame, for the filter below.
        let t = ray.to_right(p);
        let (tlo, thi) = (
            [t[0] - margin, t[1] - margin],
            [t[0] + margin, t[1] + margin],
        );
        index.near_ray(lo, hi, ray, stamps, |i| {
            let e = self.edges[i];
            let a = ray.to_right(self.pts[e.a as usize]);
            let b = ray.to_right(self.pts[e.b as usize]);
            // Filter: entirely above, below or left of the probe's box, the segment can
            // neither hold the probe nor cross the ray.
            if (a[1] > thi[1] && b[1] > thi[1])
                || (a[1] < tlo[1] && b[1] < tlo[1])
                || (a[0] < tlo[0] && b[0] < tlo[0])
            {
                return;
            }
            f(i, e, winding_step(a, b, &turned));
        });
    }

    /// The region's winding function at `probe`, `None` on a ring edge that bounds the
    /// region (on a zero-width edge `w` is the same as on either side of it).
    pub(crate) fn winding(&self, probe: &Probe, stamps: &mut Stamps) -> Option<i64> {
        let mut w = Some(0);
        self.for_each_step(probe, stamps, |i, e, step| {
            if step.is_none() && self.on_zero_width_piece(i, probe) {
                return;
            }
            w = match (w, step) {
                (Some(w), Some(s)) => Some(w + s * i64::from(self.factor[e.ring as usize])),
                _ => None,
            };
        });
        w
    }

    /// Edge `i` as its chain of positions (see [`Region::chains`]).
    fn chain(&self, i: usize) -> &[u32] {
        &self.chains[self.chain_starts[i]..self.chain_starts[i + 1]]
    }

    /// Whether the piece `u v` has net jump 0.
    fn zero_piece(&self, u: u32, v: u32) -> bool {
        self.pieces.get(&(u.min(v), u.max(v))) == Some(&0)
    }

    /// Whether segment `a b`, which crosses edge `i` properly, does so on a piece of it with
    /// net jump 0 (the segment meets the edge's line once, so then nowhere else), or
    /// through a position between two such pieces.
    pub(crate) fn crosses_zero_width_piece(&self, i: usize, a: P, b: P) -> bool {
        let chain = self.chain(i);
        chain.windows(2).enumerate().any(|(k, w)| {
            let (from, to) = (w[0], w[1]);
            self.zero_piece(from, to)
                && (cross_properly(a, b, self.pts[from as usize], self.pts[to as usize])
                    || chain.get(k + 2).is_some_and(|&after| {
                        self.zero_piece(to, after)
                            && strictly_inside_segment(a, b, self.pts[to as usize])
                    }))
        })
    }

    /// Whether `probe`, lying on edge `i`, lies on a piece of it with net jump 0.
    fn on_zero_width_piece(&self, i: usize, probe: &Probe) -> bool {
        if self.zero_width.get(i) == Some(&true) {
            return true;
        }
        for w in self.chain(i).windows(2) {
            let (p, q) = (self.pts[w[0] as usize], self.pts[w[1] as usize]);
            if probe.on_segment(p, q) {
                // On a shared endpoint of two pieces: a vertex, where the boundary is.
                let at_end = probe.exact_point().is_some_and(|x| x == p || x == q);
                return !at_end && self.zero_piece(w[0], w[1]);
            }
        }
        false
    }

    /// Scratch for [`Region::winding`] and [`Region::segments_near`].
    pub(crate) fn stamps(&self) -> Stamps {
        Stamps::new(self.edges.len())
    }

    /// Calls `f` with every ring edge that may meet segment `a b`.
    pub(crate) fn segments_near(&self, a: P, b: P, stamps: &mut Stamps, f: impl FnMut(usize)) {
        if let Some(index) = &self.segments {
            index.near_segment(a, b, stamps, f);
        }
    }

    /// The representatives of the positions strictly inside segment `a b` (representatives
    /// themselves), in order from `a` to `b`, into `out`.
    pub(crate) fn split(&self, a: u32, b: u32, out: &mut Vec<u32>) {
        out.clear();
        let Some(index) = &self.points else { return };
        let (pa, pb) = (self.pts[a as usize], self.pts[b as usize]);
        index.near_segment(pa, pb, |i| {
            if strictly_inside_segment(pa, pb, self.pts[i]) {
                out.push(self.rep[i]);
            }
        });
        if out.len() > 1 {
            // Collinear points sort along the segment by the coordinate that changes.
            let axis = usize::from(pa[0] == pb[0]);
            let forward = pa[axis] < pb[axis];
            out.sort_unstable_by(|&i, &j| {
                let o = self.pts[i as usize][axis].total_cmp(&self.pts[j as usize][axis]);
                if forward {
                    o
                } else {
                    o.reverse()
                }
            });
            out.dedup();
        }
    }

    /// The pieces and stars of the boundary, then conditions 4 and 5 and the angles.
    fn build_pieces(&mut self) {
        let mut stars: Vec<(u32, u32, i32)> = Vec::with_capacity(2 * self.edges.len());
        let mut inside = Vec::new();
        self.chains.clear();
        self.chain_starts.clear();
        for e in &self.edges {
            let (a, b) = (self.rep[e.a as usize], self.rep[e.b as usize]);
            self.split(a, b, &mut inside);
            self.chain_starts.push(self.chains.len());
            self.chains.push(a);
            self.chains.extend_from_slice(&inside);
            self.chains.push(b);
        }
        self.chain_starts.push(self.chains.len());
        for (i, e) in self.edges.iter().enumerate() {
            let f = self.factor[e.ring as usize];
            let chain = &self.chains[self.chain_starts[i]..self.chain_starts[i + 1]];
            for w in chain.windows(2) {
                let (u, v) = (w[0], w[1]);
                let key = (u.min(v), u.max(v));
                *self.pieces.entry(key).or_insert(0) += if u < v { f } else { -f };
                stars.push((u, v, f));
                stars.push((v, u, -f));
            }
        }
        let pts = &self.pts;
        stars.sort_unstable_by(|x, y| {
            x.0.cmp(&y.0)
                .then_with(|| cmp_around(pts[x.0 as usize], pts[x.1 as usize], pts[y.1 as usize]))
        });
        self.theta = vec![f64::NAN; self.pts.len()];
        let mut stars_of = Stars::default();
        let mut i = 0;
        while i < stars.len() {
            let at = stars[i].0;
            let mut j = i;
            while j < stars.len() && stars[j].0 == at {
                j += 1;
            }
            self.vertex_star(at, &stars[i..j], &mut stars_of);
            i = j;
        }
        self.check_absolute_winding(&stars, &stars_of);
        self.zero_width = (0..self.edges.len())
            .map(|i| {
                self.chain(i)
                    .windows(2)
                    .all(|w| self.zero_piece(w[0], w[1]))
            })
            .collect();
    }

    /// Condition 4 at one position, and the region's angle there; records the position's
    /// sectors in `out` for condition 5.
    fn vertex_star(&mut self, at: u32, star: &[(u32, u32, i32)], out: &mut Stars) {
        let x = self.pts[at as usize];
        // Group rays of equal direction: no sector lies between them.
        let mut groups: Vec<(P, i64)> = Vec::new();
        for &(_, toward, jump) in star {
            let d = self.pts[toward as usize];
            match groups.last_mut() {
                Some(g) if cmp_around(x, g.0, d) == Ordering::Equal => g.1 += i64::from(jump),
                _ => groups.push((d, i64::from(jump))),
            }
            out.group.push((groups.len() - 1) as u32);
        }
        let mut sums = Vec::with_capacity(groups.len());
        let mut s = 0;
        for g in &groups {
            s += g.1;
            sums.push(s);
        }
        out.first_sum.insert(at, out.sums.len());
        out.sums.extend_from_slice(&sums);
        out.first_sum_end.insert(at, out.sums.len());
        let (lo, hi) = (
            sums.iter().copied().min().unwrap_or(0),
            sums.iter().copied().max().unwrap_or(0),
        );
        if hi - lo > 1 {
            self.problem(|| {
                format!("the winding number around vertex {at} takes {} values: rings wind twice or cross there", hi - lo + 1)
            });
        }
        if hi == lo {
            // Same value all around: either inside (2π) or outside (0); only the
            // triangulation's use of the vertex tells, see `angle_sum`.
            self.theta[at as usize] = 2.0 * PI;
            return;
        }
        // Directions in [0, 2π), in the exact order of cmp_around; rounding can only
        // swap nearly equal angles, so negative differences are clamped to zero.
        let angle = |d: P| {
            let a = (d[1] - x[1]).atan2(d[0] - x[0]);
            if a < 0.0 {
                a + 2.0 * PI
            } else {
                a
            }
        };
        let m = groups.len();
        let mut theta = 0.0;
        for k in 0..m {
            if sums[k] != hi {
                continue;
            }
            // Sector k runs counter-clockwise from group k to group k + 1.
            let from = angle(groups[k].0);
            let sector = if k + 1 < m {
                angle(groups[k + 1].0) - from
            } else {
                2.0 * PI - from + angle(groups[0].0)
            };
            theta += sector.max(0.0);
        }
        self.theta[at as usize] = theta;
    }

    /// Condition 5: `w ∈ {0, 1}` in every sector around every position, absolutely.
    ///
    /// Conditions 1–4 only see differences of `w`. Lobes of opposite orientation joined by
    /// a wall the ring runs along twice (in opposite directions, so the wall cancels) pass
    /// all four, yet `w` is 1 in one lobe and −1 in the other. So: the value of sector `k`
    /// at position `x` is `base[x] + sums_x[k]`; the face left of a piece `u → v` is one
    /// face at both ends, which ties `base[v]` to `base[u]` through the boundary graph; and
    /// one winding query per connected component fixes its base absolutely.
    fn check_absolute_winding(&mut self, stars: &[(u32, u32, i32)], s: &Stars) {
        let index_of: HashMap<(u32, u32), usize> = stars
            .iter()
            .enumerate()
            .map(|(i, &(u, v, _))| ((u, v), i))
            .collect();
        let mut first = HashMap::with_capacity(s.first_sum.len());
        for (i, &(u, _, _)) in stars.iter().enumerate() {
            first.entry(u).or_insert(i);
        }
        // Sector values relative to the sector before the first ray (which closes at 0).
        let sums = |x: u32| &s.sums[s.first_sum[&x]..s.first_sum_end[&x]];
        let mut base: HashMap<u32, i64> = HashMap::with_capacity(first.len());
        let mut component: HashMap<u32, u32> = HashMap::with_capacity(first.len());
        let mut roots = Vec::new();
        let mut order: Vec<u32> = first.keys().copied().collect();
        order.sort_unstable();
        let mut queue = Vec::new();
        for &start in &order {
            if component.contains_key(&start) {
                continue;
            }
            let c = roots.len() as u32;
            component.insert(start, c);
            base.insert(start, 0);
            queue.push(start);
            let mut root = start;
            while let Some(u) = queue.pop() {
                if lex_less(self.pts[u as usize], self.pts[root as usize]) {
                    root = u;
                }
                let mut i = first[&u];
                while i < stars.len() && stars[i].0 == u {
                    let v = stars[i].1;
                    if let std::collections::hash_map::Entry::Vacant(slot) = component.entry(v) {
                        slot.insert(c);
                        let back = index_of[&(v, u)];
                        let (su, sv) = (sums(u), sums(v));
                        let left_at_u = su[s.group[i] as usize];
                        let gv = s.group[back] as usize;
                        let left_at_v = sv[(gv + sv.len() - 1) % sv.len()];
                        base.insert(v, base[&u] + left_at_u - left_at_v);
                        queue.push(v);
                    }
                    i += 1;
                }
            }
            roots.push(root);
        }
        // Per component: at its lexicographically smallest position p every ray points
        // right or straight up, so the sector containing the direction π is next to p on
        // the left, where the component itself winds 0 and the others wind as at p.
        let mut offset = vec![0i64; roots.len()];
        let mut stamps = self.stamps();
        for (c, &p) in roots.iter().enumerate() {
            let mut w = 0i64;
            self.for_each_step(
                &Probe::point(self.pts[p as usize]),
                &mut stamps,
                |_, e, step| {
                    if component.get(&self.rep[e.a as usize]) != Some(&(c as u32)) {
                        w += step.unwrap_or(0) * i64::from(self.factor[e.ring as usize]);
                    }
                },
            );
            let (x, ps) = (self.pts[p as usize], sums(p));
            // Rays at p in counter-clockwise order from angle 0: those with dy ≥ 0 first.
            let mut k = ps.len() - 1;
            let mut g = 0;
            let mut i = first[&p];
            let mut last = None;
            while i < stars.len() && stars[i].0 == p {
                let d = self.pts[stars[i].1 as usize];
                if d[1] >= x[1] && last != Some(s.group[i]) {
                    k = g;
                    g += 1;
                }
                last = Some(s.group[i]);
                i += 1;
            }
            offset[c] = w - (base[&p] + ps[k]);
        }
        for &x in &order {
            let b = base[&x] + offset[component[&x] as usize];
            let bad = sums(x)
                .iter()
                .map(|&d| b + d)
                .find(|w| !(0..=1).contains(w));
            if let Some(w) = bad {
                self.problem(|| {
                    format!("the winding number next to vertex {x} is {w}, not 0 or 1: a ring winds twice, or has lobes of opposite orientation")
                });
            }
        }
    }

    /// `Σ θ_v / π` over the representatives `used`: the number of triangles any
    /// triangulation of the region with exactly these vertices has (each triangle's angles
    /// sum to π, and around a vertex they fill the region's angle). Positions where `w`
    /// is the same all around count 2π: a triangulation using them must surround them.
    pub(crate) fn angle_sum(&self, used: impl IntoIterator<Item = u32>) -> f64 {
        used.into_iter()
            .map(|v| self.theta.get(v as usize).copied().unwrap_or(f64::NAN))
            .map(|t| if t.is_nan() { 0.0 } else { t })
            .sum::<f64>()
            / PI
    }

    /// The sign of `a b c`, exactly (for callers outside this module).
    pub(crate) fn orient(&self, a: u32, b: u32, c: u32) -> Ordering {
        orient(
            self.pts[a as usize],
            self.pts[b as usize],
            self.pts[c as usize],
        )
    }
}

/// For every point, the smallest index of a point at the same position (`-0.0` and `0.0`
/// are one position; NaN coordinates only match themselves bit for bit).
fn representatives(pts: &[P]) -> Vec<u32> {
    let key = |p: &P| [p[0] + 0.0, p[1] + 0.0];
    let mut order: Vec<usize> = (0..pts.len()).collect();
    order.sort_unstable_by(|&i, &j| {
        let (a, b) = (key(&pts[i]), key(&pts[j]));
        a[0].total_cmp(&b[0])
            .then(a[1].total_cmp(&b[1]))
            .then(i.cmp(&j))
    });
    let mut rep: Vec<u32> = (0..pts.len()).map(|i| i as u32).collect();
    let mut first = 0;
    for k in 1..order.len() {
        let same = {
            let (a, b) = (key(&pts[order[k]]), key(&pts[order[first]]));
            a[0].total_cmp(&b[0]).is_eq() && a[1].total_cmp(&b[1]).is_eq()
        };
        if same {
            rep[order[k]] = order[first] as u32;
        } else {
            first = k;
        }
    }
    rep
}

#[cfg(test)]
mod tests {
    use super::*;

    fn region(rings: &[Vec<[f64; 2]>], nesting: Nesting) -> Region {
        Region::build(&Input::from_rings(rings, nesting))
    }

    fn square(x: f64, y: f64, s: f64) -> Vec<[f64; 2]> {
        vec![[x, y], [x + s, y], [x + s, y + s], [x, y + s]]
    }

    #[test]
    fn square_with_hole_is_valid_with_exact_area() {
        let mut hole = square(1.0, 1.0, 1.0);
        hole.reverse();
        let r = region(&[square(0.0, 0.0, 4.0), hole], Nesting::Auto);
        assert!(r.problems.is_empty(), "{:?}", r.problems);
        assert_eq!(r.roles, vec![Role::Outer, Role::Hole]);
        assert_eq!(r.area2.value(), 2.0 * 15.0);
        assert_eq!(
            r.winding(&Probe::point([0.5, 0.5]), &mut r.stamps()),
            Some(1)
        );
        assert_eq!(
            r.winding(&Probe::point([1.5, 1.5]), &mut r.stamps()),
            Some(0)
        );
        // Four convex corners of the outer ring, four reflex ones of the hole:
        // (4 · ½π + 4 · 3⁄2π) / π = 8 = n − 2 + 2h triangles.
        let corners: f64 = r.angle_sum(0..8);
        assert!((corners - 8.0).abs() < 1e-9, "{corners}");
    }

    #[test]
    fn bow_tie_crosses() {
        let r = region(
            &[vec![[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]],
            Nesting::Auto,
        );
        assert!(r.problems[0].contains("cross"), "{:?}", r.problems);
    }

    #[test]
    fn bow_tie_pinched_at_a_vertex_winds_both_ways() {
        // Lobes of opposite orientation meeting at (1, 1): no proper crossing.
        let ring = vec![
            [0.0, 0.0],
            [1.0, 1.0],
            [2.0, 2.0],
            [2.0, 0.0],
            [1.0, 1.0],
            [0.0, 2.0],
        ];
        let r = region(&[ring], Nesting::Auto);
        assert!(
            r.problems.iter().any(|p| p.contains("winding")),
            "{:?}",
            r.problems
        );
    }

    #[test]
    fn lobes_of_opposite_orientation_joined_by_a_wall_are_invalid() {
        // Found by the raw_rings fuzz target: the ring runs down x = -1 from y = 1 to -1
        // and later up from -5 to 0, so [-1, 0] is a wall walked both ways. The upper lobe
        // turns counter-clockwise, the lower one clockwise: a figure eight.
        let ring = [
            [-1.0, 1.0],
            [-1.0, -1.0],
            [0.0, -2.0],
            [-1.0, -5.0],
            [-1.0, 0.0],
            [0.0, 0.0],
        ];
        for rotation in 0..4 {
            let turned: Vec<P> = ring
                .iter()
                .map(|&p| (0..rotation).fold(p, |[x, y], _| [-y, x]))
                .collect();
            let r = region(&[turned], Nesting::Auto);
            assert!(
                r.problems.iter().any(|p| p.contains("not 0 or 1")),
                "rotation {rotation}: {:?}",
                r.problems
            );
        }
        // The same wall with both lobes counter-clockwise is a valid, weakly simple ring.
        let ring = vec![
            [-1.0, 1.0],
            [-1.0, -1.0],
            [-2.0, -2.0],
            [-1.0, -5.0],
            [-1.0, 0.0],
            [0.0, 0.0],
        ];
        let r = region(&[ring], Nesting::Auto);
        assert!(r.problems.is_empty(), "{:?}", r.problems);
    }

    #[test]
    fn a_hole_outside_its_outer_ring_on_a_shared_vertex_is_invalid() {
        // Two squares touching at a corner, the second declared a hole of the first.
        let r = region(
            &[square(0.0, 0.0, 1.0), square(1.0, 1.0, 1.0)],
            Nesting::FirstIsOuter,
        );
        assert!(!r.problems.is_empty());
    }

    #[test]
    fn misdeclared_roles_are_invalid() {
        let r = region(
            &[square(0.0, 0.0, 4.0), square(1.0, 1.0, 1.0)],
            Nesting::Roles(vec![Role::Outer, Role::Outer]),
        );
        assert!(r.problems[0].contains("inside 1"), "{:?}", r.problems);
        let r = region(
            &[square(1.0, 1.0, 1.0), square(0.0, 0.0, 4.0)],
            Nesting::FirstIsOuter,
        );
        assert!(!r.problems.is_empty());
    }

    #[test]
    fn touching_holes_and_t_junctions_are_valid() {
        // Two holes sharing an edge, one touching the outer ring's edge at a vertex.
        let outer = square(0.0, 0.0, 4.0);
        let h1 = vec![[1.0, 0.0], [1.0, 1.0], [2.0, 1.0], [2.0, 0.5]];
        let h2 = vec![[2.0, 0.5], [2.0, 1.0], [3.0, 1.0], [3.0, 0.5]];
        let r = region(&[outer, h1, h2], Nesting::FirstIsOuter);
        assert!(r.problems.is_empty(), "{:?}", r.problems);
        // The shared edge of the holes is no boundary: both sides are outside the region.
        let (a, b) = (r.rep[9], r.rep[8]);
        assert_eq!(r.pieces.get(&(a.min(b), a.max(b))), Some(&0));
    }

    #[test]
    fn garbage_is_refused_without_panicking() {
        for input in [
            Input::new(
                vec![[f64::NAN, 0.0], [1.0, 0.0], [0.0, 1.0]],
                vec![0],
                Nesting::Auto,
            ),
            Input::new(
                vec![[1e200, 0.0], [1.0, 0.0], [0.0, 1.0]],
                vec![0],
                Nesting::Auto,
            ),
            Input::new(vec![[0.0, 0.0]], vec![0, 5], Nesting::Auto),
            Input::new(vec![[0.0, 0.0]], vec![], Nesting::Auto),
            Input::new(vec![[0.0, 0.0]], vec![0], Nesting::Roles(vec![])),
        ] {
            let r = Region::build(&input);
            assert!(!r.usable && !r.problems.is_empty());
        }
        assert!(Region::build(&Input::default()).problems.is_empty());
    }

    #[test]
    fn repeated_points_share_a_representative() {
        assert_eq!(
            representatives(&[[1.0, 0.0], [0.0, -0.0], [1.0, 0.0], [0.0, 0.0]]),
            vec![0, 1, 0, 1]
        );
    }
}
