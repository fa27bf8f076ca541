//! Stage `seidel` (`Strategy::Seidel`): Seidel's randomized incremental trapezoidation of
//! valid rings, monotone pieces, and their linear-time triangulation.

use crate::Error;

/// The stage's buffers.
#[derive(Debug, Default)]
pub(crate) struct Scratch {}

/// Triangulates the even–odd region of `rings` (see the module documentation): `points`
/// are distinct positions; ring `k` is `ring_ids[ring_starts[k]..ring_starts[k + 1]]`
/// (the last to the end), indices into `points`. Triangles (counter-clockwise, indices
/// into `points`) are appended to `out`.
pub(crate) fn triangulate(
    _s: &mut Scratch,
    _points: &[[f64; 2]],
    _ring_starts: &[usize],
    _ring_ids: &[u32],
    _seed: u64,
    _out: &mut Vec<[u32; 3]>,
) -> Result<(), Error> {
    Err(Error::Internal { stage: "seidel" })
}
