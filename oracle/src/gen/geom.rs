//! Integer geometry for the generators: exact orientation on the grid, star-shaped rings
//! sorted by exact angle, and a uniform grid of cells for segment searches.

use std::cmp::Ordering;

use super::rng::Rng;

/// A grid point.
pub(crate) type Pt = [i64; 2];
/// A ring of grid points, not closed (the last point connects back to the first).
pub(crate) type Ring = Vec<Pt>;

/// Twice the signed area of `a b c`, exact (`i128` cannot overflow for grid coordinates):
/// positive counter-clockwise.
pub(crate) fn orient(a: Pt, b: Pt, c: Pt) -> i128 {
    let (ux, uy) = (i128::from(b[0] - a[0]), i128::from(b[1] - a[1]));
    let (vx, vy) = (i128::from(c[0] - a[0]), i128::from(c[1] - a[1]));
    ux * vy - uy * vx
}

/// The open segments `a b` and `c d` cross at one point interior to both (exact).
pub(crate) fn cross_properly(a: Pt, b: Pt, c: Pt, d: Pt) -> bool {
    let (o1, o2) = (orient(a, b, c).signum(), orient(a, b, d).signum());
    let (o3, o4) = (orient(c, d, a).signum(), orient(c, d, b).signum());
    o1 * o2 < 0 && o3 * o4 < 0
}

/// Compares the directions `p − c` and `q − c` by angle in `[0, 2π)` from the +x axis,
/// exactly.
fn cmp_angle(c: Pt, p: Pt, q: Pt) -> Ordering {
    let half = |v: Pt| {
        let (x, y) = (v[0] - c[0], v[1] - c[1]);
        u8::from(!(y > 0 || (y == 0 && x > 0)))
    };
    half(p).cmp(&half(q)).then_with(|| 0.cmp(&orient(c, p, q)))
}

/// A star-shaped ring around `c`: `points` sorted by exact angle, the centre itself and all
/// but the first of each direction dropped (rounding to the grid may merge directions).
/// `None` unless the ring has three vertices and every angular gap is below π, the two
/// conditions under which a star ordering is a simple polygon with `c` in its kernel.
pub(crate) fn star_order(c: Pt, points: &[Pt]) -> Option<Ring> {
    let mut pts: Vec<(usize, Pt)> = points
        .iter()
        .copied()
        .filter(|&p| p != c)
        .enumerate()
        .collect();
    // Ties in direction keep the earliest point: callers list must-keep points first.
    pts.sort_by(|a, b| cmp_angle(c, a.1, b.1).then(a.0.cmp(&b.0)));
    let mut ring: Ring = Vec::with_capacity(pts.len());
    for (_, p) in pts {
        match ring.last() {
            Some(&q) if cmp_angle(c, q, p) == Ordering::Equal => {}
            _ => ring.push(p),
        }
    }
    let n = ring.len();
    let convex_gaps = (0..n).all(|i| orient(c, ring[i], ring[(i + 1) % n]) > 0);
    (n >= 3 && convex_gaps).then_some(ring)
}

/// A star-shaped ring of about `k` vertices around `c`: angles evenly spaced from a random
/// phase, each moved by up to `jitter` of the spacing, and radius `radius(angle)` (in grid
/// units, added to `c` and rounded). Falls back to fewer jittered or a regular ring.
pub(crate) fn polar_ring(
    rng: &mut Rng,
    c: Pt,
    k: usize,
    jitter: f64,
    mut radius: impl FnMut(&mut Rng, f64) -> [f64; 2],
) -> Ring {
    let k = k.max(3);
    let spacing = std::f64::consts::TAU / k as f64;
    let phase = rng.float(0.0, std::f64::consts::TAU);
    let points: Vec<Pt> = (0..k)
        .map(|i| {
            let angle = phase + spacing * (i as f64 + jitter * rng.float(-0.5, 0.5));
            let [dx, dy] = radius(rng, angle);
            [c[0] + dx.round() as i64, c[1] + dy.round() as i64]
        })
        .collect();
    star_order(c, &points).unwrap_or_else(|| square_around(c, 1))
}

/// The axis-aligned square of half-side `h` around `c` (counter-clockwise): the fallback
/// that is valid whatever went wrong with rounding.
pub(crate) fn square_around(c: Pt, h: i64) -> Ring {
    let h = h.max(1);
    vec![
        [c[0] - h, c[1] - h],
        [c[0] + h, c[1] - h],
        [c[0] + h, c[1] + h],
        [c[0] - h, c[1] + h],
    ]
}

/// The radius of a disc around `c` that the star-shaped `ring` contains: the least distance
/// from `c` to an edge, less a unit for floating-point error.
pub(crate) fn inscribed_radius(c: Pt, ring: &[Pt]) -> f64 {
    let n = ring.len();
    let mut best = f64::INFINITY;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        best = best.min(distance_to_segment(c, a, b));
    }
    (best - 1.0).max(0.0)
}

fn distance_to_segment(p: Pt, a: Pt, b: Pt) -> f64 {
    let f = |q: Pt| [q[0] as f64, q[1] as f64];
    let (p, a, b) = (f(p), f(a), f(b));
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a[0] + t * dx - p[0]).hypot(a[1] + t * dy - p[1])
}

/// A fast, deterministic hasher for small integer keys (grid points, cell indices): the
/// standard SipHash dominated the generators' running time.
#[derive(Clone, Copy, Default)]
pub(crate) struct IntHasher(u64);

