//! Horizontal bands of edges: the spatial index behind every ray cast and triangle search
//! of `nest` and `bridge`, so that neither costs holes × vertices.
//!
//! The edge starting at node `n` (`n → next(n)`) is listed in every band its y-range
//! touches; an edge spanning more than [`MAX_SPAN`] bands goes to one `long` list that every
//! query scans, which bounds memory. Entries may go stale when the pool is relinked: users
//! re-read the current edge `n → next(n)` and check it against the query, and register
//! changed edges again with [`Bands::insert`]. A band of a y value is a monotone function
//! of y, so an edge is always found in the band of any y within its range.

use crate::pool::NodeId;
use crate::predicates::Point;

/// Edges spanning more bands than this (or a sixteenth of all bands, if more) are kept in
/// the `long` list instead.
const MAX_SPAN: usize = 32;

/// The band index (see the module docs).
#[derive(Debug, Default)]
pub(crate) struct Bands {
    y0: f64,
    scale: f64,
    count: usize,
    /// Edges spanning more bands than this go to `long`.
    max_span: usize,
    lists: Vec<Vec<NodeId>>,
    long: Vec<NodeId>,
}

impl Bands {
    /// Empties the index and sizes it for `edges` edges with y in `ymin..=ymax` whose
    /// heights sum to `total_dy`: bands about as tall as an average edge, so an edge is
    /// listed about twice and a band holds a handful of edges.
    pub fn reset(&mut self, ymin: f64, ymax: f64, edges: usize, total_dy: f64) {
        let height = ymax - ymin;
        let mean_dy = total_dy / edges.max(1) as f64;
        let wanted = (height / mean_dy)
            .min((edges / 2) as f64)
            .min((1 << 20) as f64);
        let count = if wanted.is_finite() && wanted >= 1.0 {
            wanted as usize
        } else {
            1
        };
        let scale = count as f64 / height;
        self.y0 = ymin;
        self.scale = if scale.is_finite() && height > 0.0 {
            scale
        } else {
            0.0
        };
        self.count = count;
        self.max_span = MAX_SPAN.max(count / 16);
        if self.lists.len() < count {
            self.lists.resize_with(count, Vec::new);
        }
        for list in &mut self.lists[..count] {
            list.clear();
        }
        self.long.clear();
    }

    /// The band holding y (monotone in y; NaN-free inputs only reach here).
    #[inline]
    fn band(&self, y: f64) -> usize {
        let b = (y - self.y0) * self.scale;
        // `as` saturates: negative and NaN become 0, huge values the maximum.
        (b as usize).min(self.count - 1)
    }

    /// Lists the edge starting at `n`, running from `a` to `b`.
    pub fn insert(&mut self, n: NodeId, a: Point, b: Point) {
        if self.count == 0 {
            return;
        }
        let (lo, hi) = (self.band(a.y.min(b.y)), self.band(a.y.max(b.y)));
        if hi - lo >= self.max_span {
            self.long.push(n);
        } else {
            for list in &mut self.lists[lo..=hi] {
                list.push(n);
            }
        }
    }

    /// Every listed edge whose y-range may meet `ylo..=yhi` (and possibly others, and
    /// possibly some twice).
    pub fn query(&self, ylo: f64, yhi: f64) -> impl Iterator<Item = NodeId> + '_ {
        let (lo, hi) = if self.count == 0 {
            (1, 0)
        } else {
            (self.band(ylo), self.band(yhi))
        };
        let lists = self.lists.get(lo..=hi).unwrap_or(&[]);
        lists.iter().flatten().chain(self.long.iter()).copied()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_edges_by_y_range() {
        let mut bands = Bands::default();
        bands.reset(0.0, 100.0, 400, 400.0);
        bands.insert(NodeId(1), Point::new(0., 10.), Point::new(5., 12.));
        bands.insert(NodeId(2), Point::new(0., 50.), Point::new(5., 40.));
        bands.insert(NodeId(3), Point::new(0., 0.), Point::new(0., 100.)); // long
        let at = |y: f64| bands.query(y, y).collect::<Vec<_>>();
        assert!(at(11.0).contains(&NodeId(1)));
        assert!(!at(11.0).contains(&NodeId(2)));
        assert!(at(45.0).contains(&NodeId(2)));
        assert!(at(99.0).contains(&NodeId(3)));
        assert!(bands.query(0.0, 100.0).any(|n| n == NodeId(2)));
    }

    #[test]
    fn flat_and_huge_ranges_stay_in_bounds() {
        let mut bands = Bands::default();
        bands.reset(5.0, 5.0, 100, 0.0);
        bands.insert(NodeId(0), Point::new(0., 5.), Point::new(1., 5.));
        assert_eq!(bands.query(5.0, 5.0).count(), 1);
        bands.reset(-f64::MAX, f64::MAX, 100, f64::MAX);
        bands.insert(
            NodeId(0),
            Point::new(0., -f64::MAX),
            Point::new(1., f64::MAX),
        );
        assert_eq!(bands.query(0.0, 0.0).count(), 1);
    }
}
