//! [`BoxTree`]: the edges of an [`EdgeGrid`](super::EdgeGrid) too long for its cells, in a
//! packed tree of bounding boxes, so that a query reads the few whose boxes meet its own
//! and not all of them.
//!
//! Edges long both ways (longer than many cells in x and in y) are listed in the cells
//! their segments pass while a budget linear in the edges lasts; past it they come here.
//! Where many long edges meet (the slices of a pie, a fan of wedges from one point) that
//! is most of them, and reading them all on every query made ray casts quadratic.
//!
//! The tree is built once, when the grid is complete ([`BoxTree::seal`]), the way R-trees
//! are bulk-loaded (sort-tile-recursive: by the boxes' centres in x into vertical slabs,
//! each slab by y), [`FAN`] boxes to a node, level on level up to a handful at the top.
//! Edges pushed after that (a bridge) stay in a short tail that every query reads. Boxes
//! only narrow down candidates: every decision is still the caller's exact test.

use crate::geom::{greatest, least, Point};
use crate::structures::NodeId;

/// Boxes per node.
const FAN: usize = 8;

/// Levels at most: items, then nodes up to at most [`FAN`] at the top — enough for
/// `FAN^(LEVELS - 1)` items, more than the 2³² nodes an index can name. (Few levels, and
/// `u32` cursors, keep [`BoxIter`] small: every grid query carries one and moves it.)
const LEVELS: usize = 12;

/// A bounding box: least x, least y, greatest x, greatest y.
type Bbox = [f64; 4];

/// Whether box `b` meets the box `lo..=hi`.
#[inline]
fn meets(b: &Bbox, lo: Point, hi: Point) -> bool {
    b[0] <= hi.x && b[2] >= lo.x && b[1] <= hi.y && b[3] >= lo.y
}

/// The box of `boxes`.
fn union(boxes: impl Iterator<Item = Bbox>) -> Bbox {
    boxes.fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |u, b| {
            [
                u[0].min(b[0]),
                u[1].min(b[1]),
                u[2].max(b[2]),
                u[3].max(b[3]),
            ]
        },
    )
}

/// The long edges (see the module docs).
#[derive(Debug, Default)]
pub(crate) struct BoxTree {
    /// Every edge with its box; `items[..sealed]` in the tree's leaf order.
    items: Vec<(NodeId, Bbox)>,
    sealed: usize,
    /// The nodes' boxes, level by level from the lowest up; level `k + 1` (`k` from 0)
    /// starts at `starts[k]` in `nodes`, and its node `i` covers the boxes `FAN · i ..` of
    /// the level below (level 0: the sealed items).
    nodes: Vec<Bbox>,
    starts: Vec<usize>,
}

impl BoxTree {
    /// Empties the tree (buffers kept).
    pub fn clear(&mut self) {
        self.items.clear();
        self.sealed = 0;
        self.nodes.clear();
        self.starts.clear();
    }

    /// Adds the edge `n` from `a` to `b` (to the tail, until the next [`BoxTree::seal`]).
    pub fn push(&mut self, n: NodeId, a: Point, b: Point) {
        let (x0, y0) = (least(a.x, b.x), least(a.y, b.y));
        let bbox = [x0, y0, greatest(a.x, b.x), greatest(a.y, b.y)];
        self.items.push((n, bbox));
    }

    /// How many edges there are.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.items.len()
    }

    /// Renames every edge as `rename` says (see `EdgeGrid::rename`).
    pub fn rename(&mut self, mut rename: impl FnMut(NodeId) -> NodeId) {
        for (n, _) in &mut self.items {
            *n = rename(*n);
        }
    }

    /// Builds the tree over every edge (the tail included).
    pub fn seal(&mut self) {
        self.sealed = self.items.len();
        self.nodes.clear();
        self.starts.clear();
        let n = self.items.len();
        if n <= FAN {
            // the tail reads them all as fast
            self.sealed = 0;
            return;
        }
        // sort-tile-recursive: √(leaves) slabs by centre x, each sorted by centre y
        let cx = |b: &Bbox| b[0] + b[2];
        let cy = |b: &Bbox| b[1] + b[3];
        self.items
            .sort_unstable_by(|p, q| cx(&p.1).total_cmp(&cx(&q.1)));
        let leaves = n.div_ceil(FAN);
        let slabs = (leaves as f64).sqrt().ceil().max(1.0) as usize;
        let per_slab = leaves.div_ceil(slabs) * FAN;
        for slab in self.items.chunks_mut(per_slab) {
            slab.sort_unstable_by(|p, q| cy(&p.1).total_cmp(&cy(&q.1)));
        }
        // the levels, each node the box of FAN boxes below it
        let mut below = n;
        for level in 1..LEVELS {
            let start = self.nodes.len();
            self.starts.push(start);
            let under = if level >= 2 {
                self.starts[level - 2]
            } else {
                0
            };
            for k in 0..below.div_ceil(FAN) {
                let (a, e) = (FAN * k, (FAN * (k + 1)).min(below));
                let bbox = if level == 1 {
                    union(self.items[a..e].iter().map(|item| item.1))
                } else {
                    union(self.nodes[under + a..under + e].iter().copied())
                };
                self.nodes.push(bbox);
            }
            below = self.nodes.len() - start;
            if below <= FAN {
                break;
            }
        }
    }

    /// The edges whose boxes meet the box `lo..=hi`: the tail's, then the tree's.
    pub fn query(&self, lo: Point, hi: Point) -> BoxIter<'_> {
        let top = self.starts.len();
        let mut it = BoxIter {
            tree: self,
            lo,
            hi,
            tail: self.sealed,
            level: top,
            pos: [0; LEVELS],
            end: [0; LEVELS],
        };
        if top > 0 {
            it.end[top] = (self.nodes.len() - self.starts[top - 1]) as u32;
        }
        it
    }
}

