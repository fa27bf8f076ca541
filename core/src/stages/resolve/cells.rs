//! A bucket grid for `resolve`: points or segments listed by the cells they lie in, so
//! that each segment meets only the few items near it. The cells are found in floating
//! point with a margin of one cell all round, and decide nothing: every candidate is then
//! tested exactly.

use crate::structures::shape;

/// Where the cells lie: the grid's origin, cells per unit length, columns and rows.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Frame {
    x0: f64,
    y0: f64,
    sx: f64,
    sy: f64,
    cols: usize,
    rows: usize,
}

/// Items (points or segments) listed per cell, in compressed rows.
#[derive(Debug, Default)]
pub(crate) struct Cells {
    pub frame: Frame,
    /// `items[start[c]..start[c + 1]]` lie in cell `c`.
    start: Vec<u32>,
    items: Vec<u32>,
    next: Vec<u32>,
}

impl Cells {
    /// An empty grid of about `cells` cells over the box `lo..=hi`, no cell narrower than
    /// `min_size`.
    pub fn reset(&mut self, lo: [f64; 2], hi: [f64; 2], cells: usize, min_size: f64) {
        let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
        let (mut cols, mut rows) = shape(cells.max(1), w, h);
        if min_size > 0.0 {
            cols = cols.min((w / min_size) as usize).max(1);
            rows = rows.min((h / min_size) as usize).max(1);
        }
        self.frame = Frame {
            x0: lo[0],
            y0: lo[1],
            sx: per_unit(cols, w),
            sy: per_unit(rows, h),
            cols,
            rows,
        };
        self.start.clear();
        self.items.clear();
    }

    /// Lists `count` items, item `i` in the cells `place(i, push)` pushes.
    pub fn fill(&mut self, count: usize, place: impl Fn(usize, &mut dyn FnMut(usize))) {
        let n = self.frame.cols * self.frame.rows;
        self.start.clear();
        self.start.resize(n + 1, 0);
        for i in 0..count {
            place(i, &mut |c| self.start[c + 1] += 1);
        }
        for c in 0..n {
            self.start[c + 1] += self.start[c];
        }
        self.items.clear();
        self.items.resize(self.start[n] as usize, 0);
        self.next.clear();
        self.next.extend_from_slice(&self.start[..n]);
        for i in 0..count {
            place(i, &mut |c| {
                self.items[self.next[c] as usize] = i as u32;
                self.next[c] += 1;
            });
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

    /// The number of cells.
    pub fn len(&self) -> usize {
        self.frame.cols * self.frame.rows
    }
}

impl Frame {
    /// The cell a point lies in (clamped to the grid).
    pub fn cell_of(self, p: [f64; 2]) -> usize {
        self.row(p[1]) * self.cols + self.column(p[0])
    }

    fn column(&self, x: f64) -> usize {
        clamp_slot((x - self.x0) * self.sx, self.cols)
    }

    fn row(&self, y: f64) -> usize {
        clamp_slot((y - self.y0) * self.sy, self.rows)
    }

    /// Calls `f` with every cell that a point within `pad` of segment a–b lies in (and
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
                f(r * self.cols + c);
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