impl std::hash::Hasher for IntHasher {
    fn finish(&self) -> u64 {
        // Final avalanche (from splitmix64) so that nearby keys spread over the buckets.
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_u64(&mut self, v: u64) {
        self.0 = (self.0.rotate_left(29) ^ v).wrapping_mul(0x9e37_79b9_7f4a_7c15);
    }

    fn write_u32(&mut self, v: u32) {
        self.write_u64(u64::from(v));
    }

    fn write_i32(&mut self, v: i32) {
        self.write_u64(v as u32 as u64);
    }

    fn write_i64(&mut self, v: i64) {
        self.write_u64(v as u64);
    }

    fn write_usize(&mut self, v: usize) {
        self.write_u64(v as u64);
    }
}

/// A hash set with [`IntHasher`].
pub(crate) type FastSet<T> = std::collections::HashSet<T, std::hash::BuildHasherDefault<IntHasher>>;
/// A hash map with [`IntHasher`].
pub(crate) type FastMap<K, V> =
    std::collections::HashMap<K, V, std::hash::BuildHasherDefault<IntHasher>>;

/// A uniform grid of square cells over a bounding box, for finding segments near each
/// other in about linear time.
pub(crate) struct Cells {
    x0: f64,
    y0: f64,
    size: f64,
    nx: usize,
    ny: usize,
}

impl Cells {
    /// About `target` cells covering `bbox = [xmin, ymin, xmax, ymax]`.
    pub(crate) fn new(bbox: [f64; 4], target: usize) -> Cells {
        let (w, h) = ((bbox[2] - bbox[0]).max(0.0), (bbox[3] - bbox[1]).max(0.0));
        let area = (w * h).max(f64::MIN_POSITIVE);
        let mut size = (area / target.max(1) as f64).sqrt();
        // A flat box has no area: cut its long side instead.
        if !(size.is_finite() && size > 0.0) || w.max(h) / size > 4.0 * target as f64 {
            size = w.max(h) / target.max(1) as f64;
        }
        if !(size.is_finite() && size > 0.0) {
            size = 1.0;
        }
        let count = |span: f64| ((span / size).floor() as usize).clamp(0, 1 << 16) + 1;
        Cells {
            x0: bbox[0],
            y0: bbox[1],
            size,
            nx: count(w),
            ny: count(h),
        }
    }

    /// The number of cells.
    pub(crate) fn len(&self) -> usize {
        self.nx * self.ny
    }

    fn col(&self, x: f64) -> usize {
        (((x - self.x0) / self.size).floor().max(0.0) as usize).min(self.nx - 1)
    }

    fn row(&self, y: f64) -> usize {
        (((y - self.y0) / self.size).floor().max(0.0) as usize).min(self.ny - 1)
    }

    /// Calls `f` with every cell the segment `a b` may touch: per column, the rows its
    /// y-range covers there, widened by one row so floating-point error cannot miss one.
    pub(crate) fn along(&self, a: [f64; 2], b: [f64; 2], mut f: impl FnMut(usize)) {
        let (a, b) = if a[0] <= b[0] { (a, b) } else { (b, a) };
        let (c0, c1) = (self.col(a[0]), self.col(b[0]));
        let dx = b[0] - a[0];
        for c in c0..=c1 {
            let y_at = |x: f64| {
                if dx > 0.0 {
                    a[1] + (b[1] - a[1]) * ((x - a[0]) / dx).clamp(0.0, 1.0)
                } else {
                    a[1]
                }
            };
            let left = (self.x0 + c as f64 * self.size).max(a[0]);
            let right = (self.x0 + (c + 1) as f64 * self.size).min(b[0]);
            // A vertical segment spans its whole y-range in its one column.
            let (ylo, yhi) = if dx > 0.0 {
                let (p, q) = (y_at(left), y_at(right));
                (p.min(q), p.max(q))
            } else {
                (a[1].min(b[1]), a[1].max(b[1]))
            };
            let r0 = self.row(ylo).saturating_sub(1);
            let r1 = (self.row(yhi) + 1).min(self.ny - 1);
            for r in r0..=r1 {
                f(r * self.nx + c);
            }
        }
    }

    /// The cell holding point `p`.
    #[cfg(test)]
    pub(crate) fn cell(&self, p: [f64; 2]) -> usize {
        self.row(p[1]) * self.nx + self.col(p[0])
    }
}

/// The bounding box `[xmin, ymin, xmax, ymax]` of `points`.
pub(crate) fn bbox(points: impl IntoIterator<Item = [f64; 2]>) -> [f64; 4] {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in points {
        b = [
            b[0].min(p[0]),
            b[1].min(p[1]),
            b[2].max(p[0]),
            b[3].max(p[1]),
        ];
    }
    if b[0] > b[2] {
        [0.0; 4]
    } else {
        b
    }
}

/// A grid point as `f64` (exact: grid coordinates are far below 2^53).
pub(crate) fn to_f64(p: Pt) -> [f64; 2] {
    [p[0] as f64, p[1] as f64]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn star_order_sorts_and_merges_directions() {
        let c = [0, 0];
        let ring = star_order(c, &[[1, 1], [-1, 0], [2, 2], [0, -3], [5, 0]]);
        assert_eq!(ring, Some(vec![[5, 0], [1, 1], [-1, 0], [0, -3]]));
        // All on one side: a gap of π or more is refused.
        assert_eq!(star_order(c, &[[1, 0], [1, 1], [0, 1]]), None);
    }

    #[test]
    fn cells_cover_a_diagonal() {
        let cells = Cells::new([0.0, 0.0, 100.0, 100.0], 100);
        let mut seen = vec![false; cells.len()];
        cells.along([0.0, 0.0], [100.0, 100.0], |c| seen[c] = true);
        for i in 0..=100 {
            let t = f64::from(i);
            assert!(seen[cells.cell([t, t])]);
        }
    }
}
