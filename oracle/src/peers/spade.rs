//! spade: the constrained Delaunay triangulation of every ring, kept at odd nesting depth.

use std::collections::HashMap;

use spade::handles::{FixedFaceHandle, FixedVertexHandle, InnerTag};
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

use super::PeerOutput;
use crate::input::Input;

/// The CDT spade builds.
type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;

/// The rings as spade takes them: distinct points and constraint edges between them.
#[derive(Clone, Debug, Default)]
pub(super) struct Constraints {
    /// Each distinct position once, in input order of first appearance.
    pub points: Vec<Point2<f64>>,
    /// Every ring edge, as often as the rings have it.
    pub edges: Vec<[usize; 2]>,
    /// The distinct ring edges, the constraints spade is given.
    pub constraints: Vec<[usize; 2]>,
    /// For each point, the first input vertex at its position.
    pub to_input: Vec<u32>,
}

impl Constraints {
    /// The points and edges of `input`'s rings. spade merges equal points itself and
    /// refuses repeated constraints, so both are merged here first.
    pub fn new(input: &Input) -> Self {
        let mut this = Constraints::default();
        let mut point_of: HashMap<[u64; 2], usize> = HashMap::with_capacity(input.vertices.len());
        let mut unique = Vec::with_capacity(input.vertices.len());
        for (v, &[x, y]) in input.vertices.iter().enumerate() {
            // + 0.0 turns -0.0 into 0.0: spade takes them for one point
            let key = [(x + 0.0).to_bits(), (y + 0.0).to_bits()];
            let id = *point_of.entry(key).or_insert_with(|| {
                this.points.push(Point2::new(x, y));
                this.to_input.push(v as u32);
                this.points.len() - 1
            });
            unique.push(id);
        }
        for r in 0..input.ring_count() {
            let ring = &unique[input.ring_range(r)];
            for (k, &a) in ring.iter().enumerate() {
                let b = ring[(k + 1) % ring.len()];
                if a != b {
                    this.edges.push([a, b]);
                }
            }
        }
        // spade refuses the same constraint twice; the parity count keeps every copy
        let mut seen: Vec<[usize; 2]> = this
            .edges
            .iter()
            .map(|&[a, b]| [a.min(b), a.max(b)])
            .collect();
        seen.sort_unstable();
        seen.dedup();
        this.constraints = seen;
        this
    }

    /// Builds the CDT. Conflicting constraints (crossing rings) are skipped, not fatal.
    pub fn triangulate(&self) -> Result<Cdt, String> {
        Cdt::try_bulk_load_cdt(self.points.clone(), self.constraints.clone(), |_| {})
            .map_err(|e| format!("spade: {e:?}"))
    }
}

/// Whether each undirected edge of `cdt` lies on an odd number of the ring edges.
///
/// spade splits a constraint at every vertex on it, and merges constraints that overlap
/// (a hole's edge along its outer ring's): so each ring edge is followed through the CDT
/// as a chain of collinear edges, and each piece counted.
fn boundary_parity(cdt: &Cdt, edges: &[[usize; 2]]) -> Vec<bool> {
    let mut odd = vec![false; cdt.num_undirected_edges()];
    let coord = |p: Point2<f64>| robust::Coord { x: p.x, y: p.y };
    for &[a, b] in edges {
        let target = cdt.vertex(FixedVertexHandle::from_index(b)).position();
        let mut current = FixedVertexHandle::from_index(a);
        while current.index() != b {
            let here = cdt.vertex(current).position();
            let forward = |p: Point2<f64>| {
                robust::orient2d(coord(here), coord(target), coord(p)) == 0.0
                    && (p.x - here.x) * (target.x - here.x) + (p.y - here.y) * (target.y - here.y)
                        > 0.0
            };
            let next = cdt
                .vertex(current)
                .out_edges()
                .find(|edge| forward(edge.to().position()));
            let Some(edge) = next else {
                break; // a constraint spade skipped (crossing rings)
            };
            let slot = &mut odd[edge.as_undirected().fix().index()];
            *slot = !*slot;
            current = edge.to().fix();
        }
    }
    odd
}

/// The inner faces of `cdt` at odd depth: crossing a ring edge flips the depth, the outer
/// face is at depth 0.
pub(super) fn interior_faces(cdt: &Cdt, edges: &[[usize; 2]]) -> Vec<FixedFaceHandle<InnerTag>> {
    let boundary = boundary_parity(cdt, edges);
    let flips = |edge: spade::handles::DirectedEdgeHandle<'_, _, _, _, _>| {
        boundary[edge.as_undirected().fix().index()]
    };
    let mut odd: Vec<Option<bool>> = vec![None; cdt.num_all_faces()];
    let mut stack = Vec::new();
    for face in cdt.inner_faces() {
        let hull_edge = face
            .adjacent_edges()
            .into_iter()
            .find(|edge| edge.rev().face().is_outer());
        if let Some(edge) = hull_edge {
            odd[face.fix().index()] = Some(flips(edge));
            stack.push(face.fix());
        }
    }
    while let Some(fixed) = stack.pop() {
        let here = odd[fixed.index()].unwrap_or(false);
        for edge in cdt.face(fixed).adjacent_edges() {
            if let Some(next) = edge.rev().face().as_inner() {
                let slot = &mut odd[next.fix().index()];
                if slot.is_none() {
                    *slot = Some(here != flips(edge));
                    stack.push(next.fix());
                }
            }
        }
    }
    cdt.inner_faces()
        .map(|face| face.fix())
        .filter(|face| odd[face.index()] == Some(true))
        .collect()
}

/// Triangulates `input`: triangles index the input's vertices (the first at a position).
pub(super) fn triangulate(input: &Input) -> Result<PeerOutput, String> {
    let constraints = Constraints::new(input);
    let cdt = constraints.triangulate()?;
    let triangles = interior_faces(&cdt, &constraints.edges)
        .into_iter()
        .map(|face| {
            cdt.face(face)
                .vertices()
                .map(|v| constraints.to_input[v.fix().index()])
        })
        .collect();
    Ok(PeerOutput {
        vertices: None,
        triangles,
    })
}
