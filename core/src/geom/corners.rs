//! Exact tests on corners and rays at a vertex: whether a direction leaves a vertex into
//! the corner between two edges, and whether points lie on one ray from it.

use super::predicates::{orient2d, Orientation, Point};

/// Whether the direction from `o` to `q` lies inside the corner at `o` swept
/// counter-clockwise from `o → a` to `o → b`: `Some(true)` strictly inside, `Some(false)`
/// strictly outside, `None` along one of its two sides.
#[inline]
pub(crate) fn corner_contains(o: Point, a: Point, b: Point, q: Point) -> Option<bool> {
    let qa = orient2d(o, a, q);
    let qb = orient2d(o, b, q);
    if (qa == Orientation::Collinear && same_ray(o, a, q))
        || (qb == Orientation::Collinear && same_ray(o, b, q))
    {
        return None;
    }
    let inside = match orient2d(o, a, b) {
        // convex corner: left of o→a and right of o→b
        Orientation::CounterClockwise => {
            qa == Orientation::CounterClockwise && qb == Orientation::Clockwise
        }
        // reflex corner: the complement of the convex corner from o→b to o→a
        Orientation::Clockwise => {
            qa == Orientation::CounterClockwise || qb == Orientation::Clockwise
        }
        // straight corner (a, o, b on a line, opposite rays): the left half-plane of o→a;
        // a zero-width corner (same ray) contains nothing
        Orientation::Collinear => !same_ray(o, a, b) && qa == Orientation::CounterClockwise,
    };
    Some(inside)
}

/// Whether `q` lies on the ray from `o` through `a` (`a`, `q` ≠ `o`). Exact.
pub(crate) fn on_ray(o: Point, a: Point, q: Point) -> bool {
    orient2d(o, a, q) == Orientation::Collinear && same_ray(o, a, q)
}

/// For points known to be collinear with `o`: whether `a` and `q` lie on the same ray from
/// `o` (exact: coordinate comparisons only).
pub(crate) fn same_ray(o: Point, a: Point, q: Point) -> bool {
    let sx = |p: Point| p.x.partial_cmp(&o.x);
    let sy = |p: Point| p.y.partial_cmp(&o.y);
    sx(a) == sx(q) && sy(a) == sy(q) && (a != o) && (q != o)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn corner_tests() {
        let o = p(0., 0.);
        // convex corner from +x to +y
        assert_eq!(
            corner_contains(o, p(1., 0.), p(0., 1.), p(1., 1.)),
            Some(true)
        );
        assert_eq!(
            corner_contains(o, p(1., 0.), p(0., 1.), p(-1., -1.)),
            Some(false)
        );
        assert_eq!(corner_contains(o, p(1., 0.), p(0., 1.), p(2., 0.)), None);
        // reflex corner from +y to +x (270°)
        assert_eq!(
            corner_contains(o, p(0., 1.), p(1., 0.), p(-1., -1.)),
            Some(true)
        );
        assert_eq!(
            corner_contains(o, p(0., 1.), p(1., 0.), p(1., 1.)),
            Some(false)
        );
        assert_eq!(
            corner_contains(o, p(0., 1.), p(1., 0.), p(-1., 0.)),
            Some(true)
        );
        assert_eq!(
            corner_contains(o, p(0., 1.), p(1., 0.), p(0., -1.)),
            Some(true)
        );
        // straight corner from +x to -x: the upper half-plane
        assert_eq!(
            corner_contains(o, p(1., 0.), p(-1., 0.), p(0., 1.)),
            Some(true)
        );
        assert_eq!(
            corner_contains(o, p(1., 0.), p(-1., 0.), p(0., -1.)),
            Some(false)
        );
    }
}
