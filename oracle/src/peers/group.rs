//! Grouping an input's rings into polygons (outer ring first, then its holes), the
//! convention earcut and earcutr need.

use crate::input::{Input, Nesting, Role};

/// One polygon of an input, copied out contiguous: its outer ring first, then its holes.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Polygon {
    /// The points of the outer ring, then of each hole.
    pub vertices: Vec<[f64; 2]>,
    /// Where each ring starts in `vertices` (the first is 0).
    pub ring_starts: Vec<usize>,
    /// For each point of `vertices`, its index in the input.
    pub to_input: Vec<u32>,
}

impl Polygon {
    /// earcut's hole indices: every ring start but the first.
    pub fn hole_indices(&self) -> Vec<u32> {
        self.ring_starts.iter().skip(1).map(|&s| s as u32).collect()
    }

    fn push_ring(&mut self, input: &Input, r: usize) {
        let range = input.ring_range(r);
        self.ring_starts.push(self.vertices.len());
        self.vertices
            .extend_from_slice(&input.vertices[range.clone()]);
        self.to_input.extend(range.map(|v| v as u32));
    }
}

/// The polygons of `input`, each with its outer ring first.
///
/// - [`Nesting::FirstIsOuter`]: one polygon of every ring.
/// - [`Nesting::Roles`]: each outer ring starts a polygon, the holes after it join it (a
///   hole before any outer ring is taken as an outer ring).
/// - [`Nesting::Auto`]: containment depth, decided with exact orientation tests on one
///   vertex of each ring not on the other's boundary; a ring at odd depth is a hole of the
///   innermost ring containing it. Quadratic in the rings at worst, bounding boxes prune
///   most pairs.
///
/// Empty rings are left out.
pub fn polygons(input: &Input) -> Vec<Polygon> {
    let rings: Vec<usize> = (0..input.ring_count())
        .filter(|&r| !input.ring_range(r).is_empty())
        .collect();
    match &input.nesting {
        Nesting::FirstIsOuter => {
            let mut polygon = Polygon::default();
            for &r in &rings {
                polygon.push_ring(input, r);
            }
            if polygon.vertices.is_empty() {
                Vec::new()
            } else {
                vec![polygon]
            }
        }
        Nesting::Roles(roles) => {
            let mut polygons: Vec<Polygon> = Vec::new();
            for &r in &rings {
                let role = roles.get(r).copied().unwrap_or(Role::Hole);
                if role == Role::Outer || polygons.is_empty() {
                    polygons.push(Polygon::default());
                }
                if let Some(polygon) = polygons.last_mut() {
                    polygon.push_ring(input, r);
                }
            }
            polygons
        }
        Nesting::Auto => by_containment(input, &rings),
    }
}

/// Groups by containment depth: see [`polygons`].
fn by_containment(input: &Input, rings: &[usize]) -> Vec<Polygon> {
    let (groups, _) = nested_groups(input, rings);
    (groups.iter())
        .map(|group| {
            let mut polygon = Polygon::default();
            for &r in group {
                polygon.push_ring(input, r);
            }
            polygon
        })
        .collect()
}

/// The rings of `rings` (indices into `input`) grouped by containment depth, as
/// [`polygons`] does for [`Nesting::Auto`]: each group an outer ring (even depth, in input
/// order) followed by its holes (odd depth, each the hole of the innermost ring containing
/// it). Second, the rings no group took: at odd depth with an innermost container at odd
/// depth too, which only crossing rings give.
pub(crate) fn nested_groups(input: &Input, rings: &[usize]) -> (Vec<Vec<usize>>, Vec<usize>) {
    let boxes: Vec<[f64; 4]> = rings
        .iter()
        .map(|&r| bounding_box(&input.vertices[input.ring_range(r)]))
        .collect();
    // containers[i]: the rings (positions in `rings`) that contain ring i
    let mut containers: Vec<Vec<usize>> = vec![Vec::new(); rings.len()];
    for (i, &r) in rings.iter().enumerate() {
        for (j, &s) in rings.iter().enumerate() {
            if i != j && box_inside(&boxes[i], &boxes[j]) && ring_inside(input, r, s) {
                containers[i].push(j);
            }
        }
    }
    let depth: Vec<usize> = containers.iter().map(Vec::len).collect();
    let mut group_of: Vec<Option<usize>> = vec![None; rings.len()];
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for (i, &r) in rings.iter().enumerate() {
        if depth[i].is_multiple_of(2) {
            group_of[i] = Some(groups.len());
            groups.push(vec![r]);
        }
    }
    let mut unplaced = Vec::new();
    for (i, &r) in rings.iter().enumerate() {
        if !depth[i].is_multiple_of(2) {
            // the innermost container is the one nested deepest itself
            let parent = containers[i].iter().copied().max_by_key(|&j| depth[j]);
            match parent.and_then(|j| group_of[j]) {
                Some(g) => groups[g].push(r),
                None => unplaced.push(r),
            }
        }
    }
    (groups, unplaced)
}

