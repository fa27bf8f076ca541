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
