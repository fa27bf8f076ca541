//! `polytri-check-floor`: a reference, not a triangulator — what an exact input check
//! costs at least, to set beside polytri's (`polytri-check`).
//!
//! Per ring it does what no exact check can skip, and the cheapest complete proof of a
//! simple ring known to us: every vertex read (finite, −0 as +0, into a buffer), and one
//! exact orientation per edge — the certificate that the ring is star-shaped from its
//! vertices' mean (every edge turning the same way round it, the ring crossing the
//! rightward ray from it once), whose success proves the ring simple. It neither filters
//! repeated or straight vertices nor decides the rings' nesting, and counts the
//! certificate as done whether or not it holds, where a real check would then have to
//! compare edges: on any input, its time is below what any check deciding exactly could
//! take with that proof.

use robust::{orient2d, Coord};

/// The buffer of [`Floor::run`], kept between calls.
#[derive(Debug, Default)]
pub(super) struct Floor {
    points: Vec<[f64; 2]>,
}

impl Floor {
    /// Reads `vertices` and runs the certificate on every ring (`ring_starts` as polytri
    /// takes them); returns how many rings it certified, `None` for a non-finite point.
    pub(super) fn run(&mut self, vertices: &[[f64; 2]], ring_starts: &[usize]) -> Option<usize> {
        self.points.clear();
        for p in vertices {
            let q = [p[0] + 0.0, p[1] + 0.0];
            if !(q[0].is_finite() && q[1].is_finite()) {
                return None;
            }
            self.points.push(q);
        }
        let ends = ring_starts.iter().skip(1).copied();
        let rings = ring_starts.iter().zip(ends.chain([vertices.len()]));
        Some(
            rings
                .filter(|&(&s, e)| s < e && e <= self.points.len())
                .filter(|&(&s, e)| star_shaped(&self.points[s..e]))
                .count(),
        )
    }
}

/// Whether `ring` is star-shaped from its vertices' mean: every edge turns strictly the
/// same way round it (exact signs), and the ring winds round it once.
fn star_shaped(ring: &[[f64; 2]]) -> bool {
    let n = ring.len() as f64;
    let (sx, sy) = ring
        .iter()
        .fold((0.0, 0.0), |(x, y), p| (x + p[0], y + p[1]));
    let c = Coord {
        x: sx / n,
        y: sy / n,
    };
    let at = |p: [f64; 2]| Coord { x: p[0], y: p[1] };
    // An edge turning counter-clockwise round c that rises through c's height crosses
    // the rightward ray (and one turning clockwise, falling through it): with every edge
    // turning one way, their number is how often the ring winds round c.
    let (mut left, mut right, mut rising, mut falling) = (0, 0, 0, 0);
    for (i, &a) in ring.iter().enumerate() {
        let b = ring[(i + 1) % ring.len()];
        let turn = orient2d(c, at(a), at(b));
        left += usize::from(turn > 0.0);
        right += usize::from(turn < 0.0);
        rising += usize::from(a[1] <= c.y && c.y < b[1]);
        falling += usize::from(b[1] <= c.y && c.y < a[1]);
    }
    (left == ring.len() && rising == 1) || (right == ring.len() && falling == 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn certified(rings: &[&[[f64; 2]]]) -> Option<usize> {
        let mut vertices = Vec::new();
        let mut starts = Vec::new();
        for ring in rings {
            starts.push(vertices.len());
            vertices.extend_from_slice(ring);
        }
        Floor::default().run(&vertices, &starts)
    }

    #[test]
    fn the_certificate_holds_for_star_shaped_rings_only() {
        let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let hole = [[1.0, 1.0], [1.0, 3.0], [3.0, 3.0], [3.0, 1.0]];
        // either winding, each ring on its own
        assert_eq!(certified(&[&square, &hole]), Some(2));
        // a C whose mean lies in its mouth: not star-shaped from there
        let c = [
            [0.0, 0.0],
            [6.0, 0.0],
            [6.0, 1.0],
            [1.0, 1.0],
            [1.0, 5.0],
            [6.0, 5.0],
            [6.0, 6.0],
            [0.0, 6.0],
        ];
        assert_eq!(certified(&[&c]), Some(0));
        // a bow tie turns both ways round its mean; a pentagram turns one way, twice
        let bow_tie = [[0.0, 0.0], [4.0, 4.0], [4.0, 0.0], [0.0, 4.0]];
        let pentagram = [
            [0.0, 10.0],
            [-6.0, -8.0],
            [9.5, 3.0],
            [-9.5, 3.0],
            [6.0, -8.0],
        ];
        assert_eq!(certified(&[&bow_tie]), Some(0));
        assert_eq!(certified(&[&pentagram]), Some(0));
        // a point that is not finite
        assert_eq!(
            certified(&[&[[0.0, 0.0], [f64::NAN, 1.0], [1.0, 0.0]]]),
            None
        );
    }
}
