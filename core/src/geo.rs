//! [`geo_types`] integration (feature `geo-types`): triangulate a [`Polygon`],
//! [`MultiPolygon`], [`Rect`] or [`Triangle`] of the Rust geometry ecosystem in one call.
//!
//! ```
//! use geo_types::{polygon, Polygon};
//! use polytri::geo::Triangulate;
//!
//! # fn main() -> Result<(), polytri::Error> {
//! // a square with a square hole
//! let square: Polygon<f64> = polygon!(
//!     exterior: [(x: 0., y: 0.), (x: 10., y: 0.), (x: 10., y: 10.), (x: 0., y: 10.)],
//!     interiors: [[(x: 3., y: 3.), (x: 3., y: 7.), (x: 7., y: 7.), (x: 7., y: 3.)]],
//! );
//! let triangles = square.triangles(&polytri::Options::default())?;
//! assert_eq!(triangles.len(), 8);
//! let area: f64 = triangles.iter().map(|t| geo_area(t)).sum();
//! assert_eq!(area, 100.0 - 16.0);
//!
//! // for a renderer: the vertices once, and index triples into them
//! let mesh = square.triangulation(&polytri::Options::default())?;
//! assert_eq!((mesh.vertices.len(), mesh.triangles.len()), (8, 8));
//! # Ok(())
//! # }
//! # fn geo_area(t: &geo_types::Triangle<f64>) -> f64 {
//! #     let [a, b, c] = t.to_array();
//! #     ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) / 2.0
//! # }
//! ```
//!
//! Rings may come in any order and winding ([`Nesting::Auto`](crate::Nesting::Auto), the
//! default, decides holes by containment); a closing point repeating the first is dropped.
//! Triangles are counter-clockwise (y up). A [`MultiPolygon`]'s members are triangulated
//! one by one (each refused member refuses the whole, with its error). With a fill rule
//! ([`Options::with_fill_rule`]) the polygons may cross themselves: the points added
//! where edges cross are corners of the triangles, and a [`Triangulation`] lists them
//! after each polygon's own vertices.

use geo_types::{Coord as GeoCoord, CoordFloat, LineString, MultiPolygon, Polygon, Rect, Triangle};

use crate::geom::Coord;
use crate::{Error, Options, Triangulator};

/// A triangulation as a renderer wants it: the vertices once, and triangles as index
/// triples into them (counter-clockwise, y up).
#[derive(Clone, Debug, PartialEq)]
pub struct Triangulation<T> {
    /// The vertices, ring after ring, without closing points; with a fill rule, each
    /// polygon's crossing points added after its own vertices
    /// ([`Triangulator::added_vertices`]).
    pub vertices: Vec<[T; 2]>,
    /// Index triples into `vertices`.
    pub triangles: Vec<[u32; 3]>,
}

impl<T> Default for Triangulation<T> {
    fn default() -> Self {
        Triangulation {
            vertices: Vec::new(),
            triangles: Vec::new(),
        }
    }
}

/// Geometries polytri triangulates.
pub trait Triangulate<T: CoordFloat + Coord> {
    /// The triangles covering the geometry, exactly (see [`Triangulator::triangulate`]).
    ///
    /// # Errors
    ///
    /// What [`Triangulator::triangulate`] refuses with these `options`: crossing edges in
    /// strict mode, non-finite coordinates, …
    fn triangles(&self, options: &Options) -> Result<Vec<Triangle<T>>, Error> {
        let mesh = self.triangulation(options)?;
        let at = |i: u32| {
            let [x, y] = mesh.vertices[i as usize];
            GeoCoord { x, y }
        };
        Ok(mesh
            .triangles
            .iter()
            .map(|&[a, b, c]| Triangle::new(at(a), at(b), at(c)))
            .collect())
    }

    /// The vertices and index triples of the triangulation.
    ///
    /// # Errors
    ///
    /// As [`Triangulate::triangles`].
    fn triangulation(&self, options: &Options) -> Result<Triangulation<T>, Error>;
}

impl<T: CoordFloat + Coord> Triangulate<T> for Polygon<T> {
    fn triangulation(&self, options: &Options) -> Result<Triangulation<T>, Error> {
        let mut mesh = Triangulation::default();
        add_polygon(&mut Triangulator::new(), self, options, &mut mesh)?;
        Ok(mesh)
    }
}

impl<T: CoordFloat + Coord> Triangulate<T> for MultiPolygon<T> {
    fn triangulation(&self, options: &Options) -> Result<Triangulation<T>, Error> {
        let mut mesh = Triangulation::default();
        let mut tri = Triangulator::new();
        for polygon in &self.0 {
            add_polygon(&mut tri, polygon, options, &mut mesh)?;
        }
        Ok(mesh)
    }
}

impl<T: CoordFloat + Coord> Triangulate<T> for Rect<T> {
    fn triangulation(&self, options: &Options) -> Result<Triangulation<T>, Error> {
        self.to_polygon().triangulation(options)
    }
}

impl<T: CoordFloat + Coord> Triangulate<T> for Triangle<T> {
    fn triangulation(&self, options: &Options) -> Result<Triangulation<T>, Error> {
        self.to_polygon().triangulation(options)
    }
}

