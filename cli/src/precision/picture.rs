//! Pictures of bad meshes: two panels over the same window — the mesh as the precision
//! saw the coordinates, and as the user has them — zoomed to the bad triangles, flipped
//! ones filled red.

use std::fmt::Write as _;

use polytri_oracle::precision::flipped;
use polytri_oracle::Input;

/// A panel's side in canvas units.
const PANEL: f64 = 420.0;
/// Space between and around panels; room for the panel titles.
const GAP: f64 = 16.0;
const TITLE: f64 = 22.0;

const STYLE: &str = "\
.tri{fill:#cfe0f7;fill-opacity:.7;stroke:#4a6fa5;stroke-width:.6}
.bad{fill:#e03131;fill-opacity:.75;stroke:#8b0000;stroke-width:1}
.ring{fill:none;stroke:#111;stroke-width:1.6}
.pt{fill:#111}
.frame{fill:none;stroke:#999}
text{font:13px sans-serif}";

/// The window both panels show: a centre and a half side, in input coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
struct View {
    centre: [f64; 2],
    half: f64,
}

impl View {
    /// Around the bounding box of `points`, with room for their neighbours.
    fn around(points: &[[f64; 2]], extent: f64) -> View {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        if lo[0] > hi[0] {
            return View {
                centre: [0.0, 0.0],
                half: 1.0,
            };
        }
        let centre = [lo[0] / 2.0 + hi[0] / 2.0, lo[1] / 2.0 + hi[1] / 2.0];
        let side = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        // A flipped triangle may be a few ulps across: still give it a window that f64
        // can draw, a little larger than the spacing of the coordinates there.
        let ulp = centre[0].abs().max(centre[1].abs()) * f64::EPSILON;
        let half = (side * 0.8).max(ulp * 64.0).max(extent * 1e-12).max(1e-300);
        View { centre, half }
    }

    /// Input coordinates to panel units, y up on screen; relative to the window, so far
    /// points land far outside (they are clipped first).
    fn local(&self, p: [f64; 2]) -> [f64; 2] {
        [
            (p[0] - self.centre[0]) / self.half,
            (p[1] - self.centre[1]) / self.half,
        ]
    }
}

/// Window coordinates `[-1, 1]²` (and a margin beyond) to canvas units in a panel at `x0`.
fn to_canvas(q: [f64; 2], x0: f64) -> (f64, f64) {
    (
        x0 + (q[0] + 1.0) / 2.0 * PANEL,
        TITLE + GAP + (1.0 - q[1]) / 2.0 * PANEL,
    )
}

/// Clips a polygon to the square `[-m, m]²` (Sutherland–Hodgman).
fn clip(polygon: &[[f64; 2]], m: f64) -> Vec<[f64; 2]> {
    let mut out = polygon.to_vec();
    // Each edge of the square as (axis, sign): keep points with sign · p[axis] ≤ m.
    for (axis, sign) in [(0, 1.0), (0, -1.0), (1, 1.0), (1, -1.0)] {
        let inside = |p: &[f64; 2]| sign * p[axis] <= m;
        let input = std::mem::take(&mut out);
        for (k, &cur) in input.iter().enumerate() {
            let prev = input[(k + input.len() - 1) % input.len()];
            let cross = |a: [f64; 2], b: [f64; 2]| {
                let t = (sign * m - a[axis]) / (b[axis] - a[axis]);
                [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
            };
            match (inside(&prev), inside(&cur)) {
                (true, true) => out.push(cur),
                (true, false) => out.push(cross(prev, cur)),
                (false, true) => {
                    out.push(cross(prev, cur));
                    out.push(cur);
                }
                (false, false) => {}
            }
        }
        if out.is_empty() {
            break;
        }
    }
    out
}

/// Clips a segment to `[-m, m]²` (Liang–Barsky).
fn clip_segment(a: [f64; 2], b: [f64; 2], m: f64) -> Option<([f64; 2], [f64; 2])> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d[0], a[0] + m),
        (d[0], m - a[0]),
        (-d[1], a[1] + m),
        (d[1], m - a[1]),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 <= t1).then(|| {
        let at = |t: f64| [a[0] + t * d[0], a[1] + t * d[1]];
        (at(t0), at(t1))
    })
}

/// `12.34` with at most two decimals.
fn num(x: f64) -> String {
    let s = format!("{x:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// One panel: `points` are the coordinates to draw with, `bad` the triangles to fill red.
fn panel(
    svg: &mut String,
    x0: f64,
    title: &str,
    input: &Input,
    points: &[[f64; 2]],
    triangles: &[[u32; 3]],
    view: View,
) {
    // Clip a little beyond the window, so that clipped edges stay off the visible frame.
    const M: f64 = 1.1;
    let bad = flipped(points, triangles);
    let _ = writeln!(
        svg,
        r#"<text x="{}" y="{}">{}</text>"#,
        num(x0),
        num(TITLE),
        super::doc::escape_html(title)
    );
    let _ = writeln!(
        svg,
        r#"<svg x="{}" y="{}" width="{PANEL}" height="{PANEL}" viewBox="{} {} {PANEL} {PANEL}" overflow="hidden">"#,
        num(x0),
        num(TITLE + GAP),
        num(x0),
        num(TITLE + GAP)
    );
    let path = |poly: &[[f64; 2]]| -> String {
        poly.iter()
            .map(|&q| {
                let (x, y) = to_canvas(q, x0);
                format!("{},{}", num(x), num(y))
            })
            .collect::<Vec<_>>()
            .join(" ")
    };
    let at = |v: u32| points.get(v as usize).map(|&p| view.local(p));
    for (k, t) in triangles.iter().enumerate() {
        let [Some(a), Some(b), Some(c)] = t.map(at) else {
            continue;
        };
        let poly = clip(&[a, b, c], M);
        if poly.len() >= 3 {
            let class = if bad.binary_search(&k).is_ok() {
                "bad"
            } else {
                "tri"
            };
            let _ = writeln!(
                svg,
                r#"<polygon class="{class}" points="{}"/>"#,
                path(&poly)
            );
        }
    }
    for r in 0..input.ring_count() {
        let range = input.ring_range(r);
        let ring = &points[range];
        for (k, &p) in ring.iter().enumerate() {
            let q = ring[(k + 1) % ring.len()];
            if let Some((a, b)) = clip_segment(view.local(p), view.local(q), M) {
                let _ = writeln!(
                    svg,
                    r#"<polyline class="ring" points="{}"/>"#,
                    path(&[a, b])
                );
            }
        }
    }
    for &p in points {
        let q = view.local(p);
        if q[0].abs() <= M && q[1].abs() <= M {
            let (x, y) = to_canvas(q, x0);
            let _ = writeln!(
                svg,
                r#"<circle class="pt" cx="{}" cy="{}" r="2"/>"#,
                num(x),
                num(y)
            );
        }
    }
    let (fx, fy) = to_canvas([-1.0, 1.0], x0);
    let _ = writeln!(
        svg,
        r#"<rect class="frame" x="{}" y="{}" width="{PANEL}" height="{PANEL}"/>"#,
        num(fx),
        num(fy)
    );
    svg.push_str("</svg>\n");
}

/// Two panels over the same window: `seen` (the coordinates the triangulator computed
/// with) and `user` (the coordinates given), the window around the triangles flipped in
/// either, or the whole input when none is.
pub fn draw(
    user: &Input,
    seen: &Input,
    triangles: &[[u32; 3]],
    seen_title: &str,
    user_title: &str,
) -> String {
    let mut bad_points = Vec::new();
    for points in [&user.vertices, &seen.vertices] {
        for k in flipped(points, triangles) {
            for v in triangles[k] {
                if let Some(&p) = points.get(v as usize) {
                    bad_points.push(p);
                }
            }
        }
    }
    let whole = View::around(&user.vertices, 0.0);
    let extent = whole.half * 2.0;
    let view = if bad_points.is_empty() {
        View {
            half: whole.half * 1.1,
            ..whole
        }
    } else {
        View::around(&bad_points, extent)
    };
    let width = 2.0 * PANEL + 3.0 * GAP;
    let height = PANEL + TITLE + 2.0 * GAP + 18.0;
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {w} {h}" width="{w}" height="{h}">"#,
        w = num(width),
        h = num(height)
    );
    let _ = writeln!(svg, "<style>\n{STYLE}\n</style>");
    let _ = writeln!(svg, r##"<rect width="100%" height="100%" fill="#fff"/>"##);
    panel(
        &mut svg,
        GAP,
        seen_title,
        seen,
        &seen.vertices,
        triangles,
        view,
    );
    panel(
        &mut svg,
        2.0 * GAP + PANEL,
        user_title,
        user,
        &user.vertices,
        triangles,
        view,
    );
    let _ = writeln!(
        svg,
        r#"<text x="{}" y="{}">window {:.3e} wide around ({:.10e}, {:.10e}): {:.1e} of the polygon's size</text>"#,
        num(GAP),
        num(height - 8.0),
        2.0 * view.half,
        view.centre[0],
        view.centre[1],
        2.0 * view.half / extent.max(f64::MIN_POSITIVE)
    );
    svg.push_str("</svg>\n");
    svg
}

#[cfg(test)]
mod tests {
    use super::*;
    use polytri_oracle::Nesting;

    #[test]
    fn clipping_keeps_inside_and_cuts_outside() {
        let tri = [[0.0, 0.0], [4.0, 0.0], [0.0, 0.5]];
        let out = clip(&tri, 1.0);
        assert!(out
            .iter()
            .all(|p| p[0].abs() <= 1.0 + 1e-12 && p[1].abs() <= 1.0));
        assert_eq!(out.len(), 4);
        assert!(clip(&[[5.0, 5.0], [6.0, 5.0], [5.0, 6.0]], 1.0).is_empty());
        assert_eq!(
            clip_segment([-3.0, 0.0], [3.0, 0.0], 1.0),
            Some(([-1.0, 0.0], [1.0, 0.0]))
        );
        assert_eq!(clip_segment([2.0, 2.0], [3.0, 2.0], 1.0), None);
    }

    #[test]
    fn flipped_triangles_are_red_and_in_view() {
        let square = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let input = Input::from_rings(&[square], Nesting::Auto);
        let svg = draw(&input, &input, &[[0, 1, 2], [0, 3, 2]], "seen", "user");
        assert_eq!(svg.matches(r#"class="bad""#).count(), 2);
        assert_eq!(svg.matches(r#"class="tri""#).count(), 2);
        assert!(svg.starts_with("<svg "));
    }
}
