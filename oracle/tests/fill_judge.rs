//! The fill-rule judge (`check_fill`, `fill_area`) on hand-made inputs and hand-made
//! triangulations whose right answers are worked out below, independently of polytri's
//! fill path; then polytri's own results on the same shapes.

use num_bigint::BigInt;
use num_rational::BigRational;
use polytri::FillRule::{self, AbsGeqTwo, EvenOdd, Negative, NonZero, Positive};
use polytri::{Options, Triangulator};
use polytri_oracle::{check_fill, fill_area, fill_area_float, verify_fill, Verdict};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;

type Shape = (Vec<[f64; 2]>, Vec<usize>);

/// The names of the failed checks.
fn failed(v: &Verdict) -> Vec<String> {
    v.checks
        .iter()
        .filter(|c| !c.passed)
        .map(|c| c.name.clone())
        .collect()
}

#[track_caller]
fn accepts(shape: &Shape, rule: FillRule, added: &[[f64; 2]], tris: &[[u32; 3]]) {
    let v = check_fill(&shape.0, &shape.1, rule, added, tris);
    assert!(v.valid, "{rule:?} {tris:?}: {:?}", v.failures());
}

#[track_caller]
fn rejects(
    shape: &Shape,
    rule: FillRule,
    added: &[[f64; 2]],
    tris: &[[u32; 3]],
    checks: &[&str],
) -> Verdict {
    let v = check_fill(&shape.0, &shape.1, rule, added, tris);
    assert!(!v.valid, "{rule:?} {tris:?} accepted");
    let names = failed(&v);
    for c in checks {
        assert!(names.iter().any(|n| n == c), "{rule:?} {tris:?}: {names:?}");
    }
    v
}

fn cat(parts: &[&[[u32; 3]]]) -> Vec<[u32; 3]> {
    parts.concat()
}

// ------------------------------------------------------------------------------------------
// The shapes, with their regions worked out by hand
// ------------------------------------------------------------------------------------------

/// (0,0)→(2,2)→(2,0)→(0,2): the diagonals cross at (1, 1). The left wing (0,2)→(0,0)→(1,1)
/// turns counter-clockwise: winding +1; the right wing (1,1)→(2,2)→(2,0) clockwise: −1.
/// Each wing has area 1.
fn bow_tie() -> Shape {
    (
        vec![[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]],
        vec![0],
    )
}
const BOW_TIE_ADDED: [[f64; 2]; 1] = [[1.0, 1.0]];
/// Vertex 4 is the crossing.
const LEFT_WING: [u32; 3] = [0, 4, 3];
const RIGHT_WING: [u32; 3] = [2, 1, 4];

/// The unit square, given twice as two rings: winding 2 inside.
fn square_twice() -> Shape {
    let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    ([sq, sq].concat(), vec![0, 4])
}

/// A = [0,2]² and B = [1,3]², both counter-clockwise (`b_clockwise`: B reversed). Their
/// edges cross at (2, 1) and (1, 2). With B counter-clockwise: winding 2 on [1,2]² (area 1),
/// 1 on the rest of the union (area 6). Reversed: 1 on A∖B (3), −1 on B∖A (3), 0 between.
fn two_squares(b_clockwise: bool) -> Shape {
    let mut v = vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
    if b_clockwise {
        v.extend([[1.0, 1.0], [1.0, 3.0], [3.0, 3.0], [3.0, 1.0]]);
    } else {
        v.extend([[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]]);
    }
    (v, vec![0, 4])
}
/// Vertices 8 and 9.
const SQUARES_ADDED: [[f64; 2]; 2] = [[2.0, 1.0], [1.0, 2.0]];

