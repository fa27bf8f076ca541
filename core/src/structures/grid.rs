//! Spatial indexes; both only narrow down candidates, every decision is still made by
//! `predicates`.
//!
//! - [`EdgeGrid`]: a uniform grid of edges, behind every ray cast and triangle search of
//!   `nest` and `bridge`, so that neither costs holes × vertices. A ray cast walks the
//!   cells of one row from its origin outwards and stops at the first column past its
//!   nearest hit, so it costs about the cells it passes, not the row.
//! - [`Cells`]: a uniform grid of the reflex vertices of the polygon being clipped, so
//!   that an ear test looks only at the vertices near its triangle; for a long thin
//!   triangle, only in the cells along it.

use super::boxes::{BoxIter, BoxTree};
use crate::geom::{greatest, least, Point};
use crate::structures::NodeId;

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

/// Entries per edge that [`EdgeGrid`] may spend on edges long both ways, listed in the
/// cells their segments pass (see [`EdgeGrid::insert`]); past it they go to the `long`
/// list, which every query reads. As many as [`MAX_CELLS`], so that memory stays linear in
/// the edges, but at least [`ALONG_MIN`] in all (8 MB): a fan of 3,000 long wedges needs
/// about 40 per edge.
const ALONG_PER_EDGE: usize = 32;
const ALONG_MIN: usize = 1 << 20;

/// `v` truncated to a row or column index, clamped to `0..=last` (NaN gives 0). Through
/// `i64`, whose saturating conversion takes fewer instructions than `usize`'s.
#[inline]
pub(crate) fn slot(v: f64, last: usize) -> usize {
    (v as i64).max(0).min(last as i64) as usize
}

/// End of a cell's entry list.
const END: u32 = u32::MAX;

