//! A bucket grid for `resolve`: points or segments listed by the cells they lie in, so
//! that each segment meets only the few items near it. The cells are found in floating
//! point with a margin of one cell all round, and decide nothing: every candidate is then
//! tested exactly.

use crate::structures::shape;

/// Where the cells lie: the grid's origin, cells per unit length, columns and rows, and
/// how a cell maps to its bucket: directly (`row · cols + col`) when there are no more
/// cells than buckets, else by a hash of the cell, `buckets` a power of two.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Frame {
    x0: f64,
    y0: f64,
    sx: f64,
    sy: f64,
    cols: usize,
    rows: usize,
    /// log2 of the number of buckets when hashed; `None`: direct.
    hashed: Option<u32>,
    buckets: usize,
}

/// Items (points or segments) listed per cell, in compressed rows.
#[derive(Debug, Default)]
pub(crate) struct Cells {
    pub frame: Frame,
    /// `items[start[c]..start[c + 1]]` lie in cell `c`.
    start: Vec<u32>,
    items: Vec<u32>,
    next: Vec<u32>,
    /// (bucket, item) for every bucket an item was placed in, in placing order.
    placed: Vec<(u32, u32)>,
}

impl Cells {
    /// An empty grid over the box `lo..=hi` with about `cells` buckets. Cells are square
    /// where both sides are long enough, no narrower than `min_size`, and no wider than
    /// `typical` (the length of a typical segment to be listed or to look items up): on
    /// clustered input (a coastline's detail in a few places of its box) cells of about a
    /// segment's length hold a few items each, where `cells` cells spread over the whole
    /// box would crowd hundreds into some. Then there are more cells than buckets, and
    /// cells share buckets by a hash (more candidates, never fewer).
    pub fn reset(&mut self, lo: [f64; 2], hi: [f64; 2], cells: usize, min_size: f64, typical: f64) {
        let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
        let (mut cols, mut rows) = shape(cells.max(1), w, h);
        // (the side of a cell of the spread grid, on its longer axis)
        let spread = (w / cols as f64).max(h / rows as f64);
        let side = typical.max(min_size);
        if side < spread && side > 0.0 {
            // (`as` saturates; the counts stay below 2⁶³ so that the product is checked)
            cols = ((w / side) as usize).clamp(1, 1 << 31);
            rows = ((h / side) as usize).clamp(1, 1 << 31);
        } else if min_size > 0.0 {
            cols = cols.min((w / min_size) as usize).max(1);
            rows = rows.min((h / min_size) as usize).max(1);
        }
        let wanted = cells.max(2).next_power_of_two();
        let (hashed, buckets) = match cols.checked_mul(rows) {
            Some(n) if n <= wanted => (None, n),
            _ => (Some(wanted.trailing_zeros()), wanted),
        };
        self.frame = Frame {
            x0: lo[0],
            y0: lo[1],
            sx: per_unit(cols, w),
            sy: per_unit(rows, h),
            cols,
            rows,
            hashed,
            buckets,
        };
        self.start.clear();
        self.items.clear();
    }

    /// Lists `count` items, item `i` in the cells `place(i, push)` pushes.
    pub fn fill(&mut self, count: usize, place: impl Fn(usize, &mut dyn FnMut(usize))) {
        // (each item placed once: its buckets noted beside it, then sorted by bucket)
        self.placed.clear();
        for i in 0..count {
            place(i, &mut |c| self.placed.push((c as u32, i as u32)));
        }
        let n = self.frame.buckets;
        self.start.clear();
        self.start.resize(n + 1, 0);
        for &(c, _) in &self.placed {
            self.start[c as usize + 1] += 1;
        }
        for c in 0..n {
            self.start[c + 1] += self.start[c];
        }
        self.items.clear();
        self.items.resize(self.start[n] as usize, 0);
        self.next.clear();
        self.next.extend_from_slice(&self.start[..n]);
        for &(c, i) in &self.placed {
            let at = &mut self.next[c as usize];
            self.items[*at as usize] = i;
            *at += 1;
        }
    }

    /// Lists points: each in the one cell it lies in.
    pub fn fill_points(&mut self, points: &[[f64; 2]]) {
        let f = self.frame;
        self.fill(points.len(), |i, push| push(f.cell_of(points[i])));
    }

    /// The items listed in cell `c`.
    pub fn cell(&self, c: usize) -> &[u32] {
        let (s, e) = (self.start[c] as usize, self.start[c + 1] as usize);
        &self.items[s..e]
    }

    /// The number of buckets (cells, unless hashed).
    pub fn len(&self) -> usize {
        self.frame.buckets
    }
}

impl Frame {
    /// The bucket of the cell a point lies in (clamped to the grid).
    pub fn cell_of(self, p: [f64; 2]) -> usize {
        self.bucket(self.column(p[0]), self.row(p[1]))
    }