/// The convex pentagon (−3,0), (3,0), (7,10), (0,15), (−7,10) joined every second point:
/// the star winds twice (`reversed`: −2) round the inner pentagon (0,3), (2,5), (1,10),
/// (−1,10), (−2,5) — area 19 by the shoelace (38/2) — and once round each tip: the
/// triangles at (3,0) and (−3,0) of area 6, at (7,10) and (−7,10) of area 15, at (0,15) of
/// area 5; tips 47 in all. Check: 2·19 + 47 = 85, the star's own shoelace area.
fn pentagram(reversed: bool) -> Shape {
    let mut v = vec![
        [-3.0, 0.0],
        [7.0, 10.0],
        [-7.0, 10.0],
        [3.0, 0.0],
        [0.0, 15.0],
    ];
    if reversed {
        v.reverse();
    }
    (v, vec![0])
}
/// Vertices 5..10, the inner pentagon counter-clockwise.
const STAR_ADDED: [[f64; 2]; 5] = [
    [0.0, 3.0],
    [2.0, 5.0],
    [1.0, 10.0],
    [-1.0, 10.0],
    [-2.0, 5.0],
];
/// Tip triangles for the star in its given order (0 = (−3,0), 1 = (7,10), 2 = (−7,10),
/// 3 = (3,0), 4 = (0,15)).
const STAR_TIPS: [[u32; 3]; 5] = [[5, 3, 6], [0, 5, 9], [6, 1, 7], [2, 9, 8], [8, 7, 4]];
const STAR_INNER: [[u32; 3]; 3] = [[5, 6, 7], [5, 7, 8], [5, 8, 9]];

/// (0,0)→(3,3)→(3,0)→(0,2): the diagonals cross at (6/5, 6/5), not a dyadic point. The
/// left wing (0,0), (6/5,6/5), (0,2) winds +1 with area ½·(6/5)·2 = 6/5; the right wing
/// (6/5,6/5), (3,3), (3,0) winds −1 with area ½·|(9/5)(−6/5) − (9/5)(9/5)| = 27/10.
fn skew_bow_tie() -> Shape {
    (
        vec![[0.0, 0.0], [3.0, 3.0], [3.0, 0.0], [0.0, 2.0]],
        vec![0],
    )
}

