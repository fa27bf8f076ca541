//! The file's polygons flattened into what the triangulator takes — one vertex list and
//! ring starts — and the way back from a flat index to "polygon P, ring R, vertex V".
//!
//! The triangulator names problems by flat vertex index and by position in `ring_starts`;
//! a user needs the place in their file. Empty rings are left out of `ring_starts` (the
//! triangulator requires strictly increasing starts), so flat ring numbers and file ring
//! numbers can differ, and every flat ring remembers where it came from.

use std::fmt;
use std::ops::Range;

use crate::input::Polygon;

/// Where a flat ring came from: polygon and ring within it, as numbered in the file
/// (from 0; ring 0 is the polygon's outer boundary).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RingOrigin {
    /// Polygon index in file order.
    pub polygon: usize,
    /// Ring index within the polygon.
    pub ring: usize,
}

impl RingOrigin {
    /// True for every ring but a polygon's first: the file says it is a hole.
    pub fn is_hole(self) -> bool {
        self.ring > 0
    }
}

/// A flat vertex's place in the file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Location {
    /// Polygon index in file order.
    pub polygon: usize,
    /// Ring index within the polygon.
    pub ring: usize,
    /// Point index within the ring, as in the file.
    pub vertex: usize,
}

/// All rings of a file in one vertex list, as [`polytri::Triangulator::triangulate`] takes
/// them, with the file position of every ring.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Layout {
    /// Every point, rings concatenated in file order.
    pub vertices: Vec<[f64; 2]>,
    /// First vertex of each non-empty ring; the first entry is 0.
    pub ring_starts: Vec<usize>,
    /// The file position of each ring of `ring_starts`.
    pub ring_origins: Vec<RingOrigin>,
    /// For each polygon of the file, its range of rings in `ring_starts` (empty when all
    /// its rings are empty).
    pub polygon_rings: Vec<Range<usize>>,
    /// How many empty rings were left out.
    pub empty_rings: usize,
}

impl Layout {
    /// Flattens `polygons`, leaving out empty rings.
    pub fn new(polygons: &[Polygon]) -> Self {
        let mut layout = Layout::default();
        for (p, polygon) in polygons.iter().enumerate() {
            let first = layout.ring_starts.len();
            for (r, ring) in polygon.iter().enumerate() {
                if ring.is_empty() {
                    layout.empty_rings += 1;
                    continue;
                }
                layout.ring_starts.push(layout.vertices.len());
                layout.ring_origins.push(RingOrigin {
                    polygon: p,
                    ring: r,
                });
                layout.vertices.extend_from_slice(ring);
            }
            layout.polygon_rings.push(first..layout.ring_starts.len());
        }
        layout
    }

    /// The starts of flat rings `rings`, counted from vertex `first`: the ring starts of a
    /// piece triangulated on its own.
    pub fn ring_starts_from(&self, rings: Range<usize>, first: usize) -> Vec<usize> {
        (self.ring_starts[rings].iter())
            .map(|s| s - first)
            .collect()
    }

    /// The flat vertex range of flat ring `ring`.
    pub fn ring_vertices(&self, ring: usize) -> Range<usize> {
        let start = self
            .ring_starts
            .get(ring)
            .copied()
            .unwrap_or(self.vertices.len());
        let end = self
            .ring_starts
            .get(ring + 1)
            .copied()
            .unwrap_or(self.vertices.len());
        start..end
    }

    /// The flat vertex range of the file's polygon `polygon`.
    pub fn polygon_vertices(&self, polygon: usize) -> Range<usize> {
        match self.polygon_rings.get(polygon) {
            Some(rings) if !rings.is_empty() => {
                self.ring_vertices(rings.start).start..self.ring_vertices(rings.end - 1).end
            }
            _ => 0..0,
        }
    }

    /// The file position of flat vertex `vertex`, or `None` past the end.
    pub fn locate(&self, vertex: usize) -> Option<Location> {
        if vertex >= self.vertices.len() {
            return None;
        }
        // The ring is the last one starting at or before the vertex.
        let ring = self
            .ring_starts
            .partition_point(|&start| start <= vertex)
            .checked_sub(1)?;
        let origin = self.ring_origins.get(ring)?;
        Some(Location {
            polygon: origin.polygon,
            ring: origin.ring,
            vertex: vertex - self.ring_starts[ring],
        })
    }

