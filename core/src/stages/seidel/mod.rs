//! Stage `seidel` (`Strategy::Seidel`): Seidel's randomized incremental trapezoidation of
//! valid rings, monotone mountains, and their linear-time triangulation.
//!
//! Ear clipping is quadratic in the worst case (stars, pinwheels: every ear test scans many
//! reflex vertices); this stage is near-linear on every input.
//!
//! # The algorithm
//!
//! 1. **Trapezoidation** (Seidel 1991, [`map`]). The ring edges are inserted one at a time
//!    into a trapezoidal map — the plane cut by the segments and by a horizontal line
//!    through every endpoint, each trapezoid knowing its neighbours above and below — kept
//!    with its history DAG: X-nodes ask whether a point is above or below an endpoint,
//!    Y-nodes whether it is left or right of a segment, leaves are the current trapezoids.
//!    Inserting a segment finds the trapezoid its upper end starts into, cuts the
//!    trapezoids of new endpoints horizontally, then walks down through the trapezoids
//!    the segment crosses, splitting each into a left and a right piece and merging the
//!    pieces on the side where no endpoint separates them.
//!
//!    **Order.** Seidel inserts in a random order and locates every endpoint in the DAG:
//!    expected O(log n) per location, O(1) per insertion otherwise, O(n log n) in all —
//!    but every step lands somewhere else in memory, and on a million vertices the cache
//!    misses, not the work, set the time. So the order is a *biased* randomized insertion
//!    order (after Amenta, Choi and Rote): a random permutation (a xorshift generator
//!    seeded by the caller, so the same input always gives the same triangles) cut into
//!    rounds that grow by a factor `log₂ n` up to `n` — the last but one ends after
//!    Seidel's first phase, `N(1) = ⌈n / log₂ n⌉` segments — the first round (of 256 to
//!    256 · log₂ n segments, or all of them on smaller inputs) in random order, every
//!    later one in ring order. What is inserted before a round is a random sample of what
//!    is inserted by its end, so each trapezoid it leaves is crossed by O(log n) of the
//!    round's segments in expectation, which bounds what the round builds inside it,
//!    whatever the order within the round; and consecutive insertions touch neighbouring
//!    trapezoids, created one after the other in the arenas, whose indices (and the
//!    points', renumbered in ring order) lie close together. On the scaling series at a
//!    million vertices this is ten to eighteen times faster than the random order. An
//!    input built against the ring order — a comb whose teeth the ring visits from the
//!    far side first, each tooth crossing the horizontal sides of many points — costs
//!    more, by about the round ratio at worst (each horizontal side is crossed O(log n)
//!    times per round in expectation); one such input (a comb hole of 125,000 teeth facing
//!    500,000 points) ran as fast as the series.
//!
//!    **Locating without the DAG.** When one end of the new segment is already in the map
//!    and the other is not (in the last round, every segment but the first of its ring:
//!    the previous edge of the ring put the shared vertex in), the trapezoid at the known
//!    end is found from that point's own X-node (whose region is the trapezoid the point
//!    was inserted into, so the search is short), and the new end by walking from there
//!    along the segment — which crosses no segment of the map, so the walk goes from
//!    trapezoid to neighbour across horizontal sides, through exactly the trapezoids the
//!    insertion then splits. Only a segment with both ends new is located from the root.
//!    (Seidel's O(n log* n) refinement traces the rings through the map after each of
//!    log* n phases to start each search near its answer; with the walks it no longer
//!    paid for itself here, and it is left out: O(n log n) expected.)
//! 2. **Inside.** The region lies left of every directed edge, so a trapezoid is inside
//!    exactly when its right segment runs upward (its left one then runs downward; the
//!    stage checks that the two agree).
//! 3. **Monotone mountains** ([`mountains`]). Each inside trapezoid's diagonal from its top
//!    to its bottom point splits it between its left and its right segment; the parts
//!    along one segment form a monotone mountain with that segment as its base, and a
//!    stack pass clips its convex chain vertices in linear time.
//!
//! Every geometric decision is an exact [`orient2d`](crate::geom::orient2d) sign or an
//! exact comparison of coordinates; nothing else.
//!
//! # Degeneracies
//!
//! - **Points at the same height.** "Above" is the lexicographic order by y, then x: a
//!   symbolic shear of the plane by an infinitesimal angle, after which no two points are
//!   at the same height and no segment is horizontal (a horizontal segment rises to the
//!   right). A shear keeps every orientation sign, so the whole construction happens in
//!   the sheared plane and every test there is an `orient2d` of the real coordinates. A
//!   point is left of a segment when `orient2d(lower end, upper end, point)` is
//!   counter-clockwise.
//! - **Segments sharing endpoints** (every ring vertex; rings touching at a vertex).
//!   Locating an endpoint `p` of a segment `p`–`q` locates `p` moved an infinitesimal step
//!   towards `q` (smaller than the shear): at the X-node of `p` itself, `q` above or below
//!   `p` decides; at the Y-node of a segment ending at `p` (the only segments through `p`),
//!   the side of `q` decides. Two segments from one point are never collinear in one
//!   direction (they would overlap), so that side is never zero. (This is the rule of
//!   Seidel's paper and of Narkhede and Manocha's implementation.) With vertices of any
//!   degree, a trapezoid still has at most two neighbours above and two below: those
//!   sharing a stretch of positive width with it.
//! - **Collinear vertices** (straight angles) are ordinary points; the mountains never cut
//!   a vertex with a straight angle, so no triangle is flat.
//!
//! No recursion; every loop is bounded. An invariant that fails gives
//! `Error::Internal { stage: "seidel" }`, never a panic.

