//! The edge index: a grid listing every live edge of the live rings under the node it
//! starts at, which knows whether it still describes the rings.
//!
//! `nest` builds it to count winding numbers; `bridge` reuses it for its ray casts and
//! keeps it current as it adds bridges. Whatever relinks nodes in between (`touch`
//! joining rings where they meet, `clean` relinking rings as loaded) calls
//! [`EdgeIndex::invalidate`], and the next [`EdgeIndex::ensure`] rebuilds it.

use super::Ring;
use crate::geom::Point;
use crate::structures::{EdgeGrid, Pool};

/// The edges of the live rings in a grid, and whether that grid is current.
#[derive(Debug, Default)]
pub(crate) struct EdgeIndex {
    grid: EdgeGrid,
    current: bool,
}

impl EdgeIndex {
    /// Rebuilds the index unless it lists the rings as they are linked now.
    pub fn ensure(&mut self, pool: &Pool, rings: &[Ring]) {
        if !self.current {
            self.rebuild(pool, rings);
        }
        debug_assert!(self.lists_every_edge(pool, rings));
    }

    /// Lists every live edge of the live rings again.
    pub fn rebuild(&mut self, pool: &Pool, rings: &[Ring]) {
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

    /// The grid, to query. Current unless the caller relinked nodes since building it.
    pub fn grid(&self) -> &EdgeGrid {
        &self.grid
    }

    /// The grid, for a caller that relinks nodes and updates the grid alike, so that it
    /// stays current (bridges added, holes reversed).
    pub fn grid_mut(&mut self) -> &mut EdgeGrid {
        &mut self.grid
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
