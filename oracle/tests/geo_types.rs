//! `polytri::geo::Triangulate` on geo-types polygons, against earcut: geo's
//! `TriangulateEarcut` is earcut on the polygon's exterior and interiors. (geo's own
//! wrapper pins earcut 0.4.5, which cannot sit beside the earcut this workspace
//! benchmarks, so the test calls earcut the way the wrapper does.)
//!
//! On valid polygons the two agree in area with the polygon (geo's `Area`); where earcut's
//! floating-point predicates go wrong (the generators' touching-holes and orthogonal
//! families, where earcut fails the oracle on several percent of cases), polytri's result
//! is still judged valid by the oracle, and its area is exact.

use geo::{Area, Coord, LineString, Polygon, Triangle};
use polytri::geo::Triangulate;
use polytri_oracle::gen::{generate, Family, Params};
use polytri_oracle::{check, Input, Nesting};

/// The generated case as a geo polygon (its first ring outer, the rest holes).
fn polygon(input: &Input) -> Polygon<f64> {
    let rings: Vec<LineString<f64>> = input
        .rings()
        .into_iter()
        .map(|ring| ring.into_iter().map(|[x, y]| Coord { x, y }).collect())
        .collect();
    let mut rings = rings.into_iter();
    let exterior = rings.next().unwrap_or_else(|| LineString(Vec::new()));
    Polygon::new(exterior, rings.collect())
}

/// earcut's triangles on the polygon, as geo's `TriangulateEarcut` computes them.
fn earcut_triangles(polygon: &Polygon<f64>) -> Vec<Triangle<f64>> {
    let mut data: Vec<[f64; 2]> = Vec::new();
    let mut holes: Vec<usize> = Vec::new();
    for (k, ring) in std::iter::once(polygon.exterior())
        .chain(polygon.interiors())
        .enumerate()
    {
        if k > 0 {
            holes.push(data.len());
        }
        data.extend(ring.0.iter().map(|c| [c.x, c.y]));
    }
    let mut out: Vec<usize> = Vec::new();
    earcut::Earcut::new().earcut(data.iter().copied(), &holes, &mut out);
    let at = |i: usize| Coord {
        x: data[i][0],
        y: data[i][1],
    };
    out.chunks_exact(3)
        .map(|t| Triangle::new(at(t[0]), at(t[1]), at(t[2])))
        .collect()
}

fn area(triangles: &[Triangle<f64>]) -> f64 {
    triangles.iter().map(|t| t.unsigned_area()).sum()
}

/// The triangles as the oracle takes them: indices into the case's vertices.
fn indexed(input: &Input, triangles: &[Triangle<f64>]) -> Vec<[u32; 3]> {
    let index = |c: Coord<f64>| {
        input
            .vertices
            .iter()
            .position(|v| v[0] == c.x && v[1] == c.y)
            .expect("a vertex of the input") as u32
    };
    triangles.iter().map(|t| t.to_array().map(index)).collect()
}

#[test]
fn agrees_with_earcut_where_earcut_is_right_and_is_valid_where_it_is_not() {
    let (mut agreed, mut earcut_wrong) = (0, 0);
    for family in [
        Family::Star,
        Family::ManyHoles,
        Family::TouchingHoles,
        Family::Orthogonal,
    ] {
        for seed in 0..40u64 {
            let mut input = generate(family, 9100 + seed, &Params::new(60)).input;
            input.nesting = Nesting::FirstIsOuter;
            let polygon = polygon(&input);
            let ours = polygon
                .triangles(&polytri::Options::default())
                .unwrap_or_else(|e| panic!("{family:?} {seed}: refused a valid polygon: {e}"));
            let exact = polygon.unsigned_area();
            let verdict = check(&input, &indexed(&input, &ours));
            assert!(verdict.valid, "{family:?} {seed}: {:?}", verdict.failures());
            assert!(
                (area(&ours) - exact).abs() <= 1e-9 * exact,
                "{family:?} {seed}"
            );
            let theirs = earcut_triangles(&polygon);
            if check(&input, &indexed(&input, &theirs)).valid {
                agreed += 1;
                assert!((area(&theirs) - area(&ours)).abs() <= 1e-9 * exact);
            } else {
                earcut_wrong += 1;
            }
        }
    }
    assert!(agreed > 100, "{agreed} agreed");
    // the families where earcut's floating-point decisions fail, as the campaign finds
    assert!(
        earcut_wrong > 0,
        "earcut was right on every case: pick harder families"
    );
}
