//! Uniform grids that find candidates for exact tests: points near a segment, segments near
//! a segment, segments crossing a horizontal line.
//!
//! Cells are chosen with floating-point arithmetic, so a grid only ever narrows down the
//! candidates; every decision is then made by an exact predicate. For that to be sound the
//! cells a segment is filed under must include every cell it really meets. Two things make
//! sure of it: cell indices are monotone functions of the coordinates (so a point of a
//! segment always lands between the cells of its endpoints), and each column's span of
//! rows is computed over a widened column and widened by one row, while cells are never
//! smaller than 256 ulps of the coordinates, far more than the rounding of the interpolation.

use crate::exact::P;

/// A grid of `nx × ny` cells over a bounding box.
#[derive(Clone, Debug)]
pub(crate) struct Grid {
    ox: f64,
    oy: f64,
    w: f64,
    h: f64,
    nx: usize,
    ny: usize,
}

/// Cells are at least this many ulps of the largest coordinate wide, so rounding in cell
/// arithmetic stays far below a cell.
const MIN_CELL_ULPS: f64 = 256.0;

/// The most cells along one axis allowed for `span` at coordinate magnitude `magnitude`.
fn max_cells(span: f64, magnitude: f64) -> usize {
    let min_cell = (magnitude * f64::EPSILON * MIN_CELL_ULPS).max(f64::MIN_POSITIVE);
    let n = (span / min_cell).floor();
    if n.is_finite() && n >= 1.0 {
        n.min(1e7) as usize
    } else {
        1
    }
}

impl Grid {
    /// A grid over `bbox` (`[min x, min y, max x, max y]`) with about `target` cells, as
    /// square as the box allows.
    pub(crate) fn new(bbox: [f64; 4], target: usize) -> Grid {
        let target = target.max(1) as f64;
        let (width, height) = (bbox[2] - bbox[0], bbox[3] - bbox[1]);
        let (width, height) = (
            if width.is_finite() {
                width.max(0.0)
            } else {
                0.0
            },
            if height.is_finite() {
                height.max(0.0)
            } else {
                0.0
            },
        );
        let mx = bbox[0].abs().max(bbox[2].abs());
        let my = bbox[1].abs().max(bbox[3].abs());
        let (mut nx, mut ny) = if width > 0.0 && height > 0.0 {
            let side = (width * height / target).sqrt();
            ((width / side).ceil(), (height / side).ceil())
        } else if width > 0.0 {
            (target, 1.0)
        } else {
            (1.0, target)
        };
        // Never more cells along an axis than asked for in all: a flat box would otherwise
        // get a row of millions of empty cells.
        nx = nx.clamp(1.0, max_cells(width, mx).min(target as usize) as f64);
        ny = ny.clamp(1.0, max_cells(height, my).min(target as usize) as f64);
        let (nx, ny) = (nx as usize, ny as usize);
        Grid {
            ox: bbox[0],
            oy: bbox[1],
            w: if width > 0.0 { width / nx as f64 } else { 1.0 },
            h: if height > 0.0 {
                height / ny as f64
            } else {
                1.0
            },
            nx,
            ny,
        }
    }

    /// Number of cells.
    pub(crate) fn len(&self) -> usize {
        self.nx * self.ny
    }

    fn axis(v: f64, origin: f64, size: f64, n: usize) -> usize {
        let t = ((v - origin) / size).floor();
        // `as` saturates, and NaN becomes 0: never out of range.
        if t.is_nan() {
            0
        } else {
            (t.max(0.0) as usize).min(n - 1)
        }
    }

    fn col(&self, x: f64) -> usize {
        Self::axis(x, self.ox, self.w, self.nx)
    }

    fn row(&self, y: f64) -> usize {
        Self::axis(y, self.oy, self.h, self.ny)
    }

    /// The cell holding `p`.
    pub(crate) fn cell(&self, p: P) -> usize {
        self.row(p[1]) * self.nx + self.col(p[0])
    }

