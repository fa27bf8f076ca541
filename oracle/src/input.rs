//! What the oracle judges a triangulation of: rings of points, and which of them are holes.

use serde::{Deserialize, Serialize};

/// Whether a ring bounds its polygon from outside or is a hole in it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Role {
    /// An outer boundary: its inside belongs to the polygon.
    Outer,
    /// A hole: its inside is cut out of the polygon around it.
    Hole,
}

/// How to tell outer rings from holes.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Nesting {
    /// By containment depth: a ring inside an even number of other rings is an outer ring
    /// (an island inside a hole is a polygon of its own), inside an odd number a hole.
    /// What [`polytri::Nesting::Auto`] promises.
    #[default]
    Auto,
    /// earcut's convention: ring 0 is the outer ring, every other ring a hole in it.
    FirstIsOuter,
    /// One role per ring, as a file with several polygons says (each polygon's first ring
    /// outer, the rest its holes).
    Roles(Vec<Role>),
}

impl Nesting {
    /// [`Nesting::Roles`] for the rings of `polygons` concatenated: each polygon's first
    /// ring outer, the rest its holes.
    pub fn first_ring_outer(polygons: &[Vec<Vec<[f64; 2]>>]) -> Nesting {
        Nesting::Roles(
            (polygons.iter())
                .flat_map(|polygon| {
                    (0..polygon.len()).map(|k| if k == 0 { Role::Outer } else { Role::Hole })
                })
                .collect(),
        )
    }

    /// The matching option of the triangulator, where there is one (`Roles` has none: run
    /// polytri per polygon, or with [`polytri::Nesting::Auto`]).
    pub fn to_polytri(&self) -> Option<polytri::Nesting> {
        match self {
            Nesting::Auto => Some(polytri::Nesting::Auto),
            Nesting::FirstIsOuter => Some(polytri::Nesting::FirstIsOuter),
            Nesting::Roles(_) => None,
        }
    }
}

/// How the rings of a file of polygons (each polygon a list of rings) become one
/// [`Input`]: the command line's `--nesting` and `--merge` ([`Input::from_polygons`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Grouping {
    /// Which rings are holes: by containment ([`polytri::Nesting::Auto`]), or the first
    /// ring outer and the rest its holes ([`polytri::Nesting::FirstIsOuter`]) — within
    /// each polygon, or within the whole file with `merge`.
    pub nesting: polytri::Nesting,
    /// All rings of the file as one set of rings, instead of each polygon on its own.
    pub merge: bool,
}

/// Polygons as the triangulator takes them: every ring's points in one list, each ring
/// starting at its entry of `ring_starts` (the first is 0), and the nesting convention.
///
/// Rings may wind either way and need not repeat their first point.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Input {
    /// Every point of every ring, rings concatenated.
    pub vertices: Vec<[f64; 2]>,
    /// Index of each ring's first point; strictly increasing, starting at 0.
    pub ring_starts: Vec<usize>,
    /// Which rings are holes.
    #[serde(default)]
    pub nesting: Nesting,
}

impl Input {
    /// An input from its parts.
    pub fn new(vertices: Vec<[f64; 2]>, ring_starts: Vec<usize>, nesting: Nesting) -> Self {
        Input {
            vertices,
            ring_starts,
            nesting,
        }
    }

    /// Concatenates `rings`; empty rings are left out (their roles too, with
    /// [`Nesting::Roles`]).
    pub fn from_rings(rings: &[Vec<[f64; 2]>], nesting: Nesting) -> Self {
        let mut input = Input {
            nesting: Nesting::Auto,
            ..Input::default()
        };
        let mut roles = Vec::new();
        for (r, ring) in rings.iter().enumerate() {
            if ring.is_empty() {
                continue;
            }
            input.ring_starts.push(input.vertices.len());
            input.vertices.extend_from_slice(ring);
            if let Nesting::Roles(given) = &nesting {
                roles.push(given.get(r).copied().unwrap_or(Role::Hole));
            }
        }
        input.nesting = match nesting {
            Nesting::Roles(_) => Nesting::Roles(roles),
            other => other,
        };
        input
    }

