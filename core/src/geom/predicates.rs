//! The one module of geometric predicates. Nobody else computes a determinant.
//!
//! Every decision that affects validity (convex or reflex, inside or outside, which side of an
//! edge, which of two ray hits is nearer) is an [`orient2d`] sign, computed exactly with
//! Shewchuk's adaptive arithmetic from the `robust` crate: a fast floating-point filter first,
//! an exact fallback only when the filter cannot decide.
//!
//! Both precisions share this path: an `f32` input is widened to `f64` when it is loaded,
//! which is exact, so the sign computed here is the exact sign for the `f32` coordinates too.
//! (Evaluating the `f32` determinant in plain `f64` is *not* always exact: differences of
//! `f32` values with far-apart exponents need more than 53 bits. The adaptive predicate is.)

/// A point as the pipeline sees it: input coordinates widened to `f64` (exactly).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Point {
    pub x: f64,
    pub y: f64,
}

impl Point {
    pub const fn new(x: f64, y: f64) -> Self {
        Point { x, y }
    }
}

/// The sign of the turn a → b → c.
///
/// **`CounterClockwise` means c lies to the left of the directed line a → b** (y up).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Orientation {
    /// c is strictly left of a → b: the turn a → b → c is counter-clockwise.
    CounterClockwise,
    /// c is strictly right of a → b: the turn a → b → c is clockwise.
    Clockwise,
    /// a, b and c lie on one line (or two of them coincide).
    Collinear,
}

impl Orientation {
    /// The orientation seen with the order of the points reversed.
    pub const fn reversed(self) -> Self {
        match self {
            Orientation::CounterClockwise => Orientation::Clockwise,
            Orientation::Clockwise => Orientation::CounterClockwise,
            Orientation::Collinear => Orientation::Collinear,
        }
    }
}

/// Exact orientation of the triangle a, b, c.
///
/// The floating-point filter is `robust`'s own (its error bound, Ozaki et al.'s form),
/// inlined at every call; only where it cannot decide does the call go to `robust`'s
/// adaptive predicate, which filters once more and then computes exactly.
#[inline(always)]
pub(crate) fn orient2d(a: Point, b: Point, c: Point) -> Orientation {
    // robust's THETA: the relative error bound of the determinant below
    const THETA: f64 = 3.330_669_062_177_372_2e-16;
    let left = (a.x - c.x) * (b.y - c.y);
    let right = (a.y - c.y) * (b.x - c.x);
    let det = left - right;
    let bound = THETA * (left + right).abs();
    if det > bound {
        Orientation::CounterClockwise
    } else if -det > bound {
        Orientation::Clockwise
    } else {
        orient2d_exact(a, b, c)
    }
}

/// Whether [`orient2d`] decides exactly on coordinates like `x`: 0, or a magnitude from
/// 2⁻⁴⁸⁰ up to (not including) 2⁵⁰⁰. A difference of two such coordinates is below 2⁵⁰¹,
/// so products of two (and robust's splitting of them) stay below `f64::MAX`; and every
/// such coordinate is a multiple of 2⁻⁵³², its last mantissa bit, so every product of two
/// differences, and every rounding error robust's expansions carry, is a multiple of
/// 2⁻¹⁰⁶⁴, which `f64` holds exactly, subnormal or not. Every `f32` value is in range. Not
/// NaN, not infinite. (Read off the exponent bits.)
#[inline(always)]
pub(crate) fn orient_exact(x: f64) -> bool {
    // the biased exponents of 2⁻⁴⁸⁰ and 2⁵⁰⁰ (the first excluded); the sign bit shifted
    // out, zero alone has no bit left
    const LOW: u64 = 1023 - 480;
    const HIGH: u64 = 1023 + 500;
    let bits = x.to_bits() << 1;
    let exponent = bits >> 53;
    (exponent.wrapping_sub(LOW) < HIGH - LOW) | (bits == 0)
}

/// The smallest nonzero coordinate magnitude [`orient_exact`] accepts: 2⁻⁴⁸⁰.
#[cfg(test)]
pub(crate) const ORIENT_MIN: f64 = 3.203_332_952_292_961_5e-145;

