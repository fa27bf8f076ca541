//! Planar polygons in 3D: [`Triangulator::triangulate_3d`].
//!
//! A wall of a building, a face of a CAD model: rings with x, y and z that lie in one
//! plane. The polygon's normal comes from Newell's method (the sums of the rings' edge
//! cross products, robust for any simple polygon, convex or not); the coordinate of its
//! largest component is dropped, which projects the polygon onto the coordinate plane it
//! is least inclined to. The projected coordinates are the input's own (no arithmetic),
//! so the triangulation is exact for them, and each triangle indexes the 3D vertices
//! unchanged: z is kept. Triangles turn the way the outer ring does, seen along its normal.

use crate::geom::Coord;
use crate::report::Report;
use crate::{Error, Options, Triangulator};

/// How far from planar a 3D polygon may be for strict mode: every vertex within this
/// fraction of the polygon's size (its bounding box's diagonal) from the plane through
/// the vertices' centroid with the Newell normal. Rounding a planar polygon's
/// coordinates to `f64` moves them by far less; a polygon bent more than this is refused
/// with [`Error::NotPlanar`] (lenient mode triangulates its projection anyway).
pub const PLANAR_TOLERANCE: f64 = 1e-9;

/// How a 3D polygon was projected, and how planar it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    /// The polygon's normal by Newell's method (not normalised; zero for a polygon with no
    /// area).
    pub normal: [f64; 3],
    /// The coordinate dropped: 0 (x), 1 (y) or 2 (z), that of the normal's largest
    /// component.
    pub dropped: usize,
    /// The largest distance of a vertex from the polygon's plane, over the polygon's size
    /// (0 for a planar polygon; compare with [`PLANAR_TOLERANCE`]).
    pub off_plane: f64,
    /// The vertex at that distance.
    pub furthest: usize,
}

impl<T: Coord> Triangulator<T> {
    /// Triangulates a planar polygon in 3D: rings of `[x, y, z]` vertices, as
    /// [`Triangulator::triangulate`] takes rings of `[x, y]` (any number of holes, any
    /// order and winding). The triangles index `vertices`, so z is kept; they turn the way
    /// the first ring does seen along the polygon's normal. The [`Projection`] says which
    /// coordinate was dropped and how far from planar the polygon is.
    ///
    /// ```
    /// # fn main() -> Result<(), polytri::Error> {
    /// // a wall in the plane x = 2, with a window
    /// let wall: [[f64; 3]; 8] = [
    ///     [2.0, 0.0, 0.0], [2.0, 6.0, 0.0], [2.0, 6.0, 3.0], [2.0, 0.0, 3.0],
    ///     [2.0, 2.0, 1.0], [2.0, 2.0, 2.0], [2.0, 4.0, 2.0], [2.0, 4.0, 1.0],
    /// ];
    /// let mut tri = polytri::Triangulator::<f64>::new();
    /// let mut out = Vec::new();
    /// let (report, projection) =
    ///     tri.triangulate_3d(&wall, &[0, 4], &polytri::Options::default(), &mut out)?;
    /// assert_eq!(report.triangles, 8); // n - 2 + 2h
    /// assert_eq!(projection.dropped, 0); // x, the wall's normal direction
    /// assert_eq!(projection.off_plane, 0.0);
    /// # Ok(())
    /// # }
    /// ```
    ///
    /// # Errors
    ///
    /// Those of [`Triangulator::triangulate`] on the projection, in strict mode
    /// [`Error::NotPlanar`] for a polygon further from planar than [`PLANAR_TOLERANCE`],
    /// and [`Error::CrossingIn3d`] where a fill rule would add a vertex (crossing edges).
    pub fn triangulate_3d(
        &mut self,
        vertices: &[[T; 3]],
        ring_starts: &[usize],
        options: &Options,
        out: &mut Vec<[u32; 3]>,
    ) -> Result<(Report<'_>, Projection), Error> {
        let projection = project(vertices, ring_starts)?;
        if !options.lenient && projection.off_plane > PLANAR_TOLERANCE {
            return Err(Error::NotPlanar {
                vertex: projection.furthest,
            });
        }
        let (u, v) = match projection.dropped {
            0 => (1, 2),
            1 => (2, 0),
            _ => (0, 1),
        };
        // (u, v) keeps the right hand: seen from the positive dropped axis, counter-
        // clockwise in (u, v) is counter-clockwise in 3D
        let fill = |flat: &mut Vec<[T; 2]>| flat.extend(vertices.iter().map(|p| [p[u], p[v]]));
        let report = self.triangulate_filled(fill, ring_starts, options, out)?;
        // (a crossing point would have no z)
        if let Some(added) = report.added.first() {
            let [edge_a, edge_b] = added.edges.map(|e| e as usize);
            out.clear();
            return Err(Error::CrossingIn3d { edge_a, edge_b });
        }
        if projection.normal[projection.dropped] < 0.0 {
            // the outer ring turns clockwise seen from the positive axis: so must the
            // triangles
            for t in out.iter_mut() {
                t.swap(1, 2);
            }
        }
        Ok((report, projection))
    }
}

