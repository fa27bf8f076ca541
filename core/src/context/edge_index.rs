//! The edge index: a grid listing every live edge of the live rings under the node it
//! starts at, which knows whether it still describes the rings.
//!
//! `nest` builds it to count winding numbers; `bridge` reuses it for its ray casts and
//! keeps it current as it adds bridges. Whatever relinks nodes in between (`touch`
//! joining rings where they meet, `clean` relinking rings as loaded) calls
//! [`EdgeIndex::invalidate`], and the next [`EdgeIndex::ensure`] rebuilds it.
//!
//! A few edges asked a few questions (a glyph's hole or two) are not worth a grid:
//! [`EdgeIndex::ensure`] (and `nest`, through [`EdgeIndex::rebuild_or_list`], for a few
//! dozen edges) then only lists the edges, and [`EdgeIndex::query`] hands out all of
//! them. Every caller tests what it gets exactly, so either answer is right.

use super::Ring;
use crate::geom::Point;
use crate::structures::{EdgeGrid, NodeId, Pool};

/// The edges of the live rings in a grid (or only listed, when few), and whether that
/// index is current.
#[derive(Debug, Default)]
pub(crate) struct EdgeIndex {
    grid: EdgeGrid,
    current: bool,
    /// Every edge by its start node, instead of the grid (see [`EdgeIndex::ensure`]).
    listed: bool,
    edges: Vec<NodeId>,
}

/// [`EdgeIndex::ensure`] lists the edges, without a grid, while their number times
/// the questions to come is at most this: a scan of every edge per question then costs
/// less than building the grid (measured on glyphs: an outer ring with a hole or two).
const DIRECT_WORK: usize = 384;

impl EdgeIndex {
    /// Rebuilds the index unless it lists the rings as they are linked now, for about
    /// `questions` queries to come: when the edges are few, they are only listed (and
    /// every query hands out all of them).
    pub fn ensure(&mut self, pool: &Pool, rings: &[Ring], questions: usize) {
        if !self.current {
            self.list(pool, rings, questions);
        }
        debug_assert!(self.listed || self.lists_every_edge(pool, rings));
    }

    /// Lists the edges if they are few for `questions` queries (see [`DIRECT_WORK`]),
    /// else builds the grid.
    fn list(&mut self, pool: &Pool, rings: &[Ring], questions: usize) {
        // (edges × questions ≤ DIRECT_WORK, as a number of edges; no questions: any)
        let up_to = DIRECT_WORK.checked_div(questions).unwrap_or(usize::MAX);
        self.rebuild_or_list(pool, rings, up_to);
    }

    /// Lists every live edge of the live rings again: only listed when they number at
    /// most `list_up_to`, else in the grid.
    pub fn rebuild_or_list(&mut self, pool: &Pool, rings: &[Ring], list_up_to: usize) {
        self.edges.clear();
        for ring in rings.iter().filter(|r| r.alive) {
            self.edges.extend(pool.ring(ring.start));
            if self.edges.len() > list_up_to {
                return self.rebuild(pool, rings);
            }
        }
        self.listed = true;
        self.current = true;
    }

    /// Lists every live edge of the live rings again, in the grid.
    pub fn rebuild(&mut self, pool: &Pool, rings: &[Ring]) {
        self.listed = false;
        let mut lo = Point::new(f64::INFINITY, f64::INFINITY);
        let mut hi = Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
        let mut edges = 0;
        for ring in rings.iter().filter(|r| r.alive) {
            for n in pool.ring(ring.start) {
                // coordinates are finite: plain comparisons, without `f64::min`'s NaN
                // handling
                let p = pool.p(n);
                lo.x = if p.x < lo.x { p.x } else { lo.x };
                lo.y = if p.y < lo.y { p.y } else { lo.y };
                hi.x = if p.x > hi.x { p.x } else { hi.x };
                hi.y = if p.y > hi.y { p.y } else { hi.y };
                edges += 1;
            }
        }
        self.grid.reset(lo, hi, edges);
        for ring in rings.iter().filter(|r| r.alive) {
            for n in pool.ring(ring.start) {
                self.grid.insert(n, pool.p(n), pool.p(pool.next(n)));
            }
        }
        self.grid.seal();
        self.current = true;
    }

    /// Says that nodes were relinked: the grid no longer describes the rings.
    pub fn invalidate(&mut self) {
        self.current = false;
    }

    /// Whether the grid lists the rings as they are linked now.
    pub fn is_current(&self) -> bool {
        self.current
    }

    /// The grid, to query. Current unless the caller relinked nodes since building it,
    /// and built by [`EdgeIndex::rebuild`], not only listed.
    pub fn grid(&self) -> &EdgeGrid {
        debug_assert!(!self.listed, "the edges are only listed");
        &self.grid
    }

    /// After rings were reversed: the edge listed under node `n` now starts at
    /// `renamed(n)` (the listed edges need nothing: every node still starts one).
    pub fn rename(&mut self, renamed: impl Fn(NodeId) -> NodeId) {
        if !self.listed {
            self.grid.rename(renamed);
        }
    }

    /// Whether the edges are only listed, without a grid (see [`EdgeIndex::ensure`]).
    pub fn listed(&self) -> Option<&[NodeId]> {
        self.listed.then_some(&self.edges[..])
    }

    /// The edges (by start node) whose boxes may meet the box `lo..=hi`: those the grid
    /// lists there, or every edge when they are only listed.
    pub fn query(&self, lo: Point, hi: Point) -> impl Iterator<Item = NodeId> + '_ {
        let (listed, grid) = if self.listed {
            (&self.edges[..], None)
        } else {
            (&[][..], Some(self.grid.query(lo, hi)))
        };
        listed.iter().copied().chain(grid.into_iter().flatten())
    }

    /// Lists the edge now starting at `n` (a new node, or one whose successor changed)
    /// from `a` to `b`, keeping the index current.
    pub fn insert(&mut self, n: NodeId, a: Point, b: Point) {
        if self.listed {
            // listed by start node: a node already there needs no second entry (and the
            // list is short)
            if !self.edges.contains(&n) {
                self.edges.push(n);
            }
        } else {
            self.grid.insert(n, a, b);
        }
    }

    /// Whether the grid lists every edge of the live rings under the node it starts at,
    /// at both ends (debug builds check this where it is reused).
    fn lists_every_edge(&self, pool: &Pool, rings: &[Ring]) -> bool {
        rings.iter().filter(|r| r.alive).all(|ring| {
            pool.ring(ring.start).all(|n| {
                // listed where the edge's box lies: at both ends, at least
                let (a, b) = (pool.p(n), pool.p(pool.next(n)));
                [a, b]
                    .iter()
                    .all(|&p| self.grid.query(p, p).any(|e| e == n))
            })
        })
    }
}
