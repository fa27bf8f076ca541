//! Spatial indexes; both only narrow down candidates, every decision is still made by
//! `predicates`.
//!
//! - [`EdgeGrid`]: a uniform grid of edges, behind every ray cast and triangle search of
//!   `nest` and `bridge`, so that neither costs holes × vertices. A ray cast walks the
//!   cells of one row from its origin outwards and stops at the first column past its
//!   nearest hit, so it costs about the cells it passes, not the row.
//! - [`Cells`]: a uniform grid of the reflex vertices of the polygon being clipped, so
//!   that an ear test looks only at the vertices near its triangle.

use crate::pool::NodeId;
use crate::predicates::Point;

/// An edge whose bounding box covers at most this many cells is listed in each of them.
const MAX_CELLS: usize = 32;

/// A longer edge spanning at most this many rows is listed in those rows' lists instead
/// (one spanning at most this many columns, in those columns' lists), and any other edge
/// in the `long` list. An edge is listed at most `MAX_CELLS` times, which bounds memory
/// by the number of edges, also for long thin edges such as a comb's teeth.
const MAX_THIN: usize = 4;

/// Up to this many edges, [`EdgeGrid`] has one cell: looking at every edge costs less
/// than placing them in cells.
const ONE_CELL: usize = 32;

/// End of a cell's entry list.
const END: u32 = u32::MAX;

/// The edge grid (see the module docs).
///
/// The edge starting at node `n` (`n → next(n)`) is listed in every cell its bounding box
/// touches, or for a long edge in the lists of the rows or the columns it spans, or in the
/// `long` list (see [`MAX_THIN`]). Entries may go stale when the pool is relinked: users
/// re-read the current edge `n → next(n)` and check it against the query, and register
/// changed edges again with [`EdgeGrid::insert`]. Rows and columns are monotone functions
/// of y and x, so an edge is always found in the cell, row list or column list of any
/// point of its bounding box, or in `long`.
#[derive(Debug, Default)]
pub(crate) struct EdgeGrid {
    x0: f64,
    y0: f64,
    sx: f64,
    sy: f64,
    nx: usize,
    ny: usize,
    /// First entry of each list, or `END`: the cells row by row, then the rows' lists, then
    /// the columns' lists.
    head: Vec<u32>,
    /// Listed edge and the next entry of the same list.
    entries: Vec<(NodeId, u32)>,
    long: Vec<NodeId>,
}

impl EdgeGrid {
    /// Empties the index and sizes it for `edges` edges within the box `lo..=hi`: about
    /// one cell per two edges, shaped like the box, so a cell holds a handful of edges.
    /// Up to [`ONE_CELL`] edges, one cell holds them all.
    pub fn reset(&mut self, lo: Point, hi: Point, edges: usize) {
        let cells = if edges <= ONE_CELL {
            1
        } else {
            (edges / 2).clamp(1, 1 << 22)
        };
        let (w, h) = (hi.x - lo.x, hi.y - lo.y);
        let (nx, ny) = shape(cells, w, h);
        (self.x0, self.y0, self.nx, self.ny) = (lo.x, lo.y, nx, ny);
        (self.sx, self.sy) = (scale(nx, w), scale(ny, h));
        self.head.clear();
        self.head.resize(nx * ny + ny + nx, END);
        self.entries.clear();
        self.long.clear();
    }

    /// Column of x (monotone, clamped to the grid).
    #[inline]
    pub fn column(&self, x: f64) -> usize {
        // `as` saturates: negative and NaN become 0, huge values the maximum
        (((x - self.x0) * self.sx) as usize).min(self.nx.max(1) - 1)
    }

    /// Row of y (monotone, clamped to the grid).
    #[inline]
    pub fn row(&self, y: f64) -> usize {
        (((y - self.y0) * self.sy) as usize).min(self.ny.max(1) - 1)
    }

    /// Number of columns.
    #[inline]
    pub fn columns(&self) -> usize {
        self.nx
    }

    /// Number of rows.
    #[inline]
    pub fn rows(&self) -> usize {
        self.ny
    }