/// Newell's normal of the polygon's rings, the coordinate to drop, and how far from its
/// plane the vertices lie.
fn project<T: Coord>(vertices: &[[T; 3]], ring_starts: &[usize]) -> Result<Projection, Error> {
    let p = |i: usize| vertices[i].map(Coord::to_f64);
    if let Some(k) = (0..vertices.len()).find(|&i| p(i).iter().any(|c| !c.is_finite())) {
        return Err(Error::NonFinite { vertex: k });
    }
    // ring bounds as `triangulate` reads them; bad starts are its to report
    let mut normal = [0.0f64; 3];
    let outer_end = ring_starts.get(1).copied().unwrap_or(vertices.len());
    if ring_starts.first() == Some(&0) && outer_end <= vertices.len() {
        // the outer ring's normal: holes turn either way, and only the outer ring's
        // winding is the polygon's
        for i in 0..outer_end {
            let (a, b) = (p(i), p(if i + 1 == outer_end { 0 } else { i + 1 }));
            normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
            normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
            normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
        }
    }
    let dropped = (0..3)
        .max_by(|&i, &j| normal[i].abs().total_cmp(&normal[j].abs()))
        .unwrap_or(2);
    // distances from the plane through the centroid, over the bounding box's diagonal
    let n = vertices.len().max(1) as f64;
    let mut centroid = [0.0; 3];
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for i in 0..vertices.len() {
        let q = p(i);
        for k in 0..3 {
            centroid[k] += q[k] / n;
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    let length = normal.iter().map(|c| c * c).sum::<f64>().sqrt();
    let size = (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>().sqrt();
    let (mut off_plane, mut furthest) = (0.0, 0);
    if length > 0.0 && size > 0.0 {
        for i in 0..vertices.len() {
            let q = p(i);
            let d = (0..3)
                .map(|k| (q[k] - centroid[k]) * normal[k])
                .sum::<f64>()
                .abs()
                / length;
            if d / size > off_plane {
                (off_plane, furthest) = (d / size, i);
            }
        }
    }
    Ok(Projection {
        normal,
        dropped,
        off_plane,
        furthest,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The wall with a window, mapped into 3D by `place` (from plane coordinates).
    pub(super) fn wall(place: impl Fn(f64, f64) -> [f64; 3]) -> Vec<[f64; 3]> {
        [
            (0.0, 0.0),
            (6.0, 0.0),
            (6.0, 3.0),
            (0.0, 3.0),
            (2.0, 1.0),
            (2.0, 2.0),
            (4.0, 2.0),
            (4.0, 1.0),
        ]
        .into_iter()
        .map(|(s, t)| place(s, t))
        .collect()
    }

    /// Twice the 3D area of a triangle, signed along `normal`.
    fn area_along(v: &[[f64; 3]], t: [u32; 3], normal: [f64; 3]) -> f64 {
        let [a, b, c] = t.map(|i| v[i as usize]);
        let (e, f) = (
            [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
            [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
        );
        let cross = [
            e[1] * f[2] - e[2] * f[1],
            e[2] * f[0] - e[0] * f[2],
            e[0] * f[1] - e[1] * f[0],
        ];
        (0..3).map(|k| cross[k] * normal[k]).sum()
    }

    #[test]
    fn walls_in_every_plane_and_facing_keep_z_and_turn() {
        type Place = Box<dyn Fn(f64, f64) -> [f64; 3]>;
        let placements: [(&str, Place, usize); 6] = [
            ("x = 2", Box::new(|s, t| [2.0, s, t]), 0),
            ("x = 2, mirrored", Box::new(|s, t| [2.0, t, s]), 0),
            ("y = -1", Box::new(|s, t| [t, -1.0, s]), 1),
            ("z = 5", Box::new(|s, t| [s, t, 5.0]), 2),
            ("z = 5, mirrored", Box::new(|s, t| [t, s, 5.0]), 2),
            ("tilted", Box::new(|s, t| [s, t, 0.5 * s + 0.25 * t]), 2),
        ];
        let mut tri = Triangulator::<f64>::new();
        let mut out = Vec::new();
        for (name, place, axis) in placements {
            let v = wall(place);
            let (report, projection) = tri
                .triangulate_3d(&v, &[0, 4], &Options::default(), &mut out)
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(report.triangles, 8, "{name}");
            assert_eq!(projection.dropped, axis, "{name}");
            assert!(projection.off_plane < 1e-15, "{name}");
            // every triangle turns the outer ring's way; together they cover 6·3 − 2·1 of the
            // plane coordinates
            let total: f64 = out
                .iter()
                .map(|&t| area_along(&v, t, projection.normal))
                .sum();
            assert!(
                out.iter()
                    .all(|&t| area_along(&v, t, projection.normal) > 0.0),
                "{name}"
            );
            let length = projection.normal.iter().map(|c| c * c).sum::<f64>().sqrt();
            // (the tilted wall is stretched by the slope of its plane over z = 0)
            let stretch = if name == "tilted" {
                (1.0f64 + 0.25 + 0.0625).sqrt()
            } else {
                1.0
            };
            let area = total / length / 2.0;
            assert!((area - 16.0 * stretch).abs() < 1e-9, "{name}: {area}");
        }
    }

    #[test]
    fn bent_polygons_are_refused_or_projected() {
        let mut v = wall(|s, t| [s, t, 0.0]);
        v[6][2] = 0.5; // a window corner lifted off the plane
        let mut tri = Triangulator::<f64>::new();
        let mut out = Vec::new();
        let strict = tri.triangulate_3d(&v, &[0, 4], &Options::default(), &mut out);
        assert_eq!(strict.err(), Some(Error::NotPlanar { vertex: 6 }));
        let lenient = Options::default().with_lenient(true);
        let (report, projection) = tri
            .triangulate_3d(&v, &[0, 4], &lenient, &mut out)
            .expect("lenient");
        assert_eq!(report.triangles, 8);
        assert!(projection.off_plane > PLANAR_TOLERANCE);
        // f32 and non-finite input
        let v32: Vec<[f32; 3]> = wall(|s, t| [s, 1.0, t])
            .iter()
            .map(|p| p.map(|c| c as f32))
            .collect();
        assert!(Triangulator::<f32>::new()
            .triangulate_3d(&v32, &[0, 4], &Options::default(), &mut out)
            .is_ok());
        let mut bad = wall(|s, t| [s, t, 0.0]);
        bad[2][2] = f64::NAN;
        assert_eq!(
            tri.triangulate_3d(&bad, &[0, 4], &Options::default(), &mut out)
                .err(),
            Some(Error::NonFinite { vertex: 2 })
        );
    }
}

#[cfg(test)]
mod garbage {
    use super::*;
    use crate::testing::random;

    /// With a fill rule, a 3D polygon whose edges cross is refused (a crossing point has
    /// no z), naming two crossing edges, and leaves no triangles; one whose edges do not
    /// cross is triangulated, nothing added; lenient mode without a fill rule adds none.
    #[test]
    fn crossing_edges_in_3d_add_no_vertex() {
        // (lobes of unequal areas, so that the normal points along x)
        let bow_tie: [[f64; 3]; 4] = [
            [0.0, 0.0, 1.0],
            [0.0, 4.0, 7.0],
            [0.0, 4.0, 1.0],
            [0.0, 0.0, 5.0],
        ];
        let even_odd = Options::new().with_fill_rule(crate::FillRule::EvenOdd);
        let mut tri = Triangulator::<f64>::new();
        let mut out = vec![[0, 1, 2]];
        let refused = tri.triangulate_3d(&bow_tie, &[0], &even_odd, &mut out);
        assert_eq!(
            refused.err(),
            Some(Error::CrossingIn3d {
                edge_a: 0,
                edge_b: 2
            })
        );
        assert!(out.is_empty());
        let seidel = Options::new()
            .with_strategy(crate::Strategy::Seidel)
            .with_lenient(true);
        let refused = tri.triangulate_3d(&bow_tie, &[0], &seidel, &mut out);
        assert!(matches!(refused, Err(Error::CrossingIn3d { .. })));
        let lenient = Options::new().with_lenient(true);
        let made = tri.triangulate_3d(&bow_tie, &[0], &lenient, &mut out);
        assert!(made.is_ok_and(|(r, _)| r.added.is_empty()));
        assert!(out.iter().flatten().all(|&v| v < 4));
        let w = super::tests::wall(|s, t| [s, 1.0, t]);
        let made = tri.triangulate_3d(&w, &[0, 4], &even_odd, &mut out);
        assert!(made.is_ok_and(|(r, _)| r.triangles == 8 && r.added.is_empty()));
    }

    /// Whatever the input — NaN, infinities, huge and tiny values, repeated points, bad
    /// ring starts — `triangulate_3d` returns, and a result's triangles index the input.
    #[test]
    fn never_panics() {
        let mut next = random(0x3d_3d_3d);
        let values = [
            0.0,
            1.0,
            -1.0,
            0.5,
            1e300,
            -1e-300,
            f64::NAN,
            f64::INFINITY,
            3.0,
            7.0,
        ];
        let mut tri = Triangulator::<f64>::new();
        let mut out = Vec::new();
        for case in 0..3000 {
            let n = next(12) as usize;
            let vertices: Vec<[f64; 3]> = (0..n)
                .map(|_| [0; 3].map(|_| values[next(values.len() as u64) as usize]))
                .collect();
            let starts: Vec<usize> = (0..next(4)).map(|_| next(14) as usize).collect();
            let options = Options::default().with_lenient(case % 2 == 1);
            if let Ok((report, projection)) =
                tri.triangulate_3d(&vertices, &starts, &options, &mut out)
            {
                assert_eq!(report.triangles, out.len());
                assert!(out.iter().flatten().all(|&i| (i as usize) < n));
                assert!(projection.dropped < 3);
            }
        }
    }
}
