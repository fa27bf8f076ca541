//! The exact checks of the triangles against the region: orientation, edge matching,
//! boundary coverage, crossings, count, area and containment.
//!
//! Why they suffice: if every triangle is counter-clockwise and the boundary chain of the
//! triangles (their edges, each piece counted +1 in its direction, −1 against it) equals
//! the region's boundary chain, then the number of triangles covering a point equals the
//! winding number of that chain there, which is `w` ∈ {0, 1}: the triangles tile the
//! region without overlaps or gaps. Edge matching on whole edges adds that the tiling is
//! a proper triangulation (no vertex in the middle of another triangle's edge). The area,
//! count, crossing and containment checks are then second opinions that also localise a
//! fault differently.

use std::cmp::Ordering;
use std::collections::{HashMap, HashSet};

use super::region::Region;
use super::{Check, Failures};
use crate::exact::{cross_properly, Exact, Probe};

/// The triangles with valid indices, by their original position, as representatives.
pub(crate) struct Mesh<'a> {
    pub region: &'a Region,
    /// `(index in the caller's list, corners as representatives)`.
    pub tris: Vec<(usize, [u32; 3])>,
    /// Directed edges between representatives: how many triangles use each, and the first.
    directed: HashMap<(u32, u32), (u32, usize)>,
}

impl<'a> Mesh<'a> {
    pub(crate) fn new(region: &'a Region, tris: Vec<(usize, [u32; 3])>) -> Mesh<'a> {
        let mut directed: HashMap<(u32, u32), (u32, usize)> =
            HashMap::with_capacity(3 * tris.len());
        for &(k, t) in &tris {
            for (u, v) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                if u != v {
                    directed.entry((u, v)).or_insert((0, k)).0 += 1;
                }
            }
        }
        Mesh {
            region,
            tris,
            directed,
        }
    }

    /// Every triangle has positive area, counter-clockwise with y up.
    pub(crate) fn orientation(&self) -> Check {
        let mut fails = Failures::default();
        for &(k, [a, b, c]) in &self.tris {
            match self.region.orient(a, b, c) {
                Ordering::Greater => {}
                o => fails.note(|| {
                    let how = if o == Ordering::Equal {
                        "has zero area"
                    } else {
                        "is clockwise"
                    };
                    format!("triangle {k} ({a}, {b}, {c}) {how}")
                }),
            }
        }
        fails.check("orientation")
    }