mod map;
mod mountains;
#[cfg(test)]
mod tests;

use map::{above, point, Map, Seg, BROKEN, MAX_INDEX, NONE};

use crate::geom::Point;
use crate::Error;

/// The stage's buffers, kept between calls.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    map: Map,
    /// The insertion order.
    order: Vec<u32>,
    /// Where each round of the order ends (from 0), each segment's round, and the next
    /// free place of each round while sorting.
    ends: Vec<usize>,
    round: Vec<u8>,
    next: Vec<usize>,
    /// The points the rings use, in ring order; the caller's index of each; each caller's
    /// index's local one ([`NONE`] if unused); the rings in local indices.
    pts: Vec<[f64; 2]>,
    back: Vec<u32>,
    local: Vec<u32>,
    ids: Vec<u32>,
    stack: Vec<(u32, Point)>,
}

/// Triangulates the even–odd region of `rings` (see the module documentation): `points`
/// are distinct positions; ring `k` is `ring_ids[ring_starts[k]..ring_starts[k + 1]]`
/// (the last to the end), indices into `points`, each ring with the region on its left, no
/// two edges crossing or overlapping. `out` is cleared, then receives the triangles
/// (counter-clockwise, indices into `points`). `seed` fixes the random insertion order.
pub(crate) fn triangulate(
    s: &mut Scratch,
    points: &[[f64; 2]],
    ring_starts: &[usize],
    ring_ids: &[u32],
    seed: u64,
    out: &mut Vec<[u32; 3]>,
) -> Result<(), Error> {
    out.clear();
    // points and segments are at most ring_ids.len(), trapezoids one more than both
    if ring_ids.len() > MAX_INDEX / 2 - 1 {
        return Err(Error::TooManyVertices {
            count: ring_ids.len(),
        });
    }
    renumber(s, points, ring_ids)?;
    segments(&mut s.map.segs, &s.pts, ring_starts, &s.ids)?;
    let n = s.map.segs.len();
    if n == 0 {
        return Ok(());
    }
    schedule(s, n, seed);
    let pts = &s.pts;
    s.map.reset(pts.len());
    for &seg in &s.order {
        s.map.insert_segment(pts, seg)?;
    }
    out.reserve(n);
    mountains::triangulate(&s.map, pts, &mut s.stack, out)?;
    for t in out.iter_mut() {
        for v in t.iter_mut() {
            *v = *s.back.get(*v as usize).ok_or(BROKEN)?;
        }
    }
    Ok(())
}