    /// Calls `f` with every cell the closed box `lo`–`hi` may meet (widened by a cell each
    /// way, far more than rounding), each once.
    pub(crate) fn cells_in(&self, lo: P, hi: P, mut f: impl FnMut(usize)) {
        let c0 = self.col(lo[0]).saturating_sub(1);
        let c1 = (self.col(hi[0]) + 1).min(self.nx - 1);
        let r0 = self.row(lo[1]).saturating_sub(1);
        let r1 = (self.row(hi[1]) + 1).min(self.ny - 1);
        for row in r0..=r1 {
            for col in c0..=c1 {
                f(row * self.nx + col);
            }
        }
    }

    /// Calls `f` with every cell the closed segment `a b` may meet (a superset of those it
    /// meets, each once).
    pub(crate) fn cells_along(&self, a: P, b: P, mut f: impl FnMut(usize)) {
        let (p, q) = if a[0] <= b[0] { (a, b) } else { (b, a) };
        let (c0, c1) = (self.col(p[0]), self.col(q[0]));
        let (ylo, yhi) = (p[1].min(q[1]), p[1].max(q[1]));
        if c0 == c1 {
            // The endpoints' rows bound the segment's exactly: row() is monotone.
            for r in self.row(ylo)..=self.row(yhi) {
                f(r * self.nx + c0);
            }
            return;
        }
        let slope = (q[1] - p[1]) / (q[0] - p[0]);
        let at = |x: f64| {
            let y = p[1] + (x - p[0]) * slope;
            if y.is_finite() {
                y.clamp(ylo, yhi)
            } else {
                f64::NAN
            }
        };
        for c in c0..=c1 {
            // The column widened by a quarter cell each way, clipped to the segment.
            let xl = p[0].max(self.ox + (c as f64 - 0.25) * self.w);
            let xr = q[0].min(self.ox + (c as f64 + 1.25) * self.w);
            let (yl, yr) = (at(xl), at(xr));
            let (lo, hi) = if yl.is_nan() || yr.is_nan() {
                (ylo, yhi)
            } else {
                (yl.min(yr), yl.max(yr))
            };
            let r0 = self.row(lo).saturating_sub(1);
            let r1 = (self.row(hi) + 1).min(self.ny - 1);
            for r in r0..=r1 {
                f(r * self.nx + c);
            }
        }
    }
}

/// Items filed by cell: a compressed list per cell.
#[derive(Clone, Debug)]
pub(crate) struct Buckets {
    starts: Vec<u32>,
    items: Vec<u32>,
}

impl Buckets {
    /// Files items `0..count` under the cells `cells_of(i, f)` reports.
    pub(crate) fn build(
        cells: usize,
        count: usize,
        mut cells_of: impl FnMut(usize, &mut dyn FnMut(usize)),
    ) -> Buckets {
        let mut starts = vec![0u32; cells + 1];
        for i in 0..count {
            cells_of(i, &mut |c| starts[c + 1] += 1);
        }
        for c in 0..cells {
            starts[c + 1] += starts[c];
        }
        let mut fill = starts.clone();
        let mut items = vec![0u32; starts[cells] as usize];
        for i in 0..count {
            cells_of(i, &mut |c| {
                items[fill[c] as usize] = i as u32;
                fill[c] += 1;
            });
        }
        Buckets { starts, items }
    }

    /// The items filed under `cell`.
    pub(crate) fn get(&self, cell: usize) -> &[u32] {
        &self.items[self.starts[cell] as usize..self.starts[cell + 1] as usize]
    }
}

/// Deduplicates the hits of one query: an item is new to the query when its stamp is not
/// the query's. Cheaper than clearing a bitmap after every query.
#[derive(Clone, Debug, Default)]
pub(crate) struct Stamps {
    stamp: Vec<u32>,
    now: u32,
}

impl Stamps {
    /// Scratch for items `0..count`.
    pub(crate) fn new(count: usize) -> Stamps {
        Stamps {
            stamp: vec![0; count],
            now: 0,
        }
    }

    /// Starts a new query.
    fn next(&mut self) {
        self.now = self.now.wrapping_add(1);
        if self.now == 0 {
            // Wrapped: old stamps could collide with new ones.
            self.stamp.fill(0);
            self.now = 1;
        }
    }

    /// True the first time `i` is seen in the current query (false when out of range).
    fn first_visit(&mut self, i: usize) -> bool {
        match self.stamp.get_mut(i) {
            Some(s) if *s != self.now => {
                *s = self.now;
                true
            }
            _ => false,
        }
    }
}

