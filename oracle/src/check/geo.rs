//! `geo`'s second opinion: the polygon's area and the triangles' containment computed by
//! an independent library, in floating point.

use geo::coordinate_position::{CoordPos, CoordinatePosition};
use geo::{Area, BoundingRect, Coord, LineString, Point, Polygon, Rect, Triangle};

use super::region::Region;
use super::{Check, Failures};
use crate::exact::Probe;
use crate::input::{Input, Role};

/// Centroid-in-ring tests cost the ring's length each; beyond this many edge visits the
/// containment check samples triangles evenly instead of testing all (and says so).
const CONTAINMENT_BUDGET: usize = 20_000_000;

/// geo's view of the input: every ring as a polygon of its own, with its role's sign.
pub(crate) struct GeoRings {
    rings: Vec<(Polygon<f64>, Option<Rect<f64>>, f64)>,
}

impl GeoRings {
    pub(crate) fn new(input: &Input, region: &Region) -> GeoRings {
        let rings = input
            .rings()
            .into_iter()
            .zip(&region.roles)
            .map(|(ring, &role)| {
                let line = LineString::from(
                    ring.iter()
                        .map(|&[x, y]| Coord { x, y })
                        .collect::<Vec<_>>(),
                );
                let polygon = Polygon::new(line, vec![]);
                let bbox = polygon.bounding_rect();
                (polygon, bbox, if role == Role::Outer { 1.0 } else { -1.0 })
            })
            .collect();
        GeoRings { rings }
    }

    /// The polygon's area: outer rings' areas minus holes' (as earcut measures it).
    pub(crate) fn area(&self) -> f64 {
        self.rings
            .iter()
            .map(|(p, _, s)| s * p.unsigned_area())
            .sum()
    }

    /// How many rings contain `p`, outer rings counting +1 and holes −1; `None` when `p`
    /// lies on a ring (geo cannot say which side then; the exact check decides).
    fn depth(&self, p: Point<f64>) -> Option<i64> {
        let mut depth = 0;
        for (poly, bbox, s) in &self.rings {
            if !bbox.is_some_and(|b| b.holds(p)) {
                continue;
            }
            match poly.coordinate_position(&p.0) {
                CoordPos::Inside => depth += *s as i64,
                CoordPos::OnBoundary => return None,
                CoordPos::Outside => {}
            }
        }
        Some(depth)
    }

    fn ring_lengths(&self) -> usize {
        self.rings
            .iter()
            .map(|(p, _, _)| p.exterior().0.len())
            .max()
            .unwrap_or(0)
    }
}

/// A cheap bounding-box filter before geo's test.
trait Holds {
    fn holds(&self, p: Point<f64>) -> bool;
}

impl Holds for Rect<f64> {
    fn holds(&self, p: Point<f64>) -> bool {
        let (min, max) = (self.min(), self.max());
        min.x <= p.x() && p.x() <= max.x && min.y <= p.y() && p.y() <= max.y
    }
}

/// The triangles' areas, by geo.
pub(crate) fn triangle_area(pts: &[[f64; 2]], tris: &[(usize, [u32; 3])]) -> f64 {
    let c = |i: u32| {
        let [x, y] = pts[i as usize];
        Coord { x, y }
    };
    tris.iter()
        .map(|&(_, [a, b, d])| Triangle::new(c(a), c(b), c(d)).unsigned_area())
        .sum()
}

/// The deviation is within floating-point noise: relative 1e-9, plus what rounding the
/// shoelace terms of coordinates of magnitude `scale` can do.
pub(crate) fn area_check(polygon: f64, triangles: f64, terms: usize, scale: f64) -> Check {
    let mut fails = Failures::default();
    let noise = 1e-9 * polygon.abs() + 16.0 * f64::EPSILON * terms as f64 * scale * scale;
    if (polygon - triangles).abs() > noise {
        fails.note(|| {
            format!("geo: the polygon's area is {polygon:e}, the triangles' {triangles:e}")
        });
    }
    fails.check("geo-area")
}

/// Every triangle's centroid lies inside the polygon by geo's point-in-polygon test.
///
/// geo reads each ring by the even–odd rule, which for a ring winding twice round a point
/// (valid where another ring cancels a turn) says "outside". Where geo's depth is not 1,
/// the exact winding numbers of the rings at the centroid say whether that is the case;
/// such triangles are skipped and counted, not failed.
pub(crate) fn containment(
    rings: &GeoRings,
    region: &Region,
    pts: &[[f64; 2]],
    tris: &[(usize, [u32; 3])],
) -> Check {
    let mut fails = Failures::default();
    let mut stamps = None;
    let mut twice = 0;
    let cost = tris.len().saturating_mul(rings.ring_lengths().max(1));
    let stride = cost.div_ceil(CONTAINMENT_BUDGET).max(1);
    let (mut slivers, mut on_rings) = (0, 0);
    for &(k, [a, b, c]) in tris.iter().step_by(stride) {
        let (p, q, r) = (pts[a as usize], pts[b as usize], pts[c as usize]);
        if is_sliver(p, q, r) {
            slivers += 1;
            continue;
        }
        let centroid = Point::new((p[0] + q[0] + r[0]) / 3.0, (p[1] + q[1] + r[1]) / 3.0);
        let Some(depth) = rings.depth(centroid) else {
            on_rings += 1;
            continue;
        };
        if depth != 1 {
            let stamps = stamps.get_or_insert_with(|| region.stamps());
            let probe = Probe::centroid(p, q, r);
            let windings = region.windings_by_ring(&probe, stamps);
            if windings.values().any(|w| w.is_some_and(|w| w.abs() >= 2)) {
                twice += 1;
                continue;
            }
            fails.note(|| format!("geo: the centroid of triangle {k} ({a}, {b}, {c}) is not inside the polygon (depth {depth})"));
        }
    }
    let mut check = fails.check("geo-containment");
    if check.passed && (stride > 1 || slivers > 0 || on_rings > 0 || twice > 0) {
        check.detail = Some(format!(
            "tested every {stride}th triangle, skipped {slivers} too thin for floating point, {on_rings} with the centroid on a ring and {twice} where a ring winds twice round it"
        ));
    }
    check
}

/// Thinner than floating point can test: the rounded centroid may fall outside. Twice
/// the area below 1e-9 of the longest edge squared means a height under 1e-9 of its base.
fn is_sliver(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    let d2 = |p: [f64; 2], q: [f64; 2]| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2);
    let longest = d2(a, b).max(d2(b, c)).max(d2(c, a));
    let twice_area = ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs();
    twice_area <= 1e-9 * longest
}