/// The edges of [`BoxTree::query`]: a depth-first walk with one cursor per level, no
/// stack to allocate.
pub(crate) struct BoxIter<'a> {
    tree: &'a BoxTree,
    lo: Point,
    hi: Point,
    /// The next tail item.
    tail: usize,
    /// The level being walked (0: the items); `starts.len()` is the top; past it, done.
    level: usize,
    /// Per level, the next box and the end of the boxes under the node above.
    pos: [u32; LEVELS],
    end: [u32; LEVELS],
}

impl Iterator for BoxIter<'_> {
    type Item = NodeId;

    #[inline]
    fn next(&mut self) -> Option<NodeId> {
        let tree = self.tree;
        while let Some(&(n, bbox)) = tree.items.get(self.tail) {
            self.tail += 1;
            if meets(&bbox, self.lo, self.hi) {
                return Some(n);
            }
        }
        let top = tree.starts.len();
        // each round moves a cursor on, or goes up a level; every level's cursor ends
        while self.level <= top {
            let level = self.level;
            if self.pos[level] >= self.end[level] {
                self.level += 1;
                continue;
            }
            let i = self.pos[level] as usize;
            self.pos[level] += 1;
            if level == 0 {
                let (n, bbox) = tree.items[i];
                if meets(&bbox, self.lo, self.hi) {
                    return Some(n);
                }
                continue;
            }
            if meets(&tree.nodes[tree.starts[level - 1] + i], self.lo, self.hi) {
                let below = if level == 1 {
                    tree.sealed
                } else {
                    tree.starts[level - 1] - tree.starts[level - 2]
                };
                self.level = level - 1;
                self.pos[level - 1] = (FAN * i) as u32;
                self.end[level - 1] = (FAN * (i + 1)).min(below) as u32;
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_query_finds_exactly_the_boxes_meeting_its_own() {
        let mut rng = crate::testing::unit_random(0x9e37_79b9_7f4a_7c15);
        for count in [0, 1, 8, 9, 64, 65, 513, 5000] {
            let mut tree = BoxTree::default();
            let mut edges = Vec::new();
            for k in 0..count {
                let a = Point::new(rng(), rng());
                let b = Point::new(a.x + 0.3 * rng(), a.y - 0.3 * rng());
                tree.push(NodeId(k), a, b);
                edges.push((a, b));
            }
            tree.seal();
            // a few more after sealing go to the tail
            for k in count..count + 3 {
                let a = Point::new(rng(), rng());
                tree.push(NodeId(k), a, Point::new(a.x + 0.1, a.y + 0.2));
                edges.push((a, Point::new(a.x + 0.1, a.y + 0.2)));
            }
            assert_eq!(tree.len(), edges.len());
            for _ in 0..50 {
                let lo = Point::new(rng(), rng());
                let hi = Point::new(lo.x + 0.2 * rng(), lo.y + 0.2 * rng());
                let mut got: Vec<u32> = tree.query(lo, hi).map(|n| n.0).collect();
                got.sort_unstable();
                let want: Vec<u32> = (0..edges.len() as u32)
                    .filter(|&k| {
                        let (a, b) = edges[k as usize];
                        let bbox = [a.x.min(b.x), a.y.min(b.y), a.x.max(b.x), a.y.max(b.y)];
                        meets(&bbox, lo, hi)
                    })
                    .collect();
                assert_eq!(got, want, "{count} boxes");
            }
            // a ray: unbounded one way
            let lo = Point::new(0.5, 0.5);
            let hi = Point::new(f64::INFINITY, 0.5);
            let got = tree.query(lo, hi).count();
            let want = edges
                .iter()
                .filter(|(a, b)| a.x.max(b.x) >= 0.5 && a.y.min(b.y) <= 0.5 && a.y.max(b.y) >= 0.5)
                .count();
            assert_eq!(got, want, "{count} boxes, ray");
        }
    }
}
