//! The reference triangulation: `spade`'s constrained Delaunay triangulation of the rings,
//! restricted to the polygon's interior.
//!
//! The constraints are the region's atomic boundary pieces (ring edges cut at every vertex
//! lying on them), so constraints never overlap and never pass through a vertex: for a
//! valid input they meet only at endpoints, which spade accepts.

use std::panic::{catch_unwind, AssertUnwindSafe};

use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

use crate::check::region::Region;
use crate::exact::{Exact, Probe};

/// The interior triangles of the CDT, as corner positions with vertex keys.
pub(crate) type Faces = Vec<[([f64; 2], u32); 3]>;

/// Triangulates `region` (which must be valid) with spade and keeps the faces whose
/// centroid has winding number 1. Errors say why spade could not.
pub(crate) fn interior_faces(region: &Region) -> Result<Faces, String> {
    // Every position on a boundary piece, once, in a stable order.
    let mut keys: Vec<u32> = region.pieces.keys().flat_map(|&(a, b)| [a, b]).collect();
    keys.sort_unstable();
    keys.dedup();
    let slot = |k: u32| keys.binary_search(&k).unwrap_or(0);
    let vertices: Vec<Point2<f64>> = keys
        .iter()
        .map(|&k| {
            let [x, y] = region.pts[k as usize];
            Point2::new(x, y)
        })
        .collect();
    let mut edges: Vec<[usize; 2]> = region
        .pieces
        .keys()
        .map(|&(a, b)| [slot(a), slot(b)])
        .collect();
    edges.sort_unstable();
    // Spade panics on constraints that cross; the pieces of a valid input never do, so a
    // panic here would be an oracle bug or a spade bug. Catching it keeps one bad input
    // from taking a whole campaign down — acceptable only here, in the harness.
    let built = catch_unwind(AssertUnwindSafe(|| {
        ConstrainedDelaunayTriangulation::<Point2<f64>>::bulk_load_cdt(vertices, edges)
    }));
    let cdt = match built {
        Ok(Ok(cdt)) => cdt,
        Ok(Err(e)) => return Err(format!("spade refused the vertices: {e:?}")),
        Err(_) => return Err("spade panicked while building the triangulation".to_owned()),
    };
    let mut stamps = region.stamps();
    let mut faces = Faces::new();
    for face in cdt.inner_faces() {
        let corners = face.vertices().map(|v| {
            let p = v.position();
            let key = keys.get(v.fix().index()).copied().unwrap_or(u32::MAX);
            ([p.x, p.y], key)
        });
        let [a, b, c] = corners.map(|c| c.0);
        if region.winding(&Probe::centroid(a, b, c), &mut stamps) == Some(1) {
            faces.push(corners);
        }
    }
    Ok(faces)
}

/// Twice the faces' total area, exactly.
pub(crate) fn twice_area(faces: &Faces) -> Exact {
    let mut sum = Exact::default();
    for [(a, _), (b, _), (c, _)] in faces {
        sum.add_twice_area(*a, *b, *c);
    }
    sum
}
