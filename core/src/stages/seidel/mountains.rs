//! From the finished trapezoidal map to triangles: every segment with the trapezoids on
//! its inner side makes one monotone mountain, triangulated in linear time.
//!
//! A trapezoid between `lseg` and `rseg` is inside exactly when `rseg` runs upward (the
//! region lies left of every edge, and the trapezoid lies left of `rseg`); then `lseg`
//! runs downward, which is checked. Its diagonal from its top point to its bottom point
//! cuts it in two (one part empty when both points are ends of one of its segments). The
//! parts beside a segment `s`, stacked from its upper end to its lower end, form a polygon
//! bounded by `s` and by the chain of those diagonals: its vertices, the tops and bottoms
//! of the stacked trapezoids, are strictly monotone in the sheared order, and every one
//! but the ends lies strictly on the inner side of `s` (on the line through `s` and between
//! its ends it would lie on `s`). That is a monotone mountain with base `s` (Fournier &
//! Montuno; Seidel): every strictly convex chain vertex is an ear, since the other vertices
//! lie above or below the ear's height range. One pass with a stack clips them: a vertex
//! is pushed, and while the three on top turn the right way the middle one is cut off.
//! Vertices on straight angles are never cut, so no triangle is flat; a mountain with
//! positive area always has a convex vertex left, so the stack ends with the base alone.

use super::map::{point, Map, Seg, Trap, BROKEN, NONE};
use crate::geom::{orient2d, Orientation, Point};
use crate::Error;

/// Triangulates the inside of `map` (finished) into `out`: counter-clockwise triangles of
/// point indices. `stack` is scratch.
pub(super) fn triangulate(
    map: &Map,
    pts: &[[f64; 2]],
    stack: &mut Vec<(u32, Point)>,
    out: &mut Vec<[u32; 3]>,
) -> Result<(), Error> {
    for t in &map.traps {
        if t.lseg == NONE || t.rseg == NONE {
            continue;
        }
        let (ls, rs) = (map.seg(t.lseg)?, map.seg(t.rseg)?);
        match (ls.up, rs.up) {
            (false, true) => {}
            (true, false) => continue,
            // the region would be on both sides or on neither: not the rings promised
            _ => return Err(BROKEN),
        }
        // the topmost trapezoid beside a segment has the segment's upper end as its top
        if t.top == ls.hi {
            mountain(map, pts, t.lseg, ls, *t, false, stack, out)?;
        }
        if t.top == rs.hi {
            mountain(map, pts, t.rseg, rs, *t, true, stack, out)?;
        }
    }
    Ok(())
}

/// The mountain on segment `s` (fields `seg`), whose topmost inner trapezoid is `first`:
/// `base_right` when `s` bounds its trapezoids on the right (the chain is on the left).
/// The chain is clipped as it is walked, from the top down.
#[allow(clippy::too_many_arguments)] // the map, the mountain, its scratch and the output
fn mountain(
    map: &Map,
    pts: &[[f64; 2]],
    s: u32,
    seg: Seg,
    first: Trap,
    base_right: bool,
    stack: &mut Vec<(u32, Point)>,
    out: &mut Vec<[u32; 3]>,
) -> Result<(), Error> {
    // counter-clockwise, the chain runs down when it is on the left
    let convex = if base_right {
        Orientation::CounterClockwise
    } else {
        Orientation::Clockwise
    };
    stack.clear();
    stack.push((first.top, point(pts, first.top)?));
    let mut t = first;
    for _ in 0..map.traps.len() {
        stack.push((t.bot, point(pts, t.bot)?));
        while let [.., (a, pa), (b, pb), (c, pc)] = stack[..] {
            if orient2d(pa, pb, pc) != convex {
                break;
            }
            out.push(if base_right { [a, b, c] } else { [c, b, a] });
            stack.pop();
            stack.pop();
            stack.push((c, pc));
        }
        if t.bot == seg.lo {
            // a mountain of positive area always has a convex vertex left to clip
            return if stack.len() == 2 {
                Ok(())
            } else {
                Err(BROKEN)
            };
        }
        // the next trapezoid down beside s: the lower neighbour at s's side
        let next = if base_right && t.d[1] != NONE {
            t.d[1]
        } else {
            t.d[0]
        };
        t = map.trap(next)?;
        if (if base_right { t.rseg } else { t.lseg }) != s {
            return Err(BROKEN);
        }
    }
    Err(BROKEN)
}