/// Numbers the points the rings use in ring order (`s.pts`, `s.back` to the caller's
/// index, `s.ids` the rings renumbered): what the map reads one after the other — a
/// ring's points, its edges' insertions in ring order — then lies together in memory.
fn renumber(s: &mut Scratch, points: &[[f64; 2]], ring_ids: &[u32]) -> Result<(), Error> {
    s.local.clear();
    s.local.resize(points.len(), NONE);
    s.pts.clear();
    s.back.clear();
    s.ids.clear();
    for &v in ring_ids {
        let slot = s.local.get_mut(v as usize).ok_or(BROKEN)?;
        if *slot == NONE {
            *slot = s.back.len() as u32;
            s.back.push(v);
            s.pts.push(*points.get(v as usize).ok_or(BROKEN)?);
        }
        s.ids.push(*slot);
    }
    Ok(())
}

/// The ring edges as segments, after checking the rings' shape (indices in range, at
/// least three vertices, no edge from a vertex to itself).
fn segments(
    segs: &mut Vec<Seg>,
    points: &[[f64; 2]],
    ring_starts: &[usize],
    ring_ids: &[u32],
) -> Result<(), Error> {
    segs.clear();
    for (k, &start) in ring_starts.iter().enumerate() {
        let end = ring_starts.get(k + 1).copied().unwrap_or(ring_ids.len());
        let ring = ring_ids.get(start..end).ok_or(BROKEN)?;
        if ring.len() < 3 {
            return Err(BROKEN);
        }
        let mut from = *ring.last().ok_or(BROKEN)?;
        for &to in ring {
            let (a, b) = (point(points, from)?, point(points, to)?);
            if a == b {
                return Err(BROKEN);
            }
            let up = above(b, a);
            segs.push(if up {
                Seg {
                    hi: to,
                    lo: from,
                    up,
                }
            } else {
                Seg {
                    hi: from,
                    lo: to,
                    up,
                }
            });
            from = to;
        }
    }
    Ok(())
}

/// The fewest segments of a round after the first (the first, in random order, takes
/// what is left below).
const SMALLEST_ROUND: usize = 256;

/// The insertion order (`s.order`; see the module documentation): a random permutation
/// cut into rounds whose ends shrink by a factor `log₂ n` from `n` down (`n`, `n / log₂ n`,
/// `n / log₂² n`, … — Seidel's first phase `N(1) = ⌈n / log₂ n⌉` is the last but one),
/// the first round ([`SMALLEST_ROUND`] to [`SMALLEST_ROUND`] · `log₂ n` segments, or all
/// of them on a smaller input) in random order, every later one in ring order.
fn schedule(s: &mut Scratch, n: usize, seed: u64) {
    s.order.clear();
    s.order.extend(0..n as u32);
    let mut rng = Rng::new(seed);
    for i in (1..n).rev() {
        let j = (rng.next() % (i as u64 + 1)) as usize;
        s.order.swap(i, j);
    }
    // (floating point decides only where rounds end, never anything geometric)
    let ratio = (n as f64).log2().max(2.0);
    s.ends.clear();
    s.ends.push(n);
    let mut end = n as f64;
    loop {
        end = (end / ratio).ceil();
        if end < SMALLEST_ROUND as f64 {
            break;
        }
        s.ends.push(end as usize);
    }
    s.ends.push(0);
    s.ends.reverse();
    if s.ends.len() <= 2 {
        return;
    }
    // each segment's round, then every round after the first in ring order (a counting
    // sort by round, stable in the segment index)
    s.round.clear();
    s.round.resize(n, 0);
    for (k, w) in s.ends.windows(2).enumerate() {
        for &seg in &s.order[w[0]..w[1]] {
            s.round[seg as usize] = k as u8;
        }
    }
    s.next.clear();
    s.next.extend_from_slice(&s.ends);
    for seg in 0..n {
        let k = s.round[seg] as usize;
        if k > 0 {
            s.order[s.next[k]] = seg as u32;
            s.next[k] += 1;
        }
    }
}

/// xorshift64* seeded through splitmix64, so that every seed (0 too) works.
struct Rng(u64);

impl Rng {
    fn new(seed: u64) -> Self {
        let mut z = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        Rng(if z == 0 { 0x2545_F491_4F6C_DD1D } else { z })
    }

    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
}