    /// Names flat vertex `vertex` for a message: "ring 1, vertex 3", with the polygon in
    /// front when the file has several.
    pub fn describe_vertex(&self, vertex: usize) -> String {
        match self.locate(vertex) {
            Some(at) => Place {
                layout: self,
                polygon: at.polygon,
                ring: at.ring,
                vertex: Some(at.vertex),
            }
            .to_string(),
            None => format!("vertex {vertex} (past the end of the input)"),
        }
    }

    /// Names flat ring `ring` for a message: "ring 1", with the polygon in front when the
    /// file has several.
    pub fn describe_ring(&self, ring: usize) -> String {
        match self.ring_origins.get(ring) {
            Some(at) => Place {
                layout: self,
                polygon: at.polygon,
                ring: at.ring,
                vertex: None,
            }
            .to_string(),
            None => format!("ring {ring} (past the end of the input)"),
        }
    }
}

/// A position in the file, written the way a user counts it.
struct Place<'a> {
    layout: &'a Layout,
    polygon: usize,
    ring: usize,
    vertex: Option<usize>,
}

impl fmt::Display for Place<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // With one polygon "polygon 0" is noise; rings files always have one.
        if self.layout.polygon_rings.len() > 1 {
            write!(f, "polygon {}, ", self.polygon)?;
        }
        write!(f, "ring {}", self.ring)?;
        if let Some(vertex) = self.vertex {
            write!(f, ", vertex {vertex}")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(n: usize) -> Vec<[f64; 2]> {
        (0..n).map(|i| [i as f64, 0.0]).collect()
    }

    #[test]
    fn flat_indices_map_back_to_the_file() {
        // Polygon 0: rings of 4 and 3; polygon 1: an empty ring, then 5.
        let polygons = vec![vec![ring(4), ring(3)], vec![ring(0), ring(5)]];
        let layout = Layout::new(&polygons);
        assert_eq!(layout.vertices.len(), 12);
        assert_eq!(layout.ring_starts, vec![0, 4, 7]);
        assert_eq!(layout.empty_rings, 1);
        assert_eq!(layout.polygon_rings, vec![0..2, 2..3]);
        assert_eq!(layout.polygon_vertices(1), 7..12);
        assert_eq!(
            layout.locate(0),
            Some(Location {
                polygon: 0,
                ring: 0,
                vertex: 0
            })
        );
        assert_eq!(
            layout.locate(6),
            Some(Location {
                polygon: 0,
                ring: 1,
                vertex: 2
            })
        );
        // The empty ring keeps its number: the next one is still ring 1 of polygon 1.
        assert_eq!(
            layout.locate(9),
            Some(Location {
                polygon: 1,
                ring: 1,
                vertex: 2
            })
        );
        assert_eq!(layout.locate(12), None);
        assert_eq!(layout.describe_vertex(9), "polygon 1, ring 1, vertex 2");
        assert_eq!(layout.describe_ring(2), "polygon 1, ring 1");
        assert!(layout.ring_origins[2].is_hole());
    }

    #[test]
    fn single_polygon_places_omit_the_polygon() {
        let layout = Layout::new(&[vec![ring(4), ring(3)]]);
        assert_eq!(layout.describe_vertex(5), "ring 1, vertex 1");
        assert_eq!(layout.describe_ring(0), "ring 0");
        assert!(layout.describe_vertex(99).contains("past the end"));
    }

    #[test]
    fn polygons_without_rings_are_empty_ranges() {
        let layout = Layout::new(&[vec![], vec![ring(3)]]);
        assert_eq!(layout.polygon_rings, vec![0..0, 0..1]);
        assert_eq!(layout.polygon_vertices(0), 0..0);
        assert_eq!(layout.polygon_vertices(1), 0..3);
        assert_eq!(layout.polygon_vertices(7), 0..0);
    }
}