/// Segments filed by the cells they may meet.
#[derive(Clone, Debug)]
pub(crate) struct SegmentIndex {
    grid: Grid,
    buckets: Buckets,
}

impl SegmentIndex {
    /// Indexes `segments` (endpoints) over `bbox`.
    pub(crate) fn new(segments: &[(P, P)], bbox: [f64; 4]) -> SegmentIndex {
        let grid = Grid::new(bbox, segments.len());
        let buckets = Buckets::build(grid.len(), segments.len(), |i, f| {
            let (a, b) = segments[i];
            grid.cells_along(a, b, f);
        });
        SegmentIndex { grid, buckets }
    }

    /// Calls `f` once with every segment that may meet segment `a b`. `stamps` must cover
    /// the indexed segments.
    pub(crate) fn near_segment(&self, a: P, b: P, stamps: &mut Stamps, mut f: impl FnMut(usize)) {
        stamps.next();
        self.grid.cells_along(a, b, |c| {
            for &s in self.buckets.get(c) {
                if stamps.first_visit(s as usize) {
                    f(s as usize);
                }
            }
        });
    }

    /// Calls `f` once with every segment that may meet the box `lo`–`hi`. `stamps` must
    /// cover the indexed segments.
    pub(crate) fn near_box(&self, lo: P, hi: P, stamps: &mut Stamps, mut f: impl FnMut(usize)) {
        stamps.next();
        self.grid.cells_in(lo, hi, |c| {
            for &s in self.buckets.get(c) {
                if stamps.first_visit(s as usize) {
                    f(s as usize);
                }
            }
        });
    }

    /// The axis direction in which a ray from a point in the box `lo`–`hi` leaves the grid
    /// through the fewest cells.
    pub(crate) fn shortest_ray(&self, lo: P, hi: P) -> Ray {
        let g = &self.grid;
        let (c0, c1) = (g.col(lo[0]), g.col(hi[0]));
        let (r0, r1) = (g.row(lo[1]), g.row(hi[1]));
        [
            (g.nx - c0, Ray::Right),
            (c1 + 1, Ray::Left),
            (g.ny - r0, Ray::Up),
            (r1 + 1, Ray::Down),
        ]
        .into_iter()
        .min_by_key(|&(cells, _)| cells)
        .map_or(Ray::Right, |(_, ray)| ray)
    }

    /// Calls `f` once with every segment that may meet the ray from a point `p` in
    /// direction `ray`, where `p` is only known to lie in the box `lo`–`hi` (equal for an
    /// exact point).
    pub(crate) fn near_ray(
        &self,
        lo: P,
        hi: P,
        ray: Ray,
        stamps: &mut Stamps,
        mut f: impl FnMut(usize),
    ) {
        stamps.next();
        let g = &self.grid;
        // A segment meeting the ray meets it in a cell of p's row (or column), one of those
        // of the box's as cells are monotone in the coordinates, and beyond p's cell.
        let (c0, c1) = (g.col(lo[0]), g.col(hi[0]));
        let (r0, r1) = (g.row(lo[1]), g.row(hi[1]));
        let (cols, rows) = match ray {
            Ray::Right => (c0..g.nx, r0..r1 + 1),
            Ray::Left => (0..c1 + 1, r0..r1 + 1),
            Ray::Up => (c0..c1 + 1, r0..g.ny),
            Ray::Down => (c0..c1 + 1, 0..r1 + 1),
        };
        for r in rows {
            for c in cols.clone() {
                for &s in self.buckets.get(r * g.nx + c) {
                    if stamps.first_visit(s as usize) {
                        f(s as usize);
                    }
                }
            }
        }
    }
}

/// The direction of a ray along an axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Ray {
    /// Towards +x.
    Right,
    /// Towards −x.
    Left,
    /// Towards +y.
    Up,
    /// Towards −y.
    Down,
}

