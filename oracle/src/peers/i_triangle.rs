//! i_triangle: every ring at once, even-odd fill rule (nonzero on request), on its
//! integer grid.

use i_triangle::float::triangulation::Triangulation;
use i_triangle::float::triangulator::Triangulator;
use i_triangle::i_overlay::core::fill_rule::FillRule;
use i_triangle::i_overlay::core::solver::Solver;
use i_triangle::int::validation::Validation;

use super::{extent, snap_to_input, PeerOutput, Precision};
use crate::input::Input;

/// The triangulator the peer is run with: `u32` indices, `i32` grid (its default),
/// even-odd or nonzero.
pub(super) fn triangulator(capacity: usize, nonzero: bool) -> Triangulator<u32, i32> {
    let rule = if nonzero {
        FillRule::NonZero
    } else {
        FillRule::EvenOdd
    };
    Triangulator::new(
        capacity,
        Validation::with_fill_rule(rule),
        Solver::default(),
    )
}

/// Triangulates `input`; its points come back from the integer grid, so they are matched
/// to the input's within the grid's resolution, and kept as the peer's own where some
/// point has no match (crossings it resolved).
pub(super) fn triangulate(
    input: &Input,
    precision: Precision,
    nonzero: bool,
) -> Result<PeerOutput, String> {
    let rings = input.rings();
    let mut tri = triangulator(input.vertices.len(), nonzero);
    let (points, indices): (Vec<[f64; 2]>, Vec<u32>) = match precision {
        Precision::F64 => {
            let mut out = Triangulation::<[f64; 2], u32>::with_capacity(input.vertices.len());
            tri.triangulate_into(&rings, &mut out);
            (out.points, out.indices)
        }
        Precision::F32 => {
            let rings: Vec<Vec<[f32; 2]>> = rings
                .iter()
                .map(|ring| ring.iter().map(|&[x, y]| [x as f32, y as f32]).collect())
                .collect();
            let mut out = Triangulation::<[f32; 2], u32>::with_capacity(input.vertices.len());
            tri.triangulate_into(&rings, &mut out);
            let points = out
                .points
                .iter()
                .map(|&[x, y]| [f64::from(x), f64::from(y)])
                .collect();
            (points, out.indices)
        }
    };
    // A 32-bit grid over the input's extent: 2^-24 of it is far above the round-off of the
    // grid and far below any two distinct vertices of a sensible input.
    let tolerance = extent(&input.vertices) * (-24f64).exp2();
    let triangles = indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]);
    Ok(match snap_to_input(&points, &input.vertices, tolerance) {
        Some(to_input) => PeerOutput {
            vertices: None,
            triangles: triangles.map(|t| t.map(|v| to_input[v as usize])).collect(),
        },
        None => PeerOutput {
            vertices: Some(points),
            triangles: triangles.collect(),
        },
    })
}