    /// The bucket of the cell in column `c`, row `r`.
    #[inline]
    fn bucket(&self, c: usize, r: usize) -> usize {
        match self.hashed {
            None => r * self.cols + c,
            Some(bits) => {
                let h = (c as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
                    ^ (r as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F);
                // (bits ≥ 1: at least two buckets)
                (h.wrapping_mul(0x2545_F491_4F6C_DD1D) >> (64 - bits)) as usize
            }
        }
    }

    fn column(&self, x: f64) -> usize {
        clamp_slot((x - self.x0) * self.sx, self.cols)
    }

    fn row(&self, y: f64) -> usize {
        clamp_slot((y - self.y0) * self.sy, self.rows)
    }

    /// Calls `f` with the bucket of every cell that a point within `pad` of segment a–b lies in (and
    /// maybe a few more). `pad` must exceed the rounding error of the coordinates' size.
    pub fn along(self, a: [f64; 2], b: [f64; 2], pad: f64, mut f: impl FnMut(usize)) {
        let (xmin, xmax) = (a[0].min(b[0]), a[0].max(b[0]));
        let (ymin, ymax) = (a[1].min(b[1]), a[1].max(b[1]));
        let (c0, c1) = (self.column(xmin - pad), self.column(xmax + pad));
        let dx = b[0] - a[0];
        for c in c0..=c1 {
            let (r0, r1) = if c1 - c0 <= 1 || self.sx == 0.0 {
                (self.row(ymin - pad), self.row(ymax + pad))
            } else {
                // the segment's y over this column's x-range (clamped to the segment);
                // an error δ in x moves y by slope·δ, which the pad then covers
                let slope = (b[1] - a[1]) / dx;
                let xl = (self.x0 + c as f64 / self.sx).clamp(xmin, xmax);
                let xr = (self.x0 + (c + 1) as f64 / self.sx).clamp(xmin, xmax);
                let y = |x: f64| a[1] + slope * (x - a[0]);
                let (y0, y1) = (y(xl).min(y(xr)), y(xl).max(y(xr)));
                let p = pad * (1.0 + slope.abs());
                (self.row(y0.max(ymin) - p), self.row(y1.min(ymax) + p))
            };
            for r in r0..=r1 {
                f(self.bucket(c, r));
            }
        }
    }
}

fn per_unit(cells: usize, extent: f64) -> f64 {
    let s = cells as f64 / extent;
    if s.is_finite() && extent > 0.0 {
        s
    } else {
        0.0
    }
}

fn clamp_slot(v: f64, n: usize) -> usize {
    // NaN and negatives go to 0 (`as` saturates)
    (v as usize).min(n - 1)
}

#[cfg(test)]
mod tests {
    use super::Cells;
    use crate::testing::unit_random;

    /// The grids' contract: a segment's buckets hold every listed point within `pad` of
    /// it, whether the cells are spread over the box or, on clustered input, about a
    /// segment long and hashed into buckets (a coastline's detail in one corner, a few
    /// long edges across the box). Points are placed near the segments (within half the
    /// pad of a point on each) among random ones, then looked up segment by segment.
    #[test]
    fn a_segment_meets_the_bucket_of_every_point_near_it() {
        let mut next = unit_random(0x9e37_79b9_7f4a_7c15);
        for (case, (cluster, typical)) in [(1.0, f64::INFINITY), (0.01, 0.002), (0.001, 1e-4)]
            .into_iter()
            .enumerate()
        {
            let pad = cluster * 1e-3;
            // short segments in a small square at the box's corner, some long ones across
            let segments: Vec<([f64; 2], [f64; 2])> = (0..1500)
                .map(|k| {
                    let a = [cluster * next(), cluster * next()];
                    let reach = typical.min(1.0);
                    let b = if k % 100 == 0 {
                        [next(), next()]
                    } else {
                        // (inside the grid's box, as `resolve`'s segments always are)
                        let b = [a[0] + reach * (next() - 0.5), a[1] + reach * (next() - 0.5)];
                        b.map(|x| x.clamp(0.0, 1.0))
                    };
                    (a, b)
                })
                .collect();
            // points near each segment (listed by segment), random ones, the far corner
            let mut points = Vec::new();
            let mut near = Vec::new();
            for &(a, b) in &segments {
                near.push(points.len()..points.len() + 4);
                for _ in 0..4 {
                    let t = next();
                    let off = [pad * (next() - 0.5), pad * (next() - 0.5)];
                    let on = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
                    points.push([on[0] + off[0], on[1] + off[1]]);
                }
            }
            points.extend((0..2000).map(|_| [cluster * next(), cluster * next()]));
            points.push([1.0, 1.0]);
            let mut cells = Cells::default();
            cells.reset([0.0, 0.0], [1.0, 1.0], points.len(), pad, typical);
            if case > 0 {
                assert!(
                    cells.frame.hashed.is_some(),
                    "case {case}: cells of a segment's length"
                );
            }
            cells.fill_points(&points);
            for (&(a, b), near) in segments.iter().zip(near) {
                let mut met = Vec::new();
                cells
                    .frame
                    .along(a, b, pad, |c| met.extend_from_slice(cells.cell(c)));
                for i in near {
                    assert!(met.contains(&(i as u32)), "case {case}: point {i} missed");
                }
            }
        }
    }
}
