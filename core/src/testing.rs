//! Helpers of the unit tests.

/// A seeded xorshift generator: each call gives a number below its argument (not zero).
pub(crate) fn random(seed: u64) -> impl FnMut(u64) -> u64 {
    let mut state = seed;
    move |n: u64| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state % n
    }
}

/// The same generator's numbers as `f64` in [0, 1): its top 53 bits.
pub(crate) fn unit_random(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

use crate::context::Context;
use crate::triangulator::pipeline::{self, Stages};

/// Runs `load` and `clean` (and `lobes` when lenient) on `vertices` and `ring_starts`:
/// the context a stage after them starts from, and the stages' scratch.
pub(crate) fn cleaned(vertices: &[[f64; 2]], starts: &[usize], lenient: bool) -> (Context, Stages) {
    let mut cx = Context::default();
    cx.reset(lenient);
    let mut st = Stages::default();
    let ok = pipeline::load_and_clean(&mut cx, &mut st, vertices, starts, false);
    assert!(matches!(ok, Ok(true)), "load and clean: {ok:?}");
    (cx, st)
}

/// As [`cleaned`], then `nest` by containment (`Nesting::Auto`).
pub(crate) fn nested(vertices: &[[f64; 2]], starts: &[usize], lenient: bool) -> (Context, Stages) {
    let (mut cx, mut st) = cleaned(vertices, starts, lenient);
    let ok = crate::stages::nest::nest(&mut cx, &mut st.nest, crate::Nesting::Auto);
    assert!(ok.is_ok(), "nest: {ok:?}");
    (cx, st)
}

/// Rings as one vertex list and the ring starts into it.
pub(crate) fn flatten(rings: &[&[[f64; 2]]]) -> (Vec<[f64; 2]>, Vec<usize>) {
    let mut vertices = Vec::new();
    let mut starts = Vec::new();
    for ring in rings {
        starts.push(vertices.len());
        vertices.extend_from_slice(ring);
    }
    (vertices, starts)
}

/// The turn of `ring` at its rightmost vertex: its winding, once `clean` oriented it.
pub(crate) fn turn_at_rightmost(
    cx: &Context,
    ring: &crate::context::Ring,
) -> crate::geom::Orientation {
    let n = ring.rightmost;
    let (a, b, c) = (
        cx.pool.p(cx.pool.prev(n)),
        cx.pool.p(n),
        cx.pool.p(cx.pool.next(n)),
    );
    crate::geom::orient2d(a, b, c)
}