    /// Lists the edge starting at `n`, running from `a` to `b`.
    pub fn insert(&mut self, n: NodeId, a: Point, b: Point) {
        if self.head.is_empty() {
            return;
        }
        if self.nx == 1 && self.ny == 1 {
            // every box touches the only cell
            self.push(0, n);
            return;
        }
        let (c0, c1) = (self.column(a.x.min(b.x)), self.column(a.x.max(b.x)));
        let (r0, r1) = (self.row(a.y.min(b.y)), self.row(a.y.max(b.y)));
        let (cells, rows, columns) = (self.nx * self.ny, r1 - r0 + 1, c1 - c0 + 1);
        if rows * columns <= MAX_CELLS {
            for r in r0..=r1 {
                for c in c0..=c1 {
                    self.push(r * self.nx + c, n);
                }
            }
        } else if rows <= MAX_THIN {
            for r in r0..=r1 {
                self.push(cells + r, n);
            }
        } else if columns <= MAX_THIN {
            for c in c0..=c1 {
                self.push(cells + self.ny + c, n);
            }
        } else {
            self.long.push(n);
        }
    }

    /// Puts `n` at the front of list `list`.
    fn push(&mut self, list: usize, n: NodeId) {
        let at = self.entries.len() as u32;
        self.entries.push((n, self.head[list]));
        self.head[list] = at;
    }

    /// The entries of list `list`.
    fn list(&self, list: usize) -> CellIter<'_> {
        let at = self.head.get(list).copied().unwrap_or(END);
        CellIter { edges: self, at }
    }

    /// The edges listed in the cell at `row`, `column`.
    pub fn cell(&self, row: usize, column: usize) -> CellIter<'_> {
        self.list(row * self.nx + column)
    }

    /// The long edges listed for row `row`.
    pub fn row_list(&self, row: usize) -> CellIter<'_> {
        self.list(self.nx * self.ny + row)
    }

    /// The long edges listed for column `column`.
    pub fn column_list(&self, column: usize) -> CellIter<'_> {
        self.list(self.nx * self.ny + self.ny + column)
    }

    /// The edges long both ways; every query must look at them too.
    pub fn long(&self) -> &[NodeId] {
        &self.long
    }

    /// Every listed edge whose bounding box may meet the box `lo..=hi` (and possibly
    /// others, and possibly some twice): those of the cells row by row, of the rows' lists,
    /// of the columns' lists, then the long ones.
    pub fn query(&self, lo: Point, hi: Point) -> Query<'_> {
        let (c0, c1) = (self.column(lo.x), self.column(hi.x));
        let (r0, r1) = (self.row(lo.y), self.row(hi.y));
        // an empty grid has one row and column of empty lists (see `list`)
        Query {
            grid: self,
            at: END,
            stage: Stage::Cells,
            r: r0,
            c: c0,
            r0,
            r1,
            c0,
            c1,
            long: self.long.iter(),
        }
    }
}

/// Which lists a [`Query`] walks now.
#[derive(Clone, Copy)]
enum Stage {
    Cells,
    Rows,
    Columns,
    Long,
}

/// The edges of [`EdgeGrid::query`]: one list after another, as one loop (nested
/// iterator adaptors cost several times more per edge).
pub(crate) struct Query<'a> {
    grid: &'a EdgeGrid,
    /// The next entry of the current list, or `END`.
    at: u32,
    stage: Stage,
    /// The next cell, row or column whose list comes.
    r: usize,
    c: usize,
    r0: usize,
    r1: usize,
    c0: usize,
    c1: usize,
    long: core::slice::Iter<'a, NodeId>,
}

