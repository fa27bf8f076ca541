//! earcut (the georust port), its vendored copies (exact predicates, and earcut's own) and
//! earcutr: one polygon at a time, outer ring first.

use num_traits::Float;

use super::earcut_exact::{exact, vendored};
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
    let mut vertices: Vec<[T; 2]> = Vec::new();
    each_polygon(input, |polygon, out| {
        vertices.clear();
        vertices.extend(
            polygon
                .vertices
                .iter()
                .map(|p| [convert(p[0]), convert(p[1])]),
        );
        earcut.earcut_slice(&vertices, &polygon.hole_indices(), out);
    })
}

/// earcut with exact predicates on every polygon of `input`, in `f64` (an `f32` input's
/// coordinates widened exactly), triangles mapped back to input indices.
pub(super) fn earcut_exact(input: &Input) -> PeerOutput {
    let mut earcut = exact::Earcut::new();
    each_polygon(input, |p, out| {
        earcut.earcut_slice(&p.vertices, &p.hole_indices(), out)
    })
}

/// earcut-exact's baseline, the same copy with earcut's own predicates, as
/// [`earcut_exact`].
pub(super) fn earcut_vendored(input: &Input) -> PeerOutput {
    let mut earcut = vendored::Earcut::new();
    each_polygon(input, |p, out| {
        earcut.earcut_slice(&p.vertices, &p.hole_indices(), out)
    })
}

/// Runs `triangulate` (a polygon; it writes earcut's flat index list) on every polygon of
/// `input`, and gathers the triangles mapped back to input indices.
fn each_polygon(input: &Input, mut triangulate: impl FnMut(&Polygon, &mut Vec<u32>)) -> PeerOutput {
    let mut out: Vec<u32> = Vec::new();
    let mut triangles = Vec::new();
    for polygon in polygons(input) {
        triangulate(&polygon, &mut out);
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