impl Ray {
    /// The rotation (exact: it only swaps and negates coordinates) that turns this
    /// direction into +x. Rotations keep orientations, so winding numbers are unchanged.
    pub(crate) fn to_right(self, p: P) -> P {
        match self {
            Ray::Right => p,
            Ray::Left => [-p[0], -p[1]],
            Ray::Up => [p[1], -p[0]],
            Ray::Down => [-p[1], p[0]],
        }
    }
}

/// Points filed by cell.
#[derive(Clone, Debug)]
pub(crate) struct PointIndex {
    grid: Grid,
    buckets: Buckets,
}

impl PointIndex {
    /// Indexes `points` over `bbox`.
    pub(crate) fn new(points: &[P], bbox: [f64; 4]) -> PointIndex {
        let grid = Grid::new(bbox, points.len());
        let buckets = Buckets::build(grid.len(), points.len(), |i, f| f(grid.cell(points[i])));
        PointIndex { grid, buckets }
    }

    /// Calls `f` with every point that may lie on the closed segment `a b`.
    pub(crate) fn near_segment(&self, a: P, b: P, mut f: impl FnMut(usize)) {
        self.grid.cells_along(a, b, |c| {
            for &i in self.buckets.get(c) {
                f(i as usize);
            }
        });
    }
}

/// The bounding box `[min x, min y, max x, max y]` of `points` (empty: all zero).
pub(crate) fn bbox_of(points: impl IntoIterator<Item = P>) -> [f64; 4] {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Every segment passing through a box is among those `near_box` reports.
    #[test]
    fn near_box_finds_the_segments_through_the_box() {
        let segs: Vec<(P, P)> = (0..200)
            .map(|k| {
                let t = f64::from(k) * 0.05;
                ([t, 0.0], [10.0 - t, 10.0])
            })
            .collect();
        let index = SegmentIndex::new(&segs, [0.0, 0.0, 10.0, 10.0]);
        let mut stamps = Stamps::new(segs.len());
        for (lo, hi) in [
            ([4.9, 4.9], [5.1, 5.1]),
            ([0.0, 0.0], [0.2, 0.2]),
            ([9.0, 3.0], [9.5, 3.5]),
        ] {
            let mut got = Vec::new();
            index.near_box(lo, hi, &mut stamps, |i| got.push(i));
            // each reported once
            let mut once = got.clone();
            once.sort_unstable();
            once.dedup();
            assert_eq!(once.len(), got.len());
            for (i, &(a, b)) in segs.iter().enumerate() {
                // the segment's points in the box, by dense sampling
                let inside = (0..=1000).any(|k| {
                    let t = f64::from(k) / 1000.0;
                    let p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
                    (lo[0]..=hi[0]).contains(&p[0]) && (lo[1]..=hi[1]).contains(&p[1])
                });
                assert!(!inside || got.contains(&i), "segment {i} in {lo:?}–{hi:?}");
            }
        }
    }

    /// Brute force: the cells whose closed box the segment meets, by dense sampling.
    #[test]
    fn cells_along_covers_the_segment() {
        let grid = Grid::new([0.0, 0.0, 10.0, 10.0], 100);
        let segs = [
            ([0.0, 0.0], [10.0, 10.0]),
            ([0.3, 9.7], [9.9, 0.1]),
            ([5.0, 0.0], [5.0, 10.0]),
            ([0.0, 5.0], [10.0, 5.0]),
            ([1.0, 1.0], [1.5, 1.2]),
            ([2.0, 0.0], [2.001, 10.0]),
        ];
        for (a, b) in segs {
            let mut cells = Vec::new();
            grid.cells_along(a, b, |c| cells.push(c));
            for k in 0..=10_000 {
                let t = k as f64 / 10_000.0;
                let p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
                assert!(cells.contains(&grid.cell(p)), "{a:?} {b:?} at {p:?}");
            }
        }
    }

    #[test]
    fn grids_stay_coarser_than_rounding() {
        // A 1e-6 wide box at 1e9: cells must stay at least 256 ulps wide.
        let grid = Grid::new([1e9, 1e9, 1e9 + 1e-6, 1e9 + 1e-6], 1_000_000);
        assert!(grid.nx < 100, "{}", grid.nx);
        let degenerate = Grid::new([3.0, 3.0, 3.0, 3.0], 50);
        assert_eq!(degenerate.len(), 1);
    }
}