/// The coordinate magnitude from which [`orient_exact`] refuses: 2⁵⁰⁰.
#[cfg(test)]
pub(crate) const ORIENT_MAX: f64 = 3.273_390_607_896_142e150;

/// [`orient2d`] where the inlined filter could not decide (and for non-finite input).
#[cold]
#[inline(never)]
fn orient2d_exact(a: Point, b: Point, c: Point) -> Orientation {
    // The usual cases here are exact zeros: repeated points, and points on one horizontal
    // or vertical line (rings touching, collinear edges). A difference of two floats is
    // zero only when they are equal, so where a factor of each product is zero both
    // products, and the determinant, are exactly zero; with a = b the two products are
    // the same.
    let left_zero = a.x == c.x || b.y == c.y;
    let right_zero = a.y == c.y || b.x == c.x;
    if (left_zero && right_zero) || a == b {
        return Orientation::Collinear;
    }
    let det = robust::orient2d(
        robust::Coord { x: a.x, y: a.y },
        robust::Coord { x: b.x, y: b.y },
        robust::Coord { x: c.x, y: c.y },
    );
    if det > 0.0 {
        Orientation::CounterClockwise
    } else if det < 0.0 {
        Orientation::Clockwise
    } else {
        Orientation::Collinear
    }
}

/// True when c lies strictly left of a → b.
#[inline]
pub(crate) fn left_of(a: Point, b: Point, c: Point) -> bool {
    orient2d(a, b, c) == Orientation::CounterClockwise
}

/// True when p lies on the closed segment a–b (exact). The box first: most points
/// tested lie outside it, and comparisons cost less than a sign.
#[inline]
pub(crate) fn on_segment(a: Point, b: Point, p: Point) -> bool {
    within_box(a, b, p) && orient2d(a, b, p) == Orientation::Collinear
}

/// True when p lies in the axis-aligned box spanned by a and b (comparisons only, exact).
#[inline]
pub(crate) fn within_box(a: Point, b: Point, p: Point) -> bool {
    p.x >= least(a.x, b.x)
        && p.x <= greatest(a.x, b.x)
        && p.y >= least(a.y, b.y)
        && p.y <= greatest(a.y, b.y)
}

/// The lesser of two numbers, neither NaN: a plain comparison, without `f64::min`'s NaN
/// handling (coordinates are finite once loaded).
#[inline(always)]
pub(crate) fn least(a: f64, b: f64) -> f64 {
    if b < a {
        b
    } else {
        a
    }
}

/// The greater of two numbers, neither NaN (see [`least`]).
#[inline(always)]
pub(crate) fn greatest(a: f64, b: f64) -> f64 {
    if b > a {
        b
    } else {
        a
    }
}

/// Compares the directions `o → p` and `o → q` by angle, counter-clockwise from the
/// positive x axis (`p`, `q` ≠ `o`). `Equal` means the same direction. Exact. (A point at
/// `o`, which has no direction, comes before every other, so that sorting by this order
/// never meets an inconsistent comparison, whatever a caller's bug hands it.)
pub(crate) fn cmp_around(o: Point, p: Point, q: Point) -> core::cmp::Ordering {
    // the half-plane [0, π) before [π, 2π), then the turn between them
    let lower = |d: Point| d.y < o.y || (d.y == o.y && d.x < o.x);
    match (lower(p), lower(q)) {
        (false, true) => core::cmp::Ordering::Less,
        (true, false) => core::cmp::Ordering::Greater,
        _ => match orient2d(o, p, q) {
            Orientation::CounterClockwise => core::cmp::Ordering::Less,
            Orientation::Clockwise => core::cmp::Ordering::Greater,
            // one direction, or a point at o (in the upper half-plane by `lower`)
            Orientation::Collinear => (q == o).cmp(&(p == o)),
        },
    }
}

/// Lexicographic order of points: by x, then by y. Exact.
#[inline]
pub(crate) fn cmp_xy(a: Point, b: Point) -> core::cmp::Ordering {
    a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y))
}