/// `[min x, min y, max x, max y]` of `points`.
fn bounding_box(points: &[[f64; 2]]) -> [f64; 4] {
    points.iter().fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |[x0, y0, x1, y1], &[x, y]| [x0.min(x), y0.min(y), x1.max(x), y1.max(y)],
    )
}

/// Whether box `a` lies within box `b` (boundaries may touch): necessary for containment.
fn box_inside(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] >= b[0] && a[1] >= b[1] && a[2] <= b[2] && a[3] <= b[3]
}

/// Whether ring `r` lies inside ring `s`, judged at the first vertex of `r` that is not on
/// the boundary of `s` (a ring entirely on another's boundary is not inside it).
fn ring_inside(input: &Input, r: usize, s: usize) -> bool {
    let ring = &input.vertices[input.ring_range(s)];
    input.vertices[input.ring_range(r)]
        .iter()
        .map(|&p| locate(p, ring))
        .find(|&l| l != Location::Boundary)
        == Some(Location::Inside)
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Location {
    Inside,
    Outside,
    Boundary,
}

/// Where `p` lies relative to `ring`: crossing number with exact orientation tests.
fn locate(p: [f64; 2], ring: &[[f64; 2]]) -> Location {
    let point = |q: [f64; 2]| robust::Coord { x: q[0], y: q[1] };
    let mut inside = false;
    for (k, &a) in ring.iter().enumerate() {
        let b = ring[(k + 1) % ring.len()];
        let side = robust::orient2d(point(a), point(b), point(p));
        let within_box = p[0] >= a[0].min(b[0])
            && p[0] <= a[0].max(b[0])
            && p[1] >= a[1].min(b[1])
            && p[1] <= a[1].max(b[1]);
        if side == 0.0 && within_box {
            return Location::Boundary;
        }
        // half-open in y, so a ray through a vertex counts it once
        if (a[1] > p[1]) != (b[1] > p[1]) {
            // the edge crosses the ray to the right of p when p is on its left going up,
            // on its right going down
            let upward = b[1] > a[1];
            if (side > 0.0) == upward {
                inside = !inside;
            }
        }
    }
    if inside {
        Location::Inside
    } else {
        Location::Outside
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x: f64, y: f64, size: f64) -> Vec<[f64; 2]> {
        vec![[x, y], [x + size, y], [x + size, y + size], [x, y + size]]
    }

    #[test]
    fn auto_nesting_finds_island_in_hole() {
        let rings = vec![
            square(4.0, 4.0, 2.0),  // island, depth 2
            square(0.0, 0.0, 10.0), // outer, depth 0
            square(2.0, 2.0, 6.0),  // hole, depth 1
            square(20.0, 0.0, 1.0), // another outer
        ];
        let input = Input::from_rings(&rings, Nesting::Auto);
        let polygons = polygons(&input);
        let starts: Vec<_> = polygons.iter().map(|p| p.ring_starts.clone()).collect();
        assert_eq!(starts, vec![vec![0], vec![0, 4], vec![0]]);
        assert_eq!(polygons[1].to_input[4..], [8, 9, 10, 11]);
    }

    #[test]
    fn roles_start_a_polygon_at_each_outer_ring() {
        let rings = vec![
            square(0.0, 0.0, 10.0),
            square(2.0, 2.0, 1.0),
            square(20.0, 0.0, 1.0),
        ];
        let input = Input::from_rings(
            &rings,
            Nesting::Roles(vec![Role::Outer, Role::Hole, Role::Outer]),
        );
        let polygons = polygons(&input);
        assert_eq!(polygons.len(), 2);
        assert_eq!(polygons[0].hole_indices(), vec![4]);
    }

    #[test]
    fn a_vertex_on_the_boundary_is_neither_in_nor_out() {
        let ring = square(0.0, 0.0, 2.0);
        assert_eq!(locate([1.0, 0.0], &ring), Location::Boundary);
        assert_eq!(locate([1.0, 1.0], &ring), Location::Inside);
        assert_eq!(locate([3.0, 0.0], &ring), Location::Outside);
    }
}