/// Two unit squares side by side sharing the edge x = 1 (`b_clockwise`: the right one
/// reversed): winding 1 on both (or 1 and −1).
fn side_by_side(b_clockwise: bool) -> Shape {
    let mut v = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    if b_clockwise {
        v.extend([[1.0, 0.0], [1.0, 1.0], [2.0, 1.0], [2.0, 0.0]]);
    } else {
        v.extend([[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]);
    }
    (v, vec![0, 4])
}

fn ratio(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

/// Every shape with its area under EvenOdd, NonZero, Positive, Negative, AbsGeqTwo
/// (as numerator, denominator).
/// A shape's area under each rule, in [`RULES`] order, as (numerator, denominator).
type Areas = [(i64, i64); 5];

fn areas_by_hand() -> Vec<(&'static str, Shape, Areas)> {
    vec![
        (
            "bow tie",
            bow_tie(),
            [(2, 1), (2, 1), (1, 1), (1, 1), (0, 1)],
        ),
        (
            "skew bow tie",
            skew_bow_tie(),
            [(39, 10), (39, 10), (6, 5), (27, 10), (0, 1)],
        ),
        (
            "square twice",
            square_twice(),
            [(0, 1), (1, 1), (1, 1), (0, 1), (1, 1)],
        ),
        (
            "two squares",
            two_squares(false),
            [(6, 1), (7, 1), (7, 1), (0, 1), (1, 1)],
        ),
        (
            "two squares, B clockwise",
            two_squares(true),
            [(6, 1), (6, 1), (3, 1), (3, 1), (0, 1)],
        ),
        (
            "pentagram",
            pentagram(false),
            [(47, 1), (66, 1), (66, 1), (0, 1), (19, 1)],
        ),
        (
            "pentagram reversed",
            pentagram(true),
            [(47, 1), (66, 1), (0, 1), (66, 1), (19, 1)],
        ),
        (
            "side by side",
            side_by_side(false),
            [(2, 1), (2, 1), (2, 1), (0, 1), (0, 1)],
        ),
        (
            "side by side, B clockwise",
            side_by_side(true),
            [(2, 1), (2, 1), (1, 1), (1, 1), (0, 1)],
        ),
    ]
}

const RULES: [FillRule; 5] = [EvenOdd, NonZero, Positive, Negative, AbsGeqTwo];

// ------------------------------------------------------------------------------------------
// The slab area alone
// ------------------------------------------------------------------------------------------

#[test]
fn slab_areas_match_the_hand_computed_ones() {
    for (name, shape, areas) in areas_by_hand() {
        for (rule, (n, d)) in RULES.into_iter().zip(areas) {
            let area = fill_area(&shape.0, &shape.1, rule).expect("measurable");
            assert_eq!(
                area.exact,
                Some(ratio(n, d)),
                "{name} {rule:?}: {}",
                area.area
            );
            assert_eq!(area.area, n as f64 / d as f64, "{name} {rule:?}");
            let float = fill_area_float(&shape.0, &shape.1, rule).expect("measurable");
            assert_eq!(float.exact, None);
            let expected = n as f64 / d as f64;
            assert!(
                (float.area - expected).abs() <= 1e-12 * expected.max(1.0),
                "{name} {rule:?}: {} by f64",
                float.area
            );
        }
    }
    // the crossings it found: bow ties one, the pentagram five; the squares' two crossings
    // are on vertical edges, which bound no slab
    let crossings = |s: Shape| fill_area(&s.0, &s.1, NonZero).unwrap().crossings;
    assert_eq!(crossings(bow_tie()), 1);
    assert_eq!(crossings(two_squares(false)), 0);
    assert_eq!(crossings(pentagram(false)), 5);
    assert_eq!(crossings(square_twice()), 0);
}

#[test]
fn slab_areas_of_plain_polygons_are_their_shoelace_areas() {
    // a square with a hole wound the other way: 16 − 4 under every rule that takes 1
    let (v, s) = (
        vec![
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [0.0, 4.0],
            [1.0, 1.0],
            [1.0, 3.0],
            [3.0, 3.0],
            [3.0, 1.0],
        ],
        vec![0, 4],
    );
    for (rule, area) in [
        (EvenOdd, 12.0),
        (NonZero, 12.0),
        (Positive, 12.0),
        (Negative, 0.0),
        (AbsGeqTwo, 0.0),
    ] {
        assert_eq!(fill_area(&v, &s, rule).unwrap().area, area, "{rule:?}");
    }
    // closing points, repeated points and a zero-width spike change nothing
    let closed = vec![
        [0.0, 0.0],
        [0.0, 0.0],
        [4.0, 0.0],
        [4.0, 2.0],
        [6.0, 2.0],
        [4.0, 2.0],
        [4.0, 4.0],
        [0.0, 4.0],
        [0.0, 0.0],
    ];
    for rule in RULES {
        let expected = if matches!(rule, EvenOdd | NonZero | Positive) {
            16.0
        } else {
            0.0
        };
        assert_eq!(
            fill_area(&closed, &[0], rule).unwrap().area,
            expected,
            "{rule:?}"
        );
    }
    // nothing at all
    assert_eq!(fill_area(&[], &[], NonZero).unwrap().area, 0.0);
}

// ------------------------------------------------------------------------------------------
// Hand-made triangulations
// ------------------------------------------------------------------------------------------

#[test]
fn bow_tie_wings_by_rule() {
    let shape = bow_tie();
    let added = BOW_TIE_ADDED;
    let both = [LEFT_WING, RIGHT_WING];
    for rule in [NonZero, EvenOdd] {
        accepts(&shape, rule, &added, &both);
    }
    accepts(&shape, Positive, &added, &[LEFT_WING]);
    accepts(&shape, Negative, &added, &[RIGHT_WING]);
    accepts(&shape, AbsGeqTwo, &added, &[]);
    // the wing a rule leaves out is outside: its centroid has the other winding number
    let v = rejects(&shape, Positive, &added, &both, &["inside", "area"]);
    let inside = v.check("inside").unwrap().detail.clone().unwrap();
    assert!(
        inside.starts_with("the centroid of triangle 1 (2, 1, 4) has winding number -1"),
        "{inside}"
    );
    let v = rejects(&shape, Negative, &added, &both, &["inside", "area"]);
    let inside = v.check("inside").unwrap().detail.clone().unwrap();
    assert!(
        inside.contains("triangle 0 (0, 4, 3) has winding number 1"),
        "{inside}"
    );
    rejects(&shape, AbsGeqTwo, &added, &[LEFT_WING], &["inside", "area"]);
    rejects(
        &shape,
        AbsGeqTwo,
        &added,
        &[RIGHT_WING],
        &["inside", "area"],
    );
}

#[test]
fn bow_tie_faults_are_named() {
    let shape = bow_tie();
    let added = BOW_TIE_ADDED;
    // a triangle missing: only the area says so
    let v = rejects(&shape, NonZero, &added, &[LEFT_WING], &["area"]);
    assert_eq!(failed(&v), ["area"]);
    // an overlapping pair: the same wing twice, turned
    let v = rejects(
        &shape,
        NonZero,
        &added,
        &[LEFT_WING, RIGHT_WING, [4, 3, 0]],
        &["overlap", "area"],
    );
    let overlap = v.check("overlap").unwrap().detail.clone().unwrap();
    assert_eq!(
        overlap,
        "triangle 0 (0, 4, 3) overlaps triangle 2 (4, 3, 0)"
    );
    // a triangle outside: the top one, between the wings, winding 0
    let v = rejects(
        &shape,
        EvenOdd,
        &added,
        &[LEFT_WING, RIGHT_WING, [1, 3, 4]],
        &["inside", "area"],
    );
    let inside = v.check("inside").unwrap().detail.clone().unwrap();
    assert!(
        inside.starts_with("the centroid of triangle 2 (1, 3, 4) has winding number 0"),
        "{inside}"
    );
    assert!(v.check("overlap").unwrap().passed);
    // turned round
    let v = rejects(
        &shape,
        NonZero,
        &added,
        &[[0, 3, 4], RIGHT_WING],
        &["orientation"],
    );
    assert_eq!(
        v.check("orientation").unwrap().detail.as_deref(),
        Some("triangle 0 (0, 3, 4) is clockwise")
    );
    // an index past the added vertices
    let v = rejects(
        &shape,
        NonZero,
        &added,
        &[LEFT_WING, [2, 1, 5]],
        &["indices"],
    );
    assert!(v.failures()[0].starts_with("indices: triangle 1 (2, 1, 5) names vertex 5"));
    // without the added vertex, vertex 4 does not exist
    rejects(&shape, NonZero, &[], &both_wings(), &["indices"]);
}

fn both_wings() -> [[u32; 3]; 2] {
    [LEFT_WING, RIGHT_WING]
}

#[test]
fn a_square_wound_twice() {
    let shape = square_twice();
    let first = [[0, 1, 2], [0, 2, 3]];
    let second = [[4, 5, 6], [4, 6, 7]];
    for rule in [AbsGeqTwo, NonZero, Positive] {
        accepts(&shape, rule, &[], &first);
        accepts(&shape, rule, &[], &second);
        accepts(&shape, rule, &[], &[[0, 5, 6], [4, 2, 7]]);
    }
    for rule in [EvenOdd, Negative] {
        accepts(&shape, rule, &[], &[]);
        rejects(&shape, rule, &[], &[[0, 1, 2]], &["inside", "area"]);
        rejects(&shape, rule, &[], &first, &["inside", "area"]);
    }
    // both copies at once overlap
    rejects(
        &shape,
        AbsGeqTwo,
        &[],
        &cat(&[&first, &second]),
        &["overlap", "area"],
    );
}

#[test]
fn two_overlapping_squares() {
    let shape = two_squares(false);
    let added = SQUARES_ADDED;
    // A: 0 (0,0), 1 (2,0), 2 (2,2), 3 (0,2); B: 4 (1,1), 5 (3,1), 6 (3,3), 7 (1,3);
    // added: 8 (2,1), 9 (1,2).
    // The union as an octagon (area 7), fanned from (0,0) and from (2,1):
    let union = [
        [0, 1, 8],
        [0, 8, 9],
        [0, 9, 3],
        [8, 5, 6],
        [8, 6, 7],
        [8, 7, 9],
    ];
    // A∖B and B∖A, L-shapes of area 3 each, and the overlap [1,2]²:
    let a_only = [[0, 1, 8], [0, 8, 4], [0, 4, 9], [0, 9, 3]];
    let b_only = [[8, 5, 6], [8, 6, 2], [2, 6, 7], [2, 7, 9]];
    let both = [[4, 8, 2], [4, 2, 9]];
    let ring = cat(&[&a_only, &b_only]);
    let all = cat(&[&a_only, &b_only, &both]);

    for rule in [NonZero, Positive] {
        // (0,0), (2,1), (1,2) has its centroid at B's corner (1,1): the sectors there wind
        // 1, 1, 1 and 2, all accepted
        accepts(&shape, rule, &added, &union);
        accepts(&shape, rule, &added, &all);
        rejects(&shape, rule, &added, &ring, &["area"]);
    }
    accepts(&shape, EvenOdd, &added, &ring);
    rejects(&shape, EvenOdd, &added, &union, &["area"]);
    rejects(&shape, EvenOdd, &added, &all, &["inside", "area"]);
    accepts(&shape, AbsGeqTwo, &added, &both);
    rejects(&shape, AbsGeqTwo, &added, &a_only, &["inside", "area"]);
    accepts(&shape, Negative, &added, &[]);
    rejects(&shape, Negative, &added, &both, &["inside", "area"]);
    // the union's triangles together with the overlap's overlap
    let v = rejects(
        &shape,
        NonZero,
        &added,
        &cat(&[&union, &both]),
        &["overlap"],
    );
    assert!(v.failures()[0].starts_with("overlap: triangle 1 (0, 8, 9) overlaps triangle 6"));

    // B clockwise: 4 (1,1), 5 (1,3), 6 (3,3), 7 (3,1)
    let shape = two_squares(true);
    let b_only = [[8, 7, 6], [8, 6, 2], [2, 6, 5], [2, 5, 9]];
    accepts(&shape, Positive, &added, &a_only);
    accepts(&shape, Negative, &added, &b_only);
    for rule in [NonZero, EvenOdd] {
        accepts(&shape, rule, &added, &cat(&[&a_only, &b_only]));
    }
    accepts(&shape, AbsGeqTwo, &added, &[]);
    // (B∖A has A∖B's area: only the centroids tell)
    let v = rejects(&shape, Positive, &added, &b_only, &["inside"]);
    assert_eq!(failed(&v), ["inside"]);
    rejects(&shape, NonZero, &added, &both, &["inside", "area"]);
}

#[test]
fn a_pentagram() {
    let added = STAR_ADDED;
    let all = cat(&[&STAR_TIPS, &STAR_INNER]);
    let shape = pentagram(false);
    accepts(&shape, EvenOdd, &added, &STAR_TIPS);
    accepts(&shape, NonZero, &added, &all);
    accepts(&shape, Positive, &added, &all);
    accepts(&shape, AbsGeqTwo, &added, &STAR_INNER);
    accepts(&shape, Negative, &added, &[]);
    rejects(&shape, EvenOdd, &added, &all, &["inside", "area"]);
    let v = rejects(&shape, AbsGeqTwo, &added, &all, &["inside", "area"]);
    assert!(v.failures()[0].contains("triangle 0 (5, 3, 6) has winding number 1"));
    rejects(&shape, NonZero, &added, &STAR_TIPS, &["area"]);

    // reversed, input vertex k is the old 4 − k; the added ones stay
    let shape = pentagram(true);
    let remap = |tris: &[[u32; 3]]| -> Vec<[u32; 3]> {
        tris.iter()
            .map(|t| t.map(|i| if i < 5 { 4 - i } else { i }))
            .collect()
    };
    let (tips, inner, all) = (remap(&STAR_TIPS), remap(&STAR_INNER), remap(&all));
    accepts(&shape, Negative, &added, &all);
    accepts(&shape, NonZero, &added, &all);
    accepts(&shape, EvenOdd, &added, &tips);
    accepts(&shape, AbsGeqTwo, &added, &inner);
    accepts(&shape, Positive, &added, &[]);
    let v = rejects(&shape, Positive, &added, &inner, &["inside", "area"]);
    assert!(
        v.failures()[0].contains("has winding number -2"),
        "{:?}",
        v.failures()
    );
}

#[test]
fn a_centroid_on_an_edge_is_judged_by_the_sectors_round_it() {
    // 0 (0,0), 1 (1,0), 2 (1,1), 3 (0,1) | 4 (1,0), 5 (2,0), 6 (2,1), 7 (1,1)
    // (0,0), (2,0), (1,1) has its centroid (1, 1/3) on the shared edge x = 1.
    let tris = [[0, 5, 2], [5, 6, 2], [0, 2, 3]];
    let shape = side_by_side(false);
    for rule in [NonZero, Positive, EvenOdd] {
        accepts(&shape, rule, &[], &tris);
    }
    // the right square clockwise: under Positive the left half of the triangle is in, the
    // right half out, and with no added vertex nothing is excused
    // 4 (1,0), 5 (1,1), 6 (2,1), 7 (2,0)
    let shape = side_by_side(true);
    let tris = [[0, 7, 2], [7, 6, 2], [0, 2, 3]];
    accepts(&shape, NonZero, &[], &tris);
    let v = rejects(&shape, Positive, &[], &tris, &["inside", "area"]);
    assert!(
        v.failures()[0].starts_with(
            "inside: the centroid of triangle 0 (0, 7, 2) lies on an input edge, with winding numbers"
        ),
        "{:?}",
        v.failures()
    );
}

#[test]
fn exact_without_added_vertices_rounding_allowed_with_them() {
    // a square whose top bulges by e = 2^-20 at (2, 4 + e)
    let e = 2f64.powi(-20);
    let bulge = (
        vec![
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [2.0, 4.0 + e],
            [0.0, 4.0],
        ],
        vec![0],
    );
    // the square's two triangles leave out the sliver under the bulge (area 2e)
    let v = rejects(&bulge, NonZero, &[], &[[0, 1, 2], [0, 2, 4]], &["area"]);
    assert_eq!(failed(&v), ["area"]);
    accepts(&bulge, NonZero, &[], &[[0, 1, 2], [0, 2, 3], [0, 3, 4]]);

    // a plain square with a "crossing" rounded to (2, −e), just outside the bottom edge:
    // the sliver (0,0), (2,−e), (4,0) has its centroid e/3 outside, within δ = 4 ulp_f32(4)
    // = 2^-19, and the area is 16 + 2e, within 2δ·16
    let square = (
        vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]],
        vec![0],
    );
    let tris = [[0, 4, 1], [0, 1, 2], [0, 2, 3]];
    let v = check_fill(&square.0, &square.1, NonZero, &[[2.0, -e]], &tris);
    assert!(v.valid, "{:?}", v.failures());
    let note = v.check("inside").unwrap().detail.clone().unwrap();
    assert!(
        note.starts_with("1 triangle(s) outside by their centroid"),
        "{note}"
    );
    // far beyond δ it is not excused
    let v = check_fill(&square.0, &square.1, NonZero, &[[2.0, -0.5]], &tris);
    assert!(
        failed(&v).contains(&"inside".to_owned()),
        "{:?}",
        v.failures()
    );
    assert!(
        failed(&v).contains(&"area".to_owned()),
        "{:?}",
        v.failures()
    );
}

