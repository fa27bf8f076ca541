//! earcut (the georust port) and earcutr: one polygon at a time, outer ring first.

use num_traits::Float;

use super::group::{polygons, Polygon};
use super::{PeerOutput, Precision};
use crate::input::Input;

/// earcut on every polygon of `input`, triangles mapped back to input indices.
pub(super) fn earcut(input: &Input, precision: Precision) -> Result<PeerOutput, String> {
    match precision {
        Precision::F64 => Ok(earcut_in::<f64>(input, |x| x)),
        Precision::F32 => Ok(earcut_in::<f32>(input, |x| x as f32)),
    }
}

fn earcut_in<T: Float>(input: &Input, convert: impl Fn(f64) -> T) -> PeerOutput {
    let mut earcut = ::earcut::Earcut::<T>::new();
    let mut out: Vec<u32> = Vec::new();
    let mut vertices: Vec<[T; 2]> = Vec::new();
    let mut triangles = Vec::new();
    for polygon in polygons(input) {
        vertices.clear();
        vertices.extend(
            polygon
                .vertices
                .iter()
                .map(|p| [convert(p[0]), convert(p[1])]),
        );
        earcut.earcut_slice(&vertices, &polygon.hole_indices(), &mut out);
        push_mapped(&mut triangles, &polygon, out.iter().map(|&v| v as usize));
    }
    PeerOutput {
        vertices: None,
        triangles,
    }
}

/// earcutr on every polygon of `input`, triangles mapped back to input indices.
pub(super) fn earcutr(input: &Input, precision: Precision) -> Result<PeerOutput, String> {
    match precision {
        Precision::F64 => earcutr_in::<f64>(input, |x| x),
        Precision::F32 => earcutr_in::<f32>(input, |x| x as f32),
    }
}

fn earcutr_in<T: Float>(input: &Input, convert: impl Fn(f64) -> T) -> Result<PeerOutput, String> {
    let mut triangles = Vec::new();
    for polygon in polygons(input) {
        let flat: Vec<T> = polygon
            .vertices
            .iter()
            .flatten()
            .map(|&x| convert(x))
            .collect();
        let holes: Vec<usize> = polygon.ring_starts[1..].to_vec();
        let out = ::earcutr::earcut(&flat, &holes, 2).map_err(|e| format!("earcutr: {e:?}"))?;
        push_mapped(&mut triangles, &polygon, out.into_iter());
    }
    Ok(PeerOutput {
        vertices: None,
        triangles,
    })
}

/// Appends the triangles of a flat index list into `polygon`, mapped to input indices.
fn push_mapped(
    triangles: &mut Vec<[u32; 3]>,
    polygon: &Polygon,
    flat: impl Iterator<Item = usize>,
) {
    let flat: Vec<u32> = flat.map(|v| polygon.to_input[v]).collect();
    triangles.extend(flat.chunks_exact(3).map(|t| [t[0], t[1], t[2]]));
}