/// The edge grid (see the module docs).
///
/// The edge starting at node `n` (`n → next(n)`) is listed in every cell its bounding box
/// touches, or for a long edge in the lists of the rows or the columns it spans, or, for an
/// edge long both ways, in the *along* lists of the cells its segment passes (see
/// [`EdgeGrid::insert`]), or in the `long` list (see [`MAX_THIN`], [`ALONG_PER_EDGE`]).
/// Entries may go stale when the pool is relinked: users re-read the current edge
/// `n → next(n)` and check it against the query, and register changed edges again with
/// [`EdgeGrid::insert`]. Rows and columns are monotone functions of y and x, so an edge is
/// always found in the cell, row list or column list of any point of its bounding box, in
/// the along list of the cell of any point of its segment, or in `long`.
#[derive(Debug, Default)]
pub(crate) struct EdgeGrid {
    x0: f64,
    y0: f64,
    sx: f64,
    sy: f64,
    nx: usize,
    ny: usize,
    /// First entry of each list, or `END`: the cells row by row, then the rows' lists, then
    /// the columns' lists, then the cells' along lists row by row.
    head: Vec<u32>,
    /// Listed edge and the next entry of the same list.
    entries: Vec<(NodeId, u32)>,
    long: BoxTree,
    /// Entries the along lists may still take.
    along_budget: usize,
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
        // (the along lists' heads come with the first edge listed there)
        self.head.clear();
        self.head.resize(nx * ny + ny + nx, END);
        self.entries.clear();
        self.long.clear();
        self.along_budget = ALONG_PER_EDGE * edges + ALONG_MIN;
    }

    /// Column of x (monotone, clamped to the grid).
    #[inline]
    pub fn column(&self, x: f64) -> usize {
        slot((x - self.x0) * self.sx, self.nx.max(1) - 1)
    }

    /// Row of y (monotone, clamped to the grid).
    #[inline]
    pub fn row(&self, y: f64) -> usize {
        slot((y - self.y0) * self.sy, self.ny.max(1) - 1)
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

    /// Renames listed edges: the edge listed as `n` is listed as `rename(n)` from now on
    /// (when a ring is reversed, the edge from n to its old successor starts at that
    /// successor). Cheaper than listing every edge again: no cell is computed.
    pub fn rename(&mut self, mut rename: impl FnMut(NodeId) -> NodeId) {
        for (n, _) in &mut self.entries {
            *n = rename(*n);
        }
        self.long.rename(rename);
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
        // columns and rows are monotone: the box's are those of the ends, ordered
        let (ca, cb) = (self.column(a.x), self.column(b.x));
        let (ra, rb) = (self.row(a.y), self.row(b.y));
        let (c0, c1) = if cb < ca { (cb, ca) } else { (ca, cb) };
        let (r0, r1) = if rb < ra { (rb, ra) } else { (ra, rb) };
        if r0 == r1 && c0 == c1 {
            // the usual edge, shorter than a cell
            self.push(r0 * self.nx + c0, n);
            return;
        }
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
        } else if !self.insert_along(n, a, b, (r0, r1), (c0, c1)) {
            self.long.push(n, a, b);
        }
    }

    /// Lists the edge `n` from `a` to `b`, spanning rows `r0..=r1` and columns `c0..=c1`,
    /// in the along lists of the cells its segment passes: in each row, the columns of
    /// the segment's part within the row's band, both widened by far more than rounding
    /// can move them, so that the cell of every point of the segment lists it. False,
    /// listing nothing, when that would exceed the budget. Out of line, as rare: `insert`
    /// is hot.
    #[cold]
    #[inline(never)]
    fn insert_along(
        &mut self,
        n: NodeId,
        a: Point,
        b: Point,
        (r0, r1): (usize, usize),
        (c0, c1): (usize, usize),
    ) -> bool {
        // at most a row's share of the columns, plus one, per row
        let most = 2 * (r1 - r0 + 1) + (c1 - c0 + 1);
        if most > self.along_budget || self.sx <= 0.0 || self.sy <= 0.0 {
            return false;
        }
        let (height, width) = (1.0 / self.sy, 1.0 / self.sx);
        let magnitude = [a.x, a.y, b.x, b.y, self.x0, self.y0]
            .iter()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        let pad_y = 1e-9 * height + 1e-13 * magnitude;
        let pad_x = 1e-9 * width + 1e-13 * magnitude;
        let (lo, hi) = if a.y <= b.y { (a, b) } else { (b, a) };
        // x on the segment at height y, clamped to its ends
        let x_at = |y: f64| {
            let t = if hi.y > lo.y {
                ((y - lo.y) / (hi.y - lo.y)).clamp(0.0, 1.0)
            } else {
                0.0
            };
            lo.x + t * (hi.x - lo.x)
        };
        let base = self.nx * self.ny + self.ny + self.nx;
        self.head.resize(base + self.nx * self.ny, END);
        let mut listed = 0;
        for r in r0..=r1 {
            // rows clamp: the first and last take everything beyond the grid's box
            let bottom = if r == 0 {
                f64::NEG_INFINITY
            } else {
                self.y0 + r as f64 * height - pad_y
            };
            let top = if r + 1 == self.ny {
                f64::INFINITY
            } else {
                self.y0 + (r + 1) as f64 * height + pad_y
            };
            let (xa, xb) = (x_at(bottom), x_at(top));
            let (left, right) = if xa <= xb { (xa, xb) } else { (xb, xa) };
            let ca = self.column(left - pad_x).max(c0);
            let cb = self.column(right + pad_x).min(c1);
            for c in ca..=cb {
                self.push(base + r * self.nx + c, n);
                listed += 1;
            }
        }
        self.along_budget = self.along_budget.saturating_sub(listed);
        true
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

    /// The edges long both ways whose segments pass the cell at `row`, `column`.
    pub fn along(&self, row: usize, column: usize) -> CellIter<'_> {
        self.list(self.nx * self.ny + self.ny + self.nx + row * self.nx + column)
    }

    /// Builds the tree of the `long` edges: call it once every edge is listed (edges
    /// listed later are found too, by a linear scan).
    pub fn seal(&mut self) {
        self.long.seal();
    }

    /// The edges long both ways (beyond the along lists' budget) whose bounding boxes
    /// meet the box `lo..=hi` (which may be unbounded: a ray); every query must look at
    /// them too.
    pub fn long(&self, lo: Point, hi: Point) -> BoxIter<'_> {
        self.long.query(lo, hi)
    }

    /// Every listed edge whose bounding box may meet the box `lo..=hi` (and possibly
    /// others, and possibly some twice): those of the cells row by row, of the rows' lists,
    /// of the columns' lists, of the cells' along lists, then the long ones. (An edge long
    /// both ways comes only where its segment may meet the box.)
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
            long: self.long.query(lo, hi),
        }
    }
}