impl Iterator for Query<'_> {
    type Item = NodeId;

    #[inline]
    fn next(&mut self) -> Option<NodeId> {
        let grid = self.grid;
        // each round yields an entry or moves on to the next list; entries link to earlier
        // ones only, so every list ends
        loop {
            if let Some(&(n, next)) = grid.entries.get(self.at as usize) {
                self.at = next;
                return Some(n);
            }
            let cells = grid.nx * grid.ny;
            let list = match self.stage {
                Stage::Cells => {
                    let list = self.r * grid.nx + self.c;
                    if self.c < self.c1 {
                        self.c += 1;
                    } else if self.r < self.r1 {
                        (self.r, self.c) = (self.r + 1, self.c0);
                    } else {
                        (self.stage, self.r) = (Stage::Rows, self.r0);
                    }
                    list
                }
                Stage::Rows => {
                    let list = cells + self.r;
                    if self.r < self.r1 {
                        self.r += 1;
                    } else {
                        (self.stage, self.c) = (Stage::Columns, self.c0);
                    }
                    list
                }
                Stage::Columns => {
                    let list = cells + grid.ny + self.c;
                    if self.c < self.c1 {
                        self.c += 1;
                    } else {
                        self.stage = Stage::Long;
                    }
                    list
                }
                Stage::Long => return self.long.next().copied(),
            };
            self.at = grid.head.get(list).copied().unwrap_or(END);
        }
    }
}

/// Columns and rows for about `cells` cells over a `w` × `h` box, shaped like it; at
/// least one of each, also when the box is flat or its size overflows.
pub(crate) fn shape(cells: usize, w: f64, h: f64) -> (usize, usize) {
    let (wide, tall) = (w > 0.0, h > 0.0);
    let ratio = w / h;
    let nx = match (wide, tall) {
        // NaN-free here; `as` saturates
        (true, true) if ratio.is_finite() => {
            ((cells as f64 * ratio).sqrt().round() as usize).clamp(1, cells)
        }
        // both sides overflowed to infinity: square-ish
        (true, true) => ((cells as f64).sqrt() as usize).max(1),
        (true, false) => cells,
        _ => 1,
    };
    let ny = if tall { cells.div_ceil(nx).max(1) } else { 1 };
    (nx, ny)
}

/// Cells per unit length for `cells` cells over `extent` (0 when that is not finite).
pub(crate) fn scale(cells: usize, extent: f64) -> f64 {
    let s = cells as f64 / extent;
    if s.is_finite() && extent > 0.0 {
        s
    } else {
        0.0
    }
}

/// The edges of one cell of [`EdgeGrid`].
pub(crate) struct CellIter<'a> {
    edges: &'a EdgeGrid,
    at: u32,
}

impl Iterator for CellIter<'_> {
    type Item = NodeId;
    #[inline]
    fn next(&mut self) -> Option<NodeId> {
        let &(n, next) = self.edges.entries.get(self.at as usize)?;
        self.at = next;
        Some(n)
    }
}

/// `Cells` slot of a node that is not in the grid.
const NONE: u32 = u32::MAX;

/// Reflex nodes by grid cell (see the module docs), built once per polygon.
///
/// Cell `c` holds `entries[start[c]..start[c + 1]]`, cells in row-major order, so the cells
/// of one row of a query are one contiguous slice. A node that stops being a candidate
/// gets a NaN position there, which no box contains. Nodes that turn reflex after building
/// (rare: only where walls were removed) go to `extra`, which every query scans and whose
/// stale entries callers skip.
#[derive(Debug, Default)]
pub(crate) struct Cells {
    x0: f64,
    y0: f64,
    sx: f64,
    sy: f64,
    nx: usize,
    ny: usize,
    start: Vec<u32>,
    /// Nodes with their positions: filtering by box needs no look-up in the pool.
    entries: Vec<(NodeId, Point)>,
    /// Each node's index in `entries` while it is live there, else `NONE` (or stale from
    /// an earlier build: valid only when `entries` holds the node at that index; a node is
    /// listed at most once per build).
    slot: Vec<u32>,
    extra: Vec<NodeId>,
    /// Scratch of `build`: each node's cell.
    cell_of: Vec<u32>,
}

