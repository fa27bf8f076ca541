//! earcut 0.4.12 (the georust port of mapbox/earcut) vendored twice from one copy of its
//! code (`earcut.rs`): with exact predicates, the reference `earcut-exact` of `polytri
//! bench` — the price of exactness in earcut's own code — and with upstream's own
//! floating-point predicates, `earcut-vendored`, its baseline.
//!
//! The copy is trimmed to what the bench needs and reaches its nodes by safe indexing
//! (upstream reads them at unchecked byte offsets; this crate forbids `unsafe`), which
//! costs time of its own: earcut-exact over earcut-vendored is the price of the exact
//! predicates alone. With upstream's predicates the copy makes the crate's triangles,
//! index for index (the tests below). What changed, and the licences: `README.md` and the
//! `LICENSE-*` files beside this one.

/// earcut with its two geometric predicates decided by the exact sign of
/// `robust::orient2d`, with upstream's sign conventions and boundaries.
pub(super) mod exact {
    include!("earcut.rs");

    /// EXACT: whether `p` lies in triangle `a b c` (counter-clockwise), boundary included.
    /// Upstream compares two products per edge in floating point, for the edge c→a
    /// `(c.x - p.x)(a.y - p.y) >= (a.x - p.x)(c.y - p.y)`, which is the orientation
    /// determinant of `p c a` `>= 0`; here each is that determinant's exact sign, so the
    /// boundary stays included as upstream meant it.
    fn point_in_triangle(a: [f64; 2], b: [f64; 2], c: [f64; 2], p: [f64; 2]) -> bool {
        orient2d(p, c, a) >= 0.0 && orient2d(p, a, b) >= 0.0 && orient2d(p, b, c) >= 0.0
    }

    /// EXACT: the signed area of a triangle with upstream's sign convention,
    /// `(q.y - p.y)(r.x - q.x) - (q.x - p.x)(r.y - q.y)`, which is minus the orientation
    /// determinant of `p q r`: negative when counter-clockwise, positive when clockwise,
    /// 0 when collinear. Every caller compares it with 0; its sign is exact, its magnitude
    /// only approximate.
    fn area(p: &Node, q: &Node, r: &Node) -> f64 {
        -orient2d(p.xy, q.xy, r.xy)
    }

    /// The orientation of `a b c`, Shewchuk's adaptive predicate: positive when
    /// counter-clockwise, negative when clockwise, 0 when collinear, the sign exact.
    fn orient2d(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
        let coord = |[x, y]: [f64; 2]| robust::Coord { x, y };
        robust::orient2d(coord(a), coord(b), coord(c))
    }
}

/// The same copy with upstream's own floating-point predicates, verbatim.
pub(super) mod vendored {
    include!("earcut.rs");

    fn point_in_triangle(a: [f64; 2], b: [f64; 2], c: [f64; 2], p: [f64; 2]) -> bool {
        ((c[0] - p[0]) * (a[1] - p[1]) >= (a[0] - p[0]) * (c[1] - p[1]))
            && ((a[0] - p[0]) * (b[1] - p[1]) >= (b[0] - p[0]) * (a[1] - p[1]))
            && ((b[0] - p[0]) * (c[1] - p[1]) >= (c[0] - p[0]) * (b[1] - p[1]))
    }

    /// signed area of a triangle
    fn area(p: &Node, q: &Node, r: &Node) -> f64 {
        (q.xy[1] - p.xy[1]) * (r.xy[0] - q.xy[0]) - (q.xy[0] - p.xy[0]) * (r.xy[1] - q.xy[1])
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use crate::gen::{generate, Family, Params};
    use crate::input::{Input, Nesting};
    use crate::peers::polygons;

    /// earcut's fixtures, then cases of every generator family, as earcut takes them.
    fn inputs() -> Vec<(String, Input)> {
        let fixtures = Path::new(env!("CARGO_MANIFEST_DIR")).join("../corpus/earcut/fixtures");
        let mut inputs = Vec::new();
        let mut paths: Vec<_> = (std::fs::read_dir(&fixtures).expect("corpus/earcut/fixtures"))
            .map(|entry| entry.expect("a fixture").path())
            .collect();
        paths.sort();
        for path in paths {
            let text = std::fs::read_to_string(&path).expect("read a fixture");
            let rings: Vec<Vec<[f64; 2]>> = serde_json::from_str(&text).expect("rings JSON");
            let name = path.display().to_string();
            inputs.push((name, Input::from_rings(&rings, Nesting::FirstIsOuter)));
        }
        for family in Family::ALL {
            for seed in 0..20 {
                let params = Params::new(10 + 97 * seed as usize);
                inputs.push((
                    format!("{family:?} {seed}"),
                    generate(family, seed, &params).input,
                ));
            }
        }
        inputs
    }

    #[test]
    fn with_upstreams_predicates_the_copy_makes_the_crates_triangles() {
        let mut crate_earcut = ::earcut::Earcut::<f64>::new();
        let mut copy = super::vendored::Earcut::new();
        let (mut expected, mut got) = (Vec::new(), Vec::new());
        let mut polygons_seen = 0;
        for (name, input) in inputs() {
            for polygon in polygons(&input) {
                let holes = polygon.hole_indices();
                crate_earcut.earcut_slice(&polygon.vertices, &holes, &mut expected);
                copy.earcut_slice(&polygon.vertices, &holes, &mut got);
                assert_eq!(got, expected, "{name}");
                polygons_seen += 1;
            }
        }
        assert!(polygons_seen > 59 + 12 * 20, "{polygons_seen} polygons");
    }

    #[test]
    fn exact_predicates_keep_upstreams_signs_and_boundaries() {
        // Small integers: upstream's floating-point predicates are exact here too, so a sign
        // or a boundary turned the other way would show as other triangles.
        let mut exact = super::exact::Earcut::new();
        let mut copy = super::vendored::Earcut::new();
        let (mut from_exact, mut from_copy) = (Vec::new(), Vec::new());
        // a chevron: its reflex vertex (2, 2) lies exactly on the diagonal (0, 4)–(4, 0)
        // that the ear at (0, 0) would cut, and blocks it (boundaries count as inside)
        let chevron = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [2.0, 2.0], [0.0, 4.0]];
        // a square with a triangular hole, one hole vertex on the square's diagonal
        let square = vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]];
        let hole = vec![[5.0, 5.0], [6.0, 3.0], [7.0, 5.0]];
        for rings in [vec![chevron], vec![square, hole]] {
            for reverse in [false, true] {
                let mut data = Vec::new();
                let mut holes = Vec::new();
                for ring in &rings {
                    if !data.is_empty() {
                        holes.push(data.len() as u32);
                    }
                    let start = data.len();
                    data.extend_from_slice(ring);
                    if reverse {
                        data[start..].reverse();
                    }
                }
                exact.earcut_slice(&data, &holes, &mut from_exact);
                copy.earcut_slice(&data, &holes, &mut from_copy);
                assert_eq!(from_exact, from_copy, "{data:?}");
                let expected = data.len() - 2 + 2 * holes.len();
                assert_eq!(from_exact.len(), 3 * expected, "{data:?}");
            }
        }
    }

    #[test]
    fn malformed_hole_indices_make_no_triangles_instead_of_a_panic() {
        let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let mut exact = super::exact::Earcut::new();
        let mut out = vec![7];
        for holes in [&[9][..], &[3, 2]] {
            exact.earcut_slice(&square, holes, &mut out);
            assert!(out.is_empty(), "{holes:?}: {out:?}");
        }
    }
}