/// Which lists a [`Query`] walks now.
#[derive(Clone, Copy)]
enum Stage {
    Cells,
    Rows,
    Columns,
    Along,
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
    long: BoxIter<'a>,
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
                    } else if grid.head.len() > cells + grid.ny + grid.nx {
                        (self.stage, self.r, self.c) = (Stage::Along, self.r0, self.c0);
                    } else {
                        // no edge is listed along its segment
                        self.stage = Stage::Long;
                    }
                    list
                }
                Stage::Along => {
                    let list = cells + grid.ny + grid.nx + self.r * grid.nx + self.c;
                    if self.c < self.c1 {
                        self.c += 1;
                    } else if self.r < self.r1 {
                        (self.r, self.c) = (self.r + 1, self.c0);
                    } else {
                        self.stage = Stage::Long;
                    }
                    list
                }
                Stage::Long => return self.long.next(),
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

/// Whether the triangle `t` covers at most an eighth of its bounding box `lo..=hi` (or the
/// test cannot say): only then does narrowing a search to it pay. A heuristic, in floating
/// point.
#[inline]
fn thin(t: [Point; 3], lo: Point, hi: Point) -> bool {
    let twice_area =
        ((t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x)).abs();
    twice_area.is_nan() || twice_area * 4.0 < (hi.x - lo.x) * (hi.y - lo.y)
}

/// A triangle prepared for [`Sliver::span`] in many rows.
#[derive(Clone, Copy, Debug)]
struct Sliver {
    sides: [Side; 3],
    /// Widening for rounding: a handful of roundings, each within 2⁻⁵² of the triangle's
    /// coordinates; subnormals add an absolute error.
    pad: f64,
}

/// One side of a [`Sliver`]: its y and x ranges, one end and its slope dx/dy (NaN for a
/// horizontal side, or where the quotient overflows).
#[derive(Clone, Copy, Debug)]
struct Side {
    y: (f64, f64),
    x: (f64, f64),
    p: Point,
    slope: f64,
}

impl Sliver {
    /// The triangle `t` with bounding box `lo..=hi` prepared, if it is thin enough for
    /// narrowing to pay (always in the unit tests).
    #[inline(never)]
    fn of_thin(t: [Point; 3], lo: Point, hi: Point) -> Option<Sliver> {
        (cfg!(test) || thin(t, lo, hi)).then(|| Sliver::new(t))
    }

    fn new(t: [Point; 3]) -> Sliver {
        let mut size: f64 = 0.0;
        let sides = [0, 1, 2].map(|k| {
            let (p, q) = (t[k], t[(k + 1) % 3]);
            size = size.max(p.x.abs());
            let slope = (q.x - p.x) / (q.y - p.y);
            Side {
                y: (p.y.min(q.y), p.y.max(q.y)),
                x: (p.x.min(q.x), p.x.max(q.x)),
                p,
                slope: if slope.is_finite() { slope } else { f64::NAN },
            }
        });
        Sliver {
            sides,
            pad: size * 1e-12 + 1e-300,
        }
    }