impl Cells {
    /// Rebuilds the grid over `nodes` (with their positions), about one node per cell;
    /// `nodes_total` bounds every node id that will be seen.
    pub fn build(&mut self, nodes: &[(NodeId, Point)], nodes_total: usize) {
        self.extra.clear();
        self.entries.clear();
        if self.slot.len() < nodes_total {
            self.slot.resize(nodes_total, NONE);
        }
        let (mut x0, mut y0, mut x1, mut y1) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
        for &(_, p) in nodes {
            (x0, y0, x1, y1) = (x0.min(p.x), y0.min(p.y), x1.max(p.x), y1.max(p.y));
        }
        let count = nodes.len().max(1);
        let (w, h) = (x1 - x0, y1 - y0);
        // as many cells as nodes, shaped like the bounding box
        let (nx, ny) = shape(count, w, h);
        (self.x0, self.y0, self.nx, self.ny) = (x0, y0, nx, ny);
        (self.sx, self.sy) = (scale(nx, w), scale(ny, h));
        // counting sort by cell: count into start[c + 1], sum up, then fill, using
        // start[c + 1] as cell c's cursor (it ends at cell c + 1's first entry)
        let cells = nx * ny;
        self.start.clear();
        self.start.resize(cells + 2, 0);
        self.cell_of.clear();
        for &(_, p) in nodes {
            let c = self.cell(p);
            self.cell_of.push(c as u32);
            self.start[c + 2] += 1;
        }
        for c in 2..cells + 2 {
            self.start[c] += self.start[c - 1];
        }
        self.entries
            .resize(nodes.len(), (NodeId(0), Point::new(0.0, 0.0)));
        for (&(n, p), &c) in nodes.iter().zip(&self.cell_of) {
            let cursor = &mut self.start[c as usize + 1];
            let at = *cursor;
            *cursor += 1;
            self.entries[at as usize] = (n, p);
            self.slot[n.idx()] = at;
        }
        self.start.truncate(cells + 1);
    }

    /// Column of x (monotone, clamped to the grid).
    #[inline]
    fn column(&self, x: f64) -> usize {
        // `as` saturates: negative and NaN become 0
        (((x - self.x0) * self.sx) as usize).min(self.nx - 1)
    }

    /// Row of y (monotone, clamped to the grid).
    #[inline]
    fn row(&self, y: f64) -> usize {
        (((y - self.y0) * self.sy) as usize).min(self.ny - 1)
    }

    #[inline]
    fn cell(&self, p: Point) -> usize {
        self.row(p.y) * self.nx + self.column(p.x)
    }

    /// Takes node `n` out of the grid, if it is there.
    pub fn remove(&mut self, n: NodeId) {
        let at = self.slot.get(n.idx()).copied().unwrap_or(NONE);
        if let Some(entry) = self.entries.get_mut(at as usize) {
            if entry.0 == n {
                entry.1 = Point::new(f64::NAN, f64::NAN);
                self.slot[n.idx()] = NONE;
            }
        }
    }

    /// Adds a node after building (scanned by every query).
    pub fn add(&mut self, n: NodeId) {
        self.extra.push(n);
    }

    /// Calls `found` with every node listed in the box `lo..=hi` and its position until it
    /// returns true; returns whether it did. Nodes added after building are not included
    /// (see [`Cells::extra`]).
    pub fn any_in_box(
        &self,
        lo: Point,
        hi: Point,
        mut found: impl FnMut(NodeId, Point) -> bool,
    ) -> bool {
        if self.entries.is_empty() {
            return false;
        }
        // NaN (removed) positions fail every comparison
        let inside = |q: Point| q.x >= lo.x && q.x <= hi.x && q.y >= lo.y && q.y <= hi.y;
        let (c0, c1) = (self.column(lo.x), self.column(hi.x));
        for row in self.row(lo.y)..=self.row(hi.y) {
            let s = self.start[row * self.nx + c0] as usize;
            let e = self.start[row * self.nx + c1 + 1] as usize;
            if self.entries[s..e]
                .iter()
                .any(|&(n, q)| inside(q) && found(n, q))
            {
                return true;
            }
        }
        false
    }