#[test]
fn large_inputs_use_the_float_slab_method_and_fans_are_cheap() {
    // a convex 5000-gon, points of the parabola y = x², fanned from vertex 0: more edges
    // than the exact method takes
    let n = 5000;
    let v: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let x = k as f64 - 2500.0;
            [x, x * x]
        })
        .collect();
    let fan: Vec<[u32; 3]> = (1..n as u32 - 1).map(|k| [0, k, k + 1]).collect();
    let verdict = check_fill(&v, &[0], NonZero, &[], &fan);
    assert!(verdict.valid, "{:?}", verdict.failures());
    let area = verdict.check("area").unwrap().detail.clone().unwrap();
    assert!(area.contains("in f64"), "{area}");
    // one more triangle across the fan overlaps it
    let mut extra = fan.clone();
    extra.push([1, 1000, 3000]);
    let verdict = check_fill(&v, &[0], NonZero, &[], &extra);
    assert!(failed(&verdict).contains(&"overlap".to_owned()));
    assert!(failed(&verdict).contains(&"area".to_owned()));
}

// ------------------------------------------------------------------------------------------
// Garbage
// ------------------------------------------------------------------------------------------

#[test]
fn garbage_gives_verdicts_not_panics() {
    let mut rng = Pcg64::seed_from_u64(0x0f11_7e57);
    let specials = [
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        1e300,
        -1e-320,
        0.0,
        -0.0,
        f64::MAX,
    ];
    for round in 0..3000 {
        let n = rng.random_range(0..9usize);
        let coord = |rng: &mut Pcg64| -> f64 {
            if rng.random_range(0..10) == 0 {
                specials[rng.random_range(0..specials.len())]
            } else {
                f64::from(rng.random_range(-4i32..=4))
            }
        };
        let v: Vec<[f64; 2]> = (0..n).map(|_| [coord(&mut rng), coord(&mut rng)]).collect();
        let added: Vec<[f64; 2]> = (0..rng.random_range(0..3usize))
            .map(|_| [coord(&mut rng), coord(&mut rng)])
            .collect();
        let starts: Vec<usize> = match rng.random_range(0..4) {
            0 => vec![0],
            1 => vec![],
            2 => {
                let mut s = vec![0];
                if n > 3 {
                    s.push(rng.random_range(1..n));
                }
                s
            }
            _ => (0..rng.random_range(0..4))
                .map(|_| rng.random_range(0..12usize))
                .collect(),
        };
        let top = (n + added.len()) as u32 + 2;
        let tris: Vec<[u32; 3]> = (0..rng.random_range(0..6))
            .map(|_| {
                [0; 3].map(|_| {
                    if rng.random_range(0..20) == 0 {
                        u32::MAX
                    } else {
                        rng.random_range(0..top)
                    }
                })
            })
            .collect();
        let rule = RULES[round % 5];
        let verdict = check_fill(&v, &starts, rule, &added, &tris);
        assert_eq!(verdict.triangles, tris.len());
        if !verdict.input_valid {
            assert!(!verdict.valid);
            assert!(!verdict.check("input").unwrap().passed);
        }
        assert!(serde_json::to_string(&verdict).is_ok());
        let _ = fill_area(&v, &starts, rule);
        let _ = fill_area_float(&v, &starts, rule);
    }
    let v = check_fill(
        &[[f64::NAN, 0.0], [1.0, 0.0], [0.0, 1.0]],
        &[0],
        NonZero,
        &[],
        &[[0, 1, 2]],
    );
    assert!(!v.valid && !v.input_valid);
    assert!(
        v.failures()[0].starts_with("input: vertex 0 (NaN, 0)"),
        "{:?}",
        v.failures()
    );
    let v = check_fill(
        &[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
        &[0, 0],
        NonZero,
        &[],
        &[],
    );
    assert!(
        v.failures()[0].contains("not strictly increasing"),
        "{:?}",
        v.failures()
    );
    let v = check_fill(&[[0.0, 0.0]], &[0], NonZero, &[[f64::INFINITY, 0.0]], &[]);
    assert!(
        v.failures()[0].starts_with("input: added vertex 0"),
        "{:?}",
        v.failures()
    );
    assert!(fill_area(&[[0.0, 0.0]], &[1], NonZero).is_err());
}

// ------------------------------------------------------------------------------------------
// polytri's fill path, judged
// ------------------------------------------------------------------------------------------

fn triangulate_and_judge<T: polytri::Coord>(name: &str, shape: &Shape, rule: FillRule) {
    let v: Vec<[T; 2]> = shape
        .0
        .iter()
        .map(|p| [T::from_f64(p[0]), T::from_f64(p[1])])
        .collect();
    let mut tri = Triangulator::<T>::new();
    let mut out = Vec::new();
    let options = Options::new().with_fill_rule(rule);
    if let Err(e) = tri.triangulate(&v, &shape.1, &options, &mut out) {
        panic!("{name} {rule:?} ({}): {e}", std::any::type_name::<T>());
    }
    let verdict = verify_fill(&v, &shape.1, rule, tri.added_vertices(), &out);
    assert!(
        verdict.valid,
        "{name} {rule:?} ({}): {:?}\n{out:?}",
        std::any::type_name::<T>(),
        verdict.failures()
    );
}

#[test]
fn polytri_fill_results_pass_the_judge() {
    let mut shapes: Vec<(&str, Shape)> = areas_by_hand()
        .into_iter()
        .map(|(name, shape, _)| (name, shape))
        .collect();
    shapes.push(("bow tie f32-inexact", {
        let (v, s) = skew_bow_tie();
        (v.iter().map(|p| [p[0] * 0.1, p[1] * 0.1]).collect(), s)
    }));
    for (name, shape) in &shapes {
        for rule in RULES {
            triangulate_and_judge::<f64>(name, shape, rule);
            triangulate_and_judge::<f32>(name, shape, rule);
        }
    }
}