    /// Calls `f(u, v, count, k)` once per directed edge, in triangle order (`k` is the
    /// first triangle using it), so failures are reported in a stable order.
    fn each_edge(&self, mut f: impl FnMut(u32, u32, u32, usize)) {
        for &(k, t) in &self.tris {
            for (u, v) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                if let Some(&(count, first)) = self.directed.get(&(u, v)) {
                    if first == k {
                        f(u, v, count, k);
                    }
                }
            }
        }
    }

    fn uses(&self, u: u32, v: u32) -> u32 {
        self.directed.get(&(u, v)).map_or(0, |e| e.0)
    }

    /// Every directed edge is used once; an edge without its reverse lies on the
    /// boundary with the region on its left. Returns the check and the boundary chain of
    /// the triangles (net uses of each piece, in the `(min, max)` direction).
    pub(crate) fn edges(&self) -> (Check, HashMap<(u32, u32), i32>) {
        let mut fails = Failures::default();
        let mut chain: HashMap<(u32, u32), i32> = HashMap::new();
        let mut inside = Vec::new();
        let mut pieces = Vec::new();
        // A triangle repeating several edges of another is reported once.
        let mut seen_k: Option<usize> = None;
        self.each_edge(|u, v, count, k| {
            if count > 1 && seen_k != Some(k) {
                seen_k = Some(k);
                fails.note(|| {
                    format!("edge {u}→{v} is used by {count} triangles in the same direction (first: triangle {k})")
                });
            }
            let reverse = self.uses(v, u);
            if reverse > 0 && u > v {
                // The pair was handled at (v, u).
                return;
            }
            let net = count as i32 - reverse as i32;
            if net == 0 {
                return;
            }
            self.region.split(u, v, &mut inside);
            pieces.clear();
            pieces.push(u);
            pieces.extend_from_slice(&inside);
            pieces.push(v);
            let mut on_boundary = true;
            for w in pieces.windows(2) {
                let (p, q) = (w[0], w[1]);
                let key = (p.min(q), p.max(q));
                let sign = if p < q { 1 } else { -1 };
                *chain.entry(key).or_insert(0) += sign * net;
                let boundary = self.region.pieces.get(&key).copied().unwrap_or(0);
                on_boundary &= boundary * sign == 1;
            }
            if reverse == 0 && !on_boundary {
                fails.note(|| {
                    format!("edge {u}→{v} of triangle {k} has no twin {v}→{u} and is not a boundary edge with the polygon on its left")
                });
            }
        });
        (fails.check("edges"), chain)
    }

    /// Every boundary piece is covered by exactly one triangle edge, in its direction.
    pub(crate) fn boundary(&self, chain: &HashMap<(u32, u32), i32>) -> Check {
        let mut fails = Failures::default();
        let mut keys: Vec<_> = self.region.pieces.iter().filter(|(_, &n)| n != 0).collect();
        // Sorted, so the first failure reported does not depend on hashing.
        keys.sort_unstable();
        for (&(a, b), &net) in keys {
            let got = chain.get(&(a, b)).copied().unwrap_or(0);
            if got != net {
                let (from, to) = if net > 0 { (a, b) } else { (b, a) };
                fails.note(|| match got * net {
                    0 => format!("boundary edge {from}→{to} is not an edge of any triangle"),
                    g if g < 0 => {
                        format!("boundary edge {from}→{to} is used in the wrong direction")
                    }
                    _ => format!("boundary edge {from}→{to} is used by more than one triangle"),
                });
            }
        }
        fails.check("boundary")
    }

    /// No triangle edge crosses a ring edge that bounds the region (zero-width edges, with
    /// the same winding on both sides, enclose nothing and may be crossed).
    pub(crate) fn crossings(&self) -> Check {
        let mut fails = Failures::default();
        let region = self.region;
        let mut stamps = region.stamps();
        self.each_edge(|u, v, _, k| {
            // Each undirected edge once.
            if u > v && self.uses(v, u) > 0 {
                return;
            }
            let (a, b) = (region.pts[u as usize], region.pts[v as usize]);
            region.segments_near(a, b, &mut stamps, |i| {
                let e = region.edges[i];
                // A zero-width edge bounds nothing: crossing it splits no region.
                if region.zero_width[i] {
                    return;
                }
                if cross_properly(a, b, region.pts[e.a as usize], region.pts[e.b as usize])
                    && !region.crosses_zero_width_piece(i, a, b)
                {
                    fails.note(|| {
                        format!(
                            "edge {u}–{v} of triangle {k} crosses ring {} edge {}→{}",
                            e.ring, e.a, e.b
                        )
                    });
                }
            });
        });
        fails.check("crossings")
    }

    /// Σ twice the triangle areas equals twice the region's area, exactly.
    pub(crate) fn area(&self) -> Check {
        let mut sum = Exact::default();
        let pts = &self.region.pts;
        for &(_, [a, b, c]) in &self.tris {
            sum.add_twice_area(pts[a as usize], pts[b as usize], pts[c as usize]);
        }
        let covered = sum.value() / 2.0;
        sum.add_exact(&self.region.area2, -1.0);
        let mut fails = Failures::default();
        if sum.sign() != Ordering::Equal {
            let polygon = self.region.area2.value() / 2.0;
            fails.note(|| {
                format!("the triangles cover an area of {covered:e}, the polygon has {polygon:e} (difference {:e})", sum.value() / 2.0)
            });
        }
        fails.check("area")
    }

    /// Every triangle's centroid lies inside the region (winding number 1, exactly).
    pub(crate) fn containment(&self) -> Check {
        let mut fails = Failures::default();
        let pts = &self.region.pts;
        let mut stamps = self.region.stamps();
        for &(k, [a, b, c]) in &self.tris {
            let probe = Probe::centroid(pts[a as usize], pts[b as usize], pts[c as usize]);
            match self.region.winding(&probe, &mut stamps) {
                Some(1) => {}
                Some(w) => fails.note(|| {
                    format!("the centroid of triangle {k} ({a}, {b}, {c}) has winding number {w}, not 1")
                }),
                None => fails.note(|| {
                    format!("the centroid of triangle {k} ({a}, {b}, {c}) lies on a ring edge")
                }),
            }
        }
        fails.check("containment")
    }

    /// The representatives the triangles use.
    pub(crate) fn used(&self) -> HashSet<u32> {
        self.tris.iter().flat_map(|t| t.1).collect()
    }

    /// The triangle count any triangulation of the region over the used vertices has,
    /// when it is a whole number (see [`Region::angle_sum`]).
    pub(crate) fn expected_count(&self) -> Result<usize, f64> {
        let sum = self.region.angle_sum(self.used());
        let rounded = sum.round();
        // Angles come from atan2, a few ulps each: far below this tolerance.
        if (sum - rounded).abs() < 1e-6 * sum.abs().max(1.0) && rounded >= 0.0 {
            Ok(rounded as usize)
        } else {
            Err(sum)
        }
    }
}