    /// Nodes added after building, wherever they lie; entries may be stale.
    pub fn extra(&self) -> &[NodeId] {
        &self.extra
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn finds_edges_by_box() {
        let mut edges = EdgeGrid::default();
        edges.reset(p(0., 0.), p(100., 100.), 400);
        edges.insert(NodeId(1), p(0., 10.), p(5., 12.));
        edges.insert(NodeId(2), p(0., 50.), p(5., 40.));
        edges.insert(NodeId(3), p(0., 0.), p(100., 100.)); // long
        let at = |x: f64, y: f64| edges.query(p(x, y), p(x, y)).collect::<Vec<_>>();
        assert!(at(1.0, 11.0).contains(&NodeId(1)));
        assert!(!at(1.0, 11.0).contains(&NodeId(2)));
        assert!(at(4.0, 45.0).contains(&NodeId(2)));
        assert!(!at(90.0, 45.0).contains(&NodeId(2)));
        assert!(at(99.0, 1.0).contains(&NodeId(3)));
        assert!(edges
            .query(p(0., 0.), p(100., 100.))
            .any(|n| n == NodeId(2)));
    }

    #[test]
    fn long_thin_edges_go_to_row_and_column_lists() {
        let mut edges = EdgeGrid::default();
        edges.reset(p(0., 0.), p(100., 100.), 20_000);
        // a thousand horizontal teeth across the whole width, and vertical ones
        for k in 0..1000 {
            let y = k as f64 / 10.0;
            edges.insert(NodeId(k), p(0., y), p(100., y));
            edges.insert(NodeId(1000 + k), p(y, 0.), p(y, 100.));
        }
        // each listed at most `MAX_CELLS` times
        assert!(edges.entries.len() <= 2000 * MAX_CELLS);
        assert!(edges.long().is_empty());
        let at = |x: f64, y: f64| edges.query(p(x, y), p(x, y)).collect::<Vec<_>>();
        assert!(at(50.0, 50.0).contains(&NodeId(500)));
        assert!(at(50.0, 50.0).contains(&NodeId(1500)));
        assert!(!at(50.0, 70.0).contains(&NodeId(500)));
        let row = edges.row(50.0);
        assert!(edges.row_list(row).any(|n| n == NodeId(500)));
    }

    #[test]
    fn flat_and_huge_ranges_stay_in_bounds() {
        let mut edges = EdgeGrid::default();
        edges.reset(p(0., 5.), p(1., 5.), 100);
        edges.insert(NodeId(0), p(0., 5.), p(1., 5.));
        assert_eq!(edges.query(p(0., 5.), p(0., 5.)).count(), 1);
        edges.reset(p(-f64::MAX, -f64::MAX), p(f64::MAX, f64::MAX), 100);
        edges.insert(NodeId(0), p(0., -f64::MAX), p(1., f64::MAX));
        assert_eq!(edges.query(p(0., 0.), p(0., 0.)).count(), 1);
    }

    #[test]
    fn cells_track_removal() {
        let pts = [p(0., 0.), p(1., 1.), p(2., 2.), p(3., 3.), p(0., 3.)];
        let nodes: Vec<NodeId> = (0..5).map(NodeId).collect();
        let mut cells = Cells::default();
        let listed: Vec<(NodeId, Point)> = nodes.iter().map(|&n| (n, pts[n.idx()])).collect();
        cells.build(&listed, 5);
        let found = |cells: &Cells, lo: Point, hi: Point| {
            let mut v = Vec::new();
            cells.any_in_box(lo, hi, |n, _| {
                v.push(n);
                false
            });
            v.extend_from_slice(cells.extra());
            v
        };
        assert!(found(&cells, p(0.5, 0.5), p(1.5, 1.5)).contains(&NodeId(1)));
        cells.remove(NodeId(1));
        assert!(!found(&cells, p(0., 0.), p(3., 3.)).contains(&NodeId(1)));
        assert_eq!(found(&cells, p(0., 0.), p(3., 3.)).len(), 4);
        cells.remove(NodeId(1)); // not there: no effect
        cells.add(NodeId(1));
        assert!(found(&cells, p(3., 0.), p(3., 0.)).contains(&NodeId(1)));
    }
}
