//! Two small generators with one knob: a feature size `d` relative to the polygon.
//!
//! The families of [`generate`](crate::gen::generate) live on an integer grid and stay
//! exact under power-of-two scaling; these do not. Their coordinates come from `sin` and
//! `cos`, so every edge is slanted and no two points share a grid line: rounding to `f32`
//! moves each vertex its own way, and once the move is comparable to `d` the polygon can
//! stop being simple. That is the point — they find where rounding breaks an input.
//!
//! Both draw a unit-sized polygon around `(0.5, 0.5)`, rotated by an angle taken from the
//! seed; [`place`] maps it to case coordinates.

use std::f64::consts::PI;

/// Corners of the gap family's rings.
const GAP_CORNERS: usize = 16;
/// Points on each long side of the spike (besides its base and tip).
const SPIKE_STEPS: usize = 6;

/// The seed's rotation angle in `[0, 2π)`, spread by the golden ratio so that nearby seeds
/// give unrelated angles.
fn rotation(seed: u64) -> f64 {
    let golden = 0.618_033_988_749_895;
    ((seed as f64 + 1.0) * golden).fract() * 2.0 * PI
}

/// Rotates `p` by `angle` about the origin and moves it to the unit square's centre.
fn turn(p: [f64; 2], angle: f64) -> [f64; 2] {
    let (s, c) = angle.sin_cos();
    [0.5 + c * p[0] - s * p[1], 0.5 + s * p[0] + c * p[1]]
}

/// A regular 16-gon of radius ½ with a 16-gon hole turned by half a step, so that each
/// hole corner points at the middle of an outer edge and comes within `d` of it.
pub(super) fn gap(seed: u64, d: f64) -> Vec<Vec<[f64; 2]>> {
    let k = GAP_CORNERS as f64;
    let theta = rotation(seed);
    let radius = 0.5;
    let apothem = radius * (PI / k).cos();
    let inner = (apothem - d).max(apothem / 2.0);
    let ring = |r: f64, start: f64| -> Vec<[f64; 2]> {
        (0..GAP_CORNERS)
            .map(|i| {
                let a = start + 2.0 * PI * i as f64 / k;
                turn([r * a.cos(), r * a.sin()], 0.0)
            })
            .collect()
    };
    vec![ring(radius, theta), ring(inner, theta + PI / k)]
}

/// A square of side 0.6 with a spike of base width `d` and length 0.4 on one side, its
/// long sides cut into near-collinear chains: triangles inside the spike are slivers.
pub(super) fn spike(seed: u64, d: f64) -> Vec<Vec<[f64; 2]>> {
    let theta = rotation(seed);
    let half = 0.5 * d.min(0.5);
    let steps = SPIKE_STEPS + 1;
    let along = |t: f64, side: f64| [0.3 + 0.4 * t, side * half * (1.0 - t)];
    let mut ring = vec![[-0.3, -0.3], [0.3, -0.3]];
    ring.extend((0..steps).map(|i| along(i as f64 / steps as f64, -1.0)));
    ring.push([0.7, 0.0]);
    ring.extend(
        (0..steps)
            .rev()
            .map(|i| along(i as f64 / steps as f64, 1.0)),
    );
    ring.extend([[0.3, 0.3], [-0.3, 0.3]]);
    vec![ring.into_iter().map(|p| turn(p, theta)).collect()]
}

/// Maps unit-sized rings to case coordinates: `p · scale + offset` on both axes, rounded
/// once in `f64` — what a user's own data would hold.
pub(super) fn place(rings: Vec<Vec<[f64; 2]>>, scale: f64, offset: f64) -> Vec<Vec<[f64; 2]>> {
    rings
        .into_iter()
        .map(|ring| {
            ring.into_iter()
                .map(|[x, y]| [x * scale + offset, y * scale + offset])
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::region::Region;
    use crate::input::{Input, Nesting};

    fn valid(rings: Vec<Vec<[f64; 2]>>) -> bool {
        Region::build(&Input::from_rings(&rings, Nesting::Auto))
            .problems
            .is_empty()
    }

    #[test]
    fn features_are_valid_where_f64_resolves_them() {
        for seed in 0..4 {
            for d in [1e-1, 1e-4, 1e-9] {
                assert!(valid(gap(seed, d)), "gap {seed} {d}");
                assert!(valid(spike(seed, d)), "spike {seed} {d}");
                assert!(valid(place(gap(seed, d), 1024.0, 1e3)), "gap {seed} {d}");
            }
        }
    }

    #[test]
    fn gap_hole_comes_within_d_of_the_outer_ring() {
        let rings = gap(3, 1e-3);
        let r_outer = (rings[0][0][0] - 0.5).hypot(rings[0][0][1] - 0.5);
        let r_inner = (rings[1][0][0] - 0.5).hypot(rings[1][0][1] - 0.5);
        let apothem = r_outer * (PI / GAP_CORNERS as f64).cos();
        assert!((apothem - r_inner - 1e-3).abs() < 1e-12);
    }
}
