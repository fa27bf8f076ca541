//! lyon_tessellation's fill tessellator: every ring at once, even-odd fill rule (nonzero
//! on request), `f32`.

use lyon_tessellation::geometry_builder::{FillGeometryBuilder, GeometryBuilder};
use lyon_tessellation::math::point;
use lyon_tessellation::path::Path;
use lyon_tessellation::{
    FillOptions, FillRule, FillTessellator, FillVertex, GeometryBuilderError, VertexId,
    VertexSource,
};

use super::PeerOutput;
use crate::input::Input;

/// The options the peer runs with: even–odd, or nonzero. Tolerance only matters for
/// curves; polygons have none.
pub(super) fn options(nonzero: bool) -> FillOptions {
    let rule = if nonzero {
        FillRule::NonZero
    } else {
        FillRule::EvenOdd
    };
    FillOptions::non_zero().with_fill_rule(rule)
}

/// `input` as a lyon path (every ring closed), and for each endpoint id the input vertex.
pub(super) fn path(input: &Input) -> (Path, Vec<u32>) {
    let mut builder = Path::builder();
    let mut to_input = Vec::with_capacity(input.vertices.len());
    let mut note = |id: lyon_tessellation::path::EndpointId, v: usize| {
        let id = id.to_usize();
        if to_input.len() <= id {
            to_input.resize(id + 1, u32::MAX);
        }
        to_input[id] = v as u32;
    };
    for r in 0..input.ring_count() {
        let range = input.ring_range(r);
        let mut vertices = range.clone().map(|v| (v, input.vertices[v]));
        let Some((v, [x, y])) = vertices.next() else {
            continue;
        };
        note(builder.begin(point(x as f32, y as f32)), v);
        for (v, [x, y]) in vertices {
            note(builder.line_to(point(x as f32, y as f32)), v);
        }
        builder.end(true);
    }
    (builder.build(), to_input)
}

/// Triangulates `input`; vertices that lyon made at crossings have no input vertex, and
/// then the output keeps lyon's own vertex list.
pub(super) fn triangulate(input: &Input, nonzero: bool) -> Result<PeerOutput, String> {
    let (path, to_input) = path(input);
    let mut collect = Collect::default();
    // with ids, so every vertex can say which path endpoints it sits on
    FillTessellator::new()
        .tessellate_with_ids(path.id_iter(), &path, None, &options(nonzero), &mut collect)
        .map_err(|e| format!("lyon: {e:?}"))?;
    let mapped: Option<Vec<u32>> = collect
        .sources
        .iter()
        .map(|s| s.and_then(|id| to_input.get(id as usize).copied()))
        .map(|v| v.filter(|&v| v != u32::MAX))
        .collect();
    Ok(match mapped {
        Some(map) => PeerOutput {
            vertices: None,
            triangles: collect
                .triangles
                .iter()
                .map(|t| t.map(|v| map[v as usize]))
                .collect(),
        },
        None => PeerOutput {
            vertices: Some(collect.positions),
            triangles: collect.triangles,
        },
    })
}

/// Collects lyon's output: positions, the path endpoint each vertex sits on, triangles.
#[derive(Default)]
struct Collect {
    positions: Vec<[f64; 2]>,
    sources: Vec<Option<u32>>,
    triangles: Vec<[u32; 3]>,
}

impl GeometryBuilder for Collect {
    fn add_triangle(&mut self, a: VertexId, b: VertexId, c: VertexId) {
        self.triangles.push([a.0, b.0, c.0]);
    }

    fn abort_geometry(&mut self) {
        self.positions.clear();
        self.sources.clear();
        self.triangles.clear();
    }
}

impl FillGeometryBuilder for Collect {
    fn add_fill_vertex(&mut self, vertex: FillVertex) -> Result<VertexId, GeometryBuilderError> {
        let id = u32::try_from(self.positions.len())
            .map_err(|_| GeometryBuilderError::TooManyVertices)?;
        let p = vertex.position();
        self.positions.push([f64::from(p.x), f64::from(p.y)]);
        self.sources
            .push(vertex.sources().find_map(|source| match source {
                VertexSource::Endpoint { id } => Some(id.0),
                VertexSource::Edge { .. } => None,
            }));
        Ok(VertexId(id))
    }
}