    /// The rings of a file of polygons as one input, read as `grouping` says:
    ///
    /// - `merge`: every ring, with [`Nesting::Auto`] or [`Nesting::FirstIsOuter`] (the
    ///   file's first ring outer, every other ring a hole);
    /// - first-is-outer: one polygon as [`Nesting::FirstIsOuter`], several as
    ///   [`Nesting::Roles`] (each polygon's first ring outer, the rest its holes);
    /// - auto: containment decides within each polygon, decided here with the peers'
    ///   exact grouping ([`crate::peers::polygons`]) and written as [`Nesting::Roles`],
    ///   the rings in the groups' order — each outer ring followed by its holes, which is
    ///   the file's order where every polygon lists its outer ring first. A polygon that
    ///   is an island in its own hole becomes two. A ring whose containers do not nest
    ///   (only crossing rings give one) is kept, as an outer ring of its own, so that the
    ///   judge sees every ring.
    ///
    /// Empty rings are left out.
    ///
    /// ```
    /// use polytri_oracle::input::{Grouping, Input, Nesting, Role};
    ///
    /// let square = |x: f64, size: f64| vec![[x, x], [x + size, x], [x + size, x + size], [x, x + size]];
    /// // two polygons, the second inside the first
    /// let file = vec![vec![square(0.0, 10.0)], vec![square(2.0, 2.0)]];
    /// let each = Input::from_polygons(&file, Grouping::default());
    /// assert_eq!(each.nesting, Nesting::Roles(vec![Role::Outer, Role::Outer]));
    /// let merged = Grouping { merge: true, ..Grouping::default() };
    /// assert_eq!(Input::from_polygons(&file, merged).nesting, Nesting::Auto);
    /// ```
    pub fn from_polygons(polygons: &[Vec<Vec<[f64; 2]>>], grouping: Grouping) -> Self {
        let rings: Vec<Vec<[f64; 2]>> = polygons.iter().flatten().cloned().collect();
        let first_is_outer = grouping.nesting == polytri::Nesting::FirstIsOuter;
        if grouping.merge || (first_is_outer && polygons.len() == 1) {
            let nesting = if first_is_outer {
                Nesting::FirstIsOuter
            } else {
                Nesting::Auto
            };
            return Input::from_rings(&rings, nesting);
        }
        if first_is_outer {
            return Input::from_rings(&rings, Nesting::first_ring_outer(polygons));
        }
        let mut grouped = Vec::with_capacity(rings.len());
        let mut roles = Vec::with_capacity(rings.len());
        for polygon in polygons {
            let own = Input::from_rings(polygon, Nesting::Auto);
            let all: Vec<usize> = (0..own.ring_count()).collect();
            let (groups, unplaced) = crate::peers::group::nested_groups(&own, &all);
            let groups = groups
                .into_iter()
                .chain(unplaced.into_iter().map(|r| vec![r]));
            for group in groups {
                for (k, r) in group.into_iter().enumerate() {
                    grouped.push(own.vertices[own.ring_range(r)].to_vec());
                    roles.push(if k == 0 { Role::Outer } else { Role::Hole });
                }
            }
        }
        Input::from_rings(&grouped, Nesting::Roles(roles))
    }

    /// The number of rings.
    pub fn ring_count(&self) -> usize {
        self.ring_starts.len()
    }

    /// The index range of ring `r` in `vertices` (empty when out of range or malformed).
    pub fn ring_range(&self, r: usize) -> std::ops::Range<usize> {
        let n = self.vertices.len();
        let start = self.ring_starts.get(r).copied().unwrap_or(n).min(n);
        let end = self
            .ring_starts
            .get(r + 1)
            .copied()
            .unwrap_or(n)
            .clamp(start, n);
        start..end
    }

    /// The rings as point lists.
    pub fn rings(&self) -> Vec<Vec<[f64; 2]>> {
        (0..self.ring_count())
            .map(|r| self.vertices[self.ring_range(r)].to_vec())
            .collect()
    }

    /// The same input with every coordinate rounded to `f32` (and widened back exactly):
    /// what a `Triangulator<f32>` sees.
    pub fn to_f32(&self) -> Input {
        Input {
            vertices: self
                .vertices
                .iter()
                .map(|&[x, y]| [f64::from(x as f32), f64::from(y as f32)])
                .collect(),
            ..self.clone()
        }
    }

    /// The vertices as `f32`, for a `Triangulator<f32>`.
    pub fn vertices_f32(&self) -> Vec<[f32; 2]> {
        self.vertices
            .iter()
            .map(|&[x, y]| [x as f32, y as f32])
            .collect()
    }

    /// The same input without ring `r` (its role dropped too).
    pub fn without_ring(&self, r: usize) -> Input {
        let mut rings = self.rings();
        if r < rings.len() {
            rings.remove(r);
        }
        let nesting = match &self.nesting {
            Nesting::Roles(roles) => {
                let mut roles = roles.clone();
                if r < roles.len() {
                    roles.remove(r);
                }
                Nesting::Roles(roles)
            }
            other => other.clone(),
        };
        Input::from_rings(&rings, nesting)
    }

    /// The same input without vertex `v` (a ring left empty disappears).
    pub fn without_vertex(&self, v: usize) -> Input {
        let mut rings = self.rings();
        let mut nesting = self.nesting.clone();
        for (r, ring) in rings.iter_mut().enumerate() {
            let range = self.ring_range(r);
            if range.contains(&v) {
                ring.remove(v - range.start);
                if ring.is_empty() {
                    return self.without_ring(r);
                }
                break;
            }
        }
        if let Nesting::Roles(roles) = &mut nesting {
            roles.truncate(rings.len());
        }
        Input::from_rings(&rings, nesting)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rings_round_trip() {
        let rings = vec![
            vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0]],
            vec![],
            vec![[1.0, 1.0], [2.0, 1.0], [1.0, 2.0]],
        ];
        let input = Input::from_rings(
            &rings,
            Nesting::Roles(vec![Role::Outer, Role::Hole, Role::Hole]),
        );
        assert_eq!(input.ring_starts, vec![0, 3]);
        assert_eq!(input.nesting, Nesting::Roles(vec![Role::Outer, Role::Hole]));
        assert_eq!(input.rings().len(), 2);
        let smaller = input.without_vertex(4);
        assert_eq!(smaller.vertices.len(), 5);
        assert_eq!(smaller.ring_starts, vec![0, 3]);
        let outer = input.without_ring(1);
        assert_eq!(outer.ring_starts, vec![0]);
        assert_eq!(outer.nesting, Nesting::Roles(vec![Role::Outer]));
    }
}