/// Triangulates `polygon` and appends its vertices and triangles to `mesh`.
fn add_polygon<T: CoordFloat + Coord>(
    tri: &mut Triangulator<T>,
    polygon: &Polygon<T>,
    options: &Options,
    mesh: &mut Triangulation<T>,
) -> Result<(), Error> {
    let first = mesh.vertices.len();
    let mut ring_starts = Vec::with_capacity(1 + polygon.interiors().len());
    for ring in core::iter::once(polygon.exterior()).chain(polygon.interiors()) {
        ring_starts.push(mesh.vertices.len() - first);
        mesh.vertices
            .extend(open_ring(ring).iter().map(|c| [c.x, c.y]));
    }
    let offset = u32::try_from(first).map_err(|_| Error::TooManyVertices { count: first })?;
    let mut out = Vec::new();
    tri.triangulate(&mesh.vertices[first..], &ring_starts, options, &mut out)?;
    // (with a fill rule, the crossing points added: the triangles index them after the
    // polygon's own vertices)
    mesh.vertices.extend_from_slice(tri.added_vertices());
    u32::try_from(mesh.vertices.len()).map_err(|_| Error::TooManyVertices {
        count: mesh.vertices.len(),
    })?;
    mesh.triangles
        .extend(out.iter().map(|t| t.map(|i| i + offset)));
    Ok(())
}

/// A ring's points without the closing point geo-types repeats.
fn open_ring<T: CoordFloat>(ring: &LineString<T>) -> &[GeoCoord<T>] {
    match ring.0.as_slice() {
        [first, rest @ .., last] if first == last => &ring.0[..rest.len() + 1],
        all => all,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo_types::{coord, polygon};

    fn area<T: CoordFloat + Coord>(t: &Triangle<T>) -> f64 {
        let [a, b, c] = t.to_array();
        let (ax, ay) = (a.x.to_f64(), a.y.to_f64());
        ((b.x.to_f64() - ax) * (c.y.to_f64() - ay) - (c.x.to_f64() - ax) * (b.y.to_f64() - ay))
            / 2.0
    }

    #[test]
    fn every_geometry_kind_and_precision() {
        let options = Options::default();
        let rect = Rect::new(coord! { x: 0.0f32, y: 0.0 }, coord! { x: 4.0, y: 2.0 });
        let t = rect.triangles(&options).expect("a rectangle");
        assert_eq!(t.len(), 2);
        assert_eq!(t.iter().map(area).sum::<f64>(), 8.0);
        // a clockwise triangle comes out counter-clockwise
        let cw = Triangle::new(
            coord! { x: 0.0, y: 0.0 },
            coord! { x: 0.0, y: 3.0 },
            coord! { x: 3.0, y: 0.0 },
        );
        let t = cw.triangles(&options).expect("a triangle");
        assert_eq!((t.len(), area(&t[0])), (1, 4.5));
        // two members, the second's indices offset past the first's vertices
        let a: Polygon<f64> =
            polygon![(x: 0., y: 0.), (x: 2., y: 0.), (x: 2., y: 2.), (x: 0., y: 2.)];
        let b: Polygon<f64> = polygon![(x: 5., y: 0.), (x: 6., y: 0.), (x: 6., y: 1.)];
        let mesh = MultiPolygon(vec![a, b])
            .triangulation(&options)
            .expect("two members");
        assert_eq!(mesh.vertices.len(), 7);
        assert_eq!(mesh.triangles.len(), 3);
        assert!(mesh.triangles[2].iter().all(|&i| i >= 4));
    }

    /// With a fill rule, each member's crossing points follow its own vertices, and the
    /// triangles index them there: a bow tie's two halves meet at its added centre, and
    /// a square after it keeps its own indices.
    #[test]
    fn added_vertices_follow_each_member_s_own() {
        let bow_tie: Polygon<f64> =
            polygon![(x: 0., y: 0.), (x: 4., y: 4.), (x: 4., y: 0.), (x: 0., y: 4.)];
        let square: Polygon<f64> =
            polygon![(x: 5., y: 0.), (x: 6., y: 0.), (x: 6., y: 1.), (x: 5., y: 1.)];
        let options = Options::default().with_fill_rule(crate::FillRule::EvenOdd);
        let t = bow_tie
            .triangles(&options)
            .expect("even-odd takes a bow tie");
        assert_eq!(t.len(), 2);
        assert_eq!(t.iter().map(area).sum::<f64>(), 8.0);
        assert!(t
            .iter()
            .all(|t| t.to_array().contains(&coord! { x: 2.0, y: 2.0 })));
        let mesh = MultiPolygon(vec![bow_tie, square])
            .triangulation(&options)
            .expect("two members");
        // the bow tie's 4 vertices and its centre, then the square's 4
        assert_eq!(mesh.vertices.len(), 9);
        assert_eq!(mesh.vertices[4], [2.0, 2.0]);
        assert_eq!(mesh.triangles.len(), 4);
        assert!(mesh.triangles[..2].iter().all(|t| t.contains(&4)));
        assert!(mesh.triangles[2..].iter().flatten().all(|&i| i >= 5));
    }

    #[test]
    fn errors_come_through() {
        let bow_tie: Polygon<f64> =
            polygon![(x: 0., y: 0.), (x: 4., y: 4.), (x: 4., y: 0.), (x: 0., y: 4.)];
        assert!(matches!(
            bow_tie.triangles(&Options::default()),
            Err(Error::EdgesCross { .. })
        ));
        let repaired = bow_tie.triangles(&Options::default().with_lenient(true));
        assert!(repaired.is_ok_and(|t| !t.is_empty()));
        let nan: Polygon<f64> = polygon![(x: 0., y: 0.), (x: f64::NAN, y: 0.), (x: 0., y: 1.)];
        assert_eq!(
            nan.triangles(&Options::default()),
            Err(Error::NonFinite { vertex: 1 })
        );
    }
}