    /// The x range of the closed triangle where `y0 <= y <= y1`, widened to cover rounding,
    /// or `None` where it misses that band (or the band is empty).
    ///
    /// Only narrows a search, so it must never come out too small: the triangle's part of
    /// the band is a convex polygon whose corners lie on the triangle's sides, and each
    /// side's part in the band spans x between its values at the band's ends (clamped to
    /// the side).
    fn span(&self, y0: f64, y1: f64) -> Option<(f64, f64)> {
        if y0 > y1 {
            return None;
        }
        // plain comparisons, and written so that a NaN picks the safe side
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for side in &self.sides {
            if side.y.1 < y0 || side.y.0 > y1 {
                continue;
            }
            // x where the side is at y, for y within the side's range
            let at = |y: f64| {
                let y = if y > side.y.0 { y } else { side.y.0 };
                let y = if y < side.y.1 { y } else { side.y.1 };
                side.p.x + (y - side.p.y) * side.slope
            };
            let (xa, xb) = (at(y0), at(y1));
            // within the side's x range: all of it for a horizontal side (NaN slope)
            let (a, b) = if xa < xb { (xa, xb) } else { (xb, xa) };
            let a = if a >= side.x.0 { a } else { side.x.0 };
            let b = if b <= side.x.1 { b } else { side.x.1 };
            if a < lo {
                lo = a;
            }
            if b > hi {
                hi = b;
            }
        }
        (lo <= hi).then_some((lo - self.pad, hi + self.pad))
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

/// A `Cells` query for a thin triangle looks, in each row of its box holding more than this
/// many nodes, only at the columns the triangle itself reaches there: a sliver across the
/// grid, such as a fan triangle from a comb's corner to its spine, then costs the cells
/// along it, not its whole bounding box. Narrowing costs a little per row, so only full
/// rows of thin triangles take it; the unit tests narrow every row of more than one node,
/// to check it on every kind.
const NARROW: usize = if cfg!(test) { 1 } else { 32 };

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
    /// The largest y of the nodes (`y0` the smallest): a grid of nodes all at one y is one
    /// row, a line rather than a band.
    y1: f64,
    /// `1 / sy` (0 when that is 0: a single row from `y0` to `y1`), and the widening of a
    /// row's band that covers rounding (see `reach`).
    row_height: f64,
    row_pad: f64,
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
            (x0, y0) = (least(x0, p.x), least(y0, p.y));
            (x1, y1) = (greatest(x1, p.x), greatest(y1, p.y));
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
        self.y1 = y1;
        self.row_height = if self.sy > 0.0 { 1.0 / self.sy } else { 0.0 };
        self.row_pad = (y1 - y0 + y0.abs() + y1.abs()) * 1e-12 + 1e-300;
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
        slot((x - self.x0) * self.sx, self.nx - 1)
    }

