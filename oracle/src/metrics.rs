//! Quality measures of a set of triangles: smallest angle, worst aspect ratio, total edge
//! length. Floating point throughout: these are reported, never used to decide validity.

use std::collections::HashMap;

/// Quality measures of a mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Quality {
    /// The smallest interior angle of any triangle, in degrees (0 without triangles).
    pub min_angle_deg: f64,
    /// The largest aspect ratio of any triangle: longest edge × perimeter / (4√3 · area),
    /// 1 for an equilateral triangle, `f64::MAX` for a degenerate one (0 without
    /// triangles).
    pub worst_aspect: f64,
    /// The length of every distinct edge, summed (an edge two triangles share counts once).
    pub total_edge_length: f64,
}

/// The interior angle at `a` of triangle `a b c`, in degrees.
fn angle_at(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
    let cross = u[0] * v[1] - u[1] * v[0];
    let dot = u[0] * v[0] + u[1] * v[1];
    cross.abs().atan2(dot).to_degrees()
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (b[0] - a[0]).hypot(b[1] - a[1])
}

/// The aspect ratio of one triangle (see [`Quality::worst_aspect`]).
fn aspect(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    let (ab, bc, ca) = (dist(a, b), dist(b, c), dist(c, a));
    let area = ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs() / 2.0;
    let ratio = ab.max(bc).max(ca) * (ab + bc + ca) / (4.0 * 3f64.sqrt() * area);
    if ratio.is_nan() || ratio > f64::MAX {
        f64::MAX
    } else {
        ratio
    }
}

/// Measures `triangles`, each corner given as its position and a key naming that position
/// (equal keys: the same point), so shared edges are counted once.
pub(crate) fn measure(triangles: &[[([f64; 2], u32); 3]]) -> Quality {
    if triangles.is_empty() {
        return Quality::default();
    }
    let mut q = Quality {
        min_angle_deg: f64::INFINITY,
        worst_aspect: 0.0,
        total_edge_length: 0.0,
    };
    let mut edges: HashMap<(u32, u32), f64> = HashMap::with_capacity(3 * triangles.len() / 2);
    for t in triangles {
        let [(a, ka), (b, kb), (c, kc)] = *t;
        let smallest = angle_at(a, b, c)
            .min(angle_at(b, c, a))
            .min(angle_at(c, a, b));
        q.min_angle_deg = q
            .min_angle_deg
            .min(if smallest.is_nan() { 0.0 } else { smallest });
        q.worst_aspect = q.worst_aspect.max(aspect(a, b, c));
        for ((p, kp), (r, kr)) in [((a, ka), (b, kb)), ((b, kb), (c, kc)), ((c, kc), (a, ka))] {
            edges
                .entry((kp.min(kr), kp.max(kr)))
                .or_insert_with(|| dist(p, r));
        }
    }
    q.total_edge_length = edges.values().sum();
    // JSON has no NaN or infinity: the verdict must stay serialisable.
    for v in [&mut q.min_angle_deg, &mut q.total_edge_length] {
        if !v.is_finite() {
            *v = if v.is_nan() { 0.0 } else { f64::MAX };
        }
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equilateral_and_right_triangles() {
        let h = 3f64.sqrt() / 2.0;
        let q = measure(&[[([0.0, 0.0], 0), ([1.0, 0.0], 1), ([0.5, h], 2)]]);
        assert!((q.min_angle_deg - 60.0).abs() < 1e-9);
        assert!((q.worst_aspect - 1.0).abs() < 1e-9);
        assert!((q.total_edge_length - 3.0).abs() < 1e-12);
        // Two right triangles of a unit square share the diagonal.
        let (a, b, c, d) = (
            ([0.0, 0.0], 0),
            ([1.0, 0.0], 1),
            ([1.0, 1.0], 2),
            ([0.0, 1.0], 3),
        );
        let q = measure(&[[a, b, c], [a, c, d]]);
        assert!((q.min_angle_deg - 45.0).abs() < 1e-9);
        assert!((q.total_edge_length - (4.0 + 2f64.sqrt())).abs() < 1e-12);
        let flat = measure(&[[a, b, ([2.0, 0.0], 5)]]);
        assert_eq!((flat.min_angle_deg, flat.worst_aspect), (0.0, f64::MAX));
        assert_eq!(measure(&[]), Quality::default());
    }
}