/// A number that grows with the interior angle at b of the left turn a → b → c (0 to π),
/// from 0 to 2, for ranking ears: a pseudo-angle, `1 − cos θ / (|sin θ| + |cos θ|)` up to
/// the common length factor, which orders angles as they are ordered but needs no `atan2`
/// or square root. **Not exact**: it only ranks ears for the quality strategy and never
/// decides validity.
#[inline]
pub(crate) fn approx_angle_rank(a: Point, b: Point, c: Point) -> f64 {
    let (ux, uy) = (a.x - b.x, a.y - b.y);
    let (vx, vy) = (c.x - b.x, c.y - b.y);
    // the angle swept counter-clockwise from b→c to b→a: sin from the cross product,
    // cos from the dot product
    let cross = vx * uy - vy * ux;
    let dot = vx * ux + vy * uy;
    let norm = cross.abs() + dot.abs();
    if norm > 0.0 {
        1.0 - dot / norm
    } else {
        // vanishing sides (underflow): rank last
        2.0
    }
}

/// Twice the signed area of triangle a, b, c in floating point. **Not exact**: lenient mode
/// uses it to measure how well a result covers input with crossing edges.
#[inline]
pub(crate) fn approx_double_area(a: Point, b: Point, c: Point) -> f64 {
    (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
}

/// The cross product a × b in floating point, a term of the shoelace formula. **Not
/// exact**: lenient mode sums it to guess the winding of rings with crossing edges, where no
/// exact answer exists anyway.
#[inline]
pub(crate) fn approx_cross(a: Point, b: Point) -> f64 {
    a.x * b.y - a.y * b.x
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Directions round a point, with the point itself among them (no direction): every
    /// pair compares consistently, so a sort by this order cannot panic, and the point
    /// comes first.
    #[test]
    fn directions_round_a_point_are_totally_ordered_even_with_the_point_among_them() {
        let o = Point::new(0.0, 0.0);
        let mut points = vec![
            Point::new(1.0, 0.0),
            Point::new(-0.0, -0.0),
            Point::new(0.0, 1.0),
            Point::new(-1.0, 0.0),
            Point::new(0.0, 0.0),
            Point::new(0.0, -1.0),
            Point::new(2.0, 0.0),
            Point::new(1.0, -1.0),
        ];
        for &a in &points {
            for &b in &points {
                assert_eq!(
                    cmp_around(o, a, b),
                    cmp_around(o, b, a).reverse(),
                    "{a:?} {b:?}"
                );
                for &c in &points {
                    let (ab, bc) = (cmp_around(o, a, b), cmp_around(o, b, c));
                    if ab != core::cmp::Ordering::Greater && bc != core::cmp::Ordering::Greater {
                        assert_ne!(cmp_around(o, a, c), core::cmp::Ordering::Greater);
                    }
                }
            }
        }
        points.sort_by(|&a, &b| cmp_around(o, a, b));
        assert!(points[..2].iter().all(|&p| p == o));
        assert_eq!(points[2..4], [Point::new(1.0, 0.0), Point::new(2.0, 0.0)]);
        assert_eq!(points[7], Point::new(1.0, -1.0));
    }

    #[test]
    fn the_exact_range_of_orient2d_is_powers_of_two() {
        assert_eq!(ORIENT_MIN, 2f64.powi(-480));
        assert_eq!(ORIENT_MAX, 2f64.powi(500));
        let below_max = ORIENT_MAX * (1.0 - f64::EPSILON / 2.0);
        assert!(orient_exact(0.0) && orient_exact(-0.0) && orient_exact(below_max));
        assert!(orient_exact(-ORIENT_MIN) && orient_exact(f64::from(f32::MAX)));
        assert!(orient_exact(f64::from(f32::from_bits(1)))); // the least f32
        assert!(orient_exact(1.0) && orient_exact(-3.5e7) && orient_exact(1e-100));
        let bad = [f64::NAN, f64::INFINITY, -f64::INFINITY, 1e200, -1e-200];
        let more = [
            f64::MIN_POSITIVE,
            ORIENT_MAX,
            -ORIENT_MAX,
            f64::from_bits(1),
        ];
        for x in bad.into_iter().chain(more) {
            assert!(!orient_exact(x), "{x}");
        }
        assert!(!orient_exact(ORIENT_MIN * (1.0 - f64::EPSILON / 2.0)));
    }

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn orientation_signs() {
        assert_eq!(
            orient2d(p(0., 0.), p(1., 0.), p(0., 1.)),
            Orientation::CounterClockwise
        );
        assert_eq!(
            orient2d(p(0., 0.), p(0., 1.), p(1., 0.)),
            Orientation::Clockwise
        );
        assert_eq!(
            orient2d(p(0., 0.), p(1., 1.), p(2., 2.)),
            Orientation::Collinear
        );
    }

    /// Points on a small grid, scaled from subnormal to huge, make every kind of exact
    /// zero the fallback's shortcut takes (repeated points, horizontal and vertical
    /// lines) and many it must not (one product zero, the other not): the sign is always
    /// robust's.
    #[test]
    fn degenerate_triples_take_robust_signs() {
        let mut pick = crate::testing::random(0x0de9_e4e7);
        for scale in [f64::MIN_POSITIVE * 1e-10, 1e-300, 1.0, 3.0, 1e100, 1e150] {
            for _ in 0..3000 {
                let mut q = || {
                    let v = |pick: &mut dyn FnMut(u64) -> u64| (pick(5) as f64 - 2.0) * scale;
                    p(v(&mut pick), v(&mut pick))
                };
                let (a, b, c) = (q(), q(), q());
                let want = robust::orient2d(
                    robust::Coord { x: a.x, y: a.y },
                    robust::Coord { x: b.x, y: b.y },
                    robust::Coord { x: c.x, y: c.y },
                );
                let want = if want > 0.0 {
                    Orientation::CounterClockwise
                } else if want < 0.0 {
                    Orientation::Clockwise
                } else {
                    Orientation::Collinear
                };
                assert_eq!(orient2d(a, b, c), want, "{a:?} {b:?} {c:?}");
                assert_eq!(orient2d_exact(a, b, c), want, "{a:?} {b:?} {c:?}");
            }
        }
    }

    #[test]
    fn exact_where_naive_floating_point_fails() {
        // Classic near-collinear configuration: the naive determinant gets the sign wrong
        // for some of these offsets; the exact predicate must say collinear for the points
        // that are exactly on the line y = x and never flip for the others.
        let a = p(12.0, 12.0);
        let b = p(24.0, 24.0);
        for i in 0..256 {
            let x = 0.5 + f64::EPSILON * i as f64;
            let c = p(x, x);
            assert_eq!(orient2d(a, b, c), Orientation::Collinear);
            let above = p(x, f64::from_bits(x.to_bits() + 1));
            assert_eq!(orient2d(a, b, above), Orientation::CounterClockwise);
        }
    }

    #[test]
    fn f32_inputs_widened_are_exact() {
        // f32 points far apart in exponent: the naive f64 determinant loses bits here.
        let a = p(1.0e30_f32 as f64, 1.0e-30_f32 as f64);
        let b = p(-(1.0e30_f32 as f64), -(1.0e-30_f32 as f64));
        let c = p(0.0, 0.0);
        assert_eq!(orient2d(a, b, c), Orientation::Collinear);
    }

    #[test]
    fn reversed_flips() {
        let o = orient2d(p(0., 0.), p(1., 0.), p(0., 1.));
        assert_eq!(o.reversed(), orient2d(p(0., 0.), p(0., 1.), p(1., 0.)));
    }

    #[test]
    fn angle_rank_orders_like_the_angle() {
        // a left turn with interior angle t at the origin, for t from 1° to 179°
        let at = |t: f64| approx_angle_rank(p(t.cos(), t.sin()), p(0., 0.), p(1., 0.));
        let mut last = -1.0;
        for deg in 1..180 {
            let rank = at(f64::from(deg).to_radians());
            assert!(rank > last, "{deg}°: {rank} after {last}");
            assert!((0.0..=2.0).contains(&rank), "{deg}°: {rank}");
            last = rank;
        }
        assert!((at(core::f64::consts::FRAC_PI_2) - 1.0).abs() < 1e-12);
        // the length of the sides does not matter
        let long = approx_angle_rank(p(0., 7.), p(0., 0.), p(3., 3.));
        let short = approx_angle_rank(p(0., 0.5), p(0., 0.), p(1., 1.));
        assert!((long - short).abs() < 1e-12);
    }
}