    /// Row of y (monotone, clamped to the grid).
    #[inline]
    fn row(&self, y: f64) -> usize {
        slot((y - self.y0) * self.sy, self.ny - 1)
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
    /// returns true, and returns whether it did; `lo..=hi` is the bounding box of the
    /// triangle `t`, and nodes outside the closed triangle may be left out. Nodes added
    /// after building are not included (see [`Cells::extra`]).
    ///
    /// A thin triangle's box is searched, in each row holding more than [`NARROW`] nodes
    /// there, only where the triangle reaches.
    #[inline(always)]
    pub fn any_in_triangle(
        &self,
        t: [Point; 3],
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
        // the triangle prepared for narrowing, once a row asks for it: None if too fat
        let mut sliver: Option<Option<Sliver>> = None;
        for row in self.row(lo.y)..=self.row(hi.y) {
            let mut s = self.start[row * self.nx + c0] as usize;
            let mut e = self.start[row * self.nx + c1 + 1] as usize;
            if e - s > NARROW {
                if let Some(sliver) = sliver.get_or_insert_with(|| Sliver::of_thin(t, lo, hi)) {
                    let (a, b) = self.reach(sliver, lo, hi, row);
                    s = self.start[row * self.nx + a] as usize;
                    e = self.start[row * self.nx + b] as usize;
                }
            }
            // (one call site of `found`, so that it stays inlined)
            if self.entries[s..e.max(s)]
                .iter()
                .any(|&(n, q)| inside(q) && found(n, q))
            {
                return true;
            }
        }
        false
    }

    /// The columns `a..b` (maybe empty) of row `row` that the triangle `sliver`, with
    /// bounding box `lo..=hi`, reaches within the row's band.
    #[inline(never)]
    fn reach(&self, sliver: &Sliver, lo: Point, hi: Point, row: usize) -> (usize, usize) {
        // the y range of the nodes in `row`, (y - y0) * sy rounding to `row` (or more, in
        // the last row), widened for rounding; all of it when the grid is flat
        let (mut bottom, mut top) = (self.y0, self.y1);
        if self.row_height > 0.0 {
            bottom = self.y0 + row as f64 * self.row_height - self.row_pad;
            top = bottom + self.row_height + 2.0 * self.row_pad;
        }
        let y0 = if bottom > lo.y { bottom } else { lo.y };
        let y1 = if top < hi.y { top } else { hi.y };
        match sliver.span(y0, y1) {
            Some((x0, x1)) => {
                let (c0, c1) = (self.column(lo.x), self.column(hi.x));
                (self.column(x0).max(c0), self.column(x1).min(c1) + 1)
            }
            None => (0, 0),
        }
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
        edges.insert(NodeId(3), p(0., 0.), p(100., 100.)); // long both ways: along
        let at = |x: f64, y: f64| edges.query(p(x, y), p(x, y)).collect::<Vec<_>>();
        assert!(at(1.0, 11.0).contains(&NodeId(1)));
        assert!(!at(1.0, 11.0).contains(&NodeId(2)));
        assert!(at(4.0, 45.0).contains(&NodeId(2)));
        assert!(!at(90.0, 45.0).contains(&NodeId(2)));
        assert!(at(50.0, 50.0).contains(&NodeId(3)));
        assert!(!at(99.0, 1.0).contains(&NodeId(3)), "far from its segment");
        assert!(edges
            .query(p(0., 0.), p(100., 100.))
            .any(|n| n == NodeId(2)));
    }

    #[test]
    fn edges_long_both_ways_are_listed_in_the_cells_their_segments_pass() {
        let mut next = crate::testing::random(0xa106);
        for round in 0..200 {
            let mut edges = EdgeGrid::default();
            // boxes far from the origin too, where rounding is coarse
            let offset = [0.0, 1e6, -3e9][round % 3];
            let size = [1.0, 100.0, 1e-3][round % 3 / 2 + round % 2];
            let lo = p(offset, offset * 0.5);
            let hi = p(offset + size, offset * 0.5 + size * 0.7);
            edges.reset(lo, hi, 2_000);
            let coord = |next: &mut dyn FnMut(u64) -> u64| {
                let (fx, fy) = (next(1 << 20) as f64, next(1 << 20) as f64);
                let scale = 1.0 / f64::from(1u32 << 20);
                p(
                    lo.x + fx * scale * (hi.x - lo.x),
                    lo.y + fy * scale * (hi.y - lo.y),
                )
            };
            let mut segments = Vec::new();
            for k in 0..60 {
                let (mut a, mut b) = (coord(&mut next), coord(&mut next));
                if k % 10 == 0 {
                    // past the box (rows and columns clamp)
                    (a, b) = (
                        p(a.x, lo.y - 0.5 * (hi.y - lo.y)),
                        p(b.x, hi.y + 0.5 * (hi.y - lo.y)),
                    );
                }
                edges.insert(NodeId(k), a, b);
                segments.push((a, b));
            }
            for (k, &(a, b)) in segments.iter().enumerate() {
                let n = NodeId(k as u32);
                let everywhere = (
                    p(f64::NEG_INFINITY, f64::NEG_INFINITY),
                    p(f64::INFINITY, f64::INFINITY),
                );
                if edges.long(everywhere.0, everywhere.1).any(|m| m == n) {
                    continue;
                }
                // the ends exactly, and points along the segment (rounded: within a few
                // ulps of it, far inside the lists' margins)
                let along = (0..=64).map(|i| {
                    let t = f64::from(i) / 64.0;
                    p(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y))
                });
                for q in [a, b].into_iter().chain(along) {
                    assert!(
                        edges.query(q, q).any(|m| m == n),
                        "edge {k} {a:?}–{b:?} not found at {q:?}"
                    );
                }
            }
        }
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
        let everywhere = (
            p(f64::NEG_INFINITY, f64::NEG_INFINITY),
            p(f64::INFINITY, f64::INFINITY),
        );
        assert_eq!(edges.long(everywhere.0, everywhere.1).count(), 0);
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
        // the nodes found in a right triangle whose legs are twice the box's sides
        let found = |cells: &Cells, lo: Point, hi: Point| {
            let far = p(2.0 * hi.x - lo.x, 2.0 * hi.y - lo.y);
            let t = [lo, p(far.x, lo.y), p(lo.x, far.y)];
            let mut v = Vec::new();
            cells.any_in_triangle(t, lo, far, |n, _| {
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

    /// The nodes `cells` offers for triangle `t`.
    fn offered(cells: &Cells, t: [Point; 3]) -> Vec<NodeId> {
        let lo = p(
            t[0].x.min(t[1].x).min(t[2].x),
            t[0].y.min(t[1].y).min(t[2].y),
        );
        let hi = p(
            t[0].x.max(t[1].x).max(t[2].x),
            t[0].y.max(t[1].y).max(t[2].y),
        );
        let mut v = Vec::new();
        cells.any_in_triangle(t, lo, hi, |n, _| {
            v.push(n);
            false
        });
        v
    }

    #[test]
    fn cells_offer_every_node_in_the_triangle() {
        use crate::geom::{orient2d, Orientation::*};
        let mut random = crate::testing::random(0x9e37_79b9_7f4a_7c15);
        let mut cells = Cells::default();
        for round in 0..200 {
            // points on a small lattice (many on triangle sides and on cell borders), some
            // rounds squeezed into a thin band or a line, at an offset and scale
            let (scale, offset) = ([1e-3, 1.0, 7.0, 1e6][round % 4], round as f64 * 0.37);
            let flat = [1, 1, 4, 100][round / 4 % 4];
            let coordinate = |v: u64, scale: f64| offset + v as f64 * scale;
            let count = 20 + random(400) as usize;
            let nodes: Vec<(NodeId, Point)> = (0..count)
                .map(|i| {
                    let (x, y) = (random(50), random(50) / flat);
                    (
                        NodeId(i as u32),
                        p(coordinate(x, scale), coordinate(y, scale)),
                    )
                })
                .collect();
            cells.build(&nodes, count);
            for _ in 0..50 {
                let mut corner = || {
                    p(
                        coordinate(random(60), scale),
                        coordinate(random(60) / flat, scale),
                    )
                };
                let mut t = [corner(), corner(), corner()];
                match orient2d(t[0], t[1], t[2]) {
                    // ear triangles turn left (the clipper asks for no others)
                    Collinear => continue,
                    Clockwise => t.swap(1, 2),
                    CounterClockwise => {}
                }
                let got = offered(&cells, t);
                for &(n, q) in &nodes {
                    let closed = (0..3).all(|k| orient2d(t[k], t[(k + 1) % 3], q) != Clockwise);
                    assert!(!closed || got.contains(&n), "{q:?} in {t:?}");
                }
            }
        }
    }

    #[test]
    fn cells_narrow_a_sliver_to_the_cells_it_crosses() {
        // a comb's spine: a thousand nodes on y = 1, one row of cells; the fan triangle
        // from the corner (0, 0) to the spine's edge 499–500 spans all of them in x
        let nodes: Vec<(NodeId, Point)> = (0..1000)
            .map(|i| (NodeId(i), p(f64::from(i), 1.0)))
            .collect();
        let mut cells = Cells::default();
        cells.build(&nodes, 1000);
        let got = offered(&cells, [p(0., 0.), p(500., 1.), p(499., 1.)]);
        assert!(got.contains(&NodeId(499)) && got.contains(&NodeId(500)));
        assert!(got.len() <= 4, "{got:?}");
    }
}
